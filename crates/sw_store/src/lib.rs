//! Persistence for the service: users and API keys, jobs (a persistent queue with atomic
//! claims, leases and heartbeats), scenes and their edit history, asset metadata,
//! telemetry, and the blob store that holds packages.
//!
//! The default database is one SQLite file (WAL mode, so the server and any number of
//! `scenewright worker` processes on the machine share it); PostgreSQL serves scale-out
//! (claims with `FOR UPDATE SKIP LOCKED`). Every statement is a fixed string with bound
//! parameters; nothing a user sends is ever spliced into SQL.
//!
//! A job survives the crash of whoever runs it: a claim takes a lease that the runner
//! renews; [`Store::recover`] (run by every server and worker, periodically) puts jobs
//! whose lease expired back in the queue, or fails them with a reason once they used
//! their attempts, and fails jobs past their timeout. Completion is conditional on the
//! claim still being the runner's (same worker, same attempt, still running), so a job is
//! never completed twice.

mod blob;
mod blob_s3;
mod datasets;
mod ids;
mod jobs;
mod scenes;
mod schema;
mod users;

use std::path::Path;
use std::str::FromStr;

use sqlx::AnyPool;
use sqlx::any::AnyPoolOptions;
use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode};
use sqlx::{ConnectOptions, Connection};

pub use blob::{BlobError, BlobStore, LocalBlobs, check_key};
pub use blob_s3::S3Blobs;
pub use datasets::DatasetSlot;
pub use ids::{is_id, new_id, new_secret, now_ms};
pub use jobs::{Claim, Job, JobKind, JobState, NewJob, QueueLimits, Recovered};
pub use scenes::{Asset, EditRecord, NewScene, Scene, StageStat, Telemetry};
pub use sw_s3::S3Config;
pub use users::{CountedTable, Role, User};

/// What can go wrong in the store.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("database: {0}")]
    Db(#[from] sqlx::Error),
    /// A unique value (a user name) is taken.
    #[error("{0}")]
    Conflict(String),
    /// The queue holds as many jobs as it may (all of them, or as many of one user's as
    /// a user may have waiting: `per_user`).
    #[error("{}", if *per_user {
        format!("you have {cap} jobs waiting, as many as one user may; try again when one has started")
    } else {
        format!("the queue is full ({cap} jobs waiting); try again later")
    })]
    QueueFull { cap: i64, per_user: bool },
    /// A stored value is not what the code wrote.
    #[error("corrupt row: {0}")]
    Corrupt(String),
}

impl StoreError {
    /// True when the database could not write because its disk is full or failing
    /// (SQLite's SQLITE_FULL / SQLITE_IOERR, PostgreSQL's class 53 and 58 errors): the
    /// write was not stored, and trying again once space is back will work.
    pub fn is_storage_failure(&self) -> bool {
        let StoreError::Db(e) = self else { return false };
        match e {
            sqlx::Error::Database(d) => {
                let code = d.code().map(|c| c.to_string()).unwrap_or_default();
                // SQLite's primary result code is the low byte of the extended one.
                let sqlite = code.parse::<i64>().ok().map(|c| c & 0xff);
                matches!(sqlite, Some(10 | 13)) || code.starts_with("53") || code.starts_with("58")
            }
            sqlx::Error::Io(_) => true,
            _ => false,
        }
    }
}

pub type Result<T> = std::result::Result<T, StoreError>;

/// Whether a SQLite connection back from use may serve the next caller: it is in no
/// transaction. A write that failed for want of space can leave one open — SQLite keeps a
/// transaction whose COMMIT failed with SQLITE_FULL, or ends one itself while sqlx still
/// counts it — and such a connection holds an old snapshot and its lock: every later write
/// through it, or anyone else's, answers "database is locked" until the process restarts.
/// A connection that cannot start a transaction of its own is closed instead (the pool
/// opens a fresh one).
async fn sqlite_connection_is_clean(conn: &mut sqlx::AnyConnection) -> bool {
    if conn.is_in_transaction() {
        return false;
    }
    if sqlx::query("BEGIN").execute(&mut *conn).await.is_err() {
        return false;
    }
    sqlx::query("ROLLBACK").execute(&mut *conn).await.is_ok()
}

/// Which database a store is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backend {
    /// One file, WAL mode: the server and workers on one machine.
    Sqlite,
    /// Scale-out: jobs claimed with `FOR UPDATE SKIP LOCKED`.
    Postgres,
}

/// The database: a pool of connections (sqlx's `Any` driver over SQLite or PostgreSQL; every
/// statement is written once, in the SQL both understand, with `$n` parameters).
#[derive(Debug, Clone)]
pub struct Store {
    pool: AnyPool,
    backend: Backend,
}

impl Store {
    /// Opens (creating if needed) the SQLite database at `path` and brings its schema up to date.
    pub async fn open_sqlite(path: &Path) -> Result<Self> {
        let url = format!("sqlite://{}", path.display());
        // Create the file and switch it to WAL (a property of the file) with the typed driver.
        let opts = SqliteConnectOptions::from_str(&url)?.create_if_missing(true).journal_mode(SqliteJournalMode::Wal);
        let conn = opts.connect().await?;
        conn.close().await?;
        Self::open_url(&url).await
    }

    /// Opens a database by URL: `sqlite://PATH` or `postgres://USER@HOST:PORT/DB`.
    pub async fn open(url: &str) -> Result<Self> {
        match url.split_once("://").map(|x| x.0) {
            Some("sqlite") => Self::open_sqlite(Path::new(url.trim_start_matches("sqlite://"))).await,
            Some("postgres" | "postgresql") => Self::open_url(url).await,
            _ => Err(StoreError::Conflict(format!("unsupported database URL '{url}' (sqlite:// or postgres://)"))),
        }
    }

    async fn open_url(url: &str) -> Result<Self> {
        sqlx::any::install_default_drivers();
        let backend = if url.starts_with("sqlite:") { Backend::Sqlite } else { Backend::Postgres };
        let pool = AnyPoolOptions::new()
            .max_connections(16)
            .after_connect(move |conn, _| {
                Box::pin(async move {
                    if backend == Backend::Sqlite {
                        // WAL + NORMAL: a process crash loses nothing that was committed.
                        for pragma in
                            ["PRAGMA busy_timeout = 30000", "PRAGMA foreign_keys = ON", "PRAGMA synchronous = NORMAL"]
                        {
                            sqlx::query(pragma).execute(&mut *conn).await?;
                        }
                    }
                    Ok(())
                })
            })
            .after_release(move |conn, _| {
                Box::pin(async move {
                    if backend != Backend::Sqlite {
                        return Ok(true);
                    }
                    Ok(sqlite_connection_is_clean(conn).await)
                })
            })
            .connect(url)
            .await?;
        schema::migrate(&pool, backend).await?;
        Ok(Self { pool, backend })
    }

    /// The connection pool (for the store's own modules and tests).
    pub fn pool(&self) -> &AnyPool {
        &self.pool
    }

    pub fn backend(&self) -> Backend {
        self.backend
    }

    /// Writes and commits one small row (the time of the probe): fails when the database
    /// cannot write — a full disk reads fine but refuses this.
    pub async fn probe_write(&self) -> Result<()> {
        let mut tx = self.pool.begin().await?;
        sqlx::query(
            "INSERT INTO settings (name, value) VALUES ('health_probe', $1)
             ON CONFLICT(name) DO UPDATE SET value = excluded.value",
        )
        .bind(format!("{}:{}", now_ms(), new_id()))
        .execute(&mut *tx)
        .await?;
        tx.commit().await?;
        Ok(())
    }

    /// A setting, created with `init` the first time it is asked for (e.g. the JWT secret,
    /// shared by every process on the database).
    pub async fn setting_or_init(&self, name: &str, init: impl FnOnce() -> String) -> Result<String> {
        let value = init();
        sqlx::query("INSERT INTO settings (name, value) VALUES ($1, $2) ON CONFLICT(name) DO NOTHING")
            .bind(name)
            .bind(&value)
            .execute(&self.pool)
            .await?;
        let (v,): (String,) =
            sqlx::query_as("SELECT value FROM settings WHERE name = $1").bind(name).fetch_one(&self.pool).await?;
        Ok(v)
    }
}
