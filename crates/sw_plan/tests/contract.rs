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
