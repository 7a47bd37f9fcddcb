#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The whole prompt suite through the pipeline: every scene is compiled and settled in
//! MuJoCo, and must pass.

use std::path::Path;

use sw_pipeline::{Options, generate};
use sw_plan::Status;

fn suite() -> Vec<String> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/prompts.txt")).unwrap();
    text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')).map(str::to_string).collect()
}

#[test]
fn every_suite_prompt_gives_a_verified_scene() {
    let dir = tempfile::tempdir().unwrap();
    let prompts = suite();
    assert!(prompts.len() >= 40, "the suite has {} prompts", prompts.len());
    let mut failures = Vec::new();
    for (i, p) in prompts.iter().enumerate() {
        let out = dir.path().join(format!("s{i}"));
        let o = generate(p, &out, &Options { seed: i as u64, ..Options::default() }, &mut |_| {}).unwrap();
        let r = &o.report;
        let v = r.verification.as_ref().unwrap();
        let ok = r.status == Status::Verified
            && v.compiled
            && v.initial_contacts.as_ref().unwrap().deep.is_empty()
            && v.settle.as_ref().unwrap().moved.is_empty();
        if !ok {
            failures.push(format!("{p:?}: {:?} {:?}", r.status, v.failures));
        }
        // The rules are met unless the prompt asked otherwise.
        for x in r.violations.iter().filter(|x| !x.requested) {
            failures.push(format!("{p:?}: {}", x.message));
        }
        // Nothing silently dropped: placed + reported left out = requested.
        let missing: u32 = r.left_out.iter().map(|l| l.requested - l.placed).sum();
        let carriers =
            o.layout.objects.iter().filter(|x| !o.plan.objects.iter().any(|g| g.id == x.group)).count() as u32;
        assert_eq!(o.layout.objects.len() as u32 - carriers + missing, o.plan.object_count(), "{p:?}");
        assert!(
            r.warnings.iter().all(|w| w.code != "removed_after_verification"),
            "{p:?}: the layout needed a repair: {:?}",
            r.warnings
        );
        for f in ["scene.xml", "scene_only.xml", "plan.json", "layout.json", "report.json", "timings.json"] {
            assert!(out.join(f).is_file(), "{p:?}: {f} missing");
        }
    }
    assert!(failures.is_empty(), "{} of {} scenes failed:\n{}", failures.len(), prompts.len(), failures.join("\n"));
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let e = e.unwrap();
            if e.file_type().unwrap().is_dir() {
                stack.push(e.path());
            } else {
                let rel = e.path().strip_prefix(dir).unwrap().to_string_lossy().to_string();
                out.push((rel, std::fs::read(e.path()).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn the_same_prompt_and_seed_give_a_byte_identical_package() {
    let dir = tempfile::tempdir().unwrap();
    let p = "a warehouse with four pallet racks against the north wall, twelve crates on the racks, a UR5e on a pedestal and a TurtleBot";
    let a = dir.path().join("a");
    let b = dir.path().join("b");
    let c = dir.path().join("c");
    generate(p, &a, &Options { seed: 7, ..Options::default() }, &mut |_| {}).unwrap();
    generate(p, &b, &Options { seed: 7, ..Options::default() }, &mut |_| {}).unwrap();
    generate(p, &c, &Options { seed: 8, ..Options::default() }, &mut |_| {}).unwrap();
    let (fa, fb) = (files(&a), files(&b));
    let names = |f: &Vec<(String, Vec<u8>)>| f.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&fa), names(&fb));
    for ((n, x), (_, y)) in fa.iter().zip(&fb) {
        if n != "timings.json" {
            assert!(x == y, "{n} differs between two runs with the same seed");
        }
    }
    let layout = |d: &Path| std::fs::read(d.join("layout.json")).unwrap();
    assert_ne!(layout(&a), layout(&c), "a different seed should give a different layout");
}

#[test]
fn a_failed_run_leaves_nothing_behind_and_a_non_empty_out_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("pkg");
    let err = generate("   ", &out, &Options::default(), &mut |_| {}).unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "something was left behind");

    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("keep.txt"), "mine").unwrap();
    let err = generate("a table", &out, &Options::default(), &mut |_| {}).unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert!(err.to_string().contains("not empty"), "{err}");
    assert_eq!(std::fs::read_to_string(out.join("keep.txt")).unwrap(), "mine");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);

    // An existing empty directory is fine.
    let empty = dir.path().join("empty");
    std::fs::create_dir(&empty).unwrap();
    generate("a table", &empty, &Options::default(), &mut |_| {}).unwrap();
    assert!(empty.join("scene.xml").is_file());
}

#[test]
fn every_stage_reports_progress_and_a_time() {
    let dir = tempfile::tempdir().unwrap();
    let mut events = Vec::new();
    let o = generate("a lab with a table and a UR5e", &dir.path().join("p"), &Options::default(), &mut |e| {
        events.push(e.clone())
    })
    .unwrap();
    use sw_plan::Stage::*;
    for s in [Plan, Forge, Layout, Bridge, Verify] {
        assert!(
            events.iter().any(|e| matches!(e, sw_pipeline::Event::StageFinished { stage, .. } if *stage == s)),
            "{s:?}"
        );
        assert!(o.timings.get(s).is_some(), "{s:?}");
    }
}

#[test]
fn every_object_reports_its_asset_and_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let mut events = Vec::new();
    let o = generate(
        "a kitchen with a table, three mugs on the table and a TurtleBot",
        &dir.path().join("k"),
        &Options::default(),
        &mut |e| events.push(e.clone()),
    )
    .unwrap();
    use sw_pipeline::Event;
    let steps = |st: sw_plan::Stage| -> Vec<(String, String)> {
        events
            .iter()
            .filter_map(|e| match e {
                Event::Object { stage, object, step } if *stage == st => Some((object.clone(), step.clone())),
                _ => None,
            })
            .collect()
    };
    let (made, laid) = (steps(sw_plan::Stage::Forge), steps(sw_plan::Stage::Layout));
    for p in &o.layout.objects {
        assert!(made.iter().any(|(n, _)| *n == p.name), "no asset step for {}: {made:?}", p.name);
        let (_, step) =
            laid.iter().find(|(n, _)| *n == p.name).unwrap_or_else(|| panic!("{} not placed: {laid:?}", p.name));
        if p.category == "mug" {
            assert!(step.contains("on table_1"), "{step}");
        }
    }
    assert!(laid.iter().any(|(n, s)| *n == o.layout.robots[0].name && s.contains("spawned")), "{laid:?}");
    // Each object step comes inside its stage: after the stage started, before it finished.
    let pos = |f: &dyn Fn(&Event) -> bool| events.iter().position(f).unwrap();
    let forge_done = pos(&|e| matches!(e, Event::StageFinished { stage: sw_plan::Stage::Forge, .. }));
    let layout_start = pos(&|e| matches!(e, Event::StageStarted { stage: sw_plan::Stage::Layout }));
    let first_place = pos(&|e| matches!(e, Event::Object { stage: sw_plan::Stage::Layout, .. }));
    assert!(pos(&|e| matches!(e, Event::Object { stage: sw_plan::Stage::Forge, .. })) < forge_done);
    assert!(layout_start < first_place);
}

#[test]
fn a_cancelled_run_stops_at_the_next_stage_and_writes_nothing() {
    use std::sync::Arc;
    use std::sync::atomic::{AtomicBool, Ordering};
    let dir = tempfile::tempdir().unwrap();
    for stop_after in [sw_plan::Stage::Plan, sw_plan::Stage::Forge, sw_plan::Stage::Layout, sw_plan::Stage::Bridge] {
        let flag = Arc::new(AtomicBool::new(false));
        let opts = Options { cancel: Some(flag.clone()), ..Options::default() };
        let out = dir.path().join(format!("{stop_after:?}"));
        let mut started = Vec::new();
        let e = generate("a warehouse with two pallet racks and six boxes", &out, &opts, &mut |e| {
            if let sw_pipeline::Event::StageStarted { stage } = e {
                started.push(*stage);
            }
            if let sw_pipeline::Event::StageFinished { stage, .. } = e
                && *stage == stop_after
            {
                flag.store(true, Ordering::Relaxed);
            }
        })
        .unwrap_err();
        assert!(matches!(e, sw_pipeline::PipelineError::Cancelled), "{e}");
        assert_eq!(e.exit_code(), 130);
        assert_eq!(started.last(), Some(&stop_after), "no stage after a cancel: {started:?}");
        assert!(!out.exists(), "a cancelled run wrote {}", out.display());
        let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().flatten().map(|e| e.file_name()).collect();
        assert!(leftovers.is_empty(), "staging left behind: {leftovers:?}");
    }
}
