//! The bathroom and the laundry: toilets, baths, shower cubicles and vanity units; washing
//! machines and tumble dryers with porthole doors that swing open; laundry baskets,
//! ironing boards and irons; and the small things on the shelves (towels, toilet rolls,
//! soap, shampoo, toothbrushes). Sizes from product ranges (Ideal Standard, IKEA, Bosch),
//! noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::forms::{Seg, def, knobs, lathe, long_item, rounded_box, size3, spread, stretch_y, whd};
use super::kit::{
    Axis, INK, LABEL_WHITE, OFFICE_PAINT, STEEL, WOOD, along, collider_between, decal_between, pick, shade, slab,
};
use super::parts::{Hinge, MOVING_GAP, carcass, decal_on, hinged_door, open_box, round_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const SANITARY: [f32; 4] = [0.96, 0.96, 0.95, 1.0];
const TOILETRY: &[&str] = &["bathroom", "home", "tabletop", "small", "graspable"];

pub(crate) const TOILET: Category = def(
    "toilet",
    "toilet",
    &["wc", "lavatory", "loo", "toilet bowl", "water closet", "commode toilet", "close-coupled toilet"],
    &["bathroom", "fixture", "plumbing"],
    "a white close-coupled toilet: a bowl with a seat and lid, a cistern behind it",
    &["fixture", "plumbing fixture"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // Close-coupled toilets (Ideal Standard, Roca): 36–40 × 62–70 × 76–82 cm.
    &[
        ParamDef::new("width", 0.38, 0.34, 0.45, 0.05, "along X"),
        ParamDef::new("depth", 0.66, 0.55, 0.75, 0.04, "wall to the front of the bowl"),
        ParamDef::new("height", 0.78, 0.7, 0.85, 0.03, "floor to the top of the cistern"),
    ],
    build_toilet,
);

fn build_toilet(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let china = b.material("china", SANITARY, true);
    let seat = b.material("seat", pick(rng, &[SANITARY, [0.9, 0.9, 0.88, 1.0], [0.3, 0.22, 0.15, 1.0]]), false);
    let flush = b.material("flush", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let cistern_d = 0.18f64.min(d * 0.3);
    let bowl_h = 0.4;
    // The pedestal and the bowl (an oval), the seat and lid on it, the cistern at the wall.
    let ry = (d - cistern_d) / 2.0;
    let cy = -hd + cistern_d + ry - 0.02;
    let bowl = revolve(
        &[[0.0, 0.0], [hw * 0.55, 0.0], [hw * 0.6, bowl_h * 0.5], [hw, bowl_h - 0.03], [0.0, bowl_h - 0.03]],
        ROUND,
    );
    b.visual_mesh_on(0, &stretch_y(bowl, (ry + 0.02) / hw), Pose::from_pos([0.0, cy, 0.0]), china);
    collider_between(b, [-hw * 0.6, cy - ry * 0.6, 0.0], [hw * 0.6, cy + ry * 0.6, bowl_h - 0.03]);
    collider_between(b, [-hw, cy - ry, bowl_h * 0.5], [hw, hd, bowl_h - 0.03]);
    slab(b, [-hw + 0.005, cy - ry + 0.01, bowl_h - 0.031], [hw - 0.005, hd - 0.005, bowl_h], seat);
    slab(b, [-hw, -hd, bowl_h * 0.5], [hw, -hd + cistern_d, h], china);
    decal_between(b, [-0.02, -hd + cistern_d * 0.4, h - 0.001], [0.02, -hd + cistern_d * 0.6, h + 0.003], flush);
    0.0
}

pub(crate) const BATHTUB: Category = def(
    "bathtub",
    "bathtub",
    &["bath tub", "bath", "soaking tub", "freestanding bath", "bathing tub"],
    &["bathroom", "fixture", "plumbing", "open"],
    "a white rectangular bathtub, open on top",
    &["fixture", "plumbing fixture", "tub"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // Standard baths: 170 × 70 × 55–58 cm (UK), 152 × 76 × 50 cm (US alcove).
    &[
        ParamDef::new("width", 1.7, 1.4, 1.9, 0.05, "along X"),
        ParamDef::new("depth", 0.72, 0.65, 0.85, 0.04, "along Y"),
        ParamDef::new("height", 0.56, 0.45, 0.65, 0.04, "floor to the rim"),
    ],
    build_bathtub,
);

fn build_bathtub(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let enamel = b.material("enamel", SANITARY, true);
    let tap = b.material("tap", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let rim = 0.08;
    // Panels and rim around a basin whose floor is a surface.
    let floor = slab(b, [-hw, -hd, 0.0], [hw, hd, 0.12], enamel);
    for (y0, y1) in [(-hd, -hd + rim), (hd - rim, hd)] {
        slab(b, [-hw, y0, 0.119], [hw, y1, h], enamel);
    }
    for (x0, x1) in [(-hw, -hw + rim * 1.2), (hw - rim * 1.2, hw)] {
        slab(b, [x0, -hd + rim - 0.001, 0.118], [x1, hd - rim + 0.001, h], enamel);
    }
    decal_between(b, [hw - rim * 0.9, -0.015, h], [hw - rim * 0.3, 0.015, h + 0.004], tap);
    b.surface(
        "inside",
        floor,
        [-hw + rim * 1.2 + 0.02, -hd + rim + 0.02],
        [hw - rim * 1.2 - 0.02, hd - rim - 0.02],
        Some(h - floor - 0.01),
    );
    0.0
}

pub(crate) const SHOWER: Category = def(
    "shower",
    "shower",
    &["shower cubicle", "shower stall", "shower enclosure", "shower cabin", "walk-in shower", "shower tray"],
    &["bathroom", "fixture", "plumbing", "tall"],
    "a square shower cubicle: a low tray, glass sides and a shower head on a rail",
    &["fixture", "plumbing fixture", "enclosure"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // Shower enclosures: 80–100 cm square, 190–200 cm tall.
    &[
        ParamDef::new("width", 0.9, 0.7, 1.2, 0.08, "along X"),
        ParamDef::new("depth", 0.9, 0.7, 1.2, 0.08, "along Y"),
        ParamDef::new("height", 2.0, 1.85, 2.1, 0.02, "floor to the top of the glass"),
    ],
    build_shower,
);

fn build_shower(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let tray = b.material("tray", SANITARY, true);
    let glass = b.material("glass", [0.75, 0.85, 0.88, 1.0], false);
    let chrome = b.material("chrome", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let floor = slab(b, [-hw, -hd, 0.0], [hw, hd, 0.06], tray);
    let t = 0.01;
    // Glass on the two open sides (+X, +Y), the door half of the front.
    slab(b, [hw - t, -hd, 0.059], [hw, hd, h], glass);
    slab(b, [-hw, hd - t, 0.059], [hw - t - 0.001, hd, h], glass);
    slab(b, [-hw, -hd, 0.059], [-hw + 0.02, -hd + 0.02, h], chrome);
    decal_between(b, [-hw + 0.02, -hd + 0.03, h - 0.2], [-hw + 0.2, -hd + 0.05, h - 0.18], chrome);
    b.visual(
        Shape::Cylinder { radius: 0.08, half_height: 0.008 },
        Pose::from_pos([-hw + 0.2, -hd + 0.12, h - 0.2]),
        chrome,
    );
    b.surface("tray", floor, [-hw + 0.05, -hd + 0.05], [hw - t - 0.02, hd - t - 0.02], Some(h - floor - 0.3));
    0.0
}

pub(crate) const BATHROOM_VANITY: Category = def(
    "bathroom_vanity",
    "bathroom vanity",
    &["vanity unit", "vanity", "bathroom sink", "bathroom basin", "washstand", "vanity cabinet", "sink cabinet"],
    &["bathroom", "furniture", "plumbing", "surface", "storage"],
    "a bathroom vanity: a basin set in a top over a cabinet with two doors, a tap behind the basin",
    &["sink", "cabinet", "furniture", "fixture"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // IKEA GODMORGON / ENHET vanities: 60–120 × 45–49 × 85 cm (basin top at 85).
    &[
        ParamDef::new("width", 0.8, 0.5, 1.4, 0.12, "along X"),
        ParamDef::new("depth", 0.47, 0.38, 0.55, 0.04, "along Y"),
        ParamDef::new("height", 1.05, 0.95, 1.15, 0.03, "floor to the top of the tap"),
    ],
    build_bathroom_vanity,
);

fn build_bathroom_vanity(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = if rng.chance(0.5) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", rgba, true);
    let doors = b.material("doors", shade(rgba, 1.04), false);
    let china = b.material("basin", SANITARY, false);
    let tap = b.material("tap", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top = 0.85f64.min(h - 0.12);
    let dt = 0.018;
    let opening = hd - dt - MOVING_GAP;
    carcass(b, -hw, hw, -hd, opening, 0.0, top - 0.04, 0.018, body);
    // The basin top, with a sunken bowl drawn in (it collides as the top).
    let deck = slab(b, [-hw, -hd, top - 0.04], [hw, hd, top], china);
    let r = (w * 0.3).min(hd * 0.75);
    lathe(b, 0, [0.0, 0.02], r, top - 0.0005, 0.002, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], tap);
    decal_between(b, [-0.012, -hd + 0.03, top], [0.012, -hd + 0.055, h], tap);
    decal_between(b, [-0.01, -hd + 0.03, h - 0.02], [0.01, -hd + 0.15, h], tap);
    collider_between(b, [-0.012, -hd + 0.03, top], [0.012, -hd + 0.15, h]);
    let n = if w > 0.7 { 2 } else { 1 };
    for k in 0..n {
        let x0 = -hw + 0.002 + (w - 0.004) * k as f64 / n as f64;
        let x1 = x0 + (w - 0.004) / n as f64 - 0.003;
        let hinge = if k == 0 { Hinge::MinX } else { Hinge::MaxX };
        hinged_door(
            b,
            &format!("door_{}", k + 1),
            hinge,
            [x0, x1],
            [0.01, top - 0.043],
            hd - dt,
            dt,
            doors,
            tap,
            top - 0.12,
            1.5,
        );
    }
    b.surface("left_of_basin", deck, [-hw, -hd + 0.16], [-r - 0.01, hd], None);
    0.0
}

pub(crate) const TOWEL: Category = def(
    "towel",
    "towel",
    &[
        "bath towel",
        "hand towel",
        "tea towel",
        "dish towel",
        "folded towel",
        "beach towel",
        "washcloth",
        "face cloth",
        "dishrag",
        "dishcloth",
        "dish cloth",
    ],
    &["bathroom", "home", "textile", "tabletop", "small", "graspable"],
    "a folded towel",
    &["textile", "linen"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // A 50 × 100 cm hand towel folded in six: about 33 × 25 × 5 cm.
    &size3(0.33, 0.25, 0.05, 0.4, 2.0, 0.1),
    build_towel,
);

fn build_towel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let cloth = pick(
        rng,
        &[
            [0.95, 0.95, 0.94, 1.0],
            [0.35, 0.55, 0.7, 1.0],
            [0.85, 0.75, 0.6, 1.0],
            [0.6, 0.65, 0.45, 1.0],
            [0.8, 0.35, 0.35, 1.0],
        ],
    );
    let body = b.material("cloth", cloth, true);
    let hem = b.material("hem", shade(cloth, 0.82), false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, h * 0.45, body);
    decal_between(b, [-w / 2.0 + 0.02, -d / 2.0 - 0.001, h * 0.3], [w / 2.0 - 0.02, -d / 2.0 + 0.004, h * 0.45], hem);
    (w * d * h * 180.0).max(0.05)
}

pub(crate) const TOILET_PAPER: Category = def(
    "toilet_paper",
    "toilet roll",
    &[
        "loo roll",
        "toilet tissue",
        "paper roll",
        "roll of toilet paper",
        "kitchen roll",
        "paper towel roll",
        "paper towels",
    ],
    &["bathroom", "home", "tabletop", "small", "graspable", "round"],
    "a roll of toilet paper standing on its end",
    &["roll", "paper", "toiletry"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Toilet rolls: 10–12 cm across, 10 cm tall; kitchen rolls 11 × 23 cm.
    &[
        ParamDef::new("width", 0.11, 0.09, 0.14, 0.05, "diameter"),
        ParamDef::new("depth", 0.11, 0.09, 0.14, 0.05, "diameter (as width)"),
        ParamDef::new("height", 0.1, 0.09, 0.25, 0.03, "height"),
    ],
    build_toilet_paper,
);

fn build_toilet_paper(p: &Params, _rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let paper = b.material("paper", [0.97, 0.97, 0.96, 1.0], true);
    let core = b.material("core", [0.7, 0.55, 0.38, 1.0], false);
    let ring = revolve(&[[0.022, 0.0], [r, 0.0], [r, h], [0.022, h]], ROUND);
    b.visual_mesh_on(0, &ring, Pose::IDENTITY, paper);
    lathe(b, 0, [0.0, 0.0], 0.0225, 0.0005, h - 0.001, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], core);
    round_collider(b, 0, [0.0, 0.0], r, 0.0, h);
    (r * r * h * 400.0).max(0.08)
}

/// A pump or cap bottle: a round (or oval, `oval` < 1 across Y) body and a cap on top.
fn pump_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, oval: bool, pump: bool) -> f64 {
    let (w, d, h) = whd(p);
    let r = w / 2.0;
    let colours = &[
        [0.95, 0.95, 0.94, 1.0],
        [0.4, 0.6, 0.8, 1.0],
        [0.85, 0.6, 0.7, 1.0],
        [0.55, 0.75, 0.45, 1.0],
        [0.95, 0.8, 0.3, 1.0],
    ];
    let body = b.material("body", pick(rng, colours), true);
    let cap = b.material(
        "cap",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.15, 0.15, 0.16, 1.0], [0.75, 0.76, 0.78, 1.0]]),
        false,
    );
    let label = b.material("label", LABEL_WHITE, false);
    let zc = h * if pump { 0.72 } else { 0.85 };
    let bodym = revolve(&[[0.0, 0.0], [r * 0.95, 0.0], [r, 0.01], [r, zc * 0.85], [r * 0.6, zc], [0.0, zc]], ROUND);
    let f = if oval { d / w } else { 1.0 };
    b.visual_mesh_on(0, &stretch_y(bodym, f), Pose::IDENTITY, body);
    let band = revolve(
        &[[r - 0.001, zc * 0.3], [r + 0.0008, zc * 0.3], [r + 0.0008, zc * 0.65], [r - 0.001, zc * 0.65]],
        ROUND,
    );
    b.visual_mesh_on(0, &stretch_y(band, f), Pose::IDENTITY, label);
    if oval {
        collider_between(b, [-r, -d / 2.0, 0.0], [r, d / 2.0, zc]);
    } else {
        round_collider(b, 0, [0.0, 0.0], r, 0.0, zc);
    }
    let rc = (r * 0.35).max(0.008);
    lathe(b, 0, [0.0, 0.0], rc, zc - 0.001, h - zc + 0.001, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], cap);
    collider_between(b, [-rc * 0.7, -rc * 0.7, zc - 0.001], [rc * 0.7, rc * 0.7, h]);
    if pump {
        decal_between(b, [0.0, -0.006, h - 0.012], [r * 0.9, 0.006, h - 0.002], cap);
    }
    (std::f64::consts::PI * r * r * f * zc * 900.0).max(0.05)
}

pub(crate) const SOAP_DISPENSER: Category = def(
    "soap_dispenser",
    "soap dispenser",
    &[
        "hand soap",
        "liquid soap",
        "pump bottle",
        "hand sanitizer",
        "hand sanitiser",
        "sanitizer bottle",
        "lotion pump",
        "soap pump",
    ],
    &["bathroom", "home", "tabletop", "small", "graspable", "round"],
    "a pump bottle of liquid hand soap or sanitiser",
    &["bottle", "dispenser", "toiletry", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 250–500 ml pump bottles: 6.5–8 cm across, 17–21 cm to the pump.
    &[
        ParamDef::new("width", 0.072, 0.05, 0.1, 0.08, "body diameter"),
        ParamDef::new("depth", 0.072, 0.05, 0.1, 0.08, "body diameter (as width)"),
        ParamDef::new("height", 0.19, 0.13, 0.24, 0.08, "to the top of the pump"),
    ],
    build_soap_dispenser,
);

fn build_soap_dispenser(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    pump_bottle(p, rng, b, false, true)
}

pub(crate) const SHAMPOO_BOTTLE: Category = def(
    "shampoo_bottle",
    "shampoo bottle",
    &[
        "shampoo",
        "conditioner",
        "body wash",
        "shower gel",
        "lotion bottle",
        "lotion",
        "toiletry bottle",
        "squeeze bottle",
    ],
    TOILETRY,
    "an oval plastic bottle of shampoo or shower gel with a flip cap",
    &["bottle", "toiletry", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 250–400 ml shampoo bottles: 6–8 × 3.5–5 × 18–22 cm.
    &[
        ParamDef::new("width", 0.07, 0.05, 0.09, 0.08, "front width"),
        ParamDef::new("depth", 0.042, 0.03, 0.05, 0.08, "side depth"),
        ParamDef::new("height", 0.2, 0.13, 0.25, 0.08, "to the top of the cap"),
    ],
    build_shampoo_bottle,
);

fn build_shampoo_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    pump_bottle(p, rng, b, true, false)
}

pub(crate) const TOOTHBRUSH: Category = def(
    "toothbrush",
    "toothbrush",
    &["tooth brush", "electric toothbrush", "manual toothbrush"],
    TOILETRY,
    "a toothbrush lying flat",
    &["brush", "toiletry"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Manual toothbrushes: 18–19 × 1.5–2 × 2–2.5 cm (bristles up).
    &[
        ParamDef::new("width", 0.19, 0.15, 0.25, 0.04, "length"),
        ParamDef::new("depth", 0.018, 0.012, 0.03, 0.08, "handle width"),
        ParamDef::new("height", 0.025, 0.015, 0.04, 0.08, "to the tips of the bristles"),
    ],
    build_toothbrush,
);

fn build_toothbrush(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let handle = b.material(
        "handle",
        pick(rng, &[[0.2, 0.45, 0.8, 1.0], [0.85, 0.2, 0.2, 1.0], [0.3, 0.7, 0.4, 1.0], [0.95, 0.95, 0.94, 1.0]]),
        true,
    );
    let bristles = b.material("bristles", [0.95, 0.96, 0.98, 1.0], false);
    let head = w * 0.15;
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, w / 2.0, d, h * 0.45, handle),
            Seg::flat(-w / 2.0 + 0.005, -w / 2.0 + head, d * 0.8, h, bristles),
        ],
    );
    0.02
}

pub(crate) const BATHROOM_SCALE: Category = def(
    "bathroom_scale",
    "bathroom scale",
    &["scales", "weighing scale", "body scale", "personal scale", "digital scale"],
    &["bathroom", "home", "floor", "small"],
    "a flat square bathroom scale with a display",
    &["scale", "device"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Digital bathroom scales: 28–32 cm square, 2–3 cm thick.
    &size3(0.3, 0.3, 0.025, 0.8, 1.3, 0.05),
    build_bathroom_scale,
);

fn build_bathroom_scale(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let glass =
        b.material("top", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.95, 0.95, 0.94, 1.0], [0.75, 0.8, 0.82, 1.0]]), true);
    let display = b.material("display", [0.1, 0.3, 0.45, 1.0], false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, w * 0.08, glass);
    decal_between(b, [-w * 0.15, d * 0.3, h - 0.001], [w * 0.15, d * 0.42, h + 0.001], display);
    1.6
}

pub(crate) const HAIR_DRYER: Category = def(
    "hair_dryer",
    "hair dryer",
    &["hairdryer", "blow dryer", "hair drier", "blow-dryer"],
    &["bathroom", "home", "appliance", "tabletop", "small", "graspable"],
    "a hair dryer lying on its side: a round barrel with a nozzle and a handle",
    &["appliance", "dryer"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Hair dryers: barrel 22–26 cm, 20–24 cm to the end of the handle, 8–10 cm thick.
    &[
        ParamDef::new("width", 0.24, 0.18, 0.3, 0.06, "barrel length along X"),
        ParamDef::new("depth", 0.22, 0.16, 0.26, 0.06, "barrel to handle end along Y"),
        ParamDef::new("height", 0.09, 0.07, 0.11, 0.06, "thickness lying"),
    ],
    build_hair_dryer,
);

fn build_hair_dryer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell = b.material(
        "shell",
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.85, 0.2, 0.35, 1.0], [0.95, 0.95, 0.94, 1.0]]),
        true,
    );
    let grille = b.material("grille", INK, false);
    let r = h / 2.0;
    let yb = d / 2.0 - r;
    b.visual_mesh_on(0, &sw_geom::cylinder_mesh(r, w * 0.35, ROUND), along([-w * 0.15, yb, r], Axis::X), shell);
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(r * 0.55, w * 0.15 + 0.002, ROUND),
        along([w * 0.35, yb, r], Axis::X),
        shell,
    );
    b.visual(
        Shape::Cylinder { radius: r * 0.8, half_height: 0.002 },
        along([-w / 2.0 + 0.002, yb, r], Axis::X),
        grille,
    );
    collider_between(b, [-w / 2.0, yb - r, 0.0], [w / 2.0, yb + r, h]);
    // The handle, down from the barrel to -Y.
    decal_between(b, [-w * 0.12, -d / 2.0, h * 0.15], [w * 0.05, yb - r + 0.005, h * 0.85], shell);
    collider_between(b, [-w * 0.12, -d / 2.0, 0.0], [w * 0.05, yb - r + 0.005, h * 0.85]);
    0.55
}

pub(crate) const WASHING_MACHINE: Category = def(
    "washing_machine",
    "washing machine",
    &[
        "washer",
        "clothes washer",
        "laundry machine",
        "front loader",
        "front-loading washer",
        "washer-dryer",
        "washing mashine",
    ],
    &["laundry", "appliance", "home", "surface"],
    "a front-loading washing machine with a round porthole door, a detergent drawer and a control panel",
    &["appliance", "machine", "washer"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Bosch Serie 4 / Samsung front loaders: 60 × 55–65 × 85 cm.
    &[
        ParamDef::new("width", 0.6, 0.55, 0.7, 0.02, "along X"),
        ParamDef::new("depth", 0.6, 0.5, 0.75, 0.04, "along Y, door included"),
        ParamDef::new("height", 0.85, 0.8, 0.95, 0.02, "floor to top"),
    ],
    build_washing_machine,
);

/// A front-loading laundry machine: a carcass open at the front behind a square leaf
/// (hinged on −X) that carries a round porthole, a panel strip at the top with a
/// drawer and a dial. `glass` colours the porthole.
fn laundry_machine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, glass: [f32; 4], drawer: bool) -> f64 {
    let (w, d, h) = whd(p);
    let finish =
        pick(rng, &[[0.96, 0.96, 0.95, 1.0], [0.96, 0.96, 0.95, 1.0], [0.5, 0.52, 0.55, 1.0], [0.15, 0.15, 0.16, 1.0]]);
    let body = b.material("body", finish, true);
    let port = b.material("porthole", glass, false);
    let rim = b.material("rim", pick(rng, &[[0.75, 0.76, 0.78, 1.0], [0.2, 0.2, 0.21, 1.0]]), false);
    let panel = b.material("panel", shade(finish, 0.9), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.04;
    let opening = hd - dt - MOVING_GAP;
    let panel_h = 0.12;
    carcass(b, -hw, hw, -hd, opening, 0.0, h - panel_h, 0.02, body);
    let deck = slab(b, [-hw, -hd, h - panel_h - 0.001], [hw, hd, h], body);
    // The control strip: a drawer at the left (as you face it), a dial at the right.
    if drawer {
        decal_between(b, [hw - 0.2, hd - 0.001, h - panel_h + 0.02], [hw - 0.03, hd + 0.002, h - 0.02], panel);
    }
    knobs(b, &[-hw + 0.12], hd - 0.012, h - panel_h / 2.0, 0.03, rim);
    decal_between(b, [-0.08, hd - 0.001, h - panel_h + 0.03], [0.08, hd + 0.002, h - 0.03], panel);
    let door_z = [0.02, h - panel_h - 0.004];
    let leaf = hinged_door(
        b,
        "door",
        Hinge::MinX,
        [-hw + 0.004, hw - 0.004],
        door_z,
        hd - dt,
        dt,
        body,
        rim,
        (door_z[0] + door_z[1]) / 2.0,
        3.0,
    );
    let r = (w * 0.36).min((door_z[1] - door_z[0]) * 0.42);
    let zc = (door_z[1] - door_z[0]) * 0.5;
    let xc = (w - 0.008) / 2.0;
    b.visual_on(
        leaf,
        Shape::Cylinder { radius: r, half_height: 0.003 },
        along([xc, dt / 2.0 + 0.0015, zc], Axis::Y),
        rim,
    );
    b.visual_on(
        leaf,
        Shape::Cylinder { radius: r * 0.78, half_height: 0.002 },
        along([xc, dt / 2.0 + 0.0025, zc], Axis::Y),
        port,
    );
    decal_on(b, leaf, [xc * 2.0 - 0.05, dt / 2.0, zc - 0.05], [xc * 2.0 - 0.035, dt / 2.0 + 0.004, zc + 0.05], rim);
    b.surface("top", deck, [-hw, -hd], [hw, hd], None);
    0.0
}

fn build_washing_machine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    laundry_machine(p, rng, b, [0.3, 0.4, 0.45, 1.0], true)
}

pub(crate) const TUMBLE_DRYER: Category = def(
    "tumble_dryer",
    "tumble dryer",
    &["dryer", "clothes dryer", "drier", "tumble drier", "condenser dryer", "heat pump dryer"],
    &["laundry", "appliance", "home", "surface"],
    "a front-loading tumble dryer with a porthole door and a lint filter",
    &["appliance", "machine", "dryer"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Bosch / Beko condenser dryers: 60 × 60–65 × 85 cm.
    &[
        ParamDef::new("width", 0.6, 0.55, 0.7, 0.02, "along X"),
        ParamDef::new("depth", 0.62, 0.5, 0.75, 0.04, "along Y, door included"),
        ParamDef::new("height", 0.85, 0.8, 0.95, 0.02, "floor to top"),
    ],
    build_tumble_dryer,
);

fn build_tumble_dryer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    laundry_machine(p, rng, b, [0.12, 0.12, 0.14, 1.0], false)
}

pub(crate) const LAUNDRY_BASKET: Category = def(
    "laundry_basket",
    "laundry basket",
    &["laundry hamper", "hamper", "clothes basket", "washing basket", "laundry bin", "wash basket"],
    &["laundry", "home", "container", "open", "graspable"],
    "an open plastic laundry basket with handle holes",
    &["basket", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Laundry baskets: 55–60 × 38–42 × 25–30 cm (hampers 40 × 35 × 55 cm).
    &size3(0.56, 0.4, 0.28, 0.7, 1.6, 0.06),
    build_laundry_basket,
);

fn build_laundry_basket(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba =
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.4, 0.6, 0.8, 1.0], [0.55, 0.45, 0.35, 1.0], [0.8, 0.35, 0.45, 1.0]]);
    let plastic = b.material("plastic", rgba, true);
    let holes = b.material("holes", shade(rgba, 0.6), false);
    let floor = open_box(b, w, d, h, 0.008, plastic);
    for x in spread(-w * 0.4, w * 0.4, 6) {
        decal_between(b, [x - 0.015, d / 2.0 - 0.001, h * 0.3], [x + 0.015, d / 2.0 + 0.001, h * 0.7], holes);
    }
    for s in [-1.0, 1.0] {
        let x = s * (w / 2.0);
        decal_between(b, [x - 0.001, -0.05, h * 0.75], [x + 0.001, 0.05, h * 0.9], holes);
    }
    b.surface("inside", floor, [-w / 2.0 + 0.03, -d / 2.0 + 0.03], [w / 2.0 - 0.03, d / 2.0 - 0.03], None);
    0.8 + w * d * 2.0
}

pub(crate) const IRONING_BOARD: Category = def(
    "ironing_board",
    "ironing board",
    &["iron board", "ironing table", "ironing stand"],
    &["laundry", "home", "furniture", "surface"],
    "an ironing board on folding legs, narrow at one end",
    &["board", "table", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Ironing boards: 110–130 × 33–45 cm tops, 75–95 cm high.
    &[
        ParamDef::new("width", 1.22, 0.9, 1.4, 0.05, "along X"),
        ParamDef::new("depth", 0.38, 0.3, 0.46, 0.05, "along Y"),
        ParamDef::new("height", 0.88, 0.7, 0.98, 0.05, "floor to top"),
    ],
    build_ironing_board,
);

fn build_ironing_board(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let cover =
        b.material("cover", pick(rng, &[[0.6, 0.7, 0.8, 1.0], [0.85, 0.82, 0.72, 1.0], [0.7, 0.4, 0.4, 1.0]]), true);
    let legs = b.material("legs", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top = slab(b, [-hw + 0.1, -hd, h - 0.03], [hw, hd, h], cover);
    // The pointed end: a narrower block.
    slab(b, [-hw, -hd * 0.45, h - 0.03], [-hw + 0.101, hd * 0.45, h - 0.001], cover);
    // Crossed legs (drawn) standing on two foot bars; they collide as the bars and a
    // column where they cross.
    for (x0, x1) in [(-hw * 0.55, hw * 0.35), (hw * 0.35, -hw * 0.55)] {
        for y in [-hd * 0.7, hd * 0.7] {
            super::kit::strut(b, [x0, y, 0.03], [x1, y, h - 0.05], [0.03, 0.02], Axis::Y, legs, false);
        }
        slab(b, [x0 - 0.02, -hd * 0.8, 0.0], [x0 + 0.02, hd * 0.8, 0.03], legs);
    }
    collider_between(b, [-hw * 0.1 - 0.03, -hd * 0.72, 0.0], [-hw * 0.1 + 0.03, hd * 0.72, h - 0.029]);
    b.surface("top", top, [-hw + 0.1, -hd], [hw, hd], None);
    0.0
}

pub(crate) const CLOTHES_IRON: Category = def(
    "clothes_iron",
    "iron",
    &["steam iron", "flat iron", "electric iron", "laundry iron"],
    &["laundry", "home", "appliance", "tabletop", "small", "graspable"],
    "a steam iron standing on its heel plate",
    &["appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Steam irons: 26–30 × 11–13 × 13–15 cm.
    &size3(0.27, 0.12, 0.14, 0.8, 1.2, 0.05),
    build_clothes_iron,
);

fn build_clothes_iron(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell =
        b.material("shell", pick(rng, &[[0.3, 0.45, 0.75, 1.0], [0.6, 0.3, 0.6, 1.0], [0.95, 0.95, 0.94, 1.0]]), true);
    let plate = b.material("soleplate", [0.78, 0.79, 0.8, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    // The soleplate, pointed at +X, the body on it and the handle loop above.
    let sole = super::shapes::prism(&[[-hw, -hd], [hw * 0.4, -hd], [hw, 0.0], [hw * 0.4, hd], [-hw, hd]], 0.0, 0.02);
    b.visual_mesh_on(0, &sole, Pose::IDENTITY, plate);
    collider_between(b, [-hw, -hd, 0.0], [hw, hd, 0.02]);
    let bodym = super::shapes::prism(
        &[[-hw, -hd * 0.9], [hw * 0.3, -hd * 0.75], [hw * 0.85, 0.0], [hw * 0.3, hd * 0.75], [-hw, hd * 0.9]],
        0.0199,
        h * 0.55,
    );
    b.visual_mesh_on(0, &bodym, Pose::IDENTITY, shell);
    collider_between(b, [-hw, -hd * 0.85, 0.0199], [hw * 0.6, hd * 0.85, h * 0.55]);
    decal_between(b, [-hw * 0.8, -0.015, h * 0.85], [hw * 0.3, 0.015, h], shell);
    decal_between(b, [-hw * 0.8, -0.015, h * 0.54], [-hw * 0.6, 0.015, h * 0.86], shell);
    collider_between(b, [-hw * 0.8, -0.015, h * 0.54], [hw * 0.3, 0.015, h]);
    1.3
}

pub(crate) const DETERGENT_BOTTLE: Category = def(
    "detergent_bottle",
    "detergent bottle",
    &[
        "laundry detergent",
        "detergent",
        "fabric softener",
        "washing liquid",
        "cleaning product",
        "dish soap",
        "washing-up liquid",
    ],
    &["laundry", "home", "kitchen", "tabletop", "small", "graspable"],
    "a plastic jug of laundry detergent with a handle and a cap",
    &["bottle", "jug", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 1.5–3 l detergent jugs: 14–18 × 8–11 × 24–30 cm.
    &size3(0.15, 0.095, 0.27, 0.5, 1.3, 0.06),
    build_detergent_bottle,
);

fn build_detergent_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let plastic = b.material(
        "plastic",
        pick(
            rng,
            &[
                [0.95, 0.55, 0.1, 1.0],
                [0.2, 0.45, 0.8, 1.0],
                [0.35, 0.7, 0.4, 1.0],
                [0.6, 0.3, 0.65, 1.0],
                [0.95, 0.95, 0.94, 1.0],
            ],
        ),
        true,
    );
    let cap = b.material("cap", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.15, 0.15, 0.16, 1.0]]), false);
    let label = b.material("label", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let zs = h * 0.8;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, zs, d * 0.3, plastic);
    // A handle at −X, the spout and cap at +X.
    decal_between(b, [-hw, -hd * 0.4, zs - 0.002], [-hw + w * 0.4, hd * 0.4, h * 0.92], plastic);
    collider_between(b, [-hw, -hd * 0.4, zs - 0.002], [-hw + w * 0.4, hd * 0.4, h * 0.92]);
    let rc = (hd * 0.75).min(0.025);
    lathe(
        b,
        0,
        [hw - rc - 0.005, 0.0],
        rc,
        zs - 0.001,
        h - zs + 0.001,
        &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        cap,
    );
    collider_between(b, [hw - 2.0 * rc - 0.005, -rc * 0.7, zs - 0.001], [hw - 0.005, rc * 0.7, h]);
    decal_between(b, [-hw * 0.6, hd - 0.001, zs * 0.25], [hw * 0.6, hd + 0.001, zs * 0.7], label);
    (w * d * zs * 900.0).max(0.3)
}

pub(crate) const CLOTHES_HANGER: Category = def(
    "clothes_hanger",
    "clothes hanger",
    &["hanger", "coat hanger", "coathanger", "wooden hanger", "wire hanger"],
    &["laundry", "home", "tabletop", "small", "graspable"],
    "a coat hanger lying flat: a triangle with a hook",
    &["hanger"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Hangers: 42–45 cm wide, 20–24 cm with the hook, 1–2 cm thick.
    &size3(0.44, 0.22, 0.012, 0.7, 1.3, 0.05),
    build_clothes_hanger,
);

fn build_clothes_hanger(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.6, 0.45, 0.28, 1.0], [0.1, 0.1, 0.1, 1.0], [0.95, 0.95, 0.94, 1.0]]), true);
    let hook = b.material("hook", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let ys = -hd;
    let yt = hd - d * 0.35;
    // The bar along the bottom and the two arms up to the neck; the hook above.
    slab(b, [-hw, ys, 0.0], [hw, ys + 0.012, h], body);
    for s in [-1.0, 1.0] {
        // An arm from the end of the bar up to the neck, in the plane of the table.
        let (dx, dy) = (-s * hw, yt - ys - 0.006);
        let len = (dx * dx + dy * dy).sqrt();
        let at = Pose::from_pos_yaw([s * hw / 2.0, (ys + 0.006 + yt) / 2.0, h / 2.0], dy.atan2(dx));
        b.visual(Shape::Box { half: [len / 2.0 - 0.004, 0.007, h / 2.0] }, at, body);
    }
    collider_between(b, [-hw * 0.55, ys, 0.0], [hw * 0.55, yt, h]);
    decal_between(b, [-0.0025, yt - 0.01, h * 0.25], [0.0025, hd, h * 0.75], hook);
    collider_between(b, [-0.0025, yt - 0.01, 0.0], [0.0025, hd, h * 0.75]);
    0.07
}
