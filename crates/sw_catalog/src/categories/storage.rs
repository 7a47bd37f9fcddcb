//! Shelving, racking and cabinets: tall fixtures against a wall that hold other things.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::kit::{
    Axis, DARK, FRAME_PAINT, INK, LABEL_WHITE, OFFICE_PAINT, RACK_BLUE, RACK_ORANGE, SAFETY_YELLOW, STEEL, WOOD,
    decal_between, fit, ordered, pick, shade, slab, strut,
};
use super::parts::{Hinge, MOVING_GAP, carcass, decal_on, hinged_door};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const SHELF: Category = Category {
    name: "shelf",
    display: "shelf",
    synonyms: &[
        "shelving unit",
        "shelving",
        "shelf unit",
        "storage shelf",
        "storage shelving",
        "metal shelf",
        "steel shelf",
        "wire shelf",
        "shelving rack",
    ],
    tags: &["storage", "tall", "warehouse", "office", "lab", "kitchen", "retail", "furniture"],
    description: "a free-standing metal shelving unit with several flat levels",
    is_a: &["shelving", "furniture", "storage"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.0, 0.5, 2.0, 0.12, "along X"),
        ParamDef::new("depth", 0.45, 0.25, 0.8, 0.12, "along Y"),
        ParamDef::new("height", 1.8, 0.8, 2.5, 0.08, "floor to the top level"),
        ParamDef::new("levels", 4.0, 3.0, 6.0, 0.25, "number of shelf levels, the top included"),
        ParamDef::new("post", 0.035, 0.025, 0.06, 0.15, "corner post section"),
        ParamDef::new("deck_thickness", 0.025, 0.015, 0.05, 0.15, "thickness of each level"),
        ParamDef::new("bottom_height", 0.12, 0.03, 0.4, 0.3, "floor to the top of the lowest level"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_shelf,
};

/// Four corner posts and evenly spaced decks between them; the top deck is flush with
/// the posts. Each deck is a surface whose clearance reaches the underside of the next.
fn build_shelf(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let n = p.count("levels").clamp(3, 6);
    let post = fit(b, "shelf post", p.get("post"), 0.0, w * 0.08);
    let t = p.get("deck_thickness");
    let bottom = fit(b, "shelf bottom_height", p.get("bottom_height"), t, h / (n as f64 + 1.0));

    // Painted steel, all wood, or a painted frame with chipboard decks.
    let style = rng.below(3);
    let (frame_rgba, deck_rgba) = match style {
        0 => {
            let c = pick(rng, STEEL);
            (c, shade(c, 1.05))
        }
        1 => {
            let c = pick(rng, WOOD);
            (c, c)
        }
        _ => (pick(rng, FRAME_PAINT), pick(rng, WOOD)),
    };
    let frame = b.material("frame", frame_rgba, true);
    let decks = b.material("decks", deck_rgba, style == 1);

    let (hw, hd) = (w / 2.0, d / 2.0);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x0, x1) = ordered(sx * hw, sx * (hw - post));
        let (y0, y1) = ordered(sy * hd, sy * (hd - post));
        slab(b, [x0, y0, 0.0], [x1, y1, h], frame);
    }
    let ix = hw - post;
    let step = (h - bottom) / (n - 1) as f64;
    let tops: Vec<f64> = (0..n)
        .map(|i| {
            let z = if i + 1 == n { h } else { bottom + step * i as f64 };
            slab(b, [-ix, -hd, z - t], [ix, hd, z], decks)
        })
        .collect();
    for (i, &z) in tops.iter().enumerate() {
        let clearance = tops.get(i + 1).map(|next| (next - t) - z);
        b.surface(&format!("level_{}", i + 1), z, [-ix, -hd], [ix, hd], clearance);
    }
    // Steel shelving is braced with a cross of flat straps across the back.
    if style != 1 && rng.chance(0.6) {
        let (y, z0, z1) = (-hd - 0.001, bottom, h - t);
        for (xa, xb) in [(-ix, ix), (ix, -ix)] {
            strut(b, [xa, y, z0], [xb, y, z1], [0.025, 0.002], Axis::Y, frame, false);
        }
    }
    0.0
}

pub(crate) const PALLET_RACK: Category = Category {
    name: "pallet_rack",
    display: "pallet rack",
    synonyms: &[
        "pallet racking",
        "racking",
        "warehouse rack",
        "warehouse racking",
        "industrial rack",
        "selective rack",
        "selective pallet rack",
        "high bay rack",
        "heavy duty rack",
    ],
    tags: &["warehouse", "industrial", "logistics", "storage", "tall", "heavy"],
    description: "tall warehouse racking with orange beams that holds pallets on levels",
    is_a: &["rack", "shelving", "storage"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 2.7, 1.8, 3.9, 0.05, "one bay, uprights included, along X"),
        ParamDef::new("depth", 1.1, 0.6, 1.5, 0.05, "frame depth along Y"),
        ParamDef::new("height", 4.5, 3.0, 6.0, 0.15, "floor to the top of the uprights"),
        ParamDef::new("levels", 3.0, 2.0, 4.0, 0.34, "beam levels with a deck"),
        ParamDef::new("upright", 0.09, 0.07, 0.12, 0.1, "upright face width along X"),
        ParamDef::new("beam_height", 0.12, 0.08, 0.18, 0.15, "beam section height"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_pallet_rack,
};

/// Two braced upright frames (blue), a pair of step beams per level (orange) and a deck
/// on each pair. The floor under the first level is storage too, but not part of the
/// asset.
fn build_pallet_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let n = p.count("levels").clamp(2, 4);
    let u = p.get("upright");
    let bh = p.get("beam_height");
    let ud = 0.07; // upright section along Y
    let bt = 0.05; // beam section along Y
    let dt = 0.03; // deck thickness
    let uprights = b.material("uprights", pick(rng, RACK_BLUE), true);
    let beams = b.material("beams", pick(rng, RACK_ORANGE), false);
    let deck_rgba = if rng.chance(0.7) { [0.7, 0.72, 0.74, 1.0] } else { pick(rng, WOOD) };
    let decks = b.material("decks", deck_rgba, false);

    let (hw, hd) = (w / 2.0, d / 2.0);
    let ix = hw - u;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = ordered(sx * hw, sx * ix);
        for sy in [-1.0, 1.0] {
            let (y0, y1) = ordered(sy * hd, sy * (hd - ud));
            slab(b, [x0, y0, 0.0], [x1, y1, h], uprights);
        }
        // Frame bracing: horizontals and alternating diagonals between the uprights.
        let xc = sx * (hw - u / 2.0);
        let (z_lo, z_hi) = (0.15, h - 0.3);
        let panels = ((z_hi - z_lo) / 1.0).ceil().max(1.0) as usize;
        let yi = hd - ud;
        let mut z_prev = z_lo;
        for k in 0..=panels {
            let z = z_lo + (z_hi - z_lo) * k as f64 / panels as f64;
            slab(b, [xc - 0.015, -yi, z - 0.015], [xc + 0.015, yi, z + 0.015], uprights);
            if k > 0 {
                let (ya, yb) = if k % 2 == 0 { (-yi, yi) } else { (yi, -yi) };
                strut(b, [xc, ya, z_prev], [xc, yb, z], [0.03, 0.025], Axis::X, uprights, true);
            }
            z_prev = z;
        }
    }
    // Beam levels evenly spaced, the top one a little below the upright tops.
    let step = (h - (0.3f64).min(h * 0.1)) / n as f64;
    let label = b.material("labels", LABEL_WHITE, false);
    let mut tops = Vec::with_capacity(n);
    for i in 1..=n {
        let z = step * i as f64;
        let beam_top = z - dt;
        for sy in [-1.0, 1.0] {
            let (y0, y1) = ordered(sy * hd, sy * (hd - bt));
            slab(b, [-ix, y0, beam_top - bh], [ix, y1, beam_top], beams);
        }
        tops.push(slab(b, [-ix, -hd, beam_top], [ix, hd, z], decks));
        // Location labels on the front beam.
        for lx in [-ix * 0.5, ix * 0.5] {
            let zc = beam_top - bh / 2.0;
            decal_between(b, [lx - 0.05, hd - 0.001, zc - 0.025], [lx + 0.05, hd + 0.001, zc + 0.025], label);
        }
    }
    for (i, &z) in tops.iter().enumerate() {
        // Up to the underside of the next level's beams.
        let clearance = tops.get(i + 1).map(|next| (next - dt - bh) - z);
        b.surface(&format!("level_{}", i + 1), z, [-ix, -hd], [ix, hd], clearance);
    }
    // A load sign on the left front upright.
    let sign = b.material("load_sign", SAFETY_YELLOW, false);
    let (x0, x1) = (-hw + u * 0.15, -hw + u * 0.85);
    decal_between(b, [x0, hd - 0.001, 1.4], [x1, hd + 0.002, 1.4 + (x1 - x0) * 1.4], sign);
    0.0
}

pub(crate) const CABINET: Category = Category {
    name: "cabinet",
    display: "cabinet",
    synonyms: &[
        "storage cabinet",
        "cupboard",
        "supply cabinet",
        "metal cabinet",
        "steel cabinet",
        "utility cabinet",
        "office cabinet",
        "lab cabinet",
        "tool cabinet",
    ],
    tags: &["storage", "furniture", "tall", "office", "lab", "warehouse", "workshop", "kitchen"],
    description: "a tall storage cupboard with two doors and shelves inside",
    is_a: &["furniture", "storage", "cupboard"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.9, 0.4, 1.6, 0.15, "along X"),
        ParamDef::new("depth", 0.45, 0.3, 0.8, 0.1, "along Y"),
        ParamDef::new("height", 1.9, 0.6, 2.2, 0.08, "floor to top"),
        ParamDef::new("plinth", 0.06, 0.02, 0.15, 0.2, "recessed base height"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_cabinet,
};

/// An open-fronted carcass on a recessed plinth with inner shelves, closed by one or two
/// hinged doors (MuJoCo hinge joints, opening outwards up to 100°) with bar handles.
fn build_cabinet(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let pl = fit(b, "cabinet plinth", p.get("plinth"), 0.0, h * 0.1);
    let paint = pick(rng, OFFICE_PAINT);
    let body = b.material("body", paint, true);
    let doors = b.material("doors", shade(paint, 0.96), true);
    let plinth = b.material("plinth", pick(rng, DARK), false);
    let handles = b.material("handles", if rng.chance(0.6) { pick(rng, STEEL) } else { pick(rng, DARK) }, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.018; // door leaf
    let t = 0.018; // carcass panels
    let opening = hd - dt - MOVING_GAP;

    slab(b, [-(hw - 0.02), -hd, 0.0], [hw - 0.02, hd - 0.04, pl], plinth);
    let top = carcass(b, -hw, hw, -hd, opening, pl, h, t, body);
    // Inner shelves about every 40 cm (collision too: a robot can put things inside).
    let inner = h - pl - 2.0 * t;
    let shelves = ((inner / 0.4).round() as usize).saturating_sub(1);
    for k in 1..=shelves {
        let z = pl + t + inner * k as f64 / (shelves + 1) as f64;
        slab(b, [-hw + t * 0.5, -hd + t * 0.75, z - t], [hw - t * 0.5, opening - 0.01, z], body);
    }

    let n_doors = if w < 0.6 { 1 } else { 2 };
    let (edge, gap) = (0.006, 0.004);
    let door_w = (w - 2.0 * edge - gap * (n_doors - 1) as f64) / n_doors as f64;
    let (z0, z1) = (pl + edge, h - edge);
    let handle_h = (0.15f64).min((z1 - z0) * 0.3);
    let handle_z = (1.0f64).min(z1 - 0.12 - handle_h / 2.0).max(z0 + handle_h / 2.0 + 0.02);
    let vents = rng.chance(0.35) && z1 - z0 > 0.5;
    let vent_m = vents.then(|| b.material("vents", shade(INK, 3.0), false));
    let leaf_mass = door_w * (z1 - z0) * dt * 650.0;
    for i in 0..n_doors {
        let x0 = -hw + edge + i as f64 * (door_w + gap);
        // A single door turns on its -X edge; a pair on their outer edges.
        let hinge = if i == 0 { Hinge::MinX } else { Hinge::MaxX };
        let link = hinged_door(
            b,
            &format!("door_{}", i + 1),
            hinge,
            [x0, x0 + door_w],
            [z0, z1],
            hd - dt,
            dt,
            doors,
            handles,
            handle_z,
            leaf_mass,
        );
        // Ventilation louvres low on the door, in the door's frame.
        if let Some(m) = vent_m {
            let xc = if hinge == Hinge::MinX { door_w / 2.0 } else { -door_w / 2.0 };
            let lw = (door_w * 0.5).min(0.25);
            for k in 0..4 {
                let z = 0.08 + k as f64 * 0.025;
                decal_on(b, link, [xc - lw / 2.0, dt / 2.0, z], [xc + lw / 2.0, dt / 2.0 + 0.001, z + 0.008], m);
            }
        }
    }
    b.surface("top", top, [-hw + t / 2.0, -hd], [hw - t / 2.0, opening], None);
    0.0
}

pub(crate) const BOOKSHELF: Category = Category {
    name: "bookshelf",
    display: "bookshelf",
    synonyms: &["bookcase", "book shelf", "book case", "wooden shelf", "display shelf", "wall shelf unit"],
    tags: &["furniture", "storage", "tall", "office", "home", "classroom"],
    description: "a wooden bookcase with shelves for books",
    is_a: &["shelf", "furniture", "bookcase"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.8, 0.4, 1.6, 0.15, "along X"),
        ParamDef::new("depth", 0.3, 0.22, 0.45, 0.1, "along Y"),
        ParamDef::new("height", 1.8, 0.7, 2.4, 0.12, "floor to top"),
        ParamDef::new("board", 0.018, 0.012, 0.03, 0.15, "board thickness"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_bookshelf,
};

/// A closed wooden case: sides, top, back, a plinth and shelves about every 33 cm; each
/// shelf is a surface with clearance to the one above, and the top is one too.
fn build_bookshelf(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let t = fit(b, "bookshelf board", p.get("board"), 0.005, w * 0.05);
    let rgba = if rng.chance(0.75) { pick(rng, WOOD) } else { pick(rng, OFFICE_PAINT) };
    let wood = b.material("wood", rgba, true);
    let back = b.material("back", shade(rgba, 0.85), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bt = 0.006;
    for (x0, x1) in [(-hw, -hw + t), (hw - t, hw)] {
        slab(b, [x0, -hd, 0.0], [x1, hd, h], wood);
    }
    let top = slab(b, [-hw + t / 2.0, -hd, h - t], [hw - t / 2.0, hd, h], wood);
    slab(b, [-hw + t / 2.0, -hd, t * 0.5], [hw - t / 2.0, -hd + bt, h - t * 0.5], back);
    let plinth = (0.07f64).min(h * 0.1);
    slab(b, [-hw + t / 2.0, hd - 0.03 - t, 0.0], [hw - t / 2.0, hd - 0.03, plinth], wood);
    let inner = h - t - plinth;
    let n = ((inner / 0.33).round() as usize).max(2);
    let step = inner / n as f64;
    let mut levels = Vec::with_capacity(n);
    for k in 0..n {
        let z = plinth + step * k as f64 + t;
        levels.push(slab(b, [-hw + t / 2.0, -hd + bt / 2.0, z - t], [hw - t / 2.0, hd, z], wood));
    }
    for (k, z) in levels.iter().enumerate() {
        let next = levels.get(k + 1).copied().unwrap_or(h);
        let clearance = next - t - z;
        b.surface(&format!("level_{}", k + 1), *z, [-hw + t, -hd + bt], [hw - t, hd], Some(clearance));
    }
    b.surface("top", top, [-hw + t / 2.0, -hd], [hw - t / 2.0, hd], None);
    0.0
}

pub(crate) const GONDOLA_SHELF: Category = Category {
    name: "gondola_shelf",
    display: "gondola shelf",
    synonyms: &[
        "gondola",
        "gondola shelving",
        "store shelf",
        "retail shelf",
        "supermarket shelf",
        "grocery shelf",
        "shop shelf",
    ],
    tags: &["retail", "storage", "tall", "shop"],
    description: "a supermarket gondola shelf with several levels for goods",
    is_a: &["shelf", "shelving", "display"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.25, 0.66, 1.33, 0.05, "one bay along X"),
        ParamDef::new("depth", 0.5, 0.35, 0.7, 0.1, "base deck depth along Y, back panel included"),
        ParamDef::new("height", 1.6, 1.2, 2.4, 0.12, "floor to the top of the back panel"),
        ParamDef::new("levels", 4.0, 3.0, 6.0, 0.2, "shelves above the base deck"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_gondola_shelf,
};

/// A pegboard back panel on a kick-plate base, a wide base deck and cantilevered shelves
/// that get shallower towards the top, with price strips on their front edges.
fn build_gondola_shelf(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let n = p.count("levels").clamp(3, 6);
    let paint = pick(rng, &[[0.93, 0.93, 0.91, 1.0], [0.25, 0.26, 0.28, 1.0], [0.72, 0.74, 0.76, 1.0]]);
    let frame = b.material("frame", paint, true);
    let decks = b.material("decks", shade(paint, 0.95), false);
    let strips =
        b.material("price_strips", pick(rng, &[LABEL_WHITE, [0.9, 0.2, 0.15, 1.0], [0.95, 0.8, 0.1, 1.0]]), false);
    let holes = b.material("pegboard", shade(paint, 0.7), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let panel = 0.05;
    slab(b, [-hw, -hd, 0.0], [hw, -hd + panel, h], frame);
    let base_h = 0.15;
    let base = slab(b, [-hw, -hd + panel, 0.0], [hw, hd, base_h], decks);
    decal_between(b, [-hw + 0.01, hd - 0.001, base_h - 0.04], [hw - 0.01, hd + 0.002, base_h - 0.005], strips);
    let step = (h - base_h) / (n as f64 + 0.6);
    let dt = 0.02;
    let mut tops = vec![base];
    for k in 1..=n {
        let z = base_h + step * k as f64;
        let depth = (d - panel) * (1.0 - 0.25 * k as f64 / n as f64);
        let y1 = -hd + panel + depth;
        tops.push(slab(b, [-hw + 0.01, -hd + panel, z - dt], [hw - 0.01, y1, z], decks));
        decal_between(b, [-hw + 0.012, y1 - 0.001, z - 0.04], [hw - 0.012, y1 + 0.002, z - 0.002], strips);
    }
    // Pegboard holes on the panel face above the base.
    let rows = ((h - base_h - 0.1) / 0.1) as usize;
    for r in 0..rows {
        let z = base_h + 0.06 + r as f64 * 0.1;
        decal_between(b, [-hw + 0.03, -hd + panel - 0.0005, z], [hw - 0.03, -hd + panel + 0.001, z + 0.006], holes);
    }
    for k in 0..tops.len() {
        let z = tops[k];
        let (x0, x1) = if k == 0 { (-hw, hw) } else { (-hw + 0.01, hw - 0.01) };
        let y1 = if k == 0 { hd } else { -hd + panel + (d - panel) * (1.0 - 0.25 * k as f64 / n as f64) };
        let clearance = tops.get(k + 1).map(|next| next - dt - z);
        let name = if k == 0 { "base_deck".to_string() } else { format!("level_{k}") };
        b.surface(&name, z, [x0, -hd + panel], [x1, y1], clearance);
    }
    0.0
}

pub(crate) const LOCKER: Category = Category {
    name: "locker",
    display: "locker",
    synonyms: &[
        "lockers",
        "steel locker",
        "locker bank",
        "staff locker",
        "gym locker",
        "wardrobe locker",
        "locker cabinet",
    ],
    tags: &["storage", "tall", "office", "workshop", "hospital", "classroom"],
    description: "a tall steel locker with a door for staff belongings",
    is_a: &["cabinet", "furniture", "storage"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.9, 0.3, 1.6, 0.2, "along X, all columns"),
        ParamDef::new("depth", 0.45, 0.3, 0.6, 0.08, "along Y, doors included"),
        ParamDef::new("height", 1.8, 0.9, 2.0, 0.06, "floor to top"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_locker,
};

/// Columns about 30 cm wide, each a compartment with a hinged steel door (a joint),
/// ventilation slots and a handle, on a plinth.
fn build_locker(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(
        rng,
        &[
            [0.75, 0.77, 0.79, 1.0],
            [0.2, 0.35, 0.6, 1.0],
            [0.3, 0.5, 0.35, 1.0],
            [0.85, 0.3, 0.15, 1.0],
            [0.3, 0.31, 0.33, 1.0],
        ],
    );
    let body = b.material("body", shade(paint, 0.9), true);
    let doors = b.material("doors", paint, true);
    let handles = b.material("handles", pick(rng, DARK), false);
    let vents = b.material("vents", shade(INK, 2.0), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let dt = 0.02;
    let opening = hd - dt - MOVING_GAP;
    let t = 0.012;
    let pl = 0.08f64.min(h * 0.08);
    slab(b, [-hw + 0.01, -hd, 0.0], [hw - 0.01, opening - 0.02, pl], body);
    let top = carcass(b, -hw, hw, -hd, opening, pl, h, t, body);
    let n = ((w / 0.3).round() as usize).max(1);
    let cw = w / n as f64;
    for k in 1..n {
        let x = -hw + cw * k as f64;
        slab(b, [x - t / 2.0, -hd + t * 0.75, pl + t * 0.75], [x + t / 2.0, opening, h - t * 0.75], body);
    }
    for k in 0..n {
        let x0 = -hw + cw * k as f64 + 0.003;
        let x1 = x0 + cw - 0.006;
        let link = hinged_door(
            b,
            &format!("door_{}", k + 1),
            Hinge::MinX,
            [x0, x1],
            [pl + 0.003, h - 0.003],
            hd - dt,
            dt,
            doors,
            handles,
            1.1,
            (cw * h * 8.0).max(1.0),
        );
        for s in 0..5 {
            let z = h - pl - 0.15 - s as f64 * 0.02;
            decal_on(b, link, [cw * 0.3, dt / 2.0, z], [cw * 0.7, dt / 2.0 + 0.001, z + 0.008], vents);
        }
    }
    b.surface("top", top, [-hw + t / 2.0, -hd], [hw - t / 2.0, opening], None);
    0.0
}
