//! Collision geometry of generated parts. MuJoCo collides a mesh geom as the convex hull
//! of its vertices, so a concave part (a washer, a bracket, a cup) would collide as a
//! solid lump. A part whose hull is within 3 % of its own volume collides as that hull;
//! a concave one is split by approximate convex decomposition (parry3d's V-HACD) into
//! pieces whose hulls follow it. The result becomes an [`sw_geom::Asset`]: the mesh as
//! its visual, the pieces as convex collision (`AssetBuilder::convex_on`).

use parry3d::math::Vector;
use parry3d::transformation::vhacd::{VHACD, VHACDParameters};
use sw_geom::{Asset, AssetBuilder, MassModel, Mesh, PlacementKind, Pose};

/// Largest number of convex pieces kept (the biggest by volume).
pub const MAX_PIECES: usize = 24;

/// Hull volume / part volume up to which a part counts as convex.
const CONVEX_RATIO: f64 = 1.03;

fn hull(points: &[Vector]) -> Option<Mesh> {
    let (v, t) = parry3d::transformation::try_convex_hull(points).ok()?;
    if t.is_empty() {
        return None;
    }
    Some(Mesh {
        vertices: v.iter().map(|p| [p.x, p.y, p.z]).collect(),
        triangles: t.iter().map(|t| [t[0], t[1], t[2]]).collect(),
    })
}

/// Convex pieces covering `mesh` (in its own units): one hull when it is nearly convex,
/// else the V-HACD decomposition. Empty only for a mesh with no volume.
pub fn convex_pieces(mesh: &Mesh) -> Vec<Mesh> {
    let points: Vec<Vector> = mesh.vertices.iter().map(|v| Vector::new(v[0], v[1], v[2])).collect();
    let Some(whole) = hull(&points) else { return Vec::new() };
    let volume = mesh.volume();
    if volume <= 0.0 || whole.volume() <= CONVEX_RATIO * volume {
        return vec![whole];
    }
    let indices: Vec<[u32; 3]> = mesh.triangles.clone();
    let params = VHACDParameters { resolution: 48, concavity: 0.005, ..VHACDParameters::default() };
    // V-HACD is third-party code on generated geometry: a panic in it must not take the
    // pipeline down — the part then collides as its hull.
    let decomposed = std::panic::catch_unwind(|| {
        let d = VHACD::decompose(&params, &points, &indices, true);
        d.compute_exact_convex_hulls(&points, &indices)
    });
    let Ok(parts) = decomposed else { return vec![whole] };
    let mut pieces: Vec<Mesh> = parts.into_iter().filter_map(|(v, _)| hull(&v)).collect();
    if pieces.is_empty() {
        return vec![whole];
    }
    pieces.sort_by(|a, b| b.volume().total_cmp(&a.volume()));
    pieces.truncate(MAX_PIECES);
    pieces
}

/// A generated part as an asset: `mesh_m` (metres, any placement) moved so that it
/// stands on z = 0 centred in x and y, its visual in one grey material and its collision
/// as convex pieces. `mass` kg makes it a free body; `None` a fixture.
pub fn part_asset(category: &str, mesh_m: &Mesh, mass: Option<f64>, placement: PlacementKind) -> Asset {
    let b = mesh_m.bounds();
    let c = b.center();
    let shift = [-c[0], -c[1], -b.min[2]];
    let moved = Mesh {
        vertices: mesh_m
            .vertices
            .iter()
            .map(|v| {
                [
                    (f64::from(v[0]) + shift[0]) as f32,
                    (f64::from(v[1]) + shift[1]) as f32,
                    (f64::from(v[2]) + shift[2]) as f32,
                ]
            })
            .collect(),
        triangles: mesh_m.triangles.clone(),
    };
    let mut a = AssetBuilder::new(category, 0);
    let grey = a.material("generated", [0.62, 0.64, 0.68, 1.0], true);
    a.visual_mesh_on(0, &moved, Pose::default(), grey);
    for piece in convex_pieces(&moved) {
        a.convex_on(0, piece);
    }
    a.note("generated part: collision is its convex decomposition");
    let mass = match mass {
        Some(m) if m.is_finite() && m > 0.0 => MassModel::Free { mass: m },
        _ => MassModel::Static,
    };
    a.build(placement, mass)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_is_its_own_hull() {
        let m = sw_geom::box_mesh([0.1, 0.2, 0.3]);
        let p = convex_pieces(&m);
        assert_eq!(p.len(), 1);
        assert!((p[0].volume() - m.volume()).abs() < 1e-6);
    }

    #[test]
    fn an_l_shape_is_split_and_its_inner_corner_left_empty() {
        // Two boxes making an L (welded into one mesh by appending).
        let mut m = Mesh::default();
        m.append(&sw_geom::box_mesh([0.5, 0.05, 0.05]), &Pose::default());
        let up = Pose { pos: [-0.45, 0.0, 0.5], ..Pose::default() };
        m.append(&sw_geom::box_mesh([0.05, 0.05, 0.45]), &up);
        let p = convex_pieces(&m);
        assert!(p.len() >= 2, "{} pieces", p.len());
        // A point inside the L's hull but outside the L (0, 0, 0.3) is in no piece's bounding box.
        let inside = |q: &Mesh, pt: [f64; 3]| {
            let b = q.bounds();
            (0..3).all(|k| pt[k] > b.min[k] + 1e-6 && pt[k] < b.max[k] - 1e-6)
        };
        assert!(!p.iter().any(|q| inside(q, [0.0, 0.0, 0.3])));
        let a = part_asset("generated_l", &m, Some(1.0), PlacementKind::Floor);
        assert_eq!(a.links[0].convex.len(), p.len());
        assert!(a.bounds().min[2].abs() < 1e-6, "stands on z = 0");
    }
}
