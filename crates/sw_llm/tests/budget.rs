//! The token limit follows what is asked, and an answer that reaches it is looked at: a
//! loop is refused as a loop; a long answer is asked once more with twice the room; under
//! a limit the endpoint fixed, the refusal says which limit to raise. On a loopback server
//! that does exactly that.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Duration;

use sw_llm::{ChatRequest, Client, Endpoint, LlmConfig, LlmOutcome, LlmStage, Message};
use sw_mockllm::{MockServer, Reply, script};

fn endpoint(server: &MockServer) -> Endpoint {
    let mut e = Endpoint::new(server.base_url(), "m");
    e.timeout = Duration::from_millis(1500);
    e.backoff = Duration::from_millis(10);
    e.max_backoff = Duration::from_millis(50);
    e
}

fn ask(text: &str) -> ChatRequest {
    ChatRequest::new(vec![Message::system("answer in JSON"), Message::user(text)])
}

fn cut(content: String) -> Reply {
    Reply::Tokens { content, pieces: 20, gap: Duration::ZERO, finish: Some("length".into()), done: true, model: None }
}

fn complete(content: &str) -> Reply {
    Reply::Tokens {
        content: content.into(),
        pieces: 5,
        gap: Duration::ZERO,
        finish: Some("stop".into()),
        done: true,
        model: None,
    }
}

/// A plan of many different groups (no stretch of it repeats).
fn long_plan(n: usize) -> String {
    let groups: Vec<String> = (0..n)
        .map(|i| format!("{{\"id\": \"group_{i}\", \"count\": {}, \"phrase\": \"{i} things\"}}", i % 7 + 1))
        .collect();
    format!("{{\"objects\": [{}", groups.join(", "))
}

#[test]
fn a_long_prompt_gets_a_longer_limit() {
    let server = MockServer::start(|_| complete("{}")).unwrap();
    let c = Client::new(LlmConfig::offline().with_all(endpoint(&server)));
    c.complete(LlmStage::Plan, &ask("a table with two mugs"), "plan").unwrap();
    let groups: Vec<String> = (0..40).map(|i| format!("{} crates of kind {i}", i + 2)).collect();
    c.complete(LlmStage::Plan, &ask(&format!("a warehouse with {}", groups.join(", "))), "plan").unwrap();
    let limits: Vec<u64> =
        server.requests().iter().map(|r| r.json().unwrap()["max_tokens"].as_u64().unwrap()).collect();
    assert_eq!(limits[0], 640, "a short prompt: the stage's default");
    assert!(limits[1] >= 4000, "forty groups: room for forty objects, got {}", limits[1]);
}

#[test]
fn a_long_answer_is_asked_again_with_twice_the_room() {
    let server = MockServer::start(script(vec![cut(long_plan(120)), complete("{\"objects\": []}")])).unwrap();
    let c = Client::new(LlmConfig::offline().with_all(endpoint(&server)));
    let done = c.complete(LlmStage::Plan, &ask("a table with two mugs"), "plan").unwrap();
    assert_eq!(done.content, "{\"objects\": []}");
    let limits: Vec<u64> =
        server.requests().iter().map(|r| r.json().unwrap()["max_tokens"].as_u64().unwrap()).collect();
    assert_eq!(limits, vec![640, 1280]);
    let call = &c.telemetry().calls()[0];
    assert_eq!((call.outcome, call.retries), (LlmOutcome::Ok, 1));
    assert!(call.attempt_errors[0].contains("longer than 640 tokens"), "{:?}", call.attempt_errors);
}

#[test]
fn a_loop_is_refused_as_a_loop_and_a_long_answer_under_a_fixed_limit_says_what_to_raise() {
    let looped = format!("{{\"objects\": [{}", "{\"id\": \"box\", \"count\": 1}, ".repeat(40));
    let server = MockServer::start(move |_| cut(looped.clone())).unwrap();
    let c = Client::new(LlmConfig::offline().with_all(endpoint(&server)));
    let e = c.complete(LlmStage::Plan, &ask("boxes"), "plan").unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Length);
    assert!(e.to_string().contains("the model looped") && e.to_string().contains("\"box\""), "{e}");
    assert_eq!(server.requests().len(), 1, "a loop is not asked again");

    let server = MockServer::start(|_| cut(long_plan(120))).unwrap();
    let mut ep = endpoint(&server);
    ep.max_tokens = Some(500);
    let c = Client::new(LlmConfig::offline().with_all(ep));
    let e = c.complete(LlmStage::Plan, &ask("many things"), "plan").unwrap_err();
    assert!(e.to_string().contains("is not a loop") && e.to_string().contains("SCENEWRIGHT_LLM_MAX_TOKENS"), "{e}");
    assert_eq!(server.requests().len(), 1, "the endpoint's own limit is kept");
    assert_eq!(server.requests()[0].json().unwrap()["max_tokens"], 500);
}
