//! The bedroom and the hallway: beds, nightstands and dressers whose drawers slide out,
//! wardrobes whose doors swing open, cots, mirrors, coat stands, shoe racks, pillows and
//! folded blankets. Sizes from IKEA's ranges (MALM, HEMNES, PAX), noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::forms::{def, rounded_box, size3, spread, whd};
use super::kit::{DARK, OFFICE_PAINT, STEEL, WOOD, decal_between, pick, shade, slab};
use super::office::drawer_stack;
use super::parts::{Hinge, MOVING_GAP, carcass, hinged_door, round_solid};
use crate::{Category, Kind, ParamDef, Params};

/// Painted or wooden bedroom furniture.
fn case_colour(rng: &mut Rng) -> [f32; 4] {
    if rng.chance(0.55) {
        pick(rng, WOOD)
    } else {
        pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.2, 0.2, 0.21, 1.0], [0.55, 0.6, 0.62, 1.0]])
    }
}

pub(crate) const BED: Category = def(
    "bed",
    "bed",
    &[
        "double bed",
        "single bed",
        "queen bed",
        "king bed",
        "twin bed",
        "bed frame",
        "queen-size bed",
        "king-size bed",
        "divan",
        "day bed",
    ],
    &["furniture", "home", "bedroom", "surface"],
    "a bed: a frame with a headboard, a mattress, pillows and a duvet",
    &["furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA MALM bed frame for a 140 × 200 mattress: 156 × 209 cm, headboard 100 cm;
    // single 90 × 200 (96 × 209), king 180 × 200 (196 × 209).
    &[
        ParamDef::new("width", 1.56, 0.95, 2.1, 0.12, "along X"),
        ParamDef::new("depth", 2.09, 1.9, 2.25, 0.02, "along Y, headboard at -Y"),
        ParamDef::new("height", 1.0, 0.7, 1.3, 0.08, "floor to the top of the headboard"),
        ParamDef::new("mattress_top", 0.52, 0.4, 0.65, 0.05, "floor to the top of the mattress"),
    ],
    build_bed,
);

fn build_bed(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let top = super::kit::fit(b, "bed mattress_top", p.get("mattress_top"), 0.3, h - 0.1);
    let frame_rgba = case_colour(rng);
    let frame = b.material("frame", frame_rgba, true);
    let mattress = b.material("mattress", [0.95, 0.95, 0.93, 1.0], false);
    let duvet = b.material(
        "duvet",
        pick(
            rng,
            &[
                [0.85, 0.88, 0.92, 1.0],
                [0.6, 0.7, 0.8, 1.0],
                [0.9, 0.85, 0.75, 1.0],
                [0.55, 0.6, 0.5, 1.0],
                [0.75, 0.55, 0.55, 1.0],
            ],
        ),
        false,
    );
    let pillow = b.material("pillows", [0.97, 0.97, 0.96, 1.0], false);
    let slats = b.material("slats", shade(frame_rgba, 0.8), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let head_t = 0.05;
    let rail = top - 0.2;
    // The headboard, the side and foot rails on legs, the mattress inside them.
    slab(b, [-hw, -hd, 0.0], [hw, -hd + head_t, h], frame);
    for x in [-hw, hw - 0.04] {
        slab(b, [x, -hd + head_t - 0.001, 0.1], [x + 0.04, hd, rail], frame);
    }
    slab(b, [-hw + 0.02, hd - 0.04, 0.0], [hw - 0.02, hd, rail], frame);
    slab(b, [-hw + 0.039, -hd + head_t - 0.002, 0.15], [hw - 0.039, hd - 0.039, 0.2], slats);
    let bed = slab(b, [-hw + 0.045, -hd + head_t + 0.005, 0.2], [hw - 0.045, hd - 0.045, top], mattress);
    // The duvet over the lower two thirds, pillows at the head (visual: soft things).
    decal_between(b, [-hw + 0.04, -hd + d * 0.3, top - 0.02], [hw - 0.04, hd - 0.04, top + 0.004], duvet);
    let n = if w > 1.3 { 2 } else { 1 };
    for x in spread(-hw + 0.08, hw - 0.08, n) {
        let pw = ((w - 0.16) / n as f64 - 0.04).min(0.65);
        decal_between(
            b,
            [x - pw / 2.0, -hd + head_t + 0.03, top - 0.01],
            [x + pw / 2.0, -hd + head_t + 0.45, top + 0.006],
            pillow,
        );
    }
    b.surface("mattress", bed, [-hw + 0.045, -hd + head_t + 0.005], [hw - 0.045, hd - 0.045], None);
    0.0
}

pub(crate) const NIGHTSTAND: Category = def(
    "nightstand",
    "nightstand",
    &[
        "night stand",
        "bedside cabinet",
        "bedside table with drawers",
        "night table",
        "bedside chest",
        "bedside drawers",
    ],
    &["furniture", "home", "bedroom", "surface", "storage"],
    "a small bedside cabinet with two drawers that slide out",
    &["cabinet", "table", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA HEMNES 2-drawer nightstand 46 × 35 × 70 cm; MALM 40 × 48 × 55 cm.
    &[
        ParamDef::new("width", 0.46, 0.35, 0.6, 0.08, "along X"),
        ParamDef::new("depth", 0.38, 0.3, 0.5, 0.08, "along Y"),
        ParamDef::new("height", 0.62, 0.45, 0.75, 0.08, "floor to top"),
        ParamDef::new("drawers", 2.0, 1.0, 3.0, 0.2, "drawers"),
    ],
    build_nightstand,
);

/// A carcass on a plinth with a column of drawers across its width; the top is a surface.
fn chest(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, n: usize) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = case_colour(rng);
    let body = b.material("body", rgba, true);
    let fronts = b.material("fronts", shade(rgba, 1.04), true);
    let tray = b.material("drawer_inside", shade(rgba, 0.8), false);
    let handles =
        b.material("handles", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.7, 0.6, 0.35, 1.0], [0.66, 0.68, 0.7, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = 0.018;
    let y_front = hd;
    let opening = y_front - 0.018 - MOVING_GAP;
    let plinth = 0.06;
    slab(b, [-hw + 0.02, -hd, 0.0], [hw - 0.02, opening - 0.03, plinth], body);
    let top = carcass(b, -hw, hw, -hd, opening, plinth, h, t, body);
    let depth = (y_front - 0.018) - (-hd + t) - MOVING_GAP;
    drawer_stack(
        b,
        n,
        [-hw + 0.002, hw - 0.002],
        [plinth + 0.003, h - 0.003],
        [-hw + t, hw - t],
        [plinth + t, h - t],
        y_front,
        depth,
        [fronts, tray, handles],
        None,
        (w * d * 6.0).max(1.0),
    );
    b.surface("top", top, [-hw + t / 2.0, -hd], [hw - t / 2.0, opening], None);
    0.0
}

fn build_nightstand(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    chest(p, rng, b, p.count("drawers").clamp(1, 3))
}

pub(crate) const DRESSER: Category = def(
    "dresser",
    "dresser",
    &["chest of drawers", "bureau", "drawer chest", "tallboy", "commode", "dressing chest", "clothes chest"],
    &["furniture", "home", "bedroom", "surface", "storage"],
    "a chest of drawers for clothes, with three to six drawers that slide out",
    &["cabinet", "chest", "furniture", "storage"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA MALM 3-drawer chest 80 × 48 × 78 cm; 6-drawer 80 × 48 × 123 cm.
    &[
        ParamDef::new("width", 0.8, 0.6, 1.6, 0.1, "along X"),
        ParamDef::new("depth", 0.48, 0.4, 0.55, 0.05, "along Y"),
        ParamDef::new("height", 0.78, 0.6, 1.25, 0.08, "floor to top"),
    ],
    build_dresser,
);

fn build_dresser(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let n = ((p.get("height") - 0.1) / 0.22).round().clamp(3.0, 6.0) as usize;
    chest(p, rng, b, n)
}

/// A cabinet with drawers (issue 21, session 8): "a cabinet with drawers" named a door
/// cabinet, and the only drawer cabinet was the office's steel filing cabinet. A wooden
/// storage unit of three to four drawers at worktop height, on the chest's carcass.
pub(crate) const DRAWER_CABINET: Category = def(
    "drawer_cabinet",
    "drawer cabinet",
    &[
        "cabinet with drawers",
        "drawer unit",
        "cupboard with drawers",
        "unit with drawers",
        "storage drawers",
        "drawer base unit",
        "kitchen drawer unit",
        "base cabinet with drawers",
        "chest with drawers",
    ],
    &["furniture", "home", "kitchen", "surface", "storage"],
    "a wooden storage cabinet with a stack of drawers that slide out, worktop high",
    &["cabinet", "furniture", "storage"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA METOD drawer base 60 × 60 × 88 cm (with plinth and top); ALEX drawer unit 36 × 58 × 70 cm.
    &[
        ParamDef::new("width", 0.6, 0.36, 0.9, 0.1, "along X"),
        ParamDef::new("depth", 0.55, 0.45, 0.62, 0.05, "along Y"),
        ParamDef::new("height", 0.86, 0.7, 0.92, 0.04, "floor to top"),
        ParamDef::new("drawers", 3.0, 2.0, 4.0, 0.2, "drawers"),
    ],
    build_drawer_cabinet,
);

fn build_drawer_cabinet(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    chest(p, rng, b, p.count("drawers").clamp(2, 4))
}

pub(crate) const WARDROBE: Category = def(
    "wardrobe",
    "wardrobe",
    &[
        "armoire",
        "closet",
        "clothes closet",
        "wardrobe closet",
        "clothes cupboard",
        "freestanding wardrobe",
        "closet cabinet",
    ],
    &["furniture", "home", "bedroom", "tall", "storage"],
    "a tall wardrobe with two hinged doors, a hanging rail and a shelf inside",
    &["cabinet", "cupboard", "furniture", "storage"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA PAX 100 × 58 × 201 cm; KLEPPSTAD 117 × 55 × 176 cm.
    &[
        ParamDef::new("width", 1.0, 0.5, 2.0, 0.1, "along X"),
        ParamDef::new("depth", 0.58, 0.45, 0.65, 0.04, "along Y, doors included"),
        ParamDef::new("height", 2.01, 1.5, 2.36, 0.05, "floor to top"),
    ],
    build_wardrobe,
);

fn build_wardrobe(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = case_colour(rng);
    let body = b.material("body", rgba, true);
    let doors = b.material("doors", shade(rgba, 1.03), true);
    let rail = b.material("rail", pick(rng, STEEL), false);
    let handles = b.material("handles", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.66, 0.68, 0.7, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.02;
    let t = 0.018;
    let opening = hd - dt - MOVING_GAP;
    let plinth = 0.05;
    slab(b, [-hw + 0.01, -hd, 0.0], [hw - 0.01, opening - 0.02, plinth], body);
    carcass(b, -hw, hw, -hd, opening, plinth, h, t, body);
    // A shelf near the top, the rail under it.
    let shelf_z = h - 0.3;
    let shelf = slab(b, [-hw + t * 0.5, -hd + t * 0.75, shelf_z - t], [hw - t * 0.5, opening - 0.02, shelf_z], body);
    decal_between(b, [-hw + t, -0.01, shelf_z - 0.09], [hw - t, 0.01, shelf_z - 0.07], rail);
    let leaf = (w * h * dt * 600.0).max(2.0);
    if w > 0.7 {
        hinged_door(
            b,
            "door_left",
            Hinge::MinX,
            [-hw + 0.002, -0.0015],
            [plinth + 0.003, h - 0.003],
            hd - dt,
            dt,
            doors,
            handles,
            h * 0.5,
            leaf / 2.0,
        );
        hinged_door(
            b,
            "door_right",
            Hinge::MaxX,
            [0.0015, hw - 0.002],
            [plinth + 0.003, h - 0.003],
            hd - dt,
            dt,
            doors,
            handles,
            h * 0.5,
            leaf / 2.0,
        );
    } else {
        hinged_door(
            b,
            "door",
            Hinge::MinX,
            [-hw + 0.002, hw - 0.002],
            [plinth + 0.003, h - 0.003],
            hd - dt,
            dt,
            doors,
            handles,
            h * 0.5,
            leaf,
        );
    }
    b.surface("shelf", shelf, [-hw + t, -hd + t], [hw - t, opening - 0.02], Some(h - t - shelf - 0.005));
    0.0
}

pub(crate) const PILLOW: Category = def(
    "pillow",
    "pillow",
    &["bed pillow", "sleeping pillow", "head pillow"],
    &["home", "textile", "bedroom", "tabletop", "small", "graspable"],
    "a rectangular bed pillow",
    &["cushion", "textile", "bedding"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // Standard pillows: 50 × 75 cm (UK 48 × 74, US 51 × 66), 12–18 cm filled.
    &[
        ParamDef::new("width", 0.7, 0.45, 0.9, 0.08, "along X"),
        ParamDef::new("depth", 0.5, 0.35, 0.6, 0.06, "along Y"),
        ParamDef::new("height", 0.14, 0.08, 0.2, 0.12, "thickness"),
    ],
    build_pillow,
);

fn build_pillow(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material(
        "case",
        pick(rng, &[[0.97, 0.97, 0.96, 1.0], [0.85, 0.88, 0.92, 1.0], [0.9, 0.85, 0.75, 1.0]]),
        true,
    );
    let seam = b.material("seam", [0.8, 0.8, 0.8, 1.0], false);
    rounded_box(b, [0.0, 0.0], w * 0.9, d * 0.88, 0.0, h, 0.08, case);
    rounded_box(b, [0.0, 0.0], w, d, h * 0.4, h * 0.6, 0.03, seam);
    0.6
}

pub(crate) const BLANKET: Category = def(
    "blanket",
    "folded blanket",
    &["throw", "duvet", "quilt", "comforter", "folded towel stack", "bedspread"],
    &["home", "textile", "bedroom", "tabletop", "small", "graspable"],
    "a folded blanket or duvet lying flat",
    &["bedding", "textile"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // A 150 × 200 cm throw folded in eight: about 40 × 50 × 8 cm.
    &size3(0.45, 0.38, 0.08, 0.6, 1.6, 0.1),
    build_blanket,
);

fn build_blanket(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wool = pick(
        rng,
        &[
            [0.6, 0.2, 0.18, 1.0],
            [0.3, 0.4, 0.55, 1.0],
            [0.85, 0.8, 0.7, 1.0],
            [0.4, 0.5, 0.35, 1.0],
            [0.55, 0.55, 0.57, 1.0],
        ],
    );
    let body = b.material("wool", wool, true);
    let fold = b.material("folds", shade(wool, 0.8), false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, h * 0.45, body);
    for z in spread(0.0, h, 4).into_iter().skip(1) {
        decal_between(b, [w / 2.0 - 0.004, -d / 2.0 + 0.02, z - 0.002], [w / 2.0 + 0.002, d / 2.0 - 0.02, z], fold);
    }
    (w * d * h * 120.0).max(0.3)
}

pub(crate) const CRIB: Category = def(
    "crib",
    "crib",
    &["cot", "baby cot", "baby crib", "cot bed", "nursery cot", "baby bed"],
    &["furniture", "home", "bedroom"],
    "a baby's cot with slatted sides and a mattress inside",
    &["bed", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA SUNDVIK cot for a 60 × 120 mattress: 66 × 125 × 85 cm.
    &size3(1.25, 0.66, 0.86, 0.85, 1.15, 0.03),
    build_crib,
);

fn build_crib(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = case_colour(rng);
    let frame = b.material("frame", rgba, true);
    let slats = b.material("slats", shade(rgba, 0.95), false);
    let mattress = b.material("mattress", [0.95, 0.95, 0.93, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let post = 0.045;
    // Four posts, rails top and bottom, slats between them, a mattress on its base.
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * (hw - post / 2.0), sy * (hd - post / 2.0));
        slab(b, [x - post / 2.0, y - post / 2.0, 0.0], [x + post / 2.0, y + post / 2.0, h], frame);
    }
    let base = slab(b, [-hw + post, -hd + post, 0.25], [hw - post, hd - post, 0.27], frame);
    let top = slab(b, [-hw + post, -hd + post + 0.002, base], [hw - post, hd - post - 0.002, base + 0.1], mattress);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = super::kit::ordered(sy * (hd - 0.03), sy * hd);
        slab(b, [-hw + post - 0.001, y0, h - 0.05], [hw - post + 0.001, y1, h - 0.01], frame);
        for x in spread(-hw + post, hw - post, 14) {
            decal_between(b, [x - 0.01, y0 + 0.005, base], [x + 0.01, y1 - 0.005, h - 0.05], slats);
        }
        super::kit::collider_between(b, [-hw + post, y0 + 0.005, base], [hw - post, y1 - 0.005, h - 0.05]);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = super::kit::ordered(sx * (hw - 0.03), sx * hw);
        slab(b, [x0, -hd + post - 0.001, base], [x1, hd - post + 0.001, h - 0.01], frame);
    }
    b.surface("mattress", top, [-hw + post, -hd + post + 0.002], [hw - post, hd - post - 0.002], None);
    0.0
}

pub(crate) const STANDING_MIRROR: Category = def(
    "standing_mirror",
    "standing mirror",
    &[
        "mirror",
        "full-length mirror",
        "floor mirror",
        "dressing mirror",
        "cheval mirror",
        "leaning mirror",
        "body mirror",
    ],
    &["furniture", "home", "bedroom", "tall"],
    "a full-length mirror in a frame on a foot",
    &["mirror", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA NISSEDAL / HOVET: 40–78 × 30–40 (with foot) × 150–196 cm.
    &size3(0.5, 0.35, 1.6, 0.7, 1.25, 0.08),
    build_standing_mirror,
);

fn build_standing_mirror(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let frame = b.material("frame", case_colour(rng), true);
    let glass = b.material("glass", [0.75, 0.8, 0.82, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.04], frame);
    slab(b, [-hw, -0.015, 0.039], [hw, 0.015, h], frame);
    decal_between(b, [-hw + 0.03, 0.014, 0.08], [hw - 0.03, 0.017, h - 0.03], glass);
    0.0
}

pub(crate) const COAT_RACK: Category = def(
    "coat_rack",
    "coat rack",
    &[
        "coat stand",
        "hat stand",
        "coat tree",
        "hall tree",
        "hat and coat stand",
        "clothes stand",
        "coatrack",
        "hatrack",
        "hat rack",
    ],
    &["furniture", "home", "office", "tall", "round"],
    "a free-standing coat stand: a pole on a round base with hooks at the top",
    &["stand", "rack", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // IKEA coat stands: 40–50 cm base, 170–190 cm tall.
    &[
        ParamDef::new("width", 0.45, 0.3, 0.6, 0.1, "diameter"),
        ParamDef::new("depth", 0.45, 0.3, 0.6, 0.1, "diameter (as width)"),
        ParamDef::new("height", 1.8, 1.5, 2.0, 0.05, "floor to top"),
    ],
    build_coat_rack,
);

fn build_coat_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let wood = b.material("wood", case_colour(rng), true);
    let hooks = b.material("hooks", pick(rng, DARK), false);
    round_solid(b, 0, [0.0, 0.0], r, 0.0, 0.03, wood);
    round_solid(b, 0, [0.0, 0.0], 0.02, 0.029, h, wood);
    // Two crossed bars of hooks.
    let l = r * 0.45;
    decal_between(b, [-l - 0.006, -0.006, h - 0.15], [l + 0.006, 0.006, h - 0.13], hooks);
    decal_between(b, [-0.005, -l - 0.006, h - 0.149], [0.005, l + 0.006, h - 0.131], hooks);
    super::kit::collider_between(
        b,
        [-r * 0.45 - 0.006, -r * 0.45 - 0.006, h - 0.15],
        [r * 0.45 + 0.006, r * 0.45 + 0.006, h - 0.13],
    );
    0.0
}

pub(crate) const SHOE_RACK: Category = def(
    "shoe_rack",
    "shoe rack",
    &["shoe shelf", "shoe stand", "shoe bench", "shoe storage", "shoe cabinet"],
    &["furniture", "home", "storage", "surface"],
    "a low open rack with two shelves for shoes",
    &["rack", "shelf", "furniture", "storage"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA HEMNES / TJUSIG shoe racks: 60–80 × 30–37 × 45–60 cm.
    &size3(0.8, 0.32, 0.5, 0.7, 1.5, 0.08),
    build_shoe_rack,
);

fn build_shoe_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = if rng.chance(0.5) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", rgba, true);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = 0.02;
    for x0 in [-hw, hw - t] {
        slab(b, [x0, -hd, 0.0], [x0 + t, hd, h], body);
    }
    let low = slab(b, [-hw + t * 0.5, -hd, 0.06], [hw - t * 0.5, hd, 0.06 + t], body);
    let top = slab(b, [-hw + t * 0.5, -hd, h - t], [hw - t * 0.5, hd, h], body);
    b.surface("lower_shelf", low, [-hw + t, -hd], [hw - t, hd], Some(h - t - low - 0.003));
    b.surface("top", top, [-hw + t * 0.5, -hd], [hw - t * 0.5, hd], None);
    0.0
}
