//! The service as processes (the real `scenewright` binary): kill -9 of the server, and of
//! a worker process, in the middle of jobs loses no job, completes none twice and leaves no
//! scratch behind; JSON logs carry the job id on every line about a job.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{BufRead, BufReader};
use std::net::SocketAddr;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

mod common;

use common::{BIN, Proc, http};

/// A `scenewright serve`, and the address it printed.
fn serve(data: &Path, workers: usize) -> (Proc, SocketAddr) {
    serve_on(data, None, workers)
}

fn serve_on(data: &Path, database: Option<&str>, workers: usize) -> (Proc, SocketAddr) {
    let workers = workers.to_string();
    let mut args = vec!["--lease-ms", "1500", "--workers", &workers];
    if let Some(d) = database {
        args.extend(["--database", d]);
    }
    common::serve(data, &args)
}

fn worker(data: &Path, workers: usize) -> Proc {
    worker_on(data, None, workers)
}

fn worker_on(data: &Path, database: Option<&str>, workers: usize) -> Proc {
    Proc(
        Command::new(BIN)
            .args(["worker", "--lease-ms", "1500", "--workers", &workers.to_string(), "--data"])
            .arg(data)
            .args(database.map(|d| vec!["--database", d]).unwrap_or_default())
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    )
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

/// Waits until a job runs; fails (never hangs) when every job ended first or after 5 minutes.
fn wait_until_one_runs(addr: SocketAddr, token: &str) {
    let t0 = Instant::now();
    loop {
        let js = jobs(addr, token);
        if js.iter().any(|j| j["state"] == "running") {
            return;
        }
        assert!(!js.iter().all(terminal), "every job ended before one was caught running");
        assert!(t0.elapsed() < Duration::from_secs(300), "no job ran within 5 minutes");
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn terminal(job: &Value) -> bool {
    ["succeeded", "failed", "cancelled"].contains(&job["state"].as_str().unwrap_or(""))
}

fn wait_all_terminal(addr: SocketAddr, token: &str) -> Vec<Value> {
    let t0 = Instant::now();
    loop {
        let js = jobs(addr, token);
        if js.iter().all(terminal) {
            return js;
        }
        assert!(t0.elapsed() < Duration::from_secs(600), "jobs still not ended after 10 minutes: {js:?}");
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Jobs the database says were running (read straight from the file, as the crash left it).
fn open(data: &Path, database: Option<&str>) -> impl Future<Output = sw_store::Store> {
    let url = database.map_or_else(|| format!("sqlite://{}", data.join("scenewright.db").display()), str::to_string);
    async move { sw_store::Store::open(&url).await.unwrap() }
}

fn running_in_db(data: &Path) -> Vec<String> {
    running_in(data, None)
}

fn running_in(data: &Path, database: Option<&str>) -> Vec<String> {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    rt.block_on(async {
        let store = open(data, database).await;
        let all = store.all_jobs().await.unwrap();
        all.into_iter().filter(|j| j.state == sw_store::JobState::Running).map(|j| j.id).collect()
    })
}

fn check_db(data: &Path, ids: &[String], rerun: &[String]) {
    check(data, None, ids, rerun)
}

fn check(data: &Path, database: Option<&str>, ids: &[String], rerun: &[String]) {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    rt.block_on(async {
        let store = open(data, database).await;
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
        let pid = server.id();
        kill9(&mut server);
        assert!(scratch_owners(&data).contains(&pid), "the killed server left no scratch to clean");
        rerun = running_in_db(&data);
        (server, addr) = serve(&data, 2);
    }
    let done = wait_all_terminal(addr, &token);
    assert_eq!(done.len(), ids.len());
    // Only the live server's scratch is left, and its jobs' scratch went with them.
    assert_only_scratch_of(&data, &[server.id()]);
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
        let pid = w.id();
        kill9(&mut w);
        assert!(scratch_owners(&data).contains(&pid), "the killed worker left no scratch to clean");
        rerun = running_in_db(&data);
        w = worker(&data, 2);
    }
    let done = wait_all_terminal(addr, &token);
    assert_eq!(done.len(), ids.len());
    // The HTTP-only server has no scratch; the killed workers' is gone.
    assert_only_scratch_of(&data, &[w.id()]);
    kill9(&mut w);
    kill9(&mut server);
    check_db(&data, &ids, &rerun);
}

/// A throwaway PostgreSQL cluster on loopback (the store's tests' one copy of how).
#[path = "../../sw_store/tests/cluster/mod.rs"]
mod cluster;

#[test]
fn killing_a_worker_on_postgresql_loses_nothing() {
    let pg = cluster::Cluster::start();
    let url = pg.url("postgres");
    let db = Some(url.as_str());
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    // HTTP only; two worker processes share the PostgreSQL queue; one is killed mid-job.
    let (mut server, addr) = serve_on(&data, db, 0);
    let token = login(addr);
    let ids = submit(addr, &token, 8);
    // The worker to kill starts first and is killed once it holds a job; the steady one
    // starts after the first kill, so it cannot take every job before a kill lands.
    let mut w = worker_on(&data, db, 2);
    let mut steady = None;
    let mut rerun = Vec::new();
    let t0 = Instant::now();
    while rerun.is_empty() {
        let pid = w.id();
        while held_by(&data, db, pid).is_empty() {
            assert!(!jobs(addr, &token).iter().all(terminal), "every job ended before the worker held one");
            assert!(t0.elapsed() < Duration::from_secs(300), "the worker held no job within 5 minutes");
            std::thread::sleep(Duration::from_millis(20));
        }
        kill9(&mut w);
        // The jobs the killed process held (runner names start with its process id).
        rerun = held_by(&data, db, pid);
        w = worker_on(&data, db, 2);
        steady.get_or_insert_with(|| worker_on(&data, db, 1));
    }
    let mut steady = steady.unwrap();
    let done = wait_all_terminal(addr, &token);
    assert_eq!(done.len(), ids.len());
    assert_only_scratch_of(&data, &[steady.id(), w.id()]);
    kill9(&mut w);
    kill9(&mut steady);
    kill9(&mut server);
    check(&data, db, &ids, &rerun);
}

fn held_by(data: &Path, database: Option<&str>, pid: u32) -> Vec<String> {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    rt.block_on(async {
        let store = open(data, database).await;
        let all = store.all_jobs().await.unwrap();
        let prefix = format!("{pid}-");
        all.into_iter()
            .filter(|j| j.state == sw_store::JobState::Running)
            .filter(|j| j.worker.as_deref().is_some_and(|w| w.starts_with(&prefix)))
            .map(|j| j.id)
            .collect()
    })
}

/// A `scenewright serve --log-format json` whose stderr lines are collected.
fn serve_json(data: &Path) -> (Proc, SocketAddr, Arc<Mutex<Vec<String>>>) {
    let mut child = Proc(
        Command::new(BIN)
            .args(["serve", "--addr", "127.0.0.1:0", "--workers", "1", "--log-format", "json", "--data"])
            .arg(data)
            .env_remove("SCENEWRIGHT_LOG")
            .env_remove("SCENEWRIGHT_LOG_FORMAT")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap(),
    );
    let lines = Arc::new(Mutex::new(Vec::new()));
    let (tx, rx) = std::sync::mpsc::channel();
    let stderr = child.stderr.take().unwrap();
    let sink = lines.clone();
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines() {
            let line = line.unwrap();
            // The address is the `serving` event's field (no plain line in JSON mode).
            if let Ok(v) = serde_json::from_str::<Value>(&line)
                && v["message"] == "serving"
            {
                let _ = tx.send(v["addr"].as_str().unwrap().parse::<SocketAddr>().unwrap());
            }
            sink.lock().unwrap().push(line);
        }
    });
    let addr = rx.recv_timeout(Duration::from_secs(60)).expect("serve logged no `serving` event with its address");
    (child, addr, lines)
}

/// The span fields of a JSON log line's spans, outermost first.
fn spans(line: &Value) -> Vec<Value> {
    line["spans"].as_array().cloned().unwrap_or_default()
}

#[test]
fn json_logs_are_one_object_per_line_and_carry_the_job_id() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    let (mut server, addr, lines) = serve_json(&data);
    let token = login(addr);
    let ids = submit(addr, &token, 1);
    let id = ids[0].as_str();
    assert_eq!(wait_all_terminal(addr, &token)[0]["state"], "succeeded");
    // The success line is written after the state changes; wait for it to reach the pipe.
    let deadline = Instant::now() + Duration::from_secs(30);
    while !lines.lock().unwrap().iter().any(|l| l.contains("job succeeded")) {
        assert!(Instant::now() < deadline, "no `job succeeded` line: {:?}", lines.lock().unwrap());
        std::thread::sleep(Duration::from_millis(20));
    }
    kill9(&mut server);
    let lines = lines.lock().unwrap().clone();
    let records: Vec<Value> = lines
        .iter()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not a JSON line ({e}): {l}")))
        .collect();
    for r in &records {
        assert!(r.is_object() && r["level"].is_string() && r["message"].is_string(), "{r}");
    }
    // Lines logged in the job's span carry its id there; the queueing line names it itself.
    let in_job = |r: &Value| spans(r).iter().any(|s| s["name"] == "job" && s["job"] == id);
    let of_job: Vec<&Value> = records.iter().filter(|r| in_job(r) || r["job"] == id).collect();
    let messages: Vec<&str> = of_job.iter().map(|r| r["message"].as_str().unwrap()).collect();
    for m in ["job queued", "job started", "job succeeded"] {
        assert!(messages.contains(&m), "no {m:?} line for the job in {messages:?}");
    }
    // The stages are logged on the pipeline's own thread: the job's span is entered there too.
    for stage in ["plan", "forge", "layout", "bridge", "verify"] {
        let line = records.iter().find(|r| r["message"] == "stage finished" && r["stage"] == stage);
        let line = line.unwrap_or_else(|| panic!("no `stage finished` line for {stage}"));
        assert!(in_job(line), "the {stage} line does not carry the job id: {line}");
        assert!(line["ms"].as_f64().is_some(), "{line}");
    }
    // Every line in a job span is this job's (one job ran) and names its runner's attempt.
    for r in records.iter().filter(|r| spans(r).iter().any(|s| s["name"] == "job")) {
        assert!(in_job(r), "a job line without this job's id: {r}");
        assert_eq!(spans(r)[0]["attempt"], 1, "{r}");
    }
}

#[test]
fn the_log_format_also_comes_from_the_environment_and_a_bad_one_is_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    let out = Command::new(BIN)
        .args(["worker", "--workers", "1", "--data"])
        .arg(&data)
        .env("SCENEWRIGHT_LOG_FORMAT", "yaml")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("SCENEWRIGHT_LOG_FORMAT is 'yaml'; it may be 'text' or 'json'"), "{err}");
    let out = Command::new(BIN).args(["serve", "--log-format", "yaml"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);

    // A worker started with SCENEWRIGHT_LOG_FORMAT=json logs JSON from its first line.
    let mut w = Proc(
        Command::new(BIN)
            .args(["worker", "--workers", "1", "--data"])
            .arg(&data)
            .env("SCENEWRIGHT_LOG_FORMAT", "json")
            .env_remove("SCENEWRIGHT_LOG")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap(),
    );
    let mut lines = BufReader::new(w.stderr.take().unwrap()).lines();
    let first = lines.next().expect("the worker logged nothing").unwrap();
    kill9(&mut w);
    let v: Value = serde_json::from_str(&first).unwrap_or_else(|e| panic!("not JSON ({e}): {first}"));
    assert_eq!(v["message"], "job runners started", "{v}");
    assert_eq!(v["runners"], 1, "{v}");
}

/// The process ids that own scratch under `DATA/work` (directories named `PID-…`).
fn scratch_owners(data: &Path) -> Vec<u32> {
    let Ok(entries) = std::fs::read_dir(data.join("work")) else { return Vec::new() };
    let mut pids: Vec<u32> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.file_type().unwrap().is_dir())
        .filter_map(|e| e.file_name().to_string_lossy().split('-').next().and_then(|p| p.parse().ok()))
        .collect();
    pids.sort();
    pids
}

/// `DATA/work` holds exactly the scratch of `live` (a directory and its lock file each),
/// with no job's scratch left inside once their jobs are done.
fn assert_only_scratch_of(data: &Path, live: &[u32]) {
    let mut want = live.to_vec();
    want.sort();
    assert_eq!(scratch_owners(data), want, "scratch of processes that are gone was left behind");
    let work = data.join("work");
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        let mut names: Vec<String> =
            std::fs::read_dir(&work).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        let dirs: Vec<&String> = names.iter().filter(|n| work.join(n).is_dir()).collect();
        assert_eq!(names.len(), 2 * dirs.len(), "a directory and a lock each: {names:?}");
        for d in &dirs {
            assert!(names.contains(&format!("{d}.lock")), "{d} has no lock file: {names:?}");
        }
        // The last job's scratch is removed just after its completion is recorded.
        let left: Vec<_> = dirs.iter().flat_map(|d| std::fs::read_dir(work.join(d)).unwrap()).collect();
        if left.is_empty() {
            return;
        }
        assert!(Instant::now() < deadline, "finished jobs left scratch: {left:?}");
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// The scratch directory a process claimed, once it has.
fn scratch_of(data: &Path, pid: u32) -> std::path::PathBuf {
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        if let Ok(entries) = std::fs::read_dir(data.join("work")) {
            for e in entries.filter_map(|e| e.ok()) {
                let name = e.file_name().to_string_lossy().into_owned();
                if e.path().is_dir() && name.split('-').next() == Some(pid.to_string().as_str()) {
                    return e.path();
                }
            }
        }
        assert!(Instant::now() < deadline, "process {pid} claimed no scratch");
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn starting_a_process_removes_dead_scratch_but_never_a_live_ones() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    // A live worker in the middle of a job (its scratch holds a half-made package).
    let mut live = worker(&data, 1);
    let live_dir = scratch_of(&data, live.id());
    let partial = live_dir.join("job-0123-abcd/package/scene.xml");
    std::fs::create_dir_all(partial.parent().unwrap()).unwrap();
    std::fs::write(&partial, "<mujoco/>").unwrap();
    // A worker killed in the middle of a job, and scratch of an older version (no lock file).
    let mut dead = worker(&data, 1);
    let dead_dir = scratch_of(&data, dead.id());
    std::fs::create_dir_all(dead_dir.join("job-4567-efgh/package")).unwrap();
    kill9(&mut dead);
    let old = data.join("work/job-89ab-old");
    std::fs::create_dir_all(&old).unwrap();
    std::fs::write(old.join("plan.json"), "{}").unwrap();

    // Another worker starts on the same data directory: it cleans before it claims.
    let mut other = worker(&data, 1);
    let other_dir = scratch_of(&data, other.id());
    assert!(!dead_dir.exists(), "the dead worker's scratch is still there");
    assert!(!data.join("work").join(format!("{}.lock", dead_dir.file_name().unwrap().to_string_lossy())).exists());
    assert!(!old.exists(), "scratch without an owner is still there");
    assert!(partial.exists(), "the live worker's job lost its scratch");
    assert_eq!(std::fs::read_to_string(&partial).unwrap(), "<mujoco/>");
    assert!(other_dir.is_dir());

    // So does a server (HTTP only: it cleans, and claims nothing).
    let mut dead = worker(&data, 1);
    let dead_dir = scratch_of(&data, dead.id());
    kill9(&mut dead);
    let (mut server, _) = serve(&data, 0);
    assert!(!dead_dir.exists(), "the server left a dead worker's scratch");
    assert!(partial.exists() && other_dir.is_dir(), "the server removed a live worker's scratch");
    assert_eq!(scratch_owners(&data), {
        let mut v = vec![live.id(), other.id()];
        v.sort();
        v
    });

    // A worker stopped gracefully removes its own scratch.
    let status = Command::new("kill").args(["-TERM", &other.id().to_string()]).status().unwrap();
    assert!(status.success());
    other.wait().unwrap();
    assert!(!other_dir.exists(), "a worker stopped with SIGTERM left its scratch");
    kill9(&mut server);
    kill9(&mut live);
}
