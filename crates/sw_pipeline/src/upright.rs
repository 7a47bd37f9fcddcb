//! Things that stand on edge: "tires leaning on the wall" are the catalog's flat tyre
//! turned a quarter turn about X (its axis along Y), with a facet of its collision ring
//! flat on the floor so that it stands still, origin at the centre of its footprint.

use sw_geom::{Aabb, Asset, Mesh, Pose, Shape, quat_mul};

/// The asset stood on edge, when it lies flat (lower than it is wide) and is one rigid
/// link; otherwise unchanged.
pub(crate) fn on_edge(asset: Asset) -> Asset {
    let b = asset.bounds();
    let s = b.size();
    if asset.links.len() != 1 || s[2] >= s[0].min(s[1]) {
        return asset;
    }
    // A ring of n boxes has a facet every 2π/n: turn it half a facet about its axis so
    // that, stood up, one facet is at the bottom (n = 16 for the catalog's tyres).
    let boxes = asset.links[0].collisions.iter().filter(|c| matches!(c.shape, Shape::Box { .. })).count().max(4);
    let half_facet = std::f64::consts::PI / boxes as f64;
    let turn = quat_mul(
        Pose::from_pos_axis_angle([0.0; 3], [1.0, 0.0, 0.0], std::f64::consts::FRAC_PI_2).quat,
        Pose::from_pos_axis_angle([0.0; 3], [0.0, 0.0, 1.0], half_facet).quat,
    );
    let rot = Pose { pos: [0.0; 3], quat: turn };
    let mut out = asset.clone();
    let link = &mut out.links[0];
    for c in &mut link.collisions {
        c.pose = rot.compose(&c.pose);
    }
    let moved = |m: &Mesh, pose: &Pose| {
        let mut n = Mesh::default();
        n.append(m, pose);
        n
    };
    for v in &mut link.visuals {
        v.mesh = moved(&v.mesh, &rot);
    }
    for p in &mut link.convex {
        p.mesh = moved(&p.mesh, &rot);
    }
    // Onto the floor, the footprint centred on the origin.
    let cb = link.collisions.iter().fold(Aabb::EMPTY, |a, c| a.union(&c.aabb()));
    if cb.is_empty() {
        return asset;
    }
    let shift = Pose::from_pos([-0.5 * (cb.min[0] + cb.max[0]), -0.5 * (cb.min[1] + cb.max[1]), -cb.min[2]]);
    for c in &mut link.collisions {
        c.pose = shift.compose(&c.pose);
    }
    for v in &mut link.visuals {
        v.mesh = moved(&v.mesh, &shift);
    }
    for p in &mut link.convex {
        p.mesh = moved(&p.mesh, &shift);
    }
    out.surfaces.clear();
    out.notes.push("stood on edge (leaning)".into());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_tyre_stands_on_a_facet_of_its_ring() {
        let flat = sw_catalog::generate(&sw_catalog::AssetRequest::new("tire", 3)).unwrap();
        let f = flat.bounds().size();
        let up = on_edge(flat.clone());
        let u = up.bounds().size();
        // Its diameter is now its height, its tread its depth.
        assert!((u[2] - f[0]).abs() < 0.03 * f[0], "{f:?} -> {u:?}");
        assert!((u[1] - f[2]).abs() < 1e-6, "{f:?} -> {u:?}");
        let cb = up.links[0].collisions.iter().fold(Aabb::EMPTY, |a, c| a.union(&c.aabb()));
        assert!(cb.min[2].abs() < 1e-9 && cb.center()[0].abs() < 1e-9 && cb.center()[1].abs() < 1e-9);
        // One box of the ring lies flat on the floor (its bottom face level at z = 0).
        let flat_on_floor = up.links[0].collisions.iter().any(|c| {
            let a = c.aabb();
            a.min[2].abs() < 1e-9 && (a.max[2] - a.min[2]) < 0.2 * u[2]
        });
        assert!(flat_on_floor);
        // A tall thing is left alone.
        let shelf = sw_catalog::generate(&sw_catalog::AssetRequest::new("shelf", 1)).unwrap();
        assert_eq!(on_edge(shelf.clone()).bounds(), shelf.bounds());
    }
}
