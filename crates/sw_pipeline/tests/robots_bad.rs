#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Bad robot input through the pipeline: a broken file, a name clash, a missing mesh, a
//! dangling reference, a URDF with an unknown tag. Each is bad input (exit code 2) with a
//! message that names the file and the element, and nothing is written.

use std::path::{Path, PathBuf};

use sw_pipeline::{Options, PipelineError, generate};

fn setup() {
    let bad = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sw_robots/tests/assets/bad_robots");
    sw_robots::configure(sw_robots::Config { packs_dir: None, user_dirs: vec![bad] });
}

fn run(robot: &str) -> (Result<sw_pipeline::Outcome, PipelineError>, PathBuf, tempfile::TempDir) {
    setup();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("pkg");
    let opts = Options { robots: Some(vec![robot.to_string()]), ..Options::default() };
    (generate("a lab with a workbench", &out, &opts, &mut |_| {}), out, dir)
}

fn input_error(robot: &str) -> String {
    let (r, out, _dir) = run(robot);
    let e = r.err().unwrap_or_else(|| panic!("{robot}: expected an error"));
    assert_eq!(e.exit_code(), 2, "{robot}: {e}");
    assert!(!out.exists(), "{robot}: a package was written");
    let parent: Vec<_> = std::fs::read_dir(out.parent().unwrap()).unwrap().collect();
    assert!(parent.is_empty(), "{robot}: staging left behind");
    e.to_string()
}

#[test]
fn a_missing_mesh_names_the_element_and_the_file() {
    let e = input_error("missing_mesh");
    assert!(e.contains("<mesh name=\"hull\" file=\"not_there.stl\"> in "), "{e}");
    assert!(e.contains("bad_robots/missing_mesh.xml"), "{e}");
    assert!(e.contains("the file it references is missing: ") && e.ends_with("bad_robots/meshes/not_there.stl"), "{e}");
}

#[test]
fn a_broken_file_is_named_with_its_position() {
    let e = input_error("broken");
    assert!(e.contains("robot 'broken' could not be registered"), "{e}");
    assert!(e.contains("bad_robots/broken.xml: not valid XML at line 6, column 3"), "{e}");
}

#[test]
fn a_dangling_reference_and_an_unknown_urdf_tag_are_named() {
    let e = input_error("bad_reference");
    assert!(e.contains("bad_reference.xml: <geom> (material=\"chrome\") refers to 'chrome'"), "{e}");
    let e = input_error("unknown_tag");
    assert!(e.contains("unknown_tag.urdf: <camera>: is not a URDF element scenewright knows"), "{e}");
}

#[test]
fn a_name_clash_keeps_the_registered_robot() {
    let (r, _out, _dir) = run("ur5e");
    let o = r.unwrap();
    assert!(o.report.verification.unwrap().passed);
    assert!(
        sw_robots::status().problems.iter().any(|p| p.to_string().contains("robot name 'ur5e' is already taken")),
        "the clash is reported"
    );
}
