#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The verifier against small hand-written scenes whose outcome is known.

use std::path::PathBuf;

use sw_sim::{VerifyOptions, render_scene, verify_file};

fn scene(dir: &tempfile::TempDir, body: &str) -> PathBuf {
    let xml = format!(
        r#"<mujoco><compiler angle="radian"/><option timestep="0.002"/>
        <worldbody><geom name="floor" type="plane" size="5 5 0.1"/>{body}</worldbody></mujoco>"#
    );
    let path = dir.path().join("scene.xml");
    std::fs::write(&path, xml).unwrap();
    path
}

#[test]
fn a_box_resting_on_the_floor_passes() {
    let dir = tempfile::tempdir().unwrap();
    let path =
        scene(&dir, r#"<body name="box_1" pos="0 0 0.1"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>"#);
    let v = verify_file(&path, &VerifyOptions::default());
    assert!(v.passed, "{:?}", v.failures);
    assert!(v.compiled);
    assert_eq!(v.model.as_ref().unwrap().free_bodies, 1);
    let s = v.settle.unwrap();
    assert!(s.max_displacement_m < 0.001, "{s:?}");
    assert_eq!(s.worst_body.as_deref(), Some("box_1"));
}

#[test]
fn interpenetrating_bodies_are_named_with_their_depth() {
    let dir = tempfile::tempdir().unwrap();
    let path = scene(
        &dir,
        r#"<body name="shelf_1" pos="0 0 0.5"><geom type="box" size="0.5 0.2 0.5"/></body>
           <body name="box_1" pos="0.45 0 0.3"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>"#,
    );
    let v = verify_file(&path, &VerifyOptions::default());
    assert!(!v.passed);
    let c = v.initial_contacts.unwrap();
    let deep = &c.deep[0];
    assert_eq!((deep.body1.as_str(), deep.body2.as_str()), ("box_1", "shelf_1"));
    assert!((deep.depth_m - 0.15).abs() < 0.01, "{deep:?}");
    assert!(v.failures[0].contains("box_1–shelf_1"), "{:?}", v.failures);
}

#[test]
fn a_floating_box_falls_and_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    let path =
        scene(&dir, r#"<body name="box_1" pos="0 0 1"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>"#);
    let v = verify_file(&path, &VerifyOptions::default());
    assert!(!v.passed);
    let s = v.settle.unwrap();
    assert_eq!(s.moved.len(), 1);
    assert!((s.moved[0].displacement_m - 0.9).abs() < 0.01, "{s:?}");
}

#[test]
fn a_broken_file_is_a_compile_error_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.xml");
    std::fs::write(&path, "<mujoco><worldbody><geom type='box'/></worldbody>").unwrap();
    let v = verify_file(&path, &VerifyOptions::default());
    assert!(!v.compiled && !v.passed);
    assert!(v.compile_error.is_some());
    let missing = verify_file(&dir.path().join("nope.xml"), &VerifyOptions::default());
    assert!(!missing.compiled);
}

#[test]
fn the_home_keyframe_is_the_state_checked_and_robot_drift_is_measured() {
    let dir = tempfile::tempdir().unwrap();
    // The hinge starts at 0 (arm down into the floor would be bad); home lifts it and the
    // position servo holds it there.
    let path = scene(
        &dir,
        r#"<body name="arm_1_base" pos="0 0 0.5"><joint name="arm_1_j" type="hinge" axis="0 1 0" range="-3 3" damping="1"/>
             <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/></body>
           </worldbody><actuator><position name="arm_1_a" joint="arm_1_j" kp="200" kv="10"/></actuator>
           <keyframe><key name="home" qpos="-0.5" ctrl="-0.5"/></keyframe><worldbody>"#,
    );
    let v = verify_file(&path, &VerifyOptions { robots: vec!["arm_1".into()], ..Default::default() });
    assert_eq!(v.initial_state, "keyframe 'home'");
    let r = &v.robots[0];
    assert_eq!(r.name, "arm_1");
    // Gravity sags a 1 kg link on a kp=200 servo by a few hundredths of a radian.
    assert!(r.max_joint_drift > 0.001 && r.max_joint_drift < 0.05, "{r:?}");
}

#[test]
fn a_scene_renders_to_an_image_with_the_objects_in_it() {
    let dir = tempfile::tempdir().unwrap();
    let path = scene(
        &dir,
        r#"<body name="box_1" pos="0 0 0.25"><geom type="box" size="0.25 0.25 0.25" rgba="1 0 0 1" group="2"/></body>"#,
    );
    let img = render_scene(&path, 200, 150, &[2]).unwrap();
    let red = img.rgb.chunks(3).filter(|p| p[0] > 120 && p[1] < 40 && p[2] < 40).count();
    assert!(red > 500, "the red box covers {red} pixels");
}

/// The fast load (built-in textures compiled at 8 × 8) gives the verdict MuJoCo's own
/// `from_xml` gives, to the last figure: a passing scene with textures, materials and a
/// mesh, a failing one, and a rejected one (MuJoCo's message word for word).
#[test]
fn the_fast_load_changes_no_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let textured = |body: &str| {
        format!(
            r#"<mujoco><compiler angle="radian"/><option timestep="0.002"/>
            <asset>
              <texture name="grid" type="2d" builtin="checker" rgb1="0.2 0.3 0.4" rgb2="0.1 0.2 0.3" width="512" height="512"/>
              <texture name="sky" type="skybox" builtin="gradient" rgb1="0.3 0.5 0.7" rgb2="0 0 0" width="256" height="256"/>
              <texture name="wood" type="cube" builtin="flat" rgb1="0.6 0.4 0.2" width="64" height="64" mark="random" random="0.1"/>
              <material name="grid" texture="grid" texrepeat="2 2" reflectance="0.2"/>
              <material name="wood" texture="wood"/>
              <mesh name="wedge" vertex="0 0 0  0.2 0 0  0 0.2 0  0 0 0.2"/>
            </asset>
            <worldbody><geom name="floor" type="plane" size="5 5 0.1" material="grid"/>{body}</worldbody></mujoco>"#
        )
    };
    let cases = [
        r#"<body name="box_1" pos="0 0 0.1"><freejoint/><geom type="box" size="0.1 0.1 0.1" material="wood"/></body>
           <body name="wedge_1" pos="1 0 0"><freejoint/><geom type="mesh" mesh="wedge" material="wood"/></body>
           <body name="mug_1" pos="-1 0 0.05"><freejoint/><geom type="cylinder" size="0.04 0.05"/></body>"#,
        r#"<body name="shelf_1" pos="0 0 0.5"><geom type="box" size="0.5 0.2 0.5" material="wood"/></body>
           <body name="box_1" pos="0.45 0 0.3"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>
           <body name="ball_1" pos="2 0 1"><freejoint/><geom type="sphere" size="0.1"/></body>"#,
        r#"<body name="box_1"><geom type="box" size="0.1 0.1 0.1" material="no_such_material"/></body>"#,
    ];
    let opts = VerifyOptions::default();
    let mut verdicts = Vec::new();
    for (i, body) in cases.iter().enumerate() {
        let path = dir.path().join(format!("scene_{i}.xml"));
        std::fs::write(&path, textured(body)).unwrap();
        let fast = verify_file(&path, &opts);
        let full = sw_sim::verify_file_full_load(&path, &opts);
        assert_eq!(fast, full, "scene {i}");
        verdicts.push((fast.compiled, fast.passed));
    }
    // The three cases are what they are meant to be, so the comparison covers each path.
    assert_eq!(verdicts, [(true, true), (true, false), (false, false)]);
}
