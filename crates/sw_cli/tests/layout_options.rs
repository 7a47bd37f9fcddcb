#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `--rules`, `--anomaly` and `--variations` from the command line.

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");

fn run(args: &[&str]) -> std::process::Output {
    Command::new(BIN).args(args).output().unwrap()
}

#[test]
fn anomalies_are_labelled_in_the_package_and_the_scene_still_verifies() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p");
    let o = run(&[
        "generate",
        "a lab with two tables, four bins on the tables, a cabinet and six boxes",
        "--out",
        out.to_str().unwrap(),
        "--anomaly",
        "floating,overlap",
        "--anomaly-rate",
        "0.5",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let layout: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("layout.json")).unwrap()).unwrap();
    let labels = layout["anomalies"].as_array().unwrap();
    assert!(!labels.is_empty());
    for l in labels {
        assert!(["floating", "overlap"].contains(&l["kind"].as_str().unwrap()), "{l}");
        assert!(l["magnitude"].as_f64().unwrap() > 0.0);
    }
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["status"], "verified");
    // Re-validating the package reads its labels too.
    let v = run(&["validate", out.to_str().unwrap()]);
    assert_eq!(v.status.code(), Some(0), "{}", String::from_utf8_lossy(&v.stdout));
}

#[test]
fn bad_layout_options_are_one_line_errors_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p");
    let o = out.to_str().unwrap();
    for args in [
        vec!["generate", "a table", "--out", o, "--anomaly", "explode"],
        vec!["generate", "a table", "--out", o, "--anomaly", "overlap", "--anomaly-rate", "2"],
        vec!["generate", "a table", "--out", o, "--rules", "moon_base"],
        vec!["generate", "a table", "--out", o, "--variations", "0"],
    ] {
        let r = run(&args);
        assert_eq!(r.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error: "), "{err}");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "{args:?} wrote something");
    }
}

#[test]
fn variations_write_one_package_each() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("v");
    let o = run(&[
        "generate",
        "an office with three tables, six chairs and a shelf",
        "--out",
        out.to_str().unwrap(),
        "--variations",
        "2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for k in 1..=2 {
        assert!(out.join(format!("variation_{k}/scene.xml")).is_file());
    }
    assert!(out.join("variations.json").is_file());
}
