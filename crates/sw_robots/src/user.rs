//! User directories of robots (`SCENEWRIGHT_ROBOTS`, `--robots-dir`): every MJCF or URDF
//! robot file in the directory or up to two levels below (a Menagerie checkout is a directory per
//! robot; a ROS description package keeps its URDF in `urdf/`) is registered under its file name.
//!
//! A file is a robot when it is MJCF with a jointed body in its `<worldbody>`, or URDF.
//! Not registered: files another file includes, `scene*.xml` (Menagerie's demo scenes
//! around a robot), other XML (ROS `package.xml`). A broken file, or one whose name is
//! taken, is reported as a problem naming the file; the other files still register.
//! Mounting facts of user robots are unknown until measured (`RobotDef::measured`).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use sw_mjcf::xml::Element;

use crate::load::{FileModel, FilePart, ModelSpec};
use crate::{Licence, Origin, RobotDef, RobotError, RobotKind, leak};

pub(crate) fn register(dir: &Path, robots: &mut Vec<&'static RobotDef>, problems: &mut Vec<RobotError>) {
    if !dir.is_dir() {
        problems.push(RobotError::NoDirectory(dir.to_path_buf()));
        return;
    }
    let mut files = Vec::new();
    collect(dir, 0, &mut files);
    files.sort();
    // Files included by another file in the same directory are parts, not robots.
    let mut included: BTreeSet<PathBuf> = BTreeSet::new();
    let mut parsed = Vec::new();
    for f in files {
        let text = match fs_err::read_to_string(&f) {
            Ok(t) => t,
            Err(e) => {
                problems.push(RobotError::Io { path: f.clone(), reason: e.to_string() });
                continue;
            }
        };
        let urdf = f.extension().is_some_and(|e| e.eq_ignore_ascii_case("urdf"));
        match Element::parse(&text) {
            Ok(doc) => {
                if !urdf && doc.name == "mujoco" {
                    let base = f.parent().map(Path::to_path_buf).unwrap_or_default();
                    doc.walk(&mut |e| {
                        if e.name == "include"
                            && let Some(inc) = e.get("file")
                        {
                            included.insert(base.join(inc));
                        }
                    });
                }
                parsed.push((f, doc, urdf));
            }
            Err(e) if urdf || looks_like_mjcf(&text) => {
                problems.push(RobotError::Merge(sw_mjcf::MergeError::Xml(e, f.display().to_string())));
            }
            Err(_) => {}
        }
    }
    let roots = vec![dir.to_path_buf()];
    for (file, doc, urdf) in parsed {
        if included.contains(&file) {
            continue;
        }
        let stem = file.file_stem().and_then(|s| s.to_str()).unwrap_or_default().to_string();
        let (kind, spec) = if urdf {
            if doc.name != "robot" {
                continue;
            }
            let floating = has_floating_root(&doc);
            let kind = if floating { RobotKind::MobileBase } else { RobotKind::Arm };
            (kind, ModelSpec::Urdf { file: file.clone(), package_roots: roots.clone() })
        } else {
            if doc.name != "mujoco" || stem.to_lowercase().starts_with("scene") {
                continue;
            }
            let Some(kind) = mjcf_kind(&doc) else {
                continue;
            };
            let model = FileModel { parts: vec![FilePart::main(file.clone())], ..FileModel::default() };
            (kind, ModelSpec::Files(model))
        };
        let name = normalize_name(&stem);
        if let Some(other) = robots.iter().find(|r| r.name == name || r.aliases.contains(&name.as_str())) {
            let other = match &other.origin {
                Origin::BuiltIn => format!("the built-in {}", other.display),
                Origin::Pack { pack, .. } => format!("the {pack} pack's {}", other.display),
                Origin::User { file } => file.display().to_string(),
            };
            problems.push(RobotError::NameClash { name, file, other });
            continue;
        }
        let display = leak(format!("{stem} (user {}, {})", if urdf { "URDF" } else { "MJCF" }, file.display()));
        let def = RobotDef {
            name: leak(name),
            aliases: &[],
            display,
            kind,
            source: leak(format!("user file {}", file.display())),
            origin: Origin::User { file: file.clone() },
            licence: Licence { name: "as stated by the file's owner", files: Vec::new() },
            // Placeholders until measured in MuJoCo (the pipeline does).
            footprint_radius: 0.6,
            height: 1.0,
            reach: if kind == RobotKind::Arm { 0.8 } else { 0.0 },
            base_radius: 0.1,
            keepout: &[([-0.3, -0.3, 0.0], [0.3, 0.3, 1.0])],
            measured: false,
            model: spec,
            gripper: None,
        };
        robots.push(&*Box::leak(Box::new(def)));
    }
}

fn collect(dir: &Path, depth: usize, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.filter_map(Result::ok) {
        let p = e.path();
        if p.is_dir() {
            let hidden = p.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.starts_with('.'));
            if depth < 2 && !hidden {
                collect(&p, depth + 1, out);
            }
        } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xml") || x.eq_ignore_ascii_case("urdf")) {
            out.push(p);
        }
    }
}

fn looks_like_mjcf(text: &str) -> bool {
    text.contains("<mujoco")
}

/// A robot's kind from its MJCF, or `None` when no body has a joint (not a robot).
fn mjcf_kind(doc: &Element) -> Option<RobotKind> {
    let wb = doc.first("worldbody")?;
    let mut joints = false;
    wb.walk(&mut |e| joints |= e.name == "joint" || e.name == "freejoint");
    if !joints {
        return None;
    }
    let free_root = wb.children.iter().filter(|b| b.name == "body").any(|b| {
        b.children.iter().any(|c| c.name == "freejoint" || (c.name == "joint" && c.get("type") == Some("free")))
    });
    Some(if free_root { RobotKind::MobileBase } else { RobotKind::Arm })
}

fn has_floating_root(doc: &Element) -> bool {
    doc.children.iter().any(|j| j.name == "joint" && j.get("type") == Some("floating"))
}

/// A registry name from a file stem: lower case, letters, digits and underscores.
fn normalize_name(stem: &str) -> String {
    let s: String =
        stem.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect();
    let s = s.trim_matches('_').to_string();
    if s.is_empty() { "robot".into() } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_directory_is_a_problem_naming_it() {
        let mut robots = Vec::new();
        let mut problems = Vec::new();
        register(Path::new("/no/such/robots"), &mut robots, &mut problems);
        assert!(robots.is_empty());
        assert_eq!(problems[0].to_string(), "robot directory /no/such/robots does not exist or is not a directory");
    }

    #[test]
    fn names_are_safe_prefixes() {
        assert_eq!(normalize_name("My-Arm v2"), "my_arm_v2");
        assert_eq!(normalize_name("--"), "robot");
    }
}
