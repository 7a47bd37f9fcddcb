//! Inverse kinematics on MuJoCo's Jacobian: damped least squares on the tool centre
//! point's position and orientation, steps limited and clamped to the joint limits, from
//! several starts (the current pose first, then seeded random ones).

use mujoco_rs::prelude::*;
use mujoco_rs::wrappers::mj_model::traits::ModelType;
use sw_geom::Rng;

use crate::math::{M3, V3, norm, rotation_error, solve, sub};
use crate::rig::Rig;

/// A pose of the tool centre point to reach.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Target {
    pub pos: V3,
    pub rot: M3,
}

const POS_TOL: f64 = 0.002;
const ROT_TOL: f64 = 0.02;
const ITERS: usize = 120;
const DAMPING: f64 = 0.05;
const MAX_STEP: f64 = 0.25;
/// Two solutions closer than this (joint-space distance, rad) are the same posture.
const DISTINCT: f64 = 0.3;

/// Forward kinematics of the current qpos (positions, then the quantities the Jacobian
/// reads).
pub(crate) fn fk<M: ModelType>(data: &mut MjData<M>) {
    data.kinematics();
    data.com_pos();
}

/// One IK solve from `start`; the joint vector and its final errors (m, rad).
fn solve_from<M: ModelType>(rig: &Rig, data: &mut MjData<M>, start: &[f64], t: &Target) -> (Vec<f64>, f64, f64) {
    let n = rig.n();
    let nv = data.model().ffi().nv as usize;
    let mut q = start.to_vec();
    let mut errs = (f64::INFINITY, f64::INFINITY);
    for _ in 0..ITERS {
        rig.set_arm_q(data, &q);
        fk(data);
        let (p, r) = rig.tcp_pose(data);
        let ep = sub(t.pos, p);
        let er = rotation_error(&t.rot, &r);
        errs = (norm(ep), norm(er));
        if errs.0 < POS_TOL && errs.1 < ROT_TOL {
            break;
        }
        let (jp, jr) = data.jac_site(true, true, rig.tcp);
        // J (6 × n) over the arm's dofs; rotation weighted less than position.
        let w_rot = 0.5;
        let mut jm = vec![0.0; 6 * n];
        for (k, j) in rig.arm.iter().enumerate() {
            for i in 0..3 {
                jm[i * n + k] = jp[i * nv + j.dof];
                jm[(3 + i) * n + k] = w_rot * jr[i * nv + j.dof];
            }
        }
        let e = [ep[0], ep[1], ep[2], w_rot * er[0], w_rot * er[1], w_rot * er[2]];
        // dq = Jᵀ (J Jᵀ + λ² I)⁻¹ e
        let mut a = vec![0.0; 36];
        for r1 in 0..6 {
            for r2 in 0..6 {
                a[r1 * 6 + r2] = (0..n).map(|k| jm[r1 * n + k] * jm[r2 * n + k]).sum::<f64>()
                    + if r1 == r2 { DAMPING * DAMPING } else { 0.0 };
            }
        }
        let Some(y) = solve(a, e.to_vec(), 6) else { break };
        let mut dq: Vec<f64> = (0..n).map(|k| (0..6).map(|r1| jm[r1 * n + k] * y[r1]).sum()).collect();
        let big = dq.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        if big > MAX_STEP {
            dq.iter_mut().for_each(|v| *v *= MAX_STEP / big);
        }
        for (qi, d) in q.iter_mut().zip(&dq) {
            *qi += d;
        }
        rig.clamp(&mut q);
    }
    (q, errs.0, errs.1)
}

/// Solves for `t` from start 0 (`near`) and `restarts` more (`start_of(k)`), handing each
/// converged solution to `visit(k, q)` until it returns true; the state is left as it was.
fn each_solution<M: ModelType>(
    rig: &Rig,
    data: &mut MjData<M>,
    near: &[f64],
    t: &Target,
    restarts: usize,
    mut start_of: impl FnMut(usize) -> Vec<f64>,
    mut visit: impl FnMut(usize, Vec<f64>) -> bool,
) {
    let saved = rig.arm_q(data);
    for k in 0..=restarts {
        let start = if k == 0 { near.to_vec() } else { start_of(k) };
        let (q, ep, er) = solve_from(rig, data, &start, t);
        if ep < POS_TOL * 2.0 && er < ROT_TOL * 2.0 && visit(k, q) {
            break;
        }
    }
    rig.set_arm_q(data, &saved);
    fk(data);
}

/// Joint positions that put the tool at `t`, nearest to `near` among the solutions found
/// from `near` and up to `restarts` seeded random starts. `None` when none converges.
pub(crate) fn solve_ik<M: ModelType>(
    rig: &Rig,
    data: &mut MjData<M>,
    near: &[f64],
    t: &Target,
    restarts: usize,
    rng: &mut Rng,
) -> Option<Vec<f64>> {
    let mut best: Option<(f64, Vec<f64>)> = None;
    // Around the current pose first, wider later.
    let start_of = |k: usize| -> Vec<f64> {
        let spread = if k < restarts / 2 { 0.6 } else { 2.5 };
        rig.arm.iter().zip(near).map(|(j, q)| (q + rng.range(-spread, spread)).clamp(j.lo, j.hi)).collect()
    };
    each_solution(rig, data, near, t, restarts, start_of, |k, q| {
        let d = crate::motion::dist(&q, near);
        if best.as_ref().is_none_or(|(bd, _)| d < *bd) {
            best = Some((d, q));
        }
        // The first from the current pose is near enough; so is any within 1 rad.
        k == 0 || best.as_ref().is_some_and(|(bd, _)| *bd < 1.0)
    });
    best.map(|(_, q)| q)
}

/// Distinct joint solutions for `t` (nearest to `near` first) from `near` and `restarts`
/// seeded random starts over the whole joint range: the other postures of the arm (elbow
/// up or down, wrist flipped) to try when the nearest one collides.
pub(crate) fn solve_ik_all<M: ModelType>(
    rig: &Rig,
    data: &mut MjData<M>,
    near: &[f64],
    t: &Target,
    restarts: usize,
    rng: &mut Rng,
) -> Vec<Vec<f64>> {
    let mut found: Vec<(f64, Vec<f64>)> = Vec::new();
    let start_of = |_: usize| -> Vec<f64> {
        let pi = std::f64::consts::PI;
        rig.arm.iter().map(|j| rng.range(j.lo.max(-pi), j.hi.min(pi))).collect()
    };
    each_solution(rig, data, near, t, restarts, start_of, |_, q| {
        if found.iter().all(|(_, f)| crate::motion::dist(f, &q) > DISTINCT) {
            found.push((crate::motion::dist(&q, near), q));
        }
        false
    });
    found.sort_by(|a, b| a.0.total_cmp(&b.0));
    found.into_iter().map(|(_, q)| q).collect()
}
