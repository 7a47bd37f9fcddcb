//! Power and data-centre equipment: server racks (with a front door that opens),
//! switchgear line-ups, transformers, cooling units and cable trays.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::kit::{
    Axis, DARK, ENCLOSURE_GREY, INK, LABEL_WHITE, SAFETY_YELLOW, SIGNAL_GREEN, SIGNAL_RED, collider_between,
    decal_between, pick, rod, shade, slab, warning_sign,
};
use super::parts::{Hinge, MOVING_GAP, carcass, decal_on, hinged_door};
use super::shapes::revolve;
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const SERVER_RACK: Category = Category {
    name: "server_rack",
    display: "server rack",
    synonyms: &[
        "server cabinet",
        "rack cabinet",
        "19 inch rack",
        "network rack",
        "data rack",
        "computer rack",
        "server",
        "rack server",
    ],
    tags: &["data_centre", "electrical", "tall", "storage", "office"],
    description: "a 19 inch server rack full of servers",
    is_a: &["rack", "computer", "equipment"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.6, 0.6, 0.8, 0.0, "along X"),
        ParamDef::new("depth", 1.07, 0.6, 1.2, 0.06, "along Y, the front door included"),
        ParamDef::new("height", 2.0, 1.0, 2.3, 0.05, "floor to top (42U: 2.0 m)"),
        ParamDef::new("fill", 0.7, 0.0, 1.0, 0.3, "share of the rack units holding servers"),
    ],
    movable: false,
    vary_per_instance: true,
    build: build_server_rack,
};

/// A black cabinet with servers stacked behind a perforated front door on a hinge, blue
/// and green status lights, and a vented top.
fn build_server_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body =
        b.material("body", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.16, 0.16, 0.17, 1.0], [0.82, 0.83, 0.84, 1.0]]), true);
    let door_m = b.material("door", pick(rng, &[[0.14, 0.14, 0.15, 1.0], [0.2, 0.2, 0.22, 1.0]]), false);
    let servers = b.material("servers", [0.3, 0.31, 0.33, 1.0], false);
    let leds = b.material("leds", pick(rng, &[SIGNAL_GREEN, [0.2, 0.5, 1.0, 1.0]]), false);
    let handle = b.material("handle", [0.6, 0.61, 0.63, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.025;
    let opening = hd - dt - MOVING_GAP;
    let plinth = 0.05;
    slab(b, [-hw + 0.01, -hd + 0.01, 0.0], [hw - 0.01, opening - 0.02, plinth], body);
    let top = carcass(b, -hw, hw, -hd, opening, plinth, h, 0.02, body);
    // Servers: 1U–4U boxes from the bottom up, set back 8 cm from the opening.
    let u = 0.0445;
    let units = ((h - plinth - 0.1) / u).floor() as usize;
    let filled = (units as f64 * p.get("fill")).round() as usize;
    let mut k = 0;
    let front = opening - 0.08;
    while k < filled {
        let size = (1 + rng.below(4)).min(filled - k);
        let z0 = plinth + 0.04 + k as f64 * u;
        let z1 = z0 + size as f64 * u - 0.002;
        slab(b, [-hw + 0.04, -hd + 0.1, z0], [hw - 0.04, front, z1], servers);
        for j in 0..size.min(2) {
            let x = -hw + 0.08 + j as f64 * 0.03;
            decal_between(b, [x, front - 0.001, z1 - 0.015], [x + 0.012, front + 0.002, z1 - 0.008], leds);
        }
        k += size;
    }
    // The front door: a leaf on the -X edge with horizontal perforation bands.
    let link = hinged_door(
        b,
        "door",
        Hinge::MinX,
        [-hw + 0.003, hw - 0.003],
        [plinth + 0.003, h - 0.003],
        hd - dt,
        dt,
        door_m,
        handle,
        1.2,
        12.0,
    );
    let bands = b.material("perforation", shade(INK, 0.5), false);
    let dw = w - 0.006;
    let n = ((h - plinth - 0.2) / 0.05) as usize;
    for r in 0..n {
        let z = 0.1 + r as f64 * 0.05;
        decal_on(b, link, [0.05, dt / 2.0, z], [dw - 0.08, dt / 2.0 + 0.001, z + 0.025], bands);
    }
    b.surface("top", top, [-hw + 0.01, -hd], [hw - 0.01, opening], None);
    0.0
}

pub(crate) const SWITCHGEAR: Category = Category {
    name: "switchgear",
    display: "switchgear",
    synonyms: &[
        "switchgear cabinet",
        "switchboard",
        "switchgear panel",
        "motor control center",
        "motor control centre",
        "mcc",
        "power distribution unit",
        "ups cabinet",
    ],
    tags: &["electrical", "industrial", "data_centre", "utility", "hazard", "tall", "heavy"],
    description: "electrical switchgear cabinets",
    is_a: &["electrical equipment", "equipment", "cabinet"],
    kind: Kind::Machine,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 2.4, 0.8, 4.8, 0.2, "the line-up along X, about 0.8 m per section"),
        ParamDef::new("depth", 0.8, 0.6, 1.2, 0.08, "along Y"),
        ParamDef::new("height", 2.2, 1.9, 2.5, 0.03, "floor to the top"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_switchgear,
};

/// A line-up of sections, each with breaker compartments (three doors, one with a
/// meter), a warning sign and lamps, on a plinth, with a cable-duct hood on top.
fn build_switchgear(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(rng, ENCLOSURE_GREY);
    let body = b.material("body", paint, true);
    let doors = b.material("doors", shade(paint, 1.03), true);
    let plinth = b.material("plinth", pick(rng, DARK), false);
    let ink = b.material("ink", INK, false);
    let yellow = b.material("warning", SAFETY_YELLOW, false);
    let red = b.material("lamps", SIGNAL_RED, false);
    let white = b.material("meters", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let pl = 0.1;
    slab(b, [-hw, -hd, 0.0], [hw, hd, pl], plinth);
    slab(b, [-hw, -hd, pl], [hw, hd, h - 0.15], body);
    slab(b, [-hw, -hd, h - 0.151], [hw, hd - 0.09, h], body);
    let n = ((w / 0.8).round() as usize).max(1);
    let sw = w / n as f64;
    for s in 0..n {
        let x0 = -hw + sw * s as f64 + 0.01;
        let x1 = x0 + sw - 0.02;
        let xc = (x0 + x1) / 2.0;
        let body_h = h - 0.15 - pl;
        for c in 0..3 {
            let z0 = pl + 0.02 + body_h * c as f64 / 3.0;
            let z1 = z0 + body_h / 3.0 - 0.02;
            decal_between(b, [x0, hd - 0.001, z0], [x1, hd + 0.002, z1], doors);
            decal_between(
                b,
                [x1 - 0.06, hd + 0.002, (z0 + z1) / 2.0 - 0.05],
                [x1 - 0.04, hd + 0.0045, (z0 + z1) / 2.0 + 0.05],
                ink,
            );
            if c == 2 {
                decal_between(b, [xc - 0.08, hd + 0.002, z1 - 0.2], [xc + 0.08, hd + 0.003, z1 - 0.06], white);
                for (k, m) in [red, yellow].into_iter().enumerate() {
                    rod(b, [xc - 0.04 + k as f64 * 0.08, hd + 0.003, z1 - 0.25], 0.012, 0.004, Axis::Y, m);
                }
            }
            if c == 1 {
                let side = (sw * 0.2).min(0.12);
                warning_sign(b, xc, (z0 + z1) / 2.0, hd + 0.001, side, yellow, ink);
            }
        }
    }
    0.0
}

pub(crate) const TRANSFORMER: Category = Category {
    name: "transformer",
    display: "transformer",
    synonyms: &[
        "power transformer",
        "electrical transformer",
        "distribution transformer",
        "pad-mounted transformer",
        "substation transformer",
        "dry-type transformer",
    ],
    tags: &["electrical", "industrial", "utility", "hazard", "heavy"],
    description: "an electrical power transformer",
    is_a: &["electrical equipment", "equipment"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.8, 1.0, 3.0, 0.12, "along X, the radiators included"),
        ParamDef::new("depth", 1.3, 0.8, 2.0, 0.1, "along Y"),
        ParamDef::new("height", 1.9, 1.2, 2.6, 0.08, "floor to the top of the bushings"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_transformer,
};

/// An oil-filled tank on skids with radiator fin banks on both ends, high-voltage
/// bushings with porcelain sheds on the lid, a rating plate and a warning sign.
fn build_transformer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(rng, &[[0.45, 0.5, 0.45, 1.0], [0.6, 0.62, 0.64, 1.0], [0.35, 0.42, 0.38, 1.0]]);
    let tank = b.material("tank", paint, true);
    let fins = b.material("fins", shade(paint, 0.85), false);
    let porcelain = b.material("bushings", [0.55, 0.3, 0.2, 1.0], false);
    let skids = b.material("skids", pick(rng, DARK), false);
    let ink = b.material("ink", INK, false);
    let yellow = b.material("warning", SAFETY_YELLOW, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let fin_w = (w * 0.18).min(0.35);
    let tx = hw - fin_w;
    let lid = h * 0.72;
    for y in [-hd * 0.7, hd * 0.7] {
        slab(b, [-tx, y - 0.05, 0.0], [tx, y + 0.05, 0.1], skids);
    }
    let top = slab(b, [-tx, -hd, 0.1], [tx, hd, lid], tank);
    // Radiator banks: a block of fins on each end.
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 { (-hw, -tx) } else { (tx, hw) };
        collider_between(b, [x0, -hd * 0.8, 0.2], [x1, hd * 0.8, lid - 0.1]);
        let n = ((hd * 1.6) / 0.06) as usize;
        for k in 0..n {
            let y = -hd * 0.8 + (hd * 1.6) * (k as f64 + 0.5) / n as f64;
            decal_between(b, [x0, y - 0.008, 0.2], [x1, y + 0.008, lid - 0.1], fins);
        }
        slab(b, [x0, -hd * 0.8, lid - 0.16], [x1, hd * 0.8, lid - 0.12], fins);
    }
    // Three bushings on the lid.
    let bh = h - lid;
    for k in 0..3 {
        let x = -tx * 0.5 + tx * 0.5 * k as f64;
        let mut prof = vec![[0.0, 0.0], [0.06, 0.0]];
        let sheds = 4;
        for s in 0..sheds {
            let z = bh * (0.15 + 0.75 * s as f64 / sheds as f64);
            prof.extend([[0.045, z], [0.09, z + 0.02], [0.09, z + 0.035], [0.045, z + 0.06]]);
        }
        prof.extend([[0.03, bh - 0.02], [0.03, bh], [0.0, bh]]);
        b.visual_mesh_on(0, &revolve(&prof, 16), Pose::from_pos([x, -hd * 0.3, lid]), porcelain);
        b.collision_on(
            0,
            sw_geom::Shape::Cylinder { radius: 0.07, half_height: bh / 2.0 },
            Pose::from_pos([x, -hd * 0.3, lid + bh / 2.0]),
        );
    }
    decal_between(b, [-0.15, hd - 0.001, lid * 0.5], [0.15, hd + 0.002, lid * 0.5 + 0.2], ink);
    warning_sign(b, 0.0, lid * 0.78, hd, 0.2f64.min(w * 0.1), yellow, ink);
    b.surface("lid", top, [tx * 0.2, -hd], [tx, -hd * 0.3 - 0.08], None);
    0.0
}

pub(crate) const COOLING_UNIT: Category = Category {
    name: "cooling_unit",
    display: "cooling unit",
    synonyms: &["crac unit", "computer room air conditioner", "hvac unit", "air handler", "in-row cooler", "chiller"],
    tags: &["data_centre", "utility", "tall", "ventilation"],
    description: "a computer room cooling unit",
    is_a: &["hvac", "equipment"],
    kind: Kind::Machine,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.7, 0.3, 2.6, 0.15, "along X"),
        ParamDef::new("depth", 0.9, 0.6, 1.1, 0.06, "along Y"),
        ParamDef::new("height", 1.95, 1.8, 2.3, 0.03, "floor to top"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_cooling_unit,
};

/// A tall cabinet with removable front panels, louvred air grilles top and bottom and a
/// display.
fn build_cooling_unit(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(rng, &[[0.9, 0.9, 0.88, 1.0], [0.82, 0.83, 0.84, 1.0], [0.2, 0.21, 0.23, 1.0]]);
    let body = b.material("body", paint, true);
    let grille = b.material("grilles", shade(paint, 0.55), false);
    let ink = b.material("display", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top = slab(b, [-hw, -hd, 0.0], [hw, hd, h], body);
    let n = ((w / 0.6).round() as usize).max(1);
    let pw = w / n as f64;
    for k in 0..n {
        let x0 = -hw + pw * k as f64 + 0.01;
        let x1 = x0 + pw - 0.02;
        for (z0, z1) in [(0.1, h * 0.3), (h * 0.72, h - 0.08)] {
            let rows = ((z1 - z0) / 0.035) as usize;
            for r in 0..rows {
                let z = z0 + r as f64 * 0.035;
                decal_between(b, [x0 + 0.03, hd - 0.001, z], [x1 - 0.03, hd + 0.003, z + 0.018], grille);
            }
        }
        decal_between(b, [x0, hd - 0.0005, h * 0.31], [x1, hd + 0.001, h * 0.71], body);
    }
    decal_between(
        b,
        [-hw + 0.05, hd + 0.001, h * 0.6],
        [-hw + 0.05 + 0.15f64.min(w * 0.4), hd + 0.0025, h * 0.66],
        ink,
    );
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    0.0
}

pub(crate) const CABLE_TRAY: Category = Category {
    name: "cable_tray",
    display: "cable tray",
    synonyms: &["cable ladder", "cable rack", "wire tray", "cable trunking", "cable runway", "cable management tray"],
    tags: &["electrical", "data_centre", "industrial", "wall"],
    description: "a cable tray carrying cables overhead",
    is_a: &["tray"],
    kind: Kind::Fixture,
    placement: PlacementKind::WallMounted,
    params: &[
        ParamDef::new("width", 3.0, 1.0, 6.0, 0.2, "run length along X"),
        ParamDef::new("depth", 0.35, 0.15, 0.65, 0.12, "off the wall, brackets included"),
        ParamDef::new("height", 0.1, 0.05, 0.15, 0.15, "side rail height"),
        ParamDef::new("mount_height", 2.2, 1.5, 2.6, 0.05, "floor to the bottom of the tray"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_cable_tray,
};

/// A ladder-type tray (two side rails, rungs every 30 cm) on wall brackets, with cable
/// bundles lying in it. Its origin is on the floor; the tray hangs at `mount_height`.
fn build_cable_tray(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let z0 = p.get("mount_height");
    let steel =
        b.material("steel", pick(rng, &[[0.7, 0.71, 0.73, 1.0], [0.85, 0.6, 0.15, 1.0], [0.3, 0.31, 0.33, 1.0]]), true);
    let bracket = b.material("brackets", [0.45, 0.46, 0.48, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let wall_gap = 0.05f64.min(d * 0.2);
    let (y0, y1) = (-hd + wall_gap, hd);
    let rail = 0.004;
    // Wall brackets every 1.5 m: a plate on the wall and an arm under the tray.
    let arm = 0.01;
    let nb = (w / 1.5).ceil().max(1.0) as usize;
    for k in 0..nb {
        let x = -hw + w * (k as f64 + 0.5) / nb as f64;
        slab(b, [x - 0.02, -hd, z0], [x + 0.02, y1 - 0.01, z0 + arm], bracket);
        slab(b, [x - 0.02, -hd, z0 + arm * 0.5], [x + 0.02, -hd + 0.01, z0 + h], bracket);
    }
    let zt = z0 + arm;
    for (ya, yb) in [(y0, y0 + rail), (y1 - rail, y1)] {
        slab(b, [-hw, ya, zt], [hw, yb, z0 + h], steel);
    }
    let n = (w / 0.3).floor().max(2.0) as usize;
    for k in 0..=n {
        let x = -hw + 0.02 + (w - 0.04) * k as f64 / n as f64;
        slab(b, [x - 0.015, y0 + rail * 0.5, zt], [x + 0.015, y1 - rail * 0.5, zt + 0.012], steel);
    }
    // Cable bundles in the tray (visual: cables are not things to collide with).
    let colors = [[0.1, 0.1, 0.11, 1.0], [0.15, 0.3, 0.7, 1.0], [0.85, 0.75, 0.2, 1.0], [0.8, 0.2, 0.15, 1.0]];
    let cables = b.material("cables", pick(rng, &colors), false);
    let m = (((y1 - y0) / 0.05) as usize).clamp(1, 6);
    for k in 0..m {
        let y = y0 + 0.03 + (y1 - y0 - 0.06) * (k as f64 + 0.5) / m as f64;
        rod(b, [0.0, y, zt + 0.012 + 0.015], 0.015, w - 0.01, Axis::X, cables);
    }
    0.0
}
