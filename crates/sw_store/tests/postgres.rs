//! The store's scenarios on PostgreSQL: a throwaway cluster (see `cluster/mod.rs`: initdb +
//! pg_ctl from Debian's `postgresql` package, which `scripts/setup.sh --tests` installs)
//! started on loopback in a temporary directory.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod cluster;
mod scenarios;

use cluster::Cluster;
use sw_store::{Backend, Store};

/// A fresh database in the cluster.
async fn database(cluster: &Cluster, name: &str) -> Store {
    let s = Store::open(&cluster.database(name)).await.unwrap();
    assert_eq!(s.backend(), Backend::Postgres);
    s
}

macro_rules! on_postgres {
    ($cluster:expr, $($name:ident),* $(,)?) => {$(
        let s = database(&$cluster, stringify!($name)).await;
        scenarios::$name(&s).await;
        s.pool().close().await;
    )*};
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_store_on_postgresql() {
    let cluster = Cluster::start();
    on_postgres!(
        cluster,
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
}
