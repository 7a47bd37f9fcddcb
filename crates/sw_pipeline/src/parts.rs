//! Generated parts placed into a package by an edit (from the asset studio): their meshes
//! travel with the package (`parts/<asset id>.stl`, metres) and `parts.json` says which
//! object each one is, so every later edit rebuilds those objects from the same mesh —
//! the same asset, hence byte for byte the same `scene.xml` — instead of their labelled
//! stand-ins.

use std::path::Path;

use serde::{Deserialize, Serialize};
use sw_geom::{Asset, Mesh, PlacementKind};

use crate::PipelineError;

pub(crate) const FILE: &str = "parts.json";
const DIR: &str = "parts";
/// Density given to a movable generated part (a plastic part), kg/m³.
const DENSITY: f64 = 500.0;

/// One placed part, as `parts.json` records it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct PartEntry {
    pub object: String,
    pub asset_id: String,
    pub label: String,
    /// The mesh inside the package.
    pub file: String,
    pub movable: bool,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
}

#[derive(Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PartsFile {
    parts: Vec<PartEntry>,
}

/// A placed part with its mesh.
#[derive(Debug, Clone)]
pub(crate) struct Part {
    pub entry: PartEntry,
    pub stl: Vec<u8>,
    mesh: Mesh,
}

fn safe_id(id: &str) -> bool {
    !id.is_empty() && id.len() <= 128 && id.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
}

impl Part {
    /// A part from its stored mesh (binary STL, metres).
    pub fn new(asset_id: &str, label: &str, stl: Vec<u8>) -> Result<Self, String> {
        if !safe_id(asset_id) {
            return Err(format!("'{asset_id}' is not an asset id"));
        }
        let mesh = sw_geom::read_stl(stl.as_slice()).map_err(|e| format!("its mesh is not binary STL ({e})"))?;
        if mesh.triangles.is_empty() {
            return Err("its mesh has no triangles".into());
        }
        let size = mesh.bounds().size();
        if !size.iter().all(|v| v.is_finite() && *v > 0.0 && *v <= 20.0) {
            return Err(format!(
                "its mesh is {:.3} × {:.3} × {:.3} m; a part is up to 20 m",
                size[0], size[1], size[2]
            ));
        }
        let movable = size.iter().all(|v| *v <= 0.6);
        let mass = movable.then(|| ((mesh.volume().abs() * DENSITY) * 1e4).round() / 1e4).map(|m| m.max(0.05));
        let entry = PartEntry {
            object: String::new(),
            asset_id: asset_id.to_string(),
            label: label.to_string(),
            file: format!("{DIR}/{asset_id}.stl"),
            movable,
            mass,
        };
        Ok(Self { entry, stl, mesh })
    }

    pub fn for_object(mut self, name: &str) -> Self {
        self.entry.object = name.to_string();
        self
    }

    /// Its bounding box, metres.
    pub fn size(&self) -> [f64; 3] {
        self.mesh.bounds().size()
    }

    /// Its asset: the mesh as the visual, its convex decomposition for collision.
    pub fn asset(&self) -> Asset {
        let placement = if self.entry.movable { PlacementKind::OnSurface } else { PlacementKind::Floor };
        let category = format!("generated_{}", crate::forge::slug(&self.entry.label));
        sw_forge::collision::part_asset(&category, &self.mesh, self.entry.mass, placement)
    }
}

/// The parts recorded in a package (none when it has no `parts.json`).
pub(crate) fn load(dir: &Path) -> Result<Vec<Part>, PipelineError> {
    let path = dir.join(FILE);
    if !path.is_file() {
        return Ok(Vec::new());
    }
    let bad = |e: String| PipelineError::Input(format!("{}: {e}", path.display()));
    let text = std::fs::read_to_string(&path).map_err(|e| bad(e.to_string()))?;
    let file: PartsFile = serde_json::from_str(&text).map_err(|e| bad(e.to_string()))?;
    let mut out = Vec::new();
    for entry in file.parts {
        if !safe_id(&entry.asset_id) || entry.file != format!("{DIR}/{}.stl", entry.asset_id) {
            return Err(bad(format!("part {} names an unexpected file {}", entry.object, entry.file)));
        }
        let stl = std::fs::read(dir.join(&entry.file)).map_err(|e| bad(format!("{}: {e}", entry.file)))?;
        let mesh = sw_geom::read_stl(stl.as_slice()).map_err(|e| bad(format!("{}: {e}", entry.file)))?;
        out.push(Part { entry, stl, mesh });
    }
    Ok(out)
}

/// Writes `parts.json` and the meshes of the parts whose objects are still in the scene.
pub(crate) fn write(dir: &Path, parts: &[Part], present: impl Fn(&str) -> bool) -> Result<(), PipelineError> {
    let kept: Vec<&Part> = parts.iter().filter(|p| present(&p.entry.object)).collect();
    if kept.is_empty() {
        return Ok(());
    }
    let io = |e: std::io::Error| PipelineError::Internal(format!("writing the package's parts: {e}"));
    std::fs::create_dir_all(dir.join(DIR)).map_err(io)?;
    for p in &kept {
        std::fs::write(dir.join(&p.entry.file), &p.stl).map_err(io)?;
    }
    let file = PartsFile { parts: kept.iter().map(|p| p.entry.clone()).collect() };
    let mut text = serde_json::to_string_pretty(&file).map_err(|e| PipelineError::Internal(e.to_string()))?;
    text.push('\n');
    std::fs::write(dir.join(FILE), text).map_err(io)
}
