//! Relation cues: the fixed phrases that introduce a spatial relation ("against the north
//! wall", "on top of", "in a row", "facing each other").

use sw_plan::{Corner, Wall};

use crate::text::{Token, TokenKind};

/// A relation phrase, without its target object (parsed separately).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Cue {
    On,
    Under,
    NextTo,
    InFront,
    Between,
    Around,
    Row,
    Facing,
    End(Option<Wall>),
    Corner(Option<Corner>),
    Center,
    Door,
    Wall(Option<Wall>),
    Floor,
}

impl Cue {
    /// Cues that need a target object after them.
    pub fn takes_target(&self) -> bool {
        matches!(self, Cue::On | Cue::Under | Cue::NextTo | Cue::InFront | Cue::Between | Cue::Around)
    }
}

fn words_at(toks: &[Token], i: usize, n: usize) -> Vec<&str> {
    toks[i..(i + n).min(toks.len())]
        .iter()
        .map(|t| if t.kind == TokenKind::Word { t.norm.as_str() } else { "" })
        .collect()
}

fn starts_with(toks: &[Token], i: usize, phrase: &str) -> Option<usize> {
    let want: Vec<&str> = phrase.split(' ').collect();
    let got = words_at(toks, i, want.len());
    (got == want).then_some(want.len())
}

/// The first of `phrases` that starts at `i`, longest first, and its length.
fn any_of(toks: &[Token], i: usize, phrases: &[&str]) -> Option<usize> {
    let mut best = None;
    for p in phrases {
        if let Some(n) = starts_with(toks, i, p) {
            best = Some(best.map_or(n, |b: usize| b.max(n)));
        }
    }
    best
}

const DETERMINERS: &[&str] =
    &["the", "a", "an", "one", "each", "every", "both", "either", "its", "their", "this", "that"];

fn skip_determiners(toks: &[Token], mut j: usize) -> usize {
    while toks.get(j).is_some_and(|t| t.kind == TokenKind::Word && DETERMINERS.contains(&t.norm.as_str())) {
        j += 1;
    }
    j
}

/// Direction words in a wall or end phrase: north/south/east/west and back/front/left/right.
fn wall_word(w: &str) -> Option<Option<Wall>> {
    Some(match w {
        "north" | "northern" | "back" | "rear" | "far" => Some(Wall::North),
        "south" | "southern" | "front" | "near" => Some(Wall::South),
        "east" | "eastern" | "right" | "right-hand" => Some(Wall::East),
        "west" | "western" | "left" | "left-hand" => Some(Wall::West),
        "side" | "long" | "short" | "opposite" | "two" | "both" | "outer" | "perimeter" => None,
        _ => return None,
    })
}

fn corner_word(a: Option<Wall>, b: Option<Wall>) -> Option<Corner> {
    use Wall::*;
    match (a?, b?) {
        (North, East) | (East, North) => Some(Corner::NorthEast),
        (North, West) | (West, North) => Some(Corner::NorthWest),
        (South, East) | (East, South) => Some(Corner::SouthEast),
        (South, West) | (West, South) => Some(Corner::SouthWest),
        _ => None,
    }
}

fn compass_corner(w: &str) -> Option<Corner> {
    match w {
        "northeast" | "north-east" | "ne" => Some(Corner::NorthEast),
        "northwest" | "north-west" | "nw" => Some(Corner::NorthWest),
        "southeast" | "south-east" | "se" => Some(Corner::SouthEast),
        "southwest" | "south-west" | "sw" => Some(Corner::SouthWest),
        _ => None,
    }
}

/// Recognises a relation cue at token `i`: the cue and how many tokens it spans.
pub(crate) fn cue_at(toks: &[Token], i: usize) -> Option<(Cue, usize)> {
    let t = toks.get(i)?;
    if t.kind != TokenKind::Word {
        return None;
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "facing each other",
            "face to face",
            "facing one another",
            "opposite each other",
            "opposite one another",
            "across from each other",
            "on opposite sides",
            "on both sides",
            "on either side",
            "across the aisle",
            "on both sides of the aisle",
            "on either side of the aisle",
            "facing across the aisle",
        ],
    ) {
        return Some((Cue::Facing, n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "in a row",
            "in rows",
            "in a line",
            "in lines",
            "in a straight line",
            "lined up",
            "side by side",
            "in a column",
            "in columns",
            "in parallel rows",
            "in aisles",
            "in a single row",
            "in one row",
            "in two rows",
            "in three rows",
            "in four rows",
            "in a grid",
            "in a neat row",
            "all in a row",
        ],
    ) {
        return Some((Cue::Row, n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "in the middle",
            "in the center",
            "in the centre",
            "in the middle of the room",
            "in the center of the room",
            "in the centre of the room",
            "at the center",
            "at the centre",
            "centered",
            "centred",
            "in the middle of the floor",
        ],
    ) {
        return Some((Cue::Center, n));
    }
    // Corners: "in the corner", "in the far left corner", "in the northeast corner".
    if matches!(t.norm.as_str(), "in" | "into" | "at") {
        let mut j = skip_determiners(toks, i + 1);
        let mut dirs = Vec::new();
        let mut compass = None;
        while let Some(w) = toks.get(j).filter(|t| t.kind == TokenKind::Word) {
            if let Some(c) = compass_corner(&w.norm) {
                compass = Some(c);
            } else if let Some(d) = wall_word(&w.norm) {
                dirs.push(d);
            } else {
                break;
            }
            j += 1;
        }
        if toks.get(j).is_some_and(|w| w.norm == "corner" || w.norm == "corners") {
            let corner = compass.or_else(|| match dirs.as_slice() {
                [a, b] => corner_word(*a, *b),
                [Some(Wall::North)] => Some(Corner::NorthEast),
                _ => None,
            });
            return Some((Cue::Corner(corner), j + 1 - i));
        }
    }
    // Ends: "at one end", "at the far end", "at the north end".
    if t.norm == "at" {
        let mut j = skip_determiners(toks, i + 1);
        let mut wall = None;
        if let Some(d) = toks.get(j).and_then(|w| wall_word(&w.norm)) {
            wall = d;
            j += 1;
        }
        if toks.get(j).is_some_and(|w| w.norm == "end") {
            return Some((Cue::End(wall), j + 1 - i));
        }
        if let Some(n) = any_of(toks, i, &["at the back", "at the rear"]) {
            return Some((Cue::End(Some(Wall::North)), n));
        }
        if let Some(n) = any_of(toks, i, &["at the front"]) {
            return Some((Cue::End(Some(Wall::South)), n));
        }
    }
    // Walls and doors after a preposition.
    let preps = [
        "against",
        "along",
        "alongside",
        "lining",
        "on",
        "by",
        "near",
        "beside",
        "next to",
        "close to",
        "adjacent to",
        "at",
        "facing",
        "to",
    ];
    if let Some(n) = any_of(toks, i, &preps) {
        let mut j = skip_determiners(toks, i + n);
        let mut wall = None;
        let mut any_dir = false;
        while let Some(d) = toks.get(j).and_then(|w| wall_word(&w.norm)) {
            if d.is_some() {
                wall = d;
            }
            any_dir = true;
            j += 1;
        }
        if toks.get(j).is_some_and(|w| w.norm == "wall" || w.norm == "walls" || w.norm == "wall's") {
            return Some((Cue::Wall(wall), j + 1 - i));
        }
        if !any_dir
            && toks.get(j).is_some_and(|w| {
                matches!(w.norm.as_str(), "door" | "doorway" | "entrance" | "entry" | "exit" | "doors")
            })
            && !matches!(t.norm.as_str(), "on" | "against")
        {
            return Some((Cue::Door, j + 1 - i));
        }
        if !any_dir
            && matches!(t.norm.as_str(), "on")
            && toks.get(j).is_some_and(|w| w.norm == "floor" || w.norm == "ground")
        {
            return Some((Cue::Floor, j + 1 - i));
        }
    }
    if let Some(n) =
        any_of(toks, i, &["in front of", "right in front of", "directly in front of", "just in front of", "facing"])
    {
        return Some((Cue::InFront, n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "on top of",
            "on",
            "onto",
            "atop",
            "upon",
            "resting on",
            "sitting on",
            "stacked on",
            "placed on",
            "mounted on",
            "standing on",
            "installed on",
            "sits on",
            "sit on",
            "rests on",
            "bolted to",
            "mounted to",
            "fixed to",
            "attached to",
            "on each of",
            "stacked atop",
        ],
    ) {
        // "stacked on top of the pallet": the verb and "on" met first.
        let n = if starts_with(toks, i + n, "top of").is_some() { n + 2 } else { n };
        return Some((Cue::On, n));
    }
    if let Some(n) = any_of(toks, i, &["under", "underneath", "beneath", "below"]) {
        return Some((Cue::Under, n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "next to",
            "beside",
            "besides",
            "by",
            "near",
            "nearby",
            "alongside",
            "close to",
            "adjacent to",
            "to the left of",
            "to the right of",
            "left of",
            "right of",
            "behind",
            "near to",
            "right next to",
            "right beside",
            "closest to",
        ],
    ) {
        return Some((Cue::NextTo, n));
    }
    if t.norm == "between" {
        return Some((Cue::Between, 1));
    }
    if matches!(t.norm.as_str(), "around" | "surrounding" | "encircling" | "round") {
        // "around 20 boxes" means about twenty.
        if toks.get(i + 1).is_some_and(|n| matches!(n.kind, TokenKind::Number(_))) {
            return None;
        }
        return Some((Cue::Around, 1));
    }
    None
}

/// Skips determiners after a cue, returning the index of the target's first word.
pub(crate) fn target_start(toks: &[Token], j: usize) -> usize {
    skip_determiners(toks, j)
}
