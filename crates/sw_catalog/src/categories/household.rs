//! Everyday things people name again and again that the catalog lacked (issue 21):
//! condiments and their bottles, tins and packs of food, kitchen gadgets, home
//! electronics, music and sport, toys, and the larger things of homes and gardens.
//!
//! Every one collides as one box over its whole size, standing on its flat base, so that
//! it settles at once and stacks; what it looks like is drawn inside that box (turned
//! bodies, panels, bars). Hand-held ones are as small as the real thing, within a
//! gripper's opening where the real thing is. Sizes are the middle of published product
//! ranges, noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::forms::{def, lathe, size3, whd};
use super::kit::{
    Axis, DARK, GLASS, INK, LABEL_WHITE, PLASTIC, RUBBER, STEEL, UPHOLSTERY, WOOD, collider_between, decal_between,
    pick, rod, shade,
};
use crate::{Category, Kind, ParamDef, Params};

/// The whole size as one collision box, from the floor (or the table) up.
pub(crate) fn hull(b: &mut AssetBuilder, w: f64, d: f64, h: f64) -> f64 {
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h])
}

/// A turned body to look at, as wide as the narrower side allows, from `z0` to `z1`
/// (fractions of the height).
pub(crate) fn turn(b: &mut AssetBuilder, (w, d, h): (f64, f64, f64), z: [f64; 2], profile: &[[f64; 2]], m: usize) {
    lathe(b, 0, [0.0, 0.0], w.min(d) / 2.0, z[0] * h, (z[1] - z[0]) * h, profile, m);
}

/// A visual box between two corners given as fractions of the size (x and y from the
/// centre, −0.5…0.5; z from the base, 0…1).
///
/// Parts of one material are merged into one mesh, which must stay a valid solid: two
/// boxes that touch must not share an edge. Each part is therefore inset by a few
/// micrometres that depend on its own corners, so that touching parts pull apart.
pub(crate) fn part(b: &mut AssetBuilder, (w, d, h): (f64, f64, f64), lo: [f64; 3], hi: [f64; 3], m: usize) {
    let key = lo.iter().chain(&hi).enumerate().fold(0u64, |k, (i, v)| {
        k.wrapping_mul(31).wrapping_add((v * 1000.0).round() as i64 as u64).wrapping_add(i as u64)
    });
    let inset = 2e-6 * (1 + key % 47) as f64;
    // Panels stand at most 2 mm proud of the box, whatever its size.
    let bound = [w / 2.0 + 0.002, d / 2.0 + 0.002];
    let at = |f: [f64; 3]| -> [f64; 3] {
        [(f[0] * w).clamp(-bound[0], bound[0]), (f[1] * d).clamp(-bound[1], bound[1]), (f[2] * h).clamp(0.0, h + 0.002)]
    };
    let (min, max) = (at(lo), at(hi));
    let min: [f64; 3] = std::array::from_fn(|i| min[i] + inset.min((max[i] - min[i]) * 0.1));
    let max: [f64; 3] = std::array::from_fn(|i| max[i] - inset.min((max[i] - min[i]) * 0.1));
    decal_between(b, min, max, m);
}

/// A visual rod along X at fractions (`y`, `z` of the centre) of the size, `r` fraction
/// of the smaller of height and depth in radius, from `x0` to `x1` (fractions of the width).
pub(crate) fn bar_x(
    b: &mut AssetBuilder,
    (w, d, h): (f64, f64, f64),
    [x0, x1]: [f64; 2],
    [y, z]: [f64; 2],
    r: f64,
    m: usize,
) {
    rod(b, [(x0 + x1) / 2.0 * w, y * d, z * h], r * h.min(d), (x1 - x0) * w, Axis::X, m);
}

/// Mass of a box of the size at `density` kg/m³, at least 10 g.
pub(crate) fn mass(w: f64, d: f64, h: f64, density: f64) -> f64 {
    (w * d * h * density).max(0.01)
}

/// Size parameters of a thing: 0.7…1.4 times the default, a little seeded variation.
pub(crate) const fn sized(w: f64, d: f64, h: f64) -> [ParamDef; 3] {
    size3(w, d, h, 0.7, 1.4, 0.05)
}

const CAN: [[f64; 2]; 6] = [[0.0, 0.0], [0.94, 0.0], [1.0, 0.04], [1.0, 0.96], [0.94, 1.0], [0.0, 1.0]];
const DOME: [[f64; 2]; 5] = [[0.0, 0.0], [1.0, 0.0], [0.92, 0.5], [0.6, 0.88], [0.0, 1.0]];
const CONDIMENT: &[&str] = &["kitchen", "food", "tabletop", "small", "graspable"];
const ROUND_CONDIMENT: &[&str] = &["kitchen", "food", "tabletop", "small", "graspable", "round"];
const GADGET: &[&str] = &["kitchen", "utensil", "tabletop", "small", "graspable"];
const HOME: &[&str] = &["home", "tabletop", "small", "graspable"];
const LEISURE: &[&str] = &["home", "toy", "sport", "graspable"];
const BRIGHT: &[[f32; 4]] = &[
    [0.8, 0.15, 0.12, 1.0],
    [0.15, 0.35, 0.75, 1.0],
    [0.95, 0.75, 0.1, 1.0],
    [0.2, 0.6, 0.3, 1.0],
    [0.55, 0.25, 0.6, 1.0],
];

// --- condiments and food packs -------------------------------------------------------

pub(crate) const SALT_SHAKER: Category = def(
    "salt_shaker",
    "salt shaker",
    &[
        "pepper shaker",
        "salt cellar",
        "salt and pepper shaker",
        "pepper pot",
        "salt pot",
        "cruet",
        "salt",
        "saltshaker",
        "shaker",
    ],
    ROUND_CONDIMENT,
    "a small glass salt or pepper shaker with a perforated metal cap",
    &["condiment", "shaker", "tableware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Glass shakers: 4–5 cm across, 8–11 cm tall.
    &sized(0.045, 0.045, 0.095),
    build_salt_shaker,
);

fn build_salt_shaker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let glass = b.material("glass", pick(rng, &[[0.85, 0.88, 0.9, 1.0], [0.95, 0.95, 0.93, 1.0]]), true);
    let cap = b.material("cap", pick(rng, STEEL), false);
    turn(b, s, [0.0, 0.78], &[[0.0, 0.0], [0.92, 0.0], [1.0, 0.1], [1.0, 0.9], [0.85, 1.0], [0.0, 1.0]], glass);
    turn(b, s, [0.77, 1.0], &DOME, cap);
    hull(b, s.0, s.1, s.2);
    0.12
}

pub(crate) const PEPPER_MILL: Category = def(
    "pepper_mill",
    "pepper mill",
    &["pepper grinder", "salt mill", "salt grinder", "spice grinder", "peppermill"],
    ROUND_CONDIMENT,
    "a tall wooden pepper mill with a knob on top",
    &["grinder", "mill", "condiment", "tableware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Peugeot / Cole & Mason mills: 5–6.5 cm across, 18–24 cm tall.
    &sized(0.058, 0.058, 0.21),
    build_pepper_mill,
);

fn build_pepper_mill(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let wood = b.material("wood", pick(rng, WOOD), true);
    let knob = b.material("knob", pick(rng, STEEL), false);
    let profile = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.3], [0.7, 0.5], [0.85, 0.8], [0.9, 1.0], [0.0, 1.0]];
    turn(b, s, [0.0, 0.93], &profile, wood);
    turn(b, s, [0.92, 1.0], &[[0.0, 0.0], [0.3, 0.0], [0.3, 1.0], [0.0, 1.0]], knob);
    hull(b, s.0, s.1, s.2);
    0.3
}

pub(crate) const CONDIMENT_BOTTLE: Category = def(
    "condiment_bottle",
    "condiment bottle",
    &[
        "ketchup",
        "ketchup bottle",
        "catsup",
        "catsup bottle",
        "mustard",
        "mustard bottle",
        "tomato sauce",
        "sauce bottle",
        "hot sauce",
        "brown sauce",
        "bbq sauce",
        "barbecue sauce",
        "mayonnaise",
        "mayo",
        "salad dressing",
        "soy sauce",
        "tabasco",
        "tabasco sauce",
    ],
    CONDIMENT,
    "an upside-down squeeze bottle of ketchup, mustard or sauce with a flip cap",
    &["bottle", "condiment", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Heinz 460 g top-down ketchup: 7 × 5 × 19–20 cm.
    &sized(0.07, 0.05, 0.195),
    build_condiment_bottle,
);

fn build_condiment_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let sauce = b.material(
        "sauce",
        pick(rng, &[[0.72, 0.08, 0.06, 1.0], [0.9, 0.72, 0.1, 1.0], [0.45, 0.2, 0.08, 1.0], [0.95, 0.93, 0.85, 1.0]]),
        true,
    );
    let cap = b.material("cap", pick(rng, &[[0.95, 0.95, 0.95, 1.0], [0.1, 0.1, 0.1, 1.0]]), false);
    let label = b.material("label", LABEL_WHITE, false);
    part(b, s, [-0.5, -0.5, 0.16], [0.5, 0.5, 0.9], sauce);
    part(b, s, [-0.42, -0.42, 0.0], [0.42, 0.42, 0.17], cap);
    part(b, s, [-0.3, -0.3, 0.89], [0.3, 0.3, 1.0], sauce);
    part(b, s, [-0.35, -0.51, 0.35], [0.35, 0.51, 0.7], label);
    hull(b, s.0, s.1, s.2);
    0.5
}

/// A wrapped block of food: the pack and a band of its label.
fn food_pack(p: &Params, b: &mut AssetBuilder, pack: [f32; 4], band: [f32; 4], density: f64) -> f64 {
    let s = whd(p);
    let m = b.material("pack", pack, true);
    let l = b.material("band", band, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.2, -0.505, 0.1], [0.2, 0.505, 0.9], l);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, density)
}

pub(crate) const BUTTER: Category = def(
    "butter",
    "butter",
    &["block of butter", "stick of butter", "butter pack", "pack of butter", "margarine", "butter block"],
    CONDIMENT,
    "a wrapped 250 g block of butter",
    &["food", "dairy"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // A 250 g block: 12 × 6.5 × 3.5 cm (LIBERO's butter box is about this).
    &sized(0.12, 0.065, 0.035),
    build_butter,
);

fn build_butter(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let foil = pick(rng, &[[0.95, 0.88, 0.45, 1.0], [0.85, 0.85, 0.88, 1.0]]);
    food_pack(p, b, foil, [0.15, 0.35, 0.7, 1.0], 950.0)
}

pub(crate) const CREAM_CHEESE: Category = def(
    "cream_cheese",
    "cream cheese",
    &["cream cheese box", "soft cheese", "philadelphia", "box of cream cheese", "tub of cream cheese"],
    CONDIMENT,
    "a small foil-wrapped pack of cream cheese in a printed box",
    &["food", "dairy", "cheese"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // 226 g (8 oz) bricks in their box: 11 × 6 × 4 cm.
    &sized(0.11, 0.06, 0.04),
    build_cream_cheese,
);

fn build_cream_cheese(p: &Params, _rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    food_pack(p, b, [0.85, 0.88, 0.92, 1.0], [0.1, 0.3, 0.65, 1.0], 800.0)
}

pub(crate) const CHEESE: Category = def(
    "cheese",
    "cheese",
    &["block of cheese", "cheese block", "wedge of cheese", "cheddar", "cheese wedge", "piece of cheese"],
    &["kitchen", "food", "tabletop", "small", "graspable"],
    "a block of yellow hard cheese",
    &["food", "dairy"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Supermarket blocks of 200–400 g: 9–12 × 5–7 × 3–5 cm.
    &sized(0.1, 0.06, 0.04),
    build_cheese,
);

fn build_cheese(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let c = pick(rng, &[[0.98, 0.8, 0.3, 1.0], [0.95, 0.88, 0.55, 1.0], [0.96, 0.6, 0.2, 1.0]]);
    food_pack(p, b, c, shade(c, 0.9), 1100.0)
}

pub(crate) const FOOD_TIN: Category = def(
    "food_tin",
    "food tin",
    &[
        "food can",
        "soup can",
        "tin of beans",
        "can of beans",
        "can of soup",
        "tin of soup",
        "tuna can",
        "tin of tuna",
        "canned food",
        "alphabet soup",
        "baked beans",
        "tin of tomatoes",
        "can of tomatoes",
        "canned soup",
        "canned goods",
    ],
    &["kitchen", "food", "retail", "tabletop", "small", "graspable", "round"],
    "a steel tin of food with a paper label round it",
    &["can", "tin", "food", "container"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // 400 g tins: 7.3–7.5 cm across, 10.5–11 cm tall (YCB tomato soup can 6.8 × 10.2).
    &sized(0.074, 0.074, 0.11),
    build_food_tin,
);

fn build_food_tin(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let label = b.material("label", pick(rng, BRIGHT), true);
    let steel = b.material("steel", [0.75, 0.76, 0.78, 1.0], false);
    turn(b, s, [0.0, 0.06], &CAN, steel);
    turn(b, s, [0.05, 0.95], &[[0.0, 0.0], [0.99, 0.0], [0.99, 1.0], [0.0, 1.0]], label);
    turn(b, s, [0.94, 1.0], &CAN, steel);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 800.0)
}

pub(crate) const JUICE_BOX: Category = def(
    "juice_box",
    "juice box",
    &["boxed drink", "drink carton", "carton drink", "capri sun", "kids juice box", "small carton"],
    &["kitchen", "food", "retail", "tabletop", "small", "graspable"],
    "a small 200 ml drink carton with a straw on its side",
    &["carton", "drink", "package", "container"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // 200 ml Tetra Brik: 6.3 × 3.9 × 10.5 cm.
    &sized(0.063, 0.039, 0.105),
    build_juice_box,
);

fn build_juice_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("carton", pick(rng, BRIGHT), true);
    let straw = b.material("straw", LABEL_WHITE, false);
    part(b, s, [-0.5, -0.45, 0.0], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.06, -0.5, 0.2], [0.06, -0.45, 0.95], straw);
    hull(b, s.0, s.1, s.2);
    0.22
}

pub(crate) const EGG_CARTON: Category = def(
    "egg_carton",
    "egg carton",
    &["egg box", "box of eggs", "carton of eggs", "egg tray", "half dozen eggs", "dozen eggs"],
    &["kitchen", "food", "retail", "tabletop", "small", "graspable"],
    "a closed moulded-pulp carton of six eggs",
    &["carton", "box", "package", "container"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Six-egg cartons: 15–16 × 10–11 × 7 cm; twelve: 30 × 11 × 7 cm.
    &size3(0.3, 0.11, 0.07, 0.45, 1.2, 0.03),
    build_egg_carton,
);

fn build_egg_carton(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let pulp = b.material("pulp", pick(rng, &[[0.78, 0.74, 0.66, 1.0], [0.7, 0.62, 0.5, 1.0]]), true);
    let lid = b.material("lid", [0.84, 0.8, 0.72, 1.0], false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.55], pulp);
    part(b, s, [-0.48, -0.45, 0.55], [0.48, 0.45, 1.0], lid);
    hull(b, s.0, s.1, s.2);
    0.45
}

// --- kitchen gadgets -----------------------------------------------------------------

/// A gadget lying along X: a handle (−X) and a working head (+X), each a rounded bar.
fn gadget(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, handle_frac: f64, head: [f32; 4]) -> f64 {
    let s = whd(p);
    let grip =
        b.material("handle", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.75, 0.1, 0.1, 1.0], [0.2, 0.45, 0.3, 1.0]]), true);
    let steel = b.material("head", head, false);
    let split = -0.5 + handle_frac;
    part(b, s, [-0.5, -0.22, 0.0], [split, 0.22, 0.7], grip);
    part(b, s, [split - 0.01, -0.5, 0.0], [0.5, 0.5, 1.0], steel);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 900.0).min(0.4)
}

pub(crate) const CAN_OPENER: Category = def(
    "can_opener",
    "can opener",
    &["tin opener", "canopener", "can-opener", "manual can opener"],
    GADGET,
    "a hand-held can opener with two handles and a cutting wheel",
    &["opener", "kitchen utensil", "utensil", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // OXO / Zyliss openers: 19–21 × 5–7 × 3.5–4.5 cm.
    &sized(0.2, 0.06, 0.04),
    build_can_opener,
);

fn build_can_opener(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    gadget(p, rng, b, 0.72, [0.7, 0.72, 0.75, 1.0])
}

pub(crate) const BOTTLE_OPENER: Category = def(
    "bottle_opener",
    "bottle opener",
    &["beer opener", "church key", "bottle-opener"],
    GADGET,
    "a flat steel bottle opener with a hooked head",
    &["opener", "kitchen utensil", "utensil"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Flat bar openers: 11–18 × 3.5–4.5 cm, 2–12 mm thick.
    &size3(0.12, 0.04, 0.012, 0.7, 1.5, 0.05),
    build_bottle_opener,
);

fn build_bottle_opener(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    gadget(p, rng, b, 0.6, [0.72, 0.74, 0.77, 1.0])
}

pub(crate) const CORKSCREW: Category = def(
    "corkscrew",
    "corkscrew",
    &["wine opener", "waiter's friend", "wine key", "cork screw"],
    GADGET,
    "a waiter's friend corkscrew folded shut",
    &["opener", "kitchen utensil", "utensil"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Waiter's friends: 11–13 × 2–3 × 1.5–3 cm folded.
    &sized(0.12, 0.028, 0.025),
    build_corkscrew,
);

fn build_corkscrew(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    gadget(p, rng, b, 0.8, [0.6, 0.62, 0.66, 1.0])
}

pub(crate) const VEGETABLE_PEELER: Category = def(
    "vegetable_peeler",
    "vegetable peeler",
    &["peeler", "potato peeler", "y-peeler", "swivel peeler", "speed peeler"],
    GADGET,
    "a swivel-blade vegetable peeler with a plastic handle",
    &["kitchen utensil", "utensil", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Straight swivel peelers: 17–19 × 3–6 × 1.5–2.5 cm.
    &sized(0.18, 0.045, 0.02),
    build_vegetable_peeler,
);

fn build_vegetable_peeler(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    gadget(p, rng, b, 0.65, [0.78, 0.8, 0.82, 1.0])
}

pub(crate) const POTATO_MASHER: Category = def(
    "potato_masher",
    "potato masher",
    &["masher", "ricer", "potato ricer"],
    GADGET,
    "a potato masher: a long handle and a flat wavy steel head",
    &["kitchen utensil", "utensil"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 25–28 cm long, heads 8–10 cm across, lying 5–7 cm high.
    &sized(0.26, 0.09, 0.06),
    build_potato_masher,
);

fn build_potato_masher(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    gadget(p, rng, b, 0.6, [0.74, 0.76, 0.8, 1.0])
}

pub(crate) const FUNNEL: Category = def(
    "funnel",
    "funnel",
    &["kitchen funnel", "filling funnel", "oil funnel"],
    &["kitchen", "utensil", "tabletop", "small", "graspable", "round"],
    "a plastic funnel standing on its spout, wide cone on top",
    &["kitchen utensil", "utensil"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 12 cm kitchen funnels: 12 cm across, 12–15 cm tall.
    &sized(0.12, 0.12, 0.14),
    build_funnel,
);

fn build_funnel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("plastic", pick(rng, PLASTIC), true);
    turn(b, s, [0.0, 1.0], &[[0.0, 0.0], [0.18, 0.0], [0.18, 0.45], [1.0, 0.95], [1.0, 1.0], [0.0, 1.0]], m);
    hull(b, s.0, s.1, s.2);
    0.06
}

pub(crate) const WAFFLE_IRON: Category = def(
    "waffle_iron",
    "waffle iron",
    &["waffle maker", "sandwich toaster", "panini press", "sandwich maker", "toastie maker", "panini grill"],
    &["kitchen", "appliance", "tabletop", "small"],
    "an electric waffle iron: two hinged hot plates in a clamshell with a handle",
    &["kitchen appliance", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Tefal / Breville waffle makers: 26–30 × 22–26 × 10–13 cm.
    &sized(0.28, 0.24, 0.115),
    build_waffle_iron,
);

fn build_waffle_iron(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body = b.material("body", pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.75, 0.76, 0.78, 1.0]]), true);
    let handle = b.material("handle", INK, false);
    part(b, s, [-0.42, -0.5, 0.0], [0.5, 0.5, 0.5], body);
    part(b, s, [-0.42, -0.48, 0.52], [0.5, 0.48, 0.95], body);
    part(b, s, [-0.5, -0.12, 0.45], [-0.42, 0.12, 1.0], handle);
    hull(b, s.0, s.1, s.2);
    2.4
}

pub(crate) const WATERING_CAN: Category = def(
    "watering_can",
    "watering can",
    &["watering pot", "garden watering can", "plant watering can", "sprinkling can"],
    &["garden", "home", "container", "graspable"],
    "a watering can: a tank with a handle over the top and a long spout with a rose",
    &["can", "container", "garden tool"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // 5–10 l cans: 40–55 cm with the spout, 15–20 cm wide, 28–35 cm tall.
    &sized(0.45, 0.17, 0.3),
    build_watering_can,
);

fn build_watering_can(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("body", pick(rng, &[[0.15, 0.5, 0.25, 1.0], [0.2, 0.35, 0.7, 1.0], [0.6, 0.62, 0.6, 1.0]]), true);
    let rose = b.material("rose", shade(pick(rng, STEEL), 0.9), false);
    part(b, s, [-0.5, -0.5, 0.0], [0.05, 0.5, 0.7], m);
    part(b, s, [-0.45, -0.08, 0.7], [0.0, 0.08, 0.98], m);
    // The spout rising towards +X, then its rose.
    part(b, s, [0.05, -0.08, 0.2], [0.35, 0.08, 0.38], m);
    part(b, s, [0.3, -0.08, 0.35], [0.42, 0.08, 0.75], m);
    part(b, s, [0.4, -0.2, 0.7], [0.5, 0.2, 0.9], rose);
    hull(b, s.0, s.1, s.2);
    0.6
}

pub(crate) const BREAD_BIN: Category = def(
    "bread_bin",
    "bread bin",
    &["bread box", "breadbin", "breadbox", "bread crock"],
    &["kitchen", "container", "tabletop"],
    "a countertop bread bin with a roll-top front",
    &["bin", "box", "kitchen storage", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Brabantia / Typhoon bread bins: 38–45 × 23–28 × 18–22 cm.
    &sized(0.4, 0.25, 0.2),
    build_bread_bin,
);

fn build_bread_bin(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("body", pick(rng, &[[0.85, 0.84, 0.8, 1.0], [0.2, 0.22, 0.25, 1.0], [0.55, 0.12, 0.1, 1.0]]), true);
    let front = b.material("roll_top", shade(pick(rng, STEEL), 1.1), false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.75], m);
    part(b, s, [-0.5, -0.5, 0.75], [0.5, 0.2, 1.0], m);
    part(b, s, [-0.48, 0.18, 0.7], [0.48, 0.5, 0.97], front);
    hull(b, s.0, s.1, s.2);
    1.6
}

// --- home ----------------------------------------------------------------------------

pub(crate) const TYPEWRITER: Category = def(
    "typewriter",
    "typewriter",
    &["manual typewriter", "electric typewriter", "portable typewriter", "type writer"],
    &["office", "home", "tabletop", "vintage"],
    "a typewriter: a keyboard in steps, a paper carriage and a platen roller across the back",
    &["office machine", "machine"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Olivetti Lettera / Olympia portables: 30–45 × 30–38 × 10–16 cm.
    &sized(0.42, 0.35, 0.14),
    build_typewriter,
);

fn build_typewriter(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.15, 0.2, 0.18, 1.0], [0.6, 0.12, 0.1, 1.0], [0.75, 0.72, 0.62, 1.0]]), true);
    let keys = b.material("keys", INK, false);
    let roller = b.material("platen", DARK[0], false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.35], body);
    part(b, s, [-0.45, -0.5, 0.35], [0.45, 0.1, 0.7], body);
    // Keys in three steps rising towards the back; the platen across the back.
    for (k, y) in [0.33, 0.21, 0.09].into_iter().enumerate() {
        let z = 0.38 + 0.07 * k as f64;
        part(b, s, [-0.38, y, 0.3], [0.38, y + 0.09, z], keys);
    }
    bar_x(b, s, [-0.5, 0.5], [-0.25, 0.82], 0.15, roller);
    hull(b, s.0, s.1, s.2);
    5.5
}

pub(crate) const ROPE: Category = def(
    "rope",
    "rope",
    &["coil of rope", "rope coil", "length of rope", "climbing rope", "mooring rope", "hank of rope"],
    &["home", "garage", "outdoor", "graspable", "deformable", "round"],
    "a coil of rope lying flat",
    &["line", "cordage"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // A 10–20 m coil of 10 mm rope: 30–40 cm across, 5–8 cm high.
    &size3(0.34, 0.34, 0.06, 0.5, 1.6, 0.05),
    build_rope,
);

fn build_rope(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("rope", pick(rng, &[[0.78, 0.66, 0.45, 1.0], [0.15, 0.3, 0.6, 1.0], [0.85, 0.3, 0.1, 1.0]]), true);
    // The coil, and its hollow middle seen from above.
    turn(b, s, [0.0, 1.0], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], m);
    let core = b.material("core", shade(pick(rng, WOOD), 0.5), false);
    turn(b, (s.0 * 0.5, s.1 * 0.5, s.2), [0.0, 1.01], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], core);
    hull(b, s.0, s.1, s.2);
    (s.0 * s.1 * s.2 * 300.0).max(0.3)
}

pub(crate) const BATTERY_CELL: Category = def(
    "battery_cell",
    "battery cell",
    &["aa battery", "aaa battery", "9v battery", "d battery", "c battery", "dry cell", "18650 cell", "lithium cell"],
    &["electrical", "home", "tabletop", "small", "graspable", "round"],
    "a cylindrical AA battery cell standing on its end",
    &["battery", "power source"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // AA: 14.5 mm across, 50.5 mm tall; 18650: 18 × 65 mm.
    &size3(0.0145, 0.0145, 0.05, 0.7, 2.0, 0.02),
    build_battery_cell,
);

fn build_battery_cell(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let wrap =
        b.material("wrap", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.85, 0.5, 0.1, 1.0], [0.15, 0.35, 0.75, 1.0]]), true);
    let cap = b.material("terminal", [0.75, 0.76, 0.78, 1.0], false);
    turn(b, s, [0.0, 0.94], &CAN, wrap);
    turn(b, (s.0 * 0.4, s.1 * 0.4, s.2), [0.93, 1.0], &CAN, cap);
    hull(b, s.0, s.1, s.2);
    0.023
}

pub(crate) const HEADPHONES: Category = def(
    "headphones",
    "headphones",
    &["headset", "over-ear headphones", "pair of headphones", "earphones", "gaming headset"],
    HOME,
    "a pair of over-ear headphones standing on their ear cups",
    &["electronics", "audio device"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Sony / Bose over-ears: 16–19 wide across the cups, 7–9 deep, 18–21 cm tall.
    &sized(0.18, 0.08, 0.19),
    build_headphones,
);

fn build_headphones(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("body", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.85, 0.84, 0.8, 1.0], [0.2, 0.25, 0.4, 1.0]]), true);
    let pad = b.material("pads", INK, false);
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 { (-0.5, -0.28) } else { (0.28, 0.5) };
        part(b, s, [x0, -0.5, 0.0], [x1, 0.5, 0.5], pad);
        part(b, s, [x0 + 0.05, -0.1, 0.5], [x1 - 0.05, 0.1, 0.88], m);
    }
    part(b, s, [-0.45, -0.15, 0.86], [0.45, 0.15, 1.0], m);
    hull(b, s.0, s.1, s.2);
    0.25
}

pub(crate) const SPECTACLES: Category = def(
    "spectacles",
    "spectacles",
    &["eyeglasses", "reading glasses", "sunglasses", "specs", "pair of glasses", "pair of spectacles"],
    HOME,
    "a pair of spectacles with folded arms lying on the table",
    &["eyewear", "accessory"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Adult frames: 13–14.5 cm across, arms 14–15 cm; folded about 14 × 5 × 4 cm; open 14 × 15 × 4.
    &sized(0.14, 0.15, 0.04),
    build_spectacles,
);

fn build_spectacles(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let frame =
        b.material("frame", pick(rng, &[[0.08, 0.08, 0.08, 1.0], [0.45, 0.28, 0.15, 1.0], [0.7, 0.6, 0.3, 1.0]]), true);
    let lens = b.material("lenses", GLASS, false);
    part(b, s, [-0.48, -0.5, 0.05], [-0.04, -0.4, 1.0], lens);
    part(b, s, [0.04, -0.5, 0.05], [0.48, -0.4, 1.0], lens);
    part(b, s, [-0.5, -0.5, 0.85], [0.5, -0.38, 1.0], frame);
    for x in [-0.5, 0.45] {
        part(b, s, [x, -0.45, 0.0], [x + 0.05, 0.5, 0.2], frame);
    }
    hull(b, s.0, s.1, s.2);
    0.03
}

pub(crate) const LANTERN: Category = def(
    "lantern",
    "lantern",
    &["camping lantern", "hurricane lamp", "oil lamp", "storm lantern", "hurricane lantern", "paraffin lamp"],
    &["home", "outdoor", "lighting", "tabletop", "graspable", "round"],
    "a lantern: a glass chimney in a metal frame with a ring handle on top",
    &["lamp", "light"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Feuerhand 276 hurricane lantern: 15 cm across, 26 cm tall (29 with its handle up).
    &sized(0.15, 0.15, 0.27),
    build_lantern,
);

fn build_lantern(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let metal =
        b.material("metal", pick(rng, &[[0.7, 0.15, 0.12, 1.0], [0.15, 0.3, 0.2, 1.0], [0.6, 0.62, 0.64, 1.0]]), true);
    let glass = b.material("chimney", [0.95, 0.85, 0.55, 1.0], false);
    turn(b, s, [0.0, 0.22], &CAN, metal);
    turn(b, s, [0.21, 0.7], &[[0.0, 0.0], [0.6, 0.0], [0.75, 0.5], [0.6, 1.0], [0.0, 1.0]], glass);
    turn(b, s, [0.69, 0.82], &DOME, metal);
    part(b, s, [-0.3, -0.03, 0.82], [0.3, 0.03, 1.0], metal);
    hull(b, s.0, s.1, s.2);
    0.8
}

/// A box-shaped device: the case, a panel on its front (+Y) and a strip of controls.
fn device(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, case: &[[f32; 4]], panel: [f32; 4], density: f64) -> f64 {
    let s = whd(p);
    let m = b.material("case", pick(rng, case), true);
    let f = b.material("panel", panel, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.42, 0.49, 0.15], [0.2, 0.505, 0.85], f);
    part(b, s, [0.26, 0.49, 0.3], [0.44, 0.505, 0.7], f);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, density)
}

pub(crate) const RADIO: Category = def(
    "radio",
    "radio",
    &["dab radio", "transistor radio", "portable radio", "clock radio", "kitchen radio", "radio receiver", "radio set"],
    &["home", "electronics", "tabletop", "small", "graspable"],
    "a portable radio with a speaker grille and a tuning dial on the front",
    &["electronics", "audio device"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Roberts / Pure DAB radios: 22–28 × 9–12 × 13–16 cm.
    &sized(0.25, 0.1, 0.15),
    build_radio,
);

fn build_radio(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    device(p, rng, b, &[[0.55, 0.12, 0.1, 1.0], [0.85, 0.8, 0.7, 1.0], [0.15, 0.15, 0.16, 1.0]], INK, 450.0)
}

pub(crate) const WIFI_ROUTER: Category = def(
    "wifi_router",
    "wifi router",
    &["router", "wireless router", "broadband router", "modem", "internet router", "wi-fi router"],
    &["home", "office", "electronics", "tabletop", "small", "graspable"],
    "a flat wifi router with status lights along its front",
    &["electronics", "network device"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Home routers: 19–25 × 12–18 × 3–5 cm lying flat.
    &sized(0.22, 0.15, 0.04),
    build_wifi_router,
);

fn build_wifi_router(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    device(p, rng, b, &[[0.1, 0.1, 0.11, 1.0], [0.93, 0.93, 0.92, 1.0]], [0.1, 0.7, 0.9, 1.0], 400.0)
}

pub(crate) const GAMES_CONSOLE: Category = def(
    "games_console",
    "games console",
    &["game console", "video game console", "xbox", "playstation", "ps5", "ps4", "nintendo switch"],
    &["home", "electronics", "tabletop", "small"],
    "a games console lying flat under a television",
    &["electronics", "computer"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Xbox Series S / X, PS5 lying: 27–39 × 15–26 × 6.5–15 cm.
    &sized(0.3, 0.19, 0.1),
    build_games_console,
);

fn build_games_console(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    device(p, rng, b, &[[0.08, 0.08, 0.09, 1.0], [0.94, 0.94, 0.94, 1.0]], [0.25, 0.25, 0.28, 1.0], 400.0)
}

pub(crate) const GAME_CONTROLLER: Category = def(
    "game_controller",
    "game controller",
    &["gamepad", "joypad", "joystick", "games controller", "xbox controller", "ps5 controller"],
    HOME,
    "a two-handed game controller with thumbsticks and buttons",
    &["electronics", "input device"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // DualSense / Xbox pads: 15–16 × 10–11 × 5–6 cm.
    &sized(0.155, 0.105, 0.06),
    build_game_controller,
);

fn build_game_controller(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("shell", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.93, 0.93, 0.93, 1.0]]), true);
    let k = b.material("buttons", INK, false);
    part(b, s, [-0.5, -0.1, 0.0], [-0.2, 0.5, 0.7], m);
    part(b, s, [0.2, -0.1, 0.0], [0.5, 0.5, 0.7], m);
    part(b, s, [-0.3, -0.5, 0.2], [0.3, 0.3, 0.75], m);
    part(b, s, [-0.25, -0.2, 0.75], [-0.1, -0.05, 1.0], k);
    part(b, s, [0.1, -0.2, 0.75], [0.25, -0.05, 1.0], k);
    hull(b, s.0, s.1, s.2);
    0.28
}

pub(crate) const TABLET_COMPUTER: Category = def(
    "tablet_computer",
    "tablet computer",
    &["tablet", "ipad", "e-reader", "kindle", "android tablet", "tablet pc"],
    HOME,
    "a flat tablet computer lying screen up",
    &["electronics", "computer"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // iPad 10.9": 24.8 × 17.9 × 0.7 cm.
    &size3(0.248, 0.179, 0.007, 0.6, 1.3, 0.03),
    build_tablet_computer,
);

fn build_tablet_computer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("case", pick(rng, &[[0.55, 0.57, 0.6, 1.0], [0.2, 0.2, 0.22, 1.0], [0.85, 0.78, 0.7, 1.0]]), true);
    let screen = b.material("screen", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.95], m);
    part(b, s, [-0.46, -0.45, 0.9], [0.46, 0.45, 1.0], screen);
    hull(b, s.0, s.1, s.2);
    0.48
}

// --- music, sport and toys ------------------------------------------------------------

pub(crate) const GUITAR: Category = def(
    "guitar",
    "guitar",
    &["acoustic guitar", "electric guitar", "bass guitar", "classical guitar", "ukulele"],
    &["home", "music", "instrument", "graspable"],
    "a guitar lying on its back: a waisted body, a long neck and a headstock",
    &["musical instrument", "instrument"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Dreadnought acoustics: 100–105 cm long, 38–40 cm across, 10–12 cm deep.
    &sized(1.02, 0.38, 0.12),
    build_guitar,
);

fn build_guitar(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("body", pick(rng, &[[0.8, 0.55, 0.3, 1.0], [0.5, 0.2, 0.1, 1.0], [0.1, 0.1, 0.1, 1.0]]), true);
    let neck = b.material("neck", [0.35, 0.2, 0.1, 1.0], false);
    let hole = b.material("soundhole", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [-0.22, 0.5, 1.0], m);
    part(b, s, [-0.24, -0.38, 0.0], [0.0, 0.38, 1.0], m);
    part(b, s, [-0.05, -0.1, 1.0], [0.02, 0.1, 1.02], hole);
    part(b, s, [0.0, -0.08, 0.4], [0.42, 0.08, 0.75], neck);
    part(b, s, [0.42, -0.13, 0.35], [0.5, 0.13, 0.8], neck);
    hull(b, s.0, s.1, s.2);
    2.3
}

pub(crate) const PIANO: Category = def(
    "piano",
    "piano",
    &["upright piano", "digital piano", "stage piano", "pianoforte", "electric piano"],
    &["home", "music", "instrument", "furniture", "heavy"],
    "an upright piano with its keyboard lid closed and a music desk",
    &["musical instrument", "instrument", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // Yamaha b1 / U1: 150–153 × 54–61 × 109–121 cm.
    &size3(1.5, 0.6, 1.2, 0.75, 1.15, 0.03),
    build_piano,
);

fn build_piano(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("case", pick(rng, &[[0.06, 0.05, 0.05, 1.0], [0.35, 0.18, 0.1, 1.0], [0.92, 0.9, 0.86, 1.0]]), true);
    let keys = b.material("keys", LABEL_WHITE, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.0, 1.0], m);
    part(b, s, [-0.5, 0.0, 0.55], [0.5, 0.5, 0.66], m);
    part(b, s, [-0.46, 0.1, 0.66], [0.46, 0.48, 0.68], keys);
    for x in [-0.48, 0.44] {
        part(b, s, [x, 0.0, 0.0], [x + 0.04, 0.45, 0.55], m);
    }
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const DRUM_KIT: Category = def(
    "drum_kit",
    "drum kit",
    &["drum set", "drums", "drumkit", "drum-kit", "trap set"],
    &["home", "music", "instrument", "floor"],
    "a drum kit: a bass drum, toms, a snare, cymbals on stands and a stool",
    &["musical instrument", "instrument"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // A five-piece kit set up: 1.4–1.7 × 1.1–1.4 m, cymbals up to 1.2 m.
    &size3(1.5, 1.2, 1.15, 0.7, 1.3, 0.04),
    build_drum_kit,
);

fn build_drum_kit(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let shell =
        b.material("shells", pick(rng, &[[0.7, 0.1, 0.1, 1.0], [0.1, 0.1, 0.12, 1.0], [0.2, 0.3, 0.6, 1.0]]), true);
    let brass = b.material("cymbals", [0.85, 0.68, 0.3, 1.0], false);
    let head = b.material("heads", LABEL_WHITE, false);
    let stand = b.material("stands", pick(rng, STEEL), false);
    // Bass drum lying on its side at the front, toms on it, a snare and a floor tom.
    part(b, s, [-0.15, 0.1, 0.0], [0.15, 0.5, 0.48], shell);
    part(b, s, [-0.16, 0.49, 0.05], [0.16, 0.5, 0.43], head);
    part(b, s, [-0.35, -0.15, 0.0], [-0.1, 0.15, 0.5], shell);
    part(b, s, [0.12, -0.15, 0.0], [0.4, 0.15, 0.45], shell);
    part(b, s, [-0.15, -0.5, 0.0], [0.15, -0.3, 0.4], stand);
    for x in [-0.45, 0.4] {
        part(b, s, [x, -0.05, 0.0], [x + 0.02, -0.03, 0.95], stand);
        part(b, s, [x - 0.05, -0.15, 0.95], [x + 0.08, 0.05, 0.97], brass);
    }
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const MUSIC_STAND: Category = def(
    "music_stand",
    "music stand",
    &["sheet music stand", "orchestral stand", "note stand", "folding music stand"],
    &["music", "school", "furniture", "tall"],
    "a music stand: a tilted desk on a pole over a tripod base",
    &["stand", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Orchestral stands: desk 48–52 × 33 cm, base about 50 cm across, 70–150 cm tall.
    &size3(0.5, 0.45, 1.2, 0.8, 1.3, 0.04),
    build_music_stand,
);

fn build_music_stand(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("frame", pick(rng, &[[0.08, 0.08, 0.08, 1.0], [0.6, 0.62, 0.64, 1.0]]), true);
    for (x0, y0) in [(-0.5, -0.5), (0.44, -0.5), (-0.03, 0.44)] {
        part(b, s, [x0, y0, 0.0], [x0 + 0.06, y0 + 0.06, 0.05], m);
    }
    part(b, s, [-0.02, -0.02, 0.0], [0.02, 0.02, 0.75], m);
    part(b, s, [-0.5, -0.1, 0.72], [0.5, 0.1, 1.0], m);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const DUMBBELL: Category = def(
    "dumbbell",
    "dumbbell",
    &["hand weight", "free weight", "dumb-bell"],
    LEISURE,
    "a dumbbell: a knurled bar with a round weight at each end",
    &["weight", "exercise equipment"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Hex / round 5–10 kg dumbbells: 28–33 cm long, plates 10–13 cm across.
    &sized(0.3, 0.11, 0.11),
    build_dumbbell,
);

fn build_dumbbell(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let plate =
        b.material("plates", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.2, 0.35, 0.7, 1.0], [0.7, 0.15, 0.15, 1.0]]), true);
    let bar = b.material("bar", [0.7, 0.72, 0.75, 1.0], false);
    bar_x(b, s, [-0.5, -0.25], [0.0, 0.5], 0.5, plate);
    bar_x(b, s, [0.25, 0.5], [0.0, 0.5], 0.5, plate);
    bar_x(b, s, [-0.26, 0.26], [0.0, 0.5], 0.15, bar);
    hull(b, s.0, s.1, s.2);
    7.5
}

pub(crate) const SKATEBOARD: Category = def(
    "skateboard",
    "skateboard",
    &["skate board", "longboard", "penny board", "cruiser board"],
    LEISURE,
    "a skateboard: a deck on two trucks with four small wheels",
    &["board", "toy", "sports equipment"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Street decks: 78–83 × 19–21 cm, 10–12 cm high on wheels.
    &sized(0.8, 0.2, 0.11),
    build_skateboard,
);

fn build_skateboard(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let deck = b.material("deck", pick(rng, BRIGHT), true);
    let wheel = b.material("wheels", [0.95, 0.92, 0.8, 1.0], false);
    let truck = b.material("trucks", [0.7, 0.72, 0.75, 1.0], false);
    part(b, s, [-0.5, -0.5, 0.8], [0.5, 0.5, 1.0], deck);
    for x in [-0.35, 0.35] {
        part(b, s, [x - 0.03, -0.3, 0.45], [x + 0.03, 0.3, 0.8], truck);
        for y in [-0.5, 0.3] {
            part(b, s, [x - 0.035, y, 0.0], [x + 0.035, y + 0.2, 0.5], wheel);
        }
    }
    hull(b, s.0, s.1, s.2);
    2.0
}

/// A long thing for sport lying along X: a grip (−X) and a head (+X) of its own width.
fn bat(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, grip_frac: f64, head_width: f64, colours: &[[f32; 4]]) -> f64 {
    let s = whd(p);
    let head = b.material("head", pick(rng, colours), true);
    let grip = b.material("grip", INK, false);
    let split = -0.5 + grip_frac;
    part(b, s, [-0.5, -0.12, 0.1], [split, 0.12, 0.9], grip);
    part(b, s, [split - 0.01, -head_width / 2.0, 0.0], [0.5, head_width / 2.0, 1.0], head);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 300.0).clamp(0.2, 1.2)
}

pub(crate) const TENNIS_RACKET: Category = def(
    "tennis_racket",
    "tennis racket",
    &["racket", "racquet", "tennis racquet", "badminton racket", "squash racket", "badminton racquet"],
    LEISURE,
    "a tennis racket lying flat: a grip and an oval strung head",
    &["sports equipment", "bat"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Adult rackets: 68.5 cm long, heads 25–29 cm across, 2.5–3 cm thick.
    &sized(0.685, 0.27, 0.03),
    build_tennis_racket,
);

fn build_tennis_racket(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    bat(p, rng, b, 0.5, 1.0, BRIGHT)
}

pub(crate) const BASEBALL_BAT: Category = def(
    "baseball_bat",
    "baseball bat",
    &["bat", "softball bat", "cricket bat", "rounders bat", "wooden bat"],
    LEISURE,
    "a baseball bat lying on its side",
    &["sports equipment", "bat"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Adult bats: 81–86 cm long, barrel 6.4–7 cm across.
    &sized(0.84, 0.068, 0.068),
    build_baseball_bat,
);

fn build_baseball_bat(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    bat(p, rng, b, 0.35, 1.0, WOOD)
}

pub(crate) const ROCKING_HORSE: Category = def(
    "rocking_horse",
    "rocking horse",
    &["hobby horse", "rocking toy", "rocker horse"],
    &["toy", "home", "nursery", "floor"],
    "a wooden rocking horse on two curved rockers",
    &["toy", "ride-on toy"],
    Kind::Toy,
    PlacementKind::Floor,
    false,
    // Children's rocking horses: 80–110 × 30–40 × 60–80 cm.
    &size3(0.95, 0.35, 0.72, 0.6, 1.3, 0.05),
    build_rocking_horse,
);

fn build_rocking_horse(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("body", pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.55, 0.35, 0.2, 1.0], [0.2, 0.2, 0.2, 1.0]]), true);
    let rocker = b.material("rockers", pick(rng, WOOD), false);
    let mane = b.material("mane", [0.3, 0.2, 0.12, 1.0], false);
    for y in [-0.5, 0.38] {
        part(b, s, [-0.5, y, 0.0], [0.5, y + 0.12, 0.1], rocker);
    }
    for (x, y) in [(-0.32, -0.38), (0.26, -0.38), (-0.32, 0.25), (0.26, 0.25)] {
        part(b, s, [x, y, 0.08], [x + 0.06, y + 0.13, 0.5], m);
    }
    part(b, s, [-0.35, -0.38, 0.48], [0.35, 0.38, 0.72], m);
    part(b, s, [0.25, -0.18, 0.7], [0.42, 0.18, 1.0], m);
    part(b, s, [0.2, -0.05, 0.72], [0.28, 0.05, 0.98], mane);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const PIGGY_BANK: Category = def(
    "piggy_bank",
    "piggy bank",
    &["money box", "coin bank", "money bank", "savings pig"],
    &["home", "toy", "tabletop", "small", "graspable"],
    "a ceramic piggy bank with a coin slot on its back",
    &["toy", "container"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Ceramic piggy banks: 14–20 × 9–12 × 10–14 cm.
    &sized(0.16, 0.1, 0.12),
    build_piggy_bank,
);

fn build_piggy_bank(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("glaze", pick(rng, &[[0.95, 0.65, 0.7, 1.0], [0.9, 0.9, 0.88, 1.0], [0.5, 0.7, 0.9, 1.0]]), true);
    let slot = b.material("slot", INK, false);
    for (x, y) in [(-0.35, -0.4), (0.25, -0.4), (-0.35, 0.3), (0.25, 0.3)] {
        part(b, s, [x, y, 0.0], [x + 0.1, y + 0.1, 0.25], m);
    }
    part(b, s, [-0.42, -0.5, 0.2], [0.42, 0.5, 0.98], m);
    part(b, s, [0.42, -0.2, 0.4], [0.5, 0.2, 0.7], m);
    part(b, s, [-0.12, -0.03, 0.97], [0.12, 0.03, 1.0], slot);
    hull(b, s.0, s.1, s.2);
    0.45
}

// --- larger things of homes and gardens ----------------------------------------------

pub(crate) const TREADMILL: Category = def(
    "treadmill",
    "treadmill",
    &["running machine", "walking machine", "tread mill", "walking pad"],
    &["home", "gym", "exercise", "floor", "heavy"],
    "a treadmill: a belt deck with side rails and a console on two uprights",
    &["exercise machine", "exercise equipment", "machine"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Home treadmills: 170–200 × 75–90 × 130–145 cm.
    &size3(1.8, 0.8, 1.35, 0.7, 1.2, 0.03),
    build_treadmill,
);

fn build_treadmill(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let frame = b.material("frame", pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.6, 0.62, 0.64, 1.0]]), true);
    let belt = b.material("belt", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.4, 0.5, 0.14], frame);
    part(b, s, [-0.48, -0.35, 0.14], [0.38, 0.35, 0.16], belt);
    for y in [-0.5, 0.44] {
        part(b, s, [0.36, y, 0.0], [0.42, y + 0.06, 0.78], frame);
        part(b, s, [0.1, y, 0.7], [0.42, y + 0.06, 0.74], frame);
    }
    part(b, s, [0.36, -0.45, 0.78], [0.5, 0.45, 1.0], frame);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const EXERCISE_BIKE: Category = def(
    "exercise_bike",
    "exercise bike",
    &["stationary bike", "spin bike", "exercise bicycle", "exercise cycle", "indoor bike", "peloton"],
    &["home", "gym", "exercise", "floor", "heavy"],
    "an exercise bike: a flywheel frame with a saddle, handlebars and a console",
    &["exercise machine", "exercise equipment", "machine"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Spin bikes: 100–130 × 50–60 × 110–135 cm.
    &size3(1.1, 0.55, 1.25, 0.75, 1.2, 0.03),
    build_exercise_bike,
);

fn build_exercise_bike(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let frame = b.material(
        "frame",
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.75, 0.1, 0.1, 1.0], [0.85, 0.85, 0.85, 1.0]]),
        true,
    );
    let dark = b.material("saddle", INK, false);
    for x in [-0.5, 0.35] {
        part(b, s, [x, -0.5, 0.0], [x + 0.15, 0.5, 0.06], frame);
    }
    part(b, s, [-0.45, -0.05, 0.06], [0.4, 0.05, 0.14], frame);
    part(b, s, [0.1, -0.05, 0.14], [0.45, 0.05, 0.5], dark);
    part(b, s, [-0.3, -0.06, 0.06], [-0.2, 0.06, 0.75], frame);
    part(b, s, [-0.38, -0.15, 0.75], [-0.12, 0.15, 0.8], dark);
    part(b, s, [0.3, -0.06, 0.06], [0.38, 0.06, 0.9], frame);
    part(b, s, [0.3, -0.4, 0.88], [0.5, 0.4, 1.0], frame);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const BUNK_BED: Category = def(
    "bunk_bed",
    "bunk bed",
    &["bunk beds", "bunkbed", "double-decker bed", "loft bed", "cabin bed"],
    &["bedroom", "furniture", "home", "tall"],
    "a bunk bed: two single beds one above the other with a ladder at the end",
    &["bed", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Single bunk beds: 95–105 × 195–210 × 150–170 cm.
    &size3(1.0, 2.05, 1.6, 0.85, 1.15, 0.03),
    build_bunk_bed,
);

fn build_bunk_bed(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let frame = b.material("frame", pick(rng, WOOD), true);
    let mattress = b.material("mattress", pick(rng, UPHOLSTERY), false);
    for (x, y) in [(-0.5, -0.5), (0.45, -0.5), (-0.5, 0.47), (0.45, 0.47)] {
        part(b, s, [x, y, 0.0], [x + 0.05, y + 0.03, 1.0], frame);
    }
    for z in [0.12, 0.62] {
        part(b, s, [-0.47, -0.47, z], [0.47, 0.47, z + 0.05], frame);
        part(b, s, [-0.45, -0.45, z + 0.05], [0.45, 0.45, z + 0.14], mattress);
    }
    part(b, s, [-0.47, -0.47, 0.85], [0.47, -0.45, 0.95], frame);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const KENNEL: Category = def(
    "kennel",
    "kennel",
    &["dog kennel", "doghouse", "dog house", "dog kennel house", "pet house"],
    &["garden", "outdoor", "pet", "floor"],
    "a wooden dog kennel with a pitched roof and an arched door",
    &["pet house", "shelter"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Medium kennels: 80–100 × 60–80 × 65–85 cm.
    &size3(0.9, 0.7, 0.75, 0.6, 1.4, 0.04),
    build_kennel,
);

fn build_kennel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let wood = b.material("walls", pick(rng, WOOD), true);
    let roof =
        b.material("roof", pick(rng, &[[0.3, 0.3, 0.32, 1.0], [0.5, 0.15, 0.1, 1.0], [0.2, 0.35, 0.25, 1.0]]), false);
    let door = b.material("door", INK, false);
    part(b, s, [-0.47, -0.47, 0.0], [0.47, 0.47, 0.7], wood);
    part(b, s, [-0.5, -0.5, 0.7], [0.5, 0.5, 0.85], roof);
    part(b, s, [-0.35, -0.35, 0.85], [0.35, 0.35, 1.0], roof);
    part(b, s, [-0.2, 0.46, 0.0], [0.2, 0.48, 0.55], door);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const AQUARIUM: Category = def(
    "aquarium",
    "aquarium",
    &["fish tank", "fishtank", "goldfish bowl", "terrarium", "vivarium"],
    &["home", "pet", "tabletop", "glass"],
    "a glass aquarium with water, gravel and a lid",
    &["tank", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    false,
    // 54–60 l tanks: 60 × 30 × 35–40 cm.
    &size3(0.6, 0.3, 0.4, 0.5, 2.0, 0.04),
    build_aquarium,
);

fn build_aquarium(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let frame = b.material("frame", pick(rng, &[[0.08, 0.08, 0.08, 1.0], [0.85, 0.85, 0.85, 1.0]]), true);
    let water = b.material("water", [0.35, 0.6, 0.75, 1.0], false);
    let gravel = b.material("gravel", [0.7, 0.62, 0.48, 1.0], false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.05], frame);
    part(b, s, [-0.49, -0.49, 0.05], [0.49, 0.49, 0.15], gravel);
    part(b, s, [-0.49, -0.49, 0.15], [0.49, 0.49, 0.9], water);
    part(b, s, [-0.5, -0.5, 0.92], [0.5, 0.5, 1.0], frame);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const EASEL: Category = def(
    "easel",
    "easel",
    &["art easel", "painting easel", "studio easel", "display easel", "tripod easel"],
    &["home", "school", "art", "furniture", "tall"],
    "a wooden A-frame easel holding a canvas",
    &["stand", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Studio A-frame easels: 55–65 wide, 55–70 deep standing, 150–180 cm tall.
    &size3(0.6, 0.6, 1.65, 0.7, 1.3, 0.04),
    build_easel,
);

fn build_easel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let wood = b.material("wood", pick(rng, WOOD), true);
    let canvas = b.material("canvas", LABEL_WHITE, false);
    for x in [-0.5, 0.44] {
        part(b, s, [x, 0.14, 0.0], [x + 0.06, 0.2, 1.0], wood);
    }
    part(b, s, [-0.03, -0.5, 0.0], [0.03, -0.44, 0.9], wood);
    part(b, s, [-0.5, 0.2, 0.4], [0.5, 0.3, 0.44], wood);
    part(b, s, [-0.42, 0.26, 0.44], [0.42, 0.3, 0.85], canvas);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const PUSHCHAIR: Category = def(
    "pushchair",
    "pushchair",
    &["stroller", "buggy", "pram", "baby carriage", "baby buggy", "pushchair buggy", "perambulator"],
    &["home", "baby", "wheeled", "floor"],
    "a pushchair: a seat in a folding frame on four wheels with a handlebar",
    &["wheeled vehicle", "vehicle"],
    Kind::Vehicle,
    PlacementKind::Floor,
    false,
    // Bugaboo / Silver Cross pushchairs: 50–60 × 80–95 × 100–110 cm.
    &size3(0.55, 0.85, 1.05, 0.8, 1.2, 0.03),
    build_pushchair,
);

fn build_pushchair(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let fabric =
        b.material("fabric", pick(rng, &[[0.12, 0.12, 0.14, 1.0], [0.2, 0.3, 0.5, 1.0], [0.55, 0.55, 0.5, 1.0]]), true);
    let frame = b.material("frame", pick(rng, STEEL), false);
    let tyre = b.material("wheels", RUBBER[0], false);
    for (x, y) in [(-0.5, -0.5), (0.38, -0.5), (-0.5, 0.38), (0.38, 0.38)] {
        part(b, s, [x, y, 0.0], [x + 0.12, y + 0.12, 0.2], tyre);
    }
    part(b, s, [-0.45, -0.4, 0.2], [0.45, 0.4, 0.3], frame);
    part(b, s, [-0.4, -0.35, 0.3], [0.4, 0.2, 0.75], fabric);
    part(b, s, [-0.45, 0.3, 0.3], [-0.4, 0.5, 1.0], frame);
    part(b, s, [0.4, 0.3, 0.3], [0.45, 0.5, 1.0], frame);
    part(b, s, [-0.45, 0.44, 0.95], [0.45, 0.5, 1.0], frame);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const BARBECUE: Category = def(
    "barbecue",
    "barbecue",
    &["bbq", "barbeque", "charcoal grill", "gas grill", "gas barbecue", "kettle barbecue", "grill"],
    &["garden", "outdoor", "appliance", "floor"],
    "a gas barbecue: a lidded firebox on a cart with side shelves",
    &["outdoor appliance", "appliance", "cooker"],
    Kind::LargeAppliance,
    PlacementKind::Floor,
    false,
    // Weber Spirit / Char-Broil gas grills: 110–130 × 55–65 × 110–120 cm.
    &size3(1.2, 0.6, 1.15, 0.5, 1.25, 0.03),
    build_barbecue,
);

fn build_barbecue(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.08, 0.08, 0.09, 1.0], [0.6, 0.62, 0.64, 1.0], [0.55, 0.1, 0.08, 1.0]]), true);
    let shelf = b.material("shelves", pick(rng, STEEL), false);
    part(b, s, [-0.3, -0.45, 0.0], [0.3, 0.45, 0.7], shelf);
    part(b, s, [-0.32, -0.5, 0.7], [0.32, 0.5, 1.0], body);
    part(b, s, [-0.5, -0.4, 0.72], [-0.32, 0.4, 0.76], shelf);
    part(b, s, [0.32, -0.4, 0.72], [0.5, 0.4, 0.76], shelf);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const FIREPLACE: Category = def(
    "fireplace",
    "fireplace",
    &["fire place", "hearth", "wood burner", "log burner", "wood stove", "electric fire", "mantelpiece"],
    &["home", "living_room", "fixture", "heating"],
    "a fireplace: a mantel surround with a firebox and a hearth",
    &["heater", "fixture"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // Fire surrounds: 110–140 × 30–45 × 100–120 cm.
    &size3(1.2, 0.4, 1.1, 0.6, 1.3, 0.03),
    build_fireplace,
);

fn build_fireplace(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let stone = b.material(
        "surround",
        pick(rng, &[[0.9, 0.88, 0.84, 1.0], [0.6, 0.45, 0.35, 1.0], [0.2, 0.2, 0.21, 1.0]]),
        true,
    );
    let fire = b.material("firebox", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.1, 1.0], stone);
    part(b, s, [-0.5, 0.1, 0.0], [0.5, 0.5, 0.06], stone);
    part(b, s, [-0.5, 0.1, 0.9], [0.5, 0.5, 1.0], stone);
    part(b, s, [-0.3, 0.09, 0.08], [0.3, 0.11, 0.65], fire);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const WHEELIE_BIN: Category = def(
    "wheelie_bin",
    "wheelie bin",
    &["wheeled bin", "outdoor bin", "bin lorry bin", "dumpster bin"],
    &["outdoor", "waste", "container", "floor", "wheeled"],
    "a 240 litre wheelie bin with a hinged lid and two wheels",
    &["bin", "container"],
    Kind::Container,
    PlacementKind::Floor,
    false,
    // 240 l two-wheel bins (EN 840): 58 × 74 × 107 cm.
    &size3(0.58, 0.74, 1.07, 0.6, 1.15, 0.02),
    build_wheelie_bin,
);

fn build_wheelie_bin(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body = b.material(
        "body",
        pick(rng, &[[0.15, 0.35, 0.18, 1.0], [0.15, 0.15, 0.16, 1.0], [0.2, 0.35, 0.65, 1.0]]),
        true,
    );
    let lid = b.material("lid", shade(pick(rng, DARK), 1.2), false);
    let wheel = b.material("wheels", RUBBER[0], false);
    part(b, s, [-0.45, -0.45, 0.05], [0.45, 0.45, 0.94], body);
    part(b, s, [-0.5, -0.5, 0.94], [0.5, 0.5, 1.0], lid);
    for x in [-0.5, 0.35] {
        part(b, s, [x, 0.3, 0.0], [x + 0.15, 0.5, 0.2], wheel);
    }
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const FLOWERPOT: Category = def(
    "flowerpot",
    "flowerpot",
    &["terracotta pot", "plantpot", "empty plant pot"],
    &["garden", "home", "container", "tabletop", "round"],
    "an empty terracotta flowerpot with a rim",
    &["pot", "container", "planter"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // 20 cm terracotta pots: 20 cm across, 17–19 cm tall.
    &size3(0.2, 0.2, 0.18, 0.5, 2.0, 0.05),
    build_flowerpot,
);

fn build_flowerpot(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("clay", pick(rng, &[[0.75, 0.4, 0.25, 1.0], [0.9, 0.9, 0.88, 1.0], [0.2, 0.3, 0.25, 1.0]]), true);
    turn(b, s, [0.0, 1.0], &[[0.0, 0.0], [0.7, 0.0], [0.9, 0.85], [1.0, 0.85], [1.0, 1.0], [0.0, 1.0]], m);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 300.0)
}

// --- on the walls --------------------------------------------------------------------

/// A flat thing hung on the wall: its back on the wall (−Y), its origin on the floor
/// below it, hanging from `mount_height`.
fn hung(p: &Params, b: &mut AssetBuilder, face: usize, frame: usize, border: f64) {
    let (w, d, h) = whd(p);
    let z0 = p.get("mount_height");
    decal_between(b, [-w / 2.0, -d / 2.0, z0], [w / 2.0, d / 2.0 - 0.003, z0 + h], frame);
    let f = (w.min(h) * border).max(0.004);
    decal_between(b, [-w / 2.0 + f, d / 2.0 - 0.004, z0 + f], [w / 2.0 - f, d / 2.0, z0 + h - f], face);
    collider_between(b, [-w / 2.0, -d / 2.0, z0], [w / 2.0, d / 2.0, z0 + h]);
}

pub(crate) const PAINTING: Category = Category {
    name: "painting",
    display: "painting",
    synonyms: &["canvas print", "oil painting", "wall art", "artwork", "framed print", "poster", "framed painting"],
    tags: &["home", "office", "wall", "decor"],
    description: "a framed painting hung on the wall",
    is_a: &["picture", "decoration"],
    kind: Kind::Fixture,
    placement: PlacementKind::WallMounted,
    // Framed paintings and prints: 50–120 × 40–90 cm, 2–5 cm deep.
    params: &[
        ParamDef::new("width", 0.8, 0.3, 1.6, 0.1, "along the wall"),
        ParamDef::new("depth", 0.035, 0.015, 0.06, 0.05, "off the wall"),
        ParamDef::new("height", 0.6, 0.25, 1.2, 0.1, "frame height"),
        ParamDef::new("mount_height", 1.2, 0.8, 1.6, 0.05, "floor to the bottom of the frame"),
    ],
    movable: false,
    vary_per_instance: true,
    build: build_painting,
};

fn build_painting(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let canvas = b.material("canvas", pick(rng, BRIGHT), true);
    let frame =
        b.material("frame", pick(rng, &[[0.55, 0.4, 0.2, 1.0], [0.1, 0.1, 0.1, 1.0], [0.8, 0.65, 0.3, 1.0]]), false);
    hung(p, b, canvas, frame, 0.06);
    0.0
}

pub(crate) const WALL_CLOCK: Category = Category {
    name: "wall_clock",
    display: "wall clock",
    synonyms: &["kitchen clock", "station clock", "office clock", "school clock", "hanging clock"],
    tags: &["home", "office", "classroom", "wall", "decor"],
    description: "a round clock hung on the wall",
    is_a: &["clock", "timepiece"],
    kind: Kind::Fixture,
    placement: PlacementKind::WallMounted,
    // Wall clocks: 25–40 cm across, 4–6 cm deep.
    params: &[
        ParamDef::new("width", 0.3, 0.2, 0.6, 0.05, "diameter"),
        ParamDef::new("depth", 0.05, 0.03, 0.08, 0.05, "off the wall"),
        ParamDef::new("height", 0.3, 0.2, 0.6, 0.05, "diameter"),
        ParamDef::new("mount_height", 1.8, 1.2, 2.2, 0.03, "floor to the bottom of the clock"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_wall_clock,
};

fn build_wall_clock(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let z0 = p.get("mount_height");
    let rim =
        b.material("rim", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.75, 0.76, 0.78, 1.0], [0.5, 0.3, 0.15, 1.0]]), true);
    let face = b.material("face", LABEL_WHITE, false);
    let hands = b.material("hands", INK, false);
    let r = w.min(h) / 2.0;
    let axis =
        sw_geom::Pose::from_pos_axis_angle([0.0, 0.0, z0 + h / 2.0], [1.0, 0.0, 0.0], -std::f64::consts::FRAC_PI_2);
    b.visual(sw_geom::Shape::Cylinder { radius: r, half_height: d / 2.0 - 0.002 }, axis, rim);
    let front = sw_geom::Pose::from_pos_axis_angle(
        [0.0, d / 2.0 - 0.002, z0 + h / 2.0],
        [1.0, 0.0, 0.0],
        -std::f64::consts::FRAC_PI_2,
    );
    b.visual(sw_geom::Shape::Cylinder { radius: r * 0.88, half_height: 0.0015 }, front, face);
    decal_between(b, [-0.004, d / 2.0 - 0.001, z0 + h / 2.0], [0.004, d / 2.0, z0 + h / 2.0 + r * 0.7], hands);
    decal_between(b, [0.0, d / 2.0 - 0.001, z0 + h / 2.0 - 0.004], [r * 0.5, d / 2.0, z0 + h / 2.0 + 0.004], hands);
    collider_between(b, [-w / 2.0, -d / 2.0, z0], [w / 2.0, d / 2.0, z0 + h]);
    0.0
}

pub(crate) const CURTAIN: Category = def(
    "curtain",
    "curtain",
    &["curtains", "drapes", "drape", "pair of curtains", "window curtain", "shower curtain"],
    &["home", "textile", "window", "fixture", "tall"],
    "a pair of floor-length curtains hanging from a pole, drawn open",
    &["textile", "window covering"],
    Kind::Textile,
    PlacementKind::AgainstWall,
    false,
    // Ready-made pairs: 117–229 cm wide (each 1.4 m on a 1.4 m pole), 137–229 cm drop.
    &size3(1.4, 0.12, 2.2, 0.5, 1.6, 0.03),
    build_curtain,
);

fn build_curtain(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let cloth = b.material(
        "cloth",
        pick(rng, &[[0.75, 0.7, 0.6, 1.0], [0.3, 0.4, 0.6, 1.0], [0.6, 0.2, 0.2, 1.0], [0.85, 0.85, 0.82, 1.0]]),
        true,
    );
    let pole = b.material("pole", pick(rng, STEEL), false);
    bar_x(b, s, [-0.5, 0.5], [0.0, 0.985], 0.0065, pole);
    for (x0, x1) in [(-0.5, -0.25), (0.25, 0.5)] {
        for k in 0..4 {
            let y = if k % 2 == 0 { -0.5 } else { -0.1 };
            let (a, c) = (x0 + (x1 - x0) * f64::from(k) / 4.0, x0 + (x1 - x0) * f64::from(k + 1) / 4.0);
            part(b, s, [a, y, 0.0], [c, y + 0.6, 0.97], cloth);
        }
    }
    hull(b, s.0, s.1, s.2);
    0.0
}

// --- more things on tables and floors --------------------------------------------------

pub(crate) const RECORD_PLAYER: Category = def(
    "record_player",
    "record player",
    &["turntable", "gramophone", "record deck", "vinyl player", "phonograph"],
    &["home", "electronics", "music", "tabletop"],
    "a record player: a plinth with a platter, a record on it and a tone arm",
    &["audio device", "electronics"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Rega / Audio-Technica turntables: 42–45 × 33–36 × 11–14 cm.
    &sized(0.43, 0.35, 0.12),
    build_record_player,
);

fn build_record_player(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let plinth =
        b.material("plinth", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.55, 0.35, 0.2, 1.0], [0.9, 0.9, 0.88, 1.0]]), true);
    let record = b.material("record", INK, false);
    let arm = b.material("tone_arm", pick(rng, STEEL), false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.6], plinth);
    lathe(
        b,
        0,
        [-0.08 * s.0, 0.0],
        s.0.min(s.1) * 0.41,
        0.6 * s.2,
        0.12 * s.2,
        &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        record,
    );
    part(b, s, [0.35, -0.35, 0.6], [0.4, 0.3, 0.9], arm);
    hull(b, s.0, s.1, s.2);
    6.0
}

pub(crate) const SOUNDBAR: Category = def(
    "soundbar",
    "soundbar",
    &["sound bar", "tv speaker bar", "speaker bar"],
    &["home", "electronics", "living_room", "tabletop"],
    "a long low soundbar speaker with a grille along its front",
    &["speaker", "audio device", "electronics"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Sonos Beam / Samsung soundbars: 65–110 × 8–12 × 5–8 cm.
    &sized(0.9, 0.1, 0.07),
    build_soundbar,
);

fn build_soundbar(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    device(p, rng, b, &[[0.08, 0.08, 0.09, 1.0], [0.9, 0.9, 0.9, 1.0]], [0.2, 0.2, 0.22, 1.0], 350.0)
}

pub(crate) const ELECTRIC_SHAVER: Category = def(
    "electric_shaver",
    "electric shaver",
    &["shaver", "electric razor", "beard trimmer"],
    &["bathroom", "home", "tabletop", "small", "graspable"],
    "an electric shaver with its head capped, lying down",
    &["personal care appliance", "appliance"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Philips / Braun shavers: 14–17 × 5–7 × 4–6 cm.
    &sized(0.155, 0.06, 0.045),
    build_electric_shaver,
);

fn build_electric_shaver(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    gadget(p, rng, b, 0.7, [0.6, 0.62, 0.65, 1.0])
}

pub(crate) const CRUTCH: Category = def(
    "crutch",
    "crutch",
    &["crutches", "walking crutch", "elbow crutch", "underarm crutch", "pair of crutches"],
    &["hospital", "clinic", "medical", "graspable"],
    "an underarm crutch lying on its side",
    &["mobility aid", "medical equipment"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Adult underarm crutches: 115–135 cm long, 20–25 cm across the frame, 5–10 cm thick.
    &sized(1.25, 0.22, 0.06),
    build_crutch,
);

fn build_crutch(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let frame = b.material("frame", pick(rng, &[[0.7, 0.72, 0.75, 1.0], [0.25, 0.35, 0.55, 1.0]]), true);
    let pad = b.material("pads", INK, false);
    part(b, s, [-0.5, -0.08, 0.0], [-0.05, 0.08, 1.0], frame);
    part(b, s, [-0.05, -0.45, 0.0], [0.42, -0.35, 1.0], frame);
    part(b, s, [-0.05, 0.35, 0.0], [0.42, 0.45, 1.0], frame);
    part(b, s, [0.42, -0.5, 0.0], [0.5, 0.5, 1.0], pad);
    hull(b, s.0, s.1, s.2);
    0.7
}

pub(crate) const KICK_SCOOTER: Category = def(
    "kick_scooter",
    "kick scooter",
    &["scooter", "push scooter", "razor scooter", "kids scooter", "e-scooter", "electric scooter"],
    &["toy", "outdoor", "wheeled", "floor"],
    "a kick scooter: a low deck on two small wheels and a T-bar handlebar",
    &["toy", "wheeled vehicle", "vehicle"],
    Kind::Toy,
    PlacementKind::Floor,
    false,
    // Adult kick scooters: 85–110 cm long, 35–45 wide at the bar, 90–105 cm tall.
    &size3(1.0, 0.4, 1.0, 0.5, 1.2, 0.04),
    build_kick_scooter,
);

fn build_kick_scooter(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let deck = b.material("deck", pick(rng, BRIGHT), true);
    let wheel = b.material("wheels", RUBBER[0], false);
    let steel = b.material("bar", pick(rng, STEEL), false);
    part(b, s, [-0.42, -0.15, 0.06], [0.35, 0.15, 0.11], deck);
    for x in [-0.5, 0.32] {
        part(b, s, [x, -0.04, 0.0], [x + 0.14, 0.04, 0.12], wheel);
    }
    part(b, s, [0.36, -0.03, 0.05], [0.42, 0.03, 0.96], steel);
    part(b, s, [0.36, -0.5, 0.95], [0.42, 0.5, 1.0], steel);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const BALLOON: Category = def(
    "balloon",
    "balloon",
    &["party balloon", "helium balloon", "latex balloon", "bunch of balloons"],
    &["toy", "party", "home", "round", "graspable"],
    "a round party balloon resting on its knot",
    &["toy", "decoration"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // 11–12 inch latex balloons: 28–30 cm across, 33–36 cm tall inflated.
    &sized(0.28, 0.28, 0.34),
    build_balloon,
);

fn build_balloon(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("latex", pick(rng, BRIGHT), true);
    turn(
        b,
        s,
        [0.0, 1.0],
        &[[0.0, 0.0], [0.08, 0.0], [0.1, 0.04], [0.7, 0.25], [1.0, 0.55], [0.85, 0.85], [0.45, 0.98], [0.0, 1.0]],
        m,
    );
    hull(b, s.0, s.1, s.2);
    0.01
}

pub(crate) const CHRISTMAS_TREE: Category = def(
    "christmas_tree",
    "christmas tree",
    &["xmas tree", "fir tree", "artificial christmas tree"],
    &["home", "decor", "plant", "floor", "tall", "round"],
    "a Christmas fir tree in a stand, its branches a cone of green with baubles",
    &["plant", "decoration"],
    Kind::Plant,
    PlacementKind::Floor,
    false,
    // 6 ft trees: 1.8 m tall, 1.1–1.3 m across the lowest branches.
    &size3(1.2, 1.2, 1.8, 0.4, 1.4, 0.04),
    build_christmas_tree,
);

fn build_christmas_tree(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let green = b.material("branches", pick(rng, &[[0.1, 0.35, 0.15, 1.0], [0.12, 0.3, 0.2, 1.0]]), true);
    let stand = b.material("stand", [0.55, 0.1, 0.1, 1.0], false);
    turn(b, (s.0 * 0.3, s.1 * 0.3, s.2), [0.0, 0.1], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], stand);
    turn(
        b,
        s,
        [0.1, 1.0],
        &[[0.0, 0.0], [1.0, 0.0], [0.55, 0.35], [0.75, 0.36], [0.35, 0.7], [0.5, 0.71], [0.0, 1.0]],
        green,
    );
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const POTTERS_WHEEL: Category = def(
    "potters_wheel",
    "potter's wheel",
    &["pottery wheel", "throwing wheel", "ceramics wheel"],
    &["studio", "art", "workshop", "machine", "floor"],
    "an electric potter's wheel: a round wheel head in a splash pan on a low body",
    &["machine", "art equipment"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // Shimpo / Brent wheels: 55–65 × 50–60 × 50–60 cm.
    &size3(0.6, 0.55, 0.55, 0.7, 1.4, 0.03),
    build_potters_wheel,
);

fn build_potters_wheel(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.88, 0.88, 0.86, 1.0], [0.2, 0.35, 0.6, 1.0], [0.3, 0.3, 0.32, 1.0]]), true);
    let head = b.material("wheel_head", pick(rng, STEEL), false);
    part(b, s, [-0.45, -0.45, 0.0], [0.45, 0.45, 0.75], body);
    turn(b, s, [0.75, 0.9], &[[0.0, 0.0], [0.9, 0.0], [1.0, 1.0], [0.8, 1.0], [0.8, 0.3], [0.0, 0.3]], body);
    turn(b, (s.0 * 0.6, s.1 * 0.6, s.2), [0.88, 1.0], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], head);
    hull(b, s.0, s.1, s.2);
    0.0
}

/// A small food item: a turned body in one of `colours` and its topping.
fn snack(
    p: &Params,
    rng: &mut Rng,
    b: &mut AssetBuilder,
    profile: &[[f64; 2]],
    colours: &[[f32; 4]],
    top: Option<([f64; 2], [f32; 4])>,
) -> f64 {
    let s = whd(p);
    let m = b.material("food", pick(rng, colours), true);
    turn(b, s, [0.0, top.map_or(1.0, |t| t.0[0] + 0.01)], profile, m);
    if let Some((z, c)) = top {
        let t = b.material("topping", c, false);
        turn(b, s, z, &DOME, t);
    }
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 500.0)
}

pub(crate) const CUPCAKE: Category = def(
    "cupcake",
    "cupcake",
    &["muffin", "fairy cake", "cup cake"],
    &["kitchen", "food", "cafe", "tabletop", "small", "graspable", "round"],
    "a cupcake in a paper case with icing on top",
    &["cake", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Cupcakes and muffins: 6–8 cm across, 6–8 cm tall.
    &sized(0.07, 0.07, 0.07),
    build_cupcake,
);

fn build_cupcake(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let case = [[0.0, 0.0], [0.75, 0.0], [1.0, 1.0], [0.0, 1.0]];
    snack(
        p,
        rng,
        b,
        &case,
        &[[0.95, 0.8, 0.5, 1.0], [0.45, 0.28, 0.15, 1.0]],
        Some(([0.5, 1.0], [0.95, 0.75, 0.85, 1.0])),
    )
}

pub(crate) const DOUGHNUT: Category = def(
    "doughnut",
    "doughnut",
    &["donut", "ring doughnut", "glazed doughnut", "jam doughnut"],
    &["kitchen", "food", "cafe", "tabletop", "small", "graspable", "round"],
    "a ring doughnut with pink icing",
    &["cake", "pastry", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Ring doughnuts: 8.5–10 cm across, 3–4 cm tall.
    &sized(0.09, 0.09, 0.032),
    build_doughnut,
);

fn build_doughnut(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let ring = [
        [0.0, 0.45],
        [0.3, 0.45],
        [0.35, 0.0],
        [0.9, 0.0],
        [1.0, 0.5],
        [0.9, 1.0],
        [0.35, 1.0],
        [0.3, 0.55],
        [0.0, 0.55],
    ];
    snack(p, rng, b, &ring, &[[0.85, 0.6, 0.3, 1.0], [0.95, 0.7, 0.8, 1.0], [0.4, 0.22, 0.12, 1.0]], None)
}

pub(crate) const SANDWICH: Category = def(
    "sandwich",
    "sandwich",
    &["sarnie", "butty", "sub sandwich", "toastie", "club sandwich"],
    &["kitchen", "food", "cafe", "tabletop", "small", "graspable"],
    "a sandwich: two slices of bread with a filling",
    &["food", "meal"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // A sandwich of two slices of a sandwich loaf: 11–13 cm square, 4–6 cm thick.
    &sized(0.12, 0.12, 0.05),
    build_sandwich,
);

fn build_sandwich(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let bread = b.material("bread", pick(rng, &[[0.95, 0.85, 0.62, 1.0], [0.72, 0.52, 0.3, 1.0]]), true);
    let filling = b.material(
        "filling",
        pick(rng, &[[0.35, 0.6, 0.25, 1.0], [0.85, 0.3, 0.25, 1.0], [0.95, 0.8, 0.3, 1.0]]),
        false,
    );
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.38], bread);
    part(b, s, [-0.49, -0.49, 0.38], [0.49, 0.49, 0.62], filling);
    part(b, s, [-0.48, -0.48, 0.62], [0.48, 0.48, 1.0], bread);
    hull(b, s.0, s.1, s.2);
    0.2
}

pub(crate) const STEAK: Category = def(
    "steak",
    "steak",
    &["beef steak", "sirloin steak", "ribeye", "pork chop", "fillet of meat", "piece of meat"],
    &["kitchen", "food", "tabletop", "small", "graspable"],
    "a raw steak lying flat",
    &["meat", "food"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Sirloin and ribeye steaks: 18–22 × 10–14 cm, 2.5–3.5 cm thick.
    &sized(0.2, 0.12, 0.03),
    build_steak,
);

fn build_steak(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let meat = b.material("meat", pick(rng, &[[0.65, 0.12, 0.12, 1.0], [0.55, 0.3, 0.2, 1.0]]), true);
    let fat = b.material("fat", [0.95, 0.9, 0.8, 1.0], false);
    part(b, s, [-0.5, -0.4, 0.0], [0.45, 0.5, 1.0], meat);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, -0.4, 0.95], fat);
    hull(b, s.0, s.1, s.2);
    0.35
}

pub(crate) const HOT_DOG: Category = def(
    "hot_dog",
    "hot dog",
    &["hotdog", "frankfurter in a bun", "sausage in a bun"],
    &["kitchen", "food", "cafe", "tabletop", "small", "graspable"],
    "a hot dog: a sausage in a long bun",
    &["food", "meal"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // Hot dogs in their buns: 16–20 cm long, 5–6 cm across.
    &sized(0.18, 0.055, 0.05),
    build_hot_dog,
);

fn build_hot_dog(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let bun = b.material("bun", pick(rng, &[[0.9, 0.7, 0.4, 1.0], [0.85, 0.62, 0.35, 1.0]]), true);
    let sausage = b.material("sausage", [0.6, 0.25, 0.15, 1.0], false);
    part(b, s, [-0.46, -0.5, 0.0], [0.46, 0.5, 0.7], bun);
    bar_x(b, s, [-0.5, 0.5], [0.0, 0.7], 0.28, sausage);
    hull(b, s.0, s.1, s.2);
    0.12
}

pub(crate) const YOGURT_POT: Category = def(
    "yogurt_pot",
    "yogurt pot",
    &["yogurt", "yoghurt", "yoghurt pot", "pot of yogurt", "pot of yoghurt", "dessert pot"],
    &["kitchen", "food", "retail", "tabletop", "small", "graspable", "round"],
    "a single plastic pot of yogurt with a foil lid",
    &["food", "dairy", "container"],
    Kind::Food,
    PlacementKind::OnSurface,
    true,
    // 125–150 g pots: 7–7.5 cm across the lid, 7–8 cm tall.
    &sized(0.073, 0.073, 0.075),
    build_yogurt_pot,
);

fn build_yogurt_pot(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let cup =
        b.material("pot", pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.95, 0.75, 0.8, 1.0], [0.6, 0.75, 0.95, 1.0]]), true);
    let lid = b.material("lid", [0.8, 0.82, 0.85, 1.0], false);
    turn(b, s, [0.0, 0.97], &[[0.0, 0.0], [0.78, 0.0], [1.0, 1.0], [0.0, 1.0]], cup);
    turn(b, s, [0.96, 1.0], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], lid);
    hull(b, s.0, s.1, s.2);
    0.14
}
