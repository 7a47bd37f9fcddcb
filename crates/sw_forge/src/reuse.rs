//! Whether a stored asset serves a request of a given size. The semantic index says two
//! labels name the same kind of object; it cannot tell a shelf from a self-driving car
//! when their labels read alike (about a third of the hard negatives in
//! `bench/forge/label_pairs.tsv` score above the threshold). Their sizes can: a stored
//! asset is reused only when, stretched per axis to the requested box (turned a quarter
//! about z first if that fits better), no axis is stretched much more than another and
//! the whole is neither much larger nor much smaller than what was stored.

use sw_geom::Mesh;

/// The most one axis may be stretched relative to another (1.5: proportions within 50 %).
/// Chosen on the labelled pairs at typical sizes (`bench asset-index`): 1.3 keeps
/// precision 0.85 but recall falls to 0.65; 1.5 gives 0.83 / 0.71; 2.0 stretches a round
/// table into an oval one.
pub const MAX_DISTORTION: f64 = 1.5;
/// The most the asset may be scaled overall (geometric mean of the axes), up or down.
pub const MAX_SCALE: f64 = 2.0;

/// How a stored asset maps onto a requested box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SizeFit {
    /// Turn the asset a quarter about z first (its width becomes its depth).
    pub quarter_turn: bool,
    /// The per-axis factors that take it (turned) to the requested size.
    pub scale: [f64; 3],
    /// Largest factor over smallest, ≥ 1.
    pub distortion: f64,
    /// Geometric mean of the factors.
    pub overall: f64,
}

impl SizeFit {
    /// True when the stored asset serves the request.
    pub fn fits(&self) -> bool {
        self.distortion <= MAX_DISTORTION && self.overall <= MAX_SCALE && self.overall >= 1.0 / MAX_SCALE
    }
}

/// The better of the two ways (as stored, or turned a quarter) to fit a stored size onto
/// a requested one, both in metres; `None` when a side is not a positive finite length.
pub fn size_fit(stored: [f64; 3], wanted: [f64; 3]) -> Option<SizeFit> {
    if !stored.iter().chain(&wanted).all(|v| v.is_finite() && *v > 0.0) {
        return None;
    }
    let fit = |quarter_turn: bool| {
        let s = if quarter_turn { [stored[1], stored[0], stored[2]] } else { stored };
        let scale = [wanted[0] / s[0], wanted[1] / s[1], wanted[2] / s[2]];
        let (lo, hi) = scale.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
        SizeFit { quarter_turn, scale, distortion: hi / lo, overall: scale.iter().product::<f64>().cbrt() }
    };
    let (a, b) = (fit(false), fit(true));
    Some(if b.distortion < a.distortion - 1e-9 { b } else { a })
}

/// The mesh turned and stretched as `fit` says (about the origin; callers re-centre).
pub fn apply_fit(mesh: &Mesh, fit: &SizeFit) -> Mesh {
    let vertices = mesh
        .vertices
        .iter()
        .map(|v| {
            // A quarter turn about z: (x, y) → (−y, x), a rotation (winding is kept).
            let [x, y, z] = v.map(f64::from);
            let (x, y) = if fit.quarter_turn { (-y, x) } else { (x, y) };
            [(x * fit.scale[0]) as f32, (y * fit.scale[1]) as f32, (z * fit.scale[2]) as f32]
        })
        .collect();
    Mesh { vertices, triangles: mesh.triangles.clone() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn like_shapes_fit_and_unlike_ones_do_not() {
        // A 2 m rack asked for at 1.8 m: a uniform 0.9, fits.
        let f = size_fit([1.0, 0.5, 2.0], [0.9, 0.45, 1.8]).unwrap();
        assert!(f.fits() && (f.overall - 0.9).abs() < 1e-12 && !f.quarter_turn);
        // The same rack asked for turned: fits after a quarter turn.
        let f = size_fit([1.0, 0.5, 2.0], [0.5, 1.0, 2.0]).unwrap();
        assert!(f.fits() && f.quarter_turn);
        // A shelf for a car: proportions far apart.
        let f = size_fit([0.8, 0.3, 1.8], [4.5, 1.8, 1.5]).unwrap();
        assert!(!f.fits());
        // Same proportions, ten times larger.
        assert!(!size_fit([0.1, 0.1, 0.1], [1.0, 1.0, 1.0]).unwrap().fits());
        assert!(size_fit([0.0, 0.1, 0.1], [1.0, 1.0, 1.0]).is_none());
        assert!(size_fit([0.1, 0.1, 0.1], [f64::NAN, 1.0, 1.0]).is_none());
    }

    #[test]
    fn a_fitted_mesh_has_the_requested_size() {
        // Half-extents: a 1 × 0.5 × 2 m box.
        let m = sw_geom::box_mesh([0.5, 0.25, 1.0]);
        let want = [0.55, 1.1, 2.1];
        let f = size_fit([1.0, 0.5, 2.0], want).unwrap();
        assert!(f.quarter_turn && f.fits());
        let out = apply_fit(&m, &f);
        let s = out.bounds().size();
        for k in 0..3 {
            assert!((s[k] - want[k]).abs() < 1e-6, "{s:?}");
        }
        assert!((out.volume() - want.iter().product::<f64>()).abs() < 1e-6, "a rotation keeps the volume positive");
    }
}
