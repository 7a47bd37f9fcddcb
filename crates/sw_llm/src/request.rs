//! What a stage asks: messages and, optionally, the JSON Schema the answer must follow.

use serde_json::{Value, json};

use crate::Endpoint;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    System,
    User,
    Assistant,
}

impl Role {
    fn name(self) -> &'static str {
        match self {
            Role::System => "system",
            Role::User => "user",
            Role::Assistant => "assistant",
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    pub role: Role,
    pub content: String,
}

impl Message {
    pub fn system(content: impl Into<String>) -> Self {
        Self { role: Role::System, content: content.into() }
    }

    pub fn user(content: impl Into<String>) -> Self {
        Self { role: Role::User, content: content.into() }
    }

    pub fn assistant(content: impl Into<String>) -> Self {
        Self { role: Role::Assistant, content: content.into() }
    }
}

/// A chat request, independent of the endpoint it goes to.
#[derive(Debug, Clone, PartialEq)]
pub struct ChatRequest {
    pub messages: Vec<Message>,
    /// `(name, schema)`: structured output against this JSON Schema.
    pub schema: Option<(String, Value)>,
    pub max_tokens: Option<u32>,
}

impl ChatRequest {
    pub fn new(messages: Vec<Message>) -> Self {
        Self { messages, schema: None, max_tokens: None }
    }

    pub fn with_schema(mut self, name: &str, schema: Value) -> Self {
        self.schema = Some((name.to_string(), schema));
        self
    }

    /// Bytes of all messages (for token estimates).
    pub(crate) fn text_len(&self) -> usize {
        self.messages.iter().map(|m| m.content.len()).sum()
    }
}

/// How much of the OpenAI request shape a server is sent. Servers that reject
/// `response_format` with a JSON Schema (or `stream_options`) get less on a retry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Shape {
    /// `response_format: json_schema`, `stream_options.include_usage`.
    Full,
    /// `response_format: json_object`, no stream options.
    JsonObject,
    /// Messages only.
    Plain,
}

impl Shape {
    pub fn next(self) -> Option<Shape> {
        match self {
            Shape::Full => Some(Shape::JsonObject),
            Shape::JsonObject => Some(Shape::Plain),
            Shape::Plain => None,
        }
    }
}

pub(crate) fn body(req: &ChatRequest, ep: &Endpoint, stream: bool, shape: Shape) -> Value {
    let messages: Vec<Value> =
        req.messages.iter().map(|m| json!({ "role": m.role.name(), "content": m.content })).collect();
    let mut b = json!({ "model": ep.model, "messages": messages, "stream": stream });
    if let Some(t) = ep.temperature {
        b["temperature"] = json!(t);
    }
    if let Some(n) = req.max_tokens.or(ep.max_tokens) {
        b["max_tokens"] = json!(n);
    }
    if stream && shape == Shape::Full {
        b["stream_options"] = json!({ "include_usage": true });
    }
    if let Some((name, schema)) = &req.schema
        && ep.structured
    {
        match shape {
            Shape::Full => {
                b["response_format"] = json!({
                    "type": "json_schema",
                    "json_schema": { "name": name, "schema": schema, "strict": false }
                });
            }
            Shape::JsonObject => b["response_format"] = json!({ "type": "json_object" }),
            Shape::Plain => {}
        }
    }
    b
}
