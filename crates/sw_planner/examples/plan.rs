//! Prints the offline plan of each argument as one line of JSON, or the one-line error:
//! `cargo run -p sw_planner --example plan -- "a kitchen with two mugs on a table"`.

use std::io::Write;

fn main() {
    let mut out = std::io::stdout().lock();
    for prompt in std::env::args().skip(1) {
        let line = match sw_planner::plan(&prompt) {
            Ok(p) => serde_json::to_string(&p).unwrap_or_default(),
            Err(e) => format!("error: {e}"),
        };
        if writeln!(out, "{line}").is_err() {
            return;
        }
    }
}
