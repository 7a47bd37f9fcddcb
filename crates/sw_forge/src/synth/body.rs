//! A small solid-modelling description the templates build: primitives that are added
//! (pairwise disjoint) and cut (pairwise disjoint, inside what is added), each with an
//! exact volume and bounding box, written out as CadQuery code. Because of those two
//! rules the part's volume is the sum of what is added minus the sum of what is cut, and
//! its bounding box is that of what is added — the analytic values the validator checks
//! the executed code against.

use std::f64::consts::PI;
use std::fmt::Write as _;

/// A direction along an axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    X,
    Y,
    Z,
}

/// Which edges of a box are rounded or bevelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BoxEdges {
    All,
    /// The four edges parallel to an axis.
    Parallel(Dir),
}

/// An edge treatment of a box or cylinder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Edge {
    Fillet(f64),
    Chamfer(f64),
}

/// A primitive, in mm.
#[derive(Debug, Clone, PartialEq)]
pub enum Prim {
    /// A box centred at `c` with size `s`, optionally with treated edges.
    Box {
        c: [f64; 3],
        s: [f64; 3],
        edges: Option<(BoxEdges, Edge)>,
    },
    /// A cylinder along `dir` centred at `c`, optionally with both circular edges treated.
    Cyl {
        c: [f64; 3],
        r: f64,
        len: f64,
        dir: Dir,
        edge: Option<Edge>,
    },
    /// A polygon (counter-clockwise, in the plane normal to `dir`: XY → (x, y), YZ → (y, z),
    /// XZ → (x, z)) extruded symmetrically `len` along `dir` about `mid`.
    Prism {
        pts: Vec<[f64; 2]>,
        dir: Dir,
        mid: f64,
        len: f64,
    },
    /// A profile in (r, z) revolved about the vertical axis through (x, y).
    Revolve {
        profile: Vec<[f64; 2]>,
        x: f64,
        y: f64,
    },
    Sphere {
        c: [f64; 3],
        r: f64,
    },
    /// An elliptic cylinder along Z, semi-axes `a` (X) and `b` (Y), from z0 up `h`.
    Ellipse {
        a: f64,
        b: f64,
        z0: f64,
        h: f64,
    },
    /// A rectangle (X × Y) with semicircular ends on its short sides, along Z.
    Stadium {
        l: f64,
        w: f64,
        z0: f64,
        h: f64,
    },
    /// A loft between two centred rectangles: base `a0 × b0` at z0, top `a1 × b1` at z0 + h
    /// (a pyramid when the top is 0 × 0).
    RectFrustum {
        a0: f64,
        b0: f64,
        a1: f64,
        b1: f64,
        z0: f64,
        h: f64,
    },
}

impl Prim {
    pub fn volume(&self) -> f64 {
        match self {
            Prim::Box { s, edges, .. } => {
                let [a, b, c] = *s;
                let base = a * b * c;
                match edges {
                    None => base,
                    Some((BoxEdges::All, Edge::Fillet(r))) => {
                        let (p, q, t) = (a - 2.0 * r, b - 2.0 * r, c - 2.0 * r);
                        p * q * t
                            + 2.0 * (p * q + q * t + p * t) * r
                            + PI * (p + q + t) * r * r
                            + 4.0 / 3.0 * PI * r.powi(3)
                    }
                    Some((BoxEdges::All, Edge::Chamfer(k))) => base - 2.0 * k * k * (a + b + c) + 6.0 * k.powi(3),
                    Some((BoxEdges::Parallel(d), e)) => {
                        let len = match d {
                            Dir::X => a,
                            Dir::Y => b,
                            Dir::Z => c,
                        };
                        let corner = match e {
                            Edge::Fillet(r) => (4.0 - PI) * r * r,
                            Edge::Chamfer(k) => 2.0 * k * k,
                        };
                        base - corner * len
                    }
                }
            }
            Prim::Cyl { r, len, edge, .. } => {
                let base = PI * r * r * len;
                match edge {
                    None => base,
                    Some(Edge::Chamfer(k)) => base - 2.0 * 2.0 * PI * (r - k / 3.0) * (k * k / 2.0),
                    Some(Edge::Fillet(f)) => {
                        let area = f * f * (1.0 - PI / 4.0);
                        let xbar = f * (5.0 / 6.0 - PI / 4.0) / (1.0 - PI / 4.0);
                        base - 2.0 * 2.0 * PI * (r - xbar) * area
                    }
                }
            }
            Prim::Prism { pts, len, .. } => polygon_area(pts).abs() * len,
            Prim::Revolve { profile, .. } => {
                // Pappus: 2π × area × the centroid's distance from the axis.
                let (area, cx, _) = polygon_centroid(profile);
                2.0 * PI * area.abs() * cx.abs()
            }
            Prim::Sphere { r, .. } => 4.0 / 3.0 * PI * r.powi(3),
            Prim::Ellipse { a, b, h, .. } => PI * a * b * h,
            Prim::Stadium { l, w, h, .. } => ((l - w) * w + PI * w * w / 4.0) * h,
            Prim::RectFrustum { a0, b0, a1, b1, h, .. } => {
                // Prismatoid: h/6 (A0 + 4 Am + A1).
                let am = (a0 + a1) / 2.0 * (b0 + b1) / 2.0;
                h / 6.0 * (a0 * b0 + 4.0 * am + a1 * b1)
            }
        }
    }

    /// Axis-aligned bounds, [min, max].
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        match self {
            Prim::Box { c, s, .. } => [
                [c[0] - s[0] / 2.0, c[1] - s[1] / 2.0, c[2] - s[2] / 2.0],
                [c[0] + s[0] / 2.0, c[1] + s[1] / 2.0, c[2] + s[2] / 2.0],
            ],
            Prim::Cyl { c, r, len, dir, .. } => {
                let half = match dir {
                    Dir::X => [len / 2.0, *r, *r],
                    Dir::Y => [*r, len / 2.0, *r],
                    Dir::Z => [*r, *r, len / 2.0],
                };
                [[c[0] - half[0], c[1] - half[1], c[2] - half[2]], [c[0] + half[0], c[1] + half[1], c[2] + half[2]]]
            }
            Prim::Prism { pts, dir, mid, len } => {
                let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
                for p in pts {
                    for k in 0..2 {
                        lo[k] = lo[k].min(p[k]);
                        hi[k] = hi[k].max(p[k]);
                    }
                }
                let (a0, a1) = (mid - len / 2.0, mid + len / 2.0);
                match dir {
                    Dir::Z => [[lo[0], lo[1], a0], [hi[0], hi[1], a1]],
                    Dir::X => [[a0, lo[0], lo[1]], [a1, hi[0], hi[1]]],
                    Dir::Y => [[lo[0], a0, lo[1]], [hi[0], a1, hi[1]]],
                }
            }
            Prim::Revolve { profile, x, y } => {
                let rmax = profile.iter().map(|p| p[0].abs()).fold(0.0, f64::max);
                let zmin = profile.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
                let zmax = profile.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
                [[x - rmax, y - rmax, zmin], [x + rmax, y + rmax, zmax]]
            }
            Prim::Sphere { c, r } => [[c[0] - r, c[1] - r, c[2] - r], [c[0] + r, c[1] + r, c[2] + r]],
            Prim::Ellipse { a, b, z0, h } => [[-a, -b, *z0], [*a, *b, z0 + h]],
            Prim::Stadium { l, w, z0, h } => [[-l / 2.0, -w / 2.0, *z0], [l / 2.0, w / 2.0, z0 + h]],
            Prim::RectFrustum { a0, b0, a1, b1, z0, h } => {
                let (a, b) = (a0.max(*a1), b0.max(*b1));
                [[-a / 2.0, -b / 2.0, *z0], [a / 2.0, b / 2.0, z0 + h]]
            }
        }
    }

    /// A CadQuery expression for this primitive.
    pub fn code(&self) -> String {
        match self {
            Prim::Box { c, s, edges } => {
                let mut e = format!("cq.Workplane('XY').box({}, {}, {})", n(s[0]), n(s[1]), n(s[2]));
                if let Some((which, treat)) = edges {
                    let sel = match which {
                        BoxEdges::All => "edges()".to_string(),
                        BoxEdges::Parallel(Dir::X) => "edges('|X')".to_string(),
                        BoxEdges::Parallel(Dir::Y) => "edges('|Y')".to_string(),
                        BoxEdges::Parallel(Dir::Z) => "edges('|Z')".to_string(),
                    };
                    let op = match treat {
                        Edge::Fillet(r) => format!("fillet({})", n(*r)),
                        Edge::Chamfer(k) => format!("chamfer({})", n(*k)),
                    };
                    let _ = write!(e, ".{sel}.{op}");
                }
                translate(e, *c)
            }
            Prim::Cyl { c, r, len, dir, edge } => {
                let plane = plane_of(*dir);
                let mut e = format!("cq.Workplane('{plane}').circle({}).extrude({}, both=True)", n(*r), n(len / 2.0));
                if let Some(treat) = edge {
                    let op = match treat {
                        Edge::Fillet(f) => format!("fillet({})", n(*f)),
                        Edge::Chamfer(k) => format!("chamfer({})", n(*k)),
                    };
                    let _ = write!(e, ".edges('%CIRCLE').{op}");
                }
                translate(e, *c)
            }
            Prim::Prism { pts, dir, mid, len } => {
                let plane = plane_of(*dir);
                let pts: Vec<String> = pts.iter().map(|p| format!("({}, {})", n(p[0]), n(p[1]))).collect();
                let e = format!(
                    "cq.Workplane('{plane}').polyline([{}]).close().extrude({}, both=True)",
                    pts.join(", "),
                    n(len / 2.0)
                );
                let c = match dir {
                    Dir::X => [*mid, 0.0, 0.0],
                    // The XZ plane's normal is −Y: its symmetric extrusion does not care.
                    Dir::Y => [0.0, *mid, 0.0],
                    Dir::Z => [0.0, 0.0, *mid],
                };
                translate(e, c)
            }
            Prim::Revolve { profile, x, y } => {
                let pts: Vec<String> = profile.iter().map(|p| format!("({}, {})", n(p[0]), n(p[1]))).collect();
                let e = format!(
                    "cq.Workplane('XZ').polyline([{}]).close().revolve(360, (0, 0, 0), (0, 1, 0))",
                    pts.join(", ")
                );
                translate(e, [*x, *y, 0.0])
            }
            Prim::Sphere { c, r } => translate(format!("cq.Workplane('XY').sphere({})", n(*r)), *c),
            Prim::Ellipse { a, b, z0, h } => {
                format!(
                    "cq.Workplane('XY').workplane(offset={}).ellipse({}, {}).extrude({})",
                    n(*z0),
                    n(*a),
                    n(*b),
                    n(*h)
                )
            }
            Prim::Stadium { l, w, z0, h } => format!(
                "cq.Workplane('XY').workplane(offset={}).slot2D({}, {}).extrude({})",
                n(*z0),
                n(*l),
                n(*w),
                n(*h)
            ),
            Prim::RectFrustum { a0, b0, a1, b1, z0, h } => {
                if *a1 <= 0.0 || *b1 <= 0.0 {
                    // A pyramid: five faces made from polygons.
                    let (x, y) = (a0 / 2.0, b0 / 2.0);
                    let (z, t) = (*z0, z0 + h);
                    let v = |p: [f64; 3]| format!("cq.Vector({}, {}, {})", n(p[0]), n(p[1]), n(p[2]));
                    let base = [[-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z]];
                    let apex = [0.0, 0.0, t];
                    let mut faces = vec![format!(
                        "cq.Face.makeFromWires(cq.Wire.makePolygon([{}], close=True))",
                        base.iter().map(|p| v(*p)).collect::<Vec<_>>().join(", ")
                    )];
                    for k in 0..4 {
                        faces.push(format!(
                            "cq.Face.makeFromWires(cq.Wire.makePolygon([{}, {}, {}], close=True))",
                            v(base[k]),
                            v(base[(k + 1) % 4]),
                            v(apex)
                        ));
                    }
                    format!("cq.Workplane('XY').add(cq.Solid.makeSolid(cq.Shell.makeShell([{}])))", faces.join(", "))
                } else {
                    format!(
                        "cq.Workplane('XY').workplane(offset={}).rect({}, {}).workplane(offset={}).rect({}, {}).loft(combine=True)",
                        n(*z0),
                        n(*a0),
                        n(*b0),
                        n(*h),
                        n(*a1),
                        n(*b1)
                    )
                }
            }
        }
    }
}

fn plane_of(d: Dir) -> &'static str {
    match d {
        Dir::X => "YZ",
        Dir::Y => "XZ",
        Dir::Z => "XY",
    }
}

fn translate(e: String, c: [f64; 3]) -> String {
    if c.iter().all(|v| v.abs() < 1e-12) {
        e
    } else {
        format!("{e}.translate(({}, {}, {}))", n(c[0]), n(c[1]), n(c[2]))
    }
}

/// A number for code: at most 6 decimals, no trailing zeros.
pub fn n(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.to_string() }
}

/// Signed shoelace area.
pub fn polygon_area(pts: &[[f64; 2]]) -> f64 {
    let mut a = 0.0;
    for (i, p) in pts.iter().enumerate() {
        let q = pts[(i + 1) % pts.len()];
        a += p[0] * q[1] - q[0] * p[1];
    }
    a / 2.0
}

/// Signed area and centroid of a polygon.
pub fn polygon_centroid(pts: &[[f64; 2]]) -> (f64, f64, f64) {
    let a = polygon_area(pts);
    let (mut cx, mut cy) = (0.0, 0.0);
    for (i, p) in pts.iter().enumerate() {
        let q = pts[(i + 1) % pts.len()];
        let cross = p[0] * q[1] - q[0] * p[1];
        cx += (p[0] + q[0]) * cross;
        cy += (p[1] + q[1]) * cross;
    }
    if a.abs() < 1e-15 {
        return (0.0, 0.0, 0.0);
    }
    (a, cx / (6.0 * a), cy / (6.0 * a))
}

/// A regular polygon with circumradius `r`, the first vertex at `phase` radians.
pub fn regular(nv: usize, r: f64, phase: f64) -> Vec<[f64; 2]> {
    (0..nv)
        .map(|k| {
            let t = phase + 2.0 * PI * k as f64 / nv as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// A star polygon of `teeth` points alternating between `tip` and `root` radii.
pub fn star(teeth: usize, tip: f64, root: f64) -> Vec<[f64; 2]> {
    (0..2 * teeth)
        .map(|k| {
            let t = PI * k as f64 / teeth as f64;
            let r = if k % 2 == 0 { tip } else { root };
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// A part: what is added, what is cut.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Body {
    pub add: Vec<Prim>,
    pub cut: Vec<Prim>,
    /// The cuts may overlap each other or stick out of the part (the volume is then not
    /// known exactly and is not checked).
    pub inexact: bool,
    /// The volume, when the template knows it better than the disjoint sum.
    pub exact: Option<f64>,
}

impl Body {
    pub fn of(p: Prim) -> Self {
        Self { add: vec![p], ..Self::default() }
    }

    pub fn plus(mut self, p: Prim) -> Self {
        self.add.push(p);
        self
    }

    pub fn minus(mut self, p: Prim) -> Self {
        self.cut.push(p);
        self
    }

    pub fn volume(&self) -> Option<f64> {
        if let Some(v) = self.exact {
            return Some(v);
        }
        if self.inexact {
            return None;
        }
        Some(self.add.iter().map(Prim::volume).sum::<f64>() - self.cut.iter().map(Prim::volume).sum::<f64>())
    }

    pub fn bounds(&self) -> [[f64; 3]; 2] {
        let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        for p in &self.add {
            let q = p.bounds();
            for k in 0..3 {
                b[0][k] = b[0][k].min(q[0][k]);
                b[1][k] = b[1][k].max(q[1][k]);
            }
        }
        b
    }

    pub fn size(&self) -> [f64; 3] {
        let b = self.bounds();
        [b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]]
    }

    /// CadQuery code that assigns the part to `result`.
    pub fn code(&self, title: &str) -> String {
        let mut s = format!(
            "# {title}\n# Units: mm. Written by scenewright's template synthesizer.\nimport cadquery as cq\n\n"
        );
        for (i, p) in self.add.iter().enumerate() {
            let _ = writeln!(s, "{} = {}", if i == 0 { "result".to_string() } else { format!("add_{i}") }, p.code());
            if i > 0 {
                let _ = writeln!(s, "result = result.union(add_{i})");
            }
        }
        for (i, p) in self.cut.iter().enumerate() {
            let _ = writeln!(s, "cut_{i} = {}", p.code());
            let _ = writeln!(s, "result = result.cut(cut_{i})");
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_with_filleted_edges_matches_the_minkowski_sum() {
        let p = Prim::Box { c: [0.0; 3], s: [2.0, 2.0, 2.0], edges: Some((BoxEdges::All, Edge::Fillet(1.0))) };
        assert!((p.volume() - 4.0 / 3.0 * PI).abs() < 1e-9);
        let p = Prim::Box { c: [0.0; 3], s: [4.0, 4.0, 4.0], edges: Some((BoxEdges::All, Edge::Chamfer(2.0))) };
        assert!((p.volume() - 16.0).abs() < 1e-9, "a rhombic dodecahedron");
    }

    #[test]
    fn revolved_profiles_follow_pappus() {
        let cone = Prim::Revolve { profile: vec![[0.0, 0.0], [3.0, 0.0], [0.0, 4.0]], x: 0.0, y: 0.0 };
        assert!((cone.volume() - PI * 9.0 * 4.0 / 3.0).abs() < 1e-9);
        let pyramid = Prim::RectFrustum { a0: 2.0, b0: 2.0, a1: 0.0, b1: 0.0, z0: 0.0, h: 3.0 };
        assert!((pyramid.volume() - 4.0).abs() < 1e-9);
    }

    #[test]
    fn numbers_print_short() {
        assert_eq!(n(2.0), "2");
        assert_eq!(n(10.5), "10.5");
        assert_eq!(n(-0.0000001), "0");
    }
}
