//! The phrase stage: noun phrases read from the tokens — quantity, modifiers (colours,
//! materials, size words, stated dimensions, compound nouns), and the head noun — with
//! what the head is: an object (a catalog category or an unknown noun, a proxy), a robot,
//! a room, or a place (an edge, an end, a wall, a corridor), which is never an object.
//!
//! The head of an English noun phrase is its last noun: in "a robot assembly cell" the
//! head is "cell" (a room), in "a space heater" "heater" (an unknown noun, made a proxy),
//! in "the table edge" "edge" (a place, of the table). A noun before another is a
//! modifier unless the pair is a known compound ("kitchen counter", "desk lamp").

use std::collections::HashMap;
use std::sync::OnceLock;

use sw_plan::{ExplicitSize, NamedColor, RoomKind, SizeWord};

use crate::PlannerError;
use crate::cues::cue_at;
use crate::lexicon::{Lexicon, Meaning, is_head};
use crate::quantity::{Quantity, quantity_at};
use crate::tables::{COMPOUND_MODIFIERS, FUNCTION_NOUNS, FUNCTION_WORDS, PEOPLE, PLACES, rows};
use crate::text::{Token, TokenKind, edit_distance, number_word, singular, typo_distance};

/// What kind of place a place noun names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum PlaceKind {
    Edge,
    End,
    Start,
    Side,
    Corner,
    Middle,
    Wall,
    Door,
    /// A way through: an aisle, a corridor, a route.
    Path,
    Row,
    Front,
    Back,
    Top,
    Bottom,
    Floor,
    Ceiling,
    /// An arrangement's shape: a U, a semicircle, a grid.
    Shape,
    /// A person: people are not modelled.
    Person,
    /// A part of a thing named with it ("a cabinet with three drawers", "its door", "every
    /// level of the rack"): where things go on or in that thing, never an object.
    Part,
}

impl PlaceKind {
    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "edge" => PlaceKind::Edge,
            "end" => PlaceKind::End,
            "start" => PlaceKind::Start,
            "side" => PlaceKind::Side,
            "corner" => PlaceKind::Corner,
            "middle" => PlaceKind::Middle,
            "wall" => PlaceKind::Wall,
            "door" => PlaceKind::Door,
            "path" => PlaceKind::Path,
            "row" => PlaceKind::Row,
            "front" => PlaceKind::Front,
            "back" => PlaceKind::Back,
            "top" => PlaceKind::Top,
            "bottom" => PlaceKind::Bottom,
            "floor" => PlaceKind::Floor,
            "ceiling" => PlaceKind::Ceiling,
            "shape" => PlaceKind::Shape,
            "person" => PlaceKind::Person,
            "part" => PlaceKind::Part,
            _ => return None,
        })
    }
}

fn places() -> &'static HashMap<&'static str, PlaceKind> {
    static P: OnceLock<HashMap<&'static str, PlaceKind>> = OnceLock::new();
    P.get_or_init(|| {
        rows(PLACES)
            .filter_map(|r| Some((r[0], PlaceKind::parse(r[1])?)))
            .chain(rows(PEOPLE).map(|r| (r[0], PlaceKind::Person)))
            .collect()
    })
}

/// A noun that names a part of a thing: always (a drawer) or where the words around it say
/// so (a lid, a shelf).
pub(crate) fn is_part_noun(word: &str) -> bool {
    places().get(word) == Some(&PlaceKind::Part) || context_parts().contains(&word)
}

fn function_nouns() -> &'static [&'static str] {
    static F: OnceLock<Vec<&'static str>> = OnceLock::new();
    F.get_or_init(|| rows(FUNCTION_NOUNS).map(|r| r[0]).collect())
}

/// Nouns that name a part of a thing where the words around them say so (see
/// [`Phrases::part_in_context`]); elsewhere they may be things of their own ("a lid on the
/// counter", "a shelf against the wall").
fn context_parts() -> &'static [&'static str] {
    static C: OnceLock<Vec<&'static str>> = OnceLock::new();
    C.get_or_init(|| rows(crate::tables::PARTS).map(|r| r[0]).collect())
}

/// Verbs of handling things, by their base form: what a robot does to its work ("sorts",
/// "picking", "loads", "tends"). Never a word that is as often a noun or adjective before
/// a noun ("hand", "empty", "clean").
const HANDLING_VERBS: &[&str] = &[
    "pick",
    "place",
    "put",
    "sort",
    "load",
    "unload",
    "pack",
    "unpack",
    "stack",
    "unstack",
    "palletise",
    "palletize",
    "depalletise",
    "depalletize",
    "feed",
    "tend",
    "transfer",
    "insert",
    "grasp",
    "grab",
    "fetch",
    "retrieve",
    "collect",
    "gather",
    "restock",
    "handle",
    "inspect",
    "weld",
    "assemble",
    "move",
    "serve",
    "deliver",
    "tidy",
    "arrange",
    "lift",
    "push",
    "pour",
    "wipe",
    "polish",
    "deburr",
    "screw",
    "take",
    "bring",
    "carry",
    "stir",
    "chop",
    "fold",
    "shelve",
    "drop",
    "deposit",
    "wash",
    "rinse",
    "scrub",
    "pull",
];

/// Whether `w` is a verb of handling in any of its forms but the past participle ("placed
/// on a table" says where a robot stands, not what it does): base, -s / -es / -ies, -ing.
pub(crate) fn is_handling_verb(w: &str) -> bool {
    let known = |stem: &str| HANDLING_VERBS.contains(&stem);
    if known(w) {
        return true;
    }
    if let Some(stem) = w.strip_suffix("ing").filter(|s| s.len() >= 2) {
        let doubled = stem.len() >= 3 && stem.as_bytes()[stem.len() - 1] == stem.as_bytes()[stem.len() - 2];
        return known(stem) || known(&format!("{stem}e")) || (doubled && known(&stem[..stem.len() - 1]));
    }
    if let Some(stem) = w.strip_suffix("ies") {
        return known(&format!("{stem}y"));
    }
    w.strip_suffix("es").is_some_and(known) || w.strip_suffix('s').is_some_and(known)
}

/// Verbs of handling that a base without an arm does too: moving loads about ("brings",
/// "delivering", "carries"), in any of the forms [`is_handling_verb`] takes.
pub(crate) fn is_transport_verb(w: &str) -> bool {
    ["bring", "carry", "carri", "deliver", "move", "mov", "transfer", "take", "tak", "serv", "serve"]
        .iter()
        .any(|stem| w == *stem || w.strip_prefix(stem).is_some_and(|rest| matches!(rest, "s" | "es" | "ies" | "ing")))
}

/// Verbs of operating a thing that are as often adjectives or nouns ("open", "close",
/// "press"): a verb of handling only as a purpose after "to" ("a robot to open the box").
pub(crate) fn is_operating_verb(w: &str) -> bool {
    matches!(
        w,
        "open"
            | "close"
            | "shut"
            | "turn"
            | "switch"
            | "press"
            | "push"
            | "pull"
            | "stand"
            | "empty"
            | "fill"
            | "clean"
            | "wash"
            | "water"
            | "cut"
            | "hang"
            | "plug"
            | "unplug"
            | "flip"
            | "rotate"
            | "slide"
            | "hit"
    )
}

/// Adverbs and particles that end a phrase and are never its noun: "4 m apart", "a mirror
/// above", "the lid off".
pub(crate) fn is_adverb_particle(w: &str) -> bool {
    matches!(
        w,
        "apart"
            | "away"
            | "above"
            | "below"
            | "beneath"
            | "underneath"
            | "overhead"
            | "nearby"
            | "upstairs"
            | "downstairs"
            | "aside"
            | "together"
            | "upright"
            | "open"
            | "ajar"
            | "shut"
            | "closed"
            | "out"
            | "off"
    )
}

fn compound_modifiers() -> &'static [&'static str] {
    static C: OnceLock<Vec<&'static str>> = OnceLock::new();
    C.get_or_init(|| rows(COMPOUND_MODIFIERS).map(|r| r[0]).collect())
}

/// The place a word (or two words) at `i` names, and how many tokens.
pub(crate) fn place_at(toks: &[Token], i: usize) -> Option<(PlaceKind, usize)> {
    let w = |k: usize| toks.get(k).filter(|t| t.kind == TokenKind::Word).map_or("", |t| t.norm.as_str());
    let two = format!("{} {}", w(i), w(i + 1));
    if let Some(k) = places().get(two.as_str()) {
        return Some((*k, 2));
    }
    places().get(w(i)).map(|k| (*k, 1))
}

/// Reads typos of relation and place words back to the word ("betwen" is "between"): a
/// word the vocabulary does not know, of five letters or more, one edit from a word of
/// `tables/function_words.tsv` with the same first letter. Returns a note for each.
pub(crate) fn correct_function_words(lex: &Lexicon, toks: &mut [Token]) -> Vec<sw_plan::Approximation> {
    static WORDS: OnceLock<Vec<&'static str>> = OnceLock::new();
    static PHRASE_WORDS: OnceLock<Vec<String>> = OnceLock::new();
    let words = WORDS.get_or_init(|| rows(FUNCTION_WORDS).map(|r| r[0]).collect());
    // The words of the vocabulary's phrases ("living" of "living room"), which no
    // single-word match reaches: read back only where the phrase then reads whole.
    let phrase_words = PHRASE_WORDS.get_or_init(|| {
        let mut w: Vec<String> = lex.phrase_words().collect();
        w.sort();
        w.dedup();
        w
    });
    let mut notes = Vec::new();
    for i in 0..toks.len() {
        let t = &toks[i];
        if t.kind != TokenKind::Word || t.norm.chars().count() < 5 || cue_at(toks, i).is_some() {
            continue;
        }
        if words.contains(&t.norm.as_str()) || lex.longest(&[t.norm.as_str()], |_| true).is_some() {
            continue;
        }
        let first = t.norm.chars().next();
        // Not another form of the same word ("stack" is no typo of "stacks").
        let near = |w: &str| {
            w.chars().next() == first
                && w.len().abs_diff(t.norm.len()) <= 1
                && singular(w) != singular(&t.norm)
                && typo_distance(&t.norm, w) == 1
        };
        let mut found = words.iter().find(|w| near(w)).map(|w| w.to_string());
        if found.is_none() {
            for w in phrase_words.iter().filter(|w| near(w)) {
                let whole = |from: usize| {
                    let ws: Vec<&str> = toks[from..toks.len().min(from + 4)]
                        .iter()
                        .enumerate()
                        .map(|(k, x)| if from + k == i { w.as_str() } else { x.norm.as_str() })
                        .collect();
                    lex.longest(&ws, is_head).is_some_and(|(_, n)| n >= 2 && from + n > i)
                };
                if whole(i) || (i > 0 && whole(i - 1)) {
                    found = Some(w.clone());
                    break;
                }
            }
        }
        if let Some(w) = found {
            notes.push(sw_plan::Approximation {
                text: toks[i].norm.clone(),
                became: w.clone(),
                reason: format!("read '{}' as '{w}'", toks[i].norm),
            });
            toks[i].norm = w;
        }
    }
    notes
}

/// The head of a noun phrase.
#[derive(Debug, Clone)]
pub(crate) enum Head {
    /// A category, robot or room in the vocabulary.
    Known(Meaning),
    /// A place noun: never an object.
    Place(PlaceKind),
    /// Words with no meaning in the vocabulary: a proxy candidate (singular label).
    Unknown(String),
}

/// A noun phrase: what was counted and said about a head noun.
#[derive(Debug, Clone)]
pub(crate) struct NounPhrase {
    /// Token after the phrase.
    pub end: usize,
    pub count: Option<f64>,
    /// The quantity as read ("several" is not exact; "three more" adds).
    pub quantity: Option<Quantity>,
    pub color: Option<NamedColor>,
    pub sizes: Vec<SizeWord>,
    pub explicit: ExplicitSize,
    /// Words before a known head that are not modelled ("storage" in "storage shelves").
    pub descriptors: Vec<String>,
    /// A room a modifier names ("the kitchen sink").
    pub room_modifier: Option<RoomKind>,
    pub head: Head,
    pub plural: bool,
    pub text: String,
    /// The word as typed, when the head was matched despite a typo or by its last word.
    pub fuzzy_from: Option<String>,
}

/// When a phrase may consist of unknown words with nothing before them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Bare {
    No,
    /// The target of a relation ("on the racks").
    Target,
    /// A plural in a list ("… and mugs on the table").
    PluralInList,
}

/// What the phrase stage reads with: the vocabulary, the tokens and the room named so
/// far (some nouns depend on it: a "rack" is a pallet rack in a warehouse).
pub(crate) struct Phrases<'a> {
    pub lex: &'a Lexicon,
    pub toks: &'a [Token],
    pub text: &'a str,
    pub room: Option<RoomKind>,
}

/// One element of the run of nouns a phrase ends with.
#[derive(Debug, Clone)]
enum Noun {
    Known(Meaning, usize, usize),
    Place(PlaceKind, usize, usize),
    Unknown(usize),
    /// A word that only modifies what follows ("standing" in "a standing fan").
    Modifier(usize),
}

impl Noun {
    fn end(&self) -> usize {
        match self {
            Noun::Known(_, s, l) | Noun::Place(_, s, l) => s + l,
            Noun::Unknown(s) | Noun::Modifier(s) => s + 1,
        }
    }
}

impl Phrases<'_> {
    pub fn word(&self, i: usize) -> &str {
        self.toks.get(i).filter(|t| t.kind == TokenKind::Word).map_or("", |t| t.norm.as_str())
    }

    fn words_from(&self, i: usize) -> Vec<&str> {
        self.toks[i.min(self.toks.len())..]
            .iter()
            .take(6)
            .map_while(|t| {
                (t.kind == TokenKind::Word || matches!(t.kind, TokenKind::Number(_))).then_some(t.norm.as_str())
            })
            .collect()
    }

    pub fn lookup(&self, i: usize, accept: impl Fn(&Meaning) -> bool) -> Option<(Meaning, usize)> {
        let words = self.words_from(i);
        self.lex.longest(&words, accept).map(|(e, n)| (e.meaning.clone(), n))
    }

    pub fn span(&self, from: usize, to: usize) -> String {
        match (self.toks.get(from), self.toks.get(to.saturating_sub(1))) {
            (Some(a), Some(b)) if to > from => self.text[a.start..b.end].to_string(),
            _ => String::new(),
        }
    }

    /// A number followed by an optional unit: (value in metres, tokens used, unit given).
    /// A foot or inch mark counts as a unit: 6' is 1.83 m, 36" is 0.91 m.
    pub fn length_at(&self, i: usize) -> Option<(f64, usize, bool)> {
        let n = self.toks.get(i)?.number()?;
        if let Some(t) = self.toks.get(i + 1)
            && t.kind == TokenKind::Other
            && t.start == self.toks[i].end
        {
            match t.norm.as_str() {
                "'" | "′" | "’" => {
                    // 6'2" is six feet two inches.
                    if let (Some(inch), Some(mark)) =
                        (self.toks.get(i + 2).and_then(Token::number), self.toks.get(i + 3))
                        && matches!(mark.norm.as_str(), "\"" | "″" | "”")
                    {
                        return Some((n * 0.3048 + inch * 0.0254, 4, true));
                    }
                    return Some((n * 0.3048, 2, true));
                }
                "\"" | "″" | "”" => return Some((n * 0.0254, 2, true)),
                _ => {}
            }
        }
        // "36 in wide", "84 in x 40 in": "in" is inches before a dimension word.
        if self.word(i + 1) == "in"
            && (Axis::of(self.word(i + 2)).is_some()
                || self.toks.get(i + 2).is_some_and(|t| t.kind == TokenKind::Times || t.is_word("by")))
        {
            return Some((n * 0.0254, 2, true));
        }
        match self.lookup(i + 1, |m| matches!(m, Meaning::Unit(_))) {
            Some((Meaning::Unit(f), len)) => Some((n * f, 1 + len, true)),
            _ => Some((n, 1, false)),
        }
    }

    /// "2 m tall", "1.5 m wide", "80 cm deep": one explicit dimension.
    pub fn axis_length_at(&self, i: usize) -> Option<(f64, Axis, usize, String)> {
        let (v, len, _) = self.length_at(i)?;
        // "a 2-metre-long bench" is tokenised "2", "metre-long".
        let axis = Axis::of(self.word(i + len))?;
        Some((v, axis, len + 1, self.span(i, i + len + 1)))
    }

    /// A word that is not in the vocabulary at all and does not start a relation cue.
    pub fn is_plain_unknown_word(&self, i: usize) -> bool {
        let Some(t) = self.toks.get(i) else {
            return false;
        };
        if t.kind != TokenKind::Word || number_word(&t.norm).is_some() {
            return false;
        }
        if cue_at(self.toks, i).is_some() || place_at(self.toks, i).is_some() {
            return false;
        }
        self.lookup(i, |_| true).is_none()
    }

    /// A word that can be the head of an unknown noun phrase: not an adverb ("neatly"),
    /// a participle ("leaving") or a past form ("placed").
    fn can_be_noun(&self, i: usize) -> bool {
        let w = self.word(i);
        if is_adverb_particle(w) {
            return false;
        }
        // "-ly" is an adverb ("neatly") unless a noun follows it ("an assembly cell", "a
        // supply cart").
        let adverb = w.ends_with("ly") && self.lookup(i + 1, is_head).is_none();
        !(adverb || w.ends_with("ing") || (w.ends_with("ed") && w.len() > 4))
    }

    /// A word that only modifies the noun after it: a participle or an adjective the
    /// vocabulary does not model ("standing", "folding", "rolling").
    fn is_modifier_word(&self, i: usize) -> bool {
        let w = self.word(i);
        if is_adverb_particle(w) {
            return false;
        }
        let participle = (w.ends_with("ing") && w.len() > 5) || (w.ends_with("ed") && w.len() > 4);
        (participle && cue_at(self.toks, i).is_none()) || compound_modifiers().contains(&w)
    }

    /// A word the vocabulary reads as a verb or filler that ends a phrase and could be its
    /// noun ("can", "stand", "drive").
    fn function_noun_at(&self, k: usize) -> bool {
        self.toks.get(k).is_some_and(|t| t.kind == TokenKind::Word)
            && function_nouns().contains(&self.word(k))
            && cue_at(self.toks, k).is_none()
            && self.boundary(k + 1)
    }

    /// True where a phrase ends: punctuation, a conjunction, "with", a relation cue, a
    /// number, a verb or other vocabulary word that is no noun.
    fn boundary(&self, i: usize) -> bool {
        let Some(t) = self.toks.get(i) else {
            return true;
        };
        if t.kind != TokenKind::Word {
            return true;
        }
        if cue_at(self.toks, i).is_some() || number_word(&t.norm).is_some() {
            return true;
        }
        matches!(self.lookup(i, |_| true), Some((Meaning::Filler | Meaning::Count(_) | Meaning::Unit(_), _)))
    }

    /// A typo-tolerant match of one unknown word against head nouns: the first letter
    /// kept (a typo rarely changes it, and "broom" is no "room"); two letters swapped in
    /// any word of five letters or more ("chiar"), one other edit from six letters
    /// ("toster"), two from eight ("pallette"). A short real word one letter from a known
    /// one ("truck", "trunk"; "booth", "boot") is left alone.
    pub fn fuzzy(&self, word: &str) -> Option<Meaning> {
        let n = word.chars().count();
        let limit = match n {
            0..=4 => return None,
            5..=7 => 1,
            _ => 2,
        };
        let first = word.chars().next()?;
        let mut best: Option<(usize, &str, &Meaning)> = None;
        for (w, m) in self.lex.head_words() {
            if !w.starts_with(first) || w.len().abs_diff(word.len()) > limit {
                continue;
            }
            let d = typo_distance(word, w);
            let swap = d == 1 && w.len() == word.len() && edit_distance(word, w) == 2;
            let allowed = d <= limit && (swap || n >= 6);
            if allowed && best.is_none_or(|(bd, bw, _)| d < bd || (d == bd && w < bw)) {
                best = Some((d, w, m));
            }
        }
        best.map(|(_, _, m)| m.clone())
    }

    /// Whether `word` is a head noun of the same length and first letter with one letter
    /// changed or two swapped ("chiar"): a typo, not a new noun. A letter more or less
    /// makes another word as often as a typo ("balance" / "balancer", "sauce" / "saucer").
    fn near_typo(&self, word: &str) -> bool {
        word.chars().count() >= 5
            && self.lex.head_words().any(|(w, _)| {
                w.chars().next() == word.chars().next() && w.len() == word.len() && typo_distance(word, w) <= 1
            })
    }

    /// The category a noun's category is in the room named so far.
    fn room_sense(&self, cat: &'static str) -> &'static str {
        let Some(room) = self.room else { return cat };
        rows(crate::tables::ROOM_SENSES)
            .find(|r| r[0] == room.name() && r[1] == cat)
            .and_then(|r| sw_catalog::find(r[2]))
            .map_or(cat, |c| c.name)
    }

    /// A catalog category a one-word noun names by the last word of its name: "bench" for
    /// a workbench. "rack" and "workstation" depend on the room: pallet racks and
    /// workbenches in industrial rooms, shelves and desks elsewhere.
    pub fn category_by_head(&self, label: &str) -> Option<&'static str> {
        if label.contains(' ') || label.len() < 4 {
            return None;
        }
        let industrial = self.room.is_some_and(|k| {
            matches!(k, RoomKind::Warehouse | RoomKind::LoadingDock | RoomKind::Factory | RoomKind::StorageRoom)
        });
        if label == "rack" {
            return Some(if industrial { "pallet_rack" } else { "shelf" });
        }
        if matches!(label, "workstation" | "station" | "workplace") {
            let office =
                self.room.is_some_and(|k| matches!(k, RoomKind::Office | RoomKind::Classroom | RoomKind::LivingRoom));
            return Some(if office { "desk" } else { "workbench" });
        }
        sw_catalog::categories().iter().find_map(|c| {
            let last = c.display.split_whitespace().last()?;
            (last != label && last.ends_with(label) && label.len() >= 5).then_some(c.name)
        })
    }

    /// The run of nouns (and noun modifiers) at `k`: at most five.
    fn nouns_at(&self, mut k: usize, after_quantity: bool) -> Vec<Noun> {
        let mut out = Vec::new();
        while out.len() < 5 {
            // "every level of the rack", "its lid", "the shelf of the cabinet": a noun that
            // names a part of a thing, of a thing named or referred to, is that thing's part.
            if out.is_empty()
                && let Some(len) = self.part_in_context(k)
            {
                out.push(Noun::Place(PlaceKind::Part, k, len));
                break;
            }
            // Walls, windows and doors are places even where the catalog has a model of one,
            // unless a longer name begins with them ("a wall clock", "a door mat").
            if let Some((p @ (PlaceKind::Wall | PlaceKind::Door | PlaceKind::Person | PlaceKind::Part), len)) =
                place_at(self.toks, k)
                && self.lookup(k, is_head).is_none_or(|(_, n)| n <= len)
            {
                out.push(Noun::Place(p, k, len));
                k += len;
                continue;
            }
            if let Some((m, len)) = self.lookup(k, is_head) {
                // A robot's model name modifies nothing: "a panda sorts coloured blocks" ends
                // at "panda" (a generic word after it, "UR5e arm", is read with it).
                let model = matches!(&m, Meaning::Robot(w) if w.exact);
                out.push(Noun::Known(m, k, len));
                k += len;
                if model && !matches!(self.lookup(k, is_head), Some((Meaning::Robot(_), _))) {
                    break;
                }
                continue;
            }
            // "on the left" is a place; "a whiteboard right next to" is not.
            let side_word = matches!(self.word(k), "left" | "right");
            if let Some((p, len)) = place_at(self.toks, k).filter(|_| !side_word || out.is_empty()) {
                out.push(Noun::Place(p, k, len));
                k += len;
                // A place modifies only a noun right after it ("a corner desk", "a wall
                // clock"); "one side picking boxes" ends at "side".
                let noun_next =
                    self.lookup(k, is_head).is_some() || (self.is_plain_unknown_word(k) && self.can_be_noun(k));
                if !noun_next {
                    break;
                }
                continue;
            }
            if side_word {
                break;
            }
            // "three cans", "two stands": a counted word the vocabulary reads as a verb is a
            // noun here.
            // So is one after a modifier: "a watering can", "a music stand".
            let counted_function_word = self.function_noun_at(k)
                && ((after_quantity && out.is_empty() && singular(self.word(k)) != self.word(k))
                    || (after_quantity && matches!(out.last(), Some(Noun::Modifier(_) | Noun::Unknown(_)))));
            if (self.is_plain_unknown_word(k) && self.can_be_noun(k)) || counted_function_word {
                out.push(Noun::Unknown(k));
                k += 1;
                continue;
            }
            if self.is_modifier_word(k) && (!self.boundary(k + 1) || (after_quantity && self.function_noun_at(k + 1))) {
                out.push(Noun::Modifier(k));
                k += 1;
                continue;
            }
            break;
        }
        // Trailing modifiers modify nothing.
        while matches!(out.last(), Some(Noun::Modifier(_))) {
            out.pop();
        }
        out
    }

    /// A count, modifiers and a head noun starting at `i`.
    pub fn noun_phrase(&self, i: usize, allow_unknown: bool, bare: Bare) -> Result<Option<NounPhrase>, PlannerError> {
        let mut j = i;
        // A number with a unit is a length ("a 1.2 m table"), never a count.
        let quantity = quantity_at(self.toks, j).filter(|_| !matches!(self.length_at(j), Some((_, _, true))));
        if let Some(q) = quantity {
            j += q.len;
        }
        let count = quantity.map(|q| q.value);
        let mut color = None;
        let mut sizes = Vec::new();
        let mut explicit = ExplicitSize::default();
        let mut fuzzy_from: Option<String> = None;
        loop {
            if let Some((v, axis, len, text)) = self.axis_length_at(j) {
                check_positive(v, &text)?;
                axis.set(&mut explicit, v);
                j += len;
                // "2 m wide, 1 m deep" / "2 m wide and 1 m deep".
                let joined = self.toks.get(j).is_some_and(|t| t.kind == TokenKind::Comma) || self.word(j) == "and";
                if joined && self.axis_length_at(j + 1).is_some() {
                    j += 1;
                }
                continue;
            }
            // "a 4.5 m conveyor", "a 6' bench": a length before the noun is its length.
            if let Some((v, len, true)) = self.length_at(j)
                && !self.toks.get(j + len).is_some_and(|t| t.kind == TokenKind::Times || t.is_word("by"))
                && !self.boundary(j + len)
                && matches!(
                    self.nouns_at(j + len, false).last(),
                    Some(Noun::Known(Meaning::Category(_) | Meaning::Robot(_), ..) | Noun::Unknown(_))
                )
            {
                check_positive(v, &self.span(j, j + len))?;
                explicit.length = Some(v);
                j += len;
                continue;
            }
            // A colour or material word that begins a longer name of another thing is part of
            // it ("cream cheese" is no cream-coloured cheese); before a name of the same thing
            // ("a steel cabinet" is a cabinet) it stays the colour.
            let starts_name = |len: usize| match self.lookup(j, is_head) {
                Some((whole, n)) if n > len => self.lookup(j + len, is_head).is_none_or(|(rest, _)| rest != whole),
                _ => false,
            };
            match self.lookup(j, |m| matches!(m, Meaning::Color(..) | Meaning::Size(_) | Meaning::Material(..))) {
                Some((Meaning::Color(..) | Meaning::Material(..), len)) if starts_name(len) => break,
                Some((Meaning::Color(name, rgba), len)) if !self.boundary_after_modifier(j + len) => {
                    color = Some(NamedColor { name: name.to_string(), rgba });
                    j += len;
                }
                Some((Meaning::Size(s), len)) => {
                    sizes.push(s);
                    j += len;
                }
                Some((Meaning::Material(name, rgba), len)) if !self.boundary_after_modifier(j + len) => {
                    if color.is_none()
                        && let Some(rgba) = rgba
                    {
                        color = Some(NamedColor { name: name.to_string(), rgba });
                    }
                    j += len;
                }
                _ => break,
            }
        }
        let has_modifier = count.is_some() || color.is_some() || !sizes.is_empty() || !explicit.is_empty();
        let nouns = self.nouns_at(j, count.is_some());
        let counted_plural = count.is_some_and(|c| c > 1.0);
        let Some((head, head_at, head_len, mods)) =
            self.pick_head(&nouns, allow_unknown, has_modifier, counted_plural, bare)
        else {
            return Ok(None);
        };
        let mut descriptors = Vec::new();
        let mut room_modifier = None;
        for m in &mods {
            match m {
                Noun::Known(Meaning::Room(k) | Meaning::RoomAisle(k), ..) => room_modifier = Some(*k),
                Noun::Known(_, s, l) | Noun::Place(_, s, l) => descriptors.push(self.span(*s, s + l).to_lowercase()),
                Noun::Unknown(s) | Noun::Modifier(s) => descriptors.push(self.word(*s).to_string()),
            }
        }
        let mut end = head_at + head_len;
        let last = self.word(end - 1).to_string();
        let plural = singular(&last) != last;
        // "a two post lift", "a four burner hob": a number before a run of singular nouns
        // names a kind of the last one; it counts nothing.
        let names_kind = count.is_some_and(|c| c > 1.0)
            && !plural
            && head_at + head_len >= j + 2
            && (j..head_at + head_len).all(|k| singular(self.word(k)) == self.word(k));
        let (count, quantity) = if names_kind { (None, None) } else { (count, quantity) };
        let head = match head {
            Head::Unknown(label) => {
                let words: Vec<&str> = label.split(' ').collect();
                let n = words.len();
                match self.fuzzy(&label) {
                    Some(m) if n == 1 && self.fuzzy_allowed(bare, &nouns) => {
                        fuzzy_from = Some(last.clone());
                        Head::Known(m)
                    }
                    _ => match self.category_by_head(&label) {
                        Some(cat) if n == 1 => {
                            fuzzy_from = Some(last.clone());
                            Head::Known(Meaning::Category(cat))
                        }
                        _ => Head::Unknown(label),
                    },
                }
            }
            // "a bed" in a hospital room is a hospital bed (tables/room_senses.tsv).
            Head::Known(Meaning::Category(cat)) => Head::Known(Meaning::Category(self.room_sense(cat))),
            h => h,
        };
        // "UR5e arm", "TurtleBot robots": absorb the generic word after a robot name.
        if matches!(head, Head::Known(Meaning::Robot(_)))
            && matches!(self.word(end), "arm" | "arms" | "robot" | "robots" | "cobot" | "cobots" | "manipulator")
        {
            end += 1;
        }
        // "a table 2 m long", "a bench (2 m long)".
        while let Some((v, axis, len, text)) = self.axis_length_at(end) {
            check_positive(v, &text)?;
            axis.set(&mut explicit, v);
            end += len;
        }
        let text = self.span(i, end);
        Ok(Some(NounPhrase {
            end,
            count,
            quantity,
            color,
            sizes,
            explicit,
            descriptors,
            room_modifier,
            head,
            plural,
            text,
            fuzzy_from,
        }))
    }

    /// A colour or material word followed by no noun is itself the noun ("an orange").
    fn boundary_after_modifier(&self, i: usize) -> bool {
        self.boundary(i) && self.lookup(i, |m| matches!(m, Meaning::Color(..) | Meaning::Size(_))).is_none()
    }

    fn fuzzy_allowed(&self, _bare: Bare, nouns: &[Noun]) -> bool {
        nouns.len() == 1
    }

    /// The head of a run of nouns and the nouns that modify it: (head, its first token,
    /// its length, modifiers).
    fn pick_head(
        &self,
        nouns: &[Noun],
        allow_unknown: bool,
        has_modifier: bool,
        counted_plural: bool,
        bare: Bare,
    ) -> Option<(Head, usize, usize, Vec<Noun>)> {
        let last_known = nouns.iter().rposition(|n| matches!(n, Noun::Known(..) | Noun::Place(..)));
        let unknown_tail: Vec<usize> = nouns
            .iter()
            .skip(last_known.map_or(0, |k| k + 1))
            .filter_map(|n| match n {
                Noun::Unknown(s) | Noun::Modifier(s) => Some(*s),
                _ => None,
            })
            .collect();
        if let Some(k) = last_known {
            let compound = !unknown_tail.is_empty() && {
                // A known noun that names a kind of what follows ("table saw", "space
                // heater", "bench vice"), where the unknown noun ends the phrase.
                let tail_end = nouns.last().map_or(0, Noun::end);
                let modifier_noun = match &nouns[k] {
                    Noun::Known(Meaning::Room(_) | Meaning::RoomWord | Meaning::RoomAisle(_), ..) => true,
                    // "a robot dispensing system", "a robot lawnmower": the generic word names
                    // a kind of machine, not a robot of the registry.
                    Noun::Known(Meaning::Robot(w), s, l) if !w.exact && self.word(s + l - 1) == "robot" => true,
                    // "a dock leveller", "a wall clock", "a floor lamp".
                    Noun::Place(_, s, l) if singular(self.word(s + l - 1)) == self.word(s + l - 1) => true,
                    Noun::Known(_, s, l) | Noun::Place(_, s, l) => {
                        let w = singular(self.word(s + l - 1));
                        compound_modifiers().contains(&w.as_str())
                            && singular(self.word(s + l - 1)) == self.word(s + l - 1)
                    }
                    _ => false,
                };
                // English compounds are right-headed: a singular known noun before one unknown
                // noun names a kind of it ("tomato sauce", "tyre changer", "fridge magnet"),
                // when the unknown word agrees in number with the phrase's count (after "a
                // mug", "sits" is a verb) and is no typo of a known noun.
                let open_compound = match (&nouns[k], unknown_tail.as_slice()) {
                    (Noun::Known(Meaning::Category(_), s, l), [w]) if k + 2 == nouns.len() => {
                        let modifier = self.word(s + l - 1);
                        let tail = self.word(*w);
                        let tail_plural = singular(tail) != tail;
                        // "a cube out of reach", "the lid off": a particle, not a noun.
                        let particle = matches!(
                            tail,
                            "out"
                                | "up"
                                | "down"
                                | "off"
                                | "away"
                                | "over"
                                | "back"
                                | "aside"
                                | "apart"
                                | "together"
                                | "closer"
                                | "nearer"
                                | "further"
                                | "farther"
                                | "upright"
                                | "open"
                                | "shut"
                                | "closed"
                        );
                        !particle
                            && singular(modifier) == modifier
                            && tail_plural == counted_plural
                            && !self.near_typo(&singular(tail))
                            && matches!(nouns[k + 1], Noun::Unknown(_))
                    }
                    _ => false,
                };
                // A word after the noun followed by a determiner or a count is a verb ("a
                // mobile robot brings a shelf"), not the head of a compound.
                let particle_tail = unknown_tail.iter().any(|s| is_adverb_particle(self.word(*s)));
                (modifier_noun || open_compound)
                    && !particle_tail
                    && allow_unknown
                    && self.boundary(tail_end)
                    && !self.starts_object(tail_end)
            };
            // "the table edge" is a place of the table; "desks back to back" is desks.
            if let (Noun::Place(..), Some(Noun::Known(_, ps, pl))) = (&nouns[k], k.checked_sub(1).map(|p| &nouns[p])) {
                let w = self.word(ps + pl - 1);
                if singular(w) != w
                    && let Noun::Known(m, s, l) = &nouns[k - 1]
                {
                    return Some((Head::Known(m.clone()), *s, *l, nouns[..k - 1].to_vec()));
                }
            }
            // "a robot picks boxes": a robot before an object is the subject of a verb, not a
            // modifier of the object (a robot modifies rooms: "a robot assembly cell").
            if matches!(nouns[k], Noun::Known(Meaning::Category(_), ..))
                && let Some(r) = nouns[..k].iter().position(|n| matches!(n, Noun::Known(Meaning::Robot(_), ..)))
                && let Noun::Known(m, s, l) = &nouns[r]
            {
                return Some((Head::Known(m.clone()), *s, *l, nouns[..r].to_vec()));
            }
            // "a Kinova arm", "the UR5e robot": the model, not the generic word after it.
            if let (Noun::Known(Meaning::Robot(generic), ..), Some(Noun::Known(m @ Meaning::Robot(_), s, _))) =
                (&nouns[k], k.checked_sub(1).map(|p| &nouns[p]))
                && !generic.exact
            {
                let end = nouns[k].end();
                return Some((Head::Known(m.clone()), *s, end - s, nouns[..k - 1].to_vec()));
            }
            if !compound {
                let (head, s, l) = match &nouns[k] {
                    Noun::Known(m, s, l) => (Head::Known(m.clone()), *s, *l),
                    Noun::Place(p, s, l) => (Head::Place(*p), *s, *l),
                    _ => return None,
                };
                return Some((head, s, l, nouns[..k].to_vec()));
            }
            // The compound's words, singular, as the proxy's label.
            let first = match &nouns[k] {
                Noun::Known(_, s, _) | Noun::Place(_, s, _) => *s,
                _ => return None,
            };
            let end = nouns.last().map_or(first, Noun::end);
            let label = self.label(first, end);
            return Some((Head::Unknown(label), first, end - first, nouns[..k].to_vec()));
        }
        // Only unknown words: a proxy, when something marks them as a noun phrase (a count,
        // a modifier, a list or a relation around it, "x2" after it).
        let counted_after = nouns.last().is_some_and(|n| {
            self.toks.get(n.end()).is_some_and(|t| t.kind == TokenKind::Times)
                && self.toks.get(n.end() + 1).is_some_and(|t| t.number().is_some())
        });
        let has_modifier = has_modifier || counted_after;
        if !allow_unknown || !(has_modifier || bare != Bare::No) || unknown_tail.is_empty() {
            return None;
        }
        let first = match nouns.first() {
            Some(Noun::Unknown(s) | Noun::Modifier(s)) => *s,
            _ => return None,
        };
        let end = nouns.last().map_or(first, Noun::end).min(first + 4);
        let last = self.word(end - 1);
        let plural = singular(last) != last;
        // A bare plural in a list ("… and mugs on the table") is an object only when it is
        // short and a relation follows it.
        let known_typo = end - first == 1 && self.fuzzy(&singular(last)).is_some();
        if bare == Bare::PluralInList
            && !has_modifier
            && (!plural || end - first > 2 || (cue_at(self.toks, end).is_none() && !known_typo))
        {
            return None;
        }
        Some((Head::Unknown(self.label(first, end)), first, end - first, Vec::new()))
    }

    /// Whether a determiner, possessive or count starts at `i`: what follows a verb, never
    /// a noun phrase's head.
    fn starts_object(&self, i: usize) -> bool {
        quantity_at(self.toks, i).is_some()
            || matches!(
                self.word(i),
                "the" | "its" | "their" | "these" | "those" | "his" | "her" | "my" | "our" | "your"
            )
    }

    /// A noun at `k` that can name a part of a thing (tables/parts.tsv: a lid, a shelf, a
    /// level) read as that part: after a possessive ("its lid", "their doors"), or before
    /// "of" and a definite phrase ("every level of the rack", "the shelf of the cabinet").
    /// Returns its length in tokens.
    pub(crate) fn part_in_context(&self, k: usize) -> Option<usize> {
        let w = self.word(k);
        if !context_parts().contains(&w) {
            return None;
        }
        // Skip back over modifiers ("its open door", "its top shelf") to the determiner.
        let mut b = k;
        while b > 0 && self.toks[b - 1].kind == TokenKind::Word && b + 3 > k {
            let prev = self.word(b - 1);
            if matches!(prev, "its" | "their" | "his" | "her") {
                return Some(1);
            }
            if matches!(prev, "a" | "an" | "the" | "every" | "each" | "both" | "all" | "one")
                || number_word(prev).is_some()
            {
                break;
            }
            b -= 1;
        }
        let definite_after = matches!(
            self.word(k + 2),
            "the" | "its" | "their" | "this" | "that" | "each" | "every" | "both" | "his" | "her"
        );
        (self.word(k + 1) == "of" && definite_after).then_some(1)
    }

    /// Words `from..to` lowercase, the last singular: a proxy's label.
    fn label(&self, from: usize, to: usize) -> String {
        let mut words: Vec<String> = (from..to).map(|k| self.word(k).to_string()).filter(|w| !w.is_empty()).collect();
        if let Some(last) = words.last_mut() {
            *last = singular(last);
        }
        words.join(" ")
    }
}

fn check_positive(v: f64, text: &str) -> Result<(), PlannerError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(PlannerError::InvalidSize(format!("sizes must be positive lengths, got '{text}'")))
    }
}

/// The axis a dimension word names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Axis {
    /// The longer side on the floor ("long", "length").
    Length,
    Width,
    Depth,
    Height,
    Diameter,
}

impl Axis {
    fn of(word: &str) -> Option<Axis> {
        let w = word.rsplit('-').next().unwrap_or(word);
        Some(match w {
            "tall" | "high" | "height" => Axis::Height,
            "wide" | "width" => Axis::Width,
            "across" | "diameter" => Axis::Diameter,
            "long" | "length" => Axis::Length,
            "deep" | "depth" => Axis::Depth,
            _ => return None,
        })
    }

    /// Records the value; a length is the longer side on the floor, whichever of the
    /// category's axes that is (sorted out where the size reaches the asset).
    pub fn set(self, e: &mut ExplicitSize, v: f64) {
        match self {
            Axis::Length => e.length = Some(v),
            Axis::Width => e.width = Some(v),
            Axis::Diameter => e.diameter = Some(v),
            Axis::Depth => e.depth = Some(v),
            Axis::Height => e.height = Some(v),
        }
    }
}
