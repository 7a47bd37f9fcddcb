//! The living room: armchairs, coffee and side tables, TV benches and televisions, floor
//! lamps, rugs, cushions and pouffes; heaters, fans and air conditioners; and the small
//! things on its surfaces (vases, frames, remotes, speakers, candles, clocks). Sizes are
//! from published ranges (IKEA product pages, typical 55" TV dimensions), noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Rng, Shape};

use super::forms::{def, knobs, lathe, round_body, rounded_box, size3, spread, whd};
use super::kit::{
    Axis, DARK, INK, LABEL_WHITE, OFFICE_PAINT, STEEL, UPHOLSTERY, WOOD, collider_between, decal_between, four_legs,
    pick, rod, shade, slab,
};
use super::parts::{carcass, round_collider, round_solid};
use crate::{Category, Kind, ParamDef, Params};

const DECOR: &[&str] = &["home", "tabletop", "small", "graspable"];

pub(crate) const ARMCHAIR: Category = def(
    "armchair",
    "armchair",
    &[
        "arm chair",
        "easy chair",
        "lounge chair",
        "club chair",
        "recliner",
        "wingback chair",
        "accent chair",
        "fauteuil",
    ],
    &["furniture", "seating", "home"],
    "an upholstered armchair for one person with two arms and a back",
    &["chair", "seat", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // IKEA EKTORP armchair 104 × 88 × 88 cm; STRANDMON 82 × 96 × 101 cm.
    &[
        ParamDef::new("width", 0.92, 0.7, 1.15, 0.08, "along X, arms included"),
        ParamDef::new("depth", 0.88, 0.75, 1.0, 0.05, "along Y"),
        ParamDef::new("height", 0.9, 0.75, 1.05, 0.06, "floor to the top of the back"),
        ParamDef::new("seat_height", 0.44, 0.38, 0.5, 0.04, "floor to the top of the cushion"),
        ParamDef::new("arm_width", 0.14, 0.1, 0.2, 0.1, "width of each arm"),
    ],
    super::furniture::build_sofa,
);

const LOW_TABLE: [ParamDef; 5] = [
    ParamDef::new("width", 0.9, 0.5, 1.4, 0.12, "top length along X"),
    ParamDef::new("depth", 0.55, 0.4, 0.9, 0.1, "top depth along Y"),
    ParamDef::new("height", 0.45, 0.35, 0.55, 0.05, "floor to top surface"),
    ParamDef::new("top_thickness", 0.04, 0.015, 0.06, 0.2, "thickness of the top"),
    ParamDef::new("leg", 0.05, 0.025, 0.08, 0.2, "leg section"),
];

pub(crate) const COFFEE_TABLE: Category = def(
    "coffee_table",
    "coffee table",
    &["cocktail table", "living room table", "low table", "sofa table", "centre table", "center table"],
    &["furniture", "surface", "home", "tabletop"],
    "a low table in front of a sofa for drinks, books and remotes",
    &["table", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // IKEA LACK coffee table 90 × 55 × 45 cm; HEMNES 118 × 75 × 46 cm.
    &LOW_TABLE,
    super::furniture::build_table,
);

pub(crate) const SIDE_TABLE: Category = def(
    "side_table",
    "side table",
    &["end table", "lamp table", "occasional table", "accent table", "bedside table", "sofa side table"],
    &["furniture", "surface", "home", "tabletop"],
    "a small square table beside a sofa or bed",
    &["table", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // IKEA LACK side table 55 × 55 × 45 cm.
    &[
        ParamDef::new("width", 0.55, 0.35, 0.7, 0.1, "top length along X"),
        ParamDef::new("depth", 0.55, 0.35, 0.7, 0.1, "top depth along Y"),
        ParamDef::new("height", 0.5, 0.4, 0.7, 0.08, "floor to top surface"),
        ParamDef::new("top_thickness", 0.04, 0.015, 0.06, 0.2, "thickness of the top"),
        ParamDef::new("leg", 0.045, 0.025, 0.07, 0.2, "leg section"),
    ],
    super::furniture::build_table,
);

pub(crate) const TV_STAND: Category = def(
    "tv_stand",
    "tv stand",
    &[
        "tv bench",
        "tv unit",
        "tv cabinet",
        "media console",
        "entertainment unit",
        "television stand",
        "media unit",
        "sideboard",
        "credenza",
    ],
    &["furniture", "surface", "home", "storage"],
    "a long low cabinet with open compartments that a television stands on",
    &["cabinet", "stand", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // IKEA BESTÅ TV bench 180 × 42 × 38 cm; LACK TV bench 90 × 26 × 45 cm.
    &[
        ParamDef::new("width", 1.6, 0.9, 2.4, 0.12, "along X"),
        ParamDef::new("depth", 0.42, 0.3, 0.5, 0.06, "along Y"),
        ParamDef::new("height", 0.48, 0.35, 0.6, 0.08, "floor to top"),
    ],
    build_tv_stand,
);

fn build_tv_stand(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wood = rng.chance(0.5);
    let finish = if wood { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", finish, true);
    let fronts = b.material("fronts", shade(finish, 0.93), false);
    let feet = b.material("feet", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = 0.018;
    let foot = 0.06;
    for x in [-hw + 0.05, hw - 0.05] {
        for y in [-hd + 0.05, hd - 0.05] {
            slab(b, [x - 0.02, y - 0.02, 0.0], [x + 0.02, y + 0.02, foot], feet);
        }
    }
    let top = carcass(b, -hw, hw, -hd, hd, foot, h, t, body);
    // Dividers into compartments; the outer two get drawer fronts, the middle stays open.
    let n = ((w / 0.6).round() as usize).clamp(2, 4);
    let cw = (w - 2.0 * t) / n as f64;
    for k in 1..n {
        let x = -hw + t + cw * k as f64;
        slab(b, [x - t / 2.0, -hd + t, foot + t * 0.5], [x + t / 2.0, hd - 0.002, h - t * 0.5], body);
    }
    for k in [0, n - 1] {
        let x0 = -hw + t + cw * k as f64;
        decal_between(
            b,
            [x0 + 0.012, hd - 0.001, foot + t + 0.005],
            [x0 + cw - 0.012, hd + 0.002, h - t - 0.005],
            fronts,
        );
    }
    let (zc, zh) = super::kit::center_half([0.0, 0.0, foot], [0.0, 0.0, foot + t]);
    let shelf_z = zc[2] + zh[2];
    let mid = -hw + t + cw * (n / 2) as f64;
    b.surface("top", top, [-hw + t / 2.0, -hd], [hw - t / 2.0, hd], None);
    if n > 2 {
        b.surface("shelf", shelf_z, [mid + t, -hd + 2.0 * t], [mid + cw - t, hd - 0.01], Some(h - t - shelf_z - 0.002));
    }
    0.0
}

pub(crate) const TELEVISION: Category = def(
    "television",
    "television",
    &["tv", "tv set", "flat screen tv", "flat-screen tv", "smart tv", "led tv", "telly", "flatscreen"],
    &["electronics", "home", "tabletop"],
    "a flat-screen television on a pedestal stand",
    &["screen", "display", "electronics", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // 55" TVs: 123 × 7 × 71 cm panel, 25 cm deep and 77 cm tall on the stand (Samsung, LG).
    &[
        ParamDef::new("width", 1.23, 0.55, 1.65, 0.15, "screen width along X"),
        ParamDef::new("depth", 0.25, 0.15, 0.35, 0.08, "stand depth along Y"),
        ParamDef::new("height", 0.77, 0.36, 1.02, 0.15, "stand foot to the top of the screen"),
    ],
    build_television,
);

fn build_television(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let frame =
        b.material("frame", pick(rng, &[[0.08, 0.08, 0.09, 1.0], [0.3, 0.3, 0.32, 1.0], [0.7, 0.71, 0.73, 1.0]]), true);
    let screen = b.material("screen", [0.03, 0.04, 0.06, 1.0], false);
    let stand = b.material("stand", pick(rng, DARK), false);
    let panel_t = 0.05f64.min(d * 0.3);
    let z0 = h * 0.08;
    // Foot plate, neck, then the panel with its screen facing +Y.
    slab(b, [-w * 0.2, -d / 2.0, 0.0], [w * 0.2, d / 2.0, 0.015], stand);
    slab(b, [-0.04, -panel_t * 0.5 - 0.02, 0.014], [0.04, -panel_t * 0.5 + 0.002, z0 + 0.05], stand);
    slab(b, [-w / 2.0, -panel_t / 2.0, z0], [w / 2.0, panel_t / 2.0, h], frame);
    decal_between(
        b,
        [-w / 2.0 + 0.01, panel_t / 2.0 - 0.0005, z0 + 0.012],
        [w / 2.0 - 0.01, panel_t / 2.0 + 0.001, h - 0.01],
        screen,
    );
    (w * (h - z0) * 25.0).max(3.0)
}

pub(crate) const FLOOR_LAMP: Category = def(
    "floor_lamp",
    "floor lamp",
    &["standing lamp", "standard lamp", "torchiere", "arc lamp", "uplighter", "reading floor lamp", "tall lamp"],
    &["home", "office", "tall", "light", "round"],
    "a tall floor lamp: a heavy round base, a pole and a fabric shade on top",
    &["lamp", "light", "light fixture"],
    Kind::Fixture,
    PlacementKind::Floor,
    false,
    // IKEA HEKTAR / HÅRTE floor lamps: 150–180 cm tall, 28–32 cm base, 35–45 cm shade.
    &[
        ParamDef::new("width", 0.4, 0.25, 0.55, 0.1, "shade diameter"),
        ParamDef::new("depth", 0.4, 0.25, 0.55, 0.1, "shade diameter (as width)"),
        ParamDef::new("height", 1.65, 1.2, 2.0, 0.06, "floor to the top of the shade"),
    ],
    build_floor_lamp,
);

fn build_floor_lamp(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let r = w.min(d) / 2.0;
    let metal =
        b.material("metal", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.7, 0.6, 0.35, 1.0], [0.75, 0.76, 0.78, 1.0]]), false);
    let shade_m =
        b.material("shade", pick(rng, &[[0.95, 0.93, 0.86, 1.0], [0.85, 0.8, 0.7, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    let sh = (h * 0.18).min(0.35);
    round_solid(b, 0, [0.0, 0.0], r * 0.7, 0.0, 0.025, metal);
    round_solid(b, 0, [0.0, 0.0], 0.012, 0.024, h - sh * 0.6, metal);
    lathe(b, 0, [0.0, 0.0], r, h - sh, sh, &[[0.0, 0.0], [1.0, 0.0], [0.7, 1.0], [0.0, 1.0]], shade_m);
    round_collider(b, 0, [0.0, 0.0], r, h - sh, h);
    0.0
}

pub(crate) const RUG: Category = def(
    "rug",
    "rug",
    &["carpet", "area rug", "floor rug", "runner rug", "mat", "floor mat", "runner", "hall runner", "carpet runner"],
    &["home", "textile", "floor"],
    "a flat rectangular rug on the floor",
    &["floor covering", "textile", "mat"],
    Kind::Textile,
    PlacementKind::Floor,
    false,
    // IKEA rugs: 133 × 195, 160 × 230, 200 × 300 cm; 0.5–1.5 cm pile.
    &[
        ParamDef::new("width", 2.0, 0.5, 3.5, 0.15, "along X"),
        ParamDef::new("depth", 1.4, 0.4, 2.5, 0.15, "along Y"),
        ParamDef::new("height", 0.01, 0.004, 0.025, 0.2, "thickness"),
    ],
    build_rug,
);

fn build_rug(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let main =
        pick(rng, &[[0.6, 0.2, 0.18, 1.0], [0.2, 0.3, 0.5, 1.0], [0.85, 0.82, 0.74, 1.0], [0.35, 0.35, 0.37, 1.0]]);
    let field = b.material("field", main, true);
    let border = b.material("border", shade(main, 0.6), false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], field);
    let m = (w.min(d) * 0.08).min(0.12);
    for (x0, x1, y0, y1) in [
        (-w / 2.0 + m, w / 2.0 - m, -d / 2.0 + m, -d / 2.0 + m * 1.4),
        (-w / 2.0 + m, w / 2.0 - m, d / 2.0 - m * 1.4, d / 2.0 - m),
    ] {
        decal_between(b, [x0, y0, h - 0.0005], [x1, y1, h + 0.001], border);
    }
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    0.0
}

pub(crate) const CUSHION: Category = def(
    "cushion",
    "cushion",
    &["throw pillow", "scatter cushion", "sofa cushion", "decorative pillow", "floor cushion"],
    &["home", "textile", "tabletop", "small", "graspable"],
    "a square soft cushion",
    &["pillow", "textile", "soft furnishing"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // IKEA cushions 40 × 40, 50 × 50 cm, 12–16 cm thick filled.
    &[
        ParamDef::new("width", 0.45, 0.3, 0.65, 0.1, "along X"),
        ParamDef::new("depth", 0.45, 0.3, 0.65, 0.1, "along Y"),
        ParamDef::new("height", 0.14, 0.08, 0.2, 0.12, "thickness"),
    ],
    build_cushion,
);

fn build_cushion(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let cover = b.material(
        "cover",
        pick(
            rng,
            &[
                [0.75, 0.3, 0.25, 1.0],
                [0.3, 0.45, 0.6, 1.0],
                [0.9, 0.85, 0.7, 1.0],
                [0.4, 0.55, 0.4, 1.0],
                [0.85, 0.6, 0.2, 1.0],
            ],
        ),
        true,
    );
    let piping = b.material("edge", pick(rng, UPHOLSTERY), false);
    // A plump middle and thin edges, as a filled cushion looks.
    rounded_box(b, [0.0, 0.0], w, d, h * 0.3, h * 0.7, 0.05, piping);
    rounded_box(b, [0.0, 0.0], w * 0.85, d * 0.85, 0.0, h, 0.08, cover);
    0.3 + w * d * 1.5
}

pub(crate) const OTTOMAN: Category = def(
    "ottoman",
    "ottoman",
    &["pouffe", "pouf", "footstool", "foot stool", "hassock", "footrest"],
    &["furniture", "seating", "home"],
    "a padded footstool or pouffe",
    &["seat", "stool", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // IKEA pouffes 45 × 45 × 42 cm; footstools 50 × 40 × 40 cm.
    &size3(0.5, 0.45, 0.42, 0.7, 1.5, 0.08),
    build_ottoman,
);

fn build_ottoman(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let fabric = pick(rng, UPHOLSTERY);
    let body = b.material("body", fabric, true);
    let feet = b.material("feet", pick(rng, WOOD), false);
    let top = rounded_box(b, [0.0, 0.0], w, d, 0.05, h, 0.04, body);
    four_legs(b, w - 0.04, d - 0.04, 0.051, 0.035, 0.02, feet);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    0.0
}

pub(crate) const BEAN_BAG: Category = def(
    "bean_bag",
    "bean bag",
    &["beanbag", "bean bag chair", "sack chair", "floor pillow"],
    &["furniture", "seating", "home", "round"],
    "a big soft round bean bag seat",
    &["seat", "chair", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Bean bags: 80–100 cm across, 60–80 cm tall.
    &[
        ParamDef::new("width", 0.9, 0.6, 1.2, 0.1, "diameter"),
        ParamDef::new("depth", 0.9, 0.6, 1.2, 0.1, "diameter (as width)"),
        ParamDef::new("height", 0.7, 0.5, 0.9, 0.1, "height"),
    ],
    build_bean_bag,
);

fn build_bean_bag(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let cover = b.material(
        "cover",
        pick(rng, &[[0.75, 0.3, 0.25, 1.0], [0.3, 0.45, 0.6, 1.0], [0.35, 0.35, 0.37, 1.0], [0.85, 0.6, 0.2, 1.0]]),
        true,
    );
    round_body(b, w / 2.0, h, &[[0.0, 0.0], [0.8, 0.0], [1.0, 0.3], [0.85, 0.7], [0.45, 1.0], [0.0, 0.95]], cover);
    0.0
}

pub(crate) const VASE: Category = def(
    "vase",
    "vase",
    &["flower vase", "vase of flowers", "ceramic vase", "glass vase", "urn", "pottery", "piece of pottery"],
    &["home", "tabletop", "small", "graspable", "round"],
    "a decorative vase with a narrow neck",
    &["container", "vessel", "decoration"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Table vases: 10–18 cm across, 20–35 cm tall.
    &[
        ParamDef::new("width", 0.14, 0.08, 0.25, 0.12, "widest diameter"),
        ParamDef::new("depth", 0.14, 0.08, 0.25, 0.12, "widest diameter (as width)"),
        ParamDef::new("height", 0.26, 0.12, 0.45, 0.12, "height"),
    ],
    build_vase,
);

fn build_vase(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let glaze = b.material(
        "glaze",
        pick(rng, &[[0.16, 0.3, 0.55, 1.0], [0.9, 0.9, 0.88, 1.0], [0.65, 0.3, 0.2, 1.0], [0.2, 0.45, 0.4, 1.0]]),
        true,
    );
    let belly = rng.range(0.3, 0.55);
    round_body(b, w / 2.0, h, &[[0.0, 0.0], [0.6, 0.0], [1.0, belly], [0.45, 0.85], [0.55, 1.0], [0.0, 1.0]], glaze);
    0.4 + w * w * h * 60.0
}

pub(crate) const PICTURE_FRAME: Category = def(
    "picture_frame",
    "picture frame",
    &["photo frame", "framed photo", "photograph", "frame", "framed picture"],
    DECOR,
    "a framed photo standing on a table on its back leg",
    &["frame", "decoration"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 13 × 18 cm (5 × 7") photo frames: 17 × 22 cm outside, standing 12 cm deep on the leg.
    &size3(0.18, 0.1, 0.23, 0.6, 1.8, 0.1),
    build_picture_frame,
);

fn build_picture_frame(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let frame = b.material(
        "frame",
        pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.6, 0.45, 0.28, 1.0], [0.9, 0.9, 0.88, 1.0], [0.75, 0.65, 0.35, 1.0]]),
        true,
    );
    let photo =
        b.material("photo", pick(rng, &[[0.45, 0.6, 0.75, 1.0], [0.55, 0.65, 0.4, 1.0], [0.8, 0.6, 0.45, 1.0]]), false);
    let t = 0.015;
    // The frame stands near the front; a leg props it from behind.
    slab(b, [-w / 2.0, d / 2.0 - t, 0.0], [w / 2.0, d / 2.0, h], frame);
    decal_between(b, [-w / 2.0 + 0.02, d / 2.0 - 0.001, 0.02], [w / 2.0 - 0.02, d / 2.0 + 0.0015, h - 0.02], photo);
    slab(b, [-0.012, -d / 2.0, 0.0], [0.012, d / 2.0 - t + 0.001, h * 0.15], frame);
    0.2 + w * h * 2.0
}

pub(crate) const REMOTE_CONTROL: Category = def(
    "remote_control",
    "remote control",
    &["remote", "tv remote", "clicker", "remote controller", "zapper"],
    &["home", "electronics", "tabletop", "small", "graspable"],
    "a handheld tv remote control with rows of buttons",
    &["device", "electronics"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // TV remotes: 15–21 × 4–5.5 × 1.8–2.5 cm.
    &[
        ParamDef::new("width", 0.18, 0.12, 0.23, 0.08, "length"),
        ParamDef::new("depth", 0.048, 0.035, 0.06, 0.06, "width"),
        ParamDef::new("height", 0.022, 0.015, 0.03, 0.08, "thickness"),
    ],
    build_remote_control,
);

fn build_remote_control(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material(
        "body",
        pick(rng, &[[0.08, 0.08, 0.09, 1.0], [0.25, 0.25, 0.27, 1.0], [0.85, 0.86, 0.86, 1.0]]),
        true,
    );
    let keys = b.material("keys", pick(rng, &[[0.5, 0.5, 0.52, 1.0], [0.1, 0.1, 0.1, 1.0]]), false);
    let red = b.material("power", [0.8, 0.1, 0.08, 1.0], false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h - 0.002, d * 0.3, body);
    decal_between(b, [w / 2.0 - 0.025, -0.006, h - 0.004], [w / 2.0 - 0.013, 0.006, h], red);
    for x in spread(-w / 2.0 + 0.02, w / 2.0 - 0.035, 6) {
        for y in spread(-d * 0.3, d * 0.3, 3) {
            decal_between(b, [x - 0.005, y - 0.004, h - 0.004], [x + 0.005, y + 0.004, h], keys);
        }
    }
    0.11
}

pub(crate) const SPEAKER: Category = def(
    "speaker",
    "speaker",
    &["loudspeaker", "bookshelf speaker", "hi-fi speaker", "smart speaker", "bluetooth speaker", "stereo speaker"],
    &["home", "electronics", "tabletop", "small"],
    "a wooden loudspeaker box with two drivers on its front",
    &["device", "electronics"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Bookshelf speakers: 15–20 × 20–28 × 25–33 cm.
    &size3(0.17, 0.24, 0.29, 0.5, 1.5, 0.08),
    build_speaker,
);

fn build_speaker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let cab = b.material(
        "cabinet",
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.55, 0.4, 0.25, 1.0], [0.9, 0.9, 0.88, 1.0]]),
        true,
    );
    let cone = b.material("drivers", INK, false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], cab);
    let rw = (w * 0.35).min(h * 0.2);
    rod(b, [0.0, d / 2.0 + 0.002, h * 0.38], rw, 0.004, Axis::Y, cone);
    rod(b, [0.0, d / 2.0 + 0.002, h * 0.78], rw * 0.4, 0.004, Axis::Y, cone);
    (w * d * h * 500.0).max(0.5)
}

pub(crate) const STANDING_FAN: Category = def(
    "standing_fan",
    "standing fan",
    &["pedestal fan", "floor fan", "stand fan", "electric fan", "fan", "oscillating fan", "tower fan"],
    &["home", "office", "appliance", "tall"],
    "a pedestal fan: a round base, a pole and a caged fan head at the top",
    &["fan", "appliance"],
    Kind::LargeAppliance,
    PlacementKind::Floor,
    false,
    // 16" pedestal fans: 40–45 cm head, 110–135 cm tall, 40–50 cm base.
    &[
        ParamDef::new("width", 0.45, 0.3, 0.6, 0.08, "head diameter along X"),
        ParamDef::new("depth", 0.4, 0.3, 0.55, 0.08, "base diameter along Y"),
        ParamDef::new("height", 1.25, 0.9, 1.5, 0.08, "floor to the top of the head"),
    ],
    build_standing_fan,
);

fn build_standing_fan(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let plastic = b.material("body", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0]]), true);
    let cage = b.material("cage", [0.55, 0.57, 0.6, 1.0], false);
    let rb = d / 2.0;
    let rh = w / 2.0;
    round_solid(b, 0, [0.0, 0.0], rb.min(rh), 0.0, 0.04, plastic);
    slab(b, [-0.03, -rb, 0.0], [0.03, rb, 0.03], plastic);
    let zc = h - rh;
    round_solid(b, 0, [0.0, 0.0], 0.016, 0.039, zc, plastic);
    // The head: a motor pod behind a caged disc facing +Y.
    b.visual(
        Shape::Cylinder { radius: rh * 0.99, half_height: 0.05 },
        super::kit::along([0.0, 0.03, zc], Axis::Y),
        cage,
    );
    b.visual(
        Shape::Cylinder { radius: 0.07, half_height: 0.06 },
        super::kit::along([0.0, -0.05, zc], Axis::Y),
        plastic,
    );
    collider_between(b, [-rh, -0.11, zc - rh], [rh, 0.08, h]);
    0.0
}

pub(crate) const DESK_FAN: Category = def(
    "desk_fan",
    "desk fan",
    &["table fan", "small fan", "usb fan", "clip fan"],
    &["home", "office", "appliance", "tabletop", "small"],
    "a small desk fan with a caged blade on a round foot",
    &["fan", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // 12" desk fans: 30–35 cm head, 40–48 cm tall.
    &size3(0.3, 0.2, 0.42, 0.6, 1.3, 0.06),
    build_desk_fan,
);

fn build_desk_fan(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let plastic =
        b.material("body", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0], [0.3, 0.45, 0.6, 1.0]]), true);
    let cage = b.material("cage", [0.55, 0.57, 0.6, 1.0], false);
    let rh = (w / 2.0).min((h - 0.06) / 2.0);
    let zc = h - rh;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, 0.035, d * 0.3, plastic);
    collider_between(b, [-0.015, -0.015, 0.034], [0.015, 0.015, zc]);
    decal_between(b, [-0.015, -0.015, 0.034], [0.015, 0.015, zc], plastic);
    b.visual(
        Shape::Cylinder { radius: rh * 0.99, half_height: 0.03 },
        super::kit::along([0.0, 0.02, zc], Axis::Y),
        cage,
    );
    collider_between(b, [-rh, -0.04, zc - rh], [rh, 0.05, h]);
    1.5
}

pub(crate) const SPACE_HEATER: Category = def(
    "space_heater",
    "space heater",
    &[
        "heater",
        "oil heater",
        "oil-filled radiator",
        "electric heater",
        "portable heater",
        "fan heater",
        "convector heater",
    ],
    &["home", "office", "appliance"],
    "a portable oil-filled heater: a row of fins on castors with a control box",
    &["heater", "appliance"],
    Kind::LargeAppliance,
    PlacementKind::Floor,
    false,
    // De'Longhi oil-filled radiators: 35–50 × 25–30 × 62–66 cm.
    &size3(0.42, 0.27, 0.64, 0.7, 1.3, 0.06),
    build_space_heater,
);

fn build_space_heater(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material("fins", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.75, 0.76, 0.78, 1.0]]), true);
    let dark = b.material("castors", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw * 0.8, -hd, 0.0], [hw * 0.8, hd, 0.06], dark);
    let n = ((w - 0.08) / 0.045).floor().max(3.0) as usize;
    for x in spread(-hw + 0.06, hw, n) {
        decal_between(b, [x - 0.012, -hd * 0.8, 0.06], [x + 0.012, hd * 0.8, h - 0.02], paint);
    }
    collider_between(b, [-hw + 0.05, -hd * 0.8, 0.06], [hw, hd * 0.8, h]);
    slab(b, [-hw, -hd * 0.6, 0.2], [-hw + 0.08, hd * 0.6, h], paint);
    knobs(b, &[-hw + 0.04], hd * 0.6, h - 0.08, 0.014, dark);
    0.0
}

pub(crate) const RADIATOR: Category = def(
    "radiator",
    "radiator",
    &[
        "heating radiator",
        "wall radiator",
        "panel radiator",
        "column radiator",
        "central heating radiator",
        "convector",
    ],
    &["home", "office", "fixture"],
    "a white panel radiator on the wall just above the floor",
    &["heater", "fixture"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // Type 22 panel radiators: 40–160 × 10 × 30–90 cm, 15 cm above the floor.
    &[
        ParamDef::new("width", 1.0, 0.4, 2.0, 0.2, "along X"),
        ParamDef::new("depth", 0.12, 0.08, 0.16, 0.05, "out from the wall"),
        ParamDef::new("height", 0.75, 0.45, 1.05, 0.1, "floor to the top"),
    ],
    build_radiator,
);

fn build_radiator(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let white = b.material("panel", pick(rng, &[[0.96, 0.96, 0.95, 1.0], [0.85, 0.86, 0.86, 1.0]]), true);
    let valve = b.material("valve", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let z0 = 0.15f64.min(h * 0.3);
    // Two legs, then two panels with convector fins between them.
    for x in [-hw + 0.08, hw - 0.08] {
        slab(b, [x - 0.02, -hd, 0.0], [x + 0.02, hd * 0.2, z0 + 0.01], valve);
    }
    slab(b, [-hw, -hd, z0], [hw, -hd + 0.03, h], white);
    slab(b, [-hw, hd - 0.03, z0], [hw, hd, h], white);
    collider_between(b, [-hw, -hd + 0.029, z0 + 0.03], [hw, hd - 0.029, h - 0.03]);
    decal_between(b, [-hw - 0.0, -hd + 0.025, h - 0.005], [hw, hd - 0.025, h - 0.001], white);
    rod(b, [hw - 0.03, 0.0, z0 - 0.02], 0.012, 0.04, Axis::Z, valve);
    0.0
}

pub(crate) const AIR_CONDITIONER: Category = def(
    "air_conditioner",
    "air conditioner",
    &["portable air conditioner", "air conditioning unit", "ac unit", "aircon", "a/c unit", "portable ac"],
    &["home", "office", "appliance"],
    "a portable air conditioner on castors with a grille on top and an exhaust hose at the back",
    &["appliance", "cooler"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // De'Longhi Pinguino / Midea portable units: 44–48 × 36–40 × 70–78 cm.
    &size3(0.46, 0.38, 0.74, 0.6, 1.3, 0.05),
    build_air_conditioner,
);

fn build_air_conditioner(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, &[[0.96, 0.96, 0.95, 1.0], [0.85, 0.86, 0.86, 1.0]]), true);
    let grille = b.material("grille", pick(rng, DARK), false);
    let display = b.material("display", [0.1, 0.3, 0.45, 1.0], false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, 0.05, body);
    decal_between(b, [-w * 0.35, -d * 0.3, h - 0.003], [w * 0.35, d * 0.3, h + 0.001], grille);
    decal_between(b, [-w * 0.15, d / 2.0 - 0.001, h * 0.8], [w * 0.15, d / 2.0 + 0.002, h * 0.88], display);
    decal_between(b, [-w * 0.3, d / 2.0 - 0.001, h * 0.15], [w * 0.3, d / 2.0 + 0.002, h * 0.55], grille);
    0.0
}

pub(crate) const VACUUM_CLEANER: Category = def(
    "vacuum_cleaner",
    "vacuum cleaner",
    &["vacuum", "hoover", "upright vacuum", "stick vacuum", "hoover vacuum", "canister vacuum"],
    &["home", "office", "appliance", "cleaning"],
    "an upright vacuum cleaner standing on its floor head",
    &["cleaner", "appliance", "cleaning equipment"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Upright vacuums (Dyson, Shark): 30–35 × 25–35 × 105–115 cm.
    &size3(0.32, 0.3, 1.1, 0.7, 1.2, 0.05),
    build_vacuum_cleaner,
);

fn build_vacuum_cleaner(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell = b.material(
        "body",
        pick(rng, &[[0.55, 0.2, 0.6, 1.0], [0.9, 0.75, 0.1, 1.0], [0.6, 0.62, 0.65, 1.0], [0.2, 0.45, 0.7, 1.0]]),
        true,
    );
    let grey = b.material("grey", pick(rng, DARK), false);
    let bin = b.material("bin", [0.7, 0.75, 0.78, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    // The floor head in front, the body with its dust bin behind it, the handle up top.
    slab(b, [-hw, 0.0, 0.0], [hw, hd, 0.08], grey);
    slab(b, [-w * 0.3, -hd, 0.02], [w * 0.3, 0.02, h * 0.6], shell);
    lathe(
        b,
        0,
        [0.0, -hd * 0.4],
        (w * 0.18).min(hd * 0.55),
        h * 0.25,
        h * 0.3,
        &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        bin,
    );
    slab(b, [-0.02, -hd * 0.3, h * 0.6 - 0.002], [0.02, -hd * 0.3 + 0.04, h], grey);
    0.0
}

pub(crate) const ROBOT_VACUUM: Category = def(
    "robot_vacuum",
    "robot vacuum",
    &["roomba", "robotic vacuum", "robot vacuum cleaner", "robot hoover", "robovac"],
    &["home", "appliance", "small", "floor", "round"],
    "a round low robot vacuum cleaner",
    &["cleaner", "appliance", "robot"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // iRobot Roomba / Roborock: 33–35 cm across, 8–10 cm tall.
    &[
        ParamDef::new("width", 0.34, 0.25, 0.4, 0.04, "diameter"),
        ParamDef::new("depth", 0.34, 0.25, 0.4, 0.04, "diameter (as width)"),
        ParamDef::new("height", 0.09, 0.07, 0.11, 0.06, "height"),
    ],
    build_robot_vacuum,
);

fn build_robot_vacuum(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let shell = b.material(
        "shell",
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.95, 0.95, 0.94, 1.0], [0.45, 0.47, 0.5, 1.0]]),
        true,
    );
    let bumper = b.material("bumper", INK, false);
    let button = b.material("button", LABEL_WHITE, false);
    round_body(b, r, h, &[[0.0, 0.0], [0.95, 0.0], [1.0, 0.2], [1.0, 0.8], [0.9, 1.0], [0.0, 1.0]], shell);
    lathe(b, 0, [0.0, 0.0], r * 1.005, h * 0.15, h * 0.5, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], bumper);
    lathe(b, 0, [0.0, r * 0.4], r * 0.12, h - 0.001, 0.002, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], button);
    3.5
}

pub(crate) const CANDLE: Category = def(
    "candle",
    "candle",
    &["pillar candle", "candle jar", "scented candle", "tea light"],
    &["home", "tabletop", "small", "graspable", "round"],
    "a round wax pillar candle with a wick",
    &["decoration", "light"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Pillar candles: 7 × 10 cm to 7.5 × 15 cm.
    &[
        ParamDef::new("width", 0.072, 0.04, 0.1, 0.08, "diameter"),
        ParamDef::new("depth", 0.072, 0.04, 0.1, 0.08, "diameter (as width)"),
        ParamDef::new("height", 0.11, 0.05, 0.2, 0.15, "height"),
    ],
    build_candle,
);

fn build_candle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let wax = b.material(
        "wax",
        pick(rng, &[[0.96, 0.94, 0.88, 1.0], [0.8, 0.15, 0.12, 1.0], [0.6, 0.75, 0.85, 1.0], [0.85, 0.7, 0.5, 1.0]]),
        true,
    );
    let wick = b.material("wick", INK, false);
    round_solid(b, 0, [0.0, 0.0], w / 2.0, 0.0, h - 0.008, wax);
    decal_between(b, [-0.0012, -0.0012, h - 0.009], [0.0012, 0.0012, h], wick);
    collider_between(b, [-0.0012, -0.0012, h - 0.009], [0.0012, 0.0012, h]);
    (w * w * h * 700.0).max(0.05)
}

pub(crate) const TISSUE_BOX: Category = def(
    "tissue_box",
    "tissue box",
    &["box of tissues", "kleenex", "tissues", "facial tissues", "napkin box", "glove box"],
    &["home", "office", "hospital", "tabletop", "small", "graspable"],
    "a box of facial tissues with one tissue pulled up through the slot",
    &["box", "package", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Kleenex regular boxes: 22–24 × 11–12 × 8–9 cm; cube boxes 11 × 11 × 13 cm.
    &size3(0.235, 0.115, 0.09, 0.5, 1.4, 0.08),
    build_tissue_box,
);

fn build_tissue_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let print = b.material(
        "print",
        pick(rng, &[[0.4, 0.6, 0.8, 1.0], [0.85, 0.6, 0.7, 1.0], [0.55, 0.7, 0.45, 1.0], [0.95, 0.95, 0.94, 1.0]]),
        true,
    );
    let tissue = b.material("tissue", LABEL_WHITE, false);
    let top = h - 0.012;
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, top], print);
    decal_between(b, [-w * 0.15, -d * 0.12, top - 0.001], [w * 0.15, d * 0.12, h], tissue);
    collider_between(b, [-w * 0.15, -d * 0.12, top - 0.001], [w * 0.15, d * 0.12, h]);
    0.15
}

pub(crate) const TABLE_CLOCK: Category = def(
    "table_clock",
    "clock",
    &["alarm clock", "bedside clock", "desk clock", "mantel clock", "digital clock"],
    &["home", "office", "tabletop", "small", "graspable"],
    "a small clock with a round face that stands on a table",
    &["timepiece", "device"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Alarm clocks: 10–15 × 5–7 × 10–14 cm.
    &size3(0.12, 0.06, 0.12, 0.6, 1.6, 0.1),
    build_table_clock,
);

fn build_table_clock(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material(
        "case",
        pick(rng, &[[0.75, 0.15, 0.12, 1.0], [0.12, 0.12, 0.13, 1.0], [0.9, 0.9, 0.88, 1.0], [0.55, 0.4, 0.25, 1.0]]),
        true,
    );
    let face = b.material("face", LABEL_WHITE, false);
    let hands = b.material("hands", INK, false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, w.min(h) * 0.2, case);
    let r = w.min(h) * 0.38;
    b.visual(
        Shape::Cylinder { radius: r, half_height: 0.001 },
        super::kit::along([0.0, d / 2.0 + 0.0005, h / 2.0], Axis::Y),
        face,
    );
    decal_between(b, [-0.0012, d / 2.0 + 0.001, h / 2.0], [0.0012, d / 2.0 + 0.002, h / 2.0 + r * 0.75], hands);
    decal_between(b, [0.0, d / 2.0 + 0.001, h / 2.0 - 0.0012], [r * 0.5, d / 2.0 + 0.002, h / 2.0 + 0.0012], hands);
    0.25
}

pub(crate) const PARK_BENCH: Category = def(
    "park_bench",
    "park bench",
    &["garden bench", "dining bench", "entryway bench", "hallway bench", "wooden bench", "waiting bench", "bench seat"],
    &["furniture", "seating", "home", "outdoor"],
    "a wooden bench with slats and a backrest on steel legs",
    &["seat", "bench", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Garden benches: 120–180 × 55–65 × 75–85 cm, seat at 45 cm.
    &[
        ParamDef::new("width", 1.5, 0.9, 2.0, 0.1, "along X"),
        ParamDef::new("depth", 0.6, 0.35, 0.7, 0.06, "along Y"),
        ParamDef::new("height", 0.8, 0.45, 0.9, 0.05, "floor to the top of the back"),
    ],
    build_park_bench,
);

fn build_park_bench(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wood = b.material("slats", pick(rng, WOOD), true);
    let iron =
        b.material("frame", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.15, 0.25, 0.18, 1.0], [0.45, 0.47, 0.5, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    // Backless when too low for a backrest above the seat.
    let sh = if h < 0.6 { h } else { 0.45 };
    for x in [-hw + 0.06, hw - 0.06] {
        slab(b, [x - 0.025, -hd, 0.0], [x + 0.025, hd, sh - 0.04], iron);
    }
    let seat = slab(b, [-hw, -hd + 0.1, sh - 0.04], [hw, hd, sh], wood);
    for y in spread(-hd + 0.1, hd, 4).into_iter().skip(1) {
        decal_between(b, [-hw, y - 0.004, sh - 0.001], [hw, y + 0.004, sh + 0.001], iron);
    }
    if h > sh {
        slab(b, [-hw, -hd, sh - 0.041], [hw, -hd + 0.06, h], wood);
    } else {
        slab(b, [-hw, -hd, sh - 0.041], [hw, -hd + 0.1, sh - 0.002], wood);
    }
    b.surface("seat", seat, [-hw, -hd + 0.1], [hw, hd], None);
    0.0
}
