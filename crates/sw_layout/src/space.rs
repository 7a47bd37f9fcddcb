//! The occupied space of the room: every placed object's collision boxes in world
//! coordinates, keep-clear zones (the doorway, service clearances), and the tests a
//! candidate pose must pass.

use std::collections::HashMap;

use sw_geom::Aabb;

/// Gap kept between floor objects, m.
pub(crate) const FLOOR_GAP: f64 = 0.05;
/// Gap kept between items on one surface, m.
pub(crate) const SURFACE_GAP: f64 = 0.015;
/// Gap kept from the walls, m.
pub(crate) const WALL_GAP: f64 = 0.02;
/// Numerical slack for touching faces (an item resting on a surface touches it).
const EPS: f64 = 1e-6;

/// Something that occupies space.
#[derive(Debug, Clone)]
pub(crate) struct Occupant {
    /// Object or robot name.
    pub name: String,
    /// Collision boxes, world frame.
    pub boxes: Vec<Aabb>,
    /// The union of `boxes`.
    pub bounds: Aabb,
    /// Stands on the floor (as opposed to resting on another object).
    pub on_floor: bool,
}

/// A keep-clear rectangle on the floor (doorway, working space in front of equipment).
#[derive(Debug, Clone)]
pub(crate) struct Zone {
    pub owner: Option<String>,
    pub area: Aabb,
}

/// Side of the cells of the occupancy index, m.
const CELL: f64 = 1.0;

#[derive(Debug, Clone)]
pub(crate) struct Space {
    pub half: [f64; 2],
    pub height: f64,
    pub occupants: Vec<Occupant>,
    pub zones: Vec<Zone>,
    /// Occupants by floor cell: collision queries look only at their neighbourhood.
    cells: HashMap<(i32, i32), Vec<u32>>,
}

pub(crate) fn union(boxes: &[Aabb]) -> Aabb {
    boxes.iter().fold(Aabb::EMPTY, |acc, b| acc.union(b))
}

/// Overlap with `gap` added around `a` in X and Y; touching in Z is not overlap.
pub(crate) fn overlaps(a: &Aabb, b: &Aabb, gap: f64) -> bool {
    a.min[0] - gap < b.max[0] - EPS
        && b.min[0] < a.max[0] + gap - EPS
        && a.min[1] - gap < b.max[1] - EPS
        && b.min[1] < a.max[1] + gap - EPS
        && a.min[2] < b.max[2] - EPS
        && b.min[2] < a.max[2] - EPS
}

/// Overlap of the floor projections.
pub(crate) fn overlaps_2d(a: &Aabb, b: &Aabb) -> bool {
    a.min[0] < b.max[0] - EPS && b.min[0] < a.max[0] - EPS && a.min[1] < b.max[1] - EPS && b.min[1] < a.max[1] - EPS
}

impl Space {
    pub fn new(width: f64, depth: f64, height: f64) -> Self {
        Self {
            half: [width / 2.0, depth / 2.0],
            height,
            occupants: Vec::new(),
            zones: Vec::new(),
            cells: HashMap::new(),
        }
    }

    /// Inside the walls (with the wall gap) and under the ceiling.
    pub fn inside(&self, b: &Aabb) -> bool {
        b.min[0] >= -self.half[0] + WALL_GAP - EPS
            && b.max[0] <= self.half[0] - WALL_GAP + EPS
            && b.min[1] >= -self.half[1] + WALL_GAP - EPS
            && b.max[1] <= self.half[1] - WALL_GAP + EPS
            && b.min[2] >= -EPS
            && b.max[2] <= self.height + EPS
    }

    /// True when `boxes` fit: inside the room, clear of every occupant (except those in
    /// `ignore`) by `gap`, and, for floor objects, clear of keep-clear zones (except
    /// those owned by names in `ignore_zones`).
    pub fn fits(&self, boxes: &[Aabb], gap: f64, ignore: &[&str], floor_zones: bool, ignore_zones: &[&str]) -> bool {
        let all = union(boxes);
        if all.is_empty() || !self.inside(&all) {
            return false;
        }
        for o in self.near(&all, gap) {
            if ignore.contains(&o.name.as_str()) || !overlaps(&all, &o.bounds, gap) {
                continue;
            }
            if boxes.iter().any(|b| o.boxes.iter().any(|ob| overlaps(b, ob, gap))) {
                return false;
            }
        }
        if floor_zones {
            for z in &self.zones {
                if z.owner.as_deref().is_some_and(|n| ignore_zones.contains(&n) || ignore.contains(&n)) {
                    continue;
                }
                if overlaps_2d(&all, &z.area) {
                    return false;
                }
            }
        }
        true
    }

    /// True when a keep-clear zone is free of floor objects other than `except`.
    pub fn zone_is_clear(&self, zone: &Aabb, except: &[&str]) -> bool {
        self.near(zone, 0.0)
            .filter(|o| o.on_floor && !except.contains(&o.name.as_str()))
            .all(|o| !overlaps_2d(zone, &o.bounds))
    }

    fn cell_range(b: &Aabb, gap: f64) -> (i32, i32, i32, i32) {
        let f = |v: f64| (v / CELL).floor().clamp(-1e6, 1e6) as i32;
        (f(b.min[0] - gap), f(b.max[0] + gap), f(b.min[1] - gap), f(b.max[1] + gap))
    }

    /// Occupants whose floor cells meet `b` grown by `gap`, each once, in insertion order.
    fn near<'s>(&'s self, b: &Aabb, gap: f64) -> impl Iterator<Item = &'s Occupant> + 's {
        let (x0, x1, y0, y1) = Self::cell_range(b, gap);
        let mut ids: Vec<u32> = Vec::new();
        for x in x0..=x1 {
            for y in y0..=y1 {
                if let Some(v) = self.cells.get(&(x, y)) {
                    ids.extend_from_slice(v);
                }
            }
        }
        ids.sort_unstable();
        ids.dedup();
        ids.into_iter().filter_map(|i| self.occupants.get(i as usize))
    }

    pub fn add(&mut self, name: &str, boxes: Vec<Aabb>, on_floor: bool) {
        let bounds = union(&boxes);
        let id = self.occupants.len();
        if !bounds.is_empty() {
            let (x0, x1, y0, y1) = Self::cell_range(&bounds, 0.0);
            for x in x0..=x1 {
                for y in y0..=y1 {
                    self.cells.entry((x, y)).or_default().push(id as u32);
                }
            }
        }
        self.occupants.push(Occupant { name: name.to_string(), boxes, bounds, on_floor });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn touching_in_z_is_not_overlap_but_touching_sideways_with_a_gap_is() {
        let table = Aabb { min: [0.0, 0.0, 0.7], max: [1.0, 1.0, 0.75] };
        let mug = Aabb { min: [0.4, 0.4, 0.75], max: [0.5, 0.5, 0.85] };
        assert!(!overlaps(&mug, &table, 0.0));
        let beside = Aabb { min: [1.02, 0.0, 0.0], max: [2.0, 1.0, 0.75] };
        assert!(!overlaps(&beside, &table, 0.0));
        assert!(overlaps(&beside, &table, 0.05));
    }
}
