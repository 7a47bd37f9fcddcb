//! Reading a registered model into a [`RobotSource`]: built-ins from the binary, packs and
//! user MJCF files from disk (with every `<include>`d file), URDF files converted to MJCF
//! with `package://` paths resolved.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use fs_err as fs;
use sw_geom::Pose;
use sw_mjcf::xml::Element;
use sw_mjcf::{PartFixes, RobotPart, RobotSource};

use crate::RobotError;

/// How to build a model's source.
#[derive(Debug)]
pub(crate) enum ModelSpec {
    BuiltIn { parts: &'static [BuiltinPart], excludes: &'static [(&'static str, &'static str)] },
    Files(FileModel),
    Urdf { file: PathBuf, package_roots: Vec<PathBuf> },
}

/// One MJCF document of a built-in model.
#[derive(Debug)]
pub(crate) struct BuiltinPart {
    pub label: &'static str,
    pub mjcf: &'static str,
    pub prefix: &'static str,
    pub attach_to: Option<&'static str>,
    pub pos: [f64; 3],
    pub quat: [f64; 4],
}

/// A model made of MJCF files on disk.
#[derive(Debug, Clone, Default)]
pub(crate) struct FileModel {
    pub parts: Vec<FilePart>,
    pub home: Vec<(String, Vec<f64>)>,
    pub home_ctrl: Vec<(String, f64)>,
    pub excludes: Vec<(String, String)>,
    pub notes: Vec<String>,
}

#[derive(Debug, Clone)]
pub(crate) struct FilePart {
    pub file: PathBuf,
    /// How errors and notes name the file (default: its path).
    pub label: Option<String>,
    pub prefix: String,
    pub attach_to: Option<String>,
    pub attach_pose: Pose,
    pub fixes: PartFixes,
}

impl FilePart {
    pub fn main(file: PathBuf) -> Self {
        Self {
            file,
            label: None,
            prefix: String::new(),
            attach_to: None,
            attach_pose: Pose::IDENTITY,
            fixes: PartFixes::default(),
        }
    }
}

impl ModelSpec {
    pub fn files(&self) -> Vec<PathBuf> {
        match self {
            ModelSpec::BuiltIn { .. } => Vec::new(),
            ModelSpec::Files(m) => m.parts.iter().map(|p| p.file.clone()).collect(),
            ModelSpec::Urdf { file, .. } => vec![file.clone()],
        }
    }
}

pub(crate) fn source(model: &str, spec: &ModelSpec) -> Result<RobotSource, RobotError> {
    match spec {
        ModelSpec::BuiltIn { parts, excludes } => {
            let mut src = RobotSource::single(model, "", "");
            src.parts = parts
                .iter()
                .map(|p| {
                    let mut part = RobotPart::new(p.label, p.mjcf);
                    part.prefix = p.prefix.to_string();
                    part.attach_to = p.attach_to.map(str::to_string);
                    part.attach_pose = Pose { pos: p.pos, quat: p.quat };
                    part
                })
                .collect();
            src.excludes = excludes.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
            Ok(src)
        }
        ModelSpec::Files(m) => {
            let mut src = RobotSource::single(model, "", "");
            src.parts = m.parts.iter().map(read_part).collect::<Result<_, _>>()?;
            src.home = m.home.clone();
            src.home_ctrl = m.home_ctrl.clone();
            src.excludes = m.excludes.clone();
            src.notes = m.notes.clone();
            Ok(src)
        }
        ModelSpec::Urdf { file, package_roots } => {
            let text =
                fs::read_to_string(file).map_err(|e| RobotError::Io { path: file.clone(), reason: e.to_string() })?;
            let dir = file.parent().map(Path::to_path_buf).unwrap_or_default();
            let resolve = |uri: &str| resolve_uri(uri, &dir, package_roots);
            let label = file.display().to_string();
            let import = sw_mjcf::urdf_to_mjcf(&label, &text, &resolve)?;
            let mut part = RobotPart::new(&label, &import.mjcf);
            part.dir = Some(dir);
            let mut src = RobotSource::single(model, &label, "");
            src.parts = vec![part];
            src.notes = import.notes;
            Ok(src)
        }
    }
}

fn read_part(p: &FilePart) -> Result<RobotPart, RobotError> {
    let text =
        fs::read_to_string(&p.file).map_err(|e| RobotError::Io { path: p.file.clone(), reason: e.to_string() })?;
    let dir = p.file.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut includes = BTreeMap::new();
    read_includes(&text, &p.file, &dir, &mut includes, 0)?;
    let label = p.label.clone().unwrap_or_else(|| p.file.display().to_string());
    let mut part = RobotPart::new(&label, &text);
    part.dir = Some(dir);
    part.includes = includes;
    part.prefix = p.prefix.clone();
    part.attach_to = p.attach_to.clone();
    part.attach_pose = p.attach_pose;
    part.fixes = p.fixes.clone();
    Ok(part)
}

/// Reads every file `<include>`d from `text`, recursively. Paths are relative to the main
/// model's directory, as MuJoCo resolves them.
fn read_includes(
    text: &str,
    from: &Path,
    dir: &Path,
    out: &mut BTreeMap<String, String>,
    depth: usize,
) -> Result<(), RobotError> {
    if depth > 8 || !text.contains("<include") {
        return Ok(());
    }
    // A broken document is reported by the merger with its position.
    let Ok(doc) = Element::parse(text) else {
        return Ok(());
    };
    let mut files = Vec::new();
    doc.walk(&mut |e| {
        if e.name == "include"
            && let Some(f) = e.get("file")
        {
            files.push(f.to_string());
        }
    });
    for f in files {
        if out.contains_key(&f) {
            continue;
        }
        let path = dir.join(&f);
        let inc = fs::read_to_string(&path).map_err(|e| RobotError::Io {
            path: path.clone(),
            reason: format!("<include file=\"{f}\"> in {}: {}", from.display(), e.kind()),
        })?;
        out.insert(f, inc.clone());
        read_includes(&inc, &path, dir, out, depth + 1)?;
    }
    Ok(())
}

/// Resolves a URDF mesh `filename`: `package://pkg/rest` against the package roots (a
/// root named `pkg`, or `pkg` one or two levels inside a root, or an ancestor of the URDF
/// named `pkg`), `file://` as an absolute path, anything else relative to the URDF.
pub(crate) fn resolve_uri(uri: &str, urdf_dir: &Path, roots: &[PathBuf]) -> Result<PathBuf, String> {
    if let Some(rest) = uri.strip_prefix("file://") {
        return Ok(PathBuf::from(rest));
    }
    let Some(rest) = uri.strip_prefix("package://") else {
        return Ok(urdf_dir.join(uri));
    };
    let (pkg, inner) = rest.split_once('/').unwrap_or((rest, ""));
    let mut candidates: Vec<PathBuf> = Vec::new();
    for a in urdf_dir.ancestors() {
        if a.file_name().is_some_and(|n| n == pkg) {
            candidates.push(a.to_path_buf());
        }
    }
    for r in roots {
        if r.file_name().is_some_and(|n| n == pkg) {
            candidates.push(r.clone());
        }
        candidates.push(r.join(pkg));
        if let Ok(entries) = std::fs::read_dir(r) {
            let mut subs: Vec<PathBuf> =
                entries.filter_map(Result::ok).map(|e| e.path()).filter(|p| p.is_dir()).collect();
            subs.sort();
            candidates.extend(subs.into_iter().map(|s| s.join(pkg)));
        }
    }
    for c in &candidates {
        let p = c.join(inner);
        if p.exists() {
            return Ok(p);
        }
    }
    let searched: Vec<String> = roots.iter().map(|r| r.display().to_string()).collect();
    Err(format!(
        "package '{pkg}' (or its file '{inner}') was not found next to the URDF or under {}; add the directory that holds it to SCENEWRIGHT_ROBOTS",
        if searched.is_empty() { "any robot directory".to_string() } else { searched.join(", ") }
    ))
}
