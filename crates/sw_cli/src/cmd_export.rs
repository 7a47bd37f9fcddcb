//! `export DIR --format usd`: a package as OpenUSD, for Isaac Sim / Isaac Lab and other
//! USD tools, through the PyPI `mujoco-usd-converter` (run in its own venv: it pins
//! MuJoCo 3.16 and brings its own OpenUSD build, so it cannot share a venv with MuJoCo
//! 3.17 or `usd-core`).
//!
//! The converter reads `scene.xml` with MuJoCo and writes an asset directory (an
//! interface layer `scenewright.usda` with payloaded geometry, materials and physics).
//! What it cannot express it drops with a warning — MuJoCo 3.16 / converter 0.8.0 on our
//! packages: cameras, lights, keyframes (the `home` pose: robot joints stand at their
//! zero position in USD), the floor's checker texture. Those warnings are returned as
//! `dropped` and written to `export.json` beside the stage.

use std::ffi::OsString;
use std::io::Read as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde::Serialize;

use crate::Failure;
use crate::output::{print, print_json};

/// The converter run is stopped after this long.
const TIMEOUT: Duration = Duration::from_secs(600);

#[derive(Debug, clap::Args)]
pub(crate) struct ExportArgs {
    /// The package directory (holding scene.xml).
    dir: PathBuf,
    /// The format to write: `usd`.
    #[arg(long)]
    format: String,
    /// The directory to write into (new or empty; default: DIR_usd beside the package).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print one JSON document.
    #[arg(long)]
    json: bool,
}

#[derive(Debug, Serialize)]
struct Exported {
    format: &'static str,
    /// The stage to open: `<out>/scenewright.usda`.
    stage: PathBuf,
    out_dir: PathBuf,
    converter: String,
    /// What the converter could not express (its warnings, one line each).
    dropped: Vec<String>,
    files: Vec<String>,
    seconds: f64,
}

/// The Python that has `mujoco_usd_converter`: SCENEWRIGHT_USD_PYTHON, else the
/// checkout's `.cache/usd-venv` (set up by `scripts/setup.sh --usd`).
fn converter_python() -> Result<OsString, Failure> {
    if let Some(p) = std::env::var_os("SCENEWRIGHT_USD_PYTHON") {
        return Ok(p);
    }
    let exe = std::env::current_exe().map_err(|e| Failure::internal(e.to_string()))?;
    for dir in exe.ancestors().skip(1) {
        let py = dir.join(".cache/usd-venv/bin/python");
        if py.is_file() {
            return Ok(py.into_os_string());
        }
    }
    Err(Failure::internal(
        "USD export needs mujoco-usd-converter 0.8.0: run scripts/setup.sh --usd, or set SCENEWRIGHT_USD_PYTHON to a Python that has it",
    ))
}

pub(crate) fn run(a: ExportArgs) -> Result<u8, Failure> {
    if a.format.trim().to_lowercase() != "usd" {
        return Err(Failure::input(format!("unknown export format '{}' (usd)", a.format)));
    }
    let scene = a.dir.join("scene.xml");
    if !scene.is_file() {
        return Err(Failure::input(format!("'{}' is not a scene package (no scene.xml)", a.dir.display())));
    }
    let out = match &a.out {
        Some(o) => o.clone(),
        None => {
            let name = a.dir.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "scene".into());
            a.dir.with_file_name(format!("{name}_usd"))
        }
    };
    check_out(&out)?;
    let python = converter_python()?;
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs_err::create_dir_all(&parent).map_err(|e| Failure::input(e.to_string()))?;
    let staging = tempfile::Builder::new()
        .prefix(".scenewright-usd-")
        .tempdir_in(&parent)
        .map_err(|e| Failure::input(format!("cannot write in '{}': {e}", parent.display())))?;
    let started = Instant::now();
    let stage_dir = staging.path().join("stage");
    let (code, log) = run_converter(&python, &scene, &stage_dir)?;
    let stage = stage_dir.join("scenewright.usda");
    if code != Some(0) || !stage.is_file() {
        let last = log.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("no output").trim().to_string();
        return Err(Failure::internal(format!("mujoco-usd-converter failed on {}: {last}", scene.display())));
    }
    let dropped: Vec<String> = log
        .lines()
        .filter(|l| l.starts_with("[Warning]"))
        .map(|l| l.rsplit("] ").next().unwrap_or(l).trim().to_string())
        .collect();
    let converter = log
        .lines()
        .find_map(|l| l.split_once("] Version: ").map(|(_, v)| format!("mujoco-usd-converter {}", v.trim())))
        .unwrap_or_else(|| "mujoco-usd-converter".into());
    let mut done = Exported {
        format: "usd",
        stage: out.join("scenewright.usda"),
        out_dir: out.clone(),
        converter,
        dropped,
        files: Vec::new(),
        seconds: 0.0,
    };
    done.seconds = (started.elapsed().as_secs_f64() * 1000.0).round() / 1000.0;
    let mut record = serde_json::to_string_pretty(&done).map_err(|e| Failure::internal(e.to_string()))?;
    record.push('\n');
    fs_err::write(stage_dir.join("export.json"), record).map_err(|e| Failure::input(e.to_string()))?;
    if out.exists() {
        fs_err::remove_dir(&out).map_err(|e| Failure::input(e.to_string()))?;
    }
    fs_err::rename(&stage_dir, &out).map_err(|e| Failure::input(e.to_string()))?;
    done.files = sw_pipeline::manifest::file_list(&out)
        .map_err(|e| Failure::internal(e.to_string()))?
        .into_iter()
        .map(|f| f.path)
        .collect();
    if a.json {
        print_json(&done);
    } else {
        print(&format!("usd      {}", done.stage.display()));
        for d in &done.dropped {
            print(&format!("dropped  {d}"));
        }
    }
    Ok(0)
}

/// `out` must not exist or be an empty directory.
fn check_out(out: &Path) -> Result<(), Failure> {
    if out.exists() {
        if !out.is_dir() {
            return Err(Failure::input(format!("'{}' exists and is not a directory", out.display())));
        }
        let empty = fs_err::read_dir(out).map_err(|e| Failure::input(e.to_string()))?.next().is_none();
        if !empty {
            return Err(Failure::input(format!(
                "output directory '{}' already exists and is not empty; choose a new path or remove it",
                out.display()
            )));
        }
    }
    Ok(())
}

/// Runs the converter; its exit code (None when stopped) and its combined output.
fn run_converter(python: &OsString, scene: &Path, out: &Path) -> Result<(Option<i32>, String), Failure> {
    let mut child = Command::new(python)
        .args(["-m", "mujoco_usd_converter", "--verbose"])
        .arg(scene)
        .arg(out)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Failure::internal(format!("cannot run {}: {e}", PathBuf::from(python).display())))?;
    let mut pipes = Vec::new();
    for pipe in [
        child.stdout.take().map(|p| Box::new(p) as Box<dyn std::io::Read + Send>),
        child.stderr.take().map(|p| Box::new(p) as Box<dyn std::io::Read + Send>),
    ]
    .into_iter()
    .flatten()
    {
        pipes.push(std::thread::spawn(move || {
            let mut text = String::new();
            let mut pipe = pipe;
            let _ = pipe.read_to_string(&mut text);
            text
        }));
    }
    let started = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break s.code(),
            Ok(None) if started.elapsed() > TIMEOUT => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(20)),
            Err(e) => return Err(Failure::internal(e.to_string())),
        }
    };
    let log: String = pipes.into_iter().filter_map(|h| h.join().ok()).collect::<Vec<_>>().join("\n");
    Ok((status, log))
}
