//! Prints the offline plan of each argument as JSON (one line per prompt), or the one-line
//! error: `cargo run -p sw_planner --example plan -- "a kitchen with two mugs on a table"`.

fn main() {
    for prompt in std::env::args().skip(1) {
        match sw_planner::plan(&prompt) {
            Ok(p) => println!("{}", serde_json::to_string(&p).unwrap_or_default()),
            Err(e) => println!("error: {e}"),
        }
    }
}
