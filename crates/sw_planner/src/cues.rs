//! Relation cues: the fixed phrases that introduce a spatial relation ("against the north
//! wall", "on top of", "in a row", "facing each other").

use sw_plan::{Corner, EndOf, Wall};

use crate::text::{Token, TokenKind};

/// A relation phrase, without its target object (parsed separately).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Cue {
    On,
    Under,
    NextTo,
    Near,
    InFront,
    Behind,
    Between,
    Around,
    Row,
    /// "in two rows" (`Some(2)`), "in rows" / "in a grid" (`None`: as many as suit).
    Rows(Option<u32>),
    /// "in 4 rows of 5": rows and members per row.
    RowsOf(u32, u32),
    Aisles,
    Facing,
    End(Option<Wall>),
    /// "at the end of": the row (or group) named next.
    EndOf(Option<EndOf>),
    Corner(Option<Corner>),
    Center,
    Door,
    Wall(Option<Wall>),
    TwoWalls,
    /// "on opposite walls", "along both long walls".
    OppositeWalls {
        long: bool,
        /// "each long wall", "both side walls", "either wall": one of the thing per wall
        /// when the thing is said once ("one bench along each long wall" is two benches).
        per_wall: bool,
    },
    /// "in the corners", "in each corner", "in two corners": no two in one corner; the
    /// number of corners when said ("each" is four).
    Corners(Option<u32>),
    /// "back to back".
    BackToBack,
    Leaning(Option<Wall>),
    Stacked,
    /// "picking from", "tending", "working at", "at": an arm works at the target.
    Tend,
    Floor,
    /// "in the sink", "inside the cabinet", "into the tray": within the target.
    In,
    /// "on either side of", "flanking": one on each of two opposite sides of the target.
    EachSide,
    /// "opposite the sofa", "across from the desk", "facing the TV".
    FacingTarget,
    /// "above the sink", "over the desk".
    Above,
    /// "on the edge of the table" (read from a place noun, not a cue phrase).
    OnEdge,
}

impl Cue {
    /// Cues that need a target object after them.
    pub fn takes_target(&self) -> bool {
        matches!(
            self,
            Cue::On
                | Cue::Under
                | Cue::NextTo
                | Cue::Near
                | Cue::InFront
                | Cue::Behind
                | Cue::Between
                | Cue::Around
                | Cue::EndOf(_)
                | Cue::Tend
                | Cue::In
                | Cue::EachSide
                | Cue::FacingTarget
                | Cue::Above
                | Cue::OnEdge
        )
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

const DETERMINERS: &[&str] = &[
    "the",
    "a",
    "an",
    "one",
    "each",
    "every",
    "both",
    "either",
    "its",
    "their",
    "this",
    "that",
    "other",
    "first",
    "second",
    "third",
    "fourth",
    "last",
    "same",
    "remaining",
    "nearest",
    "closest",
];

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
            "on either side of",
            "on each side of",
            "on both sides of",
            "on opposite sides of",
            "at either side of",
            "at each side of",
            "at both sides of",
            "at either end of",
            "either side of",
            "each side of",
            "both sides of",
            "to either side of",
            "flanking",
        ],
    ) {
        return Some((Cue::EachSide, n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "facing each other",
            "face each other",
            "face one another",
            "face to face",
            "facing one another",
            "opposite each other",
            "opposite one another",
            "across from each other",
            "on opposite sides",
            "on both sides",
            "on either side",
            "on each side",
            "at each side",
            "at either side",
            "each side",
            "either side",
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
            "in aisles",
            "in parallel aisles",
            "forming aisles",
            "forming an aisle",
            "with aisles between them",
            "with an aisle between them",
            "with aisles in between",
            "with an aisle in between",
            "in two aisles",
            "in three aisles",
            "lined up in aisles",
        ],
    ) {
        return Some((Cue::Aisles, n));
    }
    let rows_n: &[(&str, Option<u32>)] = &[
        ("in rows", None),
        ("in parallel rows", None),
        ("in lines", None),
        ("in columns", None),
        ("in a grid", None),
        ("in a grid pattern", None),
        ("in neat rows", None),
        ("in two rows", Some(2)),
        ("in two lines", Some(2)),
        ("in two parallel rows", Some(2)),
        ("in three rows", Some(3)),
        ("in three lines", Some(3)),
        ("in four rows", Some(4)),
        ("in five rows", Some(5)),
        ("in six rows", Some(6)),
    ];
    let mut best: Option<(usize, Option<u32>)> = None;
    for (p, k) in rows_n {
        if let Some(n) = starts_with(toks, i, p)
            && best.is_none_or(|(b, _)| n > b)
        {
            best = Some((n, *k));
        }
    }
    // "in 3 rows"
    if t.norm == "in"
        && let Some(k) = toks.get(i + 1).and_then(|x| x.number())
        && toks.get(i + 2).is_some_and(|w| matches!(w.norm.as_str(), "rows" | "lines" | "columns"))
        && (1.0..=50.0).contains(&k)
    {
        best = Some((3, Some(k.round() as u32)));
    }
    if let Some((n, k)) = best {
        return Some((Cue::Rows(k), n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "in a row",
            "in a line",
            "in a straight line",
            "lined up",
            "side by side",
            "in a column",
            "in a single row",
            "in one row",
            "in a single line",
            "in one line",
            "in a neat row",
            "all in a row",
            "in a long row",
            "in a straight row",
            "lined up in a row",
        ],
    ) {
        return Some((Cue::Row, n));
    }
    // Stacks: "stacked", "in a stack", "stacked on top of each other", "stacked 5 high".
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "stacked on top of each other",
            "stacked on top of one another",
            "stacked one on top of another",
            "stacked one on top of the other",
            "piled on top of each other",
            "stacked up",
            "in a stack",
            "in a single stack",
            "in one stack",
            "in a pile",
            "piled up",
        ],
    ) {
        return Some((Cue::Stacked, n));
    }
    if matches!(t.norm.as_str(), "stacked" | "piled") {
        // "stacked on the pallet" is a support; "stacked 5 high" a stack.
        let next = toks.get(i + 1).map(|x| x.norm.as_str()).unwrap_or("");
        if !matches!(next, "on" | "onto" | "atop" | "upon" | "in" | "against" | "along" | "by" | "next" | "beside") {
            let mut n = 1;
            if toks.get(i + 1).is_some_and(|x| x.number().is_some() || crate::text::number_word(&x.norm).is_some())
                && toks.get(i + 2).is_some_and(|x| matches!(x.norm.as_str(), "high" | "tall" | "deep"))
            {
                n = 3;
            }
            return Some((Cue::Stacked, n));
        }
    }
    // Leaning: "leaning on the wall", "propped against the north wall".
    if matches!(t.norm.as_str(), "leaning" | "leaned" | "leant" | "propped" | "leans" | "lean")
        && toks.get(i + 1).is_some_and(|x| matches!(x.norm.as_str(), "on" | "against" | "up"))
    {
        let mut j = i + 1;
        if toks.get(j).is_some_and(|x| x.norm == "up") {
            j += 1;
        }
        if toks.get(j).is_some_and(|x| matches!(x.norm.as_str(), "on" | "against")) {
            j = skip_determiners(toks, j + 1);
            let mut wall = None;
            while let Some(d) = toks.get(j).and_then(|w| wall_word(&w.norm)) {
                if d.is_some() {
                    wall = d;
                }
                j += 1;
            }
            if toks.get(j).is_some_and(|w| w.norm == "wall" || w.norm == "walls") {
                return Some((Cue::Leaning(wall), j + 1 - i));
            }
        }
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "down the middle",
            "down the centre",
            "down the center",
            "along the middle",
            "along the centre line",
            "along the center line",
            "down the middle of the room",
            "down the centre of the room",
            "down the center of the room",
        ],
    ) {
        return Some((Cue::Center, n));
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
        // "in the middle of the table" is on the table: the place of a thing, read with it.
        let of_thing = toks.get(i + n).is_some_and(|w| w.norm == "of");
        if !of_thing {
            return Some((Cue::Center, n));
        }
    }
    // Corners: "in the corner", "in the far left corner", "in the northeast corner".
    if matches!(t.norm.as_str(), "in" | "into" | "at") {
        let mut j = skip_determiners(toks, i + 1);
        // "in all four corners", "in two corners".
        while toks.get(j).is_some_and(|w| {
            matches!(w.norm.as_str(), "all" | "two" | "three" | "four" | "different" | "separate" | "opposite")
        }) {
            j += 1;
        }
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
        let several = toks[i + 1..j.min(toks.len())].iter().any(|w| {
            matches!(
                w.norm.as_str(),
                "each" | "every" | "all" | "two" | "three" | "four" | "both" | "different" | "separate"
            )
        });
        if toks.get(j).is_some_and(|w| w.norm == "corners")
            || (several && toks.get(j).is_some_and(|w| w.norm == "corner"))
        {
            let n = toks[i + 1..j].iter().find_map(|w| match w.norm.as_str() {
                "each" | "every" | "all" | "four" => Some(4),
                "two" | "both" => Some(2),
                "three" => Some(3),
                _ => None,
            });
            return Some((Cue::Corners(n), j + 1 - i));
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
        if toks.get(j).is_some_and(|w| w.norm == "end" || w.norm == "ends") {
            // "at the end of the row": a row's end, not the room's.
            if toks.get(j + 1).is_some_and(|w| w.norm == "of") {
                let k = skip_determiners(toks, j + 2);
                let room_end = toks.get(k).is_some_and(|w| {
                    matches!(
                        w.norm.as_str(),
                        "room" | "hall" | "warehouse" | "space" | "building" | "floor" | "lab" | "shop"
                    )
                });
                if !room_end {
                    let both = toks[i + 1..j].iter().any(|w| matches!(w.norm.as_str(), "both" | "either"))
                        || toks[j].norm == "ends";
                    return Some((Cue::EndOf(both.then_some(EndOf::Both)), j + 2 - i));
                }
                return Some((Cue::End(wall), k + 1 - i));
            }
            return Some((Cue::End(wall), j + 1 - i));
        }
        // "at the back" of the room; "at the back of the bench" is behind it.
        let of_thing = |n: usize| {
            toks.get(i + n).is_some_and(|w| w.norm == "of")
                && !toks.get(skip_determiners(toks, i + n + 1)).is_some_and(|w| {
                    matches!(w.norm.as_str(), "room" | "hall" | "warehouse" | "space" | "building" | "lab" | "shop")
                })
        };
        if let Some(n) = any_of(toks, i, &["at the back", "at the rear"])
            && !of_thing(n)
        {
            return Some((Cue::End(Some(Wall::North)), n));
        }
        if let Some(n) = any_of(toks, i, &["at the front"])
            && !of_thing(n)
        {
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
        // "two walls", "both long walls", "two of the walls", "opposite walls".
        let mut two = false;
        let mut k = i + n;
        while toks.get(k).is_some_and(|w| {
            matches!(w.norm.as_str(), "the" | "two" | "both" | "of" | "opposite" | "each" | "every" | "either")
        }) {
            two |= matches!(toks[k].norm.as_str(), "two" | "both" | "opposite" | "each" | "every" | "either");
            k += 1;
        }
        while let Some(d) = toks.get(j).and_then(|w| wall_word(&w.norm)) {
            if d.is_some() {
                wall = d;
            }
            two |= matches!(toks[j].norm.as_str(), "two" | "both" | "opposite");
            any_dir = true;
            j += 1;
        }
        if two && wall.is_none() {
            let mut e = k;
            while toks.get(e).is_some_and(|w| matches!(w.norm.as_str(), "long" | "short" | "side" | "outer")) {
                e += 1;
            }
            let said = |w: &str| toks[i + n..e].iter().any(|t| t.norm == w);
            // "each long wall", "either side wall": the singular after a distributive.
            let each = said("each") || said("every") || said("either");
            let long = said("long") || said("short") || said("side");
            if toks.get(e).is_some_and(|w| w.norm == "walls" || (each && long && w.norm == "wall")) {
                if said("opposite") || said("both") || each {
                    let per_wall = each || said("both");
                    return Some((Cue::OppositeWalls { long: said("long"), per_wall }, e + 1 - i));
                }
                return Some((Cue::TwoWalls, e + 1 - i));
            }
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
    if let Some(n) = any_of(toks, i, &["back to back", "back-to-back"]) {
        return Some((Cue::BackToBack, n));
    }
    if let Some(n) = any_of(toks, i, &["in front of", "right in front of", "directly in front of", "just in front of"])
    {
        return Some((Cue::InFront, n));
    }
    if let Some(n) =
        any_of(toks, i, &["facing", "facing towards", "facing toward", "turned towards", "looking at", "faces"])
    {
        return Some((Cue::FacingTarget, n));
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
            "clamped to",
            "clamped on",
            "screwed to",
            "clipped to",
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
        &["behind", "at the back of", "at the rear of", "in back of", "right behind", "directly behind", "just behind"],
    ) {
        return Some((Cue::Behind, n));
    }
    if let Some(n) =
        any_of(toks, i, &["near", "nearby", "near to", "close to", "closest to", "close by", "not far from"])
    {
        return Some((Cue::Near, n));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "next to",
            "beside",
            "besides",
            "by",
            "alongside",
            "along",
            "adjacent to",
            "to the left of",
            "to the right of",
            "left of",
            "right of",
            "right next to",
            "right beside",
            "immediately next to",
            "directly next to",
        ],
    ) {
        return Some((Cue::NextTo, n));
    }
    if t.norm == "between" {
        return Some((Cue::Between, 1));
    }
    if let Some(n) = any_of(
        toks,
        i,
        &[
            "picking from",
            "picks from",
            "picking parts from",
            "picking up parts from",
            "picking items from",
            "placing parts on",
            "tending",
            "tends",
            "feeding",
            "feeds",
            "loading",
            "loads",
            "unloading",
            "unloads",
            "serving",
            "serves",
            "working at",
            "works at",
            "working on",
            "operating",
            "operates",
            "at",
            "sorting parts from",
            "sorting items from",
        ],
    ) {
        // Bare "at" needs an object after it ("at the bench"), not a number ("at 2 m").
        let j = skip_determiners(toks, i + n);
        let each = toks.get(i + n).is_some_and(|w| matches!(w.norm.as_str(), "each" | "every" | "both"));
        if toks.get(j).is_some_and(|w| w.kind == TokenKind::Word) || each {
            return Some((Cue::Tend, n));
        }
    }
    if let Some(n) = any_of(
        toks,
        i,
        &["opposite", "across from", "directly opposite", "right opposite", "opposite to", "across the room from"],
    ) {
        return Some((Cue::FacingTarget, n));
    }
    if let Some(n) = any_of(toks, i, &["above", "over", "directly above", "hanging above", "mounted above"]) {
        let j = skip_determiners(toks, i + n);
        if toks.get(j).is_some_and(|w| w.kind == TokenKind::Word) {
            return Some((Cue::Above, n));
        }
    }
    if let Some(n) = any_of(toks, i, &["in", "inside", "into", "within", "inside of", "in the inside of"]) {
        let j = skip_determiners(toks, i + n);
        if toks.get(j).is_some_and(|w| w.kind == TokenKind::Word) {
            return Some((Cue::In, n));
        }
    }
    if matches!(t.norm.as_str(), "around" | "surrounding" | "encircling" | "round") {
        // "around 20 boxes" means about twenty.
        if toks.get(i + 1).is_some_and(|n| matches!(n.kind, TokenKind::Number(_))) {
            return None;
        }
        // "round tables" are tables; "round the table" is around it.
        if t.norm == "round" && !toks.get(i + 1).is_some_and(|w| DETERMINERS.contains(&w.norm.as_str())) {
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
