//! The asset store: meshes and their metadata, addressed by the SHA-256 of the mesh
//! bytes. [`AssetStore`] is the interface; [`LocalStore`] keeps objects in a directory:
//! `objects/<first two hex>/<hash>.stl` and `<hash>.json`, each written to a temporary
//! file and renamed into place, so a reader never sees half an object;
//! [`S3Store`](crate::store_s3::S3Store) keeps the same keys in an S3-compatible bucket.
//! [`open_store`] picks one from a location (a path, or `s3://bucket/prefix`).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

/// The content address of a mesh: 64 lower-case hex digits of its SHA-256.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(transparent)]
pub struct AssetId(String);

impl AssetId {
    pub fn of(bytes: &[u8]) -> Self {
        let digest = Sha256::digest(bytes);
        Self(digest.iter().map(|b| format!("{b:02x}")).collect())
    }

    /// Reads an id (or a unique prefix is resolved by the store, not here).
    pub fn parse(s: &str) -> Result<Self, StoreError> {
        let s = s.trim();
        if s.len() == 64 && s.bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase()) {
            Ok(Self(s.to_string()))
        } else {
            Err(StoreError::BadId(s.chars().take(80).collect()))
        }
    }

    pub fn as_str(&self) -> &str {
        &self.0
    }

    pub fn short(&self) -> &str {
        &self.0[..12]
    }
}

impl std::fmt::Display for AssetId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// What is known about a stored asset.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AssetRecord {
    pub id: AssetId,
    /// What it is ("flat washer 20 mm"), the text the semantic index embeds.
    pub label: String,
    /// The prompt or description it was made from.
    pub description: String,
    /// How it was made: `template:<name>`, `llm:<model>`, `catalog:<category>`, `proxy`.
    pub source: String,
    /// Bounding box, metres.
    pub size_m: [f64; 3],
    pub triangles: usize,
    /// The CAD code, when there is some.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub code: Option<String>,
    /// Anything else (validation numbers, timings).
    #[serde(default, skip_serializing_if = "serde_json::Value::is_null")]
    pub extra: serde_json::Value,
}

/// Why the store failed.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("'{0}' is not an asset id (64 hex digits)")]
    BadId(String),
    #[error("no asset {0} in the store")]
    NotFound(String),
    #[error("asset id prefix '{0}' matches more than one asset")]
    Ambiguous(String),
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    #[error("{path}: the stored mesh does not match its id (corrupt object)")]
    Corrupt { path: String },
    #[error("'{0}' is not an asset store location (a directory, or s3://bucket/prefix)")]
    BadLocation(String),
}

fn io(path: &Path, e: impl std::fmt::Display) -> StoreError {
    StoreError::Io { path: path.display().to_string(), message: e.to_string() }
}

/// Meshes and metadata by content address.
pub trait AssetStore: Send + Sync {
    /// Stores a mesh (binary STL bytes) and its record; the id is the mesh's hash. Putting
    /// the same mesh again replaces the record and keeps the mesh.
    fn put(&self, stl: &[u8], record: AssetRecord) -> Result<AssetRecord, StoreError>;
    fn record(&self, id: &AssetId) -> Result<AssetRecord, StoreError>;
    /// The mesh bytes, checked against the id.
    fn mesh(&self, id: &AssetId) -> Result<Vec<u8>, StoreError>;
    fn list(&self) -> Result<Vec<AssetId>, StoreError>;
    /// Where the store is (a directory, `s3://bucket/prefix/`), for messages and for
    /// naming a local cache of its index.
    fn location(&self) -> String;
    /// The one id that starts with `prefix` (at least 4 hex digits).
    fn resolve(&self, prefix: &str) -> Result<AssetId, StoreError> {
        let p = prefix.trim().to_ascii_lowercase();
        if p.len() < 4 || !p.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Err(StoreError::BadId(prefix.chars().take(80).collect()));
        }
        let hits: Vec<AssetId> = self.list()?.into_iter().filter(|id| id.as_str().starts_with(&p)).collect();
        match hits.len() {
            0 => Err(StoreError::NotFound(p)),
            1 => Ok(hits.into_iter().next().ok_or(StoreError::NotFound(p))?),
            _ => Err(StoreError::Ambiguous(p)),
        }
    }
}

/// A store in a local directory.
#[derive(Debug, Clone)]
pub struct LocalStore {
    root: PathBuf,
}

impl LocalStore {
    /// Opens (creating) a store at `root`.
    pub fn open(root: impl Into<PathBuf>) -> Result<Self, StoreError> {
        let root = root.into();
        fs_err::create_dir_all(root.join("objects")).map_err(|e| io(&root, e))?;
        Ok(Self { root })
    }

    pub fn root(&self) -> &Path {
        &self.root
    }

    fn path(&self, id: &AssetId, ext: &str) -> PathBuf {
        self.root.join("objects").join(&id.as_str()[..2]).join(format!("{}.{ext}", id.as_str()))
    }

    fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), StoreError> {
        let dir = path.parent().ok_or_else(|| io(path, "no parent directory"))?;
        fs_err::create_dir_all(dir).map_err(|e| io(dir, e))?;
        let mut tmp = tempfile::NamedTempFile::new_in(dir).map_err(|e| io(dir, e))?;
        std::io::Write::write_all(&mut tmp, bytes).map_err(|e| io(path, e))?;
        tmp.persist(path).map_err(|e| io(path, e.error))?;
        Ok(())
    }
}

impl AssetStore for LocalStore {
    fn put(&self, stl: &[u8], mut record: AssetRecord) -> Result<AssetRecord, StoreError> {
        let id = AssetId::of(stl);
        record.id = id.clone();
        let mesh = self.path(&id, "stl");
        if !mesh.is_file() {
            Self::write_atomic(&mesh, stl)?;
        }
        let json = serde_json::to_vec_pretty(&record).map_err(|e| io(&mesh, e))?;
        Self::write_atomic(&self.path(&id, "json"), &json)?;
        Ok(record)
    }

    fn record(&self, id: &AssetId) -> Result<AssetRecord, StoreError> {
        let p = self.path(id, "json");
        let bytes = match fs_err::read(&p) {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(StoreError::NotFound(id.to_string())),
            Err(e) => return Err(io(&p, e)),
        };
        serde_json::from_slice(&bytes).map_err(|e| io(&p, e))
    }

    fn mesh(&self, id: &AssetId) -> Result<Vec<u8>, StoreError> {
        let p = self.path(id, "stl");
        let bytes = match fs_err::read(&p) {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(StoreError::NotFound(id.to_string())),
            Err(e) => return Err(io(&p, e)),
        };
        if AssetId::of(&bytes) != *id {
            return Err(StoreError::Corrupt { path: p.display().to_string() });
        }
        Ok(bytes)
    }

    fn list(&self) -> Result<Vec<AssetId>, StoreError> {
        let objects = self.root.join("objects");
        let mut ids = Vec::new();
        for shard in fs_err::read_dir(&objects).map_err(|e| io(&objects, e))? {
            let shard = shard.map_err(|e| io(&objects, e))?.path();
            if !shard.is_dir() {
                continue;
            }
            for f in fs_err::read_dir(&shard).map_err(|e| io(&shard, e))? {
                let f = f.map_err(|e| io(&shard, e))?.path();
                if f.extension().is_some_and(|e| e == "json")
                    && let Some(id) = f.file_stem().and_then(|s| s.to_str()).and_then(|s| AssetId::parse(s).ok())
                {
                    ids.push(id);
                }
            }
        }
        ids.sort();
        Ok(ids)
    }

    fn location(&self) -> String {
        self.root.display().to_string()
    }
}

/// The store at `location`: `s3://bucket/prefix` (endpoint and credentials from the
/// environment, see [`sw_s3::S3Config::from_env`]) or a local directory (created).
pub fn open_store(location: &str) -> Result<std::sync::Arc<dyn AssetStore>, StoreError> {
    if location.starts_with("s3://") {
        Ok(std::sync::Arc::new(crate::store_s3::S3Store::open_url(location)?))
    } else if location.contains("://") || location.trim().is_empty() {
        Err(StoreError::BadLocation(location.to_string()))
    } else {
        Ok(std::sync::Arc::new(LocalStore::open(location)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(label: &str) -> AssetRecord {
        AssetRecord {
            id: AssetId::of(b""),
            label: label.into(),
            description: label.into(),
            source: "test".into(),
            size_m: [0.1, 0.1, 0.1],
            triangles: 12,
            code: None,
            extra: serde_json::Value::Null,
        }
    }

    #[test]
    fn objects_are_addressed_by_content_and_checked_on_read() {
        let dir = tempfile::tempdir().unwrap();
        let store = LocalStore::open(dir.path()).unwrap();
        let a = store.put(b"mesh a", record("a")).unwrap();
        let b = store.put(b"mesh b", record("b")).unwrap();
        let again = store.put(b"mesh a", record("a, relabelled")).unwrap();
        assert_eq!(a.id, again.id);
        assert_ne!(a.id, b.id);
        assert_eq!(store.list().unwrap().len(), 2);
        assert_eq!(store.record(&a.id).unwrap().label, "a, relabelled");
        assert_eq!(store.mesh(&b.id).unwrap(), b"mesh b");
        assert_eq!(store.resolve(&a.id.as_str()[..8]).unwrap(), a.id);
        // A corrupted object is refused, not served.
        std::fs::write(store.path(&b.id, "stl"), b"tampered").unwrap();
        assert!(matches!(store.mesh(&b.id), Err(StoreError::Corrupt { .. })));
        assert!(matches!(store.record(&AssetId::of(b"nothing")), Err(StoreError::NotFound(_))));
        assert!(AssetId::parse("../../etc/passwd").is_err());
        assert!(store.resolve("zz").is_err());
    }
}
