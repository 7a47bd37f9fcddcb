//! The store's scenarios on a real SQLite file.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod scenarios;

use sw_store::Store;

async fn store() -> (tempfile::TempDir, Store) {
    let dir = tempfile::tempdir().unwrap();
    let s = Store::open_sqlite(&dir.path().join("db.sqlite")).await.unwrap();
    (dir, s)
}

macro_rules! on_sqlite {
    ($($name:ident),* $(,)?) => {$(
        #[tokio::test]
        async fn $name() {
            let (_d, s) = store().await;
            scenarios::$name(&s).await;
        }
    )*};
}

on_sqlite!(
    a_full_queue_refuses_and_stores_nothing,
    concurrent_enqueues_never_overshoot_the_cap,
    concurrent_claimers_never_share_a_job,
    the_per_user_limit_lets_others_go_first,
    a_lost_runner_is_recovered_and_never_completes_twice,
    a_job_that_loses_every_runner_fails_with_a_reason,
    cancelled_jobs_never_run_or_finish,
    jobs_past_their_timeout_fail,
    events_are_ordered_per_job,
    hostile_strings_are_data,
    users_are_served_in_turn,
    one_user_holds_a_share_of_the_queue,
    a_released_job_runs_again_without_losing_an_attempt,
    accounts_names_keys_and_tokens,
);
