//! The CAD runner: a pool of long-lived, warm Python workers that run generated
//! CadQuery (or OpenSCAD) code in a sandbox and hand back an STL or a structured error.
//!
//! A worker imports CadQuery once (2–5 s) and never runs generated code itself: each
//! job runs in a process forked from the warm image and confined before the code
//! arrives (Landlock: read the Python installation, write only the job's directory, no
//! TCP, no signals out; seccomp: no sockets, processes, programs or kernel interfaces;
//! rlimits: memory, CPU, file size; no capabilities), after the code's syntax tree has
//! passed the import allow-list. A job that times out or violates the sandbox takes its
//! worker with it: the worker (and anything it forked) is killed and a fresh one started
//! in the background, so the next job never shares a process with hostile code.

mod process;
mod setup;
mod stale;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};
use serde_json::Value;
use sw_geom::Mesh;
use tracing::{debug, info_span, warn};

pub use process::WorkerInfo;
pub use setup::{RunnerConfig, checkout_cache, default_python};

use crate::failure::{Failure, FailureKind};
use crate::mesh_io;

/// The language generated code is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Language {
    #[default]
    #[serde(rename = "cadquery")]
    CadQuery,
    #[serde(rename = "openscad")]
    OpenScad,
}

impl Language {
    pub fn name(self) -> &'static str {
        match self {
            Language::CadQuery => "cadquery",
            Language::OpenScad => "openscad",
        }
    }

    pub fn parse(s: &str) -> Option<Language> {
        match s.trim().to_ascii_lowercase().as_str() {
            "cadquery" | "cq" | "python" => Some(Language::CadQuery),
            "openscad" | "scad" => Some(Language::OpenScad),
            _ => None,
        }
    }

    /// The file extension of its source.
    pub fn extension(self) -> &'static str {
        match self {
            Language::CadQuery => "py",
            Language::OpenScad => "scad",
        }
    }
}

/// One piece of code to run.
#[derive(Debug, Clone, PartialEq)]
pub struct CadJob {
    pub language: Language,
    pub code: String,
    /// Check the syntax tree against the import allow-list first (always on outside of
    /// tests that prove the operating-system layers hold on their own).
    pub check_policy: bool,
}

impl CadJob {
    pub fn cadquery(code: impl Into<String>) -> Self {
        Self { language: Language::CadQuery, code: code.into(), check_policy: true }
    }

    pub fn openscad(code: impl Into<String>) -> Self {
        Self { language: Language::OpenScad, code: code.into(), check_policy: true }
    }
}

/// Where the time of one job went, ms.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct RunTimings {
    /// From sending the job to having the mesh in memory.
    pub roundtrip_ms: f64,
    /// The job process (code, export) as the worker measured it.
    pub job_ms: f64,
    pub exec_ms: f64,
    pub export_ms: f64,
    /// Reading and welding the STL.
    pub read_ms: f64,
}

/// A successful run: the mesh as the code made it (in the code's units).
#[derive(Debug, Clone)]
pub struct CadRun {
    pub mesh: Mesh,
    /// The exact solid's volume from the CAD kernel (CadQuery jobs).
    pub brep_volume: Option<f64>,
    pub brep_bbox: Option<[[f64; 3]; 2]>,
    pub timings: RunTimings,
    /// What the code printed (the first 4 KiB).
    pub output: String,
    pub worker_pid: u32,
    pub job_pid: Option<u32>,
}

/// A failed run.
#[derive(Debug, Clone, thiserror::Error)]
#[error("{failure}")]
pub struct CadError {
    pub failure: Failure,
    /// The worker that ran the job was killed and a fresh one started.
    pub worker_replaced: bool,
    pub worker_pid: Option<u32>,
    pub detail: Box<CadErrorDetail>,
}

/// The rest of what is known about a failed run.
#[derive(Debug, Clone, Default)]
pub struct CadErrorDetail {
    /// What the code printed (the first 4 KiB).
    pub output: String,
    pub timings: RunTimings,
    /// Every violation the job committed, when the sandbox reported several.
    pub violations: Vec<String>,
}

impl CadError {
    fn new(failure: Failure, worker_replaced: bool, worker_pid: Option<u32>, detail: CadErrorDetail) -> Self {
        Self { failure, worker_replaced, worker_pid, detail: Box::new(detail) }
    }

    fn runner(message: impl Into<String>) -> Self {
        Self::new(Failure::new(FailureKind::Runner, message), false, None, CadErrorDetail::default())
    }

    /// What the code printed.
    pub fn output(&self) -> &str {
        &self.detail.output
    }
}

/// Why the runner could not start.
#[derive(Debug, Clone, thiserror::Error)]
pub enum RunnerError {
    #[error(
        "CadQuery is not set up: {python} does not exist (run `scripts/setup.sh --cad`, or set SCENEWRIGHT_CAD_PYTHON)"
    )]
    NotInstalled { python: String },
    #[error("could not start the CAD worker with {python}: {message}")]
    Spawn { python: String, message: String },
    #[error("the CAD worker did not start: {0}")]
    Startup(String),
    #[error("the CAD worker refused to run code: a sandbox layer is missing on this machine ({0})")]
    SandboxUnavailable(String),
    #[error("CAD runner: {0}")]
    Io(String),
}

/// Counters over the runner's life.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct RunnerStats {
    pub jobs: u64,
    pub succeeded: u64,
    pub failed: u64,
    /// Workers killed and replaced (after a timeout, a sandbox violation, a crash).
    pub replaced: u64,
    pub workers_started: u64,
}

/// The pool. Cheap to clone; every clone shares the workers.
#[derive(Debug, Clone)]
pub struct CadRunner {
    inner: Arc<Inner>,
}

#[derive(Debug)]
struct Inner {
    config: RunnerConfig,
    script: PathBuf,
    runtime: tempfile::TempDir,
    slots: Mutex<Slots>,
    changed: Condvar,
    stats: Mutex<RunnerStats>,
    info: Mutex<Option<WorkerInfo>>,
    seq: AtomicU64,
}

#[derive(Debug, Default)]
struct Slots {
    idle: Vec<process::WorkerProcess>,
    starting: usize,
    last_error: Option<RunnerError>,
    generation: u64,
    closed: bool,
}

impl CadRunner {
    /// Starts `config.workers` workers in parallel and waits until each is ready (or has
    /// failed). Fails only when none starts.
    pub fn start(config: RunnerConfig) -> Result<Self, RunnerError> {
        let _span = info_span!("cad_runner_start", workers = config.workers).entered();
        if !config.python.exists() {
            return Err(RunnerError::NotInstalled { python: config.python.display().to_string() });
        }
        for d in stale::sweep(&std::env::temp_dir()) {
            debug!("removed the runtime directory of a runner that was killed: {}", d.display());
        }
        let runtime = tempfile::Builder::new()
            .prefix(stale::PREFIX)
            .tempdir()
            .map_err(|e| RunnerError::Io(format!("creating the runtime directory: {e}")))?;
        stale::claim(runtime.path())
            .map_err(|e| RunnerError::Io(format!("writing the runtime directory's owner: {e}")))?;
        let script = setup::write_sources(&runtime.path().join("py"))
            .map_err(|e| RunnerError::Io(format!("writing the worker's sources: {e}")))?;
        let workers = config.workers.max(1);
        let inner = Arc::new(Inner {
            config,
            script,
            runtime,
            slots: Mutex::new(Slots::default()),
            changed: Condvar::new(),
            stats: Mutex::new(RunnerStats::default()),
            info: Mutex::new(None),
            seq: AtomicU64::new(0),
        });
        for _ in 0..workers {
            Inner::spawn_async(&inner);
        }
        // Wait until every worker is up or has failed.
        let mut slots = lock(&inner.slots);
        while slots.starting > 0 {
            slots = inner.changed.wait(slots).unwrap_or_else(|e| e.into_inner());
        }
        if slots.idle.is_empty() {
            let err = slots.last_error.clone().unwrap_or_else(|| RunnerError::Startup("no worker started".into()));
            slots.closed = true;
            return Err(err);
        }
        if let Some(e) = &slots.last_error {
            warn!("{} of {workers} CAD workers started: {e}", slots.idle.len());
        }
        drop(slots);
        Ok(Self { inner })
    }

    /// What the first worker reported: Python and CadQuery versions, languages, the
    /// sandbox layers in force.
    pub fn info(&self) -> Option<WorkerInfo> {
        lock(&self.inner.info).clone()
    }

    pub fn config(&self) -> &RunnerConfig {
        &self.inner.config
    }

    pub fn stats(&self) -> RunnerStats {
        *lock(&self.inner.stats)
    }

    /// Workers ready now.
    pub fn idle_workers(&self) -> usize {
        lock(&self.inner.slots).idle.len()
    }

    /// Waits until `n` workers are idle (after replacements), up to `timeout`.
    pub fn wait_idle(&self, n: usize, timeout: Duration) -> bool {
        let deadline = Instant::now() + timeout;
        let mut slots = lock(&self.inner.slots);
        while slots.idle.len() < n {
            let now = Instant::now();
            if now >= deadline || (slots.starting == 0 && slots.idle.len() < n) {
                return slots.idle.len() >= n;
            }
            slots = self
                .inner
                .changed
                .wait_timeout(slots, deadline - now)
                .map(|(g, _)| g)
                .unwrap_or_else(|e| e.into_inner().0);
        }
        true
    }

    /// Runs one job on a free worker (waiting for one if all are busy).
    pub fn run(&self, job: &CadJob) -> Result<CadRun, CadError> {
        let id = self.inner.seq.fetch_add(1, Ordering::Relaxed) + 1;
        let _span = info_span!("cad_job", job = id, language = job.language.name()).entered();
        let started = Instant::now();
        let mut worker = self.inner.acquire()?;
        let c = &self.inner.config;
        let request = serde_json::json!({
            "id": id.to_string(),
            "language": job.language.name(),
            "code": job.code,
            "timeout_s": c.timeout.as_secs_f64(),
            "memory_mb": c.memory_mb,
            "max_output_mb": c.max_output_mb,
            "max_triangles": c.max_triangles,
            "check_policy": job.check_policy,
            "linear_deflection": c.linear_deflection,
            "angular_deflection": c.angular_deflection,
        });
        // The worker enforces the time limit itself; this deadline catches a worker
        // that stops answering altogether.
        let deadline = c.timeout + Duration::from_secs(5);
        let worker_pid = worker.info.pid;
        let answer = worker.call(&request, deadline);
        let result = match answer {
            Err(fault) => {
                let (kind, message) = match fault {
                    process::Fault::Hung => (
                        FailureKind::Timeout,
                        format!("the worker did not answer within {:.0} s and was killed", deadline.as_secs_f64()),
                    ),
                    process::Fault::Died(tail) => (FailureKind::Runtime, format!("the worker died: {tail}")),
                    process::Fault::Protocol(m) => {
                        (FailureKind::Runtime, format!("the worker broke its protocol: {m}"))
                    }
                };
                Inner::replace(&self.inner, worker);
                Err(CadError::new(
                    Failure::new(kind, message),
                    true,
                    Some(worker_pid),
                    CadErrorDetail {
                        timings: RunTimings { roundtrip_ms: ms(started), ..RunTimings::default() },
                        ..CadErrorDetail::default()
                    },
                ))
            }
            Ok(answer) => {
                let r = interpret(&answer, &worker.root, c, started, worker_pid);
                let poisoned = match &r {
                    Err(e) => e.worker_replaced,
                    Ok(_) => false,
                };
                if poisoned {
                    Inner::replace(&self.inner, worker);
                } else {
                    self.inner.release(worker);
                }
                r
            }
        };
        let mut stats = lock(&self.inner.stats);
        stats.jobs += 1;
        match &result {
            Ok(_) => stats.succeeded += 1,
            Err(e) => {
                stats.failed += 1;
                debug!(kind = %e.failure.kind, "job failed: {}", e.failure.message);
            }
        }
        result
    }

    /// The runtime directory the workers live in (removed when the runner is dropped).
    pub fn runtime_dir(&self) -> &Path {
        self.inner.runtime.path()
    }
}

impl Drop for Inner {
    fn drop(&mut self) {
        let mut slots = lock(&self.slots);
        slots.closed = true;
        for mut w in slots.idle.drain(..) {
            w.kill();
        }
    }
}

impl Inner {
    fn spawn_async(inner: &Arc<Inner>) {
        let generation = {
            let mut slots = lock(&inner.slots);
            slots.starting += 1;
            slots.generation += 1;
            slots.generation
        };
        let me = Arc::clone(inner);
        std::thread::spawn(move || {
            let root = me.runtime.path().join(format!("w{generation}"));
            let started = Instant::now();
            let result = process::WorkerProcess::spawn(&me.config, &me.script, root);
            let mut slots = lock(&me.slots);
            slots.starting -= 1;
            match result {
                Ok(w) => {
                    debug!(pid = w.info.pid, ms = ms(started), "CAD worker ready");
                    {
                        let mut info = lock(&me.info);
                        if info.is_none() {
                            *info = Some(w.info.clone());
                        }
                    }
                    lock(&me.stats).workers_started += 1;
                    if slots.closed {
                        drop(slots);
                        drop(w);
                    } else {
                        slots.idle.push(w);
                    }
                }
                Err(e) => {
                    warn!("a CAD worker failed to start: {e}");
                    slots.last_error = Some(e);
                }
            }
            me.changed.notify_all();
        });
    }

    fn acquire(&self) -> Result<process::WorkerProcess, CadError> {
        let wait = self.config.startup_timeout + self.config.timeout;
        let deadline = Instant::now() + wait;
        let mut slots = lock(&self.slots);
        loop {
            if let Some(w) = slots.idle.pop() {
                return Ok(w);
            }
            if slots.starting == 0 && slots.idle.is_empty() {
                // Every worker is busy: keep waiting for one to come back, unless
                // there are none at all (all failed to start).
                if let Some(e) = &slots.last_error
                    && lock(&self.stats).workers_started == 0
                {
                    return Err(CadError::runner(e.to_string()));
                }
            }
            let now = Instant::now();
            if now >= deadline {
                return Err(CadError::runner(format!("no CAD worker became free within {:.0} s", wait.as_secs_f64())));
            }
            slots =
                self.changed.wait_timeout(slots, deadline - now).map(|(g, _)| g).unwrap_or_else(|e| e.into_inner().0);
        }
    }

    fn release(&self, w: process::WorkerProcess) {
        let mut slots = lock(&self.slots);
        if slots.closed {
            drop(slots);
            drop(w);
            return;
        }
        slots.idle.push(w);
        self.changed.notify_all();
    }

    /// Kills a worker that ran hostile or runaway code and starts a fresh one.
    fn replace(inner: &Arc<Inner>, mut w: process::WorkerProcess) {
        w.kill();
        lock(&inner.stats).replaced += 1;
        Inner::spawn_async(inner);
    }
}

/// Turns a worker's answer into a run or an error.
fn interpret(
    answer: &Value,
    root: &Path,
    c: &RunnerConfig,
    started: Instant,
    worker_pid: u32,
) -> Result<CadRun, CadError> {
    let num = |v: Option<&Value>| v.and_then(Value::as_f64).unwrap_or(0.0);
    let ms_obj = answer.get("ms");
    let mut timings = RunTimings {
        roundtrip_ms: 0.0,
        job_ms: num(ms_obj.and_then(|m| m.get("job"))),
        exec_ms: num(ms_obj.and_then(|m| m.get("exec"))),
        export_ms: num(ms_obj.and_then(|m| m.get("export"))),
        read_ms: 0.0,
    };
    let output = answer.get("output").and_then(Value::as_str).unwrap_or("").to_string();
    let job_pid = answer.get("pid").and_then(Value::as_u64).map(|p| p as u32);
    if answer.get("ok").and_then(Value::as_bool) != Some(true) {
        let err = answer.get("error");
        let kind_s = err.and_then(|e| e.get("kind")).and_then(Value::as_str).unwrap_or("crash");
        let message =
            err.and_then(|e| e.get("message")).and_then(Value::as_str).unwrap_or("the job failed").to_string();
        let line = err.and_then(|e| e.get("line")).and_then(Value::as_u64).map(|l| l as u32);
        let violations = err
            .and_then(|e| e.get("all"))
            .and_then(Value::as_array)
            .map(|a| a.iter().filter_map(|v| v.as_str().map(str::to_string)).collect())
            .unwrap_or_default();
        // Code that timed out, crashed the kernel or touched the sandbox's walls ran in
        // a process forked from this worker: retire the worker too.
        let executed = job_pid.is_some();
        let poisoned = executed && matches!(kind_s, "timeout" | "sandbox" | "memory" | "output_limit" | "crash");
        timings.roundtrip_ms = ms(started);
        return Err(CadError::new(
            Failure::new(FailureKind::from_worker(kind_s), message).at_line(line),
            poisoned,
            Some(worker_pid),
            CadErrorDetail { output, timings, violations },
        ));
    }
    let Some(stl) = answer.get("stl").and_then(Value::as_str).map(PathBuf::from) else {
        return Err(CadError::new(
            Failure::new(FailureKind::InvalidSolid, "the job wrote no STL"),
            false,
            Some(worker_pid),
            CadErrorDetail { output, timings, violations: Vec::new() },
        ));
    };
    // The path must be inside this worker's own directory.
    if !stl.starts_with(root) || stl.components().any(|c| matches!(c, std::path::Component::ParentDir)) {
        return Err(CadError::runner(format!("the worker named a file outside its directory: {}", stl.display())));
    }
    let t_read = Instant::now();
    let mesh = mesh_io::read_untrusted_stl(&stl, c.max_output_mb << 20).map_err(|e| {
        CadError::new(
            Failure::new(FailureKind::InvalidSolid, format!("the STL could not be read: {e}")),
            false,
            Some(worker_pid),
            CadErrorDetail { output: output.clone(), timings, violations: Vec::new() },
        )
    })?;
    timings.read_ms = ms(t_read);
    timings.roundtrip_ms = ms(started);
    let brep_volume = answer.get("volume").and_then(Value::as_f64);
    let brep_bbox = answer.get("bbox").and_then(|b| {
        let pt = |i: usize| -> Option<[f64; 3]> {
            let a = b.get(i)?.as_array()?;
            Some([a.first()?.as_f64()?, a.get(1)?.as_f64()?, a.get(2)?.as_f64()?])
        };
        Some([pt(0)?, pt(1)?])
    });
    Ok(CadRun { mesh, brep_volume, brep_bbox, timings, output, worker_pid, job_pid })
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1000.0
}
