//! Things a robot arm is mounted on: fixed pedestals and wheeled bases.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::kit::{
    Axis, DARK, INDUSTRIAL_PAINT, ROBOT_PAINT, RUBBER, SAFETY_YELLOW, SIGNAL_RED, STEEL, collider_between,
    decal_between, fit, ordered, pick, rod, shade, slab, upright_cylinder,
};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const PEDESTAL: Category = Category {
    name: "pedestal",
    display: "robot pedestal",
    synonyms: &["robot base", "robot stand", "robot riser", "arm pedestal", "mounting pedestal", "riser", "plinth"],
    tags: &["robotics", "industrial", "lab", "mount", "surface", "small"],
    description: "a steel pedestal column that a robot arm is bolted on",
    is_a: &["stand", "base"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.5, 0.3, 1.0, 0.05, "base plate along X"),
        ParamDef::new("depth", 0.5, 0.3, 1.0, 0.05, "base plate along Y"),
        ParamDef::new("height", 0.7, 0.2, 1.5, 0.15, "floor to the top of the mounting plate"),
        ParamDef::new("column", 0.2, 0.1, 0.5, 0.15, "column diameter or side"),
        ParamDef::new("plate", 0.02, 0.01, 0.05, 0.2, "base and top plate thickness"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_pedestal,
};

/// A base plate with anchor bolts, a round or square steel column with gussets, and a
/// mounting plate on top: the surface a robot arm is bolted to.
fn build_pedestal(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = fit(b, "pedestal plate", p.get("plate"), 0.0, h * 0.1);
    let side = w.min(d);
    let col = fit(b, "pedestal column", p.get("column"), 0.0, side * 0.8);
    let palette = if rng.chance(0.5) { INDUSTRIAL_PAINT } else { DARK };
    let paint = pick(rng, palette);
    let column = b.material("column", paint, true);
    let plates = b.material("plates", pick(rng, STEEL), false);
    let bolts = b.material("bolts", shade(pick(rng, STEEL), 0.7), false);
    let (hw, hd) = (w / 2.0, d / 2.0);

    slab(b, [-hw, -hd, 0.0], [hw, hd, t], plates);
    let round = rng.chance(0.6);
    let r = col / 2.0;
    if round {
        upright_cylinder(b, [0.0, 0.0], r, t, h - t, column);
    } else {
        slab(b, [-r, -r, t], [r, r, h - t], column);
    }
    let tp = (col * 1.25).max(0.2).min(side);
    let top = slab(b, [-tp / 2.0, -tp / 2.0, h - t], [tp / 2.0, tp / 2.0, h], plates);
    // Gussets where there is room between the column and the plate's edge.
    let reach = side / 2.0 - r - 0.03;
    if reach > 0.04 {
        let gh = (0.12f64).min((h - 2.0 * t) * 0.3);
        for (along_x, s) in [(true, 1.0), (true, -1.0), (false, 1.0), (false, -1.0)] {
            // From just inside the column out towards the plate's edge, 12 mm thick.
            let (a0, a1) = ordered(s * r * 0.9, s * (r + reach));
            let (min, max) = if along_x { ([a0, -0.006], [a1, 0.006]) } else { ([-0.006, a0], [0.006, a1]) };
            slab(b, [min[0], min[1], t], [max[0], max[1], t + gh], column);
        }
    }
    // Anchor bolts in the base plate's corners.
    let (bx, by) = (hw - 0.035, hd - 0.035);
    if bx > r + 0.02 || by > r + 0.02 {
        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
            rod(b, [sx * bx, sy * by, t + 0.006], 0.012, 0.012, Axis::Z, bolts);
        }
    }
    b.surface("top", top, [-tp / 2.0, -tp / 2.0], [tp / 2.0, tp / 2.0], None);
    0.0
}

pub(crate) const MOBILE_CART: Category = Category {
    name: "mobile_cart",
    display: "mobile cart",
    synonyms: &["mobile platform", "robot cart", "wheeled base", "mobile manipulator base"],
    tags: &["robotics", "mobile", "warehouse", "lab", "mount", "surface"],
    description: "a wheeled mobile robot base that carries an arm",
    is_a: &["robot", "platform"],
    kind: Kind::Vehicle,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.8, 0.5, 1.5, 0.12, "along X, the driving direction"),
        ParamDef::new("depth", 0.6, 0.4, 1.2, 0.12, "along Y"),
        ParamDef::new("height", 0.45, 0.25, 1.0, 0.1, "floor to the top of the deck plate"),
        ParamDef::new("wheel_radius", 0.075, 0.04, 0.15, 0.15, "wheel radius"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_mobile_cart,
};

/// An AGV-style box chassis on four wheels with a steel deck plate on top. The wheels
/// are drawn as cylinders and collide as boxes (the base is a fixture, so they do not
/// roll), which gives it a flat footing on the floor.
fn build_mobile_cart(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = fit(b, "mobile cart wheel_radius", p.get("wheel_radius"), 0.02, (h * 0.3).min(w * 0.15));
    let paint = pick(rng, ROBOT_PAINT);
    let body = b.material("body", paint, true);
    let plate = b.material("deck", pick(rng, STEEL), false);
    let tyre = b.material("tyres", pick(rng, RUBBER), false);
    let hub = b.material("hubs", pick(rng, STEEL), false);
    let bumper = b.material("bumper", if rng.chance(0.5) { SAFETY_YELLOW } else { shade(pick(rng, DARK), 0.8) }, false);
    let red = b.material("estop", SIGNAL_RED, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let pt = 0.012;

    slab(b, [-hw, -hd, r], [hw, hd, h - pt], body);
    let e = 0.02;
    let top = slab(b, [-(hw - e), -(hd - e), h - pt], [hw - e, hd - e, h], plate);
    let ww = (r * 0.6).clamp(0.03, 0.06);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * (hw - r - 0.04), sy * (hd - ww / 2.0 - 0.03));
        rod(b, [x, y, r], r, ww, Axis::Y, tyre);
        rod(b, [x, y, r], r * 0.45, ww + 0.004, Axis::Y, hub);
        // Collision: a box under the wheel from the floor to the chassis.
        collider_between(b, [x - r * 0.5, y - ww / 2.0, 0.0], [x + r * 0.5, y + ww / 2.0, r]);
    }
    // Bumper band around the chassis and an emergency stop on the front.
    let (bz0, bz1) = (r + 0.01, r + 0.01 + (h - r) * 0.15);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * (hd - 0.001), sy * (hd + 0.003));
        decal_between(b, [-hw, y0, bz0], [hw, y1, bz1], bumper);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * (hw - 0.001), sx * (hw + 0.003));
        decal_between(b, [x0, -hd, bz0], [x1, hd, bz1], bumper);
    }
    let ez = (bz1 + h - pt) * 0.5;
    let yellow = b.material("estop_base", SAFETY_YELLOW, false);
    decal_between(b, [hw - 0.09, hd - 0.001, ez - 0.03], [hw - 0.03, hd + 0.001, ez + 0.03], yellow);
    rod(b, [hw - 0.06, hd + 0.001, ez], 0.018, 0.006, Axis::Y, red);
    b.surface("top", top, [-(hw - e), -(hd - e)], [hw - e, hd - e], None);
    0.0
}
