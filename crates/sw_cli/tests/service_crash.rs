//! kill -9 of the server, and of a worker process, in the middle of jobs: no job is lost
//! and none completes twice. Spawns the real `scenewright` binary.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

use serde_json::{Value, json};

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");

/// A `scenewright serve`, and the address it printed.
fn serve(data: &Path, workers: usize) -> (Child, SocketAddr) {
    let mut child = Command::new(BIN)
        .args(["serve", "--addr", "127.0.0.1:0", "--lease-ms", "1500", "--workers", &workers.to_string(), "--data"])
        .arg(data)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let addr = loop {
        let line = lines.next().expect("serve exited before listening").unwrap();
        if let Some(a) = line.strip_prefix("listening on http://") {
            break a.trim().parse().unwrap();
        }
    };
    // Keep draining its log so it never blocks on a full pipe.
    std::thread::spawn(move || for _ in lines {});
    (child, addr)
}

fn worker(data: &Path, workers: usize) -> Child {
    Command::new(BIN)
        .args(["worker", "--lease-ms", "1500", "--workers", &workers.to_string(), "--data"])
        .arg(data)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap()
}

fn http(addr: SocketAddr, method: &str, path: &str, token: Option<&str>, body: Option<Value>) -> (u16, Value) {
    let mut s = TcpStream::connect(addr).unwrap();
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
    s.write_all(req.as_bytes()).unwrap();
    let mut buf = String::new();
    s.read_to_string(&mut buf).unwrap();
    let status = buf.split(' ').nth(1).unwrap().parse().unwrap();
    let body = buf.split_once("\r\n\r\n").map(|x| x.1).unwrap_or("");
    (status, serde_json::from_str(body).unwrap_or(Value::Null))
}

fn login(addr: SocketAddr) -> String {
    let creds = json!({"username": "ann", "password": "correct horse battery"});
    let _ = http(addr, "POST", "/api/auth/register", None, Some(creds.clone()));
    let (s, v) = http(addr, "POST", "/api/auth/login", None, Some(creds));
    assert_eq!(s, 200, "{v}");
    v["token"].as_str().unwrap().to_string()
}

fn submit(addr: SocketAddr, token: &str, n: usize) -> Vec<String> {
    (0..n)
        .map(|i| {
            let prompt = format!(
                "a 12 by 10 m warehouse with {} shelves, a conveyor, a table with six boxes on it and a UR5e",
                2 + i % 3
            );
            let (s, v) = http(addr, "POST", "/api/jobs", Some(token), Some(json!({"prompt": prompt, "seed": i})));
            assert_eq!(s, 202, "{v}");
            v["job_id"].as_str().unwrap().to_string()
        })
        .collect()
}

fn jobs(addr: SocketAddr, token: &str) -> Vec<Value> {
    let (s, v) = http(addr, "GET", "/api/jobs", Some(token), None);
    assert_eq!(s, 200, "{v}");
    v["jobs"].as_array().unwrap().clone()
}

fn wait_until_one_runs(addr: SocketAddr, token: &str) {
    while !jobs(addr, token).iter().any(|j| j["state"] == "running") {
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn wait_all_terminal(addr: SocketAddr, token: &str) -> Vec<Value> {
    loop {
        let js = jobs(addr, token);
        if js.iter().all(|j| ["succeeded", "failed", "cancelled"].contains(&j["state"].as_str().unwrap())) {
            return js;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Jobs the database says were running (read straight from the file, as the crash left it).
fn running_in_db(data: &Path) -> Vec<String> {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    rt.block_on(async {
        let store = sw_store::Store::open_sqlite(&data.join("scenewright.db")).await.unwrap();
        let all = store.all_jobs().await.unwrap();
        all.into_iter().filter(|j| j.state == sw_store::JobState::Running).map(|j| j.id).collect()
    })
}

fn check_db(data: &Path, ids: &[String], rerun: &[String]) {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    rt.block_on(async {
        let store = sw_store::Store::open_sqlite(&data.join("scenewright.db")).await.unwrap();
        let all = store.all_jobs().await.unwrap();
        assert_eq!(all.len(), ids.len(), "no job lost, none invented");
        for j in &all {
            assert!(ids.contains(&j.id));
            assert_eq!(j.state, sw_store::JobState::Succeeded, "{}: {:?}", j.id, j.error);
            assert_eq!(j.completions, 1, "{} completed {} times", j.id, j.completions);
            if rerun.contains(&j.id) {
                assert!(j.attempts >= 2, "{} was running at the crash but ran once", j.id);
            }
        }
        assert_eq!(store.count_rows(sw_store::CountedTable::Scenes).await.unwrap(), ids.len() as i64);
    });
}

fn kill9(child: &mut Child) {
    // Child::kill is SIGKILL on Unix: no shutdown code runs.
    child.kill().unwrap();
    child.wait().unwrap();
}

#[test]
fn killing_the_server_mid_job_loses_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    let (mut server, addr) = serve(&data, 2);
    let token = login(addr);
    let ids = submit(addr, &token, 8);
    let mut rerun = Vec::new();
    let mut addr = addr;
    // Kill it while jobs run, until a kill caught at least one job running.
    while rerun.is_empty() {
        wait_until_one_runs(addr, &token);
        kill9(&mut server);
        rerun = running_in_db(&data);
        (server, addr) = serve(&data, 2);
    }
    let done = wait_all_terminal(addr, &token);
    assert_eq!(done.len(), ids.len());
    kill9(&mut server);
    check_db(&data, &ids, &rerun);
}

#[test]
fn killing_a_worker_process_mid_job_loses_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    // HTTP only; the jobs run in a separate worker process.
    let (mut server, addr) = serve(&data, 0);
    let token = login(addr);
    let ids = submit(addr, &token, 8);
    let mut w = worker(&data, 2);
    let mut rerun = Vec::new();
    while rerun.is_empty() {
        wait_until_one_runs(addr, &token);
        kill9(&mut w);
        rerun = running_in_db(&data);
        w = worker(&data, 2);
    }
    let done = wait_all_terminal(addr, &token);
    assert_eq!(done.len(), ids.len());
    kill9(&mut w);
    kill9(&mut server);
    check_db(&data, &ids, &rerun);
}
