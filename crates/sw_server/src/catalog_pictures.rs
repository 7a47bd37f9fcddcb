//! `GET /api/catalog/{name}/picture.png`: a picture of a catalog category for the web app's
//! parts list and asset studio. Categories are made procedurally in each scene, so there is
//! no stored mesh to show; the picture is the category built at seed 0 and drawn by the
//! software rasterizer (no GPU), once per category and process, then kept in memory (one
//! small PNG per category, so the cache is bounded by the catalog). Public: a picture of
//! the catalog says nothing about any user.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use axum::extract::Path;
use axum::http::header;
use axum::response::{IntoResponse, Response};

use crate::error::{ApiError, ApiResult};

/// Pixels on a side.
pub const SIZE: u32 = 256;

type Cache = Mutex<HashMap<&'static str, Arc<Vec<u8>>>>;

fn cache() -> &'static Cache {
    static C: OnceLock<Cache> = OnceLock::new();
    C.get_or_init(|| Mutex::new(HashMap::new()))
}

/// One picture is drawn at a time: a page asks for forty at once and the jobs come first.
fn drawing() -> &'static tokio::sync::Semaphore {
    static S: OnceLock<tokio::sync::Semaphore> = OnceLock::new();
    S.get_or_init(|| tokio::sync::Semaphore::new(1))
}

fn cached(name: &str) -> Option<Arc<Vec<u8>>> {
    cache().lock().ok()?.get(name).cloned()
}

/// The PNG of one category, drawn now.
pub fn draw(category: &sw_catalog::Category) -> Result<Vec<u8>, String> {
    let asset = sw_catalog::generate(&sw_catalog::AssetRequest::new(category.name, 0)).map_err(|e| e.to_string())?;
    let mut png = Vec::new();
    sw_geom::raster::draw_asset(&asset, SIZE, SIZE).write_png(&mut png).map_err(|e| e.to_string())?;
    Ok(png)
}

pub async fn picture(Path(name): Path<String>) -> ApiResult<Response> {
    let category = sw_catalog::find(&name).ok_or_else(|| ApiError::not_found("catalog category"))?;
    let png = match cached(category.name) {
        Some(p) => p,
        None => {
            let _turn = drawing().acquire().await.map_err(ApiError::internal)?;
            match cached(category.name) {
                Some(p) => p,
                None => {
                    let drawn = tokio::task::spawn_blocking(move || draw(category))
                        .await
                        .map_err(ApiError::internal)?
                        .map_err(|e| ApiError::internal(format!("drawing catalog category {}: {e}", category.name)))?;
                    let p = Arc::new(drawn);
                    if let Ok(mut c) = cache().lock() {
                        c.insert(category.name, Arc::clone(&p));
                    }
                    p
                }
            }
        }
    };
    Ok(([(header::CONTENT_TYPE, "image/png"), (header::CACHE_CONTROL, "public, max-age=86400")], png.as_ref().clone())
        .into_response())
}
