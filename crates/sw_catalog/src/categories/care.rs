//! Hospital and shop fixtures: hospital beds, IV poles, checkout counters and vending
//! machines.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{Axis, DARK, GLASS, INK, LABEL_WHITE, STEEL, collider_between, decal_between, pick, rod, shade, slab};
use super::shapes::{prism, rounded_rect};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const HOSPITAL_BED: Category = Category {
    name: "hospital_bed",
    display: "hospital bed",
    synonyms: &["patient bed", "medical bed", "care bed", "stretcher", "gurney"],
    tags: &["hospital", "medical", "furniture"],
    description: "an adjustable hospital bed with side rails",
    is_a: &["bed", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.0, 0.8, 1.6, 0.06, "along X"),
        ParamDef::new("depth", 2.15, 1.9, 2.3, 0.03, "along Y, the head board at -Y"),
        ParamDef::new("height", 1.0, 0.8, 1.2, 0.05, "floor to the top of the head board"),
        ParamDef::new("mattress_height", 0.6, 0.45, 0.85, 0.08, "floor to the top of the mattress"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_hospital_bed,
};

/// A frame on four casters, a mattress with a raised head section, head and foot boards
/// and side rails. The head is against the wall (-Y).
fn build_hospital_bed(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let mh = p.get("mattress_height").min(h - 0.15);
    let frame = b.material("frame", pick(rng, STEEL), false);
    let boards = b.material(
        "boards",
        pick(rng, &[[0.92, 0.92, 0.9, 1.0], [0.55, 0.4, 0.28, 1.0], [0.6, 0.75, 0.85, 1.0]]),
        true,
    );
    let mattress = b.material(
        "mattress",
        pick(rng, &[[0.55, 0.7, 0.85, 1.0], [0.9, 0.9, 0.88, 1.0], [0.3, 0.4, 0.55, 1.0]]),
        true,
    );
    let wheels = b.material("casters", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bt = 0.04;
    let (my0, my1) = (-hd + bt, hd - bt);
    let mt = 0.14f64.min(mh * 0.3);
    // Casters, frame, deck.
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * (hw - 0.08), sy * (hd - 0.15));
        rod(b, [x, y, 0.05], 0.05, 0.035, Axis::X, wheels);
        collider_between(b, [x - 0.02, y - 0.025, 0.0], [x + 0.02, y + 0.025, 0.1]);
        slab(b, [x - 0.02, y - 0.02, 0.099], [x + 0.02, y + 0.02, mh - mt - 0.05], frame);
    }
    slab(b, [-hw + 0.04, my0, mh - mt - 0.06], [hw - 0.04, my1, mh - mt], frame);
    let top = slab(b, [-hw + 0.05, my0 + 0.7, mh - mt], [hw - 0.05, my1, mh], mattress);
    // The raised head section: a wedge of mattress.
    let raise = 0.2f64.min(h - mh - 0.02);
    let wedge =
        prism_y(&[[my0, mh - mt], [my0 + 0.701, mh - mt], [my0 + 0.701, mh], [my0, mh + raise]], -hw + 0.05, hw - 0.05);
    b.visual_mesh_on(0, &wedge, Pose::IDENTITY, mattress);
    collider_between(b, [-hw + 0.05, my0, mh - mt], [hw - 0.05, my0 + 0.7, mh + raise * 0.5]);
    // Head and foot boards, side rails along the head half.
    slab(b, [-hw, -hd, mh - mt - 0.1], [hw, -hd + bt, h], boards);
    slab(b, [-hw, hd - bt, mh - mt - 0.1], [hw, hd, mh + 0.2f64.min(h - mh)], boards);
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 { (-hw, -hw + 0.03) } else { (hw - 0.03, hw) };
        slab(b, [x0, my0 + 0.1, mh - 0.05], [x1, my0 + 0.9, mh + 0.25f64.min(h - mh)], boards);
    }
    b.surface("mattress", top, [-hw + 0.05, my0 + 0.7], [hw - 0.05, my1], None);
    0.0
}

/// A prism lying across X: the polygon `outline` in the YZ plane (`[y, z]` points)
/// extruded from `x0` to `x1`.
fn prism_y(outline: &[[f64; 2]], x0: f64, x1: f64) -> sw_geom::Mesh {
    let mut m = prism(outline, x0, x1);
    for v in &mut m.vertices {
        *v = [v[2], v[0], v[1]];
    }
    m
}

pub(crate) const IV_POLE: Category = Category {
    name: "iv_pole",
    display: "iv pole",
    synonyms: &["iv stand", "drip stand", "infusion stand", "iv drip", "infusion pole", "drip pole"],
    tags: &["hospital", "medical", "tall", "round"],
    description: "a wheeled iv drip stand",
    is_a: &["pole", "stand", "medical equipment"],
    kind: Kind::Fixture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.55, 0.45, 0.7, 0.06, "base diameter"),
        ParamDef::new("depth", 0.55, 0.45, 0.7, 0.06, "base diameter (as width)"),
        ParamDef::new("height", 1.9, 1.5, 2.2, 0.06, "to the top of the hooks"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_iv_pole,
};

/// A five-leg base on casters, a steel pole, a hook crown with an infusion bag.
fn build_iv_pole(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let steel = b.material("steel", pick(rng, STEEL), true);
    let dark = b.material("base", pick(rng, DARK), false);
    let bag = b.material("bag", [0.88, 0.92, 0.95, 1.0], false);
    let fluid = b.material("fluid", pick(rng, &[[0.95, 0.9, 0.6, 1.0], [0.85, 0.95, 0.9, 1.0]]), false);
    for k in 0..5 {
        let a = std::f64::consts::TAU * k as f64 / 5.0 + std::f64::consts::FRAC_PI_2;
        let leg = Shape::Box { half: [r * 0.45, 0.018, 0.015] };
        let c = [r * 0.45 * a.cos(), r * 0.45 * a.sin(), 0.07];
        b.visual(leg, Pose::from_pos_yaw(c, a), dark);
        let (x, y) = (r * 0.9 * a.cos(), r * 0.9 * a.sin());
        rod(b, [x, y, 0.03], 0.03, 0.025, Axis::Z, dark);
        collider_between(b, [x - 0.025, y - 0.025, 0.0], [x + 0.025, y + 0.025, 0.06]);
    }
    // The legs collide as a disc under the pole; the bounds come from the ring.
    b.collision_on(0, Shape::Cylinder { radius: r, half_height: 0.008 }, Pose::from_pos([0.0, 0.0, 0.077]));
    rod(b, [0.0, 0.0, (0.08 + h - 0.05) / 2.0], 0.013, h - 0.13, Axis::Z, steel);
    b.collision_on(
        0,
        Shape::Cylinder { radius: 0.013, half_height: (h - 0.17) / 2.0 },
        Pose::from_pos([0.0, 0.0, 0.085 + (h - 0.17) / 2.0]),
    );
    for k in 0..4 {
        let a = std::f64::consts::FRAC_PI_2 * k as f64;
        let arm = Shape::Box { half: [0.08, 0.005, 0.005] };
        b.solid(arm, Pose::from_pos_yaw([0.08 * a.cos(), 0.08 * a.sin(), h - 0.04], a), steel);
        b.solid(
            Shape::Cylinder { radius: 0.005, half_height: 0.02 },
            Pose::from_pos([0.155 * a.cos(), 0.155 * a.sin(), h - 0.02]),
            steel,
        );
    }
    let bag_mesh = prism(&rounded_rect(0.06, 0.015, 0.012, 3), h - 0.3, h - 0.07);
    b.visual_mesh_on(0, &bag_mesh, Pose::from_pos([0.155, 0.0, 0.0]), bag);
    b.visual_mesh_on(
        0,
        &prism(&rounded_rect(0.055, 0.013, 0.01, 3), h - 0.295, h - 0.2),
        Pose::from_pos([0.155, 0.0, 0.0]),
        fluid,
    );
    4.5
}

pub(crate) const CHECKOUT_COUNTER: Category = Category {
    name: "checkout_counter",
    display: "checkout counter",
    synonyms: &[
        "checkout",
        "cash desk",
        "checkout desk",
        "cash register counter",
        "point of sale",
        "reception desk",
        "service desk",
    ],
    tags: &["retail", "office", "furniture", "surface"],
    description: "a shop checkout counter with a till",
    is_a: &["counter", "desk", "furniture"],
    kind: Kind::Furniture,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 2.2, 1.2, 3.5, 0.1, "along X"),
        ParamDef::new("depth", 0.9, 0.6, 1.2, 0.06, "along Y"),
        ParamDef::new("height", 1.35, 1.1, 1.6, 0.04, "floor to the top of the screen"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_checkout_counter,
};

/// A counter with a belt in the middle, a scanner and a cash register at the +X end and
/// a customer display; the packing end at -X is a free surface.
fn build_checkout_counter(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body =
        b.material("body", pick(rng, &[[0.85, 0.86, 0.87, 1.0], [0.25, 0.26, 0.28, 1.0], [0.6, 0.45, 0.3, 1.0]]), true);
    let top_m = b.material("top", [0.72, 0.73, 0.75, 1.0], false);
    let belt = b.material("belt", [0.08, 0.08, 0.09, 1.0], false);
    let ink = b.material("screens", INK, false);
    let reg = b.material("register", pick(rng, &[[0.2, 0.2, 0.22, 1.0], [0.9, 0.9, 0.88, 1.0]]), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let ch = 0.9f64.min(h - 0.3);
    slab(b, [-hw, -hd, 0.0], [hw, hd, ch - 0.03], body);
    let top = slab(b, [-hw, -hd, ch - 0.03], [hw, hd, ch], top_m);
    // The belt strip along X, 2 cm up, from the -X third to the register.
    let (bx0, bx1) = (-hw + w * 0.35, hw - 0.6f64.min(w * 0.3));
    slab(b, [bx0, -hd * 0.6, ch], [bx1, hd * 0.6, ch + 0.02], belt);
    // The register and its screen at the +X end.
    let rx = bx1 + 0.05;
    slab(b, [rx, -hd * 0.6, ch], [hw - 0.05, hd * 0.2, ch + 0.12], reg);
    slab(b, [rx + 0.05, -hd * 0.3, ch + 0.12], [hw - 0.1, -hd * 0.3 + 0.04, h], reg);
    decal_between(b, [rx + 0.07, -hd * 0.3 - 0.002, ch + 0.2], [hw - 0.12, -hd * 0.3 + 0.0005, h - 0.02], ink);
    let scanner = b.material("scanner", GLASS, false);
    decal_between(b, [bx1 - 0.25, -hd * 0.3, ch + 0.0195], [bx1 - 0.05, hd * 0.3, ch + 0.022], scanner);
    b.surface("packing_area", top, [-hw, -hd], [bx0, hd], None);
    0.0
}

pub(crate) const VENDING_MACHINE: Category = Category {
    name: "vending_machine",
    display: "vending machine",
    synonyms: &["snack machine", "drinks machine", "soda machine", "vending unit", "beverage machine", "drink machine"],
    tags: &["retail", "office", "appliance", "tall"],
    description: "a snack and drinks vending machine",
    is_a: &["machine", "dispenser", "appliance"],
    kind: Kind::LargeAppliance,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 0.9, 0.6, 1.3, 0.1, "along X"),
        ParamDef::new("depth", 0.8, 0.6, 0.95, 0.06, "along Y"),
        ParamDef::new("height", 1.83, 1.6, 2.0, 0.03, "floor to top"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_vending_machine,
};

/// A cabinet with a glass front over rows of products, a keypad and coin panel on the
/// right, and the pickup flap below.
fn build_vending_machine(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint =
        pick(rng, &[[0.8, 0.1, 0.1, 1.0], [0.15, 0.15, 0.16, 1.0], [0.15, 0.35, 0.65, 1.0], [0.9, 0.9, 0.88, 1.0]]);
    let body = b.material("body", paint, true);
    let glass = b.material("window", GLASS, false);
    let panel = b.material("panel", shade(paint, 0.7), false);
    let white = b.material("keys", LABEL_WHITE, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top = slab(b, [-hw, -hd, 0.0], [hw, hd, h], body);
    let pw = (w * 0.25).min(0.25);
    let (gx0, gx1, gz0, gz1) = (-hw + 0.05, hw - pw - 0.03, 0.45, h - 0.12);
    decal_between(b, [gx0, hd - 0.001, gz0], [gx1, hd + 0.002, gz1], glass);
    let rows = ((gz1 - gz0) / 0.22) as usize;
    let cols = ((gx1 - gx0) / 0.1) as usize;
    let colors = [[0.9, 0.2, 0.1, 1.0], [0.95, 0.8, 0.1, 1.0], [0.2, 0.5, 0.9, 1.0], [0.2, 0.7, 0.3, 1.0]];
    for r in 0..rows {
        let m = b.material(&format!("products_{}", r + 1), pick(rng, &colors), false);
        let z = gz0 + 0.03 + r as f64 * 0.22;
        for c in 0..cols {
            let x = gx0 + 0.05 + c as f64 * 0.1;
            decal_between(b, [x - 0.03, hd + 0.002, z], [x + 0.03, hd + 0.0035, z + 0.12], m);
        }
    }
    decal_between(b, [hw - pw, hd - 0.001, gz0], [hw - 0.03, hd + 0.002, gz1], panel);
    for k in 0..12 {
        let (i, j) = ((k % 3) as f64, (k / 3) as f64);
        let (x, z) = (hw - pw + pw * (0.12 + i * 0.26), gz1 - 0.25 - j * 0.05);
        decal_between(b, [x, hd + 0.002, z], [x + pw * 0.2, hd + 0.004, z + 0.035], white);
    }
    decal_between(b, [gx0, hd - 0.001, 0.12], [gx1, hd + 0.002, 0.32], panel);
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    0.0
}
