#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The expert on generated, verified scenes: it solves pick-and-place and stacking with
//! every built-in arm (each carries a gripper), its recorded controls replay to the same
//! end in a fresh MuJoCo, and tasks it cannot do are refused with the part named.

use std::path::{Path, PathBuf};

use mujoco_rs::prelude::*;
use sw_expert::{ExpertOptions, Vary, episode_scene, frame_timing, solve};
use sw_task::{SceneFacts, Task};

fn package(prompt: &str, seed: u64, dir: &Path) -> PathBuf {
    let out = dir.join(format!("pkg-{seed}-{}", sw_geom::fnv1a(prompt.as_bytes())));
    let opts = sw_pipeline::Options { seed, ..sw_pipeline::Options::default() };
    let o = sw_pipeline::generate(prompt, &out, &opts, &mut |_| {}).expect("generate");
    assert!(sw_pipeline::succeeded(&o.report), "{prompt} seed {seed}: {:?}", o.report.verification);
    out
}

fn bind(dir: &Path, instruction: &str) -> Result<Task, sw_task::TaskError> {
    let plan: sw_plan::ScenePlan =
        serde_json::from_str(&std::fs::read_to_string(dir.join("plan.json")).unwrap()).unwrap();
    let layout: sw_plan::LaidOutScene =
        serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json")).unwrap()).unwrap();
    sw_task::bind(instruction, "flag", &SceneFacts::new(&plan, &layout, Vec::new()))
}

fn robot_model(dir: &Path, robot: &str) -> String {
    let layout: sw_plan::LaidOutScene =
        serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json")).unwrap()).unwrap();
    layout.robots.iter().find(|r| r.name == robot).unwrap().model.clone()
}

/// Writes the episode scene and runs the expert; (episode, scene path).
fn run(dir: &Path, task: &Task, seed: u64) -> (Result<sw_expert::Episode, sw_expert::ExpertError>, PathBuf) {
    let xml = std::fs::read_to_string(dir.join("scene.xml")).unwrap();
    let movable = task.moved_objects().into_iter().map(str::to_string).collect::<Vec<_>>();
    let (text, _) = episode_scene(&xml, 15, seed, &movable, &[], Vary::ALL).unwrap();
    let path = dir.join("episode.xml");
    std::fs::write(&path, text).unwrap();
    let opts = ExpertOptions { fps: 15, seed, max_seconds: 60.0 };
    (solve(&path, task, &robot_model(dir, &task.robot), &opts), path)
}

#[test]
fn a_panda_puts_the_red_cube_in_the_bowl_and_the_controls_replay() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = package("a Panda on a table with a red cube and a bowl", 1, tmp.path());
    let task = bind(&dir, "put the red cube in the bowl").unwrap();
    assert_eq!(task.robot, "panda_1");
    let (ep, scene) = run(&dir, &task, 1);
    let ep = ep.unwrap();
    assert!(ep.success, "{:?}", ep.verdicts);
    let (dt, substeps) = frame_timing(15);
    assert_eq!((ep.substeps, ep.timestep), (substeps, dt));
    let n = ep.recording.actions.len();
    assert!(n > 30 && ep.recording.states.len() == n && ep.recording.qpos.len() == n);
    // The recorded controls, held for one frame each from `home`, end where the run ended.
    let model = MjModel::from_xml(&scene).unwrap();
    let mut data = model.make_data();
    data.reset_keyframe(model.name_to_id(MjtObjBase::mjOBJ_KEY, "home").unwrap()).unwrap();
    data.forward();
    for (k, a) in ep.recording.actions.iter().enumerate() {
        let err = data.qpos().iter().zip(&ep.recording.qpos[k]).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
        assert!(err < 1e-9, "frame {k}: replay differs by {err}");
        data.ctrl_mut().copy_from_slice(a);
        for _ in 0..substeps {
            data.step();
        }
    }
}

#[test]
fn every_built_in_arm_carries_a_gripper_and_stacks() {
    let tmp = tempfile::tempdir().unwrap();
    for (k, arm) in ["UR5e", "UR10e", "Kinova Gen3"].iter().enumerate() {
        let prompt = format!("a {arm} on a table with a red cube and a blue cube");
        let dir = package(&prompt, 2 + k as u64, tmp.path());
        let task = bind(&dir, "stack the red cube on the blue cube").unwrap();
        let g = task.gripper.as_ref().unwrap_or_else(|| panic!("{arm}: no gripper"));
        assert!(g.tcp_site.ends_with("gripper_tcp"), "{arm}: {g:?}");
        let (ep, _) = run(&dir, &task, 7);
        let ep = ep.unwrap_or_else(|e| panic!("{arm}: {e}"));
        assert!(ep.success, "{arm}: {:?}", ep.verdicts);
        assert!(ep.wrist_camera.is_some(), "{arm}: no wrist camera");
    }
}

#[test]
fn bad_tasks_name_the_part() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = package("a Panda on a table with a red cube and a bowl", 1, tmp.path());
    let e = bind(&dir, "put the mug in the sink").unwrap_err().to_string();
    assert!(e.contains("\"mug\"") && e.contains("not in the scene"), "{e}");
    let e = bind(&dir, "put the blue cube in the bowl").unwrap_err().to_string();
    assert!(e.contains("blue cube") && e.contains("cube_1 (red)"), "{e}");
    let e = bind(&dir, "put the cube in the bowl and then put the cube on the table").unwrap_err().to_string();
    assert!(e.starts_with("contradictory goals: cube_1"), "{e}");
    let e = bind(&dir, "dance").unwrap_err().to_string();
    assert!(e.contains("asks for nothing the robot can do"), "{e}");
    let tb = package("a TurtleBot in a room with a red cube and a bowl", 1, tmp.path());
    let e = bind(&tb, "put the cube in the bowl").unwrap_err().to_string();
    assert!(e.contains("no robot arm") || e.contains("gripper"), "{e}");
}

#[test]
fn a_task_that_already_holds_is_refused_at_the_start() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = package("a Panda on a table with a red cube and a bowl", 1, tmp.path());
    let task = bind(&dir, "put the cube on the table").unwrap();
    let (ep, _) = run(&dir, &task, 1);
    assert!(matches!(ep, Err(sw_expert::ExpertError::AlreadySatisfied(_))), "{:?}", ep.map(|e| e.success));
}
