//! The pieces free-form objects are built from (cylinders along an axis, boxes, rings,
//! revolved profiles, rods bent along arcs, spheres and cones), in millimetres, as bodies
//! of the feature language's [`Model`](crate::synth::model::Model).

use crate::synth::model::Model;
use crate::synth::profile::Profile;
use crate::synth::solid::{Axis, Body, EdgeKind, EdgeOp, Edges, Shape, Shell};

/// A part under construction.
#[derive(Debug, Default)]
pub struct Parts {
    pub model: Model,
}

impl Parts {
    pub fn add(&mut self, label: &str, shape: Shape) -> &mut Body {
        self.model.adds.push(Body::new(label, shape));
        let n = self.model.adds.len() - 1;
        &mut self.model.adds[n]
    }

    pub fn cut(&mut self, label: &str, shape: Shape) {
        self.model.cuts.push(Body::new(label, shape));
    }

    pub fn finish(self) -> Model {
        self.model
    }
}

/// A cylinder along Z from `z0` to `z1`, its axis at (x, y).
pub fn cyl_z(d: f64, z0: f64, z1: f64, x: f64, y: f64) -> Shape {
    Shape::Prism { profile: Profile::Circle { d }, axis: Axis::Z, at: [x, y], rot: 0.0, from: z0, to: z1 }
}

/// A cylinder along X from `x0` to `x1`, its axis at (y, z).
pub fn cyl_x(d: f64, x0: f64, x1: f64, y: f64, z: f64) -> Shape {
    Shape::Prism { profile: Profile::Circle { d }, axis: Axis::X, at: [y, z], rot: 0.0, from: x0, to: x1 }
}

/// A cylinder along Y from `y0` to `y1`, its axis at (x, z).
pub fn cyl_y(d: f64, y0: f64, y1: f64, x: f64, z: f64) -> Shape {
    // The Y axis's plane is (Z, X).
    Shape::Prism { profile: Profile::Circle { d }, axis: Axis::Y, at: [z, x], rot: 0.0, from: y0, to: y1 }
}

/// A ring along Z.
pub fn ring_z(od: f64, id: f64, z0: f64, z1: f64) -> Shape {
    Shape::Prism { profile: Profile::Annulus { od, id }, axis: Axis::Z, at: [0.0, 0.0], rot: 0.0, from: z0, to: z1 }
}

/// A box between two corners.
pub fn bx(min: [f64; 3], max: [f64; 3]) -> Shape {
    Shape::Prism {
        profile: Profile::Rect { w: max[0] - min[0], h: max[1] - min[1] },
        axis: Axis::Z,
        at: [(min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0],
        rot: 0.0,
        from: min[2],
        to: max[2],
    }
}

/// A box of size `s` centred on `c`, turned `yaw` degrees about Z.
pub fn bx_yaw(c: [f64; 3], s: [f64; 3], yaw: f64) -> Shape {
    Shape::Prism {
        profile: Profile::Rect { w: s[0], h: s[1] },
        axis: Axis::Z,
        at: [c[0], c[1]],
        rot: yaw,
        from: c[2] - s[2] / 2.0,
        to: c[2] + s[2] / 2.0,
    }
}

/// A polygon in the XZ plane (x, z) extruded along Y from `y0` to `y1`.
pub fn prism_xz(pts: &[[f64; 2]], y0: f64, y1: f64) -> Shape {
    // The Y axis's plane is (Z, X): each point (x, z) is (u, v) = (z, x).
    let uv: Vec<[f64; 2]> = pts.iter().map(|p| [p[1], p[0]]).collect();
    Shape::Prism { profile: Profile::Poly(uv), axis: Axis::Y, at: [0.0, 0.0], rot: 0.0, from: y0, to: y1 }
}

/// A polygon in the XY plane extruded along Z.
pub fn prism_xy(pts: &[[f64; 2]], z0: f64, z1: f64) -> Shape {
    Shape::Prism { profile: Profile::Poly(pts.to_vec()), axis: Axis::Z, at: [0.0, 0.0], rot: 0.0, from: z0, to: z1 }
}

/// A profile of (radius, height) points revolved about the Z axis through (x, y).
pub fn revolve(pts: &[[f64; 2]], x: f64, y: f64) -> Shape {
    Shape::Revolve { at: [x, y], profile: Profile::Poly(pts.to_vec()) }
}

/// A cup (open at the top) revolved about Z: outer radius `rb` at the bottom and `rt` at
/// the top, height `h`, wall `t`, bottom `tb`, standing on `z0`.
pub fn cup(rb: f64, rt: f64, h: f64, t: f64, tb: f64, z0: f64) -> Shape {
    revolve(&[[0.0, z0], [rb, z0], [rt, z0 + h], [rt - t, z0 + h], [rb - t, z0 + tb], [0.0, z0 + tb]], 0.0, 0.0)
}

pub fn sphere(d: f64, c: [f64; 3]) -> Shape {
    Shape::Sphere { c, d }
}

pub fn hemi(d: f64, c: [f64; 3], up: bool) -> Shape {
    Shape::Hemisphere { c, d, axis: Axis::Z, up }
}

/// A cone or frustum along Z.
pub fn cone_z(d0: f64, d1: f64, z0: f64, z1: f64, x: f64, y: f64) -> Shape {
    Shape::Cone { axis: Axis::Z, at: [x, y], from: z0, to: z1, d_from: d0, d_to: d1 }
}

/// A cone or frustum along X (`at` is (y, z)).
pub fn cone_x(d0: f64, d1: f64, x0: f64, x1: f64, y: f64, z: f64) -> Shape {
    Shape::Cone { axis: Axis::X, at: [y, z], from: x0, to: x1, d_from: d0, d_to: d1 }
}

/// A round rod of diameter `d` bent along an arc of `radius` about `centre` in the plane
/// of (`u`, `v`), from `a0` to `a1` degrees.
pub fn rod_arc(d: f64, centre: [f64; 3], radius: f64, u: Axis, v: Axis, a0: f64, a1: f64) -> Shape {
    Shape::Bend { od: d, id: 0.0, centre, radius, u, v, a0, a1 }
}

/// Rounds the vertical edges of the last body added.
pub fn round_vertical(b: &mut Body, r: f64) {
    b.edges.push(EdgeOp { edges: Edges::Parallel(Axis::Z), kind: EdgeKind::Fillet, size: r });
}

/// Hollows the last body added, open at the top, to a wall `t`.
pub fn open_top(b: &mut Body, t: f64) {
    b.shell = Some(Shell { axis: Axis::Z, max: true, t });
}
