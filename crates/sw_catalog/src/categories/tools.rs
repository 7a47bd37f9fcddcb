//! Garages and workshops: hand tools that lie flat on the bench (hammers, screwdrivers,
//! spanners, pliers, saws, levels, chisels, clamps, brushes, torches), cleaning tools,
//! paint tins and buckets, toolboxes; power tools (drills, saws, grinders, sanders) and
//! the shop's floor machines (table and band saws, bench grinders, shop vacuums, welders,
//! vices, sawhorses, wheelbarrows, mowers, bicycles, jerry cans and car batteries).
//! Sizes from product ranges (Stanley, Bosch, DeWalt, Makita), noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::forms::{Seg, def, knobs, lathe, long_item, rounded_box, size3, spread, whd};
use super::kit::{
    Axis, DARK, INK, LABEL_WHITE, MACHINE_PAINT, RUBBER, SAFETY_YELLOW, STEEL, WOOD, along, collider_between,
    decal_between, pick, rod, slab,
};
use super::parts::{round_collider, round_solid, vessel_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const HAND_TOOL: &[&str] = &["workshop", "garage", "tool", "tabletop", "small", "graspable"];
const GRIP: &[[f32; 4]] = &[
    [0.95, 0.75, 0.1, 1.0],
    [0.8, 0.15, 0.12, 1.0],
    [0.15, 0.35, 0.7, 1.0],
    [0.1, 0.1, 0.11, 1.0],
    [0.2, 0.55, 0.25, 1.0],
];
const TOOL_STEEL: [f32; 4] = [0.62, 0.64, 0.67, 1.0];
/// Power-tool housings: DeWalt yellow, Makita teal, Bosch green and blue, Milwaukee red.
const POWER: &[[f32; 4]] = &[
    [0.98, 0.78, 0.1, 1.0],
    [0.1, 0.55, 0.6, 1.0],
    [0.2, 0.55, 0.35, 1.0],
    [0.15, 0.3, 0.6, 1.0],
    [0.78, 0.1, 0.1, 1.0],
];

/// Length, width and thickness lying flat, with a shared relative range.
const fn flat3(l: f64, w: f64, t: f64) -> [ParamDef; 3] {
    [
        ParamDef::new("width", l, l * 0.7, l * 1.4, 0.06, "length along X"),
        ParamDef::new("depth", w, w * 0.7, w * 1.4, 0.06, "width along Y"),
        ParamDef::new("height", t, t * 0.7, t * 1.4, 0.06, "thickness lying"),
    ]
}

pub(crate) const HAMMER: Category = def(
    "hammer",
    "hammer",
    &["claw hammer", "mallet", "ball-peen hammer", "rubber mallet", "sledgehammer", "framing hammer"],
    HAND_TOOL,
    "a claw hammer lying on its side: a steel head on a handle",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Stanley 16 oz claw hammers: 33 cm long, 13 cm head, 3 cm thick.
    &flat3(0.33, 0.13, 0.032),
    build_hammer,
);

fn build_hammer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let grip = b.material("grip", pick(rng, &[GRIP[0], GRIP[3], [0.6, 0.45, 0.28, 1.0]]), true);
    let steel = b.material("head", TOOL_STEEL, false);
    // The head across the −X end, the handle along X.
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + 0.03, d, h, steel),
            Seg::flat(-w / 2.0 + 0.029, w / 2.0, d * 0.25, h * 0.8, grip),
        ],
    );
    0.6
}

pub(crate) const SCREWDRIVER: Category = def(
    "screwdriver",
    "screwdriver",
    &[
        "flathead screwdriver",
        "phillips screwdriver",
        "flat-head screwdriver",
        "torx screwdriver",
        "screw driver",
        "electrician's screwdriver",
    ],
    HAND_TOOL,
    "a screwdriver with a round grip and a steel shaft",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Wera / Stanley screwdrivers: 18–25 cm long, 3–4 cm grip.
    &flat3(0.2, 0.033, 0.033),
    build_screwdriver,
);

fn build_screwdriver(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let grip = b.material("grip", pick(rng, GRIP), true);
    let steel = b.material("shaft", TOOL_STEEL, false);
    let g = w * 0.45;
    long_item(
        b,
        &[
            Seg { x0: -w / 2.0, x1: -w / 2.0 + g, width: d, height: h, round: true, material: grip },
            Seg {
                x0: -w / 2.0 + g - 0.002,
                x1: w / 2.0,
                width: d * 0.2,
                height: h * 0.2,
                round: true,
                material: steel,
            },
        ],
    );
    0.1
}

pub(crate) const WRENCH: Category = def(
    "wrench",
    "wrench",
    &[
        "spanner",
        "adjustable wrench",
        "adjustable spanner",
        "combination wrench",
        "open-end wrench",
        "pipe wrench",
        "monkey wrench",
    ],
    HAND_TOOL,
    "a steel spanner lying flat, with open jaws at one end",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 8" adjustable wrenches: 20 cm long, 5–6 cm across the jaws, 1.3 cm thick.
    &flat3(0.2, 0.055, 0.014),
    build_wrench,
);

fn build_wrench(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("steel", pick(rng, &[TOOL_STEEL, [0.75, 0.76, 0.78, 1.0]]), true);
    let grip = b.material("grip", pick(rng, GRIP), false);
    let jaw = w * 0.2;
    // Two jaws around a gap at −X, the shank, a grip at +X.
    for s in [-1.0, 1.0] {
        let (y0, y1) = super::kit::ordered(s * d * 0.18, s * d / 2.0);
        decal_between(b, [-w / 2.0, y0, 0.0], [-w / 2.0 + jaw, y1, h], steel);
        collider_between(b, [-w / 2.0, y0, 0.0], [-w / 2.0 + jaw, y1, h]);
    }
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0 + jaw * 0.6, w * 0.1, d * 0.32, h * 0.9, steel),
            Seg::flat(w * 0.1 - 0.001, w / 2.0, d * 0.38, h, grip),
        ],
    );
    0.3
}

pub(crate) const PLIERS: Category = def(
    "pliers",
    "pliers",
    &[
        "pair of pliers",
        "needle-nose pliers",
        "combination pliers",
        "wire cutters",
        "side cutters",
        "locking pliers",
        "vise grips",
    ],
    HAND_TOOL,
    "a pair of pliers lying flat: jaws at one end, two red grips at the other",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Knipex combination pliers 180 mm: 18 × 5.5 × 1.5 cm.
    &flat3(0.19, 0.055, 0.016),
    build_pliers,
);

fn build_pliers(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let grip = b.material("grips", pick(rng, GRIP), true);
    let steel = b.material("jaws", TOOL_STEEL, false);
    let jaws = w * 0.35;
    decal_between(b, [-w / 2.0, -d * 0.15, 0.0], [-w / 2.0 + jaws, d * 0.15, h * 0.8], steel);
    collider_between(b, [-w / 2.0, -d * 0.15, 0.0], [-w / 2.0 + jaws, d * 0.15, h * 0.8]);
    for s in [-1.0, 1.0] {
        let (y0, y1) = super::kit::ordered(s * d * 0.08, s * d / 2.0);
        decal_between(b, [-w / 2.0 + jaws - 0.002, y0, 0.0], [w / 2.0, y1, h], grip);
        collider_between(b, [-w / 2.0 + jaws - 0.002, y0, 0.0], [w / 2.0, y1, h]);
    }
    0.25
}

pub(crate) const TAPE_MEASURE: Category = def(
    "tape_measure",
    "tape measure",
    &["measuring tape", "tape rule", "retractable tape", "measure tape"],
    HAND_TOOL,
    "a retractable tape measure in a yellow case",
    &["hand tool", "tool", "measuring tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Stanley 5 m tape measures: 7.5 × 4 × 7 cm.
    &size3(0.075, 0.04, 0.07, 0.7, 1.5, 0.05),
    build_tape_measure,
);

fn build_tape_measure(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material("case", pick(rng, &[SAFETY_YELLOW, [0.1, 0.1, 0.11, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    let blade = b.material("blade", [0.95, 0.85, 0.2, 1.0], false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, w.min(h) * 0.3, case);
    decal_between(b, [w / 2.0 - 0.004, -d * 0.35, 0.004], [w / 2.0 + 0.003, d * 0.35, 0.008], blade);
    0.3
}

pub(crate) const HAND_SAW: Category = def(
    "hand_saw",
    "hand saw",
    &["handsaw", "saw", "wood saw", "panel saw", "hacksaw", "crosscut saw", "tenon saw"],
    HAND_TOOL,
    "a hand saw lying flat: a toothed steel blade and a closed handle",
    &["hand tool", "tool", "saw"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Bahco / Stanley 20–22" panel saws: 60–66 × 13–15 × 2.5–3 cm.
    &flat3(0.62, 0.14, 0.028),
    build_hand_saw,
);

fn build_hand_saw(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let grip =
        b.material("handle", pick(rng, &[[0.8, 0.15, 0.12, 1.0], [0.6, 0.45, 0.28, 1.0], [0.1, 0.1, 0.11, 1.0]]), true);
    let steel = b.material("blade", [0.8, 0.81, 0.83, 1.0], false);
    let hl = w * 0.22;
    // A tapered blade (wide at the handle), the handle at +X.
    let blade = super::shapes::prism(
        &[[-w / 2.0, -d / 2.0], [w / 2.0 - hl + 0.01, -d / 2.0], [w / 2.0 - hl + 0.01, d / 2.0], [-w / 2.0, -d * 0.1]],
        0.0,
        0.002,
    );
    b.visual_mesh_on(0, &blade, Pose::IDENTITY, steel);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0 - hl, d * 0.2, 0.002]);
    long_item(b, &[Seg::flat(w / 2.0 - hl, w / 2.0, d, h, grip)]);
    0.55
}

pub(crate) const SPIRIT_LEVEL: Category = def(
    "spirit_level",
    "spirit level",
    &["bubble level", "carpenter's level", "box level", "torpedo level", "builder's level"],
    HAND_TOOL,
    "an aluminium spirit level with bubble vials, lying flat",
    &["hand tool", "tool", "measuring tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Stabila 60 cm box levels: 60 × 2.8 × 6 cm, lying 60 × 6 × 2.8.
    &[
        ParamDef::new("width", 0.6, 0.2, 1.2, 0.1, "length"),
        ParamDef::new("depth", 0.06, 0.04, 0.08, 0.05, "height of the profile, lying"),
        ParamDef::new("height", 0.028, 0.02, 0.035, 0.05, "thickness"),
    ],
    build_spirit_level,
);

fn build_spirit_level(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let alu = b.material("profile", pick(rng, &[SAFETY_YELLOW, [0.75, 0.76, 0.78, 1.0], [0.15, 0.35, 0.7, 1.0]]), true);
    let vial = b.material("vials", [0.6, 0.85, 0.3, 1.0], false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], alu);
    for x in [-w * 0.35, 0.0, w * 0.35] {
        decal_between(b, [x - 0.02, -0.006, h - 0.001], [x + 0.02, 0.006, h + 0.002], vial);
    }
    0.25 + w * 0.6
}

pub(crate) const CHISEL: Category = def(
    "chisel",
    "chisel",
    &["wood chisel", "cold chisel", "bevel chisel", "mortise chisel", "gouge"],
    HAND_TOOL,
    "a wood chisel: a flat steel blade in a handle",
    &["hand tool", "tool", "blade"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Bench chisels: 24–28 cm long, 1–3 cm blade, 3 cm handle.
    &flat3(0.26, 0.03, 0.03),
    build_chisel,
);

fn build_chisel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let grip = b.material("handle", pick(rng, &[GRIP[0], [0.6, 0.45, 0.28, 1.0], GRIP[2]]), true);
    let steel = b.material("blade", TOOL_STEEL, false);
    let g = w * 0.45;
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, w / 2.0 - g + 0.002, d * 0.8, h * 0.2, steel),
            Seg { x0: w / 2.0 - g, x1: w / 2.0, width: d, height: h, round: true, material: grip },
        ],
    );
    0.2
}

pub(crate) const CLAMP: Category = def(
    "clamp",
    "clamp",
    &["c-clamp", "g-clamp", "bar clamp", "f-clamp", "quick clamp", "woodworking clamp"],
    HAND_TOOL,
    "an F clamp lying flat: a steel bar with a fixed jaw and a sliding jaw with a screw handle",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Bessey F clamps 300 mm: 40 × 12 × 3 cm lying flat.
    &flat3(0.4, 0.12, 0.03),
    build_clamp,
);

fn build_clamp(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("bar", TOOL_STEEL, false);
    let jaws =
        b.material("jaws", pick(rng, &[[0.8, 0.15, 0.12, 1.0], [0.1, 0.1, 0.11, 1.0], [0.2, 0.35, 0.7, 1.0]]), true);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw, -hd + 0.02, h * 0.6], steel);
    slab(b, [hw - 0.03, -hd + 0.019, 0.0], [hw, hd, h], jaws);
    slab(b, [-hw * 0.2, -hd + 0.019, 0.0], [-hw * 0.2 + 0.03, hd, h], jaws);
    1.0
}

pub(crate) const PAINTBRUSH: Category = def(
    "paintbrush",
    "paintbrush",
    &["paint brush", "brush", "decorating brush", "artist's brush", "sash brush"],
    HAND_TOOL,
    "a decorating paintbrush: bristles in a metal ferrule on a wooden handle",
    &["hand tool", "tool", "brush"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 2" decorating brushes: 24–26 × 5 × 1.5–2 cm.
    &flat3(0.25, 0.05, 0.018),
    build_paintbrush,
);

fn build_paintbrush(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wood = b.material("handle", pick(rng, WOOD), true);
    let ferrule = b.material("ferrule", [0.75, 0.76, 0.78, 1.0], false);
    let bristle = b.material("bristles", pick(rng, &[[0.15, 0.12, 0.1, 1.0], [0.85, 0.75, 0.55, 1.0]]), false);
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + w * 0.22, d, h * 0.8, bristle),
            Seg::flat(-w / 2.0 + w * 0.22 - 0.002, -w / 2.0 + w * 0.36, d * 0.98, h, ferrule),
            Seg::flat(-w / 2.0 + w * 0.36 - 0.002, w / 2.0, d * 0.5, h * 0.7, wood),
        ],
    );
    0.08
}

pub(crate) const FLASHLIGHT: Category = def(
    "flashlight",
    "flashlight",
    &["torch", "electric torch", "led torch", "maglite", "work light", "headlamp"],
    HAND_TOOL,
    "a flashlight lying on its side: a round barrel with a wider head",
    &["light", "tool", "device"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Maglite 2D / LED torches: 15–25 cm long, 3–5 cm heads.
    &flat3(0.2, 0.045, 0.045),
    build_flashlight,
);

fn build_flashlight(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material(
        "barrel",
        pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.75, 0.1, 0.1, 1.0], [0.2, 0.2, 0.22, 1.0], SAFETY_YELLOW]),
        true,
    );
    let lens = b.material("lens", [0.95, 0.95, 0.8, 1.0], false);
    let head = w * 0.28;
    long_item(
        b,
        &[
            Seg { x0: -w / 2.0, x1: -w / 2.0 + head + 0.002, width: d, height: h, round: true, material: body },
            Seg { x0: -w / 2.0 + head, x1: w / 2.0, width: d * 0.72, height: h * 0.72, round: true, material: body },
        ],
    );
    b.visual(
        Shape::Cylinder { radius: d.min(h) * 0.42, half_height: 0.001 },
        along([-w / 2.0 - 0.0005, 0.0, h / 2.0], Axis::X),
        lens,
    );
    0.3
}

pub(crate) const TOOLBOX: Category = def(
    "toolbox",
    "toolbox",
    &["tool box", "tool case", "toolkit", "tool kit", "portable toolbox", "tool bag"],
    &["workshop", "garage", "tool", "container", "graspable"],
    "a portable plastic toolbox with a carrying handle and latches",
    &["box", "container", "case"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Stanley / DeWalt 19–22" toolboxes: 48–56 × 24–28 × 22–26 cm.
    &size3(0.5, 0.25, 0.24, 0.6, 1.3, 0.05),
    build_toolbox,
);

fn build_toolbox(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell = b.material(
        "shell",
        pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.8, 0.12, 0.1, 1.0], SAFETY_YELLOW, [0.15, 0.35, 0.7, 1.0]]),
        true,
    );
    let lid = b.material("lid", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.95, 0.75, 0.1, 1.0]]), false);
    let latch = b.material("latches", pick(rng, STEEL), false);
    let body = h * 0.65;
    let hl = h * 0.85;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, body, 0.02, shell);
    rounded_box(b, [0.0, 0.0], w, d, body - 0.001, hl, 0.03, lid);
    for x in [-w * 0.35, w * 0.35] {
        decal_between(b, [x - 0.02, d / 2.0 - 0.001, body - 0.03], [x + 0.02, d / 2.0 + 0.003, body + 0.02], latch);
    }
    decal_between(b, [-w * 0.25, -0.015, hl - 0.002], [w * 0.25, 0.015, h], shell);
    collider_between(b, [-w * 0.25, -0.015, hl - 0.002], [w * 0.25, 0.015, h]);
    2.2
}

pub(crate) const PAINT_CAN: Category = def(
    "paint_can",
    "paint can",
    &["paint tin", "tin of paint", "can of paint", "paint pot", "varnish tin", "paint bucket"],
    &["workshop", "garage", "home", "tabletop", "small", "graspable", "round", "container"],
    "a round metal paint tin with a lid and a wire handle",
    &["can", "tin", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // 2.5 l paint tins: 17–19 cm across, 19–20 cm tall; 1 l: 11 × 12 cm.
    &[
        ParamDef::new("width", 0.18, 0.1, 0.3, 0.08, "diameter"),
        ParamDef::new("depth", 0.18, 0.1, 0.3, 0.08, "diameter (as width)"),
        ParamDef::new("height", 0.19, 0.11, 0.36, 0.08, "height"),
    ],
    build_paint_can,
);

fn build_paint_can(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let label = b.material(
        "label",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.2, 0.4, 0.75, 1.0], [0.8, 0.15, 0.12, 1.0], [0.3, 0.6, 0.35, 1.0]]),
        true,
    );
    let metal = b.material("metal", [0.72, 0.73, 0.75, 1.0], false);
    let top = round_solid(b, 0, [0.0, 0.0], r, 0.0, h, metal);
    lathe(b, 0, [0.0, 0.0], r + 0.0008, h * 0.15, h * 0.7, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], label);
    let a = r / std::f64::consts::SQRT_2;
    b.surface("lid", top, [-a, -a], [a, a], None);
    (r * r * h * 3.1 * 1300.0).max(0.3)
}

pub(crate) const BUCKET: Category = def(
    "bucket",
    "bucket",
    &["pail", "mop bucket", "plastic bucket", "metal bucket", "water bucket", "builder's bucket"],
    &["workshop", "garage", "home", "cleaning", "graspable", "round", "open", "container"],
    "a round tapered bucket with a wire handle",
    &["container", "vessel"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // 10 l buckets: 28–30 cm at the rim, 26–28 cm tall.
    &[
        ParamDef::new("width", 0.29, 0.18, 0.36, 0.06, "rim diameter"),
        ParamDef::new("depth", 0.29, 0.18, 0.36, 0.06, "rim diameter (as width)"),
        ParamDef::new("height", 0.27, 0.16, 0.36, 0.06, "floor to rim"),
    ],
    build_bucket,
);

fn build_bucket(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let plastic = b.material(
        "plastic",
        pick(
            rng,
            &[
                [0.15, 0.35, 0.7, 1.0],
                [0.8, 0.15, 0.12, 1.0],
                [0.1, 0.1, 0.11, 1.0],
                [0.75, 0.76, 0.78, 1.0],
                SAFETY_YELLOW,
            ],
        ),
        true,
    );
    let handle = b.material("handle", pick(rng, STEEL), false);
    let rb = r * 0.8;
    let t = 0.004;
    b.visual_mesh_on(
        0,
        &revolve(&[[0.0, 0.0], [rb, 0.0], [r, h], [r - t, h], [rb - t, 0.006], [0.0, 0.006]], ROUND),
        Pose::IDENTITY,
        plastic,
    );
    let inside = vessel_collider(b, [0.0, 0.0], rb, r, t * 2.0, 0.006, 0.0, h, 16);
    for s in [-1.0, 1.0] {
        decal_between(
            b,
            [s * (r - 0.004) - 0.002, -0.004, h * 0.8],
            [s * (r - 0.004) + 0.002, 0.004, h - 0.004],
            handle,
        );
    }
    let a = inside.half;
    b.surface("inside", inside.floor, [-a, -a], [a, a], None);
    0.6
}

pub(crate) const MOP: Category = def(
    "mop",
    "mop",
    &["floor mop", "wet mop", "squeegee mop", "sponge mop", "swiffer"],
    &["cleaning", "home", "workshop", "graspable"],
    "a floor mop lying down: a long handle with a mop head",
    &["cleaning tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Mops: 120–140 cm handles, 12–30 cm heads.
    &flat3(1.3, 0.25, 0.08),
    build_mop,
);

fn build_mop(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let pole = b.material(
        "handle",
        pick(rng, &[[0.15, 0.35, 0.7, 1.0], [0.75, 0.76, 0.78, 1.0], [0.2, 0.55, 0.25, 1.0]]),
        true,
    );
    let head = b.material("head", [0.92, 0.9, 0.85, 1.0], false);
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + 0.18, d, h, head),
            Seg { x0: -w / 2.0 + 0.178, x1: w / 2.0, width: 0.025, height: 0.025, round: true, material: pole },
        ],
    );
    1.1
}

pub(crate) const BROOM: Category = def(
    "broom",
    "broom",
    &["sweeping brush", "push broom", "yard brush", "besom", "floor brush"],
    &["cleaning", "home", "workshop", "graspable"],
    "a broom lying down: a long handle with a bristle head",
    &["cleaning tool", "tool", "brush"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Indoor brooms: 120–140 cm long, 25–35 cm heads.
    &flat3(1.3, 0.3, 0.06),
    build_broom,
);

pub(crate) fn build_broom(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let pole = b.material(
        "handle",
        pick(rng, &[[0.6, 0.45, 0.28, 1.0], [0.15, 0.35, 0.7, 1.0], [0.8, 0.15, 0.12, 1.0]]),
        true,
    );
    let block = b.material("block", pick(rng, DARK), false);
    let bristle = b.material("bristles", pick(rng, &[[0.85, 0.7, 0.4, 1.0], [0.1, 0.1, 0.11, 1.0]]), false);
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + 0.05, d, h, bristle),
            Seg::flat(-w / 2.0 + 0.048, -w / 2.0 + 0.09, d, h * 0.8, block),
            Seg { x0: -w / 2.0 + 0.088, x1: w / 2.0, width: 0.025, height: 0.025, round: true, material: pole },
        ],
    );
    0.7
}

pub(crate) const DUSTPAN: Category = def(
    "dustpan",
    "dustpan",
    &["dust pan", "dustpan and brush", "dust pan and brush"],
    &["cleaning", "home", "tabletop", "small", "graspable"],
    "a plastic dustpan with a short handle",
    &["cleaning tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Dustpans: 30–35 × 22–25 × 7–10 cm.
    &size3(0.33, 0.24, 0.08, 0.8, 1.3, 0.05),
    build_dustpan,
);

fn build_dustpan(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let plastic = b.material(
        "plastic",
        pick(rng, &[[0.15, 0.35, 0.7, 1.0], [0.8, 0.15, 0.12, 1.0], [0.2, 0.55, 0.25, 1.0], [0.15, 0.15, 0.16, 1.0]]),
        true,
    );
    let pan = w * 0.7;
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [-hw + pan, hd, 0.004], plastic);
    for (y0, y1) in [(-hd, -hd + 0.004), (hd - 0.004, hd)] {
        slab(b, [-hw + pan * 0.2, y0, 0.003], [-hw + pan, y1, h * 0.7], plastic);
    }
    slab(b, [-hw + pan - 0.004, -hd + 0.003, 0.003], [-hw + pan, hd - 0.003, h * 0.7], plastic);
    slab(b, [-hw + pan - 0.005, -0.015, h * 0.5], [hw, 0.015, h], plastic);
    0.25
}

pub(crate) const POWER_DRILL: Category = def(
    "power_drill",
    "power drill",
    &["drill", "cordless drill", "electric drill", "drill driver", "hammer drill", "impact driver", "drill gun"],
    &["workshop", "garage", "tool", "power_tool", "tabletop", "small", "graspable"],
    "a cordless drill standing on its battery: a pistol grip under a motor body and chuck",
    &["power tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // DeWalt DCD771 / Bosch GSR 18V: 19–22 × 8 × 20–24 cm with the battery.
    &size3(0.21, 0.08, 0.22, 0.8, 1.2, 0.04),
    build_power_drill,
);

fn build_power_drill(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("housing", pick(rng, POWER), true);
    let black = b.material("black", INK, false);
    let chuck = b.material("chuck", [0.3, 0.3, 0.32, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bat = h * 0.3;
    // The battery pack on the bench, the grip up from it, the motor body across the top.
    slab(b, [-hw, -hd, 0.0], [hw * 0.3, hd, bat], black);
    slab(b, [-hw * 0.6, -hd * 0.7, bat - 0.001], [-hw * 0.05, hd * 0.7, h * 0.7], body);
    slab(b, [-hw, -hd, h * 0.7 - 0.002], [hw * 0.4, hd, h], body);
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(hd * 0.7, (w * 0.3) / 2.0, ROUND),
        along([hw * 0.4 + w * 0.15, 0.0, h * 0.85], Axis::X),
        chuck,
    );
    collider_between(b, [hw * 0.4 - 0.001, -hd * 0.7, h * 0.85 - hd * 0.7], [hw, hd * 0.7, h * 0.85 + hd * 0.7]);
    1.5
}

/// A power tool lying flat or standing on its base: a housing box with a motor
/// cylinder along X, a grip handle and a coloured shell.
fn power_tool(b: &mut AssetBuilder, rng: &mut Rng, w: f64, d: f64, h: f64) {
    let body = b.material("housing", pick(rng, POWER), true);
    let black = b.material("black", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw, hd, h * 0.35], black);
    rounded_box(b, [0.0, 0.0], w * 0.8, d * 0.9, h * 0.35 - 0.001, h * 0.8, d * 0.3, body);
    slab(b, [-hw, -0.02, h * 0.75], [hw * 0.2, 0.02, h], body);
}

pub(crate) const CIRCULAR_SAW: Category = def(
    "circular_saw",
    "circular saw",
    &["skill saw", "skilsaw", "handheld circular saw", "track saw", "plunge saw"],
    &["workshop", "garage", "tool", "power_tool", "tabletop", "small", "graspable"],
    "a handheld circular saw on its base plate, with a blade guard and a top handle",
    &["power tool", "tool", "saw"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 190 mm circular saws: 30–36 × 22–27 × 22–26 cm.
    &size3(0.33, 0.25, 0.24, 0.8, 1.2, 0.04),
    build_circular_saw,
);

fn build_circular_saw(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    power_tool(b, rng, w, d, h);
    let guard = b.material("guard", [0.7, 0.71, 0.73, 1.0], false);
    b.visual(
        Shape::Cylinder { radius: h * 0.4, half_height: 0.015 },
        along([w * 0.05, d * 0.42, h * 0.45], Axis::Y),
        guard,
    );
    4.2
}

pub(crate) const ANGLE_GRINDER: Category = def(
    "angle_grinder",
    "angle grinder",
    &["grinder", "disc grinder", "side grinder", "cut-off grinder", "grinding machine"],
    &["workshop", "garage", "tool", "power_tool", "tabletop", "small", "graspable"],
    "an angle grinder lying flat: a long motor body with a disc and guard at one end",
    &["power tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 115–125 mm angle grinders: 28–32 × 12–14 × 10–11 cm lying.
    &size3(0.3, 0.13, 0.105, 0.8, 1.3, 0.04),
    build_angle_grinder,
);

fn build_angle_grinder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("housing", pick(rng, POWER), true);
    let disc = b.material("disc", [0.3, 0.3, 0.32, 1.0], false);
    let head = b.material("gear_head", [0.7, 0.71, 0.73, 1.0], false);
    let hd = d / 2.0;
    let r = (h * 0.35).min(hd * 0.6);
    long_item(
        b,
        &[
            Seg { x0: -w / 2.0 + d, x1: w / 2.0, width: r * 2.0, height: r * 2.0, round: true, material: body },
            Seg::flat(-w / 2.0 + d * 0.3, -w / 2.0 + d + 0.002, r * 2.2, h * 0.8, head),
        ],
    );
    round_solid(b, 0, [-w / 2.0 + hd, 0.0], hd, h * 0.8 - 0.001, h, disc);
    1.9
}

pub(crate) const JIGSAW: Category = def(
    "jigsaw",
    "jigsaw",
    &["jig saw", "sabre saw", "scroll saw", "power jigsaw"],
    &["workshop", "garage", "tool", "power_tool", "tabletop", "small", "graspable"],
    "a jigsaw standing on its shoe plate with a closed handle on top",
    &["power tool", "tool", "saw"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Bosch PST / Makita jigsaws: 23–27 × 7–8 × 20–22 cm.
    &size3(0.25, 0.08, 0.21, 0.8, 1.2, 0.04),
    build_jigsaw,
);

fn build_jigsaw(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    power_tool(b, rng, w, d, h);
    2.3
}

pub(crate) const ORBITAL_SANDER: Category = def(
    "orbital_sander",
    "orbital sander",
    &["sander", "random orbital sander", "palm sander", "belt sander", "sanding machine", "detail sander"],
    &["workshop", "garage", "tool", "power_tool", "tabletop", "small", "graspable"],
    "a palm orbital sander: a square pad under a rounded motor body",
    &["power tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 1/4-sheet palm sanders: 13–14 × 11–12 × 14–16 cm.
    &size3(0.135, 0.115, 0.15, 0.8, 1.5, 0.04),
    build_orbital_sander,
);

fn build_orbital_sander(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("housing", pick(rng, POWER), true);
    let pad = b.material("pad", INK, false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, 0.025], pad);
    lathe(
        b,
        0,
        [0.0, 0.0],
        w.min(d) / 2.0,
        0.024,
        h - 0.024,
        &[[0.0, 0.0], [1.0, 0.0], [0.8, 0.7], [0.4, 1.0], [0.0, 1.0]],
        body,
    );
    round_collider(b, 0, [0.0, 0.0], w.min(d) * 0.4, 0.024, h);
    1.3
}

pub(crate) const TABLE_SAW: Category = def(
    "table_saw",
    "table saw",
    &["saw bench", "bench saw", "contractor saw", "cabinet saw", "sawbench", "mitre saw", "miter saw", "chop saw"],
    &["workshop", "machine", "surface", "hazard"],
    "a table saw: a steel table with a blade through its middle on a cabinet stand",
    &["machine", "saw", "machine tool", "power tool"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // Jobsite / contractor table saws on stands: 65–110 × 55–80 × 85–95 cm.
    &size3(0.8, 0.68, 0.9, 0.8, 1.4, 0.05),
    build_table_saw,
);

fn build_table_saw(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material("cabinet", pick(rng, MACHINE_PAINT), true);
    let table = b.material("table", [0.7, 0.71, 0.73, 1.0], false);
    let blade = b.material("blade", [0.8, 0.1, 0.1, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw * 0.8, -hd * 0.8, 0.0], [hw * 0.8, hd * 0.8, h - 0.05], paint);
    let top = slab(b, [-hw, -hd, h - 0.05], [hw, hd, h - 0.02], table);
    b.visual(Shape::Cylinder { radius: 0.11, half_height: 0.0015 }, along([0.0, 0.0, h - 0.11], Axis::X), blade);
    collider_between(b, [-0.003, -0.1, h - 0.021], [0.003, 0.1, h]);
    b.surface("left_table", top, [-hw, -hd], [-0.02, hd], None);
    0.0
}

pub(crate) const BAND_SAW: Category = def(
    "band_saw",
    "band saw",
    &["bandsaw", "vertical band saw", "metal band saw"],
    &["workshop", "machine", "tall", "hazard"],
    "a floor-standing band saw: a tall C-shaped frame with a small table at waist height",
    &["machine", "saw", "machine tool"],
    Kind::Machine,
    PlacementKind::AgainstWall,
    false,
    // 14" band saws on stands: 55–70 × 55–70 × 165–180 cm.
    &size3(0.62, 0.6, 1.7, 0.8, 1.2, 0.04),
    build_band_saw,
);

fn build_band_saw(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material("frame", pick(rng, MACHINE_PAINT), true);
    let table = b.material("table", [0.7, 0.71, 0.73, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let zt = h * 0.58;
    slab(b, [-hw, -hd * 0.7, 0.0], [hw, hd * 0.7, zt - 0.25], paint);
    slab(b, [-hw * 0.5, -hd, zt - 0.251], [hw * 0.3, hd * 0.2, h], paint);
    let top = slab(b, [-hw * 0.5, hd * 0.2 - 0.001, zt - 0.03], [hw, hd, zt], table);
    slab(b, [-hw * 0.5, hd * 0.2 - 0.001, zt + 0.25], [hw * 0.3, hd * 0.6, h], paint);
    b.surface("table", top, [-hw * 0.5, hd * 0.2], [hw, hd], Some(0.2));
    0.0
}

pub(crate) const BENCH_GRINDER: Category = def(
    "bench_grinder",
    "bench grinder",
    &["grinding wheel", "pedestal grinder", "bench sharpener", "double grinder"],
    &["workshop", "garage", "machine", "tabletop"],
    "a bench grinder: a motor with a grinding wheel under a guard at each end",
    &["machine", "grinder", "machine tool"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // 150–200 mm bench grinders: 35–45 × 18–25 × 25–30 cm.
    &size3(0.38, 0.2, 0.27, 0.8, 1.3, 0.04),
    build_bench_grinder,
);

fn build_bench_grinder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material("body", pick(rng, MACHINE_PAINT), true);
    let stone = b.material("wheels", [0.55, 0.55, 0.52, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw * 0.5, -hd, 0.0], [hw * 0.5, hd, 0.04], paint);
    let r = ((h - 0.04) / 2.0).min(hd);
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(r * 0.6, hw * 0.35, ROUND),
        along([0.0, 0.0, 0.04 + r], Axis::X),
        paint,
    );
    for s in [-1.0, 1.0] {
        b.visual(
            Shape::Cylinder { radius: r * 0.95, half_height: 0.012 },
            along([s * (hw - 0.04), 0.0, 0.04 + r], Axis::X),
            stone,
        );
        let x = s * (hw - 0.04);
        slab(b, [x - 0.03, -hd * 0.6, 0.04 + r * 0.2], [x + 0.03, hd * 0.3, h], paint);
    }
    collider_between(b, [-hw, -r, 0.039], [hw, r, h]);
    10.0
}

pub(crate) const SHOP_VAC: Category = def(
    "shop_vac",
    "shop vacuum",
    &["wet and dry vacuum", "wet/dry vac", "workshop vacuum", "dust extractor", "industrial vacuum"],
    &["workshop", "garage", "cleaning", "appliance", "round"],
    "a wet-and-dry shop vacuum: a round drum on castors with a motor head",
    &["vacuum cleaner", "cleaner", "appliance"],
    Kind::LargeAppliance,
    PlacementKind::Floor,
    false,
    // Kärcher WD / Ridgid 20–30 l: 38–42 cm across, 50–60 cm tall.
    &[
        ParamDef::new("width", 0.4, 0.3, 0.55, 0.06, "drum diameter"),
        ParamDef::new("depth", 0.4, 0.3, 0.55, 0.06, "drum diameter (as width)"),
        ParamDef::new("height", 0.56, 0.4, 0.75, 0.06, "floor to the top of the head"),
    ],
    build_shop_vac,
);

fn build_shop_vac(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let drum = b.material(
        "drum",
        pick(rng, &[SAFETY_YELLOW, [0.2, 0.2, 0.22, 1.0], [0.8, 0.15, 0.12, 1.0], [0.75, 0.76, 0.78, 1.0]]),
        true,
    );
    let head = b.material("head", pick(rng, DARK), false);
    round_solid(b, 0, [0.0, 0.0], r * 0.85, 0.0, h * 0.75, drum);
    lathe(
        b,
        0,
        [0.0, 0.0],
        r,
        h * 0.75 - 0.001,
        h * 0.25 + 0.001,
        &[[0.0, 0.0], [1.0, 0.0], [0.8, 0.8], [0.0, 1.0]],
        head,
    );
    round_collider(b, 0, [0.0, 0.0], r, h * 0.75 - 0.001, h);
    0.0
}

pub(crate) const WELDING_MACHINE: Category = def(
    "welding_machine",
    "welding machine",
    &["welder", "mig welder", "tig welder", "arc welder", "stick welder", "welding set", "inverter welder"],
    &["workshop", "garage", "machine", "electrical"],
    "a MIG welder: a box on wheels with a control panel, a torch lead and a gas bottle clip",
    &["machine", "equipment"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // MIG welders: 50–80 × 30–45 × 45–75 cm.
    &size3(0.6, 0.35, 0.55, 0.75, 1.3, 0.05),
    build_welding_machine,
);

fn build_welding_machine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material(
        "case",
        pick(rng, &[[0.8, 0.15, 0.12, 1.0], [0.15, 0.35, 0.7, 1.0], SAFETY_YELLOW, [0.2, 0.2, 0.22, 1.0]]),
        true,
    );
    let panel = b.material("panel", INK, false);
    let tyre = b.material("wheels", pick(rng, RUBBER), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.06], [hw, hd, h], paint);
    slab(b, [-hw + 0.05, -hd + 0.05, 0.0], [hw - 0.05, hd - 0.05, 0.061], tyre);
    decal_between(b, [hw - 0.001, -hd * 0.7, h * 0.35], [hw + 0.002, hd * 0.7, h * 0.85], panel);
    knobs(b, &[-hw * 0.3, hw * 0.3], hd - 0.008, h * 0.7, 0.02, panel);
    0.0
}

pub(crate) const BENCH_VISE: Category = def(
    "bench_vise",
    "bench vise",
    &["vise", "vice", "bench vice", "engineer's vice", "woodworking vise", "machinist vise"],
    &["workshop", "garage", "tool", "tabletop"],
    "a cast-iron bench vice with two jaws and a screw handle",
    &["tool", "clamp"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // 4–5" bench vices: 25–35 × 12–16 × 15–20 cm.
    &size3(0.3, 0.15, 0.17, 0.8, 1.3, 0.05),
    build_bench_vise,
);

fn build_bench_vise(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let iron = b.material(
        "iron",
        pick(rng, &[[0.15, 0.35, 0.6, 1.0], [0.25, 0.45, 0.3, 1.0], [0.45, 0.47, 0.5, 1.0], [0.8, 0.15, 0.12, 1.0]]),
        true,
    );
    let steel = b.material("jaws", TOOL_STEEL, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw * 0.6, hd, 0.03], iron);
    slab(b, [-hw * 0.3, -hd * 0.6, 0.029], [hw * 0.1, hd * 0.6, h * 0.75], iron);
    slab(b, [hw * 0.1, -hd * 0.6, h * 0.4], [hw * 0.3, hd * 0.6, h], steel);
    slab(b, [-hw * 0.3, -hd * 0.6, h * 0.749], [-hw * 0.1, hd * 0.6, h], steel);
    slab(b, [hw * 0.3, -0.01, h * 0.55], [hw, 0.01, h * 0.62], steel);
    12.0
}

pub(crate) const SAWHORSE: Category = def(
    "sawhorse",
    "sawhorse",
    &["saw horse", "trestle", "saw bench trestle", "trestle stand"],
    &["workshop", "garage", "furniture", "surface"],
    "a sawhorse: a beam on two pairs of splayed legs",
    &["stand", "support", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Folding sawhorses: 80–110 × 50–65 × 70–80 cm.
    &size3(0.95, 0.55, 0.75, 0.8, 1.3, 0.05),
    build_sawhorse,
);

fn build_sawhorse(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wood = b.material("wood", pick(rng, WOOD), true);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top = slab(b, [-hw, -0.045, h - 0.09], [hw, 0.045, h], wood);
    for x in [-hw + 0.08, hw - 0.08] {
        for s in [-1.0, 1.0] {
            super::kit::strut(
                b,
                [x, s * (hd - 0.03), 0.03],
                [x, s * 0.03, h - 0.09],
                [0.045, 0.07],
                Axis::X,
                wood,
                false,
            );
            let (y0, y1) = super::kit::ordered(s * (hd - 0.05), s * hd);
            slab(b, [x - 0.035, y0, 0.0], [x + 0.035, y1, 0.05], wood);
        }
        collider_between(b, [x - 0.035, -hd * 0.5, 0.0], [x + 0.035, hd * 0.5, h - 0.089]);
    }
    b.surface("beam", top, [-hw, -0.045], [hw, 0.045], None);
    0.0
}

pub(crate) const WHEELBARROW: Category = def(
    "wheelbarrow",
    "wheelbarrow",
    &["wheel barrow", "barrow", "garden cart", "builder's barrow"],
    &["garage", "outdoor", "vehicle", "container"],
    "a wheelbarrow: a steel tray on a front wheel and two legs, with long handles",
    &["cart", "vehicle", "container"],
    Kind::Vehicle,
    PlacementKind::Floor,
    false,
    // 85–100 l wheelbarrows: 140–155 × 60–70 × 60–70 cm.
    &size3(1.45, 0.65, 0.65, 0.85, 1.15, 0.04),
    build_wheelbarrow,
);

fn build_wheelbarrow(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let tray = b.material(
        "tray",
        pick(rng, &[[0.2, 0.5, 0.3, 1.0], [0.8, 0.15, 0.12, 1.0], [0.7, 0.71, 0.73, 1.0], [0.15, 0.15, 0.16, 1.0]]),
        true,
    );
    let frame = b.material("frame", pick(rng, DARK), false);
    let tyre = b.material("tyre", pick(rng, RUBBER), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = 0.18f64.min(h * 0.3);
    // The wheel at +X, the tray over it, the legs and handles to −X.
    b.visual(Shape::Cylinder { radius: r, half_height: 0.04 }, along([hw - r, 0.0, r], Axis::Y), tyre);
    collider_between(b, [hw - r * 2.0, -0.04, 0.0], [hw, 0.04, r * 2.0]);
    let mut bowl =
        revolve(&[[0.0, 0.0], [0.6, 0.0], [1.0, 1.0], [0.0, 1.0]].map(|[a, z]| [a * hd, z * (h - r * 1.2)]), ROUND);
    for v in &mut bowl.vertices {
        v[0] *= (w * 0.45 / d) as f32;
    }
    b.visual_mesh_on(0, &bowl, Pose::from_pos([hw * 0.15, 0.0, r * 1.2]), tray);
    collider_between(b, [hw * 0.15 - w * 0.225, -hd, r * 1.2], [hw * 0.15 + w * 0.225, hd, h]);
    for s in [-1.0, 1.0] {
        slab(b, [-hw, s * hd * 0.6 - 0.02, r * 1.4], [hw - r, s * hd * 0.6 + 0.02, r * 1.4 + 0.04], frame);
        slab(b, [-hw * 0.3, s * hd * 0.6 - 0.02, 0.0], [-hw * 0.3 + 0.04, s * hd * 0.6 + 0.02, r * 1.41], frame);
    }
    0.0
}

pub(crate) const BICYCLE: Category = def(
    "bicycle",
    "bicycle",
    &[
        "bike",
        "push bike",
        "road bike",
        "mountain bike",
        "cycle",
        "pushbike",
        "city bike",
        "e-bike",
        "kids bike",
        "child's bike",
        "balance bike",
    ],
    &["garage", "outdoor", "vehicle"],
    "a bicycle standing on its kickstand: two wheels, a frame, a saddle and handlebars",
    &["vehicle", "cycle"],
    Kind::Vehicle,
    PlacementKind::Floor,
    false,
    // Adult bikes: 170–180 cm long, 55–65 cm across the bars, 100–110 cm tall.
    &size3(1.75, 0.6, 1.05, 0.65, 1.15, 0.04),
    build_bicycle,
);

pub(crate) fn build_bicycle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material(
        "frame",
        pick(
            rng,
            &[
                [0.8, 0.12, 0.1, 1.0],
                [0.15, 0.35, 0.7, 1.0],
                [0.1, 0.1, 0.11, 1.0],
                [0.95, 0.95, 0.94, 1.0],
                [0.2, 0.55, 0.3, 1.0],
            ],
        ),
        true,
    );
    let tyre = b.material("tyres", INK, false);
    let metal = b.material("metal", pick(rng, STEEL), false);
    let hw = w / 2.0;
    let r = (w * 0.19).min(h * 0.34);
    let (xr, xf) = (-hw + r, hw - r);
    for x in [xr, xf] {
        let ring = revolve(&super::shapes::rounded_ring_profile(r - 0.04, r, -0.018, 0.018, 0.01), ROUND);
        b.visual_mesh_on(
            0,
            &ring,
            Pose::from_pos_axis_angle([x, 0.0, r], [1.0, 0.0, 0.0], std::f64::consts::FRAC_PI_2),
            tyre,
        );
        collider_between(b, [x - r, -0.02, 0.0], [x + r, 0.02, r * 2.0]);
    }
    // The frame (drawn), a top tube box to collide, the saddle, the bars across.
    let zb = r;
    let zs = h * 0.85;
    for (a, c) in [
        ([xr, 0.0, zb], [0.0, 0.0, zb]),
        ([0.0, 0.0, zb], [-w * 0.1, 0.0, zs]),
        ([-w * 0.1, 0.0, zs], [xf - r * 0.3, 0.0, h * 0.88]),
        ([0.0, 0.0, zb], [xf - r * 0.3, 0.0, h * 0.88]),
        ([xf - r * 0.3, 0.0, h * 0.88], [xf, 0.0, zb]),
        ([xr, 0.0, zb], [-w * 0.1, 0.0, zs]),
    ] {
        super::kit::strut(b, a, c, [0.03, 0.03], Axis::Y, paint, false);
    }
    collider_between(b, [xr, -0.02, zb - 0.02], [xf, 0.02, zs]);
    slab(b, [-w * 0.1 - 0.12, -0.06, zs], [-w * 0.1 + 0.06, 0.06, zs + 0.05], metal);
    slab(b, [xf - r * 0.3 - 0.02, -d / 2.0, h - 0.03], [xf - r * 0.3 + 0.02, d / 2.0, h], metal);
    slab(b, [-w * 0.05, 0.02, 0.0], [-w * 0.05 + 0.03, 0.1, zb], metal);
    0.0
}

pub(crate) const LAWN_MOWER: Category = def(
    "lawn_mower",
    "lawn mower",
    &["lawnmower", "mower", "push mower", "grass cutter", "rotary mower"],
    &["garage", "outdoor", "machine"],
    "a push lawn mower: a deck on four wheels with a grass box and a long handle",
    &["machine", "garden tool"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // 40–46 cm rotary mowers: 140–160 × 45–55 × 95–105 cm with the handle up.
    &size3(1.5, 0.5, 1.0, 0.8, 1.15, 0.04),
    build_lawn_mower,
);

fn build_lawn_mower(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let deck =
        b.material("deck", pick(rng, &[[0.2, 0.55, 0.3, 1.0], [0.8, 0.15, 0.12, 1.0], [0.95, 0.75, 0.1, 1.0]]), true);
    let black = b.material("black", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dl = w * 0.35;
    slab(b, [hw - dl, -hd, 0.03], [hw, hd, 0.3], deck);
    slab(b, [hw - dl * 0.7, -hd * 0.5, 0.299], [hw - dl * 0.2, hd * 0.5, 0.42], black);
    for x in [hw - dl + 0.08, hw - 0.08] {
        slab(b, [x - 0.08, -hd, 0.0], [x + 0.08, -hd + 0.05, 0.031], black);
        slab(b, [x - 0.08, hd - 0.05, 0.0], [x + 0.08, hd, 0.031], black);
    }
    slab(b, [hw - dl - w * 0.25, -hd * 0.8, 0.05], [hw - dl + 0.001, hd * 0.8, 0.35], black);
    super::kit::strut(
        b,
        [hw - dl, -hd * 0.8, 0.32],
        [-hw + 0.02, -hd * 0.8, h - 0.02],
        [0.025, 0.025],
        Axis::Y,
        black,
        false,
    );
    super::kit::strut(
        b,
        [hw - dl, hd * 0.8, 0.32],
        [-hw + 0.02, hd * 0.8, h - 0.02],
        [0.025, 0.025],
        Axis::Y,
        black,
        false,
    );
    slab(b, [-hw, -hd * 0.8, h - 0.03], [-hw + 0.03, hd * 0.8, h], black);
    collider_between(b, [-hw, -hd * 0.8, 0.35], [hw - dl - w * 0.25, hd * 0.8, h]);
    0.0
}

pub(crate) const JERRY_CAN: Category = def(
    "jerry_can",
    "jerry can",
    &["jerrycan", "fuel can", "gas can", "petrol can", "water canister", "fuel container", "gasoline can"],
    &["garage", "workshop", "container", "graspable", "hazard"],
    "a 20 litre jerry can with three handles and a spout cap",
    &["can", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // NATO 20 l jerry cans: 35 × 16.5 × 47 cm.
    &size3(0.35, 0.165, 0.47, 0.6, 1.1, 0.04),
    build_jerry_can,
);

fn build_jerry_can(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material(
        "body",
        pick(rng, &[[0.8, 0.12, 0.1, 1.0], [0.3, 0.38, 0.25, 1.0], [0.15, 0.35, 0.7, 1.0], [0.95, 0.75, 0.1, 1.0]]),
        true,
    );
    let cap = b.material("cap", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let body = h * 0.85;
    slab(b, [-hw, -hd, 0.0], [hw, hd, body], steel);
    for x in spread(-hw * 0.7, hw * 0.2, 3) {
        decal_between(b, [x - 0.015, -0.012, body - 0.002], [x + 0.015, 0.012, h], steel);
    }
    collider_between(b, [-hw * 0.7, -0.012, body - 0.002], [hw * 0.2, 0.012, h]);
    lathe(
        b,
        0,
        [hw * 0.65, 0.0],
        0.025,
        body - 0.001,
        h - body + 0.001,
        &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        cap,
    );
    collider_between(b, [hw * 0.65 - 0.018, -0.018, body - 0.001], [hw * 0.65 + 0.018, 0.018, h]);
    (w * d * body * 600.0).max(2.0)
}

pub(crate) const CAR_BATTERY: Category = def(
    "car_battery",
    "car battery",
    &["battery", "lead-acid battery", "vehicle battery", "12v battery", "auto battery", "leisure battery"],
    &["garage", "workshop", "electrical", "graspable", "heavy"],
    "a 12 volt car battery: a black box with two terminals on top",
    &["battery", "electrical equipment"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Group 24/H6 batteries: 26–28 × 17–18 × 19–20 cm, 15–20 kg.
    &size3(0.27, 0.175, 0.19, 0.7, 1.4, 0.04),
    build_car_battery,
);

fn build_car_battery(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material("case", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.2, 0.22, 0.25, 1.0]]), true);
    let red = b.material("positive", [0.8, 0.1, 0.08, 1.0], false);
    let lead = b.material("negative", [0.35, 0.35, 0.37, 1.0], false);
    let label = b.material("label", pick(rng, &[LABEL_WHITE, [0.15, 0.35, 0.7, 1.0], SAFETY_YELLOW]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let body = h - 0.02;
    slab(b, [-hw, -hd, 0.0], [hw, hd, body], case);
    rod(b, [-hw * 0.75, hd * 0.55, body + 0.01], 0.01, 0.02, Axis::Z, red);
    rod(b, [hw * 0.75, hd * 0.55, body + 0.01], 0.01, 0.02, Axis::Z, lead);
    collider_between(
        b,
        [-hw * 0.75 - 0.008, hd * 0.55 - 0.008, body - 0.001],
        [-hw * 0.75 + 0.008, hd * 0.55 + 0.008, h],
    );
    decal_between(b, [-hw * 0.6, hd - 0.001, body * 0.3], [hw * 0.6, hd + 0.001, body * 0.8], label);
    (w * d * h * 1500.0).clamp(8.0, 25.0)
}
