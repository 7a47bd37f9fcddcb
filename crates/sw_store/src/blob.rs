//! The blob store holding packages: keys are relative paths (`scenes/<id>/scene.xml`).
//! A local directory by default; an S3-compatible store implements the same trait.

use std::path::{Path, PathBuf};

/// A blob store problem.
#[derive(Debug, thiserror::Error)]
pub enum BlobError {
    /// The key is not a safe relative path.
    #[error("bad blob key '{0}': {1}")]
    BadKey(String, &'static str),
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

/// Where packages live. Synchronous: callers run it on a blocking thread.
pub trait BlobStore: Send + Sync + std::fmt::Debug {
    /// Writes a blob atomically (readers see the old or the new bytes, never a part).
    fn put(&self, key: &str, data: &[u8]) -> Result<(), BlobError>;
    /// Reads a blob; `None` if it does not exist.
    fn get(&self, key: &str) -> Result<Option<Vec<u8>>, BlobError>;
    /// Removes every blob under `prefix` (a directory-like key ending in `/`).
    fn delete_prefix(&self, prefix: &str) -> Result<(), BlobError>;
}

/// Checks that a key is a relative path of plain segments: no `..`, `.`, empty segments,
/// backslashes, NULs or a leading `/`. Every key a request names passes through here.
pub fn check_key(key: &str) -> Result<(), BlobError> {
    let bad = |why| Err(BlobError::BadKey(key.chars().take(200).collect(), why));
    if key.is_empty() || key.len() > 1024 {
        return bad("empty or longer than 1024 bytes");
    }
    if key.starts_with('/') {
        return bad("absolute");
    }
    if key.contains('\\') || key.contains('\0') {
        return bad("holds a backslash or NUL");
    }
    for seg in key.trim_end_matches('/').split('/') {
        if seg.is_empty() || seg == "." || seg == ".." {
            return bad("has an empty, '.' or '..' segment");
        }
    }
    Ok(())
}

/// Blobs as files under a directory.
#[derive(Debug, Clone)]
pub struct LocalBlobs {
    root: PathBuf,
}

impl LocalBlobs {
    pub fn new(root: impl Into<PathBuf>) -> Result<Self, BlobError> {
        let root = root.into();
        fs_err::create_dir_all(&root)?;
        Ok(Self { root })
    }

    pub fn root(&self) -> &Path {
        &self.root
    }

    fn path(&self, key: &str) -> Result<PathBuf, BlobError> {
        check_key(key)?;
        Ok(self.root.join(key.trim_end_matches('/')))
    }
}

impl BlobStore for LocalBlobs {
    fn put(&self, key: &str, data: &[u8]) -> Result<(), BlobError> {
        let path = self.path(key)?;
        if let Some(parent) = path.parent() {
            fs_err::create_dir_all(parent)?;
        }
        let tmp = path.with_file_name(format!(".{}.tmp-{}", crate::new_id(), std::process::id()));
        // A write that fails (a full disk) leaves no partial file behind to fill it further.
        if let Err(e) = fs_err::write(&tmp, data).and_then(|()| fs_err::rename(&tmp, &path)) {
            let _ = std::fs::remove_file(&tmp);
            return Err(e.into());
        }
        Ok(())
    }

    fn get(&self, key: &str) -> Result<Option<Vec<u8>>, BlobError> {
        let path = self.path(key)?;
        match std::fs::read(&path) {
            Ok(b) => Ok(Some(b)),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            // A directory is not a blob.
            Err(e) if path.is_dir() => {
                let _ = e;
                Ok(None)
            }
            Err(e) => Err(e.into()),
        }
    }

    fn delete_prefix(&self, prefix: &str) -> Result<(), BlobError> {
        let path = self.path(prefix)?;
        match std::fs::remove_dir_all(&path) {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
            Err(e) => Err(e.into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_that_escape_are_refused() {
        for k in ["../x", "a/../../b", "/etc/passwd", "a//b", "a\\b", "./a", "a/\0", ""] {
            assert!(check_key(k).is_err(), "{k:?} should be refused");
        }
        for k in ["scenes/abc/scene.xml", "scenes/abc/assets/robots/ur5e/base.stl", "scenes/abc/"] {
            assert!(check_key(k).is_ok(), "{k:?} should be allowed");
        }
    }
}
