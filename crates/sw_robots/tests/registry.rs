#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The registry: built-ins, aliases, user directories (MJCF with includes and degrees,
//! URDF with `package://` meshes) and the problems of bad files, which name the file.
//!
//! The registry is built once per process, so every test here configures the same two
//! fixture directories.

use std::path::{Path, PathBuf};

use sw_geom::Pose;
use sw_robots::{Origin, RobotError, RobotKind};

fn assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/assets")
}

fn setup() -> &'static sw_robots::Registry {
    sw_robots::configure(sw_robots::Config {
        packs_dir: None,
        user_dirs: vec![assets().join("user_robots"), assets().join("bad_robots")],
    });
    sw_robots::status()
}

#[test]
fn built_ins_are_registered_with_their_facts() {
    setup();
    for name in ["ur5e", "ur10e", "panda", "kinova_gen3", "turtlebot3", "mobile_manipulator"] {
        let r = sw_robots::find(name).unwrap_or_else(|| panic!("{name} is built in"));
        assert_eq!(r.origin, Origin::BuiltIn);
        assert!(r.measured && !r.keepout.is_empty() && r.height > 0.0, "{name}");
        if r.kind == RobotKind::Arm {
            assert!(r.reach > 0.5, "{name} reach");
        }
        // Every built-in merges, and every actuator has a home control.
        let model = r.model().unwrap();
        let p = sw_mjcf::prepare_robot(&model, name, &Pose::IDENTITY).unwrap();
        assert_eq!(p.home_ctrl.len(), p.sections.get("actuator").map_or(0, Vec::len));
        assert!(p.files.is_empty(), "built-ins reference no files");
    }
    // The planner's names find the models.
    assert_eq!(sw_robots::find("Franka").unwrap().name, "panda");
    assert_eq!(sw_robots::find("gen3").unwrap().name, "kinova_gen3");
    assert_eq!(sw_robots::default_of(RobotKind::MobileManipulator).name, "mobile_manipulator");
    assert_eq!(sw_robots::find("mobile_manipulator").unwrap().kind, RobotKind::MobileManipulator);
}

#[test]
fn a_user_directory_registers_its_robots() {
    let s = setup();
    let arm = sw_robots::find("degree_arm").expect("MJCF robot registered by file name");
    assert!(matches!(&arm.origin, Origin::User { file } if file.ends_with("degree_arm/degree_arm.xml")));
    assert!(!arm.measured, "user robots are measured when used");
    assert_eq!(arm.kind, RobotKind::Arm);
    let model = arm.model().unwrap();
    assert_eq!(model.parts[0].includes.len(), 1, "the included defaults are read");
    let p = sw_mjcf::prepare_robot(&model, "degree_arm_1", &Pose::IDENTITY).unwrap();
    assert_eq!(p.files.len(), 1);
    assert!(p.files[0].source.ends_with("degree_arm/meshes/link.stl"));
    assert_eq!(p.files[0].dest, "robots/degree_arm/meshes/link.stl");
    assert!(p.files[0].source.is_file());

    let urdf = sw_robots::find("two_link").expect("URDF robot registered from <pkg>/urdf/");
    let p = sw_mjcf::prepare_robot(&urdf.model().unwrap(), "two_link_1", &Pose::IDENTITY).unwrap();
    assert!(p.files[0].source.ends_with("two_link_description/meshes/link.stl"), "{:?}", p.files);
    assert!(p.files[0].source.is_file(), "package:// resolved to the package directory");
    assert!(p.notes.iter().any(|n| n.contains("servos")), "{:?}", p.notes);

    // Included files, ROS package.xml and demo scenes are not robots.
    for not_robot in ["degree_arm_defaults", "package"] {
        assert!(sw_robots::find(not_robot).is_none(), "{not_robot} registered");
    }
    assert!(s.robots.iter().all(|r| r.name != "broken"));
}

#[test]
fn bad_files_are_problems_that_name_the_file() {
    let s = setup();
    let messages: Vec<String> = s.problems.iter().map(ToString::to_string).collect();
    let broken = messages.iter().find(|m| m.contains("broken.xml")).expect("broken.xml reported");
    assert!(broken.contains("not valid XML at line 6, column 3"), "{broken}");
    let clash = s
        .problems
        .iter()
        .find(|p| matches!(p, RobotError::NameClash { .. }))
        .expect("the ur5e.xml name clash is reported");
    let text = clash.to_string();
    assert!(text.contains("bad_robots/ur5e.xml: robot name 'ur5e' is already taken by the built-in"), "{text}");
    assert_eq!(sw_robots::find("ur5e").unwrap().origin, Origin::BuiltIn, "the built-in keeps its name");
    assert_eq!(sw_robots::why_missing("ur5e"), None);

    // Registered, but broken when read: the error names the file and the element.
    let e = sw_robots::find("unknown_tag").unwrap().model().unwrap_err().to_string();
    assert!(e.ends_with("bad_robots/unknown_tag.urdf: <camera>: is not a URDF element scenewright knows"), "{e}");
    let model = sw_robots::find("bad_reference").unwrap().model().unwrap();
    let e = sw_mjcf::prepare_robot(&model, "b", &Pose::IDENTITY).unwrap_err().to_string();
    assert!(
        e.ends_with(
            "bad_reference.xml: <geom> (material=\"chrome\") refers to 'chrome' that the robot does not define"
        ),
        "{e}"
    );
    // A missing mesh is known before anything is copied: the merge lists the file.
    let model = sw_robots::find("missing_mesh").unwrap().model().unwrap();
    let p = sw_mjcf::prepare_robot(&model, "m", &Pose::IDENTITY).unwrap();
    assert!(!p.files[0].source.exists());
    assert!(
        p.files[0].element.starts_with("<mesh name=\"hull\" file=\"not_there.stl\"> in "),
        "{}",
        p.files[0].element
    );
}
