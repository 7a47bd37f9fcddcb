//! `bench asset-index`: the semantic index's reuse threshold on the labelled pairs
//! (precision and recall per threshold, the best F1), the same with the size check that
//! reuse also needs (each label at the size a scene would ask for it: the catalog's
//! default size, else the planner's prior for its head noun), and retrieval time over N
//! indexed assets whose labels are embedded with the real model.

use std::time::Instant;

use serde::Serialize;
use sw_forge::embed::{DIM, MiniLm};
use sw_forge::index::{DEFAULT_THRESHOLD, SemanticIndex, ThresholdPoint, evaluate, sweep};
use sw_forge::store::AssetId;

use crate::Failure;
use crate::output::{print, print_json};

const PAIRS: &str = include_str!("../../../bench/forge/label_pairs.tsv");

const ADJECTIVES: &[&str] = &[
    "small", "large", "tall", "low", "wide", "narrow", "heavy", "light", "old", "new", "red", "blue", "grey", "black",
];
const MATERIALS: &[&str] = &["steel", "wooden", "plastic", "aluminium", "glass", "concrete", "rubber", "cast iron"];
const NOUNS: &[&str] = &[
    "shelf",
    "rack",
    "crate",
    "box",
    "bin",
    "chair",
    "stool",
    "table",
    "desk",
    "bench",
    "cabinet",
    "locker",
    "drawer",
    "cart",
    "trolley",
    "pallet",
    "barrel",
    "drum",
    "tank",
    "pipe",
    "valve",
    "pump",
    "motor",
    "gear",
    "pulley",
    "bracket",
    "plate",
    "beam",
    "column",
    "door",
    "window",
    "lamp",
    "fan",
    "heater",
    "sink",
    "tap",
    "bucket",
    "ladder",
    "fence",
    "gate",
    "sign",
    "cone",
    "bollard",
    "conveyor",
    "robot",
    "arm",
    "gripper",
    "camera",
    "sensor",
    "monitor",
    "keyboard",
    "printer",
    "server",
    "router",
    "panel",
    "switch",
    "socket",
    "cable reel",
    "toolbox",
    "vice",
    "anvil",
    "lathe",
    "drill",
    "saw",
    "grinder",
    "welder",
    "compressor",
    "generator",
    "battery",
    "charger",
    "forklift",
    "jack",
];

#[derive(Serialize)]
struct Retrieval {
    assets: usize,
    queries: usize,
    embed_assets_s: f64,
    search_p50_ms: f64,
    search_p95_ms: f64,
    embed_query_p50_ms: f64,
    end_to_end_p50_ms: f64,
}

/// Reuse by label and size at the default threshold.
#[derive(Serialize)]
struct WithSize {
    at_default: ThresholdPoint,
    /// Non-matching pairs above the threshold (label alone would reuse them).
    hard_negatives_above_threshold: usize,
    /// Of those, the ones the size check turns away.
    turned_away_by_size: usize,
    /// Matching pairs above the threshold that the size check turns away.
    matches_lost_to_size: usize,
}

/// Reuse by label and size at the default threshold, for other limits of the size check.
#[derive(Serialize)]
struct SizeLimits {
    max_distortion: f64,
    max_scale: f64,
    precision: f64,
    recall: f64,
}

#[derive(Serialize)]
struct IndexBench {
    pairs: usize,
    matches: usize,
    at_default: ThresholdPoint,
    with_size: WithSize,
    size_limits: Vec<SizeLimits>,
    best_f1: ThresholdPoint,
    sweep: Vec<ThresholdPoint>,
    retrieval: Retrieval,
}

/// The size (m) a scene would ask for an object so labelled: the catalog's default size
/// for a category, else the planner's prior for the label's head noun.
fn typical_size(label: &str) -> [f64; 3] {
    if let Some(c) = sw_planner::vocab::category(label).and_then(sw_catalog::find) {
        return c.default_size();
    }
    let p = sw_planner::vocab::proxy(label, false, &[], &sw_plan::ExplicitSize::default());
    [p.size.width, p.size.depth, p.size.height]
}

fn pct(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(((v.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(0.0)
}

pub(crate) fn run(assets: usize, json: bool) -> Result<u8, Failure> {
    if assets == 0 || assets > 200_000 {
        return Err(Failure::input(format!("--assets must be 1 to 200000, not {assets}")));
    }
    let model = MiniLm::load_default().map_err(|e| Failure::internal(e.to_string()))?;
    let rows: Vec<(&str, &str, bool)> = PAIRS
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .filter_map(|l| {
            let c: Vec<&str> = l.split('\t').collect();
            Some((*c.first()?, *c.get(1)?, c.get(2)?.trim() == "1"))
        })
        .collect();
    let embed = |t: &[&str]| model.embed(t).map_err(|e| Failure::internal(e.to_string()));
    let a: Vec<&str> = rows.iter().map(|r| r.0).collect();
    let b: Vec<&str> = rows.iter().map(|r| r.1).collect();
    let (va, vb) = (embed(&a)?, embed(&b)?);
    let scored: Vec<(f32, bool)> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| (va[i].iter().zip(&vb[i]).map(|(x, y)| x * y).sum::<f32>(), r.2))
        .collect();
    let points = sweep(&scored);
    let size_fits: Vec<Option<sw_forge::reuse::SizeFit>> =
        rows.iter().map(|r| sw_forge::reuse::size_fit(typical_size(r.0), typical_size(r.1))).collect();
    let fits: Vec<bool> = size_fits.iter().map(|f| f.is_some_and(|f| f.fits())).collect();
    let mut size_limits = Vec::new();
    for max_distortion in [1.2, 1.3, 1.5, 2.0, 3.0] {
        for max_scale in [1.5, 2.0, 3.0] {
            let gated: Vec<(f32, bool)> = scored
                .iter()
                .zip(&size_fits)
                .map(|((s, m), f)| {
                    let ok = f.is_some_and(|f| {
                        f.distortion <= max_distortion && f.overall <= max_scale && f.overall >= 1.0 / max_scale
                    });
                    (if ok { *s } else { f32::NEG_INFINITY }, *m)
                })
                .collect();
            let p = evaluate(&gated, DEFAULT_THRESHOLD);
            size_limits.push(SizeLimits { max_distortion, max_scale, precision: p.precision, recall: p.recall });
        }
    }
    let sized: Vec<(f32, bool)> =
        scored.iter().zip(&fits).map(|((s, m), fit)| (if *fit { *s } else { f32::NEG_INFINITY }, *m)).collect();
    let above = |m: bool| scored.iter().zip(&fits).filter(move |((s, is), _)| *is == m && *s >= DEFAULT_THRESHOLD);
    let with_size = WithSize {
        at_default: evaluate(&sized, DEFAULT_THRESHOLD),
        hard_negatives_above_threshold: above(false).count(),
        turned_away_by_size: above(false).filter(|(_, fit)| !**fit).count(),
        matches_lost_to_size: above(true).filter(|(_, fit)| !**fit).count(),
    };
    let best = points.iter().copied().max_by(|x, y| x.f1.total_cmp(&y.f1).then(y.threshold.total_cmp(&x.threshold)));
    let best = best.unwrap_or_else(|| evaluate(&scored, DEFAULT_THRESHOLD));

    // N labels from adjective × material × noun, embedded for real.
    let mut labels = Vec::with_capacity(assets);
    'outer: for n in NOUNS {
        for m in MATERIALS {
            for adj in ADJECTIVES {
                for size in ["", " 1 m", " 2 m", " 50 cm"] {
                    if labels.len() == assets {
                        break 'outer;
                    }
                    labels.push(format!("{adj} {m} {n}{size}"));
                }
            }
        }
    }
    let mut k = 0;
    while labels.len() < assets {
        labels.push(format!("{} number {k}", NOUNS[k % NOUNS.len()]));
        k += 1;
    }
    let t = Instant::now();
    let refs: Vec<&str> = labels.iter().map(String::as_str).collect();
    let vectors = embed(&refs)?;
    let embed_assets_s = t.elapsed().as_secs_f64();
    let mut index = SemanticIndex::new(DIM);
    for (l, v) in labels.iter().zip(&vectors) {
        index.upsert(AssetId::of(l.as_bytes()), l.clone(), v).map_err(|e| Failure::internal(e.to_string()))?;
    }
    let (mut search_ms, mut embed_ms, mut total_ms) = (Vec::new(), Vec::new(), Vec::new());
    for q in a.iter().chain(b.iter()) {
        let t0 = Instant::now();
        let v = embed(&[q])?;
        let t1 = Instant::now();
        let hits = index.search(&v[0], 5).map_err(|e| Failure::internal(e.to_string()))?;
        let t2 = Instant::now();
        std::hint::black_box(hits);
        embed_ms.push((t1 - t0).as_secs_f64() * 1e3);
        search_ms.push((t2 - t1).as_secs_f64() * 1e3);
        total_ms.push((t2 - t0).as_secs_f64() * 1e3);
    }
    let retrieval = Retrieval {
        assets: index.len(),
        queries: search_ms.len(),
        embed_assets_s,
        search_p50_ms: pct(&mut search_ms, 0.5),
        search_p95_ms: pct(&mut search_ms, 0.95),
        embed_query_p50_ms: pct(&mut embed_ms, 0.5),
        end_to_end_p50_ms: pct(&mut total_ms, 0.5),
    };
    let bench = IndexBench {
        pairs: rows.len(),
        matches: rows.iter().filter(|r| r.2).count(),
        at_default: evaluate(&scored, DEFAULT_THRESHOLD),
        with_size,
        size_limits,
        best_f1: best,
        sweep: points,
        retrieval,
    };
    if json {
        print_json(&bench);
        return Ok(0);
    }
    let mut s =
        format!("{} labelled pairs ({} matches)\nthreshold  precision  recall  f1\n", bench.pairs, bench.matches);
    for p in bench.sweep.iter().filter(|p| (p.threshold * 100.0).round() as i32 % 5 == 0) {
        s.push_str(&format!("{:>9.2}  {:>9.3}  {:>6.3}  {:.3}\n", p.threshold, p.precision, p.recall, p.f1));
    }
    let d = &bench.at_default;
    s.push_str(&format!(
        "default {:.2}: precision {:.3}, recall {:.3} ({} false positives, {} false negatives)\nbest F1 at {:.2}: precision {:.3}, recall {:.3}, F1 {:.3}\n",
        d.threshold, d.precision, d.recall, d.false_pos, d.false_neg, best.threshold, best.precision, best.recall, best.f1
    ));
    let w = &bench.with_size;
    s.push_str(&format!(
        "with the size check: precision {:.3}, recall {:.3} — it turns away {} of the {} non-matching pairs above {:.2}, and {} matching ones\n",
        w.at_default.precision,
        w.at_default.recall,
        w.turned_away_by_size,
        w.hard_negatives_above_threshold,
        DEFAULT_THRESHOLD,
        w.matches_lost_to_size
    ));
    s.push_str("size limits (distortion × scale): precision / recall at the default threshold\n");
    for l in &bench.size_limits {
        s.push_str(&format!(
            "  ≤ {:.1} × ≤ {:.1}: {:.3} / {:.3}\n",
            l.max_distortion, l.max_scale, l.precision, l.recall
        ));
    }
    let r = &bench.retrieval;
    s.push_str(&format!(
        "retrieval over {} assets ({:.1} s to embed them): search p50 {:.2} ms, p95 {:.2} ms; query embedding p50 {:.1} ms; end to end p50 {:.1} ms ({} queries)\n",
        r.assets, r.embed_assets_s, r.search_p50_ms, r.search_p95_ms, r.embed_query_p50_ms, r.end_to_end_p50_ms, r.queries
    ));
    print(&s);
    Ok(0)
}
