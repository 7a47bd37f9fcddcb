//! Closing a drawer or a door: the hand, its fingers shut, is brought in front of the
//! moving part's face and pushes it along the joint's own path to its closed stop — a
//! straight push along a slide's axis, an arc about a hinge's axis (the hand turning with
//! the leaf) — each point of the path solved by IK on MuJoCo's Jacobian from the one
//! before. Whether it is closed is the predicate's call on the joint's state afterwards.
//!
//! Opening is not done here: the catalog's handles are visual only (a bar 3 mm proud with
//! no collision geometry), so there is nothing a finger can pull on; see [`open`].

use mujoco_rs::prelude::*;
use mujoco_rs::wrappers::mj_model::traits::ModelType;

use crate::expert::Expert;
use crate::ik::{Target, solve_ik};
use crate::math::{M3, V3, add, col, cross, dot, from_cols, mat_mul, mat_vec, norm, rot_axis, scale, sub};
use crate::motion::Allow;
use crate::{ExpertError, rig};

/// Distance in front of the face the hand stops before the push, m.
const STANDOFF: f64 = 0.08;
/// How far past the surface the fingertips are driven (a firm push), m.
const PRESS: f64 = 0.006;
/// How far past the closed stop the push is aimed (the stop holds the part), m / rad.
const OVERSHOOT_SLIDE: f64 = 0.015;
const OVERSHOOT_HINGE: f64 = 0.08;
/// The push's step along the path, m of travel of the pushed point.
const STEP: f64 = 0.02;
/// Fraction of the joint speed limit the push is made at.
const PUSH_SPEED: f64 = 0.25;
/// Tilts of the hand (its approach pitched about its finger axis) tried, rad: up to 72°,
/// the fingertips meeting a low face from above.
const TILTS: [f64; 9] = [0.0, 0.35, -0.35, 0.7, -0.7, 1.0, -1.0, 1.25, -1.25];
/// Where along the leaf, from the hinge to the free edge, a door is pushed.
const LEVER: f64 = 0.75;

/// The moving part of an articulated thing, read from the model and the current state.
#[derive(Debug, Clone, Copy)]
struct Part {
    /// Joint id, its qpos address, its range.
    qadr: usize,
    lo: f64,
    hinge: bool,
    /// World axis and anchor of the joint.
    axis: V3,
    anchor: V3,
    /// The point of the face pushed and the direction the part moves there when closing.
    point: V3,
    push: V3,
    /// Up along the face (world up, less its part along the push) and how far the face
    /// reaches that way from `point`, m: other points to push higher and lower.
    rise: (V3, f64),
}

fn part<M: ModelType>(model: &MjModel, data: &MjData<M>, joint: &str) -> Result<Part, ExpertError> {
    let j = model
        .name_to_id(MjtObjBase::mjOBJ_JOINT, joint)
        .ok_or_else(|| ExpertError::Scene(format!("no joint '{joint}' in the scene")))?;
    let hinge = match model.jnt_type()[j] {
        MjtJoint::mjJNT_HINGE => true,
        MjtJoint::mjJNT_SLIDE => false,
        _ => return Err(ExpertError::Unsupported(format!("{joint} is neither a hinge nor a slide"))),
    };
    let body = model.jnt_bodyid()[j] as usize;
    let qadr = model.jnt_qposadr()[j] as usize;
    let [lo, _hi] = model.jnt_range()[j];
    let axis = data.xaxis()[j];
    let anchor = data.xanchor()[j];
    // The part's collision boxes (centre, rotation, half sizes).
    let boxes: Vec<(V3, M3, V3)> = (0..model.ffi().ngeom as usize)
        .filter(|&g| model.geom_bodyid()[g] as usize == body && model.geom_group()[g] == rig::COLLISION_GROUP)
        .map(|g| {
            let a = model.geom_aabb()[g];
            let m: M3 = data.geom_xmat()[g];
            (add(data.geom_xpos()[g], mat_vec(&m, [a[0], a[1], a[2]])), m, [a[3], a[4], a[5]])
        })
        .collect();
    let no_geometry = || ExpertError::Grasp(format!("the part {joint} moves has no collision geometry to push"));
    let extent = |(_, m, h): &(V3, M3, V3), u: V3| (0..3).map(|k| dot(u, col(m, k)).abs() * h[k]).sum::<f64>();
    let along = |p: V3| dot(sub(p, anchor), axis);
    let radial = |p: V3| sub(sub(p, anchor), scale(axis, along(p)));
    let (point, push, leaf) = if hinge {
        // The leaf: the box reaching farthest from the axis. Its point at LEVER of the way
        // out, at the box's middle along the axis, on the face the closing turn drives.
        let b = boxes
            .iter()
            .max_by(|x, y| {
                (norm(radial(x.0)) + extent(x, unit(radial(x.0))))
                    .total_cmp(&(norm(radial(y.0)) + extent(y, unit(radial(y.0)))))
            })
            .ok_or_else(no_geometry)?;
        let r = radial(b.0);
        let out = unit(r);
        let reach = norm(r) + extent(b, out);
        let rho = (LEVER * reach).min(reach - 0.03).max(0.0);
        // Closing lowers the angle: a point at r moves along -(axis × r).
        let push = unit(scale(cross(axis, out), -1.0));
        let mid = add(add(anchor, scale(axis, along(b.0))), scale(out, rho));
        // The face the push meets: the box's side facing against the push, through `mid`.
        let depth = dot(sub(b.0, mid), push) - extent(b, push);
        (add(mid, scale(push, depth)), push, b)
    } else {
        // The front: the box standing out farthest along the axis (the drawer's front
        // panel); the middle of its outer face.
        let b = boxes
            .iter()
            .max_by(|x, y| (dot(x.0, axis) + extent(x, axis)).total_cmp(&(dot(y.0, axis) + extent(y, axis))))
            .ok_or_else(no_geometry)?;
        let push = scale(axis, -1.0);
        (add(b.0, scale(axis, extent(b, axis))), push, b)
    };
    let up = [0.0, 0.0, 1.0];
    let along_face = sub(up, scale(push, dot(up, push)));
    let rise = if norm(along_face) < 0.3 {
        (up, 0.0)
    } else {
        let u = unit(along_face);
        (u, (extent(leaf, u) - dot(sub(point, leaf.0), u)).max(0.0))
    };
    Ok(Part { qadr, lo, hinge, axis, anchor, point, push, rise })
}

/// Where the pushed point is, and how the part has turned, at `s` (0 → 1) of the push
/// from `travel` open to past the closed stop.
fn at(part: &Part, travel: f64, s: f64) -> (V3, M3) {
    if part.hinge {
        let turn = rot_axis(part.axis, -s * (travel + OVERSHOOT_HINGE));
        (add(part.anchor, mat_vec(&turn, sub(part.point, part.anchor))), turn)
    } else {
        (add(part.point, scale(part.push, s * (travel + OVERSHOOT_SLIDE))), rot_axis([0.0, 0.0, 1.0], 0.0))
    }
}

fn unit(v: V3) -> V3 {
    let n = norm(v);
    if n < 1e-12 { [1.0, 0.0, 0.0] } else { scale(v, 1.0 / n) }
}

/// The hand's rotations for pushing along `push`: its approach (z) along the push tilted
/// by each of [`TILTS`] about the finger axis, the fingers (y) across the push level, then
/// upright.
fn hand_rotations(push: V3) -> Vec<M3> {
    let up = [0.0, 0.0, 1.0];
    let side = if norm(cross(up, push)) < 0.3 { [1.0, 0.0, 0.0] } else { unit(cross(up, push)) };
    let mut out = Vec::new();
    for roll in [0.0, std::f64::consts::FRAC_PI_2] {
        let y0 = unit(sub(side, scale(push, dot(side, push))));
        let y = mat_vec(&rot_axis(push, roll), y0);
        for t in TILTS {
            let z = mat_vec(&rot_axis(y, t), push);
            out.push(from_cols(cross(y, z), y, z));
        }
    }
    out
}

/// Pushes the part that `joint` moves to its closed end.
pub(crate) fn close(ex: &mut Expert<'_, '_>, joint: &str) -> Result<(), ExpertError> {
    let part = part(ex.model, &ex.run.data, joint)?;
    let q0 = ex.run.data.qpos()[part.qadr];
    let travel = q0 - part.lo;
    // The push's length: the pushed point's travel from where it is to past the stop.
    let span = if part.hinge {
        (travel + OVERSHOOT_HINGE) * norm(sub(part.point, part.anchor))
    } else {
        travel + OVERSHOOT_SLIDE
    };
    let steps = ((span / STEP).ceil() as usize).clamp(2, 80);
    // Shut the fingers: the hand pushes with its closed fingertips.
    ex.run.grip(ex.rig, ex.rig.grip_closed, 0.4)?;
    ex.sync_scratch();
    let now = ex.run.arm_target(ex.rig);
    let mut why = ExpertError::Ik(format!("no hand pose pushes {joint} closed"));
    // The middle of the face first, then higher and lower on it.
    let (u, rise) = part.rise;
    let points: Vec<V3> = [0.0, 0.6, -0.6].iter().map(|k| add(part.point, scale(u, k * rise))).collect();
    let tries: Vec<(V3, M3)> =
        points.iter().flat_map(|p| hand_rotations(part.push).into_iter().map(move |r| (*p, r))).collect();
    for (point, rot) in tries {
        let part = Part { point, ..part };
        let before = Target { pos: sub(part.point, scale(part.push, STANDOFF)), rot };
        let Some(q_before) = ex.free_posture(&now, &before, Allow::default()) else { continue };
        // The push, solved point by point from the posture in front of the face.
        let mut path = vec![q_before.clone()];
        let mut q = q_before.clone();
        let mut ok = true;
        for k in 0..=steps {
            let s = k as f64 / steps as f64;
            let (p, turn) = at(&part, travel, s);
            let t = Target { pos: add(p, scale(mat_vec(&turn, part.push), PRESS)), rot: mat_mul(&turn, &rot) };
            ex.stats.ik_solves += 1;
            match solve_ik(ex.rig, &mut ex.scratch, &q, &t, 2, &mut ex.rng) {
                Some(n) if crate::motion::dist(&n, &q) < 0.8 => {
                    q = n;
                    path.push(q.clone());
                }
                _ => {
                    ok = false;
                    break;
                }
            }
        }
        if !ok {
            why = ExpertError::Ik(format!("the push that closes {joint} leaves the arm's reach"));
            continue;
        }
        let approach = match ex.plan_to(Allow::default(), &q_before) {
            Ok(p) => p,
            Err(e) => {
                why = e;
                continue;
            }
        };
        ex.run.follow(ex.rig, &approach, 0.8)?;
        ex.run.follow(ex.rig, &path, PUSH_SPEED)?;
        // Back off along the face's normal where the push ended.
        ex.sync_scratch();
        let (end, turn) = at(&part, travel, 1.0);
        let back = Target { pos: sub(end, scale(mat_vec(&turn, part.push), STANDOFF)), rot: mat_mul(&turn, &rot) };
        let from = ex.run.arm_target(ex.rig);
        if let Some(qb) = solve_ik(ex.rig, &mut ex.scratch, &from, &back, 2, &mut ex.rng) {
            ex.run.follow(ex.rig, &[from, qb], 0.5)?;
        }
        return ex.run.hold(ex.rig, 0.3);
    }
    Err(why)
}

/// Opening needs something to pull on: a handle with collision geometry standing off the
/// face. The catalog's are visual bars 3 mm proud, so the task is refused with the reason.
pub(crate) fn open(model: &MjModel, joint: &str) -> Result<(), ExpertError> {
    let what = model.name_to_id(MjtObjBase::mjOBJ_JOINT, joint).map_or("it", |_| joint);
    Err(ExpertError::Unsupported(format!(
        "the expert cannot open {what}: its handle is drawn only (no collision geometry standing off the face), so there is nothing to pull"
    )))
}
