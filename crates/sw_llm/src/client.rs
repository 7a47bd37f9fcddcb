//! The client: a call is one or more attempts, each a bounded HTTP exchange; between
//! them the request may change (a simpler structured-output dialect the server refused
//! the richer one), the call may wait (back-off on 429/5xx and broken connections, longer
//! for a server that is loading its model or restarting), and every call, however it
//! ends, becomes one telemetry record with each failed attempt's error.
//!
//! Bounds: a token limit sized from the request ([`crate::budget`]), the server's silence
//! (until the first byte and between pieces of a stream; a stream that keeps coming is not
//! cut), a hard limit per attempt, a number of places per server ([`crate::limits`]), and
//! cancellation ([`crate::cancel`]). An answer cut off at the token limit is its own
//! outcome (`length`) and, like a first-byte timeout at temperature 0, is never asked
//! again unchanged: one that ends in a loop is refused as a loop; a long one is asked
//! once more with twice the room (up to [`crate::budget::CEILING`]) unless the endpoint's
//! own limit was set, and otherwise refused saying which limit to raise.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use sw_plan::{LlmCall, LlmOutcome, LlmStage};
use tracing::{debug, info_span};

use crate::budget;
use crate::cancel::{self, CancelToken, any_cancelled};
use crate::config::{Endpoint, LlmConfig};
use crate::dialect::{self, Learnt, Refusal, refusal};
use crate::exchange::attempt;
use crate::limits;
use crate::request::ChatRequest;

/// The largest error body read, bytes.
pub(crate) const MAX_ERROR_BYTES: usize = 64 << 10;

/// A model's answer and what it cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Completion {
    pub content: String,
    /// `stop`, … when the server said (`length` never: that is an error).
    pub finish_reason: Option<String>,
    pub tokens_in: u64,
    pub tokens_out: u64,
    pub tokens_estimated: bool,
    pub latency: Duration,
    pub first_token: Option<Duration>,
    pub retries: u32,
    /// The model the server said answered.
    pub served_model: Option<String>,
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

    /// The endpoint never answered (nothing listening, no route): the words a report
    /// uses are "could not be reached" only then.
    pub fn unreachable(&self) -> bool {
        matches!(self.outcome(), LlmOutcome::ConnectionFailed) && !self.to_string().contains("HTTP ")
    }
}

type Calls = Arc<Mutex<Vec<LlmCall>>>;

/// The calls a client made, shared by its clones; also recorded in the taps it was
/// given (see [`Client::fresh_tapped`]).
#[derive(Debug, Clone, Default)]
pub struct Telemetry {
    calls: Calls,
    taps: Vec<Calls>,
}

impl Telemetry {
    pub fn record(&self, call: LlmCall) {
        crate::metrics::record(&call);
        for tap in &self.taps {
            tap.lock().unwrap_or_else(|p| p.into_inner()).push(call.clone());
        }
        self.calls.lock().unwrap_or_else(|p| p.into_inner()).push(call);
    }

    /// Adds calls another client already recorded (and counted in the metrics, and
    /// recorded in its taps: not again in these).
    pub fn extend(&self, calls: Vec<LlmCall>) {
        self.calls.lock().unwrap_or_else(|p| p.into_inner()).extend(calls);
    }

    /// Every call so far, in the order they ended.
    pub fn calls(&self) -> Vec<LlmCall> {
        self.calls.lock().unwrap_or_else(|p| p.into_inner()).clone()
    }

    /// Every call so far; the record starts empty again.
    pub fn take(&self) -> Vec<LlmCall> {
        std::mem::take(&mut *self.calls.lock().unwrap_or_else(|p| p.into_inner()))
    }

    /// An empty record with the same taps.
    fn child(&self) -> Telemetry {
        Telemetry { calls: Calls::default(), taps: self.taps.clone() }
    }
}

/// An OpenAI-compatible chat-completions client with an endpoint per stage.
#[derive(Debug, Clone)]
pub struct Client {
    config: LlmConfig,
    telemetry: Telemetry,
    agents: Arc<Mutex<Vec<(LlmStage, ureq::Agent)>>>,
}

/// Everything a call's record needs besides its outcome.
struct CallLog<'a> {
    stage: LlmStage,
    ep: &'a Endpoint,
    purpose: &'a str,
    started: Instant,
    streamed: bool,
    max_tokens: Option<u32>,
    dialect: Option<&'static str>,
    attempt_errors: Vec<String>,
    retries: u32,
}

impl CallLog<'_> {
    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        outcome: LlmOutcome,
        error: Option<String>,
        tokens: (u64, u64, bool),
        first_token: Option<Duration>,
        served_model: Option<String>,
    ) -> LlmCall {
        LlmCall {
            stage: self.stage,
            model: self.ep.model.clone(),
            served_model,
            endpoint: self.ep.origin(),
            streamed: self.streamed,
            latency_ms: ms(self.started.elapsed()),
            first_token_ms: first_token.map(ms),
            tokens_in: tokens.0,
            tokens_out: tokens.1,
            tokens_estimated: tokens.2,
            retries: self.retries,
            outcome,
            error,
            attempt_errors: std::mem::take(&mut self.attempt_errors),
            dialect: self.dialect.map(str::to_string),
            max_tokens: self.max_tokens,
            purpose: self.purpose.to_string(),
        }
    }
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

    /// A client with the same endpoints and a fresh telemetry record (still recording
    /// into this one's taps).
    pub fn fresh(&self) -> Client {
        Client { config: self.config.clone(), telemetry: self.telemetry.child(), agents: Arc::clone(&self.agents) }
    }

    /// A fresh client whose calls, and those of every fresh client made from it, are
    /// also recorded in `tap`: for a caller that hands a client to code which takes its
    /// own fresh copy (an edit does) and wants the calls even when that code fails.
    pub fn fresh_tapped(&self, tap: &Telemetry) -> Client {
        let mut c = self.fresh();
        c.telemetry.taps.push(Arc::clone(&tap.calls));
        c
    }

    /// Asks and waits for the whole answer (streamed underneath when the endpoint
    /// streams, so that silence and cancellation are noticed while it is written).
    pub fn complete(&self, stage: LlmStage, req: &ChatRequest, purpose: &str) -> Result<Completion, LlmError> {
        self.call(stage, req, purpose, &mut |_| {})
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
        self.call(stage, req, purpose, on)
    }

    pub(crate) fn agent(&self, stage: LlmStage, ep: &Endpoint) -> ureq::Agent {
        let mut agents = self.agents.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, a)) = agents.iter().find(|(s, _)| *s == stage) {
            return a.clone();
        }
        // Chat calls are bounded by the caller's deadlines; the agent's global timeout
        // only ends the threads of exchanges the caller walked away from. No connection is
        // kept for the next call: a local server closes a kept-alive connection after a
        // streamed answer (llama.cpp's did, and the next request on it was lost), and a
        // connection per call costs nothing next to a model's answer.
        let global = if stage == LlmStage::Embeddings { ep.timeout } else { ep.max_call.max(ep.timeout) };
        let agent: ureq::Agent = ureq::Agent::config_builder()
            .http_status_as_error(false)
            .timeout_global(Some(global + Duration::from_secs(1)))
            .timeout_connect(Some(ep.connect_timeout))
            .max_idle_connections(0)
            .max_idle_connections_per_host(0)
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
        on: &mut dyn FnMut(StreamEvent<'_>),
    ) -> Result<Completion, LlmError> {
        let ep = self.config.endpoint(stage).ok_or(LlmError::NotConfigured(stage))?;
        let _span = info_span!("llm", stage = stage.name(), model = %ep.model, purpose).entered();
        let tokens = cancel::current();
        let agent = self.agent(stage, ep);
        let mut learnt = dialect::learnt(ep);
        let fixed = ep.max_tokens.or(req.max_tokens);
        let mut max_tokens = fixed.or_else(|| budget::max_tokens_for(stage, req));
        let mut log = CallLog {
            stage,
            ep,
            purpose,
            started: Instant::now(),
            streamed: ep.stream,
            max_tokens,
            dialect: None,
            attempt_errors: Vec::new(),
            retries: 0,
        };
        let estimate_in = req.text_len().div_ceil(4) as u64;
        let mut plain_retries = 0u32;
        let fail = |log: &mut CallLog<'_>, outcome: LlmOutcome, message: String| -> LlmError {
            let attempts = log.retries + 1;
            let call = log.call(outcome, Some(message.clone()), (estimate_in, 0, true), None, None);
            self.telemetry.record(call);
            let message = if attempts > 1 { format!("{message} (after {attempts} attempts)") } else { message };
            LlmError::Failed { stage, endpoint: ep.origin(), outcome, message }
        };
        loop {
            if log.retries > 0 {
                on(StreamEvent::Restart);
            }
            log.dialect = req.schema.as_ref().map(|_| learnt.dialect.name());
            let Ok((slot, _waited)) = limits::acquire(ep, &tokens) else {
                return Err(fail(&mut log, LlmOutcome::Cancelled, "cancelled: the answer is no longer needed".into()));
            };
            let t0 = Instant::now();
            let result = attempt(&agent, ep, req, learnt, max_tokens, &tokens, on);
            drop(slot);
            let e = match result {
                Ok(a) => {
                    dialect::remember(ep, Learnt { answered: true, ..learnt });
                    let first_token = a.first_token.map(|f| f + (t0 - log.started));
                    let (tokens_in, tokens_out, estimated) = match a.usage {
                        Some((i, o)) => (i, o, false),
                        // llama.cpp servers send a token per streamed piece.
                        None if a.pieces > 0 => (estimate_in, a.pieces.max(a.content.len().div_ceil(4) as u64), true),
                        None => (estimate_in, a.content.len().div_ceil(4) as u64, true),
                    };
                    if a.finish_reason.as_deref() == Some("length") {
                        let limit = max_tokens.map_or_else(|| "the server's".to_string(), |n| n.to_string());
                        let looped = budget::repetition(&a.content);
                        // A long answer, not a loop, under a limit we chose: once more with
                        // twice the room (a different request, not the same one again).
                        if looped.is_none()
                            && fixed.is_none()
                            && let Some(n) = max_tokens.filter(|n| *n < budget::CEILING)
                        {
                            max_tokens = Some((n * 2).min(budget::CEILING));
                            log.max_tokens = max_tokens;
                            log.attempt_errors.push(format!(
                                "the answer was longer than {n} tokens; asked again with {} tokens",
                                (n * 2).min(budget::CEILING)
                            ));
                            log.retries += 1;
                            continue;
                        }
                        let message = match &looped {
                            Some(r) => format!(
                                "the model looped: its answer repeats «{}» {} times and was cut off at the token \
                                 limit ({limit} tokens); not asked again unchanged",
                                r.unit.trim(),
                                r.times
                            ),
                            None => format!(
                                "the answer was longer than the token limit ({limit} tokens, {} bytes written) and \
                                 is not a loop; raise SCENEWRIGHT_LLM_MAX_TOKENS (or the stage's) above {limit}",
                                a.content.len()
                            ),
                        };
                        let attempts = log.retries + 1;
                        let mut call = log.call(
                            LlmOutcome::Length,
                            Some(message.clone()),
                            (tokens_in, tokens_out, estimated),
                            first_token,
                            a.served_model,
                        );
                        call.latency_ms = ms(log.started.elapsed());
                        self.telemetry.record(call);
                        let message =
                            if attempts > 1 { format!("{message} (after {attempts} attempts)") } else { message };
                        return Err(LlmError::Failed {
                            stage,
                            endpoint: ep.origin(),
                            outcome: LlmOutcome::Length,
                            message,
                        });
                    }
                    let call = log.call(
                        LlmOutcome::Ok,
                        None,
                        (tokens_in, tokens_out, estimated),
                        first_token,
                        a.served_model.clone(),
                    );
                    self.telemetry.record(call);
                    return Ok(Completion {
                        content: a.content,
                        finish_reason: a.finish_reason,
                        tokens_in,
                        tokens_out,
                        tokens_estimated: estimated,
                        latency: log.started.elapsed(),
                        first_token,
                        retries: log.retries,
                        served_model: a.served_model,
                    });
                }
                Err(e) => e,
            };
            debug!(outcome = ?e.outcome, message = %e.message, "LLM attempt failed");
            if e.status.is_some() {
                dialect::remember(ep, Learnt { answered: true, ..learnt });
            }
            // A refused part of the request: ask again at once, more simply.
            if let Some(status) = e.status {
                match refusal(status, &e.body) {
                    Some(Refusal::ResponseFormat) if req.schema.is_some() => {
                        if let Some(next) = learnt.dialect.next() {
                            learnt.dialect = next;
                            dialect::remember(ep, learnt);
                            log.attempt_errors.push(e.message);
                            log.retries += 1;
                            continue;
                        }
                    }
                    Some(Refusal::StreamOptions) if ep.stream && !learnt.no_stream_options => {
                        learnt.no_stream_options = true;
                        dialect::remember(ep, learnt);
                        log.attempt_errors.push(e.message);
                        log.retries += 1;
                        continue;
                    }
                    _ => {}
                }
            }
            if e.outcome == LlmOutcome::Cancelled {
                return Err(fail(&mut log, e.outcome, e.message));
            }
            // A server loading its model, or one that answered before and now refuses
            // connections (restarting), is waited for up to `load_wait`.
            let restarting = e.refused() && learnt.answered;
            if (e.loading() || restarting) && log.started.elapsed() < ep.load_wait {
                let pause = backoff(ep, plain_retries.min(3), e.retry_after)
                    .max(Duration::from_millis(250))
                    .min(ep.load_wait.saturating_sub(log.started.elapsed()));
                if !sleep(pause, &tokens) {
                    return Err(fail(&mut log, LlmOutcome::Cancelled, "cancelled while waiting for the server".into()));
                }
                log.attempt_errors.push(e.message);
                log.retries += 1;
                continue;
            }
            if e.retryable() && plain_retries < ep.max_retries {
                if !sleep(backoff(ep, plain_retries, e.retry_after), &tokens) {
                    return Err(fail(&mut log, LlmOutcome::Cancelled, "cancelled while waiting to retry".into()));
                }
                plain_retries += 1;
                log.attempt_errors.push(e.message);
                log.retries += 1;
                continue;
            }
            return Err(fail(&mut log, e.outcome, e.message));
        }
    }
}

/// Sleeps `d`, or less when a token is cancelled (then false).
fn sleep(d: Duration, tokens: &[CancelToken]) -> bool {
    let end = Instant::now() + d;
    loop {
        if any_cancelled(tokens) {
            return false;
        }
        let now = Instant::now();
        if now >= end {
            return true;
        }
        std::thread::sleep((end - now).min(Duration::from_millis(50)));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backoff_doubles_and_is_capped() {
        let mut ep = Endpoint::new("http://x", "m");
        ep.backoff = Duration::from_millis(100);
        ep.max_backoff = Duration::from_millis(300);
        assert!(backoff(&ep, 0, None) <= Duration::from_millis(125));
        assert!(backoff(&ep, 5, None) <= Duration::from_millis(300));
        assert_eq!(backoff(&ep, 0, Some(Duration::from_secs(60))), Duration::from_millis(300));
    }

    #[test]
    fn a_cancelled_sleep_ends_early() {
        let t = CancelToken::new();
        t.cancel();
        let t0 = Instant::now();
        assert!(!sleep(Duration::from_secs(5), &[t]));
        assert!(t0.elapsed() < Duration::from_millis(200));
    }
}
