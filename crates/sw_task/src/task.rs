//! `task.json`: what a robot is asked to do in a package, as predicates over named bodies.

use serde::{Deserialize, Serialize};

/// The version of `task.json`.
pub const TASK_VERSION: u32 = 1;

/// A task: the goal is the conjunction of `goals`, judged on the MuJoCo state at the end
/// of an episode (see [`crate::judge`]). The initial state must not already satisfy it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Task {
    pub schema_version: u32,
    /// The instruction as a person would say it; a dataset's task string.
    pub instruction: String,
    /// Where the task came from: `prompt` (a clause of the scene's prompt) or `flag`
    /// (`--task`).
    pub source: String,
    /// The family the task belongs to (benchmarks count success per family).
    pub family: Family,
    /// The robot instance that does it (an arm with a gripper, or a mobile base).
    pub robot: String,
    pub goals: Vec<Predicate>,
    /// How to drive the robot's gripper (names as in scene.xml), when it has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gripper: Option<GripperInterface>,
    /// How words were bound to bodies ("'the cubes' are cube_1, cube_2").
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
}

impl Task {
    /// Every body a goal moves (the subjects), in goal order, without repeats.
    pub fn moved_objects(&self) -> Vec<&str> {
        let mut out: Vec<&str> = Vec::new();
        for g in &self.goals {
            if let Some(o) = g.subject()
                && !out.contains(&o)
            {
                out.push(o);
            }
        }
        out
    }
}

/// The robot's gripper as a controller drives it: scene names, prefixed with the robot's.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GripperInterface {
    /// The site between the finger pads (z: approach direction; y: the fingers close along it).
    pub tcp_site: String,
    pub actuator: String,
    /// The actuator's controls that open and close the fingers.
    pub open: f64,
    pub closed: f64,
    /// The camera beside the tool.
    pub wrist_camera: String,
}

/// Task families, as the benchmarks group them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// Put things on or in something (one or many objects).
    PickPlace,
    /// Put one thing on another movable thing.
    Stack,
    /// Move a thing into a region of its surface or near another.
    Push,
    /// Lift a thing to a pose.
    Lift,
    /// Open or close a drawer or door.
    Articulated,
    /// Drive a mobile base to something.
    Navigate,
}

impl Family {
    pub fn name(self) -> &'static str {
        match self {
            Family::PickPlace => "pick_place",
            Family::Stack => "stack",
            Family::Push => "push",
            Family::Lift => "lift",
            Family::Articulated => "articulated",
            Family::Navigate => "navigate",
        }
    }
}

/// One goal. Geometry is the relation report's (`sw_pipeline::relations_check`): collision
/// boxes in the world frame, support surfaces as the `sw_surface` sites, 2 cm resting
/// tolerance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "predicate", rename_all = "snake_case", deny_unknown_fields)]
pub enum Predicate {
    /// `object` rests on a support surface of one of `target` (its bottom within 2 cm of
    /// the surface, its centre over it), or on the top of a body without surfaces.
    On { object: String, target: Vec<String> },
    /// `object` is within one of `target`: its centre over the target's footprint, its
    /// bottom between the target's bottom and its rim.
    Inside { object: String, target: Vec<String> },
    /// `object` rests on the top of `target` (a movable thing), centre over its footprint.
    StackedOn { object: String, target: String },
    /// The footprints of `object` and `target` are at most `within` metres apart.
    Near { object: String, target: String, within: f64 },
    /// The centre of `object`'s footprint lies in the rectangle `min`..`max` (x, y).
    InRegion { object: String, min: [f64; 2], max: [f64; 2] },
    /// `object`'s collision-box centre is within `tolerance` of `pos`.
    AtPose { object: String, pos: [f64; 3], tolerance: f64 },
    /// The joint `joint` of `object` is at least 80 % of the way to its open end.
    Open { object: String, joint: String },
    /// The joint `joint` of `object` is within 10 % of its closed end.
    Closed { object: String, joint: String },
    /// The base of mobile robot `robot` is within `within` metres of `target`'s footprint.
    NavigateTo { robot: String, target: String, within: f64 },
}

impl Predicate {
    /// The body the goal is about (what moves), `None` for navigation.
    pub fn subject(&self) -> Option<&str> {
        match self {
            Predicate::On { object, .. }
            | Predicate::Inside { object, .. }
            | Predicate::StackedOn { object, .. }
            | Predicate::Near { object, .. }
            | Predicate::InRegion { object, .. }
            | Predicate::AtPose { object, .. }
            | Predicate::Open { object, .. }
            | Predicate::Closed { object, .. } => Some(object),
            Predicate::NavigateTo { .. } => None,
        }
    }

    /// Every body the goal names.
    pub fn bodies(&self) -> Vec<&str> {
        let mut out: Vec<&str> = self.subject().into_iter().collect();
        match self {
            Predicate::On { target, .. } | Predicate::Inside { target, .. } => {
                out.extend(target.iter().map(String::as_str));
            }
            Predicate::StackedOn { target, .. }
            | Predicate::Near { target, .. }
            | Predicate::NavigateTo { target, .. } => out.push(target),
            _ => {}
        }
        out
    }

    /// The predicate's name in `task.json`.
    pub fn name(&self) -> &'static str {
        match self {
            Predicate::On { .. } => "on",
            Predicate::Inside { .. } => "inside",
            Predicate::StackedOn { .. } => "stacked_on",
            Predicate::Near { .. } => "near",
            Predicate::InRegion { .. } => "in_region",
            Predicate::AtPose { .. } => "at_pose",
            Predicate::Open { .. } => "open",
            Predicate::Closed { .. } => "closed",
            Predicate::NavigateTo { .. } => "navigate_to",
        }
    }
}
