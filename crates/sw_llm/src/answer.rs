//! Reading what a chat-completions server answers: a whole completion (JSON), or a
//! stream of server-sent events read piece by piece, in the shapes compatible servers
//! really send (content as a string or as parts, tool-call arguments, legacy `text`,
//! usage under either name, errors inside a 200).

use std::time::Duration;

use serde_json::Value;
use sw_plan::LlmOutcome;

use crate::lenient::preview;
use crate::sse::{SseEvent, SseParser};

/// The largest answer accepted, bytes.
pub(crate) const MAX_ANSWER_BYTES: usize = 8 << 20;

/// One failed attempt.
#[derive(Debug, Clone)]
pub(crate) struct AttemptError {
    pub(crate) outcome: LlmOutcome,
    pub(crate) message: String,
    pub(crate) retry_after: Option<Duration>,
    /// The HTTP status, when the server answered.
    pub(crate) status: Option<u16>,
    /// The error body's text, when the server answered with an error.
    pub(crate) body: String,
    /// The same request would fail the same way (a first-byte timeout at temperature 0,
    /// the attempt's hard limit): not asked again unchanged.
    pub(crate) deterministic: bool,
}

impl AttemptError {
    pub(crate) fn new(outcome: LlmOutcome, message: impl Into<String>) -> Self {
        Self {
            outcome,
            message: message.into(),
            retry_after: None,
            status: None,
            body: String::new(),
            deterministic: false,
        }
    }

    /// Worth asking again unchanged (after a back-off).
    pub(crate) fn retryable(&self) -> bool {
        !self.deterministic
            && matches!(
                self.outcome,
                LlmOutcome::RateLimited
                    | LlmOutcome::ServerError
                    | LlmOutcome::ConnectionFailed
                    | LlmOutcome::Truncated
                    | LlmOutcome::Timeout
            )
    }

    /// The server says it is loading its model (`503 Loading model`).
    pub(crate) fn loading(&self) -> bool {
        self.status == Some(503) && self.body.to_ascii_lowercase().contains("loading")
    }

    /// Nothing listens at the endpoint (refused or reset before any answer).
    pub(crate) fn refused(&self) -> bool {
        self.outcome == LlmOutcome::ConnectionFailed && self.status.is_none()
    }
}

/// A successful attempt.
#[derive(Debug, Default)]
pub(crate) struct Answer {
    pub(crate) content: String,
    pub(crate) finish_reason: Option<String>,
    pub(crate) usage: Option<(u64, u64)>,
    pub(crate) first_token: Option<Duration>,
    /// The `model` the server named in its answer.
    pub(crate) served_model: Option<String>,
    /// Streamed events that carried a piece of the answer (a token each, on llama.cpp).
    pub(crate) pieces: u64,
}

/// `{"error": {"message": …}}` or `{"error": "…"}` or `{"message": …}` or `{"detail": …}`.
pub(crate) fn error_message(text: &str) -> Option<String> {
    let v: Value = serde_json::from_str(text).ok()?;
    let e = v.get("error").or_else(|| v.get("detail")).unwrap_or(&v);
    let m = e.get("message").and_then(Value::as_str).or_else(|| e.as_str());
    match m {
        Some(m) => Some(preview(m)),
        None if e.is_array() || e.is_object() => Some(preview(&e.to_string())),
        None => None,
    }
}

fn usage_of(v: &Value) -> Option<(u64, u64)> {
    let u = v.get("usage").filter(|u| u.is_object())?;
    let get = |names: &[&str]| names.iter().find_map(|n| u.get(*n).and_then(Value::as_u64));
    Some((get(&["prompt_tokens", "input_tokens"])?, get(&["completion_tokens", "output_tokens"]).unwrap_or(0)))
}

fn model_of(v: &Value) -> Option<String> {
    v.get("model").and_then(Value::as_str).filter(|m| !m.trim().is_empty()).map(|m| m.chars().take(200).collect())
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

fn error_inside(v: &Value, what: &str) -> Option<AttemptError> {
    let e = v.get("error").filter(|e| !e.is_null())?;
    let m = e.get("message").and_then(Value::as_str).or_else(|| e.as_str()).unwrap_or("unknown error");
    Some(AttemptError::new(LlmOutcome::ServerError, format!("{what}: {}", preview(m))))
}

/// A whole (not streamed) completion.
pub(crate) fn parse_completion(text: &str) -> Result<Answer, AttemptError> {
    let v: Value = serde_json::from_str(text.trim_start_matches('\u{feff}')).map_err(|_| {
        AttemptError::new(LlmOutcome::Malformed, format!("the response is not JSON (it begins \"{}\")", preview(text)))
    })?;
    if let Some(e) = error_inside(&v, "the server answered with an error") {
        return Err(e);
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
        served_model: model_of(&v),
        pieces: 0,
    })
}

/// A streamed answer being read.
#[derive(Debug, Default)]
pub(crate) struct StreamReader {
    parser: SseParser,
    pub(crate) answer: Answer,
    /// `data: [DONE]` arrived.
    pub(crate) done: bool,
}

impl StreamReader {
    /// Feeds bytes; `on_piece` sees each piece of the answer.
    pub(crate) fn push(
        &mut self,
        bytes: &[u8],
        elapsed: Duration,
        on_piece: &mut dyn FnMut(&str),
    ) -> Result<(), AttemptError> {
        let events = self.parser.push(bytes);
        self.handle(events, elapsed, on_piece)
    }

    /// The end of the byte stream.
    pub(crate) fn finish(&mut self, elapsed: Duration, on_piece: &mut dyn FnMut(&str)) -> Result<(), AttemptError> {
        if self.done {
            return Ok(());
        }
        let events = self.parser.finish();
        self.handle(events, elapsed, on_piece)
    }

    fn handle(
        &mut self,
        events: Vec<SseEvent>,
        elapsed: Duration,
        on_piece: &mut dyn FnMut(&str),
    ) -> Result<(), AttemptError> {
        for ev in events {
            if self.done {
                break;
            }
            let data = match ev {
                SseEvent::Done => {
                    self.done = true;
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
            if let Some(e) = error_inside(&v, "the stream ended with an error") {
                return Err(e);
            }
            let a = &mut self.answer;
            if let Some(u) = usage_of(&v) {
                a.usage = Some(u);
            }
            if a.served_model.is_none() {
                a.served_model = model_of(&v);
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
                if a.first_token.is_none() {
                    a.first_token = Some(elapsed);
                }
                if a.content.len() + piece.len() > MAX_ANSWER_BYTES {
                    return Err(AttemptError::new(LlmOutcome::Malformed, "the streamed answer is too long"));
                }
                a.content.push_str(&piece);
                a.pieces += 1;
                on_piece(&piece);
            }
            if let Some(f) = choice.get("finish_reason").and_then(Value::as_str) {
                a.finish_reason = Some(f.to_string());
            }
        }
        Ok(())
    }

    /// The answer, when the stream said it was complete: a finish reason is required (a
    /// `[DONE]` without one is how llama-cpp-python's server ends a stream it interrupts).
    pub(crate) fn complete(self) -> Result<Answer, AttemptError> {
        if self.answer.finish_reason.is_none() {
            let how =
                if self.done { "ended ([DONE]) without a finish reason" } else { "ended without a finish reason" };
            return Err(AttemptError::new(
                LlmOutcome::Truncated,
                format!("the stream {how} after {} bytes: the answer is incomplete", self.answer.content.len()),
            ));
        }
        Ok(self.answer)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn completions_of_compatible_servers_parse() {
        let a = parse_completion(
            r#"{"model":"served","choices":[{"message":{"role":"assistant","content":"hi"},"finish_reason":"stop"}],"usage":{"prompt_tokens":3,"completion_tokens":1}}"#,
        )
        .unwrap();
        assert_eq!((a.content.as_str(), a.usage, a.served_model.as_deref()), ("hi", Some((3, 1)), Some("served")));
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
    fn a_done_without_a_finish_reason_is_incomplete() {
        let mut s = StreamReader::default();
        let mut got = String::new();
        s.push(
            b"data: {\"model\":\"m\",\"choices\":[{\"delta\":{\"content\":\"{\\\"a\\\"\"}}]}\n\ndata: [DONE]\n\n",
            Duration::ZERO,
            &mut |p| got.push_str(p),
        )
        .unwrap();
        assert_eq!(got, "{\"a\"");
        assert!(s.done);
        let e = s.complete().unwrap_err();
        assert_eq!(e.outcome, LlmOutcome::Truncated);
        assert!(e.message.contains("[DONE]"), "{}", e.message);
    }

    #[test]
    fn error_bodies_of_every_shape_give_a_message() {
        assert_eq!(error_message(r#"{"error":{"message":"bad"}}"#).as_deref(), Some("bad"));
        assert_eq!(error_message(r#"{"detail":"no such model"}"#).as_deref(), Some("no such model"));
        assert!(
            error_message(r#"{"detail":[{"loc":["body","response_format"]}]}"#).unwrap().contains("response_format")
        );
        assert_eq!(error_message("plain"), None);
    }
}
