//! Things on wheels: forklifts, pallet jacks, hand trucks, utility carts and shopping
//! carts. Wheels are drawn round and collide as boxes from the floor to the axle, so a
//! parked cart stands still (it has no wheel joints to roll on).

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::kit::{
    Axis, DARK, INDUSTRIAL_PAINT, RUBBER, SAFETY_YELLOW, STEEL, collider_between, decal_between, pick, rod, shade,
    slab, strut,
};
use super::shapes::{ROUND, revolve, rounded_ring_profile};
use crate::{Category, Kind, ParamDef, Params};

/// A wheel of radius `r` and width `wd` on an axle along X at `center` (it rolls along
/// Y): a tyre ring and a hub to look at, a box from the floor to the axle to stand on.
fn wheel(b: &mut AssetBuilder, center: [f64; 3], r: f64, wd: f64, materials: [usize; 2]) {
    wheel_on(b, center, r, wd, Axis::X, materials);
}

/// [`wheel`] with the axle along `axle` (X or Y).
fn wheel_on(b: &mut AssetBuilder, center: [f64; 3], r: f64, wd: f64, axle: Axis, [tyre, hub]: [usize; 2]) {
    let pose = super::kit::along(center, axle);
    let ring = revolve(&rounded_ring_profile(r * 0.55, r, -wd / 2.0, wd / 2.0, (wd * 0.3).min(r * 0.2)), ROUND);
    b.visual_mesh_on(0, &ring, pose, tyre);
    b.visual(sw_geom::Shape::Cylinder { radius: r * 0.56, half_height: wd * 0.4 }, pose, hub);
    let (x, y) = (center[0], center[1]);
    let (hx, hy) = if axle == Axis::X { (wd / 2.0, r * 0.5) } else { (r * 0.5, wd / 2.0) };
    collider_between(b, [x - hx, y - hy, 0.0], [x + hx, y + hy, center[2]]);
}

pub(crate) const FORKLIFT: Category = Category {
    name: "forklift",
    display: "forklift",
    synonyms: &["fork lift", "forklift truck", "lift truck", "fork truck", "reach truck", "counterbalance forklift"],
    tags: &["warehouse", "logistics", "vehicle", "heavy", "industrial"],
    description: "a forklift truck for lifting pallets",
    is_a: &["vehicle", "truck"],
    kind: Kind::Vehicle,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 1.15, 0.9, 1.5, 0.06, "along X"),
        ParamDef::new("depth", 3.2, 2.4, 4.0, 0.05, "along Y, forks included (they point +Y)"),
        ParamDef::new("height", 2.15, 1.9, 2.5, 0.03, "to the top of the overhead guard or mast"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_forklift,
};

/// A counterbalance truck: chassis and counterweight at the back, overhead guard over
/// the seat, the mast at the front with the carriage lowered and the forks on the floor.
fn build_forklift(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint =
        pick(rng, &[[0.95, 0.75, 0.1, 1.0], [0.93, 0.45, 0.1, 1.0], [0.75, 0.15, 0.12, 1.0], [0.15, 0.35, 0.6, 1.0]]);
    let body = b.material("body", paint, true);
    let dark = b.material("frame", pick(rng, DARK), false);
    let tyre = b.material("tyres", pick(rng, RUBBER), false);
    let hub = b.material("hubs", [0.75, 0.76, 0.78, 1.0], false);
    let seat = b.material("seat", [0.1, 0.1, 0.1, 1.0], false);
    let forks = b.material("forks", [0.25, 0.26, 0.28, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let fork_len = (d * 0.34).min(1.2);
    let y_mast = hd - fork_len;
    let (y_back, y_front) = (-hd, y_mast - 0.12);
    let r = 0.3f64.min(h * 0.14);
    // Chassis, counterweight, engine hood.
    slab(b, [-hw + 0.08, y_back + 0.15, 0.12], [hw - 0.08, y_front, 0.75], body);
    slab(b, [-hw, y_back, 0.12], [hw, y_back + 0.5, 1.05], body);
    slab(b, [-hw + 0.1, y_back + 0.45, 0.74], [hw - 0.1, y_back + 1.0, 0.95], body);
    // Seat and steering column under the guard.
    slab(b, [-0.22, y_back + 0.95, 0.74], [0.22, y_back + 1.4, 0.85], seat);
    slab(b, [-0.22, y_back + 0.95, 0.84], [0.22, y_back + 1.05, 1.3], seat);
    strut(b, [0.0, y_front - 0.3, 0.75], [0.0, y_front - 0.45, 1.25], [0.06, 0.06], Axis::X, dark, true);
    rod(b, [0.0, y_front - 0.47, 1.27], 0.17, 0.03, Axis::Z, dark);
    // Overhead guard: four posts and a slatted roof.
    let (gy0, gy1) = (y_back + 0.7, y_front - 0.05);
    let gh = h - 0.05;
    for x in [-hw + 0.06, hw - 0.1] {
        for y in [gy0, gy1 - 0.04] {
            slab(b, [x, y, 0.74], [x + 0.04, y + 0.04, gh], dark);
        }
    }
    slab(b, [-hw + 0.05, gy0 - 0.01, gh], [hw - 0.05, gy1 + 0.01, gh + 0.05], dark);
    // Wheels: drive wheels under the mast, steer wheels under the counterweight.
    for (y, rr) in [(y_front - r - 0.05, r), (y_back + 0.5, r * 0.85)] {
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - 0.12);
            wheel(b, [x, y, rr], rr, 0.2, [tyre, hub]);
        }
    }
    // Mast, carriage and forks.
    let mast_h = h - 0.02;
    for x in [-hw + 0.15, hw - 0.27] {
        slab(b, [x, y_mast - 0.12, 0.08], [x + 0.12, y_mast - 0.02, mast_h], dark);
    }
    slab(b, [-hw + 0.15, y_mast - 0.02, 0.05], [hw - 0.15, y_mast + 0.03, 0.6], forks);
    for x in [-0.3f64.min(hw * 0.5), 0.3f64.min(hw * 0.5) - 0.1] {
        slab(b, [x, y_mast + 0.03, 0.0], [x + 0.1, hd, 0.045], forks);
        slab(b, [x, y_mast + 0.029, 0.044], [x + 0.1, y_mast + 0.075, 0.6], forks);
    }
    let warn = b.material("stripes", SAFETY_YELLOW, false);
    decal_between(b, [-hw + 0.02, y_back - 0.002, 0.2], [hw - 0.02, y_back + 0.001, 0.28], warn);
    0.0
}

pub(crate) const PALLET_JACK: Category = Category {
    name: "pallet_jack",
    display: "pallet jack",
    synonyms: &["pallet truck", "hand pallet truck", "pump truck", "hand jack", "pallet mover", "jigger"],
    tags: &["warehouse", "logistics", "vehicle", "industrial"],
    description: "a manual pallet jack for moving pallets",
    is_a: &["truck", "trolley"],
    kind: Kind::Vehicle,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.54, 0.45, 0.7, 0.05, "over the forks, along X"),
        ParamDef::new("depth", 1.55, 1.2, 1.9, 0.05, "forks and pump unit along Y (forks point +Y)"),
        ParamDef::new("height", 1.22, 1.0, 1.35, 0.04, "to the top of the handle"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_pallet_jack,
};

/// Two lowered forks with load rollers, the pump unit and steering wheel at the back, and
/// an upright tiller handle.
fn build_pallet_jack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint =
        pick(rng, &[[0.9, 0.45, 0.1, 1.0], [0.85, 0.15, 0.1, 1.0], [0.95, 0.75, 0.1, 1.0], [0.15, 0.35, 0.6, 1.0]]);
    let body = b.material("body", paint, true);
    let dark = b.material("handle", pick(rng, DARK), false);
    let tyre = b.material("wheels", pick(rng, RUBBER), false);
    let hub = b.material("hubs", [0.7, 0.71, 0.73, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let fw = (w * 0.3).min(0.17);
    let y_body = -hd + 0.35;
    let fh = 0.085;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 { (-hw, -hw + fw) } else { (hw - fw, hw) };
        slab(b, [x0, y_body, 0.0], [x1, hd, fh], body);
    }
    slab(b, [-hw, y_body - 0.12, 0.02], [hw, y_body + 0.001, fh + 0.05], body);
    slab(b, [-0.09, -hd + 0.1, 0.1], [0.09, y_body - 0.05, 0.38], body);
    wheel(b, [0.0, -hd + 0.1, 0.1], 0.1, 0.16, [tyre, hub]);
    // The tiller: a bar up from the pump with a loop grip.
    strut(b, [0.0, -hd + 0.2, 0.36], [0.0, -hd + 0.05, h - 0.1], [0.04, 0.04], Axis::X, dark, true);
    slab(b, [-0.12, -hd, h - 0.12], [0.12, -hd + 0.05, h], dark);
    // 2 mm steel forks plus the pump: about 70 kg for a 1.15 m truck.
    45.0 + 20.0 * d
}

pub(crate) const HAND_TRUCK: Category = Category {
    name: "hand_truck",
    display: "hand truck",
    synonyms: &["sack truck", "dolly", "two-wheeler", "hand trolley", "box dolly", "appliance dolly", "sack trolley"],
    tags: &["warehouse", "logistics", "vehicle", "retail"],
    description: "a two-wheeled hand truck for moving boxes",
    is_a: &["trolley", "dolly"],
    kind: Kind::Vehicle,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.5, 0.4, 0.65, 0.05, "along X"),
        ParamDef::new("depth", 0.42, 0.3, 0.55, 0.06, "wheels and nose plate along Y"),
        ParamDef::new("height", 1.2, 0.9, 1.5, 0.06, "to the top of the handle"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_hand_truck,
};

/// Standing upright: two rails with cross bars, a nose plate on the floor in front (+Y)
/// and two wheels behind.
fn build_hand_truck(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let frame = b.material(
        "frame",
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.85, 0.15, 0.1, 1.0], [0.15, 0.35, 0.6, 1.0], [0.75, 0.76, 0.78, 1.0]]),
        true,
    );
    let plate = b.material("nose_plate", pick(rng, STEEL), false);
    let tyre = b.material("tyres", pick(rng, RUBBER), false);
    let hub = b.material("hubs", [0.75, 0.76, 0.78, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = (d * 0.3).min(0.13);
    let y_frame = -hd + r;
    // Nose plate from the frame to the front edge.
    slab(b, [-hw * 0.7, y_frame - 0.02, 0.0], [hw * 0.7, hd, 0.01], plate);
    for x in [-hw + 0.06, hw - 0.09] {
        slab(b, [x, y_frame - 0.02, 0.009], [x + 0.03, y_frame + 0.01, h], frame);
    }
    for k in 0..4 {
        let z = 0.2 + (h - 0.35) * k as f64 / 3.0;
        slab(b, [-hw + 0.09, y_frame - 0.015, z], [hw - 0.09, y_frame + 0.005, z + 0.02], frame);
    }
    for sx in [-1.0, 1.0] {
        wheel(b, [sx * (hw - 0.04), y_frame, r], r, 0.08, [tyre, hub]);
    }
    collider_between(b, [-hw + 0.08, -hd, r - 0.02], [hw - 0.08, y_frame - 0.02, r + 0.02]);
    8.0 + 4.0 * h
}

pub(crate) const CART: Category = Category {
    name: "cart",
    display: "cart",
    synonyms: &[
        "utility cart",
        "service cart",
        "trolley",
        "platform cart",
        "push cart",
        "lab cart",
        "tool cart",
        "medical cart",
    ],
    tags: &["warehouse", "lab", "hospital", "workshop", "storage", "mobile", "surface"],
    description: "a wheeled utility cart with shelves",
    is_a: &["trolley", "vehicle"],
    kind: Kind::Vehicle,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.9, 0.6, 1.2, 0.1, "shelf length along X, the handle included"),
        ParamDef::new("depth", 0.5, 0.4, 0.7, 0.08, "along Y"),
        ParamDef::new("height", 0.95, 0.8, 1.1, 0.05, "to the top of the push handle"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_cart,
};

/// Two trays with raised lips on four posts and casters, a push handle at the -X end.
fn build_cart(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let rgba =
        pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.2, 0.35, 0.65, 1.0], [0.75, 0.76, 0.78, 1.0], [0.6, 0.1, 0.1, 1.0]]);
    let trays = b.material("trays", rgba, true);
    let posts = b.material("posts", pick(rng, STEEL), false);
    let tyre = b.material("casters", pick(rng, RUBBER), false);
    let hub = b.material("caster_hubs", [0.7, 0.71, 0.73, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = 0.05;
    let hx = -hw + 0.025; // the handle's plane
    let (x0, x1) = (hx, hw);
    let tops_z = [0.2, (h - 0.12).max(0.5)];
    let mut levels = Vec::new();
    for &z in &tops_z {
        levels.push(slab(b, [x0, -hd, z - 0.02], [x1, hd, z], trays));
        for (ya, yb) in [(-hd, -hd + 0.012), (hd - 0.012, hd)] {
            decal_between(b, [x0 + 0.001, ya, z], [x1 - 0.001, yb, z + 0.03], trays);
        }
    }
    for x in [x0 + 0.01, x1 - 0.03] {
        for y in [-hd + 0.01, hd - 0.03] {
            slab(b, [x, y, 2.0 * r], [x + 0.02, y + 0.02, tops_z[1] - 0.019], posts);
        }
    }
    // Casters rolling along X, under the trays' corners.
    for x in [x0 + r + 0.01, x1 - r - 0.01] {
        for y in [-hd + 0.03, hd - 0.03] {
            wheel_on(b, [x, y, r], r, 0.03, Axis::Y, [tyre, hub]);
            slab(b, [x - 0.015, y - 0.015, 2.0 * r - 0.01], [x + 0.015, y + 0.015, 0.18], posts);
        }
    }
    // The push handle: two uprights and a grip bar beyond the -X end.
    for y in [-hd + 0.03, hd - 0.05] {
        slab(b, [-hw, y, tops_z[1] - 0.02], [-hw + 0.025, y + 0.02, h], posts);
    }
    slab(b, [-hw, -hd + 0.03, h - 0.03], [-hw + 0.025, hd - 0.03, h - 0.001], posts);
    let m = 0.012;
    b.surface("top_shelf", levels[1], [x0 + m, -hd + m], [x1 - m, hd - m], None);
    b.surface(
        "bottom_shelf",
        levels[0],
        [x0 + 0.04, -hd + 0.035],
        [x1 - 0.035, hd - 0.035],
        Some(tops_z[1] - 0.02 - levels[0]),
    );
    (w * d * 30.0 + 6.0).min(40.0)
}

pub(crate) const SHOPPING_CART: Category = Category {
    name: "shopping_cart",
    display: "shopping cart",
    synonyms: &["shopping trolley", "grocery cart", "supermarket trolley", "supermarket cart", "shopping basket cart"],
    tags: &["retail", "vehicle", "container", "open"],
    description: "a supermarket shopping cart",
    is_a: &["cart", "trolley"],
    kind: Kind::Vehicle,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.56, 0.45, 0.65, 0.04, "along X"),
        ParamDef::new("depth", 0.95, 0.7, 1.05, 0.04, "along Y, the handle at -Y"),
        ParamDef::new("height", 1.0, 0.85, 1.1, 0.03, "to the handle"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_shopping_cart,
};

/// A wire basket (open: a floor and four walls) on a chassis with four casters and a
/// handle with a coloured grip at the back.
fn build_shopping_cart(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let wire = b.material("wire", [0.78, 0.79, 0.8, 1.0], false);
    let grip = b.material(
        "grip",
        pick(rng, &[[0.8, 0.1, 0.1, 1.0], [0.1, 0.35, 0.7, 1.0], [0.15, 0.55, 0.25, 1.0], [0.95, 0.6, 0.1, 1.0]]),
        true,
    );
    let tyre = b.material("casters", pick(rng, RUBBER), false);
    let hub = b.material("caster_hubs", shade(pick(rng, INDUSTRIAL_PAINT), 0.8), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let r = 0.06;
    let (bz0, bz1) = (0.45f64.min(h - 0.35), h - 0.08);
    let (by0, by1) = (-hd + 0.04, hd);
    let t = 0.008;
    let floor = slab(b, [-hw, by0, bz0], [hw, by1, bz0 + t], wire);
    for (x0, x1) in [(-hw, -hw + t), (hw - t, hw)] {
        slab(b, [x0, by0 + 0.0005, bz0 + t * 0.5], [x1, by1 - 0.0005, bz1], wire);
    }
    for (y0, y1) in [(by0, by0 + t), (by1 - t, by1)] {
        slab(b, [-hw + t * 0.5, y0, bz0 + t * 0.6], [hw - t * 0.5, y1, bz1 + 0.0005], wire);
    }
    // Wire grid drawn on the side walls.
    for k in 1..8 {
        let y = by0 + (by1 - by0) * k as f64 / 8.0;
        for x in [-hw - 0.002, hw - 0.0005] {
            decal_between(b, [x, y - 0.003, bz0], [x + 0.0025, y + 0.003, bz1], wire);
        }
    }
    // Chassis: two rails from the casters up to the basket.
    for x in [-hw + 0.05, hw - 0.07] {
        slab(b, [x, -hd + 0.1, 2.0 * r], [x + 0.02, hd - 0.1, 2.0 * r + 0.03], wire);
        strut(
            b,
            [x + 0.01, -hd + 0.12, 2.0 * r + 0.02],
            [x + 0.01, by0 + 0.05, bz0 - 0.005],
            [0.03, 0.02],
            Axis::X,
            wire,
            true,
        );
        for y in [-hd + 0.12, hd - 0.12] {
            wheel(b, [x + 0.01, y, r], r, 0.035, [tyre, hub]);
        }
    }
    // The handle behind the basket.
    slab(b, [-hw, -hd, h - 0.03], [hw, -hd + 0.035, h], grip);
    for x in [-hw + 0.01, hw - 0.03] {
        slab(b, [x, -hd + 0.02, bz1 - 0.05], [x + 0.02, by0 + 0.002, h - 0.029], wire);
    }
    let m = t + 0.01;
    b.surface("basket", floor, [-hw + m, by0 + m], [hw - m, by1 - m], None);
    14.0
}
