//! Physics targets: the simulator a package is written for.
//!
//! `native` is MuJoCo itself (and MuJoCo Warp, which implements every collision pair
//! MuJoCo has). `mjx` is MuJoCo XLA's JAX implementation, which lacks some collision
//! pairs and cannot scan a model without degrees of freedom. MJX 3.17 implements every
//! pair among plane, sphere, capsule, box and mesh (except plane–plane, which never
//! collides), and these with cylinders and ellipsoids: plane–cylinder, sphere–cylinder,
//! capsule–cylinder, cylinder–cylinder, plane–ellipsoid, sphere–ellipsoid,
//! capsule–ellipsoid, ellipsoid–ellipsoid, ellipsoid–cylinder. It lacks (see
//! [`MJX_MISSING_PAIRS`]) cylinder–box, cylinder–mesh, ellipsoid–box, ellipsoid–mesh and
//! every pair with a height field but plane, sphere, capsule, box and mesh.
//!
//! So for `mjx` every colliding cylinder and ellipsoid is rewritten, and the scene then
//! holds only planes, spheres, capsules, boxes and meshes, whose pairs MJX all has:
//!
//! - an object's cylinder (class `sw_collision`) becomes the box of its own bounding box
//!   (half sizes r, r, h; same pose). The layout keeps objects apart by exactly these
//!   boxes (`Asset::collision_aabbs`), so placement and clearances are unchanged, and a
//!   support surface on a cylinder top only grows;
//! - a robot's cylinder becomes the capsule inside it (same axis and radius, its end
//!   points pulled in by the radius, so it reaches the same end faces and never sticks
//!   out). One shorter than its diameter becomes, on a body that turns about a hinge (a
//!   wheel), the sphere of its radius at its centre, which rolls as the wheel did and
//!   touches the floor where it did; otherwise (a base plate, a flange) the box around it,
//!   which keeps its end faces where they were (a sphere would reach into the next link);
//! - an ellipsoid becomes the box around it.
//!
//! A scene with no joint at all gets one hinge about the vertical axis on a massless-
//! looking body with no geoms (`sw_mjx_anchor`): gravity exerts no torque about it, so it
//! never moves, and MJX can step the model. Visual geoms (no contacts) are left as they are.

use std::collections::BTreeMap;

use crate::SceneFiles;
use crate::xml::{Element, XmlError, num, nums};

/// The simulator a package is written for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PhysicsTarget {
    /// MuJoCo (and MuJoCo Warp): every primitive as it is.
    #[default]
    Native,
    /// MuJoCo XLA (JAX): only collision pairs MJX implements, at least one DOF.
    Mjx,
}

impl PhysicsTarget {
    pub const ALL: [PhysicsTarget; 2] = [PhysicsTarget::Native, PhysicsTarget::Mjx];

    pub fn name(self) -> &'static str {
        match self {
            PhysicsTarget::Native => "native",
            PhysicsTarget::Mjx => "mjx",
        }
    }

    pub fn parse(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == s.trim().to_ascii_lowercase())
    }
}

/// Collision pairs (MJCF geom type names) that MuJoCo XLA 3.17 does not implement.
pub const MJX_MISSING_PAIRS: &[(&str, &str)] = &[
    ("cylinder", "box"),
    ("cylinder", "mesh"),
    ("ellipsoid", "box"),
    ("ellipsoid", "mesh"),
    ("hfield", "ellipsoid"),
    ("hfield", "cylinder"),
];

/// Name of the body that gives a scene without joints its one degree of freedom.
pub const MJX_ANCHOR: &str = "sw_mjx_anchor";

/// Rewrites `files` for `target`; returns what was changed, in words (nothing for native).
pub fn adapt(files: &mut SceneFiles, target: PhysicsTarget) -> Result<Vec<String>, XmlError> {
    if target == PhysicsTarget::Native {
        return Ok(Vec::new());
    }
    let (scene, notes) = adapt_document(&files.scene_xml, target)?;
    let (only, _) = adapt_document(&files.scene_only_xml, target)?;
    files.scene_xml = scene;
    files.scene_only_xml = only;
    Ok(notes)
}

/// [`adapt`] for one MJCF document (its leading comment is kept and says the target).
pub fn adapt_document(xml: &str, target: PhysicsTarget) -> Result<(String, Vec<String>), XmlError> {
    let mut root = Element::parse(xml)?;
    if target == PhysicsTarget::Native {
        return Ok((xml.to_string(), Vec::new()));
    }
    root.comment = leading_comment(xml).map(|c| format!("{c} · physics: {}", target.name()));
    let defaults = Defaults::read(&root);
    let mut counts = Counts::default();
    if let Some(world) = root.first_mut("worldbody") {
        rewrite_bodies(world, &defaults, None, &mut counts);
    }
    if !has_joint(&root) {
        add_anchor(&mut root);
        counts.anchor = true;
    }
    Ok((root.to_document(), counts.notes()))
}

/// Writes MJX's contact limits into a document's `<custom>` numerics: `max_geom_pairs`
/// (pairs kept per pair-type group, nearest bounding spheres first) and
/// `max_contact_points` (deepest contacts kept). Native MuJoCo ignores them; the numbers
/// come from `sw_sim::contact_budget`, measured on the scene.
pub fn with_contact_budget(xml: &str, max_geom_pairs: u32, max_contact_points: u32) -> Result<String, XmlError> {
    let mut root = Element::parse(xml)?;
    root.comment = leading_comment(xml);
    let custom = root.section("custom");
    custom
        .children
        .retain(|c| !(c.name == "numeric" && matches!(c.get("name"), Some("max_geom_pairs" | "max_contact_points"))));
    custom
        .children
        .push(Element::new("numeric").with("name", "max_geom_pairs").with("data", max_geom_pairs.to_string()));
    custom
        .children
        .push(Element::new("numeric").with("name", "max_contact_points").with("data", max_contact_points.to_string()));
    Ok(root.to_document())
}

/// Geom type pairs among colliding geoms that MJX lacks, e.g. `("cylinder", "box")`.
/// A quick check of a document (the tests' independent check is `mjx.put_model` itself).
pub fn mjx_missing_pairs(xml: &str) -> Result<Vec<(String, String)>, XmlError> {
    let root = Element::parse(xml)?;
    let defaults = Defaults::read(&root);
    let mut types: Vec<String> = Vec::new();
    if let Some(world) = root.first("worldbody") {
        collect_colliding_types(world, &defaults, None, &mut types);
    }
    types.sort();
    types.dedup();
    let mut out = Vec::new();
    for (a, b) in MJX_MISSING_PAIRS {
        if types.iter().any(|t| t == a) && types.iter().any(|t| t == b) {
            out.push((a.to_string(), b.to_string()));
        }
    }
    Ok(out)
}

fn leading_comment(xml: &str) -> Option<String> {
    let start = xml.find("<!--")?;
    let root = xml.find("<mujoco")?;
    if start > root {
        return None;
    }
    let end = xml[start..].find("-->")? + start;
    Some(xml[start + 4..end].trim().to_string())
}

/// A default class: its parent and the geom attributes it sets itself.
type Class = (Option<String>, Vec<(String, String)>);

/// Geom attributes of every default class, and each class's parent.
#[derive(Debug, Default)]
struct Defaults {
    classes: BTreeMap<String, Class>,
}

impl Defaults {
    fn read(root: &Element) -> Self {
        let mut d = Defaults::default();
        fn visit(e: &Element, parent: Option<&str>, d: &mut Defaults) {
            let name = e.get("class").unwrap_or("main").to_string();
            let geom = e.first("geom").map(|g| g.attrs.clone()).unwrap_or_default();
            d.classes.insert(name.clone(), (parent.map(str::to_string), geom));
            for c in e.children.iter().filter(|c| c.name == "default") {
                visit(c, Some(&name), d);
            }
        }
        for top in root.children.iter().filter(|c| c.name == "default") {
            visit(top, None, &mut d);
        }
        d
    }

    /// A geom attribute: its own, else its class's (walking up to `main`).
    fn attr<'a>(&'a self, geom: &'a Element, class: Option<&str>, key: &str) -> Option<&'a str> {
        if let Some(v) = geom.get(key) {
            return Some(v);
        }
        let mut c = Some(geom.get("class").or(class).unwrap_or("main").to_string());
        let mut hops = 0;
        while let Some(name) = c {
            let (parent, attrs) = self.classes.get(&name)?;
            if let Some((_, v)) = attrs.iter().find(|(k, _)| k == key) {
                return Some(v.as_str());
            }
            c = parent.clone();
            hops += 1;
            if hops > 64 {
                return None;
            }
        }
        None
    }

    fn geom_type<'a>(&'a self, geom: &'a Element, class: Option<&str>) -> &'a str {
        self.attr(geom, class, "type").unwrap_or("sphere")
    }

    fn collides(&self, geom: &Element, class: Option<&str>) -> bool {
        let flag = |k: &str| self.attr(geom, class, k).and_then(|v| v.trim().parse::<i64>().ok()).unwrap_or(1);
        flag("contype") != 0 || flag("conaffinity") != 0
    }
}

#[derive(Debug, Default)]
struct Counts {
    object_boxes: usize,
    robot_capsules: usize,
    robot_spheres: usize,
    robot_boxes: usize,
    ellipsoid_boxes: usize,
    anchor: bool,
}

impl Counts {
    fn notes(&self) -> Vec<String> {
        let mut out = Vec::new();
        if self.object_boxes > 0 {
            out.push(format!(
                "physics mjx: {} object cylinder{} collide as {} bounding box{} (MJX has no cylinder–box pair)",
                self.object_boxes,
                plural(self.object_boxes),
                if self.object_boxes == 1 { "its" } else { "their" },
                if self.object_boxes == 1 { "" } else { "es" }
            ));
        }
        if self.robot_capsules + self.robot_spheres + self.robot_boxes > 0 {
            out.push(format!(
                "physics mjx: robot cylinders collide as the capsule inside them ({}); shorter than wide, as a sphere on wheels ({}) or their bounding box ({})",
                self.robot_capsules, self.robot_spheres, self.robot_boxes
            ));
        }
        if self.ellipsoid_boxes > 0 {
            out.push(format!(
                "physics mjx: {} ellipsoid{} collide as {} bounding box",
                self.ellipsoid_boxes,
                plural(self.ellipsoid_boxes),
                if self.ellipsoid_boxes == 1 { "its" } else { "their" }
            ));
        }
        if self.anchor {
            out.push(format!(
                "physics mjx: the scene has no joint, so an anchor hinge ({MJX_ANCHOR}) gives MJX one degree of freedom"
            ));
        }
        out
    }
}

fn plural(n: usize) -> &'static str {
    if n == 1 { "" } else { "s" }
}

fn rewrite_bodies(e: &mut Element, defaults: &Defaults, childclass: Option<&str>, counts: &mut Counts) {
    let inherited = e.get("childclass").map(str::to_string).or_else(|| childclass.map(str::to_string));
    // A body that turns about a hinge (a joint's type defaults to hinge).
    let turns =
        e.name == "body" && e.children.iter().any(|c| c.name == "joint" && c.get("type").is_none_or(|t| t == "hinge"));
    for c in &mut e.children {
        match c.name.as_str() {
            "geom" => rewrite_geom(c, defaults, inherited.as_deref(), turns, counts),
            "body" | "frame" => rewrite_bodies(c, defaults, inherited.as_deref(), counts),
            _ => {}
        }
    }
}

fn collect_colliding_types(e: &Element, defaults: &Defaults, childclass: Option<&str>, out: &mut Vec<String>) {
    let inherited = e.get("childclass").map(str::to_string).or_else(|| childclass.map(str::to_string));
    for c in &e.children {
        match c.name.as_str() {
            "geom" if defaults.collides(c, inherited.as_deref()) => {
                out.push(defaults.geom_type(c, inherited.as_deref()).to_string());
            }
            "body" | "frame" => collect_colliding_types(c, defaults, inherited.as_deref(), out),
            _ => {}
        }
    }
}

fn floats(s: Option<&str>) -> Vec<f64> {
    s.map(|s| s.split_whitespace().filter_map(|x| x.parse::<f64>().ok()).collect()).unwrap_or_default()
}

fn rewrite_geom(g: &mut Element, defaults: &Defaults, class: Option<&str>, turns: bool, counts: &mut Counts) {
    if !defaults.collides(g, class) {
        return;
    }
    let kind = defaults.geom_type(g, class).to_string();
    let size = floats(defaults.attr(g, class, "size"));
    let fromto = floats(defaults.attr(g, class, "fromto"));
    let is_object = g.get("class") == Some("sw_collision");
    match kind.as_str() {
        "cylinder" if is_object => {
            let (Some(&r), Some(&h)) = (size.first(), size.get(1)) else { return };
            g.set("type", "box");
            g.set("size", nums(&[r, r, h]));
            counts.object_boxes += 1;
        }
        "cylinder" => {
            let Some(&r) = size.first() else { return };
            // The cylinder's centre, axis (unit, in the geom's frame or the body's) and half length.
            let (centre, axis, h) = if fromto.len() == 6 {
                let (a, b) = ([fromto[0], fromto[1], fromto[2]], [fromto[3], fromto[4], fromto[5]]);
                let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                if len < 1e-12 {
                    return;
                }
                ([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0], Some(d.map(|x| x / len)), len / 2.0)
            } else {
                let Some(&h) = size.get(1) else { return };
                ([0.0; 3], None, h)
            };
            if h > r + 1e-9 {
                // The capsule inside: same axis and radius, reaching the same end faces.
                g.set("type", "capsule");
                match axis {
                    Some(u) => {
                        let k = h - r;
                        let a = [centre[0] - u[0] * k, centre[1] - u[1] * k, centre[2] - u[2] * k];
                        let b = [centre[0] + u[0] * k, centre[1] + u[1] * k, centre[2] + u[2] * k];
                        g.set("fromto", nums(&[a[0], a[1], a[2], b[0], b[1], b[2]]));
                        g.set("size", num(r));
                    }
                    None => g.set("size", nums(&[r, h - r])),
                }
                counts.robot_capsules += 1;
            } else if turns {
                // A wheel: the sphere of its radius rolls as it did.
                g.set("type", "sphere");
                g.set("size", num(r));
                if axis.is_some() {
                    g.remove("fromto");
                    g.set("pos", nums(&centre));
                }
                counts.robot_spheres += 1;
            } else {
                // A plate or flange: the box around it keeps its end faces in place.
                g.set("type", "box");
                g.set("size", nums(&[r, r, h]));
                if let Some(u) = axis {
                    g.remove("fromto");
                    for k in ["axisangle", "euler", "xyaxes", "zaxis"] {
                        g.remove(k);
                    }
                    g.set("pos", nums(&centre));
                    g.set("quat", nums(&quat_z_to(u)));
                }
                counts.robot_boxes += 1;
            }
        }
        "ellipsoid" if size.len() == 3 => {
            g.set("type", "box");
            g.set("size", nums(&size));
            counts.ellipsoid_boxes += 1;
        }
        _ => {}
    }
}

/// The unit quaternion (w x y z) turning +Z onto the unit vector `u` (MuJoCo's own
/// convention for `fromto`: the shortest rotation).
fn quat_z_to(u: [f64; 3]) -> [f64; 4] {
    // Half-way vector between +Z and u; for u = -Z, a half turn about X.
    let w = 1.0 + u[2];
    if w < 1e-9 {
        return [0.0, 1.0, 0.0, 0.0];
    }
    let q = [w, -u[1], u[0], 0.0];
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    q.map(|x| x / n)
}

fn has_joint(root: &Element) -> bool {
    let mut found = false;
    if let Some(world) = root.first("worldbody") {
        world.walk(&mut |e| {
            if e.name == "joint" || e.name == "freejoint" {
                found = true;
            }
        });
    }
    found
}

/// One hinge about +Z through its own centre of mass: gravity cannot turn it.
fn add_anchor(root: &mut Element) {
    let body = Element::new("body")
        .with("name", MJX_ANCHOR)
        .with("pos", "0 0 0")
        .child(Element::new("joint").with("name", MJX_ANCHOR).with("type", "hinge").with("axis", "0 0 1"))
        .child(
            Element::new("inertial").with("pos", "0 0 0").with("mass", "0.001").with("diaginertia", "1e-6 1e-6 1e-6"),
        );
    root.section("worldbody").children.push(body);
    // No joint before means no keyframe qpos before: `home` gets the anchor's one value.
    let keyframe = root.section("keyframe");
    match keyframe.children.iter_mut().find(|k| k.get("name") == Some("home")) {
        Some(k) => {
            let mut q = floats(k.get("qpos"));
            q.push(0.0);
            k.set("qpos", nums(&q));
        }
        None => keyframe.children.push(Element::new("key").with("name", "home").with("qpos", "0")),
    }
}
