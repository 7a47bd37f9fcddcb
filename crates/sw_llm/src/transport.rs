//! One HTTP exchange on a thread of its own, read by the calling thread through a
//! channel: the caller can then wait with deadlines that move (the first byte, then the
//! silence between pieces of a stream), watch cancellation, and walk away. A walked-away
//! exchange stops reading at its next piece and drops its connection, so a local server
//! that notices the closed socket stops generating; one whose server stays silent ends at
//! the agent's global timeout (the endpoint's `max_call`).

use std::io::Read;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, RecvTimeoutError, SyncSender, sync_channel};
use std::time::{Duration, Instant};

use sw_plan::LlmOutcome;

use crate::answer::AttemptError;
use crate::cancel::{CancelToken, any_cancelled};

/// What the exchange's thread reports.
#[derive(Debug)]
pub(crate) enum Io {
    /// The response's head.
    Head { status: u16, content_type: String, retry_after: Option<Duration> },
    /// Bytes of the body, as they arrived.
    Bytes(Vec<u8>),
    /// The body is complete.
    End,
    /// The request could not be sent, or the body broke off.
    Failed(AttemptError),
}

/// What waiting for the next report gave.
#[derive(Debug)]
pub(crate) enum Wait {
    Got(Io),
    /// The deadline passed first.
    TimedOut,
    /// A cancel token was set.
    Cancelled,
}

/// A request in flight.
#[derive(Debug)]
pub(crate) struct Exchange {
    rx: Receiver<Io>,
    abandon: Arc<AtomicBool>,
    finished: bool,
}

/// The request to send.
pub(crate) struct Outgoing {
    pub(crate) url: String,
    pub(crate) headers: Vec<(String, String)>,
    pub(crate) body: String,
}

/// How often a waiting caller looks at its cancel tokens.
const POLL: Duration = Duration::from_millis(100);

impl Exchange {
    /// Sends `out` with `agent` on a new thread.
    pub(crate) fn start(agent: ureq::Agent, out: Outgoing) -> Exchange {
        // A small buffer: the reader waits for the caller rather than running ahead.
        let (tx, rx) = sync_channel::<Io>(64);
        let abandon = Arc::new(AtomicBool::new(false));
        let flag = Arc::clone(&abandon);
        let spawned = std::thread::Builder::new().name("llm-io".into()).spawn(move || run(agent, out, &tx, &flag));
        if let Err(e) = spawned {
            let (tx, rx) = sync_channel::<Io>(1);
            let _ = tx.send(Io::Failed(AttemptError::new(
                LlmOutcome::ConnectionFailed,
                format!("could not start the request's thread: {e}"),
            )));
            return Exchange { rx, abandon, finished: false };
        }
        Exchange { rx, abandon, finished: false }
    }

    /// The next report, or why there is none before `deadline`.
    pub(crate) fn next(&mut self, deadline: Instant, tokens: &[CancelToken]) -> Wait {
        loop {
            if any_cancelled(tokens) {
                return Wait::Cancelled;
            }
            let now = Instant::now();
            if now >= deadline {
                return Wait::TimedOut;
            }
            match self.rx.recv_timeout((deadline - now).min(POLL)) {
                Ok(io) => {
                    if matches!(io, Io::End | Io::Failed(_)) {
                        self.finished = true;
                    }
                    return Wait::Got(io);
                }
                Err(RecvTimeoutError::Timeout) => continue,
                Err(RecvTimeoutError::Disconnected) => {
                    self.finished = true;
                    return Wait::Got(Io::Failed(AttemptError::new(
                        LlmOutcome::ConnectionFailed,
                        "the request's thread ended without an answer",
                    )));
                }
            }
        }
    }
}

impl Drop for Exchange {
    fn drop(&mut self) {
        if !self.finished {
            self.abandon.store(true, Ordering::SeqCst);
        }
    }
}

fn run(agent: ureq::Agent, out: Outgoing, tx: &SyncSender<Io>, abandon: &AtomicBool) {
    let mut r = agent.post(&out.url);
    for (k, v) in &out.headers {
        r = r.header(k.as_str(), v.as_str());
    }
    let resp = match r.send(out.body.as_bytes()) {
        Ok(resp) => resp,
        Err(e) => {
            let _ = tx.send(Io::Failed(transport_error(e)));
            return;
        }
    };
    let header = |name: &str| resp.headers().get(name).and_then(|v| v.to_str().ok()).map(str::to_string);
    let retry_after = header("retry-after")
        .and_then(|v| v.trim().parse::<f64>().ok())
        .filter(|v| v.is_finite() && *v >= 0.0)
        .map(|v| Duration::from_secs_f64(v.min(3600.0)));
    let head = Io::Head {
        status: resp.status().as_u16(),
        content_type: header("content-type").unwrap_or_default().to_ascii_lowercase(),
        retry_after,
    };
    if tx.send(head).is_err() {
        return;
    }
    let mut reader = resp.into_body().into_reader();
    let mut buf = vec![0u8; 16 * 1024];
    loop {
        if abandon.load(Ordering::SeqCst) {
            return;
        }
        match reader.read(&mut buf) {
            Ok(0) => {
                let _ = tx.send(Io::End);
                return;
            }
            Ok(n) => {
                if tx.send(Io::Bytes(buf[..n].to_vec())).is_err() {
                    return;
                }
            }
            Err(e) => {
                let _ = tx.send(Io::Failed(transport_error(ureq::Error::from(e))));
                return;
            }
        }
    }
}

pub(crate) fn transport_error(e: ureq::Error) -> AttemptError {
    match e {
        ureq::Error::Timeout(t) => AttemptError::new(LlmOutcome::Timeout, format!("no answer in time ({t})")),
        ureq::Error::Io(io) if matches!(io.kind(), std::io::ErrorKind::TimedOut | std::io::ErrorKind::WouldBlock) => {
            AttemptError::new(LlmOutcome::Timeout, "no answer in time")
        }
        ureq::Error::Io(io) => AttemptError::new(LlmOutcome::ConnectionFailed, format!("connection failed: {io}")),
        ureq::Error::HostNotFound => AttemptError::new(LlmOutcome::ConnectionFailed, "host not found"),
        ureq::Error::ConnectionFailed => AttemptError::new(LlmOutcome::ConnectionFailed, "connection failed"),
        ureq::Error::BadUri(u) => AttemptError::new(LlmOutcome::Rejected, format!("bad URL {u}")),
        ureq::Error::Protocol(p) => AttemptError::new(LlmOutcome::Malformed, format!("not HTTP: {p}")),
        other => AttemptError::new(LlmOutcome::ConnectionFailed, other.to_string()),
    }
}

/// A 2xx response's body, or the error a non-2xx one means, for blocking callers (the
/// embeddings stage).
pub(crate) fn http_error(resp: ureq::http::Response<ureq::Body>) -> Result<ureq::Body, AttemptError> {
    let status = resp.status().as_u16();
    let retry_after = resp
        .headers()
        .get("retry-after")
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.trim().parse::<f64>().ok())
        .filter(|v| v.is_finite() && *v >= 0.0)
        .map(|v| Duration::from_secs_f64(v.min(3600.0)));
    let mut body = resp.into_body();
    if (200..300).contains(&status) {
        return Ok(body);
    }
    let text = body
        .with_config()
        .limit(crate::client::MAX_ERROR_BYTES as u64)
        .read_to_vec()
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .unwrap_or_default();
    Err(status_error(status, text, retry_after))
}

/// The error an HTTP status and its body mean.
pub(crate) fn status_error(status: u16, text: String, retry_after: Option<Duration>) -> AttemptError {
    let message = crate::answer::error_message(&text).unwrap_or_else(|| crate::lenient::preview(&text));
    let outcome = match status {
        429 => LlmOutcome::RateLimited,
        500..=599 => LlmOutcome::ServerError,
        _ => LlmOutcome::Rejected,
    };
    AttemptError {
        outcome,
        message: format!("HTTP {status}: {message}"),
        retry_after,
        status: Some(status),
        body: text,
        deterministic: false,
    }
}
