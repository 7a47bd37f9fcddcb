//! The small readers every part of a model's answer goes through: bounded one-line text,
//! numbers written as strings, ids, walls and corners in the words models use, and
//! references between groups.

use std::collections::BTreeMap;

use serde_json::{Map, Value};
use sw_plan::{Approximation, Corner, Wall};

use crate::vocab;

/// Longest id, characters (the schema's `maxLength`).
pub(crate) const MAX_ID: usize = 40;
/// Longest phrase or note, characters.
pub(crate) const MAX_TEXT: usize = 200;
/// Longest label (category, proxy label, colour name), characters.
pub(crate) const MAX_LABEL: usize = 60;

pub(crate) fn text(v: Option<&Value>, max: usize) -> Option<String> {
    let s = match v? {
        Value::String(s) => s.clone(),
        Value::Number(n) => n.to_string(),
        _ => return None,
    };
    let cleaned: String = s.chars().map(|c| if c.is_control() { ' ' } else { c }).collect();
    let trimmed = cleaned.split_whitespace().collect::<Vec<_>>().join(" ");
    if trimmed.is_empty() {
        return None;
    }
    Some(trimmed.chars().take(max).collect())
}

pub(crate) fn field<'a>(o: &'a Map<String, Value>, names: &[&str]) -> Option<&'a Value> {
    names.iter().find_map(|n| o.get(*n).filter(|v| !v.is_null()))
}

pub(crate) fn number(v: Option<&Value>) -> Option<f64> {
    match v? {
        Value::Number(n) => n.as_f64(),
        Value::String(s) => {
            let t = s.trim().trim_end_matches('m').trim();
            t.parse::<f64>().ok()
        }
        _ => None,
    }
    .filter(|x| x.is_finite())
}

/// An id: lowercase letters, digits and underscores, at most 40 characters.
pub fn sanitize_id(raw: &str) -> String {
    let s: String = raw
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' })
        .collect::<String>()
        .split('_')
        .filter(|p| !p.is_empty())
        .collect::<Vec<_>>()
        .join("_");
    s.chars().take(MAX_ID).collect()
}

/// Keys that put geometry into a plan, which a model may not do.
pub(crate) const POSITION_KEYS: &[&str] =
    &["position", "pos", "x", "y", "z", "coordinates", "coords", "location", "pose", "rotation", "yaw", "angle", "xy"];

pub(crate) fn note(notes: &mut Vec<Approximation>, text: &str, became: &str, reason: &str) {
    let a = Approximation { text: text.chars().take(MAX_TEXT).collect(), became: became.into(), reason: reason.into() };
    if !notes.contains(&a) {
        notes.push(a);
    }
}

/// Reads one object group of an answer (also used on streamed elements, so that work
/// for it can start early). `index` is its position in the list (for a default id).
pub(crate) fn wall(v: Option<&Value>) -> Option<Wall> {
    let s = v?.as_str()?.trim().to_lowercase();
    let s = s.strip_suffix(" wall").unwrap_or(&s).trim_start_matches("the ").to_string();
    match s.as_str() {
        "north" | "n" | "back" => Some(Wall::North),
        "south" | "s" | "front" => Some(Wall::South),
        "east" | "e" | "right" => Some(Wall::East),
        "west" | "w" | "left" => Some(Wall::West),
        _ => None,
    }
}

pub(crate) fn corner(v: Option<&Value>) -> Option<Corner> {
    let s: String = v?.as_str()?.to_lowercase().chars().filter(|c| c.is_ascii_alphabetic()).collect();
    match s.as_str() {
        "northeast" | "ne" => Some(Corner::NorthEast),
        "northwest" | "nw" => Some(Corner::NorthWest),
        "southeast" | "se" => Some(Corner::SouthEast),
        "southwest" | "sw" => Some(Corner::SouthWest),
        _ => None,
    }
}

/// Resolves a reference to a group: its id (as written or sanitized), else a group
/// whose category or phrase names the same thing, when exactly one does.
pub(crate) struct Refs {
    /// Raw id as written → final id.
    pub(crate) ids: BTreeMap<String, String>,
    pub(crate) groups: Vec<(String, String, String)>,
}

impl Refs {
    pub(crate) fn resolve(&self, raw: &str) -> Option<String> {
        if let Some(id) = self.ids.get(raw) {
            return Some(id.clone());
        }
        let s = sanitize_id(raw);
        if self.groups.iter().any(|(id, _, _)| *id == s) {
            return Some(s);
        }
        // "table_1" for id "table": a numbered instance of a group.
        if let Some((base, n)) = s.rsplit_once('_')
            && n.chars().all(|c| c.is_ascii_digit())
            && self.groups.iter().any(|(id, _, _)| id == base)
        {
            return Some(base.to_string());
        }
        let cat = vocab::category(raw);
        let hits: Vec<&String> = self
            .groups
            .iter()
            .filter(|(_, c, phrase)| cat.is_some_and(|k| k == c) || vocab::words(phrase) == vocab::words(raw))
            .map(|(id, _, _)| id)
            .collect();
        if hits.len() == 1 { Some(hits[0].clone()) } else { None }
    }
}
