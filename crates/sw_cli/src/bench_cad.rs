//! `bench cad --suite standard_100|abstract_45|features|FILE`: every prompt of a CAD suite
//! through a writer and the sandboxed runner. Per tier: how many were made (executed, a
//! closed solid), how many are within tolerance of the suite's independent reference
//! (bounding box within 1 %, volume within 2 %), the Chamfer distance to the reference
//! mesh (made from the suite's reference programs, after aligning bounding boxes), and
//! for free-form suites whether the size is plausible; the runner's warm latency. The
//! writer is the offline synthesizer (the feature language, free-form compositions, the
//! catalog), or (`--writer llm`) the CAD stage's model in the generation loop: up to three
//! attempts, each failure fed back, as the paper measures its retries. With
//! `SCENEWRIGHT_CAD_SHEET=FILE.png` the made parts are drawn on a contact sheet.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use serde::Serialize;
use sw_forge::failure::FailureKind;
use sw_forge::freeform::{Offline, catalog_mesh_mm, offline};
use sw_forge::generate::{CodeWriter, ForgeOutcome, LlmWriter, LoopConfig, PartRequest, forge};
use sw_forge::metrics::extent_error;
use sw_forge::runner::{CadJob, CadRunner};
use sw_forge::suite::{
    Plausible, Prompt, Reference, Tile, chamfer_aligned, contact_sheet, parse_programs, parse_refs, parse_sizes,
    parse_suite,
};
use sw_forge::{mesh_io, synth, validate};
use sw_geom::Mesh;

use crate::Failure;
use crate::output::{print, print_json};

const STANDARD_100: &str = include_str!("../../../bench/cad/standard_100.tsv");
const STANDARD_100_REFS: &str = include_str!("../../../bench/cad/standard_100.refs.tsv");
const STANDARD_100_PROGRAMS: &str = include_str!("../../../bench/cad/standard_100.ref.py");
const FEATURES: &str = include_str!("../../../bench/cad/features.tsv");
const FEATURES_REFS: &str = include_str!("../../../bench/cad/features.refs.tsv");
const FEATURES_PROGRAMS: &str = include_str!("../../../bench/cad/features.ref.py");
const ABSTRACT_45: &str = include_str!("../../../bench/cad/abstract_45.tsv");
const ABSTRACT_45_SIZES: &str = include_str!("../../../bench/cad/abstract_45.sizes.tsv");

/// Size tolerance and volume tolerance of a pass.
const SIZE_TOL: f64 = 0.01;
const VOLUME_TOL: f64 = 0.02;
/// Surface samples per mesh for the Chamfer distance.
const CHAMFER_SAMPLES: usize = 2000;

#[derive(Debug, Clone, Serialize)]
struct Outcome {
    id: String,
    tier: String,
    /// What made it: `features`, `freeform:<object>`, `catalog:<category>`, or the model.
    made_by: Option<String>,
    /// The part was made: the code ran and gave a closed solid (or the catalog made it).
    executed: bool,
    /// Template: re-runs after a runner failure. Model: attempts after the first.
    retries: u32,
    failure: Option<FailureKind>,
    message: Option<String>,
    size_mm: Option<[f64; 3]>,
    bbox_error: Option<f64>,
    volume_error: Option<f64>,
    /// Within 1 % bbox and 2 % volume of the reference.
    pass: Option<bool>,
    chamfer_mm: Option<f64>,
    /// Chamfer distance as a share of the reference's bounding-box diagonal.
    chamfer_rel: Option<f64>,
    /// Free-form: the largest extent is one a real object of the kind has.
    plausible: Option<bool>,
    roundtrip_ms: Option<f64>,
    /// Refused by the writer with the words it could not read (not made, said why).
    refused_with_words: bool,
    /// The writer's own check of the executed part failed (not handed out).
    own_check_failed: bool,
    /// The suite has a reference for it.
    has_reference: bool,
    /// The manner the prompt is written in, where the suite says.
    #[serde(skip_serializing_if = "Option::is_none")]
    style: Option<String>,
    /// A prompt that must be refused, quoting some of these words.
    #[serde(skip_serializing_if = "Option::is_none")]
    refuse_words: Option<String>,
    #[serde(skip)]
    mesh: Option<Mesh>,
}

/// What a prompt came to, against its reference: the part made exactly (a closed solid,
/// bounding box within 1 %, volume within 2 %); refused with the words it could not read;
/// made wrong (handed out, but not the part the reference is); or failed otherwise (the
/// code did not run, the mesh is no solid, or the part failed its own check).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
enum Verdict {
    Exact,
    Refused,
    Wrong,
    Failed,
}

impl Outcome {
    /// The verdict, where the prompt has a reference or must be refused. A prompt that
    /// must be refused passes when the refusal quotes some of its words, and any part made
    /// for it is a wrong one.
    fn verdict(&self) -> Option<Verdict> {
        if let Some(words) = &self.refuse_words {
            return Some(if self.made_by.is_some() {
                Verdict::Wrong
            } else if self.refused_with_words && quotes(self.message.as_deref().unwrap_or(""), words) {
                Verdict::Refused
            } else {
                Verdict::Failed
            });
        }
        if self.refused_with_words {
            return Some(Verdict::Refused);
        }
        if !self.has_reference {
            return None;
        }
        let Some(pass) = self.pass else { return Some(Verdict::Failed) };
        Some(match (self.executed, pass, self.own_check_failed) {
            (true, true, false) => Verdict::Exact,
            (true, false, false) => Verdict::Wrong,
            _ => Verdict::Failed,
        })
    }
}

#[derive(Debug, Default, Serialize)]
struct TierSummary {
    prompts: usize,
    executed: usize,
    retried: usize,
    with_reference: usize,
    bbox_within_1pct: usize,
    volume_within_2pct: usize,
    /// Both, of those with a reference.
    passed: usize,
    with_chamfer: usize,
    median_chamfer_mm: Option<f64>,
    max_chamfer_mm: Option<f64>,
    median_chamfer_rel: Option<f64>,
    with_plausibility: usize,
    plausible: usize,
    /// Against a reference: exact, refused with the words, made wrong, failed otherwise.
    exact: usize,
    refused_with_words: usize,
    wrong: usize,
    failed: usize,
    failures: BTreeMap<String, usize>,
}

#[derive(Debug, Serialize)]
struct Latency {
    jobs: usize,
    median_ms: f64,
    p95_ms: f64,
    min_ms: f64,
}

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
    writer: String,
    workers: usize,
    wall_s: f64,
    parts_per_s: f64,
    tiers: BTreeMap<String, TierSummary>,
    /// By the manner prompts are written in, and by what they expect (made or refused),
    /// where the suite says.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    styles: BTreeMap<String, TierSummary>,
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    expected: BTreeMap<String, TierSummary>,
    all: TierSummary,
    /// Every part that ran code, in the suite run (parallel workers).
    part_latency: Option<Latency>,
    /// Warm runner, one part per job, the suite's first-tier parts run again one at a time.
    warm_latency: Option<Latency>,
    #[serde(skip_serializing_if = "Option::is_none")]
    model_calls: Option<ModelCalls>,
    outcomes: Vec<Outcome>,
}

/// A suite: its prompts, reference sizes, reference programs and plausible sizes.
struct Suite {
    name: String,
    prompts: Vec<Prompt>,
    refs: BTreeMap<String, Reference>,
    programs: BTreeMap<String, String>,
    sizes: BTreeMap<String, Plausible>,
}

fn load(suite: &str) -> Result<Suite, Failure> {
    let bundled = |name: &str, p: &str, r: &str, g: &str, z: &str| Suite {
        name: name.into(),
        prompts: parse_suite(p),
        refs: parse_refs(r),
        programs: parse_programs(g),
        sizes: parse_sizes(z),
    };
    match suite {
        "standard_100" => Ok(bundled(suite, STANDARD_100, STANDARD_100_REFS, STANDARD_100_PROGRAMS, "")),
        "features" => Ok(bundled(suite, FEATURES, FEATURES_REFS, FEATURES_PROGRAMS, "")),
        "abstract_45" => Ok(bundled(suite, ABSTRACT_45, "", "", ABSTRACT_45_SIZES)),
        path => {
            let p = Path::new(path);
            let text = fs_err::read_to_string(p).map_err(|e| {
                Failure::input(format!(
                    "unknown suite '{path}' (standard_100, abstract_45, features or a TSV file): {e}"
                ))
            })?;
            let prompts = parse_suite(&text);
            if prompts.is_empty() {
                return Err(Failure::input(format!("{path}: no prompts (id<TAB>tier<TAB>prompt per line)")));
            }
            // Beside it: STEM.refs.tsv (else refs.tsv in its folder), STEM.ref.py, STEM.sizes.tsv.
            let side = |ext: &str| fs_err::read_to_string(p.with_extension(ext)).unwrap_or_default();
            let mut refs = side("refs.tsv");
            if refs.trim().is_empty() {
                refs = std::fs::read_to_string(p.with_file_name("refs.tsv")).unwrap_or_default();
            }
            // Only the references of this file's prompts.
            let ids: std::collections::BTreeSet<&str> = prompts.iter().map(|q| q.id.as_str()).collect();
            let refs = parse_refs(&refs).into_iter().filter(|(id, _)| ids.contains(id.as_str())).collect();
            Ok(Suite {
                name: path.into(),
                prompts,
                refs,
                programs: parse_programs(&side("ref.py")),
                sizes: parse_sizes(&side("sizes.tsv")),
            })
        }
    }
}

fn blank(p: &Prompt) -> Outcome {
    Outcome {
        id: p.id.clone(),
        tier: p.tier.clone(),
        style: p.style.clone(),
        refuse_words: p.refuse_words.clone(),
        made_by: None,
        executed: false,
        retries: 0,
        failure: None,
        message: None,
        size_mm: None,
        bbox_error: None,
        volume_error: None,
        pass: None,
        chamfer_mm: None,
        chamfer_rel: None,
        plausible: None,
        roundtrip_ms: None,
        refused_with_words: false,
        own_check_failed: false,
        has_reference: false,
        mesh: None,
    }
}

/// Whether a refusal (`could not read "…": …`) quotes a word or number of `words`.
fn quotes(message: &str, words: &str) -> bool {
    const COMMON: &[&str] = &["a", "an", "the", "of", "with", "and", "mm", "in", "on", "to", "x"];
    let quoted = message.split('"').nth(1).unwrap_or("");
    let toks = |t: &str| -> Vec<String> {
        t.to_lowercase()
            .split(|c: char| !(c.is_alphanumeric() || c == '.' || c == '/'))
            .map(|w| w.trim_matches('.').to_string())
            .filter(|w| !w.is_empty() && !COMMON.contains(&w.as_str()))
            .collect()
    };
    let want = toks(words);
    toks(quoted).iter().any(|w| want.contains(w))
}

/// Runs code, retrying once when the runner (not the code) failed.
fn run_code(runner: &CadRunner, code: &str, o: &mut Outcome) -> Option<Mesh> {
    let job = CadJob::cadquery(code.to_string());
    let mut run = runner.run(&job);
    while let Err(e) = &run {
        if o.retries >= 1 || !matches!(e.failure.kind, FailureKind::Runner | FailureKind::Timeout) {
            break;
        }
        o.retries += 1;
        run = runner.run(&job);
    }
    match run {
        Ok(mut r) => {
            o.roundtrip_ms = Some(r.timings.roundtrip_ms);
            mesh_io::drop_collapsed_triangles(&mut r.mesh);
            Some(r.mesh)
        }
        Err(e) => {
            o.failure = Some(e.failure.kind);
            o.message = Some(e.failure.message.lines().next().unwrap_or("").to_string());
            None
        }
    }
}

/// One prompt through the offline synthesizer (and the runner for code).
fn one(runner: &CadRunner, p: &Prompt) -> Outcome {
    let mut o = blank(p);
    let (mesh, promise) = match offline(&p.text) {
        Ok(Offline::Code(s)) => {
            o.made_by = Some(s.template.clone());
            (run_code(runner, &s.code, &mut o), Some(s))
        }
        Ok(Offline::Catalog { category, asset }) => {
            o.made_by = Some(format!("catalog:{category}"));
            (Some(catalog_mesh_mm(&asset)), None)
        }
        Err(e) => {
            o.failure = Some(FailureKind::Writer);
            o.refused_with_words = matches!(e, synth::SynthError::Unread { .. });
            o.message = Some(e.to_string());
            return o;
        }
    };
    let Some(mesh) = mesh else { return o };
    // Executed: a closed solid with positive volume.
    if let Err(f) = validate::validate(&mesh, &validate::Target::default()) {
        o.failure = Some(f.kind);
        o.message = Some(f.message);
        return o;
    }
    o.executed = true;
    // The synthesizer's own promise (its certain extents, its volume when exact).
    if let Some(s) = promise
        && let Err(f) = validate::validate(&mesh, &s.target())
    {
        o.failure = Some(f.kind);
        o.own_check_failed = true;
        o.message = Some(format!("against its own promise: {}", f.message));
    }
    o.size_mm = Some(mesh.bounds().size());
    o.mesh = Some(mesh);
    o
}

/// One prompt through the generation loop with the model as writer.
fn one_by_model(runner: &CadRunner, writer: &dyn CodeWriter, p: &Prompt) -> Outcome {
    let mut o = blank(p);
    o.made_by = Some(writer.name());
    let request = PartRequest { description: p.text.clone(), size_m: None };
    let t = Instant::now();
    match forge(runner, writer, &request, LoopConfig::default()) {
        ForgeOutcome::Made(part) => {
            o.retries = part.attempts.len().saturating_sub(1) as u32;
            o.roundtrip_ms = Some(t.elapsed().as_secs_f64() * 1e3);
            o.executed = true;
            o.size_mm = Some(part.mesh_mm.bounds().size());
            o.mesh = Some(part.mesh_mm);
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

/// Measures an executed part against the suite's reference and plausible size.
fn compare(
    o: &mut Outcome,
    reference: Option<&Reference>,
    reference_mesh: Option<&Mesh>,
    plausible: Option<&Plausible>,
) {
    o.has_reference = reference.is_some();
    let Some(mesh) = o.mesh.as_ref() else { return };
    let measured = validate::measure(mesh);
    if let Some(r) = reference {
        let be = extent_error(measured.size, r.size);
        let ve = r.volume.filter(|v| *v > 0.0).map(|v| (measured.volume - v).abs() / v);
        o.bbox_error = Some(be);
        o.volume_error = ve;
        o.pass = Some(be <= SIZE_TOL && ve.is_none_or(|e| e <= VOLUME_TOL));
        if o.pass == Some(false) && o.failure.is_none() {
            o.failure = Some(if be > SIZE_TOL { FailureKind::ScaleMismatch } else { FailureKind::SemanticMismatch });
            o.message = Some(format!(
                "against the reference: extents off by {:.2} %, volume by {}",
                100.0 * be,
                ve.map_or("-".into(), |v| format!("{:.2} %", 100.0 * v))
            ));
        }
    }
    if let Some(rm) = reference_mesh
        && let Some((d, rel)) = chamfer_aligned(mesh, rm, CHAMFER_SAMPLES)
    {
        o.chamfer_mm = Some(d);
        o.chamfer_rel = Some(rel);
    }
    if let Some(pl) = plausible {
        let largest = measured.size.iter().copied().fold(0.0, f64::max);
        let ok = (pl.min..=pl.max).contains(&largest);
        o.plausible = Some(ok);
        if !ok && o.failure.is_none() {
            o.failure = Some(FailureKind::ScaleMismatch);
            o.message = Some(format!("{largest:.0} mm across, not a plausible {} ({}–{} mm)", pl.what, pl.min, pl.max));
        }
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
    let (mut cd, mut cr) = (Vec::new(), Vec::new());
    for o in outcomes {
        s.prompts += 1;
        s.executed += usize::from(o.executed);
        s.retried += usize::from(o.retries > 0);
        if let Some(k) = o.failure {
            *s.failures.entry(k.name().to_string()).or_default() += 1;
        }
        if o.pass.is_some() {
            s.with_reference += 1;
        }
        s.bbox_within_1pct += usize::from(o.bbox_error.is_some_and(|b| b <= SIZE_TOL));
        s.volume_within_2pct += usize::from(o.volume_error.is_some_and(|v| v <= VOLUME_TOL));
        s.passed += usize::from(o.pass == Some(true));
        if let (Some(d), Some(r)) = (o.chamfer_mm, o.chamfer_rel) {
            cd.push(d);
            cr.push(r);
        }
        if let Some(p) = o.plausible {
            s.with_plausibility += 1;
            s.plausible += usize::from(p);
        }
        match o.verdict() {
            Some(Verdict::Exact) => s.exact += 1,
            Some(Verdict::Refused) => s.refused_with_words += 1,
            Some(Verdict::Wrong) => s.wrong += 1,
            Some(Verdict::Failed) => s.failed += 1,
            None => {}
        }
    }
    s.with_chamfer = cd.len();
    s.max_chamfer_mm = cd.iter().copied().reduce(f64::max);
    s.median_chamfer_mm = median(cd);
    s.median_chamfer_rel = median(cr);
    s
}

fn latency(mut times: Vec<f64>) -> Option<Latency> {
    times.sort_by(f64::total_cmp);
    (!times.is_empty()).then(|| Latency {
        jobs: times.len(),
        median_ms: times[times.len() / 2],
        p95_ms: times[(times.len() * 95 / 100).min(times.len() - 1)],
        min_ms: times[0],
    })
}

/// Runs `f` over `items` on `workers` threads, results in item order.
fn parallel<T: Sync, R: Send>(items: &[T], workers: usize, f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let next = AtomicUsize::new(0);
    let out: Mutex<Vec<(usize, R)>> = Mutex::new(Vec::with_capacity(items.len()));
    std::thread::scope(|scope| {
        for _ in 0..workers.max(1) {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(item) = items.get(i) else { break };
                    let r = f(item);
                    out.lock().unwrap_or_else(|e| e.into_inner()).push((i, r));
                }
            });
        }
    });
    let mut v = out.into_inner().unwrap_or_else(|e| e.into_inner());
    v.sort_by_key(|(i, _)| *i);
    v.into_iter().map(|(_, r)| r).collect()
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
    let s = load(suite)?;
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
    runner.wait_idle(workers.max(1), std::time::Duration::from_secs(120));
    // The reference meshes, from the suite's reference programs (not timed).
    let ids: Vec<&String> = s.programs.keys().collect();
    let meshes = parallel(&ids, workers, |id| {
        let mesh = runner.run(&CadJob::cadquery(s.programs[*id].clone())).ok().map(|mut r| {
            mesh_io::drop_collapsed_triangles(&mut r.mesh);
            r.mesh
        });
        ((*id).clone(), mesh)
    });
    let ref_meshes: BTreeMap<String, Mesh> = meshes.into_iter().filter_map(|(id, m)| Some((id, m?))).collect();
    let missing_refs = ids.len() - ref_meshes.len();

    let started = Instant::now();
    let mut outcomes = parallel(&s.prompts, workers, |p| match &model {
        Some(w) => one_by_model(&runner, w, p),
        None => one(&runner, p),
    });
    let wall_s = started.elapsed().as_secs_f64();
    for o in &mut outcomes {
        compare(o, s.refs.get(&o.id), ref_meshes.get(&o.id), s.sizes.get(&o.id));
    }
    let part_latency = latency(outcomes.iter().filter_map(|o| o.roundtrip_ms).collect());

    // Warm latency: the first tier's executed parts again, one at a time.
    let first_tier = s.prompts.first().map(|p| p.tier.clone()).unwrap_or_default();
    let simple: Vec<&Prompt> = s
        .prompts
        .iter()
        .filter(|p| p.tier == first_tier && outcomes.iter().any(|o| o.id == p.id && o.executed))
        .collect();
    let mut times = Vec::new();
    if model.is_none() {
        for _ in 0..latency_repeat {
            for p in &simple {
                let Ok(sy) = synth::synthesize(&p.text) else { continue };
                let t = Instant::now();
                if runner.run(&CadJob::cadquery(sy.code)).is_ok() {
                    times.push(t.elapsed().as_secs_f64() * 1e3);
                }
            }
        }
    }
    let warm_latency = latency(times);

    let mut tiers = BTreeMap::new();
    let mut names: Vec<String> = s.prompts.iter().map(|p| p.tier.clone()).collect();
    names.dedup();
    for t in &names {
        tiers.insert(t.clone(), summarize(outcomes.iter().filter(|o| &o.tier == t)));
    }
    let all = summarize(outcomes.iter());
    let mut styles = BTreeMap::new();
    let mut expected = BTreeMap::new();
    if outcomes.iter().any(|o| o.style.is_some() || o.refuse_words.is_some()) {
        let mut seen: Vec<String> = outcomes.iter().filter_map(|o| o.style.clone()).collect();
        seen.sort();
        seen.dedup();
        for st in seen {
            styles.insert(st.clone(), summarize(outcomes.iter().filter(|o| o.style.as_deref() == Some(st.as_str()))));
        }
        expected.insert("make".to_string(), summarize(outcomes.iter().filter(|o| o.refuse_words.is_none())));
        expected.insert("refuse".to_string(), summarize(outcomes.iter().filter(|o| o.refuse_words.is_some())));
    }
    let model_calls = model.as_ref().map(|w| {
        let calls = w.take_calls();
        ModelCalls {
            model: calls.first().map_or_else(String::new, |c| c.model.clone()),
            calls: calls.len(),
            tokens_in: calls.iter().map(|c| c.tokens_in).sum(),
            tokens_out: calls.iter().map(|c| c.tokens_out).sum(),
            median_latency_ms: median(calls.iter().map(|c| c.latency_ms).collect()),
        }
    });
    if let Some(path) = std::env::var_os("SCENEWRIGHT_CAD_SHEET") {
        write_sheet(Path::new(&path), &outcomes)?;
    }
    let bench = CadBench {
        suite: s.name,
        writer: model.as_ref().map_or_else(|| "offline".to_string(), CodeWriter::name),
        workers: workers.max(1),
        wall_s,
        parts_per_s: outcomes.len() as f64 / wall_s.max(1e-9),
        tiers,
        styles,
        expected,
        all,
        part_latency,
        warm_latency,
        model_calls,
        outcomes,
    };
    if json {
        print_json(&bench);
    } else {
        print(&render(&bench, missing_refs));
    }
    Ok(0)
}

fn write_sheet(path: &Path, outcomes: &[Outcome]) -> Result<(), Failure> {
    let tiles: Vec<Tile<'_>> = outcomes
        .iter()
        .map(|o| Tile {
            label: o.id.clone(),
            mesh: o.mesh.as_ref(),
            caption: match (&o.made_by, o.executed) {
                (Some(m), true) => m.trim_start_matches("freeform:").to_string(),
                _ => "not made".to_string(),
            },
            // The catalog's objects face +Y; show their fronts. Others are seen across their
            // longer side (a guitar or a hammer lying along X from its side, not its end).
            azimuth: match (o.made_by.as_deref(), o.mesh.as_ref().map(|m| m.bounds().size())) {
                (Some(m), _) if m.starts_with("catalog:") => 1.15,
                (_, Some(s)) if s[0] >= 1.5 * s[1] => -1.2,
                (_, Some(s)) if s[1] >= 1.5 * s[0] => -0.4,
                _ => -0.9,
            },
        })
        .collect();
    let image = contact_sheet(&tiles, 9, 200);
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        fs_err::create_dir_all(dir).map_err(|e| Failure::internal(e.to_string()))?;
    }
    let file = fs_err::File::create(path).map_err(|e| Failure::internal(e.to_string()))?;
    image.write_png(std::io::BufWriter::new(file)).map_err(|e| Failure::internal(format!("{}: {e}", path.display())))
}

fn pct(n: usize, d: usize) -> String {
    if d == 0 { "-".into() } else { format!("{:.0} %", 100.0 * n as f64 / d as f64) }
}

fn render(b: &CadBench, missing_refs: usize) -> String {
    let mut s = format!(
        "suite {} · writer {} · {} prompts · {} worker(s) · {:.1} s wall ({:.1} parts/s)\n\n",
        b.suite,
        b.writer,
        b.outcomes.len(),
        b.workers,
        b.wall_s,
        b.parts_per_s
    );
    if missing_refs > 0 {
        s.push_str(&format!("({missing_refs} reference programs did not run)\n"));
    }
    s.push_str("tier      prompts  executed  ref  within tol  bbox≤1%  vol≤2%  chamfer med / max mm  (% diag)  plausible  failures\n");
    let mut line = |name: &str, t: &TierSummary| {
        let fails: Vec<String> = t.failures.iter().map(|(k, n)| format!("{k} {n}")).collect();
        let chamfer = match (t.median_chamfer_mm, t.max_chamfer_mm) {
            (Some(m), Some(x)) => format!("{m:.4} / {x:.4}"),
            _ => "-".into(),
        };
        s.push_str(&format!(
            "{name:<9} {:>7} {:>9} {:>4} {:>11} {:>8} {:>7} {:>21} {:>9} {:>10}  {}\n",
            t.prompts,
            format!("{} ({})", t.executed, pct(t.executed, t.prompts)),
            t.with_reference,
            format!("{} ({})", t.passed, pct(t.passed, t.with_reference)),
            pct(t.bbox_within_1pct, t.with_reference),
            pct(t.volume_within_2pct, t.with_reference),
            chamfer,
            t.median_chamfer_rel.map_or("-".into(), |r| format!("{:.3} %", 100.0 * r)),
            if t.with_plausibility > 0 { format!("{}/{}", t.plausible, t.with_plausibility) } else { "-".into() },
            fails.join(", ")
        ));
    };
    for (name, t) in &b.tiers {
        line(name, t);
    }
    line("all", &b.all);
    if b.all.with_reference > 0 || b.all.refused_with_words > 0 {
        s.push_str("\nverdict      prompts         exact  refused with the words  wrong  failed otherwise\n");
        let mut verdicts = |name: &str, t: &TierSummary| {
            let of = t.exact + t.refused_with_words + t.wrong + t.failed;
            s.push_str(&format!(
                "{name:<12} {of:>7}  {:>12}  {:>22}  {:>5}  {:>16}\n",
                format!("{} ({})", t.exact, pct(t.exact, of)),
                t.refused_with_words,
                t.wrong,
                t.failed
            ));
        };
        for (name, t) in b.tiers.iter().chain(&b.styles) {
            verdicts(name, t);
        }
        for (name, t) in &b.expected {
            verdicts(&format!("{name} rows"), t);
        }
        verdicts("all", &b.all);
        if b.expected.contains_key("refuse") {
            s.push_str("(a row that must be refused counts under \"refused with the words\" when the refusal quotes its words)\n");
        }
    }
    if let Some(l) = &b.part_latency {
        s.push_str(&format!(
            "\nparts in the run: median {:.0} ms · p95 {:.0} ms · min {:.0} ms over {} jobs ({} workers)\n",
            l.median_ms, l.p95_ms, l.min_ms, l.jobs, b.workers
        ));
    }
    if let Some(l) = &b.warm_latency {
        s.push_str(&format!(
            "warm runner, first-tier parts one at a time: median {:.0} ms · p95 {:.0} ms · min {:.0} ms over {} jobs\n",
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
        s.push_str("\nnot made or not passed:\n");
        for o in failed {
            s.push_str(&format!(
                "  {} {} {}: {}\n",
                o.id,
                o.made_by.as_deref().unwrap_or("-"),
                o.failure.map_or("", |k| k.name()),
                o.message.as_deref().unwrap_or("")
            ));
        }
    }
    s
}
