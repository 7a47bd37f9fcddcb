//! Solids of the feature language: a profile extruded along an axis, cones and frustums,
//! spheres and hemispheres, tori, revolved profiles, lofts, pyramids and pipe bends swept
//! along an arc — each placed in part coordinates (mm), with its exact volume and bounds —
//! and bodies: a solid with its edge treatments and its shell.

use std::f64::consts::PI;

use super::num::n;
use super::profile::Profile;

/// A part axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Axis {
    X,
    Y,
    Z,
}

impl Axis {
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        }
    }

    /// The in-plane axes (u, v) of a profile extruded along this axis, right-handed:
    /// u × v is the axis.
    pub fn uv(self) -> (Axis, Axis) {
        match self {
            Axis::Z => (Axis::X, Axis::Y),
            Axis::X => (Axis::Y, Axis::Z),
            Axis::Y => (Axis::Z, Axis::X),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "X",
            Axis::Y => "Y",
            Axis::Z => "Z",
        }
    }

    fn unit(self) -> [f64; 3] {
        let mut v = [0.0; 3];
        v[self.index()] = 1.0;
        v
    }

    /// A CadQuery plane at the origin whose x direction is u and whose normal is the axis.
    fn plane(self) -> String {
        let (u, _) = self.uv();
        format!("cq.Plane(origin=(0, 0, 0), xDir={}, normal={})", tup(u.unit()), tup(self.unit()))
    }
}

/// Part coordinates of a point given along an axis and in its (u, v) plane.
pub fn point(axis: Axis, uv: [f64; 2], w: f64) -> [f64; 3] {
    let (u, v) = axis.uv();
    let mut p = [0.0; 3];
    p[u.index()] = uv[0];
    p[v.index()] = uv[1];
    p[axis.index()] = w;
    p
}

/// A solid in part coordinates.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// `profile` in the plane normal to `axis`, turned `rot` degrees about its own origin,
    /// its origin at `at` (u, v), extruded from `from` to `to` along the axis.
    Prism {
        profile: Profile,
        axis: Axis,
        at: [f64; 2],
        rot: f64,
        from: f64,
        to: f64,
    },
    /// A cone or frustum along `axis`: diameter `d_from` at `from`, `d_to` at `to`.
    Cone {
        axis: Axis,
        at: [f64; 2],
        from: f64,
        to: f64,
        d_from: f64,
        d_to: f64,
    },
    Sphere {
        c: [f64; 3],
        d: f64,
    },
    /// The half of a sphere on the `up` (positive) or negative side of `c` along `axis`.
    Hemisphere {
        c: [f64; 3],
        d: f64,
        axis: Axis,
        up: bool,
    },
    /// A ring torus: `major` the diameter of its centre circle, `minor` of its tube.
    Torus {
        c: [f64; 3],
        axis: Axis,
        major: f64,
        minor: f64,
    },
    /// A profile in (r, z) revolved about the vertical axis through (x, y) = `at`.
    Revolve {
        at: [f64; 2],
        profile: Profile,
    },
    /// A loft along Z from `bottom` at `from` to `top` at `to`, centred on `at`.
    Loft {
        at: [f64; 2],
        from: f64,
        to: f64,
        bottom: Profile,
        top: Profile,
    },
    /// A pyramid on a `w` × `d` rectangle at `from`, its apex at `to` along Z.
    Pyramid {
        at: [f64; 2],
        from: f64,
        to: f64,
        w: f64,
        d: f64,
    },
    /// A pipe (outer diameter `od`, inner `id`, 0 for a solid rod) swept along a circular
    /// arc of `radius` about `centre` in the plane of axes (`u`, `v`), from angle `a0` to
    /// `a1` degrees (a point at angle a is centre + radius (cos a · u + sin a · v)).
    Bend {
        od: f64,
        id: f64,
        centre: [f64; 3],
        radius: f64,
        u: Axis,
        v: Axis,
        a0: f64,
        a1: f64,
    },
}

impl Shape {
    /// The exact volume, when it has a closed form.
    pub fn volume(&self) -> Option<f64> {
        Some(match self {
            Shape::Prism { profile, from, to, .. } => profile.area() * (to - from).abs(),
            Shape::Cone { from, to, d_from, d_to, .. } => {
                let (r0, r1) = (d_from / 2.0, d_to / 2.0);
                PI * (to - from).abs() / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1)
            }
            Shape::Sphere { d, .. } => PI * d.powi(3) / 6.0,
            Shape::Hemisphere { d, .. } => PI * d.powi(3) / 12.0,
            Shape::Torus { major, minor, .. } => 2.0 * PI * PI * (major / 2.0) * (minor / 2.0).powi(2),
            Shape::Revolve { profile, .. } => {
                let (a, c) = profile.area_centroid();
                2.0 * PI * a.abs() * c[0].abs()
            }
            Shape::Loft { from, to, bottom, top, .. } => match (bottom, top) {
                (Profile::Rect { w: a0, h: b0 }, Profile::Rect { w: a1, h: b1 }) => {
                    let am = (a0 + a1) / 2.0 * (b0 + b1) / 2.0;
                    (to - from).abs() / 6.0 * (a0 * b0 + 4.0 * am + a1 * b1)
                }
                (Profile::Circle { d: d0 }, Profile::Circle { d: d1 }) => {
                    let (r0, r1) = (d0 / 2.0, d1 / 2.0);
                    PI * (to - from).abs() / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1)
                }
                _ => return None,
            },
            Shape::Pyramid { from, to, w, d, .. } => w * d * (to - from).abs() / 3.0,
            Shape::Bend { od, id, radius, a0, a1, .. } => {
                PI * (od * od - id * id) / 4.0 * radius * (a1 - a0).abs().to_radians()
            }
        })
    }

    /// Axis-aligned bounds, [min, max].
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        match self {
            Shape::Prism { profile, axis, at, rot, from, to } => {
                let b = profile.bounds(*rot);
                let lo = point(*axis, [at[0] + b[0][0], at[1] + b[0][1]], from.min(*to));
                let hi = point(*axis, [at[0] + b[1][0], at[1] + b[1][1]], from.max(*to));
                [lo, hi]
            }
            Shape::Cone { axis, at, from, to, d_from, d_to } => {
                let r = d_from.max(*d_to) / 2.0;
                [
                    point(*axis, [at[0] - r, at[1] - r], from.min(*to)),
                    point(*axis, [at[0] + r, at[1] + r], from.max(*to)),
                ]
            }
            Shape::Sphere { c, d } => {
                let r = d / 2.0;
                [[c[0] - r, c[1] - r, c[2] - r], [c[0] + r, c[1] + r, c[2] + r]]
            }
            Shape::Hemisphere { c, d, axis, up } => {
                let r = d / 2.0;
                let mut b = [[c[0] - r, c[1] - r, c[2] - r], [c[0] + r, c[1] + r, c[2] + r]];
                let k = axis.index();
                if *up {
                    b[0][k] = c[k];
                } else {
                    b[1][k] = c[k];
                }
                b
            }
            Shape::Torus { c, axis, major, minor } => {
                let (rr, r) = (major / 2.0 + minor / 2.0, minor / 2.0);
                let mut b = [[c[0] - rr, c[1] - rr, c[2] - rr], [c[0] + rr, c[1] + rr, c[2] + rr]];
                let k = axis.index();
                b[0][k] = c[k] - r;
                b[1][k] = c[k] + r;
                b
            }
            Shape::Revolve { at, profile } => {
                let b = profile.bounds(0.0);
                let r = b[0][0].abs().max(b[1][0].abs());
                [[at[0] - r, at[1] - r, b[0][1]], [at[0] + r, at[1] + r, b[1][1]]]
            }
            Shape::Loft { at, from, to, bottom, top } => {
                let (b0, b1) = (bottom.bounds(0.0), top.bounds(0.0));
                let lo = [b0[0][0].min(b1[0][0]), b0[0][1].min(b1[0][1])];
                let hi = [b0[1][0].max(b1[1][0]), b0[1][1].max(b1[1][1])];
                [[at[0] + lo[0], at[1] + lo[1], from.min(*to)], [at[0] + hi[0], at[1] + hi[1], from.max(*to)]]
            }
            Shape::Pyramid { at, from, to, w, d } => {
                [[at[0] - w / 2.0, at[1] - d / 2.0, from.min(*to)], [at[0] + w / 2.0, at[1] + d / 2.0, from.max(*to)]]
            }
            Shape::Bend { od, centre, radius, u, v, a0, a1, .. } => {
                bend_bounds(*od, *centre, *radius, *u, *v, *a0, *a1)
            }
        }
    }

    /// A CadQuery expression for the solid.
    pub fn code(&self) -> String {
        match self {
            Shape::Prism { profile, axis, at, rot, from, to } => {
                let (lo, hi) = (from.min(*to), from.max(*to));
                let mut e = format!("cq.Workplane({}){}.extrude({})", axis.plane(), profile.code(), n(hi - lo));
                if rot.abs() > 1e-12 {
                    e.push_str(&format!(".rotate((0, 0, 0), {}, {})", tup(axis.unit()), n(*rot)));
                }
                translate(e, point(*axis, *at, lo))
            }
            Shape::Cone { axis, at, from, to, d_from, d_to } => {
                let (base, dir, r0, r1) = if to >= from {
                    (point(*axis, *at, *from), axis.unit(), d_from / 2.0, d_to / 2.0)
                } else {
                    (point(*axis, *at, *from), axis.unit().map(|c| -c), d_from / 2.0, d_to / 2.0)
                };
                format!(
                    "cq.Workplane('XY').add(cq.Solid.makeCone({}, {}, {}, cq.Vector{}, cq.Vector{}))",
                    n(r0),
                    n(r1),
                    n((to - from).abs()),
                    tup(base),
                    tup(dir)
                )
            }
            Shape::Sphere { c, d } => translate(format!("cq.Workplane('XY').sphere({})", n(d / 2.0)), *c),
            Shape::Hemisphere { c, d, axis, up } => {
                let dir = axis.unit().map(|x| if *up { x } else { -x });
                format!(
                    "cq.Workplane('XY').add(cq.Solid.makeSphere({}, cq.Vector{}, cq.Vector{}, 0, 90, 360))",
                    n(d / 2.0),
                    tup(*c),
                    tup(dir)
                )
            }
            Shape::Torus { c, axis, major, minor } => format!(
                "cq.Workplane('XY').add(cq.Solid.makeTorus({}, {}, cq.Vector{}, cq.Vector{}))",
                n(major / 2.0),
                n(minor / 2.0),
                tup(*c),
                tup(axis.unit())
            ),
            Shape::Revolve { at, profile } => translate(
                format!("cq.Workplane('XZ'){}.revolve(360, (0, 0, 0), (0, 1, 0))", profile.code()),
                [at[0], at[1], 0.0],
            ),
            Shape::Loft { at, from, to, bottom, top } => translate(
                format!(
                    "cq.Workplane('XY').workplane(offset={}){}.workplane(offset={}){}.loft(combine=True)",
                    n(*from),
                    bottom.code(),
                    n(to - from),
                    top.code()
                ),
                [at[0], at[1], 0.0],
            ),
            Shape::Pyramid { at, from, to, w, d } => {
                let (x, y) = (w / 2.0, d / 2.0);
                let v = |p: [f64; 3]| format!("cq.Vector{}", tup([p[0] + at[0], p[1] + at[1], p[2]]));
                let base = [[-x, -y, *from], [x, -y, *from], [x, y, *from], [-x, y, *from]];
                let apex = [0.0, 0.0, *to];
                let face = |ps: &[[f64; 3]]| {
                    format!(
                        "cq.Face.makeFromWires(cq.Wire.makePolygon([{}], close=True))",
                        ps.iter().map(|p| v(*p)).collect::<Vec<_>>().join(", ")
                    )
                };
                let mut faces = vec![face(&base)];
                for k in 0..4 {
                    faces.push(face(&[base[k], base[(k + 1) % 4], apex]));
                }
                format!("cq.Workplane('XY').add(cq.Solid.makeSolid(cq.Shell.makeShell([{}])).fix())", faces.join(", "))
            }
            Shape::Bend { od, id, centre, radius, u, v, a0, a1 } => {
                let at = |a: f64| {
                    let (s, c) = a.to_radians().sin_cos();
                    let mut p = *centre;
                    p[u.index()] += radius * c;
                    p[v.index()] += radius * s;
                    p
                };
                let (s, c) = a0.to_radians().sin_cos();
                let sign = if a1 >= a0 { 1.0 } else { -1.0 };
                let mut tangent = [0.0; 3];
                tangent[u.index()] = -s * sign;
                tangent[v.index()] = c * sign;
                let start = at(*a0);
                let mid = at((a0 + a1) / 2.0);
                let end = at(*a1);
                // The profile's x direction: the radial direction at the start.
                let mut radial = [0.0; 3];
                radial[u.index()] = c;
                radial[v.index()] = s;
                let plane = format!("cq.Plane(origin={}, xDir={}, normal={})", tup(start), tup(radial), tup(tangent));
                let path = format!(
                    "cq.Workplane('XY').add(cq.Wire.assembleEdges([cq.Edge.makeThreePointArc(cq.Vector{}, cq.Vector{}, cq.Vector{})]))",
                    tup(start),
                    tup(mid),
                    tup(end)
                );
                let rod =
                    |d: f64| format!("cq.Workplane({plane}).circle({}).sweep({path}, transition='round')", n(d / 2.0));
                if *id > 0.0 { format!("{}.cut({})", rod(*od), rod(*id)) } else { rod(*od) }
            }
        }
    }

    /// The extrusion axis of a prism (or a cone's axis).
    pub fn axis(&self) -> Option<Axis> {
        match self {
            Shape::Prism { axis, .. } | Shape::Cone { axis, .. } => Some(*axis),
            Shape::Revolve { .. } | Shape::Loft { .. } | Shape::Pyramid { .. } => Some(Axis::Z),
            _ => None,
        }
    }
}

fn bend_bounds(od: f64, centre: [f64; 3], radius: f64, u: Axis, v: Axis, a0: f64, a1: f64) -> [[f64; 3]; 2] {
    // The swept circle: at each point of the arc, a disc of radius od/2 normal to the
    // tangent. Its extent along a direction e is p·e + r·sqrt(1 − (t·e)²).
    let r = od / 2.0;
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let steps = 3600;
    for k in 0..=steps {
        let a = (a0 + (a1 - a0) * k as f64 / steps as f64).to_radians();
        let (s, c) = a.sin_cos();
        let mut p = centre;
        p[u.index()] += radius * c;
        p[v.index()] += radius * s;
        let mut t = [0.0; 3];
        t[u.index()] = -s;
        t[v.index()] = c;
        for i in 0..3 {
            let reach = r * (1.0 - t[i] * t[i]).max(0.0).sqrt();
            lo[i] = lo[i].min(p[i] - reach);
            hi[i] = hi[i].max(p[i] + reach);
        }
    }
    [lo, hi]
}

fn tup(p: [f64; 3]) -> String {
    format!("({}, {}, {})", n(p[0]), n(p[1]), n(p[2]))
}

fn translate(e: String, c: [f64; 3]) -> String {
    if c.iter().all(|v| v.abs() < 1e-12) { e } else { format!("{e}.translate({})", tup(c)) }
}

/// Which edges of a body are rounded or bevelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edges {
    All,
    /// The edges parallel to an axis ("the four vertical edges").
    Parallel(Axis),
    /// The circular edges at both ends of a round body.
    Circular,
    /// The edges of the face at the positive (true) or negative end of an axis.
    Face(Axis, bool),
    /// The edges of both end faces along an axis ("the end edges" of a bar).
    Ends(Axis),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EdgeKind {
    Fillet,
    Chamfer,
}

/// A fillet or chamfer of a body's edges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeOp {
    pub edges: Edges,
    pub kind: EdgeKind,
    pub size: f64,
}

/// A body hollowed to a wall of `t` with the face at the end of `axis` (`max` or min) open.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shell {
    pub axis: Axis,
    pub max: bool,
    pub t: f64,
}

/// A solid with its edge treatments and its shell, as one piece of the part.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// What it is in the prompt's words ("flange", "bolt holes").
    pub label: String,
    pub shape: Shape,
    pub edges: Vec<EdgeOp>,
    pub shell: Option<Shell>,
}

impl Body {
    pub fn new(label: impl Into<String>, shape: Shape) -> Self {
        Self { label: label.into(), shape, edges: Vec::new(), shell: None }
    }

    pub fn bounds(&self) -> [[f64; 3]; 2] {
        self.shape.bounds()
    }

    /// The profile of a prism after its edge treatments, when they only round or bevel
    /// the edges along its axis.
    fn effective_profile(&self) -> Option<Profile> {
        let Shape::Prism { profile, axis, .. } = &self.shape else { return None };
        let mut p = profile.clone();
        for e in &self.edges {
            match (e.edges, e.kind, &p) {
                (Edges::Parallel(a), EdgeKind::Fillet, Profile::Rect { w, h }) if a == *axis => {
                    p = Profile::RoundedRect { w: *w, h: *h, r: e.size };
                }
                _ => return None,
            }
        }
        Some(p)
    }

    /// The exact volume, when the solid, its edge treatments and its shell have one.
    pub fn volume(&self) -> Option<f64> {
        let base = self.shape.volume()?;
        let solid = if self.edges.is_empty() {
            base
        } else if let Some(p) = self.effective_profile() {
            let Shape::Prism { from, to, .. } = &self.shape else { return None };
            p.area() * (to - from).abs()
        } else {
            self.treated_volume(base)?
        };
        let Some(shell) = self.shell else { return Some(solid) };
        // A prism along the shell's axis with a profile that offsets to its own kind.
        let Shape::Prism { axis, from, to, .. } = &self.shape else { return None };
        if *axis != shell.axis {
            return None;
        }
        let outer = if self.edges.is_empty() {
            match &self.shape {
                Shape::Prism { profile, .. } => profile.clone(),
                _ => return None,
            }
        } else {
            self.effective_profile()?
        };
        let inner = outer.offset(-shell.t)?;
        Some(solid - inner.area() * ((to - from).abs() - shell.t))
    }

    /// Volumes of boxes and cylinders with treated edges (one treatment).
    fn treated_volume(&self, base: f64) -> Option<f64> {
        let [e] = self.edges.as_slice() else { return None };
        match &self.shape {
            Shape::Prism { profile: Profile::Rect { .. }, rot, .. } if rot.rem_euclid(90.0).abs() < 1e-9 => {
                let b = self.shape.bounds();
                let s = [b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]];
                let (a, bb, c) = (s[0], s[1], s[2]);
                let k = e.size;
                match (e.edges, e.kind) {
                    (Edges::All, EdgeKind::Fillet) => {
                        let (p, q, t) = (a - 2.0 * k, bb - 2.0 * k, c - 2.0 * k);
                        Some(
                            p * q * t
                                + 2.0 * (p * q + q * t + p * t) * k
                                + PI * (p + q + t) * k * k
                                + 4.0 / 3.0 * PI * k.powi(3),
                        )
                    }
                    // OCCT closes each corner with the plane through the three chamfers'
                    // ends (x + y + z = 2k): 16/3 k³ back over the eight corners.
                    (Edges::All, EdgeKind::Chamfer) => {
                        Some(a * bb * c - 2.0 * k * k * (a + bb + c) + 16.0 / 3.0 * k.powi(3))
                    }
                    (Edges::Parallel(ax), kind) => {
                        let corner = match kind {
                            EdgeKind::Fillet => (4.0 - PI) * k * k,
                            EdgeKind::Chamfer => 2.0 * k * k,
                        };
                        Some(base - corner * s[ax.index()])
                    }
                    _ => None,
                }
            }
            Shape::Prism { profile: Profile::Circle { d }, .. } => {
                let r = d / 2.0;
                let k = e.size;
                let one_end = match e.kind {
                    EdgeKind::Chamfer => 2.0 * PI * (r - k / 3.0) * (k * k / 2.0),
                    EdgeKind::Fillet => {
                        let area = k * k * (1.0 - PI / 4.0);
                        let xbar = k * (5.0 / 6.0 - PI / 4.0) / (1.0 - PI / 4.0);
                        2.0 * PI * (r - xbar) * area
                    }
                };
                match e.edges {
                    Edges::Circular => Some(base - 2.0 * one_end),
                    Edges::Face(..) => Some(base - one_end),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// A CadQuery expression for the body.
    pub fn code(&self) -> String {
        let mut e = self.shape.code();
        for op in &self.edges {
            let sel = match op.edges {
                Edges::All => "edges()".to_string(),
                Edges::Parallel(a) => format!("edges('|{}')", a.name()),
                Edges::Circular => "edges('%CIRCLE')".to_string(),
                Edges::Face(a, max) => format!("faces('{}{}').edges()", if max { '>' } else { '<' }, a.name()),
                Edges::Ends(a) => format!("faces('>{0} or <{0}').edges()", a.name()),
            };
            let what = match op.kind {
                EdgeKind::Fillet => "fillet",
                EdgeKind::Chamfer => "chamfer",
            };
            e.push_str(&format!(".{sel}.{what}({})", n(op.size)));
        }
        if let Some(s) = self.shell {
            e.push_str(&format!(".faces('{}{}').shell({})", if s.max { '>' } else { '<' }, s.axis.name(), n(-s.t)));
        }
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn prism(profile: Profile, axis: Axis, from: f64, to: f64) -> Shape {
        Shape::Prism { profile, axis, at: [0.0, 0.0], rot: 0.0, from, to }
    }

    #[test]
    fn boxes_with_treated_edges_follow_steiner_and_occt_corners() {
        let mut b = Body::new("cube", prism(Profile::Rect { w: 2.0, h: 2.0 }, Axis::Z, 0.0, 2.0));
        b.edges.push(EdgeOp { edges: Edges::All, kind: EdgeKind::Fillet, size: 1.0 });
        assert!((b.volume().unwrap() - 4.0 / 3.0 * PI).abs() < 1e-9);
        let mut c = Body::new("block", prism(Profile::Rect { w: 25.0, h: 15.0 }, Axis::Z, 0.0, 10.0));
        c.edges.push(EdgeOp { edges: Edges::All, kind: EdgeKind::Chamfer, size: 1.0 });
        assert!((c.volume().unwrap() - (3650.0 + 16.0 / 3.0)).abs() < 1e-9);
    }

    #[test]
    fn an_open_shelled_rounded_box_is_outer_less_cavity() {
        let mut b = Body::new("tray", prism(Profile::Rect { w: 60.0, h: 40.0 }, Axis::Z, 0.0, 30.0));
        b.edges.push(EdgeOp { edges: Edges::Parallel(Axis::Z), kind: EdgeKind::Fillet, size: 5.0 });
        b.shell = Some(Shell { axis: Axis::Z, max: true, t: 2.0 });
        let outer = 60.0 * 40.0 - (4.0 - PI) * 25.0;
        let inner = 56.0 * 36.0 - (4.0 - PI) * 9.0;
        assert!((b.volume().unwrap() - (outer * 30.0 - inner * 28.0)).abs() < 1e-9);
    }

    #[test]
    fn bends_follow_pappus_and_reach_past_their_ends() {
        let s = Shape::Bend {
            od: 20.0,
            id: 16.0,
            centre: [40.0, 0.0, 0.0],
            radius: 40.0,
            u: Axis::X,
            v: Axis::Z,
            a0: 180.0,
            a1: 90.0,
        };
        assert!((s.volume().unwrap() - PI * 36.0 * PI / 2.0 * 40.0).abs() < 1e-9);
        let b = s.bounds();
        assert!(
            (b[0][0] + 10.0).abs() < 1e-6 && (b[1][0] - 40.0).abs() < 1e-6 && (b[1][2] - 50.0).abs() < 1e-6,
            "{b:?}"
        );
        let hemi = Shape::Hemisphere { c: [0.0; 3], d: 50.0, axis: Axis::Z, up: true };
        assert_eq!(hemi.bounds(), [[-25.0, -25.0, 0.0], [25.0, 25.0, 25.0]]);
    }
}
