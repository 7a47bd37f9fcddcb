#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Layout invariants: everything inside the room, no two objects' collision geometry
//! overlapping, items resting exactly on the surfaces they are on — for any seed.

use proptest::prelude::*;
use sw_geom::{Aabb, Pose};
use sw_layout::{RobotItem, RobotMount};
use sw_plan::{Dims, LaidOutScene, Relation, RelationKind, RoomKind, ScenePlan, Support, Wall};

mod common;
use common::{Forged, forge, group, room, solve_forged};

fn world_boxes(f: &Forged, scene: &LaidOutScene, name: &str) -> Vec<Aabb> {
    let o = scene.object(name).unwrap();
    let (_, _, asset, _) = f.assets.iter().find(|(n, ..)| n == name).unwrap();
    let pose = Pose::from_pos_yaw(o.pos, o.yaw);
    asset.collision_aabbs().iter().map(|b| b.transformed(&pose)).collect()
}

fn overlap(a: &Aabb, b: &Aabb) -> f64 {
    let d: Vec<f64> = (0..3).map(|i| a.max[i].min(b.max[i]) - a.min[i].max(b.min[i])).collect();
    d[0].min(d[1]).min(d[2])
}

/// Everything inside the room; no pair of objects' collision boxes overlapping by more
/// than 0.1 mm; items on surfaces resting at the surface's height.
fn check_invariants(f: &Forged, scene: &LaidOutScene) {
    let half = [scene.room.size.width / 2.0, scene.room.size.depth / 2.0];
    let boxes: Vec<(String, Vec<Aabb>)> =
        scene.objects.iter().map(|o| (o.name.clone(), world_boxes(f, scene, &o.name))).collect();
    for (name, bs) in &boxes {
        for b in bs {
            assert!(b.min[0] >= -half[0] - 1e-6 && b.max[0] <= half[0] + 1e-6, "{name} outside in x: {b:?}");
            assert!(b.min[1] >= -half[1] - 1e-6 && b.max[1] <= half[1] + 1e-6, "{name} outside in y: {b:?}");
            assert!(b.min[2] >= -1e-6 && b.max[2] <= scene.room.size.height + 1e-6, "{name} outside in z: {b:?}");
        }
    }
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            for a in &boxes[i].1 {
                for b in &boxes[j].1 {
                    let o = overlap(a, b);
                    assert!(o < 1e-4, "{} and {} overlap by {o} m", boxes[i].0, boxes[j].0);
                }
            }
        }
    }
    for o in &scene.objects {
        if let Support::Object { object, surface } = &o.support {
            let host = scene.object(object).unwrap();
            let (_, _, asset, _) = f.assets.iter().find(|(n, ..)| n == object).unwrap();
            // "rim" is no declared surface: it is an open container's top, what a member
            // stacked on a tote rests on (its collision boxes' top, not a floor inside it).
            let z = match asset.surfaces.iter().find(|s| &s.name == surface) {
                Some(s) => s.z,
                None if surface == "rim" && asset.is_open() => {
                    asset.collision_aabbs().iter().map(|b| b.max[2]).fold(f64::NEG_INFINITY, f64::max)
                }
                None => panic!("{} rests on {object}/{surface}, a surface {object} does not have", o.name),
            };
            assert!((o.pos[2] - (host.pos[2] + z)).abs() < 1e-6, "{} is not resting on {object}/{surface}", o.name);
        }
    }
    scene.validate().unwrap();
}

#[test]
fn boxes_on_shelves_rest_on_a_level_and_shelves_stand_against_the_named_wall() {
    let mut plan = room(RoomKind::StorageRoom, Dims::new(6.0, 4.0, 3.0), true);
    plan.objects.push(group("shelf", "shelf", 2));
    plan.objects.push(group("box", "cardboard_box", 8));
    plan.relations
        .push(Relation { subject: "shelf".into(), kind: RelationKind::AgainstWall { wall: Some(Wall::West) } });
    plan.relations.push(Relation { subject: "box".into(), kind: RelationKind::On { target: "shelf".into() } });
    let f = forge(plan, 3);
    let scene = solve_forged(&f, Vec::new(), 3);
    check_invariants(&f, &scene);
    assert!(scene.left_out.is_empty(), "{:?}", scene.left_out);
    for o in scene.objects.iter().filter(|o| o.category == "shelf") {
        let bs = world_boxes(&f, &scene, &o.name);
        let min_x = bs.iter().map(|b| b.min[0]).fold(f64::INFINITY, f64::min);
        assert!(min_x < -3.0 + 0.1, "{} is not against the west wall (min x {min_x})", o.name);
    }
    let on_shelves = scene
        .objects
        .iter()
        .filter(|o| matches!(&o.support, Support::Object { object, .. } if object.starts_with("shelf")))
        .count();
    assert_eq!(on_shelves, 8);
}

#[test]
fn a_bin_fits_under_a_table_and_chairs_go_around_it() {
    let mut plan = room(RoomKind::Kitchen, Dims::new(5.0, 4.0, 2.7), true);
    plan.objects.push(group("table", "table", 1));
    plan.objects.push(group("chair", "chair", 4));
    plan.objects.push(group("bin", "bin", 1));
    plan.relations.push(Relation { subject: "chair".into(), kind: RelationKind::Around { target: "table".into() } });
    plan.relations.push(Relation { subject: "bin".into(), kind: RelationKind::Under { target: "table".into() } });
    let f = forge(plan, 0);
    let scene = solve_forged(&f, Vec::new(), 0);
    check_invariants(&f, &scene);
    let table = scene.object("table_1").unwrap();
    let bin = scene.object("bin_1").unwrap();
    assert!(
        (bin.pos[0] - table.pos[0]).abs() < 0.6 && (bin.pos[1] - table.pos[1]).abs() < 0.4,
        "bin not under the table"
    );
    for c in scene.objects.iter().filter(|o| o.category == "chair") {
        let d = (c.pos[0] - table.pos[0]).hypot(c.pos[1] - table.pos[1]);
        assert!(d < 1.3, "{} is {d} m from the table", c.name);
    }
}

#[test]
fn too_much_for_a_fixed_room_is_left_out_and_reported_never_overlapped() {
    let mut plan = room(RoomKind::Room, Dims::new(2.0, 2.0, 3.0), true);
    plan.objects.push(group("rack", "pallet_rack", 40));
    let f = forge(plan, 1);
    let scene = solve_forged(&f, Vec::new(), 1);
    check_invariants(&f, &scene);
    let l = &scene.left_out[0];
    assert_eq!(l.requested, 40);
    assert!(l.placed < 40);
    assert_eq!(scene.objects.len() as u32, l.placed);
}

#[test]
fn a_room_whose_size_was_not_given_grows_to_fit() {
    let mut plan = room(RoomKind::Room, Dims::new(3.0, 3.0, 3.0), false);
    plan.objects.push(group("machine", "machine", 6));
    let f = forge(plan, 2);
    let scene = solve_forged(&f, Vec::new(), 2);
    check_invariants(&f, &scene);
    assert!(scene.left_out.is_empty());
    assert!(scene.room.size.width > 3.0);
    assert!(scene.warnings.iter().any(|w| w.code == "room_grown"));
}

#[test]
fn an_arm_on_a_workbench_stands_on_its_top_clear_of_the_items_on_it() {
    let mut plan = room(RoomKind::Lab, Dims::new(6.0, 5.0, 3.0), true);
    plan.objects.push(group("workbench", "workbench", 1));
    plan.objects.push(group("bin", "bin", 3));
    plan.relations.push(Relation { subject: "bin".into(), kind: RelationKind::On { target: "workbench".into() } });
    let f = forge(plan, 4);
    let def = sw_robots::find("ur5e").unwrap();
    let keepout: Vec<Aabb> = def.keepout.iter().map(|(a, b)| Aabb { min: *a, max: *b }).collect();
    let robot = RobotItem {
        name: "ur5e_1".into(),
        group: "ur5e".into(),
        model: "ur5e".into(),
        is_arm: true,
        keepout: keepout.clone(),
        base_radius: def.base_radius,
        reach: def.reach,
        mount: RobotMount::Surface { group: "workbench".into() },
        near: None,
    };
    let scene = solve_forged(&f, vec![robot], 4);
    check_invariants(&f, &scene);
    let r = &scene.robots[0];
    let bench = scene.object("workbench_1").unwrap();
    let top = f.assets[0].2.surfaces.iter().find(|s| s.name == "top").unwrap().z;
    assert!((r.pos[2] - (bench.pos[2] + top)).abs() < 1e-6, "robot not on the bench top");
    assert_eq!(r.mounted_on.as_deref(), Some("workbench_1"));
    assert!(r.reach_coverage.unwrap() > 0.5, "{r:?}");
    let rpose = Pose::from_pos_yaw(r.pos, r.yaw);
    for o in scene.objects.iter().filter(|o| o.category == "bin") {
        for b in world_boxes(&f, &scene, &o.name) {
            for k in &keepout {
                assert!(overlap(&b, &k.transformed(&rpose)) < 1e-6, "{} is inside the arm's volume", o.name);
            }
        }
    }
}

const CATEGORIES: &[&str] = &[
    "table",
    "workbench",
    "shelf",
    "pallet_rack",
    "cardboard_box",
    "crate",
    "bin",
    "pallet",
    "conveyor",
    "cabinet",
    "electrical_panel",
    "chair",
    "machine",
];

fn arb_plan() -> impl Strategy<Value = (ScenePlan, u64)> {
    let groups = prop::collection::vec((0..CATEGORIES.len(), 1u32..6), 1..6);
    let rels = prop::collection::vec((0usize..6, 0usize..6, 0u8..8), 0..4);
    (groups, rels, 4.0f64..20.0, 3.0f64..14.0, any::<bool>(), any::<u64>()).prop_map(
        |(groups, rels, w, d, fixed, seed)| {
            let mut plan = room(RoomKind::Room, Dims::new(w, d, 4.0), fixed);
            for (i, (c, n)) in groups.iter().enumerate() {
                plan.objects.push(group(&format!("g{i}"), CATEGORIES[*c], *n));
            }
            let n = plan.objects.len();
            for (a, b, k) in rels {
                let (a, b) = (a % n, b % n);
                if a == b {
                    continue;
                }
                let (s, t) = (format!("g{a}"), format!("g{b}"));
                let kind = match k {
                    0 => RelationKind::On { target: t },
                    1 => RelationKind::NextTo { target: t },
                    2 => RelationKind::AgainstWall { wall: None },
                    3 => RelationKind::InRow,
                    4 => RelationKind::InCorner { corner: None },
                    5 => RelationKind::Around { target: t },
                    6 => RelationKind::Under { target: t },
                    _ => RelationKind::FacingEachOther,
                };
                plan.relations.push(Relation { subject: s, kind });
            }
            (plan, seed)
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    #[test]
    fn for_any_plan_and_seed_nothing_overlaps_and_everything_is_inside((plan, seed) in arb_plan()) {
        let f = forge(plan, seed);
        let scene = solve_forged(&f, Vec::new(), seed);
        check_invariants(&f, &scene);
        // Every requested instance is placed or accounted for.
        let requested: u32 = f.plan.objects.iter().map(|o| o.count).sum();
        let missing: u32 = scene.left_out.iter().map(|l| l.requested - l.placed).sum();
        prop_assert_eq!(scene.objects.len() as u32 + missing, requested);
    }

    #[test]
    fn the_same_seed_gives_the_same_layout((plan, seed) in arb_plan()) {
        let f = forge(plan, seed);
        prop_assert_eq!(solve_forged(&f, Vec::new(), seed), solve_forged(&f, Vec::new(), seed));
    }
}

#[test]
fn a_small_kitchen_layout_is_stable() {
    let mut plan = room(RoomKind::Kitchen, Dims::new(5.0, 4.0, 2.7), false);
    plan.objects.push(group("table", "table", 1));
    plan.objects.push(group("chair", "chair", 2));
    plan.objects.push(group("cabinet", "cabinet", 1));
    plan.objects.push(group("box", "cardboard_box", 2));
    plan.relations.push(Relation { subject: "chair".into(), kind: RelationKind::Around { target: "table".into() } });
    plan.relations
        .push(Relation { subject: "cabinet".into(), kind: RelationKind::AgainstWall { wall: Some(Wall::North) } });
    plan.relations.push(Relation { subject: "box".into(), kind: RelationKind::On { target: "table".into() } });
    let f = forge(plan, 11);
    let scene = solve_forged(&f, Vec::new(), 11);
    check_invariants(&f, &scene);
    insta::assert_json_snapshot!("kitchen_layout", scene);
}

#[test]
fn a_shelf_asked_to_stand_in_front_of_an_electrical_panel_does_and_the_violation_is_named() {
    let mut plan = room(RoomKind::Workshop, Dims::new(10.0, 8.0, 4.0), true);
    plan.rules_profile = "industrial".into();
    plan.objects.push(group("panel", "electrical_panel", 1));
    plan.objects.push(group("shelf", "shelf", 1));
    plan.relations
        .push(Relation { subject: "panel".into(), kind: RelationKind::AgainstWall { wall: Some(Wall::North) } });
    plan.relations.push(Relation { subject: "shelf".into(), kind: RelationKind::InFrontOf { target: "panel".into() } });
    let f = forge(plan, 0);
    let scene = solve_forged(&f, Vec::new(), 0);
    check_invariants(&f, &scene);
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let v = scene
        .violations
        .iter()
        .find(|v| v.rule.starts_with("nec_working_space"))
        .expect("the NEC violation is reported");
    assert!(v.requested, "{v:?}");
    assert_eq!(v.objects, ["electrical_panel_1", "shelf_1"]);
    assert!(v.measured < v.required && v.required == 1.0, "{v:?}");
    assert!(v.standard.contains("NEC 110.26"));
}

#[test]
fn by_default_the_rules_are_met() {
    let mut plan = room(RoomKind::Workshop, Dims::new(10.0, 8.0, 4.0), true);
    plan.rules_profile = "industrial".into();
    plan.objects.push(group("panel", "electrical_panel", 2));
    plan.objects.push(group("machine", "machine", 2));
    plan.objects.push(group("shelf", "shelf", 3));
    plan.objects.push(group("bench", "workbench", 2));
    let f = forge(plan, 5);
    let scene = solve_forged(&f, Vec::new(), 5);
    check_invariants(&f, &scene);
    assert!(scene.violations.is_empty(), "{:#?}", scene.violations);
}

#[test]
fn chairs_with_nowhere_said_go_to_the_tables() {
    let mut plan = room(RoomKind::Office, Dims::new(8.0, 6.0, 3.0), true);
    plan.objects.push(group("table", "table", 2));
    plan.objects.push(group("chair", "chair", 8));
    let f = forge(plan, 2);
    let scene = solve_forged(&f, Vec::new(), 2);
    check_invariants(&f, &scene);
    let tables: Vec<_> = scene.objects.iter().filter(|o| o.category == "table").collect();
    for c in scene.objects.iter().filter(|o| o.category == "chair") {
        let d = tables.iter().map(|t| (c.pos[0] - t.pos[0]).hypot(c.pos[1] - t.pos[1])).fold(f64::INFINITY, f64::min);
        assert!(d < 1.3, "{} is {d:.2} m from the nearest table", c.name);
    }
    // Both tables get chairs.
    for t in &tables {
        let n = scene
            .objects
            .iter()
            .filter(|c| c.category == "chair" && (c.pos[0] - t.pos[0]).hypot(c.pos[1] - t.pos[1]) < 1.3)
            .count();
        assert!(n >= 2, "{} has {n} chairs", t.name);
    }
}
