//! Structured edits from the viewer: an object put at a pose (dragged or turned), and a
//! library part — a catalog category or a generated mesh — placed at a point. The object
//! is kept inside the room (its footprint shifted back from the walls), set on the surface
//! under the point when it is a small item (else on the floor), pinned there, and whatever
//! it now stands in is taken out and placed again by the solver around it. The edit is
//! refused, with the reason, when the object cannot stand there at all.

use sw_geom::{Aabb, Pose};
use sw_plan::{Dims, ObjectPlan, ProxyPlan, Support, Warning};

use crate::edit_work::{OpError, Work, norm_yaw, overlap, placed_stub, union};
use crate::forge::{ForgedObject, slug};
use crate::parts::Part;

/// A structured edit.
#[derive(Debug, Clone)]
pub enum StructuredEdit {
    /// Put an object at `pos` (x, y in the room, metres), turned to `yaw_deg` when given.
    Move { object: String, pos: [f64; 2], yaw_deg: Option<f64> },
    /// Place one object of a catalog category at `pos`.
    PlaceCategory { category: String, pos: [f64; 2], yaw_deg: Option<f64> },
    /// Place a generated part (its mesh as binary STL, metres) at `pos`.
    PlaceMesh { asset_id: String, label: String, stl: Vec<u8>, pos: [f64; 2], yaw_deg: Option<f64> },
}

const WALL_GAP: f64 = 0.02;
const EPS: f64 = 1e-6;

/// A surface that can carry an item: its host, its name and its rectangle in the world.
struct Spot {
    host: String,
    surface: String,
    z: f64,
}

impl Work {
    /// Applies a structured edit.
    pub(crate) fn apply_structured(&mut self, e: &StructuredEdit) -> Result<(), OpError> {
        match e {
            StructuredEdit::Move { object, pos, yaw_deg } => {
                let what = self.put_at(object, *pos, *yaw_deg)?;
                self.moved.push(object.clone());
                self.ops.push(what);
            }
            StructuredEdit::PlaceCategory { category, pos, yaw_deg } => {
                let c = sw_catalog::find(category).ok_or_else(|| format!("'{category}' is not a catalog category"))?;
                let (names, _) = self.add_phrase(&format!("a {}", c.display), &[])?;
                let name = names.first().cloned().ok_or_else(|| format!("no {} could be made", c.display))?;
                // Only one, kept where it was dropped (not placed by the solver).
                for extra in names.iter().skip(1) {
                    self.drop_object(extra);
                }
                self.pin_new(&name)?;
                let what = self.put_at(&name, *pos, *yaw_deg)?;
                self.added.push(name.clone());
                self.ops.push(format!("add {}: {what}", c.display));
            }
            StructuredEdit::PlaceMesh { asset_id, label, stl, pos, yaw_deg } => {
                let name = self.add_part(asset_id, label, stl)?;
                let what = self.put_at(&name, *pos, *yaw_deg)?;
                self.added.push(name.clone());
                self.ops.push(format!("add the part \"{label}\": {what}"));
            }
        }
        Ok(())
    }

    /// Gives a new object a place in the kept layout (it is then posed by `put_at`).
    fn pin_new(&mut self, name: &str) -> Result<(), OpError> {
        let f = self.asset_of(name).cloned().ok_or_else(|| format!("{name} was not made"))?;
        self.layout.objects.push(placed_stub(&f));
        self.free.remove(name);
        Ok(())
    }

    /// A generated part as a new object: its own plan group (a labelled stand-in of its
    /// size), its asset from the mesh, its mesh kept with the package (`parts/`).
    fn add_part(&mut self, asset_id: &str, label: &str, stl: &[u8]) -> Result<String, OpError> {
        let part = Part::new(asset_id, label, stl.to_vec()).map_err(|e| format!("the part \"{label}\": {e}"))?;
        let size = part.size();
        let short = short_name(label);
        let group = self.unique_group_id(&short);
        let name = self.unique_name(&short);
        self.plan.objects.push(ObjectPlan {
            id: group.clone(),
            category: "proxy".into(),
            phrase: label.to_string(),
            count: 1,
            color: None,
            size: Default::default(),
            proxy: Some(ProxyPlan {
                label: label.to_string(),
                prior: "generated part".into(),
                size: Dims::new(size[0].max(0.001), size[1].max(0.001), size[2].max(0.001)),
                movable: part.entry.movable,
            }),
        });
        let mut tags = vec!["proxy".to_string()];
        if part.entry.movable {
            tags.push("tabletop".into());
        }
        self.forged.objects.push(ForgedObject {
            name: name.clone(),
            group,
            category: "proxy".into(),
            label: label.to_string(),
            asset: part.asset(),
            tags,
            carries_robot: None,
        });
        self.parts.push(part.for_object(&name));
        self.pin_new(&name)?;
        Ok(name)
    }

    /// Puts a kept object at (x, y), turned to `yaw_deg` when given; returns what it did.
    pub(crate) fn put_at(&mut self, name: &str, pos: [f64; 2], yaw_deg: Option<f64>) -> Result<String, OpError> {
        let Some(o) = self.layout.object(name).cloned() else {
            if self.layout.robots.iter().any(|r| r.name == name) {
                return Err(format!("{name} is a robot; robots move by words (\"move {name} next to the table\")"));
            }
            return Err(format!("there is no object named {name} in the scene"));
        };
        if let Some(r) = self.robots_on(name).first() {
            return Err(format!("{name} carries {r}; move the robot with words instead"));
        }
        if let Support::Wall { wall } = o.support {
            return Err(format!(
                "{name} hangs on the {} wall; move it with words (\"move {name} to the east wall\")",
                wall.name()
            ));
        }
        let yaw = norm_yaw(yaw_deg.map_or(o.yaw, f64::to_radians));
        let riders = self.riders_of(name);
        let ignore: Vec<String> = riders.iter().cloned().chain([name.to_string()]).collect();
        // Where it rests: a small item on the surface under the point (its own first), a
        // floor object on the floor.
        let spot = if o.movable || matches!(o.support, Support::Object { .. }) {
            self.surface_under(name, pos, &o.support, &ignore)
        } else {
            None
        };
        let (z, support) = match &spot {
            Some(s) => (s.z, Support::Object { object: s.host.clone(), surface: s.surface.clone() }),
            None => (if matches!(o.support, Support::Object { .. }) { 0.0 } else { o.pos[2] }, Support::Floor),
        };
        let (at, clamped) = self.clamp_into_room(name, [pos[0], pos[1], z], yaw)?;
        let at = match &spot {
            Some(s) => self.clamp_onto(name, at, yaw, s).unwrap_or(at),
            None => at,
        };
        let (objects, robots) = self.in_the_way(name, at, yaw, &ignore, spot.as_ref().map(|s| s.host.as_str()));
        if let Some(r) = robots.first() {
            return Err(format!("{name} would stand in {r}'s working space at ({:.2}, {:.2})", at[0], at[1]));
        }
        for other in &objects {
            if let Some(r) = self.robots_on(other).first() {
                return Err(format!("{name} would stand where {other} carries {r}"));
            }
        }
        // The user put it here: its old placement relations no longer apply.
        let group = self.isolate(&[name.to_string()]);
        if let Some(g) = group.first() {
            self.clear_placement(g);
        }
        // What is in the way makes room, and what was stated relative to it goes with it.
        let related = self.related_to(&objects, name);
        self.free_objects(&objects);
        self.free_objects(&related);
        let objects: Vec<String> = objects.into_iter().chain(related).collect();
        if let Some(p) = self.layout.objects.iter_mut().find(|x| x.name == name) {
            p.support = support.clone();
        }
        self.repose(name, at, yaw);
        let mut what = format!("{name} to ({:.2}, {:.2}) facing {:.0}°", at[0], at[1], yaw.to_degrees());
        if let Some(s) = &spot {
            what.push_str(&format!(" on {}", s.host));
        }
        if clamped {
            what.push_str(", kept inside the room");
            self.warnings.push(Warning::new(
                sw_plan::Stage::Layout,
                "moved_inside_room",
                format!(
                    "{name} was asked for at ({:.2}, {:.2}); it stands at ({:.2}, {:.2}) to stay inside the room",
                    pos[0], pos[1], at[0], at[1]
                ),
            ));
        }
        if !objects.is_empty() {
            what.push_str(&format!("; {} placed again around it", objects.join(", ")));
        }
        Ok(what)
    }

    /// Shifts `name` at a pose so that its footprint lies inside the room's walls.
    fn clamp_into_room(&self, name: &str, pos: [f64; 3], yaw: f64) -> Result<([f64; 3], bool), OpError> {
        let b = union(&self.boxes_at(name, pos, yaw));
        if b.min[0] > b.max[0] {
            return Ok((pos, false));
        }
        let s = self.layout.room.size;
        let (hw, hd) = (s.width / 2.0 - WALL_GAP, s.depth / 2.0 - WALL_GAP);
        if b.max[0] - b.min[0] > 2.0 * hw + EPS || b.max[1] - b.min[1] > 2.0 * hd + EPS {
            return Err(format!("{name} turned this way is wider than the {:.1} × {:.1} m room", s.width, s.depth));
        }
        if b.max[2] > s.height + EPS {
            return Err(format!("{name} would reach above the {:.1} m ceiling there", s.height));
        }
        let shift = |lo: f64, hi: f64, half: f64| {
            if lo < -half {
                -half - lo
            } else if hi > half {
                half - hi
            } else {
                0.0
            }
        };
        let dx = shift(b.min[0], b.max[0], hw);
        let dy = shift(b.min[1], b.max[1], hd);
        let moved = dx.abs() > EPS || dy.abs() > EPS;
        Ok(([pos[0] + dx, pos[1] + dy, pos[2]], moved))
    }

    /// Shifts an item so that its footprint stays on its host's surface.
    fn clamp_onto(&self, name: &str, pos: [f64; 3], yaw: f64, spot: &Spot) -> Option<[f64; 3]> {
        let host = self.layout.object(&spot.host)?;
        let surf = self.asset_of(&spot.host)?.asset.surfaces.iter().find(|s| s.name == spot.surface)?.clone();
        // The item's footprint in the host's frame.
        let (s, c) = (-host.yaw).sin_cos();
        let to_local = |x: f64, y: f64| {
            let (dx, dy) = (x - host.pos[0], y - host.pos[1]);
            (c * dx - s * dy, s * dx + c * dy)
        };
        let b = union(&self.boxes_at(name, pos, yaw));
        let mut rect = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
        for x in [b.min[0], b.max[0]] {
            for y in [b.min[1], b.max[1]] {
                let (lx, ly) = to_local(x, y);
                rect = [rect[0].min(lx), rect[1].min(ly), rect[2].max(lx), rect[3].max(ly)];
            }
        }
        let fit = |lo: f64, hi: f64, min: f64, max: f64| {
            if hi - lo > max - min {
                None
            } else if lo < min {
                Some(min - lo)
            } else if hi > max {
                Some(max - hi)
            } else {
                Some(0.0)
            }
        };
        let dx = fit(rect[0], rect[2], surf.min[0], surf.max[0])?;
        let dy = fit(rect[1], rect[3], surf.min[1], surf.max[1])?;
        // Back to the world.
        let (s2, c2) = host.yaw.sin_cos();
        Some([pos[0] + c2 * dx - s2 * dy, pos[1] + s2 * dx + c2 * dy, pos[2]])
    }

    /// The surface under (x, y) that could carry `name`: its current one when the point is
    /// on it, else the highest with room above for it.
    fn surface_under(&self, name: &str, pos: [f64; 2], current: &Support, ignore: &[String]) -> Option<Spot> {
        let height = union(&self.boxes_at(name, [0.0; 3], 0.0)).size()[2];
        let mut best: Option<(bool, Spot)> = None;
        for host in &self.layout.objects {
            if ignore.contains(&host.name) {
                continue;
            }
            let Some(asset) = self.asset_of(&host.name) else { continue };
            let (s, c) = (-host.yaw).sin_cos();
            let (dx, dy) = (pos[0] - host.pos[0], pos[1] - host.pos[1]);
            let (lx, ly) = (c * dx - s * dy, s * dx + c * dy);
            for surf in &asset.asset.surfaces {
                let inside = lx >= surf.min[0] && lx <= surf.max[0] && ly >= surf.min[1] && ly <= surf.max[1];
                if !inside || surf.clearance.is_some_and(|cl| cl < height) {
                    continue;
                }
                let own = matches!(current, Support::Object { object, surface } if *object == host.name && *surface == surf.name);
                let spot = Spot { host: host.name.clone(), surface: surf.name.clone(), z: host.pos[2] + surf.z };
                let better = match &best {
                    None => true,
                    Some((best_own, b)) => (own && !best_own) || (own == *best_own && spot.z > b.z),
                };
                if better {
                    best = Some((own, spot));
                }
            }
        }
        best.map(|b| b.1)
    }

    /// Kept objects and robots that `name` at a pose would overlap (its support excepted).
    fn in_the_way(
        &self,
        name: &str,
        pos: [f64; 3],
        yaw: f64,
        ignore: &[String],
        host: Option<&str>,
    ) -> (Vec<String>, Vec<String>) {
        let boxes = self.boxes_at(name, pos, yaw);
        let all = union(&boxes);
        let mut objects = Vec::new();
        for o in &self.layout.objects {
            if ignore.contains(&o.name) || Some(o.name.as_str()) == host {
                continue;
            }
            let other = self.boxes_at(&o.name, o.pos, o.yaw);
            if overlap(&all, &union(&other), 0.0) && boxes.iter().any(|b| other.iter().any(|c| overlap(b, c, 0.0))) {
                objects.push(o.name.clone());
            }
        }
        // An item resting on something else in the way goes with its host.
        let riders: Vec<String> = objects.iter().flat_map(|o| self.riders_of(o)).collect();
        objects.retain(|o| !riders.contains(o));
        let mut robots = Vec::new();
        for r in &self.layout.robots {
            let Some(item) = self.forged.robots.iter().find(|x| x.name == r.name) else { continue };
            let pose = Pose::from_pos_yaw(r.pos, r.yaw);
            let keep: Vec<Aabb> = item.keepout.iter().map(|k| k.transformed(&pose)).collect();
            if keep.iter().any(|k| boxes.iter().any(|b| overlap(b, k, 0.0))) {
                robots.push(r.name.clone());
            }
        }
        (objects, robots)
    }
}

/// A body name for a part from its description: the words before any dimensions or
/// details (`a flat washer: outer diameter …` → `flat_washer`), at most 32 characters.
fn short_name(label: &str) -> String {
    let head = label.split([':', ',', ';', '(']).next().unwrap_or(label);
    let head = head.split(" with ").next().unwrap_or(head);
    let words: Vec<&str> = head
        .split_whitespace()
        .filter(|w| !matches!(w.to_lowercase().as_str(), "a" | "an" | "the" | "one"))
        .take_while(|w| !w.chars().next().is_some_and(|c| c.is_ascii_digit()))
        .collect();
    let mut s = slug(&words.join(" "));
    if s.len() > 32 {
        let cut = s[..32].rfind('_').unwrap_or(32);
        s.truncate(cut);
    }
    if s.is_empty() || s == "object" { "part".into() } else { s }
}

#[cfg(test)]
mod tests {
    use super::short_name;

    #[test]
    fn part_names_are_the_words_before_the_details() {
        assert_eq!(short_name("a flat washer: outer diameter 120mm, inner 40mm"), "flat_washer");
        assert_eq!(short_name("A mounting plate 120 x 80 mm with four holes"), "mounting_plate");
        assert_eq!(
            short_name("an enormously long and needlessly descriptive name for a bracket"),
            "enormously_long_and_needlessly"
        );
        assert_eq!(short_name("120 mm cube"), "part");
    }
}
