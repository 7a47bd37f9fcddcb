//! `demos`: solved, replayable demonstrations of a task as a LeRobot v3.0 dataset —
//! resumable after kill -9 or Ctrl-C (see `demos_dir`).
//!
//! Each attempt takes the prompt's next seed: a new verified scene variant (layout, sizes,
//! colours of the package), the task bound to it (`sw_task`), the episode's own scene with
//! its randomisation (`sw_expert::episode_scene`), the expert's run, the judgement; a
//! solved run is rendered (cameras), written (data, videos) and committed as the next
//! episode. An attempt that is not solved is discarded and counted.

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use serde::Serialize;
use sw_lerobot::{Column, DatasetInfo, Dtype, EpisodePlace, EpisodeRecord, FeatureSpec, VideoWriter};
use sw_pipeline::{Options, PipelineError};
use sw_task::{SceneFacts, Task, TaskError};

use crate::Failure;
use crate::cmd_dataset::{ACTIVE, Progress, lock, stop_flag};
use crate::demos_dir::{
    AttemptLine, DEMOS_FORMAT, DEMOS_VERSION, DemosDir, DemosError, DemosSpec, EpisodeFile, episode_dir,
};
use crate::output::{print, print_json};

/// Attempts a slot makes before it is given up.
const TRIES: u32 = 20;
/// The outcome logged for a variant whose start already satisfied the task.
const RESAMPLED: &str = "resampled";
/// Seeds tried up front to find a scene the task can be bound to.
const PREFLIGHT_TRIES: u64 = 5;
/// Largest episodes per prompt, frames per second, image side.
const MAX_EPISODES: u32 = 100_000;

#[derive(Debug, clap::Args)]
pub(crate) struct DemosArgs {
    /// One prompt (the task may be part of it: "… that puts the red cube in the bowl").
    #[arg(long, conflicts_with = "prompts", required_unless_present = "prompts")]
    prompt: Option<OsString>,
    /// A file of prompts: one per line, `#` starts a comment, blank lines are skipped.
    #[arg(long)]
    prompts: Option<PathBuf>,
    /// The task, for every prompt ("put the red cube in the bowl").
    #[arg(long)]
    task: Option<String>,
    /// Episodes per prompt.
    #[arg(long)]
    episodes: u32,
    /// The dataset directory (new, empty, or a dataset of the same options to resume).
    #[arg(long)]
    out: PathBuf,
    /// The dataset format (LeRobot v3.0).
    #[arg(long, default_value = "lerobot")]
    format: String,
    /// Cameras to record: `front`, `wrist` (the robot's), or any camera of the scene.
    #[arg(long, value_delimiter = ',')]
    cameras: Option<Vec<String>>,
    /// Frames (and controls) per second.
    #[arg(long, default_value_t = 15)]
    fps: u32,
    /// Image size, WxH.
    #[arg(long, default_value = "224x224")]
    image_size: String,
    /// Episodes made at once (default: every core).
    #[arg(long)]
    jobs: Option<usize>,
    /// The first seed of every prompt's seed stream.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Keep colours, masses, friction, lighting and the camera as the scene has them.
    #[arg(long)]
    no_randomise: bool,
    /// Keep each unsolved attempt's scene, task and a video of it (front camera) under
    /// DIR/failed/ to see why (they are never part of the dataset).
    #[arg(long)]
    keep_failed: bool,
    /// Print one JSON summary instead of progress and a summary.
    #[arg(long)]
    json: bool,
}

fn read_prompts(a: &DemosArgs) -> Result<Vec<String>, Failure> {
    match (&a.prompt, &a.prompts) {
        (Some(p), _) => {
            let p = p.to_str().ok_or_else(|| Failure::input("the prompt is not valid UTF-8 text"))?;
            if p.trim().is_empty() {
                return Err(Failure::input("the prompt is empty"));
            }
            Ok(vec![p.trim().to_string()])
        }
        (None, Some(path)) => {
            let bytes = fs_err::read(path).map_err(|e| Failure::input(e.to_string()))?;
            let text = String::from_utf8(bytes)
                .map_err(|_| Failure::input(format!("{} is not UTF-8 text", path.display())))?;
            let out: Vec<String> = text
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .map(str::to_string)
                .collect();
            if out.is_empty() {
                return Err(Failure::input(format!("{} holds no prompts", path.display())));
            }
            Ok(out)
        }
        (None, None) => Err(Failure::input("give --prompt or --prompts")),
    }
}

fn spec_of(a: &DemosArgs) -> Result<DemosSpec, Failure> {
    if a.episodes == 0 || a.episodes > MAX_EPISODES {
        return Err(Failure::input(format!("--episodes must be between 1 and {MAX_EPISODES}, got {}", a.episodes)));
    }
    if a.format != "lerobot" {
        return Err(Failure::input(format!("unknown --format '{}' (lerobot)", a.format)));
    }
    if a.jobs == Some(0) {
        return Err(Failure::input("--jobs must be at least 1"));
    }
    if !(1..=120).contains(&a.fps) {
        return Err(Failure::input(format!("--fps must be between 1 and 120, got {}", a.fps)));
    }
    let size = parse_size(&a.image_size)?;
    let cameras: Vec<String> = a
        .cameras
        .clone()
        .unwrap_or_default()
        .into_iter()
        .map(|c| c.trim().to_string())
        .filter(|c| !c.is_empty())
        .collect();
    for (i, c) in cameras.iter().enumerate() {
        if !c.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_') {
            return Err(Failure::input(format!("camera name '{c}' has characters other than letters, digits and _")));
        }
        if cameras[..i].contains(c) {
            return Err(Failure::input(format!("camera '{c}' is named twice")));
        }
    }
    if let Some(t) = &a.task
        && t.trim().is_empty()
    {
        return Err(Failure::input("--task is empty"));
    }
    Ok(DemosSpec {
        format: DEMOS_FORMAT.into(),
        version: DEMOS_VERSION,
        prompts: read_prompts(a)?,
        task: a.task.as_ref().map(|t| t.trim().to_string()),
        episodes: a.episodes,
        seed: a.seed,
        fps: a.fps,
        cameras,
        image_size: size,
        randomise: !a.no_randomise,
        output: a.format.clone(),
    })
}

fn parse_size(s: &str) -> Result<[u32; 2], Failure> {
    let bad = || Failure::input(format!("--image-size must be WxH with even sides from 16 to 1024, got '{s}'"));
    let (w, h) = s
        .to_lowercase()
        .split_once('x')
        .map(|(w, h)| (w.trim().parse::<u32>(), h.trim().parse::<u32>()))
        .ok_or_else(bad)?;
    let (w, h) = (w.map_err(|_| bad())?, h.map_err(|_| bad())?);
    if !(16..=1024).contains(&w) || !(16..=1024).contains(&h) || w % 2 == 1 || h % 2 == 1 {
        return Err(bad());
    }
    Ok([w, h])
}

/// A prompt made ready: the scene words and the instruction.
#[derive(Debug, Clone)]
struct Job {
    scene: String,
    instruction: String,
    source: &'static str,
}

fn jobs_of(spec: &DemosSpec) -> Result<Vec<Job>, Failure> {
    spec.prompts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let where_ = if spec.prompts.len() > 1 { format!("prompt {}: ", i + 1) } else { String::new() };
            match (&spec.task, sw_task::split_prompt(p)) {
                (Some(t), _) => Ok(Job { scene: p.clone(), instruction: t.clone(), source: "flag" }),
                (None, Some(s)) => Ok(Job { scene: s.scene, instruction: s.instruction, source: "prompt" }),
                (None, None) => Err(Failure::input(format!(
                    "{where_}\"{p}\" asks for no task; add one (\"… that puts the red cube in the bowl\") or give --task"
                ))),
            }
        })
        .collect()
}

/// The scene joints of articulated things, from scene.xml (for open/close goals).
fn object_joints(dir: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(dir.join("scene.xml")).unwrap_or_default();
    let Ok(root) = sw_mjcf::xml::Element::parse(&text) else { return Vec::new() };
    let mut out = Vec::new();
    root.walk(&mut |e| {
        if e.name == "joint"
            && let Some(n) = e.get("name")
            && n.ends_with("_joint")
        {
            out.push(n.to_string());
        }
    });
    out
}

fn read_json<T: serde::de::DeserializeOwned>(path: &Path) -> Result<T, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Binds the task to the package in `dir`.
fn bind(job: &Job, dir: &Path) -> Result<Result<Task, TaskError>, String> {
    let plan: sw_plan::ScenePlan = read_json(&dir.join("plan.json"))?;
    let layout: sw_plan::LaidOutScene = read_json(&dir.join("layout.json"))?;
    let facts = SceneFacts::new(&plan, &layout, object_joints(dir));
    Ok(sw_task::bind(&job.instruction, job.source, &facts))
}

/// Every prompt is tried once up front: a task that names something the scene does not
/// have, no gripper, contradictory goals, goals the expert cannot do, words that ask for
/// nothing, or prompts for robots of different kinds (a dataset has one action layout) are
/// bad input.
fn preflight(spec: &DemosSpec, jobs: &[Job], scratch: &Path) -> Result<(), Failure> {
    let mut models: Vec<(usize, String)> = Vec::new();
    for (i, job) in jobs.iter().enumerate() {
        let where_ = if jobs.len() > 1 { format!("prompt {}: ", i + 1) } else { String::new() };
        sw_planner::plan(&job.scene).map_err(|e| Failure::input(format!("{where_}{e}")))?;
        let mut last: Option<TaskError> = None;
        for t in 0..PREFLIGHT_TRIES {
            let dir = scratch.join(format!("preflight-{i}-{t}"));
            let opts = Options { seed: spec.seed + t, ..Options::default() };
            let out = sw_pipeline::generate(&job.scene, &dir, &opts, &mut |_| {});
            let layout = match out {
                Ok(o) if sw_pipeline::succeeded(&o.report) => o.layout,
                _ => {
                    let _ = std::fs::remove_dir_all(&dir);
                    continue;
                }
            };
            let bound = bind(job, &dir).map_err(Failure::internal)?;
            let _ = std::fs::remove_dir_all(&dir);
            match bound {
                Ok(task) => {
                    sw_expert::supports(&task).map_err(|e| Failure::input(format!("{where_}{e}")))?;
                    let model = layout.robots.iter().find(|r| r.name == task.robot).map(|r| r.model.clone());
                    models.push((i, model.unwrap_or_default()));
                    last = None;
                    break;
                }
                Err(e @ TaskError::Unreachable(_)) => last = Some(e),
                Err(e) => return Err(Failure::input(format!("{where_}{e}"))),
            }
        }
        if let Some(e) = last {
            return Err(Failure::input(format!("{where_}{e} (in {PREFLIGHT_TRIES} scene variants)")));
        }
    }
    if let Some((i, m)) = models.iter().find(|(_, m)| *m != models[0].1) {
        return Err(Failure::input(format!(
            "prompt {} is done by a {} and prompt {} by a {m}: a dataset holds one robot's actions; make one dataset per robot",
            models[0].0 + 1,
            models[0].1,
            i + 1
        )));
    }
    Ok(())
}

/// What a run did.
#[derive(Debug, Default, Serialize)]
pub(crate) struct Summary {
    pub out_dir: PathBuf,
    pub episodes_wanted: usize,
    pub episodes: usize,
    pub made: usize,
    pub attempts: usize,
    pub solved: usize,
    /// Attempts not solved, by class.
    pub failures: BTreeMap<String, usize>,
    /// Solved / attempts per task family (this run).
    pub families: BTreeMap<String, (usize, usize)>,
    pub seconds: f64,
    pub episodes_per_min: f64,
    pub frames: u64,
    pub bytes: u64,
    pub bytes_per_episode: u64,
    pub jobs: usize,
    pub resumed_episodes: usize,
    pub removed_partial: usize,
    pub gave_up: usize,
    /// Variants drawn again because their start already satisfied the task (not attempts).
    pub resampled: usize,
    pub interrupted: bool,
}

struct Shared<'a> {
    dir: &'a DemosDir,
    jobs: Vec<Job>,
    pending: Mutex<Vec<usize>>,
    seeds: Vec<AtomicU64>,
    stop: Arc<AtomicBool>,
    fatal: Mutex<Option<String>>,
    stats: Mutex<Stats>,
    commit: Mutex<()>,
    info: Mutex<Option<DatasetInfo>>,
    progress: Progress,
    last_meta: Mutex<Instant>,
    keep_failed: bool,
}

#[derive(Default)]
struct Stats {
    made: usize,
    attempts: usize,
    solved: usize,
    failures: BTreeMap<String, usize>,
    families: BTreeMap<String, (usize, usize)>,
    frames: u64,
    bytes: u64,
    gave_up: usize,
    resampled: usize,
}

pub(crate) fn run(a: DemosArgs) -> Result<u8, Failure> {
    let spec = spec_of(&a)?;
    let jobs = jobs_of(&spec)?;
    DemosDir::check(&a.out, &spec).map_err(|e| Failure::input(e.to_string()))?;
    // Bad input writes nothing: the tasks are tried on scenes in a scratch directory
    // before the dataset's directory is made.
    let scratch = tempfile::Builder::new()
        .prefix("scenewright-demos-")
        .tempdir()
        .map_err(|e| Failure::internal(format!("a scratch directory: {e}")))?;
    preflight(&spec, &jobs, scratch.path())?;
    drop(scratch);
    let (dir, resumed) = DemosDir::open(&a.out, &spec).map_err(|e| match e {
        DemosError::Unwritable { .. } | DemosError::Foreign(_) | DemosError::Mismatch { .. } | DemosError::Busy(_) => {
            Failure::input(e.to_string())
        }
    })?;
    let spec = dir.spec().clone();
    let njobs = a.jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())).max(1);
    // Seeds: each prompt's stream resumes past the largest seed it tried.
    let mut next: Vec<u64> = vec![spec.seed; jobs.len()];
    for at in &dir.attempts_before {
        if let Some(s) = next.get_mut(at.prompt_index) {
            *s = (*s).max(at.seed + 1);
        }
    }
    let per_prompt: Vec<usize> = {
        let eps = lock(&dir.episodes);
        (0..jobs.len()).map(|p| eps.iter().filter(|e| e.prompt_index == p).count()).collect()
    };
    let mut pending = Vec::new();
    for (p, have) in per_prompt.iter().enumerate() {
        for _ in *have..spec.episodes as usize {
            pending.push(p);
        }
    }
    pending.reverse();
    let wanted = jobs.len() * spec.episodes as usize;
    let have = wanted - pending.len();
    let info = lock(&dir.episodes).first().map(|e| info_of(e, spec.image_size));
    let stop = stop_flag();
    let shared = Shared {
        dir: &dir,
        jobs,
        pending: Mutex::new(pending),
        seeds: next.into_iter().map(AtomicU64::new).collect(),
        stop: stop.clone(),
        fatal: Mutex::new(None),
        stats: Mutex::new(Stats::default()),
        commit: Mutex::new(()),
        info: Mutex::new(info),
        progress: Progress::new(wanted, have).unit("episodes", "demos"),
        last_meta: Mutex::new(Instant::now()),
        keep_failed: a.keep_failed,
    };
    ACTIVE.store(true, Ordering::SeqCst);
    let started = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..njobs {
            s.spawn(|| worker(&shared));
        }
    });
    ACTIVE.store(false, Ordering::SeqCst);
    let seconds = started.elapsed().as_secs_f64();
    shared.progress.finish();
    if let Some(info) = lock(&shared.info).clone() {
        dir.write_meta(&info).map_err(|e| Failure::internal(e.to_string()))?;
    }
    dir.sync().map_err(|e| Failure::internal(e.to_string()))?;
    let episodes = lock(&dir.episodes).len();
    if let Some(message) = lock(&shared.fatal).take() {
        return Err(Failure::internal(format!(
            "{message}; {episodes} episodes are complete; run the same command again to resume"
        )));
    }
    let st = std::mem::take(&mut *lock(&shared.stats));
    let summary = Summary {
        out_dir: dir.root().to_path_buf(),
        episodes_wanted: wanted,
        episodes,
        made: st.made,
        attempts: st.attempts,
        solved: st.solved,
        failures: st.failures,
        families: st.families,
        seconds: (seconds * 1000.0).round() / 1000.0,
        episodes_per_min: if seconds > 0.0 { (st.made as f64 * 60.0 / seconds * 100.0).round() / 100.0 } else { 0.0 },
        frames: st.frames,
        bytes: st.bytes,
        bytes_per_episode: if st.made > 0 { st.bytes / st.made as u64 } else { 0 },
        jobs: njobs,
        resumed_episodes: resumed.episodes,
        removed_partial: resumed.removed_partial,
        gave_up: st.gave_up,
        resampled: st.resampled,
        interrupted: stop.load(Ordering::SeqCst) && episodes < wanted,
    };
    report(&summary, a.json);
    Ok(if summary.interrupted {
        130
    } else if summary.episodes < summary.episodes_wanted {
        1
    } else {
        0
    })
}

fn worker(sh: &Shared<'_>) {
    while !sh.stop.load(Ordering::SeqCst) {
        let Some(p) = lock(&sh.pending).pop() else { break };
        let mut done = false;
        let (mut tries, mut resampled) = (0, 0);
        // A start that already satisfies the task poses no task: the variant is drawn
        // again without using up a try (at most TRIES times; after that each counts).
        while tries < TRIES {
            if sh.stop.load(Ordering::SeqCst) {
                return;
            }
            let seed = sh.seeds[p].fetch_add(1, Ordering::SeqCst);
            match attempt(sh, p, seed) {
                Ok(Tried::Episode) => {
                    done = true;
                    break;
                }
                Ok(Tried::Failed) => tries += 1,
                Ok(Tried::Resampled) => {
                    resampled += 1;
                    if resampled > TRIES {
                        tries += 1;
                    }
                }
                Err(Stop::Interrupted) => return,
                Err(Stop::Fatal(message)) => {
                    lock(&sh.fatal).get_or_insert(message);
                    sh.stop.store(true, Ordering::SeqCst);
                    return;
                }
            }
        }
        if !done {
            lock(&sh.stats).gave_up += 1;
            sh.progress.note(&format!("prompt {}: no solved episode in {TRIES} attempts; given up", p + 1));
        }
    }
}

/// What became of one attempt.
enum Tried {
    Episode,
    Failed,
    /// The variant's start already satisfied the task: no attempt, a new variant.
    Resampled,
}

enum Stop {
    Interrupted,
    Fatal(String),
}

fn fatal(e: impl std::fmt::Display) -> Stop {
    Stop::Fatal(e.to_string())
}

/// One attempt at an episode of prompt `p` with `seed`.
fn attempt(sh: &Shared<'_>, p: usize, seed: u64) -> Result<Tried, Stop> {
    let started = Instant::now();
    let spec = sh.dir.spec();
    let job = &sh.jobs[p];
    let work = sh.dir.work_dir(p, seed).map_err(fatal)?;
    let record = |outcome: &str, reason: Option<String>, family: Option<String>, episode: Option<u64>| {
        let line = AttemptLine {
            prompt_index: p,
            seed,
            outcome: outcome.to_string(),
            reason,
            family: family.clone(),
            episode,
            seconds: (started.elapsed().as_secs_f64() * 1000.0).round() / 1000.0,
        };
        let mut st = lock(&sh.stats);
        if outcome == RESAMPLED {
            st.resampled += 1;
            drop(st);
            return sh.dir.log_attempt(&line).map_err(fatal);
        }
        st.attempts += 1;
        if let Some(f) = family {
            let e = st.families.entry(f).or_insert((0, 0));
            e.1 += 1;
            if outcome == "solved" {
                e.0 += 1;
            }
        }
        if outcome == "solved" {
            st.solved += 1;
        } else {
            *st.failures.entry(outcome.to_string()).or_insert(0) += 1;
        }
        drop(st);
        sh.dir.log_attempt(&line).map_err(fatal)
    };
    let fail = |outcome: &str, reason: String, family: Option<String>| -> Result<Tried, Stop> {
        let _ = std::fs::remove_dir_all(&work);
        record(outcome, Some(reason.chars().take(240).collect()), family, None)?;
        if outcome == RESAMPLED {
            return Ok(Tried::Resampled);
        }
        sh.progress.failed();
        Ok(Tried::Failed)
    };
    // A verified scene variant.
    let opts = Options { seed, cancel: Some(sh.stop.clone()), ..Options::default() };
    let pkg = work.join("scene");
    let outcome = match sw_pipeline::generate(&job.scene, &pkg, &opts, &mut |_| {}) {
        Ok(o) => o,
        Err(PipelineError::Cancelled) => return Err(Stop::Interrupted),
        Err(PipelineError::Output(e)) => return Err(fatal(e)),
        Err(e) => return fail("scene", e.to_string(), None),
    };
    if !sw_pipeline::succeeded(&outcome.report) {
        return fail("scene", "the scene variant failed verification".into(), None);
    }
    // The task on it.
    let task = match bind(job, &pkg).map_err(fatal)? {
        Ok(t) => t,
        Err(e) => return fail("task", e.to_string(), None),
    };
    let family = Some(task.family.name().to_string());
    let robot_model =
        outcome.layout.robots.iter().find(|r| r.name == task.robot).map(|r| r.model.clone()).unwrap_or_default();
    sw_lerobot::write_atomically(&pkg.join("task.json"), &pretty(&task)).map_err(fatal)?;
    // The episode's own scene.
    let package_xml = std::fs::read_to_string(pkg.join("scene.xml")).map_err(fatal)?;
    let movable: Vec<String> = outcome.layout.objects.iter().filter(|o| o.movable).map(|o| o.name.clone()).collect();
    let coloured: Vec<&str> =
        outcome.plan.objects.iter().filter(|g| g.color.is_some()).map(|g| g.id.as_str()).collect();
    let named_colour: Vec<String> = outcome
        .layout
        .objects
        .iter()
        .filter(|o| coloured.contains(&o.group.as_str()))
        .map(|o| o.name.clone())
        .collect();
    let vary = if spec.randomise { sw_expert::Vary::ALL } else { sw_expert::Vary::NONE };
    let focus: Vec<String> =
        task.goals.iter().flat_map(|g| g.bodies()).map(str::to_string).filter(|b| movable.contains(b)).collect();
    let (xml, randomisation) =
        match sw_expert::episode_scene(&package_xml, spec.fps, seed, &movable, &named_colour, &focus, vary) {
            Ok(x) => x,
            Err(e) => return fail("scene", e.to_string(), family),
        };
    std::fs::write(pkg.join("scene.xml"), xml).map_err(fatal)?;
    // A task that closes a drawer or door starts with it part way open.
    let to_close: Vec<String> = task
        .goals
        .iter()
        .filter_map(|g| match g {
            sw_task::Predicate::Closed { joint, .. } => Some(joint.clone()),
            _ => None,
        })
        .collect();
    if let Err(e) = sw_expert::open_at_start(&pkg.join("scene.xml"), &to_close, seed) {
        return fail("scene", e.to_string(), family);
    }
    let eopts = sw_expert::ExpertOptions { fps: spec.fps, seed, max_seconds: 30.0 * task.goals.len().max(1) as f64 };
    let ep = match sw_expert::solve(&pkg.join("scene.xml"), &task, &robot_model, &eopts) {
        Ok(ep) => ep,
        Err(e @ sw_expert::ExpertError::AlreadySatisfied(_)) => return fail(RESAMPLED, e.to_string(), family),
        Err(e) => return fail(e.kind(), e.to_string(), family),
    };
    if !ep.success {
        if sh.keep_failed {
            keep_failed(sh.dir.root(), p, seed, &pkg, &ep, spec);
        }
        if let Some(e) = &ep.failure {
            return fail(e.kind(), e.to_string(), family);
        }
        let why: Vec<String> = ep.verdicts.iter().filter_map(|v| v.why.clone()).collect();
        return fail("not_solved", why.join("; "), family);
    }
    if sh.stop.load(Ordering::SeqCst) {
        return Err(Stop::Interrupted);
    }
    // Cameras: rendered from the recording, into the attempt's directory.
    let cams: Vec<(String, String)> = spec
        .cameras
        .iter()
        .map(|c| {
            let mjcf = match c.as_str() {
                "wrist" => ep.wrist_camera.clone().unwrap_or_else(|| format!("{}_wrist", task.robot)),
                other => other.to_string(),
            };
            (format!("observation.images.{c}"), mjcf)
        })
        .collect();
    let mut image_stats: BTreeMap<String, sw_lerobot::FeatureStats> = BTreeMap::new();
    if !cams.is_empty() {
        match render_videos(&pkg, &work, &cams, &ep, spec) {
            Ok(s) => image_stats = s,
            Err(RenderFailure::Input(m)) => return fail("render", m, family),
            Err(RenderFailure::Fatal(m)) => return Err(Stop::Fatal(m)),
        }
    }
    commit(sh, p, seed, &work, &pkg, &task, &robot_model, ep, cams, image_stats, randomisation, started)
}

/// Moves an unsolved attempt's scene to DIR/failed/pPPPP-seedS/ with front and wrist videos,
/// its controls (`actions.json`) and why it failed (`failure.txt` for a run stopped part
/// way, `verdicts.json`) — best effort: this is for looking at, never for the dataset.
fn keep_failed(root: &Path, p: usize, seed: u64, pkg: &Path, ep: &sw_expert::Episode, spec: &DemosSpec) {
    let dest = root.join(format!("failed/p{p:04}-seed{seed}"));
    let _ = std::fs::create_dir_all(root.join("failed"));
    let _ = std::fs::remove_dir_all(&dest);
    if std::fs::rename(pkg, &dest).is_err() {
        return;
    }
    let _ = sw_lerobot::write_atomically(&dest.join("verdicts.json"), &pretty(&ep.verdicts));
    // The controls it ran, one row a frame from keyframe `home`: the attempt replays in
    // plain MuJoCo to the moment it failed.
    let _ = sw_lerobot::write_atomically(&dest.join("actions.json"), &pretty(&ep.recording.actions));
    if let Some(e) = &ep.failure {
        let _ = sw_lerobot::write_atomically(&dest.join("failure.txt"), &format!("{}: {e}\n", e.kind()));
    }
    let mut cams = vec![("front".to_string(), "front".to_string())];
    cams.extend(ep.wrist_camera.clone().map(|c| ("wrist".to_string(), c)));
    let _ = render_videos(&dest, &dest, &cams, ep, spec);
}

enum RenderFailure {
    Input(String),
    Fatal(String),
}

fn render_videos(
    pkg: &Path,
    work: &Path,
    cams: &[(String, String)],
    ep: &sw_expert::Episode,
    spec: &DemosSpec,
) -> Result<BTreeMap<String, sw_lerobot::FeatureStats>, RenderFailure> {
    let specs: Vec<sw_expert::CameraSpec> =
        cams.iter().map(|(k, c)| sw_expert::CameraSpec { key: k.clone(), camera: c.clone() }).collect();
    let [w, h] = spec.image_size;
    let mut r =
        sw_expert::FrameRenderer::new(&pkg.join("scene.xml"), &specs, w as usize, h as usize).map_err(|e| match e {
            sw_expert::ExpertError::Scene(m) => RenderFailure::Input(m),
            other => RenderFailure::Fatal(other.to_string()),
        })?;
    let mut writers: Vec<VideoWriter> = Vec::new();
    for (k, _) in cams {
        let path = work.join(format!("videos/{k}.mp4"));
        writers.push(
            VideoWriter::create(&path, w as usize, h as usize, spec.fps)
                .map_err(|e| RenderFailure::Fatal(e.to_string()))?,
        );
    }
    let mut sink = |cam: usize, rgb: &[u8]| -> Result<(), sw_expert::ExpertError> {
        writers[cam].push(rgb).map_err(|e| sw_expert::ExpertError::Render(e.to_string()))
    };
    r.render(&ep.recording.qpos, &mut sink).map_err(|e| RenderFailure::Fatal(e.to_string()))?;
    let mut out = BTreeMap::new();
    for ((k, _), wr) in cams.iter().zip(writers) {
        out.insert(k.clone(), wr.finish().map_err(|e| RenderFailure::Fatal(e.to_string()))?);
    }
    Ok(out)
}

fn f32_rows(rows: &[Vec<f64>]) -> Vec<Vec<f32>> {
    rows.iter().map(|r| r.iter().map(|v| *v as f32).collect()).collect()
}

fn info_of(e: &EpisodeFile, size: [u32; 2]) -> DatasetInfo {
    let vector = |key: &str, names: &[String]| FeatureSpec {
        key: key.into(),
        dtype: Dtype::Float32,
        shape: vec![names.len()],
        names: names.to_vec(),
    };
    let mut features = vec![vector("action", &e.action_names), vector("observation.state", &e.state_names)];
    if !e.env_names.is_empty() {
        features.push(vector("observation.environment_state", &e.env_names));
    }
    for (k, _) in &e.cameras {
        features.push(FeatureSpec {
            key: k.clone(),
            dtype: Dtype::Video,
            shape: vec![size[1] as usize, size[0] as usize, 3],
            names: Vec::new(),
        });
    }
    DatasetInfo { fps: e.fps, robot_type: e.robot_model.clone(), features }
}

#[allow(clippy::too_many_arguments)]
fn commit(
    sh: &Shared<'_>,
    p: usize,
    seed: u64,
    work: &Path,
    pkg: &Path,
    task: &Task,
    robot_model: &str,
    ep: sw_expert::Episode,
    cams: Vec<(String, String)>,
    image_stats: BTreeMap<String, sw_lerobot::FeatureStats>,
    randomisation: sw_expert::Randomisation,
    started: Instant,
) -> Result<Tried, Stop> {
    let spec = sh.dir.spec();
    let actions = f32_rows(&ep.recording.actions);
    let states = f32_rows(&ep.recording.states);
    let env = f32_rows(&ep.recording.env);
    let n = actions.len() as u64;
    let mut stats: BTreeMap<String, sw_lerobot::FeatureStats> = BTreeMap::new();
    stats.insert("action".into(), sw_lerobot::FeatureStats::of_rows(&ep.recording.actions, ep.action_names.len()));
    stats.insert(
        "observation.state".into(),
        sw_lerobot::FeatureStats::of_rows(&ep.recording.states, ep.state_names.len()),
    );
    if !ep.env_names.is_empty() {
        stats.insert(
            "observation.environment_state".into(),
            sw_lerobot::FeatureStats::of_rows(&ep.recording.env, ep.env_names.len()),
        );
    }
    stats.extend(image_stats);
    let _guard = lock(&sh.commit);
    // Every episode of a dataset has the same features: the first one sets them.
    let mut info_slot = lock(&sh.info);
    let mut file = EpisodeFile {
        record: EpisodeRecord { episode_index: 0, length: n, task: task.instruction.clone(), first_index: 0, stats },
        prompt_index: p,
        seed,
        robot: task.robot.clone(),
        robot_model: robot_model.to_string(),
        family: task.family.name().to_string(),
        fps: ep.fps,
        substeps: ep.substeps,
        timestep: ep.timestep,
        action_names: ep.action_names.clone(),
        state_names: ep.state_names.clone(),
        env_names: ep.env_names.clone(),
        cameras: cams.clone(),
        randomisation,
        verdicts: ep.verdicts.clone(),
        planning: ep.stats.clone(),
        bytes: 0,
    };
    let info = info_slot.clone().unwrap_or_else(|| info_of(&file, spec.image_size));
    let same =
        |key: &str, names: &[String]| info.features.iter().find(|f| f.key == key).is_some_and(|f| f.names == names);
    if !same("action", &ep.action_names)
        || !same("observation.state", &ep.state_names)
        || (!ep.env_names.is_empty() && !same("observation.environment_state", &ep.env_names))
    {
        drop(info_slot);
        let _ = std::fs::remove_dir_all(work);
        let mut st = lock(&sh.stats);
        st.attempts += 1;
        *st.failures.entry("other_robot".into()).or_insert(0) += 1;
        drop(st);
        let line = AttemptLine {
            prompt_index: p,
            seed,
            outcome: "other_robot".into(),
            reason: Some("this scene's robot or things differ from the dataset's first episode (a dataset has one action and state layout)".into()),
            family: Some(task.family.name().into()),
            episode: None,
            seconds: started.elapsed().as_secs_f64(),
        };
        sh.dir.log_attempt(&line).map_err(fatal)?;
        return Ok(Tried::Failed);
    }
    let mut eps = lock(&sh.dir.episodes);
    let index = eps.len() as u64;
    let first_index: u64 = eps.iter().map(|e| e.record.length).sum();
    file.record.episode_index = index;
    file.record.first_index = first_index;
    let root = sh.dir.root();
    let task_index = {
        let mut tasks: Vec<&str> = Vec::new();
        for e in eps.iter() {
            if !tasks.contains(&e.record.task.as_str()) {
                tasks.push(&e.record.task);
            }
        }
        tasks.iter().position(|t| *t == task.instruction).unwrap_or(tasks.len()) as u64
    };
    let mut columns =
        vec![Column { key: "action", rows: &actions }, Column { key: "observation.state", rows: &states }];
    if !ep.env_names.is_empty() {
        columns.push(Column { key: "observation.environment_state", rows: &env });
    }
    let place = EpisodePlace { episode_index: index, task_index, first_index, fps: ep.fps };
    let mut bytes = sw_lerobot::write_episode(&sw_lerobot::data_path(root, index), place, &columns).map_err(fatal)?;
    for (k, _) in &cams {
        let from = work.join(format!("videos/{k}.mp4"));
        let to = sw_lerobot::video_path(root, k, index);
        if let Some(d) = to.parent() {
            std::fs::create_dir_all(d).map_err(fatal)?;
        }
        std::fs::rename(&from, &to).map_err(fatal)?;
        bytes += std::fs::metadata(&to).map(|m| m.len()).unwrap_or(0);
    }
    bytes += dir_size(pkg);
    file.bytes = bytes;
    sw_lerobot::write_atomically(&pkg.join("episode.json"), &pretty(&file)).map_err(fatal)?;
    std::fs::rename(pkg, episode_dir(root, index)).map_err(fatal)?;
    eps.push(file);
    drop(eps);
    *info_slot = Some(info.clone());
    drop(info_slot);
    let _ = std::fs::remove_dir_all(work);
    {
        let mut st = lock(&sh.stats);
        st.made += 1;
        st.frames += n;
        st.bytes += bytes;
    }
    // The attempt line after the commit: a kill in between loses a count, not an episode.
    let line = AttemptLine {
        prompt_index: p,
        seed,
        outcome: "solved".into(),
        reason: None,
        family: Some(task.family.name().into()),
        episode: Some(index),
        seconds: (started.elapsed().as_secs_f64() * 1000.0).round() / 1000.0,
    };
    {
        let mut st = lock(&sh.stats);
        st.attempts += 1;
        st.solved += 1;
        let e = st.families.entry(task.family.name().into()).or_insert((0, 0));
        e.0 += 1;
        e.1 += 1;
    }
    sh.dir.log_attempt(&line).map_err(fatal)?;
    // Metadata now and then, so that a long run is readable while it goes.
    let mut last = lock(&sh.last_meta);
    if last.elapsed() > Duration::from_secs(20) {
        *last = Instant::now();
        sh.dir.write_meta(&info).map_err(fatal)?;
    }
    drop(last);
    sh.progress.made();
    Ok(Tried::Episode)
}

fn dir_size(p: &Path) -> u64 {
    let Ok(entries) = std::fs::read_dir(p) else { return 0 };
    entries
        .flatten()
        .map(|e| {
            let path = e.path();
            if path.is_dir() { dir_size(&path) } else { e.metadata().map(|m| m.len()).unwrap_or(0) }
        })
        .sum()
}

fn pretty<T: Serialize>(v: &T) -> String {
    let mut s = serde_json::to_string_pretty(v).unwrap_or_default();
    s.push('\n');
    s
}

fn report(s: &Summary, json: bool) {
    if json {
        print_json(s);
        return;
    }
    let mut lines = vec![format!(
        "demos    {} · {} of {} episodes ({} made now in {:.1} s, {} before)",
        s.out_dir.display(),
        s.episodes,
        s.episodes_wanted,
        s.made,
        s.seconds,
        s.resumed_episodes
    )];
    lines.push(format!(
        "rate     {:.1} episodes/min with {} jobs · {} frames · {} bytes/episode",
        s.episodes_per_min, s.jobs, s.frames, s.bytes_per_episode
    ));
    let failures: Vec<String> = s.failures.iter().map(|(k, v)| format!("{v} {k}")).collect();
    lines.push(format!(
        "solved   {} of {} attempts{}",
        s.solved,
        s.attempts,
        if failures.is_empty() { String::new() } else { format!(" · discarded: {}", failures.join(", ")) }
    ));
    if s.resampled > 0 {
        lines.push(format!("redrawn  {} variants whose start already satisfied the task", s.resampled));
    }
    for (f, (ok, n)) in &s.families {
        lines.push(format!("family   {f}: {ok}/{n}"));
    }
    if s.gave_up > 0 {
        lines.push(format!("gave up  {} episodes (no solved attempt in {TRIES})", s.gave_up));
    }
    if s.interrupted {
        lines.push("stopped  interrupted; run the same command again to resume".into());
    }
    print(&lines.join("\n"));
}
