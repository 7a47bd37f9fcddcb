//! The measured definition of each relation, on the written geometry (see
//! `relations_check` and ARCHITECTURE.md, "Relations"). A group relation holds when it
//! holds for every instance of the subject; a formation (row, rows, aisles, facing
//! rows, stack, ring around) is judged as a whole.

use sw_geom::Aabb;
use sw_plan::{Corner, Relation, RelationKind, ScenePlan, Wall};

use crate::relations_check::{
    CORNER, DOOR, FRONT, FRONT_SIDE, NEAR, NEXT_TO, REST, Thing, Verdict, WALL, Written, center, dot, gap, half_along,
    in_hull, inside, nearest_target, nearest_wall, site_under, wall_gap,
};
use crate::relations_places as places;

pub(crate) fn measure(plan: &ScenePlan, w: &Written, r: &Relation, subjects: &[Thing], v: &mut Verdict) {
    let half = w.half();
    let n = subjects.len();
    let targets_of = |t: &str, v: &mut Verdict| -> Vec<Thing> {
        let ts = w.things(t);
        if ts.is_empty() {
            v.fail(format!("no \"{}\" in the scene", plan.phrase_of(t)));
        }
        ts
    };
    match &r.kind {
        RelationKind::On { target } => {
            let hosts = targets_of(target, v);
            let direct = |s: &Thing| {
                hosts.iter().any(|h| match &s.robot {
                    // A robot's base on the host's top.
                    Some(_) => h.body.sites.iter().any(|site| {
                        (s.body.pos[2] - site.z).abs() <= REST
                            && (site.rect[0]..=site.rect[2]).contains(&s.body.pos[0])
                            && (site.rect[1]..=site.rect[3]).contains(&s.body.pos[1])
                    }),
                    None => site_under(&s.body, &h.body).is_some(),
                })
            };
            // On it, or on one of its own kind that is ("a stack of plates on the counter").
            let mut resting: Vec<bool> = subjects.iter().map(direct).collect();
            loop {
                let before = resting.iter().filter(|x| **x).count();
                for i in 0..subjects.len() {
                    if resting[i] || subjects[i].robot.is_some() {
                        continue;
                    }
                    resting[i] = (0..subjects.len())
                        .any(|j| resting[j] && j != i && stands_on(&subjects[i].body, &subjects[j].body));
                }
                if resting.iter().filter(|x| **x).count() == before {
                    break;
                }
            }
            let on = resting.iter().filter(|x| **x).count();
            v.set("resting", on as f64);
            v.set("count", n as f64);
            if on < n {
                v.fail(format!("{} of {n} rest on it", on));
            }
        }
        RelationKind::Under { target } => {
            let hosts = targets_of(target, v);
            for s in subjects {
                let c = s.body.center();
                let ok = hosts
                    .iter()
                    .any(|h| inside(c, &h.body.bounds) && s.body.bounds.max[2] <= h.body.bounds.max[2] + 1e-6);
                if !ok {
                    v.fail(format!("{} is not under it", s.name));
                }
            }
        }
        RelationKind::AgainstWall { wall } => {
            let mut worst: f64 = 0.0;
            for s in subjects {
                let g = match wall {
                    Some(wl) => wall_gap(half, &s.body.bounds, *wl),
                    None => nearest_wall(half, &s.body.bounds).1,
                };
                worst = worst.max(g);
            }
            v.set("wall_gap_m", worst);
            if worst > WALL {
                v.fail(format!("{worst:.2} m from the wall (at most {WALL} m)"));
            }
        }
        RelationKind::OnTwoWalls => {
            let mut walls: Vec<Wall> = Vec::new();
            let mut worst: f64 = 0.0;
            for s in subjects {
                let (wl, g) = nearest_wall(half, &s.body.bounds);
                worst = worst.max(g);
                if !walls.contains(&wl) {
                    walls.push(wl);
                }
            }
            v.set("walls", walls.len() as f64);
            v.set("wall_gap_m", worst);
            if worst > WALL {
                v.fail(format!("one stands {worst:.2} m from any wall"));
            } else if walls.len() < 2.min(n) {
                v.fail("all on one wall");
            }
        }
        RelationKind::NextTo { target } | RelationKind::Near { target } => {
            let limit = if matches!(r.kind, RelationKind::NextTo { .. }) { NEXT_TO } else { NEAR };
            let ts = targets_of(target, v);
            cluster_near(subjects, &ts, limit, v);
        }
        RelationKind::Around { target } => {
            let ts = targets_of(target, v);
            around(subjects, &ts, v);
        }
        RelationKind::Between { first, second } => {
            let a = targets_of(first, v);
            let b = targets_of(second, v);
            for s in subjects {
                let c = s.body.center();
                let ok = a.iter().any(|x| {
                    b.iter().any(|y| {
                        x.name != y.name
                            && in_hull(&x.body.bounds, &y.body.bounds, c)
                            && !inside(c, &x.body.bounds)
                            && !inside(c, &y.body.bounds)
                    })
                });
                if !ok {
                    v.fail(format!("{} is not between them", s.name));
                }
            }
        }
        RelationKind::InRow => match rows(subjects) {
            Some(rs) if rs.len() == 1 || n < 2 => v.set("rows", 1.0),
            Some(rs) => {
                v.set("rows", rs.len() as f64);
                v.fail(format!("in {} rows, not one", rs.len()));
            }
            None => v.fail("not in straight rows"),
        },
        RelationKind::InRows { n: want, m } => match rows(subjects) {
            Some(rs) => {
                v.set("rows", rs.len() as f64);
                let ok = match want {
                    Some(k) => rs.len() == *k as usize || (*k as usize > n && rs.len() == n),
                    None => rs.len() >= 2 || n < 2,
                };
                if !ok {
                    v.fail(format!("in {} rows", rs.len()));
                }
                if let Some(m) = m {
                    places::rows_of(&rs.iter().map(Vec::len).collect::<Vec<_>>(), *m, v);
                }
            }
            None => v.fail("not in straight parallel rows"),
        },
        RelationKind::InAisles => aisles(subjects, v),
        RelationKind::FacingEachOther => facing(subjects, v),
        RelationKind::InFrontOf { target } | RelationKind::Behind { target } => {
            let sign = if matches!(r.kind, RelationKind::InFrontOf { .. }) { 1.0 } else { -1.0 };
            let ts = targets_of(target, v);
            let mut bodies: Vec<(Aabb, [f64; 2])> = ts.iter().map(|t| (t.body.bounds, t.body.front())).collect();
            if let Some(row) = row_of(&ts) {
                bodies.insert(0, row);
            }
            let each = subjects.iter().all(|s| bodies.iter().any(|(b, f)| in_front(&s.body.bounds, b, *f, sign)));
            let union = subjects.iter().fold(Aabb::EMPTY, |a, s| a.union(&s.body.bounds));
            let whole = bodies.iter().any(|(b, f)| in_front(&union, b, *f, sign));
            if !(each || (n > 1 && whole)) {
                v.fail(if sign > 0.0 { "not in front of its front" } else { "not behind its back" });
            }
        }
        RelationKind::AtEndOfRow { target } => {
            let ts = targets_of(target, v);
            let row = row_of(&ts);
            for s in subjects {
                let ok = match row {
                    Some((b, f)) => {
                        let u = [-f[1], f[0]];
                        let (c, rc) = (s.body.center(), center(&b));
                        let d = [c[0] - rc[0], c[1] - rc[1]];
                        let along = dot(d, u).abs() - half_along(&b, u);
                        let perp = dot(d, f).abs();
                        v.set("beyond_end_m", along);
                        v.set("off_line_m", perp);
                        along > 0.0 && along <= 2.0 && perp <= 1.0
                    }
                    None => ts.iter().any(|t| gap(&s.body.bounds, &t.body.bounds) <= NEXT_TO),
                };
                if !ok {
                    v.fail(format!("{} is not at the end of the row", s.name));
                }
            }
        }
        RelationKind::AtEnd { wall } => {
            let ends: Vec<Wall> = match wall {
                Some(wl) => vec![*wl],
                None if half[0] >= half[1] => vec![Wall::East, Wall::West],
                None => vec![Wall::North, Wall::South],
            };
            let mut worst: f64 = 0.0;
            for s in subjects {
                let c = s.body.center();
                let best = ends
                    .iter()
                    .map(|wl| {
                        let (from, long) = match wl {
                            Wall::North => (half[1] - c[1], 2.0 * half[1]),
                            Wall::South => (c[1] + half[1], 2.0 * half[1]),
                            Wall::East => (half[0] - c[0], 2.0 * half[0]),
                            Wall::West => (c[0] + half[0], 2.0 * half[0]),
                        };
                        from / long
                    })
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max(best);
            }
            v.set("end_fraction", worst);
            if worst > 0.25 {
                v.fail(format!("{:.0} % of the room's length from its end (at most 25 %)", worst * 100.0));
            }
        }
        RelationKind::NearDoor => {
            let d = &w.layout.room.door;
            let p = match d.wall {
                Wall::North => [d.offset, half[1]],
                Wall::South => [d.offset, -half[1]],
                Wall::East => [half[0], d.offset],
                Wall::West => [-half[0], d.offset],
            };
            let worst = subjects
                .iter()
                .map(|s| {
                    let c = s.body.center();
                    (c[0] - p[0]).hypot(c[1] - p[1])
                })
                .fold(0.0, f64::max);
            v.set("door_distance_m", worst);
            if worst > DOOR {
                v.fail(format!("{worst:.2} m from the door (at most {DOOR} m)"));
            }
        }
        RelationKind::InCorner { corner } => {
            let corners = corner.map_or(Corner::ALL.to_vec(), |c| vec![c]);
            for s in subjects {
                let best = corners
                    .iter()
                    .map(|c| {
                        let (a, b) = c.walls();
                        wall_gap(half, &s.body.bounds, a).max(wall_gap(half, &s.body.bounds, b))
                    })
                    .fold(f64::INFINITY, f64::min);
                v.set("corner_gap_m", best);
                if best > CORNER {
                    v.fail(format!("{} is {best:.2} m from the corner's walls", s.name));
                }
            }
        }
        RelationKind::InCenter => {
            let (along_i, across_i) = if half[0] >= half[1] { (0, 1) } else { (1, 0) };
            let (long, short) = (2.0 * half[along_i], 2.0 * half[across_i]);
            for s in subjects {
                let c = s.body.center();
                let (along, across) = (c[along_i].abs() / long, c[across_i].abs() / short);
                v.set("off_centre_line", across);
                if across > 0.2 || (n == 1 && along > 0.25) {
                    v.fail(format!("{} is off the middle", s.name));
                }
            }
        }
        RelationKind::Stacked { n: high, stacks } => stacked(subjects, *high, *stacks, v),
        RelationKind::Loaded { target } => {
            let loaded = subjects
                .iter()
                .filter(|s| {
                    w.resting_on(s)
                        .iter()
                        .any(|(name, _)| w.layout.objects.iter().any(|o| &o.name == name && &o.group == target))
                })
                .count();
            v.set("loaded", loaded as f64);
            v.set("count", n as f64);
            if loaded < n {
                v.fail(format!("{loaded} of {n} carry any"));
            }
        }
        RelationKind::FullOf { target } => full_of(w, subjects, target, v),
        RelationKind::Leaning { wall } => {
            for s in subjects {
                let b = &s.body.bounds;
                let g = match wall {
                    Some(wl) => wall_gap(half, b, *wl),
                    None => nearest_wall(half, b).1,
                };
                let s_ = b.size();
                let upright = s_[2] >= 1.2 * s_[0].min(s_[1]);
                v.set("wall_gap_m", g);
                if g > WALL {
                    v.fail(format!("{} is {g:.2} m from the wall", s.name));
                } else if !upright {
                    v.fail(format!("{} lies flat", s.name));
                }
            }
        }
        RelationKind::EachWith { target } => {
            let companions = targets_of(target, v);
            each_with(w, subjects, &companions, v);
        }
        RelationKind::Reach { target } => {
            let ts = targets_of(target, v);
            for s in subjects {
                reach(w, s, &ts, v);
            }
        }
        RelationKind::Inside { target } => places::inside_of(subjects, &targets_of(target, v), v),
        RelationKind::SetInto { target } => places::set_into(subjects, &targets_of(target, v), v),
        RelationKind::AtEndOf { target, end } => places::at_end_of(subjects, &targets_of(target, v), *end, v),
        RelationKind::OnEdgeOf { target } => places::on_edge_of(subjects, &targets_of(target, v), v),
        RelationKind::OnEachSideOf { target } => places::on_each_side_of(subjects, &targets_of(target, v), v),
        RelationKind::Facing { target } => places::facing(subjects, &targets_of(target, v), v),
        RelationKind::OnOppositeWalls { long } => places::on_opposite_walls(half, subjects, *long, v),
        RelationKind::InCorners => places::in_corners(half, subjects, v),
        RelationKind::BackToBack => places::back_to_back(subjects, v),
    }
}

/// Every subject within `limit` of the target, directly or through other subjects that
/// are (a row of chairs next to a table).
fn cluster_near(subjects: &[Thing], targets: &[Thing], limit: f64, v: &mut Verdict) {
    let mut reached: Vec<Aabb> = targets.iter().map(|t| t.body.bounds).collect();
    let mut left: Vec<&Thing> = subjects.iter().collect();
    let direct = subjects
        .iter()
        .map(|s| targets.iter().map(|t| gap(&s.body.bounds, &t.body.bounds)).fold(f64::INFINITY, f64::min))
        .fold(0.0, f64::max);
    v.set("gap_m", direct);
    loop {
        let before = left.len();
        left.retain(|s| {
            let near = reached.iter().any(|b| gap(&s.body.bounds, b) <= limit);
            if near {
                reached.push(s.body.bounds);
            }
            !near
        });
        if left.is_empty() || left.len() == before {
            break;
        }
    }
    if let Some(s) = left.first() {
        v.fail(format!("{} is more than {limit} m away", s.name));
    }
}

/// Which side of a target a point is on: 0 front, 1 right, 2 back, 3 left.
pub(crate) fn side_of(t: &Thing, p: [f64; 2]) -> usize {
    let f = t.body.front();
    let sd = [f[1], -f[0]];
    let c = t.body.center();
    let d = [p[0] - c[0], p[1] - c[1]];
    let (a, b) =
        (dot(d, f) / half_along(&t.body.bounds, f).max(0.05), dot(d, sd) / half_along(&t.body.bounds, sd).max(0.05));
    if a.abs() >= b.abs() {
        if a >= 0.0 { 0 } else { 2 }
    } else if b >= 0.0 {
        1
    } else {
        3
    }
}

/// Farthest a piece "around" something may stand from it, m (a guard ring keeps an
/// arm's reach plus the safety distance).
const AROUND: f64 = 3.0;

/// Pieces on at least three sides of their target (or every side they can be on).
fn around(subjects: &[Thing], targets: &[Thing], v: &mut Verdict) {
    let mut per: Vec<(Vec<usize>, usize)> = vec![(Vec::new(), 0); targets.len()];
    let mut worst_gap: f64 = 0.0;
    for s in subjects {
        let Some((ti, g)) = nearest_target(s, targets) else {
            return;
        };
        worst_gap = worst_gap.max(g);
        let side = side_of(&targets[ti], s.body.center());
        if !per[ti].0.contains(&side) {
            per[ti].0.push(side);
        }
        per[ti].1 += 1;
    }
    v.set("gap_m", worst_gap);
    let sides = per.iter().filter(|(_, k)| *k > 0).map(|(s, k)| (s.len(), *k)).min_by_key(|(s, _)| *s);
    if let Some((s, k)) = sides {
        v.set("sides", s as f64);
        if s < 3.min(k) {
            v.fail(format!("on {s} side(s) only"));
        }
    }
    if worst_gap > AROUND {
        v.fail(format!("{worst_gap:.2} m from it"));
    }
}

/// The subjects as straight rows: groups of collinear centres (within 0.15 m of a line)
/// along one axis, every member turned alike within its row; `None` when they are not.
fn rows(subjects: &[Thing]) -> Option<Vec<Vec<usize>>> {
    if subjects.len() < 2 {
        return Some(vec![(0..subjects.len()).collect()]);
    }
    let mut best: Option<Vec<Vec<usize>>> = None;
    for axis in 0..2 {
        let across = 1 - axis;
        let mut idx: Vec<usize> = (0..subjects.len()).collect();
        idx.sort_by(|a, b| subjects[*a].body.center()[across].total_cmp(&subjects[*b].body.center()[across]));
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for i in idx {
            let c = subjects[i].body.center()[across];
            match groups.last_mut() {
                Some(g) if (subjects[g[0]].body.center()[across] - c).abs() <= 0.15 => g.push(i),
                _ => groups.push(vec![i]),
            }
        }
        // Each row side by side (no gap over 1.5 m) and turned alike.
        let ok = groups.iter().all(|g| {
            let mut along: Vec<&Thing> = g.iter().map(|i| &subjects[*i]).collect();
            along.sort_by(|a, b| a.body.center()[axis].total_cmp(&b.body.center()[axis]));
            let gaps_ok = along.windows(2).all(|p| gap(&p[0].body.bounds, &p[1].body.bounds) <= 1.5);
            let f = along[0].body.front();
            gaps_ok && along.iter().all(|t| dot(t.body.front(), f) > 0.99)
        });
        // Rows with one member each are no rows at all (unless only two things).
        let singles = groups.iter().filter(|g| g.len() == 1).count();
        if ok
            && (singles == 0 || subjects.len() <= 2 || groups.len() == 1)
            && best.as_ref().is_none_or(|b| groups.len() < b.len())
        {
            best = Some(groups);
        }
    }
    best
}

/// Parallel rows with corridors 1.5–3.5 m wide between neighbours, fronts to a corridor.
fn aisles(subjects: &[Thing], v: &mut Verdict) {
    let Some(rs) = rows(subjects) else {
        v.fail("not in straight rows");
        return;
    };
    v.set("rows", rs.len() as f64);
    if rs.len() < 2 {
        v.fail("one row: no aisle");
        return;
    }
    let bounds: Vec<Aabb> =
        rs.iter().map(|r| r.iter().fold(Aabb::EMPTY, |a, i| a.union(&subjects[*i].body.bounds))).collect();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
    for k in 0..rs.len() - 1 {
        let g = gap(&bounds[k], &bounds[k + 1]);
        lo = lo.min(g);
        hi = hi.max(g);
    }
    v.set("corridor_min_m", lo);
    v.set("corridor_max_m", hi);
    if lo < 1.5 || hi > 3.5 {
        v.fail(format!("corridors {lo:.2}–{hi:.2} m wide (1.5–3.5 m)"));
    }
    // Every row's front looks onto a neighbouring row's corridor.
    for (k, r) in rs.iter().enumerate() {
        let f = subjects[r[0]].body.front();
        let c = center(&bounds[k]);
        let towards = |j: usize| dot([center(&bounds[j])[0] - c[0], center(&bounds[j])[1] - c[1]], f) > 0.0;
        let ok = (k > 0 && towards(k - 1)) || (k + 1 < rs.len() && towards(k + 1));
        if !ok {
            v.fail("a row turns its back to every aisle");
        }
    }
}

/// Two rows (or two things) parallel, fronts facing each other across a gap.
fn facing(subjects: &[Thing], v: &mut Verdict) {
    if subjects.len() < 2 {
        v.fail("only one");
        return;
    }
    let f0 = subjects[0].body.front();
    let (a, b): (Vec<&Thing>, Vec<&Thing>) = subjects.iter().partition(|t| dot(t.body.front(), f0) > 0.0);
    if b.is_empty() {
        v.fail("all face the same way");
        return;
    }
    let anti = a.iter().all(|x| b.iter().all(|y| dot(x.body.front(), y.body.front()) < -0.99));
    let ua = a.iter().fold(Aabb::EMPTY, |acc, t| acc.union(&t.body.bounds));
    let ub = b.iter().fold(Aabb::EMPTY, |acc, t| acc.union(&t.body.bounds));
    let (ca, cb) = (center(&ua), center(&ub));
    let fa = a[0].body.front();
    let toward = dot([cb[0] - ca[0], cb[1] - ca[1]], fa) > 0.0;
    let side = [-fa[1], fa[0]];
    // The two rows overlap seen along their fronts.
    let (la, ha) = (dot(ca, side) - half_along(&ua, side), dot(ca, side) + half_along(&ua, side));
    let (lb, hb) = (dot(cb, side) - half_along(&ub, side), dot(cb, side) + half_along(&ub, side));
    let overlap = ha.min(hb) - la.max(lb);
    let g = gap(&ua, &ub);
    v.set("gap_m", g);
    v.set("overlap_m", overlap);
    if !anti {
        v.fail("not parallel");
    } else if !toward {
        v.fail("their backs face each other");
    } else if overlap <= 0.0 {
        v.fail("not opposite each other");
    } else if g < 0.3 {
        v.fail("no gap between them");
    }
}

/// `a` rests on `b`: on one of its sites, or on its top with its centre over it.
fn stands_on(a: &crate::scene_geom::BodyGeom, b: &crate::scene_geom::BodyGeom) -> bool {
    site_under(a, b).is_some() || ((a.bounds.min[2] - b.bounds.max[2]).abs() <= REST && inside(a.center(), &b.bounds))
}

/// Stacks: each resting on the one below, as many columns as said (`stacks`, else as
/// many as `high` members each need, else one). The stacks are counted as the things
/// resting on none of the others (the bottoms of the columns), so that three columns of
/// sixteen, where the ceiling allows no more, are three stacks, not forty-eight.
fn stacked(subjects: &[Thing], high: Option<u32>, said: Option<u32>, v: &mut Verdict) {
    let bottoms = subjects
        .iter()
        .enumerate()
        .filter(|(i, a)| !subjects.iter().enumerate().any(|(j, b)| *i != j && stands_on(&a.body, &b.body)))
        .count();
    let stacks = u32::try_from(bottoms.max(1)).unwrap_or(u32::MAX);
    v.set("stacks", f64::from(stacks));
    v.set("height_m", subjects.iter().map(|t| t.body.bounds.max[2]).fold(0.0, f64::max));
    let n = u32::try_from(subjects.len()).unwrap_or(u32::MAX);
    let want = said.unwrap_or_else(|| high.filter(|h| *h > 0).map_or(1, |h| n.div_ceil(h)));
    if stacks != want {
        v.fail(format!("{stacks} stacks, not {want}"));
    }
}

/// Every item on the subjects, spread over as many levels as there are items (or every
/// level that can take one).
fn full_of(w: &Written, subjects: &[Thing], target: &str, v: &mut Verdict) {
    let items: Vec<&sw_plan::PlacedObject> = w.layout.objects.iter().filter(|o| o.group == target).collect();
    let lowest = items
        .iter()
        .filter_map(|o| w.geom.bodies.get(&o.name))
        .map(|b| b.bounds.max[2] - b.bounds.min[2])
        .fold(f64::INFINITY, f64::min);
    let mut usable = 0;
    let mut covered = 0;
    let mut on = 0;
    for s in subjects {
        let mut zs: Vec<f64> = s.body.sites.iter().map(|x| x.z).collect();
        zs.sort_by(f64::total_cmp);
        let rest = w.resting_on(s);
        for site in &s.body.sites {
            let above = zs.iter().copied().filter(|z| *z > site.z + 1e-6).fold(f64::INFINITY, f64::min);
            if above - site.z >= lowest - 0.01 {
                usable += 1;
            }
            if rest.iter().any(|(n, st)| st.name == site.name && items.iter().any(|o| &o.name == n)) {
                covered += 1;
            }
        }
        on += rest.iter().filter(|(n, _)| items.iter().any(|o| &o.name == n)).count();
    }
    let want = usable.min(items.len());
    v.set("levels_used", covered as f64);
    v.set("levels_usable", usable as f64);
    v.set("items_on", on as f64);
    if on < items.len() {
        v.fail(format!("{} of {} items on them", on, items.len()));
    } else if covered < want {
        v.fail(format!("items on {covered} of {want} levels"));
    }
}

/// One companion per subject instance, where it is used: resting on it (small things),
/// in front of it (seats), else beside it.
fn each_with(w: &Written, subjects: &[Thing], companions: &[Thing], v: &mut Verdict) {
    let mut taken = vec![false; companions.len()];
    let mut matched = 0;
    for s in subjects {
        let resting = w.resting_on(s);
        let pick = companions.iter().enumerate().filter(|(i, _)| !taken[*i]).find_map(|(i, c)| {
            let on = resting.iter().any(|(n, _)| n == &c.name);
            let near = gap(&c.body.bounds, &s.body.bounds) <= NEXT_TO + 0.4;
            (on || near).then_some(i)
        });
        if let Some(i) = pick {
            taken[i] = true;
            matched += 1;
        }
    }
    v.set("matched", matched as f64);
    v.set("count", subjects.len() as f64);
    if matched < subjects.len() {
        v.fail(format!("{matched} of {} have their own", subjects.len()));
    }
}

/// An arm's reach of what it works at, from its shoulder: everything resting on the
/// instance it stands on or is nearest (a belt: its centreline at belt height; nothing
/// on it: the nearest point of its top; no surface: the nearest point of its box), and
/// every instance of the target within the reach of this arm or another of its model
/// (where arms share a surface, each item on it within the reach of one of them).
fn reach(w: &Written, arm: &Thing, targets: &[Thing], v: &mut Verdict) {
    let model = arm.robot.as_deref().unwrap_or_default();
    let reach = sw_robots::find(model).map_or(0.0, |d| d.reach);
    let shoulder_of = |t: &Thing| t.body.shoulder().unwrap_or([t.body.pos[0], t.body.pos[1], t.body.pos[2] + 0.2]);
    let me = shoulder_of(arm);
    // The arms of the same model that may share the work.
    let arms: Vec<[f64; 3]> = w
        .layout
        .robots
        .iter()
        .filter(|r| r.model == model)
        .filter_map(|r| w.robot_thing(r))
        .map(|t| shoulder_of(&t))
        .collect();
    let mut worst: f64 = 0.0;
    let mut mine: f64 = f64::INFINITY;
    // A surface several arms share: each item on it within the reach of one of them.
    let shared = arms.len() > 1;
    for t in targets {
        let items: Vec<[f64; 3]> = if shared
            && !w.layout.objects.iter().any(|o| o.name == t.name && (o.movable || o.category == "conveyor"))
        {
            w.resting_on(t).iter().filter_map(|(name, _)| w.geom.bodies.get(name)).map(|b| b.bounds.center()).collect()
        } else {
            Vec::new()
        };
        if items.is_empty() {
            let d_me = work_distance(w, t, me);
            mine = mine.min(d_me);
            let best = arms.iter().map(|s| work_distance(w, t, *s)).fold(d_me, f64::min);
            worst = worst.max(best);
            continue;
        }
        let d =
            |p: [f64; 3], s: [f64; 3]| ((p[0] - s[0]).powi(2) + (p[1] - s[1]).powi(2) + (p[2] - s[2]).powi(2)).sqrt();
        for p in items {
            mine = mine.min(d(p, me));
            worst = worst.max(arms.iter().map(|s| d(p, *s)).fold(d(p, me), f64::min));
        }
    }
    v.set("distance_m", worst);
    v.set("nearest_work_m", mine);
    v.set("reach_m", reach);
    if mine > reach {
        v.fail(format!("{} reaches {reach:.2} m; its nearest work is {mine:.2} m from its shoulder", arm.name));
    } else if worst > reach {
        v.fail(format!("some of its work is {worst:.2} m from the shoulder of every arm (reach {reach:.2} m)"));
    }
}

/// The distance from a shoulder to the farthest point of a work instance it must reach.
fn work_distance(w: &Written, t: &Thing, s: [f64; 3]) -> f64 {
    let d = |p: [f64; 3]| ((p[0] - s[0]).powi(2) + (p[1] - s[1]).powi(2) + (p[2] - s[2]).powi(2)).sqrt();
    let placed = w.layout.objects.iter().find(|o| o.name == t.name);
    if placed.is_some_and(|o| o.movable) {
        // A free item: its centre.
        return d(t.body.bounds.center());
    }
    let conveyor = placed.is_some_and(|o| o.category == "conveyor");
    let top = t.body.sites.iter().max_by(|a, b| a.z.total_cmp(&b.z));
    if conveyor && let Some(top) = top {
        let r = top.rect;
        let (a, b) = if r[2] - r[0] >= r[3] - r[1] {
            let y = 0.5 * (r[1] + r[3]);
            ([r[0], y], [r[2], y])
        } else {
            let x = 0.5 * (r[0] + r[2]);
            ([x, r[1]], [x, r[3]])
        };
        let along = [b[0] - a[0], b[1] - a[1]];
        let k = (dot([s[0] - a[0], s[1] - a[1]], along) / dot(along, along).max(1e-12)).clamp(0.0, 1.0);
        return d([a[0] + k * along[0], a[1] + k * along[1], top.z]);
    }
    let items: Vec<f64> =
        w.resting_on(t).iter().filter_map(|(name, _)| w.geom.bodies.get(name)).map(|b| d(b.bounds.center())).collect();
    if !items.is_empty() {
        return items.into_iter().fold(0.0, f64::max);
    }
    match top {
        Some(top) => {
            let r = top.rect;
            d([s[0].clamp(r[0], r[2]), s[1].clamp(r[1], r[3]), top.z])
        }
        None => {
            let b = &t.body.bounds;
            d([s[0].clamp(b.min[0], b.max[0]), s[1].clamp(b.min[1], b.max[1]), s[2].clamp(b.min[2], b.max[2])])
        }
    }
}

/// A group standing in one row, as one footprint with its front; `None` otherwise.
fn row_of(ts: &[Thing]) -> Option<(Aabb, [f64; 2])> {
    if ts.len() < 2 {
        return None;
    }
    let f = ts[0].body.front();
    if ts.iter().any(|t| dot(t.body.front(), f) < 0.99) {
        return None;
    }
    let c0 = ts[0].body.center();
    if ts.iter().any(|t| dot([t.body.center()[0] - c0[0], t.body.center()[1] - c0[1]], f).abs() > 0.3) {
        return None;
    }
    Some((ts.iter().fold(Aabb::EMPTY, |a, t| a.union(&t.body.bounds)), f))
}

/// `s` in front of (`sign` 1) or behind (-1) a body with front `f`.
fn in_front(s: &Aabb, t: &Aabb, f: [f64; 2], sign: f64) -> bool {
    let f = [f[0] * sign, f[1] * sign];
    let side = [-f[1], f[0]];
    let (c, tc) = (center(s), center(t));
    let d = [c[0] - tc[0], c[1] - tc[1]];
    dot(d, f) > half_along(t, f) && dot(d, side).abs() <= half_along(t, side) + FRONT_SIDE && gap(s, t) <= FRONT
}
