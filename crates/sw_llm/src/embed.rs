//! Embeddings from the embeddings stage's endpoint (`POST {base}/embeddings`, OpenAI's
//! shape): the provider's alternative to the in-process model of the asset index. The
//! same retries, back-off and telemetry as chat calls.

use std::time::Instant;

use serde_json::{Value, json};
use sw_plan::{LlmCall, LlmOutcome, LlmStage};
use tracing::{debug, info_span};

use crate::answer::{AttemptError, MAX_ANSWER_BYTES};
use crate::client::{Client, LlmError, backoff, ms};
use crate::config::Endpoint;
use crate::lenient::preview;
use crate::transport::{http_error, transport_error};

/// Most texts in one request (providers cap batches; OpenAI at 2048).
pub const MAX_BATCH: usize = 256;

impl Client {
    /// One vector per text, in order. An empty list asks nothing.
    pub fn embed(&self, texts: &[String], purpose: &str) -> Result<Vec<Vec<f32>>, LlmError> {
        let stage = LlmStage::Embeddings;
        let ep = self.config().endpoint(stage).ok_or(LlmError::NotConfigured(stage))?;
        let mut out = Vec::with_capacity(texts.len());
        for batch in texts.chunks(MAX_BATCH) {
            out.extend(self.embed_batch(ep, batch, purpose)?);
        }
        Ok(out)
    }

    fn embed_batch(&self, ep: &Endpoint, texts: &[String], purpose: &str) -> Result<Vec<Vec<f32>>, LlmError> {
        let stage = LlmStage::Embeddings;
        let _span = info_span!("llm", stage = stage.name(), model = %ep.model, purpose).entered();
        let agent = self.agent(stage, ep);
        let started = Instant::now();
        let estimate = texts.iter().map(|t| t.len().div_ceil(4) as u64).sum::<u64>();
        let mut retries = 0u32;
        let record = |outcome: LlmOutcome, tokens_in: u64, estimated: bool, retries: u32, error: Option<String>| {
            self.telemetry().record(LlmCall {
                stage,
                model: ep.model.clone(),
                served_model: None,
                endpoint: ep.origin(),
                streamed: false,
                latency_ms: ms(started.elapsed()),
                first_token_ms: None,
                tokens_in,
                tokens_out: 0,
                tokens_estimated: estimated,
                retries,
                outcome,
                error,
                attempt_errors: Vec::new(),
                dialect: None,
                max_tokens: None,
                purpose: purpose.to_string(),
            });
        };
        loop {
            match attempt(&agent, ep, texts) {
                Ok((vectors, usage)) => {
                    record(LlmOutcome::Ok, usage.unwrap_or(estimate), usage.is_none(), retries, None);
                    return Ok(vectors);
                }
                Err(e) => {
                    debug!(outcome = ?e.outcome, message = %e.message, "embeddings attempt failed");
                    if e.retryable() && retries < ep.max_retries {
                        std::thread::sleep(backoff(ep, retries, e.retry_after));
                        retries += 1;
                        continue;
                    }
                    record(e.outcome, estimate, true, retries, Some(e.message.clone()));
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

fn attempt(agent: &ureq::Agent, ep: &Endpoint, texts: &[String]) -> Result<(Vec<Vec<f32>>, Option<u64>), AttemptError> {
    let payload = json!({ "model": ep.model, "input": texts, "encoding_format": "float" }).to_string();
    let mut r = agent.post(ep.embeddings_url()).header("content-type", "application/json");
    if let Some(k) = &ep.api_key {
        r = r.header("authorization", format!("Bearer {}", k.expose()));
    }
    let resp = r.send(payload.as_bytes()).map_err(transport_error)?;
    let mut body = http_error(resp)?;
    let bytes = body.with_config().limit(MAX_ANSWER_BYTES as u64).read_to_vec().map_err(transport_error)?;
    parse(&String::from_utf8_lossy(&bytes), texts.len())
}

/// `{"data": [{"index": i, "embedding": [...]}, ...], "usage": {"prompt_tokens": n}}`:
/// every text gets a finite vector, all of one length, put in input order by `index`.
fn parse(text: &str, n: usize) -> Result<(Vec<Vec<f32>>, Option<u64>), AttemptError> {
    let bad = |why: String| AttemptError::new(LlmOutcome::Malformed, why);
    let v: Value = serde_json::from_str(text.trim_start_matches('\u{feff}'))
        .map_err(|_| bad(format!("the response is not JSON (it begins \"{}\")", preview(text))))?;
    let data = v.get("data").and_then(Value::as_array).ok_or_else(|| bad("the response has no data array".into()))?;
    if data.len() != n {
        return Err(bad(format!("{} embeddings for {n} texts", data.len())));
    }
    let mut out: Vec<Option<Vec<f32>>> = vec![None; n];
    for (k, item) in data.iter().enumerate() {
        let i = item.get("index").and_then(Value::as_u64).map_or(k, |i| i as usize);
        let vec: Vec<f32> = item
            .get("embedding")
            .and_then(Value::as_array)
            .ok_or_else(|| bad(format!("item {k} has no embedding (base64 answers are not asked for)")))?
            .iter()
            .map(|x| x.as_f64().filter(|f| f.is_finite()).map(|f| f as f32))
            .collect::<Option<_>>()
            .ok_or_else(|| bad(format!("item {k} holds a value that is not a finite number")))?;
        if vec.is_empty() {
            return Err(bad(format!("item {k} is an empty vector")));
        }
        match out.get_mut(i) {
            Some(slot @ None) => *slot = Some(vec),
            _ => return Err(bad(format!("item {k} has a bad or repeated index {i}"))),
        }
    }
    let out: Vec<Vec<f32>> = out.into_iter().flatten().collect();
    if out.iter().any(|v| v.len() != out[0].len()) {
        return Err(bad("the vectors differ in length".into()));
    }
    let usage = v.get("usage").and_then(|u| u.get("prompt_tokens")).and_then(Value::as_u64);
    Ok((out, usage))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_are_put_in_input_order_and_checked() {
        let t = r#"{"data": [{"index": 1, "embedding": [0.5, 1]}, {"index": 0, "embedding": [2, 3]}], "usage": {"prompt_tokens": 7}}"#;
        let (v, u) = parse(t, 2).unwrap();
        assert_eq!(v, vec![vec![2.0, 3.0], vec![0.5, 1.0]]);
        assert_eq!(u, Some(7));
        for (bad, n) in [
            ("prose", 1),
            (r#"{"data": []}"#, 1),
            (r#"{"data": [{"index": 0, "embedding": "AAAA"}]}"#, 1),
            (r#"{"data": [{"index": 0, "embedding": [1, 2]}, {"index": 0, "embedding": [1, 2]}]}"#, 2),
            (r#"{"data": [{"index": 0, "embedding": [1, 2]}, {"index": 1, "embedding": [1]}]}"#, 2),
            (r#"{"data": [{"index": 0, "embedding": []}]}"#, 1),
        ] {
            let e = parse(bad, n).expect_err(bad);
            assert_eq!(e.outcome, LlmOutcome::Malformed, "{bad}: {}", e.message);
        }
    }
}
