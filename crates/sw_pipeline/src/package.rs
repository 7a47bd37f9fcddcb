//! The package on disk: staged in a hidden sibling directory, renamed into place when
//! complete, removed if anything fails.

use std::path::{Path, PathBuf};

use fs_err as fs;
use sw_mjcf::{RobotInput, SceneFiles, SceneInput};
use sw_plan::{LaidOutScene, Report, ScenePlan, Timings, Verification};

use crate::PipelineError;
use crate::forge::Forged;

/// An output directory that cannot be used. Nothing is written when this is returned.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error("output directory '{0}' already exists and is not empty; choose a new path or remove it")]
    NotEmpty(PathBuf),
    #[error("output path '{0}' exists and is not a directory")]
    NotADirectory(PathBuf),
    #[error("cannot write the package to '{path}': {reason}")]
    Unwritable { path: PathBuf, reason: String },
    #[error("'{0}' is not a scene package (no scene.xml)")]
    NotAPackage(PathBuf),
}

fn unwritable(path: &Path, e: &std::io::Error) -> OutputError {
    OutputError::Unwritable { path: path.to_path_buf(), reason: e.kind().to_string() }
}

/// Staging directories of runs in progress, so that an interrupted process can remove
/// them ([`discard_staged_packages`]).
static STAGED: std::sync::Mutex<Vec<PathBuf>> = std::sync::Mutex::new(Vec::new());

/// Removes the staging directories of every run in progress. For signal handlers: after
/// this, no half-written package is left on disk.
pub fn discard_staged_packages() {
    let dirs = match STAGED.lock() {
        Ok(mut d) => std::mem::take(&mut *d),
        Err(poisoned) => std::mem::take(&mut *poisoned.into_inner()),
    };
    for d in dirs {
        let _ = std::fs::remove_dir_all(d);
    }
}

fn forget_staged(path: &Path) {
    if let Ok(mut d) = STAGED.lock() {
        d.retain(|p| p != path);
    }
}

/// Checks that `dest` can receive a package, without creating anything.
pub(crate) fn check_destination(dest: &Path) -> Result<(), OutputError> {
    check_not_taken(dest)?;
    probe_parent(dest)
}

/// `dest` is absent or an empty directory.
fn check_not_taken(dest: &Path) -> Result<(), OutputError> {
    if dest.exists() {
        if !dest.is_dir() {
            return Err(OutputError::NotADirectory(dest.to_path_buf()));
        }
        let mut entries = std::fs::read_dir(dest).map_err(|e| unwritable(dest, &e))?;
        if entries.next().is_some() {
            return Err(OutputError::NotEmpty(dest.to_path_buf()));
        }
    }
    Ok(())
}

/// The nearest existing ancestor of `dest` is a directory we can write in.
fn probe_parent(dest: &Path) -> Result<(), OutputError> {
    // The nearest existing ancestor must be a directory we can write in: probe it with a
    // directory that is removed at once, so that nothing is left behind either way.
    let mut a = dest.parent();
    while let Some(p) = a {
        let p = if p.as_os_str().is_empty() { Path::new(".") } else { p };
        if p.exists() {
            if !p.is_dir() {
                let reason = format!("'{}' is not a directory", p.display());
                return Err(OutputError::Unwritable { path: dest.to_path_buf(), reason });
            }
            // Unique per call: several runs in one process (threads, a server) probe at once.
            static PROBES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
            let k = PROBES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let probe = p.join(format!(".scenewright-probe-{}-{k}", std::process::id()));
            std::fs::create_dir(&probe).map_err(|e| unwritable(dest, &e))?;
            let _ = std::fs::remove_dir(&probe);
            break;
        }
        a = p.parent();
    }
    Ok(())
}

/// A package being written.
#[derive(Debug)]
pub(crate) struct Staging {
    tmp: PathBuf,
    dest: PathBuf,
    committed: bool,
}

impl Staging {
    pub fn create(dest: &Path) -> Result<Self, OutputError> {
        // No second probe of the parent (callers checked it before any work): creating the
        // staging directory below fails the same way if it has become unwritable.
        check_not_taken(dest)?;
        let name =
            dest.file_name().and_then(|n| n.to_str()).filter(|n| !n.is_empty() && *n != "." && *n != "..").ok_or_else(
                || OutputError::Unwritable { path: dest.to_path_buf(), reason: "not a directory name".into() },
            )?;
        let parent = match dest.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(|e| unwritable(&parent, &e))?;
        let stamp = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.subsec_nanos());
        let tmp = parent.join(format!(".{name}.partial-{}-{stamp}", std::process::id()));
        std::fs::create_dir(&tmp).map_err(|e| unwritable(dest, &e))?;
        if let Ok(mut d) = STAGED.lock() {
            d.push(tmp.clone());
        }
        Ok(Self { tmp, dest: dest.to_path_buf(), committed: false })
    }

    pub fn path(&self) -> &Path {
        &self.tmp
    }

    fn write(&self, rel: &str, bytes: &[u8]) -> Result<(), OutputError> {
        let path = self.tmp.join(rel);
        fs::write(&path, bytes)
            .map_err(|e| OutputError::Unwritable { path: self.dest.join(rel), reason: e.to_string() })
    }

    fn json<T: serde::Serialize>(&self, rel: &str, value: &T) -> Result<(), OutputError> {
        let mut text = serde_json::to_string_pretty(value)
            .map_err(|e| OutputError::Unwritable { path: self.dest.join(rel), reason: e.to_string() })?;
        text.push('\n');
        self.write(rel, text.as_bytes())
    }

    /// Writes the MJCF, meshes, plan and layout (again, after a repair round).
    pub fn write_scene(&self, files: &SceneFiles, plan: &ScenePlan, layout: &LaidOutScene) -> Result<(), OutputError> {
        let assets = self.tmp.join("assets");
        if assets.exists() {
            std::fs::remove_dir_all(&assets).map_err(|e| unwritable(&assets, &e))?;
        }
        std::fs::create_dir(&assets).map_err(|e| unwritable(&assets, &e))?;
        for m in &files.meshes {
            self.write(&format!("assets/{}", m.file_name), &m.bytes)?;
        }
        // The robots' own meshes and textures, copied (never linked: the package must not
        // share files with the cache it came from).
        for f in &files.robot_files {
            let to = assets.join(&f.dest);
            if let Some(dir) = to.parent() {
                std::fs::create_dir_all(dir).map_err(|e| unwritable(dir, &e))?;
            }
            std::fs::copy(&f.source, &to).map_err(|e| OutputError::Unwritable {
                path: self.dest.join("assets").join(&f.dest),
                reason: format!("copying {} ({}): {e}", f.source.display(), f.element),
            })?;
        }
        self.write("scene.xml", files.scene_xml.as_bytes())?;
        self.write("scene_only.xml", files.scene_only_xml.as_bytes())?;
        self.json("plan.json", plan)?;
        self.json("layout.json", layout)
    }

    pub fn write_report(&self, report: &Report, timings: &Timings) -> Result<(), OutputError> {
        self.json("report.json", report)?;
        self.json("timings.json", timings)
    }

    /// Moves the finished package into place.
    pub fn commit(mut self) -> Result<PathBuf, OutputError> {
        if self.dest.exists() {
            // Checked empty at the start; replaced by the finished package.
            std::fs::remove_dir(&self.dest).map_err(|e| unwritable(&self.dest, &e))?;
        }
        std::fs::rename(&self.tmp, &self.dest).map_err(|e| unwritable(&self.dest, &e))?;
        forget_staged(&self.tmp);
        self.committed = true;
        Ok(self.dest.clone())
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.tmp);
            forget_staged(&self.tmp);
        }
    }
}

/// L4: MJCF and meshes for the layout, with the robots merged. A robot model that cannot
/// be read or merged, or a file it references that is missing, is bad input (it names the
/// file and the element); anything else is an internal error.
pub(crate) fn bridge(prompt: &str, layout: &LaidOutScene, forged: &Forged) -> Result<SceneFiles, PipelineError> {
    let assets: Vec<&sw_geom::Asset> = layout
        .objects
        .iter()
        .filter_map(|o| forged.objects.iter().find(|f| f.name == o.name).map(|f| &f.asset))
        .collect();
    let mut sources: Vec<(String, sw_mjcf::RobotSource)> = Vec::new();
    for r in &layout.robots {
        let def = sw_robots::find(&r.model)
            .ok_or_else(|| PipelineError::Input(format!("robot model '{}' is not registered", r.model)))?;
        let model = def.model().map_err(|e| PipelineError::Input(format!("robot {}: {e}", def.name)))?;
        sources.push((r.name.clone(), model));
    }
    let robots: Vec<RobotInput<'_>> =
        sources.iter().map(|(name, model)| RobotInput { name: name.as_str(), model }).collect();
    let files = sw_mjcf::write_scene(&SceneInput { prompt, layout, assets, robots }).map_err(|e| match e {
        sw_mjcf::BridgeError::Merge(m) => PipelineError::Input(format!("robot model: {m}")),
        other => PipelineError::Internal(other.to_string()),
    })?;
    for f in &files.robot_files {
        if !f.source.is_file() {
            return Err(PipelineError::Input(format!(
                "{}: the file it references is missing: {}",
                f.element,
                f.source.display()
            )));
        }
    }
    Ok(files)
}

/// Re-verifies a package directory in MuJoCo.
pub fn validate_dir(dir: &Path) -> Result<Verification, OutputError> {
    let scene = dir.join("scene.xml");
    if !scene.is_file() {
        return Err(OutputError::NotAPackage(dir.to_path_buf()));
    }
    let layout = std::fs::read_to_string(dir.join("layout.json"))
        .ok()
        .and_then(|t| serde_json::from_str::<LaidOutScene>(&t).ok());
    let robots = layout.as_ref().map(|l| l.robots.iter().map(|r| r.name.clone()).collect()).unwrap_or_default();
    // What the package's labelled anomalies explain is expected, as when it was generated.
    let expected_bodies = layout.as_ref().map(crate::report::anomaly_bodies).unwrap_or_default();
    Ok(sw_sim::verify_file(&scene, &sw_sim::VerifyOptions { robots, expected_bodies, ..Default::default() }))
}
