//! Office furniture: desks and filing cabinets with drawers that slide (MuJoCo slide
//! joints), whiteboards on the wall and water coolers.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::kit::{DARK, LABEL_WHITE, OFFICE_PAINT, STEEL, WOOD, decal_between, fit, pick, shade, slab};
use super::parts::{MOVING_GAP, carcass, decal_on, drawer, round_collider};
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

/// A column of `n` drawers with overlay fronts between `x0..x1`, fronts from `z_lo` to
/// `z_hi` with 3 mm gaps, in a carcass whose inside runs `inner_z` and `inner_x`, with
/// fronts ending at `y_front`. Returns nothing: each drawer is a link.
#[allow(clippy::too_many_arguments)]
pub(crate) fn drawer_stack(
    b: &mut AssetBuilder,
    n: usize,
    [x0, x1]: [f64; 2],
    [z_lo, z_hi]: [f64; 2],
    inner_x: [f64; 2],
    inner_z: [f64; 2],
    y_front: f64,
    depth: f64,
    materials: [usize; 3],
    label: Option<usize>,
    mass: f64,
) {
    let gap = 0.003;
    let step = (z_hi - z_lo + gap) / n as f64;
    for k in 0..n {
        let fz0 = z_lo + step * k as f64;
        let fz1 = fz0 + step - gap;
        let cz = [fz0.max(inner_z[0]), fz1.min(inner_z[1])];
        let link = drawer(
            b,
            &format!("drawer_{}", k + 1),
            [x0, x1],
            [fz0, fz1],
            inner_x,
            cz,
            y_front,
            0.018,
            depth,
            depth * 0.8,
            materials,
            mass,
        );
        if let Some(m) = label {
            // A label holder under the handle.
            let xc = (x0 + x1) / 2.0;
            let zc = fz1 - ((fz1 - fz0) * 0.3).min(0.05) - 0.03;
            if zc - 0.012 > fz0 {
                decal_on(b, link, [xc - 0.04, 0.018, zc - 0.012], [xc + 0.04, 0.0195, zc + 0.012], m);
            }
        }
    }
}

pub(crate) const DESK: Category = Category {
    name: "desk",
    display: "desk",
    synonyms: &[
        "office desk",
        "writing desk",
        "computer desk",
        "work desk",
        "study desk",
        "teacher's desk",
        "student desk",
    ],
    tags: &["furniture", "surface", "office", "tabletop"],
    description: "an office desk with a drawer pedestal for working at a computer",
    is_a: &["table", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.4, 0.9, 2.2, 0.12, "top length along X"),
        ParamDef::new("depth", 0.7, 0.5, 0.9, 0.08, "top depth along Y"),
        ParamDef::new("height", 0.74, 0.65, 0.8, 0.02, "floor to the top surface"),
        ParamDef::new("drawers", 3.0, 2.0, 4.0, 0.2, "drawers in the pedestal"),
        ParamDef::new("pedestal_width", 0.42, 0.3, 0.5, 0.08, "width of the drawer pedestal"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_desk,
};

/// A top on a panel leg (-X) and a drawer pedestal (+X) with a modesty panel between;
/// the drawers face the user (+Y) and slide out.
fn build_desk(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let n = p.count("drawers").clamp(2, 4);
    let pw = fit(b, "desk pedestal_width", p.get("pedestal_width"), 0.2, w * 0.45);
    let t = 0.025;
    let top_rgba = pick(rng, WOOD);
    let top = b.material("top", top_rgba, true);
    let body_rgba = if rng.chance(0.5) { top_rgba } else { pick(rng, OFFICE_PAINT) };
    let body = b.material("body", shade(body_rgba, 0.97), false);
    let fronts = b.material("fronts", shade(body_rgba, 1.03), false);
    let tray = b.material("drawer_inside", shade(body_rgba, 0.8), false);
    let handles = b.material("handles", pick(rng, STEEL), false);
    let (hw, hd) = (w / 2.0, d / 2.0);

    let top_z = slab(b, [-hw, -hd, h - t], [hw, hd, h], top);
    // The panel leg and the modesty panel.
    slab(b, [-hw + 0.01, -hd + 0.02, 0.0], [-hw + 0.035, hd - 0.02, h - t], body);
    slab(b, [-hw + 0.035, -hd + 0.03, h * 0.35], [hw - pw, -hd + 0.048, h - t], body);
    // The pedestal: fronts at y_front, a carcass behind them.
    let tc = 0.018;
    let y_front = hd - 0.02;
    let opening = y_front - 0.018 - MOVING_GAP;
    let (px0, px1) = (hw - pw, hw - 0.01);
    carcass(b, px0, px1, -hd + 0.02, opening, 0.0, h - t, tc, body);
    let depth = (y_front - 0.018) - (-hd + 0.02 + tc) - MOVING_GAP;
    drawer_stack(
        b,
        n,
        [px0 + 0.002, px1 - 0.002],
        [0.012, h - t - 0.003],
        [px0 + tc, px1 - tc],
        [tc, h - t - tc],
        y_front,
        depth,
        [fronts, tray, handles],
        None,
        2.5,
    );
    b.surface("top", top_z, [-hw, -hd], [hw, hd], None);
    0.0
}

pub(crate) const FILING_CABINET: Category = Category {
    name: "filing_cabinet",
    display: "filing cabinet",
    synonyms: &["file cabinet", "filing drawers", "file drawers", "office drawer cabinet", "steel drawer cabinet"],
    tags: &["furniture", "storage", "office", "tall"],
    description: "a steel office filing cabinet with pull-out drawers for documents",
    is_a: &["cabinet", "furniture", "storage"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.47, 0.38, 0.9, 0.06, "along X"),
        ParamDef::new("depth", 0.62, 0.4, 0.75, 0.06, "along Y"),
        ParamDef::new("height", 1.32, 0.6, 1.55, 0.12, "floor to top"),
        ParamDef::new("drawers", 4.0, 2.0, 5.0, 0.2, "drawers, stacked"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_filing_cabinet,
};

/// A steel carcass on a plinth with a stack of full-width drawers, label holders and bar
/// handles.
fn build_filing_cabinet(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let n = p.count("drawers").clamp(2, 5).min(((h - 0.08) / 0.22).floor().max(2.0) as usize);
    let paint = pick(rng, OFFICE_PAINT);
    let body = b.material("body", paint, true);
    let fronts = b.material("fronts", shade(paint, 1.04), true);
    let tray = b.material("drawer_inside", shade(paint, 0.75), false);
    let handles = b.material("handles", if rng.chance(0.7) { pick(rng, STEEL) } else { pick(rng, DARK) }, false);
    let label = b.material("labels", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let tc = 0.015;
    let opening = hd - 0.018 - MOVING_GAP;
    let top = carcass(b, -hw, hw, -hd, opening, 0.0, h, tc, body);
    let plinth = b.material("plinth", pick(rng, DARK), false);
    decal_between(b, [-hw + 0.02, opening - 0.03, 0.0], [hw - 0.02, opening + 0.001, 0.05], plinth);
    let depth = (hd - 0.018) - (-hd + tc) - MOVING_GAP;
    drawer_stack(
        b,
        n,
        [-hw + 0.002, hw - 0.002],
        [0.055, h - 0.006],
        [-hw + tc, hw - tc],
        [tc, h - tc],
        hd,
        depth,
        [fronts, tray, handles],
        Some(label),
        3.0,
    );
    b.surface("top", top, [-hw + tc / 2.0, -hd], [hw - tc / 2.0, opening], None);
    0.0
}

pub(crate) const WHITEBOARD: Category = Category {
    name: "whiteboard",
    display: "whiteboard",
    synonyms: &[
        "white board",
        "dry erase board",
        "marker board",
        "blackboard",
        "chalkboard",
        "notice board",
        "bulletin board",
        "pinboard",
        "noticeboard",
        "corkboard",
        "cork board",
    ],
    tags: &["office", "classroom", "lab", "wall"],
    description: "a white dry-erase board on the wall of an office or classroom",
    is_a: &["board"],
    kind: Kind::Fixture,
    placement: PlacementKind::WallMounted,
    params: &[
        ParamDef::new("width", 1.8, 0.6, 3.6, 0.15, "along X"),
        ParamDef::new("depth", 0.07, 0.04, 0.12, 0.1, "off the wall, marker tray included"),
        ParamDef::new("height", 1.2, 0.45, 1.5, 0.1, "board height"),
        ParamDef::new("mount_height", 0.9, 0.5, 1.3, 0.05, "floor to the bottom of the board"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_whiteboard,
};

/// A framed board on the wall (its origin on the floor below it) with a marker tray.
fn build_whiteboard(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let z0 = p.get("mount_height");
    let (hw, hd) = (w / 2.0, d / 2.0);
    let kind = rng.below(4);
    let face_rgba = match kind {
        0 | 1 => [0.97, 0.97, 0.96, 1.0],
        2 => [0.14, 0.24, 0.2, 1.0],
        _ => [0.72, 0.56, 0.38, 1.0], // cork
    };
    let face = b.material("face", face_rgba, kind >= 2);
    let frame = b.material("frame", pick(rng, &[[0.78, 0.79, 0.8, 1.0], [0.55, 0.4, 0.25, 1.0]]), kind < 2);
    let bt = (d * 0.35).min(0.025);
    let f = (w.min(h) * 0.03).clamp(0.012, 0.03);
    // The board, its back on the wall (-Y).
    slab(b, [-hw, -hd, z0], [hw, -hd + bt, z0 + h], frame);
    decal_between(b, [-hw + f, -hd + bt - 0.001, z0 + f], [hw - f, -hd + bt + 0.0015, z0 + h - f], face);
    // The tray along the bottom, out to the full depth.
    let tray_h = (h * 0.04).min(0.03);
    slab(b, [-hw * 0.8, -hd + bt, z0], [hw * 0.8, hd, z0 + tray_h], frame);
    if kind < 2 {
        for (i, c) in [[0.1, 0.2, 0.7, 1.0], [0.8, 0.1, 0.1, 1.0], [0.05, 0.05, 0.05, 1.0]].into_iter().enumerate() {
            let m = b.material(&format!("marker_{}", i + 1), c, false);
            let x = -hw * 0.5 + i as f64 * 0.16;
            let y = (-hd + bt + hd) / 2.0;
            super::kit::rod(b, [x, y, z0 + tray_h + 0.009], 0.009, 0.13, super::kit::Axis::X, m);
        }
    }
    0.0
}

pub(crate) const WATER_COOLER: Category = Category {
    name: "water_cooler",
    display: "water cooler",
    synonyms: &["water dispenser", "drinking fountain", "water fountain", "bottled water cooler", "water station"],
    tags: &["office", "kitchen", "hospital", "appliance"],
    description: "a floor-standing water dispenser with a large bottle on top",
    is_a: &["dispenser", "appliance"],
    kind: Kind::LargeAppliance,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.31, 0.26, 0.4, 0.05, "along X"),
        ParamDef::new("depth", 0.33, 0.26, 0.42, 0.05, "along Y"),
        ParamDef::new("height", 1.38, 1.0, 1.6, 0.04, "floor to the top of the bottle"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_water_cooler,
};

/// A cabinet with a tap recess and drip tray, and an upturned 19 l bottle on top.
fn build_water_cooler(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let (hw, hd) = (w / 2.0, d / 2.0);
    let body =
        b.material("body", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.75, 0.77, 0.79, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    let water = b.material("bottle", [0.55, 0.75, 0.92, 1.0], false);
    let dark = b.material("recess", shade(pick(rng, DARK), 0.8), false);
    let taps = b.material("taps", [0.15, 0.35, 0.8, 1.0], false);
    let hot = b.material("hot_tap", [0.8, 0.12, 0.1, 1.0], false);
    let body_h = h - (0.49f64).min(h * 0.4);
    let top = slab(b, [-hw, -hd, 0.0], [hw, hd, body_h], body);
    let (rz0, rz1) = (body_h * 0.55, body_h * 0.8);
    decal_between(b, [-hw * 0.7, hd - 0.001, rz0], [hw * 0.7, hd + 0.002, rz1], dark);
    for (x, m) in [(-hw * 0.3, taps), (hw * 0.3, hot)] {
        decal_between(b, [x - 0.015, hd + 0.002, rz1 - 0.06], [x + 0.015, hd + 0.004, rz1 - 0.02], m);
    }
    // The bottle: a collar, the upturned bottle with rounded shoulders.
    let r = (w.min(d) / 2.0 * 0.88).min(0.135);
    let bh = h - top;
    let prof =
        [[0.0, 0.0], [r * 0.3, 0.0], [r * 0.3, bh * 0.12], [r, bh * 0.3], [r, bh * 0.92], [r * 0.8, bh], [0.0, bh]];
    b.visual_mesh_on(0, &revolve(&prof, ROUND), Pose::from_pos([0.0, 0.0, top]), water);
    round_collider(b, 0, [0.0, 0.0], r, top + bh * 0.3, h);
    b.collision_on(
        0,
        sw_geom::Shape::Cylinder { radius: r * 0.3, half_height: bh * 0.15 },
        Pose::from_pos([0.0, 0.0, top + bh * 0.15]),
    );
    0.0
}
