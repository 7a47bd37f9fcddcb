//! `--physics mjx`: the same scenes with only collision pairs MuJoCo XLA implements, the
//! same placement and validity, verified in MuJoCo like every scene. (MJX itself loads,
//! steps and settles them in the Python tests: python/tests/test_physics.py.)

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;

use sw_mjcf::physics::{MJX_ANCHOR, mjx_missing_pairs};
use sw_pipeline::{Options, Outcome, PhysicsTarget, generate};

fn make(prompt: &str, dir: &Path, physics: PhysicsTarget, robots: Option<Vec<String>>) -> Outcome {
    let opts = Options { seed: 2, physics, robots, ..Options::default() };
    generate(prompt, dir, &opts, &mut |_| {}).unwrap()
}

fn xml(o: &Outcome) -> String {
    std::fs::read_to_string(o.out_dir.join("scene.xml")).unwrap()
}

/// Prompts whose scenes hold object cylinders (round tables, mugs, bottles, barrels),
/// robot cylinders, wheels, and one with no joint at all.
const PROMPTS: &[&str] = &[
    "a robotics lab with a workbench, a UR5e on the bench, three bins on the bench and a chair next to the workbench",
    "a kitchen with a round table, four chairs around it and two mugs on the table",
    "a lab with a Franka Panda on a pedestal, a table next to it and six bottles on the table",
    "a warehouse aisle with two shelving racks, six boxes and a TurtleBot",
    "a warehouse with four pallet racks against the north wall",
];

#[test]
fn mjx_scenes_keep_placement_and_validity_with_only_pairs_mjx_has() {
    let tmp = tempfile::tempdir().unwrap();
    let mut native_missing = 0;
    for (i, p) in PROMPTS.iter().enumerate() {
        let native = make(p, &tmp.path().join(format!("n{i}")), PhysicsTarget::Native, None);
        let mjx = make(p, &tmp.path().join(format!("m{i}")), PhysicsTarget::Mjx, None);
        assert!(sw_pipeline::succeeded(&native.report), "{p}: native {:?}", native.report.verification);
        assert!(sw_pipeline::succeeded(&mjx.report), "{p}: mjx {:?}", mjx.report.verification);
        assert_eq!(mjx_missing_pairs(&xml(&mjx)).unwrap(), Vec::<(String, String)>::new(), "{p}");
        native_missing += usize::from(!mjx_missing_pairs(&xml(&native)).unwrap().is_empty());
        // Same placement: the layouts are the same document.
        assert_eq!(native.layout, mjx.layout, "{p}: the layout changed");
        // Same validity: the same bodies, free bodies, no deep contact, settled.
        let (vn, vm) = (native.report.verification.clone().unwrap(), mjx.report.verification.clone().unwrap());
        let (sn, sm) = (vn.model.unwrap(), vm.model.unwrap());
        assert_eq!(sn.free_bodies, sm.free_bodies, "{p}");
        let anchor = usize::from(sn.joints == 0);
        assert_eq!(sn.bodies as usize + anchor, sm.bodies as usize, "{p}");
        assert!(vm.initial_contacts.unwrap().deep.is_empty(), "{p}");
        assert!(vm.settle.unwrap().max_displacement_m < 0.01, "{p}");
        if anchor == 1 {
            let text = xml(&mjx);
            assert!(text.contains(&format!("<body name=\"{MJX_ANCHOR}\"")), "{p}");
            assert!(text.contains("<key name=\"home\" qpos=\"0\"/>"), "{p}");
            assert_eq!(vm.initial_state, "keyframe 'home'");
        }
        assert!(mjx.report.warnings.iter().any(|w| w.code == "physics_target"), "{p}: the report does not say");
        assert!(native.report.warnings.iter().all(|w| w.code != "physics_target"));
    }
    // The native scenes do hold pairs MJX lacks: the check above can fail.
    assert!(native_missing >= 3, "only {native_missing} native scenes had cylinder–box pairs");
}

#[test]
fn every_registered_robot_has_only_pairs_mjx_has() {
    let tmp = tempfile::tempdir().unwrap();
    let prompt = "a lab with a table, two bins and a mug on the table";
    for def in sw_robots::registry() {
        let o = make(prompt, &tmp.path().join(def.name), PhysicsTarget::Mjx, Some(vec![def.name.to_string()]));
        assert!(sw_pipeline::succeeded(&o.report), "{}: {:?}", def.name, o.report.verification);
        assert_eq!(mjx_missing_pairs(&xml(&o)).unwrap(), Vec::<(String, String)>::new(), "{}", def.name);
        assert_eq!(o.layout.robots.len(), 1, "{}", def.name);
    }
}

#[test]
fn the_rewrite_stays_inside_robot_cylinders_and_on_object_boxes() {
    use sw_mjcf::physics::adapt_document;
    let doc = r#"<mujoco>
      <default>
        <default class="r_col"><geom type="cylinder" group="3"/></default>
        <default class="sw_collision"><geom group="3"/></default>
      </default>
      <worldbody>
        <geom name="floor" type="plane" size="1 1 0.1"/>
        <body name="crate_1"><geom name="b" class="sw_collision" type="box" size="0.1 0.1 0.1"/></body>
        <body name="table_1"><geom name="t" class="sw_collision" type="cylinder" size="0.4 0.02" pos="0 0 0.7"/></body>
        <body name="r_base">
          <geom name="long" class="r_col" fromto="0 0 0 0 0 0.3" size="0.05"/>
          <geom name="plate" class="r_col" fromto="0 0 0 0.02 0 0" size="0.07"/>
          <geom name="vis" type="cylinder" size="0.1 0.1" contype="0" conaffinity="0"/>
          <body name="r_wheel"><joint name="w" axis="0 1 0"/><geom name="wheel" class="r_col" size="0.033 0.009"/></body>
        </body>
      </worldbody>
    </mujoco>"#;
    let (out, notes) = adapt_document(doc, PhysicsTarget::Mjx).unwrap();
    let root = sw_mjcf::xml::Element::parse(&out).unwrap();
    let mut geoms = std::collections::BTreeMap::new();
    root.first("worldbody").unwrap().walk(&mut |e| {
        if e.name == "geom" {
            geoms.insert(e.get("name").unwrap().to_string(), e.clone());
        }
    });
    let t = &geoms["t"];
    assert_eq!((t.get("type"), t.get("size"), t.get("pos")), (Some("box"), Some("0.4 0.4 0.02"), Some("0 0 0.7")));
    // The capsule inside the long cylinder: its caps end at the cylinder's end faces.
    let l = &geoms["long"];
    assert_eq!(
        (l.get("type"), l.get("fromto"), l.get("size")),
        (Some("capsule"), Some("0 0 0.05 0 0 0.25"), Some("0.05"))
    );
    // A plate on a body without a hinge: the box around it, its axis along the fromto.
    let pl = &geoms["plate"];
    assert_eq!(
        (pl.get("type"), pl.get("size"), pl.get("pos")),
        (Some("box"), Some("0.07 0.07 0.01"), Some("0.01 0 0"))
    );
    let q: Vec<f64> = pl.get("quat").unwrap().split(' ').map(|x| x.parse().unwrap()).collect();
    // The quaternion turns +Z onto +X.
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    let zx = [2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)];
    assert!((zx[0] - 1.0).abs() < 1e-6 && zx[1].abs() < 1e-6 && zx[2].abs() < 1e-6, "{zx:?}");
    assert_eq!((geoms["wheel"].get("type"), geoms["wheel"].get("size")), (Some("sphere"), Some("0.033")));
    assert_eq!(geoms["vis"].get("type"), Some("cylinder"), "a visual geom was rewritten");
    assert_eq!(mjx_missing_pairs(&out).unwrap(), Vec::<(String, String)>::new());
    assert_eq!(mjx_missing_pairs(doc).unwrap(), vec![("cylinder".to_string(), "box".to_string())]);
    assert_eq!(notes.len(), 2, "{notes:?}");
    // Native leaves the document alone.
    assert_eq!(adapt_document(doc, PhysicsTarget::Native).unwrap(), (doc.to_string(), Vec::new()));
}
