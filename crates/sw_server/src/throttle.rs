//! Attempt limits for the unauthenticated endpoints: wrong sign-ins per user name and per
//! client address, registrations per client address. A sliding window per key, in this
//! process's memory (a restart forgets it; each process of a scale-out keeps its own).

use std::collections::{BTreeMap, VecDeque};
use std::net::IpAddr;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use crate::error::ApiError;

/// How many attempts a window allows.
#[derive(Debug, Clone, Copy)]
pub struct AuthLimits {
    /// Wrong passwords for one user name per window.
    pub failed_logins_per_user: usize,
    /// Wrong passwords from one client address per window.
    pub failed_logins_per_client: usize,
    pub login_window: Duration,
    /// New accounts from one client address per window.
    pub registrations_per_client: usize,
    pub registration_window: Duration,
}

impl Default for AuthLimits {
    fn default() -> Self {
        Self {
            failed_logins_per_user: 10,
            failed_logins_per_client: 30,
            login_window: Duration::from_secs(300),
            registrations_per_client: 20,
            registration_window: Duration::from_secs(3600),
        }
    }
}

/// The attempts seen, by key.
#[derive(Debug, Default)]
pub struct Throttle {
    seen: Mutex<BTreeMap<String, VecDeque<Instant>>>,
}

/// What a request is: its client address, when it came over a socket.
pub fn client_key(ip: Option<IpAddr>) -> String {
    ip.map_or_else(|| "local".to_string(), |ip| ip.to_string())
}

impl Throttle {
    /// Refuses (429, with the seconds until a place frees) when `key` already made `max`
    /// attempts within `window`; records nothing.
    pub fn check(&self, key: &str, max: usize, window: Duration, what: &str) -> Result<(), ApiError> {
        let now = Instant::now();
        let mut seen = self.seen.lock().map_err(|_| ApiError::internal("the throttle's lock is poisoned"))?;
        let Some(q) = seen.get_mut(key) else { return Ok(()) };
        while q.front().is_some_and(|t| now.duration_since(*t) >= window) {
            q.pop_front();
        }
        if q.len() < max {
            return Ok(());
        }
        let wait = q.front().map_or(window, |t| window.saturating_sub(now.duration_since(*t)));
        Err(ApiError::new(
            axum::http::StatusCode::TOO_MANY_REQUESTS,
            format!("too many {what}; try again in {} s", wait.as_secs().max(1)),
        )
        .retry_after(wait.as_secs().max(1)))
    }

    /// Records an attempt of `key` (forgetting keys whose attempts all left their window,
    /// so the map stays as small as the traffic of one window).
    pub fn record(&self, key: &str, window: Duration) {
        let now = Instant::now();
        if let Ok(mut seen) = self.seen.lock() {
            if seen.len() > 10_000 {
                seen.retain(|_, q| q.back().is_some_and(|t| now.duration_since(*t) < window));
            }
            seen.entry(key.to_string()).or_default().push_back(now);
        }
    }

    /// Forgets a key's attempts (a user who signed in correctly starts afresh).
    pub fn clear(&self, key: &str) {
        if let Ok(mut seen) = self.seen.lock() {
            seen.remove(key);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_admits_max_attempts_then_refuses_with_the_wait() {
        let t = Throttle::default();
        let w = Duration::from_millis(300);
        for _ in 0..3 {
            assert!(t.check("k", 3, w, "attempts").is_ok());
            t.record("k", w);
        }
        let e = t.check("k", 3, w, "attempts").err().map(|e| (e.status.as_u16(), e.retry_after));
        assert_eq!(e, Some((429, Some(1))));
        assert!(t.check("other", 3, w, "attempts").is_ok(), "keys are separate");
        std::thread::sleep(w);
        assert!(t.check("k", 3, w, "attempts").is_ok(), "the window slides");
        t.record("k", w);
        t.clear("k");
        assert!(t.check("k", 1, w, "attempts").is_ok());
    }
}
