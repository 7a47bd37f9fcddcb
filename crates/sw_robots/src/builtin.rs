//! The built-in models: written for scenewright from published kinematics, masses and
//! limits (see the comment at the top of each file in `models/`), shipped in the binary.
//!
//! Keep-out boxes, heights and footprints were measured at the `home` keyframe with the
//! official MuJoCo 4.0 Python bindings (`tools/measure.py` on `scenewright robots show NAME
//! --mjcf`): the union of the collision geometry's boxes, split into a column over the
//! base and the rest (and, where it hangs below the rest, the gripper), with about 1 cm of
//! margin. The registry's tests check them against an in-process measurement in MuJoCo 3.17.

use crate::load::{BuiltinPart, ModelSpec};
use crate::{Gripper, Licence, Origin, RobotDef, RobotKind};

const IDENTITY: [f64; 4] = [1.0, 0.0, 0.0, 0.0];

const fn part(label: &'static str, mjcf: &'static str) -> BuiltinPart {
    BuiltinPart { label, mjcf, prefix: "", attach_to: None, pos: [0.0; 3], quat: IDENTITY }
}

const OWN: Licence = Licence { name: "MIT OR Apache-2.0 (scenewright)", files: Vec::new() };

/// The built-in parallel gripper on an arm's flange body, at the tool frame (z out of the
/// flange).
const fn gripper_on(carrier: &'static str, pos: [f64; 3], quat: [f64; 4]) -> BuiltinPart {
    BuiltinPart {
        label: "built-in parallel gripper",
        mjcf: include_str!("../models/parallel_gripper.xml"),
        prefix: "gripper_",
        attach_to: Some(carrier),
        pos,
        quat,
    }
}

/// The UR flange frame in `wrist_3_link`: x = -x, y = z, z = y of the link (site `tool0`).
const UR_TOOL: [f64; 4] = [0.0, 0.0, std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2];

static UR5E_PARTS: [BuiltinPart; 2] =
    [part("built-in ur5e", include_str!("../models/ur5e.xml")), gripper_on("wrist_3_link", [0.0; 3], UR_TOOL)];
static UR10E_PARTS: [BuiltinPart; 2] =
    [part("built-in ur10e", include_str!("../models/ur10e.xml")), gripper_on("wrist_3_link", [0.0; 3], UR_TOOL)];
static PANDA_PARTS: [BuiltinPart; 1] = [part("built-in panda", include_str!("../models/panda.xml"))];
static GEN3_PARTS: [BuiltinPart; 2] = [
    part("built-in kinova_gen3", include_str!("../models/kinova_gen3.xml")),
    // The tool interface: 61.5 mm below the bracelet, turned half a turn about x.
    gripper_on("bracelet_link", [0.0, 0.0, -0.0615], [0.0, 1.0, 0.0, 0.0]),
];

/// The parallel gripper's drive, as the registry names it under the arm.
const PARALLEL_GRIPPER: Gripper = Gripper {
    tcp_site: "gripper_tcp",
    actuator: "gripper_fingers",
    open: 0.0425,
    closed: 0.0,
    max_opening: 0.085,
    finger_depth: 0.02,
    wrist_camera: "wrist",
};
static TB3_PARTS: [BuiltinPart; 1] = [part("built-in turtlebot3", include_str!("../models/turtlebot3.xml"))];
static MM_PARTS: [BuiltinPart; 2] = [
    part("built-in mobile_manipulator base", include_str!("../models/mobile_base.xml")),
    BuiltinPart {
        label: "built-in mobile_manipulator arm (panda)",
        mjcf: include_str!("../models/panda.xml"),
        prefix: "arm_",
        attach_to: Some("arm_mount"),
        pos: [0.0; 3],
        quat: IDENTITY,
    },
];

static UR5E: RobotDef = RobotDef {
    name: "ur5e",
    aliases: &[],
    display: "Universal Robots UR5e (built-in, from published DH parameters)",
    kind: RobotKind::Arm,
    source: "written for scenewright from the UR5e's published DH parameters, masses and limits",
    origin: Origin::BuiltIn,
    licence: OWN,
    footprint_radius: 0.55,
    height: 0.65,
    reach: 0.85,
    base_radius: 0.075,
    // Measured at the home keyframe: base, shoulder and vertical upper arm; forearm and wrist;
    // the parallel gripper hanging from the flange, its fingers open (down to z = 0.175).
    keepout: &[
        ([-0.09, -0.09, 0.0], [0.09, 0.215, 0.66]),
        ([-0.08, -0.065, 0.31], [0.53, 0.215, 0.67]),
        ([0.38, 0.08, 0.16], [0.53, 0.19, 0.34]),
    ],
    measured: true,
    model: ModelSpec::BuiltIn { parts: &UR5E_PARTS, excludes: &[] },
    gripper: Some(PARALLEL_GRIPPER),
};

static UR10E: RobotDef = RobotDef {
    name: "ur10e",
    aliases: &[],
    display: "Universal Robots UR10e (built-in, from published DH parameters)",
    kind: RobotKind::Arm,
    source: "written for scenewright from the UR10e's published DH parameters, masses and limits",
    origin: Origin::BuiltIn,
    licence: OWN,
    footprint_radius: 0.77,
    height: 0.89,
    reach: 1.3,
    base_radius: 0.095,
    keepout: &[([-0.11, -0.11, 0.0], [0.11, 0.12, 0.27]), ([-0.09, -0.04, 0.09], [0.72, 0.26, 0.89])],
    measured: true,
    model: ModelSpec::BuiltIn { parts: &UR10E_PARTS, excludes: &[] },
    gripper: Some(PARALLEL_GRIPPER),
};

static PANDA: RobotDef = RobotDef {
    name: "panda",
    aliases: &["franka", "franka_panda", "fr3"],
    display: "Franka Emika Panda with Franka Hand (built-in, from published DH parameters)",
    kind: RobotKind::Arm,
    source: "written for scenewright from Franka's published DH parameters and limits and the identified link inertias of Gaz et al. (2019)",
    origin: Origin::BuiltIn,
    licence: OWN,
    footprint_radius: 0.41,
    height: 0.81,
    reach: 0.855,
    base_radius: 0.135,
    keepout: &[([-0.24, -0.09, 0.0], [0.25, 0.09, 0.81]), ([-0.31, -0.12, 0.39], [0.39, 0.12, 0.77])],
    measured: true,
    model: ModelSpec::BuiltIn { parts: &PANDA_PARTS, excludes: &[] },
    gripper: Some(Gripper {
        tcp_site: "tcp",
        actuator: "gripper",
        open: 0.04,
        closed: 0.0,
        max_opening: 0.08,
        finger_depth: 0.008,
        wrist_camera: "wrist",
    }),
};

static KINOVA_GEN3: RobotDef = RobotDef {
    name: "kinova_gen3",
    aliases: &["gen3", "kinova"],
    display: "Kinova Gen3 7-DOF (built-in, from Kinova's published frame transforms)",
    kind: RobotKind::Arm,
    source: "written for scenewright from the Gen3 user guide's frame transforms, limits and link masses",
    origin: Origin::BuiltIn,
    licence: OWN,
    // With the parallel gripper, which points forward at home.
    footprint_radius: 0.62,
    height: 0.76,
    reach: 0.902,
    base_radius: 0.052,
    keepout: &[([-0.07, -0.08, 0.0], [0.18, 0.07, 0.76]), ([0.08, -0.06, 0.36], [0.62, 0.06, 0.71])],
    measured: true,
    model: ModelSpec::BuiltIn { parts: &GEN3_PARTS, excludes: &[] },
    gripper: Some(PARALLEL_GRIPPER),
};

static TURTLEBOT3: RobotDef = RobotDef {
    name: "turtlebot3",
    aliases: &[],
    display: "TurtleBot3 Waffle-class mobile base (built-in)",
    kind: RobotKind::MobileBase,
    source: "written for scenewright from the TurtleBot3 Waffle Pi's published dimensions",
    origin: Origin::BuiltIn,
    licence: OWN,
    footprint_radius: 0.21,
    height: 0.15,
    reach: 0.0,
    base_radius: 0.19,
    keepout: &[([-0.155, -0.165, 0.0], [0.155, 0.165, 0.16])],
    measured: true,
    model: ModelSpec::BuiltIn { parts: &TB3_PARTS, excludes: &[] },
    gripper: None,
};

static MOBILE_MANIPULATOR: RobotDef = RobotDef {
    name: "mobile_manipulator",
    aliases: &["mobile_manipulator_panda"],
    display: "Mobile manipulator: the built-in Panda on a differential-drive base (built-in)",
    kind: RobotKind::MobileManipulator,
    source: "written for scenewright: a generic 0.60 x 0.46 m differential-drive base carrying the built-in Panda",
    origin: Origin::BuiltIn,
    licence: OWN,
    footprint_radius: 0.57,
    height: 1.14,
    reach: 0.855,
    base_radius: 0.3,
    keepout: &[([-0.31, -0.25, 0.0], [0.51, 0.25, 1.14])],
    measured: true,
    model: ModelSpec::BuiltIn { parts: &MM_PARTS, excludes: &[] },
    gripper: Some(Gripper {
        tcp_site: "arm_tcp",
        actuator: "arm_gripper",
        open: 0.04,
        closed: 0.0,
        max_opening: 0.08,
        finger_depth: 0.008,
        wrist_camera: "arm_wrist",
    }),
};

static ALL: [&RobotDef; 6] = [&UR5E, &UR10E, &PANDA, &KINOVA_GEN3, &TURTLEBOT3, &MOBILE_MANIPULATOR];

pub(crate) fn all() -> &'static [&'static RobotDef] {
    &ALL
}

pub(crate) fn default_of(kind: RobotKind) -> &'static RobotDef {
    match kind {
        RobotKind::Arm => &UR5E,
        RobotKind::MobileBase => &TURTLEBOT3,
        RobotKind::MobileManipulator => &MOBILE_MANIPULATOR,
    }
}
