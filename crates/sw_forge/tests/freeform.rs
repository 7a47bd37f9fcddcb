#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Free-form objects offline: every prompt of abstract_45 is made — the catalog's object or
//! a composition run in the sandboxed CadQuery runner — as a closed solid whose size is
//! one a real object of its kind has (bench/cad/abstract_45.sizes.tsv, written from
//! everyday sizes, not from the synthesizer); words it cannot honour are refused with them.
//!
//! Needs `scripts/setup.sh --tests` (the CadQuery venv); fails, never skips, without it.

use std::sync::OnceLock;
use std::time::Duration;

use sw_forge::freeform::{Freeform, Offline, catalog_mesh_mm, offline, read};
use sw_forge::runner::{CadJob, CadRunner, RunnerConfig};
use sw_forge::suite::{parse_sizes, parse_suite};
use sw_forge::synth::SynthError;

const ABSTRACT_45: &str = include_str!("../../../bench/cad/abstract_45.tsv");
const SIZES: &str = include_str!("../../../bench/cad/abstract_45.sizes.tsv");

fn runner() -> &'static CadRunner {
    static R: OnceLock<CadRunner> = OnceLock::new();
    R.get_or_init(|| {
        CadRunner::start(RunnerConfig { workers: 2, timeout: Duration::from_secs(30), ..RunnerConfig::default() })
            .unwrap_or_else(|e| panic!("the CAD runner must start (run scripts/setup.sh --tests): {e}"))
    })
}

/// A made object's mesh (mm) and what made it, or why it was not made.
type Made = Result<(sw_geom::Mesh, String), String>;

/// One prompt made.
fn make(prompt: &str) -> Made {
    match offline(prompt).map_err(|e| e.to_string())? {
        Offline::Catalog { category, asset } => Ok((catalog_mesh_mm(&asset), format!("catalog:{category}"))),
        Offline::Code(s) => {
            let mut run = runner().run(&CadJob::cadquery(s.code.clone())).map_err(|e| e.failure.message.clone())?;
            sw_forge::mesh_io::drop_collapsed_triangles(&mut run.mesh);
            Ok((run.mesh, s.template.clone()))
        }
    }
}

#[test]
fn every_abstract_45_object_is_made_closed_and_of_a_plausible_size() {
    let sizes = parse_sizes(SIZES);
    let prompts = parse_suite(ABSTRACT_45);
    assert_eq!(prompts.len(), 45);
    let results: Vec<(String, Made)> = std::thread::scope(|s| {
        let handles: Vec<_> = prompts
            .chunks(prompts.len().div_ceil(2))
            .map(|chunk| s.spawn(move || chunk.iter().map(|p| (p.id.clone(), make(&p.text))).collect::<Vec<_>>()))
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let mut bad = Vec::new();
    let mut catalog = 0;
    for (id, r) in results {
        match r {
            Ok((mesh, by)) => {
                catalog += usize::from(by.starts_with("catalog:"));
                let check = mesh.check();
                let largest = mesh.bounds().size().into_iter().fold(0.0, f64::max);
                let p = &sizes[&id];
                if !check.watertight || check.volume <= 0.0 {
                    bad.push(format!("{id} ({by}): not a closed solid ({} bad edges)", check.bad_edges));
                } else if !(p.min..=p.max).contains(&largest) {
                    bad.push(format!(
                        "{id} ({by}): {largest:.0} mm, not a plausible {} ({}-{} mm)",
                        p.what, p.min, p.max
                    ));
                }
            }
            Err(e) => bad.push(format!("{id}: {e}")),
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert!(catalog >= 10, "the catalog makes the objects it has ({catalog})");
}

#[test]
fn the_catalog_makes_what_it_has_and_compositions_the_rest() {
    let by = |p: &str| match read(p).unwrap() {
        Freeform::Catalog { category, .. } => format!("catalog:{category}"),
        Freeform::Composed { object, .. } => object.to_string(),
    };
    assert_eq!(by("a chair with four legs and a backrest"), "catalog:chair");
    assert_eq!(by("a computer monitor on a stand"), "catalog:monitor");
    assert_eq!(by("a small trophy"), "trophy");
    assert_eq!(by("a tall pillar"), "pillar");
    // Size words scale it.
    let size = |p: &str| match offline(p).unwrap() {
        Offline::Code(s) => s.size,
        Offline::Catalog { asset, .. } => asset.bounds().size(),
    };
    assert!(size("a large bucket")[2] > 1.4 * size("a bucket")[2]);
    assert!(size("a long hollow pipe")[0] > 1.8 * size("a hollow pipe")[0]);
    let steps = |p: &str| match offline(p).unwrap() {
        Offline::Code(s) => s.code.matches("# step").count(),
        Offline::Catalog { .. } => 0,
    };
    assert_eq!(steps("a staircase with five steps"), 5);
}

#[test]
fn words_it_cannot_honour_are_refused_with_them() {
    for (prompt, words) in [
        ("a chair with three legs", "three legs"),
        ("a coffee mug with a lid and a spoon", "lid"),
        // The catalog has saucers: the word it cannot give one is refused; a noun it knows
        // no object by is refused whole.
        ("a flying saucer", "flying"),
        ("a hovercraft", "a hovercraft"),
        ("a hammer or a saw", "saw"),
        ("a glowing mushroom", "glowing"),
        ("a coat rack with six hooks", "six hooks"),
        ("a hollow ball", "hollow"),
    ] {
        match offline(prompt) {
            Err(SynthError::Unread { phrase, .. }) => assert!(phrase.contains(words), "{prompt}: {phrase:?}"),
            other => panic!("{prompt}: {other:?}"),
        }
    }
}
