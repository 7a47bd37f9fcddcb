//! The order floor things are placed in: object groups and robots, each after what its
//! relations point at (a stool after its station, screens after the robot they
//! surround, an arm after the bench it works at); among the ready ones, objects before
//! robots, wall-bound and large groups first, plan order among equals.

use std::collections::BTreeMap;

use sw_geom::PlacementKind;
use sw_plan::RelationKind;

use crate::RobotMount;
use crate::attempt::Ctx;
use crate::floor::hosts_of;

/// A group of floor objects (their indices, in order) or one robot.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Unit {
    Group(String, Vec<usize>),
    Robot(usize),
}

impl Unit {
    fn key(&self) -> String {
        match self {
            Unit::Group(g, _) => g.clone(),
            Unit::Robot(ri) => format!("@robot{ri}"),
        }
    }
}

/// The floor units of `items` (object indices) and every robot not yet placed, in
/// placement order.
pub(crate) fn units(ctx: &Ctx<'_>, items: &[usize]) -> Vec<Unit> {
    let objects = &ctx.input.objects;
    let mut units: Vec<Unit> = Vec::new();
    for &i in items {
        let g = &objects[i].group;
        match units.iter_mut().find(|u| matches!(u, Unit::Group(x, _) if x == g)) {
            Some(Unit::Group(_, v)) => v.push(i),
            _ => units.push(Unit::Group(g.clone(), vec![i])),
        }
    }
    for ri in 0..ctx.input.robots.len() {
        if ctx.robots[ri].is_none() {
            units.push(Unit::Robot(ri));
        }
    }
    // What each unit waits for, by key.
    let group_keys: Vec<String> = units.iter().filter(|u| matches!(u, Unit::Group(..))).map(Unit::key).collect();
    let robot_keys = |group: &str| -> Vec<String> {
        ctx.input
            .robots
            .iter()
            .enumerate()
            .filter(|(ri, r)| r.group == group && ctx.robots[*ri].is_none())
            .map(|(ri, _)| format!("@robot{ri}"))
            .collect()
    };
    // A target resting on something (placed with the items, later): its host.
    let host_of = |t: &str| -> Option<String> {
        ctx.relations(t).into_iter().find_map(|r| match r {
            RelationKind::On { target } | RelationKind::Inside { target } if target != t => Some(target.clone()),
            _ => None,
        })
    };
    let resolve = |t: &str| -> Vec<String> {
        if group_keys.iter().any(|g| g == t) {
            vec![t.to_string()]
        } else if ctx.input.robots.iter().any(|r| r.group == t) {
            robot_keys(t)
        } else {
            host_of(t).filter(|h| group_keys.contains(h)).into_iter().collect()
        }
    };
    // An arm on the floor or on a stand of its own with work in several groups ("tends a
    // mill and a lathe", "sorts blocks from a bin into trays"): it stands beside its
    // first work (the anchor), and the rest of its work is placed after it, around it,
    // where it reaches — not the arm after all of it, beside the first.
    let split = |ri: usize| -> Option<(String, Vec<String>)> {
        let r = &ctx.input.robots[ri];
        if !crate::reach::has_arm(r) || matches!(r.mount, RobotMount::Surface { .. }) || ctx.robots[ri].is_some() {
            return None;
        }
        let rels = ctx.relations(&r.group);
        let mut work: Vec<String> = Vec::new();
        for rel in &rels {
            if let RelationKind::Reach { target } = rel {
                for k in resolve(target) {
                    if !k.starts_with('@') && !work.contains(&k) {
                        work.push(k);
                    }
                }
            }
        }
        // What its other relations name (and the group it tends) stays a dependency.
        let mut said: Vec<String> = r.near.iter().flat_map(|n| resolve(n)).collect();
        for rel in rels.iter().filter(|k| !matches!(k, RelationKind::Reach { .. })) {
            for t in rel.targets() {
                said.extend(resolve(t));
            }
        }
        let anchor = said.iter().find(|g| work.contains(g)).cloned().or_else(|| work.first().cloned())?;
        let rest: Vec<String> = work.into_iter().filter(|g| *g != anchor && !said.contains(g)).collect();
        (!rest.is_empty()).then_some((anchor, rest))
    };
    let splits: Vec<(usize, String, Vec<String>)> =
        (0..ctx.input.robots.len()).filter_map(|ri| split(ri).map(|(a, rest)| (ri, a, rest))).collect();
    let deps: BTreeMap<String, Vec<String>> = units
        .iter()
        .map(|u| {
            let mut d: Vec<String> = Vec::new();
            match u {
                Unit::Group(g, _) => {
                    for r in ctx.relations(g) {
                        // What rests on, or is loaded into, something is not a floor dependency.
                        if matches!(
                            r,
                            RelationKind::Loaded { .. } | RelationKind::FullOf { .. } | RelationKind::EachWith { .. }
                        ) {
                            continue;
                        }
                        for t in r.targets() {
                            d.extend(resolve(t));
                        }
                    }
                    for h in hosts_of(ctx, g) {
                        d.extend(resolve(&h));
                    }
                    for (ri, _, rest) in &splits {
                        if rest.contains(g) {
                            d.push(format!("@robot{ri}"));
                        }
                    }
                }
                Unit::Robot(ri) => {
                    let r = &ctx.input.robots[*ri];
                    if let RobotMount::Surface { group } = &r.mount {
                        d.extend(resolve(group));
                    }
                    if let Some(n) = &r.near {
                        d.extend(resolve(n));
                    }
                    let later: Vec<String> =
                        splits.iter().filter(|(x, ..)| x == ri).flat_map(|(_, _, rest)| rest.clone()).collect();
                    for rel in ctx.relations(&r.group) {
                        for t in rel.targets() {
                            if t != r.group {
                                d.extend(resolve(t).into_iter().filter(|k| !later.contains(k)));
                            }
                        }
                    }
                }
            }
            let me = u.key();
            d.retain(|x| *x != me);
            (me, d)
        })
        .collect();
    let priority = |u: &Unit| -> (u8, u8, u8, i64) {
        match u {
            Unit::Robot(_) => (1, 1, 1, 0),
            Unit::Group(g, idxs) => {
                let first = idxs[0];
                let o = &objects[first];
                let walled = o.asset.placement == PlacementKind::AgainstWall
                    || ctx.relations(g).iter().any(|r| {
                        matches!(
                            r,
                            RelationKind::AgainstWall { .. }
                                | RelationKind::InCorner { .. }
                                | RelationKind::AtEnd { .. }
                                | RelationKind::NearDoor
                                | RelationKind::OnTwoWalls
                                | RelationKind::OnOppositeWalls { .. }
                                | RelationKind::InCorners
                                | RelationKind::Leaning { .. }
                        )
                    });
                // Formations claim their space before loose pieces.
                let formation = ctx.relations(g).iter().any(|r| r.is_group_formation());
                // What goes under something claims the space before what goes around it.
                let under = ctx.relations(g).iter().any(|r| matches!(r, RelationKind::Under { .. }));
                // Corners are few: what is said to stand in them claims them first.
                let cornered = ctx
                    .relations(g)
                    .iter()
                    .any(|r| matches!(r, RelationKind::InCorner { .. } | RelationKind::InCorners));
                let s = ctx.bounds[first].size();
                let area = (s[0] * s[1] * 1e4) as i64;
                (0, u8::from(!under && !cornered), u8::from(!walled && !formation), -area)
            }
        }
    };
    let mut done: Vec<String> = Vec::new();
    let mut out: Vec<Unit> = Vec::new();
    while out.len() < units.len() {
        let ready = units
            .iter()
            .filter(|u| !done.contains(&u.key()) && deps[&u.key()].iter().all(|d| done.contains(d)))
            .min_by_key(|u| priority(u));
        // A cycle of relations: break it by priority.
        let pick = ready.or_else(|| units.iter().filter(|u| !done.contains(&u.key())).min_by_key(|u| priority(u)));
        match pick {
            Some(u) => {
                done.push(u.key());
                out.push(u.clone());
            }
            None => break,
        }
    }
    out
}
