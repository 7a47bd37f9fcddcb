//! LeRobot v3.0 datasets on disk, written here with arrow-rs's parquet writer and
//! Debian's `ffmpeg` (no Python at run time):
//!
//! ```text
//! DIR/meta/info.json                          codebase_version "v3.0", fps, features
//! DIR/meta/stats.json                         per feature: min max mean std count q01…q99
//! DIR/meta/tasks.parquet                      task string (index) → task_index
//! DIR/meta/episodes/chunk-000/file-000.parquet one row per episode
//! DIR/data/chunk-CCC/file-FFF.parquet         one file per episode (episode = CCC·1000 + FFF)
//! DIR/videos/<key>/chunk-CCC/file-FFF.mp4     one file per camera and episode
//! ```
//!
//! A file per episode is what makes a dataset resumable after kill -9 without rewriting
//! what was written: data and video files are made under temporary names and renamed into
//! place; the metadata is derived from the episodes' records and rewritten whole.

pub mod data;
pub mod meta;
pub mod stats;
pub mod video;

use std::io::Write as _;
use std::path::{Path, PathBuf};

pub use data::{Column, EpisodePlace, write_episode};
pub use meta::{DatasetInfo, Dtype, EpisodeRecord, FeatureSpec, write_meta};
pub use stats::FeatureStats;
pub use video::VideoWriter;

/// The format version written into `info.json`.
pub const CODEBASE_VERSION: &str = "v3.0";
/// Files per chunk directory.
pub const CHUNK_SIZE: u64 = 1000;
pub const DATA_PATH: &str = "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet";
pub const VIDEO_PATH: &str = "videos/{video_key}/chunk-{chunk_index:03d}/file-{file_index:03d}.mp4";

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LeRobotError {
    #[error("{0}")]
    Io(String),
    #[error("parquet: {0}")]
    Data(String),
    #[error("video: {0}")]
    Video(String),
}

/// The (chunk, file) of episode `index`.
pub fn chunk_file(index: u64) -> (u64, u64) {
    (index / CHUNK_SIZE, index % CHUNK_SIZE)
}

/// `data/chunk-CCC/file-FFF.parquet` of episode `index`.
pub fn data_path(root: &Path, index: u64) -> PathBuf {
    let (c, f) = chunk_file(index);
    root.join(format!("data/chunk-{c:03}/file-{f:03}.parquet"))
}

/// `videos/<key>/chunk-CCC/file-FFF.mp4` of episode `index`.
pub fn video_path(root: &Path, key: &str, index: u64) -> PathBuf {
    let (c, f) = chunk_file(index);
    root.join(format!("videos/{key}/chunk-{c:03}/file-{f:03}.mp4"))
}

/// Writes `path` through a temporary sibling renamed over it.
pub fn write_atomically(path: &Path, text: &str) -> Result<(), LeRobotError> {
    let io = |e: std::io::Error| LeRobotError::Io(format!("{}: {e}", path.display()));
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(io)?;
    }
    let tmp = path.with_extension(format!("partial-{}", std::process::id()));
    {
        let mut f = std::fs::File::create(&tmp).map_err(io)?;
        f.write_all(text.as_bytes()).map_err(io)?;
        f.sync_all().map_err(io)?;
    }
    std::fs::rename(&tmp, path).map_err(io)
}
