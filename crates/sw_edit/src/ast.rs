//! What an edit says, in symbols: operations on objects picked out by references.
//! The offline grammar and the LLM (structured output against [`edit_schema`]) both
//! produce an [`EditCommand`]; neither ever produces coordinates other than the
//! distances the user gave ("1 m to the left").

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use sw_plan::{Corner, Wall};

/// One edit command: one or more operations, applied in order and all or nothing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EditCommand {
    pub ops: Vec<EditOp>,
}

/// One operation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum EditOp {
    /// Remove the objects or robots referred to.
    Remove { target: Reference },
    /// Add what a noun phrase describes ("two red chairs", "a UR5e"), optionally placed.
    Add {
        what: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        place: Option<Placement>,
    },
    /// Move the objects referred to.
    Move { target: Reference, to: Placement },
    /// Replace the objects referred to with what a noun phrase describes, in their place.
    Replace { target: Reference, with: String },
    /// Turn about the vertical axis; positive is counter-clockwise seen from above.
    Rotate { target: Reference, degrees: f64 },
    /// Change the size.
    Resize { target: Reference, resize: Resize },
    /// Change the colour ("red", "dark grey").
    Recolor { target: Reference, color: String },
}

/// Objects (or robots) of the scene, described as a person would.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Reference {
    /// What it is called: a category or label ("chair", "cardboard box", "robot"), an
    /// object's name ("chair_2"), or "" / "one" / "object" for anything.
    pub noun: String,
    /// Every match ("all boxes", "the boxes"); otherwise one object is meant.
    #[serde(default)]
    pub all: bool,
    /// "a chair": any one of them will do.
    #[serde(default)]
    pub any: bool,
    /// "the red one".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<String>,
    /// "the second chair" (in name order); 0 means the last.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ordinal: Option<u32>,
    /// "the chair next to the conveyor".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub anchor: Option<Anchor>,
}

/// Where a referred object is relative to another.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Anchor {
    pub relation: Spatial,
    pub of: Box<Reference>,
}

/// Spatial words. Left and right are as seen from the doorway looking into the room;
/// in front of and behind follow the anchor's own front.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Spatial {
    NextTo,
    LeftOf,
    RightOf,
    InFrontOf,
    Behind,
    On,
    Under,
    Nearest,
    Farthest,
}

/// Where to put something.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Placement {
    /// Beside, or on one side of, an object.
    Beside {
        side: Spatial,
        of: Reference,
    },
    /// On a surface of an object.
    On {
        of: Reference,
    },
    /// Underneath an object.
    Under {
        of: Reference,
    },
    AgainstWall {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        wall: Option<Wall>,
    },
    InCorner {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        corner: Option<Corner>,
    },
    NearDoor,
    InCenter,
    /// A shift, m: along compass directions (east, north) and as seen from the doorway
    /// (right, forward).
    Shift {
        #[serde(default)]
        east: f64,
        #[serde(default)]
        north: f64,
        #[serde(default)]
        right: f64,
        #[serde(default)]
        forward: f64,
    },
}

/// A change of size: factors of width, depth and height, or target dimensions in m.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Resize {
    /// Factors (width, depth, height); `[1.5, 1.5, 1.5]` is "50 % bigger".
    #[serde(default = "unit_scale")]
    pub scale: [f64; 3],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub width: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub depth: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
}

fn unit_scale() -> [f64; 3] {
    [1.0; 3]
}

impl Resize {
    pub fn uniform(f: f64) -> Self {
        Self { scale: [f; 3], width: None, depth: None, height: None }
    }
}

/// The JSON Schema of [`EditCommand`] (for structured output).
pub fn edit_schema() -> serde_json::Value {
    serde_json::to_value(schemars::schema_for!(EditCommand)).unwrap_or_else(|_| serde_json::json!({"type": "object"}))
}

impl Reference {
    pub fn noun(noun: &str) -> Self {
        Self { noun: noun.to_string(), ..Self::default() }
    }

    /// The reference in words ("the red chair next to the conveyor").
    pub fn describe(&self) -> String {
        let mut s = String::new();
        if self.all {
            s.push_str("all ");
        } else if self.any {
            s.push_str("a ");
        } else {
            s.push_str("the ");
        }
        if let Some(k) = self.ordinal {
            s.push_str(&if k == 0 { "last ".to_string() } else { format!("#{k} ") });
        }
        if let Some(c) = &self.color {
            s.push_str(c);
            s.push(' ');
        }
        s.push_str(if self.noun.is_empty() { "object" } else { &self.noun });
        if let Some(a) = &self.anchor {
            s.push(' ');
            s.push_str(a.relation.words());
            s.push(' ');
            s.push_str(&a.of.describe());
        }
        s
    }
}

impl Spatial {
    pub fn words(self) -> &'static str {
        match self {
            Spatial::NextTo => "next to",
            Spatial::LeftOf => "left of",
            Spatial::RightOf => "right of",
            Spatial::InFrontOf => "in front of",
            Spatial::Behind => "behind",
            Spatial::On => "on",
            Spatial::Under => "under",
            Spatial::Nearest => "nearest to",
            Spatial::Farthest => "farthest from",
        }
    }
}
