//! How structured output is asked for, per endpoint.
//!
//! "OpenAI-compatible" servers disagree on `response_format`. OpenAI, vLLM and llama.cpp's
//! `llama-server` take `{"type": "json_schema", "json_schema": {"schema": …}}`;
//! llama-cpp-python's server refuses that (HTTP 500, a validation error naming
//! `response_format`) and takes `{"type": "json_object", "schema": …}`; some take only
//! `{"type": "json_object"}`; some nothing at all. A call starts with the richest
//! [`Dialect`] not yet refused by its endpoint and steps down at once (not a retry: the
//! request changed) on any refusal that names the field, whatever the status; the step is
//! remembered per endpoint for the life of the process. With the two weaker dialects the
//! schema goes into the system message instead, so the model still sees it.

use std::collections::BTreeMap;
use std::sync::Mutex;

use serde_json::{Value, json};

use crate::config::Endpoint;
use crate::request::ChatRequest;
use crate::schema::{for_model, to_ordered_string};

/// A way of asking for structured output, richest first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Dialect {
    /// `response_format: {type: json_schema, json_schema: {name, schema, strict: false}}`.
    JsonSchema,
    /// `response_format: {type: json_object, schema}` (llama-cpp-python, Anyscale).
    JsonObjectSchema,
    /// `response_format: {type: json_object}`, the schema in the system message.
    JsonObject,
    /// No `response_format`; the schema in the system message.
    Prompt,
}

impl Dialect {
    pub fn name(self) -> &'static str {
        match self {
            Dialect::JsonSchema => "json_schema",
            Dialect::JsonObjectSchema => "json_object_schema",
            Dialect::JsonObject => "json_object",
            Dialect::Prompt => "prompt",
        }
    }

    pub fn next(self) -> Option<Dialect> {
        match self {
            Dialect::JsonSchema => Some(Dialect::JsonObjectSchema),
            Dialect::JsonObjectSchema => Some(Dialect::JsonObject),
            Dialect::JsonObject => Some(Dialect::Prompt),
            Dialect::Prompt => None,
        }
    }

    /// The schema is enforced by the server (a grammar or constrained decoding).
    pub fn enforced(self) -> bool {
        matches!(self, Dialect::JsonSchema | Dialect::JsonObjectSchema)
    }
}

/// What a process has learnt about one endpoint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Learnt {
    pub dialect: Dialect,
    /// The server refused `stream_options`.
    pub no_stream_options: bool,
    /// The server has answered in this process (so refused connections later mean it
    /// is restarting, and are waited for).
    pub answered: bool,
}

static LEARNT: Mutex<BTreeMap<String, Learnt>> = Mutex::new(BTreeMap::new());

fn first(ep: &Endpoint) -> Learnt {
    Learnt {
        dialect: if ep.structured { Dialect::JsonSchema } else { Dialect::Prompt },
        no_stream_options: !ep.stream_options,
        answered: false,
    }
}

/// What to send to `ep` now.
pub(crate) fn learnt(ep: &Endpoint) -> Learnt {
    let map = LEARNT.lock().unwrap_or_else(|e| e.into_inner());
    let base = first(ep);
    match map.get(&ep.completions_url()) {
        Some(l) => Learnt {
            dialect: l.dialect.max(base.dialect),
            no_stream_options: l.no_stream_options || base.no_stream_options,
            answered: l.answered,
        },
        None => base,
    }
}

/// Remembers what `ep` refused.
pub(crate) fn remember(ep: &Endpoint, l: Learnt) {
    let mut map = LEARNT.lock().unwrap_or_else(|e| e.into_inner());
    let e = map.entry(ep.completions_url()).or_insert(l);
    e.dialect = e.dialect.max(l.dialect);
    e.no_stream_options |= l.no_stream_options;
    e.answered |= l.answered;
}

/// Forgets what was learnt about `ep` (for `llm status`, which probes afresh).
pub fn forget(ep: &Endpoint) {
    LEARNT.lock().unwrap_or_else(|e| e.into_inner()).remove(&ep.completions_url());
}

/// The dialect a process currently uses with `ep`.
pub fn current(ep: &Endpoint) -> Dialect {
    learnt(ep).dialect
}

/// What part of the request an error body refuses, if it names one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Refusal {
    ResponseFormat,
    StreamOptions,
}

/// Reads a refusal out of an error answer (any status: llama-cpp-python answers a
/// request it cannot validate with 500).
pub(crate) fn refusal(status: u16, body: &str) -> Option<Refusal> {
    if !(400..600).contains(&status) || status == 429 || status == 503 {
        return None;
    }
    let lower = body.to_ascii_lowercase();
    if lower.contains("stream_options") {
        return Some(Refusal::StreamOptions);
    }
    let names_format =
        ["response_format", "json_schema", "response format", "json_object"].iter().any(|w| lower.contains(w));
    // 4xx that only say "unsupported"/"unknown field" about a request that carries a
    // response_format are refusals of it too.
    let vague_4xx = (400..500).contains(&status)
        && ["unsupported", "not supported", "unknown field", "extra fields", "extra_forbidden"]
            .iter()
            .any(|w| lower.contains(w));
    (names_format || vague_4xx).then_some(Refusal::ResponseFormat)
}

/// The system message extended with the schema, for dialects that do not send it.
fn schema_note(schema: &Value) -> String {
    format!(
        "\n\nAnswer with one JSON object (no prose, no code fences) that follows this JSON Schema:\n{}",
        to_ordered_string(schema)
    )
}

/// The request body as JSON text (the schema's properties in the caller's order).
pub(crate) fn body(req: &ChatRequest, ep: &Endpoint, stream: bool, l: Learnt, max_tokens: Option<u32>) -> String {
    let schema = req.schema.as_ref().map(|(name, s)| (name, for_model(s)));
    let mut messages: Vec<Value> = Vec::with_capacity(req.messages.len());
    let mut noted = false;
    for m in &req.messages {
        let mut content = m.content.clone();
        if !noted
            && m.role == crate::Role::System
            && let Some((_, s)) = &schema
            && !l.dialect.enforced()
        {
            content.push_str(&schema_note(s));
            noted = true;
        }
        messages.push(json!({ "role": m.role.name(), "content": content }));
    }
    if !noted
        && let Some((_, s)) = &schema
        && !l.dialect.enforced()
    {
        messages.insert(0, json!({ "role": "system", "content": schema_note(s).trim_start() }));
    }
    let mut b = json!({ "model": ep.model, "messages": messages, "stream": stream });
    if let Some(t) = ep.temperature {
        b["temperature"] = json!(t);
    }
    if let Some(n) = max_tokens {
        b["max_tokens"] = json!(n);
    }
    if stream && !l.no_stream_options {
        b["stream_options"] = json!({ "include_usage": true });
    }
    // The schema is spliced in as ordered text below; a placeholder keeps its place.
    const MARK: &str = "\u{0}schema\u{0}";
    let mut schema_text = None;
    if let Some((name, s)) = &schema {
        match l.dialect {
            Dialect::JsonSchema => {
                b["response_format"] =
                    json!({ "type": "json_schema", "json_schema": { "name": name, "schema": MARK, "strict": false } });
                schema_text = Some(to_ordered_string(s));
            }
            Dialect::JsonObjectSchema => {
                b["response_format"] = json!({ "type": "json_object", "schema": MARK });
                schema_text = Some(to_ordered_string(s));
            }
            Dialect::JsonObject => b["response_format"] = json!({ "type": "json_object" }),
            Dialect::Prompt => {}
        }
    }
    let text = b.to_string();
    match schema_text {
        Some(s) => text.replacen(&Value::String(MARK.into()).to_string(), &s, 1),
        None => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Message;

    #[test]
    fn refusals_are_read_from_what_servers_answer() {
        let cpp_python = r#"{"error":{"message":"[{'type': 'literal_error', 'loc': ('body', 'response_format', 'type'), 'msg': \"Input should be 'text' or 'json_object'\"}]"}}"#;
        assert_eq!(refusal(500, cpp_python), Some(Refusal::ResponseFormat));
        assert_eq!(
            refusal(400, r#"{"error":"Unrecognized request argument supplied: stream_options"}"#),
            Some(Refusal::StreamOptions)
        );
        assert_eq!(refusal(422, "unknown field `foo`"), Some(Refusal::ResponseFormat));
        assert_eq!(refusal(500, "CUDA out of memory"), None);
        assert_eq!(refusal(503, "Loading model"), None);
        assert_eq!(refusal(200, "response_format"), None);
    }

    #[test]
    fn each_dialect_sends_the_schema_once() {
        let req = ChatRequest::new(vec![Message::system("sys"), Message::user("u")])
            .with_schema("s", json!({"type": "object", "required": ["b", "a"], "properties": {"a": {"type": "string"}, "b": {"type": "integer"}}}));
        let ep = Endpoint::new("http://x/v1", "m");
        for d in [Dialect::JsonSchema, Dialect::JsonObjectSchema, Dialect::JsonObject, Dialect::Prompt] {
            let text =
                body(&req, &ep, true, Learnt { dialect: d, no_stream_options: false, answered: false }, Some(99));
            let v: Value = serde_json::from_str(&text).unwrap();
            assert_eq!(v["max_tokens"], 99);
            let in_prompt = v["messages"][0]["content"].as_str().unwrap().contains("JSON Schema");
            assert_eq!(in_prompt, !d.enforced(), "{d:?}");
            let sent = match d {
                Dialect::JsonSchema => v["response_format"]["json_schema"]["schema"].clone(),
                Dialect::JsonObjectSchema => v["response_format"]["schema"].clone(),
                _ => Value::Null,
            };
            if d.enforced() {
                assert_eq!(sent["properties"]["a"]["maxLength"], crate::schema::DEFAULT_MAX_LENGTH, "{d:?}");
                assert!(text.find("\"b\":{").unwrap() < text.find("\"a\":{").unwrap(), "ordered: {text}");
            }
        }
    }
}
