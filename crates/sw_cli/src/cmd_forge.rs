//! `assets generate`: a part from a dimensioned prompt, offline — the template
//! synthesizer's CadQuery code run in the sandboxed runner, validated, written as files.

use std::path::PathBuf;

use serde::Serialize;
use sw_forge::part::{GenerateError, PartMetadata, generate_offline, write_part};
use sw_forge::runner::{CadRunner, RunnerConfig};

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Serialize)]
struct Generated<'a> {
    out: String,
    files: Vec<String>,
    metadata: &'a PartMetadata,
    timings_ms: sw_forge::part::PartTimings,
}

/// The runner with the environment's settings and `workers` workers.
pub(crate) fn start_runner(workers: usize) -> Result<CadRunner, Failure> {
    let config = RunnerConfig { workers: workers.max(1), ..RunnerConfig::from_env() };
    CadRunner::start(config).map_err(|e| Failure::internal(e.to_string()))
}

pub(crate) fn generate(prompt: &str, out: PathBuf, no_preview: bool, json: bool) -> Result<u8, Failure> {
    // Read the prompt first: bad input is refused before the runner starts (2–5 s).
    if let Err(e) = sw_forge::synth::synthesize(prompt) {
        return Err(Failure::input(e.to_string()));
    }
    if out.is_file() {
        return Err(Failure::input(format!("{}: exists and is a file", out.display())));
    }
    let runner = start_runner(1)?;
    let part = generate_offline(&runner, prompt).map_err(|e| match e {
        GenerateError::Synth(e) => Failure::input(e.to_string()),
        other => Failure::internal(other.to_string()),
    })?;
    let files =
        write_part(&out, &part, !no_preview).map_err(|e| Failure::internal(format!("{}: {e}", out.display())))?;
    let mut names = vec![files.mesh.clone(), files.code.clone(), files.metadata.clone()];
    names.extend(files.preview.clone());
    if json {
        print_json(&Generated {
            out: out.display().to_string(),
            files: names.iter().map(|p| p.display().to_string()).collect(),
            metadata: &files.meta,
            timings_ms: part.timings,
        });
        return Ok(0);
    }
    let m = &files.meta;
    let volume = match m.volume_mm3 {
        Some(v) if v > 0.0 => format!(
            "volume {:.1} mm³ (analytic {v:.1}, {:+.2} %)",
            m.mesh_volume_mm3,
            100.0 * (m.mesh_volume_mm3 - v) / v
        ),
        _ => format!("volume {:.1} mm³", m.mesh_volume_mm3),
    };
    print(&format!(
        "part     {}\ntemplate {} · {} triangles · watertight\nsize     {:.3} × {:.3} × {:.3} mm (requested {:.3} × {:.3} × {:.3}, largest error {:.3} %)\n         {volume}{}\ntime     {:.0} ms (code ran in {:.0} ms)",
        files.mesh.display(),
        m.template,
        m.triangles,
        m.measured_size_mm[0],
        m.measured_size_mm[1],
        m.measured_size_mm[2],
        m.size_mm[0],
        m.size_mm[1],
        m.size_mm[2],
        100.0 * m.size_error.unwrap_or(0.0),
        m.through_holes
            .filter(|g| *g > 0)
            .map_or(String::new(), |g| { format!(" · {g} through-hole{}", if g == 1 { "" } else { "s" }) }),
        part.timings.total_ms,
        part.timings.run.roundtrip_ms,
    ));
    Ok(0)
}
