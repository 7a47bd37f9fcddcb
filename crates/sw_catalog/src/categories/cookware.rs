//! Cookware, utensils, cutlery and glassware: pans and pots that collide as open vessels
//! (a floor and a ring of wall boxes, so that things go in and they stand on their floor
//! alone), and long things that lie flat on the table as a box per segment.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::forms::{Seg, def, lathe, long_item, whd};
use super::kit::{DARK, WOOD, collider_between, decal_between, pick};
use super::parts::vessel_collider;
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const COOKWARE: &[&str] = &["kitchen", "tabletop", "small", "graspable", "open", "container", "handled"];
const UTENSIL: &[&str] = &["kitchen", "tabletop", "small", "graspable"];
const PAN_METAL: &[[f32; 4]] =
    &[[0.12, 0.12, 0.13, 1.0], [0.72, 0.73, 0.75, 1.0], [0.2, 0.2, 0.22, 1.0], [0.62, 0.3, 0.18, 1.0]];
const HANDLE: &[[f32; 4]] = &[[0.08, 0.08, 0.09, 1.0], [0.45, 0.3, 0.18, 1.0], [0.6, 0.61, 0.63, 1.0]];

/// A round open pan or pot of diameter `d` and height `h` whose body sits at the −X end
/// so that a long handle (to +X, reaching `w`) fits: the body collides as an open vessel,
/// the handle as one raised box. Returns the body's centre X.
fn handled_vessel(b: &mut AssetBuilder, w: f64, d: f64, h: f64, [body, handle]: [usize; 2], handle_z: f64) -> f64 {
    let r = d / 2.0;
    let cx = -w / 2.0 + r;
    let wall = 0.004;
    let floor = 0.005f64.min(h * 0.2);
    let profile = [[0.0, 0.0], [r * 0.85, 0.0], [r, h], [r - wall, h], [r * 0.85 - wall, floor], [0.0, floor]];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), Pose::from_pos([cx, 0.0, 0.0]), body);
    vessel_collider(b, [cx, 0.0], r * 0.85, r, wall * 2.0, floor, 0.0, h, 16);
    let hz = handle_z.min(h - 0.012).max(0.01);
    let x0 = cx + r - 0.004;
    decal_between(b, [x0, -0.011, hz], [w / 2.0, 0.011, hz + 0.012], handle);
    collider_between(b, [cx + r, -0.011, hz], [w / 2.0, 0.011, hz + 0.012]);
    cx
}

pub(crate) const FRYING_PAN: Category = def(
    "frying_pan",
    "frying pan",
    &["skillet", "fry pan", "frypan", "pan", "non-stick pan", "sauté pan", "saute pan", "omelette pan"],
    COOKWARE,
    "a round shallow frying pan with a long handle",
    &["pan", "cookware", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Tefal / Le Creuset 28 cm skillets: 28 cm across, 48–50 cm with the handle, 5 cm deep.
    &[
        ParamDef::new("width", 0.48, 0.3, 0.6, 0.04, "pan and handle along X"),
        ParamDef::new("depth", 0.27, 0.16, 0.32, 0.06, "pan diameter"),
        ParamDef::new("height", 0.05, 0.035, 0.08, 0.1, "floor to rim"),
    ],
    build_frying_pan,
);

fn build_frying_pan(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("pan", pick(rng, PAN_METAL), true);
    let handle = b.material("handle", pick(rng, HANDLE), false);
    handled_vessel(b, w, d, h, [body, handle], h * 0.7);
    0.4 + d * d * 12.0
}

pub(crate) const SAUCEPAN: Category = def(
    "saucepan",
    "saucepan",
    &["sauce pan", "cooking pan", "milk pan", "small pot"],
    COOKWARE,
    "a deep round saucepan with a single long handle",
    &["pan", "pot", "cookware", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 16–20 cm saucepans (1.5–2.5 l): 36–40 cm with the handle, 9–11 cm deep.
    &[
        ParamDef::new("width", 0.37, 0.25, 0.45, 0.04, "pan and handle along X"),
        ParamDef::new("depth", 0.18, 0.12, 0.24, 0.06, "pan diameter"),
        ParamDef::new("height", 0.1, 0.06, 0.15, 0.08, "floor to rim"),
    ],
    build_saucepan,
);

fn build_saucepan(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("pan", pick(rng, PAN_METAL), true);
    let handle = b.material("handle", pick(rng, HANDLE), false);
    handled_vessel(b, w, d, h, [body, handle], h * 0.75);
    0.5 + d * d * h * 60.0
}

pub(crate) const STOCK_POT: Category = def(
    "stock_pot",
    "stock pot",
    &["stockpot", "cooking pot", "pot", "soup pot", "casserole", "dutch oven", "cauldron"],
    &["kitchen", "tabletop", "small", "graspable", "open", "container", "handled"],
    "a tall round cooking pot with two side handles",
    &["pot", "cookware", "kitchenware", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 24–28 cm stock pots (6–10 l): 24–28 cm across, 18–24 cm tall.
    &[
        ParamDef::new("width", 0.32, 0.22, 0.44, 0.06, "across the handles"),
        ParamDef::new("depth", 0.26, 0.16, 0.36, 0.06, "pot diameter"),
        ParamDef::new("height", 0.2, 0.1, 0.32, 0.1, "floor to rim"),
    ],
    build_stock_pot,
);

fn build_stock_pot(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let r = w / 2.0;
    let body = b.material("pot", pick(rng, PAN_METAL), true);
    let handle = b.material("handles", pick(rng, DARK), false);
    let wall = 0.004;
    let rb = d / 2.0;
    let profile = [[0.0, 0.0], [rb, 0.0], [rb, h], [rb - wall, h], [rb - wall, 0.006], [0.0, 0.006]];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), Pose::IDENTITY, body);
    vessel_collider(b, [0.0, 0.0], rb, rb, wall * 2.0, 0.006, 0.0, h, 16);
    for s in [-1.0, 1.0] {
        let (x0, x1) = if s < 0.0 { (-r, -rb + 0.002) } else { (rb - 0.002, r) };
        decal_between(b, [x0, -0.03, h * 0.8], [x1, 0.03, h * 0.8 + 0.012], handle);
        collider_between(b, [x0, -0.03, h * 0.8], [x1, 0.03, h * 0.8 + 0.012]);
    }
    0.9 + r * r * h * 40.0
}

pub(crate) const WOK: Category = def(
    "wok",
    "wok",
    &["stir-fry pan", "stir fry pan", "carbon steel wok"],
    COOKWARE,
    "a deep round-bottomed wok with a long handle",
    &["pan", "cookware", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 30–36 cm carbon-steel woks: 55–60 cm with the handle, 9–11 cm deep.
    &[
        ParamDef::new("width", 0.55, 0.35, 0.65, 0.04, "wok and handle along X"),
        ParamDef::new("depth", 0.32, 0.22, 0.38, 0.05, "wok diameter"),
        ParamDef::new("height", 0.1, 0.07, 0.13, 0.08, "floor to rim"),
    ],
    build_wok,
);

fn build_wok(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("wok", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.3, 0.28, 0.26, 1.0]]), true);
    let handle = b.material("handle", pick(rng, WOOD), false);
    let r = d / 2.0;
    let cx = -w / 2.0 + r;
    let t = 0.003;
    let mut prof = vec![[0.0, 0.0], [r * 0.35, 0.0]];
    for k in 1..=5 {
        let a = f64::from(k) / 5.0 * std::f64::consts::FRAC_PI_2;
        prof.push([r * 0.35 + r * 0.65 * a.sin(), h * (1.0 - a.cos())]);
    }
    for k in (1..=5).rev() {
        let a = f64::from(k) / 5.0 * std::f64::consts::FRAC_PI_2;
        prof.push([(r * 0.35 + r * 0.65 * a.sin() - t).max(0.001), (h * (1.0 - a.cos())).max(t)]);
    }
    prof.push([0.0, t]);
    prof.dedup();
    b.visual_mesh_on(0, &revolve(&prof, ROUND), Pose::from_pos([cx, 0.0, 0.0]), body);
    vessel_collider(b, [cx, 0.0], r * 0.35, r, 0.01, 0.004, 0.0, h, 16);
    decal_between(b, [cx + r - 0.004, -0.013, h * 0.75], [w / 2.0, 0.013, h * 0.75 + 0.018], handle);
    collider_between(b, [cx + r, -0.013, h * 0.75], [w / 2.0, 0.013, h * 0.75 + 0.018]);
    1.2
}

pub(crate) const CUTTING_BOARD: Category = def(
    "cutting_board",
    "cutting board",
    &["chopping board", "chopping block", "bread board", "carving board", "wooden board"],
    &["kitchen", "tabletop", "small", "graspable", "surface"],
    "a flat wooden or plastic chopping board",
    &["board", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // IKEA PROPPMÄTT 38 × 30 × 2 cm; plastic boards 30–45 × 20–30 × 1–2 cm.
    &[
        ParamDef::new("width", 0.38, 0.25, 0.5, 0.1, "along X"),
        ParamDef::new("depth", 0.27, 0.18, 0.35, 0.08, "along Y"),
        ParamDef::new("height", 0.02, 0.01, 0.04, 0.12, "thickness"),
    ],
    build_cutting_board,
);

fn build_cutting_board(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wooden = rng.chance(0.6);
    let rgba = if wooden {
        pick(rng, WOOD)
    } else {
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.3, 0.6, 0.35, 1.0], [0.8, 0.25, 0.2, 1.0]])
    };
    let board = b.material("board", rgba, true);
    let top = super::forms::rounded_box(b, [0.0, 0.0], w, d, 0.0, h, 0.015, board);
    b.surface("top", top, [-w / 2.0 + 0.02, -d / 2.0 + 0.02], [w / 2.0 - 0.02, d / 2.0 - 0.02], None);
    w * d * h * if wooden { 650.0 } else { 950.0 }
}

/// A utensil's handle along +X from `x0` to the end of the width (`w / 2`).
fn handle_seg(w: f64, x0: f64, width: f64, height: f64, m: usize) -> Seg {
    Seg::flat(x0, w / 2.0, width, height, m)
}

pub(crate) const CHEFS_KNIFE: Category = def(
    "chefs_knife",
    "chef's knife",
    &[
        "kitchen knife",
        "cook's knife",
        "chef knife",
        "bread knife",
        "carving knife",
        "paring knife",
        "cleaver",
        "butcher knife",
    ],
    UTENSIL,
    "a kitchen knife with a broad steel blade and a handle",
    &["knife", "utensil", "kitchenware", "blade"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 20 cm (8") chef's knives: 33 cm long, 4.5–5 cm blade height, 2 cm handle.
    &[
        ParamDef::new("width", 0.33, 0.2, 0.45, 0.08, "length"),
        ParamDef::new("depth", 0.045, 0.025, 0.07, 0.1, "blade height (lying flat)"),
        ParamDef::new("height", 0.02, 0.014, 0.028, 0.08, "handle thickness"),
    ],
    build_chefs_knife,
);

fn build_chefs_knife(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("blade", [0.82, 0.83, 0.85, 1.0], false);
    let grip = b.material("handle", pick(rng, HANDLE), true);
    let split = w / 2.0 - w * 0.36;
    long_item(b, &[Seg::flat(-w / 2.0, split + 0.002, d, 0.003, steel), handle_seg(w, split, d * 0.5, h, grip)]);
    0.2
}

pub(crate) const TABLE_KNIFE: Category = def(
    "table_knife",
    "table knife",
    &["knife", "butter knife", "dinner knife", "steak knife", "cutlery knife"],
    UTENSIL,
    "a table knife from a cutlery set",
    &["knife", "cutlery", "utensil"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Dinner knives: 22–24 cm long, 2 cm wide.
    &[
        ParamDef::new("width", 0.225, 0.16, 0.26, 0.04, "length"),
        ParamDef::new("depth", 0.02, 0.014, 0.026, 0.08, "width"),
        ParamDef::new("height", 0.012, 0.008, 0.016, 0.1, "handle thickness"),
    ],
    build_table_knife,
);

fn build_table_knife(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("steel", pick(rng, &[[0.8, 0.81, 0.83, 1.0], [0.72, 0.62, 0.35, 1.0]]), true);
    let grip =
        b.material("grip", pick(rng, &[[0.8, 0.81, 0.83, 1.0], [0.1, 0.1, 0.1, 1.0], [0.95, 0.94, 0.9, 1.0]]), false);
    let split = w / 2.0 - w * 0.45;
    long_item(b, &[Seg::flat(-w / 2.0, split + 0.002, d * 0.85, 0.003, steel), handle_seg(w, split, d, h, grip)]);
    0.06
}

pub(crate) const FORK: Category = def(
    "fork",
    "fork",
    &["dinner fork", "table fork", "dessert fork", "salad fork"],
    UTENSIL,
    "a table fork with four tines",
    &["cutlery", "utensil"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Dinner forks: 19–21 cm long, 2.5 cm across the tines.
    &[
        ParamDef::new("width", 0.2, 0.14, 0.24, 0.04, "length"),
        ParamDef::new("depth", 0.025, 0.018, 0.032, 0.06, "across the tines"),
        ParamDef::new("height", 0.012, 0.008, 0.018, 0.1, "thickness"),
    ],
    build_fork,
);

fn build_fork(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("steel", pick(rng, &[[0.8, 0.81, 0.83, 1.0], [0.72, 0.62, 0.35, 1.0]]), true);
    let head = w * 0.3;
    let x0 = -w / 2.0;
    // Four tines, then the neck and the handle.
    for k in 0..4 {
        let y = -d / 2.0 + d * (0.125 + 0.25 * f64::from(k));
        decal_between(b, [x0, y - d * 0.06, 0.0], [x0 + head * 0.6, y + d * 0.06, h * 0.4], steel);
    }
    decal_between(b, [x0 + head * 0.6 - 0.002, -d / 2.0, 0.0], [x0 + head, d / 2.0, h * 0.4], steel);
    collider_between(b, [x0, -d / 2.0, 0.0], [x0 + head, d / 2.0, h * 0.4]);
    long_item(b, &[Seg::flat(x0 + head - 0.001, w / 2.0, d * 0.4, h, steel)]);
    0.045
}

pub(crate) const SPOON: Category = def(
    "spoon",
    "spoon",
    &["tablespoon", "teaspoon", "soup spoon", "dessert spoon", "serving spoon", "wooden spoon", "soupspoon"],
    UTENSIL,
    "a spoon with an oval bowl and a handle",
    &["cutlery", "utensil"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Tablespoons 18–20 cm, 4 cm bowl; teaspoons 13–15 cm.
    &[
        ParamDef::new("width", 0.19, 0.12, 0.32, 0.05, "length"),
        ParamDef::new("depth", 0.04, 0.025, 0.06, 0.06, "bowl width"),
        ParamDef::new("height", 0.02, 0.012, 0.03, 0.1, "bowl depth"),
    ],
    build_spoon,
);

fn build_spoon(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wooden = w > 0.26 && rng.chance(0.5);
    let rgba = if wooden { pick(rng, WOOD) } else { pick(rng, &[[0.8, 0.81, 0.83, 1.0], [0.72, 0.62, 0.35, 1.0]]) };
    let steel = b.material("spoon", rgba, true);
    let r = d / 2.0;
    let bowl_len = (w * 0.32).max(d);
    let cx = -w / 2.0 + bowl_len / 2.0;
    let bowl = revolve(&[[0.0, 0.0], [r * 0.6, 0.0], [r, h], [0.0, h]], ROUND);
    let mut m = bowl;
    for v in &mut m.vertices {
        v[0] *= (bowl_len / d) as f32;
    }
    b.visual_mesh_on(0, &m, Pose::from_pos([cx, 0.0, 0.0]), steel);
    collider_between(b, [-w / 2.0, -r, 0.0], [-w / 2.0 + bowl_len, r, h]);
    long_item(b, &[Seg::flat(-w / 2.0 + bowl_len - 0.002, w / 2.0, d * 0.3, h * 0.45, steel)]);
    if wooden { 0.04 } else { 0.05 }
}

/// A kitchen utensil: a head at −X (`head` long, `d` wide, `h_head` thick) on a handle.
#[allow(clippy::too_many_arguments)]
fn utensil(b: &mut AssetBuilder, w: f64, d: f64, h: f64, head: f64, h_head: f64, [hm, gm]: [usize; 2]) {
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + head + 0.002, d, h_head, hm),
            Seg::flat(-w / 2.0 + head, w / 2.0, (d * 0.3).max(0.012), h, gm),
        ],
    );
}

pub(crate) const SPATULA: Category = def(
    "spatula",
    "spatula",
    &["turner", "fish slice", "egg flip", "pancake turner", "flipper", "spatula turner"],
    UTENSIL,
    "a kitchen turner: a flat slotted blade on a long handle",
    &["utensil", "kitchenware"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // OXO / Joseph Joseph turners: 30–35 cm long, 7–9 cm blade.
    &[
        ParamDef::new("width", 0.33, 0.22, 0.4, 0.05, "length"),
        ParamDef::new("depth", 0.08, 0.05, 0.1, 0.08, "blade width"),
        ParamDef::new("height", 0.02, 0.012, 0.03, 0.1, "handle thickness"),
    ],
    build_spatula,
);

fn build_spatula(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let head = b.material("blade", pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.8, 0.81, 0.83, 1.0]]), true);
    let grip = b.material("handle", pick(rng, HANDLE), false);
    utensil(b, w, d, h, w * 0.32, 0.004, [head, grip]);
    0.08
}

pub(crate) const LADLE: Category = def(
    "ladle",
    "ladle",
    &["soup ladle", "serving ladle", "dipper"],
    UTENSIL,
    "a soup ladle: a deep round cup on a long handle",
    &["utensil", "spoon", "kitchenware"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Ladles: 28–33 cm long, 8–9 cm bowl, 5 cm deep.
    &[
        ParamDef::new("width", 0.31, 0.22, 0.38, 0.05, "length"),
        ParamDef::new("depth", 0.085, 0.06, 0.1, 0.06, "bowl diameter"),
        ParamDef::new("height", 0.05, 0.035, 0.07, 0.08, "bowl depth"),
    ],
    build_ladle,
);

fn build_ladle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("ladle", pick(rng, &[[0.8, 0.81, 0.83, 1.0], [0.12, 0.12, 0.13, 1.0]]), true);
    let r = d / 2.0;
    let cx = -w / 2.0 + r;
    let bowl = [
        [0.0, 0.0],
        [r * 0.5, 0.0],
        [r, h * 0.6],
        [r, h],
        [r - 0.002, h],
        [r - 0.002, h * 0.6],
        [r * 0.5 - 0.002, 0.002],
        [0.0, 0.002],
    ];
    b.visual_mesh_on(0, &revolve(&bowl, ROUND), Pose::from_pos([cx, 0.0, 0.0]), steel);
    vessel_collider(b, [cx, 0.0], r * 0.5, r, 0.006, 0.002, 0.0, h, 8);
    // The handle slopes from the rim down to the table, where its end rests.
    let (x0, x1) = (cx + r - 0.003, w / 2.0 - 0.004);
    super::kit::strut(b, [x0, 0.0, h - 0.005], [x1, 0.0, 0.004], [0.006, 0.012], super::kit::Axis::Y, steel, true);
    collider_between(b, [x1 - 0.004, -0.006, 0.0], [w / 2.0, 0.006, 0.008]);
    0.12
}

pub(crate) const WHISK: Category = def(
    "whisk",
    "whisk",
    &["balloon whisk", "egg whisk", "wire whisk", "egg beater", "eggbeater", "rotary whisk"],
    UTENSIL,
    "a balloon whisk: loops of wire on a handle",
    &["utensil", "kitchenware"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Balloon whisks: 25–30 cm long, 6–7 cm across.
    &[
        ParamDef::new("width", 0.28, 0.2, 0.35, 0.05, "length"),
        ParamDef::new("depth", 0.065, 0.045, 0.08, 0.06, "across the loops"),
        ParamDef::new("height", 0.065, 0.045, 0.08, 0.06, "across the loops, lying"),
    ],
    build_whisk,
);

fn build_whisk(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wire = b.material("wires", [0.82, 0.83, 0.85, 1.0], true);
    let grip = b.material("handle", pick(rng, HANDLE), false);
    let loops = w * 0.6;
    let x0 = -w / 2.0;
    // The balloon: a prolate solid of thin wires drawn as four flat loops.
    for k in 0..4 {
        let a = f64::from(k) * std::f64::consts::PI / 4.0;
        let ring = revolve(&super::shapes::rounded_ring_profile(0.47, 0.5, -0.0012, 0.0012, 0.0), 12);
        let mut m = ring;
        for v in &mut m.vertices {
            let (x, y, z) = (f64::from(v[0]), f64::from(v[1]), f64::from(v[2]));
            // Unit ring in XY → an ellipse of loops × d, turned about X by a.
            let (lx, ly) = (x * loops, y * d.min(h));
            *v = [lx as f32, (ly * a.cos() - z * a.sin()) as f32, (ly * a.sin() + z * a.cos()) as f32];
        }
        b.visual_mesh_on(0, &m, Pose::from_pos([x0 + loops / 2.0, 0.0, h / 2.0]), wire);
    }
    collider_between(b, [x0, -d / 2.0, 0.0], [x0 + loops, d / 2.0, h]);
    long_item(b, &[Seg::round(x0 + loops - 0.01, w / 2.0, (h * 0.4).min(0.03), grip)]);
    0.09
}

pub(crate) const ROLLING_PIN: Category = def(
    "rolling_pin",
    "rolling pin",
    &["pastry roller", "dough roller", "rolling pin with handles"],
    UTENSIL,
    "a wooden rolling pin with a handle at each end",
    &["utensil", "kitchenware", "pin"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Rolling pins: 43–48 cm long, 5–6 cm barrel.
    &[
        ParamDef::new("width", 0.45, 0.3, 0.55, 0.05, "length"),
        ParamDef::new("depth", 0.058, 0.045, 0.07, 0.05, "barrel diameter"),
        ParamDef::new("height", 0.058, 0.045, 0.07, 0.05, "barrel diameter"),
    ],
    build_rolling_pin,
);

fn build_rolling_pin(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wood = b.material("barrel", pick(rng, WOOD), true);
    let ends = b.material("handles", pick(rng, WOOD), false);
    let hl = w * 0.17;
    // The barrel collides as its box; a flat-bottomed box cannot roll.
    let barrel = Seg { x0: -w / 2.0 + hl, x1: w / 2.0 - hl, width: d, height: h, round: true, material: wood };
    long_item(
        b,
        &[
            Seg::round(-w / 2.0, -w / 2.0 + hl + 0.003, d.min(h) * 0.5, ends),
            barrel,
            Seg::round(w / 2.0 - hl - 0.003, w / 2.0, d.min(h) * 0.5, ends),
        ],
    );
    0.35
}

pub(crate) const COLANDER: Category = def(
    "colander",
    "colander",
    &["strainer", "sieve", "pasta strainer", "drainer basket"],
    &["kitchen", "tabletop", "small", "graspable", "open", "container", "round"],
    "a round perforated colander on a foot ring, with two small handles",
    &["bowl", "kitchenware", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 24–28 cm colanders, 11–13 cm deep.
    &[
        ParamDef::new("width", 0.26, 0.16, 0.32, 0.08, "rim diameter"),
        ParamDef::new("depth", 0.26, 0.16, 0.32, 0.08, "rim diameter (as width)"),
        ParamDef::new("height", 0.12, 0.07, 0.16, 0.08, "floor to rim"),
    ],
    build_colander,
);

fn build_colander(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let body = b.material(
        "colander",
        pick(rng, &[[0.8, 0.81, 0.83, 1.0], [0.85, 0.2, 0.15, 1.0], [0.95, 0.95, 0.94, 1.0], [0.3, 0.6, 0.35, 1.0]]),
        true,
    );
    let holes = b.material("holes", [0.2, 0.2, 0.2, 1.0], false);
    let rf = r * 0.5;
    let t = 0.003;
    let profile = [[0.0, 0.0], [rf, 0.0], [rf, 0.02], [r, h], [r - t, h], [rf - t, 0.02 + t], [0.0, 0.02 + t]];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), Pose::IDENTITY, body);
    // Rings of holes around the wall.
    let band = revolve(
        &[
            [rf + (r - rf) * 0.45, h * 0.45],
            [rf + (r - rf) * 0.45 + 0.0008, h * 0.45],
            [rf + (r - rf) * 0.55 + 0.0008, h * 0.55],
            [rf + (r - rf) * 0.55, h * 0.55],
        ],
        ROUND,
    );
    b.visual_mesh_on(0, &band, Pose::IDENTITY, holes);
    let inside = vessel_collider(b, [0.0, 0.0], rf, r, 0.008, 0.02 + t, 0.0, h, 16);
    let a = inside.half;
    b.surface("inside", inside.floor, [-a, -a], [a, a], None);
    0.3 + r * r * 4.0
}

pub(crate) const MEASURING_CUP: Category = def(
    "measuring_cup",
    "measuring cup",
    &["measuring jug", "measuring glass", "jug for measuring"],
    &["kitchen", "tabletop", "small", "graspable", "open", "container", "handled"],
    "a clear measuring jug with printed marks, a spout and a handle",
    &["cup", "jug", "kitchenware", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Pyrex 500 ml–1 l measuring jugs: 10–12 cm body, 15–17 cm with the handle, 11–15 cm tall.
    &[
        ParamDef::new("width", 0.155, 0.11, 0.2, 0.05, "body, handle and spout along X"),
        ParamDef::new("depth", 0.1, 0.07, 0.13, 0.05, "body diameter"),
        ParamDef::new("height", 0.12, 0.08, 0.16, 0.06, "floor to rim"),
    ],
    build_measuring_cup,
);

fn build_measuring_cup(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let glass = b.material("glass", [0.78, 0.86, 0.9, 1.0], true);
    let marks = b.material("marks", pick(rng, &[[0.8, 0.1, 0.1, 1.0], [0.1, 0.2, 0.6, 1.0]]), false);
    let r = d / 2.0;
    let cx = w / 2.0 - r;
    let t = 0.004;
    let profile = [[0.0, 0.0], [r, 0.0], [r, h], [r - t, h], [r - t, 0.006], [0.0, 0.006]];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), Pose::from_pos([cx, 0.0, 0.0]), glass);
    vessel_collider(b, [cx, 0.0], r, r, t * 2.0, 0.006, 0.0, h, 16);
    for k in 1..=4 {
        let z = h * 0.2 * f64::from(k);
        decal_between(b, [cx - 0.002, r - 0.0005, z], [cx + 0.012, r + 0.0008, z + 0.002], marks);
    }
    decal_between(b, [-w / 2.0, -0.008, h * 0.25], [-w / 2.0 + 0.014, 0.008, h * 0.9], glass);
    decal_between(b, [-w / 2.0 + 0.01, -0.007, h * 0.8], [cx - r + 0.002, 0.007, h * 0.9], glass);
    collider_between(b, [-w / 2.0, -0.008, h * 0.25], [cx - r, 0.008, h * 0.9]);
    0.35
}

/// A tall round jug with a spout (+X) and a handle (−X), or a teapot.
fn jug(b: &mut AssetBuilder, w: f64, d: f64, h: f64, profile: &[[f64; 2]], [body, handle]: [usize; 2]) {
    let r = d / 2.0;
    let spout = 0.025f64.min((w - d) * 0.45);
    let reach = w - d - spout;
    let cx = -w / 2.0 + reach + r;
    lathe(b, 0, [cx, 0.0], r, 0.0, h, profile, body);
    super::parts::round_collider(b, 0, [cx, 0.0], r, 0.0, h);
    let (z0, z1) = (h * 0.3, h * 0.85);
    decal_between(b, [-w / 2.0, -0.008, z0], [-w / 2.0 + 0.014, 0.008, z1], handle);
    decal_between(b, [-w / 2.0 + 0.01, -0.007, z1 - 0.014], [cx - r * 0.7, 0.007, z1], handle);
    decal_between(b, [-w / 2.0 + 0.01, -0.007, z0], [cx - r * 0.7, 0.007, z0 + 0.014], handle);
    collider_between(b, [-w / 2.0, -0.008, z0], [cx - r * 0.7, 0.008, z1]);
    decal_between(b, [cx + r * 0.7, -0.01, h * 0.55], [w / 2.0, 0.01, h * 0.7], body);
    collider_between(b, [cx + r * 0.7, -0.01, h * 0.55], [w / 2.0, 0.01, h * 0.7]);
}

pub(crate) const TEAPOT: Category = def(
    "teapot",
    "teapot",
    &["tea pot", "coffee pot", "tea kettle pot", "coffeepot"],
    &["kitchen", "tabletop", "small", "graspable", "handled"],
    "a round ceramic teapot with a lid, a spout and a handle",
    &["pot", "jug", "kitchenware", "crockery"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 1 l teapots: 13–15 cm body, 22–25 cm spout to handle, 13–16 cm tall.
    &[
        ParamDef::new("width", 0.23, 0.16, 0.3, 0.05, "spout to handle along X"),
        ParamDef::new("depth", 0.145, 0.1, 0.18, 0.05, "body diameter"),
        ParamDef::new("height", 0.15, 0.1, 0.2, 0.06, "base to the lid knob"),
    ],
    build_teapot,
);

fn build_teapot(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let glaze =
        pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.16, 0.3, 0.55, 1.0], [0.75, 0.2, 0.16, 1.0], [0.2, 0.35, 0.28, 1.0]]);
    let body = b.material("glaze", glaze, true);
    let handle = b.material("handle", glaze, false);
    let profile = [[0.0, 0.0], [0.7, 0.0], [1.0, 0.35], [0.9, 0.75], [0.5, 0.85], [0.15, 0.9], [0.12, 1.0], [0.0, 1.0]];
    jug(b, w, d, h, &profile, [body, handle]);
    0.7
}

pub(crate) const PITCHER: Category = def(
    "pitcher",
    "pitcher",
    &["jug", "water jug", "milk jug", "carafe", "water pitcher", "juice jug", "creamer", "pitcher base"],
    &["kitchen", "tabletop", "small", "graspable", "handled"],
    "a tall water jug with a spout and a handle",
    &["jug", "container", "vessel", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 1.5–2 l jugs: 11–13 cm body, 18–21 cm with the handle, 22–26 cm tall.
    &[
        ParamDef::new("width", 0.19, 0.13, 0.24, 0.05, "spout to handle along X"),
        ParamDef::new("depth", 0.12, 0.08, 0.15, 0.05, "body diameter"),
        ParamDef::new("height", 0.24, 0.14, 0.3, 0.06, "base to rim"),
    ],
    build_pitcher,
);

fn build_pitcher(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let glass = rng.chance(0.5);
    let rgba =
        if glass { [0.78, 0.86, 0.9, 1.0] } else { pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.16, 0.3, 0.55, 1.0]]) };
    let body = b.material("body", rgba, true);
    let handle = b.material("handle", rgba, false);
    let profile = [[0.0, 0.0], [0.85, 0.0], [1.0, 0.1], [0.95, 0.7], [0.82, 1.0], [0.0, 1.0]];
    jug(b, w, d, h, &profile, [body, handle]);
    0.6
}

pub(crate) const WINE_GLASS: Category = def(
    "wine_glass",
    "wine glass",
    &["stemmed glass", "goblet", "champagne glass", "red wine glass", "white wine glass", "wineglass"],
    &["kitchen", "tabletop", "small", "graspable", "round"],
    "a stemmed wine glass on a round foot",
    &["glass", "drinkware", "glassware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Wine glasses: 8–9 cm bowl, 20–23 cm tall, 7–8 cm foot.
    &[
        ParamDef::new("width", 0.085, 0.06, 0.11, 0.06, "bowl diameter"),
        ParamDef::new("depth", 0.085, 0.06, 0.11, 0.06, "bowl diameter (as width)"),
        ParamDef::new("height", 0.21, 0.14, 0.26, 0.06, "foot to rim"),
    ],
    build_wine_glass,
);

fn build_wine_glass(p: &Params, _rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let glass = b.material("glass", [0.82, 0.88, 0.9, 1.0], true);
    let zs = h * 0.42;
    let profile = [
        [0.0, 0.0],
        [r * 0.9, 0.0],
        [r * 0.9, 0.003],
        [0.005, 0.006],
        [0.004, zs],
        [r * 0.8, zs + (h - zs) * 0.2],
        [r, zs + (h - zs) * 0.55],
        [r * 0.85, h],
        [r * 0.85 - 0.0015, h],
        [r - 0.0015, zs + (h - zs) * 0.55],
        [0.0, zs + 0.004],
    ];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), Pose::IDENTITY, glass);
    // The foot and stem as a short disc and a thin column; the bowl as its cylinder.
    super::parts::round_collider(b, 0, [0.0, 0.0], r * 0.9, 0.0, 0.004);
    collider_between(b, [-0.004, -0.004, 0.003], [0.004, 0.004, zs + 0.001]);
    super::parts::round_collider(b, 0, [0.0, 0.0], r, zs, h);
    0.16
}

pub(crate) const DRINKING_GLASS: Category = def(
    "drinking_glass",
    "drinking glass",
    &[
        "water glass",
        "highball glass",
        "tumbler",
        "tumbler glass",
        "juice glass",
        "pint glass",
        "glass of water",
        "whisky glass",
    ],
    &["kitchen", "tabletop", "small", "graspable", "round", "open", "container"],
    "a clear straight-sided drinking glass",
    &["glass", "drinkware", "glassware", "vessel"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // IKEA POKAL / Duralex tumblers: 7–8 cm across, 9–14 cm tall.
    &[
        ParamDef::new("width", 0.075, 0.055, 0.095, 0.06, "diameter"),
        ParamDef::new("depth", 0.075, 0.055, 0.095, 0.06, "diameter (as width)"),
        ParamDef::new("height", 0.12, 0.08, 0.16, 0.1, "floor to rim"),
    ],
    build_drinking_glass,
);

fn build_drinking_glass(p: &Params, _rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let glass = b.material("glass", [0.82, 0.88, 0.9, 1.0], true);
    let t = 0.003;
    let fl = 0.01;
    let profile = [[0.0, 0.0], [r * 0.92, 0.0], [r, h], [r - t, h], [r * 0.92 - t, fl], [0.0, fl]];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), Pose::IDENTITY, glass);
    vessel_collider(b, [0.0, 0.0], r * 0.92, r, t * 2.0, fl, 0.0, h, 16);
    0.25
}
