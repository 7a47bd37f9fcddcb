//! Group formations: a row, rows, rows facing each other across a gap, aisles, rows
//! spread over two walls, and stacks. A formation is laid out in its own frame (rows
//! along X, the first row's front towards +Y), taken as one body by the candidate
//! generators (against a wall, in the middle, behind a target …), and committed only
//! when every member fits: a stated arrangement is kept whole or reported, never
//! half-kept silently.

use std::f64::consts::PI;

use sw_geom::Aabb;
use sw_plan::{RelationKind, Support, Wall};

use crate::attempt::Ctx;
use crate::candidates;
use crate::floor;
use crate::frames::Spot;
use crate::relate::{self, Body};
use crate::space::{FLOOR_GAP, Zone, overlaps, overlaps_2d, union};

/// Candidate placements of one formation that are fully tested.
const MAX_TRIALS: usize = 6000;

/// One member: the object, its origin in the formation frame and its extra turn.
#[derive(Debug, Clone, Copy)]
struct Member {
    idx: usize,
    offset: [f64; 3],
    turn: f64,
}

/// A laid-out group in its own frame.
#[derive(Debug, Clone)]
struct Formation {
    /// The whole formation, reserved space included, in its frame.
    bounds: Aabb,
    members: Vec<Member>,
    /// Free space kept in front of (and behind) each member for what a relation puts
    /// there (a stool in front of each station, a conveyor behind the row), m.
    front_reserve: f64,
    back_reserve: f64,
    /// Free floor kept beyond the formation's +X end ("a cabinet at the end of the row").
    end_reserve: f64,
    /// Each member's support: the floor, or the member below it in a stack.
    stacked: bool,
    /// Members abut (units of one counter run): no floor gap or keep-clear space between them.
    tight: bool,
}

impl Formation {
    fn members_at(&self, ctx: &Ctx<'_>, at: &Spot) -> Vec<(usize, Spot)> {
        self.members
            .iter()
            .map(|m| {
                let p = at.apply(m.offset);
                let _ = ctx;
                (m.idx, Spot::new(p[0], p[1], p[2], at.yaw + m.turn))
            })
            .collect()
    }
}

/// The footprint of an object at a turn, origin at zero.
fn fp_at(ctx: &Ctx<'_>, idx: usize, turn: f64) -> Aabb {
    ctx.bounds[idx].transformed(&Spot::new(0.0, 0.0, 0.0, turn).pose())
}

/// Rows laid out along X: `rows[r]` holds the members of row r, `faces_up[r]` whether it
/// faces +Y, `corridors[r]` the clear width between row r and r + 1.
fn rows(ctx: &Ctx<'_>, rows: &[Vec<usize>], faces_up: &[bool], corridors: &[f64], reserve: (f64, f64)) -> Formation {
    let (front_reserve, back_reserve) = reserve;
    let mut members = Vec::new();
    let mut y0 = 0.0;
    let mut max_len: f64 = 0.0;
    for (r, row) in rows.iter().enumerate() {
        let up = faces_up.get(r).copied().unwrap_or(true);
        let turn = if up { 0.0 } else { PI };
        let fps: Vec<Aabb> = row.iter().map(|&i| fp_at(ctx, i, turn)).collect();
        let depth = fps.iter().map(|f| f.max[1] - f.min[1]).fold(0.0, f64::max);
        // Side gaps: what the rules keep beside each member, at least a hand's width.
        let gap = row.iter().map(|&i| ctx.clearances[i].sides).fold(0.1_f64, f64::max) + 0.02;
        let len: f64 =
            fps.iter().map(|f| f.max[0] - f.min[0]).sum::<f64>() + gap * (row.len().saturating_sub(1)) as f64;
        max_len = max_len.max(len);
        let (below, above) = if up { (back_reserve, front_reserve) } else { (front_reserve, back_reserve) };
        let mut x = -len / 2.0;
        for (&idx, fp) in row.iter().zip(&fps) {
            // Fronts on the row's front line; backs vary with depth.
            let oy = if up { y0 + below + depth - fp.max[1] } else { y0 + below - fp.min[1] };
            members.push(Member { idx, offset: [x - fp.min[0], oy, 0.0], turn });
            x += fp.max[0] - fp.min[0] + gap;
        }
        y0 += below + depth + above + corridors.get(r).copied().unwrap_or(0.0);
    }
    let total = y0 - corridors.get(rows.len().saturating_sub(1)).copied().unwrap_or(0.0);
    // Centre the formation on its origin.
    for m in &mut members {
        m.offset[1] -= total / 2.0;
    }
    Formation {
        bounds: Aabb { min: [-max_len / 2.0, -total / 2.0, 0.0], max: [max_len / 2.0, total / 2.0, 1.0] },
        members,
        front_reserve,
        back_reserve,
        end_reserve: 0.0,
        stacked: false,
        tight: false,
    }
}

/// One stack, members centred over each other.
fn stack(ctx: &Ctx<'_>, idxs: &[usize]) -> Formation {
    let mut members = Vec::new();
    let mut z = 0.0;
    let mut b = Aabb::EMPTY;
    for &idx in idxs {
        let fp = fp_at(ctx, idx, 0.0);
        let c = [0.5 * (fp.min[0] + fp.max[0]), 0.5 * (fp.min[1] + fp.max[1])];
        members.push(Member { idx, offset: [-c[0], -c[1], z], turn: 0.0 });
        b = b.union(&Aabb {
            min: [fp.min[0] - c[0], fp.min[1] - c[1], 0.0],
            max: [fp.max[0] - c[0], fp.max[1] - c[1], 1.0],
        });
        z += top_of(ctx, idx);
    }
    Formation {
        bounds: b,
        members,
        front_reserve: 0.0,
        back_reserve: 0.0,
        end_reserve: 0.0,
        stacked: true,
        tight: false,
    }
}

/// The height something stacked on an object rests at: its top surface, else its top —
/// an open tote's rim: totes are stacked on one another, not put inside.
pub(crate) fn top_of(ctx: &Ctx<'_>, idx: usize) -> f64 {
    let top = ctx.bounds[idx].max[2];
    ctx.input.objects[idx].asset.top_surface_under(top).map_or(top, |s| s.z)
}

/// The top surface's name (what a stacked member rests on); "rim" for an open tote.
pub(crate) fn top_surface(ctx: &Ctx<'_>, idx: usize) -> String {
    let a = ctx.input.objects[idx].asset;
    match a.top_surface_under(ctx.bounds[idx].max[2]) {
        Some(s) => s.name.clone(),
        None if a.surfaces.iter().any(|s| s.clearance.is_none()) => "rim".to_string(),
        None => "top".to_string(),
    }
}

/// Splits `idxs` into `n` rows, the first rows one longer when they do not divide.
fn split(idxs: &[usize], n: usize) -> Vec<Vec<usize>> {
    let n = n.clamp(1, idxs.len().max(1));
    let base = idxs.len() / n;
    let extra = idxs.len() % n;
    let mut out = Vec::new();
    let mut at = 0;
    for r in 0..n {
        let len = base + usize::from(r < extra);
        out.push(idxs[at..at + len].to_vec());
        at += len;
    }
    out
}

/// How many rows "in rows" asks for: `n`, else enough rows of `m`, else two.
fn rows_wanted(n: Option<u32>, m: Option<u32>, count: usize) -> usize {
    match (n, m) {
        (Some(n), _) => n as usize,
        (None, Some(m)) if m > 0 => count.div_ceil(m as usize),
        _ => 2,
    }
}

/// Splits `idxs` into rows of `m` (the last one shorter when they do not divide).
fn chunks(idxs: &[usize], m: usize) -> Vec<Vec<usize>> {
    idxs.chunks(m.max(1)).map(<[usize]>::to_vec).collect()
}

/// The clear width kept in front of a member by the rules, m.
fn front_clearance(ctx: &Ctx<'_>, idxs: &[usize]) -> f64 {
    idxs.iter().map(|&i| ctx.clearances[i].front.max(ctx.clearances[i].back)).fold(0.0, f64::max)
}

/// Whether the group is storage (racks, shelving): its aisles are a forklift's width.
fn is_storage(ctx: &Ctx<'_>, idxs: &[usize]) -> bool {
    idxs.first().is_some_and(|&i| {
        let o = &ctx.input.objects[i];
        o.has_tag("storage") || o.has_tag("server_rack")
    })
}

/// The formations to try for a group relation, preferred first.
fn formations(ctx: &Ctx<'_>, group: &str, idxs: &[usize], rel: &RelationKind) -> Vec<Formation> {
    let end = end_reserve(ctx, group);
    let mut v = formations_of(ctx, group, idxs, rel);
    if end > 0.0 {
        for f in &mut v {
            f.bounds.max[0] += end;
            f.end_reserve = end;
        }
    }
    v
}

/// Room kept beyond a row's end for what is said to stand at it.
fn end_reserve(ctx: &Ctx<'_>, group: &str) -> f64 {
    ctx.input
        .plan
        .relations
        .iter()
        .filter(|r| matches!(&r.kind, RelationKind::AtEndOfRow { target } if target == group))
        .map(|r| {
            let size =
                ctx.instances(&r.subject).first().map(|&i| ctx.bounds[i].size()).or_else(|| {
                    ctx.input.robots.iter().find(|x| x.group == r.subject).map(|x| union(&x.keepout).size())
                });
            size.map_or(0.8, |s| s[0].max(s[1]) + 0.25)
        })
        .fold(0.0, f64::max)
}

fn formations_of(ctx: &Ctx<'_>, group: &str, idxs: &[usize], rel: &RelationKind) -> Vec<Formation> {
    let reserve = reserves(ctx, group);
    let n = idxs.len();
    let clear = front_clearance(ctx, idxs);
    let aisle: f64 = if is_storage(ctx, idxs) { 2.5_f64 } else { 1.6 };
    let aisle = aisle.max(clear + 0.1).min(3.4);
    let seat_gap = (1.2_f64).max(clear + 0.1);
    // "two rows of three machines facing each other": the rows said.
    let rows_said = ctx.relations(group).iter().find_map(|r| match r {
        RelationKind::InRows { n, m } => Some(rows_wanted(*n, *m, idxs.len())),
        _ => None,
    });
    match rel {
        RelationKind::InRow => {
            let mut v = vec![rows(ctx, &[idxs.to_vec()], &[true], &[], reserve)];
            // When one row does not fit a room whose size was given: two. A room whose
            // size was not given grows to fit the row instead (`solve`); a row folded in
            // two is not the row that was asked for.
            if n >= 4 && ctx.input.plan.room.size_fixed {
                v.push(rows(ctx, &split(idxs, 2), &[true, true], &[seat_gap], reserve));
            }
            v
        }
        RelationKind::InRows { n: rows_n, m } => {
            let k = rows_wanted(*rows_n, *m, n).clamp(1, n.max(1));
            // Seats in front of each row take the row's own reserve; a narrower walkway
            // behind them suffices.
            let walk = if reserve.0 > 0.0 { (0.6_f64).max(clear + 0.1) } else { seat_gap };
            let corridors = vec![walk; k];
            let parts = match m {
                Some(m) if *m > 0 => chunks(idxs, *m as usize),
                _ => split(idxs, k),
            };
            let k = parts.len();
            vec![rows(ctx, &parts, &vec![true; k], &corridors, reserve)]
        }
        RelationKind::InAisles => {
            let k = rows_said.unwrap_or_else(|| ((n as f64).sqrt().round() as usize).clamp(2, n.max(2))).min(n);
            let mut v = Vec::new();
            for k in [k, k + 1, 2] {
                if k > n || k < 2 {
                    continue;
                }
                // Each row faces a corridor: even rows up, odd rows down, the last down.
                let faces: Vec<bool> = (0..k).map(|r| r % 2 == 0 && r + 1 < k).collect();
                v.push(rows(ctx, &split(idxs, k), &faces, &vec![aisle; k], reserve));
            }
            v
        }
        RelationKind::FacingEachOther => {
            let halves = if n == 1 { vec![idxs.to_vec()] } else { split(idxs, 2) };
            let faces = [true, false];
            let mut v = vec![rows(ctx, &halves, &faces, &[aisle], reserve)];
            for g in [aisle + 0.6, (aisle - 0.6).max(1.2 + 2.0 * reserve.0), 3.4] {
                v.push(rows(ctx, &halves, &faces, &[g], reserve));
            }
            v
        }
        RelationKind::BackToBack => {
            // Pairs of rows back to back ("two rows of desks back to back"), pairs apart
            // by a walkway; a pair of two is one row each.
            let k = rows_said.unwrap_or(2).clamp(2, n.max(2)).min(n);
            let parts = split(idxs, k);
            let faces: Vec<bool> = (0..parts.len()).map(|r| r % 2 == 1).collect();
            let corridors: Vec<f64> = (0..parts.len()).map(|r| if r % 2 == 0 { 0.06 } else { aisle }).collect();
            vec![rows(ctx, &parts, &faces, &corridors, (reserve.0, 0.0))]
        }
        RelationKind::Stacked { .. } => vec![stack(ctx, idxs)],
        _ => Vec::new(),
    }
}

/// Space kept in front of and behind each member for what other relations put there.
/// Room kept at the ends (along X) of a single object for what is said to stand in its
/// run or at its end ("a sink set into the counter", "a bin at the end of the bench"):
/// the widest one's width, and whether both ends are wanted (two or more of them).
pub(crate) fn end_room(ctx: &Ctx<'_>, group: &str) -> (f64, bool) {
    let widths: Vec<f64> = ctx
        .input
        .plan
        .relations
        .iter()
        .filter(|r| {
            matches!(&r.kind, RelationKind::SetInto { target } | RelationKind::AtEndOf { target, .. } | RelationKind::OnEachSideOf { target } if target == group)
        })
        .filter_map(|r| ctx.instances(&r.subject).first().map(|&i| (i, r)))
        // Things resting on it need no floor.
        .filter(|(i, _)| !crate::attempt::is_small(ctx, *i) && ctx.bounds[*i].size()[2] > 0.15)
        .map(|(i, r)| {
            let s = ctx.bounds[i].size();
            let n = match r.kind {
                RelationKind::AtEndOf { end: Some(sw_plan::EndOf::Both), .. } | RelationKind::OnEachSideOf { .. } => 2,
                _ => 1,
            };
            (s[0].max(s[1]) + 0.1, n.min(ctx.instances(&r.subject).len()))
        })
        .flat_map(|(w, n)| std::iter::repeat_n(w, n))
        .collect();
    (widths.iter().copied().fold(0.0, f64::max), widths.len() >= 2)
}

pub(crate) fn reserves(ctx: &Ctx<'_>, group: &str) -> (f64, f64) {
    let mut front: f64 = 0.0;
    let mut back: f64 = 0.0;
    for r in &ctx.input.plan.relations {
        let depth_of = |g: &str| {
            ctx.instances(g).first().map_or(0.5, |&i| {
                let b = ctx.bounds[i];
                (b.max[1] - b.min[1]).min(b.max[0] - b.min[0])
            })
        };
        match &r.kind {
            RelationKind::EachWith { target }
                if r.subject == group
                    && ctx.instances(target).first().is_some_and(|&i| !crate::attempt::is_small(ctx, i)) =>
            {
                front = front.max(depth_of(target) + 0.2);
            }
            RelationKind::InFrontOf { target } if target == group => front = front.max(depth_of(&r.subject) + 0.2),
            RelationKind::Behind { target } if target == group => back = back.max(depth_of(&r.subject) + 0.2),
            _ => {}
        }
    }
    (front, back)
}

/// Places a whole group in its formation. False when no placement of the whole
/// formation fits (the caller then places the members one by one and says so).
pub(crate) fn place(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize], rel: &RelationKind) -> bool {
    if idxs.is_empty() {
        return true;
    }
    if matches!(rel, RelationKind::OnTwoWalls) {
        return two_walls(ctx, group, idxs);
    }
    if let RelationKind::OnOppositeWalls { long } = rel {
        return opposite_walls(ctx, group, idxs, *long);
    }
    if let RelationKind::Around { target } = rel {
        return around(ctx, group, idxs, target);
    }
    if matches!(rel, RelationKind::Stacked { .. }) {
        return stacks(ctx, group, idxs);
    }
    let rels: Vec<RelationKind> = ctx.relations(group).into_iter().cloned().collect();
    for f in formations(ctx, group, idxs, rel) {
        if try_formation(ctx, group, &f, &rels, rel) {
            return true;
        }
    }
    false
}

/// Candidate placements of the formation taken as one body, best first.
fn placements(ctx: &mut Ctx<'_>, group: &str, f: &Formation, rels: &[RelationKind], rel: &RelationKind) -> Vec<Spot> {
    let b = f.bounds;
    let positional: Vec<&RelationKind> = rels.iter().filter(|r| relate::is_positional(r)).collect();
    let mut out: Vec<Spot> = Vec::new();
    // Facing rows stated to stand against the walls: along two opposite walls.
    let walled = positional.iter().any(|r| matches!(r, RelationKind::AgainstWall { .. }));
    if walled && matches!(rel, RelationKind::FacingEachOther | RelationKind::InAisles) {
        out.extend(wall_to_wall(ctx, f));
    }
    for r in &positional {
        out.extend(candidates::for_relation(ctx, &b, group, 0, r));
    }
    if positional.is_empty() {
        let first = f.members[0].idx;
        let o = &ctx.input.objects[first];
        let wallish =
            o.asset.placement == sw_geom::PlacementKind::AgainstWall || (o.has_tag("storage") && o.has_tag("tall"));
        let pair = matches!(rel, RelationKind::FacingEachOther | RelationKind::InAisles | RelationKind::InRows { .. });
        if wallish && !pair {
            out.extend(candidates::wall_slots(ctx, &b, group, None));
        }
        out.extend(candidates::center_slots(ctx, &b, group));
    }
    out.extend(candidates::free_grid(ctx, &b, group, false).iter().copied());
    out
}

/// Facing rows stretched from wall to wall: the gap is whatever the room leaves.
fn wall_to_wall(ctx: &Ctx<'_>, f: &Formation) -> Vec<Spot> {
    let [hw, hd] = ctx.space.half;
    let height = f.bounds.max[1] - f.bounds.min[1];
    let mut out = Vec::new();
    for (yaw, across) in [(0.0, hd), (PI / 2.0, hw)] {
        // The formation's depth must match the room's: scale is not possible, so only
        // when it already spans the room within the wall tolerance.
        if (2.0 * across - height).abs() < 2.0 * relate::WALL_TOL {
            out.push(Spot::new(0.0, 0.0, 0.0, yaw));
        }
    }
    out
}

fn try_formation(ctx: &mut Ctx<'_>, group: &str, f: &Formation, rels: &[RelationKind], rel: &RelationKind) -> bool {
    let positional: Vec<RelationKind> = rels.iter().filter(|r| relate::is_positional(r)).cloned().collect();
    // Facing rows against the walls: rebuild with the gap the room leaves.
    let mut f = f.clone();
    if positional.iter().any(|r| matches!(r, RelationKind::AgainstWall { .. }))
        && matches!(rel, RelationKind::FacingEachOther)
        && f.members.len() >= 2
    {
        f = stretched(ctx, group, &f);
    }
    let spots = placements(ctx, group, &f, rels, rel);
    let mut egress_budget = 40usize;
    let size = f.members.len();
    for at in spots.into_iter().take(MAX_TRIALS) {
        // The formation with its reserved space inside the room.
        if !ctx.space.inside(&f.bounds.transformed(&at.pose())) {
            continue;
        }
        let placed = f.members_at(ctx, &at);
        let members: Vec<Body> = placed.iter().map(|(i, s)| Body::object(&ctx.local[*i], s)).collect();
        let whole = Body {
            fp: members.iter().fold(Aabb::EMPTY, |a, m| a.union(&m.fp)),
            front: Body::object(&[f.bounds], &at).front,
        };
        // Walls and corners hold for every member; the rest for the formation as a body.
        let ok = positional.iter().all(|r| match r {
            RelationKind::AgainstWall { .. } | RelationKind::InCorner { .. } | RelationKind::Leaning { .. } => {
                if matches!(rel, RelationKind::FacingEachOther | RelationKind::InAisles) {
                    members.iter().all(|m| relate::holds(ctx, m, r, size))
                } else {
                    relate::holds(ctx, &whole, r, size)
                }
            }
            _ => relate::holds(ctx, &whole, r, size),
        });
        if !ok || !fits(ctx, &f, &placed) {
            continue;
        }
        if egress_budget > 0 {
            egress_budget -= 1;
            if !keeps_egress(ctx, &placed) {
                continue;
            }
        }
        commit(ctx, &f, &placed);
        if f.end_reserve > 0.0
            && let Some((last, _)) = placed.last()
        {
            let b = f.bounds;
            let zone = Aabb { min: [b.max[0] - f.end_reserve, b.min[1], 0.0], max: [b.max[0], b.max[1], 2.0] };
            let owner = ctx.input.objects[*last].name.clone();
            ctx.space.zones.push(Zone { owner: Some(owner), area: zone.transformed(&at.pose()) });
        }
        return true;
    }
    false
}

/// Facing rows whose gap is set so that each row's back is at a wall.
fn stretched(ctx: &Ctx<'_>, group: &str, f: &Formation) -> Formation {
    let _ = group;
    let [hw, hd] = ctx.space.half;
    let idxs: Vec<usize> = f.members.iter().map(|m| m.idx).collect();
    let halves = split(&idxs, 2);
    let depth = |row: &[usize]| row.iter().map(|&i| ctx.bounds[i].max[1] - ctx.bounds[i].min[1]).fold(0.0, f64::max);
    let used = depth(&halves[0]) + depth(&halves.get(1).cloned().unwrap_or_default()) + f.front_reserve * 2.0;
    // Across the shorter side first (racks along the long walls).
    let across = 2.0 * hw.min(hd) - 2.0 * (crate::space::WALL_GAP + 0.004);
    let g = across - used;
    if g < 0.6 {
        return f.clone();
    }
    rows(ctx, &halves, &[true, false], &[g], (f.front_reserve, f.back_reserve))
}

/// Every member fits the room and the occupied space, and members keep each other's
/// keep-clear zones.
fn fits(ctx: &Ctx<'_>, f: &Formation, placed: &[(usize, Spot)]) -> bool {
    for (k, (idx, spot)) in placed.iter().enumerate() {
        if f.stacked && k > 0 {
            let boxes = spot.boxes(&ctx.local[*idx]);
            if !ctx.space.fits(&boxes, 0.0, &[], false, &[]) {
                return false;
            }
            continue;
        }
        if !floor::fits_floor(ctx, *idx, spot, &[]) {
            return false;
        }
    }
    if f.stacked {
        return true;
    }
    for (a, (ia, sa)) in placed.iter().enumerate() {
        let ba = sa.boxes(&ctx.local[*ia]);
        let fa = union(&ba);
        for (ib, sb) in placed.iter().skip(a + 1) {
            let bb = sb.boxes(&ctx.local[*ib]);
            if f.tight {
                if overlaps(&fa, &union(&bb), 0.004) {
                    return false;
                }
                continue;
            }
            if overlaps(&fa, &union(&bb), FLOOR_GAP - 1e-6) {
                return false;
            }
            let fb = union(&bb);
            if floor::zones(ctx, *ia, sa).iter().any(|(z, _)| overlaps_2d(z, &fb))
                || floor::zones(ctx, *ib, sb).iter().any(|(z, _)| overlaps_2d(z, &fa))
            {
                return false;
            }
        }
    }
    true
}

/// Every working front still reaches the door with the whole formation in place.
fn keeps_egress(ctx: &Ctx<'_>, placed: &[(usize, Spot)]) -> bool {
    let Some(grid) = &ctx.egress else { return true };
    let mut g = grid.clone();
    let mut fronts = ctx.access.clone();
    for (idx, spot) in placed {
        fronts.extend(floor::zones(ctx, *idx, spot).into_iter().filter(|(_, f)| *f).map(|(z, _)| z));
    }
    for (idx, spot) in placed {
        let fp = union(&spot.boxes(&ctx.local[*idx]));
        if !g.keeps_connected(&fp, &fronts) {
            return false;
        }
        g.add(&fp);
    }
    true
}

fn commit(ctx: &mut Ctx<'_>, f: &Formation, placed: &[(usize, Spot)]) {
    for (k, (idx, spot)) in placed.iter().enumerate() {
        let support = if f.stacked && k > 0 {
            let below = placed[k - 1].0;
            Support::Object { object: ctx.input.objects[below].name.clone(), surface: top_surface(ctx, below) }
        } else {
            Support::Floor
        };
        ctx.commit(*idx, *spot, support);
        reserve_zones(ctx, *idx, spot, f.front_reserve, f.back_reserve);
    }
}

/// Keeps the reserved strips in front of and behind a member free of other floor
/// objects (what they are reserved for ignores them).
pub(crate) fn reserve_zones(ctx: &mut Ctx<'_>, idx: usize, spot: &Spot, front: f64, back: f64) {
    let b = ctx.bounds[idx];
    let name = ctx.input.objects[idx].name.clone();
    let mut add = |z: Aabb| {
        let area = z.transformed(&spot.pose());
        ctx.space.zones.push(Zone { owner: Some(name.clone()), area });
    };
    if front > 0.0 {
        add(Aabb { min: [b.min[0], b.max[1], 0.0], max: [b.max[0], b.max[1] + front, 2.0] });
    }
    if back > 0.0 {
        add(Aabb { min: [b.min[0], b.min[1] - back, 0.0], max: [b.max[0], b.min[1], 2.0] });
    }
}

/// Half the group against one wall, half against another (long walls first).
fn two_walls(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize]) -> bool {
    let halves = if idxs.len() >= 2 { split(idxs, 2) } else { vec![idxs.to_vec()] };
    let reserve = reserves(ctx, group);
    let [hw, hd] = ctx.space.half;
    let order: Vec<Wall> = if hw >= hd {
        vec![Wall::North, Wall::South, Wall::East, Wall::West]
    } else {
        vec![Wall::East, Wall::West, Wall::North, Wall::South]
    };
    // Walls other groups are said to stand at come last ("counters along two walls, a
    // fridge against the east wall").
    let named: Vec<Wall> = ctx
        .input
        .plan
        .relations
        .iter()
        .filter(|r| r.subject != group)
        .filter_map(|r| match r.kind {
            RelationKind::AgainstWall { wall } | RelationKind::Leaning { wall } => wall,
            _ => None,
        })
        .collect();
    // Walls no one else needs first; the others only when that fails.
    let free: Vec<Wall> = order.iter().copied().filter(|w| !named.contains(w)).collect();
    if free.len() >= 2 && place_on_walls(ctx, group, &halves, reserve, &free) {
        return true;
    }
    // A room whose size was not given grows until the free walls hold them.
    if !ctx.input.plan.room.size_fixed && free.len() >= 2 {
        ctx.floor_failures += 1;
    }
    let mut order = order;
    order.sort_by_key(|w| named.contains(w));
    place_on_walls(ctx, group, &halves, reserve, &order)
}

/// The unplaced floor units said to be set into `group`'s run (a sink unit, a range):
/// they are laid out with it, abutting, as one run.
pub(crate) fn run_units(ctx: &Ctx<'_>, group: &str) -> Vec<usize> {
    let mut out = Vec::new();
    for r in &ctx.input.plan.relations {
        if !matches!(&r.kind, RelationKind::SetInto { target } if target == group) {
            continue;
        }
        for i in ctx.instances(&r.subject) {
            let unit = !crate::attempt::is_small(ctx, i) && ctx.bounds[i].size()[2] > 0.15;
            if unit && ctx.placed[i].is_none() && !out.contains(&i) {
                out.push(i);
            }
        }
    }
    out
}

/// A counter run: the units set into it (half at each end) and the group's instances in
/// one row, fronts flush, abutting; placed where the group's own relations say.
pub(crate) fn place_run(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize], units: &[usize]) -> bool {
    let half = units.len().div_ceil(2);
    let mut order: Vec<usize> = units[..half].to_vec();
    order.extend_from_slice(idxs);
    order.extend_from_slice(&units[half..]);
    let mut members = Vec::new();
    let fps: Vec<Aabb> = order.iter().map(|&i| fp_at(ctx, i, 0.0)).collect();
    let depth = fps.iter().map(|f| f.max[1] - f.min[1]).fold(0.0, f64::max);
    let gap = 0.012;
    let len: f64 = fps.iter().map(|f| f.max[0] - f.min[0]).sum::<f64>() + gap * (order.len() - 1) as f64;
    let mut x = -len / 2.0;
    for (&idx, fp) in order.iter().zip(&fps) {
        // Fronts on one line.
        members.push(Member { idx, offset: [x - fp.min[0], depth / 2.0 - fp.max[1], 0.0], turn: 0.0 });
        x += fp.max[0] - fp.min[0] + gap;
    }
    let f = Formation {
        bounds: Aabb { min: [-len / 2.0, -depth / 2.0, 0.0], max: [len / 2.0, depth / 2.0, 1.0] },
        members,
        front_reserve: 0.0,
        back_reserve: 0.0,
        end_reserve: 0.0,
        stacked: false,
        tight: true,
    };
    let rels: Vec<RelationKind> = ctx.relations(group).into_iter().cloned().collect();
    try_formation(ctx, group, &f, &rels, &RelationKind::InRow)
}

/// Half the group against one wall, half against the opposite one: the long walls first
/// (only them with `long`), then the short ones.
fn opposite_walls(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize], long: bool) -> bool {
    let halves = if idxs.len() >= 2 { split(idxs, 2) } else { vec![idxs.to_vec()] };
    let reserve = reserves(ctx, group);
    let [hw, hd] = ctx.space.half;
    let (long_pair, short_pair) = if hw >= hd {
        ([Wall::North, Wall::South], [Wall::East, Wall::West])
    } else {
        ([Wall::East, Wall::West], [Wall::North, Wall::South])
    };
    let mut pairs = vec![long_pair];
    if !long {
        pairs.push(short_pair);
    }
    for pair in pairs {
        for walls in [[pair[0], pair[1]], [pair[1], pair[0]]] {
            // Each half on its own wall of the pair — as one row, else each member on its
            // own along that wall (a doorway in the middle) — nothing committed unless
            // both halves fit.
            let saved = ctx.placed.clone();
            let space = ctx.space.clone();
            let (access, egress) = (ctx.access.clone(), ctx.egress.clone());
            let all = halves.iter().zip(walls).all(|(half, w)| {
                place_on_walls(ctx, group, std::slice::from_ref(half), reserve, &[w])
                    || half
                        .iter()
                        .all(|&m| ctx.placed[m].is_some() || place_on_walls(ctx, group, &[vec![m]], reserve, &[w]))
            });
            if all {
                return true;
            }
            ctx.placed = saved;
            ctx.space = space;
            ctx.access = access;
            ctx.egress = egress;
        }
    }
    if !ctx.input.plan.room.size_fixed {
        ctx.floor_failures += 1;
    }
    false
}

/// Each half against its own wall, walls tried in `order`. Commits what it places.
fn place_on_walls(ctx: &mut Ctx<'_>, group: &str, halves: &[Vec<usize>], reserve: (f64, f64), order: &[Wall]) -> bool {
    let _ = group;
    // Walls already taken by a half placed before.
    let mut used: Vec<Wall> = Vec::new();
    for half in halves {
        if let Some(p) = half.first().and_then(|&i| ctx.placed[i].as_ref().map(|p| (i, p.spot))) {
            let b = Body::object(&ctx.local[p.0], &p.1);
            if let Some(w) =
                Wall::ALL.into_iter().find(|w| relate::holds(ctx, &b, &RelationKind::AgainstWall { wall: Some(*w) }, 1))
            {
                used.push(w);
            }
        }
    }
    for half in halves {
        if half.iter().all(|&i| ctx.placed[i].is_some()) {
            continue;
        }
        let f = rows(ctx, std::slice::from_ref(half), &[true], &[], reserve);
        let mut done = false;
        let free: Vec<Wall> = order.iter().copied().filter(|w| !used.contains(w)).collect();
        for w in free {
            let rel = RelationKind::AgainstWall { wall: Some(w) };
            let spots = candidates::along_wall(ctx, &f.bounds, w, false);
            let size = f.members.len();
            for at in spots {
                let placed = f.members_at(ctx, &at);
                let all_on_wall =
                    placed.iter().all(|(i, s)| relate::holds(ctx, &Body::object(&ctx.local[*i], s), &rel, size));
                if all_on_wall && fits(ctx, &f, &placed) && keeps_egress(ctx, &placed) {
                    commit(ctx, &f, &placed);
                    used.push(w);
                    done = true;
                    break;
                }
            }
            if done {
                break;
            }
        }
        if !done {
            return false;
        }
    }
    true
}

/// Stacks of as many members as fit under the ceiling; the first stack holds them all
/// when it can.
fn stacks(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize]) -> bool {
    let ceiling = ctx.space.height;
    let mut rest: Vec<usize> = idxs.to_vec();
    let rels: Vec<RelationKind> = ctx.relations(group).into_iter().cloned().collect();
    // "three stacks of four", "stacked two high": the column size said.
    let said = column_size(&rels, idxs.len());
    let mut first = true;
    while !rest.is_empty() {
        // As many as fit under the ceiling, and no more than a column may hold.
        let layers = ctx.input.max_layers.get(group).copied().unwrap_or(usize::MAX).max(1).min(said);
        let mut z = 0.0;
        let mut n = 0;
        for &i in &rest {
            if z + ctx.bounds[i].max[2] > ceiling - 0.02 || n == layers {
                break;
            }
            z += top_of(ctx, i);
            n += 1;
        }
        if n == 0 {
            return false;
        }
        if n < rest.len() && first && n < said {
            let phrase = ctx.input.plan.phrase_of(group);
            let why = if n == layers {
                "stand in one column (a taller one sinks more than 1 cm into the simulation's soft contacts)"
                    .to_string()
            } else {
                format!("fit under the {ceiling:.1} m ceiling in one stack")
            };
            ctx.warn(
                "relation_unmet",
                format!("\"{phrase}\" stacked: {} of {} {why}; the rest stand in more stacks beside it", n, rest.len()),
            );
        }
        let these: Vec<usize> = rest.drain(..n).collect();
        let f = stack(ctx, &these);
        let mut spots: Vec<Spot> = Vec::new();
        if !first {
            // Beside the previous stacks.
            let bodies: Vec<Body> =
                ctx.placed_instances(group).into_iter().map(|(i, s)| Body::object(&ctx.local[i], &s)).collect();
            spots.extend(candidates::beside_bodies(&f.bounds, &bodies));
        }
        spots.extend(placements(ctx, group, &f, &rels, &RelationKind::Stacked { n: None, stacks: None }));
        let size = f.members.len();
        let positional: Vec<RelationKind> = rels.iter().filter(|r| relate::is_positional(r)).cloned().collect();
        let mut done = false;
        for at in spots.into_iter().take(MAX_TRIALS) {
            let placed = f.members_at(ctx, &at);
            let base = Body::object(&ctx.local[placed[0].0], &placed[0].1);
            if !positional.iter().all(|r| relate::holds(ctx, &base, r, size)) && first {
                continue;
            }
            if fits(ctx, &f, &placed) && keeps_egress(ctx, &placed[..1]) {
                commit(ctx, &f, &placed);
                done = true;
                break;
            }
        }
        if !done {
            return false;
        }
        first = false;
    }
    true
}

/// The members a column of a stacked group holds: `n` when said, else the group split
/// over `stacks` columns, else all.
pub(crate) fn column_size(rels: &[RelationKind], count: usize) -> usize {
    rels.iter()
        .find_map(|r| match r {
            RelationKind::Stacked { n: Some(n), .. } if *n > 0 => Some(*n as usize),
            RelationKind::Stacked { stacks: Some(k), .. } if *k > 0 => Some(count.div_ceil(*k as usize)),
            _ => None,
        })
        .unwrap_or(usize::MAX)
        .max(1)
}

/// Around a target: members spread over its sides in turn, facing it. Barriers
/// (screens, fences, 1.2 m and taller) keep to three sides, leaving the fourth open to
/// walk in; a fourth side is used only when the three are full.
fn around(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize], target: &str) -> bool {
    let targets = relate::bodies(ctx, target);
    if targets.is_empty() {
        return false;
    }
    let guard = crate::guards::is_guard_of_arm(ctx, idxs[0], target);
    let barrier = ctx.bounds[idxs[0]].max[2] - ctx.bounds[idxs[0]].min[2] >= 1.2;
    let n_targets = targets.len();
    let per = idxs.len().div_ceil(n_targets).max(1);
    let start = (candidates::group_rng(ctx, group) % 4) as usize;
    let mut used: Vec<Vec<usize>> = vec![Vec::new(); n_targets];
    let mut all_ok = true;
    for (k, &idx) in idxs.iter().enumerate() {
        let ti = (k / per).min(n_targets - 1);
        let t = targets[ti].1;
        let local_k = k % per;
        let b = ctx.bounds[idx];
        // Opposite sides first for two, then round the others; barriers start opposite
        // the opening (side 3), where a second piece goes too.
        let pattern: &[usize] = if barrier { &[1, 0, 2] } else { &[0, 2, 1, 3] };
        let want = (pattern[local_k % pattern.len()] + start) % 4;
        let sides: Vec<usize> = pattern.iter().map(|p| (p + start) % 4).collect();
        // The side it is meant for, then sides nobody stands on yet, then the rest.
        let mut order: Vec<usize> = Vec::new();
        let free = |s: &usize| !used[ti].contains(s);
        if free(&want) || used[ti].len() >= sides.len() {
            order.push(want);
        }
        for s in sides.iter().copied().filter(free) {
            if !order.contains(&s) {
                order.push(s);
            }
        }
        for s in sides.iter().copied() {
            if !order.contains(&s) {
                order.push(s);
            }
        }
        // The open fourth side stays open unless nothing else fits.
        let open = (3 + start) % 4;
        if barrier && !order.contains(&open) {
            order.push(open);
        }
        let tucks: &[f64] =
            if ctx.input.objects[idx].has_tag("seating") { &candidates::TUCKED } else { &candidates::OUTSIDE };
        let mut done = false;
        for side in order {
            let cands = if guard {
                crate::guards::ring(ctx, idx, target, &[side])
            } else {
                candidates::around_body(&b, &t, &[side], tucks)
            };
            for spot in cands {
                if floor::fits_floor(ctx, idx, &spot, &[]) && floor::keeps_egress(ctx, idx, &spot) {
                    ctx.commit(idx, spot, Support::Floor);
                    if !used[ti].contains(&side) {
                        used[ti].push(side);
                    }
                    done = true;
                    break;
                }
            }
            if done {
                break;
            }
        }
        if !done {
            all_ok &= floor::place(ctx, idx);
        }
    }
    all_ok
}
