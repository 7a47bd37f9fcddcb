//! Offices and classrooms: computers, mice, notebooks, pencils and markers, scissors, tape
//! dispensers, hole punches, calculators, projectors, shredders, reams of paper, pen pots,
//! globes, lecterns and backpacks. Sizes from product ranges, noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::forms::{Seg, def, long_item, rounded_box, size3, spread, whd};
use super::kit::{
    Axis, DARK, INK, LABEL_WHITE, OFFICE_PAINT, PLASTIC, STEEL, WOOD, along, collider_between, decal_between, pick,
    shade, slab,
};
use super::parts::{round_collider, round_solid};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const DESKTOP: &[&str] = &["office", "classroom", "tabletop", "small", "graspable"];

pub(crate) const DESKTOP_COMPUTER: Category = def(
    "desktop_computer",
    "desktop computer",
    &["computer", "pc", "tower pc", "computer tower", "desktop pc", "tower computer", "workstation pc", "gaming pc"],
    &["office", "electronics", "tabletop"],
    "a desktop computer tower case with a power button and vents",
    &["computer", "electronics", "device"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Mid-tower cases: 20–23 × 42–48 × 43–48 cm.
    &size3(0.2, 0.44, 0.44, 0.6, 1.2, 0.06),
    build_desktop_computer,
);

fn build_desktop_computer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case =
        b.material("case", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.85, 0.86, 0.86, 1.0], [0.3, 0.3, 0.32, 1.0]]), true);
    let panel = b.material("front", INK, false);
    let led = b.material("led", [0.2, 0.6, 0.95, 1.0], false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], case);
    decal_between(b, [-w / 2.0 + 0.01, d / 2.0 - 0.001, 0.03], [w / 2.0 - 0.01, d / 2.0 + 0.002, h - 0.03], panel);
    decal_between(b, [-0.008, d / 2.0 + 0.001, h - 0.06], [0.008, d / 2.0 + 0.003, h - 0.045], led);
    (w * d * h * 200.0).max(4.0)
}

pub(crate) const COMPUTER_MOUSE: Category = def(
    "computer_mouse",
    "computer mouse",
    &["mouse", "wireless mouse", "optical mouse", "pc mouse"],
    DESKTOP,
    "a computer mouse",
    &["electronics", "input device", "device"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Logitech M185 / MX: 10–12.5 × 6–7 × 3.5–4.5 cm.
    &size3(0.115, 0.065, 0.04, 0.8, 1.2, 0.05),
    build_computer_mouse,
);

fn build_computer_mouse(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell =
        b.material("shell", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.85, 0.86, 0.86, 1.0], [0.3, 0.3, 0.32, 1.0]]), true);
    let wheel = b.material("wheel", INK, false);
    // A dome stretched along X.
    let m = revolve(
        &[[0.0, 0.0], [0.95, 0.0], [1.0, 0.15], [0.8, 0.7], [0.4, 0.98], [0.0, 1.0]].map(|[a, z]| [a * d / 2.0, z * h]),
        ROUND,
    );
    let mut m = m;
    for v in &mut m.vertices {
        v[0] *= (w / d) as f32;
    }
    b.visual_mesh_on(0, &m, Pose::IDENTITY, shell);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h * 0.6]);
    collider_between(b, [-w * 0.35, -d * 0.3, h * 0.6 - 0.001], [w * 0.35, d * 0.3, h]);
    decal_between(b, [w * 0.2, -0.003, h * 0.7], [w * 0.3, 0.003, h * 0.98], wheel);
    0.09
}

pub(crate) const NOTEBOOK: Category = def(
    "notebook",
    "notebook",
    &[
        "exercise book",
        "notepad",
        "jotter",
        "spiral notebook",
        "copybook",
        "writing pad",
        "legal pad",
        "sketchbook",
        "diary",
    ],
    DESKTOP,
    "an A4 spiral notebook lying closed",
    &["stationery", "paper", "book"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // A4 notebooks 29.7 × 21 × 0.8–1.5 cm; A5 21 × 14.8 cm.
    &[
        ParamDef::new("width", 0.297, 0.14, 0.33, 0.05, "along X"),
        ParamDef::new("depth", 0.21, 0.1, 0.24, 0.1, "along Y"),
        ParamDef::new("height", 0.012, 0.004, 0.025, 0.2, "thickness"),
    ],
    build_notebook,
);

fn build_notebook(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let cover = b.material(
        "cover",
        pick(
            rng,
            &[
                [0.15, 0.3, 0.6, 1.0],
                [0.75, 0.15, 0.12, 1.0],
                [0.2, 0.5, 0.3, 1.0],
                [0.1, 0.1, 0.11, 1.0],
                [0.95, 0.8, 0.2, 1.0],
            ],
        ),
        true,
    );
    let pages = b.material("pages", LABEL_WHITE, false);
    let spiral = b.material("spiral", pick(rng, STEEL), false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], cover);
    decal_between(
        b,
        [-w / 2.0 + 0.003, -d / 2.0 - 0.0005, h * 0.2],
        [w / 2.0 - 0.003, d / 2.0 + 0.0005, h * 0.8],
        pages,
    );
    for x in spread(-w / 2.0 + 0.01, w / 2.0 - 0.01, 12) {
        decal_between(b, [x - 0.002, d / 2.0 - 0.006, -0.0], [x + 0.002, d / 2.0 + 0.002, h], spiral);
    }
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    w * d * h * 600.0 + 0.02
}

pub(crate) const PENCIL: Category = def(
    "pencil",
    "pencil",
    &["graphite pencil", "hb pencil", "colored pencil", "coloured pencil", "crayon", "mechanical pencil"],
    DESKTOP,
    "a hexagonal wooden pencil with a sharpened tip and an eraser",
    &["writing implement", "stationery"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Standard pencils: 19 cm long, 7 mm across flats.
    &[
        ParamDef::new("width", 0.175, 0.08, 0.19, 0.08, "length"),
        ParamDef::new("depth", 0.0075, 0.006, 0.012, 0.05, "across"),
        ParamDef::new("height", 0.0075, 0.006, 0.012, 0.05, "across"),
    ],
    build_pencil,
);

fn build_pencil(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material(
        "paint",
        pick(rng, &[[0.95, 0.8, 0.1, 1.0], [0.2, 0.45, 0.8, 1.0], [0.8, 0.15, 0.12, 1.0], [0.2, 0.6, 0.3, 1.0]]),
        true,
    );
    let wood = b.material("wood", [0.9, 0.75, 0.55, 1.0], false);
    let eraser = b.material("eraser", [0.95, 0.55, 0.6, 1.0], false);
    let tip = w * 0.1;
    long_item(
        b,
        &[
            Seg {
                x0: -w / 2.0,
                x1: -w / 2.0 + tip + 0.001,
                width: d * 0.6,
                height: h * 0.6,
                round: true,
                material: wood,
            },
            Seg { x0: -w / 2.0 + tip, x1: w / 2.0 - 0.012, width: d, height: h, round: false, material: paint },
            Seg { x0: w / 2.0 - 0.0125, x1: w / 2.0, width: d * 0.95, height: h * 0.95, round: true, material: eraser },
        ],
    );
    0.006
}

pub(crate) const MARKER: Category = def(
    "marker",
    "marker",
    &[
        "marker pen",
        "felt pen",
        "felt-tip pen",
        "highlighter",
        "whiteboard marker",
        "sharpie",
        "permanent marker",
        "dry erase marker",
    ],
    DESKTOP,
    "a capped felt-tip marker pen",
    &["writing implement", "stationery", "pen"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Whiteboard markers: 12.5–14 cm long, 1.7–2 cm across.
    &[
        ParamDef::new("width", 0.135, 0.1, 0.15, 0.05, "length"),
        ParamDef::new("depth", 0.018, 0.012, 0.022, 0.05, "across"),
        ParamDef::new("height", 0.018, 0.012, 0.022, 0.05, "across"),
    ],
    build_marker,
);

fn build_marker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let barrel = b.material(
        "barrel",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0], [0.95, 0.9, 0.2, 1.0]]),
        false,
    );
    let cap = b.material(
        "cap",
        pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.1, 0.3, 0.75, 1.0], [0.8, 0.12, 0.1, 1.0], [0.15, 0.6, 0.25, 1.0]]),
        true,
    );
    let c = w * 0.3;
    long_item(
        b,
        &[
            Seg { x0: -w / 2.0, x1: -w / 2.0 + c + 0.002, width: d, height: h, round: true, material: cap },
            Seg { x0: -w / 2.0 + c, x1: w / 2.0, width: d * 0.92, height: h * 0.92, round: true, material: barrel },
        ],
    );
    0.015
}

pub(crate) const SCISSORS: Category = def(
    "scissors",
    "scissors",
    &["pair of scissors", "shears", "paper scissors", "kitchen scissors", "office scissors"],
    DESKTOP,
    "a pair of scissors lying closed, with two finger loops",
    &["tool", "cutting tool", "stationery"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Office scissors: 17–21 × 6–8 × 1–1.5 cm.
    &size3(0.2, 0.075, 0.012, 0.7, 1.3, 0.05),
    build_scissors,
);

fn build_scissors(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let grips = b.material(
        "grips",
        pick(rng, &[[0.15, 0.3, 0.7, 1.0], [0.85, 0.2, 0.15, 1.0], [0.1, 0.1, 0.11, 1.0], [0.95, 0.6, 0.1, 1.0]]),
        true,
    );
    let steel = b.material("blades", [0.82, 0.83, 0.85, 1.0], false);
    let blade = w * 0.55;
    decal_between(b, [-w / 2.0, -0.008, 0.0], [-w / 2.0 + blade + 0.005, 0.008, h * 0.5], steel);
    collider_between(b, [-w / 2.0, -0.008, 0.0], [-w / 2.0 + blade, 0.008, h * 0.5]);
    // Two loops side by side behind the pivot.
    let lw = w - blade;
    for s in [-1.0, 1.0] {
        let (y0, y1) = super::kit::ordered(s * 0.002, s * d / 2.0);
        let ring = revolve(&super::shapes::rounded_ring_profile(0.5 * 0.55, 0.5, 0.0, h, 0.0), 16);
        let mut m = ring;
        for v in &mut m.vertices {
            v[0] *= lw as f32;
            v[1] *= (y1 - y0) as f32;
        }
        b.visual_mesh_on(0, &m, Pose::from_pos([w / 2.0 - lw / 2.0, (y0 + y1) / 2.0, 0.0]), grips);
        collider_between(b, [w / 2.0 - lw, y0, 0.0], [w / 2.0, y1, h]);
    }
    0.07
}

pub(crate) const TAPE_DISPENSER: Category = def(
    "tape_dispenser",
    "tape dispenser",
    &["sellotape dispenser", "scotch tape dispenser", "desk tape dispenser", "tape holder"],
    DESKTOP,
    "a weighted desk tape dispenser holding a roll of clear tape",
    &["office supply", "stationery", "dispenser"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Scotch C-38 desk dispenser: 15 × 6 × 8 cm.
    &size3(0.15, 0.06, 0.08, 0.7, 1.3, 0.06),
    build_tape_dispenser,
);

fn build_tape_dispenser(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.85, 0.2, 0.15, 1.0], [0.2, 0.45, 0.75, 1.0]]), true);
    let tape = b.material("tape", [0.85, 0.88, 0.85, 1.0], false);
    let r = (h * 0.4).min(w * 0.25);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h - 2.0 * r + 0.01, 0.01, body);
    b.visual(Shape::Cylinder { radius: r, half_height: d * 0.35 }, along([-w * 0.12, 0.0, h - r], Axis::Y), tape);
    collider_between(b, [-w * 0.12 - r, -d * 0.35, h - 2.0 * r], [-w * 0.12 + r, d * 0.35, h]);
    decal_between(b, [w / 2.0 - 0.03, -d / 2.0, h - 2.0 * r + 0.009], [w / 2.0, d / 2.0, h - r], body);
    collider_between(b, [w / 2.0 - 0.03, -d / 2.0, h - 2.0 * r + 0.009], [w / 2.0, d / 2.0, h - r]);
    0.5
}

pub(crate) const HOLE_PUNCH: Category = def(
    "hole_punch",
    "hole punch",
    &["paper punch", "two-hole punch", "hole puncher", "paper puncher", "puncher"],
    DESKTOP,
    "a two-hole paper punch with a lever on top",
    &["office supply", "stationery", "tool"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Leitz / Rapesco 2-hole punches: 12–14 × 10–12 × 6–8 cm.
    &size3(0.13, 0.11, 0.07, 0.75, 1.3, 0.06),
    build_hole_punch,
);

fn build_hole_punch(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let lever =
        b.material("lever", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.2, 0.45, 0.75, 1.0], [0.6, 0.62, 0.65, 1.0]]), true);
    let base = b.material("base", pick(rng, DARK), false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h * 0.3], base);
    slab(b, [-w / 2.0 + 0.01, -d / 2.0, h * 0.3 - 0.001], [w / 2.0 - 0.01, d * 0.1, h], lever);
    0.4
}

pub(crate) const CALCULATOR: Category = def(
    "calculator",
    "calculator",
    &["pocket calculator", "desk calculator", "scientific calculator", "graphing calculator"],
    DESKTOP,
    "a desk calculator with a display and a keypad",
    &["device", "electronics"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Casio desk / scientific calculators: 16–19 × 8–14 × 1.5–3 cm.
    &size3(0.16, 0.085, 0.02, 0.7, 1.3, 0.06),
    build_calculator,
);

fn build_calculator(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material(
        "case",
        pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.75, 0.76, 0.78, 1.0], [0.3, 0.35, 0.45, 1.0]]),
        true,
    );
    let screen = b.material("screen", [0.6, 0.68, 0.58, 1.0], false);
    let keys = b.material("keys", pick(rng, &[[0.9, 0.9, 0.88, 1.0], [0.25, 0.25, 0.27, 1.0]]), false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], case);
    decal_between(b, [w * 0.25, -d * 0.38, h - 0.001], [w * 0.45, d * 0.38, h + 0.001], screen);
    for x in spread(-w * 0.45, w * 0.15, 5) {
        for y in spread(-d * 0.4, d * 0.4, 4) {
            decal_between(b, [x - w * 0.04, y - d * 0.07, h - 0.001], [x + w * 0.04, y + d * 0.07, h + 0.002], keys);
        }
    }
    0.12
}

pub(crate) const PROJECTOR: Category = def(
    "projector",
    "projector",
    &["video projector", "beamer", "data projector", "overhead projector", "digital projector"],
    &["office", "classroom", "electronics", "tabletop", "small"],
    "a video projector with a lens on its front",
    &["device", "electronics", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Epson / BenQ office projectors: 29–33 × 22–25 × 8–11 cm.
    &size3(0.3, 0.23, 0.095, 0.7, 1.4, 0.05),
    build_projector,
);

fn build_projector(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material("case", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.2, 0.2, 0.21, 1.0]]), true);
    let lens = b.material("lens", [0.1, 0.12, 0.16, 1.0], false);
    let vent = b.material("vents", pick(rng, DARK), false);
    rounded_box(b, [0.0, 0.0], w, d - 0.004, 0.0, h, 0.02, case);
    let r = (h * 0.32).min(w * 0.15);
    b.visual(
        Shape::Cylinder { radius: r, half_height: 0.006 },
        along([-w * 0.25, d / 2.0 - 0.008, h / 2.0], Axis::Y),
        lens,
    );
    decal_between(b, [w * 0.1, d / 2.0 - 0.003, h * 0.25], [w * 0.45, d / 2.0, h * 0.75], vent);
    2.6
}

pub(crate) const PAPER_SHREDDER: Category = def(
    "paper_shredder",
    "paper shredder",
    &["shredder", "document shredder", "office shredder"],
    &["office", "appliance", "container"],
    "an office paper shredder: a cutting head on a bin",
    &["appliance", "office machine", "machine"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Fellowes / Rexel office shredders: 34–40 × 25–30 × 55–65 cm.
    &size3(0.37, 0.28, 0.6, 0.75, 1.3, 0.05),
    build_paper_shredder,
);

fn build_paper_shredder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let bin = b.material("bin", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.55, 0.57, 0.6, 1.0]]), true);
    let head = b.material("head", INK, false);
    let slot = b.material("slot", [0.3, 0.3, 0.32, 1.0], false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h * 0.78], bin);
    slab(b, [-w / 2.0, -d / 2.0, h * 0.78 - 0.001], [w / 2.0, d / 2.0, h], head);
    decal_between(b, [-w * 0.38, -0.004, h - 0.001], [w * 0.38, 0.004, h + 0.001], slot);
    decal_between(b, [-w * 0.25, d / 2.0 - 0.001, h * 0.2], [w * 0.25, d / 2.0 + 0.002, h * 0.25], slot);
    0.0
}

pub(crate) const PAPER_REAM: Category = def(
    "paper_ream",
    "ream of paper",
    &["stack of paper", "printer paper", "copy paper", "paper stack", "pile of paper", "papers", "documents"],
    DESKTOP,
    "a wrapped ream of A4 printer paper",
    &["paper", "stationery", "package"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // A4 reams (500 sheets, 80 g/m²): 29.7 × 21 × 5 cm, 2.5 kg.
    &[
        ParamDef::new("width", 0.297, 0.2, 0.32, 0.02, "along X"),
        ParamDef::new("depth", 0.21, 0.14, 0.23, 0.02, "along Y"),
        ParamDef::new("height", 0.05, 0.002, 0.1, 0.3, "stack height"),
    ],
    build_paper_ream,
);

fn build_paper_ream(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wrap =
        b.material("wrap", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.2, 0.4, 0.75, 1.0], [0.9, 0.3, 0.2, 1.0]]), true);
    let paper = b.material("paper", LABEL_WHITE, false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], wrap);
    decal_between(b, [-w / 2.0 - 0.001, -d / 2.0 + 0.01, h * 0.1], [w / 2.0 + 0.001, d / 2.0 - 0.01, h * 0.9], paper);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    (w * d * h * 800.0).max(0.01)
}

pub(crate) const PEN_HOLDER: Category = def(
    "pen_holder",
    "pen holder",
    &["pen pot", "pencil cup", "pencil holder", "pen cup", "desk organizer", "desk organiser", "pen jar"],
    &["office", "classroom", "tabletop", "small", "graspable", "round", "container"],
    "a round pen pot holding pens and pencils",
    &["container", "holder", "office supply"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Pen pots: 7–9 cm across, 10–11 cm tall (19 cm with the pens).
    &[
        ParamDef::new("width", 0.08, 0.06, 0.11, 0.08, "diameter"),
        ParamDef::new("depth", 0.08, 0.06, 0.11, 0.08, "diameter (as width)"),
        ParamDef::new("height", 0.17, 0.1, 0.2, 0.06, "to the tops of the pens"),
    ],
    build_pen_holder,
);

fn build_pen_holder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let pot = b.material(
        "pot",
        pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.75, 0.76, 0.78, 1.0], [0.55, 0.4, 0.25, 1.0], [0.2, 0.45, 0.75, 1.0]]),
        true,
    );
    let pens = b.material("pens", pick(rng, PLASTIC), false);
    let cup = (h * 0.6).min(0.11);
    round_solid(b, 0, [0.0, 0.0], r, 0.0, cup, pot);
    for (k, a) in [0.0f64, 2.1, 4.2].iter().enumerate() {
        let (x, y) = (r * 0.45 * a.cos(), r * 0.45 * a.sin());
        let top = h - 0.012 * k as f64;
        b.visual(
            Shape::Cylinder { radius: 0.0045, half_height: (top - cup * 0.5) / 2.0 },
            Pose::from_pos([x, y, (top + cup * 0.5) / 2.0]),
            pens,
        );
    }
    collider_between(b, [-r * 0.55, -r * 0.55, cup - 0.001], [r * 0.55, r * 0.55, h]);
    0.2
}

pub(crate) const GLOBE: Category = def(
    "globe",
    "globe",
    &["world globe", "terrestrial globe", "desk globe", "earth globe"],
    &["classroom", "office", "home", "tabletop", "small", "round"],
    "a world globe on a stand",
    &["model", "decoration"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Desk globes: 25–30 cm sphere, 35–42 cm tall with the stand.
    &[
        ParamDef::new("width", 0.3, 0.2, 0.4, 0.06, "globe diameter"),
        ParamDef::new("depth", 0.3, 0.2, 0.4, 0.06, "globe diameter (as width)"),
        ParamDef::new("height", 0.4, 0.28, 0.55, 0.05, "base to the top of the globe"),
    ],
    build_globe,
);

fn build_globe(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rb = w.min(d) / 2.0;
    let r = rb.min((h - 0.06) / 2.0);
    let sea = b.material("sea", pick(rng, &[[0.2, 0.45, 0.75, 1.0], [0.35, 0.55, 0.7, 1.0]]), true);
    let land = b.material("land", pick(rng, &[[0.45, 0.65, 0.3, 1.0], [0.85, 0.75, 0.5, 1.0]]), false);
    let stand = b.material(
        "stand",
        pick(rng, &[[0.6, 0.45, 0.28, 1.0], [0.1, 0.1, 0.11, 1.0], [0.75, 0.65, 0.35, 1.0]]),
        false,
    );
    let zc = h - r;
    round_solid(b, 0, [0.0, 0.0], rb, 0.0, 0.025, stand);
    round_solid(b, 0, [0.0, 0.0], 0.01, 0.024, zc - r + 0.01, stand);
    b.visual(Shape::Sphere { radius: r }, Pose::from_pos([0.0, 0.0, zc]), sea);
    for (x, y, z) in [(0.5, 0.3, 0.5), (-0.4, 0.5, 0.2), (0.2, -0.6, -0.3)] {
        let n: f64 = x * x + y * y + z * z;
        let k = r * 0.72 / n.sqrt();
        b.visual(Shape::Sphere { radius: r * 0.3 }, Pose::from_pos([x * k, y * k, zc + z * k]), land);
    }
    round_collider(b, 0, [0.0, 0.0], r, zc - r * 0.7, zc + r);
    1.2
}

pub(crate) const LECTERN: Category = def(
    "lectern",
    "lectern",
    &["podium", "speaker's stand", "reading stand", "pulpit", "rostrum"],
    &["classroom", "office", "furniture", "surface"],
    "a lectern: a tall stand with a sloping top to put notes on",
    &["stand", "desk", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Lecterns: 50–60 × 40–50 × 110–120 cm.
    &size3(0.55, 0.45, 1.15, 0.8, 1.2, 0.05),
    build_lectern,
);

fn build_lectern(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = if rng.chance(0.6) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", rgba, true);
    let top = b.material("top", shade(rgba, 0.85), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.04], body);
    slab(b, [-hw * 0.7, -hd * 0.6, 0.039], [hw * 0.7, hd * 0.6, h - 0.06], body);
    // The sloping top: a ledge at the front, higher at the back.
    let mut m = super::shapes::prism(&[[-hd, h - 0.06], [hd, h - 0.06], [hd, h - 0.03], [-hd, h]], -hw, hw);
    for v in &mut m.vertices {
        *v = [v[2], v[0], v[1]];
    }
    b.visual_mesh_on(0, &m, Pose::IDENTITY, top);
    collider_between(b, [-hw, -hd, h - 0.061], [hw, hd, h - 0.03]);
    collider_between(b, [-hw, -hd, h - 0.031], [hw, 0.0, h]);
    0.0
}

pub(crate) const BACKPACK: Category = def(
    "backpack",
    "backpack",
    &["rucksack", "school bag", "schoolbag", "knapsack", "daypack", "bookbag", "satchel"],
    &["classroom", "office", "home", "small", "graspable"],
    "a backpack standing upright with a front pocket and shoulder straps",
    &["bag", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // School backpacks: 28–33 × 15–20 × 42–48 cm.
    &size3(0.3, 0.18, 0.45, 0.7, 1.3, 0.06),
    build_backpack,
);

fn build_backpack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let fabric = pick(
        rng,
        &[
            [0.15, 0.25, 0.5, 1.0],
            [0.7, 0.15, 0.15, 1.0],
            [0.12, 0.12, 0.13, 1.0],
            [0.3, 0.45, 0.3, 1.0],
            [0.85, 0.6, 0.15, 1.0],
        ],
    );
    let body = b.material("fabric", fabric, true);
    let trim = b.material("trim", shade(fabric, 0.6), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    rounded_box(b, [0.0, -hd * 0.2], w, d * 0.8, 0.0, h, w * 0.25, body);
    rounded_box(b, [0.0, hd * 0.6], w * 0.75, d * 0.4 + 0.002, 0.02, h * 0.5, w * 0.15, trim);
    for x in [-hw * 0.5, hw * 0.5] {
        decal_between(b, [x - 0.025, -hd, h * 0.15], [x + 0.025, -hd + 0.012, h * 0.85], trim);
    }
    0.6
}
