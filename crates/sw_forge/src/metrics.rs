//! Comparing a made part with a reference: extent and volume errors, and the Chamfer
//! distance between their surfaces (points sampled by area with a fixed seed).

use sw_geom::{Mesh, Rng};

/// Largest relative error of the sorted extents (any orientation).
pub fn extent_error(got: [f64; 3], want: [f64; 3]) -> f64 {
    let (mut g, mut w) = (got, want);
    g.sort_by(f64::total_cmp);
    w.sort_by(f64::total_cmp);
    g.iter().zip(&w).map(|(g, w)| if *w > 0.0 { (g - w).abs() / w } else { (g - w).abs() }).fold(0.0, f64::max)
}

/// `n` points on the surface of `mesh`, each triangle chosen with probability
/// proportional to its area.
pub fn sample_surface(mesh: &Mesh, n: usize, seed: u64) -> Vec<[f64; 3]> {
    let tri = |t: &[u32; 3]| -> Option<[[f64; 3]; 3]> {
        let p = |i: u32| mesh.vertices.get(i as usize).map(|v| v.map(f64::from));
        Some([p(t[0])?, p(t[1])?, p(t[2])?])
    };
    let tris: Vec<[[f64; 3]; 3]> = mesh.triangles.iter().filter_map(tri).collect();
    let mut cum = Vec::with_capacity(tris.len());
    let mut total = 0.0;
    for [a, b, c] in &tris {
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let x = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        total += 0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
        cum.push(total);
    }
    if tris.is_empty() || total <= 0.0 {
        return Vec::new();
    }
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let r = rng.range(0.0, total);
            let k = cum.partition_point(|c| *c < r).min(tris.len() - 1);
            let [a, b, c] = tris[k];
            let (mut s, mut t) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
            if s + t > 1.0 {
                s = 1.0 - s;
                t = 1.0 - t;
            }
            [0, 1, 2].map(|i| a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]))
        })
        .collect()
}

fn mean_nearest(from: &[[f64; 3]], to: &[[f64; 3]]) -> f64 {
    let sum: f64 = from
        .iter()
        .map(|p| {
            to.iter()
                .map(|q| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2))
                .fold(f64::INFINITY, f64::min)
                .sqrt()
        })
        .sum();
    sum / from.len().max(1) as f64
}

/// Symmetric Chamfer distance (mean nearest-point distance both ways, averaged), in the
/// meshes' units, from `n` samples on each surface. `None` when a mesh has no area.
pub fn chamfer_distance(a: &Mesh, b: &Mesh, n: usize) -> Option<f64> {
    let pa = sample_surface(a, n, 0x5eed_0001);
    let pb = sample_surface(b, n, 0x5eed_0002);
    if pa.is_empty() || pb.is_empty() {
        return None;
    }
    Some(0.5 * (mean_nearest(&pa, &pb) + mean_nearest(&pb, &pa)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chamfer_is_small_for_the_same_shape_and_grows_with_a_shift() {
        let a = sw_geom::box_mesh([1.0, 1.0, 1.0]);
        let same = chamfer_distance(&a, &a, 2000).unwrap();
        assert!(same < 0.1, "{same}");
        let mut b = a.clone();
        for v in &mut b.vertices {
            v[0] += 0.5;
        }
        let shifted = chamfer_distance(&a, &b, 2000).unwrap();
        assert!(shifted > 0.2 && shifted > 3.0 * same, "{shifted} vs {same}");
        assert!(chamfer_distance(&a, &Mesh::default(), 10).is_none());
    }

    #[test]
    fn extents_compare_in_any_order() {
        assert!(extent_error([30.0, 20.0, 10.0], [10.0, 20.0, 30.0]) < 1e-12);
        assert!((extent_error([10.0, 20.0, 33.0], [10.0, 20.0, 30.0]) - 0.1).abs() < 1e-12);
    }
}
