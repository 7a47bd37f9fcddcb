//! Factory fixtures: conveyors, machine tools, electrical cabinets.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::kit::{
    Axis, BELT, DARK, ENCLOSURE_GREY, FRAME_PAINT, GLASS, INDUSTRIAL_PAINT, INK, LABEL_WHITE, MACHINE_PAINT,
    SAFETY_YELLOW, SIGNAL_GREEN, SIGNAL_RED, STEEL, decal_between, fit, ordered, pick, rod, shade, slab,
    upright_cylinder, warning_sign,
};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const CONVEYOR: Category = Category {
    name: "conveyor",
    display: "conveyor",
    synonyms: &[
        "belt conveyor",
        "conveyor belt",
        "conveyer",
        "conveyer belt",
        "conveyor line",
        "belt line",
        "transfer conveyor",
    ],
    tags: &["industrial", "warehouse", "logistics", "machine", "surface"],
    description: "a belt conveyor on legs that carries items along a line",
    is_a: &["machine", "equipment"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 3.0, 1.0, 8.0, 0.15, "length along X, the direction of travel"),
        ParamDef::new("depth", 0.6, 0.3, 1.5, 0.1, "overall width across the belt, along Y"),
        ParamDef::new("height", 0.8, 0.4, 1.2, 0.05, "floor to the belt surface"),
        ParamDef::new("roller_radius", 0.05, 0.03, 0.1, 0.15, "radius of the end drums"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_conveyor,
};

/// Side frames, a belt between them whose top is the highest point, end drums, leg
/// pairs with cross members, and a drive motor under the discharge end.
fn build_conveyor(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = fit(b, "conveyor roller_radius", p.get("roller_radius"), 0.01, h * 0.2);
    let frame = b.material("frame", pick(rng, FRAME_PAINT), true);
    let belt = b.material("belt", pick(rng, BELT), false);
    let steel = b.material("steel", pick(rng, STEEL), false);
    let motor = b.material("motor", pick(rng, INDUSTRIAL_PAINT), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let ft = (0.04f64).min(d * 0.1); // side frame plate
    let fh = (2.0 * r + 0.06).min(h * 0.5); // side frame height
    let bw = hd - ft; // half width of the belt

    let belt_top = slab(b, [-(hw - r), -bw, h - 2.0 * r], [hw - r, bw, h], belt);
    for sx in [-1.0, 1.0] {
        rod(b, [sx * (hw - r), 0.0, h - r], r, 2.0 * bw - 0.004, Axis::Y, steel);
    }
    let frame_top = h - (r * 0.3).min(0.01);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * hd, sy * bw);
        slab(b, [-hw, y0, h - fh], [hw, y1, frame_top], frame);
        // Axle caps on the outside of the frames, 3 mm proud.
        for sx in [-1.0, 1.0] {
            rod(b, [sx * (hw - r), sy * (hd + 0.001), h - r], r * 0.35, 0.004, Axis::Y, steel);
        }
    }
    // Leg pairs at most ~1.5 m apart, with a cross member low down.
    let leg = 0.05;
    let leg_top = h - fh;
    let pairs = ((w - 0.3) / 1.5).ceil().max(1.0) as usize + 1;
    let x_end = hw - 0.15 - leg / 2.0;
    for i in 0..pairs {
        let x = -x_end + 2.0 * x_end * i as f64 / (pairs - 1) as f64;
        for sy in [-1.0, 1.0] {
            let (y0, y1) = ordered(sy * hd, sy * (hd - leg));
            slab(b, [x - leg / 2.0, y0, 0.0], [x + leg / 2.0, y1, leg_top], steel);
        }
        let zc = (leg_top * 0.2).max(0.06);
        slab(b, [x - 0.02, -(hd - leg), zc - 0.02], [x + 0.02, hd - leg, zc + 0.02], steel);
    }
    // Gear motor hanging under the belt at the +X end.
    let mh = ((h - 2.0 * r) * 0.35).min(0.2);
    let mx1 = hw - 2.0 * r - 0.05;
    let my = bw * 0.6;
    slab(b, [mx1 - 0.25, -my, h - 2.0 * r - mh], [mx1, my, h - 2.0 * r], motor);

    b.surface("belt", belt_top, [-(hw - r), -bw], [hw - r, bw], None);
    0.0
}

pub(crate) const MACHINE: Category = Category {
    name: "machine",
    display: "machine",
    synonyms: &[
        "cnc machine",
        "cnc",
        "cnc mill",
        "machining center",
        "machining centre",
        "milling machine",
        "mill",
        "machine tool",
        "industrial machine",
        "production machine",
    ],
    tags: &["machine", "industrial", "factory", "workshop", "tall", "heavy"],
    description: "a large enclosed industrial cnc machine tool with a window door",
    is_a: &["machine tool", "equipment"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 2.0, 1.0, 4.0, 0.15, "along X"),
        ParamDef::new("depth", 1.5, 0.8, 3.0, 0.12, "along Y"),
        ParamDef::new("height", 2.0, 1.2, 3.0, 0.1, "floor to the top, signal tower included"),
        ParamDef::new("base_height", 0.12, 0.05, 0.3, 0.2, "dark machine base"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_machine,
};

/// A CNC-style enclosure: a dark base, the enclosure with a sliding door and window on
/// the front, a control column at the -X end (the operator's right: the front faces +Y)
/// and, often, a signal tower on top.
fn build_machine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let bh = fit(b, "machine base_height", p.get("base_height"), 0.0, h * 0.15);
    let paint = pick(rng, MACHINE_PAINT);
    let body = b.material("body", paint, true);
    let base = b.material("base", pick(rng, DARK), false);
    let control = b.material("control", shade(paint, 0.8), false);
    let door = b.material("door", pick(rng, INDUSTRIAL_PAINT), false);
    let glass = b.material("window", GLASS, false);
    let ink = b.material("screen", INK, false);
    let stripe = b.material("stripe", SAFETY_YELLOW, false);
    let (hw, hd) = (w / 2.0, d / 2.0);

    let tower = rng.chance(0.7);
    let tower_h = if tower { (0.35f64).min(h * 0.15) } else { 0.0 };
    let top = h - tower_h;
    let cw = (w * 0.18).clamp(0.2, 0.5);
    slab(b, [-hw, -hd, 0.0], [hw, hd, bh], base);
    slab(b, [-hw + cw, -hd, bh], [hw, hd, top], body);
    let ctop = bh + (top - bh) * 0.9;
    slab(b, [-hw, -hd, bh], [-hw + cw, hd, ctop], control);

    // Sliding door with its window and handle on the front of the enclosure.
    let (dx0, dx1) = (-hw + cw + 0.08, hw - 0.08);
    let (dz0, dz1) = (bh + (top - bh) * 0.12, top - (top - bh) * 0.1);
    decal_between(b, [dx0, hd - 0.001, dz0], [dx1, hd + 0.001, dz1], door);
    let (gx, gz) = ((dx1 - dx0) * 0.15, (dz1 - dz0) * 0.2);
    decal_between(b, [dx0 + gx, hd + 0.001, dz0 + gz * 1.4], [dx1 - gx, hd + 0.0025, dz1 - gz * 0.6], glass);
    let hz = (dz0 + dz1) * 0.5;
    decal_between(b, [dx0 + 0.035, hd + 0.001, hz - 0.15], [dx0 + 0.06, hd + 0.004, hz + 0.15], ink);
    // Screen and buttons on the control column.
    let cx = -hw + cw / 2.0;
    let (sw, sh) = (cw * 0.7, (ctop - bh) * 0.18);
    let sz = ctop - 0.08 - sh / 2.0;
    decal_between(b, [cx - sw / 2.0, hd - 0.001, sz - sh / 2.0], [cx + sw / 2.0, hd + 0.002, sz + sh / 2.0], ink);
    let red = b.material("estop", SIGNAL_RED, false);
    let green = b.material("start", SIGNAL_GREEN, false);
    let bz = sz - sh / 2.0 - 0.06;
    rod(b, [cx - cw * 0.2, hd + 0.001, bz], 0.02, 0.006, Axis::Y, red);
    rod(b, [cx + cw * 0.2, hd + 0.001, bz], 0.012, 0.004, Axis::Y, green);
    // Hazard stripe along the front of the base.
    decal_between(b, [-hw + 0.02, hd - 0.001, bh * 0.3], [hw - 0.02, hd + 0.001, bh * 0.7], stripe);
    // Louvres on the +X side.
    for k in 0..5 {
        let z = bh + (top - bh) * 0.3 + k as f64 * 0.04;
        decal_between(b, [hw - 0.001, -hd * 0.4, z], [hw + 0.001, hd * 0.4, z + 0.015], ink);
    }
    if tower {
        let pole = b.material("tower_pole", pick(rng, STEEL), false);
        let amber = b.material("tower_amber", [0.95, 0.6, 0.05, 1.0], false);
        let (x, y) = (hw - 0.12, -hd + 0.12);
        let seg = tower_h * 0.2;
        let mut z = upright_cylinder(b, [x, y], 0.012, top, top + tower_h * 0.4, pole);
        for (i, m) in [green, amber, red].into_iter().enumerate() {
            let z1 = if i == 2 { h } else { z + seg };
            z = upright_cylinder(b, [x, y], 0.035, z, z1, m);
        }
    }
    0.0
}

pub(crate) const ELECTRICAL_PANEL: Category = Category {
    name: "electrical_panel",
    display: "electrical panel",
    synonyms: &[
        "electrical cabinet",
        "electric panel",
        "electrical enclosure",
        "switch cabinet",
        "distribution board",
        "distribution panel",
        "breaker panel",
        "control cabinet",
        "power cabinet",
    ],
    tags: &["electrical", "industrial", "data_centre", "warehouse", "utility", "hazard", "tall"],
    description: "a grey electrical control cabinet with a door and warning sign",
    is_a: &["enclosure", "cabinet", "equipment"],
    kind: Kind::Fixture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.8, 0.4, 1.6, 0.15, "along X"),
        ParamDef::new("depth", 0.4, 0.2, 0.8, 0.1, "along Y"),
        ParamDef::new("height", 2.0, 0.8, 2.3, 0.05, "floor to top, plinth included"),
        ParamDef::new("plinth", 0.1, 0.04, 0.2, 0.2, "base height"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_electrical_panel,
};

/// A floor-standing enclosure on a plinth: one or two doors with swing handles, a
/// warning triangle and a danger plate on each door, louvres low down and pilot lamps.
fn build_electrical_panel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let pl = fit(b, "electrical panel plinth", p.get("plinth"), 0.0, h * 0.12);
    let paint = pick(rng, ENCLOSURE_GREY);
    let body = b.material("body", paint, true);
    let door = b.material("door", shade(paint, 0.97), true);
    let plinth = b.material("plinth", pick(rng, DARK), false);
    let ink = b.material("ink", INK, false);
    let yellow = b.material("warning", SAFETY_YELLOW, false);
    let white = b.material("plate", LABEL_WHITE, false);
    let red = b.material("plate_band", SIGNAL_RED, false);
    let (hw, hd) = (w / 2.0, d / 2.0);

    slab(b, [-hw, -hd, 0.0], [hw, hd, pl], plinth);
    slab(b, [-hw, -hd, pl], [hw, hd, h], body);

    let n_doors = if w > 1.0 { 2 } else { 1 };
    let (edge, gap) = (0.015, 0.004);
    let door_w = (w - 2.0 * edge - gap * (n_doors - 1) as f64) / n_doors as f64;
    let (z0, z1) = (pl + edge, h - edge);
    let lamps = rng.chance(0.6);
    for i in 0..n_doors {
        let x0 = -hw + edge + i as f64 * (door_w + gap);
        let xc = x0 + door_w / 2.0;
        decal_between(b, [x0, hd - 0.001, z0], [x0 + door_w, hd + 0.001, z1], door);
        // Swing handle at the free edge.
        let hx = if i == 0 { x0 + door_w - 0.05 } else { x0 + 0.05 };
        let hz = (1.1f64).min((z0 + z1) * 0.5);
        let hl = (0.16f64).min((z1 - z0) * 0.25);
        decal_between(b, [hx - 0.012, hd + 0.001, hz - hl / 2.0], [hx + 0.012, hd + 0.004, hz + hl / 2.0], ink);
        // Warning triangle and a danger plate under it, in the upper part of the door.
        let side = (door_w * 0.35).min(0.14).min((z1 - z0) * 0.2);
        let tz = z1 - 0.06 - side * 0.5;
        warning_sign(b, xc, tz, hd + 0.001, side, yellow, ink);
        let (pw, ph) = (side * 1.3, side * 0.45);
        let pz = tz - side * 0.45 - 0.02 - ph / 2.0;
        decal_between(b, [xc - pw / 2.0, hd + 0.001, pz - ph / 2.0], [xc + pw / 2.0, hd + 0.002, pz + ph / 2.0], white);
        decal_between(
            b,
            [xc - pw / 2.0 + 0.003, hd + 0.002, pz + ph * 0.1],
            [xc + pw / 2.0 - 0.003, hd + 0.003, pz + ph / 2.0 - 0.003],
            red,
        );
        // Louvres near the bottom of the door.
        let lw = door_w * 0.5;
        for k in 0..4 {
            let z = z0 + 0.05 + k as f64 * 0.025;
            decal_between(b, [xc - lw / 2.0, hd + 0.001, z], [xc + lw / 2.0, hd + 0.0025, z + 0.01], ink);
        }
        if lamps && i == 0 {
            let green = b.material("lamp_on", SIGNAL_GREEN, false);
            let lz = pz - ph / 2.0 - 0.04;
            rod(b, [xc - 0.03, hd + 0.001, lz], 0.011, 0.006, Axis::Y, green);
            rod(b, [xc + 0.03, hd + 0.001, lz], 0.011, 0.006, Axis::Y, red);
        }
    }
    0.0
}
