//! Where the CAD worker comes from: its Python sources (compiled into this binary and
//! written out next to the workers, so an installed binary needs no checkout), the
//! Python interpreter with CadQuery (`scripts/setup.sh --cad` makes `.cache/cad-venv`),
//! and the runner's limits.

use std::path::{Path, PathBuf};
use std::time::Duration;

/// The worker's sources, relative to the directory they are written into.
const SOURCES: &[(&str, &str)] = &[
    ("cad_worker.py", include_str!("../../../../python/cad_worker.py")),
    ("scenewright_cad/__init__.py", include_str!("../../../../python/scenewright_cad/__init__.py")),
    ("scenewright_cad/policy.py", include_str!("../../../../python/scenewright_cad/policy.py")),
    ("scenewright_cad/sandbox.py", include_str!("../../../../python/scenewright_cad/sandbox.py")),
    ("scenewright_cad/worker.py", include_str!("../../../../python/scenewright_cad/worker.py")),
];

/// Writes the worker's sources into `dir` and returns the entry script's path.
pub(crate) fn write_sources(dir: &Path) -> std::io::Result<PathBuf> {
    for (rel, text) in SOURCES {
        let path = dir.join(rel);
        if let Some(parent) = path.parent() {
            fs_err::create_dir_all(parent)?;
        }
        fs_err::write(&path, text)?;
    }
    Ok(dir.join("cad_worker.py"))
}

/// How the runner runs code.
#[derive(Debug, Clone)]
pub struct RunnerConfig {
    /// The Python interpreter that has CadQuery.
    pub python: PathBuf,
    /// Worker processes (each runs one job at a time).
    pub workers: usize,
    /// Wall-clock limit of one job (the CPU limit is the same).
    pub timeout: Duration,
    /// Address space a job may add to the warm worker image, MiB.
    pub memory_mb: u64,
    /// Largest file a job may write (its STL), MiB.
    pub max_output_mb: u64,
    /// Triangles a job's mesh may have.
    pub max_triangles: usize,
    /// How long a worker may take to import CadQuery and report ready.
    pub startup_timeout: Duration,
    /// Refuse to run code when a sandbox layer is missing (Landlock, seccomp, the
    /// self-test). Off only for experiments on kernels without Landlock.
    pub strict_sandbox: bool,
    /// Relative chord deflection of the STL export (of the part's diagonal).
    pub linear_deflection: f64,
    /// Angular deflection of the STL export, radians.
    pub angular_deflection: f64,
}

impl Default for RunnerConfig {
    fn default() -> Self {
        Self {
            python: default_python(),
            workers: 2,
            timeout: Duration::from_secs(10),
            memory_mb: 2048,
            max_output_mb: 64,
            max_triangles: 200_000,
            startup_timeout: Duration::from_secs(90),
            strict_sandbox: true,
            linear_deflection: 5e-4,
            angular_deflection: 0.15,
        }
    }
}

impl RunnerConfig {
    /// The defaults, with `SCENEWRIGHT_CAD_PYTHON`, `SCENEWRIGHT_CAD_WORKERS` and
    /// `SCENEWRIGHT_CAD_TIMEOUT_S` applied.
    pub fn from_env() -> Self {
        let mut c = Self::default();
        if let Some(n) = std::env::var("SCENEWRIGHT_CAD_WORKERS").ok().and_then(|v| v.trim().parse::<usize>().ok()) {
            c.workers = n.clamp(1, 64);
        }
        if let Some(s) = std::env::var("SCENEWRIGHT_CAD_TIMEOUT_S").ok().and_then(|v| v.trim().parse::<f64>().ok())
            && s.is_finite()
            && s > 0.0
        {
            c.timeout = Duration::from_secs_f64(s.min(600.0));
        }
        c
    }
}

/// `SCENEWRIGHT_CAD_PYTHON`, else the venv `scripts/setup.sh --cad` makes in the checkout.
pub fn default_python() -> PathBuf {
    if let Some(p) = std::env::var_os("SCENEWRIGHT_CAD_PYTHON").filter(|p| !p.is_empty()) {
        return PathBuf::from(p);
    }
    checkout_cache().join("cad-venv/bin/python")
}

/// The checkout's `.cache` directory: beside the sources this binary was built from,
/// or above the running executable (`target/<profile>/…`).
pub fn checkout_cache() -> PathBuf {
    let built = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.cache");
    if built.is_dir() {
        return built;
    }
    if let Ok(exe) = std::env::current_exe() {
        for dir in exe.ancestors().skip(1) {
            let candidate = dir.join(".cache");
            if candidate.join("cad-venv").is_dir() || candidate.join("minilm").is_dir() {
                return candidate;
            }
        }
    }
    built
}
