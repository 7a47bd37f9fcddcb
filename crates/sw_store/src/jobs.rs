//! The job queue: enqueue with a cap, atomic claims under a per-user limit, leases renewed
//! by heartbeats, conditional completion, cancellation, recovery of lost and timed-out jobs.

use serde::Serialize;
use sqlx::Row;
use sqlx::any::AnyRow;

use crate::{Result, Store, StoreError, new_id, now_ms};

/// Where a job is in its life.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum JobState {
    Queued,
    Running,
    Succeeded,
    Failed,
    Cancelled,
}

impl JobState {
    pub const ALL: [JobState; 5] =
        [JobState::Queued, JobState::Running, JobState::Succeeded, JobState::Failed, JobState::Cancelled];

    pub fn as_str(self) -> &'static str {
        match self {
            JobState::Queued => "queued",
            JobState::Running => "running",
            JobState::Succeeded => "succeeded",
            JobState::Failed => "failed",
            JobState::Cancelled => "cancelled",
        }
    }

    pub fn parse(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|x| x.as_str() == s)
    }

    /// Succeeded, failed or cancelled: nothing more will happen to the job.
    pub fn is_terminal(self) -> bool {
        matches!(self, JobState::Succeeded | JobState::Failed | JobState::Cancelled)
    }
}

/// What a job does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum JobKind {
    /// Generate a scene from a prompt.
    Generate,
    /// Apply a plain-English edit (the prompt) to `parent_scene_id`, making a new version.
    Edit,
}

impl JobKind {
    pub fn as_str(self) -> &'static str {
        match self {
            JobKind::Generate => "generate",
            JobKind::Edit => "edit",
        }
    }
}

/// A job as stored.
#[derive(Debug, Clone, Serialize)]
pub struct Job {
    pub id: String,
    #[serde(skip)]
    pub user_id: String,
    pub kind: JobKind,
    pub prompt: String,
    pub seed: u64,
    /// The request's options, as JSON.
    pub options: serde_json::Value,
    pub parent_scene_id: Option<String>,
    pub state: JobState,
    /// The stage running now (or last run).
    pub stage: Option<String>,
    /// Claims so far (1 on the first run; more after a runner was lost).
    pub attempts: i64,
    pub max_attempts: i64,
    #[serde(skip)]
    pub worker: Option<String>,
    #[serde(skip)]
    pub lease_until: Option<i64>,
    pub timeout_ms: i64,
    pub created_at: i64,
    pub started_at: Option<i64>,
    pub finished_at: Option<i64>,
    pub error: Option<String>,
    pub scene_id: Option<String>,
    /// How many times the job was completed (0 or 1: a check on the queue's promise).
    #[serde(skip)]
    pub completions: i64,
}

impl Job {
    fn from_row(r: &AnyRow) -> Result<Self> {
        let kind: String = r.try_get("kind")?;
        let state: String = r.try_get("state")?;
        let options: String = r.try_get("options")?;
        let seed: i64 = r.try_get("seed")?;
        Ok(Job {
            id: r.try_get("id")?,
            user_id: r.try_get("user_id")?,
            kind: match kind.as_str() {
                "generate" => JobKind::Generate,
                "edit" => JobKind::Edit,
                k => return Err(StoreError::Corrupt(format!("job kind '{k}'"))),
            },
            prompt: r.try_get("prompt")?,
            seed: seed as u64,
            options: serde_json::from_str(&options).map_err(|e| StoreError::Corrupt(format!("job options: {e}")))?,
            parent_scene_id: r.try_get("parent_scene_id")?,
            state: JobState::parse(&state).ok_or_else(|| StoreError::Corrupt(format!("job state '{state}'")))?,
            stage: r.try_get("stage")?,
            attempts: r.try_get("attempts")?,
            max_attempts: r.try_get("max_attempts")?,
            worker: r.try_get("worker")?,
            lease_until: r.try_get("lease_until")?,
            timeout_ms: r.try_get("timeout_ms")?,
            created_at: r.try_get("created_at")?,
            started_at: r.try_get("started_at")?,
            finished_at: r.try_get("finished_at")?,
            error: r.try_get("error")?,
            scene_id: r.try_get("scene_id")?,
            completions: r.try_get("completions")?,
        })
    }

    /// Milliseconds between creation and the (latest) claim.
    pub fn queue_wait_ms(&self) -> Option<i64> {
        self.started_at.map(|s| s - self.created_at)
    }
}

/// A job to enqueue.
#[derive(Debug, Clone)]
pub struct NewJob {
    pub user_id: String,
    pub kind: JobKind,
    pub prompt: String,
    pub seed: u64,
    pub options: serde_json::Value,
    pub parent_scene_id: Option<String>,
    pub timeout_ms: i64,
    pub max_attempts: i64,
}

/// Limits of the queue.
#[derive(Debug, Clone, Copy)]
pub struct QueueLimits {
    /// Jobs that may wait in the queue at once (more are refused: HTTP 429).
    pub queue_cap: i64,
    /// Jobs of one user that may run at once (more wait in the queue).
    pub per_user_running: i64,
    /// Jobs of one user that may wait in the queue at once: one user cannot fill the
    /// queue for everyone (more are refused: HTTP 429).
    pub per_user_queued: i64,
}

impl Default for QueueLimits {
    fn default() -> Self {
        Self { queue_cap: 100, per_user_running: 5, per_user_queued: 20 }
    }
}

/// A claimed job: the job and the proof of the claim that completion must present.
#[derive(Debug, Clone)]
pub struct Claim {
    pub job: Job,
    pub worker: String,
    pub attempt: i64,
}

/// What [`Store::recover`] did.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Recovered {
    /// Jobs whose runner was lost, back in the queue.
    pub requeued: Vec<String>,
    /// Jobs whose runner was lost once too often, or that ran past their timeout.
    pub failed: Vec<String>,
}

/// The PostgreSQL advisory lock key that serialises enqueues (any fixed 64-bit number;
/// this one is "swqueue\0" in ASCII).
const ENQUEUE_LOCK: i64 = 0x7377_7175_6575_6500;

/// The columns [`Job::from_row`] reads (a macro so that statements stay `&'static str`).
macro_rules! job_columns {
    () => {
        "id, user_id, kind, prompt, seed, options, parent_scene_id, state, stage, attempts, max_attempts, worker, lease_until, timeout_ms, created_at, started_at, finished_at, error, scene_id, completions"
    };
}

impl Store {
    /// Adds a job to the queue unless the queue is full (checked and inserted atomically),
    /// with its `queued` event in the same transaction: no runner can claim the job, and
    /// append `started`, before the stream begins with `queued`.
    ///
    /// Enqueues are serialised, so the cap is exact: SQLite's writer lock does it (the
    /// first statement writes), and on PostgreSQL a transaction-scoped advisory lock does —
    /// under READ COMMITTED two transactions would otherwise both count the same free
    /// place and both insert.
    pub async fn enqueue(&self, new: &NewJob, limits: QueueLimits) -> Result<Job> {
        let mut jobs = self.enqueue_all(std::slice::from_ref(new), limits).await?;
        jobs.pop().ok_or_else(|| StoreError::Corrupt("no job after insert".into()))
    }

    /// Enqueues every job of `news` or none of them (variations of one request): the caps
    /// are checked for each as it is inserted, in one transaction.
    pub async fn enqueue_all(&self, news: &[NewJob], limits: QueueLimits) -> Result<Vec<Job>> {
        let mut tx = self.pool.begin().await?;
        let mut ids = Vec::with_capacity(news.len());
        for new in news {
            ids.push(self.insert_job(&mut tx, new, limits).await?);
        }
        tx.commit().await?;
        let mut jobs = Vec::with_capacity(ids.len());
        for id in ids {
            jobs.push(
                self.job(&id).await?.ok_or_else(|| StoreError::Corrupt(format!("job {id} vanished after insert")))?,
            );
        }
        Ok(jobs)
    }

    /// [`Store::enqueue`]'s work inside a transaction the caller commits (so that other rows
    /// can be written with the job, atomically); the new job's id. On
    /// [`StoreError::QueueFull`] nothing was written (drop the transaction).
    pub(crate) async fn insert_job(
        &self,
        tx: &mut sqlx::Transaction<'static, sqlx::Any>,
        new: &NewJob,
        limits: QueueLimits,
    ) -> Result<String> {
        let id = new_id();
        let now = now_ms();
        let options = new.options.to_string();
        if self.backend == crate::Backend::Postgres {
            // Held until commit or rollback; the count below is a new snapshot taken after it.
            sqlx::query("SELECT pg_advisory_xact_lock($1)").bind(ENQUEUE_LOCK).execute(&mut **tx).await?;
        }
        let prompt_id = new_id();
        sqlx::query("INSERT INTO prompts (id, user_id, text, created_at) VALUES ($1, $2, $3, $4)")
            .bind(&prompt_id)
            .bind(&new.user_id)
            .bind(&new.prompt)
            .bind(now)
            .execute(&mut **tx)
            .await?;
        let done = sqlx::query(
            "INSERT INTO jobs (id, user_id, kind, prompt_id, prompt, seed, options, parent_scene_id, state, max_attempts, timeout_ms, created_at, qseq)
             SELECT $1, $2, $3, $4, $5, $6, $7, $8, 'queued', $9, $10, $11, (SELECT COALESCE(MAX(qseq), 0) + 1 FROM jobs)
             WHERE (SELECT COUNT(*) FROM jobs WHERE state = 'queued') < $12
               AND (SELECT COUNT(*) FROM jobs WHERE state = 'queued' AND user_id = $13) < $14",
        )
        .bind(&id)
        .bind(&new.user_id)
        .bind(new.kind.as_str())
        .bind(&prompt_id)
        .bind(&new.prompt)
        .bind(new.seed as i64)
        .bind(&options)
        .bind(&new.parent_scene_id)
        .bind(new.max_attempts.max(1))
        .bind(new.timeout_ms)
        .bind(now)
        .bind(limits.queue_cap)
        .bind(&new.user_id)
        .bind(limits.per_user_queued)
        .execute(&mut **tx)
        .await?;
        if done.rows_affected() == 0 {
            // Which cap: the whole queue, else the user's share of it.
            let (all,): (i64,) =
                sqlx::query_as("SELECT COUNT(*) FROM jobs WHERE state = 'queued'").fetch_one(&mut **tx).await?;
            return Err(if all >= limits.queue_cap {
                StoreError::QueueFull { cap: limits.queue_cap, per_user: false }
            } else {
                StoreError::QueueFull { cap: limits.per_user_queued, per_user: true }
            });
        }
        push_event(&mut **tx, &id, &serde_json::json!({"event": "queued", "job_id": id})).await?;
        Ok(id)
    }

    /// Any job by id.
    pub async fn job(&self, id: &str) -> Result<Option<Job>> {
        let row = sqlx::query(concat!("SELECT ", job_columns!(), " FROM jobs WHERE id = $1"))
            .bind(id)
            .fetch_optional(&self.pool)
            .await?;
        row.as_ref().map(Job::from_row).transpose()
    }

    /// A job if `user_id` owns it (`None` both when it does not exist and when it is another's).
    pub async fn job_of(&self, id: &str, user_id: &str) -> Result<Option<Job>> {
        Ok(self.job(id).await?.filter(|j| j.user_id == user_id))
    }

    /// The user's jobs, newest first.
    pub async fn jobs_of(&self, user_id: &str, limit: i64) -> Result<Vec<Job>> {
        let rows = sqlx::query(concat!(
            "SELECT ",
            job_columns!(),
            " FROM jobs WHERE user_id = $1 ORDER BY created_at DESC LIMIT $2"
        ))
        .bind(user_id)
        .bind(limit)
        .fetch_all(&self.pool)
        .await?;
        rows.iter().map(Job::from_row).collect()
    }

    /// Every job (for checks and benchmarks).
    pub async fn all_jobs(&self) -> Result<Vec<Job>> {
        let rows = sqlx::query(concat!("SELECT ", job_columns!(), " FROM jobs ORDER BY created_at"))
            .fetch_all(&self.pool)
            .await?;
        rows.iter().map(Job::from_row).collect()
    }

    /// Claims a queued job whose owner runs fewer than `per_user_running` jobs, with a
    /// lease of `lease_ms`. One statement: two claimers never get the same job.
    ///
    /// Users are served in turn, not in arrival order: a job's rank is how many jobs of its
    /// owner run or wait ahead of it, and the lowest rank goes first (arrival order among
    /// equals). A user who queued fifty jobs gets one runner after another user's single
    /// job has had its turn, not fifty runners before it.
    pub async fn claim(&self, worker: &str, lease_ms: i64, limits: QueueLimits) -> Result<Option<Claim>> {
        let now = now_ms();
        let sql = match self.backend {
            crate::Backend::Sqlite => concat!(
                "UPDATE jobs SET state = 'running', worker = $1, lease_until = $2, attempts = attempts + 1, started_at = $3, stage = NULL
                 WHERE id = (
                    SELECT q.id FROM jobs q
                    WHERE q.state = 'queued'
                      AND (SELECT COUNT(*) FROM jobs r WHERE r.user_id = q.user_id AND r.state = 'running') < $4
                    ORDER BY (SELECT COUNT(*) FROM jobs r WHERE r.user_id = q.user_id
                                AND (r.state = 'running' OR (r.state = 'queued' AND r.qseq < q.qseq))),
                             q.qseq, q.id LIMIT 1)
                   AND state = 'queued'
                 RETURNING ",
                job_columns!()
            ),
            // Concurrent claimers skip each other's locked rows instead of queueing on them.
            crate::Backend::Postgres => concat!(
                "UPDATE jobs SET state = 'running', worker = $1, lease_until = $2, attempts = attempts + 1, started_at = $3, stage = NULL
                 WHERE id = (
                    SELECT q.id FROM jobs q
                    WHERE q.state = 'queued'
                      AND (SELECT COUNT(*) FROM jobs r WHERE r.user_id = q.user_id AND r.state = 'running') < $4
                    ORDER BY (SELECT COUNT(*) FROM jobs r WHERE r.user_id = q.user_id
                                AND (r.state = 'running' OR (r.state = 'queued' AND r.qseq < q.qseq))),
                             q.qseq, q.id LIMIT 1
                    FOR UPDATE SKIP LOCKED)
                   AND state = 'queued'
                 RETURNING ",
                job_columns!()
            ),
        };
        let row = sqlx::query(sql)
            .bind(worker)
            .bind(now + lease_ms)
            .bind(now)
            .bind(limits.per_user_running)
            .fetch_optional(&self.pool)
            .await?;
        match row {
            None => Ok(None),
            Some(r) => {
                let job = Job::from_row(&r)?;
                let attempt = job.attempts;
                Ok(Some(Claim { job, worker: worker.to_string(), attempt }))
            }
        }
    }

    /// Renews a claim's lease; `false` when the claim is no longer the runner's (the job
    /// was cancelled, failed by a timeout, or taken over after the lease expired).
    pub async fn heartbeat(&self, claim: &Claim, lease_ms: i64) -> Result<bool> {
        let r = sqlx::query(
            "UPDATE jobs SET lease_until = $1 WHERE id = $2 AND worker = $3 AND attempts = $4 AND state = 'running'",
        )
        .bind(now_ms() + lease_ms)
        .bind(&claim.job.id)
        .bind(&claim.worker)
        .bind(claim.attempt)
        .execute(&self.pool)
        .await?;
        Ok(r.rows_affected() == 1)
    }

    /// True while the claim is still the runner's (a read: the job was not cancelled,
    /// failed by a timeout, or taken over).
    pub async fn still_running(&self, claim: &Claim) -> Result<bool> {
        let r: Option<(String,)> =
            sqlx::query_as("SELECT id FROM jobs WHERE id = $1 AND worker = $2 AND attempts = $3 AND state = 'running'")
                .bind(&claim.job.id)
                .bind(&claim.worker)
                .bind(claim.attempt)
                .fetch_optional(&self.pool)
                .await?;
        Ok(r.is_some())
    }

    /// Records the stage a claimed job is in.
    pub async fn set_stage(&self, claim: &Claim, stage: &str) -> Result<()> {
        sqlx::query("UPDATE jobs SET stage = $1 WHERE id = $2 AND worker = $3 AND attempts = $4 AND state = 'running'")
            .bind(stage)
            .bind(&claim.job.id)
            .bind(&claim.worker)
            .bind(claim.attempt)
            .execute(&self.pool)
            .await?;
        Ok(())
    }

    /// Fails a claimed job with a reason (and its `error` event); `false` if the claim was
    /// no longer the runner's.
    pub async fn fail(&self, claim: &Claim, reason: &str) -> Result<bool> {
        let mut tx = self.pool.begin().await?;
        let r = sqlx::query(
            "UPDATE jobs SET state = 'failed', error = $1, finished_at = $2, lease_until = NULL
             WHERE id = $3 AND worker = $4 AND attempts = $5 AND state = 'running'",
        )
        .bind(reason)
        .bind(now_ms())
        .bind(&claim.job.id)
        .bind(&claim.worker)
        .bind(claim.attempt)
        .execute(&mut *tx)
        .await?;
        if r.rows_affected() != 1 {
            tx.rollback().await?;
            return Ok(false);
        }
        push_event(&mut *tx, &claim.job.id, &serde_json::json!({"event": "error", "message": reason})).await?;
        tx.commit().await?;
        Ok(true)
    }

    /// Gives a claimed job back to the queue at once (this process is stopping): it runs
    /// again, first in its owner's turn, and the claim does not count as a lost attempt.
    /// `false` if the claim was no longer the runner's.
    pub async fn release(&self, claim: &Claim, reason: &str) -> Result<bool> {
        let mut tx = self.pool.begin().await?;
        let r = sqlx::query(
            "UPDATE jobs SET state = 'queued', worker = NULL, lease_until = NULL, stage = NULL,
                 attempts = attempts - 1
             WHERE id = $1 AND worker = $2 AND attempts = $3 AND state = 'running'",
        )
        .bind(&claim.job.id)
        .bind(&claim.worker)
        .bind(claim.attempt)
        .execute(&mut *tx)
        .await?;
        if r.rows_affected() != 1 {
            tx.rollback().await?;
            return Ok(false);
        }
        push_event(&mut *tx, &claim.job.id, &serde_json::json!({"event": "requeued", "reason": reason})).await?;
        tx.commit().await?;
        Ok(true)
    }

    /// Cancels the user's job if it has not finished: a queued job never runs, a running
    /// one's result is discarded. Returns the job's state afterwards, `None` if the user
    /// has no such job.
    pub async fn cancel(&self, id: &str, user_id: &str) -> Result<Option<JobState>> {
        let mut tx = self.pool.begin().await?;
        let r = sqlx::query(
            "UPDATE jobs SET state = 'cancelled', finished_at = $1, error = 'cancelled by the user', lease_until = NULL
             WHERE id = $2 AND user_id = $3 AND state IN ('queued', 'running')",
        )
        .bind(now_ms())
        .bind(id)
        .bind(user_id)
        .execute(&mut *tx)
        .await?;
        if r.rows_affected() == 1 {
            push_event(&mut *tx, id, &serde_json::json!({"event": "cancelled"})).await?;
        }
        tx.commit().await?;
        Ok(self.job_of(id, user_id).await?.map(|j| j.state))
    }

    /// Puts jobs whose runner's lease expired back in the queue (or fails them when they
    /// used their attempts) and fails running jobs past their timeout. Idempotent; safe to
    /// run from every process at once.
    pub async fn recover(&self) -> Result<Recovered> {
        let now = now_ms();
        let mut out = Recovered::default();
        let mut tx = self.pool.begin().await?;
        let timed_out: Vec<(String,)> = sqlx::query_as(
            "UPDATE jobs SET state = 'failed', finished_at = $1, lease_until = NULL,
                 error = 'timed out after ' || (timeout_ms / 1000) || ' s'
             WHERE state = 'running' AND started_at + timeout_ms < $2
             RETURNING id",
        )
        .bind(now)
        .bind(now)
        .fetch_all(&mut *tx)
        .await?;
        out.failed.extend(timed_out.into_iter().map(|r| r.0));
        let exhausted: Vec<(String,)> = sqlx::query_as(
            "UPDATE jobs SET state = 'failed', finished_at = $1, lease_until = NULL,
                 error = 'its runner was lost (crashed or stopped) ' || attempts || ' time(s); not retried again'
             WHERE state = 'running' AND lease_until < $2 AND attempts >= max_attempts
             RETURNING id",
        )
        .bind(now)
        .bind(now)
        .fetch_all(&mut *tx)
        .await?;
        out.failed.extend(exhausted.into_iter().map(|r| r.0));
        let requeued: Vec<(String,)> = sqlx::query_as(
            "UPDATE jobs SET state = 'queued', worker = NULL, lease_until = NULL, stage = NULL
             WHERE state = 'running' AND lease_until < $1 AND attempts < max_attempts
             RETURNING id",
        )
        .bind(now)
        .fetch_all(&mut *tx)
        .await?;
        out.requeued.extend(requeued.into_iter().map(|r| r.0));
        for id in &out.failed {
            let (reason,): (Option<String>,) =
                sqlx::query_as("SELECT error FROM jobs WHERE id = $1").bind(id).fetch_one(&mut *tx).await?;
            push_event(&mut *tx, id, &serde_json::json!({"event": "error", "message": reason})).await?;
        }
        for id in &out.requeued {
            let ev = serde_json::json!({"event": "requeued", "reason": "its runner was lost; the job runs again"});
            push_event(&mut *tx, id, &ev).await?;
        }
        tx.commit().await?;
        Ok(out)
    }

    /// Jobs per state.
    pub async fn count_by_state(&self) -> Result<Vec<(JobState, i64)>> {
        let rows: Vec<(String, i64)> =
            sqlx::query_as("SELECT state, COUNT(*) FROM jobs GROUP BY state").fetch_all(&self.pool).await?;
        Ok(JobState::ALL
            .into_iter()
            .map(|s| (s, rows.iter().find(|r| r.0 == s.as_str()).map(|r| r.1).unwrap_or(0)))
            .collect())
    }

    /// Appends an event to a job's stream; returns its sequence number (from 1).
    pub async fn append_event(&self, job_id: &str, body: &serde_json::Value) -> Result<i64> {
        push_event(&self.pool, job_id, body).await
    }

    /// A job's events after `seq`, in order.
    pub async fn events_after(&self, job_id: &str, seq: i64) -> Result<Vec<(i64, serde_json::Value)>> {
        let rows: Vec<(i64, String)> =
            sqlx::query_as("SELECT seq, body FROM job_events WHERE job_id = $1 AND seq > $2 ORDER BY seq")
                .bind(job_id)
                .bind(seq)
                .fetch_all(&self.pool)
                .await?;
        rows.into_iter()
            .map(|(s, b)| {
                serde_json::from_str(&b).map(|v| (s, v)).map_err(|e| StoreError::Corrupt(format!("event: {e}")))
            })
            .collect()
    }
}

/// Appends an event in a connection or transaction (terminal transitions append theirs in
/// the same transaction, so a job's stream is complete once its state is terminal).
pub(crate) async fn push_event<'e, E>(e: E, job_id: &str, body: &serde_json::Value) -> Result<i64>
where
    E: sqlx::Executor<'e, Database = sqlx::Any>,
{
    let (seq,): (i64,) = sqlx::query_as(
        "INSERT INTO job_events (job_id, seq, at, body)
         VALUES ($1, (SELECT COALESCE(MAX(seq), 0) + 1 FROM job_events WHERE job_id = $2), $3, $4)
         RETURNING seq",
    )
    .bind(job_id)
    .bind(job_id)
    .bind(now_ms())
    .bind(body.to_string())
    .fetch_one(e)
    .await?;
    Ok(seq)
}
