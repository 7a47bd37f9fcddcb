//! Robot spawns: arms on work surfaces, pedestals or carts, facing their work; mobile
//! bases on open floor. Every robot's home-pose volume is kept clear of everything.

use std::f64::consts::PI;

use sw_geom::{Aabb, SupportSurface};
use sw_plan::{PlacedRobot, Support};

use crate::attempt::{Ctx, round};
use crate::candidates::free_grid;
use crate::floor::{fits_floor, keeps_egress};
use crate::frames::{Spot, robot_yaw_facing};
use crate::reach;
use crate::space::FLOOR_GAP;
use crate::{RobotItem, RobotMount};

/// Gap kept around a robot's home volume, m.
const ROBOT_GAP: f64 = 0.02;
/// Extra room around mobile bases so they can move, m.
const MOBILE_GAP: f64 = 0.25;

/// Places one robot (with its pedestal or cart): first with guards kept at their safety
/// distance, then (reported by the rules check) without, rather than leaving it out.
pub(crate) fn place_one(ctx: &mut Ctx<'_>, ri: usize) {
    if ctx.robots[ri].is_some() {
        // Pinned where an earlier layout put it.
        return;
    }
    let robot = ctx.input.robots[ri].clone();
    let mut ok = false;
    for strict in [true, false] {
        ctx.guards_strict = strict;
        ok = match &robot.mount {
            RobotMount::Surface { group } => on_surface(ctx, ri, &robot, group),
            RobotMount::Carrier { object } => on_carrier(ctx, ri, &robot, object),
            RobotMount::Floor => on_floor(ctx, ri, &robot),
        };
        if ok {
            break;
        }
    }
    ctx.guards_strict = true;
    if !ok {
        let s = ctx.space.half;
        ctx.warn(
            "robot_left_out",
            format!(
                "{}: no collision-free spawn found in the {:.1} × {:.1} m room; the robot was left out",
                robot.name,
                2.0 * s[0],
                2.0 * s[1]
            ),
        );
        ctx.floor_failures += 1;
    }
}

/// The robot-space rule: an arm's reach plus margin stays off the doorway.
/// The guard-distance rule: no guard within an arm's reach plus the safety distance
/// (only while `guards_strict`).
fn clear_of_guards(ctx: &Ctx<'_>, robot: &RobotItem, spot: &Spot) -> bool {
    let Some((_, tags, distance, _)) = ctx.profile.fence_distance() else { return true };
    if !robot.is_arm || !ctx.guards_strict {
        return true;
    }
    ctx.input.objects.iter().enumerate().all(|(i, o)| {
        let Some(p) = &ctx.placed[i] else { return true };
        if !tags.iter().all(|t| o.has_tag(t)) {
            return true;
        }
        let b = ctx.bounds[i].transformed(&p.spot.pose());
        let dx = (b.min[0] - spot.x).max(spot.x - b.max[0]).max(0.0);
        let dy = (b.min[1] - spot.y).max(spot.y - b.max[1]).max(0.0);
        dx.hypot(dy) >= robot.reach + distance
    })
}

fn clear_of_doorway(ctx: &Ctx<'_>, robot: &RobotItem, spot: &Spot) -> bool {
    if !clear_of_guards(ctx, robot, spot) {
        return false;
    }
    let Some((_, margin, _)) = ctx.profile.robot_space() else { return true };
    if !robot.is_arm {
        return true;
    }
    let z = &ctx.door_zone;
    let dx = (z.min[0] - spot.x).max(spot.x - z.max[0]).max(0.0);
    let dy = (z.min[1] - spot.y).max(spot.y - z.max[1]).max(0.0);
    dx.hypot(dy) >= robot.reach + margin
}

fn robot_boxes(robot: &RobotItem, spot: &Spot) -> Vec<Aabb> {
    spot.boxes(&robot.keepout)
}

/// On the top surface of an instance of `group`: base fully on the surface, near its
/// back edge, working towards the surface's centre.
fn on_surface(ctx: &mut Ctx<'_>, ri: usize, robot: &RobotItem, group: &str) -> bool {
    let mut hosts = ctx.placed_instances(group);
    let turn = ctx.input.robots[..ri].iter().filter(|r| r.mount == robot.mount).count();
    if !hosts.is_empty() {
        let n = hosts.len();
        hosts.rotate_left(turn % n);
    }
    // Where its own relations say ("on the counter next to the sink") first.
    let rels: Vec<sw_plan::RelationKind> =
        ctx.relations(&robot.group).into_iter().filter(|r| crate::relate::is_positional(r)).cloned().collect();
    for strict in [true, false] {
        if !strict && rels.is_empty() {
            break;
        }
        let checks: Vec<crate::relate::Check<'_>> =
            rels.iter().map(|r| crate::relate::Check::new(ctx, r).in_group(ctx, &robot.group)).collect();
        // "an arm on the edge of the table": its base near an edge of the top.
        let edge = ctx.relations(&robot.group).iter().any(|r| matches!(r, sw_plan::RelationKind::OnEdgeOf { .. }));
        // Things said to be between arms on one surface need the length of it: the arms
        // stand at its ends.
        // So do arms said to stand on either side of it: its ends leave their home poses
        // apart.
        let ends = ctx.input.plan.relations.iter().any(|r| {
            matches!(&r.kind, sw_plan::RelationKind::Between { first, second } if *first == robot.group || *second == robot.group)
                || (r.subject == robot.group && matches!(&r.kind, sw_plan::RelationKind::OnEachSideOf { target } if target == group))
        });
        // What else it is said to reach that already stands (a stove beside its counter, a
        // belt by its table): spots from which it reaches all of that first.
        let work = reach_targets(ctx, robot, group);
        let misses = |ctx: &Ctx<'_>, spot: &Spot| {
            work.iter().filter(|&&i| !reach::can_work_at(ctx, [spot.x, spot.y, spot.z], robot.reach, i)).count()
        };
        let mut chosen: Option<(usize, Spot, Spot, SupportSurface, Vec<Aabb>)> = None;
        'hosts: for (hi, hspot) in &hosts {
            let surfaces: Vec<SupportSurface> =
                ctx.input.objects[*hi].asset.surfaces.iter().filter(|s| s.clearance.is_none()).cloned().collect();
            for surf in surfaces {
                let mut spots = surface_spots(ctx, robot, hspot, &surf, ends);
                if !work.is_empty() {
                    // Stable: the preferred order stands among spots that reach as much.
                    spots.sort_by_key(|(spot, _)| misses(ctx, spot));
                }
                for (spot, boxes) in spots {
                    if edge && !near_edge(&spot, hspot, &surf) {
                        continue;
                    }
                    let body = crate::relate::robot_body(robot, &spot);
                    if strict && !checks.iter().all(|c| c.holds(ctx, &body, 1)) {
                        continue;
                    }
                    chosen = Some((*hi, *hspot, spot, surf.clone(), boxes));
                    break 'hosts;
                }
            }
        }
        drop(checks);
        if let Some((hi, hspot, spot, surf, boxes)) = chosen {
            if !strict {
                let unmet = described(ctx.input.plan, &robot.group, &rels);
                ctx.warn("relation_unmet", format!("{}: could not keep {unmet} on its surface", robot.name));
            }
            let host_name = ctx.input.objects[hi].name.clone();
            let coverage = coverage(&spot, robot, &hspot, &surf);
            commit(ctx, ri, robot, spot, boxes, "surface", Some(host_name), Some(coverage));
            return true;
        }
    }
    false
}

/// The placed objects an arm on a surface of `host` is said to reach besides its host
/// ("a Panda on the counter reaching the stove"): instances of every group its `reach`
/// relations name. What stands on surfaces is placed after the arms (and kept in reach
/// by them), so only what already stands counts here.
fn reach_targets(ctx: &Ctx<'_>, robot: &RobotItem, host: &str) -> Vec<usize> {
    let mut out = Vec::new();
    for r in ctx.relations(&robot.group) {
        let sw_plan::RelationKind::Reach { target } = r else { continue };
        if target == host {
            continue;
        }
        out.extend(ctx.placed_instances(target).into_iter().map(|(i, _)| i));
    }
    out
}

/// Whether a base at `spot` stands within 0.15 m of an edge of a host's surface.
fn near_edge(spot: &Spot, host: &Spot, surf: &SupportSurface) -> bool {
    let (s, c) = host.yaw.sin_cos();
    let (dx, dy) = (spot.x - host.x, spot.y - host.y);
    let (lx, ly) = (c * dx + s * dy, -s * dx + c * dy);
    (lx - surf.min[0]).min(surf.max[0] - lx).min(ly - surf.min[1]).min(surf.max[1] - ly) <= 0.15
}

/// Free spawns of an arm on a surface: the back edge centre first, then along the edges,
/// then inwards, working towards the surface's centre.
fn surface_spots(
    ctx: &Ctx<'_>,
    robot: &RobotItem,
    hspot: &Spot,
    surf: &SupportSurface,
    ends: bool,
) -> Vec<(Spot, Vec<Aabb>)> {
    let (cx, cy) = (0.5 * (surf.min[0] + surf.max[0]), 0.5 * (surf.min[1] + surf.max[1]));
    let m = robot.base_radius + 0.01;
    let mut local: Vec<(f64, f64)> = Vec::new();
    let mut x = surf.min[0] + m;
    while x <= surf.max[0] - m + 1e-9 {
        let mut y = surf.min[1] + m;
        while y <= surf.max[1] - m + 1e-9 {
            local.push((x, y));
            y += 0.05;
        }
        x += 0.05;
    }
    let back = (cx, surf.min[1] + m);
    // Towards an end of the surface's length, centred across it, no further from the
    // middle than keeps it within reach of what lies half way to an arm at the other end.
    let long_x = surf.max[0] - surf.min[0] >= surf.max[1] - surf.min[1];
    let half_len = if long_x { 0.5 * (surf.max[0] - surf.min[0]) } else { 0.5 * (surf.max[1] - surf.min[1]) } - m;
    let apart = half_len.min(0.9 * robot.reach);
    let key = |p: &(f64, f64)| {
        if ends {
            let (along, across) = if long_x { (p.0 - cx, p.1 - cy) } else { (p.1 - cy, p.0 - cx) };
            2.0 * (along.abs() - apart).abs() + across.abs()
        } else {
            (p.0 - back.0).abs() + 2.0 * (p.1 - back.1).abs()
        }
    };
    local.sort_by(|a, b| key(a).total_cmp(&key(b)));
    let mut out = Vec::new();
    for (lx, ly) in local {
        let p = hspot.apply([lx, ly, surf.z]);
        let c = hspot.apply([cx, cy, surf.z]);
        let facing = robot_yaw_facing(c[0] - p[0], c[1] - p[1]);
        // Arms at the ends of a surface with things between them work across it (their
        // home pose then leaves the length between them free), towards its front.
        // Of the two ways across, the one whose home volume reaches least towards the
        // middle first.
        let across = [-hspot.yaw.sin(), hspot.yaw.cos()];
        let yaws = if ends {
            let inward = |yaw: f64| {
                let k = crate::space::union(&Spot::new(p[0], p[1], p[2], yaw).boxes(&robot.keepout));
                let d = [c[0] - p[0], c[1] - p[1]];
                let len = d[0].hypot(d[1]).max(1e-9);
                let u = [d[0] / len, d[1] / len];
                let far = |x: f64, y: f64| (x - p[0]) * u[0] + (y - p[1]) * u[1];
                far(k.min[0], k.min[1])
                    .max(far(k.max[0], k.max[1]))
                    .max(far(k.min[0], k.max[1]))
                    .max(far(k.max[0], k.min[1]))
            };
            let mut v = vec![robot_yaw_facing(across[0], across[1]), robot_yaw_facing(-across[0], -across[1]), facing];
            v.sort_by(|a, b| inward(*a).total_cmp(&inward(*b)));
            v
        } else if (c[0] - p[0]).hypot(c[1] - p[1]) < 0.05 {
            vec![hspot.yaw + PI / 2.0, hspot.yaw, hspot.yaw + PI, hspot.yaw - PI / 2.0]
        } else {
            vec![facing]
        };
        for yaw in yaws {
            let spot = Spot::new(p[0], p[1], p[2], yaw);
            let boxes = robot_boxes(robot, &spot);
            if ctx.space.fits(&boxes, ROBOT_GAP, &[], false, &[]) && clear_of_doorway(ctx, robot, &spot) {
                out.push((spot, boxes));
            }
        }
    }
    out
}

/// How many poses beside its work that keep everything an arm on a stand is compared
/// at, for the one that reaches most of its work.
const GOOD_POSES: usize = 160;
/// How much more of its work surfaces a pose must reach to be preferred to an earlier one.
const SHARE_STEP: f64 = 0.05;

/// A carrier's pose, the robot's on it, its boxes, the instance it works at, and whether
/// the work is in reach and its relations hold.
type CarrierSpot = (Spot, Spot, Vec<Aabb>, Option<usize>, bool, bool);

/// On a pedestal or cart made for it, standing beside its work with the work in reach.
fn on_carrier(ctx: &mut Ctx<'_>, ri: usize, robot: &RobotItem, carrier: &str) -> bool {
    let Some(ci) = ctx.input.objects.iter().position(|o| o.name == carrier) else {
        return false;
    };
    let top = ctx.input.objects[ci]
        .asset
        .surfaces
        .iter()
        .filter(|s| s.clearance.is_none())
        .map(|s| s.z)
        .fold(f64::NAN, f64::max);
    let top = if top.is_finite() { top } else { ctx.bounds[ci].max[2] };
    // Work to stand beside: the named group, else any work surface, conveyor or machine.
    let named = reach::work_group(ctx, robot);
    let work_groups: Vec<String> = match &named {
        Some(g) => vec![g.clone()],
        None => {
            let mut gs: Vec<String> = Vec::new();
            for (i, o) in ctx.input.objects.iter().enumerate() {
                let worky = o.has_tag("surface") || o.category == "conveyor" || o.has_tag("machine");
                if worky && ctx.placed[i].is_some() && o.carries_robot.is_none() && !gs.contains(&o.group) {
                    gs.push(o.group.clone());
                }
            }
            gs
        }
    };
    let turn = ctx.input.robots[..ri].iter().filter(|r| matches!(r.mount, RobotMount::Carrier { .. })).count();
    let cb = ctx.bounds[ci];
    // Beside its work first (kept only with the work in reach), then where its own
    // relations say, then anywhere (reported).
    let mut candidates: Vec<(Spot, bool)> = Vec::new();
    for g in &work_groups {
        for s in crate::candidates::beside(ctx, &cb, g, turn) {
            candidates.push((s, true));
        }
    }
    let rels: Vec<sw_plan::RelationKind> =
        ctx.relations(&robot.group).into_iter().filter(|r| crate::relate::is_positional(r)).cloned().collect();
    for r in &rels {
        candidates
            .extend(crate::candidates::for_relation(ctx, &cb, &robot.group, turn, r).into_iter().map(|s| (s, true)));
    }
    // With no work named and nothing said, open floor is as good as anywhere.
    let anywhere = named.is_none() && rels.is_empty();
    for s in free_grid(ctx, &cb, &format!("{}#carrier", robot.group), true).iter().copied() {
        candidates.push((s, anywhere));
    }
    // The arm's stand is the operator's place at its work: it may stand in the work's
    // keep-clear space.
    let exempt: Vec<String> = work_groups
        .iter()
        .flat_map(|g| ctx.instances(g).into_iter().map(|i| ctx.input.objects[i].name.clone()).collect::<Vec<_>>())
        .collect();
    let ignore: Vec<&str> = exempt.iter().map(String::as_str).collect();
    let checks: Vec<crate::relate::Check<'_>> =
        rels.iter().map(|r| crate::relate::Check::new(ctx, r).in_group(ctx, &robot.group)).collect();
    let mut fallback: Option<CarrierSpot> = None;
    let mut fallback_score = 0u8;
    let mut best: Option<((usize, f64), CarrierSpot)> = None;
    let mut tried = 0usize;
    for (spot, preferred) in candidates {
        // Past the places beside its work, a place in reach found there is the best left.
        if !preferred && (fallback_score >= 2 || best.is_some()) {
            break;
        }
        if !fits_floor(ctx, ci, &spot, &ignore) {
            continue;
        }
        let base = spot.apply([0.0, 0.0, top]);
        // The instance it works at, and that it can: a belt within reach, a surface at hand.
        let work = work_groups.iter().find_map(|g| reach::work_instance(ctx, g, base));
        // Every instance of its work within reach ("next to two pallets"), else at least one.
        let (reached, instances) = match (&named, robot.is_arm) {
            (Some(g), true) => reach::instances_in_reach(ctx, base, robot.reach, g),
            _ => (1, 1),
        };
        let in_reach = reached > 0;
        let body = crate::relate::Body::object(&ctx.local[ci], &spot);
        let holds = checks.iter().all(|c| c.holds(ctx, &body, 1));
        let good = preferred && reached == instances && holds;
        // A fallback is replaced only by a better one: in reach beats out of reach.
        let score = u8::from(preferred && in_reach) * 2 + u8::from(holds);
        if !good && fallback_score >= score && fallback.is_some() {
            continue;
        }
        let (tx, ty) = work.and_then(|w| reach::work_point(ctx, base, w)).map_or((0.0, 0.0), |p| (p[0], p[1]));
        let yaw = robot_yaw_facing(tx - base[0], ty - base[1]);
        let rspot = Spot::new(base[0], base[1], base[2], yaw);
        let boxes = robot_boxes(robot, &rspot);
        if !ctx.space.fits(&boxes, ROBOT_GAP, &[], false, &[]) || !clear_of_doorway(ctx, robot, &rspot) {
            continue;
        }
        if !keeps_egress(ctx, ci, &spot) {
            continue;
        }
        if !good {
            fallback = Some((spot, rspot, boxes, work, in_reach, holds));
            fallback_score = score;
            continue;
        }
        // Of the poses beside its work, the one from which it reaches most of it: all of
        // what it is said to reach, then the most of its work surfaces (the first pose
        // beside a table may be at its far end).
        let key = reach::work_in_reach(ctx, robot, base, named.as_deref());
        // Among poses that reach about as much, the first (the preferred order: facing
        // its work, centred on a side) stays.
        if best.as_ref().is_none_or(|(k, _)| key.0 < k.0 || (key.0 == k.0 && key.1 > k.1 + SHARE_STEP)) {
            best = Some((key, (spot, rspot, boxes, work, true, true)));
        }
        tried += 1;
        if (key.0 == 0 && key.1 >= 0.999) || tried >= GOOD_POSES {
            break;
        }
    }
    drop(checks);
    if let Some((_, (spot, rspot, boxes, work, ..))) = best {
        commit_carrier(ctx, ri, robot, ci, spot, rspot, boxes, work);
        return true;
    }
    if let Some((spot, rspot, boxes, work, in_reach, holds)) = fallback {
        let plan = ctx.input.plan;
        let mut unmet: Vec<String> = Vec::new();
        if !holds {
            unmet.extend(
                rels.iter()
                    .map(|r| plan.describe(&sw_plan::Relation { subject: robot.group.clone(), kind: r.clone() })),
            );
        }
        if !in_reach && let Some(g) = &named {
            unmet.push(plan.describe(&sw_plan::Relation {
                subject: robot.group.clone(),
                kind: sw_plan::RelationKind::Reach { target: g.clone() },
            }));
        }
        ctx.warn(
            "relation_unmet",
            format!(
                "{}: could not keep {} (no free floor beside its work); placed nearby",
                robot.name,
                unmet.join(", ")
            ),
        );
        commit_carrier(ctx, ri, robot, ci, spot, rspot, boxes, work);
        return true;
    }
    false
}

#[allow(clippy::too_many_arguments)]
fn commit_carrier(
    ctx: &mut Ctx<'_>,
    ri: usize,
    robot: &RobotItem,
    ci: usize,
    spot: Spot,
    rspot: Spot,
    boxes: Vec<Aabb>,
    work: Option<usize>,
) {
    ctx.commit(ci, spot, Support::Floor);
    let kind = if ctx.input.objects[ci].category == "mobile_cart" { "mobile_base" } else { "pedestal" };
    let cov = work.and_then(|w| {
        let ws = ctx.placed[w].as_ref()?.spot;
        let surf = reach::top_surface(ctx, w)?;
        Some(coverage(&rspot, robot, &ws, &surf))
    });
    let carrier_name = ctx.input.objects[ci].name.clone();
    commit(ctx, ri, robot, rspot, boxes, kind, Some(carrier_name), cov.filter(|_| robot.is_arm));
}

/// A robot standing on the floor (mobile bases, arms on their own base plate): where its
/// relations say ("between the racks", "near the door"), near its work if it has one;
/// a mobile base with nothing said drives in the aisle when the scene has one.
fn on_floor(ctx: &mut Ctx<'_>, ri: usize, robot: &RobotItem) -> bool {
    let mut rels: Vec<sw_plan::RelationKind> =
        ctx.relations(&robot.group).into_iter().filter(|r| crate::relate::is_positional(r)).cloned().collect();
    let implicit = rels.is_empty() && robot.near.is_none() && !robot.is_arm;
    if implicit && let Some(aisle) = aisle_group(ctx) {
        rels.push(sw_plan::RelationKind::Between { first: aisle.clone(), second: aisle });
    }
    let mut targets: Vec<(f64, f64)> = Vec::new();
    if let Some(g) = &robot.near {
        targets.extend(ctx.placed_instances(g).iter().map(|(_, s)| (s.x, s.y)));
    }
    // A robot with an arm (a mobile manipulator, an arm on its own base plate) stands
    // where its arm reaches its work: the group it works at, and all it is said to reach.
    let work = reach::work_group(ctx, robot);
    if robot.near.is_none()
        && let Some(g) = &work
    {
        targets.extend(ctx.placed_instances(g).iter().map(|(i, s)| {
            let c = s.apply(ctx.bounds[*i].center());
            (c[0], c[1])
        }));
    }
    let reaches_work = |ctx: &Ctx<'_>, x: f64, y: f64| {
        (work.is_none()
            && !ctx.relations(&robot.group).iter().any(|r| matches!(r, sw_plan::RelationKind::Reach { .. })))
            || reach::work_in_reach(ctx, robot, reach::arm_base(robot, [x, y, 0.0]), work.as_deref()).0 == 0
    };
    let [hw, hd] = ctx.space.half;
    let keep = crate::space::union(&robot.keepout);
    let mut pts: Vec<(f64, f64, Option<f64>)> = Vec::new();
    for r in &rels {
        // Where it works at or faces something, it turns to face it (below).
        let faces = matches!(
            r,
            sw_plan::RelationKind::Facing { .. }
                | sw_plan::RelationKind::OnEachSideOf { .. }
                | sw_plan::RelationKind::AtEndOf { .. }
        );
        if let (true, Some(t)) = (faces, r.targets().first()) {
            for (_, b) in crate::relate::bodies(ctx, t) {
                let c = b.center();
                if !targets.iter().any(|p| (p.0 - c[0]).abs() < 1e-9 && (p.1 - c[1]).abs() < 1e-9) {
                    targets.push((c[0], c[1]));
                }
            }
        }
        for s in crate::candidates::for_relation(ctx, &keep, &robot.group, ri, r) {
            pts.push((s.x, s.y, (!faces).then_some(s.yaw)));
        }
    }
    let step = 0.1;
    let mut grid = Vec::new();
    let mut x = -hw;
    while x <= hw {
        let mut y = -hd;
        while y <= hd {
            grid.push((x, y, None));
            y += step;
        }
        x += step;
    }
    let turn = ri as f64;
    let key = |p: &(f64, f64, Option<f64>)| -> f64 {
        match targets.first() {
            Some(t) => (p.0 - t.0).hypot(p.1 - t.1),
            // Open floor a little off centre, different for each robot.
            None => (p.0 - 0.3 * turn).hypot(p.1 + 0.2 * hd.min(2.0)),
        }
    };
    grid.sort_by(|a, b| key(a).total_cmp(&key(b)));
    pts.extend(grid);
    let names: Vec<String> = ctx.input.objects.iter().map(|o| o.name.clone()).collect();
    let object_names: Vec<&str> = names.iter().map(String::as_str).collect();
    let checks: Vec<crate::relate::Check<'_>> =
        rels.iter().map(|r| crate::relate::Check::new(ctx, r).in_group(ctx, &robot.group)).collect();
    let mut fallback: Option<(Spot, Vec<Aabb>)> = None;
    for (x, y, given) in pts {
        // Facing the nearest thing it works at.
        let (tx, ty) = targets
            .iter()
            .copied()
            .min_by(|a, b| (a.0 - x).hypot(a.1 - y).total_cmp(&(b.0 - x).hypot(b.1 - y)))
            .unwrap_or((0.0, 0.0));
        // A relation's pose keeps its yaw (along an aisle); else facing its work.
        let yaw = match given {
            Some(y) => y,
            None if (tx - x).hypot(ty - y) < 1e-6 => 0.0,
            None => robot_yaw_facing(tx - x, ty - y),
        };
        let spot = Spot::new(x, y, 0.0, yaw);
        let boxes = robot_boxes(robot, &spot);
        let body = crate::relate::robot_body(robot, &spot);
        let all_hold = checks.iter().all(|c| c.holds(ctx, &body, 1)) && reaches_work(ctx, x, y);
        if !all_hold && fallback.is_some() {
            continue;
        }
        let inflated: Vec<Aabb> = boxes
            .iter()
            .map(|b| Aabb {
                min: [b.min[0] - MOBILE_GAP, b.min[1] - MOBILE_GAP, b.min[2]],
                max: [b.max[0] + MOBILE_GAP, b.max[1] + MOBILE_GAP, b.max[2]],
            })
            .collect();
        let inside = ctx.space.inside(&crate::space::union(&inflated));
        let fronts = ctx.access.clone();
        // A mobile robot moves out of the way: it blocks no exit route (an arm standing
        // on the floor does).
        let keeps_routes = || -> bool {
            !robot.is_arm
                || ctx.egress.clone().is_none_or(|mut g| g.keeps_connected(&crate::space::union(&boxes), &fronts))
        };
        // A mobile robot may stand in the access space in front of shelving (that is
        // what the space is for), not in the doorway.
        if inside && ctx.space.fits(&boxes, MOBILE_GAP.max(FLOOR_GAP), &[], true, &object_names) && keeps_routes() {
            if all_hold {
                drop(checks);
                commit(ctx, ri, robot, spot, boxes, "floor", None, None);
                return true;
            }
            fallback = Some((spot, boxes));
        }
    }
    drop(checks);
    if let Some((spot, boxes)) = fallback {
        if !implicit {
            let unmet = described(ctx.input.plan, &robot.group, &rels);
            ctx.warn(
                "relation_unmet",
                format!("{}: could not keep {unmet} (no free floor there); placed nearby", robot.name),
            );
        }
        commit(ctx, ri, robot, spot, boxes, "floor", None, None);
        return true;
    }
    false
}

/// A group standing in rows that face each other or in aisles: the aisle a mobile robot
/// drives in.
fn aisle_group(ctx: &Ctx<'_>) -> Option<String> {
    ctx.input.plan.relations.iter().find_map(|r| {
        let aisle = matches!(r.kind, sw_plan::RelationKind::FacingEachOther | sw_plan::RelationKind::InAisles);
        (aisle && ctx.placed_instances(&r.subject).len() >= 2).then(|| r.subject.clone())
    })
}

#[allow(clippy::too_many_arguments)]
fn commit(
    ctx: &mut Ctx<'_>,
    ri: usize,
    robot: &RobotItem,
    spot: Spot,
    boxes: Vec<Aabb>,
    mount: &str,
    mounted_on: Option<String>,
    reach_coverage: Option<f64>,
) {
    if mount == "floor"
        && let Some(g) = &mut ctx.egress
    {
        g.add(&crate::space::union(&boxes));
    }
    ctx.space.add(&robot.name, boxes, mount == "floor");
    ctx.robots[ri] = Some(PlacedRobot {
        name: robot.name.clone(),
        group: robot.group.clone(),
        model: robot.model.clone(),
        pos: [round(spot.x), round(spot.y), round(spot.z)],
        yaw: spot.yaw,
        mount: mount.to_string(),
        mounted_on,
        reach_coverage: reach_coverage.map(|c| (c * 1000.0).round() / 1000.0),
    });
}

/// The fraction of a work surface an arm at `spot` can reach: sample points on the
/// surface within [0.15 m, reach] of the shoulder.
fn coverage(spot: &Spot, robot: &RobotItem, host: &Spot, surf: &SupportSurface) -> f64 {
    if robot.reach <= 0.0 {
        return 0.0;
    }
    let shoulder = [spot.x, spot.y, spot.z + 0.16];
    let n = 16;
    let mut hit = 0;
    for i in 0..n {
        for j in 0..n {
            let lx = surf.min[0] + (surf.max[0] - surf.min[0]) * (i as f64 + 0.5) / n as f64;
            let ly = surf.min[1] + (surf.max[1] - surf.min[1]) * (j as f64 + 0.5) / n as f64;
            let p = host.apply([lx, ly, surf.z]);
            let d = ((p[0] - shoulder[0]).powi(2) + (p[1] - shoulder[1]).powi(2) + (p[2] - shoulder[2]).powi(2)).sqrt();
            if (0.15..=robot.reach).contains(&d) {
                hit += 1;
            }
        }
    }
    f64::from(hit) / f64::from(n * n)
}

/// The robot group's relations `rels` as the prompt put them, for a warning.
fn described(plan: &sw_plan::ScenePlan, group: &str, rels: &[sw_plan::RelationKind]) -> String {
    let said: Vec<String> = rels
        .iter()
        .map(|r| plan.describe(&sw_plan::Relation { subject: group.to_string(), kind: r.clone() }))
        .collect();
    said.join(", ")
}
