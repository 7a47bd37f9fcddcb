//! Items on surfaces: packed onto the support surfaces of their targets (table tops,
//! every shelf level), spread across instances, kept below the next shelf.

use std::f64::consts::FRAC_PI_2;

use sw_geom::Aabb;
use sw_plan::{RelationKind, Support};

use crate::attempt::{Ctx, surface_target};
use crate::floor;
use crate::frames::Spot;
use crate::reach;
use crate::space::SURFACE_GAP;

/// Resolution of positions on a surface, m.
const STEP: f64 = 0.02;
/// "on the edge of": the footprint centre at most this far from an edge, m (the report
/// allows 0.2).
const EDGE: f64 = 0.15;
/// A support this far or more below its host's top is inside it, m (the report and the
/// judge: 0.02; a shallow tray's floor is 2–3 cm down).
const INTERIOR: f64 = 0.021;
/// Between things packed inside a small container, m (the collision test keeps 4 mm).
const CONTAINER_GAP: f64 = 0.006;

/// Which of a host's surfaces an item may use, and where on them.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Want {
    /// Any surface (the top of work furniture first).
    Any,
    /// An interior support: a level under another, a drawer, a bin's floor ("inside").
    Interior,
    /// Near an edge of a surface ("on the edge of").
    Edge,
    /// The top surface only ("a hob set into the worktop").
    Top,
    /// Towards one of its long edges, alternately ("a plate on each side of the table").
    Side,
}

/// What an item's relation to `host` asks of the surface it rests on.
fn want(ctx: &Ctx<'_>, idx: usize, host: &str) -> Want {
    let group = &ctx.input.objects[idx].group;
    ctx.relations(group)
        .iter()
        .find_map(|r| match r {
            RelationKind::Inside { target } if target == host => Some(Want::Interior),
            RelationKind::OnEdgeOf { target } if target == host => Some(Want::Edge),
            RelationKind::SetInto { target } if target == host => Some(Want::Top),
            RelationKind::OnEachSideOf { target } if target == host => Some(Want::Side),
            // Between the arms that share a work surface: on its top, where they work.
            RelationKind::Between { first, .. } if ctx.input.robots.iter().any(|r| &r.group == first) => {
                Some(Want::Top)
            }
            _ => None,
        })
        .unwrap_or(Want::Any)
}

/// Items with an `on` relation (or resting on their host, "desks each with a monitor"):
/// on their target, within reach of the arm that works there, else on the floor next to
/// it (reported).
pub(crate) fn place_all(ctx: &mut Ctx<'_>, items: &[usize]) {
    // Hosts that are loose small things themselves ("cans inside the bin") go first.
    let mut hosts: Vec<usize> = Vec::new();
    for &idx in items {
        let Some(t) = surface_target(ctx, idx) else { continue };
        for i in ctx.instances(&t) {
            let loose = ctx.placed[i].is_none() && crate::attempt::is_small(ctx, i) && surface_target(ctx, i).is_none();
            if loose && !items.contains(&i) && !hosts.contains(&i) && ctx.input.objects[i].carries_robot.is_none() {
                hosts.push(i);
            }
        }
    }
    if !hosts.is_empty() {
        place_loose(ctx, &hosts);
    }
    for idx in hosts_first(ctx, &in_stack_order(ctx, items)) {
        if sw_geom::cancel::requested() {
            return;
        }
        let Some(target) = surface_target(ctx, idx) else {
            continue;
        };
        let group = ctx.input.objects[idx].group.clone();
        // "a stack of five plates on the counter": the first on it, the rest on each other.
        let stacked = ctx.relations(&group).iter().any(|r| matches!(r, RelationKind::Stacked { .. }));
        let order = if stacked { stack_order(ctx, &group) } else { ctx.instances(&group) };
        let k = order.iter().position(|&i| i == idx).unwrap_or(0);
        // Columns no taller than the group may have (learnt from a settle): every
        // `layers`-th member starts a new one on the surface.
        let rels: Vec<RelationKind> = ctx.relations(&group).into_iter().cloned().collect();
        let layers = ctx
            .input
            .max_layers
            .get(&group)
            .copied()
            .unwrap_or(usize::MAX)
            .max(1)
            .min(crate::formation::column_size(&rels, order.len()));
        if stacked && k % layers != 0 && on_the_one_below(ctx, idx, &group, k) {
            continue;
        }
        if place_on_group(ctx, idx, &target, k, true) {
            continue;
        }
        let name = ctx.input.objects[idx].name.clone();
        let want = want(ctx, idx, &target);
        // On a thing no wider than itself ("a red cube on the green cube"): centred on
        // its top, the one with nothing on it yet first.
        if want == Want::Any && on_small_thing(ctx, idx, &target) {
            continue;
        }
        // Said to be between two arms with no room left on the line between them: within
        // the reach of one of them still (the report names the relation not kept).
        if !robot_pairs(ctx, &ctx.input.objects[idx].group).is_empty()
            && place_on_group_as(ctx, idx, &target, k, true, want, false)
        {
            continue;
        }
        if place_on_group(ctx, idx, &target, k, false) {
            let phrase = ctx.input.plan.phrase_of(&target);
            ctx.warn(
                "relation_unmet",
                format!("{name}: no room on \"{phrase}\" within the reach of the arm that works there; placed out of its reach"),
            );
            continue;
        }
        if stack_on_own(ctx, idx, &group) {
            continue;
        }
        // A container whose floor is full ("four cubes in a bowl" with room for two side
        // by side): heaped on one of its own kind inside it, within the walls.
        if want == Want::Interior && heap_inside(ctx, idx, &target) {
            let subject = ctx.input.plan.phrase_of(&group);
            let phrase = ctx.input.plan.phrase_of(&target);
            ctx.warn(
                "relation_unmet",
                format!("{name}: \"{phrase}\" has no room on its floor for \"{subject}\"; heaped on one inside it"),
            );
            continue;
        }
        // A container or small thing that cannot hold it ("six eggs in a bowl" with room
        // for one): beside it on what it stands on, within the same arm's reach, rather
        // than on the floor.
        if let Some(host) = beside_on_host(ctx, idx, &target, k) {
            let subject = ctx.input.plan.phrase_of(&group);
            let phrase = ctx.input.plan.phrase_of(&target);
            let how = if want == Want::Interior { "inside" } else { "on" };
            ctx.warn(
                "relation_unmet",
                format!("{name}: \"{phrase}\" has no room for \"{subject}\" {how} it; placed on {host} instead"),
            );
            continue;
        }
        let had_target = !ctx.placed_instances(&target).is_empty();
        if floor::place(ctx, idx) {
            let why = if had_target { "no room left on it" } else { "it could not be placed" };
            let subject = ctx.input.plan.phrase_of(&group);
            let phrase = ctx.input.plan.phrase_of(&target);
            ctx.warn(
                "relation_unmet",
                format!("{name}: could not keep \"{subject}\" on \"{phrase}\" ({why}); placed on the floor"),
            );
        }
    }
}

/// `items` with each one after the items it rests on ("four cubes in a bowl on the
/// table": the bowl first, then the cubes; "a red cube on the green cube" likewise):
/// an item whose host is itself still to be placed would find no host and go to the
/// floor. Stable otherwise; a cycle of hosts keeps the given order.
fn hosts_first(ctx: &Ctx<'_>, items: &[usize]) -> Vec<usize> {
    let group_of = |i: usize| ctx.input.objects[i].group.as_str();
    // How many hosts among `items` lie under each item's group (its depth in the pile).
    let depth = |i: usize| -> usize {
        let mut g = group_of(i).to_string();
        let mut seen: Vec<String> = vec![g.clone()];
        let mut d = 0;
        while let Some(t) = ctx.instances(&g).first().and_then(|&j| surface_target(ctx, j)) {
            if seen.contains(&t) || !items.iter().any(|&j| group_of(j) == t) {
                break;
            }
            seen.push(t.clone());
            g = t;
            d += 1;
        }
        d
    };
    let mut keyed: Vec<(usize, usize)> = items.iter().map(|&i| (depth(i), i)).collect();
    keyed.sort_by_key(|(d, _)| *d);
    keyed.into_iter().map(|(_, i)| i).collect()
}

/// The members of a stacked group from the bottom up, widest first (stable): what stands
/// on the bottom one stays within its footprint, so a stack placed near a wall does not
/// have a wider member above poking into it ("a stack of plates" of varied sizes).
fn stack_order(ctx: &Ctx<'_>, group: &str) -> Vec<usize> {
    let mut v = ctx.instances(group);
    let width = |i: usize| {
        let s = ctx.bounds[i].size();
        s[0].max(s[1])
    };
    v.sort_by(|a, b| width(*b).total_cmp(&width(*a)));
    v
}

/// `items` with the members of each stacked group, in the places they hold, put in their
/// stack order.
fn in_stack_order(ctx: &Ctx<'_>, items: &[usize]) -> Vec<usize> {
    let mut out = items.to_vec();
    let mut groups: Vec<String> = Vec::new();
    for &i in items {
        let g = &ctx.input.objects[i].group;
        if !groups.contains(g) && ctx.relations(g).iter().any(|r| matches!(r, RelationKind::Stacked { .. })) {
            groups.push(g.clone());
        }
    }
    for g in &groups {
        let slots: Vec<usize> = (0..out.len()).filter(|&p| &ctx.input.objects[out[p]].group == g).collect();
        let order: Vec<usize> = stack_order(ctx, g).into_iter().filter(|i| items.contains(i)).collect();
        for (p, i) in slots.into_iter().zip(order) {
            out[p] = i;
        }
    }
    out
}

/// Item `idx` on the top of an instance of `target` that is itself a small thing whose
/// support surface is smaller than the item's footprint (a cube on a cube): centred on
/// it, the judge's `on` (centre over the surface). Instances with something on them
/// already are skipped.
fn on_small_thing(ctx: &mut Ctx<'_>, idx: usize, target: &str) -> bool {
    let free: Vec<usize> = ctx
        .placed_instances(target)
        .into_iter()
        .map(|(i, _)| i)
        .filter(|&i| crate::attempt::is_small(ctx, i) && i != idx)
        .filter(|&i| {
            let name = &ctx.input.objects[i].name;
            !ctx.placed.iter().flatten().any(|q| matches!(&q.support, Support::Object { object, .. } if object == name))
        })
        .collect();
    free.into_iter().any(|b| on_top_of(ctx, idx, b))
}

/// Item `idx` whose target (`target`, instance `k` first) has no room for it: on the
/// object an instance of the target rests on, as near the target as there is room and
/// within the reach of the arm that works there. Returns that object's name.
/// (Its place on that surface is where the reach and the free room allow.)
fn beside_on_host(ctx: &mut Ctx<'_>, idx: usize, target: &str, k: usize) -> Option<String> {
    let mut hosts: Vec<(String, String, [f64; 2])> = Vec::new();
    for (i, s) in ctx.placed_instances(target) {
        let Some(Support::Object { object, .. }) = ctx.placed[i].as_ref().map(|p| &p.support) else { continue };
        let Some(hi) = ctx.input.objects.iter().position(|o| &o.name == object) else { continue };
        let g = ctx.input.objects[hi].group.clone();
        if g != ctx.input.objects[idx].group {
            hosts.push((g, object.clone(), [s.x, s.y]));
        }
    }
    if hosts.is_empty() {
        return None;
    }
    let n = hosts.len();
    hosts.rotate_left(k % n);
    hosts.into_iter().find_map(|(group, name, at)| near_on_group(ctx, idx, &group, at).then_some(name))
}

/// Item `idx` on a surface of one of `group`'s instances in reach of its arms: the
/// instance nearest `at` first, its open (top) surfaces before those under a shelf.
fn near_on_group(ctx: &mut Ctx<'_>, idx: usize, group: &str, at: [f64; 2]) -> bool {
    let mut hosts = ctx.placed_instances(group);
    hosts.sort_by(|a, b| (a.1.x - at[0]).hypot(a.1.y - at[1]).total_cmp(&(b.1.x - at[0]).hypot(b.1.y - at[1])));
    for (hi, _) in hosts {
        let item_group = ctx.input.objects[idx].group.clone();
        let (arms, all) = reach::arms_for(ctx, hi, &item_group);
        let nsurf = ctx.input.objects[hi].asset.surfaces.len();
        ctx.surface_use.entry(hi).or_insert_with(|| vec![Vec::new(); nsurf]);
        let mut order: Vec<usize> = (0..nsurf).collect();
        order.sort_by_key(|&i| ctx.input.objects[hi].asset.surfaces[i].clearance.is_some());
        for si in order {
            if try_surface(ctx, idx, hi, si, &arms, all, (false, None), &[]) {
                return true;
            }
        }
    }
    false
}

/// Member `k` of a stacked group (in its stack order) on top of member `k - 1`, centred
/// over it.
fn on_the_one_below(ctx: &mut Ctx<'_>, idx: usize, group: &str, k: usize) -> bool {
    let Some(&below) = stack_order(ctx, group).get(k - 1) else { return false };
    on_top_of(ctx, idx, below)
}

/// A stackable item with no room left on its target: on top of one of its own kind that
/// rests there ("three crates on a pallet" that holds two side by side: the third on one
/// of them). The lowest free one first.
fn stack_on_own(ctx: &mut Ctx<'_>, idx: usize, group: &str) -> bool {
    if !ctx.input.objects[idx].has_tag("stackable") {
        return false;
    }
    let members = ctx.instances(group);
    let mut below: Vec<(f64, usize)> = members
        .iter()
        .filter(|&&i| i != idx)
        .filter_map(|&i| {
            let p = ctx.placed[i].as_ref()?;
            let resting = matches!(&p.support, Support::Object { .. });
            // Nothing of its own kind on it yet.
            let free =
                !ctx.placed.iter().flatten().any(
                    |q| matches!(&q.support, Support::Object { object, .. } if *object == ctx.input.objects[i].name),
                );
            (resting && free).then_some((p.spot.z, i))
        })
        .collect();
    below.sort_by(|a, b| a.0.total_cmp(&b.0));
    below.into_iter().any(|(_, b)| on_top_of(ctx, idx, b))
}

/// Item `idx` on top of one of its own kind that rests on an interior support of an
/// instance of `target` (a bowl's, a bin's floor) with nothing on it yet, when its bottom
/// then stays below the container's rim. Round things are not heaped (they roll off in
/// the settle) and neither is what is rounder than it is flat on top.
fn heap_inside(ctx: &mut Ctx<'_>, idx: usize, target: &str) -> bool {
    if ctx.input.objects[idx].has_tag("round") {
        return false;
    }
    let group = ctx.input.objects[idx].group.clone();
    let mut below: Vec<(f64, usize)> = Vec::new();
    for (hi, _) in ctx.placed_instances(target) {
        let host = ctx.input.objects[hi].name.clone();
        let rim = ctx.placed[hi].as_ref().map_or(f64::NEG_INFINITY, |p| p.spot.z) + ctx.bounds[hi].max[2];
        for i in ctx.instances(&group) {
            let Some(p) = ctx.placed[i].as_ref() else { continue };
            let inside = matches!(&p.support, Support::Object { object, .. } if *object == host);
            let name = &ctx.input.objects[i].name;
            let free = !ctx
                .placed
                .iter()
                .flatten()
                .any(|q| matches!(&q.support, Support::Object { object, .. } if object == name));
            // The top of the one below, where this one's bottom would be.
            let top = p.spot.z + ctx.bounds[i].max[2];
            if i != idx && inside && free && top < rim {
                below.push((top, i));
            }
        }
    }
    below.sort_by(|a, b| a.0.total_cmp(&b.0));
    below.into_iter().any(|(_, b)| on_top_of(ctx, idx, b))
}

/// Item `idx` on top of object `below`, centred over it.
fn on_top_of(ctx: &mut Ctx<'_>, idx: usize, below: usize) -> bool {
    let Some(bs) = ctx.placed[below].as_ref().map(|p| p.spot) else { return false };
    // On the highest point of the one below (a plate's rim, a box's lid).
    let top = ctx.bounds[below].max[2];
    let (lb, lt) = (ctx.bounds[below], ctx.bounds[idx]);
    // Footprint centres over each other, in the one below's frame.
    let cb = [0.5 * (lb.min[0] + lb.max[0]), 0.5 * (lb.min[1] + lb.max[1])];
    let ct = [0.5 * (lt.min[0] + lt.max[0]), 0.5 * (lt.min[1] + lt.max[1])];
    let p = bs.apply([cb[0] - ct[0], cb[1] - ct[1], top - lt.min[2]]);
    let spot = Spot::new(p[0], p[1], p[2], bs.yaw);
    if !ctx.space.fits(&spot.boxes(&ctx.local[idx]), 0.0, &[], false, &[]) {
        return false;
    }
    let surface = crate::formation::top_surface(ctx, below);
    let name = ctx.input.objects[below].name.clone();
    ctx.commit(idx, spot, Support::Object { object: name, surface });
    true
}

/// Small items with no support named: tabletop things on work surfaces, the rest on
/// the floor.
pub(crate) fn place_loose(ctx: &mut Ctx<'_>, items: &[usize]) {
    let hosts_tagged = |ctx: &Ctx<'_>, work: bool| -> Vec<String> {
        let mut v: Vec<String> = Vec::new();
        for (i, o) in ctx.input.objects.iter().enumerate() {
            let host = if work {
                o.has_tag("surface") && o.has_tag("furniture")
            } else {
                o.has_tag("storage") && !o.asset.surfaces.is_empty()
            };
            if host && ctx.placed[i].is_some() && o.carries_robot.is_none() && !v.contains(&o.group) {
                v.push(o.group.clone());
            }
        }
        v
    };
    let work_hosts = hosts_tagged(ctx, true);
    let storage_hosts = hosts_tagged(ctx, false);
    for &idx in items {
        if sw_geom::cancel::requested() {
            return;
        }
        let o = &ctx.input.objects[idx];
        // "a bin under the table", "a crate next to the door": where it goes was said.
        let placed_by_relation = !ctx.relations(&o.group).is_empty();
        // Tabletop things go on work surfaces; boxes and crates on the shelving.
        let hosts = if o.has_tag("tabletop") {
            &work_hosts
        } else if o.has_tag("container") || o.has_tag("stackable") {
            &storage_hosts
        } else {
            &Vec::new()
        };
        if !placed_by_relation && !hosts.is_empty() {
            let group = o.group.clone();
            let k = ctx.instances(&group).iter().position(|&i| i == idx).unwrap_or(0);
            let host = hosts[k % hosts.len()].clone();
            let hosts = hosts.clone();
            if place_on_group(ctx, idx, &host, k / hosts.len(), true)
                || hosts.iter().any(|h| place_on_group(ctx, idx, h, 0, true))
            {
                continue;
            }
        }
        floor::place(ctx, idx);
    }
}

/// Tries every placed instance of `target` (starting with instance `k`) and every
/// surface of it, least used first.
fn place_on_group(ctx: &mut Ctx<'_>, idx: usize, target: &str, k: usize, in_reach: bool) -> bool {
    let want = want(ctx, idx, target);
    place_on_group_as(ctx, idx, target, k, in_reach, want, true)
}

/// A small thing said to be under something whose floor space is taken (a crate under
/// a workbench with a bottom shelf): on a level under its top.
pub(crate) fn under_top(ctx: &mut Ctx<'_>, idx: usize, target: &str) -> bool {
    place_on_group_as(ctx, idx, target, 0, false, Want::Interior, true)
}

fn place_on_group_as(
    ctx: &mut Ctx<'_>,
    idx: usize,
    target: &str,
    k: usize,
    in_reach: bool,
    want: Want,
    between: bool,
) -> bool {
    let mut hosts = ctx.placed_instances(target);
    if hosts.is_empty() {
        return false;
    }
    let n = hosts.len();
    hosts.rotate_left(k % n);
    for (hi, _) in hosts {
        let nsurf = ctx.input.objects[hi].asset.surfaces.len();
        let mut order: Vec<usize> = (0..nsurf).collect();
        let used = ctx.surface_use.entry(hi).or_insert_with(|| vec![Vec::new(); nsurf]).clone();
        let host = &ctx.input.objects[hi];
        let surfaces = &host.asset.surfaces;
        // On work furniture ("on the bench") the top is meant, the shelf under it only
        // when the top is full; storage spreads items over its levels.
        let work = host.has_tag("surface") && host.has_tag("furniture") && !host.has_tag("storage");
        let lower = |i: usize| work && surfaces[i].clearance.is_some();
        order.sort_by(|&a, &b| {
            let fa = fill(&used[a]) / surfaces[a].area().max(1e-6);
            let fb = fill(&used[b]) / surfaces[b].area().max(1e-6);
            lower(a).cmp(&lower(b)).then(fa.total_cmp(&fb)).then(a.cmp(&b))
        });
        let item_group = ctx.input.objects[idx].group.clone();
        let (arms, all) = if in_reach { reach::arms_for(ctx, hi, &item_group) } else { (Vec::new(), false) };
        let top = ctx.bounds[hi].max[2];
        let highest = surfaces
            .iter()
            .enumerate()
            .filter(|(_, s)| s.clearance.is_none())
            .max_by(|a, b| a.1.z.total_cmp(&b.1.z))
            .map(|(i, _)| i);
        let usable: Vec<usize> = order
            .into_iter()
            .filter(|&i| match want {
                Want::Interior => surfaces[i].clearance.is_some() || top - surfaces[i].z >= INTERIOR,
                Want::Top | Want::Side => Some(i) == highest,
                Want::Any | Want::Edge => true,
            })
            .collect();
        let pairs = if between { robot_pairs(ctx, &item_group) } else { Vec::new() };
        // Arms sharing the surface: where all of them reach first (each arm then has some
        // of every kind of thing to work on), then where one does.
        if !all && arms.len() > 1 {
            for &si in usable.iter().filter(|&&i| surfaces[i].clearance.is_none()) {
                let side = (want == Want::Side).then_some(k.is_multiple_of(2));
                if try_surface(ctx, idx, hi, si, &arms, true, (want == Want::Edge, side), &pairs) {
                    return true;
                }
            }
        }
        for si in usable {
            let side = (want == Want::Side).then_some(k.is_multiple_of(2));
            if try_surface(ctx, idx, hi, si, &arms, all, (want == Want::Edge, side), &pairs) {
                return true;
            }
        }
    }
    false
}

fn fill(rects: &[[f64; 4]]) -> f64 {
    rects.iter().map(|r| (r[2] - r[0]) * (r[3] - r[1])).sum()
}

/// Puts the item on surface `si` of `host`, within the reach of one of `arms` (base,
/// reach) — of every one with `all` — when there are any.
/// The footprints of the robots an item is said to be between, in pairs.
fn robot_pairs(ctx: &Ctx<'_>, item_group: &str) -> Vec<(Aabb, Aabb)> {
    let mut out = Vec::new();
    for r in ctx.relations(item_group) {
        let RelationKind::Between { first, second } = r else { continue };
        let robot = |g: &str| ctx.input.robots.iter().any(|x| x.group == g);
        if !robot(first) || !robot(second) {
            continue;
        }
        let (a, b) = (crate::relate::bodies(ctx, first), crate::relate::bodies(ctx, second));
        for (i, (_, x)) in a.iter().enumerate() {
            for (j, (_, y)) in b.iter().enumerate() {
                if (first != second || i < j) && x.fp.min != y.fp.min {
                    // A little inside their bases: the judge takes the base's own geometry.
                    let shrink = |b: &Aabb| Aabb {
                        min: [b.min[0] + 0.04, b.min[1] + 0.04, b.min[2]],
                        max: [b.max[0] - 0.04, b.max[1] - 0.04, b.max[2]],
                    };
                    out.push((shrink(&x.fp), shrink(&y.fp)));
                }
            }
        }
    }
    out
}

#[allow(clippy::too_many_arguments)]
fn try_surface(
    ctx: &mut Ctx<'_>,
    idx: usize,
    host: usize,
    si: usize,
    arms: &[([f64; 3], f64)],
    all: bool,
    (edge, side): (bool, Option<bool>),
    between: &[(Aabb, Aabb)],
) -> bool {
    let Some(host_spot) = ctx.placed[host].as_ref().map(|p| p.spot) else {
        return false;
    };
    let surf = ctx.input.objects[host].asset.surfaces[si].clone();
    let b = ctx.bounds[idx];
    let height = b.max[2] - b.min[2];
    if let Some(c) = surf.clearance
        && height > c - 0.01
    {
        return false;
    }
    let host_name = ctx.input.objects[host].name.clone();
    // Inside a small container (a bowl's, a tote's floor) things are packed close, as a
    // person fills a bowl: the collision test's own gap and a little more.
    let container = crate::attempt::is_small(ctx, host) || ctx.input.objects[host].has_tag("container");
    let interior = container && surf.clearance.is_none() && ctx.bounds[host].max[2] - surf.z >= INTERIOR;
    let gap = if interior { CONTAINER_GAP } else { SURFACE_GAP };
    // A host with a relation to itself would be odd; an item never rests on itself.
    if ctx.input.objects[idx].name == host_name {
        return false;
    }
    let group = ctx.input.objects[idx].group.clone();
    let flanked =
        ctx.input.plan.relations.iter().any(
            |r| matches!(&r.kind, RelationKind::OnEachSideOf { target } if *target == group && r.subject != group),
        );
    let flip = ctx.rng.chance(0.5);
    let mut yaws = if flip { [FRAC_PI_2, 0.0] } else { [0.0, FRAC_PI_2] };
    if let Some((a, c)) = between.first() {
        // Between two arms: its short side along the line between them, so more fit.
        let (ca, cc) = (a.center(), c.center());
        let (s, co) = host_spot.yaw.sin_cos();
        let d = [cc[0] - ca[0], cc[1] - ca[1]];
        let along_x = (co * d[0] + s * d[1]).abs() >= (-s * d[0] + co * d[1]).abs();
        let wide_x = b.max[0] - b.min[0] >= b.max[1] - b.min[1];
        yaws = if along_x == wide_x { [FRAC_PI_2, 0.0] } else { [0.0, FRAC_PI_2] };
    }
    if flanked {
        // Its long side along the top's long side: room at both its ends.
        let long_x = surf.max[0] - surf.min[0] >= surf.max[1] - surf.min[1];
        let wide_x = b.max[0] - b.min[0] >= b.max[1] - b.min[1];
        yaws = if long_x == wide_x { [0.0, FRAC_PI_2] } else { [FRAC_PI_2, 0.0] };
    }
    let from_right = ctx.rng.chance(0.5);
    // Where it is said to stand by something placed ("a plate next to the toaster", "blocks
    // in front of the Panda"): the grid is tried nearest that first, and only spots that
    // keep those relations until none does.
    let host_group = ctx.input.objects[host].group.clone();
    let flanked =
        ctx.input.plan.relations.iter().any(
            |r| matches!(&r.kind, RelationKind::OnEachSideOf { target } if *target == group && r.subject != group),
        );
    let by: Vec<RelationKind> = ctx
        .relations(&group)
        .into_iter()
        .filter(|r| {
            // On each side of the host itself is `Want::Side`; of a thing on it, kept here.
            let by_thing = matches!(r, RelationKind::OnEachSideOf { target } if *target != host_group);
            (by_thing
                || matches!(
                    r,
                    RelationKind::NextTo { .. }
                        | RelationKind::Near { .. }
                        | RelationKind::InFrontOf { .. }
                        | RelationKind::Behind { .. }
                ))
                && r.targets().first().is_some_and(|t| !crate::relate::bodies(ctx, t).is_empty())
        })
        .cloned()
        .collect();
    let aims: Vec<[f64; 2]> = by
        .iter()
        .flat_map(|r| {
            // On each side of a thing: towards the two ends of its long axis, where a thing
            // set down on a top has room more often than at its front and back.
            if let RelationKind::OnEachSideOf { target } = r {
                return crate::relate::bodies(ctx, target)
                    .into_iter()
                    .flat_map(|(_, b)| {
                        let x = crate::relate::x_axis(&b);
                        let u = if b.half_along(x) >= b.half_along(b.front) { x } else { b.front };
                        let (c, d) = (b.center(), b.half_along(u) + 0.12);
                        [[c[0] + u[0] * d, c[1] + u[1] * d], [c[0] - u[0] * d, c[1] - u[1] * d]]
                    })
                    .collect::<Vec<_>>();
            }
            let sign = match r {
                RelationKind::InFrontOf { .. } => 1.0,
                RelationKind::Behind { .. } => -1.0,
                _ => 0.0,
            };
            let t = r.targets().first().map(|t| t.to_string()).unwrap_or_default();
            crate::relate::bodies(ctx, &t)
                .into_iter()
                .map(|(_, b)| {
                    let (c, f) = (b.center(), b.front);
                    let d = b.half_along([f[0] * sign, f[1] * sign]) + 0.15;
                    [c[0] + sign * f[0] * d, c[1] + sign * f[1] * d]
                })
                .collect::<Vec<_>>()
        })
        .collect();
    for strict in [true, false] {
        if strict && by.is_empty() {
            continue;
        }
        for local_yaw in yaws {
            let rotated = local_yaw != 0.0;
            let (ex, ey) = if rotated {
                (0.5 * (b.max[1] - b.min[1]), 0.5 * (b.max[0] - b.min[0]))
            } else {
                (0.5 * (b.max[0] - b.min[0]), 0.5 * (b.max[1] - b.min[1]))
            };
            let m = if interior { 0.002 } else { 0.005 };
            let (x0, x1) = (surf.min[0] + ex + m, surf.max[0] - ex - m);
            let (y0, y1) = (surf.min[1] + ey + m, surf.max[1] - ey - m);
            if x1 < x0 || y1 < y0 {
                continue;
            }
            // Offset of the item's origin from its footprint centre, in the surface frame.
            let (cx, cy) = (0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1]));
            let (ox, oy) = if rotated { (-cy, cx) } else { (cx, cy) };
            let nx = ((x1 - x0) / STEP).floor() as usize;
            let ny = ((y1 - y0) / STEP).floor() as usize;
            let mut grid: Vec<(f64, f64)> = Vec::with_capacity((nx + 1) * (ny + 1));
            for j in 0..=ny {
                for i in 0..=nx {
                    let x = if from_right { x1 - i as f64 * STEP } else { x0 + i as f64 * STEP };
                    grid.push((x, y0 + j as f64 * STEP));
                }
            }
            if !between.is_empty() {
                // Between two arms: packed from the middle of the line between them outwards,
                // so that each end stays within the reach of its arm.
                let mids: Vec<[f64; 2]> = between
                    .iter()
                    .map(|(a, b)| {
                        let (ca, cb) = (a.center(), b.center());
                        [0.5 * (ca[0] + cb[0]), 0.5 * (ca[1] + cb[1])]
                    })
                    .collect();
                let key = |p: &(f64, f64)| {
                    let w = host_spot.apply([p.0, p.1, 0.0]);
                    mids.iter().map(|m| (w[0] - m[0]).hypot(w[1] - m[1])).fold(f64::INFINITY, f64::min)
                };
                grid.sort_by(|a, b| key(a).total_cmp(&key(b)));
            } else if !aims.is_empty() {
                let key = |p: &(f64, f64)| {
                    let w = host_spot.apply([p.0, p.1, 0.0]);
                    aims.iter().map(|m| (w[0] - m[0]).hypot(w[1] - m[1])).fold(f64::INFINITY, f64::min)
                };
                grid.sort_by(|a, b| key(a).total_cmp(&key(b)));
            } else if flanked {
                // Things are to stand on each side of it on this top: from the middle out,
                // so that both sides of it have room.
                let (cx, cy) = (0.5 * (surf.min[0] + surf.max[0]), 0.5 * (surf.min[1] + surf.max[1]));
                grid.sort_by(|a, b| (a.0 - cx).hypot(a.1 - cy).total_cmp(&(b.0 - cx).hypot(b.1 - cy)));
            }
            {
                for (x, y) in grid {
                    if edge && (x - surf.min[0]).min(surf.max[0] - x).min(y - surf.min[1]).min(surf.max[1] - y) > EDGE {
                        continue;
                    }
                    if let Some(up) = side {
                        // In the outer part of the half towards one long edge.
                        let (cx, cy) = (0.5 * (surf.min[0] + surf.max[0]), 0.5 * (surf.min[1] + surf.max[1]));
                        let (hx, hy) = (0.5 * (surf.max[0] - surf.min[0]), 0.5 * (surf.max[1] - surf.min[1]));
                        let (across, half, along, half_along) =
                            if hx >= hy { (y - cy, hy, x - cx, hx) } else { (x - cx, hx, y - cy, hy) };
                        let off = if up { across } else { -across };
                        // On that side as seen from the middle (not nearer an end than the edge).
                        if off < 0.3 * half || along.abs() / half_along >= off / half {
                            continue;
                        }
                    }
                    let rect = [x - ex, y - ey, x + ex, y + ey];
                    let used = ctx.surface_use.get(&host).and_then(|u| u.get(si));
                    if used.is_some_and(|u| u.iter().any(|r| rects_overlap(r, &rect, gap))) {
                        continue;
                    }
                    if !between.is_empty() {
                        // Its centre on the line between two arms (inside the hull of their bases).
                        let c = host_spot.apply([x, y, surf.z]);
                        if !between.iter().any(|(a, b)| crate::relate::in_hull(a, b, [c[0], c[1]])) {
                            continue;
                        }
                    }
                    if !arms.is_empty() {
                        let centre = host_spot.apply([x, y, surf.z + 0.5 * height]);
                        let ok = |(base, r): &([f64; 3], f64)| reach::reaches(*base, *r, centre);
                        if !(if all { arms.iter().all(ok) } else { arms.iter().any(ok) }) {
                            continue;
                        }
                    }
                    let origin = host_spot.apply([x - ox, y - oy, surf.z - b.min[2]]);
                    let spot = Spot::new(origin[0], origin[1], origin[2], host_spot.yaw + local_yaw);
                    let boxes = spot.boxes(&ctx.local[idx]);
                    if !ctx.space.fits(&boxes, 0.004, &[], false, &[]) {
                        continue;
                    }
                    if strict {
                        let body = crate::relate::Body::object(&ctx.local[idx], &spot);
                        let n = ctx.instances(&group).len();
                        if !by
                            .iter()
                            .all(|r| crate::relate::Check::new(ctx, r).in_group(ctx, &group).holds(ctx, &body, n))
                        {
                            continue;
                        }
                    }
                    ctx.commit(idx, spot, Support::Object { object: host_name, surface: surf.name.clone() });
                    let nsurf = ctx.input.objects[host].asset.surfaces.len();
                    ctx.surface_use.entry(host).or_insert_with(|| vec![Vec::new(); nsurf])[si].push(rect);
                    return true;
                }
            }
        }
    }
    false
}

fn rects_overlap(a: &[f64; 4], b: &[f64; 4], gap: f64) -> bool {
    a[0] < b[2] + gap && b[0] < a[2] + gap && a[1] < b[3] + gap && b[1] < a[3] + gap
}
