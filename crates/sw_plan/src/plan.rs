//! L1's output: what the user asked for, in symbols. No geometry, no poses.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::{Corner, Dims, NamedColor, SCHEMA_VERSION, Wall};

/// The structured reading of a prompt: the room, the objects with counts and size hints,
/// the relations between them, the robots and how they are mounted, and an honest list
/// of what was not understood or only approximated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ScenePlan {
    pub schema_version: u32,
    /// The prompt as the user typed it (after trimming).
    pub prompt: String,
    pub room: RoomPlan,
    /// Object groups: one entry per phrase ("six cardboard boxes" is one group of 6).
    pub objects: Vec<ObjectPlan>,
    pub relations: Vec<Relation>,
    pub robots: Vec<RobotPlan>,
    /// The industrial rules profile the layout checks (by default the room kind's).
    pub rules_profile: String,
    /// Controlled violations to inject, for anomaly-detection datasets.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub anomaly: Option<AnomalyRequest>,
    pub understanding: Understanding,
}

impl ScenePlan {
    /// An empty plan for `room`, with the room kind's rules profile.
    pub fn new(prompt: &str, room: RoomPlan) -> Self {
        Self {
            schema_version: SCHEMA_VERSION,
            prompt: prompt.to_string(),
            rules_profile: room.kind.rules_profile().to_string(),
            room,
            objects: Vec::new(),
            relations: Vec::new(),
            robots: Vec::new(),
            anomaly: None,
            understanding: Understanding::default(),
        }
    }

    pub fn object(&self, id: &str) -> Option<&ObjectPlan> {
        self.objects.iter().find(|o| o.id == id)
    }

    /// Relations whose subject is the object group `id`.
    pub fn relations_of<'a>(&'a self, id: &'a str) -> impl Iterator<Item = &'a RelationKind> + 'a {
        self.relations.iter().filter(move |r| r.subject == id).map(|r| &r.kind)
    }

    /// Total number of object instances requested.
    pub fn object_count(&self) -> u32 {
        self.objects.iter().map(|o| o.count).sum()
    }

    pub fn robot(&self, id: &str) -> Option<&RobotPlan> {
        self.robots.iter().find(|r| r.id == id)
    }

    /// The words of the prompt behind a group or robot id (its phrase), else the id.
    pub fn phrase_of(&self, id: &str) -> String {
        self.object(id)
            .map(|o| o.phrase.clone())
            .or_else(|| self.robot(id).map(|r| r.phrase.clone()))
            .unwrap_or_else(|| id.to_string())
    }

    /// A relation in the prompt's words, for messages: `"four screens" around "the bench"`.
    pub fn describe(&self, r: &Relation) -> String {
        let subject = format!("\"{}\"", self.phrase_of(&r.subject));
        let detail = match &r.kind {
            RelationKind::AgainstWall { wall: Some(w) } | RelationKind::Leaning { wall: Some(w) } => {
                format!(" ({} wall)", w.name())
            }
            RelationKind::AtEnd { wall: Some(w) } => format!(" ({} end)", w.name()),
            RelationKind::InCorner { corner: Some(c) } => format!(" ({})", c.name()),
            RelationKind::InRows { n: Some(n), m: Some(m) } => format!(" ({n} of {m})"),
            RelationKind::InRows { n: Some(n), .. } => format!(" ({n})"),
            RelationKind::Stacked { stacks: Some(k), n } if *k > 1 => match n {
                Some(n) => format!(" ({k} stacks of {n})"),
                None => format!(" ({k} stacks)"),
            },
            RelationKind::Stacked { n: Some(n), .. } => format!(" ({n} high)"),
            RelationKind::AtEndOf { end: Some(e), .. } => format!(" ({})", e.name()),
            RelationKind::OnOppositeWalls { long: true } => " (the long walls)".to_string(),
            _ => String::new(),
        };
        let targets: Vec<String> = match &r.kind {
            RelationKind::Between { first, second } if first == second => {
                vec![format!("\"{}\"", self.phrase_of(first))]
            }
            RelationKind::Between { first, second } => {
                vec![format!("\"{}\" and \"{}\"", self.phrase_of(first), self.phrase_of(second))]
            }
            k => k.targets().into_iter().map(|t| format!("\"{}\"", self.phrase_of(t))).collect(),
        };
        if targets.is_empty() {
            format!("{subject} {}{detail}", r.kind.words())
        } else {
            format!("{subject} {} {}{detail}", r.kind.words(), targets.join(" "))
        }
    }
}

/// The room: its kind, its size and whether the user fixed that size.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RoomPlan {
    pub kind: RoomKind,
    pub size: Dims,
    /// True when the prompt gave the size; layout may grow a room only when false.
    pub size_fixed: bool,
    /// The wall with the door.
    pub door: Wall,
}

/// Kinds of rooms the planner knows, each with a default size and rules profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RoomKind {
    Warehouse,
    StorageRoom,
    Lab,
    Kitchen,
    Office,
    Workshop,
    Garage,
    CleanRoom,
    RetailStore,
    Pharmacy,
    Classroom,
    DataCentre,
    LoadingDock,
    Greenhouse,
    Closet,
    Factory,
    Hospital,
    LivingRoom,
    /// A small room around a table, for manipulation.
    Tabletop,
    /// No kind was named.
    Room,
}

impl RoomKind {
    pub const ALL: [RoomKind; 20] = [
        RoomKind::Warehouse,
        RoomKind::StorageRoom,
        RoomKind::Lab,
        RoomKind::Kitchen,
        RoomKind::Office,
        RoomKind::Workshop,
        RoomKind::Garage,
        RoomKind::CleanRoom,
        RoomKind::RetailStore,
        RoomKind::Pharmacy,
        RoomKind::Classroom,
        RoomKind::DataCentre,
        RoomKind::LoadingDock,
        RoomKind::Greenhouse,
        RoomKind::Closet,
        RoomKind::Factory,
        RoomKind::Hospital,
        RoomKind::LivingRoom,
        RoomKind::Tabletop,
        RoomKind::Room,
    ];

    /// The snake_case name used in JSON.
    pub fn name(self) -> &'static str {
        match self {
            RoomKind::Warehouse => "warehouse",
            RoomKind::StorageRoom => "storage_room",
            RoomKind::Lab => "lab",
            RoomKind::Kitchen => "kitchen",
            RoomKind::Office => "office",
            RoomKind::Workshop => "workshop",
            RoomKind::Garage => "garage",
            RoomKind::CleanRoom => "clean_room",
            RoomKind::RetailStore => "retail_store",
            RoomKind::Pharmacy => "pharmacy",
            RoomKind::Classroom => "classroom",
            RoomKind::DataCentre => "data_centre",
            RoomKind::LoadingDock => "loading_dock",
            RoomKind::Greenhouse => "greenhouse",
            RoomKind::Closet => "closet",
            RoomKind::Factory => "factory",
            RoomKind::Hospital => "hospital",
            RoomKind::LivingRoom => "living_room",
            RoomKind::Tabletop => "tabletop",
            RoomKind::Room => "room",
        }
    }

    /// A typical size for a room of this kind (width × depth × height, m).
    pub fn default_size(self) -> Dims {
        let (w, d, h) = match self {
            RoomKind::Warehouse => (20.0, 14.0, 6.0),
            RoomKind::StorageRoom => (6.0, 4.0, 3.0),
            RoomKind::Lab => (8.0, 6.0, 3.0),
            RoomKind::Kitchen => (5.0, 4.0, 2.7),
            RoomKind::Office => (8.0, 6.0, 3.0),
            RoomKind::Workshop => (10.0, 8.0, 4.0),
            RoomKind::Garage => (7.0, 6.0, 3.0),
            RoomKind::CleanRoom => (8.0, 6.0, 3.0),
            RoomKind::RetailStore => (12.0, 10.0, 3.5),
            RoomKind::Pharmacy => (8.0, 6.0, 3.0),
            RoomKind::Classroom => (9.0, 7.0, 3.0),
            RoomKind::DataCentre => (12.0, 10.0, 3.5),
            RoomKind::LoadingDock => (16.0, 12.0, 6.0),
            RoomKind::Greenhouse => (10.0, 6.0, 3.5),
            RoomKind::Closet => (2.0, 1.5, 2.4),
            RoomKind::Factory => (30.0, 20.0, 8.0),
            RoomKind::Hospital => (6.0, 5.0, 3.0),
            RoomKind::LivingRoom => (6.0, 5.0, 2.7),
            RoomKind::Tabletop => (4.0, 4.0, 3.0),
            RoomKind::Room => (6.0, 5.0, 3.0),
        };
        Dims::new(w, d, h)
    }

    /// The industrial rules profile that applies by default.
    pub fn rules_profile(self) -> &'static str {
        match self {
            RoomKind::Warehouse | RoomKind::LoadingDock | RoomKind::StorageRoom => "warehouse",
            RoomKind::Workshop | RoomKind::Factory | RoomKind::Garage => "industrial",
            RoomKind::Lab | RoomKind::CleanRoom | RoomKind::Pharmacy | RoomKind::Hospital => "laboratory",
            RoomKind::DataCentre => "data_centre",
            RoomKind::Kitchen => "kitchen",
            RoomKind::RetailStore | RoomKind::Classroom | RoomKind::Office => "commercial",
            RoomKind::Greenhouse => "agricultural",
            RoomKind::Closet | RoomKind::LivingRoom | RoomKind::Tabletop | RoomKind::Room => "general",
        }
    }
}

/// One phrase's worth of objects: a category, a count and what was said about them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ObjectPlan {
    /// Unique within the plan; relations refer to groups by this id.
    pub id: String,
    /// Catalog category, or `proxy` for a labelled stand-in.
    pub category: String,
    /// The words of the prompt this group came from.
    pub phrase: String,
    #[schemars(range(min = 1))]
    pub count: u32,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<NamedColor>,
    #[serde(default, skip_serializing_if = "SizeHint::is_empty")]
    pub size: SizeHint,
    /// Set when no catalog category fits: the stand-in's label and size.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub proxy: Option<ProxyPlan>,
}

/// What the prompt said about an object's size.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SizeHint {
    /// Size words, in the order they were written ("large", "tall").
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub words: Vec<SizeWord>,
    /// Explicit dimensions ("a 2 m tall shelf"), m.
    #[serde(default, skip_serializing_if = "ExplicitSize::is_empty")]
    pub explicit: ExplicitSize,
}

impl SizeHint {
    pub fn is_empty(&self) -> bool {
        self.words.is_empty() && self.explicit.is_empty()
    }
}

/// Explicit dimensions given in the prompt ("a 4.5 m conveyor", "a table 2 m long and
/// 90 cm wide", "a 30 cm bowl"), m; any may be absent. This is how a plan states a size:
/// a field of the object group, not a relation. The forge makes the asset to it and the
/// layout keeps the asset as made; the report measures it on the written collision
/// geometry (`report.json` `sizes`) and the relation judge as the `size` line.
///
/// The axes are the asset's own (front +Y): `width` across the front (X), `depth` front
/// to back (Y), `height` up. `length` is the longer horizontal side, whichever axis that
/// is for the category; when `length` is given, `width` is the other, shorter horizontal
/// side (the English of "2 m long and 90 cm wide"). `diameter` is a round thing's width
/// and depth. [`ExplicitSize::axes`] resolves them.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ExplicitSize {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub width: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub depth: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
    /// The longer horizontal side ("a 4.5 m conveyor", "3 m long").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// A round thing's diameter (its width and depth).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub diameter: Option<f64>,
}

impl ExplicitSize {
    pub fn is_empty(&self) -> bool {
        self.width.is_none()
            && self.depth.is_none()
            && self.height.is_none()
            && self.length.is_none()
            && self.diameter.is_none()
    }

    /// Every stated dimension with its name, in a fixed order.
    pub fn stated(&self) -> Vec<(&'static str, f64)> {
        [
            ("length", self.length),
            ("width", self.width),
            ("depth", self.depth),
            ("height", self.height),
            ("diameter", self.diameter),
        ]
        .into_iter()
        .filter_map(|(n, v)| v.map(|v| (n, v)))
        .collect()
    }

    /// The stated extents along the asset's axes (X across the front, Y front to back, Z
    /// up), given whether the category's longer horizontal side is its X (`x_long`).
    /// `length` takes the long axis; a `width` stated with it takes the other one;
    /// `diameter` takes both; an explicit `depth` wins over what `width` would imply.
    pub fn axes(&self, x_long: bool) -> [Option<f64>; 3] {
        let mut xy = [None, None];
        if let Some(d) = self.diameter {
            xy = [Some(d), Some(d)];
        }
        match self.length {
            Some(l) => {
                let (long, short) = if x_long { (0, 1) } else { (1, 0) };
                xy[long] = Some(l);
                if let Some(w) = self.width {
                    xy[short] = Some(w);
                }
            }
            None => {
                if let Some(w) = self.width {
                    xy[0] = Some(w);
                }
            }
        }
        if let Some(d) = self.depth {
            xy[1] = Some(d);
        }
        [xy[0], xy[1], self.height]
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SizeWord {
    Tiny,
    Small,
    Large,
    Huge,
    Tall,
    Short,
    Long,
    Wide,
    Narrow,
}

impl SizeWord {
    /// Scale factors (width, depth, height) this word applies to a default size.
    pub fn factors(self) -> [f64; 3] {
        match self {
            SizeWord::Tiny => [0.55; 3],
            SizeWord::Small => [0.75; 3],
            SizeWord::Large => [1.3; 3],
            SizeWord::Huge => [1.7; 3],
            SizeWord::Tall => [1.0, 1.0, 1.35],
            SizeWord::Short => [1.0, 1.0, 0.7],
            SizeWord::Long => [1.4, 1.0, 1.0],
            SizeWord::Wide => [1.35, 1.0, 1.0],
            SizeWord::Narrow => [0.7, 1.0, 1.0],
        }
    }
}

/// A stand-in for a noun with no catalog asset: a box of a plausible size, labelled.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ProxyPlan {
    pub label: String,
    /// The size prior used ("tabletop item", "floor object", …).
    pub prior: String,
    pub size: Dims,
    /// True for small items that rest freely (simulated with a free joint).
    pub movable: bool,
}

/// A spatial relation of an object group (or a robot group) to the room or to other
/// groups. Every relation is a constraint the layout keeps; `report.json` says whether it
/// held in the written scene (see [`RelationKind`] for what each one means, measured).
///
/// (serde cannot deny unknown fields on a struct with a flattened enum, so extra fields
/// of a relation are ignored rather than rejected.)
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct Relation {
    /// The group the relation constrains: an object group, or a robot group's id.
    pub subject: String,
    #[serde(flatten)]
    pub kind: RelationKind,
}

/// The relations the planner and the layout understand. The snake_case names are the
/// names in plans, reports and the relation suite (`bench/relations`). Distances are
/// between collision footprints (floor projections of the collision boxes), "front" is
/// an object's +Y axis turned by its yaw, and a group relation holds when it holds for
/// every instance. The measured definitions are in ARCHITECTURE.md ("Relations").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "relation", rename_all = "snake_case")]
pub enum RelationKind {
    /// Resting on a support surface of `target` ("boxes on the shelves").
    On { target: String },
    /// Underneath `target`: footprint centre inside its footprint, top below its top.
    Under { target: String },
    /// Back to a wall (within 0.15 m of it); any wall when `wall` is absent.
    AgainstWall {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        wall: Option<Wall>,
    },
    /// The group spread over two walls, every instance against one of them.
    OnTwoWalls,
    /// Beside `target`: at most 0.6 m between footprints.
    NextTo { target: String },
    /// Near `target`: at most 1.5 m between footprints.
    Near { target: String },
    /// In the gap between instances of two groups (or two instances of one group): the
    /// footprint centre inside the hull of the two footprints and outside both.
    Between { first: String, second: String },
    /// The group's instances stand in one straight row, turned alike.
    InRow,
    /// The group's instances stand in `n` parallel rows (two when absent) of `m` each
    /// when given ("three rows of four desks": n 3, m 4); rows differ by at most one.
    InRows {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        n: Option<u32>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        m: Option<u32>,
    },
    /// Parallel rows with corridors 1.5–3.5 m wide between them, fronts to a corridor.
    InAisles,
    /// Two rows (or a pair) parallel, fronts facing each other across a gap.
    FacingEachOther,
    /// Directly in front of `target`'s front (or a row's front), within 1.5 m.
    InFrontOf { target: String },
    /// Directly behind `target`'s back (or a row's back), within 1.5 m.
    Behind { target: String },
    /// Spread around `target`: on at least three of its sides, leaving an opening.
    Around { target: String },
    /// At the end of `target`'s row: on its line, beyond its last instance.
    AtEndOfRow { target: String },
    /// At one end of the room (the end quarter of its long axis); a specific end when
    /// `wall` is given.
    AtEnd {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        wall: Option<Wall>,
    },
    /// Within 2.5 m of the doorway, clear of it.
    NearDoor,
    /// Within 0.3 m of two walls that meet.
    InCorner {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        corner: Option<Corner>,
    },
    /// In the middle of the room, or down the middle of its long axis for a group.
    #[serde(rename = "in_middle", alias = "in_center")]
    InCenter,
    /// Stacks: each instance resting on the one below, in `stacks` columns (one when
    /// absent) of `n` each (all when absent): "a stack of five pallets", "three stacks of
    /// four crates" (stacks 3, n 4), "boxes stacked two high" (n 2).
    Stacked {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        n: Option<u32>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        stacks: Option<u32>,
    },
    /// Every instance of the subject carries instances of `target` ("pallets of boxes").
    Loaded { target: String },
    /// Every support level of the subject holds instances of `target` ("shelves full of
    /// boxes").
    FullOf { target: String },
    /// Standing on edge against a wall ("tires leaning on the wall").
    Leaning {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        wall: Option<Wall>,
    },
    /// One instance of `target` per instance of the subject, where a person would use it
    /// ("workstations each with a stool": the stool in front of its station).
    EachWith { target: String },
    /// An arm (the subject is a robot group) reaches everything on `target`'s work
    /// surface, or a conveyor's centreline.
    Reach { target: String },
    /// Inside `target`'s interior, resting on an interior support of it: a shelf or
    /// cabinet level, a drawer, the floor of a bin or a box ("cups inside the cabinet").
    Inside { target: String },
    /// Set into a counter run ("a sink in the worktop", "a hob set into the counter"):
    /// its footprint within the target's top, its own top within 5 cm of the target's.
    SetInto { target: String },
    /// Beyond an end of `target`'s long axis, on its line ("a bin at the end of the
    /// bench"); `end`: the target's local −X end (`start`), +X end (`end`), or instances
    /// at both (`both`); either end when absent.
    AtEndOf {
        target: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        end: Option<EndOf>,
    },
    /// Resting on `target` (as `on`) near an edge of its top: the footprint centre within
    /// 0.2 m of an edge ("a lamp on the edge of the desk", an arm on a table's edge).
    OnEdgeOf { target: String },
    /// The group on two opposite sides of `target` ("a chair on either side of the desk",
    /// "flanking the door", "on opposite sides of the bench"), each within 1.5 m of it.
    OnEachSideOf { target: String },
    /// Its front turned towards `target` (within 30°), 0.3–5 m clear of it ("a sofa
    /// facing the TV", "across from the bed").
    Facing { target: String },
    /// Against walls, the group using two opposite walls; the room's two long walls when
    /// `long` ("along both long walls").
    OnOppositeWalls {
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        long: bool,
    },
    /// Each instance in a corner of the room (as `in_corner`), no two in the same one.
    InCorners,
    /// Two rows (or two instances) with their backs to each other, at most 0.3 m apart
    /// ("desks back to back", a double-sided rack run).
    BackToBack,
}

/// Which end of a thing `at_end_of` means.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum EndOf {
    /// The start: the target's local −X end (a conveyor's infeed).
    Start,
    /// The end: its local +X end (a conveyor's outfeed).
    End,
    /// Instances at both ends.
    Both,
}

impl EndOf {
    pub fn name(self) -> &'static str {
        match self {
            EndOf::Start => "start",
            EndOf::End => "end",
            EndOf::Both => "both",
        }
    }
}

impl RelationKind {
    /// Every relation name, in the order of the enum.
    pub const NAMES: [&'static str; 34] = [
        "on",
        "under",
        "against_wall",
        "on_two_walls",
        "next_to",
        "near",
        "between",
        "in_row",
        "in_rows",
        "in_aisles",
        "facing_each_other",
        "in_front_of",
        "behind",
        "around",
        "at_end_of_row",
        "at_end",
        "near_door",
        "in_corner",
        "in_middle",
        "stacked",
        "loaded",
        "full_of",
        "leaning",
        "each_with",
        "reach",
        "inside",
        "set_into",
        "at_end_of",
        "on_edge_of",
        "on_each_side_of",
        "facing",
        "on_opposite_walls",
        "in_corners",
        "back_to_back",
    ];

    /// The groups this relation refers to (besides its subject).
    pub fn targets(&self) -> Vec<&str> {
        match self {
            RelationKind::On { target }
            | RelationKind::Under { target }
            | RelationKind::NextTo { target }
            | RelationKind::Near { target }
            | RelationKind::InFrontOf { target }
            | RelationKind::Behind { target }
            | RelationKind::Around { target }
            | RelationKind::AtEndOfRow { target }
            | RelationKind::Loaded { target }
            | RelationKind::FullOf { target }
            | RelationKind::EachWith { target }
            | RelationKind::Reach { target }
            | RelationKind::Inside { target }
            | RelationKind::SetInto { target }
            | RelationKind::AtEndOf { target, .. }
            | RelationKind::OnEdgeOf { target }
            | RelationKind::OnEachSideOf { target }
            | RelationKind::Facing { target } => vec![target.as_str()],
            RelationKind::Between { first, second } => vec![first.as_str(), second.as_str()],
            RelationKind::AgainstWall { .. }
            | RelationKind::OnTwoWalls
            | RelationKind::InRow
            | RelationKind::InRows { .. }
            | RelationKind::InAisles
            | RelationKind::FacingEachOther
            | RelationKind::AtEnd { .. }
            | RelationKind::NearDoor
            | RelationKind::InCorner { .. }
            | RelationKind::InCenter
            | RelationKind::Stacked { .. }
            | RelationKind::Leaning { .. }
            | RelationKind::OnOppositeWalls { .. }
            | RelationKind::InCorners
            | RelationKind::BackToBack => Vec::new(),
        }
    }

    /// The snake_case name of the relation (as in JSON).
    pub fn name(&self) -> &'static str {
        match self {
            RelationKind::On { .. } => "on",
            RelationKind::Under { .. } => "under",
            RelationKind::AgainstWall { .. } => "against_wall",
            RelationKind::OnTwoWalls => "on_two_walls",
            RelationKind::NextTo { .. } => "next_to",
            RelationKind::Near { .. } => "near",
            RelationKind::Between { .. } => "between",
            RelationKind::InRow => "in_row",
            RelationKind::InRows { .. } => "in_rows",
            RelationKind::InAisles => "in_aisles",
            RelationKind::FacingEachOther => "facing_each_other",
            RelationKind::InFrontOf { .. } => "in_front_of",
            RelationKind::Behind { .. } => "behind",
            RelationKind::Around { .. } => "around",
            RelationKind::AtEndOfRow { .. } => "at_end_of_row",
            RelationKind::AtEnd { .. } => "at_end",
            RelationKind::NearDoor => "near_door",
            RelationKind::InCorner { .. } => "in_corner",
            RelationKind::InCenter => "in_middle",
            RelationKind::Stacked { .. } => "stacked",
            RelationKind::Loaded { .. } => "loaded",
            RelationKind::FullOf { .. } => "full_of",
            RelationKind::Leaning { .. } => "leaning",
            RelationKind::EachWith { .. } => "each_with",
            RelationKind::Reach { .. } => "reach",
            RelationKind::Inside { .. } => "inside",
            RelationKind::SetInto { .. } => "set_into",
            RelationKind::AtEndOf { .. } => "at_end_of",
            RelationKind::OnEdgeOf { .. } => "on_edge_of",
            RelationKind::OnEachSideOf { .. } => "on_each_side_of",
            RelationKind::Facing { .. } => "facing",
            RelationKind::OnOppositeWalls { .. } => "on_opposite_walls",
            RelationKind::InCorners => "in_corners",
            RelationKind::BackToBack => "back_to_back",
        }
    }

    /// The words a prompt uses for the relation, for messages ("around", "next to").
    pub fn words(&self) -> &'static str {
        match self {
            RelationKind::On { .. } => "on",
            RelationKind::Under { .. } => "under",
            RelationKind::AgainstWall { .. } => "against the wall",
            RelationKind::OnTwoWalls => "on two walls",
            RelationKind::NextTo { .. } => "next to",
            RelationKind::Near { .. } => "near",
            RelationKind::Between { .. } => "between",
            RelationKind::InRow => "in a row",
            RelationKind::InRows { .. } => "in rows",
            RelationKind::InAisles => "in aisles",
            RelationKind::FacingEachOther => "facing each other",
            RelationKind::InFrontOf { .. } => "in front of",
            RelationKind::Behind { .. } => "behind",
            RelationKind::Around { .. } => "around",
            RelationKind::AtEndOfRow { .. } => "at the end of",
            RelationKind::AtEnd { .. } => "at one end",
            RelationKind::NearDoor => "near the door",
            RelationKind::InCorner { .. } => "in the corner",
            RelationKind::InCenter => "in the middle",
            RelationKind::Stacked { .. } => "stacked",
            RelationKind::Loaded { .. } => "loaded with",
            RelationKind::FullOf { .. } => "full of",
            RelationKind::Leaning { .. } => "leaning on the wall",
            RelationKind::EachWith { .. } => "each with",
            RelationKind::Reach { .. } => "reaching",
            RelationKind::Inside { .. } => "inside",
            RelationKind::SetInto { .. } => "set into",
            RelationKind::AtEndOf { .. } => "at the end of",
            RelationKind::OnEdgeOf { .. } => "on the edge of",
            RelationKind::OnEachSideOf { .. } => "on each side of",
            RelationKind::Facing { .. } => "facing",
            RelationKind::OnOppositeWalls { .. } => "on opposite walls",
            RelationKind::InCorners => "in the corners",
            RelationKind::BackToBack => "back to back",
        }
    }

    /// Relations that arrange a whole group together (rows, aisles, stacks, walls).
    pub fn is_group_formation(&self) -> bool {
        matches!(
            self,
            RelationKind::InRow
                | RelationKind::InRows { .. }
                | RelationKind::InAisles
                | RelationKind::FacingEachOther
                | RelationKind::OnTwoWalls
                | RelationKind::Stacked { .. }
                | RelationKind::Around { .. }
                | RelationKind::OnOppositeWalls { .. }
                | RelationKind::InCorners
                | RelationKind::BackToBack
                | RelationKind::OnEachSideOf { .. }
        )
    }
}

/// A robot request: which model, how many, and where it is mounted.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RobotPlan {
    /// Unique within the plan.
    pub id: String,
    /// Registry name of the model that will be used (e.g. `ur5e`, `turtlebot3`).
    pub model: String,
    /// The words of the prompt ("a UR5", "two TurtleBots").
    pub phrase: String,
    #[schemars(range(min = 1))]
    pub count: u32,
    pub mount: Mount,
    /// An object group the robot should work next to ("a UR5e next to the conveyor").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub near: Option<String>,
}

/// Where a robot stands.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "mount", rename_all = "snake_case")]
pub enum Mount {
    /// The layout decides: arms on a work surface if there is one, else on a pedestal.
    Auto,
    Floor,
    /// On a surface of the object group `target` (a bench, a table).
    OnSurface {
        target: String,
    },
    Pedestal,
    /// On a mobile cart or base.
    MobileBase,
}

/// Kinds of controlled violations for anomaly datasets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum AnomalyKind {
    Overlap,
    Scale,
    Misplacement,
    Floating,
    RuleViolation,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AnomalyRequest {
    pub kinds: Vec<AnomalyKind>,
    /// Fraction of eligible objects to corrupt, 0..1.
    pub rate: f64,
}

/// What the planner did not understand or only approximated. Nothing is dropped silently.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Understanding {
    #[serde(default)]
    pub not_understood: Vec<NotUnderstood>,
    #[serde(default)]
    pub approximated: Vec<Approximation>,
}

/// Words of the prompt that did not contribute to the plan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct NotUnderstood {
    pub text: String,
    pub reason: String,
}

/// Something that was understood but represented approximately.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Approximation {
    /// The words of the prompt.
    pub text: String,
    /// What they became.
    pub became: String,
    pub reason: String,
}
