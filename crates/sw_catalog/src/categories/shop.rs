//! Cafés, shops, clinics and labs: tills, drinks fridges with glass doors, shopping
//! baskets, café tables, A-boards, clothes rails, mannequins, display cases and shop
//! scales; wheelchairs, examination couches, walking frames, pill bottles, first-aid kits
//! and sharps bins; flasks, cylinders, Petri dishes, pipettes, hot plates, balances,
//! incubators, burners, vortex mixers and water baths. Sizes from product ranges.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::forms::{Seg, def, drop_door, knobs, lathe, long_item, rounded_box, size3, spread, whd};
use super::kit::{
    Axis, INK, LABEL_WHITE, OFFICE_PAINT, PLASTIC, SIGNAL_RED, STEEL, UPHOLSTERY, WOOD, along, collider_between,
    decal_between, pick, rod, shade, slab,
};
use super::parts::{Hinge, MOVING_GAP, carcass, hinged_door, open_box, round_collider, round_solid, vessel_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const LAB_WHITE: &[[f32; 4]] = &[[0.93, 0.93, 0.91, 1.0], [0.86, 0.87, 0.88, 1.0], [0.9, 0.91, 0.93, 1.0]];
const LAB_GLASS: [f32; 4] = [0.78, 0.86, 0.9, 1.0];
const BENCHTOP: &[&str] = &["lab", "tabletop", "small", "instrument"];

pub(crate) const CASH_REGISTER: Category = def(
    "cash_register",
    "cash register",
    &["till", "register", "pos terminal", "point of sale terminal", "cash till", "card terminal"],
    &["retail", "cafe", "electronics", "tabletop"],
    "a shop till: a cash drawer under a keypad and a customer display",
    &["machine", "electronics", "device"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Electronic cash registers (Casio, Sharp): 33–40 × 35–45 × 20–30 cm.
    &size3(0.37, 0.4, 0.27, 0.8, 1.25, 0.05),
    build_cash_register,
);

fn build_cash_register(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.85, 0.86, 0.86, 1.0]]), true);
    let keys = b.material("keys", pick(rng, &[[0.9, 0.9, 0.88, 1.0], [0.3, 0.3, 0.32, 1.0]]), false);
    let screen = b.material("display", [0.1, 0.3, 0.35, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let drawer = h * 0.4;
    slab(b, [-hw, -hd, 0.0], [hw, hd, drawer], body);
    slab(b, [-hw, -hd, drawer - 0.001], [hw, hd * 0.2, h * 0.62], body);
    for x in spread(-hw * 0.8, hw * 0.8, 5) {
        for y in spread(-hd * 0.8, hd * 0.1, 4) {
            decal_between(b, [x - 0.015, y - 0.012, h * 0.62 - 0.001], [x + 0.015, y + 0.012, h * 0.62 + 0.004], keys);
        }
    }
    slab(b, [-hw * 0.4, -hd, h * 0.62 - 0.002], [hw * 0.4, -hd + 0.05, h], body);
    decal_between(b, [-hw * 0.35, -hd + 0.049, h * 0.75], [hw * 0.35, -hd + 0.052, h * 0.95], screen);
    decal_between(b, [-hw * 0.9, hd - 0.001, drawer * 0.3], [hw * 0.9, hd + 0.002, drawer * 0.35], keys);
    6.0
}

pub(crate) const DISPLAY_FRIDGE: Category = def(
    "display_fridge",
    "display fridge",
    &[
        "drinks fridge",
        "beverage cooler",
        "glass door fridge",
        "display cooler",
        "merchandiser fridge",
        "bottle cooler",
        "cooler cabinet",
        "wine fridge",
    ],
    &["retail", "cafe", "kitchen", "appliance", "tall", "storage"],
    "a tall shop drinks fridge with a glass door and shelves of bottles inside",
    &["fridge", "refrigerator", "appliance", "cooler"],
    Kind::LargeAppliance,
    PlacementKind::AgainstWall,
    false,
    // Single-door merchandisers (True, Liebherr FKv): 60–65 × 60–70 × 170–200 cm.
    &[
        ParamDef::new("width", 0.62, 0.5, 0.8, 0.05, "along X"),
        ParamDef::new("depth", 0.65, 0.55, 0.75, 0.04, "along Y, door included"),
        ParamDef::new("height", 1.85, 0.85, 2.05, 0.05, "floor to top"),
    ],
    build_display_fridge,
);

fn build_display_fridge(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let finish = pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.95, 0.95, 0.94, 1.0], [0.75, 0.12, 0.1, 1.0]]);
    let body = b.material("body", finish, true);
    let glass = b.material("glass", [0.6, 0.72, 0.78, 1.0], false);
    let inside = b.material("inside", [0.85, 0.88, 0.9, 1.0], false);
    let handle = b.material("handle", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.045;
    let opening = hd - dt - MOVING_GAP;
    let wall = 0.04;
    let base = 0.1;
    slab(b, [-hw + 0.015, -hd, 0.0], [hw - 0.015, opening - 0.02, base], body);
    carcass(b, -hw, hw, -hd, opening, base, h, wall, body);
    // Shelves with drinks on them; the door a glass pane in a frame.
    let n = ((h - base - 0.3) / 0.32).floor().max(1.0) as usize;
    let bottles = b.material("bottles", pick(rng, PLASTIC), false);
    for k in 1..=n {
        let z = base + wall + (h - base - 2.0 * wall) * k as f64 / (n + 1) as f64;
        slab(b, [-hw + wall * 0.5, -hd + wall * 0.75, z - 0.008], [hw - wall * 0.5, opening - 0.03, z], inside);
        for x in spread(-hw + wall, hw - wall, 5) {
            rod(b, [x, 0.0, z + 0.1], 0.03, 0.2, Axis::Z, bottles);
        }
    }
    let leaf = hinged_door(
        b,
        "door",
        Hinge::MinX,
        [-hw + 0.003, hw - 0.003],
        [base + 0.005, h - 0.005],
        hd - dt,
        dt,
        body,
        handle,
        h * 0.5,
        8.0,
    );
    super::parts::decal_on(b, leaf, [0.05, dt / 2.0, 0.06], [w - 0.056, dt / 2.0 + 0.002, h - base - 0.07], glass);
    0.0
}

pub(crate) const SHOPPING_BASKET: Category = def(
    "shopping_basket",
    "shopping basket",
    &["hand basket", "grocery basket", "supermarket basket", "wire basket", "basket", "picnic basket", "wicker basket"],
    &["retail", "container", "open", "tabletop", "graspable"],
    "an open plastic shopping basket with two handles",
    &["basket", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Supermarket hand baskets: 43–48 × 30–33 × 20–23 cm (22 l).
    &size3(0.44, 0.31, 0.22, 0.6, 1.3, 0.06),
    build_shopping_basket,
);

fn build_shopping_basket(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba =
        pick(rng, &[[0.8, 0.12, 0.1, 1.0], [0.15, 0.35, 0.7, 1.0], [0.2, 0.55, 0.3, 1.0], [0.7, 0.55, 0.35, 1.0]]);
    let plastic = b.material("plastic", rgba, true);
    let handles = b.material("handles", shade(rgba, 0.6), false);
    let floor = open_box(b, w, d, h * 0.85, 0.006, plastic);
    for x in [-w * 0.2, w * 0.2] {
        decal_between(b, [x - 0.01, -d / 2.0 + 0.01, h * 0.85 - 0.002], [x + 0.01, d / 2.0 - 0.01, h], handles);
        collider_between(b, [x - 0.01, -d / 2.0 + 0.01, h * 0.85 - 0.002], [x + 0.01, d / 2.0 - 0.01, h]);
    }
    b.surface(
        "inside",
        floor,
        [-w / 2.0 + 0.03, -d / 2.0 + 0.03],
        [w / 2.0 - 0.03, d / 2.0 - 0.03],
        Some(h * 0.85 - floor - 0.02),
    );
    0.6
}

pub(crate) const CAFE_TABLE: Category = def(
    "cafe_table",
    "cafe table",
    &["café table", "bistro table", "round table", "pedestal table", "bar table", "high table", "tulip table"],
    &["furniture", "surface", "cafe", "home", "round", "tabletop"],
    "a small round table on a single pedestal with a round foot",
    &["table", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Bistro tables: 60–80 cm round tops, 72–76 cm high (bar tables 105 cm).
    &[
        ParamDef::new("width", 0.7, 0.5, 1.2, 0.12, "top diameter"),
        ParamDef::new("depth", 0.7, 0.5, 1.2, 0.12, "top diameter (as width)"),
        ParamDef::new("height", 0.74, 0.6, 1.1, 0.03, "floor to top"),
    ],
    build_cafe_table,
);

fn build_cafe_table(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let top = b.material(
        "top",
        pick(rng, &[[0.72, 0.55, 0.36, 1.0], [0.95, 0.95, 0.94, 1.0], [0.15, 0.15, 0.16, 1.0], [0.6, 0.6, 0.62, 1.0]]),
        true,
    );
    let metal = b.material("pedestal", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.66, 0.68, 0.7, 1.0]]), false);
    let z = round_solid(b, 0, [0.0, 0.0], r, h - 0.03, h, top);
    round_solid(b, 0, [0.0, 0.0], r * 0.55, 0.0, 0.025, metal);
    round_solid(b, 0, [0.0, 0.0], 0.035, 0.024, h - 0.029, metal);
    let a = r / std::f64::consts::SQRT_2 - 1e-6;
    b.surface("top", z, [-a, -a], [a, a], None);
    0.0
}

pub(crate) const SANDWICH_BOARD: Category = def(
    "sandwich_board",
    "sandwich board",
    &["a-board", "a-frame sign", "pavement sign", "sidewalk sign", "chalkboard sign", "menu board", "easel sign"],
    &["retail", "cafe", "sign"],
    "a folding A-frame chalkboard sign standing on the floor",
    &["sign", "board"],
    Kind::Fixture,
    PlacementKind::Floor,
    false,
    // A-boards: 60 × 50–60 × 90–100 cm (standing open).
    &size3(0.6, 0.55, 0.95, 0.7, 1.3, 0.05),
    build_sandwich_board,
);

fn build_sandwich_board(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let frame = b.material("frame", pick(rng, WOOD), true);
    let board = b.material("board", [0.12, 0.13, 0.13, 1.0], false);
    let chalk = b.material("chalk", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    // Two boards leaning together at the top: each a slanted slab on a foot rail.
    for s in [-1.0, 1.0] {
        let (y0, y1) = super::kit::ordered(s * (hd - 0.03), s * hd);
        slab(b, [-hw, y0, 0.0], [hw, y1, 0.012], frame);
        let at =
            Pose::from_pos_axis_angle([0.0, s * (hd / 2.0 - 0.012), h / 2.0], [1.0, 0.0, 0.0], s * (hd / h).atan());
        let len = (h * h + hd * hd).sqrt();
        b.solid(Shape::Box { half: [hw, 0.012, len / 2.0 - 0.01] }, at, frame);
        let inner =
            Pose::from_pos_axis_angle([0.0, s * (hd / 2.0 + 0.001), h / 2.0], [1.0, 0.0, 0.0], s * (hd / h).atan());
        b.visual(Shape::Box { half: [hw - 0.04, 0.002, len / 2.0 - 0.06] }, inner, board);
        let line =
            Pose::from_pos_axis_angle([0.0, s * (hd / 2.0 + 0.004), h * 0.6], [1.0, 0.0, 0.0], s * (hd / h).atan());
        b.visual(Shape::Box { half: [hw * 0.6, 0.001, 0.008] }, line, chalk);
    }
    0.0
}

pub(crate) const CLOTHES_RACK: Category = def(
    "clothes_rack",
    "clothes rack",
    &["clothing rack", "garment rack", "clothes rail", "rolling rack", "coat rail", "dress rail"],
    &["retail", "home", "furniture", "tall"],
    "a clothes rail on a wheeled frame with garments hanging on it",
    &["rack", "stand", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Garment rails: 120–180 × 45–55 × 150–170 cm.
    &size3(1.5, 0.5, 1.6, 0.7, 1.3, 0.06),
    build_clothes_rack,
);

fn build_clothes_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let steel = b.material("frame", pick(rng, STEEL), true);
    let (hw, hd) = (w / 2.0, d / 2.0);
    for x in [-hw + 0.02, hw - 0.02] {
        slab(b, [x - 0.02, -hd, 0.0], [x + 0.02, hd, 0.04], steel);
        slab(b, [x - 0.015, -0.015, 0.039], [x + 0.015, 0.015, h], steel);
    }
    slab(b, [-hw, -0.015, h - 0.03], [hw, 0.015, h - 0.001], steel);
    // Garments in a row under the rail.
    let n = ((w - 0.2) / 0.12).floor().max(2.0) as usize;
    for (k, x) in spread(-hw + 0.1, hw - 0.1, n).into_iter().enumerate() {
        let c = b.material(&format!("garment_{k}"), pick(rng, UPHOLSTERY), false);
        decal_between(b, [x - 0.03, -hd * 0.9, h * 0.35], [x + 0.03, hd * 0.9, h - 0.05], c);
    }
    collider_between(b, [-hw + 0.07, -hd * 0.9, h * 0.35], [hw - 0.07, hd * 0.9, h - 0.05]);
    0.0
}

pub(crate) const MANNEQUIN: Category = def(
    "mannequin",
    "mannequin",
    &["dress form", "shop dummy", "display dummy", "manikin", "tailor's dummy", "dummy"],
    &["retail", "tall"],
    "a shop mannequin: a torso on a pole and round base",
    &["figure", "display"],
    Kind::Fixture,
    PlacementKind::Floor,
    false,
    // Dress forms: 35–45 cm shoulders, 150–175 cm tall on the stand.
    &size3(0.42, 0.35, 1.6, 0.8, 1.15, 0.05),
    build_mannequin,
);

fn build_mannequin(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let skin =
        b.material("body", pick(rng, &[[0.95, 0.93, 0.9, 1.0], [0.15, 0.15, 0.16, 1.0], [0.85, 0.75, 0.6, 1.0]]), true);
    let stand = b.material("stand", pick(rng, STEEL), false);
    let r = w.min(d) / 2.0;
    round_solid(b, 0, [0.0, 0.0], r * 0.8, 0.0, 0.03, stand);
    round_solid(b, 0, [0.0, 0.0], 0.012, 0.029, h * 0.45, stand);
    let torso = revolve(
        &[
            [0.0, 0.0],
            [0.75, 0.0],
            [0.85, 0.15],
            [0.65, 0.45],
            [0.9, 0.75],
            [1.0, 0.88],
            [0.25, 0.95],
            [0.2, 1.0],
            [0.0, 1.0],
        ]
        .map(|[a, z]| [a * w / 2.0, z * h * 0.55]),
        ROUND,
    );
    b.visual_mesh_on(0, &super::forms::stretch_y(torso, d / w), Pose::from_pos([0.0, 0.0, h * 0.45]), skin);
    collider_between(b, [-w / 2.0, -d / 2.0, h * 0.45], [w / 2.0, d / 2.0, h]);
    0.0
}

pub(crate) const DISPLAY_CASE: Category = def(
    "display_case",
    "display case",
    &[
        "glass display case",
        "showcase",
        "display counter",
        "vitrine",
        "pastry case",
        "bakery case",
        "glass counter",
        "jewelry case",
    ],
    &["retail", "cafe", "furniture", "surface", "storage"],
    "a glass-topped shop counter with lit shelves of goods inside",
    &["counter", "cabinet", "furniture", "display"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Shop display counters: 100–180 × 50–60 × 90–100 cm.
    &size3(1.2, 0.55, 0.95, 0.75, 1.5, 0.05),
    build_display_case,
);

fn build_display_case(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = if rng.chance(0.5) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", rgba, true);
    let glass = b.material("glass", [0.7, 0.82, 0.86, 1.0], false);
    let goods = b.material("goods", pick(rng, PLASTIC), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let base = slab(b, [-hw, -hd, 0.0], [hw, hd, h * 0.45], body);
    // Glass walls around a lit shelf, a glass top.
    let t = 0.01;
    slab(b, [-hw, hd - t, base - 0.001], [hw, hd, h - t], glass);
    slab(b, [-hw, -hd, base - 0.001], [hw, -hd + t, h - t], glass);
    for (x0, x1) in [(-hw, -hw + t), (hw - t, hw)] {
        slab(b, [x0, -hd + t - 0.001, base - 0.001], [x1, hd - t + 0.001, h - t], glass);
    }
    let top = slab(b, [-hw, -hd, h - t - 0.001], [hw, hd, h], glass);
    for x in spread(-hw + 0.1, hw - 0.1, 5) {
        decal_between(b, [x - 0.05, -0.08, base], [x + 0.05, 0.08, base + 0.06], goods);
    }
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    b.surface("shelf", base, [-hw + t, -hd + t], [hw - t, hd - t], Some(h - t - base - 0.01));
    0.0
}

pub(crate) const KITCHEN_SCALE: Category = def(
    "kitchen_scale",
    "kitchen scale",
    &[
        "food scale",
        "shop scale",
        "counter scale",
        "postal scale",
        "weighing scales",
        "kitchen scales",
        "digital kitchen scale",
    ],
    &["kitchen", "retail", "cafe", "tabletop", "small", "graspable"],
    "a flat digital kitchen scale with a weighing platform and a display",
    &["scale", "device"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Salter / OXO kitchen scales: 18–24 × 15–20 × 2–4 cm.
    &size3(0.21, 0.17, 0.03, 0.7, 1.6, 0.06),
    build_kitchen_scale,
);

fn build_kitchen_scale(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material(
        "body",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.15, 0.15, 0.16, 1.0], [0.75, 0.76, 0.78, 1.0]]),
        true,
    );
    let screen = b.material("display", [0.1, 0.3, 0.35, 1.0], false);
    let top = rounded_box(b, [0.0, 0.0], w, d, 0.0, h, 0.02, body);
    decal_between(b, [-w * 0.25, d / 2.0 - 0.025, h - 0.001], [w * 0.25, d / 2.0 - 0.008, h + 0.001], screen);
    b.surface("platform", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    0.6
}

pub(crate) const WHEELCHAIR: Category = def(
    "wheelchair",
    "wheelchair",
    &["wheel chair", "manual wheelchair", "transport chair", "invalid chair"],
    &["hospital", "care", "seating", "vehicle"],
    "a folding manual wheelchair: a seat and back between two large wheels",
    &["chair", "seat", "vehicle"],
    Kind::Vehicle,
    PlacementKind::Floor,
    false,
    // Standard manual wheelchairs: 63–68 × 100–110 × 90–95 cm, seat at 48–50 cm.
    &size3(0.65, 1.05, 0.92, 0.85, 1.15, 0.04),
    build_wheelchair,
);

fn build_wheelchair(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let frame = b.material("frame", pick(rng, STEEL), false);
    let seat = b.material("seat", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.15, 0.25, 0.5, 1.0]]), true);
    let tyre = b.material("tyres", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let rw = 0.3f64.min(h * 0.33);
    let sh = 0.49f64.min(h * 0.6);
    // The big wheels at the back third, the castors at the front, the seat between.
    let yw = -hd + rw + 0.05;
    for s in [-1.0, 1.0] {
        let x = s * (hw - 0.02);
        b.visual(Shape::Cylinder { radius: rw, half_height: 0.018 }, along([x, yw, rw], Axis::X), tyre);
        collider_between(b, [x - 0.02, yw - rw * 0.7, 0.0], [x + 0.02, yw + rw * 0.7, rw * 2.0]);
        decal_between(b, [x - 0.03 * s - 0.01, hd - 0.16, 0.0], [x - 0.03 * s + 0.01, hd - 0.04, 0.12], tyre);
        collider_between(b, [x - 0.03 * s - 0.01, hd - 0.16, 0.0], [x - 0.03 * s + 0.01, hd - 0.04, 0.12]);
        slab(b, [x - 0.03 * s - 0.012, -hd + 0.05, 0.119], [x - 0.03 * s + 0.012, hd - 0.05, sh - 0.04], frame);
    }
    let top = slab(b, [-hw + 0.06, -hd + 0.2, sh - 0.05], [hw - 0.06, hd - 0.15, sh], seat);
    slab(b, [-hw + 0.06, -hd + 0.14, sh - 0.051], [hw - 0.06, -hd + 0.2, h - 0.06], seat);
    for s in [-1.0, 1.0] {
        let x = s * (hw - 0.08);
        slab(b, [x - 0.012, -hd, h - 0.05], [x + 0.012, -hd + 0.2, h], frame);
    }
    // Footrests reaching the front.
    slab(b, [-hw + 0.08, hd - 0.12, 0.12], [hw - 0.08, hd, 0.15], frame);
    b.surface("seat", top, [-hw + 0.06, -hd + 0.2], [hw - 0.06, hd - 0.15], None);
    0.0
}

pub(crate) const EXAM_TABLE: Category = def(
    "exam_table",
    "examination couch",
    &[
        "examination table",
        "treatment couch",
        "medical couch",
        "doctor's table",
        "massage table",
        "treatment table",
        "exam couch",
    ],
    &["hospital", "care", "furniture", "surface"],
    "a padded examination couch on a steel frame with a raised head section",
    &["table", "couch", "furniture", "bed"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Examination couches: 180–195 × 60–70 × 70–80 cm.
    &[
        ParamDef::new("width", 1.85, 1.6, 2.0, 0.03, "along X"),
        ParamDef::new("depth", 0.65, 0.55, 0.75, 0.04, "along Y"),
        ParamDef::new("height", 0.95, 0.75, 1.1, 0.04, "floor to the top of the head section"),
    ],
    build_exam_table,
);

fn build_exam_table(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let pad = b.material(
        "padding",
        pick(rng, &[[0.25, 0.45, 0.55, 1.0], [0.15, 0.15, 0.16, 1.0], [0.85, 0.86, 0.86, 1.0]]),
        true,
    );
    let frame = b.material("frame", pick(rng, &[[0.93, 0.93, 0.91, 1.0], [0.66, 0.68, 0.7, 1.0]]), false);
    let paper = b.material("paper", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top_z = h * 0.75;
    super::kit::four_legs(b, w - 0.04, d - 0.04, top_z - 0.1, 0.04, 0.0, frame);
    slab(b, [-hw + 0.02, -hd + 0.02, top_z - 0.1], [hw - 0.02, hd - 0.02, top_z - 0.08], frame);
    let top = slab(b, [-hw + 0.5, -hd, top_z - 0.081], [hw, hd, top_z], pad);
    // The head section at −X, rising towards the end.
    let wedge = super::shapes::prism_xz(
        &[[-hw, top_z - 0.1], [-hw + 0.501, top_z - 0.1], [-hw + 0.501, top_z], [-hw, h]],
        -hd,
        hd,
    );
    b.visual_mesh_on(0, &wedge, Pose::IDENTITY, pad);
    collider_between(b, [-hw, -hd, top_z - 0.1], [-hw + 0.501, hd, top_z]);
    collider_between(b, [-hw, -hd, top_z - 0.001], [-hw + 0.2, hd, h]);
    decal_between(b, [-hw + 0.55, -hd * 0.8, top_z - 0.001], [hw - 0.05, hd * 0.8, top_z + 0.001], paper);
    b.surface("couch", top, [-hw + 0.5, -hd], [hw, hd], None);
    0.0
}

pub(crate) const WALKER: Category = def(
    "walker",
    "walking frame",
    &["zimmer frame", "walking aid", "rollator", "mobility walker"],
    &["hospital", "care", "home"],
    "a lightweight aluminium walking frame on four legs",
    &["frame", "mobility aid", "medical equipment"],
    Kind::Fixture,
    PlacementKind::Floor,
    false,
    // Walking frames: 55–65 × 45–55 × 80–95 cm.
    &size3(0.6, 0.5, 0.88, 0.85, 1.15, 0.04),
    build_walker,
);

fn build_walker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let alu = b.material("frame", pick(rng, &[[0.75, 0.76, 0.78, 1.0], [0.3, 0.4, 0.6, 1.0]]), true);
    let grips = b.material("grips", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    for (x, y) in [(-hw, -hd), (hw, -hd), (-hw, hd), (hw, hd)] {
        let (x0, x1) = super::kit::ordered(x, x - x.signum() * 0.025);
        let (y0, y1) = super::kit::ordered(y, y - y.signum() * 0.025);
        slab(b, [x0, y0, 0.0], [x1, y1, h - 0.03], alu);
    }
    for s in [-1.0, 1.0] {
        let x = s * (hw - 0.0125);
        slab(b, [x - 0.0125, -hd + 0.02, h - 0.031], [x + 0.0125, hd - 0.02, h], alu);
        decal_between(b, [x - 0.016, -hd * 0.3, h - 0.035], [x + 0.016, hd * 0.5, h + 0.003], grips);
    }
    slab(b, [-hw + 0.02, hd - 0.0225, h * 0.55], [hw - 0.02, hd - 0.0025, h * 0.55 + 0.025], alu);
    0.0
}

pub(crate) const PILL_BOTTLE: Category = def(
    "pill_bottle",
    "pill bottle",
    &[
        "medicine bottle",
        "pill container",
        "prescription bottle",
        "vitamin bottle",
        "medicine",
        "pills",
        "tablets",
        "vial",
    ],
    &["hospital", "pharmacy", "home", "tabletop", "small", "graspable", "round"],
    "a small plastic pill bottle with a white cap and a label",
    &["bottle", "container", "medical supply"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Prescription vials: 3.5–5 cm across, 7–10 cm tall.
    &[
        ParamDef::new("width", 0.042, 0.025, 0.07, 0.1, "diameter"),
        ParamDef::new("depth", 0.042, 0.025, 0.07, 0.1, "diameter (as width)"),
        ParamDef::new("height", 0.08, 0.04, 0.13, 0.1, "to the top of the cap"),
    ],
    build_pill_bottle,
);

fn build_pill_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let body =
        b.material("body", pick(rng, &[[0.9, 0.55, 0.15, 1.0], [0.95, 0.95, 0.94, 1.0], [0.45, 0.3, 0.2, 1.0]]), true);
    let cap = b.material("cap", LABEL_WHITE, false);
    let label = b.material("label", [0.97, 0.97, 0.96, 1.0], false);
    let zc = h * 0.8;
    round_solid(b, 0, [0.0, 0.0], r, 0.0, zc, body);
    round_solid(b, 0, [0.0, 0.0], r * 1.02, zc - 0.001, h, cap);
    lathe(b, 0, [0.0, 0.0], r + 0.0006, zc * 0.2, zc * 0.55, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], label);
    0.04
}

pub(crate) const FIRST_AID_KIT: Category = def(
    "first_aid_kit",
    "first aid kit",
    &["first-aid kit", "medical kit", "med kit", "first aid box", "emergency kit", "first aid case"],
    &["hospital", "home", "office", "safety", "tabletop", "small", "graspable"],
    "a green or red first aid case with a white cross and a handle",
    &["box", "case", "container", "medical supply"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // First aid cases: 25–30 × 8–12 × 18–22 cm.
    &size3(0.27, 0.1, 0.2, 0.7, 1.5, 0.06),
    build_first_aid_kit,
);

fn build_first_aid_kit(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let case = b.material("case", pick(rng, &[[0.1, 0.55, 0.25, 1.0], [0.8, 0.1, 0.08, 1.0]]), true);
    let cross = b.material("cross", LABEL_WHITE, false);
    let hh = h * 0.85;
    rounded_box(b, [0.0, 0.0], w, d, 0.0, hh, 0.015, case);
    let c = hh * 0.4;
    decal_between(
        b,
        [-c * 0.15, d / 2.0 - 0.001, hh / 2.0 - c / 2.0],
        [c * 0.15, d / 2.0 + 0.0015, hh / 2.0 + c / 2.0],
        cross,
    );
    decal_between(
        b,
        [-c / 2.0, d / 2.0 - 0.0005, hh / 2.0 - c * 0.15],
        [c / 2.0, d / 2.0 + 0.001, hh / 2.0 + c * 0.15],
        cross,
    );
    decal_between(b, [-w * 0.2, -0.01, hh - 0.002], [w * 0.2, 0.01, h], case);
    collider_between(b, [-w * 0.2, -0.01, hh - 0.002], [w * 0.2, 0.01, h]);
    0.9
}

pub(crate) const SHARPS_CONTAINER: Category = def(
    "sharps_container",
    "sharps container",
    &["sharps bin", "needle disposal box", "sharps box", "biohazard bin", "clinical waste bin", "medical waste bin"],
    &["hospital", "lab", "care", "tabletop", "small", "hazard"],
    "a yellow sharps bin with a red lid",
    &["bin", "container", "medical supply"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Sharps bins 2.5–7 l: 18–25 × 12–18 × 20–28 cm.
    &size3(0.2, 0.15, 0.24, 0.7, 1.6, 0.06),
    build_sharps_container,
);

fn build_sharps_container(p: &Params, _rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", [0.96, 0.8, 0.1, 1.0], true);
    let lid = b.material("lid", SIGNAL_RED, false);
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h * 0.82], body);
    slab(b, [-w / 2.0, -d / 2.0, h * 0.82 - 0.001], [w / 2.0, d / 2.0, h], lid);
    0.35
}

pub(crate) const ERLENMEYER_FLASK: Category = def(
    "erlenmeyer_flask",
    "erlenmeyer flask",
    &["conical flask", "flask", "lab flask", "titration flask", "volumetric flask", "round-bottom flask"],
    &["lab", "tabletop", "small", "graspable", "round", "container"],
    "a conical glass laboratory flask with a narrow neck",
    &["glassware", "vessel", "container", "flask"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // DURAN conical flasks: 250 ml 8.5 × 14.5 cm, 500 ml 10.5 × 18 cm.
    &[
        ParamDef::new("width", 0.085, 0.05, 0.14, 0.1, "base diameter"),
        ParamDef::new("depth", 0.085, 0.05, 0.14, 0.1, "base diameter (as width)"),
        ParamDef::new("height", 0.145, 0.09, 0.23, 0.1, "height"),
    ],
    build_erlenmeyer_flask,
);

fn build_erlenmeyer_flask(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let glass = b.material("glass", LAB_GLASS, true);
    let liquid = b.material(
        "liquid",
        pick(rng, &[[0.3, 0.55, 0.85, 1.0], [0.85, 0.3, 0.3, 1.0], [0.4, 0.75, 0.35, 1.0], [0.95, 0.85, 0.3, 1.0]]),
        false,
    );
    let rn = (r * 0.3).max(0.011);
    let zn = h * 0.7;
    b.visual_mesh_on(0, &revolve(&[[0.0, 0.0], [r, 0.0], [rn, zn], [rn, h], [0.0, h]], ROUND), Pose::IDENTITY, glass);
    let zl = h * 0.3;
    let rl = r - (r - rn) * zl / zn;
    b.visual_mesh_on(
        0,
        &revolve(&[[0.0, 0.0005], [r - 0.002, 0.0005], [rl - 0.002, zl], [0.0, zl]], ROUND),
        Pose::IDENTITY,
        liquid,
    );
    round_collider(b, 0, [0.0, 0.0], r, 0.0, zn * 0.45);
    round_collider(b, 0, [0.0, 0.0], (r + rn) / 2.0, zn * 0.45, zn);
    round_collider(b, 0, [0.0, 0.0], rn, zn, h);
    0.15 + r * r * h * 1500.0
}

pub(crate) const GRADUATED_CYLINDER: Category = def(
    "graduated_cylinder",
    "graduated cylinder",
    &["measuring cylinder", "graduated tube", "mixing cylinder"],
    &["lab", "tabletop", "small", "graspable", "container"],
    "a tall narrow glass measuring cylinder on a hexagonal foot",
    &["glassware", "vessel", "container", "cylinder"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 100 ml cylinders: 3 cm tube on a 7–8 cm foot, 25 cm tall.
    &[
        ParamDef::new("width", 0.075, 0.05, 0.1, 0.06, "foot across"),
        ParamDef::new("depth", 0.075, 0.05, 0.1, 0.06, "foot across (as width)"),
        ParamDef::new("height", 0.25, 0.15, 0.45, 0.08, "height"),
    ],
    build_graduated_cylinder,
);

fn build_graduated_cylinder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let glass = b.material("glass", LAB_GLASS, true);
    let foot = b.material("foot", pick(rng, &[[0.2, 0.45, 0.85, 1.0], LAB_GLASS, [0.95, 0.95, 0.94, 1.0]]), false);
    let marks = b.material("marks", INK, false);
    let r = (w.min(d) * 0.22).max(0.012);
    b.visual_mesh_on(0, &sw_geom::cylinder_mesh(w.min(d) / 2.0, 0.006, 6), Pose::from_pos([0.0, 0.0, 0.006]), foot);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, 0.012]);
    vessel_collider(b, [0.0, 0.0], r, r, 0.003, 0.012, 0.0, h, 8);
    let tube = revolve(&[[0.0, 0.011], [r, 0.011], [r, h], [r - 0.0015, h], [r - 0.0015, 0.014], [0.0, 0.014]], ROUND);
    b.visual_mesh_on(0, &tube, Pose::IDENTITY, glass);
    for z in spread(h * 0.15, h * 0.9, 6) {
        decal_between(b, [-0.004, r - 0.0004, z], [0.004, r + 0.0008, z + 0.0012], marks);
    }
    0.1 + h * 0.3
}

pub(crate) const PETRI_DISH: Category = def(
    "petri_dish",
    "petri dish",
    &["culture dish", "cell culture dish", "agar plate", "petri plate"],
    &["lab", "tabletop", "small", "graspable", "round"],
    "a shallow round glass or plastic dish with a lid and agar inside",
    &["dish", "labware", "container"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Standard Petri dishes: 90 × 15 mm (100 × 15, 60 × 15).
    &[
        ParamDef::new("width", 0.09, 0.05, 0.15, 0.06, "diameter"),
        ParamDef::new("depth", 0.09, 0.05, 0.15, 0.06, "diameter (as width)"),
        ParamDef::new("height", 0.015, 0.01, 0.025, 0.1, "height with the lid"),
    ],
    build_petri_dish,
);

fn build_petri_dish(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let plastic = b.material("dish", LAB_GLASS, true);
    let agar =
        b.material("agar", pick(rng, &[[0.95, 0.85, 0.55, 1.0], [0.85, 0.35, 0.3, 1.0], [0.9, 0.9, 0.75, 1.0]]), false);
    round_solid(b, 0, [0.0, 0.0], r, 0.0, h, plastic);
    lathe(b, 0, [0.0, 0.0], r * 0.95, h * 0.1, h * 0.5, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], agar);
    0.02
}

pub(crate) const PIPETTE: Category = def(
    "pipette",
    "pipette",
    &["micropipette", "pipettor", "pasteur pipette", "dropper", "eppendorf pipette"],
    &["lab", "tabletop", "small", "graspable"],
    "a hand-held micropipette lying on the bench",
    &["lab equipment", "instrument", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Eppendorf Research plus / Gilson: 25–28 cm long with a tip, 3–4 cm grip.
    &[
        ParamDef::new("width", 0.26, 0.15, 0.3, 0.05, "length"),
        ParamDef::new("depth", 0.035, 0.02, 0.045, 0.06, "grip width"),
        ParamDef::new("height", 0.035, 0.02, 0.045, 0.06, "grip thickness"),
    ],
    build_pipette,
);

fn build_pipette(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.3, 0.45, 0.75, 1.0]]), true);
    let plunger = b.material(
        "plunger",
        pick(rng, &[[0.2, 0.45, 0.8, 1.0], [0.85, 0.25, 0.2, 1.0], [0.95, 0.8, 0.2, 1.0]]),
        false,
    );
    let tip = b.material("tip", [0.85, 0.88, 0.9, 1.0], false);
    long_item(
        b,
        &[
            Seg {
                x0: -w / 2.0,
                x1: -w / 2.0 + w * 0.28 + 0.002,
                width: d * 0.25,
                height: h * 0.25,
                round: true,
                material: tip,
            },
            Seg { x0: -w / 2.0 + w * 0.28, x1: w / 2.0 - w * 0.12, width: d, height: h, round: false, material: body },
            Seg {
                x0: w / 2.0 - w * 0.12 - 0.002,
                x1: w / 2.0,
                width: d * 0.5,
                height: h * 0.5,
                round: true,
                material: plunger,
            },
        ],
    );
    0.1
}

/// A benchtop instrument: a box housing with a panel on its front (+Y) and knobs.
fn instrument_box(b: &mut AssetBuilder, rng: &mut Rng, w: f64, d: f64, h: f64) -> (usize, f64) {
    let body = b.material("housing", pick(rng, LAB_WHITE), true);
    let panel = b.material(
        "panel",
        pick(rng, &[[0.2, 0.35, 0.55, 1.0], [0.25, 0.25, 0.27, 1.0], [0.55, 0.2, 0.2, 1.0]]),
        false,
    );
    let knob = b.material("knobs", INK, false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], body);
    decal_between(b, [-w * 0.45, d / 2.0 - 0.001, h * 0.1], [w * 0.45, d / 2.0 + 0.002, h * 0.55], panel);
    knobs(b, &[-w * 0.25, w * 0.25], d / 2.0 - 0.008, h * 0.32, (h * 0.12).min(0.02), knob);
    (body, top)
}

pub(crate) const HOT_PLATE: Category = def(
    "hot_plate",
    "hotplate stirrer",
    &["magnetic stirrer", "hot plate stirrer", "stirring hotplate", "lab hot plate", "stir plate"],
    BENCHTOP,
    "a laboratory hotplate stirrer: a square ceramic top on a housing with two knobs",
    &["lab equipment", "equipment", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // IKA C-MAG / Corning PC-420: 18–28 × 28–38 × 10–12 cm.
    &size3(0.2, 0.3, 0.11, 0.8, 1.3, 0.05),
    build_hot_plate,
);

fn build_hot_plate(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let ceramic = b.material("plate", [0.92, 0.92, 0.9, 1.0], false);
    let body = b.material("housing", pick(rng, LAB_WHITE), true);
    let knob = b.material("knobs", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw, hd, h - 0.012], body);
    let y1 = -hd + w.min(d) - 0.01;
    let top = slab(b, [-hw + 0.01, -hd + 0.01, h - 0.0125], [hw - 0.01, y1, h], ceramic);
    knobs(b, &[-hw * 0.5, hw * 0.5], hd - 0.012, (h - 0.012) / 2.0, (h * 0.15).min(0.018), knob);
    b.surface("plate", top, [-hw + 0.01, -hd + 0.01], [hw - 0.01, y1], None);
    3.5
}

pub(crate) const LAB_BALANCE: Category = def(
    "lab_balance",
    "analytical balance",
    &["balance", "precision balance", "laboratory scale", "lab scale", "weighing balance"],
    BENCHTOP,
    "an analytical balance with a glass draft shield over its weighing pan",
    &["lab equipment", "instrument", "scale"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Mettler Toledo / Sartorius analytical balances: 20–23 × 35–45 × 30–35 cm.
    &size3(0.22, 0.4, 0.32, 0.8, 1.3, 0.05),
    build_lab_balance,
);

fn build_lab_balance(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("housing", pick(rng, LAB_WHITE), true);
    let glass = b.material("shield", [0.75, 0.85, 0.88, 1.0], false);
    let screen = b.material("display", [0.1, 0.25, 0.3, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.07], body);
    slab(b, [-hw, -hd, 0.069], [hw, -hd + 0.08, h], body);
    slab(b, [-hw, -hd + 0.079, 0.069], [hw, hd - 0.08, h - 0.004], glass);
    decal_between(b, [-hw * 0.7, hd - 0.079, 0.02], [hw * 0.7, hd, 0.065], screen);
    8.0
}

pub(crate) const INCUBATOR: Category = def(
    "incubator",
    "incubator",
    &["lab incubator", "co2 incubator", "culture incubator", "drying oven", "laboratory oven", "benchtop incubator"],
    BENCHTOP,
    "a benchtop laboratory incubator: an insulated box with a door and a control panel",
    &["lab equipment", "equipment", "oven", "appliance"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Memmert / Binder benchtop incubators: 50–60 × 50–60 × 60–75 cm.
    &size3(0.55, 0.55, 0.65, 0.7, 1.3, 0.05),
    build_incubator,
);

fn build_incubator(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material("body", pick(rng, LAB_WHITE), true);
    let door = b.material("door", pick(rng, &[[0.75, 0.76, 0.78, 1.0], [0.9, 0.91, 0.93, 1.0]]), false);
    let panel = b.material("panel", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.04;
    let opening = hd - dt - MOVING_GAP;
    let ph = 0.1f64.min(h * 0.2);
    carcass(b, -hw, hw, -hd, opening, 0.0, h - ph, 0.03, body);
    slab(b, [-hw, -hd, h - ph - 0.001], [hw, hd, h], body);
    decal_between(b, [-hw * 0.6, hd - 0.001, h - ph * 0.8], [hw * 0.6, hd + 0.002, h - ph * 0.2], panel);
    drop_door(b, "door", [-hw + 0.004, hw - 0.004], [0.004, h - ph - 0.004], hd - dt, dt, [door, panel], 5.0);
    (w * d * h * 120.0).clamp(15.0, 60.0)
}

pub(crate) const BUNSEN_BURNER: Category = def(
    "bunsen_burner",
    "bunsen burner",
    &["gas burner", "lab burner", "alcohol burner", "spirit lamp"],
    &["lab", "tabletop", "small", "graspable", "round", "hazard"],
    "a Bunsen burner: a steel tube on a heavy round base with a gas inlet",
    &["burner", "lab equipment"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Bunsen burners: 9–10 cm base, 15–17 cm tall.
    &[
        ParamDef::new("width", 0.095, 0.07, 0.12, 0.05, "base diameter"),
        ParamDef::new("depth", 0.095, 0.07, 0.12, 0.05, "base diameter (as width)"),
        ParamDef::new("height", 0.16, 0.12, 0.2, 0.05, "to the top of the tube"),
    ],
    build_bunsen_burner,
);

fn build_bunsen_burner(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let base = b.material("base", pick(rng, &[[0.15, 0.25, 0.5, 1.0], [0.2, 0.2, 0.21, 1.0]]), true);
    let steel = b.material("tube", pick(rng, STEEL), false);
    round_solid(b, 0, [0.0, 0.0], r, 0.0, 0.02, base);
    round_solid(b, 0, [0.0, 0.0], 0.007, 0.019, h, steel);
    decal_between(b, [0.0, -0.004, 0.025], [r, 0.004, 0.033], steel);
    collider_between(b, [0.0, -0.004, 0.019], [r, 0.004, 0.033]);
    0.35
}

pub(crate) const VORTEX_MIXER: Category = def(
    "vortex_mixer",
    "vortex mixer",
    &["vortexer", "vortex", "tube shaker", "lab shaker", "orbital shaker"],
    BENCHTOP,
    "a small vortex mixer with a rubber cup on top",
    &["lab equipment", "mixer"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Vortex-Genie 2: 13 × 16 × 16 cm.
    &size3(0.13, 0.16, 0.16, 0.8, 1.3, 0.05),
    build_vortex_mixer,
);

fn build_vortex_mixer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let (_, top) = instrument_box(b, rng, w, d, h * 0.7);
    let cup = b.material("cup", INK, false);
    round_solid(b, 0, [0.0, 0.0], (w.min(d) * 0.3).min(0.035), top - 0.001, h, cup);
    3.0
}

pub(crate) const WATER_BATH: Category = def(
    "water_bath",
    "water bath",
    &["lab water bath", "heated bath", "thermostatic bath", "circulating bath"],
    &["lab", "tabletop", "small", "instrument", "open"],
    "a laboratory water bath: a steel tank with a lid in a housing with a control panel",
    &["lab equipment", "equipment", "tank"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Memmert WNB / Grant: 35–60 × 30–40 × 20–30 cm.
    &size3(0.45, 0.32, 0.25, 0.7, 1.4, 0.05),
    build_water_bath,
);

fn build_water_bath(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let (_, top) = instrument_box(b, rng, w, d, h * 0.8);
    let lid = b.material("lid", pick(rng, STEEL), false);
    slab(b, [-w / 2.0 + 0.01, -d / 2.0 + 0.01, top - 0.001], [w / 2.0 - 0.01, d / 2.0 - 0.04, h], lid);
    9.0
}
