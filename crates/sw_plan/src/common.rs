//! Small types shared by the plan, the layout and the report.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// A wall of the room. North is +Y, east is +X.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Wall {
    North,
    South,
    East,
    West,
}

impl Wall {
    pub const ALL: [Wall; 4] = [Wall::North, Wall::South, Wall::East, Wall::West];

    pub fn name(self) -> &'static str {
        match self {
            Wall::North => "north",
            Wall::South => "south",
            Wall::East => "east",
            Wall::West => "west",
        }
    }

    pub fn opposite(self) -> Wall {
        match self {
            Wall::North => Wall::South,
            Wall::South => Wall::North,
            Wall::East => Wall::West,
            Wall::West => Wall::East,
        }
    }

    /// The outward normal of the wall (pointing out of the room).
    pub fn outward(self) -> [f64; 2] {
        match self {
            Wall::North => [0.0, 1.0],
            Wall::South => [0.0, -1.0],
            Wall::East => [1.0, 0.0],
            Wall::West => [-1.0, 0.0],
        }
    }
}

/// A corner of the room.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Corner {
    NorthEast,
    NorthWest,
    SouthEast,
    SouthWest,
}

impl Corner {
    pub const ALL: [Corner; 4] = [Corner::NorthEast, Corner::NorthWest, Corner::SouthEast, Corner::SouthWest];

    /// The snake_case name used in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Corner::NorthEast => "north_east",
            Corner::NorthWest => "north_west",
            Corner::SouthEast => "south_east",
            Corner::SouthWest => "south_west",
        }
    }

    /// The two walls that meet at this corner: (north/south, east/west).
    pub fn walls(self) -> (Wall, Wall) {
        match self {
            Corner::NorthEast => (Wall::North, Wall::East),
            Corner::NorthWest => (Wall::North, Wall::West),
            Corner::SouthEast => (Wall::South, Wall::East),
            Corner::SouthWest => (Wall::South, Wall::West),
        }
    }
}

/// Width (X), depth (Y) and height (Z), in metres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Dims {
    pub width: f64,
    pub depth: f64,
    pub height: f64,
}

impl Dims {
    pub fn new(width: f64, depth: f64, height: f64) -> Self {
        Self { width, depth, height }
    }

    pub fn as_array(&self) -> [f64; 3] {
        [self.width, self.depth, self.height]
    }
}

/// A colour the user asked for, by name, with its RGBA in 0..1.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct NamedColor {
    pub name: String,
    pub rgba: [f64; 4],
}

/// A pipeline stage, for warnings, timings and progress events.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// L1: prompt to plan.
    Plan,
    /// L2: plan objects to assets.
    Forge,
    /// L3: assets to poses.
    Layout,
    /// L4: laid-out scene to MJCF package.
    Bridge,
    /// MuJoCo compile and settle.
    Verify,
}

impl Stage {
    pub const ALL: [Stage; 5] = [Stage::Plan, Stage::Forge, Stage::Layout, Stage::Bridge, Stage::Verify];

    /// The label users see: "L1 plan", …, "verify".
    pub fn label(self) -> &'static str {
        match self {
            Stage::Plan => "L1 plan",
            Stage::Forge => "L2 forge",
            Stage::Layout => "L3 layout",
            Stage::Bridge => "L4 bridge",
            Stage::Verify => "verify",
        }
    }
}

/// Something a stage could only do approximately, or changed from what was asked.
/// Warnings never stop a scene; they are how best-effort results stay honest.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Warning {
    pub stage: Stage,
    /// A stable machine-readable code, e.g. `size_clamped`, `relation_unmet`.
    pub code: String,
    pub message: String,
}

impl Warning {
    pub fn new(stage: Stage, code: &str, message: impl Into<String>) -> Self {
        Self { stage, code: code.to_string(), message: message.into() }
    }
}
