//! Numbers as they are written into generated code.

/// A number for code: at most 6 decimals, no trailing zeros, never "-0".
pub fn n(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.to_string() }
}

#[cfg(test)]
mod tests {
    use super::n;

    #[test]
    fn numbers_print_short() {
        assert_eq!(n(2.0), "2");
        assert_eq!(n(10.5), "10.5");
        assert_eq!(n(-0.0000001), "0");
    }
}
