//! One attempt of a chat call: the request in the endpoint's dialect, then the answer
//! read with deadlines — the first byte within the endpoint's `timeout`, then (streamed)
//! each piece within `timeout` of the last, never past `max_call` — watching the cancel
//! tokens all along.

use std::time::{Duration, Instant};

use sw_plan::LlmOutcome;

use crate::answer::{Answer, AttemptError, MAX_ANSWER_BYTES, StreamReader, parse_completion};
use crate::cancel::CancelToken;
use crate::client::{MAX_ERROR_BYTES, StreamEvent};
use crate::config::Endpoint;
use crate::dialect::{self, Learnt};
use crate::request::ChatRequest;
use crate::transport::{Exchange, Io, Outgoing, Wait, status_error};

fn secs(d: Duration) -> String {
    format!("{:.1} s", d.as_secs_f64())
}

fn cancelled() -> AttemptError {
    AttemptError::new(LlmOutcome::Cancelled, "cancelled: the answer is no longer needed")
}

/// One attempt; `on` sees the pieces of the answer as they arrive.
pub(crate) fn attempt(
    agent: &ureq::Agent,
    ep: &Endpoint,
    req: &ChatRequest,
    learnt: Learnt,
    max_tokens: Option<u32>,
    tokens: &[CancelToken],
    on: &mut dyn FnMut(StreamEvent<'_>),
) -> Result<Answer, AttemptError> {
    let t0 = Instant::now();
    let stream = ep.stream;
    let mut headers = vec![
        ("content-type".to_string(), "application/json".to_string()),
        ("accept".to_string(), if stream { "text/event-stream" } else { "application/json" }.to_string()),
    ];
    if let Some(k) = &ep.api_key {
        headers.push(("authorization".into(), format!("Bearer {}", k.expose())));
    }
    let body = dialect::body(req, ep, stream, learnt, max_tokens);
    let mut ex = Exchange::start(agent.clone(), Outgoing { url: ep.completions_url(), headers, body });
    let hard = t0 + ep.max_call;
    let first_deadline = (t0 + ep.timeout).min(hard);
    let deterministic = ep.temperature == Some(0.0);
    let silent = |before: &str| {
        let mut e = if Instant::now() >= hard {
            AttemptError::new(
                LlmOutcome::Timeout,
                format!("the attempt took longer than its limit of {} ({before})", secs(ep.max_call)),
            )
        } else {
            AttemptError::new(LlmOutcome::Timeout, format!("the server was silent for {} {before}", secs(ep.timeout)))
        };
        e.deterministic = deterministic || Instant::now() >= hard;
        e
    };
    // The head.
    let (status, content_type, retry_after) = match ex.next(first_deadline, tokens) {
        Wait::Got(Io::Head { status, content_type, retry_after }) => (status, content_type, retry_after),
        Wait::Got(Io::Failed(e)) => return Err(e),
        Wait::Got(_) => return Err(AttemptError::new(LlmOutcome::Malformed, "a body arrived before the response")),
        Wait::TimedOut => return Err(silent("before the first byte of the answer")),
        Wait::Cancelled => return Err(cancelled()),
    };
    if !(200..300).contains(&status) {
        let mut text = Vec::new();
        let deadline = (Instant::now() + ep.timeout).min(hard);
        while let Wait::Got(Io::Bytes(b)) = ex.next(deadline, tokens) {
            text.extend_from_slice(&b);
            if text.len() > MAX_ERROR_BYTES {
                text.truncate(MAX_ERROR_BYTES);
                break;
            }
        }
        return Err(status_error(status, String::from_utf8_lossy(&text).into_owned(), retry_after));
    }
    if stream && content_type.contains("text/event-stream") {
        let mut reader = StreamReader::default();
        let mut deadline = (Instant::now() + ep.timeout).min(hard);
        let mut on_piece = |p: &str| on(StreamEvent::Delta(p));
        loop {
            match ex.next(deadline, tokens) {
                Wait::Got(Io::Bytes(b)) => {
                    reader.push(&b, t0.elapsed(), &mut on_piece)?;
                    if reader.done {
                        break;
                    }
                    deadline = (Instant::now() + ep.timeout).min(hard);
                }
                Wait::Got(Io::End) => {
                    reader.finish(t0.elapsed(), &mut on_piece)?;
                    break;
                }
                Wait::Got(Io::Failed(mut e)) => {
                    if e.outcome == LlmOutcome::ConnectionFailed || e.outcome == LlmOutcome::Timeout {
                        e = AttemptError::new(
                            LlmOutcome::Truncated,
                            format!("the stream broke off after {} bytes: {}", reader.answer.content.len(), e.message),
                        );
                    }
                    return Err(e);
                }
                Wait::Got(Io::Head { .. }) => {
                    return Err(AttemptError::new(LlmOutcome::Malformed, "a second response head arrived"));
                }
                Wait::TimedOut => {
                    let mut e = silent(&format!("after {} bytes of the stream", reader.answer.content.len()));
                    // Silence in the middle of a stream is the server's or the network's
                    // hiccup, not the request's: it may be asked again.
                    e.deterministic = Instant::now() >= hard;
                    return Err(e);
                }
                Wait::Cancelled => return Err(cancelled()),
            }
        }
        return reader.complete();
    }
    // One JSON document (asked for, or the server ignored `stream`).
    let mut bytes = Vec::new();
    loop {
        match ex.next(first_deadline.max((t0 + ep.timeout).min(hard)), tokens) {
            Wait::Got(Io::Bytes(b)) => {
                bytes.extend_from_slice(&b);
                if bytes.len() > MAX_ANSWER_BYTES {
                    return Err(AttemptError::new(
                        LlmOutcome::Malformed,
                        format!("the answer exceeds {} MB", MAX_ANSWER_BYTES >> 20),
                    ));
                }
            }
            Wait::Got(Io::End) => break,
            Wait::Got(Io::Failed(e)) => return Err(e),
            Wait::Got(Io::Head { .. }) => {
                return Err(AttemptError::new(LlmOutcome::Malformed, "a second response head arrived"));
            }
            Wait::TimedOut => return Err(silent("before the whole answer arrived")),
            Wait::Cancelled => return Err(cancelled()),
        }
    }
    let a = parse_completion(&String::from_utf8_lossy(&bytes))?;
    if !a.content.is_empty() {
        on(StreamEvent::Delta(&a.content));
    }
    Ok(Answer { first_token: Some(t0.elapsed()), ..a })
}
