//! A demonstrations directory: a LeRobot v3.0 dataset plus what made each episode —
//! safe to kill at any moment and to resume.
//!
//! ```text
//! DIR/demos.json                 what the dataset is (prompts, task, fps, cameras, size); written first
//! DIR/.lock                      held (flock) by the process working on it
//! DIR/attempts.jsonl             one line per attempt, solved or not (the summary's counts)
//! DIR/scenes/episode_NNNNNN/     the episode's scene (scene.xml: its physics step, its
//!                                randomisation; `home` = its start), plan, layout, task.json,
//!                                episode.json (its record) — renamed into place last: the commit
//! DIR/data/…, DIR/videos/…       the episode's frames, written before its scene directory
//! DIR/meta/…                     derived from the records; rewritten on every start and end
//! DIR/.work/                     attempts being made (removed on every start)
//! ```
//!
//! An episode counts once its scene directory is in place. On resume, episodes are read
//! back in index order up to the first gap; data and video files of any later index (a kill
//! between writing them and the commit) are removed, and the metadata is written again.

use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use serde::{Deserialize, Serialize};
use sw_lerobot::EpisodeRecord;

/// The marker of a demonstrations directory.
pub(crate) const DEMOS_FORMAT: &str = "scenewright-demos";
pub(crate) const DEMOS_VERSION: u32 = 1;

/// What a demonstrations dataset is. Two runs on one directory agree on everything but
/// `episodes`, which may grow.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct DemosSpec {
    pub format: String,
    pub version: u32,
    pub prompts: Vec<String>,
    /// The task given with `--task` (else each prompt's own).
    pub task: Option<String>,
    /// Episodes per prompt.
    pub episodes: u32,
    pub seed: u64,
    pub fps: u32,
    pub cameras: Vec<String>,
    pub image_size: [u32; 2],
    /// Colours, masses, friction, lighting, camera pose vary per episode.
    pub randomise: bool,
    pub output: String,
}

impl DemosSpec {
    fn differences(&self, o: &DemosSpec) -> Vec<&'static str> {
        let mut d = Vec::new();
        let pairs: [(bool, &'static str); 8] = [
            (self.prompts != o.prompts, "prompts"),
            (self.task != o.task, "task"),
            (self.seed != o.seed, "seed"),
            (self.fps != o.fps, "fps"),
            (self.cameras != o.cameras, "cameras"),
            (self.image_size != o.image_size, "image size"),
            (self.randomise != o.randomise, "randomisation"),
            (self.output != o.output, "format"),
        ];
        for (differs, what) in pairs {
            if differs {
                d.push(what);
            }
        }
        d
    }
}

/// What an episode's `episode.json` holds: the LeRobot record and how it was made.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct EpisodeFile {
    pub record: EpisodeRecord,
    pub prompt_index: usize,
    pub seed: u64,
    pub robot: String,
    pub robot_model: String,
    pub family: String,
    pub fps: u32,
    pub substeps: u32,
    pub timestep: f64,
    pub action_names: Vec<String>,
    pub state_names: Vec<String>,
    pub env_names: Vec<String>,
    pub cameras: Vec<(String, String)>,
    pub randomisation: sw_expert::Randomisation,
    pub verdicts: Vec<sw_task::GoalVerdict>,
    pub planning: sw_expert::Stats,
    pub bytes: u64,
}

/// One attempt, solved or not (a line of `attempts.jsonl`).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub(crate) struct AttemptLine {
    pub prompt_index: usize,
    pub seed: u64,
    /// `solved` or the class of failure.
    pub outcome: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub family: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub episode: Option<u64>,
    pub seconds: f64,
}

#[derive(Debug, thiserror::Error)]
pub(crate) enum DemosError {
    #[error(
        "'{0}' is not a scenewright demonstrations dataset (it is not empty and holds no demos.json of ours); choose a new or empty directory"
    )]
    Foreign(PathBuf),
    #[error("'{dir}' holds demonstrations with other {what}; use another directory (or the same options to resume)")]
    Mismatch { dir: PathBuf, what: String },
    #[error("another scenewright process is working on the dataset in '{0}'")]
    Busy(PathBuf),
    #[error("cannot write the dataset in '{path}': {reason}")]
    Unwritable { path: PathBuf, reason: String },
}

fn unwritable(path: &Path, e: impl std::fmt::Display) -> DemosError {
    DemosError::Unwritable { path: path.to_path_buf(), reason: e.to_string() }
}

/// What resuming found.
#[derive(Debug, Clone, Default, Serialize)]
pub(crate) struct Resumed {
    pub episodes: usize,
    pub removed_partial: usize,
    pub dropped_torn_line: bool,
}

/// A demonstrations directory opened for work (its lock held until dropped).
#[derive(Debug)]
pub(crate) struct DemosDir {
    root: PathBuf,
    spec: DemosSpec,
    pub episodes: Mutex<Vec<EpisodeFile>>,
    pub attempts_before: Vec<AttemptLine>,
    attempts: Mutex<File>,
    _lock: File,
}

impl DemosDir {
    /// Refuses `root` without touching it: a file, a foreign directory, or demonstrations
    /// of other options.
    pub fn check(root: &Path, spec: &DemosSpec) -> Result<(), DemosError> {
        if let Some(old) = Self::existing(root)? {
            let diff = old.differences(spec);
            if !diff.is_empty() {
                return Err(DemosError::Mismatch { dir: root.to_path_buf(), what: diff.join(", ") });
            }
        }
        Ok(())
    }

    fn existing(root: &Path) -> Result<Option<DemosSpec>, DemosError> {
        let spec_path = root.join("demos.json");
        if !root.exists() {
            return Ok(None);
        }
        if !root.is_dir() {
            return Err(DemosError::Foreign(root.to_path_buf()));
        }
        let empty = std::fs::read_dir(root).map_err(|e| unwritable(root, e))?.next().is_none();
        if empty {
            return Ok(None);
        }
        let text = std::fs::read_to_string(&spec_path).ok();
        let old: Option<DemosSpec> = text.and_then(|t| serde_json::from_str(&t).ok());
        old.filter(|s| s.format == DEMOS_FORMAT && s.version == DEMOS_VERSION)
            .map(Some)
            .ok_or_else(|| DemosError::Foreign(root.to_path_buf()))
    }

    pub fn open(root: &Path, spec: &DemosSpec) -> Result<(Self, Resumed), DemosError> {
        let spec_path = root.join("demos.json");
        let existing = Self::existing(root)?;
        let mut spec = spec.clone();
        if let Some(old) = &existing {
            let diff = old.differences(&spec);
            if !diff.is_empty() {
                return Err(DemosError::Mismatch { dir: root.to_path_buf(), what: diff.join(", ") });
            }
            spec.episodes = spec.episodes.max(old.episodes);
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
            Err(TryLockError::WouldBlock) => return Err(DemosError::Busy(root.to_path_buf())),
            Err(TryLockError::Error(e)) => return Err(unwritable(root, e)),
        }
        if existing.as_ref() != Some(&spec) {
            sw_lerobot::write_atomically(&spec_path, &pretty(&spec)).map_err(|e| unwritable(&spec_path, e))?;
        }
        let mut resumed = Resumed::default();
        let episodes = reconcile(root, &mut resumed)?;
        resumed.episodes = episodes.len();
        let (attempts_before, torn) = read_attempts(&root.join("attempts.jsonl"))?;
        resumed.dropped_torn_line = torn;
        if torn {
            let mut text = String::new();
            for a in &attempts_before {
                text.push_str(&serde_json::to_string(a).unwrap_or_default());
                text.push('\n');
            }
            sw_lerobot::write_atomically(&root.join("attempts.jsonl"), &text).map_err(|e| unwritable(root, e))?;
        }
        let attempts = OpenOptions::new()
            .create(true)
            .append(true)
            .open(root.join("attempts.jsonl"))
            .map_err(|e| unwritable(root, e))?;
        Ok((
            Self {
                root: root.to_path_buf(),
                spec,
                episodes: Mutex::new(episodes),
                attempts_before,
                attempts: Mutex::new(attempts),
                _lock: lock,
            },
            resumed,
        ))
    }

    pub fn root(&self) -> &Path {
        &self.root
    }

    pub fn spec(&self) -> &DemosSpec {
        &self.spec
    }

    /// A fresh directory in `.work/` for one attempt.
    pub fn work_dir(&self, prompt: usize, seed: u64) -> Result<PathBuf, DemosError> {
        let work = self.root.join(".work");
        std::fs::create_dir_all(&work).map_err(|e| unwritable(&work, e))?;
        let dir = work.join(format!("p{prompt:04}-seed{seed}"));
        if dir.exists() {
            std::fs::remove_dir_all(&dir).map_err(|e| unwritable(&dir, e))?;
        }
        Ok(dir)
    }

    /// Appends one attempt line in one write.
    pub fn log_attempt(&self, a: &AttemptLine) -> Result<(), DemosError> {
        let mut line = serde_json::to_string(a).map_err(|e| unwritable(&self.root, e))?;
        line.push('\n');
        let mut f = crate::cmd_dataset::lock(&self.attempts);
        f.write_all(line.as_bytes()).map_err(|e| unwritable(&self.root.join("attempts.jsonl"), e))
    }

    /// Writes the dataset's metadata from the committed episodes.
    pub fn write_meta(&self, info: &sw_lerobot::DatasetInfo) -> Result<(), DemosError> {
        let eps = crate::cmd_dataset::lock(&self.episodes);
        let records: Vec<EpisodeRecord> = eps.iter().map(|e| e.record.clone()).collect();
        drop(eps);
        sw_lerobot::write_meta(&self.root, info, &records).map_err(|e| unwritable(&self.root.join("meta"), e))
    }

    /// Removes `.work/` (at the end of a run) and flushes the attempts log.
    pub fn sync(&self) -> Result<(), DemosError> {
        let _ = std::fs::remove_dir_all(self.root.join(".work"));
        let f = crate::cmd_dataset::lock(&self.attempts);
        f.sync_all().map_err(|e| unwritable(&self.root.join("attempts.jsonl"), e))
    }
}

/// The episode directory of index `i`.
pub(crate) fn episode_dir(root: &Path, i: u64) -> PathBuf {
    root.join(format!("scenes/episode_{i:06}"))
}

fn pretty<T: Serialize>(v: &T) -> String {
    let mut s = serde_json::to_string_pretty(v).unwrap_or_default();
    s.push('\n');
    s
}

fn read_attempts(path: &Path) -> Result<(Vec<AttemptLine>, bool), DemosError> {
    let text = match std::fs::read(path) {
        Ok(b) => String::from_utf8_lossy(&b).into_owned(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => String::new(),
        Err(e) => return Err(unwritable(path, e)),
    };
    let torn = !text.is_empty() && !text.ends_with('\n');
    let body = if torn { text.rfind('\n').map_or("", |i| &text[..=i]) } else { text.as_str() };
    Ok((body.lines().filter_map(|l| serde_json::from_str(l).ok()).collect(), torn))
}

/// Reads the committed episodes (contiguous from 0) and removes everything a kill left.
fn reconcile(root: &Path, r: &mut Resumed) -> Result<Vec<EpisodeFile>, DemosError> {
    let work = root.join(".work");
    if work.exists() {
        r.removed_partial += std::fs::read_dir(&work).map(|d| d.count()).unwrap_or(0);
        std::fs::remove_dir_all(&work).map_err(|e| unwritable(&work, e))?;
    }
    let mut episodes = Vec::new();
    loop {
        let dir = episode_dir(root, episodes.len() as u64);
        let ep: Option<EpisodeFile> = std::fs::read_to_string(dir.join("episode.json"))
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok())
            .filter(|e: &EpisodeFile| {
                e.record.episode_index == episodes.len() as u64
                    && sw_lerobot::data_path(root, e.record.episode_index).is_file()
            });
        match ep {
            Some(e) => episodes.push(e),
            None => break,
        }
    }
    let n = episodes.len() as u64;
    // Anything of a later index: scene directories, data and video files.
    let scenes = root.join("scenes");
    for e in std::fs::read_dir(&scenes).map_err(|e| unwritable(&scenes, e))?.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let idx = name.strip_prefix("episode_").and_then(|s| s.parse::<u64>().ok());
        if idx.is_none_or(|i| i >= n) {
            std::fs::remove_dir_all(e.path()).map_err(|err| unwritable(&e.path(), err))?;
            r.removed_partial += 1;
        }
    }
    for top in ["data", "videos"] {
        let mut files = Vec::new();
        collect_files(&root.join(top), &mut files);
        for f in files {
            let keep = index_of_file(&f).is_some_and(|i| i < n);
            if !keep {
                std::fs::remove_file(&f).map_err(|e| unwritable(&f, e))?;
                r.removed_partial += 1;
            }
        }
    }
    Ok(episodes)
}

fn collect_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            collect_files(&p, out);
        } else {
            out.push(p);
        }
    }
}

/// The episode index of `…/chunk-CCC/file-FFF.ext` (`None` for anything else, e.g. a
/// partial file).
fn index_of_file(p: &Path) -> Option<u64> {
    let file = p.file_name()?.to_str()?;
    let chunk = p.parent()?.file_name()?.to_str()?;
    let f: u64 = file.strip_prefix("file-")?.split('.').next()?.parse().ok()?;
    let ext_ok = file.ends_with(".parquet") || file.ends_with(".mp4");
    let c: u64 = chunk.strip_prefix("chunk-")?.parse().ok()?;
    (ext_ok && file.matches('.').count() == 1).then_some(c * sw_lerobot::CHUNK_SIZE + f)
}
