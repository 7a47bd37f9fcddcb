//! Scratch space for the packages runners are making, cleaned up after processes that died.
//!
//! Several processes (a `serve` and any number of `scenewright worker`s) may share one work
//! root. Each process that runs jobs owns a directory `ROOT/NAME/` (its jobs' scratch
//! directories live inside) and a lock file `ROOT/NAME.lock` that it holds locked (`flock`)
//! for as long as it lives. The kernel drops the lock when the process dies, however it
//! dies (kill -9 included), so at start a process removes every directory whose lock it can
//! take: its owner is gone. A live process's lock cannot be taken, and its directory stays.
//!
//! The lock file is made, locked and checked before its directory exists, and removed only
//! after its directory is gone; so a directory without a lock file next to it has no owner
//! (scratch of an older version, or a removal cut short) and is removed too.

use std::fs::{File, OpenOptions, TryLockError};
use std::io;
use std::path::{Path, PathBuf};

/// What [`sweep`] could not tell or remove.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {source}")]
pub struct ScratchError {
    pub path: String,
    pub source: io::Error,
}

fn at(path: &Path) -> impl FnOnce(io::Error) -> ScratchError + '_ {
    move |source| ScratchError { path: path.display().to_string(), source }
}

/// This process's scratch directory, removed when dropped (a graceful stop).
#[derive(Debug)]
pub struct ProcessScratch {
    dir: PathBuf,
    lock_path: PathBuf,
    /// Held locked while the value lives; dropped (unlocked) after the files are removed.
    _lock: File,
}

impl ProcessScratch {
    /// Claims `root/name/` for this process (`name` must be unique to it, e.g. the pid
    /// with a random suffix).
    pub fn claim(root: &Path, name: &str) -> Result<Self, ScratchError> {
        std::fs::create_dir_all(root).map_err(at(root))?;
        let lock_path = root.join(format!("{name}.lock"));
        let lock =
            OpenOptions::new().read(true).write(true).create_new(true).open(&lock_path).map_err(at(&lock_path))?;
        match lock.try_lock() {
            Ok(()) => {}
            // Another process's sweep holds it for a moment: it saw a lock file nobody held
            // yet and is removing it. The name is spent.
            Err(TryLockError::WouldBlock) => {
                let e = io::Error::new(io::ErrorKind::WouldBlock, "taken by a concurrent cleanup; try again");
                return Err(at(&lock_path)(e));
            }
            Err(TryLockError::Error(e)) => return Err(at(&lock_path)(e)),
        }
        // A sweep may have locked and removed the file between its creation and our lock.
        if !still_named(&lock, &lock_path) {
            let e = io::Error::new(io::ErrorKind::NotFound, "removed by a concurrent cleanup; try again");
            return Err(at(&lock_path)(e));
        }
        let dir = root.join(name);
        std::fs::create_dir(&dir).map_err(at(&dir))?;
        Ok(Self { dir, lock_path, _lock: lock })
    }

    /// Claims a directory, retrying with a fresh name when a concurrent cleanup took one.
    pub fn claim_unique(root: &Path, name: &str) -> Result<Self, ScratchError> {
        let mut last = None;
        for attempt in 0..5 {
            let candidate = if attempt == 0 { name.to_string() } else { format!("{name}-{attempt}") };
            match Self::claim(root, &candidate) {
                Ok(s) => return Ok(s),
                Err(e) if matches!(e.source.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::NotFound) => {
                    last = Some(e);
                }
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| at(root)(io::Error::other("no scratch directory could be claimed"))))
    }

    /// Where this process's jobs make their scratch directories.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}

impl Drop for ProcessScratch {
    fn drop(&mut self) {
        // The directory first, then the lock file, while still holding the lock.
        if let Err(e) = remove_dir(&self.dir) {
            tracing::warn!(dir = %self.dir.display(), error = %e, "removing this process's scratch failed");
        }
        let _ = std::fs::remove_file(&self.lock_path);
    }
}

/// Whether `path` still names the open file `file` (not removed, not replaced).
fn still_named(file: &File, path: &Path) -> bool {
    match (file.metadata(), std::fs::metadata(path)) {
        (Ok(a), Ok(b)) => same_file(&a, &b),
        _ => false,
    }
}

#[cfg(unix)]
fn same_file(a: &std::fs::Metadata, b: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    a.dev() == b.dev() && a.ino() == b.ino()
}

#[cfg(not(unix))]
fn same_file(a: &std::fs::Metadata, b: &std::fs::Metadata) -> bool {
    a.len() == b.len() && a.modified().ok() == b.modified().ok()
}

/// Removes a directory tree; one that is already gone (another sweep got there first) is fine.
fn remove_dir(dir: &Path) -> io::Result<()> {
    match std::fs::remove_dir_all(dir) {
        Err(e) if e.kind() != io::ErrorKind::NotFound => Err(e),
        _ => Ok(()),
    }
}

/// Removes the scratch of processes that are gone from `root`; returns the directories
/// removed. Scratch of live processes (their lock is held) is left alone. A file system
/// without locks leaves everything in place (with a warning): no owner can be told apart.
pub fn sweep(root: &Path) -> Result<Vec<PathBuf>, ScratchError> {
    let mut removed = Vec::new();
    let entries = match std::fs::read_dir(root) {
        Ok(e) => e,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(removed),
        Err(e) => return Err(at(root)(e)),
    };
    let mut locks = Vec::new();
    let mut dirs = Vec::new();
    for entry in entries {
        let entry = entry.map_err(at(root))?;
        let path = entry.path();
        let Ok(kind) = entry.file_type() else { continue };
        let name = entry.file_name().to_string_lossy().into_owned();
        if kind.is_dir() {
            dirs.push(path);
        } else if let Some(owner) = name.strip_suffix(".lock") {
            locks.push((path.clone(), root.join(owner)));
        }
    }
    for (lock_path, dir) in locks {
        let file = match OpenOptions::new().read(true).write(true).open(&lock_path) {
            Ok(f) => f,
            Err(e) if e.kind() == io::ErrorKind::NotFound => continue,
            Err(e) => return Err(at(&lock_path)(e)),
        };
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => continue,
            Err(TryLockError::Error(e)) if e.kind() == io::ErrorKind::Unsupported => {
                tracing::warn!(root = %root.display(), "the file system has no locks; stale scratch is not removed");
                return Ok(removed);
            }
            Err(TryLockError::Error(e)) => return Err(at(&lock_path)(e)),
        }
        // Its owner is gone (or another sweep removed it a moment ago).
        if still_named(&file, &lock_path) {
            remove_dir(&dir).map_err(at(&dir))?;
            match std::fs::remove_file(&lock_path) {
                Err(e) if e.kind() != io::ErrorKind::NotFound => return Err(at(&lock_path)(e)),
                _ => removed.push(dir),
            }
        }
    }
    for dir in dirs {
        let mut lock_name = dir.file_name().unwrap_or_default().to_os_string();
        lock_name.push(".lock");
        if !root.join(lock_name).exists() && !removed.contains(&dir) {
            remove_dir(&dir).map_err(at(&dir))?;
            removed.push(dir);
        }
    }
    Ok(removed)
}
