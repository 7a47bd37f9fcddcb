//! `scenewright dataset --database postgres://…` with packages in S3 (moto): two worker
//! processes make the scenes, the leader assembles the manifest from the store. The leader
//! and a worker are killed -9 in the middle; the dataset still ends with every slot once,
//! distinct and verified, and no job is completed twice.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeSet;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");
const PROMPT: &str = "a kitchen with a table, two chairs and two mugs on the table";

#[path = "../../sw_store/tests/cluster/mod.rs"]
mod cluster;

struct Proc(Child);

impl Drop for Proc {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

struct Env {
    url: String,
    s3: String,
}

impl Env {
    fn cmd(&self) -> Command {
        let mut c = Command::new(BIN);
        c.env("SCENEWRIGHT_S3_ENDPOINT", &self.s3)
            .env("SCENEWRIGHT_S3_BUCKET", "datasets")
            .env("AWS_ACCESS_KEY_ID", "testing")
            .env("AWS_SECRET_ACCESS_KEY", "testing")
            .stdin(Stdio::null());
        c
    }

    fn worker(&self, data: &Path) -> Proc {
        let mut c = self.cmd();
        c.args([
            "worker",
            "--workers",
            "2",
            "--per-user",
            "8",
            "--lease-ms",
            "1500",
            "--database",
            &self.url,
            "--data",
        ])
        .arg(data)
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(data.with_extension("log")).unwrap());
        Proc(c.spawn().unwrap())
    }

    fn leader(&self, out: &Path, data: &Path, count: u32) -> Command {
        let mut c = self.cmd();
        c.args([
            "dataset",
            "--prompt",
            PROMPT,
            "--count",
            &count.to_string(),
            "--database",
            &self.url,
            "--json",
            "--out",
        ])
        .arg(out)
        .arg("--data")
        .arg(data);
        c
    }
}

fn lines(out: &Path) -> usize {
    std::fs::read_to_string(out.join("manifest.jsonl")).map_or(0, |t| t.matches('\n').count())
}

#[test]
fn a_dataset_on_the_queue_survives_killing_its_leader_and_a_worker() {
    let pg = cluster::Cluster::start();
    let moto = sw_s3::moto::MotoServer::start().unwrap();
    let env = Env { url: pg.url("postgres"), s3: format!("http://{}", moto.addr()) };
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("ds");
    let leader_data = tmp.path().join("leader");
    let count = 16;
    let steady = env.worker(&tmp.path().join("w1"));
    let mut flaky = env.worker(&tmp.path().join("w2"));

    // The leader is killed once a few scenes are listed; a worker is killed meanwhile.
    let log = std::fs::File::create(tmp.path().join("leader.log")).unwrap();
    let mut leader = Proc(env.leader(&out, &leader_data, count).stdout(Stdio::null()).stderr(log).spawn().unwrap());
    let t0 = Instant::now();
    while lines(&out) < 4 {
        if t0.elapsed() > Duration::from_secs(300) || leader.0.try_wait().unwrap().is_some() {
            let read = |n: &str| std::fs::read_to_string(tmp.path().join(n)).unwrap_or_default();
            panic!("no scenes: leader: {}\nworker: {}", read("leader.log"), read("w1.log"));
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    flaky.0.kill().unwrap();
    leader.0.kill().unwrap();
    let _ = leader.0.wait();
    let listed_before: Vec<Value> = std::fs::read_to_string(out.join("manifest.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let _flaky = env.worker(&tmp.path().join("w3"));

    // Started again, the leader finishes: the queue went on while it was away.
    let o = env.leader(&out, &leader_data, count).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(summary["scenes_listed"], count);
    let text = std::fs::read_to_string(out.join("manifest.jsonl")).unwrap();
    let entries: Vec<Value> = text.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(entries.len(), count as usize);
    for e in &listed_before {
        assert!(entries.contains(e), "{} changed or was lost", e["id"]);
    }
    let ids: BTreeSet<&str> = entries.iter().map(|e| e["id"].as_str().unwrap()).collect();
    let want: BTreeSet<String> = (0..count).map(|k| format!("0000-{k:06}")).collect();
    assert_eq!(ids, want.iter().map(String::as_str).collect());
    let fps: BTreeSet<&str> = entries.iter().map(|e| e["fingerprint"].as_str().unwrap()).collect();
    assert_eq!(fps.len(), count as usize, "duplicate scenes");
    for e in &entries {
        let v = sw_pipeline::validate_dir(&out.join(e["dir"].as_str().unwrap())).unwrap();
        assert!(v.passed, "{}: {:?}", e["id"], v.failures);
        // The slot's seeds are its own: seed ≡ slot (mod count).
        let k: u64 = e["id"].as_str().unwrap()[5..].parse().unwrap();
        assert_eq!(e["seed"].as_u64().unwrap() % u64::from(count), k, "{}", e["id"]);
    }

    // The store's side: one job per slot completed exactly once, its package in S3.
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    rt.block_on(async {
        let store = sw_store::Store::open(&env.url).await.unwrap();
        let jobs = store.all_jobs().await.unwrap();
        let mut done = 0;
        for j in &jobs {
            assert!(j.completions <= 1, "job {} completed {} times", j.id, j.completions);
            done += usize::from(j.state == sw_store::JobState::Succeeded);
        }
        assert!(done >= count as usize);
    });
    let bucket = moto.bucket("datasets").unwrap();
    let keys = bucket.list("scenes/").unwrap();
    assert!(keys.iter().filter(|k| k.ends_with("/scene.xml")).count() >= count as usize);
    drop(steady);
}
