//! Renders a compiled scene to PNG with the software rasterizer: what MuJoCo sees,
//! from its own geoms at the `home` state, with no OpenGL needed.

use std::path::Path;

use mujoco_rs::prelude::*;
use sw_geom::raster::{Camera, Image, Renderer};
use sw_geom::{Aabb, Mesh, Pose, box_mesh, cylinder_mesh, sphere_mesh};

/// Loads `scene` and draws the geoms of the given groups (2 = visual) from a camera
/// framing the room. Returns the image, or MuJoCo's error message.
pub fn render_scene(scene: &Path, width: u32, height: u32, groups: &[i32]) -> Result<Image, String> {
    let model = MjModel::from_xml(scene).map_err(|e| e.to_string())?;
    let mut data = model.make_data();
    if let Some(key) = model.name_to_id(MjtObjBase::mjOBJ_KEY, "home") {
        let _ = data.reset_keyframe(key);
    }
    data.forward();
    let ngeom = model.ffi().ngeom as usize;
    let mut items: Vec<(Mesh, Pose, [f32; 4])> = Vec::new();
    let mut walls: Vec<bool> = Vec::new();
    let mut bounds = Aabb::EMPTY;
    let mut room = Aabb::EMPTY;
    for g in 0..ngeom {
        let group = model.geom_group()[g];
        let gtype = model.geom_type()[g];
        let is_plane = gtype == MjtGeomBase::mjGEOM_PLANE;
        if !is_plane && !groups.contains(&group) && group != 0 && group != 1 {
            continue;
        }
        let size = model.geom_size()[g];
        let mesh = match gtype {
            MjtGeomBase::mjGEOM_PLANE => box_mesh([size[0], size[1], 0.001]),
            MjtGeomBase::mjGEOM_BOX => box_mesh(size),
            MjtGeomBase::mjGEOM_SPHERE => sphere_mesh(size[0], 10, 16),
            MjtGeomBase::mjGEOM_CYLINDER => cylinder_mesh(size[0], size[1], 20),
            MjtGeomBase::mjGEOM_CAPSULE => cylinder_mesh(size[0], size[1] + size[0], 20),
            MjtGeomBase::mjGEOM_ELLIPSOID => {
                let mut m = sphere_mesh(1.0, 10, 16);
                for v in &mut m.vertices {
                    for i in 0..3 {
                        v[i] *= size[i] as f32;
                    }
                }
                m
            }
            MjtGeomBase::mjGEOM_MESH => {
                let id = model.geom_dataid()[g];
                if id < 0 {
                    continue;
                }
                mesh_of(&model, id as usize)
            }
            _ => continue,
        };
        let pos = data.geom_xpos()[g];
        let m = data.geom_xmat()[g];
        let quat = mat_to_quat(&m);
        let mut rgba = model.geom_rgba()[g];
        let mat = model.geom_matid()[g];
        if mat >= 0 {
            rgba = model.mat_rgba()[mat as usize];
        }
        let pose = Pose { pos, quat };
        let is_wall = model.geom_bodyid()[g] == 0
            && model.id_to_name(MjtObjBase::mjOBJ_GEOM, g).is_some_and(|n| n.starts_with("wall_"));
        // Frame what is in the room, not the room itself (walls and floor belong to the
        // world body).
        if model.geom_bodyid()[g] != 0 {
            bounds = bounds.union(&mesh.bounds().transformed(&pose));
        } else if !is_plane {
            room = room.union(&mesh.bounds().transformed(&pose));
        }
        walls.push(is_wall);
        items.push((mesh, pose, rgba));
    }
    if bounds.is_empty() {
        bounds = if room.is_empty() { Aabb::from_center_half([0.0; 3], [1.0; 3]) } else { room };
    }
    // A little floor around the objects, and never less than a 2 m cube of view.
    let c = bounds.center();
    let s = bounds.size();
    bounds = Aabb::from_center_half(c, [(s[0] * 0.6).max(1.0), (s[1] * 0.6).max(1.0), (s[2] * 0.5).max(0.5)]);
    // Frame the objects (not the whole floor plane), from the south-east, above.
    let cam = Camera::framing(&bounds, -1.1, 0.62);
    let centre = bounds.center();
    let view = [cam.eye[0] - centre[0], cam.eye[1] - centre[1]];
    let mut r = Renderer::new(width, height, &cam, [236, 240, 245]);
    for (k, (mesh, pose, rgba)) in items.iter().enumerate() {
        // Cut away the walls between the camera and the room.
        if walls[k] && (pose.pos[0] - centre[0]) * view[0] + (pose.pos[1] - centre[1]) * view[1] > 0.0 {
            continue;
        }
        r.draw_mesh(mesh, pose, *rgba);
    }
    Ok(r.finish())
}

fn mesh_of(model: &MjModel, id: usize) -> Mesh {
    let vadr = model.mesh_vertadr()[id] as usize;
    let vnum = model.mesh_vertnum()[id] as usize;
    let fadr = model.mesh_faceadr()[id] as usize;
    let fnum = model.mesh_facenum()[id] as usize;
    let verts = &model.mesh_vert()[vadr..vadr + vnum];
    let faces = &model.mesh_face()[fadr..fadr + fnum];
    Mesh {
        vertices: verts.to_vec(),
        triangles: faces.iter().map(|f| [f[0] as u32, f[1] as u32, f[2] as u32]).collect(),
    }
}

fn mat_to_quat(m: &[f64; 9]) -> [f64; 4] {
    let (m00, m01, m02, m10, m11, m12, m20, m21, m22) = (m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
    let tr = m00 + m11 + m22;
    let q = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        [0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s]
    } else if m00 > m11 && m00 > m22 {
        let s = (1.0 + m00 - m11 - m22).sqrt() * 2.0;
        [(m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s]
    } else if m11 > m22 {
        let s = (1.0 + m11 - m00 - m22).sqrt() * 2.0;
        [(m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s]
    } else {
        let s = (1.0 + m22 - m00 - m11).sqrt() * 2.0;
        [(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s]
    };
    let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    q.map(|x| x / n)
}
