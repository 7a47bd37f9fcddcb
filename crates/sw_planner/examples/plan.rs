//! Prints the plan of a prompt: `cargo run -p sw_planner --example plan -- "a warehouse ..."`.
#![allow(clippy::print_stdout)]
fn main() {
    let prompt = std::env::args().skip(1).collect::<Vec<_>>().join(" ");
    match sw_planner::plan(&prompt) {
        Ok(p) => println!("{}", serde_json::to_string_pretty(&p).unwrap_or_default()),
        Err(e) => println!("error: {e}"),
    }
}
