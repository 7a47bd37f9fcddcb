//! The geometry of one catalog or generated object: links (a root and, for articulated
//! objects, moving parts), visual meshes grouped by material, collision primitives,
//! support surfaces, placement kind and mass.
//!
//! Frame convention: the asset's origin is the centre of its footprint on the floor
//! (`z = 0` is its lowest point), width along +X, depth along +Y, height along +Z, and
//! its front faces +Y.

use serde::{Deserialize, Serialize};

use crate::{Aabb, Mesh, Pose, box_mesh, cylinder_mesh, sphere_mesh};

/// Segments used for round primitives in visual meshes.
const ROUND_SEGMENTS: u32 = 24;

/// A collision primitive, in MuJoCo's parameterisation (half sizes).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Shape {
    Box {
        half: [f64; 3],
    },
    /// Axis along the local Z axis.
    Cylinder {
        radius: f64,
        half_height: f64,
    },
    Sphere {
        radius: f64,
    },
    /// Axis along local Z; `half_height` is the half length of the cylindrical part.
    Capsule {
        radius: f64,
        half_height: f64,
    },
}

impl Shape {
    /// The visual mesh of this primitive, centred on its own origin.
    pub fn mesh(&self) -> Mesh {
        match *self {
            Shape::Box { half } => box_mesh(half),
            Shape::Cylinder { radius, half_height } => cylinder_mesh(radius, half_height, ROUND_SEGMENTS),
            Shape::Sphere { radius } => sphere_mesh(radius, ROUND_SEGMENTS / 2, ROUND_SEGMENTS),
            Shape::Capsule { radius, half_height } => {
                // Visual stand-in: a cylinder as long as the capsule with its caps.
                cylinder_mesh(radius, half_height + radius, ROUND_SEGMENTS)
            }
        }
    }

    /// The half extents of the primitive's own axis-aligned box.
    pub fn half_extents(&self) -> [f64; 3] {
        match *self {
            Shape::Box { half } => half,
            Shape::Cylinder { radius, half_height } => [radius, radius, half_height],
            Shape::Sphere { radius } => [radius; 3],
            Shape::Capsule { radius, half_height } => [radius, radius, half_height + radius],
        }
    }

    pub fn volume(&self) -> f64 {
        use std::f64::consts::PI;
        match *self {
            Shape::Box { half } => 8.0 * half[0] * half[1] * half[2],
            Shape::Cylinder { radius, half_height } => PI * radius * radius * 2.0 * half_height,
            Shape::Sphere { radius } => 4.0 / 3.0 * PI * radius.powi(3),
            Shape::Capsule { radius, half_height } => {
                PI * radius * radius * 2.0 * half_height + 4.0 / 3.0 * PI * radius.powi(3)
            }
        }
    }

    /// True when every size is finite and positive.
    pub fn is_well_formed(&self) -> bool {
        self.half_extents().iter().all(|h| h.is_finite() && *h > 0.0)
    }
}

/// A named colour of an asset. `recolorable` marks the material a colour word in the
/// prompt ("a red cabinet") applies to.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Material {
    pub name: String,
    pub rgba: [f32; 4],
    pub recolorable: bool,
}

/// One visual mesh of a link, all in one material.
#[derive(Debug, Clone, PartialEq)]
pub struct Visual {
    pub material: usize,
    pub mesh: Mesh,
}

/// A convex collision piece of a link: MuJoCo collides a mesh geom as the convex hull of
/// its vertices, so a concave object (a generated part) collides as several of these.
/// The mesh is the piece's hull, in the link frame.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexPiece {
    pub mesh: Mesh,
}

impl ConvexPiece {
    pub fn aabb(&self) -> Aabb {
        self.mesh.bounds()
    }
}

/// One collision primitive of a link, posed in the link frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Collision {
    pub shape: Shape,
    pub pose: Pose,
}

impl Collision {
    /// The primitive's bounding box in the link frame.
    pub fn aabb(&self) -> Aabb {
        let h = self.shape.half_extents();
        Aabb::from_center_half([0.0; 3], h).transformed(&self.pose)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JointKind {
    Hinge,
    Slide,
}

/// The joint that connects a moving link to its parent.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct JointSpec {
    pub kind: JointKind,
    /// Joint axis, in the link frame.
    pub axis: [f64; 3],
    /// Joint anchor, in the link frame.
    pub anchor: [f64; 3],
    /// Limits: radians for hinges, metres for slides.
    pub range: [f64; 2],
    pub damping: f64,
}

/// A rigid part of an asset. Link 0 is the root; others hang from a parent by a joint.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    pub name: String,
    pub parent: Option<usize>,
    /// Pose in the parent link's frame (at joint value zero).
    pub pose: Pose,
    pub joint: Option<JointSpec>,
    pub visuals: Vec<Visual>,
    pub collisions: Vec<Collision>,
    /// Convex mesh pieces that collide besides the primitives (generated assets).
    pub convex: Vec<ConvexPiece>,
    /// Mass of a moving link, kg (the root's mass is the asset's [`MassModel`]).
    pub mass: f64,
}

/// An open surface this far or more below an asset's top is inside it (a tote's
/// floor), not its top, m.
pub const INSIDE_DEPTH: f64 = 0.02;

/// A horizontal surface that other objects can rest on (a table top, a shelf level).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SupportSurface {
    pub name: String,
    /// Height of the surface above the asset's origin, m.
    pub z: f64,
    /// The usable rectangle in the root frame, `[x, y]` corners.
    pub min: [f64; 2],
    pub max: [f64; 2],
    /// Free height above the surface (to the next shelf), m; `None` when open above.
    pub clearance: Option<f64>,
}

impl SupportSurface {
    pub fn area(&self) -> f64 {
        (self.max[0] - self.min[0]).max(0.0) * (self.max[1] - self.min[1]).max(0.0)
    }
}

/// Where an object of this kind goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlacementKind {
    /// Stands on the floor anywhere.
    Floor,
    /// Stands on the floor, back to a wall (shelves, cabinets, panels).
    AgainstWall,
    /// Set into a wall (doors, windows).
    InWall,
    /// Rests on a table, shelf or counter (mugs, boxes on shelves, monitors).
    OnSurface,
    /// Hangs on a wall above the floor (whiteboards, extinguishers on brackets).
    WallMounted,
}

/// How the object behaves in simulation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum MassModel {
    /// A fixture: welded to the world.
    Static,
    /// A free body with this mass, kg.
    Free { mass: f64 },
}

/// A complete object, ready for layout and MJCF writing.
#[derive(Debug, Clone, PartialEq)]
pub struct Asset {
    pub category: String,
    pub seed: u64,
    /// The parameter values the generator used, after clamping.
    pub params: Vec<(String, f64)>,
    pub materials: Vec<Material>,
    pub links: Vec<Link>,
    pub surfaces: Vec<SupportSurface>,
    pub placement: PlacementKind,
    pub mass: MassModel,
    /// Problems the generator corrected (clamped parameters and the like).
    pub notes: Vec<String>,
}

impl Asset {
    /// The world pose of every link at joint value zero, in the root frame.
    pub fn link_poses(&self) -> Vec<Pose> {
        let mut out: Vec<Pose> = Vec::with_capacity(self.links.len());
        for link in &self.links {
            let pose = match link.parent.and_then(|p| out.get(p)) {
                Some(parent) => parent.compose(&link.pose),
                None => link.pose,
            };
            out.push(pose);
        }
        out
    }

    /// Bounding boxes of every collision primitive, in the root frame.
    pub fn collision_aabbs(&self) -> Vec<Aabb> {
        let poses = self.link_poses();
        self.links
            .iter()
            .zip(&poses)
            .flat_map(|(link, lp)| {
                let primitives = link.collisions.iter().map(move |c| c.aabb().transformed(lp));
                primitives.chain(link.convex.iter().map(move |p| p.aabb().transformed(lp)))
            })
            .collect()
    }

    /// The bounding box of all visual and collision geometry, in the root frame.
    pub fn bounds(&self) -> Aabb {
        let poses = self.link_poses();
        let mut b = Aabb::EMPTY;
        for (link, lp) in self.links.iter().zip(&poses) {
            for v in &link.visuals {
                b = b.union(&v.mesh.bounds().transformed(lp));
            }
            for c in &link.collisions {
                b = b.union(&c.aabb().transformed(lp));
            }
            for p in &link.convex {
                b = b.union(&p.aabb().transformed(lp));
            }
        }
        b
    }

    pub fn is_free(&self) -> bool {
        matches!(self.mass, MassModel::Free { .. })
    }

    /// The highest support surface open above that is the asset's top: not the floor
    /// inside a tote, bin or tray, which lies [`INSIDE_DEPTH`] or more below the top.
    pub fn top_surface(&self) -> Option<&SupportSurface> {
        self.top_surface_under(self.bounds().max[2])
    }

    /// [`Self::top_surface`] with the asset's top height given (a caller that keeps its
    /// bounds need not walk every mesh again).
    pub fn top_surface_under(&self, top: f64) -> Option<&SupportSurface> {
        self.surfaces
            .iter()
            .filter(|s| s.clearance.is_none() && s.z > top - INSIDE_DEPTH)
            .max_by(|a, b| a.z.total_cmp(&b.z))
    }

    /// An open container (a tote, a tray, a bowl): it has surfaces open above, and all of
    /// them are inside it. What is stacked on it rests on its rim.
    pub fn is_open(&self) -> bool {
        self.top_surface().is_none() && self.surfaces.iter().any(|s| s.clearance.is_none())
    }

    /// The value of a parameter the generator used.
    pub fn param(&self, name: &str) -> Option<f64> {
        self.params.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
    }

    /// The same asset scaled uniformly by `factor` about its origin (the centre of its
    /// footprint on the floor, so it still stands there). Mass scales with volume.
    pub fn scaled(&self, factor: f64) -> Asset {
        let f = if factor.is_finite() && factor > 0.0 { factor } else { 1.0 };
        let scale3 = |p: [f64; 3]| p.map(|v| v * f);
        let mut a = self.clone();
        for link in &mut a.links {
            link.pose.pos = scale3(link.pose.pos);
            for v in &mut link.visuals {
                for p in &mut v.mesh.vertices {
                    *p = p.map(|c| (f64::from(c) * f) as f32);
                }
            }
            for p in &mut link.convex {
                for v in &mut p.mesh.vertices {
                    *v = v.map(|c| (f64::from(c) * f) as f32);
                }
            }
            for c in &mut link.collisions {
                c.pose.pos = scale3(c.pose.pos);
                c.shape = match c.shape {
                    Shape::Box { half } => Shape::Box { half: scale3(half) },
                    Shape::Cylinder { radius, half_height } => {
                        Shape::Cylinder { radius: radius * f, half_height: half_height * f }
                    }
                    Shape::Sphere { radius } => Shape::Sphere { radius: radius * f },
                    Shape::Capsule { radius, half_height } => {
                        Shape::Capsule { radius: radius * f, half_height: half_height * f }
                    }
                };
            }
            if let Some(j) = &mut link.joint {
                j.anchor = scale3(j.anchor);
                if j.kind == JointKind::Slide {
                    j.range = j.range.map(|r| r * f);
                }
            }
            link.mass *= f * f * f;
        }
        for s in &mut a.surfaces {
            s.z *= f;
            s.min = s.min.map(|v| v * f);
            s.max = s.max.map(|v| v * f);
            s.clearance = s.clearance.map(|c| c * f);
        }
        if let MassModel::Free { mass } = a.mass {
            a.mass = MassModel::Free { mass: mass * f * f * f };
        }
        a
    }
}

/// Builds an [`Asset`] from solids: each solid adds a visual mesh (merged per material)
/// and a collision primitive to a link.
#[derive(Debug)]
pub struct AssetBuilder {
    asset: Asset,
}

impl AssetBuilder {
    pub fn new(category: &str, seed: u64) -> Self {
        Self {
            asset: Asset {
                category: category.to_string(),
                seed,
                params: Vec::new(),
                materials: Vec::new(),
                links: vec![Link {
                    name: String::new(),
                    parent: None,
                    pose: Pose::IDENTITY,
                    joint: None,
                    visuals: Vec::new(),
                    collisions: Vec::new(),
                    convex: Vec::new(),
                    mass: 0.0,
                }],
                surfaces: Vec::new(),
                placement: PlacementKind::Floor,
                mass: MassModel::Static,
                notes: Vec::new(),
            },
        }
    }

    /// Records the parameter values used (for the report and reproducibility).
    pub fn params(&mut self, params: Vec<(String, f64)>) -> &mut Self {
        self.asset.params = params;
        self
    }

    pub fn note(&mut self, note: impl Into<String>) -> &mut Self {
        self.asset.notes.push(note.into());
        self
    }

    /// Adds a material and returns its index.
    pub fn material(&mut self, name: &str, rgba: [f32; 4], recolorable: bool) -> usize {
        self.asset.materials.push(Material { name: name.to_string(), rgba, recolorable });
        self.asset.materials.len() - 1
    }

    /// Adds a moving link hanging from `parent` and returns its index.
    pub fn link(&mut self, name: &str, parent: usize, pose: Pose, joint: JointSpec, mass: f64) -> usize {
        self.asset.links.push(Link {
            name: name.to_string(),
            parent: Some(parent),
            pose,
            joint: Some(joint),
            visuals: Vec::new(),
            collisions: Vec::new(),
            convex: Vec::new(),
            mass,
        });
        self.asset.links.len() - 1
    }

    /// A solid on the root link: visible and colliding.
    pub fn solid(&mut self, shape: Shape, pose: Pose, material: usize) -> &mut Self {
        self.solid_on(0, shape, pose, material)
    }

    /// A solid on link `link`: visible and colliding.
    pub fn solid_on(&mut self, link: usize, shape: Shape, pose: Pose, material: usize) -> &mut Self {
        self.visual_on(link, shape, pose, material);
        self.collision_on(link, shape, pose)
    }

    /// Visible only (decoration that must not change contacts: labels, tape, handles).
    pub fn visual(&mut self, shape: Shape, pose: Pose, material: usize) -> &mut Self {
        self.visual_on(0, shape, pose, material)
    }

    pub fn visual_on(&mut self, link: usize, shape: Shape, pose: Pose, material: usize) -> &mut Self {
        self.visual_mesh_on(link, &shape.mesh(), pose, material)
    }

    /// Appends an arbitrary closed mesh to the visual of `link` in `material`.
    pub fn visual_mesh_on(&mut self, link: usize, mesh: &Mesh, pose: Pose, material: usize) -> &mut Self {
        let Some(l) = self.asset.links.get_mut(link) else {
            return self;
        };
        match l.visuals.iter_mut().find(|v| v.material == material) {
            Some(v) => v.mesh.append(mesh, &pose),
            None => {
                let mut m = Mesh::default();
                m.append(mesh, &pose);
                l.visuals.push(Visual { material, mesh: m });
            }
        }
        self
    }

    /// Colliding only (simplified collision for detailed visuals).
    pub fn collision_on(&mut self, link: usize, shape: Shape, pose: Pose) -> &mut Self {
        if let Some(l) = self.asset.links.get_mut(link) {
            l.collisions.push(Collision { shape, pose });
        }
        self
    }

    /// A convex collision piece on link `link` (its hull mesh, in the link frame).
    pub fn convex_on(&mut self, link: usize, mesh: Mesh) -> &mut Self {
        if let Some(l) = self.asset.links.get_mut(link) {
            l.convex.push(ConvexPiece { mesh });
        }
        self
    }

    pub fn surface(&mut self, name: &str, z: f64, min: [f64; 2], max: [f64; 2], clearance: Option<f64>) -> &mut Self {
        self.asset.surfaces.push(SupportSurface { name: name.to_string(), z, min, max, clearance });
        self
    }

    pub fn build(mut self, placement: PlacementKind, mass: MassModel) -> Asset {
        self.asset.placement = placement;
        self.asset.mass = mass;
        self.asset
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaling_keeps_the_asset_on_the_floor_and_scales_mass_with_volume() {
        let mut b = AssetBuilder::new("box", 1);
        let m = b.material("m", [1.0; 4], true);
        b.solid(Shape::Box { half: [0.2, 0.1, 0.15] }, Pose::from_pos([0.0, 0.0, 0.15]), m);
        b.surface("top", 0.3, [-0.2, -0.1], [0.2, 0.1], None);
        let a = b.build(PlacementKind::OnSurface, MassModel::Free { mass: 2.0 });
        let s = a.scaled(2.0);
        let bounds = s.bounds();
        assert!(bounds.min[2].abs() < 1e-6 && (bounds.max[2] - 0.6).abs() < 1e-6);
        assert!((s.surfaces[0].z - 0.6).abs() < 1e-9);
        assert_eq!(s.mass, MassModel::Free { mass: 16.0 });
        assert!(s.links[0].visuals[0].mesh.check().is_valid_solid());
    }

    #[test]
    fn builder_merges_visuals_per_material_and_keeps_one_collision_per_solid() {
        let mut b = AssetBuilder::new("table", 1);
        let wood = b.material("top", [0.6, 0.4, 0.2, 1.0], true);
        let steel = b.material("legs", [0.3, 0.3, 0.3, 1.0], false);
        b.solid(Shape::Box { half: [0.6, 0.4, 0.02] }, Pose::from_pos([0.0, 0.0, 0.73]), wood);
        for (x, y) in [(-0.55, -0.35), (0.55, -0.35), (-0.55, 0.35), (0.55, 0.35)] {
            b.solid(Shape::Box { half: [0.02, 0.02, 0.355] }, Pose::from_pos([x, y, 0.355]), steel);
        }
        let a = b.build(PlacementKind::Floor, MassModel::Static);
        assert_eq!(a.links[0].visuals.len(), 2);
        assert_eq!(a.links[0].collisions.len(), 5);
        let bounds = a.bounds();
        assert!((bounds.min[2]).abs() < 1e-6 && (bounds.max[2] - 0.75).abs() < 1e-6);
        for v in &a.links[0].visuals {
            assert!(v.mesh.check().watertight);
        }
    }
}
