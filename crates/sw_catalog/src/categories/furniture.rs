//! Tables, benches, seating.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::kit::{DARK, FRAME_PAINT, STEEL, UPHOLSTERY, WOOD, fit, four_legs, pick, slab};
use crate::{Category, ParamDef, Params};

pub(crate) const TABLE: Category = Category {
    name: "table",
    display: "table",
    synonyms: &["dining table", "desk table", "work table", "worktable", "side table"],
    tags: &["furniture", "surface", "office", "kitchen", "lab", "tabletop"],
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.2, 0.4, 3.0, 0.15, "top length along X"),
        ParamDef::new("depth", 0.75, 0.4, 1.5, 0.1, "top depth along Y"),
        ParamDef::new("height", 0.75, 0.4, 1.2, 0.03, "floor to top surface"),
        ParamDef::new("top_thickness", 0.035, 0.015, 0.08, 0.2, "thickness of the top"),
        ParamDef::new("leg", 0.05, 0.025, 0.12, 0.2, "leg section"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_table,
};

fn build_table(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = p.get("top_thickness").min(h * 0.3);
    let leg = p.get("leg").min(w.min(d) * 0.2);
    let top = b.material("top", pick(rng, WOOD), true);
    let frame = b.material("legs", pick(rng, STEEL), false);
    // The surface takes the top's exact collision height (`h - t/2 + t/2` is not always `h`).
    let top_z = slab(b, [-w / 2.0, -d / 2.0, h - t], [w / 2.0, d / 2.0, h], top);
    four_legs(b, w, d, h - t, leg, 0.03, frame);
    b.surface("top", top_z, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    0.0
}

pub(crate) const WORKBENCH: Category = Category {
    name: "workbench",
    display: "workbench",
    synonyms: &[
        "work bench",
        "workshop bench",
        "workshop table",
        "assembly bench",
        "assembly table",
        "tool bench",
        "packing bench",
        "packing table",
        "lab bench",
        "laboratory bench",
    ],
    tags: &["furniture", "surface", "industrial", "workshop", "lab", "warehouse", "heavy", "tabletop"],
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.5, 0.8, 3.0, 0.15, "top length along X"),
        ParamDef::new("depth", 0.75, 0.5, 1.2, 0.1, "top depth along Y"),
        ParamDef::new("height", 0.9, 0.6, 1.1, 0.03, "floor to top surface"),
        ParamDef::new("top_thickness", 0.045, 0.02, 0.1, 0.2, "thickness of the heavy top"),
        ParamDef::new("leg", 0.06, 0.04, 0.12, 0.15, "leg section"),
        ParamDef::new("shelf_height", 0.2, 0.06, 0.6, 0.25, "floor to the top of the lower shelf"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_workbench,
};

fn build_workbench(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = fit(b, "workbench top_thickness", p.get("top_thickness"), 0.0, h * 0.12);
    let leg = fit(b, "workbench leg", p.get("leg"), 0.0, d * 0.15);
    let inset = 0.03;
    let under = h - t;
    let board = 0.025;
    let shelf_top = fit(b, "workbench shelf_height", p.get("shelf_height"), board + 0.03, under - 0.25);

    // Butcher block, grey laminate or a steel sheet over a painted frame.
    let top_rgba = if rng.chance(0.7) { pick(rng, WOOD) } else { pick(rng, STEEL) };
    let top = b.material("top", top_rgba, false);
    let frame = b.material("frame", pick(rng, FRAME_PAINT), true);
    let shelf = b.material("shelf", if rng.chance(0.5) { pick(rng, WOOD) } else { pick(rng, DARK) }, false);

    let top_z = slab(b, [-w / 2.0, -d / 2.0, under], [w / 2.0, d / 2.0, h], top);
    four_legs(b, w, d, under, leg, inset, frame);
    // Aprons under the top, in line with the legs so they stay out of the shelf's space.
    let (ix, iy) = (w / 2.0 - inset - leg, d / 2.0 - inset - leg);
    let apron = (0.1f64).min(under * 0.15);
    for sy in [-1.0, 1.0] {
        let (y0, y1) = (iy + leg * 0.25, iy + leg * 0.75);
        let (y0, y1) = if sy > 0.0 { (y0, y1) } else { (-y1, -y0) };
        slab(b, [-ix, y0, under - apron], [ix, y1, under], frame);
    }
    // The lower shelf spans between the legs.
    let shelf_z = slab(b, [-ix, -iy, shelf_top - board], [ix, iy, shelf_top], shelf);

    b.surface("top", top_z, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    b.surface("lower_shelf", shelf_z, [-ix, -iy], [ix, iy], Some(under - apron - shelf_z));
    0.0
}

pub(crate) const CHAIR: Category = Category {
    name: "chair",
    display: "chair",
    synonyms: &[
        "office chair",
        "desk chair",
        "dining chair",
        "stacking chair",
        "side chair",
        "seat",
        "lab chair",
        "visitor chair",
    ],
    tags: &["furniture", "seating", "office", "kitchen", "lab", "small"],
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.46, 0.35, 0.7, 0.08, "seat width along X"),
        ParamDef::new("depth", 0.5, 0.4, 0.7, 0.06, "seat depth along Y, backrest included"),
        ParamDef::new("height", 0.85, 0.6, 1.2, 0.06, "floor to the top of the backrest"),
        ParamDef::new("seat_height", 0.46, 0.3, 0.65, 0.04, "floor to the top of the seat"),
        ParamDef::new("leg", 0.03, 0.018, 0.06, 0.2, "leg section"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_chair,
};

fn build_chair(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let seat_h = fit(b, "chair seat_height", p.get("seat_height"), 0.2, h - 0.2);
    let leg = fit(b, "chair leg", p.get("leg"), 0.0, w * 0.12);
    // Upholstered seats are thicker than wooden or moulded ones.
    let upholstered = rng.chance(0.5);
    let seat_t = f64::min(if upholstered { 0.06 } else { 0.03 }, seat_h * 0.2);
    let (shell_rgba, frame_rgba) = if upholstered {
        (pick(rng, UPHOLSTERY), pick(rng, DARK))
    } else {
        let wood = pick(rng, WOOD);
        (wood, if rng.chance(0.5) { wood } else { pick(rng, STEEL) })
    };
    let shell = b.material("seat", shell_rgba, true);
    let frame = b.material("frame", frame_rgba, false);

    let inset = 0.012;
    let back_t = 0.02;
    let x = w / 2.0 - inset - leg / 2.0;
    let y_front = d / 2.0 - inset - leg;
    let y_back = -d / 2.0 + inset;
    let seat_top = slab(b, [-w / 2.0, -d / 2.0, seat_h - seat_t], [w / 2.0, d / 2.0, seat_h], shell);
    for sx in [-1.0, 1.0] {
        // Front legs stop under the seat; back legs rise through it as the backrest posts.
        slab(b, [sx * x - leg / 2.0, y_front, 0.0], [sx * x + leg / 2.0, y_front + leg, seat_h - seat_t], frame);
        slab(b, [sx * x - leg / 2.0, y_back, 0.0], [sx * x + leg / 2.0, y_back + leg, h - 0.03], frame);
    }
    // The backrest sits in front of the posts, at -Y: the chair faces +Y.
    let gap = ((h - seat_h) * rng.range(0.15, 0.35)).min(0.15);
    let back_y = y_back + leg;
    slab(b, [-(w / 2.0 - inset), back_y, seat_h + gap], [w / 2.0 - inset, back_y + back_t, h], shell);

    b.surface("seat", seat_top, [-w / 2.0, back_y + back_t], [w / 2.0, d / 2.0], None);
    0.0
}
