//! An arm's reach of its work. An arm works at the instance it is mounted on, or at the
//! nearest instance of the group it tends ("a Panda picking from the belt"); everything
//! resting on that instance must be within its reach, and so must a conveyor's
//! centreline. Distances are 3D, from the arm's base origin (its mount point) to the
//! work point: an item's footprint centre where it rests, or the nearest point of the
//! belt's centreline at the belt's top. The solver keeps them within [`REACH_USE`] of
//! the registry's reach; the report measures the same on the written scene.

use sw_geom::SupportSurface;

use crate::attempt::Ctx;
use crate::{RobotItem, RobotMount};

/// Share of the registry reach the solver uses, leaving a margin for the arm's wrist.
pub(crate) const REACH_USE: f64 = 0.85;

/// The group an arm works at: the surface it is mounted on, else the group it tends
/// (`near`), else the target of a reach relation.
pub(crate) fn work_group(ctx: &Ctx<'_>, robot: &RobotItem) -> Option<String> {
    if !robot.is_arm {
        return None;
    }
    if let RobotMount::Surface { group } = &robot.mount {
        return Some(group.clone());
    }
    robot.near.clone().or_else(|| {
        ctx.relations(&robot.group).iter().find_map(|r| match r {
            sw_plan::RelationKind::Reach { target } => Some(target.clone()),
            _ => None,
        })
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
    if ctx.input.objects[idx].category != "conveyor" {
        return None;
    }
    let spot = ctx.placed[idx].as_ref()?.spot;
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
    if let Some((a, b)) = belt_line(ctx, idx) {
        return dist(base, nearest_on_segment(a, b, base)) <= REACH_USE * reach;
    }
    let Some(spot) = ctx.placed[idx].as_ref().map(|p| p.spot) else { return false };
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
            dist(base, p) <= 0.5 * reach
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

/// The placed arms working at object `idx`: their base positions and reaches.
pub(crate) fn arms_at(ctx: &Ctx<'_>, idx: usize) -> Vec<([f64; 3], f64)> {
    let host = &ctx.input.objects[idx];
    ctx.input
        .robots
        .iter()
        .enumerate()
        .filter_map(|(ri, r)| {
            let p = ctx.robots[ri].as_ref()?;
            let group = work_group(ctx, r)?;
            if group != host.group {
                return None;
            }
            let on_it = p.mounted_on.as_deref() == Some(host.name.as_str());
            let works = on_it || work_instance(ctx, &group, p.pos) == Some(idx);
            works.then_some((p.pos, r.reach))
        })
        .collect()
}
