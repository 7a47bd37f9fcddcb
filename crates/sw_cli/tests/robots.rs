#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `scenewright robots …` and robot input through the CLI: packs listed or how to fetch
//! them, licences shown, user directories, bad robot files as one-line input errors.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");

fn run(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(BIN);
    c.args(args).env_remove("SCENEWRIGHT_LOG").env_remove("SCENEWRIGHT_ROBOTS").stdin(Stdio::null());
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("cannot run the scenewright binary")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../sw_robots/tests/assets")
}

#[test]
fn absent_packs_are_listed_with_how_to_fetch_them() {
    let env = [("SCENEWRIGHT_ROBOT_PACKS", "/nonexistent/robot-packs")];
    let out = run(&["robots", "list"], &env);
    assert_eq!(out.status.code(), Some(0));
    let stdout = text(&out.stdout);
    assert!(stdout.contains("pack robosuite 1.5.2: not installed"), "{stdout}");
    assert!(stdout.contains("run `scripts/setup.sh --robots` to fetch it"), "{stdout}");
    assert!(!stdout.contains("robosuite_panda "), "an absent pack's robots are not listed: {stdout}");
    let out = run(&["robots", "show", "robosuite_iiwa"], &env);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(err.contains("comes from the robosuite 1.5.2 pack, which is not installed"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn a_pack_robot_shows_its_licence_and_loads_alone() {
    let out = run(&["robots", "show", "robosuite_panda"], &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let s = text(&out.stdout);
    assert!(s.contains("licence: MIT (") && s.contains("robosuite-1.5.2/LICENSE"), "{s}");
    assert!(s.contains("torque motors became joint position servos"), "{s}");
    let out = run(&["robots", "show", "menagerie_ur5e_2f85", "--json"], &[]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let files = v["licence_files"].as_array().unwrap();
    assert!(files.iter().any(|f| f.as_str().unwrap().ends_with("robotiq_2f85/LICENSE")), "{v}");
    // `--mjcf` is the robot alone, loadable as is.
    let out = run(&["robots", "show", "kinova_gen3", "--mjcf"], &[]);
    assert!(text(&out.stdout).contains("<key name=\"home\""));
}

#[test]
fn bad_robot_files_are_one_line_input_errors() {
    let bad = assets().join("bad_robots");
    let tmp = tempfile::tempdir().unwrap();
    let pkg = tmp.path().join("pkg");
    let args = ["--robots-dir", bad.to_str().unwrap(), "generate", "a lab with a workbench", "--robot", "missing_mesh"];
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--out", pkg.to_str().unwrap()]);
    let out = run(&all, &[]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    let err = text(&out.stderr);
    assert_eq!(err.lines().filter(|l| l.starts_with("error:")).count(), 1, "{err}");
    assert!(err.contains("<mesh name=\"hull\" file=\"not_there.stl\">") && err.contains("missing_mesh.xml"), "{err}");
    assert!(!pkg.exists());
    // `robots list` names the files it could not register, and still lists the rest.
    let out = run(&["--robots-dir", bad.to_str().unwrap(), "robots", "list"], &[]);
    assert_eq!(out.status.code(), Some(0));
    let err = text(&out.stderr);
    assert!(err.contains("broken.xml: not valid XML at line 6"), "{err}");
    assert!(err.contains("robot name 'ur5e' is already taken"), "{err}");
    assert!(text(&out.stdout).contains("missing_mesh"));
}

#[test]
fn a_user_directory_from_the_environment_is_used_by_generate() {
    let tmp = tempfile::tempdir().unwrap();
    let pkg = tmp.path().join("pkg");
    let dir = assets().join("user_robots");
    let out = run(
        &["generate", "a lab with a workbench", "--robot", "two_link", "--out", pkg.to_str().unwrap(), "--json"],
        &[("SCENEWRIGHT_ROBOTS", dir.to_str().unwrap())],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(pkg.join("assets/robots/two_link/ext/two_link_description/meshes/link.stl").is_file());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["report"]["verification"]["passed"], true, "{v}");
}

#[test]
fn the_merge_benchmark_times_every_robot() {
    let out = run(&["robots", "bench", "--repeat", "2", "--json"], &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let rows = rows.as_array().unwrap();
    assert!(rows.len() >= 17, "{rows:?}");
    assert!(rows.iter().all(|r| r["merge_ms_p50"].as_f64().is_some_and(|t| t > 0.0)));
}
