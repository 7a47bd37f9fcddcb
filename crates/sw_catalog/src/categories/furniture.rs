//! Tables, benches, seating.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::kit::{
    DARK, FRAME_PAINT, STEEL, UPHOLSTERY, WOOD, collider_between, decal_between, fit, four_legs, ordered, pick, shade,
    slab,
};
use super::parts::round_collider;
use super::shapes::{ROUND, prism, prism_xz, revolve, rounded_rect, rounded_ring_profile};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const TABLE: Category = Category {
    name: "table",
    display: "table",
    synonyms: &["desk table", "work table", "worktable", "folding table"],
    tags: &["furniture", "surface", "office", "kitchen", "lab", "tabletop"],
    description: "a flat top on four legs for working, eating or putting things on",
    is_a: &["furniture"],
    kind: Kind::Furniture,
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

pub(crate) fn build_table(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
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
        "potting bench",
        "potting table",
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
    description: "a sturdy workshop table with a lower shelf for assembly and repairs",
    is_a: &["bench", "table", "furniture"],
    kind: Kind::Furniture,
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
    description: "a chair with a seat, a backrest and legs for one person",
    is_a: &["seat", "furniture"],
    kind: Kind::Furniture,
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

pub(crate) const DINING_TABLE: Category = Category {
    name: "dining_table",
    display: "dining table",
    synonyms: &["kitchen table", "wooden dining table", "dinner table", "farmhouse table", "breakfast table"],
    tags: &["furniture", "surface", "kitchen", "home"],
    description: "a wooden dining table for eating meals at home",
    is_a: &["table", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.6, 0.8, 2.6, 0.15, "top length along X"),
        ParamDef::new("depth", 0.9, 0.7, 1.2, 0.08, "top depth along Y"),
        ParamDef::new("height", 0.76, 0.7, 0.8, 0.02, "floor to the top surface"),
        ParamDef::new("leg", 0.07, 0.05, 0.1, 0.15, "leg section"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_dining_table,
};

/// A thick top with rounded corners, an apron under it and four turned legs.
fn build_dining_table(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let leg = p.get("leg");
    let wood = pick(rng, WOOD);
    let top = b.material("top", wood, true);
    let legs = b.material("legs", shade(wood, rng.range(0.75, 1.0) as f32), false);
    let t = rng.range(0.03, 0.045);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let corner = rng.range(0.02, 0.12);
    b.visual_mesh_on(0, &prism(&rounded_rect(hw, hd, corner, 4), h - t, h), Pose::IDENTITY, top);
    let top_z = collider_between(b, [-hw, -hd, h - t], [hw, hd, h]);
    // Legs inset from the corners; the apron runs between them.
    let inset = corner.max(0.04) + leg / 2.0;
    let (lx, ly) = (hw - inset, hd - inset);
    let apron = 0.1f64.min(h * 0.15);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * lx, sy * ly);
        let r = leg / 2.0;
        let turned = revolve(
            &[
                [0.0, 0.0],
                [r * 0.7, 0.0],
                [r * 0.8, h * 0.08],
                [r * 0.55, h * 0.2],
                [r * 0.85, h * 0.55],
                [r * 0.7, h * 0.68],
                [r, h * 0.7],
                [r, h - t],
                [0.0, h - t],
            ],
            ROUND,
        );
        b.visual_mesh_on(0, &turned, Pose::from_pos([x, y, 0.0]), legs);
        collider_between(b, [x - r, y - r, 0.0], [x + r, y + r, h - t]);
    }
    for sy in [-1.0, 1.0] {
        let (y0, y1) = ordered(sy * (ly - 0.012), sy * (ly + 0.012));
        slab(b, [-lx + leg / 2.0, y0, h - t - apron], [lx - leg / 2.0, y1, h - t], legs);
    }
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * (lx - 0.012), sx * (lx + 0.012));
        slab(b, [x0, -ly + leg / 2.0, h - t - apron], [x1, ly - leg / 2.0, h - t], legs);
    }
    b.surface("top", top_z, [-hw, -hd], [hw, hd], None);
    0.0
}

pub(crate) const STOOL: Category = Category {
    name: "stool",
    display: "stool",
    synonyms: &["bar stool", "lab stool", "shop stool", "work stool", "counter stool", "step stool", "tabouret"],
    tags: &["furniture", "seating", "kitchen", "lab", "workshop", "small", "round"],
    description: "a backless seat on legs",
    is_a: &["seat", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.36, 0.28, 0.5, 0.08, "seat diameter"),
        ParamDef::new("depth", 0.36, 0.28, 0.5, 0.08, "seat diameter (as width)"),
        ParamDef::new("height", 0.65, 0.42, 0.82, 0.12, "floor to the top of the seat"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_stool,
};

/// A round seat on four legs with a foot ring.
fn build_stool(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let upholstered = rng.chance(0.5);
    let seat_rgba = if upholstered { pick(rng, UPHOLSTERY) } else { pick(rng, WOOD) };
    let seat = b.material("seat", seat_rgba, true);
    let frame = b.material("frame", if rng.chance(0.6) { pick(rng, STEEL) } else { pick(rng, DARK) }, false);
    let st = if upholstered { 0.06 } else { 0.03 };
    let seat_mesh = revolve(&[[0.0, h - st], [r, h - st], [r, h - 0.01], [r - 0.01, h], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &seat_mesh, Pose::IDENTITY, seat);
    let top = round_collider(b, 0, [0.0, 0.0], r, h - st, h);
    let (lr, leg) = (r * 0.72, 0.014f64.min(r * 0.1));
    for k in 0..4 {
        let a = std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
        let (x, y) = (lr * a.cos(), lr * a.sin());
        b.solid(
            sw_geom::Shape::Cylinder { radius: leg, half_height: (h - st) / 2.0 },
            Pose::from_pos([x, y, (h - st) / 2.0]),
            frame,
        );
    }
    let zr = h * 0.3;
    let ring = revolve(&rounded_ring_profile(lr - 0.01, lr + 0.01, zr - 0.01, zr + 0.01, 0.006), ROUND);
    b.visual_mesh_on(0, &ring, Pose::IDENTITY, frame);
    let a = r / std::f64::consts::SQRT_2 - 1e-6;
    b.surface("seat", top, [-a, -a], [a, a], None);
    0.0
}

pub(crate) const SOFA: Category = Category {
    name: "sofa",
    display: "sofa",
    synonyms: &["couch", "settee", "loveseat", "love seat", "lounge sofa", "two-seater", "three-seater"],
    tags: &["furniture", "seating", "home", "office"],
    description: "an upholstered sofa that seats two or three people in a living room",
    is_a: &["seat", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 2.0, 1.3, 2.6, 0.12, "along X, arms included"),
        ParamDef::new("depth", 0.9, 0.75, 1.05, 0.06, "along Y"),
        ParamDef::new("height", 0.85, 0.7, 1.0, 0.06, "floor to the top of the back"),
        ParamDef::new("seat_height", 0.44, 0.38, 0.5, 0.04, "floor to the top of the cushions"),
        ParamDef::new("arm_width", 0.2, 0.1, 0.28, 0.15, "width of each arm"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_sofa,
};

/// A chaise longue (BEHAVIOR-100's `chaise_longue`, issue 21 session 8): the sofa's build,
/// long and narrow, with one low arm-width of frame at each end.
pub(crate) const CHAISE_LONGUE: Category = Category {
    name: "chaise_longue",
    display: "chaise longue",
    synonyms: &["chaise lounge", "chaise", "fainting couch", "lounger sofa"],
    tags: &["furniture", "seating", "home"],
    description: "an upholstered chaise longue: a long seat to lie on with a backrest",
    is_a: &["sofa", "seat", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::Floor,
    // Habitat / IKEA chaise longues 160–190 cm long, 65–80 cm deep, 75–90 cm tall.
    params: &[
        ParamDef::new("width", 1.7, 1.5, 1.95, 0.08, "along X, ends included"),
        ParamDef::new("depth", 0.72, 0.62, 0.85, 0.06, "along Y"),
        ParamDef::new("height", 0.8, 0.7, 0.92, 0.06, "floor to the top of the back"),
        ParamDef::new("seat_height", 0.42, 0.36, 0.48, 0.04, "floor to the top of the cushions"),
        ParamDef::new("arm_width", 0.1, 0.08, 0.14, 0.15, "width of each end"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_sofa,
};

/// A base on short feet, seat cushions, back cushions, a back frame and rounded arms;
/// it faces +Y with its back at -Y.
pub(crate) fn build_sofa(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let sh = fit(b, "sofa seat_height", p.get("seat_height"), 0.2, h - 0.2);
    let aw = fit(b, "sofa arm_width", p.get("arm_width"), 0.05, w * 0.2);
    let fabric = pick(rng, UPHOLSTERY);
    let body = b.material("body", fabric, true);
    let cushions = b.material("cushions", shade(fabric, 1.12), true);
    let feet =
        b.material("feet", pick(rng, &[[0.3, 0.2, 0.12, 1.0], [0.1, 0.1, 0.1, 1.0], [0.6, 0.6, 0.62, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let foot = 0.06;
    let back_t = (d * 0.22).min(0.22);
    // Feet, base, back frame.
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * (hw - 0.06), sy * (hd - 0.06));
        slab(b, [x - 0.025, y - 0.025, 0.0], [x + 0.025, y + 0.025, foot], feet);
    }
    let base_top = sh - 0.14;
    slab(b, [-hw + aw * 0.5, -hd, foot], [hw - aw * 0.5, hd, base_top], body);
    slab(b, [-hw + aw * 0.5, -hd, base_top - 0.01], [hw - aw * 0.5, -hd + back_t, h], body);
    // Arms: rounded on top, colliding as boxes.
    let arm_h = sh + 0.18;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * hw, sx * (hw - aw));
        let outline = rounded_rect((x1 - x0) / 2.0, (arm_h - foot) / 2.0, aw * 0.45, 4)
            .into_iter()
            .map(|[x, z]| [x + (x0 + x1) / 2.0, z + (arm_h + foot) / 2.0])
            .collect::<Vec<_>>();
        b.visual_mesh_on(0, &prism_xz(&outline, -hd, hd), Pose::IDENTITY, body);
        collider_between(b, [x0, -hd, foot], [x1, hd, arm_h]);
    }
    // Seat cushions, one collision box across them; back cushions against the frame.
    let inner = w - 2.0 * aw;
    let n = if inner > 1.4 {
        3
    } else if inner > 0.85 {
        2
    } else {
        1
    };
    let (cx0, cx1) = (-hw + aw, hw - aw);
    let cw = (cx1 - cx0) / n as f64;
    let (cy0, cy1) = (-hd + back_t, hd - 0.01);
    for k in 0..n {
        let x = cx0 + cw * k as f64;
        decal_between(b, [x + 0.004, cy0 + 0.004, base_top], [x + cw - 0.004, cy1, sh - 0.002], cushions);
        let bz1 = h - 0.08;
        decal_between(b, [x + 0.006, cy0 - 0.001, sh], [x + cw - 0.006, cy0 + 0.12, bz1], cushions);
    }
    let seat = collider_between(b, [cx0, cy0, base_top], [cx1, cy1, sh]);
    collider_between(b, [cx0, cy0, sh], [cx1, cy0 + 0.12, h - 0.08]);
    b.surface("seat", seat, [cx0, cy0 + 0.12], [cx1, cy1], None);
    0.0
}
