//! How many calls may be in flight at one server, process-wide.
//!
//! A local server runs one model on a few cores: concurrent requests only share the same
//! compute, and llama-cpp-python's server ends a running stream (with `[DONE]` and no
//! finish reason) when another request arrives. So calls to a loopback endpoint go one at
//! a time by default, whatever stage makes them; remote endpoints are limited only by
//! each stage's own concurrency. `endpoint_concurrency` overrides either.

use std::collections::BTreeMap;
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

use crate::cancel::{CancelToken, any_cancelled};
use crate::config::Endpoint;

#[derive(Debug, Default)]
struct Gate {
    busy: Mutex<usize>,
    freed: Condvar,
}

static GATES: Mutex<BTreeMap<String, Arc<Gate>>> = Mutex::new(BTreeMap::new());

/// True for hosts on this machine (`127.0.0.0/8`, `localhost`, `[::1]`).
pub fn is_loopback(origin: &str) -> bool {
    let rest = origin.split_once("://").map_or(origin, |(_, h)| h);
    let host = match rest.strip_prefix('[') {
        Some(v6) => v6.split(']').next().unwrap_or(""),
        None => rest.split([':', '/']).next().unwrap_or(""),
    };
    host == "localhost" || host.starts_with("127.") || host == "::1"
}

/// The most calls in flight at `ep`'s server at once (`None`: no limit).
pub fn limit(ep: &Endpoint) -> Option<usize> {
    match ep.endpoint_concurrency {
        Some(n) => Some(n.max(1)),
        None if is_loopback(&ep.origin()) => Some(1),
        None => None,
    }
}

/// A place in the server's queue, given back when dropped.
#[derive(Debug)]
pub(crate) struct Slot {
    gate: Option<Arc<Gate>>,
}

impl Drop for Slot {
    fn drop(&mut self) {
        if let Some(g) = self.gate.take() {
            let mut busy = g.busy.lock().unwrap_or_else(|e| e.into_inner());
            *busy = busy.saturating_sub(1);
            g.freed.notify_all();
        }
    }
}

/// Waits for a free place at `ep`'s server. `Err(waited)` when a token was cancelled.
pub(crate) fn acquire(ep: &Endpoint, tokens: &[CancelToken]) -> Result<(Slot, Duration), Duration> {
    let started = Instant::now();
    let Some(max) = limit(ep) else {
        return Ok((Slot { gate: None }, Duration::ZERO));
    };
    let gate = {
        let mut gates = GATES.lock().unwrap_or_else(|e| e.into_inner());
        Arc::clone(gates.entry(ep.origin()).or_default())
    };
    let mut busy = gate.busy.lock().unwrap_or_else(|e| e.into_inner());
    while *busy >= max {
        if any_cancelled(tokens) {
            return Err(started.elapsed());
        }
        busy = match gate.freed.wait_timeout(busy, Duration::from_millis(100)) {
            Ok((b, _)) => b,
            Err(p) => p.into_inner().0,
        };
    }
    *busy += 1;
    drop(busy);
    Ok((Slot { gate: Some(gate) }, started.elapsed()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loopback_hosts_are_recognised() {
        for o in ["http://127.0.0.1:8080", "http://localhost:1", "http://[::1]:9", "http://127.0.0.1"] {
            assert!(is_loopback(o), "{o}");
        }
        for o in ["https://api.openai.com", "http://10.0.0.2:8000", "http://localhost.example.com"] {
            assert!(!is_loopback(o), "{o}");
        }
    }

    #[test]
    fn a_loopback_endpoint_takes_one_call_at_a_time() {
        let ep = Endpoint::new("http://127.0.0.1:9/v1", "m");
        let (first, _) = acquire(&ep, &[]).unwrap();
        let token = CancelToken::new();
        let t = token.clone();
        let waiter = std::thread::spawn(move || {
            let ep = Endpoint::new("http://127.0.0.1:9/v1", "m");
            acquire(&ep, &[t]).map(|(_, waited)| waited)
        });
        std::thread::sleep(Duration::from_millis(150));
        token.cancel();
        assert!(waiter.join().unwrap().is_err(), "the waiter was cancelled while the slot was taken");
        drop(first);
        let (_again, waited) = acquire(&ep, &[]).unwrap();
        assert!(waited < Duration::from_millis(100));
    }
}
