//! The store's scenarios on PostgreSQL: a throwaway cluster (initdb + pg_ctl from Debian's
//! `postgresql` package, which `scripts/setup.sh --tests` installs) started on loopback in a
//! temporary directory, as the `postgres` user when the tests run as root.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod scenarios;

use std::net::TcpListener;
use std::path::PathBuf;
use std::process::Command;

use sw_store::{Backend, Store};

/// A PostgreSQL cluster that lives as long as this value.
struct Cluster {
    dir: tempfile::TempDir,
    bin: PathBuf,
    port: u16,
    as_postgres: bool,
}

fn bin_dir() -> PathBuf {
    let mut versions: Vec<PathBuf> = std::fs::read_dir("/usr/lib/postgresql")
        .expect("PostgreSQL is not installed: run scripts/setup.sh --tests")
        .filter_map(|e| e.ok().map(|e| e.path().join("bin")))
        .filter(|p| p.join("initdb").exists())
        .collect();
    versions.sort();
    versions.pop().expect("no initdb under /usr/lib/postgresql: run scripts/setup.sh --tests")
}

fn is_root() -> bool {
    Command::new("id").arg("-u").output().is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
}

impl Cluster {
    fn run(&self, tool: &str, args: &[&str]) {
        let exe = self.bin.join(tool);
        let mut cmd = if self.as_postgres {
            let mut c = Command::new("runuser");
            c.args(["-u", "postgres", "--"]).arg(&exe);
            c
        } else {
            Command::new(&exe)
        };
        let out = cmd.args(args).output().unwrap();
        assert!(
            out.status.success(),
            "{tool} failed: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }

    fn start() -> Self {
        let dir = tempfile::Builder::new().prefix("sw-pg-").tempdir().unwrap();
        let as_postgres = is_root();
        if as_postgres {
            let ok = Command::new("chown").args(["-R", "postgres:postgres"]).arg(dir.path()).status().unwrap();
            assert!(ok.success());
        }
        let port = TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
        let c = Cluster { dir, bin: bin_dir(), port, as_postgres };
        let data = c.path("data");
        c.run("initdb", &["-D", &data, "-A", "trust", "-U", "sw", "-E", "UTF8", "--no-sync"]);
        let opts = format!("-h 127.0.0.1 -p {port} -k {} -c fsync=off -c max_connections=200", c.dir.path().display());
        c.run("pg_ctl", &["-D", &data, "-l", &c.path("log"), "-w", "-o", &opts, "start"]);
        c
    }

    fn path(&self, name: &str) -> String {
        self.dir.path().join(name).display().to_string()
    }

    /// A fresh database in the cluster.
    async fn database(&self, name: &str) -> Store {
        sqlx::any::install_default_drivers();
        let admin = sqlx::AnyPool::connect(&format!("postgres://sw@127.0.0.1:{}/postgres", self.port)).await.unwrap();
        assert!(name.chars().all(|c| c.is_ascii_lowercase() || c == '_'));
        sqlx::query(sqlx::AssertSqlSafe(format!("CREATE DATABASE {name}"))).execute(&admin).await.unwrap();
        admin.close().await;
        let s = Store::open(&format!("postgres://sw@127.0.0.1:{}/{name}", self.port)).await.unwrap();
        assert_eq!(s.backend(), Backend::Postgres);
        s
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let data = self.path("data");
        let exe = self.bin.join("pg_ctl");
        let mut cmd = if self.as_postgres {
            let mut c = Command::new("runuser");
            c.args(["-u", "postgres", "--"]).arg(&exe);
            c
        } else {
            Command::new(&exe)
        };
        let _ = cmd.args(["-D", &data, "-m", "immediate", "stop"]).output();
    }
}

macro_rules! on_postgres {
    ($cluster:expr, $($name:ident),* $(,)?) => {$(
        let s = $cluster.database(stringify!($name)).await;
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
    );
}
