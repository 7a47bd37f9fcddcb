//! Driving a wheeled base to a place ("go to the table"): the base's drive wheels and
//! their velocity servos are read from the compiled scene (each wheel's radius from its
//! geometry, its side and which way it turns forward from its joint's axis), a path over
//! the floor is searched on a grid clear of every other thing's collision box (grown by
//! the base's own footprint), and the base follows it — turning on the spot towards each
//! waypoint, then driving with its heading corrected every frame — until the goal's
//! distance holds. The wheels' controls are the episode's actions, so the drive replays in
//! plain MuJoCo like an arm's.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use mujoco_rs::prelude::*;
use sw_task::Bounds;

use crate::ExpertError;
use crate::expert::Expert;
use crate::math::{cross, dot, norm};

/// Grid cell of the floor plan, m (grown when the room is large; see [`MAX_CELLS`]).
const CELL: f64 = 0.05;
/// Most cells on a side of the grid.
const MAX_CELLS: usize = 400;
/// Clearance kept between the base's footprint and other things, m.
const CLEARANCE: f64 = 0.05;
/// Things lower than this are driven over (rugs, mats), m.
const PASSABLE: f64 = 0.02;
/// Top speed of the base's centre, m/s, and of its turn, rad/s.
const V_MAX: f64 = 0.5;
const W_MAX: f64 = 1.5;
/// Heading error past which the base turns on the spot before driving, rad.
const TURN_FIRST: f64 = 0.35;
/// A waypoint is passed within this, m.
const WAYPOINT_TOL: f64 = 0.06;
/// The goal is aimed this far inside the distance the task allows, m (at most).
const GOAL_MARGIN: f64 = 0.06;
/// The base is stuck when it moved less than this over [`STUCK_SECONDS`], m ...
const STUCK_MOVE: f64 = 0.02;
const STUCK_SECONDS: f64 = 3.0;
/// ... and turned less than this, rad.
const STUCK_TURN: f64 = 0.2;

/// A drive wheel: its actuator, radius, which way its positive speed drives the base
/// (±1 along the base's x axis) and its offset to the left of the base's centre.
#[derive(Debug, Clone, Copy)]
struct Wheel {
    act: usize,
    radius: f64,
    sign: f64,
    lateral: f64,
    ctrl: [f64; 2],
}

/// The base's position and heading (its x axis) on the floor.
fn pose(data: &MjData<&MjModel>, root: usize) -> ([f64; 2], f64) {
    let p = data.xpos()[root];
    let m = data.xmat()[root];
    ([p[0], p[1]], m[3].atan2(m[0]))
}

fn wrap(a: f64) -> f64 {
    let t = std::f64::consts::TAU;
    (a + std::f64::consts::PI).rem_euclid(t) - std::f64::consts::PI
}

/// The drive wheels of the rig's base (the rig's driven joints; see `Rig::base`).
fn wheels(ex: &Expert<'_, '_>) -> Result<Vec<Wheel>, ExpertError> {
    let model = ex.model;
    let data = &ex.run.data;
    let root = ex.rig.base_body;
    let p = data.xpos()[root];
    let m = data.xmat()[root];
    let fwd = [m[0], m[3], 0.0];
    let left = [-m[3], m[0], 0.0];
    let mut out = Vec::new();
    for j in &ex.rig.arm {
        let jid = model.actuator_trnid()[j.act][0] as usize;
        let body = model.jnt_bodyid()[jid] as usize;
        let anchor = data.xanchor()[jid];
        let axis = data.xaxis()[jid];
        // A wheel turning by +ω about `axis` rolls its centre along axis × up.
        let roll = cross(axis, [0.0, 0.0, 1.0]);
        let along = dot(roll, fwd);
        // Its lowest point: the bottom of its geometry.
        let bottom = (0..model.ffi().ngeom as usize)
            .filter(|&g| model.geom_bodyid()[g] as usize == body)
            .map(|g| crate::rig::geom_bounds(model, data, g).min[2])
            .fold(f64::INFINITY, f64::min);
        let radius = anchor[2] - bottom;
        if along.abs() < 0.5 || !radius.is_finite() || radius < 0.005 {
            continue;
        }
        let r = model.actuator_ctrlrange()[j.act];
        let limited = model.actuator_ctrllimited()[j.act] && r[1] > r[0];
        out.push(Wheel {
            act: j.act,
            radius,
            sign: along.signum() / norm(roll).max(1e-9),
            lateral: dot([anchor[0] - p[0], anchor[1] - p[1], 0.0], left),
            ctrl: if limited { r } else { [-20.0, 20.0] },
        });
    }
    let sides = (out.iter().any(|w| w.lateral > 0.02), out.iter().any(|w| w.lateral < -0.02));
    if sides != (true, true) {
        return Err(ExpertError::Robot(format!(
            "{} has no drive wheels on both sides; the expert drives differential bases",
            ex.rig.robot
        )));
    }
    Ok(out)
}

/// The floor as a grid: blocked cells are within the base's footprint (plus clearance) of
/// some other thing's collision box.
struct Floor {
    x0: f64,
    y0: f64,
    cell: f64,
    nx: usize,
    ny: usize,
    blocked: Vec<bool>,
}

impl Floor {
    fn new(boxes: &[Bounds], around: [f64; 2], grow: f64) -> Floor {
        let mut lo = [around[0] - 1.0, around[1] - 1.0];
        let mut hi = [around[0] + 1.0, around[1] + 1.0];
        for b in boxes {
            lo = [lo[0].min(b.min[0] - 1.0), lo[1].min(b.min[1] - 1.0)];
            hi = [hi[0].max(b.max[0] + 1.0), hi[1].max(b.max[1] + 1.0)];
        }
        let cell = CELL.max((hi[0] - lo[0]).max(hi[1] - lo[1]) / MAX_CELLS as f64);
        let nx = ((hi[0] - lo[0]) / cell).ceil() as usize + 1;
        let ny = ((hi[1] - lo[1]) / cell).ceil() as usize + 1;
        let mut f = Floor { x0: lo[0], y0: lo[1], cell, nx, ny, blocked: vec![false; nx * ny] };
        for b in boxes {
            let (i0, j0) = f.index([b.min[0] - grow, b.min[1] - grow]);
            let (i1, j1) = f.index([b.max[0] + grow, b.max[1] + grow]);
            for i in i0..=i1 {
                for j in j0..=j1 {
                    let c = f.center(i, j);
                    let pt = Bounds { min: [c[0], c[1], 0.0], max: [c[0], c[1], 0.0] };
                    if sw_task::judge::gap(&pt, b) < grow {
                        f.blocked[j * nx + i] = true;
                    }
                }
            }
        }
        f
    }

    fn index(&self, p: [f64; 2]) -> (usize, usize) {
        let i = ((p[0] - self.x0) / self.cell).round().clamp(0.0, (self.nx - 1) as f64) as usize;
        let j = ((p[1] - self.y0) / self.cell).round().clamp(0.0, (self.ny - 1) as f64) as usize;
        (i, j)
    }

    fn center(&self, i: usize, j: usize) -> [f64; 2] {
        [self.x0 + i as f64 * self.cell, self.y0 + j as f64 * self.cell]
    }

    /// Shortest 8-connected path from `start` to the nearest cell where `goal` holds.
    fn path(&self, start: [f64; 2], goal: impl Fn([f64; 2]) -> bool) -> Option<Vec<[f64; 2]>> {
        let (si, sj) = self.index(start);
        let n = self.nx * self.ny;
        let mut cost = vec![u64::MAX; n];
        let mut from = vec![usize::MAX; n];
        let s = sj * self.nx + si;
        cost[s] = 0;
        let mut heap = BinaryHeap::new();
        heap.push(Reverse((0_u64, s)));
        while let Some(Reverse((c, k))) = heap.pop() {
            if c > cost[k] {
                continue;
            }
            let (i, j) = (k % self.nx, k / self.nx);
            if goal(self.center(i, j)) {
                let mut cells = vec![k];
                let mut cur = k;
                while from[cur] != usize::MAX {
                    cur = from[cur];
                    cells.push(cur);
                }
                cells.reverse();
                return Some(cells.into_iter().map(|c| self.center(c % self.nx, c / self.nx)).collect());
            }
            for (di, dj, w) in
                [(1, 0, 10), (-1, 0, 10), (0, 1, 10), (0, -1, 10), (1, 1, 14), (1, -1, 14), (-1, 1, 14), (-1, -1, 14)]
            {
                let (ni, nj) = (i as i64 + di, j as i64 + dj);
                if ni < 0 || nj < 0 || ni >= self.nx as i64 || nj >= self.ny as i64 {
                    continue;
                }
                let nk = nj as usize * self.nx + ni as usize;
                // The start may lie in grown space (the base stands close to something):
                // the path may leave it within its first metre, never enter it.
                if self.blocked[nk] && (!self.blocked[k] || c as f64 * 0.1 * self.cell > 1.0) {
                    continue;
                }
                let nc = c + w;
                if nc < cost[nk] {
                    cost[nk] = nc;
                    from[nk] = k;
                    heap.push(Reverse((nc, nk)));
                }
            }
        }
        None
    }

    /// True when the straight segment a–b crosses no blocked cell, except on its way out
    /// of the blocked space `a` stands in.
    fn clear(&self, a: [f64; 2], b: [f64; 2]) -> bool {
        let d = (b[0] - a[0]).hypot(b[1] - a[1]);
        let steps = (d / (0.5 * self.cell)).ceil().max(1.0) as usize;
        let (i, j) = self.index(a);
        let mut leaving = self.blocked[j * self.nx + i];
        (1..=steps).all(|k| {
            let t = k as f64 / steps as f64;
            let (i, j) = self.index([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
            let blocked = self.blocked[j * self.nx + i];
            leaving &= blocked;
            leaving || !blocked
        })
    }

    /// The path with every waypoint dropped that a straight line can skip.
    fn simplify(&self, path: &[[f64; 2]]) -> Vec<[f64; 2]> {
        let mut out = vec![path[0]];
        let mut k = 0;
        while k + 1 < path.len() {
            let mut far = k + 1;
            for m in (k + 2..path.len()).rev() {
                if self.clear(path[k], path[m]) {
                    far = m;
                    break;
                }
            }
            out.push(path[far]);
            k = far;
        }
        out
    }
}

/// Drives the rig's base until its centre is within `within` of `target`'s collision box
/// on the floor.
pub(crate) fn navigate(ex: &mut Expert<'_, '_>, target: &str, within: f64) -> Result<(), ExpertError> {
    let wheels = wheels(ex)?;
    let root = ex.rig.base_body;
    let snap = ex.snapshot();
    let robot_root = ex.model.id_to_name(MjtObjBase::mjOBJ_BODY, root).unwrap_or("").to_string();
    let goal_box = snap
        .bodies
        .get(target)
        .map(|b| b.bounds)
        .ok_or_else(|| ExpertError::Scene(format!("no body '{target}' in the scene")))?;
    let (start, _) = pose(&ex.run.data, root);
    // The base's footprint about its centre: the narrower half of its box (a base is
    // longer than wide; it comes up to things head-on or side-on, and the clearance
    // covers its corners as it turns).
    let me = snap.bodies.get(&robot_root).map(|b| b.bounds);
    let foot = me.map_or(0.3, |b| {
        let dx = (b.max[0] - start[0]).abs().max((start[0] - b.min[0]).abs());
        let dy = (b.max[1] - start[1]).abs().max((start[1] - b.min[1]).abs());
        dx.min(dy)
    });
    let boxes: Vec<Bounds> = snap
        .bodies
        .iter()
        .filter(|(n, b)| **n != robot_root && b.bounds.max[2] > PASSABLE)
        .map(|(_, b)| b.bounds)
        .collect();
    let floor = Floor::new(&boxes, start, foot + CLEARANCE);
    let aim = within - GOAL_MARGIN.min(0.3 * within);
    let at_goal = |p: [f64; 2]| {
        let pt = Bounds { min: [p[0], p[1], 0.0], max: [p[0], p[1], 0.0] };
        sw_task::judge::gap(&pt, &goal_box) <= aim
    };
    let cells = floor.path(start, at_goal).ok_or_else(|| {
        ExpertError::Path(format!(
            "no way over the floor brings {} within {within:.2} m of {target} (its footprint is {:.2} m across)",
            ex.rig.robot,
            2.0 * foot
        ))
    })?;
    let path = floor.simplify(&cells);
    // Bound the drive by its length at the base's top speed (the wheels' limits).
    let v_top = wheels.iter().map(|w| w.ctrl[1].abs().min(w.ctrl[0].abs()) * w.radius).fold(V_MAX, f64::min);
    let length: f64 = path.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum();
    let fps = f64::from(ex.run.fps);
    let needed = ex.run.rec.actions.len() + ((3.0 * length / v_top.max(0.02) + 20.0) * fps) as usize;
    ex.run.max_frames = ex.run.max_frames.max(needed);
    let stuck_frames = (STUCK_SECONDS * fps) as usize;
    for (k, w) in path.iter().enumerate().skip(1) {
        let last = k + 1 == path.len();
        let mut trail: Vec<([f64; 2], f64)> = Vec::new();
        loop {
            let (p, yaw) = pose(&ex.run.data, root);
            let d = (w[0] - p[0]).hypot(w[1] - p[1]);
            // The last waypoint is only where the search stopped: the goal holding is enough.
            if (last && at_goal(p)) || d < WAYPOINT_TOL {
                break;
            }
            trail.push((p, yaw));
            if trail.len() > stuck_frames {
                let (q, qyaw) = trail[trail.len() - 1 - stuck_frames];
                // Neither moved nor turned (a turn on the spot is progress).
                if (p[0] - q[0]).hypot(p[1] - q[1]) < STUCK_MOVE && wrap(yaw - qyaw).abs() < STUCK_TURN {
                    return Err(ExpertError::Failed(format!(
                        "{} is stuck {:.2} m short of a waypoint on its way to {target}",
                        ex.rig.robot, d
                    )));
                }
            }
            let err = wrap((w[1] - p[1]).atan2(w[0] - p[0]) - yaw);
            // Turn on the spot when far off the heading; else drive, no faster than lets the
            // turn close in on the waypoint (an arc of radius v / ω below half the distance
            // left, or the base circles the waypoint for ever).
            let om = (4.0 * err).clamp(-W_MAX, W_MAX);
            let v = if err.abs() > TURN_FIRST { 0.0 } else { (1.5 * d).min(V_MAX).min(0.4 * W_MAX * d) * err.cos() };
            set_wheels(ex, &wheels, v, om);
            ex.run.frame(ex.rig)?;
        }
    }
    set_wheels(ex, &wheels, 0.0, 0.0);
    ex.run.hold(ex.rig, 0.5)
}

/// Wheel speeds for a forward speed `v` and a turn `om` (counter-clockwise), scaled down
/// together when one would pass its servo's limit.
fn set_wheels(ex: &mut Expert<'_, '_>, wheels: &[Wheel], v: f64, om: f64) {
    let raw: Vec<f64> = wheels.iter().map(|w| w.sign * (v - om * w.lateral) / w.radius).collect();
    let over = wheels
        .iter()
        .zip(&raw)
        .map(|(w, r)| if *r > 0.0 { r / w.ctrl[1].max(1e-9) } else { r / w.ctrl[0].min(-1e-9) })
        .fold(1.0_f64, f64::max);
    for (w, r) in wheels.iter().zip(raw) {
        ex.run.ctrl[w.act] = r / over;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_path_goes_around_a_box_to_the_far_side() {
        // A 1 m wall between the start and the goal region.
        let wall = Bounds { min: [0.9, -0.5, 0.0], max: [1.1, 0.5, 1.0] };
        let floor = Floor::new(&[wall], [0.0, 0.0], 0.2);
        let goal = |p: [f64; 2]| p[0] > 2.0 && p[1].abs() < 0.1;
        let cells = floor.path([0.0, 0.0], goal).unwrap();
        let path = floor.simplify(&cells);
        // Every segment stays clear of the grown wall, and the path ends at the goal.
        for s in path.windows(2) {
            assert!(floor.clear(s[0], s[1]), "{s:?}");
        }
        let end = *path.last().unwrap();
        assert!(goal(end), "{end:?}");
        assert!(path.len() >= 3, "the wall is in the way: {path:?}");
        // No goal beyond a closed room.
        let room = [
            Bounds { min: [-1.0, -1.0, 0.0], max: [1.0, -0.9, 1.0] },
            Bounds { min: [-1.0, 0.9, 0.0], max: [1.0, 1.0, 1.0] },
            Bounds { min: [-1.0, -1.0, 0.0], max: [-0.9, 1.0, 1.0] },
            Bounds { min: [0.9, -1.0, 0.0], max: [1.0, 1.0, 1.0] },
        ];
        let shut = Floor::new(&room, [0.0, 0.0], 0.2);
        assert!(shut.path([0.0, 0.0], |p| p[0] > 2.0).is_none());
    }

    #[test]
    fn angles_wrap_to_a_half_turn() {
        assert!((wrap(3.0 * std::f64::consts::PI).abs() - std::f64::consts::PI).abs() < 1e-9);
        assert!((wrap(0.5) - 0.5).abs() < 1e-12);
        assert!((wrap(-7.0) - (-7.0 + std::f64::consts::TAU)).abs() < 1e-12);
    }
}
