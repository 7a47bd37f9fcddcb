//! The coordinator: prompt → plan (L1) → assets (L2) → layout (L3) → MJCF (L4) →
//! verification in MuJoCo → package on disk.
//!
//! The same [`generate`] runs behind the CLI, the benchmarks and (later) the server's
//! workers. Every stage reports progress through a callback and records its wall-clock
//! time. The package is written to a temporary sibling directory and renamed into place
//! only when complete, so an interrupted or failed run never leaves half a package.

mod asset_source;
pub mod dataset;
mod edit;
mod edit_ops;
mod edit_pose;
mod edit_work;
mod forge;
mod forge_source;
mod llm_generate;
mod loads;
pub mod manifest;
mod package;
mod parts;
mod physics_budget;
mod rebuild;
mod refine;
mod relations_check;
mod relations_measure;
mod relations_places;
mod report;
mod robot_facts;
mod scene_geom;
mod upright;
mod variations;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use serde::Serialize;
use sw_plan::{
    AnomalyKind, AnomalyRequest, LaidOutScene, Mount, Report, RobotPlan, ScenePlan, Stage, StageTiming, Status,
    Support, Timings, Verification, Warning,
};
use tracing::info_span;

pub use asset_source::{AssetSource, CadCallSource, CatalogSource, GroupAssets, MadeAsset};
pub use edit::{EditOutcome, EditReader, edit_package, edit_structured};
pub use edit_pose::StructuredEdit;
pub use forge::{Forged, ForgedObject, forge};
pub use forge_source::ForgeSource;
pub use llm_generate::{LlmRun, Structure, generate_with_llm, plan_with_llm, relations_with_llm};
pub use package::{OutputError, discard_staged_packages, validate_dir};
pub use refine::{MAX_TURNS as REFINE_MAX_TURNS, Refined, Refiner, Turn};
pub use robot_facts::measure as measure_robot;
pub use sw_mjcf::PhysicsTarget;
pub use variations::{generate_variations, structural_difference};

/// How to run the pipeline.
#[derive(Debug, Clone)]
pub struct Options {
    pub seed: u64,
    /// Compile and settle the package in MuJoCo (on by default).
    pub verify: bool,
    /// Replace the prompt's robots with these registry models (`--robot`); an empty list
    /// removes all robots.
    pub robots: Option<Vec<String>>,
    /// Use this industrial rules profile instead of the room kind's (`--rules`).
    pub rules_profile: Option<String>,
    /// Inject controlled anomalies (`--anomaly`), labelled in layout.json.
    pub anomaly: Option<AnomalyRequest>,
    /// Set by another thread to stop the run between stages (a cancelled or timed-out
    /// job): the run ends with [`PipelineError::Cancelled`] and writes nothing.
    pub cancel: Option<Arc<AtomicBool>>,
    /// The simulator the package is written for (`--physics`): native MuJoCo, or MuJoCo
    /// XLA's collision pairs (`sw_mjcf::physics`).
    pub physics: PhysicsTarget,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            seed: 0,
            verify: true,
            robots: None,
            rules_profile: None,
            anomaly: None,
            cancel: None,
            physics: PhysicsTarget::Native,
        }
    }
}

impl Options {
    fn check_cancel(&self) -> Result<(), PipelineError> {
        match &self.cancel {
            Some(c) if c.load(Ordering::Relaxed) => Err(PipelineError::Cancelled),
            _ => Ok(()),
        }
    }
}

/// A progress event.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "event", rename_all = "snake_case")]
pub enum Event {
    StageStarted {
        stage: Stage,
    },
    StageFinished {
        stage: Stage,
        ms: f64,
        summary: String,
    },
    Note {
        stage: Stage,
        message: String,
    },
    /// One object's step within a stage: its asset made (L2), where it was placed or
    /// why it was left out (L3).
    Object {
        stage: Stage,
        object: String,
        step: String,
    },
}

/// Why a run did not produce a package.
#[derive(Debug, thiserror::Error)]
pub enum PipelineError {
    /// The prompt or options are unusable (exit code 2).
    #[error("{0}")]
    Input(String),
    /// The output directory is unusable (exit code 2).
    #[error(transparent)]
    Output(#[from] OutputError),
    /// A bug or an environment failure (exit code 1).
    #[error("internal error: {0}")]
    Internal(String),
    /// Stopped through [`Options::cancel`] (exit code 130); nothing was written.
    #[error("cancelled")]
    Cancelled,
}

impl PipelineError {
    /// The process exit code for this error.
    pub fn exit_code(&self) -> i32 {
        match self {
            PipelineError::Input(_) | PipelineError::Output(_) => 2,
            PipelineError::Internal(_) => 1,
            PipelineError::Cancelled => 130,
        }
    }
}

/// What a run produced.
#[derive(Debug)]
pub struct Outcome {
    pub plan: ScenePlan,
    pub layout: LaidOutScene,
    pub report: Report,
    pub timings: Timings,
    pub out_dir: PathBuf,
}

/// Repair rounds: objects that fail verification are removed and the scene re-checked.
const MAX_REPAIRS: usize = 3;

/// Runs the whole pipeline and writes the package to `out` (which must not exist or be
/// an empty directory).
pub fn generate(
    prompt: &str,
    out: &Path,
    opts: &Options,
    on_event: &mut dyn FnMut(&Event),
) -> Result<Outcome, PipelineError> {
    let started = Instant::now();
    // Refuse an unusable destination before any work, and create nothing until the
    // prompt has been understood.
    package::check_destination(out)?;
    let mut timings = Timings::default();
    let stage = |s: Stage, on_event: &mut dyn FnMut(&Event)| {
        on_event(&Event::StageStarted { stage: s });
        Instant::now()
    };
    let finish = |s: Stage, t0: Instant, summary: String, timings: &mut Timings, on_event: &mut dyn FnMut(&Event)| {
        let ms = t0.elapsed().as_secs_f64() * 1000.0;
        match timings.stages.iter_mut().find(|x| x.stage == s) {
            Some(x) => x.ms += ms,
            None => timings.stages.push(StageTiming { stage: s, ms }),
        }
        on_event(&Event::StageFinished { stage: s, ms, summary });
    };

    // L1
    let t = stage(Stage::Plan, on_event);
    let mut plan = {
        let _s = info_span!("stage", stage = "plan").entered();
        sw_planner::plan(prompt).map_err(|e| PipelineError::Input(e.to_string()))?
    };
    apply_options(&mut plan, opts)?;
    finish(Stage::Plan, t, report::plan_summary(&plan), &mut timings, on_event);
    opts.check_cancel()?;
    run_from_plan(prompt, plan, out, opts, Prepared::default(), timings, started, on_event)
}

/// The command line's overrides of a plan: robots, rules profile, anomalies.
fn apply_options(plan: &mut ScenePlan, opts: &Options) -> Result<(), PipelineError> {
    if let Some(models) = &opts.robots {
        plan.robots = robots_override(models)?;
    }
    if let Some(p) = &opts.rules_profile {
        let known = sw_layout::rules::profile_names();
        if !known.contains(p) {
            return Err(PipelineError::Input(format!("unknown rules profile '{p}' (known: {})", known.join(", "))));
        }
        plan.rules_profile = p.clone();
    }
    if let Some(a) = &opts.anomaly {
        if !(a.rate.is_finite() && (0.0..=1.0).contains(&a.rate)) || a.kinds.is_empty() {
            return Err(PipelineError::Input(format!("the anomaly rate must be in 0..1, got {}", a.rate)));
        }
        plan.anomaly = Some(a.clone());
    }
    Ok(())
}

/// Finishes L2 for a plan (the LLM path: waits for assets already being made).
pub(crate) type FinishForge<'a> = Box<dyn FnOnce(&ScenePlan) -> Forged + 'a>;

/// What an earlier stage prepared for [`run_from_plan`]: the LLM path's assets (made
/// while the plan was still streaming), its warnings and its calls.
#[derive(Default)]
pub(crate) struct Prepared<'a> {
    /// Finishes L2 (waits for the assets already being made); `forge` when absent.
    pub forge: Option<FinishForge<'a>>,
    pub warnings: Vec<Warning>,
    /// The calls of the run, read when the report is written.
    pub telemetry: Option<sw_llm::Telemetry>,
}

fn stage_started(s: Stage, on_event: &mut dyn FnMut(&Event)) -> Instant {
    on_event(&Event::StageStarted { stage: s });
    Instant::now()
}

fn stage_finished(s: Stage, t0: Instant, summary: String, timings: &mut Timings, on_event: &mut dyn FnMut(&Event)) {
    let ms = t0.elapsed().as_secs_f64() * 1000.0;
    match timings.stages.iter_mut().find(|x| x.stage == s) {
        Some(x) => x.ms += ms,
        None => timings.stages.push(StageTiming { stage: s, ms }),
    }
    on_event(&Event::StageFinished { stage: s, ms, summary });
}

/// One event per placed object and robot (where, on what) and per group left out.
fn placement_events(layout: &LaidOutScene, on_event: &mut dyn FnMut(&Event)) {
    for o in &layout.objects {
        let on = match &o.support {
            Support::Floor => "on the floor".to_string(),
            Support::Object { object, surface } => format!("on {object} ({surface})"),
            Support::Wall { wall } => format!("in the {} wall", wall.name()),
        };
        let step = format!("placed at ({:.2}, {:.2}) {on}", o.pos[0], o.pos[1]);
        on_event(&Event::Object { stage: Stage::Layout, object: o.name.clone(), step });
    }
    for r in &layout.robots {
        let on = r.mounted_on.as_ref().map_or_else(|| format!("mounted: {}", r.mount), |m| format!("on {m}"));
        let step = format!("{} spawned at ({:.2}, {:.2}), {on}", r.model, r.pos[0], r.pos[1]);
        on_event(&Event::Object { stage: Stage::Layout, object: r.name.clone(), step });
    }
    for l in &layout.left_out {
        let step = format!("{} of {} left out: {}", l.requested - l.placed.min(l.requested), l.requested, l.reason);
        on_event(&Event::Object { stage: Stage::Layout, object: l.group.clone(), step });
    }
}

/// L2 to verification for a plan, and the package.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_from_plan(
    prompt: &str,
    plan: ScenePlan,
    out: &Path,
    opts: &Options,
    prepared: Prepared<'_>,
    mut timings: Timings,
    started: Instant,
    on_event: &mut dyn FnMut(&Event),
) -> Result<Outcome, PipelineError> {
    let stage = stage_started;
    let finish = stage_finished;
    let staging = package::Staging::create(out)?;

    // L2
    let t = stage(Stage::Forge, on_event);
    let mut forged = {
        let _s = info_span!("stage", stage = "forge").entered();
        match prepared.forge {
            Some(f) => f(&plan),
            None => forge(&plan, opts.seed),
        }
    };
    for o in &forged.objects {
        let step = if o.label == o.category.replace('_', " ") {
            format!("asset ready ({})", o.category)
        } else {
            format!("asset ready ({}, \"{}\")", o.category, o.label)
        };
        on_event(&Event::Object { stage: Stage::Forge, object: o.name.clone(), step });
    }
    finish(Stage::Forge, t, report::count(forged.objects.len(), "asset", "assets"), &mut timings, on_event);
    opts.check_cancel()?;

    // L3
    let t = stage(Stage::Layout, on_event);
    let mut layout = {
        let _s = info_span!("stage", stage = "layout").entered();
        let mut layout = lay_out(&plan, &forged, opts.seed, None, &BTreeMap::new());
        // When objects do not fit, shrink what may shrink (within the catalog's ranges):
        // each step scales the original assets of every group that has been short.
        let original = forged.clone();
        let mut shrunk_groups: Vec<String> = Vec::new();
        for factor in SHRINK_STEPS {
            let mut groups = shrunk_groups.clone();
            // A size the prompt stated is kept: those groups never shrink.
            groups.extend(
                layout
                    .left_out
                    .iter()
                    .filter(|l| plan.object(&l.group).is_some_and(|o| o.size.explicit.is_empty()))
                    .map(|l| l.group.clone()),
            );
            groups.sort();
            groups.dedup();
            if missing(&layout) == 0 || groups.is_empty() {
                break;
            }
            let mut smaller = original.clone();
            for o in smaller.objects.iter_mut().filter(|o| groups.contains(&o.group)) {
                o.asset = forge::shrunk(o, factor);
            }
            let candidate = lay_out(&plan, &smaller, opts.seed, None, &BTreeMap::new());
            if missing(&candidate) < missing(&layout) {
                for g in &groups {
                    smaller.warnings.push(Warning::new(
                        Stage::Layout,
                        "shrunk_to_fit",
                        format!("{g}: footprints shrunk to {:.0} % to fit the room", factor * 100.0),
                    ));
                }
                shrunk_groups = groups;
                forged = smaller;
                layout = candidate;
            }
        }
        if let Some(a) = &plan.anomaly {
            layout = lay_out(&plan, &forged, opts.seed, Some((a, &mut layout)), &BTreeMap::new());
        }
        layout
    };
    // Scale anomalies change the geometry itself.
    for label in layout.anomalies.iter().filter(|l| l.kind == AnomalyKind::Scale) {
        if let Some(o) = forged.objects.iter_mut().find(|o| o.name == label.object) {
            o.asset = o.asset.scaled(label.magnitude);
        }
    }
    placement_events(&layout, on_event);
    finish(Stage::Layout, t, report::layout_summary(&layout), &mut timings, on_event);
    let expected = report::anomaly_bodies(&layout);

    let mut warnings: Vec<Warning> = prepared.warnings;
    warnings.extend(forged.warnings.iter().cloned());
    let mut verification: Option<Verification> = None;
    // Stacked groups laid out again in shorter columns after a settle, and how short.
    let mut max_layers: BTreeMap<String, usize> = BTreeMap::new();
    for round in 0..=MAX_REPAIRS {
        opts.check_cancel()?;
        // L4
        let t = stage(Stage::Bridge, on_event);
        let files = {
            let _s = info_span!("stage", stage = "bridge").entered();
            let mut files = package::bridge(prompt, &layout, &forged)?;
            let adapted = sw_mjcf::physics::adapt(&mut files, opts.physics)
                .map_err(|e| PipelineError::Internal(format!("physics target {}: {e}", opts.physics.name())))?;
            (files, adapted)
        };
        let (mut files, adapted) = files;
        if round == 0 {
            for n in &files.notes {
                warnings.push(Warning::new(Stage::Bridge, "robot_model_adjusted", n.clone()));
            }
            for n in adapted {
                warnings.push(Warning::new(Stage::Bridge, "physics_target", n));
            }
        }
        staging.write_scene(&files, &plan, &layout)?;
        if opts.physics == PhysicsTarget::Mjx {
            let note = physics_budget::write_budget(&staging, &mut files, &plan, &layout)?;
            if round == 0 {
                warnings.push(Warning::new(Stage::Bridge, "physics_target", note));
            }
        }
        finish(
            Stage::Bridge,
            t,
            format!(
                "{}, {}",
                report::count(layout.objects.len() + layout.robots.len(), "body", "bodies"),
                report::count(files.meshes.len(), "mesh", "meshes")
            ),
            &mut timings,
            on_event,
        );
        if !opts.verify {
            break;
        }
        opts.check_cancel()?;
        let t = stage(Stage::Verify, on_event);
        let v = {
            let _s = info_span!("stage", stage = "verify").entered();
            let vopts = sw_sim::VerifyOptions {
                robots: layout.robots.iter().map(|r| r.name.clone()).collect(),
                expected_bodies: expected.clone(),
                ..Default::default()
            };
            sw_sim::verify_file(&staging.path().join("scene.xml"), &vopts)
        };
        finish(Stage::Verify, t, report::verify_summary(&v), &mut timings, on_event);
        let repairable = !v.passed && v.compiled && round < MAX_REPAIRS;
        // Columns that sank too far: their groups are laid out again in columns as short
        // as the layers that stayed (once per group), rather than losing their tops.
        if repairable && plan.anomaly.is_none() {
            let new: Vec<(String, usize)> = report::sunk_columns(&plan, &layout, &v)
                .into_iter()
                .filter(|(g, _)| !max_layers.contains_key(g))
                .collect();
            if !new.is_empty() {
                for (g, layers) in &new {
                    let message = format!(
                        "\"{}\" stacked: the layers above the {} sank or slid more than 1 cm in the settle; laid out again in columns of at most {layers}",
                        plan.phrase_of(g),
                        ordinal(*layers)
                    );
                    on_event(&Event::Note { stage: Stage::Verify, message: message.clone() });
                    warnings.push(Warning::new(Stage::Verify, "stack_shortened", message));
                }
                max_layers.extend(new);
                // Counted in the layout's time; the events say it as a note above.
                let t = Instant::now();
                layout = lay_out(&plan, &forged, opts.seed, None, &max_layers);
                if let Some(x) = timings.stages.iter_mut().find(|x| x.stage == Stage::Layout) {
                    x.ms += t.elapsed().as_secs_f64() * 1000.0;
                }
                placement_events(&layout, on_event);
                verification = Some(v);
                continue;
            }
        }
        let removed = if repairable { report::repair(&mut layout, &v, &expected) } else { Vec::new() };
        verification = Some(v);
        if removed.is_empty() {
            break;
        }
        for (name, why) in removed {
            let message = format!("{name} was removed: {why}");
            on_event(&Event::Note { stage: Stage::Verify, message: message.clone() });
            warnings.push(Warning::new(Stage::Verify, "removed_after_verification", message));
        }
    }

    timings.total_ms = started.elapsed().as_secs_f64() * 1000.0;
    let mut report = report::assemble(&plan, &layout, opts.seed, warnings, verification);
    report.llm_calls = prepared.telemetry.map(|t| t.calls()).unwrap_or_default();
    report.asset_cache = forged.cache;
    relations_check::attach(&mut report, &plan, staging.path());
    staging.write_report(&report, &timings)?;
    let out_dir = staging.commit()?;
    Ok(Outcome { plan, layout, report, timings, out_dir })
}

/// "1st", "2nd", "3rd", "4th", … "11th", "12th", "13th", "21st".
fn ordinal(n: usize) -> String {
    let suffix = match (n % 10, n % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// Footprint scales tried, in turn, for objects that did not fit.
const SHRINK_STEPS: [f64; 2] = [0.85, 0.7];

/// Object instances requested but not placed.
fn missing(l: &LaidOutScene) -> u32 {
    l.left_out.iter().map(|x| x.requested - x.placed).sum()
}

/// L3 on the forged assets; with `anomaly`, injects anomalies into the given layout instead
/// of solving again, and measures the rules afterwards.
fn lay_out(
    plan: &ScenePlan,
    forged: &Forged,
    seed: u64,
    anomaly: Option<(&AnomalyRequest, &mut LaidOutScene)>,
    max_layers: &BTreeMap<String, usize>,
) -> LaidOutScene {
    let input = sw_layout::LayoutInput {
        plan,
        objects: forged
            .objects
            .iter()
            .map(|o| sw_layout::ObjectItem {
                name: o.name.clone(),
                group: o.group.clone(),
                category: o.category.clone(),
                label: o.label.clone(),
                asset: &o.asset,
                tags: o.tags.clone(),
                carries_robot: o.carries_robot.clone(),
            })
            .collect(),
        robots: forged.robots.clone(),
        seed,
        max_layers: max_layers.clone(),
    };
    match anomaly {
        None => sw_layout::solve(&input),
        Some((a, layout)) => {
            let mut l = layout.clone();
            let notes = sw_layout::inject_anomalies(&input, &mut l, a, seed);
            l.warnings.extend(notes);
            l.violations = sw_layout::check_rules(&input, &l);
            l
        }
    }
}

fn robots_override(models: &[String]) -> Result<Vec<RobotPlan>, PipelineError> {
    let mut out: Vec<RobotPlan> = Vec::new();
    for m in models {
        let m = m.trim().to_lowercase();
        if m.is_empty() || m == "none" {
            continue;
        }
        let def = sw_robots::find(&m).ok_or_else(|| match sw_robots::why_missing(&m) {
            Some(why) => PipelineError::Input(why),
            None => {
                let known: Vec<&str> = sw_robots::registry().iter().map(|r| r.name).collect();
                PipelineError::Input(format!("unknown robot '{m}' (known: {})", known.join(", ")))
            }
        })?;
        match out.iter_mut().find(|r| r.model == def.name) {
            Some(r) => r.count += 1,
            None => out.push(RobotPlan {
                id: def.name.to_string(),
                model: def.name.to_string(),
                phrase: format!("--robot {m}"),
                count: 1,
                mount: Mount::Auto,
                near: None,
            }),
        }
    }
    Ok(out)
}

/// True when the report's verification passed (or was skipped on request).
pub fn succeeded(report: &Report) -> bool {
    report.status != Status::Failed
}
