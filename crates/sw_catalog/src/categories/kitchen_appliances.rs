//! Kitchen appliances: countertop ones that a robot moves and uses (toasters, kettles,
//! coffee makers, blenders, mixers, cookers) and built-in ones whose doors open
//! (dishwasher with a drop-down door, chest freezer with a lid, toaster oven).
//! Sizes are the middle of published product ranges, noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::forms::{back_lid, def, drop_door, knobs, lathe, rounded_box, size3, spread, stretch_y, whd};
use super::kit::{DARK, GLASS, INK, STEEL, collider_between, decal_between, pick, shade, slab};
use super::kitchen::APPLIANCE;
use super::parts::{MOVING_GAP, carcass, round_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const SMALL: &[&str] = &["kitchen", "appliance", "tabletop", "small"];

pub(crate) const TOASTER: Category = def(
    "toaster",
    "toaster",
    &["pop-up toaster", "bread toaster", "2-slice toaster", "two-slice toaster", "4-slice toaster"],
    SMALL,
    "a pop-up bread toaster with two slots on top and a lever on the side",
    &["kitchen appliance", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Dualit / Breville 2-slice toasters: 27–31 × 17–20 × 18–21 cm.
    &size3(0.29, 0.18, 0.19, 0.75, 1.6, 0.05),
    build_toaster,
);

fn build_toaster(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, APPLIANCE), true);
    let slot = b.material("slots", INK, false);
    let trim = b.material("trim", pick(rng, DARK), false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, d * 0.25, body);
    // Two (or four) slots along X on top, the lever and a browning knob on the +X end.
    let n = if w > 0.36 { 4 } else { 2 };
    for y in spread(-d * 0.28, d * 0.28, n.min(2)) {
        decal_between(b, [-w * 0.36, y - 0.015, h - 0.004], [w * 0.36, y + 0.015, h + 0.001], slot);
    }
    decal_between(b, [w / 2.0 - 0.012, -0.012, h * 0.55], [w / 2.0 + 0.003, 0.012, h * 0.7], trim);
    decal_between(b, [-w / 2.0 - 0.002, -d * 0.3, 0.0], [-w / 2.0 + 0.01, d * 0.3, 0.015], trim);
    1.2 + w * d * h * 40.0
}

pub(crate) const KETTLE: Category = def(
    "kettle",
    "kettle",
    &["electric kettle", "tea kettle", "water kettle", "jug kettle", "cordless kettle"],
    &["kitchen", "appliance", "tabletop", "small", "graspable", "handled"],
    "an electric jug kettle on a power base with a handle and a spout",
    &["kitchen appliance", "appliance", "jug"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Russell Hobbs / Bosch 1.7 l jug kettles: 21–24 × 14–17 × 24–26 cm.
    &[
        ParamDef::new("width", 0.225, 0.17, 0.3, 0.04, "body, handle and spout along X"),
        ParamDef::new("depth", 0.155, 0.12, 0.19, 0.04, "body diameter"),
        ParamDef::new("height", 0.25, 0.18, 0.32, 0.05, "base to lid"),
    ],
    build_kettle,
);

/// A round body set left of centre so that the handle (−X) and the spout (+X) fit the
/// width; both collide as a box each.
fn handled_round_body(
    b: &mut AssetBuilder,
    w: f64,
    d: f64,
    h: f64,
    profile: &[[f64; 2]],
    [body, handle]: [usize; 2],
    spout: f64,
) -> f64 {
    let r = d / 2.0;
    let reach = w - d - spout;
    let cx = -w / 2.0 + reach + r;
    lathe(b, 0, [cx, 0.0], r, 0.0, h, profile, body);
    round_collider(b, 0, [cx, 0.0], r, 0.0, h);
    let (z0, z1) = (h * 0.3, h * 0.92);
    decal_between(b, [-w / 2.0, -0.012, z0], [-w / 2.0 + 0.016, 0.012, z1], handle);
    decal_between(b, [-w / 2.0 + 0.01, -0.01, z1 - 0.016], [cx - r * 0.8, 0.01, z1], handle);
    decal_between(b, [-w / 2.0 + 0.01, -0.01, z0], [cx - r * 0.8, 0.01, z0 + 0.016], handle);
    collider_between(b, [-w / 2.0, -0.012, z0], [cx - r * 0.7, 0.012, z1]);
    if spout > 0.0 {
        decal_between(b, [cx + r * 0.8, -0.012, h * 0.7], [w / 2.0, 0.012, h * 0.8], body);
        collider_between(b, [cx + r * 0.8, -0.012, h * 0.7], [w / 2.0, 0.012, h * 0.8]);
    }
    cx
}

fn build_kettle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell =
        pick(rng, &[[0.75, 0.76, 0.78, 1.0], [0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0], [0.7, 0.15, 0.14, 1.0]]);
    let body = b.material("body", shell, true);
    let handle = b.material("handle", pick(rng, DARK), false);
    let profile = [[0.0, 0.0], [0.92, 0.0], [1.0, 0.08], [0.9, 0.9], [0.6, 1.0], [0.0, 1.0]];
    handled_round_body(b, w, d, h, &profile, [body, handle], 0.018);
    0.9 + d * d * h * 15.0
}

pub(crate) const COFFEE_MAKER: Category = def(
    "coffee_maker",
    "coffee maker",
    &[
        "coffee machine",
        "drip coffee maker",
        "filter coffee machine",
        "coffeemaker",
        "coffee brewer",
        "drip coffee machine",
    ],
    SMALL,
    "a drip filter coffee maker with a water tank, a filter basket and a glass carafe on a hot plate",
    &["kitchen appliance", "appliance", "machine", "maker"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Melitta / Mr. Coffee 10–12 cup: 22–26 × 19–24 × 33–38 cm.
    &size3(0.24, 0.22, 0.36, 0.8, 1.4, 0.05),
    build_coffee_maker,
);

fn build_coffee_maker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material(
        "body",
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.93, 0.93, 0.92, 1.0], [0.7, 0.71, 0.73, 1.0]]),
        true,
    );
    let glass = b.material("carafe", [0.35, 0.3, 0.25, 1.0], false);
    let plate = b.material("hot_plate", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let tower = d * 0.4;
    // The foot with the hot plate, the tower at the back, the head overhanging the carafe.
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.035], body);
    slab(b, [-hw, -hd, 0.034], [hw, -hd + tower, h], body);
    slab(b, [-hw, -hd + tower - 0.002, h * 0.72], [hw, hd, h], body);
    let r = (hd - tower / 2.0 - 0.01).min(hw * 0.75) * 0.55;
    let cy = (-hd + tower + hd) / 2.0;
    decal_between(b, [-r * 1.1, cy - r * 1.1, 0.035], [r * 1.1, cy + r * 1.1, 0.039], plate);
    lathe(
        b,
        0,
        [0.0, cy],
        r,
        0.035,
        h * 0.72 - 0.045,
        &[[0.0, 0.0], [0.9, 0.0], [1.0, 0.35], [0.75, 0.95], [0.0, 1.0]],
        glass,
    );
    round_collider(b, 0, [0.0, cy], r, 0.035, 0.035 + (h * 0.72 - 0.045) * 0.9);
    1.8 + w * d * h * 25.0
}

pub(crate) const ESPRESSO_MACHINE: Category = def(
    "espresso_machine",
    "espresso machine",
    &["espresso maker", "bean-to-cup machine", "cappuccino machine", "barista machine", "pump espresso machine"],
    SMALL,
    "a boxy espresso machine with a group head, a portafilter, a steam wand and a drip tray",
    &["kitchen appliance", "appliance", "machine", "coffee machine"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Breville Barista Express / De'Longhi: 30–34 × 28–32 × 38–41 cm.
    &size3(0.32, 0.31, 0.4, 0.8, 1.5, 0.04),
    build_espresso_machine,
);

fn build_espresso_machine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material(
        "body",
        pick(rng, &[[0.72, 0.73, 0.75, 1.0], [0.15, 0.15, 0.16, 1.0], [0.75, 0.2, 0.16, 1.0]]),
        true,
    );
    let steel = b.material("steel", pick(rng, STEEL), false);
    let black = b.material("black", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let front = hd - d * 0.3;
    slab(b, [-hw, -hd, 0.0], [hw, front, h], body);
    // Drip tray in front of the body, group head and portafilter above it.
    slab(b, [-hw * 0.8, front - 0.002, 0.0], [hw * 0.5, hd, 0.03], steel);
    decal_between(b, [-0.045, front, h * 0.55], [0.045, front + 0.04, h * 0.62], steel);
    decal_between(b, [-0.012, front + 0.04, h * 0.565], [0.012, hd - 0.005, h * 0.59], black);
    decal_between(b, [hw * 0.6, front, h * 0.3], [hw * 0.6 + 0.008, front + 0.04, h * 0.6], steel);
    decal_between(b, [-hw * 0.7, front, h * 0.75], [hw * 0.7, front + 0.004, h * 0.9], black);
    knobs(b, &[-hw * 0.5, hw * 0.5], front, h * 0.82, 0.014, steel);
    6.0 + w * d * h * 30.0
}

pub(crate) const BLENDER: Category = def(
    "blender",
    "blender",
    &["countertop blender", "smoothie maker", "liquidiser", "liquidizer", "smoothie blender"],
    SMALL,
    "a countertop blender: a motor base with a tall tapered jug and lid on top",
    &["kitchen appliance", "appliance", "mixer"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Ninja / Vitamix / Oster: 18–22 × 18–22 × 40–50 cm.
    &size3(0.2, 0.2, 0.44, 0.75, 1.3, 0.05),
    build_blender,
);

fn build_blender(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let base = b.material("base", pick(rng, APPLIANCE), true);
    let jar = b.material("jar", [0.7, 0.78, 0.82, 1.0], false);
    let lid = b.material("lid", INK, false);
    let zb = h * 0.3;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, zb, w * 0.2, base);
    knobs(b, &[0.0], d / 2.0 - 0.008, zb * 0.5, 0.018, lid);
    let r = w.min(d) * 0.45;
    lathe(b, 0, [0.0, 0.0], r, zb, h - zb - 0.02, &[[0.0, 0.0], [0.65, 0.0], [1.0, 1.0], [0.0, 1.0]], jar);
    lathe(b, 0, [0.0, 0.0], r * 1.02, h - 0.02, 0.02, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], lid);
    round_collider(b, 0, [0.0, 0.0], r * 0.85, zb, h);
    2.5 + w * d * zb * 60.0
}

pub(crate) const FOOD_PROCESSOR: Category = def(
    "food_processor",
    "food processor",
    &["food chopper", "mini chopper", "kitchen processor"],
    SMALL,
    "a food processor: a motor base with a clear bowl, a lid and a feed tube",
    &["kitchen appliance", "appliance", "processor"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Cuisinart / Magimix 12–14 cup: 20–26 × 18–24 × 34–40 cm.
    &size3(0.23, 0.21, 0.37, 0.75, 1.3, 0.05),
    build_food_processor,
);

fn build_food_processor(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let base = b.material("base", pick(rng, APPLIANCE), true);
    let bowl = b.material("bowl", [0.75, 0.8, 0.82, 1.0], false);
    let zb = h * 0.35;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, zb, w * 0.15, base);
    let r = w.min(d) * 0.45;
    let zt = h * 0.82;
    lathe(b, 0, [0.0, 0.0], r, zb, zt - zb, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], bowl);
    round_collider(b, 0, [0.0, 0.0], r, zb, zt);
    // The feed tube at the back of the lid.
    let tube = (r * 0.35).min(0.04);
    decal_between(b, [-tube, -r * 0.7, zt - 0.002], [tube, -r * 0.7 + 2.0 * tube, h], bowl);
    collider_between(b, [-tube, -r * 0.7, zt], [tube, -r * 0.7 + 2.0 * tube, h]);
    3.0 + w * d * zb * 50.0
}

pub(crate) const STAND_MIXER: Category = def(
    "stand_mixer",
    "stand mixer",
    &["kitchen mixer", "food mixer", "kitchenaid", "cake mixer", "tilt-head mixer", "mixer"],
    SMALL,
    "a tilt-head stand mixer: a heavy base, a column and a motor head over a steel bowl",
    &["kitchen appliance", "appliance", "mixer"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // KitchenAid Artisan 5 qt: 37 × 22 × 36 cm.
    &size3(0.36, 0.22, 0.36, 0.8, 1.3, 0.04),
    build_stand_mixer,
);

fn build_stand_mixer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let enamel = b.material(
        "enamel",
        pick(rng, &[[0.75, 0.1, 0.12, 1.0], [0.95, 0.94, 0.9, 1.0], [0.3, 0.4, 0.6, 1.0], [0.2, 0.2, 0.21, 1.0]]),
        true,
    );
    let steel = b.material("bowl", [0.8, 0.81, 0.83, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, 0.05, 0.04, enamel);
    // The column at -X and the head reaching over the bowl at +X.
    rounded_box(b, [-hw + w * 0.14, 0.0], w * 0.26, d * 0.6, 0.049, h * 0.72, 0.03, enamel);
    rounded_box(b, [0.0, 0.0], w, d * 0.55, h * 0.7, h, 0.05, enamel);
    let r = (hw * 0.45).min(hd * 0.98);
    let bx = hw * 0.42;
    lathe(
        b,
        0,
        [bx, 0.0],
        r,
        0.05,
        h * 0.5 - 0.05,
        &[[0.0, 0.0], [0.6, 0.0], [1.0, 0.6], [1.0, 1.0], [0.0, 1.0]],
        steel,
    );
    round_collider(b, 0, [bx, 0.0], r, 0.05, h * 0.5);
    10.0
}

pub(crate) const RICE_COOKER: Category = def(
    "rice_cooker",
    "rice cooker",
    &["rice maker", "electric rice cooker", "multicooker", "multi cooker", "instant pot"],
    &["kitchen", "appliance", "tabletop", "small", "round"],
    "a round electric rice cooker or multicooker with a domed lid and a carrying handle",
    &["kitchen appliance", "appliance", "cooker"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Zojirushi / Instant Pot 5–6 l: 25–33 cm across, 22–32 cm tall.
    &[
        ParamDef::new("width", 0.28, 0.2, 0.36, 0.06, "diameter"),
        ParamDef::new("depth", 0.28, 0.2, 0.36, 0.06, "diameter (as width)"),
        ParamDef::new("height", 0.26, 0.18, 0.34, 0.06, "base to lid"),
    ],
    build_rice_cooker,
);

fn build_rice_cooker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let body = b.material("body", pick(rng, APPLIANCE), true);
    let lid = b.material("lid", pick(rng, &[[0.2, 0.2, 0.21, 1.0], [0.75, 0.76, 0.78, 1.0]]), false);
    let panel = b.material("panel", INK, false);
    lathe(b, 0, [0.0, 0.0], r, 0.0, h * 0.75, &[[0.0, 0.0], [0.9, 0.0], [1.0, 0.15], [1.0, 1.0], [0.0, 1.0]], body);
    lathe(b, 0, [0.0, 0.0], r * 0.96, h * 0.749, h * 0.251, &[[0.0, 0.0], [1.0, 0.0], [0.8, 0.7], [0.0, 1.0]], lid);
    decal_between(b, [-r * 0.3, r * 0.85, h * 0.35], [r * 0.3, r * 0.99, h * 0.55], panel);
    round_collider(b, 0, [0.0, 0.0], r, 0.0, h);
    2.5 + r * r * h * 40.0
}

pub(crate) const SLOW_COOKER: Category = def(
    "slow_cooker",
    "slow cooker",
    &["crock pot", "crockpot", "casserole cooker"],
    SMALL,
    "an oval slow cooker: a ceramic pot in a heated shell with a glass lid",
    &["kitchen appliance", "appliance", "cooker", "pot"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Crock-Pot 6 qt oval: 38 × 25 × 24 cm.
    &size3(0.37, 0.25, 0.24, 0.75, 1.3, 0.05),
    build_slow_cooker,
);

fn build_slow_cooker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.2, 0.2, 0.21, 1.0], [0.75, 0.76, 0.78, 1.0], [0.55, 0.1, 0.1, 1.0]]), true);
    let glass = b.material("lid", [0.6, 0.66, 0.68, 1.0], false);
    let r = w / 2.0;
    let f = d / w;
    let pot = revolve(&[[0.0, 0.0], [r * 0.85, 0.0], [r, h * 0.15], [r, h * 0.8], [0.0, h * 0.8]], ROUND);
    b.visual_mesh_on(0, &stretch_y(pot, f), Pose::IDENTITY, body);
    let lid = revolve(&[[0.0, h * 0.79], [r * 0.95, h * 0.79], [r * 0.5, h * 0.97], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &stretch_y(lid, f), Pose::IDENTITY, glass);
    collider_between(b, [-r * 0.92, -d / 2.0 * 0.92, 0.0], [r * 0.92, d / 2.0 * 0.92, h]);
    collider_between(b, [-r, -d * 0.2, 0.0], [r, d * 0.2, h * 0.8]);
    collider_between(b, [-r * 0.4, -d / 2.0, 0.0], [r * 0.4, d / 2.0, h * 0.8]);
    3.0 + w * d * h * 30.0
}

pub(crate) const AIR_FRYER: Category = def(
    "air_fryer",
    "air fryer",
    &["airfryer", "hot air fryer", "fryer"],
    SMALL,
    "an air fryer: a rounded box with a pull-out basket drawer and a handle at the front",
    &["kitchen appliance", "appliance", "fryer"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Philips XL / Cosori 5.5 l: 28–32 × 31–38 × 30–33 cm.
    &size3(0.3, 0.34, 0.31, 0.8, 1.4, 0.04),
    build_air_fryer,
);

fn build_air_fryer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.94, 0.94, 0.93, 1.0]]), true);
    let drawer = b.material("drawer", [0.08, 0.08, 0.09, 1.0], false);
    let screen = b.material("screen", [0.1, 0.25, 0.35, 1.0], false);
    let hd = d / 2.0;
    rounded_box(b, [0.0, -0.02], w, d - 0.04, 0.0, h, w * 0.2, body);
    // The basket drawer's front and its handle reach the front of the overall box.
    decal_between(b, [-w * 0.38, hd - 0.041, 0.02], [w * 0.38, hd - 0.03, h * 0.5], drawer);
    decal_between(b, [-0.025, hd - 0.03, h * 0.2], [0.025, hd, h * 0.42], drawer);
    collider_between(b, [-0.025, hd - 0.04, h * 0.2], [0.025, hd, h * 0.42]);
    decal_between(b, [-w * 0.25, hd - 0.045, h * 0.62], [w * 0.25, hd - 0.038, h * 0.85], screen);
    4.5
}

pub(crate) const TOASTER_OVEN: Category = def(
    "toaster_oven",
    "toaster oven",
    &["countertop oven", "mini oven", "convection oven", "benchtop oven", "tabletop oven"],
    SMALL,
    "a countertop toaster oven with a drop-down glass door, a wire rack and control knobs",
    &["kitchen appliance", "appliance", "oven"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Breville Smart Oven / Panasonic: 42–48 × 33–38 × 24–28 cm.
    &size3(0.46, 0.36, 0.27, 0.8, 1.3, 0.04),
    build_toaster_oven,
);

/// An open-fronted box with a glass door hinged at the bottom (a robot pulls it down by
/// its bar) and a knob panel on the right.
fn build_toaster_oven(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let finish = pick(rng, &[[0.72, 0.73, 0.75, 1.0], [0.15, 0.15, 0.16, 1.0]]);
    let body = b.material("body", finish, true);
    let door = b.material("door", GLASS, false);
    let handle = b.material("handle", pick(rng, STEEL), false);
    let panel = b.material("panel", shade(finish, 0.7), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.02;
    let opening = hd - dt - MOVING_GAP;
    let pw = (w * 0.24).min(0.12);
    let top = carcass(b, -hw, hw, -hd, opening, 0.0, h, 0.012, body);
    slab(b, [hw - pw, opening - 0.05, 0.012], [hw - 0.006, hd, h - 0.012], panel);
    knobs(b, &[hw - pw / 2.0], hd - 0.012, h * 0.65, 0.016, handle);
    drop_door(b, "door", [-hw + 0.004, hw - pw - 0.003], [0.006, h - 0.004], hd - dt, dt, [door, handle], 1.0);
    b.surface("top", top, [-hw + 0.006, -hd], [hw - 0.006, opening], None);
    (w * d * h * 180.0).max(4.0)
}

pub(crate) const DISHWASHER: Category = def(
    "dishwasher",
    "dishwasher",
    &["dish washer", "dishwashing machine", "built-in dishwasher", "freestanding dishwasher"],
    &["kitchen", "appliance", "storage"],
    "a 60 cm kitchen dishwasher with a drop-down door, a control strip and racks inside",
    &["kitchen appliance", "appliance", "washer", "machine"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Bosch Series 4 / Miele freestanding: 60 × 60 × 84.5 cm (45 cm slimline).
    &[
        ParamDef::new("width", 0.6, 0.45, 0.6, 0.0, "along X: 60 cm, or 45 cm slimline"),
        ParamDef::new("depth", 0.6, 0.55, 0.65, 0.02, "along Y, door included"),
        ParamDef::new("height", 0.845, 0.8, 0.9, 0.01, "floor to worktop height"),
    ],
    build_dishwasher,
);

fn build_dishwasher(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let finish = pick(rng, APPLIANCE);
    let body = b.material("body", finish, true);
    let door = b.material("door", shade(finish, 1.03), true);
    let inside = b.material("inside", [0.78, 0.79, 0.8, 1.0], false);
    let strip = b.material("controls", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.05;
    let opening = hd - dt - MOVING_GAP;
    let wall = 0.02;
    let top = carcass(b, -hw, hw, -hd, opening, 0.06, h, wall, body);
    slab(b, [-hw + 0.015, -hd, 0.0], [hw - 0.015, opening - 0.04, 0.06], body);
    // Two racks inside (thin wire decks).
    for z in [0.06 + (h - 0.06) * 0.2, 0.06 + (h - 0.06) * 0.55] {
        decal_between(
            b,
            [-hw + wall + 0.01, -hd + wall + 0.02, z],
            [hw - wall - 0.01, opening - 0.03, z + 0.008],
            inside,
        );
    }
    let leaf = drop_door(b, "door", [-hw + 0.003, hw - 0.003], [0.065, h - 0.004], hd - dt, dt, [door, strip], 6.0);
    super::parts::decal_on(
        b,
        leaf,
        [-hw + 0.01, -0.001, h - 0.065 - 0.06],
        [hw - 0.01, 0.003, h - 0.065 - 0.012],
        strip,
    );
    b.surface("top", top, [-hw + wall / 2.0, -hd], [hw - wall / 2.0, opening], None);
    0.0
}

pub(crate) const CHEST_FREEZER: Category = def(
    "chest_freezer",
    "chest freezer",
    &["deep freezer", "box freezer", "ice cream freezer", "horizontal freezer"],
    &["kitchen", "appliance", "retail", "storage"],
    "a white chest freezer: an insulated box with a lid hinged at the back",
    &["appliance", "freezer", "cooler"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Beko / Frigidaire 200–300 l: 90–130 × 55–70 × 84–86 cm.
    &[
        ParamDef::new("width", 1.0, 0.55, 1.6, 0.12, "along X"),
        ParamDef::new("depth", 0.6, 0.5, 0.75, 0.06, "along Y"),
        ParamDef::new("height", 0.85, 0.75, 0.92, 0.02, "floor to the top of the lid"),
    ],
    build_chest_freezer,
);

fn build_chest_freezer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let white = b.material("body", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.9, 0.91, 0.92, 1.0]]), true);
    let base = b.material("plinth", pick(rng, DARK), false);
    let inside = b.material("inside", [0.85, 0.88, 0.9, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = 0.05;
    let lid_t = 0.06;
    let rim = h - lid_t - MOVING_GAP;
    slab(b, [-hw + 0.02, -hd + 0.02, 0.0], [hw - 0.02, hd - 0.02, 0.08], base);
    let floor = slab(b, [-hw, -hd, 0.08], [hw, hd, 0.15], white);
    for (x0, x1) in [(-hw, -hw + t), (hw - t, hw)] {
        slab(b, [x0, -hd, 0.1], [x1, hd, rim], white);
    }
    for (y0, y1) in [(-hd, -hd + t), (hd - t, hd)] {
        slab(b, [-hw + t / 2.0, y0, 0.1], [hw - t / 2.0, y1, rim], white);
    }
    decal_between(b, [-hw + t, -hd + t, floor - 0.002], [hw - t, hd - t, floor + 0.001], inside);
    back_lid(b, "lid", [-hw, hw], [-hd, hd], rim + MOVING_GAP, lid_t, white, (w * d * 12.0).max(4.0));
    let m = 0.03;
    b.surface("inside", floor, [-hw + t + m, -hd + t + m], [hw - t - m, hd - t - m], Some(rim - floor - 0.02));
    0.0
}

pub(crate) const COOKTOP: Category = def(
    "cooktop",
    "cooktop",
    &["hob", "induction hob", "gas hob", "ceramic hob", "induction cooktop", "stovetop", "electric hob"],
    &["kitchen", "appliance", "surface"],
    "a built-in hob: a black glass cooking top with four zones, set into a worktop",
    &["kitchen appliance", "appliance", "cooker"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Bosch / Neff 60 cm induction hob: 59.2 × 52.2 × 5.1 cm.
    &[
        ParamDef::new("width", 0.59, 0.3, 0.9, 0.08, "along X"),
        ParamDef::new("depth", 0.52, 0.4, 0.55, 0.03, "along Y"),
        ParamDef::new("height", 0.055, 0.04, 0.1, 0.1, "underside to glass"),
    ],
    build_cooktop,
);

fn build_cooktop(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let glass = b.material("glass", pick(rng, &[[0.06, 0.06, 0.07, 1.0], [0.62, 0.63, 0.65, 1.0]]), true);
    let box_ = b.material("housing", pick(rng, DARK), false);
    let rings = b.material("zones", [0.35, 0.35, 0.37, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw + 0.02, -hd + 0.02, 0.0], [hw - 0.02, hd - 0.02, h - 0.006], box_);
    let top = slab(b, [-hw, -hd, h - 0.006], [hw, hd, h], glass);
    let (bx, by) = (w * 0.24, d * 0.22);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let r = f64::min(if sx * sy > 0.0 { 0.1 } else { 0.08 }, (w * 0.2).min(d * 0.22));
        let ring = revolve(&super::shapes::rounded_ring_profile(r - 0.006, r, h, h + 0.0008, 0.0003), ROUND);
        b.visual_mesh_on(0, &ring, Pose::from_pos([sx * bx, sy * by, 0.0]), rings);
    }
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    (w * d * 30.0).max(3.0)
}

pub(crate) const DISH_RACK: Category = def(
    "dish_rack",
    "dish rack",
    &["dish drainer", "drying rack for dishes", "draining rack", "dish drying rack", "plate rack", "drainer"],
    &["kitchen", "tabletop", "small", "container", "open"],
    "a dish drainer: a low wire basket with plate slots and a cutlery cup",
    &["rack", "holder", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Simplehuman / IKEA dish drainers: 40–52 × 30–38 × 12–16 cm.
    &size3(0.45, 0.33, 0.14, 0.75, 1.3, 0.05),
    build_dish_rack,
);

fn build_dish_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wire =
        b.material("wire", pick(rng, &[[0.8, 0.81, 0.82, 1.0], [0.95, 0.95, 0.94, 1.0], [0.2, 0.2, 0.21, 1.0]]), true);
    let tines = b.material("tines", pick(rng, STEEL), false);
    let floor = super::parts::open_box(b, w, d, h * 0.55, 0.006, wire);
    // Plate tines across the left two thirds, a cutlery cup on the right.
    for x in spread(-w / 2.0 + 0.02, w * 0.15, 8) {
        decal_between(b, [x - 0.0015, -d / 2.0 + 0.03, floor], [x + 0.0015, d / 2.0 - 0.03, h], tines);
    }
    decal_between(b, [w * 0.22, -d * 0.3, floor], [w / 2.0 - 0.02, d * 0.1, h * 0.95], tines);
    collider_between(b, [-w / 2.0 + 0.02, -0.004, floor], [w * 0.15, 0.004, h]);
    0.6
}

pub(crate) const KNIFE_BLOCK: Category = def(
    "knife_block",
    "knife block",
    &["knife holder", "knife set", "knife stand"],
    &["kitchen", "tabletop", "small", "graspable"],
    "a slanted wooden knife block with knife handles sticking out of the top",
    &["holder", "block", "kitchenware"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Wüsthof / Zwilling 6-slot blocks: 10–14 × 20–24 × 24–30 cm with knives.
    &size3(0.12, 0.22, 0.28, 0.75, 1.3, 0.05),
    build_knife_block,
);

fn build_knife_block(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let wood = b.material("wood", pick(rng, super::kit::WOOD), true);
    let handles = b.material("handles", pick(rng, &[[0.1, 0.1, 0.1, 1.0], [0.35, 0.22, 0.14, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let zt = h * 0.72;
    // A wedge, high at the back (-Y), low at the front.
    let side = super::shapes::prism(&[[-hd, 0.0], [hd, 0.0], [hd, zt * 0.45], [-hd, zt]], -hw, hw);
    let mut m = side;
    for v in &mut m.vertices {
        *v = [v[2], v[0], v[1]];
    }
    b.visual_mesh_on(0, &m, Pose::IDENTITY, wood);
    collider_between(b, [-hw, -hd, 0.0], [hw, hd, zt * 0.6]);
    collider_between(b, [-hw, -hd, zt * 0.6 - 0.001], [hw, 0.0, zt]);
    for (k, y) in spread(-hd * 0.8, -hd * 0.1, 3).into_iter().enumerate() {
        let x = (k as f64 - 1.0) * hw * 0.5;
        decal_between(b, [x - 0.01, y - 0.012, zt - 0.01], [x + 0.01, y + 0.012, h], handles);
    }
    collider_between(b, [-hw * 0.7, -hd * 0.85, zt - 0.002], [hw * 0.7, -hd * 0.05, h]);
    1.6
}
