//! A full disk, over a real socket: the data directory on a small tmpfs is filled; while
//! it is full, writes are refused (503 with Retry-After, never a 2xx for what was not
//! stored) and /healthz says the store cannot write; once space returns, writes work again
//! within seconds (no lasting "database is locked"), and after a restart the database holds
//! exactly what was acknowledged.
//!
//! Mounting a tmpfs needs root; elsewhere the test says it was skipped.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use common::http;
use serde_json::json;
use sw_server::{AppState, HttpOptions};
use sw_store::QueueLimits;

/// A tmpfs of `mb` MiB at a new directory, unmounted when dropped.
struct Tmpfs {
    dir: tempfile::TempDir,
}

impl Tmpfs {
    fn mount(mb: u32) -> Option<Self> {
        let dir = tempfile::tempdir().ok()?;
        let ok = std::process::Command::new("mount")
            .args(["-t", "tmpfs", "-o", &format!("size={mb}m"), "tmpfs"])
            .arg(dir.path())
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success());
        ok.then_some(Self { dir })
    }

    fn path(&self) -> &Path {
        self.dir.path()
    }
}

impl Drop for Tmpfs {
    fn drop(&mut self) {
        let _ = std::process::Command::new("umount").arg(self.dir.path()).status();
    }
}

/// Fills the file system holding `dir` until a write fails.
fn fill(dir: &Path) -> PathBuf {
    use std::io::Write;
    let path = dir.join("filler");
    let mut f = std::fs::File::create(&path).unwrap();
    let block = vec![7u8; 64 << 10];
    while f.write_all(&block).is_ok() {}
    // The last bytes too, a small block at a time.
    while f.write_all(&block[..512]).is_ok() {}
    let _ = f.flush();
    path
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn writes_recover_when_the_disk_has_room_again() {
    let Some(fs) = Tmpfs::mount(24) else {
        eprintln!("skipped: mounting a tmpfs needs root");
        return;
    };
    let data = fs.path().join("data");
    let (store, blobs) = sw_server::open_data(&data, None).await.unwrap();
    let runner = sw_server::RunnerConfig { work_dir: Some(data.join("work")), ..common::runner() };
    let state = AppState::new(store, blobs, QueueLimits::default(), runner, 3600).await.unwrap();
    let a = common::App { dir: tempfile::tempdir().unwrap(), router: sw_server::router(state.clone()), state };
    let (addr, stop, served) = common::serve_on_socket(&a, HttpOptions::default()).await;

    let creds = json!({"username": "ann", "password": "correct horse battery"});
    assert_eq!(http(addr, "POST", "/api/auth/register", None, Some(creds.clone())).await.0, 201);
    let token = http(addr, "POST", "/api/auth/login", None, Some(creds)).await.2["token"].as_str().unwrap().to_string();
    assert_eq!(http(addr, "GET", "/healthz", None, None).await.0, 200);

    // Full.
    let filler = fill(fs.path());
    let mut acknowledged: Vec<String> = Vec::new();
    let mut refused = 0;
    for i in 0..12 {
        let (s, h, v) =
            http(addr, "POST", "/api/auth/keys", Some(&token), Some(json!({"name": format!("full {i}")}))).await;
        match s {
            201 => acknowledged.push(v["id"].as_str().unwrap().to_string()),
            503 => {
                refused += 1;
                assert!(h.contains_key("retry-after"), "{h:?}");
                assert!(v["error"].as_str().unwrap().contains("nothing was stored"), "{v}");
            }
            other => panic!("a write on a full disk answered {other}: {v}"),
        }
    }
    assert!(refused > 0, "the full disk refused no write");
    let (s, h, v) = http(addr, "GET", "/healthz", None, None).await;
    assert_eq!(s, 503, "health while full: {v}");
    assert!(v["problem"].as_str().unwrap().contains("cannot write"), "{v}");
    assert!(h.contains_key("retry-after"));
    // A job is not accepted either (it could not be stored).
    let (s, _, v) = http(addr, "POST", "/api/jobs", Some(&token), Some(json!({"prompt": "a lab with a table"}))).await;
    assert!(s == 503 || s == 202, "{s}: {v}");
    let job_acknowledged = (s == 202).then(|| v["job_id"].as_str().unwrap().to_string());

    // Room again: writes work within seconds, health is ok.
    std::fs::remove_file(&filler).unwrap();
    let t0 = Instant::now();
    let key = loop {
        let (s, _, v) = http(addr, "POST", "/api/auth/keys", Some(&token), Some(json!({"name": "after"}))).await;
        if s == 201 {
            break v["id"].as_str().unwrap().to_string();
        }
        assert!(
            t0.elapsed() < Duration::from_secs(10),
            "writes still fail {:?} after space returned: {s} {v}",
            t0.elapsed()
        );
        tokio::time::sleep(Duration::from_millis(200)).await;
    };
    acknowledged.push(key);
    let (s, _, v) = http(addr, "GET", "/healthz", None, None).await;
    if s != 200 {
        let probes: Vec<String> = futures_util::future::join_all((0..20).map(|_| a.state.store.probe_write()))
            .await
            .into_iter()
            .map(|r| format!("{r:?}"))
            .collect();
        panic!("health after space returned: {v}; 20 write probes: {probes:?}");
    }
    let (s, _, v) = http(addr, "POST", "/api/jobs", Some(&token), Some(json!({"prompt": "a lab with a table"}))).await;
    assert_eq!(s, 202, "{v}");
    let job_after = v["job_id"].as_str().unwrap().to_string();

    // Restart: exactly what was acknowledged is there.
    let _ = stop.send(());
    let _ = served.await;
    let user = a.state.store.user_by_name("ann").await.unwrap().unwrap();
    a.state.store.pool().close().await;
    drop(a);
    let reopened = sw_store::Store::open_sqlite(&data.join("scenewright.db")).await.unwrap();
    let mut stored: Vec<String> = reopened.api_keys_of(&user.id).await.unwrap().into_iter().map(|k| k.0).collect();
    stored.sort();
    acknowledged.sort();
    assert_eq!(stored, acknowledged, "stored keys are exactly the acknowledged ones");
    assert!(reopened.job(&job_after).await.unwrap().is_some());
    if let Some(j) = job_acknowledged {
        assert!(reopened.job(&j).await.unwrap().is_some(), "an acknowledged job was lost");
    }
    reopened.pool().close().await;
}
