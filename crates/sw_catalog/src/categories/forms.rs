//! Building blocks of the everyday categories (homes, offices, shops, clinics, workshops):
//! a compact way to declare a category, round bodies turned from a profile, long things
//! that lie on the table (tools, cutlery), boxy appliances and packages, and the
//! articulated parts that appliances add to `parts`' doors and drawers: doors hinged at
//! the bottom (ovens, dishwashers) and lids hinged at the back (chest freezers, toy chests).
//!
//! Collision stays a few primitives per thing, resting flat: round things collide as
//! `parts::round_collider` (a cylinder and its inscribed square, multi-point contacts), long
//! things as one box per segment, all from z = 0, so that they settle at once and never roll.

use std::f64::consts::FRAC_PI_2;

use sw_geom::{AssetBuilder, JointKind, JointSpec, PlacementKind, Pose, Shape, cylinder_mesh};

use super::kit::{Axis, along, center_half, ordered};
use super::parts::{round_collider, solid_box};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

/// A category in one call: `vary_per_instance` follows `movable` (free things vary per
/// instance, fixtures in a group look alike).
#[allow(clippy::too_many_arguments)]
pub(crate) const fn def(
    name: &'static str,
    display: &'static str,
    synonyms: &'static [&'static str],
    tags: &'static [&'static str],
    description: &'static str,
    is_a: &'static [&'static str],
    kind: Kind,
    placement: PlacementKind,
    movable: bool,
    params: &'static [ParamDef],
    build: fn(&Params, &mut sw_geom::Rng, &mut AssetBuilder) -> f64,
) -> Category {
    Category {
        name,
        display,
        synonyms,
        tags,
        description,
        is_a,
        kind,
        placement,
        params,
        movable,
        vary_per_instance: movable,
        build,
    }
}

/// The three size parameters: `[width, depth, height]` defaults with a shared relative
/// range (`lo`..`hi` times the default) and variation.
pub(crate) const fn size3(w: f64, d: f64, h: f64, lo: f64, hi: f64, vary: f64) -> [ParamDef; 3] {
    [
        ParamDef::new("width", w, w * lo, w * hi, vary, "along X"),
        ParamDef::new("depth", d, d * lo, d * hi, vary, "along Y"),
        ParamDef::new("height", h, h * lo, h * hi, vary, "floor to top"),
    ]
}

/// The overall size of the request.
pub(crate) fn whd(p: &Params) -> (f64, f64, f64) {
    (p.get("width"), p.get("depth"), p.get("height"))
}

/// A solid of revolution around `xy` on `link`, `r` in radius and `h` high from `z0`,
/// from a profile in fractions (`[r / r_max, z / h]`, first and last point on the axis).
#[allow(clippy::too_many_arguments)]
pub(crate) fn lathe(
    b: &mut AssetBuilder,
    link: usize,
    xy: [f64; 2],
    r: f64,
    z0: f64,
    h: f64,
    profile: &[[f64; 2]],
    m: usize,
) {
    let pts: Vec<[f64; 2]> = profile.iter().map(|[a, z]| [a * r, z * h]).collect();
    b.visual_mesh_on(link, &revolve(&pts, ROUND), Pose::from_pos([xy[0], xy[1], z0]), m);
}

/// A round thing standing on its base: the profile turned to look at, and
/// [`round_collider`] of its widest radius from the floor to its top. Returns the top.
pub(crate) fn round_body(b: &mut AssetBuilder, r: f64, h: f64, profile: &[[f64; 2]], m: usize) -> f64 {
    lathe(b, 0, [0.0, 0.0], r, 0.0, h, profile, m);
    round_collider(b, 0, [0.0, 0.0], r, 0.0, h)
}

/// A fruit-like round body: a flattened base, a full belly and a dimpled top, in
/// fractions for [`lathe`]; `belly` is the height of the widest point (0..1), `base` the
/// radius of the flat it stands on.
pub(crate) fn bulb(base: f64, belly: f64, top: f64) -> Vec<[f64; 2]> {
    let mut p = vec![[0.0, 0.0], [base, 0.0]];
    for k in 1..=4 {
        let a = f64::from(k) / 4.0 * FRAC_PI_2;
        p.push([base + (1.0 - base) * a.sin(), belly * (1.0 - a.cos())]);
    }
    for k in 1..=4 {
        let a = f64::from(k) / 4.0 * FRAC_PI_2;
        p.push([top + (1.0 - top) * a.cos(), belly + (1.0 - belly) * a.sin()]);
    }
    p.push([0.0, 0.94]);
    p.dedup();
    p
}

/// One piece of a long thing lying along X: from `x0` to `x1`, `width` across (Y),
/// `height` tall from the table, round (a cylinder along X) or flat (a box).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seg {
    pub x0: f64,
    pub x1: f64,
    pub width: f64,
    pub height: f64,
    pub round: bool,
    pub material: usize,
}

impl Seg {
    pub(crate) fn flat(x0: f64, x1: f64, width: f64, height: f64, material: usize) -> Self {
        Self { x0, x1, width, height, round: false, material }
    }
    pub(crate) fn round(x0: f64, x1: f64, diameter: f64, material: usize) -> Self {
        Self { x0, x1, width: diameter, height: diameter, round: true, material }
    }
}

/// A long thing lying on the table (a hammer, a spoon, a remote): each segment visible as
/// a box or a cylinder along X and colliding as its box from the table up, so that it
/// lies still. Segments of one material must not share both end faces' edges exactly:
/// neighbours overlap by a millimetre.
pub(crate) fn long_item(b: &mut AssetBuilder, segs: &[Seg]) {
    for s in segs {
        let (x0, x1) = ordered(s.x0, s.x1);
        let len = x1 - x0;
        let cx = (x0 + x1) / 2.0;
        if s.round {
            let r = s.width.min(s.height) / 2.0;
            b.visual_mesh_on(0, &cylinder_mesh(r, len / 2.0, ROUND), along([cx, 0.0, r], Axis::X), s.material);
        } else {
            let (c, half) = center_half([x0, -s.width / 2.0, 0.0], [x1, s.width / 2.0, s.height]);
            b.visual(Shape::Box { half }, Pose::from_pos(c), s.material);
        }
        let (c, half) = center_half([x0, -s.width / 2.0, 0.0], [x1, s.width / 2.0, s.height]);
        b.collision_on(0, Shape::Box { half }, Pose::from_pos(c));
    }
}

/// A door hinged along its bottom edge that drops open towards +Y up to 90° (an oven,
/// a dishwasher), over `x0..x1` × `z0..z1`, its back face at `y_back`. The hinge is on
/// the door's front face, so its weight holds it shut against the joint's stop. A bar
/// handle (visual) runs across near the top. Returns the link.
#[allow(clippy::too_many_arguments)]
pub(crate) fn drop_door(
    b: &mut AssetBuilder,
    name: &str,
    [x0, x1]: [f64; 2],
    [z0, z1]: [f64; 2],
    y_back: f64,
    thickness: f64,
    [panel, handle]: [usize; 2],
    mass: f64,
) -> usize {
    // Turning about -X lifts nothing: the top edge swings out towards +Y.
    let joint = JointSpec {
        kind: JointKind::Hinge,
        axis: [-1.0, 0.0, 0.0],
        anchor: [0.0; 3],
        range: [0.0, 1.57],
        damping: 2.0,
    };
    let link = b.link(name, 0, Pose::from_pos([0.0, y_back + thickness, z0]), joint, mass);
    solid_box(b, link, [x0, -thickness, 0.0], [x1, 0.0, z1 - z0], panel);
    let hz = (z1 - z0) - ((z1 - z0) * 0.12).clamp(0.012, 0.05);
    let hw = ((x1 - x0) * 0.38).min(0.25);
    let xc = (x0 + x1) / 2.0;
    super::parts::decal_on(b, link, [xc - hw, 0.0, hz - 0.006], [xc + hw, 0.004, hz + 0.006], handle);
    link
}

/// A lid hinged along its back edge (-Y) that lifts open up to 100° (a chest freezer, a
/// toy chest, a washing machine's top): over `x0..x1` × `y0..y1`, from `z0` up by
/// `thickness`. Its weight holds it shut against the joint's stop. Returns the link.
#[allow(clippy::too_many_arguments)]
pub(crate) fn back_lid(
    b: &mut AssetBuilder,
    name: &str,
    [x0, x1]: [f64; 2],
    [y0, y1]: [f64; 2],
    z0: f64,
    thickness: f64,
    material: usize,
    mass: f64,
) -> usize {
    // Turning about +X raises the front edge (+Y).
    let joint =
        JointSpec { kind: JointKind::Hinge, axis: [1.0, 0.0, 0.0], anchor: [0.0; 3], range: [0.0, 1.75], damping: 2.0 };
    let link = b.link(name, 0, Pose::from_pos([0.0, y0, z0]), joint, mass);
    solid_box(b, link, [x0, 0.0, 0.0], [x1, y1 - y0, thickness], material);
    link
}

/// Control knobs along X on a face looking +Y at `y`, at height `z` (visual).
pub(crate) fn knobs(b: &mut AssetBuilder, xs: &[f64], y: f64, z: f64, r: f64, m: usize) {
    for &x in xs {
        b.visual(Shape::Cylinder { radius: r, half_height: 0.006 }, along([x, y + 0.006, z], Axis::Y), m);
    }
}

/// Points spread evenly across `a..b`, `n` of them, centred in their cells.
pub(crate) fn spread(a: f64, b: f64, n: usize) -> Vec<f64> {
    let n = n.max(1);
    (0..n).map(|k| a + (b - a) * (k as f64 + 0.5) / n as f64).collect()
}

/// A box with rounded vertical edges (an appliance body, a package): the rounded prism to
/// look at, its bounding box to collide, from `z0` to `z1`, centred on `xy`. Returns its top.
#[allow(clippy::too_many_arguments)]
pub(crate) fn rounded_box(
    b: &mut AssetBuilder,
    xy: [f64; 2],
    w: f64,
    d: f64,
    z0: f64,
    z1: f64,
    r: f64,
    m: usize,
) -> f64 {
    let outline = super::shapes::rounded_rect(w / 2.0, d / 2.0, r, 3);
    b.visual_mesh_on(0, &super::shapes::prism(&outline, z0, z1), Pose::from_pos([xy[0], xy[1], 0.0]), m);
    let (c, half) = center_half([xy[0] - w / 2.0, xy[1] - d / 2.0, z0], [xy[0] + w / 2.0, xy[1] + d / 2.0, z1]);
    b.collision_on(0, Shape::Box { half }, Pose::from_pos(c));
    c[2] + half[2]
}

/// A mesh stretched along Y by `f` (an oval pot from a round one).
pub(crate) fn stretch_y(mut m: sw_geom::Mesh, f: f64) -> sw_geom::Mesh {
    for v in &mut m.vertices {
        v[1] *= f as f32;
    }
    m
}

/// A visual ellipsoid with semi-axes `radii` centred at `center` (soft toys' limbs).
pub(crate) fn ellipsoid(b: &mut AssetBuilder, center: [f64; 3], radii: [f64; 3], m: usize) {
    let mut mesh = sw_geom::sphere_mesh(1.0, 10, 16);
    for v in &mut mesh.vertices {
        for k in 0..3 {
            v[k] *= radii[k] as f32;
        }
    }
    b.visual_mesh_on(0, &mesh, Pose::from_pos(center), m);
}
