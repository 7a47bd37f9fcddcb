//! Edits of a scene and its versions. `POST /api/scenes/{id}/edits` takes a sentence
//! (`{"command": …}`, read by the edit grammar or model) or a structured edit from the
//! viewer — `{"move": {object, pos: [x, y], yaw_deg?}}` puts an object at a pose,
//! `{"place": {asset, pos: [x, y], yaw_deg?}}` puts a library part there (`catalog:<name>`
//! or one of the caller's generated assets). Each runs as an edit job: the layout is
//! re-solved around the change, kept inside the room, re-verified in MuJoCo, and the job
//! either makes the next version or fails with the reason. `GET …/versions` lists the
//! scene's lineage.

use axum::Json;
use axum::extract::{Path, State};
use axum::http::StatusCode;
use serde::Deserialize;
use serde_json::{Value, json};
use sw_store::{JobKind, NewJob, is_id};

use crate::AppState;
use crate::auth::Caller;
use crate::body::Body;
use crate::error::{ApiError, ApiResult};
use crate::routes_jobs::check_text;
use crate::routes_scenes::owned_scene;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MoveRequest {
    object: String,
    pos: [f64; 2],
    #[serde(default)]
    yaw_deg: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaceRequest {
    asset: String,
    pos: [f64; 2],
    #[serde(default)]
    yaw_deg: Option<f64>,
}

/// One of: a sentence, a move, a placement.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EditRequest {
    #[serde(default)]
    command: Option<String>,
    #[serde(default, rename = "move")]
    move_to: Option<MoveRequest>,
    #[serde(default)]
    place: Option<PlaceRequest>,
}

fn check_pose(pos: [f64; 2], yaw_deg: Option<f64>) -> ApiResult<()> {
    if !pos.iter().all(|v| v.is_finite() && v.abs() <= 1000.0) {
        return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, "pos: two finite numbers (metres) within 1 km"));
    }
    if yaw_deg.is_some_and(|y| !y.is_finite() || y.abs() > 36_000.0) {
        return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, "yaw_deg: a finite angle in degrees"));
    }
    Ok(())
}

fn fmt_pose(pos: [f64; 2], yaw_deg: Option<f64>) -> String {
    let turn = yaw_deg.map(|y| format!(" facing {y:.0}°")).unwrap_or_default();
    format!("({:.2}, {:.2}){turn}", pos[0], pos[1])
}

/// What a job runs: its prompt (shown in the history) and its options.
async fn describe(s: &AppState, caller: &Caller, r: EditRequest) -> ApiResult<(String, Value)> {
    match (r.command, r.move_to, r.place) {
        (Some(command), None, None) => {
            check_text("command", &command)?;
            Ok((command, json!({})))
        }
        (None, Some(m), None) => {
            check_pose(m.pos, m.yaw_deg)?;
            check_text("object", &m.object)?;
            if m.object.len() > 200 || !m.object.chars().all(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '.')) {
                return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, "object: an object's name from the scene"));
            }
            let prompt = format!("move {} to {}", m.object, fmt_pose(m.pos, m.yaw_deg));
            Ok((
                prompt,
                json!({ "structured": { "move": { "object": m.object, "pos": m.pos, "yaw_deg": m.yaw_deg } } }),
            ))
        }
        (None, None, Some(p)) => {
            check_pose(p.pos, p.yaw_deg)?;
            let at = fmt_pose(p.pos, p.yaw_deg);
            if let Some(name) = p.asset.strip_prefix("catalog:") {
                let c = sw_catalog::find(name).ok_or_else(|| {
                    ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, format!("'{name}' is not a catalog category"))
                })?;
                let prompt = format!("place a {} at {at}", c.display);
                return Ok((
                    prompt,
                    json!({ "structured": { "place": { "category": c.name, "pos": p.pos, "yaw_deg": p.yaw_deg } } }),
                ));
            }
            let a = if is_id(&p.asset) { s.store.asset_of(&p.asset, &caller.user.id).await? } else { None };
            let a = a.ok_or_else(|| ApiError::not_found("asset"))?;
            let place = match (a.meta.get("asset_id").and_then(Value::as_str), &a.category) {
                (Some(stored), _) => {
                    json!({ "mesh": stored, "label": a.description, "pos": p.pos, "yaw_deg": p.yaw_deg })
                }
                (None, Some(category)) => json!({ "category": category, "pos": p.pos, "yaw_deg": p.yaw_deg }),
                (None, None) => {
                    return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, "this asset has no mesh to place"));
                }
            };
            Ok((format!("place \"{}\" at {at}", a.description), json!({ "structured": { "place": place } })))
        }
        _ => Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            "send exactly one of \"command\" (a sentence), \"move\" {object, pos, yaw_deg?} or \"place\" {asset, pos, yaw_deg?}",
        )),
    }
}

/// `POST /api/scenes/{id}/edits` → 202 `{job_id}`: a job that makes the next version.
pub async fn edit(
    State(s): State<AppState>,
    caller: Caller,
    Path(id): Path<String>,
    Body(r): Body<EditRequest>,
) -> ApiResult<(StatusCode, Json<Value>)> {
    let sc = owned_scene(&s, &caller, &id).await?;
    let (prompt, options) = describe(&s, &caller, r).await?;
    let new = NewJob {
        user_id: caller.user.id.clone(),
        kind: JobKind::Edit,
        prompt,
        seed: 0,
        options,
        parent_scene_id: Some(sc.id.clone()),
        timeout_ms: s.runner.job_timeout_ms,
        max_attempts: s.runner.max_attempts,
    };
    let job = s.store.enqueue(&new, s.limits).await?;
    s.wake.notify_one();
    tracing::info!(job = %job.id, user = %caller.user.id, scene = %sc.id, "job queued");
    Ok((StatusCode::ACCEPTED, Json(json!({ "job_id": job.id, "state": job.state, "scene_id": sc.id }))))
}

/// `GET /api/scenes/{id}/versions` → every version of the scene's lineage, oldest first,
/// with the edit that made each.
pub async fn versions(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Json<Value>> {
    let sc = owned_scene(&s, &caller, &id).await?;
    let all = s.store.scene_versions(&sc.id, &caller.user.id).await?;
    let list: Vec<Value> = all
        .iter()
        .map(|(v, command)| {
            json!({
                "id": v.id, "job_id": v.job_id, "parent_id": v.parent_id, "version": v.version,
                "prompt": v.prompt, "status": v.status, "created_at": v.created_at, "command": command,
                "scene_prompt": v.report.get("prompt").and_then(Value::as_str).unwrap_or(&v.prompt),
            })
        })
        .collect();
    Ok(Json(json!({ "scene_id": sc.id, "versions": list })))
}
