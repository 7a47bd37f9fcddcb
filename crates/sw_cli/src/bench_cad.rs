//! `bench cad --suite standard_100|abstract_45|FILE`: every prompt of a CAD suite through
//! a writer and the sandboxed runner — execution rate, retries, failure kinds, extent and
//! volume errors against the suite's references (and Chamfer distance where a reference
//! mesh is given), and the runner's warm latency. The writer is the offline template
//! synthesizer, or (`--writer llm`) the CAD stage's model in the generation loop: up to
//! three attempts, each failure fed back, as the paper measures its retries.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use serde::Serialize;
use sw_forge::failure::FailureKind;
use sw_forge::generate::{CodeWriter, ForgeOutcome, LlmWriter, LoopConfig, PartRequest, forge};
use sw_forge::metrics::{chamfer_distance, extent_error};
use sw_forge::runner::{CadJob, CadRunner};
use sw_forge::{mesh_io, synth, validate};

use crate::Failure;
use crate::output::{print, print_json};

const STANDARD_100: &str = include_str!("../../../bench/cad/standard_100.tsv");
const STANDARD_100_REFS: &str = include_str!("../../../bench/cad/standard_100.refs.tsv");
const ABSTRACT_45: &str = include_str!("../../../bench/cad/abstract_45.tsv");

/// Size tolerance and volume tolerance of a pass.
const SIZE_TOL: f64 = 0.01;
const VOLUME_TOL: f64 = 0.02;

#[derive(Debug, Clone)]
struct Prompt {
    id: String,
    tier: String,
    text: String,
}

#[derive(Debug, Clone)]
struct Reference {
    size: [f64; 3],
    volume: Option<f64>,
    mesh: Option<PathBuf>,
}

#[derive(Debug, Clone, Serialize)]
struct Outcome {
    id: String,
    tier: String,
    template: Option<String>,
    /// The code ran and gave a closed solid.
    executed: bool,
    /// Template: re-runs after a runner failure (a timeout or a worker that died). Model:
    /// attempts after the first (each after a failure fed back).
    retries: u32,
    /// Why it failed, when it did (the taxonomy's kind).
    failure: Option<FailureKind>,
    message: Option<String>,
    /// Against the suite's reference (sorted extents).
    bbox_error: Option<f64>,
    volume_error: Option<f64>,
    chamfer_mm: Option<f64>,
    /// Both within tolerance of the reference.
    pass: Option<bool>,
    roundtrip_ms: Option<f64>,
}

#[derive(Debug, Default, Serialize)]
struct TierSummary {
    prompts: usize,
    executed: usize,
    /// Prompts that needed more than one attempt.
    retried: usize,
    with_reference: usize,
    bbox_within_1pct: usize,
    volume_within_2pct: usize,
    passed: usize,
    retries: u32,
    failures: BTreeMap<String, usize>,
    median_bbox_error: Option<f64>,
    median_volume_error: Option<f64>,
}

#[derive(Debug, Serialize)]
struct Latency {
    jobs: usize,
    median_ms: f64,
    p95_ms: f64,
    min_ms: f64,
}

/// The model's calls, when it wrote the code.
#[derive(Debug, Serialize)]
struct ModelCalls {
    model: String,
    calls: usize,
    tokens_in: u64,
    tokens_out: u64,
    median_latency_ms: Option<f64>,
}

#[derive(Debug, Serialize)]
struct CadBench {
    suite: String,
    /// `template` or `llm:<model>`.
    writer: String,
    workers: usize,
    wall_s: f64,
    parts_per_s: f64,
    tiers: BTreeMap<String, TierSummary>,
    /// The target subset: T1 and T2's washers and hole-pattern plates.
    target: TierSummary,
    /// Warm runner, one simple part per job (T1 parts that executed, repeated).
    warm_latency: Option<Latency>,
    #[serde(skip_serializing_if = "Option::is_none")]
    model_calls: Option<ModelCalls>,
    outcomes: Vec<Outcome>,
}

fn parse_suite(text: &str) -> Vec<Prompt> {
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .filter_map(|l| {
            let mut cols = l.splitn(3, '\t');
            let (id, tier, text) = (cols.next()?, cols.next()?, cols.next()?);
            Some(Prompt { id: id.trim().into(), tier: tier.trim().into(), text: text.trim().into() })
        })
        .collect()
}

fn parse_refs(text: &str, base: Option<&Path>) -> BTreeMap<String, Reference> {
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .filter_map(|l| {
            let c: Vec<&str> = l.split('\t').map(str::trim).collect();
            let num = |i: usize| c.get(i).and_then(|s| s.parse::<f64>().ok());
            let size = [num(1)?, num(2)?, num(3)?];
            let mesh = c.get(5).filter(|m| **m != "-" && !m.is_empty()).map(|m| match base {
                Some(b) => b.join(m),
                None => PathBuf::from(m),
            });
            Some((c.first()?.to_string(), Reference { size, volume: num(4), mesh }))
        })
        .collect()
}

/// A suite's name, prompts and references by id.
type Suite = (String, Vec<Prompt>, BTreeMap<String, Reference>);

fn load(suite: &str) -> Result<Suite, Failure> {
    match suite {
        "standard_100" => Ok((suite.into(), parse_suite(STANDARD_100), parse_refs(STANDARD_100_REFS, None))),
        "abstract_45" => Ok((suite.into(), parse_suite(ABSTRACT_45), BTreeMap::new())),
        path => {
            let p = Path::new(path);
            let text = fs_err::read_to_string(p).map_err(|e| {
                Failure::input(format!("unknown suite '{path}' (standard_100, abstract_45 or a TSV file): {e}"))
            })?;
            let prompts = parse_suite(&text);
            if prompts.is_empty() {
                return Err(Failure::input(format!("{path}: no prompts (id<TAB>tier<TAB>prompt per line)")));
            }
            let refs_path = p.with_extension("refs.tsv");
            let refs = match fs_err::read_to_string(&refs_path) {
                Ok(t) => parse_refs(&t, p.parent()),
                Err(_) => BTreeMap::new(),
            };
            Ok((path.into(), prompts, refs))
        }
    }
}

fn is_target(p: &Prompt) -> bool {
    let t = p.text.to_ascii_lowercase();
    p.tier == "T1" || (p.tier == "T2" && (t.contains("washer") || (t.contains("plate") && t.contains("hole"))))
}

fn blank(p: &Prompt) -> Outcome {
    Outcome {
        id: p.id.clone(),
        tier: p.tier.clone(),
        template: None,
        executed: false,
        retries: 0,
        failure: None,
        message: None,
        bbox_error: None,
        volume_error: None,
        chamfer_mm: None,
        pass: None,
        roundtrip_ms: None,
    }
}

/// One prompt through the template synthesizer and the runner.
fn one(runner: &CadRunner, p: &Prompt, reference: Option<&Reference>) -> Outcome {
    let mut o = blank(p);
    let s = match synth::synthesize(&p.text) {
        Ok(s) => s,
        Err(e) => {
            o.failure = Some(FailureKind::Writer);
            o.message = Some(e.to_string());
            return o;
        }
    };
    o.template = Some(s.template.clone());
    let job = CadJob::cadquery(s.code.clone());
    let mut run = runner.run(&job);
    // A runner failure (not the code's) is retried once.
    while let Err(e) = &run {
        if o.retries >= 1 || !matches!(e.failure.kind, FailureKind::Runner | FailureKind::Timeout) {
            break;
        }
        o.retries += 1;
        run = runner.run(&job);
    }
    let mut run = match run {
        Ok(r) => r,
        Err(e) => {
            o.failure = Some(e.failure.kind);
            o.message = Some(e.failure.message.clone());
            return o;
        }
    };
    o.roundtrip_ms = Some(run.timings.roundtrip_ms);
    mesh_io::drop_collapsed_triangles(&mut run.mesh);
    // Executed: the code made a closed solid with positive volume.
    if let Err(f) = validate::validate(&run.mesh, &validate::Target::default()) {
        o.failure = Some(f.kind);
        o.message = Some(f.message);
        return o;
    }
    o.executed = true;
    // The synthesizer's own promise (size, volume, holes).
    if let Err(f) = validate::validate(&run.mesh, &s.target()) {
        o.failure = Some(f.kind);
        o.message = Some(f.message);
    }
    compare(&mut o, &run.mesh, reference);
    o
}

/// One prompt through the generation loop with the model as writer: the prompt is the
/// description (its dimensions are in its words), up to three attempts.
fn one_by_model(runner: &CadRunner, writer: &dyn CodeWriter, p: &Prompt, reference: Option<&Reference>) -> Outcome {
    let mut o = blank(p);
    o.template = Some(writer.name());
    let request = PartRequest { description: p.text.clone(), size_m: None };
    let t = Instant::now();
    match forge(runner, writer, &request, LoopConfig::default()) {
        ForgeOutcome::Made(part) => {
            o.retries = part.attempts.len().saturating_sub(1) as u32;
            o.roundtrip_ms = Some(t.elapsed().as_secs_f64() * 1e3);
            o.executed = true;
            compare(&mut o, &part.mesh_mm, reference);
        }
        ForgeOutcome::Failed { attempts, .. } => {
            o.retries = attempts.len().saturating_sub(1) as u32;
            if let Some(f) = attempts.last().and_then(|a| a.failure.as_ref()) {
                o.failure = Some(f.kind);
                o.message = Some(f.message.lines().next().unwrap_or("").to_string());
            }
        }
    }
    o
}

/// Measures an executed part against the suite's reference, when there is one.
fn compare(o: &mut Outcome, mesh: &sw_geom::Mesh, reference: Option<&Reference>) {
    let Some(r) = reference else { return };
    let measured = validate::measure(mesh);
    let be = extent_error(measured.size, r.size);
    o.bbox_error = Some(be);
    let ve = r.volume.filter(|v| *v > 0.0).map(|v| (measured.volume - v).abs() / v);
    o.volume_error = ve;
    o.pass = Some(be <= SIZE_TOL && ve.is_none_or(|e| e <= VOLUME_TOL));
    if let Some(path) = &r.mesh {
        match mesh_io::read_untrusted_stl(path, 256 << 20) {
            Ok(reference_mesh) => o.chamfer_mm = chamfer_distance(mesh, &reference_mesh, 2000),
            Err(e) => o.message = Some(format!("reference mesh: {e}")),
        }
    }
    if o.pass == Some(false) && o.failure.is_none() {
        o.failure = Some(if be > SIZE_TOL { FailureKind::ScaleMismatch } else { FailureKind::SemanticMismatch });
        o.message = Some(format!(
            "against the reference: extents off by {:.2} %, volume by {}",
            100.0 * be,
            ve.map_or("-".into(), |v| format!("{:.2} %", 100.0 * v))
        ));
    }
}

fn median(mut v: Vec<f64>) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    Some(v[v.len() / 2])
}

fn summarize<'a>(outcomes: impl Iterator<Item = &'a Outcome>) -> TierSummary {
    let mut s = TierSummary::default();
    let (mut be, mut ve) = (Vec::new(), Vec::new());
    for o in outcomes {
        s.prompts += 1;
        s.executed += usize::from(o.executed);
        s.retries += o.retries;
        s.retried += usize::from(o.retries > 0);
        if let Some(k) = o.failure {
            *s.failures.entry(k.name().to_string()).or_default() += 1;
        }
        if o.pass.is_some() {
            s.with_reference += 1;
        }
        if let Some(b) = o.bbox_error {
            s.bbox_within_1pct += usize::from(b <= SIZE_TOL);
            be.push(b);
        }
        if let Some(v) = o.volume_error {
            s.volume_within_2pct += usize::from(v <= VOLUME_TOL);
            ve.push(v);
        }
        s.passed += usize::from(o.pass == Some(true));
    }
    s.median_bbox_error = median(be);
    s.median_volume_error = median(ve);
    s
}

/// Who writes the code.
#[derive(Debug, Clone)]
pub(crate) enum Writer {
    Template,
    /// The CAD stage's model of this configuration.
    Model(sw_llm::LlmConfig),
}

pub(crate) fn run(
    suite: &str,
    writer: Writer,
    workers: usize,
    latency_repeat: usize,
    json: bool,
) -> Result<u8, Failure> {
    let (name, prompts, refs) = load(suite)?;
    let model = match &writer {
        Writer::Template => None,
        Writer::Model(cfg) => {
            if cfg.endpoint(sw_llm::LlmStage::Cad).is_none() {
                return Err(Failure::input(
                    "--writer llm needs a model for the CAD stage: set SCENEWRIGHT_LLM_BASE_URL and SCENEWRIGHT_LLM_MODEL \
                     (or SCENEWRIGHT_LLM_CAD_MODEL), or pass --llm-config FILE",
                ));
            }
            Some(LlmWriter::new(sw_llm::Client::new(cfg.clone())))
        }
    };
    let runner = crate::cmd_forge::start_runner(workers)?;
    // Every worker warm before the clock starts.
    runner.wait_idle(workers.max(1), std::time::Duration::from_secs(120));
    let started = Instant::now();
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Outcome>> = Mutex::new(Vec::with_capacity(prompts.len()));
    std::thread::scope(|scope| {
        for _ in 0..workers.max(1) {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(p) = prompts.get(i) else { break };
                    let o = match &model {
                        Some(w) => one_by_model(&runner, w, p, refs.get(&p.id)),
                        None => one(&runner, p, refs.get(&p.id)),
                    };
                    results.lock().unwrap_or_else(|e| e.into_inner()).push(o);
                }
            });
        }
    });
    let wall_s = started.elapsed().as_secs_f64();
    let mut outcomes = results.into_inner().unwrap_or_else(|e| e.into_inner());
    outcomes.sort_by(|a, b| a.id.cmp(&b.id));

    // Warm latency: the executed T1 parts again, one at a time.
    let simple: Vec<&Prompt> =
        prompts.iter().filter(|p| p.tier == "T1" && outcomes.iter().any(|o| o.id == p.id && o.executed)).collect();
    let warm_latency = if latency_repeat > 0 && !simple.is_empty() {
        let mut times = Vec::new();
        for _ in 0..latency_repeat {
            for p in &simple {
                let Ok(s) = synth::synthesize(&p.text) else { continue };
                let t = Instant::now();
                if runner.run(&CadJob::cadquery(s.code)).is_ok() {
                    times.push(t.elapsed().as_secs_f64() * 1e3);
                }
            }
        }
        times.sort_by(f64::total_cmp);
        (!times.is_empty()).then(|| Latency {
            jobs: times.len(),
            median_ms: times[times.len() / 2],
            p95_ms: times[(times.len() * 95 / 100).min(times.len() - 1)],
            min_ms: times[0],
        })
    } else {
        None
    };

    let mut tiers = BTreeMap::new();
    let tier_names: Vec<String> = {
        let mut t: Vec<String> = outcomes.iter().map(|o| o.tier.clone()).collect();
        t.dedup();
        t
    };
    for t in &tier_names {
        tiers.insert(t.clone(), summarize(outcomes.iter().filter(|o| &o.tier == t)));
    }
    let target_ids: Vec<&str> = prompts.iter().filter(|p| is_target(p)).map(|p| p.id.as_str()).collect();
    let target = summarize(outcomes.iter().filter(|o| target_ids.contains(&o.id.as_str())));
    let model_calls = model.as_ref().map(|w| {
        let calls = w.take_calls();
        let mut latency: Vec<f64> = calls.iter().map(|c| c.latency_ms).collect();
        ModelCalls {
            model: calls.first().map_or_else(String::new, |c| c.model.clone()),
            calls: calls.len(),
            tokens_in: calls.iter().map(|c| c.tokens_in).sum(),
            tokens_out: calls.iter().map(|c| c.tokens_out).sum(),
            median_latency_ms: median(std::mem::take(&mut latency)),
        }
    });
    let bench = CadBench {
        suite: name,
        writer: model.as_ref().map_or_else(|| "template".to_string(), CodeWriter::name),
        workers: workers.max(1),
        wall_s,
        parts_per_s: outcomes.len() as f64 / wall_s.max(1e-9),
        tiers,
        target,
        warm_latency,
        model_calls,
        outcomes,
    };
    if json {
        print_json(&bench);
    } else {
        print(&render(&bench));
    }
    Ok(0)
}

fn pct(n: usize, d: usize) -> String {
    if d == 0 { "-".into() } else { format!("{:.0} %", 100.0 * n as f64 / d as f64) }
}

fn render(b: &CadBench) -> String {
    let mut s = format!(
        "suite {} · writer {} · {} prompts · {} worker(s) · {:.1} s wall ({:.1} parts/s)\n\n",
        b.suite,
        b.writer,
        b.outcomes.len(),
        b.workers,
        b.wall_s,
        b.parts_per_s
    );
    s.push_str(
        "tier      prompts executed  ref  bbox≤1%  vol≤2%  pass  retried  median bbox err  median vol err  failures\n",
    );
    let mut line = |name: &str, t: &TierSummary| {
        let fails: Vec<String> = t.failures.iter().map(|(k, n)| format!("{k} {n}")).collect();
        s.push_str(&format!(
            "{name:<9} {:>7} {:>8} {:>4} {:>8} {:>7} {:>5} {:>8} {:>16} {:>15}  {}\n",
            t.prompts,
            pct(t.executed, t.prompts),
            t.with_reference,
            pct(t.bbox_within_1pct, t.with_reference),
            pct(t.volume_within_2pct, t.with_reference),
            pct(t.passed, t.with_reference),
            pct(t.retried, t.prompts),
            t.median_bbox_error.map_or("-".into(), |e| format!("{:.3} %", 100.0 * e)),
            t.median_volume_error.map_or("-".into(), |e| format!("{:.3} %", 100.0 * e)),
            fails.join(", ")
        ));
    };
    for (name, t) in &b.tiers {
        line(name, t);
    }
    line("target", &b.target);
    if let Some(l) = &b.warm_latency {
        s.push_str(&format!(
            "\nwarm runner, simple parts: median {:.0} ms · p95 {:.0} ms · min {:.0} ms over {} jobs\n",
            l.median_ms, l.p95_ms, l.min_ms, l.jobs
        ));
    }
    if let Some(m) = &b.model_calls {
        s.push_str(&format!(
            "\nmodel {}: {} calls · {} tokens in / {} out · median latency {}\n",
            m.model,
            m.calls,
            m.tokens_in,
            m.tokens_out,
            m.median_latency_ms.map_or("-".into(), |l| format!("{l:.0} ms"))
        ));
    }
    let failed: Vec<&Outcome> = b.outcomes.iter().filter(|o| o.failure.is_some()).collect();
    if !failed.is_empty() {
        s.push_str("\nnot passed:\n");
        for o in failed {
            s.push_str(&format!(
                "  {} {} {}: {}\n",
                o.id,
                o.template.as_deref().unwrap_or("-"),
                o.failure.map_or("", |k| k.name()),
                o.message.as_deref().unwrap_or("")
            ));
        }
    }
    s
}
