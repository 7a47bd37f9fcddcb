//! Running an episode: the state advances only through the robot's actuators, one control
//! vector per frame held for `substeps` physics steps, and every frame's observation and
//! action is recorded — so that the same controls replay the episode in plain MuJoCo.

use mujoco_rs::prelude::*;

use crate::ExpertError;
use crate::rig::Rig;

/// Joint speed limit of planned motion, rad/s.
const V_MAX: f64 = 1.2;
/// Shortest timed segment, s.
const MIN_SEGMENT: f64 = 0.3;
/// How long a move may wait at its end for the servos to arrive, s.
const SETTLE_MAX: f64 = 1.0;
/// An arm has arrived when every joint is this close to its target, rad.
const ARRIVED: f64 = 0.01;
/// How far a held thing may move from where the grasp put it in the hand before it
/// counts as lost when the fingers no longer touch it, m.
const HELD_DRIFT: f64 = 0.03;
/// How far it may move while the fingers still hold it (turned between the pads), m.
const HELD_TURNED: f64 = 0.08;

/// What is recorded per frame.
#[derive(Debug, Clone, Default)]
pub struct Recording {
    /// The actuator controls applied for the frame (the dataset's `action`).
    pub actions: Vec<Vec<f64>>,
    /// Arm joints then finger joint positions at the start of the frame.
    pub states: Vec<Vec<f64>>,
    /// Position and orientation (w, x, y, z) of each tracked thing at the start of the frame.
    pub env: Vec<Vec<f64>>,
    /// The whole `qpos` at the start of the frame (to render it again).
    pub qpos: Vec<Vec<f64>>,
}

/// The simulation an episode runs in.
#[derive(Debug)]
pub(crate) struct Runner<'m> {
    pub data: MjData<&'m MjModel>,
    pub substeps: usize,
    pub fps: u32,
    pub ctrl: Vec<f64>,
    pub rec: Recording,
    /// Bodies whose pose is recorded in `env`.
    pub tracked: Vec<usize>,
    pub max_frames: usize,
    /// The thing in the hand, watched every frame: the run fails the frame it leaves the
    /// hand, naming what it touches then.
    pub holding: Option<(crate::motion::Held, usize)>,
}

impl<'m> Runner<'m> {
    pub fn new(
        model: &'m MjModel,
        fps: u32,
        substeps: usize,
        tracked: Vec<usize>,
        max_seconds: f64,
    ) -> Result<Self, ExpertError> {
        let mut data = model.make_data();
        let key = model
            .name_to_id(MjtObjBase::mjOBJ_KEY, "home")
            .ok_or_else(|| ExpertError::Scene("the scene has no 'home' keyframe".into()))?;
        data.reset_keyframe(key).map_err(|e| ExpertError::Scene(e.to_string()))?;
        data.forward();
        let ctrl = data.ctrl().to_vec();
        Ok(Self {
            data,
            substeps,
            fps,
            ctrl,
            rec: Recording::default(),
            tracked,
            max_frames: (max_seconds * f64::from(fps)).ceil() as usize,
            holding: None,
        })
    }

    /// Records the observation, applies `self.ctrl` for one frame.
    pub fn frame(&mut self, rig: &Rig) -> Result<(), ExpertError> {
        if self.rec.actions.len() >= self.max_frames {
            return Err(ExpertError::Failed(format!(
                "the episode ran past its {:.0} s limit",
                self.max_frames as f64 / f64::from(self.fps)
            )));
        }
        let qpos = self.data.qpos().to_vec();
        let mut state: Vec<f64> = rig.arm.iter().map(|j| qpos[j.qpos]).collect();
        state.extend(rig.finger_qpos.first().map(|&a| qpos[a]));
        let mut env = Vec::with_capacity(7 * self.tracked.len());
        for &b in &self.tracked {
            env.extend_from_slice(&self.data.xpos()[b]);
            env.extend_from_slice(&self.data.xquat()[b]);
        }
        self.rec.states.push(state);
        self.rec.env.push(env);
        self.rec.qpos.push(qpos);
        // The dataset stores controls as float32: the run applies exactly those values, so
        // that a replay of the stored actions is the same motion.
        for c in &mut self.ctrl {
            *c = f64::from(*c as f32);
        }
        self.rec.actions.push(self.ctrl.clone());
        self.data.ctrl_mut().copy_from_slice(&self.ctrl);
        for _ in 0..self.substeps {
            self.data.step();
        }
        if self.data.qpos().iter().any(|v| !v.is_finite()) {
            return Err(ExpertError::Failed("the simulation became unstable".into()));
        }
        if let Some((held, tcp)) = self.holding {
            // Out of the pads, or turned far in them (a tall thing may pivot a little
            // between the pads and still be carried).
            let drift = held.drift(&self.data, tcp);
            if drift > HELD_DRIFT && (drift > HELD_TURNED || self.touching(rig, held.body).1.is_empty()) {
                return Err(ExpertError::Failed(self.lost(rig, held.body, drift)));
            }
        }
        Ok(())
    }

    /// What `body` touches now: (other things, by their top-level body's name; the
    /// robot's bodies, the hand's own left out).
    fn touching(&self, rig: &Rig, body: usize) -> (Vec<String>, Vec<usize>) {
        let model = self.data.model();
        let name = |b: usize| model.id_to_name(MjtObjBase::mjOBJ_BODY, b).unwrap_or("?").to_string();
        let root = model.body_rootid();
        let (mut things, mut hand) = (Vec::new(), Vec::new());
        let ncon = self.data.ncon().max(0) as usize;
        for c in self.data.contact().iter().take(ncon) {
            let b1 = model.geom_bodyid()[c.geom1 as usize] as usize;
            let b2 = model.geom_bodyid()[c.geom2 as usize] as usize;
            let other = if b1 == body {
                b2
            } else if b2 == body {
                b1
            } else {
                continue;
            };
            if rig.hand_body[other] {
                hand.push(other);
                continue;
            }
            let n = if rig.robot_body[other] { name(other) } else { name(root[other] as usize) };
            if !things.contains(&n) {
                things.push(n);
            }
        }
        (things, hand)
    }

    /// Why the held `body` left the hand: what it touches now.
    fn lost(&self, rig: &Rig, body: usize, drift: f64) -> String {
        let model = self.data.model();
        let name = |b: usize| model.id_to_name(MjtObjBase::mjOBJ_BODY, b).unwrap_or("?").to_string();
        let (touching, hand) = self.touching(rig, body);
        let touching: Vec<String> =
            touching.into_iter().chain((!hand.is_empty()).then(|| "the fingers".to_string())).collect();
        let frame = self.rec.actions.len();
        // Each finger's travel from closed, and the gripper's control: closed on nothing, or
        // opened under it.
        let travel: Vec<String> =
            rig.finger_qpos.iter().map(|&a| format!("{:.0}", 1000.0 * self.data.qpos()[a])).collect();
        format!(
            "{} left the hand while carried ({:.0} mm off at {:.1} s{}; fingers at {} mm, control {:.3})",
            name(body),
            drift * 1000.0,
            frame as f64 / f64::from(self.fps),
            if touching.is_empty() { String::new() } else { format!(", touching {}", touching.join(", ")) },
            travel.join("/"),
            self.ctrl[rig.grip_act]
        )
    }

    fn set_arm_ctrl(&mut self, rig: &Rig, q: &[f64]) {
        for (j, v) in rig.arm.iter().zip(q) {
            self.ctrl[j.act] = *v;
        }
    }

    pub fn arm_target(&self, rig: &Rig) -> Vec<f64> {
        rig.arm.iter().map(|j| self.ctrl[j.act]).collect()
    }

    /// Follows a joint path, each segment timed by the joint speed limit with a
    /// minimum-jerk profile, then waits (up to a second) for the servos to arrive.
    pub fn follow(&mut self, rig: &Rig, path: &[Vec<f64>], speed: f64) -> Result<(), ExpertError> {
        for w in path.windows(2) {
            let (a, b) = (&w[0], &w[1]);
            let span = a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
            let t = (span / (V_MAX * speed)).max(MIN_SEGMENT);
            let frames = (t * f64::from(self.fps)).ceil() as usize;
            for k in 1..=frames {
                let s = k as f64 / frames as f64;
                let s = s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
                let q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + s * (y - x)).collect();
                self.set_arm_ctrl(rig, &q);
                self.frame(rig)?;
            }
        }
        self.arrive(rig)
    }

    /// Holds the current targets until the arm is there (at most [`SETTLE_MAX`]).
    pub fn arrive(&mut self, rig: &Rig) -> Result<(), ExpertError> {
        let target = self.arm_target(rig);
        let max = (SETTLE_MAX * f64::from(self.fps)) as usize;
        for _ in 0..max {
            let q = rig.arm_q(&self.data);
            if q.iter().zip(&target).all(|(a, b)| (a - b).abs() < ARRIVED) {
                break;
            }
            self.frame(rig)?;
        }
        Ok(())
    }

    /// Sets the gripper's control and holds everything for `seconds`.
    pub fn grip(&mut self, rig: &Rig, value: f64, seconds: f64) -> Result<(), ExpertError> {
        self.ctrl[rig.grip_act] = value;
        let frames = (seconds * f64::from(self.fps)).ceil() as usize;
        for _ in 0..frames {
            self.frame(rig)?;
        }
        Ok(())
    }

    /// Holds every control for `seconds`.
    pub fn hold(&mut self, rig: &Rig, seconds: f64) -> Result<(), ExpertError> {
        let frames = (seconds * f64::from(self.fps)).ceil() as usize;
        for _ in 0..frames {
            self.frame(rig)?;
        }
        Ok(())
    }
}
