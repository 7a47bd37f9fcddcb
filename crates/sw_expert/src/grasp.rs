//! Grasps and places from the collision geometry the catalog wrote: a thing's box in its
//! own frame (boxes, cylinders, spheres and capsules all give one), grasped from above
//! across its narrower side that fits the gripper's opening; places on surfaces, in
//! containers, on top of other things, beside them, in a region.

use mujoco_rs::prelude::*;
use mujoco_rs::wrappers::mj_model::traits::ModelType;
use sw_task::{Bounds, Snapshot};

use crate::ExpertError;
use crate::ik::Target;
use crate::math::{M3, V3, add, col, cross, from_cols, mat_mul, mat_vec, quat_to_mat, rot_axis, scale, sub};
use crate::rig::Rig;

/// Clearance kept between the gripper's opening and the thing, m.
pub(crate) const OPENING_SLACK: f64 = 0.012;
/// How far above the grasp the hand comes in from, m.
pub(crate) const APPROACH: f64 = 0.10;
/// How far fingertips stay above the surface under the thing, m.
const TIP_CLEARANCE: f64 = 0.006;

/// A thing's box in its body frame: centre and half sizes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LocalBox {
    pub center: V3,
    pub half: V3,
}

/// The box around `body`'s colliding geoms, in the body's frame.
pub(crate) fn local_box(model: &MjModel, body: usize) -> Option<LocalBox> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for g in 0..model.ffi().ngeom as usize {
        if model.geom_bodyid()[g] as usize != body || model.geom_group()[g] != 3 {
            continue;
        }
        let a = model.geom_aabb()[g];
        let m = quat_to_mat(model.geom_quat()[g]);
        let c = add(model.geom_pos()[g], mat_vec(&m, [a[0], a[1], a[2]]));
        for i in 0..3 {
            let h = (m[3 * i] * a[3]).abs() + (m[3 * i + 1] * a[4]).abs() + (m[3 * i + 2] * a[5]).abs();
            lo[i] = lo[i].min(c[i] - h);
            hi[i] = hi[i].max(c[i] + h);
        }
    }
    (lo[0] <= hi[0]).then(|| LocalBox {
        center: [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])],
        half: [0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]), 0.5 * (hi[2] - lo[2])],
    })
}

/// A top-down grasp: the tool pose at the grasp, and the thing's width across the pads.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Grasp {
    pub at: Target,
    pub width: f64,
    /// The one geom grasped (a mug's wall, a handle), `None` for the whole thing.
    pub geom: Option<usize>,
}

impl Grasp {
    /// The pose `h` back from the grasp along the tool's approach axis (straight above it
    /// for a top-down grasp).
    pub fn above(&self, h: f64) -> Target {
        Target { pos: sub(self.at.pos, scale(col(&self.at.rot, 2), h)), rot: self.at.rot }
    }

    /// The same grasp with the hand pitched by `angle` about the fingers' closing axis: the
    /// pads close across the same width at the same point, the approach comes in slanted
    /// (for things close to the arm's base or under an overhang, where straight down has
    /// no joint solution or the forearm hits something).
    pub fn pitched(&self, angle: f64) -> Grasp {
        let closing = col(&self.at.rot, 1);
        Grasp { at: Target { pos: self.at.pos, rot: mat_mul(&rot_axis(closing, angle), &self.at.rot) }, ..*self }
    }
}

/// The tool rotation that points down with the fingers closing along `closing` (horizontal).
pub(crate) fn down_closing(closing: V3) -> M3 {
    let z = [0.0, 0.0, -1.0];
    let n = (closing[0] * closing[0] + closing[1] * closing[1]).sqrt().max(1e-9);
    let y = [closing[0] / n, closing[1] / n, 0.0];
    let x = cross(y, z);
    from_cols(x, y, z)
}

/// Top-down grasps of `body` as it is now, best first.
pub(crate) fn grasps<M: ModelType>(
    model: &MjModel,
    data: &MjData<M>,
    rig: &Rig,
    body: usize,
    name: &str,
    bounds: &Bounds,
    support_z: f64,
) -> Result<Vec<Grasp>, ExpertError> {
    let b = local_box(model, body).ok_or_else(|| ExpertError::Grasp(format!("{name} has no collision geometry")))?;
    let xmat = data.xmat()[body];
    let upright = xmat[8].abs() > 0.95;
    let center = add(data.xpos()[body], mat_vec(&xmat, b.center));
    // Horizontal axes of the thing and their widths.
    let axes: Vec<(V3, f64)> = if upright {
        vec![(col(&xmat, 0), 2.0 * b.half[0]), (col(&xmat, 1), 2.0 * b.half[1])]
    } else {
        vec![([1.0, 0.0, 0.0], bounds.max[0] - bounds.min[0]), ([0.0, 1.0, 0.0], bounds.max[1] - bounds.min[1])]
    };
    let top = bounds.max[2];
    let height = bounds.max[2] - bounds.min[2];
    let depth = (0.5 * height).min(0.035);
    let z = (top - depth).max(support_z + rig.finger_depth + TIP_CLEARANCE);
    let mut out = Vec::new();
    let mut order: Vec<&(V3, f64)> = axes.iter().collect();
    order.sort_by(|a, b| a.1.total_cmp(&b.1));
    for (axis, width) in order {
        if *width + OPENING_SLACK > rig.max_opening {
            continue;
        }
        for sign in [1.0, -1.0] {
            let closing = [sign * axis[0], sign * axis[1], 0.0];
            out.push(Grasp {
                at: Target { pos: [center[0], center[1], z], rot: down_closing(closing) },
                width: *width,
                geom: None,
            });
        }
    }
    // A part of the thing that fits when the whole does not (a mug's wall, a handle): each
    // upright collision geom across its narrower side, from its own top.
    if out.is_empty() {
        for g in 0..model.ffi().ngeom as usize {
            if model.geom_bodyid()[g] as usize != body || model.geom_group()[g] != 3 {
                continue;
            }
            let gm = data.geom_xmat()[g];
            if gm[8].abs() < 0.95 {
                continue;
            }
            let a = model.geom_aabb()[g];
            let c = add(data.geom_xpos()[g], mat_vec(&gm, [a[0], a[1], a[2]]));
            let top = c[2] + a[5] * gm[8].abs();
            let z = (top - a[5].min(0.02)).max(support_z + rig.finger_depth + TIP_CLEARANCE);
            for (axis, width) in [(col(&gm, 0), 2.0 * a[3]), (col(&gm, 1), 2.0 * a[4])] {
                if width + OPENING_SLACK > rig.max_opening || width < 0.003 {
                    continue;
                }
                for sign in [1.0, -1.0] {
                    let closing = [sign * axis[0], sign * axis[1], 0.0];
                    out.push(Grasp {
                        at: Target { pos: [c[0], c[1], z], rot: down_closing(closing) },
                        width,
                        geom: Some(g),
                    });
                }
            }
        }
    }
    if out.is_empty() {
        let narrow = axes.iter().map(|a| a.1).fold(f64::INFINITY, f64::min);
        return Err(ExpertError::Grasp(format!(
            "{name} is {:.0} mm across at its narrowest; with {:.0} mm of clearance it does not fit the gripper's {:.0} mm opening",
            narrow * 1000.0,
            OPENING_SLACK * 1000.0,
            rig.max_opening * 1000.0
        )));
    }
    Ok(out)
}

/// The height of the surface a thing stands on (the highest top under its bottom).
pub(crate) fn support_under(s: &Snapshot, name: &str) -> f64 {
    let Some(me) = s.bodies.get(name) else { return 0.0 };
    let c = me.bounds.center();
    let mut z: f64 = 0.0;
    for (n, b) in &s.bodies {
        if n == name {
            continue;
        }
        for sf in &b.surfaces {
            if sf.z <= me.bounds.min[2] + 0.02
                && (sf.rect[0]..=sf.rect[2]).contains(&c[0])
                && (sf.rect[1]..=sf.rect[3]).contains(&c[1])
            {
                z = z.max(sf.z);
            }
        }
        if b.bounds.max[2] <= me.bounds.min[2] + 0.02 && b.bounds.covers_xy(c) {
            z = z.max(b.bounds.max[2]);
        }
    }
    z
}

/// Free spots for a thing of footprint half-sizes `half` on the rectangles `rects` at
/// height z, away from every other body, scored by closeness to `prefer`.
pub(crate) fn free_spots(
    s: &Snapshot,
    rects: &[(f64, [f64; 4])],
    half: [f64; 2],
    ignore: &[&str],
    prefer: [f64; 2],
    reach: Option<([f64; 3], f64)>,
) -> Vec<V3> {
    let clear = 0.03;
    let mut spots: Vec<(f64, V3)> = Vec::new();
    for (z, r) in rects {
        let (x0, y0, x1, y1) =
            (r[0] + half[0] + 0.01, r[1] + half[1] + 0.01, r[2] - half[0] - 0.01, r[3] - half[1] - 0.01);
        if x0 > x1 || y0 > y1 {
            continue;
        }
        let nx = ((x1 - x0) / 0.03).ceil().max(1.0) as usize;
        let ny = ((y1 - y0) / 0.03).ceil().max(1.0) as usize;
        for i in 0..=nx {
            for j in 0..=ny {
                let x = x0 + (x1 - x0) * i as f64 / nx as f64;
                let y = y0 + (y1 - y0) * j as f64 / ny as f64;
                let me =
                    Bounds { min: [x - half[0], y - half[1], z + 0.001], max: [x + half[0], y + half[1], z + 0.2] };
                let blocked = s.bodies.iter().any(|(n, b)| {
                    !ignore.contains(&n.as_str())
                        && b.bounds.max[2] > z + 0.003
                        && b.bounds.min[2] < me.max[2]
                        && sw_task::judge::gap(&me, &b.bounds) < clear
                });
                if blocked {
                    continue;
                }
                if let Some((base, r)) = reach
                    && ((x - base[0]).hypot(y - base[1]) > r || (x - base[0]).hypot(y - base[1]) < 0.25)
                {
                    continue;
                }
                let score = (x - prefer[0]).hypot(y - prefer[1]);
                spots.push((score, [x, y, *z]));
            }
        }
    }
    spots.sort_by(|a, b| a.0.total_cmp(&b.0));
    spots.into_iter().map(|(_, p)| p).collect()
}
