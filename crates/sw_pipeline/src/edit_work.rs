//! The scene an edit works on, in memory, and its geometry: what is kept (pinned), what
//! is free for the solver, items riding on objects that move, and the fit checks.
//!
//! The working state is the package's plan, its layout (the poses that are kept) and
//! its assets. An object that an operation takes out of the layout is "free": the
//! layout solver places it around the pinned ones, honouring the relations the edit gave
//! its group. Items resting on an object that moves ride along with it (their pose in
//! their host's frame is kept). Moves to a side of an object and shifts by a distance
//! are placed here, against the collision geometry of everything else.

use std::collections::BTreeSet;

use sw_edit::{Reference, SceneView, Selection, Spatial};
use sw_geom::{Aabb, Pose};
use sw_layout::ObjectItem;
use sw_plan::{LaidOutScene, Mount, ObjectPlan, PlacedObject, Relation, ScenePlan, Support, Warning};

use crate::forge::{Forged, ForgedObject, make_seeded};

/// Something the edit cannot do (bad input: the package is left as it was).
pub(crate) type OpError = String;

/// An item that rides on a host that moves: its pose in the host's frame.
#[derive(Debug, Clone)]
pub(crate) struct Rider {
    pub object: PlacedObject,
    pub host: String,
    pub local: [f64; 3],
    pub local_yaw: f64,
}

/// The scene being edited.
pub(crate) struct Work {
    pub plan: ScenePlan,
    /// Poses that are kept (pinned).
    pub layout: LaidOutScene,
    pub forged: Forged,
    /// Objects and robots the solver will place.
    pub free: BTreeSet<String>,
    pub riders: Vec<Rider>,
    pub seed: u64,
    pub ops: Vec<String>,
    pub added: Vec<String>,
    pub removed: Vec<String>,
    pub moved: Vec<String>,
    pub modified: Vec<String>,
    pub warnings: Vec<Warning>,
    /// Generated parts placed in the package, with their meshes (see `parts`).
    pub parts: Vec<crate::parts::Part>,
}

const FIT_GAP: f64 = 0.02;
const WALL_GAP: f64 = 0.02;
const EPS: f64 = 1e-6;

pub(crate) fn overlap(a: &Aabb, b: &Aabb, gap: f64) -> bool {
    a.min[0] - gap < b.max[0] - EPS
        && b.min[0] < a.max[0] + gap - EPS
        && a.min[1] - gap < b.max[1] - EPS
        && b.min[1] < a.max[1] + gap - EPS
        && a.min[2] < b.max[2] - EPS
        && b.min[2] < a.max[2] - EPS
}

pub(crate) fn union(boxes: &[Aabb]) -> Aabb {
    boxes.iter().fold(Aabb::EMPTY, |acc, b| acc.union(b))
}

impl Work {
    pub(crate) fn view(&self) -> SceneView<'_> {
        SceneView { plan: &self.plan, layout: &self.layout }
    }

    pub(crate) fn asset_of(&self, name: &str) -> Option<&ForgedObject> {
        self.forged.objects.iter().find(|o| o.name == name)
    }

    /// Resolves a reference among the objects and robots still in the scene.
    pub(crate) fn select(&self, r: &Reference) -> Result<Selection, OpError> {
        sw_edit::resolve(&self.view(), r).map_err(|e| e.to_string())
    }

    /// Collision boxes of an object at a pose, in the world.
    pub(crate) fn boxes_at(&self, name: &str, pos: [f64; 3], yaw: f64) -> Vec<Aabb> {
        let pose = Pose::from_pos_yaw(pos, yaw);
        self.asset_of(name)
            .map(|f| f.asset.collision_aabbs().iter().map(|b| b.transformed(&pose)).collect())
            .unwrap_or_default()
    }

    /// Checks that `name` fits at a pose: inside the room, clear of every kept object and
    /// robot except those in `ignore`. Returns what is in the way.
    pub(crate) fn fits(&self, name: &str, pos: [f64; 3], yaw: f64, ignore: &[String]) -> Result<(), OpError> {
        let boxes = self.boxes_at(name, pos, yaw);
        let all = union(&boxes);
        let s = self.layout.room.size;
        let (hw, hd) = (s.width / 2.0, s.depth / 2.0);
        if all.min[0] < -hw + WALL_GAP - EPS
            || all.max[0] > hw - WALL_GAP + EPS
            || all.min[1] < -hd + WALL_GAP - EPS
            || all.max[1] > hd - WALL_GAP + EPS
            || all.min[2] < -EPS
            || all.max[2] > s.height + EPS
        {
            return Err("the room's walls".into());
        }
        for o in &self.layout.objects {
            if o.name == name || ignore.contains(&o.name) {
                continue;
            }
            let other = self.boxes_at(&o.name, o.pos, o.yaw);
            if !overlap(&all, &union(&other), FIT_GAP) {
                continue;
            }
            if boxes.iter().any(|b| other.iter().any(|c| overlap(b, c, FIT_GAP))) {
                return Err(o.name.clone());
            }
        }
        for r in &self.layout.robots {
            if ignore.contains(&r.name) {
                continue;
            }
            let Some(item) = self.forged.robots.iter().find(|x| x.name == r.name) else { continue };
            let pose = Pose::from_pos_yaw(r.pos, r.yaw);
            if item.keepout.iter().any(|k| boxes.iter().any(|b| overlap(b, &k.transformed(&pose), FIT_GAP))) {
                return Err(r.name.clone());
            }
        }
        Ok(())
    }

    /// Items resting (directly or not) on `host`.
    pub(crate) fn riders_of(&self, host: &str) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        let mut hosts = vec![host.to_string()];
        while let Some(h) = hosts.pop() {
            for o in &self.layout.objects {
                if matches!(&o.support, Support::Object { object, .. } if *object == h) && !out.contains(&o.name) {
                    out.push(o.name.clone());
                    hosts.push(o.name.clone());
                }
            }
        }
        out
    }

    /// Robots standing on `object` (a surface or a pedestal).
    pub(crate) fn robots_on(&self, object: &str) -> Vec<String> {
        self.layout.robots.iter().filter(|r| r.mounted_on.as_deref() == Some(object)).map(|r| r.name.clone()).collect()
    }

    /// Takes the riders of `host` out of the kept poses, remembering them relative to it.
    pub(crate) fn lift_riders(&mut self, host: &str) {
        let Some(h) = self.layout.object(host).cloned() else { return };
        for name in self.riders_of(host) {
            let Some(i) = self.layout.objects.iter().position(|o| o.name == name) else { continue };
            let o = self.layout.objects.remove(i);
            let (s, c) = (-h.yaw).sin_cos();
            let d = [o.pos[0] - h.pos[0], o.pos[1] - h.pos[1], o.pos[2] - h.pos[2]];
            let local = [c * d[0] - s * d[1], s * d[0] + c * d[1], d[2]];
            // Riders of riders keep their own host.
            let direct = match &o.support {
                Support::Object { object, .. } => object.clone(),
                _ => host.to_string(),
            };
            let (local, local_yaw, host_name) = if direct == host {
                (local, o.yaw - h.yaw, host.to_string())
            } else {
                let dh = self.riders.iter().find(|r| r.object.name == direct).map(|r| r.object.clone());
                match dh {
                    Some(p) => {
                        let (s2, c2) = (-p.yaw).sin_cos();
                        let d2 = [o.pos[0] - p.pos[0], o.pos[1] - p.pos[1], o.pos[2] - p.pos[2]];
                        ([c2 * d2[0] - s2 * d2[1], s2 * d2[0] + c2 * d2[1], d2[2]], o.yaw - p.yaw, direct.clone())
                    }
                    None => (local, o.yaw - h.yaw, host.to_string()),
                }
            };
            self.riders.push(Rider { object: o, host: host_name, local, local_yaw });
        }
    }

    /// Puts the riders whose hosts are in `layout` back on their hosts' poses (hosts
    /// first); the others wait for their hosts to be placed.
    pub(crate) fn land_riders(&mut self, layout: &mut LaidOutScene) {
        let mut pending = std::mem::take(&mut self.riders);
        loop {
            let before = pending.len();
            let mut rest = Vec::new();
            for r in pending {
                match layout.object(&r.host).cloned() {
                    Some(h) => {
                        let (s, c) = h.yaw.sin_cos();
                        let p = [
                            h.pos[0] + c * r.local[0] - s * r.local[1],
                            h.pos[1] + s * r.local[0] + c * r.local[1],
                            h.pos[2] + r.local[2],
                        ];
                        let mut o = r.object;
                        o.pos = p.map(round);
                        o.yaw = norm_yaw(h.yaw + r.local_yaw);
                        layout.objects.push(o);
                    }
                    None => rest.push(r),
                }
            }
            pending = rest;
            if pending.is_empty() || pending.len() == before {
                break;
            }
        }
        self.riders = pending;
    }

    /// Moves a kept object to a new pose, its riders with it.
    pub(crate) fn repose(&mut self, name: &str, pos: [f64; 3], yaw: f64) {
        self.lift_riders(name);
        if let Some(o) = self.layout.objects.iter_mut().find(|o| o.name == name) {
            o.pos = pos.map(round);
            o.yaw = norm_yaw(yaw);
        }
        let room = self.layout.room.clone();
        let mut layout = std::mem::replace(&mut self.layout, LaidOutScene::new(0, room));
        self.land_riders(&mut layout);
        self.layout = layout;
    }

    /// Gives the objects their own plan group when they are not all of theirs (so a
    /// relation, colour or size can apply to them alone). Returns their group ids.
    pub(crate) fn isolate(&mut self, names: &[String]) -> Vec<String> {
        let mut groups: Vec<String> = Vec::new();
        let mut by_group: Vec<(String, Vec<String>)> = Vec::new();
        for n in names {
            let Some(g) = self.asset_of(n).map(|f| f.group.clone()) else { continue };
            match by_group.iter_mut().find(|(x, _)| *x == g) {
                Some((_, v)) => v.push(n.clone()),
                None => by_group.push((g, vec![n.clone()])),
            }
        }
        for (g, members) in by_group {
            let Some(plan_group) = self.plan.object(&g).cloned() else {
                groups.push(g);
                continue;
            };
            let all = self.forged.objects.iter().filter(|o| o.group == g).count();
            if members.len() == all {
                groups.push(g);
                continue;
            }
            let id = self.unique_group_id(&format!("{g}_{}", members[0]));
            let mut ng = plan_group.clone();
            ng.id = id.clone();
            ng.count = members.len() as u32;
            if let Some(old) = self.plan.objects.iter_mut().find(|o| o.id == g) {
                old.count = old.count.saturating_sub(members.len() as u32).max(1);
            }
            let pos = self.plan.objects.iter().position(|o| o.id == g).map_or(self.plan.objects.len(), |p| p + 1);
            self.plan.objects.insert(pos, ng);
            let copies: Vec<Relation> = self
                .plan
                .relations
                .iter()
                .filter(|r| r.subject == g)
                .map(|r| Relation { subject: id.clone(), kind: r.kind.clone() })
                .collect();
            self.plan.relations.extend(copies);
            for m in &members {
                if let Some(f) = self.forged.objects.iter_mut().find(|o| &o.name == m) {
                    f.group = id.clone();
                }
                if let Some(o) = self.layout.objects.iter_mut().find(|o| &o.name == m) {
                    o.group = id.clone();
                }
                for r in self.riders.iter_mut().filter(|r| &r.object.name == m) {
                    r.object.group = id.clone();
                }
            }
            groups.push(id);
        }
        groups
    }

    pub(crate) fn unique_group_id(&self, base: &str) -> String {
        let base = sw_planner::llm::sanitize_id(base);
        let taken =
            |id: &str| self.plan.objects.iter().any(|o| o.id == id) || self.plan.robots.iter().any(|r| r.id == id);
        if !taken(&base) {
            return base;
        }
        (2..).map(|k| format!("{base}_{k}")).find(|c| !taken(c)).unwrap_or(base)
    }

    pub(crate) fn unique_name(&self, base: &str) -> String {
        let n = self
            .forged
            .objects
            .iter()
            .map(|o| o.name.as_str())
            .chain(self.forged.robots.iter().map(|r| r.name.as_str()))
            .chain(self.removed.iter().map(String::as_str))
            .filter_map(|name| {
                name.strip_prefix(base).and_then(|r| r.strip_prefix('_')).and_then(|k| k.parse::<u32>().ok())
            })
            .max()
            .unwrap_or(0);
        format!("{base}_{}", n + 1)
    }

    /// Drops a group's positional relations (those placing it in the room).
    pub(crate) fn clear_placement(&mut self, group: &str) {
        self.plan.relations.retain(|r| r.subject != group);
    }

    /// Removes an object (not its riders) from plan, layout and assets.
    pub(crate) fn drop_object(&mut self, name: &str) {
        let group = self.asset_of(name).map(|f| f.group.clone());
        self.forged.objects.retain(|o| o.name != name);
        self.layout.objects.retain(|o| o.name != name);
        self.free.remove(name);
        if let Some(g) = group {
            let left = self.forged.objects.iter().filter(|o| o.group == g).count() as u32;
            if left == 0 {
                self.plan.objects.retain(|o| o.id != g);
                self.plan.relations.retain(|r| r.subject != g && !r.kind.targets().contains(&g.as_str()));
                for r in &mut self.plan.robots {
                    if r.near.as_deref() == Some(g.as_str()) {
                        r.near = None;
                    }
                    if matches!(&r.mount, Mount::OnSurface { target } if *target == g) {
                        r.mount = Mount::Auto;
                    }
                }
            } else if let Some(pg) = self.plan.objects.iter_mut().find(|o| o.id == g) {
                pg.count = left;
            }
        }
        self.removed.push(name.to_string());
    }

    pub(crate) fn drop_robot(&mut self, name: &str) {
        let group = self.forged.robots.iter().find(|r| r.name == name).map(|r| r.group.clone());
        let carrier = self
            .layout
            .robots
            .iter()
            .find(|r| r.name == name && r.mount != "surface")
            .and_then(|r| r.mounted_on.clone());
        self.forged.robots.retain(|r| r.name != name);
        self.layout.robots.retain(|r| r.name != name);
        self.free.remove(name);
        if let Some(c) = carrier {
            self.forged.objects.retain(|o| o.name != c);
            self.layout.objects.retain(|o| o.name != c);
            self.removed.push(c);
        }
        if let Some(g) = group {
            let left = self.forged.robots.iter().filter(|r| r.group == g).count() as u32;
            if left == 0 {
                self.plan.robots.retain(|r| r.id != g);
            } else if let Some(p) = self.plan.robots.iter_mut().find(|r| r.id == g) {
                p.count = left;
            }
        }
        self.removed.push(name.to_string());
    }

    /// The kept objects whose stated relations are to one of `names` (chairs next to a
    /// table that has to make way, directly or through others): placed again with them, so
    /// the solver honours those relations around the objects' new places. Never `keep`
    /// (the object the user put somewhere) nor an item riding on one of them.
    pub(crate) fn related_to(&self, names: &[String], keep: &str) -> Vec<String> {
        let group_of = |n: &str| self.layout.object(n).map(|o| o.group.clone());
        let mut groups: Vec<String> = names.iter().filter_map(|n| group_of(n)).collect();
        let mut out: Vec<String> = Vec::new();
        loop {
            let follow: Vec<String> = self
                .plan
                .relations
                .iter()
                .filter(|r| {
                    !groups.contains(&r.subject) && r.kind.targets().iter().any(|t| groups.iter().any(|g| g == t))
                })
                .map(|r| r.subject.clone())
                .collect();
            if follow.is_empty() {
                break;
            }
            groups.extend(follow);
        }
        let riding: Vec<String> =
            names.iter().map(String::as_str).chain([keep]).flat_map(|n| self.riders_of(n)).collect();
        for o in &self.layout.objects {
            if groups.contains(&o.group)
                && o.name != keep
                && !names.contains(&o.name)
                && !riding.contains(&o.name)
                && self.robots_on(&o.name).is_empty()
            {
                out.push(o.name.clone());
            }
        }
        // An item riding on a related object goes with its host.
        let riders: Vec<String> = out.iter().flat_map(|n| self.riders_of(n)).collect();
        out.retain(|n| !riders.contains(n));
        out
    }

    /// Makes objects free: the solver will place them (riders lifted first).
    pub(crate) fn free_objects(&mut self, names: &[String]) {
        for n in names {
            self.lift_riders(n);
            self.layout.objects.retain(|o| &o.name != n);
            self.free.insert(n.clone());
        }
    }

    /// The asset of one instance of `group` from its seed.
    pub(crate) fn make_instance(&self, group: &ObjectPlan, name: &str, seed: u64) -> Result<ForgedObject, OpError> {
        let (asset, tags, label) = make_seeded(group, seed).map_err(|e| format!("{}: {e}", group.phrase))?;
        Ok(ForgedObject {
            name: name.to_string(),
            group: group.id.clone(),
            category: group.category.clone(),
            label,
            asset,
            tags,
            carries_robot: None,
        })
    }

    /// Makes the assets of a group's objects again (after a colour or size change),
    /// each from its own seed.
    pub(crate) fn remake(&mut self, group: &str) -> Result<(), OpError> {
        let Some(g) = self.plan.object(group).cloned() else { return Ok(()) };
        let names: Vec<(String, u64)> =
            self.forged.objects.iter().filter(|o| o.group == group).map(|o| (o.name.clone(), o.asset.seed)).collect();
        for (name, seed) in names {
            let f = self.make_instance(&g, &name, seed)?;
            for n in &f.asset.notes {
                if !n.contains("labelled proxy") {
                    self.warnings.push(Warning::new(sw_plan::Stage::Forge, "size_clamped", format!("{name}: {n}")));
                }
            }
            if let Some(slot) = self.forged.objects.iter_mut().find(|o| o.name == name) {
                *slot = f;
            }
        }
        Ok(())
    }

    /// Places `name` beside `anchor` on one of `sides`, here rather than by the solver.
    pub(crate) fn place_beside(&mut self, name: &str, anchor: &str, side: Spatial) -> Result<(), OpError> {
        let a = self.layout.object(anchor).cloned().ok_or_else(|| format!("{anchor} is not in the scene"))?;
        let yaw = self.layout.object(name).map_or(0.0, |o| o.yaw);
        let ab = union(&self.boxes_at(anchor, a.pos, a.yaw));
        let local = union(&self.boxes_at(name, [0.0; 3], yaw));
        let (z, support) = match &a.support {
            Support::Object { .. } => (a.pos[2], a.support.clone()),
            _ => (0.0, Support::Floor),
        };
        let view = self.view();
        let f = sw_edit::resolve::forward(&view);
        let r = sw_edit::resolve::right(&view);
        let front = [-a.yaw.sin(), a.yaw.cos()];
        let sides: Vec<[f64; 2]> = match side {
            Spatial::LeftOf => vec![[-r[0], -r[1]]],
            Spatial::RightOf => vec![r],
            Spatial::InFrontOf => vec![front],
            Spatial::Behind => vec![[-front[0], -front[1]]],
            _ => vec![r, [-r[0], -r[1]], [-f[0], -f[1]], f],
        };
        let ignore: Vec<String> = self.riders_of(name).into_iter().chain([name.to_string()]).collect();
        let mut best: Option<(f64, [f64; 3])> = None;
        for dir in sides {
            let along = [-dir[1], dir[0]];
            for gap in [0.05, 0.15, 0.3, 0.5, 0.8, 1.2] {
                for slide in [0.0, 0.25, -0.25, 0.5, -0.5, 0.75, -0.75, 1.0, -1.0, 1.5, -1.5] {
                    // Distance from the anchor's centre to the object's centre along `dir`.
                    let ca = [(ab.min[0] + ab.max[0]) / 2.0, (ab.min[1] + ab.max[1]) / 2.0];
                    let half_a =
                        (ab.max[0] - ab.min[0]) / 2.0 * dir[0].abs() + (ab.max[1] - ab.min[1]) / 2.0 * dir[1].abs();
                    let half_o = (local.max[0] - local.min[0]) / 2.0 * dir[0].abs()
                        + (local.max[1] - local.min[1]) / 2.0 * dir[1].abs();
                    let d = half_a + gap + half_o;
                    let co = [ca[0] + dir[0] * d + along[0] * slide, ca[1] + dir[1] * d + along[1] * slide];
                    // The asset origin is offset from its footprint centre by the local bounds.
                    let lc = [(local.min[0] + local.max[0]) / 2.0, (local.min[1] + local.max[1]) / 2.0];
                    let pos = [co[0] - lc[0], co[1] - lc[1], z];
                    if self.fits(name, pos, yaw, &ignore).is_ok() && self.on_host_surface(name, pos, yaw, &support) {
                        let cost = gap + slide.abs() * 0.5;
                        if best.is_none_or(|(c, _)| cost < c) {
                            best = Some((cost, pos));
                        }
                    }
                }
                if best.is_some() {
                    break;
                }
            }
        }
        let (_, pos) = best.ok_or_else(|| format!("there is no free space {} {anchor} for {name}", side.words()))?;
        if let Some(o) = self.layout.objects.iter_mut().find(|o| o.name == name) {
            o.support = support;
        }
        self.repose(name, pos, yaw);
        Ok(())
    }

    /// An item on a surface stays within its host's footprint.
    pub(crate) fn on_host_surface(&self, name: &str, pos: [f64; 3], yaw: f64, support: &Support) -> bool {
        let Support::Object { object, .. } = support else { return true };
        let Some(h) = self.layout.object(object) else { return false };
        let hb = union(&self.boxes_at(object, h.pos, h.yaw));
        let b = union(&self.boxes_at(name, pos, yaw));
        b.min[0] >= hb.min[0] - EPS
            && b.max[0] <= hb.max[0] + EPS
            && b.min[1] >= hb.min[1] - EPS
            && b.max[1] <= hb.max[1] + EPS
    }

    /// The solver's input: every object, pinned or free, except riders (they are put
    /// back on their hosts afterwards).
    pub(crate) fn items(&self) -> Vec<ObjectItem<'_>> {
        self.forged
            .objects
            .iter()
            .filter(|o| !self.riders.iter().any(|r| r.object.name == o.name))
            .map(|o| ObjectItem {
                name: o.name.clone(),
                group: o.group.clone(),
                category: o.category.clone(),
                label: o.label.clone(),
                asset: &o.asset,
                tags: o.tags.clone(),
                carries_robot: o.carries_robot.clone(),
            })
            .collect()
    }
}

/// A layout entry for an object placed by the edit itself (its pose is set after).
pub(crate) fn placed_stub(f: &ForgedObject) -> PlacedObject {
    // The layout records the extent of the collision geometry.
    let s = union(&f.asset.collision_aabbs()).size();
    PlacedObject {
        name: f.name.clone(),
        group: f.group.clone(),
        category: f.category.clone(),
        label: f.label.clone(),
        pos: [0.0; 3],
        yaw: 0.0,
        size: s.map(round),
        support: Support::Floor,
        movable: f.asset.is_free(),
        mass: match f.asset.mass {
            sw_geom::MassModel::Free { mass } => Some(round(mass)),
            sw_geom::MassModel::Static => None,
        },
        asset_seed: f.asset.seed,
        added: false,
    }
}

pub(crate) fn round(x: f64) -> f64 {
    (x * 1e7).round() / 1e7
}

pub(crate) fn norm_yaw(y: f64) -> f64 {
    let mut y = y % (2.0 * std::f64::consts::PI);
    if y <= -std::f64::consts::PI {
        y += 2.0 * std::f64::consts::PI;
    } else if y > std::f64::consts::PI {
        y -= 2.0 * std::f64::consts::PI;
    }
    for q in [0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI, -std::f64::consts::FRAC_PI_2] {
        if (y - q).abs() < 1e-9 {
            return q;
        }
    }
    y
}
