//! Where to look: candidate poses for one body — an object, or a formation taken as one
//! body — best first. Each generator takes the body's bounds in its own frame (front
//! +Y) and yields poses at quarter turns; the solver keeps the first that fits and
//! satisfies every relation (`relate::holds`).

use std::f64::consts::PI;
use std::rc::Rc;

use sw_geom::{Aabb, Rng};
use sw_plan::{Corner, EndOf, RelationKind, Wall};

use crate::attempt::Ctx;
use crate::frames::{QUARTER_TURNS, Spot, yaw_facing};
use crate::relate::{self, Body};
use crate::space::{FLOOR_GAP, WALL_GAP};

/// Along-wall and grid resolution of candidate positions, m.
pub(crate) const STEP: f64 = 0.05;

/// A per-group pseudo-random number, stable across the group's instances.
pub(crate) fn group_rng(ctx: &Ctx<'_>, group: &str) -> u64 {
    sw_geom::fnv1a(group.as_bytes()) ^ ctx.input.seed.rotate_left(13) ^ ctx.input.seed.wrapping_mul(0x9E37_79B9)
}

/// The footprint of bounds `b` at `yaw`, with the body at the origin.
fn footprint_at(b: &Aabb, yaw: f64) -> Aabb {
    b.transformed(&Spot::new(0.0, 0.0, 0.0, yaw).pose())
}

/// Smallest coordinate of a rectangle's corners along a unit axis direction.
fn lo_along(r: &Aabb, d: [f64; 2]) -> f64 {
    let xs = [r.min[0] * d[0], r.max[0] * d[0]];
    let ys = [r.min[1] * d[1], r.max[1] * d[1]];
    xs[0].min(xs[1]) + ys[0].min(ys[1])
}

/// The pose at `yaw` whose footprint's nearest face along `dir` is at `lo` and whose
/// centre along `side` is at `mid` (`dir` and `side` axis-aligned unit vectors).
pub(crate) fn aligned(b: &Aabb, yaw: f64, dir: [f64; 2], lo: f64, side: [f64; 2], mid: f64) -> Spot {
    let fp = footprint_at(b, yaw);
    let c = [0.5 * (fp.min[0] + fp.max[0]), 0.5 * (fp.min[1] + fp.max[1])];
    let da = lo - lo_along(&fp, dir);
    let db = mid - (c[0] * side[0] + c[1] * side[1]);
    Spot::new(dir[0] * da + side[0] * db, dir[1] * da + side[1] * db, 0.0, yaw)
}

/// The unit axis direction nearest to `v`.
fn axis(v: [f64; 2]) -> [f64; 2] {
    if v[0].abs() >= v[1].abs() { [v[0].signum(), 0.0] } else { [0.0, v[1].signum()] }
}

/// Candidates for one relation, best first. `k` is the instance's index in its group
/// (spreads a group over the target's instances).
pub(crate) fn for_relation(ctx: &mut Ctx<'_>, b: &Aabb, group: &str, k: usize, rel: &RelationKind) -> Vec<Spot> {
    match rel {
        RelationKind::AgainstWall { wall } | RelationKind::Leaning { wall } => wall_slots(ctx, b, group, *wall),
        RelationKind::InCorner { corner } => corner_slots(ctx, b, *corner),
        RelationKind::AtEnd { wall } => {
            let mut v = Vec::new();
            for w in relate::end_walls(ctx, *wall) {
                v.extend(along_wall(ctx, b, w, false));
                v.extend(strip_near(ctx, b, group, w));
            }
            v
        }
        RelationKind::NearDoor => {
            let door = ctx.door.wall;
            let mut v = along_wall(ctx, b, door, false);
            let d = relate::door_point(ctx);
            v.extend(free_grid(ctx, b, group, false).iter().copied());
            v.sort_by(|a, b| (a.x - d[0]).hypot(a.y - d[1]).total_cmp(&(b.x - d[0]).hypot(b.y - d[1])));
            v
        }
        RelationKind::InCenter => center_slots(ctx, b, group),
        RelationKind::NextTo { target } | RelationKind::Near { target } => beside(ctx, b, target, k),
        RelationKind::InFrontOf { target } => {
            let mut v = facing_side(ctx, b, target, k, 1.0);
            v.extend(past_siblings(ctx, b, group, target, 1.0));
            v
        }
        RelationKind::Behind { target } => {
            let mut v = facing_side(ctx, b, target, k, -1.0);
            v.extend(past_siblings(ctx, b, group, target, -1.0));
            v
        }
        RelationKind::AtEndOfRow { target } => row_end(ctx, b, target),
        RelationKind::Between { first, second } => between(ctx, first, second, k),
        RelationKind::Under { target } => under(ctx, target, k, ctx.instances(group).len()),
        RelationKind::Around { target } => around_one(ctx, b, target, k),
        RelationKind::InCorners => corner_slots(ctx, b, None),
        RelationKind::Facing { target } => facing_toward(ctx, b, target, k),
        RelationKind::OnEachSideOf { target } => {
            let bodies: Vec<Body> = relate::bodies(ctx, target).into_iter().map(|(_, b)| b).collect();
            let n = ctx.instances(group).len().max(1);
            // Two to a target: instance k flanks target k / 2 (round robin beyond).
            let per = n.div_ceil(bodies.len().max(1)).max(1);
            apart(b, &rotated(bodies, k / per), &[0.06, 0.15, 0.3, 0.5, 0.8])
        }
        RelationKind::AtEndOf { target, end } => end_slots(ctx, b, target, *end),
        RelationKind::SetInto { target } => run_slots(ctx, b, target),
        _ => Vec::new(),
    }
}

/// Facing a target from its front first, then its other sides, at increasing distances,
/// turned to it.
fn facing_toward(ctx: &Ctx<'_>, b: &Aabb, target: &str, k: usize) -> Vec<Spot> {
    let bodies = rotated(relate::bodies(ctx, target).into_iter().map(|(_, b)| b).collect(), k);
    let mut out = Vec::new();
    for t in &bodies {
        let f = axis(t.front);
        let dirs = [f, [f[1], -f[0]], [-f[1], f[0]], [-f[0], -f[1]]];
        let tc = t.center();
        for d in [0.8, 1.2, 1.7, 2.3, 3.0, 0.45, 3.8] {
            for dir in dirs {
                let side = [-dir[1], dir[0]];
                let face = tc[0] * dir[0] + tc[1] * dir[1] + t.half_along(dir) + d;
                let mid = tc[0] * side[0] + tc[1] * side[1];
                let yaw = yaw_facing(-dir[0], -dir[1]);
                for shift in [0.0, 0.25, -0.25, 0.5, -0.5] {
                    out.push(aligned(b, yaw, dir, face, side, mid + shift));
                }
            }
        }
    }
    out
}

/// Beyond the ends of a target (its long axis; its local −X / +X for a start / end),
/// on its axis line, turned like it and across it.
fn end_slots(ctx: &Ctx<'_>, b: &Aabb, target: &str, end: Option<EndOf>) -> Vec<Spot> {
    let all = relate::bodies(ctx, target);
    let mut targets: Vec<Body> = relate::row_body(&all).into_iter().collect();
    targets.extend(all.iter().map(|(_, b)| *b));
    let mut out = Vec::new();
    for t in &targets {
        let x = axis(relate::x_axis(t));
        let long = if t.half_along(x) >= t.half_along(t.front) { x } else { axis(t.front) };
        let dirs: Vec<[f64; 2]> = match end {
            Some(EndOf::Start) => vec![[-x[0], -x[1]]],
            Some(EndOf::End) => vec![x],
            _ => vec![long, [-long[0], -long[1]]],
        };
        let c = t.center();
        let yaw = yaw_facing(t.front[0], t.front[1]);
        for extra in [0.0, 0.1, 0.25, 0.45, 0.7] {
            for dir in &dirs {
                let side = [-dir[1], dir[0]];
                let face = c[0] * dir[0] + c[1] * dir[1] + t.half_along(*dir) + FLOOR_GAP + 0.01 + extra;
                let mid = c[0] * side[0] + c[1] * side[1];
                for turn in [0.0, PI / 2.0, PI, -PI / 2.0] {
                    out.push(aligned(b, yaw + turn, *dir, face, side, mid));
                }
            }
        }
    }
    out
}

/// In a target's run: at either end of it along its X, turned like it, fronts flush,
/// abutting (the solver lets the two touch; see `floor::place`).
fn run_slots(ctx: &Ctx<'_>, b: &Aabb, target: &str) -> Vec<Spot> {
    let mut out = Vec::new();
    for (_, t) in relate::bodies(ctx, target) {
        let f = axis(t.front);
        let x = [f[1], -f[0]];
        let yaw = yaw_facing(f[0], f[1]);
        let fp = footprint_at(b, yaw);
        let half_f = 0.5 * ((fp.max[0] - fp.min[0]) * f[0].abs() + (fp.max[1] - fp.min[1]) * f[1].abs());
        let c = t.center();
        // The subject's front plane on the target's.
        let front = c[0] * f[0] + c[1] * f[1] + t.half_along(f);
        for dir in [x, [-x[0], -x[1]]] {
            let face = c[0] * dir[0] + c[1] * dir[1] + t.half_along(dir) + 0.012;
            out.push(aligned(b, yaw, dir, face, f, front - half_f));
        }
    }
    out
}

/// Slots with the back to a wall, facing into the room, along `wall` (or every wall,
/// long walls first, in a seeded order).
pub(crate) fn wall_slots(ctx: &Ctx<'_>, b: &Aabb, group: &str, wall: Option<Wall>) -> Vec<Spot> {
    let seed = group_rng(ctx, group);
    let walls: Vec<Wall> = match wall {
        Some(w) => vec![w],
        None => {
            let [hw, hd] = ctx.space.half;
            let (long, short) = if hw >= hd {
                ([Wall::North, Wall::South], [Wall::East, Wall::West])
            } else {
                ([Wall::East, Wall::West], [Wall::North, Wall::South])
            };
            let mut l = long.to_vec();
            let mut s = short.to_vec();
            if seed & 1 == 1 {
                l.reverse();
            }
            if seed & 2 == 2 {
                s.reverse();
            }
            l.extend(s);
            l
        }
    };
    let reverse = seed & 4 == 4;
    walls.into_iter().flat_map(|w| along_wall(ctx, b, w, reverse)).collect()
}

/// The inward normal of a wall.
pub(crate) fn inward(w: Wall) -> [f64; 2] {
    let o = w.outward();
    [-o[0], -o[1]]
}

/// Poses along a wall, back to it, from one end to the other.
pub(crate) fn along_wall(ctx: &Ctx<'_>, b: &Aabb, wall: Wall, reverse: bool) -> Vec<Spot> {
    let [hw, hd] = ctx.space.half;
    let n = inward(wall);
    let yaw = yaw_facing(n[0], n[1]);
    let side = [n[1].abs(), n[0].abs()];
    let fp = footprint_at(b, yaw);
    let half_along = 0.5 * ((fp.max[0] - fp.min[0]) * side[0] + (fp.max[1] - fp.min[1]) * side[1]);
    let (half_room_along, wall_at) = match wall {
        Wall::North | Wall::South => (hw, hd),
        Wall::East | Wall::West => (hd, hw),
    };
    // The face nearest the wall sits WALL_GAP + 2 mm from it.
    let lo = -wall_at + WALL_GAP + 0.002;
    let start = -half_room_along + WALL_GAP + half_along + 0.002;
    let end = half_room_along - WALL_GAP - half_along - 0.002;
    if end < start {
        return Vec::new();
    }
    let steps = ((end - start) / STEP).floor() as usize;
    (0..=steps)
        .map(|k| {
            let t = if reverse { end - k as f64 * STEP } else { start + k as f64 * STEP };
            aligned(b, yaw, n, lo, side, t)
        })
        .collect()
}

/// Near each corner of the room (or the named one), along both of its walls.
fn corner_slots(ctx: &Ctx<'_>, b: &Aabb, corner: Option<Corner>) -> Vec<Spot> {
    let corners = corner.map_or(Corner::ALL.to_vec(), |c| vec![c]);
    let mut out = Vec::new();
    for c in corners {
        let (ns, ew) = c.walls();
        for w in [ns, ew] {
            let mut slots = along_wall(ctx, b, w, false);
            let other = if w == ns { ew } else { ns };
            let key = |s: &Spot| match other {
                Wall::East => -s.x,
                Wall::West => s.x,
                Wall::North => -s.y,
                Wall::South => s.y,
            };
            slots.sort_by(|a, b| key(a).total_cmp(&key(b)));
            out.extend(slots.into_iter().take(40));
        }
    }
    out
}

/// Grid positions in the fifth of the room next to `wall`.
fn strip_near(ctx: &mut Ctx<'_>, b: &Aabb, group: &str, wall: Wall) -> Vec<Spot> {
    let [hw, hd] = ctx.space.half;
    free_grid(ctx, b, group, false)
        .iter()
        .copied()
        .filter(|s| match wall {
            Wall::North => s.y > hd * 0.6,
            Wall::South => s.y < -hd * 0.6,
            Wall::East => s.x > hw * 0.6,
            Wall::West => s.x < -hw * 0.6,
        })
        .collect()
}

/// In the middle of the room, long axis first: the body's width along the room's long
/// axis, outwards from the centre.
pub(crate) fn center_slots(ctx: &mut Ctx<'_>, b: &Aabb, group: &str) -> Vec<Spot> {
    let [hw, hd] = ctx.space.half;
    let long_x = hw >= hd;
    let mut out: Vec<(f64, Spot)> = free_grid(ctx, b, group, true)
        .iter()
        .map(|s| {
            // Along the long axis the body's width (local X) lies along it at yaw 0 / π.
            let lengthwise = if long_x { s.yaw.sin().abs() < 0.5 } else { s.yaw.cos().abs() < 0.5 };
            let across = if long_x { s.y.abs() } else { s.x.abs() };
            let along = if long_x { s.x.abs() } else { s.y.abs() };
            (across * 3.0 + along * 0.5 + if lengthwise { 0.0 } else { 0.4 }, *s)
        })
        .collect();
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out.into_iter().map(|(_, s)| s).collect()
}

/// Grid positions over the whole floor at every quarter turn; `central` orders them from
/// the middle of the room outwards, otherwise in a seeded random order. Cached per group
/// and size of body.
pub(crate) fn free_grid(ctx: &mut Ctx<'_>, b: &Aabb, group: &str, central: bool) -> Rc<Vec<Spot>> {
    let s = b.size();
    let key = (format!("{group}#{:.3}x{:.3}", s[0], s[1]), central);
    if let Some(g) = ctx.grid_cache.get(&key) {
        return Rc::clone(g);
    }
    let [hw, hd] = ctx.space.half;
    // Fine enough to pack, coarse enough that a large room stays a few thousand points.
    let step = (s[0].min(s[1]) / 2.0).clamp(0.1, 1.0).max((4.0 * hw * hd / 4000.0).sqrt());
    let mut rng = Rng::derive(group_rng(ctx, group), if central { "central grid" } else { "grid" });
    let nx = ((2.0 * hw) / step).floor() as i64;
    let ny = ((2.0 * hd) / step).floor() as i64;
    let mut keyed: Vec<(f64, (f64, f64))> = Vec::with_capacity(((nx + 1) * (ny + 1)) as usize);
    for i in 0..=nx {
        for j in 0..=ny {
            let p = (-hw + i as f64 * step, -hd + j as f64 * step);
            let key = if central { p.0.hypot(p.1) + rng.range(0.0, step) } else { rng.unit() };
            keyed.push((key, p));
        }
    }
    keyed.sort_by(|a, b| a.0.total_cmp(&b.0));
    let start = rng.below(4);
    let mut out = Vec::with_capacity(keyed.len() * 4);
    for (_, (x, y)) in keyed {
        for k in 0..4 {
            out.push(Spot::new(x, y, 0.0, QUARTER_TURNS[(start + k) % 4]));
        }
    }
    let out = Rc::new(out);
    ctx.grid_cache.insert(key, Rc::clone(&out));
    out
}

/// Target bodies starting with the one matching instance `k` (round robin).
fn rotated(mut v: Vec<Body>, k: usize) -> Vec<Body> {
    if !v.is_empty() {
        let n = v.len();
        v.rotate_left(k % n);
    }
    v
}

/// Beside a target: left and right of it (same facing), then in front and behind,
/// a little further out each round.
pub(crate) fn beside(ctx: &Ctx<'_>, b: &Aabb, target: &str, k: usize) -> Vec<Spot> {
    // Beside an arm on a stand: beside its stand (the arm's own base is inside it).
    let stands: Vec<Body> = ctx
        .input
        .robots
        .iter()
        .filter(|r| r.group == target)
        .filter_map(|r| match &r.mount {
            crate::RobotMount::Carrier { object } => {
                let i = ctx.input.objects.iter().position(|o| &o.name == object)?;
                ctx.placed[i].as_ref().map(|p| Body::object(&ctx.local[i], &p.spot))
            }
            _ => None,
        })
        .collect();
    let bodies: Vec<Body> =
        if stands.is_empty() { relate::bodies(ctx, target).into_iter().map(|(_, b)| b).collect() } else { stands };
    beside_bodies(b, &rotated(bodies, k))
}

pub(crate) fn beside_bodies(b: &Aabb, targets: &[Body]) -> Vec<Spot> {
    let gaps: Vec<f64> = [0.0, 0.1, 0.25, 0.45, 0.8].iter().map(|e| FLOOR_GAP + 0.01 + e).collect();
    apart(b, targets, &gaps)
}

/// Poses beside each target at each of `gaps` (footprint to footprint), on its four
/// sides, centred and slid along each side.
pub(crate) fn apart(b: &Aabb, targets: &[Body], gaps: &[f64]) -> Vec<Spot> {
    let mut out = Vec::new();
    for &g in gaps {
        for t in targets {
            let f = axis(t.front);
            let side = [-f[1], f[0]];
            let tc = t.center();
            let yaw = yaw_facing(f[0], f[1]);
            // Its long faces first (things stand side by side), then its ends.
            let mut faces = [(side, f), ([-side[0], -side[1]], f), (f, side), ([-f[0], -f[1]], side)];
            faces.sort_by(|a, b| t.half_along(a.0).total_cmp(&t.half_along(b.0)));
            for (dir, shift_dir) in faces {
                let face = tc[0] * dir[0] + tc[1] * dir[1] + t.half_along(dir) + g;
                let mid = tc[0] * shift_dir[0] + tc[1] * shift_dir[1];
                // Centred on the side, then slid along it (to reach two things at once,
                // or to step out of a corner).
                let half = t.half_along(shift_dir);
                for shift in [0.0, 0.5, -0.5, 1.0, -1.0] {
                    for turn in [0.0, PI, PI / 2.0, -PI / 2.0] {
                        out.push(aligned(b, yaw + turn, dir, face, shift_dir, mid + shift * half));
                    }
                }
            }
        }
    }
    out
}

/// In front of (`sign` 1) or behind (`sign` -1) a target's front — a row's, when the
/// target group is a row — facing it, or alongside it (a conveyor behind a row of
/// stations runs along the row).
fn facing_side(ctx: &Ctx<'_>, b: &Aabb, target: &str, k: usize, sign: f64) -> Vec<Spot> {
    let all = relate::bodies(ctx, target);
    let mut bodies: Vec<Body> = rotated(all.iter().map(|(_, b)| *b).collect(), k);
    if let Some(row) = relate::row_body(&all) {
        bodies.insert(0, row);
    }
    facing_bodies(b, &bodies, sign)
}

/// Several in front of (behind) one target narrower than they are together ("a bin and
/// three trays in front of it"): beyond each member of the group already there, away
/// from the target's face, and beside it, a floor gap apart — the fixed steps of
/// [`facing_bodies`] leave gaps narrower than the thing between its placed siblings.
fn past_siblings(ctx: &Ctx<'_>, b: &Aabb, group: &str, target: &str, sign: f64) -> Vec<Spot> {
    let mut out = Vec::new();
    let gap = FLOOR_GAP + 0.01;
    for (_, t) in relate::bodies(ctx, target) {
        let f = axis([t.front[0] * sign, t.front[1] * sign]);
        let side = [-f[1], f[0]];
        let toward = yaw_facing(-f[0], -f[1]);
        for (_, m) in relate::bodies(ctx, group) {
            let mc = m.center();
            let (lo, hi) = relate::span(&m.fp, f);
            let (slo, shi) = relate::span(&m.fp, side);
            let mid = mc[0] * side[0] + mc[1] * side[1];
            for turn in [0.0, PI] {
                let fp = footprint_at(b, toward + turn);
                let half_side =
                    0.5 * ((fp.max[0] - fp.min[0]) * side[0].abs() + (fp.max[1] - fp.min[1]) * side[1].abs());
                // Beyond it, then beside it on either hand, level with it.
                out.push(aligned(b, toward + turn, f, hi + gap, side, mid));
                out.push(aligned(b, toward + turn, f, lo, side, shi + gap + half_side));
                out.push(aligned(b, toward + turn, f, lo, side, slo - gap - half_side));
            }
        }
    }
    out
}

pub(crate) fn facing_bodies(b: &Aabb, targets: &[Body], sign: f64) -> Vec<Spot> {
    let mut out = Vec::new();
    for t in targets {
        let f = axis([t.front[0] * sign, t.front[1] * sign]);
        let side = [-f[1], f[0]];
        let tc = t.center();
        let half_w = t.half_along(side);
        let face = tc[0] * f[0] + tc[1] * f[1] + t.half_along(f);
        let mid = tc[0] * side[0] + tc[1] * side[1];
        // Turned to face the target, then parallel to it, then across.
        let toward = yaw_facing(-f[0], -f[1]);
        for d in [0.1, 0.25, 0.45, 0.7, 1.0] {
            for turn in [0.0, PI, PI / 2.0, -PI / 2.0] {
                for s in [0.0_f64, -0.15, 0.15, -0.3, 0.3, -0.5, 0.5, -0.8, 0.8, -1.2, 1.2] {
                    if s.abs() > half_w + 0.1 && s != 0.0 {
                        continue;
                    }
                    out.push(aligned(b, toward + turn, f, face + d, side, mid + s));
                }
            }
        }
    }
    out
}

/// At either end of a row, on its line.
fn row_end(ctx: &Ctx<'_>, b: &Aabb, target: &str) -> Vec<Spot> {
    let all = relate::bodies(ctx, target);
    let row = relate::row_body(&all).or_else(|| all.first().map(|(_, b)| *b));
    let Some(row) = row else { return Vec::new() };
    let f = axis(row.front);
    let u = [-f[1], f[0]];
    let c = row.center();
    let yaw = yaw_facing(f[0], f[1]);
    let mid = c[0] * f[0] + c[1] * f[1];
    let mut out = Vec::new();
    for extra in [0.0, 0.1, 0.25, 0.4] {
        for dir in [u, [-u[0], -u[1]]] {
            let face = c[0] * dir[0] + c[1] * dir[1] + row.half_along(dir) + FLOOR_GAP + 0.01 + extra;
            for turn in [0.0, PI, PI / 2.0, -PI / 2.0] {
                out.push(aligned(b, yaw + turn, dir, face, f, mid));
            }
        }
    }
    out
}

/// Between instances of two groups (or two instances of one group): the middle of the
/// gap between their facing faces first.
fn between(ctx: &Ctx<'_>, first: &str, second: &str, k: usize) -> Vec<Spot> {
    let a = relate::bodies(ctx, first);
    let b = relate::bodies(ctx, second);
    let mut mids = Vec::new();
    for (ia, ba) in &a {
        for (ib, bb) in &b {
            if ia.is_some() && ia == ib || (ia.is_none() && ba.fp.min == bb.fp.min) {
                continue;
            }
            let (ca, cb) = (ba.center(), bb.center());
            let d = (ca[0] - cb[0]).hypot(ca[1] - cb[1]);
            mids.push((d, [0.5 * (ca[0] + cb[0]), 0.5 * (ca[1] + cb[1])], ba.front));
        }
    }
    mids.sort_by(|x, y| x.0.total_cmp(&y.0));
    if !mids.is_empty() {
        let n = mids.len();
        mids.rotate_left(k % n);
    }
    let mut out = Vec::new();
    for (_, [x, y], front) in mids {
        let yaw = yaw_facing(front[0], front[1]);
        for r in [0.0, 0.2, 0.4, 0.7, 1.0, 1.5] {
            for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
                if r == 0.0 && (dx != 0.0 || dy != 0.0) {
                    continue;
                }
                for turn in [0.0, PI / 2.0, PI, -PI / 2.0] {
                    out.push(Spot::new(x + dx * r, y + dy * r, 0.0, yaw + turn));
                }
            }
        }
    }
    out
}

/// Inside a target's footprint (under a table or bench): several under one target share
/// its length, instance `k` in its own slot first.
fn under(ctx: &Ctx<'_>, target: &str, k: usize, group_size: usize) -> Vec<Spot> {
    let mut t = ctx.placed_instances(target);
    let per = group_size.div_ceil(t.len().max(1)).max(1);
    if !t.is_empty() {
        let n = t.len();
        t.rotate_left((k / per) % n);
    }
    let mut out = Vec::new();
    for (ti, ts) in t {
        let tb = ctx.bounds[ti];
        let (cx, cy) = (0.5 * (tb.min[0] + tb.max[0]), 0.5 * (tb.min[1] + tb.max[1]));
        let (hx, hy) = (0.5 * (tb.max[0] - tb.min[0]), 0.5 * (tb.max[1] - tb.min[1]));
        if per > 1 {
            let slot = (k % per) as f64;
            let fx = -1.0 + (2.0 * slot + 1.0) / per as f64;
            let p = ts.apply([cx + fx * hx, cy, 0.0]);
            out.push(Spot::new(p[0], p[1], 0.0, ts.yaw + PI / 2.0));
            out.push(Spot::new(p[0], p[1], 0.0, ts.yaw));
        }
        for fx in [0.0, -0.3, 0.3, -0.6, 0.6, -0.1, 0.1, -0.2, 0.2, -0.4, 0.4, -0.5, 0.5, -0.7, 0.7] {
            for fy in [0.0, -0.3, 0.3] {
                let p = ts.apply([cx + fx * hx, cy + fy * hy, 0.0]);
                out.push(Spot::new(p[0], p[1], 0.0, ts.yaw));
                out.push(Spot::new(p[0], p[1], 0.0, ts.yaw + PI / 2.0));
            }
        }
    }
    out
}

/// One piece around a target (the formation spreads a group; this is for a single
/// piece): on the side `k` first, facing the target.
fn around_one(ctx: &Ctx<'_>, b: &Aabb, target: &str, k: usize) -> Vec<Spot> {
    let Some(t) = relate::target_bodies(ctx, target).into_iter().next() else { return Vec::new() };
    around_body(b, &t, &sides_from(k), &OUTSIDE)
}

/// Gaps to a target's face for pieces standing around it, m.
/// The far ones leave room for what else stands by the target ("chairs around the table
/// with a trolley beside it").
pub(crate) const OUTSIDE: [f64; 7] = [0.07, 0.22, 0.42, 0.67, 1.0, 1.4, 1.9];
/// Gaps for seats around a table: tucked under its top first (negative), then out.
pub(crate) const TUCKED: [f64; 8] = [-0.3, -0.2, -0.1, 0.0, 0.07, 0.2, 0.35, 0.6];

/// The four sides of a body, side `k % 4` first: 0 front, 1 right, 2 back, 3 left.
pub(crate) fn sides_from(k: usize) -> [usize; 4] {
    [k % 4, (k + 1) % 4, (k + 2) % 4, (k + 3) % 4]
}

/// Poses on the given sides of a body (0 front, 1 right, 2 back, 3 left), in that
/// order, every gap in `tucks` on a side before the next, each facing the body.
pub(crate) fn around_body(b: &Aabb, t: &Body, sides: &[usize], tucks: &[f64]) -> Vec<Spot> {
    let f = axis(t.front);
    let dirs = [f, [f[1], -f[0]], [-f[0], -f[1]], [-f[1], f[0]]];
    let tc = t.center();
    let mut out = Vec::new();
    for &s in sides {
        let n = dirs[s % 4];
        let side = [-n[1], n[0]];
        let mid = tc[0] * side[0] + tc[1] * side[1];
        // Shifts along the side: within the target's length, or by the piece's own width
        // when the target is small (a robot) and several pieces share a side.
        let half = t.half_along(side).max(0.5 * (b.max[0] - b.min[0]) + 0.03);
        for tuck in tucks {
            let face = tc[0] * n[0] + tc[1] * n[1] + t.half_along(n) + tuck;
            for shift in [0.0, -0.5, 0.5, -0.8, 0.8, -1.1, 1.1] {
                let yaw = yaw_facing(-n[0], -n[1]);
                out.push(aligned(b, yaw, n, face, side, mid + shift * half));
            }
        }
    }
    out
}
