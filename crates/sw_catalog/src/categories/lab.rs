//! Laboratory equipment: fume hoods, microscopes, centrifuges, test-tube racks and
//! beakers.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{
    Axis, DARK, GLASS, INK, LABEL_WHITE, SIGNAL_GREEN, collider_between, decal_between, pick, rod, shade, slab,
};
use super::parts::{round_collider, vessel_collider};
use super::shapes::{ROUND, prism, revolve, rounded_rect};
use crate::{Category, Kind, ParamDef, Params};

/// Lab equipment enclosures: white and light grey enamel.
const LAB_WHITE: &[[f32; 4]] = &[[0.93, 0.93, 0.91, 1.0], [0.86, 0.87, 0.88, 1.0], [0.9, 0.91, 0.93, 1.0]];
/// Laboratory glass, drawn opaque.
const LAB_GLASS: [f32; 4] = [0.78, 0.86, 0.9, 1.0];

pub(crate) const FUME_HOOD: Category = Category {
    name: "fume_hood",
    display: "fume hood",
    synonyms: &[
        "fume cupboard",
        "chemical hood",
        "laboratory hood",
        "lab hood",
        "fume cabinet",
        "extraction hood",
        "biosafety cabinet",
    ],
    tags: &["lab", "tall", "surface", "hazard", "ventilation"],
    description: "a laboratory fume hood with a sliding glass sash",
    is_a: &["enclosure", "lab equipment"],
    kind: Kind::Fixture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.5, 1.0, 2.4, 0.12, "along X"),
        ParamDef::new("depth", 0.85, 0.7, 1.0, 0.05, "along Y"),
        ParamDef::new("height", 2.4, 2.1, 2.8, 0.04, "floor to the top of the exhaust duct"),
        ParamDef::new("work_height", 0.9, 0.75, 1.0, 0.03, "floor to the work surface"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_fume_hood,
};

/// A base cabinet, a chamber (sides, back, ceiling) over a chemical-resistant work
/// surface, a glass sash half down at the front, and an exhaust duct on the roof. The
/// work surface is a support surface up to the chamber ceiling.
fn build_fume_hood(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let wh = p.get("work_height").min(h - 1.0);
    let body = b.material("body", pick(rng, LAB_WHITE), true);
    let top = b.material("work_surface", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.3, 0.32, 0.33, 1.0]]), false);
    let glass = b.material("sash", GLASS, false);
    let frame = b.material("frame", pick(rng, DARK), false);
    let duct = b.material("duct", [0.7, 0.71, 0.73, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let side = 0.1;
    let roof = h - 0.3;
    // Base cabinet with doors drawn on, then the work surface.
    slab(b, [-hw, -hd, 0.0], [hw, hd - 0.02, wh - 0.03], body);
    for (x0, x1) in [(-hw + 0.01, -0.003), (0.003, hw - 0.01)] {
        decal_between(b, [x0, hd - 0.021, 0.08], [x1, hd - 0.018, wh - 0.06], body);
    }
    let work = slab(b, [-hw + side, -hd, wh - 0.03], [hw - side, hd, wh], top);
    // The chamber: side posts, back, ceiling with the sash housing over the front.
    for (x0, x1) in [(-hw, -hw + side), (hw - side, hw)] {
        slab(b, [x0, -hd, wh - 0.031], [x1, hd, roof], body);
    }
    slab(b, [-hw + side * 0.5, -hd, wh - 0.001], [hw - side * 0.5, -hd + 0.05, roof - 0.1], body);
    let sash_y = hd - 0.06;
    slab(b, [-hw + side * 0.5, -hd, roof - 0.2], [hw - side * 0.5, hd, roof], body);
    // The sash: a framed glass pane, lowered to leave a 45 cm opening.
    let (sz0, sz1) = (wh + 0.45, roof - 0.2);
    slab(b, [-hw + side, sash_y, sz0], [hw - side, sash_y + 0.03, sz1 + 0.001], frame);
    decal_between(
        b,
        [-hw + side + 0.03, sash_y + 0.029, sz0 + 0.03],
        [hw - side - 0.03, sash_y + 0.032, sz1 - 0.03],
        glass,
    );
    // Airfoil sill and a control display on the right post.
    rod(b, [0.0, hd - 0.02, wh + 0.015], 0.015, w - 2.0 * side - 0.02, Axis::X, frame);
    let ink = b.material("display", INK, false);
    decal_between(b, [-hw + 0.02, hd - 0.001, wh + 0.8], [-hw + side - 0.02, hd + 0.002, wh + 0.9], ink);
    // Exhaust duct on the roof.
    let r = (w.min(d) * 0.15).min(0.15);
    slab(b, [-hw + 0.001, -hd + 0.001, roof - 0.001], [hw - 0.001, hd - 0.001, roof + 0.001], body);
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(r, (h - roof) / 2.0, ROUND),
        Pose::from_pos([0.0, -hd * 0.3, (roof + h) / 2.0]),
        duct,
    );
    round_collider(b, 0, [0.0, -hd * 0.3], r, roof, h);
    let clearance = (roof - 0.2) - work;
    b.surface("work_surface", work, [-hw + side, -hd + 0.05], [hw - side, sash_y - 0.01], Some(clearance));
    0.0
}

pub(crate) const MICROSCOPE: Category = Category {
    name: "microscope",
    display: "microscope",
    synonyms: &["light microscope", "compound microscope", "stereo microscope", "lab microscope", "optical microscope"],
    tags: &["lab", "tabletop", "hospital", "small", "instrument"],
    description: "a laboratory light microscope",
    is_a: &["instrument", "lab equipment", "equipment"],
    kind: Kind::SmallAppliance,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.22, 0.16, 0.3, 0.08, "along X"),
        ParamDef::new("depth", 0.3, 0.22, 0.4, 0.08, "along Y"),
        ParamDef::new("height", 0.42, 0.3, 0.5, 0.08, "to the top of the eyepieces"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_microscope,
};

/// A heavy base, the arm at the back, a stage over the base, the head with a revolving
/// nosepiece and two eyepieces leaning back towards the user (+Y).
fn build_microscope(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body = b.material("body", pick(rng, LAB_WHITE), true);
    let black = b.material("optics", shade(pick(rng, DARK), 0.8), false);
    let stage = b.material("stage", [0.2, 0.2, 0.22, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bh = h * 0.1;
    b.visual_mesh_on(0, &prism(&rounded_rect(hw, hd, w * 0.2, 4), 0.0, bh), Pose::IDENTITY, body);
    collider_between(b, [-hw, -hd, 0.0], [hw, hd, bh]);
    // The arm at the back.
    let (ay0, ay1) = (-hd + 0.01, -hd + d * 0.3);
    slab(b, [-w * 0.2, ay0, bh - 0.001], [w * 0.2, ay1, h * 0.8], body);
    // The stage over the middle of the base.
    let sz = h * 0.38;
    slab(b, [-hw * 0.75, ay1 - 0.002, sz - 0.015], [hw * 0.75, hd * 0.6, sz], stage);
    // The head over the stage, the nosepiece under it, the eyepieces on top.
    let (hy0, hy1) = (ay0, hd * 0.2);
    slab(b, [-w * 0.22, hy0, h * 0.62], [w * 0.22, hy1, h * 0.8], body);
    rod(b, [0.0, hd * 0.05, h * 0.56], w * 0.12, h * 0.1, Axis::Z, black);
    for x in [-w * 0.08, w * 0.08] {
        let len = h * 0.24;
        let pose = Pose::from_pos_axis_angle([x, hy1 - 0.02, h * 0.8 + len * 0.35], [1.0, 0.0, 0.0], -0.5);
        b.visual(Shape::Cylinder { radius: 0.014, half_height: len / 2.0 }, pose, black);
    }
    collider_between(b, [-w * 0.15, hy1 - 0.06, h * 0.8 - 0.001], [w * 0.15, hy1 + 0.04, h]);
    // Focus knobs on both sides of the arm.
    rod(b, [0.0, (ay0 + ay1) / 2.0, h * 0.3], 0.025, w * 0.55, Axis::X, black);
    (w * d * h * 220.0).clamp(2.0, 12.0)
}

pub(crate) const CENTRIFUGE: Category = Category {
    name: "centrifuge",
    display: "centrifuge",
    synonyms: &["benchtop centrifuge", "lab centrifuge", "microcentrifuge", "sample centrifuge"],
    tags: &["lab", "tabletop", "hospital", "small", "instrument", "machine"],
    description: "a benchtop laboratory centrifuge",
    is_a: &["lab equipment", "equipment"],
    kind: Kind::SmallAppliance,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.4, 0.22, 0.7, 0.12, "along X"),
        ParamDef::new("depth", 0.5, 0.28, 0.75, 0.1, "along Y"),
        ParamDef::new("height", 0.3, 0.2, 0.5, 0.1, "to the top of the lid"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_centrifuge,
};

/// A rounded body with a domed lid over the rotor chamber and a sloped control panel at
/// the front.
fn build_centrifuge(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body = b.material("body", pick(rng, LAB_WHITE), true);
    let lid =
        b.material("lid", pick(rng, &[[0.3, 0.45, 0.65, 1.0], [0.55, 0.57, 0.6, 1.0], [0.25, 0.26, 0.28, 1.0]]), false);
    let panel = b.material("panel", INK, false);
    let led = b.material("led", SIGNAL_GREEN, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bh = h * 0.8;
    b.visual_mesh_on(0, &prism(&rounded_rect(hw, hd, w * 0.15, 4), 0.0, bh), Pose::IDENTITY, body);
    collider_between(b, [-hw, -hd, 0.0], [hw, hd, bh]);
    let r = (w * 0.42).min(d * 0.35);
    let cy = -hd + d * 0.42;
    let dome =
        revolve(&[[0.0, bh - 0.002], [r, bh - 0.002], [r, bh + (h - bh) * 0.4], [r * 0.6, h - 0.004], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &dome, Pose::from_pos([0.0, cy, 0.0]), lid);
    round_collider(b, 0, [0.0, cy], r, bh, h);
    let (py0, py1) = (hd - d * 0.22, hd - 0.01);
    decal_between(b, [-hw * 0.7, py0, bh - 0.001], [hw * 0.7, py1, bh + 0.002], panel);
    rod(b, [hw * 0.5, (py0 + py1) / 2.0, bh + 0.003], 0.006, 0.003, Axis::Z, led);
    (w * d * h * 260.0).clamp(3.0, 60.0)
}

pub(crate) const TEST_TUBE_RACK: Category = Category {
    name: "test_tube_rack",
    display: "test tube rack",
    synonyms: &["test-tube rack", "tube rack", "sample rack", "vial rack", "test tube holder"],
    tags: &["lab", "tabletop", "hospital", "small", "graspable"],
    description: "a rack holding test tubes",
    is_a: &["rack", "holder", "lab equipment"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.24, 0.12, 0.4, 0.1, "along X"),
        ParamDef::new("depth", 0.08, 0.05, 0.12, 0.1, "along Y"),
        ParamDef::new("height", 0.14, 0.08, 0.2, 0.1, "to the top of the tubes"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_test_tube_rack,
};

/// A base plate, end posts and a top plate with holes (rings drawn on it), two rows of
/// test tubes with coloured samples and caps in some of them.
fn build_test_tube_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let rack = b.material(
        "rack",
        pick(rng, &[[0.95, 0.95, 0.93, 1.0], [0.2, 0.45, 0.75, 1.0], [0.9, 0.75, 0.15, 1.0], [0.7, 0.72, 0.74, 1.0]]),
        true,
    );
    let glass = b.material("tubes", LAB_GLASS, false);
    let sample = b.material(
        "samples",
        pick(rng, &[[0.8, 0.15, 0.12, 1.0], [0.2, 0.5, 0.85, 1.0], [0.3, 0.7, 0.3, 1.0], [0.95, 0.85, 0.2, 1.0]]),
        false,
    );
    let caps = b.material("caps", pick(rng, &[LABEL_WHITE, [0.85, 0.2, 0.2, 1.0], [0.2, 0.3, 0.8, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let rack_h = h * 0.6;
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.006], rack);
    for (x0, x1) in [(-hw, -hw + 0.008), (hw - 0.008, hw)] {
        slab(b, [x0, -hd + 0.001, 0.0059], [x1, hd - 0.001, rack_h], rack);
    }
    slab(b, [-hw + 0.004, -hd, rack_h - 0.006], [hw - 0.004, hd, rack_h], rack);
    let cols = ((w - 0.02) / 0.022).floor().max(2.0) as usize;
    let pitch = (w - 0.02) / cols as f64;
    let rt = (pitch * 0.36).min(d * 0.2);
    let ys: Vec<f64> = if d > 4.6 * rt { vec![-d * 0.22, d * 0.22] } else { vec![0.0] };
    for (ri, &y) in ys.iter().enumerate() {
        for c in 0..cols {
            let x = -hw + 0.01 + pitch * (c as f64 + 0.5);
            if rng.chance(0.35) {
                continue; // an empty hole
            }
            let top = h - if (ri + c) % 3 == 0 { 0.0 } else { 0.008 };
            let tube =
                revolve(&[[0.0, 0.008], [rt * 0.7, 0.008], [rt, 0.012], [rt, top - 0.008], [0.0, top - 0.008]], 16);
            b.visual_mesh_on(0, &tube, Pose::from_pos([x, y, 0.0]), glass);
            rod(b, [x, y, 0.012 + (top - 0.02) * 0.25], rt + 0.0003, (top - 0.02) * 0.5, Axis::Z, sample);
            rod(b, [x, y, top - 0.004], rt + 0.001, 0.008, Axis::Z, caps);
        }
    }
    // The tubes collide as one box over the rack's top plate.
    collider_between(b, [-hw + 0.008, -hd * 0.9, rack_h], [hw - 0.008, hd * 0.9, h]);
    (0.08 + w * d * 4.0).min(0.6)
}

pub(crate) const BEAKER: Category = Category {
    name: "beaker",
    display: "beaker",
    synonyms: &["glass beaker", "lab beaker", "measuring beaker"],
    tags: &["lab", "tabletop", "small", "graspable", "container", "round", "open"],
    description: "a glass laboratory beaker with a spout",
    is_a: &["vessel", "glassware", "container"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.07, 0.04, 0.15, 0.12, "diameter"),
        ParamDef::new("depth", 0.07, 0.04, 0.15, 0.12, "diameter (as width)"),
        ParamDef::new("height", 0.095, 0.05, 0.2, 0.12, "floor to rim"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_beaker,
};

/// A straight glass beaker with a rim and graduation marks, some liquid inside.
fn build_beaker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let glass = b.material("glass", LAB_GLASS, true);
    let marks = b.material("marks", LABEL_WHITE, false);
    let liquid = b.material(
        "liquid",
        pick(rng, &[[0.3, 0.55, 0.85, 1.0], [0.85, 0.35, 0.2, 1.0], [0.4, 0.75, 0.35, 1.0], [0.9, 0.85, 0.3, 1.0]]),
        false,
    );
    let t = 0.0025;
    let floor = 0.004;
    let mesh = revolve(
        &[
            [0.0, 0.0],
            [r - 0.002, 0.0],
            [r - 0.0015, 0.003],
            [r - 0.0015, h - 0.003],
            [r, h],
            [r - t, h],
            [r - t, floor],
            [0.0, floor],
        ],
        ROUND,
    );
    b.visual_mesh_on(0, &mesh, Pose::IDENTITY, glass);
    let fill = h * rng.range(0.25, 0.6);
    let liquid_mesh = revolve(&[[0.0, floor], [r - t - 0.0004, floor], [r - t - 0.0004, fill], [0.0, fill]], ROUND);
    b.visual_mesh_on(0, &liquid_mesh, Pose::IDENTITY, liquid);
    for k in 1..=4 {
        let z = h * 0.18 * k as f64;
        decal_between(b, [-0.004, r - 0.0016, z], [0.004, r + 0.0004, z + 0.0012], marks);
    }
    vessel_collider(b, [0.0, 0.0], r, r, 0.004, floor, 0.0, h, 16);
    let volume = std::f64::consts::PI * r * r * fill;
    0.05 * (w / 0.07) * (h / 0.095) + volume * 1000.0
}
