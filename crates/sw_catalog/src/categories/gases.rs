//! Compressed gas: cylinders (free, standing) and the racks that hold them.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{Axis, SAFETY_YELLOW, STEEL, pick, rod, slab};
use super::parts::round_collider;
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

/// Cylinder body and shoulder colours by gas (EN 1089-3 shoulders, US bodies mixed):
/// oxygen, nitrogen, argon, CO2, acetylene, helium.
const GAS_COLOURS: &[([f32; 4], [f32; 4])] = &[
    ([0.15, 0.15, 0.16, 1.0], [0.95, 0.95, 0.95, 1.0]),
    ([0.55, 0.56, 0.58, 1.0], [0.1, 0.1, 0.1, 1.0]),
    ([0.2, 0.45, 0.3, 1.0], [0.15, 0.5, 0.3, 1.0]),
    ([0.55, 0.56, 0.58, 1.0], [0.55, 0.56, 0.58, 1.0]),
    ([0.45, 0.12, 0.12, 1.0], [0.5, 0.1, 0.1, 1.0]),
    ([0.55, 0.4, 0.2, 1.0], [0.55, 0.4, 0.2, 1.0]),
];

/// One cylinder drawn at `xy`: the body, a coloured shoulder, the valve and its cap.
/// Returns the top of the body collision.
fn cylinder_body(b: &mut AssetBuilder, xy: [f64; 2], r: f64, h: f64, [body, shoulder, valve]: [usize; 3]) -> f64 {
    let zs = h - r * 1.1 - 0.12f64.min(h * 0.15);
    let at = Pose::from_pos([xy[0], xy[1], 0.0]);
    b.visual_mesh_on(0, &revolve(&[[0.0, 0.0], [r * 0.92, 0.0], [r, 0.02], [r, zs], [0.0, zs]], ROUND), at, body);
    let top = zs + r * 1.1;
    let dome =
        revolve(&[[0.0, zs - 0.001], [r, zs - 0.001], [r * 0.85, zs + r * 0.6], [r * 0.3, top], [0.0, top]], ROUND);
    b.visual_mesh_on(0, &dome, at, shoulder);
    let cap =
        revolve(&[[0.0, top - 0.005], [r * 0.45, top - 0.005], [r * 0.45, h - r * 0.2], [r * 0.3, h], [0.0, h]], ROUND);
    b.visual_mesh_on(0, &cap, at, valve);
    round_collider(b, 0, xy, r, 0.0, zs);
    b.collision_on(
        0,
        Shape::Cylinder { radius: r * 0.85, half_height: (top - zs) / 2.0 },
        Pose::from_pos([xy[0], xy[1], (zs + top) / 2.0]),
    );
    b.collision_on(
        0,
        Shape::Cylinder { radius: r * 0.45, half_height: (h - top) / 2.0 },
        Pose::from_pos([xy[0], xy[1], (top + h) / 2.0]),
    );
    zs
}

pub(crate) const GAS_CYLINDER: Category = Category {
    name: "gas_cylinder",
    display: "gas cylinder",
    synonyms: &[
        "gas bottle",
        "compressed gas cylinder",
        "oxygen cylinder",
        "nitrogen cylinder",
        "argon cylinder",
        "co2 cylinder",
        "gas tank",
        "welding gas cylinder",
        "propane tank",
    ],
    tags: &["lab", "workshop", "industrial", "hazard", "round", "tall"],
    description: "a tall compressed gas cylinder",
    is_a: &["cylinder", "container", "tank"],
    kind: Kind::Container,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.23, 0.12, 0.3, 0.08, "diameter"),
        ParamDef::new("depth", 0.23, 0.12, 0.3, 0.08, "diameter (as width)"),
        ParamDef::new("height", 1.45, 0.4, 1.7, 0.08, "to the top of the valve cap"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_gas_cylinder,
};

/// A standing steel cylinder, coloured by its gas, with its valve cap on.
fn build_gas_cylinder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let (body_rgba, shoulder_rgba) = rng.pick(GAS_COLOURS).copied().unwrap_or(GAS_COLOURS[0]);
    let body = b.material("body", body_rgba, true);
    let shoulder = b.material("shoulder", shoulder_rgba, false);
    let valve = b.material("valve_cap", pick(rng, STEEL), false);
    let label = b.material("label", [0.95, 0.95, 0.93, 1.0], false);
    let r = w / 2.0;
    let zs = cylinder_body(b, [0.0, 0.0], r, h, [body, shoulder, valve]);
    let band = revolve(
        &[[r - 0.001, zs * 0.62], [r + 0.001, zs * 0.62], [r + 0.001, zs * 0.72], [r - 0.001, zs * 0.72]],
        ROUND,
    );
    b.visual_mesh_on(0, &band, Pose::IDENTITY, label);
    // 50 l at 200 bar: about 60 kg with the steel.
    let litres = std::f64::consts::PI * r * r * zs * 1000.0;
    (litres * 1.15).clamp(3.0, 90.0)
}

pub(crate) const GAS_CYLINDER_RACK: Category = Category {
    name: "gas_cylinder_rack",
    display: "gas cylinder rack",
    synonyms: &["cylinder rack", "gas bottle rack", "cylinder cage", "gas cylinder cage", "cylinder stand", "gas rack"],
    tags: &["lab", "workshop", "industrial", "hazard", "storage"],
    description: "a rack holding gas cylinders",
    is_a: &["rack", "stand"],
    kind: Kind::Fixture,
    placement: PlacementKind::AgainstWall,
    params: &[
        ParamDef::new("width", 1.0, 0.4, 2.0, 0.15, "along X"),
        ParamDef::new("depth", 0.35, 0.3, 0.5, 0.08, "along Y"),
        ParamDef::new("height", 1.5, 1.0, 1.8, 0.05, "floor to the top of the cylinders"),
        ParamDef::new("fill", 0.8, 0.0, 1.0, 0.2, "share of the places holding a cylinder"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_gas_cylinder_rack,
};

/// A steel frame with a back panel, two restraint bars with chains and a row of
/// cylinders (part of the fixture) in some of its places.
fn build_gas_cylinder_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let frame = b.material("frame", pick(rng, &[SAFETY_YELLOW, [0.2, 0.35, 0.65, 1.0], [0.25, 0.26, 0.28, 1.0]]), true);
    let valve = b.material("valve_caps", pick(rng, STEEL), false);
    let chain = b.material("chains", [0.6, 0.61, 0.63, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let post = 0.04;
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.02], frame);
    for x in [-hw, hw - post] {
        slab(b, [x, -hd + 0.0005, 0.0199], [x + post, -hd + post, h - 0.039], frame);
    }
    slab(b, [-hw + post * 0.5, -hd, h - 0.04], [hw - post * 0.5, -hd + 0.06, h], frame);
    // Restraint bars from post to post at 1/3 and 2/3 of the cylinder height.
    for f in [0.35, 0.7] {
        let z = h * f;
        slab(b, [-hw + post * 0.5, -hd, z - 0.02], [hw - post * 0.5, -hd + 0.03, z + 0.02], frame);
    }
    let r = ((d - 0.06) / 2.0).min(0.115);
    let n = ((w - 2.0 * post) / (2.0 * r + 0.03)).floor().max(1.0) as usize;
    let pitch = (w - 2.0 * post) / n as f64;
    let cy = -hd + 0.03 + r + 0.002;
    for k in 0..n {
        let x = -hw + post + pitch * (k as f64 + 0.5);
        if !rng.chance(p.get("fill")) {
            continue;
        }
        let (body_rgba, shoulder_rgba) = rng.pick(GAS_COLOURS).copied().unwrap_or(GAS_COLOURS[0]);
        let body = b.material(&format!("cylinder_{}", k + 1), body_rgba, false);
        let shoulder = b.material(&format!("shoulder_{}", k + 1), shoulder_rgba, false);
        cylinder_body(b, [x, cy], r, h, [body, shoulder, valve]);
        for f in [0.35, 0.7] {
            rod(b, [x, cy + r + 0.004, h * f], 0.004, pitch * 0.8, Axis::X, chain);
        }
    }
    0.0
}
