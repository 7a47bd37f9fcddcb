//! What was checked: the verification in real MuJoCo, the warnings of every stage and
//! everything the planner did not understand. `report.json` holds only deterministic
//! facts, so the same prompt and seed give a byte-identical package; wall-clock timings
//! go to `timings.json` ([`Timings`]).

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use std::collections::BTreeMap;

use crate::{Approximation, LeftOut, LlmCall, NotUnderstood, Relation, SCHEMA_VERSION, Stage, Violation, Warning};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Report {
    pub schema_version: u32,
    /// "scenewright <version>".
    pub generator: String,
    pub prompt: String,
    pub seed: u64,
    pub status: Status,
    pub summary: SceneSummary,
    /// Absent only when verification was skipped (`--no-verify`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verification: Option<Verification>,
    pub not_understood: Vec<NotUnderstood>,
    pub approximated: Vec<Approximation>,
    pub left_out: Vec<LeftOut>,
    pub violations: Vec<Violation>,
    /// Every relation the prompt stated (and every arm's reach of its work), measured on
    /// the written scene (read as empty from older reports).
    #[serde(default)]
    pub relations: Vec<RelationCheck>,
    /// Every size the prompt stated ("a 4.5 m conveyor"), measured on the written scene
    /// (read as empty from older reports).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sizes: Vec<SizeCheck>,
    pub warnings: Vec<Warning>,
    /// Every call to a language model the run made (absent for offline runs).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub llm_calls: Vec<LlmCall>,
    /// How L2 came by the object groups' assets (read as zeros from older reports).
    #[serde(default)]
    pub asset_cache: AssetCache,
}

/// How L2 came by each object group's assets, counted in groups: a hit was at hand (the
/// catalog, the asset library by meaning and size, or made earlier in the run); a miss
/// had to be generated (or generation was tried and the group kept its proxy).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AssetCache {
    pub hits: u32,
    pub misses: u32,
}

impl Report {
    pub fn new(prompt: &str, seed: u64, summary: SceneSummary) -> Self {
        Self {
            schema_version: SCHEMA_VERSION,
            generator: format!("scenewright {}", env!("CARGO_PKG_VERSION")),
            prompt: prompt.to_string(),
            seed,
            status: Status::Unverified,
            summary,
            verification: None,
            not_understood: Vec::new(),
            approximated: Vec::new(),
            left_out: Vec::new(),
            violations: Vec::new(),
            relations: Vec::new(),
            sizes: Vec::new(),
            warnings: Vec::new(),
            llm_calls: Vec::new(),
            asset_cache: AssetCache::default(),
        }
    }
}

/// One stated relation and whether it holds in the written scene (`scene.xml` as written:
/// collision geometry, surface sites and robot bases), with the numbers measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct RelationCheck {
    /// The relation as planned: `subject`, `relation` and its targets, wall or corner.
    #[serde(flatten)]
    pub relation: Relation,
    /// The subject's catalog category (object bodies are `<category>_<n>`) or robot model.
    pub subject_category: String,
    /// The targets' categories or robot models, in the relation's order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub target_categories: Vec<String>,
    /// The relation in the prompt's words.
    pub phrase: String,
    pub held: bool,
    /// What was measured, by name: `gap_m`, `angle_deg`, `sides`, `distance_m`, `reach_m` …
    pub measured: BTreeMap<String, f64>,
    /// Why it does not hold (absent when it holds).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// One object group's stated size ([`crate::ExplicitSize`]) and whether every instance
/// has it in the written scene: its collision geometry's extents in its own frame, within
/// 10 % of each stated dimension.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SizeCheck {
    /// The object group.
    pub group: String,
    /// Its words in the prompt.
    pub phrase: String,
    /// What was stated, by dimension: `length_m`, `width_m`, `depth_m`, `height_m`, `diameter_m`.
    pub stated: BTreeMap<String, f64>,
    /// What was measured, by the same names (the instance furthest from the statement).
    pub measured: BTreeMap<String, f64>,
    pub held: bool,
    /// Why it does not hold (absent when it holds).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Compiled and settled in MuJoCo within every threshold.
    Verified,
    /// MuJoCo rejected the scene or a threshold was exceeded; see `verification.failures`.
    Failed,
    /// Verification was skipped on request.
    Unverified,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SceneSummary {
    pub room: String,
    pub room_size: [f64; 3],
    pub objects_requested: u32,
    pub objects_placed: u32,
    pub robots: Vec<String>,
}

/// MuJoCo's verdict on the package.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Verification {
    /// "MuJoCo 3.17.0".
    pub engine: String,
    pub compiled: bool,
    /// The compiler's message when `compiled` is false.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compile_error: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<ModelStats>,
    /// The state checked: the `home` keyframe when the scene has one.
    pub initial_state: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial_contacts: Option<ContactCheck>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub settle: Option<SettleCheck>,
    pub robots: Vec<RobotCheck>,
    pub passed: bool,
    /// One line per failed check.
    pub failures: Vec<String>,
    /// Findings explained by injected anomalies (expected, so they do not fail the scene).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub expected: Vec<String>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ModelStats {
    pub bodies: u32,
    pub geoms: u32,
    pub joints: u32,
    pub actuators: u32,
    pub meshes: u32,
    pub free_bodies: u32,
    pub keyframes: u32,
}

/// Contacts at t = 0 between different bodies deeper than the threshold.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ContactCheck {
    pub threshold_m: f64,
    /// All contacts MuJoCo reported at t = 0.
    pub contacts: u32,
    /// Deepest penetration between different bodies, m (0 when none).
    pub max_depth_m: f64,
    pub deep: Vec<DeepContact>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DeepContact {
    pub body1: String,
    pub body2: String,
    pub depth_m: f64,
}

/// A passive settle: gravity on, robots holding their pose, free bodies watched.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SettleCheck {
    pub duration_s: f64,
    pub timestep_s: f64,
    pub threshold_m: f64,
    /// Largest displacement of any free body, m.
    pub max_displacement_m: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub worst_body: Option<String>,
    /// Free bodies that moved more than the threshold.
    pub moved: Vec<MovedBody>,
    /// MuJoCo raised a numerical warning (NaN, bad QACC, contact overflow …).
    pub unstable: bool,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub engine_warnings: Vec<String>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MovedBody {
    pub body: String,
    pub displacement_m: f64,
}

/// A robot's own checks: contacts with itself or the scene at spawn, joint drift.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RobotCheck {
    pub name: String,
    /// Contacts deeper than the threshold that involve this robot at t = 0.
    pub spawn_contacts: u32,
    /// Largest drift of a hinge or slide joint from its start over the settle, rad or m.
    pub max_joint_drift: f64,
    /// Displacement of the robot's base over the settle (free-floating bases), m.
    pub base_displacement_m: f64,
}

/// Wall-clock time of each stage for one run (not part of the reproducible package).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Timings {
    pub stages: Vec<StageTiming>,
    pub total_ms: f64,
}

impl Timings {
    pub fn get(&self, stage: Stage) -> Option<f64> {
        self.stages.iter().find(|s| s.stage == stage).map(|s| s.ms)
    }
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StageTiming {
    pub stage: Stage,
    pub ms: f64,
}
