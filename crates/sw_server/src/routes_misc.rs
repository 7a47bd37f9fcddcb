//! Health, robots, assets, static files of the web app, the JSON 404.

use axum::Json;
use axum::extract::{Path, Query, State};
use axum::http::{StatusCode, Uri, header};
use axum::response::{IntoResponse, Response};
use serde::Deserialize;
use serde_json::{Value, json};
use std::sync::Arc;

use sw_store::is_id;

use crate::AppState;
use crate::auth::Caller;
use crate::body::Body;
use crate::error::{ApiError, ApiResult};
use crate::forge::ForgeError;

/// `GET /healthz` → 200 when the database answers and can write (a write is tried each
/// time: a full disk reads fine), else 503 saying which.
pub async fn healthz(State(s): State<AppState>) -> Response {
    let unhealthy = |what: &str, e: &dyn std::fmt::Display| {
        tracing::warn!(error = %e, "health: {what}");
        let body = json!({ "status": "unavailable", "problem": what, "version": env!("CARGO_PKG_VERSION") });
        let mut r = (StatusCode::SERVICE_UNAVAILABLE, Json(body)).into_response();
        r.headers_mut().insert(header::RETRY_AFTER, axum::http::HeaderValue::from(crate::error::STORAGE_RETRY_S));
        r
    };
    if let Err(e) = s.store.count_by_state().await {
        return unhealthy("the database does not answer", &e);
    }
    if let Err(e) = s.store.probe_write().await {
        return unhealthy("the database cannot write (is its disk full?)", &e);
    }
    let blobs = s.blobs.clone();
    match tokio::task::spawn_blocking(move || blobs.put("health/probe", b"ok")).await {
        Ok(Ok(())) => {}
        Ok(Err(e)) => return unhealthy("the package store cannot write (is its disk full?)", &e),
        Err(e) => return unhealthy("the package store's check crashed", &e),
    }
    Json(json!({ "status": "ok", "version": env!("CARGO_PKG_VERSION") })).into_response()
}

/// `GET /api/robots` → the registry's robots.
pub async fn robots(_caller: Caller) -> Json<Value> {
    let list: Vec<Value> = sw_robots::registry()
        .iter()
        .map(|r| {
            json!({
                "name": r.name, "display": r.display, "aliases": r.aliases, "kind": r.kind.label(),
                "source": r.source, "licence": r.licence.name, "reach": r.reach, "height": r.height,
            })
        })
        .collect();
    Json(json!({ "robots": list }))
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AssetQuery {
    #[serde(default)]
    q: String,
}

fn catalog_matches(q: &str) -> Vec<Value> {
    let q = q.trim().to_lowercase();
    sw_catalog::categories()
        .iter()
        .filter(|c| {
            q.is_empty()
                || c.name.contains(&q)
                || c.display.contains(&q)
                || c.synonyms.iter().any(|s| s.contains(&q))
                || c.tags.iter().any(|t| *t == q)
        })
        .map(|c| json!({ "name": c.name, "display": c.display, "tags": c.tags, "size": c.default_size(), "movable": c.movable }))
        .collect()
}

/// The catalog category a description is of: the offline planner reads it as it reads a
/// prompt, and the description is of its first object — "a trophy on a pedestal" is a
/// trophy (the pedestal is where it stands), "a red office chair" is a chair. A first
/// object the catalog does not hold (a proxy) is made by the forge, and so is one whose
/// stated size (in the words or `size_m`) no object of its category has: "a flat washer,
/// 20 mm across" is a part, not a washing machine.
fn match_category(description: &str, size_m: Option<[f64; 3]>) -> Option<&'static sw_catalog::Category> {
    let plan = sw_planner::plan(description).ok()?;
    let first = plan.objects.iter().min_by_key(|o| {
        let phrase = o.phrase.to_lowercase();
        description.to_lowercase().find(&phrase).unwrap_or(usize::MAX)
    })?;
    if first.proxy.is_some() {
        return None;
    }
    let c = sw_catalog::find(&first.category)?;
    let [w, d, _] = c.default_size();
    let said = first.size.explicit.axes(w >= d);
    (c.admits_size(said) && c.admits_size(size_m.map_or([None; 3], |s| s.map(Some)))).then_some(c)
}

/// The caller's generated assets nearest in meaning to `q` (the asset library's
/// embedder), best first, each with its `score`; or why that search is unavailable.
async fn similar(s: &AppState, user_id: &str, q: &str) -> Result<Vec<Value>, String> {
    let forge = Arc::clone(&s.forge);
    let query = q.to_string();
    let hits = tokio::task::spawn_blocking(move || -> Result<Vec<(String, f32)>, String> {
        let library = forge.library().map_err(|e| e.to_string())?;
        let hits = library.search(&query, 64).map_err(|e| e.to_string())?;
        Ok(hits.into_iter().map(|h| (h.id.to_string(), h.score)).collect())
    })
    .await
    .map_err(|e| e.to_string())??;
    let mine = s.store.assets_of(user_id, "").await.map_err(|e| e.to_string())?;
    let mut out: Vec<(f32, Value)> = mine
        .iter()
        .filter_map(|a| {
            let stored = a.meta.get("asset_id").and_then(Value::as_str)?;
            let score = hits.iter().find(|h| h.0 == stored)?.1;
            let mut v = json!(a);
            v["score"] = json!(score);
            Some((score, v))
        })
        .collect();
    out.sort_by(|a, b| b.0.total_cmp(&a.0));
    Ok(out.into_iter().take(20).map(|x| x.1).collect())
}

/// `GET /api/assets?q=` → catalog categories and the caller's own assets whose words
/// match, and (`similar`) the caller's generated parts nearest in meaning.
pub async fn assets(State(s): State<AppState>, caller: Caller, Query(q): Query<AssetQuery>) -> ApiResult<Json<Value>> {
    if q.q.len() > 1024 {
        return Err(ApiError::bad_request("the query is longer than 1024 bytes"));
    }
    let mine = s.store.assets_of(&caller.user.id, &q.q).await?;
    let (similar, note) = if q.q.trim().is_empty() {
        (Vec::new(), None)
    } else {
        match similar(&s, &caller.user.id, q.q.trim()).await {
            Ok(v) => (v, None),
            Err(e) => {
                let e = crate::error::scrub_paths(&e);
                (Vec::new(), Some(format!("search by meaning is unavailable ({e}); parts are matched by their words")))
            }
        }
    };
    Ok(Json(json!({ "catalog": catalog_matches(&q.q), "mine": mine, "similar": similar, "note": note })))
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AssetRequest {
    description: String,
    /// Its bounding box, metres: width, depth, height.
    #[serde(default)]
    size_m: Option<[f64; 3]>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CreateQuery {
    /// `1`: answer with the forge's progress as it comes, one JSON object per line.
    #[serde(default)]
    stream: Option<u8>,
}

type Report = Arc<dyn Fn(Value) + Send + Sync>;

/// The asset for a request: a catalog category the offline planner reads the description
/// as, else the asset forge's (reused by meaning and size, or generated, validated,
/// stored and indexed).
async fn make_asset(s: &AppState, user_id: &str, r: AssetRequest, report: Report) -> ApiResult<Value> {
    let category = match_category(&r.description, r.size_m).map(|c| c.name);
    let meta = match category.and_then(sw_catalog::find) {
        Some(c) => {
            report(json!({ "event": "progress", "message": format!("a catalog category: {}", c.display) }));
            json!({ "source": "catalog", "size": c.default_size(), "movable": c.movable, "tags": c.tags })
        }
        None => {
            let forge = Arc::clone(&s.forge);
            let (description, size) = (r.description.trim().to_string(), r.size_m);
            let work = tokio::task::spawn_blocking(move || forge.make_reporting(&description, size, &*report));
            let made = match tokio::time::timeout(crate::forge::ASSET_TIMEOUT, work).await {
                Ok(Ok(made)) => made,
                Ok(Err(e)) => return Err(ApiError::internal(format!("the asset forge stopped: {e}"))),
                Err(_) => {
                    return Err(ApiError::new(
                        StatusCode::GATEWAY_TIMEOUT,
                        format!("making the asset took over {} s", crate::forge::ASSET_TIMEOUT.as_secs()),
                    ));
                }
            };
            match made {
                Ok(m) => m.meta,
                Err(e @ ForgeError::NotMade(_)) => {
                    return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, e.to_string()));
                }
                Err(e @ ForgeError::Unavailable(_)) => {
                    // Logged in full; answered with what to run, never the server's paths.
                    tracing::error!("{e}");
                    return Err(ApiError::new(
                        StatusCode::SERVICE_UNAVAILABLE,
                        format!("the asset studio cannot make parts on this server: {e}"),
                    ));
                }
            }
        }
    };
    let a = s.store.create_asset(user_id, r.description.trim(), category, &meta).await?;
    Ok(json!(a))
}

/// `POST /api/assets {description, size_m?}` → 201 the asset. A catalog category the
/// offline planner reads the description as is recorded as such; anything else goes to
/// the asset forge: reused from the asset library by meaning (and size), else generated
/// (the CAD stage's model, or the offline template synthesizer for dimensioned parts),
/// validated, stored and indexed. 422 when it cannot be made, with why. With `?stream=1`
/// the answer is `application/x-ndjson`: progress and failed attempts (with their failure
/// kinds) as they happen, then `{"event": "asset", "asset"}` or `{"event": "error",
/// "status", "error", "kinds"}`.
pub async fn create_asset(
    State(s): State<AppState>,
    caller: Caller,
    Query(q): Query<CreateQuery>,
    Body(r): Body<AssetRequest>,
) -> ApiResult<Response> {
    crate::routes_jobs::check_text("description", &r.description)?;
    if r.description.len() > 4096 {
        return Err(ApiError::new(StatusCode::PAYLOAD_TOO_LARGE, "an asset description is at most 4096 bytes"));
    }
    if let Some(size) = r.size_m
        && !size.iter().all(|v| v.is_finite() && (0.0005..=50.0).contains(v))
    {
        return Err(ApiError::bad_request("size_m: each side must be between 0.0005 and 50 metres"));
    }
    if q.stream != Some(1) {
        let a = make_asset(&s, &caller.user.id, r, Arc::new(|_| {})).await?;
        return Ok((StatusCode::CREATED, Json(a)).into_response());
    }
    let (tx, rx) = tokio::sync::mpsc::unbounded_channel::<Value>();
    let kinds = Arc::new(std::sync::Mutex::new(Vec::<String>::new()));
    let report: Report = {
        let (tx, kinds) = (tx.clone(), Arc::clone(&kinds));
        Arc::new(move |v: Value| {
            if let (Some(k), Ok(mut all)) = (v.get("kind").and_then(Value::as_str), kinds.lock()) {
                all.push(k.to_string());
            }
            let _ = tx.send(v);
        })
    };
    let user = caller.user.id.clone();
    tokio::spawn(async move {
        let last = match make_asset(&s, &user, r, report).await {
            Ok(a) => json!({ "event": "asset", "asset": a }),
            Err(e) => {
                let kinds = kinds.lock().map(|k| k.clone()).unwrap_or_default();
                json!({ "event": "error", "status": e.status.as_u16(), "error": e.message, "kinds": kinds })
            }
        };
        let _ = tx.send(last);
    });
    let lines = futures_util::stream::unfold(rx, |mut rx| async move {
        let v = rx.recv().await?;
        Some((Ok::<_, std::convert::Infallible>(axum::body::Bytes::from(format!("{v}\n"))), rx))
    });
    Ok((
        [(header::CONTENT_TYPE, "application/x-ndjson"), (header::CACHE_CONTROL, "no-store")],
        axum::body::Body::from_stream(lines),
    )
        .into_response())
}

/// `GET /api/assets/{id}` → one of the caller's assets.
pub async fn asset(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Json<Value>> {
    if !is_id(&id) {
        return Err(ApiError::not_found("asset"));
    }
    let a = s.store.asset_of(&id, &caller.user.id).await?.ok_or_else(|| ApiError::not_found("asset"))?;
    Ok(Json(json!(a)))
}

/// `GET /api/assets/{id}/mesh.stl` → the mesh (binary STL, metres) of one of the caller's
/// generated or reused assets.
pub async fn asset_mesh(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<Response> {
    if !is_id(&id) {
        return Err(ApiError::not_found("asset"));
    }
    let a = s.store.asset_of(&id, &caller.user.id).await?.ok_or_else(|| ApiError::not_found("asset"))?;
    let Some(stored) = a.meta.get("asset_id").and_then(Value::as_str).map(str::to_string) else {
        return Err(ApiError::new(StatusCode::NOT_FOUND, "this asset is a catalog category; it has no stored mesh"));
    };
    let forge = Arc::clone(&s.forge);
    let mesh = tokio::task::spawn_blocking(move || forge.mesh(&stored))
        .await
        .map_err(|e| ApiError::internal(e.to_string()))?
        .map_err(|e| ApiError::new(StatusCode::SERVICE_UNAVAILABLE, e.to_string()))?
        .ok_or_else(|| ApiError::new(StatusCode::NOT_FOUND, "the asset's mesh is no longer in the asset store"))?;
    Ok(([(header::CONTENT_TYPE, "model/stl")], mesh).into_response())
}

/// Anything else: the web app's files (and `index.html` for its routes) when it is built,
/// a page saying how to build it when not, and a JSON 404 under `/api/`.
pub async fn not_found(State(s): State<AppState>, uri: Uri, headers: axum::http::HeaderMap) -> Response {
    let path = uri.path();
    if !path.starts_with("/api/") {
        match s.web_dir.as_ref() {
            Some(web) => {
                if let Some(r) = crate::web::file(web, path, &headers).await {
                    return r;
                }
            }
            None if !path.rsplit('/').next().unwrap_or("").contains('.') => return crate::web::not_built(),
            None => {}
        }
    }
    ApiError::new(StatusCode::NOT_FOUND, format!("no route for {path}")).into_response()
}

/// `GET /api/options` → what a job may ask for: rules profiles and anomaly kinds.
pub async fn options(_caller: Caller) -> Json<Value> {
    Json(json!({
        "rules_profiles": sw_layout::rules::profile_names(),
        "anomaly_kinds": ["overlap", "scale", "misplacement", "floating", "rule_violation"],
    }))
}

#[cfg(test)]
mod tests {
    use super::match_category;

    #[test]
    fn a_description_is_of_its_first_object_not_of_what_it_stands_on() {
        let cat = |d: &str| match_category(d, None).map(|c| c.name);
        // What it stands on, beside or under is not what is described.
        assert_eq!(cat("a trophy on a pedestal"), None, "a trophy, made by the forge");
        assert_eq!(cat("a vase on a table"), Some("vase"), "the catalog has vases (issue 21)");
        assert_ne!(cat("a lamp next to a shelf"), Some("shelf"), "a lamp, whatever it stands beside");
        // The thing itself, in the catalog.
        assert_eq!(cat("pedestal"), Some("pedestal"));
        assert_eq!(cat("a red office chair"), Some("chair"));
        assert_eq!(cat("a table with two mugs on it"), Some("table"));
        // Dimensioned parts go to the forge.
        assert_eq!(cat("a flat washer: outer diameter 120mm, inner diameter 40mm, thickness 10mm"), None);
    }

    #[test]
    fn a_size_no_object_of_the_category_has_names_another_thing() {
        let cat = |d: &str, size: Option<[f64; 3]>| match_category(d, size).map(|c| c.name);
        // The same word at the category's size, in the words or in `size_m`, is the category.
        assert_eq!(cat("a washer", None), Some("washing_machine"));
        assert_eq!(cat("a washer 60 cm wide", None), Some("washing_machine"));
        assert_eq!(cat("a mug 10 cm tall", None), Some("mug"));
        assert_eq!(cat("a mug", Some([0.12, 0.09, 0.1])), Some("mug"));
        // Far from it, it is something else, for the forge to make.
        assert_eq!(cat("a flat washer, 20 mm across", None), None);
        assert_eq!(cat("a washer", Some([0.02, 0.02, 0.002])), None);
        assert_eq!(cat("a mug 2 m tall", None), None);
        assert_eq!(cat("a table 5 mm wide", None), None);
    }
}
