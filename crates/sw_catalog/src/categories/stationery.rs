//! Small desk things: books, pens and staplers.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng};

use super::kit::{Axis, collider_between, decal_between, pick, rod, shade, slab};
use super::shapes::{ROUND, prism_xz, revolve, rounded_rect};
use crate::{Category, Kind, ParamDef, Params};

/// Book cloth and printed covers.
const COVERS: &[[f32; 4]] = &[
    [0.55, 0.1, 0.1, 1.0],
    [0.1, 0.2, 0.45, 1.0],
    [0.12, 0.35, 0.2, 1.0],
    [0.85, 0.75, 0.3, 1.0],
    [0.15, 0.15, 0.16, 1.0],
    [0.9, 0.9, 0.88, 1.0],
    [0.45, 0.25, 0.5, 1.0],
];

pub(crate) const BOOK: Category = Category {
    name: "book",
    display: "book",
    synonyms: &[
        "phonebook",
        "phone book",
        "telephone directory",
        "hardcover book",
        "paperback",
        "textbook",
        "manual",
        "novel",
        "bible",
        "hardback",
    ],
    tags: &["office", "tabletop", "classroom", "small", "graspable", "stackable"],
    description: "a hardcover book or binder",
    is_a: &["publication"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.16, 0.1, 0.3, 0.15, "along X, lying flat"),
        ParamDef::new("depth", 0.24, 0.14, 0.35, 0.12, "along Y, the spine on the -X side"),
        ParamDef::new("height", 0.03, 0.005, 0.08, 0.35, "thickness"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_book,
};

/// A book lying flat: covers slightly larger than the page block, the spine at -X.
fn build_book(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let cover = b.material("cover", pick(rng, COVERS), true);
    let pages = b.material("pages", [0.95, 0.93, 0.86, 1.0], false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let t = (h * 0.12).clamp(0.0008, 0.003);
    let top = collider_between(b, [-hw, -hd, 0.0], [hw, hd, h]);
    decal_between(b, [-hw, -hd, 0.0], [hw, hd, t], cover);
    decal_between(b, [-hw + 0.0001, -hd + 0.0001, h - t], [hw - 0.0001, hd - 0.0001, h], cover);
    decal_between(b, [-hw, -hd + 0.0002, t * 0.5], [-hw + t, hd - 0.0002, h - t * 0.5], cover);
    decal_between(b, [-hw + t * 0.5, -hd + 0.003, t * 0.9], [hw - 0.003, hd - 0.003, h - t * 0.9], pages);
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    (w * d * h * 650.0).max(0.01)
}

pub(crate) const PEN: Category = Category {
    name: "pen",
    display: "pen",
    synonyms: &["ballpoint pen", "ballpoint", "biro", "rollerball pen", "gel pen"],
    tags: &["office", "tabletop", "classroom", "small", "graspable"],
    description: "a ballpoint pen",
    is_a: &["writing implement", "stationery"],
    kind: Kind::HandHeld,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.14, 0.08, 0.2, 0.08, "length along X"),
        ParamDef::new("depth", 0.011, 0.006, 0.025, 0.1, "barrel diameter"),
        ParamDef::new("height", 0.011, 0.006, 0.025, 0.1, "barrel diameter (as depth)"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_pen,
};

/// A barrel lying along X with a cone tip at +X and a clip on the cap. Collides as a
/// box so that it does not roll away.
fn build_pen(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let r = d.min(h) / 2.0;
    let barrel = b.material("barrel", pick(rng, COVERS), true);
    let trim = b.material("trim", [0.2, 0.2, 0.22, 1.0], false);
    let tip = w * 0.1;
    let along_x = Pose::from_pos_axis_angle([0.0, 0.0, r], [0.0, 1.0, 0.0], std::f64::consts::FRAC_PI_2);
    let x0 = -w / 2.0;
    let body = revolve(&[[0.0, x0], [r, x0], [r, w / 2.0 - tip], [r * 0.3, w / 2.0 - 0.001], [0.0, w / 2.0]], ROUND);
    b.visual_mesh_on(0, &body, along_x, barrel);
    rod(b, [x0 + w * 0.2, 0.0, r], r * 1.08, w * 0.35, Axis::X, trim);
    collider_between(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h]);
    (w * d * h * 900.0).max(0.005)
}

pub(crate) const STAPLER: Category = Category {
    name: "stapler",
    display: "stapler",
    synonyms: &["desk stapler", "office stapler"],
    tags: &["office", "tabletop", "small", "graspable"],
    description: "a desk stapler",
    is_a: &["office supply", "stationery"],
    kind: Kind::Tabletop,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.045, 0.035, 0.07, 0.08, "along X"),
        ParamDef::new("depth", 0.16, 0.1, 0.25, 0.08, "along Y"),
        ParamDef::new("height", 0.06, 0.04, 0.09, 0.1, "to the top of the arm"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_stapler,
};

/// A base plate and a rounded top arm hinged at the back (-Y).
fn build_stapler(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let color =
        pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.7, 0.1, 0.1, 1.0], [0.15, 0.3, 0.6, 1.0], [0.6, 0.6, 0.62, 1.0]]);
    let arm = b.material("arm", color, true);
    let base = b.material("base", shade(color, 0.6), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bt = h * 0.25;
    slab(b, [-hw, -hd, 0.0], [hw, hd, bt], base);
    // The arm: a rounded block, side profile in the YZ plane extruded along X.
    let outline: Vec<[f64; 2]> = rounded_rect(hd * 0.97, (h - bt) / 2.0, (h - bt) * 0.45, 4)
        .into_iter()
        .map(|[y, z]| [y, z + (bt + h) / 2.0])
        .collect();
    let mut mesh = prism_xz(&outline, -hw * 0.85, hw * 0.85);
    // prism_xz lies along Y; turn it to lie along X by swapping the first two coordinates.
    for v in &mut mesh.vertices {
        *v = [v[1], v[0], v[2]];
    }
    for t in &mut mesh.triangles {
        t.swap(1, 2);
    }
    b.visual_mesh_on(0, &mesh, Pose::IDENTITY, arm);
    collider_between(b, [-hw * 0.85, -hd * 0.97, bt], [hw * 0.85, hd * 0.97, h]);
    (w * d * h * 900.0).max(0.1)
}
