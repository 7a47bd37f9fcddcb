//! Brings one robot document to the scene's conventions before it is prefixed: includes
//! flattened, the part's fixes applied, angles in radians (euler and axis-angle turned
//! into quaternions, hinge and ball joint range/ref/springref converted), limits explicit
//! where the file turned `autolimits` off, and geoms outside `inertiagrouprange` weightless.
//!
//! The scene is written with `angle="radian"`, `autolimits="true"`, the default
//! `eulerseq` and every geom group counted for inertia; a robot written otherwise keeps its
//! meaning only if its values are rewritten into those conventions.

use std::collections::BTreeMap;

use crate::robot::{MergeError, PartFixes};
use crate::xml::{Element, nums};

/// Compiler settings of a robot document that the merge has to honour.
#[derive(Debug, Clone, Default)]
pub(crate) struct Compiler {
    pub attrs: BTreeMap<String, String>,
}

impl Compiler {
    pub fn get(&self, key: &str) -> Option<&str> {
        self.attrs.get(key).map(String::as_str)
    }

    fn degrees(&self) -> bool {
        // MJCF's default unit is degrees.
        self.get("angle").is_none_or(|a| a != "radian")
    }

    fn eulerseq(&self) -> &str {
        self.get("eulerseq").unwrap_or("xyz")
    }
}

/// Compiler attributes with no effect on a merged robot, or none we can reproduce: they
/// are reported, not silently dropped.
const IGNORED_COMPILER: &[&str] = &[
    "fusestatic",
    "discardvisual",
    "usethread",
    "convexhull",
    "exactmeshinertia",
    "fitaabb",
    "alignfree",
    "saveinertial",
    "balanceinertia",
    "boundmass",
    "boundinertia",
    "settotalmass",
    "inertiafromgeom",
];

/// Handled compiler attributes.
const HANDLED_COMPILER: &[&str] =
    &["angle", "eulerseq", "autolimits", "inertiagrouprange", "meshdir", "texturedir", "assetdir", "strippath"];

/// Flattens includes, applies the fixes and rewrites angles and limits. Returns the
/// compiler settings the later steps need (file directories).
pub(crate) fn normalize(
    doc: &mut Element,
    label: &str,
    includes: &BTreeMap<String, String>,
    fixes: &PartFixes,
    notes: &mut Vec<String>,
) -> Result<Compiler, MergeError> {
    flatten_includes(doc, label, includes, 0)?;

    let mut compiler = Compiler::default();
    for (k, v) in &fixes.assume_compiler {
        compiler.attrs.insert(k.clone(), v.clone());
    }
    for c in doc.children.iter().filter(|c| c.name == "compiler") {
        for (k, v) in &c.attrs {
            compiler.attrs.insert(k.clone(), v.clone());
        }
    }
    if compiler.get("coordinate").is_some_and(|c| c == "global") {
        return Err(MergeError::Unsupported {
            source_name: label.into(),
            element: "compiler coordinate=\"global\"".into(),
            why: "global coordinates were removed from MuJoCo; convert the model to local coordinates".into(),
        });
    }
    for (k, v) in &compiler.attrs {
        if IGNORED_COMPILER.contains(&k.as_str()) {
            notes.push(format!("{label}: <compiler {k}=\"{v}\"> has no effect in the merged scene"));
        } else if !HANDLED_COMPILER.contains(&k.as_str()) && k != "coordinate" && k != "lengthrange" {
            notes.push(format!("{label}: <compiler {k}> was ignored"));
        }
    }
    for section in ["option", "size", "visual", "statistic"] {
        if doc.children.iter().any(|c| c.name == section) {
            notes.push(format!("{label}: the robot's <{section}> was not merged; the scene keeps its own"));
        }
    }
    for child in &doc.children {
        if matches!(child.name.as_str(), "extension" | "deformable" | "custom") {
            return Err(MergeError::Unsupported {
                source_name: label.into(),
                element: child.name.clone(),
                why: "plugins, deformables and custom data cannot be merged into a scene".into(),
            });
        }
    }

    apply_fixes(doc, fixes, notes, label);
    merge_top_defaults(doc);
    let defaults = Defaults::index(doc);

    let degrees = compiler.degrees();
    let eulerseq = compiler.eulerseq().to_string();
    if eulerseq.len() != 3 || !eulerseq.chars().all(|c| "xyzXYZ".contains(c)) {
        return Err(MergeError::BadValue {
            source_name: label.into(),
            element: format!("compiler eulerseq=\"{eulerseq}\""),
            why: "expected three of x, y, z, X, Y, Z".into(),
        });
    }
    let scale = if degrees { std::f64::consts::PI / 180.0 } else { 1.0 };
    if degrees || eulerseq != "xyz" {
        convert_orientations(doc, scale, &eulerseq, label)?;
    }
    let autolimits = compiler.get("autolimits").is_none_or(|v| v != "false");
    let groups = match compiler.get("inertiagrouprange") {
        Some(v) => {
            let g = crate::merge::parse_list(Some(v));
            if g.len() != 2 {
                return Err(MergeError::BadValue {
                    source_name: label.into(),
                    element: format!("compiler inertiagrouprange=\"{v}\""),
                    why: "expected two integers".into(),
                });
            }
            Some((g[0], g[1]))
        }
        None => None,
    };
    if let Some(wb) = doc.first_mut("worldbody") {
        let mut ctx = WalkCtx { defaults: &defaults, scale, degrees, autolimits, groups, regroup: fixes.regroup };
        ctx.body_tree(wb, "main");
    }
    if !autolimits {
        for section in ["tendon", "actuator"] {
            let items: Vec<&mut Element> = doc.children.iter_mut().filter(|c| c.name == section).collect();
            for s in items {
                for item in &mut s.children {
                    let class = item.get("class").unwrap_or("main").to_string();
                    explicit_limits(item, &defaults, &class);
                }
            }
        }
    }
    if degrees {
        // The defaults' own orientations were converted above; joint values in defaults stay
        // as written because slide joints use them unconverted (hinge joints now carry
        // explicit converted values).
        notes.push(format!("{label}: angles converted from degrees to radians"));
    }
    doc.children.retain(|c| c.name != "compiler");
    Ok(compiler)
}

fn flatten_includes(
    e: &mut Element,
    label: &str,
    includes: &BTreeMap<String, String>,
    depth: usize,
) -> Result<(), MergeError> {
    if !e.children.iter().any(|c| c.name == "include") && e.children.is_empty() {
        return Ok(());
    }
    let mut out = Vec::with_capacity(e.children.len());
    for mut c in std::mem::take(&mut e.children) {
        if c.name == "include" {
            let file = c.get("file").unwrap_or_default().to_string();
            if depth > 8 {
                return Err(MergeError::Unsupported {
                    source_name: label.into(),
                    element: format!("include file=\"{file}\""),
                    why: "includes nested more than 8 deep (a cycle?)".into(),
                });
            }
            let text = includes
                .get(&file)
                .ok_or_else(|| MergeError::MissingInclude { source_name: label.into(), file: file.clone() })?;
            let inc_label = format!("{label} → {file}");
            let mut root = Element::parse(text).map_err(|err| MergeError::Xml(err, inc_label.clone()))?;
            if root.name != "mujoco" {
                return Err(MergeError::NotMjcf { source_name: inc_label, found: root.name });
            }
            flatten_includes(&mut root, label, includes, depth + 1)?;
            out.extend(root.children);
        } else {
            flatten_includes(&mut c, label, includes, depth)?;
            out.push(c);
        }
    }
    e.children = out;
    Ok(())
}

fn apply_fixes(doc: &mut Element, fixes: &PartFixes, notes: &mut Vec<String>, label: &str) {
    if !fixes.drop_attrs.is_empty() {
        let mut dropped = 0;
        doc.walk_mut(&mut |e| {
            for (tag, attr) in &fixes.drop_attrs {
                if &e.name == tag && e.remove(attr).is_some() {
                    dropped += 1;
                }
            }
        });
        if dropped > 0 {
            notes.push(format!("{label}: removed {dropped} attribute(s) MuJoCo's schema rejects"));
        }
    }
    if fixes.keep_first_duplicate_asset {
        let mut seen: std::collections::BTreeSet<(String, String)> = Default::default();
        for a in doc.children.iter_mut().filter(|c| c.name == "asset") {
            a.children.retain(|item| match item.get("name") {
                Some(n) => {
                    let fresh = seen.insert((item.name.clone(), n.to_string()));
                    if !fresh {
                        notes.push(format!(
                            "{label}: second <{} name=\"{n}\"> dropped; the first is used, as robosuite does",
                            item.name
                        ));
                    }
                    fresh
                }
                None => true,
            });
        }
    }
}

/// Several top-level `<default>` elements (from includes) become one.
fn merge_top_defaults(doc: &mut Element) {
    let n = doc.children.iter().filter(|c| c.name == "default").count();
    if n < 2 {
        return;
    }
    let mut merged = Element::new("default");
    let mut first_at = None;
    let mut kept = Vec::new();
    for (i, c) in std::mem::take(&mut doc.children).into_iter().enumerate() {
        if c.name == "default" {
            first_at.get_or_insert(i);
            for (k, v) in c.attrs {
                merged.set(&k, v);
            }
            merged.children.extend(c.children);
        } else {
            kept.push(c);
        }
    }
    let at = first_at.unwrap_or(0).min(kept.len());
    kept.insert(at, merged);
    doc.children = kept;
}

/// Default classes: per class, its parent and its element defaults.
#[derive(Debug, Default)]
pub(crate) struct Defaults {
    classes: BTreeMap<String, (Option<String>, Vec<Element>)>,
}

impl Defaults {
    pub fn index(doc: &Element) -> Self {
        let mut d = Defaults::default();
        if let Some(root) = doc.first("default") {
            d.add(root, "main", None);
        }
        d
    }

    fn add(&mut self, e: &Element, class: &str, parent: Option<&str>) {
        let own: Vec<Element> = e
            .children
            .iter()
            .filter(|c| c.name != "default")
            .map(|c| Element { children: Vec::new(), ..c.clone() })
            .collect();
        self.classes.insert(class.to_string(), (parent.map(str::to_string), own));
        for c in e.children.iter().filter(|c| c.name == "default") {
            let name = c.get("class").unwrap_or_default().to_string();
            self.add(c, &name, Some(class));
        }
    }

    /// The value of `attr` for a `<tag>` of class `class`: from the class or its ancestors.
    pub fn lookup(&self, class: &str, tag: &str, attr: &str) -> Option<&str> {
        let mut at = Some(class);
        let mut guard = 0;
        while let Some(c) = at {
            let (parent, own) = self.classes.get(c)?;
            if let Some(v) = own.iter().rev().filter(|e| e.name == tag).find_map(|e| e.get(attr)) {
                return Some(v);
            }
            at = parent.as_deref();
            guard += 1;
            if guard > 64 {
                return None;
            }
        }
        None
    }
}

struct WalkCtx<'a> {
    defaults: &'a Defaults,
    scale: f64,
    degrees: bool,
    autolimits: bool,
    groups: Option<(f64, f64)>,
    regroup: bool,
}

impl WalkCtx<'_> {
    fn body_tree(&mut self, e: &mut Element, childclass: &str) {
        for c in &mut e.children {
            let class = c.get("class").map_or_else(|| childclass.to_string(), str::to_string);
            match c.name.as_str() {
                "joint" => self.joint(c, &class),
                "geom" => {
                    let look = |attr: &str| {
                        c.get(attr).or_else(|| self.defaults.lookup(&class, "geom", attr)).map(str::to_string)
                    };
                    let group: f64 = look("group").and_then(|g| g.trim().parse().ok()).unwrap_or(0.0);
                    let off = |attr: &str| look(attr).is_some_and(|v| v.trim() == "0");
                    let visual = off("contype") && off("conaffinity");
                    if let Some((lo, hi)) = self.groups
                        && (group < lo || group > hi)
                    {
                        c.set("mass", "0");
                    }
                    if self.regroup {
                        c.set("group", if visual { "2" } else { "3" });
                    }
                }
                "body" | "frame" => {
                    let inner = c.get("childclass").map_or_else(|| childclass.to_string(), str::to_string);
                    self.body_tree(c, &inner);
                }
                _ => {}
            }
        }
    }

    fn joint(&self, j: &mut Element, class: &str) {
        let kind = j.get("type").or_else(|| self.defaults.lookup(class, "joint", "type")).unwrap_or("hinge");
        if self.degrees && matches!(kind, "hinge" | "ball") {
            for attr in ["range", "ref", "springref"] {
                let v = j.get(attr).or_else(|| self.defaults.lookup(class, "joint", attr)).map(str::to_string);
                if let Some(v) = v {
                    let vals = crate::merge::parse_list(Some(&v));
                    j.set(attr, nums(&vals.iter().map(|x| x * self.scale).collect::<Vec<_>>()));
                }
            }
        }
        if !self.autolimits {
            explicit_limits(j, self.defaults, class);
        }
    }
}

/// With `autolimits="false"` a range without `limited` is no limit; the scene turns
/// `autolimits` on, so the file's meaning is written out explicitly.
fn explicit_limits(e: &mut Element, defaults: &Defaults, class: &str) {
    let tag = match e.name.as_str() {
        "joint" => "joint",
        "fixed" | "spatial" => "tendon",
        _ => "general",
    };
    for (range, limited) in [
        ("range", "limited"),
        ("ctrlrange", "ctrllimited"),
        ("forcerange", "forcelimited"),
        ("actrange", "actlimited"),
        ("actuatorfrcrange", "actuatorfrclimited"),
    ] {
        let has_range = e.get(range).is_some() || defaults.lookup(class, tag, range).is_some();
        let has_flag = e.get(limited).is_some() || defaults.lookup(class, tag, limited).is_some();
        if has_range && !has_flag {
            e.set(limited, "false");
        }
    }
}

/// Euler angles and axis-angles (in the whole document, defaults included) become
/// quaternions; their angles are in the file's unit and its Euler sequence.
fn convert_orientations(doc: &mut Element, scale: f64, seq: &str, label: &str) -> Result<(), MergeError> {
    let mut bad: Option<MergeError> = None;
    doc.walk_mut(&mut |e| {
        if bad.is_some() {
            return;
        }
        if let Some(v) = e.get("euler").map(str::to_string) {
            let a = crate::merge::parse_list(Some(&v));
            if a.len() != 3 {
                bad = Some(MergeError::BadValue {
                    source_name: label.into(),
                    element: format!("{} euler=\"{v}\"", e.name),
                    why: "expected three angles".into(),
                });
                return;
            }
            e.remove("euler");
            e.set("quat", nums(&euler_to_quat([a[0] * scale, a[1] * scale, a[2] * scale], seq)));
        }
        if let Some(v) = e.get("axisangle").map(str::to_string) {
            let a = crate::merge::parse_list(Some(&v));
            let n = if a.len() == 4 { (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt() } else { 0.0 };
            if n <= 0.0 {
                bad = Some(MergeError::BadValue {
                    source_name: label.into(),
                    element: format!("{} axisangle=\"{v}\"", e.name),
                    why: "expected a non-zero axis and an angle".into(),
                });
                return;
            }
            let (s, c) = (a[3] * scale * 0.5).sin_cos();
            e.remove("axisangle");
            e.set("quat", nums(&[c, a[0] / n * s, a[1] / n * s, a[2] / n * s]));
        }
    });
    match bad {
        Some(err) => Err(err),
        None => Ok(()),
    }
}

/// MuJoCo's Euler convention: for each axis of `seq` in turn, a lower-case letter rotates
/// about the moving (intrinsic) axis, an upper-case one about the fixed (extrinsic) axis.
pub(crate) fn euler_to_quat(angles: [f64; 3], seq: &str) -> [f64; 4] {
    let mut q = [1.0, 0.0, 0.0, 0.0];
    for (ch, a) in seq.chars().zip(angles) {
        let (s, c) = (a * 0.5).sin_cos();
        let r = match ch.to_ascii_lowercase() {
            'x' => [c, s, 0.0, 0.0],
            'y' => [c, 0.0, s, 0.0],
            _ => [c, 0.0, 0.0, s],
        };
        q = if ch.is_ascii_lowercase() { sw_geom::quat_mul(q, r) } else { sw_geom::quat_mul(r, q) };
    }
    q
}

/// Short description of an element for messages: `<mesh name="x" file="y">`.
pub(crate) fn describe(e: &Element) -> String {
    let mut s = format!("<{}", e.name);
    for key in ["name", "file", "class", "joint", "mesh", "type"] {
        if let Some(v) = e.get(key) {
            s.push_str(&format!(" {key}=\"{v}\""));
        }
    }
    s.push('>');
    s
}
