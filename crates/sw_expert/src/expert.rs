//! The expert: for each goal of the task, pick the thing (a grasp from its collision box,
//! IK, a collision-free path to above it, straight down, close, lift), carry it (a path
//! with the thing in the hand), put it down where the goal wants it, open, retreat. Then
//! the task is judged on the state.

use mujoco_rs::prelude::*;
use sw_geom::Rng;
use sw_task::{Predicate, Snapshot, Task};

use crate::grasp::{APPROACH, Grasp, free_spots, grasps, local_box, support_under};
use crate::ik::{Target, fk, solve_ik, solve_ik_all};
use crate::math::{V3, add, rot_z, sub};
use crate::motion::{Allow, Checker, Held, plan};
use crate::rig::Rig;
use crate::run::Runner;
use crate::{ExpertError, Stats};

/// How high the thing is lifted before it is carried, m.
const LIFT: f64 = 0.12;
/// Height above the destination at which the thing is let go, m.
const RELEASE_GAP: f64 = 0.012;
/// Extra height when dropping into a container, m.
const DROP_GAP: f64 = 0.03;
/// Fraction of the joint speed limit a carried thing is moved at.
const CARRY_SPEED: f64 = 0.6;
/// The lever (centre of mass from the pinch, m) up to which a thing is carried at
/// [`CARRY_SPEED`]; past it the speed falls as 1/lever (see [`carry_speed`]).
const CARRY_LEVER: f64 = 0.02;
/// The slowest carry, as a fraction of the joint speed limit.
const CARRY_SPEED_MIN: f64 = 0.15;
/// Turns about the vertical tried for a place, rad.
const TURNS: [f64; 4] = [0.0, std::f64::consts::FRAC_PI_2, -std::f64::consts::FRAC_PI_2, std::f64::consts::PI];
/// IK restarts per pose.
const RESTARTS: usize = 12;
/// Pitches of the hand tried for a grasp, in order (each both ways), rad.
const PITCHES: [f64; 3] = [0.0, 0.35, 0.7];
/// Grasps tried when the thing slips out on the lift.
const GRASP_TRIES: usize = 2;

/// A collision-free joint solution, or why there is none.
enum Posture {
    Free(Vec<f64>),
    NoIk,
    /// Every posture found collides (the last pair of bodies hit).
    Hit(Option<(usize, usize)>),
}

/// Why the grasp candidates of a thing were rejected, for the attempt's log line.
#[derive(Debug, Default)]
struct Rejections {
    tried: usize,
    ik_above: usize,
    ik_at: usize,
    /// Collisions, by the pair of bodies' names.
    hits: std::collections::BTreeMap<String, usize>,
}

impl Rejections {
    fn hit(&mut self, model: &MjModel, pair: Option<(usize, usize)>) {
        let name = |b: usize| model.id_to_name(MjtObjBase::mjOBJ_BODY, b).unwrap_or("?").to_string();
        let key = pair.map_or_else(|| "?".to_string(), |(a, b)| format!("{}–{}", name(a), name(b)));
        *self.hits.entry(key).or_insert(0) += 1;
    }
}

impl std::fmt::Display for Rejections {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} tried: {} no IK above, {} no IK at the grasp", self.tried, self.ik_above, self.ik_at)?;
        for (k, n) in &self.hits {
            write!(f, ", {n} hit {k}")?;
        }
        Ok(())
    }
}

pub(crate) struct Expert<'a, 'm> {
    pub model: &'m MjModel,
    pub rig: &'a Rig,
    pub run: Runner<'m>,
    /// Planning copy of the state.
    pub scratch: MjData<&'m MjModel>,
    pub rng: Rng,
    pub stats: Stats,
    pub reach: f64,
}

impl<'a, 'm> Expert<'a, 'm> {
    pub(crate) fn sync_scratch(&mut self) {
        let q = self.run.data.qpos().to_vec();
        self.scratch.qpos_mut().copy_from_slice(&q);
        fk(&mut self.scratch);
    }

    pub fn snapshot(&self) -> Snapshot {
        self.rig.snapshot(self.model, &self.run.data)
    }

    fn ik(&mut self, near: &[f64], t: &Target) -> Option<Vec<f64>> {
        self.stats.ik_solves += 1;
        solve_ik(self.rig, &mut self.scratch, near, t, RESTARTS, &mut self.rng)
    }

    /// A straight line of the tool from where it is to `to` (same rotation), as joint
    /// waypoints each solved from the one before.
    pub(crate) fn line(
        &mut self,
        from_q: &[f64],
        from: V3,
        to: &Target,
        pieces: usize,
    ) -> Result<Vec<Vec<f64>>, ExpertError> {
        let mut path = vec![from_q.to_vec()];
        let mut q = from_q.to_vec();
        for k in 1..=pieces {
            let s = k as f64 / pieces as f64;
            let t = Target { pos: add(from, crate::math::scale(sub(to.pos, from), s)), rot: to.rot };
            self.stats.ik_solves += 1;
            q = solve_ik(self.rig, &mut self.scratch, &q, &t, 2, &mut self.rng)
                .ok_or_else(|| ExpertError::Ik("a straight move of the hand has no joint solution".into()))?;
            path.push(q.clone());
        }
        Ok(path)
    }

    pub(crate) fn plan_to(&mut self, allow: Allow, goal: &[f64]) -> Result<Vec<Vec<f64>>, ExpertError> {
        let start = self.run.arm_target(self.rig);
        let mut checker = Checker::new(self.rig, allow);
        let out = plan(&mut checker, &mut self.scratch, &start, goal, &mut self.rng);
        self.stats.collision_checks += checker.checks;
        out.ok_or_else(|| ExpertError::Path("no collision-free path for the arm was found".into()))
    }

    /// Joints that put the tool at `t` free of collisions: the nearest posture, else the
    /// arm's other postures (elbow, shoulder, wrist flipped) from restarts over the whole
    /// joint range.
    fn posture(&mut self, near: &[f64], t: &Target, allow: Allow) -> Posture {
        let Some(first) = self.ik(near, t) else { return Posture::NoIk };
        let mut c = Checker::new(self.rig, allow);
        let free = c.free(&mut self.scratch, &first);
        if free {
            self.stats.collision_checks += c.checks;
            return Posture::Free(first);
        }
        let mut hit = c.hit;
        self.stats.ik_solves += 1;
        let alt = solve_ik_all(self.rig, &mut self.scratch, near, t, RESTARTS, &mut self.rng);
        for q in alt.into_iter().filter(|q| crate::motion::dist(q, &first) > 0.3) {
            if c.free(&mut self.scratch, &q) {
                self.stats.collision_checks += c.checks;
                return Posture::Free(q);
            }
            hit = c.hit;
        }
        self.stats.collision_checks += c.checks;
        Posture::Hit(hit)
    }

    /// A collision-free posture putting the tool at `t` (see [`Expert::posture`]).
    pub(crate) fn free_posture(&mut self, near: &[f64], t: &Target, allow: Allow) -> Option<Vec<f64>> {
        match self.posture(near, t, allow) {
            Posture::Free(q) => Some(q),
            Posture::NoIk | Posture::Hit(_) => None,
        }
    }

    /// Runs every goal in order.
    pub fn solve(&mut self, task: &Task) -> Result<(), ExpertError> {
        // Let the scene come to rest with the gripper open.
        self.run.ctrl[self.rig.grip_act] = self.rig.grip_open;
        self.run.hold(self.rig, 0.2)?;
        for g in &task.goals {
            self.goal(g)?;
        }
        self.run.hold(self.rig, 0.5)
    }

    fn goal(&mut self, g: &Predicate) -> Result<(), ExpertError> {
        self.run.holding = None;
        if let Predicate::NavigateTo { target, within, .. } = g {
            return crate::drive::navigate(self, target, *within);
        }
        match g {
            Predicate::Closed { joint, .. } => return crate::articulate::close(self, joint),
            Predicate::Open { joint, .. } => return crate::articulate::open(self, joint),
            _ => {}
        }
        let Some(object) = g.subject() else {
            return Err(ExpertError::Unsupported(format!("the expert cannot do {} yet", g.name())));
        };
        let (body, free) = *self
            .rig
            .objects
            .get(object)
            .ok_or_else(|| ExpertError::Scene(format!("no body '{object}' in the scene")))?;
        let qadr = free.ok_or_else(|| ExpertError::Grasp(format!("{object} is fixed in place")))?;
        let held = self.pick(object, body, qadr)?;
        if let Predicate::AtPose { pos, .. } = g {
            let snap = self.snapshot();
            let c = snap.bodies.get(object).map(|b| b.bounds.center()).unwrap_or(*pos);
            let (tp, tr) = self.rig.tcp_pose(&self.run.data);
            let to = Target { pos: add(tp, sub(*pos, c)), rot: tr };
            self.sync_scratch();
            let q = self.run.arm_target(self.rig);
            let path = self.line(&q, tp, &to, 4)?;
            return self.run.follow(self.rig, &path, 0.4);
        }
        let dests = self.destinations(g, object, body)?;
        self.place(object, held, &dests)
    }

    /// Grasps `object` and lifts it, trying again (from a fresh look at where it lies)
    /// when it slips out on the lift; the thing's pose in the hand.
    fn pick(&mut self, object: &str, body: usize, qadr: usize) -> Result<Held, ExpertError> {
        let mut last = None;
        for _ in 0..GRASP_TRIES {
            match self.pick_once(object, body, qadr) {
                Ok(h) => return Ok(h),
                Err(e @ ExpertError::Failed(_)) => {
                    // Let go, back off upwards, and look again.
                    self.run.grip(self.rig, self.rig.grip_open, 0.4)?;
                    self.sync_scratch();
                    let here = self.run.arm_target(self.rig);
                    let (tp, tr) = self.rig.tcp_pose(&self.scratch);
                    let up = Target { pos: add(tp, [0.0, 0.0, 0.5 * APPROACH]), rot: tr };
                    if let Ok(back) = self.line(&here, tp, &up, 2) {
                        self.run.follow(self.rig, &back, 0.5)?;
                    }
                    self.run.hold(self.rig, 0.3)?;
                    last = Some(e);
                }
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| ExpertError::Failed(format!("{object} could not be picked"))))
    }

    /// One grasp and lift of `object`. Candidates straight from above first; when none of
    /// them has a free joint solution, the same grasps with the hand pitched more and more.
    fn pick_once(&mut self, object: &str, body: usize, qadr: usize) -> Result<Held, ExpertError> {
        self.sync_scratch();
        let snap = self.snapshot();
        let bounds = snap
            .bodies
            .get(object)
            .map(|b| b.bounds)
            .ok_or_else(|| ExpertError::Scene(format!("{object} has no collision geometry")))?;
        let support = support_under(&snap, object);
        let candidates: Vec<Grasp> = grasps(self.model, &self.scratch, self.rig, body, object, &bounds, support)?;
        let now = self.run.arm_target(self.rig);
        let mut why = Rejections::default();
        let mut chosen: Option<(Grasp, Vec<f64>)> = None;
        for pitch in PITCHES {
            let mut best_d = f64::INFINITY;
            for c0 in &candidates {
                let signs: &[f64] = if pitch == 0.0 { &[1.0] } else { &[1.0, -1.0] };
                for sign in signs {
                    let c = c0.pitched(sign * pitch);
                    why.tried += 1;
                    self.rig.set_fingers(&mut self.scratch, self.rig.opening_for(c.width).1);
                    let q_above = match self.posture(&now, &c.above(APPROACH), Allow::default()) {
                        Posture::Free(q) => q,
                        Posture::NoIk => {
                            why.ik_above += 1;
                            continue;
                        }
                        Posture::Hit(pair) => {
                            why.hit(self.model, pair);
                            continue;
                        }
                    };
                    let Some(q_at) = self.ik(&q_above, &c.at) else {
                        why.ik_at += 1;
                        continue;
                    };
                    let mut touch = Checker::new(self.rig, Allow { held: None, touch: Some((body, c.geom)) });
                    let free_at = touch.free(&mut self.scratch, &q_at);
                    self.stats.collision_checks += touch.checks;
                    if !free_at {
                        why.hit(self.model, touch.hit);
                        continue;
                    }
                    let d = crate::motion::dist(&now, &q_above);
                    if d < best_d {
                        best_d = d;
                        chosen = Some((c, q_above));
                    }
                }
            }
            if chosen.is_some() {
                break;
            }
        }
        self.sync_scratch();
        let (grasp, q_above) = chosen
            .ok_or_else(|| ExpertError::Ik(format!("no grasp of {object} is reachable without collision ({why})")))?;
        let path = self.plan_to(Allow::default(), &q_above)?;
        self.run.ctrl[self.rig.grip_act] = self.rig.opening_for(grasp.width).0;
        self.run.follow(self.rig, &path, 1.0)?;
        self.sync_scratch();
        let down = self.line(&q_above, grasp.above(APPROACH).pos, &grasp.at, 4)?;
        self.run.follow(self.rig, &down, 0.3)?;
        self.run.grip(self.rig, self.rig.grip_closed, 0.7)?;
        let z0 = self.run.data.xpos()[body][2];
        self.sync_scratch();
        let here = self.run.arm_target(self.rig);
        let (tp, tr) = self.rig.tcp_pose(&self.scratch);
        let up = Target { pos: add(tp, [0.0, 0.0, LIFT]), rot: tr };
        let lift = self.line(&here, tp, &up, 4)?;
        self.run.follow(self.rig, &lift, 0.3)?;
        let rise = self.run.data.xpos()[body][2] - z0;
        if rise < 0.5 * LIFT {
            return Err(ExpertError::Failed(format!(
                "{object} slipped from the gripper (lifted {:.0} mm)",
                rise * 1000.0
            )));
        }
        let held = Held::grasped(self.rig, &self.run.data, body, qadr);
        self.run.holding = Some((held, self.rig.tcp));
        Ok(held)
    }

    /// Where the thing's bottom centre may go for the goal, best first.
    fn destinations(&mut self, g: &Predicate, object: &str, body: usize) -> Result<Vec<V3>, ExpertError> {
        let snap = self.snapshot();
        let me = snap.bodies.get(object).ok_or_else(|| ExpertError::Scene(format!("no {object}")))?;
        let half = [0.5 * (me.bounds.max[0] - me.bounds.min[0]), 0.5 * (me.bounds.max[1] - me.bounds.min[1])];
        let base = self.run.data.xpos()[self.rig.base_body];
        let reach = Some((base, 0.85 * self.reach));
        let prefer = [base[0] + 0.45 * self.reach * (me.bounds.center()[0] - base[0]).signum().max(0.0), base[1]];
        let prefer = [0.5 * (prefer[0] + me.bounds.center()[0]), 0.5 * (prefer[1] + me.bounds.center()[1])];
        let _ = body;
        let body_of =
            |n: &str| snap.bodies.get(n).ok_or_else(|| ExpertError::Scene(format!("no body '{n}' in the scene")));
        let out: Vec<V3> = match g {
            Predicate::Inside { target, .. } => {
                let mut v = Vec::new();
                for t in target {
                    let b = body_of(t)?;
                    let c = b.bounds.center();
                    // The middle, then spots around it, clear of what is already inside.
                    let (hx, hy) =
                        (0.5 * (b.bounds.max[0] - b.bounds.min[0]), 0.5 * (b.bounds.max[1] - b.bounds.min[1]));
                    let (ox, oy) = ((hx - half[0] - 0.01).max(0.0), (hy - half[1] - 0.01).max(0.0));
                    let before = v.len();
                    let spots = [(0.0, 0.0), (ox, 0.0), (-ox, 0.0), (0.0, oy), (0.0, -oy)];
                    for (dx, dy) in spots {
                        let p = [c[0] + dx, c[1] + dy];
                        // Things already in it (their centre over it, their bottom in it).
                        let taken = snap.bodies.iter().any(|(n, o)| {
                            n != object
                                && n != t
                                && sw_task::judge::within(o, b)
                                && (o.bounds.center()[0] - p[0]).abs()
                                    < 0.5 * (o.bounds.max[0] - o.bounds.min[0]) + half[0]
                                && (o.bounds.center()[1] - p[1]).abs()
                                    < 0.5 * (o.bounds.max[1] - o.bounds.min[1]) + half[1]
                        });
                        if !taken {
                            v.push([p[0], p[1], b.bounds.max[2] + DROP_GAP]);
                        }
                    }
                    // Full: drop it on what is there (it settles beside it or on it).
                    if v.len() == before {
                        v.extend(spots.iter().map(|(dx, dy)| [c[0] + dx, c[1] + dy, b.bounds.max[2] + DROP_GAP]));
                    }
                }
                v.sort_by(|a, b| {
                    (a[0] - base[0]).hypot(a[1] - base[1]).total_cmp(&(b[0] - base[0]).hypot(b[1] - base[1]))
                });
                v
            }
            Predicate::StackedOn { target, .. } => {
                let b = body_of(target)?;
                let c = b.bounds.center();
                vec![[c[0], c[1], b.bounds.max[2] + RELEASE_GAP]]
            }
            Predicate::On { target, .. } => {
                let mut rects = Vec::new();
                for t in target {
                    let b = body_of(t)?;
                    if b.surfaces.is_empty() {
                        rects.push((
                            b.bounds.max[2],
                            [b.bounds.min[0], b.bounds.min[1], b.bounds.max[0], b.bounds.max[1]],
                        ));
                    }
                    rects.extend(b.surfaces.iter().map(|s| (s.z, s.rect)));
                }
                let mut ignore: Vec<&str> = vec![object];
                ignore.extend(target.iter().map(String::as_str));
                free_spots(&snap, &rects, half, &ignore, prefer, reach)
                    .into_iter()
                    .map(|p| [p[0], p[1], p[2] + RELEASE_GAP])
                    .collect()
            }
            Predicate::Near { target, within, .. } => {
                let b = body_of(target)?;
                let z = support_under(&snap, target);
                let m = (within * 0.5).min(0.04);
                let r = [
                    b.bounds.min[0] - m - 2.0 * half[0],
                    b.bounds.min[1] - m - 2.0 * half[1],
                    b.bounds.max[0] + m + 2.0 * half[0],
                    b.bounds.max[1] + m + 2.0 * half[1],
                ];
                let ignore = [object];
                free_spots(&snap, &[(z, r)], half, &ignore, [b.bounds.center()[0], b.bounds.center()[1]], reach)
                    .into_iter()
                    .filter(|p| {
                        let mine = sw_task::Bounds {
                            min: [p[0] - half[0], p[1] - half[1], 0.0],
                            max: [p[0] + half[0], p[1] + half[1], 0.0],
                        };
                        sw_task::judge::gap(&mine, &b.bounds) <= within - 0.01
                    })
                    .map(|p| [p[0], p[1], p[2] + RELEASE_GAP])
                    .collect()
            }
            Predicate::InRegion { min, max, .. } => {
                let z = support_under(&snap, object);
                let rect = [min[0], min[1], max[0], max[1]];
                let ignore = [object];
                let c = [0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1])];
                let inner: Vec<V3> = free_spots(
                    &snap,
                    &[(z, [rect[0] - half[0], rect[1] - half[1], rect[2] + half[0], rect[3] + half[1]])],
                    half,
                    &ignore,
                    c,
                    reach,
                )
                .into_iter()
                .filter(|p| (min[0]..=max[0]).contains(&p[0]) && (min[1]..=max[1]).contains(&p[1]))
                .collect();
                inner.into_iter().map(|p| [p[0], p[1], p[2] + RELEASE_GAP]).collect()
            }
            _ => Vec::new(),
        };
        if out.is_empty() {
            return Err(ExpertError::Place(format!(
                "no free place for {object} where the goal ({}) wants it",
                g.name()
            )));
        }
        Ok(out)
    }

    /// Carries the held thing so that its bottom centre comes to one of `dests`, lets go
    /// and retreats.
    fn place(&mut self, object: &str, held: Held, dests: &[V3]) -> Result<(), ExpertError> {
        // Where it sits in the hand now (a ball may have turned between the pads).
        let held = Held::grasped(self.rig, &self.run.data, held.body, held.qpos);
        let snap = self.snapshot();
        let me = snap.bodies.get(object).ok_or_else(|| ExpertError::Scene(format!("no {object}")))?;
        let bottom = [me.bounds.center()[0], me.bounds.center()[1], me.bounds.min[2]];
        let (tp, tr) = self.rig.tcp_pose(&self.run.data);
        let now = self.run.arm_target(self.rig);
        self.sync_scratch();
        let mut chosen = None;
        // The thing may be turned about the vertical on the way (a quarter or half turn):
        // the wrist often cannot keep the grasp's heading at the far place.
        let hand = sub(tp, bottom);
        let mut why = Rejections::default();
        let allow = Allow { held: Some(held), touch: None };
        'search: for d in dests.iter().take(12) {
            for turn in TURNS {
                let rz = rot_z(turn);
                let rot = crate::math::mat_mul(&rz, &tr);
                let release = Target { pos: add(*d, crate::math::mat_vec(&rz, hand)), rot };
                let above = Target { pos: add(release.pos, [0.0, 0.0, APPROACH]), rot };
                why.tried += 1;
                // The nearest posture above the place, or another when it collides.
                match self.posture(&now, &above, allow) {
                    Posture::Free(q_above) => {
                        if self.ik(&q_above, &release).is_some() {
                            chosen = Some((above, release, q_above));
                            break 'search;
                        }
                        why.ik_at += 1;
                    }
                    Posture::NoIk => why.ik_above += 1,
                    Posture::Hit(pair) => why.hit(self.model, pair),
                }
            }
        }
        self.sync_scratch();
        let (above, release, q_above) = chosen.ok_or_else(|| {
            ExpertError::Ik(format!("no place for {object} is reachable with it in the hand ({why})"))
        })?;
        let path = self.plan_to(Allow { held: Some(held), touch: None }, &q_above)?;
        // The run fails the frame the thing leaves the hand (Runner::holding).
        self.run.follow(self.rig, &path, carry_speed(&held))?;
        self.sync_scratch();
        let down = self.line(&q_above, above.pos, &release, 4)?;
        self.run.follow(self.rig, &down, 0.3)?;
        self.run.holding = None;
        self.run.grip(self.rig, self.rig.grip_open, 0.5)?;
        self.sync_scratch();
        let here = self.run.arm_target(self.rig);
        let (tp, tr) = self.rig.tcp_pose(&self.scratch);
        let up = Target { pos: add(tp, [0.0, 0.0, APPROACH]), rot: tr };
        let retreat = self.line(&here, tp, &up, 3)?;
        self.run.follow(self.rig, &retreat, 0.5)?;
        let _ = local_box;
        Ok(())
    }
}

/// The speed a held thing is carried at. Two pads pinch it along a short vertical line,
/// and the hand's accelerations act on its centre of mass: a thing held far from its
/// centre (a bottle by its neck, 8 – 9 cm above it) is turned about the closing axis by
/// a torque of mass × acceleration × lever, which the pads' friction over that short line
/// cannot hold, so it pivots and drops out while carried. The carry's accelerations
/// scale with the square of the speed, so the speed falls as 1/lever past
/// [`CARRY_LEVER`] (the torque then falls as 1/lever).
pub(crate) fn carry_speed(held: &Held) -> f64 {
    let c = held.rel_com;
    let lever = (c[0] * c[0] + c[2] * c[2]).sqrt();
    (CARRY_SPEED * (CARRY_LEVER / lever.max(1e-9)).min(1.0)).max(CARRY_SPEED_MIN)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::M3;

    fn held_at(rel_com: V3) -> Held {
        let eye: M3 = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
        Held { body: 1, qpos: 0, rel_pos: rel_com, rel_rot: eye, rel_com }
    }

    #[test]
    fn carry_slows_with_the_lever_about_the_closing_axis() {
        // A cube pinched through its centre: full carry speed.
        assert_eq!(carry_speed(&held_at([0.0, 0.0, 0.008])), CARRY_SPEED);
        // A tall thing held 50 mm above its centre: slower, by the lever.
        let v = carry_speed(&held_at([0.03, 0.0, 0.04]));
        assert!((v - CARRY_SPEED * CARRY_LEVER / 0.05).abs() < 1e-9, "{v}");
        // A bottle by its neck, 85 mm above its centre: at the floor.
        assert_eq!(carry_speed(&held_at([0.0, 0.0, 0.085])), CARRY_SPEED_MIN);
        // An offset along the closing axis (y) is no lever about it.
        assert_eq!(carry_speed(&held_at([0.0, 0.2, 0.0])), CARRY_SPEED);
        // Never slower than the floor.
        assert_eq!(carry_speed(&held_at([0.5, 0.0, 0.5])), CARRY_SPEED_MIN);
    }
}
