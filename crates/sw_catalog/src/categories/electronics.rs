//! Desk electronics: monitors, laptops, keyboards, printers, desk lamps and phones.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{INK, collider_between, decal_between, pick, shade, slab};
use super::shapes::{ROUND, prism, revolve, rounded_rect};
use crate::{Category, Kind, ParamDef, Params};

/// Plastic and aluminium housings.
const HOUSING: &[[f32; 4]] = &[
    [0.12, 0.12, 0.13, 1.0],
    [0.2, 0.21, 0.23, 1.0],
    [0.78, 0.79, 0.8, 1.0],
    [0.9, 0.9, 0.88, 1.0],
    [0.55, 0.56, 0.58, 1.0],
];
/// A dark screen with a slight blue tint.
const SCREEN: [f32; 4] = [0.05, 0.07, 0.1, 1.0];

pub(crate) const MONITOR: Category = Category {
    name: "monitor",
    display: "monitor",
    synonyms: &["computer monitor", "computer screen", "display", "screen", "lcd monitor", "flat screen"],
    tags: &["office", "tabletop", "electronics", "small"],
    description: "a flat computer monitor on a stand",
    is_a: &["display", "screen", "electronics", "device"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.56, 0.3, 0.9, 0.12, "screen width along X"),
        ParamDef::new("depth", 0.2, 0.14, 0.3, 0.1, "stand depth along Y"),
        ParamDef::new("height", 0.45, 0.28, 0.65, 0.1, "floor to the top of the screen"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_monitor,
};

/// A flat screen on a neck over a base plate, facing +Y.
fn build_monitor(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let housing = b.material("housing", pick(rng, HOUSING), true);
    let screen = b.material("screen", SCREEN, false);
    let hd = d / 2.0;
    let panel_t = (d * 0.2).min(0.04);
    let panel_h = (w * rng.range(0.56, 0.62)).min(h - 0.06);
    let base_t = 0.015;
    let (bw, by0) = ((w * 0.4).min(0.26), -hd);
    slab(b, [-bw / 2.0, by0, 0.0], [bw / 2.0, hd, base_t], housing);
    // The panel stands over the middle of the base, its face towards +Y.
    let (py0, py1) = (-panel_t / 2.0, panel_t / 2.0);
    slab(b, [-w / 2.0, py0, h - panel_h], [w / 2.0, py1, h], housing);
    slab(b, [-0.03, py0 - 0.03, base_t - 0.001], [0.03, py0 + 0.001, h - panel_h * 0.4], housing);
    let bezel = (w * 0.015).max(0.008);
    decal_between(
        b,
        [-w / 2.0 + bezel, py1 - 0.001, h - panel_h + bezel * 1.6],
        [w / 2.0 - bezel, py1 + 0.0015, h - bezel],
        screen,
    );
    (w * panel_h * 18.0 + 1.2).min(12.0)
}

pub(crate) const LAPTOP: Category = Category {
    name: "laptop",
    display: "laptop",
    synonyms: &["notebook computer", "laptop computer", "macbook", "notebook pc", "chromebook"],
    tags: &["office", "tabletop", "electronics", "small", "graspable"],
    description: "an open laptop computer",
    is_a: &["computer", "electronics", "device"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.33, 0.24, 0.42, 0.1, "along X"),
        ParamDef::new("depth", 0.3, 0.2, 0.4, 0.08, "footprint along Y, the open lid included"),
        ParamDef::new("height", 0.22, 0.15, 0.3, 0.08, "to the top of the open lid"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_laptop,
};

/// A keyboard deck with the lid open about 110°, leaning back (-Y); the user sits at +Y.
fn build_laptop(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let shell = b.material("shell", pick(rng, HOUSING), true);
    let screen = b.material("screen", SCREEN, false);
    let keys = b.material("keys", shade(INK, 2.5), false);
    let (tb, tl) = (0.016, 0.007);
    let tilt = rng.range(0.25, 0.4);
    // The lid's bounding box spans tb..h in Z and starts at -d/2 in Y.
    let hz = (h - tb) / 2.0;
    let len = (2.0 * hz - tl * tilt.sin()) / tilt.cos();
    let hy = tl / 2.0 * tilt.cos() + len / 2.0 * tilt.sin();
    let (yc, zc) = (-d / 2.0 + hy, tb + hz);
    let lid_pose = Pose::from_pos_axis_angle([0.0, yc, zc], [1.0, 0.0, 0.0], tilt);
    let lid = Shape::Box { half: [w / 2.0, tl / 2.0, len / 2.0] };
    b.solid(lid, lid_pose, shell);
    // The screen on the lid's front face.
    let face = Shape::Box { half: [w / 2.0 - 0.012, 0.0008, len / 2.0 - 0.014] };
    let n = [0.0, tilt.cos(), tilt.sin()];
    let off = tl / 2.0 + 0.0004;
    b.visual(face, Pose { pos: [0.0, yc + n[1] * off, zc + n[2] * off], ..lid_pose }, screen);
    // The deck from under the hinge to the front edge.
    let y_hinge = yc + len / 2.0 * tilt.sin();
    slab(b, [-w / 2.0, y_hinge - tl, 0.0], [w / 2.0, d / 2.0, tb], shell);
    let (ky0, ky1) = (y_hinge + 0.02, y_hinge + (d / 2.0 - y_hinge) * 0.55);
    decal_between(b, [-w / 2.0 + 0.02, ky0, tb - 0.001], [w / 2.0 - 0.02, ky1, tb + 0.001], keys);
    1.2 + w * d * 6.0
}

pub(crate) const KEYBOARD: Category = Category {
    name: "keyboard",
    display: "keyboard",
    synonyms: &["computer keyboard", "pc keyboard", "keypad"],
    tags: &["office", "tabletop", "electronics", "small", "graspable"],
    description: "a computer keyboard",
    is_a: &["electronics", "input device", "device"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.44, 0.28, 0.48, 0.05, "along X"),
        ParamDef::new("depth", 0.14, 0.1, 0.18, 0.06, "along Y"),
        ParamDef::new("height", 0.03, 0.02, 0.04, 0.1, "to the top of the keys"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_keyboard,
};

/// A low case with rows of key caps.
fn build_keyboard(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let case_rgba = pick(rng, HOUSING);
    let case = b.material("case", case_rgba, true);
    let keys = b.material("keys", shade(case_rgba, if case_rgba[0] > 0.5 { 0.9 } else { 1.6 }), false);
    let base = h * 0.55;
    slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, base], case);
    collider_between(b, [-w / 2.0 + 0.01, -d / 2.0 + 0.01, base], [w / 2.0 - 0.01, d / 2.0 - 0.01, h]);
    let (rows, cols) = (5, 15);
    let (kx, ky) = ((w - 0.02) / cols as f64, (d - 0.02) / rows as f64);
    for r in 0..rows {
        let y0 = -d / 2.0 + 0.01 + ky * r as f64;
        for c in 0..cols {
            // The space bar: one long key in the front row.
            if r == 0 && (4..11).contains(&c) && c != 4 {
                continue;
            }
            let x0 = -w / 2.0 + 0.01 + kx * c as f64;
            let x1 = if r == 0 && c == 4 { x0 + kx * 7.0 } else { x0 + kx };
            decal_between(b, [x0 + 0.0012, y0 + 0.0012, base - 0.001], [x1 - 0.0012, y0 + ky - 0.0012, h], keys);
        }
    }
    (0.3 + w * d * 6.0).min(1.5)
}

pub(crate) const PRINTER: Category = Category {
    name: "printer",
    display: "printer",
    synonyms: &["office printer", "laser printer", "inkjet printer", "multifunction printer", "scanner"],
    tags: &["office", "electronics", "surface", "small"],
    description: "an office laser printer or copier",
    is_a: &["office machine", "electronics", "device"],
    kind: Kind::SmallAppliance,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.45, 0.35, 0.65, 0.1, "along X"),
        ParamDef::new("depth", 0.42, 0.3, 0.6, 0.08, "along Y"),
        ParamDef::new("height", 0.35, 0.2, 0.6, 0.15, "to the top of the scanner lid"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_printer,
};

/// A body with a paper drawer, an output slot under the scanner lid and a control panel.
fn build_printer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body_rgba = pick(rng, &[[0.9, 0.9, 0.88, 1.0], [0.85, 0.86, 0.87, 1.0], [0.22, 0.23, 0.25, 1.0]]);
    let body = b.material("body", body_rgba, true);
    let trim = b.material("trim", shade(body_rgba, 0.7), false);
    let ink = b.material("panel", INK, false);
    let paper = b.material("paper", [0.97, 0.97, 0.95, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let slot = h * 0.62;
    slab(b, [-hw, -hd, 0.0], [hw, hd, slot], body);
    // The output slot: the scanner unit stands on a back block, open at the front.
    slab(b, [-hw, -hd, slot - 0.001], [hw, -hd + d * 0.3, h - 0.06], trim);
    let top = slab(b, [-hw, -hd, h - 0.06], [hw, hd, h], body);
    decal_between(b, [-hw * 0.7, -hd + d * 0.3, slot], [hw * 0.7, hd * 0.6, slot + 0.004], paper);
    decal_between(b, [-hw + 0.02, hd - 0.001, 0.02], [hw - 0.02, hd + 0.002, slot * 0.35], trim);
    decal_between(b, [hw * 0.2, hd - 0.001, h - 0.05], [hw - 0.02, hd + 0.002, h - 0.012], ink);
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    (w * d * h * 140.0).clamp(4.0, 40.0)
}

pub(crate) const DESK_LAMP: Category = Category {
    name: "desk_lamp",
    display: "desk lamp",
    synonyms: &["lamp", "table lamp", "reading lamp", "task lamp", "work lamp", "anglepoise lamp", "light"],
    tags: &["office", "tabletop", "small", "lighting"],
    description: "an adjustable desk lamp on a base",
    is_a: &["lamp", "light", "light fixture"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.18, 0.12, 0.3, 0.1, "base width along X"),
        ParamDef::new("depth", 0.3, 0.2, 0.45, 0.1, "from the back of the base to the front of the shade"),
        ParamDef::new("height", 0.45, 0.3, 0.65, 0.1, "to the top of the arm"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_desk_lamp,
};

/// A weighted base at the back, an arm up and forward, and a conical shade pointing down
/// at the desk in front. The base reaches past the middle, so the lamp stands.
fn build_desk_lamp(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = [[0.12, 0.12, 0.13, 1.0], [0.92, 0.92, 0.9, 1.0], [0.75, 0.15, 0.12, 1.0], [0.15, 0.35, 0.6, 1.0]];
    let color = b.material("paint", pick(rng, &paint), true);
    let joints = b.material("joints", [0.6, 0.61, 0.63, 1.0], false);
    let bulb = b.material("bulb", [1.0, 0.95, 0.75, 1.0], false);
    let bd = d * 0.55;
    let by = -d / 2.0 + bd / 2.0;
    let plate = prism(&rounded_rect(w / 2.0, bd / 2.0, w.min(bd) * 0.45, 4), 0.0, 0.025);
    b.visual_mesh_on(0, &plate, Pose::from_pos([0.0, by, 0.0]), color);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, -d / 2.0 + bd, 0.025]);
    // The upright arm, the forward arm and the shade.
    let arm = 0.012;
    slab(b, [-arm, by - arm, 0.024], [arm, by + arm, h], color);
    let shade_r = (w / 2.0).min(d * 0.22);
    let sy = d / 2.0 - shade_r;
    slab(b, [-arm, by + arm * 0.5, h - 2.0 * arm], [arm, sy, h - 0.001], color);
    let sz1 = h - 2.0 * arm;
    let sz0 = (sz1 - shade_r * 1.2).max(0.06);
    let shade_mesh =
        revolve(&[[0.0, sz1], [shade_r * 0.35, sz1], [shade_r, sz0], [shade_r * 0.92, sz0], [0.0, sz0 + 0.02]], ROUND);
    b.visual_mesh_on(0, &shade_mesh, Pose::from_pos([0.0, sy, 0.0]), color);
    b.collision_on(
        0,
        Shape::Cylinder { radius: shade_r, half_height: (sz1 - sz0) / 2.0 },
        Pose::from_pos([0.0, sy, (sz0 + sz1) / 2.0]),
    );
    super::kit::rod(b, [0.0, sy, sz0 + 0.015], shade_r * 0.4, 0.01, super::kit::Axis::Z, bulb);
    super::kit::rod(b, [0.0, by, h - arm], arm * 1.4, arm * 2.6, super::kit::Axis::X, joints);
    1.4
}

pub(crate) const PHONE: Category = Category {
    name: "phone",
    display: "phone",
    synonyms: &["smartphone", "cell phone", "cellphone", "mobile phone", "telephone", "iphone"],
    tags: &["office", "tabletop", "electronics", "small", "graspable"],
    description: "a smartphone with a touch screen",
    is_a: &["device", "electronics"],
    kind: Kind::HandHeld,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.075, 0.06, 0.09, 0.06, "along X"),
        ParamDef::new("depth", 0.155, 0.12, 0.18, 0.06, "along Y"),
        ParamDef::new("height", 0.009, 0.007, 0.013, 0.1, "thickness"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_phone,
};

/// A slab with rounded corners, lying screen up.
fn build_phone(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let case = b.material("case", pick(rng, HOUSING), true);
    let screen = b.material("screen", SCREEN, false);
    b.visual_mesh_on(0, &prism(&rounded_rect(w / 2.0, d / 2.0, w * 0.12, 3), 0.0, h), Pose::IDENTITY, case);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h]);
    b.visual_mesh_on(
        0,
        &prism(&rounded_rect(w / 2.0 - 0.003, d / 2.0 - 0.004, w * 0.1, 3), h - 0.0005, h + 0.0005),
        Pose::IDENTITY,
        screen,
    );
    0.18 * (w * d) / (0.075 * 0.155)
}
