//! The scene contract shared by every stage of scenewright.
//!
//! ```text
//! prompt ──L1──▶ ScenePlan ──L2──▶ (assets) ──L3──▶ LaidOutScene ──L4──▶ package ──verify──▶ Report
//! ```
//!
//! [`ScenePlan`], [`LaidOutScene`] and [`Report`] are plain serde types; their JSON Schemas
//! are generated from this code ([`schemas`]) and checked in under `schemas/`. A change to
//! them is a versioned change: bump [`SCHEMA_VERSION`].
//!
//! Units: metres, kilograms, seconds, radians. Z up; the room's floor is centred on the
//! origin; +X east, +Y north.

mod common;
mod layout;
mod plan;
mod report;
mod schema;
mod telemetry;
mod validate;

pub use common::{Corner, Dims, NamedColor, Stage, Wall, Warning};
pub use layout::{
    AnomalyLabel, DoorLayout, LaidOutScene, LeftOut, PlacedObject, PlacedRobot, RoomLayout, Support, Violation,
};
pub use plan::{
    AnomalyKind, AnomalyRequest, Approximation, EndOf, ExplicitSize, Mount, NotUnderstood, ObjectPlan, ProxyPlan,
    Relation, RelationKind, RobotPlan, RoomKind, RoomPlan, ScenePlan, SizeHint, SizeWord, Understanding,
};
pub use report::{
    AssetCache, ContactCheck, DeepContact, ModelStats, MovedBody, RelationCheck, Report, RobotCheck, SceneSummary,
    SettleCheck, SizeCheck, StageTiming, Status, Timings, Verification,
};
pub use schema::{SchemaFile, schemas};
pub use telemetry::{EditLog, EditRecord, LlmCall, LlmOutcome, LlmStage};
pub use validate::{FieldError, MAX_ROBOT_COUNT as MAX_ROBOTS, PlanError, ValidationErrors};

/// The version of the contract types. Written into every document.
pub const SCHEMA_VERSION: u32 = 3;
