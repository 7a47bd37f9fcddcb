//! `serve` (the HTTP API with in-process job runners) and `worker` (job runners only, for
//! scale-out on the same database and blob store).

use std::net::SocketAddr;
use std::path::PathBuf;

use sw_server::{AppState, RunnerConfig, ServerConfig};
use sw_store::QueueLimits;

use crate::Failure;

/// How the service writes its logs on stderr.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum LogFormat {
    /// Human-readable lines.
    #[default]
    Text,
    /// One JSON object per line, with the fields of the spans it was logged in (a job's
    /// lines carry `job`).
    Json,
}

/// Starts the logger: the service's in its format at `info`, every other command's as text
/// at `warn` (`SCENEWRIGHT_LOG` overrides the level, e.g. `debug` or `sw_server=trace`).
pub(crate) fn init_logs(service: Option<LogFormat>) {
    let default = if service.is_some() { "info,sqlx=warn" } else { "warn" };
    let filter = tracing_subscriber::EnvFilter::try_from_env("SCENEWRIGHT_LOG")
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new(default));
    let text = tracing_subscriber::fmt().with_env_filter(filter).with_writer(std::io::stderr).with_target(false);
    match service.unwrap_or_default() {
        LogFormat::Text => text.init(),
        LogFormat::Json => text.json().flatten_event(true).with_current_span(true).with_span_list(true).init(),
    }
}

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
    /// Jobs of one user that may wait in the queue at once (more are answered 429): one
    /// user cannot fill the queue for everyone. Users are served in turn either way.
    #[arg(long, default_value_t = 20)]
    per_user_queue: i64,
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
    /// Logs on stderr as `text` or `json` (one object per line; also
    /// SCENEWRIGHT_LOG_FORMAT; default text).
    #[arg(long, value_name = "FORMAT")]
    log_format: Option<LogFormat>,
}

impl QueueArgs {
    /// `--log-format`, else SCENEWRIGHT_LOG_FORMAT, else text.
    pub(crate) fn log_format(&self) -> Result<LogFormat, Failure> {
        if let Some(f) = self.log_format {
            return Ok(f);
        }
        match std::env::var("SCENEWRIGHT_LOG_FORMAT") {
            Ok(v) if !v.is_empty() => <LogFormat as clap::ValueEnum>::from_str(&v, true)
                .map_err(|_| Failure::input(format!("SCENEWRIGHT_LOG_FORMAT is '{v}'; it may be 'text' or 'json'"))),
            _ => Ok(LogFormat::Text),
        }
    }

    fn database(&self) -> Option<String> {
        self.database.clone().or_else(|| std::env::var("SCENEWRIGHT_DATABASE_URL").ok().filter(|u| !u.is_empty()))
    }

    fn limits(&self) -> QueueLimits {
        QueueLimits {
            queue_cap: self.queue_cap,
            per_user_running: self.per_user,
            per_user_queued: self.per_user_queue.clamp(1, self.queue_cap.max(1)),
        }
    }

    fn runner(&self) -> RunnerConfig {
        RunnerConfig {
            lease_ms: self.lease_ms.max(100),
            job_timeout_ms: (self.job_timeout.max(1) * 1000) as i64,
            max_attempts: self.max_attempts.max(1),
            work_dir: Some(self.data.join("work")),
            ..RunnerConfig::default()
        }
        // The SCENEWRIGHT_LLM_* environment: edits the grammar cannot read go to its model.
        .with_llm_from_env()
    }
}

#[derive(Debug, clap::Args)]
pub(crate) struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1:8080")]
    addr: SocketAddr,
    #[command(flatten)]
    queue: QueueArgs,
    /// The browser app's built files, served at / (default: web/dist of the checkout,
    /// built by scripts/setup.sh --web).
    #[arg(long, value_name = "DIR")]
    web: Option<PathBuf>,
    /// A connection must send a request's headers within this many seconds (idle
    /// keep-alive connections close after it too).
    #[arg(long, default_value_t = 10)]
    header_timeout: u64,
}

impl ServeArgs {
    pub(crate) fn log_format(&self) -> Result<LogFormat, Failure> {
        self.queue.log_format()
    }
}

#[derive(Debug, clap::Args)]
pub(crate) struct WorkerArgs {
    #[command(flatten)]
    queue: QueueArgs,
}

impl WorkerArgs {
    pub(crate) fn log_format(&self) -> Result<LogFormat, Failure> {
        self.queue.log_format()
    }
}

fn runtime() -> Result<tokio::runtime::Runtime, Failure> {
    tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .map_err(|e| Failure::internal(format!("starting the async runtime: {e}")))
}

pub(crate) fn serve(a: ServeArgs) -> Result<u8, Failure> {
    let format = a.log_format()?;
    let mut config = ServerConfig::new(a.addr, a.queue.data.clone());
    config.database_url = a.queue.database();
    config.workers = a.queue.workers;
    config.limits = a.queue.limits();
    config.runner = a.queue.runner();
    config.web_dir = a.web.or_else(sw_server::web::default_dir);
    // With JSON logs every stderr line is JSON: the address is the `serving` event's `addr`.
    config.listen_line = format == LogFormat::Text;
    config.http.header_timeout = std::time::Duration::from_secs(a.header_timeout.max(1));
    let rt = runtime()?;
    let served = rt.block_on(sw_server::serve(config));
    // A pipeline thread stops at its next cancellation check; one inside a single long
    // call (MuJoCo compiling a huge scene) is not waited for past this.
    rt.shutdown_timeout(std::time::Duration::from_secs(3));
    served.map_err(|e| Failure::input(e.to_string()))?;
    Ok(0)
}

pub(crate) fn worker(a: WorkerArgs) -> Result<u8, Failure> {
    a.log_format()?;
    let q = a.queue;
    let rt = runtime()?;
    let done = rt.block_on(async move {
        let (store, blobs) =
            sw_server::open_data(&q.data, q.database().as_deref()).await.map_err(|e| Failure::input(e.to_string()))?;
        let state = AppState::new(store, blobs, q.limits(), q.runner(), 3600)
            .await
            .map_err(|e| Failure::internal(e.to_string()))?;
        sw_server::run_workers(state, q.workers, sw_server::shutdown_signal())
            .await
            .map_err(|e| Failure::input(e.to_string()))
    });
    rt.shutdown_timeout(std::time::Duration::from_secs(3));
    done?;
    Ok(0)
}
