//! `GET /api/scenes/{id}/thumbnail.png`: a small picture of a scene for the "My scenes"
//! page, drawn by MuJoCo's geoms through the software rasterizer (no GPU) the first time
//! it is asked for and kept in the blob store beside the package (`thumbnails/<id>.png`).

use std::sync::OnceLock;

use axum::extract::{Path, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};

use crate::AppState;
use crate::auth::Caller;
use crate::error::{ApiError, ApiResult};
use crate::routes_scenes::owned_scene;

const WIDTH: u32 = 480;
const HEIGHT: u32 = 300;

/// One picture is drawn at a time (each loads the scene in MuJoCo).
fn drawing() -> &'static tokio::sync::Semaphore {
    static S: OnceLock<tokio::sync::Semaphore> = OnceLock::new();
    S.get_or_init(|| tokio::sync::Semaphore::new(1))
}

fn png(data: Vec<u8>) -> Response {
    ([(header::CONTENT_TYPE, "image/png"), (header::CACHE_CONTROL, "private, max-age=31536000, immutable")], data)
        .into_response()
}

pub async fn thumbnail(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Response> {
    let sc = owned_scene(&s, &caller, &id).await?;
    let key = format!("thumbnails/{}.png", sc.id);
    let blobs = s.blobs.clone();
    let k = key.clone();
    if let Some(data) = tokio::task::spawn_blocking(move || blobs.get(&k)).await.map_err(ApiError::internal)?? {
        return Ok(png(data));
    }
    let _turn = drawing().acquire().await.map_err(ApiError::internal)?;
    let blobs = s.blobs.clone();
    let work = s.runner.work_root();
    let data = tokio::task::spawn_blocking(move || -> Result<Vec<u8>, ApiError> {
        if let Some(data) = blobs.get(&key)? {
            return Ok(data);
        }
        fs_err::create_dir_all(&work).map_err(ApiError::internal)?;
        let tmp = tempfile::Builder::new().prefix("thumb-").tempdir_in(&work).map_err(ApiError::internal)?;
        for f in sc.files.iter().filter(|f| f.ends_with(".xml") || f.starts_with("assets/")) {
            sw_store::check_key(f)?;
            let bytes = blobs
                .get(&format!("scenes/{}/{f}", sc.id))?
                .ok_or_else(|| ApiError::internal(format!("scene {} lost its file {f}", sc.id)))?;
            let path = tmp.path().join(f);
            if let Some(dir) = path.parent() {
                fs_err::create_dir_all(dir).map_err(ApiError::internal)?;
            }
            fs_err::write(&path, bytes).map_err(ApiError::internal)?;
        }
        let img = sw_sim::render_scene(&tmp.path().join("scene.xml"), WIDTH, HEIGHT, &[2])
            .map_err(|e| ApiError::internal(format!("drawing scene {}: {e}", sc.id)))?;
        let mut out = Vec::new();
        img.write_png(&mut out).map_err(ApiError::internal)?;
        blobs.put(&key, &out)?;
        Ok(out)
    })
    .await
    .map_err(ApiError::internal)??;
    Ok(png(data))
}
