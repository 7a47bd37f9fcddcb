//! Plane profiles of the feature language — rectangles, circles, rings, polygons, stars,
//! stadiums, ellipses, ring sectors and closed paths of lines and arcs — with their exact
//! area, centroid and bounds, and the CadQuery calls that draw them on a workplane.

use std::f64::consts::PI;

use super::num::n;

/// One step of a closed path: a straight line to a point, or a circular arc through a
/// point to a point.
#[derive(Debug, Clone, PartialEq)]
pub enum Seg {
    Line([f64; 2]),
    Arc { mid: [f64; 2], end: [f64; 2] },
}

/// A plane profile in a workplane's (u, v) coordinates, centred on (0, 0) unless it is a
/// polygon or path (whose points are where they are).
#[derive(Debug, Clone, PartialEq)]
pub enum Profile {
    Rect {
        w: f64,
        h: f64,
    },
    /// A rectangle whose four corners are rounded with radius `r`.
    RoundedRect {
        w: f64,
        h: f64,
        r: f64,
    },
    Circle {
        d: f64,
    },
    /// A ring between two concentric circles.
    Annulus {
        od: f64,
        id: f64,
    },
    /// An ellipse of full axes `a` (along u) and `b` (along v).
    Ellipse {
        a: f64,
        b: f64,
    },
    /// A regular polygon of `n` sides on a circle of diameter `d`, the first corner at
    /// `phase` degrees from +u.
    Ngon {
        n: usize,
        d: f64,
        phase: f64,
    },
    /// A star of `n` tips alternating between the tip and root radii, the first tip on +u.
    Star {
        n: usize,
        tip: f64,
        root: f64,
    },
    /// A rectangle with semicircular ends, `l` end to end along u, `w` wide.
    Stadium {
        l: f64,
        w: f64,
    },
    Poly(Vec<[f64; 2]>),
    /// A closed path from `start`: lines and arcs.
    Path {
        start: [f64; 2],
        segs: Vec<Seg>,
    },
}

impl Profile {
    /// The area and the centroid (u, v).
    pub fn area_centroid(&self) -> (f64, [f64; 2]) {
        match self {
            Profile::Rect { w, h } => (w * h, [0.0, 0.0]),
            Profile::RoundedRect { w, h, r } => (w * h - (4.0 - PI) * r * r, [0.0, 0.0]),
            Profile::Circle { d } => (PI * d * d / 4.0, [0.0, 0.0]),
            Profile::Annulus { od, id } => (PI * (od * od - id * id) / 4.0, [0.0, 0.0]),
            Profile::Ellipse { a, b } => (PI * a * b / 4.0, [0.0, 0.0]),
            Profile::Ngon { n, d, .. } => {
                let r = d / 2.0;
                (*n as f64 / 2.0 * r * r * (2.0 * PI / *n as f64).sin(), [0.0, 0.0])
            }
            Profile::Star { n, tip, root } => (*n as f64 * tip * root * (PI / *n as f64).sin(), [0.0, 0.0]),
            Profile::Stadium { l, w } => ((l - w) * w + PI * w * w / 4.0, [0.0, 0.0]),
            Profile::Poly(pts) => {
                let (a, c) = poly_area_centroid(pts);
                (a.abs(), c)
            }
            Profile::Path { start, segs } => {
                let (a, c) = path_area_centroid(*start, segs);
                (a.abs(), c)
            }
        }
    }

    pub fn area(&self) -> f64 {
        self.area_centroid().0
    }

    /// Points on the boundary, dense enough that their bounds are the profile's within
    /// 1e-9 of its size for the straight parts (arcs are sampled at every degree and at
    /// their extremes).
    pub fn outline(&self) -> Vec<[f64; 2]> {
        let circle = |r: f64, c: [f64; 2]| -> Vec<[f64; 2]> {
            (0..360).map(|k| f64::from(k).to_radians()).map(|t| [c[0] + r * t.cos(), c[1] + r * t.sin()]).collect()
        };
        match self {
            Profile::Rect { w, h } | Profile::RoundedRect { w, h, .. } => {
                vec![[-w / 2.0, -h / 2.0], [w / 2.0, -h / 2.0], [w / 2.0, h / 2.0], [-w / 2.0, h / 2.0]]
            }
            Profile::Circle { d } | Profile::Annulus { od: d, .. } => circle(d / 2.0, [0.0, 0.0]),
            Profile::Ellipse { a, b } => {
                (0..360).map(|k| f64::from(k).to_radians()).map(|t| [a / 2.0 * t.cos(), b / 2.0 * t.sin()]).collect()
            }
            Profile::Ngon { n, d, phase } => regular(*n, d / 2.0, phase.to_radians()),
            Profile::Star { n, tip, root } => star(*n, *tip, *root),
            Profile::Stadium { l, w } => {
                let mut p = circle(w / 2.0, [-(l - w) / 2.0, 0.0]);
                p.extend(circle(w / 2.0, [(l - w) / 2.0, 0.0]));
                p
            }
            Profile::Poly(pts) => pts.clone(),
            Profile::Path { start, segs } => {
                let mut out = vec![*start];
                let mut at = *start;
                for s in segs {
                    match s {
                        Seg::Line(p) => {
                            out.push(*p);
                            at = *p;
                        }
                        Seg::Arc { mid, end } => {
                            if let Some((c, r, a0, sweep)) = arc_of(at, *mid, *end) {
                                let steps = (sweep.abs().to_degrees().ceil() as usize).max(2);
                                for k in 1..=steps {
                                    let t = a0 + sweep * k as f64 / steps as f64;
                                    out.push([c[0] + r * t.cos(), c[1] + r * t.sin()]);
                                }
                                // The arc's extremes along u and v, where it passes them.
                                for q in 0..4 {
                                    let t = f64::from(q) * PI / 2.0;
                                    if angle_within(a0, sweep, t) {
                                        out.push([c[0] + r * t.cos(), c[1] + r * t.sin()]);
                                    }
                                }
                            }
                            out.push(*end);
                            at = *end;
                        }
                    }
                }
                out
            }
        }
    }

    /// Bounds after turning the profile by `rot` degrees about (0, 0): [[umin, vmin], [umax, vmax]].
    pub fn bounds(&self, rot: f64) -> [[f64; 2]; 2] {
        let (s, c) = rot.to_radians().sin_cos();
        let exact_round = matches!(self, Profile::Circle { .. } | Profile::Annulus { .. });
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        if exact_round {
            let r = match self {
                Profile::Circle { d } | Profile::Annulus { od: d, .. } => d / 2.0,
                _ => 0.0,
            };
            return [[-r, -r], [r, r]];
        }
        let mut pts = self.outline();
        if let Profile::RoundedRect { .. } | Profile::Ellipse { .. } | Profile::Stadium { .. } = self
            && rot.rem_euclid(90.0).abs() < 1e-12
        {
            // Axis-aligned: the exact box.
            let (w, h) = match self {
                Profile::RoundedRect { w, h, .. } => (*w, *h),
                Profile::Ellipse { a, b } => (*a, *b),
                Profile::Stadium { l, w } => (*l, *w),
                _ => (0.0, 0.0),
            };
            pts = vec![[-w / 2.0, -h / 2.0], [w / 2.0, h / 2.0]];
        }
        for p in pts {
            let q = [c * p[0] - s * p[1], s * p[0] + c * p[1]];
            for k in 0..2 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        [lo, hi]
    }

    /// Whether (u, v) is inside (on the boundary counts as inside).
    pub fn contains(&self, p: [f64; 2]) -> bool {
        let [u, v] = p;
        let eps = 1e-9;
        match self {
            Profile::Rect { w, h } => u.abs() <= w / 2.0 + eps && v.abs() <= h / 2.0 + eps,
            Profile::RoundedRect { w, h, r } => {
                let (a, b) = ((u.abs() - (w / 2.0 - r)).max(0.0), (v.abs() - (h / 2.0 - r)).max(0.0));
                u.abs() <= w / 2.0 + eps && v.abs() <= h / 2.0 + eps && a * a + b * b <= (r + eps) * (r + eps)
            }
            Profile::Circle { d } => u * u + v * v <= (d / 2.0 + eps).powi(2),
            Profile::Annulus { od, id } => {
                let q = u * u + v * v;
                q <= (od / 2.0 + eps).powi(2) && q >= (id / 2.0 - eps).powi(2)
            }
            Profile::Ellipse { a, b } => (u / (a / 2.0)).powi(2) + (v / (b / 2.0)).powi(2) <= 1.0 + eps,
            Profile::Stadium { l, w } => {
                let du = (u.abs() - (l - w) / 2.0).max(0.0);
                du * du + v * v <= (w / 2.0 + eps).powi(2)
            }
            _ => point_in_polygon(&self.outline(), p),
        }
    }

    /// CadQuery calls that draw the profile on the current workplane, centred on its
    /// origin (chained after a `Workplane(...)` expression).
    pub fn code(&self) -> String {
        match self {
            Profile::Rect { w, h } => format!(".rect({}, {})", n(*w), n(*h)),
            Profile::RoundedRect { w, h, r } => {
                format!(".sketch().rect({}, {}).vertices().fillet({}).finalize()", n(*w), n(*h), n(*r))
            }
            Profile::Circle { d } => format!(".circle({})", n(d / 2.0)),
            Profile::Annulus { od, id } => format!(".circle({}).circle({})", n(od / 2.0), n(id / 2.0)),
            Profile::Ellipse { a, b } => format!(".ellipse({}, {})", n(a / 2.0), n(b / 2.0)),
            Profile::Ngon { n: k, d, phase } => {
                if phase.abs() < 1e-12 {
                    format!(".polygon({k}, {})", n(*d))
                } else {
                    poly_code(&regular(*k, d / 2.0, phase.to_radians()))
                }
            }
            Profile::Star { n: k, tip, root } => poly_code(&star(*k, *tip, *root)),
            Profile::Stadium { l, w } => format!(".slot2D({}, {})", n(*l), n(*w)),
            Profile::Poly(pts) => poly_code(pts),
            Profile::Path { start, segs } => {
                let mut s = format!(".moveTo({}, {})", n(start[0]), n(start[1]));
                for seg in segs {
                    match seg {
                        Seg::Line(p) => s.push_str(&format!(".lineTo({}, {})", n(p[0]), n(p[1]))),
                        Seg::Arc { mid, end } => s.push_str(&format!(
                            ".threePointArc(({}, {}), ({}, {}))",
                            n(mid[0]),
                            n(mid[1]),
                            n(end[0]),
                            n(end[1])
                        )),
                    }
                }
                s.push_str(".close()");
                s
            }
        }
    }

    /// The profile grown (positive) or shrunk (negative) by `t` where that is again a
    /// profile of the same kind (used for shells).
    pub fn offset(&self, t: f64) -> Option<Profile> {
        let p = match self {
            Profile::Rect { w, h } => Profile::Rect { w: w + 2.0 * t, h: h + 2.0 * t },
            Profile::RoundedRect { w, h, r } if r + t > 0.0 => {
                Profile::RoundedRect { w: w + 2.0 * t, h: h + 2.0 * t, r: r + t }
            }
            Profile::RoundedRect { w, h, .. } => Profile::Rect { w: w + 2.0 * t, h: h + 2.0 * t },
            Profile::Circle { d } => Profile::Circle { d: d + 2.0 * t },
            Profile::Stadium { l, w } => Profile::Stadium { l: l + 2.0 * t, w: w + 2.0 * t },
            _ => return None,
        };
        Some(p)
    }
}

fn poly_code(pts: &[[f64; 2]]) -> String {
    let p: Vec<String> = pts.iter().map(|q| format!("({}, {})", n(q[0]), n(q[1]))).collect();
    format!(".polyline([{}]).close()", p.join(", "))
}

/// A regular polygon with circumradius `r`, the first corner at `phase` radians.
pub fn regular(k: usize, r: f64, phase: f64) -> Vec<[f64; 2]> {
    (0..k)
        .map(|i| {
            let t = phase + 2.0 * PI * i as f64 / k as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// A star polygon of `teeth` tips alternating between the tip and root radii.
pub fn star(teeth: usize, tip: f64, root: f64) -> Vec<[f64; 2]> {
    (0..2 * teeth)
        .map(|k| {
            let t = PI * k as f64 / teeth as f64;
            let r = if k % 2 == 0 { tip } else { root };
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// Signed area and centroid of a polygon (counter-clockwise positive).
pub fn poly_area_centroid(pts: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let mut a = 0.0;
    let (mut cx, mut cy) = (0.0, 0.0);
    for (i, p) in pts.iter().enumerate() {
        let q = pts[(i + 1) % pts.len()];
        let cross = p[0] * q[1] - q[0] * p[1];
        a += cross;
        cx += (p[0] + q[0]) * cross;
        cy += (p[1] + q[1]) * cross;
    }
    a /= 2.0;
    if a.abs() < 1e-15 {
        return (0.0, [0.0, 0.0]);
    }
    (a, [cx / (6.0 * a), cy / (6.0 * a)])
}

/// The circle through three points: centre, radius, the start angle and the signed sweep
/// from `a` through `m` to `b`.
pub fn arc_of(a: [f64; 2], m: [f64; 2], b: [f64; 2]) -> Option<([f64; 2], f64, f64, f64)> {
    let d = 2.0 * (a[0] * (m[1] - b[1]) + m[0] * (b[1] - a[1]) + b[0] * (a[1] - m[1]));
    if d.abs() < 1e-12 {
        return None;
    }
    let sq = |p: [f64; 2]| p[0] * p[0] + p[1] * p[1];
    let ux = (sq(a) * (m[1] - b[1]) + sq(m) * (b[1] - a[1]) + sq(b) * (a[1] - m[1])) / d;
    let uy = (sq(a) * (b[0] - m[0]) + sq(m) * (a[0] - b[0]) + sq(b) * (m[0] - a[0])) / d;
    let c = [ux, uy];
    let r = ((a[0] - ux).powi(2) + (a[1] - uy).powi(2)).sqrt();
    let ang = |p: [f64; 2]| (p[1] - uy).atan2(p[0] - ux);
    let (ta, tm, tb) = (ang(a), ang(m), ang(b));
    // Counter-clockwise sweep from a to b; flip when m is not on it.
    let ccw = (tb - ta).rem_euclid(2.0 * PI);
    let to_m = (tm - ta).rem_euclid(2.0 * PI);
    let sweep = if to_m <= ccw { ccw } else { ccw - 2.0 * PI };
    Some((c, r, ta, sweep))
}

fn angle_within(a0: f64, sweep: f64, t: f64) -> bool {
    let rel = if sweep >= 0.0 { (t - a0).rem_euclid(2.0 * PI) } else { (a0 - t).rem_euclid(2.0 * PI) };
    rel <= sweep.abs() + 1e-12
}

/// Area and centroid of a closed path of lines and arcs: the polygon of its vertices
/// plus (or minus) the circular segment of each arc.
pub fn path_area_centroid(start: [f64; 2], segs: &[Seg]) -> (f64, [f64; 2]) {
    let mut verts = vec![start];
    let mut pieces: Vec<(f64, [f64; 2])> = Vec::new();
    let mut at = start;
    for s in segs {
        match s {
            Seg::Line(p) => {
                verts.push(*p);
                at = *p;
            }
            Seg::Arc { mid, end } => {
                if let Some((c, r, a0, sweep)) = arc_of(at, *mid, *end) {
                    // The segment between the chord and the arc: area r²/2 (θ − sin θ),
                    // centroid on the bisector at 4 r sin³(θ/2) / (3 (θ − sin θ)).
                    let th = sweep.abs();
                    let area = r * r / 2.0 * (th - th.sin());
                    let bis = a0 + sweep / 2.0;
                    let dist = if th - th.sin() > 1e-15 {
                        4.0 * r * (th / 2.0).sin().powi(3) / (3.0 * (th - th.sin()))
                    } else {
                        r
                    };
                    let cen = [c[0] + dist * bis.cos(), c[1] + dist * bis.sin()];
                    // A counter-clockwise arc on a counter-clockwise path bulges outwards.
                    let sign = if sweep > 0.0 { 1.0 } else { -1.0 };
                    pieces.push((sign * area, cen));
                }
                verts.push(*end);
                at = *end;
            }
        }
    }
    // Signed throughout: an arc turning the path's way bulges out of it, the other way in.
    let (pa, pc) = poly_area_centroid(&verts);
    let mut area = pa;
    let mut mx = pa * pc[0];
    let mut my = pa * pc[1];
    for (a, c) in pieces {
        area += a;
        mx += a * c[0];
        my += a * c[1];
    }
    if area.abs() < 1e-15 {
        return (0.0, [0.0, 0.0]);
    }
    (area, [mx / area, my / area])
}

fn point_in_polygon(poly: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    let k = poly.len();
    for i in 0..k {
        let (a, b) = (poly[i], poly[(i + 1) % k]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x {
                inside = !inside;
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_half_disc_path_has_the_half_discs_area_and_centroid() {
        // From (-1, 0) along the lower semicircle to (1, 0), then back along the diameter.
        let p = Profile::Path {
            start: [-1.0, 0.0],
            segs: vec![Seg::Arc { mid: [0.0, -1.0], end: [1.0, 0.0] }, Seg::Line([-1.0, 0.0])],
        };
        let (a, c) = p.area_centroid();
        assert!((a - PI / 2.0).abs() < 1e-12, "{a}");
        assert!((c[1] + 4.0 / (3.0 * PI)).abs() < 1e-12, "{c:?}");
        let b = p.bounds(0.0);
        assert!((b[0][1] + 1.0).abs() < 1e-9 && (b[1][0] - 1.0).abs() < 1e-9, "{b:?}");
    }

    #[test]
    fn stars_rings_and_rounded_rectangles() {
        let s = Profile::Star { n: 16, tip: 20.0, root: 16.0 };
        assert!((s.area() - 16.0 * 20.0 * 16.0 * (PI / 16.0).sin()).abs() < 1e-9);
        let poly = Profile::Poly(star(16, 20.0, 16.0));
        assert!((poly.area() - s.area()).abs() < 1e-9);
        let r = Profile::RoundedRect { w: 60.0, h: 40.0, r: 5.0 };
        assert!(r.contains([29.0, 0.0]) && !r.contains([29.9, 19.9]));
        assert_eq!(r.offset(-2.0), Some(Profile::RoundedRect { w: 56.0, h: 36.0, r: 3.0 }));
        let b = Profile::Rect { w: 10.0, h: 2.0 }.bounds(90.0);
        assert!((b[1][1] - 5.0).abs() < 1e-12 && (b[1][0] - 1.0).abs() < 1e-12, "{b:?}");
    }
}
