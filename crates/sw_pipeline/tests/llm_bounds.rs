//! The LLM pipeline bounded and grounded, against a loopback server doing what small
//! models behind local servers do: a plan that contradicts the prompt (grounded: the
//! prompt's words win), a model that loops until its token limit (one bounded attempt,
//! then the offline planner), and part jobs of a plan that is thrown away (cancelled, not
//! waited for). Also: the schema the model is sent keeps every relation's subject and
//! bounds every string. Every scene is compiled and settled in MuJoCo by the pipeline.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::Arc;
use std::time::{Duration, Instant};

use serde_json::{Value, json};
use sw_llm::{Client, Endpoint, LlmConfig, LlmOutcome, LlmStage};
use sw_mockllm::{MockServer, Reply, Request};
use sw_pipeline::{CadCallSource, LlmRun, Options, generate_with_llm};
use sw_plan::Status;

fn config(server: &MockServer) -> LlmConfig {
    let mut cfg = LlmConfig::offline();
    for (stage, model) in [(LlmStage::Plan, "m-plan"), (LlmStage::Cad, "m-cad"), (LlmStage::Relations, "m-rel")] {
        let mut e = Endpoint::new(server.base_url(), model);
        e.timeout = Duration::from_millis(3000);
        e.backoff = Duration::from_millis(10);
        e.max_backoff = Duration::from_millis(40);
        e.max_retries = 1;
        e.endpoint_concurrency = Some(8);
        cfg = cfg.with(stage, e);
    }
    cfg
}

fn codes(o: &sw_pipeline::Outcome) -> Vec<String> {
    o.report.warnings.iter().map(|w| w.code.clone()).collect()
}

fn count(o: &sw_pipeline::Outcome, category: &str) -> u32 {
    o.plan.objects.iter().filter(|g| g.category == category).map(|g| g.count).sum()
}

#[test]
fn a_plan_that_contradicts_the_prompt_is_grounded_in_its_words() {
    let prompt = "a kitchen with a fridge, a sink and a table with two plates";
    let answer = json!({
        "objects": [
            {"phrase": "fridges", "id": "fridge", "category": "fridge", "count": 3},
            {"phrase": "a table", "id": "table", "category": "table", "count": 1},
            {"phrase": "a stool", "id": "stool", "category": "stool", "count": 2}
        ],
        "robots": [],
        "relations": [],
        "room": {"kind": "factory", "size": {"width": 45, "depth": 12, "height": 30}, "size_fixed": true, "door": "south"},
        "rules_profile": "industrial"
    })
    .to_string();
    let server = MockServer::start(move |_| Reply::answer(answer.clone())).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let run = LlmRun::new(Client::new(config(&server)));
    let o = generate_with_llm(prompt, &dir.path().join("s"), &Options::default(), &run, &mut |_| {}).unwrap();
    assert_eq!(o.report.status, Status::Verified);
    assert_eq!(o.plan.room.kind, sw_plan::RoomKind::Kitchen);
    assert!(!o.plan.room.size_fixed && o.plan.room.size.height < 5.0, "{:?}", o.plan.room);
    assert_eq!((count(&o, "fridge"), count(&o, "sink"), count(&o, "table"), count(&o, "plate")), (1, 1, 1, 2));
    assert!(count(&o, "stool") >= 1, "what the model adds stays");
    assert!(codes(&o).contains(&"llm_plan_grounded".to_string()), "{:?}", codes(&o));
    // The written package says so too.
    let report: Value = serde_json::from_str(&std::fs::read_to_string(o.out_dir.join("report.json")).unwrap()).unwrap();
    assert!(report["warnings"].as_array().unwrap().iter().any(|w| w["code"] == "llm_plan_grounded"));
}

#[test]
fn a_looping_model_costs_one_bounded_attempt_before_the_fallback() {
    let server = MockServer::start(|_| Reply::Tokens {
        content: format!("{{\"objects\": [{{\"phrase\": \"{}", "large ".repeat(200)),
        pieces: 200,
        gap: Duration::ZERO,
        finish: Some("length".into()),
        done: true,
        model: None,
    })
    .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let run = LlmRun::new(Client::new(config(&server)));
    let t0 = Instant::now();
    let o = generate_with_llm(
        "a lab with a workbench and two bins",
        &dir.path().join("s"),
        &Options::default(),
        &run,
        &mut |_| {},
    )
    .unwrap();
    assert!(t0.elapsed() < Duration::from_secs(10));
    assert_eq!(o.report.status, Status::Verified);
    assert_eq!(server.requests().len(), 1, "no retry, no repair round");
    assert!(codes(&o).contains(&"llm_answer_cut_off".to_string()), "{:?}", o.report.warnings);
    let call = &o.report.llm_calls[0];
    assert_eq!((call.outcome, call.max_tokens), (LlmOutcome::Length, Some(640)));
    assert_eq!(count(&o, "bin"), 2, "the offline plan");
}

#[test]
fn part_jobs_of_a_plan_that_is_thrown_away_are_cancelled() {
    // The model streams a plan with two things the catalog lacks, then the stream is cut
    // (`[DONE]` without a finish reason) on every attempt: the run falls back to the
    // offline plan, which has neither. The part jobs started from the stream must end.
    let plan = json!({
        "objects": [
            {"phrase": "a centrifuge", "id": "centrifuge", "category": "proxy", "count": 1,
             "proxy": {"label": "centrifuge", "prior": "tabletop item", "size": {"width": 0.5, "depth": 0.5, "height": 0.4}, "movable": false}},
            {"phrase": "an autoclave", "id": "autoclave", "category": "proxy", "count": 1,
             "proxy": {"label": "autoclave", "prior": "floor object", "size": {"width": 0.7, "depth": 0.6, "height": 0.9}, "movable": false}},
            {"phrase": "a workbench", "id": "bench", "category": "workbench", "count": 1}
        ],
        "robots": [], "relations": [],
        "room": {"kind": "lab", "size": {"width": 8, "depth": 6, "height": 3}, "size_fixed": false, "door": "south"},
        "rules_profile": "laboratory"
    })
    .to_string();
    let server = MockServer::start(move |req: &Request| match req.model().as_str() {
        "m-plan" => Reply::Tokens {
            content: plan.clone(),
            pieces: 40,
            gap: Duration::from_millis(10),
            finish: None,
            done: true,
            model: None,
        },
        // A slow model writing CAD code: 20 s if nobody stops it.
        _ => Reply::tokens("result = None\n".repeat(50), 100, Duration::from_millis(200)),
    })
    .unwrap();
    let client = Client::new(config(&server));
    let mut run = LlmRun::new(client.clone());
    run.assets = Arc::new(CadCallSource::new(client, true));
    let dir = tempfile::tempdir().unwrap();
    let t0 = Instant::now();
    let o = generate_with_llm(
        "a lab with a workbench and two bins",
        &dir.path().join("s"),
        &Options::default(),
        &run,
        &mut |_| {},
    )
    .unwrap();
    assert!(t0.elapsed() < Duration::from_secs(8), "the run waited for orphaned part jobs: {:?}", t0.elapsed());
    assert_eq!(o.report.status, Status::Verified);
    assert!(codes(&o).contains(&"llm_unavailable".to_string()), "{:?}", o.report.warnings);
    let cad: Vec<_> = o.report.llm_calls.iter().filter(|c| c.stage == LlmStage::Cad).collect();
    assert!(!cad.is_empty(), "part jobs started from the stream");
    assert!(cad.iter().all(|c| c.outcome == LlmOutcome::Cancelled), "{cad:?}");
    let deadline = Instant::now() + Duration::from_secs(3);
    while (server.abandoned() as usize) < cad.len() && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(server.abandoned() as usize >= cad.len(), "the server saw each cancelled call's connection close");
}

#[test]
fn the_schema_the_model_is_sent_keeps_every_subject_and_bounds_every_string() {
    let schema = sw_llm::schema::for_model(&sw_planner::llm::plan_schema());
    sw_llm::schema::refs_resolve(&schema).unwrap();
    let variants = schema["$defs"]["Relation"]["oneOf"].as_array().unwrap();
    assert!(variants.len() >= 13);
    for v in variants {
        assert_eq!(v["required"][0], "subject", "{v}");
        assert_eq!(v["properties"]["subject"]["pattern"], "^[a-z][a-z0-9_]{0,39}$", "{v}");
        assert_eq!(v["additionalProperties"], false, "{v}");
    }
    fn walk(v: &Value, path: &str, loose: &mut Vec<String>) {
        match v {
            Value::Object(o) => {
                let ty = o.get("type").and_then(Value::as_str);
                if ty == Some("string") && !["maxLength", "enum", "const", "pattern"].iter().any(|k| o.contains_key(*k))
                {
                    loose.push(path.to_string());
                }
                if ty == Some("array") && !o.contains_key("maxItems") {
                    loose.push(path.to_string());
                }
                if o.contains_key("properties") && o.get("additionalProperties") != Some(&Value::Bool(false)) {
                    loose.push(format!("{path} (open object)"));
                }
                if o.contains_key("properties") && (o.contains_key("oneOf") || o.contains_key("anyOf")) {
                    loose.push(format!("{path} (properties beside oneOf)"));
                }
                for (k, c) in o {
                    if k != "enum" && k != "const" {
                        walk(c, &format!("{path}/{k}"), loose);
                    }
                }
            }
            Value::Array(a) => a.iter().enumerate().for_each(|(i, c)| walk(c, &format!("{path}/{i}"), loose)),
            _ => {}
        }
    }
    for s in [
        schema,
        sw_llm::schema::for_model(&sw_planner::llm::relations_schema()),
        sw_llm::schema::for_model(&sw_edit::llm::model_schema()),
    ] {
        let mut loose = Vec::new();
        walk(&s, "", &mut loose);
        assert!(loose.is_empty(), "{loose:?}");
    }
}
