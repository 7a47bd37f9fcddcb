//! What the browser app needs from the service: its files at `/` (with `index.html` for its
//! routes, precompressed twins, cache headers), gzip and ETags for scene files, the
//! refinement chat, structured edits (a move, a placed part) beside sentences, a scene's
//! versions, thumbnails, API key listing, and the forge's progress as a stream. Bad input
//! (malformed edits, another user's scene or asset, too long a chat) answers a clear 4xx.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::io::Read;

use axum::body::Body;
use axum::http::{Method, Request, StatusCode, header};
use common::{App, PROMPT, Payload, app, start_workers};
use serde_json::{Value, json};
use sw_store::QueueLimits;
use tower::ServiceExt;

/// A raw request with headers; answers the status, the headers and the body.
async fn fetch(
    a: &App,
    uri: &str,
    token: Option<&str>,
    headers: &[(&str, &str)],
) -> (StatusCode, axum::http::HeaderMap, Vec<u8>) {
    let mut b = Request::builder().method(Method::GET).uri(uri);
    if let Some(t) = token {
        b = b.header("authorization", format!("Bearer {t}"));
    }
    for (k, v) in headers {
        b = b.header(*k, *v);
    }
    let resp = a.router.clone().oneshot(b.body(Body::empty()).unwrap()).await.unwrap();
    let (parts, body) = resp.into_parts();
    (parts.status, parts.headers, axum::body::to_bytes(body, usize::MAX).await.unwrap().to_vec())
}

fn gunzip(data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    flate2::read::GzDecoder::new(data).read_to_end(&mut out).unwrap();
    out
}

fn with_web(mut a: App, web: &std::path::Path) -> App {
    a.state.web_dir = Some(web.to_path_buf());
    a.router = sw_server::router(a.state.clone());
    a
}

#[tokio::test]
async fn the_app_is_served_at_its_routes_with_cache_headers_and_compressed_twins() {
    let web = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(web.path().join("assets")).unwrap();
    std::fs::write(web.path().join("index.html"), "<!doctype html><title>app</title>").unwrap();
    let js = "console.log('scenewright');".repeat(100);
    std::fs::write(web.path().join("assets/index-abc123.js"), &js).unwrap();
    std::fs::write(web.path().join("assets/index-abc123.js.br"), b"brotli bytes").unwrap();
    std::fs::write(web.path().join("assets/index-abc123.js.gz"), sw_server_gzip(js.as_bytes())).unwrap();
    let a = with_web(app(QueueLimits::default()).await, web.path());

    for route in ["/", "/scenes/0123456789abcdef0123456789abcdef", "/jobs/x", "/studio", "/settings"] {
        let (s, h, body) = fetch(&a, route, None, &[]).await;
        assert_eq!(s, StatusCode::OK, "{route}");
        assert!(String::from_utf8_lossy(&body).contains("<title>app</title>"), "{route} is not index.html");
        assert_eq!(h[header::CACHE_CONTROL], "no-cache", "{route}");
        assert!(h[header::CONTENT_TYPE].to_str().unwrap().starts_with("text/html"));
    }
    let (s, h, body) = fetch(&a, "/assets/index-abc123.js", None, &[("accept-encoding", "gzip, deflate, br")]).await;
    assert_eq!(
        (s, h[header::CONTENT_ENCODING].to_str().unwrap(), body.as_slice()),
        (StatusCode::OK, "br", &b"brotli bytes"[..])
    );
    assert!(h[header::CACHE_CONTROL].to_str().unwrap().contains("immutable"));
    assert_eq!(h[header::VARY], "accept-encoding");
    let (_, h, body) = fetch(&a, "/assets/index-abc123.js", None, &[("accept-encoding", "gzip")]).await;
    assert_eq!(h[header::CONTENT_ENCODING], "gzip");
    assert_eq!(gunzip(&body), js.as_bytes());
    let (_, h, body) = fetch(&a, "/assets/index-abc123.js", None, &[]).await;
    assert!(h.get(header::CONTENT_ENCODING).is_none());
    assert_eq!(body, js.as_bytes());
    let etag = h[header::ETAG].to_str().unwrap().to_string();
    let (s, _, _) = fetch(&a, "/assets/index-abc123.js", None, &[("if-none-match", &etag)]).await;
    assert_eq!(s, StatusCode::NOT_MODIFIED);

    // A missing file, a path outside the app and the API's own 404s stay JSON 404s.
    for bad in ["/assets/missing.js", "/../../etc/passwd.txt", "/api/nothing"] {
        let (s, h, body) = fetch(&a, bad, None, &[]).await;
        assert_eq!(s, StatusCode::NOT_FOUND, "{bad}");
        assert_eq!(h[header::CONTENT_TYPE], "application/json", "{bad}");
        assert!(String::from_utf8_lossy(&body).contains("no route"), "{bad}");
    }
    // A JSON answer is gzipped for a client that accepts it.
    let (s, h, body) = fetch(&a, "/api/openapi.json", None, &[("accept-encoding", "gzip")]).await;
    assert_eq!((s, h[header::CONTENT_ENCODING].to_str().unwrap()), (StatusCode::OK, "gzip"));
    let doc: Value = serde_json::from_slice(&gunzip(&body)).unwrap();
    assert!(doc["paths"].is_object());

    // Without a built app, / says how to build it (not a blank page, not a JSON 404).
    let bare = app(QueueLimits::default()).await;
    let (s, _, body) = fetch(&bare, "/scenes/abc", None, &[]).await;
    assert_eq!(s, StatusCode::OK);
    assert!(String::from_utf8_lossy(&body).contains("scripts/setup.sh --web"));
}

fn sw_server_gzip(data: &[u8]) -> Vec<u8> {
    use std::io::Write;
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    e.write_all(data).unwrap();
    e.finish().unwrap()
}

async fn edit(a: &App, scene: &str, token: &str, body: Value) -> Value {
    let (s, v) = a.post(&format!("/api/scenes/{scene}/edits"), token, body).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    a.wait_job(v["job_id"].as_str().unwrap(), token).await
}

async fn layout(a: &App, scene: &str, token: &str) -> Value {
    let (s, v) = a.get(&format!("/api/scenes/{scene}/files/layout.json"), token).await;
    assert_eq!(s, StatusCode::OK);
    v
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn structured_edits_versions_files_and_thumbnails() {
    let a = app(QueueLimits::default()).await;
    let _workers = start_workers(&a.state, 2);
    let ann = a.user("ann").await;
    let bob = a.user("bob").await;
    let (s, v) = a.post("/api/jobs", &ann, json!({ "prompt": PROMPT })).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let job = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    assert_eq!(job["state"], "succeeded", "{job}");
    let v1 = job["scene_id"].as_str().unwrap().to_string();

    // Scene files: gzip for clients that accept it, an ETag, a year of caching.
    let uri = format!("/api/scenes/{v1}/files/scene.xml");
    let (_, h, plain) = fetch(&a, &uri, Some(&ann), &[]).await;
    let (_, hz, packed) = fetch(&a, &uri, Some(&ann), &[("accept-encoding", "gzip")]).await;
    assert_eq!(hz[header::CONTENT_ENCODING], "gzip");
    assert_eq!(gunzip(&packed), plain);
    assert!(packed.len() * 3 < plain.len(), "{} of {} bytes", packed.len(), plain.len());
    assert!(h[header::CACHE_CONTROL].to_str().unwrap().contains("immutable"));
    let etag = h[header::ETAG].to_str().unwrap().to_string();
    let (s, _, _) = fetch(&a, &uri, Some(&ann), &[("if-none-match", &etag)]).await;
    assert_eq!(s, StatusCode::NOT_MODIFIED);
    let (_, again, packed2) = fetch(&a, &uri, Some(&ann), &[("accept-encoding", "gzip")]).await;
    assert_eq!((packed2, again[header::CONTENT_ENCODING].to_str().unwrap()), (packed, "gzip"), "the cached body");

    // A move to a point outside the room: kept inside, verified, the next version.
    let l1 = layout(&a, &v1, &ann).await;
    let cabinet = l1["objects"].as_array().unwrap().iter().find(|o| o["category"] == "cabinet").unwrap()["name"]
        .as_str()
        .unwrap()
        .to_string();
    let job = edit(&a, &v1, &ann, json!({ "move": { "object": cabinet, "pos": [50.0, 0.0] } })).await;
    assert_eq!(job["state"], "succeeded", "{job}");
    let v2 = job["scene_id"].as_str().unwrap().to_string();
    let l2 = layout(&a, &v2, &ann).await;
    let moved = l2["objects"].as_array().unwrap().iter().find(|o| o["name"] == cabinet.as_str()).unwrap();
    let x = moved["pos"][0].as_f64().unwrap();
    let half = l2["room"]["size"]["width"].as_f64().unwrap() / 2.0;
    assert!(x < half && x > half - 1.5, "x = {x} in a room of half width {half}");
    let (_, scene) = a.get(&format!("/api/scenes/{v2}"), &ann).await;
    assert_eq!(scene["status"], "verified");
    assert_eq!(scene["version"], 2);
    assert!(scene["report"]["warnings"].as_array().unwrap().iter().any(|w| w["code"] == "moved_inside_room"));

    // A catalog part at a point, turned.
    let job =
        edit(&a, &v2, &ann, json!({ "place": { "asset": "catalog:crate", "pos": [-3.0, -2.5], "yaw_deg": 45 } })).await;
    assert_eq!(job["state"], "succeeded", "{job}");
    let v3 = job["scene_id"].as_str().unwrap().to_string();
    let added: Vec<Value> = layout(&a, &v3, &ann).await["objects"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|o| o["category"] == "crate")
        .cloned()
        .collect();
    assert_eq!(added.len(), 1);

    // Refusals: the job fails with the reason, no version is made.
    let job = edit(&a, &v3, &ann, json!({ "move": { "object": "unicorn_1", "pos": [0, 0] } })).await;
    assert_eq!(job["state"], "failed");
    assert!(job["error"].as_str().unwrap().contains("no object named unicorn_1"), "{job}");
    for (body, says) in [
        (json!({ "command": "remove the cabinet", "move": { "object": "x", "pos": [0, 0] } }), "exactly one"),
        (json!({}), "exactly one"),
        (json!({ "move": { "object": "a b", "pos": [0, 0] } }), "object"),
        (json!({ "move": { "object": "table_1", "pos": [1e9, 0] } }), "pos"),
        (json!({ "place": { "asset": "catalog:unicorn", "pos": [0, 0] } }), "not a catalog category"),
    ] {
        let (s, v) = a.post(&format!("/api/scenes/{v3}/edits"), &ann, body.clone()).await;
        assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{body}: {v}");
        assert!(v["error"].as_str().unwrap().contains(says), "{body}: {v}");
    }
    let (s, _) = a
        .post(
            &format!("/api/scenes/{v3}/edits"),
            &ann,
            json!({ "place": { "asset": "0123456789abcdef0123456789abcdef", "pos": [0, 0] } }),
        )
        .await;
    assert_eq!(s, StatusCode::NOT_FOUND, "an asset that is not the caller's");

    // The lineage, oldest first, each with the edit that made it; any version lists it all.
    let (s, v) = a.get(&format!("/api/scenes/{v1}/versions"), &ann).await;
    assert_eq!(s, StatusCode::OK);
    let versions = v["versions"].as_array().unwrap();
    let ids: Vec<&str> = versions.iter().map(|x| x["id"].as_str().unwrap()).collect();
    assert_eq!(ids, vec![v1.as_str(), v2.as_str(), v3.as_str()]);
    assert!(versions[0]["command"].is_null());
    assert!(versions[1]["command"].as_str().unwrap().starts_with(&format!("move {cabinet} to (50.00, 0.00)")));
    assert_eq!(versions[2]["scene_prompt"], PROMPT);
    assert_eq!(a.get(&format!("/api/scenes/{v3}/versions"), &ann).await.1["versions"], v["versions"]);

    // A thumbnail: a PNG drawn once, then kept.
    let (s, h, png) = fetch(&a, &format!("/api/scenes/{v3}/thumbnail.png"), Some(&ann), &[]).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(h[header::CONTENT_TYPE], "image/png");
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let mut reader = png::Decoder::new(std::io::Cursor::new(&png)).read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    assert_eq!((info.width, info.height), (480, 300));
    let colours: std::collections::BTreeSet<&[u8]> = pixels[..info.buffer_size()].chunks(3).collect();
    assert!(colours.len() > 30, "a picture of {} colours", colours.len());
    assert_eq!(fetch(&a, &format!("/api/scenes/{v3}/thumbnail.png"), Some(&ann), &[]).await.2, png);

    // Another user: every one of these is a 404, as if the scene did not exist.
    for uri in [format!("/api/scenes/{v1}/versions"), format!("/api/scenes/{v1}/thumbnail.png")] {
        let (s, _, _) = fetch(&a, &uri, Some(&bob), &[]).await;
        assert_eq!(s, StatusCode::NOT_FOUND, "{uri}");
    }
    let (s, _) =
        a.post(&format!("/api/scenes/{v1}/edits"), &bob, json!({ "move": { "object": cabinet, "pos": [0, 0] } })).await;
    assert_eq!(s, StatusCode::NOT_FOUND);
}

#[tokio::test]
async fn the_refinement_chat_is_stateless_turn_by_turn() {
    let a = app(QueueLimits::default()).await;
    let ann = a.user("ann").await;
    let (s, v) = a.post("/api/refine", &ann, json!({ "prompt": "a lab with a workbench" })).await;
    assert_eq!(s, StatusCode::OK, "{v}");
    assert_eq!(v["done"], false);
    assert_eq!(v["asked_by"], "offline");
    let q1 = v["question"].as_str().unwrap().to_string();
    assert!(q1.to_lowercase().contains("room"), "{q1}");
    let turns = json!([{ "question": q1, "answer": "9 by 7 m" }]);
    let (_, v) = a.post("/api/refine", &ann, json!({ "prompt": "a lab with a workbench", "turns": turns })).await;
    assert!(v["prompt"].as_str().unwrap().contains("9 by 7"), "{v}");
    let q2 = v["question"].as_str().unwrap().to_string();
    assert_ne!(q1, q2, "the answered question is not asked again");
    let turns = json!([{ "question": q1, "answer": "9 by 7 m" }, { "question": q2, "answer": "done" }]);
    let (_, v) = a.post("/api/refine", &ann, json!({ "prompt": "a lab with a workbench", "turns": turns })).await;
    assert_eq!(v["done"], true, "{v}");
    assert!(v["question"].is_null());
    assert!(v["summary"].as_str().unwrap().contains("9.0 × 7.0"), "{v}");
    assert_eq!(v["turns"].as_array().unwrap().len(), 2);
    // The first question of an empty prompt asks for a description; "done" to it is an error.
    let (_, v) = a.post("/api/refine", &ann, json!({})).await;
    let q = v["question"].as_str().unwrap().to_string();
    let (s, v) = a.post("/api/refine", &ann, json!({ "turns": [{ "question": q, "answer": "done" }] })).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    // Bad input.
    let many: Vec<Value> = (0..20).map(|i| json!({ "question": format!("q{i}"), "answer": "skip" })).collect();
    let (s, _) = a.post("/api/refine", &ann, json!({ "prompt": "a lab", "turns": many })).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY);
    let (s, _) = a.post("/api/refine", &ann, json!({ "prompt": "a lab", "turns": [{ "question": "q" }] })).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY);
    let (s, _) = a.call(Method::POST, "/api/refine", None, Payload::Json(json!({ "prompt": "a lab" }))).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
}

#[tokio::test]
async fn keys_are_listed_without_their_secrets_and_options_are_offered() {
    let a = app(QueueLimits::default()).await;
    let ann = a.user("ann").await;
    let (s, made) = a.post("/api/auth/keys", &ann, json!({ "name": "laptop" })).await;
    assert_eq!(s, StatusCode::CREATED);
    let (s, v) = a.get("/api/auth/keys", &ann).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(v["keys"].as_array().unwrap().len(), 1);
    assert_eq!(v["keys"][0]["name"], "laptop");
    assert_eq!(v["keys"][0]["id"], made["id"]);
    assert!(!v.to_string().contains(made["key"].as_str().unwrap()), "a listed key shows its secret");
    let bob = a.user("bob").await;
    assert_eq!(a.get("/api/auth/keys", &bob).await.1["keys"], json!([]));
    let (_, o) = a.get("/api/options", &ann).await;
    assert!(o["rules_profiles"].as_array().unwrap().iter().any(|p| p == "laboratory"), "{o}");
    assert_eq!(o["anomaly_kinds"].as_array().unwrap().len(), 5);
    // Anomalies a job asks for reach its scene; bad ones are refused.
    let (s, v) = a
        .post("/api/jobs", &ann, json!({ "prompt": "a room", "options": { "anomaly": { "kinds": [], "rate": 0.2 } } }))
        .await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    let (s, v) = a
        .post(
            "/api/jobs",
            &ann,
            json!({ "prompt": "a room", "options": { "anomaly": { "kinds": ["overlap"], "rate": 2.0 } } }),
        )
        .await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    let (s, v) = a
        .post(
            "/api/jobs",
            &ann,
            json!({ "prompt": "a room", "options": { "anomaly": { "kinds": ["teleport"], "rate": 0.5 } } }),
        )
        .await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn anomalies_asked_for_by_a_job_are_labelled_in_its_scene() {
    let a = app(QueueLimits::default()).await;
    let _workers = start_workers(&a.state, 1);
    let ann = a.user("ann").await;
    let body = json!({ "prompt": "a warehouse with ten boxes on two tables", "seed": 4, "options": { "anomaly": { "kinds": ["floating"], "rate": 0.5 } } });
    let (s, v) = a.post("/api/jobs", &ann, body).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let job = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    assert_eq!(job["state"], "succeeded", "{job}");
    let l = layout(&a, job["scene_id"].as_str().unwrap(), &ann).await;
    let labels = l["anomalies"].as_array().unwrap();
    assert!(!labels.is_empty() && labels.iter().all(|x| x["kind"] == "floating"), "{labels:?}");
}

/// The lines of a streamed answer.
fn lines(body: &[u8]) -> Vec<Value> {
    String::from_utf8_lossy(body)
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// Needs `scripts/setup.sh --tests` (the CadQuery venv and the MiniLM weights).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_forge_streams_its_progress_and_search_ranks_parts_by_meaning() {
    let mut a = app(QueueLimits::default()).await;
    let store = a.dir.path().join("assets").display().to_string();
    a.state = a.state.clone().with_asset_store(store);
    a.router = sw_server::router(a.state.clone());
    let ann = a.user("ann").await;
    let stream = |d: &str| Payload::Json(json!({ "description": d }));

    let (s, body) = a
        .raw(
            Method::POST,
            "/api/assets?stream=1",
            Some(&ann),
            stream("A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm"),
        )
        .await;
    assert_eq!(s, StatusCode::OK);
    let events = lines(&body);
    assert!(events.iter().filter(|e| e["event"] == "progress").count() >= 3, "{events:?}");
    let last = events.last().unwrap();
    assert_eq!(last["event"], "asset", "{events:?}");
    assert_eq!(last["asset"]["meta"]["source"], "generated");
    let washer = last["asset"]["id"].as_str().unwrap().to_string();

    // What cannot be made: each failed attempt with its kind, then the reason.
    let (s, body) =
        a.raw(Method::POST, "/api/assets?stream=1", Some(&ann), stream("a sentient hovercraft that sings opera")).await;
    assert_eq!(s, StatusCode::OK);
    let events = lines(&body);
    let failures: Vec<&Value> = events.iter().filter(|e| e["event"] == "failure").collect();
    assert!(
        !failures.is_empty() && failures.iter().all(|f| f["kind"].as_str().is_some_and(|k| !k.is_empty())),
        "{events:?}"
    );
    let last = events.last().unwrap();
    assert_eq!((last["event"].as_str(), last["status"].as_u64()), (Some("error"), Some(422)), "{last}");
    assert_eq!(last["kinds"].as_array().unwrap().len(), failures.len());
    // Bad input is refused before anything streams.
    let (s, _) = a.raw(Method::POST, "/api/assets?stream=1", Some(&ann), stream("  ")).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY);

    // A second part, of another kind; search by meaning puts the right one first.
    let (s, v) =
        a.post("/api/assets", &ann, json!({ "description": "a hex nut M12, 19mm across flats, 10mm thick" })).await;
    if s == StatusCode::CREATED && v["meta"]["asset_id"].is_string() {
        let nut = v["id"].as_str().unwrap().to_string();
        // Words of its shape, none of the description's: MiniLM knows shapes better than
        // what a part is for ("spreads the load under a bolt head" ranks the nut first).
        let (_, r) = a.get("/api/assets?q=a%20thin%20flat%20ring%20with%20a%20hole", &ann).await;
        assert_eq!(r["similar"][0]["id"], washer.as_str(), "{r}");
        let (_, r) = a.get("/api/assets?q=a%20threaded%20six-sided%20fastener", &ann).await;
        assert_eq!(r["similar"][0]["id"], nut.as_str(), "{r}");
        assert!(r["similar"][0]["score"].as_f64().unwrap() > r["similar"][1]["score"].as_f64().unwrap());
    } else {
        // The synthesizer reads fewer parts than it might; the washer alone still ranks.
        let (_, r) = a.get("/api/assets?q=a%20ring%20that%20spreads%20the%20load", &ann).await;
        assert_eq!(r["similar"][0]["id"], washer.as_str(), "{r}");
    }
    // Another user's search never sees ann's parts.
    let bob = a.user("bob").await;
    let (_, r) = a.get("/api/assets?q=washer", &bob).await;
    assert_eq!(r["similar"], json!([]));
    assert_eq!(r["mine"], json!([]));
}

/// With a REFINE model (a loopback OpenAI-compatible server), the model asks; resuming a
/// conversation sends it the transcript and asks it once per turn; a failing model leaves
/// the offline questions, and the answer says so.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_refinement_chat_asks_the_models_questions_when_one_is_configured() {
    use sw_llm::{Endpoint, LlmConfig, LlmStage};
    use sw_mockllm::{MockServer, Reply};
    let model = MockServer::start(|r| {
        let asked = r.messages().iter().filter(|(role, _)| role == "assistant").count();
        if asked == 0 {
            Reply::answer(r#"{"done": false, "question": "What will the arm pick up?"}"#)
        } else {
            Reply::answer(
                r#"{"done": true, "final_prompt": "a 6 by 5 m lab with a workbench and a UR5e that picks boxes"}"#,
            )
        }
    })
    .unwrap();
    let endpoint = |url: String| {
        let mut e = Endpoint::new(url, "m-refine");
        e.timeout = std::time::Duration::from_secs(5);
        e.max_retries = 0;
        e
    };
    let mut r = common::runner();
    r.llm = Some(LlmConfig::offline().with(LlmStage::Refine, endpoint(model.base_url())));
    let a = common::app_with(QueueLimits::default(), r).await;
    let ann = a.user("ann").await;
    let (s, v) = a.post("/api/refine", &ann, json!({ "prompt": "a lab with a workbench and a UR5e" })).await;
    assert_eq!(s, StatusCode::OK, "{v}");
    assert_eq!((v["asked_by"].as_str(), v["question"].as_str()), (Some("llm"), Some("What will the arm pick up?")));
    let turns = json!([{ "question": "What will the arm pick up?", "answer": "boxes" }]);
    let (_, v) =
        a.post("/api/refine", &ann, json!({ "prompt": "a lab with a workbench and a UR5e", "turns": turns })).await;
    assert_eq!(v["done"], true, "{v}");
    assert_eq!(v["prompt"], "a 6 by 5 m lab with a workbench and a UR5e that picks boxes");
    let calls = model.requests();
    assert_eq!(calls.len(), 2, "one call per turn, none to replay the past");
    assert!(
        calls[1].messages().iter().any(|(role, c)| role == "user" && c.contains("boxes")),
        "the answer reached the model"
    );

    // A model that fails: the offline questions, with a warning.
    let dead = MockServer::start(|_| Reply::status(500, "down")).unwrap();
    let mut r = common::runner();
    r.llm = Some(LlmConfig::offline().with(LlmStage::Refine, endpoint(dead.base_url())));
    let b = common::app_with(QueueLimits::default(), r).await;
    let bob = b.user("bob").await;
    let (s, v) = b.post("/api/refine", &bob, json!({ "prompt": "a lab with a workbench" })).await;
    assert_eq!(s, StatusCode::OK, "{v}");
    assert_eq!(v["asked_by"], "offline", "{v}");
    assert!(v["question"].as_str().unwrap().to_lowercase().contains("room"), "{v}");
    assert!(v["warnings"][0].as_str().unwrap().contains("offline planner's questions"), "{v}");
}

/// Decodes an RGB PNG: (width, height, pixels).
fn decode_rgb(png: &[u8]) -> (u32, u32, Vec<[u8; 3]>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(png)).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    let px = buf[..info.buffer_size()].chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
    (info.width, info.height, px)
}

#[tokio::test]
async fn catalog_categories_have_pictures() {
    let a = app(QueueLimits::default()).await;
    // No token: a picture of the catalog says nothing about a user, and an <img> sends none.
    let (s, h, mug) = fetch(&a, "/api/catalog/mug/picture.png", None, &[]).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(h[header::CONTENT_TYPE], "image/png");
    let (w, hgt, px) = decode_rgb(&mug);
    assert_eq!((w, hgt), (256, 256));
    // The thing fills a good part of the frame and is not one flat colour: the background is
    // the light grey the rasterizer clears to.
    let background = px.iter().filter(|p| **p == [238, 241, 246]).count() as f64 / px.len() as f64;
    assert!((0.05..0.95).contains(&background), "background covers {:.0} % of the mug's picture", background * 100.0);
    let colours: std::collections::BTreeSet<[u8; 3]> = px.iter().copied().collect();
    assert!(colours.len() >= 4, "a picture of {} colours", colours.len());
    // Asked again: the same bytes (kept, not drawn again differently).
    assert_eq!(fetch(&a, "/api/catalog/mug/picture.png", None, &[]).await.2, mug);
    // Another category is another picture; an unknown one is a 404.
    let (s, _, shelf) = fetch(&a, "/api/catalog/shelf/picture.png", None, &[]).await;
    assert_eq!(s, StatusCode::OK);
    assert_ne!(shelf, mug);
    let (s, _, body) = fetch(&a, "/api/catalog/no_such_thing/picture.png", None, &[]).await;
    assert_eq!(s, StatusCode::NOT_FOUND, "{}", String::from_utf8_lossy(&body));
    // Hostile or malformed names are a plain 404, never a file or a crash.
    let long = format!("/api/catalog/{}/picture.png", "x".repeat(5000));
    for uri in [
        "/api/catalog/..%2F..%2Fetc%2Fpasswd/picture.png",
        "/api/catalog/%00/picture.png",
        "/api/catalog/mug%20/picture.png",
        long.as_str(),
    ] {
        let (s, _, _) = fetch(&a, uri, None, &[]).await;
        assert_eq!(s, StatusCode::NOT_FOUND, "{}", &uri[..uri.len().min(60)]);
    }
    // A sample across the whole catalog draws (every category is built at seed 0).
    let all = sw_catalog::categories();
    for c in all.iter().step_by(37) {
        let (s, _, png) = fetch(&a, &format!("/api/catalog/{}/picture.png", c.name), None, &[]).await;
        assert_eq!(s, StatusCode::OK, "{}", c.name);
        let (_, _, px) = decode_rgb(&png);
        assert!(px.iter().any(|p| *p != [238, 241, 246]), "{} drew nothing", c.name);
    }
}
