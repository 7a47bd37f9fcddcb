//! Relations in a model's answer, read generically: the relation kinds, their fields and
//! which fields name object groups come from the plan's own JSON Schema (generated from
//! [`sw_plan::RelationKind`]), so a kind added to the contract is read — and described to
//! the model — without a change here. Each relation is rebuilt from the fields its kind
//! has (references resolved to the plan's ids, walls and corners in the words models use)
//! and then deserialised into the contract type; anything that cannot be is dropped with
//! a note, never silently.

use std::sync::OnceLock;

use serde_json::{Map, Value};
use sw_plan::{Approximation, Relation};

use super::fields::{MAX_LABEL, MAX_TEXT, POSITION_KEYS, Refs, corner, field, note, number, text, wall};

/// What a field of a relation kind holds.
#[derive(Debug, Clone, PartialEq)]
enum Field {
    /// An object group's id.
    Id,
    /// One of these values (a wall, a corner).
    Enum(Vec<String>),
    Integer,
    Number,
    Other,
}

/// A relation kind as the schema states it.
#[derive(Debug, Clone)]
struct Kind {
    name: String,
    /// Fields besides `relation`, with whether each is required.
    fields: Vec<(String, Field, bool)>,
}

fn classify(p: &Value, defs: &Value) -> Field {
    // `anyOf: [X, null]` and `type: [T, null]` are X and T.
    let p = match p.get("anyOf").and_then(Value::as_array) {
        Some(alts) => alts.iter().find(|a| a.get("type").and_then(Value::as_str) != Some("null")).unwrap_or(p),
        None => p,
    };
    let p = match p.get("$ref").and_then(Value::as_str).and_then(|r| r.strip_prefix("#/$defs/")) {
        Some(name) => defs.get(name).unwrap_or(p),
        None => p,
    };
    if let Some(values) = p.get("enum").and_then(Value::as_array) {
        return Field::Enum(values.iter().filter_map(Value::as_str).map(str::to_string).collect());
    }
    let ty = match p.get("type") {
        Some(Value::String(t)) => t.clone(),
        Some(Value::Array(ts)) => ts.iter().filter_map(Value::as_str).find(|t| *t != "null").unwrap_or("").to_string(),
        _ => String::new(),
    };
    match ty.as_str() {
        "string" => Field::Id,
        "integer" => Field::Integer,
        "number" => Field::Number,
        _ => Field::Other,
    }
}

fn kinds() -> &'static [Kind] {
    static KINDS: OnceLock<Vec<Kind>> = OnceLock::new();
    KINDS.get_or_init(|| {
        let schema: Value = sw_plan::schemas()
            .into_iter()
            .find(|s| s.file_name == "plan.schema.json")
            .and_then(|f| serde_json::from_str(&f.json).ok())
            .unwrap_or(Value::Null);
        let defs = schema.get("$defs").cloned().unwrap_or(Value::Null);
        let variants = defs.pointer("/Relation/oneOf").and_then(Value::as_array).cloned().unwrap_or_default();
        variants
            .iter()
            .filter_map(|v| {
                let props = v.get("properties")?.as_object()?;
                let name = props.get("relation")?.get("const")?.as_str()?.to_string();
                let required: Vec<&str> = v
                    .get("required")
                    .and_then(Value::as_array)
                    .into_iter()
                    .flatten()
                    .filter_map(Value::as_str)
                    .collect();
                let fields = props
                    .iter()
                    .filter(|(k, _)| *k != "relation")
                    .map(|(k, p)| (k.clone(), classify(p, &defs), required.contains(&k.as_str())))
                    .collect();
                Some(Kind { name, fields })
            })
            .collect()
    })
}

/// The relation kinds as the model is told them: `on {target}, against_wall {wall?}, …`.
pub(crate) fn relation_help() -> String {
    kinds()
        .iter()
        .map(|k| {
            if k.fields.is_empty() {
                return k.name.clone();
            }
            let fields: Vec<String> = k
                .fields
                .iter()
                .map(|(f, kind, req)| {
                    let q = if *req { "" } else { "?" };
                    match kind {
                        Field::Enum(vs) if f == "corner" => format!("{f}{q}: {}", vs.join("|")),
                        _ => format!("{f}{q}"),
                    }
                })
                .collect();
            format!("{} {{{}}}", k.name, fields.join(", "))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The kinds a relation's name may mean, most likely first.
fn candidates(raw: &str) -> Vec<String> {
    let s: String =
        raw.trim().to_lowercase().chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
    let s = s.trim_matches('_').to_string();
    let alias: &[&str] = match s.as_str() {
        "on_top_of" | "onto" | "on_top" | "resting_on" | "on_surface" | "atop" => &["on"],
        "below" | "beneath" | "underneath" => &["under"],
        "against" | "along_wall" | "against_the_wall" | "along_the_wall" | "wall" => &["against_wall"],
        "beside" | "adjacent_to" | "next" | "by" | "close_to" | "alongside" => &["next_to"],
        "near" => &["near", "next_to"],
        "in_a_row" | "row" | "in_line" | "in_a_line" | "aligned" => &["in_row"],
        "rows" | "in_rows" => &["in_rows", "in_row"],
        "facing" | "face_each_other" | "opposite" => &["facing_each_other"],
        "in_front" | "before" => &["in_front_of"],
        "in_back_of" => &["behind"],
        "surrounding" | "encircling" => &["around"],
        "at_the_end" | "end" | "at_one_end" => &["at_end"],
        "by_the_door" | "near_the_door" | "at_the_door" | "next_to_door" | "door" => &["near_door"],
        "corner" | "in_the_corner" => &["in_corner"],
        "center" | "centre" | "in_centre" | "middle" | "in_the_middle" | "in_middle" | "in_the_center"
        | "in_center" => &["in_middle", "in_center"],
        _ => &[],
    };
    let mut out = vec![s.clone()];
    out.extend(alias.iter().map(|a| a.to_string()));
    out
}

fn kind_named(raw: &str) -> Option<&'static Kind> {
    candidates(raw).into_iter().find_map(|c| kinds().iter().find(|k| k.name == c))
}

/// The names a model uses for a field.
fn aliases(field_name: &str) -> Vec<&str> {
    match field_name {
        "target" => vec!["target", "to", "object2", "on", "of", "object"],
        "first" => vec!["first", "a"],
        "second" => vec!["second", "b"],
        "wall" => vec!["wall", "target", "end", "side"],
        "corner" => vec!["corner", "target"],
        other => vec![other],
    }
}

fn enum_value(v: &Value, values: &[String]) -> Option<String> {
    let s = v.as_str()?.trim().to_lowercase().replace([' ', '-'], "_");
    if values.contains(&s) {
        return Some(s);
    }
    let via = wall(Some(v))
        .and_then(|w| serde_json::to_value(w).ok())
        .or_else(|| corner(Some(v)).and_then(|c| serde_json::to_value(c).ok()))?;
    via.as_str().filter(|x| values.iter().any(|v| v == x)).map(str::to_string)
}

/// Reads one relation of an answer; `None` (with a note) when it cannot be used.
pub(crate) fn read_relation(v: &Value, refs: &Refs, notes: &mut Vec<Approximation>) -> Option<Relation> {
    let Some(o) = v.as_object() else {
        note(notes, &v.to_string().chars().take(60).collect::<String>(), "ignored", "a relation must be an object");
        return None;
    };
    let raw_subject = text(field(o, &["subject", "object", "from", "source", "item"]), MAX_TEXT);
    let raw_kind = text(field(o, &["relation", "type", "kind", "predicate"]), MAX_LABEL).unwrap_or_default();
    let raw_target = text(field(o, &["target", "to", "object2", "on", "first"]), MAX_TEXT).unwrap_or_default();
    let describe =
        format!("{} {raw_kind} {raw_target}", raw_subject.as_deref().unwrap_or("(no subject)")).trim().to_string();
    let Some(raw_subject) = raw_subject else {
        note(notes, &describe, "ignored", "the relation names no subject");
        return None;
    };
    let Some(kind) = kind_named(&raw_kind) else {
        note(notes, &describe, "ignored", "not a relation the layout understands");
        return None;
    };
    let Some(subject) = refs.resolve(&raw_subject) else {
        note(notes, &describe, "ignored", "the relation names an object group the plan does not have");
        return None;
    };
    let mut out = Map::new();
    out.insert("subject".into(), Value::String(subject.clone()));
    out.insert("relation".into(), Value::String(kind.name.clone()));
    let listed: Vec<&Value> =
        o.get("targets").and_then(Value::as_array).map(|a| a.iter().collect()).unwrap_or_default();
    for (name, f, required) in &kind.fields {
        let mut raw = field(o, &aliases(name));
        if raw.is_none() {
            raw = match name.as_str() {
                "first" => listed.first().copied(),
                "second" => listed.get(1).copied(),
                _ => None,
            };
        }
        let value = raw.and_then(|r| match f {
            Field::Id => text(Some(r), MAX_TEXT).and_then(|t| refs.resolve(&t)).map(Value::String),
            Field::Enum(values) => enum_value(r, values).map(Value::String),
            Field::Integer => {
                number(Some(r)).filter(|n| (0.0..=1000.0).contains(n)).map(|n| Value::from(n.round() as u64))
            }
            Field::Number => number(Some(r)).and_then(serde_json::Number::from_f64).map(Value::Number),
            Field::Other => Some(r.clone()),
        });
        match value {
            Some(val) => {
                out.insert(name.clone(), val);
            }
            None if *required => {
                let why = if matches!(f, Field::Id) {
                    "the relation's target is not an object group of the plan"
                } else {
                    "the relation lacks a field it needs"
                };
                note(notes, &describe, "ignored", why);
                return None;
            }
            None if raw.is_some() => {
                note(notes, &describe, &format!("{} without its {name}", kind.name), "the value could not be read");
            }
            None => {}
        }
    }
    let relation: Relation = match serde_json::from_value(Value::Object(out)) {
        Ok(r) => r,
        Err(e) => {
            note(notes, &describe, "ignored", &format!("the relation could not be read ({e})"));
            return None;
        }
    };
    if relation.kind.targets().contains(&subject.as_str()) {
        note(notes, &describe, "ignored", "an object group cannot be related to itself");
        return None;
    }
    if o.keys().any(|k| POSITION_KEYS.contains(&k.as_str())) {
        note(notes, &describe, "ignored coordinates", "the layout solver places objects; coordinates are not used");
    }
    Some(relation)
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;

    fn refs() -> Refs {
        Refs {
            ids: [("box", "box"), ("table", "table"), ("shelf", "shelf")]
                .into_iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect(),
            groups: vec![
                ("box".into(), "cardboard_box".into(), "boxes".into()),
                ("table".into(), "table".into(), "a table".into()),
                ("shelf".into(), "shelf".into(), "a shelf".into()),
            ],
        }
    }

    #[test]
    fn every_kind_of_the_contract_is_known_with_its_fields() {
        let names: Vec<&str> = kinds().iter().map(|k| k.name.as_str()).collect();
        for n in ["on", "against_wall", "between", "in_row", "in_corner", "near_door"] {
            assert!(names.contains(&n), "{n} in {names:?}");
        }
        let between = kinds().iter().find(|k| k.name == "between").unwrap();
        assert!(between.fields.iter().all(|(_, f, req)| *f == Field::Id && *req), "{between:?}");
        let corner = kinds().iter().find(|k| k.name == "in_corner").unwrap();
        assert!(matches!(&corner.fields[0].1, Field::Enum(v) if v.len() == 4), "{corner:?}");
        assert!(relation_help().contains("on {target}") && relation_help().contains("against_wall {wall?}"));
    }

    #[test]
    fn relations_are_rebuilt_from_their_kind_and_drops_are_noted() {
        let mut notes = Vec::new();
        let r =
            read_relation(&json!({"subject": "box", "relation": "on top of", "target": "table"}), &refs(), &mut notes)
                .unwrap();
        assert_eq!(r.kind.targets(), vec!["table"]);
        let r = read_relation(
            &json!({"subject": "shelf", "relation": "against", "wall": "the north wall"}),
            &refs(),
            &mut notes,
        )
        .unwrap();
        assert_eq!(serde_json::to_value(&r).unwrap()["wall"], "north");
        let r = read_relation(
            &json!({"subject": "box", "relation": "between", "targets": ["table", "shelf"]}),
            &refs(),
            &mut notes,
        )
        .unwrap();
        assert_eq!(r.kind.targets(), vec!["table", "shelf"]);
        assert!(notes.is_empty(), "{notes:?}");
        for bad in [
            json!({"relation": "on", "target": "table"}),
            json!({"subject": "box", "relation": "hovering", "target": "table"}),
            json!({"subject": "box", "relation": "on", "target": "moon"}),
            json!({"subject": "box", "relation": "on", "target": "box"}),
            json!("on"),
        ] {
            let before = notes.len();
            assert!(read_relation(&bad, &refs(), &mut notes).is_none(), "{bad}");
            assert_eq!(notes.len(), before + 1, "every drop is a note: {bad}");
        }
        assert!(notes[0].reason.contains("no subject"), "{notes:?}");
    }
}
