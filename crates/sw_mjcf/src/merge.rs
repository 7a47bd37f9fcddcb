//! The robot merger: takes a robot's MJCF document and prepares its parts for insertion
//! into a scene under a prefix. Every name it brings is prefixed (bodies, joints, geoms,
//! sites, cameras, lights, actuators, sensors, tendons, equalities, meshes, textures,
//! materials and default classes) and every reference to those names follows.

use std::collections::{BTreeMap, BTreeSet};

use sw_geom::{Pose, quat_mul};

use crate::xml::{Element, XmlError, nums};

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
];

/// Sections copied from the robot into the scene, in MJCF order.
pub(crate) const MERGED_SECTIONS: &[&str] = &["contact", "equality", "tendon", "actuator", "sensor"];

/// A robot document that cannot be merged; the message names the element.
#[derive(Debug, thiserror::Error)]
pub enum MergeError {
    #[error("{source_name}: not valid XML at {0}", source_name = .1)]
    Xml(XmlError, String),
    #[error("{source_name}: the root element is <{found}>, expected <mujoco>")]
    NotMjcf { source_name: String, found: String },
    #[error("{source_name}: has no <worldbody> with a body")]
    NoBody { source_name: String },
    #[error("{source_name}: <{element}> is not supported by the merger yet ({why})")]
    Unsupported { source_name: String, element: String, why: String },
    #[error("{source_name}: <{element} name=\"{name}\"> appears twice")]
    DuplicateName { source_name: String, element: String, name: String },
}

/// A robot, prefixed and ready to insert.
#[derive(Debug, Clone)]
pub struct PreparedRobot {
    pub prefix: String,
    /// Top-level bodies, prefixed and posed in the world.
    pub bodies: Vec<Element>,
    /// Asset children (materials, meshes, textures), prefixed.
    pub assets: Vec<Element>,
    /// The robot's default tree as `<default class="<prefix>_main">`.
    pub defaults: Option<Element>,
    /// Children of the merged sections, by section name.
    pub sections: BTreeMap<String, Vec<Element>>,
    /// The robot's own `home` keyframe (or its first), by prefixed joint name.
    pub home_qpos: BTreeMap<String, Vec<f64>>,
    /// Control of each of the robot's actuators at home, in order.
    pub home_ctrl: Vec<f64>,
}

/// Prefixes and poses a robot document. `source_name` appears in every error.
pub fn prepare_robot(source_name: &str, mjcf: &str, prefix: &str, mount: &Pose) -> Result<PreparedRobot, MergeError> {
    let src = source_name.to_string();
    let mut doc = Element::parse(mjcf).map_err(|e| MergeError::Xml(e, src.clone()))?;
    if doc.name != "mujoco" {
        return Err(MergeError::NotMjcf { source_name: src, found: doc.name });
    }
    for child in &doc.children {
        match child.name.as_str() {
            "include" | "extension" | "custom" | "deformable" => {
                return Err(MergeError::Unsupported {
                    source_name: src,
                    element: child.name.clone(),
                    why: "flatten the model first".into(),
                });
            }
            _ => {}
        }
    }
    // MJCF's default angle unit is degrees.
    let angle =
        doc.children.iter().rev().filter(|c| c.name == "compiler").find_map(|c| c.get("angle")).unwrap_or("degree");
    if angle != "radian" {
        return Err(MergeError::Unsupported {
            source_name: src,
            element: "compiler".into(),
            why: "angles in degrees; the scene uses radians".into(),
        });
    }

    // Names defined by the robot, and the implicit names of file assets.
    let mut names: BTreeSet<String> = BTreeSet::new();
    let mut classes: BTreeSet<String> = BTreeSet::from(["main".to_string()]);
    collect_names(&mut doc, &src, &mut names, &mut classes)?;
    let main_class = format!("{prefix}_main");

    // Name unnamed joints so the keyframe can address them.
    let mut joint_counter = 0;
    if let Some(wb) = doc.first_mut("worldbody") {
        wb.walk_mut(&mut |e| {
            if (e.name == "joint" || e.name == "freejoint") && e.get("name").is_none() {
                e.set("name", format!("joint{joint_counter}"));
                joint_counter += 1;
            }
        });
        wb.walk(&mut |e| {
            if (e.name == "joint" || e.name == "freejoint")
                && let Some(n) = e.get("name")
            {
                names.insert(n.to_string());
            }
        });
    }

    // Keyframe values before renaming (they are positional).
    let joint_order = joint_names(&doc);
    let (home_qpos_raw, home_ctrl) = home_key(&doc, &joint_order)?;

    // Rename everything.
    let rename = |e: &mut Element| {
        if let Some(n) = e.get("name").map(str::to_string) {
            e.set("name", format!("{prefix}_{n}"));
        }
        for key in REFERENCE_ATTRS {
            let Some(v) = e.get(key).map(str::to_string) else {
                continue;
            };
            let is_class = *key == "class" || *key == "childclass";
            let hit = if is_class { classes.contains(&v) } else { names.contains(&v) };
            if hit {
                e.set(key, if is_class && v == "main" { main_class.clone() } else { format!("{prefix}_{v}") });
            }
        }
    };
    doc.walk_mut(&mut |e| {
        if e.name == "default" {
            if let Some(c) = e.get("class").map(str::to_string) {
                e.set("class", if c == "main" { main_class.clone() } else { format!("{prefix}_{c}") });
            }
        } else if e.name != "mujoco" {
            rename(e);
        }
    });

    // Defaults: the robot's root default becomes a named class.
    let defaults = doc.first("default").cloned().map(|mut d| {
        d.set("class", main_class.clone());
        d
    });
    let has_defaults = defaults.is_some();

    // Assets.
    let mut assets = Vec::new();
    for a in doc.children.iter().filter(|c| c.name == "asset") {
        for mut item in a.children.clone() {
            if has_defaults && matches!(item.name.as_str(), "mesh" | "material") && item.get("class").is_none() {
                item.set("class", main_class.clone());
            }
            assets.push(item);
        }
    }

    // Bodies: composed with the mount pose.
    let mut bodies = Vec::new();
    for wb in doc.children.iter().filter(|c| c.name == "worldbody") {
        for b in &wb.children {
            if b.name != "body" {
                return Err(MergeError::Unsupported {
                    source_name: src.clone(),
                    element: b.name.clone(),
                    why: "a robot's worldbody may hold only bodies".into(),
                });
            }
            let mut body = b.clone();
            for attr in ["euler", "axisangle", "xyaxes", "zaxis"] {
                if body.get(attr).is_some() {
                    return Err(MergeError::Unsupported {
                        source_name: src.clone(),
                        element: format!("body {attr}"),
                        why: "root bodies must be oriented with quat".into(),
                    });
                }
            }
            let own = Pose {
                pos: parse3(body.get("pos")).unwrap_or([0.0; 3]),
                quat: parse4(body.get("quat")).map(normalize).unwrap_or([1.0, 0.0, 0.0, 0.0]),
            };
            let world = Pose { pos: mount.apply(own.pos), quat: quat_mul(mount.quat, own.quat) };
            body.set("pos", nums(&world.pos));
            body.set("quat", nums(&world.quat));
            if has_defaults && body.get("childclass").is_none() {
                body.set("childclass", main_class.clone());
            }
            bodies.push(body);
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
                if has_defaults && takes_class && item.get("class").is_none() {
                    item.set("class", main_class.clone());
                }
                items.push(item);
            }
        }
        if !items.is_empty() {
            sections.insert((*name).to_string(), items);
        }
    }

    let home_qpos = home_qpos_raw.into_iter().map(|(n, v)| (format!("{prefix}_{n}"), v)).collect();
    Ok(PreparedRobot { prefix: prefix.to_string(), bodies, assets, defaults, sections, home_qpos, home_ctrl })
}

fn collect_names(
    doc: &mut Element,
    src: &str,
    names: &mut BTreeSet<String>,
    classes: &mut BTreeSet<String>,
) -> Result<(), MergeError> {
    let mut dup: Option<(String, String)> = None;
    let mut seen: BTreeMap<(String, String), ()> = BTreeMap::new();
    doc.walk_mut(&mut |e| {
        if e.name == "default" {
            if let Some(c) = e.get("class") {
                classes.insert(c.to_string());
            }
            return;
        }
        if e.name == "mujoco" || e.name == "key" {
            return;
        }
        // Meshes, textures, hfields and skins without a name are named after their file.
        if matches!(e.name.as_str(), "mesh" | "texture" | "hfield" | "skin")
            && e.get("name").is_none()
            && let Some(stem) = e.get("file").and_then(|f| std::path::Path::new(f).file_stem()).and_then(|s| s.to_str())
        {
            let stem = stem.to_string();
            e.set("name", stem);
        }
        if let Some(n) = e.get("name") {
            let key = (namespace(&e.name).to_string(), n.to_string());
            if seen.insert(key, ()).is_some() && dup.is_none() {
                dup = Some((e.name.clone(), n.to_string()));
            }
            names.insert(n.to_string());
        }
    });
    match dup {
        Some((element, name)) => Err(MergeError::DuplicateName { source_name: src.to_string(), element, name }),
        None => Ok(()),
    }
}

/// MJCF keeps one namespace per object type; actuators of every kind share one.
fn namespace(element: &str) -> &str {
    match element {
        "motor" | "position" | "velocity" | "general" | "intvelocity" | "damper" | "cylinder" | "muscle"
        | "adhesion" | "plugin" => "actuator",
        "joint" | "freejoint" => "joint",
        "spatial" | "fixed" => "tendon",
        "weld" | "connect" | "distance" => "equality",
        other => other,
    }
}

/// Joint names in qpos order (bodies depth-first, joints in document order).
fn joint_names(doc: &Element) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    if let Some(wb) = doc.first("worldbody") {
        wb.walk(&mut |e| {
            if e.name == "freejoint" {
                out.push((e.get("name").unwrap_or_default().to_string(), 7));
            } else if e.name == "joint" {
                let width = match e.get("type").unwrap_or("hinge") {
                    "free" => 7,
                    "ball" => 4,
                    _ => 1,
                };
                out.push((e.get("name").unwrap_or_default().to_string(), width));
            }
        });
    }
    out
}

type HomeQpos = BTreeMap<String, Vec<f64>>;

/// The robot's `home` key (or its first key), split per joint.
fn home_key(doc: &Element, joints: &[(String, usize)]) -> Result<(HomeQpos, Vec<f64>), MergeError> {
    let keys: Vec<&Element> = doc
        .children
        .iter()
        .filter(|c| c.name == "keyframe")
        .flat_map(|k| k.children.iter())
        .filter(|k| k.name == "key")
        .collect();
    let Some(key) = keys.iter().find(|k| k.get("name") == Some("home")).or(keys.first()) else {
        return Ok((BTreeMap::new(), Vec::new()));
    };
    let qpos = parse_list(key.get("qpos"));
    let ctrl = parse_list(key.get("ctrl"));
    let mut out = BTreeMap::new();
    let mut at = 0;
    for (name, width) in joints {
        if at + width <= qpos.len() {
            out.insert(name.clone(), qpos[at..at + width].to_vec());
        }
        at += width;
    }
    Ok((out, ctrl))
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

fn normalize(q: [f64; 4]) -> [f64; 4] {
    let n = (q.iter().map(|x| x * x).sum::<f64>()).sqrt();
    if n > 0.0 { q.map(|x| x / n) } else { [1.0, 0.0, 0.0, 0.0] }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ROBOT: &str = r#"<mujoco model="r">
      <compiler angle="radian"/>
      <default><joint damping="1"/><default class="big"><geom size="0.1"/></default></default>
      <asset><material name="m" rgba="1 0 0 1"/><mesh file="meshes/link.stl"/></asset>
      <worldbody>
        <body name="base" pos="0 0 0.1">
          <geom class="big" material="m" type="mesh" mesh="link"/>
          <body name="l1"><joint name="j1"/><geom size="0.05"/></body>
          <body name="l2"><joint/><geom size="0.05"/></body>
        </body>
      </worldbody>
      <contact><exclude body1="base" body2="l1"/></contact>
      <actuator><position name="a1" joint="j1"/></actuator>
      <keyframe><key name="home" qpos="0.5 -0.25" ctrl="0.5"/></keyframe>
    </mujoco>"#;

    #[test]
    fn everything_is_prefixed_and_references_follow() {
        let r = prepare_robot("test robot", ROBOT, "arm_1", &Pose::from_pos_yaw([1.0, 2.0, 0.75], 0.0)).unwrap();
        let body = &r.bodies[0];
        assert_eq!(body.get("name"), Some("arm_1_base"));
        assert_eq!(body.get("pos"), Some("1 2 0.85"));
        assert_eq!(body.get("childclass"), Some("arm_1_main"));
        let geom = &body.children[0];
        assert_eq!(geom.get("class"), Some("arm_1_big"));
        assert_eq!(geom.get("material"), Some("arm_1_m"));
        assert_eq!(geom.get("mesh"), Some("arm_1_link"));
        assert_eq!(r.assets[1].get("name"), Some("arm_1_link"));
        let exclude = &r.sections["contact"][0];
        assert_eq!(exclude.get("body1"), Some("arm_1_base"));
        assert_eq!(exclude.get("class"), None, "exclude takes no class");
        let act = &r.sections["actuator"][0];
        assert_eq!(
            (act.get("name"), act.get("joint"), act.get("class")),
            (Some("arm_1_a1"), Some("arm_1_j1"), Some("arm_1_main"))
        );
        assert_eq!(r.home_qpos["arm_1_j1"], vec![0.5]);
        assert_eq!(r.home_qpos["arm_1_joint0"], vec![-0.25]);
        assert_eq!(r.home_ctrl, vec![0.5]);
        assert_eq!(r.defaults.as_ref().and_then(|d| d.get("class")), Some("arm_1_main"));
    }

    #[test]
    fn bad_robots_name_the_problem() {
        let e = prepare_robot("bad.xml", "<mujoco><worldbody>", "x", &Pose::IDENTITY).unwrap_err();
        assert!(e.to_string().starts_with("bad.xml: not valid XML at line"), "{e}");
        let e = prepare_robot("deg.xml", "<mujoco><worldbody><body/></worldbody></mujoco>", "x", &Pose::IDENTITY)
            .unwrap_err();
        assert!(e.to_string().contains("degrees"), "{e}");
        let twice =
            r#"<mujoco><compiler angle="radian"/><worldbody><body name="a"/><body name="a"/></worldbody></mujoco>"#;
        let e = prepare_robot("dup.xml", twice, "x", &Pose::IDENTITY).unwrap_err();
        assert_eq!(e.to_string(), "dup.xml: <body name=\"a\"> appears twice");
        let e = prepare_robot("urdf.xml", "<robot/>", "x", &Pose::IDENTITY).unwrap_err();
        assert!(e.to_string().contains("expected <mujoco>"));
    }
}
