//! Persistence for the service: users and API keys, jobs (a persistent queue with atomic
//! claims, leases and heartbeats), scenes and their edit history, asset metadata,
//! telemetry, and the blob store that holds packages.
//!
//! The default database is one SQLite file (WAL mode, so the server and any number of
//! `scenewright worker` processes on the machine share it). Every statement is a fixed
//! string with bound parameters; nothing a user sends is ever spliced into SQL.
//!
//! A job survives the crash of whoever runs it: a claim takes a lease that the runner
//! renews; [`Store::recover`] (run by every server and worker, periodically) puts jobs
//! whose lease expired back in the queue, or fails them with a reason once they used
//! their attempts, and fails jobs past their timeout. Completion is conditional on the
//! claim still being the runner's (same worker, same attempt, still running), so a job is
//! never completed twice.

mod blob;
mod blob_s3;
mod ids;
mod jobs;
mod scenes;
mod schema;
mod users;

use std::path::Path;
use std::str::FromStr;
use std::time::Duration;

use sqlx::SqlitePool;
use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePoolOptions, SqliteSynchronous};

pub use blob::{BlobError, BlobStore, LocalBlobs, check_key};
pub use blob_s3::{S3Blobs, S3Config};
pub use ids::{is_id, new_id, new_secret, now_ms};
pub use jobs::{Claim, Job, JobKind, JobState, NewJob, QueueLimits, Recovered};
pub use scenes::{Asset, EditRecord, NewScene, Scene, StageStat, Telemetry};
pub use users::{CountedTable, Role, User};

/// What can go wrong in the store.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("database: {0}")]
    Db(#[from] sqlx::Error),
    /// A unique value (a user name) is taken.
    #[error("{0}")]
    Conflict(String),
    /// The queue holds as many jobs as it may.
    #[error("the queue is full ({cap} jobs waiting); try again later")]
    QueueFull { cap: i64 },
    /// A stored value is not what the code wrote.
    #[error("corrupt row: {0}")]
    Corrupt(String),
}

pub type Result<T> = std::result::Result<T, StoreError>;

/// The database: a pool of connections.
#[derive(Debug, Clone)]
pub struct Store {
    pool: SqlitePool,
}

impl Store {
    /// Opens (creating if needed) the SQLite database at `path` and brings its schema up to date.
    pub async fn open_sqlite(path: &Path) -> Result<Self> {
        let url = format!("sqlite://{}", path.display());
        let opts = SqliteConnectOptions::from_str(&url)?
            .create_if_missing(true)
            .journal_mode(SqliteJournalMode::Wal)
            // WAL + NORMAL: a process crash loses nothing that was committed.
            .synchronous(SqliteSynchronous::Normal)
            .busy_timeout(Duration::from_secs(30))
            .foreign_keys(true);
        let pool = SqlitePoolOptions::new().max_connections(16).connect_with(opts).await?;
        schema::migrate(&pool).await?;
        Ok(Self { pool })
    }

    /// The connection pool (for the store's own modules and tests).
    pub fn pool(&self) -> &SqlitePool {
        &self.pool
    }

    /// A setting, created with `init` the first time it is asked for (e.g. the JWT secret,
    /// shared by every process on the database).
    pub async fn setting_or_init(&self, name: &str, init: impl FnOnce() -> String) -> Result<String> {
        let value = init();
        sqlx::query("INSERT INTO settings (name, value) VALUES (?, ?) ON CONFLICT(name) DO NOTHING")
            .bind(name)
            .bind(&value)
            .execute(&self.pool)
            .await?;
        let (v,): (String,) =
            sqlx::query_as("SELECT value FROM settings WHERE name = ?").bind(name).fetch_one(&self.pool).await?;
        Ok(v)
    }
}
