//! Jobs: submit, list, show, cancel; the admin's overview.

use axum::Json;
use axum::extract::{Path, State};
use axum::http::StatusCode;
use serde::Deserialize;
use serde_json::{Value, json};
use sw_store::{Job, JobKind, NewJob, is_id};

use crate::AppState;
use crate::auth::Caller;
use crate::body::Body;
use crate::error::{ApiError, ApiResult};

/// `POST /api/jobs`'s body.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JobRequest {
    prompt: String,
    #[serde(default)]
    seed: Option<u64>,
    /// Registry robot names to use instead of the prompt's (an empty list: none).
    #[serde(default)]
    robots: Option<Vec<String>>,
    #[serde(default)]
    options: Option<JobOptions>,
}

/// Pipeline options a job may set.
#[derive(Debug, Default, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct JobOptions {
    /// Compile and settle in MuJoCo (default true).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verify: Option<bool>,
    /// An industrial rules profile instead of the room kind's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rules: Option<String>,
    /// Labelled anomalies to inject (as `--anomaly KINDS --anomaly-rate R`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub anomaly: Option<sw_plan::AnomalyRequest>,
}

/// Checks a prompt or command: not blank, at most [`crate::PROMPT_LIMIT`] bytes.
pub fn check_text(what: &str, text: &str) -> ApiResult<()> {
    if text.len() > crate::PROMPT_LIMIT {
        return Err(ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            format!("the {what} is {} bytes; at most {} are accepted", text.len(), crate::PROMPT_LIMIT),
        ));
    }
    if text.trim().is_empty() {
        return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, format!("the {what} is empty")));
    }
    if text.contains('\0') {
        return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, format!("the {what} holds a NUL character")));
    }
    Ok(())
}

/// A job as the API shows it.
pub fn job_json(j: &Job) -> Value {
    let mut v = json!(j);
    v["queue_wait_ms"] = json!(j.queue_wait_ms());
    v
}

/// `POST /api/jobs` → 202 `{job_id, state}`; 429 when the queue is full.
pub async fn create(
    State(s): State<AppState>,
    caller: Caller,
    Body(r): Body<JobRequest>,
) -> ApiResult<(StatusCode, Json<Value>)> {
    check_text("prompt", &r.prompt)?;
    let opts = r.options.unwrap_or_default();
    if let Some(p) = &opts.rules
        && !sw_layout_profiles().contains(p)
    {
        return Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            format!("unknown rules profile '{p}' (known: {})", sw_layout_profiles().join(", ")),
        ));
    }
    if let Some(a) = &opts.anomaly
        && (a.kinds.is_empty() || !(a.rate > 0.0 && a.rate <= 1.0))
    {
        return Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            "anomaly: at least one kind, and a rate above 0 and at most 1",
        ));
    }
    if let Some(robots) = &r.robots {
        for name in robots {
            if sw_robots::find(name).is_none() {
                return Err(ApiError::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    format!("unknown robot '{name}' (see GET /api/robots)"),
                ));
            }
        }
    }
    let mut options = json!(opts);
    if let Some(robots) = &r.robots {
        options["robots"] = json!(robots);
    }
    let new = NewJob {
        user_id: caller.user.id.clone(),
        kind: JobKind::Generate,
        prompt: r.prompt,
        seed: r.seed.unwrap_or(0),
        options,
        parent_scene_id: None,
        timeout_ms: s.runner.job_timeout_ms,
        max_attempts: s.runner.max_attempts,
    };
    let job = s.store.enqueue(&new, s.limits).await?;
    s.wake.notify_one();
    tracing::info!(job = %job.id, user = %caller.user.id, "job queued");
    Ok((StatusCode::ACCEPTED, Json(json!({ "job_id": job.id, "state": job.state }))))
}

fn sw_layout_profiles() -> Vec<String> {
    sw_layout::rules::profile_names()
}

/// `GET /api/jobs` → the caller's jobs, newest first.
pub async fn list(State(s): State<AppState>, caller: Caller) -> ApiResult<Json<Value>> {
    let jobs = s.store.jobs_of(&caller.user.id, 200).await?;
    Ok(Json(json!({ "jobs": jobs.iter().map(job_json).collect::<Vec<_>>() })))
}

/// The caller's job, or 404 (also for another user's job).
pub async fn owned_job(s: &AppState, caller: &Caller, id: &str) -> ApiResult<Job> {
    if !is_id(id) {
        return Err(ApiError::not_found("job"));
    }
    s.store.job_of(id, &caller.user.id).await?.ok_or_else(|| ApiError::not_found("job"))
}

/// `GET /api/jobs/{id}` → status, stage, timings, scene id.
pub async fn show(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Json<Value>> {
    let job = owned_job(&s, &caller, &id).await?;
    Ok(Json(job_json(&job)))
}

/// `DELETE /api/jobs/{id}` → the job after cancelling (a finished job stays as it was).
pub async fn cancel(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Json<Value>> {
    let before = owned_job(&s, &caller, &id).await?;
    s.store.cancel(&id, &caller.user.id).await?.ok_or_else(|| ApiError::not_found("job"))?;
    if !before.state.is_terminal() {
        let _ = s.events.send(id.clone());
        tracing::info!(job = %id, "job cancelled");
    }
    let job = owned_job(&s, &caller, &id).await?;
    Ok(Json(job_json(&job)))
}

/// `GET /api/admin/jobs` (admins) → jobs per state and the newest jobs of everyone.
pub async fn admin_overview(State(s): State<AppState>, caller: Caller) -> ApiResult<Json<Value>> {
    if !caller.is_admin() {
        return Err(ApiError::new(StatusCode::FORBIDDEN, "this needs the admin role"));
    }
    let counts = s.store.count_by_state().await?;
    let by_state: serde_json::Map<String, Value> =
        counts.iter().map(|(k, n)| (k.as_str().to_string(), json!(n))).collect();
    Ok(Json(json!({ "by_state": by_state })))
}
