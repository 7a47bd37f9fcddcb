//! The robot merger: takes a robot's MJCF parts and prepares them for insertion into a
//! scene under a prefix. Every name a robot brings is prefixed (bodies, joints, geoms,
//! sites, cameras, lights, actuators, sensors, tendons, equalities, meshes, textures,
//! materials and default classes) and every reference to those names follows. Parts are
//! assembled (a gripper into the arm's hand, an arm onto a base), the robot's files are
//! given package paths, and its home state is collected for the scene's keyframe.

use std::collections::{BTreeMap, BTreeSet};

use sw_geom::Pose;

use crate::normalize::{Defaults, describe, euler_to_quat, normalize};
use crate::robot::{MergeError, PreparedRobot, RobotPart, RobotSource, ServoGains};
use crate::xml::{Element, num, nums};

/// Attributes whose value names another element.
const REFERENCE_ATTRS: &[&str] = &[
    "class",
    "childclass",
    "material",
    "mesh",
    "texture",
    "hfield",
    "skin",
    "joint",
    "joint1",
    "joint2",
    "jointinparent",
    "body",
    "body1",
    "body2",
    "geom",
    "geom1",
    "geom2",
    "site",
    "site1",
    "site2",
    "refsite",
    "tendon",
    "tendon1",
    "tendon2",
    "actuator",
    "objname",
    "refname",
    "targetbody",
    "slidersite",
    "cranksite",
    "flex",
    "flex1",
    "flex2",
    "camera",
    "light",
    "target",
];

/// Sections copied from the robot into the scene, in MJCF order.
pub(crate) const MERGED_SECTIONS: &[&str] = &["contact", "equality", "tendon", "actuator", "sensor"];

/// Elements at the robot's world level that belong to its demo scene, not to the robot.
const WORLD_EXTRAS: &[&str] = &["light", "geom", "site", "camera"];

/// One part, prefixed, before assembly.
struct PartOut {
    bodies: Vec<Element>,
    assets: Vec<Element>,
    default: Element,
    sections: BTreeMap<String, Vec<Element>>,
    home_qpos: BTreeMap<String, Vec<f64>>,
    /// Per actuator (in order): the key's control, if the part's key gave one.
    key_ctrl: Vec<Option<f64>>,
    /// Per actuator: its final name and, for position-like actuators on a joint, that
    /// joint's final name and the actuator's control range.
    actuators: Vec<ActuatorInfo>,
    /// Every final name defined by the part (bodies, joints, ...).
    names: BTreeSet<String>,
}

#[derive(Debug, Clone)]
struct ActuatorInfo {
    name: Option<String>,
    position_joint: Option<String>,
    ctrlrange: Option<(f64, f64)>,
}

/// Prefixes, assembles and poses a robot. Every error names the part's file and the element.
pub fn prepare_robot(source: &RobotSource, prefix: &str, mount: &Pose) -> Result<PreparedRobot, MergeError> {
    if source.parts.is_empty() {
        return Err(MergeError::Assembly { model: source.model.clone(), why: "has no MJCF parts".into() });
    }
    let multi = source.parts.len() > 1;
    let mut notes = source.notes.clone();
    let mut files = BTreeSet::new();
    let mut roots: Vec<Element> = Vec::new();
    let mut out = PreparedRobot {
        prefix: prefix.to_string(),
        bodies: Vec::new(),
        assets: Vec::new(),
        defaults: Vec::new(),
        sections: BTreeMap::new(),
        home_qpos: BTreeMap::new(),
        home_ctrl: Vec::new(),
        files: Vec::new(),
        notes: Vec::new(),
    };
    let mut names: BTreeSet<String> = BTreeSet::new();
    let mut key_ctrl = Vec::new();
    let mut actuators = Vec::new();
    let mut part_prefixes = BTreeSet::new();
    for part in &source.parts {
        if !part_prefixes.insert(part.prefix.clone()) {
            return Err(MergeError::Assembly {
                model: source.model.clone(),
                why: format!("two parts share the name prefix '{}'", part.prefix),
            });
        }
        let full = format!("{prefix}_{}", part.prefix);
        let file_dir = if multi {
            let key = part.prefix.trim_end_matches('_');
            format!("robots/{}/{}/", source.model, if key.is_empty() { "main" } else { key })
        } else {
            format!("robots/{}/", source.model)
        };
        let p = prepare_part(part, &full, &file_dir, &mut files, &mut notes)?;
        if let Some(clash) = p.names.iter().find(|n| names.contains(*n)) {
            return Err(MergeError::Assembly {
                model: source.model.clone(),
                why: format!("part {} defines '{clash}', which an earlier part defines too", part.label),
            });
        }
        names.extend(p.names.iter().cloned());
        // Place the part's top-level bodies.
        let mut bodies = p.bodies;
        for b in &mut bodies {
            let own = body_pose(b, &part.label)?;
            let pose = part.attach_pose.compose(&own);
            let pose = if part.attach_to.is_none() { mount.compose(&pose) } else { pose };
            set_pose(b, &pose);
        }
        match &part.attach_to {
            None => roots.extend(bodies),
            Some(carrier) => {
                let target = format!("{prefix}_{carrier}");
                let mut bodies = Some(bodies);
                for r in &mut roots {
                    attach(r, &target, &mut bodies);
                }
                if bodies.is_some() {
                    return Err(MergeError::Assembly {
                        model: source.model.clone(),
                        why: format!("part {} is attached to body '{carrier}', which no earlier part has", part.label),
                    });
                }
            }
        }
        out.assets.extend(p.assets);
        out.defaults.push(p.default);
        for (k, v) in p.sections {
            out.sections.entry(k).or_default().extend(v);
        }
        out.home_qpos.extend(p.home_qpos);
        key_ctrl.extend(p.key_ctrl);
        actuators.extend(p.actuators);
    }

    // Extra contact excludes asked for by the registry.
    for (a, b) in &source.excludes {
        let (a, b) = (format!("{prefix}_{a}"), format!("{prefix}_{b}"));
        for n in [&a, &b] {
            if !names.contains(n) {
                return Err(MergeError::Assembly {
                    model: source.model.clone(),
                    why: format!("a contact exclude names body '{n}', which the robot does not have"),
                });
            }
        }
        out.sections
            .entry("contact".into())
            .or_default()
            .push(Element::new("exclude").with("body1", a).with("body2", b));
    }
    // Home overrides from the registry.
    for (joint, q) in &source.home {
        let n = format!("{prefix}_{joint}");
        if !names.contains(&n) {
            return Err(MergeError::Assembly {
                model: source.model.clone(),
                why: format!("the home pose names joint '{joint}', which the robot does not have"),
            });
        }
        out.home_qpos.insert(n, q.clone());
    }
    let overrides: BTreeMap<String, f64> =
        source.home_ctrl.iter().map(|(n, v)| (format!("{prefix}_{n}"), *v)).collect();
    for n in overrides.keys() {
        if !actuators.iter().any(|a| a.name.as_deref() == Some(n.as_str())) {
            return Err(MergeError::Assembly {
                model: source.model.clone(),
                why: format!("the home controls name actuator '{n}', which the robot does not have"),
            });
        }
    }
    out.home_ctrl = actuators
        .iter()
        .zip(&key_ctrl)
        .map(|(a, key)| {
            if let Some(v) = a.name.as_ref().and_then(|n| overrides.get(n)) {
                return *v;
            }
            if let Some(v) = key {
                return *v;
            }
            // A position servo holds its joint's home position; anything else rests at 0.
            let q = a.position_joint.as_ref().and_then(|j| out.home_qpos.get(j)).and_then(|q| q.first().copied());
            match (q, a.ctrlrange) {
                (Some(q), Some((lo, hi))) if lo < hi => q.clamp(lo, hi),
                (Some(q), _) => q,
                (None, _) => 0.0,
            }
        })
        .collect();
    out.bodies = roots;
    out.files = files.into_iter().collect();
    for w in out.files.windows(2) {
        if w[0].dest == w[1].dest && w[0].source != w[1].source {
            return Err(MergeError::Assembly {
                model: source.model.clone(),
                why: format!(
                    "{} and {} would both be copied to assets/{}",
                    w[0].source.display(),
                    w[1].source.display(),
                    w[0].dest
                ),
            });
        }
    }
    out.files.dedup_by(|a, b| a.dest == b.dest);
    out.notes = notes;
    Ok(out)
}

fn attach(body: &mut Element, target: &str, parts: &mut Option<Vec<Element>>) {
    if parts.is_none() {
        return;
    }
    if body.name == "body" && body.get("name") == Some(target) {
        if let Some(p) = parts.take() {
            body.children.extend(p);
        }
        return;
    }
    for c in &mut body.children {
        attach(c, target, parts);
    }
}

fn prepare_part(
    part: &RobotPart,
    full: &str,
    file_dir: &str,
    files: &mut BTreeSet<crate::robot::RobotFile>,
    notes: &mut Vec<String>,
) -> Result<PartOut, MergeError> {
    let src = part.label.clone();
    let mut doc = Element::parse(&part.mjcf).map_err(|e| MergeError::Xml(e, src.clone()))?;
    if doc.name != "mujoco" {
        return Err(MergeError::NotMjcf { source_name: src, found: doc.name });
    }
    let compiler = normalize(&mut doc, &src, &part.includes, &part.fixes, notes)?;

    // Names defined by the part, and the implicit names of file assets.
    let mut names: BTreeSet<String> = BTreeSet::new();
    let mut classes: BTreeSet<String> = BTreeSet::from(["main".to_string()]);
    collect_names(&mut doc, &src, &mut names, &mut classes)?;
    let main_class = format!("{full}main");

    // Name unnamed joints so the keyframe can address them.
    let mut k = 0;
    if let Some(wb) = doc.first_mut("worldbody") {
        wb.walk_mut(&mut |e| {
            if (e.name == "joint" || e.name == "freejoint") && e.get("name").is_none() {
                while names.contains(&format!("unnamed_joint{k}")) {
                    k += 1;
                }
                let n = format!("unnamed_joint{k}");
                names.insert(n.clone());
                e.set("name", n);
            }
        });
    }

    let defaults = Defaults::index(&doc);
    let joints = joint_table(&doc, &defaults);
    check_references(&doc, &src, &names, &classes)?;

    // Keyframe values before renaming (they are positional).
    let (mut home_raw, key_ctrl_raw) = home_key(&doc, &joints);
    // Joints the key does not cover rest at their reference position.
    for j in &joints {
        if !home_raw.contains_key(&j.name) {
            match j.width {
                1 => {
                    home_raw.insert(j.name.clone(), vec![j.reference]);
                }
                4 => {
                    home_raw.insert(j.name.clone(), vec![1.0, 0.0, 0.0, 0.0]);
                }
                _ => {}
            }
        }
    }
    if let Some(gains) = &part.fixes.servos {
        motors_to_servos(&mut doc, &defaults, &joints, gains, &src, notes);
    }
    if part.fixes.gravcomp
        && let Some(wb) = doc.first_mut("worldbody")
    {
        for b in wb.children.iter_mut() {
            b.walk_mut(&mut |e| {
                if e.name == "body" && e.get("gravcomp").is_none() {
                    e.set("gravcomp", "1");
                }
            });
        }
    }
    let actuators_raw = actuator_table(&doc, &defaults);

    // Rename everything.
    let rename = |e: &mut Element| {
        if let Some(n) = e.get("name").map(str::to_string) {
            e.set("name", format!("{full}{n}"));
        }
        for key in REFERENCE_ATTRS {
            let Some(v) = e.get(key).map(str::to_string) else {
                continue;
            };
            let is_class = *key == "class" || *key == "childclass";
            if is_class {
                e.set(key, if v == "main" { main_class.clone() } else { format!("{full}{v}") });
            } else if names.contains(&v) {
                e.set(key, format!("{full}{v}"));
            }
        }
    };
    doc.walk_mut(&mut |e| {
        if e.name == "default" {
            if let Some(c) = e.get("class").map(str::to_string) {
                e.set("class", if c == "main" { main_class.clone() } else { format!("{full}{c}") });
            }
        } else if e.name != "mujoco" && e.name != "key" {
            rename(e);
        }
    });

    // Defaults: the part's root default becomes a named class (an empty one when the
    // part has none, so that an outer part's childclass does not leak into it).
    let mut default = doc.first("default").cloned().unwrap_or_else(|| Element::new("default"));
    default.set("class", main_class.clone());

    // Assets, with package paths for their files.
    let mut assets = Vec::new();
    for a in doc.children.iter().filter(|c| c.name == "asset") {
        for mut item in a.children.clone() {
            if matches!(item.name.as_str(), "mesh" | "material") && item.get("class").is_none() {
                item.set("class", main_class.clone());
            }
            if item.name == "model" {
                return Err(MergeError::Unsupported {
                    source_name: src,
                    element: "asset model".into(),
                    why: "flatten <attach>ed models first".into(),
                });
            }
            crate::files::relocate(&mut item, full, part, &compiler, file_dir, files)?;
            assets.push(item);
        }
    }

    // Bodies.
    let mut bodies = Vec::new();
    for wb in doc.children.iter().filter(|c| c.name == "worldbody") {
        for b in &wb.children {
            match b.name.as_str() {
                "body" => {
                    let mut body = b.clone();
                    if body.get("childclass").is_none() {
                        body.set("childclass", main_class.clone());
                    }
                    bodies.push(body);
                }
                extra if WORLD_EXTRAS.contains(&extra) => {
                    notes.push(format!("{src}: {} at the robot's world level was not merged", describe(b)));
                }
                other => {
                    return Err(MergeError::Unsupported {
                        source_name: src,
                        element: format!("worldbody/{other}"),
                        why:
                            "a robot's worldbody may hold bodies (and lights, geoms, sites, cameras, which are dropped)"
                                .into(),
                    });
                }
            }
        }
    }
    if bodies.is_empty() {
        return Err(MergeError::NoBody { source_name: src });
    }

    // Sections.
    let mut sections = BTreeMap::new();
    for name in MERGED_SECTIONS {
        let mut items = Vec::new();
        for s in doc.children.iter().filter(|c| c.name == *name) {
            for mut item in s.children.clone() {
                let takes_class = match *name {
                    "actuator" | "tendon" | "equality" => true,
                    "contact" => item.name == "pair",
                    _ => false,
                };
                if takes_class && item.get("class").is_none() {
                    item.set("class", main_class.clone());
                }
                items.push(item);
            }
        }
        if !items.is_empty() {
            sections.insert((*name).to_string(), items);
        }
    }
    let keys = doc.children.iter().filter(|c| c.name == "keyframe").flat_map(|k| &k.children).count();
    if keys > 1 {
        notes.push(format!("{src}: only the 'home' keyframe (or the first) is used; {} others dropped", keys - 1));
    }

    let n_act = actuators_raw.len();
    let key_ctrl = if key_ctrl_raw.len() == n_act {
        key_ctrl_raw.into_iter().map(Some).collect()
    } else {
        if !key_ctrl_raw.is_empty() {
            notes.push(format!(
                "{src}: the home key has {} controls for {n_act} actuators; controls were derived instead",
                key_ctrl_raw.len()
            ));
        }
        vec![None; n_act]
    };
    let prefixed = |n: &str| format!("{full}{n}");
    Ok(PartOut {
        bodies,
        assets,
        default,
        sections,
        home_qpos: home_raw.into_iter().map(|(n, v)| (prefixed(&n), v)).collect(),
        key_ctrl,
        actuators: actuators_raw
            .into_iter()
            .map(|a| ActuatorInfo {
                name: a.name.as_deref().map(prefixed),
                position_joint: a.position_joint.as_deref().map(prefixed),
                ctrlrange: a.ctrlrange,
            })
            .collect(),
        names: names.iter().map(|n| prefixed(n)).collect(),
    })
}

fn collect_names(
    doc: &mut Element,
    src: &str,
    names: &mut BTreeSet<String>,
    classes: &mut BTreeSet<String>,
) -> Result<(), MergeError> {
    let mut dup: Option<(String, String)> = None;
    let mut seen: BTreeSet<(String, String)> = BTreeSet::new();
    for section in doc.children.iter_mut().filter(|c| c.name != "keyframe") {
        // Elements directly in these sections share the section's namespace whatever
        // their tag (`<equality><tendon name=...>` is an equality, not a tendon).
        let shared = match section.name.as_str() {
            s @ ("equality" | "actuator" | "sensor" | "tendon") => Some(s.to_string()),
            _ => None,
        };
        let section_name = section.name.clone();
        section.walk_mut(&mut |e| {
            if e.name == "default" {
                if let Some(c) = e.get("class") {
                    classes.insert(c.to_string());
                }
                return;
            }
            if e.name == section_name {
                return;
            }
            // Meshes, textures, hfields and skins without a name are named after their file.
            if matches!(e.name.as_str(), "mesh" | "texture" | "hfield" | "skin")
                && e.get("name").is_none()
                && let Some(stem) =
                    e.get("file").and_then(|f| std::path::Path::new(f).file_stem()).and_then(|s| s.to_str())
            {
                let stem = stem.to_string();
                e.set("name", stem);
            }
            if let Some(n) = e.get("name") {
                let ns = shared.clone().unwrap_or_else(|| namespace(&e.name).to_string());
                if !seen.insert((ns, n.to_string())) && dup.is_none() {
                    dup = Some((e.name.clone(), n.to_string()));
                }
                names.insert(n.to_string());
            }
        });
    }
    match dup {
        Some((element, name)) => Err(MergeError::DuplicateName { source_name: src.to_string(), element, name }),
        None => Ok(()),
    }
}

/// MJCF keeps one namespace per object type.
fn namespace(element: &str) -> &str {
    match element {
        "joint" | "freejoint" => "joint",
        other => other,
    }
}

/// Every reference must name something the part defines (or the world body).
fn check_references(
    doc: &Element,
    src: &str,
    names: &BTreeSet<String>,
    classes: &BTreeSet<String>,
) -> Result<(), MergeError> {
    let mut bad: Option<MergeError> = None;
    for c in doc.children.iter().filter(|c| c.name != "keyframe" && c.name != "default") {
        c.walk(&mut |e| {
            if bad.is_some() {
                return;
            }
            for key in REFERENCE_ATTRS {
                let Some(v) = e.get(key) else {
                    continue;
                };
                let known = if *key == "class" || *key == "childclass" {
                    classes.contains(v)
                } else {
                    v == "world" || names.contains(v)
                };
                if !known {
                    let what = if *key == "class" || *key == "childclass" {
                        format!("default class '{v}'")
                    } else {
                        format!("'{v}'")
                    };
                    bad = Some(MergeError::UnknownReference {
                        source_name: src.to_string(),
                        element: format!("{} ({key}=\"{v}\")", describe(e)),
                        what,
                    });
                    return;
                }
            }
        });
    }
    match bad {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// A joint's resolved facts.
#[derive(Debug, Clone)]
struct JointInfo {
    name: String,
    width: usize,
    range: Option<(f64, f64)>,
    /// The joint's reference position (qpos0 for hinge and slide joints).
    reference: f64,
}

/// Joints in qpos order (depth-first over bodies; a body's joints before its children),
/// with types and ranges resolved through the default classes.
fn joint_table(doc: &Element, defaults: &Defaults) -> Vec<JointInfo> {
    fn visit(body: &Element, childclass: &str, defaults: &Defaults, out: &mut Vec<JointInfo>) {
        for c in &body.children {
            let class = c.get("class").unwrap_or(childclass);
            let name = c.get("name").unwrap_or_default().to_string();
            match c.name.as_str() {
                "freejoint" => out.push(JointInfo { name, width: 7, range: None, reference: 0.0 }),
                "joint" => {
                    let kind = c.get("type").or_else(|| defaults.lookup(class, "joint", "type")).unwrap_or("hinge");
                    let width = match kind {
                        "free" => 7,
                        "ball" => 4,
                        _ => 1,
                    };
                    let range = c
                        .get("range")
                        .or_else(|| defaults.lookup(class, "joint", "range"))
                        .map(|r| parse_list(Some(r)))
                        .filter(|r| r.len() == 2)
                        .map(|r| (r[0], r[1]));
                    let limited = c.get("limited").or_else(|| defaults.lookup(class, "joint", "limited"));
                    let range = if limited == Some("false") { None } else { range };
                    let reference = c
                        .get("ref")
                        .or_else(|| defaults.lookup(class, "joint", "ref"))
                        .and_then(|r| r.trim().parse().ok())
                        .unwrap_or(0.0);
                    out.push(JointInfo { name, width, range, reference });
                }
                _ => {}
            }
        }
        for c in body.children.iter().filter(|c| c.name == "body" || c.name == "frame") {
            let inner = c.get("childclass").unwrap_or(childclass);
            visit(c, inner, defaults, out);
        }
    }
    let mut out = Vec::new();
    if let Some(wb) = doc.first("worldbody") {
        visit(wb, "main", defaults, &mut out);
    }
    out
}

/// Per actuator (document order): its name, and the joint it servoes if it is
/// position-like (a `<position>`, or a `<general>` with an affine bias).
fn actuator_table(doc: &Element, defaults: &Defaults) -> Vec<ActuatorInfo> {
    let mut out = Vec::new();
    for s in doc.children.iter().filter(|c| c.name == "actuator") {
        for a in &s.children {
            let class = a.get("class").unwrap_or("main");
            let look = |attr: &str| a.get(attr).or_else(|| defaults.lookup(class, &a.name, attr));
            let position_like = match a.name.as_str() {
                "position" | "intvelocity" => true,
                "general" => look("biastype") == Some("affine"),
                _ => false,
            };
            let ctrlrange =
                look("ctrlrange").map(|r| parse_list(Some(r))).filter(|r| r.len() == 2).map(|r| (r[0], r[1]));
            out.push(ActuatorInfo {
                name: a.get("name").map(str::to_string),
                position_joint: if position_like { a.get("joint").map(str::to_string) } else { None },
                ctrlrange,
            });
        }
    }
    out
}

/// Torque motors on joints become position servos with the motor's torque limit.
fn motors_to_servos(
    doc: &mut Element,
    defaults: &Defaults,
    joints: &[JointInfo],
    gains: &ServoGains,
    src: &str,
    notes: &mut Vec<String>,
) {
    let mut converted = 0;
    for s in doc.children.iter_mut().filter(|c| c.name == "actuator") {
        for a in &mut s.children {
            if a.name != "motor" {
                continue;
            }
            let Some(joint) = a.get("joint").map(str::to_string) else {
                continue;
            };
            let class = a.get("class").unwrap_or("main").to_string();
            let look = |attr: &str| {
                a.get(attr)
                    .or_else(|| defaults.lookup(&class, "motor", attr))
                    .map(|v| parse_list(Some(v)))
                    .filter(|v| !v.is_empty())
            };
            let gear = look("gear").map_or(1.0, |g| g[0].abs());
            let Some(limit) =
                look("ctrlrange").or_else(|| look("forcerange")).map(|r| r.iter().fold(0.0f64, |m, x| m.max(x.abs())))
            else {
                notes.push(format!("{src}: <motor joint=\"{joint}\"> has no torque limit; left as a motor"));
                continue;
            };
            let torque = limit * gear;
            let range = joints
                .iter()
                .find(|j| j.name == joint)
                .and_then(|j| j.range)
                .unwrap_or((-std::f64::consts::TAU, std::f64::consts::TAU));
            let kp = torque * gains.kp_per_torque;
            let mut servo = Element::new("position").with("joint", joint);
            if let Some(n) = a.get("name") {
                servo.set("name", n);
            }
            servo.set("kp", num(kp));
            servo.set("kv", num(kp * gains.kv_per_kp));
            servo.set("ctrlrange", nums(&[range.0, range.1]));
            servo.set("forcerange", nums(&[-torque, torque]));
            *a = servo;
            converted += 1;
        }
    }
    if converted > 0 {
        notes.push(format!(
            "{src}: {converted} torque motors became joint position servos with the same torque limits (the scene has no external controller)"
        ));
    }
}

type HomeQpos = BTreeMap<String, Vec<f64>>;

/// The part's `home` key (or its first key), split per joint, and its controls.
fn home_key(doc: &Element, joints: &[JointInfo]) -> (HomeQpos, Vec<f64>) {
    let keys: Vec<&Element> = doc
        .children
        .iter()
        .filter(|c| c.name == "keyframe")
        .flat_map(|k| k.children.iter())
        .filter(|k| k.name == "key")
        .collect();
    let Some(key) = keys.iter().find(|k| k.get("name") == Some("home")).or(keys.first()) else {
        return (BTreeMap::new(), Vec::new());
    };
    let qpos = parse_list(key.get("qpos"));
    let ctrl = parse_list(key.get("ctrl"));
    let mut out = BTreeMap::new();
    let mut at = 0;
    for j in joints {
        if at + j.width <= qpos.len() {
            out.insert(j.name.clone(), qpos[at..at + j.width].to_vec());
        }
        at += j.width;
    }
    (out, ctrl)
}

/// A root body's pose from whichever orientation attribute it uses (radians by now).
fn body_pose(b: &Element, src: &str) -> Result<Pose, MergeError> {
    let bad = |attr: &str, v: &str| MergeError::BadValue {
        source_name: src.to_string(),
        element: format!("{} {attr}=\"{v}\"", describe(b)),
        why: "not a valid orientation".into(),
    };
    let pos = parse3(b.get("pos")).unwrap_or([0.0; 3]);
    let quat = if let Some(v) = b.get("quat") {
        parse4(Some(v)).map(unit_quat).ok_or_else(|| bad("quat", v))?
    } else if let Some(v) = b.get("euler") {
        let e = parse3(Some(v)).ok_or_else(|| bad("euler", v))?;
        euler_to_quat(e, "xyz")
    } else if let Some(v) = b.get("axisangle") {
        let a = parse4(Some(v)).ok_or_else(|| bad("axisangle", v))?;
        let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        if n <= 0.0 {
            return Err(bad("axisangle", v));
        }
        let (s, c) = (a[3] * 0.5).sin_cos();
        [c, a[0] / n * s, a[1] / n * s, a[2] / n * s]
    } else if let Some(v) = b.get("xyaxes") {
        let l = parse_list(Some(v));
        if l.len() != 6 {
            return Err(bad("xyaxes", v));
        }
        let x = unit([l[0], l[1], l[2]]).ok_or_else(|| bad("xyaxes", v))?;
        let y0 = [l[3], l[4], l[5]];
        let d = x[0] * y0[0] + x[1] * y0[1] + x[2] * y0[2];
        let y = unit([y0[0] - d * x[0], y0[1] - d * x[1], y0[2] - d * x[2]]).ok_or_else(|| bad("xyaxes", v))?;
        let z = cross(x, y);
        mat_to_quat([x, y, z])
    } else if let Some(v) = b.get("zaxis") {
        let z = parse3(Some(v)).and_then(unit).ok_or_else(|| bad("zaxis", v))?;
        // The smallest rotation taking +Z to z.
        let c = z[2];
        if c < -1.0 + 1e-12 {
            [0.0, 1.0, 0.0, 0.0]
        } else {
            let axis = [-z[1], z[0], 0.0];
            unit_quat([1.0 + c, axis[0], axis[1], axis[2]])
        }
    } else {
        [1.0, 0.0, 0.0, 0.0]
    };
    Ok(Pose { pos, quat })
}

fn set_pose(b: &mut Element, pose: &Pose) {
    for attr in ["euler", "axisangle", "xyaxes", "zaxis"] {
        b.remove(attr);
    }
    b.set("pos", nums(&pose.pos));
    b.set("quat", nums(&pose.quat));
}

fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (n > 1e-12).then(|| [v[0] / n, v[1] / n, v[2] / n])
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Quaternion of the rotation whose columns are `cols` (x, y, z axes).
fn mat_to_quat(cols: [[f64; 3]; 3]) -> [f64; 4] {
    let m = |r: usize, c: usize| cols[c][r];
    let tr = m(0, 0) + m(1, 1) + m(2, 2);
    let q = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        [0.25 * s, (m(2, 1) - m(1, 2)) / s, (m(0, 2) - m(2, 0)) / s, (m(1, 0) - m(0, 1)) / s]
    } else if m(0, 0) > m(1, 1) && m(0, 0) > m(2, 2) {
        let s = (1.0 + m(0, 0) - m(1, 1) - m(2, 2)).sqrt() * 2.0;
        [(m(2, 1) - m(1, 2)) / s, 0.25 * s, (m(0, 1) + m(1, 0)) / s, (m(0, 2) + m(2, 0)) / s]
    } else if m(1, 1) > m(2, 2) {
        let s = (1.0 + m(1, 1) - m(0, 0) - m(2, 2)).sqrt() * 2.0;
        [(m(0, 2) - m(2, 0)) / s, (m(0, 1) + m(1, 0)) / s, 0.25 * s, (m(1, 2) + m(2, 1)) / s]
    } else {
        let s = (1.0 + m(2, 2) - m(0, 0) - m(1, 1)).sqrt() * 2.0;
        [(m(1, 0) - m(0, 1)) / s, (m(0, 2) + m(2, 0)) / s, (m(1, 2) + m(2, 1)) / s, 0.25 * s]
    };
    unit_quat(q)
}

pub(crate) fn parse_list(v: Option<&str>) -> Vec<f64> {
    v.map(|s| s.split_whitespace().filter_map(|x| x.parse().ok()).collect()).unwrap_or_default()
}

fn parse3(v: Option<&str>) -> Option<[f64; 3]> {
    let l = parse_list(v);
    (l.len() == 3).then(|| [l[0], l[1], l[2]])
}

fn parse4(v: Option<&str>) -> Option<[f64; 4]> {
    let l = parse_list(v);
    (l.len() == 4).then(|| [l[0], l[1], l[2], l[3]])
}

fn unit_quat(q: [f64; 4]) -> [f64; 4] {
    let n = (q.iter().map(|x| x * x).sum::<f64>()).sqrt();
    if n > 0.0 { q.map(|x| x / n) } else { [1.0, 0.0, 0.0, 0.0] }
}
