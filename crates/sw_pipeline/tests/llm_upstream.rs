//! The model's failure is named as the model's: with no fallback, a planner whose endpoint
//! fails is exit code 3 with the stage, the endpoint and why — not "internal error" (1).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Duration;

use sw_llm::{Client, Endpoint, LlmConfig};
use sw_mockllm::{MockServer, Reply};

#[test]
fn a_failing_model_is_an_upstream_failure_not_an_internal_error() {
    let server =
        MockServer::start(|_| Reply::Status { code: 503, body: "overloaded".into(), retry_after: None }).unwrap();
    let mut ep = Endpoint::new(server.base_url(), "m");
    ep.max_retries = 0;
    ep.load_wait = Duration::ZERO;
    ep.backoff = Duration::from_millis(5);
    let client = Client::new(LlmConfig::offline().with_all(ep));
    let e = sw_pipeline::plan_with_llm("a lab with a table", &client, false).unwrap_err();
    assert_eq!(e.exit_code(), 3, "{e}");
    let text = e.to_string();
    assert!(!text.contains("internal error"), "{text}");
    assert!(text.contains("LLM planner") && text.contains(&server.base_url().replace("/v1", "")), "{text}");
}
