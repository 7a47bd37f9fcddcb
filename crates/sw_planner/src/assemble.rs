//! From the scan's draft to a validated [`ScenePlan`]: defaults, counts, proxies, robot
//! models, and the honest account of what was approximated or not understood.

use std::collections::BTreeMap;

use sw_plan::{
    Approximation, Dims, Mount, NotUnderstood, ObjectPlan, ProxyPlan, Relation, RelationKind, RobotPlan, RoomKind,
    RoomPlan, ScenePlan, SizeHint, SizeWord, Wall,
};

use crate::PlannerError;
use crate::parse::{CountRule, Draft, GroupDraft};
use crate::priors::prior_for;

/// Count used for a plural with no number ("boxes on the shelf").
const DEFAULT_PLURAL_COUNT: u32 = 4;
/// The largest count of one group the planner passes on.
const MAX_COUNT: u32 = 2000;
/// The largest number of objects in one scene.
const MAX_TOTAL: u32 = 2000;
/// Room sides are clamped into this range, m.
const ROOM_SIDE: (f64, f64) = (1.0, 300.0);
const ROOM_HEIGHT: (f64, f64) = (2.0, 30.0);

pub(crate) fn assemble(prompt: &str, d: Draft, leftovers: Vec<String>) -> Result<ScenePlan, PlannerError> {
    if d.room.is_none() && !d.room_word && d.groups.is_empty() && d.robots.is_empty() {
        return Err(PlannerError::NothingUnderstood);
    }
    let mut approximated = d.approximated.clone();

    // ---- room
    let kind = match &d.room {
        Some((k, _)) => *k,
        None if d.room_word => RoomKind::Room,
        None => {
            let k = infer_room(&d);
            approximated.push(Approximation {
                text: "(no room named)".into(),
                became: k.name().into(),
                reason: "inferred from the objects requested".into(),
            });
            k
        }
    };
    for other in &d.other_rooms {
        approximated.push(Approximation {
            text: other.clone(),
            became: "ignored".into(),
            reason: format!("a scene is one room; used the first room named ({})", kind.name()),
        });
    }
    let mut size = kind.default_size();
    if d.aisle && d.room_dims.is_none() && kind == RoomKind::Warehouse {
        size = Dims::new(16.0, 7.0, 6.0);
    }
    let size_fixed = d.room_dims.is_some();
    if !size_fixed && !d.room_sizes.is_empty() {
        // "a small room", "a huge warehouse": scale the kind's default floor.
        let f: f64 = d
            .room_sizes
            .iter()
            .map(|w| match w {
                SizeWord::Tiny => 0.5,
                SizeWord::Small | SizeWord::Narrow | SizeWord::Short => 0.7,
                SizeWord::Large | SizeWord::Wide | SizeWord::Long => 1.5,
                SizeWord::Huge => 2.2,
                SizeWord::Tall => 1.0,
            })
            .product();
        size.width = ((size.width * f).max(2.0) * 10.0).round() / 10.0;
        size.depth = ((size.depth * f).max(2.0) * 10.0).round() / 10.0;
        if d.room_sizes.contains(&SizeWord::Tall) || d.room_sizes.contains(&SizeWord::Huge) {
            size.height = (size.height * 1.4 * 10.0).round() / 10.0;
        }
    }
    if let Some((dims, text)) = &d.room_dims {
        size.width = dims[0];
        size.depth = dims.get(1).copied().unwrap_or(dims[0]);
        if let Some(h) = dims.get(2) {
            size.height = *h;
        }
        for (name, v, (lo, hi)) in [("width", &mut size.width, ROOM_SIDE), ("depth", &mut size.depth, ROOM_SIDE)] {
            clamp_noted(name, v, lo, hi, text, &mut approximated);
        }
    }
    if let Some((h, text)) = &d.room_height {
        size.height = *h;
        let _ = text;
    }
    let height_text =
        d.room_height.as_ref().map(|(_, t)| t.clone()).or_else(|| d.room_dims.as_ref().map(|(_, t)| t.clone()));
    clamp_noted(
        "height",
        &mut size.height,
        ROOM_HEIGHT.0,
        ROOM_HEIGHT.1,
        height_text.as_deref().unwrap_or("room height"),
        &mut approximated,
    );

    let mut plan = ScenePlan::new(prompt, RoomPlan { kind, size, size_fixed, door: Wall::South });

    // ---- objects
    let on_targets: BTreeMap<&str, bool> = d
        .relations
        .iter()
        .filter(|(_, k)| matches!(k, RelationKind::On { .. }))
        .map(|(s, _)| (s.as_str(), true))
        .collect();
    let mut dropped = Vec::new();
    // Counts, hosts before the groups whose count follows theirs ("each with").
    let mut counts: BTreeMap<String, u32> = BTreeMap::new();
    let mut order: Vec<&GroupDraft> = Vec::new();
    let mut waiting: Vec<&GroupDraft> = d.groups.iter().collect();
    while !waiting.is_empty() {
        let before = waiting.len();
        waiting.retain(|g| {
            let host = match &g.count_rule {
                Some(CountRule::EachOf { host, .. } | CountRule::Fill { host, .. }) => Some(host),
                None => None,
            };
            let ready = host.is_none_or(|h| order.iter().any(|o| &o.id == h) || !d.groups.iter().any(|x| &x.id == h));
            if ready {
                order.push(g);
            }
            !ready
        });
        if waiting.len() == before {
            order.append(&mut waiting);
        }
    }
    // The scene's bound is applied in the same order, hosts first: a host keeps room for
    // what is counted per each of it ("a stool at each bench, 99999999 benches" is as many
    // benches as leave a stool for each), and the things counted per host follow from the
    // hosts kept.
    let mut resolved_counts: BTreeMap<String, Option<u32>> = BTreeMap::new();
    let mut total: u32 = 0;
    for g in &order {
        let per_each: f64 = d
            .groups
            .iter()
            .filter_map(|x| match &x.count_rule {
                Some(CountRule::EachOf { host, per }) if *host == g.id && per.is_finite() && *per > 0.0 => Some(*per),
                _ => None,
            })
            .sum();
        let c = group_count(g, &d, &counts, &mut approximated)
            .and_then(|c| fit_hosts(c, per_each, total, &g.phrase, &mut approximated))
            .and_then(|c| cap(c, total, MAX_TOTAL, "objects", &g.phrase, &mut approximated));
        if let Some(c) = c {
            counts.insert(g.id.clone(), c);
            total += c;
        }
        resolved_counts.insert(g.id.clone(), c);
    }
    for g in &d.groups {
        let Some(count) = resolved_counts.get(&g.id).copied().flatten() else {
            dropped.push(g.id.clone());
            continue;
        };
        let hint = SizeHint { words: g.sizes.clone(), explicit: g.explicit };
        size_note(g, &mut approximated);
        let (category, proxy) = match g.category {
            Some(c) => (c.to_string(), None),
            None => {
                (String::from("proxy"), Some(proxy_for(g, on_targets.contains_key(g.id.as_str()), &mut approximated)))
            }
        };
        plan.objects.push(ObjectPlan {
            id: g.id.clone(),
            category,
            phrase: g.phrase.clone(),
            count,
            color: g.color.clone(),
            size: hint,
            proxy,
        });
    }

    // ---- relations
    for (subject, kind) in &d.relations {
        if dropped.contains(subject) || kind.targets().iter().any(|t| dropped.iter().any(|x| x == t)) {
            continue;
        }
        // A stack's layers and columns, as the prompt counted them.
        let kind = &match kind {
            RelationKind::Stacked { .. } => {
                let g = d.groups.iter().find(|g| &g.id == subject);
                let whole = |v: Option<f64>| v.filter(|v| v.is_finite() && *v >= 1.0).map(|v| v.round() as u32);
                let stacks = whole(g.and_then(|g| g.stacks)).filter(|s| *s > 1);
                RelationKind::Stacked { n: whole(g.and_then(|g| g.layers)), stacks }
            }
            k => k.clone(),
        };
        plan.relations.push(Relation { subject: subject.clone(), kind: kind.clone() });
    }
    if d.aisle {
        // An aisle is storage on both sides of it, facing across.
        let storage: Vec<String> = plan
            .objects
            .iter()
            .filter(|o| sw_catalog::find(&o.category).is_some_and(|c| c.has_tag("storage") && c.has_tag("tall")))
            .map(|o| o.id.clone())
            .collect();
        for id in storage {
            let placed = plan.relations.iter().any(|r| {
                r.subject == id
                    && !matches!(
                        r.kind,
                        RelationKind::On { .. } | RelationKind::FullOf { .. } | RelationKind::Loaded { .. }
                    )
            });
            if !placed {
                plan.relations.push(Relation { subject: id, kind: RelationKind::FacingEachOther });
            }
        }
    }
    screens_are_partitions(&mut plan, &mut approximated);

    // ---- robots
    let mut robot_ids: BTreeMap<String, u32> = BTreeMap::new();
    let mut robot_id_of: BTreeMap<usize, String> = BTreeMap::new();
    for (ri, r) in d.robots.iter().enumerate() {
        let Some(count) = resolve_count(r.count, r.plural, &r.phrase, &mut approximated) else {
            continue;
        };
        let robots_so_far: u32 = plan.robots.iter().map(|x| x.count).sum();
        let Some(count) = cap(count, robots_so_far, sw_plan::MAX_ROBOTS, "robots", &r.phrase, &mut approximated) else {
            continue;
        };
        let found = sw_robots::find(r.word.wants);
        let def = found.unwrap_or_else(|| sw_robots::default_of(r.word.kind));
        if found.is_some() && def.name != r.word.wants {
            // Registered under an alias (a pack model standing for the name).
            approximated.push(Approximation {
                text: r.phrase.clone(),
                became: def.name.into(),
                reason: format!("read as the {}", def.display),
            });
        } else if def.name != r.word.wants {
            approximated.push(Approximation {
                text: r.phrase.clone(),
                became: def.name.into(),
                reason: format!(
                    "'{}' is not in the robot registry yet; used the built-in {}",
                    r.word.wants, def.display
                ),
            });
        } else if !r.word.exact {
            approximated.push(Approximation {
                text: r.phrase.clone(),
                became: def.name.into(),
                reason: format!("read as the {}", def.display),
            });
        }
        let n = robot_ids.entry(def.name.to_string()).or_insert(0);
        *n += 1;
        let id = if *n == 1 { def.name.to_string() } else { format!("{}_group{}", def.name, n) };
        let mount = match &r.mount {
            Mount::OnSurface { target } if dropped.contains(target) => Mount::Auto,
            m => m.clone(),
        };
        if def.kind != sw_robots::RobotKind::Arm && !matches!(mount, Mount::Auto | Mount::Floor) {
            approximated.push(Approximation {
                text: r.phrase.clone(),
                became: "on the floor".into(),
                reason: "mobile bases drive on the floor".into(),
            });
        }
        let mount = if def.kind == sw_robots::RobotKind::Arm { mount } else { Mount::Floor };
        let near = r.near.clone().filter(|t| !dropped.contains(t) && !t.starts_with('@'));
        robot_id_of.insert(ri, id.clone());
        // An arm on or at its work reaches it.
        if def.kind == sw_robots::RobotKind::Arm {
            let mut work: Vec<String> = Vec::new();
            if let Mount::OnSurface { target } = &mount {
                work.push(target.clone());
            }
            if let Some(n) = &near
                && !work.contains(n)
            {
                work.push(n.clone());
            }
            for t in work {
                plan.relations.push(Relation { subject: id.clone(), kind: RelationKind::Reach { target: t } });
            }
        }
        plan.robots.push(RobotPlan { id, model: def.name.into(), phrase: r.phrase.clone(), count, mount, near });
    }
    // Relations of robots, and relations to robots, by robot id.
    for (ri, kind) in &d.robot_relations {
        let Some(id) = robot_id_of.get(ri) else { continue };
        plan.relations.push(Relation { subject: id.clone(), kind: kind.clone() });
        // An arm between two things works on both ("a robot arm between the mixer and
        // the blender", "a cobot between two conveyors").
        let arm = plan
            .robots
            .iter()
            .any(|r| &r.id == id && sw_robots::find(&r.model).is_some_and(|x| x.kind == sw_robots::RobotKind::Arm));
        if let RelationKind::Between { first, second } = kind
            && arm
        {
            for t in [first, second] {
                let r = Relation { subject: id.clone(), kind: RelationKind::Reach { target: t.clone() } };
                if !t.starts_with('@') && !plan.relations.contains(&r) {
                    plan.relations.push(r);
                }
            }
        }
    }
    let robot_ref = |t: &str| -> Option<String> {
        match t.strip_prefix("@robot:") {
            Some(n) => n.parse::<usize>().ok().and_then(|n| robot_id_of.get(&n).cloned()),
            None => Some(t.to_string()),
        }
    };
    let mut resolved = Vec::new();
    for r in std::mem::take(&mut plan.relations) {
        let kind = match r.kind {
            RelationKind::Between { first, second } => match (robot_ref(&first), robot_ref(&second)) {
                (Some(first), Some(second)) => RelationKind::Between { first, second },
                _ => continue,
            },
            k => {
                let Some(t) = k.targets().first().map(|t| t.to_string()) else {
                    resolved.push(Relation { subject: r.subject, kind: k });
                    continue;
                };
                let Some(t2) = robot_ref(&t) else { continue };
                with_target(k, t2)
            }
        };
        if dropped.contains(&r.subject) || kind.targets().contains(&r.subject.as_str()) {
            continue;
        }
        let entry = Relation { subject: r.subject, kind };
        if !resolved.contains(&entry) {
            resolved.push(entry);
        }
    }
    plan.relations = resolved;
    shared_support(&mut plan, &d.on_floor);
    size_for_load(&mut plan, &mut approximated);

    plan.understanding.approximated = approximated;
    plan.understanding.not_understood = leftovers
        .into_iter()
        .map(|text| NotUnderstood {
            text,
            reason: "not a room, object, robot, size or relation the offline planner knows".into(),
        })
        .collect();
    drop_invalid_relations(&mut plan);
    plan.validate().map_err(|e| PlannerError::InvalidSize(e.to_string()))?;
    Ok(plan)
}

/// A category's footprint on the floor (its `width` × `depth` defaults, m), if it has one.
fn footprint(cat: &str) -> Option<(f64, f64, f64)> {
    let c = sw_catalog::find(cat)?;
    let w = c.param("width")?;
    let d = c.param("depth").or_else(|| c.param("width"))?;
    Some((w.default, d.default, w.max))
}

/// A surface said to carry many things is made long enough to carry them, within its
/// category's range ("a table with four seedling trays" is no 1.2 m table): on each host,
/// every kind of item stands in rows across the top's depth (turned whichever way takes
/// less length), with a gap between items and a margin at the edges; the kinds side by
/// side. That length sets the host's when none was stated. The report says the size used
/// and why.
fn size_for_load(plan: &mut ScenePlan, notes: &mut Vec<Approximation>) {
    /// Clear gap between items, and margin at each edge of the top (m).
    const GAP: f64 = 0.05;
    const MARGIN: f64 = 0.05;
    // (item width, item depth, count) per host.
    let mut load: BTreeMap<String, Vec<(f64, f64, u32)>> = BTreeMap::new();
    for r in &plan.relations {
        let RelationKind::On { target } = &r.kind else { continue };
        let Some(item) = plan.object(&r.subject) else { continue };
        let Some((mut w, mut d, _)) = footprint(&item.category) else { continue };
        // "six small boxes": the size words scale the footprint as they will the asset.
        for word in &item.size.words {
            let [fw, fd, _] = word.factors();
            w *= fw;
            d *= fd;
        }
        load.entry(target.clone()).or_default().push((w, d, item.count));
    }
    for (host, items) in load {
        let Some(h) = plan.objects.iter_mut().find(|o| o.id == host) else { continue };
        let e = &h.size.explicit;
        if e.length.is_some() || e.width.is_some() || e.diameter.is_some() || !h.size.words.is_empty() {
            continue;
        }
        let Some((w, d, w_max)) = footprint(&h.category) else { continue };
        let hosts = f64::from(h.count.max(1));
        let usable = d - 2.0 * MARGIN;
        let mut needed = 2.0 * MARGIN - GAP;
        let mut count = 0.0;
        for (iw, id, n) in &items {
            let each = (f64::from(*n) / hosts).ceil();
            count += each;
            let run = |along: f64, across: f64| {
                let rows = ((usable + GAP) / (across + GAP)).floor().max(1.0);
                (each / rows).ceil() * (along + GAP)
            };
            needed += run(*iw, *id).min(run(*id, *iw));
        }
        if needed <= w || w_max <= w {
            continue;
        }
        let length = ((needed.min(w_max)) * 20.0).ceil() / 20.0;
        h.size.explicit.length = Some(length.min(w_max));
        let what = h.category.replace('_', " ");
        let reason = if needed > w_max {
            format!(
                "{} things on it need about {needed:.2} m of top; made {w_max:.2} m long, the longest {what} (the items may crowd)",
                trim_count(count)
            )
        } else {
            format!(
                "{} things on it need about {needed:.2} m of top; made {length:.2} m long (a {what} is {w:.2} m, up to {w_max:.2} m)",
                trim_count(count)
            )
        };
        notes.push(Approximation {
            text: h.phrase.clone(),
            became: format!("{:.2} m long", length.min(w_max)),
            reason,
        });
    }
}

fn trim_count(v: f64) -> String {
    if (v - v.round()).abs() < 1e-9 { format!("{}", v.round() as i64) } else { format!("{v:.1}") }
}

/// Small things placed by something that rests on a surface rest on it too ("a toaster
/// on the counter and a plate next to it", "a hob set into the worktop with a kettle
/// beside it", "a Panda on the table, three blocks in front of the Panda"), unless said
/// to rest elsewhere; and an arm reaches the small things placed by it.
fn shared_support(plan: &mut ScenePlan, on_floor: &[String]) {
    let arms: Vec<(String, Option<String>)> = plan
        .robots
        .iter()
        .filter(|r| sw_robots::find(&r.model).is_some_and(|d| d.kind == sw_robots::RobotKind::Arm))
        .map(|r| {
            // The surface it stands on, else the work surface it stands at ("two arms on
            // opposite sides of the bench with bins between them": the bins are on the bench).
            let at_surface = |id: &String| {
                plan.objects.iter().find(|o| &o.id == id).and_then(|o| sw_catalog::find(&o.category)).is_some_and(|c| {
                    c.has_tag("surface") && !c.has_tag("seating") && c.placement != sw_catalog::PlacementKind::OnSurface
                })
            };
            let surface = match &r.mount {
                Mount::OnSurface { target } if !target.starts_with('@') => Some(target.clone()),
                Mount::Auto => r
                    .near
                    .clone()
                    .filter(at_surface)
                    .or_else(|| {
                        plan.relations.iter().find_map(|x| match &x.kind {
                            RelationKind::OnEachSideOf { target } if x.subject == r.id && at_surface(target) => {
                                Some(target.clone())
                            }
                            _ => None,
                        })
                    })
                    // Nothing said of where it stands, and one work surface in the scene ("a
                    // table, two cubes, a Panda"): it works there.
                    .or_else(|| {
                        let mut work = plan.objects.iter().filter(|o| at_surface(&o.id));
                        match (work.next(), work.next(), plan.relations.iter().any(|x| x.subject == r.id)) {
                            (Some(o), None, false) => Some(o.id.clone()),
                            _ => None,
                        }
                    }),
                _ => None,
            };
            (r.id.clone(), surface)
        })
        .collect();
    let small: Vec<String> = plan
        .objects
        .iter()
        .filter(|o| match &o.proxy {
            Some(p) => p.movable,
            None => sw_catalog::find(&o.category).is_some_and(|c| c.placement == sw_catalog::PlacementKind::OnSurface),
        })
        .map(|o| o.id.clone())
        .collect();
    let is_object = |id: &str| plan.objects.iter().any(|o| o.id == id);
    // The targets a subject is placed by.
    let placed_by = |r: &Relation| -> Vec<String> {
        match &r.kind {
            RelationKind::NextTo { target }
            | RelationKind::Near { target }
            | RelationKind::InFrontOf { target }
            | RelationKind::Behind { target }
            | RelationKind::Around { target }
            | RelationKind::OnEachSideOf { target } => vec![target.clone()],
            RelationKind::Between { first, second } if first == second => vec![first.clone()],
            RelationKind::Between { first, second } => vec![first.clone(), second.clone()],
            _ => Vec::new(),
        }
    };
    let support = |rels: &[Relation], id: &str| -> Option<String> {
        if let Some((_, s)) = arms.iter().find(|(a, _)| a == id) {
            return s.clone();
        }
        rels.iter().find_map(|r| match &r.kind {
            RelationKind::On { target } | RelationKind::SetInto { target } if r.subject == id && is_object(target) => {
                Some(target.clone())
            }
            _ => None,
        })
    };
    let rests = |rels: &[Relation], id: &str| {
        rels.iter().any(|r| {
            r.subject == id
                && matches!(
                    r.kind,
                    RelationKind::On { .. }
                        | RelationKind::Inside { .. }
                        | RelationKind::SetInto { .. }
                        | RelationKind::Under { .. }
                        | RelationKind::Loaded { .. }
                        | RelationKind::Stacked { .. }
                        | RelationKind::Leaning { .. }
                        | RelationKind::AgainstWall { .. }
                )
        })
    };
    // Chains ("a kettle on the worktop, a mug by the kettle, a spoon by the mug") settle in
    // as many rounds as there are small groups.
    for _ in 0..small.len() {
        let mut added = Vec::new();
        for id in &small {
            if rests(&plan.relations, id) || on_floor.contains(id) {
                continue;
            }
            // All the things it is placed by share one surface.
            let targets: Vec<String> = plan.relations.iter().filter(|r| &r.subject == id).flat_map(placed_by).collect();
            let surfaces: Vec<Option<String>> = targets.iter().map(|t| support(&plan.relations, t)).collect();
            if let Some(Some(s)) = surfaces.first()
                && surfaces.iter().all(|x| x.as_ref() == Some(s))
                && s != id
            {
                added.push(Relation { subject: id.clone(), kind: RelationKind::On { target: s.clone() } });
            }
        }
        if added.is_empty() {
            break;
        }
        plan.relations.extend(added);
    }
    // Small things nothing places, in a scene whose arms all work at one surface ("a
    // table, two cubes, a Panda on it"): the arms' work, on that surface.
    let mut surfaces: Vec<&String> = arms.iter().filter_map(|(_, s)| s.as_ref()).collect();
    surfaces.dedup();
    let mut loose_work = Vec::new();
    if let ([s], true) = (surfaces.as_slice(), arms.iter().all(|(_, x)| x.is_some())) {
        for id in &small {
            let said = plan.relations.iter().any(|r| &r.subject == id) || on_floor.contains(id);
            if !said && id != *s {
                plan.relations.push(Relation { subject: id.clone(), kind: RelationKind::On { target: (*s).clone() } });
                loose_work.push(id.clone());
            }
        }
    }
    let mut reach = Vec::new();
    for (arm, surface) in &arms {
        // Nothing said of the arm, one work surface ("a cabinet on a table …. Franka."): it
        // works there.
        if let Some(s) = surface
            && !plan.relations.iter().any(|x| &x.subject == arm)
        {
            reach.push(Relation { subject: arm.clone(), kind: RelationKind::Reach { target: s.clone() } });
        }
        for id in &loose_work {
            reach.push(Relation { subject: arm.clone(), kind: RelationKind::Reach { target: id.clone() } });
        }
        for id in &small {
            // What stands on the floor beside an arm is kept beside it, not hauled up to
            // its shoulder's reach.
            let resting = plan.relations.iter().any(|r| &r.subject == id && matches!(r.kind, RelationKind::On { .. }));
            let by_arm = resting && plan.relations.iter().any(|r| &r.subject == id && placed_by(r).contains(arm));
            let r = Relation { subject: arm.clone(), kind: RelationKind::Reach { target: id.clone() } };
            if by_arm && !plan.relations.contains(&r) && !reach.contains(&r) {
                reach.push(r);
            }
        }
    }
    plan.relations.extend(reach);
}

/// A relation the contract cannot state (a stack of robots, the end of a robot's row) is
/// left out and said so, rather than refusing the whole prompt.
fn drop_invalid_relations(plan: &mut ScenePlan) {
    let Err(errors) = plan.validate() else { return };
    let mut bad: Vec<(usize, String)> = errors
        .0
        .iter()
        .filter_map(|e| {
            let i = e.path.strip_prefix("relations[")?.split(']').next()?.parse::<usize>().ok()?;
            Some((i, e.message.clone()))
        })
        .collect();
    bad.sort_by_key(|(i, _)| std::cmp::Reverse(*i));
    bad.dedup_by_key(|(i, _)| *i);
    for (i, why) in bad {
        if i < plan.relations.len() {
            let r = plan.relations.remove(i);
            let text = plan.describe(&r);
            plan.understanding.approximated.push(Approximation { text, became: "left out".into(), reason: why });
        }
    }
}

/// The same relation pointing at `target` (every kind listed, so that a new kind with a
/// target cannot slip through unresolved).
fn with_target(k: RelationKind, target: String) -> RelationKind {
    match k {
        RelationKind::On { .. } => RelationKind::On { target },
        RelationKind::Under { .. } => RelationKind::Under { target },
        RelationKind::NextTo { .. } => RelationKind::NextTo { target },
        RelationKind::Near { .. } => RelationKind::Near { target },
        RelationKind::InFrontOf { .. } => RelationKind::InFrontOf { target },
        RelationKind::Behind { .. } => RelationKind::Behind { target },
        RelationKind::Around { .. } => RelationKind::Around { target },
        RelationKind::AtEndOfRow { .. } => RelationKind::AtEndOfRow { target },
        RelationKind::Loaded { .. } => RelationKind::Loaded { target },
        RelationKind::FullOf { .. } => RelationKind::FullOf { target },
        RelationKind::EachWith { .. } => RelationKind::EachWith { target },
        RelationKind::Reach { .. } => RelationKind::Reach { target },
        RelationKind::Inside { .. } => RelationKind::Inside { target },
        RelationKind::SetInto { .. } => RelationKind::SetInto { target },
        RelationKind::AtEndOf { end, .. } => RelationKind::AtEndOf { target, end },
        RelationKind::OnEdgeOf { .. } => RelationKind::OnEdgeOf { target },
        RelationKind::OnEachSideOf { .. } => RelationKind::OnEachSideOf { target },
        RelationKind::Facing { .. } => RelationKind::Facing { target },
        k @ (RelationKind::Between { .. }
        | RelationKind::AgainstWall { .. }
        | RelationKind::OnTwoWalls
        | RelationKind::InRow
        | RelationKind::InRows { .. }
        | RelationKind::InAisles
        | RelationKind::FacingEachOther
        | RelationKind::AtEnd { .. }
        | RelationKind::NearDoor
        | RelationKind::InCorner { .. }
        | RelationKind::InCenter
        | RelationKind::Stacked { .. }
        | RelationKind::Leaning { .. }
        | RelationKind::OnOppositeWalls { .. }
        | RelationKind::InCorners
        | RelationKind::BackToBack) => k,
    }
}

/// A group's count: its own, or what its count rule makes of its host's.
fn group_count(
    g: &GroupDraft,
    d: &Draft,
    counts: &BTreeMap<String, u32>,
    notes: &mut Vec<Approximation>,
) -> Option<u32> {
    // A host whose own count is unknown (it was left out): the group keeps the count its
    // own words give, and says why, never vanishing without a word.
    let host_count = |host: &str, notes: &mut Vec<Approximation>| {
        let n = counts.get(host).copied();
        if n.is_none() {
            notes.push(Approximation {
                text: g.phrase.clone(),
                became: "counted on its own".into(),
                reason: format!(
                    "it was counted per '{}', which is not in the scene",
                    d.groups.iter().find(|x| x.id == host).map_or(host, |x| x.phrase.as_str())
                ),
            });
        }
        n
    };
    match &g.count_rule {
        Some(CountRule::EachOf { host, per }) => {
            let Some(hosts) = host_count(host, notes) else {
                return resolve_count(g.count, g.plural, &g.phrase, notes);
            };
            let n = (f64::from(hosts) * per).round().clamp(1.0, f64::from(MAX_COUNT)) as u32;
            Some(n)
        }
        Some(CountRule::Fill { host, levels }) if g.count.is_none() => {
            let Some(hosts) = host_count(host, notes) else {
                return resolve_count(g.count, g.plural, &g.phrase, notes);
            };
            let host_cat = d.groups.iter().find(|x| &x.id == host).and_then(|x| x.category).and_then(sw_catalog::find);
            // Two on every level of every shelf (as many levels as the category's default
            // has; the forge keeps that number); three on every pallet.
            let per = if *levels { 2.0 * host_cat.map_or(3, support_levels) as f64 } else { 3.0 };
            let n = (f64::from(hosts) * per).clamp(1.0, f64::from(MAX_COUNT)) as u32;
            notes.push(Approximation {
                text: g.phrase.clone(),
                became: format!("{n}"),
                reason: format!("no count was given; {} on each", if *levels { "two per level" } else { "three" }),
            });
            Some(n)
        }
        _ => resolve_count(g.count, g.plural, &g.phrase, notes),
    }
}

/// How many support surfaces a category's default asset has (its levels).
fn support_levels(c: &sw_catalog::Category) -> usize {
    let mut req = sw_catalog::AssetRequest::new(c.name, 0);
    if let Some(p) = c.param("levels") {
        req.overrides.push(("levels".into(), p.default));
    }
    sw_catalog::generate(&req).map_or(3, |a| a.surfaces.len().max(1))
}

/// "screens" around something, or in a row, or against a wall, are partitions (welding
/// screens), not computer monitors.
fn screens_are_partitions(plan: &mut ScenePlan, notes: &mut Vec<Approximation>) {
    let floor_words = |k: &RelationKind| {
        !matches!(k, RelationKind::On { .. } | RelationKind::Loaded { .. } | RelationKind::FullOf { .. })
    };
    let ids: Vec<String> = plan
        .objects
        .iter()
        .filter(|o| o.category == "monitor" && o.phrase.to_lowercase().contains("screen"))
        .filter(|o| plan.relations.iter().any(|r| r.subject == o.id && floor_words(&r.kind)))
        .filter(|o| !plan.relations.iter().any(|r| r.subject == o.id && matches!(r.kind, RelationKind::On { .. })))
        .map(|o| o.id.clone())
        .collect();
    for id in ids {
        if let Some(o) = plan.objects.iter_mut().find(|o| o.id == id) {
            o.category = "welding_screen".into();
            notes.push(Approximation {
                text: o.phrase.clone(),
                became: "welding_screen".into(),
                reason: "screens that stand on the floor are partition screens".into(),
            });
        }
    }
}

/// Says what size words do to a group: the factors on its usual size (width, depth,
/// height), which the catalog keeps within the category's range.
fn size_note(g: &GroupDraft, notes: &mut Vec<Approximation>) {
    if g.sizes.is_empty() {
        return;
    }
    let mut f = [1.0f64; 3];
    for w in &g.sizes {
        for (a, b) in f.iter_mut().zip(w.factors()) {
            *a *= b;
        }
    }
    let words: Vec<&str> = g.sizes.iter().map(|w| size_word_name(*w)).collect();
    let what = g.category.map_or_else(|| g.label.clone(), |c| c.replace('_', " "));
    notes.push(Approximation {
        text: g.phrase.clone(),
        became: format!("× {} wide, × {} deep, × {} tall", trim(f[0]), trim(f[1]), trim(f[2])),
        reason: format!("'{}': the usual {what} scaled, kept within the sizes a {what} comes in", words.join(" ")),
    });
}

fn size_word_name(w: SizeWord) -> &'static str {
    match w {
        SizeWord::Tiny => "tiny",
        SizeWord::Small => "small",
        SizeWord::Large => "large",
        SizeWord::Huge => "huge",
        SizeWord::Tall => "tall",
        SizeWord::Short => "short",
        SizeWord::Long => "long",
        SizeWord::Wide => "wide",
        SizeWord::Narrow => "narrow",
    }
}

fn resolve_count(count: Option<f64>, plural: bool, phrase: &str, notes: &mut Vec<Approximation>) -> Option<u32> {
    let n = match count {
        Some(c) if !c.is_finite() => 1.0,
        Some(c) => c,
        None if plural => {
            notes.push(Approximation {
                text: phrase.to_string(),
                became: format!("{DEFAULT_PLURAL_COUNT}"),
                reason: "no count was given for a plural".into(),
            });
            f64::from(DEFAULT_PLURAL_COUNT)
        }
        None => 1.0,
    };
    if n < 0.5 {
        // A retraction already said why.
        if !notes.iter().any(|a| a.text == phrase && a.became == "left out") {
            notes.push(Approximation {
                text: phrase.to_string(),
                became: "left out".into(),
                reason: "the count is zero".into(),
            });
        }
        return None;
    }
    if n.fract() != 0.0 {
        notes.push(Approximation {
            text: phrase.to_string(),
            became: format!("{}", n.round().max(1.0)),
            reason: "counts are whole numbers".into(),
        });
    }
    let rounded = n.round().max(1.0);
    if rounded > f64::from(MAX_COUNT) {
        notes.push(Approximation {
            text: phrase.to_string(),
            became: format!("{MAX_COUNT}"),
            reason: format!("at most {MAX_COUNT} objects of one kind per scene"),
        });
        return Some(MAX_COUNT);
    }
    Some(rounded as u32)
}

/// Keeps a scene's total of `what` at `max`: the count that still fits (noted when cut),
/// or `None` when nothing does.
fn cap(count: u32, so_far: u32, max: u32, what: &str, phrase: &str, notes: &mut Vec<Approximation>) -> Option<u32> {
    if so_far + count <= max {
        return Some(count);
    }
    let allowed = max.saturating_sub(so_far);
    notes.push(Approximation {
        text: phrase.to_string(),
        became: if allowed == 0 { "left out".into() } else { format!("{allowed}") },
        reason: format!("at most {max} {what} per scene"),
    });
    (allowed > 0).then_some(allowed)
}

/// How many of a host fit in the scene's bound when each keeps `per_each` things counted
/// per host ("a stool at each bench"): hosts × (1 + per_each) within what is left, noted
/// when cut. `None` when not one fits.
fn fit_hosts(count: u32, per_each: f64, so_far: u32, phrase: &str, notes: &mut Vec<Approximation>) -> Option<u32> {
    if per_each <= 0.0 {
        return Some(count);
    }
    let left = f64::from(MAX_TOTAL.saturating_sub(so_far));
    let fits = (left / (1.0 + per_each)).floor().max(0.0) as u32;
    if count <= fits {
        return Some(count);
    }
    notes.push(Approximation {
        text: phrase.to_string(),
        became: if fits == 0 { "left out".into() } else { format!("{fits}") },
        reason: format!(
            "at most {MAX_TOTAL} objects per scene, counting what each of them has ({per_each} per one); the hosts were bounded first"
        ),
    });
    (fits > 0).then_some(fits)
}

fn proxy_for(g: &GroupDraft, resting: bool, notes: &mut Vec<Approximation>) -> ProxyPlan {
    let prior = prior_for(&g.label, resting);
    let mut size = prior.size;
    for w in &g.sizes {
        let f = w.factors();
        for i in 0..3 {
            size[i] *= f[i];
        }
    }
    if let Some(w) = g.explicit.width {
        size[0] = w;
    }
    if let Some(v) = g.explicit.depth {
        size[1] = v;
    }
    if let Some(h) = g.explicit.height {
        size[2] = h;
    }
    let clamped = size.map(|v| v.clamp(0.02, 20.0));
    if clamped != size {
        notes.push(Approximation {
            text: g.phrase.clone(),
            became: format!("{:.2} × {:.2} × {:.2} m", clamped[0], clamped[1], clamped[2]),
            reason: "proxy sizes are kept between 2 cm and 20 m".into(),
        });
    }
    notes.push(Approximation {
        text: g.phrase.clone(),
        became: format!("labelled proxy '{}'", g.label),
        reason: format!(
            "no catalog asset for '{}'; a {:.2} × {:.2} × {:.2} m box sized as a {}",
            g.label, clamped[0], clamped[1], clamped[2], prior.name
        ),
    });
    ProxyPlan {
        label: g.label.clone(),
        prior: prior.name.into(),
        size: Dims::new(clamped[0], clamped[1], clamped[2]),
        movable: prior.movable,
    }
}

fn clamp_noted(name: &str, v: &mut f64, lo: f64, hi: f64, text: &str, notes: &mut Vec<Approximation>) {
    let c = v.clamp(lo, hi);
    if c != *v {
        notes.push(Approximation {
            text: text.to_string(),
            became: format!("room {name} {c} m"),
            reason: format!("room {name} {} m is outside {lo}–{hi} m", trim(*v)),
        });
        *v = c;
    }
}

fn trim(v: f64) -> String {
    let s = format!("{v:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The room kind the objects suggest: by their catalog tags, tabletop scenes when the
/// scene is an arm and small items.
fn infer_room(d: &Draft) -> RoomKind {
    let mut votes: BTreeMap<RoomKind, u32> = BTreeMap::new();
    let mut small = 0;
    let mut large = 0;
    for g in &d.groups {
        let Some(cat) = g.category.and_then(sw_catalog::find) else {
            continue;
        };
        let n = g.count.unwrap_or(if g.plural { 4.0 } else { 1.0 }).clamp(1.0, 10_000.0) as u32;
        if cat.placement == sw_catalog::PlacementKind::OnSurface {
            small += n;
        } else if cat.has_tag("surface") && cat.has_tag("furniture") {
            large += n;
        } else {
            // Storage, machines and other floor fixtures make it a room, not a tabletop.
            large += 2 * n;
        }
        for (tag, kind) in [
            ("warehouse", RoomKind::Warehouse),
            ("logistics", RoomKind::Warehouse),
            ("storage", RoomKind::StorageRoom),
            ("lab", RoomKind::Lab),
            ("kitchen", RoomKind::Kitchen),
            ("office", RoomKind::Office),
            ("industrial", RoomKind::Workshop),
            ("data_centre", RoomKind::DataCentre),
            ("retail", RoomKind::RetailStore),
            ("garage", RoomKind::Garage),
        ] {
            if cat.has_tag(tag) {
                *votes.entry(kind).or_insert(0) += 1;
            }
        }
    }
    let arms_only = d.robots.iter().all(|r| r.word.kind == sw_robots::RobotKind::Arm);
    if large <= 1 && arms_only && (small > 0 || !d.robots.is_empty()) {
        return RoomKind::Tabletop;
    }
    votes.into_iter().max_by(|a, b| a.1.cmp(&b.1).then(b.0.cmp(&a.0))).map_or(RoomKind::Room, |(k, _)| k)
}
