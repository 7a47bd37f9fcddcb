//! Natural-language edits of a scene package, the pure half: an edit command becomes
//! an [`EditCommand`] — operations (remove, add, move, replace, rotate, resize,
//! recolour) on objects picked out by references ("the chair next to the conveyor",
//! "all boxes", "the red one", "chair_2") — either by the offline [`grammar`] or by a
//! language model ([`llm`]); [`resolve`] finds the objects a reference means in a
//! laid-out scene. Applying an edit (re-solving the layout with everything else pinned,
//! re-verifying in MuJoCo, replacing the package atomically) is the pipeline's job.
//!
//! Why a crate of its own rather than part of `sw_planner`: edits read laid-out scenes
//! (names, poses, supports), not prompts; the planner stays a prompt-to-plan reader, and
//! the two compile in parallel.

mod ast;
pub mod grammar;
pub mod llm;
pub mod resolve;
mod words;

pub use ast::{Anchor, EditCommand, EditOp, Placement, Reference, Resize, Spatial, edit_schema};
pub use grammar::{GrammarError, parse};
pub use resolve::{ResolveError, SceneView, Selection, resolve};
