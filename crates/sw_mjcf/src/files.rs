//! The files a robot's assets reference (meshes, textures, height fields, skins): resolved
//! against the part's directory and its compiler's `meshdir`/`texturedir`/`assetdir`, and
//! given a path inside the package (`robots/<model>/...` under the scene's `assets/`).
//! Nothing is read here; the pipeline copies the files and reports any that are missing.

use std::collections::BTreeSet;
use std::path::{Component, Path, PathBuf};

use crate::normalize::{Compiler, describe};
use crate::robot::{MergeError, RobotFile, RobotPart};
use crate::xml::Element;

/// File attributes of asset elements, and whether the texture directory applies.
const FILE_ATTRS: &[(&str, &[&str], bool)] = &[
    ("mesh", &["file"], false),
    ("hfield", &["file"], false),
    ("skin", &["file"], false),
    ("texture", &["file", "fileright", "fileleft", "fileup", "filedown", "filefront", "fileback"], true),
];

/// Rewrites the file attributes of one asset element to package paths and records the files.
pub(crate) fn relocate(
    item: &mut Element,
    prefix: &str,
    part: &RobotPart,
    compiler: &Compiler,
    file_dir: &str,
    files: &mut BTreeSet<RobotFile>,
) -> Result<(), MergeError> {
    let Some((_, attrs, texture)) = FILE_ATTRS.iter().find(|(tag, _, _)| *tag == item.name) else {
        return Ok(());
    };
    let asset_dir = compiler.get("assetdir");
    let dir_attr =
        if *texture { compiler.get("texturedir").or(asset_dir) } else { compiler.get("meshdir").or(asset_dir) }
            .unwrap_or("");
    let strip = compiler.get("strippath").is_some_and(|v| v == "true");
    for attr in *attrs {
        let Some(file) = item.get(attr).map(str::to_string) else {
            continue;
        };
        // Named as in the robot's file, not as prefixed for the scene.
        let name = item.get("name").map(|n| n.strip_prefix(prefix).unwrap_or(n).to_string()).unwrap_or_default();
        let element = format!("<{} name=\"{name}\" {attr}=\"{file}\"> in {}", item.name, part.label);
        let Some(base) = &part.dir else {
            return Err(MergeError::BadValue {
                source_name: part.label.clone(),
                element: describe(item),
                why: "references a file, but the model has no directory to find it in".into(),
            });
        };
        let written = if strip {
            Path::new(&file).file_name().map_or_else(|| PathBuf::from(&file), PathBuf::from)
        } else {
            PathBuf::from(&file)
        };
        let rel = if written.is_absolute() { written.clone() } else { Path::new(dir_attr).join(&written) };
        let source = if rel.is_absolute() { rel.clone() } else { base.join(&rel) };
        let dest = format!("{file_dir}{}", package_path(&rel));
        item.set(attr, dest.clone());
        files.insert(RobotFile { source: lexical(&source), dest, element });
    }
    Ok(())
}

/// A relative, forward-slashed path without `..` or a root: `meshes/link0.stl`.
fn package_path(rel: &Path) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut escaped = false;
    for c in rel.components() {
        match c {
            Component::Normal(s) => parts.push(s.to_string_lossy().into_owned()),
            Component::ParentDir => {
                if parts.pop().is_none() {
                    escaped = true;
                }
            }
            Component::RootDir | Component::Prefix(_) => escaped = true,
            Component::CurDir => {}
        }
    }
    if escaped {
        // Outside the model's directory: keep the last three components, enough to tell
        // files apart and free of where the user keeps them.
        let tail = &parts[parts.len().saturating_sub(3)..];
        format!("ext/{}", tail.join("/"))
    } else {
        parts.join("/")
    }
}

/// `a/b/../c` → `a/c`, without touching the file system.
fn lexical(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn package_paths_stay_inside_the_package() {
        assert_eq!(package_path(Path::new("meshes/./a.stl")), "meshes/a.stl");
        assert_eq!(package_path(Path::new("meshes/../a.stl")), "a.stl");
        assert_eq!(package_path(Path::new("../../shared/a.stl")), "ext/shared/a.stl");
        assert_eq!(package_path(Path::new("/abs/a.stl")), "ext/abs/a.stl");
        assert_eq!(package_path(Path::new("/home/me/ws/pkg/meshes/a.stl")), "ext/pkg/meshes/a.stl");
        assert_eq!(lexical(Path::new("/x/y/../z/./a.stl")), PathBuf::from("/x/z/a.stl"));
    }
}
