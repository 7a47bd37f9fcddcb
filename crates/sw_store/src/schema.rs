//! The schema, created idempotently when a database is opened.

use sqlx::AnyPool;

use crate::Backend;

/// Statements run in order on every open; each is idempotent.
const STATEMENTS: &[&str] = &[
    "CREATE TABLE IF NOT EXISTS settings (name TEXT PRIMARY KEY, value TEXT NOT NULL)",
    "CREATE TABLE IF NOT EXISTS users (
        id TEXT PRIMARY KEY,
        username TEXT NOT NULL UNIQUE,
        password_hash TEXT NOT NULL,
        role TEXT NOT NULL CHECK (role IN ('admin', 'user')),
        created_at INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS api_keys (
        id TEXT PRIMARY KEY,
        user_id TEXT NOT NULL REFERENCES users(id),
        name TEXT NOT NULL,
        key_hash TEXT NOT NULL UNIQUE,
        created_at INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS prompts (
        id TEXT PRIMARY KEY,
        user_id TEXT NOT NULL REFERENCES users(id),
        text TEXT NOT NULL,
        created_at INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS jobs (
        id TEXT PRIMARY KEY,
        user_id TEXT NOT NULL REFERENCES users(id),
        kind TEXT NOT NULL CHECK (kind IN ('generate', 'edit')),
        prompt_id TEXT REFERENCES prompts(id),
        prompt TEXT NOT NULL,
        seed INTEGER NOT NULL,
        options TEXT NOT NULL,
        parent_scene_id TEXT,
        state TEXT NOT NULL CHECK (state IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
        stage TEXT,
        attempts INTEGER NOT NULL DEFAULT 0,
        max_attempts INTEGER NOT NULL,
        worker TEXT,
        lease_until INTEGER,
        timeout_ms INTEGER NOT NULL,
        created_at INTEGER NOT NULL,
        started_at INTEGER,
        finished_at INTEGER,
        error TEXT,
        scene_id TEXT,
        completions INTEGER NOT NULL DEFAULT 0,
        -- Arrival order (FIFO; enqueues are serialised, so no ties; any would go by id).
        qseq INTEGER NOT NULL DEFAULT 0)",
    "CREATE INDEX IF NOT EXISTS jobs_state ON jobs(state, qseq)",
    "CREATE INDEX IF NOT EXISTS jobs_user ON jobs(user_id, state)",
    "CREATE TABLE IF NOT EXISTS job_events (
        job_id TEXT NOT NULL REFERENCES jobs(id),
        seq INTEGER NOT NULL,
        at INTEGER NOT NULL,
        body TEXT NOT NULL,
        PRIMARY KEY (job_id, seq))",
    "CREATE TABLE IF NOT EXISTS scenes (
        id TEXT PRIMARY KEY,
        user_id TEXT NOT NULL REFERENCES users(id),
        job_id TEXT NOT NULL REFERENCES jobs(id),
        parent_id TEXT REFERENCES scenes(id),
        version INTEGER NOT NULL,
        prompt TEXT NOT NULL,
        status TEXT NOT NULL,
        report TEXT NOT NULL,
        files TEXT NOT NULL,
        created_at INTEGER NOT NULL)",
    "CREATE INDEX IF NOT EXISTS scenes_user ON scenes(user_id, created_at)",
    "CREATE TABLE IF NOT EXISTS edits (
        id TEXT PRIMARY KEY,
        user_id TEXT NOT NULL REFERENCES users(id),
        scene_id TEXT NOT NULL REFERENCES scenes(id),
        new_scene_id TEXT NOT NULL REFERENCES scenes(id),
        command TEXT NOT NULL,
        record TEXT NOT NULL,
        created_at INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS assets (
        id TEXT PRIMARY KEY,
        user_id TEXT NOT NULL REFERENCES users(id),
        description TEXT NOT NULL,
        category TEXT,
        meta TEXT NOT NULL,
        created_at INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS telemetry (
        job_id TEXT NOT NULL REFERENCES jobs(id),
        kind TEXT NOT NULL,
        name TEXT NOT NULL,
        ms REAL NOT NULL,
        tokens_in INTEGER NOT NULL DEFAULT 0,
        tokens_out INTEGER NOT NULL DEFAULT 0,
        at INTEGER NOT NULL)",
    "CREATE INDEX IF NOT EXISTS telemetry_kind ON telemetry(kind, name)",
    // The checksum of every stored file of a scene (what is served is checked against it).
    "CREATE TABLE IF NOT EXISTS scene_files (
        scene_id TEXT NOT NULL REFERENCES scenes(id),
        path TEXT NOT NULL,
        sha256 TEXT NOT NULL,
        PRIMARY KEY (scene_id, path))",
    // User names are one whatever their case: `Alice` and `alice` are the same user.
    "CREATE UNIQUE INDEX IF NOT EXISTS users_name_nocase ON users (lower(username))",
    // Access tokens revoked before they expire (signed out), by their `jti`.
    "CREATE TABLE IF NOT EXISTS revoked_tokens (
        jti TEXT PRIMARY KEY,
        expires_at INTEGER NOT NULL)",
    // Datasets on the queue (`scenewright dataset --database`): the dataset, the job that
    // makes each scene slot (one at a time), and the structural fingerprints taken, each
    // by one slot (a scene whose fingerprint another slot holds is a duplicate).
    "CREATE TABLE IF NOT EXISTS datasets (
        id TEXT PRIMARY KEY,
        spec TEXT NOT NULL,
        created_at INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS dataset_slots (
        dataset_id TEXT NOT NULL REFERENCES datasets(id),
        slot TEXT NOT NULL,
        job_id TEXT NOT NULL REFERENCES jobs(id),
        PRIMARY KEY (dataset_id, slot))",
    "CREATE TABLE IF NOT EXISTS dataset_fingerprints (
        dataset_id TEXT NOT NULL REFERENCES datasets(id),
        fingerprint TEXT NOT NULL,
        slot TEXT NOT NULL,
        PRIMARY KEY (dataset_id, fingerprint))",
];

/// The PostgreSQL advisory lock that serialises migrations ("swschema" in ASCII): two
/// processes starting at once on a new database would otherwise race in `CREATE TABLE IF
/// NOT EXISTS` (PostgreSQL's catalog rejects the second with a duplicate key).
const MIGRATE_LOCK: i64 = 0x7377_7363_6865_6d61;

pub(crate) async fn migrate(pool: &AnyPool, backend: Backend) -> Result<(), sqlx::Error> {
    match backend {
        Backend::Sqlite => {
            for s in STATEMENTS {
                sqlx::query(*s).execute(pool).await?;
            }
        }
        Backend::Postgres => {
            // One transaction under the lock (PostgreSQL's DDL is transactional).
            let mut tx = pool.begin().await?;
            sqlx::query("SELECT pg_advisory_xact_lock($1)").bind(MIGRATE_LOCK).execute(&mut *tx).await?;
            for s in STATEMENTS {
                // The same tables with PostgreSQL's 64-bit and double types. The text is
                // derived from the constants above, never from input.
                let pg = s.replace("INTEGER", "BIGINT").replace("REAL", "DOUBLE PRECISION");
                sqlx::query(sqlx::AssertSqlSafe(pg)).execute(&mut *tx).await?;
            }
            tx.commit().await?;
        }
    }
    Ok(())
}
