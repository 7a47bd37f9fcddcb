//! Boxes, crates, bins, pallets: the things that get stacked and carried.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::kit::{
    CARDBOARD, INK, LABEL_WHITE, PLASTIC, WOOD, block, collider_between, decal, decal_between, fit, ordered, pick,
    shade, slab,
};
use super::parts::{open_box, round_collider, vessel_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const CARDBOARD_BOX: Category = Category {
    name: "cardboard_box",
    display: "cardboard box",
    synonyms: &["box", "carton", "parcel", "package", "shipping box", "moving box"],
    tags: &["warehouse", "container", "small", "stackable", "logistics"],
    description: "a corrugated cardboard shipping box with taped flaps",
    is_a: &["box", "container", "package"],
    kind: Kind::Container,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.4, 0.05, 1.2, 0.25, "along X"),
        ParamDef::new("depth", 0.3, 0.05, 1.0, 0.25, "along Y"),
        ParamDef::new("height", 0.3, 0.05, 1.0, 0.25, "along Z"),
        ParamDef::new("fill_density", 90.0, 10.0, 400.0, 0.5, "mass per box volume, kg/m³"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_cardboard_box,
};

fn build_cardboard_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body = b.material("cardboard", pick(rng, CARDBOARD), true);
    let tape = b.material("tape", [0.55, 0.42, 0.27, 1.0], false);
    block(b, [0.0, 0.0, h / 2.0], [w, d, h], body);
    // Packing tape over the top seam and down both ends.
    let tape_w = (w.min(d) * 0.18).min(0.05);
    decal(b, [0.0, 0.0, h + 0.0008], [w + 0.002, tape_w, 0.0016], tape);
    for sx in [-1.0, 1.0] {
        decal(b, [sx * (w / 2.0 + 0.0008), 0.0, h - 0.04], [0.0016, tape_w, 0.08f64.min(h * 0.5)], tape);
    }
    b.surface("top", h, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    (w * d * h * p.get("fill_density")).max(0.1)
}

pub(crate) const CRATE: Category = Category {
    name: "crate",
    display: "crate",
    synonyms: &[
        "shipping crate",
        "wooden crate",
        "plastic crate",
        "storage crate",
        "stacking crate",
        "transport crate",
        "euro container",
        "lidded crate",
    ],
    tags: &["warehouse", "logistics", "retail", "container", "small", "stackable"],
    description: "a stackable plastic or wooden crate for carrying goods",
    is_a: &["container", "box"],
    kind: Kind::Container,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.6, 0.2, 1.2, 0.15, "along X"),
        ParamDef::new("depth", 0.4, 0.15, 1.0, 0.15, "along Y"),
        ParamDef::new("height", 0.32, 0.1, 1.0, 0.2, "along Z, lid included"),
        ParamDef::new("fill_density", 150.0, 0.0, 500.0, 0.5, "mass of the contents per crate volume, kg/m³"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_crate,
};

/// A closed crate is convex: one collision box. Plastic crates get a rim, hand holds and
/// a label holder; wooden ones corner battens and slat seams.
fn build_crate(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let wooden = rng.chance(0.35);
    let body_rgba = if wooden { pick(rng, WOOD) } else { pick(rng, PLASTIC) };
    let body = b.material("body", body_rgba, true);
    let trim = b.material("trim", shade(body_rgba, 0.72), false);
    let ink = b.material("recess", INK, false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], body);

    // Hand holds on both ends.
    let hold_z = (h - 0.07).max(h * 0.6);
    let (hold_d, hold_h) = ((d * 0.4).min(0.12), (h * 0.12).min(0.03));
    for sx in [-1.0, 1.0] {
        let x = sx * w / 2.0;
        decal_between(
            b,
            [x - 0.001, -hold_d / 2.0, hold_z - hold_h / 2.0],
            [x + 0.001, hold_d / 2.0, hold_z + hold_h / 2.0],
            ink,
        );
    }
    let shell_area = 2.0 * (w * d + w * h + d * h);
    let shell_mass = if wooden {
        // Corner battens 3 mm proud, and the seams between the side slats.
        let bat = (w.min(d) * 0.1).min(0.04);
        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
            let (x0, x1) = ordered(sx * (w / 2.0 - bat), sx * (w / 2.0 + 0.003));
            let (y0, y1) = ordered(sy * (d / 2.0 - bat), sy * (d / 2.0 + 0.003));
            decal_between(b, [x0, y0, 0.0], [x1, y1, h], trim);
        }
        let slats = ((h / 0.1).round() as usize).clamp(2, 8);
        for k in 1..slats {
            let z = h * k as f64 / slats as f64;
            decal_between(
                b,
                [-w / 2.0 - 0.001, -d / 2.0 - 0.001, z - 0.003],
                [w / 2.0 + 0.001, d / 2.0 + 0.001, z + 0.003],
                ink,
            );
        }
        shell_area * 6.0 // 12 mm pine
    } else {
        // The lid's rim stands 3 mm proud around the top.
        let rim = (h * 0.1).min(0.03);
        decal_between(
            b,
            [-w / 2.0 - 0.003, -d / 2.0 - 0.003, h - rim - 0.004],
            [w / 2.0 + 0.003, d / 2.0 + 0.003, h - 0.004],
            trim,
        );
        if rng.chance(0.7) {
            let lw = (w * 0.3).min(0.15);
            let lh = (h * 0.25).min(0.06);
            let label = b.material("label", LABEL_WHITE, false);
            let z = (h - rim) * 0.5;
            decal_between(
                b,
                [-lw / 2.0, d / 2.0 - 0.001, z - lh / 2.0],
                [lw / 2.0, d / 2.0 + 0.002, z + lh / 2.0],
                label,
            );
        }
        shell_area * 2.2 // polypropylene, ~2.5 mm walls and ribs
    };
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    shell_mass + w * d * h * p.get("fill_density")
}

pub(crate) const BIN: Category = Category {
    name: "bin",
    display: "bin",
    synonyms: &[
        "tote",
        "tote bin",
        "storage bin",
        "plastic bin",
        "plastic tote",
        "picking bin",
        "parts bin",
        "open bin",
        "tub",
    ],
    tags: &["warehouse", "logistics", "container", "small", "stackable", "open", "tabletop"],
    description: "an open plastic tote bin for parts and picking",
    is_a: &["container", "box", "tub"],
    kind: Kind::Container,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.6, 0.2, 1.0, 0.1, "along X"),
        ParamDef::new("depth", 0.4, 0.15, 0.8, 0.1, "along Y"),
        ParamDef::new("height", 0.3, 0.08, 0.6, 0.2, "along Z"),
        ParamDef::new("wall", 0.01, 0.005, 0.03, 0.2, "wall and bottom thickness"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_bin,
};

/// An open tote ([`open_box`]: it stands on its floor) with a rim band, hand holds and
/// sometimes a label.
fn build_bin(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = fit(b, "bin wall", p.get("wall"), 0.002, w.min(d).min(h) * 0.1);
    let rgba = pick(rng, PLASTIC);
    let body = b.material("body", rgba, true);
    let rim = b.material("rim", shade(rgba, 0.8), false);
    let ink = b.material("hand_hold", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let floor = open_box(b, w, d, h, t, body);

    // A rim band outside the walls at the top, as four strips (a single box would lid it).
    let band = (h * 0.08).min(0.02);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * (hd - 0.002), sy * (hd + 0.003));
        decal_between(b, [-(hw + 0.003), y0, h - band], [hw + 0.003, y1, h], rim);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * (hw - 0.002), sx * (hw + 0.003));
        decal_between(b, [x0, -(hd + 0.002), h - band], [x1, hd + 0.002, h], rim);
        // Hand hold below the rim.
        let (hh, hl) = ((h * 0.12).min(0.03), (d * 0.35).min(0.12));
        let z = h - band - 0.01 - hh / 2.0;
        let (x0, x1) = ordered(sx * (hw - 0.001), sx * (hw + 0.0015));
        decal_between(b, [x0, -hl / 2.0, z - hh / 2.0], [x1, hl / 2.0, z + hh / 2.0], ink);
    }
    if rng.chance(0.6) {
        let label = b.material("label", LABEL_WHITE, false);
        let (lw, lh) = ((w * 0.25).min(0.12), (h * 0.2).min(0.05));
        let z = (h - band) * 0.55;
        decal_between(b, [-lw / 2.0, hd - 0.001, z - lh / 2.0], [lw / 2.0, hd + 0.002, z + lh / 2.0], label);
    }
    b.surface("inside", floor, [-(hw - t), -(hd - t)], [hw - t, hd - t], None);
    // Polypropylene at ~180 kg/m² per metre of wall thickness (ribs included).
    let area = w * d + 2.0 * (w + d) * h;
    (area * 180.0 * t).max(0.05)
}

pub(crate) const PALLET: Category = Category {
    name: "pallet",
    display: "pallet",
    synonyms: &["euro pallet", "eur pallet", "epal pallet", "wooden pallet", "shipping pallet", "skid", "empty pallet"],
    tags: &["warehouse", "logistics", "surface", "stackable", "low"],
    description: "a wooden euro pallet that goods are stacked on for forklifts",
    is_a: &["platform"],
    kind: Kind::Container,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.2, 0.6, 1.4, 0.0, "length along X (EUR: 1.2)"),
        ParamDef::new("depth", 0.8, 0.6, 1.2, 0.0, "width along Y (EUR: 0.8)"),
        ParamDef::new("height", 0.144, 0.1, 0.2, 0.0, "overall height (EUR: 0.144)"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_pallet,
};

/// A EUR pallet scaled to the requested size: three bottom boards along X, nine blocks,
/// three cross boards along Y and five top boards along X (22 + 78 + 22 + 22 mm high).
/// The top deck collides as one board-thick slab; the boards and gaps are visual.
fn build_pallet(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let (sx, sy) = (w / 1.2, d / 0.8);
    let board = h * 22.0 / 144.0;
    let (z1, z2) = (board, board + h * 78.0 / 144.0);
    let z3 = z2 + board;
    let wood = pick(rng, WOOD);
    let aged = rng.chance(0.4);
    let deck_rgba = if aged { shade([0.62, 0.6, 0.55, 1.0], rng.range(0.85, 1.05) as f32) } else { wood };
    let deck = b.material("deck", deck_rgba, true);
    let blocks = b.material("blocks", shade(deck_rgba, 0.8), false);
    let (hw, hd) = (w / 2.0, d / 2.0);

    // Rows along Y (outer 100 mm, middle 145 mm) and columns along X (145 mm).
    let bx = 0.145 * sx;
    let (outer, middle) = (0.1 * sy, 0.145 * sy);
    let rows = [(-hd, -hd + outer), (-middle / 2.0, middle / 2.0), (hd - outer, hd)];
    let cols = [(-hw, -hw + bx), (-bx / 2.0, bx / 2.0), (hw - bx, hw)];
    for &(y0, y1) in &rows {
        slab(b, [-hw, y0, 0.0], [hw, y1, z1], deck);
        for &(x0, x1) in &cols {
            slab(b, [x0, y0, z1], [x1, y1, z2], blocks);
        }
    }
    for &(x0, x1) in &cols {
        slab(b, [x0, -hd, z2], [x1, hd, z3], deck);
    }
    // Top boards: 145, 100, 145, 100, 145 mm with equal gaps.
    let widths = [0.145, 0.1, 0.145, 0.1, 0.145].map(|v| v * sy);
    let gap = (d - widths.iter().sum::<f64>()) / 4.0;
    let mut y = -hd;
    for bw in widths {
        decal_between(b, [-hw, y, z3], [hw, y + bw, h], deck);
        y += bw + gap;
    }
    let top = collider_between(b, [-hw, -hd, z3], [hw, hd, h]);
    // EPAL stamps on the front blocks.
    if rng.chance(0.6) {
        let ink = b.material("stamp", shade(INK, 3.0), false);
        let (sw, sh) = ((bx * 0.6).min(0.08), (z2 - z1) * 0.5);
        for &(x0, x1) in &cols {
            let x = (x0 + x1) / 2.0;
            let z = (z1 + z2) / 2.0;
            decal_between(b, [x - sw / 2.0, hd - 0.001, z - sh / 2.0], [x + sw / 2.0, hd + 0.001, z + sh / 2.0], ink);
        }
    }
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    25.0 * (w * d / 0.96) * (h / 0.144)
}

pub(crate) const DRUM: Category = Category {
    name: "drum",
    display: "drum",
    synonyms: &[
        "barrel",
        "oil drum",
        "steel drum",
        "plastic drum",
        "chemical drum",
        "55 gallon drum",
        "oil barrel",
        "keg",
    ],
    tags: &["warehouse", "industrial", "garage", "logistics", "container", "round", "heavy"],
    description: "a steel or plastic 200 litre drum for oil or chemicals",
    is_a: &["container", "barrel"],
    kind: Kind::Container,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.585, 0.35, 0.7, 0.04, "diameter"),
        ParamDef::new("depth", 0.585, 0.35, 0.7, 0.04, "diameter (as width)"),
        ParamDef::new("height", 0.88, 0.45, 1.0, 0.05, "floor to the top chime"),
        ParamDef::new("fill", 0.5, 0.0, 1.0, 0.8, "how full (for the mass)"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_drum,
};

/// A steel drum with two rolling hoops and chimes, or a blue plastic drum with a
/// moulded rim; bungs on the lid. The lid is the support surface.
fn build_drum(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let plastic = rng.chance(0.3);
    let rgba = if plastic {
        [0.1, 0.3, 0.7, 1.0]
    } else {
        pick(
            rng,
            &[
                [0.12, 0.3, 0.6, 1.0],
                [0.7, 0.1, 0.08, 1.0],
                [0.12, 0.12, 0.13, 1.0],
                [0.2, 0.45, 0.25, 1.0],
                [0.9, 0.7, 0.1, 1.0],
            ],
        )
    };
    let body = b.material("body", rgba, true);
    let rim = b.material("rims", shade(rgba, 0.8), false);
    let bung = b.material("bungs", if plastic { shade(rgba, 0.6) } else { [0.6, 0.61, 0.62, 1.0] }, false);
    let rb = r - 0.008; // shell inside the hoops and chimes
    let chime = (h * 0.02).min(0.015);
    b.visual_mesh_on(
        0,
        &revolve(&[[0.0, chime], [rb, chime], [rb, h - chime], [0.0, h - chime]], ROUND),
        Pose::IDENTITY,
        body,
    );
    // Chimes (top and bottom rims) and, on steel drums, two rolling hoops.
    let mut bands = vec![(0.0, chime + 0.002), (h - chime - 0.002, h)];
    if !plastic {
        for f in [0.33, 0.67] {
            bands.push((h * f - 0.012, h * f + 0.012));
        }
    }
    for (z0, z1) in bands {
        let ring = revolve(&[[rb - 0.004, z0], [r, z0], [r, z1], [rb - 0.004, z1]], ROUND);
        b.visual_mesh_on(0, &ring, Pose::IDENTITY, rim);
    }
    // Bungs on the lid, inside the chime.
    for (x, rr) in [(-r * 0.55, 0.03), (r * 0.6, 0.018)] {
        let m = revolve(
            &[[0.0, h - chime - 0.001], [rr, h - chime - 0.001], [rr, h - chime + 0.008], [0.0, h - chime + 0.008]],
            ROUND,
        );
        b.visual_mesh_on(0, &m, Pose::from_pos([x, 0.0, 0.0]), bung);
    }
    let top = round_collider(b, 0, [0.0, 0.0], r, 0.0, h);
    let a = r / std::f64::consts::SQRT_2 - 1e-6;
    b.surface("top", top, [-a, -a], [a, a], None);
    let empty = if plastic { 9.0 } else { 18.0 } * (w * w * h) / (0.585 * 0.585 * 0.88);
    empty + 180.0 * (w * w * h) / (0.585 * 0.585 * 0.88) * p.get("fill")
}

pub(crate) const TRASH_CAN: Category = Category {
    name: "trash_can",
    display: "trash can",
    synonyms: &[
        "garbage can",
        "waste bin",
        "wastebasket",
        "waste basket",
        "rubbish bin",
        "dustbin",
        "garbage bin",
        "recycling bin",
        "trash bin",
    ],
    tags: &["office", "kitchen", "retail", "hospital", "container", "round", "open", "small"],
    description: "a waste bin for rubbish with an open top",
    is_a: &["container", "bin", "receptacle"],
    kind: Kind::Container,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.4, 0.25, 0.6, 0.12, "rim diameter"),
        ParamDef::new("depth", 0.4, 0.25, 0.6, 0.12, "rim diameter (as width)"),
        ParamDef::new("height", 0.65, 0.3, 1.0, 0.15, "floor to rim"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_trash_can,
};

/// A tapered open can with a rolled rim; things can be dropped inside.
fn build_trash_can(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let rb = r * rng.range(0.78, 0.9);
    let t = 0.006;
    let rgba = pick(
        rng,
        &[
            [0.2, 0.2, 0.22, 1.0],
            [0.6, 0.62, 0.64, 1.0],
            [0.12, 0.35, 0.65, 1.0],
            [0.2, 0.5, 0.25, 1.0],
            [0.9, 0.9, 0.88, 1.0],
        ],
    );
    let body = b.material("body", rgba, true);
    let rim = b.material("rim", shade(rgba, 0.75), false);
    let floor = 0.01;
    let mesh = revolve(
        &[[0.0, 0.0], [rb, 0.0], [r - 0.006, h - 0.02], [r - 0.006 - t, h - 0.02], [rb - t, floor], [0.0, floor]],
        ROUND,
    );
    b.visual_mesh_on(0, &mesh, Pose::IDENTITY, body);
    let band = revolve(&[[r - 0.012, h - 0.025], [r, h - 0.025], [r, h], [r - 0.012, h]], ROUND);
    b.visual_mesh_on(0, &band, Pose::IDENTITY, rim);
    let inside = vessel_collider(b, [0.0, 0.0], rb, r, 0.012, floor, 0.0, h, 16);
    let a = inside.half.min(rb * 0.65);
    b.surface("inside", inside.floor, [-a, -a], [a, a], None);
    (std::f64::consts::PI * r * (r + 2.0 * h) * t * 950.0).max(0.3)
}
