//! Closing a drawer or a door: the hand, its fingers shut, is brought in front of the
//! moving part's face and pushes it along the joint's own path to its closed stop — a
//! straight push along a slide's axis, an arc about a hinge's axis (the hand turning with
//! the leaf) — each point of the path solved by IK on MuJoCo's Jacobian from the one
//! before. Whether it is closed is the predicate's call on the joint's state afterwards.
//!
//! Opening: the hand pinches the part's handle (the collider standing proudest of the
//! moving face, narrow enough for the pads), squeezes, and pulls it along the same path the
//! other way — straight out along a slide's axis, an arc about a hinge (the hand turning
//! with the leaf) — to most of the joint's range, lets go and backs off; see [`open`].

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
/// How far behind the frontmost collider a drawer's front panel may lie (a handle on it
/// stands proud), m.
const FRONT_DEPTH: f64 = 0.02;
/// Where along the leaf, from the hinge to the free edge, a door is pushed.
const LEVER: f64 = 0.75;

/// The moving part of an articulated thing, read from the model and the current state.
#[derive(Debug, Clone, Copy)]
struct Part {
    /// Joint id, its qpos address, its range.
    qadr: usize,
    lo: f64,
    hi: f64,
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
    let [lo, hi] = model.jnt_range()[j];
    let axis = data.xaxis()[j];
    let anchor = data.xanchor()[j];
    let boxes: Vec<(V3, M3, V3)> = boxes(model, data, body).into_iter().map(|(c, m, h, _)| (c, m, h)).collect();
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
        // The front: of the boxes whose outer face is within [`FRONT_DEPTH`] of the
        // frontmost along the axis (the drawer's front panel and the handle on it), the
        // one with the largest face across the axis (the panel); the middle of its face.
        let front = |x: &(V3, M3, V3)| dot(x.0, axis) + extent(x, axis);
        let first = boxes.iter().map(front).fold(f64::NEG_INFINITY, f64::max);
        let area = |x: &(V3, M3, V3)| {
            let e: Vec<f64> = (0..3).map(|k| (1.0 - dot(col(&x.1, k), axis).abs()) * x.2[k]).collect();
            e[0] * e[1] + e[1] * e[2] + e[0] * e[2]
        };
        let b = boxes
            .iter()
            .filter(|x| front(x) >= first - FRONT_DEPTH)
            .max_by(|x, y| area(x).total_cmp(&area(y)))
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
    Ok(Part { qadr, lo, hi, hinge, axis, anchor, point, push, rise })
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

/// The collision boxes of `body` as they are now: centre, rotation, half sizes, geom id.
fn boxes<M: ModelType>(model: &MjModel, data: &MjData<M>, body: usize) -> Vec<(V3, M3, V3, usize)> {
    (0..model.ffi().ngeom as usize)
        .filter(|&g| model.geom_bodyid()[g] as usize == body && model.geom_group()[g] == rig::COLLISION_GROUP)
        .map(|g| {
            let a = model.geom_aabb()[g];
            let m: M3 = data.geom_xmat()[g];
            (add(data.geom_xpos()[g], mat_vec(&m, [a[0], a[1], a[2]])), m, [a[3], a[4], a[5]], g)
        })
        .collect()
}

/// How far the box `b` reaches from its centre along the unit vector `u`.
fn extent_along(b: &(V3, M3, V3, usize), u: V3) -> f64 {
    (0..3).map(|k| dot(u, col(&b.1, k)).abs() * b.2[k]).sum::<f64>()
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

/// Where the fingertips are aimed relative to the face behind the handle, m: 4 mm into it
/// (the part rests on its closed stop, and the hand stops where the tips touch), so that
/// the pads cover the bar's whole depth even with the hand a few millimetres short of its
/// target; a shallower pinch squeezes the bar out of the pads as they close.
const TIP_GAP: f64 = -0.004;
/// How far a handle must stand proud of the rest of its part to be pinched, m.
const MIN_PROUD: f64 = 0.004;
/// The fraction of the joint's range an opening pull aims at (the predicate wants 0.8),
/// and the least a pull cut short by the arm's reach must make to be kept.
const OPEN_TO: f64 = 0.92;
const OPEN_ENOUGH: f64 = 0.86;
/// Tilts of the hand about its closing axis tried at a handle, rad (the pads stay astride
/// the bar, which runs across that tilt).
const HANDLE_TILTS: [f64; 5] = [0.0, 0.3, -0.3, 0.55, -0.55];
/// Fraction of the joint speed limit the pull is made at.
const PULL_SPEED: f64 = 0.2;

/// A handle to pull: where the tool centre point pinches it, the hand's rotation there, the
/// width across the pads, and the way back out along the hand's approach (the face's outward normal, tilted).
#[derive(Debug, Clone, Copy)]
struct Handle {
    at: V3,
    rot: M3,
    width: f64,
    normal: V3,
}

/// The handle of the part `joint` moves: the collider standing proudest along the face's
/// outward normal (the way the part moves as it opens), proud of the rest by at least
/// [`MIN_PROUD`] and narrow enough across one side for the pads. The hand comes in along
/// -normal, fingers closing across that narrow side, its tips at the face ([`TIP_GAP`]).
fn handle<M: ModelType>(
    model: &MjModel,
    data: &MjData<M>,
    rig: &rig::Rig,
    joint: &str,
    part: &Part,
) -> Result<Vec<Handle>, ExpertError> {
    let j = model
        .name_to_id(MjtObjBase::mjOBJ_JOINT, joint)
        .ok_or_else(|| ExpertError::Scene(format!("no joint '{joint}'")))?;
    let body = model.jnt_bodyid()[j] as usize;
    let all = boxes(model, data, body);
    // The face's outward normal: opposite the closing push.
    let n = scale(part.push, -1.0);
    let front = |b: &(V3, M3, V3, usize)| dot(b.0, n) + extent_along(b, n);
    let none = || {
        ExpertError::Grasp(format!(
            "{joint}: its part has no handle to pull (no collider standing {:.0} mm proud of its face that fits the gripper)",
            MIN_PROUD * 1000.0
        ))
    };
    let h = all.iter().max_by(|a, b| front(a).total_cmp(&front(b))).ok_or_else(none)?;
    let rest = all.iter().filter(|b| b.3 != h.3).map(front).fold(f64::NEG_INFINITY, f64::max);
    if front(h) - rest < MIN_PROUD {
        return Err(none());
    }
    // The narrowest side across the normal that fits between the pads.
    let (u, width) = (0..3)
        .filter_map(|k| {
            let c = col(&h.1, k);
            (dot(c, n).abs() < 0.5).then(|| (unit(sub(c, scale(n, dot(c, n)))), 2.0 * h.2[k]))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .ok_or_else(none)?;
    if width + 2.0 * crate::grasp::OPENING_SLACK > rig.max_opening {
        return Err(none());
    }
    let back = sub(h.0, scale(n, extent_along(h, n)));
    let depth = 2.0 * extent_along(h, n);
    let at = add(back, scale(n, (TIP_GAP + rig.finger_depth).min(depth + rig.finger_depth)));
    let z = scale(n, -1.0);
    // Both ways round (the wrist may reach one and not the other), each tilted about the
    // closing axis.
    let mut out = Vec::new();
    for t in HANDLE_TILTS {
        for y in [u, scale(u, -1.0)] {
            let zt = mat_vec(&rot_axis(y, t), z);
            out.push(Handle { at, rot: from_cols(cross(y, zt), y, zt), width, normal: scale(zt, -1.0) });
        }
    }
    Ok(out)
}

/// Where a point `p` of the part goes, and how the part has turned, when the joint moves by
/// `dq` (m or rad) from where it is.
fn moved(part: &Part, p: V3, dq: f64) -> (V3, M3) {
    if part.hinge {
        let turn = rot_axis(part.axis, dq);
        (add(part.anchor, mat_vec(&turn, sub(p, part.anchor))), turn)
    } else {
        (add(p, scale(part.axis, dq)), rot_axis([0.0, 0.0, 1.0], 0.0))
    }
}

/// Pulls the part that `joint` moves open by its handle: in front of the handle, straight
/// in, squeeze, the joint's own path out to [`OPEN_TO`] of its range, let go, back off.
pub(crate) fn open(ex: &mut Expert<'_, '_>, joint: &str) -> Result<(), ExpertError> {
    let part = part(ex.model, &ex.run.data, joint)?;
    let handles = handle(ex.model, &ex.run.data, ex.rig, joint, &part)?;
    let q0 = ex.run.data.qpos()[part.qadr];
    let dq = part.lo + OPEN_TO * (part.hi - part.lo) - q0;
    if dq <= 0.0 {
        return Ok(());
    }
    let span = if part.hinge { dq * norm(sub(handles[0].at, part.anchor)) } else { dq };
    let steps = ((span / STEP).ceil() as usize).clamp(2, 80);
    ex.sync_scratch();
    let now = ex.run.arm_target(ex.rig);
    let mut why = ExpertError::Ik(format!("no hand pose reaches the handle of {joint}"));
    for h in handles {
        let before = Target { pos: add(h.at, scale(h.normal, STANDOFF)), rot: h.rot };
        let (grip, travel) = ex.rig.opening_for(h.width);
        ex.rig.set_fingers(&mut ex.scratch, travel);
        let Some(q_before) = ex.free_posture(&now, &before, Allow::default()) else { continue };
        // In to the handle, then the pull, each point solved from the one before.
        let into = match ex.line(&q_before, before.pos, &Target { pos: h.at, rot: h.rot }, 3) {
            Ok(p) => p,
            Err(e) => {
                why = e;
                continue;
            }
        };
        let mut q = into.last().cloned().unwrap_or_else(|| q_before.clone());
        let mut pull = vec![q.clone()];
        // The pull, as far as the arm reaches; kept when that opens it far enough.
        let mut made = 0.0;
        for k in 1..=steps {
            let d = dq * k as f64 / steps as f64;
            let (p, turn) = moved(&part, h.at, d);
            let t = Target { pos: p, rot: mat_mul(&turn, &h.rot) };
            ex.stats.ik_solves += 1;
            match solve_ik(ex.rig, &mut ex.scratch, &q, &t, 2, &mut ex.rng) {
                Some(n) if crate::motion::dist(&n, &q) < 0.8 => {
                    q = n;
                    pull.push(q.clone());
                    made = d;
                }
                _ => break,
            }
        }
        if q0 + made < part.lo + OPEN_ENOUGH * (part.hi - part.lo) {
            why = ExpertError::Ik(format!("the pull that opens {joint} leaves the arm's reach"));
            continue;
        }
        let approach = match ex.plan_to(Allow::default(), &q_before) {
            Ok(p) => p,
            Err(e) => {
                why = e;
                continue;
            }
        };
        ex.run.ctrl[ex.rig.grip_act] = grip;
        ex.run.follow(ex.rig, &approach, 0.8)?;
        ex.run.follow(ex.rig, &into, 0.3)?;
        // Pinch: the control at the bottom of the actuator's range (past the pads touching),
        // harder than a grasp's close.
        let pinch = ex.model.actuator_ctrlrange()[ex.rig.grip_act][0].min(ex.rig.grip_closed);
        ex.run.grip(ex.rig, pinch, 0.5)?;
        ex.run.follow(ex.rig, &pull, PULL_SPEED)?;
        ex.run.grip(ex.rig, grip, 0.4)?;
        // Back off along the face's normal where the pull ended.
        ex.sync_scratch();
        let (end, turn) = moved(&part, h.at, made);
        let back = Target { pos: add(end, scale(mat_vec(&turn, h.normal), STANDOFF)), rot: mat_mul(&turn, &h.rot) };
        let from = ex.run.arm_target(ex.rig);
        if let Some(qb) = solve_ik(ex.rig, &mut ex.scratch, &from, &back, 2, &mut ex.rng) {
            ex.run.follow(ex.rig, &[from, qb], 0.5)?;
        }
        return ex.run.hold(ex.rig, 0.3);
    }
    Err(why)
}
