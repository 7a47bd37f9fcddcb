//! JSON Schemas as a model's server sees them.
//!
//! Servers that constrain a model with a grammar (llama.cpp's `llama-server`,
//! llama-cpp-python, and servers built on them) convert the schema with converters that
//! implement a subset of JSON Schema. Both llama.cpp converters drop an object's own
//! `properties` when it also has `oneOf`/`anyOf` (schemars writes an internally tagged
//! enum flattened into a struct exactly so), and neither bounds a string or an array
//! unless the schema does, which is what lets a small model loop inside a string until
//! its context is full. [`for_model`] rewrites any schema, generically, into one every
//! converter keeps:
//!
//! - an object's own `properties`/`required` are moved into each of its `oneOf`/`anyOf`
//!   variants (so `{subject, oneOf: [{relation: on, target}, …]}` becomes
//!   `oneOf: [{subject, relation: on, target}, …]`): a new variant is picked up as is;
//! - objects with properties get `additionalProperties: false`;
//! - every string without a length, enum, const or pattern gets `maxLength`
//!   ([`DEFAULT_MAX_LENGTH`]), every array without `maxItems` gets [`DEFAULT_MAX_ITEMS`];
//!   bounds the caller set (matching its reader's limits) are kept, up to [`MAX_REPEAT`];
//! - `null` alternatives of optional properties are dropped (an absent property says
//!   the same), and so are schemars' numeric `format`s and `default`s, which converters
//!   do not know.
//!
//! [`to_ordered_string`] writes a schema with each object's `properties` in the order of
//! its `required` list (then the rest): converters make the model write properties in
//! the order they are listed, so the caller decides what comes first (ids before
//! relations, the phrase before its category).

use serde_json::{Map, Value};

/// `maxLength` of strings the caller left unbounded.
pub const DEFAULT_MAX_LENGTH: u64 = 200;
/// `maxItems` of arrays the caller left unbounded.
pub const DEFAULT_MAX_ITEMS: u64 = 64;
/// The largest `maxLength`/`maxItems` sent: llama.cpp's grammar parser refuses a
/// repetition of more than 2000 rules, and llama-cpp-python 0.3.36's converter unrolls a
/// `maxLength` of 1500 into a grammar its server dies on (checked here); bigger bounds are
/// lowered to this.
pub const MAX_REPEAT: u64 = 1000;

/// The schema rewritten for grammar-constrained servers (see the module docs).
/// Idempotent.
pub fn for_model(schema: &Value) -> Value {
    let mut s = schema.clone();
    rewrite(&mut s);
    s
}

fn is_null_schema(v: &Value) -> bool {
    v.get("type").and_then(Value::as_str) == Some("null") || v.get("const").is_some_and(Value::is_null)
}

fn rewrite(v: &mut Value) {
    match v {
        Value::Array(items) => items.iter_mut().for_each(rewrite),
        Value::Object(o) => {
            rewrite_object(o);
            for (k, child) in o.iter_mut() {
                // Enum values and consts are data, not schemas.
                if k != "enum" && k != "const" && k != "examples" {
                    rewrite(child);
                }
            }
        }
        _ => {}
    }
}

fn rewrite_object(o: &mut Map<String, Value>) {
    o.remove("default");
    // `"type": ["string", "null"]` → `"string"`.
    if let Some(Value::Array(types)) = o.get("type") {
        let kept: Vec<Value> = types.iter().filter(|t| t.as_str() != Some("null")).cloned().collect();
        match kept.len() {
            0 => {}
            1 => {
                o.insert("type".into(), kept[0].clone());
            }
            _ => {
                o.insert("type".into(), Value::Array(kept));
            }
        }
    }
    // `anyOf: [X, {type: null}]` → X.
    for key in ["anyOf", "oneOf"] {
        if let Some(Value::Array(alts)) = o.get(key) {
            let kept: Vec<Value> = alts.iter().filter(|a| !is_null_schema(a)).cloned().collect();
            if kept.len() == 1 && kept.len() < alts.len() {
                o.remove(key);
                if let Value::Object(only) = &kept[0] {
                    for (k, val) in only {
                        o.entry(k.clone()).or_insert_with(|| val.clone());
                    }
                }
            } else if kept.len() < alts.len() {
                o.insert(key.into(), Value::Array(kept));
            }
        }
    }
    // Own properties into each variant.
    let variants_key = ["oneOf", "anyOf"].into_iter().find(|k| o.get(*k).is_some_and(Value::is_array));
    if let Some(key) = variants_key
        && (o.contains_key("properties") || o.contains_key("required"))
    {
        let own_props = o.remove("properties").and_then(|p| p.as_object().cloned()).unwrap_or_default();
        let own_required: Vec<Value> = o.remove("required").and_then(|r| r.as_array().cloned()).unwrap_or_default();
        o.remove("additionalProperties");
        if let Some(Value::Array(variants)) = o.get_mut(key) {
            for variant in variants.iter_mut() {
                let Value::Object(vo) = variant else { continue };
                if vo.contains_key("$ref") {
                    // A referenced variant cannot be extended in place: wrap it.
                    let r = vo.clone();
                    *vo = Map::from_iter([("allOf".to_string(), Value::Array(vec![Value::Object(r)]))]);
                }
                let mut props = own_props.clone();
                if let Some(Value::Object(vp)) = vo.get("properties") {
                    for (k, val) in vp {
                        props.insert(k.clone(), val.clone());
                    }
                }
                let mut required = own_required.clone();
                for r in vo.get("required").and_then(Value::as_array).into_iter().flatten() {
                    if !required.contains(r) {
                        required.push(r.clone());
                    }
                }
                vo.insert("type".into(), Value::String("object".into()));
                vo.insert("properties".into(), Value::Object(props));
                vo.insert("required".into(), Value::Array(required));
            }
        }
        if o.get("type").and_then(Value::as_str) == Some("object") {
            o.remove("type");
        }
    }
    let ty = o.get("type").and_then(Value::as_str).map(str::to_string);
    // Numeric formats (schemars' uint32, double) are not JSON Schema formats converters know.
    if ty.as_deref() != Some("string") {
        o.remove("format");
    }
    match ty.as_deref() {
        Some("object") | None if o.get("properties").is_some_and(Value::is_object) => {
            o.entry("additionalProperties").or_insert(Value::Bool(false));
        }
        _ => {}
    }
    for key in ["maxLength", "maxItems"] {
        if o.get(key).and_then(Value::as_u64).is_some_and(|n| n > MAX_REPEAT) {
            o.insert(key.into(), Value::from(MAX_REPEAT));
        }
    }
    match ty.as_deref() {
        Some("string") if !["maxLength", "enum", "const", "pattern", "format"].iter().any(|k| o.contains_key(*k)) => {
            o.insert("maxLength".into(), Value::from(DEFAULT_MAX_LENGTH));
        }
        Some("array") if !o.contains_key("maxItems") && !o.get("items").is_some_and(Value::is_array) => {
            o.insert("maxItems".into(), Value::from(DEFAULT_MAX_ITEMS));
        }
        _ => {}
    }
}

/// JSON text of `v` with each object's `properties` in the order of its `required` list,
/// then the rest in their own order.
pub fn to_ordered_string(v: &Value) -> String {
    let mut out = String::new();
    write(v, None, &mut out);
    out
}

fn write(v: &Value, order: Option<&[Value]>, out: &mut String) {
    match v {
        Value::Object(o) => {
            let mut keys: Vec<&String> = o.keys().collect();
            if let Some(order) = order {
                let rank = |k: &str| order.iter().position(|r| r.as_str() == Some(k)).unwrap_or(usize::MAX);
                keys.sort_by_key(|k| rank(k));
            }
            let required = o.get("required").and_then(Value::as_array).map(Vec::as_slice);
            out.push('{');
            for (i, k) in keys.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push_str(&Value::String((*k).clone()).to_string());
                out.push(':');
                let child_order = if *k == "properties" { required } else { None };
                write(&o[k.as_str()], child_order, out);
            }
            out.push('}');
        }
        Value::Array(a) => {
            out.push('[');
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write(x, None, out);
            }
            out.push(']');
        }
        other => out.push_str(&other.to_string()),
    }
}

/// Every `$ref` in `v` resolves to a definition in its root (`#/$defs/…`).
pub fn refs_resolve(root: &Value) -> Result<(), String> {
    fn walk(v: &Value, root: &Value) -> Result<(), String> {
        match v {
            Value::Object(o) => {
                if let Some(r) = o.get("$ref").and_then(Value::as_str) {
                    let ptr = r.strip_prefix('#').ok_or_else(|| format!("external reference {r}"))?;
                    if root.pointer(ptr).is_none() {
                        return Err(format!("unresolved reference {r}"));
                    }
                }
                o.values().try_for_each(|c| walk(c, root))
            }
            Value::Array(a) => a.iter().try_for_each(|c| walk(c, root)),
            _ => Ok(()),
        }
    }
    walk(root, root)
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;

    #[test]
    fn own_properties_move_into_each_variant_and_everything_is_bounded() {
        let s = json!({
            "$defs": {"Wall": {"type": "string", "enum": ["north", "south"]}},
            "type": "object",
            "properties": {"subject": {"type": "string"}, "note": {"type": ["string", "null"], "format": "x"}},
            "required": ["subject"],
            "oneOf": [
                {"type": "object", "properties": {"relation": {"const": "on"}, "target": {"type": "string"}}, "required": ["relation", "target"]},
                {"type": "object", "properties": {"relation": {"const": "against_wall"}, "wall": {"anyOf": [{"$ref": "#/$defs/Wall"}, {"type": "null"}]}}, "required": ["relation"]},
                {"type": "object", "properties": {"relation": {"const": "rows"}, "n": {"type": "integer", "format": "uint32", "default": 2}}, "required": ["relation"]}
            ]
        });
        let m = for_model(&s);
        assert!(m.get("properties").is_none() && m.get("required").is_none(), "{m}");
        for v in m["oneOf"].as_array().unwrap() {
            assert_eq!(v["required"][0], "subject", "{v}");
            assert_eq!(v["properties"]["subject"]["maxLength"], DEFAULT_MAX_LENGTH);
            assert_eq!(v["additionalProperties"], false);
        }
        assert_eq!(m["oneOf"][1]["properties"]["wall"], json!({"$ref": "#/$defs/Wall"}));
        assert_eq!(m["oneOf"][2]["properties"]["n"], json!({"type": "integer"}));
        assert_eq!(m["oneOf"][0]["properties"]["note"]["type"], "string");
        assert_eq!(for_model(&m), m, "idempotent");
        refs_resolve(&m).unwrap();
    }

    #[test]
    fn caller_bounds_are_kept_and_arrays_are_bounded() {
        let s = json!({"type": "object", "properties": {
            "a": {"type": "array", "items": {"type": "string", "maxLength": 5}, "maxItems": 3},
            "b": {"type": "array", "items": {"type": "string", "enum": ["x"]}},
            "c": {"type": "string", "maxLength": 4000}
        }});
        let m = for_model(&s);
        assert_eq!(m["properties"]["c"]["maxLength"], MAX_REPEAT, "what a converter can take");
        assert_eq!(m["properties"]["a"]["maxItems"], 3);
        assert_eq!(m["properties"]["a"]["items"]["maxLength"], 5);
        assert_eq!(m["properties"]["b"]["maxItems"], DEFAULT_MAX_ITEMS);
        assert!(m["properties"]["b"]["items"].get("maxLength").is_none());
    }

    #[test]
    fn properties_are_written_in_the_order_of_required() {
        let s = json!({"type": "object", "required": ["phrase", "id"], "properties": {"count": {}, "id": {}, "phrase": {}}});
        let text = to_ordered_string(&s);
        let (p, i, c) =
            (text.find("\"phrase\":").unwrap(), text.find("\"id\":").unwrap(), text.find("\"count\":").unwrap());
        assert!(p < i && i < c, "{text}");
        assert_eq!(serde_json::from_str::<Value>(&text).unwrap(), s);
    }
}
