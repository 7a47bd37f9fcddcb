//! Errors as HTTP answers: a status and `{"error": "<one clear sentence>"}`, with
//! `Retry-After` when trying again later will work (a full queue, too many sign-in
//! attempts, a full disk). No answer carries a path on the server's disk.

use axum::Json;
use axum::http::{HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use sw_store::StoreError;

/// An error answer.
#[derive(Debug)]
pub struct ApiError {
    pub status: StatusCode,
    pub message: String,
    /// Seconds after which the same request may succeed (`Retry-After`).
    pub retry_after: Option<u64>,
}

/// How long a client waits after the queue was full, s.
pub const QUEUE_RETRY_S: u64 = 10;
/// How long a client waits after the store could not write, s.
pub const STORAGE_RETRY_S: u64 = 30;

impl ApiError {
    pub fn new(status: StatusCode, message: impl Into<String>) -> Self {
        Self { status, message: scrub_paths(&message.into()), retry_after: None }
    }

    /// The same answer with `Retry-After: seconds`.
    pub fn retry_after(mut self, seconds: u64) -> Self {
        self.retry_after = Some(seconds.max(1));
        self
    }

    pub fn bad_request(message: impl Into<String>) -> Self {
        Self::new(StatusCode::BAD_REQUEST, message)
    }

    pub fn unauthorized(message: impl Into<String>) -> Self {
        Self::new(StatusCode::UNAUTHORIZED, message)
    }

    pub fn unprocessable(message: impl Into<String>) -> Self {
        Self::new(StatusCode::UNPROCESSABLE_ENTITY, message)
    }

    /// The one answer for "no such thing" and "not yours": the two are indistinguishable.
    pub fn not_found(what: &str) -> Self {
        Self::new(StatusCode::NOT_FOUND, format!("no such {what}"))
    }

    pub fn internal(message: impl std::fmt::Display) -> Self {
        // Logged once here; the client gets a generic sentence.
        tracing::error!(error = %message, "internal error");
        Self::new(StatusCode::INTERNAL_SERVER_ERROR, "internal error; see the server's log")
    }

    /// The store could not write (a full or failing disk): nothing was stored.
    pub fn storage(message: impl std::fmt::Display) -> Self {
        tracing::error!(error = %message, "the store cannot write");
        Self::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "the server cannot store anything at the moment (its disk is full or failing); nothing was stored — try again later",
        )
        .retry_after(STORAGE_RETRY_S)
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let mut r = (self.status, Json(serde_json::json!({ "error": self.message }))).into_response();
        if self.status == StatusCode::UNAUTHORIZED {
            r.headers_mut().insert(header::WWW_AUTHENTICATE, HeaderValue::from_static("Bearer"));
        }
        if let Some(s) = self.retry_after {
            r.headers_mut().insert(header::RETRY_AFTER, HeaderValue::from(s));
        }
        r
    }
}

impl From<StoreError> for ApiError {
    fn from(e: StoreError) -> Self {
        match e {
            StoreError::QueueFull { .. } => {
                ApiError::new(StatusCode::TOO_MANY_REQUESTS, e.to_string()).retry_after(QUEUE_RETRY_S)
            }
            StoreError::Conflict(m) => ApiError::new(StatusCode::CONFLICT, m),
            e if e.is_storage_failure() => ApiError::storage(e),
            e => ApiError::internal(e),
        }
    }
}

impl From<sw_store::BlobError> for ApiError {
    fn from(e: sw_store::BlobError) -> Self {
        match e {
            sw_store::BlobError::BadKey(..) => ApiError::bad_request(e.to_string()),
            e if blob_storage_failure(&e) => ApiError::storage(e),
            e => ApiError::internal(e),
        }
    }
}

/// True when a blob could not be written for want of space.
fn blob_storage_failure(e: &sw_store::BlobError) -> bool {
    let text = e.to_string();
    text.contains("No space left") || text.contains("Disk quota exceeded") || text.contains("Read-only file system")
}

/// Replaces absolute paths in a message with their last component: an answer says which
/// file, never where the server keeps it (`/srv/data/.cache/x/model.onnx` → `…/model.onnx`).
pub fn scrub_paths(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(i) = rest.find('/') {
        let (before, at) = rest.split_at(i);
        // A path starts at a '/' that begins a word (not "a/b", not "http://…").
        let starts_word =
            before.chars().last().is_none_or(|c| c.is_whitespace() || matches!(c, '(' | '\'' | '"' | '`' | ':' | '='));
        let end =
            at.find(|c: char| c.is_whitespace() || matches!(c, '\'' | '"' | '`' | ')' | ',' | ';')).unwrap_or(at.len());
        let path = &at[..end];
        let path_trimmed = path.trim_end_matches(['.', ':']);
        out.push_str(before);
        // The service's own routes (`/api/…`) are addresses, not files.
        let route = path_trimmed.starts_with("/api/");
        if starts_word && !route && path_trimmed.matches('/').count() >= 2 && !before.ends_with(':') {
            let last = path_trimmed.rsplit('/').find(|s| !s.is_empty()).unwrap_or("");
            out.push('…');
            out.push('/');
            out.push_str(last);
            out.push_str(&path[path_trimmed.len()..]);
        } else {
            out.push_str(path);
        }
        rest = &at[end..];
    }
    out.push_str(rest);
    out
}

pub type ApiResult<T> = Result<T, ApiError>;

#[cfg(test)]
mod tests {
    use super::scrub_paths;

    #[test]
    fn answers_name_files_not_where_they_live() {
        assert_eq!(
            scrub_paths("the MiniLM model is not set up: /work/main/.cache/minilm/model.safetensors is missing"),
            "the MiniLM model is not set up: …/model.safetensors is missing"
        );
        assert_eq!(scrub_paths("scene.xml: no such file ('/srv/d/blobs/x')"), "scene.xml: no such file ('…/x')");
        // Not paths: relative ones, units, URLs, a lone slash.
        for keep in ["a/b of the package", "3 m/s", "see http://localhost:8080/api/jobs", "1 / 2", "GET /api/jobs"] {
            assert_eq!(scrub_paths(keep), keep);
        }
    }
}
