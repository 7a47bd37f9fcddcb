//! Scene edits through the service with a model for what the offline grammar cannot read
//! (a loopback OpenAI-compatible server): the new version is verified and its history
//! says who read the command; a command the grammar reads never calls the model.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::time::Duration;

use axum::http::StatusCode;
use common::{PROMPT, app_with, runner, start_workers};
use serde_json::json;
use sw_llm::{Endpoint, LlmConfig, LlmStage};
use sw_mockllm::{MockServer, Reply};
use sw_store::QueueLimits;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_edit_the_grammar_cannot_read_goes_to_the_model() {
    let model =
        MockServer::start(|_| Reply::answer(r#"{"ops": [{"op": "remove", "target": {"noun": "cabinet"}}]}"#)).unwrap();
    let mut e = Endpoint::new(model.base_url(), "m-edit");
    e.timeout = Duration::from_secs(5);
    e.max_retries = 0;
    let mut r = runner();
    r.llm = Some(LlmConfig::offline().with(LlmStage::Edit, e));
    let a = app_with(QueueLimits::default(), r).await;
    let _workers = start_workers(&a.state, 1);
    let ann = a.user("ann").await;
    let (s, v) = a.post("/api/jobs", &ann, json!({"prompt": PROMPT})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let job = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    let scene = job["scene_id"].as_str().unwrap().to_string();

    let command = "I would rather not have that red cabinet in here";
    let (s, v) = a.post(&format!("/api/scenes/{scene}/edits"), &ann, json!({ "command": command })).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let edit = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    assert_eq!(edit["state"], "succeeded", "{edit}");
    let v2 = edit["scene_id"].as_str().unwrap();
    let (_, s2) = a.get(&format!("/api/scenes/{v2}"), &ann).await;
    assert_eq!(s2["status"], "verified", "{s2}");
    assert_eq!(s2["edits"][0]["command"], command);
    let (_, history) = a.get(&format!("/api/scenes/{v2}/files/edits.json"), &ann).await;
    assert!(history.to_string().contains("\"understood_by\":\"llm\""), "{history}");
    let (_, layout) = a.get(&format!("/api/scenes/{v2}/files/layout.json"), &ann).await;
    assert!(!layout.to_string().contains("\"cabinet_1\""), "the cabinet is gone: {layout}");
    assert_eq!(model.requests().len(), 1);

    // The grammar reads this one: no model call.
    let (_, v) = a.post(&format!("/api/scenes/{v2}/edits"), &ann, json!({"command": "remove chair_1"})).await;
    let edit = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    assert_eq!(edit["state"], "succeeded", "{edit}");
    assert_eq!(model.requests().len(), 1);
}
