//! Every relation the prompt stated, measured on the written package: geometry from
//! `scene.xml` (collision boxes, surface sites, robot bases; `scene_geom`), names and
//! groups from `layout.json`. Written independently of the solver's own tests, with the
//! definitions of ARCHITECTURE.md ("Relations"): footprints are floor projections of
//! collision boxes, a front is +Y turned by the body's yaw, gaps are between footprints.

use std::collections::BTreeMap;
use std::path::Path;

use sw_geom::Aabb;
use sw_plan::{LaidOutScene, Mount, PlacedObject, PlacedRobot, Relation, RelationCheck, RelationKind, ScenePlan, Wall};

use crate::scene_geom::{BodyGeom, SceneGeom, Site};

/// Measured limits, m.
pub(crate) const WALL: f64 = 0.15;
pub(crate) const NEXT_TO: f64 = 0.6;
pub(crate) const NEAR: f64 = 1.5;
pub(crate) const FRONT: f64 = 1.5;
pub(crate) const FRONT_SIDE: f64 = 0.3;
pub(crate) const CORNER: f64 = 0.3;
pub(crate) const DOOR: f64 = 2.5;
pub(crate) const REST: f64 = 0.02;

/// The relations a plan states, with what it implies for robots: an arm mounted on a
/// surface, a pedestal or a cart is "on" it and reaches what it works at; the pedestal
/// under an arm stands where the arm was said to ("a UR10 on a pedestal next to the
/// pallets").
pub(crate) fn stated(plan: &ScenePlan, layout: &LaidOutScene) -> Vec<Relation> {
    let mut out = plan.relations.clone();
    let add = |r: Relation, out: &mut Vec<Relation>| {
        if !out.contains(&r) {
            out.push(r);
        }
    };
    for r in &plan.robots {
        let arm = sw_robots::find(&r.model).is_some_and(|d| d.kind == sw_robots::RobotKind::Arm);
        if !arm {
            continue;
        }
        let carrier = format!("{}_mount", r.id);
        let has_carrier = layout.objects.iter().any(|o| o.group == carrier);
        // Where the layout mounted an arm the prompt did not say where to put.
        let mounted_group = layout
            .robots
            .iter()
            .find(|p| p.group == r.id)
            .and_then(|p| p.mounted_on.as_ref())
            .and_then(|o| layout.objects.iter().find(|x| &x.name == o))
            .map(|o| o.group.clone())
            .filter(|g| plan.object(g).is_some());
        let mount = match (&r.mount, mounted_group) {
            (Mount::Auto, Some(g)) => Mount::OnSurface { target: g },
            (m, _) => m.clone(),
        };
        match &mount {
            Mount::OnSurface { target } => {
                add(Relation { subject: r.id.clone(), kind: RelationKind::On { target: target.clone() } }, &mut out);
            }
            _ if has_carrier => {
                add(Relation { subject: r.id.clone(), kind: RelationKind::On { target: carrier.clone() } }, &mut out);
                for rel in plan.relations.iter().filter(|x| x.subject == r.id) {
                    if matches!(rel.kind, RelationKind::NextTo { .. } | RelationKind::Near { .. }) {
                        add(Relation { subject: carrier.clone(), kind: rel.kind.clone() }, &mut out);
                    }
                }
            }
            _ => {}
        }
        if let Mount::OnSurface { target } = &mount {
            add(Relation { subject: r.id.clone(), kind: RelationKind::Reach { target: target.clone() } }, &mut out);
        }
        if let Some(n) = &r.near {
            add(Relation { subject: r.id.clone(), kind: RelationKind::Reach { target: n.clone() } }, &mut out);
        }
        // An arm said to be at, beside, behind, facing or on either side of a work
        // surface, a conveyor or a machine reaches it (everything on it).
        for rel in plan.relations.iter().filter(|x| x.subject == r.id) {
            let target = match &rel.kind {
                RelationKind::NextTo { target }
                | RelationKind::Near { target }
                | RelationKind::InFrontOf { target }
                | RelationKind::Behind { target }
                | RelationKind::Facing { target }
                | RelationKind::OnEachSideOf { target }
                | RelationKind::AtEndOf { target, .. }
                | RelationKind::OnEdgeOf { target } => target,
                _ => continue,
            };
            if is_work(plan, target) {
                add(Relation { subject: r.id.clone(), kind: RelationKind::Reach { target: target.clone() } }, &mut out);
            }
        }
    }
    out
}

/// Whether an object group is something an arm works at: a work surface, a conveyor or
/// a machine (by its catalog tags).
fn is_work(plan: &ScenePlan, group: &str) -> bool {
    plan.object(group).and_then(|o| sw_catalog::find(&o.category)).is_some_and(|c| {
        c.name == "conveyor" || c.has_tag("machine") || (c.has_tag("surface") && !c.has_tag("seating"))
    })
}

/// A thing a relation is measured on: an object body or a robot.
#[derive(Debug, Clone)]
pub(crate) struct Thing {
    pub name: String,
    pub body: BodyGeom,
    /// The robot's model, for robots.
    pub robot: Option<String>,
}

/// The written package, ready to measure.
pub(crate) struct Written {
    pub geom: SceneGeom,
    pub layout: LaidOutScene,
}

impl Written {
    pub fn read(dir: &Path) -> Result<Written, String> {
        let geom = SceneGeom::read(dir)?;
        let text = std::fs::read_to_string(dir.join("layout.json")).map_err(|e| format!("layout.json: {e}"))?;
        let layout: LaidOutScene = serde_json::from_str(&text).map_err(|e| format!("layout.json: {e}"))?;
        Ok(Written { geom, layout })
    }

    pub fn half(&self) -> [f64; 2] {
        [self.layout.room.size.width / 2.0, self.layout.room.size.depth / 2.0]
    }

    /// Object instances of a group, or the robots of a robot group, as written.
    pub fn things(&self, group: &str) -> Vec<Thing> {
        let objects: Vec<&PlacedObject> = self.layout.objects.iter().filter(|o| o.group == group).collect();
        if !objects.is_empty() {
            return objects
                .iter()
                .filter_map(|o| {
                    let body = self.geom.bodies.get(&o.name)?;
                    Some(Thing { name: o.name.clone(), body: body.clone(), robot: None })
                })
                .collect();
        }
        let robots: Vec<&PlacedRobot> = self.layout.robots.iter().filter(|r| r.group == group).collect();
        robots.iter().filter_map(|r| self.robot_thing(r)).collect()
    }

    /// A robot as its base: the top-level body its name prefixes, with a footprint of
    /// the registry's footprint radius around it.
    pub fn robot_thing(&self, r: &PlacedRobot) -> Option<Thing> {
        let prefix = format!("{}_", r.name);
        let (_, base) = self.geom.bodies.iter().find(|(n, _)| n.starts_with(&prefix))?;
        let radius = sw_robots::find(&r.model).map_or(0.3, |d| {
            if d.kind == sw_robots::RobotKind::Arm { d.base_radius.max(0.1) } else { d.footprint_radius }
        });
        let p = base.pos;
        let bounds =
            Aabb { min: [p[0] - radius, p[1] - radius, p[2]], max: [p[0] + radius, p[1] + radius, p[2] + 0.3] };
        let body = BodyGeom { pos: p, yaw: base.yaw, bounds, sites: Vec::new(), joints: base.joints.clone() };
        Some(Thing { name: r.name.clone(), body, robot: Some(r.model.clone()) })
    }

    /// Objects resting on `host`: their bottom on one of its sites, centre inside it.
    pub fn resting_on<'h>(&self, host: &'h Thing) -> Vec<(String, &'h Site)> {
        let mut out = Vec::new();
        for o in &self.layout.objects {
            let Some(b) = self.geom.bodies.get(&o.name) else { continue };
            if o.name == host.name {
                continue;
            }
            if let Some(s) = site_under(b, &host.body) {
                out.push((o.name.clone(), s));
            }
        }
        out
    }

    /// The category (objects) or model (robots) of a group.
    pub fn category_of(&self, plan: &ScenePlan, id: &str) -> String {
        plan.object(id)
            .map(|o| o.category.clone())
            .or_else(|| plan.robot(id).map(|r| r.model.clone()))
            .or_else(|| self.layout.objects.iter().find(|o| o.group == id).map(|o| o.category.clone()))
            .unwrap_or_default()
    }
}

/// The site of `host` that `b` rests on, if any.
pub(crate) fn site_under<'h>(b: &BodyGeom, host: &'h BodyGeom) -> Option<&'h Site> {
    let c = b.center();
    host.sites.iter().find(|s| {
        (b.bounds.min[2] - s.z).abs() <= REST
            && c[0] >= s.rect[0] - 0.01
            && c[0] <= s.rect[2] + 0.01
            && c[1] >= s.rect[1] - 0.01
            && c[1] <= s.rect[3] + 0.01
    })
}

/// Distance between two footprints (negative when they overlap).
pub(crate) fn gap(a: &Aabb, b: &Aabb) -> f64 {
    let dx = (b.min[0] - a.max[0]).max(a.min[0] - b.max[0]);
    let dy = (b.min[1] - a.max[1]).max(a.min[1] - b.max[1]);
    if dx < 0.0 && dy < 0.0 { dx.max(dy) } else { dx.max(0.0).hypot(dy.max(0.0)) }
}

/// The target whose footprint is nearest a subject's, and the gap to it (`None` without targets).
pub(crate) fn nearest_target(s: &Thing, targets: &[Thing]) -> Option<(usize, f64)> {
    targets.iter().enumerate().map(|(i, t)| (i, gap(&s.body.bounds, &t.body.bounds))).min_by(|a, b| a.1.total_cmp(&b.1))
}

pub(crate) fn wall_gap(half: [f64; 2], b: &Aabb, w: Wall) -> f64 {
    match w {
        Wall::North => half[1] - b.max[1],
        Wall::South => b.min[1] + half[1],
        Wall::East => half[0] - b.max[0],
        Wall::West => b.min[0] + half[0],
    }
}

pub(crate) fn nearest_wall(half: [f64; 2], b: &Aabb) -> (Wall, f64) {
    Wall::ALL
        .iter()
        .map(|w| (*w, wall_gap(half, b, *w)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap_or((Wall::North, f64::INFINITY))
}

pub(crate) fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// Half the extent of a footprint along a unit direction.
pub(crate) fn half_along(b: &Aabb, d: [f64; 2]) -> f64 {
    0.5 * ((b.max[0] - b.min[0]) * d[0].abs() + (b.max[1] - b.min[1]) * d[1].abs())
}

pub(crate) fn center(b: &Aabb) -> [f64; 2] {
    [0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1])]
}

pub(crate) fn inside(p: [f64; 2], b: &Aabb) -> bool {
    b.min[0] < p[0] && p[0] < b.max[0] && b.min[1] < p[1] && p[1] < b.max[1]
}

/// In the convex hull of two rectangles' corners.
pub(crate) fn in_hull(a: &Aabb, b: &Aabb, p: [f64; 2]) -> bool {
    let mut pts: Vec<[f64; 2]> = Vec::new();
    for r in [a, b] {
        for x in [r.min[0], r.max[0]] {
            for y in [r.min[1], r.max[1]] {
                pts.push([x, y]);
            }
        }
    }
    pts.sort_by(|u, v| u[0].total_cmp(&v[0]).then(u[1].total_cmp(&v[1])));
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let mut hull: Vec<[f64; 2]> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let iter: Vec<[f64; 2]> = if pass == 0 { pts.clone() } else { pts.iter().rev().copied().collect() };
        for q in iter {
            while hull.len() >= start + 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0 {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    let n = hull.len();
    n >= 3 && (0..n).all(|i| cross(hull[i], hull[(i + 1) % n], p) >= -1e-9)
}

/// One relation's verdict: held, the numbers measured, and why not.
pub(crate) struct Verdict {
    pub held: bool,
    pub measured: BTreeMap<String, f64>,
    pub reason: Option<String>,
}

impl Verdict {
    fn new() -> Self {
        Verdict { held: true, measured: BTreeMap::new(), reason: None }
    }

    pub fn set(&mut self, key: &str, v: f64) {
        if v.is_finite() {
            self.measured.insert(key.to_string(), (v * 1e4).round() / 1e4);
        }
    }

    pub fn fail(&mut self, why: impl Into<String>) {
        if self.held {
            self.reason = Some(why.into());
        }
        self.held = false;
    }
}

/// Measures the stated relations on the package staged in `dir` and adds them to the
/// report, with a warning naming each one that does not hold (a relation is never
/// dropped silently). A package that cannot be read back is itself a warning.
pub(crate) fn attach(report: &mut sw_plan::Report, plan: &ScenePlan, dir: &Path) {
    let w = match Written::read(dir) {
        Ok(w) => w,
        Err(e) => {
            report.warnings.push(sw_plan::Warning::new(
                sw_plan::Stage::Layout,
                "relations_unmeasured",
                format!("the relations could not be measured on the written scene: {e}"),
            ));
            return;
        }
    };
    let checks = check_written(plan, &w);
    for c in checks.iter().filter(|c| !c.held) {
        let why = c.reason.as_deref().unwrap_or("it does not hold");
        report.warnings.push(sw_plan::Warning::new(
            sw_plan::Stage::Layout,
            "relation_not_held",
            format!("{}: {why}", c.phrase),
        ));
    }
    report.relations = checks;
    let sizes = crate::relations_places::sizes(plan, &w);
    for c in sizes.iter().filter(|c| !c.held) {
        report.warnings.push(sw_plan::Warning::new(
            sw_plan::Stage::Forge,
            "size_not_kept",
            format!("\"{}\": {}", c.phrase, c.reason.as_deref().unwrap_or("not the size stated")),
        ));
    }
    report.sizes = sizes;
}

/// The words of the prompt behind a group, robot or robot's stand.
fn phrase_of(plan: &ScenePlan, w: &Written, id: &str) -> String {
    if plan.object(id).is_some() || plan.robot(id).is_some() {
        return plan.phrase_of(id);
    }
    format!("{} under {}", w.category_of(plan, id), plan.phrase_of(id.trim_end_matches("_mount")))
}

/// Measures every stated relation of `plan` on the package written in `dir`.
fn check_written(plan: &ScenePlan, w: &Written) -> Vec<RelationCheck> {
    stated(plan, &w.layout).into_iter().map(|r| check_one(plan, w, r)).collect()
}

fn check_one(plan: &ScenePlan, w: &Written, relation: Relation) -> RelationCheck {
    let subjects = w.things(&relation.subject);
    let mut v = Verdict::new();
    if subjects.is_empty() {
        v.fail(format!("no \"{}\" in the scene", phrase_of(plan, w, &relation.subject)));
    } else {
        crate::relations_measure::measure(plan, w, &relation, &subjects, &mut v);
    }
    let target_categories = match &relation.kind {
        RelationKind::Between { first, second } => vec![w.category_of(plan, first), w.category_of(plan, second)],
        k => k.targets().iter().map(|t| w.category_of(plan, t)).collect(),
    };
    let phrase = if plan.object(&relation.subject).is_some() || plan.robot(&relation.subject).is_some() {
        plan.describe(&relation)
    } else {
        // A robot's pedestal: "the pedestal under \"a UR10\"".
        let robot = relation.subject.trim_end_matches("_mount");
        let mut r = relation.clone();
        r.subject = robot.to_string();
        format!("the stand under {}", plan.describe(&r))
    };
    RelationCheck {
        subject_category: w.category_of(plan, &relation.subject),
        target_categories,
        phrase,
        held: v.held,
        measured: v.measured,
        reason: v.reason,
        relation,
    }
}
