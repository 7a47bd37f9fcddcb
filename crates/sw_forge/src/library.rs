//! The asset library: the store and the semantic index together. Every part made is put
//! in the store by content and its label embedded into the index, so the next request
//! for the same kind of object ("storage rack" after "shelving unit") reuses it — when
//! its size fits the request ([`crate::reuse`]).
//!
//! The store is the truth; the index is derived from it and kept in a local directory
//! (beside a local store, or in the cache for a bucket). Opening a library brings the
//! index up to date with the store — assets other processes stored are embedded, assets
//! gone from the store are dropped — and a damaged index is rebuilt, not fatal.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use crate::embed::{DIM, EmbedError, MiniLm};
use crate::index::{DEFAULT_THRESHOLD, Hit, IndexError, SemanticIndex};
use crate::part::{GeneratedPart, stl_bytes_m};
use crate::reuse::{SizeFit, size_fit};
use crate::store::{AssetId, AssetRecord, AssetStore, LocalStore, StoreError, open_store};

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

/// `SCENEWRIGHT_ASSET_STORE` (a directory or `s3://bucket/prefix`), else `.cache/assets`
/// in the checkout.
pub fn default_store_location() -> String {
    match std::env::var("SCENEWRIGHT_ASSET_STORE") {
        Ok(p) if !p.trim().is_empty() => p,
        _ => crate::runner::checkout_cache().join("assets").display().to_string(),
    }
}

/// Where the index of a bucket's assets is kept: `SCENEWRIGHT_ASSET_INDEX`, else the
/// checkout's cache, one directory per location (bucket, prefix and endpoint).
fn index_cache_dir(location: &str) -> PathBuf {
    if let Some(p) = std::env::var_os("SCENEWRIGHT_ASSET_INDEX").filter(|p| !p.is_empty()) {
        return PathBuf::from(p);
    }
    let digest = AssetId::of(location.as_bytes());
    crate::runner::checkout_cache().join("asset-index").join(digest.short())
}

/// What bringing the index up to date did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Sync {
    /// Assets in the store that the index lacked, now embedded.
    pub added: usize,
    /// Index rows whose asset is gone from the store, now dropped.
    pub dropped: usize,
    /// The saved index could not be read and was rebuilt from the store.
    pub rebuilt: bool,
}

/// A stored asset that serves a request, and how to fit it to the requested size.
#[derive(Debug, Clone)]
pub struct Reuse {
    pub hit: Hit,
    pub record: AssetRecord,
    /// `None` when the request gave no size.
    pub fit: Option<SizeFit>,
}

/// How many of the nearest labels a sized lookup considers.
const CANDIDATES: usize = 8;

/// A store with its index and embedder.
pub struct AssetLibrary {
    store: Arc<dyn AssetStore>,
    index_dir: PathBuf,
    index: Mutex<SemanticIndex>,
    embedder: MiniLm,
    threshold: f32,
    last_sync: Sync,
    /// When the index was last brought up to date with the store.
    synced_at: Mutex<std::time::Instant>,
}

impl std::fmt::Debug for AssetLibrary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AssetLibrary")
            .field("store", &self.store.location())
            .field("index_dir", &self.index_dir)
            .field("threshold", &self.threshold)
            .finish_non_exhaustive()
    }
}

impl AssetLibrary {
    /// Opens the local store at `dir` (creating it), its index beside it, and the embedder.
    pub fn open(dir: &Path, embedder: MiniLm) -> Result<Self, LibraryError> {
        let store: Arc<dyn AssetStore> = Arc::new(LocalStore::open(dir)?);
        Self::open_with(store, dir, embedder)
    }

    /// Opens the store at `location` (a directory, or `s3://bucket/prefix` whose index is
    /// kept in the checkout's cache).
    pub fn open_location(location: &str, embedder: MiniLm) -> Result<Self, LibraryError> {
        if location.starts_with("s3://") {
            let store = open_store(location)?;
            let dir = index_cache_dir(&store.location());
            Self::open_with(store, &dir, embedder)
        } else {
            Self::open(Path::new(location), embedder)
        }
    }

    /// A library over any store, with its index in `index_dir`, brought up to date.
    pub fn open_with(store: Arc<dyn AssetStore>, index_dir: &Path, embedder: MiniLm) -> Result<Self, LibraryError> {
        let (index, rebuilt) = match SemanticIndex::load(index_dir, DIM) {
            Ok(i) => (i, false),
            Err(e) => {
                tracing::warn!(index = %index_dir.display(), "the asset index is unreadable ({e}); rebuilding it from the store");
                (SemanticIndex::new(DIM), true)
            }
        };
        let mut lib = Self {
            store,
            index_dir: index_dir.to_path_buf(),
            index: Mutex::new(index),
            embedder,
            threshold: DEFAULT_THRESHOLD,
            last_sync: Sync::default(),
            synced_at: Mutex::new(std::time::Instant::now()),
        };
        let mut sync = lib.sync()?;
        sync.rebuilt = rebuilt;
        lib.last_sync = sync;
        Ok(lib)
    }

    /// What the last [`AssetLibrary::sync`] at opening did.
    pub fn opened_with(&self) -> Sync {
        self.last_sync
    }

    /// [`AssetLibrary::sync`] when the last one is older than `max_age` (listing a bucket
    /// on every request would put a round trip on the hot path); `None` when it was fresh.
    pub fn sync_if_older(&self, max_age: std::time::Duration) -> Result<Option<Sync>, LibraryError> {
        let stale = self.synced_at.lock().map_or(true, |t| t.elapsed() >= max_age);
        if stale { self.sync().map(Some) } else { Ok(None) }
    }

    /// Brings the index up to date with the store: embeds what it lacks, drops what the
    /// store no longer has, and saves it when anything changed.
    pub fn sync(&self) -> Result<Sync, LibraryError> {
        let stored = self.store.list()?;
        let have: BTreeSet<AssetId> = self.lock().entries().iter().map(|e| e.id.clone()).collect();
        let missing: Vec<AssetRecord> =
            stored.iter().filter(|id| !have.contains(*id)).map(|id| self.store.record(id)).collect::<Result<_, _>>()?;
        let keep: BTreeSet<&AssetId> = stored.iter().collect();
        let mut vectors = Vec::with_capacity(missing.len());
        for chunk in missing.chunks(64) {
            let labels: Vec<&str> = chunk.iter().map(|r| r.label.as_str()).collect();
            vectors.extend(self.embedder.embed(&labels)?);
        }
        let mut index = self.lock();
        let dropped = index.retain(|id| keep.contains(id));
        for (r, v) in missing.iter().zip(&vectors) {
            index.upsert(r.id.clone(), r.label.clone(), v)?;
        }
        let sync = Sync { added: missing.len(), dropped, rebuilt: false };
        if let Ok(mut t) = self.synced_at.lock() {
            *t = std::time::Instant::now();
        }
        if sync.added > 0 || sync.dropped > 0 || !self.index_dir.join("index.bin").exists() {
            index.save(&self.index_dir)?;
        }
        Ok(sync)
    }

    pub fn with_threshold(mut self, threshold: f32) -> Self {
        self.threshold = threshold;
        self
    }

    pub fn store(&self) -> &dyn AssetStore {
        self.store.as_ref()
    }

    /// Where the index is kept.
    pub fn index_dir(&self) -> &Path {
        &self.index_dir
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
        index.save(&self.index_dir)?;
        Ok(record)
    }

    /// Stores a part made offline, labelled with its prompt.
    pub fn add_part(&self, part: &GeneratedPart, label: &str) -> Result<AssetRecord, LibraryError> {
        let stl = stl_bytes_m(part);
        let s = part.report.size;
        let record = AssetRecord {
            id: AssetId::of(&stl),
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

    /// The stored asset that serves a request for `text` of size `size_m` (metres): the
    /// nearest label at or above the threshold whose stored size fits the request
    /// ([`crate::reuse`]); with no size, the nearest label at or above the threshold.
    pub fn lookup(&self, text: &str, size_m: Option<[f64; 3]>) -> Result<Option<Reuse>, LibraryError> {
        for hit in self.search(text, CANDIDATES)?.into_iter().filter(|h| h.score >= self.threshold) {
            let record = match self.store.record(&hit.id) {
                Ok(r) => r,
                // Gone since the index was synced (another process's store): skip it.
                Err(StoreError::NotFound(_)) => continue,
                Err(e) => return Err(e.into()),
            };
            let Some(wanted) = size_m else { return Ok(Some(Reuse { hit, record, fit: None })) };
            if let Some(fit) = size_fit(record.size_m, wanted).filter(SizeFit::fits) {
                return Ok(Some(Reuse { hit, record, fit: Some(fit) }));
            }
        }
        Ok(None)
    }
}
