//! `export DIR --format usd`: a package as OpenUSD, for Isaac Sim / Isaac Lab and other
//! USD tools, through the PyPI `mujoco-usd-converter` (run in its own venv: it pins
//! MuJoCo 3.16 and brings its own OpenUSD build, so it cannot share a venv with MuJoCo
//! 3.17 or `usd-core`).
//!
//! The converter reads `scene.xml` with MuJoCo and writes an asset directory (an
//! interface layer `scenewright.usda` with payloaded geometry, materials and physics).
//! What it cannot express it drops with a warning — MuJoCo 3.16 / converter 0.8.0 on our
//! packages: cameras, lights, keyframes, the floor's checker texture. Those warnings are
//! returned as `dropped` and written to `export.json` beside the stage, with every file.
//!
//! The converter keeps MuJoCo's actuators as `MjcActuator` prims, which PhysX ignores: a
//! robot would hang limp in Isaac Sim. So each joint a position servo drives gets a USD
//! `PhysicsDriveAPI` (angular or linear) with the servo's stiffness and damping (per
//! degree for angular drives, as USD physics counts them), its force limit, and as target
//! the `home` keyframe's control: PhysX holds the arm at home, as MuJoCo does. The drives
//! are written into the physics layer by the converter's own OpenUSD (`DRIVES`), and
//! listed as `drives` in `export.json`.

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
    /// The joints given a PhysX drive, from their MuJoCo position servos.
    drives: Vec<serde_json::Value>,
    /// Every file written (export.json included), relative to `out_dir`.
    files: Vec<String>,
    seconds: f64,
}

/// Writes a `PhysicsDriveAPI` on each joint a MuJoCo position servo drives (argv: the
/// scene.xml, the physics layer); prints the drives as JSON. Run by the converter's venv.
const DRIVES: &str = r#"
import json, math, sys
import mujoco
from pxr import Usd, UsdPhysics

scene, physics = sys.argv[1], sys.argv[2]
m = mujoco.MjModel.from_xml_path(scene)
key = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_KEY, "home")
stage = Usd.Stage.Open(physics)
done = []
for prim in stage.Traverse():
    if prim.GetTypeName() != "MjcActuator":
        continue
    targets = prim.GetRelationship("mjc:target").GetTargets()
    joint = stage.GetPrimAtPath(targets[0]) if targets else None
    a = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_ACTUATOR, prim.GetName())
    if joint is None or not joint.IsValid() or a < 0:
        continue
    gain, bias = float(m.actuator_gainprm[a][0]), m.actuator_biasprm[a]
    # A position servo: force = kp * (ctrl - q) - kv * qdot.
    servo = int(m.actuator_biastype[a]) == int(mujoco.mjtBias.mjBIAS_AFFINE) and gain > 0
    if not servo or abs(bias[1] + gain) > 1e-9 * max(1.0, gain):
        continue
    angular, linear = joint.IsA(UsdPhysics.RevoluteJoint), joint.IsA(UsdPhysics.PrismaticJoint)
    if not (angular or linear):
        continue
    per = math.pi / 180.0 if angular else 1.0
    target = float(m.key_ctrl[key][a]) if key >= 0 else 0.0
    drive = UsdPhysics.DriveAPI.Apply(joint, "angular" if angular else "linear")
    drive.CreateTypeAttr("force")
    drive.CreateStiffnessAttr(gain * per)
    drive.CreateDampingAttr(-float(bias[2]) * per)
    drive.CreateTargetPositionAttr(target / per)
    entry = {"joint": joint.GetName(), "kind": "angular" if angular else "linear", "stiffness": gain * per,
             "damping": -float(bias[2]) * per, "target": target / per}
    if m.actuator_forcelimited[a]:
        drive.CreateMaxForceAttr(float(m.actuator_forcerange[a][1]))
        entry["max_force"] = float(m.actuator_forcerange[a][1])
    done.append(entry)
stage.GetRootLayer().Save()
print("DRIVES " + json.dumps(done))
"#;

/// The Python that has `mujoco_usd_converter`: SCENEWRIGHT_USD_PYTHON, else the venv at
/// SCENEWRIGHT_USD_VENV, else the checkout's `.cache/usd-venv` (both made by `scripts/setup.sh
/// --usd`). Not set up is a problem of the set-up, said in one line (exit 2).
fn converter_python() -> Result<OsString, Failure> {
    let missing = "USD export needs mujoco-usd-converter 0.8.0: run scripts/setup.sh --usd (SCENEWRIGHT_USD_VENV=DIR puts it outside the checkout), or set SCENEWRIGHT_USD_PYTHON to a Python that has it";
    if let Some(p) = std::env::var_os("SCENEWRIGHT_USD_PYTHON").filter(|p| !p.is_empty()) {
        return if Path::new(&p).is_file() {
            Ok(p)
        } else {
            Err(Failure::input(format!(
                "SCENEWRIGHT_USD_PYTHON is {}, which does not exist. {missing}",
                Path::new(&p).display()
            )))
        };
    }
    if let Some(v) = std::env::var_os("SCENEWRIGHT_USD_VENV").filter(|v| !v.is_empty()) {
        let py = Path::new(&v).join("bin/python");
        return if py.is_file() {
            Ok(py.into_os_string())
        } else {
            Err(Failure::input(format!(
                "SCENEWRIGHT_USD_VENV is {}, which holds no bin/python. {missing}",
                Path::new(&v).display()
            )))
        };
    }
    let exe = std::env::current_exe().map_err(|e| Failure::internal(e.to_string()))?;
    for dir in exe.ancestors().skip(1) {
        let py = dir.join(".cache/usd-venv/bin/python");
        if py.is_file() {
            return Ok(py.into_os_string());
        }
    }
    Err(Failure::input(missing))
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
    // PhysX drives for the joints MuJoCo's servos drive, at the home pose.
    let physics = stage_dir.join("Payload").join("Physics.usda");
    let drives = if physics.is_file() { add_drives(&python, &scene, &physics)? } else { Vec::new() };
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
        drives,
        files: Vec::new(),
        seconds: 0.0,
    };
    // The record lists every file, itself included.
    let mut files: Vec<String> = sw_pipeline::manifest::file_list(&stage_dir)
        .map_err(|e| Failure::internal(e.to_string()))?
        .into_iter()
        .map(|f| f.path)
        .collect();
    files.push("export.json".into());
    files.sort();
    done.files = files;
    done.seconds = (started.elapsed().as_secs_f64() * 1000.0).round() / 1000.0;
    let mut record = serde_json::to_string_pretty(&done).map_err(|e| Failure::internal(e.to_string()))?;
    record.push('\n');
    fs_err::write(stage_dir.join("export.json"), record).map_err(|e| Failure::input(e.to_string()))?;
    if out.exists() {
        fs_err::remove_dir(&out).map_err(|e| Failure::input(e.to_string()))?;
    }
    fs_err::rename(&stage_dir, &out).map_err(|e| Failure::input(e.to_string()))?;
    if a.json {
        print_json(&done);
    } else {
        print(&format!("usd      {}", done.stage.display()));
        for d in &done.dropped {
            print(&format!("dropped  {d}"));
        }
        if !done.drives.is_empty() {
            print(&format!("drives   {} joints driven to the home pose", done.drives.len()));
        }
    }
    Ok(0)
}

/// Adds the PhysX drives (see [`DRIVES`]); the joints driven.
fn add_drives(python: &OsString, scene: &Path, physics: &Path) -> Result<Vec<serde_json::Value>, Failure> {
    let out = Command::new(python)
        .args(["-c", DRIVES])
        .arg(scene)
        .arg(physics)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| Failure::internal(format!("cannot run the USD exporter's Python: {e}")))?;
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().find_map(|l| l.strip_prefix("DRIVES "));
    match (out.status.success(), line) {
        (true, Some(json)) => serde_json::from_str(json).map_err(|e| Failure::internal(format!("the drives: {e}"))),
        _ => {
            let err = String::from_utf8_lossy(&out.stderr);
            let last = err.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("no output").trim().to_string();
            Err(Failure::internal(format!("writing the joints' drives into the USD stage failed: {last}")))
        }
    }
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
        .map_err(|e| {
            Failure::input(format!(
                "cannot run the USD exporter's Python {} ({e}); run scripts/setup.sh --usd",
                PathBuf::from(python).display()
            ))
        })?;
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
