//! Geometry for scenewright: triangle meshes and their primitives, binary STL, mesh
//! validation (watertight, orientation, volume), poses, the [`Asset`] geometry that the
//! catalog produces and the layout and MJCF writer consume, and a small software
//! rasterizer used for thumbnails and scene previews.
//!
//! Pure: no I/O beyond writing bytes to a caller-supplied writer.

mod asset;
pub mod cancel;
mod mesh;
mod pose;
mod primitives;
pub mod raster;
mod rng;
mod stl;

pub use asset::{
    Asset, AssetBuilder, Collision, ConvexPiece, INSIDE_DEPTH, JointKind, JointSpec, Link, MassModel, Material,
    PlacementKind, Shape, SupportSurface, Visual,
};
pub use mesh::{Aabb, Mesh, MeshCheck};
pub use pose::{Pose, quat_from_yaw, quat_mul, rotate};
pub use primitives::{box_mesh, cylinder_mesh, frustum_mesh, sphere_mesh};
pub use rng::{Rng, fnv1a};
pub use stl::{StlError, read_stl, write_stl};
