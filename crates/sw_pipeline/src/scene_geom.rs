//! The written scene as geometry: every top-level body of `scene.xml` with the world
//! boxes of its collision geometry (geoms of class `sw_collision`, mesh pieces read from
//! their STL files), its support-surface sites and its pose. This is what the relation
//! checks measure — the MJCF as written, not the solver's bookkeeping.

use std::collections::BTreeMap;
use std::path::Path;

use sw_geom::{Aabb, rotate};
use sw_mjcf::xml::Element;

/// A support-surface site (`<object>_top`, `<object>_level_2`): a flat rectangle.
#[derive(Debug, Clone)]
pub(crate) struct Site {
    pub name: String,
    /// World height of the surface.
    pub z: f64,
    /// World rectangle [x0, y0, x1, y1].
    pub rect: [f64; 4],
}

/// One top-level body.
#[derive(Debug, Clone)]
pub(crate) struct BodyGeom {
    pub pos: [f64; 3],
    /// Rotation about +Z of the body frame, radians.
    pub yaw: f64,
    /// World bounds of its collision geometry (empty for bodies with none).
    pub bounds: Aabb,
    pub sites: Vec<Site>,
    /// World anchors of the hinge joints met first going down the body's tree (its
    /// first child at each level): for an arm, the base pan joint, then the shoulder.
    pub joints: Vec<[f64; 3]>,
}

impl BodyGeom {
    /// An arm's shoulder: on the axis of its first joint (the vertical pan joint), at the
    /// height of the next one (the lift joint) — the centre of the sphere its reach
    /// describes. `None` for a body with fewer than two joints.
    pub fn shoulder(&self) -> Option<[f64; 3]> {
        match self.joints.as_slice() {
            [pan, lift, ..] => Some([pan[0], pan[1], lift[2]]),
            _ => None,
        }
    }

    /// The object's front: its +Y turned by its yaw.
    pub fn front(&self) -> [f64; 2] {
        [-self.yaw.sin(), self.yaw.cos()]
    }

    pub fn center(&self) -> [f64; 2] {
        [0.5 * (self.bounds.min[0] + self.bounds.max[0]), 0.5 * (self.bounds.min[1] + self.bounds.max[1])]
    }
}

/// Every top-level body of the written scene, by name.
#[derive(Debug, Default)]
pub(crate) struct SceneGeom {
    pub bodies: BTreeMap<String, BodyGeom>,
}

fn nums(s: Option<&str>) -> Vec<f64> {
    s.map(|s| s.split_whitespace().filter_map(|x| x.parse::<f64>().ok()).collect()).unwrap_or_default()
}

fn quat_of(e: &Element) -> [f64; 4] {
    let q = nums(e.get("quat"));
    if q.len() == 4 {
        let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
        if n > 0.0 {
            return [q[0] / n, q[1] / n, q[2] / n, q[3] / n];
        }
    }
    [1.0, 0.0, 0.0, 0.0]
}

fn pos_of(e: &Element) -> [f64; 3] {
    let p = nums(e.get("pos"));
    if p.len() == 3 { [p[0], p[1], p[2]] } else { [0.0; 3] }
}

/// A rigid transform: rotation (quaternion w x y z) then translation.
#[derive(Debug, Clone, Copy)]
struct Frame {
    pos: [f64; 3],
    quat: [f64; 4],
}

impl Frame {
    fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let r = rotate(self.quat, p);
        [r[0] + self.pos[0], r[1] + self.pos[1], r[2] + self.pos[2]]
    }

    fn child(&self, e: &Element) -> Frame {
        Frame { pos: self.apply(pos_of(e)), quat: sw_geom::quat_mul(self.quat, quat_of(e)) }
    }
}

/// World bounds of a box with half extents `h` centred at the origin of `f`.
fn box_bounds(f: &Frame, h: [f64; 3]) -> Aabb {
    let mut b = Aabb::EMPTY;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                let p = f.apply([sx * h[0], sy * h[1], sz * h[2]]);
                b = b.union(&Aabb { min: p, max: p });
            }
        }
    }
    b
}

/// Mesh bounds by mesh name, read from the package's STL files once.
struct Meshes<'a> {
    dir: &'a Path,
    files: BTreeMap<String, String>,
    cache: BTreeMap<String, Option<Aabb>>,
}

impl Meshes<'_> {
    fn bounds(&mut self, name: &str) -> Option<Aabb> {
        if let Some(b) = self.cache.get(name) {
            return *b;
        }
        let b = self.files.get(name).and_then(|f| {
            let bytes = std::fs::read(self.dir.join(f)).ok()?;
            let mesh = sw_geom::read_stl(bytes.as_slice()).ok()?;
            Some(mesh.bounds())
        });
        self.cache.insert(name.to_string(), b);
        b
    }
}

fn collect(e: &Element, f: &Frame, body: &mut BodyGeom, meshes: &mut Meshes<'_>) {
    for c in &e.children {
        match c.name.as_str() {
            "geom" if c.get("class") == Some("sw_collision") => {
                let g = f.child(c);
                let size = nums(c.get("size"));
                let b = match c.get("type").unwrap_or("sphere") {
                    "box" if size.len() == 3 => Some(box_bounds(&g, [size[0], size[1], size[2]])),
                    "cylinder" if size.len() >= 2 => Some(box_bounds(&g, [size[0], size[0], size[1]])),
                    "capsule" if size.len() >= 2 => Some(box_bounds(&g, [size[0], size[0], size[1] + size[0]])),
                    "sphere" if !size.is_empty() => Some(box_bounds(&g, [size[0]; 3])),
                    "mesh" => c.get("mesh").and_then(|m| meshes.bounds(m)).map(|mb| {
                        let mut b = Aabb::EMPTY;
                        for x in [mb.min[0], mb.max[0]] {
                            for y in [mb.min[1], mb.max[1]] {
                                for z in [mb.min[2], mb.max[2]] {
                                    let p = g.apply([x, y, z]);
                                    b = b.union(&Aabb { min: p, max: p });
                                }
                            }
                        }
                        b
                    }),
                    _ => None,
                };
                if let Some(b) = b {
                    body.bounds = body.bounds.union(&b);
                }
            }
            "site" if c.get("class") == Some("sw_surface") => {
                let s = f.child(c);
                let size = nums(c.get("size"));
                if size.len() == 3 {
                    let b = box_bounds(&s, [size[0], size[1], 0.0]);
                    body.sites.push(Site {
                        name: c.get("name").unwrap_or_default().to_string(),
                        z: s.pos[2],
                        rect: [b.min[0], b.min[1], b.max[0], b.max[1]],
                    });
                }
            }
            "body" => collect(c, &f.child(c), body, meshes),
            _ => {}
        }
    }
}

/// The hinge anchors along the first chain of bodies below `e` (frame `f`).
fn joint_chain(e: &Element, f: &Frame, out: &mut Vec<[f64; 3]>) {
    for j in e.children.iter().filter(|c| c.name == "joint") {
        let kind = j.get("type").unwrap_or("hinge");
        if kind == "hinge" {
            out.push(f.apply(pos_of(j)));
            break;
        }
    }
    if out.len() >= 2 {
        return;
    }
    if let Some(child) = e.children.iter().find(|c| c.name == "body") {
        joint_chain(child, &f.child(child), out);
    }
}

impl SceneGeom {
    /// Reads `scene.xml` in `dir` (and the STL files of mesh collision pieces).
    pub fn read(dir: &Path) -> Result<SceneGeom, String> {
        let text = std::fs::read_to_string(dir.join("scene.xml")).map_err(|e| format!("scene.xml: {e}"))?;
        let doc = Element::parse(&text).map_err(|e| format!("scene.xml: {e}"))?;
        let meshdir = doc.first("compiler").and_then(|c| c.get("meshdir")).unwrap_or("");
        let mut files = BTreeMap::new();
        if let Some(asset) = doc.first("asset") {
            for m in asset.children.iter().filter(|c| c.name == "mesh") {
                if let (Some(n), Some(f)) = (m.get("name"), m.get("file")) {
                    files.insert(n.to_string(), f.to_string());
                }
            }
        }
        let mesh_dir = dir.join(meshdir);
        let mut meshes = Meshes { dir: &mesh_dir, files, cache: BTreeMap::new() };
        let mut out = SceneGeom::default();
        let Some(world) = doc.first("worldbody") else { return Ok(out) };
        for b in world.children.iter().filter(|c| c.name == "body") {
            let Some(name) = b.get("name") else { continue };
            let f = Frame { pos: pos_of(b), quat: quat_of(b) };
            // Yaw of a rotation about +Z only (objects and robot bases are turned so).
            let yaw = 2.0 * f.quat[3].atan2(f.quat[0]);
            let mut body = BodyGeom { pos: f.pos, yaw, bounds: Aabb::EMPTY, sites: Vec::new(), joints: Vec::new() };
            collect(b, &f, &mut body, &mut meshes);
            joint_chain(b, &f, &mut body.joints);
            out.bodies.insert(name.to_string(), body);
        }
        Ok(out)
    }
}
