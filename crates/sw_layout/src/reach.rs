//! An arm's reach of its work. An arm works at the group it is mounted on or tends ("a
//! Panda picking from the belt"); everything resting on that group must be within the
//! reach of an arm that works there (of every arm said to reach it), and so must a
//! conveyor's centreline. Distances are 3D from the shoulder — the registry has no
//! shoulder heights, so the solver takes a point [`SHOULDER`] above the base and keeps
//! work within [`REACH_USE`] of the registry's reach, which holds for shoulders 0.16–0.33 m
//! high (UR, Kinova, Panda) — to an item's centre, or the nearest point of a belt's
//! centreline at its top. The report measures from the arm's real shoulder.

use sw_geom::SupportSurface;
use sw_plan::RelationKind;

use crate::attempt::Ctx;
use crate::frames::Spot;
use crate::{RobotItem, RobotMount};

/// Share of the registry reach the solver uses.
pub(crate) const REACH_USE: f64 = 0.92;
/// Height of the solver's shoulder point above the arm's base, m.
pub(crate) const SHOULDER: f64 = 0.25;

/// Whether a robot has an arm that works: a fixed arm, or a mobile manipulator (its arm
/// on a wheeled base; `is_arm` is false for it, it drives on the floor).
pub(crate) fn has_arm(robot: &RobotItem) -> bool {
    robot.is_arm || robot.reach > 0.0
}

/// The base the solver's reach is measured from for a robot standing at `pos`: a fixed
/// arm's own base; for a mobile manipulator, its arm's base on the deck — the registry
/// has no deck heights, so its shoulder is taken at [`MOBILE_SHOULDER`] of the robot's
/// height at home (the built-in one's is 0.66 m of 1.14 m).
pub(crate) fn arm_base(robot: &RobotItem, pos: [f64; 3]) -> [f64; 3] {
    if robot.is_arm {
        return pos;
    }
    let height = robot.keepout.iter().map(|b| b.max[2]).fold(0.0, f64::max);
    [pos[0], pos[1], pos[2] + (MOBILE_SHOULDER * height - SHOULDER).max(0.0)]
}

/// A mobile manipulator's shoulder height, as a share of its height at home.
const MOBILE_SHOULDER: f64 = 0.55;

/// The solver's shoulder point of an arm whose base is at `base`.
pub(crate) fn shoulder(base: [f64; 3]) -> [f64; 3] {
    [base[0], base[1], base[2] + SHOULDER]
}

/// Whether an arm at `base` with `reach` reaches `p`.
pub(crate) fn reaches(base: [f64; 3], reach: f64, p: [f64; 3]) -> bool {
    dist(shoulder(base), p) <= REACH_USE * reach
}

/// The group an arm works at: the surface it is mounted on, else the group it tends
/// (`near`), else the target of a reach relation.
pub(crate) fn work_group(ctx: &Ctx<'_>, robot: &RobotItem) -> Option<String> {
    if !has_arm(robot) {
        return None;
    }
    if let RobotMount::Surface { group } = &robot.mount {
        return Some(group.clone());
    }
    robot.near.clone().or_else(|| {
        let rels = ctx.relations(&robot.group);
        rels.iter()
            .find_map(|r| match r {
                RelationKind::Reach { target } => Some(target.clone()),
                _ => None,
            })
            // An arm said to be at, beside, behind, facing or on either side of a thing
            // works at it.
            .or_else(|| {
                rels.iter().find_map(|r| match r {
                    RelationKind::NextTo { target }
                    | RelationKind::Near { target }
                    | RelationKind::InFrontOf { target }
                    | RelationKind::Behind { target }
                    | RelationKind::Facing { target }
                    | RelationKind::OnEachSideOf { target }
                    | RelationKind::AtEndOf { target, .. }
                    | RelationKind::OnEdgeOf { target }
                        if is_work(ctx, target) =>
                    {
                        Some(target.clone())
                    }
                    _ => None,
                })
            })
    })
}

/// Whether an object group is something an arm works at: a work surface, a conveyor or
/// a machine.
pub(crate) fn is_work(ctx: &Ctx<'_>, group: &str) -> bool {
    ctx.instances(group).first().is_some_and(|&i| {
        let o = &ctx.input.objects[i];
        o.category == "conveyor" || o.has_tag("machine") || (o.has_tag("surface") && !o.has_tag("seating"))
    })
}

/// The top work surface of an object (not a shelf under it).
pub(crate) fn top_surface(ctx: &Ctx<'_>, idx: usize) -> Option<SupportSurface> {
    ctx.input.objects[idx]
        .asset
        .surfaces
        .iter()
        .filter(|s| s.clearance.is_none())
        .max_by(|a, b| a.z.total_cmp(&b.z))
        .cloned()
}

/// The instance of `group` an arm at `base` works at: the nearest placed one.
pub(crate) fn work_instance(ctx: &Ctx<'_>, group: &str, base: [f64; 3]) -> Option<usize> {
    ctx.placed_instances(group)
        .into_iter()
        .map(|(i, s)| {
            let b = ctx.bounds[i].transformed(&s.pose());
            let dx = (b.min[0] - base[0]).max(base[0] - b.max[0]).max(0.0);
            let dy = (b.min[1] - base[1]).max(base[1] - b.max[1]).max(0.0);
            (dx.hypot(dy), i)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, i)| i)
}

/// The centreline of a conveyor's belt (its top surface's long axis), world frame.
pub(crate) fn belt_line(ctx: &Ctx<'_>, idx: usize) -> Option<([f64; 3], [f64; 3])> {
    belt_line_at(ctx, idx, &ctx.placed[idx].as_ref()?.spot)
}

/// [`belt_line`] of a conveyor standing at `spot`.
fn belt_line_at(ctx: &Ctx<'_>, idx: usize, spot: &Spot) -> Option<([f64; 3], [f64; 3])> {
    if ctx.input.objects[idx].category != "conveyor" {
        return None;
    }
    let s = top_surface(ctx, idx)?;
    let cy = 0.5 * (s.min[1] + s.max[1]);
    let cx = 0.5 * (s.min[0] + s.max[0]);
    let (a, b) = if s.max[0] - s.min[0] >= s.max[1] - s.min[1] {
        ([s.min[0], cy, s.z], [s.max[0], cy, s.z])
    } else {
        ([cx, s.min[1], s.z], [cx, s.max[1], s.z])
    };
    Some((spot.apply(a), spot.apply(b)))
}

/// The point of segment ab nearest to p.
pub(crate) fn nearest_on_segment(a: [f64; 3], b: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1] + (p[2] - a[2]) * ab[2]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    [a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]]
}

pub(crate) fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// Whether an arm at `base` can work at object `idx`: a belt's centreline within reach,
/// or enough of a work surface (its nearest point within half the reach), or a
/// machine's side within reach.
pub(crate) fn can_work_at(ctx: &Ctx<'_>, base: [f64; 3], reach: f64, idx: usize) -> bool {
    match ctx.placed[idx].as_ref() {
        Some(p) => can_work_at_pose(ctx, base, reach, idx, &p.spot),
        None => false,
    }
}

/// [`can_work_at`] with object `idx` standing at `spot` (a candidate pose).
pub(crate) fn can_work_at_pose(ctx: &Ctx<'_>, base: [f64; 3], reach: f64, idx: usize, spot: &Spot) -> bool {
    if let Some((a, b)) = belt_line_at(ctx, idx, spot) {
        let sh = shoulder(base);
        return reaches(base, reach, nearest_on_segment(a, b, sh));
    }
    let spot = *spot;
    // A free item (a pallet): its centre.
    if ctx.input.objects[idx].asset.is_free() {
        let b = ctx.bounds[idx];
        return reaches(base, reach, spot.apply(b.center()));
    }
    match top_surface(ctx, idx) {
        Some(s) => {
            let corners = [[s.min[0], s.min[1]], [s.max[0], s.min[1]], [s.max[0], s.max[1]], [s.min[0], s.max[1]]];
            let w: Vec<[f64; 3]> = corners.iter().map(|c| spot.apply([c[0], c[1], s.z])).collect();
            let (x0, x1) = (
                w.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min),
                w.iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max),
            );
            let (y0, y1) = (
                w.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min),
                w.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max),
            );
            let p = [base[0].clamp(x0, x1), base[1].clamp(y0, y1), spot.z + s.z];
            dist(shoulder(base), p) <= 0.75 * reach
        }
        None => {
            let b = ctx.bounds[idx].transformed(&spot.pose());
            let dx = (b.min[0] - base[0]).max(base[0] - b.max[0]).max(0.0);
            let dy = (b.min[1] - base[1]).max(base[1] - b.max[1]).max(0.0);
            dx.hypot(dy) <= 0.5 * reach
        }
    }
}

/// The point an arm at `base` should face to work at object `idx`.
pub(crate) fn work_point(ctx: &Ctx<'_>, base: [f64; 3], idx: usize) -> Option<[f64; 3]> {
    if let Some((a, b)) = belt_line(ctx, idx) {
        return Some(nearest_on_segment(a, b, base));
    }
    let spot = ctx.placed[idx].as_ref()?.spot;
    let b = ctx.bounds[idx];
    Some(spot.apply([0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1]), b.max[2]]))
}

/// The placed arms an item on object `idx` must be in reach of: every arm said to reach
/// the item's group (`reaching`), else those that work at `idx`'s group (any one will do).
/// Returns the arms (base, reach) and whether all of them must reach.
pub(crate) fn arms_for(ctx: &Ctx<'_>, idx: usize, item_group: &str) -> (Vec<([f64; 3], f64)>, bool) {
    let placed = |ri: usize| base_of(ctx, ri).map(|b| (b, ctx.input.robots[ri].reach));
    // Arms the item is said to be between ("bins between the two arms") reach it too.
    let between: Vec<&str> = ctx
        .relations(item_group)
        .iter()
        .filter_map(|r| match r {
            RelationKind::Between { first, second } => Some([first.as_str(), second.as_str()]),
            _ => None,
        })
        .flatten()
        .collect();
    let said: Vec<([f64; 3], f64)> = ctx
        .input
        .robots
        .iter()
        .enumerate()
        .filter(|(_, r)| {
            has_arm(r)
                && ctx
                    .relations(&r.group)
                    .iter()
                    .any(|k| matches!(k, RelationKind::Reach { target } if target == item_group))
        })
        .filter_map(|(ri, _)| placed(ri))
        .collect();
    if !said.is_empty() {
        return (said, true);
    }
    // Between two arms: within the reach of one of them (each arm has some).
    let flanking: Vec<([f64; 3], f64)> = ctx
        .input
        .robots
        .iter()
        .enumerate()
        .filter(|(_, r)| has_arm(r) && between.contains(&r.group.as_str()))
        .filter_map(|(ri, _)| placed(ri))
        .collect();
    if !flanking.is_empty() {
        return (flanking, false);
    }
    let host = &ctx.input.objects[idx];
    // The arms that work at this very instance (the one each is on or nearest): what
    // rests on the group's other instances is theirs to reach, or nobody's.
    let at: Vec<([f64; 3], f64)> = ctx
        .input
        .robots
        .iter()
        .enumerate()
        .filter(|(_, r)| work_group(ctx, r).as_deref() == Some(host.group.as_str()))
        .filter_map(|(ri, _)| placed(ri))
        .filter(|(base, _)| work_instance(ctx, &host.group, *base) == Some(idx))
        .collect();
    (at, false)
}

/// How many instances of `group` an arm at `base` can work at.
pub(crate) fn instances_in_reach(ctx: &Ctx<'_>, base: [f64; 3], reach: f64, group: &str) -> (usize, usize) {
    let all = ctx.placed_instances(group);
    let n = all.iter().filter(|(i, _)| can_work_at(ctx, base, reach, *i)).count();
    (n, all.len())
}

/// The arms standing on the floor or on a stand of their own (not on a work surface)
/// said to reach `group`, placed or not: robot indices. Such an arm and its work are
/// placed together — its first work, the arm beside it, then the rest of its work
/// around it, where it reaches (`order`, `floor::place`).
pub(crate) fn floor_arms_reaching(ctx: &Ctx<'_>, group: &str) -> Vec<usize> {
    ctx.input
        .robots
        .iter()
        .enumerate()
        .filter(|(_, r)| has_arm(r) && !matches!(r.mount, RobotMount::Surface { .. }))
        .filter(|(_, r)| {
            ctx.relations(&r.group).iter().any(|k| matches!(k, RelationKind::Reach { target } if target == group))
        })
        .map(|(ri, _)| ri)
        .collect()
}

/// The base of a placed robot's arm (see [`arm_base`]).
pub(crate) fn base_of(ctx: &Ctx<'_>, ri: usize) -> Option<[f64; 3]> {
    ctx.robots[ri].as_ref().map(|p| arm_base(&ctx.input.robots[ri], p.pos))
}

/// The names of the arms on the floor or on a stand said to reach `group`, and of their
/// stands: the operators of that work, who stand in its working space (and it in theirs).
pub(crate) fn operators(ctx: &Ctx<'_>, group: &str) -> Vec<String> {
    let mut out = Vec::new();
    for ri in floor_arms_reaching(ctx, group) {
        let r = &ctx.input.robots[ri];
        out.push(r.name.clone());
        if let RobotMount::Carrier { object } = &r.mount {
            out.push(object.clone());
        }
    }
    out
}

/// How well an arm at `base` reaches the work already placed for it: every placed
/// instance of `work` (the group it stands at) and of each group it is said to reach.
/// Returns the instances it cannot work at, and the share of the work surfaces' tops
/// within its reach (sampled; 1 with no surface). A pose is chosen by the fewest misses,
/// then the largest share: what goes on a surface later is placed within reach, and the
/// more of the top is, the more of it fits there.
pub(crate) fn work_in_reach(ctx: &Ctx<'_>, robot: &RobotItem, base: [f64; 3], work: Option<&str>) -> (usize, f64) {
    let mut groups: Vec<&str> = work.into_iter().collect();
    for r in ctx.relations(&robot.group) {
        if let RelationKind::Reach { target } = r
            && !groups.contains(&target.as_str())
        {
            groups.push(target);
        }
    }
    let (mut misses, mut share, mut surfaces) = (0, 0.0, 0);
    for g in groups {
        for (i, spot) in ctx.placed_instances(g) {
            if !can_work_at_pose(ctx, base, robot.reach, i, &spot) {
                misses += 1;
            }
            if belt_line_at(ctx, i, &spot).is_none()
                && !ctx.input.objects[i].asset.is_free()
                && let Some(s) = top_surface(ctx, i)
            {
                surfaces += 1;
                share += top_share(base, robot.reach, &spot, &s);
            }
        }
    }
    (misses, if surfaces == 0 { 1.0 } else { share / f64::from(surfaces) })
}

/// The share of a surface (of an object standing at `spot`) within the solver's reach
/// of an arm at `base`, on an 8 × 8 grid.
fn top_share(base: [f64; 3], reach: f64, spot: &Spot, s: &SupportSurface) -> f64 {
    let n = 8;
    let mut hit = 0u32;
    for i in 0..n {
        for j in 0..n {
            let lx = s.min[0] + (s.max[0] - s.min[0]) * (f64::from(i) + 0.5) / f64::from(n);
            let ly = s.min[1] + (s.max[1] - s.min[1]) * (f64::from(j) + 0.5) / f64::from(n);
            if reaches(base, reach, spot.apply([lx, ly, s.z])) {
                hit += 1;
            }
        }
    }
    f64::from(hit) / f64::from(n * n)
}
