//! Larger building blocks shared by the generators: round solids that stand flat,
//! open round vessels, open-fronted carcasses, and the articulated parts a robot uses —
//! hinged doors and sliding drawers.
//!
//! Collision rules the helpers keep:
//! - Round things collide as a cylinder plus the square inscribed in it: box-on-box
//!   contacts are multi-point in MuJoCo, so a can stands still on a table and a box
//!   stays on a drum lid, and the square carries the support surface.
//! - Open vessels collide as a ring of boxes and a floor, never as one hull, so that
//!   things can go inside. They stand on the floor alone: the walls start [`STAND_GAP`]
//!   above the vessel's bottom. Each box touching the support is another four contact
//!   points for the solver; a mug standing on all sixteen made 60 – 70 contacts with
//!   its table, and a scene's settle time follows its contacts. For the same reason a
//!   ring with no floor (a tyre lying flat) stands on four of its boxes.
//! - Moving parts keep 2–3 mm from everything else at joint value zero: MuJoCo checks
//!   contacts between a door and its (static) carcass, and between sibling drawers.

use std::f64::consts::{PI, SQRT_2};

use sw_geom::{AssetBuilder, Collision, JointKind, JointSpec, Pose, Shape, cylinder_mesh};

use super::kit::{center_half, ordered};
use super::shapes::ROUND;

/// How far a drawer's or a door's handle bar stands off its face, m: a collider a
/// gripper's pads pinch (within the asset's stated depth, as the envelope allows).
pub(crate) const HANDLE_PROUD: f64 = 0.008;

/// Clearance around moving parts at joint value zero, m.
pub(crate) const MOVING_GAP: f64 = 0.003;

/// How far the walls of an open vessel or tote stop above its bottom, m, so that only
/// its floor touches what it stands on (at most half the floor's thickness, so that the
/// walls still overlap the floor). Several times a resting contact's penetration (0.1 –
/// 0.2 mm measured under a bin, a mug and a stack of tyres), too little to see or to tip on.
pub(crate) const STAND_GAP: f64 = 0.001;

/// Collision of a round solid on `link`: a cylinder of radius `r` from `z0` to `z1`
/// around `xy`, and the square inscribed in it. Returns the top, exactly as the
/// collision bounds compute it (the height for a support surface).
pub(crate) fn round_collider(b: &mut AssetBuilder, link: usize, xy: [f64; 2], r: f64, z0: f64, z1: f64) -> f64 {
    let (cz, hh) = ((z0 + z1) * 0.5, (z1 - z0) * 0.5);
    b.collision_on(link, Shape::Cylinder { radius: r, half_height: hh }, Pose::from_pos([xy[0], xy[1], cz]));
    let s = r / SQRT_2;
    b.collision_on(link, Shape::Box { half: [s, s, hh] }, Pose::from_pos([xy[0], xy[1], cz]));
    cz + hh
}

/// A round solid: a smooth cylinder to look at and [`round_collider`] to collide.
pub(crate) fn round_solid(
    b: &mut AssetBuilder,
    link: usize,
    xy: [f64; 2],
    r: f64,
    z0: f64,
    z1: f64,
    material: usize,
) -> f64 {
    let (cz, hh) = ((z0 + z1) * 0.5, (z1 - z0) * 0.5);
    b.visual_mesh_on(link, &cylinder_mesh(r, hh, ROUND), Pose::from_pos([xy[0], xy[1], cz]), material);
    round_collider(b, link, xy, r, z0, z1)
}

/// The inside of an open vessel, as [`vessel_collider`] returns it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Inside {
    /// Top of the vessel's floor.
    pub floor: f64,
    /// Half side of the square on the floor that no wall reaches into.
    pub half: f64,
}

/// Collision of an open round vessel around `xy` (a mug, a bowl, a bucket): a floor
/// `floor_t` thick from `z0`, and a [`ring_collider`] wall up to `z1` that starts
/// [`STAND_GAP`] above `z0`, so that the vessel stands on its floor. Returns its inside
/// (around `xy`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn vessel_collider(
    b: &mut AssetBuilder,
    xy: [f64; 2],
    r_floor: f64,
    r_out: f64,
    wall: f64,
    floor_t: f64,
    z0: f64,
    z1: f64,
    n: u32,
) -> Inside {
    let (r_in, limit) = ring_collider(b, xy, r_out, wall, z0 + STAND_GAP.min(floor_t * 0.5), z1, n, RingBase::Flat);
    let r_floor = r_floor.min(r_in);
    let floor = round_collider(b, 0, xy, r_floor, z0, z0 + floor_t);
    Inside { floor, half: (limit - 1e-6).min(r_floor / SQRT_2 - 1e-6).max(0.0) }
}

/// An open rectangular tote or tray, `w` × `d` × `h` from `z = 0`, walls and floor `t`
/// thick, in `material`: a floor and four walls, each its own collision box so that
/// things can be put inside. The end walls reach halfway into the side walls and the
/// floor halfway under all four, so that no two boxes share an edge. The walls are seen
/// down to the bottom but collide from [`STAND_GAP`] up, so that the tote stands on its
/// floor alone (4 contacts with a bench, not 20). Returns the floor's top.
pub(crate) fn open_box(b: &mut AssetBuilder, w: f64, d: f64, h: f64, t: f64, material: usize) -> f64 {
    let (hw, hd) = (w / 2.0, d / 2.0);
    let lift = STAND_GAP.min(t * 0.5);
    let wall = |b: &mut AssetBuilder, min: [f64; 3], max: [f64; 3]| {
        let (center, half) = center_half(min, max);
        b.visual(Shape::Box { half }, Pose::from_pos(center), material);
        let (center, half) = center_half([min[0], min[1], lift], max);
        b.collision_on(0, Shape::Box { half }, Pose::from_pos(center));
    };
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * (hd - t), sy * hd);
        wall(b, [-hw, y0, 0.0], [hw, y1, h]);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * (hw - t), sx * hw);
        wall(b, [x0, -(hd - t / 2.0), 0.0], [x1, hd - t / 2.0, h]);
    }
    solid_box(b, 0, [-(hw - t / 2.0), -(hd - t / 2.0), 0.0], [hw - t / 2.0, hd - t / 2.0, t], material)
}

/// How the bottom of a [`ring_collider`] meets what is under it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum RingBase {
    /// Every box reaches down to `z0` (a wall standing on something of the same body).
    Flat,
    /// Four boxes, a quarter turn apart, reach `z0`; the rest stop [`STAND_GAP`] above it,
    /// so that a ring lying on a support touches it with four feet, not all `n` boxes.
    Feet,
}

/// A round wall of `n` boxes (a multiple of 4, at least 8) around `xy`, inscribed in
/// radius `r_out` (its bounds reach `r_out` exactly on the axes), about `wall` thick,
/// from `z0` to `z1`. Returns the inner radius and the half side of the square around
/// `xy` that no box reaches into.
#[allow(clippy::too_many_arguments)]
pub(crate) fn ring_collider(
    b: &mut AssetBuilder,
    xy: [f64; 2],
    r_out: f64,
    wall: f64,
    z0: f64,
    z1: f64,
    n: u32,
    base: RingBase,
) -> (f64, f64) {
    let n = (n.max(8) / 4) * 4;
    let half_angle = PI / f64::from(n);
    let outer = r_out * half_angle.cos();
    let r_in = (r_out - wall).min(outer - 0.0015).max(r_out * 0.3);
    let (rc, hr) = ((r_in + outer) * 0.5, (outer - r_in) * 0.5);
    let ht = r_out * half_angle.sin();
    let lift = STAND_GAP.min((z1 - z0) * 0.25);
    let mut limit = f64::INFINITY;
    for k in 0..n {
        let foot = base == RingBase::Flat || k % (n / 4) == 0;
        let bottom = if foot { z0 } else { z0 + lift };
        let (cz, hz) = ((bottom + z1) * 0.5, (z1 - bottom) * 0.5);
        let a = (f64::from(k) + 0.5) * 2.0 * half_angle;
        let shape = Shape::Box { half: [hr, ht, hz] };
        let local = Collision { shape, pose: Pose::from_pos_yaw([rc * a.cos(), rc * a.sin(), cz], a) };
        let bb = local.aabb();
        limit = limit.min(bb.min[0].max(-bb.max[0]).max(bb.min[1]).max(-bb.max[1]));
        b.collision_on(0, shape, Pose::from_pos_yaw([xy[0] + rc * a.cos(), xy[1] + rc * a.sin(), cz], a));
    }
    (r_in, limit)
}

/// An open-fronted box: two sides, a top, a bottom and a back, solid, between `x0..x1`,
/// `y_back..y_front` and `z0..z1`, panels `t` thick. Panels overlap by half their
/// thickness so that no two share an edge (one material stays watertight). Returns the
/// top of the carcass.
#[allow(clippy::too_many_arguments)]
pub(crate) fn carcass(
    b: &mut AssetBuilder,
    x0: f64,
    x1: f64,
    y_back: f64,
    y_front: f64,
    z0: f64,
    z1: f64,
    t: f64,
    material: usize,
) -> f64 {
    let h = t / 2.0;
    for (xa, xb) in [(x0, x0 + t), (x1 - t, x1)] {
        solid_box(b, 0, [xa, y_back, z0], [xb, y_front, z1], material);
    }
    let top = solid_box(b, 0, [x0 + h, y_back, z1 - t], [x1 - h, y_front, z1], material);
    solid_box(b, 0, [x0 + h, y_back, z0], [x1 - h, y_front, z0 + t], material);
    solid_box(b, 0, [x0 + h, y_back, z0 + h], [x1 - h, y_back + t, z1 - h], material);
    top
}

/// A solid box between two corners on `link`. Returns its top like `kit::slab`.
pub(crate) fn solid_box(b: &mut AssetBuilder, link: usize, min: [f64; 3], max: [f64; 3], material: usize) -> f64 {
    let (center, half) = center_half(min, max);
    b.solid_on(link, Shape::Box { half }, Pose::from_pos(center), material);
    center[2] + half[2]
}

/// A visual-only box between two corners on `link`.
pub(crate) fn decal_on(b: &mut AssetBuilder, link: usize, min: [f64; 3], max: [f64; 3], material: usize) {
    let (center, half) = center_half(min, max);
    b.visual_on(link, Shape::Box { half }, Pose::from_pos(center), material);
}

/// Which vertical edge a door turns on. Assets face +Y, so as you stand in front of one
/// the -X edge is on your right.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Hinge {
    /// The -X edge (your right as you face the door).
    MinX,
    /// The +X edge (your left).
    MaxX,
}

/// A door leaf over the opening `x0..x1` × `z0..z1`, its back face at `y_back`,
/// `thickness` thick, hinged on a vertical edge and opening outwards (+Y) up to 100°.
/// A bar handle (visual, `handle`) sits near the free edge at `handle_z`. Returns the
/// link index.
#[allow(clippy::too_many_arguments)]
pub(crate) fn hinged_door(
    b: &mut AssetBuilder,
    name: &str,
    hinge: Hinge,
    [x0, x1]: [f64; 2],
    [z0, z1]: [f64; 2],
    y_back: f64,
    thickness: f64,
    panel: usize,
    handle: usize,
    handle_z: f64,
    mass: f64,
) -> usize {
    let (x_hinge, s, axis) = match hinge {
        Hinge::MinX => (x0, 1.0, [0.0, 0.0, 1.0]),
        Hinge::MaxX => (x1, -1.0, [0.0, 0.0, -1.0]),
    };
    let width = x1 - x0;
    let joint = JointSpec { kind: JointKind::Hinge, axis, anchor: [0.0; 3], range: [0.0, 1.75], damping: 2.0 };
    let pose = Pose::from_pos([x_hinge, y_back + thickness / 2.0, z0]);
    let link = b.link(name, 0, pose, joint, mass);
    let (xa, xb) = ordered(0.0, s * width);
    solid_box(b, link, [xa, -thickness / 2.0, 0.0], [xb, thickness / 2.0, z1 - z0], panel);
    // The handle: a vertical bar [`HANDLE_PROUD`] proud, 4 cm in from the free edge, a
    // collider that a gripper can pinch across its width and pull.
    let hx = s * (width - 0.04);
    let hl = (0.16f64).min((z1 - z0) * 0.3);
    let hz = (handle_z - z0).min((z1 - z0) - hl / 2.0 - 0.01).max(hl / 2.0 + 0.01);
    solid_box(
        b,
        link,
        [hx - 0.008, thickness / 2.0, hz - hl / 2.0],
        [hx + 0.008, thickness / 2.0 + HANDLE_PROUD, hz + hl / 2.0],
        handle,
    );
    link
}

/// A drawer in the cavity `cavity_x` × `cavity_z` of a carcass whose front opening is
/// at `y_front - front_t`: a front panel over `front_x` × `front_z` (in front of the
/// carcass, `front_t` thick) and a tray `depth` deep behind it with [`MOVING_GAP`] all
/// round. It slides out along +Y by up to `travel`. A bar handle (visual) runs across
/// the front's upper part. Returns the link index.
#[allow(clippy::too_many_arguments)]
pub(crate) fn drawer(
    b: &mut AssetBuilder,
    name: &str,
    front_x: [f64; 2],
    front_z: [f64; 2],
    cavity_x: [f64; 2],
    cavity_z: [f64; 2],
    y_front: f64,
    front_t: f64,
    depth: f64,
    travel: f64,
    [front, tray, handle]: [usize; 3],
    mass: f64,
) -> usize {
    let g = MOVING_GAP;
    let joint = JointSpec {
        kind: JointKind::Slide,
        axis: [0.0, 1.0, 0.0],
        anchor: [0.0; 3],
        range: [0.0, travel.max(0.05)],
        damping: 20.0,
    };
    let pose = Pose::from_pos([0.0, y_front - front_t, 0.0]);
    let link = b.link(name, 0, pose, joint, mass);
    solid_box(b, link, [front_x[0], 0.0, front_z[0]], [front_x[1], front_t, front_z[1]], front);
    // The tray: a bottom, two sides and a back, clear of the cavity by the gap.
    let (tx0, tx1) = (cavity_x[0] + g, cavity_x[1] - g);
    let (tz0, tz1) = (cavity_z[0] + g, cavity_z[1] - g);
    let ty0 = -(depth - g);
    let t = (0.012f64).min((tx1 - tx0) * 0.1).min((tz1 - tz0) * 0.3);
    let ty1 = -g;
    solid_box(b, link, [tx0 + t / 2.0, ty0, tz0], [tx1 - t / 2.0, ty1, tz0 + t], tray);
    for (xa, xb) in [(tx0, tx0 + t), (tx1 - t, tx1)] {
        solid_box(b, link, [xa, ty0 + t / 2.0, tz0 + t / 2.0], [xb, ty1, tz1], tray);
    }
    solid_box(b, link, [tx0 + t / 2.0, ty0 + t / 4.0, tz0 + t / 3.0], [tx1 - t / 2.0, ty0 + t, tz1 - t / 3.0], tray);
    // A bar handle across the upper part of the front, [`HANDLE_PROUD`] proud: a collider
    // that a gripper can pinch across its height and pull.
    let (fx0, fx1) = (front_x[0], front_x[1]);
    let hw = ((fx1 - fx0) * 0.35).min(0.2);
    let hz = front_z[1] - ((front_z[1] - front_z[0]) * 0.3).min(0.05);
    let xc = (fx0 + fx1) / 2.0;
    solid_box(b, link, [xc - hw, front_t, hz - 0.006], [xc + hw, front_t + HANDLE_PROUD, hz + 0.006], handle);
    link
}
