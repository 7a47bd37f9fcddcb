//! Writing to stdout without panicking on a closed pipe (`scenewright … | head`).

use std::io::Write;

/// Prints `text` (and a newline) to stdout; a closed pipe is not an error.
pub(crate) fn print(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes());
    if !text.ends_with('\n') {
        let _ = out.write_all(b"\n");
    }
    let _ = out.flush();
}

/// Prints a value as pretty JSON.
pub(crate) fn print_json<T: serde::Serialize>(value: &T) {
    match serde_json::to_string_pretty(value) {
        Ok(s) => print(&s),
        Err(e) => eprintln!("error: cannot encode JSON: {e}"),
    }
}
