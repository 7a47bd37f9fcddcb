//! `bench scenes`: the prompt suite through the whole pipeline, with per-stage
//! percentiles and validity counts. `bench assets`: generation time of every catalog
//! category over many seeds.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use clap::Subcommand;
use serde::Serialize;
use sw_pipeline::Options;
use sw_plan::{Stage, Status};

use crate::Failure;
use crate::output::{print, print_json};

/// The suite shipped with the binary (`bench/prompts.txt`).
const SUITE: &str = include_str!("../../../bench/prompts.txt");

#[derive(Debug, Subcommand)]
pub(crate) enum BenchCommand {
    /// The service under load: WebSocket clients, or a deep queue and many runners.
    #[command(subcommand)]
    Server(crate::bench_server::ServerBench),
    /// Every prompt of the suite (or one prompt, repeated) through the pipeline; with a
    /// relation suite (`.jsonl`, bench/relations/suite.jsonl), per-relation pass rates.
    Scenes {
        /// A prompt file: one prompt per line, `#` comments (default: the built-in suite);
        /// or a relation suite, one JSON line per prompt with its counts and relations.
        #[arg(long)]
        suite: Option<PathBuf>,
        /// Benchmark this prompt instead of a suite.
        #[arg(long)]
        prompt: Option<String>,
        /// Seeds per prompt (0..N).
        #[arg(long, default_value_t = 1)]
        seeds: u64,
        /// Runs per prompt and seed.
        #[arg(long, default_value_t = 1)]
        repeat: u32,
        #[arg(long)]
        json: bool,
    },
    /// Rooms with `--fill` (kitchens, offices, bedrooms, living rooms, workshops, shops):
    /// objects per room, free bodies that stayed put, deep contacts, fill and run times.
    Fill {
        /// none, furnished or cluttered.
        #[arg(long, default_value = "cluttered")]
        level: String,
        /// Seeds per room (0..N).
        #[arg(long, default_value_t = 2)]
        seeds: u64,
        /// Rooms (prompts) instead of the six of issue 21, comma-separated.
        #[arg(long, value_delimiter = ',')]
        rooms: Vec<String>,
        #[arg(long)]
        json: bool,
    },
    /// Every catalog category generated at seeds 0..N: median and p95 per category.
    Assets {
        /// Seeds per category.
        #[arg(long, default_value_t = 50)]
        seeds: u64,
        /// Only these categories, comma-separated.
        #[arg(long, value_delimiter = ',')]
        only: Vec<String>,
        #[arg(long)]
        json: bool,
    },
    /// A CAD prompt suite through the offline template synthesizer and the sandboxed
    /// runner: execution rate, retries, failure kinds, extent and volume errors against
    /// the suite's references, Chamfer distance where a reference mesh is given, and the
    /// warm runner's latency per simple part.
    Cad {
        /// standard_100, abstract_45, or a TSV file (id<TAB>tier<TAB>prompt; references
        /// from FILE.refs.tsv beside it).
        #[arg(long, default_value = "standard_100")]
        suite: String,
        /// Runner workers (parts run in parallel).
        #[arg(long, default_value_t = 2)]
        workers: usize,
        /// Times the executed T1 parts are run again, one at a time, for the latency.
        #[arg(long, default_value_t = 3)]
        latency_repeat: usize,
        /// Who writes the code: `template` (the offline synthesizer) or `llm` (the CAD
        /// stage's model, SCENEWRIGHT_LLM_* or --llm-config; up to three attempts).
        #[arg(long, default_value = "template")]
        writer: String,
        /// Endpoints for `--writer llm` (the environment overrides the file).
        #[arg(long)]
        llm_config: Option<PathBuf>,
        #[arg(long)]
        json: bool,
    },
    /// The semantic asset index: precision and recall of the reuse threshold on the
    /// labelled pairs, and retrieval time over N assets embedded with all-MiniLM-L6-v2.
    AssetIndex {
        #[arg(long, default_value_t = 10_000)]
        assets: usize,
        #[arg(long)]
        json: bool,
    },
    /// End-to-end latency with LLM stages against a local server with the paper's
    /// per-call latencies (time-scaled), ours next to the paper's structure.
    LlmLatency {
        /// Runs per scenario (5 misses, 8 misses, all cached).
        #[arg(long, default_value_t = 40)]
        runs: usize,
        /// Simulated seconds per real second.
        #[arg(long, default_value_t = 500.0)]
        time_scale: f64,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        #[arg(long)]
        json: bool,
    },
    /// The plan, relations and edit stages against a real server and model (see
    /// `scripts/setup.sh --real-llm`): calls accepted, cut off, slowest, and whether each
    /// plan keeps what the prompt states (`bench/llm/grounding.jsonl`).
    LlmReal {
        /// The server's API root, e.g. http://127.0.0.1:8080/v1.
        #[arg(long)]
        base_url: String,
        #[arg(long, default_value = "smollm2-135m-instruct")]
        model: String,
        /// An annotated suite (JSON lines) instead of bench/llm/grounding.jsonl.
        #[arg(long)]
        suite: Option<PathBuf>,
        #[arg(long)]
        json: bool,
    },
}

#[derive(Debug, Serialize)]
struct Percentiles {
    p50_ms: f64,
    p95_ms: f64,
    max_ms: f64,
}

#[derive(Debug, Serialize)]
struct Validity {
    runs: usize,
    rejected_as_bad_input: usize,
    compiled: usize,
    no_deep_contacts: usize,
    settled_within_1cm: usize,
    verified: usize,
    /// Scenes with no rule violation the prompt did not ask for.
    rules_met: usize,
    objects_requested: u64,
    objects_placed: u64,
}

#[derive(Debug, Serialize)]
struct BenchResult {
    prompts: usize,
    seeds: u64,
    repeat: u32,
    stages: BTreeMap<String, Percentiles>,
    total: Percentiles,
    validity: Validity,
    failures: Vec<String>,
}

pub(crate) fn run(c: BenchCommand) -> Result<u8, Failure> {
    match c {
        BenchCommand::Server(b) => crate::bench_server::run(b),
        BenchCommand::Scenes { suite, prompt, seeds, repeat, json } => scenes(suite, prompt, seeds, repeat, json),
        BenchCommand::Assets { seeds, only, json } => assets(seeds, &only, json),
        BenchCommand::Fill { level, seeds, rooms, json } => crate::bench_fill::run(&level, seeds, &rooms, json),
        BenchCommand::Cad { suite, workers, latency_repeat, writer, llm_config, json } => {
            let writer = match writer.as_str() {
                "template" => crate::bench_cad::Writer::Template,
                "llm" => crate::bench_cad::Writer::Model(crate::cmd_llm::config(llm_config.as_deref())?),
                other => return Err(Failure::input(format!("--writer {other}: it may be 'template' or 'llm'"))),
            };
            crate::bench_cad::run(&suite, writer, workers, latency_repeat, json)
        }
        BenchCommand::AssetIndex { assets, json } => crate::bench_index::run(assets, json),
        BenchCommand::LlmLatency { runs, time_scale, seed, json } => {
            crate::bench_llm::run(runs, time_scale, seed, json)
        }
        BenchCommand::LlmReal { base_url, model, suite, json } => {
            crate::bench_llm_real::run(&base_url, &model, suite, json)
        }
    }
}

fn scenes(suite: Option<PathBuf>, prompt: Option<String>, seeds: u64, repeat: u32, json: bool) -> Result<u8, Failure> {
    // A relation suite (`bench/relations/suite.jsonl`): per-relation pass rates.
    if prompt.is_none()
        && let Some(path) = &suite
        && crate::bench_relations::is_suite(path)
    {
        let text = fs_err::read_to_string(path).map_err(|e| Failure::input(e.to_string()))?;
        return crate::bench_relations::run(&crate::bench_relations::parse(&text)?, seeds, json);
    }
    let prompts: Vec<String> = match (&prompt, &suite) {
        (Some(p), _) => vec![p.clone()],
        (None, Some(path)) => parse_suite(&fs_err::read_to_string(path).map_err(|e| Failure::input(e.to_string()))?),
        (None, None) => parse_suite(SUITE),
    };
    if prompts.is_empty() {
        return Err(Failure::input("the suite holds no prompts"));
    }
    let scratch = tempfile::tempdir().map_err(|e| Failure::internal(e.to_string()))?;
    let mut stage_ms: BTreeMap<Stage, Vec<f64>> = BTreeMap::new();
    let mut total = Vec::new();
    let mut v = Validity {
        runs: 0,
        rejected_as_bad_input: 0,
        compiled: 0,
        no_deep_contacts: 0,
        settled_within_1cm: 0,
        verified: 0,
        rules_met: 0,
        objects_requested: 0,
        objects_placed: 0,
    };
    let mut failures = Vec::new();
    let mut n = 0u64;
    for (pi, p) in prompts.iter().enumerate() {
        for seed in 0..seeds.max(1) {
            for _ in 0..repeat.max(1) {
                n += 1;
                let out = scratch.path().join(format!("run{n}"));
                let opts = Options { seed, ..Options::default() };
                let t0 = Instant::now();
                let result = sw_pipeline::generate(p, &out, &opts, &mut |_| {});
                let ms = t0.elapsed().as_secs_f64() * 1000.0;
                v.runs += 1;
                match result {
                    Err(e) if e.exit_code() == 2 => v.rejected_as_bad_input += 1,
                    Err(e) => failures.push(format!("prompt {} seed {seed}: {e}", pi + 1)),
                    Ok(o) => {
                        total.push(ms);
                        for s in &o.timings.stages {
                            stage_ms.entry(s.stage).or_default().push(s.ms);
                        }
                        let r = &o.report;
                        v.objects_requested += u64::from(r.summary.objects_requested);
                        v.objects_placed += u64::from(r.summary.objects_placed);
                        if let Some(ver) = &r.verification {
                            v.compiled += usize::from(ver.compiled);
                            v.no_deep_contacts +=
                                usize::from(ver.initial_contacts.as_ref().is_some_and(|c| c.deep.is_empty()));
                            v.settled_within_1cm +=
                                usize::from(ver.settle.as_ref().is_some_and(|s| s.moved.is_empty() && !s.unstable));
                        }
                        v.rules_met += usize::from(r.violations.iter().all(|x| x.requested));
                        for x in r.violations.iter().filter(|x| !x.requested) {
                            failures.push(format!("prompt {} seed {seed}: rule {}: {}", pi + 1, x.rule, x.message));
                        }
                        if r.status == Status::Verified {
                            v.verified += 1;
                        } else {
                            failures.push(format!(
                                "prompt {} seed {seed}: {:?}: {}",
                                pi + 1,
                                r.status,
                                r.verification.as_ref().map(|x| x.failures.join("; ")).unwrap_or_default()
                            ));
                        }
                    }
                }
                let _ = std::fs::remove_dir_all(&out);
            }
        }
    }
    let result = BenchResult {
        prompts: prompts.len(),
        seeds: seeds.max(1),
        repeat: repeat.max(1),
        stages: stage_ms.iter().map(|(s, xs)| (format!("{s:?}").to_lowercase(), percentiles(xs))).collect(),
        total: percentiles(&total),
        validity: v,
        failures,
    };
    if json {
        print_json(&result);
    } else {
        let mut lines = vec![format!(
            "{} prompt(s) × {} seed(s) × {} repeat(s) = {} runs",
            result.prompts, result.seeds, result.repeat, result.validity.runs
        )];
        lines.push(format!("{:<10} {:>10} {:>10} {:>10}", "stage", "p50 ms", "p95 ms", "max ms"));
        for (s, p) in &result.stages {
            lines.push(format!("{:<10} {:>10.2} {:>10.2} {:>10.2}", s, p.p50_ms, p.p95_ms, p.max_ms));
        }
        lines.push(format!(
            "{:<10} {:>10.2} {:>10.2} {:>10.2}",
            "total", result.total.p50_ms, result.total.p95_ms, result.total.max_ms
        ));
        let x = &result.validity;
        lines.push(format!(
            "compiled {}/{} · no contact > 1 mm {}/{} · settled < 1 cm {}/{} · verified {}/{} · rules met {}/{} · rejected as bad input {} · objects placed {}/{}",
            x.compiled, x.runs, x.no_deep_contacts, x.runs, x.settled_within_1cm, x.runs, x.verified, x.runs, x.rules_met, x.runs, x.rejected_as_bad_input, x.objects_placed, x.objects_requested
        ));
        for f in &result.failures {
            lines.push(format!("failure  {f}"));
        }
        print(&lines.join("\n"));
    }
    Ok(if result.failures.is_empty() { 0 } else { 1 })
}

fn parse_suite(text: &str) -> Vec<String> {
    text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')).map(str::to_string).collect()
}

fn percentiles(xs: &[f64]) -> Percentiles {
    if xs.is_empty() {
        return Percentiles { p50_ms: 0.0, p95_ms: 0.0, max_ms: 0.0 };
    }
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((q * (v.len() - 1) as f64).round() as usize).min(v.len() - 1)];
    let r = |x: f64| (x * 100.0).round() / 100.0;
    Percentiles { p50_ms: r(at(0.5)), p95_ms: r(at(0.95)), max_ms: r(v[v.len() - 1]) }
}

#[derive(Debug, Serialize)]
struct AssetTiming {
    category: &'static str,
    p50_ms: f64,
    p95_ms: f64,
    max_ms: f64,
    /// Visual triangles and collision primitives at seed 0.
    triangles: usize,
    primitives: usize,
}

#[derive(Debug, Serialize)]
struct AssetsResult {
    categories: usize,
    seeds: u64,
    /// Over every (category, seed) generation.
    all: Percentiles,
    /// The slowest category's median.
    worst_median_ms: f64,
    worst_category: &'static str,
    per_category: Vec<AssetTiming>,
}

/// Times `sw_catalog::generate` for every category and seed (one warm-up call first).
fn assets(seeds: u64, only: &[String], json: bool) -> Result<u8, Failure> {
    let seeds = seeds.clamp(1, 100_000);
    let cats: Vec<&'static sw_catalog::Category> = if only.is_empty() {
        sw_catalog::categories().iter().collect()
    } else {
        only.iter()
            .map(|n| {
                sw_catalog::find(&n.trim().to_lowercase().replace([' ', '-'], "_")).ok_or_else(|| {
                    Failure::input(format!("unknown asset category '{n}' (see `scenewright assets list`)"))
                })
            })
            .collect::<Result<_, _>>()?
    };
    let mut all = Vec::new();
    let mut per_category = Vec::new();
    for cat in cats {
        let make = |seed: u64| sw_catalog::generate(&sw_catalog::AssetRequest::new(cat.name, seed));
        let first = make(0).map_err(|e| Failure::internal(e.to_string()))?;
        let mut times = Vec::with_capacity(seeds as usize);
        for seed in 0..seeds {
            let t0 = Instant::now();
            let a = make(seed).map_err(|e| Failure::internal(e.to_string()))?;
            times.push(t0.elapsed().as_secs_f64() * 1000.0);
            std::hint::black_box(a);
        }
        all.extend_from_slice(&times);
        let p = percentiles_fine(&times);
        per_category.push(AssetTiming {
            category: cat.name,
            p50_ms: p.p50_ms,
            p95_ms: p.p95_ms,
            max_ms: p.max_ms,
            triangles: first.links.iter().flat_map(|l| &l.visuals).map(|v| v.mesh.triangles.len()).sum(),
            primitives: first.links.iter().map(|l| l.collisions.len()).sum(),
        });
    }
    let worst = per_category.iter().max_by(|a, b| a.p50_ms.total_cmp(&b.p50_ms));
    let result = AssetsResult {
        categories: per_category.len(),
        seeds,
        all: percentiles_fine(&all),
        worst_median_ms: worst.map_or(0.0, |w| w.p50_ms),
        worst_category: worst.map_or("", |w| w.category),
        per_category,
    };
    if json {
        print_json(&result);
    } else {
        let mut lines = vec![format!("{} categories × {} seeds", result.categories, result.seeds)];
        lines.push(format!(
            "{:<20} {:>9} {:>9} {:>9} {:>9} {:>5}",
            "category", "p50 ms", "p95 ms", "max ms", "tris", "prims"
        ));
        for t in &result.per_category {
            lines.push(format!(
                "{:<20} {:>9.3} {:>9.3} {:>9.3} {:>9} {:>5}",
                t.category, t.p50_ms, t.p95_ms, t.max_ms, t.triangles, t.primitives
            ));
        }
        lines.push(format!(
            "{:<20} {:>9.3} {:>9.3} {:>9.3}",
            "all", result.all.p50_ms, result.all.p95_ms, result.all.max_ms
        ));
        lines.push(format!("slowest median: {} {:.3} ms", result.worst_category, result.worst_median_ms));
        print(&lines.join("\n"));
    }
    Ok(0)
}

/// Percentiles rounded to 1 µs (asset generation takes well under a millisecond).
fn percentiles_fine(xs: &[f64]) -> Percentiles {
    let p = percentiles_raw(xs);
    let r = |x: f64| (x * 1000.0).round() / 1000.0;
    Percentiles { p50_ms: r(p.0), p95_ms: r(p.1), max_ms: r(p.2) }
}

fn percentiles_raw(xs: &[f64]) -> (f64, f64, f64) {
    if xs.is_empty() {
        return (0.0, 0.0, 0.0);
    }
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((q * (v.len() - 1) as f64).round() as usize).min(v.len() - 1)];
    (at(0.5), at(0.95), v[v.len() - 1])
}
