//! The robot and the things of a compiled scene, as the expert drives them: the arm's
//! joints on the chain to the tool centre point and their position servos, the gripper's
//! actuator, which bodies are the robot's and which are the fingers', and the state as a
//! task judges it ([`Rig::snapshot`]).

use std::collections::BTreeMap;

use mujoco_rs::prelude::*;
use mujoco_rs::wrappers::mj_model::traits::ModelType;
use sw_task::{BodyState, Bounds, Snapshot, Surface};

use crate::ExpertError;
use crate::math::{M3, V3};

/// Group of the collision geoms the scene writer emits (`sw_collision`).
pub(crate) const COLLISION_GROUP: i32 = 3;
/// Group of the support-surface sites (`sw_surface`).
const SURFACE_GROUP: i32 = 5;

/// The compiled scene with the robot that does the task resolved.
#[derive(Debug)]
pub(crate) struct Rig {
    pub robot: String,
    /// Arm joints from the base to the tool: qpos address, dof address, actuator, range.
    pub arm: Vec<ArmJoint>,
    pub grip_act: usize,
    pub grip_open: f64,
    pub grip_closed: f64,
    pub max_opening: f64,
    pub finger_depth: f64,
    /// qpos addresses of the finger joints (the gripper actuator's joint and those coupled).
    pub finger_qpos: Vec<usize>,
    pub finger_names: Vec<String>,
    pub tcp: usize,
    /// Per body: belongs to the robot.
    pub robot_body: Vec<bool>,
    /// Per body: the hand (the tcp's body and everything below it).
    pub hand_body: Vec<bool>,
    /// Object name → (body id, qpos address of its free joint, if any).
    pub objects: BTreeMap<String, (usize, Option<usize>)>,
    /// The robot's base body (for its position).
    pub base_body: usize,
    pub wrist_camera: Option<usize>,
}

#[derive(Debug, Clone)]
pub(crate) struct ArmJoint {
    pub name: String,
    pub qpos: usize,
    pub dof: usize,
    pub act: usize,
    pub lo: f64,
    pub hi: f64,
}

fn name(model: &MjModel, kind: MjtObjBase, id: usize) -> String {
    model.id_to_name(kind, id).unwrap_or("").to_string()
}

impl Rig {
    /// Resolves robot `robot` (an instance name) of model `model_name` in `model`.
    pub fn new(model: &MjModel, robot: &str, model_name: &str) -> Result<Self, ExpertError> {
        let def = sw_robots::find(model_name)
            .ok_or_else(|| ExpertError::Robot(format!("robot model '{model_name}' is not registered")))?;
        let g = def
            .gripper
            .ok_or_else(|| ExpertError::Robot(format!("{robot} ({model_name}) has no gripper the expert can drive")))?;
        let full = |n: &str| format!("{robot}_{n}");
        let tcp = model
            .name_to_id(MjtObjBase::mjOBJ_SITE, &full(g.tcp_site))
            .ok_or_else(|| ExpertError::Robot(format!("{robot} has no site '{}'", full(g.tcp_site))))?;
        let grip_act = model
            .name_to_id(MjtObjBase::mjOBJ_ACTUATOR, &full(g.actuator))
            .ok_or_else(|| ExpertError::Robot(format!("{robot} has no actuator '{}'", full(g.actuator))))?;
        let nbody = model.ffi().nbody as usize;
        let parent = model.body_parentid();
        let prefix = format!("{robot}_");
        let robot_body: Vec<bool> =
            (0..nbody).map(|b| b > 0 && name(model, MjtObjBase::mjOBJ_BODY, b).starts_with(&prefix)).collect();
        let tcp_body = model.site_bodyid()[tcp] as usize;
        // A body is the hand's when the tool's body is on its way to the world.
        let hand_body: Vec<bool> = (0..nbody)
            .map(|b| {
                let mut cur = b;
                while cur > 0 {
                    if cur == tcp_body {
                        return true;
                    }
                    cur = parent[cur] as usize;
                }
                false
            })
            .collect();
        // The chain from the tool's body to the robot's root.
        let mut chain_joints: Vec<usize> = Vec::new();
        let mut cur = tcp_body;
        let mut base_body = tcp_body;
        while cur > 0 && robot_body[cur] {
            base_body = cur;
            let adr = model.body_jntadr()[cur];
            let num = model.body_jntnum()[cur];
            for j in (0..num).rev() {
                let j = (adr + j) as usize;
                if matches!(model.jnt_type()[j], MjtJoint::mjJNT_HINGE | MjtJoint::mjJNT_SLIDE) {
                    chain_joints.push(j);
                }
            }
            cur = parent[cur] as usize;
        }
        chain_joints.reverse();
        let nu = model.ffi().nu as usize;
        let servo_of = |j: usize| {
            (0..nu).find(|&a| {
                model.actuator_trntype()[a] == MjtTrn::mjTRN_JOINT && model.actuator_trnid()[a][0] as usize == j
            })
        };
        let mut arm = Vec::new();
        for j in chain_joints {
            let jname = name(model, MjtObjBase::mjOBJ_JOINT, j);
            let act = servo_of(j)
                .ok_or_else(|| ExpertError::Robot(format!("arm joint {jname} has no servo the expert can drive")))?;
            let r = model.jnt_range()[j];
            let limited = r[1] > r[0];
            arm.push(ArmJoint {
                name: jname,
                qpos: model.jnt_qposadr()[j] as usize,
                dof: model.jnt_dofadr()[j] as usize,
                act,
                lo: if limited { r[0] } else { -std::f64::consts::TAU },
                hi: if limited { r[1] } else { std::f64::consts::TAU },
            });
        }
        if arm.len() < 6 {
            return Err(ExpertError::Robot(format!(
                "{robot} has {} driven joints between its base and its tool; the expert needs 6 or more",
                arm.len()
            )));
        }
        // Fingers: the gripper actuator's joint and every joint of the hand's bodies.
        let mut finger_qpos = Vec::new();
        let mut finger_names = Vec::new();
        for j in 0..model.ffi().njnt as usize {
            let b = model.jnt_bodyid()[j] as usize;
            if hand_body[b] && b != tcp_body && model.jnt_type()[j] == MjtJoint::mjJNT_SLIDE {
                finger_qpos.push(model.jnt_qposadr()[j] as usize);
                finger_names.push(name(model, MjtObjBase::mjOBJ_JOINT, j));
            }
        }
        let mut objects = BTreeMap::new();
        for b in 1..nbody {
            if parent[b] != 0 || robot_body[b] {
                continue;
            }
            let n = name(model, MjtObjBase::mjOBJ_BODY, b);
            if n.is_empty() {
                continue;
            }
            let adr = model.body_jntadr()[b];
            let free = (adr >= 0 && model.jnt_type()[adr as usize] == MjtJoint::mjJNT_FREE)
                .then(|| model.jnt_qposadr()[adr as usize] as usize);
            objects.insert(n, (b, free));
        }
        let wrist_camera = model.name_to_id(MjtObjBase::mjOBJ_CAMERA, &full(g.wrist_camera));
        Ok(Rig {
            robot: robot.to_string(),
            arm,
            grip_act,
            grip_open: g.open,
            grip_closed: g.closed,
            max_opening: g.max_opening,
            finger_depth: g.finger_depth,
            finger_qpos,
            finger_names,
            tcp,
            robot_body,
            hand_body,
            objects,
            base_body,
            wrist_camera,
        })
    }

    /// Resolves mobile base `robot` (an instance name) to drive it: its root body (a free
    /// body on the floor) and the joints of its wheels driven by velocity servos, as the
    /// rig's driven joints (the episode's state). It has no arm or gripper here: an arm it
    /// carries holds its pose.
    pub fn base(model: &MjModel, robot: &str) -> Result<Self, ExpertError> {
        let nbody = model.ffi().nbody as usize;
        let parent = model.body_parentid();
        let prefix = format!("{robot}_");
        let robot_body: Vec<bool> =
            (0..nbody).map(|b| b > 0 && name(model, MjtObjBase::mjOBJ_BODY, b).starts_with(&prefix)).collect();
        let free_root = (1..nbody).find(|&b| {
            let adr = model.body_jntadr()[b];
            robot_body[b] && parent[b] == 0 && adr >= 0 && model.jnt_type()[adr as usize] == MjtJoint::mjJNT_FREE
        });
        let base_body = free_root
            .ok_or_else(|| ExpertError::Robot(format!("{robot} is not a free body on the floor; it cannot drive")))?;
        let mut arm = Vec::new();
        for a in 0..model.ffi().nu as usize {
            if model.actuator_trntype()[a] != MjtTrn::mjTRN_JOINT {
                continue;
            }
            let j = model.actuator_trnid()[a][0] as usize;
            let bias = model.actuator_biasprm()[a];
            // A velocity servo: force = kv (ctrl - qvel).
            let velocity = model.actuator_biastype()[a] == MjtBias::mjBIAS_AFFINE && bias[1] == 0.0 && bias[2] < 0.0;
            if !velocity || model.jnt_type()[j] != MjtJoint::mjJNT_HINGE || !robot_body[model.jnt_bodyid()[j] as usize]
            {
                continue;
            }
            let r = model.actuator_ctrlrange()[a];
            arm.push(ArmJoint {
                name: name(model, MjtObjBase::mjOBJ_JOINT, j),
                qpos: model.jnt_qposadr()[j] as usize,
                dof: model.jnt_dofadr()[j] as usize,
                act: a,
                lo: r[0],
                hi: r[1],
            });
        }
        if arm.len() < 2 {
            return Err(ExpertError::Robot(format!(
                "{robot} has no wheels driven by velocity servos; the expert drives wheeled bases"
            )));
        }
        let mut objects = BTreeMap::new();
        for b in 1..nbody {
            let n = name(model, MjtObjBase::mjOBJ_BODY, b);
            if parent[b] != 0 || robot_body[b] || n.is_empty() {
                continue;
            }
            let adr = model.body_jntadr()[b];
            let free = (adr >= 0 && model.jnt_type()[adr as usize] == MjtJoint::mjJNT_FREE)
                .then(|| model.jnt_qposadr()[adr as usize] as usize);
            objects.insert(n, (b, free));
        }
        let first = arm[0].act;
        Ok(Rig {
            robot: robot.to_string(),
            arm,
            grip_act: first,
            grip_open: 0.0,
            grip_closed: 0.0,
            max_opening: 0.0,
            finger_depth: 0.0,
            finger_qpos: Vec::new(),
            finger_names: Vec::new(),
            tcp: 0,
            robot_body,
            hand_body: vec![false; nbody],
            objects,
            base_body,
            wrist_camera: None,
        })
    }

    pub fn n(&self) -> usize {
        self.arm.len()
    }

    pub fn arm_q<M: ModelType>(&self, data: &MjData<M>) -> Vec<f64> {
        self.arm.iter().map(|j| data.qpos()[j.qpos]).collect()
    }

    pub fn set_arm_q<M: ModelType>(&self, data: &mut MjData<M>, q: &[f64]) {
        for (j, v) in self.arm.iter().zip(q) {
            data.qpos_mut()[j.qpos] = *v;
        }
    }

    pub fn tcp_pose<M: ModelType>(&self, data: &MjData<M>) -> (V3, M3) {
        (data.site_xpos()[self.tcp], data.site_xmat()[self.tcp])
    }

    /// The gripper control (and each finger's travel) that opens the pads to `width` plus
    /// a clearance either side: a grasp opens no wider than it must, to fit between things.
    pub fn opening_for(&self, width: f64) -> (f64, f64) {
        let w = (width + 2.0 * crate::grasp::OPENING_SLACK).min(self.max_opening);
        let f = w / self.max_opening;
        // The control is the finger travel, 0 with the pads touching (`Gripper::open`);
        // `grip_closed` lies past that, to squeeze.
        (f * self.grip_open, 0.5 * w)
    }

    /// Sets the fingers' joints to `travel` each (for collision checks of a grasp).
    pub fn set_fingers<M: ModelType>(&self, data: &mut MjData<M>, travel: f64) {
        for &a in &self.finger_qpos {
            data.qpos_mut()[a] = travel;
        }
    }

    pub fn clamp(&self, q: &mut [f64]) {
        for (v, j) in q.iter_mut().zip(&self.arm) {
            *v = v.clamp(j.lo, j.hi);
        }
    }

    /// The state as a task judges it: every top-level body's collision box (its whole
    /// tree) and support surfaces, robot bases, joints of articulated objects.
    pub fn snapshot<M: ModelType>(&self, model: &MjModel, data: &MjData<M>) -> Snapshot {
        snapshot(model, data, &self.robot, self.base_body)
    }
}

/// World boxes of the top-level bodies' collision geometry and their surfaces.
pub(crate) fn snapshot<M: ModelType>(model: &MjModel, data: &MjData<M>, robot: &str, base_body: usize) -> Snapshot {
    let mut s = Snapshot::default();
    let nbody = model.ffi().nbody as usize;
    let root = model.body_rootid();
    let mut bounds: BTreeMap<usize, Bounds> = BTreeMap::new();
    for g in 0..model.ffi().ngeom as usize {
        let b = model.geom_bodyid()[g] as usize;
        if b == 0 || model.geom_group()[g] != COLLISION_GROUP {
            continue;
        }
        let r = root[b] as usize;
        let gb = geom_bounds(model, data, g);
        bounds
            .entry(r)
            .and_modify(|x| {
                for i in 0..3 {
                    x.min[i] = x.min[i].min(gb.min[i]);
                    x.max[i] = x.max[i].max(gb.max[i]);
                }
            })
            .or_insert(gb);
    }
    let mut surfaces: BTreeMap<usize, Vec<Surface>> = BTreeMap::new();
    for st in 0..model.ffi().nsite as usize {
        if model.site_group()[st] != SURFACE_GROUP {
            continue;
        }
        let b = model.site_bodyid()[st] as usize;
        let p = data.site_xpos()[st];
        let m = data.site_xmat()[st];
        let h = model.site_size()[st];
        let hx = (m[0] * h[0]).abs() + (m[1] * h[1]).abs();
        let hy = (m[3] * h[0]).abs() + (m[4] * h[1]).abs();
        surfaces
            .entry(root[b] as usize)
            .or_default()
            .push(Surface { z: p[2], rect: [p[0] - hx, p[1] - hy, p[0] + hx, p[1] + hy] });
    }
    for (b, r) in root.iter().enumerate().take(nbody).skip(1) {
        if *r as usize != b {
            continue;
        }
        let n = name(model, MjtObjBase::mjOBJ_BODY, b);
        if n.is_empty() {
            continue;
        }
        if let Some(bd) = bounds.get(&b) {
            s.bodies.insert(n, BodyState { bounds: *bd, surfaces: surfaces.remove(&b).unwrap_or_default() });
        }
    }
    if base_body > 0 {
        s.robots.insert(robot.to_string(), data.xpos()[base_body]);
    }
    for j in 0..model.ffi().njnt as usize {
        if matches!(model.jnt_type()[j], MjtJoint::mjJNT_HINGE | MjtJoint::mjJNT_SLIDE) {
            let n = name(model, MjtObjBase::mjOBJ_JOINT, j);
            let r = model.jnt_range()[j];
            s.joints.insert(n, (data.qpos()[model.jnt_qposadr()[j] as usize], r[0], r[1]));
        }
    }
    s
}

/// The world box of one geom (its local box turned by its world rotation).
pub(crate) fn geom_bounds<M: ModelType>(model: &MjModel, data: &MjData<M>, g: usize) -> Bounds {
    let a = model.geom_aabb()[g];
    let p = data.geom_xpos()[g];
    let m = data.geom_xmat()[g];
    let c = crate::math::add(p, crate::math::mat_vec(&m, [a[0], a[1], a[2]]));
    let mut h = [0.0; 3];
    for (i, hi) in h.iter_mut().enumerate() {
        *hi = (m[3 * i] * a[3]).abs() + (m[3 * i + 1] * a[4]).abs() + (m[3 * i + 2] * a[5]).abs();
    }
    Bounds { min: [c[0] - h[0], c[1] - h[1], c[2] - h[2]], max: [c[0] + h[0], c[1] + h[1], c[2] + h[2]] }
}
