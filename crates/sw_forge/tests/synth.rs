#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The offline synthesizer's feature language, checked against references made apart from
//! it (bench/cad/*.refs.tsv: the CadQuery reference programs' exact solids, themselves
//! checked against closed formulas by bench/cad/refs.py).
//!
//! - Every prompt of standard_100 and of our features suite is read (pure Rust, fast):
//!   all but the two that contradict themselves are made, and what the synthesizer
//!   promises (extents it is certain of, exact volumes) agrees with the reference.
//! - A representative subset — one or more prompts of every construct — runs in the
//!   sandboxed CadQuery runner and is measured against the reference (1 % bbox, 2 %
//!   volume). `scenewright bench cad` runs the whole suites.
//! - Prompts it cannot honour are refused with the exact words.
//!
//! Needs `scripts/setup.sh --tests` (the CadQuery venv); fails, never skips, without it.

use std::collections::BTreeMap;
use std::sync::OnceLock;
use std::time::Duration;

use sw_forge::part::{GenerateError, generate_offline, write_part};
use sw_forge::runner::{CadRunner, RunnerConfig};
use sw_forge::suite::{Reference, parse_refs, parse_suite};
use sw_forge::synth::{SynthError, synthesize};

const STANDARD_100: &str = include_str!("../../../bench/cad/standard_100.tsv");
const STANDARD_REFS: &str = include_str!("../../../bench/cad/standard_100.refs.tsv");
const FEATURES: &str = include_str!("../../../bench/cad/features.tsv");
const FEATURE_REFS: &str = include_str!("../../../bench/cad/features.refs.tsv");

fn runner() -> &'static CadRunner {
    static R: OnceLock<CadRunner> = OnceLock::new();
    R.get_or_init(|| {
        CadRunner::start(RunnerConfig { workers: 2, timeout: Duration::from_secs(30), ..RunnerConfig::default() })
            .unwrap_or_else(|e| panic!("the CAD runner must start (run scripts/setup.sh --tests): {e}"))
    })
}

fn refs() -> BTreeMap<String, Reference> {
    let mut r = parse_refs(STANDARD_REFS);
    r.extend(parse_refs(FEATURE_REFS));
    r
}

fn prompts() -> BTreeMap<String, String> {
    parse_suite(STANDARD_100).into_iter().chain(parse_suite(FEATURES)).map(|p| (p.id, p.text)).collect()
}

fn sorted(mut v: [f64; 3]) -> [f64; 3] {
    v.sort_by(f64::total_cmp);
    v
}

/// The two standard_100 prompts whose words contradict each other, refused with them.
const CONTRADICTORY: &[(&str, &str)] = &[("T2_019", "pin hole"), ("T3_025", "5.75mm")];

#[test]
fn every_suite_prompt_is_read_and_its_promise_agrees_with_the_reference() {
    let refs = refs();
    let mut problems = Vec::new();
    let mut made = 0;
    for (id, text) in prompts() {
        match (synthesize(&text), CONTRADICTORY.iter().find(|(c, _)| *c == id)) {
            (Ok(s), None) => {
                made += 1;
                let Some(r) = refs.get(&id) else {
                    problems.push(format!("{id}: no reference"));
                    continue;
                };
                // Extents it is certain of, compared as sorted when all are certain.
                if s.size_certain.iter().all(|c| *c) {
                    let (a, b) = (sorted(s.size), sorted(r.size));
                    if a.iter().zip(&b).any(|(x, y)| (x - y).abs() > 0.01 * y + 0.02) {
                        problems.push(format!("{id}: promises {:?}, the reference is {:?}", s.size, r.size));
                    }
                }
                if let (Some(v), Some(rv)) = (s.volume, r.volume)
                    && (v - rv).abs() > 0.02 * rv
                {
                    problems.push(format!("{id}: promises {v:.1} mm3, the reference is {rv:.1}"));
                }
            }
            (Err(SynthError::Unread { phrase, .. }), Some((_, words))) => {
                assert!(phrase.contains(words), "{id}: refused with {phrase:?}, not the contradicting {words:?}");
            }
            (Ok(_), Some(_)) => problems.push(format!("{id}: made, though its words contradict each other")),
            (Err(e), _) => problems.push(format!("{id}: {e}")),
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert_eq!(made, 166, "98 of standard_100 and 68 features");
}

/// One or more prompts of every construct: base solids, sections, holes and patterns,
/// counterbores and countersinks, slots, keyways, grooves, pockets, fillets, chamfers,
/// shells, revolves, lofts, bends, radial arms, stacked and joined assemblies.
const SUBSET: &[&str] = &[
    "T1_013", "T1_024", "T1_028", "T1_031", "T1_043", "T1_045", "T2_004", "T2_006", "T2_012", "T2_013", "T2_015",
    "T2_020", "T2_021", "T2_023", "T2_024", "T3_003", "T3_004", "T3_007", "T3_011", "T3_013", "T3_015", "T3_019",
    "T3_022", "F_008", "F_021", "F_022", "F_024", "F_026", "F_028", "F_036", "F_040", "F_043", "F_047", "F_056",
    "F_061", "F_063", "F_064", "F_065", "F_066", "F_068",
];

/// A part's largest extent and volume errors against its reference, or why it failed.
type Errors = Result<(f64, f64), String>;

#[test]
fn a_subset_of_every_construct_runs_and_matches_its_reference() {
    let refs = refs();
    let prompts = prompts();
    let r = runner();
    let jobs: Vec<(&str, String)> = SUBSET.iter().map(|id| (*id, prompts[*id].clone())).collect();
    let results: Vec<(String, Errors)> = std::thread::scope(|s| {
        let handles: Vec<_> = jobs
            .chunks(jobs.len().div_ceil(2))
            .map(|chunk| {
                s.spawn(|| {
                    chunk
                        .iter()
                        .map(|(id, text)| {
                            let out = match generate_offline(r, text) {
                                Ok(part) => {
                                    assert!(part.report.watertight, "{id}");
                                    let rf = refs[*id];
                                    let (a, b) = (sorted(part.report.size), sorted(rf.size));
                                    let be = a.iter().zip(&b).map(|(x, y)| (x - y).abs() / y).fold(0.0, f64::max);
                                    let ve = rf.volume.map_or(0.0, |v| (part.report.volume - v).abs() / v);
                                    Ok((be, ve))
                                }
                                Err(e) => Err(e.to_string()),
                            };
                            (id.to_string(), out)
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let bad: Vec<String> = results
        .iter()
        .filter_map(|(id, r)| match r {
            Ok((be, ve)) if *be <= 0.01 && *ve <= 0.02 => None,
            Ok((be, ve)) => Some(format!("{id}: bbox {:.2} %, volume {:.2} %", 100.0 * be, 100.0 * ve)),
            Err(e) => Some(format!("{id}: {e}")),
        })
        .collect();
    assert!(bad.is_empty(), "{} of {} off:\n{}", bad.len(), SUBSET.len(), bad.join("\n"));
}

#[test]
fn a_part_is_written_as_stl_in_metres_with_metadata_and_preview() {
    let part =
        generate_offline(runner(), "A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm").unwrap();
    let dir = tempfile::tempdir().unwrap();
    let files = write_part(dir.path(), &part, true).unwrap();
    let mesh = sw_geom::read_stl(std::fs::File::open(&files.mesh).unwrap()).unwrap();
    let size = mesh.bounds().size();
    assert!((size[0] - 0.020).abs() < 2e-4 && (size[2] - 0.002).abs() < 2e-5, "{size:?}");
    let meta: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&files.metadata).unwrap()).unwrap();
    assert_eq!(meta["template"], "features");
    assert_eq!(meta["through_holes"], 1);
    let png = std::fs::read(files.preview.unwrap()).unwrap();
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn a_wrong_part_fails_validation_with_its_kind() {
    // Code that makes a different size than the synthesizer promised is caught: the
    // washer's code with a doubled thickness, through the same validator.
    let s = synthesize("A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm").unwrap();
    let code = s.code.replace(".extrude(2)", ".extrude(4)");
    assert_ne!(code, s.code, "the test edits the extrusion: {}", s.code);
    let run = runner().run(&sw_forge::runner::CadJob::cadquery(code)).unwrap();
    let err = sw_forge::validate::validate(&run.mesh, &s.target()).unwrap_err();
    assert_eq!(err.kind, sw_forge::failure::FailureKind::ScaleMismatch);
}

/// Prompts the synthesizer cannot honour, and the words it must name.
const REFUSED: &[(&str, &str)] = &[
    ("a block 20mm long, 10mm wide and 5mm tall with a dragon engraved on top", "dragon"),
    ("a knurled knob 20mm in diameter and 10mm tall", "knurled"),
    ("a plate 100 x 50 x 5 mm with four holes", "holes"),
    ("a cylinder 20mm in diameter and 30mm tall with a 25mm bore", "25mm bore"),
    ("a plate 60 x 40 x 5 mm with a 6mm hole at (X=40, Y=0)", "6mm hole"),
    ("a gear with 20 teeth, 8mm thick", "gear"),
    ("a washer: outer diameter 10mm, inner diameter 12mm, 1mm thick", "washer"),
    (
        "a disc 50mm in diameter and 5mm thick with six 4mm holes at 0, 90 and 180 degrees on a 30mm bolt circle",
        "holes",
    ),
    ("a cube with 10mm sides and 6mm fillets on all edges", "6mm fillets"),
    ("A shaft 30mm in diameter and 200mm long with a 40mm long, 8mm wide, 4mm deep keyway at one end.", "40mm long"),
    // Positions from an edge, holes in side faces, unnamed edges and corners, a ball beside a
    // body, threads: refused, never made as something else.
    ("A plate 100 x 60 x 5 mm with a 10 mm hole 20 mm from the left edge.", "20 mm"),
    ("A cylinder 40 mm in diameter and 60 mm tall with a 10 mm hole through its side.", "its side"),
    ("A box 100 x 100 x 100 mm with a 20 mm hole on each face.", "each face"),
    ("A block 50 x 30 x 20 mm with a 5 mm chamfer on one edge.", "one edge"),
    ("A plate 100 x 50 x 5 mm with a 10 mm hole in each corner.", "corner"),
    ("A block 40 x 40 x 40 mm with a sphere 20 mm in diameter on top.", "sphere"),
    ("A disc 80 mm in diameter, 10 mm thick, with a 30 mm hexagonal hole in the middle.", "hexagonal"),
    ("A 50 mm long bolt with an M10 thread.", "bolt"),
];

#[test]
fn prompts_it_cannot_honour_are_refused_with_their_words() {
    for (prompt, words) in REFUSED {
        match synthesize(prompt) {
            Err(SynthError::Unread { phrase, reason }) => {
                assert!(phrase.contains(words), "{prompt}: refused with {phrase:?} ({reason}), expected {words:?}");
            }
            other => panic!("{prompt}: {other:?}"),
        }
    }
    for p in ["", "a hovercraft", "a spaceship 20mm long"] {
        assert!(matches!(generate_offline(runner(), p), Err(GenerateError::Synth(_))), "{p}");
    }
}
