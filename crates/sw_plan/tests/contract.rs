#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The contract: checked-in schemas match the code, and invalid plans are rejected with
//! errors that name the field.

use std::path::PathBuf;

use sw_plan::{
    Dims, Mount, ObjectPlan, PlanError, Relation, RelationKind, RobotPlan, RoomKind, RoomPlan, ScenePlan, Wall,
};

fn schemas_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../schemas")
}

/// Regenerate with `UPDATE_SCHEMAS=1 cargo test -p sw_plan`.
#[test]
fn checked_in_schemas_match_the_code() {
    let update = std::env::var_os("UPDATE_SCHEMAS").is_some();
    for s in sw_plan::schemas() {
        let path = schemas_dir().join(s.file_name);
        if update {
            std::fs::create_dir_all(schemas_dir()).unwrap();
            std::fs::write(&path, &s.json).unwrap();
            continue;
        }
        let on_disk = std::fs::read_to_string(&path)
            .unwrap_or_else(|_| panic!("{} is missing; run UPDATE_SCHEMAS=1 cargo test -p sw_plan", path.display()));
        assert_eq!(
            on_disk, s.json,
            "{} is out of date: a schema change is a versioned change (bump SCHEMA_VERSION) and regenerate with UPDATE_SCHEMAS=1",
            s.file_name
        );
    }
}

fn plan() -> ScenePlan {
    let mut p = ScenePlan::new(
        "a table with a mug",
        RoomPlan {
            kind: RoomKind::Kitchen,
            size: RoomKind::Kitchen.default_size(),
            size_fixed: false,
            door: Wall::South,
        },
    );
    p.objects.push(ObjectPlan {
        id: "table".into(),
        category: "table".into(),
        phrase: "a table".into(),
        count: 1,
        color: None,
        size: Default::default(),
        proxy: None,
    });
    p.objects.push(ObjectPlan {
        id: "mug".into(),
        category: "cardboard_box".into(),
        phrase: "a mug".into(),
        count: 2,
        color: None,
        size: Default::default(),
        proxy: None,
    });
    p.relations.push(Relation { subject: "mug".into(), kind: RelationKind::On { target: "table".into() } });
    p.robots.push(RobotPlan {
        id: "ur5e".into(),
        model: "ur5e".into(),
        phrase: "a UR5e".into(),
        count: 1,
        mount: Mount::OnSurface { target: "table".into() },
        near: None,
    });
    p
}

#[test]
fn a_valid_plan_round_trips_through_json() {
    let p = plan();
    p.validate().unwrap();
    let text = serde_json::to_string_pretty(&p).unwrap();
    let back = ScenePlan::from_json(&text).unwrap();
    assert_eq!(back, p);
}

#[test]
fn semantic_errors_name_the_field() {
    let mut p = plan();
    p.objects[1].count = 0;
    p.relations.push(Relation { subject: "table".into(), kind: RelationKind::NextTo { target: "nothing".into() } });
    p.robots[0].mount = Mount::OnSurface { target: "ghost".into() };
    p.room.size = Dims::new(f64::NAN, 4.0, 3.0);
    let err = p.validate().unwrap_err();
    let paths: Vec<&str> = err.0.iter().map(|e| e.path.as_str()).collect();
    assert_eq!(
        paths,
        ["room.size.width", "objects[1].count", "robots[0].mount.target", "relations[1].target"],
        "{err}"
    );
}

#[test]
fn shape_errors_name_the_field() {
    let mut v = serde_json::to_value(plan()).unwrap();
    v["objects"][1]["count"] = serde_json::json!("two");
    match ScenePlan::from_json(&v.to_string()) {
        Err(PlanError::Shape { path, .. }) => assert_eq!(path, "objects[1].count"),
        other => panic!("expected a shape error, got {other:?}"),
    }
    let mut v = serde_json::to_value(plan()).unwrap();
    v["room"]["colour"] = serde_json::json!("blue");
    match ScenePlan::from_json(&v.to_string()) {
        Err(PlanError::Shape { path, message }) => {
            assert_eq!(path, "room.colour");
            assert!(message.contains("colour"), "{message}");
        }
        other => panic!("expected a shape error, got {other:?}"),
    }
    assert!(matches!(ScenePlan::from_json("not json"), Err(PlanError::Shape { .. })));
}

#[test]
fn duplicate_ids_and_self_relations_are_rejected() {
    let mut p = plan();
    p.objects[1].id = "table".into();
    p.relations[0] = Relation { subject: "table".into(), kind: RelationKind::On { target: "table".into() } };
    let err = p.validate().unwrap_err().to_string();
    assert!(err.contains("objects[1].id: 'table' is used twice"), "{err}");
    assert!(err.contains("cannot be related to itself"), "{err}");
}

#[test]
fn issue_20_relations_read_under_the_vocabulary_names() {
    // The names and fields of VOCAB-20.md, as the corpus and the judge write them.
    let lines = [
        (r#"{"subject": "cup", "relation": "inside", "target": "cabinet"}"#, "inside"),
        (r#"{"subject": "sink", "relation": "set_into", "target": "counter"}"#, "set_into"),
        (r#"{"subject": "bin", "relation": "at_end_of", "target": "conveyor", "end": "both"}"#, "at_end_of"),
        (r#"{"subject": "bin", "relation": "at_end_of", "target": "conveyor"}"#, "at_end_of"),
        (r#"{"subject": "lamp", "relation": "on_edge_of", "target": "desk"}"#, "on_edge_of"),
        (r#"{"subject": "chair", "relation": "on_each_side_of", "target": "desk"}"#, "on_each_side_of"),
        (r#"{"subject": "sofa", "relation": "facing", "target": "tv"}"#, "facing"),
        (r#"{"subject": "shelf", "relation": "on_opposite_walls", "long": true}"#, "on_opposite_walls"),
        (r#"{"subject": "plant", "relation": "in_corners"}"#, "in_corners"),
        (r#"{"subject": "desk", "relation": "back_to_back"}"#, "back_to_back"),
        (r#"{"subject": "desk", "relation": "in_rows", "n": 3, "m": 4}"#, "in_rows"),
        (r#"{"subject": "crate", "relation": "stacked", "n": 4, "stacks": 3}"#, "stacked"),
        (r#"{"subject": "crate", "relation": "stacked"}"#, "stacked"),
    ];
    for (text, name) in lines {
        let r: Relation = serde_json::from_str(text).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(r.kind.name(), name);
        assert!(RelationKind::NAMES.contains(&name));
        // Written back the same way (absent options stay absent).
        let back: serde_json::Value = serde_json::to_value(&r).unwrap();
        let orig: serde_json::Value = serde_json::from_str(text).unwrap();
        assert_eq!(back, orig, "{text}");
    }
    let r: Relation = serde_json::from_str(r#"{"subject": "desk", "relation": "in_rows", "n": 3, "m": 4}"#).unwrap();
    assert_eq!(r.kind, RelationKind::InRows { n: Some(3), m: Some(4) });
    assert!(
        serde_json::from_str::<Relation>(
            r#"{"subject": "a", "relation": "at_end_of", "target": "b", "end": "middle"}"#
        )
        .is_err()
    );
}

#[test]
fn a_stated_length_takes_the_long_side_and_width_the_other() {
    let s = sw_plan::ExplicitSize { length: Some(2.0), width: Some(0.9), ..Default::default() };
    assert_eq!(s.axes(true), [Some(2.0), Some(0.9), None]);
    assert_eq!(s.axes(false), [Some(0.9), Some(2.0), None]);
    let w = sw_plan::ExplicitSize { width: Some(1.8), height: Some(2.0), ..Default::default() };
    assert_eq!(w.axes(false), [Some(1.8), None, Some(2.0)]);
    let d = sw_plan::ExplicitSize { diameter: Some(0.3), ..Default::default() };
    assert_eq!(d.axes(true), [Some(0.3), Some(0.3), None]);
    assert_eq!(s.stated(), vec![("length", 2.0), ("width", 0.9)]);
}
