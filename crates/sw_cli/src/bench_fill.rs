//! `bench fill`: rooms of the kinds people live and work in, generated with `--fill
//! cluttered` (or the level given) at several seeds, verified in MuJoCo as always: objects
//! per room, added objects, free bodies that stayed put, contacts deeper than 1 mm at the
//! start, and the time of the fill (the layout stage, which includes it) and of the whole run.

use std::time::Instant;

use serde::Serialize;
use sw_pipeline::{FillLevel, Options};
use sw_plan::Stage;

use crate::Failure;
use crate::output::{print, print_json};

/// The rooms of issue 21's measure, as people ask for them.
const ROOMS: &[&str] = &["a kitchen", "an office", "a bedroom", "a living room", "a workshop", "a shop"];

#[derive(Debug, Serialize)]
struct RoomRun {
    prompt: String,
    seed: u64,
    objects: usize,
    added: usize,
    free_bodies: usize,
    moved: usize,
    deep_contacts: usize,
    verified: bool,
    layout_ms: f64,
    total_ms: f64,
}

#[derive(Debug, Serialize)]
struct FillBench {
    level: &'static str,
    seeds: u64,
    runs: Vec<RoomRun>,
    mean_objects: f64,
    min_objects: usize,
    free_bodies_stable: f64,
    deep_contacts: usize,
    max_layout_ms: f64,
    median_total_ms: f64,
}

pub(crate) fn run(level: &str, seeds: u64, rooms: &[String], json: bool) -> Result<u8, Failure> {
    let level = FillLevel::from_name(level)
        .ok_or_else(|| Failure::input(format!("--level {level}: none, furnished or cluttered")))?;
    let rooms: Vec<String> =
        if rooms.is_empty() { ROOMS.iter().map(|r| r.to_string()).collect() } else { rooms.to_vec() };
    let scratch = tempfile::tempdir().map_err(|e| Failure::internal(format!("scratch directory: {e}")))?;
    let mut runs = Vec::new();
    for (k, prompt) in rooms.iter().enumerate() {
        for seed in 0..seeds {
            let out = scratch.path().join(format!("r{k}-{seed}"));
            let opts = Options { seed, fill: Some(level), ..Options::default() };
            let t = Instant::now();
            let o = sw_pipeline::generate(prompt, &out, &opts, &mut |_| {})
                .map_err(|e| Failure::internal(format!("{prompt}: {e}")))?;
            let total_ms = t.elapsed().as_secs_f64() * 1000.0;
            let layout_ms = o.timings.stages.iter().filter(|s| s.stage == Stage::Layout).map(|s| s.ms).sum();
            let v = o.report.verification.as_ref();
            runs.push(RoomRun {
                prompt: prompt.clone(),
                seed,
                objects: o.layout.objects.len(),
                added: o.layout.objects.iter().filter(|p| p.added).count(),
                free_bodies: o.layout.objects.iter().filter(|p| p.movable).count(),
                moved: v.and_then(|v| v.settle.as_ref()).map_or(0, |s| s.moved.len()),
                deep_contacts: v.and_then(|v| v.initial_contacts.as_ref()).map_or(0, |c| c.deep.len()),
                verified: sw_pipeline::succeeded(&o.report) && v.is_some(),
                layout_ms,
                total_ms,
            });
            let _ = std::fs::remove_dir_all(&out);
        }
    }
    let n = runs.len().max(1) as f64;
    let free: usize = runs.iter().map(|r| r.free_bodies).sum();
    let moved: usize = runs.iter().map(|r| r.moved).sum();
    let mut totals: Vec<f64> = runs.iter().map(|r| r.total_ms).collect();
    totals.sort_by(f64::total_cmp);
    let bench = FillBench {
        level: level.name(),
        seeds,
        mean_objects: runs.iter().map(|r| r.objects as f64).sum::<f64>() / n,
        min_objects: runs.iter().map(|r| r.objects).min().unwrap_or(0),
        free_bodies_stable: if free == 0 { 1.0 } else { 1.0 - moved as f64 / free as f64 },
        deep_contacts: runs.iter().map(|r| r.deep_contacts).sum(),
        max_layout_ms: runs.iter().map(|r| r.layout_ms).fold(0.0, f64::max),
        median_total_ms: totals.get(totals.len() / 2).copied().unwrap_or(0.0),
        runs,
    };
    if json {
        print_json(&bench);
    } else {
        for r in &bench.runs {
            print(&format!(
                "{:<16} seed {:<2} {:>4} objects ({:>3} added, {:>3} free, {} moved, {} deep) {}  layout+fill {:>6.0} ms  total {:>7.0} ms",
                r.prompt,
                r.seed,
                r.objects,
                r.added,
                r.free_bodies,
                r.moved,
                r.deep_contacts,
                if r.verified { "verified" } else { "FAILED" },
                r.layout_ms,
                r.total_ms
            ));
        }
        print(&format!(
            "--fill {}: {:.1} objects per room (min {}), {:.1} % of free bodies stable, {} contacts deeper than 1 mm, layout+fill max {:.0} ms, whole run median {:.0} ms",
            bench.level,
            bench.mean_objects,
            bench.min_objects,
            bench.free_bodies_stable * 100.0,
            bench.deep_contacts,
            bench.max_layout_ms,
            bench.median_total_ms
        ));
    }
    let ok = bench.runs.iter().all(|r| r.verified && r.moved == 0 && r.deep_contacts == 0);
    Ok(if ok { 0 } else { 1 })
}
