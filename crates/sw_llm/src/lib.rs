//! An OpenAI-compatible chat-completions client for the stages that may use a language
//! model (plan, relations, CAD, edit, refine, embeddings), written against what real
//! servers do (OpenAI, vLLM, Ollama, llama.cpp's `llama-server`, llama-cpp-python).
//!
//! - [`LlmConfig`]: an endpoint (base URL, key, model, timeouts, retries, token limit)
//!   per stage, from a JSON file, the environment or code; nothing by default (the
//!   pipeline is offline).
//! - [`Client`]: blocking calls over HTTP(S), streamed underneath (server-sent events)
//!   so that every call is bounded by the server's silence, a token limit per stage and
//!   a hard limit per attempt, and can be cancelled ([`cancel`]); retries with back-off
//!   on 429, 5xx and broken connections (honouring `Retry-After`, waiting out a model
//!   load or a restart); never an unchanged retry of an answer cut off at the token limit
//!   or of a first-byte timeout at temperature 0.
//! - Structured output in the endpoint's own [`Dialect`] (negotiated on refusal and
//!   remembered per endpoint), with schemas rewritten so that grammar converters keep
//!   every field and bound every string and array ([`schema::for_model`]).
//! - [`limits`]: calls in flight per server (one at a time to a local server).
//! - [`probe`]: what `llm status` asks a server (its models, a one-token call, whether
//!   it enforces a schema).
//! - [`Client::embed`]: vectors from the embeddings stage's endpoint (`/embeddings`).
//! - Telemetry: every call becomes an [`sw_plan::LlmCall`] (stage, model asked and served,
//!   latency, tokens real or estimated, retries, each attempt's error, outcome — a cut-off
//!   at the token limit is `length`) in the client's [`Telemetry`] and in the
//!   process-wide [`metrics`].
//! - Lenient reading of what "compatible" servers answer ([`extract_json`]) and of
//!   streamed documents ([`ArrayScanner`]).
//!
//! The client never executes anything a model says: answers are text for the caller to
//! parse and validate.

mod answer;
pub mod budget;
pub mod cancel;
mod client;
mod config;
pub mod dialect;
mod embed;
mod exchange;
mod lenient;
pub mod limits;
pub mod metrics;
pub mod probe;
mod request;
mod scan;
pub mod schema;
mod sse;
mod transport;

pub use cancel::CancelToken;
pub use client::{Client, Completion, LlmError, StreamEvent, Telemetry};
pub use config::{ApiKey, ConfigError, Endpoint, LlmConfig, default_max_tokens};
pub use dialect::Dialect;
pub use embed::MAX_BATCH as EMBED_BATCH;
pub use lenient::{ExtractError, extract_json, preview};
pub use request::{ChatRequest, Message, Role};
pub use scan::ArrayScanner;
pub use sw_plan::{LlmCall, LlmOutcome, LlmStage};
