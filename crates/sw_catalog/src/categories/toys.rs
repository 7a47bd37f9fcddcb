//! Toys and everyday things people carry: teddy bears, toy cars, rubber ducks, board
//! games, puzzle cubes, stacking rings, dolls, toy chests, sports balls; shoes, boots,
//! shoe boxes, wallets, handbags, suitcases, umbrellas, storage boxes, spray bottles and
//! keys. Sizes from product ranges (FIFA ball sizes, IATA carry-on limits), noted per category.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::forms::{Seg, back_lid, def, ellipsoid, lathe, long_item, rounded_box, size3, spread, whd};
use super::kit::{
    Axis, INK, LABEL_WHITE, PLASTIC, STEEL, WOOD, along, collider_between, decal_between, pick, shade, slab,
};
use super::parts::{MOVING_GAP, round_collider, round_solid};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

const TOY: &[&str] = &["toy", "home", "tabletop", "small", "graspable"];
const CARRIED: &[&str] = &["home", "tabletop", "small", "graspable"];
const BRIGHT: &[[f32; 4]] = &[
    [0.9, 0.15, 0.12, 1.0],
    [0.15, 0.4, 0.85, 1.0],
    [0.98, 0.8, 0.1, 1.0],
    [0.2, 0.65, 0.3, 1.0],
    [0.95, 0.5, 0.1, 1.0],
    [0.6, 0.3, 0.75, 1.0],
];

pub(crate) const TEDDY_BEAR: Category = def(
    "teddy_bear",
    "teddy bear",
    &["teddy", "stuffed animal", "soft toy", "plush toy", "plushie", "stuffed toy", "cuddly toy"],
    TOY,
    "a sitting teddy bear: a round body, a head with ears, arms and legs",
    &["toy", "stuffed animal"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Sitting teddy bears: 20–30 cm tall, 18–25 cm wide, 15–20 cm deep.
    &size3(0.2, 0.17, 0.26, 0.6, 2.0, 0.08),
    build_teddy_bear,
);

fn build_teddy_bear(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let fur =
        pick(rng, &[[0.6, 0.42, 0.25, 1.0], [0.85, 0.72, 0.52, 1.0], [0.95, 0.95, 0.92, 1.0], [0.4, 0.28, 0.18, 1.0]]);
    let body = b.material("fur", fur, true);
    let snout = b.material("snout", shade(fur, 1.25), false);
    let eyes = b.material("eyes", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let rb = (hw * 0.6).min(hd * 0.8);
    let zb = h * 0.55;
    let rh = (h * 0.22).min(hw * 0.55).min(hd * 0.9);
    // The body, legs forward on the floor, the head with ears, the arms at the sides.
    ellipsoid(b, [0.0, -hd * 0.1, zb / 2.0], [rb, rb * 0.85, zb / 2.0], body);
    for s in [-1.0, 1.0] {
        ellipsoid(b, [s * rb * 0.55, hd * 0.45, rb * 0.35], [rb * 0.4, hd * 0.5, rb * 0.35], body);
        let arm = (hw - rb * 0.8) / 2.0;
        ellipsoid(b, [s * (hw - arm), 0.0, zb * 0.55], [arm, rb * 0.3, zb * 0.28], body);
        b.visual(Shape::Sphere { radius: rh * 0.35 }, Pose::from_pos([s * rh * 0.75, 0.0, h - rh * 0.4]), body);
        b.visual(Shape::Sphere { radius: rh * 0.09 }, Pose::from_pos([s * rh * 0.35, rh * 0.85, h - rh * 0.9]), eyes);
    }
    b.visual(Shape::Sphere { radius: rh }, Pose::from_pos([0.0, 0.0, h - rh * 1.05]), body);
    b.visual(Shape::Sphere { radius: rh * 0.3 }, Pose::from_pos([0.0, rh * 0.75, h - rh * 1.3]), snout);
    collider_between(b, [-rb, -hd, 0.0], [rb, hd, zb]);
    collider_between(b, [-hw, -rb * 0.3, zb * 0.3], [hw, rb * 0.3, zb * 0.8]);
    collider_between(b, [-rh, -rh, zb - 0.001], [rh, rh, h]);
    0.25
}

pub(crate) const TOY_CAR: Category = def(
    "toy_car",
    "toy car",
    &["model car", "toy truck", "matchbox car", "die-cast car", "toy vehicle", "rc car", "hot wheels car"],
    TOY,
    "a toy car with four wheels and a cabin",
    &["toy", "model"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Toy cars: 1:64 die-casts 7 cm to 1:24 models 18–20 cm; play cars 15 × 7 × 6 cm.
    &size3(0.15, 0.07, 0.06, 0.4, 2.0, 0.08),
    build_toy_car,
);

fn build_toy_car(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let paint = b.material("paint", pick(rng, BRIGHT), true);
    let glass = b.material("windows", [0.2, 0.25, 0.3, 1.0], false);
    let tyre = b.material("wheels", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = (h * 0.22).min(hw * 0.35);
    for x in [-hw * 0.62, hw * 0.62] {
        for y in [-hd + 0.004, hd - 0.004] {
            b.visual(Shape::Cylinder { radius: r, half_height: 0.004 }, along([x, y, r], Axis::Y), tyre);
        }
        collider_between(b, [x - r, -hd, 0.0], [x + r, hd, r * 2.0]);
    }
    slab(b, [-hw, -hd + 0.009, r * 0.8], [hw, hd - 0.009, h * 0.6], paint);
    slab(b, [-hw * 0.45, -hd + 0.012, h * 0.6 - 0.001], [hw * 0.3, hd - 0.012, h], paint);
    decal_between(b, [-hw * 0.4, -hd + 0.011, h * 0.65], [hw * 0.25, hd - 0.011, h * 0.95], glass);
    (w * d * h * 300.0).max(0.03)
}

pub(crate) const RUBBER_DUCK: Category = def(
    "rubber_duck",
    "rubber duck",
    &["rubber duckie", "bath duck", "toy duck", "squeaky duck"],
    TOY,
    "a yellow rubber bath duck",
    &["toy"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Classic bath ducks: 8–10 × 7–8 × 8–9 cm.
    &size3(0.095, 0.075, 0.085, 0.6, 2.0, 0.06),
    build_rubber_duck,
);

fn build_rubber_duck(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let yellow =
        b.material("rubber", pick(rng, &[[0.98, 0.85, 0.1, 1.0], [0.98, 0.85, 0.1, 1.0], [0.95, 0.5, 0.6, 1.0]]), true);
    let beak = b.material("beak", [0.95, 0.45, 0.08, 1.0], false);
    let eyes = b.material("eyes", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    ellipsoid(b, [-hw * 0.15, 0.0, h * 0.3], [hw * 0.85, hd, h * 0.3], yellow);
    let rh = (h * 0.22).min(hd * 0.8).min(hw * 0.65);
    b.visual(Shape::Sphere { radius: rh }, Pose::from_pos([hw * 0.3, 0.0, h - rh]), yellow);
    ellipsoid(b, [hw * 0.72, 0.0, h - rh * 1.1], [hw * 0.25, rh * 0.45, rh * 0.2], beak);
    b.visual(
        Shape::Sphere { radius: rh * 0.15 },
        Pose::from_pos([hw * 0.3 + rh * 0.7, rh * 0.45, h - rh * 0.75]),
        eyes,
    );
    collider_between(b, [-hw, -hd, 0.0], [hw * 0.7, hd, h * 0.6]);
    collider_between(b, [hw * 0.3 - rh, -rh, h * 0.6 - 0.001], [hw, rh, h]);
    0.04
}

pub(crate) const BOARD_GAME: Category = def(
    "board_game",
    "board game",
    &[
        "game box",
        "boxed game",
        "jigsaw puzzle",
        "puzzle box",
        "monopoly",
        "chess set",
        "box of games",
        "gameboard",
        "game board",
    ],
    TOY,
    "a boxed board game lying flat",
    &["game", "toy", "box"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Board game boxes: 27 × 27 × 5.5 cm (Catan 30 × 30 × 7.5, Monopoly 40 × 27 × 5).
    &[
        ParamDef::new("width", 0.4, 0.2, 0.45, 0.12, "along X"),
        ParamDef::new("depth", 0.27, 0.2, 0.35, 0.08, "along Y"),
        ParamDef::new("height", 0.055, 0.03, 0.1, 0.15, "thickness"),
    ],
    build_board_game,
);

fn build_board_game(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let lid = b.material("lid", pick(rng, BRIGHT), true);
    let art = b.material("art", pick(rng, &[LABEL_WHITE, [0.1, 0.1, 0.11, 1.0], [0.95, 0.85, 0.6, 1.0]]), false);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], lid);
    decal_between(b, [-w * 0.35, -d * 0.3, h - 0.001], [w * 0.35, d * 0.1, h + 0.001], art);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    (w * d * h * 250.0).max(0.2)
}

pub(crate) const PUZZLE_CUBE: Category = def(
    "puzzle_cube",
    "puzzle cube",
    &["rubik's cube", "rubiks cube", "magic cube", "speed cube", "rubik cube"],
    &["toy", "home", "tabletop", "small", "graspable", "uniform"],
    "a 3 by 3 twisty puzzle cube with coloured stickers",
    &["toy", "puzzle", "cube"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Rubik's Cube 3×3: 5.7 cm.
    &[
        ParamDef::new("width", 0.057, 0.04, 0.09, 0.03, "side"),
        ParamDef::new("depth", 0.057, 0.04, 0.09, 0.03, "side (as width)"),
        ParamDef::new("height", 0.057, 0.04, 0.09, 0.03, "side (as width)"),
    ],
    build_puzzle_cube,
);

fn build_puzzle_cube(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (s, _, _) = whd(p);
    let body = b.material("body", pick(rng, &[[0.08, 0.08, 0.09, 1.0], [0.95, 0.95, 0.94, 1.0]]), true);
    slab(b, [-s / 2.0, -s / 2.0, 0.0], [s / 2.0, s / 2.0, s], body);
    let cell = s / 3.0;
    let faces: [([f64; 3], usize, [f32; 4]); 3] = [
        ([0.0, 0.0, 1.0], 2, [0.95, 0.95, 0.94, 1.0]),
        ([0.0, 1.0, 0.0], 1, [0.9, 0.15, 0.12, 1.0]),
        ([1.0, 0.0, 0.0], 0, [0.15, 0.55, 0.25, 1.0]),
    ];
    for (k, (_, axis, rgba)) in faces.iter().enumerate() {
        let m = b.material(&format!("stickers_{k}"), *rgba, false);
        for i in 0..3 {
            for j in 0..3 {
                let (u, v) = (-s / 2.0 + cell * (i as f64 + 0.5), -s / 2.0 + cell * (j as f64 + 0.5));
                let half = cell * 0.42;
                let (min, max) = match axis {
                    2 => ([u - half, v - half, s - 0.0005], [u + half, v + half, s + 0.001]),
                    1 => (
                        [u - half, s / 2.0 - 0.0005, v + s / 2.0 - half],
                        [u + half, s / 2.0 + 0.001, v + s / 2.0 + half],
                    ),
                    _ => (
                        [s / 2.0 - 0.0005, u - half, v + s / 2.0 - half],
                        [s / 2.0 + 0.001, u + half, v + s / 2.0 + half],
                    ),
                };
                decal_between(b, min, max, m);
            }
        }
    }
    0.09 * (s / 0.057).powi(3)
}

pub(crate) const STACKING_RINGS: Category = def(
    "stacking_rings",
    "stacking rings",
    &["ring stacker", "stacking toy", "ring tower", "rainbow stacker", "stacking cups"],
    &["toy", "home", "tabletop", "small", "graspable", "round"],
    "a baby's stacking toy: coloured rings of decreasing size on a post",
    &["toy"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Fisher-Price Rock-a-Stack: 13 cm base, 22 cm tall.
    &[
        ParamDef::new("width", 0.13, 0.08, 0.18, 0.06, "base diameter"),
        ParamDef::new("depth", 0.13, 0.08, 0.18, 0.06, "base diameter (as width)"),
        ParamDef::new("height", 0.22, 0.12, 0.3, 0.06, "height"),
    ],
    build_stacking_rings,
);

fn build_stacking_rings(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, h) = whd(p);
    let r = w / 2.0;
    let base = b.material("base", pick(rng, BRIGHT), true);
    round_solid(b, 0, [0.0, 0.0], r, 0.0, h * 0.12, base);
    let n = 5;
    let step = (h * 0.8) / n as f64;
    for k in 0..n {
        let m = b.material(&format!("ring_{k}"), BRIGHT[k % BRIGHT.len()], false);
        let rr = r * (1.0 - 0.13 * k as f64);
        let z0 = h * 0.12 + step * k as f64;
        let ring =
            revolve(&super::shapes::rounded_ring_profile(rr * 0.25, rr, z0, z0 + step * 0.96, step * 0.4), ROUND);
        b.visual_mesh_on(0, &ring, Pose::IDENTITY, m);
    }
    round_collider(b, 0, [0.0, 0.0], r * 0.75, h * 0.12 - 0.001, h * 0.92);
    lathe(b, 0, [0.0, 0.0], r * 0.22, h * 0.9, h * 0.1, &[[0.0, 0.0], [1.0, 0.0], [0.6, 1.0], [0.0, 1.0]], base);
    round_collider(b, 0, [0.0, 0.0], r * 0.2, h * 0.9, h);
    0.3
}

pub(crate) const DOLL: Category = def(
    "doll",
    "doll",
    &["baby doll", "fashion doll", "barbie", "action figure", "figurine", "toy figure", "rag doll"],
    TOY,
    "a doll lying on its back",
    &["toy", "figure"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Fashion dolls 29–30 cm; baby dolls 30–45 cm.
    &size3(0.3, 0.08, 0.05, 0.4, 1.6, 0.08),
    build_doll,
);

fn build_doll(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let dress = b.material("clothes", pick(rng, BRIGHT), true);
    let skin = b.material(
        "skin",
        pick(rng, &[[0.95, 0.8, 0.68, 1.0], [0.72, 0.52, 0.38, 1.0], [0.5, 0.34, 0.24, 1.0]]),
        false,
    );
    let hair = b.material(
        "hair",
        pick(rng, &[[0.95, 0.82, 0.45, 1.0], [0.25, 0.15, 0.08, 1.0], [0.1, 0.08, 0.07, 1.0]]),
        false,
    );
    let head = w * 0.17;
    long_item(
        b,
        &[
            Seg::flat(-w / 2.0, -w / 2.0 + w * 0.38, d * 0.55, h * 0.6, skin),
            Seg::flat(-w / 2.0 + w * 0.38 - 0.002, w / 2.0 - head, d, h * 0.8, dress),
            Seg { x0: w / 2.0 - head - 0.003, x1: w / 2.0, width: head.min(d), height: h, round: true, material: skin },
        ],
    );
    decal_between(
        b,
        [w / 2.0 - head * 0.6, -head.min(d) * 0.45, h * 0.3],
        [w / 2.0 + 0.003, head.min(d) * 0.45, h + 0.002],
        hair,
    );
    0.2
}

pub(crate) const TOY_CHEST: Category = def(
    "toy_chest",
    "toy chest",
    &["toy box", "toybox", "storage chest", "blanket chest", "trunk", "chest", "ottoman chest"],
    &["furniture", "home", "toy", "storage", "container"],
    "a wooden chest for toys with a lid that lifts open",
    &["chest", "box", "container", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // Toy chests: 70–90 × 40–45 × 45–50 cm.
    &size3(0.8, 0.42, 0.48, 0.75, 1.4, 0.06),
    build_toy_chest,
);

fn build_toy_chest(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let rgba = if rng.chance(0.5) {
        pick(rng, WOOD)
    } else {
        pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.55, 0.7, 0.85, 1.0], [0.9, 0.65, 0.7, 1.0]])
    };
    let wood = b.material("wood", rgba, true);
    let trim = b.material("trim", shade(rgba, 0.8), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = 0.018;
    let lid_t = 0.025;
    let rim = h - lid_t - MOVING_GAP;
    let floor = slab(b, [-hw, -hd, 0.0], [hw, hd, 0.05], wood);
    for (y0, y1) in [(-hd, -hd + t), (hd - t, hd)] {
        slab(b, [-hw, y0, 0.049], [hw, y1, rim], wood);
    }
    for (x0, x1) in [(-hw, -hw + t), (hw - t, hw)] {
        slab(b, [x0, -hd + t * 0.5, 0.048], [x1, hd - t * 0.5, rim], wood);
    }
    decal_between(b, [-hw * 0.2, hd - 0.001, rim - 0.06], [hw * 0.2, hd + 0.002, rim - 0.04], trim);
    back_lid(b, "lid", [-hw, hw], [-hd, hd], rim + MOVING_GAP, lid_t, wood, (w * d * 8.0).max(1.5));
    b.surface(
        "inside",
        floor,
        [-hw + t + 0.02, -hd + t + 0.02],
        [hw - t - 0.02, hd - t - 0.02],
        Some(rim - floor - 0.02),
    );
    0.0
}

pub(crate) const SPORTS_BALL: Category = def(
    "sports_ball",
    "sports ball",
    &[
        "football",
        "soccer ball",
        "basketball",
        "volleyball",
        "beach ball",
        "beachball",
        "rugby ball",
        "netball",
        "handball",
        "bowling ball",
        "medicine ball",
    ],
    &["toy", "home", "sport", "graspable", "uniform", "round"],
    "a size 5 football",
    &["ball", "toy", "sports equipment"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // FIFA size 5 footballs: 22 cm; basketballs (size 7) 24 cm; volleyballs 21 cm.
    &[
        ParamDef::new("width", 0.22, 0.15, 0.3, 0.05, "diameter"),
        ParamDef::new("depth", 0.22, 0.15, 0.3, 0.05, "diameter (as width)"),
        ParamDef::new("height", 0.22, 0.15, 0.3, 0.05, "diameter (as width)"),
    ],
    build_sports_ball,
);

fn build_sports_ball(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, _, _) = whd(p);
    let r = w / 2.0;
    let (main, seam) = pick2(rng);
    let skin = b.material("skin", main, true);
    let panels = b.material("panels", seam, false);
    b.visual(Shape::Sphere { radius: r }, Pose::from_pos([0.0, 0.0, r]), skin);
    for (x, y, z) in
        [(0.0, 0.0, 1.0), (0.0, 0.0, -1.0), (1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0)]
    {
        b.visual(
            Shape::Sphere { radius: r * 0.25 },
            Pose::from_pos([x * r * 0.78, y * r * 0.78, r + z * r * 0.78]),
            panels,
        );
    }
    // A ball rests on a point: it collides as a sphere (and a real ball rolls), with a
    // small flat at the bottom so that it stays where it is put.
    b.collision_on(0, Shape::Sphere { radius: r }, Pose::from_pos([0.0, 0.0, r]));
    let f = r * 0.3;
    collider_between(b, [-f, -f, 0.0], [f, f, r]);
    0.43 * (w / 0.22).powi(2)
}

fn pick2(rng: &mut Rng) -> ([f32; 4], [f32; 4]) {
    let pairs: &[([f32; 4], [f32; 4])] = &[
        (LABEL_WHITE, [0.08, 0.08, 0.09, 1.0]),
        ([0.9, 0.45, 0.12, 1.0], [0.1, 0.1, 0.1, 1.0]),
        ([0.95, 0.95, 0.9, 1.0], [0.15, 0.35, 0.75, 1.0]),
        ([0.95, 0.85, 0.2, 1.0], [0.15, 0.35, 0.75, 1.0]),
    ];
    rng.pick(pairs).copied().unwrap_or((LABEL_WHITE, INK))
}

pub(crate) const SHOE: Category = def(
    "shoe",
    "shoe",
    &[
        "sneaker",
        "trainer",
        "running shoe",
        "sports shoe",
        "loafer",
        "dress shoe",
        "slipper",
        "sandal",
        "pair of shoes",
    ],
    CARRIED,
    "a single sneaker or shoe",
    &["footwear", "clothing"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // Adult shoes (EU 42): 29–31 × 10–11.5 × 10–12 cm.
    &size3(0.3, 0.11, 0.11, 0.6, 1.2, 0.06),
    build_shoe,
);

pub(crate) fn build_shoe(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let upper = b.material(
        "upper",
        pick(
            rng,
            &[
                [0.95, 0.95, 0.94, 1.0],
                [0.1, 0.1, 0.11, 1.0],
                [0.2, 0.3, 0.55, 1.0],
                [0.45, 0.3, 0.2, 1.0],
                [0.8, 0.15, 0.12, 1.0],
            ],
        ),
        true,
    );
    let sole = b.material(
        "sole",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0], [0.55, 0.4, 0.25, 1.0]]),
        false,
    );
    let laces = b.material("laces", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    // The sole, the toe box at +X and the heel counter with its opening at −X.
    rounded_box(b, [0.0, 0.0], w, d, 0.0, 0.025, hd * 0.9, sole);
    rounded_box(b, [hw * 0.25, 0.0], w * 0.75, d * 0.92, 0.024, h * 0.55, hd * 0.8, upper);
    rounded_box(b, [-hw * 0.55, 0.0], w * 0.45, d * 0.9, 0.024, h, hd * 0.8, upper);
    decal_between(b, [-hw * 0.2, -hd * 0.3, h * 0.55 - 0.002], [hw * 0.3, hd * 0.3, h * 0.55 + 0.004], laces);
    0.35
}

pub(crate) const BOOT: Category = def(
    "boot",
    "boot",
    &[
        "ankle boot",
        "work boot",
        "rain boot",
        "wellington boot",
        "wellie",
        "welly",
        "wellies",
        "wellington",
        "hiking boot",
        "snow boot",
    ],
    CARRIED,
    "a single ankle boot standing upright",
    &["footwear", "clothing", "shoe"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // Ankle and work boots (EU 42): 30–32 × 11–12 × 15–25 cm; wellingtons 35–40 cm tall.
    &size3(0.3, 0.115, 0.2, 0.7, 1.9, 0.06),
    build_boot,
);

fn build_boot(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let leather = b.material(
        "leather",
        pick(rng, &[[0.45, 0.3, 0.18, 1.0], [0.1, 0.1, 0.11, 1.0], [0.2, 0.35, 0.2, 1.0], [0.7, 0.55, 0.35, 1.0]]),
        true,
    );
    let sole = b.material("sole", [0.12, 0.12, 0.13, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, 0.03, hd * 0.9, sole);
    rounded_box(b, [hw * 0.25, 0.0], w * 0.75, d * 0.92, 0.029, 0.1f64.min(h * 0.5), hd * 0.8, leather);
    rounded_box(b, [-hw * 0.5, 0.0], w * 0.5, d * 0.9, 0.029, h, hd * 0.7, leather);
    0.7
}

pub(crate) const SHOE_BOX: Category = def(
    "shoe_box",
    "shoe box",
    &["shoebox", "box of shoes", "storage box for shoes"],
    &["home", "retail", "container", "tabletop", "graspable"],
    "a cardboard shoe box with a lid",
    &["box", "container", "package"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Adult shoe boxes: 33–35 × 19–22 × 11–13 cm.
    &size3(0.34, 0.2, 0.12, 0.6, 1.4, 0.05),
    build_shoe_box,
);

fn build_shoe_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let box_ = b.material(
        "box",
        pick(rng, &[[0.95, 0.6, 0.1, 1.0], [0.15, 0.15, 0.16, 1.0], [0.95, 0.95, 0.94, 1.0], [0.76, 0.6, 0.42, 1.0]]),
        true,
    );
    let lid = b.material(
        "lid",
        pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.8, 0.15, 0.12, 1.0], [0.95, 0.95, 0.94, 1.0]]),
        false,
    );
    slab(b, [-w / 2.0 + 0.003, -d / 2.0 + 0.003, 0.0], [w / 2.0 - 0.003, d / 2.0 - 0.003, h * 0.8], box_);
    let top = slab(b, [-w / 2.0, -d / 2.0, h * 0.8 - 0.001], [w / 2.0, d / 2.0, h], lid);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    0.9
}

pub(crate) const WALLET: Category = def(
    "wallet",
    "wallet",
    &["purse", "billfold", "card holder", "coin purse", "pocketbook"],
    CARRIED,
    "a folded leather wallet lying flat",
    &["accessory", "case"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Bifold wallets: 11–12 × 9–10 × 1.5–2.5 cm.
    &size3(0.115, 0.095, 0.02, 0.7, 1.6, 0.06),
    build_wallet,
);

fn build_wallet(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let leather = b.material(
        "leather",
        pick(rng, &[[0.45, 0.3, 0.18, 1.0], [0.1, 0.1, 0.11, 1.0], [0.55, 0.15, 0.12, 1.0]]),
        true,
    );
    let stitch = b.material("stitching", [0.85, 0.8, 0.65, 1.0], false);
    rounded_box(b, [0.0, 0.0], w, d, 0.0, h, 0.01, leather);
    decal_between(
        b,
        [-w / 2.0 + 0.005, -d / 2.0 + 0.005, h - 0.0005],
        [w / 2.0 - 0.005, -d / 2.0 + 0.007, h + 0.0005],
        stitch,
    );
    0.1
}

pub(crate) const HANDBAG: Category = def(
    "handbag",
    "handbag",
    &["hand bag", "tote bag", "shoulder bag", "shopping bag", "carrier bag", "messenger bag"],
    CARRIED,
    "a handbag standing upright with two handles",
    &["bag", "container", "accessory"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Handbags and totes: 30–40 × 12–16 × 25–30 cm (40 with the handles).
    &size3(0.34, 0.14, 0.36, 0.6, 1.4, 0.06),
    build_handbag,
);

fn build_handbag(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let leather = b.material(
        "leather",
        pick(
            rng,
            &[
                [0.45, 0.3, 0.18, 1.0],
                [0.1, 0.1, 0.11, 1.0],
                [0.55, 0.15, 0.12, 1.0],
                [0.85, 0.75, 0.6, 1.0],
                [0.2, 0.3, 0.5, 1.0],
            ],
        ),
        true,
    );
    let straps = b.material("straps", pick(rng, &[[0.3, 0.2, 0.12, 1.0], [0.08, 0.08, 0.09, 1.0]]), false);
    let body = h * 0.72;
    let outline = [[-w / 2.0, 0.0], [w / 2.0, 0.0], [w * 0.4, body], [-w * 0.4, body]];
    b.visual_mesh_on(0, &super::shapes::prism_xz(&outline, -d / 2.0, d / 2.0), Pose::IDENTITY, leather);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, body * 0.6]);
    collider_between(b, [-w * 0.42, -d / 2.0, body * 0.6 - 0.001], [w * 0.42, d / 2.0, body]);
    for s in [-1.0, 1.0] {
        decal_between(b, [-w * 0.22, s * d * 0.3 - 0.006, body - 0.002], [-w * 0.18, s * d * 0.3 + 0.006, h], straps);
        decal_between(b, [w * 0.18, s * d * 0.3 - 0.006, body - 0.002], [w * 0.22, s * d * 0.3 + 0.006, h], straps);
        decal_between(b, [-w * 0.21, s * d * 0.3 - 0.0055, h - 0.012], [w * 0.21, s * d * 0.3 + 0.0055, h], straps);
    }
    collider_between(b, [-w * 0.22, -d * 0.3 - 0.006, body - 0.002], [w * 0.22, d * 0.3 + 0.006, h]);
    0.8
}

pub(crate) const SUITCASE: Category = def(
    "suitcase",
    "suitcase",
    &["luggage", "carry-on", "trolley case", "travel case", "rolling suitcase", "carry-on bag", "valise"],
    &["home", "container", "graspable"],
    "a hard-shell carry-on suitcase standing on its wheels with the handle down",
    &["case", "luggage", "container", "bag"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // IATA carry-on limit 55 × 40 × 23 cm (standing: 40 wide, 23 deep, 55 tall).
    &size3(0.4, 0.23, 0.58, 0.8, 1.4, 0.05),
    build_suitcase,
);

fn build_suitcase(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let shell = pick(
        rng,
        &[
            [0.1, 0.1, 0.11, 1.0],
            [0.15, 0.3, 0.55, 1.0],
            [0.7, 0.15, 0.12, 1.0],
            [0.75, 0.76, 0.78, 1.0],
            [0.3, 0.5, 0.45, 1.0],
        ],
    );
    let body = b.material("shell", shell, true);
    let ribs = b.material("ribs", shade(shell, 0.8), false);
    let wheels = b.material("wheels", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let zb = 0.05;
    for x in [-hw + 0.03, hw - 0.03] {
        for y in [-hd + 0.03, hd - 0.03] {
            slab(b, [x - 0.02, y - 0.02, 0.0], [x + 0.02, y + 0.02, zb], wheels);
        }
    }
    rounded_box(b, [0.0, 0.0], w, d, zb - 0.001, h - 0.03, 0.04, body);
    for x in spread(-hw * 0.6, hw * 0.6, 3) {
        decal_between(b, [x - 0.01, hd - 0.003, zb + 0.03], [x + 0.01, hd + 0.002, h - 0.06], ribs);
    }
    decal_between(b, [-hw * 0.3, -hd + 0.02, h - 0.031], [hw * 0.3, -hd + 0.05, h], wheels);
    collider_between(b, [-hw * 0.3, -hd + 0.02, h - 0.031], [hw * 0.3, -hd + 0.05, h]);
    3.2
}

pub(crate) const UMBRELLA: Category = def(
    "umbrella",
    "umbrella",
    &["brolly", "parasol", "folding umbrella", "golf umbrella", "walking umbrella"],
    CARRIED,
    "a closed umbrella lying down: a furled canopy on a shaft with a hooked handle",
    &["accessory"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Stick umbrellas: 85–95 cm closed, 5–6 cm across the furled canopy.
    &flat3_um(0.9, 0.09, 0.055),
    build_umbrella,
);

const fn flat3_um(l: f64, w: f64, t: f64) -> [ParamDef; 3] {
    [
        ParamDef::new("width", l, 0.25, 1.1, 0.06, "length along X"),
        ParamDef::new("depth", w, 0.05, 0.12, 0.06, "handle hook across Y"),
        ParamDef::new("height", t, 0.04, 0.07, 0.06, "thickness lying"),
    ]
}

fn build_umbrella(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let canopy = b.material(
        "canopy",
        pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.15, 0.3, 0.6, 1.0], [0.75, 0.12, 0.1, 1.0], [0.2, 0.45, 0.3, 1.0]]),
        true,
    );
    let handle = b.material("handle", pick(rng, &[[0.45, 0.3, 0.18, 1.0], [0.1, 0.1, 0.11, 1.0]]), false);
    let hook = w * 0.12;
    long_item(
        b,
        &[
            Seg { x0: -w / 2.0, x1: w / 2.0 - hook * 1.5, width: h.min(d), height: h, round: true, material: canopy },
            Seg {
                x0: w / 2.0 - hook * 1.5 - 0.002,
                x1: w / 2.0 - 0.02,
                width: 0.022,
                height: 0.022,
                round: true,
                material: handle,
            },
        ],
    );
    decal_between(b, [w / 2.0 - 0.025, -d / 2.0, 0.0], [w / 2.0, d / 2.0, 0.022], handle);
    collider_between(b, [w / 2.0 - 0.025, -d / 2.0, 0.0], [w / 2.0, d / 2.0, 0.022]);
    0.45
}

pub(crate) const STORAGE_BOX: Category = def(
    "storage_box",
    "storage box",
    &[
        "plastic storage box",
        "storage container",
        "lidded box",
        "plastic box",
        "storage tub",
        "stackable box",
        "really useful box",
    ],
    &["home", "office", "storage", "container", "graspable"],
    "a clear plastic storage box with a coloured lid",
    &["box", "container"],
    Kind::Container,
    PlacementKind::OnSurface,
    true,
    // Really Useful Box 35 l: 48 × 39 × 31 cm; 9 l: 39.5 × 25.5 × 15.5 cm.
    &size3(0.48, 0.39, 0.31, 0.5, 1.5, 0.05),
    build_storage_box,
);

fn build_storage_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let clear = b.material("body", [0.82, 0.86, 0.88, 1.0], false);
    let lid = b.material("lid", pick(rng, PLASTIC), true);
    let contents = b.material("contents", pick(rng, &[[0.6, 0.5, 0.4, 1.0], [0.4, 0.5, 0.6, 1.0]]), false);
    slab(b, [-w / 2.0 + 0.01, -d / 2.0 + 0.01, 0.0], [w / 2.0 - 0.01, d / 2.0 - 0.01, h - 0.02], clear);
    decal_between(b, [-w * 0.35, -d * 0.3, 0.01], [w * 0.2, d * 0.3, h * 0.5], contents);
    let top = slab(b, [-w / 2.0, -d / 2.0, h - 0.021], [w / 2.0, d / 2.0, h], lid);
    b.surface("lid", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    (w * d * h * 30.0).max(0.5)
}

pub(crate) const SPRAY_BOTTLE: Category = def(
    "spray_bottle",
    "spray bottle",
    &[
        "spray cleaner",
        "trigger spray",
        "plant mister",
        "atomizer",
        "cleaning spray",
        "window cleaner",
        "aerosol can",
        "spray can",
        "cleansing agent",
        "cleaning agent",
        "household cleaner",
        "surface cleaner",
    ],
    &["home", "cleaning", "tabletop", "small", "graspable"],
    "a trigger spray bottle of cleaner",
    &["bottle", "container", "cleaning product"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // 500–750 ml trigger sprays: 9–11 × 6–7 × 24–28 cm.
    &size3(0.1, 0.065, 0.26, 0.6, 1.2, 0.05),
    build_spray_bottle,
);

fn build_spray_bottle(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let body = b.material(
        "body",
        pick(rng, &[[0.3, 0.6, 0.9, 1.0], [0.95, 0.95, 0.94, 1.0], [0.4, 0.75, 0.4, 1.0], [0.95, 0.6, 0.7, 1.0]]),
        true,
    );
    let head = b.material(
        "trigger",
        pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0], [0.2, 0.4, 0.8, 1.0]]),
        false,
    );
    let (hw, hd) = (w / 2.0, d / 2.0);
    let zb = h * 0.72;
    // An oval body: turned, then stretched to the depth.
    let r = hw * 0.75;
    let prof: Vec<[f64; 2]> = [[0.0, 0.0], [0.95, 0.0], [1.0, 0.05], [1.0, 0.85], [0.4, 1.0], [0.0, 1.0]]
        .iter()
        .map(|[a, z]| [a * r, z * zb])
        .collect();
    b.visual_mesh_on(0, &super::forms::stretch_y(revolve(&prof, ROUND), hd / r), Pose::IDENTITY, body);
    collider_between(b, [-r, -hd, 0.0], [r, hd, zb]);
    // The trigger head: a block over the neck with the nozzle towards +X.
    slab(b, [-r * 0.5, -r * 0.45, zb - 0.002], [hw, r * 0.45, h], head);
    decal_between(b, [r * 0.2, -0.006, zb - 0.04], [r * 0.6, 0.006, zb], head);
    slab(b, [-hw, -0.008, zb * 0.5], [-r + 0.002, 0.008, zb * 0.55], body);
    0.6
}

pub(crate) const KEYS: Category = def(
    "keys",
    "keys",
    &["key", "bunch of keys", "keyring", "key ring", "car key", "house key", "set of keys", "key fob"],
    CARRIED,
    "a bunch of keys on a ring, lying flat",
    &["accessory"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Keys 5–7 cm on a 3 cm ring: a bunch 9–11 × 5–7 × 1–1.5 cm.
    &size3(0.1, 0.06, 0.012, 0.6, 1.5, 0.06),
    build_keys,
);

fn build_keys(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let metal = b.material("keys", pick(rng, &[[0.78, 0.68, 0.35, 1.0], [0.75, 0.76, 0.78, 1.0]]), true);
    let ring = b.material("ring", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let rr = hd.min(w * 0.2);
    let loop_ = revolve(&super::shapes::rounded_ring_profile(rr * 0.8, rr, 0.0, 0.003, 0.0), 16);
    b.visual_mesh_on(0, &loop_, Pose::from_pos([-hw + rr, 0.0, 0.0]), ring);
    collider_between(b, [-hw, -rr, 0.0], [-hw + 2.0 * rr, rr, 0.003]);
    for (k, y) in spread(-hd * 0.7, hd * 0.7, 3).into_iter().enumerate() {
        let z0 = 0.003 * k as f64;
        decal_between(b, [-hw + rr * 1.4, y - 0.009, z0], [hw, y + 0.009, z0 + 0.003], metal);
    }
    collider_between(b, [-hw + rr * 1.4, -hd * 0.7 - 0.009, 0.0], [hw, hd * 0.7 + 0.009, h]);
    0.05
}
