//! L3's output: every object and robot with a pose, what it stands on, and what was
//! left out or violated.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::{Dims, RoomKind, SCHEMA_VERSION, Wall, Warning};

/// A solved scene: poses for everything that was placed, and an honest account of the rest.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LaidOutScene {
    pub schema_version: u32,
    pub seed: u64,
    pub room: RoomLayout,
    pub objects: Vec<PlacedObject>,
    pub robots: Vec<PlacedRobot>,
    /// Industrial-rule violations, measured on the final layout.
    pub violations: Vec<Violation>,
    /// Requested objects that could not be placed, and why.
    pub left_out: Vec<LeftOut>,
    /// Labels of injected anomalies (empty unless requested).
    pub anomalies: Vec<AnomalyLabel>,
    pub warnings: Vec<Warning>,
}

impl LaidOutScene {
    pub fn new(seed: u64, room: RoomLayout) -> Self {
        Self {
            schema_version: SCHEMA_VERSION,
            seed,
            room,
            objects: Vec::new(),
            robots: Vec::new(),
            violations: Vec::new(),
            left_out: Vec::new(),
            anomalies: Vec::new(),
            warnings: Vec::new(),
        }
    }

    pub fn object(&self, name: &str) -> Option<&PlacedObject> {
        self.objects.iter().find(|o| o.name == name)
    }
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RoomLayout {
    pub kind: RoomKind,
    /// Inner size of the room, m. The floor spans ±width/2 × ±depth/2.
    pub size: Dims,
    pub wall_thickness: f64,
    pub door: DoorLayout,
}

/// The doorway: a gap in one wall that the layout keeps clear.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DoorLayout {
    pub wall: Wall,
    /// Centre of the doorway along its wall, measured from the wall's midpoint
    /// (along +X for north/south walls, +Y for east/west walls), m.
    pub offset: f64,
    pub width: f64,
    pub height: f64,
}

/// One placed object instance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PlacedObject {
    /// Stable readable name: `<category>_<n>`, also the MJCF body name.
    pub name: String,
    /// The plan group it belongs to.
    pub group: String,
    pub category: String,
    /// What a person would call it ("cardboard box", or a proxy's label).
    pub label: String,
    /// Position of the asset origin (centre of its footprint at its base), m.
    pub pos: [f64; 3],
    /// Rotation about +Z, radians.
    pub yaw: f64,
    /// Extents of the asset's bounding box in its own frame (width, depth, height), m.
    pub size: [f64; 3],
    pub support: Support,
    /// Free body (true) or static fixture (false).
    pub movable: bool,
    /// Mass of a free body, kg.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// The generator seed of the asset (reproducible from category, params and seed).
    pub asset_seed: u64,
    /// Added by `--fill` (furnishing and clutter), not asked for by the prompt.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub added: bool,
}

/// What an object rests on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "on", rename_all = "snake_case")]
pub enum Support {
    Floor,
    /// A named support surface of another object.
    Object {
        object: String,
        surface: String,
    },
    /// Set into or hung on a wall.
    Wall {
        wall: Wall,
    },
}

/// One placed robot.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PlacedRobot {
    /// Instance name; every MJCF name the robot brings is prefixed with `<name>_`.
    pub name: String,
    /// The plan robot group.
    pub group: String,
    /// Registry model name.
    pub model: String,
    /// Position of the robot's base frame, m.
    pub pos: [f64; 3],
    pub yaw: f64,
    /// How it is mounted: `floor`, `surface`, `pedestal`, `mobile_base`.
    pub mount: String,
    /// The object it is mounted on, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mounted_on: Option<String>,
    /// For arms: the fraction of the work surface within reach (0..1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reach_coverage: Option<f64>,
}

/// A measured industrial-rule violation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Violation {
    pub rule: String,
    pub objects: Vec<String>,
    pub measured: f64,
    pub required: f64,
    pub unit: String,
    /// The standard the number comes from, e.g. "NEC 110.26(A)(1)".
    pub standard: String,
    pub message: String,
    /// True when the prompt asked for this violation.
    pub requested: bool,
}

/// Instances of a group that were not placed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LeftOut {
    pub group: String,
    pub category: String,
    pub requested: u32,
    pub placed: u32,
    pub reason: String,
}

/// The exact label of one injected anomaly.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AnomalyLabel {
    /// The corrupted object.
    pub object: String,
    pub kind: crate::AnomalyKind,
    /// Penetration depth (overlap, rule violation), height (floating), distance moved
    /// (misplacement) or scale factor (scale).
    pub magnitude: f64,
    /// `m` or `x` (a factor).
    pub unit: String,
    /// The other object involved (the one overlapped, the equipment whose space is taken).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub with: Option<String>,
    /// What was done, in words.
    pub description: String,
}
