//! More everyday small things and a few large soft ones: magazines, envelopes, saucers,
//! sponges, bars of soap, toothpaste, erasers, hairbrushes, vacuum flasks, cameras,
//! padlocks and mattresses. Sizes from product ranges, noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Rng, Shape};

use super::forms::{Seg, def, lathe, long_item, rounded_box, size3, whd};
use super::kit::{Axis, INK, LABEL_WHITE, STEEL, along, collider_between, decal_between, pick, slab};
use super::parts::{round_collider, vessel_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const SMALL: &[&str] = &["home", "office", "tabletop", "small", "graspable"];
const PRINT: &[[f32; 4]] = &[
    [0.85, 0.2, 0.15, 1.0],
    [0.2, 0.4, 0.75, 1.0],
    [0.95, 0.8, 0.2, 1.0],
    [0.3, 0.6, 0.35, 1.0],
    [0.95, 0.95, 0.94, 1.0],
];

pub(crate) const MAGAZINE: Category = def(
    "magazine",
    "magazine",
    &["comic", "comic book", "brochure", "catalogue", "catalog", "leaflet", "pamphlet"],
    SMALL,
    "a magazine or folded newspaper lying flat",
    &["publication", "paper"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // A4 magazines 21 × 28 × 0.5 cm; tabloid newspapers folded 29 × 38 × 1 cm.
    &[
        ParamDef::new("width", 0.28, 0.18, 0.4, 0.1, "along X"),
        ParamDef::new("depth", 0.21, 0.14, 0.3, 0.1, "along Y"),
        ParamDef::new("height", 0.006, 0.002, 0.015, 0.2, "thickness"),
    ],
    build_magazine,
);

fn build_magazine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let cover = b.material("cover", pick(rng, PRINT), true);
    let art = b.material("art", pick(rng, &[LABEL_WHITE, [0.15, 0.15, 0.16, 1.0], [0.75, 0.6, 0.45, 1.0]]), false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], cover);
    decal_between(b, [-w * 0.4, -d * 0.35, h - 0.0003], [w * 0.4, d * 0.05, h + 0.0005], art);
    decal_between(b, [-w * 0.4, d * 0.15, h - 0.0003], [w * 0.2, d * 0.35, h + 0.0005], art);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    (w * d * h * 700.0).max(0.02)
}

pub(crate) const ENVELOPE: Category = def(
    "envelope",
    "envelope",
    &["letter", "parcel envelope", "padded envelope", "postcard"],
    SMALL,
    "a paper envelope lying flat",
    &["stationery", "paper"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // DL envelopes 22 × 11 cm; C5 23 × 16 cm.
    &[
        ParamDef::new("width", 0.22, 0.12, 0.35, 0.08, "along X"),
        ParamDef::new("depth", 0.11, 0.08, 0.25, 0.08, "along Y"),
        ParamDef::new("height", 0.003, 0.001, 0.02, 0.2, "thickness"),
    ],
    build_envelope,
);

fn build_envelope(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paper =
        b.material("paper", pick(rng, &[[0.97, 0.97, 0.95, 1.0], [0.85, 0.72, 0.5, 1.0], [0.9, 0.88, 0.8, 1.0]]), true);
    let stamp = b.material("stamp", pick(rng, PRINT), false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], paper);
    decal_between(
        b,
        [w / 2.0 - 0.03, d / 2.0 - 0.03, h - 0.0003],
        [w / 2.0 - 0.008, d / 2.0 - 0.008, h + 0.0004],
        stamp,
    );
    0.02
}

pub(crate) const SAUCER: Category = def(
    "saucer",
    "saucer",
    &["small plate", "tea saucer", "coffee saucer"],
    &["kitchen", "cafe", "tabletop", "small", "graspable", "round"],
    "a small round saucer for a cup",
    &["dish", "tableware", "crockery", "plate"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Saucers: 14–16 cm across, 2 cm high.
    &[
        ParamDef::new("width", 0.15, 0.09, 0.18, 0.05, "diameter"),
        ParamDef::new("depth", 0.15, 0.09, 0.18, 0.05, "diameter (as width)"),
        ParamDef::new("height", 0.02, 0.008, 0.03, 0.1, "height"),
    ],
    build_saucer,
);

fn build_saucer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let glaze = b.material(
        "glaze",
        pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.16, 0.3, 0.55, 1.0], [0.75, 0.2, 0.16, 1.0], [0.45, 0.62, 0.5, 1.0]]),
        true,
    );
    let t = (h * 0.4).min(0.006);
    let profile =
        [[0.0, 0.0], [r * 0.55, 0.0], [r, h * 0.8], [r, h], [r - 0.004, h], [r * 0.55, t + 0.002], [0.0, t + 0.002]];
    b.visual_mesh_on(0, &revolve(&profile, ROUND), sw_geom::Pose::IDENTITY, glaze);
    let inside = vessel_collider(b, [0.0, 0.0], r * 0.55, r, r * 0.4, t + 0.002, 0.0, h, 16);
    let a = inside.half;
    b.surface("top", inside.floor, [-a, -a], [a, a], None);
    (r * r * 3.1 * t * 2300.0).max(0.05)
}

pub(crate) const SPONGE: Category = def(
    "sponge",
    "sponge",
    &["kitchen sponge", "scouring pad", "scrubbing sponge", "dish sponge", "bath sponge", "cleaning sponge"],
    &["kitchen", "bathroom", "cleaning", "tabletop", "small", "graspable"],
    "a kitchen sponge with a green scouring layer",
    &["cleaning tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Kitchen sponges: 9–11 × 6–7 × 3–4.5 cm.
    &size3(0.1, 0.068, 0.035, 0.7, 1.6, 0.06),
    build_sponge,
);

fn build_sponge(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let foam =
        b.material("foam", pick(rng, &[[0.98, 0.85, 0.25, 1.0], [0.95, 0.6, 0.7, 1.0], [0.45, 0.7, 0.9, 1.0]]), true);
    let scour = b.material("scourer", [0.15, 0.5, 0.25, 1.0], false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h * 0.72], foam);
    slab(b, [-w / 2.0, -d / 2.0, h * 0.72 - 0.0005], [w / 2.0, d / 2.0, h], scour);
    0.02
}

pub(crate) const SOAP_BAR: Category = def(
    "soap_bar",
    "bar of soap",
    &["soap", "cake of soap", "hand soap bar"],
    &["bathroom", "kitchen", "tabletop", "small", "graspable"],
    "a rounded bar of soap",
    &["toiletry"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 100 g soap bars: 9 × 6 × 2.5 cm.
    &size3(0.09, 0.06, 0.025, 0.7, 1.4, 0.06),
    build_soap_bar,
);

fn build_soap_bar(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let soap = b.material(
        "soap",
        pick(rng, &[[0.97, 0.95, 0.9, 1.0], [0.9, 0.7, 0.75, 1.0], [0.7, 0.85, 0.7, 1.0], [0.95, 0.85, 0.55, 1.0]]),
        true,
    );
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, d * 0.4, soap);
    (w * d * h * 1000.0).max(0.03)
}

pub(crate) const TOOTHPASTE: Category = def(
    "toothpaste",
    "toothpaste",
    &["tube of toothpaste", "toothpaste tube", "tube of cream", "ointment tube", "glue tube"],
    &["bathroom", "tabletop", "small", "graspable"],
    "a tube of toothpaste lying flat, with a cap at one end",
    &["tube", "toiletry"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 75–100 ml tubes: 17–20 × 4.5–5 × 3 cm.
    &size3(0.18, 0.048, 0.03, 0.6, 1.3, 0.06),
    build_toothpaste,
);

fn build_toothpaste(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let tube =
        b.material("tube", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.2, 0.45, 0.8, 1.0], [0.85, 0.15, 0.12, 1.0]]), true);
    let cap =
        b.material("cap", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.15, 0.15, 0.16, 1.0], [0.2, 0.45, 0.8, 1.0]]), false);
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + 0.02, d * 0.6, h * 0.8, cap),
            Seg { x0: -w / 2.0 + 0.019, x1: w / 2.0 - w * 0.2, width: d * 0.8, height: h, round: true, material: tube },
            Seg::flat(w / 2.0 - w * 0.2 - 0.002, w / 2.0, d, h * 0.25, tube),
        ],
    );
    0.12
}

pub(crate) const ERASER: Category = def(
    "eraser",
    "eraser",
    &["rubber eraser", "pencil eraser", "rubber"],
    SMALL,
    "a rectangular rubber eraser",
    &["stationery", "office supply"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Pencil erasers: 4–6 × 2–2.5 × 1–1.2 cm; board erasers 15 × 5 × 3 cm.
    &size3(0.05, 0.022, 0.012, 0.7, 3.0, 0.06),
    build_eraser,
);

fn build_eraser(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rubber =
        b.material("rubber", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.95, 0.6, 0.65, 1.0], [0.3, 0.5, 0.8, 1.0]]), true);
    let sleeve = b.material("sleeve", pick(rng, PRINT), false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], rubber);
    decal_between(b, [-w * 0.1, -d / 2.0 - 0.0005, -0.0005], [w / 2.0 - 0.005, d / 2.0 + 0.0005, h + 0.0005], sleeve);
    (w * d * h * 1200.0).max(0.01)
}

pub(crate) const HAIRBRUSH: Category = def(
    "hairbrush",
    "hairbrush",
    &["hair brush", "paddle brush", "round brush"],
    &["bathroom", "bedroom", "home", "tabletop", "small", "graspable"],
    "a paddle hairbrush lying on its back",
    &["brush", "toiletry"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Paddle brushes: 23–25 × 7–9 × 3–4 cm.
    &size3(0.24, 0.08, 0.035, 0.6, 1.3, 0.06),
    build_hairbrush,
);

fn build_hairbrush(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.6, 0.45, 0.28, 1.0], [0.85, 0.5, 0.6, 1.0]]), true);
    let pad = b.material("pad", INK, false);
    let head = w * 0.42;
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + head, d, h * 0.5, body),
            Seg::flat(-w / 2.0 + head - 0.002, w / 2.0, d * 0.35, h * 0.45, body),
        ],
    );
    decal_between(
        b,
        [-w / 2.0 + 0.008, -d / 2.0 + 0.008, h * 0.5 - 0.001],
        [-w / 2.0 + head - 0.008, d / 2.0 - 0.008, h],
        pad,
    );
    collider_between(
        b,
        [-w / 2.0 + 0.008, -d / 2.0 + 0.008, h * 0.5 - 0.001],
        [-w / 2.0 + head - 0.008, d / 2.0 - 0.008, h],
    );
    0.1
}

pub(crate) const VACUUM_FLASK: Category = def(
    "vacuum_flask",
    "vacuum flask",
    &["thermos", "thermos flask", "travel mug", "insulated bottle", "flask bottle", "hip flask", "drinks flask"],
    &["kitchen", "office", "tabletop", "small", "graspable", "round"],
    "a steel vacuum flask with a cup-cap",
    &["bottle", "container", "drinkware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 0.5–1 l vacuum flasks: 7–9 cm across, 24–32 cm tall.
    &[
        ParamDef::new("width", 0.08, 0.06, 0.11, 0.06, "diameter"),
        ParamDef::new("depth", 0.08, 0.06, 0.11, 0.06, "diameter (as width)"),
        ParamDef::new("height", 0.27, 0.16, 0.35, 0.08, "height"),
    ],
    build_vacuum_flask,
);

fn build_vacuum_flask(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let steel = b.material(
        "steel",
        pick(rng, &[[0.72, 0.73, 0.75, 1.0], [0.15, 0.3, 0.2, 1.0], [0.12, 0.12, 0.13, 1.0], [0.75, 0.15, 0.12, 1.0]]),
        true,
    );
    let cap = b.material("cap", pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.72, 0.73, 0.75, 1.0]]), false);
    let zc = h * 0.78;
    lathe(
        b,
        0,
        [0.0, 0.0],
        r,
        0.0,
        zc,
        &[[0.0, 0.0], [0.95, 0.0], [1.0, 0.03], [1.0, 0.95], [0.85, 1.0], [0.0, 1.0]],
        steel,
    );
    lathe(
        b,
        0,
        [0.0, 0.0],
        r * 0.92,
        zc - 0.001,
        h - zc + 0.001,
        &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        cap,
    );
    round_collider(b, 0, [0.0, 0.0], r, 0.0, h);
    0.45
}

pub(crate) const CAMERA: Category = def(
    "camera",
    "camera",
    &[
        "digital camera",
        "dslr",
        "slr camera",
        "mirrorless camera",
        "compact camera",
        "video camera",
        "camcorder",
        "webcam",
    ],
    &["electronics", "home", "office", "tabletop", "small", "graspable"],
    "a camera body with a lens on its front",
    &["device", "electronics"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Mirrorless / DSLR bodies with a kit lens: 12–14 × 10–12 × 8–10 cm.
    &size3(0.13, 0.11, 0.095, 0.6, 1.3, 0.06),
    build_camera,
);

fn build_camera(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.75, 0.76, 0.78, 1.0]]), true);
    let lens = b.material("lens", [0.15, 0.15, 0.16, 1.0], false);
    let glass = b.material("glass", [0.2, 0.3, 0.4, 1.0], false);
    let bd = d * 0.45;
    rounded_box(b, [0.0, -d / 2.0 + bd / 2.0], w, bd, 0.0, h * 0.85, 0.01, body);
    decal_between(b, [w * 0.15, -d / 2.0 + 0.005, h * 0.84], [w * 0.4, -d / 2.0 + bd - 0.005, h], body);
    collider_between(b, [w * 0.15, -d / 2.0 + 0.005, h * 0.84], [w * 0.4, -d / 2.0 + bd - 0.005, h]);
    let r = (h * 0.32).min(w * 0.3);
    let len = d - bd;
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(r, len / 2.0 + 0.001, ROUND),
        along([-w * 0.05, -d / 2.0 + bd + len / 2.0, h * 0.42], Axis::Y),
        lens,
    );
    b.visual(
        Shape::Cylinder { radius: r * 0.8, half_height: 0.001 },
        along([-w * 0.05, d / 2.0, h * 0.42], Axis::Y),
        glass,
    );
    collider_between(b, [-w * 0.05 - r, -d / 2.0 + bd - 0.001, h * 0.42 - r], [-w * 0.05 + r, d / 2.0, h * 0.42 + r]);
    0.7
}

pub(crate) const PADLOCK: Category = def(
    "padlock",
    "padlock",
    &["lock", "combination lock", "bike lock", "d-lock", "cable lock"],
    &["home", "garage", "workshop", "tabletop", "small", "graspable"],
    "a brass padlock lying on its side",
    &["lock", "hardware"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 40–50 mm padlocks: 4–5 × 7–8 cm with the shackle, 1.5–2.5 cm thick.
    &size3(0.05, 0.08, 0.02, 0.6, 2.0, 0.06),
    build_padlock,
);

fn build_padlock(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let brass =
        b.material("body", pick(rng, &[[0.8, 0.65, 0.3, 1.0], [0.72, 0.73, 0.75, 1.0], [0.15, 0.3, 0.6, 1.0]]), true);
    let steel = b.material("shackle", pick(rng, STEEL), false);
    let bd = d * 0.6;
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, -d / 2.0 + bd, h], brass);
    let ring = revolve(&super::shapes::rounded_ring_profile(0.35, 0.5, -0.004, 0.004, 0.0), 16);
    let mut m = ring;
    for v in &mut m.vertices {
        v[0] *= (w * 0.8) as f32;
        v[1] *= ((d - bd) * 2.0 * 0.98) as f32;
    }
    b.visual_mesh_on(0, &m, sw_geom::Pose::from_pos([0.0, -d / 2.0 + bd, h / 2.0]), steel);
    collider_between(b, [-w * 0.4, -d / 2.0 + bd - 0.001, h / 2.0 - 0.004], [w * 0.4, d / 2.0, h / 2.0 + 0.004]);
    0.2
}

pub(crate) const MATTRESS: Category = def(
    "mattress",
    "mattress",
    &[
        "double mattress",
        "single mattress",
        "foam mattress",
        "air mattress",
        "futon",
        "camp bed mattress",
        "sleeping mat",
    ],
    &["furniture", "home", "bedroom", "textile", "surface"],
    "a mattress lying on the floor",
    &["bedding", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // UK double mattresses 135 × 190 cm, EU 140 × 200, 18–25 cm thick.
    &[
        ParamDef::new("width", 1.4, 0.8, 2.0, 0.1, "along X"),
        ParamDef::new("depth", 2.0, 1.8, 2.1, 0.02, "along Y"),
        ParamDef::new("height", 0.22, 0.08, 0.32, 0.1, "thickness"),
    ],
    build_mattress,
);

fn build_mattress(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let ticking = b.material(
        "ticking",
        pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.85, 0.88, 0.92, 1.0], [0.9, 0.86, 0.78, 1.0]]),
        true,
    );
    let piping = b.material("piping", pick(rng, &[[0.3, 0.35, 0.5, 1.0], [0.55, 0.55, 0.57, 1.0]]), false);
    let top = rounded_box(b, [0.0, 0.0], w, d, 0.0, h, 0.05, ticking);
    rounded_box(b, [0.0, 0.0], w + 0.004, d + 0.004, h * 0.45, h * 0.55, 0.05, piping);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    0.0
}
