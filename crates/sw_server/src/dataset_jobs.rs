//! Dataset jobs (`scenewright dataset --database`): a job makes one scene slot of a
//! dataset. It tries the slot's seeds (`DatasetSpec::queue_seed`) until a scene verifies
//! in MuJoCo and its structural fingerprint is taken for the slot in the database (a
//! fingerprint another slot holds is a duplicate: next seed). The scene is then stored and
//! the job completed like any generation job; the dataset's leader assembles the
//! manifest from the jobs' scenes. A job run again after its runner was lost tries the
//! same seeds, finds its fingerprint already its own, and ends with the same scene.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use serde_json::{Value, json};
use sw_pipeline::dataset::{SlotJob, TRIES, failure_reason};
use sw_pipeline::{Event, PipelineError};
use sw_store::Job;

use crate::AppState;

/// What a slot's job made: the report, timings and package directory.
pub(crate) type SlotMade = (sw_plan::Report, sw_plan::Timings, PathBuf);

/// Runs `slot` in `work` within the job's remaining time.
pub(crate) async fn run(
    state: &AppState,
    job: &Job,
    slot: &SlotJob,
    work: &Path,
    tx: tokio::sync::mpsc::UnboundedSender<Value>,
    stop: Arc<AtomicBool>,
) -> Result<SlotMade, String> {
    let started = job.started_at.unwrap_or_else(sw_store::now_ms);
    let left = (started + job.timeout_ms - sw_store::now_ms()).max(0) as u64;
    match tokio::time::timeout(Duration::from_millis(left), seeds(state, job, slot, work, tx, stop.clone())).await {
        Ok(r) => r,
        Err(_) => {
            stop.store(true, Ordering::Relaxed);
            Err(format!("timed out after {} s", job.timeout_ms / 1000))
        }
    }
}

async fn seeds(
    state: &AppState,
    job: &Job,
    slot: &SlotJob,
    work: &Path,
    tx: tokio::sync::mpsc::UnboundedSender<Value>,
    stop: Arc<AtomicBool>,
) -> Result<SlotMade, String> {
    let mut reasons: Vec<String> = Vec::new();
    for t in 0..TRIES {
        if stop.load(Ordering::Relaxed) {
            return Err("cancelled".into());
        }
        let seed = slot.spec.queue_seed(slot.k, t);
        let robot = slot.spec.draw_robot(slot.prompt_index as usize, seed);
        let opts =
            sw_pipeline::Options { cancel: Some(stop.clone()), ..slot.spec.scene_options(robot.as_deref(), seed) };
        let out = work.join(format!("seed{seed}"));
        let prompt = job.prompt.clone();
        let events = tx.clone();
        let dir = out.clone();
        let span = tracing::Span::current();
        let made = tokio::task::spawn_blocking(move || {
            let _job = span.enter();
            let mut on_event = |e: &Event| {
                let _ = events.send(serde_json::to_value(e).unwrap_or_else(|_| json!({"event": "note"})));
            };
            // The layout and the settle stop at their next check when the job is cancelled.
            let flag = opts.cancel.clone().unwrap_or_default();
            sw_geom::cancel::scope(&flag, || sw_pipeline::generate(&prompt, &dir, &opts, &mut on_event))
        })
        .await
        .map_err(|e| format!("the pipeline crashed: {e}"))?;
        let o = match made {
            Ok(o) => o,
            Err(PipelineError::Cancelled) => return Err("cancelled".into()),
            Err(PipelineError::Input(m)) => return Err(m),
            Err(e) => {
                reasons.push(e.to_string());
                continue;
            }
        };
        if !sw_pipeline::succeeded(&o.report) {
            let failures = o.report.verification.as_ref().map(|v| v.failures.clone()).unwrap_or_default();
            reasons.push(failure_reason(&failures));
            let _ = fs_err::remove_dir_all(&o.out_dir);
            continue;
        }
        let fp = {
            let dir = o.out_dir.clone();
            tokio::task::spawn_blocking(move || sw_pipeline::manifest::fingerprint(&dir))
                .await
                .map_err(|e| e.to_string())?
                .map_err(|e| e.to_string())?
        };
        if state.store.claim_fingerprint(&slot.dataset, &fp, &slot.slot).await.map_err(|e| e.to_string())? {
            tracing::info!(slot = %slot.slot, seed, fingerprint = %fp, "dataset scene made");
            return Ok((o.report, o.timings, o.out_dir));
        }
        reasons.push("duplicate of an earlier scene".into());
        let _ = fs_err::remove_dir_all(&o.out_dir);
    }
    reasons.sort();
    reasons.dedup();
    Err(format!("no valid new scene in {TRIES} seeds ({})", reasons.join("; ")))
}
