//! L4, the bridge: turns a laid-out scene and its assets into MJCF.
//!
//! Engine-independent: this crate writes XML and STL; it never links MuJoCo (the
//! verification in `sw_sim` does). The robot merger prefixes every name a robot brings
//! so that several robots, and robots with common names like `base`, coexist.

mod merge;
mod scene;
pub mod xml;

pub use merge::{MergeError, PreparedRobot, prepare_robot};
pub use scene::{BridgeError, MeshFile, RobotInput, SceneFiles, SceneInput, TIMESTEP, write_scene};
