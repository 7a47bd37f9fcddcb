//! A service over a temporary data directory, driven through its `Router`, with its
//! database in the directory (SQLite) or in a throwaway PostgreSQL cluster.

#![allow(clippy::unwrap_used, clippy::expect_used)]
#![allow(dead_code)]

use std::sync::Arc;

use axum::Router;
use axum::body::Body;
use axum::http::{Method, Request, StatusCode};
use serde_json::{Value, json};
use sw_server::{AppState, RunnerConfig};
use sw_store::QueueLimits;
use tower::ServiceExt;

/// The throwaway PostgreSQL cluster of the store's tests (one copy of how to start one).
#[path = "../../../sw_store/tests/cluster/mod.rs"]
pub mod cluster;

/// Where a test service keeps its database.
#[derive(Debug, Clone)]
pub enum Db {
    /// `scenewright.db` in the service's data directory.
    Sqlite,
    /// A database URL (`postgres://…`).
    Url(String),
}

pub const PROMPT: &str = "a 10 by 8 m warehouse with a conveyor, a table with four boxes on it, three chairs next to the conveyor, a red cabinet and a shelf against the north wall";

pub struct App {
    pub dir: tempfile::TempDir,
    pub state: AppState,
    pub router: Router,
}

pub fn runner() -> RunnerConfig {
    RunnerConfig { poll_ms: 50, ..RunnerConfig::default() }
}

pub async fn app(limits: QueueLimits) -> App {
    app_with(limits, runner()).await
}

/// A service on the database `db`.
pub async fn app_on(db: &Db, limits: QueueLimits) -> App {
    app_with_on(db, limits, runner()).await
}

/// A service whose runners have this configuration (their scratch space in the app's directory).
pub async fn app_with(limits: QueueLimits, r: RunnerConfig) -> App {
    app_with_on(&Db::Sqlite, limits, r).await
}

/// [`app_with`] on the database `db`.
pub async fn app_with_on(db: &Db, limits: QueueLimits, mut r: RunnerConfig) -> App {
    let dir = tempfile::tempdir().unwrap();
    let url = match db {
        Db::Sqlite => None,
        Db::Url(u) => Some(u.as_str()),
    };
    let (store, blobs) = sw_server::open_data(dir.path(), url).await.unwrap();
    let backend = if url.is_some() { sw_store::Backend::Postgres } else { sw_store::Backend::Sqlite };
    assert_eq!(store.backend(), backend);
    r.work_dir = Some(dir.path().join("work"));
    let state = AppState::new(store, blobs, limits, r, 3600).await.unwrap();
    let router = sw_server::router(state.clone());
    App { dir, state, router }
}

/// Starts `n` runners in this process; they stop when the returned sender is dropped or sent to.
pub fn start_workers(state: &AppState, n: usize) -> tokio::sync::oneshot::Sender<()> {
    let (tx, rx) = tokio::sync::oneshot::channel::<()>();
    tokio::spawn(sw_server::run_workers(state.clone(), n, async move {
        let _ = rx.await;
    }));
    tx
}

pub enum Payload<'a> {
    None,
    Json(Value),
    Raw(&'a str, Option<&'a str>),
}

impl App {
    pub async fn raw(
        &self,
        method: Method,
        uri: &str,
        token: Option<&str>,
        body: Payload<'_>,
    ) -> (StatusCode, Vec<u8>) {
        let mut b = Request::builder().method(method).uri(uri);
        if let Some(t) = token {
            b = b.header("authorization", format!("Bearer {t}"));
        }
        let body = match body {
            Payload::None => Body::empty(),
            Payload::Json(v) => {
                b = b.header("content-type", "application/json");
                Body::from(v.to_string())
            }
            Payload::Raw(s, ct) => {
                if let Some(ct) = ct {
                    b = b.header("content-type", ct);
                }
                Body::from(s.to_string())
            }
        };
        let resp = self.router.clone().oneshot(b.body(body).unwrap()).await.unwrap();
        let status = resp.status();
        let bytes = axum::body::to_bytes(resp.into_body(), usize::MAX).await.unwrap();
        (status, bytes.to_vec())
    }

    pub async fn call(&self, method: Method, uri: &str, token: Option<&str>, body: Payload<'_>) -> (StatusCode, Value) {
        let (s, b) = self.raw(method, uri, token, body).await;
        let v = serde_json::from_slice(&b).unwrap_or_else(|_| Value::String(String::from_utf8_lossy(&b).into_owned()));
        (s, v)
    }

    pub async fn get(&self, uri: &str, token: &str) -> (StatusCode, Value) {
        self.call(Method::GET, uri, Some(token), Payload::None).await
    }

    pub async fn post(&self, uri: &str, token: &str, body: Value) -> (StatusCode, Value) {
        self.call(Method::POST, uri, Some(token), Payload::Json(body)).await
    }

    /// Registers and logs in; returns the access token.
    pub async fn user(&self, name: &str) -> String {
        let creds = json!({"username": name, "password": "correct horse battery"});
        let (s, v) = self.call(Method::POST, "/api/auth/register", None, Payload::Json(creds.clone())).await;
        assert_eq!(s, StatusCode::CREATED, "{v}");
        let (s, v) = self.call(Method::POST, "/api/auth/login", None, Payload::Json(creds)).await;
        assert_eq!(s, StatusCode::OK, "{v}");
        v["token"].as_str().unwrap().to_string()
    }

    /// Logs an existing user in; returns a new access token.
    pub async fn user_login(&self, name: &str) -> String {
        let creds = json!({"username": name, "password": "correct horse battery"});
        let (s, v) = self.call(Method::POST, "/api/auth/login", None, Payload::Json(creds)).await;
        assert_eq!(s, StatusCode::OK, "{v}");
        v["token"].as_str().unwrap().to_string()
    }

    /// Waits until a job is terminal (no time limit here: the job's own timeout ends it).
    pub async fn wait_job(&self, id: &str, token: &str) -> Value {
        loop {
            let (s, v) = self.get(&format!("/api/jobs/{id}"), token).await;
            assert_eq!(s, StatusCode::OK, "{v}");
            if ["succeeded", "failed", "cancelled"].contains(&v["state"].as_str().unwrap()) {
                return v;
            }
            tokio::time::sleep(std::time::Duration::from_millis(50)).await;
        }
    }

    pub async fn jobs_stored(&self) -> i64 {
        self.state.store.count_rows(sw_store::CountedTable::Jobs).await.unwrap()
    }
}

pub fn shared<T>(t: T) -> Arc<T> {
    Arc::new(t)
}

/// A tiny HTTP/1.1 client over a real socket: status, headers (lower-case names) and the
/// body as JSON (or `Null`).
pub async fn http(
    addr: std::net::SocketAddr,
    method: &str,
    path: &str,
    token: Option<&str>,
    body: Option<Value>,
) -> (u16, std::collections::BTreeMap<String, String>, Value) {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let mut s = tokio::net::TcpStream::connect(addr).await.unwrap();
    let body = body.map(|b| b.to_string()).unwrap_or_default();
    let mut req =
        format!("{method} {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nContent-Length: {}\r\n", body.len());
    if !body.is_empty() {
        req.push_str("Content-Type: application/json\r\n");
    }
    if let Some(t) = token {
        req.push_str(&format!("Authorization: Bearer {t}\r\n"));
    }
    req.push_str("\r\n");
    req.push_str(&body);
    s.write_all(req.as_bytes()).await.unwrap();
    let mut buf = Vec::new();
    s.read_to_end(&mut buf).await.unwrap();
    let text = String::from_utf8_lossy(&buf);
    let (head, body) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status: u16 = head.split(' ').nth(1).and_then(|s| s.parse().ok()).unwrap_or(0);
    let headers = head
        .lines()
        .skip(1)
        .filter_map(|l| l.split_once(':'))
        .map(|(k, v)| (k.trim().to_ascii_lowercase(), v.trim().to_string()))
        .collect();
    // Chunked bodies are not expected here (JSON answers have a length).
    (status, headers, serde_json::from_str(body).unwrap_or(Value::Null))
}

/// Serves `a`'s router on a loopback port (with the service's own connection handling)
/// until the returned sender is dropped or sent to.
pub async fn serve_on_socket(
    a: &App,
    opts: sw_server::HttpOptions,
) -> (std::net::SocketAddr, tokio::sync::oneshot::Sender<()>, tokio::task::JoinHandle<()>) {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let (tx, rx) = tokio::sync::oneshot::channel::<()>();
    let router = a.router.clone();
    let task = tokio::spawn(async move {
        let _ = sw_server::http::serve(listener, router, opts, async move {
            let _ = rx.await;
        })
        .await;
    });
    (addr, tx, task)
}
