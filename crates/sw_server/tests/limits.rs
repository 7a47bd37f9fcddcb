//! Issue 22 through the Router: everything that scales a job's work is bounded before it
//! is queued (robots, variations, objects, seed); one user cannot fill the queue and users
//! are served in turn, with `Retry-After` on every 429; sign-ins and registrations are
//! limited; names are one whatever their case; the service account's name is reserved;
//! signing out and revoking a key end them at once; `?token=` works only on a job's
//! WebSocket; `/metrics` is the admins'; `GET /api/jobs?limit=`; security headers.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use axum::body::Body;
use axum::http::{Method, Request, StatusCode, header};
use common::{Payload, app};
use serde_json::{Value, json};
use sw_store::{CountedTable, QueueLimits};
use tower::ServiceExt;

fn err(v: &Value) -> &str {
    v["error"].as_str().unwrap_or_else(|| panic!("no error message in {v}"))
}

/// A request's full answer: status, headers, JSON body.
async fn full(a: &common::App, req: Request<Body>) -> (StatusCode, axum::http::HeaderMap, Value) {
    let resp = a.router.clone().oneshot(req).await.unwrap();
    let (status, headers) = (resp.status(), resp.headers().clone());
    let bytes = axum::body::to_bytes(resp.into_body(), usize::MAX).await.unwrap();
    (status, headers, serde_json::from_slice(&bytes).unwrap_or(Value::Null))
}

fn post(uri: &str, token: Option<&str>, body: Value) -> Request<Body> {
    let mut b = Request::builder().method(Method::POST).uri(uri).header("content-type", "application/json");
    if let Some(t) = token {
        b = b.header("authorization", format!("Bearer {t}"));
    }
    b.body(Body::from(body.to_string())).unwrap()
}

#[tokio::test]
async fn work_is_bounded_before_anything_is_queued() {
    let a = app(QueueLimits::default()).await;
    let t = a.user("ann").await;
    let robots = |n: usize| json!({"prompt": "a lab with a table", "robots": vec!["ur5e"; n]});
    let cases = [
        (robots(3000), "robots: at most 16 per scene, got 3000"),
        (robots(17), "at most 16"),
        (json!({"prompt": "a lab", "variations": 0}), "variations: 1 to 10"),
        (json!({"prompt": "a lab", "variations": 11}), "variations: 1 to 10"),
        (json!({"prompt": "a lab", "seed": i64::MAX as u64, "variations": 2}), "seed"),
        (json!({"prompt": "a warehouse with 100000 boxes"}), "ask for fewer"),
        (json!({"prompt": "a warehouse with 1500 boxes and 1500 crates"}), "ask for fewer"),
        (json!({"prompt": "zzzz qqqq"}), "nothing in the prompt was recognised"),
    ];
    for (body, says) in cases {
        let (s, v) = a.post("/api/jobs", &t, body.clone()).await;
        assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{body}: {v}");
        assert!(err(&v).contains(says), "{body}: {says:?} not in {v}");
    }
    assert_eq!(a.jobs_stored().await, 0, "nothing was queued");
    // Sixteen robots, "none" entries not counted, are fine.
    let mut names = vec!["ur5e"; 16];
    names.push("none");
    let (s, v) = a.post("/api/jobs", &t, json!({"prompt": "a lab with a table", "robots": names})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");

    // Variations: one request, one job per seed, queued together.
    let (s, v) = a.post("/api/jobs", &t, json!({"prompt": "a lab with a table", "seed": 7, "variations": 3})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let ids: Vec<&str> = v["job_ids"].as_array().unwrap().iter().map(|x| x.as_str().unwrap()).collect();
    assert_eq!((ids.len(), ids[0]), (3, v["job_id"].as_str().unwrap()));
    let mut seeds = Vec::new();
    for id in &ids {
        seeds.push(a.get(&format!("/api/jobs/{id}"), &t).await.1["seed"].as_u64().unwrap());
    }
    assert_eq!(seeds, vec![7, 8, 9]);
    // `limit` is obeyed, and checked.
    let (_, v) = a.get("/api/jobs?limit=2", &t).await;
    assert_eq!(v["jobs"].as_array().unwrap().len(), 2);
    let (s, v) = a.get("/api/jobs?limit=0", &t).await;
    assert_eq!((s, err(&v).contains("limit")), (StatusCode::UNPROCESSABLE_ENTITY, true), "{v}");
}

#[tokio::test]
async fn one_user_cannot_fill_the_queue_and_429s_say_when_to_retry() {
    let limits = QueueLimits { queue_cap: 10, per_user_running: 5, per_user_queued: 4 };
    let a = app(limits).await;
    let (ann, bob) = (a.user("ann").await, a.user("bob").await);
    for i in 0..4 {
        let (s, v) = a.post("/api/jobs", &ann, json!({"prompt": "a lab with a table", "seed": i})).await;
        assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    }
    let (s, h, v) = full(&a, post("/api/jobs", Some(&ann), json!({"prompt": "a lab with a table"}))).await;
    assert_eq!(s, StatusCode::TOO_MANY_REQUESTS, "{v}");
    assert!(err(&v).contains("as many as one user may"), "{v}");
    assert!(h.get(header::RETRY_AFTER).and_then(|v| v.to_str().ok()).is_some_and(|s| s.parse::<u64>().unwrap() > 0));
    // Variations are all or nothing against the share.
    let (s, _) = a.post("/api/jobs", &bob, json!({"prompt": "a lab with a table", "variations": 5})).await;
    assert_eq!(s, StatusCode::TOO_MANY_REQUESTS);
    assert_eq!(a.jobs_stored().await, 4, "none of the five was queued");
    // Another user still gets in.
    let (s, v) = a.post("/api/jobs", &bob, json!({"prompt": "a lab with a table", "variations": 4})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    // The whole queue full: 429 with Retry-After too.
    let carl = a.user("carl").await;
    for _ in 0..2 {
        a.post("/api/jobs", &carl, json!({"prompt": "a lab with a table"})).await;
    }
    let (s, h, v) = full(&a, post("/api/jobs", Some(&carl), json!({"prompt": "a lab with a table"}))).await;
    assert_eq!(s, StatusCode::TOO_MANY_REQUESTS, "{v}");
    assert!(err(&v).contains("the queue is full"), "{v}");
    assert!(h.contains_key(header::RETRY_AFTER));

    // Served in turn: ann queued first, but bob's and carl's first jobs come before ann's second.
    let mut owners = Vec::new();
    for _ in 0..4 {
        let c = a.state.store.claim("w", 60_000, limits).await.unwrap().unwrap();
        owners.push(a.state.store.user(&c.job.user_id).await.unwrap().unwrap().username);
    }
    assert_eq!(owners, vec!["ann", "bob", "carl", "ann"], "round robin, not arrival order");
}

#[tokio::test]
async fn sign_ins_and_registrations_are_limited_and_names_are_one_whatever_their_case() {
    let a = app(QueueLimits::default()).await;
    a.user("Alice").await;
    for name in ["alice", "ALICE", "aLiCe"] {
        let (s, v) = a
            .call(
                Method::POST,
                "/api/auth/register",
                None,
                Payload::Json(json!({"username": name, "password": "another password"})),
            )
            .await;
        assert_eq!(s, StatusCode::CONFLICT, "{name}: {v}");
    }
    // Signing in by any case finds the one user, and says the name as registered.
    let (s, v) = a
        .call(
            Method::POST,
            "/api/auth/login",
            None,
            Payload::Json(json!({"username": "ALICE", "password": "correct horse battery"})),
        )
        .await;
    assert_eq!((s, v["username"].as_str()), (StatusCode::OK, Some("Alice")), "{v}");
    assert_eq!(a.state.store.count_rows(CountedTable::Users).await.unwrap(), 1);

    // The service account's name (any case) is not for registration.
    for name in ["scenewright-dataset", "SceneWright-Dataset", "scenewright-anything"] {
        let (s, v) = a
            .call(
                Method::POST,
                "/api/auth/register",
                None,
                Payload::Json(json!({"username": name, "password": "long enough pw"})),
            )
            .await;
        assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{name}: {v}");
        assert!(err(&v).contains("reserved"), "{v}");
    }

    // Wrong passwords: after ten for a name, 429 with Retry-After — even with the right one.
    let wrong = json!({"username": "alice", "password": "wrong password"});
    for i in 0..10 {
        let (s, _, v) = full(&a, post("/api/auth/login", None, wrong.clone())).await;
        assert_eq!(s, StatusCode::UNAUTHORIZED, "attempt {i}: {v}");
    }
    let right = json!({"username": "alice", "password": "correct horse battery"});
    let (s, h, v) = full(&a, post("/api/auth/login", None, right)).await;
    assert_eq!(s, StatusCode::TOO_MANY_REQUESTS, "{v}");
    assert!(err(&v).contains("too many wrong sign-ins"), "{v}");
    let wait: u64 = h[header::RETRY_AFTER].to_str().unwrap().parse().unwrap();
    assert!((1..=300).contains(&wait), "{wait}");

    // Registrations from one address: twenty an hour.
    let b = app(QueueLimits::default()).await;
    for i in 0..20 {
        b.user(&format!("user{i}")).await;
    }
    let (s, h, v) =
        full(&b, post("/api/auth/register", None, json!({"username": "one_more", "password": "long enough pw"}))).await;
    assert_eq!(s, StatusCode::TOO_MANY_REQUESTS, "{v}");
    assert!(h.contains_key(header::RETRY_AFTER));
}

#[tokio::test]
async fn signing_out_and_revoking_keys_end_them_now() {
    let a = app(QueueLimits::default()).await;
    let t = a.user("ann").await;
    let (s, _) = a.get("/api/me", &t).await;
    assert_eq!(s, StatusCode::OK);
    let (s, _) = a.call(Method::POST, "/api/auth/logout", Some(&t), Payload::None).await;
    assert_eq!(s, StatusCode::NO_CONTENT);
    let (s, v) = a.get("/api/me", &t).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED, "{v}");
    assert!(err(&v).contains("revoked"), "{v}");

    // A new sign-in works; a key works until it is revoked.
    let t = a.user_login("ann").await;
    let (_, k) = a.post("/api/auth/keys", &t, json!({"name": "script"})).await;
    let key = k["key"].as_str().unwrap().to_string();
    assert_eq!(a.get("/api/me", &key).await.0, StatusCode::OK);
    let path = format!("/api/auth/keys/{}", k["id"].as_str().unwrap());
    // Not another user's to revoke.
    let bob = a.user("bob").await;
    assert_eq!(a.call(Method::DELETE, &path, Some(&bob), Payload::None).await.0, StatusCode::NOT_FOUND);
    assert_eq!(a.call(Method::DELETE, &path, Some(&t), Payload::None).await.0, StatusCode::NO_CONTENT);
    let (s, v) = a.get("/api/me", &key).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED, "{v}");
    assert!(a.get("/api/auth/keys", &t).await.1["keys"].as_array().unwrap().is_empty());
}

#[tokio::test]
async fn tokens_in_urls_metrics_and_headers() {
    let a = app(QueueLimits::default()).await;
    let admin = a.user("ann").await;
    let user = a.user("bob").await;
    // `?token=` outside a job's WebSocket is refused.
    let (s, v) = a.call(Method::GET, &format!("/api/me?token={user}"), None, Payload::None).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED, "{v}");
    assert!(err(&v).contains("only by a job's WebSocket"), "{v}");
    let (s, _) = a.call(Method::GET, &format!("/api/scenes?token={user}"), None, Payload::None).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
    // /metrics: the admins'.
    assert_eq!(a.call(Method::GET, "/metrics", None, Payload::None).await.0, StatusCode::UNAUTHORIZED);
    assert_eq!(a.call(Method::GET, "/metrics", Some(&user), Payload::None).await.0, StatusCode::FORBIDDEN);
    let (s, m) = a.raw(Method::GET, "/metrics", Some(&admin), Payload::None).await;
    assert_eq!(s, StatusCode::OK);
    assert!(String::from_utf8(m).unwrap().contains("scenewright_pipelines_running 0"));
    // Every answer carries the security headers: the API's, the app's, a 404.
    for uri in ["/api/me", "/healthz", "/api/nothing", "/"] {
        let req = Request::builder().uri(uri).header("authorization", format!("Bearer {user}")).body(Body::empty());
        let (_, h, _) = full(&a, req.unwrap()).await;
        let csp = h.get(header::CONTENT_SECURITY_POLICY).and_then(|v| v.to_str().ok()).unwrap_or("");
        assert!(csp.contains("frame-ancestors 'none'") && csp.contains("default-src 'self'"), "{uri}: {csp}");
        assert_eq!(h.get(header::X_CONTENT_TYPE_OPTIONS).map(|v| v.as_bytes()), Some(&b"nosniff"[..]), "{uri}");
    }
}
