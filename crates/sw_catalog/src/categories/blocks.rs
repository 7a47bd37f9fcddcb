//! Geometric objects for manipulation tasks: cubes, cylinders and spheres in bright
//! colours, the YCB-style props of tabletop benchmarks.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape, sphere_mesh};

use super::kit::{pick, slab};
use super::parts::round_solid;
use crate::{Category, Kind, ParamDef, Params};

/// Toy-block colours.
const BRIGHT: &[[f32; 4]] = &[
    [0.85, 0.12, 0.1, 1.0],
    [0.1, 0.55, 0.2, 1.0],
    [0.12, 0.3, 0.8, 1.0],
    [0.95, 0.78, 0.1, 1.0],
    [0.95, 0.5, 0.1, 1.0],
    [0.55, 0.2, 0.65, 1.0],
    [0.1, 0.65, 0.7, 1.0],
];

/// Density of the blocks: hard wood or solid plastic, kg/m³.
const BLOCK_DENSITY: f64 = 700.0;

pub(crate) const CUBE: Category = Category {
    name: "cube",
    display: "cube",
    synonyms: &["block", "toy block", "wooden block", "building block", "small cube", "dice"],
    tags: &["tabletop", "small", "graspable", "primitive", "uniform"],
    description: "a small solid cube or toy block for picking and stacking",
    is_a: &["block", "toy", "shape"],
    kind: Kind::Toy,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.05, 0.01, 0.3, 0.1, "edge (all three edges follow it)"),
        ParamDef::new("depth", 0.05, 0.01, 0.3, 0.1, "edge along Y"),
        ParamDef::new("height", 0.05, 0.01, 0.3, 0.1, "edge along Z"),
        ParamDef::new("density", BLOCK_DENSITY, 50.0, 8000.0, 0.2, "kg/m³"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_cube,
};

/// A cube: all three edges follow `width` (the tag `uniform`).
fn build_cube(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let body = b.material("body", pick(rng, BRIGHT), true);
    let top = slab(b, [-w / 2.0, -d / 2.0, 0.0], [w / 2.0, d / 2.0, h], body);
    b.surface("top", top, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    (w * d * h * p.get("density")).max(0.002)
}

pub(crate) const CYLINDER: Category = Category {
    name: "cylinder",
    display: "cylinder",
    synonyms: &["cylindrical block", "puck", "round block", "rod", "dowel"],
    tags: &["tabletop", "small", "graspable", "primitive", "round"],
    description: "a small solid cylinder or peg for picking",
    is_a: &["block", "toy", "shape"],
    kind: Kind::Toy,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.05, 0.01, 0.3, 0.12, "diameter"),
        ParamDef::new("depth", 0.05, 0.01, 0.3, 0.12, "diameter (as width)"),
        ParamDef::new("height", 0.08, 0.01, 0.4, 0.2, "along Z"),
        ParamDef::new("density", BLOCK_DENSITY, 50.0, 8000.0, 0.2, "kg/m³"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_cylinder,
};

/// An upright cylinder; its top carries things.
fn build_cylinder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, h) = (p.get("width"), p.get("height"));
    let r = w / 2.0;
    let body = b.material("body", pick(rng, BRIGHT), true);
    let top = round_solid(b, 0, [0.0, 0.0], r, 0.0, h, body);
    let a = r / std::f64::consts::SQRT_2 - 1e-6;
    b.surface("top", top, [-a, -a], [a, a], None);
    (std::f64::consts::PI * r * r * h * p.get("density")).max(0.002)
}

pub(crate) const SPHERE: Category = Category {
    name: "sphere",
    display: "sphere",
    synonyms: &["ball", "small ball", "rubber ball", "tennis ball", "marble", "orb"],
    tags: &["tabletop", "small", "graspable", "primitive", "round", "uniform"],
    description: "a small ball",
    is_a: &["ball", "toy", "shape"],
    kind: Kind::Toy,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.06, 0.01, 0.4, 0.12, "diameter"),
        ParamDef::new("depth", 0.06, 0.01, 0.4, 0.12, "diameter (as width)"),
        ParamDef::new("height", 0.06, 0.01, 0.4, 0.12, "diameter (follows width)"),
        ParamDef::new("density", 400.0, 50.0, 8000.0, 0.3, "kg/m³"),
    ],
    movable: true,
    vary_per_instance: true,
    build: build_sphere,
};

/// A ball resting on its lowest point. All three sizes are its diameter: `height`
/// follows `width` as `depth` does.
fn build_sphere(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let r = p.get("width") / 2.0;
    let body = b.material("body", pick(rng, BRIGHT), true);
    b.visual_mesh_on(0, &sphere_mesh(r, 16, 32), Pose::from_pos([0.0, 0.0, r]), body);
    b.collision_on(0, Shape::Sphere { radius: r }, Pose::from_pos([0.0, 0.0, r]));
    (4.0 / 3.0 * std::f64::consts::PI * r.powi(3) * p.get("density")).max(0.002)
}
