//! How many collision pairs and contacts MuJoCo XLA must consider for a scene.
//!
//! MJX (JAX) has no broad phase: it runs the narrow phase on every pair of geoms that may
//! collide, every step, and sizes its constraint arrays for all their possible contacts.
//! A warehouse with racks of many boxes and forty free cartons has ~12,000 box–box pairs
//! and ~50,000 potential contacts — beyond what a CPU (or a GPU batch) steps in useful
//! time. MJX reads two limits from the model's `<custom>` numerics: `max_geom_pairs` (per
//! pair-type group, the pairs with the nearest bounding spheres are kept) and
//! `max_contact_points` (the deepest contacts are kept). Native MuJoCo ignores both.
//!
//! [`contact_budget`] measures a scene at its `home` state in MuJoCo: per pair-type
//! group, the pairs MJX would consider (contype/conaffinity, different bodies, not both
//! welded to the world, not parent and child, not excluded) whose bounding spheres are
//! within [`NEAR_M`] of touching; and the most contacts MuJoCo finds at `home` and in
//! the 0.2 s after it (objects are placed a hair above their supports). The budget is twice each
//! (and at least a floor), so every pair and contact of the spawn state, and of any state
//! whose near pairs are no more than twice as many, is kept.

use std::collections::BTreeMap;
use std::path::Path;

use mujoco_rs::prelude::*;

/// Bounding spheres closer than this count as near, m.
pub const NEAR_M: f64 = 0.1;
/// Steps watched for contacts after `home` (0.2 s at 2 ms).
const SETTLE_STEPS: usize = 100;
/// The smallest budgets written.
const MIN_PAIRS: u32 = 16;
const MIN_CONTACTS: u32 = 64;

/// The limits for MJX and what they were measured from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ContactBudget {
    /// `max_geom_pairs`: pairs kept per pair-type group.
    pub max_geom_pairs: u32,
    /// `max_contact_points`: contacts kept per contact dimension.
    pub max_contact_points: u32,
    /// The largest number of near pairs in one pair-type group at `home`.
    pub near_pairs: u32,
    /// Every pair MJX would consider without limits.
    pub candidate_pairs: u32,
    /// The most contacts MuJoCo finds at `home` and in the first 0.2 s after it.
    pub contacts: u32,
}

/// Measures the budget of the scene at `path` (see the module docs).
pub fn contact_budget(path: &Path) -> Result<ContactBudget, String> {
    let model = MjModel::from_xml(path).map_err(|e| e.to_string())?;
    let mut data = model.make_data();
    if let Some(key) = model.name_to_id(MjtObjBase::mjOBJ_KEY, "home") {
        data.reset_keyframe(key).map_err(|e| e.to_string())?;
    }
    data.forward();
    let ngeom = model.ffi().ngeom as usize;
    let (contype, conaff) = (model.geom_contype(), model.geom_conaffinity());
    let (gbody, weld, parent) = (model.geom_bodyid(), model.body_weldid(), model.body_parentid());
    let (rbound, types, xpos) = (model.geom_rbound(), model.geom_type(), data.geom_xpos());
    let excluded: Vec<i32> = model.exclude_signature().to_vec();
    let plane = MjtGeomBase::mjGEOM_PLANE as u32;
    let hfield = MjtGeomBase::mjGEOM_HFIELD as u32;
    let mut near: BTreeMap<(u32, u32), u32> = BTreeMap::new();
    let mut candidates = 0u32;
    for g1 in 0..ngeom {
        for g2 in g1 + 1..ngeom {
            if contype[g1] & conaff[g2] == 0 && contype[g2] & conaff[g1] == 0 {
                continue;
            }
            let (b1, b2) = (gbody[g1] as usize, gbody[g2] as usize);
            // The same body, or bodies welded together (two static ones included).
            let (w1, w2) = (weld[b1] as usize, weld[b2] as usize);
            if b1 == b2 || w1 == w2 {
                continue;
            }
            // Parent and child (by their weld roots) do not collide, unless one is the world.
            if w1 != 0
                && w2 != 0
                && (weld[parent[w1] as usize] as usize == w2 || weld[parent[w2] as usize] as usize == w1)
            {
                continue;
            }
            let (lo, hi) = (b1.min(b2) as i32, b1.max(b2) as i32);
            if excluded.contains(&((lo << 16) + hi)) {
                continue;
            }
            candidates += 1;
            let (t1, t2) = (types[g1] as u32, types[g2] as u32);
            let key = (t1.min(t2), t1.max(t2));
            // MJX never culls pairs with planes or height fields.
            if [plane, hfield].contains(&key.0) {
                continue;
            }
            let d = xpos[g1].iter().zip(&xpos[g2]).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt();
            if d - (rbound[g1] + rbound[g2]) <= NEAR_M {
                *near.entry(key).or_insert(0) += 1;
            }
        }
    }
    let near_pairs = near.values().copied().max().unwrap_or(0);
    // Contacts at home and while the scene settles onto its supports (objects are placed a
    // hair above them): the most in the first 0.2 s.
    let mut contacts = data.ncon().max(0) as u32;
    for _ in 0..SETTLE_STEPS {
        data.step();
        contacts = contacts.max(data.ncon().max(0) as u32);
    }
    Ok(ContactBudget {
        max_geom_pairs: (2 * near_pairs).max(MIN_PAIRS),
        max_contact_points: (2 * contacts + MIN_CONTACTS).max(MIN_CONTACTS),
        near_pairs,
        candidate_pairs: candidates,
        contacts,
    })
}
