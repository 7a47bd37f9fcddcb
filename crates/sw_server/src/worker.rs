//! Job runners: claim a job, keep its lease alive, run the pipeline on a blocking thread
//! while forwarding its events, store the package in the blob store, and complete the job
//! only if the claim is still ours. A recovery loop puts jobs of lost runners back.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use serde_json::{Value, json};
use sw_llm::LlmStage;
use sw_pipeline::{EditReader, Event, Options, PipelineError};
use sw_store::{BlobStore, Claim, JobKind, NewScene, Telemetry, new_id};
use tracing::Instrument;

use crate::scratch::{self, ProcessScratch};
use crate::{AppState, StartError};

/// How runners behave.
#[derive(Debug, Clone)]
pub struct RunnerConfig {
    /// A claim's lease, ms; renewed every third of it.
    pub lease_ms: i64,
    /// A job running longer than this fails, ms.
    pub job_timeout_ms: i64,
    /// Claims of one job before it fails (its runners kept getting lost).
    pub max_attempts: i64,
    /// How often an idle runner looks for work from other processes, ms.
    pub poll_ms: u64,
    /// Scratch space for packages being made (default: `scenewright-work` in the system's
    /// temp directory). Processes sharing it each work in their own subdirectory; see
    /// [`crate::scratch`].
    pub work_dir: Option<PathBuf>,
    /// Model endpoints: an edit the offline grammar cannot read goes to the edit stage's
    /// model, as with `scenewright edit` (none: the grammar only).
    pub llm: Option<sw_llm::LlmConfig>,
}

impl Default for RunnerConfig {
    fn default() -> Self {
        Self { lease_ms: 30_000, job_timeout_ms: 600_000, max_attempts: 3, poll_ms: 250, work_dir: None, llm: None }
    }
}

impl RunnerConfig {
    /// The directory holding every process's scratch.
    pub fn work_root(&self) -> PathBuf {
        self.work_dir.clone().unwrap_or_else(|| std::env::temp_dir().join("scenewright-work"))
    }

    /// The edit stage's model from the SCENEWRIGHT_LLM_* environment (as `scenewright
    /// edit`); unusable settings are logged and leave the offline grammar only.
    pub fn with_llm_from_env(self) -> Self {
        let llm = match sw_llm::LlmConfig::from_env() {
            Ok(c) => Some(c),
            Err(e) => {
                tracing::warn!(error = %e, "the LLM settings are unusable; edits use the offline grammar only");
                None
            }
        };
        Self { llm, ..self }
    }
}

/// Runs `n` job runners and the recovery loop until `shutdown` resolves. A runner then
/// stops the job it holds — its pipeline ends at its next cancellation check — and gives
/// it back to the queue, so the next process to run jobs makes it (a process that dies
/// instead loses its lease, and the job runs again elsewhere after it). Before they start,
/// the scratch left in the work root by processes that died is removed.
pub async fn run_workers(
    state: AppState,
    n: usize,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> Result<(), StartError> {
    let run = start_workers(state, n, shutdown)?;
    let _ = run.await;
    Ok(())
}

/// [`run_workers`] with its start (the scratch cleaned and claimed) done now and the rest
/// in a task.
pub(crate) fn start_workers(
    state: AppState,
    n: usize,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> Result<tokio::task::JoinHandle<()>, StartError> {
    let process = format!("{}-{}", std::process::id(), &new_id()[..8]);
    let root = state.runner.work_root();
    let removed = scratch::sweep(&root)?;
    if !removed.is_empty() {
        let dirs: Vec<String> = removed.iter().map(|d| d.display().to_string()).collect();
        tracing::info!(removed = ?dirs, "removed the scratch of processes that are gone");
    }
    // Only a process that runs jobs needs scratch of its own.
    let scratch = if n > 0 { Some(ProcessScratch::claim_unique(&root, &process)?) } else { None };
    tracing::info!(runners = n, process = %process, "job runners started");
    Ok(tokio::spawn(async move {
        let work = scratch.as_ref().map(|s| s.dir().to_path_buf()).unwrap_or_else(|| root.clone());
        run_loops(state, n, &process, work, shutdown).await;
        // Every runner is done: this process's scratch goes (dropped after the loops).
        drop(scratch);
    }))
}

async fn run_loops(
    state: AppState,
    n: usize,
    process: &str,
    work: PathBuf,
    shutdown: impl Future<Output = ()> + Send + 'static,
) {
    let stop = Arc::new(AtomicBool::new(false));
    let wake = state.wake.clone();
    let mut tasks = Vec::new();
    for i in 0..n {
        let (state, stop, work) = (state.clone(), stop.clone(), work.clone());
        let name = format!("{process}-{i}");
        tasks.push(tokio::spawn(runner(state, name, work, stop)));
    }
    let recovery = {
        let (state, stop) = (state.clone(), stop.clone());
        tokio::spawn(async move {
            while !stop.load(Ordering::Relaxed) {
                match state.store.recover().await {
                    Ok(r) => {
                        for id in r.requeued.iter().chain(&r.failed) {
                            let _ = state.events.send(id.clone());
                            state.wake.notify_one();
                        }
                        if !r.requeued.is_empty() || !r.failed.is_empty() {
                            tracing::warn!(requeued = ?r.requeued, failed = ?r.failed, "recovered jobs of lost runners");
                        }
                    }
                    Err(e) => tracing::error!(error = %e, "recovery failed"),
                }
                tokio::time::sleep(Duration::from_millis(1000)).await;
            }
        })
    };
    shutdown.await;
    stop.store(true, Ordering::Relaxed);
    tracing::info!("job runners stopping: the jobs they hold go back to the queue");
    for _ in 0..n {
        wake.notify_one();
    }
    wake.notify_waiters();
    for t in tasks {
        let _ = t.await;
    }
    let _ = recovery.await;
}

async fn runner(state: AppState, name: String, work: PathBuf, stop: Arc<AtomicBool>) {
    while !stop.load(Ordering::Relaxed) {
        match state.store.claim(&name, state.runner.lease_ms, state.limits).await {
            Ok(Some(claim)) => {
                let span = tracing::info_span!("job", job = %claim.job.id, attempt = claim.attempt, worker = %name);
                run_job(&state, claim, &work, &stop).instrument(span).await;
            }
            Ok(None) => {
                let _ = tokio::time::timeout(Duration::from_millis(state.runner.poll_ms), state.wake.notified()).await;
            }
            Err(e) => {
                tracing::error!(error = %e, "claiming a job failed");
                tokio::time::sleep(Duration::from_millis(1000)).await;
            }
        }
    }
}

/// Appends an event to a job's stream and wakes its WebSocket listeners.
async fn emit(state: &AppState, job_id: &str, body: Value) {
    if let Err(e) = state.store.append_event(job_id, &body).await {
        tracing::error!(error = %e, "storing an event failed");
    }
    let _ = state.events.send(job_id.to_string());
}

/// What the pipeline produced for a job.
struct Made {
    report: sw_plan::Report,
    timings: sw_plan::Timings,
    dir: PathBuf,
    edit: Option<Value>,
}

async fn run_job(state: &AppState, claim: Claim, work: &Path, stopping: &Arc<AtomicBool>) {
    let job = claim.job.clone();
    tracing::info!(kind = job.kind.as_str(), "job started");
    emit(state, &job.id, json!({"event": "started", "attempt": claim.attempt})).await;

    // Keep the lease alive; notice when the claim is lost (cancelled, timed out, taken
    // over) or the process is stopping: either sets the pipeline's cancel flag, and the
    // pipeline stops at its next check (between stages, and inside the layout's and the
    // verification's loops).
    let lost = Arc::new(AtomicBool::new(false));
    let heartbeat = {
        let (store, claim, lost, stopping) = (state.store.clone(), claim.clone(), lost.clone(), stopping.clone());
        let lease = state.runner.lease_ms;
        let beat = Duration::from_millis((lease / 3).max(10) as u64);
        tokio::spawn(
            async move {
                let mut last = tokio::time::Instant::now();
                loop {
                    // Looked at often: a cancelled job's runner learns of it within the
                    // check interval, not a third of a lease later.
                    tokio::time::sleep(CHECK_INTERVAL.min(beat)).await;
                    if stopping.load(Ordering::Relaxed) {
                        lost.store(true, Ordering::Relaxed);
                        break;
                    }
                    let renew = last.elapsed() >= beat;
                    let still = if renew {
                        last = tokio::time::Instant::now();
                        store.heartbeat(&claim, lease).await
                    } else {
                        store.still_running(&claim).await
                    };
                    match still {
                        Ok(true) => {}
                        Ok(false) => {
                            lost.store(true, Ordering::Relaxed);
                            break;
                        }
                        Err(e) => tracing::warn!(error = %e, "heartbeat failed"),
                    }
                }
            }
            .in_current_span(),
        )
    };

    // Forward the pipeline's events as they come.
    let (tx, mut rx) = tokio::sync::mpsc::unbounded_channel::<Value>();
    let forwarder = {
        let (state, claim) = (state.clone(), claim.clone());
        tokio::spawn(
            async move {
                while let Some(ev) = rx.recv().await {
                    if ev["event"] == "stage_started"
                        && let Some(stage) = ev["stage"].as_str()
                    {
                        let _ = state.store.set_stage(&claim, stage).await;
                    }
                    emit(&state, &claim.job.id, ev).await;
                }
            }
            .in_current_span(),
        )
    };

    let result = run_pipeline(state, &claim, work, tx, lost.clone()).await;
    let _ = forwarder.await;
    heartbeat.abort();

    if stopping.load(Ordering::Relaxed) {
        // The process is stopping: a job its pipeline did not finish runs again in the next
        // one (a finished one is stored below, as usual).
        if result.is_err() {
            match state.store.release(&claim, "the server stopped while it ran; it runs again").await {
                Ok(true) => {
                    tracing::info!("job given back to the queue");
                    let _ = state.events.send(job.id.clone());
                }
                Ok(false) => {}
                Err(e) => tracing::warn!(error = %e, "giving the job back failed; it runs again after its lease"),
            }
            return;
        }
    }

    match result {
        Err(message) => {
            // The user reads it: it names files, never where the server keeps them.
            let message = crate::error::scrub_paths(&message);
            if claim_still_ours(state, &claim, &lost).await {
                match state.store.fail(&claim, &message).await {
                    Ok(true) => {
                        tracing::warn!(error = %message, "job failed");
                        let _ = state.events.send(job.id.clone());
                    }
                    Ok(false) => {}
                    Err(e) => tracing::error!(error = %e, "recording a failure failed"),
                }
            }
        }
        Ok((made, _tmp)) => {
            if let Err(e) = finish(state, &claim, made).await {
                tracing::error!(error = %e, "storing the package failed");
                let why = crate::error::scrub_paths(&format!("storing the package failed: {e}"));
                let _ = state.store.fail(&claim, &why).await;
                let _ = state.events.send(job.id.clone());
            }
        }
    }
}

async fn claim_still_ours(state: &AppState, claim: &Claim, lost: &AtomicBool) -> bool {
    if lost.load(Ordering::Relaxed) {
        return false;
    }
    matches!(state.store.job(&claim.job.id).await, Ok(Some(j)) if j.state == sw_store::JobState::Running && j.attempts == claim.attempt)
}

/// How often a running job's runner looks whether the job was cancelled.
const CHECK_INTERVAL: Duration = Duration::from_millis(500);

/// Counts a pipeline thread while it lives (`scenewright_pipelines_running`).
struct Running(Arc<std::sync::atomic::AtomicI64>);

impl Running {
    fn start(n: &Arc<std::sync::atomic::AtomicI64>) -> Self {
        n.fetch_add(1, Ordering::SeqCst);
        Self(Arc::clone(n))
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Runs the pipeline on a blocking thread within the job's remaining time.
///
/// `stop` is the pipeline's cancel flag: the heartbeat sets it when the claim is lost
/// (cancelled, timed out, taken over) or the process stops, and the time limit sets it
/// here. The pipeline runs inside `sw_geom::cancel::scope(stop)`, so it stops at its next
/// check — between stages, and inside the layout's and the verification's loops — instead
/// of finishing work nobody will keep.
async fn run_pipeline(
    state: &AppState,
    claim: &Claim,
    work: &Path,
    tx: tokio::sync::mpsc::UnboundedSender<Value>,
    stop: Arc<AtomicBool>,
) -> Result<(Made, tempfile::TempDir), String> {
    let job = claim.job.clone();
    let tmp = tempfile::Builder::new()
        .prefix(&format!("job-{}-", job.id))
        .tempdir_in(work)
        .map_err(|e| format!("scratch space {}: {e}", work.display()))?;
    let out = tmp.path().join("package");
    // A scene slot of a dataset (`scenewright dataset --database`).
    if let Some(slot) = sw_pipeline::dataset::SlotJob::of(&job.options) {
        let (report, timings, dir) = crate::dataset_jobs::run(state, &job, &slot?, tmp.path(), tx, stop).await?;
        return Ok((Made { report, timings, dir, edit: None }, tmp));
    }
    let blobs = state.blobs.clone();
    let (parent_files, parent_hashes) = match &job.parent_scene_id {
        Some(p) => match state.store.scene_of(p, &job.user_id).await {
            Ok(Some(sc)) => {
                let hashes = state.store.file_hashes(p).await.map_err(|e| e.to_string())?;
                (sc.files, hashes)
            }
            Ok(None) => return Err(format!("the scene {p} to edit no longer exists")),
            Err(e) => return Err(e.to_string()),
        },
        None => (Vec::new(), Default::default()),
    };
    let cancel = stop.clone();
    let llm = state.runner.llm.clone();
    let forge = Arc::clone(&state.forge);
    // The pipeline's thread logs in the job's span too (its stage spans nest in it).
    let span = tracing::Span::current();
    let running = Arc::clone(&state.metrics.pipelines);
    let handle = tokio::task::spawn_blocking(move || {
        let _job = span.enter();
        let _running = Running::start(&running);
        let scope_flag = Arc::clone(&cancel);
        sw_geom::cancel::scope(&scope_flag, || {
            let mut on_event = |e: &Event| {
                log_event(e);
                let _ = tx.send(serde_json::to_value(e).unwrap_or_else(|_| json!({"event": "note"})));
            };
            match job.kind {
                JobKind::Generate => {
                    let opts = Options { cancel: Some(cancel), ..options(&job.options, job.seed) };
                    // With a plan stage model, the LLM pipeline (as `scenewright llm generate`),
                    // its assets from the forge when the CAD stage has a model too.
                    let o = match llm.as_ref().filter(|c| c.endpoint(LlmStage::Plan).is_some()) {
                        Some(cfg) => {
                            let client = sw_llm::Client::new(cfg.clone());
                            let mut run = sw_pipeline::LlmRun::new(client.clone());
                            if cfg.endpoint(LlmStage::Cad).is_some() {
                                match forge.source_for_job(&client) {
                                    Ok(source) => run.assets = source,
                                    Err(e) => tracing::warn!("{e}; novel objects keep labelled proxies"),
                                }
                            }
                            sw_pipeline::generate_with_llm(&job.prompt, &out, &opts, &run, &mut on_event)
                        }
                        None => sw_pipeline::generate(&job.prompt, &out, &opts, &mut on_event),
                    }
                    .map_err(describe)?;
                    Ok(Made { report: o.report, timings: o.timings, dir: o.out_dir, edit: None })
                }
                JobKind::Edit => {
                    let parent = job.parent_scene_id.clone().ok_or("an edit job without a scene")?;
                    download(&*blobs, &parent, &parent_files, &parent_hashes, &out)?;
                    // The offline grammar first; a command it cannot read goes to the edit stage's
                    // model when one is configured (as `scenewright edit`).
                    let client = llm.filter(|c| c.endpoint(LlmStage::Edit).is_some()).map(sw_llm::Client::new);
                    let reader = if client.is_some() { EditReader::GrammarThenLlm } else { EditReader::Grammar };
                    // A structured edit from the viewer (a move, a placed part), or a sentence.
                    let o = match crate::edit_jobs::spec(&job.options) {
                        Some(spec) => crate::edit_jobs::run(&out, spec?, &job.prompt, &forge, &mut on_event),
                        None => sw_pipeline::edit_package(&out, &job.prompt, reader, client.as_ref(), &mut on_event),
                    }
                    .map_err(describe)?;
                    let record = serde_json::to_value(&o.record).unwrap_or(Value::Null);
                    Ok(Made { report: o.report, timings: o.timings, dir: o.dir, edit: Some(record) })
                }
            }
        })
    });
    let started = job.started_at.unwrap_or_else(sw_store::now_ms);
    let left = (started + job.timeout_ms - sw_store::now_ms()).max(0) as u64;
    match tokio::time::timeout(Duration::from_millis(left), handle).await {
        Ok(Ok(Ok(made))) => Ok((made, tmp)),
        Ok(Ok(Err(message))) => Err(message),
        Ok(Err(join)) => Err(format!("the pipeline crashed: {join}")),
        Err(_) => {
            stop.store(true, Ordering::Relaxed);
            Err(format!("timed out after {} s", job.timeout_ms / 1000))
        }
    }
}

/// Logs a pipeline event (on the pipeline's thread, inside the job's span).
fn log_event(e: &Event) {
    match e {
        Event::StageStarted { stage } => tracing::debug!(stage = %stage_name(*stage), "stage started"),
        Event::StageFinished { stage, ms, summary } => {
            tracing::info!(stage = %stage_name(*stage), ms = *ms, summary = %summary, "stage finished");
        }
        Event::Note { stage, message } => tracing::debug!(stage = %stage_name(*stage), message = %message, "note"),
        Event::Object { stage, object, step } => {
            tracing::debug!(stage = %stage_name(*stage), object = %object, step = %step, "object");
        }
    }
}

fn describe(e: PipelineError) -> String {
    match e {
        PipelineError::Input(m) => m,
        e => e.to_string(),
    }
}

/// The pipeline's options from a job's stored options.
fn options(o: &Value, seed: u64) -> Options {
    Options {
        seed,
        verify: o["verify"].as_bool().unwrap_or(true),
        robots: o["robots"].as_array().map(|a| a.iter().filter_map(|x| x.as_str().map(str::to_string)).collect()),
        rules_profile: o["rules"].as_str().map(str::to_string),
        anomaly: o.get("anomaly").and_then(|a| serde_json::from_value(a.clone()).ok()),
        cancel: None,
        physics: o["physics"].as_str().and_then(sw_pipeline::PhysicsTarget::parse).unwrap_or_default(),
        fill: None,
    }
}

/// The SHA-256 of `data`, hex.
pub(crate) fn sha256_hex(data: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(data).iter().map(|b| format!("{b:02x}")).collect()
}

/// Copies a stored scene's files into `dir`, each checked against the checksum stored
/// with it (`hashes`: path → SHA-256; scenes stored before checksums have none).
fn download(
    blobs: &dyn BlobStore,
    scene: &str,
    files: &[String],
    hashes: &std::collections::BTreeMap<String, String>,
    dir: &Path,
) -> Result<(), String> {
    for f in files {
        sw_store::check_key(f).map_err(|e| e.to_string())?;
        let data = blobs
            .get(&format!("scenes/{scene}/{f}"))
            .map_err(|e| e.to_string())?
            .ok_or_else(|| format!("scene {scene} lost its file {f}"))?;
        if hashes.get(f).is_some_and(|h| *h != sha256_hex(&data)) {
            return Err(format!("the stored file {f} of scene {scene} is damaged (its checksum does not match)"));
        }
        let path = dir.join(f);
        if let Some(p) = path.parent() {
            fs_err::create_dir_all(p).map_err(|e| e.to_string())?;
        }
        fs_err::write(&path, data).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// Every file under `dir`, as relative `/` paths, sorted.
fn list_files(dir: &Path) -> std::io::Result<Vec<String>> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs_err::read_dir(&d)? {
            let entry = entry?;
            let p = entry.path();
            if entry.file_type()?.is_dir() {
                stack.push(p);
            } else if let Ok(rel) = p.strip_prefix(dir) {
                let rel: Vec<String> = rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
                out.push(rel.join("/"));
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Uploads the package and completes the job (or discards the upload if the claim was lost).
async fn finish(state: &AppState, claim: &Claim, made: Made) -> Result<(), String> {
    let scene_id = new_id();
    let blobs = state.blobs.clone();
    let dir = made.dir.clone();
    let sid = scene_id.clone();
    let uploaded = tokio::task::spawn_blocking(move || -> Result<Vec<(String, String)>, String> {
        let files = list_files(&dir).map_err(|e| e.to_string())?;
        let mut hashes = Vec::with_capacity(files.len());
        for f in files {
            let data = fs_err::read(dir.join(&f)).map_err(|e| e.to_string())?;
            if let Err(e) = blobs.put(&format!("scenes/{sid}/{f}"), &data) {
                // Nothing half-stored stays behind.
                let _ = blobs.delete_prefix(&format!("scenes/{sid}/"));
                return Err(e.to_string());
            }
            hashes.push((f, sha256_hex(&data)));
        }
        Ok(hashes)
    })
    .await
    .map_err(|e| e.to_string())??;
    let files: Vec<String> = uploaded.iter().map(|(f, _)| f.clone()).collect();
    let status = serde_json::to_value(made.report.status).ok().and_then(|v| v.as_str().map(str::to_string));
    // An edited scene's report keeps its generation's calls and asset story; the job's own
    // telemetry is the edit's calls, and only generation counts asset cache lookups.
    let (calls, cache): (Vec<sw_plan::LlmCall>, _) = match &made.edit {
        Some(edit) => {
            (edit.get("llm_calls").and_then(|v| serde_json::from_value(v.clone()).ok()).unwrap_or_default(), None)
        }
        None => {
            let c = made.report.asset_cache;
            (made.report.llm_calls.clone(), Some((i64::from(c.hits), i64::from(c.misses))))
        }
    };
    let telemetry = Telemetry {
        stages: made.timings.stages.iter().map(|s| (stage_name(s.stage), s.ms)).collect(),
        llm_calls: calls
            .iter()
            .map(|c| {
                let stage = serde_json::to_value(c.stage).ok().and_then(|v| v.as_str().map(str::to_string));
                (stage.unwrap_or_default(), c.latency_ms, c.tokens_in as i64, c.tokens_out as i64)
            })
            .collect(),
        cache,
    };
    let new = NewScene {
        id: scene_id.clone(),
        status: status.clone().unwrap_or_else(|| "unknown".into()),
        report: serde_json::to_value(&made.report).map_err(|e| e.to_string())?,
        files: files.clone(),
        hashes: uploaded,
        edit: made.edit.map(|r| (claim.job.prompt.clone(), r)),
    };
    for w in &made.report.warnings {
        emit(state, &claim.job.id, json!({"event": "warning", "stage": w.stage, "code": w.code, "message": w.message}))
            .await;
    }
    let completed = match state.store.complete(claim, &new, &telemetry).await {
        Ok(c) => c,
        Err(e) => {
            // Not stored (a full disk, say): the upload goes, the job fails or runs again.
            let blobs = state.blobs.clone();
            let prefix = format!("scenes/{scene_id}/");
            let _ = tokio::task::spawn_blocking(move || blobs.delete_prefix(&prefix)).await;
            return Err(e.to_string());
        }
    };
    if completed {
        tracing::info!(scene = %scene_id, status = status.as_deref().unwrap_or("unknown"), "job succeeded");
        let _ = state.events.send(claim.job.id.clone());
    } else {
        // Cancelled, timed out or taken over while we worked: our result is not the job's.
        tracing::warn!("the job's claim was lost before completion; discarding its package");
        let blobs = state.blobs.clone();
        let _ = tokio::task::spawn_blocking(move || blobs.delete_prefix(&format!("scenes/{scene_id}/"))).await;
    }
    Ok(())
}

fn stage_name(s: sw_plan::Stage) -> String {
    serde_json::to_value(s).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}
