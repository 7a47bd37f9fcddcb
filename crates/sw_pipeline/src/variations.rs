//! `--variations N`: N structurally different valid layouts of the same plan, each a
//! complete package in `<out>/variation_<k>/`, with `<out>/variations.json` listing them.

use std::path::Path;

use serde::Serialize;
use sw_plan::LaidOutScene;

use crate::{Event, Options, Outcome, PipelineError, generate, package};

/// Share of objects that must stand elsewhere for two layouts to count as different.
const MIN_DIFFERENCE: f64 = 0.3;
/// Seeds tried per variation before accepting a less different layout.
const TRIES: u64 = 6;

#[derive(Debug, Serialize)]
struct Entry {
    dir: String,
    seed: u64,
    /// Share of objects and robots placed differently from the nearest earlier variation.
    difference: f64,
}

#[derive(Debug, Serialize)]
struct Index {
    prompt: String,
    variations: Vec<Entry>,
}

/// Share of the objects and robots of `a` that stand somewhere else in `b`: more than
/// 0.5 m away, turned, or on another support.
pub fn structural_difference(a: &LaidOutScene, b: &LaidOutScene) -> f64 {
    let mut n = 0usize;
    let mut changed = 0usize;
    for o in &a.objects {
        n += 1;
        let moved = match b.object(&o.name) {
            None => true,
            Some(p) => {
                (o.pos[0] - p.pos[0]).hypot(o.pos[1] - p.pos[1]) > 0.5
                    || (o.yaw - p.yaw).abs() > 1e-3
                    || o.support != p.support
            }
        };
        changed += usize::from(moved);
    }
    for r in &a.robots {
        n += 1;
        let moved = b
            .robots
            .iter()
            .find(|x| x.name == r.name)
            .is_none_or(|p| (r.pos[0] - p.pos[0]).hypot(r.pos[1] - p.pos[1]) > 0.5);
        changed += usize::from(moved);
    }
    if n == 0 { 0.0 } else { changed as f64 / n as f64 }
}

/// Generates `count` variations into `out`.
pub fn generate_variations(
    prompt: &str,
    out: &Path,
    count: u32,
    opts: &Options,
    on_event: &mut dyn FnMut(&Event),
) -> Result<Vec<Outcome>, PipelineError> {
    if count == 0 || count > 1000 {
        return Err(PipelineError::Input(format!("--variations must be between 1 and 1000, got {count}")));
    }
    package::check_destination(out)?;
    let mut outcomes: Vec<Outcome> = Vec::new();
    let mut entries = Vec::new();
    let mut seed = opts.seed;
    for k in 1..=count {
        // Candidates go to hidden directories; the most different one becomes variation_k.
        let mut best: Option<(Outcome, f64)> = None;
        for _ in 0..TRIES {
            let trial = out.join(format!(".variation_{k}.seed_{seed}"));
            let o = generate(prompt, &trial, &Options { seed, ..opts.clone() }, on_event)?;
            seed += 1;
            let diff = outcomes.iter().map(|p| structural_difference(&p.layout, &o.layout)).fold(1.0, f64::min);
            match &best {
                Some((_, d)) if *d >= diff => {
                    let _ = std::fs::remove_dir_all(&o.out_dir);
                }
                _ => {
                    if let Some((old, _)) = best.take() {
                        let _ = std::fs::remove_dir_all(&old.out_dir);
                    }
                    best = Some((o, diff));
                }
            }
            if best.as_ref().is_some_and(|(_, d)| *d >= MIN_DIFFERENCE) {
                break;
            }
        }
        let Some((mut o, diff)) = best else { break };
        let dir = out.join(format!("variation_{k}"));
        std::fs::rename(&o.out_dir, &dir).map_err(|e| PipelineError::Internal(format!("{}: {e}", dir.display())))?;
        o.out_dir = dir;
        entries.push(Entry {
            dir: format!("variation_{k}"),
            seed: o.report.seed,
            difference: (diff * 1000.0).round() / 1000.0,
        });
        outcomes.push(o);
    }
    let index = Index { prompt: prompt.to_string(), variations: entries };
    let mut text = serde_json::to_string_pretty(&index).map_err(|e| PipelineError::Internal(e.to_string()))?;
    text.push('\n');
    std::fs::write(out.join("variations.json"), text).map_err(|e| PipelineError::Internal(e.to_string()))?;
    Ok(outcomes)
}
