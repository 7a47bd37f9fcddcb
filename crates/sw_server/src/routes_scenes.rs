//! Scenes: list, metadata with report and edit history, files, the package as a zip.
//! A scene never changes (an edit makes a new one), so its files are sent with an ETag and
//! cached by the browser for a year.

use axum::Json;
use axum::extract::{Path, State};
use axum::http::{HeaderMap, StatusCode, header};
use axum::response::{IntoResponse, Response};
use serde_json::{Value, json};
use sw_store::{Scene, check_key, is_id};

use crate::AppState;
use crate::auth::Caller;
use crate::error::{ApiError, ApiResult};

/// The caller's scene, or 404 (also for another user's scene).
pub(crate) async fn owned_scene(s: &AppState, caller: &Caller, id: &str) -> ApiResult<Scene> {
    if !is_id(id) {
        return Err(ApiError::not_found("scene"));
    }
    s.store.scene_of(id, &caller.user.id).await?.ok_or_else(|| ApiError::not_found("scene"))
}

/// A scene in lists: `prompt` is what its job was asked (an edit's command for a later
/// version), `scene_prompt` the description the scene was generated from.
fn summary(sc: &Scene) -> Value {
    json!({
        "id": sc.id, "job_id": sc.job_id, "parent_id": sc.parent_id, "version": sc.version,
        "prompt": sc.prompt, "scene_prompt": sc.report.get("prompt").and_then(Value::as_str).unwrap_or(&sc.prompt),
        "status": sc.status, "created_at": sc.created_at, "seed": sc.report.get("seed").and_then(Value::as_u64),
    })
}

/// `GET /api/scenes` → the caller's scenes, newest first.
pub async fn list(State(s): State<AppState>, caller: Caller) -> ApiResult<Json<Value>> {
    let scenes = s.store.scenes_of(&caller.user.id, 500).await?;
    Ok(Json(json!({ "scenes": scenes.iter().map(summary).collect::<Vec<_>>() })))
}

/// `GET /api/scenes/{id}` → metadata, report, files and edit history.
pub async fn show(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Json<Value>> {
    let sc = owned_scene(&s, &caller, &id).await?;
    let edits = s.store.edits_of_scene(&sc.id, &caller.user.id).await?;
    let mut v = summary(&sc);
    v["report"] = sc.report.clone();
    v["files"] = json!(sc.files);
    v["edits"] = json!(edits);
    Ok(Json(v))
}

/// A file path inside a package, checked: relative, plain segments, no traversal.
fn check_path(path: &str) -> ApiResult<()> {
    check_key(path).map_err(|e| ApiError::bad_request(format!("bad file path: {e}")))
}

fn content_type(path: &str) -> &'static str {
    match path.rsplit('.').next().unwrap_or("") {
        "xml" => "application/xml",
        "json" => "application/json",
        "png" => "image/png",
        "obj" | "mtl" | "urdf" => "text/plain; charset=utf-8",
        "stl" => "model/stl",
        _ => "application/octet-stream",
    }
}

/// `GET /api/scenes/{id}/files/{path}` → one file of the package.
pub async fn file(
    State(s): State<AppState>,
    caller: Caller,
    Path((id, path)): Path<(String, String)>,
    headers: HeaderMap,
) -> ApiResult<Response> {
    check_path(&path)?;
    let sc = owned_scene(&s, &caller, &id).await?;
    if !sc.files.iter().any(|f| f == &path) {
        return Err(ApiError::not_found("file in this scene"));
    }
    // The scene id and path name the bytes for good: no hash of the content is needed.
    let etag = format!("\"{}/{}\"", sc.id, path.replace('"', ""));
    let cache = (header::CACHE_CONTROL, "private, max-age=31536000, immutable".to_string());
    if headers.get(header::IF_NONE_MATCH).and_then(|v| v.to_str().ok()) == Some(etag.as_str()) {
        return Ok((StatusCode::NOT_MODIFIED, [cache, (header::ETAG, etag)]).into_response());
    }
    let key = format!("scenes/{}/{path}", sc.id);
    let blobs = s.blobs.clone();
    let data = tokio::task::spawn_blocking(move || blobs.get(&key)).await.map_err(ApiError::internal)??;
    let data = data.ok_or_else(|| ApiError::internal(format!("scene {} lost its file {path}", sc.id)))?;
    check_stored(&s, &sc.id, &path, &data).await?;
    Ok(([(header::CONTENT_TYPE, content_type(&path).to_string()), cache, (header::ETAG, etag)], data).into_response())
}

/// Refuses to serve a stored file whose bytes are not the ones stored with the scene (a
/// damaged disk, a hand-edited blob): 500 with what is wrong, never the wrong bytes.
async fn check_stored(s: &AppState, scene: &str, path: &str, data: &[u8]) -> ApiResult<()> {
    match s.store.file_hash(scene, path).await? {
        Some(h) if h != crate::worker::sha256_hex(data) => {
            tracing::error!(scene, file = path, "a stored file does not match its checksum");
            Err(damaged(path))
        }
        _ => Ok(()),
    }
}

fn damaged(path: &str) -> ApiError {
    ApiError::new(
        StatusCode::INTERNAL_SERVER_ERROR,
        format!("the stored file {path} of this scene is damaged (its checksum does not match); it is not served"),
    )
}

/// `GET /api/scenes/{id}/package.zip` → the package as a zip (stored, not compressed).
pub async fn package_zip(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Response> {
    let sc = owned_scene(&s, &caller, &id).await?;
    let blobs = s.blobs.clone();
    let scene_id = sc.id.clone();
    let files = sc.files.clone();
    let hashes = s.store.file_hashes(&sc.id).await?;
    let zip = tokio::task::spawn_blocking(move || -> Result<Vec<u8>, ApiError> {
        let mut w = crate::zip::ZipWriter::default();
        for f in &files {
            let data = blobs
                .get(&format!("scenes/{scene_id}/{f}"))?
                .ok_or_else(|| ApiError::internal(format!("scene {scene_id} lost its file {f}")))?;
            if hashes.get(f).is_some_and(|h| *h != crate::worker::sha256_hex(&data)) {
                tracing::error!(scene = %scene_id, file = %f, "a stored file does not match its checksum");
                return Err(damaged(f));
            }
            w.add(f, &data);
        }
        Ok(w.finish())
    })
    .await
    .map_err(ApiError::internal)??;
    let disposition = format!("attachment; filename=\"scene_{}.zip\"", sc.id);
    Ok(([(header::CONTENT_TYPE, "application/zip".to_string()), (header::CONTENT_DISPOSITION, disposition)], zip)
        .into_response())
}

/// `DELETE /api/scenes/{id}` → 200 `{deleted: [ids]}`: the scene and every version of its
/// lineage (the first version and all edits of it), with their files.
pub async fn delete(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Json<Value>> {
    let sc = owned_scene(&s, &caller, &id).await?;
    let ids = s.store.delete_lineage(&sc.id, &caller.user.id).await?;
    let blobs = s.blobs.clone();
    let gone = ids.clone();
    let removed = tokio::task::spawn_blocking(move || {
        for id in &gone {
            blobs.delete_prefix(&format!("scenes/{id}/"))?;
        }
        Ok::<(), sw_store::BlobError>(())
    })
    .await
    .map_err(ApiError::internal)?;
    if let Err(e) = removed {
        // The rows are gone; files left behind are only space, never served again.
        tracing::warn!(error = %e, "removing a deleted scene's files failed");
    }
    tracing::info!(user = %caller.user.id, scenes = ?ids, "scenes deleted");
    Ok(Json(json!({ "deleted": ids })))
}
