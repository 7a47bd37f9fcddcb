//! An OpenAI-compatible chat-completions client for the stages that may use a language
//! model (plan, relations, CAD, edit, refine, embeddings).
//!
//! - [`LlmConfig`]: an endpoint (base URL, key, model, timeouts, retries) per stage, from
//!   a JSON file, the environment or code; nothing by default (the pipeline is offline).
//! - [`Client`]: blocking calls over HTTP(S) with structured output (`response_format`
//!   with our JSON Schemas), streaming (server-sent events), a timeout per attempt,
//!   retries with exponential back-off on 429, 5xx, timeouts and broken connections
//!   (honouring `Retry-After`), and a simpler request for servers that reject parts of
//!   the OpenAI shape.
//! - [`Client::embed`]: vectors from the embeddings stage's endpoint (`/embeddings`).
//! - Telemetry: every call becomes an [`sw_plan::LlmCall`] (stage, model, latency,
//!   tokens in and out, retries, outcome) in the client's [`Telemetry`] and in the
//!   process-wide [`metrics`].
//! - Lenient reading of what "compatible" servers answer ([`extract_json`]) and of
//!   streamed documents ([`ArrayScanner`]).
//!
//! The client never executes anything a model says: answers are text for the caller to
//! parse and validate.

mod client;
mod config;
mod embed;
mod lenient;
pub mod metrics;
mod request;
mod scan;
mod sse;

pub use client::{Client, Completion, LlmError, StreamEvent, Telemetry};
pub use config::{ApiKey, ConfigError, Endpoint, LlmConfig};
pub use embed::MAX_BATCH as EMBED_BATCH;
pub use lenient::{ExtractError, extract_json, preview};
pub use request::{ChatRequest, Message, Role};
pub use scan::ArrayScanner;
pub use sw_plan::{LlmCall, LlmOutcome, LlmStage};
