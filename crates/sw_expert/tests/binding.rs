#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The task reader bound to generated, verified scenes (each compiled and settled in
//! MuJoCo by the pipeline): parts of articulated things by their joints ("the top drawer
//! of the filing cabinet", "the microwave door"), switch verbs, kinds the catalog names
//! (`is_a`), and position words; refusals name the thing.

use std::path::{Path, PathBuf};

use sw_task::{Predicate, SceneFacts, Task, TaskError};

fn package(prompt: &str, seed: u64, dir: &Path) -> PathBuf {
    let out = dir.join(format!("pkg-{seed}-{}", sw_geom::fnv1a(prompt.as_bytes())));
    let opts = sw_pipeline::Options { seed, ..sw_pipeline::Options::default() };
    let o = sw_pipeline::generate(prompt, &out, &opts, &mut |_| {}).expect("generate");
    assert!(sw_pipeline::succeeded(&o.report), "{prompt} seed {seed}: {:?}", o.report.verification);
    out
}

/// Binds with the joints the written scene.xml really has.
fn bind(dir: &Path, instruction: &str) -> Result<Task, TaskError> {
    let read = |n: &str| std::fs::read_to_string(dir.join(n)).unwrap();
    let plan: sw_plan::ScenePlan = serde_json::from_str(&read("plan.json")).unwrap();
    let layout: sw_plan::LaidOutScene = serde_json::from_str(&read("layout.json")).unwrap();
    let mut joints = Vec::new();
    sw_mjcf::xml::Element::parse(&read("scene.xml")).unwrap().walk(&mut |e| {
        if e.name == "joint"
            && let Some(n) = e.get("name")
        {
            joints.push(n.to_string());
        }
    });
    sw_task::bind(instruction, "flag", &SceneFacts::new(&plan, &layout, joints))
}

fn joint_of(t: &Task) -> (&str, &str, bool) {
    match &t.goals[..] {
        [Predicate::Open { object, joint }] => (object, joint, true),
        [Predicate::Closed { object, joint }] => (object, joint, false),
        g => panic!("one open/closed goal, got {g:?}"),
    }
}

#[test]
fn parts_of_articulated_things_bind_to_their_joints() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = package("a Panda on a table next to a filing cabinet", 1, tmp.path());
    // Drawers count from the bottom: the top one is the last.
    let t = bind(&dir, "please close the top drawer of the filing cabinet").unwrap();
    let (object, top, open) = joint_of(&t);
    assert!(object.starts_with("filing_cabinet") && top.contains("drawer") && !open, "{t:?}");
    let t = bind(&dir, "Open the bottom drawer").unwrap();
    let (_, bottom, open) = joint_of(&t);
    assert!(open && bottom.contains("drawer") && bottom != top, "{bottom} vs {top}");
    assert_eq!(joint_of(&bind(&dir, "pull the drawer open").unwrap()).1, bottom);
    // A thing with no such part is refused, naming it and what does open.
    let e = bind(&dir, "open the table").unwrap_err().to_string();
    assert!(e.contains("table_1") && e.contains("filing_cabinet"), "{e}");
    let e = bind(&dir, "turn on the stove").unwrap_err().to_string();
    assert!(e.contains("stove"), "{e}");
}

#[test]
fn doors_switches_kinds_and_positions_bind() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = package("a kitchen with a Panda on a counter, a microwave on the counter and a stove", 3, tmp.path());
    let t = bind(&dir, "can you open the microwave door?").unwrap();
    let (object, joint, open) = joint_of(&t);
    assert!(object.starts_with("microwave") && joint.contains("door") && open);
    // "turn on" is open; a stove without a moving part is refused with its name.
    match bind(&dir, "turn on the stove") {
        Ok(t) => assert!(matches!(t.goals[..], [Predicate::Open { .. }])),
        Err(e) => assert!(e.to_string().contains("stove"), "{e}"),
    }
    // Kinds the catalog names: a mug is "drinkware", a bowl a "container".
    let dir = package("a Panda on a table with a mug and a bowl", 4, tmp.path());
    let t = bind(&dir, "put the drinkware in the container").unwrap();
    assert_eq!(t.goals, vec![Predicate::Inside { object: "mug_1".into(), target: vec!["bowl_1".into()] }]);
    // "the cube on the left": the one furthest to the arm's left.
    let dir = package("a Panda on a table with three cubes and a bowl", 5, tmp.path());
    let left = bind(&dir, "pick up the cube on the left and put it in the bowl").unwrap();
    let right = bind(&dir, "put the rightmost cube in the bowl").unwrap();
    let (Some(l), Some(r)) = (left.goals[0].subject(), right.goals[0].subject()) else { panic!() };
    assert_ne!(l, r, "{left:?} {right:?}");
}
