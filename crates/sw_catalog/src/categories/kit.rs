//! Shared building blocks and palettes for the generators.
//!
//! Two rules the helpers keep for every generator:
//! - Support surfaces take their height from [`slab`]'s return value, which is the top of
//!   the collision box exactly as the collision bounds compute it, so things placed there
//!   touch it without penetrating.
//! - Visual meshes are merged per material and judged watertight by exact vertex
//!   position: two boxes of one material must not share an edge (same two end points).
//!   Parts that meet flush use different materials, or overlap, or differ in extent.

use std::f64::consts::FRAC_PI_2;

use sw_geom::{AssetBuilder, Pose, Rng, Shape, cylinder_mesh, quat_from_yaw, quat_mul};

pub(crate) type Rgba = [f32; 4];

pub(crate) const WOOD: &[Rgba] =
    &[[0.72, 0.55, 0.36, 1.0], [0.62, 0.45, 0.28, 1.0], [0.80, 0.66, 0.47, 1.0], [0.52, 0.36, 0.22, 1.0]];
pub(crate) const STEEL: &[Rgba] = &[[0.55, 0.57, 0.6, 1.0], [0.42, 0.44, 0.47, 1.0], [0.66, 0.68, 0.7, 1.0]];
pub(crate) const DARK: &[Rgba] = &[[0.16, 0.17, 0.19, 1.0], [0.22, 0.23, 0.25, 1.0]];
pub(crate) const CARDBOARD: &[Rgba] = &[[0.76, 0.6, 0.42, 1.0], [0.70, 0.54, 0.36, 1.0], [0.81, 0.66, 0.47, 1.0]];
pub(crate) const INDUSTRIAL_PAINT: &[Rgba] = &[
    [0.93, 0.55, 0.12, 1.0], // safety orange
    [0.12, 0.35, 0.65, 1.0], // rack blue
    [0.85, 0.75, 0.15, 1.0], // yellow
    [0.25, 0.5, 0.3, 1.0],   // machine green
    [0.75, 0.77, 0.8, 1.0],  // light grey
];
/// Injection-moulded crates and totes.
pub(crate) const PLASTIC: &[Rgba] = &[
    [0.12, 0.33, 0.62, 1.0], // blue
    [0.52, 0.54, 0.57, 1.0], // grey
    [0.72, 0.14, 0.12, 1.0], // red
    [0.2, 0.48, 0.26, 1.0],  // green
    [0.93, 0.72, 0.1, 1.0],  // yellow
    [0.15, 0.15, 0.17, 1.0], // black
];
/// Pallet-rack uprights.
pub(crate) const RACK_BLUE: &[Rgba] = &[[0.08, 0.27, 0.58, 1.0], [0.1, 0.32, 0.66, 1.0], [0.05, 0.22, 0.48, 1.0]];
/// Pallet-rack beams.
pub(crate) const RACK_ORANGE: &[Rgba] = &[[0.93, 0.42, 0.08, 1.0], [0.95, 0.52, 0.1, 1.0], [0.86, 0.35, 0.06, 1.0]];
/// Powder-coated office and storage furniture.
pub(crate) const OFFICE_PAINT: &[Rgba] = &[
    [0.85, 0.86, 0.86, 1.0], // light grey
    [0.93, 0.93, 0.91, 1.0], // white
    [0.8, 0.77, 0.68, 1.0],  // beige
    [0.42, 0.5, 0.58, 1.0],  // blue grey
    [0.25, 0.27, 0.29, 1.0], // anthracite
];
/// Electrical enclosures (RAL 7035 light grey and its neighbours).
pub(crate) const ENCLOSURE_GREY: &[Rgba] = &[[0.78, 0.8, 0.78, 1.0], [0.84, 0.85, 0.84, 1.0], [0.73, 0.72, 0.66, 1.0]];
/// Machine-tool enclosures.
pub(crate) const MACHINE_PAINT: &[Rgba] = &[
    [0.88, 0.89, 0.87, 1.0], // off-white
    [0.8, 0.82, 0.83, 1.0],  // light grey
    [0.36, 0.5, 0.42, 1.0],  // machine green
    [0.16, 0.36, 0.6, 1.0],  // blue
    [0.28, 0.3, 0.32, 1.0],  // anthracite
];
/// Workbench and conveyor frames.
pub(crate) const FRAME_PAINT: &[Rgba] = &[
    [0.16, 0.36, 0.62, 1.0], // blue
    [0.45, 0.47, 0.5, 1.0],  // grey
    [0.25, 0.45, 0.3, 1.0],  // green
    [0.22, 0.23, 0.25, 1.0], // anthracite
    [0.9, 0.5, 0.1, 1.0],    // orange
];
/// Seat and backrest upholstery or shells.
pub(crate) const UPHOLSTERY: &[Rgba] = &[
    [0.12, 0.12, 0.13, 1.0],
    [0.27, 0.28, 0.3, 1.0],
    [0.15, 0.2, 0.36, 1.0],
    [0.58, 0.12, 0.12, 1.0],
    [0.1, 0.4, 0.42, 1.0],
];
/// Conveyor belts.
pub(crate) const BELT: &[Rgba] =
    &[[0.08, 0.08, 0.09, 1.0], [0.2, 0.21, 0.22, 1.0], [0.18, 0.42, 0.25, 1.0], [0.2, 0.4, 0.68, 1.0]];
/// Mobile robot bodies.
pub(crate) const ROBOT_PAINT: &[Rgba] = &[
    [0.92, 0.92, 0.9, 1.0],
    [0.95, 0.55, 0.12, 1.0],
    [0.45, 0.47, 0.5, 1.0],
    [0.95, 0.78, 0.1, 1.0],
    [0.16, 0.36, 0.62, 1.0],
];
pub(crate) const RUBBER: &[Rgba] = &[[0.07, 0.07, 0.08, 1.0], [0.13, 0.13, 0.14, 1.0]];

pub(crate) const SAFETY_YELLOW: Rgba = [0.98, 0.8, 0.05, 1.0];
pub(crate) const SIGNAL_RED: Rgba = [0.8, 0.08, 0.06, 1.0];
pub(crate) const SIGNAL_GREEN: Rgba = [0.1, 0.65, 0.2, 1.0];
pub(crate) const LABEL_WHITE: Rgba = [0.95, 0.95, 0.93, 1.0];
pub(crate) const INK: Rgba = [0.05, 0.05, 0.06, 1.0];
pub(crate) const GLASS: Rgba = [0.22, 0.3, 0.34, 1.0];

/// One colour of a palette.
pub(crate) fn pick(rng: &mut Rng, palette: &[Rgba]) -> Rgba {
    rng.pick(palette).copied().unwrap_or([0.6, 0.6, 0.6, 1.0])
}

/// A colour scaled towards black (`f < 1`) or white (`f > 1`), for seams and trims.
pub(crate) fn shade(c: Rgba, f: f32) -> Rgba {
    [(c[0] * f).min(1.0), (c[1] * f).min(1.0), (c[2] * f).min(1.0), c[3]]
}

/// A solid box given by its centre and full size.
pub(crate) fn block(b: &mut AssetBuilder, center: [f64; 3], size: [f64; 3], material: usize) {
    b.solid(Shape::Box { half: size.map(|s| s / 2.0) }, Pose::from_pos(center), material);
}

/// A visual-only box (decoration that must not change contacts).
pub(crate) fn decal(b: &mut AssetBuilder, center: [f64; 3], size: [f64; 3], material: usize) {
    b.visual(Shape::Box { half: size.map(|s| s / 2.0) }, Pose::from_pos(center), material);
}

/// The centre and half size of the box between two corners. A corner at 0 stays exactly
/// at 0 (`(0 + m) / 2 - (m - 0) / 2 == 0`).
pub(crate) fn center_half(min: [f64; 3], max: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    (std::array::from_fn(|i| (min[i] + max[i]) * 0.5), std::array::from_fn(|i| (max[i] - min[i]) * 0.5))
}

/// A solid box between corners `min` and `max`. Returns the top of its collision box
/// exactly as the collision bounds compute it: the height for a support surface on it.
pub(crate) fn slab(b: &mut AssetBuilder, min: [f64; 3], max: [f64; 3], material: usize) -> f64 {
    let (center, half) = center_half(min, max);
    b.solid(Shape::Box { half }, Pose::from_pos(center), material);
    center[2] + half[2]
}

/// A visual-only box between corners `min` and `max`.
pub(crate) fn decal_between(b: &mut AssetBuilder, min: [f64; 3], max: [f64; 3], material: usize) {
    let (center, half) = center_half(min, max);
    b.visual(Shape::Box { half }, Pose::from_pos(center), material);
}

/// A collision-only box between corners `min` and `max` (a simplified stand-in for
/// detailed visuals). Returns its top like [`slab`].
pub(crate) fn collider_between(b: &mut AssetBuilder, min: [f64; 3], max: [f64; 3]) -> f64 {
    let (center, half) = center_half(min, max);
    b.collision_on(0, Shape::Box { half }, Pose::from_pos(center));
    center[2] + half[2]
}

/// A solid upright cylinder on the root link from `z0` to `z1`. Returns its top like [`slab`].
pub(crate) fn upright_cylinder(
    b: &mut AssetBuilder,
    xy: [f64; 2],
    radius: f64,
    z0: f64,
    z1: f64,
    material: usize,
) -> f64 {
    let (cz, hh) = ((z0 + z1) * 0.5, (z1 - z0) * 0.5);
    b.solid(Shape::Cylinder { radius, half_height: hh }, Pose::from_pos([xy[0], xy[1], cz]), material);
    cz + hh
}

/// An axis of the asset frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Axis {
    X,
    Y,
    Z,
}

/// A pose at `center` that turns a primitive's local Z axis onto `axis`.
pub(crate) fn along(center: [f64; 3], axis: Axis) -> Pose {
    match axis {
        Axis::X => Pose::from_pos_axis_angle(center, [0.0, 1.0, 0.0], FRAC_PI_2),
        Axis::Y => Pose::from_pos_axis_angle(center, [1.0, 0.0, 0.0], -FRAC_PI_2),
        Axis::Z => Pose::from_pos(center),
    }
}

/// A visual-only cylinder (rollers, wheels, buttons, bolt heads) along `axis`.
pub(crate) fn rod(b: &mut AssetBuilder, center: [f64; 3], radius: f64, length: f64, axis: Axis, material: usize) {
    b.visual(Shape::Cylinder { radius, half_height: length / 2.0 }, along(center, axis), material);
}

/// A bar from `from` to `to` in the plane of a frame (braces, straps): a box of
/// `section = [width, thickness]`, turned about `normal` (X: a bar in the YZ plane;
/// otherwise in the XZ plane). Colliding when `solid`, else visual only.
pub(crate) fn strut(
    b: &mut AssetBuilder,
    from: [f64; 3],
    to: [f64; 3],
    section: [f64; 2],
    normal: Axis,
    material: usize,
    solid: bool,
) {
    let center = std::array::from_fn(|i| (from[i] + to[i]) * 0.5);
    let d: [f64; 3] = std::array::from_fn(|i| to[i] - from[i]);
    let length = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let (shape, pose) = match normal {
        // In the YZ plane: the bar's length is its local Y, turned about X.
        Axis::X => (
            Shape::Box { half: [section[1] / 2.0, length / 2.0, section[0] / 2.0] },
            Pose::from_pos_axis_angle(center, [1.0, 0.0, 0.0], d[2].atan2(d[1])),
        ),
        // In the XZ plane: the bar's length is its local X, turned about Y.
        _ => (
            Shape::Box { half: [length / 2.0, section[1] / 2.0, section[0] / 2.0] },
            Pose::from_pos_axis_angle(center, [0.0, 1.0, 0.0], -d[2].atan2(d[0])),
        ),
    };
    if solid {
        b.solid(shape, pose, material);
    } else {
        b.visual(shape, pose, material);
    }
}

/// A hazard sign on a face that looks along +Y at `y_face`: a black-bordered yellow
/// triangle with an exclamation mark, `side` wide, centred at (`x`, `z`). It stands at
/// most 3.5 mm proud of the face.
pub(crate) fn warning_sign(b: &mut AssetBuilder, x: f64, z: f64, y_face: f64, side: f64, yellow: usize, ink: usize) {
    // A three-sided prism with one corner up, its axis along Y.
    let tip_up = Pose::from_pos_axis_angle([0.0; 3], [1.0, 0.0, 0.0], FRAC_PI_2).quat;
    let up = quat_mul(tip_up, quat_from_yaw(FRAC_PI_2));
    let r = side / 3f64.sqrt();
    let mut prism = |radius: f64, y0: f64, y1: f64, material: usize| {
        let mesh = cylinder_mesh(radius, (y1 - y0) / 2.0, 3);
        let pose = Pose { pos: [x, y_face + (y0 + y1) / 2.0, z], quat: up };
        b.visual_mesh_on(0, &mesh, pose, material);
    };
    prism(r, -0.0005, 0.0015, ink);
    prism(r * 0.78, 0.0005, 0.0025, yellow);
    decal_between(b, [x - 0.06 * r, y_face + 0.002, z - 0.02 * r], [x + 0.06 * r, y_face + 0.0035, z + 0.42 * r], ink);
    decal_between(b, [x - 0.06 * r, y_face + 0.002, z - 0.28 * r], [x + 0.06 * r, y_face + 0.0035, z - 0.14 * r], ink);
}

/// `(a, b)` in increasing order (for boxes mirrored by a sign).
pub(crate) fn ordered(a: f64, b: f64) -> (f64, f64) {
    if a <= b { (a, b) } else { (b, a) }
}

/// `value` brought into `lo..=hi` (`hi` wins when they cross). When a parameter had to
/// move to fit the others, the asset's notes say so.
pub(crate) fn fit(b: &mut AssetBuilder, what: &str, value: f64, lo: f64, hi: f64) -> f64 {
    let v = value.max(lo).min(hi);
    if (v - value).abs() > 1e-9 {
        b.note(format!("{what} {value:.3} does not fit the other dimensions; used {v:.3}"));
    }
    v
}

/// Four square legs under a rectangle of `width × depth`, from the floor to `height`,
/// inset by `inset` from the edges.
pub(crate) fn four_legs(
    b: &mut AssetBuilder,
    width: f64,
    depth: f64,
    height: f64,
    leg: f64,
    inset: f64,
    material: usize,
) {
    let x = width / 2.0 - inset - leg / 2.0;
    let y = depth / 2.0 - inset - leg / 2.0;
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        block(b, [sx * x, sy * y, height / 2.0], [leg, leg, height], material);
    }
}
