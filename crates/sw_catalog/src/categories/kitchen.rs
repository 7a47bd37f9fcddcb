//! Kitchen fixtures and appliances: counters, sinks, fridges with hinged doors, stoves
//! and microwaves (whose door a robot can open).

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::forms::drop_door;
use super::kit::{
    Axis, DARK, GLASS, INK, OFFICE_PAINT, STEEL, WOOD, collider_between, decal_between, fit, pick, rod, shade, slab,
};
use super::parts::{Hinge, MOVING_GAP, carcass, decal_on, hinged_door};
use super::shapes::{ROUND, revolve, rounded_ring_profile};
use crate::{Category, Kind, ParamDef, Params};

/// Worktops: laminate, stone, wood and steel.
const WORKTOP: &[[f32; 4]] = &[
    [0.9, 0.89, 0.86, 1.0],
    [0.2, 0.2, 0.22, 1.0],
    [0.62, 0.45, 0.28, 1.0],
    [0.72, 0.73, 0.75, 1.0],
    [0.55, 0.53, 0.5, 1.0],
];
/// Appliance finishes.
pub(crate) const APPLIANCE: &[[f32; 4]] =
    &[[0.95, 0.95, 0.94, 1.0], [0.72, 0.73, 0.75, 1.0], [0.15, 0.15, 0.16, 1.0], [0.85, 0.86, 0.86, 1.0]];

/// Cabinet fronts drawn on the +Y face of a base unit between `x0..x1` and `z0..z1`:
/// a drawer row on top and doors below, with small bar handles.
fn base_fronts(b: &mut AssetBuilder, [x0, x1]: [f64; 2], [z0, z1]: [f64; 2], y: f64, [fronts, handles]: [usize; 2]) {
    let n = (((x1 - x0) / 0.6).round() as usize).max(1);
    let uw = (x1 - x0) / n as f64;
    let dz = z1 - 0.16;
    for k in 0..n {
        let xa = x0 + uw * k as f64 + 0.002;
        let xb = xa + uw - 0.004;
        decal_between(b, [xa, y - 0.001, dz + 0.003], [xb, y + 0.002, z1 - 0.003], fronts);
        decal_between(b, [xa, y - 0.001, z0 + 0.003], [xb, y + 0.002, dz - 0.003], fronts);
        let xc = (xa + xb) / 2.0;
        decal_between(b, [xc - 0.06, y + 0.002, z1 - 0.05], [xc + 0.06, y + 0.006, z1 - 0.04], handles);
        decal_between(b, [xb - 0.04, y + 0.002, dz - 0.16], [xb - 0.03, y + 0.006, dz - 0.04], handles);
    }
}

pub(crate) const COUNTER: Category = Category {
    name: "counter",
    display: "counter",
    synonyms: &[
        "kitchen counter",
        "countertop",
        "worktop",
        "base cabinet",
        "kitchen island",
        "service counter",
        "lab counter",
    ],
    tags: &["furniture", "surface", "kitchen", "lab", "storage"],
    description: "a run of kitchen base cabinets under a worktop",
    is_a: &["furniture", "cabinet", "worktop"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 2.0, 0.6, 4.0, 0.2, "along X"),
        ParamDef::new("depth", 0.62, 0.5, 0.8, 0.05, "along Y, worktop overhang included"),
        ParamDef::new("height", 0.91, 0.8, 1.0, 0.02, "floor to the worktop surface"),
        ParamDef::new("worktop", 0.035, 0.02, 0.06, 0.2, "worktop thickness"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_counter,
};

/// A run of base cabinets on a recessed plinth under a worktop that overhangs the front.
fn build_counter(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = p.get("worktop").min(h * 0.1);
    let top = b.material("worktop", pick(rng, WORKTOP), true);
    let front_rgba = if rng.chance(0.4) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", shade(front_rgba, 0.9), false);
    let fronts = b.material("fronts", front_rgba, true);
    let plinth = b.material("plinth", pick(rng, DARK), false);
    let handles = b.material("handles", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let y_front = hd - 0.025;
    let top_z = slab(b, [-hw, -hd, h - t], [hw, hd, h], top);
    slab(b, [-hw + 0.005, -hd, 0.0], [hw - 0.005, y_front - 0.06, 0.1], plinth);
    slab(b, [-hw + 0.005, -hd, 0.1], [hw - 0.005, y_front, h - t], body);
    base_fronts(b, [-hw + 0.005, hw - 0.005], [0.1, h - t], y_front, [fronts, handles]);
    b.surface("top", top_z, [-hw, -hd], [hw, hd], None);
    0.0
}

pub(crate) const SINK: Category = Category {
    name: "sink",
    display: "sink",
    synonyms: &[
        "kitchen sink",
        "lab sink",
        "wash basin",
        "washbasin",
        "utility sink",
        "hand sink",
        "basin",
        "sink unit",
    ],
    tags: &["kitchen", "lab", "hospital", "surface", "plumbing"],
    description: "a kitchen sink unit with a steel bowl, a drainboard and a tap",
    is_a: &["fixture", "basin", "plumbing fixture"],
    kind: Kind::Fixture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.0, 0.7, 2.0, 0.15, "along X"),
        ParamDef::new("depth", 0.62, 0.5, 0.75, 0.05, "along Y"),
        ParamDef::new("height", 1.2, 1.0, 1.4, 0.03, "floor to the top of the tap"),
        ParamDef::new("worktop_height", 0.91, 0.8, 0.95, 0.02, "floor to the worktop surface"),
        ParamDef::new("basin_depth", 0.18, 0.1, 0.25, 0.15, "depth of the bowl"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_sink,
};

/// A base unit whose worktop has a steel bowl on one side (open: things go in) and a
/// drainboard on the other, with a swan-neck tap behind the bowl.
fn build_sink(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, top_h) = (p.get("width"), p.get("depth"), p.get("height"));
    let h = fit(b, "sink worktop_height", p.get("worktop_height"), 0.5, top_h - 0.1);
    let bd = p.get("basin_depth").min(h * 0.3);
    let t = 0.035;
    let steel = b.material("steel", [0.74, 0.75, 0.77, 1.0], true);
    let front_rgba = pick(rng, OFFICE_PAINT);
    let body = b.material("body", shade(front_rgba, 0.9), false);
    let fronts = b.material("fronts", front_rgba, false);
    let plinth = b.material("plinth", pick(rng, DARK), false);
    let chrome = b.material("tap", pick(rng, STEEL), false);
    let handles = b.material("handles", shade(pick(rng, STEEL), 0.9), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let y_front = hd - 0.025;
    // The bowl on the left (-X), the drainboard on the right.
    let bw = (w * 0.45).min(0.55);
    let (bx0, bx1) = (-hw + 0.06, -hw + 0.06 + bw);
    let (by0, by1) = (-hd + 0.1, hd - 0.06);
    let zb = h - bd;
    slab(b, [-hw + 0.005, -hd, 0.0], [hw - 0.005, y_front - 0.06, 0.1], plinth);
    slab(b, [-hw + 0.005, -hd, 0.1], [hw - 0.005, y_front, zb - 0.02], body);
    base_fronts(b, [-hw + 0.005, hw - 0.005], [0.1, h - t], y_front, [fronts, handles]);
    // The worktop in four pieces around the bowl opening.
    slab(b, [-hw, -hd, h - t], [bx0, hd, h], steel);
    let drain = slab(b, [bx1, -hd, h - t], [hw, hd, h], steel);
    slab(b, [bx0 - 0.001, -hd, h - t], [bx1 + 0.001, by0, h], steel);
    slab(b, [bx0 - 0.001, by1, h - t], [bx1 + 0.001, hd, h], steel);
    // The bowl: a floor and four walls.
    let wt = 0.01;
    let floor = slab(b, [bx0, by0, zb - 0.02], [bx1, by1, zb], steel);
    slab(b, [bx0, by0 - 0.0005, zb], [bx0 + wt, by1 + 0.0005, h - t], steel);
    slab(b, [bx1 - wt, by0 - 0.0005, zb], [bx1, by1 + 0.0005, h - t], steel);
    slab(b, [bx0 + wt * 0.5, by0, zb + 0.0005], [bx1 - wt * 0.5, by0 + wt, h - t], steel);
    slab(b, [bx0 + wt * 0.5, by1 - wt, zb + 0.0005], [bx1 - wt * 0.5, by1, h - t], steel);
    // Drain and a swan-neck tap behind the bowl (visual: they must not carry things).
    let (cx, cy) = ((bx0 + bx1) / 2.0, (by0 + by1) / 2.0);
    rod(b, [cx, cy, zb + 0.001], 0.035, 0.002, Axis::Z, chrome);
    let ty = (-hd + by0) / 2.0;
    let post = top_h - h;
    rod(b, [cx, ty, h + post / 2.0], 0.012, post, Axis::Z, chrome);
    let reach = (by0 - ty) + 0.08;
    rod(b, [cx, ty + reach / 2.0, top_h - 0.012], 0.011, reach, Axis::Y, chrome);
    collider_between(b, [cx - 0.012, ty - 0.012, h], [cx + 0.012, ty + 0.012, top_h]);
    collider_between(b, [cx - 0.011, ty, top_h - 0.023], [cx + 0.011, ty + reach, top_h - 0.001]);
    b.surface("drainboard", drain, [bx1, -hd], [hw, hd], None);
    let m = 0.02;
    b.surface("basin", floor, [bx0 + wt + m, by0 + wt + m], [bx1 - wt - m, by1 - wt - m], Some(bd - 0.01));
    0.0
}

pub(crate) const FRIDGE: Category = Category {
    name: "fridge",
    display: "fridge",
    synonyms: &[
        "refrigerator",
        "fridge freezer",
        "fridge-freezer",
        "freezer",
        "lab fridge",
        "lab refrigerator",
        "icebox",
    ],
    tags: &["kitchen", "lab", "appliance", "tall", "storage"],
    description: "a tall refrigerator with a fridge door and a freezer door",
    is_a: &["appliance", "kitchen appliance", "cooler"],
    kind: Kind::LargeAppliance,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.6, 0.5, 0.95, 0.1, "along X"),
        ParamDef::new("depth", 0.66, 0.55, 0.8, 0.05, "along Y, doors included"),
        ParamDef::new("height", 1.8, 0.8, 2.0, 0.08, "floor to top"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_fridge,
};

/// An open-fronted insulated carcass with glass shelves, closed by a fridge door and,
/// on tall ones, a freezer door below: both hinge joints that open outwards.
fn build_fridge(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let finish = pick(rng, APPLIANCE);
    let body = b.material("body", finish, true);
    let doors = b.material("doors", shade(finish, 1.02), true);
    let inside = b.material("inside", [0.93, 0.94, 0.95, 1.0], false);
    let handles = b.material("handles", if rng.chance(0.5) { pick(rng, STEEL) } else { pick(rng, DARK) }, false);
    let grille = b.material("grille", shade(INK, 2.0), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.05;
    let opening = hd - dt - MOVING_GAP;
    let wall = 0.04;
    let top = carcass(b, -hw, hw, -hd, opening, 0.05, h, wall, body);
    slab(b, [-hw + 0.01, -hd, 0.0], [hw - 0.01, opening - 0.01, 0.05], body);
    decal_between(b, [-hw + 0.03, opening - 0.002, 0.01], [hw - 0.03, opening + 0.001, 0.045], grille);
    // Shelves inside.
    let shelves = ((h - 0.3) / 0.35).floor().max(1.0) as usize;
    for k in 1..=shelves {
        let z = 0.05 + wall + (h - 0.05 - 2.0 * wall) * k as f64 / (shelves + 1) as f64;
        slab(b, [-hw + wall * 0.5, -hd + wall * 0.75, z - 0.006], [hw - wall * 0.5, opening - 0.04, z], inside);
    }
    let hinge = if rng.chance(0.5) { Hinge::MinX } else { Hinge::MaxX };
    let (z0, z1) = (0.055, h - 0.005);
    let freezer = h > 1.4;
    let split = if freezer { z0 + (z1 - z0) * rng.range(0.3, 0.4) } else { z0 };
    let leaf = |zz: f64| (w * zz * dt * 250.0).max(1.0);
    if freezer {
        hinged_door(
            b,
            "freezer_door",
            hinge,
            [-hw + 0.003, hw - 0.003],
            [z0, split - 0.002],
            hd - dt,
            dt,
            doors,
            handles,
            split - 0.12,
            leaf(split - z0),
        );
    }
    let start = if freezer { split + 0.002 } else { z0 };
    hinged_door(
        b,
        "door",
        hinge,
        [-hw + 0.003, hw - 0.003],
        [start, z1],
        hd - dt,
        dt,
        doors,
        handles,
        start + 0.15,
        leaf(z1 - start),
    );
    b.surface("top", top, [-hw + wall / 2.0, -hd], [hw - wall / 2.0, opening], None);
    0.0
}

pub(crate) const STOVE: Category = Category {
    name: "stove",
    display: "stove",
    synonyms: &["cooker", "range", "oven", "cooking range", "gas stove", "electric stove", "kitchen range"],
    tags: &["kitchen", "appliance", "surface"],
    description: "a freestanding kitchen range with four burners on top and an oven below",
    is_a: &["appliance", "kitchen appliance", "cooker"],
    kind: Kind::LargeAppliance,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.6, 0.5, 1.0, 0.1, "along X"),
        ParamDef::new("depth", 0.62, 0.55, 0.75, 0.05, "along Y"),
        ParamDef::new("height", 1.0, 0.85, 1.15, 0.04, "floor to the top of the back guard"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_stove,
};

/// A freestanding range: an oven (an open box with a glass door hinged at the bottom that
/// a robot pulls down by its bar), control knobs above it, a cooktop with four burners and
/// a back guard.
fn build_stove(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let finish = pick(rng, APPLIANCE);
    let body = b.material("body", finish, true);
    let hob = b.material("cooktop", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.62, 0.63, 0.65, 1.0]]), false);
    let burners = b.material("burners", [0.05, 0.05, 0.05, 1.0], false);
    let glass = b.material("window", GLASS, false);
    let handles = b.material("handles", pick(rng, STEEL), false);
    let inside = b.material("oven_inside", [0.12, 0.12, 0.13, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top_h = 0.9f64.min(h - 0.06);
    let guard = 0.05;
    // The door is 3.5 cm thick; the carcass and the control band stand behind it.
    let dt = 0.035;
    let yf = hd - dt;
    let opening = yf - MOVING_GAP;
    let (dz0, dz1) = (0.12, top_h - 0.14);
    // The plinth under the oven, the oven's open box, the control band above it.
    slab(b, [-hw, -hd, 0.0], [hw, yf, dz0], body);
    carcass(b, -hw, hw, -hd, opening, dz0, dz1, 0.02, body);
    decal_between(b, [-hw + 0.021, -hd + 0.021, dz0 + 0.021], [hw - 0.021, opening - 0.01, dz0 + 0.022], inside);
    slab(b, [-hw, -hd, dz1], [hw, yf, top_h - 0.02], body);
    let top = slab(b, [-hw, -hd + guard, top_h - 0.02], [hw, yf, top_h], hob);
    slab(b, [-hw, -hd, top_h - 0.021], [hw, -hd + guard, h], body);
    // Four burners in a square.
    let (bx, by) = (w * 0.22, (d - guard) * 0.22);
    let yc = (-hd + guard + yf) / 2.0;
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let r = f64::min(if sx * sy > 0.0 { 0.09 } else { 0.07 }, w * 0.15);
        let ring = revolve(&rounded_ring_profile(r * 0.5, r, top_h, top_h + 0.012, 0.004), ROUND);
        b.visual_mesh_on(0, &ring, Pose::from_pos([sx * bx, yc + sy * by, 0.0]), burners);
    }
    // The oven door with its window; `drop_door` puts the handle bar across its top.
    let door =
        drop_door(b, "oven_door", [-hw + 0.004, hw - 0.004], [dz0 + 0.002, dz1 - 0.002], yf, dt, [body, handles], 4.0);
    let dh = dz1 - dz0 - 0.004;
    decal_on(b, door, [-hw + 0.08, 0.0, 0.08], [hw - 0.08, 0.002, dh - 0.1], glass);
    for k in 0..4 {
        let x = -hw + w * (0.2 + 0.2 * k as f64);
        rod(b, [x, yf + 0.01, top_h - 0.07], 0.018, 0.02, Axis::Y, handles);
    }
    b.surface("cooktop", top, [-hw, -hd + guard], [hw, yf], None);
    0.0
}

pub(crate) const MICROWAVE: Category = Category {
    name: "microwave",
    display: "microwave",
    synonyms: &["microwave oven", "lab oven"],
    tags: &["kitchen", "office", "appliance", "tabletop"],
    description: "a countertop microwave oven with a glass door",
    is_a: &["appliance", "kitchen appliance", "oven"],
    kind: Kind::SmallAppliance,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.48, 0.38, 0.6, 0.08, "along X"),
        ParamDef::new("depth", 0.36, 0.3, 0.45, 0.06, "along Y, door included"),
        ParamDef::new("height", 0.28, 0.22, 0.36, 0.06, "floor to top"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_microwave,
};

/// An open-fronted box with a glass door hinged on its left edge as you face it (+X; a
/// robot can open it) and a control panel on the right (-X).
fn build_microwave(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let finish = pick(rng, APPLIANCE);
    let body = b.material("body", finish, true);
    let door = b.material("door", GLASS, false);
    let panel = b.material("panel", shade(finish, 0.8), false);
    let ink = b.material("display", INK, false);
    let handle = b.material("handle", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.02;
    let opening = hd - dt - MOVING_GAP;
    let pw = (w * 0.25).min(0.13);
    let top = carcass(b, -hw, hw, -hd, opening, 0.0, h, 0.012, body);
    slab(b, [-hw + 0.006, opening - 0.05, 0.012], [-hw + pw, hd, h - 0.012], panel);
    decal_between(b, [-hw + 0.02, hd - 0.001, h - 0.07], [-hw + pw - 0.015, hd + 0.002, h - 0.04], ink);
    let door_x = [-hw + pw + 0.003, hw - 0.004];
    hinged_door(b, "door", Hinge::MaxX, door_x, [0.004, h - 0.004], hd - dt, dt, door, handle, h / 2.0, 1.2);
    b.surface("top", top, [-hw + 0.006, -hd], [hw - 0.006, opening], None);
    // Steel box, glass door, magnetron: about 12 kg for a 0.05 m³ oven.
    (w * d * h * 250.0).max(6.0)
}
