//! Parts of the building and access: doors (a hinged leaf a robot can open), roll-up
//! doors, windows and step ladders. Doors and windows are set against a wall (placement
//! `InWall`); a window hangs at its sill height above its origin on the floor.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::kit::{
    Axis, DARK, GLASS, OFFICE_PAINT, SAFETY_YELLOW, STEEL, WOOD, collider_between, decal_between, pick, rod, shade,
    slab, strut,
};
use super::parts::{Hinge, MOVING_GAP, decal_on, hinged_door};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const DOOR: Category = Category {
    name: "door",
    display: "door",
    synonyms: &[
        "interior door",
        "office door",
        "swing door",
        "hinged door",
        "wooden door",
        "fire door",
        "doorway frame",
    ],
    tags: &["building", "office", "home", "wall"],
    description: "a hinged door in a wall",
    is_a: &["doorway", "opening"],
    kind: Kind::Fixture,
    placement: PlacementKind::InWall,
    params: &[
        ParamDef::new("width", 1.0, 0.8, 1.4, 0.08, "frame width along X"),
        ParamDef::new("depth", 0.12, 0.08, 0.2, 0.1, "frame depth along Y"),
        ParamDef::new("height", 2.15, 2.0, 2.5, 0.03, "floor to the top of the frame"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_door,
};

/// A frame (two jambs and a head) and a leaf hinged on the -X jamb that swings out into
/// the room (+Y) up to 100°, with a lever handle and, on some doors, a vision panel.
fn build_door(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let leaf_rgba = if rng.chance(0.5) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let frame = b.material("frame", shade(leaf_rgba, 0.8), false);
    let leaf = b.material("leaf", leaf_rgba, true);
    let handle = b.material("handle", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let jamb = 0.06;
    for (x0, x1) in [(-hw, -hw + jamb), (hw - jamb, hw)] {
        slab(b, [x0, -hd, 0.0], [x1, hd, h], frame);
    }
    slab(b, [-hw + jamb * 0.5, -hd, h - jamb], [hw - jamb * 0.5, hd, h], frame);
    // The leaf sits in the frame, its front flush with the frame's front.
    let lt = 0.04f64.min(d * 0.6);
    let g = MOVING_GAP;
    let (x0, x1) = (-hw + jamb + g, hw - jamb - g);
    let link =
        hinged_door(b, "leaf", Hinge::MinX, [x0, x1], [0.01, h - jamb - g], hd - lt, lt, leaf, handle, 1.05, 25.0);
    if rng.chance(0.4) {
        let glass = b.material("vision_panel", GLASS, false);
        let lw = x1 - x0;
        decal_on(b, link, [lw * 0.3, lt / 2.0, 1.3], [lw * 0.7, lt / 2.0 + 0.001, 1.3 + (h - 1.6).min(0.6)], glass);
    }
    0.0
}

pub(crate) const ROLL_UP_DOOR: Category = Category {
    name: "roll_up_door",
    display: "roll-up door",
    synonyms: &[
        "roller door",
        "rolling door",
        "roller shutter",
        "shutter door",
        "garage door",
        "overhead door",
        "loading dock door",
        "rollup door",
    ],
    tags: &["building", "warehouse", "garage", "logistics", "wall"],
    description: "a roll-up shutter door in a wall",
    is_a: &["door", "opening"],
    kind: Kind::Fixture,
    placement: PlacementKind::InWall,
    params: &[
        ParamDef::new("width", 2.6, 1.5, 4.0, 0.12, "along X, guides included"),
        ParamDef::new("depth", 0.35, 0.25, 0.5, 0.08, "along Y, the drum housing's depth"),
        ParamDef::new("height", 2.7, 2.2, 2.9, 0.04, "floor to the top of the drum housing"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_roll_up_door,
};

/// A closed slatted curtain between two guide rails under a drum housing, with a bottom
/// bar, a handle and yellow-black hazard stripes on the guides.
fn build_roll_up_door(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let slats_rgba =
        pick(rng, &[[0.72, 0.74, 0.76, 1.0], [0.9, 0.9, 0.88, 1.0], [0.2, 0.35, 0.6, 1.0], [0.35, 0.36, 0.38, 1.0]]);
    let curtain = b.material("curtain", slats_rgba, true);
    let seams = b.material("seams", shade(slats_rgba, 0.75), false);
    let guides = b.material("guides", pick(rng, STEEL), false);
    let yellow = b.material("stripes", SAFETY_YELLOW, false);
    let ink = b.material("stripes_dark", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let gw = 0.08;
    let housing = 0.4f64.min(h * 0.18);
    let zt = h - housing;
    for (x0, x1) in [(-hw, -hw + gw), (hw - gw, hw)] {
        slab(b, [x0, -hd, 0.0], [x1, -hd + 0.12, zt + 0.001], guides);
        // Hazard stripes on the guide's front, 25 cm up to 1.2 m.
        let (xa, xb) = (x0 + 0.01, x1 - 0.01);
        let y = -hd + 0.12;
        for k in 0..4 {
            let z = 0.25 + k as f64 * 0.25;
            let m = if k % 2 == 0 { yellow } else { ink };
            decal_between(b, [xa, y - 0.001, z], [xb, y + 0.002, z + 0.25], m);
        }
    }
    slab(b, [-hw, -hd, zt], [hw, hd, h], guides);
    // The curtain between the guides, with a seam every 10 cm and a bottom bar.
    let (cx0, cx1) = (-hw + gw * 0.5, hw - gw * 0.5);
    slab(b, [cx0, -hd + 0.03, 0.0], [cx1, -hd + 0.06, zt + 0.0005], curtain);
    let n = (zt / 0.1) as usize;
    for k in 1..n {
        let z = zt * k as f64 / n as f64;
        decal_between(b, [cx0 + 0.002, -hd + 0.058, z - 0.008], [cx1 - 0.002, -hd + 0.0625, z], seams);
    }
    decal_between(b, [cx0 + 0.002, -hd + 0.059, 0.0], [cx1 - 0.002, -hd + 0.066, 0.05], seams);
    rod(b, [0.0, -hd + 0.075, 0.9], 0.012, 0.2, Axis::X, ink);
    collider_between(b, [-0.1, -hd + 0.06, 0.88], [0.1, -hd + 0.087, 0.92]);
    0.0
}

pub(crate) const WINDOW: Category = Category {
    name: "window",
    display: "window",
    synonyms: &["window frame", "glass window", "casement window", "sash window", "wall window"],
    tags: &["building", "office", "home", "wall"],
    description: "a glazed window in a wall",
    is_a: &["opening"],
    kind: Kind::Fixture,
    placement: PlacementKind::InWall,
    params: &[
        ParamDef::new("width", 1.2, 0.5, 2.5, 0.15, "along X"),
        ParamDef::new("depth", 0.15, 0.08, 0.3, 0.1, "along Y, the sill included"),
        ParamDef::new("height", 1.2, 0.5, 1.8, 0.1, "frame height"),
        ParamDef::new("mount_height", 0.9, 0.3, 1.2, 0.08, "floor to the sill"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_window,
};

/// A framed, glazed window with a mullion and a sill; its origin is on the floor below
/// it and the frame starts at `mount_height`.
fn build_window(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let z0 = p.get("mount_height");
    let frame = b.material(
        "frame",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.3, 0.31, 0.33, 1.0], [0.55, 0.4, 0.25, 1.0]]),
        true,
    );
    let glass = b.material("glass", [0.55, 0.7, 0.8, 1.0], false);
    let sill_m = b.material("sill", [0.85, 0.85, 0.83, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let ft = 0.06;
    let fd = 0.07f64.min(d * 0.6);
    // The frame against the wall (-Y), the glass inside it.
    let (y0, y1) = (-hd, -hd + fd);
    for (x0, x1) in [(-hw, -hw + ft), (hw - ft, hw)] {
        slab(b, [x0, y0, z0], [x1, y1, z0 + h], frame);
    }
    for (za, zb) in [(z0, z0 + ft), (z0 + h - ft, z0 + h)] {
        slab(b, [-hw + ft * 0.5, y0, za], [hw - ft * 0.5, y1, zb], frame);
    }
    if w > 1.0 {
        slab(b, [-0.025, y0 + 0.005, z0 + ft * 0.5], [0.025, y1 - 0.005, z0 + h - ft * 0.5], frame);
    }
    slab(b, [-hw + ft, (y0 + y1) / 2.0 - 0.006, z0 + ft], [hw - ft, (y0 + y1) / 2.0 + 0.006, z0 + h - ft], glass);
    // The sill under the frame, out to the full depth.
    slab(b, [-hw, y1 - 0.01, z0], [hw, hd, z0 + 0.03], sill_m);
    0.0
}

pub(crate) const LADDER: Category = Category {
    name: "ladder",
    display: "ladder",
    synonyms: &["step ladder", "stepladder", "a-frame ladder", "step stool ladder", "rolling ladder", "library ladder"],
    tags: &["warehouse", "workshop", "garage", "storage", "tall"],
    description: "a folding step ladder",
    is_a: &["steps"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.5, 0.4, 0.7, 0.08, "along X"),
        ParamDef::new("depth", 0.8, 0.5, 1.2, 0.1, "footprint of the open A-frame along Y"),
        ParamDef::new("height", 1.5, 0.8, 2.4, 0.15, "to the top cap"),
        ParamDef::new("steps", 4.0, 2.0, 7.0, 0.2, "treads on the front side"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_ladder,
};

/// An open A-frame: front rails with treads (+Y), rear rails with braces, a top cap and
/// rubber feet. Aluminium or painted steel.
fn build_ladder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let n = p.count("steps").clamp(2, 7);
    let rails =
        b.material("rails", pick(rng, &[[0.78, 0.79, 0.8, 1.0], [0.95, 0.75, 0.1, 1.0], [0.2, 0.35, 0.65, 1.0]]), true);
    let treads = b.material("treads", [0.6, 0.61, 0.63, 1.0], false);
    let feet = b.material("feet", [0.08, 0.08, 0.08, 1.0], false);
    let cap = b.material("cap", pick(rng, &[[0.9, 0.3, 0.1, 1.0], [0.15, 0.15, 0.16, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let (rs, ft) = (0.03, 0.03);
    let top_y = 0.09f64.min(d * 0.15);
    let cap_t = 0.05;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - rs / 2.0);
        for sy in [-1.0, 1.0] {
            let y_foot = sy * (hd - 0.035);
            // A foot pad, then the rail from it to under the cap.
            slab(b, [x - rs / 2.0 - 0.001, y_foot - 0.035, 0.0], [x + rs / 2.0 + 0.001, y_foot + 0.035, ft], feet);
            strut(b, [x, y_foot, ft], [x, sy * top_y, h - cap_t], [0.06, rs], Axis::X, rails, true);
        }
    }
    // Treads between the front rails, evenly up to below the cap; braces at the back.
    let front = |z: f64| (hd - 0.035) + (top_y - (hd - 0.035)) * (z - ft) / (h - cap_t - ft);
    for k in 1..=n {
        let z = ft + (h - cap_t - ft) * k as f64 / (n + 1) as f64;
        let y = front(z);
        slab(b, [-hw + rs, y - 0.05, z - 0.02], [hw - rs, y + 0.04, z], treads);
        if k % 2 == 1 {
            decal_between(b, [-hw + rs, -y - 0.008, z - 0.012], [hw - rs, -y + 0.008, z], treads);
        }
    }
    let top = slab(b, [-hw, -top_y - 0.04, h - cap_t], [hw, top_y + 0.04, h], cap);
    b.surface("top", top, [-hw, -top_y - 0.04], [hw, top_y + 0.04], None);
    3.0 + h * 3.0
}
