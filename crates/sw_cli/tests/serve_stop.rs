//! `scenewright serve` stops on SIGTERM while a long job runs (its pipeline stops at its
//! next check; the job goes back to the queue, its attempt not counted) and while a client
//! holds a connection open without finishing its request; the next server runs the job.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::Write;
use std::net::{SocketAddr, TcpStream};
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use serde_json::json;

mod common;

use common::{Proc, http};

fn serve(data: &Path) -> (Proc, SocketAddr) {
    common::serve(data, &["--workers", "1"])
}

fn sigterm(p: &Proc) {
    let ok = Command::new("kill").args(["-TERM", &p.0.id().to_string()]).status().unwrap();
    assert!(ok.success());
}

/// Waits for the process to end, at most `limit`; how long it took.
fn exits_within(p: &mut Proc, limit: Duration) -> Duration {
    let t0 = Instant::now();
    loop {
        if let Some(status) = p.0.try_wait().unwrap() {
            assert!(status.success(), "serve exited with {status}");
            return t0.elapsed();
        }
        assert!(t0.elapsed() < limit, "serve still running {limit:?} after SIGTERM");
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn sigterm_stops_the_server_while_a_long_job_runs_and_the_job_runs_again() {
    let data = tempfile::tempdir().unwrap();
    let (mut server, addr) = serve(data.path());
    let creds = json!({"username": "ann", "password": "correct horse battery"});
    assert_eq!(http(addr, "POST", "/api/auth/register", None, Some(creds.clone())).0, 201);
    let token =
        http(addr, "POST", "/api/auth/login", None, Some(creds.clone())).1["token"].as_str().unwrap().to_string();
    let (s, v) = http(addr, "POST", "/api/jobs", Some(&token), Some(json!({"prompt": "a warehouse with 2000 boxes"})));
    assert_eq!(s, 202, "{v}");
    let id = v["job_id"].as_str().unwrap().to_string();
    let t0 = Instant::now();
    while http(addr, "GET", &format!("/api/jobs/{id}"), Some(&token), None).1["stage"] != "layout" {
        assert!(t0.elapsed() < Duration::from_secs(60), "the job never reached its layout");
        std::thread::sleep(Duration::from_millis(100));
    }
    // A client that connected and never finished its request.
    let mut idle = TcpStream::connect(addr).unwrap();
    idle.write_all(b"GET /api/me HTTP/1.1\r\nHost: x\r\n").unwrap();

    sigterm(&server);
    let took = exits_within(&mut server, Duration::from_secs(15));
    eprintln!("serve stopped {took:?} after SIGTERM with a layout of 2000 boxes running");

    // The job went back to the queue (its attempt not counted), and runs in the next server.
    let store = tokio::runtime::Runtime::new().unwrap().block_on(async {
        let s = sw_store::Store::open_sqlite(&data.path().join("scenewright.db")).await.unwrap();
        let j = s.job(&id).await.unwrap().unwrap();
        s.pool().close().await;
        j
    });
    assert_eq!((store.state, store.attempts), (sw_store::JobState::Queued, 0), "{store:?}");
    let events = tokio::runtime::Runtime::new().unwrap().block_on(async {
        let s = sw_store::Store::open_sqlite(&data.path().join("scenewright.db")).await.unwrap();
        let e = s.events_after(&id, 0).await.unwrap();
        s.pool().close().await;
        e
    });
    assert!(events.iter().any(|(_, e)| e["event"] == "requeued"), "{events:?}");
    let (_server, addr) = serve(data.path());
    let token = http(addr, "POST", "/api/auth/login", None, Some(creds)).1["token"].as_str().unwrap().to_string();
    let t0 = Instant::now();
    while http(addr, "GET", &format!("/api/jobs/{id}"), Some(&token), None).1["state"] != "running" {
        assert!(t0.elapsed() < Duration::from_secs(30), "the job did not run again");
        std::thread::sleep(Duration::from_millis(100));
    }
}
