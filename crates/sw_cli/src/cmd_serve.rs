//! `serve` (the HTTP API with in-process job runners) and `worker` (job runners only, for
//! scale-out on the same database and blob store).

use std::net::SocketAddr;
use std::path::PathBuf;

use sw_server::{AppState, RunnerConfig, ServerConfig};
use sw_store::QueueLimits;

use crate::Failure;

/// Settings shared by `serve` and `worker`.
#[derive(Debug, clap::Args)]
pub(crate) struct QueueArgs {
    /// Directory of the database (scenewright.db) and the package blobs (blobs/).
    #[arg(long, default_value = "scenewright-data")]
    data: PathBuf,
    /// The database, when not `DATA/scenewright.db`: `postgres://USER@HOST:PORT/DB` for
    /// scale-out (also SCENEWRIGHT_DATABASE_URL).
    #[arg(long, value_name = "URL")]
    database: Option<String>,
    /// Job runners in this process.
    #[arg(long, default_value_t = 5)]
    workers: usize,
    /// Jobs that may wait in the queue (more are answered 429).
    #[arg(long, default_value_t = 100)]
    queue_cap: i64,
    /// Jobs of one user that may run at once.
    #[arg(long, default_value_t = 5)]
    per_user: i64,
    /// A job running longer than this fails, seconds.
    #[arg(long, default_value_t = 600)]
    job_timeout: u64,
    /// A runner's lease on its job, ms (renewed every third; a crashed runner's job runs
    /// again this long after its last renewal).
    #[arg(long, default_value_t = 30_000)]
    lease_ms: i64,
    /// Claims of one job before it fails because its runners kept getting lost.
    #[arg(long, default_value_t = 3)]
    max_attempts: i64,
}

impl QueueArgs {
    fn database(&self) -> Option<String> {
        self.database.clone().or_else(|| std::env::var("SCENEWRIGHT_DATABASE_URL").ok().filter(|u| !u.is_empty()))
    }

    fn limits(&self) -> QueueLimits {
        QueueLimits { queue_cap: self.queue_cap, per_user_running: self.per_user }
    }

    fn runner(&self) -> RunnerConfig {
        RunnerConfig {
            lease_ms: self.lease_ms.max(100),
            job_timeout_ms: (self.job_timeout.max(1) * 1000) as i64,
            max_attempts: self.max_attempts.max(1),
            work_dir: Some(self.data.join("work")),
            // The SCENEWRIGHT_LLM_* environment: edits the grammar cannot read go to its model.
            llm: match sw_llm::LlmConfig::from_env() {
                Ok(c) => Some(c),
                Err(e) => {
                    eprintln!("warning: the LLM settings are unusable, edits use the offline grammar only: {e}");
                    None
                }
            },
            ..RunnerConfig::default()
        }
    }
}

#[derive(Debug, clap::Args)]
pub(crate) struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1:8080")]
    addr: SocketAddr,
    #[command(flatten)]
    queue: QueueArgs,
    /// The browser app's files, served at / when the directory exists.
    #[arg(long, default_value = "web")]
    web: PathBuf,
}

#[derive(Debug, clap::Args)]
pub(crate) struct WorkerArgs {
    #[command(flatten)]
    queue: QueueArgs,
}

fn runtime() -> Result<tokio::runtime::Runtime, Failure> {
    tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| Failure::internal(format!("starting the async runtime: {e}")))
}

pub(crate) fn serve(a: ServeArgs) -> Result<u8, Failure> {
    let mut config = ServerConfig::new(a.addr, a.queue.data.clone());
    config.database_url = a.queue.database();
    config.workers = a.queue.workers;
    config.limits = a.queue.limits();
    config.runner = a.queue.runner();
    config.web_dir = Some(a.web);
    runtime()?.block_on(sw_server::serve(config)).map_err(|e| Failure::input(e.to_string()))?;
    Ok(0)
}

pub(crate) fn worker(a: WorkerArgs) -> Result<u8, Failure> {
    let q = a.queue;
    runtime()?.block_on(async move {
        let (store, blobs) =
            sw_server::open_data(&q.data, q.database().as_deref()).await.map_err(|e| Failure::input(e.to_string()))?;
        let state = AppState::new(store, blobs, q.limits(), q.runner(), 3600)
            .await
            .map_err(|e| Failure::internal(e.to_string()))?;
        eprintln!("worker: {} runner(s) on {}", q.workers, q.data.display());
        sw_server::run_workers(state, q.workers, sw_server::shutdown_signal()).await;
        Ok::<_, Failure>(())
    })?;
    Ok(0)
}
