//! `scenewright export --format usd`: a missing converter set-up is a one-line exit 2;
//! the exported arm has a PhysX drive on every joint its MuJoCo servo drives, aimed at the
//! `home` pose — read back with usd-core's `pxr` (another OpenUSD build than the
//! converter's) and compared with the keyframe MuJoCo 3.17 compiles; export.json lists
//! every file written. The export part needs `scripts/setup.sh --usd` and `--tests`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");

fn checkout() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).ancestors().nth(2).unwrap().to_path_buf()
}

#[test]
fn a_missing_converter_is_a_set_up_problem_said_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let pkg = dir.path().join("pkg");
    let o = Command::new(BIN).args(["generate", "a table with a mug", "--out"]).arg(&pkg).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for (var, value) in
        [("SCENEWRIGHT_USD_PYTHON", "/nonexistent/python"), ("SCENEWRIGHT_USD_VENV", "/nonexistent/venv")]
    {
        let o = Command::new(BIN)
            .args(["export", "--format", "usd"])
            .arg(&pkg)
            .env_remove("SCENEWRIGHT_USD_PYTHON")
            .env(var, value)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{var}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains("scripts/setup.sh --usd"), "{err}");
        assert!(!pkg.with_file_name("pkg_usd").exists(), "nothing written");
    }
}

#[test]
fn an_exported_arm_is_driven_to_its_home_pose() {
    let root = checkout();
    let (converter, reader) = (root.join(".cache/usd-venv/bin/python"), root.join(".cache/py-venv/bin/python"));
    if !converter.is_file() || !reader.is_file() {
        eprintln!("skipped: needs scripts/setup.sh --usd --tests");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let pkg = dir.path().join("pkg");
    let o =
        Command::new(BIN).args(["generate", "a lab with a UR5e on a workbench", "--out"]).arg(&pkg).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = dir.path().join("usd");
    let o = Command::new(BIN)
        .args(["export", "--format", "usd", "--json", "--out"])
        .arg(&out)
        .arg(&pkg)
        .env_remove("SCENEWRIGHT_USD_PYTHON")
        .env_remove("SCENEWRIGHT_USD_VENV")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let record: Value = serde_json::from_str(&std::fs::read_to_string(out.join("export.json")).unwrap()).unwrap();
    // Every file written is listed, and nothing else.
    let mut listed: Vec<String> =
        record["files"].as_array().unwrap().iter().map(|f| f.as_str().unwrap().to_string()).collect();
    listed.sort();
    let mut found = Vec::new();
    let mut stack = vec![out.clone()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            if e.path().is_dir() {
                stack.push(e.path());
            } else {
                found.push(e.path().strip_prefix(&out).unwrap().display().to_string());
            }
        }
    }
    found.sort();
    assert_eq!(listed, found);
    // One drive per position servo: the UR5e's six joints (angular) and its built-in
    // gripper's left finger (linear; the right finger follows it by an equality).
    let drives = record["drives"].as_array().unwrap();
    let of_kind = |k: &str| drives.iter().filter(|d| d["kind"] == k).count();
    assert_eq!((of_kind("angular"), of_kind("linear"), drives.len()), (6, 1, 7), "{record}");
    assert!(drives.iter().any(|d| d["joint"] == "ur5e_1_gripper_finger_left" && d["kind"] == "linear"), "{record}");

    // Read back independently: usd-core's pxr for the drives, MuJoCo 3.17 for the home pose.
    let check = r#"
import json, math, sys
import mujoco
from pxr import Usd, UsdPhysics
stage = Usd.Stage.Open(sys.argv[1])
m = mujoco.MjModel.from_xml_path(sys.argv[2])
key = m.key("home").id
servo = {m.joint(m.actuator_trnid[i][0]).name: i for i in range(m.nu) if m.actuator_trntype[i] == mujoco.mjtTrn.mjTRN_JOINT}
out = {}
for p in stage.Traverse():
    angular, linear = p.IsA(UsdPhysics.RevoluteJoint), p.IsA(UsdPhysics.PrismaticJoint)
    if not (angular or linear):
        continue
    kind = "angular" if angular else "linear"
    d = UsdPhysics.DriveAPI.Get(p, kind)
    a = servo.get(p.GetName(), -1)
    home = float(m.key_ctrl[key][a]) if a >= 0 else None
    out[p.GetName()] = {
        "kind": kind,
        "servo": a >= 0,
        "driven": p.HasAPI(UsdPhysics.DriveAPI, kind),
        "stiffness": d.GetStiffnessAttr().Get() if d else None,
        "target": d.GetTargetPositionAttr().Get() if d else None,
        # Degrees for angular drives, metres for linear ones, as USD physics counts them.
        "home": (math.degrees(home) if angular else home) if home is not None else None,
    }
print(json.dumps(out))
"#;
    let o = Command::new(&reader)
        .args(["-c", check])
        .arg(out.join("scenewright.usda"))
        .arg(pkg.join("scene.xml"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let joints: Value = serde_json::from_slice(&o.stdout).unwrap();
    let joints = joints.as_object().unwrap();
    // The arm's six revolute joints and the gripper's two sliding fingers.
    let of_kind = |k: &str| joints.values().filter(|j| j["kind"] == k).count();
    assert_eq!((of_kind("angular"), of_kind("linear")), (6, 2), "{joints:?}");
    // Every joint a servo drives has a drive to its home control; the others have none.
    for (name, j) in joints {
        assert_eq!(j["driven"], j["servo"], "{name}: {j}");
        if j["servo"] != true {
            continue;
        }
        assert!(j["stiffness"].as_f64().unwrap() > 1.0, "{name}: {j}");
        let (target, home) = (j["target"].as_f64().unwrap(), j["home"].as_f64().unwrap());
        assert!((target - home).abs() < 1e-3, "{name}: drive target {target} but home is {home} ({})", j["kind"]);
    }
    assert_eq!(joints.values().filter(|j| j["driven"] == true).count(), 7, "{joints:?}");
    // The arm's home is not its zero pose: at least one target is not 0.
    assert!(joints.values().any(|j| j["kind"] == "angular" && j["target"].as_f64().unwrap().abs() > 10.0));
    // The gripper is held open at home (42.5 mm per finger), not left to slide.
    assert!((joints["ur5e_1_gripper_finger_left"]["target"].as_f64().unwrap() - 0.0425).abs() < 1e-6, "{joints:?}");
}
