//! Process-wide counters of every LLM call, by stage and outcome, for the server's
//! `/metrics` (Prometheus text format) and for anyone who asks ([`snapshot`]).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::Mutex;

use sw_plan::{LlmCall, LlmOutcome, LlmStage};

/// Upper bounds of the latency histogram, seconds.
pub const LATENCY_BUCKETS_S: [f64; 10] = [0.1, 0.5, 1.0, 2.5, 5.0, 10.0, 20.0, 40.0, 80.0, 160.0];

/// Totals of the calls of one stage that ended one way.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CallTotals {
    pub calls: u64,
    pub retries: u64,
    pub tokens_in: u64,
    pub tokens_out: u64,
    pub latency_s_sum: f64,
    /// Calls at or under each of [`LATENCY_BUCKETS_S`] (cumulative).
    pub latency_buckets: [u64; LATENCY_BUCKETS_S.len()],
}

static TOTALS: Mutex<BTreeMap<(LlmStage, LlmOutcome), CallTotals>> = Mutex::new(BTreeMap::new());

pub(crate) fn record(call: &LlmCall) {
    let mut t = match TOTALS.lock() {
        Ok(t) => t,
        Err(p) => p.into_inner(),
    };
    let e = t.entry((call.stage, call.outcome)).or_default();
    e.calls += 1;
    e.retries += u64::from(call.retries);
    e.tokens_in += call.tokens_in;
    e.tokens_out += call.tokens_out;
    let s = call.latency_ms / 1000.0;
    e.latency_s_sum += s;
    for (i, b) in LATENCY_BUCKETS_S.iter().enumerate() {
        if s <= *b {
            e.latency_buckets[i] += 1;
        }
    }
}

/// Totals so far, by (stage, outcome).
pub fn snapshot() -> Vec<(LlmStage, LlmOutcome, CallTotals)> {
    let t = match TOTALS.lock() {
        Ok(t) => t,
        Err(p) => p.into_inner(),
    };
    t.iter().map(|((s, o), c)| (*s, *o, c.clone())).collect()
}

fn outcome_name(o: LlmOutcome) -> String {
    serde_json::to_value(o).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}

/// The totals in Prometheus' text format.
pub fn prometheus() -> String {
    let mut out = String::new();
    let rows = snapshot();
    let _ = writeln!(out, "# HELP scenewright_llm_calls_total LLM calls by stage and outcome.");
    let _ = writeln!(out, "# TYPE scenewright_llm_calls_total counter");
    for (s, o, c) in &rows {
        let _ = writeln!(
            out,
            "scenewright_llm_calls_total{{stage=\"{}\",outcome=\"{}\"}} {}",
            s.name(),
            outcome_name(*o),
            c.calls
        );
    }
    for (metric, help, get) in [
        (
            "scenewright_llm_retries_total",
            "Retries of LLM calls.",
            (|c: &CallTotals| c.retries) as fn(&CallTotals) -> u64,
        ),
        ("scenewright_llm_tokens_in_total", "Prompt tokens sent.", |c: &CallTotals| c.tokens_in),
        ("scenewright_llm_tokens_out_total", "Completion tokens received.", |c: &CallTotals| c.tokens_out),
    ] {
        let _ = writeln!(out, "# HELP {metric} {help}");
        let _ = writeln!(out, "# TYPE {metric} counter");
        for (s, o, c) in &rows {
            let _ = writeln!(out, "{metric}{{stage=\"{}\",outcome=\"{}\"}} {}", s.name(), outcome_name(*o), get(c));
        }
    }
    let _ = writeln!(out, "# HELP scenewright_llm_latency_seconds Latency of LLM calls, retries included.");
    let _ = writeln!(out, "# TYPE scenewright_llm_latency_seconds histogram");
    for (s, o, c) in &rows {
        let labels = format!("stage=\"{}\",outcome=\"{}\"", s.name(), outcome_name(*o));
        for (b, n) in LATENCY_BUCKETS_S.iter().zip(c.latency_buckets) {
            let _ = writeln!(out, "scenewright_llm_latency_seconds_bucket{{{labels},le=\"{b}\"}} {n}");
        }
        let _ = writeln!(out, "scenewright_llm_latency_seconds_bucket{{{labels},le=\"+Inf\"}} {}", c.calls);
        let _ = writeln!(out, "scenewright_llm_latency_seconds_sum{{{labels}}} {:.6}", c.latency_s_sum);
        let _ = writeln!(out, "scenewright_llm_latency_seconds_count{{{labels}}} {}", c.calls);
    }
    out
}
