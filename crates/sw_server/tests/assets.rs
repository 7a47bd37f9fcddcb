//! `POST /api/assets` runs the asset forge: a dimensioned part is generated offline (the
//! template synthesizer in the sandboxed runner), stored and indexed; asking again by
//! other words reuses it; a catalog category is recorded as such; what cannot be made is
//! a 422 with why; with a CAD model configured (a loopback OpenAI-compatible server) a
//! novel object is written by the model. Meshes are served to their owner only. Needs
//! `scripts/setup.sh --tests` (the CadQuery venv and the MiniLM weights).

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::time::Duration;

use axum::http::{Method, StatusCode};
use common::{App, Payload, app, app_with, runner};
use serde_json::json;
use sw_llm::{Endpoint, LlmConfig, LlmStage};
use sw_mockllm::{MockServer, Reply};
use sw_store::QueueLimits;

/// The app with its asset store in its own directory.
fn with_store(mut a: App) -> App {
    let store = a.dir.path().join("assets").display().to_string();
    a.state = a.state.clone().with_asset_store(store);
    a.router = sw_server::router(a.state.clone());
    a
}

async fn mesh(a: &App, id: &str, token: &str) -> (StatusCode, Vec<u8>) {
    a.raw(Method::GET, &format!("/api/assets/{id}/mesh.stl"), Some(token), Payload::None).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn assets_are_generated_offline_stored_reused_and_owned() {
    let a = with_store(app(QueueLimits::default()).await);
    let ann = a.user("ann").await;
    let washer = "A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm";
    let (s, v) = a.post("/api/assets", &ann, json!({ "description": washer })).await;
    assert_eq!(s, StatusCode::CREATED, "{v}");
    assert_eq!(v["meta"]["source"], "generated", "{v}");
    assert_eq!(v["meta"]["made_by"], "template");
    let size = v["meta"]["size_m"].as_array().unwrap();
    for (got, want) in size.iter().zip([0.020, 0.020, 0.002]) {
        assert!((got.as_f64().unwrap() - want).abs() < 0.0002, "{size:?}");
    }
    let stored = v["meta"]["asset_id"].as_str().unwrap().to_string();
    let first = v["id"].as_str().unwrap().to_string();
    let (s, stl) = mesh(&a, &first, &ann).await;
    assert_eq!(s, StatusCode::OK);
    let m = sw_geom::read_stl(stl.as_slice()).unwrap();
    assert!(m.check().watertight);
    let analytic = std::f64::consts::PI * (0.010f64.powi(2) - 0.00525f64.powi(2)) * 0.002;
    assert!((m.volume() - analytic).abs() / analytic < 0.02, "{} m³", m.volume());

    // The same part in other words, at its size: reused from the library, not made again.
    let (s, v) = a
        .post(
            "/api/assets",
            &ann,
            json!({ "description": "a flat washer, 20 mm across", "size_m": [0.02, 0.02, 0.002] }),
        )
        .await;
    assert_eq!(s, StatusCode::CREATED, "{v}");
    assert_eq!(v["meta"]["source"], "library", "{v}");
    assert_eq!(v["meta"]["asset_id"], stored.as_str());
    // Asked for ten times larger: the washer does not serve; no template reads the words either.
    let (s, v) = a
        .post("/api/assets", &ann, json!({ "description": "a flat washer, 20 mm across", "size_m": [0.2, 0.2, 0.02] }))
        .await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");

    // A catalog category is recorded as one.
    let (s, v) = a.post("/api/assets", &ann, json!({ "description": "a wooden table" })).await;
    assert_eq!(s, StatusCode::CREATED, "{v}");
    assert_eq!(v["meta"]["source"], "catalog");
    let (s, _) = mesh(&a, v["id"].as_str().unwrap(), &ann).await;
    assert_eq!(s, StatusCode::NOT_FOUND, "a catalog category has no stored mesh");

    // What neither the library nor a template can make is a 422 that says why, and nothing is stored.
    let before = a.get("/api/assets", &ann).await.1["mine"].as_array().unwrap().len();
    let (s, v) = a.post("/api/assets", &ann, json!({ "description": "a flux capacitor" })).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    assert!(v["error"].as_str().unwrap().contains("could not make"), "{v}");
    assert_eq!(a.get("/api/assets", &ann).await.1["mine"].as_array().unwrap().len(), before);
    // Bad sizes are refused before any work.
    for bad in [json!([0.1, 0.1]), json!([0.1, -1.0, 0.1]), json!([0.1, 0.1, 1e9]), json!("big")] {
        let (s, v) =
            a.post("/api/assets", &ann, json!({ "description": "a block 10mm x 10mm x 10mm", "size_m": bad })).await;
        assert!(s.is_client_error(), "{bad}: {s} {v}");
    }

    // Another user's asset and its mesh answer 404 as if they did not exist.
    let bob = a.user("bob").await;
    assert_eq!(a.get(&format!("/api/assets/{first}"), &bob).await.0, StatusCode::NOT_FOUND);
    assert_eq!(mesh(&a, &first, &bob).await.0, StatusCode::NOT_FOUND);
    assert_eq!(mesh(&a, "../../etc/passwd", &ann).await.0, StatusCode::NOT_FOUND);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn with_a_cad_model_a_novel_object_is_written_by_the_model() {
    let model = MockServer::start(|req| {
        let [x, y, z] = sw_forge::generate::asked_size_mm(&req.last_user()).unwrap_or([100.0, 100.0, 100.0]);
        Reply::answer(format!("```python\nimport cadquery as cq\nresult = cq.Workplane('XY').box({x}, {y}, {z})\n```"))
    })
    .unwrap();
    let mut e = Endpoint::new(model.base_url(), "m-cad");
    e.timeout = Duration::from_secs(10);
    e.max_retries = 0;
    let mut r = runner();
    r.llm = Some(LlmConfig::offline().with(LlmStage::Cad, e));
    let a = with_store(app_with(QueueLimits::default(), r).await);
    let ann = a.user("ann").await;
    let (s, v) = a
        .post(
            "/api/assets",
            &ann,
            json!({ "description": "a rack-mount spectrum analyzer", "size_m": [0.45, 0.4, 0.18] }),
        )
        .await;
    assert_eq!(s, StatusCode::CREATED, "{v}");
    assert_eq!(v["meta"]["source"], "generated");
    assert_eq!(v["meta"]["made_by"], "llm:m-cad");
    let (s, stl) = mesh(&a, v["id"].as_str().unwrap(), &ann).await;
    assert_eq!(s, StatusCode::OK);
    let size = sw_geom::read_stl(stl.as_slice()).unwrap().bounds().size();
    for (got, want) in size.iter().zip([0.45, 0.4, 0.18]) {
        assert!((got - want).abs() < 0.005, "{size:?}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn generation_jobs_use_the_models_and_the_forge_and_count_cache_hits() {
    let fixture =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../sw_pipeline/tests/assets/llm_plan_lab.json");
    let plan = std::fs::read_to_string(fixture).unwrap();
    let groups = serde_json::from_str::<serde_json::Value>(&plan).unwrap()["objects"].as_array().unwrap().len() as u64;
    let model = MockServer::start(move |req| {
        if req.model() != "m-cad" {
            return Reply::answer(plan.clone());
        }
        let [x, y, z] = sw_forge::generate::asked_size_mm(&req.last_user()).unwrap_or([100.0, 100.0, 100.0]);
        Reply::answer(format!("```python\nimport cadquery as cq\nresult = cq.Workplane('XY').box({x}, {y}, {z})\n```"))
    })
    .unwrap();
    let endpoint = |name: &str| {
        let mut e = Endpoint::new(model.base_url(), name);
        e.timeout = Duration::from_secs(10);
        e.max_retries = 0;
        e
    };
    let mut r = runner();
    r.llm = Some(LlmConfig::offline().with(LlmStage::Plan, endpoint("m-plan")).with(LlmStage::Cad, endpoint("m-cad")));
    let a = with_store(app_with(QueueLimits::default(), r).await);
    let _workers = common::start_workers(&a.state, 1);
    let ann = a.user("ann").await;
    let prompt = "a lab with a long workbench, three red bins and a spectrum analyzer on it, a tall cabinet against the north wall, and a UR5e on a pedestal next to the bench";
    let mut caches = Vec::new();
    for _ in 0..2 {
        let (s, v) = a.post("/api/jobs", &ann, json!({ "prompt": prompt })).await;
        assert_eq!(s, StatusCode::ACCEPTED, "{v}");
        let job = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
        assert_eq!(job["state"], "succeeded", "{job}");
        let (_, scene) = a.get(&format!("/api/scenes/{}", job["scene_id"].as_str().unwrap()), &ann).await;
        assert_eq!(scene["status"], "verified", "{scene}");
        let report = &scene["report"];
        let stages: Vec<&str> =
            report["llm_calls"].as_array().unwrap().iter().filter_map(|c| c["stage"].as_str()).collect();
        assert!(stages.contains(&"plan"), "{stages:?}");
        caches
            .push((report["asset_cache"]["hits"].as_u64().unwrap(), report["asset_cache"]["misses"].as_u64().unwrap()));
    }
    // The spectrum analyzer is generated by the model once; the second job reuses it.
    assert_eq!(caches, vec![(groups - 1, 1), (groups, 0)]);
    let (_, m) = a.raw(Method::GET, "/metrics", Some(&ann), Payload::None).await;
    let m = String::from_utf8(m).unwrap();
    assert!(m.contains(&format!("scenewright_asset_cache_lookups_total{{result=\"hit\"}} {}", 2 * groups - 1)), "{m}");
    assert!(m.contains("scenewright_asset_cache_lookups_total{result=\"miss\"} 1"), "{m}");
}
