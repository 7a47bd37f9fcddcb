//! Measures a robot at its home pose: per body, its frame origin and the box around its
//! collision geometry, in the world frame of the document (a robot document places its
//! base at the origin). Mesh geoms are measured from their vertices, primitives from
//! their bounding boxes. The registry turns this into keep-out boxes and reach.

use std::path::Path;

use mujoco_rs::prelude::*;

/// One body of the measured model (the world body excluded).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyBox {
    pub name: String,
    /// Index into the returned list of the parent body (`None` for a root body).
    pub parent: Option<usize>,
    pub origin: [f64; 3],
    /// Box around the body's colliding geoms; `min > max` when it has none.
    pub min: [f64; 3],
    pub max: [f64; 3],
}

/// Loads `path`, resets to the `home` keyframe (if any) and measures every body.
pub fn measure_robot(path: &Path) -> Result<Vec<BodyBox>, String> {
    let model = MjModel::from_xml(path).map_err(|e| e.to_string())?;
    let mut data = model.make_data();
    if let Some(key) = model.name_to_id(MjtObjBase::mjOBJ_KEY, "home") {
        data.reset_keyframe(key).map_err(|e| e.to_string())?;
    }
    data.forward();
    let nbody = model.ffi().nbody as usize;
    let mut out: Vec<BodyBox> = (1..nbody)
        .map(|b| {
            let p = model.body_parentid()[b] as usize;
            BodyBox {
                name: model.id_to_name(MjtObjBase::mjOBJ_BODY, b).unwrap_or("").to_string(),
                parent: (p > 0).then(|| p - 1),
                origin: data.xpos()[b],
                min: [f64::INFINITY; 3],
                max: [f64::NEG_INFINITY; 3],
            }
        })
        .collect();
    for g in 0..model.ffi().ngeom as usize {
        if model.geom_contype()[g] == 0 && model.geom_conaffinity()[g] == 0 {
            continue;
        }
        let b = model.geom_bodyid()[g] as usize;
        if b == 0 {
            continue;
        }
        let pos = data.geom_xpos()[g];
        let m = data.geom_xmat()[g];
        let apply = |v: [f64; 3]| {
            [
                pos[0] + m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
                pos[1] + m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
                pos[2] + m[6] * v[0] + m[7] * v[1] + m[8] * v[2],
            ]
        };
        let mut points: Vec<[f64; 3]> = Vec::new();
        let mesh = model.geom_dataid()[g];
        if model.geom_type()[g] == MjtGeomBase::mjGEOM_MESH && mesh >= 0 {
            let adr = model.mesh_vertadr()[mesh as usize] as usize;
            let num = model.mesh_vertnum()[mesh as usize] as usize;
            for v in &model.mesh_vert()[adr..adr + num] {
                points.push(apply([f64::from(v[0]), f64::from(v[1]), f64::from(v[2])]));
            }
        } else {
            let a = model.geom_aabb()[g];
            for k in 0..8 {
                let s = |i: usize| if k & (1 << i) == 0 { -1.0 } else { 1.0 };
                points.push(apply([a[0] + s(0) * a[3], a[1] + s(1) * a[4], a[2] + s(2) * a[5]]));
            }
        }
        let e = &mut out[b - 1];
        for p in points {
            for (i, v) in p.iter().enumerate() {
                e.min[i] = e.min[i].min(*v);
                e.max[i] = e.max[i].max(*v);
            }
        }
    }
    Ok(out)
}
