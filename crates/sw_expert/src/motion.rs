//! Collision-free motion in joint space, checked by MuJoCo itself: a configuration is set
//! (the carried thing moved with the hand), MuJoCo's kinematics and collision detection
//! run, and any contact deeper than [`DEPTH`] that involves the robot or the carried thing
//! makes it a collision — except the fingers on the thing they hold and the robot's base
//! on its mount. Paths are searched by RRT-Connect (a straight line is tried first) and
//! shortened by random shortcuts.
//!
//! A maintained planning library (OMPL) has Python wheels only; the planner's whole cost
//! here is the collision check, which is MuJoCo's, so the sampler is written here.

use mujoco_rs::prelude::*;
use mujoco_rs::wrappers::mj_model::traits::ModelType;
use sw_geom::Rng;

use crate::ik::fk;
use crate::math::{M3, V3, add, mat_mul, mat_to_quat, mat_vec, transpose};
use crate::rig::Rig;

/// Penetration that counts as a collision, m (grazing contacts at the mount are not).
const DEPTH: f64 = 0.002;
/// Largest joint step between checked configurations on an edge, rad.
const RESOLUTION: f64 = 0.04;
const STEP: f64 = 0.3;
const MAX_NODES: usize = 3000;
const SHORTCUTS: usize = 80;

/// A thing held in the hand: its body, free joint and pose in the tool frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Held {
    pub body: usize,
    pub qpos: usize,
    pub rel_pos: V3,
    pub rel_rot: M3,
    /// Its centre of mass in the tool frame: what must stay put in the hand (a ball
    /// may turn between the pads, which moves its frame's origin but not its centre).
    pub rel_com: V3,
}

impl Held {
    /// Records `body`'s pose relative to the tool as it is now.
    pub fn grasped<M: ModelType>(rig: &Rig, data: &MjData<M>, body: usize, qpos: usize) -> Self {
        let (tp, tr) = rig.tcp_pose(data);
        let bp = data.xpos()[body];
        let br = data.xmat()[body];
        let rt = transpose(&tr);
        Held {
            body,
            qpos,
            rel_pos: mat_vec(&rt, crate::math::sub(bp, tp)),
            rel_rot: mat_mul(&rt, &br),
            rel_com: mat_vec(&rt, crate::math::sub(data.xipos()[body], tp)),
        }
    }

    /// How far the thing is from where the grasp put it in the hand, m.
    pub fn drift<M: ModelType>(&self, data: &MjData<M>, tcp: usize) -> f64 {
        let (tp, tr) = (data.site_xpos()[tcp], data.site_xmat()[tcp]);
        crate::math::norm(crate::math::sub(data.xipos()[self.body], add(tp, mat_vec(&tr, self.rel_com))))
    }

    /// Moves the held thing's free joint to follow the tool (after `fk`).
    fn follow<M: ModelType>(&self, rig: &Rig, data: &mut MjData<M>) {
        let (tp, tr) = rig.tcp_pose(data);
        let p = add(tp, mat_vec(&tr, self.rel_pos));
        let q = mat_to_quat(&mat_mul(&tr, &self.rel_rot));
        let qp = data.qpos_mut();
        qp[self.qpos..self.qpos + 3].copy_from_slice(&p);
        qp[self.qpos + 3..self.qpos + 7].copy_from_slice(&q);
    }
}

/// What a collision check allows.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Allow {
    /// The thing in the hand (moved with it; the fingers may touch it).
    pub held: Option<Held>,
    /// A thing the hand may touch where it stands (at a grasp): the body, and the one geom
    /// of it the fingers may touch (`None`: any of its geoms).
    pub touch: Option<(usize, Option<usize>)>,
}

/// Collision checks on a scratch copy of the state.
#[derive(Debug)]
pub(crate) struct Checker<'r> {
    pub rig: &'r Rig,
    pub allow: Allow,
    pub checks: usize,
    /// The two bodies of the last contact that made a configuration a collision.
    pub hit: Option<(usize, usize)>,
}

impl<'r> Checker<'r> {
    pub fn new(rig: &'r Rig, allow: Allow) -> Self {
        Self { rig, allow, checks: 0, hit: None }
    }

    /// True when configuration `q` is free of collisions.
    pub fn free<M: ModelType>(&mut self, data: &mut MjData<M>, q: &[f64]) -> bool {
        self.checks += 1;
        self.rig.set_arm_q(data, q);
        data.kinematics();
        if let Some(h) = self.allow.held {
            h.follow(self.rig, data);
            data.kinematics();
        }
        data.collision();
        let model = data.model();
        let root = model.body_rootid();
        let held = self.allow.held.map(|h| h.body);
        let ncon = data.ncon().max(0) as usize;
        for c in data.contact().iter().take(ncon) {
            if c.dist > -DEPTH {
                continue;
            }
            let b1 = model.geom_bodyid()[c.geom1 as usize] as usize;
            let b2 = model.geom_bodyid()[c.geom2 as usize] as usize;
            let involves = |b: usize| self.rig.robot_body[b] || Some(b) == held;
            if !involves(b1) && !involves(b2) {
                continue;
            }
            // The robot's base on its mount never moves (but a carried thing must clear it).
            let base = |b: usize| b == self.rig.base_body || (self.rig.robot_body[b] && root[b] as usize == b);
            if (base(b1) || base(b2)) && held.is_none_or(|h| h != b1 && h != b2) {
                continue;
            }
            // Fingers on the thing they hold or are about to.
            let hand = &self.rig.hand_body;
            let fingers_on = |h: usize| (b1 == h && hand[b2]) || (b2 == h && hand[b1]);
            if held.is_some_and(fingers_on) {
                continue;
            }
            if let Some((body, geom)) = self.allow.touch
                && fingers_on(body)
                && geom.is_none_or(|g| c.geom1 as usize == g || c.geom2 as usize == g)
            {
                continue;
            }
            self.hit = Some((b1, b2));
            return false;
        }
        true
    }

    /// True when the straight joint-space segment `a`–`b` is free.
    pub fn edge_free<M: ModelType>(&mut self, data: &mut MjData<M>, a: &[f64], b: &[f64]) -> bool {
        let d = dist(a, b);
        let steps = (d / RESOLUTION).ceil().max(1.0) as usize;
        (1..=steps).all(|k| {
            let t = k as f64 / steps as f64;
            let q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + t * (y - x)).collect();
            self.free(data, &q)
        })
    }
}

pub(crate) fn dist(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>().sqrt()
}

fn steer(from: &[f64], to: &[f64]) -> Vec<f64> {
    let d = dist(from, to);
    if d <= STEP {
        return to.to_vec();
    }
    from.iter().zip(to).map(|(a, b)| a + (b - a) * STEP / d).collect()
}

struct Tree {
    nodes: Vec<Vec<f64>>,
    parent: Vec<usize>,
}

impl Tree {
    fn nearest(&self, q: &[f64]) -> usize {
        let mut best = (f64::INFINITY, 0);
        for (i, n) in self.nodes.iter().enumerate() {
            let d = dist(n, q);
            if d < best.0 {
                best = (d, i);
            }
        }
        best.1
    }

    fn path_to_root(&self, mut i: usize) -> Vec<Vec<f64>> {
        let mut out = vec![self.nodes[i].clone()];
        while i != 0 {
            i = self.parent[i];
            out.push(self.nodes[i].clone());
        }
        out
    }
}

/// A collision-free joint path from `start` to `goal` (both included), or `None`.
pub(crate) fn plan<M: ModelType>(
    checker: &mut Checker<'_>,
    data: &mut MjData<M>,
    start: &[f64],
    goal: &[f64],
    rng: &mut Rng,
) -> Option<Vec<Vec<f64>>> {
    let saved = checker.rig.arm_q(data);
    let out = plan_inner(checker, data, start, goal, rng);
    checker.rig.set_arm_q(data, &saved);
    fk(data);
    out
}

fn plan_inner<M: ModelType>(
    checker: &mut Checker<'_>,
    data: &mut MjData<M>,
    start: &[f64],
    goal: &[f64],
    rng: &mut Rng,
) -> Option<Vec<Vec<f64>>> {
    if !checker.free(data, goal) {
        return None;
    }
    if checker.edge_free(data, start, goal) {
        return Some(vec![start.to_vec(), goal.to_vec()]);
    }
    // Sample within the joint limits, around the two ends for unlimited joints.
    let bounds: Vec<(f64, f64)> = checker
        .rig
        .arm
        .iter()
        .enumerate()
        .map(|(k, j)| {
            let lo = j.lo.max(start[k].min(goal[k]) - std::f64::consts::PI);
            let hi = j.hi.min(start[k].max(goal[k]) + std::f64::consts::PI);
            (lo, hi)
        })
        .collect();
    let mut a = Tree { nodes: vec![start.to_vec()], parent: vec![0] };
    let mut b = Tree { nodes: vec![goal.to_vec()], parent: vec![0] };
    let mut a_is_start = true;
    while a.nodes.len() + b.nodes.len() < MAX_NODES {
        let sample: Vec<f64> = if rng.chance(0.1) {
            b.nodes[0].clone()
        } else {
            bounds.iter().map(|(lo, hi)| rng.range(*lo, *hi)).collect()
        };
        // Extend a towards the sample.
        let i = a.nearest(&sample);
        let q = steer(&a.nodes[i], &sample);
        if checker.edge_free(data, &a.nodes[i], &q) {
            a.nodes.push(q.clone());
            a.parent.push(i);
            let new_a = a.nodes.len() - 1;
            // Connect b towards it.
            let mut j = b.nearest(&q);
            loop {
                let r = steer(&b.nodes[j], &q);
                if !checker.edge_free(data, &b.nodes[j], &r) {
                    break;
                }
                b.nodes.push(r.clone());
                b.parent.push(j);
                j = b.nodes.len() - 1;
                if dist(&r, &q) < 1e-9 {
                    let mut pa = a.path_to_root(new_a);
                    pa.reverse();
                    let pb = b.path_to_root(j);
                    pa.extend(pb.into_iter().skip(1));
                    if !a_is_start {
                        pa.reverse();
                    }
                    return Some(shortcut(checker, data, pa, rng));
                }
            }
        }
        std::mem::swap(&mut a, &mut b);
        a_is_start = !a_is_start;
    }
    None
}

/// Removes waypoints where a straight segment between non-neighbours is free.
fn shortcut<M: ModelType>(
    checker: &mut Checker<'_>,
    data: &mut MjData<M>,
    mut path: Vec<Vec<f64>>,
    rng: &mut Rng,
) -> Vec<Vec<f64>> {
    for _ in 0..SHORTCUTS {
        if path.len() < 3 {
            break;
        }
        let i = rng.below(path.len() - 2);
        let j = i + 2 + rng.below(path.len() - i - 2);
        if checker.edge_free(data, &path[i], &path[j]) {
            path.drain(i + 1..j);
        }
    }
    path
}
