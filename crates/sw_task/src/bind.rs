//! Binding a read instruction to a scene: noun phrases to bodies (by category and colour,
//! as the planner reads them), the robot that does it (an arm with a gripper that reaches
//! every body it must touch), and the predicates. Bad tasks are refused here with one line
//! that names the part: a thing that is not there, no gripper, out of reach, goals that
//! contradict each other.

use std::collections::BTreeMap;

use sw_plan::{LaidOutScene, ScenePlan, Support};
use sw_planner::vocab::Noun;

use crate::task::{Family, GripperInterface, Predicate, TASK_VERSION, Task};
use crate::vocab::{Action, Region, Rel};
use crate::words::{Clause, NounPhrase};
use crate::{TaskError, words};

/// How close a thing put "next to" another must end up (footprint gap), m.
pub const NEAR_ITEMS: f64 = 0.10;
/// How high "lift the cube" raises it above where it starts, m, and how close it must be.
pub const LIFT_HEIGHT: f64 = 0.15;
pub const LIFT_TOLERANCE: f64 = 0.05;
/// How close a mobile base must get to where it is sent, m.
pub const NAVIGATE_WITHIN: f64 = 0.5;
/// An arm's reach is checked with this margin (the expert finds out the rest), m.
const REACH_MARGIN: f64 = 0.05;

/// Categories that hold things inside them ("on the bin" means in it).
const CONTAINERS: &[&str] =
    &["bowl", "bin", "cardboard_box", "crate", "trash_can", "drum", "mug", "cup", "sink", "tray", "basket"];

/// Words that pick one of several things by where it stands.
const POSITION_WORDS: &[&str] =
    &["left", "leftmost", "right", "rightmost", "far", "farthest", "furthest", "near", "nearest", "closest"];

/// Ordinal and position words for parts, as a fraction along their order (drawers count
/// from the bottom; doors from the left).
const ORDINALS: &[(&str, f64)] = &[
    ("bottom", 0.0),
    ("lower", 0.0),
    ("lowest", 0.0),
    ("first", 0.0),
    ("left", 0.0),
    ("middle", 0.5),
    ("centre", 0.5),
    ("center", 0.5),
    ("top", 1.0),
    ("upper", 1.0),
    ("highest", 1.0),
    ("right", 1.0),
    ("last", 1.0),
];

/// A robot of the scene, with what the task needs to know of it.
#[derive(Debug, Clone)]
pub struct SceneRobot {
    pub name: String,
    pub model: String,
    pub pos: [f64; 3],
    pub yaw: f64,
    pub reach: f64,
    pub has_gripper: bool,
    pub mobile: bool,
}

/// What a task is bound against: the package's plan and layout, its robots, and the
/// names of the joints of articulated objects (`<object>_<part>_joint`).
#[derive(Debug, Clone)]
pub struct SceneFacts<'a> {
    pub plan: &'a ScenePlan,
    pub layout: &'a LaidOutScene,
    pub robots: Vec<SceneRobot>,
    pub joints: Vec<String>,
}

impl<'a> SceneFacts<'a> {
    /// The facts of a plan and layout, robots described by the registry.
    pub fn new(plan: &'a ScenePlan, layout: &'a LaidOutScene, joints: Vec<String>) -> Self {
        let robots = layout
            .robots
            .iter()
            .map(|r| {
                let def = sw_robots::find(&r.model);
                SceneRobot {
                    name: r.name.clone(),
                    model: r.model.clone(),
                    pos: r.pos,
                    yaw: r.yaw,
                    reach: def.map_or(0.0, |d| d.reach),
                    has_gripper: def.is_some_and(|d| d.gripper.is_some()),
                    mobile: def.is_some_and(|d| d.kind != sw_robots::RobotKind::Arm),
                }
            })
            .collect();
        Self { plan, layout, robots, joints }
    }

    fn colour_of(&self, group: &str) -> Option<&str> {
        self.plan.objects.iter().find(|o| o.id == group).and_then(|o| o.color.as_ref()).map(|c| c.name.as_str())
    }

    /// The objects a noun phrase names, in name order; an error names what is missing.
    fn objects(&self, np: &NounPhrase) -> Result<Vec<String>, TaskError> {
        let category = match sw_planner::vocab::noun(&np.text) {
            Noun::Category(c) => Some(c),
            _ => None,
        };
        let colour = sw_planner::vocab::color(&np.text).map(|c| c.name);
        let words = sw_planner::vocab::words(&np.text);
        let kind_fits = |o: &sw_plan::PlacedObject| match category {
            Some(c) => o.category == c,
            // A labelled proxy: its label's words.
            None => {
                let label = sw_planner::vocab::words(&o.label);
                words.last().is_some_and(|w| label.contains(w))
            }
        };
        let mut of_kind: Vec<&sw_plan::PlacedObject> = self.layout.objects.iter().filter(|o| kind_fits(o)).collect();
        if of_kind.is_empty() {
            // A kind the catalog says these things are ("the fruit", "the container"): a
            // category whose `is_a` names the phrase's head, or the phrase without colour.
            let head = words.last().cloned().unwrap_or_default();
            let plain: Vec<&str> = words
                .iter()
                .map(String::as_str)
                .filter(|w| sw_planner::vocab::color(w).is_none() && !POSITION_WORDS.contains(w))
                .collect();
            let plain = plain.join(" ");
            of_kind = self
                .layout
                .objects
                .iter()
                .filter(|o| {
                    sw_catalog::find(&o.category).is_some_and(|c| c.is_a.iter().any(|k| *k == head || *k == plain))
                })
                .collect();
        }
        let fits: Vec<String> = of_kind
            .iter()
            .filter(|o| colour.as_deref().is_none_or(|c| self.colour_of(&o.group) == Some(c)))
            .map(|o| o.name.clone())
            .collect();
        if !fits.is_empty() {
            return Ok(self.by_position(&words, fits));
        }
        let there: Vec<String> = if of_kind.is_empty() {
            self.layout.objects.iter().filter(|o| o.movable).map(|o| o.name.clone()).take(8).collect()
        } else {
            of_kind
                .iter()
                .map(|o| format!("{} ({})", o.name, self.colour_of(&o.group).unwrap_or("no colour named")))
                .collect()
        };
        Err(TaskError::Missing(format!(
            "the task names \"{}\", which is not in the scene (it has {})",
            np.text,
            if there.is_empty() { "no movable things".to_string() } else { there.join(", ") }
        )))
    }

    /// Of several things that fit, the one a position word picks ("the cube on the left",
    /// "the nearest mug"), in the frame of the arm that works (it faces +x; left is +y).
    fn by_position(&self, words: &[String], fits: Vec<String>) -> Vec<String> {
        let Some(word) = words.iter().find(|w| POSITION_WORDS.contains(&w.as_str())) else { return fits };
        if fits.len() < 2 {
            return fits;
        }
        let Some(r) = self.robots.iter().find(|r| r.has_gripper).or(self.robots.first()) else { return fits };
        let (c, s) = (r.yaw.cos(), r.yaw.sin());
        let score = |n: &String| -> f64 {
            let Some(o) = self.object(n) else { return 0.0 };
            let (dx, dy) = (o.pos[0] - r.pos[0], o.pos[1] - r.pos[1]);
            let (fwd, left) = (c * dx + s * dy, -s * dx + c * dy);
            match word.as_str() {
                "left" | "leftmost" => left,
                "right" | "rightmost" => -left,
                "far" | "farthest" | "furthest" | "back" => fwd,
                _ => -dx.hypot(dy),
            }
        };
        let best = fits.iter().max_by(|a, b| score(a).total_cmp(&score(b))).cloned();
        best.into_iter().collect()
    }

    /// The joint an open/close phrase names, and its object: "the top drawer of the
    /// cabinet", "the microwave door", "the drawer", "the fridge". Joints are named
    /// `<object>_<part>_<n>_joint`; drawers count up from the bottom.
    fn articulated(
        &self,
        np: &NounPhrase,
        used: &mut Vec<String>,
        notes: &mut Vec<String>,
    ) -> Result<(String, String), TaskError> {
        let ws: Vec<String> = sw_planner::vocab::words(&np.text);
        let parts_of = |j: &str, obj: &str| -> Vec<String> {
            j.strip_prefix(&format!("{obj}_"))
                .and_then(|r| r.strip_suffix("_joint"))
                .map(|r| r.split('_').map(str::to_string).collect())
                .unwrap_or_default()
        };
        let names_part = |w: &str| {
            self.layout.objects.iter().any(|o| self.joints.iter().any(|j| parts_of(j, &o.name).iter().any(|p| p == w)))
        };
        // "X of Y": the part X of the thing Y; "Y X" with X a part ("microwave door").
        let (part, owner): (Option<String>, Vec<String>) = match np.text.split(' ').position(|w| w == "of") {
            Some(k) => {
                let all: Vec<&str> = np.text.split(' ').collect();
                (
                    sw_planner::vocab::words(all[..k].last().unwrap_or(&"")).first().cloned(),
                    sw_planner::vocab::words(&all[k + 1..].join(" ")),
                )
            }
            None => match ws.last() {
                Some(last)
                    if names_part(last) || matches!(last.as_str(), "drawer" | "door" | "lid" | "flap" | "hatch") =>
                {
                    (Some(last.clone()), ws[..ws.len() - 1].to_vec())
                }
                _ => (None, ws.clone()),
            },
        };
        let owner: Vec<String> = owner.into_iter().filter(|w| !ORDINALS.iter().any(|(o, _)| o == w)).collect();
        let candidates: Vec<String> = if owner.is_empty() {
            let p = part.clone().unwrap_or_default();
            self.layout
                .objects
                .iter()
                .filter(|o| self.joints.iter().any(|j| parts_of(j, &o.name).contains(&p)))
                .map(|o| o.name.clone())
                .collect()
        } else {
            let owner_np = NounPhrase { text: owner.join(" "), every: false, other: false };
            self.objects(&owner_np)?
        };
        let what = part.clone().unwrap_or_else(|| "door or drawer".into());
        let mut with_joints: Vec<(String, Vec<String>)> = Vec::new();
        for o in &candidates {
            let mut js: Vec<String> = self
                .joints
                .iter()
                .filter(|j| {
                    let ps = parts_of(j, o);
                    !ps.is_empty() && part.as_ref().is_none_or(|p| ps.contains(p))
                })
                .cloned()
                .collect();
            js.sort_by_key(|j| (j.len(), j.clone()));
            if !js.is_empty() {
                with_joints.push((o.clone(), js));
            }
        }
        if with_joints.is_empty() {
            let named = if candidates.is_empty() { format!("\"{}\"", np.text) } else { candidates.join(", ") };
            let movable: Vec<String> = self
                .layout
                .objects
                .iter()
                .filter(|o| self.joints.iter().any(|j| !parts_of(j, &o.name).is_empty()))
                .map(|o| o.name.clone())
                .take(6)
                .collect();
            return Err(TaskError::Missing(format!(
                "the task opens or closes {named}, and the scene has no {what} of it that moves ({})",
                if movable.is_empty() {
                    "nothing in it opens".to_string()
                } else {
                    format!("things that open: {}", movable.join(", "))
                }
            )));
        }
        let names: Vec<String> = with_joints.iter().map(|(o, _)| o.clone()).collect();
        let obj = pick_one(&names, &NounPhrase { text: np.text.clone(), every: false, other: false }, used, notes);
        let js = &with_joints.iter().find(|(o, _)| *o == obj).map(|(_, j)| j.clone()).unwrap_or_default();
        let ordinal = ws.iter().find_map(|w| ORDINALS.iter().find(|(o, _)| o == w).map(|x| x.1));
        let k = match ordinal {
            Some(f) => ((f * (js.len() as f64 - 1.0)).round() as usize).min(js.len() - 1),
            None => 0,
        };
        if js.len() > 1 {
            notes.push(format!("\"{}\" fits {}; the task uses {}", np.text, js.join(", "), js[k]));
        }
        Ok((obj, js[k].clone()))
    }

    fn object(&self, name: &str) -> Option<&sw_plan::PlacedObject> {
        self.layout.object(name)
    }

    /// The footprint rectangle (x0, y0, x1, y1) of an object, from its pose and size.
    fn footprint(&self, name: &str) -> Option<[f64; 4]> {
        let o = self.object(name)?;
        let (c, s) = (o.yaw.cos().abs(), o.yaw.sin().abs());
        let hx = 0.5 * (o.size[0] * c + o.size[1] * s);
        let hy = 0.5 * (o.size[0] * s + o.size[1] * c);
        Some([o.pos[0] - hx, o.pos[1] - hy, o.pos[0] + hx, o.pos[1] + hy])
    }
}

/// Reads `instruction` and binds it to the scene.
pub fn bind(instruction: &str, source: &str, facts: &SceneFacts<'_>) -> Result<Task, TaskError> {
    let clauses = words::read(instruction)?;
    let mut goals: Vec<Predicate> = Vec::new();
    let mut notes: Vec<String> = Vec::new();
    let mut families: Vec<Family> = Vec::new();
    let mut used: Vec<String> = Vec::new();
    let mut navigator: Option<String> = None;
    for c in &clauses {
        let (family, mut g) = clause_goals(c, facts, &mut used, &mut notes, &mut navigator)?;
        families.push(family);
        goals.append(&mut g);
    }
    check_consistent(&goals)?;
    let family = families.iter().copied().max().unwrap_or(Family::PickPlace);
    let robot = match navigator {
        Some(r) => r,
        None => choose_arm(&goals, facts)?,
    };
    let gripper = facts
        .robots
        .iter()
        .find(|r| r.name == robot)
        .and_then(|r| sw_robots::find(&r.model))
        .and_then(|d| d.gripper)
        .map(|g| GripperInterface {
            tcp_site: format!("{robot}_{}", g.tcp_site),
            actuator: format!("{robot}_{}", g.actuator),
            open: g.open,
            closed: g.closed,
            wrist_camera: format!("{robot}_{}", g.wrist_camera),
        });
    Ok(Task {
        schema_version: TASK_VERSION,
        gripper,
        instruction: crate::imperative(instruction),
        source: source.to_string(),
        family,
        robot,
        goals,
        notes,
    })
}

fn clause_goals(
    c: &Clause,
    facts: &SceneFacts<'_>,
    used: &mut Vec<String>,
    notes: &mut Vec<String>,
    navigator: &mut Option<String>,
) -> Result<(Family, Vec<Predicate>), TaskError> {
    if c.action == Action::Navigate {
        let target = c.target.as_ref().or(c.subjects.first()).ok_or_else(|| {
            TaskError::Words("a task to go somewhere names no place to go (\"go to the shelf\")".into())
        })?;
        let t = pick_one(&facts.objects(target)?, target, used, notes);
        let robot = facts.robots.iter().find(|r| r.mobile).ok_or_else(|| {
            TaskError::Robot(format!("the task asks to go to {t}, and the scene has no mobile robot"))
        })?;
        *navigator = Some(robot.name.clone());
        return Ok((
            Family::Navigate,
            vec![Predicate::NavigateTo { robot: robot.name.clone(), target: t, within: NAVIGATE_WITHIN }],
        ));
    }
    if c.subjects.is_empty() {
        return Err(TaskError::Words("the task says where to put something but not what".into()));
    }
    if matches!(c.action, Action::Open | Action::Close) {
        let mut goals = Vec::new();
        for np in &c.subjects {
            let (object, joint) = facts.articulated(np, used, notes)?;
            goals.push(if c.action == Action::Open {
                Predicate::Open { object, joint }
            } else {
                Predicate::Closed { object, joint }
            });
        }
        return Ok((Family::Articulated, goals));
    }
    let mut subjects: Vec<String> = Vec::new();
    for np in &c.subjects {
        let found = facts.objects(np)?;
        if np.every {
            subjects.extend(found);
        } else {
            subjects.push(pick_one(&found, np, used, notes));
        }
    }
    for s in &subjects {
        if c.action != Action::Open && c.action != Action::Close && facts.object(s).is_some_and(|o| !o.movable) {
            return Err(TaskError::Missing(format!("{s} is fixed in place; the robot cannot move it")));
        }
    }
    let targets: Option<Vec<String>> = match &c.target {
        Some(np) => {
            // Where a thing goes is another thing than the ones moved ("stack the red cube
            // on the other cube"); "the other …" is also none named before.
            let found = facts.objects(np)?;
            let mut taken = subjects.clone();
            if np.other {
                taken.extend(used.iter().cloned());
            }
            let rest: Vec<String> = found.iter().filter(|f| !subjects.contains(f)).cloned().collect();
            Some(match (np.every, rest.is_empty()) {
                (true, false) => rest,
                (true, true) => found,
                (false, _) => vec![pick_one(&found, np, &mut taken, notes)],
            })
        }
        None => None,
    };
    // "slide the cup to the right of the table" with the cup on that table: a part of its
    // surface, not beside the table (which it already is).
    let on_target = |s: &String| match (facts.object(s).map(|o| &o.support), targets.as_ref()) {
        (Some(Support::Object { object, .. }), Some(t)) => *object == t[0],
        _ => false,
    };
    let region = match (c.region, c.rel, c.side) {
        (None, Some(Rel::Near), Some(side)) if subjects.iter().all(on_target) => Some(side),
        (r, _, _) => r,
    };
    let mut goals = Vec::new();
    let family;
    match (c.action, c.rel, region) {
        (_, _, Some(region)) => {
            family = if c.action == Action::Push { Family::Push } else { Family::PickPlace };
            for s in &subjects {
                let surface = match &targets {
                    Some(t) => t[0].clone(),
                    None => match facts.object(s).map(|o| &o.support) {
                        Some(Support::Object { object, .. }) => object.clone(),
                        _ => return Err(TaskError::Missing(format!("{s} stands on no surface to move it across"))),
                    },
                };
                let rect = facts
                    .footprint(&surface)
                    .ok_or_else(|| TaskError::Missing(format!("no surface {surface} in the scene")))?;
                let yaw = facts.robots.iter().find(|r| r.has_gripper).map_or(0.0, |r| r.yaw);
                let (min, max) = region_rect(rect, region, yaw);
                goals.push(Predicate::InRegion { object: s.clone(), min, max });
            }
        }
        (Action::Lift, None, None) => {
            family = Family::Lift;
            for s in &subjects {
                let o = facts.object(s).ok_or_else(|| TaskError::Missing(format!("no {s} in the scene")))?;
                let pos = [o.pos[0], o.pos[1], o.pos[2] + 0.5 * o.size[2] + LIFT_HEIGHT];
                goals.push(Predicate::AtPose { object: s.clone(), pos, tolerance: LIFT_TOLERANCE });
            }
        }
        (Action::Stack, None, None) => {
            // "stack the cubes": each on the one before.
            family = Family::Stack;
            if subjects.len() < 2 {
                return Err(TaskError::Words(format!(
                    "stacking needs two things or a thing to stack on, got {subjects:?}"
                )));
            }
            for w in subjects.windows(2) {
                goals.push(Predicate::StackedOn { object: w[1].clone(), target: w[0].clone() });
            }
        }
        (_, rel, None) => {
            let targets = targets.ok_or_else(|| {
                TaskError::Words(format!("the task says what to move ({}) but not where", subjects.join(", ")))
            })?;
            let t0 = targets[0].clone();
            let movable_target = facts.object(&t0).is_some_and(|o| o.movable);
            let container = facts.object(&t0).is_some_and(|o| CONTAINERS.contains(&o.category.as_str()));
            let rel = rel.unwrap_or(Rel::To);
            family = match (c.action, rel) {
                (Action::Push, _) => Family::Push,
                (Action::Stack, _) => Family::Stack,
                (_, Rel::On | Rel::To) if movable_target && !container => Family::Stack,
                _ => Family::PickPlace,
            };
            for s in &subjects {
                goals.push(match rel {
                    Rel::Near => Predicate::Near { object: s.clone(), target: t0.clone(), within: NEAR_ITEMS },
                    Rel::Inside => Predicate::Inside { object: s.clone(), target: targets.clone() },
                    Rel::On | Rel::To if container => Predicate::Inside { object: s.clone(), target: targets.clone() },
                    Rel::On | Rel::To if family == Family::Stack => {
                        Predicate::StackedOn { object: s.clone(), target: t0.clone() }
                    }
                    Rel::To if c.action == Action::Push => {
                        Predicate::Near { object: s.clone(), target: t0.clone(), within: NEAR_ITEMS }
                    }
                    Rel::On | Rel::To => Predicate::On { object: s.clone(), target: targets.clone() },
                });
            }
        }
    }
    Ok((family, goals))
}

/// One body of several that fit a singular noun phrase: the first not yet used by another
/// clause, noted when there was a choice.
fn pick_one(found: &[String], np: &NounPhrase, used: &mut Vec<String>, notes: &mut Vec<String>) -> String {
    let pick = found.iter().find(|f| !used.contains(f)).unwrap_or(&found[0]).clone();
    if found.len() > 1 {
        notes.push(format!("\"{}\" fits {}; the task uses {pick}", np.text, found.join(", ")));
    }
    used.push(pick.clone());
    pick
}

/// A part of a surface's rectangle, in the robot's frame (yaw), 3 cm in from the edges.
fn region_rect(r: [f64; 4], region: Region, yaw: f64) -> ([f64; 2], [f64; 2]) {
    let m = 0.03;
    let (x0, y0, x1, y1) = (r[0] + m, r[1] + m, r[2] - m, r[3] - m);
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let third_x = (x1 - x0) / 3.0;
    let third_y = (y1 - y0) / 3.0;
    // The robot's forward and left, snapped to the nearest world axis.
    let (fx, fy) = (yaw.cos(), yaw.sin());
    let axis = |dx: f64, dy: f64| -> ([f64; 2], [f64; 2]) {
        if dx.abs() >= dy.abs() {
            if dx > 0.0 { ([x1 - third_x, y0], [x1, y1]) } else { ([x0, y0], [x0 + third_x, y1]) }
        } else if dy > 0.0 {
            ([x0, y1 - third_y], [x1, y1])
        } else {
            ([x0, y0], [x1, y0 + third_y])
        }
    };
    match region {
        Region::Left => axis(-fy, fx),
        Region::Right => axis(fy, -fx),
        Region::Back => axis(fx, fy),
        Region::Front => axis(-fx, -fy),
        Region::Centre => ([cx - third_x / 2.0, cy - third_y / 2.0], [cx + third_x / 2.0, cy + third_y / 2.0]),
        Region::Corner => {
            let (a, b) = axis(-fy, fx);
            let (c, d) = axis(fx, fy);
            ([a[0].max(c[0]), a[1].max(c[1])], [b[0].min(d[0]), b[1].min(d[1])])
        }
    }
}

/// Goals that cannot all hold: a thing sent to two places, into itself, or stacked in a
/// cycle.
fn check_consistent(goals: &[Predicate]) -> Result<(), TaskError> {
    let mut place: BTreeMap<&str, &Predicate> = BTreeMap::new();
    for g in goals {
        let Some(s) = g.subject() else { continue };
        if g.bodies().iter().skip(1).any(|b| *b == s) {
            return Err(TaskError::Contradiction(format!("the task asks to put {s} {} itself", g.name())));
        }
        if let Some(prev) = place.insert(s, g)
            && prev != g
            && !matches!(g, Predicate::Near { .. })
            && !matches!(prev, Predicate::Near { .. })
        {
            return Err(TaskError::Contradiction(format!(
                "contradictory goals: {s} cannot be both {} {} and {} {}",
                prev.name(),
                prev.bodies()[1..].join("/"),
                g.name(),
                g.bodies()[1..].join("/")
            )));
        }
    }
    // Stacking cycles: a on b, b on a.
    let on: BTreeMap<&str, &str> = goals
        .iter()
        .filter_map(|g| match g {
            Predicate::StackedOn { object, target } => Some((object.as_str(), target.as_str())),
            _ => None,
        })
        .collect();
    for start in on.keys() {
        let mut cur = *start;
        for _ in 0..=on.len() {
            match on.get(cur) {
                Some(next) if next == start => {
                    return Err(TaskError::Contradiction(format!("contradictory goals: {start} is stacked on itself")));
                }
                Some(next) => cur = next,
                None => break,
            }
        }
    }
    Ok(())
}

/// The arm that does the task: one with a gripper whose reach covers every body a goal
/// names, nearest first.
fn choose_arm(goals: &[Predicate], facts: &SceneFacts<'_>) -> Result<String, TaskError> {
    let bodies: Vec<&str> = goals.iter().flat_map(Predicate::bodies).collect();
    let arms: Vec<&SceneRobot> = facts.robots.iter().filter(|r| !r.mobile || r.has_gripper).collect();
    if arms.is_empty() {
        return Err(TaskError::Robot("the scene has no robot arm to do the task".into()));
    }
    let grippers: Vec<&&SceneRobot> = arms.iter().filter(|r| r.has_gripper).collect();
    if grippers.is_empty() {
        let names: Vec<String> = arms.iter().map(|r| format!("{} ({})", r.name, r.model)).collect();
        return Err(TaskError::Robot(format!(
            "no robot in the scene has a gripper the expert can drive: {}",
            names.join(", ")
        )));
    }
    let dist = |r: &SceneRobot, b: &str| -> f64 {
        let Some(rect) = facts.footprint(b) else { return f64::INFINITY };
        // The nearest point of the body's footprint: an arm reaches over a table's edge.
        let nx = r.pos[0].clamp(rect[0], rect[2]);
        let ny = r.pos[1].clamp(rect[1], rect[3]);
        (nx - r.pos[0]).hypot(ny - r.pos[1])
    };
    let mut best: Option<(f64, &SceneRobot)> = None;
    let mut worst_miss: Option<(f64, String, &SceneRobot)> = None;
    for r in grippers {
        let far = bodies.iter().map(|b| (dist(r, b), *b)).fold((0.0, ""), |a, b| if b.0 > a.0 { b } else { a });
        if far.0 <= r.reach + REACH_MARGIN {
            let total: f64 = bodies.iter().map(|b| dist(r, b)).sum();
            if best.is_none_or(|(t, _)| total < t) {
                best = Some((total, r));
            }
        } else if worst_miss.as_ref().is_none_or(|(d, _, _)| far.0 - r.reach < *d) {
            worst_miss = Some((far.0 - r.reach, far.1.to_string(), r));
        }
    }
    match (best, worst_miss) {
        (Some((_, r)), _) => Ok(r.name.clone()),
        (None, Some((_, body, r))) => Err(TaskError::Unreachable(format!(
            "no arm reaches {body}: {} reaches {:.2} m and it is {:.2} m away",
            r.name,
            r.reach,
            dist(r, &body)
        ))),
        (None, None) => Err(TaskError::Robot("no arm can do the task".into())),
    }
}
