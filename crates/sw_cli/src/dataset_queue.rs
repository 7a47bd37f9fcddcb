//! `dataset --database URL`: the same dataset made by the service's job queue. This
//! process is the dataset's leader: it enqueues one job per missing scene slot (as the
//! queue's cap allows), and every `scenewright worker` (or `serve`) on the same database
//! and blob store (S3 with the SCENEWRIGHT_S3_* settings, else `--data DIR/blobs`) makes
//! scenes (`sw_server::dataset_jobs`). The leader downloads each finished slot's package
//! into the dataset directory and appends its manifest line, exactly as the local mode
//! does — so the directory, the manifest and resuming are the same, and the manifest is
//! assembled from the store. The leader can be killed and started again at any time
//! (workers go on with the queued jobs); a slot whose job failed gets a new job when the
//! leader starts again.
//!
//! The jobs belong to the user `scenewright-dataset` (made when missing, with no usable
//! password). Workers run at most `--per-user` jobs of one user at once, so give them a
//! `--per-user` as large as their runners.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

use sw_pipeline::dataset::{DatasetDir, DatasetSpec, SlotJob};
use sw_store::{BlobStore, JobKind, JobState, NewJob, QueueLimits, Store, StoreError};

use crate::Failure;
use crate::cmd_dataset::{ACTIVE, Progress, Summary, dataset_failure, report, stop_flag};

/// The user that owns dataset jobs.
const USER: &str = "scenewright-dataset";
/// A dataset job's time limit: TRIES scenes.
const JOB_TIMEOUT_MS: i64 = 600_000;

fn internal(e: impl std::fmt::Display) -> Failure {
    Failure::internal(e.to_string())
}

pub(crate) fn run(
    out: &Path,
    mut spec: DatasetSpec,
    database: &str,
    data: Option<&Path>,
    json: bool,
) -> Result<u8, Failure> {
    // The dataset's queue id: the directory's, else a new one.
    let existing = std::fs::read_to_string(out.join("dataset.json"))
        .ok()
        .and_then(|t| serde_json::from_str::<DatasetSpec>(&t).ok())
        .and_then(|s| s.queue_id);
    spec.queue_id = Some(existing.unwrap_or_else(sw_store::new_id));
    let (dir, resumed) = DatasetDir::open(out, &spec).map_err(dataset_failure)?;
    let spec = dir.spec().clone();
    let id = spec.queue_id.clone().unwrap_or_default();
    let rt = tokio::runtime::Builder::new_multi_thread().enable_all().build().map_err(internal)?;
    let data = data.map_or_else(|| std::path::PathBuf::from("scenewright-data"), Path::to_path_buf);
    let (store, blobs) =
        rt.block_on(sw_server::open_data(&data, Some(database))).map_err(|e| Failure::input(e.to_string()))?;
    // The same dataset in the database (its prompts and options; the count may grow).
    let identity = DatasetSpec { count: 0, queue_id: None, ..spec.clone() };
    let text = serde_json::to_string(&identity).map_err(internal)?;
    let stored = rt.block_on(store.open_dataset(&id, &text)).map_err(internal)?;
    if stored != text {
        return Err(Failure::input(format!("the database holds dataset {id} with other prompts or options")));
    }
    // The service account: never one somebody registered over the API (its name is
    // reserved there; an older login account of that name is refused).
    let user = rt.block_on(store.service_account(USER)).map_err(|e| match e {
        StoreError::Conflict(m) => Failure::input(m),
        e => internal(e),
    })?;
    ACTIVE.store(true, Ordering::SeqCst);
    let result = lead(&rt, &store, &*blobs, &dir, &user.id);
    ACTIVE.store(false, Ordering::SeqCst);
    let (made, gave_up, seconds) = result?;
    let wanted = spec.prompts.len() * spec.count as usize;
    let listed = dir.entries().len() + made;
    let stop = stop_flag().load(Ordering::SeqCst);
    let summary = Summary {
        out_dir: out.to_path_buf(),
        manifest: out.join("manifest.jsonl"),
        scenes_wanted: wanted,
        scenes_listed: listed,
        made,
        resumed,
        seconds: (seconds * 1000.0).round() / 1000.0,
        scenes_per_s: if seconds > 0.0 { ((made as f64 / seconds) * 100.0).round() / 100.0 } else { 0.0 },
        jobs: 0,
        attempts: made + gave_up.len(),
        valid_share: if made + gave_up.len() > 0 { made as f64 / (made + gave_up.len()) as f64 } else { 1.0 },
        failures: gave_up.values().fold(BTreeMap::new(), |mut m, why| {
            *m.entry(why.clone()).or_insert(0) += 1;
            m
        }),
        gave_up: gave_up.keys().cloned().collect(),
        interrupted: stop && listed < wanted,
    };
    report(&summary, json);
    Ok(if summary.interrupted {
        130
    } else if listed < wanted {
        1
    } else {
        0
    })
}

/// The leader's loop: enqueue, wait, download; returns (scenes listed now, slots given
/// up with why, seconds).
fn lead(
    rt: &tokio::runtime::Runtime,
    store: &Store,
    blobs: &dyn BlobStore,
    dir: &DatasetDir,
    user_id: &str,
) -> Result<(usize, BTreeMap<String, String>, f64), Failure> {
    let spec = dir.spec();
    let id = spec.queue_id.clone().unwrap_or_default();
    let wanted = spec.prompts.len() * spec.count as usize;
    let progress = Progress::new(wanted, dir.entries().len());
    let mut pending: BTreeMap<String, (usize, u32)> =
        dir.pending().into_iter().map(|(p, k)| (DatasetSpec::scene_id(p, k), (p, k))).collect();
    let mut fingerprints: BTreeSet<String> = dir.entries().iter().map(|e| e.fingerprint.clone()).collect();
    let mut gave_up: BTreeMap<String, String> = BTreeMap::new();
    let stop = stop_flag();
    let started = Instant::now();
    let mut made = 0usize;
    let mut first_round = true;
    let slot_spec = Arc::new(DatasetSpec { prompts: Vec::new(), ..spec.clone() });
    while !pending.is_empty() && !stop.load(Ordering::SeqCst) {
        let jobs: BTreeMap<String, sw_store::Job> =
            rt.block_on(store.dataset_slots(&id)).map_err(internal)?.into_iter().map(|s| (s.slot, s.job)).collect();
        let mut queue_full = false;
        for (slot, &(p, k)) in pending.clone().iter() {
            if stop.load(Ordering::SeqCst) {
                break;
            }
            let job = jobs.get(slot);
            let ended_badly = job.is_some_and(|j| matches!(j.state, JobState::Failed | JobState::Cancelled));
            if job.is_none() || (ended_badly && first_round) {
                if queue_full {
                    continue;
                }
                let slot_job = SlotJob {
                    dataset: id.clone(),
                    slot: slot.clone(),
                    prompt_index: p as u32,
                    k,
                    spec: (*slot_spec).clone(),
                };
                let new = NewJob {
                    user_id: user_id.to_string(),
                    kind: JobKind::Generate,
                    prompt: spec.prompts[p].clone(),
                    seed: spec.queue_seed(k, 0),
                    options: serde_json::json!({ SlotJob::KEY: slot_job }),
                    parent_scene_id: None,
                    timeout_ms: JOB_TIMEOUT_MS,
                    max_attempts: 3,
                };
                match rt.block_on(store.enqueue_dataset_slot(&id, slot, &new, QueueLimits::default())) {
                    Ok(_) => {}
                    Err(StoreError::QueueFull { .. }) => queue_full = true,
                    Err(e) => return Err(internal(e)),
                }
                continue;
            }
            let Some(job) = job else { continue };
            match job.state {
                JobState::Succeeded => {
                    let scene = job.scene_id.clone().ok_or_else(|| internal(format!("job {} has no scene", job.id)))?;
                    match fetch(rt, store, blobs, dir, slot, p, &scene, &mut fingerprints)? {
                        Fetched::Listed => {
                            made += 1;
                            progress.made();
                        }
                        Fetched::Duplicate => {
                            gave_up.insert(slot.clone(), "duplicate of an earlier scene".into());
                        }
                    }
                    pending.remove(slot);
                }
                JobState::Failed | JobState::Cancelled => {
                    let why = job.error.clone().unwrap_or_else(|| "failed".into());
                    progress.note(&format!("{slot}: {why}"));
                    gave_up.insert(slot.clone(), why.split(" (").next().unwrap_or(&why).to_string());
                    pending.remove(slot);
                }
                JobState::Queued | JobState::Running => {}
            }
        }
        first_round = false;
        if !pending.is_empty() {
            std::thread::sleep(Duration::from_millis(300));
        }
    }
    progress.finish();
    dir.sync().map_err(internal)?;
    Ok((made, gave_up, started.elapsed().as_secs_f64()))
}

enum Fetched {
    Listed,
    /// The scene equals one listed already (possible only when scenes were listed by
    /// another mode or dataset run): not listed.
    Duplicate,
}

/// Downloads a finished slot's package from the blob store and lists it.
#[allow(clippy::too_many_arguments)]
fn fetch(
    rt: &tokio::runtime::Runtime,
    store: &Store,
    blobs: &dyn BlobStore,
    dir: &DatasetDir,
    slot: &str,
    p: usize,
    scene: &str,
    fingerprints: &mut BTreeSet<String>,
) -> Result<Fetched, Failure> {
    let files = rt
        .block_on(store.scene_files(scene))
        .map_err(internal)?
        .ok_or_else(|| internal(format!("scene {scene} of slot {slot} is missing")))?;
    let work = dir.work_dir(slot, 0).map_err(internal)?;
    if work.exists() {
        std::fs::remove_dir_all(&work).map_err(internal)?;
    }
    for f in &files {
        sw_store::check_key(f).map_err(internal)?;
        let bytes = blobs
            .get(&format!("scenes/{scene}/{f}"))
            .map_err(internal)?
            .ok_or_else(|| internal(format!("scene {scene} lost its file {f}")))?;
        let path = work.join(f);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent).map_err(|e| internal(format!("{}: {e}", parent.display())))?;
        }
        std::fs::write(&path, bytes).map_err(|e| internal(format!("{}: {e}", path.display())))?;
    }
    let fp = sw_pipeline::manifest::fingerprint(&work).map_err(internal)?;
    if !fingerprints.insert(fp) {
        let _ = std::fs::remove_dir_all(&work);
        return Ok(Fetched::Duplicate);
    }
    let seed = std::fs::read_to_string(work.join("report.json"))
        .ok()
        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
        .and_then(|r| r["seed"].as_u64())
        .unwrap_or(0);
    let robot = dir.spec().draw_robot(p, seed);
    dir.commit(&work, slot, robot.as_deref()).map_err(internal)?;
    Ok(Fetched::Listed)
}
