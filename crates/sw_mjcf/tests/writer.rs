#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The MJCF writer on a small hand-placed scene: a snapshot of the document, and the scene
//! compiled and settled in MuJoCo.

use sw_catalog::AssetRequest;
use sw_mjcf::{RobotInput, SceneInput, write_scene};
use sw_plan::{DoorLayout, LaidOutScene, PlacedObject, PlacedRobot, RoomKind, RoomLayout, Support, Wall};

fn object(name: &str, category: &str, pos: [f64; 3], yaw: f64, support: Support, movable: bool) -> PlacedObject {
    PlacedObject {
        name: name.into(),
        group: category.into(),
        category: category.into(),
        label: category.into(),
        pos,
        yaw,
        size: [0.0; 3],
        support,
        movable,
        mass: None,
        asset_seed: 1,
        added: false,
    }
}

fn scene() -> (LaidOutScene, Vec<sw_geom::Asset>) {
    let room = RoomLayout {
        kind: RoomKind::Lab,
        size: RoomKind::Lab.default_size(),
        wall_thickness: 0.2,
        door: DoorLayout { wall: Wall::South, offset: 0.0, width: 1.0, height: 2.1 },
    };
    let mut layout = LaidOutScene::new(1, room);
    let table = sw_catalog::generate(&AssetRequest::new("table", 1)).unwrap();
    let top = table.surfaces[0].z;
    let bx = sw_catalog::generate(&AssetRequest::new("cardboard_box", 1)).unwrap();
    layout.objects.push(object("table_1", "table", [0.0, 0.0, 0.0], 0.0, Support::Floor, false));
    let on = Support::Object { object: "table_1".into(), surface: "top".into() };
    layout.objects.push(object(
        "cardboard_box_1",
        "cardboard_box",
        [0.3, 0.1, top],
        std::f64::consts::FRAC_PI_2,
        on,
        true,
    ));
    layout.robots.push(PlacedRobot {
        name: "ur5e_1".into(),
        group: "ur5e".into(),
        model: "ur5e".into(),
        pos: [-0.3, -0.2, top],
        yaw: std::f64::consts::FRAC_PI_2,
        mount: "surface".into(),
        mounted_on: Some("table_1".into()),
        reach_coverage: None,
    });
    (layout, vec![table, bx])
}

fn write_with_ur5e(prompt: &str) -> sw_mjcf::SceneFiles {
    let (layout, assets) = scene();
    let ur5e = sw_robots::find("ur5e").unwrap().model().unwrap();
    write_scene(&SceneInput {
        prompt,
        layout: &layout,
        assets: assets.iter().collect(),
        robots: vec![RobotInput { name: "ur5e_1", model: &ur5e }],
    })
    .unwrap()
}

#[test]
fn a_small_scene_writes_stable_mjcf_that_compiles_and_settles() {
    let files = write_with_ur5e("a table with a box and a UR5e");
    insta::assert_snapshot!("scene_xml", files.scene_xml);
    assert!(!files.scene_only_xml.contains("ur5e_1"));

    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("assets")).unwrap();
    for m in &files.meshes {
        std::fs::write(dir.path().join("assets").join(&m.file_name), &m.bytes).unwrap();
    }
    for (name, text) in [("scene.xml", &files.scene_xml), ("scene_only.xml", &files.scene_only_xml)] {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        let v =
            sw_sim::verify_file(&path, &sw_sim::VerifyOptions { robots: vec!["ur5e_1".into()], ..Default::default() });
        assert!(v.passed, "{name}: {:?}", v.failures);
        assert_eq!(v.initial_state, "keyframe 'home'");
    }
}

#[test]
fn every_name_a_robot_brings_is_prefixed() {
    let files = write_with_ur5e("");
    let doc = sw_mjcf::xml::Element::parse(&files.scene_xml).unwrap();
    // The scene's own: its objects, room, cameras (`overview`, and `front` across the first
    // robot's work), keyframe and asset names.
    let scene_names =
        ["table", "cardboard_box", "floor", "wall_", "doorway", "sw_", "overview", "front", "home", "scenewright"];
    doc.walk(&mut |e| {
        for key in ["name", "class", "childclass"] {
            if let Some(v) = e.get(key) {
                let ok = v.starts_with("ur5e_1_") || scene_names.iter().any(|p| v.starts_with(p));
                assert!(ok, "<{} {key}=\"{v}\"> is neither a scene name nor prefixed", e.name);
            }
        }
    });
}

#[test]
fn a_missing_robot_model_is_an_error_naming_the_robot() {
    let (layout, assets) = scene();
    let err = write_scene(&SceneInput { prompt: "", layout: &layout, assets: assets.iter().collect(), robots: vec![] })
        .unwrap_err();
    assert_eq!(err.to_string(), "robot 'ur5e_1' is in the layout but no model was given for it");
}

#[test]
fn a_scene_without_joints_still_has_a_home_keyframe() {
    // Only fixtures, no robot: nothing moves, and resetting to `home` must still work.
    let (mut layout, assets) = scene();
    layout.objects.retain(|o| o.name == "table_1");
    layout.robots.clear();
    let files = write_scene(&SceneInput {
        prompt: "an empty lab with a table",
        layout: &layout,
        assets: assets.iter().take(1).collect(),
        robots: Vec::new(),
    })
    .unwrap();
    assert!(files.scene_xml.contains("<key name=\"home\""), "{}", files.scene_xml);
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("assets")).unwrap();
    for m in &files.meshes {
        std::fs::write(dir.path().join("assets").join(&m.file_name), &m.bytes).unwrap();
    }
    let path = dir.path().join("scene.xml");
    std::fs::write(&path, &files.scene_xml).unwrap();
    let v = sw_sim::verify_file(&path, &sw_sim::VerifyOptions::default());
    assert!(v.passed, "{:?}", v.failures);
    assert_eq!(v.initial_state, "keyframe 'home'");
}
