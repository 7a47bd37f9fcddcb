//! Which objects a reference picks out of a laid-out scene: by name, category, label,
//! colour, ordinal and position relative to other objects.

use std::cmp::Ordering;

use sw_plan::{LaidOutScene, PlacedObject, ScenePlan, Support, Wall};
use sw_planner::vocab;

use crate::ast::{Reference, Spatial};

/// A scene to edit: its plan and its layout.
#[derive(Debug, Clone, Copy)]
pub struct SceneView<'a> {
    pub plan: &'a ScenePlan,
    pub layout: &'a LaidOutScene,
}

/// What a reference picked: object names and robot names.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Selection {
    pub objects: Vec<String>,
    pub robots: Vec<String>,
}

impl Selection {
    pub fn is_empty(&self) -> bool {
        self.objects.is_empty() && self.robots.is_empty()
    }

    pub fn names(&self) -> Vec<String> {
        self.objects.iter().chain(&self.robots).cloned().collect()
    }
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ResolveError {
    #[error("nothing in the scene is {what} (it holds {present})")]
    NoMatch { what: String, present: String },
    #[error(
        "{what} could be any of {candidates}; say which (by name, e.g. '{example}', or 'the second …', or where it is)"
    )]
    Ambiguous { what: String, candidates: String, example: String },
}

/// Something with a place: an object or a robot.
#[derive(Debug, Clone)]
struct Thing {
    name: String,
    robot: bool,
    pos: [f64; 3],
    yaw: f64,
    /// Half extents of the footprint in the world (axis-aligned), and height.
    half: [f64; 2],
    height: f64,
}

fn thing_of(o: &PlacedObject) -> Thing {
    let (s, c) = o.yaw.sin_cos();
    let (w, d) = (o.size[0] / 2.0, o.size[1] / 2.0);
    Thing {
        name: o.name.clone(),
        robot: false,
        pos: o.pos,
        yaw: o.yaw,
        half: [c.abs() * w + s.abs() * d, s.abs() * w + c.abs() * d],
        height: o.size[2],
    }
}

/// The forward direction of someone standing in the doorway looking into the room.
pub fn forward(view: &SceneView<'_>) -> [f64; 2] {
    let o = view.layout.room.door.wall.outward();
    [-o[0], -o[1]]
}

/// Their right hand.
pub fn right(view: &SceneView<'_>) -> [f64; 2] {
    let f = forward(view);
    [f[1], -f[0]]
}

/// Gap between two footprints (0 when they touch or overlap), m.
fn gap(a: &Thing, b: &Thing) -> f64 {
    let dx = ((a.pos[0] - b.pos[0]).abs() - a.half[0] - b.half[0]).max(0.0);
    let dy = ((a.pos[1] - b.pos[1]).abs() - a.half[1] - b.half[1]).max(0.0);
    dx.hypot(dy)
}

/// Natural order of names: `chair_2` before `chair_10`.
pub fn name_order(a: &str, b: &str) -> Ordering {
    let split = |s: &str| -> (String, u64) {
        match s.rsplit_once('_') {
            Some((base, n)) if n.chars().all(|c| c.is_ascii_digit()) && !n.is_empty() => {
                (base.to_string(), n.parse().unwrap_or(0))
            }
            _ => (s.to_string(), 0),
        }
    };
    split(a).cmp(&split(b))
}

fn noun_matches_object(view: &SceneView<'_>, noun: &str, o: &PlacedObject) -> bool {
    if noun.is_empty() {
        return true;
    }
    let n = noun.trim();
    if n == o.name || n == o.group {
        return true;
    }
    let words = vocab::words(n);
    if words.is_empty() {
        return true;
    }
    if let Some(c) = vocab::category(n)
        && c == o.category
    {
        return true;
    }
    // The label ("spectrum analyzer") ends with the noun ("analyzer").
    let label = vocab::words(&o.label);
    if label.len() >= words.len() && label[label.len() - words.len()..] == words[..] {
        return true;
    }
    // The group's phrase names it ("two long workbenches").
    view.plan.object(&o.group).is_some_and(|g| {
        let p = vocab::words(&g.phrase);
        p.len() >= words.len() && p.windows(words.len()).any(|w| w == &words[..]) && vocab::category(n).is_none()
    })
}

fn noun_matches_robot(view: &SceneView<'_>, noun: &str, name: &str, model: &str) -> bool {
    let n = noun.trim();
    if n.is_empty() {
        return false;
    }
    if n == name {
        return true;
    }
    let words = vocab::words(n);
    if words.iter().any(|w| matches!(w.as_str(), "robot" | "arm" | "manipulator" | "cobot")) && words.len() <= 2 {
        return true;
    }
    if vocab::robot_model(n).is_some_and(|(m, _)| m == model) {
        return true;
    }
    let _ = view;
    false
}

fn color_matches(view: &SceneView<'_>, color: &str, o: &PlacedObject) -> bool {
    let Some(g) = view.plan.object(&o.group) else { return false };
    let Some(c) = &g.color else { return false };
    if c.name == color {
        return true;
    }
    vocab::color(color).is_some_and(|k| k.rgba.iter().zip(c.rgba).all(|(a, b)| (a - b).abs() < 0.05))
}

fn describe_present(view: &SceneView<'_>) -> String {
    let mut counts: Vec<(String, usize)> = Vec::new();
    for o in &view.layout.objects {
        match counts.iter_mut().find(|(l, _)| *l == o.label) {
            Some((_, n)) => *n += 1,
            None => counts.push((o.label.clone(), 1)),
        }
    }
    let mut parts: Vec<String> = counts.iter().map(|(l, n)| format!("{n} {l}")).collect();
    parts.extend(view.layout.robots.iter().map(|r| r.name.clone()));
    if parts.is_empty() { "nothing".into() } else { parts.join(", ") }
}

/// The door as a thing (for "near the door").
fn door_thing(view: &SceneView<'_>) -> Thing {
    let room = &view.layout.room;
    let (hw, hd) = (room.size.width / 2.0, room.size.depth / 2.0);
    let d = &room.door;
    let pos = match d.wall {
        Wall::North => [d.offset, hd, 0.0],
        Wall::South => [d.offset, -hd, 0.0],
        Wall::East => [hw, d.offset, 0.0],
        Wall::West => [-hw, d.offset, 0.0],
    };
    Thing {
        name: "the door".into(),
        robot: false,
        pos,
        yaw: 0.0,
        half: [d.width / 2.0, d.width / 2.0],
        height: d.height,
    }
}

fn candidates(view: &SceneView<'_>, r: &Reference) -> Vec<Thing> {
    let mut out: Vec<Thing> = Vec::new();
    for o in &view.layout.objects {
        if noun_matches_object(view, &r.noun, o) && r.color.as_ref().is_none_or(|c| color_matches(view, c, o)) {
            out.push(thing_of(o));
        }
    }
    if r.color.is_none() {
        for rb in &view.layout.robots {
            if noun_matches_robot(view, &r.noun, &rb.name, &rb.model) {
                out.push(Thing {
                    name: rb.name.clone(),
                    robot: true,
                    pos: rb.pos,
                    yaw: rb.yaw,
                    half: [0.2, 0.2],
                    height: 1.0,
                });
            }
        }
    }
    // An exact name wins over everything else it might also mean.
    if let Some(t) = out.iter().find(|t| t.name == r.noun.trim()).cloned() {
        return vec![t];
    }
    out
}

/// Resolves a reference. One object is meant unless it says "all" (or a plural with
/// "the"); an ambiguous single reference is an error that lists the candidates, except
/// when its anchor orders them (the nearest wins).
pub fn resolve(view: &SceneView<'_>, r: &Reference) -> Result<Selection, ResolveError> {
    let things = select(view, r)?;
    let mut sel = Selection::default();
    for t in things {
        if t.robot {
            sel.robots.push(t.name);
        } else {
            sel.objects.push(t.name);
        }
    }
    Ok(sel)
}

fn select(view: &SceneView<'_>, r: &Reference) -> Result<Vec<Thing>, ResolveError> {
    let what = r.describe();
    let mut c = candidates(view, r);
    let mut ordered = false;
    if let Some(a) = &r.anchor {
        let anchors: Vec<Thing> = match select(view, &a.of) {
            Ok(v) => v,
            Err(ResolveError::Ambiguous { .. }) => candidates(view, &a.of),
            Err(e)
                if vocab::words(&a.of.noun).iter().any(|w| matches!(w.as_str(), "door" | "doorway" | "entrance")) =>
            {
                let _ = e;
                vec![door_thing(view)]
            }
            Err(e) => return Err(e),
        };
        let names: Vec<&str> = anchors.iter().map(|t| t.name.as_str()).collect();
        c.retain(|t| !names.contains(&t.name.as_str()));
        let f = forward(view);
        let rt = right(view);
        let score = |t: &Thing| -> Option<f64> {
            let mut best: Option<f64> = None;
            for a0 in &anchors {
                let d = [t.pos[0] - a0.pos[0], t.pos[1] - a0.pos[1]];
                let side = d[0] * rt[0] + d[1] * rt[1];
                let ahead = d[0] * f[0] + d[1] * f[1];
                let front = [-a0.yaw.sin(), a0.yaw.cos()];
                let fw = d[0] * front[0] + d[1] * front[1];
                let lat = (d[0] * front[1] - d[1] * front[0]).abs();
                let g = gap(t, a0);
                let ok = match a.relation {
                    Spatial::NextTo => g <= 1.0 && !on_top(view, &t.name, &a0.name),
                    Spatial::LeftOf => side < 0.0 && side.abs() >= 0.5 * ahead.abs(),
                    Spatial::RightOf => side > 0.0 && side.abs() >= 0.5 * ahead.abs(),
                    Spatial::InFrontOf => fw > 0.0 && fw >= 0.5 * lat,
                    Spatial::Behind => fw < 0.0 && -fw >= 0.5 * lat,
                    Spatial::On => on_top(view, &t.name, &a0.name),
                    Spatial::Under => {
                        g <= 1e-6
                            && t.pos[2] + t.height <= a0.pos[2] + a0.height
                            && t.pos[2] < a0.pos[2] + 1e-6 + a0.height
                            && !on_top(view, &t.name, &a0.name)
                            && t.height < a0.height
                    }
                    Spatial::Nearest | Spatial::Farthest => true,
                };
                if ok {
                    let dist = g + 1e-3 * d[0].hypot(d[1]);
                    best = Some(best.map_or(dist, |b: f64| b.min(dist)));
                }
            }
            best
        };
        let mut scored: Vec<(f64, Thing)> = c.into_iter().filter_map(|t| score(&t).map(|s| (s, t))).collect();
        scored.sort_by(|x, y| x.0.total_cmp(&y.0).then_with(|| name_order(&x.1.name, &y.1.name)));
        if a.relation == Spatial::Farthest {
            scored.reverse();
        }
        ordered = !matches!(a.relation, Spatial::On | Spatial::Under);
        if matches!(a.relation, Spatial::Nearest | Spatial::Farthest) && !r.all {
            scored.truncate(1);
        }
        c = scored.into_iter().map(|(_, t)| t).collect();
    } else {
        c.sort_by(|x, y| name_order(&x.name, &y.name));
    }
    if c.is_empty() {
        return Err(ResolveError::NoMatch { what, present: describe_present(view) });
    }
    if let Some(k) = r.ordinal {
        let mut sorted = c.clone();
        sorted.sort_by(|x, y| name_order(&x.name, &y.name));
        let pick = if k == 0 { sorted.last().cloned() } else { sorted.get(k as usize - 1).cloned() };
        return match pick {
            Some(t) => Ok(vec![t]),
            None => Err(ResolveError::NoMatch {
                what,
                present: format!(
                    "only {} of them: {}",
                    sorted.len(),
                    sorted.iter().map(|t| t.name.as_str()).collect::<Vec<_>>().join(", ")
                ),
            }),
        };
    }
    if r.all || c.len() == 1 {
        return Ok(c);
    }
    if r.any {
        let mut sorted = c;
        sorted.sort_by(|x, y| name_order(&x.name, &y.name));
        return Ok(sorted.pop().into_iter().collect());
    }
    if ordered {
        return Ok(c.into_iter().take(1).collect());
    }
    let names: Vec<&str> = c.iter().map(|t| t.name.as_str()).take(8).collect();
    let more = if c.len() > 8 { format!(" and {} more", c.len() - 8) } else { String::new() };
    Err(ResolveError::Ambiguous {
        what,
        candidates: format!("{}{more}", names.join(", ")),
        example: names[0].to_string(),
    })
}

/// True when object `item` rests on object `host`.
fn on_top(view: &SceneView<'_>, item: &str, host: &str) -> bool {
    view.layout.object(item).is_some_and(|o| matches!(&o.support, Support::Object { object, .. } if object == host))
}

/// The scene as the edit LLM sees it: names, labels, groups, colours, rough positions.
pub fn scene_summary(view: &SceneView<'_>) -> serde_json::Value {
    let r1 = |v: f64| (v * 10.0).round() / 10.0;
    let objects: Vec<serde_json::Value> = view
        .layout
        .objects
        .iter()
        .map(|o| {
            let color = view.plan.object(&o.group).and_then(|g| g.color.as_ref()).map(|c| c.name.clone());
            let on = match &o.support {
                Support::Object { object, .. } => Some(object.clone()),
                _ => None,
            };
            serde_json::json!({ "name": o.name, "label": o.label, "category": o.category, "color": color,
                "at": [r1(o.pos[0]), r1(o.pos[1])], "on": on })
        })
        .collect();
    let robots: Vec<serde_json::Value> =
        view.layout.robots.iter().map(|r| serde_json::json!({ "name": r.name, "model": r.model })).collect();
    let s = view.layout.room.size;
    serde_json::json!({ "room": { "kind": view.layout.room.kind.name(), "size": [s.width, s.depth],
        "door": view.layout.room.door.wall.name() }, "objects": objects, "robots": robots })
}
