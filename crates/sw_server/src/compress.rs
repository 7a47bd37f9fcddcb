//! gzip for the API's answers: JSON, package files (MJCF, meshes, robot models — a robot
//! pack's package is ~40 MB raw and ~6 MB gzipped) when the client accepts it. A scene's
//! files never change (every edit makes a new scene), so their compressed bodies are kept
//! in a bounded in-memory cache keyed by their ETag; the app's own files come
//! precompressed (brotli and gzip) from the build and are not touched here.

use std::collections::HashMap;
use std::io::Write;
use std::sync::{Arc, Mutex};

use axum::body::{Body, Bytes};
use axum::extract::{Request, State};
use axum::http::{HeaderValue, StatusCode, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

/// Bodies smaller than this are sent as they are.
const MIN_BYTES: usize = 1024;
/// Bodies larger than this are sent as they are (they are not held in memory twice).
const MAX_BYTES: usize = 256 << 20;
/// The cache of compressed immutable bodies, bytes.
const CACHE_BYTES: usize = 512 << 20;

/// Compressed bodies of immutable responses, by ETag; the least recently used go first.
#[derive(Debug, Default)]
pub struct GzipCache {
    inner: Mutex<CacheInner>,
}

#[derive(Debug, Default)]
struct CacheInner {
    entries: HashMap<String, (Bytes, u64)>,
    bytes: usize,
    tick: u64,
}

impl GzipCache {
    fn get(&self, key: &str) -> Option<Bytes> {
        let mut c = self.inner.lock().ok()?;
        c.tick += 1;
        let tick = c.tick;
        c.entries.get_mut(key).map(|e| {
            e.1 = tick;
            e.0.clone()
        })
    }

    fn put(&self, key: String, body: Bytes) {
        let Ok(mut c) = self.inner.lock() else { return };
        if body.len() > CACHE_BYTES / 4 {
            return;
        }
        c.tick += 1;
        let tick = c.tick;
        c.bytes += body.len();
        if let Some((old, _)) = c.entries.insert(key, (body, tick)) {
            c.bytes -= old.len();
        }
        while c.bytes > CACHE_BYTES {
            let Some(oldest) = c.entries.iter().min_by_key(|e| e.1.1).map(|e| e.0.clone()) else { break };
            if let Some((b, _)) = c.entries.remove(&oldest) {
                c.bytes -= b.len();
            }
        }
    }
}

fn compressible(content_type: &str) -> bool {
    let ct = content_type.split(';').next().unwrap_or("").trim();
    ct.starts_with("text/")
        || matches!(
            ct,
            "application/json" | "application/xml" | "application/octet-stream" | "model/stl" | "image/svg+xml"
        )
}

fn accepts_gzip(req: &Request) -> bool {
    req.headers().get_all(header::ACCEPT_ENCODING).iter().filter_map(|v| v.to_str().ok()).any(|v| {
        v.split(',').any(|p| {
            let mut it = p.split(';');
            it.next().is_some_and(|e| e.trim().eq_ignore_ascii_case("gzip"))
                && !it.any(|q| q.trim().replace(' ', "") == "q=0")
        })
    })
}

/// gzip at a level that keeps large files fast to compress.
pub fn gzip(data: &[u8]) -> std::io::Result<Vec<u8>> {
    let level = if data.len() > 1 << 20 { 1 } else { 5 };
    let mut enc = flate2::write::GzEncoder::new(Vec::with_capacity(data.len() / 3), flate2::Compression::new(level));
    enc.write_all(data)?;
    enc.finish()
}

/// The middleware: compresses eligible answers for clients that accept gzip.
pub async fn layer(State(cache): State<Arc<GzipCache>>, req: Request, next: Next) -> Response {
    let wants = accepts_gzip(&req);
    let resp = next.run(req).await;
    if !wants || resp.status() != StatusCode::OK {
        return resp;
    }
    let h = resp.headers();
    if h.contains_key(header::CONTENT_ENCODING) {
        return resp;
    }
    let ct = h.get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("");
    if !compressible(ct) {
        return resp;
    }
    let immutable = h.get(header::CACHE_CONTROL).and_then(|v| v.to_str().ok()).is_some_and(|v| v.contains("immutable"));
    let key = h.get(header::ETAG).and_then(|v| v.to_str().ok()).filter(|_| immutable).map(str::to_string);
    let (mut parts, body) = resp.into_parts();
    parts.headers.append(header::VARY, HeaderValue::from_static("accept-encoding"));
    if let Some(hit) = key.as_deref().and_then(|k| cache.get(k)) {
        return finish(parts, hit);
    }
    let bytes = match axum::body::to_bytes(body, MAX_BYTES).await {
        Ok(b) => b,
        Err(e) => return crate::ApiError::internal(format!("reading a response to compress: {e}")).into_response(),
    };
    if bytes.len() < MIN_BYTES {
        return Response::from_parts(parts, Body::from(bytes));
    }
    let raw = bytes.clone();
    let packed = match tokio::task::spawn_blocking(move || gzip(&raw)).await {
        Ok(Ok(p)) => Bytes::from(p),
        _ => return Response::from_parts(parts, Body::from(bytes)),
    };
    if let Some(k) = key {
        cache.put(k, packed.clone());
    }
    finish(parts, packed)
}

fn finish(mut parts: axum::http::response::Parts, body: Bytes) -> Response {
    parts.headers.insert(header::CONTENT_ENCODING, HeaderValue::from_static("gzip"));
    parts.headers.remove(header::CONTENT_LENGTH);
    Response::from_parts(parts, Body::from(body))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cache_keeps_the_recent_and_stays_under_its_budget() {
        let c = GzipCache::default();
        let chunk = Bytes::from(vec![0u8; CACHE_BYTES / 5]);
        for k in 0..8 {
            c.put(format!("k{k}"), chunk.clone());
            assert!(c.get("k0").is_some() || k > 0, "the first entry is there until evicted");
        }
        let inner = c.inner.lock().map(|i| i.bytes).unwrap_or(usize::MAX);
        assert!(inner <= CACHE_BYTES, "{inner} bytes cached");
        assert!(c.get("k7").is_some(), "the newest entry is kept");
    }

    #[test]
    fn gzip_round_trips() {
        let data: Vec<u8> = (0..100_000u32).flat_map(|i| (i % 251).to_le_bytes()).collect();
        let z = gzip(&data).unwrap_or_default();
        let mut out = Vec::new();
        let mut d = flate2::read::GzDecoder::new(z.as_slice());
        std::io::Read::read_to_end(&mut d, &mut out).unwrap_or_default();
        assert_eq!(out, data);
        assert!(z.len() < data.len() / 3);
    }
}
