//! Writes a laid-out scene as MJCF: room, lights, camera, materials, meshes, object
//! bodies (static fixtures and free items), merged robots, and a `home` keyframe that
//! covers the whole model.

use std::collections::BTreeMap;

use sw_geom::{Aabb, Asset, Link, MassModel, Pose, Shape, fnv1a, write_stl};
use sw_plan::{LaidOutScene, PlacedObject, Wall};

use crate::merge::{MERGED_SECTIONS, parse_list, prepare_robot};
use crate::robot::{MergeError, PreparedRobot, RobotFile, RobotSource};
use crate::xml::{Element, num, nums, sig};

/// Simulation timestep of generated scenes, s.
pub const TIMESTEP: f64 = 0.002;

/// A robot to merge: its instance name must match a `PlacedRobot` in the layout.
#[derive(Debug, Clone)]
pub struct RobotInput<'a> {
    pub name: &'a str,
    pub model: &'a RobotSource,
}

/// Everything the writer needs.
#[derive(Debug)]
pub struct SceneInput<'a> {
    /// The prompt, written into a comment at the top of the file.
    pub prompt: &'a str,
    pub layout: &'a LaidOutScene,
    /// The asset of each placed object, in layout order.
    pub assets: Vec<&'a Asset>,
    pub robots: Vec<RobotInput<'a>>,
}

/// One mesh file of the package.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshFile {
    /// File name inside `assets/`.
    pub file_name: String,
    pub bytes: Vec<u8>,
}

/// The documents of a scene package.
#[derive(Debug, Clone)]
pub struct SceneFiles {
    pub scene_xml: String,
    pub scene_only_xml: String,
    pub meshes: Vec<MeshFile>,
    /// Files the robots reference, to copy into `assets/` (each destination once).
    pub robot_files: Vec<RobotFile>,
    /// What the merger dropped or adjusted in the robots' models.
    pub notes: Vec<String>,
}

#[derive(Debug, thiserror::Error)]
pub enum BridgeError {
    #[error("layout has {objects} objects but {assets} assets were given")]
    AssetCount { objects: usize, assets: usize },
    #[error("robot '{0}' is in the layout but no model was given for it")]
    MissingRobot(String),
    #[error(transparent)]
    Merge(#[from] MergeError),
}

/// Writes `scene.xml` and `scene_only.xml` and the mesh files they reference.
pub fn write_scene(input: &SceneInput<'_>) -> Result<SceneFiles, BridgeError> {
    let layout = input.layout;
    if layout.objects.len() != input.assets.len() {
        return Err(BridgeError::AssetCount { objects: layout.objects.len(), assets: input.assets.len() });
    }
    let mut robots = Vec::new();
    for placed in &layout.robots {
        let r = input
            .robots
            .iter()
            .find(|r| r.name == placed.name)
            .ok_or_else(|| BridgeError::MissingRobot(placed.name.clone()))?;
        let mount = Pose::from_pos_yaw(placed.pos, placed.yaw);
        robots.push(prepare_robot(r.model, &placed.name, &mount)?);
    }
    let mut robot_files: Vec<RobotFile> = robots.iter().flat_map(|r| r.files.iter().cloned()).collect();
    robot_files.sort();
    robot_files.dedup_by(|a, b| a.dest == b.dest);
    let mut notes: Vec<String> = Vec::new();
    for n in robots.iter().flat_map(|r| &r.notes) {
        if !notes.contains(n) {
            notes.push(n.clone());
        }
    }
    let mut meshes = MeshTable::default();
    let with = build(input, &robots, &mut meshes);
    let without = build(input, &[], &mut meshes);
    Ok(SceneFiles {
        scene_xml: with.to_document(),
        scene_only_xml: without.to_document(),
        meshes: meshes.files,
        robot_files,
        notes,
    })
}

/// One robot alone, as a loadable MJCF document: at the origin, names prefixed with
/// `prefix`, a `home` keyframe, and file references pointing at the robot's files where
/// they are (absolute paths), so that MuJoCo can load it without a package.
pub fn robot_document(model: &RobotSource, prefix: &str) -> Result<String, MergeError> {
    let r = prepare_robot(model, prefix, &Pose::IDENTITY)?;
    let mut root = Element::new("mujoco").with("model", model.model.clone());
    root.children.push(Element::new("compiler").with("angle", "radian").with("autolimits", "true"));
    root.children.push(Element::new("option").with("timestep", num(TIMESTEP)).with("integrator", "implicitfast"));
    let mut defaults = Element::new("default");
    defaults.children.extend(r.defaults.iter().cloned());
    root.children.push(defaults);
    let mut asset = Element::new("asset");
    for a in &r.assets {
        let mut a = a.clone();
        let keys: Vec<String> = a.attrs.iter().filter(|(k, _)| k.starts_with("file")).map(|(k, _)| k.clone()).collect();
        for k in keys {
            if let Some(f) = r.files.iter().find(|f| Some(f.dest.as_str()) == a.get(&k)) {
                a.set(&k, f.source.to_string_lossy().into_owned());
            }
        }
        asset.children.push(a);
    }
    root.children.push(asset);
    let mut world = Element::new("worldbody");
    world.children.extend(r.bodies.iter().cloned());
    let key = home_key(&world, std::slice::from_ref(&r));
    root.children.push(world);
    for section in MERGED_SECTIONS {
        if let Some(items) = r.sections.get(*section) {
            let mut s = Element::new(section);
            s.children = items.clone();
            root.children.push(s);
        }
    }
    root.children.push(Element::new("keyframe").child(key));
    Ok(root.to_document())
}

#[derive(Debug, Default)]
struct MeshTable {
    /// Content hash → mesh name.
    by_hash: BTreeMap<u64, String>,
    files: Vec<MeshFile>,
}

impl MeshTable {
    /// The mesh name for this geometry, writing its STL the first time it is seen.
    fn intern(&mut self, category: &str, mesh: &sw_geom::Mesh) -> String {
        let mut bytes = Vec::new();
        // Writing into a Vec cannot fail.
        let _ = write_stl(&mut bytes, mesh, category);
        let hash = fnv1a(&bytes);
        if let Some(name) = self.by_hash.get(&hash) {
            return name.clone();
        }
        let name = format!("{category}_{:010x}", hash >> 24);
        self.files.push(MeshFile { file_name: format!("{name}.stl"), bytes });
        self.by_hash.insert(hash, name.clone());
        name
    }
}

#[derive(Debug, Default)]
struct MaterialTable {
    by_key: BTreeMap<(String, [u32; 4]), String>,
    used: BTreeMap<String, u32>,
    elements: Vec<Element>,
}

impl MaterialTable {
    fn intern(&mut self, base: &str, rgba: [f32; 4]) -> String {
        let key = (base.to_string(), rgba.map(f32::to_bits));
        if let Some(n) = self.by_key.get(&key) {
            return n.clone();
        }
        let n = self.used.entry(base.to_string()).or_insert(0);
        *n += 1;
        let name = if *n == 1 { base.to_string() } else { format!("{base}_{n}") };
        self.elements.push(
            Element::new("material")
                .with("name", name.clone())
                .with("rgba", nums(&rgba.map(f64::from)))
                .with("specular", "0.2")
                .with("shininess", "0.2"),
        );
        self.by_key.insert(key, name.clone());
        name
    }
}

fn build(input: &SceneInput<'_>, robots: &[PreparedRobot], meshes: &mut MeshTable) -> Element {
    let layout = input.layout;
    let size = layout.room.size;
    let (w, d, h) = (size.width, size.depth, size.height);
    let mut root = Element::new("mujoco").with("model", "scenewright");
    let mut prompt: String = input.prompt.chars().take(240).collect();
    if prompt.len() < input.prompt.len() {
        prompt.push('…');
    }
    root.comment = Some(format!(
        "scenewright {} · seed {} · {:?} · units m kg s rad, Z up, +X east, +Y north · reset to keyframe 'home' for the spawn state",
        env!("CARGO_PKG_VERSION"),
        layout.seed,
        prompt
    ));
    root.children.push(
        Element::new("compiler")
            .with("angle", "radian")
            .with("meshdir", "assets")
            .with("texturedir", "assets")
            .with("autolimits", "true"),
    );
    root.children.push(Element::new("option").with("timestep", num(TIMESTEP)).with("integrator", "implicitfast"));
    root.children.push(
        Element::new("visual")
            .child(
                Element::new("headlight")
                    .with("ambient", "0.35 0.35 0.35")
                    .with("diffuse", "0.5 0.5 0.5")
                    .with("specular", "0.05 0.05 0.05"),
            )
            .child(
                Element::new("global")
                    .with("azimuth", "120")
                    .with("elevation", "-30")
                    .with("offwidth", "1600")
                    .with("offheight", "900"),
            )
            .child(Element::new("quality").with("shadowsize", "4096")),
    );
    let extent = 0.5 * (w * w + d * d).sqrt();
    root.children
        .push(Element::new("statistic").with("center", nums(&[0.0, 0.0, 1.0])).with("extent", num(extent.max(1.0))));

    // Defaults: visual meshes neither collide nor weigh; collision primitives are group 3.
    let mut defaults = Element::new("default")
        .child(Element::new("default").with("class", "sw_visual").child(
            Element::new("geom").with("group", "2").with("contype", "0").with("conaffinity", "0").with("density", "0"),
        ))
        .child(
            Element::new("default")
                .with("class", "sw_collision")
                .child(Element::new("geom").with("group", "3").with("rgba", "0.85 0.4 0.3 0.35")),
        )
        .child(
            Element::new("default")
                .with("class", "sw_surface")
                .child(Element::new("site").with("group", "5").with("type", "box").with("rgba", "0.2 0.8 0.3 0.3")),
        );
    for r in robots {
        defaults.children.extend(r.defaults.iter().cloned());
    }
    root.children.push(defaults);

    let mut materials = MaterialTable::default();
    let mut asset = Element::new("asset")
        .child(
            Element::new("texture")
                .with("name", "sw_floor")
                .with("type", "2d")
                .with("builtin", "checker")
                .with("rgb1", "0.62 0.63 0.64")
                .with("rgb2", "0.55 0.56 0.57")
                .with("width", "512")
                .with("height", "512")
                .with("mark", "edge")
                .with("markrgb", "0.45 0.46 0.47"),
        )
        .child(
            Element::new("texture")
                .with("name", "sw_sky")
                .with("type", "skybox")
                .with("builtin", "gradient")
                .with("rgb1", "0.75 0.82 0.9")
                .with("rgb2", "0.25 0.3 0.38")
                .with("width", "256")
                .with("height", "256"),
        )
        .child(
            Element::new("material")
                .with("name", "sw_floor")
                .with("texture", "sw_floor")
                .with("texrepeat", "1 1")
                .with("texuniform", "true")
                .with("reflectance", "0.05"),
        )
        .child(Element::new("material").with("name", "sw_wall").with("rgba", "0.86 0.86 0.83 1"))
        .child(Element::new("material").with("name", "sw_door").with("rgba", "0.35 0.55 0.4 1"));

    let mut world = Element::new("worldbody");
    world.children.push(
        Element::new("light")
            .with("name", "sw_sun")
            .with("directional", "true")
            .with("pos", nums(&[0.0, 0.0, h + 2.0]))
            .with("dir", "0.25 0.35 -1")
            .with("diffuse", "0.55 0.55 0.55")
            .with("castshadow", "true"),
    );
    world.children.push(
        Element::new("light")
            .with("name", "sw_fill")
            .with("pos", nums(&[0.0, 0.0, h]))
            .with("dir", "0 0 -1")
            .with("diffuse", "0.25 0.25 0.25")
            .with("castshadow", "false"),
    );
    world.children.push(overview_camera(d, h));
    world.children.push(front_camera(layout));
    let t = layout.room.wall_thickness;
    world.children.push(
        Element::new("geom")
            .with("name", "floor")
            .with("type", "plane")
            .with("size", nums(&[w / 2.0 + t, d / 2.0 + t, 0.05]))
            .with("material", "sw_floor"),
    );
    for g in walls(layout) {
        world.children.push(g);
    }

    for (obj, asset_ref) in layout.objects.iter().zip(&input.assets) {
        world.children.push(object_body(obj, asset_ref, meshes, &mut materials));
    }
    for r in robots {
        world.children.extend(r.bodies.iter().cloned());
    }
    asset.children.extend(materials.elements);
    // Meshes referenced by this document only (scene_only omits none: robots bring none).
    let mut used_meshes = Vec::new();
    world.walk(&mut |e| {
        if e.name == "geom"
            && let Some(m) = e.get("mesh")
            && !used_meshes.iter().any(|x: &String| x == m)
        {
            used_meshes.push(m.to_string());
        }
    });
    for f in &meshes.files {
        let stem = f.file_name.trim_end_matches(".stl");
        if used_meshes.iter().any(|m| m == stem) {
            asset.children.push(Element::new("mesh").with("name", stem).with("file", f.file_name.clone()));
        }
    }
    for r in robots {
        asset.children.extend(r.assets.iter().cloned());
    }
    root.children.push(asset);

    let key = home_key(&world, robots);
    root.children.push(world);
    for section in MERGED_SECTIONS {
        let items: Vec<Element> =
            robots.iter().flat_map(|r| r.sections.get(*section).cloned().unwrap_or_default()).collect();
        if !items.is_empty() {
            let mut s = Element::new(section);
            s.children = items;
            root.children.push(s);
        }
    }
    root.children.push(Element::new("keyframe").child(key));
    root
}

/// A camera inside the room, high on the south side, looking at the room's centre (wide
/// angle: a room seen from within).
fn overview_camera(d: f64, h: f64) -> Element {
    let margin = 0.15;
    let eye = [0.0, -0.5 * d + margin, (h - margin).max(0.5)];
    look_at("overview", eye, [0.0, 0.1 * d, 0.3 * h.min(3.0)], 75.0)
}

/// The camera a policy sees the work with: in front of the first robot, across its work
/// (its base and the movable things within its reach), slightly above — inside the room.
fn front_camera(layout: &LaidOutScene) -> Element {
    let s = layout.room.size;
    let (hw, hd) = (0.5 * s.width, 0.5 * s.depth);
    let near_things = |p: [f64; 3], r: f64| -> Vec<[f64; 3]> {
        layout
            .objects
            .iter()
            .filter(|o| o.movable && (o.pos[0] - p[0]).hypot(o.pos[1] - p[1]) < r)
            .map(|o| [o.pos[0], o.pos[1], o.pos[2] + 0.5 * o.size[2]])
            .collect()
    };
    let (center, forward, radius) = match layout.robots.first() {
        Some(r) => {
            let f = [r.yaw.cos(), r.yaw.sin()];
            let mut pts = vec![[r.pos[0] + 0.45 * f[0], r.pos[1] + 0.45 * f[1], r.pos[2] + 0.1]];
            pts.push([r.pos[0], r.pos[1], r.pos[2] + 0.3]);
            pts.extend(near_things(r.pos, 1.0));
            let c = centroid(&pts);
            let rad = pts.iter().map(|p| (p[0] - c[0]).hypot(p[1] - c[1])).fold(0.3, f64::max);
            (c, f, rad)
        }
        None => {
            let pts = near_things([0.0; 3], f64::INFINITY);
            let c = if pts.is_empty() { [0.0, 0.0, 0.5] } else { centroid(&pts) };
            let rad = pts.iter().map(|p| (p[0] - c[0]).hypot(p[1] - c[1])).fold(0.5, f64::max);
            (c, [0.0, 1.0], rad)
        }
    };
    // Across the work from in front, looking down at about 40 degrees.
    let dist = (1.5 * radius).clamp(0.8, 3.0);
    let margin = 0.12;
    let eye = [
        (center[0] + forward[0] * dist).clamp(-hw + margin, hw - margin),
        (center[1] + forward[1] * dist).clamp(-hd + margin, hd - margin),
        (center[2] + 0.85 * dist).min(s.height - margin),
    ];
    look_at("front", eye, center, 58.0)
}

fn centroid(pts: &[[f64; 3]]) -> [f64; 3] {
    let n = pts.len().max(1) as f64;
    let mut c = [0.0; 3];
    for p in pts {
        for i in 0..3 {
            c[i] += p[i] / n;
        }
    }
    c
}

/// A fixed camera at `eye` looking at `target`, image up towards +Z.
fn look_at(name: &str, eye: [f64; 3], target: [f64; 3], fovy: f64) -> Element {
    let f = normalize([target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]]);
    let z = [-f[0], -f[1], -f[2]];
    let x = normalize(cross([0.0, 0.0, 1.0], z));
    let y = cross(z, x);
    Element::new("camera")
        .with("name", name)
        .with("pos", nums(&eye))
        .with("xyaxes", nums(&[x[0], x[1], x[2], y[0], y[1], y[2]]))
        .with("fovy", num(fovy))
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalize(a: [f64; 3]) -> [f64; 3] {
    let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    if l > 0.0 { a.map(|v| v / l) } else { [0.0, 0.0, 1.0] }
}

/// Four walls outside the floor rectangle, with the doorway cut from its wall.
fn walls(layout: &LaidOutScene) -> Vec<Element> {
    let s = layout.room.size;
    let (w, d, h, t) = (s.width, s.depth, s.height, layout.room.wall_thickness);
    let door = &layout.room.door;
    let mut out = Vec::new();
    for wall in Wall::ALL {
        // Along-wall extent (including corners for north/south), and the wall's centre line.
        let (len, normal_offset, along_x) = match wall {
            Wall::North => (w + 2.0 * t, d / 2.0 + t / 2.0, true),
            Wall::South => (w + 2.0 * t, -(d / 2.0 + t / 2.0), true),
            Wall::East => (d, w / 2.0 + t / 2.0, false),
            Wall::West => (d, -(w / 2.0 + t / 2.0), false),
        };
        let mut segments: Vec<(f64, f64, f64, f64, &str)> = Vec::new(); // (from, to, z0, z1, material)
        if door.wall == wall {
            let (a, b) = (door.offset - door.width / 2.0, door.offset + door.width / 2.0);
            segments.push((-len / 2.0, a, 0.0, h, "sw_wall"));
            segments.push((b, len / 2.0, 0.0, h, "sw_wall"));
            if h > door.height + 0.05 {
                segments.push((a, b, door.height, h, "sw_wall"));
            }
        } else {
            segments.push((-len / 2.0, len / 2.0, 0.0, h, "sw_wall"));
        }
        for (k, (a, b, z0, z1, mat)) in segments.into_iter().enumerate() {
            if b - a < 1e-3 {
                continue;
            }
            let c = 0.5 * (a + b);
            let (pos, half) = if along_x {
                ([c, normal_offset, 0.5 * (z0 + z1)], [0.5 * (b - a), t / 2.0, 0.5 * (z1 - z0)])
            } else {
                ([normal_offset, c, 0.5 * (z0 + z1)], [t / 2.0, 0.5 * (b - a), 0.5 * (z1 - z0)])
            };
            let name = if door.wall == wall {
                format!("wall_{}_{}", wall.name(), k + 1)
            } else {
                format!("wall_{}", wall.name())
            };
            out.push(
                Element::new("geom")
                    .with("name", name)
                    .with("type", "box")
                    .with("pos", nums(&pos))
                    .with("size", nums(&half))
                    .with("material", mat),
            );
        }
    }
    // A visual door leaf standing open against the wall is noise; mark the doorway on the floor.
    let (dx, dy, hx, hy) = match door.wall {
        Wall::North => (door.offset, d / 2.0 - 0.3, door.width / 2.0, 0.3),
        Wall::South => (door.offset, -d / 2.0 + 0.3, door.width / 2.0, 0.3),
        Wall::East => (w / 2.0 - 0.3, door.offset, 0.3, door.width / 2.0),
        Wall::West => (-w / 2.0 + 0.3, door.offset, 0.3, door.width / 2.0),
    };
    out.push(
        Element::new("geom")
            .with("name", "doorway")
            .with("type", "box")
            .with("pos", nums(&[dx, dy, 0.0005]))
            .with("size", nums(&[hx, hy, 0.0005]))
            .with("material", "sw_door")
            .with("contype", "0")
            .with("conaffinity", "0")
            .with("group", "1"),
    );
    out
}

fn object_body(obj: &PlacedObject, asset: &Asset, meshes: &mut MeshTable, materials: &mut MaterialTable) -> Element {
    let mut body = Element::new("body").with("name", obj.name.clone()).with("pos", nums(&obj.pos));
    if obj.yaw.abs() > 1e-12 {
        body.set("quat", nums(&Pose::from_pos_yaw([0.0; 3], obj.yaw).quat));
    }
    if let MassModel::Free { mass } = asset.mass {
        body.children.push(Element::new("freejoint").with("name", format!("{}_joint", obj.name)));
        body.children.push(inertial(&asset.links[0], mass));
    }
    fill_link(&mut body, obj, asset, 0, meshes, materials);
    for s in &asset.surfaces {
        let cx = 0.5 * (s.min[0] + s.max[0]);
        let cy = 0.5 * (s.min[1] + s.max[1]);
        body.children.push(
            Element::new("site")
                .with("name", format!("{}_{}", obj.name, s.name))
                .with("class", "sw_surface")
                .with("pos", nums(&[cx, cy, s.z]))
                .with("size", nums(&[0.5 * (s.max[0] - s.min[0]), 0.5 * (s.max[1] - s.min[1]), 0.001])),
        );
    }
    body
}

/// Adds link `index`'s geoms to `body`, and its child links as nested bodies.
fn fill_link(
    body: &mut Element,
    obj: &PlacedObject,
    asset: &Asset,
    index: usize,
    meshes: &mut MeshTable,
    materials: &mut MaterialTable,
) {
    let Some(link) = asset.links.get(index) else {
        return;
    };
    for v in &link.visuals {
        let Some(mat) = asset.materials.get(v.material) else {
            continue;
        };
        if v.mesh.is_empty() {
            continue;
        }
        let mesh = meshes.intern(&asset.category, &v.mesh);
        let material = materials.intern(&format!("{}_{}", asset.category, mat.name), mat.rgba);
        body.children.push(
            Element::new("geom")
                .with("class", "sw_visual")
                .with("type", "mesh")
                .with("mesh", mesh)
                .with("material", material),
        );
    }
    let prefix = if link.name.is_empty() { obj.name.clone() } else { format!("{}_{}", obj.name, link.name) };
    for (k, c) in link.collisions.iter().enumerate() {
        let mut g = Element::new("geom").with("name", format!("{prefix}_c{k}")).with("class", "sw_collision");
        match c.shape {
            Shape::Box { half } => {
                g.set("type", "box");
                g.set("size", nums(&half));
            }
            Shape::Cylinder { radius, half_height } => {
                g.set("type", "cylinder");
                g.set("size", nums(&[radius, half_height]));
            }
            Shape::Sphere { radius } => {
                g.set("type", "sphere");
                g.set("size", num(radius));
            }
            Shape::Capsule { radius, half_height } => {
                g.set("type", "capsule");
                g.set("size", nums(&[radius, half_height]));
            }
        }
        g.set("pos", nums(&c.pose.pos));
        if !c.pose.is_unrotated() {
            g.set("quat", nums(&c.pose.quat));
        }
        body.children.push(g);
    }
    // Convex pieces of generated assets: MuJoCo collides a mesh as its convex hull.
    let first = link.collisions.len();
    for (k, piece) in link.convex.iter().enumerate() {
        if piece.mesh.is_empty() {
            continue;
        }
        let mesh = meshes.intern(&format!("{}_hull", asset.category), &piece.mesh);
        body.children.push(
            Element::new("geom")
                .with("name", format!("{prefix}_c{}", first + k))
                .with("class", "sw_collision")
                .with("type", "mesh")
                .with("mesh", mesh),
        );
    }
    for (ci, child) in asset.links.iter().enumerate().filter(|(_, l)| l.parent == Some(index)) {
        let mut b = Element::new("body")
            .with("name", format!("{}_{}", obj.name, child.name))
            .with("pos", nums(&child.pose.pos));
        if !child.pose.is_unrotated() {
            b.set("quat", nums(&child.pose.quat));
        }
        if let Some(j) = &child.joint {
            let kind = match j.kind {
                sw_geom::JointKind::Hinge => "hinge",
                sw_geom::JointKind::Slide => "slide",
            };
            b.children.push(
                Element::new("joint")
                    .with("name", format!("{}_{}_joint", obj.name, child.name))
                    .with("type", kind)
                    .with("axis", nums(&j.axis))
                    .with("pos", nums(&j.anchor))
                    .with("range", nums(&j.range))
                    .with("damping", num(j.damping)),
            );
        }
        b.children.push(inertial(child, child.mass.max(0.05)));
        fill_link(&mut b, obj, asset, ci, meshes, materials);
        body.children.push(b);
    }
}

/// A solid-box inertia over the link's collision geometry.
fn inertial(link: &Link, mass: f64) -> Element {
    let mut b = Aabb::EMPTY;
    for c in &link.collisions {
        b = b.union(&c.aabb());
    }
    for p in &link.convex {
        b = b.union(&p.aabb());
    }
    let (c, s) = if b.is_empty() { ([0.0; 3], [0.1; 3]) } else { (b.center(), b.size()) };
    let m = mass.max(1e-3);
    let i = [
        m / 12.0 * (s[1] * s[1] + s[2] * s[2]),
        m / 12.0 * (s[0] * s[0] + s[2] * s[2]),
        m / 12.0 * (s[0] * s[0] + s[1] * s[1]),
    ]
    .map(|v| v.max(1e-7));
    let inertia = i.iter().map(|v| sig(*v)).collect::<Vec<_>>().join(" ");
    Element::new("inertial").with("pos", nums(&c)).with("mass", sig(m)).with("diaginertia", inertia)
}

/// The `home` keyframe over every joint of the model: free bodies at their written
/// pose, robot joints at their own home, everything else at zero. A scene with no joint
/// and no actuator still gets one (empty), so that resetting to `home` works on every
/// package, as the README says.
pub(crate) fn home_key(world: &Element, robots: &[PreparedRobot]) -> Element {
    let robot_home: BTreeMap<&str, &Vec<f64>> =
        robots.iter().flat_map(|r| r.home_qpos.iter().map(|(k, v)| (k.as_str(), v))).collect();
    let mut qpos: Vec<f64> = Vec::new();
    fn visit(body: &Element, robot_home: &BTreeMap<&str, &Vec<f64>>, qpos: &mut Vec<f64>) {
        for c in &body.children {
            match c.name.as_str() {
                "freejoint" => push_free(body, qpos),
                "joint" => {
                    let name = c.get("name").unwrap_or_default();
                    // Robot joints carry their home with the width their (resolved) type has.
                    match (c.get("type"), robot_home.get(name)) {
                        (Some("free"), _) => push_free(body, qpos),
                        (_, Some(v)) if v.len() != 7 => qpos.extend(v.iter().copied()),
                        (Some("ball"), _) => qpos.extend([1.0, 0.0, 0.0, 0.0]),
                        _ => qpos.push(c.get("ref").and_then(|r| r.parse().ok()).unwrap_or(0.0)),
                    }
                }
                _ => {}
            }
        }
        for c in body.children.iter().filter(|c| c.name == "body" || c.name == "frame") {
            visit(c, robot_home, qpos);
        }
    }
    fn push_free(body: &Element, qpos: &mut Vec<f64>) {
        let p = parse_list(body.get("pos"));
        let q = parse_list(body.get("quat"));
        qpos.extend(if p.len() == 3 { p } else { vec![0.0; 3] });
        qpos.extend(if q.len() == 4 { q } else { vec![1.0, 0.0, 0.0, 0.0] });
    }
    for b in world.children.iter().filter(|c| c.name == "body") {
        visit(b, &robot_home, &mut qpos);
    }
    let ctrl: Vec<f64> = robots
        .iter()
        .flat_map(|r| {
            let n = r.sections.get("actuator").map_or(0, Vec::len);
            (0..n).map(|i| r.home_ctrl.get(i).copied().unwrap_or(0.0)).collect::<Vec<_>>()
        })
        .collect();
    let mut key = Element::new("key").with("name", "home");
    if !qpos.is_empty() {
        key.set("qpos", nums(&qpos));
    }
    if !ctrl.is_empty() {
        key.set("ctrl", nums(&ctrl));
    }
    key
}
