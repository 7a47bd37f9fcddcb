//! The occupied space of the room: every placed object's collision boxes in world
//! coordinates, keep-clear zones (the doorway, service clearances), and the tests a
//! candidate pose must pass.

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

#[derive(Debug, Clone)]
pub(crate) struct Space {
    pub half: [f64; 2],
    pub height: f64,
    pub occupants: Vec<Occupant>,
    pub zones: Vec<Zone>,
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
        Self { half: [width / 2.0, depth / 2.0], height, occupants: Vec::new(), zones: Vec::new() }
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
        for o in &self.occupants {
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
        self.occupants
            .iter()
            .filter(|o| o.on_floor && !except.contains(&o.name.as_str()))
            .all(|o| !overlaps_2d(zone, &o.bounds))
    }

    pub fn add(&mut self, name: &str, boxes: Vec<Aabb>, on_floor: bool) {
        let bounds = union(&boxes);
        self.occupants.push(Occupant { name: name.to_string(), boxes, bounds, on_floor });
    }

    pub fn occupant(&self, name: &str) -> Option<&Occupant> {
        self.occupants.iter().find(|o| o.name == name)
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
