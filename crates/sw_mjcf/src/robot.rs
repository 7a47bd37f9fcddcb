//! What the merger takes (a robot's MJCF, in one or more parts) and what it gives back
//! (prefixed elements ready to insert, the files they reference, the home state).

use std::collections::BTreeMap;
use std::path::PathBuf;

use sw_geom::Pose;

use crate::xml::{Element, XmlError};

/// A robot model to merge: one or more MJCF parts assembled into one robot (an arm and
/// its gripper, a mobile base and the arm on it).
#[derive(Debug, Clone)]
pub struct RobotSource {
    /// Registry name. The robot's mesh and texture files go to `assets/robots/<model>/`.
    pub model: String,
    pub parts: Vec<RobotPart>,
    /// Joint positions at home by joint name (with the part prefix), overriding the files' keys.
    pub home: Vec<(String, Vec<f64>)>,
    /// Controls at home by actuator name (with the part prefix), overriding derived ones.
    pub home_ctrl: Vec<(String, f64)>,
    /// Extra contact excludes between two bodies (names with the part prefix).
    pub excludes: Vec<(String, String)>,
    /// What was adjusted before the merge (a URDF import's additions), for the report.
    pub notes: Vec<String>,
}

impl RobotSource {
    /// A robot of one self-contained MJCF document with no files (the built-in models).
    pub fn single(model: &str, label: &str, mjcf: &str) -> Self {
        Self {
            model: model.to_string(),
            parts: vec![RobotPart::new(label, mjcf)],
            home: Vec::new(),
            home_ctrl: Vec::new(),
            excludes: Vec::new(),
            notes: Vec::new(),
        }
    }
}

/// One MJCF document of a robot.
#[derive(Debug, Clone)]
pub struct RobotPart {
    /// Named in every error: the file path, or "built-in ur5e".
    pub label: String,
    pub mjcf: String,
    /// The directory relative file names start from (the MJCF file's directory). `None`
    /// for documents that reference no files.
    pub dir: Option<PathBuf>,
    /// The text of every file `<include>`d (directly or from another include), by the
    /// `file` attribute as written.
    pub includes: BTreeMap<String, String>,
    /// Prefix of this part's names inside the robot ("gripper_"); empty for the main part.
    pub prefix: String,
    /// The body of an earlier part (name with that part's prefix) that carries this part's
    /// top-level bodies; `None` puts them on the robot's mount.
    pub attach_to: Option<String>,
    /// Pose of the part in the carrying body's frame (or the mount's).
    pub attach_pose: Pose,
    pub fixes: PartFixes,
}

impl RobotPart {
    pub fn new(label: &str, mjcf: &str) -> Self {
        Self {
            label: label.to_string(),
            mjcf: mjcf.to_string(),
            dir: None,
            includes: BTreeMap::new(),
            prefix: String::new(),
            attach_to: None,
            attach_pose: Pose::IDENTITY,
            fixes: PartFixes::default(),
        }
    }
}

/// Adjustments a registered model asks for, each with a reason the registry states.
#[derive(Debug, Clone, Default)]
pub struct PartFixes {
    /// Compiler attributes assumed when the file does not set them, as (attribute, value).
    /// MJCF's default angle unit is degrees, but robosuite's fragments are written for its
    /// base model (`angle="radian"`, `inertiagrouprange="0 0"`).
    pub assume_compiler: Vec<(String, String)>,
    /// Keep the first of two assets with one name and drop the second (robosuite merges
    /// assets this way; one of its grippers defines a mesh name twice).
    pub keep_first_duplicate_asset: bool,
    /// Attributes to remove, as (element, attribute): schema violations in shipped files.
    pub drop_attrs: Vec<(String, String)>,
    /// `gravcomp="1"` on every body of the part: the real controller compensates gravity.
    pub gravcomp: bool,
    /// Replace torque motors on joints by joint position servos with the same torque limits.
    pub servos: Option<ServoGains>,
    /// Put geoms in the scene's groups: non-colliding (visual) geoms in group 2, colliding
    /// ones in group 3 (robosuite uses 1 and 0, which viewers show together).
    pub regroup: bool,
}

/// Gains of the position servos that replace torque motors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ServoGains {
    /// Stiffness per N·m of the motor's torque limit, 1/rad (kp = limit × this).
    pub kp_per_torque: f64,
    /// Damping as a fraction of the stiffness, s (kv = kp × this).
    pub kv_per_kp: f64,
}

/// A file a merged robot references, to be copied into the package.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct RobotFile {
    /// Where the file is.
    pub source: PathBuf,
    /// Its path inside the package's `assets/` directory (`robots/<model>/...`).
    pub dest: String,
    /// The element that references it and the file that element is in, for errors.
    pub element: String,
}

/// A robot, prefixed and ready to insert.
#[derive(Debug, Clone)]
pub struct PreparedRobot {
    pub prefix: String,
    /// Top-level bodies, prefixed and posed in the world.
    pub bodies: Vec<Element>,
    /// Asset children (materials, meshes, textures), prefixed, file paths relative to the
    /// scene's `assets/` directory.
    pub assets: Vec<Element>,
    /// Each part's default tree as `<default class="<prefix>_<part>main">`.
    pub defaults: Vec<Element>,
    /// Children of the merged sections, by section name.
    pub sections: BTreeMap<String, Vec<Element>>,
    /// Joint positions at home, by prefixed joint name.
    pub home_qpos: BTreeMap<String, Vec<f64>>,
    /// Control of each of the robot's actuators at home, in order.
    pub home_ctrl: Vec<f64>,
    /// Files to copy into the package, sorted, without duplicates.
    pub files: Vec<RobotFile>,
    /// What was dropped or adjusted, for the report (never silent).
    pub notes: Vec<String>,
}

/// A robot document that cannot be merged; the message names the file and the element.
#[derive(Debug, thiserror::Error)]
pub enum MergeError {
    #[error("{source_name}: not valid XML at {0}", source_name = .1)]
    Xml(XmlError, String),
    #[error("{source_name}: the root element is <{found}>, expected <mujoco>")]
    NotMjcf { source_name: String, found: String },
    #[error("{source_name}: has no <worldbody> with a body")]
    NoBody { source_name: String },
    #[error("{source_name}: <{element}> is not supported by the merger ({why})")]
    Unsupported { source_name: String, element: String, why: String },
    #[error("{source_name}: <{element} name=\"{name}\"> appears twice")]
    DuplicateName { source_name: String, element: String, name: String },
    #[error("{source_name}: {element} refers to {what} that the robot does not define")]
    UnknownReference { source_name: String, element: String, what: String },
    #[error("{source_name}: <include file=\"{file}\">: the file was not read (missing or unreadable)")]
    MissingInclude { source_name: String, file: String },
    #[error("{source_name}: <{element}>: {why}")]
    BadValue { source_name: String, element: String, why: String },
    #[error("robot {model}: {why}")]
    Assembly { model: String, why: String },
}
