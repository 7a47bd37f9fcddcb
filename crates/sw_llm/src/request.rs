//! What a stage asks: messages and, optionally, the JSON Schema the answer must follow.

use serde_json::Value;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    System,
    User,
    Assistant,
}

impl Role {
    pub(crate) fn name(self) -> &'static str {
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
    /// The caller's token limit (an endpoint's own limit wins over it).
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

    pub fn with_max_tokens(mut self, n: u32) -> Self {
        self.max_tokens = Some(n);
        self
    }

    /// Bytes of all messages (for token estimates).
    pub(crate) fn text_len(&self) -> usize {
        self.messages.iter().map(|m| m.content.len()).sum()
    }
}
