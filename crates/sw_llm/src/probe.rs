//! What `llm status` asks an endpoint: the models it lists (`GET {base}/models`), one
//! one-token call (does it answer, how fast, which model answers), and one small call with
//! a JSON Schema (which structured-output dialect it takes, and whether the answer
//! follows the schema).

use std::time::{Duration, Instant};

use serde::Serialize;
use serde_json::{Value, json};
use sw_plan::{LlmOutcome, LlmStage};

use crate::client::ms;
use crate::config::{Endpoint, LlmConfig};
use crate::lenient::extract_json;
use crate::request::{ChatRequest, Message};
use crate::transport::{http_error, transport_error};
use crate::{Client, dialect};

/// What one endpoint answered.
#[derive(Debug, Clone, Serialize)]
pub struct ProbeReport {
    /// Model ids the server lists, or why the list could not be read.
    pub models: Result<Vec<String>, String>,
    /// The configured model is among them (`None` when the list could not be read).
    pub model_listed: Option<bool>,
    /// The one-token call: latency (ms) and the model that answered, or the error.
    pub ping: Result<(f64, Option<String>), String>,
    /// The dialect the schema call ended up with, and whether its answer followed the
    /// schema; or the error.
    pub schema: Result<(String, bool), String>,
}

/// Every model id of `GET {base}/models` (`{"data": [{"id": …}]}`, or Ollama's
/// `{"models": [{"name": …}]}`).
pub fn list_models(ep: &Endpoint) -> Result<Vec<String>, String> {
    let agent: ureq::Agent = ureq::Agent::config_builder()
        .http_status_as_error(false)
        .timeout_global(Some(ep.timeout.min(Duration::from_secs(30))))
        .timeout_connect(Some(ep.connect_timeout))
        .build()
        .into();
    let url = format!("{}/models", ep.base_url.trim_end_matches('/').trim_end_matches("/chat/completions"));
    let mut r = agent.get(&url);
    if let Some(k) = &ep.api_key {
        r = r.header("authorization", format!("Bearer {}", k.expose()));
    }
    let resp = r.call().map_err(|e| transport_error(e).message)?;
    let mut body = http_error(resp).map_err(|e| e.message)?;
    let bytes = body.with_config().limit(1 << 20).read_to_vec().map_err(|e| transport_error(e).message)?;
    let v: Value = serde_json::from_slice(&bytes).map_err(|_| "the model list is not JSON".to_string())?;
    let list = v.get("data").or_else(|| v.get("models")).and_then(Value::as_array).ok_or("no model list")?;
    Ok(list
        .iter()
        .filter_map(|m| m.get("id").or_else(|| m.get("name")).and_then(Value::as_str))
        .map(|s| s.chars().take(200).collect())
        .collect())
}

/// Probes `ep` (as `stage`'s endpoint), learning its dialect afresh.
pub fn probe(stage: LlmStage, ep: &Endpoint) -> ProbeReport {
    let models = list_models(ep);
    let model_listed = models.as_ref().ok().map(|l| {
        let want = ep.model.to_ascii_lowercase();
        l.iter().any(|m| {
            let m = m.to_ascii_lowercase();
            m == want || m.rsplit('/').next() == Some(want.as_str())
        })
    });
    let mut once = ep.clone();
    once.max_retries = 0;
    once.max_tokens = None;
    let client = Client::new(LlmConfig::offline().with(stage, once.clone()));
    let t0 = Instant::now();
    let ping = client
        .complete(
            stage,
            &ChatRequest::new(vec![Message::user("Reply with the word OK.")]).with_max_tokens(1),
            "probe: one token",
        )
        .map(|c| (ms(t0.elapsed()), c.served_model))
        .or_else(|e| match e.outcome() {
            // One token asked, one given: an answer cut at its limit is an answer.
            LlmOutcome::Length => {
                Ok((ms(t0.elapsed()), client.telemetry().calls().last().and_then(|c| c.served_model.clone())))
            }
            _ => Err(e.to_string()),
        });
    dialect::forget(&once);
    let schema_req = ChatRequest::new(vec![
        Message::system("Answer with JSON."),
        Message::user("Is water wet? Answer {\"answer\": \"yes\"} or {\"answer\": \"no\"}."),
    ])
    .with_schema(
        "probe",
        json!({"type": "object", "properties": {"answer": {"type": "string", "enum": ["yes", "no"]}}, "required": ["answer"]}),
    )
    .with_max_tokens(24);
    let schema = client
        .complete(stage, &schema_req, "probe: schema")
        .map(|c| {
            let follows = extract_json(&c.content)
                .ok()
                .and_then(|v| v.get("answer").and_then(Value::as_str).map(|a| a == "yes" || a == "no"))
                .unwrap_or(false);
            (dialect::current(&once).name().to_string(), follows)
        })
        .map_err(|e| e.to_string());
    ProbeReport { models, model_listed, ping, schema }
}
