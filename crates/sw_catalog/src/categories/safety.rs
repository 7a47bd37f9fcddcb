//! Safety equipment: fire extinguishers, eyewash stations, safety fences, welding
//! screens and traffic cones.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{
    Axis, DARK, SAFETY_YELLOW, SIGNAL_GREEN, SIGNAL_RED, STEEL, collider_between, decal_between, pick, rod, shade, slab,
};
use super::parts::{round_collider, solid_box};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const FIRE_EXTINGUISHER: Category = Category {
    name: "fire_extinguisher",
    display: "fire extinguisher",
    synonyms: &[
        "extinguisher",
        "fire extinguisher cylinder",
        "co2 extinguisher",
        "powder extinguisher",
        "foam extinguisher",
    ],
    tags: &["safety", "office", "warehouse", "lab", "kitchen", "workshop", "garage", "small"],
    description: "a red fire extinguisher",
    is_a: &["safety equipment", "cylinder"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.24, 0.21, 0.32, 0.06, "body and lever handle along X"),
        ParamDef::new("depth", 0.16, 0.1, 0.18, 0.08, "body diameter"),
        ParamDef::new("height", 0.6, 0.35, 0.9, 0.1, "to the top of the valve"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_fire_extinguisher,
};

/// A red cylinder with a domed shoulder, a valve with a lever handle over +X, a hose
/// down the front and a label band.
fn build_fire_extinguisher(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = d / 2.0;
    let cx = -(w - d) / 2.0;
    let red = b.material("body", SIGNAL_RED, true);
    let black = b.material("valve", shade(pick(rng, DARK), 0.8), false);
    let label =
        b.material("label", pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.9, 0.8, 0.2, 1.0], [0.15, 0.3, 0.7, 1.0]]), false);
    let zb = h * 0.82;
    let body = revolve(&[[0.0, 0.0], [r * 0.95, 0.0], [r, 0.01], [r, zb - r * 0.6], [r * 0.5, zb], [0.0, zb]], ROUND);
    let at = Pose::from_pos([cx, 0.0, 0.0]);
    b.visual_mesh_on(0, &body, at, red);
    let band =
        revolve(&[[r - 0.001, zb * 0.35], [r + 0.001, zb * 0.35], [r + 0.001, zb * 0.7], [r - 0.001, zb * 0.7]], ROUND);
    b.visual_mesh_on(0, &band, at, label);
    round_collider(b, 0, [cx, 0.0], r, 0.0, zb - r * 0.3);
    // The valve on top, the lever handle reaching out over +X.
    let vr = r * 0.3;
    rod(b, [cx, 0.0, (zb + h) / 2.0], vr, h - zb, Axis::Z, black);
    b.collision_on(
        0,
        Shape::Cylinder { radius: vr, half_height: (h - zb + r * 0.3) / 2.0 },
        Pose::from_pos([cx, 0.0, (zb - r * 0.3 + h) / 2.0]),
    );
    solid_box(b, 0, [cx, -0.012, h - 0.025], [w / 2.0, 0.012, h - 0.012], black);
    solid_box(b, 0, [cx + vr, -0.01, h - 0.05], [w / 2.0 - 0.01, 0.01, h - 0.037], black);
    // The hose down the front.
    rod(b, [cx + r * 0.45, r * 0.6, zb * 0.6], 0.007, zb * 0.6, Axis::Z, black);
    let litres = std::f64::consts::PI * r * r * zb * 1000.0;
    (3.5 + litres * 0.7).min(25.0)
}

pub(crate) const EYEWASH_STATION: Category = Category {
    name: "eyewash_station",
    display: "eyewash station",
    synonyms: &["eye wash station", "eyewash", "eye wash", "emergency eyewash", "safety shower", "emergency shower"],
    tags: &["safety", "lab", "industrial", "plumbing", "round"],
    description: "an emergency eyewash station on a stand",
    is_a: &["safety equipment", "fixture"],
    kind: Kind::Fixture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.4, 0.3, 0.5, 0.08, "bowl diameter"),
        ParamDef::new("depth", 0.4, 0.3, 0.5, 0.08, "bowl diameter (as width)"),
        ParamDef::new("height", 1.1, 0.9, 1.3, 0.05, "to the rim of the bowl"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_eyewash_station,
};

/// A pedestal: a base plate, a yellow pipe column, a green bowl with two spray heads and
/// a push flag, and a sign on a plate.
fn build_eyewash_station(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let yellow = b.material("pipe", SAFETY_YELLOW, true);
    let green = b.material("bowl", SIGNAL_GREEN, false);
    let steel = b.material("base", pick(rng, STEEL), false);
    let white = b.material("sign", [0.95, 0.95, 0.93, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = hw.min(hd);
    let by = 0.0; // the column stands under the bowl's centre
    slab(b, [-hw * 0.6, -hd * 0.6, 0.0], [hw * 0.6, hd * 0.6, 0.012], steel);
    let zb = h - 0.12;
    rod(b, [0.0, by, zb / 2.0], 0.03, zb, Axis::Z, yellow);
    b.collision_on(
        0,
        Shape::Cylinder { radius: 0.03, half_height: zb / 2.0 - 0.006 },
        Pose::from_pos([0.0, by, zb / 2.0 + 0.006]),
    );
    // The bowl: an open dish on the column, its rim at h.
    let bowl = revolve(
        &[
            [0.0, zb],
            [r * 0.3, zb],
            [r, h - 0.01],
            [r, h],
            [r - 0.006, h],
            [r * 0.3 - 0.006, zb + 0.01],
            [0.0, zb + 0.01],
        ],
        ROUND,
    );
    b.visual_mesh_on(0, &bowl, Pose::from_pos([0.0, by, 0.0]), green);
    round_collider(b, 0, [0.0, by], r, zb, h);
    for x in [-r * 0.35, r * 0.35] {
        rod(b, [x, by, zb + 0.05], 0.018, 0.04, Axis::Z, yellow);
    }
    // The push flag in front of the bowl and a sign plate on the column.
    decal_between(b, [-0.06, hd - 0.012, zb - 0.08], [0.06, hd, zb - 0.02], yellow);
    slab(b, [-0.01, 0.0, zb - 0.03], [0.01, hd - 0.012, zb - 0.015], yellow);
    decal_between(b, [-0.08, by + 0.03, zb * 0.55], [0.08, by + 0.032, zb * 0.55 + 0.12], white);
    0.0
}

pub(crate) const SAFETY_FENCE: Category = Category {
    name: "safety_fence",
    display: "safety fence",
    synonyms: &[
        "machine guard",
        "guard fence",
        "mesh fence",
        "robot fence",
        "perimeter guard",
        "safety barrier",
        "wire mesh panel",
        "fence",
    ],
    tags: &["safety", "industrial", "warehouse", "robotics"],
    description: "a wire mesh safety fence panel around machines",
    is_a: &["fence", "barrier", "guard"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 2.0, 0.8, 3.0, 0.1, "one panel with its two posts, along X"),
        ParamDef::new("depth", 0.3, 0.15, 0.5, 0.1, "footprint of the post feet along Y"),
        ParamDef::new("height", 2.0, 1.4, 2.5, 0.05, "floor to the top of the posts"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_safety_fence,
};

/// Two square posts on foot plates and a framed wire-mesh panel between them, the mesh
/// drawn as thin bars.
fn build_safety_fence(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(rng, &[SAFETY_YELLOW, [0.15, 0.15, 0.16, 1.0], [0.95, 0.55, 0.1, 1.0]]);
    let posts = b.material("posts", paint, true);
    let mesh_m = b.material("mesh", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.55, 0.56, 0.58, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let ps = 0.06;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 { (-hw, -hw + ps) } else { (hw - ps, hw) };
        slab(b, [x0, -ps / 2.0, 0.0], [x1, ps / 2.0, h], posts);
        let (f0, f1) = if sx < 0.0 { (-hw, -hw + 0.12f64.min(w * 0.1)) } else { (hw - 0.12f64.min(w * 0.1), hw) };
        slab(b, [f0 - 0.0001 * sx, -hd, 0.0], [f1 + 0.0001 * sx, hd, 0.01], posts);
    }
    // The panel: a frame and the mesh, 10 cm off the floor.
    let (px0, px1, pz0, pz1) = (-hw + ps, hw - ps, 0.1, h - 0.05);
    collider_between(b, [px0, -0.01, pz0], [px1, 0.01, pz1]);
    for (z0, z1) in [(pz0, pz0 + 0.025), (pz1 - 0.025, pz1)] {
        decal_between(b, [px0, -0.012, z0], [px1, 0.012, z1], posts);
    }
    let pitch = 0.05;
    let cols = ((px1 - px0) / pitch) as usize;
    for c in 1..cols {
        let x = px0 + (px1 - px0) * c as f64 / cols as f64;
        decal_between(b, [x - 0.0015, -0.003, pz0 + 0.025], [x + 0.0015, 0.003, pz1 - 0.025], mesh_m);
    }
    let rows = ((pz1 - pz0) / pitch) as usize;
    for r in 1..rows {
        let z = pz0 + (pz1 - pz0) * r as f64 / rows as f64;
        decal_between(b, [px0, -0.0045, z - 0.0015], [px1, -0.0025, z + 0.0015], mesh_m);
    }
    0.0
}

pub(crate) const WELDING_SCREEN: Category = Category {
    name: "welding_screen",
    display: "welding screen",
    synonyms: &[
        "welding curtain",
        "welding partition",
        "weld screen",
        "welding shield",
        "privacy screen",
        "room divider",
        "partition screen",
    ],
    tags: &["safety", "industrial", "workshop", "garage"],
    description: "a welding screen or room divider on feet",
    is_a: &["screen", "partition", "barrier"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.8, 1.0, 2.4, 0.1, "along X"),
        ParamDef::new("depth", 0.6, 0.4, 0.8, 0.1, "foot length along Y"),
        ParamDef::new("height", 1.9, 1.5, 2.2, 0.05, "floor to the top rail"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_welding_screen,
};

/// A tube frame on two feet with a tinted PVC curtain (red, orange or green) and the
/// curtain's hanging rings along the top rail.
fn build_welding_screen(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let frame =
        b.material("frame", pick(rng, &[SAFETY_YELLOW, [0.2, 0.35, 0.65, 1.0], [0.55, 0.56, 0.58, 1.0]]), false);
    let curtain = b.material(
        "curtain",
        pick(rng, &[[0.75, 0.12, 0.08, 1.0], [0.9, 0.45, 0.08, 1.0], [0.1, 0.4, 0.2, 1.0]]),
        true,
    );
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = 0.03;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        slab(b, [x - t / 2.0, -t / 2.0, 0.03], [x + t / 2.0, t / 2.0, h - t + 0.001], frame);
        slab(b, [x - t / 2.0 - 0.0005, -hd, 0.0], [x + t / 2.0 + 0.0005, hd, 0.03], frame);
    }
    slab(b, [-hw, -t / 2.0, h - t], [hw, t / 2.0, h], frame);
    slab(b, [-hw + t, -0.002, 0.15], [hw - t, 0.002, h - t - 0.03], curtain);
    let n = ((w - 2.0 * t) / 0.25) as usize;
    for k in 0..=n {
        let x = -hw + t + 0.02 + (w - 2.0 * t - 0.04) * k as f64 / n.max(1) as f64;
        rod(b, [x, 0.0, h - t - 0.015], 0.012, 0.006, Axis::Y, frame);
    }
    0.0
}

pub(crate) const TRAFFIC_CONE: Category = Category {
    name: "traffic_cone",
    display: "traffic cone",
    synonyms: &["safety cone", "cone", "pylon", "road cone", "warning cone"],
    tags: &["safety", "warehouse", "garage", "small", "round"],
    description: "an orange traffic cone",
    is_a: &["marker", "safety equipment"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.35, 0.2, 0.45, 0.08, "base plate side"),
        ParamDef::new("depth", 0.35, 0.2, 0.45, 0.08, "base plate side (as width)"),
        ParamDef::new("height", 0.7, 0.3, 1.0, 0.12, "to the tip"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_traffic_cone,
};

/// An orange cone with white reflective bands on a square black base.
fn build_traffic_cone(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let orange =
        b.material("cone", pick(rng, &[[0.98, 0.42, 0.05, 1.0], [0.95, 0.3, 0.05, 1.0], [0.95, 0.8, 0.1, 1.0]]), true);
    let base = b.material("base", [0.1, 0.1, 0.11, 1.0], false);
    let white = b.material("bands", [0.96, 0.96, 0.96, 1.0], false);
    let hw = w / 2.0;
    let bt = (h * 0.04).max(0.015);
    slab(b, [-hw, -hw, 0.0], [hw, hw, bt], base);
    let (r0, r1) = (hw * 0.78, hw * 0.12);
    let at = |z: f64| r0 + (r1 - r0) * (z - bt) / (h - bt);
    let cone = revolve(&[[0.0, bt - 0.001], [r0, bt - 0.001], [r1, h - 0.01], [r1 * 0.6, h], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &cone, Pose::IDENTITY, orange);
    for (f0, f1) in [(0.45, 0.55), (0.65, 0.72)] {
        let (z0, z1) = (bt + (h - bt) * f0, bt + (h - bt) * f1);
        let band =
            revolve(&[[at(z0) - 0.004, z0], [at(z0) + 0.0015, z0], [at(z1) + 0.0015, z1], [at(z1) - 0.004, z1]], ROUND);
        b.visual_mesh_on(0, &band, Pose::IDENTITY, white);
    }
    // The cone collides as two stacked cylinders.
    let zm = bt + (h - bt) * 0.5;
    b.collision_on(
        0,
        Shape::Cylinder { radius: at(bt + (h - bt) * 0.25), half_height: (zm - bt) / 2.0 },
        Pose::from_pos([0.0, 0.0, (bt + zm) / 2.0]),
    );
    b.collision_on(
        0,
        Shape::Cylinder { radius: at(zm + (h - zm) * 0.5), half_height: (h - zm) / 2.0 },
        Pose::from_pos([0.0, 0.0, (zm + h) / 2.0]),
    );
    (w * w * 8.0 + h * 2.0).clamp(0.5, 5.0)
}
