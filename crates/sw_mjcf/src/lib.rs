//! L4, the bridge: turns a laid-out scene and its assets into MJCF.
//!
//! Engine-independent: this crate writes XML and STL; it never links MuJoCo (the
//! verification in `sw_sim` does) and reads no files (robot files are given to it as
//! text; the files their meshes live in are returned as a list to copy). The robot merger
//! prefixes every name a robot brings so that several robots, and robots with common names
//! like `base`, coexist; the URDF importer turns a URDF robot into MJCF the merger takes.

mod files;
mod merge;
mod normalize;
pub mod physics;
mod robot;
mod scene;
mod urdf;
pub mod xml;

pub use merge::prepare_robot;
pub use physics::PhysicsTarget;
pub use robot::{MergeError, PartFixes, PreparedRobot, RobotFile, RobotPart, RobotSource, ServoGains};
pub use scene::{BridgeError, MeshFile, RobotInput, SceneFiles, SceneInput, TIMESTEP, robot_document, write_scene};
pub use urdf::{UrdfError, UrdfImport, urdf_to_mjcf};
