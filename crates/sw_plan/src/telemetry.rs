//! Telemetry of language-model calls and the edit history of a package.
//!
//! Every call to an LLM endpoint is recorded as an [`LlmCall`]: which stage asked, which
//! model answered, how long it took, how many tokens went in and out, how many retries
//! it needed and how it ended, each failed attempt's error, the model the server said
//! answered and how structured output was asked for. Runs of the offline pipeline make no calls, so their
//! `report.json` carries no such field and stays byte-identical to earlier versions.
//!
//! `edits.json` ([`EditLog`]) is the history of natural-language edits applied to a
//! package, oldest first.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::SCHEMA_VERSION;

/// The stages that may call a language model, each configurable with its own endpoint
/// and model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum LlmStage {
    /// L1: prompt to plan.
    Plan,
    /// Relations between the plan's objects, when the plan came without them.
    Relations,
    /// L2: CAD code for an asset the catalog and the cache do not have.
    Cad,
    /// A natural-language edit the offline grammar did not understand.
    Edit,
    /// Questions about an underspecified prompt.
    Refine,
    /// Embeddings for the semantic asset index.
    Embeddings,
}

impl LlmStage {
    pub const ALL: [LlmStage; 6] =
        [LlmStage::Plan, LlmStage::Relations, LlmStage::Cad, LlmStage::Edit, LlmStage::Refine, LlmStage::Embeddings];

    /// The snake_case name used in JSON, configuration and environment variables.
    pub fn name(self) -> &'static str {
        match self {
            LlmStage::Plan => "plan",
            LlmStage::Relations => "relations",
            LlmStage::Cad => "cad",
            LlmStage::Edit => "edit",
            LlmStage::Refine => "refine",
            LlmStage::Embeddings => "embeddings",
        }
    }

    pub fn from_name(name: &str) -> Option<LlmStage> {
        LlmStage::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// How a call ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum LlmOutcome {
    /// An answer arrived and was usable.
    Ok,
    /// An answer arrived but could not be used (not JSON, or not a valid document).
    Unusable,
    /// The endpoint answered 429 on every attempt.
    RateLimited,
    /// The endpoint answered 5xx on every attempt.
    ServerError,
    /// The endpoint refused the request (4xx other than 429): key, model or request.
    Rejected,
    /// No answer within the timeout.
    Timeout,
    /// The endpoint could not be reached, or the connection broke.
    ConnectionFailed,
    /// A streamed answer ended before it was complete.
    Truncated,
    /// The answer was cut off at the token limit sent with the call (`max_tokens`): a
    /// model that loops or rambles. Never retried unchanged.
    Length,
    /// The response was not an OpenAI-compatible chat completion.
    Malformed,
    /// The run no longer needed the answer.
    Cancelled,
}

/// One call to a language-model endpoint.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LlmCall {
    pub stage: LlmStage,
    /// The model asked for.
    pub model: String,
    /// The model the server said answered, when it said (servers that hold one model
    /// answer any name with theirs).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub served_model: Option<String>,
    /// Scheme, host and port of the endpoint (never a key or a path with secrets).
    pub endpoint: String,
    /// The answer was streamed (server-sent events).
    #[serde(default)]
    pub streamed: bool,
    /// Wall-clock time from the first request to the end of the last answer, ms.
    pub latency_ms: f64,
    /// Time to the first streamed token, ms.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_token_ms: Option<f64>,
    pub tokens_in: u64,
    pub tokens_out: u64,
    /// The server reported no usage; the token counts are estimates (4 bytes a token).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub tokens_estimated: bool,
    /// Attempts after the first (on 429, 5xx, timeouts and broken connections).
    pub retries: u32,
    pub outcome: LlmOutcome,
    /// What went wrong, in one line, when the outcome is not `ok`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// Why each earlier attempt of this call failed, in order (the last one's is `error`,
    /// or the call succeeded after them).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub attempt_errors: Vec<String>,
    /// How structured output was asked for: `json_schema`, `json_object_schema` (the
    /// schema inside `json_object`), `json_object`, or `prompt` (the schema in the
    /// messages); absent when the call asked for no structure.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dialect: Option<String>,
    /// The token limit sent with the call (`max_tokens`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_tokens: Option<u32>,
    /// What the call was for ("plan", "repair", "cad: forklift", …).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub purpose: String,
}

/// The edit history of a package (`edits.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EditLog {
    pub schema_version: u32,
    /// Applied edits, oldest first.
    pub edits: Vec<EditRecord>,
}

impl Default for EditLog {
    fn default() -> Self {
        Self { schema_version: SCHEMA_VERSION, edits: Vec::new() }
    }
}

/// One applied edit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EditRecord {
    /// 1 for the first edit of the package.
    pub number: u32,
    /// The command as the user typed it.
    pub command: String,
    /// Who understood it: `grammar` (offline) or `llm`.
    pub understood_by: String,
    /// The operations, in words ("remove chair_2", "move table_1 next to conveyor_1").
    pub operations: Vec<String>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub added: Vec<String>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub removed: Vec<String>,
    /// Objects whose pose changed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub moved: Vec<String>,
    /// Objects whose asset changed (colour, size, kind).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub modified: Vec<String>,
    /// Language-model calls the edit made.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub llm_calls: Vec<LlmCall>,
}
