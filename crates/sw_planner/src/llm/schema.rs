//! The JSON Schemas a model is asked to follow: the contract's own schemas (generated
//! from `sw_plan`'s types, so a new relation kind or field appears here by itself), with
//! what the readers need of them written in:
//!
//! - the bounds the readers keep (ids, phrases and labels cut to length, at most 32 object
//!   groups, 128 relations, 16 robot entries, counts up to 2000, four size words): a
//!   grammar-constrained model cannot write past them, so it cannot loop inside a string;
//! - categories, robot models and rules profiles as enums of what the catalog, the robot
//!   registry and the rules know;
//! - the order properties are written in, as the order of `required` (the client writes
//!   a schema's properties in that order, and converters make the model follow it):
//!   objects first (their assets start as each one arrives), then robots, relations and
//!   the room; each object's phrase before its id and category.
//!
//! What every schema needs for every converter (own properties moved into each `oneOf`
//! variant, `additionalProperties: false`, default bounds) is done by the client
//! (`sw_llm::schema::for_model`) for any schema it sends.

use serde_json::{Value, json};
use sw_plan::RoomKind;

use super::fields::{MAX_LABEL, MAX_TEXT};

/// The shape of an id: what [`super::sanitize_id`] keeps, a letter first (small models
/// otherwise write `"1234567890…"`), at most 40 characters.
pub const ID_PATTERN: &str = "^[a-z][a-z0-9_]{0,39}$";
/// The longest phrase a model may copy from the prompt for one group (the reader keeps
/// up to 200 characters from servers that do not enforce the schema).
const MAX_PHRASE: usize = 80;
use super::read::{MAX_GROUPS, MAX_NOTES, MAX_RELATIONS, MAX_ROBOT_GROUPS, MAX_TOTAL};

/// Sets `key` of the schema at `pointer` (nothing when the contract no longer has it).
fn set(schema: &mut Value, pointer: &str, key: &str, value: Value) {
    if let Some(Value::Object(o)) = schema.pointer_mut(pointer) {
        o.insert(key.to_string(), value);
    }
}

/// Puts `first` at the head of the `required` list at `pointer`, in that order.
fn order(schema: &mut Value, pointer: &str, first: &[&str]) {
    if let Some(Value::Array(req)) = schema.pointer_mut(&format!("{pointer}/required")) {
        let mut out: Vec<Value> = first.iter().filter(|f| req.iter().any(|r| r == *f)).map(|f| json!(f)).collect();
        let rest: Vec<Value> = req.iter().filter(|r| !out.contains(r)).cloned().collect();
        out.extend(rest);
        *req = out;
    }
}

fn strings(names: impl IntoIterator<Item = String>) -> Value {
    Value::Array(names.into_iter().map(Value::String).collect())
}

/// The plan's JSON Schema as the model is asked to follow it: `ScenePlan`'s, without
/// `schema_version` and `prompt` (filled in here: echoing a long prompt back costs output
/// tokens, which is latency), bounded and ordered for the readers.
pub fn plan_schema() -> Value {
    let file = sw_plan::schemas().into_iter().find(|s| s.file_name == "plan.schema.json");
    let mut schema: Value =
        file.and_then(|f| serde_json::from_str(&f.json).ok()).unwrap_or_else(|| json!({"type": "object"}));
    if let Some(props) = schema.get_mut("properties").and_then(Value::as_object_mut) {
        props.remove("schema_version");
        props.remove("prompt");
    }
    if let Some(req) = schema.get_mut("required").and_then(Value::as_array_mut) {
        req.retain(|r| r != "schema_version" && r != "prompt" && r != "understanding");
    }
    order(&mut schema, "", &["objects", "robots", "relations", "room", "rules_profile"]);
    set(&mut schema, "/properties/objects", "maxItems", json!(MAX_GROUPS));
    set(&mut schema, "/properties/relations", "maxItems", json!(MAX_RELATIONS));
    set(&mut schema, "/properties/robots", "maxItems", json!(MAX_ROBOT_GROUPS));
    let mut profiles: Vec<String> = RoomKind::ALL.iter().map(|k| k.rules_profile().to_string()).collect();
    profiles.sort();
    profiles.dedup();
    set(&mut schema, "/properties/rules_profile", "enum", strings(profiles));

    // Object groups.
    let d = "/$defs/ObjectPlan";
    order(&mut schema, d, &["phrase", "id", "category", "count"]);
    set(&mut schema, &format!("{d}/properties/id"), "pattern", json!(ID_PATTERN));
    set(&mut schema, &format!("{d}/properties/phrase"), "maxLength", json!(MAX_PHRASE));
    let mut categories: Vec<String> = sw_catalog::categories().iter().map(|c| c.name.to_string()).collect();
    categories.push("proxy".into());
    set(&mut schema, &format!("{d}/properties/category"), "enum", strings(categories));
    set(&mut schema, &format!("{d}/properties/count"), "maximum", json!(MAX_TOTAL));
    set(&mut schema, "/$defs/ProxyPlan/properties/label", "maxLength", json!(MAX_LABEL));
    set(&mut schema, "/$defs/ProxyPlan/properties/prior", "maxLength", json!(MAX_LABEL));
    set(&mut schema, "/$defs/NamedColor/properties/name", "maxLength", json!(30));
    set(&mut schema, "/$defs/SizeHint/properties/words", "maxItems", json!(4));

    // Robots.
    let d = "/$defs/RobotPlan";
    order(&mut schema, d, &["phrase", "id", "model", "count", "mount"]);
    set(&mut schema, &format!("{d}/properties/id"), "pattern", json!(ID_PATTERN));
    set(&mut schema, &format!("{d}/properties/phrase"), "maxLength", json!(MAX_PHRASE));
    set(&mut schema, &format!("{d}/properties/near"), "pattern", json!(ID_PATTERN));
    let mut models: Vec<String> = sw_robots::registry().iter().map(|r| r.name.to_string()).collect();
    models.sort();
    set(&mut schema, &format!("{d}/properties/model"), "enum", strings(models));
    set(&mut schema, &format!("{d}/properties/count"), "maximum", json!(sw_plan::MAX_ROBOTS));

    // Every plain string of a relation or a mount is an id.
    set(&mut schema, "/$defs/Relation/properties/subject", "pattern", json!(ID_PATTERN));
    for def in ["Relation", "Mount"] {
        if let Some(Value::Array(variants)) = schema.pointer_mut(&format!("/$defs/{def}/oneOf")) {
            for v in variants.iter_mut() {
                let Some(props) = v.get_mut("properties").and_then(Value::as_object_mut) else { continue };
                for p in props.values_mut() {
                    let plain = p.get("type").and_then(Value::as_str) == Some("string")
                        && !p.as_object().is_some_and(|o| o.contains_key("const") || o.contains_key("enum"));
                    if plain && let Some(o) = p.as_object_mut() {
                        o.insert("pattern".into(), json!(ID_PATTERN));
                    }
                }
            }
        }
    }

    // The room.
    order(&mut schema, "/$defs/RoomPlan", &["kind", "size", "size_fixed", "door"]);

    // Notes.
    for list in ["not_understood", "approximated"] {
        set(&mut schema, &format!("/$defs/Understanding/properties/{list}"), "maxItems", json!(MAX_NOTES));
    }
    for (def, fields) in [("NotUnderstood", &["text", "reason"][..]), ("Approximation", &["text", "became", "reason"])]
    {
        for f in fields {
            set(&mut schema, &format!("/$defs/{def}/properties/{f}"), "maxLength", json!(MAX_TEXT));
        }
    }
    set(&mut schema, "/$defs/AnomalyRequest/properties/kinds", "maxItems", json!(5));
    schema
}

/// The relations stage's schema: `{"relations": [Relation]}`, with the plan's bounds.
pub fn relations_schema() -> Value {
    let plan = plan_schema();
    json!({
        "type": "object",
        "properties": { "relations": { "type": "array", "maxItems": MAX_RELATIONS, "items": { "$ref": "#/$defs/Relation" } } },
        "required": ["relations"],
        "$defs": plan.get("$defs").cloned().unwrap_or_else(|| json!({}))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::llm::fields::MAX_ID;

    /// Every `"type": "string"` without a bound, enum or const, with its path.
    fn unbounded(v: &Value, path: String, out: &mut Vec<String>) {
        match v {
            Value::Object(o) => {
                if o.get("type").and_then(Value::as_str) == Some("string")
                    && !["maxLength", "enum", "const", "pattern"].iter().any(|k| o.contains_key(*k))
                {
                    out.push(path.clone());
                }
                for (k, c) in o {
                    if k != "enum" && k != "const" {
                        unbounded(c, format!("{path}/{k}"), out);
                    }
                }
            }
            Value::Array(a) => a.iter().enumerate().for_each(|(i, c)| unbounded(c, format!("{path}/{i}"), out)),
            _ => {}
        }
    }

    #[test]
    fn the_model_facing_plan_schema_bounds_every_string_the_readers_cut() {
        let s = plan_schema();
        let mut loose = Vec::new();
        unbounded(&s, String::new(), &mut loose);
        assert!(loose.is_empty(), "unbounded strings: {loose:?}");
        assert_eq!(s["required"][0], "objects");
        assert_eq!(s["$defs"]["ObjectPlan"]["required"][0], "phrase");
        assert!(
            s["$defs"]["ObjectPlan"]["properties"]["category"]["enum"].as_array().unwrap().contains(&json!("proxy"))
        );
        assert!(s["$defs"]["RobotPlan"]["properties"]["model"]["enum"].as_array().unwrap().contains(&json!("ur5e")));
        assert_eq!(s["properties"]["objects"]["maxItems"], MAX_GROUPS);
        assert!(s.get("properties").unwrap().get("prompt").is_none());
        let r = relations_schema();
        assert_eq!(r["$defs"]["Relation"]["properties"]["subject"]["pattern"], ID_PATTERN);
        assert!(ID_PATTERN.ends_with(&format!("{{0,{}}}$", MAX_ID - 1)), "ids bounded as the reader cuts them");
    }
}
