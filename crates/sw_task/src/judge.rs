//! Judging a task on a state: the predicates' geometry, on a [`Snapshot`] of the bodies
//! that the simulator fills in (`sw_expert` from MuJoCo's `geom_xpos`/`geom_xmat`, the
//! Python replay check from the official bindings). The definitions are the relation
//! report's (`sw_pipeline::relations_check`): world-frame boxes around the collision
//! geoms, support surfaces as the `sw_surface` sites' top rectangles, and a body rests on
//! a surface when its bottom is within [`REST`] of it and its centre over it.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::task::{Predicate, Task};

/// A body rests on a surface when its bottom is this close to it, m (the report's REST).
pub const REST: f64 = 0.02;
/// Slack around a surface's rectangle for the resting body's centre, m (as the report).
pub const EDGE: f64 = 0.01;
/// Below the container's bottom an inside body may reach (its floor's thickness), m.
pub const FLOOR_SLACK: f64 = 0.01;

/// An axis-aligned box in the world frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Bounds {
    pub min: [f64; 3],
    pub max: [f64; 3],
}

impl Bounds {
    pub fn center(&self) -> [f64; 3] {
        [0.5 * (self.min[0] + self.max[0]), 0.5 * (self.min[1] + self.max[1]), 0.5 * (self.min[2] + self.max[2])]
    }

    /// The centre's footprint is strictly inside this box's footprint.
    pub fn covers_xy(&self, p: [f64; 3]) -> bool {
        self.min[0] < p[0] && p[0] < self.max[0] && self.min[1] < p[1] && p[1] < self.max[1]
    }
}

/// A support surface: the top face of an `sw_surface` site.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Surface {
    pub z: f64,
    /// x0, y0, x1, y1.
    pub rect: [f64; 4],
}

/// One body of the state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyState {
    /// Around the body's colliding geoms, world frame.
    pub bounds: Bounds,
    pub surfaces: Vec<Surface>,
}

/// The state a task is judged on.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Snapshot {
    pub bodies: BTreeMap<String, BodyState>,
    /// Robot instance → base position.
    pub robots: BTreeMap<String, [f64; 3]>,
    /// Joint name → (position, lower limit, upper limit), for open/closed goals.
    pub joints: BTreeMap<String, (f64, f64, f64)>,
}

/// One goal's verdict, with what was measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GoalVerdict {
    pub predicate: String,
    pub held: bool,
    /// The number that decided it (a distance or a fraction), when there is one.
    pub measured: Option<f64>,
    pub why: Option<String>,
}

/// Every goal's verdict; the task holds when all do.
pub fn judge(task: &Task, s: &Snapshot) -> Vec<GoalVerdict> {
    task.goals.iter().map(|g| judge_goal(g, s)).collect()
}

/// True when every goal holds.
pub fn holds(task: &Task, s: &Snapshot) -> bool {
    judge(task, s).iter().all(|v| v.held)
}

fn verdict(p: &Predicate, held: bool, measured: Option<f64>, why: impl Into<String>) -> GoalVerdict {
    let why = why.into();
    GoalVerdict { predicate: p.name().to_string(), held, measured, why: (!held && !why.is_empty()).then_some(why) }
}

/// Whether `b` rests on one of `host`'s surfaces (the report's `site_under`), or on the
/// top of a host without surfaces (the report's `stands_on`).
pub fn rests_on(b: &BodyState, host: &BodyState) -> bool {
    let c = b.bounds.center();
    let on_site = host.surfaces.iter().any(|s| {
        (b.bounds.min[2] - s.z).abs() <= REST
            && c[0] >= s.rect[0] - EDGE
            && c[0] <= s.rect[2] + EDGE
            && c[1] >= s.rect[1] - EDGE
            && c[1] <= s.rect[3] + EDGE
    });
    on_site || stands_on_top(b, host)
}

/// `b`'s bottom is at `host`'s top and its centre over `host`'s footprint.
pub fn stands_on_top(b: &BodyState, host: &BodyState) -> bool {
    (b.bounds.min[2] - host.bounds.max[2]).abs() <= REST && host.bounds.covers_xy(b.bounds.center())
}

/// `b` is within `host`: centre over its footprint, bottom between its bottom and rim.
pub fn within(b: &BodyState, host: &BodyState) -> bool {
    host.bounds.covers_xy(b.bounds.center())
        && b.bounds.min[2] >= host.bounds.min[2] - FLOOR_SLACK
        && b.bounds.min[2] < host.bounds.max[2]
}

/// Distance between two footprints (negative when they overlap), as the report's `gap`.
pub fn gap(a: &Bounds, b: &Bounds) -> f64 {
    let dx = (b.min[0] - a.max[0]).max(a.min[0] - b.max[0]);
    let dy = (b.min[1] - a.max[1]).max(a.min[1] - b.max[1]);
    if dx < 0.0 && dy < 0.0 { dx.max(dy) } else { dx.max(0.0).hypot(dy.max(0.0)) }
}

fn judge_goal(p: &Predicate, s: &Snapshot) -> GoalVerdict {
    let body = |n: &str| s.bodies.get(n);
    let missing = |n: &str| verdict(p, false, None, format!("no body '{n}' in the state"));
    match p {
        Predicate::On { object, target } | Predicate::Inside { object, target } => {
            let Some(b) = body(object) else { return missing(object) };
            let inside = matches!(p, Predicate::Inside { .. });
            let mut any_target = false;
            for t in target {
                let Some(h) = body(t) else { continue };
                any_target = true;
                if (inside && within(b, h)) || (!inside && rests_on(b, h)) {
                    return verdict(p, true, Some(b.bounds.min[2]), "");
                }
            }
            if !any_target {
                return missing(target.first().map_or("", String::as_str));
            }
            let how = if inside { "within" } else { "resting on" };
            verdict(p, false, Some(b.bounds.min[2]), format!("{object} is not {how} {}", target.join(" or ")))
        }
        Predicate::StackedOn { object, target } => {
            let (Some(b), Some(h)) = (body(object), body(target)) else {
                return missing(if body(object).is_none() { object } else { target });
            };
            let dz = b.bounds.min[2] - h.bounds.max[2];
            let ok = stands_on_top(b, h);
            verdict(p, ok, Some(dz), format!("{object} is not on top of {target} (bottom {dz:+.3} m from its top)"))
        }
        Predicate::Near { object, target, within } => {
            let (Some(b), Some(h)) = (body(object), body(target)) else {
                return missing(if body(object).is_none() { object } else { target });
            };
            let g = gap(&b.bounds, &h.bounds);
            verdict(p, g <= *within, Some(g), format!("{object} is {g:.3} m from {target} (at most {within} m)"))
        }
        Predicate::InRegion { object, min, max } => {
            let Some(b) = body(object) else { return missing(object) };
            let c = b.bounds.center();
            let ok = (min[0]..=max[0]).contains(&c[0]) && (min[1]..=max[1]).contains(&c[1]);
            let d = (c[0] - 0.5 * (min[0] + max[0])).hypot(c[1] - 0.5 * (min[1] + max[1]));
            verdict(p, ok, Some(d), format!("{object}'s centre is outside the region"))
        }
        Predicate::AtPose { object, pos, tolerance } => {
            let Some(b) = body(object) else { return missing(object) };
            let c = b.bounds.center();
            let d = ((c[0] - pos[0]).powi(2) + (c[1] - pos[1]).powi(2) + (c[2] - pos[2]).powi(2)).sqrt();
            verdict(p, d <= *tolerance, Some(d), format!("{object} is {d:.3} m from the pose"))
        }
        Predicate::Open { joint, .. } | Predicate::Closed { joint, .. } => {
            let Some(&(q, lo, hi)) = s.joints.get(joint) else {
                return verdict(p, false, None, format!("no joint '{joint}' in the state"));
            };
            let f = if hi > lo { (q - lo) / (hi - lo) } else { 0.0 };
            let ok = if matches!(p, Predicate::Open { .. }) { f >= 0.8 } else { f <= 0.1 };
            verdict(p, ok, Some(f), format!("{joint} is {:.0} % open", 100.0 * f))
        }
        Predicate::NavigateTo { robot, target, within } => {
            let (Some(r), Some(h)) = (s.robots.get(robot), body(target)) else {
                return verdict(p, false, None, format!("no robot '{robot}' or body '{target}' in the state"));
            };
            let point = Bounds { min: *r, max: *r };
            let g = gap(&point, &h.bounds);
            verdict(p, g <= *within, Some(g), format!("{robot} is {g:.2} m from {target} (at most {within} m)"))
        }
    }
}
