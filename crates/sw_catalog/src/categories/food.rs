//! Food and its packaging, the everyday objects of manipulation benchmarks (YCB, LIBERO,
//! RoboCasa): fruit and vegetables turned from a profile and standing on a small flat,
//! so that they stay where they are put (a real apple rests on its base, a ball would
//! roll); loaves, eggs, boxes, cartons and jars. Sizes are typical produce and retail
//! package sizes (YCB object set measurements where it has them).

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::forms::{Seg, bulb, def, lathe, long_item, round_body, rounded_box, stretch_y, whd};
use super::kit::{LABEL_WHITE, collider_between, decal_between, pick, shade};
use super::parts::round_collider;
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const PRODUCE: &[&str] = &["kitchen", "food", "tabletop", "small", "graspable", "round"];
const PACKAGE: &[&str] = &["kitchen", "food", "retail", "tabletop", "small", "graspable"];

/// Round-size parameters: diameter and height with a shared relative range.
const fn round3(dia: f64, h: f64, vary: f64) -> [ParamDef; 3] {
    [
        ParamDef::new("width", dia, dia * 0.7, dia * 1.4, vary, "diameter"),
        ParamDef::new("depth", dia, dia * 0.7, dia * 1.4, vary, "diameter (as width)"),
        ParamDef::new("height", h, h * 0.7, h * 1.4, vary, "height"),
    ]
}

/// A round fruit or vegetable: `profile` (see [`bulb`]) in one of `skins`, with a stalk
/// (visual) of `stalk` colour on top. Mass from its volume at `density` kg/m³.
fn produce(
    p: &Params,
    rng: &mut Rng,
    b: &mut AssetBuilder,
    profile: &[[f64; 2]],
    skins: &[[f32; 4]],
    stalk: [f32; 4],
    density: f64,
) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let skin = b.material("skin", pick(rng, skins), true);
    let stem = b.material("stalk", stalk, false);
    round_body(b, r, h, profile, skin);
    let s = (r * 0.08).max(0.002);
    decal_between(b, [-s, -s, h * 0.86], [s, s, h + 0.002], stem);
    (std::f64::consts::PI / 6.0 * w * w * h * density).max(0.01)
}

macro_rules! fruit {
    ($id:ident, $name:literal, $display:literal, [$($syn:literal),*], $desc:literal, $dia:expr, $h:expr, $build:ident, $profile:expr, $skins:expr, $stalk:expr, $density:expr, $src:literal) => {
        #[doc = $src]
        pub(crate) const $id: Category = def(
            $name,
            $display,
            &[$($syn),*],
            PRODUCE,
            $desc,
            &["fruit", "produce", "food"],
            Kind::Food,
            PlacementKind::OnSurface,
            true,
            &round3($dia, $h, 0.08),
            $build,
        );
        fn $build(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
            produce(p, rng, b, &$profile, $skins, $stalk, $density)
        }
    };
}

const STALK: [f32; 4] = [0.35, 0.25, 0.12, 1.0];
const LEAF: [f32; 4] = [0.2, 0.45, 0.15, 1.0];

// YCB apple 7.5 cm; supermarket apples 7–8.5 cm across, 6.5–8 cm tall.
fruit!(
    APPLE,
    "apple",
    "apple",
    ["red apple", "green apple", "granny smith", "gala apple"],
    "a round apple with a short stalk",
    0.078,
    0.072,
    build_apple,
    bulb(0.35, 0.45, 0.25),
    &[[0.75, 0.1, 0.1, 1.0], [0.55, 0.75, 0.25, 1.0], [0.85, 0.55, 0.15, 1.0]],
    STALK,
    800.0,
    "Apples: 7–8.5 cm across, 6.5–8 cm tall (YCB 7.5 cm)."
);
// YCB orange 7.3 cm; navel oranges 7–9 cm.
fruit!(
    ORANGE,
    "orange",
    "orange",
    ["navel orange", "mandarin", "tangerine", "clementine", "satsuma"],
    "a round orange citrus fruit",
    0.075,
    0.072,
    build_orange,
    bulb(0.3, 0.5, 0.15),
    &[[0.95, 0.55, 0.08, 1.0], [0.98, 0.6, 0.12, 1.0]],
    LEAF,
    850.0,
    "Oranges: 7–9 cm (YCB 7.3 cm)."
);
// YCB lemon 5.4 × 6.8 cm.
fruit!(
    LEMON,
    "lemon",
    "lemon",
    ["lime fruit", "citrus fruit", "citron"],
    "an oval yellow lemon",
    0.056,
    0.07,
    build_lemon,
    [[0.0, 0.0], [0.2, 0.0], [0.7, 0.15], [1.0, 0.45], [0.9, 0.75], [0.3, 0.95], [0.0, 1.0]],
    &[[0.98, 0.88, 0.2, 1.0], [0.55, 0.75, 0.2, 1.0]],
    LEAF,
    900.0,
    "Lemons: 5–6 cm across, 6.5–7.5 cm long (YCB 5.4 × 6.8 cm)."
);
// YCB pear 6.6 × 10 cm.
fruit!(
    PEAR,
    "pear",
    "pear",
    ["conference pear", "bartlett pear"],
    "a pear, wide at the bottom and narrow at the top",
    0.07,
    0.1,
    build_pear,
    [[0.0, 0.0], [0.4, 0.0], [0.9, 0.12], [1.0, 0.3], [0.75, 0.55], [0.5, 0.78], [0.3, 0.95], [0.0, 0.97]],
    &[[0.7, 0.75, 0.25, 1.0], [0.75, 0.6, 0.25, 1.0]],
    STALK,
    800.0,
    "Pears: 6–7.5 cm across, 9–11 cm tall (YCB 6.6 × 10 cm)."
);
// YCB peach 5.9 cm; peaches 6–7.5 cm.
fruit!(
    PEACH,
    "peach",
    "peach",
    ["nectarine", "flat peach", "donut peach"],
    "a round fuzzy peach",
    0.065,
    0.062,
    build_peach,
    bulb(0.3, 0.5, 0.2),
    &[[0.95, 0.6, 0.4, 1.0], [0.85, 0.35, 0.3, 1.0], [0.45, 0.15, 0.3, 1.0]],
    STALK,
    850.0,
    "Peaches: 6–7.5 cm (YCB 5.9 cm)."
);
// Tomatoes: 6–8 cm across, 5–6 cm tall.
fruit!(
    TOMATO,
    "tomato",
    "tomato",
    ["beefsteak tomato", "vine tomato", "salad tomato"],
    "a round red tomato with a green calyx",
    0.07,
    0.055,
    build_tomato,
    bulb(0.4, 0.45, 0.3),
    &[[0.85, 0.12, 0.08, 1.0], [0.9, 0.3, 0.1, 1.0]],
    LEAF,
    950.0,
    "Tomatoes: 6–8 cm across, 5–6 cm tall."
);
// Onions: 6–9 cm.
fruit!(
    ONION,
    "onion",
    "onion",
    ["red onion", "yellow onion", "white onion", "shallot"],
    "a round onion with papery skin and a pointed top",
    0.075,
    0.07,
    build_onion,
    [[0.0, 0.0], [0.3, 0.0], [0.8, 0.15], [1.0, 0.42], [0.8, 0.72], [0.25, 0.92], [0.0, 1.0]],
    &[[0.8, 0.6, 0.35, 1.0], [0.55, 0.2, 0.35, 1.0], [0.92, 0.9, 0.82, 1.0]],
    STALK,
    900.0,
    "Onions: 6–9 cm."
);
// Melons: cantaloupe 15–18 cm, small watermelons 20–25 cm.
fruit!(
    MELON,
    "melon",
    "melon",
    ["watermelon", "cantaloupe", "honeydew", "honeydew melon", "cantaloup", "rockmelon"],
    "a large round melon",
    0.18,
    0.17,
    build_melon,
    bulb(0.3, 0.5, 0.2),
    &[[0.25, 0.45, 0.2, 1.0], [0.8, 0.72, 0.45, 1.0], [0.8, 0.85, 0.55, 1.0]],
    STALK,
    900.0,
    "Melons: cantaloupe 15–18 cm, small watermelons 20–25 cm."
);

// Mangoes: 9–11 cm across, 12–14 cm long (standing 8 × 8 × 12 cm).
fruit!(
    MANGO,
    "mango",
    "mango",
    ["ataulfo mango", "ripe mango"],
    "an oval mango",
    0.085,
    0.11,
    build_mango,
    [[0.0, 0.0], [0.35, 0.0], [0.85, 0.15], [1.0, 0.45], [0.85, 0.8], [0.35, 0.97], [0.0, 1.0]],
    &[[0.95, 0.65, 0.15, 1.0], [0.55, 0.7, 0.2, 1.0], [0.25, 0.35, 0.15, 1.0]],
    STALK,
    950.0,
    "Mangoes: 9–11 cm across, 12–14 cm long."
);
// Kiwi fruit: 5 cm across, 6–7 cm long.
fruit!(
    KIWI,
    "kiwi",
    "kiwi fruit",
    ["kiwifruit", "golden kiwi"],
    "a small oval brown kiwi fruit",
    0.052,
    0.065,
    build_kiwi,
    bulb(0.3, 0.5, 0.25),
    &[[0.55, 0.4, 0.22, 1.0], [0.45, 0.33, 0.2, 1.0]],
    STALK,
    1000.0,
    "Kiwi fruit: 5 cm across, 6–7 cm long."
);
// Pumpkins: 20–30 cm across, 15–25 cm tall.
fruit!(
    PUMPKIN,
    "pumpkin",
    "pumpkin",
    ["squash", "butternut squash", "gourd", "jack-o'-lantern"],
    "a round orange pumpkin with a stalk",
    0.26,
    0.2,
    build_pumpkin,
    bulb(0.4, 0.45, 0.2),
    &[[0.95, 0.5, 0.1, 1.0], [0.85, 0.45, 0.12, 1.0], [0.9, 0.75, 0.45, 1.0]],
    STALK,
    400.0,
    "Pumpkins: 20–30 cm across, 15–25 cm tall."
);
// Cauliflowers and broccoli heads: 12–18 cm across, 10–15 cm tall.
fruit!(
    CAULIFLOWER,
    "cauliflower",
    "cauliflower",
    ["head of cauliflower", "cauliflower head"],
    "a round white head of cauliflower in its leaves",
    0.15,
    0.13,
    build_cauliflower,
    bulb(0.4, 0.35, 0.3),
    &[[0.95, 0.93, 0.85, 1.0], [0.92, 0.9, 0.8, 1.0]],
    LEAF,
    400.0,
    "Cauliflower heads: 12–18 cm across, 10–15 cm tall."
);
fruit!(
    BROCCOLI,
    "broccoli",
    "broccoli",
    ["head of broccoli", "broccoli head", "calabrese", "broccoli floret"],
    "a green head of broccoli on a short thick stalk",
    0.15,
    0.15,
    build_broccoli,
    bulb(0.25, 0.55, 0.5),
    &[[0.2, 0.45, 0.18, 1.0], [0.25, 0.5, 0.2, 1.0]],
    LEAF,
    350.0,
    "Broccoli heads: 12–18 cm across and as tall."
);
fruit!(
    LETTUCE,
    "lettuce",
    "lettuce",
    ["head of lettuce", "iceberg lettuce", "romaine lettuce", "round lettuce", "little gem"],
    "a round head of lettuce, leaves wrapped tight",
    0.17,
    0.14,
    build_lettuce,
    bulb(0.35, 0.45, 0.35),
    &[[0.55, 0.78, 0.35, 1.0], [0.45, 0.7, 0.3, 1.0], [0.35, 0.55, 0.25, 1.0]],
    LEAF,
    450.0,
    "Iceberg lettuces: 15–20 cm across, 12–16 cm tall."
);
fruit!(
    PLUM,
    "plum",
    "plum",
    ["damson", "greengage", "red plum"],
    "a small purple plum with a short stalk",
    0.052,
    0.055,
    build_plum,
    bulb(0.3, 0.45, 0.25),
    &[[0.4, 0.12, 0.35, 1.0], [0.5, 0.15, 0.3, 1.0], [0.95, 0.6, 0.2, 1.0]],
    STALK,
    1000.0,
    "Plums: 4.5–6 cm across."
);
fruit!(
    LIME,
    "lime",
    "lime",
    ["key lime", "persian lime"],
    "a small round green lime",
    0.05,
    0.054,
    build_lime,
    bulb(0.3, 0.5, 0.2),
    &[[0.45, 0.7, 0.15, 1.0], [0.35, 0.6, 0.12, 1.0]],
    STALK,
    1000.0,
    "Limes: 4.5–6 cm across, 5–6 cm long."
);
fruit!(
    STRAWBERRY,
    "strawberry",
    "strawberry",
    ["wild strawberry", "garden strawberry"],
    "a red strawberry with green leaves on top",
    0.04,
    0.05,
    build_strawberry,
    [[0.0, 0.0], [0.2, 0.0], [0.7, 0.4], [1.0, 0.75], [0.9, 0.95], [0.0, 0.97]],
    &[[0.85, 0.1, 0.12, 1.0], [0.75, 0.08, 0.1, 1.0]],
    LEAF,
    950.0,
    "Strawberries: 3–5 cm across, 4–6 cm long."
);
// Bell peppers: 7–9 cm across, 8–10 cm tall.
fruit!(
    BELL_PEPPER,
    "bell_pepper",
    "bell pepper",
    ["capsicum", "sweet pepper", "red pepper", "green pepper", "pepper"],
    "a bell pepper",
    0.08,
    0.09,
    build_bell_pepper,
    [[0.0, 0.0], [0.5, 0.0], [0.9, 0.1], [1.0, 0.5], [0.9, 0.88], [0.3, 0.95], [0.0, 0.92]],
    &[[0.85, 0.1, 0.08, 1.0], [0.2, 0.55, 0.2, 1.0], [0.95, 0.8, 0.1, 1.0], [0.95, 0.5, 0.1, 1.0]],
    LEAF,
    500.0,
    "Bell peppers: 7–9 cm across, 8–10 cm tall."
);
// Garlic bulbs: 5–6 cm across, 4–5 cm tall.
fruit!(
    GARLIC,
    "garlic",
    "head of garlic",
    ["garlic bulb", "bulb of garlic", "garlic clove"],
    "a head of garlic",
    0.055,
    0.048,
    build_garlic,
    [[0.0, 0.0], [0.4, 0.0], [0.9, 0.15], [1.0, 0.4], [0.7, 0.75], [0.2, 0.92], [0.0, 1.0]],
    &[[0.95, 0.93, 0.88, 1.0], [0.9, 0.85, 0.85, 1.0]],
    [0.8, 0.75, 0.6, 1.0],
    600.0,
    "Garlic bulbs: 5–6 cm across, 4–5 cm tall."
);
// Pineapples: 12–15 cm across, 30 cm tall with the crown.
fruit!(
    PINEAPPLE,
    "pineapple",
    "pineapple",
    ["ananas"],
    "a pineapple with a leafy crown",
    0.13,
    0.3,
    build_pineapple,
    [[0.0, 0.0], [0.6, 0.0], [0.95, 0.12], [1.0, 0.35], [0.8, 0.6], [0.3, 0.68], [0.5, 0.85], [0.15, 1.0], [0.0, 1.0]],
    &[[0.8, 0.6, 0.2, 1.0], [0.7, 0.55, 0.2, 1.0]],
    LEAF,
    500.0,
    "Pineapples: 12–15 cm across, 28–32 cm tall with the crown."
);
// Strawberries 3 cm; a punnet of them: 14 × 9 × 6 cm.
fruit!(
    GRAPES,
    "grapes",
    "bunch of grapes",
    ["grape", "red grapes", "green grapes"],
    "a bunch of grapes or a handful of berries",
    0.12,
    0.08,
    build_grapes,
    bulb(0.45, 0.4, 0.35),
    &[[0.45, 0.15, 0.35, 1.0], [0.6, 0.8, 0.3, 1.0], [0.8, 0.1, 0.15, 1.0]],
    STALK,
    600.0,
    "A bunch of grapes lying down: 12–18 cm long, 8–10 cm high; a punnet of berries 14 × 9 × 6 cm."
);

/// A long vegetable lying down: tapering ends around a round body along X.
fn long_veg(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, skins: &[[f32; 4]]) -> f64 {
    let (w, d, h) = whd(p);
    let skin = b.material("skin", pick(rng, skins), true);
    let tip = b.material("ends", [0.55, 0.5, 0.25, 1.0], false);
    let end = w * 0.1;
    long_item(
        b,
        &[
            Seg {
                x0: -w / 2.0,
                x1: -w / 2.0 + end + 0.002,
                width: d * 0.6,
                height: h * 0.6,
                round: true,
                material: tip,
            },
            Seg { x0: -w / 2.0 + end, x1: w / 2.0 - end, width: d, height: h, round: true, material: skin },
            Seg { x0: w / 2.0 - end - 0.002, x1: w / 2.0, width: d * 0.6, height: h * 0.6, round: true, material: tip },
        ],
    );
    (w * d * h * 700.0).max(0.05)
}

pub(crate) const CUCUMBER: Category = def(
    "cucumber",
    "cucumber",
    &["english cucumber", "salad cucumber"],
    PACKAGE,
    "a long green cucumber lying down",
    &["vegetable", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Cucumbers 25–30 cm, courgettes 18–22 cm, 4–5 cm across.
    &[
        ParamDef::new("width", 0.24, 0.14, 0.35, 0.1, "length"),
        ParamDef::new("depth", 0.045, 0.03, 0.08, 0.08, "diameter"),
        ParamDef::new("height", 0.045, 0.03, 0.08, 0.08, "diameter, lying"),
    ],
    build_cucumber,
);

fn build_cucumber(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    long_veg(p, rng, b, &[[0.2, 0.45, 0.15, 1.0], [0.3, 0.55, 0.2, 1.0]])
}

pub(crate) const COURGETTE: Category = def(
    "courgette",
    "courgette",
    &["zucchini", "marrow", "summer squash", "baby marrow"],
    PACKAGE,
    "a dark green courgette lying down",
    &["vegetable", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Courgettes: 18–22 cm long, 4–5 cm across.
    &[
        ParamDef::new("width", 0.2, 0.12, 0.4, 0.1, "length"),
        ParamDef::new("depth", 0.045, 0.03, 0.09, 0.08, "diameter"),
        ParamDef::new("height", 0.045, 0.03, 0.09, 0.08, "diameter, lying"),
    ],
    build_courgette,
);

fn build_courgette(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    long_veg(p, rng, b, &[[0.12, 0.3, 0.1, 1.0], [0.18, 0.38, 0.12, 1.0]])
}

pub(crate) const AUBERGINE: Category = def(
    "aubergine",
    "aubergine",
    &["eggplant", "brinjal"],
    PACKAGE,
    "a glossy purple aubergine lying down",
    &["vegetable", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Aubergines: 18–22 cm long, 7–9 cm across.
    &[
        ParamDef::new("width", 0.2, 0.12, 0.3, 0.1, "length"),
        ParamDef::new("depth", 0.08, 0.05, 0.11, 0.08, "diameter"),
        ParamDef::new("height", 0.08, 0.05, 0.11, 0.08, "diameter, lying"),
    ],
    build_aubergine,
);

fn build_aubergine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    long_veg(p, rng, b, &[[0.3, 0.12, 0.3, 1.0], [0.25, 0.08, 0.25, 1.0]])
}

pub(crate) const CORN_COB: Category = def(
    "corn_cob",
    "corn on the cob",
    &["ear of corn", "sweetcorn", "sweet corn", "maize", "corn"],
    PACKAGE,
    "a yellow ear of sweetcorn lying down",
    &["vegetable", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Sweetcorn cobs: 17–22 cm long, 4.5–5 cm across.
    &[
        ParamDef::new("width", 0.19, 0.12, 0.25, 0.08, "length"),
        ParamDef::new("depth", 0.05, 0.035, 0.065, 0.06, "diameter"),
        ParamDef::new("height", 0.05, 0.035, 0.065, 0.06, "diameter, lying"),
    ],
    build_corn_cob,
);

fn build_corn_cob(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    long_veg(p, rng, b, &[[0.98, 0.82, 0.25, 1.0], [0.95, 0.75, 0.2, 1.0]])
}

pub(crate) const POTATO: Category = def(
    "potato",
    "potato",
    &["baking potato", "sweet potato", "spud"],
    PACKAGE,
    "an oval brown potato",
    &["vegetable", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Baking potatoes: 9–12 × 6–7.5 × 5–6 cm.
    &[
        ParamDef::new("width", 0.1, 0.06, 0.14, 0.1, "length"),
        ParamDef::new("depth", 0.068, 0.045, 0.09, 0.08, "width"),
        ParamDef::new("height", 0.055, 0.035, 0.075, 0.08, "height lying"),
    ],
    build_potato,
);

fn build_potato(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let skin =
        b.material("skin", pick(rng, &[[0.7, 0.55, 0.35, 1.0], [0.6, 0.3, 0.25, 1.0], [0.78, 0.65, 0.45, 1.0]]), true);
    let r = w / 2.0;
    let m = revolve(&bulb(0.55, 0.5, 0.5).iter().map(|[a, z]| [a * r, z * h]).collect::<Vec<_>>(), ROUND);
    b.visual_mesh_on(0, &stretch_y(m, d / w), Pose::IDENTITY, skin);
    collider_between(b, [-r, -d / 2.0 * 0.75, 0.0], [r, d / 2.0 * 0.75, h]);
    collider_between(b, [-r * 0.75, -d / 2.0, 0.0], [r * 0.75, d / 2.0, h]);
    w * d * h * 600.0
}

pub(crate) const BANANA: Category = def(
    "banana",
    "banana",
    &["bananas", "plantain", "bunch of bananas"],
    PACKAGE,
    "a curved yellow banana lying on its side",
    &["fruit", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // YCB banana: 19 cm tip to tip, 3.6 cm thick, its curve 6–7 cm across; 17–22 cm long.
    &[
        ParamDef::new("width", 0.19, 0.13, 0.24, 0.08, "tip to tip"),
        ParamDef::new("depth", 0.065, 0.04, 0.09, 0.08, "across the curve"),
        ParamDef::new("height", 0.037, 0.028, 0.045, 0.06, "thickness lying"),
    ],
    build_banana,
);

fn build_banana(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let skin =
        b.material("skin", pick(rng, &[[0.95, 0.85, 0.2, 1.0], [0.8, 0.82, 0.25, 1.0], [0.93, 0.78, 0.2, 1.0]]), true);
    let tip = b.material("tips", [0.25, 0.2, 0.1, 1.0], false);
    // Five round pieces along a gentle arc bowed towards +Y, each its own box.
    let n = 5;
    let seg = w / n as f64;
    let rm = d.min(h) / 2.0;
    // The arc's centres stay inside the overall box, which collides as one.
    let sag = (d / 2.0 - rm).max(0.0);
    for k in 0..n {
        let x0 = -w / 2.0 + seg * k as f64;
        let t = ((k as f64 + 0.5) / n as f64 - 0.5) / 0.4;
        let y = sag * (1.0 - 2.0 * t * t).clamp(-1.0, 1.0);
        let end = k == 0 || k == n - 1;
        let r = rm * if end { 0.7 } else { 1.0 };
        let body = sw_geom::cylinder_mesh(r, seg / 2.0 + 0.002, ROUND);
        let m = if end { tip } else { skin };
        b.visual_mesh_on(0, &body, super::kit::along([x0 + seg / 2.0, y, r], super::kit::Axis::X), m);
    }
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h]);
    0.12 * w / 0.19
}

pub(crate) const CARROT: Category = def(
    "carrot",
    "carrot",
    &["carrots", "baby carrot"],
    PACKAGE,
    "a long orange carrot with green tops",
    &["vegetable", "produce", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Carrots: 15–20 cm long, 2.5–3.5 cm at the top.
    &[
        ParamDef::new("width", 0.18, 0.1, 0.25, 0.1, "length"),
        ParamDef::new("depth", 0.03, 0.02, 0.04, 0.08, "diameter at the top"),
        ParamDef::new("height", 0.03, 0.02, 0.04, 0.08, "diameter at the top, lying"),
    ],
    build_carrot,
);

fn build_carrot(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let skin = b.material("skin", pick(rng, &[[0.95, 0.5, 0.1, 1.0], [0.9, 0.45, 0.12, 1.0]]), true);
    let leaf = b.material("tops", LEAF, false);
    let tops = w * 0.15;
    long_item(
        b,
        &[
            Seg { x0: -w / 2.0, x1: -w / 2.0 + w * 0.3, width: d * 0.5, height: h * 0.5, round: true, material: skin },
            Seg {
                x0: -w / 2.0 + w * 0.3 - 0.002,
                x1: w / 2.0 - tops,
                width: d,
                height: h,
                round: true,
                material: skin,
            },
            Seg::flat(w / 2.0 - tops - 0.002, w / 2.0, d * 0.6, h * 0.5, leaf),
        ],
    );
    (w * d * h * 500.0).max(0.03)
}

pub(crate) const EGG: Category = def(
    "egg",
    "egg",
    &["hen's egg", "chicken egg", "boiled egg"],
    PRODUCE,
    "a hen's egg standing on its broad end",
    &["food", "produce"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Large eggs: 4.3–4.6 cm across, 5.6–6 cm tall.
    &round3(0.045, 0.058, 0.05),
    build_egg,
);

fn build_egg(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let shell = [[0.0, 0.0], [0.35, 0.0], [0.85, 0.12], [1.0, 0.38], [0.85, 0.72], [0.45, 0.94], [0.0, 1.0]];
    produce(p, rng, b, &shell, &[[0.95, 0.92, 0.85, 1.0], [0.85, 0.68, 0.5, 1.0]], [0.9, 0.88, 0.82, 1.0], 1030.0)
}

pub(crate) const BREAD_LOAF: Category = def(
    "bread_loaf",
    "loaf of bread",
    &["bread", "loaf", "baguette", "baguet", "sourdough loaf", "sandwich loaf"],
    PACKAGE,
    "a baked loaf of bread with a domed golden crust",
    &["bread", "food", "baked good"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // 800 g tin loaves: 22–28 × 11–13 × 11–13 cm.
    &[
        ParamDef::new("width", 0.26, 0.16, 0.6, 0.1, "length"),
        ParamDef::new("depth", 0.12, 0.07, 0.15, 0.08, "width"),
        ParamDef::new("height", 0.12, 0.06, 0.15, 0.08, "height"),
    ],
    build_bread_loaf,
);

fn build_bread_loaf(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let crust = b.material(
        "crust",
        pick(rng, &[[0.78, 0.52, 0.25, 1.0], [0.65, 0.4, 0.2, 1.0], [0.85, 0.65, 0.38, 1.0]]),
        true,
    );
    let score = b.material("scores", [0.92, 0.82, 0.6, 1.0], false);
    // A box base and a domed top along X.
    let hb = h * 0.55;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, hb, d * 0.2, crust);
    let dome = revolve(
        &[[0.0, 0.0], [d / 2.0, 0.0], [d / 2.0 * 0.85, (h - hb) * 0.6], [d / 2.0 * 0.45, h - hb], [0.0, h - hb]],
        ROUND,
    );
    let mut m = dome;
    for v in &mut m.vertices {
        v[0] *= (w / d * 0.95) as f32;
    }
    b.visual_mesh_on(0, &m, Pose::from_pos([0.0, 0.0, hb - 0.002]), crust);
    collider_between(b, [-w * 0.42, -d * 0.3, hb - 0.002], [w * 0.42, d * 0.3, h]);
    for x in [-w * 0.2, 0.0, w * 0.2] {
        decal_between(b, [x - 0.004, -d * 0.25, h * 0.93], [x + 0.004, d * 0.25, h + 0.001], score);
    }
    w * d * h * 230.0
}

/// A printed carton: the box, a front panel in another colour and a white label band.
fn carton(b: &mut AssetBuilder, rng: &mut Rng, w: f64, d: f64, h: f64, prints: &[[f32; 4]]) -> f64 {
    let print = pick(rng, prints);
    let body = b.material("print", print, true);
    let panel = b.material("panel", shade(print, 1.25), false);
    let label = b.material("label", LABEL_WHITE, false);
    let top = super::kit::slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], body);
    decal_between(b, [-w * 0.4, d / 2.0 - 0.0005, h * 0.2], [w * 0.4, d / 2.0 + 0.001, h * 0.75], panel);
    decal_between(b, [-w * 0.3, d / 2.0, h * 0.42], [w * 0.3, d / 2.0 + 0.0015, h * 0.58], label);
    top
}

pub(crate) const CEREAL_BOX: Category = def(
    "cereal_box",
    "cereal box",
    &[
        "box of cereal",
        "cracker box",
        "cornflakes box",
        "biscuit box",
        "food box",
        "pasta box",
        "box of crackers",
        "cereal",
        "boxed food",
        "box of food",
    ],
    PACKAGE,
    "a tall printed cardboard box of breakfast cereal or crackers",
    &["box", "package", "packaging", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // YCB cracker box 16 × 6 × 21 cm; 375 g cereal boxes 19 × 7 × 28 cm.
    &[
        ParamDef::new("width", 0.19, 0.12, 0.3, 0.1, "front width"),
        ParamDef::new("depth", 0.07, 0.05, 0.1, 0.1, "side depth"),
        ParamDef::new("height", 0.27, 0.18, 0.36, 0.1, "height"),
    ],
    build_cereal_box,
);

fn build_cereal_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    carton(
        b,
        rng,
        w,
        d,
        h,
        &[[0.85, 0.15, 0.12, 1.0], [0.95, 0.75, 0.15, 1.0], [0.15, 0.35, 0.7, 1.0], [0.2, 0.55, 0.25, 1.0]],
    );
    0.1 + w * d * h * 150.0
}

pub(crate) const MILK_CARTON: Category = def(
    "milk_carton",
    "milk carton",
    &["carton of milk", "juice carton", "milk", "orange juice", "tetra pak", "carton of juice"],
    PACKAGE,
    "a gable-topped carton of milk or juice",
    &["carton", "package", "packaging", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Tetra Rex 1 l gable top: 7 × 7 × 24 cm; Tetra Brik 1 l: 9.5 × 6.4 × 19.5 cm.
    &[
        ParamDef::new("width", 0.075, 0.05, 0.1, 0.1, "along X"),
        ParamDef::new("depth", 0.072, 0.05, 0.1, 0.08, "along Y"),
        ParamDef::new("height", 0.235, 0.1, 0.3, 0.08, "to the top of the gable"),
    ],
    build_milk_carton,
);

fn build_milk_carton(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let print =
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.95, 0.6, 0.1, 1.0], [0.2, 0.45, 0.8, 1.0], [0.85, 0.2, 0.15, 1.0]]);
    let body = b.material("carton", print, true);
    let band =
        b.material("band", pick(rng, &[[0.15, 0.35, 0.75, 1.0], [0.8, 0.1, 0.1, 1.0], [0.15, 0.55, 0.25, 1.0]]), false);
    let shoulder = h * 0.84;
    super::kit::slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, shoulder], body);
    // The gable roof along X and the sealed fin on top.
    let roof = super::shapes::prism_xz(
        &[[-w / 2.0, shoulder - 0.001], [w / 2.0, shoulder - 0.001], [0.0, h - 0.012]],
        -d / 2.0,
        d / 2.0,
    );
    b.visual_mesh_on(0, &roof, Pose::IDENTITY, body);
    decal_between(b, [-0.003, -d / 2.0, h - 0.014], [0.003, d / 2.0, h], body);
    collider_between(b, [-w * 0.25, -d / 2.0, shoulder - 0.001], [w * 0.25, d / 2.0, h]);
    decal_between(b, [-w / 2.0 - 0.001, -d / 2.0 - 0.001, h * 0.3], [w / 2.0 + 0.001, d / 2.0 + 0.001, h * 0.5], band);
    0.05 + w * d * shoulder * 1000.0
}

pub(crate) const JAR: Category = def(
    "jar",
    "jar",
    &[
        "mason jar",
        "jam jar",
        "glass jar",
        "honey jar",
        "peanut butter jar",
        "storage jar",
        "pickle jar",
        "spice jar",
        "cookie jar",
        "honey",
        "jar of honey",
        "jar of jam",
        "pot of honey",
        "marmalade",
        "cayenne",
        "cayenne pepper",
        "paprika",
    ],
    &["kitchen", "food", "tabletop", "small", "graspable", "round", "container"],
    "a glass jar with a screw lid",
    &["container", "vessel"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Ball mason jar 16 oz: 8.6 × 13.5 cm; jam jars 7 × 10 cm.
    &round3(0.08, 0.12, 0.1),
    build_jar,
);

fn build_jar(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let contents = b.material(
        "contents",
        pick(
            rng,
            &[
                [0.6, 0.1, 0.15, 1.0],
                [0.85, 0.6, 0.15, 1.0],
                [0.55, 0.35, 0.2, 1.0],
                [0.35, 0.5, 0.2, 1.0],
                [0.85, 0.88, 0.9, 1.0],
            ],
        ),
        true,
    );
    let lid = b.material(
        "lid",
        pick(rng, &[[0.8, 0.7, 0.3, 1.0], [0.75, 0.1, 0.1, 1.0], [0.8, 0.81, 0.83, 1.0], [0.15, 0.15, 0.16, 1.0]]),
        false,
    );
    let label = b.material("label", LABEL_WHITE, false);
    let lid_h = (h * 0.12).max(0.012);
    lathe(
        b,
        0,
        [0.0, 0.0],
        r,
        0.0,
        h - lid_h,
        &[[0.0, 0.0], [0.92, 0.0], [1.0, 0.05], [1.0, 0.85], [0.85, 1.0], [0.0, 1.0]],
        contents,
    );
    lathe(
        b,
        0,
        [0.0, 0.0],
        r * 0.88,
        h - lid_h - 0.002,
        lid_h + 0.002,
        &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        lid,
    );
    lathe(b, 0, [0.0, 0.0], r + 0.0008, h * 0.3, h * 0.3, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], label);
    round_collider(b, 0, [0.0, 0.0], r, 0.0, h);
    0.2 + r * r * h * 2500.0
}

pub(crate) const SUGAR_BAG: Category = def(
    "sugar_bag",
    "bag of sugar",
    &[
        "bag of flour",
        "flour bag",
        "bag of rice",
        "coffee bag",
        "bag of coffee",
        "paper bag of flour",
        "rice",
        "flour",
        "rice bag",
        "sack of rice",
    ],
    PACKAGE,
    "a 1 kg paper bag of sugar, flour or rice, standing up",
    &["bag", "package", "packaging", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // 1 kg sugar / flour bags: 11–13 × 7–8 × 16–19 cm.
    &[
        ParamDef::new("width", 0.12, 0.08, 0.2, 0.08, "front width"),
        ParamDef::new("depth", 0.075, 0.05, 0.11, 0.08, "side depth"),
        ParamDef::new("height", 0.17, 0.12, 0.3, 0.08, "height"),
    ],
    build_sugar_bag,
);

fn build_sugar_bag(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paper =
        b.material("paper", pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.8, 0.65, 0.45, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    let print =
        b.material("print", pick(rng, &[[0.1, 0.3, 0.7, 1.0], [0.8, 0.15, 0.1, 1.0], [0.2, 0.55, 0.3, 1.0]]), false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h * 0.9, d * 0.3, paper);
    decal_between(b, [-w * 0.45, -d * 0.3, h * 0.9 - 0.002], [w * 0.45, d * 0.3, h], paper);
    collider_between(b, [-w * 0.45, -d * 0.3, h * 0.9 - 0.002], [w * 0.45, d * 0.3, h]);
    decal_between(b, [-w * 0.38, d / 2.0 - 0.001, h * 0.25], [w * 0.38, d / 2.0 + 0.001, h * 0.6], print);
    (w * d * h * 700.0).max(0.2)
}
