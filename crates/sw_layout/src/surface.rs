//! Items on surfaces: packed onto the support surfaces of their targets (table tops,
//! every shelf level), spread across instances, kept below the next shelf.

use std::f64::consts::FRAC_PI_2;

use sw_plan::{RelationKind, Support};

use crate::attempt::{Ctx, surface_target};
use crate::floor;
use crate::frames::Spot;
use crate::reach;
use crate::space::SURFACE_GAP;

/// Resolution of positions on a surface, m.
const STEP: f64 = 0.02;

/// Items with an `on` relation (or resting on their host, "desks each with a monitor"):
/// on their target, within reach of the arm that works there, else on the floor next to
/// it (reported).
pub(crate) fn place_all(ctx: &mut Ctx<'_>, items: &[usize]) {
    for idx in in_stack_order(ctx, items) {
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
        let layers = ctx.input.max_layers.get(&group).copied().unwrap_or(usize::MAX).max(1);
        if stacked && k % layers != 0 && on_the_one_below(ctx, idx, &group, k) {
            continue;
        }
        if place_on_group(ctx, idx, &target, k, true) {
            continue;
        }
        let name = ctx.input.objects[idx].name.clone();
        if place_on_group(ctx, idx, &target, k, false) {
            let phrase = ctx.input.plan.phrase_of(&target);
            ctx.warn(
                "relation_unmet",
                format!("{name}: no room on \"{phrase}\" within the reach of the arm that works there; placed out of its reach"),
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

/// Member `k` of a stacked group (in its stack order) on top of member `k - 1`, centred
/// over it.
fn on_the_one_below(ctx: &mut Ctx<'_>, idx: usize, group: &str, k: usize) -> bool {
    let Some(&below) = stack_order(ctx, group).get(k - 1) else { return false };
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
        for si in order {
            if try_surface(ctx, idx, hi, si, &arms, all) {
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
fn try_surface(ctx: &mut Ctx<'_>, idx: usize, host: usize, si: usize, arms: &[([f64; 3], f64)], all: bool) -> bool {
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
    // A host with a relation to itself would be odd; an item never rests on itself.
    if ctx.input.objects[idx].name == host_name {
        return false;
    }
    let flip = ctx.rng.chance(0.5);
    let yaws = if flip { [FRAC_PI_2, 0.0] } else { [0.0, FRAC_PI_2] };
    let from_right = ctx.rng.chance(0.5);
    for local_yaw in yaws {
        let rotated = local_yaw != 0.0;
        let (ex, ey) = if rotated {
            (0.5 * (b.max[1] - b.min[1]), 0.5 * (b.max[0] - b.min[0]))
        } else {
            (0.5 * (b.max[0] - b.min[0]), 0.5 * (b.max[1] - b.min[1]))
        };
        let m = 0.005;
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
        for j in 0..=ny {
            for i in 0..=nx {
                let x = if from_right { x1 - i as f64 * STEP } else { x0 + i as f64 * STEP };
                let y = y0 + j as f64 * STEP;
                let rect = [x - ex, y - ey, x + ex, y + ey];
                let used = ctx.surface_use.get(&host).and_then(|u| u.get(si));
                if used.is_some_and(|u| u.iter().any(|r| rects_overlap(r, &rect, SURFACE_GAP))) {
                    continue;
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
                ctx.commit(idx, spot, Support::Object { object: host_name, surface: surf.name.clone() });
                let nsurf = ctx.input.objects[host].asset.surfaces.len();
                ctx.surface_use.entry(host).or_insert_with(|| vec![Vec::new(); nsurf])[si].push(rect);
                return true;
            }
        }
    }
    false
}

fn rects_overlap(a: &[f64; 4], b: &[f64; 4], gap: f64) -> bool {
    a[0] < b[2] + gap && b[0] < a[2] + gap && a[1] < b[3] + gap && b[1] < a[3] + gap
}
