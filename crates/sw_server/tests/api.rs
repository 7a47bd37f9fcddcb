//! Auth, bad input, the queue cap, the OpenAPI document, roles — through the Router, on
//! SQLite (a test each) and on a throwaway PostgreSQL cluster (one test for them all).

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use axum::http::{Method, StatusCode};
use common::cluster::Cluster;
use common::{App, Db, Payload, app, app_on};
use serde_json::json;
use sw_store::{CountedTable, QueueLimits};

fn err(v: &serde_json::Value) -> &str {
    v["error"].as_str().unwrap_or_else(|| panic!("no error message in {v}"))
}

/// Each scenario as a SQLite test of its own name, and all of them, in order, on PostgreSQL
/// (each in a fresh database of one cluster).
macro_rules! on_sqlite_and_postgresql {
    ($($name:ident),* $(,)?) => {
        mod sqlite {
            $(
                #[tokio::test]
                async fn $name() {
                    super::$name(super::Db::Sqlite).await;
                }
            )*
        }

        #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
        async fn the_api_on_postgresql() {
            let cluster = Cluster::start();
            $( $name(Db::Url(cluster.database(stringify!($name)))).await; )*
        }
    };
}

on_sqlite_and_postgresql!(
    register_login_and_identity,
    missing_invalid_and_expired_credentials_are_refused,
    api_keys_work_like_tokens,
    bad_job_requests_get_a_clear_4xx_and_store_nothing,
    sql_in_a_prompt_is_only_text,
    a_full_queue_answers_429,
    a_queued_job_can_be_cancelled,
    roles_guard_the_admin_overview,
    assets_and_robots,
);

async fn register_login_and_identity(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let (s, me) = a.get("/api/me", &t).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(me["username"], "ann");
    assert_eq!(me["role"], "admin", "the first user is the admin");
    assert!(me.get("password_hash").is_none());
    let t2 = a.user("bob").await;
    assert_eq!(a.get("/api/me", &t2).await.1["role"], "user");

    let creds = |u: &str, p: &str| Payload::Json(json!({"username": u, "password": p}));
    let (s, v) = a.call(Method::POST, "/api/auth/register", None, creds("ann", "another password")).await;
    assert_eq!(s, StatusCode::CONFLICT, "{v}");
    let (s, v) = a.call(Method::POST, "/api/auth/register", None, creds("carl", "short")).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    let (s, v) = a.call(Method::POST, "/api/auth/register", None, creds("../../etc", "long enough pw")).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    let (s, v) = a.call(Method::POST, "/api/auth/register", None, creds("x' OR '1'='1", "long enough pw")).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    let (s, v) = a.call(Method::POST, "/api/auth/login", None, creds("ann", "wrong password")).await;
    assert_eq!((s, err(&v)), (StatusCode::UNAUTHORIZED, "wrong user name or password"));
    let (s, v) = a.call(Method::POST, "/api/auth/login", None, creds("' OR 1=1 --", "wrong password")).await;
    assert_eq!((s, err(&v)), (StatusCode::UNAUTHORIZED, "wrong user name or password"));
    assert_eq!(a.state.store.count_rows(CountedTable::Users).await.unwrap(), 2);
}

async fn missing_invalid_and_expired_credentials_are_refused(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let (s, v) = a.call(Method::GET, "/api/me", None, Payload::None).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
    assert!(err(&v).contains("access token"));
    let (s, _) = a.get("/api/me", "not.a.jwt").await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
    // A valid token with one character of its signature changed.
    let mut bad = t.clone();
    let last = bad.pop().unwrap();
    bad.push(if last == 'A' { 'B' } else { 'A' });
    let (s, v) = a.get("/api/me", &bad).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED, "{v}");
    // A token signed with another secret.
    let user = a.state.store.user_by_name("ann").await.unwrap().unwrap();
    let foreign = sw_server::Tokens::new(b"some other secret", 3600).issue(&user).unwrap();
    assert_eq!(a.get("/api/me", &foreign).await.0, StatusCode::UNAUTHORIZED);
    // An expired token (issued two hours ago, valid for one).
    let old = a.state.tokens.issue_at(&user, sw_store::now_ms() / 1000 - 7200).unwrap();
    let (s, v) = a.get("/api/me", &old).await;
    assert_eq!((s, err(&v)), (StatusCode::UNAUTHORIZED, "the access token has expired; log in again"));
    // The wrong scheme.
    let req = axum::http::Request::builder().uri("/api/me").header("authorization", format!("Basic {t}"));
    let resp =
        tower::ServiceExt::oneshot(a.router.clone(), req.body(axum::body::Body::empty()).unwrap()).await.unwrap();
    assert_eq!(resp.status(), StatusCode::UNAUTHORIZED);
}

async fn api_keys_work_like_tokens(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let (s, v) = a.post("/api/auth/keys", &t, json!({"name": "ci"})).await;
    assert_eq!(s, StatusCode::CREATED, "{v}");
    let key = v["key"].as_str().unwrap().to_string();
    assert!(key.starts_with("swk_"));
    assert_eq!(a.get("/api/me", &key).await.1["username"], "ann");
    let req = axum::http::Request::builder().uri("/api/me").header("x-api-key", &key);
    let resp =
        tower::ServiceExt::oneshot(a.router.clone(), req.body(axum::body::Body::empty()).unwrap()).await.unwrap();
    assert_eq!(resp.status(), StatusCode::OK);
    assert_eq!(a.get("/api/me", "swk_0000").await.0, StatusCode::UNAUTHORIZED);
}

async fn bad_job_requests_get_a_clear_4xx_and_store_nothing(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let raw = |body: &'static str| Payload::Raw(body, Some("application/json"));
    let cases: Vec<(Payload, StatusCode, &str)> = vec![
        (raw("{\"prompt\": \"a lab\""), StatusCode::BAD_REQUEST, "malformed JSON"),
        (raw("not json at all"), StatusCode::BAD_REQUEST, "malformed JSON"),
        (raw("{\"prompt\": 42}"), StatusCode::UNPROCESSABLE_ENTITY, "invalid type"),
        (raw("{\"prompt\": \"a lab\", \"seed\": \"seven\"}"), StatusCode::UNPROCESSABLE_ENTITY, "invalid type"),
        (raw("{\"prompt\": \"a lab\", \"seed\": -1}"), StatusCode::UNPROCESSABLE_ENTITY, "seed"),
        (raw("{\"seed\": 1}"), StatusCode::UNPROCESSABLE_ENTITY, "missing field `prompt`"),
        (raw("{\"prompt\": \"a lab\", \"admin\": true}"), StatusCode::UNPROCESSABLE_ENTITY, "unknown field `admin`"),
        (raw("{\"prompt\": \"   \"}"), StatusCode::UNPROCESSABLE_ENTITY, "the prompt is empty"),
        (
            raw("{\"prompt\": \"a lab\", \"robots\": [\"hal9000\"]}"),
            StatusCode::UNPROCESSABLE_ENTITY,
            "unknown robot 'hal9000'",
        ),
        (
            raw("{\"prompt\": \"a lab\", \"options\": {\"rules\": \"x'; DROP TABLE jobs; --\"}}"),
            StatusCode::UNPROCESSABLE_ENTITY,
            "unknown rules profile",
        ),
        (
            Payload::Raw("{\"prompt\": \"a lab\"}", None),
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "Content-Type: application/json",
        ),
    ];
    for (body, status, needle) in cases {
        let (s, v) = a.call(Method::POST, "/api/jobs", Some(&t), body).await;
        assert_eq!(s, status, "{v}");
        assert!(err(&v).contains(needle), "{needle:?} not in {v}");
    }
    // A prompt over 64 KiB.
    let big = "a lab with a table. ".repeat(3300);
    let (s, v) = a.post("/api/jobs", &t, json!({"prompt": big})).await;
    assert_eq!(s, StatusCode::PAYLOAD_TOO_LARGE, "{v}");
    assert!(err(&v).contains("at most 65536"), "{v}");
    // A body over the 1 MiB limit.
    let huge = "x".repeat(2 << 20);
    let (s, v) = a.post("/api/jobs", &t, json!({"prompt": huge})).await;
    assert_eq!(s, StatusCode::PAYLOAD_TOO_LARGE, "{v}");
    // No token: refused before anything is read.
    let (s, _) = a.call(Method::POST, "/api/jobs", None, Payload::Json(json!({"prompt": "a lab"}))).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
    assert_eq!(a.jobs_stored().await, 0);
    assert_eq!(a.state.store.count_rows(CountedTable::Prompts).await.unwrap(), 0);
}

async fn sql_in_a_prompt_is_only_text(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let prompt = "a lab'); DROP TABLE jobs; DELETE FROM users WHERE ('1'='1";
    let (s, v) = a.post("/api/jobs", &t, json!({"prompt": prompt, "seed": 3})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let (_, job) = a.get(&format!("/api/jobs/{}", v["job_id"].as_str().unwrap()), &t).await;
    assert_eq!(job["prompt"], prompt);
    assert_eq!(job["seed"], 3);
    assert_eq!(job["state"], "queued");
    assert_eq!(a.jobs_stored().await, 1);
    assert_eq!(a.state.store.count_rows(CountedTable::Users).await.unwrap(), 1);
}

async fn a_full_queue_answers_429(db: Db) {
    let a = app_on(&db, QueueLimits { queue_cap: 2, per_user_running: 5, per_user_queued: 2 }).await;
    let t = a.user("ann").await;
    for i in 0..2 {
        let (s, v) = a.post("/api/jobs", &t, json!({"prompt": format!("a lab with {i} tables")})).await;
        assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    }
    let (s, v) = a.post("/api/jobs", &t, json!({"prompt": "a lab with one more table"})).await;
    assert_eq!(s, StatusCode::TOO_MANY_REQUESTS);
    assert_eq!(err(&v), "the queue is full (2 jobs waiting); try again later");
    assert_eq!(a.jobs_stored().await, 2);
}

async fn a_queued_job_can_be_cancelled(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let (_, v) = a.post("/api/jobs", &t, json!({"prompt": "a lab with a table"})).await;
    let id = v["job_id"].as_str().unwrap();
    let (s, v) = a.call(Method::DELETE, &format!("/api/jobs/{id}"), Some(&t), Payload::None).await;
    assert_eq!((s, v["state"].as_str()), (StatusCode::OK, Some("cancelled")));
    // Runners started now never run it.
    let stop = common::start_workers(&a.state, 2);
    let (_, list) = a.get("/api/jobs", &t).await;
    assert_eq!(list["jobs"][0]["state"], "cancelled");
    drop(stop);
    let events = a.state.store.events_after(id, 0).await.unwrap();
    let kinds: Vec<_> = events.iter().map(|e| e.1["event"].as_str().unwrap().to_string()).collect();
    assert_eq!(kinds, ["queued", "cancelled"]);
}

async fn roles_guard_the_admin_overview(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let admin = a.user("root").await;
    let user = a.user("ann").await;
    a.post("/api/jobs", &user, json!({"prompt": "a lab"})).await;
    let (s, v) = a.get("/api/admin/jobs", &admin).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(v["by_state"]["queued"], 1);
    let (s, v) = a.get("/api/admin/jobs", &user).await;
    assert_eq!((s, err(&v)), (StatusCode::FORBIDDEN, "this needs the admin role"));
}

#[tokio::test]
async fn the_openapi_document_lists_every_route() {
    let a: App = app(QueueLimits::default()).await;
    let (s, doc) = a.call(Method::GET, "/api/openapi.json", None, Payload::None).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(doc["openapi"], "3.1.0");
    let src = include_str!("../src/lib.rs");
    let mut n = 0;
    for line in src.lines().filter(|l| l.trim_start().starts_with(".route(\"")) {
        let path = line.split('"').nth(1).unwrap().replace("{*path}", "{path}");
        assert!(doc["paths"].get(&path).is_some(), "{path} is not in the OpenAPI document");
        n += 1;
    }
    assert!(n >= 19, "found only {n} routes");
    let (s, v) = a.call(Method::GET, "/api/nothing-here", None, Payload::None).await;
    assert_eq!(s, StatusCode::NOT_FOUND);
    assert!(err(&v).contains("/api/nothing-here"));
    let (s, v) = a.call(Method::GET, "/healthz", None, Payload::None).await;
    assert_eq!((s, v["status"].as_str()), (StatusCode::OK, Some("ok")));
}

async fn assets_and_robots(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let t = a.user("ann").await;
    let (s, v) = a.get("/api/robots", &t).await;
    assert_eq!(s, StatusCode::OK);
    assert!(v["robots"].as_array().unwrap().iter().any(|r| r["name"] == "ur5e"));
    let (s, v) = a.post("/api/assets", &t, json!({"description": "pallet rack"})).await;
    assert_eq!(s, StatusCode::CREATED, "{v}");
    assert_eq!(v["category"], "pallet_rack");
    let id = v["id"].as_str().unwrap().to_string();
    let (s, v) = a.get("/api/assets?q=rack", &t).await;
    assert_eq!(s, StatusCode::OK);
    assert!(v["catalog"].as_array().unwrap().iter().any(|c| c["name"] == "pallet_rack"));
    assert_eq!(v["mine"][0]["id"], id.as_str());
    let (s, _) = a.get(&format!("/api/assets/{id}"), &t).await;
    assert_eq!(s, StatusCode::OK);
    let (s, v) = a.get("/api/assets?q=%27%20OR%201%3D1%20--", &t).await;
    assert_eq!((s, v["mine"].as_array().unwrap().len()), (StatusCode::OK, 0));
    let (s, _) = a.get("/api/assets?limit=5", &t).await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    let (s, _) = a.post("/api/assets", &t, json!({"description": 5})).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(a.state.store.count_rows(CountedTable::Assets).await.unwrap(), 1);
}

#[tokio::test]
async fn the_web_app_is_served_outside_the_api_and_cannot_be_escaped() {
    let mut a = app(QueueLimits::default()).await;
    let web = a.dir.path().join("web");
    std::fs::create_dir_all(web.join("js")).unwrap();
    std::fs::write(web.join("index.html"), "<!doctype html><title>scenewright</title>").unwrap();
    std::fs::write(web.join("js/app.js"), "export const x = 1;").unwrap();
    std::fs::write(a.dir.path().join("secret.txt"), "not for the web").unwrap();
    a.state.web_dir = Some(web);
    a.router = sw_server::router(a.state.clone());
    let (s, body) = a.raw(Method::GET, "/", None, Payload::None).await;
    assert_eq!(s, StatusCode::OK);
    assert!(String::from_utf8_lossy(&body).contains("<title>scenewright</title>"));
    let (s, body) = a.raw(Method::GET, "/js/app.js", None, Payload::None).await;
    assert_eq!((s, String::from_utf8_lossy(&body).into_owned()), (StatusCode::OK, "export const x = 1;".to_string()));
    for evil in ["/../secret.txt", "/%2e%2e/secret.txt", "/js/..%2f..%2fsecret.txt", "/scenewright.db"] {
        let (s, body) = a.raw(Method::GET, evil, None, Payload::None).await;
        assert_eq!(s, StatusCode::NOT_FOUND, "{evil}");
        assert!(!String::from_utf8_lossy(&body).contains("not for the web"), "{evil}");
    }
    // API paths never fall through to files.
    let (s, v) = a.call(Method::GET, "/api/index.html", None, Payload::None).await;
    assert_eq!(s, StatusCode::NOT_FOUND);
    assert!(err(&v).contains("no route"));
}
