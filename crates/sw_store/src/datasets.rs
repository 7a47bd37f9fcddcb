//! Datasets on the job queue (`scenewright dataset --database`): every scene slot of a
//! dataset is made by one job at a time, and every structural fingerprint belongs to one
//! slot — so across any number of workers on any number of machines each slot ends with
//! one scene and no two slots with the same scene.
//!
//! A slot's job is enqueued in the same transaction that records it as the slot's job, so
//! a crash between the two cannot leave a job nobody counts or a slot counted twice. A
//! slot whose job failed gets a new job only when the dataset's leader asks again (on
//! resume).

use sqlx::Row;

use crate::jobs::{Job, NewJob, QueueLimits};
use crate::{Result, Store, StoreError, now_ms};

/// A slot of a dataset and the job that makes (or made) its scene.
#[derive(Debug, Clone)]
pub struct DatasetSlot {
    pub slot: String,
    pub job: Job,
}

impl Store {
    /// Records the dataset `id` with `spec` (JSON) if new; returns the spec stored for it
    /// (the caller checks it is the same dataset).
    pub async fn open_dataset(&self, id: &str, spec: &str) -> Result<String> {
        sqlx::query(
            "INSERT INTO datasets (id, spec, created_at) SELECT $1, $2, $3
             WHERE NOT EXISTS (SELECT 1 FROM datasets WHERE id = $4)",
        )
        .bind(id)
        .bind(spec)
        .bind(now_ms())
        .bind(id)
        .execute(&self.pool)
        .await?;
        let row = sqlx::query("SELECT spec FROM datasets WHERE id = $1").bind(id).fetch_one(&self.pool).await?;
        Ok(row.try_get("spec")?)
    }

    /// Enqueues `new` as the job of `slot` (replacing the slot's earlier job, which must
    /// have ended), atomically. [`StoreError::QueueFull`] when the queue is full.
    pub async fn enqueue_dataset_slot(
        &self,
        dataset: &str,
        slot: &str,
        new: &NewJob,
        limits: QueueLimits,
    ) -> Result<Job> {
        let mut tx = self.pool.begin().await?;
        let id = self.insert_job(&mut tx, new, limits).await?;
        sqlx::query("DELETE FROM dataset_slots WHERE dataset_id = $1 AND slot = $2")
            .bind(dataset)
            .bind(slot)
            .execute(&mut *tx)
            .await?;
        sqlx::query("INSERT INTO dataset_slots (dataset_id, slot, job_id) VALUES ($1, $2, $3)")
            .bind(dataset)
            .bind(slot)
            .bind(&id)
            .execute(&mut *tx)
            .await?;
        tx.commit().await?;
        self.job(&id).await?.ok_or_else(|| StoreError::Corrupt(format!("job {id} vanished after insert")))
    }

    /// Every slot of the dataset that has a job, with its job, by slot.
    pub async fn dataset_slots(&self, dataset: &str) -> Result<Vec<DatasetSlot>> {
        let rows = sqlx::query("SELECT slot, job_id FROM dataset_slots WHERE dataset_id = $1 ORDER BY slot")
            .bind(dataset)
            .fetch_all(&self.pool)
            .await?;
        let mut out = Vec::with_capacity(rows.len());
        for r in rows {
            let slot: String = r.try_get("slot")?;
            let job_id: String = r.try_get("job_id")?;
            let job =
                self.job(&job_id).await?.ok_or_else(|| StoreError::Corrupt(format!("slot {slot}: job {job_id}")))?;
            out.push(DatasetSlot { slot, job });
        }
        Ok(out)
    }

    /// Takes `fingerprint` for `slot` of the dataset: true when it is now (or already was)
    /// the slot's, false when another slot holds it (the scene is a duplicate).
    pub async fn claim_fingerprint(&self, dataset: &str, fingerprint: &str, slot: &str) -> Result<bool> {
        sqlx::query(
            "INSERT INTO dataset_fingerprints (dataset_id, fingerprint, slot) VALUES ($1, $2, $3)
             ON CONFLICT (dataset_id, fingerprint) DO NOTHING",
        )
        .bind(dataset)
        .bind(fingerprint)
        .bind(slot)
        .execute(&self.pool)
        .await?;
        let row = sqlx::query("SELECT slot FROM dataset_fingerprints WHERE dataset_id = $1 AND fingerprint = $2")
            .bind(dataset)
            .bind(fingerprint)
            .fetch_one(&self.pool)
            .await?;
        let holder: String = row.try_get("slot")?;
        Ok(holder == slot)
    }

    /// The scene a job stored (its files), for the dataset's leader: no owner check (the
    /// leader made the jobs).
    pub async fn scene_files(&self, scene_id: &str) -> Result<Option<Vec<String>>> {
        let row =
            sqlx::query("SELECT files FROM scenes WHERE id = $1").bind(scene_id).fetch_optional(&self.pool).await?;
        match row {
            None => Ok(None),
            Some(r) => {
                let files: String = r.try_get("files")?;
                serde_json::from_str(&files).map(Some).map_err(|e| StoreError::Corrupt(format!("scene files: {e}")))
            }
        }
    }
}
