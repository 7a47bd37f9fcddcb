//! The client: one blocking HTTP call per attempt, retries with back-off on 429, 5xx,
//! timeouts and broken connections, a simpler request for servers that reject parts of
//! the OpenAI shape, and a telemetry record for every call.

use std::io::Read;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use serde_json::Value;
use sw_plan::{LlmCall, LlmOutcome, LlmStage};
use tracing::{debug, info_span};

use crate::config::{Endpoint, LlmConfig};
use crate::lenient::preview;
use crate::request::{ChatRequest, Shape, body};
use crate::sse::{SseEvent, SseParser};

/// The largest answer accepted, bytes.
pub(crate) const MAX_ANSWER_BYTES: usize = 8 << 20;
/// The largest error body read, bytes.
pub(crate) const MAX_ERROR_BYTES: u64 = 64 << 10;

/// A model's answer and what it cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Completion {
    pub content: String,
    /// `stop`, `length` (cut off by the token limit), … when the server said.
    pub finish_reason: Option<String>,
    pub tokens_in: u64,
    pub tokens_out: u64,
    pub tokens_estimated: bool,
    pub latency: Duration,
    pub first_token: Option<Duration>,
    pub retries: u32,
}

/// What a streamed call reports while it runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StreamEvent<'a> {
    /// A piece of the answer.
    Delta(&'a str),
    /// The answer is being asked for again (a retry): forget the pieces so far.
    Restart,
}

/// Why a call produced no answer. Each names the stage and the endpoint.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LlmError {
    #[error("no LLM endpoint is configured for the {} stage (set SCENEWRIGHT_LLM_BASE_URL and SCENEWRIGHT_LLM_MODEL)", .0.name())]
    NotConfigured(LlmStage),
    #[error("{} stage, {endpoint}: {message}", .stage.name())]
    Failed { stage: LlmStage, endpoint: String, outcome: LlmOutcome, message: String },
}

impl LlmError {
    pub fn outcome(&self) -> LlmOutcome {
        match self {
            LlmError::NotConfigured(_) => LlmOutcome::Rejected,
            LlmError::Failed { outcome, .. } => *outcome,
        }
    }
}

/// The calls a client made, shared by its clones.
#[derive(Debug, Clone, Default)]
pub struct Telemetry(Arc<Mutex<Vec<LlmCall>>>);

impl Telemetry {
    pub fn record(&self, call: LlmCall) {
        crate::metrics::record(&call);
        match self.0.lock() {
            Ok(mut v) => v.push(call),
            Err(p) => p.into_inner().push(call),
        }
    }

    /// Adds calls another client already recorded (and counted in the metrics).
    pub fn extend(&self, calls: Vec<LlmCall>) {
        match self.0.lock() {
            Ok(mut v) => v.extend(calls),
            Err(p) => p.into_inner().extend(calls),
        }
    }

    /// Every call so far, in the order they ended.
    pub fn calls(&self) -> Vec<LlmCall> {
        match self.0.lock() {
            Ok(v) => v.clone(),
            Err(p) => p.into_inner().clone(),
        }
    }

    /// Every call so far; the record starts empty again.
    pub fn take(&self) -> Vec<LlmCall> {
        match self.0.lock() {
            Ok(mut v) => std::mem::take(&mut *v),
            Err(p) => std::mem::take(&mut *p.into_inner()),
        }
    }
}

/// An OpenAI-compatible chat-completions client with an endpoint per stage.
#[derive(Debug, Clone)]
pub struct Client {
    config: LlmConfig,
    telemetry: Telemetry,
    agents: Arc<Mutex<Vec<(LlmStage, ureq::Agent)>>>,
}

/// One failed attempt.
#[derive(Debug)]
pub(crate) struct AttemptError {
    pub(crate) outcome: LlmOutcome,
    pub(crate) message: String,
    pub(crate) retry_after: Option<Duration>,
    /// The server refused part of the request shape (a simpler one may work).
    shape_refused: bool,
}

impl AttemptError {
    pub(crate) fn new(outcome: LlmOutcome, message: impl Into<String>) -> Self {
        Self { outcome, message: message.into(), retry_after: None, shape_refused: false }
    }

    pub(crate) fn retryable(&self) -> bool {
        matches!(
            self.outcome,
            LlmOutcome::RateLimited
                | LlmOutcome::ServerError
                | LlmOutcome::Timeout
                | LlmOutcome::ConnectionFailed
                | LlmOutcome::Truncated
        )
    }
}

/// A successful attempt.
struct Answer {
    content: String,
    finish_reason: Option<String>,
    usage: Option<(u64, u64)>,
    first_token: Option<Duration>,
}

impl Client {
    pub fn new(config: LlmConfig) -> Self {
        Self { config, telemetry: Telemetry::default(), agents: Arc::new(Mutex::new(Vec::new())) }
    }

    pub fn config(&self) -> &LlmConfig {
        &self.config
    }

    /// True when `stage` has an endpoint.
    pub fn has(&self, stage: LlmStage) -> bool {
        self.config.endpoint(stage).is_some()
    }

    pub fn telemetry(&self) -> &Telemetry {
        &self.telemetry
    }

    /// A client with the same endpoints and a fresh telemetry record.
    pub fn fresh(&self) -> Client {
        Client { config: self.config.clone(), telemetry: Telemetry::default(), agents: Arc::clone(&self.agents) }
    }

    /// Asks once (with retries) and waits for the whole answer.
    pub fn complete(&self, stage: LlmStage, req: &ChatRequest, purpose: &str) -> Result<Completion, LlmError> {
        self.call(stage, req, purpose, false, &mut |_| {})
    }

    /// Asks for a streamed answer and reports its pieces as they arrive. Endpoints
    /// configured with `stream: false` are asked for the whole answer, reported as one
    /// piece.
    pub fn stream(
        &self,
        stage: LlmStage,
        req: &ChatRequest,
        purpose: &str,
        on: &mut dyn FnMut(StreamEvent<'_>),
    ) -> Result<Completion, LlmError> {
        self.call(stage, req, purpose, true, on)
    }

    pub(crate) fn agent(&self, stage: LlmStage, ep: &Endpoint) -> ureq::Agent {
        let mut agents = match self.agents.lock() {
            Ok(a) => a,
            Err(p) => p.into_inner(),
        };
        if let Some((_, a)) = agents.iter().find(|(s, _)| *s == stage) {
            return a.clone();
        }
        let agent: ureq::Agent = ureq::Agent::config_builder()
            .http_status_as_error(false)
            .timeout_global(Some(ep.timeout))
            .timeout_connect(Some(ep.connect_timeout))
            .user_agent(format!("scenewright/{}", env!("CARGO_PKG_VERSION")))
            .build()
            .into();
        agents.push((stage, agent.clone()));
        agent
    }

    fn call(
        &self,
        stage: LlmStage,
        req: &ChatRequest,
        purpose: &str,
        want_stream: bool,
        on: &mut dyn FnMut(StreamEvent<'_>),
    ) -> Result<Completion, LlmError> {
        let ep = self.config.endpoint(stage).ok_or(LlmError::NotConfigured(stage))?;
        let _span = info_span!("llm", stage = stage.name(), model = %ep.model, purpose).entered();
        let stream = want_stream && ep.stream;
        let agent = self.agent(stage, ep);
        let started = Instant::now();
        let mut retries = 0u32;
        let mut shape = Shape::Full;
        let mut attempt_no = 0u32;
        loop {
            attempt_no += 1;
            if attempt_no > 1 {
                on(StreamEvent::Restart);
            }
            let t0 = Instant::now();
            let result = attempt(&agent, ep, req, stream, shape, on);
            match result {
                Ok(a) => {
                    let (tokens_in, tokens_out, estimated) = match a.usage {
                        Some((i, o)) => (i, o, false),
                        None => (req.text_len().div_ceil(4) as u64, a.content.len().div_ceil(4) as u64, true),
                    };
                    let latency = started.elapsed();
                    let first_token = a.first_token.map(|f| f + (t0 - started));
                    self.telemetry.record(LlmCall {
                        stage,
                        model: ep.model.clone(),
                        endpoint: ep.origin(),
                        streamed: stream,
                        latency_ms: ms(latency),
                        first_token_ms: first_token.map(ms),
                        tokens_in,
                        tokens_out,
                        tokens_estimated: estimated,
                        retries,
                        outcome: LlmOutcome::Ok,
                        error: None,
                        purpose: purpose.to_string(),
                    });
                    return Ok(Completion {
                        content: a.content,
                        finish_reason: a.finish_reason,
                        tokens_in,
                        tokens_out,
                        tokens_estimated: estimated,
                        latency,
                        first_token,
                        retries,
                    });
                }
                Err(e) => {
                    debug!(outcome = ?e.outcome, message = %e.message, "LLM attempt failed");
                    if e.shape_refused
                        && let Some(next) = shape.next()
                    {
                        // Not a transient failure: ask again, more simply, at once.
                        shape = next;
                        retries += 1;
                        continue;
                    }
                    if e.retryable() && retries < ep.max_retries {
                        std::thread::sleep(backoff(ep, retries, e.retry_after));
                        retries += 1;
                        continue;
                    }
                    let latency = started.elapsed();
                    self.telemetry.record(LlmCall {
                        stage,
                        model: ep.model.clone(),
                        endpoint: ep.origin(),
                        streamed: stream,
                        latency_ms: ms(latency),
                        first_token_ms: None,
                        tokens_in: req.text_len().div_ceil(4) as u64,
                        tokens_out: 0,
                        tokens_estimated: true,
                        retries,
                        outcome: e.outcome,
                        error: Some(e.message.clone()),
                        purpose: purpose.to_string(),
                    });
                    let attempts =
                        if retries > 0 { format!(" (after {} attempts)", retries + 1) } else { String::new() };
                    return Err(LlmError::Failed {
                        stage,
                        endpoint: ep.origin(),
                        outcome: e.outcome,
                        message: format!("{}{attempts}", e.message),
                    });
                }
            }
        }
    }
}

pub(crate) fn ms(d: Duration) -> f64 {
    (d.as_secs_f64() * 1e6).round() / 1e3
}

/// Exponential back-off with ±25 % jitter, or the server's `Retry-After`, capped.
pub(crate) fn backoff(ep: &Endpoint, retry: u32, retry_after: Option<Duration>) -> Duration {
    if let Some(ra) = retry_after {
        return ra.min(ep.max_backoff);
    }
    let base = ep.backoff.as_secs_f64() * 2f64.powi(retry.min(16) as i32);
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.subsec_nanos());
    let jitter = 0.75 + 0.5 * f64::from(nanos % 1000) / 1000.0;
    Duration::from_secs_f64((base * jitter).min(ep.max_backoff.as_secs_f64()))
}

fn attempt(
    agent: &ureq::Agent,
    ep: &Endpoint,
    req: &ChatRequest,
    stream: bool,
    shape: Shape,
    on: &mut dyn FnMut(StreamEvent<'_>),
) -> Result<Answer, AttemptError> {
    let started = Instant::now();
    let payload = body(req, ep, stream, shape).to_string();
    let mut r = agent
        .post(ep.completions_url())
        .header("content-type", "application/json")
        .header("accept", if stream { "text/event-stream" } else { "application/json" });
    if let Some(k) = &ep.api_key {
        r = r.header("authorization", format!("Bearer {}", k.expose()));
    }
    let resp = r.send(payload.as_bytes()).map_err(transport_error)?;
    let content_type =
        resp.headers().get("content-type").and_then(|v| v.to_str().ok()).unwrap_or("").to_ascii_lowercase();
    let mut body = match http_error(resp) {
        Ok(body) => body,
        Err((mut e, status, text)) => {
            let lower = text.to_ascii_lowercase();
            e.shape_refused = matches!(status, 400 | 422)
                && shape != Shape::Plain
                && [
                    "response_format",
                    "json_schema",
                    "stream_options",
                    "unsupported",
                    "not supported",
                    "extra",
                    "unknown",
                ]
                .iter()
                .any(|w| lower.contains(w));
            return Err(e);
        }
    };
    if stream && content_type.contains("text/event-stream") {
        read_stream(body.into_reader(), started, on)
    } else {
        // Not streamed (asked for, or the server ignored `stream`): one JSON document.
        let bytes = body.with_config().limit(MAX_ANSWER_BYTES as u64).read_to_vec().map_err(|e| match e {
            ureq::Error::BodyExceedsLimit(_) => {
                AttemptError::new(LlmOutcome::Malformed, format!("the answer exceeds {} MB", MAX_ANSWER_BYTES >> 20))
            }
            other => transport_error(other),
        })?;
        let a = parse_completion(&String::from_utf8_lossy(&bytes))?;
        if !a.content.is_empty() {
            on(StreamEvent::Delta(&a.content));
        }
        Ok(Answer { first_token: Some(started.elapsed()), ..a })
    }
}

/// A 2xx response's body, or the error a non-2xx one means (with its `Retry-After`), its
/// status and the error body's text.
pub(crate) fn http_error(resp: ureq::http::Response<ureq::Body>) -> Result<ureq::Body, (AttemptError, u16, String)> {
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
        .limit(MAX_ERROR_BYTES)
        .read_to_vec()
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .unwrap_or_default();
    let message = error_message(&text).unwrap_or_else(|| preview(&text));
    let outcome = match status {
        429 => LlmOutcome::RateLimited,
        500..=599 => LlmOutcome::ServerError,
        _ => LlmOutcome::Rejected,
    };
    let e = AttemptError { outcome, message: format!("HTTP {status}: {message}"), retry_after, shape_refused: false };
    Err((e, status, text))
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

/// `{"error": {"message": …}}` or `{"error": "…"}` or `{"message": …}`.
pub(crate) fn error_message(text: &str) -> Option<String> {
    let v: Value = serde_json::from_str(text).ok()?;
    let e = v.get("error").unwrap_or(&v);
    let m = e.get("message").and_then(Value::as_str).or_else(|| e.as_str())?;
    Some(preview(m))
}

fn usage_of(v: &Value) -> Option<(u64, u64)> {
    let u = v.get("usage").filter(|u| u.is_object())?;
    let get = |names: &[&str]| names.iter().find_map(|n| u.get(*n).and_then(Value::as_u64));
    Some((get(&["prompt_tokens", "input_tokens"])?, get(&["completion_tokens", "output_tokens"]).unwrap_or(0)))
}

/// The arguments of a message's (or a streamed delta's) first tool call: how some servers
/// answer structured output.
fn tool_arguments(message: Option<&Value>) -> Option<String> {
    message?.get("tool_calls")?.get(0)?.get("function")?.get("arguments")?.as_str().map(str::to_string)
}

/// The text of a message's `content`: a string, or an array of parts.
fn content_text(c: &Value) -> Option<String> {
    match c {
        Value::String(s) => Some(s.clone()),
        Value::Array(parts) => {
            let s: String =
                parts.iter().filter_map(|p| p.get("text").and_then(Value::as_str).or_else(|| p.as_str())).collect();
            Some(s)
        }
        _ => None,
    }
}

fn parse_completion(text: &str) -> Result<Answer, AttemptError> {
    let v: Value = serde_json::from_str(text.trim_start_matches('\u{feff}')).map_err(|_| {
        AttemptError::new(LlmOutcome::Malformed, format!("the response is not JSON (it begins \"{}\")", preview(text)))
    })?;
    if let Some(e) = v.get("error").filter(|e| !e.is_null()) {
        let m = e.get("message").and_then(Value::as_str).or_else(|| e.as_str()).unwrap_or("unknown error");
        return Err(AttemptError::new(
            LlmOutcome::ServerError,
            format!("the server answered with an error: {}", preview(m)),
        ));
    }
    let choice = v.get("choices").and_then(|c| c.get(0)).ok_or_else(|| {
        AttemptError::new(
            LlmOutcome::Malformed,
            format!("the response has no choices (it begins \"{}\")", preview(text)),
        )
    })?;
    let message = choice.get("message");
    let content = message
        .and_then(|m| m.get("content"))
        .and_then(content_text)
        .filter(|s| !s.trim().is_empty())
        // Some servers answer structured output as a tool call.
        .or_else(|| tool_arguments(message))
        .or_else(|| choice.get("text").and_then(Value::as_str).map(str::to_string))
        .unwrap_or_default();
    if content.len() > MAX_ANSWER_BYTES {
        return Err(AttemptError::new(LlmOutcome::Malformed, "the answer is too long"));
    }
    Ok(Answer {
        content,
        finish_reason: choice.get("finish_reason").and_then(Value::as_str).map(str::to_string),
        usage: usage_of(&v),
        first_token: None,
    })
}

fn read_stream(
    mut reader: impl Read,
    started: Instant,
    on: &mut dyn FnMut(StreamEvent<'_>),
) -> Result<Answer, AttemptError> {
    let mut parser = SseParser::default();
    let mut content = String::new();
    let mut finish_reason: Option<String> = None;
    let mut usage: Option<(u64, u64)> = None;
    let mut first_token: Option<Duration> = None;
    let mut buf = vec![0u8; 16 * 1024];
    let mut done = false;
    let mut handle = |events: Vec<SseEvent>,
                      content: &mut String,
                      finish_reason: &mut Option<String>,
                      usage: &mut Option<(u64, u64)>,
                      first_token: &mut Option<Duration>,
                      done: &mut bool|
     -> Result<(), AttemptError> {
        for ev in events {
            let data = match ev {
                SseEvent::Done => {
                    *done = true;
                    continue;
                }
                SseEvent::Data(d) => d,
            };
            let v: Value = serde_json::from_str(&data).map_err(|_| {
                AttemptError::new(
                    LlmOutcome::Malformed,
                    format!("a streamed event is not JSON: \"{}\"", preview(&data)),
                )
            })?;
            if let Some(e) = v.get("error").filter(|e| !e.is_null()) {
                let m = e.get("message").and_then(Value::as_str).or_else(|| e.as_str()).unwrap_or("unknown error");
                return Err(AttemptError::new(
                    LlmOutcome::ServerError,
                    format!("the stream ended with an error: {}", preview(m)),
                ));
            }
            if let Some(u) = usage_of(&v) {
                *usage = Some(u);
            }
            let Some(choice) = v.get("choices").and_then(|c| c.get(0)) else {
                continue;
            };
            let piece = choice
                .get("delta")
                .and_then(|d| {
                    d.get("content")
                        .and_then(content_text)
                        .filter(|s| !s.is_empty())
                        .or_else(|| tool_arguments(Some(d)))
                })
                .or_else(|| choice.get("text").and_then(Value::as_str).map(str::to_string))
                .unwrap_or_default();
            if !piece.is_empty() {
                if first_token.is_none() {
                    *first_token = Some(started.elapsed());
                }
                if content.len() + piece.len() > MAX_ANSWER_BYTES {
                    return Err(AttemptError::new(LlmOutcome::Malformed, "the streamed answer is too long"));
                }
                content.push_str(&piece);
                on(StreamEvent::Delta(&piece));
            }
            if let Some(f) = choice.get("finish_reason").and_then(Value::as_str) {
                *finish_reason = Some(f.to_string());
            }
        }
        Ok(())
    };
    while !done {
        let n = match reader.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) => {
                let ue = ureq::Error::from(e);
                let mut err = transport_error(ue);
                if err.outcome == LlmOutcome::ConnectionFailed && !content.is_empty() {
                    err = AttemptError::new(LlmOutcome::Truncated, format!("the stream broke off: {}", err.message));
                }
                return Err(err);
            }
        };
        let events = parser.push(&buf[..n]);
        handle(events, &mut content, &mut finish_reason, &mut usage, &mut first_token, &mut done)?;
    }
    if !done {
        let events = parser.finish();
        handle(events, &mut content, &mut finish_reason, &mut usage, &mut first_token, &mut done)?;
    }
    if !done && finish_reason.is_none() {
        return Err(AttemptError::new(
            LlmOutcome::Truncated,
            format!("the stream ended before the answer was complete ({} bytes received)", content.len()),
        ));
    }
    Ok(Answer { content, finish_reason, usage, first_token })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn completions_of_compatible_servers_parse() {
        let a = parse_completion(
            r#"{"choices":[{"message":{"role":"assistant","content":"hi"},"finish_reason":"stop"}],"usage":{"prompt_tokens":3,"completion_tokens":1}}"#,
        )
        .unwrap();
        assert_eq!((a.content.as_str(), a.usage), ("hi", Some((3, 1))));
        let a = parse_completion(
            r#"{"choices":[{"message":{"content":[{"type":"text","text":"a"},{"type":"text","text":"b"}]}}]}"#,
        )
        .unwrap();
        assert_eq!(a.content, "ab");
        let a = parse_completion(
            r#"{"choices":[{"message":{"content":null,"tool_calls":[{"function":{"arguments":"{}"}}]}}]}"#,
        )
        .unwrap();
        assert_eq!(a.content, "{}");
        let a = parse_completion(r#"{"choices":[{"text":"x"}],"usage":{"input_tokens":5,"output_tokens":2}}"#).unwrap();
        assert_eq!((a.content.as_str(), a.usage), ("x", Some((5, 2))));
        assert_eq!(parse_completion("<html>").err().map(|e| e.outcome), Some(LlmOutcome::Malformed));
        assert_eq!(
            parse_completion(r#"{"error":{"message":"overloaded"}}"#).err().map(|e| e.outcome),
            Some(LlmOutcome::ServerError)
        );
        assert_eq!(parse_completion(r#"{"id":"x"}"#).err().map(|e| e.outcome), Some(LlmOutcome::Malformed));
    }

    #[test]
    fn backoff_doubles_and_is_capped() {
        let mut ep = Endpoint::new("http://x", "m");
        ep.backoff = Duration::from_millis(100);
        ep.max_backoff = Duration::from_millis(300);
        assert!(backoff(&ep, 0, None) <= Duration::from_millis(125));
        assert!(backoff(&ep, 5, None) <= Duration::from_millis(300));
        assert_eq!(backoff(&ep, 0, Some(Duration::from_secs(60))), Duration::from_millis(300));
    }
}
