//! The asset forge behind `POST /api/assets`: a description the catalog does not cover is
//! looked up in the asset library by meaning (and size, when given), else made by the
//! generation loop — the CAD stage's model when one is configured, else the offline
//! template synthesizer for dimensioned mechanical parts — run in the sandboxed runner,
//! validated, stored and indexed. The runner (a cold `import cadquery` costs seconds) and
//! the embedder start on first use and are shared by every request after.

use std::sync::{Arc, OnceLock};
use std::time::Duration;

use serde_json::{Value, json};
use sw_forge::failure::Failure;
use sw_forge::generate::{
    Attempt, CodeWriter, ForgeOutcome, LlmWriter, LoopConfig, PartRequest, TemplateWriter, forge,
};
use sw_forge::library::AssetLibrary;
use sw_forge::runner::{CadRunner, RunnerConfig};
use sw_forge::store::{AssetId, AssetRecord, StoreError};
use sw_llm::{Client, LlmConfig, LlmStage};
use sw_pipeline::{AssetSource, ForgeSource};

/// How stale the asset index may be before a request re-reads the store (other
/// processes' new assets become reusable within this).
const SYNC_AGE: Duration = Duration::from_secs(10);

/// How long one asset may take end to end (every attempt of the loop).
pub const ASSET_TIMEOUT: Duration = Duration::from_secs(180);

/// Where a service keeps generated assets: `SCENEWRIGHT_ASSET_STORE` when set; else
/// `assets/` in the S3 bucket when packages go to S3 (every worker shares it); else
/// `assets/` in the data directory.
pub fn store_location(data_dir: &std::path::Path) -> String {
    match std::env::var("SCENEWRIGHT_ASSET_STORE") {
        Ok(p) if !p.trim().is_empty() => p,
        _ => match sw_forge::store_s3::S3Config::from_env() {
            Some(c) => format!("s3://{}/assets", c.bucket),
            None => data_dir.join("assets").display().to_string(),
        },
    }
}

/// The shared runner and library, started on first use.
pub struct AssetForge {
    location: String,
    llm: Option<LlmConfig>,
    runner: OnceLock<Result<CadRunner, String>>,
    library: OnceLock<Result<Arc<AssetLibrary>, String>>,
}

impl std::fmt::Debug for AssetForge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AssetForge").field("location", &self.location).finish_non_exhaustive()
    }
}

/// Why an asset could not be made or served.
#[derive(Debug, thiserror::Error)]
pub enum ForgeError {
    /// Every attempt failed; the request cannot be served as asked.
    #[error("{0}")]
    NotMade(String),
    /// The runner, the embedder or the store is not available.
    #[error("the asset forge is unavailable: {0}")]
    Unavailable(String),
}

/// What the forge did for a description.
#[derive(Debug, Clone)]
pub struct Made {
    pub record: AssetRecord,
    /// `library` (reused by meaning) or `generated`.
    pub source: &'static str,
    /// Metadata for the asset's row.
    pub meta: Value,
}

impl AssetForge {
    /// A forge over the asset store at `location` (a directory or `s3://bucket/prefix`);
    /// `llm` gives the CAD stage's model, when there is one.
    pub fn new(location: String, llm: Option<LlmConfig>) -> Self {
        Self { location, llm, runner: OnceLock::new(), library: OnceLock::new() }
    }

    pub fn location(&self) -> &str {
        &self.location
    }

    fn runner(&self) -> Result<&CadRunner, ForgeError> {
        self.runner
            .get_or_init(|| CadRunner::start(RunnerConfig::from_env()).map_err(|e| e.to_string()))
            .as_ref()
            .map_err(|e| ForgeError::Unavailable(e.clone()))
    }

    /// The library (loading the embedder and syncing the index on first use).
    pub fn library(&self) -> Result<&Arc<AssetLibrary>, ForgeError> {
        self.library
            .get_or_init(|| {
                let model = sw_forge::embed::MiniLm::load_default().map_err(|e| e.to_string())?;
                AssetLibrary::open_location(&self.location, model)
                    .map(Arc::new)
                    .map_err(|e| format!("asset store {}: {e}", self.location))
            })
            .as_ref()
            .map_err(|e| ForgeError::Unavailable(e.clone()))
    }

    fn writer(&self) -> Arc<dyn CodeWriter> {
        match self.llm.as_ref().filter(|c| c.endpoint(LlmStage::Cad).is_some()) {
            Some(cfg) => Arc::new(LlmWriter::new(Client::new(cfg.clone()))),
            None => Arc::new(TemplateWriter),
        }
    }

    /// Reuses or makes the asset for `description` (blocking: seconds when generated).
    pub fn make(&self, description: &str, size_m: Option<[f64; 3]>) -> Result<Made, ForgeError> {
        self.make_reporting(description, size_m, &|_| {})
    }

    /// [`Self::make`], telling `report` what happens as it happens: one JSON object per
    /// step (`{"event": "progress", "message"}`) and per failed attempt (`{"event":
    /// "failure", "attempt", "kind", "message"}`).
    pub fn make_reporting(
        &self,
        description: &str,
        size_m: Option<[f64; 3]>,
        report: &(dyn Fn(Value) + Send + Sync),
    ) -> Result<Made, ForgeError> {
        let say = |m: &str| report(json!({ "event": "progress", "message": m }));
        say("looking in the asset library for a part that means the same and fits the size");
        let library = self.library()?;
        // Another process may have stored it since this one synced.
        if let Err(e) = library.sync_if_older(SYNC_AGE) {
            tracing::warn!("asset index sync failed: {e}");
        }
        match library.lookup(description, size_m) {
            Ok(Some(found)) => {
                let meta = json!({
                    "source": "library",
                    "asset_id": found.record.id,
                    "label": found.record.label,
                    "score": found.hit.score,
                    "size_m": found.record.size_m,
                    "made_by": found.record.source,
                    "fit": found.fit.map(|f| json!({ "scale": f.scale, "quarter_turn": f.quarter_turn })),
                });
                return Ok(Made { record: found.record, source: "library", meta });
            }
            Ok(None) => {}
            Err(e) => return Err(ForgeError::Unavailable(e.to_string())),
        }
        say("none fits: generating it (starting the CAD runner when it is cold)");
        let runner = self.runner()?;
        let writer = Reporting { inner: self.writer(), report, reported: std::sync::atomic::AtomicUsize::new(0) };
        let request = PartRequest { description: description.to_string(), size_m };
        let t = std::time::Instant::now();
        let outcome = forge(runner, &writer, &request, LoopConfig::default());
        writer.failures_since(outcome.attempts());
        match outcome {
            ForgeOutcome::Made(part) => {
                say(&format!("made and validated in {} attempt(s); storing and indexing it", part.attempts.len()));
                let (stl, record) = part.stored(description, description, json!({}));
                let record = library.add(&stl, record).map_err(|e| ForgeError::Unavailable(e.to_string()))?;
                let meta = json!({
                    "source": "generated",
                    "asset_id": record.id,
                    "label": record.label,
                    "size_m": record.size_m,
                    "triangles": record.triangles,
                    "made_by": record.source,
                    "attempts": part.attempts.len(),
                    "ms": t.elapsed().as_secs_f64() * 1e3,
                });
                Ok(Made { record, source: "generated", meta })
            }
            ForgeOutcome::Failed { attempts, writer } => {
                let why: Vec<String> = attempts
                    .iter()
                    .filter_map(|a| a.failure.as_ref())
                    .map(|f| format!("{}: {}", f.kind.name(), f.message.lines().next().unwrap_or("")))
                    .collect();
                Err(ForgeError::NotMade(format!(
                    "{writer} could not make \"{}\" in {} attempt(s) ({})",
                    description.trim(),
                    attempts.len(),
                    why.join("; ")
                )))
            }
        }
    }
}

/// A code writer that reports each attempt and each failure of the one it wraps.
struct Reporting<'a> {
    inner: Arc<dyn CodeWriter>,
    report: &'a (dyn Fn(Value) + Send + Sync),
    /// Failed attempts already reported.
    reported: std::sync::atomic::AtomicUsize,
}

impl Reporting<'_> {
    /// Reports the failures among `attempts` not reported yet.
    fn failures_since(&self, attempts: &[Attempt]) {
        use std::sync::atomic::Ordering;
        let from = self.reported.swap(attempts.len(), Ordering::Relaxed);
        for (i, a) in attempts.iter().enumerate().skip(from) {
            if let Some(f) = &a.failure {
                (self.report)(json!({
                    "event": "failure", "attempt": i + 1, "kind": f.kind.name(),
                    "message": f.message.lines().next().unwrap_or(""),
                }));
            }
        }
    }
}

impl CodeWriter for Reporting<'_> {
    fn name(&self) -> String {
        self.inner.name()
    }

    fn write(&self, request: &PartRequest, history: &[Attempt]) -> Result<String, Failure> {
        self.failures_since(history);
        (self.report)(json!({
            "event": "progress",
            "message": format!("attempt {}: the {} writer writes CadQuery; the runner builds it and the validator checks it", history.len() + 1, self.inner.name()),
        }));
        self.inner.write(request, history)
    }

    fn take_calls(&self) -> Vec<sw_llm::LlmCall> {
        self.inner.take_calls()
    }
}

impl AssetForge {
    /// L2 for one generation job whose CAD stage has a model: the generation loop with the
    /// model as writer, in the shared runner, reusing and keeping assets in the shared
    /// library (a fresh source per job, so each job's report holds its own calls).
    pub fn source_for_job(&self, client: &Client) -> Result<Arc<dyn AssetSource>, ForgeError> {
        let runner = self.runner()?.clone();
        let source = ForgeSource::new(runner, Arc::new(LlmWriter::new(client.clone())), LoopConfig::default());
        Ok(match self.library() {
            Ok(library) => {
                if let Err(e) = library.sync_if_older(SYNC_AGE) {
                    tracing::warn!("asset index sync failed: {e}");
                }
                Arc::new(source.with_library(Arc::clone(library)))
            }
            Err(e) => {
                tracing::warn!("generated parts are not kept for reuse: {e}");
                Arc::new(source)
            }
        })
    }

    /// The mesh (binary STL, metres) of a stored asset.
    pub fn mesh(&self, id: &str) -> Result<Option<Vec<u8>>, ForgeError> {
        let Ok(id) = AssetId::parse(id) else { return Ok(None) };
        match self.library()?.store().mesh(&id) {
            Ok(bytes) => Ok(Some(bytes)),
            Err(StoreError::NotFound(_)) => Ok(None),
            Err(e) => Err(ForgeError::Unavailable(e.to_string())),
        }
    }
}
