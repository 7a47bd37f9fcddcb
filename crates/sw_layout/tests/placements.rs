#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue 20's placements as solver properties, for any seed: everything inside the room,
//! no two objects' collision boxes overlapping, and each stated placement held, measured
//! here from the laid-out collision boxes (not the solver's own checks).

use proptest::prelude::*;
use sw_geom::{Aabb, Pose};
use sw_plan::{
    Dims, EndOf, LaidOutScene, ObjectPlan, PlacedObject, Relation, RelationKind, RoomKind, RoomPlan, ScenePlan,
    Support, Wall,
};

mod common;
use common::{Forged, forge};

fn solve_forged(f: &Forged, seed: u64) -> LaidOutScene {
    common::solve_forged(f, Vec::new(), seed)
}

fn plan(kind: RoomKind, size: Dims, groups: &[(&str, &str, u32)], rels: Vec<(&str, RelationKind)>) -> ScenePlan {
    let mut p = ScenePlan::new("test", RoomPlan { kind, size, size_fixed: true, door: Wall::South });
    for (id, cat, n) in groups {
        p.objects.push(ObjectPlan {
            id: (*id).into(),
            category: (*cat).into(),
            phrase: (*id).into(),
            count: *n,
            color: None,
            size: Default::default(),
            proxy: None,
        });
    }
    for (s, k) in rels {
        p.relations.push(Relation { subject: s.into(), kind: k });
    }
    p
}

fn world_boxes(f: &Forged, o: &PlacedObject) -> Vec<Aabb> {
    let (_, _, asset, _) = f.assets.iter().find(|(n, ..)| *n == o.name).unwrap();
    let pose = Pose::from_pos_yaw(o.pos, o.yaw);
    asset.collision_aabbs().iter().map(|b| b.transformed(&pose)).collect()
}

fn footprint(f: &Forged, o: &PlacedObject) -> Aabb {
    world_boxes(f, o).iter().fold(Aabb::EMPTY, |a, b| a.union(b))
}

fn front(o: &PlacedObject) -> [f64; 2] {
    [-o.yaw.sin(), o.yaw.cos()]
}

/// Inside the room, nothing overlapping, nothing left out.
fn check(f: &Forged, s: &LaidOutScene) {
    assert!(s.left_out.is_empty(), "left out: {:?}", s.left_out);
    let half = [s.room.size.width / 2.0, s.room.size.depth / 2.0];
    let boxes: Vec<(String, Vec<Aabb>)> = s.objects.iter().map(|o| (o.name.clone(), world_boxes(f, o))).collect();
    for (name, bs) in &boxes {
        for b in bs {
            assert!(b.min[0] >= -half[0] - 1e-6 && b.max[0] <= half[0] + 1e-6, "{name} outside in x");
            assert!(b.min[1] >= -half[1] - 1e-6 && b.max[1] <= half[1] + 1e-6, "{name} outside in y");
        }
    }
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            for a in &boxes[i].1 {
                for b in &boxes[j].1 {
                    let o =
                        (0..3).map(|k| a.max[k].min(b.max[k]) - a.min[k].max(b.min[k])).fold(f64::INFINITY, f64::min);
                    assert!(o < 1e-4, "{} and {} overlap by {o} m", boxes[i].0, boxes[j].0);
                }
            }
        }
    }
}

fn of<'a>(s: &'a LaidOutScene, group: &str) -> Vec<&'a PlacedObject> {
    s.objects.iter().filter(|o| o.group == group).collect()
}

fn wall_gaps(half: [f64; 2], b: &Aabb) -> [(Wall, f64); 4] {
    [
        (Wall::North, half[1] - b.max[1]),
        (Wall::South, b.min[1] + half[1]),
        (Wall::East, half[0] - b.max[0]),
        (Wall::West, b.min[0] + half[0]),
    ]
}

fn center(b: &Aabb) -> [f64; 2] {
    [0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1])]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10, ..ProptestConfig::default() })]

    #[test]
    fn plants_take_distinct_corners_and_shelves_the_two_long_walls(seed in 0u64..10_000) {
        let p = plan(RoomKind::Warehouse, Dims::new(9.0, 6.0, 4.0),
            &[("plants", "potted_plant", 4), ("shelves", "shelf", 4)],
            vec![("plants", RelationKind::InCorners), ("shelves", RelationKind::OnOppositeWalls { long: true })]);
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let half = [4.5, 3.0];
        let mut corners = Vec::new();
        for o in of(&s, "plants") {
            let g = wall_gaps(half, &footprint(&f, o));
            let ns = if g[0].1 < g[1].1 { g[0] } else { g[1] };
            let ew = if g[2].1 < g[3].1 { g[2] } else { g[3] };
            prop_assert!(ns.1 <= 0.3 && ew.1 <= 0.3, "{} not in a corner: {g:?}", o.name);
            prop_assert!(!corners.contains(&(ns.0, ew.0)), "two plants in one corner");
            corners.push((ns.0, ew.0));
        }
        let mut walls = Vec::new();
        for o in of(&s, "shelves") {
            let g = wall_gaps(half, &footprint(&f, o));
            // Its back to the wall: the long wall its front looks away from.
            let w = if front(o)[1] < 0.0 { g[0] } else { g[1] };
            prop_assert!(w.1 <= 0.15, "{} not against a long wall: {g:?}", o.name);
            if !walls.contains(&w.0) { walls.push(w.0); }
        }
        prop_assert_eq!(walls.len(), 2, "{:?}", s.warnings);
    }

    #[test]
    fn chairs_flank_the_desk_and_a_sofa_faces_the_board(seed in 0u64..10_000) {
        let p = plan(RoomKind::Office, Dims::new(7.0, 6.0, 3.0),
            &[("desk", "desk", 1), ("chairs", "chair", 2), ("board", "whiteboard", 1), ("sofa", "sofa", 1)],
            vec![
                ("chairs", RelationKind::OnEachSideOf { target: "desk".into() }),
                ("board", RelationKind::AgainstWall { wall: Some(Wall::North) }),
                ("sofa", RelationKind::Facing { target: "board".into() }),
            ]);
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let desk = of(&s, "desk")[0];
        let (df, dc) = (front(desk), center(&footprint(&f, desk)));
        let sides: Vec<[f64; 2]> = of(&s, "chairs").iter().map(|c| {
            let cc = center(&footprint(&f, c));
            let d = [cc[0] - dc[0], cc[1] - dc[1]];
            [d[0] * df[0] + d[1] * df[1], d[0] * df[1] - d[1] * df[0]]
        }).collect();
        // Opposite sides along one of the desk's axes.
        let along_front = sides[0][0] * sides[1][0] < 0.0 && sides[0][0].abs() > sides[0][1].abs();
        let along_side = sides[0][1] * sides[1][1] < 0.0 && sides[0][1].abs() > sides[0][0].abs();
        prop_assert!(along_front || along_side, "chairs not on opposite sides: {sides:?}");
        let sofa = of(&s, "sofa")[0];
        let board = of(&s, "board")[0];
        let (sc, bc) = (center(&footprint(&f, sofa)), center(&footprint(&f, board)));
        let to = [bc[0] - sc[0], bc[1] - sc[1]];
        let cos = (front(sofa)[0] * to[0] + front(sofa)[1] * to[1]) / to[0].hypot(to[1]);
        prop_assert!(cos >= 30f64.to_radians().cos(), "the sofa is turned {} degrees from the board", cos.acos().to_degrees());
    }

    #[test]
    fn bins_stand_at_both_ends_and_desks_back_to_back(seed in 0u64..10_000) {
        let p = plan(RoomKind::Factory, Dims::new(12.0, 9.0, 4.0),
            &[("belt", "conveyor", 1), ("bins", "bin", 2), ("desks", "desk", 4)],
            vec![
                ("bins", RelationKind::AtEndOf { target: "belt".into(), end: Some(EndOf::Both) }),
                ("desks", RelationKind::BackToBack),
            ]);
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let belt = of(&s, "belt")[0];
        let bb = footprint(&f, belt);
        let x = [belt.yaw.cos(), belt.yaw.sin()];
        let span = |b: &Aabb| {
            let c = center(b);
            let m = c[0] * x[0] + c[1] * x[1];
            let h = 0.5 * ((b.max[0] - b.min[0]) * x[0].abs() + (b.max[1] - b.min[1]) * x[1].abs());
            (m - h, m + h)
        };
        let (lo, hi) = span(&bb);
        let ends: Vec<i8> = of(&s, "bins").iter().map(|o| {
            let (a, b) = span(&footprint(&f, o));
            if a >= hi - 0.05 && a - hi <= 1.5 { 1 } else if b <= lo + 0.05 && lo - b <= 1.5 { -1 } else { 0 }
        }).collect();
        prop_assert!(ends.contains(&1) && ends.contains(&-1), "bins not at both ends: {ends:?}");
        let desks = of(&s, "desks");
        let f0 = front(desks[0]);
        let opposite = desks.iter().filter(|d| front(d)[0] * f0[0] + front(d)[1] * f0[1] < -0.99).count();
        prop_assert_eq!(opposite, 2, "desks not in two rows facing away");
    }

    #[test]
    fn a_sink_stands_in_the_counter_run_and_cans_go_inside_a_bin(seed in 0u64..10_000) {
        let p = plan(RoomKind::Kitchen, Dims::new(5.0, 4.0, 2.7),
            &[("counter", "counter", 1), ("sink", "sink", 1), ("bin", "bin", 1), ("cans", "drink_can", 3)],
            vec![
                ("counter", RelationKind::AgainstWall { wall: Some(Wall::North) }),
                ("sink", RelationKind::SetInto { target: "counter".into() }),
                ("cans", RelationKind::Inside { target: "bin".into() }),
            ]);
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let (c, k) = (of(&s, "counter")[0], of(&s, "sink")[0]);
        prop_assert!((c.yaw - k.yaw).abs() < 1e-6, "the sink is turned differently");
        let (cb, kb) = (footprint(&f, c), footprint(&f, k));
        let gap = (kb.min[0] - cb.max[0]).max(cb.min[0] - kb.max[0]);
        prop_assert!((0.0..=0.05).contains(&gap), "the sink is {gap} m from the counter's end");
        // Against the north wall both face south: fronts flush on the south side.
        prop_assert!((kb.min[1] - cb.min[1]).abs() <= 0.03, "fronts not flush: {} vs {}", kb.min[1], cb.min[1]);
        for o in of(&s, "cans") {
            prop_assert!(matches!(&o.support, Support::Object { object, surface } if object.starts_with("bin") && surface == "inside"),
                "{} is not inside the bin: {:?}", o.name, o.support);
        }
    }
}

/// The object `o` rests on, if another object.
fn host<'a>(s: &'a LaidOutScene, o: &PlacedObject) -> Option<(&'a PlacedObject, String)> {
    let Support::Object { object, surface } = &o.support else { return None };
    s.objects.iter().find(|x| &x.name == object).map(|x| (x, surface.clone()))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10, ..ProptestConfig::default() })]

    /// "n cubes in a bowl on the table": every cube inside the bowl, on its floor or heaped
    /// on a cube that is, below its rim; a cube that does not fit is named in a warning.
    /// With a 30 cm bowl at least two go in (its floor holds one or more, one more heaps).
    #[test]
    fn things_in_a_bowl_go_inside_packed_or_heaped(seed in 0u64..10_000, n in 2u32..=5) {
        let p = plan(RoomKind::Tabletop, Dims::new(4.0, 4.0, 3.0),
            &[("table", "table", 1), ("bowl", "bowl", 1), ("cubes", "cube", n)],
            vec![("bowl", RelationKind::On { target: "table".into() }), ("cubes", RelationKind::Inside { target: "bowl".into() })]);
        let mut f = forge(p, seed);
        // The forge makes a bowl as wide as its contents need (the widest it comes in).
        for (_, group, asset, _) in f.assets.iter_mut().filter(|a| a.1 == "bowl") {
            let mut req = sw_catalog::AssetRequest::new("bowl", seed);
            req.overrides = vec![("width".into(), 0.3), ("depth".into(), 0.3), ("height".into(), 0.1)];
            *asset = sw_catalog::generate(&req).unwrap();
            prop_assert_eq!(group.as_str(), "bowl");
        }
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let bowl = of(&s, "bowl")[0];
        let rim = bowl.pos[2] + world_boxes(&f, bowl).iter().map(|b| b.max[2] - bowl.pos[2]).fold(0.0, f64::max);
        let mut inside = 0;
        for o in of(&s, "cubes") {
            let on_floor = |x: &PlacedObject| host(&s, x).is_some_and(|(h, surf)| h.name == bowl.name && surf == "inside");
            let heaped = host(&s, o).is_some_and(|(h, _)| h.group == "cubes" && on_floor(h))
                && footprint(&f, o).min[2] < rim;
            if on_floor(o) || heaped {
                inside += 1;
            } else {
                prop_assert!(s.warnings.iter().any(|w| w.message.contains(&format!("{}:", o.name))),
                    "{} is not in the bowl and no warning names it: {:?}", o.name, s.warnings);
            }
        }
        prop_assert!(inside >= 2.min(n), "only {inside} of {n} cubes in the bowl: {:?}", s.warnings);
    }

    /// "eight workbenches in a row" in a room whose size was not given: one row, the room
    /// grown to hold it (was: folded into two rows).
    #[test]
    fn a_row_that_does_not_fit_grows_a_room_of_no_stated_size(seed in 0u64..10_000) {
        let mut p = plan(RoomKind::Workshop, Dims::new(6.0, 5.0, 3.0), &[("benches", "workbench", 8)],
            vec![("benches", RelationKind::InRow)]);
        p.room.size_fixed = false;
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        prop_assert!(s.room.size.width > 6.0, "the room did not grow: {:?}", s.room.size);
        let cs: Vec<[f64; 2]> = of(&s, "benches").iter().map(|o| center(&footprint(&f, o))).collect();
        let (xs, ys): (Vec<f64>, Vec<f64>) = cs.iter().map(|c| (c[0], c[1])).unzip();
        let spread = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max) - v.iter().copied().fold(f64::INFINITY, f64::min);
        // Two rows stand a bench depth and a walkway apart; one row varies only with its members' depths.
        prop_assert!(spread(&xs).min(spread(&ys)) <= 0.25, "not one row: centres {cs:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10, ..ProptestConfig::default() })]

    /// "a bin and three trays in front of it" with no table: the bin, a small thing with no
    /// place of its own, stands before the trays look for it, and every tray's centre is
    /// 0–2.5 m beyond its front face, within its width ± 0.3 m (the judge's rule). Was:
    /// the trays first, along the far wall.
    #[test]
    fn several_things_stand_in_front_of_a_small_loose_thing(seed in 0u64..10_000, n in 1u32..=3) {
        let p = plan(RoomKind::Tabletop, Dims::new(4.0, 4.0, 3.0), &[("bin", "bin", 1), ("trays", "tray", n)],
            vec![("trays", RelationKind::InFrontOf { target: "bin".into() })]);
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let bin = of(&s, "bin")[0];
        let (bf, bb) = (front(bin), footprint(&f, bin));
        let bc = center(&bb);
        let side = [-bf[1], bf[0]];
        let half = |d: [f64; 2]| 0.5 * ((bb.max[0] - bb.min[0]) * d[0].abs() + (bb.max[1] - bb.min[1]) * d[1].abs());
        for o in of(&s, "trays") {
            let c = center(&footprint(&f, o));
            let d = [c[0] - bc[0], c[1] - bc[1]];
            let beyond = d[0] * bf[0] + d[1] * bf[1] - half(bf);
            let lateral = (d[0] * side[0] + d[1] * side[1]).abs();
            prop_assert!((0.0..=2.5).contains(&beyond) && lateral <= half(side) + 0.3,
                "{} is not in front of the bin: {beyond:.2} m beyond its face, {lateral:.2} m aside; {:?}", o.name, s.objects.iter().map(|x| (&x.name, x.pos, x.yaw)).collect::<Vec<_>>());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10, ..ProptestConfig::default() })]

    /// "a bowl on each side of the cutting board" (the board on a table): the bowls rest
    /// on the table, not on the board, on two opposite sides of it in its frame, each
    /// within 0.6 m of it. Was: on the board (no room), then on the floor.
    #[test]
    fn things_on_each_side_of_a_small_thing_stand_beside_it_on_its_host(seed in 0u64..10_000) {
        let p = plan(RoomKind::Kitchen, Dims::new(5.0, 4.0, 2.7),
            &[("table", "table", 1), ("board", "cutting_board", 1), ("bowls", "bowl", 2)],
            vec![("board", RelationKind::On { target: "table".into() }),
                 ("bowls", RelationKind::OnEachSideOf { target: "board".into() })]);
        let f = forge(p, seed);
        let s = solve_forged(&f, seed);
        check(&f, &s);
        let board = of(&s, "board")[0];
        let (bf, bb) = (front(board), footprint(&f, board));
        let bc = center(&bb);
        let right = [bf[1], -bf[0]];
        let mut sides = Vec::new();
        for o in of(&s, "bowls") {
            prop_assert!(host(&s, o).is_some_and(|(h, _)| h.group == "table"), "{} is not on the table: {:?}", o.name, o.support);
            let ob = footprint(&f, o);
            let c = center(&ob);
            let d = [c[0] - bc[0], c[1] - bc[1]];
            let half = |b: &Aabb, v: [f64; 2]| 0.5 * ((b.max[0] - b.min[0]) * v[0].abs() + (b.max[1] - b.min[1]) * v[1].abs());
            let (a, r) = (d[0] * bf[0] + d[1] * bf[1], d[0] * right[0] + d[1] * right[1]);
            let (ga, gr) = (a.abs() - half(&bb, bf) - half(&ob, bf), r.abs() - half(&bb, right) - half(&ob, right));
            prop_assert!(ga.max(gr) <= 0.6, "{} is {:.2} m from the board", o.name, ga.max(gr));
            sides.push(if a.abs() / half(&bb, bf) >= r.abs() / half(&bb, right) { (0, a.signum()) } else { (1, r.signum()) });
        }
        prop_assert!(sides[0].0 == sides[1].0 && sides[0].1 != sides[1].1, "not on opposite sides: {sides:?}; {:?} {:?}", s.objects.iter().map(|x| (&x.name, x.pos, x.yaw, x.size)).collect::<Vec<_>>(), s.warnings);
    }
}
