//! Greenhouse and farm things: potted plants, planter boxes, seedling trays, hay bales
//! and feed sacks.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape, sphere_mesh};

use super::kit::{WOOD, collider_between, decal_between, ordered, pick, shade, slab};
use super::parts::{round_collider, solid_box};
use super::shapes::{ROUND, prism, revolve, rounded_rect};
use crate::{Category, Kind, ParamDef, Params};

/// Leaf greens, dark to light.
const LEAVES: &[[f32; 4]] =
    &[[0.15, 0.4, 0.15, 1.0], [0.22, 0.52, 0.2, 1.0], [0.3, 0.6, 0.25, 1.0], [0.12, 0.33, 0.18, 1.0]];
/// Terracotta, glazed and plastic pots.
const POTS: &[[f32; 4]] = &[
    [0.72, 0.38, 0.22, 1.0],
    [0.62, 0.32, 0.2, 1.0],
    [0.92, 0.92, 0.9, 1.0],
    [0.2, 0.2, 0.22, 1.0],
    [0.3, 0.45, 0.6, 1.0],
];
const SOIL: [f32; 4] = [0.25, 0.17, 0.1, 1.0];

/// A clump of leaves: overlapping flattened spheres around `center` inside a sphere of
/// radius `r`, seeded.
fn foliage(b: &mut AssetBuilder, rng: &mut Rng, center: [f64; 3], r: f64, n: usize, material: usize) {
    for k in 0..n {
        let a = rng.range(0.0, std::f64::consts::TAU);
        let (rr, lift) = if k == 0 { (0.0, 0.0) } else { (rng.range(0.3, 0.48) * r, rng.range(-0.25, 0.3) * r) };
        let s = if k == 0 { 0.72 * r } else { rng.range(0.42, 0.52) * r };
        let c = [center[0] + rr * a.cos(), center[1] + rr * a.sin(), center[2] + lift];
        let mut m = sphere_mesh(s, 6, 10);
        for v in &mut m.vertices {
            v[2] *= 0.8;
        }
        b.visual_mesh_on(0, &m, Pose::from_pos(c), material);
    }
}

pub(crate) const POTTED_PLANT: Category = Category {
    name: "potted_plant",
    display: "potted plant",
    synonyms: &[
        "plant",
        "house plant",
        "houseplant",
        "pot plant",
        "plant pot",
        "flower pot",
        "planter",
        "potted tree",
        "shrub",
        "bush",
    ],
    tags: &["office", "home", "retail", "agriculture", "greenhouse", "decor", "small", "round"],
    description: "a house plant in a pot",
    is_a: &["plant", "pot"],
    kind: Kind::Plant,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.35, 0.1, 1.2, 0.2, "foliage diameter"),
        ParamDef::new("depth", 0.35, 0.1, 1.2, 0.2, "foliage diameter (as width)"),
        ParamDef::new("height", 0.55, 0.15, 2.2, 0.25, "floor to the top of the leaves"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_potted_plant,
};

/// A tapered pot with a rim and soil, and the plant: a leafy bush on short plants, a stem
/// and a crown on tall ones.
fn build_potted_plant(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let pot = b.material("pot", pick(rng, POTS), true);
    let soil = b.material("soil", SOIL, false);
    let leaves = b.material("leaves", pick(rng, LEAVES), false);
    let leaves2 = b.material("leaves_light", shade(pick(rng, LEAVES), 1.25), false);
    let pr = (r * 0.7).min(h * 0.3);
    let ph = (pr * 1.6).min(h * 0.45);
    let pot_mesh = revolve(
        &[
            [0.0, 0.0],
            [pr * 0.75, 0.0],
            [pr * 0.95, ph - 0.02],
            [pr, ph - 0.02],
            [pr, ph],
            [pr * 0.9, ph],
            [pr * 0.9, ph - 0.015],
            [0.0, ph - 0.015],
        ],
        ROUND,
    );
    b.visual_mesh_on(0, &pot_mesh, Pose::IDENTITY, pot);
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(pr * 0.9 - 0.001, 0.004, ROUND),
        Pose::from_pos([0.0, 0.0, ph - 0.017]),
        soil,
    );
    round_collider(b, 0, [0.0, 0.0], pr * 0.85, 0.0, ph);
    // The plant above the pot, within a cylinder of radius r up to h.
    let tall = h > 3.0 * r && h - ph > 0.4;
    let crown_r = r * 0.92;
    if tall {
        let stem = b.material("stem", [0.35, 0.25, 0.15, 1.0], false);
        let cz = h - crown_r * 0.85;
        b.visual(
            Shape::Cylinder { radius: (r * 0.06).max(0.01), half_height: (cz - ph) / 2.0 + 0.01 },
            Pose::from_pos([0.0, 0.0, (ph + cz) / 2.0]),
            stem,
        );
        foliage(b, rng, [0.0, 0.0, cz], crown_r, 7, leaves);
        foliage(b, rng, [0.0, 0.0, cz + crown_r * 0.2], crown_r * 0.7, 4, leaves2);
        b.collision_on(
            0,
            Shape::Cylinder { radius: 0.03f64.min(pr * 0.5), half_height: (cz - ph) / 2.0 },
            Pose::from_pos([0.0, 0.0, (ph + cz) / 2.0]),
        );
        b.collision_on(
            0,
            Shape::Cylinder { radius: r, half_height: (h - cz) / 2.0 + crown_r * 0.4 },
            Pose::from_pos([0.0, 0.0, (h + cz) / 2.0 - crown_r * 0.4]),
        );
    } else {
        let bush_h = h - ph;
        let cz = ph + bush_h * 0.5;
        let br = (bush_h / 2.0).min(crown_r);
        foliage(b, rng, [0.0, 0.0, cz], br, 8, leaves);
        foliage(b, rng, [0.0, 0.0, cz + br * 0.3], br * 0.6, 4, leaves2);
        b.collision_on(
            0,
            Shape::Cylinder { radius: r, half_height: bush_h / 2.0 - 0.0005 },
            Pose::from_pos([0.0, 0.0, cz + 0.0005]),
        );
    }
    let soil_kg = std::f64::consts::PI * pr * pr * ph * 0.6 * 1100.0;
    (soil_kg + 0.3).clamp(0.3, 150.0)
}

pub(crate) const PLANTER_BOX: Category = Category {
    name: "planter_box",
    display: "planter box",
    synonyms: &[
        "raised bed",
        "window box",
        "window planter",
        "raised garden bed",
        "garden bed",
        "plant bed",
        "grow bed",
        "trough planter",
        "flower box",
    ],
    tags: &["agriculture", "greenhouse", "home", "surface"],
    description: "a raised planter box with plants",
    is_a: &["planter", "container", "box"],
    kind: Kind::Plant,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.2, 0.5, 3.0, 0.15, "along X"),
        ParamDef::new("depth", 0.6, 0.3, 1.2, 0.12, "along Y"),
        ParamDef::new("height", 0.45, 0.2, 0.9, 0.15, "floor to the top of the plants"),
    ],
    movable: false,
    vary_per_instance: true,
    build: build_planter_box,
};

/// A wooden box of stacked boards full of soil, with rows of young plants. The soil is a
/// support surface between the plants' rows.
fn build_planter_box(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let wood = b.material("boards", pick(rng, WOOD), true);
    let soil = b.material("soil", SOIL, false);
    let leaves = b.material("leaves", pick(rng, LEAVES), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bh = h * 0.6;
    let t = 0.04;
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * (hd - t), sy * hd);
        slab(b, [-hw, y0, 0.0], [hw, y1, bh], wood);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * (hw - t), sx * hw);
        slab(b, [x0, -(hd - t * 0.5), 0.0], [x1, hd - t * 0.5, bh], wood);
    }
    let top = solid_box(b, 0, [-hw + t * 0.5, -hd + t * 0.5, 0.0], [hw - t * 0.5, hd - t * 0.5, bh - 0.04], soil);
    // Board seams on the long sides.
    let boards = ((bh / 0.14).round() as usize).max(1);
    for k in 1..boards {
        let z = bh * k as f64 / boards as f64;
        decal_between(b, [-hw - 0.001, -hd - 0.001, z - 0.003], [hw + 0.001, -hd + 0.002, z + 0.003], soil);
    }
    // Two rows of plants along X, leaving the middle strip free.
    let pr = ((h - bh + 0.04) / 2.0).min(hd * 0.3).max(0.03);
    let n = ((w - 2.0 * t) / (2.5 * pr)).floor().max(1.0) as usize;
    for row in [-1.0, 1.0] {
        let y = row * (hd - t - pr);
        for k in 0..n {
            let x = -hw + t + (w - 2.0 * t) * (k as f64 + 0.5) / n as f64;
            foliage(b, rng, [x, y, h - pr], pr, 3, leaves);
        }
        collider_between(b, [-hw + t, y - pr, bh - 0.04], [hw - t, y + pr, h]);
    }
    let strip = (hd - t - 2.0 * pr).max(0.02);
    b.surface("soil", top, [-hw + t, -strip], [hw - t, strip], None);
    0.0
}

pub(crate) const SEEDLING_TRAY: Category = Category {
    name: "seedling_tray",
    display: "seedling tray",
    synonyms: &["seed tray", "plant tray", "propagation tray", "cell tray", "plug tray"],
    tags: &["agriculture", "greenhouse", "tabletop", "small"],
    description: "a tray of seedlings",
    is_a: &["tray", "plant"],
    kind: Kind::Plant,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.54, 0.25, 0.6, 0.05, "along X"),
        ParamDef::new("depth", 0.28, 0.15, 0.4, 0.05, "along Y"),
        ParamDef::new("height", 0.1, 0.05, 0.2, 0.15, "to the top of the seedlings"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_seedling_tray,
};

/// A black plastic tray of cells with soil and a sprout in each.
fn build_seedling_tray(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let tray =
        b.material("tray", pick(rng, &[[0.1, 0.1, 0.11, 1.0], [0.25, 0.4, 0.25, 1.0], [0.3, 0.3, 0.32, 1.0]]), true);
    let soil = b.material("soil", SOIL, false);
    let sprouts = b.material("sprouts", pick(rng, LEAVES), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let th = 0.05f64.min(h * 0.5);
    slab(b, [-hw, -hd, 0.0], [hw, hd, th - 0.008], tray);
    let (cols, rows) = (((w / 0.045) as usize).max(2), ((d / 0.045) as usize).max(2));
    let (cw, cd) = (w / cols as f64, d / rows as f64);
    for i in 0..cols {
        for j in 0..rows {
            let (x, y) = (-hw + cw * (i as f64 + 0.5), -hd + cd * (j as f64 + 0.5));
            decal_between(b, [x - cw * 0.4, y - cd * 0.4, th - 0.0085], [x + cw * 0.4, y + cd * 0.4, th - 0.004], soil);
            let sh = (h - th) * rng.range(0.6, 1.0);
            let leaf = prism(&rounded_rect(cw * 0.3, cd * 0.12, cd * 0.1, 2), 0.0, 0.003);
            b.visual(
                Shape::Box { half: [0.0015, 0.0015, sh / 2.0] },
                Pose::from_pos([x, y, th - 0.004 + sh / 2.0]),
                sprouts,
            );
            b.visual_mesh_on(
                0,
                &leaf,
                Pose::from_pos_yaw([x, y, th - 0.004 + sh - 0.003], rng.range(0.0, std::f64::consts::PI)),
                sprouts,
            );
        }
    }
    // Rim strips around the top of the cells.
    for (y0, y1) in [(-hd, -hd + 0.006), (hd - 0.006, hd)] {
        slab(b, [-hw + 0.0005, y0, th - 0.0081], [hw - 0.0005, y1, th], tray);
    }
    collider_between(b, [-hw + 0.01, -hd + 0.01, th - 0.008], [hw - 0.01, hd - 0.01, h]);
    (w * d * th * 500.0).max(0.2)
}

pub(crate) const HAY_BALE: Category = Category {
    name: "hay_bale",
    display: "hay bale",
    synonyms: &["straw bale", "bale of hay", "hay", "bale", "square bale"],
    tags: &["agriculture", "stackable", "small"],
    description: "a square bale of hay",
    is_a: &["bale", "fodder"],
    kind: Kind::Container,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.9, 0.6, 1.2, 0.1, "along X"),
        ParamDef::new("depth", 0.46, 0.35, 0.6, 0.06, "along Y"),
        ParamDef::new("height", 0.36, 0.3, 0.5, 0.06, "along Z"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_hay_bale,
};

/// A small square bale with two strings around it.
fn build_hay_bale(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let hay =
        b.material("hay", pick(rng, &[[0.85, 0.75, 0.4, 1.0], [0.78, 0.68, 0.35, 1.0], [0.7, 0.65, 0.35, 1.0]]), true);
    let twine =
        b.material("twine", pick(rng, &[[0.9, 0.3, 0.1, 1.0], [0.2, 0.4, 0.7, 1.0], [0.85, 0.8, 0.6, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    b.visual_mesh_on(0, &prism(&rounded_rect(hw, hd, 0.03, 2), 0.0, h), Pose::IDENTITY, hay);
    let top = collider_between(b, [-hw, -hd, 0.0], [hw, hd, h]);
    for x in [-w * 0.25, w * 0.25] {
        decal_between(b, [x - 0.006, -hd - 0.002, h - 0.0005], [x + 0.006, hd + 0.002, h + 0.002], twine);
        decal_between(b, [x - 0.006, hd - 0.0005, 0.001], [x + 0.006, hd + 0.002, h], twine);
    }
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    (w * d * h * 140.0).clamp(5.0, 40.0)
}

pub(crate) const FEED_SACK: Category = Category {
    name: "feed_sack",
    display: "feed sack",
    synonyms: &[
        "sack",
        "bag of feed",
        "feed bag",
        "sandbag",
        "grain sack",
        "cement bag",
        "fertilizer bag",
        "sack of flour",
    ],
    tags: &["agriculture", "warehouse", "stackable", "small"],
    description: "a full sack of feed or flour",
    is_a: &["sack", "bag", "container"],
    kind: Kind::Container,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.65, 0.3, 1.0, 0.1, "along X, lying flat"),
        ParamDef::new("depth", 0.42, 0.25, 0.6, 0.08, "along Y"),
        ParamDef::new("height", 0.14, 0.06, 0.25, 0.15, "thickness"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_feed_sack,
};

/// A filled woven or paper sack lying flat: a pillow with a printed panel.
fn build_feed_sack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let rgba = pick(rng, &[[0.92, 0.9, 0.85, 1.0], [0.8, 0.7, 0.5, 1.0], [0.55, 0.6, 0.45, 1.0]]);
    let sack = b.material("sack", rgba, true);
    let print = b.material(
        "print",
        pick(rng, &[[0.15, 0.45, 0.2, 1.0], [0.75, 0.15, 0.12, 1.0], [0.15, 0.3, 0.6, 1.0]]),
        false,
    );
    let (hw, hd) = (w / 2.0, d / 2.0);
    // Pillow: a thick middle and thinner seams, stacked prisms.
    let layers = [(0.0, 0.25, 0.85), (0.25, 0.75, 1.0), (0.75, 1.0, 0.85)];
    for (k, (f0, f1, s)) in layers.into_iter().enumerate() {
        let (z0, z1) = (h * f0, h * f1);
        let mesh = prism(&rounded_rect(hw * s, hd * s, d * 0.15 * s, 3), z0 - if k > 0 { 0.0005 } else { 0.0 }, z1);
        b.visual_mesh_on(0, &mesh, Pose::IDENTITY, sack);
    }
    let top = collider_between(b, [-hw, -hd, 0.0], [hw, hd, h]);
    decal_between(b, [-hw * 0.5, -hd * 0.5, h - 0.001], [hw * 0.5, hd * 0.5, h + 0.0015], print);
    let a = 0.85;
    b.surface("top", top, [-hw * a * 0.8, -hd * a * 0.8], [hw * a * 0.8, hd * a * 0.8], None);
    (w * d * h * 550.0).clamp(2.0, 50.0)
}
