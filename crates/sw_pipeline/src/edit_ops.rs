//! The operations of an edit: remove, add, move, replace, rotate, resize, recolour —
//! each applied to the scene in memory ([`Work`]), everything else pinned where it was.

use sw_edit::{EditOp, Placement, Reference, Resize, Spatial};
use sw_layout::RobotMount;
use sw_plan::{Corner, ExplicitSize, Mount, PlacedObject, Relation, RelationKind, RobotPlan, Support, Wall, Warning};

use crate::edit_work::{OpError, Work, placed_stub};
use crate::forge::{forge_with, instance_seed, slug};

impl Work {
    /// Adds the objects (and robots) a phrase describes; returns the new object names.
    pub(crate) fn add_phrase(
        &mut self,
        what: &str,
        relations: &[RelationKind],
    ) -> Result<(Vec<String>, Vec<String>), OpError> {
        let sub = sw_planner::plan(what).map_err(|e| format!("cannot read \"{what}\": {e}"))?;
        if sub.objects.is_empty() && sub.robots.is_empty() {
            return Err(format!("\"{what}\" names no object or robot"));
        }
        let mut names = Vec::new();
        let mut renamed: Vec<(String, String)> = Vec::new();
        for g in &sub.objects {
            let id = self.unique_group_id(&g.id);
            renamed.push((g.id.clone(), id.clone()));
            let mut ng = g.clone();
            ng.id = id.clone();
            self.plan.objects.push(ng.clone());
            for k in 0..ng.count {
                let base = if ng.category == "proxy" {
                    slug(ng.proxy.as_ref().map_or("object", |p| p.label.as_str()))
                } else {
                    ng.category.clone()
                };
                let name = self.unique_name(&base);
                let vary = ng.proxy.is_some() || sw_catalog::find(&ng.category).is_none_or(|c| c.vary_per_instance);
                let seed = instance_seed(self.seed, &format!("edit:{id}"), if vary { k } else { 0 });
                let f = self.make_instance(&ng, &name, seed)?;
                self.forged.objects.push(f);
                self.free.insert(name.clone());
                names.push(name);
            }
            for kind in relations {
                self.plan.relations.push(Relation { subject: id.clone(), kind: kind.clone() });
            }
        }
        let rename = |s: &str| renamed.iter().find(|(a, _)| a == s).map_or(s.to_string(), |(_, b)| b.clone());
        for r in &sub.relations {
            let kind = match &r.kind {
                RelationKind::On { target } => RelationKind::On { target: rename(target) },
                RelationKind::Under { target } => RelationKind::Under { target: rename(target) },
                RelationKind::NextTo { target } => RelationKind::NextTo { target: rename(target) },
                RelationKind::InFrontOf { target } => RelationKind::InFrontOf { target: rename(target) },
                RelationKind::Around { target } => RelationKind::Around { target: rename(target) },
                RelationKind::Between { first, second } => {
                    RelationKind::Between { first: rename(first), second: rename(second) }
                }
                k => k.clone(),
            };
            self.plan.relations.push(Relation { subject: rename(&r.subject), kind });
        }
        let robots = self.add_robots(&sub.robots, relations)?;
        Ok((names, robots))
    }

    /// Adds robots (with their pedestals or carts); returns their names.
    pub(crate) fn add_robots(
        &mut self,
        robots: &[RobotPlan],
        relations: &[RelationKind],
    ) -> Result<Vec<String>, OpError> {
        let mut out = Vec::new();
        for r in robots {
            let mut rp = r.clone();
            rp.id = self.unique_group_id(&r.id);
            for k in relations {
                match k {
                    RelationKind::On { target } => rp.mount = Mount::OnSurface { target: target.clone() },
                    RelationKind::NextTo { target } | RelationKind::InFrontOf { target } => {
                        rp.near = Some(target.clone())
                    }
                    _ => {}
                }
            }
            let mut mini = self.plan.clone();
            mini.robots = vec![rp.clone()];
            let made = forge_with(&mini, self.seed, &mut |_, _| Err("skipped".into()));
            self.plan.robots.push(rp.clone());
            for mut item in made.robots {
                let base = item.model.clone();
                let name = self.unique_name(&base);
                let old = item.name.clone();
                item.name = name.clone();
                if let RobotMount::Carrier { object } = &item.mount {
                    let carrier_old = object.clone();
                    if let Some(mut c) = made.objects.iter().find(|o| o.name == carrier_old).cloned() {
                        let cname = self.unique_name(&c.category);
                        c.name = cname.clone();
                        c.carries_robot = Some(name.clone());
                        self.free.insert(cname.clone());
                        self.forged.objects.push(c);
                        item.mount = RobotMount::Carrier { object: cname.clone() };
                        self.added.push(cname);
                    }
                }
                let _ = old;
                self.free.insert(name.clone());
                self.forged.robots.push(item);
                out.push(name);
            }
        }
        Ok(out)
    }

    /// The plan group an anchor's objects form (isolated when they are part of one).
    pub(crate) fn anchor_group(&mut self, of: &Reference, what: &str) -> Result<(String, Vec<String>), OpError> {
        let sel = self.select(of)?;
        if sel.objects.is_empty() {
            return Err(format!("{} is not an object {what} can go by", of.describe()));
        }
        let groups = self.isolate(&sel.objects);
        Ok((groups[0].clone(), sel.objects))
    }

    /// The relation a placement gives a group, when the solver is to place it.
    pub(crate) fn relation_for(&mut self, place: &Placement, what: &str) -> Result<Option<RelationKind>, OpError> {
        Ok(Some(match place {
            Placement::On { of } => RelationKind::On { target: self.anchor_group(of, what)?.0 },
            Placement::Under { of } => RelationKind::Under { target: self.anchor_group(of, what)?.0 },
            Placement::Beside { side: Spatial::NextTo, of } => {
                RelationKind::NextTo { target: self.anchor_group(of, what)?.0 }
            }
            Placement::Beside { side: Spatial::InFrontOf, of } => {
                RelationKind::InFrontOf { target: self.anchor_group(of, what)?.0 }
            }
            Placement::AgainstWall { wall } => RelationKind::AgainstWall { wall: *wall },
            Placement::InCorner { corner } => RelationKind::InCorner { corner: *corner },
            Placement::NearDoor => RelationKind::NearDoor,
            Placement::InCenter => RelationKind::InCenter,
            Placement::Beside { .. } | Placement::Shift { .. } => return Ok(None),
        }))
    }

    /// Applies one operation.
    pub(crate) fn apply(&mut self, op: &EditOp) -> Result<(), OpError> {
        match op {
            EditOp::Remove { target } => {
                let sel = self.select(target)?;
                for o in &sel.objects {
                    let carried: Vec<String> =
                        self.robots_on(o).into_iter().filter(|r| !sel.robots.contains(r)).collect();
                    if let Some(r) = carried.first() {
                        return Err(format!("{o} carries {r}; remove or move the robot first"));
                    }
                }
                for o in &sel.objects {
                    // What rests on it is placed again (on another of its kind, or the floor).
                    let riders = self.riders_of(o);
                    self.layout.objects.retain(|x| !riders.contains(&x.name));
                    for r in riders {
                        self.free.insert(r);
                    }
                    self.drop_object(o);
                }
                for r in &sel.robots {
                    self.drop_robot(r);
                }
                self.ops.push(format!("remove {}", sel.names().join(", ")));
            }
            EditOp::Add { what, place } => {
                let (relations, beside) = match place {
                    None => (Vec::new(), None),
                    Some(Placement::Shift { .. }) => {
                        return Err(format!("add \"{what}\" where? a shift needs something to move"));
                    }
                    Some(Placement::Beside { side, of }) if !matches!(side, Spatial::NextTo | Spatial::InFrontOf) => {
                        let anchor = self.select(of)?;
                        let a = anchor
                            .objects
                            .first()
                            .cloned()
                            .ok_or_else(|| format!("{} is not an object", of.describe()))?;
                        (Vec::new(), Some((*side, a)))
                    }
                    Some(p) => (self.relation_for(p, what)?.into_iter().collect(), None),
                };
                let (names, robots) = self.add_phrase(what, &relations)?;
                if let Some((side, anchor)) = beside {
                    for n in &names {
                        // Kept where it is put: it joins the layout here.
                        let f = self.asset_of(n).cloned();
                        if let Some(f) = f {
                            self.layout.objects.push(placed_stub(&f));
                            self.free.remove(n);
                            self.place_beside(n, &anchor, side)?;
                        }
                    }
                }
                self.added.extend(names.iter().cloned());
                self.added.extend(robots.iter().cloned());
                let mut all = names;
                all.extend(robots);
                let where_ = place.as_ref().map(describe_place).unwrap_or_default();
                self.ops.push(format!("add {}{where_}", all.join(", ")));
            }
            EditOp::Move { target, to } => {
                let sel = self.select(target)?;
                if !sel.robots.is_empty() {
                    self.move_robots(&sel.robots, to)?;
                }
                for name in &sel.objects {
                    self.move_object(name, to)?;
                }
                self.moved.extend(sel.names());
                self.ops.push(format!("move {}{}", sel.names().join(", "), describe_place(to)));
            }
            EditOp::Rotate { target, degrees } => {
                let sel = self.select(target)?;
                if !sel.robots.is_empty() {
                    return Err("robots keep the heading the layout gave them; rotate objects only".into());
                }
                for name in &sel.objects {
                    let o = self.layout.object(name).cloned().ok_or_else(|| format!("{name} is not placed"))?;
                    let yaw = o.yaw + degrees.to_radians();
                    let ignore: Vec<String> = self.riders_of(name);
                    self.fits(name, o.pos, yaw, &ignore)
                        .map_err(|b| format!("{name} cannot turn {degrees}° where it stands: it would hit {b}"))?;
                    self.repose(name, o.pos, yaw);
                }
                self.moved.extend(sel.objects.iter().cloned());
                self.ops.push(format!("rotate {} by {degrees}°", sel.objects.join(", ")));
            }
            EditOp::Resize { target, resize } => {
                let sel = self.select(target)?;
                if !sel.robots.is_empty() {
                    return Err("robots cannot be resized".into());
                }
                let groups = self.isolate(&sel.objects);
                for g in &groups {
                    self.resize_group(g, resize)?;
                }
                self.refit(&sel.objects)?;
                self.modified.extend(sel.objects.iter().cloned());
                self.ops.push(format!("resize {}", sel.objects.join(", ")));
            }
            EditOp::Recolor { target, color } => {
                let sel = self.select(target)?;
                if !sel.robots.is_empty() {
                    return Err("robots keep their own colours".into());
                }
                let c = sw_planner::vocab::color(color)
                    .ok_or_else(|| format!("'{color}' is not a colour the planner knows"))?;
                let groups = self.isolate(&sel.objects);
                for g in &groups {
                    if let Some(pg) = self.plan.objects.iter_mut().find(|o| &o.id == g) {
                        pg.color = Some(sw_plan::NamedColor { name: color.clone(), rgba: c.rgba });
                    }
                    self.remake(g)?;
                }
                self.modified.extend(sel.objects.iter().cloned());
                self.ops.push(format!("recolour {} {color}", sel.objects.join(", ")));
            }
            EditOp::Replace { target, with } => {
                let sel = self.select(target)?;
                if !sel.robots.is_empty() {
                    return Err("replace objects; remove and add robots instead".into());
                }
                let old: Vec<PlacedObject> =
                    sel.objects.iter().filter_map(|n| self.layout.object(n).cloned()).collect();
                let groups = self.isolate(&sel.objects);
                let inherited: Vec<RelationKind> = self
                    .plan
                    .relations
                    .iter()
                    .filter(|r| groups.contains(&r.subject))
                    .map(|r| r.kind.clone())
                    .collect();
                for o in &sel.objects {
                    let carried = self.robots_on(o);
                    if let Some(r) = carried.first() {
                        return Err(format!("{o} carries {r}; move or remove the robot first"));
                    }
                }
                let riders: Vec<String> = sel.objects.iter().flat_map(|o| self.riders_of(o)).collect();
                let mut sub = sw_planner::plan(with).map_err(|e| format!("cannot read \"{with}\": {e}"))?;
                if sub.objects.is_empty() {
                    return Err(format!("\"{with}\" names no object"));
                }
                sub.objects.truncate(1);
                let count = old.len().max(1) as u32;
                let phrase = sub.objects[0].phrase.clone();
                for name in &sel.objects {
                    self.layout.objects.retain(|x| !riders.contains(&x.name));
                    self.drop_object(name);
                }
                let (names, _) = self.add_phrase(&phrase, &inherited)?;
                // The replacement group holds as many as were replaced.
                let new_group = names.first().and_then(|n| self.asset_of(n)).map(|f| f.group.clone());
                if let Some(g) = &new_group {
                    let have = names.len() as u32;
                    if have < count {
                        let pg = self.plan.object(g).cloned();
                        if let Some(pg) = pg {
                            let mut extra = Vec::new();
                            for k in have..count {
                                let name = self.unique_name(
                                    &self.asset_of(&names[0]).map_or(pg.category.clone(), |f| name_base(&f.name)),
                                );
                                let seed = instance_seed(self.seed, &format!("edit:{g}"), k);
                                let f = self.make_instance(&pg, &name, seed)?;
                                self.forged.objects.push(f);
                                self.free.insert(name.clone());
                                extra.push(name);
                            }
                            if let Some(p) = self.plan.objects.iter_mut().find(|o| &o.id == g) {
                                p.count = count;
                            }
                            let mut all = names.clone();
                            all.extend(extra);
                            self.finish_replace(&old, &all, &riders, g)?;
                        }
                    } else {
                        self.finish_replace(&old, &names, &riders, g)?;
                    }
                }
                self.ops.push(format!("replace {} with {with}", sel.objects.join(", ")));
            }
        }
        Ok(())
    }

    /// Puts each replacement where the replaced object stood, when it fits there; its
    /// riders go back on it (or are placed again).
    pub(crate) fn finish_replace(
        &mut self,
        old: &[PlacedObject],
        names: &[String],
        riders: &[String],
        group: &str,
    ) -> Result<(), OpError> {
        for (o, n) in old.iter().zip(names) {
            let ignore: Vec<String> = riders.to_vec();
            if self.fits(n, o.pos, o.yaw, &ignore).is_ok() {
                let f = self.asset_of(n).cloned();
                if let Some(f) = f {
                    let mut p = placed_stub(&f);
                    p.pos = o.pos;
                    p.yaw = o.yaw;
                    p.support = o.support.clone();
                    self.layout.objects.push(p);
                    self.free.remove(n);
                }
            }
        }
        // Riders: their `on` relations now point at the replacement.
        for r in riders {
            self.free.insert(r.clone());
        }
        let old_groups: Vec<String> = old.iter().map(|o| o.group.clone()).collect();
        for rel in &mut self.plan.relations {
            if let RelationKind::On { target } = &mut rel.kind
                && old_groups.contains(target)
            {
                *target = group.to_string();
            }
        }
        self.added.extend(names.iter().cloned());
        Ok(())
    }

    pub(crate) fn move_object(&mut self, name: &str, to: &Placement) -> Result<(), OpError> {
        let o = self.layout.object(name).cloned().ok_or_else(|| format!("{name} is not placed"))?;
        if let Some(r) = self.robots_on(name).first() {
            return Err(format!("{name} carries {r}; move the robot instead"));
        }
        match to {
            Placement::Shift { east, north, right, forward } => {
                let d = self.shift_delta(*east, *north, *right, *forward);
                let pos = [o.pos[0] + d[0], o.pos[1] + d[1], o.pos[2]];
                let ignore = self.riders_of(name);
                self.fits(name, pos, o.yaw, &ignore)
                    .map_err(|b| format!("{name} cannot move there: it would hit {b}"))?;
                if !self.on_host_surface(name, pos, o.yaw, &o.support) {
                    return Err(format!("{name} would leave the surface it rests on"));
                }
                self.repose(name, pos, o.yaw);
            }
            Placement::Beside { side, of }
                if !matches!(side, Spatial::NextTo | Spatial::InFrontOf) || o.support != Support::Floor =>
            {
                let anchor = self
                    .select(of)?
                    .objects
                    .first()
                    .cloned()
                    .ok_or_else(|| format!("{} is not an object", of.describe()))?;
                if anchor == name {
                    return Err(format!("{name} cannot move {} itself", side.words()));
                }
                self.place_beside(name, &anchor, *side)?;
            }
            Placement::Beside { side, of } => {
                // Beside a floor object: here, next to it; the solver only if no side is free.
                let anchor = self
                    .select(of)?
                    .objects
                    .first()
                    .cloned()
                    .ok_or_else(|| format!("{} is not an object", of.describe()))?;
                if anchor == name {
                    return Err(format!("{name} cannot move next to itself"));
                }
                self.place_beside(name, &anchor, *side)?;
            }
            place => {
                let rel = self.relation_for(place, name)?.ok_or_else(|| "unsupported place".to_string())?;
                if let RelationKind::On { target } | RelationKind::Under { target } = &rel
                    && self.forged.objects.iter().any(|f| &f.group == target && f.name == name)
                {
                    return Err(format!("{name} cannot go on or under itself"));
                }
                let g = self.isolate(&[name.to_string()]);
                let group = g.first().cloned().unwrap_or_default();
                self.clear_placement(&group);
                self.plan.relations.push(Relation { subject: group, kind: rel });
                self.free_objects(&[name.to_string()]);
            }
        }
        Ok(())
    }

    pub(crate) fn move_robots(&mut self, robots: &[String], to: &Placement) -> Result<(), OpError> {
        for name in robots {
            let r = self
                .layout
                .robots
                .iter()
                .find(|x| &x.name == name)
                .cloned()
                .ok_or_else(|| format!("{name} is not placed"))?;
            let carrier = if r.mount != "surface" { r.mounted_on.clone() } else { None };
            match to {
                Placement::Beside { of, .. } | Placement::On { of } => {
                    let (group, _) = self.anchor_group(of, name)?;
                    if let Some(item) = self.forged.robots.iter_mut().find(|x| &x.name == name) {
                        match to {
                            Placement::On { .. } if item.is_arm && carrier.is_none() => {
                                item.mount = RobotMount::Surface { group: group.clone() }
                            }
                            Placement::On { .. } => {
                                return Err(format!("{name} stands on its own mount; move it next to {group} instead"));
                            }
                            _ => item.near = Some(group.clone()),
                        }
                    }
                    if let Some(p) = self.plan.robots.iter_mut().find(|p| p.id == r.group) {
                        p.near = Some(group);
                    }
                    self.layout.robots.retain(|x| &x.name != name);
                    self.free.insert(name.clone());
                    if let Some(c) = carrier {
                        self.layout.objects.retain(|x| x.name != c);
                        self.free.insert(c);
                    }
                }
                _ => {
                    return Err(format!(
                        "move robots next to or onto an object (e.g. 'move {name} next to the table')"
                    ));
                }
            }
        }
        Ok(())
    }

    pub(crate) fn resize_group(&mut self, group: &str, resize: &Resize) -> Result<(), OpError> {
        let Some(first) = self.forged.objects.iter().find(|o| o.group == group).cloned() else { return Ok(()) };
        let now = first.asset.bounds().size();
        let target = [
            resize.width.unwrap_or(now[0] * resize.scale[0]),
            resize.depth.unwrap_or(now[1] * resize.scale[1]),
            resize.height.unwrap_or(now[2] * resize.scale[2]),
        ];
        if target.iter().any(|v| !(v.is_finite() && *v > 0.01 && *v <= 50.0)) {
            return Err(format!("{:.2} × {:.2} × {:.2} m is not a plausible size", target[0], target[1], target[2]));
        }
        let Some(pg) = self.plan.objects.iter_mut().find(|o| o.id == group) else { return Ok(()) };
        match &mut pg.proxy {
            Some(p) => {
                p.size = sw_plan::Dims::new(
                    target[0].clamp(0.02, 20.0),
                    target[1].clamp(0.02, 20.0),
                    target[2].clamp(0.02, 20.0),
                )
            }
            None => {
                pg.size.words.clear();
                pg.size.explicit = ExplicitSize {
                    width: Some(target[0]),
                    depth: Some(target[1]),
                    height: Some(target[2]),
                    ..Default::default()
                };
            }
        }
        self.remake(group)?;
        if let Some(f) = self.forged.objects.iter().find(|o| o.group == group) {
            let got = f.asset.bounds().size();
            if (0..3).any(|i| (got[i] - target[i]).abs() > 0.02 * target[i].max(0.05)) {
                self.warnings.push(Warning::new(
                    sw_plan::Stage::Forge,
                    "size_clamped",
                    format!(
                        "{}: asked for {:.2} × {:.2} × {:.2} m; the catalog's ranges give {:.2} × {:.2} × {:.2} m",
                        f.label, target[0], target[1], target[2], got[0], got[1], got[2]
                    ),
                ));
            }
        }
        Ok(())
    }

    /// After a change of geometry: objects stay where they are when they still fit;
    /// otherwise the solver places them (and says so).
    pub(crate) fn refit(&mut self, names: &[String]) -> Result<(), OpError> {
        for n in names {
            let Some(o) = self.layout.object(n).cloned() else { continue };
            let riders = self.riders_of(n);
            // What rests on a resized object is placed again on it (or elsewhere).
            self.layout.objects.retain(|x| !riders.contains(&x.name));
            for r in &riders {
                self.free.insert(r.clone());
            }
            if self.fits(n, o.pos, o.yaw, &[]).is_err() || !self.on_host_surface(n, o.pos, o.yaw, &o.support) {
                self.free_objects(std::slice::from_ref(n));
                self.moved.push(n.clone());
            }
        }
        Ok(())
    }

    pub(crate) fn shift_delta(&self, east: f64, north: f64, right: f64, forward: f64) -> [f64; 2] {
        let view = self.view();
        let f = sw_edit::resolve::forward(&view);
        let r = sw_edit::resolve::right(&view);
        [east + right * r[0] + forward * f[0], north + right * r[1] + forward * f[1]]
    }
}

fn name_base(name: &str) -> String {
    match name.rsplit_once('_') {
        Some((b, n)) if n.chars().all(|c| c.is_ascii_digit()) => b.to_string(),
        _ => name.to_string(),
    }
}

fn describe_place(p: &Placement) -> String {
    match p {
        Placement::Beside { side, of } => format!(" {} {}", side.words(), of.describe()),
        Placement::On { of } => format!(" on {}", of.describe()),
        Placement::Under { of } => format!(" under {}", of.describe()),
        Placement::AgainstWall { wall } => format!(" against the {} wall", wall.map_or("nearest", Wall::name)),
        Placement::InCorner { corner } => {
            format!(" in the {} corner", corner.map_or("nearest".to_string(), corner_name))
        }
        Placement::NearDoor => " near the door".into(),
        Placement::InCenter => " in the middle of the room".into(),
        Placement::Shift { east, north, right, forward } => {
            let mut parts = Vec::new();
            for (v, pos, neg) in [
                (east, "east", "west"),
                (north, "north", "south"),
                (right, "right", "left"),
                (forward, "forward", "back"),
            ] {
                if v.abs() > 1e-9 {
                    parts.push(format!("{:.2} m {}", v.abs(), if *v > 0.0 { pos } else { neg }));
                }
            }
            format!(" {}", parts.join(", "))
        }
    }
}

fn corner_name(c: Corner) -> String {
    match c {
        Corner::NorthEast => "north-east",
        Corner::NorthWest => "north-west",
        Corner::SouthEast => "south-east",
        Corner::SouthWest => "south-west",
    }
    .to_string()
}
