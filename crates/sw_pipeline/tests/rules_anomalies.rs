#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue #4 through the pipeline: rules met by default and named when asked to be broken,
//! labelled anomalies, and variations.

use sw_pipeline::{Options, generate, generate_variations, structural_difference};
use sw_plan::{AnomalyKind, AnomalyRequest, Status};

const WAREHOUSE: &str = "a warehouse with four pallet racks against the north wall, twelve crates on the racks, \
                         an electrical panel, six boxes, two workbenches and a TurtleBot";

#[test]
fn a_violation_the_prompt_asks_for_is_in_the_layout_and_named() {
    let dir = tempfile::tempdir().unwrap();
    let p =
        "a workshop with an electrical panel against the north wall and a shelf right in front of the electrical panel";
    let o = generate(p, &dir.path().join("p"), &Options::default(), &mut |_| {}).unwrap();
    assert_eq!(o.report.status, Status::Verified);
    let v = o.report.violations.iter().find(|v| v.rule.starts_with("nec_working_space")).expect("named");
    assert!(v.requested && v.measured < v.required, "{v:?}");
    assert!(v.standard.starts_with("NEC 110.26"));
}

#[test]
fn by_default_no_rule_is_broken() {
    let dir = tempfile::tempdir().unwrap();
    for (i, p) in
        [WAREHOUSE, "a machine shop with two CNC machines, three shelves, an electrical panel and a workbench"]
            .iter()
            .enumerate()
    {
        for seed in 0..3 {
            let o = generate(
                p,
                &dir.path().join(format!("p{i}_{seed}")),
                &Options { seed, ..Options::default() },
                &mut |_| {},
            )
            .unwrap();
            assert!(o.report.violations.is_empty(), "{p} seed {seed}: {:#?}", o.report.violations);
        }
    }
}

#[test]
fn the_rules_profile_can_be_switched_and_an_unknown_one_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let opts = Options { rules_profile: Some("data_centre".into()), ..Options::default() };
    let o = generate("a room with a table", &dir.path().join("a"), &opts, &mut |_| {}).unwrap();
    assert_eq!(o.plan.rules_profile, "data_centre");
    let bad = Options { rules_profile: Some("moon_base".into()), ..Options::default() };
    let err = generate("a room with a table", &dir.path().join("b"), &bad, &mut |_| {}).unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert!(err.to_string().contains("unknown rules profile 'moon_base'"), "{err}");
    assert!(!dir.path().join("b").exists());
}

#[test]
fn anomalies_are_injected_with_exact_labels_and_explain_every_finding() {
    let dir = tempfile::tempdir().unwrap();
    let all = vec![
        AnomalyKind::Overlap,
        AnomalyKind::Scale,
        AnomalyKind::Misplacement,
        AnomalyKind::Floating,
        AnomalyKind::RuleViolation,
    ];
    let clean = generate(WAREHOUSE, &dir.path().join("clean"), &Options { seed: 4, ..Options::default() }, &mut |_| {})
        .unwrap();
    let opts =
        Options { seed: 4, anomaly: Some(AnomalyRequest { kinds: all.clone(), rate: 0.5 }), ..Options::default() };
    let o = generate(WAREHOUSE, &dir.path().join("anomalous"), &opts, &mut |_| {}).unwrap();
    let labels = &o.layout.anomalies;
    for k in &all {
        assert!(labels.iter().any(|l| l.kind == *k), "no {k:?} label in {labels:#?}");
    }
    let v = o.report.verification.as_ref().unwrap();
    assert_eq!(o.report.status, Status::Verified, "{:?}", v.failures);
    assert!(!v.expected.is_empty(), "anomalies were found by MuJoCo");
    for l in labels {
        assert!(l.magnitude > 0.0, "{l:?}");
        let before = clean.layout.object(&l.object).unwrap();
        let after = o.layout.object(&l.object).unwrap();
        match l.kind {
            AnomalyKind::Floating => assert!((after.pos[2] - before.pos[2] - l.magnitude).abs() < 1e-3, "{l:?}"),
            AnomalyKind::Misplacement => {
                let d = (after.pos[0] - before.pos[0]).hypot(after.pos[1] - before.pos[1]);
                assert!((d - l.magnitude).abs() < 1e-3 && d > 1.0, "{l:?} moved {d}");
            }
            AnomalyKind::Overlap => {
                // MuJoCo measures the penetration the label states.
                let with = l.with.as_ref().unwrap();
                let c = v.initial_contacts.as_ref().unwrap();
                let deep = c
                    .deep
                    .iter()
                    .find(|d| (d.body1 == l.object && &d.body2 == with) || (&d.body1 == with && d.body2 == l.object));
                let deep = deep.unwrap_or_else(|| panic!("no contact between {} and {with}: {:?}", l.object, c.deep));
                assert!((deep.depth_m - l.magnitude).abs() < 0.01, "{l:?} vs {deep:?}");
            }
            AnomalyKind::RuleViolation => {
                let with = l.with.as_ref().unwrap();
                assert!(
                    o.report.violations.iter().any(|x| x.objects.contains(with) && x.objects.contains(&l.object)),
                    "{l:?} not in {:#?}",
                    o.report.violations
                );
            }
            AnomalyKind::Scale => assert!(l.magnitude < 0.75 || l.magnitude > 1.35, "{l:?}"),
        }
    }
    // The same request and seed give the same labels.
    let again = generate(WAREHOUSE, &dir.path().join("again"), &opts, &mut |_| {}).unwrap();
    assert_eq!(&again.layout.anomalies, labels);
}

#[test]
fn variations_are_structurally_different_valid_layouts() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("vars");
    let p = "an office with four tables, eight chairs, two shelves and a cabinet";
    let all = generate_variations(p, &out, 3, &Options::default(), &mut |_| {}).unwrap();
    assert_eq!(all.len(), 3);
    for (i, o) in all.iter().enumerate() {
        assert_eq!(o.out_dir, out.join(format!("variation_{}", i + 1)));
        assert!(o.out_dir.join("scene.xml").is_file());
        assert_eq!(o.report.status, Status::Verified);
        for p in &all[..i] {
            let d = structural_difference(&p.layout, &o.layout);
            assert!(d >= 0.3, "variation {} differs from an earlier one by only {d}", i + 1);
        }
    }
    let index: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("variations.json")).unwrap()).unwrap();
    assert_eq!(index["variations"].as_array().unwrap().len(), 3);
    // No candidate directories are left behind.
    let names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().to_string()).collect();
    assert!(names.iter().all(|n| !n.starts_with('.')), "{names:?}");
}

#[test]
fn what_does_not_fit_a_fixed_room_is_shrunk_within_its_ranges_before_anything_is_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let o =
        generate("a 5 by 4 m room with 10 tables", &dir.path().join("p"), &Options::default(), &mut |_| {}).unwrap();
    assert!(o.report.left_out.is_empty(), "{:?}", o.report.left_out);
    assert!(o.report.warnings.iter().any(|w| w.code == "shrunk_to_fit"), "{:?}", o.report.warnings);
    assert_eq!(o.report.status, Status::Verified);
    // Never below the category's smallest table.
    for t in &o.layout.objects {
        assert!(t.size[0] >= 0.4 - 1e-6 && t.size[1] >= 0.4 - 1e-6, "{t:?}");
    }
}

#[test]
fn fences_around_an_arms_bench_form_a_cell_at_the_safety_distance() {
    let dir = tempfile::tempdir().unwrap();
    let p = "a workshop with a workbench, a UR5e on the workbench and four safety fences around the workbench";
    for seed in 0..3 {
        let o = generate(p, &dir.path().join(format!("p{seed}")), &Options { seed, ..Options::default() }, &mut |_| {})
            .unwrap();
        assert_eq!(o.report.status, Status::Verified);
        assert_eq!(o.layout.objects.iter().filter(|x| x.category == "safety_fence").count(), 4);
        assert!(o.report.violations.is_empty(), "seed {seed}: {:#?}", o.report.violations);
    }
    // Fences pushed inside the reach are named.
    let q = "a workshop with a UR5e on a pedestal next to a safety fence";
    let o = generate(q, &dir.path().join("close"), &Options::default(), &mut |_| {}).unwrap();
    assert_eq!(o.report.status, Status::Verified);
    for v in &o.report.violations {
        assert_eq!(v.rule, "robot_fence_distance", "{v:?}");
        assert!(v.standard.contains("ISO 13857"));
    }
}
