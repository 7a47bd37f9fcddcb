//! Jobs: submit, list, show, cancel; the admin's overview.

use axum::Json;
use axum::extract::{Path, Query, State};
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
    /// Scenes to make, one per seed from `seed` up (1 to [`crate::MAX_VARIATIONS`]); all
    /// are queued or none.
    #[serde(default)]
    variations: Option<u32>,
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

/// `POST /api/jobs` → 202 `{job_id, job_ids, state}`; 429 with `Retry-After` when the
/// queue, or the caller's share of it, is full. Everything that scales the work is bounded
/// here, before anything is queued: the prompt's length, the robots, the objects the
/// prompt asks for, the variations.
pub async fn create(
    State(s): State<AppState>,
    caller: Caller,
    Body(r): Body<JobRequest>,
) -> ApiResult<(StatusCode, Json<Value>)> {
    check_text("prompt", &r.prompt)?;
    let variations = r.variations.unwrap_or(1);
    if !(1..=crate::MAX_VARIATIONS).contains(&variations) {
        return Err(ApiError::unprocessable(format!(
            "variations: 1 to {} scenes per request, got {variations}",
            crate::MAX_VARIATIONS
        )));
    }
    let seed = r.seed.unwrap_or(0);
    if seed.checked_add(u64::from(variations - 1)).is_none_or(|last| last > i64::MAX as u64) {
        return Err(ApiError::unprocessable(format!("seed: at most {} (with its variations)", i64::MAX)));
    }
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
        let wanted = robots.iter().filter(|n| !n.trim().eq_ignore_ascii_case("none")).count();
        if wanted > sw_plan::MAX_ROBOTS as usize {
            return Err(ApiError::unprocessable(format!(
                "robots: at most {} per scene, got {wanted}",
                sw_plan::MAX_ROBOTS
            )));
        }
        for name in robots.iter().filter(|n| !n.trim().eq_ignore_ascii_case("none")) {
            if sw_robots::find(name).is_none() {
                return Err(ApiError::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    format!("unknown robot '{name}' (see GET /api/robots)"),
                ));
            }
        }
    }
    // Without a plan model, the offline planner is the reader: a prompt it refuses, or one
    // asking for more objects than a scene may hold, is answered now.
    if s.runner.llm.as_ref().and_then(|c| c.endpoint(sw_llm::LlmStage::Plan)).is_none() {
        let prompt = r.prompt.clone();
        let read = tokio::task::spawn_blocking(move || sw_planner::plan(&prompt)).await.map_err(ApiError::internal)?;
        match read {
            Err(e) => return Err(ApiError::unprocessable(e.to_string())),
            Ok(plan) => {
                if let Some(cut) = plan.understanding.approximated.iter().find(|a| a.reason.ends_with("per scene")) {
                    return Err(ApiError::unprocessable(format!(
                        "\"{}\": {} (it would become {}); ask for fewer",
                        cut.text, cut.reason, cut.became
                    )));
                }
            }
        }
    }
    let mut options = json!(opts);
    if let Some(robots) = &r.robots {
        options["robots"] = json!(robots);
    }
    let news: Vec<NewJob> = (0..u64::from(variations))
        .map(|k| NewJob {
            user_id: caller.user.id.clone(),
            kind: JobKind::Generate,
            prompt: r.prompt.clone(),
            seed: seed + k,
            options: options.clone(),
            parent_scene_id: None,
            timeout_ms: s.runner.job_timeout_ms,
            max_attempts: s.runner.max_attempts,
        })
        .collect();
    let jobs = s.store.enqueue_all(&news, s.limits).await?;
    for _ in &jobs {
        s.wake.notify_one();
    }
    // One line per job, naming it as every other line about the job does (`job`), so a
    // search for one job's id finds when it was queued.
    for job in &jobs {
        tracing::info!(job = %job.id, user = %caller.user.id, "job queued");
    }
    let ids: Vec<&str> = jobs.iter().map(|j| j.id.as_str()).collect();
    let first = jobs.first().ok_or_else(|| ApiError::internal("no job was queued"))?;
    Ok((StatusCode::ACCEPTED, Json(json!({ "job_id": first.id, "job_ids": ids, "state": first.state }))))
}

fn sw_layout_profiles() -> Vec<String> {
    sw_layout::rules::profile_names()
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ListQuery {
    /// How many (1 to 200, default 200).
    #[serde(default)]
    limit: Option<i64>,
}

/// `GET /api/jobs?limit=N` → the caller's newest `N` jobs (1 to 200), newest first.
pub async fn list(State(s): State<AppState>, caller: Caller, Query(q): Query<ListQuery>) -> ApiResult<Json<Value>> {
    let limit = q.limit.unwrap_or(200);
    if !(1..=200).contains(&limit) {
        return Err(ApiError::unprocessable(format!("limit: 1 to 200, got {limit}")));
    }
    let jobs = s.store.jobs_of(&caller.user.id, limit).await?;
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
