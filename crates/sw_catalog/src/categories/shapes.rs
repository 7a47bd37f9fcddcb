//! Closed meshes the primitives do not cover: solids of revolution (mugs, bowls,
//! bottles, tyres, pots) and prisms (slanted side panels, wedges). Visual only; the
//! collision of the things they draw stays primitives.
//!
//! Every mesh here is watertight and faces outwards whatever the winding of its input:
//! the builders check the signed volume and flip the triangles if it is negative.

use std::f64::consts::TAU;

use sw_geom::Mesh;

/// Segments around solids of revolution: a multiple of 4, so that the mesh reaches its
/// radius exactly on the X and Y axes (bounds equal the parameters).
pub(crate) const ROUND: u32 = 32;

/// The solid swept by turning a closed profile about the Z axis. `profile` holds
/// `(r, z)` points of a simple polygon in the half plane `r >= 0`, in order. A point
/// with `r == 0` is on the axis and becomes a single apex vertex; only the first and the
/// last point may be on the axis (a closed vessel or a cone), otherwise the profile is
/// a ring (a tyre, a rim) and its last point joins its first. Consecutive points must
/// differ.
pub(crate) fn revolve(profile: &[[f64; 2]], segments: u32) -> Mesh {
    let n = segments.max(3);
    let mut m = Mesh::default();
    // The first vertex of each profile point; `None` marks a point on the axis.
    let mut rings: Vec<(u32, bool)> = Vec::with_capacity(profile.len());
    for &[r, z] in profile {
        let start = m.vertices.len() as u32;
        if r <= 0.0 {
            m.vertices.push([0.0, 0.0, z as f32]);
            rings.push((start, false));
        } else {
            for j in 0..n {
                let a = TAU * f64::from(j) / f64::from(n);
                m.vertices.push([(r * a.cos()) as f32, (r * a.sin()) as f32, z as f32]);
            }
            rings.push((start, true));
        }
    }
    let len = rings.len();
    if len < 2 {
        return Mesh::default();
    }
    let closes = rings[0].1 || rings[len - 1].1;
    let pairs = if closes { len } else { len - 1 };
    for k in 0..pairs {
        let (a, a_ring) = rings[k];
        let (b, b_ring) = rings[(k + 1) % len];
        for j in 0..n {
            let jn = (j + 1) % n;
            match (a_ring, b_ring) {
                (true, true) => {
                    m.triangles.push([a + j, a + jn, b + jn]);
                    m.triangles.push([a + j, b + jn, b + j]);
                }
                (false, true) => m.triangles.push([a, b + jn, b + j]),
                (true, false) => m.triangles.push([a + j, a + jn, b]),
                (false, false) => {}
            }
        }
    }
    outward(m)
}

/// A straight prism: the simple convex polygon `outline` (`[x, y]` points, either
/// winding) extruded along Z from `z0` to `z1`.
pub(crate) fn prism(outline: &[[f64; 2]], z0: f64, z1: f64) -> Mesh {
    let n = outline.len() as u32;
    let mut m = Mesh::default();
    if n < 3 {
        return m;
    }
    for z in [z0, z1] {
        m.vertices.extend(outline.iter().map(|p| [p[0] as f32, p[1] as f32, z as f32]));
    }
    for i in 1..n - 1 {
        m.triangles.push([0, i + 1, i]); // bottom, seen from below
        m.triangles.push([n, n + i, n + i + 1]); // top
    }
    for i in 0..n {
        let j = (i + 1) % n;
        m.triangles.push([i, j, n + j]);
        m.triangles.push([i, n + j, n + i]);
    }
    outward(m)
}

/// A straight prism lying along Y: the simple convex polygon `outline` (`[x, z]`
/// points, either winding) extruded from `y0` to `y1` (sofa arms, slanted panels).
pub(crate) fn prism_xz(outline: &[[f64; 2]], y0: f64, y1: f64) -> Mesh {
    let mut m = prism(outline, y0, y1);
    // prism() built (x, y=z_outline, z=y); swap the last two coordinates.
    for v in &mut m.vertices {
        *v = [v[0], v[2], v[1]];
    }
    outward(m)
}

/// A rectangle with rounded corners, as a polygon for [`prism`]: half sizes `hx`, `hy`,
/// corner radius `r` (clamped to fit), `steps` segments per corner.
pub(crate) fn rounded_rect(hx: f64, hy: f64, r: f64, steps: u32) -> Vec<[f64; 2]> {
    let r = r.min(hx * 0.999).min(hy * 0.999).max(0.0);
    if r < 1e-5 {
        return vec![[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]];
    }
    let steps = steps.max(1);
    let mut out = Vec::with_capacity(4 * (steps as usize + 1));
    for (cx, cy, a0) in
        [(hx - r, hy - r, 0.0), (-(hx - r), hy - r, 0.25), (-(hx - r), -(hy - r), 0.5), (hx - r, -(hy - r), 0.75)]
    {
        for s in 0..=steps {
            let a = TAU * (a0 + 0.25 * f64::from(s) / f64::from(steps));
            out.push([cx + r * a.cos(), cy + r * a.sin()]);
        }
    }
    out
}

/// The profile of a ring with a rounded cross-section (a tyre, a handle, a rim): from
/// radius `r_in` to `r_out` and height `z0` to `z1`, corners rounded by `round`.
pub(crate) fn rounded_ring_profile(r_in: f64, r_out: f64, z0: f64, z1: f64, round: f64) -> Vec<[f64; 2]> {
    let (hr, hz) = ((r_out - r_in) / 2.0, (z1 - z0) / 2.0);
    let (cr, cz) = ((r_in + r_out) / 2.0, (z0 + z1) / 2.0);
    rounded_rect(hr, hz, round, 4).into_iter().map(|[x, y]| [cr + x, cz + y]).collect()
}

/// Flips every triangle when the mesh encloses a negative volume.
fn outward(mut m: Mesh) -> Mesh {
    if m.volume() < 0.0 {
        for t in &mut m.triangles {
            t.swap(1, 2);
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_revolved_cup_is_a_closed_solid_with_exact_bounds() {
        // Outer wall up, rim, inner wall down, inner floor to the axis.
        let cup = revolve(&[[0.0, 0.0], [0.04, 0.0], [0.04, 0.1], [0.036, 0.1], [0.036, 0.008], [0.0, 0.008]], ROUND);
        let c = cup.check();
        assert!(c.is_valid_solid(), "{c:?}");
        assert!((c.bounds.max[0] - 0.04).abs() < 1e-6 && (c.bounds.min[1] + 0.04).abs() < 1e-6);
        // Reversed input gives the same solid.
        let rev = revolve(&[[0.0, 0.008], [0.036, 0.008], [0.036, 0.1], [0.04, 0.1], [0.04, 0.0], [0.0, 0.0]], ROUND);
        assert!(rev.check().is_valid_solid());
        assert!((rev.check().volume - c.volume).abs() < 1e-9);
    }

    #[test]
    fn rings_cones_and_prisms_are_closed_solids() {
        let tyre = revolve(&rounded_ring_profile(0.2, 0.32, 0.0, 0.2, 0.04), ROUND);
        assert!(tyre.check().is_valid_solid(), "{:?}", tyre.check());
        let cone = revolve(&[[0.0, 0.0], [0.2, 0.0], [0.0, 0.7]], ROUND);
        assert!(cone.check().is_valid_solid());
        let p = prism(&rounded_rect(0.3, 0.2, 0.05, 4), 0.0, 0.1);
        let c = p.check();
        assert!(c.is_valid_solid(), "{c:?}");
        let wedge = prism(&[[0.0, 0.0], [0.0, 0.5], [0.4, 0.0]], -0.1, 0.1);
        assert!(wedge.check().is_valid_solid());
    }
}
