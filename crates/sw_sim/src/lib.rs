//! Verification in real MuJoCo, in-process: the only crate that links the engine.
//!
//! [`verify_file`] loads a package's `scene.xml` from disk exactly as a user would,
//! resets to the `home` keyframe, reports every contact deeper than a threshold between
//! different bodies at t = 0, then settles the scene for a few seconds with robots
//! holding their pose and measures how far each free body moved. [`measure_robot`]
//! measures a robot at its home pose for the registry's keep-out boxes.

mod load;
mod measure;
mod mjx_budget;
mod snapshot;
mod verify;

pub use measure::{BodyBox, measure_robot};
pub use mjx_budget::{ContactBudget, NEAR_M, contact_budget};
pub use snapshot::render_scene;
pub use verify::{VerifyOptions, mujoco_version, verify_file, verify_file_full_load};
