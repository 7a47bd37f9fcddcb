//! The browser app's files (`web/dist`, built by `npm run build`): served at `/`, with
//! `index.html` for the app's own routes (`/scenes/{id}`, `/jobs/{id}`, `/studio` …) so
//! links can be shared and reloaded. Hashed build outputs (`/assets/…`) are cached for a
//! year; `index.html` is revalidated every time. A file built with a `.br` or `.gz` twin
//! is sent compressed when the browser accepts it.

use std::path::{Path, PathBuf};

use axum::http::{HeaderMap, HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};

/// Where the built app is looked for when `--web` is not given: `web/dist` under the
/// working directory, then under the checkout that holds the running binary
/// (`target/<profile>/scenewright` → `../../web/dist`).
pub fn default_dir() -> Option<PathBuf> {
    let mut candidates = vec![PathBuf::from("web/dist")];
    if let Ok(exe) = std::env::current_exe()
        && let Some(repo) = exe.parent().and_then(Path::parent).and_then(Path::parent)
    {
        candidates.push(repo.join("web/dist"));
    }
    candidates.into_iter().find(|d| d.join("index.html").is_file())
}

fn content_type(name: &str) -> &'static str {
    match name.rsplit('.').next().unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "json" => "application/json",
        "wasm" => "application/wasm",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "ico" => "image/x-icon",
        "txt" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

/// Which precompressed twin to send: `br` before `gzip` when both are accepted.
fn encodings(headers: &HeaderMap) -> Vec<(&'static str, &'static str)> {
    let accept = headers.get(header::ACCEPT_ENCODING).and_then(|v| v.to_str().ok()).unwrap_or("");
    let accepts = |name: &str| {
        accept.split(',').any(|part| {
            let mut it = part.split(';');
            let enc = it.next().unwrap_or("").trim();
            let q0 = it.any(|p| p.trim().replace(' ', "") == "q=0");
            enc.eq_ignore_ascii_case(name) && !q0
        })
    };
    let mut out = Vec::new();
    if accepts("br") {
        out.push(("br", ".br"));
    }
    if accepts("gzip") {
        out.push(("gzip", ".gz"));
    }
    out
}

/// An app route (no file extension in its last segment) is answered with `index.html`.
fn is_app_route(rel: &str) -> bool {
    !rel.rsplit('/').next().unwrap_or("").contains('.')
}

/// The file for `path` under `web`, or `None` (the caller answers 404).
pub async fn file(web: &Path, path: &str, headers: &HeaderMap) -> Option<Response> {
    let rel = path.trim_start_matches('/');
    let rel = if rel.is_empty() || is_app_route(rel) { "index.html".to_string() } else { rel.to_string() };
    sw_store::check_key(&rel).ok()?;
    let full = web.join(&rel);
    let meta = tokio::fs::metadata(&full).await.ok().filter(|m| m.is_file())?;
    let stamp =
        meta.modified().ok().and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok()).map_or(0, |d| d.as_secs());
    let etag = format!("\"{:x}-{:x}\"", meta.len(), stamp);
    let cache = if rel.starts_with("assets/") {
        "public, max-age=31536000, immutable"
    } else if rel == "index.html" {
        "no-cache"
    } else {
        "public, max-age=3600"
    };
    let mut base = HeaderMap::new();
    base.insert(header::CONTENT_TYPE, HeaderValue::from_static(content_type(&rel)));
    base.insert(header::CACHE_CONTROL, HeaderValue::from_static(cache));
    base.insert(header::VARY, HeaderValue::from_static("accept-encoding"));
    if let Ok(v) = HeaderValue::from_str(&etag) {
        base.insert(header::ETAG, v);
    }
    if headers.get(header::IF_NONE_MATCH).and_then(|v| v.to_str().ok()) == Some(etag.as_str()) {
        return Some((StatusCode::NOT_MODIFIED, base).into_response());
    }
    for (encoding, suffix) in encodings(headers) {
        let twin = web.join(format!("{rel}{suffix}"));
        if let Ok(data) = tokio::fs::read(&twin).await {
            base.insert(header::CONTENT_ENCODING, HeaderValue::from_static(encoding));
            return Some((base, data).into_response());
        }
    }
    let data = tokio::fs::read(&full).await.ok()?;
    Some((base, data).into_response())
}

/// The page `/` shows when the app has not been built: how to build it.
pub fn not_built() -> Response {
    let body = "<!doctype html><meta charset=utf-8><title>scenewright</title>\
        <body style=\"font-family:system-ui;max-width:40rem;margin:3rem auto\">\
        <h1>scenewright</h1><p>The HTTP API is running under <code>/api/</code>, but the browser app \
        has not been built. Build it with <code>scripts/setup.sh --web</code> (npm ci and npm run build \
        in <code>web/</code>), or start the server with <code>./scenewright serve</code>, which builds it \
        first; then reload this page.</p></body>";
    ([(header::CONTENT_TYPE, "text/html; charset=utf-8"), (header::CACHE_CONTROL, "no-cache")], body).into_response()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn app_routes_are_paths_without_an_extension() {
        assert!(is_app_route("scenes/0123"));
        assert!(is_app_route("studio"));
        assert!(!is_app_route("assets/index-abc.js"));
        assert!(!is_app_route("favicon.ico"));
    }

    #[test]
    fn brotli_is_preferred_and_q0_refuses() {
        let mut h = HeaderMap::new();
        h.insert(header::ACCEPT_ENCODING, HeaderValue::from_static("gzip, deflate, br, zstd"));
        assert_eq!(encodings(&h).first().map(|e| e.0), Some("br"));
        h.insert(header::ACCEPT_ENCODING, HeaderValue::from_static("br;q=0, gzip"));
        assert_eq!(encodings(&h).iter().map(|e| e.0).collect::<Vec<_>>(), vec!["gzip"]);
        h.remove(header::ACCEPT_ENCODING);
        assert!(encodings(&h).is_empty());
    }
}
