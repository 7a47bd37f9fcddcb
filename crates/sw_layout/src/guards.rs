//! Robot cells: guards (safety fences) around something an arm works at stand on a ring
//! far enough out that the arm keeps the rule's safety distance to them (ISO 13857).

use sw_geom::Aabb;

use crate::attempt::Ctx;
use crate::frames::{Spot, yaw_facing};
use crate::{RobotItem, RobotMount};

/// True when object `idx` is a guard and an arm works at or on `target`.
pub(crate) fn is_guard_of_arm(ctx: &Ctx<'_>, idx: usize, target: &str) -> bool {
    let Some((_, tags, _, _)) = ctx.profile.fence_distance() else { return false };
    let guard = tags.iter().all(|t| ctx.input.objects[idx].has_tag(t));
    guard && ctx.input.robots.iter().any(|r| r.is_arm && (arm_at(r, target) || r.group == target))
}

/// An arm works at `group` when it is mounted on it or tends it.
pub(crate) fn arm_at(r: &RobotItem, group: &str) -> bool {
    matches!(&r.mount, RobotMount::Surface { group: g } if g == group) || r.near.as_deref() == Some(group)
}

/// Guard poses on a square ring around the target, on the given sides in that order
/// (0 south, 1 east, 2 north, 3 west), fronts inwards.
pub(crate) fn ring(ctx: &Ctx<'_>, idx: usize, target: &str, sides: &[usize]) -> Vec<Spot> {
    let Some((_, _, distance, _)) = ctx.profile.fence_distance() else { return Vec::new() };
    let arms: Vec<&RobotItem> =
        ctx.input.robots.iter().filter(|r| r.is_arm && (arm_at(r, target) || r.group == target)).collect();
    let reach = arms.iter().map(|r| r.reach).fold(0.0, f64::max);
    let b = ctx.bounds[idx];
    let mut out = Vec::new();
    // The target's instances, or the robots themselves for "around the robot".
    let mut centres: Vec<(Aabb, [f64; 2], f64)> = Vec::new();
    for (ti, ts) in ctx.placed_instances(target) {
        let tb = ctx.bounds[ti];
        let c = ts.apply([0.5 * (tb.min[0] + tb.max[0]), 0.5 * (tb.min[1] + tb.max[1]), 0.0]);
        let half_diag = 0.5 * (tb.max[0] - tb.min[0]).hypot(tb.max[1] - tb.min[1]);
        // An arm on a pedestal beside the target may stand up to ~0.8 m past its edge.
        let carrier = if arms.iter().any(|r| r.near.as_deref() == Some(target)) { 0.8 } else { 0.0 };
        centres.push((tb, [c[0], c[1]], half_diag + carrier));
    }
    for (ri, r) in ctx.input.robots.iter().enumerate() {
        if r.group == target
            && let Some(p) = &ctx.robots[ri]
        {
            centres.push((Aabb::EMPTY, [p.pos[0], p.pos[1]], r.base_radius));
        }
    }
    // Side k first (every radius, every shift), then the others; a little further out
    // when something stands where the ring is (the machine the arm tends).
    for &side in sides {
        let (nx, ny) = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)][side % 4];
        for (_, c, extent) in &centres {
            for extra in [0.0, 0.25, 0.5] {
                let radius = extent + reach + distance + 0.05 + extra;
                for along in [0.0, -0.5, 0.5, -1.0, 1.0, -1.5, 1.5, -2.0, 2.0] {
                    let t = along * (b.max[0] - b.min[0] + 0.05);
                    let (px, py) = (c[0] + nx * (radius - b.min[1]) - ny * t, c[1] + ny * (radius - b.min[1]) + nx * t);
                    out.push(Spot::new(px, py, 0.0, yaw_facing(-nx, -ny)));
                }
            }
        }
    }
    out
}
