//! Free-form shapes with no object behind them ("a thick disc", "a long hollow pipe", "an
//! L-shaped block", "a plus-shaped block"): a parametric model each, sized by the words
//! ("large", "tall", "thick" …) around sensible proportions, in millimetres, on Z = 0.

use super::shapes::{Parts, bx, cone_z, cyl_z, hemi, prism_xy, prism_xz, ring_z, sphere};
use super::{Build, Spec};
use crate::synth::model::Model;
use crate::synth::profile::Profile;
use crate::synth::solid::{Axis, Shape};

/// The basic shapes: names, the features their words may name, and the builder.
pub const BASIC: &[Build] = &[
    Build { names: &["box", "cuboid", "crate shape", "block"], features: &[], build: block },
    Build { names: &["ball", "sphere", "orb", "globe"], features: &[], build: ball },
    Build { names: &["disc", "disk", "puck"], features: &[], build: disc },
    Build { names: &["cylinder"], features: &[], build: cylinder },
    Build { names: &["cone"], features: &[], build: cone },
    Build { names: &["pipe", "tube", "hollow pipe", "hollow tube"], features: &[], build: pipe },
    Build { names: &["wedge", "doorstop", "door wedge"], features: &[], build: wedge },
    Build { names: &["dome", "hemisphere"], features: &[], build: dome },
    Build { names: &["ring", "annulus", "donut", "doughnut"], features: &[], build: ring },
    Build { names: &["board", "plank", "slab", "panel"], features: &[], build: board },
    Build { names: &["pillar", "column"], features: &[], build: pillar },
    Build { names: &["l-shaped block", "l-shape", "l shape", "l-block"], features: &[], build: l_block },
    Build {
        names: &["plus-shaped block", "plus shape", "cross-shaped block", "plus sign"],
        features: &[],
        build: plus_block,
    },
];

fn block(s: &Spec) -> Model {
    let (w, d, h) = (200.0 * s.size * s.wide * s.long, 150.0 * s.size * s.wide, 120.0 * s.size * s.tall * s.thick);
    let mut p = Parts::default();
    p.add("box", bx([-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h]));
    p.finish()
}

fn ball(s: &Spec) -> Model {
    let d = 100.0 * s.size * s.wide;
    let mut p = Parts::default();
    p.add("ball", sphere(d, [0.0, 0.0, d / 2.0]));
    p.finish()
}

fn disc(s: &Spec) -> Model {
    let (d, t) = (120.0 * s.size * s.wide, 12.0 * s.size * s.thick * s.tall);
    let mut p = Parts::default();
    p.add("disc", cyl_z(d, 0.0, t, 0.0, 0.0));
    p.finish()
}

fn cylinder(s: &Spec) -> Model {
    let (d, h) = (80.0 * s.size * s.wide * s.thick, 120.0 * s.size * s.tall * s.long);
    let mut p = Parts::default();
    p.add("cylinder", cyl_z(d, 0.0, h, 0.0, 0.0));
    p.finish()
}

fn cone(s: &Spec) -> Model {
    let (d, h) = (100.0 * s.size * s.wide, 120.0 * s.size * s.tall);
    let mut p = Parts::default();
    p.add("cone", cone_z(d, 0.0, 0.0, h, 0.0, 0.0));
    p.finish()
}

/// A pipe lying along X.
fn pipe(s: &Spec) -> Model {
    let od = 80.0 * s.size * s.thick;
    let id = od * 0.8;
    let len = 300.0 * s.size * s.long;
    let mut p = Parts::default();
    p.add(
        "pipe",
        Shape::Prism {
            profile: Profile::Annulus { od, id },
            axis: Axis::X,
            at: [0.0, od / 2.0],
            rot: 0.0,
            from: -len / 2.0,
            to: len / 2.0,
        },
    );
    p.finish()
}

/// A door wedge: a right triangle in XZ (thick end at X=0), across Y.
fn wedge(s: &Spec) -> Model {
    let (l, w, h) = (150.0 * s.size * s.long, 80.0 * s.size * s.wide, 45.0 * s.size * s.tall * s.thick);
    let mut p = Parts::default();
    p.add("wedge", prism_xz(&[[-l / 2.0, 0.0], [l / 2.0, 0.0], [-l / 2.0, h]], -w / 2.0, w / 2.0));
    p.finish()
}

fn dome(s: &Spec) -> Model {
    let d = 200.0 * s.size * s.wide;
    let mut p = Parts::default();
    p.add("dome", hemi(d, [0.0, 0.0, 0.0], true));
    p.finish()
}

fn ring(s: &Spec) -> Model {
    let od = 120.0 * s.size * s.wide;
    let wall = (20.0 * s.size * s.thick).min(od * 0.4);
    let h = 25.0 * s.size * s.thick * s.tall;
    let mut p = Parts::default();
    p.add("ring", ring_z(od, od - 2.0 * wall, 0.0, h));
    p.finish()
}

fn board(s: &Spec) -> Model {
    let (l, w, t) = (600.0 * s.size * s.long, 250.0 * s.size * s.wide, 20.0 * s.size * s.thick * s.tall);
    let mut p = Parts::default();
    p.add("board", bx([-l / 2.0, -w / 2.0, 0.0], [l / 2.0, w / 2.0, t]));
    p.finish()
}

/// A column on a square plinth under a square capital.
fn pillar(s: &Spec) -> Model {
    let h = 1800.0 * s.size * s.tall;
    let d = 250.0 * s.size * s.thick * s.wide;
    let (pw, ph) = (d * 1.35, h * 0.06);
    let mut p = Parts::default();
    p.add("plinth", bx([-pw / 2.0, -pw / 2.0, 0.0], [pw / 2.0, pw / 2.0, ph]));
    p.add("shaft", cyl_z(d, ph, h - ph, 0.0, 0.0));
    p.add("capital", bx([-pw / 2.0, -pw / 2.0, h - ph], [pw / 2.0, pw / 2.0, h]));
    p.finish()
}

/// An L in XZ (a leg along X and one along Z), across Y.
fn l_block(s: &Spec) -> Model {
    let (a, b) = (200.0 * s.size * s.long, 150.0 * s.size * s.tall);
    let t = 60.0 * s.size * s.thick;
    let d = 100.0 * s.size * s.wide;
    let mut p = Parts::default();
    p.add("l-block", prism_xz(&[[0.0, 0.0], [a, 0.0], [a, t], [t, t], [t, b], [0.0, b]], -d / 2.0, d / 2.0));
    p.finish()
}

/// A plus sign in XY, extruded up.
fn plus_block(s: &Spec) -> Model {
    let span = 180.0 * s.size * s.wide * s.long;
    let w = 60.0 * s.size * s.thick;
    let h = 60.0 * s.size * s.tall * s.thick;
    let (a, b) = (span / 2.0, w / 2.0);
    let pts =
        [[b, -a], [b, -b], [a, -b], [a, b], [b, b], [b, a], [-b, a], [-b, b], [-a, b], [-a, -b], [-b, -b], [-b, -a]];
    let mut p = Parts::default();
    p.add("plus-block", prism_xy(&pts, 0.0, h));
    p.finish()
}
