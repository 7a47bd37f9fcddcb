//! What real local servers do that the first client did not expect, on a loopback server
//! that does exactly that: llama-cpp-python's HTTP 500 for `json_schema`, a model that
//! loops until the token limit, a stream ended by `[DONE]` without a finish reason (an
//! interrupted llama-cpp-python stream), a slow stream that keeps coming, a server loading
//! its model or restarting, a call cancelled mid-stream, one call at a time to a local
//! server, the model the server says answered.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::Arc;
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};

use serde_json::{Value, json};
use sw_llm::{CancelToken, ChatRequest, Client, Endpoint, LlmConfig, LlmOutcome, LlmStage, Message};
use sw_mockllm::{MockServer, Reply, script};

fn endpoint(server: &MockServer) -> Endpoint {
    let mut e = Endpoint::new(server.base_url(), "asked-model");
    e.timeout = Duration::from_millis(1500);
    e.connect_timeout = Duration::from_millis(500);
    e.backoff = Duration::from_millis(10);
    e.max_backoff = Duration::from_millis(50);
    e
}

fn client(ep: Endpoint) -> Client {
    Client::new(LlmConfig::offline().with_all(ep))
}

/// A relation-like schema: own properties beside a `oneOf`, as schemars writes them.
fn request() -> ChatRequest {
    ChatRequest::new(vec![Message::system("answer in JSON"), Message::user("relate them")]).with_schema(
        "relation",
        json!({
            "type": "object",
            "properties": {"subject": {"type": "string"}},
            "required": ["subject"],
            "oneOf": [
                {"type": "object", "properties": {"relation": {"const": "on"}, "target": {"type": "string"}}, "required": ["relation", "target"]},
                {"type": "object", "properties": {"relation": {"const": "in_row"}}, "required": ["relation"]}
            ]
        }),
    )
}

fn within<T>(budget: Duration, f: impl FnOnce() -> T) -> T {
    let t0 = Instant::now();
    let out = f();
    assert!(t0.elapsed() < budget, "took {:?}, budget {budget:?}", t0.elapsed());
    out
}

#[test]
fn a_500_naming_response_format_steps_down_to_json_object_with_schema_and_is_remembered() {
    // llama-cpp-python 0.3.36's answer to `json_schema`.
    let server = MockServer::start(|req| match req.response_format().as_deref() {
        Some("json_schema") => Reply::status(
            500,
            "[{'type': 'literal_error', 'loc': ('body', 'response_format', 'type'), 'msg': \"Input should be 'text' or 'json_object'\"}]",
        ),
        _ => Reply::answer(r#"{"subject": "box", "relation": "in_row"}"#),
    })
    .unwrap();
    let c = client(endpoint(&server));
    c.complete(LlmStage::Plan, &request(), "plan").unwrap();
    c.complete(LlmStage::Relations, &request(), "relations").unwrap();
    let reqs = server.requests();
    assert_eq!(reqs.len(), 3, "one refusal, then the remembered dialect");
    let sent: Value = reqs[1].json().unwrap();
    assert_eq!(sent["response_format"]["type"], "json_object");
    let variants = sent["response_format"]["schema"]["oneOf"].as_array().unwrap();
    for v in variants {
        assert_eq!(v["required"][0], "subject", "subject is inside every variant: {v}");
        assert_eq!(v["additionalProperties"], false);
    }
    assert_eq!(reqs[2].response_format().as_deref(), Some("json_object"));
    let calls = c.telemetry().calls();
    assert_eq!(calls[0].dialect.as_deref(), Some("json_object_schema"));
    assert_eq!(calls[0].attempt_errors.len(), 1);
    assert!(calls[0].attempt_errors[0].contains("HTTP 500"), "{:?}", calls[0].attempt_errors);
    assert_eq!((calls[1].retries, calls[1].outcome), (0, LlmOutcome::Ok));
}

#[test]
fn a_looping_model_costs_one_bounded_attempt() {
    let server = MockServer::start(|_| Reply::Tokens {
        content: "1234567890".repeat(40),
        pieces: 40,
        gap: Duration::ZERO,
        finish: Some("length".into()),
        done: true,
        model: None,
    })
    .unwrap();
    let c = client(endpoint(&server));
    let e = within(Duration::from_secs(3), || c.complete(LlmStage::Plan, &request(), "plan")).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Length, "{e}");
    assert!(e.to_string().contains("token limit (640 tokens)"), "{e}");
    let reqs = server.requests();
    assert_eq!(reqs.len(), 1, "never asked again unchanged");
    assert_eq!(reqs[0].json().unwrap()["max_tokens"], 640, "the plan stage's default limit");
    let call = &c.telemetry().calls()[0];
    // No usage was sent: the estimate is the larger of the pieces (40) and the bytes / 4.
    assert_eq!((call.outcome, call.max_tokens, call.tokens_out), (LlmOutcome::Length, Some(640), 400 / 4));
    assert!(call.tokens_estimated);
}

#[test]
fn a_stream_ended_by_done_without_a_finish_reason_is_asked_again() {
    let doc = r#"{"subject": "box", "relation": "in_row"}"#;
    let server = MockServer::start(script(vec![
        Reply::Tokens {
            content: doc[..12].into(),
            pieces: 3,
            gap: Duration::ZERO,
            finish: None,
            done: true,
            model: None,
        },
        Reply::answer(doc),
    ]))
    .unwrap();
    let c = client(endpoint(&server));
    let mut restarts = 0;
    let a = c
        .stream(LlmStage::Plan, &request(), "plan", &mut |ev| {
            if ev == sw_llm::StreamEvent::Restart {
                restarts += 1;
            }
        })
        .unwrap();
    assert_eq!(a.content, doc);
    assert_eq!(restarts, 1);
    let call = &c.telemetry().calls()[0];
    assert_eq!(call.retries, 1);
    assert!(call.attempt_errors[0].contains("without a finish reason"), "{:?}", call.attempt_errors);
}

#[test]
fn a_slow_stream_that_keeps_coming_is_not_cut() {
    // 10 pieces 150 ms apart: 1.35 s in all, against a silence limit of 400 ms.
    let doc = r#"{"subject": "box", "relation": "in_row"}"#;
    let server = MockServer::start(move |_| Reply::tokens(doc, 12, Duration::from_millis(150))).unwrap();
    let mut ep = endpoint(&server);
    ep.timeout = Duration::from_millis(400);
    let a = client(ep).complete(LlmStage::Plan, &request(), "plan").unwrap();
    assert_eq!(a.content, doc);
    assert!(a.latency > Duration::from_millis(1200), "{:?}", a.latency);
}

#[test]
fn a_server_loading_its_model_is_waited_for() {
    let asked = Arc::new(AtomicU32::new(0));
    let n = Arc::clone(&asked);
    let started = Instant::now();
    let server = MockServer::start(move |_| {
        n.fetch_add(1, Ordering::SeqCst);
        if started.elapsed() < Duration::from_millis(1200) { Reply::loading() } else { Reply::answer("{}") }
    })
    .unwrap();
    let mut ep = endpoint(&server);
    ep.max_retries = 0;
    let a = within(Duration::from_secs(5), || client(ep.clone()).complete(LlmStage::Plan, &request(), "plan")).unwrap();
    assert_eq!(a.content, "{}");
    assert!(asked.load(Ordering::SeqCst) >= 2);
    // Told not to wait, the same server fails at once, saying what it said.
    let server = MockServer::start(|_| Reply::loading()).unwrap();
    let mut ep = endpoint(&server);
    ep.load_wait = Duration::ZERO;
    ep.max_retries = 0;
    let e = client(ep).complete(LlmStage::Plan, &request(), "plan").unwrap_err();
    assert!(e.to_string().contains("HTTP 503: Loading model"), "{e}");
    assert!(!e.unreachable(), "a server that answered was reached: {e}");
}

#[test]
fn a_server_that_restarts_between_calls_is_waited_for() {
    let first = MockServer::start(|_| Reply::answer("{}")).unwrap();
    let addr = first.addr().to_string();
    let mut ep = endpoint(&first);
    ep.max_retries = 0;
    let c = client(ep);
    c.complete(LlmStage::Plan, &request(), "plan").unwrap();
    drop(first);
    let restart = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(700));
        MockServer::start_at(&addr, |_| Reply::answer(r#"{"again": true}"#)).unwrap()
    });
    let a = within(Duration::from_secs(5), || c.complete(LlmStage::Plan, &request(), "plan")).unwrap();
    assert_eq!(a.content, r#"{"again": true}"#);
    let call = &c.telemetry().calls()[1];
    assert!(call.retries >= 1 && call.attempt_errors.iter().all(|e| e.contains("connection")), "{call:?}");
    drop(restart.join().unwrap());
}

#[test]
fn a_cancelled_call_ends_at_once_and_closes_its_connection() {
    let server = MockServer::start(|_| Reply::tokens("x".repeat(200), 100, Duration::from_millis(50))).unwrap();
    let c = client(endpoint(&server));
    let token = CancelToken::new();
    let t = token.clone();
    std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(300));
        t.cancel();
    });
    let t0 = Instant::now();
    let e = sw_llm::cancel::scope(&token, || c.complete(LlmStage::Cad, &request(), "cad")).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Cancelled, "{e}");
    assert!(t0.elapsed() < Duration::from_millis(800), "{:?}", t0.elapsed());
    let deadline = Instant::now() + Duration::from_secs(2);
    while server.abandoned() == 0 && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    assert_eq!(server.abandoned(), 1, "the server saw the connection close and stopped writing");
    assert_eq!(c.telemetry().calls()[0].outcome, LlmOutcome::Cancelled);
}

#[test]
fn a_local_server_gets_one_call_at_a_time_unless_told_otherwise() {
    let server = MockServer::start(|_| Reply::answer_after("{}", Duration::from_millis(300))).unwrap();
    let both = |ep: Endpoint| {
        let c = client(ep);
        let t0 = Instant::now();
        let handles: Vec<_> = (0..2)
            .map(|_| {
                let c = c.clone();
                std::thread::spawn(move || c.complete(LlmStage::Cad, &request(), "cad").unwrap())
            })
            .collect();
        handles.into_iter().for_each(|h| {
            h.join().unwrap();
        });
        t0.elapsed()
    };
    let one_at_a_time = both(endpoint(&server));
    assert!(one_at_a_time >= Duration::from_millis(600), "{one_at_a_time:?}");
    let mut ep = endpoint(&server);
    ep.endpoint_concurrency = Some(2);
    let together = both(ep);
    assert!(together < Duration::from_millis(550), "{together:?}");
}

#[test]
fn the_model_that_answered_and_a_refused_model_name_are_told_apart() {
    let server = MockServer::start(|req| {
        if req.model() == "no-such-model" {
            Reply::status(404, "model 'no-such-model' not found")
        } else {
            Reply::Tokens {
                content: "{}".into(),
                pieces: 1,
                gap: Duration::ZERO,
                finish: Some("stop".into()),
                done: true,
                model: Some("SmolLM2-135M-Instruct".into()),
            }
        }
    })
    .unwrap();
    let c = client(endpoint(&server));
    let a = c.complete(LlmStage::Plan, &request(), "plan").unwrap();
    assert_eq!(a.served_model.as_deref(), Some("SmolLM2-135M-Instruct"));
    assert_eq!(c.telemetry().calls()[0].served_model.as_deref(), Some("SmolLM2-135M-Instruct"));
    let mut ep = endpoint(&server);
    ep.model = "no-such-model".into();
    let e = client(ep).complete(LlmStage::Plan, &request(), "plan").unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Rejected);
    assert!(e.to_string().contains("HTTP 404") && !e.unreachable(), "{e}");
}

#[test]
fn status_probes_list_models_ping_and_check_the_schema() {
    let server = MockServer::start(|req| {
        if req.method == "GET" {
            Reply::models(&["asked-model"])
        } else if req.response_format().is_some() {
            Reply::answer(r#"{"answer": "yes"}"#)
        } else {
            Reply::answer("OK")
        }
    })
    .unwrap();
    let r = sw_llm::probe::probe(LlmStage::Plan, &endpoint(&server));
    assert_eq!(r.models.as_ref().unwrap(), &vec!["asked-model".to_string()]);
    assert_eq!(r.model_listed, Some(true));
    assert!(r.ping.is_ok(), "{:?}", r.ping);
    assert_eq!(r.schema.as_ref().unwrap(), &("json_schema".to_string(), true));
    let ping = &server.requests()[1];
    assert_eq!(ping.json().unwrap()["max_tokens"], 1);
}

#[test]
fn a_tap_sees_the_calls_of_fresh_clients_made_from_a_tapped_one() {
    let server = MockServer::start(|_| Reply::answer(r#"{"subject": "box", "relation": "in_row"}"#)).unwrap();
    let parent = client(endpoint(&server));
    let tap = sw_llm::Telemetry::default();
    let tapped = parent.fresh_tapped(&tap);
    // Code given the tapped client takes its own fresh copy (as an edit does).
    let inner = tapped.fresh();
    inner.complete(LlmStage::Edit, &request(), "edit").unwrap();
    tapped.complete(LlmStage::Plan, &request(), "plan").unwrap();
    parent.complete(LlmStage::Plan, &request(), "untapped").unwrap();
    let purposes = |t: &sw_llm::Telemetry| t.calls().iter().map(|c| c.purpose.clone()).collect::<Vec<_>>();
    assert_eq!(purposes(&tap), ["edit", "plan"]);
    assert_eq!(purposes(inner.telemetry()), ["edit"]);
    assert_eq!(purposes(tapped.telemetry()), ["plan"]);
    assert_eq!(purposes(parent.telemetry()), ["untapped"]);
    // Calls handed on by `extend` were tapped when they were made: not twice.
    tapped.telemetry().extend(inner.telemetry().calls());
    assert_eq!(tap.calls().len(), 2);
}
