//! A cancelled or timed-out job stops working, not only stops being waited for: its
//! pipeline thread ends within seconds (the layout and the verification check the job's
//! flag in their loops), `/metrics` says so, and the next job — another user's — gets the
//! runner at once.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

use axum::http::StatusCode;
use serde_json::json;
use sw_server::RunnerConfig;
use sw_store::QueueLimits;

/// Two thousand boxes: a layout of about a minute (debug build), and minutes of settling.
const SLOW: &str = "a warehouse with 2000 boxes";

/// Waits until `f` holds, for at most `limit`; the time it took.
async fn within(limit: Duration, what: &str, mut f: impl AsyncFnMut() -> bool) -> Duration {
    let t0 = Instant::now();
    while !f().await {
        assert!(t0.elapsed() < limit, "{what}: not within {limit:?}");
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    t0.elapsed()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_cancelled_job_stops_working_and_the_next_one_runs() {
    let a = common::app(QueueLimits::default()).await;
    let _workers = common::start_workers(&a.state, 1);
    let (ann, bob) = (a.user("ann").await, a.user("bob").await);
    let (_, v) = a.post("/api/jobs", &ann, json!({"prompt": SLOW})).await;
    let slow = v["job_id"].as_str().unwrap().to_string();
    // Queued behind it on the one runner: another user's small job.
    let (_, v) = a.post("/api/jobs", &bob, json!({"prompt": "a lab with a table"})).await;
    let small = v["job_id"].as_str().unwrap().to_string();
    within(Duration::from_secs(60), "the slow job reaches the layout", async || {
        a.get(&format!("/api/jobs/{slow}"), &ann).await.1["stage"] == "layout"
    })
    .await;
    tokio::time::sleep(Duration::from_millis(500)).await;
    let pipelines = &a.state.metrics.pipelines;
    assert_eq!(pipelines.load(Ordering::SeqCst), 1, "the slow job is laying out");
    let (s, v) =
        a.call(axum::http::Method::DELETE, &format!("/api/jobs/{slow}"), Some(&ann), common::Payload::None).await;
    assert_eq!((s, v["state"].as_str()), (StatusCode::OK, Some("cancelled")), "{v}");
    let stopped = within(Duration::from_secs(8), "the cancelled pipeline stops", async || {
        // The small job may have started on the freed runner already: the slow one is gone
        // once at most one pipeline runs and the small one is past its queue.
        let small_started = a.get(&format!("/api/jobs/{small}"), &bob).await.1["state"] != "queued";
        pipelines.load(Ordering::SeqCst) == 0 || (small_started && pipelines.load(Ordering::SeqCst) <= 1)
    })
    .await;
    eprintln!("the cancelled layout stopped {stopped:?} after the cancel");
    let done = a.wait_job(&small, &bob).await;
    assert_eq!(done["state"], "succeeded", "{done}");
    assert!(
        done["queue_wait_ms"].as_i64().unwrap() < 30_000,
        "bob waited {} ms behind a cancelled job",
        done["queue_wait_ms"]
    );
    within(Duration::from_secs(5), "no pipeline left", async || pipelines.load(Ordering::SeqCst) == 0).await;
    // Cancelled: nothing stored.
    assert!(a.get(&format!("/api/jobs/{slow}"), &ann).await.1["scene_id"].is_null());
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_timed_out_job_stops_working() {
    let runner = RunnerConfig { job_timeout_ms: 3000, ..common::runner() };
    let a = common::app_with(QueueLimits::default(), runner).await;
    let _workers = common::start_workers(&a.state, 1);
    let t = a.user("ann").await;
    let (_, v) = a.post("/api/jobs", &t, json!({"prompt": SLOW})).await;
    let id = v["job_id"].as_str().unwrap().to_string();
    let job = a.wait_job(&id, &t).await;
    assert_eq!(job["state"], "failed");
    assert!(job["error"].as_str().unwrap().contains("timed out"), "{job}");
    let pipelines = &a.state.metrics.pipelines;
    let stopped =
        within(Duration::from_secs(8), "the timed-out pipeline stops", async || pipelines.load(Ordering::SeqCst) == 0)
            .await;
    eprintln!("the timed-out pipeline stopped {stopped:?} after the job failed");
}
