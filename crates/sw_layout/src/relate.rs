//! Relations as the solver keeps them: a test of each per-instance relation on a
//! candidate footprint, on the same measured definitions the report uses (ARCHITECTURE.md,
//! "Relations") with tolerances a little tighter, so that what the solver accepts is
//! measured as held on the written scene.
//!
//! A [`Body`] is a footprint on the floor (world frame, the union of collision boxes)
//! with the direction its front faces. Targets are the placed instances of an object
//! group, or the placed robots of a robot group.

use sw_geom::Aabb;
use sw_plan::{Corner, RelationKind, Wall};

use crate::attempt::Ctx;
use crate::frames::Spot;

/// Largest gap to a wall for "against the wall", m (the report allows 0.15).
pub(crate) const WALL_TOL: f64 = 0.1;
/// Largest gap between footprints for "next to", m (the report allows 0.6; a machine's
/// 0.5 m side clearance must fit in it).
pub(crate) const NEXT_TO: f64 = 0.57;
/// Largest gap between footprints for "near", m (the report allows 1.5).
pub(crate) const NEAR: f64 = 1.2;
/// Largest gap for "in front of" and "behind", m (the report allows 1.5).
pub(crate) const FRONT_GAP: f64 = 1.2;
/// Sideways slack of "in front of" beyond the target's half width, m (report: 0.3).
pub(crate) const FRONT_SIDE: f64 = 0.2;
/// Largest gap to either wall for "in the corner", m (the report allows 0.3).
pub(crate) const CORNER_TOL: f64 = 0.25;
/// Largest distance from the doorway's centre for "near the door", m (report: 2.5).
pub(crate) const DOOR_DIST: f64 = 2.3;

/// A footprint on the floor and the direction its front faces.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Body {
    /// World-frame bounds (z included).
    pub fp: Aabb,
    /// Unit vector of the front (objects: +Y turned by the yaw; robots: +X).
    pub front: [f64; 2],
}

impl Body {
    pub fn object(local: &[Aabb], spot: &Spot) -> Self {
        let fp = crate::space::union(&spot.boxes(local));
        let (s, c) = spot.yaw.sin_cos();
        Body { fp, front: [-s, c] }
    }

    pub fn center(&self) -> [f64; 2] {
        [0.5 * (self.fp.min[0] + self.fp.max[0]), 0.5 * (self.fp.min[1] + self.fp.max[1])]
    }

    /// Half the footprint's extent along a unit direction.
    pub fn half_along(&self, d: [f64; 2]) -> f64 {
        0.5 * ((self.fp.max[0] - self.fp.min[0]) * d[0].abs() + (self.fp.max[1] - self.fp.min[1]) * d[1].abs())
    }
}

/// A robot as relations measure it: an arm by its base (its mounting plate), a mobile
/// base by its whole footprint; its front is its working direction (+X).
pub(crate) fn robot_body(robot: &crate::RobotItem, spot: &Spot) -> Body {
    let front = [spot.yaw.cos(), spot.yaw.sin()];
    if robot.is_arm {
        let r = robot.base_radius.max(0.1);
        let fp = Aabb { min: [spot.x - r, spot.y - r, spot.z], max: [spot.x + r, spot.y + r, spot.z + 0.2] };
        return Body { fp, front };
    }
    Body { fp: crate::space::union(&spot.boxes(&robot.keepout)), front }
}

/// Distance between two floor rectangles (negative when they overlap).
pub(crate) fn gap(a: &Aabb, b: &Aabb) -> f64 {
    let dx = (b.min[0] - a.max[0]).max(a.min[0] - b.max[0]);
    let dy = (b.min[1] - a.max[1]).max(a.min[1] - b.max[1]);
    if dx < 0.0 && dy < 0.0 { dx.max(dy) } else { dx.max(0.0).hypot(dy.max(0.0)) }
}

/// Placed instances of an object group (with their object index), or the placed robots
/// of a robot group (index `None`), as bodies.
pub(crate) fn bodies(ctx: &Ctx<'_>, target: &str) -> Vec<(Option<usize>, Body)> {
    let objects: Vec<(Option<usize>, Body)> =
        ctx.placed_instances(target).into_iter().map(|(i, s)| (Some(i), Body::object(&ctx.local[i], &s))).collect();
    if !objects.is_empty() {
        return objects;
    }
    ctx.input
        .robots
        .iter()
        .enumerate()
        .filter(|(_, r)| r.group == target)
        .filter_map(|(ri, r)| {
            let p = ctx.robots[ri].as_ref()?;
            Some((None, robot_body(r, &Spot::new(p.pos[0], p.pos[1], p.pos[2], p.yaw))))
        })
        .collect()
}

/// A group whose instances stand side by side facing the same way, taken as one body
/// (a row's front is its members' front); `None` for a single instance or a scatter.
pub(crate) fn row_body(group: &[(Option<usize>, Body)]) -> Option<Body> {
    if group.len() < 2 {
        return None;
    }
    let f = group[0].1.front;
    if group.iter().any(|(_, b)| b.front[0] * f[0] + b.front[1] * f[1] < 0.99) {
        return None;
    }
    // Collinear: centres within 0.3 m of the line through the first along the side axis.
    let c0 = group[0].1.center();
    if group.iter().any(|(_, b)| {
        let c = b.center();
        ((c[0] - c0[0]) * f[0] + (c[1] - c0[1]) * f[1]).abs() > 0.3
    }) {
        return None;
    }
    let fp = group.iter().fold(Aabb::EMPTY, |acc, (_, b)| acc.union(&b.fp));
    Some(Body { fp, front: f })
}

/// The bodies a relation to `target` is measured against: the row as one body when the
/// target group is a row, else each instance.
pub(crate) fn target_bodies(ctx: &Ctx<'_>, target: &str) -> Vec<Body> {
    let all = bodies(ctx, target);
    let mut out: Vec<Body> = all.iter().map(|(_, b)| *b).collect();
    if let Some(r) = row_body(&all) {
        out.insert(0, r);
    }
    out
}

fn wall_gap(ctx: &Ctx<'_>, fp: &Aabb, w: Wall) -> f64 {
    let [hw, hd] = ctx.space.half;
    match w {
        Wall::North => hd - fp.max[1],
        Wall::South => fp.min[1] + hd,
        Wall::East => hw - fp.max[0],
        Wall::West => fp.min[0] + hw,
    }
}

/// The walls at the room's two ends (its short walls), or `wall` when given.
pub(crate) fn end_walls(ctx: &Ctx<'_>, wall: Option<Wall>) -> Vec<Wall> {
    let [hw, hd] = ctx.space.half;
    match wall {
        Some(w) => vec![w],
        None if hw >= hd => vec![Wall::East, Wall::West],
        None => vec![Wall::North, Wall::South],
    }
}

/// The centre of the doorway on its wall.
pub(crate) fn door_point(ctx: &Ctx<'_>) -> [f64; 2] {
    let [hw, hd] = ctx.space.half;
    let d = &ctx.door;
    match d.wall {
        Wall::North => [d.offset, hd],
        Wall::South => [d.offset, -hd],
        Wall::East => [hw, d.offset],
        Wall::West => [-hw, d.offset],
    }
}

/// True when `p` lies inside the convex hull of two rectangles' corners.
pub(crate) fn in_hull(a: &Aabb, b: &Aabb, p: [f64; 2]) -> bool {
    let mut pts: Vec<[f64; 2]> = Vec::with_capacity(8);
    for r in [a, b] {
        for x in [r.min[0], r.max[0]] {
            for y in [r.min[1], r.max[1]] {
                pts.push([x, y]);
            }
        }
    }
    let hull = convex_hull(pts);
    if hull.len() < 3 {
        return false;
    }
    let n = hull.len();
    (0..n).all(|i| {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= -1e-9
    })
}

/// Counter-clockwise convex hull (monotone chain).
fn convex_hull(mut pts: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup_by(|a, b| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let mut lower: Vec<[f64; 2]> = Vec::new();
    for &p in &pts {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<[f64; 2]> = Vec::new();
    for &p in pts.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

fn inside(p: [f64; 2], r: &Aabb) -> bool {
    r.min[0] < p[0] && p[0] < r.max[0] && r.min[1] < p[1] && p[1] < r.max[1]
}

/// "in front of" (`sign` 1) or "behind" (`sign` -1) a target body.
pub(crate) fn in_front(s: &Body, t: &Body, sign: f64) -> bool {
    let f = [t.front[0] * sign, t.front[1] * sign];
    let side = [-f[1], f[0]];
    let (c, tc) = (s.center(), t.center());
    let d = [c[0] - tc[0], c[1] - tc[1]];
    let along = d[0] * f[0] + d[1] * f[1];
    let lateral = (d[0] * side[0] + d[1] * side[1]).abs();
    along > t.half_along(f) && lateral <= t.half_along(side) + FRONT_SIDE && gap(&s.fp, &t.fp) <= FRONT_GAP
}

/// True when a body at the end of a row: on the row's line, beyond its last member.
pub(crate) fn at_row_end(s: &Body, row: &Body) -> bool {
    let f = row.front;
    let u = [-f[1], f[0]];
    let (c, rc) = (s.center(), row.center());
    let d = [c[0] - rc[0], c[1] - rc[1]];
    let along = (d[0] * u[0] + d[1] * u[1]).abs();
    let perp = (d[0] * f[0] + d[1] * f[1]).abs();
    along > row.half_along(u) && perp <= 0.5 && gap(&s.fp, &row.fp) <= NEXT_TO
}

/// One per-instance relation, ready to test many candidate bodies: the target bodies
/// are gathered once.
pub(crate) struct Check<'r> {
    pub rel: &'r RelationKind,
    /// Target bodies (the row as one body first, when the target is a row).
    targets: Vec<Body>,
    /// For "between": instances of the two groups, with their object index.
    firsts: Vec<(Option<usize>, Body)>,
    seconds: Vec<(Option<usize>, Body)>,
    /// For "at the end of the row": the row.
    row: Option<Body>,
}

impl<'r> Check<'r> {
    pub fn new(ctx: &Ctx<'_>, rel: &'r RelationKind) -> Self {
        let mut c = Check { rel, targets: Vec::new(), firsts: Vec::new(), seconds: Vec::new(), row: None };
        match rel {
            RelationKind::Between { first, second } => {
                c.firsts = bodies(ctx, first);
                c.seconds = bodies(ctx, second);
            }
            RelationKind::AtEndOfRow { target } => {
                let all = bodies(ctx, target);
                c.row = row_body(&all);
                c.targets = all.into_iter().map(|(_, b)| b).collect();
            }
            RelationKind::Under { target } => {
                c.targets = bodies(ctx, target).into_iter().map(|(_, b)| b).collect();
            }
            r => {
                if let Some(t) = r.targets().first() {
                    c.targets = target_bodies(ctx, t);
                }
            }
        }
        c
    }

    /// Whether a body satisfies the relation. Group relations (rows, stacks, loads) are
    /// kept by their formations and hold here.
    pub fn holds(&self, ctx: &Ctx<'_>, body: &Body, group_size: usize) -> bool {
        let fp = &body.fp;
        let [hw, hd] = ctx.space.half;
        let near_target = |limit: f64| self.targets.iter().any(|t| gap(fp, &t.fp) <= limit);
        match self.rel {
            RelationKind::AgainstWall { wall } | RelationKind::Leaning { wall } => match wall {
                Some(w) => wall_gap(ctx, fp, *w) <= WALL_TOL,
                None => Wall::ALL.iter().any(|w| wall_gap(ctx, fp, *w) <= WALL_TOL),
            },
            RelationKind::InCorner { corner } => {
                let corners = corner.map_or(Corner::ALL.to_vec(), |c| vec![c]);
                corners.iter().any(|c| {
                    let (a, b) = c.walls();
                    wall_gap(ctx, fp, a) <= CORNER_TOL && wall_gap(ctx, fp, b) <= CORNER_TOL
                })
            }
            RelationKind::AtEnd { wall } => end_walls(ctx, *wall).iter().any(|w| {
                let long = if matches!(w, Wall::East | Wall::West) { 2.0 * hw } else { 2.0 * hd };
                let c = body.center();
                let from_wall = match w {
                    Wall::North => hd - c[1],
                    Wall::South => c[1] + hd,
                    Wall::East => hw - c[0],
                    Wall::West => c[0] + hw,
                };
                from_wall <= 0.22 * long
            }),
            RelationKind::NearDoor => {
                let d = door_point(ctx);
                let c = body.center();
                (c[0] - d[0]).hypot(c[1] - d[1]) <= DOOR_DIST
            }
            RelationKind::InCenter => {
                let c = body.center();
                let (along, across, long, short) =
                    if hw >= hd { (c[0], c[1], 2.0 * hw, 2.0 * hd) } else { (c[1], c[0], 2.0 * hd, 2.0 * hw) };
                // A group runs down the middle; one object stands in the middle.
                across.abs() <= 0.18 * short && (group_size > 1 || along.abs() <= 0.22 * long)
            }
            RelationKind::NextTo { .. } => near_target(NEXT_TO),
            RelationKind::Near { .. } | RelationKind::Around { .. } => near_target(NEAR),
            RelationKind::InFrontOf { .. } => self.targets.iter().any(|t| in_front(body, t, 1.0)),
            RelationKind::Behind { .. } => self.targets.iter().any(|t| in_front(body, t, -1.0)),
            RelationKind::AtEndOfRow { .. } => match &self.row {
                Some(row) => at_row_end(body, row),
                None => near_target(NEXT_TO),
            },
            RelationKind::Between { .. } => {
                let c = body.center();
                self.firsts.iter().any(|(ia, ba)| {
                    self.seconds.iter().any(|(ib, bb)| {
                        let same = match (ia, ib) {
                            (Some(a), Some(b)) => a == b,
                            _ => ba.fp.min == bb.fp.min && ba.fp.max == bb.fp.max,
                        };
                        !same && in_hull(&ba.fp, &bb.fp, c) && !inside(c, &ba.fp) && !inside(c, &bb.fp)
                    })
                })
            }
            RelationKind::Under { .. } => self.targets.iter().any(|t| {
                let c = body.center();
                inside(c, &t.fp) && fp.max[2] <= t.fp.max[2]
            }),
            RelationKind::On { .. }
            | RelationKind::OnTwoWalls
            | RelationKind::InRow
            | RelationKind::InRows { .. }
            | RelationKind::InAisles
            | RelationKind::FacingEachOther
            | RelationKind::Stacked { .. }
            | RelationKind::Loaded { .. }
            | RelationKind::FullOf { .. }
            | RelationKind::EachWith { .. }
            | RelationKind::Reach { .. }
            | RelationKind::Inside { .. }
            | RelationKind::SetInto { .. }
            | RelationKind::AtEndOf { .. }
            | RelationKind::OnEdgeOf { .. }
            | RelationKind::OnEachSideOf { .. }
            | RelationKind::Facing { .. }
            | RelationKind::OnOppositeWalls { .. }
            | RelationKind::InCorners
            | RelationKind::BackToBack => true,
        }
    }
}

/// Whether a body satisfies one relation (gathers the targets each call; use [`Check`]
/// for many bodies).
pub(crate) fn holds(ctx: &Ctx<'_>, body: &Body, rel: &RelationKind, group_size: usize) -> bool {
    Check::new(ctx, rel).holds(ctx, body, group_size)
}

/// Relations that say where a floor body stands (as opposed to what rests on what, or
/// how a group is arranged).
pub(crate) fn is_positional(rel: &RelationKind) -> bool {
    matches!(
        rel,
        RelationKind::AgainstWall { .. }
            | RelationKind::Leaning { .. }
            | RelationKind::InCorner { .. }
            | RelationKind::AtEnd { .. }
            | RelationKind::NearDoor
            | RelationKind::InCenter
            | RelationKind::NextTo { .. }
            | RelationKind::Near { .. }
            | RelationKind::InFrontOf { .. }
            | RelationKind::Behind { .. }
            | RelationKind::AtEndOfRow { .. }
            | RelationKind::Between { .. }
            | RelationKind::Under { .. }
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(x0: f64, y0: f64, x1: f64, y1: f64) -> Aabb {
        Aabb { min: [x0, y0, 0.0], max: [x1, y1, 1.0] }
    }

    #[test]
    fn the_hull_of_two_racks_holds_the_aisle_between_them() {
        let a = r(-2.0, 1.0, 2.0, 2.0);
        let b = r(-2.0, -2.0, 2.0, -1.0);
        assert!(in_hull(&a, &b, [0.0, 0.0]));
        assert!(in_hull(&a, &b, [1.9, 0.5]));
        assert!(!in_hull(&a, &b, [2.5, 0.0]));
        // Diagonal placement: the hull is a hexagon.
        let c = r(0.0, 0.0, 1.0, 1.0);
        let d = r(3.0, 3.0, 4.0, 4.0);
        assert!(in_hull(&c, &d, [2.0, 2.0]));
        assert!(!in_hull(&c, &d, [0.5, 3.5]));
    }

    #[test]
    fn in_front_and_behind_are_judged_from_the_targets_front() {
        let t = Body { fp: r(-0.5, -0.3, 0.5, 0.3), front: [0.0, 1.0] };
        let front = Body { fp: r(-0.2, 0.5, 0.2, 0.9), front: [0.0, -1.0] };
        let back = Body { fp: r(-0.2, -0.9, 0.2, -0.5), front: [0.0, 1.0] };
        assert!(in_front(&front, &t, 1.0) && !in_front(&front, &t, -1.0));
        assert!(in_front(&back, &t, -1.0) && !in_front(&back, &t, 1.0));
        let far_side = Body { fp: r(1.5, 0.5, 1.9, 0.9), front: [0.0, 1.0] };
        assert!(!in_front(&far_side, &t, 1.0));
    }

    #[test]
    fn a_body_beyond_the_last_member_of_a_row_is_at_its_end() {
        let row = Body { fp: r(-2.0, -0.3, 2.0, 0.3), front: [0.0, 1.0] };
        assert!(at_row_end(&Body { fp: r(2.1, -0.2, 2.5, 0.2), front: [0.0, 1.0] }, &row));
        assert!(!at_row_end(&Body { fp: r(0.0, 0.5, 0.4, 0.9), front: [0.0, 1.0] }, &row));
        assert!(!at_row_end(&Body { fp: r(4.0, -0.2, 4.4, 0.2), front: [0.0, 1.0] }, &row));
    }
}
