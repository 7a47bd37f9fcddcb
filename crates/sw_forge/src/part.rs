//! A part made offline: the offline synthesizer writes the code (or the catalog makes a
//! free-form object it has), the sandboxed runner
//! executes it, the validator checks the mesh against the analytic size, volume and
//! through-holes, and the part is written as files (STL in metres, the code, metadata
//! JSON and a preview PNG).

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};
use sw_geom::Mesh;
use tracing::info_span;

use crate::failure::Failure;
use crate::mesh_io;
use crate::runner::{CadError, CadJob, CadRunner, RunTimings, RunnerError};
use crate::synth::{SynthError, Synthesis};
use crate::validate::{self, MeshReport};

/// A validated part.
#[derive(Debug, Clone)]
pub struct GeneratedPart {
    pub prompt: String,
    pub synthesis: Synthesis,
    /// The mesh in mm, as the code made it.
    pub mesh_mm: Mesh,
    pub report: MeshReport,
    /// The exact solid's volume from the CAD kernel, mm³.
    pub brep_volume: Option<f64>,
    pub timings: PartTimings,
}

/// Where the time went, ms.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct PartTimings {
    pub synth_ms: f64,
    pub run: RunTimings,
    pub validate_ms: f64,
    pub total_ms: f64,
}

/// Why a part was not made.
#[derive(Debug, thiserror::Error)]
pub enum GenerateError {
    /// The prompt is not one the synthesizer understands (bad input).
    #[error(transparent)]
    Synth(#[from] SynthError),
    #[error(transparent)]
    Runner(#[from] RunnerError),
    /// The code did not run.
    #[error("the generated code failed: {0}")]
    Run(Box<CadError>),
    /// It ran, but the part is not what was asked for.
    #[error("the part failed validation: {failure}")]
    Invalid { failure: Failure, synthesis: Box<Synthesis>, report: Option<Box<MeshReport>> },
}

/// Synthesizes, runs and validates one prompt: a dimensioned part, or a free-form object
/// (composed, or the procedural catalog's).
pub fn generate_offline(runner: &CadRunner, prompt: &str) -> Result<GeneratedPart, GenerateError> {
    let _span = info_span!("forge_offline").entered();
    let t0 = Instant::now();
    let synthesis = match crate::freeform::offline(prompt)? {
        crate::freeform::Offline::Code(s) => *s,
        crate::freeform::Offline::Catalog { category, asset } => return Ok(catalog_part(prompt, category, &asset, t0)),
    };
    let synth_ms = ms(t0);
    let mut run = runner.run(&CadJob::cadquery(synthesis.code.clone())).map_err(|e| GenerateError::Run(Box::new(e)))?;
    let t1 = Instant::now();
    // Poles of spheres and cones come out as triangles with a repeated corner.
    mesh_io::drop_collapsed_triangles(&mut run.mesh);
    let target = synthesis.target();
    let report = match validate::validate(&run.mesh, &target) {
        Ok(r) => r,
        Err(failure) => {
            let report = validate::measure(&run.mesh);
            return Err(GenerateError::Invalid {
                failure,
                synthesis: Box::new(synthesis),
                report: Some(Box::new(report)),
            });
        }
    };
    let validate_ms = ms(t1);
    Ok(GeneratedPart {
        prompt: prompt.trim().to_string(),
        synthesis,
        mesh_mm: run.mesh,
        report,
        brep_volume: run.brep_volume,
        timings: PartTimings { synth_ms, run: run.timings, validate_ms, total_ms: ms(t0) },
    })
}

/// A catalog object as a made part: its visual meshes in mm, measured; no code.
fn catalog_part(prompt: &str, category: &str, asset: &sw_geom::Asset, t0: Instant) -> GeneratedPart {
    let mesh = crate::freeform::catalog_mesh_mm(asset);
    let report = validate::measure(&mesh);
    let synthesis = Synthesis {
        template: format!("catalog:{category}"),
        code: format!("# {}\n# The procedural catalog's {category} (seed 0): made without code.\n", prompt.trim()),
        size: report.size,
        min: report.min,
        size_certain: [true; 3],
        volume: None,
        genus: None,
    };
    let total = ms(t0);
    GeneratedPart {
        prompt: prompt.trim().to_string(),
        synthesis,
        mesh_mm: mesh,
        report,
        brep_volume: None,
        timings: PartTimings { synth_ms: total, total_ms: total, ..PartTimings::default() },
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The metadata written beside a part's mesh.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PartMetadata {
    pub prompt: String,
    pub template: String,
    /// Units of `mesh`: metres (the code works in mm; the mesh is scaled by 0.001).
    pub mesh: String,
    pub mesh_units: String,
    pub code: String,
    /// Requested (analytic) bounding box, mm.
    pub size_mm: [f64; 3],
    /// Measured bounding box of the mesh, mm.
    pub measured_size_mm: [f64; 3],
    /// Analytic volume, mm³ (when the template knows it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub volume_mm3: Option<f64>,
    pub mesh_volume_mm3: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub brep_volume_mm3: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub through_holes: Option<u32>,
    pub triangles: usize,
    pub watertight: bool,
    /// Largest relative bounding-box error.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size_error: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub volume_error: Option<f64>,
    /// Content hash of the STL (FNV-1a 64, hex).
    pub mesh_hash: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preview: Option<String>,
}

/// The files of a written part.
#[derive(Debug, Clone, PartialEq)]
pub struct PartFiles {
    pub mesh: PathBuf,
    pub code: PathBuf,
    pub metadata: PathBuf,
    pub preview: Option<PathBuf>,
    pub meta: PartMetadata,
}

/// Binary STL bytes of the part in metres.
pub fn stl_bytes_m(part: &GeneratedPart) -> Vec<u8> {
    mesh_io::stl_bytes_mm_as_m(&part.mesh_mm, &part.synthesis.template)
}

/// Writes `part.stl` (metres), `part.py`, `part.json` and `preview.png` into `dir`.
pub fn write_part(dir: &Path, part: &GeneratedPart, preview: bool) -> std::io::Result<PartFiles> {
    fs_err::create_dir_all(dir)?;
    let stl = stl_bytes_m(part);
    let hash = format!("{:016x}", sw_geom::fnv1a(&stl));
    let mesh = dir.join("part.stl");
    fs_err::write(&mesh, &stl)?;
    let code = dir.join("part.py");
    fs_err::write(&code, &part.synthesis.code)?;
    let preview_path = if preview {
        let p = dir.join("preview.png");
        let image = render_preview(&part.mesh_mm, 320);
        let file = fs_err::File::create(&p)?;
        image.write_png(std::io::BufWriter::new(file)).map_err(std::io::Error::other)?;
        Some(p)
    } else {
        None
    };
    let meta = PartMetadata {
        prompt: part.prompt.clone(),
        template: part.synthesis.template.clone(),
        mesh: "part.stl".into(),
        mesh_units: "m".into(),
        code: "part.py".into(),
        size_mm: part.synthesis.size,
        measured_size_mm: part.report.size,
        volume_mm3: part.synthesis.volume,
        mesh_volume_mm3: part.report.volume,
        brep_volume_mm3: part.brep_volume,
        through_holes: part.synthesis.genus,
        triangles: part.report.triangles,
        watertight: part.report.watertight,
        size_error: part.report.size_error,
        volume_error: part.report.volume_error,
        mesh_hash: hash,
        preview: preview_path.as_ref().map(|_| "preview.png".to_string()),
    };
    let metadata = dir.join("part.json");
    let json = serde_json::to_string_pretty(&meta).map_err(std::io::Error::other)?;
    fs_err::write(&metadata, json + "\n")?;
    Ok(PartFiles { mesh, code, metadata, preview: preview_path, meta })
}

/// A shaded picture of a mesh, seen from the front right and above.
pub fn render_preview(mesh: &Mesh, size: u32) -> sw_geom::raster::Image {
    use sw_geom::raster::{Camera, Renderer};
    let bounds = mesh.bounds();
    let camera = Camera::framing(&bounds, -0.9, 0.55);
    let mut r = Renderer::new(size, size, &camera, [245, 245, 240]);
    r.draw_mesh(mesh, &sw_geom::Pose::default(), [0.55, 0.62, 0.72, 1.0]);
    r.finish()
}
