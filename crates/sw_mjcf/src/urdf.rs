//! URDF import: a URDF robot as an MJCF document the merger takes.
//!
//! Links become bodies (the joint's origin is the child body's pose), revolute and
//! continuous joints hinges, prismatic joints slides, floating joints free joints, mimic
//! joints joint equalities. Visuals become non-colliding geoms in group 2, collisions geoms
//! in group 3. URDF describes no controller, so every actuated joint gets a position servo
//! limited to the joint's `effort`, and the bodies are gravity-compensated (as the real
//! controllers of arms are); both are reported in the notes. Mesh paths (`package://`,
//! `file://`, relative) are resolved by the caller's function; MuJoCo reads STL, OBJ and
//! MSH meshes only, so other formats are an error naming the element.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::normalize::euler_to_quat;
use crate::xml::{Element, num, nums};

/// A URDF that cannot be imported; names the file and the element.
#[derive(Debug, thiserror::Error)]
pub enum UrdfError {
    #[error("{file}: not valid XML at line {line}, column {column}: {message}")]
    Xml { file: String, line: u32, column: u32, message: String },
    #[error("{file}: {element}: {why}")]
    Element { file: String, element: String, why: String },
}

/// Tags URDF tools write that have no meaning for a MuJoCo scene: skipped, and noted.
const IGNORED: &[&str] = &["transmission", "gazebo", "calibration", "safety_controller"];

/// Servo stiffness per N·m of joint effort, 1/rad, and damping per stiffness, s.
const KP_PER_EFFORT: f64 = 20.0;
const KV_PER_KP: f64 = 0.1;

/// The converted document and what the conversion added or skipped.
#[derive(Debug, Clone)]
pub struct UrdfImport {
    pub mjcf: String,
    pub notes: Vec<String>,
}

struct Joint<'a> {
    node: roxmltree::Node<'a, 'a>,
    name: String,
    kind: String,
    parent: String,
    child: String,
}

/// Converts URDF text. `resolve` turns a mesh `filename` into a file path (or says why not).
pub fn urdf_to_mjcf(
    file: &str,
    text: &str,
    resolve: &dyn Fn(&str) -> Result<PathBuf, String>,
) -> Result<UrdfImport, UrdfError> {
    let doc = roxmltree::Document::parse(text).map_err(|e| {
        let p = e.pos();
        UrdfError::Xml { file: file.into(), line: p.row, column: p.col, message: e.to_string() }
    })?;
    let err = |element: String, why: &str| UrdfError::Element { file: file.into(), element, why: why.into() };
    let root = doc.root_element();
    if root.tag_name().name() != "robot" {
        return Err(err(format!("<{}>", root.tag_name().name()), "the root element of a URDF is <robot>"));
    }
    let robot_name = root.attribute("name").unwrap_or("robot").to_string();
    let mut notes = Vec::new();
    let mut links: BTreeMap<String, roxmltree::Node<'_, '_>> = BTreeMap::new();
    let mut link_order: Vec<String> = Vec::new();
    let mut joints: Vec<Joint<'_>> = Vec::new();
    let mut materials: BTreeMap<String, [f64; 4]> = BTreeMap::new();
    for n in root.children().filter(roxmltree::Node::is_element) {
        let tag = n.tag_name().name();
        match tag {
            "link" => {
                let name = n.attribute("name").ok_or_else(|| err("<link>".into(), "has no name"))?.to_string();
                if links.insert(name.clone(), n).is_some() {
                    return Err(err(format!("<link name=\"{name}\">"), "appears twice"));
                }
                link_order.push(name);
            }
            "joint" => {
                let name = n.attribute("name").ok_or_else(|| err("<joint>".into(), "has no name"))?.to_string();
                let el = format!("<joint name=\"{name}\">");
                let kind = n.attribute("type").ok_or_else(|| err(el.clone(), "has no type"))?.to_string();
                let link_of = |tag: &str| {
                    n.children()
                        .find(|c| c.has_tag_name(tag))
                        .and_then(|c| c.attribute("link"))
                        .map(str::to_string)
                        .ok_or_else(|| err(el.clone(), &format!("has no <{tag} link=...>")))
                };
                let (parent, child) = (link_of("parent")?, link_of("child")?);
                if joints.iter().any(|j| j.name == name) {
                    return Err(err(el, "appears twice"));
                }
                joints.push(Joint { node: n, name, kind, parent, child });
            }
            "material" => {
                if let (Some(name), Some(rgba)) = (n.attribute("name"), color(n)) {
                    materials.insert(name.to_string(), rgba);
                }
            }
            t if IGNORED.contains(&t) => {
                notes.push(format!("{file}: <{t}> elements were skipped (no meaning in a MuJoCo scene)"));
            }
            other => return Err(err(format!("<{other}>"), "is not a URDF element scenewright knows")),
        }
    }
    notes.dedup();
    for j in &joints {
        for l in [&j.parent, &j.child] {
            if !links.contains_key(l) {
                return Err(err(
                    format!("<joint name=\"{}\">", j.name),
                    &format!("names link '{l}', which is not defined"),
                ));
            }
        }
    }
    let children: BTreeSet<&str> = joints.iter().map(|j| j.child.as_str()).collect();
    let roots: Vec<&String> = link_order.iter().filter(|l| !children.contains(l.as_str())).collect();
    let [root_link] = roots.as_slice() else {
        return Err(err("<robot>".into(), &format!("needs exactly one root link, found {}", roots.len())));
    };

    let mut ctx = Ctx { file, resolve, materials, meshes: BTreeMap::new(), mesh_elems: Vec::new(), notes: Vec::new() };
    let mut world = Element::new("worldbody");
    let mut actuators = Vec::new();
    let mut equalities = Vec::new();
    let mut visited = BTreeSet::new();
    // A massless "world" root is the URDF convention for "fixed to the ground".
    let world_root = root_link.as_str() == "world" && links[root_link.as_str()].children().all(|c| !c.is_element());
    if world_root {
        for j in joints.iter().filter(|j| &j.parent == *root_link) {
            let b = ctx.body_for_joint(j, &links, &joints, &mut actuators, &mut equalities, &mut visited, true)?;
            world.children.push(b);
        }
    } else {
        let mut b = Element::new("body").with("name", root_link.as_str());
        ctx.fill_link(&mut b, links[root_link.as_str()])?;
        visited.insert(root_link.to_string());
        for j in joints.iter().filter(|j| &j.parent == *root_link) {
            let c = ctx.body_for_joint(j, &links, &joints, &mut actuators, &mut equalities, &mut visited, false)?;
            b.children.push(c);
        }
        world.children.push(b);
    }
    if visited.len() + usize::from(world_root) != links.len() {
        return Err(err("<robot>".into(), "its joints do not connect every link to the root (or form a loop)"));
    }

    let mut doc = Element::new("mujoco").with("model", robot_name);
    doc.children.push(Element::new("compiler").with("angle", "radian").with("autolimits", "true"));
    doc.children.push(
        Element::new("default")
            .child(
                Element::new("default").with("class", "visual").child(
                    Element::new("geom")
                        .with("group", "2")
                        .with("contype", "0")
                        .with("conaffinity", "0")
                        .with("density", "0"),
                ),
            )
            .child(Element::new("default").with("class", "collision").child(Element::new("geom").with("group", "3"))),
    );
    let mut asset = Element::new("asset");
    for (name, rgba) in &ctx.materials {
        asset.children.push(Element::new("material").with("name", format!("urdf_{name}")).with("rgba", nums(rgba)));
    }
    asset.children.extend(ctx.mesh_elems.iter().cloned());
    if !asset.children.is_empty() {
        doc.children.push(asset);
    }
    doc.children.push(world);
    if !equalities.is_empty() {
        doc.children.push(Element { children: equalities, ..Element::new("equality") });
    }
    if !actuators.is_empty() {
        notes.push(format!(
            "{file}: URDF has no controller; {} joint position servos (limited to each joint's effort) and gravity compensation were added",
            actuators.len()
        ));
        doc.children.push(Element { children: actuators, ..Element::new("actuator") });
    }
    notes.extend(ctx.notes);
    Ok(UrdfImport { mjcf: doc.to_document(), notes })
}

struct Ctx<'r> {
    file: &'r str,
    resolve: &'r dyn Fn(&str) -> Result<PathBuf, String>,
    materials: BTreeMap<String, [f64; 4]>,
    /// (path, scale) → mesh name.
    meshes: BTreeMap<(PathBuf, String), String>,
    mesh_elems: Vec<Element>,
    notes: Vec<String>,
}

impl Ctx<'_> {
    fn err(&self, element: String, why: impl Into<String>) -> UrdfError {
        UrdfError::Element { file: self.file.into(), element, why: why.into() }
    }

    #[allow(clippy::too_many_arguments)]
    fn body_for_joint(
        &mut self,
        j: &Joint<'_>,
        links: &BTreeMap<String, roxmltree::Node<'_, '_>>,
        joints: &[Joint<'_>],
        actuators: &mut Vec<Element>,
        equalities: &mut Vec<Element>,
        visited: &mut BTreeSet<String>,
        top_level: bool,
    ) -> Result<Element, UrdfError> {
        let el = format!("<joint name=\"{}\">", j.name);
        if !visited.insert(j.child.clone()) {
            return Err(self.err(el, format!("link '{}' is the child of two joints", j.child)));
        }
        let mut b = Element::new("body").with("name", j.child.as_str());
        let (pos, quat) = origin(j.node.children().find(|c| c.has_tag_name("origin")), self.file, &el)?;
        b.set("pos", nums(&pos));
        if (quat[0] - 1.0).abs() > 1e-12 {
            b.set("quat", nums(&quat));
        }
        b.set("gravcomp", "1");
        for c in j.node.children().filter(roxmltree::Node::is_element) {
            let t = c.tag_name().name();
            if !["parent", "child", "origin", "axis", "limit", "dynamics", "mimic"].contains(&t)
                && !IGNORED.contains(&t)
            {
                return Err(self.err(format!("{el}/<{t}>"), "is not a URDF joint element scenewright knows"));
            }
        }
        let axis = match j.node.children().find(|c| c.has_tag_name("axis")) {
            Some(a) => vec3(a.attribute("xyz"), self.file, &format!("{el}/<axis xyz>"))?,
            None => [1.0, 0.0, 0.0],
        };
        let limit = j.node.children().find(|c| c.has_tag_name("limit"));
        let lim = |k: &str| limit.and_then(|l| l.attribute(k)).and_then(|v| v.trim().parse::<f64>().ok());
        let dynamics = j.node.children().find(|c| c.has_tag_name("dynamics"));
        let dyn_attr = |k: &str| dynamics.and_then(|d| d.attribute(k)).and_then(|v| v.trim().parse::<f64>().ok());
        let mimic = j.node.children().find(|c| c.has_tag_name("mimic"));
        match j.kind.as_str() {
            "fixed" => {}
            "floating" => {
                if !top_level {
                    return Err(self.err(
                        el,
                        "a floating joint must connect the root link to the world (MuJoCo free joints are top-level)",
                    ));
                }
                b.children.push(Element::new("freejoint").with("name", j.name.as_str()));
            }
            "revolute" | "continuous" | "prismatic" => {
                let kind = if j.kind == "prismatic" { "slide" } else { "hinge" };
                let mut joint =
                    Element::new("joint").with("name", j.name.as_str()).with("type", kind).with("axis", nums(&axis));
                let range = match (j.kind.as_str(), lim("lower"), lim("upper")) {
                    ("continuous", _, _) => None,
                    (_, Some(lo), Some(hi)) if lo < hi => Some((lo, hi)),
                    (_, lo, hi) => {
                        return Err(self.err(
                            format!("{el}/<limit>"),
                            format!("a {} joint needs lower < upper (got {lo:?}, {hi:?})", j.kind),
                        ));
                    }
                };
                if let Some((lo, hi)) = range {
                    joint.set("range", nums(&[lo, hi]));
                }
                if let Some(d) = dyn_attr("damping") {
                    joint.set("damping", num(d));
                }
                if let Some(f) = dyn_attr("friction") {
                    joint.set("frictionloss", num(f));
                }
                joint.set("armature", "0.01");
                b.children.push(joint);
                if let Some(m) = mimic {
                    let Some(of) = m.attribute("joint") else {
                        return Err(self.err(format!("{el}/<mimic>"), "has no joint"));
                    };
                    if !joints.iter().any(|x| x.name == of) {
                        return Err(
                            self.err(format!("{el}/<mimic joint=\"{of}\">"), "names a joint that is not defined")
                        );
                    }
                    let mult = m.attribute("multiplier").and_then(|v| v.parse().ok()).unwrap_or(1.0);
                    let off = m.attribute("offset").and_then(|v| v.parse().ok()).unwrap_or(0.0);
                    equalities.push(
                        Element::new("joint")
                            .with("joint1", j.name.as_str())
                            .with("joint2", of)
                            .with("polycoef", nums(&[off, mult, 0.0, 0.0, 0.0])),
                    );
                } else {
                    let effort = lim("effort").filter(|e| *e > 0.0);
                    let kp = effort.map_or(100.0, |e| e * KP_PER_EFFORT);
                    let mut a = Element::new("position")
                        .with("name", j.name.as_str())
                        .with("joint", j.name.as_str())
                        .with("kp", num(kp))
                        .with("kv", num(kp * KV_PER_KP));
                    if let Some((lo, hi)) = range {
                        a.set("ctrlrange", nums(&[lo, hi]));
                    }
                    if let Some(e) = effort {
                        a.set("forcerange", nums(&[-e, e]));
                    }
                    actuators.push(a);
                }
            }
            other => {
                return Err(self.err(
                    el,
                    format!("joint type '{other}' is not supported (revolute, continuous, prismatic, fixed, floating)"),
                ));
            }
        }
        let link = links[j.child.as_str()];
        self.fill_link(&mut b, link)?;
        for c in joints.iter().filter(|c| c.parent == j.child) {
            let child = self.body_for_joint(c, links, joints, actuators, equalities, visited, false)?;
            b.children.push(child);
        }
        Ok(b)
    }

    fn fill_link(&mut self, b: &mut Element, link: roxmltree::Node<'_, '_>) -> Result<(), UrdfError> {
        let name = link.attribute("name").unwrap_or_default().to_string();
        let el = format!("<link name=\"{name}\">");
        let mut has_inertial = false;
        let (mut nv, mut nc) = (0, 0);
        for c in link.children().filter(roxmltree::Node::is_element) {
            match c.tag_name().name() {
                "inertial" => {
                    has_inertial = true;
                    let (pos, quat) = origin(c.children().find(|x| x.has_tag_name("origin")), self.file, &el)?;
                    let mass = c
                        .children()
                        .find(|x| x.has_tag_name("mass"))
                        .and_then(|m| m.attribute("value"))
                        .and_then(|v| v.trim().parse::<f64>().ok())
                        .ok_or_else(|| self.err(format!("{el}/<inertial>"), "has no <mass value=...>"))?;
                    let i = c.children().find(|x| x.has_tag_name("inertia"));
                    let g = |k: &str| {
                        i.and_then(|i| i.attribute(k)).and_then(|v| v.trim().parse::<f64>().ok()).unwrap_or(0.0)
                    };
                    let mut inertial =
                        Element::new("inertial").with("pos", nums(&pos)).with("mass", num(mass.max(1e-6)));
                    if (quat[0] - 1.0).abs() > 1e-12 {
                        inertial.set("quat", nums(&quat));
                    }
                    let diag = [g("ixx"), g("iyy"), g("izz")].map(|v| v.max(1e-9));
                    let off = [g("ixy"), g("ixz"), g("iyz")];
                    if off.iter().all(|v| v.abs() < 1e-12) {
                        inertial.set("diaginertia", nums(&diag));
                    } else {
                        inertial.set("fullinertia", nums(&[diag[0], diag[1], diag[2], off[0], off[1], off[2]]));
                    }
                    b.children.insert(0, inertial);
                }
                tag @ ("visual" | "collision") => {
                    let visual = tag == "visual";
                    let k = if visual { &mut nv } else { &mut nc };
                    let geom_el = format!("{el}/<{tag}> #{}", *k + 1);
                    *k += 1;
                    let geom = self.geom(c, visual, &geom_el)?;
                    b.children.push(geom);
                }
                other => {
                    return Err(self.err(format!("{el}/<{other}>"), "is not a URDF link element scenewright knows"));
                }
            }
        }
        if !has_inertial && nc > 0 {
            self.notes.push(format!(
                "{}: link '{name}' has no <inertial>; its mass comes from its collision geometry",
                self.file
            ));
        }
        Ok(())
    }

    fn geom(&mut self, node: roxmltree::Node<'_, '_>, visual: bool, el: &str) -> Result<Element, UrdfError> {
        let (pos, quat) = origin(node.children().find(|x| x.has_tag_name("origin")), self.file, el)?;
        let mut g = Element::new("geom").with("class", if visual { "visual" } else { "collision" });
        let shape = node
            .children()
            .find(|x| x.has_tag_name("geometry"))
            .and_then(|g| g.children().find(roxmltree::Node::is_element))
            .ok_or_else(|| self.err(el.to_string(), "has no <geometry>"))?;
        let f = |k: &str| shape.attribute(k).and_then(|v| v.trim().parse::<f64>().ok());
        let shape_el = format!("{el}/<{}>", shape.tag_name().name());
        match shape.tag_name().name() {
            "box" => {
                let s = vec3(shape.attribute("size"), self.file, &shape_el)?;
                g.set("type", "box");
                g.set("size", nums(&s.map(|v| v / 2.0)));
            }
            "cylinder" => {
                let (Some(r), Some(l)) = (f("radius"), f("length")) else {
                    return Err(self.err(shape_el, "needs radius and length"));
                };
                g.set("type", "cylinder");
                g.set("size", nums(&[r, l / 2.0]));
            }
            "sphere" => {
                let Some(r) = f("radius") else {
                    return Err(self.err(shape_el, "needs a radius"));
                };
                g.set("type", "sphere");
                g.set("size", num(r));
            }
            "mesh" => {
                let Some(filename) = shape.attribute("filename") else {
                    return Err(self.err(shape_el, "has no filename"));
                };
                let el_full = format!("{el}/<mesh filename=\"{filename}\">");
                let path = (self.resolve)(filename).map_err(|why| self.err(el_full.clone(), why))?;
                let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
                if !["stl", "obj", "msh"].contains(&ext.as_str()) {
                    return Err(self.err(el_full, format!("MuJoCo reads STL, OBJ and MSH meshes, not '.{ext}'")));
                }
                let scale = shape.attribute("scale").unwrap_or("1 1 1").to_string();
                let key = (path.clone(), scale.clone());
                let name = match self.meshes.get(&key) {
                    Some(n) => n.clone(),
                    None => {
                        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("mesh");
                        let mut name = format!("mesh_{stem}");
                        let mut k = 1;
                        while self.meshes.values().any(|n| n == &name) {
                            k += 1;
                            name = format!("mesh_{stem}_{k}");
                        }
                        let mut m = Element::new("mesh").with("name", name.clone()).with("file", path_str(&path));
                        if scale != "1 1 1" {
                            m.set("scale", scale);
                        }
                        self.mesh_elems.push(m);
                        self.meshes.insert(key, name.clone());
                        name
                    }
                };
                g.set("type", "mesh");
                g.set("mesh", name);
            }
            other => return Err(self.err(format!("{el}/<{other}>"), "is not a URDF geometry")),
        }
        g.set("pos", nums(&pos));
        if (quat[0] - 1.0).abs() > 1e-12 {
            g.set("quat", nums(&quat));
        }
        if visual && let Some(m) = node.children().find(|x| x.has_tag_name("material")) {
            if let Some(rgba) = color(m) {
                g.set("rgba", nums(&rgba));
            } else if let Some(n) = m.attribute("name")
                && self.materials.contains_key(n)
            {
                g.set("material", format!("urdf_{n}"));
            }
        }
        Ok(g)
    }
}

fn path_str(p: &Path) -> String {
    p.to_string_lossy().into_owned()
}

fn color(n: roxmltree::Node<'_, '_>) -> Option<[f64; 4]> {
    let c = n.children().find(|c| c.has_tag_name("color"))?.attribute("rgba")?;
    let v: Vec<f64> = c.split_whitespace().filter_map(|x| x.parse().ok()).collect();
    (v.len() == 4).then(|| [v[0], v[1], v[2], v[3]])
}

fn vec3(v: Option<&str>, file: &str, el: &str) -> Result<[f64; 3], UrdfError> {
    let l: Vec<f64> = v.unwrap_or("").split_whitespace().filter_map(|x| x.parse().ok()).collect();
    match l.as_slice() {
        [a, b, c] => Ok([*a, *b, *c]),
        _ => Err(UrdfError::Element {
            file: file.into(),
            element: el.into(),
            why: format!("expected three numbers, got {v:?}"),
        }),
    }
}

/// `<origin xyz rpy>`: URDF's roll-pitch-yaw turns about the fixed X, Y, Z axes.
fn origin(n: Option<roxmltree::Node<'_, '_>>, file: &str, el: &str) -> Result<([f64; 3], [f64; 4]), UrdfError> {
    let Some(n) = n else {
        return Ok(([0.0; 3], [1.0, 0.0, 0.0, 0.0]));
    };
    let pos = match n.attribute("xyz") {
        Some(v) => vec3(Some(v), file, &format!("{el}/<origin xyz>"))?,
        None => [0.0; 3],
    };
    let rpy = match n.attribute("rpy") {
        Some(v) => vec3(Some(v), file, &format!("{el}/<origin rpy>"))?,
        None => [0.0; 3],
    };
    Ok((pos, euler_to_quat(rpy, "XYZ")))
}
