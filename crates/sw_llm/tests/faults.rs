//! The client against a real HTTP server on loopback: recorded answers of real servers,
//! streams, and the fault matrix (malformed bodies, 429, 500, truncated streams, silence
//! past the timeout, refused request shapes, no server at all). Every case must end —
//! with an answer or an error naming the stage and endpoint — within its time budget.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;
use std::time::{Duration, Instant};

use sw_llm::{ChatRequest, Client, Endpoint, LlmConfig, LlmOutcome, LlmStage, Message, StreamEvent, extract_json};
use sw_mockllm::{MockServer, Reply, script};

fn asset(name: &str) -> Vec<u8> {
    std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/assets").join(name)).unwrap()
}

fn endpoint(server: &MockServer) -> Endpoint {
    let mut e = Endpoint::new(server.base_url(), "mock-model");
    e.timeout = Duration::from_millis(1500);
    e.connect_timeout = Duration::from_millis(500);
    e.backoff = Duration::from_millis(10);
    e.max_backoff = Duration::from_millis(50);
    e.max_retries = 2;
    e
}

fn client(server: &MockServer) -> Client {
    Client::new(LlmConfig::offline().with_all(endpoint(server)))
}

fn request() -> ChatRequest {
    ChatRequest::new(vec![Message::system("answer in JSON"), Message::user("a plan please")])
        .with_schema("answer", serde_json::json!({"type": "object"}))
}

/// Runs `f` and checks it returned within `budget`.
fn within<T>(budget: Duration, f: impl FnOnce() -> T) -> T {
    let t0 = Instant::now();
    let out = f();
    assert!(t0.elapsed() < budget, "took {:?}, budget {budget:?}", t0.elapsed());
    out
}

#[test]
fn a_recorded_openai_answer_is_read_with_its_usage() {
    let server = MockServer::start(|_| Reply::recorded(asset("openai_completion.json"), "application/json")).unwrap();
    let mut c = client(&server);
    c = Client::new({
        let mut cfg = c.config().clone();
        cfg.endpoint_mut(LlmStage::Plan).unwrap().stream = false;
        cfg
    });
    let a = c.complete(LlmStage::Plan, &request(), "plan").unwrap();
    assert_eq!(extract_json(&a.content).unwrap()["n"], 3);
    assert_eq!((a.tokens_in, a.tokens_out, a.tokens_estimated), (1117, 46, false));
    let calls = c.telemetry().calls();
    assert_eq!(calls.len(), 1);
    assert_eq!(calls[0].outcome, LlmOutcome::Ok);
    assert_eq!(calls[0].stage, LlmStage::Plan);
    assert_eq!(calls[0].model, "mock-model");
    // The request carried our schema as structured output.
    let req = &server.requests()[0];
    assert_eq!(req.response_format().as_deref(), Some("json_schema"));
    assert!(req.path.ends_with("/v1/chat/completions"));
}

#[test]
fn a_recorded_vllm_stream_and_a_chatty_ollama_answer_are_read() {
    let server = MockServer::start(|req| {
        if req.wants_stream() {
            Reply::recorded(asset("vllm_stream.sse"), "text/event-stream")
        } else {
            Reply::recorded(asset("ollama_completion.json"), "application/json")
        }
    })
    .unwrap();
    let c = client(&server);
    let mut pieces = Vec::new();
    let a = c
        .stream(LlmStage::Plan, &request(), "plan", &mut |e| {
            if let StreamEvent::Delta(d) = e {
                pieces.push(d.to_string())
            }
        })
        .unwrap();
    assert!(pieces.len() >= 2, "{pieces:?}");
    assert_eq!(extract_json(&a.content).unwrap()["answer"], "a plan");
    assert_eq!((a.tokens_in, a.tokens_out), (812, 18));
    let b = c.complete(LlmStage::Edit, &request(), "edit").unwrap();
    assert_eq!(extract_json(&b.content).unwrap()["n"], 3, "fenced JSON with a trailing comma and prose around it");
}

#[test]
fn a_live_stream_arrives_in_pieces_with_a_first_token_time() {
    let server =
        MockServer::start(|_| Reply::stream(r#"{"answer": "streamed", "n": 1}"#, 6, Duration::from_millis(120)))
            .unwrap();
    let c = client(&server);
    let mut n = 0;
    let a = c
        .stream(LlmStage::Plan, &request(), "plan", &mut |e| {
            if matches!(e, StreamEvent::Delta(_)) {
                n += 1
            }
        })
        .unwrap();
    assert_eq!(n, 6);
    assert_eq!(extract_json(&a.content).unwrap()["answer"], "streamed");
    assert!(a.first_token.unwrap() < a.latency);
    assert!(a.tokens_estimated, "the stream sent no usage");
    assert!(server.requests()[0].wants_stream());
}

#[test]
fn rate_limits_are_retried_with_backoff() {
    let server =
        MockServer::start(script(vec![Reply::rate_limited(1), Reply::rate_limited(0), Reply::answer("{}")])).unwrap();
    let c = client(&server);
    let a = within(Duration::from_secs(3), || c.complete(LlmStage::Plan, &request(), "plan")).unwrap();
    assert_eq!(a.retries, 2);
    assert_eq!(c.telemetry().calls()[0].retries, 2);
    assert_eq!(server.requests().len(), 3);
}

#[test]
fn server_errors_give_up_after_the_retries_and_say_so() {
    let server = MockServer::start(|_| Reply::status(500, "boom")).unwrap();
    let c = client(&server);
    let e = within(Duration::from_secs(3), || c.complete(LlmStage::Cad, &request(), "cad")).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::ServerError);
    let msg = e.to_string();
    assert!(
        msg.contains("cad stage") && msg.contains("HTTP 500") && msg.contains("boom") && msg.contains("3 attempts"),
        "{msg}"
    );
    let call = &c.telemetry().calls()[0];
    assert_eq!((call.retries, call.outcome), (2, LlmOutcome::ServerError));
    assert_eq!(server.requests().len(), 3);
}

#[test]
fn silence_past_the_timeout_ends_in_a_timeout_asked_again_only_when_sampling() {
    let server = MockServer::start(|_| Reply::Hang(Duration::from_secs(30))).unwrap();
    let mut ep = endpoint(&server);
    ep.timeout = Duration::from_millis(300);
    ep.max_retries = 1;
    // At temperature 0 the same request would be as slow again: one attempt.
    let c = Client::new(LlmConfig::offline().with(LlmStage::Plan, ep.clone()));
    let e = within(Duration::from_secs(3), || c.stream(LlmStage::Plan, &request(), "plan", &mut |_| {})).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Timeout, "{e}");
    assert!(e.to_string().contains("silent"), "{e}");
    assert_eq!(server.requests().len(), 1);
    // Sampling, another attempt may be luckier.
    ep.temperature = Some(0.7);
    let c = Client::new(LlmConfig::offline().with(LlmStage::Plan, ep));
    let e = within(Duration::from_secs(3), || c.stream(LlmStage::Plan, &request(), "plan", &mut |_| {})).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Timeout, "{e}");
    assert_eq!(server.requests().len(), 3);
    let call = &c.telemetry().calls()[0];
    assert_eq!((call.retries, call.attempt_errors.len()), (1, 1), "{call:?}");
}

#[test]
fn a_stream_that_stalls_half_way_times_out() {
    let server = MockServer::start(|_| Reply::Stream {
        content: r#"{"answer": "slow"}"#.into(),
        chunks: 3,
        first: Duration::ZERO,
        total: Duration::from_secs(20),
        done: true,
    })
    .unwrap();
    let mut ep = endpoint(&server);
    ep.timeout = Duration::from_millis(400);
    ep.max_retries = 0;
    let c = Client::new(LlmConfig::offline().with(LlmStage::Plan, ep));
    let e = within(Duration::from_secs(3), || c.stream(LlmStage::Plan, &request(), "plan", &mut |_| {})).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Timeout, "{e}");
}

#[test]
fn a_truncated_stream_is_retried_from_the_start() {
    let doc = r#"{"answer": "whole", "n": 2}"#;
    let server = MockServer::start(script(vec![
        Reply::Truncated { content: doc.into(), fraction: 0.5 },
        Reply::stream(doc, 3, Duration::from_millis(30)),
    ]))
    .unwrap();
    let c = client(&server);
    let mut text = String::new();
    let mut restarts = 0;
    let a = c
        .stream(LlmStage::Plan, &request(), "plan", &mut |e| match e {
            StreamEvent::Delta(d) => text.push_str(d),
            StreamEvent::Restart => {
                restarts += 1;
                text.clear();
            }
        })
        .unwrap();
    assert_eq!(restarts, 1);
    assert_eq!(text, doc);
    assert_eq!(a.content, doc);
    assert_eq!(a.retries, 1);
}

#[test]
fn a_stream_that_always_breaks_off_is_an_error() {
    let server =
        MockServer::start(|_| Reply::Truncated { content: r#"{"answer": "never"}"#.into(), fraction: 0.6 }).unwrap();
    let c = client(&server);
    let e = within(Duration::from_secs(3), || c.stream(LlmStage::Plan, &request(), "plan", &mut |_| {})).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Truncated, "{e}");
}

#[test]
fn a_stream_without_done_but_with_a_finish_reason_is_complete() {
    let server = MockServer::start(|_| Reply::Stream {
        content: "{}".into(),
        chunks: 1,
        first: Duration::ZERO,
        total: Duration::ZERO,
        done: false,
    })
    .unwrap();
    let c = client(&server);
    assert_eq!(c.stream(LlmStage::Plan, &request(), "plan", &mut |_| {}).unwrap().content, "{}");
}

#[test]
fn malformed_bodies_are_errors_not_panics() {
    for body in [
        &b"<html>502 Bad Gateway</html>"[..],
        b"",
        b"{\"choices\": 7}",
        b"\xff\xfe\x00garbage",
        b"{\"error\": \"quota\"}",
    ] {
        let server = MockServer::start(move |_| Reply::recorded(body.to_vec(), "application/json")).unwrap();
        let mut ep = endpoint(&server);
        ep.stream = false;
        ep.max_retries = 0;
        let c = Client::new(LlmConfig::offline().with(LlmStage::Plan, ep));
        let e = within(Duration::from_secs(2), || c.complete(LlmStage::Plan, &request(), "plan")).unwrap_err();
        assert!(matches!(e.outcome(), LlmOutcome::Malformed | LlmOutcome::ServerError), "{body:?}: {e}");
    }
    // A garbled event in a stream.
    let server = MockServer::start(|_| Reply::recorded(&b"data: {not json\n\n"[..], "text/event-stream")).unwrap();
    let c = client(&server);
    let e = c.stream(LlmStage::Plan, &request(), "plan", &mut |_| {}).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Malformed);
}

#[test]
fn servers_that_refuse_structured_output_get_a_simpler_request() {
    let server = MockServer::start(|req| match req.response_format().as_deref() {
        Some("json_schema") => Reply::status(400, "response_format json_schema is not supported by this model"),
        _ => Reply::answer(r#"{"ok": true}"#),
    })
    .unwrap();
    let c = client(&server);
    let a = c.complete(LlmStage::Plan, &request(), "plan").unwrap();
    assert_eq!(extract_json(&a.content).unwrap()["ok"], true);
    let reqs = server.requests();
    assert_eq!(reqs.len(), 2);
    assert_eq!(reqs[1].response_format().as_deref(), Some("json_object"));
}

#[test]
fn bad_keys_are_not_retried() {
    let server = MockServer::start(|_| Reply::status(401, "Incorrect API key provided")).unwrap();
    let c = client(&server);
    let e = c.complete(LlmStage::Plan, &request(), "plan").unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::Rejected);
    assert!(e.to_string().contains("HTTP 401"));
    assert_eq!(server.requests().len(), 1);
}

#[test]
fn no_server_at_all_fails_fast() {
    // A port that was just free.
    let port = std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    let mut ep = Endpoint::new(format!("http://127.0.0.1:{port}/v1"), "m");
    ep.backoff = Duration::from_millis(5);
    ep.max_backoff = Duration::from_millis(10);
    let c = Client::new(LlmConfig::offline().with(LlmStage::Plan, ep));
    let e = within(Duration::from_secs(3), || c.complete(LlmStage::Plan, &request(), "plan")).unwrap_err();
    assert_eq!(e.outcome(), LlmOutcome::ConnectionFailed, "{e}");
}

#[test]
fn the_key_goes_in_the_header_and_nowhere_else() {
    let server = MockServer::start(|_| Reply::answer("{}")).unwrap();
    let mut ep = endpoint(&server);
    ep.api_key = Some(sw_llm::ApiKey::new("sk-secret-123"));
    let c = Client::new(LlmConfig::offline().with(LlmStage::Plan, ep));
    c.complete(LlmStage::Plan, &request(), "plan").unwrap();
    assert_eq!(server.requests()[0].header("authorization"), Some("Bearer sk-secret-123"));
    let recorded = serde_json::to_string(&c.telemetry().calls()).unwrap();
    assert!(!recorded.contains("sk-secret"), "{recorded}");
    assert!(!sw_llm::metrics::prometheus().contains("sk-secret"));
}

#[test]
fn unconfigured_stages_say_how_to_configure_them() {
    let c = Client::new(LlmConfig::offline());
    let e = c.complete(LlmStage::Refine, &request(), "refine").unwrap_err();
    assert!(e.to_string().contains("refine stage") && e.to_string().contains("SCENEWRIGHT_LLM_BASE_URL"), "{e}");
}

#[test]
fn metrics_count_calls_by_stage_and_outcome() {
    let server = MockServer::start(|_| Reply::answer("{}")).unwrap();
    let c = client(&server);
    c.complete(LlmStage::Embeddings, &request(), "probe").unwrap();
    let text = sw_llm::metrics::prometheus();
    assert!(text.contains("scenewright_llm_calls_total{stage=\"embeddings\",outcome=\"ok\"}"), "{text}");
    assert!(text.contains("scenewright_llm_latency_seconds_bucket{stage=\"embeddings\",outcome=\"ok\",le=\"+Inf\"}"));
}

#[test]
fn embeddings_come_back_in_order_with_usage_and_similar_texts_point_alike() {
    let server = MockServer::start(|req| {
        assert!(req.path.ends_with("/embeddings"), "{}", req.path);
        Reply::embeddings(req, 64)
    })
    .unwrap();
    let c = client(&server);
    let texts: Vec<String> = ["steel storage rack", "storage rack", "coffee mug"].map(String::from).to_vec();
    let v = c.embed(&texts, "index").unwrap();
    assert_eq!(v.len(), 3);
    assert!(v.iter().all(|x| x.len() == 64));
    let cos = |a: &[f32], b: &[f32]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f32>();
    assert!(cos(&v[0], &v[1]) > cos(&v[0], &v[2]), "the double is not a real embedding otherwise");
    let call = &c.telemetry().calls()[0];
    assert_eq!((call.stage, call.outcome, call.tokens_estimated), (LlmStage::Embeddings, LlmOutcome::Ok, false));
    let body = server.requests()[0].json().unwrap();
    assert_eq!(body["model"], "mock-model");
    assert_eq!(body["input"][2], "coffee mug");
    // Nothing to embed: no request.
    assert!(c.embed(&[], "index").unwrap().is_empty());
    assert_eq!(server.requests().len(), 1);
}

#[test]
fn embedding_faults_are_retried_or_named() {
    let texts = vec!["a crate".to_string()];
    let server = MockServer::start(script(vec![
        Reply::rate_limited(0),
        Reply::status(503, "overloaded"),
        Reply::recorded(r#"{"data":[{"index":0,"embedding":[0.6,0.8]}]}"#, "application/json"),
    ]))
    .unwrap();
    let c = client(&server);
    let v = within(Duration::from_secs(3), || c.embed(&texts, "index")).unwrap();
    assert_eq!(v, vec![vec![0.6f32, 0.8]]);
    assert_eq!(c.telemetry().calls()[0].retries, 2);
    for (reply, outcome) in [
        (Reply::recorded("I am a language model and cannot embed.", "text/plain"), LlmOutcome::Malformed),
        (Reply::recorded(r#"{"data":[{"index":0,"embedding":[1,"x"]}]}"#, "application/json"), LlmOutcome::Malformed),
        (Reply::recorded(r#"{"data":[]}"#, "application/json"), LlmOutcome::Malformed),
        (Reply::status(401, "bad key"), LlmOutcome::Rejected),
        (Reply::Hang(Duration::from_secs(5)), LlmOutcome::Timeout),
    ] {
        let server = MockServer::start(move |_| reply.clone()).unwrap();
        let c = client(&server);
        let e = within(Duration::from_secs(8), || c.embed(&texts, "index")).unwrap_err();
        assert_eq!(e.outcome(), outcome, "{e}");
        assert!(e.to_string().contains("embeddings stage"), "{e}");
    }
    let e = Client::new(LlmConfig::offline()).embed(&texts, "index").unwrap_err();
    assert!(e.to_string().contains("embeddings stage"), "{e}");
}
