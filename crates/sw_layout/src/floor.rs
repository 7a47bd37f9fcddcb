//! Floor placement: candidate poses for furniture and fixtures, ordered by how well they
//! satisfy the object's relations, and the order objects are placed in.

use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::rc::Rc;

use sw_geom::{Aabb, PlacementKind, Rng};
use sw_plan::{Corner, RelationKind, Support, Wall};

use crate::attempt::Ctx;
use crate::frames::{QUARTER_TURNS, Spot, yaw_facing};
use crate::space::{FLOOR_GAP, WALL_GAP, union};

/// Candidates of one object that may be tested against the egress routes.
const EGRESS_CHECKS: u32 = 60;

/// Along-wall and grid resolution of candidate positions, m.
const STEP: f64 = 0.05;

/// Placement order: groups whose relations point at other groups come after those
/// groups; wall-bound and large groups first; plan order among equals.
pub(crate) fn order(ctx: &Ctx<'_>, items: &[usize]) -> Vec<usize> {
    let objects = &ctx.input.objects;
    let mut groups: Vec<&str> = Vec::new();
    for &i in items {
        if !groups.contains(&objects[i].group.as_str()) {
            groups.push(&objects[i].group);
        }
    }
    let deps: BTreeMap<&str, Vec<String>> = groups
        .iter()
        .map(|g| {
            let d = ctx
                .relations(g)
                .iter()
                .flat_map(|r| r.targets())
                .filter(|t| t != g && groups.contains(t))
                .map(str::to_string)
                .collect();
            (*g, d)
        })
        .collect();
    let priority = |g: &str| -> (u8, u8, i64) {
        let first = ctx.instances(g)[0];
        let o = &objects[first];
        let walled = o.asset.placement == PlacementKind::AgainstWall
            || ctx.relations(g).iter().any(|r| {
                matches!(
                    r,
                    RelationKind::AgainstWall { .. }
                        | RelationKind::InCorner { .. }
                        | RelationKind::AtEnd { .. }
                        | RelationKind::NearDoor
                )
            });
        // What goes under something claims the space before what goes around it.
        let under = ctx.relations(g).iter().any(|r| matches!(r, RelationKind::Under { .. }));
        let s = ctx.bounds[first].size();
        (u8::from(!walled), u8::from(!under), -((s[0] * s[1] * 1e4) as i64))
    };
    let mut done: Vec<&str> = Vec::new();
    while done.len() < groups.len() {
        let ready: Vec<&str> = groups
            .iter()
            .copied()
            .filter(|g| !done.contains(g) && deps[g].iter().all(|d| done.contains(&d.as_str())))
            .collect();
        // A cycle of relations: break it in plan order.
        let pick = ready
            .iter()
            .copied()
            .min_by_key(|g| priority(g))
            .or_else(|| groups.iter().copied().find(|g| !done.contains(g)));
        match pick {
            Some(g) => done.push(g),
            None => break,
        }
    }
    done.iter().flat_map(|g| items.iter().copied().filter(move |&i| objects[i].group == *g)).collect()
}

/// Places one floor object at its best feasible candidate. Returns false when none fits.
pub(crate) fn place(ctx: &mut Ctx<'_>, idx: usize) -> bool {
    let group = ctx.input.objects[idx].group.clone();
    // A group's instances are alike: after a few found no place, the rest will not either.
    if ctx.group_failures.get(&group).copied().unwrap_or(0) >= 3 {
        return fail(ctx, idx);
    }
    let rels = ctx.relations(&group);
    let ignore_zones: Vec<String> = rels
        .iter()
        .filter_map(|r| match r {
            RelationKind::InFrontOf { target } | RelationKind::Under { target } => Some(target.clone()),
            _ => None,
        })
        .flat_map(|t| ctx.instances(&t).into_iter().map(|i| ctx.input.objects[i].name.clone()).collect::<Vec<_>>())
        .collect();
    let ignore: Vec<&str> = ignore_zones.iter().map(String::as_str).collect();
    let (specific, defaults, grid) = candidates(ctx, idx);
    // Egress is checked on candidates that fit, up to a budget; past it, what blocks a
    // route is reported by the rules check rather than searched for indefinitely.
    // Placing something in front of equipment on request blocks its access by design.
    let in_front = rels.iter().any(|r| matches!(r, RelationKind::InFrontOf { .. }));
    let mut egress_budget = if in_front { 0 } else { EGRESS_CHECKS };
    let mut acceptable = |ctx: &mut Ctx<'_>, spot: &Spot| -> bool {
        if !fits_floor(ctx, idx, spot, &ignore) {
            return false;
        }
        if egress_budget == 0 {
            return true;
        }
        egress_budget -= 1;
        keeps_egress(ctx, idx, spot)
    };
    let mut found: Option<(Spot, u8)> = None;
    for (spot, tier) in specific {
        if acceptable(ctx, &spot) {
            found = Some((spot, tier));
            break;
        }
    }
    if found.is_none() {
        // Defaults and the free grid are the same list for every instance of a group:
        // start where the previous instance found its place (space only fills up).
        let start = ctx.cursor.get(&group).copied().unwrap_or(0);
        let all = defaults.len() + grid.len();
        let at = |k: usize| if k < defaults.len() { defaults[k] } else { grid[k - defaults.len()] };
        for k in start..all {
            if acceptable(ctx, &at(k)) {
                ctx.cursor.insert(group.clone(), k);
                found = Some((at(k), 2));
                break;
            }
        }
    }
    let Some((spot, tier)) = found else {
        *ctx.group_failures.entry(group).or_insert(0) += 1;
        return fail(ctx, idx);
    };
    ctx.commit(idx, spot, Support::Floor);
    if tier > 0 && !rels.is_empty() {
        let o = &ctx.input.objects[idx];
        let names: Vec<&str> = rels.iter().map(|r| r.name()).collect();
        ctx.warn(
            "relation_unmet",
            format!("{}: could not satisfy {} (no free space there); placed elsewhere", o.name, names.join(", ")),
        );
    }
    true
}

fn fail(ctx: &mut Ctx<'_>, idx: usize) -> bool {
    let s = ctx.space.half;
    let o = &ctx.input.objects[idx];
    ctx.reasons.insert(
        idx,
        format!("no free floor space for a {} in a {:.1} × {:.1} m room", o.label, 2.0 * s[0], 2.0 * s[1]),
    );
    ctx.floor_failures += 1;
    false
}

pub(crate) fn fits_floor(ctx: &Ctx<'_>, idx: usize, spot: &Spot, ignore_zones: &[&str]) -> bool {
    let boxes = spot.boxes(&ctx.local[idx]);
    if !ctx.space.fits(&boxes, FLOOR_GAP, &[], true, ignore_zones) {
        return false;
    }
    // Its own keep-clear zones must be inside the room and free of floor objects.
    zones(ctx, idx, spot).iter().all(|(z, _)| {
        ctx.space.inside(&Aabb { min: [z.min[0], z.min[1], 0.0], max: [z.max[0], z.max[1], 0.0] })
            && ctx.space.zone_is_clear(z, &[])
    })
}

/// True when placing object `idx` at `spot` keeps every working front reachable from
/// the door by a route of the profile's egress width.
pub(crate) fn keeps_egress(ctx: &mut Ctx<'_>, idx: usize, spot: &Spot) -> bool {
    let footprint = union(&spot.boxes(&ctx.local[idx]));
    let mut fronts = ctx.access.clone();
    fronts.extend(zones(ctx, idx, spot).into_iter().filter(|(_, front)| *front).map(|(z, _)| z));
    match &mut ctx.egress {
        Some(g) => g.keeps_connected(&footprint, &fronts),
        None => true,
    }
}

/// The keep-clear zones the rules ask around an object at `spot` (world frame), each with
/// whether it is its working front.
pub(crate) fn zones(ctx: &Ctx<'_>, idx: usize, spot: &Spot) -> Vec<(Aabb, bool)> {
    let c = &ctx.clearances[idx];
    if c.is_empty() {
        return Vec::new();
    }
    let b = ctx.bounds[idx];
    let width = (b.max[0] - b.min[0]).max(c.min_width);
    let cx = 0.5 * (b.min[0] + b.max[0]);
    let mut out = Vec::new();
    if c.front > 0.0 {
        out.push((
            Aabb { min: [cx - width / 2.0, b.max[1], 0.0], max: [cx + width / 2.0, b.max[1] + c.front, 2.0] },
            true,
        ));
    }
    if c.back > 0.0 {
        out.push((Aabb { min: [b.min[0], b.min[1] - c.back, 0.0], max: [b.max[0], b.min[1], 2.0] }, false));
    }
    if c.sides > 0.0 {
        out.push((Aabb { min: [b.min[0] - c.sides, b.min[1], 0.0], max: [b.min[0], b.max[1], 2.0] }, false));
        out.push((Aabb { min: [b.max[0], b.min[1], 0.0], max: [b.max[0] + c.sides, b.max[1], 2.0] }, false));
    }
    out.into_iter().map(|(z, f)| (z.transformed(&spot.pose()), f)).collect()
}

/// Half extents of the object's footprint at a yaw, and the local bounds.
fn footprint(ctx: &Ctx<'_>, idx: usize) -> Aabb {
    ctx.bounds[idx]
}

/// All candidates, best first: relation-satisfying, then the object's defaults, then
/// anywhere. Each comes with its tier (0 = satisfies the relations).
type Candidates = (Vec<(Spot, u8)>, Vec<Spot>, Rc<Vec<Spot>>);

/// Candidates, best first: those satisfying all the object's relations (tier 0), each
/// relation's alone (tier 1), then the object's defaults, then the free grid.
fn candidates(ctx: &mut Ctx<'_>, idx: usize) -> Candidates {
    let o = &ctx.input.objects[idx];
    let rels = ctx.relations(&o.group);
    let mut specific: Vec<(Spot, u8)> = Vec::new();
    let positional: Vec<&RelationKind> =
        rels.iter().copied().filter(|r| !matches!(r, RelationKind::On { .. })).collect();
    if !positional.is_empty() {
        let mut all: Vec<Vec<Spot>> = positional.iter().map(|r| generate(ctx, idx, r)).collect();
        for (i, set) in all.iter().enumerate() {
            for s in set {
                if positional.iter().enumerate().all(|(j, r)| i == j || satisfies(ctx, idx, s, r)) {
                    specific.push((*s, 0));
                }
            }
        }
        for set in all.iter_mut() {
            specific.extend(set.drain(..).map(|s| (s, 1)));
        }
    }
    // Chairs with nowhere said go to the tables and desks.
    if positional.is_empty() && ctx.input.objects[idx].has_tag("seating") {
        let group = ctx.input.objects[idx].group.clone();
        let k = ctx.instances(&group).iter().position(|&i| i == idx).unwrap_or(0);
        let tables: Vec<String> = {
            let mut v: Vec<String> = Vec::new();
            for (i, o) in ctx.input.objects.iter().enumerate() {
                let table = o.has_tag("surface") && o.has_tag("furniture") && !o.has_tag("seating");
                if table && ctx.placed[i].is_some() && !v.contains(&o.group) {
                    v.push(o.group.clone());
                }
            }
            v
        };
        if !tables.is_empty() {
            // Spread the chairs over every table, round robin.
            let all: Vec<(usize, Spot)> = tables.iter().flat_map(|t| ctx.placed_instances(t)).collect();
            let n = all.len().max(1);
            let (ti, _) = all[k % n];
            let target = ctx.input.objects[ti].group.clone();
            let within = ctx.placed_instances(&target).iter().position(|(i, _)| *i == ti).unwrap_or(0);
            specific.extend(around(ctx, idx, &target, within, k / n).into_iter().map(|s| (s, 0)));
        }
    }
    let defaults = defaults(ctx, idx);
    let grid = free_grid(ctx, idx, false);
    (specific, defaults, grid)
}

/// The object's default places: storage against walls, machines and tables out in the
/// room, small things along the walls.
fn defaults(ctx: &mut Ctx<'_>, idx: usize) -> Vec<Spot> {
    let o = &ctx.input.objects[idx];
    match o.asset.placement {
        PlacementKind::AgainstWall | PlacementKind::InWall | PlacementKind::WallMounted => wall_slots(ctx, idx, None),
        PlacementKind::OnSurface => wall_slots(ctx, idx, None),
        PlacementKind::Floor => {
            if o.has_tag("storage") && o.has_tag("tall") {
                wall_slots(ctx, idx, None)
            } else {
                free_grid(ctx, idx, true).to_vec()
            }
        }
    }
}

/// Slots with the object's back to a wall, facing into the room, along `wall` (or every
/// wall, long walls first, in a seeded order).
fn wall_slots(ctx: &mut Ctx<'_>, idx: usize, wall: Option<Wall>) -> Vec<Spot> {
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
            let group_seed = group_rng(ctx, idx);
            if group_seed & 1 == 1 {
                l.reverse();
            }
            if group_seed & 2 == 2 {
                s.reverse();
            }
            l.extend(s);
            l
        }
    };
    let reverse = group_rng(ctx, idx) & 4 == 4;
    let mut out = Vec::new();
    for w in walls {
        out.extend(along_wall(ctx, idx, w, reverse));
    }
    out
}

/// A per-group pseudo-random number, stable across the group's instances.
fn group_rng(ctx: &Ctx<'_>, idx: usize) -> u64 {
    let g = &ctx.input.objects[idx].group;
    sw_geom::fnv1a(g.as_bytes()) ^ ctx.input.seed.rotate_left(13) ^ ctx.input.seed.wrapping_mul(0x9E37_79B9)
}

fn along_wall(ctx: &Ctx<'_>, idx: usize, wall: Wall, reverse: bool) -> Vec<Spot> {
    let b = footprint(ctx, idx);
    let [hw, hd] = ctx.space.half;
    let inward = match wall {
        Wall::North => (0.0, -1.0),
        Wall::South => (0.0, 1.0),
        Wall::East => (-1.0, 0.0),
        Wall::West => (1.0, 0.0),
    };
    let yaw = yaw_facing(inward.0, inward.1);
    // Distance from the origin to the back face (local -Y), plus the wall gap.
    let back = -b.min[1] + WALL_GAP + 0.002;
    let (half_along_lo, half_along_hi) = (-b.min[0], b.max[0]);
    let mut out = Vec::new();
    let (lo, hi) = match wall {
        Wall::North | Wall::South => (-hw, hw),
        Wall::East | Wall::West => (-hd, hd),
    };
    let start = lo + WALL_GAP + half_along_lo.max(half_along_hi) + 0.002;
    let end = hi - WALL_GAP - half_along_lo.max(half_along_hi) - 0.002;
    if end < start {
        return out;
    }
    let n = ((end - start) / STEP).floor() as usize;
    for k in 0..=n {
        let t = if reverse { end - k as f64 * STEP } else { start + k as f64 * STEP };
        let (x, y) = match wall {
            Wall::North => (t, hd - back),
            Wall::South => (t, -hd + back),
            Wall::East => (hw - back, t),
            Wall::West => (-hw + back, t),
        };
        out.push(Spot::new(x, y, 0.0, yaw));
    }
    out
}

/// Grid positions over the whole floor at every quarter turn; `central` orders them from
/// the middle of the room outwards, otherwise in a seeded random order.
pub(crate) fn free_grid(ctx: &mut Ctx<'_>, idx: usize, central: bool) -> Rc<Vec<Spot>> {
    let group = ctx.input.objects[idx].group.clone();
    if let Some(g) = ctx.grid_cache.get(&(group.clone(), central)) {
        return Rc::clone(g);
    }
    let b = footprint(ctx, idx);
    let s = b.size();
    let [hw, hd] = ctx.space.half;
    // Fine enough to pack, coarse enough that a large room stays a few thousand points.
    let step = (s[0].min(s[1]) / 2.0).clamp(0.1, 1.0).max((4.0 * hw * hd / 4000.0).sqrt());
    let mut rng = Rng::derive(group_rng(ctx, idx), if central { "central grid" } else { "grid" });
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
    ctx.grid_cache.insert((group, central), Rc::clone(&out));
    out
}

/// Candidate spots for one relation.
fn generate(ctx: &mut Ctx<'_>, idx: usize, rel: &RelationKind) -> Vec<Spot> {
    let group = ctx.input.objects[idx].group.clone();
    let k = ctx.instances(&group).iter().position(|&i| i == idx).unwrap_or(0);
    match rel {
        RelationKind::AgainstWall { wall } => wall_slots(ctx, idx, *wall),
        RelationKind::InCorner { corner } => corner_slots(ctx, idx, *corner),
        RelationKind::AtEnd { wall } => {
            let [hw, hd] = ctx.space.half;
            let ends = match wall {
                Some(w) => vec![*w],
                None if hw >= hd => vec![Wall::East, Wall::West],
                None => vec![Wall::North, Wall::South],
            };
            let mut v = Vec::new();
            for w in ends {
                v.extend(along_wall(ctx, idx, w, false));
                v.extend(strip_near(ctx, idx, w));
            }
            v
        }
        RelationKind::NearDoor => {
            let door = ctx.door.wall;
            let mut v = along_wall(ctx, idx, door, false);
            let (ox, oy) = door_point(ctx);
            v.sort_by(|a, b| (a.x - ox).hypot(a.y - oy).total_cmp(&(b.x - ox).hypot(b.y - oy)));
            v
        }
        RelationKind::InCenter => free_grid(ctx, idx, true).to_vec(),
        RelationKind::NextTo { target } => beside(ctx, idx, target, k),
        RelationKind::InFrontOf { target } => in_front_of(ctx, idx, target, k),
        RelationKind::Around { target } if is_guard_of_arm(ctx, idx, target) => guard_ring(ctx, idx, target, k),
        RelationKind::Around { target } => around(ctx, idx, target, k, k),
        RelationKind::Between { first, second } => between(ctx, first, second, k),
        RelationKind::Under { target } => under(ctx, target, k),
        RelationKind::InRow => row(ctx, idx, &group, k),
        RelationKind::FacingEachOther => facing(ctx, idx, &group, k),
        RelationKind::On { .. } => Vec::new(),
    }
}

/// Whether a spot satisfies a relation (used to combine relations).
fn satisfies(ctx: &Ctx<'_>, idx: usize, spot: &Spot, rel: &RelationKind) -> bool {
    let fp = union(&spot.boxes(&ctx.local[idx]));
    let [hw, hd] = ctx.space.half;
    let near_wall = |w: Wall, tol: f64| match w {
        Wall::North => hd - fp.max[1] < tol,
        Wall::South => fp.min[1] + hd < tol,
        Wall::East => hw - fp.max[0] < tol,
        Wall::West => fp.min[0] + hw < tol,
    };
    let gap_to = |group: &str| -> f64 {
        ctx.placed_instances(group)
            .iter()
            .filter_map(|(i, _)| ctx.space.occupant(&ctx.input.objects[*i].name))
            .map(|o| gap(&fp, &o.bounds))
            .fold(f64::INFINITY, f64::min)
    };
    match rel {
        RelationKind::AgainstWall { wall } => match wall {
            Some(w) => near_wall(*w, 0.15),
            None => Wall::ALL.iter().any(|w| near_wall(*w, 0.15)),
        },
        RelationKind::InCorner { corner } => {
            let corners = corner.map_or(Corner::ALL.to_vec(), |c| vec![c]);
            corners.iter().any(|c| {
                let (a, b) = c.walls();
                near_wall(a, 0.3) && near_wall(b, 0.3)
            })
        }
        RelationKind::AtEnd { wall } => {
            let ends = match wall {
                Some(w) => vec![*w],
                None if hw >= hd => vec![Wall::East, Wall::West],
                None => vec![Wall::North, Wall::South],
            };
            ends.iter().any(|w| near_wall(*w, 0.25 * 2.0 * if matches!(w, Wall::East | Wall::West) { hw } else { hd }))
        }
        RelationKind::NearDoor => {
            let (ox, oy) = door_point(ctx);
            let c = fp.center();
            (c[0] - ox).hypot(c[1] - oy) < 2.5
        }
        RelationKind::InCenter => spot.x.abs() < 0.2 * hw.max(1.0) && spot.y.abs() < 0.2 * hd.max(1.0),
        RelationKind::NextTo { target } | RelationKind::Around { target } => gap_to(target) < 0.6,
        RelationKind::InFrontOf { target } => gap_to(target) < 1.5,
        RelationKind::Between { first, second } => gap_to(first) < 2.0 && gap_to(second) < 2.0,
        RelationKind::Under { target } => gap_to(target) < 0.0,
        RelationKind::InRow | RelationKind::FacingEachOther | RelationKind::On { .. } => true,
    }
}

/// Distance between two floor rectangles (negative when they overlap).
fn gap(a: &Aabb, b: &Aabb) -> f64 {
    let dx = (b.min[0] - a.max[0]).max(a.min[0] - b.max[0]);
    let dy = (b.min[1] - a.max[1]).max(a.min[1] - b.max[1]);
    if dx < 0.0 && dy < 0.0 { dx.max(dy) } else { dx.max(0.0).hypot(dy.max(0.0)) }
}

fn door_point(ctx: &Ctx<'_>) -> (f64, f64) {
    let [hw, hd] = ctx.space.half;
    let d = &ctx.door;
    match d.wall {
        Wall::North => (d.offset, hd),
        Wall::South => (d.offset, -hd),
        Wall::East => (hw, d.offset),
        Wall::West => (-hw, d.offset),
    }
}

fn corner_slots(ctx: &mut Ctx<'_>, idx: usize, corner: Option<Corner>) -> Vec<Spot> {
    let corners = corner.map_or(Corner::ALL.to_vec(), |c| vec![c]);
    let mut out = Vec::new();
    for c in corners {
        let (ns, ew) = c.walls();
        for w in [ns, ew] {
            let mut slots = along_wall(ctx, idx, w, false);
            // Nearest the other wall first.
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

/// Positions in the quarter of the room next to `wall`.
fn strip_near(ctx: &mut Ctx<'_>, idx: usize, wall: Wall) -> Vec<Spot> {
    let [hw, hd] = ctx.space.half;
    free_grid(ctx, idx, false)
        .iter()
        .copied()
        .filter(|s| match wall {
            Wall::North => s.y > hd * 0.5,
            Wall::South => s.y < -hd * 0.5,
            Wall::East => s.x > hw * 0.5,
            Wall::West => s.x < -hw * 0.5,
        })
        .collect()
}

/// Target instances, starting with the one matching instance `k` (round robin).
fn targets_for(ctx: &Ctx<'_>, target: &str, k: usize) -> Vec<(usize, Spot)> {
    let mut t = ctx.placed_instances(target);
    if !t.is_empty() {
        let n = t.len();
        t.rotate_left(k % n);
    }
    t
}

/// Beside a target: left and right of it (same facing), then in front and behind.
pub(crate) fn beside(ctx: &Ctx<'_>, idx: usize, target: &str, k: usize) -> Vec<Spot> {
    let b = footprint(ctx, idx);
    let mut out = Vec::new();
    for (ti, ts) in targets_for(ctx, target, k) {
        let tb = ctx.bounds[ti];
        let yaw = ts.yaw;
        for extra in [0.0, 0.1, 0.25, 0.5] {
            let g = FLOOR_GAP + 0.01 + extra;
            let sides = [
                (tb.max[0] + g - b.min[0], 0.0),
                (tb.min[0] - g - b.max[0], 0.0),
                (0.0, tb.min[1] - g - b.max[1]),
                (0.0, tb.max[1] + g - b.min[1]),
            ];
            for (lx, ly) in sides {
                let p = ts.apply([lx, ly, 0.0]);
                out.push(Spot::new(p[0], p[1], 0.0, yaw));
                out.push(Spot::new(p[0], p[1], 0.0, yaw + PI));
            }
        }
    }
    out
}

/// Right in front of a target's front face, facing it.
fn in_front_of(ctx: &Ctx<'_>, idx: usize, target: &str, k: usize) -> Vec<Spot> {
    let b = footprint(ctx, idx);
    let mut out = Vec::new();
    for (ti, ts) in targets_for(ctx, target, k) {
        let tb = ctx.bounds[ti];
        for d in [0.2, 0.35, 0.5, 0.7, 0.9] {
            // Centred on the target first, then shifted sideways (a corner may not leave room).
            for shift in [0.0, -0.1, 0.1, -0.2, 0.2, -0.35, 0.35, -0.5, 0.5] {
                let p = ts.apply([0.5 * (tb.min[0] + tb.max[0]) + shift, tb.max[1] + d + b.max[1], 0.0]);
                out.push(Spot::new(p[0], p[1], 0.0, ts.yaw + PI));
                out.push(Spot::new(p[0], p[1], 0.0, ts.yaw));
            }
        }
    }
    out
}

/// A guard (safety fence) around something an arm works at or on.
fn is_guard_of_arm(ctx: &Ctx<'_>, idx: usize, target: &str) -> bool {
    let Some((_, tags, _, _)) = ctx.profile.fence_distance() else { return false };
    let guard = tags.iter().all(|t| ctx.input.objects[idx].has_tag(t));
    guard && ctx.input.robots.iter().any(|r| r.is_arm && arm_at(r, target))
}

fn arm_at(r: &crate::RobotItem, group: &str) -> bool {
    matches!(&r.mount, crate::RobotMount::Surface { group: g } if g == group) || r.near.as_deref() == Some(group)
}

/// A robot cell: guards on a square ring around the target, far enough out that an arm
/// anywhere on (or beside) the target keeps the rule's safety distance to them.
fn guard_ring(ctx: &Ctx<'_>, idx: usize, target: &str, k: usize) -> Vec<Spot> {
    let Some((_, _, distance, _)) = ctx.profile.fence_distance() else { return Vec::new() };
    let reach = ctx.input.robots.iter().filter(|r| r.is_arm && arm_at(r, target)).map(|r| r.reach).fold(0.0, f64::max);
    let b = footprint(ctx, idx);
    let mut out = Vec::new();
    for (ti, ts) in targets_for(ctx, target, 0) {
        let tb = ctx.bounds[ti];
        // The farthest an arm's base can be from the target's centre, plus reach and distance.
        let half_diag = 0.5 * (tb.max[0] - tb.min[0]).hypot(tb.max[1] - tb.min[1]);
        let carrier = if ctx.input.robots.iter().any(|r| r.near.as_deref() == Some(target)) { 0.8 } else { 0.0 };
        let radius = half_diag + carrier + reach + distance + 0.05;
        let c = ts.apply([0.5 * (tb.min[0] + tb.max[0]), 0.5 * (tb.min[1] + tb.max[1]), 0.0]);
        // Side k % 4 first: fences face the centre (their front, +Y, inwards).
        for s in 0..4 {
            let side = (k + s) % 4;
            let (nx, ny) = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)][side];
            for along in [0.0, -1.0, 1.0, -2.0, 2.0] {
                let t = along * (b.max[0] - b.min[0] + 0.05);
                let (px, py) = (c[0] + nx * (radius - b.min[1]) - ny * t, c[1] + ny * (radius - b.min[1]) + nx * t);
                out.push(Spot::new(px, py, 0.0, yaw_facing(-nx, -ny)));
            }
        }
    }
    out
}

/// Around a target: on each side, facing it, tucked in as far as collision allows.
fn around(ctx: &Ctx<'_>, idx: usize, target: &str, k: usize, seat: usize) -> Vec<Spot> {
    let b = footprint(ctx, idx);
    let depth_front = b.max[1];
    let mut out = Vec::new();
    let Some((ti, ts)) = targets_for(ctx, target, k).first().copied() else {
        return out;
    };
    let tb = ctx.bounds[ti];
    // Sides of the target: (outward normal in target frame, half length of the side).
    let sides = [
        ([0.0, 1.0], 0.5 * (tb.max[0] - tb.min[0]), tb.max[1]),
        ([0.0, -1.0], 0.5 * (tb.max[0] - tb.min[0]), -tb.min[1]),
        ([1.0, 0.0], 0.5 * (tb.max[1] - tb.min[1]), tb.max[0]),
        ([-1.0, 0.0], 0.5 * (tb.max[1] - tb.min[1]), -tb.min[0]),
    ];
    let rot = (seat / 4) % 2;
    for tuck in [-0.3, -0.2, -0.1, 0.0, 0.05, 0.15, 0.3] {
        for s in 0..4 {
            let (n, half_len, edge) = sides[(s + seat + rot) % 4];
            for along in [0.0, -0.5, 0.5, -0.8, 0.8] {
                let t = along * (half_len - 0.25).max(0.0);
                let dist = edge + depth_front + FLOOR_GAP + tuck;
                let local = [n[0] * dist + n[1].abs() * t, n[1] * dist + n[0].abs() * t, 0.0];
                let p = ts.apply(local);
                let c = ts.apply([0.0, 0.0, 0.0]);
                out.push(Spot::new(p[0], p[1], 0.0, yaw_facing(c[0] - p[0], c[1] - p[1])));
            }
        }
    }
    out
}

/// Between instances of two groups (or two instances of one group).
fn between(ctx: &Ctx<'_>, first: &str, second: &str, k: usize) -> Vec<Spot> {
    let a = ctx.placed_instances(first);
    let b = ctx.placed_instances(second);
    let mut mids = Vec::new();
    for (ia, sa) in &a {
        for (ib, sb) in &b {
            if ia == ib {
                continue;
            }
            let d = (sa.x - sb.x).hypot(sa.y - sb.y);
            mids.push((d, (0.5 * (sa.x + sb.x), 0.5 * (sa.y + sb.y)), sa.yaw));
        }
    }
    mids.sort_by(|x, y| x.0.total_cmp(&y.0));
    if !mids.is_empty() {
        let n = mids.len();
        mids.rotate_left(k % n);
    }
    let mut out = Vec::new();
    for (_, (x, y), yaw) in mids {
        for (dx, dy) in [
            (0.0, 0.0),
            (0.2, 0.0),
            (-0.2, 0.0),
            (0.0, 0.2),
            (0.0, -0.2),
            (0.4, 0.0),
            (-0.4, 0.0),
            (0.0, 0.4),
            (0.0, -0.4),
        ] {
            for turn in [0.0, PI / 2.0] {
                out.push(Spot::new(x + dx, y + dy, 0.0, yaw + turn));
            }
        }
    }
    out
}

/// Inside a target's footprint (under a table or bench).
fn under(ctx: &Ctx<'_>, target: &str, k: usize) -> Vec<Spot> {
    let mut out = Vec::new();
    for (ti, ts) in targets_for(ctx, target, k) {
        let tb = ctx.bounds[ti];
        let (cx, cy) = (0.5 * (tb.min[0] + tb.max[0]), 0.5 * (tb.min[1] + tb.max[1]));
        let (hx, hy) = (0.5 * (tb.max[0] - tb.min[0]), 0.5 * (tb.max[1] - tb.min[1]));
        for fx in [0.0, -0.3, 0.3, -0.6, 0.6] {
            for fy in [0.0, -0.3, 0.3] {
                let p = ts.apply([cx + fx * hx, cy + fy * hy, 0.0]);
                out.push(Spot::new(p[0], p[1], 0.0, ts.yaw));
                out.push(Spot::new(p[0], p[1], 0.0, ts.yaw + PI / 2.0));
            }
        }
    }
    out
}

/// The last placed instance of `group` before instance `k`.
fn previous_sibling(ctx: &Ctx<'_>, group: &str, k: usize) -> Option<(usize, Spot)> {
    ctx.instances(group).into_iter().take(k).rev().find_map(|i| ctx.placed[i].as_ref().map(|p| (i, p.spot)))
}

/// A row: continue from the previous instance along its width; the first instance goes
/// on the room's long centre line.
fn row(ctx: &mut Ctx<'_>, idx: usize, group: &str, k: usize) -> Vec<Spot> {
    let b = footprint(ctx, idx);
    let prev = previous_sibling(ctx, group, k);
    match prev {
        Some((pi, ps)) => {
            let pb = ctx.bounds[pi];
            let mut out = Vec::new();
            for extra in 0..40 {
                let g = FLOOR_GAP + 0.01 + extra as f64 * 0.1;
                for dir in [1.0, -1.0] {
                    let lx = if dir > 0.0 { pb.max[0] + g - b.min[0] } else { pb.min[0] - g - b.max[0] };
                    let p = ps.apply([lx, 0.0, 0.0]);
                    out.push(Spot::new(p[0], p[1], 0.0, ps.yaw));
                }
            }
            out
        }
        None => {
            let [hw, hd] = ctx.space.half;
            let along_x = hw >= hd;
            let mut out = Vec::new();
            let len = if along_x { hw } else { hd };
            let mut t = -len;
            while t <= len {
                for off in [0.0, 1.0, -1.0, 2.0, -2.0] {
                    let (x, y) = if along_x { (t, off) } else { (off, t) };
                    out.push(Spot::new(x, y, 0.0, if along_x { 0.0 } else { PI / 2.0 }));
                }
                t += STEP * 2.0;
            }
            out.sort_by(|a, b| {
                (if along_x { a.y.abs() } else { a.x.abs() }).total_cmp(&(if along_x { b.y.abs() } else { b.x.abs() }))
            });
            out
        }
    }
}

/// Facing each other: wall-standing things alternate between opposite long walls; other
/// things stand in front of their predecessor, turned round.
fn facing(ctx: &mut Ctx<'_>, idx: usize, group: &str, k: usize) -> Vec<Spot> {
    let o = &ctx.input.objects[idx];
    let wallish = o.asset.placement == PlacementKind::AgainstWall || (o.has_tag("storage") && o.has_tag("tall"));
    if wallish {
        let [hw, hd] = ctx.space.half;
        let (a, b) = if hw >= hd { (Wall::North, Wall::South) } else { (Wall::East, Wall::West) };
        let w = if k.is_multiple_of(2) { a } else { b };
        return along_wall(ctx, idx, w, false);
    }
    if k % 2 == 1
        && let Some((pi, ps)) = previous_sibling(ctx, group, k)
    {
        let pb = ctx.bounds[pi];
        let b = footprint(ctx, idx);
        let mut out = Vec::new();
        for d in [0.8, 1.0, 1.3, 1.6, 2.0, 2.5] {
            let p = ps.apply([0.0, pb.max[1] + d + b.max[1], 0.0]);
            out.push(Spot::new(p[0], p[1], 0.0, ps.yaw + PI));
        }
        return out;
    }
    Vec::new()
}
