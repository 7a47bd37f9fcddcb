//! `assets generate`: a part offline — a dimensioned part (the synthesizer's feature
//! language) or a free-form object (composed, or the procedural catalog's); code run in the
//! sandboxed runner, validated, written as files.

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
    /// The id in the asset store.
    stored: Option<String>,
}

/// The runner with the environment's settings and `workers` workers.
pub(crate) fn start_runner(workers: usize) -> Result<CadRunner, Failure> {
    let config = RunnerConfig { workers: workers.max(1), ..RunnerConfig::from_env() };
    CadRunner::start(config).map_err(|e| Failure::internal(e.to_string()))
}

pub(crate) fn generate(
    prompt: &str,
    out: PathBuf,
    no_preview: bool,
    store: Option<String>,
    no_store: bool,
    json: bool,
) -> Result<u8, Failure> {
    // Read the prompt first: bad input is refused before the runner starts (2–5 s).
    if let Err(e) = sw_forge::freeform::offline(prompt) {
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
    // Every success is stored and indexed for reuse.
    let stored = if no_store { None } else { Some(store_part(store, &part)?) };
    let mut names = vec![files.mesh.clone(), files.code.clone(), files.metadata.clone()];
    names.extend(files.preview.clone());
    if json {
        print_json(&Generated {
            out: out.display().to_string(),
            files: names.iter().map(|p| p.display().to_string()).collect(),
            metadata: &files.meta,
            timings_ms: part.timings,
            stored: stored.as_ref().map(|r| r.id.to_string()),
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
    // An extent a cut may trim is promised only as a bound ("at most").
    let wanted: Vec<String> = (0..3)
        .map(|k| format!("{}{:.3}", if part.synthesis.size_certain[k] { "" } else { "≤" }, m.size_mm[k]))
        .collect();
    print(&format!(
        "part     {}\nmade by  {} · {} triangles · watertight\nsize     {:.3} × {:.3} × {:.3} mm (wanted {}, largest error {:.3} %)\n         {volume}{}\ntime     {:.0} ms (code ran in {:.0} ms)",
        files.mesh.display(),
        m.template,
        m.triangles,
        m.measured_size_mm[0],
        m.measured_size_mm[1],
        m.measured_size_mm[2],
        wanted.join(" × "),
        100.0 * m.size_error.unwrap_or(0.0),
        m.through_holes
            .filter(|g| *g > 0)
            .map_or(String::new(), |g| { format!(" · {g} through-hole{}", if g == 1 { "" } else { "s" }) }),
        part.timings.total_ms,
        part.timings.run.roundtrip_ms,
    ));
    if let Some(r) = stored {
        print(&format!("stored   {} (scenewright assets show {})", r.id, r.id.short()));
    }
    Ok(0)
}

/// A store location from the command line: an `s3://` URL or a directory.
fn check_location(store: Option<String>) -> Result<String, Failure> {
    let location = store.unwrap_or_else(sw_forge::library::default_store_location);
    if location.contains("://") && !location.starts_with("s3://") {
        return Err(Failure::input(format!("asset store {location}: give a directory or s3://bucket/prefix")));
    }
    if location.starts_with("s3://") && sw_forge::store_s3::S3Config::from_env().is_none() {
        return Err(Failure::input(format!(
            "asset store {location}: set SCENEWRIGHT_S3_ENDPOINT (and AWS_ACCESS_KEY_ID, AWS_SECRET_ACCESS_KEY) for an s3:// store"
        )));
    }
    Ok(location)
}

/// The library at `store` (or the default one), with the embedder loaded.
fn open_library(store: Option<String>) -> Result<sw_forge::library::AssetLibrary, Failure> {
    let location = check_location(store)?;
    let model = sw_forge::embed::MiniLm::load_default().map_err(|e| Failure::internal(e.to_string()))?;
    sw_forge::library::AssetLibrary::open_location(&location, model)
        .map_err(|e| Failure::internal(format!("asset store {location}: {e}")))
}

/// Puts a generated part into the library (store and index).
pub(crate) fn store_part(
    store: Option<String>,
    part: &sw_forge::part::GeneratedPart,
) -> Result<sw_forge::store::AssetRecord, Failure> {
    let lib = open_library(store)?;
    lib.add_part(part, &part.prompt).map_err(|e| Failure::internal(e.to_string()))
}

#[derive(Serialize)]
struct SearchHit {
    id: String,
    label: String,
    score: f32,
    reuse: bool,
    size_m: Option<[f64; 3]>,
    source: Option<String>,
}

pub(crate) fn search(query: &str, k: usize, store: Option<String>, json: bool) -> Result<u8, Failure> {
    if query.trim().is_empty() {
        return Err(Failure::input("the query is empty"));
    }
    if k == 0 || k > 1000 {
        return Err(Failure::input(format!("--top must be 1 to 1000, not {k}")));
    }
    let lib = open_library(store)?;
    let t = std::time::Instant::now();
    let hits = lib.search(query, k).map_err(|e| Failure::internal(e.to_string()))?;
    let ms = t.elapsed().as_secs_f64() * 1e3;
    let rows: Vec<SearchHit> = hits
        .iter()
        .map(|h| {
            let rec = lib.store().record(&h.id).ok();
            SearchHit {
                id: h.id.to_string(),
                label: h.label.clone(),
                score: h.score,
                reuse: h.score >= sw_forge::index::DEFAULT_THRESHOLD,
                size_m: rec.as_ref().map(|r| r.size_m),
                source: rec.map(|r| r.source),
            }
        })
        .collect();
    if json {
        print_json(&serde_json::json!({ "query": query, "assets": lib.len(), "ms": ms, "hits": rows }));
        return Ok(0);
    }
    if rows.is_empty() {
        print(&format!("no stored assets ({} indexed)", lib.len()));
        return Ok(0);
    }
    let mut s = format!("{} of {} assets for \"{query}\" ({ms:.1} ms)\n", rows.len(), lib.len());
    for r in &rows {
        s.push_str(&format!(
            "{}  {:.3}{}  {}\n",
            &r.id[..12],
            r.score,
            if r.reuse { " reuse" } else { "      " },
            r.label
        ));
    }
    print(&s);
    Ok(0)
}

/// `assets show ID` of a stored asset (an id or a unique prefix of at least 8 digits).
pub(crate) fn show_stored(id: &str, store: Option<String>, json: bool) -> Result<u8, Failure> {
    use sw_forge::store::StoreError;
    let location = check_location(store)?;
    let s = sw_forge::store::open_store(&location).map_err(|e| Failure::internal(e.to_string()))?;
    let id = s.resolve(id).map_err(|e| match e {
        StoreError::Io { .. } | StoreError::Corrupt { .. } => Failure::internal(e.to_string()),
        other => Failure::input(other.to_string()),
    })?;
    let rec = s.record(&id).map_err(|e| Failure::internal(e.to_string()))?;
    let mesh = s.mesh(&id).map_err(|e| Failure::internal(e.to_string()))?;
    if json {
        print_json(&serde_json::json!({ "record": rec, "mesh_bytes": mesh.len() }));
        return Ok(0);
    }
    print(&format!(
        "asset    {}\nlabel    {}\nsource   {}\nsize     {:.4} × {:.4} × {:.4} m · {} triangles · mesh {} bytes (checked against its id)\nprompt   {}",
        rec.id,
        rec.label,
        rec.source,
        rec.size_m[0],
        rec.size_m[1],
        rec.size_m[2],
        rec.triangles,
        mesh.len(),
        rec.description
    ));
    Ok(0)
}
