//! Floor placement of one object: candidate poses that keep every relation it has
//! (`relate`), tried best first against the occupied space, the keep-clear zones the
//! rules ask for and the egress routes. A relation that no free pose satisfies is a
//! warning naming the prompt's words, never a silent drop.

use sw_geom::{Aabb, PlacementKind};
use sw_plan::{Relation, RelationKind, Support};

use crate::attempt::Ctx;
use crate::candidates::{self, free_grid, wall_slots};
use crate::frames::Spot;
use crate::relate::{self, Body, Check};
use crate::space::{FLOOR_GAP, union};

/// Candidates of one object that may be tested against the egress routes.
const EGRESS_CHECKS: u32 = 60;

/// The object groups whose keep-clear zones an object of `group` may stand in: what it
/// is said to be in front of, behind, under or the companion of.
pub(crate) fn zone_exemptions(ctx: &Ctx<'_>, group: &str) -> Vec<String> {
    let mut targets: Vec<String> = ctx
        .relations(group)
        .iter()
        .filter_map(|r| match r {
            RelationKind::InFrontOf { target }
            | RelationKind::Behind { target }
            | RelationKind::Under { target }
            | RelationKind::AtEndOfRow { target }
            | RelationKind::AtEndOf { target, .. }
            | RelationKind::OnEachSideOf { target }
            | RelationKind::SetInto { target } => Some(target.clone()),
            _ => None,
        })
        .collect();
    targets.extend(hosts_of(ctx, group));
    targets.iter().flat_map(|t| ctx.instances(t).into_iter().map(|i| ctx.input.objects[i].name.clone())).collect()
}

/// The groups `group` is the companion of ("stations each with a stool": the stations).
pub(crate) fn hosts_of(ctx: &Ctx<'_>, group: &str) -> Vec<String> {
    ctx.input
        .plan
        .relations
        .iter()
        .filter_map(|r| match &r.kind {
            RelationKind::EachWith { target } if target == group => Some(r.subject.clone()),
            _ => None,
        })
        .collect()
}

/// The relation that makes instance `k` of a companion group stand by its own host:
/// in front of it for seating, beside it otherwise.
fn companion_relation(ctx: &Ctx<'_>, idx: usize, host: &str) -> RelationKind {
    if ctx.input.objects[idx].has_tag("seating") {
        RelationKind::InFrontOf { target: host.to_string() }
    } else {
        RelationKind::NextTo { target: host.to_string() }
    }
}

/// Places one floor object at its best feasible candidate. Returns false when none fits.
pub(crate) fn place(ctx: &mut Ctx<'_>, idx: usize) -> bool {
    let group = ctx.input.objects[idx].group.clone();
    // A group's instances are alike: after a few found no place, the rest will not either.
    if ctx.group_failures.get(&group).copied().unwrap_or(0) >= 3 {
        return fail(ctx, idx);
    }
    let k = ctx.instances(&group).iter().position(|&i| i == idx).unwrap_or(0);
    let group_size = ctx.instances(&group).len();
    let mut rels: Vec<RelationKind> =
        ctx.relations(&group).into_iter().filter(|r| relate::is_positional(r)).cloned().collect();
    // A companion ("each with a stool") stands by its own host instance.
    let host = hosts_of(ctx, &group).into_iter().next();
    let host_body = host.as_ref().and_then(|h| relate::bodies(ctx, h).get(k).map(|(_, b)| *b));
    let exempt = zone_exemptions(ctx, &group);
    let ignore: Vec<&str> = exempt.iter().map(String::as_str).collect();
    let in_front = rels.iter().any(|r| matches!(r, RelationKind::InFrontOf { .. }));
    // Room in front of and behind it for what is said to stand there ("a chair behind
    // the desk"), for an object standing alone (a formation keeps its own).
    let reserve = crate::formation::reserves(ctx, &group);
    let ends = crate::formation::end_room(ctx, &group);
    let wants_room = reserve != (0.0, 0.0) || ends.0 > 0.0;
    let mut egress_budget = if in_front { 0 } else { EGRESS_CHECKS };
    let b = ctx.bounds[idx];

    // Candidates satisfying every relation first, then each relation alone.
    let mut specific: Vec<Spot> = Vec::new();
    let mut companion: Option<RelationKind> = None;
    if let (Some(h), Some(hb)) = (&host, host_body) {
        let rel = companion_relation(ctx, idx, h);
        specific.extend(match &rel {
            RelationKind::InFrontOf { .. } => candidates::facing_bodies(&b, &[hb], 1.0),
            _ => candidates::beside_bodies(&b, &[hb]),
        });
        companion = Some(rel);
    }
    // "a workbench between the lathe and the drill press": the second of the two keeps
    // room for what goes between them.
    specific.extend(room_between(ctx, &group, k, &b));
    specific.extend(beside_an_arms_work(ctx, &group, &b));
    // The instances an arm works at stay together, within its reach ("two pallets").
    // An arm on a stand works best between them: leave the stand's width between the
    // first and the next (palletizing between two pallets).
    let stands: Vec<f64> = ctx
        .input
        .robots
        .iter()
        .filter(|r| crate::reach::work_group(ctx, r).as_deref() == Some(group.as_str()))
        .map(|r| match &r.mount {
            crate::RobotMount::Carrier { object } => ctx
                .input
                .objects
                .iter()
                .position(|o| &o.name == object)
                .map_or(0.6, |i| ctx.bounds[i].size()[0].max(ctx.bounds[i].size()[1])),
            _ => 0.0,
        })
        .collect();
    if k > 0 && !stands.is_empty() && rels.is_empty() {
        let first: Vec<Body> = relate::bodies(ctx, &group).into_iter().take(1).map(|(_, b)| b).collect();
        let stand = stands.iter().copied().fold(0.0, f64::max);
        if stand > 0.0 {
            specific.extend(candidates::apart(&b, &first, &[stand + 0.16, stand + 0.3]));
        }
        specific.extend(candidates::beside(ctx, &b, &group, 0));
    }
    for r in &rels {
        specific.extend(candidates::for_relation(ctx, &b, &group, k, r));
    }
    // Work of an arm on the floor or on a stand that already stands (see `order`): beside
    // it, where it reaches — after the places its own relations name, which it then
    // keeps only where the arm reaches too.
    let reaching = crate::reach::floor_arms_reaching(ctx, &group);
    let arms: Vec<([f64; 3], f64)> =
        reaching.iter().filter_map(|&ri| Some((crate::reach::base_of(ctx, ri)?, ctx.input.robots[ri].reach))).collect();
    if !arms.is_empty() {
        for &ri in &reaching {
            let g = ctx.input.robots[ri].group.clone();
            specific.extend(candidates::beside(ctx, &b, &g, k));
        }
    }
    let out_of_reach = |ctx: &Ctx<'_>, spot: &Spot| {
        usize::from(!arms.iter().all(|(base, r)| crate::reach::can_work_at_pose(ctx, *base, *r, idx, spot)))
    };
    // Among poses that keep as much, the one nearest its arms (the solver's reach is
    // conservative: a low free thing by a pedestal is often reached all the same).
    let arm_distance = |spot: &Spot| {
        let c = spot.apply(b.center());
        arms.iter().map(|(base, _)| (c[0] - base[0]).hypot(c[1] - base[1])).fold(0.0, f64::max)
    };
    // Under something with too little clear height below it (a stool under a bench with
    // a bottom shelf): said once, then beside it rather than anywhere.
    for r in &rels {
        let RelationKind::Under { target } = r else { continue };
        let Some(clear) = clear_below(ctx, target) else { continue };
        let tall = b.max[2] - b.min[2];
        if tall + FLOOR_GAP <= clear {
            continue;
        }
        if k == 0 {
            let plan = ctx.input.plan;
            let (subject, under) = (plan.phrase_of(&group), plan.phrase_of(target));
            ctx.warn(
                "does_not_fit_under",
                format!(
                    "\"{subject}\" is {tall:.2} m tall; \"{under}\" has {clear:.2} m clear below it (its lowest shelf or rail): placed beside it"
                ),
            );
        }
        specific.extend(candidates::beside(ctx, &b, target, k));
    }
    if rels.is_empty() && host.is_none() && ctx.input.objects[idx].has_tag("seating") {
        specific.extend(seats_at_tables(ctx, idx, k));
    }
    let checks: Vec<Check<'_>> = rels.iter().map(|r| Check::new(ctx, r).in_group(ctx, &group)).collect();
    // A unit set into a run abuts the run (closer than floor objects otherwise stand).
    let abut: Vec<String> = rels
        .iter()
        .filter_map(|r| match r {
            RelationKind::SetInto { target } => Some(target.as_str()),
            _ => None,
        })
        .flat_map(|t| ctx.instances(t).into_iter().map(|i| ctx.input.objects[i].name.clone()))
        .collect();
    let abut: Vec<&str> = abut.iter().map(String::as_str).collect();
    let host_ok = |ctx: &Ctx<'_>, body: &Body| match (&companion, host_body) {
        (Some(RelationKind::InFrontOf { .. }), Some(hb)) => relate::in_front(body, &hb, 1.0),
        (Some(_), Some(hb)) => relate::gap(&body.fp, &hb.fp) <= relate::NEXT_TO,
        _ => {
            let _ = ctx;
            true
        }
    };
    let mut found: Option<(Spot, usize)> = None;
    let mut best_partial: Option<(Spot, usize)> = None;
    let mut best_distance = f64::INFINITY;
    for spot in &specific {
        let body = Body::object(&ctx.local[idx], spot);
        // Room kept for what is said to stand around it counts as one more thing to keep.
        let kept = !wants_room || room_kept(ctx, idx, spot, reserve, ends);
        let unmet = checks.iter().filter(|c| !c.holds(ctx, &body, group_size)).count()
            + usize::from(!host_ok(ctx, &body))
            + usize::from(!kept)
            + out_of_reach(ctx, spot);
        let d = arm_distance(spot);
        if unmet > 0 && best_partial.as_ref().is_some_and(|(_, u)| *u < unmet || (*u == unmet && best_distance <= d)) {
            continue;
        }
        if !fits_floor_by(ctx, idx, spot, &ignore, &abut) {
            continue;
        }
        if egress_budget > 0 {
            egress_budget -= 1;
            if !keeps_egress(ctx, idx, spot) {
                continue;
            }
        }
        if unmet == 0 {
            found = Some((*spot, 0));
            break;
        }
        best_partial = Some((*spot, unmet));
        best_distance = d;
    }
    drop(checks);
    // Under something whose floor space is taken: on a level under its top.
    if found.is_none() && crate::attempt::is_small(ctx, idx) {
        let under = rels.iter().find_map(|r| match r {
            RelationKind::Under { target } => Some(target.clone()),
            _ => None,
        });
        if let Some(t) = under
            && crate::surface::under_top(ctx, idx, &t)
        {
            return true;
        }
    }
    if found.is_none() {
        found = best_partial;
    }
    if found.is_none() {
        // Defaults and the free grid are the same list for every instance of a group:
        // start where the previous instance found its place (space only fills up).
        let defaults = defaults(ctx, idx);
        let grid = free_grid(ctx, &b, &group, false);
        let start = ctx.cursor.get(&group).copied().unwrap_or(0);
        let all = defaults.len() + grid.len();
        let at = |k: usize| if k < defaults.len() { defaults[k] } else { grid[k - defaults.len()] };
        // With room kept in front and behind for what is said to stand there, then
        // (when nothing has it) without.
        let strict: &[bool] = if wants_room { &[true, false] } else { &[false] };
        'passes: for &keep in strict {
            for j in start..all {
                let spot = at(j);
                if !fits_floor(ctx, idx, &spot, &ignore) || (keep && !room_kept(ctx, idx, &spot, reserve, ends)) {
                    continue;
                }
                if egress_budget > 0 {
                    egress_budget -= 1;
                    if !keeps_egress(ctx, idx, &spot) {
                        continue;
                    }
                }
                if !keep {
                    ctx.cursor.insert(group.clone(), j);
                }
                found = Some((spot, usize::MAX));
                break 'passes;
            }
        }
    }
    let Some((spot, unmet)) = found else {
        *ctx.group_failures.entry(group).or_insert(0) += 1;
        return fail(ctx, idx);
    };
    if room_kept(ctx, idx, &spot, reserve, (0.0, false)) {
        crate::formation::reserve_zones(ctx, idx, &spot, reserve.0, reserve.1);
    }
    if unmet > 0 {
        let body = Body::object(&ctx.local[idx], &spot);
        if let Some(rel) = companion.clone()
            && !host_ok(ctx, &body)
        {
            rels.push(rel);
        }
        warn_unmet(ctx, idx, &group, &rels, &body, group_size);
    }
    ctx.commit(idx, spot, Support::Floor);
    true
}

/// The clear height below `target`'s top over the middle of its footprint: the lowest
/// underside of its collision boxes that stand off the floor and cover its centre (a
/// bottom shelf, a rail, the top itself). None when it has no placed instance or stands
/// solid on the floor there (a base cabinet: nothing goes under it).
pub(crate) fn clear_below(ctx: &Ctx<'_>, target: &str) -> Option<f64> {
    let &ti = ctx.instances(target).first()?;
    let b = ctx.bounds[ti];
    let c = [0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1])];
    // Inner part of the footprint (inside the legs).
    let inner = [0.25 * (b.max[0] - b.min[0]), 0.25 * (b.max[1] - b.min[1])];
    let over = |a: &Aabb| {
        a.min[0] < c[0] + inner[0]
            && a.max[0] > c[0] - inner[0]
            && a.min[1] < c[1] + inner[1]
            && a.max[1] > c[1] - inner[1]
    };
    let boxes: Vec<&Aabb> = ctx.local[ti].iter().filter(|a| over(a)).collect();
    if boxes.iter().any(|a| a.min[2] <= b.min[2] + 0.01) {
        return Some(0.0);
    }
    boxes.iter().map(|a| a.min[2] - b.min[2]).reduce(f64::min)
}

/// Whether the strips kept in front of and behind an object at `spot` (`reserve`, m) are
/// inside the room and free of floor objects.
fn room_kept(ctx: &Ctx<'_>, idx: usize, spot: &Spot, reserve: (f64, f64), (ends, both): (f64, bool)) -> bool {
    let b = ctx.bounds[idx];
    let mut strips = Vec::new();
    if ends > 0.0 {
        // Room at one end, or at both when two things go there.
        let left = Aabb { min: [b.min[0] - ends, b.min[1], 0.0], max: [b.min[0], b.max[1], 2.0] };
        let right = Aabb { min: [b.max[0], b.min[1], 0.0], max: [b.max[0] + ends, b.max[1], 2.0] };
        let free = |z: &Aabb| {
            let w = z.transformed(&spot.pose());
            ctx.space.inside(&Aabb { min: [w.min[0], w.min[1], 0.0], max: [w.max[0], w.max[1], 0.0] })
                && ctx.space.zone_is_clear(&w, &[])
        };
        let (l, r) = (free(&left), free(&right));
        if !(l && r || (!both && (l || r))) {
            return false;
        }
    }
    if reserve.0 > 0.0 {
        strips.push(Aabb { min: [b.min[0], b.max[1], 0.0], max: [b.max[0], b.max[1] + reserve.0, 2.0] });
    }
    if reserve.1 > 0.0 {
        strips.push(Aabb { min: [b.min[0], b.min[1] - reserve.1, 0.0], max: [b.max[0], b.min[1], 2.0] });
    }
    strips.iter().all(|z| {
        let w = z.transformed(&spot.pose());
        ctx.space.inside(&Aabb { min: [w.min[0], w.min[1], 0.0], max: [w.max[0], w.max[1], 0.0] })
            && ctx.space.zone_is_clear(&w, &[])
    })
}

/// Poses for an instance of `group` that leave room between it and the other target of
/// a "between" whose subject is still to be placed: as far from the other as the
/// subject is wide (and a robot's clearance), on any side of it.
fn room_between(ctx: &Ctx<'_>, group: &str, k: usize, b: &Aabb) -> Vec<Spot> {
    let mut out = Vec::new();
    for r in &ctx.input.plan.relations {
        let RelationKind::Between { first, second } = &r.kind else { continue };
        let other = if first == group && second == group {
            if k == 0 {
                continue;
            }
            group
        } else if first == group {
            second.as_str()
        } else if second == group {
            first.as_str()
        } else {
            continue;
        };
        let others: Vec<Body> = relate::bodies(ctx, other).into_iter().map(|(_, b)| b).collect();
        if others.is_empty() {
            continue;
        }
        // How wide the subject is, and the room it needs.
        let robot = ctx.input.robots.iter().find(|x| x.group == r.subject);
        let width = match robot {
            Some(rb) => {
                let k = union(&rb.keepout);
                k.size()[0].min(k.size()[1]) + if rb.is_arm { 0.1 } else { 2.0 * 0.25 }
            }
            None => ctx.instances(&r.subject).first().map_or(0.6, |&i| {
                let s = ctx.bounds[i].size();
                s[0].min(s[1])
            }),
        };
        // The targets' own keep-clear space stays clear of it too.
        let zone = |g: &str| {
            ctx.instances(g).first().map_or(0.0, |&i| {
                let c = &ctx.clearances[i];
                c.front.max(c.back).max(c.sides)
            })
        };
        // An arm between them is their operator: it stands in their working space and
        // reaches both ("a UR5e between two conveyors"), so none is kept for it.
        let width = if robot.is_some_and(|rb| rb.is_arm) { width } else { width + zone(group) + zone(other) };
        let gaps: Vec<f64> = [0.15, 0.3, 0.5, 0.8].iter().map(|e| width + e).collect();
        out.extend(candidates::apart(b, &others, &gaps));
    }
    out
}

/// "a Panda on the counter next to the sink": the counter stands beside the sink (and
/// the sink beside the counter), so that the arm on one can be next to the other.
fn beside_an_arms_work(ctx: &Ctx<'_>, group: &str, b: &Aabb) -> Vec<Spot> {
    let mut out = Vec::new();
    for r in &ctx.input.robots {
        let crate::RobotMount::Surface { group: host } = &r.mount else { continue };
        for rel in ctx.relations(&r.group) {
            let (RelationKind::NextTo { target } | RelationKind::Near { target }) = rel else { continue };
            if host == group && target != group {
                out.extend(candidates::beside(ctx, b, target, 0));
            } else if target == group && host != group {
                out.extend(candidates::beside(ctx, b, host, 0));
            }
        }
    }
    out
}

/// Names each relation of the object that its final pose does not keep.
fn warn_unmet(ctx: &mut Ctx<'_>, idx: usize, group: &str, rels: &[RelationKind], body: &Body, group_size: usize) {
    let plan = ctx.input.plan;
    let unmet: Vec<String> = rels
        .iter()
        .filter(|r| !relate::holds(ctx, body, r, group_size))
        .map(|r| {
            // A companion's own host relation is stated by the host's "each with".
            let subject = match r {
                RelationKind::InFrontOf { target } | RelationKind::NextTo { target }
                    if hosts_of(ctx, group).contains(target) =>
                {
                    return plan.describe(&Relation {
                        subject: target.clone(),
                        kind: RelationKind::EachWith { target: group.to_string() },
                    });
                }
                _ => group.to_string(),
            };
            plan.describe(&Relation { subject, kind: r.clone() })
        })
        .collect();
    if unmet.is_empty() {
        return;
    }
    let name = ctx.input.objects[idx].name.clone();
    ctx.warn(
        "relation_unmet",
        format!("{name}: could not keep {} (no free floor space satisfies it); placed nearby", unmet.join(", ")),
    );
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
    fits_floor_by(ctx, idx, spot, ignore_zones, &[])
}

/// As [`fits_floor`], standing closer than the floor gap to the objects `abut` (a sink
/// unit in a counter run touches the counter), never into them.
pub(crate) fn fits_floor_by(ctx: &Ctx<'_>, idx: usize, spot: &Spot, ignore_zones: &[&str], abut: &[&str]) -> bool {
    let boxes = spot.boxes(&ctx.local[idx]);
    let operators = crate::reach::operators(ctx, &ctx.input.objects[idx].group);
    let ignore_zones: Vec<&str> = ignore_zones.iter().copied().chain(operators.iter().map(String::as_str)).collect();
    if !ctx.space.fits(&boxes, FLOOR_GAP, abut, true, &ignore_zones) {
        return false;
    }
    if !abut.is_empty() && !ctx.space.fits(&boxes, 0.004, &[], false, &[]) {
        return false;
    }
    // Its own keep-clear zones must be inside the room and free of floor objects — but
    // for what it stands under (a cabinet under a table is reached past the table's
    // legs; the table stands over that space, not in it).
    let over: Vec<String> = ctx
        .relations(&ctx.input.objects[idx].group)
        .iter()
        .filter_map(|r| match r {
            RelationKind::Under { target } => Some(target.as_str()),
            _ => None,
        })
        .flat_map(|t| ctx.instances(t).into_iter().map(|i| ctx.input.objects[i].name.clone()))
        .collect();
    // Nor for the arm that works at it and its stand (its operator stands there).
    let except: Vec<&str> = abut
        .iter()
        .copied()
        .chain(over.iter().map(String::as_str))
        .chain(operators.iter().map(String::as_str))
        .collect();
    zones(ctx, idx, spot).iter().all(|(z, _)| {
        ctx.space.inside(&Aabb { min: [z.min[0], z.min[1], 0.0], max: [z.max[0], z.max[1], 0.0] })
            && ctx.space.zone_is_clear(z, &except)
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

/// The object's default places: storage against walls, machines and tables out in the
/// room, small things along the walls.
fn defaults(ctx: &mut Ctx<'_>, idx: usize) -> Vec<Spot> {
    let o = &ctx.input.objects[idx];
    let b = ctx.bounds[idx];
    let group = o.group.clone();
    match o.asset.placement {
        PlacementKind::AgainstWall | PlacementKind::InWall | PlacementKind::WallMounted | PlacementKind::OnSurface => {
            wall_slots(ctx, &b, &group, None)
        }
        PlacementKind::Floor => {
            if o.has_tag("storage") && o.has_tag("tall") {
                wall_slots(ctx, &b, &group, None)
            } else {
                free_grid(ctx, &b, &group, true).to_vec()
            }
        }
    }
}

/// Chairs with nowhere said go to the tables and desks, spread round robin.
fn seats_at_tables(ctx: &Ctx<'_>, idx: usize, k: usize) -> Vec<Spot> {
    let mut tables: Vec<String> = Vec::new();
    for (i, o) in ctx.input.objects.iter().enumerate() {
        let table = o.has_tag("surface") && o.has_tag("furniture") && !o.has_tag("seating");
        if table && ctx.placed[i].is_some() && !tables.contains(&o.group) {
            tables.push(o.group.clone());
        }
    }
    if tables.is_empty() {
        return Vec::new();
    }
    let all: Vec<Body> = tables.iter().flat_map(|t| relate::bodies(ctx, t)).map(|(_, b)| b).collect();
    let n = all.len().max(1);
    let t = all[k % n];
    candidates::around_body(&ctx.bounds[idx], &t, &candidates::sides_from(k / n), &candidates::TUCKED)
}
