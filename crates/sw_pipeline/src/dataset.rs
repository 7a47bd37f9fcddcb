//! A dataset directory: many packages of a few prompts, and `manifest.jsonl` listing
//! every finished one — safe to kill at any moment and to resume.
//!
//! ```text
//! DIR/dataset.json     what the dataset is (prompts, options); written first, atomically
//! DIR/manifest.jsonl   one line per finished scene, appended when its package is in place
//! DIR/scenes/<id>/     the packages (`<id>` = PPPP-KKKKKK: prompt index, slot)
//! DIR/.work/           packages being made (removed on every start)
//! DIR/.lock            held (flock) by the process working on the dataset
//! ```
//!
//! A package is made in `.work/`, checked for duplicates, renamed into `scenes/` (atomic)
//! and only then appended to the manifest in one write. A kill at any point leaves either
//! nothing, a half-made package in `.work/` (removed on resume), a package in `scenes/`
//! without its line (its line is made again from the package on resume: nothing is redone
//! or lost), or a line cut short (dropped; its package is then adopted as before). So the
//! manifest never lists a half-written scene. A directory that is not empty and holds no
//! `dataset.json` of ours is refused, as is a dataset of other prompts or options.

use std::collections::{BTreeMap, BTreeSet};
use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use serde::{Deserialize, Serialize};

use crate::manifest::{EntryContext, ManifestEntry, Variation, entry_from_package};

/// The marker of a dataset directory (in `dataset.json`).
pub const DATASET_FORMAT: &str = "scenewright-dataset";
/// The layout version of a dataset directory.
pub const DATASET_VERSION: u32 = 1;

/// What a dataset is: its prompts and options. Two runs on one directory must agree on
/// everything but `count`, which may grow (the dataset is extended).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DatasetSpec {
    pub format: String,
    pub version: u32,
    pub prompts: Vec<String>,
    /// Scenes per prompt.
    pub count: u32,
    /// The first seed tried for each prompt.
    pub seed: u64,
    /// `native` or `mjx`.
    pub physics: String,
    /// Robots drawn per scene (`--robots`); absent: the prompt's robots.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub robots: Option<Vec<String>>,
    /// Injected anomalies (`--anomaly`), as given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub anomaly: Option<sw_plan::AnomalyRequest>,
    /// The dataset's id on the service's job queue, when it is made there (`--database`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub queue_id: Option<String>,
}

impl DatasetSpec {
    pub fn new(prompts: Vec<String>, count: u32) -> Self {
        Self {
            format: DATASET_FORMAT.into(),
            version: DATASET_VERSION,
            prompts,
            count,
            seed: 0,
            physics: "native".into(),
            robots: None,
            anomaly: None,
            queue_id: None,
        }
    }

    /// The kinds of variation every scene of this dataset has (see [`Variation`]).
    pub fn variation(&self, robot: Option<&str>) -> Variation {
        let mut kinds: Vec<String> = ["layout", "asset_parameters", "colours"].map(String::from).to_vec();
        if self.robots.is_some() {
            kinds.push("robot".into());
        }
        if self.anomaly.is_some() {
            kinds.push("anomalies".into());
        }
        Variation { kinds, robot: robot.map(str::to_string) }
    }

    /// The id of slot `k` of prompt `p`.
    pub fn scene_id(p: usize, k: u32) -> String {
        format!("{p:04}-{k:06}")
    }

    /// The (prompt, slot) of an id made by [`DatasetSpec::scene_id`].
    pub fn parse_id(id: &str) -> Option<(usize, u32)> {
        let (p, k) = id.split_once('-')?;
        if p.len() != 4 || k.len() != 6 {
            return None;
        }
        Some((p.parse().ok()?, k.parse().ok()?))
    }

    /// The robot drawn for a scene of prompt `p` at `seed` from `robots` (deterministic).
    pub fn draw_robot(&self, p: usize, seed: u64) -> Option<String> {
        let list = self.robots.as_ref()?;
        let mut rng = sw_geom::Rng::derive(seed, &format!("dataset-robot#{p}"));
        rng.pick(list).cloned()
    }

    /// The pipeline's options for a scene of this dataset at `seed` with `robot` drawn.
    pub fn scene_options(&self, robot: Option<&str>, seed: u64) -> crate::Options {
        crate::Options {
            seed,
            robots: robot.map(|r| if r == "none" { Vec::new() } else { vec![r.to_string()] }),
            anomaly: self.anomaly.clone(),
            physics: crate::PhysicsTarget::parse(&self.physics).unwrap_or_default(),
            ..crate::Options::default()
        }
    }

    /// The `t`-th seed a slot tries on the job queue: slot `k` of `count` takes
    /// `seed + k + t·count`, so slots never share a seed and a slot's retry after a lost
    /// worker tries the same seeds again.
    pub fn queue_seed(&self, k: u32, t: u32) -> u64 {
        self.seed.saturating_add(u64::from(k)).saturating_add(u64::from(t) * u64::from(self.count))
    }

    fn differences(&self, other: &DatasetSpec) -> Vec<&'static str> {
        let mut d = Vec::new();
        if self.prompts != other.prompts {
            d.push("prompts");
        }
        if self.seed != other.seed {
            d.push("seed");
        }
        if self.physics != other.physics {
            d.push("physics");
        }
        if self.robots != other.robots {
            d.push("robots");
        }
        if self.anomaly != other.anomaly {
            d.push("anomaly");
        }
        d
    }
}

/// One scene slot of a dataset made on the job queue: what its job's options carry (the
/// job's prompt is the slot's prompt; the spec's prompt list is left out).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SlotJob {
    /// The dataset's queue id.
    pub dataset: String,
    /// The scene id, `PPPP-KKKKKK`.
    pub slot: String,
    pub prompt_index: u32,
    pub k: u32,
    pub spec: DatasetSpec,
}

impl SlotJob {
    /// The key of a job's options that holds a slot.
    pub const KEY: &'static str = "dataset_slot";

    /// The slot a job's options hold: `None` for other jobs, an error for a damaged one.
    pub fn of(options: &serde_json::Value) -> Option<Result<SlotJob, String>> {
        let v = options.get(Self::KEY)?;
        Some(serde_json::from_value(v.clone()).map_err(|e| format!("a dataset job with unreadable options: {e}")))
    }
}

/// Seeds a scene slot tries before it is given up (failed verification or duplicates).
pub const TRIES: u32 = 25;

/// Why an attempt did not give a scene, in a few words (summaries count these).
pub fn failure_reason(failures: &[String]) -> String {
    let f = failures.join("; ");
    if f.contains("rejected") {
        "did not compile".into()
    } else if f.contains("contact") {
        "contact deeper than 1 mm at t = 0".into()
    } else if f.contains("moved") {
        "moved in the settle".into()
    } else if f.contains("unstable") {
        "numerically unstable".into()
    } else if f.is_empty() {
        "not verified".into()
    } else {
        f.chars().take(80).collect()
    }
}

/// Why a dataset directory cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum DatasetError {
    #[error(
        "'{0}' is not a scenewright dataset (it is not empty and holds no dataset.json of ours); choose a new or empty directory"
    )]
    Foreign(PathBuf),
    #[error("'{dir}' holds a dataset with other {what}; use another directory (or the same options to resume)")]
    Mismatch { dir: PathBuf, what: String },
    #[error("another scenewright process is working on the dataset in '{0}'")]
    Busy(PathBuf),
    #[error("cannot write the dataset in '{path}': {reason}")]
    Unwritable { path: PathBuf, reason: String },
}

fn unwritable(path: &Path, e: impl std::fmt::Display) -> DatasetError {
    DatasetError::Unwritable { path: path.to_path_buf(), reason: e.to_string() }
}

/// What resuming found and did.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Resumed {
    /// Scenes listed in the manifest.
    pub listed: usize,
    /// Packages in `scenes/` whose line was missing, listed again.
    pub adopted: usize,
    /// Half-made packages removed from `.work/` and hidden staging directories.
    pub discarded_partial: usize,
    /// A manifest line cut short by a kill, dropped.
    pub dropped_torn_line: bool,
    /// Listed scenes whose package was gone (they will be made again).
    pub missing_packages: usize,
    /// Packages that duplicated a listed scene or were not verified, removed.
    pub removed_packages: usize,
}

/// A dataset directory opened for work (its lock held until dropped).
#[derive(Debug)]
pub struct DatasetDir {
    root: PathBuf,
    spec: DatasetSpec,
    entries: Vec<ManifestEntry>,
    manifest: Mutex<File>,
    _lock: File,
}

impl DatasetDir {
    /// Opens `root` for `spec`: creates the dataset in a new or empty directory, or
    /// resumes the one there (see the module docs).
    pub fn open(root: &Path, spec: &DatasetSpec) -> Result<(Self, Resumed), DatasetError> {
        let spec_path = root.join("dataset.json");
        let existing = if root.exists() {
            if !root.is_dir() {
                return Err(DatasetError::Foreign(root.to_path_buf()));
            }
            let empty = std::fs::read_dir(root).map_err(|e| unwritable(root, e))?.next().is_none();
            if empty {
                None
            } else {
                Some(read_spec(&spec_path).ok_or_else(|| DatasetError::Foreign(root.to_path_buf()))?)
            }
        } else {
            None
        };
        let mut spec = spec.clone();
        if let Some(old) = &existing {
            let diff = old.differences(&spec);
            if !diff.is_empty() {
                return Err(DatasetError::Mismatch { dir: root.to_path_buf(), what: diff.join(", ") });
            }
            spec.count = spec.count.max(old.count);
            spec.queue_id = spec.queue_id.or_else(|| old.queue_id.clone());
        }
        std::fs::create_dir_all(root.join("scenes")).map_err(|e| unwritable(root, e))?;
        let lock = OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(root.join(".lock"))
            .map_err(|e| unwritable(root, e))?;
        match lock.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => return Err(DatasetError::Busy(root.to_path_buf())),
            Err(TryLockError::Error(e)) => return Err(unwritable(root, e)),
        }
        if existing.as_ref() != Some(&spec) {
            write_atomically(&spec_path, &pretty(&spec)).map_err(|e| unwritable(&spec_path, e))?;
        }
        let mut resumed = Resumed::default();
        let entries = reconcile(root, &spec, &mut resumed)?;
        let manifest = OpenOptions::new()
            .create(true)
            .append(true)
            .open(root.join("manifest.jsonl"))
            .map_err(|e| unwritable(root, e))?;
        resumed.listed = entries.len();
        Ok((Self { root: root.to_path_buf(), spec, entries, manifest: Mutex::new(manifest), _lock: lock }, resumed))
    }

    pub fn root(&self) -> &Path {
        &self.root
    }

    /// The spec as stored (its count is the largest asked for).
    pub fn spec(&self) -> &DatasetSpec {
        &self.spec
    }

    /// The scenes listed when the dataset was opened.
    pub fn entries(&self) -> &[ManifestEntry] {
        &self.entries
    }

    /// Slots not yet listed, in order: (prompt index, slot).
    pub fn pending(&self) -> Vec<(usize, u32)> {
        let done: BTreeSet<&str> = self.entries.iter().map(|e| e.id.as_str()).collect();
        let mut out = Vec::new();
        for p in 0..self.spec.prompts.len() {
            for k in 0..self.spec.count {
                if !done.contains(DatasetSpec::scene_id(p, k).as_str()) {
                    out.push((p, k));
                }
            }
        }
        out
    }

    /// A fresh directory in `.work/` for making one package (it must not exist yet).
    pub fn work_dir(&self, id: &str, seed: u64) -> Result<PathBuf, DatasetError> {
        let work = self.root.join(".work");
        std::fs::create_dir_all(&work).map_err(|e| unwritable(&work, e))?;
        Ok(work.join(format!("{id}-seed{seed}")))
    }

    /// Moves a finished package into `scenes/<id>` and appends its manifest line.
    pub fn commit(&self, made: &Path, id: &str, ctx_robot: Option<&str>) -> Result<ManifestEntry, DatasetError> {
        let (p, _) = DatasetSpec::parse_id(id).ok_or_else(|| unwritable(made, "not a scene id"))?;
        let rel = format!("scenes/{id}");
        let dest = self.root.join(&rel);
        std::fs::rename(made, &dest).map_err(|e| unwritable(&dest, e))?;
        let ctx = EntryContext {
            id,
            prompt_index: p as u32,
            physics: &self.spec.physics,
            variation: self.spec.variation(ctx_robot),
        };
        let entry = entry_from_package(&dest, &rel, ctx).map_err(|e| unwritable(&dest, e))?;
        self.append(&entry)?;
        Ok(entry)
    }

    /// Appends one line in one write (a kill cannot leave half of it but at the very end,
    /// where resuming drops it).
    fn append(&self, entry: &ManifestEntry) -> Result<(), DatasetError> {
        let mut line = serde_json::to_string(entry).map_err(|e| unwritable(&self.root, e))?;
        line.push('\n');
        let mut f = match self.manifest.lock() {
            Ok(f) => f,
            Err(poisoned) => poisoned.into_inner(),
        };
        f.write_all(line.as_bytes()).map_err(|e| unwritable(&self.root.join("manifest.jsonl"), e))
    }

    /// Flushes the manifest to the disk (at the end of a run) and removes `.work/` when
    /// nothing is left in it.
    pub fn sync(&self) -> Result<(), DatasetError> {
        let _ = std::fs::remove_dir(self.root.join(".work"));
        let f = match self.manifest.lock() {
            Ok(f) => f,
            Err(poisoned) => poisoned.into_inner(),
        };
        f.sync_all().map_err(|e| unwritable(&self.root.join("manifest.jsonl"), e))
    }
}

fn pretty<T: Serialize>(v: &T) -> String {
    let mut s = serde_json::to_string_pretty(v).unwrap_or_default();
    s.push('\n');
    s
}

fn read_spec(path: &Path) -> Option<DatasetSpec> {
    let text = std::fs::read_to_string(path).ok()?;
    let spec: DatasetSpec = serde_json::from_str(&text).ok()?;
    (spec.format == DATASET_FORMAT && spec.version == DATASET_VERSION).then_some(spec)
}

/// Writes `path` through a sibling temporary file renamed over it.
fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let tmp = path.with_extension(format!("tmp-{}", std::process::id()));
    {
        let mut f = File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.sync_all()?;
    }
    std::fs::rename(&tmp, path)
}

/// Reads the manifest, repairs what a kill can leave, and returns the listed scenes.
fn reconcile(root: &Path, spec: &DatasetSpec, r: &mut Resumed) -> Result<Vec<ManifestEntry>, DatasetError> {
    // Half-made packages.
    let work = root.join(".work");
    if work.exists() {
        r.discarded_partial += std::fs::read_dir(&work).map(|d| d.count()).unwrap_or(0);
        std::fs::remove_dir_all(&work).map_err(|e| unwritable(&work, e))?;
    }
    let scenes = root.join("scenes");
    for e in std::fs::read_dir(&scenes).map_err(|e| unwritable(&scenes, e))?.flatten() {
        if e.file_name().to_string_lossy().starts_with('.') {
            std::fs::remove_dir_all(e.path()).map_err(|err| unwritable(&e.path(), err))?;
            r.discarded_partial += 1;
        }
    }
    // The manifest: whole lines only; a line that does not parse is made again from its
    // package (or dropped when its package is gone).
    let path = root.join("manifest.jsonl");
    let text = match std::fs::read(&path) {
        Ok(b) => String::from_utf8_lossy(&b).into_owned(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => String::new(),
        Err(e) => return Err(unwritable(&path, e)),
    };
    let mut rewrite = false;
    let body = match text.rfind('\n') {
        Some(i) if i + 1 < text.len() => {
            r.dropped_torn_line = true;
            rewrite = true;
            &text[..=i]
        }
        None if !text.is_empty() => {
            r.dropped_torn_line = true;
            rewrite = true;
            ""
        }
        _ => text.as_str(),
    };
    let mut by_id: BTreeMap<String, ManifestEntry> = BTreeMap::new();
    for line in body.lines().filter(|l| !l.trim().is_empty()) {
        match serde_json::from_str::<ManifestEntry>(line) {
            Ok(e) if root.join(&e.dir).join("scene.xml").is_file() => {
                by_id.insert(e.id.clone(), e);
            }
            Ok(_) => {
                r.missing_packages += 1;
                rewrite = true;
            }
            Err(_) => rewrite = true,
        }
    }
    // Packages in place whose line is missing: adopt them (or remove a duplicate).
    let mut fingerprints: BTreeSet<String> = by_id.values().map(|e| e.fingerprint.clone()).collect();
    let mut names: Vec<String> = std::fs::read_dir(&scenes)
        .map_err(|e| unwritable(&scenes, e))?
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    for id in names {
        if by_id.contains_key(&id) {
            continue;
        }
        let dir = scenes.join(&id);
        let slot = DatasetSpec::parse_id(&id).filter(|(p, k)| *p < spec.prompts.len() && *k < spec.count);
        let entry = slot.and_then(|(p, _)| {
            let robot = robot_of(&dir, spec);
            let ctx = EntryContext {
                id: &id,
                prompt_index: p as u32,
                physics: &spec.physics,
                variation: spec.variation(robot.as_deref()),
            };
            entry_from_package(&dir, &format!("scenes/{id}"), ctx).ok()
        });
        match entry {
            Some(e) if e.verification.status == "verified" && fingerprints.insert(e.fingerprint.clone()) => {
                by_id.insert(id, e);
                r.adopted += 1;
                rewrite = true;
            }
            _ => {
                std::fs::remove_dir_all(&dir).map_err(|e| unwritable(&dir, e))?;
                r.removed_packages += 1;
            }
        }
    }
    let entries: Vec<ManifestEntry> = by_id.into_values().collect();
    if rewrite {
        let mut text = String::new();
        for e in &entries {
            text.push_str(&serde_json::to_string(e).map_err(|err| unwritable(&path, err))?);
            text.push('\n');
        }
        write_atomically(&path, &text).map_err(|e| unwritable(&path, e))?;
    }
    Ok(entries)
}

/// The robot drawn for an adopted package: the model of its first robot, `none` without.
fn robot_of(dir: &Path, spec: &DatasetSpec) -> Option<String> {
    spec.robots.as_ref()?;
    let text = std::fs::read_to_string(dir.join("layout.json")).ok()?;
    let layout: serde_json::Value = serde_json::from_str(&text).ok()?;
    Some(layout["robots"][0]["model"].as_str().unwrap_or("none").to_string())
}
