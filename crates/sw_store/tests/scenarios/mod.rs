//! The store's scenarios, run on SQLite (`queue.rs`) and PostgreSQL (`postgres.rs`): caps,
//! atomic claims under concurrency, per-user limits, leases lost and recovered,
//! cancellation, timeouts, conditional completion, hostile strings.

#![allow(clippy::unwrap_used, clippy::expect_used, dead_code)]

use std::collections::BTreeMap;

use sw_store::{
    CountedTable, JobKind, JobState, NewJob, NewScene, QueueLimits, Role, Store, StoreError, Telemetry, new_id,
};

fn job(user: &str, prompt: &str) -> NewJob {
    NewJob {
        user_id: user.to_string(),
        kind: JobKind::Generate,
        prompt: prompt.to_string(),
        seed: 7,
        options: serde_json::json!({}),
        parent_scene_id: None,
        timeout_ms: 600_000,
        max_attempts: 2,
    }
}

fn scene() -> NewScene {
    NewScene { id: new_id(), status: "passed".into(), report: serde_json::json!({}), files: vec![], edit: None }
}

pub async fn a_full_queue_refuses_and_stores_nothing(s: &Store) {
    let u = s.create_user("ann", "h", None).await.unwrap();
    let limits = QueueLimits { queue_cap: 3, per_user_running: 5 };
    for i in 0..3 {
        s.enqueue(&job(&u.id, &format!("p{i}")), limits).await.unwrap();
    }
    let err = s.enqueue(&job(&u.id, "one too many"), limits).await.unwrap_err();
    assert!(matches!(err, StoreError::QueueFull { cap: 3 }), "{err}");
    assert_eq!(s.count_rows(CountedTable::Jobs).await.unwrap(), 3);
    assert_eq!(s.count_rows(CountedTable::Prompts).await.unwrap(), 3);
    // Running jobs do not count against the cap.
    s.claim("w", 60_000, limits).await.unwrap().unwrap();
    s.enqueue(&job(&u.id, "now there is room"), limits).await.unwrap();
}

/// Many enqueues at once against a small cap, in rounds (the queue emptied by cancelling
/// between them): exactly `cap` are queued each time and every other one is refused as
/// full — no overshoot from two transactions counting the same free places.
pub async fn concurrent_enqueues_never_overshoot_the_cap(s: &Store) {
    let u = s.create_user("ann", "h", None).await.unwrap();
    let limits = QueueLimits { queue_cap: 5, per_user_running: 5 };
    for round in 0..8 {
        let mut tasks = Vec::new();
        for i in 0..48 {
            let (s, user) = (s.clone(), u.id.clone());
            tasks.push(tokio::spawn(async move { s.enqueue(&job(&user, &format!("r{round} j{i}")), limits).await }));
        }
        let (mut queued, mut full) = (Vec::new(), 0);
        for t in tasks {
            match t.await.unwrap() {
                Ok(j) => queued.push(j.id),
                Err(StoreError::QueueFull { cap: 5 }) => full += 1,
                Err(e) => panic!("round {round}: {e}"),
            }
        }
        let waiting = s.all_jobs().await.unwrap().into_iter().filter(|j| j.state == JobState::Queued).count();
        assert_eq!((queued.len(), full, waiting), (5, 43, 5), "round {round}");
        for id in &queued {
            assert_eq!(s.cancel(id, &u.id).await.unwrap(), Some(JobState::Cancelled));
        }
    }
    // A refused job stored nothing: one prompt per queued job.
    assert_eq!(s.count_rows(CountedTable::Jobs).await.unwrap(), 40);
    assert_eq!(s.count_rows(CountedTable::Prompts).await.unwrap(), 40);
}

pub async fn concurrent_claimers_never_share_a_job(s: &Store) {
    let limits = QueueLimits { queue_cap: 1000, per_user_running: 1000 };
    let mut users = Vec::new();
    for i in 0..4 {
        users.push(s.create_user(&format!("u{i}"), "h", None).await.unwrap());
    }
    for i in 0..200 {
        s.enqueue(&job(&users[i % 4].id, &format!("job {i}")), limits).await.unwrap();
    }
    let mut tasks = Vec::new();
    for w in 0..16 {
        let s = s.clone();
        tasks.push(tokio::spawn(async move {
            let mut mine = Vec::new();
            while let Some(c) = s.claim(&format!("w{w}"), 60_000, limits).await.unwrap() {
                assert!(s.complete(&c, &scene(), &Telemetry::default()).await.unwrap());
                mine.push(c.job.id.clone());
            }
            mine
        }));
    }
    let mut seen = BTreeMap::new();
    for t in tasks {
        for id in t.await.unwrap() {
            *seen.entry(id).or_insert(0) += 1;
        }
    }
    assert_eq!(seen.len(), 200);
    assert!(seen.values().all(|&n| n == 1));
    let jobs = s.all_jobs().await.unwrap();
    assert!(jobs.iter().all(|j| j.state == JobState::Succeeded && j.completions == 1 && j.attempts == 1));
    assert_eq!(s.count_rows(CountedTable::Scenes).await.unwrap(), 200);
}

pub async fn the_per_user_limit_lets_others_go_first(s: &Store) {
    let limits = QueueLimits { queue_cap: 100, per_user_running: 1 };
    let a = s.create_user("a", "h", None).await.unwrap();
    let b = s.create_user("b", "h", None).await.unwrap();
    let a1 = s.enqueue(&job(&a.id, "a1"), limits).await.unwrap();
    let a2 = s.enqueue(&job(&a.id, "a2"), limits).await.unwrap();
    let b1 = s.enqueue(&job(&b.id, "b1"), limits).await.unwrap();
    let c1 = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(c1.job.id, a1.id);
    let c2 = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(c2.job.id, b1.id, "a's second job must wait while a1 runs");
    assert!(s.claim("w", 60_000, limits).await.unwrap().is_none());
    assert!(s.complete(&c1, &scene(), &Telemetry::default()).await.unwrap());
    let c3 = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(c3.job.id, a2.id);
}

pub async fn a_lost_runner_is_recovered_and_never_completes_twice(s: &Store) {
    let limits = QueueLimits::default();
    let u = s.create_user("ann", "h", None).await.unwrap();
    let j = s.enqueue(&job(&u.id, "p"), limits).await.unwrap();
    // A runner claims with a lease that has already run out (it "crashed").
    let lost = s.claim("dead", -1, limits).await.unwrap().unwrap();
    let r = s.recover().await.unwrap();
    assert_eq!(r.requeued, vec![j.id.clone()]);
    assert!(!s.heartbeat(&lost, 60_000).await.unwrap(), "the lost runner's claim is gone");
    let again = s.claim("alive", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(again.attempt, 2);
    // The lost runner wakes up and tries to finish: refused, nothing stored.
    assert!(!s.complete(&lost, &scene(), &Telemetry::default()).await.unwrap());
    assert_eq!(s.count_rows(CountedTable::Scenes).await.unwrap(), 0);
    assert!(s.heartbeat(&again, 60_000).await.unwrap());
    assert!(s.complete(&again, &scene(), &Telemetry::default()).await.unwrap());
    assert!(!s.complete(&again, &scene(), &Telemetry::default()).await.unwrap(), "only once");
    let done = s.job(&j.id).await.unwrap().unwrap();
    assert_eq!((done.state, done.completions, done.attempts), (JobState::Succeeded, 1, 2));
}

pub async fn a_job_that_loses_every_runner_fails_with_a_reason(s: &Store) {
    let limits = QueueLimits::default();
    let u = s.create_user("ann", "h", None).await.unwrap();
    let j = s.enqueue(&job(&u.id, "p"), limits).await.unwrap();
    s.claim("w1", -1, limits).await.unwrap().unwrap();
    assert_eq!(s.recover().await.unwrap().requeued.len(), 1);
    s.claim("w2", -1, limits).await.unwrap().unwrap();
    let r = s.recover().await.unwrap();
    assert_eq!(r.failed, vec![j.id.clone()]);
    let f = s.job(&j.id).await.unwrap().unwrap();
    assert_eq!(f.state, JobState::Failed);
    assert!(f.error.unwrap().contains("runner was lost"));
}

pub async fn cancelled_jobs_never_run_or_finish(s: &Store) {
    let limits = QueueLimits::default();
    let u = s.create_user("ann", "h", None).await.unwrap();
    let other = s.create_user("bob", "h", None).await.unwrap();
    let queued = s.enqueue(&job(&u.id, "q"), limits).await.unwrap();
    assert_eq!(s.cancel(&queued.id, &other.id).await.unwrap(), None, "not bob's job");
    assert_eq!(s.cancel(&queued.id, &u.id).await.unwrap(), Some(JobState::Cancelled));
    assert!(s.claim("w", 60_000, limits).await.unwrap().is_none());
    let running = s.enqueue(&job(&u.id, "r"), limits).await.unwrap();
    let c = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(c.job.id, running.id);
    assert_eq!(s.cancel(&running.id, &u.id).await.unwrap(), Some(JobState::Cancelled));
    assert!(!s.heartbeat(&c, 60_000).await.unwrap());
    assert!(!s.complete(&c, &scene(), &Telemetry::default()).await.unwrap());
    assert_eq!(s.job(&running.id).await.unwrap().unwrap().state, JobState::Cancelled);
}

pub async fn jobs_past_their_timeout_fail(s: &Store) {
    let limits = QueueLimits::default();
    let u = s.create_user("ann", "h", None).await.unwrap();
    let mut j = job(&u.id, "slow");
    j.timeout_ms = -1;
    let j = s.enqueue(&j, limits).await.unwrap();
    let c = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    let r = s.recover().await.unwrap();
    assert_eq!(r.failed, vec![j.id.clone()]);
    assert!(!s.complete(&c, &scene(), &Telemetry::default()).await.unwrap());
    assert!(s.job(&j.id).await.unwrap().unwrap().error.unwrap().starts_with("timed out"));
}

pub async fn events_are_ordered_per_job(s: &Store) {
    let u = s.create_user("ann", "h", None).await.unwrap();
    let a = s.enqueue(&job(&u.id, "a"), QueueLimits::default()).await.unwrap();
    let b = s.enqueue(&job(&u.id, "b"), QueueLimits::default()).await.unwrap();
    // Every stream begins with `queued`, written with the job.
    let first = s.events_after(&a.id, 0).await.unwrap();
    assert_eq!((first.len(), first[0].0, &first[0].1["event"]), (1, 1, &serde_json::json!("queued")));
    for i in 0..5 {
        assert_eq!(s.append_event(&a.id, &serde_json::json!({"i": i})).await.unwrap(), i + 2);
    }
    s.append_event(&b.id, &serde_json::json!({"other": true})).await.unwrap();
    let ev = s.events_after(&a.id, 3).await.unwrap();
    assert_eq!(ev.iter().map(|e| e.0).collect::<Vec<_>>(), vec![4, 5, 6]);
    assert_eq!(ev[0].1["i"], 2);
}

pub async fn hostile_strings_are_data(s: &Store) {
    let name = "x'; DROP TABLE users; --";
    let u = s.create_user(name, "h", None).await.unwrap();
    assert_eq!(u.role, Role::Admin, "the first user is the admin");
    assert_eq!(s.user_by_name(name).await.unwrap().unwrap().id, u.id);
    assert!(s.user_by_name("' OR '1'='1").await.unwrap().is_none());
    assert!(matches!(s.create_user(name, "h", None).await, Err(StoreError::Conflict(_))));
    let second = s.create_user("bob", "h", None).await.unwrap();
    assert_eq!(second.role, Role::User);
    s.create_asset(&u.id, "100% _odd_ shelf", None, &serde_json::json!({})).await.unwrap();
    assert_eq!(s.assets_of(&u.id, "%").await.unwrap().len(), 1);
    assert_eq!(s.assets_of(&u.id, "_o").await.unwrap().len(), 1);
    assert_eq!(s.assets_of(&u.id, "zz%").await.unwrap().len(), 0);
    assert_eq!(s.assets_of(&second.id, "").await.unwrap().len(), 0);
    assert_eq!(s.count_rows(CountedTable::Users).await.unwrap(), 2);
}
