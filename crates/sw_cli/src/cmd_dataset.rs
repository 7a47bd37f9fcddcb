//! `dataset`: N structurally different verified scenes per prompt, on every core, into a
//! directory with `manifest.jsonl` — resumable after kill -9 or Ctrl-C (see
//! `sw_pipeline::dataset` for the directory and why a kill loses nothing).
//!
//! Each prompt has a seed stream (from `--seed`); a scene slot takes the next seed until
//! it gets a verified scene whose structural fingerprint (`sw_pipeline::manifest::
//! fingerprint`) no earlier scene of the dataset has, up to [`TRIES`] seeds. With
//! `--database`, the same run goes through the service's job queue instead
//! (`crate::dataset_queue`).

use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::ffi::OsString;
use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use sw_pipeline::dataset::{DatasetDir, DatasetError, DatasetSpec, Resumed, TRIES, failure_reason};
use sw_pipeline::{Options, PhysicsTarget, PipelineError};
use sw_plan::AnomalyRequest;

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Debug, clap::Args)]
pub(crate) struct DatasetArgs {
    /// One prompt.
    #[arg(long, conflicts_with = "prompts", required_unless_present = "prompts")]
    prompt: Option<OsString>,
    /// A file of prompts: one per line, `#` starts a comment, blank lines are skipped.
    #[arg(long)]
    prompts: Option<PathBuf>,
    /// Scenes per prompt.
    #[arg(long)]
    count: u32,
    /// The dataset directory (new, empty, or a dataset of the same prompts and options to
    /// resume or extend).
    #[arg(long)]
    out: PathBuf,
    /// Scenes made at once (default: every core).
    #[arg(long)]
    jobs: Option<usize>,
    /// `native` (MuJoCo, MuJoCo Warp) or `mjx` (MuJoCo XLA's collision pairs).
    #[arg(long, default_value = "native", value_parser = parse_physics)]
    physics: PhysicsTarget,
    /// Draw each scene's robot from this list (`none` for no robot), instead of the prompt's.
    #[arg(long, value_delimiter = ',')]
    robots: Option<Vec<String>>,
    /// Inject labelled anomalies: overlap, scale, misplacement, floating, rule-violation, all.
    #[arg(long, value_delimiter = ',')]
    anomaly: Option<Vec<String>>,
    /// Fraction of eligible objects to corrupt with --anomaly.
    #[arg(long, default_value_t = 0.2)]
    anomaly_rate: f64,
    /// The first seed of every prompt's seed stream.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Run on the service's job queue (postgres://… with the S3 store, or a SQLite file):
    /// every `scenewright worker` on the same database and store makes scenes.
    #[arg(long)]
    database: Option<String>,
    /// With --database: the blob store's directory when no S3 store is configured.
    #[arg(long)]
    data: Option<PathBuf>,
    /// Print one JSON summary instead of progress and a summary.
    #[arg(long)]
    json: bool,
}

pub(crate) fn parse_physics(s: &str) -> Result<PhysicsTarget, String> {
    PhysicsTarget::parse(s).ok_or_else(|| format!("unknown physics target '{s}' (native, mjx)"))
}

/// Set by Ctrl-C while a dataset runs: the run stops between stages and keeps what it made.
static STOP: OnceLock<Arc<AtomicBool>> = OnceLock::new();
pub(crate) static ACTIVE: AtomicBool = AtomicBool::new(false);

pub(crate) fn stop_flag() -> Arc<AtomicBool> {
    STOP.get_or_init(|| Arc::new(AtomicBool::new(false))).clone()
}

/// For the Ctrl-C handler: true when a dataset run took the interrupt (the first one) and
/// will stop by itself, keeping every finished scene; false when the process should exit.
pub(crate) fn interrupt() -> bool {
    ACTIVE.load(Ordering::SeqCst) && !stop_flag().swap(true, Ordering::SeqCst)
}

/// The prompts of `--prompt` or `--prompts`, each checked by the planner.
fn read_prompts(a: &DatasetArgs) -> Result<Vec<String>, Failure> {
    let prompts: Vec<(String, String)> = match (&a.prompt, &a.prompts) {
        (Some(p), _) => {
            let p = p.to_str().ok_or_else(|| Failure::input("the prompt is not valid UTF-8 text"))?;
            vec![("--prompt".to_string(), p.to_string())]
        }
        (None, Some(path)) => {
            let bytes = fs_err::read(path).map_err(|e| Failure::input(e.to_string()))?;
            let mut out = Vec::new();
            for (i, line) in bytes.split(|b| *b == b'\n').enumerate() {
                let where_ = format!("{} line {}", path.display(), i + 1);
                let line = std::str::from_utf8(line)
                    .map_err(|_| Failure::input(format!("{where_} is not UTF-8 text")))?
                    .trim();
                if line.is_empty() || line.starts_with('#') {
                    continue;
                }
                out.push((where_, line.to_string()));
            }
            if out.is_empty() {
                return Err(Failure::input(format!("{} holds no prompts", path.display())));
            }
            out
        }
        (None, None) => return Err(Failure::input("give --prompt or --prompts")),
    };
    for (where_, p) in &prompts {
        sw_planner::plan(p).map_err(|e| Failure::input(format!("{where_}: {e}")))?;
    }
    Ok(prompts.into_iter().map(|(_, p)| p).collect())
}

/// The dataset's spec from the arguments, every option checked.
fn spec_of(a: &DatasetArgs) -> Result<DatasetSpec, Failure> {
    if a.count == 0 || a.count > 1_000_000 {
        return Err(Failure::input(format!("--count must be between 1 and 1000000, got {}", a.count)));
    }
    if a.jobs == Some(0) {
        return Err(Failure::input("--jobs must be at least 1"));
    }
    let mut spec = DatasetSpec::new(read_prompts(a)?, a.count);
    spec.seed = a.seed;
    spec.physics = a.physics.name().to_string();
    if let Some(list) = &a.robots {
        let mut robots = Vec::new();
        for r in list {
            let r = r.trim().to_lowercase();
            if r.is_empty() {
                continue;
            }
            if r != "none" && sw_robots::find(&r).is_none() {
                return Err(Failure::input(sw_robots::why_missing(&r).unwrap_or_else(|| {
                    let known: Vec<&str> = sw_robots::registry().iter().map(|d| d.name).collect();
                    format!("unknown robot '{r}' (known: {}, none)", known.join(", "))
                })));
            }
            robots.push(r);
        }
        if robots.is_empty() {
            return Err(Failure::input("--robots names no robot (use `none` for scenes without robots)"));
        }
        spec.robots = Some(robots);
    }
    if let Some(kinds) = &a.anomaly {
        if !(a.anomaly_rate.is_finite() && (0.0..=1.0).contains(&a.anomaly_rate)) {
            return Err(Failure::input(format!("the anomaly rate must be in 0..1, got {}", a.anomaly_rate)));
        }
        spec.anomaly =
            Some(AnomalyRequest { kinds: crate::cmd_generate::parse_anomalies(kinds)?, rate: a.anomaly_rate });
    }
    Ok(spec)
}

/// What a run did.
#[derive(Debug, Default, Serialize)]
pub(crate) struct Summary {
    pub out_dir: PathBuf,
    pub manifest: PathBuf,
    /// Scenes the dataset should hold (prompts × count).
    pub scenes_wanted: usize,
    /// Scenes it holds now.
    pub scenes_listed: usize,
    /// Scenes made by this run.
    pub made: usize,
    pub resumed: Resumed,
    pub seconds: f64,
    pub scenes_per_s: f64,
    /// Scenes made at once in this process (0: on the job queue's workers).
    pub jobs: usize,
    /// Scenes attempted by this run (made, failed and duplicates).
    pub attempts: usize,
    /// Made / attempts.
    pub valid_share: f64,
    pub failures: BTreeMap<String, usize>,
    /// Slots that found no valid new scene in [`TRIES`] seeds.
    pub gave_up: Vec<String>,
    pub interrupted: bool,
}

pub(crate) fn run(a: DatasetArgs) -> Result<u8, Failure> {
    let spec = spec_of(&a)?;
    if let Some(db) = &a.database {
        return crate::dataset_queue::run(&a.out, spec, db, a.data.as_deref(), a.json);
    }
    let (dir, resumed) = DatasetDir::open(&a.out, &spec).map_err(dataset_failure)?;
    let jobs = a.jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())).max(1);
    ACTIVE.store(true, Ordering::SeqCst);
    let summary = make_scenes(&dir, resumed, jobs);
    ACTIVE.store(false, Ordering::SeqCst);
    let summary = summary?;
    report(&summary, a.json);
    Ok(if summary.interrupted {
        130
    } else if summary.scenes_listed < summary.scenes_wanted {
        1
    } else {
        0
    })
}

/// Every reason a dataset directory cannot be used is bad input (exit 2).
pub(crate) fn dataset_failure(e: DatasetError) -> Failure {
    Failure::input(e.to_string())
}

struct Shared<'a> {
    dir: &'a DatasetDir,
    pending: Mutex<VecDeque<(usize, u32)>>,
    seeds: Vec<AtomicU64>,
    fingerprints: Mutex<BTreeSet<String>>,
    stop: Arc<AtomicBool>,
    fatal: Mutex<Option<String>>,
    stats: Mutex<Stats>,
    progress: Progress,
}

#[derive(Default)]
struct Stats {
    made: usize,
    attempts: usize,
    failures: BTreeMap<String, usize>,
    gave_up: Vec<String>,
}

fn make_scenes(dir: &DatasetDir, resumed: Resumed, jobs: usize) -> Result<Summary, Failure> {
    let spec = dir.spec();
    let pending = dir.pending();
    let wanted = spec.prompts.len() * spec.count as usize;
    let mut next_seed: Vec<u64> = vec![spec.seed; spec.prompts.len()];
    for e in dir.entries() {
        if let Some(s) = next_seed.get_mut(e.prompt_index as usize) {
            *s = (*s).max(e.seed.saturating_add(1));
        }
    }
    let stop = stop_flag();
    let shared = Shared {
        dir,
        pending: Mutex::new(pending.into()),
        seeds: next_seed.into_iter().map(AtomicU64::new).collect(),
        fingerprints: Mutex::new(dir.entries().iter().map(|e| e.fingerprint.clone()).collect()),
        stop: stop.clone(),
        fatal: Mutex::new(None),
        stats: Mutex::new(Stats::default()),
        progress: Progress::new(wanted, dir.entries().len()),
    };
    let started = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..jobs {
            s.spawn(|| worker(&shared));
        }
    });
    let seconds = started.elapsed().as_secs_f64();
    shared.progress.finish();
    dir.sync().map_err(|e| Failure::internal(e.to_string()))?;
    if let Some(message) = lock(&shared.fatal).take() {
        let made = lock(&shared.stats).made;
        return Err(Failure::internal(format!(
            "{message}; {} scenes are complete ({made} made now); run the same command again to resume",
            dir.entries().len() + made
        )));
    }
    let stats = std::mem::take(&mut *lock(&shared.stats));
    let listed = dir.entries().len() + stats.made;
    Ok(Summary {
        out_dir: dir.root().to_path_buf(),
        manifest: dir.root().join("manifest.jsonl"),
        scenes_wanted: wanted,
        scenes_listed: listed,
        made: stats.made,
        resumed,
        seconds: (seconds * 1000.0).round() / 1000.0,
        scenes_per_s: if seconds > 0.0 { ((stats.made as f64 / seconds) * 100.0).round() / 100.0 } else { 0.0 },
        jobs,
        attempts: stats.attempts,
        valid_share: if stats.attempts > 0 {
            ((stats.made as f64 / stats.attempts as f64) * 1000.0).round() / 1000.0
        } else {
            1.0
        },
        failures: stats.failures,
        gave_up: stats.gave_up,
        interrupted: stop.load(Ordering::SeqCst) && listed < wanted,
    })
}

pub(crate) fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    match m.lock() {
        Ok(g) => g,
        Err(poisoned) => poisoned.into_inner(),
    }
}

fn worker(sh: &Shared<'_>) {
    while !sh.stop.load(Ordering::SeqCst) {
        let Some((p, k)) = lock(&sh.pending).pop_front() else { break };
        let id = DatasetSpec::scene_id(p, k);
        let mut done = false;
        for _ in 0..TRIES {
            if sh.stop.load(Ordering::SeqCst) {
                return;
            }
            let seed = sh.seeds[p].fetch_add(1, Ordering::SeqCst);
            match attempt(sh, p, &id, seed) {
                Ok(true) => {
                    done = true;
                    break;
                }
                Ok(false) => {}
                Err(Stop::Interrupted) => return,
                Err(Stop::Fatal(message)) => {
                    lock(&sh.fatal).get_or_insert(message);
                    sh.stop.store(true, Ordering::SeqCst);
                    return;
                }
            }
        }
        if !done {
            lock(&sh.stats).gave_up.push(id.clone());
            sh.progress.note(&format!("{id}: no valid new scene in {TRIES} seeds; given up"));
        }
    }
}

enum Stop {
    Interrupted,
    /// The dataset cannot be written (a full disk): stop everything, keep what is done.
    Fatal(String),
}

/// One seed for slot `id` of prompt `p`: true when it became a scene of the dataset.
fn attempt(sh: &Shared<'_>, p: usize, id: &str, seed: u64) -> Result<bool, Stop> {
    let spec = sh.dir.spec();
    let robot = spec.draw_robot(p, seed);
    let opts = Options { cancel: Some(sh.stop.clone()), ..spec.scene_options(robot.as_deref(), seed) };
    let work = sh.dir.work_dir(id, seed).map_err(|e| Stop::Fatal(e.to_string()))?;
    let fail = |reason: String| {
        let mut st = lock(&sh.stats);
        st.attempts += 1;
        *st.failures.entry(reason).or_insert(0) += 1;
        drop(st);
        sh.progress.failed();
    };
    let outcome = match sw_pipeline::generate(&spec.prompts[p], &work, &opts, &mut |_| {}) {
        Ok(o) => o,
        Err(PipelineError::Cancelled) => return Err(Stop::Interrupted),
        Err(PipelineError::Output(e)) => return Err(Stop::Fatal(e.to_string())),
        Err(e) => {
            fail(format!("pipeline error: {}", e.to_string().chars().take(80).collect::<String>()));
            return Ok(false);
        }
    };
    if !sw_pipeline::succeeded(&outcome.report) {
        let failures = outcome.report.verification.as_ref().map(|v| v.failures.clone()).unwrap_or_default();
        let _ = std::fs::remove_dir_all(&work);
        fail(failure_reason(&failures));
        return Ok(false);
    }
    let fp = match sw_pipeline::manifest::fingerprint(&work) {
        Ok(fp) => fp,
        Err(e) => return Err(Stop::Fatal(e.to_string())),
    };
    if !lock(&sh.fingerprints).insert(fp) {
        let _ = std::fs::remove_dir_all(&work);
        fail("duplicate of an earlier scene".into());
        return Ok(false);
    }
    sh.dir.commit(&work, id, robot.as_deref()).map_err(|e| Stop::Fatal(e.to_string()))?;
    let mut st = lock(&sh.stats);
    st.attempts += 1;
    st.made += 1;
    drop(st);
    sh.progress.made();
    Ok(true)
}

/// A progress bar with rate and ETA on a terminal, a line every few seconds otherwise.
pub(crate) struct Progress {
    bar: Option<ProgressBar>,
    lines: bool,
    wanted: usize,
    done: AtomicU64,
    failed: AtomicU64,
    started: Instant,
    last_line: Mutex<Instant>,
    start_done: usize,
    /// What is counted ("scenes") and the lines' label ("dataset").
    unit: &'static str,
    label: &'static str,
}

impl Progress {
    /// Progress is on stderr, so it shows with --json too (which is about stdout).
    pub(crate) fn new(wanted: usize, done: usize) -> Self {
        let terminal = std::io::stderr().is_terminal();
        let bar = terminal.then(|| {
            let b = ProgressBar::new(wanted as u64);
            b.set_style(
                ProgressStyle::with_template(
                    "{bar:30.cyan/blue} {pos}/{len} scenes · {per_sec} · ETA {eta} · elapsed {elapsed} {msg}",
                )
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            b.set_position(done as u64);
            b.reset_eta();
            b.enable_steady_tick(Duration::from_millis(200));
            b
        });
        Self {
            bar,
            lines: !terminal,
            wanted,
            done: AtomicU64::new(done as u64),
            failed: AtomicU64::new(0),
            started: Instant::now(),
            last_line: Mutex::new(Instant::now()),
            start_done: done,
            unit: "scenes",
            label: "dataset",
        }
    }

    /// Counts `unit` ("episodes") on lines labelled `label` ("demos").
    pub(crate) fn unit(mut self, unit: &'static str, label: &'static str) -> Self {
        self.unit = unit;
        self.label = label;
        if let Some(b) = &self.bar {
            b.set_style(
                ProgressStyle::with_template(&format!(
                    "{{bar:30.cyan/blue}} {{pos}}/{{len}} {unit} · {{per_sec}} · ETA {{eta}} · elapsed {{elapsed}} {{msg}}"
                ))
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
        }
        self
    }

    pub(crate) fn made(&self) {
        let done = self.done.fetch_add(1, Ordering::SeqCst) + 1;
        if let Some(b) = &self.bar {
            b.set_position(done);
        }
        self.line(false);
    }

    pub(crate) fn failed(&self) {
        let n = self.failed.fetch_add(1, Ordering::SeqCst) + 1;
        if let Some(b) = &self.bar {
            b.set_message(format!("· {n} rejected"));
        }
    }

    pub(crate) fn note(&self, text: &str) {
        match &self.bar {
            Some(b) => b.println(text),
            None if self.lines => eprintln!("{:<8} {text}", self.label),
            None => {}
        }
    }

    /// A plain progress line (not on a terminal), at most every 2 s, and at the end.
    fn line(&self, last: bool) {
        if !self.lines {
            return;
        }
        let mut at = lock(&self.last_line);
        if !last && at.elapsed() < Duration::from_secs(2) {
            return;
        }
        *at = Instant::now();
        let done = self.done.load(Ordering::SeqCst) as usize;
        let new = done.saturating_sub(self.start_done);
        let secs = self.started.elapsed().as_secs_f64().max(1e-9);
        let rate = new as f64 / secs;
        let eta =
            if rate > 0.0 { format!("{:.0} s", (self.wanted.saturating_sub(done)) as f64 / rate) } else { "?".into() };
        eprintln!(
            "{:<8} {done}/{} {unit} · {rate:.2} {unit}/s · ETA {eta} · {} rejected",
            self.label,
            self.wanted,
            self.failed.load(Ordering::SeqCst),
            unit = self.unit
        );
    }

    pub(crate) fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
        self.line(true);
    }
}

pub(crate) fn report(s: &Summary, json: bool) {
    if json {
        print_json(s);
        return;
    }
    let mut lines = vec![format!(
        "dataset  {} · {} of {} scenes ({} made now in {:.1} s, {} listed before{})",
        s.out_dir.display(),
        s.scenes_listed,
        s.scenes_wanted,
        s.made,
        s.seconds,
        s.resumed.listed,
        if s.resumed.adopted > 0 { format!(", {} adopted", s.resumed.adopted) } else { String::new() }
    )];
    lines.push(if s.jobs == 0 {
        format!("rate     {:.1} scenes/s through the job queue", s.scenes_per_s)
    } else {
        format!("rate     {:.1} scenes/s with {} jobs", s.scenes_per_s, s.jobs)
    });
    let failures: Vec<String> = s.failures.iter().map(|(k, v)| format!("{v} {k}")).collect();
    lines.push(format!(
        "valid    {} of {} attempts ({:.1} %){}",
        s.made,
        s.attempts,
        s.valid_share * 100.0,
        if failures.is_empty() { String::new() } else { format!(" · rejected: {}", failures.join(", ")) }
    ));
    if !s.gave_up.is_empty() {
        lines.push(format!("gave up  {} slots: {}", s.gave_up.len(), s.gave_up.join(", ")));
    }
    if s.interrupted {
        lines.push("stopped  interrupted; run the same command again to resume".into());
    }
    lines.push(format!("manifest {}", s.manifest.display()));
    print(&lines.join("\n"));
}
