//! Comparing a made part with a reference: extent and volume errors, and the Chamfer
//! distance between their surfaces — points sampled by area with a fixed seed, each
//! measured to the nearest point of the other surface (its triangles, found through a
//! uniform grid), so that two tessellations of one shape are ~0 apart rather than the
//! spacing of the samples.

use std::collections::HashMap;

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

type Tri = [[f64; 3]; 3];

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The closest point of a triangle to `p` (Ericson, Real-Time Collision Detection 5.1.5).
fn closest_on_triangle(p: [f64; 3], t: &Tri) -> [f64; 3] {
    let [a, b, c] = *t;
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return [a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]];
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return [a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]];
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return [b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])];
    }
    let denom = 1.0 / (va + vb + vc);
    let (v, w) = (vb * denom, vc * denom);
    [a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w]
}

/// A mesh's triangles binned in a uniform grid, for nearest-surface queries.
struct Surface {
    tris: Vec<Tri>,
    origin: [f64; 3],
    cell: f64,
    cells: HashMap<[i64; 3], Vec<u32>>,
}

impl Surface {
    fn new(mesh: &Mesh) -> Option<Self> {
        let p = |i: u32| mesh.vertices.get(i as usize).map(|v| v.map(f64::from));
        let tris: Vec<Tri> = mesh.triangles.iter().filter_map(|t| Some([p(t[0])?, p(t[1])?, p(t[2])?])).collect();
        let b = mesh.bounds();
        if tris.is_empty() || b.is_empty() {
            return None;
        }
        let s = b.size();
        let diag = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt().max(1e-9);
        let cell = diag / 40.0;
        let mut cells: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let key = |v: f64, o: f64| ((v - o) / cell).floor() as i64;
        for (i, t) in tris.iter().enumerate() {
            let lo: [i64; 3] =
                std::array::from_fn(|k| key(t.iter().map(|q| q[k]).fold(f64::INFINITY, f64::min), b.min[k]));
            let hi: [i64; 3] =
                std::array::from_fn(|k| key(t.iter().map(|q| q[k]).fold(f64::NEG_INFINITY, f64::max), b.min[k]));
            for x in lo[0]..=hi[0] {
                for y in lo[1]..=hi[1] {
                    for z in lo[2]..=hi[2] {
                        cells.entry([x, y, z]).or_default().push(i as u32);
                    }
                }
            }
        }
        Some(Self { tris, origin: b.min, cell, cells })
    }

    /// Distance from `p` to the surface: rings of cells around `p`'s until the best found
    /// is nearer than any unsearched cell can be.
    fn distance(&self, p: [f64; 3]) -> f64 {
        let c: [i64; 3] = std::array::from_fn(|k| ((p[k] - self.origin[k]) / self.cell).floor() as i64);
        let mut best = f64::INFINITY;
        // Near the surface, rings of cells; far from it (a misplaced part), every triangle.
        for r in 0..=6i64 {
            for x in c[0] - r..=c[0] + r {
                for y in c[1] - r..=c[1] + r {
                    for z in c[2] - r..=c[2] + r {
                        let ring = (x - c[0]).abs().max((y - c[1]).abs()).max((z - c[2]).abs());
                        if ring != r {
                            continue;
                        }
                        if let Some(list) = self.cells.get(&[x, y, z]) {
                            for &i in list {
                                let q = closest_on_triangle(p, &self.tris[i as usize]);
                                best = best.min(dot(sub(p, q), sub(p, q)).sqrt());
                            }
                        }
                    }
                }
            }
            if best <= r as f64 * self.cell {
                return best;
            }
        }
        self.tris
            .iter()
            .map(|t| {
                let q = closest_on_triangle(p, t);
                dot(sub(p, q), sub(p, q)).sqrt()
            })
            .fold(best, f64::min)
    }
}

/// Symmetric Chamfer distance to the surfaces: `n` points sampled on each mesh, each
/// measured to the other mesh's nearest surface point; the two means averaged. `None`
/// when a mesh has no area.
pub fn surface_chamfer(a: &Mesh, b: &Mesh, n: usize) -> Option<f64> {
    let (sa, sb) = (Surface::new(a)?, Surface::new(b)?);
    let pa = sample_surface(a, n, 0x5eed_0001);
    let pb = sample_surface(b, n, 0x5eed_0002);
    if pa.is_empty() || pb.is_empty() {
        return None;
    }
    let ab = pa.iter().map(|p| sb.distance(*p)).sum::<f64>() / pa.len() as f64;
    let ba = pb.iter().map(|p| sa.distance(*p)).sum::<f64>() / pb.len() as f64;
    Some(0.5 * (ab + ba))
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
    fn the_surface_chamfer_of_a_shape_with_itself_is_zero_and_a_shift_shows() {
        let a = sw_geom::box_mesh([10.0, 10.0, 10.0]);
        assert!(surface_chamfer(&a, &a, 1000).unwrap() < 1e-9);
        let mut b = a.clone();
        for v in &mut b.vertices {
            v[2] += 1.0;
        }
        let d = surface_chamfer(&a, &b, 4000).unwrap();
        // A 1 mm shift of a 10 mm cube: the top and bottom faces are 1 mm off, the sides 0.
        assert!((0.2..0.5).contains(&d), "{d}");
    }

    #[test]
    fn extents_compare_in_any_order() {
        assert!(extent_error([30.0, 20.0, 10.0], [10.0, 20.0, 30.0]) < 1e-12);
        assert!((extent_error([10.0, 20.0, 33.0], [10.0, 20.0, 30.0]) - 0.1).abs() < 1e-12);
    }
}
