//! `GET /metrics` in Prometheus' text format: jobs by state, queue depth, latency per
//! stage, queue wait, LLM calls, tokens and latency, asset cache hits, HTTP requests.
//! Job figures come from the database, so they cover every process on it.

use std::fmt::Write as _;
use std::sync::atomic::{AtomicU64, Ordering};

use axum::extract::{Request, State};
use axum::http::header;
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use crate::AppState;
use crate::auth::Caller;
use crate::error::{ApiError, ApiResult};

/// This process's counters.
#[derive(Debug, Default)]
pub struct Counters {
    pub requests: AtomicU64,
    pub client_errors: AtomicU64,
    pub server_errors: AtomicU64,
    /// Pipeline threads running in this process (a cancelled job's stop within a second).
    pub pipelines: std::sync::Arc<std::sync::atomic::AtomicI64>,
}

/// Counts requests by outcome and logs each with its status.
pub async fn track(State(s): State<AppState>, req: Request, next: Next) -> Response {
    let method = req.method().clone();
    let path = req.uri().path().to_string();
    let r = next.run(req).await;
    let status = r.status();
    s.metrics.requests.fetch_add(1, Ordering::Relaxed);
    if status.is_client_error() {
        s.metrics.client_errors.fetch_add(1, Ordering::Relaxed);
    } else if status.is_server_error() {
        s.metrics.server_errors.fetch_add(1, Ordering::Relaxed);
    }
    tracing::debug!(%method, %path, status = status.as_u16(), "request");
    r
}

/// `GET /metrics` (admins: an admin's token or API key, e.g. a scraper's
/// `Authorization: Bearer swk_…`) → Prometheus text.
pub async fn metrics(State(s): State<AppState>, caller: Caller) -> ApiResult<Response> {
    if !caller.is_admin() {
        return Err(ApiError::new(axum::http::StatusCode::FORBIDDEN, "the metrics need the admin role"));
    }
    let mut out = String::new();
    let counts = s.store.count_by_state().await?;
    let _ = writeln!(out, "# HELP scenewright_jobs Jobs by state.\n# TYPE scenewright_jobs gauge");
    for (state, n) in &counts {
        let _ = writeln!(out, "scenewright_jobs{{state=\"{}\"}} {n}", state.as_str());
    }
    let queued = counts.iter().find(|c| c.0 == sw_store::JobState::Queued).map_or(0, |c| c.1);
    let _ = writeln!(
        out,
        "# HELP scenewright_queue_depth Jobs waiting to be claimed.\n# TYPE scenewright_queue_depth gauge"
    );
    let _ = writeln!(out, "scenewright_queue_depth {queued}");
    let _ = writeln!(
        out,
        "# HELP scenewright_pipelines_running Pipeline threads working in this process (a cancelled or timed-out job's stop within a second).\n# TYPE scenewright_pipelines_running gauge"
    );
    let _ = writeln!(out, "scenewright_pipelines_running {}", s.metrics.pipelines.load(Ordering::SeqCst));

    let totals = s.store.telemetry_totals().await?;
    let _ = writeln!(
        out,
        "# HELP scenewright_stage_seconds Wall-clock time per pipeline stage of completed jobs.\n# TYPE scenewright_stage_seconds summary"
    );
    for t in totals.iter().filter(|t| t.kind == "stage") {
        let _ = writeln!(out, "scenewright_stage_seconds_sum{{stage=\"{}\"}} {}", t.name, t.sum_ms / 1000.0);
        let _ = writeln!(out, "scenewright_stage_seconds_count{{stage=\"{}\"}} {}", t.name, t.count);
    }
    let _ = writeln!(
        out,
        "# HELP scenewright_job_seconds Queue wait and run time of completed jobs.\n# TYPE scenewright_job_seconds summary"
    );
    for t in totals.iter().filter(|t| t.kind == "job") {
        let _ = writeln!(out, "scenewright_job_seconds_sum{{phase=\"{}\"}} {}", t.name, t.sum_ms / 1000.0);
        let _ = writeln!(out, "scenewright_job_seconds_count{{phase=\"{}\"}} {}", t.name, t.count);
    }
    let _ = writeln!(
        out,
        "# HELP scenewright_llm_calls_total LLM calls of completed jobs.\n# TYPE scenewright_llm_calls_total counter"
    );
    let llm: Vec<_> = totals.iter().filter(|t| t.kind == "llm").collect();
    let calls: i64 = llm.iter().map(|t| t.count).sum();
    let _ = writeln!(out, "scenewright_llm_calls_total {calls}");
    for t in &llm {
        let _ = writeln!(out, "scenewright_llm_calls_total{{stage=\"{}\"}} {}", t.name, t.count);
    }
    let _ =
        writeln!(out, "# HELP scenewright_llm_tokens_total LLM tokens.\n# TYPE scenewright_llm_tokens_total counter");
    for t in &llm {
        let _ = writeln!(out, "scenewright_llm_tokens_total{{stage=\"{}\",direction=\"in\"}} {}", t.name, t.tokens_in);
        let _ =
            writeln!(out, "scenewright_llm_tokens_total{{stage=\"{}\",direction=\"out\"}} {}", t.name, t.tokens_out);
    }
    let _ = writeln!(out, "# HELP scenewright_llm_seconds LLM call latency.\n# TYPE scenewright_llm_seconds summary");
    for t in &llm {
        let _ = writeln!(out, "scenewright_llm_seconds_sum{{stage=\"{}\"}} {}", t.name, t.sum_ms / 1000.0);
        let _ = writeln!(out, "scenewright_llm_seconds_count{{stage=\"{}\"}} {}", t.name, t.count);
    }
    let hits: i64 = totals.iter().filter(|t| t.kind == "cache" && t.name == "hit").map(|t| t.tokens_in).sum();
    let misses: i64 = totals.iter().filter(|t| t.kind == "cache" && t.name == "miss").map(|t| t.tokens_in).sum();
    let _ = writeln!(
        out,
        "# HELP scenewright_asset_cache_lookups_total Asset cache lookups.\n# TYPE scenewright_asset_cache_lookups_total counter"
    );
    let _ = writeln!(out, "scenewright_asset_cache_lookups_total{{result=\"hit\"}} {hits}");
    let _ = writeln!(out, "scenewright_asset_cache_lookups_total{{result=\"miss\"}} {misses}");
    let _ = writeln!(
        out,
        "# HELP scenewright_asset_cache_hit_ratio Share of lookups that hit.\n# TYPE scenewright_asset_cache_hit_ratio gauge"
    );
    let ratio = if hits + misses > 0 { hits as f64 / (hits + misses) as f64 } else { 0.0 };
    let _ = writeln!(out, "scenewright_asset_cache_hit_ratio {ratio}");
    let m = &s.metrics;
    let _ = writeln!(
        out,
        "# HELP scenewright_http_requests_total Requests this process answered.\n# TYPE scenewright_http_requests_total counter"
    );
    let _ = writeln!(out, "scenewright_http_requests_total{{class=\"all\"}} {}", m.requests.load(Ordering::Relaxed));
    let _ =
        writeln!(out, "scenewright_http_requests_total{{class=\"4xx\"}} {}", m.client_errors.load(Ordering::Relaxed));
    let _ =
        writeln!(out, "scenewright_http_requests_total{{class=\"5xx\"}} {}", m.server_errors.load(Ordering::Relaxed));
    Ok(([(header::CONTENT_TYPE, "text/plain; version=0.0.4")], out).into_response())
}
