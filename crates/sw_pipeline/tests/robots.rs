#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Every registered robot merged into a scene: the built-ins, the robot packs (which
//! `scripts/setup.sh --tests` fetches; these tests fail, never skip, without them) and a
//! user directory with an MJCF robot in degrees and a URDF robot. Each scene compiles in
//! MuJoCo 3.17 in-process and in the official MuJoCo 4.0 Python bindings, has no contact
//! deeper than 1 mm at spawn, and every robot holds its home pose under its own actuators
//! for 2 s (joint drift < 0.05 rad). The registered keep-out boxes contain the robots.

use std::path::{Path, PathBuf};

use sw_pipeline::{Options, generate};

fn user_robots() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../sw_robots/tests/assets/user_robots")
}

fn setup() {
    sw_robots::configure(sw_robots::Config { packs_dir: None, user_dirs: vec![user_robots()] });
    for pack in &sw_robots::status().packs {
        assert!(
            pack.present,
            "the {} robot pack is missing from {}: run scripts/setup.sh --tests (the tests merge every pack robot)",
            pack.name,
            pack.dir.display()
        );
    }
}

fn python() -> PathBuf {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.cache/venv/bin/python");
    assert!(p.exists(), "run scripts/setup.sh --tests: the tests load scenes with MuJoCo 4.0's Python bindings");
    p
}

/// Loads scenes with the official bindings; returns each one's body count or the error.
fn load_in_mujoco4(scenes: &[PathBuf]) {
    let script = "import sys, mujoco\nfor p in sys.argv[1:]:\n    m = mujoco.MjModel.from_xml_path(p)\n    d = mujoco.MjData(m)\n    mujoco.mj_resetDataKeyframe(m, d, m.key('home').id)\n    mujoco.mj_forward(m, d)\n";
    let out = std::process::Command::new(python()).arg("-c").arg(script).args(scenes).output().unwrap();
    assert!(out.status.success(), "MuJoCo 4.0 rejected a scene: {}", String::from_utf8_lossy(&out.stderr));
}

/// Generates "a lab with N workbenches" with these robots and checks every target.
fn generate_with(robots: &[&str], benches: u32, dir: &Path) -> PathBuf {
    let out = dir.join(robots.join("+"));
    let opts = Options { robots: Some(robots.iter().map(|r| r.to_string()).collect()), ..Options::default() };
    let prompt = format!("a lab with {benches} workbenches");
    let o = generate(&prompt, &out, &opts, &mut |_| {}).unwrap_or_else(|e| panic!("{robots:?}: {e}"));
    let v = o.report.verification.as_ref().unwrap();
    assert!(v.compiled, "{robots:?}: {:?}", v.compile_error);
    assert!(v.passed, "{robots:?}: {:?}", v.failures);
    assert_eq!(o.layout.robots.len(), robots.len(), "{robots:?}: {:?}", o.report.warnings);
    assert_eq!(v.robots.len(), robots.len());
    for r in &v.robots {
        assert_eq!(r.spawn_contacts, 0, "{}: contact at spawn", r.name);
        assert!(r.max_joint_drift < 0.05, "{}: drift {} rad in 2 s", r.name, r.max_joint_drift);
    }
    // Every file a robot references was copied into the package.
    let scene = std::fs::read_to_string(o.out_dir.join("scene.xml")).unwrap();
    let doc = sw_mjcf::xml::Element::parse(&scene).unwrap();
    doc.walk(&mut |e| {
        if (e.name == "mesh" || e.name == "texture")
            && let Some(f) = e.get("file")
        {
            assert!(o.out_dir.join("assets").join(f).is_file(), "{robots:?}: {f} not in the package");
        }
    });
    o.out_dir.join("scene.xml")
}

#[test]
fn every_registered_robot_merges_into_a_scene_that_holds_still() {
    setup();
    let names: Vec<&'static str> = sw_robots::registry().iter().map(|r| r.name).collect();
    // Packs and the user directory really are in the list.
    for expected in ["robosuite_panda", "robosuite_omron", "menagerie_ur5e_2f85", "degree_arm", "two_link"] {
        assert!(names.contains(&expected), "{expected} is not registered: {names:?}");
    }
    let dir = tempfile::tempdir().unwrap();
    let scenes: Vec<PathBuf> = std::thread::scope(|s| {
        let chunks: Vec<Vec<&'static str>> =
            [0, 1].iter().map(|k| names.iter().skip(*k).step_by(2).copied().collect()).collect();
        let handles: Vec<_> = chunks
            .into_iter()
            .map(|chunk| {
                let dir = dir.path();
                s.spawn(move || chunk.iter().map(|r| generate_with(&[r], 1, dir)).collect::<Vec<_>>())
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(scenes.len(), names.len());
    load_in_mujoco4(&scenes);
}

#[test]
fn several_robots_share_one_scene() {
    setup();
    let dir = tempfile::tempdir().unwrap();
    let robots =
        ["panda", "ur10e", "robosuite_panda", "menagerie_ur5e_2f85", "mobile_manipulator", "robosuite_panda_omron"];
    let scene = generate_with(&robots, 4, dir.path());
    load_in_mujoco4(&[scene]);
    // Two of the same model: names stay apart, files are copied once.
    let scene = generate_with(&["robosuite_iiwa", "robosuite_iiwa"], 2, dir.path());
    let text = std::fs::read_to_string(&scene).unwrap();
    assert!(text.contains("robosuite_iiwa_1_joint_1") && text.contains("robosuite_iiwa_2_joint_1"));
}

/// The registered keep-out boxes contain every body's collision geometry at home, as
/// measured in MuJoCo 3.17 (they were measured with MuJoCo 4.0's bindings).
#[test]
fn keepout_boxes_contain_the_robot_at_home() {
    setup();
    let dir = tempfile::tempdir().unwrap();
    for r in sw_robots::registry().iter().filter(|r| r.measured) {
        let path = dir.path().join(format!("{}.xml", r.name));
        std::fs::write(&path, sw_mjcf::robot_document(&r.model().unwrap(), "m").unwrap()).unwrap();
        let bodies = sw_sim::measure_robot(&path).unwrap();
        let tol = 0.003;
        for b in bodies.iter().filter(|b| (0..3).all(|i| b.min[i] <= b.max[i])) {
            let inside =
                r.keepout.iter().any(|(lo, hi)| (0..3).all(|i| b.min[i] >= lo[i] - tol && b.max[i] <= hi[i] + tol));
            assert!(
                inside,
                "{}: body {} ({:?} .. {:?}) is outside every keep-out box {:?}",
                r.name, b.name, b.min, b.max, r.keepout
            );
        }
        let top = bodies.iter().filter(|b| b.max[2].is_finite()).map(|b| b.max[2]).fold(0.0, f64::max);
        assert!(r.height + tol >= top, "{}: height {} below the robot's top {top}", r.name, r.height);
    }
}

#[test]
fn a_user_robot_is_measured_when_first_used() {
    setup();
    let def = sw_robots::find("degree_arm").unwrap();
    assert!(!def.measured);
    let f = sw_pipeline::measure_robot(def).unwrap();
    assert!(f.height > 0.5 && f.height < 0.7, "{f:?}");
    assert!(f.reach > 0.3 && f.reach < 0.6, "{f:?}");
}
