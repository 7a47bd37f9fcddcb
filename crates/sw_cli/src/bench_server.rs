//! `bench server`: the service under load, in this process over real sockets.
//!
//! - `websockets`: C clients, each its own user, submit a job and follow it on the
//!   WebSocket to the result; counts complete streams and reports the queue wait.
//! - `queue`: J jobs queued at once, W runners; checks that none is lost or completed
//!   twice and reports the throughput.

use std::net::SocketAddr;
use std::time::{Duration, Instant};

use futures_util::StreamExt;
use serde::Serialize;
use serde_json::{Value, json};
use sw_server::{AppState, RunnerConfig};
use sw_store::{JobKind, JobState, NewJob, QueueLimits};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio_tungstenite::tungstenite::Message;

use crate::Failure;
use crate::output::print_json;

#[derive(Debug, clap::Subcommand)]
pub(crate) enum ServerBench {
    /// C concurrent WebSocket clients, each submitting one job and following it.
    Websockets {
        #[arg(long, default_value_t = 100)]
        clients: usize,
        /// Job runners.
        #[arg(long, default_value_t = 5)]
        workers: usize,
        /// Skip MuJoCo verification (measures the service, not the physics).
        #[arg(long)]
        no_verify: bool,
        #[arg(long)]
        json: bool,
    },
    /// J jobs queued at once and W runners: losses, duplicates, throughput.
    Queue {
        #[arg(long, default_value_t = 1000)]
        jobs: usize,
        #[arg(long, default_value_t = 20)]
        workers: usize,
        #[arg(long)]
        no_verify: bool,
        /// An empty PostgreSQL database to run on (default: SQLite in a temporary directory).
        #[arg(long, value_name = "URL")]
        database: Option<String>,
        #[arg(long)]
        json: bool,
    },
}

const SUITE: &str = include_str!("../../../bench/prompts.txt");

fn prompts() -> Vec<String> {
    SUITE.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')).map(str::to_string).collect()
}

pub(crate) fn run(c: ServerBench) -> Result<u8, Failure> {
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| Failure::internal(format!("starting the async runtime: {e}")))?;
    rt.block_on(async move {
        match c {
            ServerBench::Websockets { clients, workers, no_verify, json } => {
                websockets(clients, workers, !no_verify, json).await
            }
            ServerBench::Queue { jobs, workers, no_verify, database, json } => {
                queue(jobs, workers, !no_verify, database, json).await
            }
        }
    })
}

async fn state(dir: &std::path::Path, database: Option<&str>, limits: QueueLimits) -> Result<AppState, Failure> {
    let (store, blobs) = sw_server::open_data(dir, database).await.map_err(|e| Failure::internal(e.to_string()))?;
    let runner = RunnerConfig { work_dir: Some(dir.join("work")), poll_ms: 100, ..RunnerConfig::default() };
    AppState::new(store, blobs, limits, runner, 3600).await.map_err(|e| Failure::internal(e.to_string()))
}

fn pct(xs: &mut [f64], p: f64) -> f64 {
    if xs.is_empty() {
        return 0.0;
    }
    xs.sort_by(f64::total_cmp);
    xs[((xs.len() - 1) as f64 * p).round() as usize]
}

async fn http(addr: SocketAddr, method: &str, path: &str, token: Option<&str>, body: Option<Value>) -> (u16, Value) {
    let Ok(mut s) = tokio::net::TcpStream::connect(addr).await else { return (0, Value::Null) };
    let body = body.map(|b| b.to_string()).unwrap_or_default();
    let mut req = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nContent-Type: application/json\r\nContent-Length: {}\r\n",
        body.len()
    );
    if let Some(t) = token {
        req.push_str(&format!("Authorization: Bearer {t}\r\n"));
    }
    req.push_str("\r\n");
    req.push_str(&body);
    if s.write_all(req.as_bytes()).await.is_err() {
        return (0, Value::Null);
    }
    let mut buf = Vec::new();
    let _ = s.read_to_end(&mut buf).await;
    let text = String::from_utf8_lossy(&buf);
    let status = text.split(' ').nth(1).and_then(|x| x.parse().ok()).unwrap_or(0);
    let body = text.split_once("\r\n\r\n").map(|x| x.1).unwrap_or("");
    (status, serde_json::from_str(body).unwrap_or(Value::Null))
}

#[derive(Debug, Serialize)]
struct WsResult {
    clients: usize,
    workers: usize,
    verify: bool,
    completed: usize,
    saw_every_stage: usize,
    verified: usize,
    queue_wait_p50_ms: f64,
    queue_wait_p95_ms: f64,
    run_p50_ms: f64,
    wall_s: f64,
    scenes_per_s: f64,
    failures: Vec<String>,
}

async fn websockets(clients: usize, workers: usize, verify: bool, json_out: bool) -> Result<u8, Failure> {
    let dir = tempfile::tempdir().map_err(|e| Failure::internal(e.to_string()))?;
    let limits = QueueLimits {
        queue_cap: clients.max(100) as i64,
        per_user_running: 5,
        per_user_queued: clients.max(100) as i64,
    };
    let st = state(dir.path(), None, limits).await?;
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.map_err(|e| Failure::internal(e.to_string()))?;
    let addr = listener.local_addr().map_err(|e| Failure::internal(e.to_string()))?;
    let app = sw_server::router(st.clone());
    tokio::spawn(async move { axum_serve(listener, app).await });
    let (stop_tx, stop_rx) = tokio::sync::oneshot::channel::<()>();
    let runners = tokio::spawn(sw_server::run_workers(st.clone(), workers, async move {
        let _ = stop_rx.await;
    }));

    // Users first (argon2 is deliberately slow; not part of the measurement).
    let mut tokens = Vec::new();
    for i in 0..clients {
        let creds = json!({"username": format!("client{i}"), "password": "benchmark password"});
        http(addr, "POST", "/api/auth/register", None, Some(creds.clone())).await;
        let (_, v) = http(addr, "POST", "/api/auth/login", None, Some(creds)).await;
        tokens.push(v["token"].as_str().unwrap_or_default().to_string());
    }
    let prompts = prompts();
    let t0 = Instant::now();
    let mut tasks = Vec::new();
    for (i, token) in tokens.into_iter().enumerate() {
        let prompt = prompts[i % prompts.len()].clone();
        tasks.push(tokio::spawn(async move {
            let body = json!({"prompt": prompt, "seed": i, "options": {"verify": verify}});
            let (s, v) = http(addr, "POST", "/api/jobs", Some(&token), Some(body)).await;
            if s != 202 {
                return Err(format!("client {i}: submit answered {s}: {v}"));
            }
            let id = v["job_id"].as_str().unwrap_or_default().to_string();
            let url = format!("ws://{addr}/api/jobs/{id}/events?token={token}");
            let (mut ws, _) =
                tokio_tungstenite::connect_async(url).await.map_err(|e| format!("client {i}: websocket: {e}"))?;
            let mut events = Vec::new();
            while let Some(m) = ws.next().await {
                match m {
                    Ok(Message::Text(t)) => events.push(serde_json::from_str::<Value>(&t).unwrap_or(Value::Null)),
                    Ok(Message::Close(_)) | Err(_) => break,
                    _ => {}
                }
            }
            Ok(events)
        }));
    }
    let mut r = WsResult {
        clients,
        workers,
        verify,
        completed: 0,
        saw_every_stage: 0,
        verified: 0,
        queue_wait_p50_ms: 0.0,
        queue_wait_p95_ms: 0.0,
        run_p50_ms: 0.0,
        wall_s: 0.0,
        scenes_per_s: 0.0,
        failures: Vec::new(),
    };
    let mut waits = Vec::new();
    let mut runs = Vec::new();
    for t in tasks {
        match t.await {
            Ok(Ok(events)) => {
                let last = events.last().cloned().unwrap_or(Value::Null);
                if last["event"] == "result" && last["job"]["state"] == "succeeded" {
                    r.completed += 1;
                    if let Some(w) = last["job"]["queue_wait_ms"].as_f64() {
                        waits.push(w);
                    }
                    if let (Some(s), Some(f)) =
                        (last["job"]["started_at"].as_f64(), last["job"]["finished_at"].as_f64())
                    {
                        runs.push(f - s);
                    }
                    if last["scene"]["status"] == "verified" {
                        r.verified += 1;
                    }
                } else {
                    r.failures.push(format!("{}", last["job"]["error"]));
                }
                let every = ["plan", "forge", "layout", "bridge", "verify"].iter().all(|stage| {
                    ["stage_started", "stage_finished"]
                        .iter()
                        .all(|k| events.iter().any(|e| e["event"] == *k && e["stage"] == *stage))
                });
                let every = every || (!verify && events.iter().filter(|e| e["event"] == "stage_finished").count() >= 4);
                if every {
                    r.saw_every_stage += 1;
                }
            }
            Ok(Err(e)) => r.failures.push(e),
            Err(e) => r.failures.push(e.to_string()),
        }
    }
    r.wall_s = t0.elapsed().as_secs_f64();
    r.scenes_per_s = r.completed as f64 / r.wall_s;
    r.queue_wait_p50_ms = pct(&mut waits, 0.5);
    r.queue_wait_p95_ms = pct(&mut waits, 0.95);
    r.run_p50_ms = pct(&mut runs, 0.5);
    let _ = stop_tx.send(());
    let _ = tokio::time::timeout(Duration::from_secs(10), runners).await;
    if json_out {
        print_json(&r);
    } else {
        eprintln!(
            "websockets: {} clients, {} runners, verify {}: {} completed, {} saw every stage event, {} verified; queue wait p50 {:.0} ms, p95 {:.0} ms; run p50 {:.0} ms; {:.1} s, {:.2} scenes/s",
            r.clients,
            r.workers,
            r.verify,
            r.completed,
            r.saw_every_stage,
            r.verified,
            r.queue_wait_p50_ms,
            r.queue_wait_p95_ms,
            r.run_p50_ms,
            r.wall_s,
            r.scenes_per_s
        );
        for f in r.failures.iter().take(5) {
            eprintln!("  failure: {f}");
        }
    }
    Ok(if r.completed == clients && r.saw_every_stage == clients { 0 } else { 1 })
}

async fn axum_serve(listener: tokio::net::TcpListener, app: axum::Router) {
    let _ = axum::serve(listener, app).await;
}

#[derive(Debug, Serialize)]
struct QueueResult {
    database: &'static str,
    jobs: usize,
    workers: usize,
    verify: bool,
    succeeded: usize,
    failed: usize,
    lost: usize,
    completed_twice: usize,
    scenes_stored: i64,
    verified: usize,
    wall_s: f64,
    scenes_per_s: f64,
    queue_wait_p50_ms: f64,
    errors: Vec<String>,
}

async fn queue(
    jobs: usize,
    workers: usize,
    verify: bool,
    database: Option<String>,
    json_out: bool,
) -> Result<u8, Failure> {
    let dir = tempfile::tempdir().map_err(|e| Failure::internal(e.to_string()))?;
    let limits =
        QueueLimits { queue_cap: jobs as i64 + 1, per_user_running: workers as i64, per_user_queued: jobs as i64 + 1 };
    let st = state(dir.path(), database.as_deref(), limits).await?;
    let store = st.store.clone();
    let ie = |e: sw_store::StoreError| Failure::internal(e.to_string());
    let mut users = Vec::new();
    for i in 0..10 {
        users.push(store.create_user(&format!("user{i}"), "not a login", None).await.map_err(ie)?.id);
    }
    let prompts = prompts();
    for i in 0..jobs {
        let new = NewJob {
            user_id: users[i % users.len()].clone(),
            kind: JobKind::Generate,
            prompt: prompts[i % prompts.len()].clone(),
            seed: i as u64,
            options: json!({"verify": verify}),
            parent_scene_id: None,
            timeout_ms: 600_000,
            max_attempts: 3,
        };
        store.enqueue(&new, limits).await.map_err(ie)?;
    }
    let t0 = Instant::now();
    let (stop_tx, stop_rx) = tokio::sync::oneshot::channel::<()>();
    let runners = tokio::spawn(sw_server::run_workers(st.clone(), workers, async move {
        let _ = stop_rx.await;
    }));
    loop {
        let counts = store.count_by_state().await.map_err(ie)?;
        let open: i64 = counts.iter().filter(|c| !c.0.is_terminal()).map(|c| c.1).sum();
        if open == 0 {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    let wall = t0.elapsed().as_secs_f64();
    let _ = stop_tx.send(());
    let _ = tokio::time::timeout(Duration::from_secs(10), runners).await;
    let all = store.all_jobs().await.map_err(ie)?;
    let scenes = store.count_rows(sw_store::CountedTable::Scenes).await.map_err(ie)?;
    let mut waits: Vec<f64> = all.iter().filter_map(|j| j.queue_wait_ms().map(|w| w as f64)).collect();
    let mut verified = 0;
    for j in all.iter().filter(|j| j.state == JobState::Succeeded) {
        if let Some(sid) = &j.scene_id
            && let Ok(Some(sc)) = store.scene_of(sid, &j.user_id).await
            && sc.status == "verified"
        {
            verified += 1;
        }
    }
    let mut errors: Vec<String> = all.iter().filter_map(|j| j.error.clone()).collect();
    errors.sort();
    errors.dedup();
    let r = QueueResult {
        database: if database.is_some() { "postgresql" } else { "sqlite" },
        jobs,
        workers,
        verify,
        succeeded: all.iter().filter(|j| j.state == JobState::Succeeded).count(),
        failed: all.iter().filter(|j| j.state == JobState::Failed).count(),
        lost: jobs.saturating_sub(all.len()) + all.iter().filter(|j| !j.state.is_terminal()).count(),
        completed_twice: all.iter().filter(|j| j.completions > 1).count(),
        scenes_stored: scenes,
        verified,
        wall_s: wall,
        scenes_per_s: all.iter().filter(|j| j.state == JobState::Succeeded).count() as f64 / wall,
        queue_wait_p50_ms: pct(&mut waits, 0.5),
        errors,
    };
    if json_out {
        print_json(&r);
    } else {
        eprintln!(
            "queue ({}): {} jobs, {} runners, verify {}: {} succeeded, {} failed, {} lost, {} completed twice, {} scenes stored, {} verified; {:.1} s, {:.2} scenes/s; queue wait p50 {:.0} ms",
            r.database,
            r.jobs,
            r.workers,
            r.verify,
            r.succeeded,
            r.failed,
            r.lost,
            r.completed_twice,
            r.scenes_stored,
            r.verified,
            r.wall_s,
            r.scenes_per_s,
            r.queue_wait_p50_ms
        );
        for e in r.errors.iter().take(5) {
            eprintln!("  error: {e}");
        }
    }
    Ok(if r.lost == 0 && r.completed_twice == 0 && r.scenes_stored as usize == r.succeeded { 0 } else { 1 })
}
