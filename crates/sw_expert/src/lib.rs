//! The expert that solves tasks, and what an episode records.
//!
//! ```text
//! package scene.xml ──episode_scene (frame-exact step, randomisation)──▶ episode scene.xml
//!        │ MuJoCo                                           task.json
//!        ▼                                                      │
//!  Rig (arm chain to the tool, servos, gripper) ── Expert: grasp → IK → RRT-Connect (MuJoCo's
//!  collision checks) → timed moves through the actuators, one control vector per frame
//!        ▼
//!  Recording (action, state, object poses, qpos per frame) ──judge (sw_task)──▶ solved or not
//!        ▼ (solved only)
//!  FrameRenderer (MuJoCo's renderer, offscreen EGL) ──▶ frames per camera
//! ```
//!
//! The expert links MuJoCo (as `sw_sim` does) because its IK, planning and execution are
//! MuJoCo's kinematics, Jacobians, collision detection and dynamics.

mod articulate;
mod drive;
mod episode_scene;
mod expert;
mod grasp;
mod ik;
mod math;
mod motion;
mod render;
mod rig;
mod run;

use std::path::Path;
use std::time::Instant;

use mujoco_rs::prelude::*;
use serde::{Deserialize, Serialize};
use sw_geom::Rng;
use sw_task::{GoalVerdict, Task};

pub use episode_scene::{BASE_TIMESTEP, Randomisation, Vary, episode_scene, frame_timing, open_at_start};
pub use render::{CameraSpec, FrameRenderer};
pub use run::Recording;

/// Why an attempt gave no episode. `kind()` names the class for summaries.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExpertError {
    #[error("{0}")]
    Scene(String),
    #[error("{0}")]
    Robot(String),
    #[error("{0}")]
    Grasp(String),
    #[error("{0}")]
    Ik(String),
    #[error("{0}")]
    Path(String),
    #[error("{0}")]
    Place(String),
    #[error("{0}")]
    Failed(String),
    #[error("{0}")]
    Unsupported(String),
    #[error("the task already holds at the start: {0}")]
    AlreadySatisfied(String),
    #[error("{0}")]
    Render(String),
}

impl ExpertError {
    /// A short name of the class of failure.
    pub fn kind(&self) -> &'static str {
        match self {
            ExpertError::Scene(_) => "scene",
            ExpertError::Robot(_) => "robot",
            ExpertError::Grasp(_) => "no_grasp",
            ExpertError::Ik(_) => "ik",
            ExpertError::Path(_) => "no_path",
            ExpertError::Place(_) => "no_place",
            ExpertError::Failed(_) => "execution",
            ExpertError::Unsupported(_) => "unsupported",
            ExpertError::AlreadySatisfied(_) => "already_satisfied",
            ExpertError::Render(_) => "render",
        }
    }
}

/// How an episode is run.
#[derive(Debug, Clone)]
pub struct ExpertOptions {
    pub fps: u32,
    /// Seeds the IK restarts and the planner's samples.
    pub seed: u64,
    /// An episode longer than this fails.
    pub max_seconds: f64,
}

impl Default for ExpertOptions {
    fn default() -> Self {
        Self { fps: 15, seed: 0, max_seconds: 60.0 }
    }
}

/// Effort spent on an episode.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Stats {
    pub ik_solves: usize,
    pub collision_checks: usize,
    pub seconds: f64,
}

/// A finished attempt: what was recorded and whether the task holds at its end.
#[derive(Debug, Clone)]
pub struct Episode {
    pub fps: u32,
    pub substeps: u32,
    pub timestep: f64,
    /// Names of the action's entries (every actuator of the scene, in order).
    pub action_names: Vec<String>,
    /// Names of the state's entries (the arm's joints, then the fingers).
    pub state_names: Vec<String>,
    /// Names of the object-pose entries (`cube_1.x` … `cube_1.qz`).
    pub env_names: Vec<String>,
    pub recording: Recording,
    pub verdicts: Vec<GoalVerdict>,
    pub success: bool,
    /// Why the run stopped before its end (a thing left the hand, no place was reachable
    /// with it in the hand, ...): the attempt failed, and what was recorded up to there is
    /// kept, to be looked at (never to be part of a dataset).
    pub failure: Option<ExpertError>,
    pub stats: Stats,
    /// The camera beside the robot's tool, if it has one.
    pub wrist_camera: Option<String>,
}

/// Whether the expert can do every goal of `task`: it picks and places things (on, inside,
/// stacked on, near, in a region, lifted to a pose) with an arm, or drives a wheeled base
/// to a place, or pushes a drawer or door closed, or pulls one open by its handle; it does
/// not yet drive and handle things in one task.
pub fn supports(task: &Task) -> Result<(), ExpertError> {
    let drives = task.goals.iter().filter(|g| matches!(g, sw_task::Predicate::NavigateTo { .. })).count();
    if drives > 0 && drives < task.goals.len() {
        return Err(ExpertError::Unsupported(
            "the expert drives a base to a place or handles things with an arm, not both in one task yet".into(),
        ));
    }
    Ok(())
}

/// True when every goal of `task` is a drive to a place.
fn drives(task: &Task) -> bool {
    !task.goals.is_empty() && task.goals.iter().all(|g| matches!(g, sw_task::Predicate::NavigateTo { .. }))
}

/// Runs the expert on the episode scene at `scene` for `task`, done by robot instance
/// `task.robot` of registry model `robot_model`. An error is returned when the run cannot
/// begin (the scene, the robot, a task the expert does not do, a start that already
/// satisfies it); a run that stops part way is an unsuccessful episode with its
/// [`Episode::failure`] and what it recorded.
pub fn solve(scene: &Path, task: &Task, robot_model: &str, opts: &ExpertOptions) -> Result<Episode, ExpertError> {
    let started = Instant::now();
    supports(task)?;
    let model = MjModel::from_xml(scene).map_err(|e| ExpertError::Scene(e.to_string()))?;
    let dt = model.opt().timestep;
    let fps = opts.fps.max(1);
    let substeps = (1.0 / (f64::from(fps) * dt)).round().max(1.0);
    if (substeps * dt * f64::from(fps) - 1.0).abs() > 1e-6 {
        return Err(ExpertError::Scene(format!(
            "the scene's step {dt} s does not divide a frame of 1/{fps} s; write it with episode_scene"
        )));
    }
    let drive = drives(task);
    let rig =
        if drive { rig::Rig::base(&model, &task.robot)? } else { rig::Rig::new(&model, &task.robot, robot_model)? };
    let reach = sw_robots::find(robot_model).map_or(0.85, |d| d.reach);
    let mut tracked_names: Vec<String> = task.moved_objects().into_iter().map(str::to_string).collect();
    if drive {
        // A drive's observation: the base's pose.
        tracked_names.extend(model.id_to_name(MjtObjBase::mjOBJ_BODY, rig.base_body).map(str::to_string));
    }
    let tracked: Vec<usize> = tracked_names
        .iter()
        .filter_map(|n| rig.objects.get(n).map(|o| o.0).or_else(|| model.name_to_id(MjtObjBase::mjOBJ_BODY, n)))
        .collect();
    let run = run::Runner::new(&model, fps, substeps as usize, tracked, opts.max_seconds)?;
    let initial = sw_task::judge(task, &rig.snapshot(&model, &run.data));
    if initial.iter().all(|v| v.held) {
        return Err(ExpertError::AlreadySatisfied(task.instruction.clone()));
    }
    let mut scratch = model.make_data();
    scratch.qpos_mut().copy_from_slice(run.data.qpos());
    ik::fk(&mut scratch);
    let mut expert = expert::Expert {
        model: &model,
        rig: &rig,
        run,
        scratch,
        rng: Rng::derive(opts.seed, "expert"),
        stats: Stats::default(),
        reach,
    };
    let failure = expert.solve(task).err();
    let verdicts = sw_task::judge(task, &expert.snapshot());
    let success = failure.is_none() && verdicts.iter().all(|v| v.held);
    let mut stats = expert.stats;
    stats.seconds = started.elapsed().as_secs_f64();
    let action_names = (0..model.ffi().nu as usize)
        .map(|a| model.id_to_name(MjtObjBase::mjOBJ_ACTUATOR, a).unwrap_or("").to_string())
        .collect();
    let mut state_names: Vec<String> = rig.arm.iter().map(|j| j.name.clone()).collect();
    state_names.extend(rig.finger_names.first().cloned());
    let env_names = tracked_names
        .iter()
        .flat_map(|n| ["x", "y", "z", "qw", "qx", "qy", "qz"].map(|c| format!("{n}.{c}")))
        .collect();
    let wrist_camera = rig.wrist_camera.and_then(|c| model.id_to_name(MjtObjBase::mjOBJ_CAMERA, c).map(str::to_string));
    Ok(Episode {
        fps,
        substeps: substeps as u32,
        timestep: dt,
        action_names,
        state_names,
        env_names,
        recording: expert.run.rec,
        verdicts,
        success,
        failure,
        stats,
        wrist_camera,
    })
}
