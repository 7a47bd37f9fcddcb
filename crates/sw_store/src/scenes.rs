//! Scenes (versions of a package in the blob store), their edit history, asset metadata,
//! telemetry, and the completion of a job that made a scene.

use serde::Serialize;

use crate::{Claim, Result, Store, StoreError, new_id, now_ms};

/// A scene: one version of a package.
#[derive(Debug, Clone, Serialize)]
pub struct Scene {
    pub id: String,
    #[serde(skip)]
    pub user_id: String,
    pub job_id: String,
    /// The version this one was edited from.
    pub parent_id: Option<String>,
    pub version: i64,
    pub prompt: String,
    /// The verification status from report.json ("verified", "failed", "unverified").
    pub status: String,
    pub report: serde_json::Value,
    /// The package's files (paths relative to the package).
    pub files: Vec<String>,
    pub created_at: i64,
}

type SceneRow = (String, String, String, Option<String>, i64, String, String, String, String, i64);
/// A scene row and the command of the edit that made it.
type VersionRow = (String, String, String, Option<String>, i64, String, String, String, String, i64, Option<String>);

fn scene(r: SceneRow) -> Result<Scene> {
    Ok(Scene {
        id: r.0,
        user_id: r.1,
        job_id: r.2,
        parent_id: r.3,
        version: r.4,
        prompt: r.5,
        status: r.6,
        report: serde_json::from_str(&r.7).map_err(|e| StoreError::Corrupt(format!("scene report: {e}")))?,
        files: serde_json::from_str(&r.8).map_err(|e| StoreError::Corrupt(format!("scene files: {e}")))?,
        created_at: r.9,
    })
}

/// What a finished job made.
#[derive(Debug, Clone)]
pub struct NewScene {
    /// Chosen by the runner (the blobs are written under it before completion).
    pub id: String,
    pub status: String,
    pub report: serde_json::Value,
    pub files: Vec<String>,
    /// The SHA-256 (hex) of each file, by path: what is served is checked against it.
    pub hashes: Vec<(String, String)>,
    /// For an edit: the command and its record (edits.json's entry).
    pub edit: Option<(String, serde_json::Value)>,
}

/// Measurements of a run, stored with its completion.
#[derive(Debug, Clone, Default)]
pub struct Telemetry {
    /// Wall-clock ms per stage.
    pub stages: Vec<(String, f64)>,
    /// LLM calls: (stage, ms, tokens in, tokens out).
    pub llm_calls: Vec<(String, f64, i64, i64)>,
    /// Asset cache lookups: (hits, misses).
    pub cache: Option<(i64, i64)>,
}

/// An edit of a scene.
#[derive(Debug, Clone, Serialize)]
pub struct EditRecord {
    pub id: String,
    pub scene_id: String,
    pub new_scene_id: String,
    pub command: String,
    pub record: serde_json::Value,
    pub created_at: i64,
}

/// Asset metadata owned by a user.
#[derive(Debug, Clone, Serialize)]
pub struct Asset {
    pub id: String,
    #[serde(skip)]
    pub user_id: String,
    pub description: String,
    pub category: Option<String>,
    pub meta: serde_json::Value,
    pub created_at: i64,
}

/// Totals of one telemetry series.
#[derive(Debug, Clone, PartialEq)]
pub struct StageStat {
    pub kind: String,
    pub name: String,
    pub count: i64,
    pub sum_ms: f64,
    pub tokens_in: i64,
    pub tokens_out: i64,
}

impl Store {
    /// Completes a claimed job with the scene it made, its telemetry and (for an edit) the
    /// edit record — all in one transaction, and only if the claim is still the runner's.
    /// Returns `false` (and stores nothing) otherwise: the job was cancelled, timed out, or
    /// taken over after this runner's lease expired.
    /// The job's `finished` event is appended in the same transaction.
    pub async fn complete(&self, claim: &Claim, new: &NewScene, telemetry: &Telemetry) -> Result<bool> {
        let now = now_ms();
        let job = &claim.job;
        let mut tx = self.pool.begin().await?;
        let r = sqlx::query(
            "UPDATE jobs SET state = 'succeeded', finished_at = $1, scene_id = $2, lease_until = NULL, completions = completions + 1
             WHERE id = $3 AND worker = $4 AND attempts = $5 AND state = 'running'",
        )
        .bind(now)
        .bind(&new.id)
        .bind(&job.id)
        .bind(&claim.worker)
        .bind(claim.attempt)
        .execute(&mut *tx)
        .await?;
        if r.rows_affected() != 1 {
            tx.rollback().await?;
            return Ok(false);
        }
        let version: i64 = match &job.parent_scene_id {
            None => 1,
            Some(p) => {
                let (v,): (i64,) =
                    sqlx::query_as("SELECT version FROM scenes WHERE id = $1").bind(p).fetch_one(&mut *tx).await?;
                v + 1
            }
        };
        sqlx::query(
            "INSERT INTO scenes (id, user_id, job_id, parent_id, version, prompt, status, report, files, created_at)
             VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10)",
        )
        .bind(&new.id)
        .bind(&job.user_id)
        .bind(&job.id)
        .bind(&job.parent_scene_id)
        .bind(version)
        .bind(&job.prompt)
        .bind(&new.status)
        .bind(new.report.to_string())
        .bind(serde_json::Value::from(new.files.clone()).to_string())
        .bind(now)
        .execute(&mut *tx)
        .await?;
        for (path, sha256) in &new.hashes {
            sqlx::query("INSERT INTO scene_files (scene_id, path, sha256) VALUES ($1, $2, $3)")
                .bind(&new.id)
                .bind(path)
                .bind(sha256)
                .execute(&mut *tx)
                .await?;
        }
        if let (Some((command, record)), Some(parent)) = (&new.edit, &job.parent_scene_id) {
            sqlx::query(
                "INSERT INTO edits (id, user_id, scene_id, new_scene_id, command, record, created_at) VALUES ($1, $2, $3, $4, $5, $6, $7)",
            )
            .bind(new_id())
            .bind(&job.user_id)
            .bind(parent)
            .bind(&new.id)
            .bind(command)
            .bind(record.to_string())
            .bind(now)
            .execute(&mut *tx)
            .await?;
        }
        let mut rows: Vec<(&str, &str, f64, i64, i64)> = Vec::new();
        for (stage, ms) in &telemetry.stages {
            rows.push(("stage", stage, *ms, 0, 0));
        }
        for (stage, ms, tin, tout) in &telemetry.llm_calls {
            rows.push(("llm", stage, *ms, *tin, *tout));
        }
        if let Some((hits, misses)) = telemetry.cache {
            rows.push(("cache", "hit", 0.0, hits, 0));
            rows.push(("cache", "miss", 0.0, misses, 0));
        }
        let wait = job.started_at.map(|s| (s - job.created_at) as f64).unwrap_or(0.0);
        rows.push(("job", "queue_wait", wait, 0, 0));
        rows.push(("job", "run", job.started_at.map(|s| (now - s) as f64).unwrap_or(0.0), 0, 0));
        for (kind, name, ms, a, b) in rows {
            sqlx::query(
                "INSERT INTO telemetry (job_id, kind, name, ms, tokens_in, tokens_out, at) VALUES ($1, $2, $3, $4, $5, $6, $7)",
            )
            .bind(&job.id)
            .bind(kind)
            .bind(name)
            .bind(ms)
            .bind(a)
            .bind(b)
            .bind(now)
            .execute(&mut *tx)
            .await?;
        }
        let finished = serde_json::json!({
            "event": "finished", "scene_id": new.id, "status": new.status, "files": new.files,
        });
        crate::jobs::push_event(&mut *tx, &job.id, &finished).await?;
        tx.commit().await?;
        Ok(true)
    }

    /// A scene if `user_id` owns it.
    /// The SHA-256 recorded for a file of a scene when it was stored (`None` for scenes
    /// stored before checksums were kept, and for paths the scene does not have).
    pub async fn file_hash(&self, scene_id: &str, path: &str) -> Result<Option<String>> {
        let r: Option<(String,)> = sqlx::query_as("SELECT sha256 FROM scene_files WHERE scene_id = $1 AND path = $2")
            .bind(scene_id)
            .bind(path)
            .fetch_optional(&self.pool)
            .await?;
        Ok(r.map(|r| r.0))
    }

    /// Every stored checksum of a scene's files, by path.
    pub async fn file_hashes(&self, scene_id: &str) -> Result<std::collections::BTreeMap<String, String>> {
        let rows: Vec<(String, String)> = sqlx::query_as("SELECT path, sha256 FROM scene_files WHERE scene_id = $1")
            .bind(scene_id)
            .fetch_all(&self.pool)
            .await?;
        Ok(rows.into_iter().collect())
    }

    pub async fn scene_of(&self, id: &str, user_id: &str) -> Result<Option<Scene>> {
        let r: Option<SceneRow> = sqlx::query_as(
            "SELECT id, user_id, job_id, parent_id, version, prompt, status, report, files, created_at
             FROM scenes WHERE id = $1 AND user_id = $2",
        )
        .bind(id)
        .bind(user_id)
        .fetch_optional(&self.pool)
        .await?;
        r.map(scene).transpose()
    }

    /// The user's scenes, newest first.
    pub async fn scenes_of(&self, user_id: &str, limit: i64) -> Result<Vec<Scene>> {
        let rows: Vec<SceneRow> = sqlx::query_as(
            "SELECT id, user_id, job_id, parent_id, version, prompt, status, report, files, created_at
             FROM scenes WHERE user_id = $1 ORDER BY created_at DESC, id LIMIT $2",
        )
        .bind(user_id)
        .bind(limit)
        .fetch_all(&self.pool)
        .await?;
        rows.into_iter().map(scene).collect()
    }

    /// Every version in a scene's lineage (its first version, every edit of it and of its
    /// edits, branches included), oldest first, each with the command that made it (none
    /// for the first); empty when `user_id` does not own the scene.
    pub async fn scene_versions(&self, id: &str, user_id: &str) -> Result<Vec<(Scene, Option<String>)>> {
        // Up to the first version (each step is one owned row; lineages are short).
        let Some(mut first) = self.scene_of(id, user_id).await? else { return Ok(Vec::new()) };
        let mut seen = std::collections::BTreeSet::new();
        while let Some(parent) = first.parent_id.clone() {
            if !seen.insert(parent.clone()) {
                return Err(StoreError::Corrupt(format!("scene {parent} is its own ancestor")));
            }
            match self.scene_of(&parent, user_id).await? {
                Some(p) => first = p,
                None => break,
            }
        }
        let rows: Vec<VersionRow> =
            sqlx::query_as(
                "WITH RECURSIVE lineage(id) AS (
                     SELECT id FROM scenes WHERE id = $1 AND user_id = $2
                     UNION ALL
                     SELECT s.id FROM scenes s JOIN lineage l ON s.parent_id = l.id WHERE s.user_id = $3)
                 SELECT s.id, s.user_id, s.job_id, s.parent_id, s.version, s.prompt, s.status, s.report, s.files, s.created_at,
                        (SELECT e.command FROM edits e WHERE e.new_scene_id = s.id ORDER BY e.created_at LIMIT 1)
                 FROM scenes s WHERE s.id IN (SELECT id FROM lineage) ORDER BY s.version, s.created_at, s.id",
            )
            .bind(&first.id)
            .bind(user_id)
            .bind(user_id)
            .fetch_all(&self.pool)
            .await?;
        rows.into_iter()
            .map(|r| {
                let command = r.10.clone();
                Ok((scene((r.0, r.1, r.2, r.3, r.4, r.5, r.6, r.7, r.8, r.9))?, command))
            })
            .collect()
    }

    /// Deletes a scene with every version of its lineage (its first version and all
    /// edits of it), in one transaction; the ids deleted, for the caller to remove their
    /// files. Empty when `user_id` owns no such scene.
    pub async fn delete_lineage(&self, id: &str, user_id: &str) -> Result<Vec<String>> {
        let mut versions = self.scene_versions(id, user_id).await?;
        // Later versions first: each row goes before the parent it references.
        versions.sort_by(|a, b| b.0.version.cmp(&a.0.version).then(b.0.created_at.cmp(&a.0.created_at)));
        let mut tx = self.pool.begin().await?;
        let mut ids = Vec::with_capacity(versions.len());
        for (sc, _) in &versions {
            sqlx::query("DELETE FROM edits WHERE (scene_id = $1 OR new_scene_id = $2) AND user_id = $3")
                .bind(&sc.id)
                .bind(&sc.id)
                .bind(user_id)
                .execute(&mut *tx)
                .await?;
            sqlx::query("DELETE FROM scene_files WHERE scene_id = $1").bind(&sc.id).execute(&mut *tx).await?;
        }
        for (sc, _) in &versions {
            let r = sqlx::query("DELETE FROM scenes WHERE id = $1 AND user_id = $2")
                .bind(&sc.id)
                .bind(user_id)
                .execute(&mut *tx)
                .await?;
            if r.rows_affected() == 1 {
                ids.push(sc.id.clone());
            }
        }
        tx.commit().await?;
        Ok(ids)
    }

    /// The edits made from a scene or leading to it.
    pub async fn edits_of_scene(&self, scene_id: &str, user_id: &str) -> Result<Vec<EditRecord>> {
        let rows: Vec<(String, String, String, String, String, i64)> = sqlx::query_as(
            "SELECT id, scene_id, new_scene_id, command, record, created_at FROM edits
             WHERE user_id = $1 AND (scene_id = $2 OR new_scene_id = $3) ORDER BY created_at",
        )
        .bind(user_id)
        .bind(scene_id)
        .bind(scene_id)
        .fetch_all(&self.pool)
        .await?;
        rows.into_iter()
            .map(|r| {
                Ok(EditRecord {
                    id: r.0,
                    scene_id: r.1,
                    new_scene_id: r.2,
                    command: r.3,
                    record: serde_json::from_str(&r.4).map_err(|e| StoreError::Corrupt(format!("edit: {e}")))?,
                    created_at: r.5,
                })
            })
            .collect()
    }

    /// Stores asset metadata for a user.
    pub async fn create_asset(
        &self,
        user_id: &str,
        description: &str,
        category: Option<&str>,
        meta: &serde_json::Value,
    ) -> Result<Asset> {
        let a = Asset {
            id: new_id(),
            user_id: user_id.to_string(),
            description: description.to_string(),
            category: category.map(str::to_string),
            meta: meta.clone(),
            created_at: now_ms(),
        };
        sqlx::query(
            "INSERT INTO assets (id, user_id, description, category, meta, created_at) VALUES ($1, $2, $3, $4, $5, $6)",
        )
        .bind(&a.id)
        .bind(&a.user_id)
        .bind(&a.description)
        .bind(&a.category)
        .bind(a.meta.to_string())
        .bind(a.created_at)
        .execute(&self.pool)
        .await?;
        Ok(a)
    }

    /// The user's assets whose description or category contains `q` (all when empty).
    pub async fn assets_of(&self, user_id: &str, q: &str) -> Result<Vec<Asset>> {
        let pattern = format!("%{}%", q.replace('\\', "\\\\").replace('%', "\\%").replace('_', "\\_"));
        let rows: Vec<(String, String, String, Option<String>, String, i64)> = sqlx::query_as(
            "SELECT id, user_id, description, category, meta, created_at FROM assets
             WHERE user_id = $1 AND (description LIKE $2 ESCAPE '\\' OR COALESCE(category, '') LIKE $3 ESCAPE '\\')
             ORDER BY created_at DESC",
        )
        .bind(user_id)
        .bind(&pattern)
        .bind(&pattern)
        .fetch_all(&self.pool)
        .await?;
        rows.into_iter()
            .map(|r| {
                Ok(Asset {
                    id: r.0,
                    user_id: r.1,
                    description: r.2,
                    category: r.3,
                    meta: serde_json::from_str(&r.4).map_err(|e| StoreError::Corrupt(format!("asset: {e}")))?,
                    created_at: r.5,
                })
            })
            .collect()
    }

    /// One asset if `user_id` owns it.
    pub async fn asset_of(&self, id: &str, user_id: &str) -> Result<Option<Asset>> {
        Ok(self.assets_of(user_id, "").await?.into_iter().find(|a| a.id == id))
    }

    /// Totals per telemetry series (stage latencies, LLM calls, cache, queue wait).
    pub async fn telemetry_totals(&self) -> Result<Vec<StageStat>> {
        let rows: Vec<(String, String, i64, f64, i64, i64)> = sqlx::query_as(
            "SELECT kind, name, COUNT(*), CAST(SUM(ms) AS DOUBLE PRECISION), CAST(SUM(tokens_in) AS BIGINT), CAST(SUM(tokens_out) AS BIGINT)
             FROM telemetry GROUP BY kind, name ORDER BY kind, name",
        )
        .fetch_all(&self.pool)
        .await?;
        Ok(rows
            .into_iter()
            .map(|r| StageStat { kind: r.0, name: r.1, count: r.2, sum_ms: r.3, tokens_in: r.4, tokens_out: r.5 })
            .collect())
    }
}
