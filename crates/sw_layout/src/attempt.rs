//! One layout attempt at a given room size: furniture, then robots, then items on
//! surfaces, then small items on the floor.

use std::collections::BTreeMap;

use sw_geom::{Aabb, PlacementKind, Rng};
use sw_plan::{
    Dims, DoorLayout, LaidOutScene, LeftOut, PlacedObject, PlacedRobot, RelationKind, RoomKind, RoomLayout, Stage,
    Support, Wall, Warning,
};

use crate::LayoutInput;
use crate::floor;
use crate::frames::Spot;
use crate::robots;
use crate::rules::{self, Clearance, EgressGrid, Profile};
use crate::space::{Space, Zone};
use crate::surface;

pub(crate) const WALL_THICKNESS: f64 = 0.2;

pub(crate) struct AttemptResult {
    pub scene: LaidOutScene,
    /// Floor objects that found no place (a bigger room may help).
    pub floor_failures: usize,
}

/// Where an object ended up.
#[derive(Debug, Clone)]
pub(crate) struct Placement {
    pub spot: Spot,
    pub support: Support,
}

/// The state of one attempt.
pub(crate) struct Ctx<'a> {
    pub input: &'a LayoutInput<'a>,
    pub space: Space,
    pub rng: Rng,
    pub door: DoorLayout,
    /// Collision boxes of each object in its own frame.
    pub local: Vec<Vec<Aabb>>,
    pub bounds: Vec<Aabb>,
    pub placed: Vec<Option<Placement>>,
    /// Occupied rectangles (object frame, [x0, y0, x1, y1]) per object and surface.
    pub surface_use: BTreeMap<usize, Vec<Vec<[f64; 4]>>>,
    pub robots: Vec<Option<PlacedRobot>>,
    pub warnings: Vec<Warning>,
    pub reasons: BTreeMap<usize, String>,
    pub floor_failures: usize,
    /// Floor placements that failed, per group: after a few, the rest of the group fails
    /// at once (its instances are alike; searching the whole floor again cannot succeed).
    pub group_failures: BTreeMap<String, u32>,
    /// Where in its default candidates each group last found a place.
    pub cursor: BTreeMap<String, usize>,
    /// The free-floor grid of each group (and whether it is ordered from the centre).
    pub grid_cache: BTreeMap<(String, bool), std::rc::Rc<Vec<Spot>>>,
    /// The rules that apply, and the keep-clear space they ask around each object.
    pub profile: Profile,
    pub clearances: Vec<Clearance>,
    /// Routes of the egress width from the door, and the working fronts they must reach.
    pub egress: Option<EgressGrid>,
    pub access: Vec<Aabb>,
    pub door_zone: Aabb,
    /// Robots are being placed with guards kept at their safety distance.
    pub guards_strict: bool,
}

impl<'a> Ctx<'a> {
    pub fn relations(&self, group: &str) -> Vec<&'a RelationKind> {
        self.input.plan.relations.iter().filter(|r| r.subject == group).map(|r| &r.kind).collect()
    }

    /// Indices of the objects of a plan group, in order.
    pub fn instances(&self, group: &str) -> Vec<usize> {
        self.input.objects.iter().enumerate().filter(|(_, o)| o.group == group).map(|(i, _)| i).collect()
    }

    /// Placed instances of a group.
    pub fn placed_instances(&self, group: &str) -> Vec<(usize, Spot)> {
        self.instances(group).into_iter().filter_map(|i| self.placed[i].as_ref().map(|p| (i, p.spot))).collect()
    }

    pub fn warn(&mut self, code: &str, message: String) {
        if !self.warnings.iter().any(|w| w.message == message) {
            self.warnings.push(Warning::new(Stage::Layout, code, message));
        }
    }

    /// Records a placement and its occupied space: its collision boxes, the keep-clear
    /// zones its rules ask for, and its footprint on the egress grid.
    pub fn commit(&mut self, idx: usize, spot: Spot, support: Support) {
        let boxes = spot.boxes(&self.local[idx]);
        let on_floor = matches!(support, Support::Floor);
        let name = self.input.objects[idx].name.clone();
        let footprint = crate::space::union(&boxes);
        self.space.add(&name, boxes, on_floor);
        if on_floor {
            for (zone, front) in floor::zones(self, idx, &spot) {
                if front {
                    self.access.push(zone);
                }
                self.space.zones.push(Zone { owner: Some(name.clone()), area: zone });
            }
            if let Some(g) = &mut self.egress {
                g.add(&footprint);
            }
        }
        self.placed[idx] = Some(Placement { spot, support });
    }
}

/// The door: a gap in the south wall (or the plan's wall), wide enough for the room kind.
fn door_for(kind: RoomKind, wall: Wall, size: &Dims) -> DoorLayout {
    let width: f64 = match kind {
        RoomKind::Warehouse | RoomKind::LoadingDock | RoomKind::Factory | RoomKind::Garage => 3.0,
        RoomKind::Closet => 0.8,
        _ => 1.0,
    };
    let along = match wall {
        Wall::North | Wall::South => size.width,
        Wall::East | Wall::West => size.depth,
    };
    let width = width.min(along * 0.5).max(0.6);
    DoorLayout { wall, offset: 0.0, width, height: (2.1f64).min(size.height - 0.1).max(1.0) }
}

/// The keep-clear rectangle in front of the doorway.
pub(crate) fn door_zone(door: &DoorLayout, size: &Dims) -> Aabb {
    let depth = 1.2f64.min(0.45 * size.depth.min(size.width));
    let (hw, hd) = (size.width / 2.0, size.depth / 2.0);
    let half = door.width / 2.0 + 0.2;
    match door.wall {
        Wall::South => {
            Aabb { min: [door.offset - half, -hd, 0.0], max: [door.offset + half, -hd + depth, size.height] }
        }
        Wall::North => Aabb { min: [door.offset - half, hd - depth, 0.0], max: [door.offset + half, hd, size.height] },
        Wall::East => Aabb { min: [hw - depth, door.offset - half, 0.0], max: [hw, door.offset + half, size.height] },
        Wall::West => Aabb { min: [-hw, door.offset - half, 0.0], max: [-hw + depth, door.offset + half, size.height] },
    }
}

/// Items that rest on other objects rather than the floor.
pub(crate) fn surface_target(ctx: &Ctx<'_>, idx: usize) -> Option<String> {
    let o = &ctx.input.objects[idx];
    ctx.relations(&o.group)
        .iter()
        .find_map(|r| match r {
            RelationKind::On { target } | RelationKind::Inside { target } | RelationKind::OnEdgeOf { target } => {
                Some(target.clone())
            }
            // A hob in the worktop rests on it; a sink unit stands in the run.
            RelationKind::SetInto { target } if is_small(ctx, idx) || ctx.bounds[idx].size()[2] <= 0.15 => {
                Some(target.clone())
            }
            // Small things on each side of a table: on its top, at opposite edges. On each
            // side of a small thing ("a bowl on each side of the cutting board"): beside it
            // on what it rests on (`surface::try_surface` keeps the sides), or on the floor
            // by it when it rests on nothing.
            RelationKind::OnEachSideOf { target } if is_small(ctx, idx) => {
                let &t = ctx.instances(target).first()?;
                if is_small(ctx, t) {
                    ctx.relations(target).iter().find_map(|r| match r {
                        RelationKind::On { target: h } | RelationKind::Inside { target: h } if h != target => {
                            Some(h.clone())
                        }
                        _ => None,
                    })
                } else {
                    (!ctx.input.objects[t].asset.surfaces.is_empty()).then(|| target.clone())
                }
            }
            // Items between two arms rest on the surface the arms share.
            RelationKind::Between { first, second } if is_small(ctx, idx) => shared_work(ctx, first, second),
            _ => None,
        })
        .or_else(|| beside_work(ctx, idx))
        .or_else(|| {
            companion_rests_on_host(ctx, idx).then(|| floor::hosts_of(ctx, &o.group).into_iter().next()).flatten()
        })
}

/// A tabletop thing said to stand by an arm or by the work furniture an arm works at
/// ("four cups in front of the Panda", "the bowls next to the table the UR5e is on"):
/// it rests on that work surface, where the arm reaches it — a cup is not set on the
/// floor beside a robot's table. Things with a place of their own on the floor said
/// (under, against a wall, in a corner …) keep it.
fn beside_work(ctx: &Ctx<'_>, idx: usize) -> Option<String> {
    let o = &ctx.input.objects[idx];
    // Bins, crates and boxes stand on the floor by a table ("an empty tote next to the
    // table").
    if !is_small(ctx, idx) || !o.has_tag("tabletop") || o.has_tag("stackable") {
        return None;
    }
    let rels = ctx.relations(&o.group);
    let floor_said = rels.iter().any(|r| {
        matches!(
            r,
            RelationKind::Under { .. }
                | RelationKind::AgainstWall { .. }
                | RelationKind::InCorner { .. }
                | RelationKind::InCorners
                | RelationKind::Leaning { .. }
                | RelationKind::NearDoor
        )
    });
    if floor_said {
        return None;
    }
    // A top with room for it: a quarter of it at most.
    let size = ctx.bounds[idx].size();
    let has_top = |g: &str| {
        ctx.instances(g).first().is_some_and(|&i| {
            ctx.input.objects[i]
                .asset
                .surfaces
                .iter()
                .any(|s| s.clearance.is_none() && 4.0 * size[0] * size[1] <= s.area())
        })
    };
    // The surfaces arms work at.
    let worked: Vec<String> = ctx.input.robots.iter().filter_map(|r| crate::reach::work_group(ctx, r)).collect();
    rels.iter().find_map(|r| {
        let beside = matches!(
            r,
            RelationKind::NextTo { .. }
                | RelationKind::Near { .. }
                | RelationKind::InFrontOf { .. }
                | RelationKind::Behind { .. }
                | RelationKind::Facing { .. }
        );
        let t = r.targets().first().map(|t| t.to_string())?;
        if !beside {
            return None;
        }
        // By an arm: on the surface it works at.
        if let Some(robot) = ctx.input.robots.iter().find(|x| x.group == t && x.is_arm) {
            return crate::reach::work_group(ctx, robot).filter(|g| has_top(g));
        }
        // By the work surface an arm works at: on it.
        (worked.contains(&t) && has_top(&t)).then_some(t)
    })
}

/// The object group two robot groups (or one, twice) both work at, when it has a surface
/// ("three bins between the two arms": on the bench the arms share).
pub(crate) fn shared_work(ctx: &Ctx<'_>, first: &str, second: &str) -> Option<String> {
    let work = |g: &str| -> Vec<String> {
        ctx.input.robots.iter().filter(|r| r.group == g).filter_map(|r| crate::reach::work_group(ctx, r)).collect()
    };
    let (a, b) = (work(first), work(second));
    a.into_iter().find(|g| {
        b.contains(g) && ctx.instances(g).first().is_some_and(|&i| !ctx.input.objects[i].asset.surfaces.is_empty())
    })
}

/// The keep-clear space of an object the prompt put at a wall: none behind it (nor
/// beside it, in a corner) — the rules check reports that shortfall as asked for.
fn said_clearance(plan: &sw_plan::ScenePlan, group: &str, mut c: Clearance) -> Clearance {
    for r in plan.relations.iter().filter(|r| r.subject == group) {
        match r.kind {
            RelationKind::AgainstWall { .. }
            | RelationKind::OnTwoWalls
            | RelationKind::OnOppositeWalls { .. }
            | RelationKind::Leaning { .. }
            | RelationKind::BackToBack => c.back = 0.0,
            // A unit in a run stands against its neighbour.
            RelationKind::SetInto { .. } => c.sides = 0.0,
            RelationKind::InCorner { .. } | RelationKind::InCorners => {
                c.back = 0.0;
                c.sides = 0.0;
            }
            _ => {}
        }
    }
    c
}

/// A small thing with no place of its own said that others are placed by on the floor
/// ("a bin and three trays in front of it" in a room with no table): it goes on the
/// floor anyway (step 4 finds no host for it), so it is placed with the floor things,
/// before them (`order`) — else they look for it before it stands and are placed
/// anywhere.
fn floor_target(ctx: &Ctx<'_>, idx: usize) -> bool {
    let o = &ctx.input.objects[idx];
    if !is_small(ctx, idx) || !ctx.relations(&o.group).is_empty() || surface_target(ctx, idx).is_some() {
        return false;
    }
    let targeted = ctx.input.plan.relations.iter().any(|r| {
        r.subject != o.group
            && crate::relate::is_positional(&r.kind)
            && r.kind.targets().contains(&o.group.as_str())
            && ctx.instances(&r.subject).first().is_some_and(|&i| surface_target(ctx, i).is_none())
    });
    // The hosts step 4 would put it on (`surface::place_loose`).
    let host = |work: bool| {
        ctx.input.objects.iter().any(|h| {
            h.carries_robot.is_none()
                && if work {
                    h.has_tag("surface") && h.has_tag("furniture")
                } else {
                    h.has_tag("storage") && !h.asset.surfaces.is_empty()
                }
        })
    };
    let hosted = (o.has_tag("tabletop") && host(true))
        || (!o.has_tag("tabletop") && (o.has_tag("container") || o.has_tag("stackable")) && host(false));
    targeted && !hosted
}

/// Small things that rest on surfaces (as opposed to furniture and fixtures).
pub(crate) fn is_small(ctx: &Ctx<'_>, idx: usize) -> bool {
    ctx.input.objects[idx].asset.placement == PlacementKind::OnSurface
}

/// A companion that rests on its host ("desks each with a monitor").
pub(crate) fn companion_rests_on_host(ctx: &Ctx<'_>, idx: usize) -> bool {
    is_small(ctx, idx)
        && floor::hosts_of(ctx, &ctx.input.objects[idx].group)
            .iter()
            .any(|h| ctx.instances(h).first().is_some_and(|&i| !ctx.input.objects[i].asset.surfaces.is_empty()))
}

/// A floor group: as a formation when it has one (kept whole, or each member placed on
/// its own and the formation reported unmet), else one instance at a time.
fn place_group(ctx: &mut Ctx<'_>, group: &str, idxs: &[usize]) {
    // Facing rows and aisles are rows too; they decide how the rows face.
    let rank = |r: &RelationKind| match r {
        RelationKind::BackToBack => 0,
        RelationKind::FacingEachOther => 1,
        RelationKind::InAisles => 2,
        RelationKind::InRows { .. } => 3,
        RelationKind::InRow => 4,
        _ => 5,
    };
    let formation =
        ctx.relations(group).into_iter().filter(|r| r.is_group_formation()).min_by_key(|r| rank(r)).cloned();
    // A counter with a sink unit or a range set into it: laid out as one run.
    let units = crate::formation::run_units(ctx, group);
    if formation.is_none() && !units.is_empty() && crate::formation::place_run(ctx, group, idxs, &units) {
        return;
    }
    if let Some(rel) = formation
        && idxs.len() > 1
    {
        if crate::formation::place(ctx, group, idxs, &rel) {
            return;
        }
        // A room whose size was not given grows until the arrangement fits.
        if !ctx.input.plan.room.size_fixed {
            ctx.floor_failures += 1;
        }
        let plan = ctx.input.plan;
        let phrase = plan.describe(&sw_plan::Relation { subject: group.to_string(), kind: rel.clone() });
        ctx.warn(
            "relation_unmet",
            format!("could not keep {phrase}: no free floor space for the whole group in that arrangement; placed one by one"),
        );
    }
    for &idx in idxs {
        if sw_geom::cancel::requested() {
            return;
        }
        if ctx.placed[idx].is_none() {
            floor::place(ctx, idx);
        }
    }
}

pub(crate) fn run(input: &LayoutInput<'_>, size: Dims) -> AttemptResult {
    run_pinned(input, size, None)
}

/// An attempt with some objects and robots kept where they were (see `pinned`).
pub(crate) fn run_pinned(input: &LayoutInput<'_>, size: Dims, pins: Option<&crate::Pins>) -> AttemptResult {
    let plan = input.plan;
    let door = door_for(plan.room.kind, plan.room.door, &size);
    let mut space = Space::new(size.width, size.depth, size.height);
    let door_area = door_zone(&door, &size);
    space.zones.push(Zone { owner: None, area: door_area });
    let (profile, unknown_profile) = match rules::profile(&plan.rules_profile) {
        Some(p) => (p, None),
        None => (
            rules::profile("general").unwrap_or(Profile { name: "general".into(), rules: Vec::new() }),
            Some(format!(
                "rules profile '{}' is unknown (known: {}); used 'general'",
                plan.rules_profile,
                rules::profile_names().join(", ")
            )),
        ),
    };
    let local: Vec<Vec<Aabb>> = input.objects.iter().map(|o| o.asset.collision_aabbs()).collect();
    let bounds: Vec<Aabb> = local.iter().map(|b| crate::space::union(b)).collect();
    let mut ctx = Ctx {
        input,
        space,
        rng: Rng::derive(input.seed, &format!("layout {:.3} {:.3}", size.width, size.depth)),
        door: door.clone(),
        local,
        bounds,
        placed: vec![None; input.objects.len()],
        surface_use: BTreeMap::new(),
        robots: vec![None; input.robots.len()],
        warnings: Vec::new(),
        reasons: BTreeMap::new(),
        floor_failures: 0,
        group_failures: BTreeMap::new(),
        cursor: BTreeMap::new(),
        grid_cache: BTreeMap::new(),
        clearances: input.objects.iter().map(|o| said_clearance(plan, &o.group, profile.clearance(&o.tags))).collect(),
        egress: profile.egress().map(|(_, w, _)| EgressGrid::new([size.width / 2.0, size.depth / 2.0], w, &door_area)),
        profile,
        access: Vec::new(),
        door_zone: door_area,
        guards_strict: true,
    };
    if let Some(w) = unknown_profile {
        ctx.warn("rules_profile_unknown", w);
    }
    if let Some(p) = pins {
        crate::pinned::commit(&mut ctx, p);
    }
    let pinned: Vec<bool> = ctx.placed.iter().map(Option::is_some).collect();

    // 1. Furniture, fixtures and robots on the floor, each after what its relations
    //    point at; groups with a formation (a row, aisles, a stack …) as a whole.
    // Small things go here too when where they stand was said ("a bin under the table").
    let related: Vec<bool> = input.objects.iter().map(|o| !ctx.relations(&o.group).is_empty()).collect();
    let companions: Vec<bool> = input.objects.iter().map(|o| !floor::hosts_of(&ctx, &o.group).is_empty()).collect();
    let floor_first: Vec<bool> = (0..input.objects.len()).map(|i| floor_target(&ctx, i)).collect();
    let furniture: Vec<usize> = (0..input.objects.len())
        .filter(|&i| {
            !pinned[i]
                && input.objects[i].carries_robot.is_none()
                && (!is_small(&ctx, i) || related[i] || companions[i] || floor_first[i])
                && surface_target(&ctx, i).is_none()
        })
        .collect();
    for unit in crate::order::units(&ctx, &furniture) {
        // A cancelled job's layout stops here; its caller discards the partial result.
        if sw_geom::cancel::requested() {
            break;
        }
        match unit {
            crate::order::Unit::Group(group, idxs) => place_group(&mut ctx, &group, &idxs),
            crate::order::Unit::Robot(ri) => robots::place_one(&mut ctx, ri),
        }
    }
    // 3. Items on surfaces (and large objects said to be on something).
    let on_surfaces: Vec<usize> = (0..input.objects.len())
        .filter(|&i| !pinned[i] && input.objects[i].carries_robot.is_none() && surface_target(&ctx, i).is_some())
        .collect();
    surface::place_all(&mut ctx, &on_surfaces);
    // 4. Small items with no support named: on work surfaces when they are tabletop
    //    things, else on the floor.
    let rest: Vec<usize> = (0..input.objects.len())
        .filter(|&i| {
            !pinned[i]
                && ctx.placed[i].is_none()
                && input.objects[i].carries_robot.is_none()
                && is_small(&ctx, i)
                && surface_target(&ctx, i).is_none()
        })
        .collect();
    surface::place_loose(&mut ctx, &rest);

    finish(ctx, size, door)
}

fn finish(ctx: Ctx<'_>, size: Dims, door: DoorLayout) -> AttemptResult {
    let input = ctx.input;
    let mut scene = LaidOutScene::new(
        input.seed,
        RoomLayout { kind: input.plan.room.kind, size, wall_thickness: WALL_THICKNESS, door },
    );
    let mut per_group: BTreeMap<&str, (u32, u32, String)> = BTreeMap::new();
    for (i, o) in input.objects.iter().enumerate() {
        let entry = per_group.entry(o.group.as_str()).or_insert((0, 0, o.category.clone()));
        entry.0 += 1;
        let Some(p) = &ctx.placed[i] else { continue };
        entry.1 += 1;
        let b = ctx.bounds[i];
        let size = b.size();
        scene.objects.push(PlacedObject {
            name: o.name.clone(),
            group: o.group.clone(),
            category: o.category.clone(),
            label: o.label.clone(),
            pos: [round(p.spot.x), round(p.spot.y), round(p.spot.z)],
            yaw: p.spot.yaw,
            size: [round(size[0]), round(size[1]), round(size[2])],
            support: p.support.clone(),
            movable: o.asset.is_free(),
            mass: match o.asset.mass {
                sw_geom::MassModel::Free { mass } => Some(round(mass)),
                sw_geom::MassModel::Static => None,
            },
            asset_seed: o.asset.seed,
            added: false,
        });
    }
    for (group, (requested, placed, category)) in per_group {
        if placed < requested {
            let reason = input
                .objects
                .iter()
                .enumerate()
                .filter(|(_, o)| o.group == group)
                .find_map(|(i, _)| ctx.reasons.get(&i).cloned())
                .unwrap_or_else(|| "no free space".into());
            scene.left_out.push(LeftOut { group: group.to_string(), category, requested, placed, reason });
        }
    }
    scene.robots = ctx.robots.into_iter().flatten().collect();
    scene.violations = rules::check(input, &scene, &ctx.profile, &ctx.door_zone);
    scene.warnings = ctx.warnings;
    AttemptResult { scene, floor_failures: ctx.floor_failures }
}

/// Positions are kept to 0.1 µm so the JSON stays short and stable.
pub(crate) fn round(x: f64) -> f64 {
    (x * 1e7).round() / 1e7
}
