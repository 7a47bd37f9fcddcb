//! The planner's vocabulary: rooms, robots, colours, sizes, materials, units, counts and
//! filler words, plus every catalog category's names and synonyms.

use std::collections::HashMap;

use sw_plan::{RoomKind, SizeWord};
use sw_robots::RobotKind;

use crate::text::singular;

/// What a (possibly multi-word) lexicon entry means.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Meaning {
    Room(RoomKind),
    /// A room kind that implies racks along both long walls: "warehouse aisle".
    RoomAisle(RoomKind),
    /// "room", "space", "cell": a room of no particular kind.
    RoomWord,
    Category(&'static str),
    Robot(RobotWord),
    Color(&'static str, [f64; 4]),
    Size(SizeWord),
    /// A material word; with a colour when it implies one ("wooden").
    Material(&'static str, Option<[f64; 4]>),
    /// A length unit, in metres.
    Unit(f64),
    /// A count word or quantifier phrase.
    Count(f64),
    /// Words that carry no meaning for the scene.
    Filler,
}

/// A robot name as people write it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RobotWord {
    /// The registry model this name asks for (may not be registered yet).
    pub wants: &'static str,
    pub kind: RobotKind,
    /// The name is exactly the model (no approximation note needed when registered).
    pub exact: bool,
    /// An arm that comes on a mobile base ("mobile manipulator").
    pub on_mobile_base: bool,
}

const fn robot(wants: &'static str, kind: RobotKind, exact: bool) -> Meaning {
    Meaning::Robot(RobotWord { wants, kind, exact, on_mobile_base: false })
}

/// A lexicon entry: its words (singular, lowercase) and meaning.
#[derive(Debug, Clone)]
pub(crate) struct Entry {
    pub words: Vec<String>,
    pub meaning: Meaning,
}

/// The vocabulary, indexed by first word; entries for a first word are longest first.
#[derive(Debug)]
pub(crate) struct Lexicon {
    by_first: HashMap<String, Vec<Entry>>,
}

const ROOMS: &[(&str, RoomKind)] = &[
    ("warehouse", RoomKind::Warehouse),
    ("storage facility", RoomKind::Warehouse),
    ("distribution center", RoomKind::Warehouse),
    ("distribution centre", RoomKind::Warehouse),
    ("fulfillment center", RoomKind::Warehouse),
    ("fulfilment centre", RoomKind::Warehouse),
    ("depot", RoomKind::Warehouse),
    ("stockroom", RoomKind::StorageRoom),
    ("stock room", RoomKind::StorageRoom),
    ("storage room", RoomKind::StorageRoom),
    ("storeroom", RoomKind::StorageRoom),
    ("store room", RoomKind::StorageRoom),
    ("supply room", RoomKind::StorageRoom),
    ("mail room", RoomKind::StorageRoom),
    ("mailroom", RoomKind::StorageRoom),
    ("lab", RoomKind::Lab),
    ("laboratory", RoomKind::Lab),
    ("research lab", RoomKind::Lab),
    ("robotics lab", RoomKind::Lab),
    ("chemistry lab", RoomKind::Lab),
    ("wet lab", RoomKind::Lab),
    ("kitchen", RoomKind::Kitchen),
    ("kitchenette", RoomKind::Kitchen),
    ("commercial kitchen", RoomKind::Kitchen),
    ("office", RoomKind::Office),
    ("open office", RoomKind::Office),
    ("open-plan office", RoomKind::Office),
    ("workshop", RoomKind::Workshop),
    ("machine shop", RoomKind::Workshop),
    ("fabrication shop", RoomKind::Workshop),
    ("fab shop", RoomKind::Workshop),
    ("makerspace", RoomKind::Workshop),
    ("maker space", RoomKind::Workshop),
    ("tool room", RoomKind::Workshop),
    ("shop floor", RoomKind::Workshop),
    ("garage", RoomKind::Garage),
    ("auto shop", RoomKind::Garage),
    ("auto repair shop", RoomKind::Garage),
    ("repair shop", RoomKind::Garage),
    ("service bay", RoomKind::Garage),
    ("clean room", RoomKind::CleanRoom),
    ("cleanroom", RoomKind::CleanRoom),
    ("retail store", RoomKind::RetailStore),
    ("store", RoomKind::RetailStore),
    ("shop", RoomKind::RetailStore),
    ("supermarket", RoomKind::RetailStore),
    ("grocery store", RoomKind::RetailStore),
    ("convenience store", RoomKind::RetailStore),
    ("pharmacy", RoomKind::Pharmacy),
    ("drugstore", RoomKind::Pharmacy),
    ("classroom", RoomKind::Classroom),
    ("class room", RoomKind::Classroom),
    ("lecture room", RoomKind::Classroom),
    ("data centre", RoomKind::DataCentre),
    ("data center", RoomKind::DataCentre),
    ("datacenter", RoomKind::DataCentre),
    ("datacentre", RoomKind::DataCentre),
    ("server room", RoomKind::DataCentre),
    ("server hall", RoomKind::DataCentre),
    ("loading dock", RoomKind::LoadingDock),
    ("loading bay", RoomKind::LoadingDock),
    ("greenhouse", RoomKind::Greenhouse),
    ("glasshouse", RoomKind::Greenhouse),
    ("closet", RoomKind::Closet),
    ("storage closet", RoomKind::Closet),
    ("utility closet", RoomKind::Closet),
    ("pantry", RoomKind::Closet),
    ("factory", RoomKind::Factory),
    ("factory floor", RoomKind::Factory),
    ("manufacturing plant", RoomKind::Factory),
    ("production hall", RoomKind::Factory),
    ("assembly hall", RoomKind::Factory),
    ("assembly line", RoomKind::Factory),
    ("production line", RoomKind::Factory),
    ("hospital", RoomKind::Hospital),
    ("hospital room", RoomKind::Hospital),
    ("clinic", RoomKind::Hospital),
    ("ward", RoomKind::Hospital),
    ("exam room", RoomKind::Hospital),
    ("living room", RoomKind::LivingRoom),
    ("lounge", RoomKind::LivingRoom),
    ("apartment", RoomKind::LivingRoom),
    ("home", RoomKind::LivingRoom),
    ("dining room", RoomKind::LivingRoom),
    ("bedroom", RoomKind::LivingRoom),
    ("bathroom", RoomKind::LivingRoom),
    ("en-suite", RoomKind::LivingRoom),
    ("washroom", RoomKind::LivingRoom),
    ("laundry", RoomKind::LivingRoom),
    ("laundry room", RoomKind::LivingRoom),
    ("utility room", RoomKind::LivingRoom),
    ("nursery", RoomKind::LivingRoom),
    ("dormitory", RoomKind::LivingRoom),
    ("dorm room", RoomKind::LivingRoom),
    ("study", RoomKind::Office),
    ("den", RoomKind::LivingRoom),
    ("hallway", RoomKind::LivingRoom),
    ("attic", RoomKind::StorageRoom),
    ("basement", RoomKind::StorageRoom),
    ("cellar", RoomKind::StorageRoom),
    ("shed", RoomKind::Garage),
    ("workroom", RoomKind::Workshop),
    ("work room", RoomKind::Workshop),
    ("cafe", RoomKind::Kitchen),
    ("café", RoomKind::Kitchen),
    ("coffee shop", RoomKind::Kitchen),
    ("restaurant", RoomKind::Kitchen),
    ("canteen", RoomKind::Kitchen),
    ("cafeteria", RoomKind::Kitchen),
    ("diner", RoomKind::Kitchen),
    ("bakery", RoomKind::Kitchen),
    ("staff room", RoomKind::Kitchen),
    ("break room", RoomKind::Kitchen),
    ("gym", RoomKind::Room),
    ("library", RoomKind::Office),
    ("museum", RoomKind::Room),
    ("gallery", RoomKind::Room),
    ("mezzanine", RoomKind::Warehouse),
    ("tabletop", RoomKind::Tabletop),
    ("table top", RoomKind::Tabletop),
    ("table-top", RoomKind::Tabletop),
];

const ROOM_WORDS: &[&str] = &[
    "room",
    "space",
    "area",
    "hall",
    "cell",
    "work cell",
    "robot cell",
    "workcell",
    "workspace",
    "environment",
    "facility",
    "building",
    "site",
    "floor plan",
    "zone",
];

const ROBOTS: &[(&str, Meaning)] = &[
    ("ur5e", robot("ur5e", RobotKind::Arm, true)),
    ("ur5-e", robot("ur5e", RobotKind::Arm, true)),
    ("ur 5e", robot("ur5e", RobotKind::Arm, true)),
    ("ur5", robot("ur5e", RobotKind::Arm, false)),
    ("ur 5", robot("ur5e", RobotKind::Arm, false)),
    ("ur10", robot("ur10e", RobotKind::Arm, false)),
    ("ur10e", robot("ur10e", RobotKind::Arm, true)),
    ("ur 10", robot("ur10e", RobotKind::Arm, false)),
    ("ur3", robot("ur3e", RobotKind::Arm, false)),
    ("ur3e", robot("ur3e", RobotKind::Arm, true)),
    ("ur16e", robot("ur16e", RobotKind::Arm, true)),
    ("universal robot", robot("ur5e", RobotKind::Arm, false)),
    ("universal robots", robot("ur5e", RobotKind::Arm, false)),
    ("franka", robot("panda", RobotKind::Arm, false)),
    ("panda", robot("panda", RobotKind::Arm, true)),
    ("franka panda", robot("panda", RobotKind::Arm, true)),
    ("franka emika panda", robot("panda", RobotKind::Arm, true)),
    ("franka emika", robot("panda", RobotKind::Arm, false)),
    ("fr3", robot("panda", RobotKind::Arm, false)),
    ("kinova", robot("kinova_gen3", RobotKind::Arm, false)),
    ("kinova gen3", robot("kinova_gen3", RobotKind::Arm, true)),
    ("kinova gen 3", robot("kinova_gen3", RobotKind::Arm, true)),
    ("gen3", robot("kinova_gen3", RobotKind::Arm, false)),
    ("jaco", robot("jaco", RobotKind::Arm, true)),
    ("kinova jaco", robot("jaco", RobotKind::Arm, true)),
    ("iiwa", robot("iiwa", RobotKind::Arm, true)),
    ("kuka iiwa", robot("iiwa", RobotKind::Arm, true)),
    ("kuka", robot("iiwa", RobotKind::Arm, false)),
    ("sawyer", robot("sawyer", RobotKind::Arm, true)),
    ("xarm", robot("xarm7", RobotKind::Arm, false)),
    ("xarm7", robot("xarm7", RobotKind::Arm, true)),
    ("robot arm", robot("ur5e", RobotKind::Arm, false)),
    ("robotic arm", robot("ur5e", RobotKind::Arm, false)),
    ("industrial robot", robot("ur5e", RobotKind::Arm, false)),
    ("industrial arm", robot("ur5e", RobotKind::Arm, false)),
    ("collaborative robot", robot("ur5e", RobotKind::Arm, false)),
    ("cobot", robot("ur5e", RobotKind::Arm, false)),
    ("manipulator", robot("ur5e", RobotKind::Arm, false)),
    ("robot manipulator", robot("ur5e", RobotKind::Arm, false)),
    ("arm", robot("ur5e", RobotKind::Arm, false)),
    ("robot", robot("ur5e", RobotKind::Arm, false)),
    ("turtlebot", robot("turtlebot3", RobotKind::MobileBase, true)),
    ("turtlebot3", robot("turtlebot3", RobotKind::MobileBase, true)),
    ("turtlebot 3", robot("turtlebot3", RobotKind::MobileBase, true)),
    ("turtle bot", robot("turtlebot3", RobotKind::MobileBase, true)),
    ("turtlebot waffle", robot("turtlebot3", RobotKind::MobileBase, true)),
    ("turtlebot burger", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("mobile robot", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("autonomous mobile robot", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("mobile base", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("wheeled robot", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("delivery robot", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("amr", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("agv", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("robot vacuum", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("robot vacuum cleaner", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("robotic vacuum", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("robot hoover", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("robot cleaner", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("roomba", robot("turtlebot3", RobotKind::MobileBase, false)),
    ("fetch robot", robot("mobile_manipulator", RobotKind::MobileManipulator, false)),
    ("tiago", robot("mobile_manipulator", RobotKind::MobileManipulator, false)),
    ("stretch robot", robot("mobile_manipulator", RobotKind::MobileManipulator, false)),
    (
        "mobile manipulator",
        Meaning::Robot(RobotWord {
            wants: "mobile_manipulator",
            kind: RobotKind::MobileManipulator,
            exact: true,
            on_mobile_base: false,
        }),
    ),
];

const COLORS: &[(&str, [f64; 4])] = &[
    ("red", [0.8, 0.12, 0.1, 1.0]),
    ("green", [0.15, 0.6, 0.2, 1.0]),
    ("blue", [0.12, 0.3, 0.8, 1.0]),
    ("yellow", [0.95, 0.8, 0.1, 1.0]),
    ("orange", [0.95, 0.5, 0.1, 1.0]),
    ("purple", [0.5, 0.2, 0.65, 1.0]),
    ("violet", [0.55, 0.3, 0.75, 1.0]),
    ("pink", [0.95, 0.55, 0.7, 1.0]),
    ("brown", [0.45, 0.3, 0.18, 1.0]),
    ("black", [0.08, 0.08, 0.09, 1.0]),
    ("white", [0.94, 0.94, 0.94, 1.0]),
    ("grey", [0.5, 0.5, 0.52, 1.0]),
    ("gray", [0.5, 0.5, 0.52, 1.0]),
    ("silver", [0.75, 0.76, 0.78, 1.0]),
    ("gold", [0.85, 0.68, 0.2, 1.0]),
    ("golden", [0.85, 0.68, 0.2, 1.0]),
    ("beige", [0.85, 0.78, 0.62, 1.0]),
    ("tan", [0.82, 0.7, 0.52, 1.0]),
    ("teal", [0.1, 0.5, 0.5, 1.0]),
    ("cyan", [0.1, 0.75, 0.85, 1.0]),
    ("magenta", [0.8, 0.15, 0.6, 1.0]),
    ("navy", [0.08, 0.12, 0.35, 1.0]),
    ("maroon", [0.45, 0.08, 0.1, 1.0]),
    ("olive", [0.45, 0.45, 0.15, 1.0]),
    ("turquoise", [0.2, 0.75, 0.7, 1.0]),
    ("lime", [0.6, 0.85, 0.2, 1.0]),
    ("cream", [0.96, 0.93, 0.82, 1.0]),
];

const MATERIALS: &[(&str, Option<[f64; 4]>)] = &[
    ("wooden", Some([0.62, 0.45, 0.28, 1.0])),
    ("wood", Some([0.62, 0.45, 0.28, 1.0])),
    ("steel", Some([0.6, 0.62, 0.65, 1.0])),
    ("stainless", Some([0.72, 0.73, 0.75, 1.0])),
    ("stainless steel", Some([0.72, 0.73, 0.75, 1.0])),
    ("metal", Some([0.6, 0.62, 0.65, 1.0])),
    ("metallic", Some([0.6, 0.62, 0.65, 1.0])),
    ("aluminium", Some([0.78, 0.79, 0.8, 1.0])),
    ("aluminum", Some([0.78, 0.79, 0.8, 1.0])),
    ("plastic", None),
    ("glass", None),
    ("concrete", Some([0.62, 0.62, 0.6, 1.0])),
];

const UNITS: &[(&str, f64)] = &[
    ("m", 1.0),
    ("meter", 1.0),
    ("metre", 1.0),
    ("cm", 0.01),
    ("centimeter", 0.01),
    ("centimetre", 0.01),
    ("mm", 0.001),
    ("millimeter", 0.001),
    ("millimetre", 0.001),
    ("ft", 0.3048),
    ("foot", 0.3048),
    ("feet", 0.3048),
    ("inch", 0.0254),
    ("km", 1000.0),
];

const QUANTIFIERS: &[(&str, f64)] = &[
    ("a", 1.0),
    ("an", 1.0),
    ("a single", 1.0),
    ("a pair of", 2.0),
    ("pair of", 2.0),
    ("a couple of", 2.0),
    ("a couple", 2.0),
    ("couple of", 2.0),
    ("a few", 3.0),
    ("few", 3.0),
    ("several", 4.0),
    ("some", 3.0),
    ("multiple", 3.0),
    ("many", 8.0),
    ("numerous", 8.0),
    ("lots of", 8.0),
    ("a lot of", 8.0),
    ("plenty of", 8.0),
    ("a dozen", 12.0),
    ("dozens of", 24.0),
    ("hundreds of", 200.0),
    ("a hundred", 100.0),
];

const FILLERS: &[&str] = &[
    "drives",
    "drive",
    "driving",
    "stands",
    "sits",
    "rests",
    "waits",
    "waiting",
    "parked",
    "runs",
    "running",
    "goes",
    "lies",
    "the",
    "with",
    "and",
    "of",
    "in",
    "inside",
    "within",
    "into",
    "containing",
    "contains",
    "contain",
    "includes",
    "including",
    "include",
    "featuring",
    "features",
    "feature",
    "has",
    "have",
    "having",
    "there",
    "is",
    "are",
    "be",
    "being",
    "that",
    "which",
    "where",
    "for",
    "to",
    "plus",
    "also",
    "as",
    "well",
    "place",
    "put",
    "add",
    "set",
    "arrange",
    "arranged",
    "placed",
    "standing",
    "sitting",
    "positioned",
    "located",
    "situated",
    "surrounded",
    "enclosed",
    "encircled",
    "ringed",
    "equipped",
    "filled",
    "full",
    "stocked",
    "loaded",
    "holding",
    "scene",
    "simulation",
    "setup",
    "set-up",
    "layout",
    "please",
    "make",
    "create",
    "generate",
    "build",
    "design",
    "want",
    "need",
    "i",
    "me",
    "we",
    "our",
    "my",
    "this",
    "these",
    "those",
    "other",
    "another",
    "more",
    "different",
    "various",
    "typical",
    "simple",
    "realistic",
    "modern",
    "busy",
    "clean",
    "industrial",
    "empty",
    "new",
    "old",
    "standard",
    "basic",
    "its",
    "their",
    "it",
    "them",
    "each",
    "every",
    "all",
    "both",
    "at",
    "from",
    "by",
    "on",
    "along",
    "some",
    "any",
    "just",
    "only",
    "very",
    "few",
    "or",
    "one",
    "sized",
    "size",
    "measuring",
    "dimension",
    "dimensions",
    "square",
    "about",
    "around",
    "approximately",
    "roughly",
    "total",
    "type",
    "kind",
    "style",
    "used",
    "like",
    "should",
    "must",
    "can",
    "will",
    "would",
    "could",
    "so",
    "then",
    "while",
    "here",
    "also",
    "too",
    "overall",
    "large-scale",
    "small-scale",
    "your",
    "you",
    "let's",
    "lets",
    "get",
    "give",
    "show",
    "showing",
    "furnished",
    "plain",
    "nice",
    "bright",
    "dark",
    "light",
    "lit",
    "heavy",
    "light-weight",
    "lightweight",
    "mixed",
    "assorted",
    "random",
    "scattered",
    "stacked",
    "lined",
    "lining",
    "mounted",
    "resting",
    "spread",
    "distributed",
    "arrayed",
    "except",
    "who",
    "whose",
    "whom",
    "when",
    "per",
    "not",
    "without",
    "skip",
    "ignore",
    "whole",
    "worth",
    "second",
    "first",
    "third",
    "last",
];

impl Lexicon {
    /// Builds the vocabulary from the fixed tables and the catalog.
    pub fn new() -> Self {
        let mut lex = Lexicon { by_first: HashMap::new() };
        for (w, k) in ROOMS {
            lex.add(w, Meaning::Room(*k));
        }
        lex.add("warehouse aisle", Meaning::RoomAisle(RoomKind::Warehouse));
        lex.add("store aisle", Meaning::RoomAisle(RoomKind::RetailStore));
        lex.add("supermarket aisle", Meaning::RoomAisle(RoomKind::RetailStore));
        for w in ROOM_WORDS {
            lex.add(w, Meaning::RoomWord);
        }
        for (w, m) in ROBOTS {
            lex.add(w, m.clone());
        }
        for cat in sw_catalog::categories() {
            lex.add(cat.display, Meaning::Category(cat.name));
            lex.add(&cat.name.replace('_', " "), Meaning::Category(cat.name));
            for s in cat.synonyms {
                lex.add(s, Meaning::Category(cat.name));
            }
        }
        for (w, c) in COLORS {
            lex.add(w, Meaning::Color(w, *c));
        }
        for r in crate::tables::rows(crate::tables::SIZE_WORDS) {
            if let Some(s) = size_word(r[1]) {
                lex.add(r[0], Meaning::Size(s));
            }
        }
        for (w, c) in MATERIALS {
            lex.add(w, Meaning::Material(w, *c));
        }
        for (w, f) in UNITS {
            lex.add(w, Meaning::Unit(*f));
        }
        for (w, n) in QUANTIFIERS {
            lex.add(w, Meaning::Count(*n));
        }
        for w in FILLERS {
            lex.add(w, Meaning::Filler);
        }
        for list in lex.by_first.values_mut() {
            // Longest first; for equal length, the first added wins (rooms before fillers).
            list.sort_by_key(|e| std::cmp::Reverse(e.words.len()));
        }
        lex
    }

    fn add(&mut self, phrase: &str, meaning: Meaning) {
        let words: Vec<String> = phrase.split_whitespace().map(|w| singular(&w.to_lowercase())).collect();
        let Some(first) = words.first().cloned() else {
            return;
        };
        // The same words may name a thing and a colour ("orange", "lime", a carton's "cream"):
        // both are kept, the thing first, so a head lookup finds the thing and a modifier
        // lookup the colour ("an orange mug"). Any other repeat keeps the first meaning.
        let colour = matches!(meaning, Meaning::Color(..));
        let list = self.by_first.entry(first).or_default();
        if !list.iter().any(|e| e.words == words && matches!(e.meaning, Meaning::Color(..)) == colour) {
            list.push(Entry { words, meaning });
        }
    }

    /// The longest entry matching the words starting at `words[0]`, and its length.
    /// `accept` filters meanings (to look only for heads, only for colours …).
    pub fn longest(&self, words: &[&str], accept: impl Fn(&Meaning) -> bool) -> Option<(&Entry, usize)> {
        let first = words.first()?;
        let key = singular(first);
        for key in [first.to_string(), key] {
            if let Some(list) = self.by_first.get(&key) {
                for e in list {
                    if e.words.len() <= words.len()
                        && e.words.iter().zip(words).all(|(a, b)| *a == *b || *a == singular(b))
                        && accept(&e.meaning)
                    {
                        return Some((e, e.words.len()));
                    }
                }
            }
        }
        None
    }

    /// The words of the vocabulary's phrases of two words or more ("living" of "living
    /// room"), five letters or longer, for reading typos back.
    pub fn phrase_words(&self) -> impl Iterator<Item = String> + '_ {
        self.by_first
            .values()
            .flatten()
            .filter(|e| e.words.len() >= 2 && is_head(&e.meaning))
            .flat_map(|e| e.words.iter().filter(|w| w.len() >= 5).cloned())
    }

    /// Single-word heads (categories, robots, rooms), for typo matching.
    pub fn head_words(&self) -> impl Iterator<Item = (&str, &Meaning)> {
        self.by_first
            .values()
            .flatten()
            .filter(|e| e.words.len() == 1 && is_head(&e.meaning))
            .map(|e| (e.words[0].as_str(), &e.meaning))
    }
}

/// A size word's name in `tables/size_words.tsv`.
fn size_word(name: &str) -> Option<SizeWord> {
    Some(match name {
        "tiny" => SizeWord::Tiny,
        "small" => SizeWord::Small,
        "large" => SizeWord::Large,
        "huge" => SizeWord::Huge,
        "tall" => SizeWord::Tall,
        "short" => SizeWord::Short,
        "long" => SizeWord::Long,
        "wide" => SizeWord::Wide,
        "narrow" => SizeWord::Narrow,
        _ => return None,
    })
}

/// Meanings that can be the head noun of a phrase.
pub(crate) fn is_head(m: &Meaning) -> bool {
    matches!(m, Meaning::Room(_) | Meaning::RoomAisle(_) | Meaning::RoomWord | Meaning::Category(_) | Meaning::Robot(_))
}
