//! The offline grammar: English edit commands to [`EditCommand`]s, for the common
//! forms. What it does not understand is an error (the LLM, when configured, reads it
//! instead).
//!
//! ```text
//! remove the chair next to the conveyor        add two red chairs next to the table
//! delete all boxes                             put a mug on the table
//! move the table 1 m to the left               move the shelf against the north wall
//! move chair_2 next to the conveyor            rotate the cabinet 90 degrees clockwise
//! replace the chair with a stool               make the red box blue / paint the desk grey
//! make the table bigger / 2 m long / twice as big, then remove the lamp
//! ```

use sw_planner::vocab;

use crate::ast::{Anchor, EditCommand, EditOp, Placement, Reference, Resize, Spatial};
use crate::words::{
    ORDINALS, SHADES, anchor_at, corner_of, direction, is_size_start, number, resize_of, rotation, shift, starts_with,
    tokens, trailing_color, unit, wall_word,
};

/// A command the offline grammar cannot read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GrammarError {
    #[error("the command is empty")]
    Empty,
    #[error(
        "the offline edit grammar does not understand \"{0}\" (it reads e.g. \"remove the chair next to the conveyor\", \
         \"add two boxes on the table\", \"move the table 1 m to the left\", \"rotate the shelf 90 degrees\", \
         \"make the cabinet red\", \"make the table bigger\", \"replace the chair with a stool\"; configure an LLM \
         endpoint for anything else)"
    )]
    NotUnderstood(String),
    #[error("\"{clause}\": {problem}")]
    Incomplete { clause: String, problem: String },
}

/// Longest command accepted, bytes.
pub const MAX_COMMAND_BYTES: usize = 4096;

const VERBS: &[&str] = &[
    "remove",
    "delete",
    "erase",
    "discard",
    "drop",
    "get",
    "take",
    "add",
    "put",
    "place",
    "insert",
    "include",
    "create",
    "set",
    "bring",
    "move",
    "shift",
    "push",
    "slide",
    "relocate",
    "drag",
    "replace",
    "swap",
    "exchange",
    "substitute",
    "change",
    "turn",
    "rotate",
    "spin",
    "paint",
    "color",
    "colour",
    "recolor",
    "recolour",
    "make",
    "resize",
    "scale",
    "enlarge",
    "shrink",
    "grow",
];

/// Parses a reference ("the red chair next to the conveyor", "all boxes", "chair_2").
fn reference(t: &[String]) -> Result<Reference, String> {
    let mut i = 0;
    let mut r = Reference::default();
    let mut definite = false;
    while i < t.len() {
        match t[i].as_str() {
            "the" | "this" | "that" => definite = true,
            "these" | "those" | "both" => r.all = true,
            "a" | "an" | "any" | "some" => r.any = true,
            "all" | "every" | "each" => r.all = true,
            "of" if r.all => {}
            _ => break,
        }
        i += 1;
    }
    if let Some((_, k)) = t.get(i).and_then(|w| ORDINALS.iter().find(|(o, _)| o == w)) {
        r.ordinal = Some(*k);
        r.any = false;
        i += 1;
    }
    let rest = &t[i..];
    let cut = (0..rest.len()).find(|&j| j > 0 && anchor_at(rest, j).is_some()).unwrap_or(rest.len());
    let mut noun_words: Vec<String> = rest[..cut].to_vec();
    // "the red one", "the dark blue box": a colour before the noun.
    let shade = noun_words.first().is_some_and(|w| SHADES.contains(&w.as_str()));
    let at = usize::from(shade);
    if let Some(c) = noun_words.get(at).and_then(|w| vocab::color(w)) {
        r.color = Some(if shade { noun_words[..2].join(" ") } else { c.name });
        noun_words.drain(..=at);
    }
    let noun = noun_words.join(" ");
    let noun = match noun.as_str() {
        "one" | "ones" | "thing" | "things" | "object" | "objects" | "item" | "items" => String::new(),
        _ => noun,
    };
    if noun.is_empty() && r.color.is_none() && r.ordinal.is_none() && !r.all {
        return Err("which object? (name it, e.g. 'the chair next to the table' or 'chair_2')".into());
    }
    // "the boxes": every box.
    if definite && !r.all && !noun.contains('_') {
        let last = noun.split_whitespace().last().unwrap_or("");
        let singular = vocab::words(last).join(" ");
        if !last.is_empty() && singular != last && last.ends_with('s') {
            r.all = true;
        }
    }
    r.noun = noun;
    if cut < rest.len()
        && let Some((relation, n)) = anchor_at(rest, cut)
    {
        let of = reference(&rest[cut + n..])?;
        r.anchor = Some(Anchor { relation, of: Box::new(of) });
    }
    Ok(r)
}

/// Parses a placement ("next to the table", "against the north wall", "1 m left").
fn placement(t: &[String]) -> Result<Placement, String> {
    if t.is_empty() {
        return Err("where to? (e.g. 'next to the table', 'against the north wall', '1 m to the left')".into());
    }
    let s = t.join(" ");
    if t.iter().any(|w| w == "wall") && !t.iter().any(|w| w == "corner") {
        let wall = t.iter().find_map(|w| wall_word(w));
        return Ok(Placement::AgainstWall { wall });
    }
    if let Some(c) = corner_of(t) {
        return Ok(Placement::InCorner { corner: c });
    }
    if t.iter().any(|w| matches!(w.as_str(), "door" | "doorway" | "entrance" | "exit")) && t.len() <= 5 {
        return Ok(Placement::NearDoor);
    }
    if ["middle", "center", "centre"].iter().any(|w| t.iter().any(|x| x == w)) && !s.contains(" of the ")
        || s.ends_with("of the room") && ["middle", "center", "centre"].iter().any(|w| s.contains(w))
    {
        return Ok(Placement::InCenter);
    }
    if let Some(p) = shift(t) {
        return Ok(p);
    }
    let (side, n) = match anchor_at(t, 0) {
        Some(x) => x,
        None if t[0] == "to" || t[0] == "towards" || t[0] == "toward" => (Spatial::NextTo, 1),
        None if t[0] == "into" || t[0] == "in" => (Spatial::On, 1),
        None => return Err(format!("'{s}' is not a place the grammar knows")),
    };
    let of = reference(&t[n..])?;
    Ok(match side {
        Spatial::On => Placement::On { of },
        Spatial::Under => Placement::Under { of },
        Spatial::Nearest | Spatial::Farthest => Placement::Beside { side: Spatial::NextTo, of },
        side => Placement::Beside { side, of },
    })
}

/// Where a placement begins in `t` (the first, or the last for moves).
fn placement_start(t: &[String], last: bool) -> Option<usize> {
    let starts: Vec<usize> = (1..t.len())
        .filter(|&i| {
            let w = t[i].as_str();
            anchor_at(t, i).is_some_and(|(s, _)| !matches!(s, Spatial::Nearest | Spatial::Farthest))
                || matches!(w, "against" | "along" | "into" | "towards" | "toward")
                || (w == "to" && t.get(i + 1).is_none_or(|x| x != "a"))
                || (w == "in"
                    && t.get(i + 1).is_some_and(|x| x == "the")
                    && t.get(i + 2).is_some_and(|x| {
                        matches!(x.as_str(), "middle" | "center" | "centre" | "corner")
                            || t[i + 2..].iter().any(|y| y == "corner")
                    }))
                || (number(w).is_some()
                    && !matches!(w, "a" | "an" | "one")
                    && t.get(i + 1).is_some_and(|u| unit(u).is_some()))
                || (direction(w).is_some() && i + 1 == t.len())
        })
        .collect();
    if last {
        // The destination of a move is a shift ("1 m to the left", from its number), else
        // the last place named ("the chair next to the table TO THE NORTH WALL").
        starts.iter().copied().find(|&s| shift(&t[s..]).is_some()).or_else(|| starts.last().copied())
    } else {
        starts.first().copied()
    }
}

/// Parses one clause (one operation).
fn clause(t: &[String]) -> Result<EditOp, GrammarError> {
    let text = t.join(" ");
    let incomplete = |problem: String| GrammarError::Incomplete { clause: text.clone(), problem };
    let Some(verb) = t.first().map(String::as_str) else { return Err(GrammarError::Empty) };
    let rest = &t[1..];
    let op = match verb {
        "remove" | "delete" | "erase" | "discard" | "drop" => {
            EditOp::Remove { target: reference(rest).map_err(incomplete)? }
        }
        "get" if starts_with(rest, &["rid", "of"]) => {
            EditOp::Remove { target: reference(&rest[2..]).map_err(incomplete)? }
        }
        "take" => {
            let r: Vec<String> = rest.iter().filter(|w| *w != "away" && *w != "out").cloned().collect();
            EditOp::Remove { target: reference(&r).map_err(incomplete)? }
        }
        "add" | "insert" | "include" | "create" | "put" | "place" | "set" | "bring" => {
            let at = placement_start(rest, false);
            let (what, place) = match at {
                Some(i) => (&rest[..i], Some(placement(&rest[i..]).map_err(incomplete)?)),
                None => (rest, None),
            };
            if what.is_empty() {
                return Err(incomplete("add what?".into()));
            }
            let existing = matches!(what[0].as_str(), "the" | "all" | "every" | "these" | "those" | "this" | "that")
                || what.iter().any(|w| w.contains('_') && w.chars().any(|c| c.is_ascii_digit()));
            if existing && matches!(verb, "put" | "place" | "set" | "bring") {
                let to = place.ok_or_else(|| incomplete("put it where?".into()))?;
                EditOp::Move { target: reference(what).map_err(incomplete)?, to }
            } else {
                EditOp::Add { what: what.join(" "), place }
            }
        }
        "move" | "shift" | "push" | "slide" | "relocate" | "drag" => {
            let at = placement_start(rest, true)
                .ok_or_else(|| incomplete("move it where? (e.g. 'next to the table', '1 m to the left')".into()))?;
            EditOp::Move {
                target: reference(&rest[..at]).map_err(incomplete)?,
                to: placement(&rest[at..]).map_err(incomplete)?,
            }
        }
        "replace" | "swap" | "exchange" | "substitute" => {
            let at = rest
                .iter()
                .position(|w| matches!(w.as_str(), "with" | "for" | "by"))
                .ok_or_else(|| incomplete("replace it with what?".into()))?;
            if at + 1 >= rest.len() {
                return Err(incomplete("replace it with what?".into()));
            }
            EditOp::Replace { target: reference(&rest[..at]).map_err(incomplete)?, with: rest[at + 1..].join(" ") }
        }
        "change" | "turn" if rest.iter().any(|w| w == "into") => {
            let at = rest.iter().position(|w| w == "into").unwrap_or(0);
            EditOp::Replace { target: reference(&rest[..at]).map_err(incomplete)?, with: rest[at + 1..].join(" ") }
        }
        "change" if starts_with(rest, &["the", "color", "of"]) || starts_with(rest, &["the", "colour", "of"]) => {
            let (color, n) = trailing_color(rest).ok_or_else(|| incomplete("to which colour?".into()))?;
            let mut end = rest.len() - n;
            if end > 3 && rest[end - 1] == "to" {
                end -= 1;
            }
            EditOp::Recolor { target: reference(&rest[3..end]).map_err(incomplete)?, color }
        }
        "rotate" | "spin" | "turn" => {
            let (at, degrees) = rotation(rest).map_err(incomplete)?;
            EditOp::Rotate { target: reference(&rest[..at]).map_err(incomplete)?, degrees }
        }
        "paint" | "color" | "colour" | "recolor" | "recolour" => {
            let (color, n) = trailing_color(rest).ok_or_else(|| incomplete("which colour?".into()))?;
            let mut end = rest.len() - n;
            if end > 0 && matches!(rest[end - 1].as_str(), "to" | "in") {
                end -= 1;
            }
            EditOp::Recolor { target: reference(&rest[..end]).map_err(incomplete)?, color }
        }
        "make" => {
            if let Some((color, n)) = trailing_color(rest)
                && rest.len() > n
            {
                EditOp::Recolor { target: reference(&rest[..rest.len() - n]).map_err(incomplete)?, color }
            } else {
                let at = (1..rest.len())
                    .find(|&i| is_size_start(rest, i))
                    .ok_or_else(|| GrammarError::NotUnderstood(text.clone()))?;
                EditOp::Resize {
                    target: reference(&rest[..at]).map_err(incomplete)?,
                    resize: resize_of(&rest[at..]).map_err(incomplete)?,
                }
            }
        }
        "resize" | "scale" => {
            let at =
                (1..rest.len()).find(|&i| is_size_start(rest, i)).ok_or_else(|| incomplete("to what size?".into()))?;
            EditOp::Resize {
                target: reference(&rest[..at]).map_err(incomplete)?,
                resize: resize_of(&rest[at..]).map_err(incomplete)?,
            }
        }
        "enlarge" | "grow" | "shrink" => {
            let at = (1..rest.len()).find(|&i| is_size_start(rest, i)).unwrap_or(rest.len());
            let resize = if at < rest.len() {
                resize_of(&rest[at..]).map_err(incomplete)?
            } else {
                Resize::uniform(if verb == "shrink" { 0.8 } else { 1.25 })
            };
            EditOp::Resize { target: reference(&rest[..at]).map_err(incomplete)?, resize }
        }
        _ => return Err(GrammarError::NotUnderstood(text)),
    };
    Ok(op)
}

/// Parses a command of one or more clauses ("remove the lamp and add a chair").
pub fn parse(command: &str) -> Result<EditCommand, GrammarError> {
    if command.len() > MAX_COMMAND_BYTES {
        return Err(GrammarError::NotUnderstood(format!("a command of {} bytes", command.len())));
    }
    let t = tokens(command);
    let t: Vec<String> =
        t.into_iter().skip_while(|w| matches!(w.as_str(), "please" | "now" | "also" | "and" | "then")).collect();
    if t.is_empty() {
        return Err(GrammarError::Empty);
    }
    if !VERBS.contains(&t[0].as_str()) {
        return Err(GrammarError::NotUnderstood(command.trim().to_string()));
    }
    // Clauses: split at "then", ";" and at "and" / "," followed by a verb.
    let mut clauses: Vec<Vec<String>> = vec![Vec::new()];
    let mut i = 0;
    while i < t.len() {
        let w = t[i].as_str();
        let next_is_verb = |j: usize| {
            let mut j = j;
            while t.get(j).is_some_and(|x| matches!(x.as_str(), "and" | "then" | "also" | "," | "please")) {
                j += 1;
            }
            t.get(j).is_some_and(|x| VERBS.contains(&x.as_str()))
                && t.get(j).is_some_and(|x| x != "set" && x != "place")
        };
        if matches!(w, ";" | "then") || (matches!(w, "and" | ",") && next_is_verb(i + 1)) {
            if clauses.last().is_some_and(|c| !c.is_empty()) {
                clauses.push(Vec::new());
            }
        } else if w != ","
            && w != "please"
            && let Some(c) = clauses.last_mut()
        {
            c.push(t[i].clone());
        }
        i += 1;
    }
    let ops = clauses.iter().filter(|c| !c.is_empty()).map(|c| clause(c)).collect::<Result<Vec<_>, _>>()?;
    if ops.is_empty() {
        return Err(GrammarError::Empty);
    }
    Ok(EditCommand { ops })
}
