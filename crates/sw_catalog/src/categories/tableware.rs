//! Things on a table that a robot picks: mugs, cups, plates, bowls, bottles, cans and
//! trays. They look round (solids of revolution) and collide as primitives; the open
//! ones collide as a ring of boxes and a floor, so that things can go inside.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::kit::{LABEL_WHITE, PLASTIC, fit, ordered, pick, shade};
use super::parts::{RingBase, open_box, ring_collider, round_collider, vessel_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

/// Glazed ceramics.
const CERAMIC: &[[f32; 4]] = &[
    [0.95, 0.95, 0.93, 1.0],
    [0.16, 0.3, 0.55, 1.0],
    [0.75, 0.2, 0.16, 1.0],
    [0.22, 0.22, 0.24, 1.0],
    [0.93, 0.8, 0.35, 1.0],
    [0.45, 0.62, 0.5, 1.0],
];
/// Printed can bodies.
const CAN_PRINT: &[[f32; 4]] = &[
    [0.8, 0.08, 0.1, 1.0],
    [0.1, 0.25, 0.6, 1.0],
    [0.1, 0.55, 0.25, 1.0],
    [0.95, 0.75, 0.1, 1.0],
    [0.1, 0.1, 0.1, 1.0],
];
const ALUMINIUM: [f32; 4] = [0.78, 0.79, 0.8, 1.0];

pub(crate) const MUG: Category = Category {
    name: "mug",
    display: "mug",
    synonyms: &["coffee mug", "tea mug", "ceramic mug", "coffee cup", "tea cup", "teacup"],
    tags: &["tabletop", "kitchen", "office", "small", "graspable", "handled"],
    description: "a ceramic mug with a handle for coffee or tea",
    is_a: &["cup", "vessel", "drinkware", "crockery"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        // A classic 11 oz mug: an 8 cm body (a Panda's fingers open 8 cm) and a 3.5 cm loop.
        ParamDef::new("width", 0.115, 0.085, 0.18, 0.03, "body diameter plus the handle, along X"),
        ParamDef::new("depth", 0.079, 0.055, 0.1, 0.015, "body diameter (at most width - 3 cm)"),
        ParamDef::new("height", 0.095, 0.07, 0.14, 0.08, "floor to rim"),
        ParamDef::new("wall", 0.005, 0.003, 0.01, 0.15, "wall thickness"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_mug,
};

/// A hollow cylinder with a thick floor and a C handle on the +X side. The body collides
/// as an open ring so a robot can reach in; the handle as one box.
fn build_mug(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = d / 2.0;
    let wall = fit(b, "mug wall", p.get("wall"), 0.002, r * 0.2);
    let glaze = pick(rng, CERAMIC);
    let body = b.material("glaze", glaze, true);
    let inside_rgba = if rng.chance(0.5) { glaze } else { [0.95, 0.95, 0.93, 1.0] };
    let inside = b.material("inside", shade(inside_rgba, 0.97), false);
    let floor = (h * 0.08).max(0.006);
    // The body sits left of centre so that body and handle together are centred.
    let cx = -(w - d) / 2.0;
    let at = Pose::from_pos([cx, 0.0, 0.0]);
    let mesh = revolve(
        &[[0.0, 0.0], [r * 0.9, 0.0], [r, 0.004], [r, h], [r - wall, h], [r - wall, floor], [0.0, floor]],
        ROUND,
    );
    b.visual_mesh_on(0, &mesh, at, body);
    // A thin disc of the inner colour just above the floor (the glaze inside).
    let disc = revolve(
        &[[0.0, floor], [r - wall - 0.0005, floor], [r - wall - 0.0005, floor + 0.0008], [0.0, floor + 0.0008]],
        ROUND,
    );
    b.visual_mesh_on(0, &disc, at, inside);
    vessel_collider(b, [cx, 0.0], r, r, wall, floor, 0.0, h, 16);
    // Handle: two bars out of the wall and an upright joining them, x from r to w - r.
    let reach = w - d;
    let (x0, x1) = (cx + r - wall * 0.5, w / 2.0);
    let (zb, zt) = (h * 0.2, h * 0.82);
    let bar = (h * 0.1).clamp(0.007, 0.012);
    let hy = (d * 0.08).clamp(0.005, 0.008);
    let handle = b.material("handle", glaze, true);
    let (cx0, cx1) = (x1 - bar, x1);
    super::kit::decal_between(b, [x0, -hy, zt - bar], [cx0 + bar * 0.5, hy, zt], handle);
    super::kit::decal_between(b, [x0, -hy, zb], [cx0 + bar * 0.5, hy, zb + bar], handle);
    super::kit::decal_between(b, [cx0, -hy * 0.98, zb + bar * 0.3], [cx1, hy * 0.98, zt - bar * 0.3], handle);
    super::kit::collider_between(b, [cx + r, -hy, zb], [x1, hy, zt]);
    // Stoneware: about 2.3 g/cm³.
    let shell = 2.0 * std::f64::consts::PI * r * h * wall + std::f64::consts::PI * r * r * floor;
    (shell * 2300.0 + reach * h * 0.01 * 2300.0 * 0.3).max(0.1)
}

pub(crate) const CUP: Category = Category {
    name: "cup",
    display: "cup",
    synonyms: &["paper cup", "plastic cup", "drinking cup", "disposable cup", "beverage cup"],
    tags: &["tabletop", "kitchen", "office", "small", "graspable", "round"],
    description: "a paper or plastic drinking cup without a handle",
    is_a: &["vessel", "drinkware", "container"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.08, 0.05, 0.12, 0.08, "rim diameter"),
        ParamDef::new("depth", 0.08, 0.05, 0.12, 0.08, "rim diameter (as width)"),
        ParamDef::new("height", 0.1, 0.06, 0.16, 0.1, "floor to rim"),
        ParamDef::new("taper", 0.72, 0.5, 1.0, 0.08, "bottom diameter over rim diameter"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_cup,
};

/// A tapered open cup with a rolled rim; a sleeve band on paper cups.
fn build_cup(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = w.min(d) / 2.0;
    let rb = r * p.get("taper");
    let wall = 0.0025;
    let paper = rng.chance(0.5);
    let rgba = if paper { pick(rng, &[[0.96, 0.95, 0.92, 1.0], [0.85, 0.75, 0.6, 1.0]]) } else { pick(rng, PLASTIC) };
    let body = b.material("body", rgba, true);
    let floor = 0.004;
    let mesh = revolve(&[[0.0, 0.0], [rb, 0.0], [r, h], [r - wall, h], [rb - wall * 0.8, floor], [0.0, floor]], ROUND);
    b.visual_mesh_on(0, &mesh, Pose::IDENTITY, body);
    if paper {
        // A printed band a third of the way up, 1 mm proud.
        let band = b.material("band", pick(rng, CAN_PRINT), false);
        let (z0, z1) = (h * 0.35, h * 0.6);
        let at = |z: f64| rb + (r - rb) * z / h + 0.001;
        let ring = revolve(&[[at(z0) - 0.002, z0], [at(z0), z0], [at(z1), z1], [at(z1) - 0.002, z1]], ROUND);
        b.visual_mesh_on(0, &ring, Pose::IDENTITY, band);
    }
    vessel_collider(b, [0.0, 0.0], rb, r, wall * 2.0, floor, 0.0, h, 16);
    (0.012 + 2.5 * std::f64::consts::PI * r * h * wall * 900.0).max(0.05)
}

pub(crate) const PLATE: Category = Category {
    name: "plate",
    display: "plate",
    synonyms: &["dinner plate", "dish", "side plate", "ceramic plate", "serving plate"],
    tags: &["tabletop", "kitchen", "small", "graspable", "round"],
    description: "a flat round ceramic dinner plate",
    is_a: &["dish", "tableware", "crockery"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.26, 0.15, 0.32, 0.08, "diameter"),
        ParamDef::new("depth", 0.26, 0.15, 0.32, 0.08, "diameter (as width)"),
        ParamDef::new("height", 0.025, 0.015, 0.04, 0.12, "floor to rim"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_plate,
};

/// A foot ring, a flat well and a sloping rim; the well is the support surface.
fn build_plate(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = w.min(d) / 2.0;
    let well = r * 0.62;
    let t = (h * 0.35).min(0.008);
    let body = b.material("glaze", pick(rng, CERAMIC), true);
    let mesh = revolve(
        &[
            [0.0, 0.0],
            [well * 0.8, 0.0],
            [well * 0.85, h * 0.3],
            [r, h * 0.8],
            [r, h],
            [r - 0.006, h],
            [well, t + h * 0.3],
            [0.0, t + h * 0.3],
        ],
        ROUND,
    );
    b.visual_mesh_on(0, &mesh, Pose::IDENTITY, body);
    // The rim collides as a ring; the well as a disc with its inscribed square on top.
    let inside = vessel_collider(b, [0.0, 0.0], well, r, r - well, t + h * 0.3, 0.0, h, 16);
    let a = inside.half.min(well * 0.7);
    b.surface("top", inside.floor, [-a, -a], [a, a], None);
    (std::f64::consts::PI * r * r * t * 2300.0).max(0.1)
}

pub(crate) const BOWL: Category = Category {
    name: "bowl",
    display: "bowl",
    synonyms: &["soup bowl", "cereal bowl", "mixing bowl", "salad bowl", "ceramic bowl", "fruit bowl"],
    tags: &["tabletop", "kitchen", "small", "container", "open", "graspable", "round"],
    description: "a round open ceramic bowl for soup, cereal or fruit",
    is_a: &["dish", "vessel", "tableware", "crockery", "container"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.16, 0.1, 0.3, 0.1, "rim diameter"),
        ParamDef::new("depth", 0.16, 0.1, 0.3, 0.1, "rim diameter (as width)"),
        ParamDef::new("height", 0.07, 0.04, 0.14, 0.12, "floor to rim"),
        ParamDef::new("foot", 0.5, 0.35, 0.7, 0.1, "foot diameter over rim diameter"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_bowl,
};

/// A curved bowl on a foot ring. Collision: a floor as wide as the low ring's inside and
/// two rings of wall boxes, a narrow one low down and the rim ring above it, so the inside
/// stays open.
fn build_bowl(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = w.min(d) / 2.0;
    let rf = r * p.get("foot");
    let t = 0.005;
    let body = b.material("glaze", pick(rng, CERAMIC), true);
    // Outer curve from the foot to the rim, then the inner curve back down.
    let mut prof = vec![[0.0, 0.0], [rf, 0.0], [rf, h * 0.08]];
    let steps = 6;
    let curve = |k: usize, inset: f64| {
        let s = k as f64 / steps as f64; // 0 at the bottom, 1 at the rim
        let a = s * std::f64::consts::FRAC_PI_2;
        [rf + (r - rf) * a.sin() - inset, h * 0.08 + (h * 0.92) * (1.0 - a.cos())]
    };
    for k in 1..=steps {
        prof.push(curve(k, 0.0));
    }
    for k in (1..=steps).rev() {
        let [x, z] = curve(k, t);
        prof.push([x, z.max(h * 0.08 + t)]);
    }
    prof.push([0.0, h * 0.08 + t]);
    prof.dedup();
    b.visual_mesh_on(0, &revolve(&prof, ROUND), Pose::IDENTITY, body);
    // The rim ring above a narrower ring from the floor up, both inside the curve.
    // The floor reaches the lower ring's inside (not only the foot), so that the support
    // inside is as wide as the bowl's flat bottom: a 16 cm bowl takes a 5 cm cube, a
    // 30 cm one 14 cm of things (the foot alone gave 10 cm in the widest bowl).
    let (_, upper) = ring_collider(b, [0.0, 0.0], r, t * 2.0, h * 0.45, h, 16, RingBase::Flat);
    let r_low = rf + (r - rf) * 0.45;
    let lower = vessel_collider(b, [0.0, 0.0], r_low, r_low, t * 2.0, h * 0.08 + t, 0.0, h * 0.45, 16);
    let a = lower.half.min(upper);
    b.surface("inside", lower.floor, [-a, -a], [a, a], None);
    let area = std::f64::consts::PI * (r * r + 2.0 * r * h);
    (area * t * 2300.0).max(0.08)
}

pub(crate) const BOTTLE: Category = Category {
    name: "bottle",
    display: "bottle",
    synonyms: &["water bottle", "plastic bottle", "glass bottle", "drink bottle", "soda bottle", "wine bottle"],
    tags: &["tabletop", "kitchen", "office", "lab", "small", "graspable", "round"],
    description: "a bottle with a narrow neck and a cap for water or drinks",
    is_a: &["container", "vessel"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.07, 0.04, 0.12, 0.1, "body diameter"),
        ParamDef::new("depth", 0.07, 0.04, 0.12, 0.1, "body diameter (as width)"),
        ParamDef::new("height", 0.23, 0.12, 0.38, 0.12, "floor to the top of the cap"),
        ParamDef::new("fill", 0.8, 0.0, 1.0, 0.2, "how full (for the mass)"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_bottle,
};

/// A round body, a shoulder, a neck and a cap. Collides as the body and the neck.
fn build_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = w.min(d) / 2.0;
    let rn = (r * 0.38).max(0.012).min(r * 0.8);
    let (z_body, z_neck) = (h * rng.range(0.55, 0.68), h * 0.82);
    let cap_h = (h * 0.06).max(0.012);
    let glass = rng.chance(0.4);
    let tint = if glass {
        pick(rng, &[[0.25, 0.45, 0.3, 1.0], [0.45, 0.3, 0.15, 1.0], [0.75, 0.85, 0.85, 1.0]])
    } else {
        pick(rng, &[[0.6, 0.8, 0.95, 1.0], [0.82, 0.9, 0.95, 1.0], [0.9, 0.9, 0.88, 1.0]])
    };
    let body = b.material("body", tint, true);
    let cap = b.material("cap", pick(rng, PLASTIC), false);
    let label = b.material("label", pick(rng, &[LABEL_WHITE, [0.85, 0.15, 0.12, 1.0], [0.15, 0.3, 0.6, 1.0]]), false);
    let top = h - cap_h;
    let mesh = revolve(
        &[
            [0.0, 0.0],
            [r * 0.9, 0.0],
            [r, r * 0.1],
            [r, z_body],
            [rn * 1.05, z_neck],
            [rn, z_neck + 0.01],
            [rn, top],
            [0.0, top],
        ],
        ROUND,
    );
    b.visual_mesh_on(0, &mesh, Pose::IDENTITY, body);
    let capm = revolve(&[[0.0, top - 0.004], [rn + 0.0015, top - 0.004], [rn + 0.0015, h], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &capm, Pose::IDENTITY, cap);
    let (l0, l1) = (z_body * 0.35, z_body * 0.8);
    let band = revolve(&[[r - 0.001, l0], [r + 0.0008, l0], [r + 0.0008, l1], [r - 0.001, l1]], ROUND);
    b.visual_mesh_on(0, &band, Pose::IDENTITY, label);
    round_collider(b, 0, [0.0, 0.0], r, 0.0, z_body);
    b.collision_on(
        0,
        sw_geom::Shape::Cylinder { radius: rn + 0.0015, half_height: (h - z_body) / 2.0 },
        Pose::from_pos([0.0, 0.0, (z_body + h) / 2.0]),
    );
    // Shoulder: a shorter, wider cylinder so the collision follows the taper.
    b.collision_on(
        0,
        sw_geom::Shape::Cylinder { radius: (r + rn) / 2.0, half_height: (z_neck - z_body) / 2.0 },
        Pose::from_pos([0.0, 0.0, (z_body + z_neck) / 2.0]),
    );
    let volume = std::f64::consts::PI * r * r * z_body;
    let shell = if glass { 0.35 * volume / 0.0008 } else { 0.025 * volume / 0.0008 };
    (shell.min(0.8) + volume * 1000.0 * p.get("fill")).max(0.03)
}

pub(crate) const DRINK_CAN: Category = Category {
    name: "drink_can",
    display: "drink can",
    synonyms: &["soda can", "beer can", "tin can", "cola can", "beverage can", "tin", "can of coke", "can"],
    tags: &["tabletop", "kitchen", "retail", "small", "graspable", "round"],
    description: "a printed aluminium drink can",
    is_a: &["can", "container"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.066, 0.05, 0.1, 0.05, "diameter"),
        ParamDef::new("depth", 0.066, 0.05, 0.1, 0.05, "diameter (as width)"),
        ParamDef::new("height", 0.122, 0.07, 0.17, 0.1, "floor to the lid rim"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_drink_can,
};

/// A printed aluminium body necked in at the top, with a lid rim.
fn build_drink_can(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = w.min(d) / 2.0;
    let print = b.material("print", pick(rng, CAN_PRINT), true);
    let metal = b.material("aluminium", ALUMINIUM, false);
    let (z0, z1) = (0.008f64.min(h * 0.1), h - 0.014f64.min(h * 0.12));
    let body = revolve(&[[0.0, z0], [r, z0], [r, z1], [0.0, z1]], ROUND);
    b.visual_mesh_on(0, &body, Pose::IDENTITY, print);
    let base = revolve(&[[0.0, 0.0], [r * 0.8, 0.0], [r, z0 + 0.0005], [0.0, z0 + 0.0005]], ROUND);
    b.visual_mesh_on(0, &base, Pose::IDENTITY, metal);
    let lid = revolve(&[[0.0, z1 - 0.0005], [r, z1 - 0.0005], [r * 0.84, h - 0.003], [r * 0.84, h], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &lid, Pose::IDENTITY, metal);
    round_collider(b, 0, [0.0, 0.0], r, 0.0, h);
    // A full can: about 1 g per cm³ of its volume.
    (std::f64::consts::PI * r * r * h * 950.0).max(0.02)
}

pub(crate) const TRAY: Category = Category {
    name: "tray",
    display: "tray",
    synonyms: &[
        "serving tray",
        "parts tray",
        "kitting tray",
        "plastic tray",
        "sorting tray",
        "lab tray",
        "cafeteria tray",
    ],
    tags: &["tabletop", "kitchen", "lab", "office", "container", "small", "open"],
    description: "a flat tray with a low rim for carrying parts or food",
    is_a: &["container", "tableware"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.45, 0.2, 0.8, 0.12, "along X"),
        ParamDef::new("depth", 0.32, 0.15, 0.6, 0.12, "along Y"),
        ParamDef::new("height", 0.035, 0.015, 0.1, 0.2, "floor to rim"),
        ParamDef::new("wall", 0.006, 0.003, 0.015, 0.2, "wall and floor thickness"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_tray,
};

/// A flat floor and four low walls ([`open_box`]: it stands on its floor) with a lip band.
fn build_tray(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = fit(b, "tray wall", p.get("wall"), 0.002, h * 0.4);
    let rgba = pick(rng, PLASTIC);
    let body = b.material("body", rgba, true);
    let lip = b.material("lip", shade(rgba, 0.8), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let floor = open_box(b, w, d, h, t, body);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * (hd - 0.001), sy * (hd + 0.002));
        super::kit::decal_between(b, [-(hw + 0.002), y0, h - (h * 0.25).min(0.008)], [hw + 0.002, y1, h], lip);
    }
    b.surface("inside", floor, [-(hw - t), -(hd - t)], [hw - t, hd - t], None);
    ((w * d + 2.0 * (w + d) * h) * t * 1000.0).max(0.05)
}
