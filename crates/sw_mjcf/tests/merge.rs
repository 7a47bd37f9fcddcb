#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The robot merger on small documents: prefixing, parts, includes, angle units, files,
//! fixes, home state, URDF import, and errors that name the file and the element.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use sw_geom::Pose;
use sw_mjcf::xml::Element;
use sw_mjcf::{PartFixes, RobotPart, RobotSource, ServoGains, prepare_robot, robot_document, urdf_to_mjcf};

const ROBOT: &str = r#"<mujoco model="r">
  <compiler angle="radian"/>
  <default><joint damping="1"/><default class="big"><geom size="0.1"/></default></default>
  <asset><material name="m" rgba="1 0 0 1"/><mesh file="meshes/link.stl"/></asset>
  <worldbody>
    <body name="base" pos="0 0 0.1">
      <geom class="big" material="m" type="mesh" mesh="link"/>
      <body name="l1"><joint name="j1"/><geom size="0.05"/></body>
      <body name="l2"><joint/><geom size="0.05"/></body>
    </body>
  </worldbody>
  <contact><exclude body1="base" body2="l1"/></contact>
  <equality><joint name="couple" joint1="j1" joint2="unnamed_joint0"/></equality>
  <actuator><position name="a1" joint="j1"/></actuator>
  <keyframe><key name="home" qpos="0.5 -0.25" ctrl="0.5"/></keyframe>
</mujoco>"#;

fn source(mjcf: &str) -> RobotSource {
    RobotSource::single("r", "r.xml", mjcf)
}

fn with_dir(mut s: RobotSource, dir: &str) -> RobotSource {
    s.parts[0].dir = Some(PathBuf::from(dir));
    s
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../sw_robots/tests/assets")
}

#[test]
fn everything_is_prefixed_and_references_follow() {
    let r = prepare_robot(&with_dir(source(ROBOT), "/robots/r"), "arm_1", &Pose::from_pos_yaw([1.0, 2.0, 0.75], 0.0))
        .unwrap();
    let body = &r.bodies[0];
    assert_eq!(body.get("name"), Some("arm_1_base"));
    assert_eq!(body.get("pos"), Some("1 2 0.85"));
    assert_eq!(body.get("childclass"), Some("arm_1_main"));
    let geom = &body.children[0];
    assert_eq!(geom.get("class"), Some("arm_1_big"));
    assert_eq!(geom.get("material"), Some("arm_1_m"));
    assert_eq!(geom.get("mesh"), Some("arm_1_link"));
    assert_eq!(r.assets[1].get("name"), Some("arm_1_link"));
    assert_eq!(r.assets[1].get("file"), Some("robots/r/meshes/link.stl"));
    assert_eq!(r.files.len(), 1);
    assert_eq!(r.files[0].source, PathBuf::from("/robots/r/meshes/link.stl"));
    assert_eq!(r.files[0].element, "<mesh name=\"link\" file=\"meshes/link.stl\"> in r.xml");
    let exclude = &r.sections["contact"][0];
    assert_eq!(exclude.get("body1"), Some("arm_1_base"));
    assert_eq!(exclude.get("class"), None, "exclude takes no class");
    // An equality named like a joint is no clash (its own namespace); it follows renames.
    let eq = &r.sections["equality"][0];
    assert_eq!((eq.get("joint1"), eq.get("joint2")), (Some("arm_1_j1"), Some("arm_1_unnamed_joint0")));
    let act = &r.sections["actuator"][0];
    assert_eq!(
        (act.get("name"), act.get("joint"), act.get("class")),
        (Some("arm_1_a1"), Some("arm_1_j1"), Some("arm_1_main"))
    );
    assert_eq!(r.home_qpos["arm_1_j1"], vec![0.5]);
    assert_eq!(r.home_qpos["arm_1_unnamed_joint0"], vec![-0.25]);
    assert_eq!(r.home_ctrl, vec![0.5]);
    assert_eq!(r.defaults[0].get("class"), Some("arm_1_main"));
}

#[test]
fn degrees_become_radians_where_mujoco_converts_them() {
    let doc = r#"<mujoco>
      <compiler angle="degree" eulerseq="zyx"/>
      <default><joint range="0 90"/><default class="s"><joint type="slide"/></default></default>
      <worldbody>
        <body name="b" euler="90 0 0">
          <joint name="h" ref="10" springref="20"/>
          <geom size="0.1" axisangle="0 0 1 90"/>
          <body name="c"><joint name="s" class="s"/><geom size="0.1"/></body>
          <body name="d"><joint name="ball" type="ball" range="0 45"/><geom size="0.1"/></body>
        </body>
      </worldbody>
      <actuator><position joint="h" ctrlrange="0 90"/></actuator>
    </mujoco>"#;
    let r = prepare_robot(&source(doc), "x", &Pose::IDENTITY).unwrap();
    let b = &r.bodies[0];
    // zyx: 90 degrees about z.
    assert_eq!(b.get("quat"), Some("0.707107 0 0 0.707107"));
    let find = |name: &str| {
        let mut out = None;
        b.walk(&mut |e| {
            if e.get("name") == Some(name) {
                out = Some(e.clone());
            }
        });
        out.unwrap()
    };
    let h = find("x_h");
    assert_eq!(
        (h.get("range"), h.get("ref"), h.get("springref")),
        (Some("0 1.570796"), Some("0.174533"), Some("0.349066"))
    );
    assert_eq!(find("x_s").get("range"), None, "a slide joint keeps its default's range unconverted");
    assert_eq!(find("x_ball").get("range"), Some("0 0.785398"));
    assert_eq!(b.children[1].get("quat"), Some("0.707107 0 0 0.707107"));
    assert_eq!(r.sections["actuator"][0].get("ctrlrange"), Some("0 90"), "MuJoCo never converts ctrlrange");
    assert!(r.notes.iter().any(|n| n.contains("degrees")));
}

/// The converted robot means in MuJoCo exactly what the degree file means: compared with
/// the official Python bindings loading the original file.
#[test]
fn a_degree_file_and_its_merge_compile_to_the_same_model() {
    let dir = fixtures().join("user_robots/degree_arm");
    let file = dir.join("degree_arm.xml");
    let mut part = RobotPart::new(&file.display().to_string(), &std::fs::read_to_string(&file).unwrap());
    part.dir = Some(dir.clone());
    part.includes.insert(
        "degree_arm_defaults.xml".into(),
        std::fs::read_to_string(dir.join("degree_arm_defaults.xml")).unwrap(),
    );
    let mut src = RobotSource::single("degree_arm", "", "");
    src.parts = vec![part];
    let merged = robot_document(&src, "m").unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let merged_path = tmp.path().join("merged.xml");
    std::fs::write(&merged_path, merged).unwrap();
    let python = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.cache/venv/bin/python");
    assert!(python.exists(), "run scripts/setup.sh --tests: the tests need the MuJoCo 4.0 Python bindings");
    let script = r#"
import json, sys, mujoco
out = []
for p in sys.argv[1:]:
    m = mujoco.MjModel.from_xml_path(p)
    out.append({"range": m.jnt_range.round(6).tolist(), "qpos0": m.qpos0.round(6).tolist(),
                "spring": m.qpos_spring.round(6).tolist(), "body_quat": m.body_quat.round(6).tolist(),
                "geom_quat": m.geom_quat.round(6).tolist(), "mass": m.body_mass.round(6).tolist(),
                "ctrlrange": m.actuator_ctrlrange.round(6).tolist(), "key": m.key_qpos.round(6).tolist()})
print(json.dumps(out))
"#;
    let out = std::process::Command::new(&python).arg("-c").arg(script).arg(&file).arg(&merged_path).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in ["range", "qpos0", "spring", "body_quat", "geom_quat", "mass", "ctrlrange", "key"] {
        assert_eq!(v[0][key], v[1][key], "{key} differs between the degree file and its merge");
    }
}

#[test]
fn includes_are_flattened_in_place() {
    let main = r#"<mujoco><compiler angle="radian"/><include file="parts/defaults.xml"/>
      <worldbody><body name="b" childclass="c"><joint name="j"/><geom size="0.1"/></body></worldbody></mujoco>"#;
    let mut s = source(main);
    s.parts[0].includes.insert(
        "parts/defaults.xml".into(),
        r#"<mujoco><default><default class="c"><joint damping="3"/></default></default></mujoco>"#.into(),
    );
    let r = prepare_robot(&s, "x", &Pose::IDENTITY).unwrap();
    assert_eq!(r.defaults[0].children[0].get("class"), Some("x_c"));
    assert_eq!(r.bodies[0].get("childclass"), Some("x_c"));
    let err = prepare_robot(&source(main), "x", &Pose::IDENTITY).unwrap_err();
    assert_eq!(
        err.to_string(),
        "r.xml: <include file=\"parts/defaults.xml\">: the file was not read (missing or unreadable)"
    );
}

#[test]
fn parts_assemble_into_one_robot() {
    let arm = r#"<mujoco><compiler angle="radian"/>
      <worldbody><body name="base"><body name="hand" pos="0 0 0.5"><joint name="j" range="-1 1"/><geom size="0.05"/></body></body></worldbody>
      <actuator><motor name="m" joint="j" ctrlrange="-10 10"/></actuator></mujoco>"#;
    let gripper = r#"<mujoco><worldbody><body name="base" quat="0 0 0 1"><geom size="0.02"/>
      <body name="finger"><joint name="f" type="slide" range="0 0.04"/><geom size="0.01"/></body></body></worldbody>
      <actuator><position name="f" joint="f" kp="100" ctrlrange="0 0.04"/></actuator></mujoco>"#;
    let mut s = RobotSource::single("two", "arm.xml", arm);
    s.parts[0].fixes = PartFixes {
        gravcomp: true,
        servos: Some(ServoGains { kp_per_torque: 20.0, kv_per_kp: 0.1 }),
        ..PartFixes::default()
    };
    let mut g = RobotPart::new("gripper.xml", gripper);
    // Degrees by default, but this fragment is written in radians.
    g.fixes.assume_compiler = vec![("angle".into(), "radian".into())];
    g.prefix = "gripper_".into();
    g.attach_to = Some("hand".into());
    s.parts.push(g);
    s.home = vec![("j".into(), vec![0.3]), ("gripper_f".into(), vec![0.04])];
    s.excludes = vec![("base".into(), "gripper_finger".into())];
    let r = prepare_robot(&s, "two_1", &Pose::from_pos([0.0, 0.0, 1.0])).unwrap();
    assert_eq!(r.bodies.len(), 1, "the gripper hangs in the hand, not in the world");
    let mut gripper_base = None;
    r.bodies[0].walk(&mut |e| {
        if e.get("name") == Some("two_1_gripper_base") {
            gripper_base = Some(e.clone());
        }
    });
    let gb = gripper_base.expect("gripper attached");
    assert_eq!(gb.get("quat"), Some("0 0 0 1"), "its own pose inside the hand, not the mount's");
    assert_eq!(gb.get("childclass"), Some("two_1_gripper_main"), "the arm's defaults do not leak into it");
    assert_eq!(r.bodies[0].get("gravcomp"), Some("1"));
    assert_eq!(gb.get("gravcomp"), None, "gravity compensation only where asked");
    let servo = &r.sections["actuator"][0];
    assert_eq!(servo.name, "position", "the torque motor became a servo");
    assert_eq!(
        (servo.get("kp"), servo.get("kv"), servo.get("forcerange"), servo.get("ctrlrange")),
        (Some("200"), Some("20"), Some("-10 10"), Some("-1 1"))
    );
    assert_eq!(r.home_ctrl, vec![0.3, 0.04], "servos hold their joint's home");
    assert_eq!(r.sections["contact"][0].get("body2"), Some("two_1_gripper_finger"));
    // Built as a document, it compiles and holds its pose.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("robot.xml");
    std::fs::write(&path, robot_document(&s, "two").unwrap()).unwrap();
    let v = sw_sim::verify_file(&path, &sw_sim::VerifyOptions { robots: vec!["two".into()], ..Default::default() });
    assert!(v.passed, "{:?}", v.failures);
    assert!(v.robots[0].max_joint_drift < 0.05, "{:?}", v.robots);
}

#[test]
fn robosuite_style_fixes() {
    let doc = r#"<mujoco>
      <asset><mesh name="a" file="a.stl"/><mesh name="a" file="a_vis.stl"/></asset>
      <default><default class="hand" group="1"><geom type="sphere"/></default></default>
      <worldbody><body name="b"><geom class="hand" size="0.1" contype="0" conaffinity="0" group="1"/><geom size="0.1" group="0"/></body></worldbody>
    </mujoco>"#;
    let mut s = with_dir(source(doc), "/g");
    assert!(
        prepare_robot(&s, "x", &Pose::IDENTITY).unwrap_err().to_string().contains("<mesh name=\"a\"> appears twice")
    );
    s.parts[0].fixes = PartFixes {
        assume_compiler: vec![("angle".into(), "radian".into()), ("inertiagrouprange".into(), "0 0".into())],
        keep_first_duplicate_asset: true,
        drop_attrs: vec![("default".into(), "group".into())],
        regroup: true,
        ..PartFixes::default()
    };
    let r = prepare_robot(&s, "x", &Pose::IDENTITY).unwrap();
    assert_eq!(r.assets.len(), 1);
    assert_eq!(r.files.len(), 1);
    assert_eq!(r.defaults[0].children[0].get("group"), None);
    let geoms = &r.bodies[0].children;
    assert_eq!((geoms[0].get("group"), geoms[0].get("mass")), (Some("2"), Some("0")), "visual: group 2, no mass");
    assert_eq!((geoms[1].get("group"), geoms[1].get("mass")), (Some("3"), None), "collision: group 3, counted");
}

#[test]
fn bad_robots_name_the_file_and_the_element() {
    let e = |doc: &str| prepare_robot(&source(doc), "x", &Pose::IDENTITY).unwrap_err().to_string();
    assert!(e("<mujoco><worldbody>").starts_with("r.xml: not valid XML at line"));
    assert_eq!(
        e(r#"<mujoco><compiler angle="radian"/><worldbody><body name="a"/><body name="a"/></worldbody></mujoco>"#),
        "r.xml: <body name=\"a\"> appears twice"
    );
    assert_eq!(e("<robot/>"), "r.xml: the root element is <robot>, expected <mujoco>");
    assert_eq!(
        e(r#"<mujoco><worldbody><body><geom size="1" material="steel"/></body></worldbody></mujoco>"#),
        "r.xml: <geom> (material=\"steel\") refers to 'steel' that the robot does not define"
    );
    assert_eq!(
        e(r#"<mujoco><worldbody><body childclass="nope"/></worldbody></mujoco>"#),
        "r.xml: <body> (childclass=\"nope\") refers to default class 'nope' that the robot does not define"
    );
    assert!(
        e(r#"<mujoco><extension/><worldbody><body/></worldbody></mujoco>"#).contains("<extension> is not supported")
    );
    assert!(e(r#"<mujoco><worldbody><body euler="1 2"/></worldbody></mujoco>"#).contains("euler=\"1 2\""));
    assert_eq!(e(r#"<mujoco><worldbody/></mujoco>"#), "r.xml: has no <worldbody> with a body");
    assert!(
        e(r#"<mujoco><asset><mesh file="a.stl"/></asset><worldbody><body/></worldbody></mujoco>"#)
            .contains("references a file, but the model has no directory")
    );
    let mut s = source(r#"<mujoco><worldbody><body name="b"/></worldbody></mujoco>"#);
    let mut p = RobotPart::new("tool.xml", r#"<mujoco><worldbody><body name="t"/></worldbody></mujoco>"#);
    p.attach_to = Some("flange".into());
    p.prefix = "tool_".into();
    s.parts.push(p);
    let err = prepare_robot(&s, "x", &Pose::IDENTITY).unwrap_err().to_string();
    assert_eq!(err, "robot r: part tool.xml is attached to body 'flange', which no earlier part has");
}

#[test]
fn keyframes_cover_the_robots_own_joint_widths() {
    let doc = r#"<mujoco><compiler angle="radian"/>
      <default><default class="b"><joint type="ball"/></default></default>
      <worldbody><body name="r"><freejoint name="free"/><geom size="0.1"/>
        <body name="a"><joint name="ball" class="b"/><geom size="0.1"/>
          <body name="c"><joint name="hinge" ref="0.2"/><geom size="0.1"/></body></body></body></worldbody>
      <keyframe><key name="home" qpos="0 0 0.5 1 0 0 0 0.6 0.8 0 0"/></keyframe></mujoco>"#;
    let r = prepare_robot(&source(doc), "x", &Pose::IDENTITY).unwrap();
    assert_eq!(r.home_qpos["x_ball"], vec![0.6, 0.8, 0.0, 0.0]);
    assert_eq!(r.home_qpos["x_hinge"], vec![0.2], "a joint the key does not cover rests at its reference");
    let document = Element::parse(&robot_document(&source(doc), "x").unwrap()).unwrap();
    let key = document.first("keyframe").unwrap().children[0].get("qpos").unwrap().to_string();
    assert_eq!(key, "0 0 0 1 0 0 0 0.6 0.8 0 0 0.2", "free joint at its mounted pose, ball and hinge at home");
}

#[test]
fn urdf_becomes_mjcf_with_servos_and_resolved_meshes() {
    let file = fixtures().join("user_robots/two_link_description/urdf/two_link.urdf");
    let text = std::fs::read_to_string(&file).unwrap();
    let pkg = fixtures().join("user_robots/two_link_description");
    let resolve = |uri: &str| -> Result<PathBuf, String> {
        uri.strip_prefix("package://two_link_description/").map(|r| pkg.join(r)).ok_or_else(|| format!("no {uri}"))
    };
    let import = urdf_to_mjcf("two_link.urdf", &text, &resolve).unwrap();
    let doc = Element::parse(&import.mjcf).unwrap();
    let mut joints = BTreeMap::new();
    doc.walk(&mut |e| {
        if e.name == "joint" && e.get("type").is_some() {
            joints.insert(
                e.get("name").unwrap().to_string(),
                (e.get("type").unwrap().to_string(), e.get("range").map(str::to_string)),
            );
        }
    });
    assert_eq!(joints["joint1"], ("hinge".to_string(), Some("-1.5 1.5".to_string())));
    assert_eq!(joints["joint2"], ("hinge".to_string(), None), "continuous: no range");
    let acts = &doc.first("actuator").unwrap().children;
    assert_eq!(acts.len(), 2);
    assert_eq!((acts[0].get("kp"), acts[0].get("forcerange")), (Some("400"), Some("-20 20")));
    let mesh = &doc.first("asset").unwrap().children.iter().find(|e| e.name == "mesh").unwrap().clone();
    assert_eq!(mesh.get("file").map(PathBuf::from), Some(pkg.join("meshes/link.stl")));
    assert!(import.notes.iter().any(|n| n.contains("<transmission>")), "{:?}", import.notes);
    // The world link is dropped: base_link is the top-level body, fixed to the mount.
    assert_eq!(doc.first("worldbody").unwrap().children[0].get("name"), Some("base_link"));
}

#[test]
fn bad_urdf_names_the_file_and_the_element() {
    let none = |_: &str| -> Result<PathBuf, String> { Err("package 'p' was not found".into()) };
    let e = |text: &str| urdf_to_mjcf("bad.urdf", text, &none).unwrap_err().to_string();
    let unknown = std::fs::read_to_string(fixtures().join("bad_robots/unknown_tag.urdf")).unwrap();
    assert_eq!(e(&unknown), "bad.urdf: <camera>: is not a URDF element scenewright knows");
    assert_eq!(
        e("<robot><link name=\"a\"><mystery/></link></robot>"),
        "bad.urdf: <link name=\"a\">/<mystery>: is not a URDF link element scenewright knows"
    );
    let mesh = r#"<robot><link name="a"><visual><geometry><mesh filename="package://p/m.stl"/></geometry></visual></link></robot>"#;
    assert_eq!(
        e(mesh),
        "bad.urdf: <link name=\"a\">/<visual> #1/<mesh filename=\"package://p/m.stl\">: package 'p' was not found"
    );
    let dae = |_: &str| -> Result<PathBuf, String> { Ok(PathBuf::from("/m/arm.dae")) };
    let err = urdf_to_mjcf("bad.urdf", &mesh.replace("m.stl", "arm.dae"), &dae).unwrap_err().to_string();
    assert!(err.contains("MuJoCo reads STL, OBJ and MSH meshes, not '.dae'"), "{err}");
    let joint = r#"<robot><link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint></robot>"#;
    assert!(e(joint).starts_with("bad.urdf: <joint name=\"j\">/<limit>: a revolute joint needs lower < upper"));
    assert!(e("<robot><link name=\"a\"/><link name=\"b\"/></robot>").contains("exactly one root link, found 2"));
    assert!(e("<robot><link name=\"a\"></robot>").starts_with("bad.urdf: not valid XML at line 1"));
}
