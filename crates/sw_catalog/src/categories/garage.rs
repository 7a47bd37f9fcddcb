//! Garage and workshop equipment: tool chests with sliding drawers, air compressors,
//! two-post car lifts and tyres.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{
    Axis, DARK, INDUSTRIAL_PAINT, RUBBER, SAFETY_YELLOW, SIGNAL_RED, STEEL, along, collider_between, decal_between,
    pick, rod, shade, slab,
};
use super::office::drawer_stack;
use super::parts::{MOVING_GAP, RingBase, carcass, ring_collider};
use super::shapes::{ROUND, revolve, rounded_ring_profile};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const TOOL_CHEST: Category = Category {
    name: "tool_chest",
    display: "tool chest",
    synonyms: &[
        "tool cabinet on wheels",
        "roller cabinet",
        "rolling tool chest",
        "mechanic's tool chest",
        "tool trolley",
    ],
    tags: &["garage", "workshop", "industrial", "storage", "surface"],
    description: "a rolling mechanic's tool chest with drawers",
    is_a: &["chest", "cabinet", "storage"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.7, 0.5, 1.2, 0.12, "along X"),
        ParamDef::new("depth", 0.46, 0.35, 0.6, 0.06, "along Y, drawer fronts included"),
        ParamDef::new("height", 1.0, 0.6, 1.4, 0.08, "floor to the top mat"),
        ParamDef::new("drawers", 5.0, 3.0, 8.0, 0.2, "drawers, stacked"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_tool_chest,
};

/// A roller cabinet on casters: a stack of drawers that slide out (joints) with full-width
/// bar handles, and a rubber mat on the top.
fn build_tool_chest(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(
        rng,
        &[
            [0.75, 0.1, 0.08, 1.0],
            [0.12, 0.12, 0.13, 1.0],
            [0.15, 0.35, 0.65, 1.0],
            [0.2, 0.5, 0.3, 1.0],
            [0.9, 0.5, 0.1, 1.0],
        ],
    );
    let body = b.material("body", paint, true);
    let fronts = b.material("fronts", shade(paint, 1.08), true);
    let tray = b.material("drawer_inside", shade(paint, 0.6), false);
    let handles = b.material("handles", pick(rng, STEEL), false);
    let mat = b.material("mat", [0.08, 0.08, 0.08, 1.0], false);
    let tyre = b.material("casters", pick(rng, RUBBER), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let ch = 0.1f64.min(h * 0.12);
    let opening = hd - 0.018 - MOVING_GAP;
    let tc = 0.012;
    let top = carcass(b, -hw, hw, -hd, opening, ch, h, tc, body);
    decal_between(b, [-hw + 0.01, -hd + 0.01, h - 0.001], [hw - 0.01, opening - 0.01, h + 0.003], mat);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * (hw - 0.05), sy * (hd - 0.07));
        rod(b, [x, y, ch * 0.4], ch * 0.4, 0.03, Axis::X, tyre);
        collider_between(b, [x - 0.02, y - 0.03, 0.0], [x + 0.02, y + 0.03, ch + 0.001]);
    }
    let n = p.count("drawers").clamp(3, 8).min(((h - ch) / 0.08).floor().max(3.0) as usize);
    let depth = (hd - 0.018) - (-hd + tc) - MOVING_GAP;
    drawer_stack(
        b,
        n,
        [-hw + 0.002, hw - 0.002],
        [ch + 0.004, h - 0.004],
        [-hw + tc, hw - tc],
        [ch + tc, h - tc],
        hd,
        depth,
        [fronts, tray, handles],
        None,
        3.0,
    );
    b.surface("top", top, [-hw + tc / 2.0, -hd], [hw - tc / 2.0, opening], None);
    0.0
}

pub(crate) const AIR_COMPRESSOR: Category = Category {
    name: "air_compressor",
    display: "air compressor",
    synonyms: &["compressor", "shop compressor", "portable compressor", "compressed air unit"],
    tags: &["garage", "workshop", "industrial", "machine"],
    description: "a workshop air compressor with a tank",
    is_a: &["machine", "compressor"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.0, 0.6, 1.3, 0.1, "along X, the tank's axis"),
        ParamDef::new("depth", 0.4, 0.3, 0.55, 0.08, "along Y"),
        ParamDef::new("height", 0.75, 0.55, 0.95, 0.08, "to the top of the motor"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_air_compressor,
};

/// A horizontal receiver tank on two wheels and a foot, with the motor, pump and belt
/// guard on top, a pressure gauge and a handle.
fn build_air_compressor(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint =
        pick(rng, &[[0.85, 0.15, 0.1, 1.0], [0.15, 0.35, 0.65, 1.0], [0.95, 0.7, 0.1, 1.0], [0.2, 0.45, 0.25, 1.0]]);
    let tank = b.material("tank", paint, true);
    let dark = b.material("motor", pick(rng, DARK), false);
    let guard = b.material("belt_guard", pick(rng, INDUSTRIAL_PAINT), false);
    let tyre = b.material("wheels", pick(rng, RUBBER), false);
    let gauge = b.material("gauge", [0.95, 0.95, 0.93, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = (hd * 0.9).min(0.2).min(h * 0.3);
    let wr = 0.1f64.min(h * 0.15);
    let zc = wr + r * 0.6;
    // The tank runs from the handle (-X) to the +X end.
    let tank_len = w - 0.07;
    let cx = 0.035;
    let prof = [
        [0.0, -tank_len / 2.0],
        [r * 0.7, -tank_len / 2.0],
        [r, -tank_len / 2.0 + r * 0.3],
        [r, tank_len / 2.0 - r * 0.3],
        [r * 0.7, tank_len / 2.0],
        [0.0, tank_len / 2.0],
    ];
    b.visual_mesh_on(0, &revolve(&prof, ROUND), along([cx, 0.0, zc], Axis::X), tank);
    b.collision_on(0, Shape::Cylinder { radius: r, half_height: tank_len / 2.0 }, along([cx, 0.0, zc], Axis::X));
    // Wheels at +X, a rubber foot at -X, the handle beyond the foot.
    for sy in [-1.0, 1.0] {
        let y = sy * (hd - 0.03);
        rod(b, [hw - 0.14, y, wr], wr, 0.06, Axis::Y, tyre);
        collider_between(b, [hw - 0.14 - wr * 0.5, y - 0.03, 0.0], [hw - 0.14 + wr * 0.5, y + 0.03, wr]);
    }
    slab(b, [-hw + 0.1, -r * 0.6, 0.0], [-hw + 0.2, r * 0.6, zc - r * 0.8], dark);
    slab(b, [-hw, -0.15f64.min(hd), zc + r * 0.4], [-hw + 0.07, 0.15f64.min(hd), zc + r * 0.55], dark);
    // Motor, pump and belt guard on the tank.
    let zt = zc + r * 0.95;
    slab(b, [cx - tank_len * 0.35, -r * 0.5, zt], [cx - tank_len * 0.02, r * 0.5, h], dark);
    slab(b, [cx + tank_len * 0.02, -r * 0.45, zt], [cx + tank_len * 0.3, r * 0.45, h - 0.05], guard);
    rod(b, [cx + tank_len * 0.15, r * 0.45 + 0.004, h - 0.15], 0.03, 0.008, Axis::Y, gauge);
    let litres = std::f64::consts::PI * r * r * tank_len * 1000.0;
    (15.0 + litres * 0.4).min(120.0)
}

pub(crate) const CAR_LIFT: Category = Category {
    name: "car_lift",
    display: "car lift",
    synonyms: &["vehicle lift", "two-post lift", "auto lift", "hydraulic lift", "car hoist", "vehicle hoist"],
    tags: &["garage", "machine", "heavy", "industrial"],
    description: "a two-post car lift in a garage",
    is_a: &["lift", "hoist", "equipment"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 3.4, 3.0, 3.9, 0.04, "post to post along X"),
        ParamDef::new("depth", 1.1, 0.8, 1.5, 0.06, "along Y, the arms folded"),
        ParamDef::new("height", 2.8, 2.5, 2.9, 0.02, "to the top of the posts (baseplate lift)"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_car_lift,
};

/// A baseplate two-post lift: two posts with carriages at floor level, two swing arms
/// each with pads, a cover plate over the hoses between the posts and the power unit.
fn build_car_lift(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint =
        pick(rng, &[[0.15, 0.35, 0.65, 1.0], [0.85, 0.15, 0.1, 1.0], [0.95, 0.7, 0.1, 1.0], [0.25, 0.26, 0.28, 1.0]]);
    let posts = b.material("posts", paint, true);
    let arms = b.material("arms", [0.3, 0.31, 0.33, 1.0], false);
    let pads = b.material("pads", [0.05, 0.05, 0.05, 1.0], false);
    let plate = b.material("cover_plate", pick(rng, STEEL), false);
    let yellow = b.material("stripes", SAFETY_YELLOW, false);
    let red = b.material("power_unit", SIGNAL_RED, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let (pw, pd) = (0.32, 0.42f64.min(d * 0.6));
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 { (-hw, -hw + pw) } else { (hw - pw, hw) };
        slab(b, [x0, -pd / 2.0, 0.0], [x1, pd / 2.0, h], posts);
        decal_between(b, [x0 + 0.02, pd / 2.0 - 0.001, 0.3], [x1 - 0.02, pd / 2.0 + 0.002, 0.5], yellow);
        // The carriage and two arms folded along the post towards ±Y.
        let xi = if sx < 0.0 { x1 } else { x0 };
        let (cx0, cx1) = if sx < 0.0 { (xi, xi + 0.12) } else { (xi - 0.12, xi) };
        slab(b, [cx0, -pd / 2.0 + 0.02, 0.08], [cx1, pd / 2.0 - 0.02, 0.45], arms);
        for sy in [-1.0, 1.0] {
            let (y0, y1) = if sy < 0.0 { (-hd, -pd / 2.0 + 0.05) } else { (pd / 2.0 - 0.05, hd) };
            slab(b, [cx0 + 0.01, y0, 0.1], [cx1 - 0.01, y1, 0.18], arms);
            let ye = if sy < 0.0 { y0 + 0.08 } else { y1 - 0.08 };
            rod(b, [(cx0 + cx1) / 2.0, ye, 0.2], 0.06, 0.04, Axis::Z, pads);
        }
    }
    // The cover plate between the posts and the power unit on the -X post.
    slab(b, [-hw + pw, -0.2, 0.0], [hw - pw, 0.2, 0.03], plate);
    slab(b, [-hw + 0.02, pd / 2.0, 1.2], [-hw + pw - 0.02, (pd / 2.0 + 0.25).min(hd), 1.6], red);
    0.0
}

pub(crate) const TIRE: Category = Category {
    name: "tire",
    display: "tire",
    synonyms: &["tyre", "car tire", "car tyre", "wheel", "spare tire", "truck tire", "spare wheel", "car wheel"],
    tags: &["garage", "automotive", "round", "stackable"],
    description: "a car tyre",
    is_a: &["wheel"],
    kind: Kind::Container,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.65, 0.45, 1.1, 0.08, "outer diameter"),
        ParamDef::new("depth", 0.65, 0.45, 1.1, 0.08, "outer diameter (as width)"),
        ParamDef::new("height", 0.21, 0.14, 0.4, 0.12, "tread width: it lies flat"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_tire,
};

/// A tyre lying flat, with tread grooves, on a steel or alloy rim on some seeds. The tyre
/// collides as a ring of boxes standing on four of them, the rim as a disc in the hole.
fn build_tire(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let rubber = b.material("rubber", pick(rng, RUBBER), true);
    let groove = b.material("grooves", [0.03, 0.03, 0.03, 1.0], false);
    let r_in = r * rng.range(0.58, 0.68);
    let ring = revolve(&rounded_ring_profile(r_in, r, 0.0, h, (h * 0.3).min((r - r_in) * 0.4)), ROUND);
    b.visual_mesh_on(0, &ring, Pose::IDENTITY, rubber);
    for k in 1..4 {
        let z = h * k as f64 / 4.0;
        let g = revolve(
            &[[r - 0.006, z - 0.004], [r + 0.001, z - 0.004], [r + 0.001, z + 0.004], [r - 0.006, z + 0.004]],
            ROUND,
        );
        b.visual_mesh_on(0, &g, Pose::IDENTITY, groove);
    }
    ring_collider(b, [0.0, 0.0], r, r - r_in, 0.0, h, 16, RingBase::Feet);
    let rim = rng.chance(0.4);
    if rim {
        let steel = b.material("rim", pick(rng, &[[0.75, 0.76, 0.78, 1.0], [0.35, 0.36, 0.38, 1.0]]), false);
        let disc = revolve(
            &[[0.0, h * 0.3], [r_in + 0.004, h * 0.2], [r_in + 0.004, h * 0.8], [r_in * 0.4, h * 0.7], [0.0, h * 0.7]],
            ROUND,
        );
        b.visual_mesh_on(0, &disc, Pose::IDENTITY, steel);
        b.collision_on(0, Shape::Cylinder { radius: r_in, half_height: h * 0.3 }, Pose::from_pos([0.0, 0.0, h * 0.5]));
    }
    let rubber_kg = std::f64::consts::PI * (r * r - r_in * r_in) * h * 250.0;
    rubber_kg.clamp(4.0, 60.0) + if rim { 8.0 * r / 0.33 } else { 0.0 }
}
