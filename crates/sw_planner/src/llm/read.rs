//! Reading a model's answer into the plan's own types, field by field: anything that is
//! not part of a plan (coordinates, commands, extra fields) is dropped and noted, names
//! are cut to length, counts and sizes are clamped, categories and robots must resolve to
//! the catalog and the robot registry (else a labelled proxy, or the robot is left out
//! with a note), references between groups must resolve to ids of the plan. The limits
//! here are the model-facing schema's bounds ([`super::schema`]).

use std::collections::{BTreeMap, BTreeSet};

use serde_json::{Map, Value};
use sw_plan::{
    Approximation, ExplicitSize, Mount, NamedColor, NotUnderstood, ObjectPlan, PlanError, ProxyPlan, Relation,
    RelationKind, RobotPlan, RoomKind, SCHEMA_VERSION, ScenePlan, SizeHint, SizeWord, Wall,
};

use super::fields::{MAX_ID, MAX_LABEL, MAX_TEXT, POSITION_KEYS, Refs, field, note, number, sanitize_id, text, wall};
use super::relation::read_relation;
use crate::vocab::{self, Noun};

/// The most object instances a plan may hold (as the offline planner).
pub(crate) const MAX_TOTAL: u32 = 2000;
/// The most object groups read from one answer.
pub(crate) const MAX_GROUPS: usize = 32;
/// The most relations read from one answer.
pub(crate) const MAX_RELATIONS: usize = 128;
/// The most robot entries read from one answer.
pub(crate) const MAX_ROBOT_GROUPS: usize = 16;
/// The most entries of each `understanding` list read.
pub(crate) const MAX_NOTES: usize = 20;
pub(crate) const ROOM_SIDE: (f64, f64) = (1.0, 300.0);
pub(crate) const ROOM_HEIGHT: (f64, f64) = (2.0, 30.0);
/// Object dimensions above this are not believed, m.
pub(crate) const MAX_OBJECT_SIDE: f64 = 50.0;

pub fn read_object(v: &Value, index: usize) -> Option<(ObjectPlan, Vec<Approximation>)> {
    let mut notes = Vec::new();
    let owned;
    let o = match v {
        Value::Object(o) => o,
        Value::String(s) => {
            owned = Map::from_iter([("phrase".to_string(), Value::String(s.clone()))]);
            &owned
        }
        _ => return None,
    };
    let raw_category = text(field(o, &["category", "type", "kind", "class"]), MAX_LABEL);
    let phrase = text(field(o, &["phrase", "name", "label", "description"]), MAX_TEXT)
        .or_else(|| raw_category.clone())
        .or_else(|| text(o.get("proxy").and_then(|p| p.get("label")), MAX_LABEL))?;
    if o.keys().any(|k| POSITION_KEYS.contains(&k.as_str())) {
        note(&mut notes, &phrase, "ignored", "the model gave coordinates; the layout solver places objects");
    }
    // Count.
    let count = match number(field(o, &["count", "quantity", "number", "n"])) {
        None => 1,
        Some(c) if c < 0.5 => {
            note(&mut notes, &phrase, "1", "the count must be at least 1");
            1
        }
        Some(c) if c > f64::from(MAX_TOTAL) => {
            note(&mut notes, &phrase, &MAX_TOTAL.to_string(), &format!("at most {MAX_TOTAL} objects per scene"));
            MAX_TOTAL
        }
        Some(c) => c.round() as u32,
    };
    // Colour and size.
    let color = read_color(field(o, &["color", "colour"]), &phrase, &mut notes);
    let size = read_size(o, &phrase, &mut notes);
    // Category: the catalog name, or what the phrase names, else a labelled proxy.
    let named = raw_category.as_deref().filter(|c| *c != "proxy");
    let category = named.and_then(vocab::category).or_else(|| match vocab::noun(&phrase) {
        Noun::Category(c) => Some(c),
        _ => None,
    });
    let (category, proxy) = match category {
        Some(c) => {
            if let Some(raw) = named
                && sw_catalog::find(&raw.to_lowercase().replace([' ', '-'], "_")).is_none()
            {
                note(&mut notes, raw, c, "read as the nearest catalog category");
            }
            (c.to_string(), None)
        }
        None => {
            let label = text(o.get("proxy").and_then(|p| p.get("label")), MAX_LABEL)
                .or_else(|| named.map(|n| n.replace('_', " ")))
                .unwrap_or_else(|| phrase.chars().take(MAX_LABEL).collect());
            let given = o.get("proxy").and_then(Value::as_object);
            let mut p = vocab::proxy(&label, false, &size.words, &size.explicit);
            if let Some(g) = given {
                if let Some(s) = g.get("size").and_then(Value::as_object) {
                    let dims = [number(s.get("width")), number(s.get("depth")), number(s.get("height"))];
                    if dims.iter().all(|d| d.is_some_and(|d| d > 0.0 && d <= MAX_OBJECT_SIDE)) {
                        let d = dims.map(|d| d.unwrap_or(0.5).clamp(0.02, 20.0));
                        p.size = sw_plan::Dims::new(d[0], d[1], d[2]);
                    }
                }
                if let Some(m) = g.get("movable").and_then(Value::as_bool) {
                    p.movable = m;
                }
                if let Some(prior) = text(g.get("prior"), MAX_LABEL) {
                    p.prior = prior;
                }
            }
            note(
                &mut notes,
                &phrase,
                &format!("labelled proxy '{label}'"),
                "no catalog asset for it; a box of its size stands in",
            );
            ("proxy".to_string(), Some(ProxyPlan { label, ..p }))
        }
    };
    let id = text(field(o, &["id", "group", "key"]), MAX_ID * 2)
        .map(|s| sanitize_id(&s))
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| {
            let base = if category == "proxy" { "object".to_string() } else { category.clone() };
            format!("{base}_{}", index + 1)
        });
    Some((ObjectPlan { id, category, phrase, count, color, size, proxy }, notes))
}

fn read_color(v: Option<&Value>, phrase: &str, notes: &mut Vec<Approximation>) -> Option<NamedColor> {
    let v = v?;
    let from_rgba = |rgba: &Value| -> Option<[f64; 4]> {
        let a = rgba.as_array()?;
        let mut c: Vec<f64> = a.iter().map(|x| number(Some(x))).collect::<Option<Vec<f64>>>()?;
        if c.len() == 3 {
            c.push(1.0);
        }
        if c.len() != 4 || c.iter().any(|x| *x < 0.0) {
            return None;
        }
        // 0..255 colours.
        if c.iter().any(|x| *x > 1.0) {
            if c.iter().any(|x| *x > 255.0) {
                return None;
            }
            c = c.iter().map(|x| x / 255.0).collect();
        }
        Some([c[0], c[1], c[2], c[3].clamp(0.0, 1.0)])
    };
    match v {
        Value::String(s) => {
            let c = vocab::color(s);
            if c.is_none() {
                note(
                    notes,
                    phrase,
                    "its own colour",
                    &format!("'{}' is not a colour the planner knows", s.chars().take(30).collect::<String>()),
                );
            }
            c
        }
        Value::Object(o) => {
            let name = text(o.get("name"), 30);
            let known = name.as_deref().and_then(vocab::color);
            match (o.get("rgba").and_then(from_rgba), known) {
                (Some(rgba), k) => {
                    Some(NamedColor { name: k.map(|k| k.name).or(name).unwrap_or_else(|| "custom".into()), rgba })
                }
                (None, Some(k)) => Some(k),
                (None, None) => {
                    note(notes, phrase, "its own colour", "the colour could not be read");
                    None
                }
            }
        }
        _ => None,
    }
}

fn read_size(o: &Map<String, Value>, phrase: &str, notes: &mut Vec<Approximation>) -> SizeHint {
    let mut hint = SizeHint::default();
    let Some(v) = field(o, &["size", "dimensions"]) else {
        return hint;
    };
    let mut explicit_from = |e: &Map<String, Value>, hint: &mut SizeHint| {
        for (name, slot) in [("width", 0), ("depth", 1), ("height", 2)] {
            if let Some(x) = number(e.get(name)) {
                if x > 0.0 && x <= MAX_OBJECT_SIDE {
                    match slot {
                        0 => hint.explicit.width = Some(x),
                        1 => hint.explicit.depth = Some(x),
                        _ => hint.explicit.height = Some(x),
                    }
                } else {
                    note(notes, phrase, "its usual size", &format!("a {name} of {x} m is not plausible"));
                }
            }
        }
    };
    match v {
        Value::String(s) => hint.words.extend(s.split_whitespace().filter_map(vocab::size_word)),
        Value::Object(s) => {
            if let Some(ws) = s.get("words").and_then(Value::as_array) {
                let mut words: Vec<SizeWord> = Vec::new();
                for w in ws.iter().filter_map(Value::as_str).filter_map(vocab::size_word) {
                    if !words.contains(&w) {
                        words.push(w);
                    }
                }
                hint.words = words;
            }
            match s.get("explicit").and_then(Value::as_object) {
                Some(e) => explicit_from(e, &mut hint),
                None => explicit_from(s, &mut hint),
            }
        }
        _ => {}
    }
    hint
}

fn read_robot(v: &Value, index: usize, refs: &Refs, notes: &mut Vec<Approximation>) -> Option<RobotPlan> {
    let o = match v {
        Value::Object(o) => o.clone(),
        Value::String(s) => Map::from_iter([("model".to_string(), Value::String(s.clone()))]),
        _ => return None,
    };
    let raw_model = text(field(&o, &["model", "name", "type", "robot"]), MAX_LABEL);
    let phrase = text(field(&o, &["phrase", "description"]), MAX_TEXT).or_else(|| raw_model.clone())?;
    let found = raw_model.as_deref().and_then(vocab::robot_model).or_else(|| vocab::robot_model(&phrase));
    let Some((model, approx)) = found else {
        note(notes, &phrase, "left out", "not a robot the registry knows");
        return None;
    };
    if let Some(reason) = approx {
        note(notes, &phrase, model, &reason);
    }
    let def = sw_robots::find(model)?;
    let count = number(field(&o, &["count", "quantity", "number"])).map_or(1, |c| c.round().clamp(1.0, 16.0) as u32);
    let id = text(o.get("id"), MAX_ID * 2)
        .map(|s| sanitize_id(&s))
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| if index == 0 { model.to_string() } else { format!("{model}_{}", index + 1) });
    let near = text(o.get("near"), MAX_TEXT).and_then(|n| refs.resolve(&n));
    let mount_v = o.get("mount");
    let (mount_name, mount_target) = match mount_v {
        Some(Value::String(s)) => (s.to_lowercase(), None),
        Some(Value::Object(m)) => (
            text(field(m, &["mount", "type", "kind"]), 30).unwrap_or_default().to_lowercase(),
            text(field(m, &["target", "on", "object"]), MAX_TEXT),
        ),
        _ => ("auto".into(), None),
    };
    let arm = def.kind == sw_robots::RobotKind::Arm;
    let mount = match mount_name.replace([' ', '-'], "_").as_str() {
        _ if !arm => Mount::Floor,
        "floor" | "ground" => Mount::Floor,
        "pedestal" | "stand" => Mount::Pedestal,
        "mobile_base" | "mobile" | "cart" | "mobile_cart" => Mount::MobileBase,
        "on_surface" | "surface" | "table" | "on" | "bench" => {
            match mount_target.as_deref().and_then(|t| refs.resolve(t)) {
                Some(target) => Mount::OnSurface { target },
                None => {
                    note(
                        notes,
                        &phrase,
                        "mounted where the layout decides",
                        "the surface named is not an object group of the plan",
                    );
                    Mount::Auto
                }
            }
        }
        _ => Mount::Auto,
    };
    Some(RobotPlan { id, model: def.name.to_string(), phrase, count, mount, near })
}

fn read_room(v: Option<&Value>, notes: &mut Vec<Approximation>) -> sw_plan::RoomPlan {
    let o = v.and_then(Value::as_object).cloned().unwrap_or_default();
    let raw_kind = text(field(&o, &["kind", "type", "name"]), MAX_LABEL);
    let kind = match raw_kind.as_deref().map(|k| (k, vocab::room_kind(k))) {
        Some((_, Some(k))) => k,
        Some((raw, None)) => {
            note(notes, raw, "room", "not a room kind the planner knows");
            RoomKind::Room
        }
        None => RoomKind::Room,
    };
    let mut size = kind.default_size();
    let given = match field(&o, &["size", "dimensions"]) {
        Some(Value::Object(s)) => Some([number(s.get("width")), number(s.get("depth")), number(s.get("height"))]),
        Some(Value::Array(a)) => Some([number(a.first()), number(a.get(1)), number(a.get(2))]),
        _ => None,
    };
    let mut any_given = false;
    if let Some([w, d, h]) = given {
        for (slot, value, (lo, hi), name) in
            [(0, w, ROOM_SIDE, "width"), (1, d, ROOM_SIDE, "depth"), (2, h, ROOM_HEIGHT, "height")]
        {
            let Some(x) = value else { continue };
            any_given = true;
            let c = x.clamp(lo, hi);
            if c != x {
                note(
                    notes,
                    &format!("room {name} {x} m"),
                    &format!("{c} m"),
                    &format!("room {name}s are kept within {lo} … {hi} m"),
                );
            }
            match slot {
                0 => size.width = c,
                1 => size.depth = c,
                _ => size.height = c,
            }
        }
    }
    let size_fixed = any_given && o.get("size_fixed").and_then(Value::as_bool).unwrap_or(false);
    let door = wall(o.get("door")).unwrap_or(Wall::South);
    sw_plan::RoomPlan { kind, size, size_fixed, door }
}

fn read_understanding(v: Option<&Value>) -> (Vec<NotUnderstood>, Vec<Approximation>) {
    let mut nu = Vec::new();
    let mut ap = Vec::new();
    let Some(o) = v.and_then(Value::as_object) else {
        return (nu, ap);
    };
    for item in o.get("not_understood").and_then(Value::as_array).into_iter().flatten().take(MAX_NOTES) {
        let (t, r) = match item {
            Value::String(s) => (text(Some(&Value::String(s.clone())), MAX_TEXT), None),
            Value::Object(m) => (text(m.get("text"), MAX_TEXT), text(m.get("reason"), MAX_TEXT)),
            _ => (None, None),
        };
        if let Some(text) = t {
            nu.push(NotUnderstood { text, reason: r.unwrap_or_else(|| "the model could not use it".into()) });
        }
    }
    for item in o.get("approximated").and_then(Value::as_array).into_iter().flatten().take(MAX_NOTES) {
        if let Some(m) = item.as_object()
            && let Some(t) = text(m.get("text"), MAX_TEXT)
        {
            ap.push(Approximation {
                text: t,
                became: text(m.get("became"), MAX_TEXT).unwrap_or_default(),
                reason: text(m.get("reason"), MAX_TEXT).unwrap_or_else(|| "approximated by the model".into()),
            });
        }
    }
    (nu, ap)
}

/// Some models wrap the plan: `{"scene_plan": {...}}` or `{"plan": {...}}`.
fn unwrap_plan(answer: &Value) -> &Value {
    if let Some(o) = answer.as_object()
        && o.len() == 1
        && let Some(inner) = o.values().next()
        && inner.get("room").is_some()
    {
        return inner;
    }
    answer
}

const TOP_LEVEL: &[&str] = &[
    "schema_version",
    "prompt",
    "room",
    "objects",
    "relations",
    "robots",
    "rules_profile",
    "anomaly",
    "understanding",
];

/// Reads a model's answer into a validated plan of `prompt`. Problems that can be
/// corrected (names, counts, unknown categories, stray fields) are corrected and noted
/// in `understanding.approximated`; the rest are errors naming the field.
pub fn read_plan(prompt: &str, answer: &Value) -> Result<ScenePlan, PlanError> {
    let answer = unwrap_plan(answer);
    let Some(o) = answer.as_object() else {
        return Err(PlanError::Shape { path: "$".into(), message: "the answer is not a JSON object".into() });
    };
    let mut notes: Vec<Approximation> = Vec::new();
    for k in o.keys().filter(|k| !TOP_LEVEL.contains(&k.as_str())) {
        note(&mut notes, k, "ignored", "not a field of a scene plan");
    }
    let room = read_room(o.get("room"), &mut notes);
    // Objects.
    let mut objects: Vec<ObjectPlan> = Vec::new();
    let mut raw_ids: BTreeMap<String, String> = BTreeMap::new();
    let mut used: BTreeSet<String> = BTreeSet::new();
    let mut total = 0u32;
    let list = o.get("objects").and_then(Value::as_array).cloned().unwrap_or_default();
    if list.len() > MAX_GROUPS {
        note(
            &mut notes,
            &format!("{} object groups", list.len()),
            &MAX_GROUPS.to_string(),
            "at most 32 object groups per plan",
        );
    }
    for (i, v) in list.iter().take(MAX_GROUPS).enumerate() {
        let Some((mut obj, n)) = read_object(v, i) else {
            note(&mut notes, &short(v), "ignored", "not an object group");
            continue;
        };
        notes.extend(n.into_iter().filter(|a| !notes.contains(a)).collect::<Vec<_>>());
        if total + obj.count > MAX_TOTAL {
            let allowed = MAX_TOTAL.saturating_sub(total);
            note(&mut notes, &obj.phrase, &allowed.to_string(), &format!("at most {MAX_TOTAL} objects per scene"));
            if allowed == 0 {
                continue;
            }
            obj.count = allowed;
        }
        total += obj.count;
        let mut id = obj.id.clone();
        let mut k = 2;
        while used.contains(&id) {
            id = format!("{}_{k}", obj.id);
            k += 1;
        }
        if let Some(raw) = v.get("id").and_then(Value::as_str) {
            raw_ids.entry(raw.to_string()).or_insert_with(|| id.clone());
        }
        raw_ids.entry(obj.id.clone()).or_insert_with(|| id.clone());
        used.insert(id.clone());
        obj.id = id;
        objects.push(obj);
    }
    let refs = Refs {
        ids: raw_ids,
        groups: objects.iter().map(|g| (g.id.clone(), g.category.clone(), g.phrase.clone())).collect(),
    };
    // Robots (before the relations: a relation may constrain a robot group).
    let listed = o.get("robots").and_then(Value::as_array).map_or(0, Vec::len);
    if listed > MAX_ROBOT_GROUPS {
        note(
            &mut notes,
            &format!("{listed} robot entries"),
            &MAX_ROBOT_GROUPS.to_string(),
            "at most 16 robot entries per plan",
        );
    }
    let mut robots: Vec<RobotPlan> = Vec::new();
    let mut robot_total = 0u32;
    for (i, v) in o.get("robots").and_then(Value::as_array).into_iter().flatten().take(MAX_ROBOT_GROUPS).enumerate() {
        let Some(mut r) = read_robot(v, i, &refs, &mut notes) else { continue };
        if robot_total + r.count > sw_plan::MAX_ROBOTS {
            let allowed = sw_plan::MAX_ROBOTS.saturating_sub(robot_total);
            note(&mut notes, &r.phrase, &allowed.to_string(), "at most 16 robots per scene");
            if allowed == 0 {
                continue;
            }
            r.count = allowed;
        }
        robot_total += r.count;
        let base = r.id.clone();
        let mut k = 2;
        while used.contains(&r.id) {
            r.id = format!("{base}_{k}");
            k += 1;
        }
        used.insert(r.id.clone());
        robots.push(r);
    }
    // Relations.
    let mut refs = refs;
    for r in &robots {
        refs.ids.entry(r.id.clone()).or_insert_with(|| r.id.clone());
        refs.groups.push((r.id.clone(), r.model.clone(), r.phrase.clone()));
    }
    let mut relations: Vec<Relation> = Vec::new();
    let listed = o.get("relations").and_then(Value::as_array).map_or(0, Vec::len);
    if listed > MAX_RELATIONS {
        note(&mut notes, &format!("{listed} relations"), &MAX_RELATIONS.to_string(), "at most 128 relations per plan");
    }
    for v in o.get("relations").and_then(Value::as_array).into_iter().flatten().take(MAX_RELATIONS) {
        if let Some(r) = read_relation(v, &refs, &mut notes)
            && !relations.contains(&r)
        {
            relations.push(r);
        }
    }
    // Proxies that rest on something are sized as tabletop items when the model gave no size.
    for g in objects.iter_mut() {
        let resting = relations.iter().any(|r| r.subject == g.id && matches!(r.kind, RelationKind::On { .. }));
        if let Some(p) = &mut g.proxy
            && resting
            && !p.movable
            && g.size.explicit.is_empty()
        {
            let fresh = vocab::proxy(&p.label, true, &g.size.words, &ExplicitSize::default());
            if fresh.movable {
                *p = fresh;
            }
        }
    }
    if objects.is_empty() && robots.is_empty() {
        return Err(PlanError::Shape {
            path: "objects".into(),
            message: "the plan holds no objects and no robots; list what the description asks for".into(),
        });
    }
    // Rules profile.
    let known: BTreeSet<&str> = RoomKind::ALL.iter().map(|k| k.rules_profile()).collect();
    let rules_profile = match text(o.get("rules_profile"), MAX_LABEL) {
        Some(p) if known.contains(p.as_str()) => p,
        Some(p) => {
            note(&mut notes, &p, room.kind.rules_profile(), "not a rules profile; used the room kind's");
            room.kind.rules_profile().to_string()
        }
        None => room.kind.rules_profile().to_string(),
    };
    // Anomaly requests only when well formed.
    let anomaly = o.get("anomaly").filter(|a| !a.is_null()).and_then(|a| {
        let parsed = serde_json::from_value::<sw_plan::AnomalyRequest>(a.clone()).ok();
        if parsed.is_none() {
            note(&mut notes, "anomaly", "ignored", "the anomaly request could not be read");
        }
        parsed
    });
    let (not_understood, mut approximated) = read_understanding(o.get("understanding"));
    for n in notes {
        if !approximated.contains(&n) {
            approximated.push(n);
        }
    }
    let plan = ScenePlan {
        schema_version: SCHEMA_VERSION,
        prompt: prompt.trim().to_string(),
        room,
        objects,
        relations,
        robots,
        rules_profile,
        anomaly,
        understanding: sw_plan::Understanding { not_understood, approximated },
    };
    // Through the contract's own entry point: errors name the field.
    let text =
        serde_json::to_string(&plan).map_err(|e| PlanError::Shape { path: "$".into(), message: e.to_string() })?;
    ScenePlan::from_json(&text)
}

fn short(v: &Value) -> String {
    v.to_string().chars().take(60).collect()
}

/// Reads the relations stage's answer: relations between the plan's groups (others are
/// dropped and noted).
pub fn read_relations(plan: &ScenePlan, answer: &Value) -> (Vec<Relation>, Vec<Approximation>) {
    let refs = Refs {
        ids: plan.objects.iter().map(|o| (o.id.clone(), o.id.clone())).collect(),
        groups: plan.objects.iter().map(|g| (g.id.clone(), g.category.clone(), g.phrase.clone())).collect(),
    };
    let list = match answer {
        Value::Array(a) => a.clone(),
        v => v.get("relations").and_then(Value::as_array).cloned().unwrap_or_default(),
    };
    let mut notes = Vec::new();
    let mut out: Vec<Relation> = Vec::new();
    if list.len() > MAX_RELATIONS {
        note(
            &mut notes,
            &format!("{} relations", list.len()),
            &MAX_RELATIONS.to_string(),
            "at most 128 relations per plan",
        );
    }
    for v in list.iter().take(MAX_RELATIONS) {
        if let Some(r) = read_relation(v, &refs, &mut notes)
            && !out.contains(&r)
        {
            out.push(r);
        }
    }
    (out, notes)
}
