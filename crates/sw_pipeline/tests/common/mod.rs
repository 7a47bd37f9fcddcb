//! Placements from hand-built plans, shared by the placement suites: a plan is written,
//! verified (compiled and settled) in MuJoCo over several seeds and judged by the
//! independent judge (`bench/relations/judge.py`, reading the written `scene.xml` only).

#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde_json::{Value, json};
use sw_pipeline::{Options, generate_from_plan};
use sw_plan::{ScenePlan, Status};

pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A plan: room kind and size (fixed), groups (id, category, count), relations, robots.
pub fn plan(room: &str, size: [f64; 3], groups: &[(&str, &str, u32)], relations: Value, robots: Value) -> ScenePlan {
    let objects: Vec<Value> = groups
        .iter()
        .map(|(id, cat, n)| json!({"id": id, "category": cat, "phrase": id.replace('_', " "), "count": n}))
        .collect();
    let v = json!({
        "schema_version": sw_plan::SCHEMA_VERSION,
        "prompt": "a hand-built plan",
        "room": {"kind": room, "size": {"width": size[0], "depth": size[1], "height": size[2]}, "size_fixed": true, "door": "south"},
        "objects": objects,
        "relations": relations,
        "robots": robots,
        "rules_profile": "general",
        "understanding": {"not_understood": [], "approximated": []}
    });
    serde_json::from_value(v).unwrap()
}

/// The judge's verdicts on (package, line) pairs.
pub fn judge(cases: &[(PathBuf, Value)]) -> Vec<Value> {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("batch.jsonl");
    let text: Vec<String> =
        cases.iter().map(|(p, l)| json!({"package": p.to_string_lossy(), "line": l}).to_string()).collect();
    std::fs::write(&batch, text.join("\n")).unwrap();
    let py = root().join(".cache/venv/bin/python");
    assert!(py.is_file(), "the judge's venv is missing at {}: run scripts/setup.sh --tests", py.display());
    let out = Command::new(py)
        .arg(root().join("bench/relations/judge.py"))
        .arg("--batch")
        .arg(&batch)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert!(out.status.success(), "judge failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

/// What a suite expects of the report beside the judge's verdicts.
#[derive(Debug, Default, Clone, Copy)]
pub struct Expect<'a> {
    /// Relations whose phrase names one of these may be unmet in the report (the scene
    /// cannot hold them and says so in a warning).
    pub unmet: &'a [&'a str],
    /// Warning codes every report must carry.
    pub warns: &'a [&'a str],
    /// The report's size checks and the judge's room verdict must hold too.
    pub sizes_and_room: bool,
}

/// Generates `plan` on seeds 1, 2 and 3 and judges each package against `line`; the
/// report's own relation checks must hold too (nothing unmet, no warning required). Panics
/// with every failure. `keep_env` as for [`run`].
pub fn assert_holds_on_three_seeds(name: &str, plan: &ScenePlan, line: &Value, keep_env: &str) {
    let f = run(name, plan, line, &[1, 2, 3], keep_env, Expect { unmet: &[], warns: &[], sizes_and_room: false });
    assert!(f.is_empty(), "{} failures:\n{}", f.len(), f.join("\n"));
}

/// Generates `plan` on `seeds` (each verified in MuJoCo), judges each package against
/// `line` and checks the report's own verdicts; returns the failures. `KEEP_ENV=DIR` (the
/// variable a suite names) keeps the packages there, to render and look at them.
pub fn run(
    name: &str,
    plan: &ScenePlan,
    line: &Value,
    seeds: &[u64],
    keep_env: &str,
    expect: Expect<'_>,
) -> Vec<String> {
    let dir = tempfile::tempdir().unwrap();
    let keep = std::env::var_os(keep_env).map(PathBuf::from);
    let base = keep.as_deref().unwrap_or(dir.path());
    let mut cases = Vec::new();
    let mut failures = Vec::new();
    for &seed in seeds {
        let pkg = base.join(format!("{name}-{seed}"));
        let _ = std::fs::remove_dir_all(&pkg);
        let o = generate_from_plan(plan.clone(), &pkg, &Options { seed, ..Options::default() }, &mut |_| {}).unwrap();
        let v = o.report.verification.as_ref().unwrap();
        if o.report.status != Status::Verified {
            failures.push(format!("{name} seed {seed}: not verified: {:?}", v.failures));
        }
        for c in o.report.relations.iter().filter(|c| !c.held) {
            if !expect.unmet.iter().any(|u| c.phrase.contains(u)) {
                failures.push(format!("{name} seed {seed}: the report: {} not held: {:?}", c.phrase, c.reason));
            }
        }
        if expect.sizes_and_room {
            for c in o.report.sizes.iter().filter(|c| !c.held) {
                failures.push(format!("{name} seed {seed}: the report: size of {} not kept: {:?}", c.phrase, c.reason));
            }
        }
        for w in expect.warns {
            if !o.report.warnings.iter().any(|x| x.code == *w) {
                failures.push(format!("{name} seed {seed}: no {w} warning in {:?}", o.report.warnings));
            }
        }
        if !o.report.left_out.is_empty() {
            failures.push(format!("{name} seed {seed}: left out {:?}", o.report.left_out));
        }
        cases.push((pkg, line.clone()));
    }
    for ((pkg, _), v) in cases.iter().zip(judge(&cases)) {
        let id = pkg.file_name().unwrap().to_string_lossy().to_string();
        if let Some(e) = v.get("error") {
            failures.push(format!("{id}: judge error {e}"));
            continue;
        }
        if v["counts"]["held"] != true {
            failures.push(format!("{id}: counts {}", v["counts"]));
        }
        for r in v["relations"].as_array().unwrap() {
            if r["held"] != true {
                failures.push(format!(
                    "{id}: judge: {} {} {}: {} {}",
                    r["subject"], r["relation"], r["target"], r["why"], r["measured"]
                ));
            }
        }
        if expect.sizes_and_room && v.get("room").is_some_and(|r| r["held"] != true) {
            failures.push(format!("{id}: room {}", v["room"]));
        }
    }
    failures
}
