//! Identifiers, secrets and time.

use std::time::{SystemTime, UNIX_EPOCH};

/// A new random identifier: 32 lowercase hex digits (128 bits).
pub fn new_id() -> String {
    hex(&random_bytes::<16>())
}

/// A new random secret: 64 lowercase hex digits (256 bits).
pub fn new_secret() -> String {
    hex(&random_bytes::<32>())
}

/// Whether `s` has the shape of an id from [`new_id`] (anything else is answered 404
/// before it reaches the database).
pub fn is_id(s: &str) -> bool {
    s.len() == 32 && s.bytes().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

/// Milliseconds since the Unix epoch.
pub fn now_ms() -> i64 {
    SystemTime::now().duration_since(UNIX_EPOCH).map(|d| d.as_millis() as i64).unwrap_or(0)
}

fn random_bytes<const N: usize>() -> [u8; N] {
    let mut b = [0u8; N];
    if getrandom::fill(&mut b).is_err() {
        // The OS random source is unavailable: fall back to time and a counter, which is
        // unique but not secret. Secrets are never made this way in practice on Linux.
        use std::sync::atomic::{AtomicU64, Ordering};
        static COUNTER: AtomicU64 = AtomicU64::new(0);
        let t = now_ms() as u64 ^ (COUNTER.fetch_add(1, Ordering::Relaxed) << 40) ^ u64::from(std::process::id());
        for (i, x) in b.iter_mut().enumerate() {
            *x = (t.rotate_left(i as u32 * 7) & 0xff) as u8;
        }
    }
    b
}

fn hex(bytes: &[u8]) -> String {
    const D: &[u8; 16] = b"0123456789abcdef";
    let mut s = String::with_capacity(bytes.len() * 2);
    for b in bytes {
        s.push(D[(b >> 4) as usize] as char);
        s.push(D[(b & 15) as usize] as char);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_have_their_shape_and_differ() {
        let a = new_id();
        let b = new_id();
        assert!(is_id(&a) && is_id(&b));
        assert_ne!(a, b);
        assert!(!is_id("../../etc/passwd"));
        assert!(!is_id("1' OR '1'='1"));
        assert_eq!(new_secret().len(), 64);
    }
}
