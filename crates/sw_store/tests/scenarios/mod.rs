//! The store's scenarios, run on SQLite (`queue.rs`) and PostgreSQL (`postgres.rs`): caps,
//! atomic claims under concurrency, per-user limits, leases lost and recovered,
//! cancellation, timeouts, conditional completion, hostile strings.

#![allow(clippy::unwrap_used, clippy::expect_used, dead_code)]

use std::collections::BTreeMap;

use sw_store::{
    CountedTable, JobKind, JobState, NewJob, NewScene, QueueLimits, Role, Store, StoreError, Telemetry, new_id, now_ms,
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
    NewScene {
        id: new_id(),
        status: "passed".into(),
        report: serde_json::json!({}),
        files: vec![],
        hashes: vec![],
        edit: None,
    }
}

pub async fn a_full_queue_refuses_and_stores_nothing(s: &Store) {
    let u = s.create_user("ann", "h", None).await.unwrap();
    let limits = QueueLimits { queue_cap: 3, per_user_running: 5, per_user_queued: 3 };
    for i in 0..3 {
        s.enqueue(&job(&u.id, &format!("p{i}")), limits).await.unwrap();
    }
    let err = s.enqueue(&job(&u.id, "one too many"), limits).await.unwrap_err();
    assert!(matches!(err, StoreError::QueueFull { cap: 3, .. }), "{err}");
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
    let limits = QueueLimits { queue_cap: 5, per_user_running: 5, per_user_queued: 5 };
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
                Err(StoreError::QueueFull { cap: 5, .. }) => full += 1,
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
    let limits = QueueLimits { queue_cap: 1000, per_user_running: 1000, per_user_queued: 1000 };
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
    let limits = QueueLimits { queue_cap: 100, per_user_running: 1, per_user_queued: 100 };
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

/// Users are served in turn: one user's long backlog does not hold another's single job
/// behind it; among equals, arrival order.
pub async fn users_are_served_in_turn(s: &Store) {
    let limits = QueueLimits { queue_cap: 100, per_user_running: 5, per_user_queued: 100 };
    let a = s.create_user("a", "h", None).await.unwrap();
    let b = s.create_user("b", "h", None).await.unwrap();
    let mut mine = Vec::new();
    for i in 0..6 {
        mine.push(s.enqueue(&job(&a.id, &format!("a{i}")), limits).await.unwrap().id);
    }
    let theirs = s.enqueue(&job(&b.id, "b0"), limits).await.unwrap().id;
    let first = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(first.job.id, mine[0]);
    let second = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(second.job.id, theirs, "b's only job goes before a's second");
    let third = s.claim("w", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(third.job.id, mine[1]);
}

/// One user may hold only a share of the queue; another still gets in; a batch that does
/// not fit is refused whole.
pub async fn one_user_holds_a_share_of_the_queue(s: &Store) {
    let limits = QueueLimits { queue_cap: 10, per_user_running: 5, per_user_queued: 3 };
    let a = s.create_user("a", "h", None).await.unwrap();
    let b = s.create_user("b", "h", None).await.unwrap();
    for i in 0..3 {
        s.enqueue(&job(&a.id, &format!("a{i}")), limits).await.unwrap();
    }
    let e = s.enqueue(&job(&a.id, "a3"), limits).await.unwrap_err();
    assert!(matches!(e, StoreError::QueueFull { cap: 3, per_user: true }), "{e}");
    let batch: Vec<NewJob> = (0..4).map(|i| job(&b.id, &format!("b{i}"))).collect();
    assert!(matches!(s.enqueue_all(&batch, limits).await, Err(StoreError::QueueFull { per_user: true, .. })));
    assert_eq!(s.count_rows(CountedTable::Jobs).await.unwrap(), 3, "nothing of the refused batch");
    assert_eq!(s.enqueue_all(&batch[..3], limits).await.unwrap().len(), 3);
}

/// A job given back by a stopping runner runs again, its attempt not counted, and the
/// stopping runner cannot complete it any more.
pub async fn a_released_job_runs_again_without_losing_an_attempt(s: &Store) {
    let limits = QueueLimits::default();
    let u = s.create_user("ann", "h", None).await.unwrap();
    let j = s.enqueue(&job(&u.id, "p"), limits).await.unwrap();
    let c = s.claim("stopping", 60_000, limits).await.unwrap().unwrap();
    assert!(s.release(&c, "the server stopped").await.unwrap());
    let back = s.job(&j.id).await.unwrap().unwrap();
    assert_eq!((back.state, back.attempts), (JobState::Queued, 0));
    assert!(!s.complete(&c, &scene(), &Telemetry::default()).await.unwrap(), "the released claim is void");
    assert!(!s.release(&c, "again").await.unwrap());
    let again = s.claim("next", 60_000, limits).await.unwrap().unwrap();
    assert_eq!(again.attempt, 1);
    let events = s.events_after(&j.id, 0).await.unwrap();
    assert!(events.iter().any(|(_, e)| e["event"] == "requeued" && e["reason"] == "the server stopped"));
}

/// Names are one whatever their case; the service account is never a login account;
/// keys and tokens can be revoked.
pub async fn accounts_names_keys_and_tokens(s: &Store) {
    let alice = s.create_user("Alice", "h", None).await.unwrap();
    for name in ["alice", "ALICE"] {
        assert!(matches!(s.create_user(name, "h", None).await, Err(StoreError::Conflict(_))), "{name}");
        assert_eq!(s.user_by_name(name).await.unwrap().unwrap().id, alice.id);
    }
    let svc = s.service_account("scenewright-dataset").await.unwrap();
    assert_eq!(s.service_account("scenewright-dataset").await.unwrap().id, svc.id, "the same account again");
    // A login account holding a service name (registered before names were reserved).
    s.create_user("scenewright-x", "$argon2id$v=19$m=1,t=1,p=1$c2FsdA$aGFzaA", None).await.unwrap();
    assert!(matches!(s.service_account("scenewright-x").await, Err(StoreError::Conflict(_))));
    let key = s.create_api_key(&alice.id, "k", "hash-1").await.unwrap();
    assert!(!s.delete_api_key(&svc.id, &key).await.unwrap(), "not another user's to delete");
    assert!(s.user_by_api_key("hash-1").await.unwrap().is_some());
    assert!(s.delete_api_key(&alice.id, &key).await.unwrap());
    assert!(s.user_by_api_key("hash-1").await.unwrap().is_none());
    assert!(!s.token_revoked("jti-1").await.unwrap());
    s.revoke_token("jti-1", now_ms() + 60_000).await.unwrap();
    s.revoke_token("jti-1", now_ms() + 60_000).await.unwrap();
    assert!(s.token_revoked("jti-1").await.unwrap());
    // Expired revocations are forgotten when the next is written.
    s.revoke_token("old", now_ms() - 1).await.unwrap();
    s.revoke_token("jti-2", now_ms() + 60_000).await.unwrap();
    assert!(!s.token_revoked("old").await.unwrap());
    s.probe_write().await.unwrap();
}
