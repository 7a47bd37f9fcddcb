//! The asset library: the store and the semantic index together. Every part made is put
//! in the store by content and its label embedded into the index, so the next request
//! for the same kind of object ("storage rack" after "shelving unit") reuses it.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::embed::{DIM, EmbedError, MiniLm};
use crate::index::{DEFAULT_THRESHOLD, Hit, IndexError, SemanticIndex};
use crate::part::{GeneratedPart, stl_bytes_m};
use crate::store::{AssetRecord, AssetStore, LocalStore, StoreError};

/// Why the library failed.
#[derive(Debug, thiserror::Error)]
pub enum LibraryError {
    #[error(transparent)]
    Store(#[from] StoreError),
    #[error(transparent)]
    Index(#[from] IndexError),
    #[error(transparent)]
    Embed(#[from] EmbedError),
    #[error("the query is empty")]
    EmptyQuery,
}

/// `SCENEWRIGHT_ASSET_STORE`, else `.cache/assets` in the checkout.
pub fn default_store_dir() -> PathBuf {
    if let Some(p) = std::env::var_os("SCENEWRIGHT_ASSET_STORE").filter(|p| !p.is_empty()) {
        return PathBuf::from(p);
    }
    crate::runner::checkout_cache().join("assets")
}

/// A store with its index and embedder.
#[derive(Debug)]
pub struct AssetLibrary {
    store: LocalStore,
    index: Mutex<SemanticIndex>,
    embedder: MiniLm,
    threshold: f32,
}

impl AssetLibrary {
    /// Opens the store at `dir` (creating it), its index, and the embedder.
    pub fn open(dir: &Path, embedder: MiniLm) -> Result<Self, LibraryError> {
        let store = LocalStore::open(dir)?;
        let index = SemanticIndex::load(dir, DIM)?;
        Ok(Self { store, index: Mutex::new(index), embedder, threshold: DEFAULT_THRESHOLD })
    }

    pub fn with_threshold(mut self, threshold: f32) -> Self {
        self.threshold = threshold;
        self
    }

    pub fn store(&self) -> &LocalStore {
        &self.store
    }

    pub fn embedder(&self) -> &MiniLm {
        &self.embedder
    }

    pub fn len(&self) -> usize {
        self.lock().len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, SemanticIndex> {
        self.index.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Stores a mesh with its record and indexes the record's label.
    pub fn add(&self, stl: &[u8], record: AssetRecord) -> Result<AssetRecord, LibraryError> {
        let record = self.store.put(stl, record)?;
        let v = self.embedder.embed(&[record.label.as_str()])?;
        let mut index = self.lock();
        if let Some(v) = v.first() {
            index.upsert(record.id.clone(), record.label.clone(), v)?;
        }
        index.save(self.store.root())?;
        Ok(record)
    }

    /// Stores a part made offline, labelled with its prompt.
    pub fn add_part(&self, part: &GeneratedPart, label: &str) -> Result<AssetRecord, LibraryError> {
        let stl = stl_bytes_m(part);
        let s = part.report.size;
        let record = AssetRecord {
            id: crate::store::AssetId::of(&stl),
            label: label.trim().to_string(),
            description: part.prompt.clone(),
            source: format!("template:{}", part.synthesis.template),
            size_m: [s[0] * 1e-3, s[1] * 1e-3, s[2] * 1e-3],
            triangles: part.report.triangles,
            code: Some(part.synthesis.code.clone()),
            extra: serde_json::json!({
                "volume_mm3": part.report.volume,
                "analytic_volume_mm3": part.synthesis.volume,
                "through_holes": part.synthesis.genus,
            }),
        };
        self.add(&stl, record)
    }

    /// The `k` nearest stored assets to a text.
    pub fn search(&self, text: &str, k: usize) -> Result<Vec<Hit>, LibraryError> {
        if text.trim().is_empty() {
            return Err(LibraryError::EmptyQuery);
        }
        let v = self.embedder.embed(&[text])?;
        let Some(q) = v.first() else { return Ok(Vec::new()) };
        Ok(self.lock().search(q, k)?)
    }

    /// The stored asset that serves a request for `text`, when one is similar enough.
    pub fn lookup(&self, text: &str) -> Result<Option<Hit>, LibraryError> {
        Ok(self.search(text, 1)?.into_iter().next().filter(|h| h.score >= self.threshold))
    }
}
