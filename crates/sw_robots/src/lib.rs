//! The robot registry: every robot scenewright can put into a scene, with the facts the
//! planner and the layout need (kind, aliases, footprint, reach) and its MJCF.
//!
//! Built-in models are written here from published kinematics and dimensions and ship
//! inside the binary. Their MJCF names are unprefixed; the merger in `sw_mjcf` prefixes
//! everything with the instance name.

/// What a robot is, for mounting and layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RobotKind {
    /// A fixed-base arm: mounted on a surface, a pedestal or a cart.
    Arm,
    /// A wheeled base that drives on the floor.
    MobileBase,
}

/// One registered robot model.
#[derive(Debug)]
pub struct RobotDef {
    /// Registry name: `ur5e`.
    pub name: &'static str,
    /// Human name: "Universal Robots UR5e".
    pub display: &'static str,
    pub kind: RobotKind,
    /// Where the model comes from and under what terms.
    pub source: &'static str,
    /// The MJCF document (one top-level body, unprefixed names).
    pub mjcf: &'static str,
    /// Radius of a circle around the base axis that contains the robot at its home pose,
    /// seen from above, m. The layout keeps this clear.
    pub footprint_radius: f64,
    /// Height of the robot at its home pose above its mount plane, m.
    pub height: f64,
    /// Reach from the base axis for arms, m (0 for bases).
    pub reach: f64,
    /// Radius of the base plate that rests on the mount, m.
    pub base_radius: f64,
    /// Boxes (min, max corners, in the base frame) that contain the robot's collision
    /// geometry at its home pose, with a 1–2 cm margin. The layout keeps them clear.
    /// The robot works towards its +X axis.
    pub keepout: &'static [([f64; 3], [f64; 3])],
}

static UR5E: RobotDef = RobotDef {
    name: "ur5e",
    display: "Universal Robots UR5e (built-in, from published DH parameters)",
    kind: RobotKind::Arm,
    source: "written for scenewright from the UR5e's published DH parameters, masses and limits",
    mjcf: include_str!("../models/ur5e.xml"),
    footprint_radius: 0.55,
    height: 0.65,
    reach: 0.85,
    base_radius: 0.075,
    // Measured at the home keyframe: base, shoulder and vertical upper arm; forearm and wrist.
    keepout: &[([-0.09, -0.09, 0.0], [0.09, 0.215, 0.66]), ([-0.08, -0.065, 0.31], [0.53, 0.215, 0.67])],
};

static TURTLEBOT3: RobotDef = RobotDef {
    name: "turtlebot3",
    display: "TurtleBot3 Waffle-class mobile base (built-in)",
    kind: RobotKind::MobileBase,
    source: "written for scenewright from the TurtleBot3 Waffle Pi's published dimensions",
    mjcf: include_str!("../models/turtlebot3.xml"),
    footprint_radius: 0.21,
    height: 0.15,
    reach: 0.0,
    base_radius: 0.19,
    keepout: &[([-0.155, -0.165, 0.0], [0.155, 0.165, 0.16])],
};

static REGISTRY: [&RobotDef; 2] = [&UR5E, &TURTLEBOT3];

/// Every registered robot, in a stable order.
pub fn registry() -> &'static [&'static RobotDef] {
    &REGISTRY
}

/// The robot registered under `name`.
pub fn find(name: &str) -> Option<&'static RobotDef> {
    registry().iter().copied().find(|r| r.name == name)
}

/// The default model of a kind, used when a requested robot is not registered.
pub fn default_of(kind: RobotKind) -> &'static RobotDef {
    match kind {
        RobotKind::Arm => &UR5E,
        RobotKind::MobileBase => &TURTLEBOT3,
    }
}
