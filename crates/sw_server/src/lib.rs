//! The service: the HTTP API of DESIGN.md (axum), a WebSocket event stream per job, auth,
//! Prometheus metrics, and the queue workers that run the pipeline.
//!
//! One process ([`serve`]) answers HTTP and runs `workers` job runners; more runners can
//! join from other processes ([`run_workers`], `scenewright worker`) on the same database
//! and blob store. Jobs are leased: a runner renews its lease while it works, and whoever
//! finds an expired lease puts the job back in the queue (see `sw_store`).

mod auth;
mod body;
mod catalog_pictures;
mod compress;
mod dataset_jobs;
mod edit_jobs;
mod error;
pub mod forge;
pub mod http;
mod metrics;
mod openapi;
mod routes_auth;
mod routes_edits;
mod routes_jobs;
mod routes_misc;
mod routes_refine;
mod routes_scenes;
mod scratch;
mod throttle;
mod thumbnail;
pub mod web;
mod worker;
mod ws;
mod zip;

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use axum::Router;
use axum::extract::DefaultBodyLimit;
use axum::routing::{get, post};
use sw_store::{BlobStore, LocalBlobs, QueueLimits, S3Blobs, S3Config, Store};
use tokio::sync::broadcast;

pub use auth::{Claims, Tokens, hash_password};
pub use error::ApiError;
pub use http::HttpOptions;
pub use throttle::AuthLimits;
pub use worker::{RunnerConfig, run_workers};

/// The largest request body, bytes (a prompt may be at most [`PROMPT_LIMIT`]).
pub const BODY_LIMIT: usize = 1 << 20;
/// The largest prompt or edit command, bytes (the offline planner's own bound).
pub const PROMPT_LIMIT: usize = sw_planner::MAX_PROMPT_BYTES;
/// The most scenes one request may ask for (`variations`).
pub const MAX_VARIATIONS: u32 = 10;

/// How the service runs.
#[derive(Debug, Clone)]
pub struct ServerConfig {
    pub addr: SocketAddr,
    /// Holds `scenewright.db` and `blobs/`.
    pub data_dir: PathBuf,
    /// A database URL instead of `data_dir/scenewright.db` (`postgres://…`).
    pub database_url: Option<String>,
    /// Job runners in this process (0: HTTP only, the jobs run in `scenewright worker`s).
    pub workers: usize,
    pub limits: QueueLimits,
    pub runner: RunnerConfig,
    /// Access tokens live this long, s.
    pub token_ttl_s: i64,
    /// The browser app's built files (`web/dist`), served at `/` when the directory
    /// holds an `index.html`; without them `/` says how to build the app.
    pub web_dir: Option<PathBuf>,
    /// Print `listening on http://ADDR` on stderr, for scripts (off when every stderr line
    /// must be a JSON log record; the `serving` event carries `addr` too).
    pub listen_line: bool,
    /// Header timeout and shutdown grace of connections.
    pub http: HttpOptions,
    /// Wrong sign-ins and registrations allowed per window.
    pub auth_limits: AuthLimits,
}

impl ServerConfig {
    pub fn new(addr: SocketAddr, data_dir: PathBuf) -> Self {
        Self {
            addr,
            data_dir,
            database_url: None,
            workers: 5,
            limits: QueueLimits::default(),
            runner: RunnerConfig::default(),
            token_ttl_s: 3600,
            web_dir: web::default_dir(),
            listen_line: true,
            http: HttpOptions::default(),
            auth_limits: AuthLimits::default(),
        }
    }
}

/// What every handler shares.
#[derive(Debug, Clone)]
pub struct AppState {
    pub store: Store,
    pub blobs: Arc<dyn BlobStore>,
    pub tokens: Tokens,
    pub limits: QueueLimits,
    pub runner: RunnerConfig,
    /// Job ids whose event stream grew (in this process); WebSockets also poll the
    /// database for runners in other processes.
    pub events: broadcast::Sender<String>,
    pub metrics: Arc<metrics::Counters>,
    /// Wakes idle runners in this process when a job is queued.
    pub wake: Arc<tokio::sync::Notify>,
    /// The browser app's directory, served for paths outside `/api/`.
    pub web_dir: Option<PathBuf>,
    /// Makes and serves the assets `POST /api/assets` asks for.
    pub forge: Arc<forge::AssetForge>,
    /// Compressed bodies of immutable answers (scene files), shared by every request.
    pub gzip: Arc<compress::GzipCache>,
    /// Wrong sign-ins and registrations seen (per name and client address).
    pub throttle: Arc<throttle::Throttle>,
    pub auth_limits: AuthLimits,
}

/// A problem starting the service.
#[derive(Debug, thiserror::Error)]
pub enum StartError {
    #[error("{0}")]
    Store(#[from] sw_store::StoreError),
    #[error("{0}")]
    Blob(#[from] sw_store::BlobError),
    #[error("{path}: {source}")]
    Io { path: String, source: std::io::Error },
    #[error("scratch space {0}")]
    Scratch(#[from] scratch::ScratchError),
}

/// Opens the database under `data_dir` and the blob store: an S3-compatible bucket when
/// `SCENEWRIGHT_S3_ENDPOINT` is set (see [`S3Config::from_env`]), else `data_dir/blobs`.
/// The database is `database_url` (`postgres://…` for scale-out) or `data_dir/scenewright.db`.
pub async fn open_data(
    data_dir: &std::path::Path,
    database_url: Option<&str>,
) -> Result<(Store, Arc<dyn BlobStore>), StartError> {
    fs_err::create_dir_all(data_dir).map_err(|e| StartError::Io { path: data_dir.display().to_string(), source: e })?;
    // Only the service's own user reads the data: the database holds the token secret and
    // every user's password hash.
    private(data_dir, 0o700)?;
    let store = match database_url {
        Some(url) => Store::open(url).await?,
        None => {
            let db = data_dir.join("scenewright.db");
            let store = Store::open_sqlite(&db).await?;
            // SQLite makes its -wal and -shm files with the database's own mode.
            for f in ["scenewright.db", "scenewright.db-wal", "scenewright.db-shm"] {
                let p = data_dir.join(f);
                if p.exists() {
                    private(&p, 0o600)?;
                }
            }
            store
        }
    };
    let blobs: Arc<dyn BlobStore> = match S3Config::from_env() {
        Some(config) => {
            tracing::info!(endpoint = %config.endpoint, bucket = %config.bucket, "packages in S3");
            let s3 = S3Blobs::new(config);
            let s3 = tokio::task::spawn_blocking(move || s3.ensure_bucket().map(|()| s3))
                .await
                .map_err(|e| StartError::Io { path: "S3".into(), source: std::io::Error::other(e) })??;
            Arc::new(s3)
        }
        None => Arc::new(LocalBlobs::new(data_dir.join("blobs"))?),
    };
    Ok((store, blobs))
}

/// Makes `path` readable by its owner only (`mode`: 0o700 for a directory, 0o600 a file).
fn private(path: &std::path::Path, mode: u32) -> Result<(), StartError> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode))
            .map_err(|e| StartError::Io { path: path.display().to_string(), source: e })?;
    }
    #[cfg(not(unix))]
    let _ = (path, mode);
    Ok(())
}

impl AppState {
    /// Keeps generated assets in the store at `location` (a directory or
    /// `s3://bucket/prefix`) instead of the default one.
    pub fn with_asset_store(mut self, location: String) -> Self {
        self.forge = Arc::new(forge::AssetForge::new(location, self.runner.llm.clone()));
        self
    }

    /// The state for a store and blob store (the JWT secret is kept in the database, so
    /// every process on it accepts the same tokens).
    pub async fn new(
        store: Store,
        blobs: Arc<dyn BlobStore>,
        limits: QueueLimits,
        runner: RunnerConfig,
        token_ttl_s: i64,
    ) -> Result<Self, StartError> {
        let secret = store.setting_or_init("jwt_secret", sw_store::new_secret).await?;
        let (events, _) = broadcast::channel(4096);
        let forge = Arc::new(forge::AssetForge::new(sw_forge::library::default_store_location(), runner.llm.clone()));
        Ok(Self {
            store,
            blobs,
            tokens: Tokens::new(secret.as_bytes(), token_ttl_s),
            limits,
            runner,
            events,
            metrics: Arc::new(metrics::Counters::default()),
            web_dir: None,
            forge,
            gzip: Arc::new(compress::GzipCache::default()),
            wake: Arc::new(tokio::sync::Notify::new()),
            throttle: Arc::new(throttle::Throttle::default()),
            auth_limits: AuthLimits::default(),
        })
    }
}

/// The HTTP routes (without static files).
pub fn router(state: AppState) -> Router {
    Router::new()
        .route("/healthz", get(routes_misc::healthz))
        .route("/metrics", get(metrics::metrics))
        .route("/api/openapi.json", get(openapi::document))
        .route("/api/auth/register", post(routes_auth::register))
        .route("/api/auth/login", post(routes_auth::login))
        .route("/api/auth/logout", post(routes_auth::logout))
        .route("/api/auth/keys", post(routes_auth::create_key).get(routes_auth::list_keys))
        .route("/api/auth/keys/{id}", axum::routing::delete(routes_auth::delete_key))
        .route("/api/me", get(routes_auth::me))
        .route("/api/options", get(routes_misc::options))
        .route("/api/refine", post(routes_refine::refine))
        .route("/api/jobs", post(routes_jobs::create).get(routes_jobs::list))
        .route("/api/jobs/{id}", get(routes_jobs::show).delete(routes_jobs::cancel))
        .route("/api/jobs/{id}/events", get(ws::events))
        .route("/api/scenes", get(routes_scenes::list))
        .route("/api/scenes/{id}", get(routes_scenes::show).delete(routes_scenes::delete))
        .route("/api/scenes/{id}/files/{*path}", get(routes_scenes::file))
        .route("/api/scenes/{id}/package.zip", get(routes_scenes::package_zip))
        .route("/api/scenes/{id}/edits", post(routes_edits::edit))
        .route("/api/scenes/{id}/versions", get(routes_edits::versions))
        .route("/api/scenes/{id}/thumbnail.png", get(thumbnail::thumbnail))
        .route("/api/assets", get(routes_misc::assets).post(routes_misc::create_asset))
        .route("/api/assets/{id}", get(routes_misc::asset))
        .route("/api/assets/{id}/mesh.stl", get(routes_misc::asset_mesh))
        .route("/api/catalog/{name}/picture.png", get(catalog_pictures::picture))
        .route("/api/robots", get(routes_misc::robots))
        .route("/api/admin/jobs", get(routes_jobs::admin_overview))
        .fallback(routes_misc::not_found)
        .layer(axum::middleware::from_fn_with_state(Arc::clone(&state.gzip), compress::layer))
        .layer(axum::middleware::from_fn_with_state(state.clone(), metrics::track))
        .layer(DefaultBodyLimit::max(BODY_LIMIT))
        .layer(axum::middleware::from_fn(http::security_headers))
        .with_state(state)
}

/// Runs the service until Ctrl-C / SIGTERM: HTTP on `config.addr`, `config.workers` job
/// runners, and the recovery of jobs whose runners were lost (at start and every second).
pub async fn serve(config: ServerConfig) -> Result<(), StartError> {
    let (store, blobs) = open_data(&config.data_dir, config.database_url.as_deref()).await?;
    let mut state = AppState::new(store, blobs, config.limits, config.runner.clone(), config.token_ttl_s)
        .await?
        .with_asset_store(forge::store_location(&config.data_dir));
    state.auth_limits = config.auth_limits;
    state.web_dir = config.web_dir.clone().filter(|d| d.join("index.html").is_file());
    match &state.web_dir {
        Some(d) => tracing::info!(dir = %d.display(), "serving the web app"),
        None => tracing::warn!("the web app is not built (scripts/setup.sh --web); / says how"),
    }
    let recovered = state.store.recover().await?;
    if !recovered.requeued.is_empty() || !recovered.failed.is_empty() {
        tracing::warn!(requeued = ?recovered.requeued, failed = ?recovered.failed, "recovered jobs of lost runners");
    }
    // One shutdown for both halves: SIGTERM or Ctrl-C stops accepting, ends the jobs this
    // process runs (their pipelines stop at their next check and the jobs go back to the
    // queue) and closes what is left after the grace period.
    let (stop_tx, stop_rx) = tokio::sync::watch::channel(false);
    tokio::spawn(async move {
        shutdown_signal().await;
        tracing::info!("stopping");
        let _ = stop_tx.send(true);
    });
    let stopped = move || {
        let mut rx = stop_rx.clone();
        async move {
            let _ = rx.wait_for(|s| *s).await;
        }
    };
    // The scratch of dead processes is gone before the address is announced.
    let runners = worker::start_workers(state.clone(), config.workers, stopped())?;
    let app = router(state.clone());
    let listener = tokio::net::TcpListener::bind(config.addr)
        .await
        .map_err(|e| StartError::Io { path: config.addr.to_string(), source: e })?;
    let local = listener.local_addr().map_err(|e| StartError::Io { path: config.addr.to_string(), source: e })?;
    tracing::info!(addr = %local, workers = config.workers, "serving");
    if config.listen_line {
        // Scripts (and the tests) read the address from this line.
        eprintln!("listening on http://{local}");
    }
    http::serve(listener, app, config.http, stopped())
        .await
        .map_err(|e| StartError::Io { path: local.to_string(), source: e })?;
    if tokio::time::timeout(Duration::from_secs(10), runners).await.is_err() {
        tracing::warn!("job runners still busy after 10 s; their jobs run again after their lease");
    }
    Ok(())
}

/// Resolves on Ctrl-C or SIGTERM.
pub async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        _ = ctrl_c => {},
        _ = term => {},
    }
}
