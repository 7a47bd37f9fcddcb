//! Closed, outward-facing meshes of the basic solids. Every mesh here is watertight.

use std::f64::consts::TAU;

use crate::Mesh;

/// An axis-aligned box centred on the origin with half-extents `half`.
pub fn box_mesh(half: [f64; 3]) -> Mesh {
    let [x, y, z] = half.map(|h| h as f32);
    let vertices =
        vec![[-x, -y, -z], [x, -y, -z], [x, y, -z], [-x, y, -z], [-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z]];
    let triangles = vec![
        [0, 2, 1],
        [0, 3, 2], // bottom (-z)
        [4, 5, 6],
        [4, 6, 7], // top (+z)
        [0, 1, 5],
        [0, 5, 4], // -y
        [2, 3, 7],
        [2, 7, 6], // +y
        [1, 2, 6],
        [1, 6, 5], // +x
        [3, 0, 4],
        [3, 4, 7], // -x
    ];
    Mesh { vertices, triangles }
}

/// A frustum of a cone along +Z from `z = -half_height` (radius `r_bottom`) to
/// `z = +half_height` (radius `r_top`), with `segments` sides. A zero radius makes a
/// pointed cone with a single apex vertex.
pub fn frustum_mesh(r_bottom: f64, r_top: f64, half_height: f64, segments: u32) -> Mesh {
    let n = segments.max(3);
    let h = half_height as f32;
    let mut m = Mesh::default();
    let ring = |m: &mut Mesh, r: f64, z: f32| -> Option<u32> {
        if r <= 0.0 {
            m.vertices.push([0.0, 0.0, z]);
            return None;
        }
        let start = m.vertices.len() as u32;
        for i in 0..n {
            let a = TAU * f64::from(i) / f64::from(n);
            m.vertices.push([(r * a.cos()) as f32, (r * a.sin()) as f32, z]);
        }
        Some(start)
    };
    let bottom = ring(&mut m, r_bottom, -h);
    let bottom_apex = m.vertices.len() as u32 - 1;
    let top = ring(&mut m, r_top, h);
    let top_apex = m.vertices.len() as u32 - 1;
    // Cap centres (only used for rings).
    let cb = m.vertices.len() as u32;
    m.vertices.push([0.0, 0.0, -h]);
    let ct = cb + 1;
    m.vertices.push([0.0, 0.0, h]);
    for i in 0..n {
        let j = (i + 1) % n;
        match (bottom, top) {
            (Some(b), Some(t)) => {
                m.triangles.push([b + i, b + j, t + j]);
                m.triangles.push([b + i, t + j, t + i]);
            }
            (Some(b), None) => m.triangles.push([b + i, b + j, top_apex]),
            (None, Some(t)) => m.triangles.push([bottom_apex, t + j, t + i]),
            (None, None) => {}
        }
        if let Some(b) = bottom {
            m.triangles.push([cb, b + j, b + i]);
        }
        if let Some(t) = top {
            m.triangles.push([ct, t + i, t + j]);
        }
    }
    // Drop unused cap centres so every vertex is referenced (keeps checks clean).
    compact(m)
}

/// A cylinder along +Z centred on the origin.
pub fn cylinder_mesh(radius: f64, half_height: f64, segments: u32) -> Mesh {
    frustum_mesh(radius, radius, half_height, segments)
}

/// A UV sphere centred on the origin.
pub fn sphere_mesh(radius: f64, rings: u32, segments: u32) -> Mesh {
    let rings = rings.max(2);
    let segs = segments.max(3);
    let mut m = Mesh::default();
    m.vertices.push([0.0, 0.0, -radius as f32]);
    for r in 1..rings {
        let phi = std::f64::consts::PI * f64::from(r) / f64::from(rings) - std::f64::consts::FRAC_PI_2;
        let (z, rr) = (radius * phi.sin(), radius * phi.cos());
        for s in 0..segs {
            let a = TAU * f64::from(s) / f64::from(segs);
            m.vertices.push([(rr * a.cos()) as f32, (rr * a.sin()) as f32, z as f32]);
        }
    }
    let north = m.vertices.len() as u32;
    m.vertices.push([0.0, 0.0, radius as f32]);
    let at = |r: u32, s: u32| 1 + (r - 1) * segs + (s % segs);
    for s in 0..segs {
        m.triangles.push([0, at(1, s + 1), at(1, s)]);
        m.triangles.push([north, at(rings - 1, s), at(rings - 1, s + 1)]);
    }
    for r in 1..rings - 1 {
        for s in 0..segs {
            m.triangles.push([at(r, s), at(r, s + 1), at(r + 1, s + 1)]);
            m.triangles.push([at(r, s), at(r + 1, s + 1), at(r + 1, s)]);
        }
    }
    m
}

/// Removes unreferenced vertices, keeping order.
fn compact(m: Mesh) -> Mesh {
    let mut used = vec![false; m.vertices.len()];
    for t in &m.triangles {
        for &i in t {
            used[i as usize] = true;
        }
    }
    let mut remap = vec![0u32; m.vertices.len()];
    let mut vertices = Vec::with_capacity(m.vertices.len());
    for (i, v) in m.vertices.iter().enumerate() {
        if used[i] {
            remap[i] = vertices.len() as u32;
            vertices.push(*v);
        }
    }
    let triangles = m.triangles.iter().map(|t| t.map(|i| remap[i as usize])).collect();
    Mesh { vertices, triangles }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primitives_are_closed_solids_with_the_right_volume() {
        let b = box_mesh([0.5, 1.0, 1.5]).check();
        assert!(b.is_valid_solid(), "{b:?}");
        assert!((b.volume - 6.0).abs() < 1e-6);

        let c = cylinder_mesh(1.0, 1.0, 64).check();
        assert!(c.is_valid_solid(), "{c:?}");
        // An inscribed 64-gon loses a little area against pi r^2.
        assert!((c.volume - 2.0 * std::f64::consts::PI).abs() < 0.02);

        let cone = frustum_mesh(1.0, 0.0, 0.5, 32).check();
        assert!(cone.is_valid_solid(), "{cone:?}");
        let inverted = frustum_mesh(0.0, 0.4, 0.5, 32).check();
        assert!(inverted.is_valid_solid(), "{inverted:?}");

        let s = sphere_mesh(1.0, 24, 48).check();
        assert!(s.is_valid_solid(), "{s:?}");
        assert!((s.volume - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.05);
    }

    #[test]
    fn a_mesh_with_a_missing_face_is_not_watertight() {
        let mut m = box_mesh([1.0; 3]);
        m.triangles.pop();
        let c = m.check();
        assert!(!c.watertight);
        assert_eq!(c.bad_edges, 3);
    }

    #[test]
    fn a_flipped_face_is_an_orientation_error() {
        let mut m = box_mesh([1.0; 3]);
        m.triangles[0].swap(1, 2);
        assert!(!m.check().watertight);
    }
}
