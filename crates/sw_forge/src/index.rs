//! The semantic index: one unit vector per stored asset (its label embedded), searched
//! by brute-force cosine similarity — 10,000 assets × 384 dimensions is 3.8 M
//! multiply-adds, a few milliseconds, with no approximate structure to tune or rebuild.
//! Persisted as `index.bin` (magic, dimension, count, little-endian f32 rows) and
//! `index.json` (the id and label of each row), written atomically.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::store::AssetId;

/// The cosine similarity at and above which a query reuses a stored asset, tuned on
/// `bench/forge/label_pairs.tsv` (see BENCHMARKS.md).
pub const DEFAULT_THRESHOLD: f32 = 0.55;

/// The file's magic, with the version of the vectors it holds: bumped whenever the
/// embedder's vectors change (002: the tokenizer fixed for non-ASCII input and 256-token
/// inputs), so an index of older vectors fails to load and the library rebuilds it from
/// the store.
const MAGIC: &[u8; 8] = b"SWIDX002";

/// One indexed asset.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    pub id: AssetId,
    pub label: String,
}

/// A search result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Hit {
    pub id: AssetId,
    pub label: String,
    /// Cosine similarity, −1…1.
    pub score: f32,
}

/// Why the index could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum IndexError {
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    #[error("{path}: not an index file ({message})")]
    Format { path: String, message: String },
    #[error("a vector has {got} dimensions, the index {want}")]
    Dimension { got: usize, want: usize },
}

fn io(path: &Path, e: impl std::fmt::Display) -> IndexError {
    IndexError::Io { path: path.display().to_string(), message: e.to_string() }
}

/// Vectors and their assets.
#[derive(Debug, Clone, PartialEq)]
pub struct SemanticIndex {
    dim: usize,
    entries: Vec<Entry>,
    vectors: Vec<f32>,
}

impl SemanticIndex {
    pub fn new(dim: usize) -> Self {
        Self { dim, entries: Vec::new(), vectors: Vec::new() }
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    pub fn dim(&self) -> usize {
        self.dim
    }

    pub fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// Adds (or replaces, by id) an asset's vector; it is normalised here.
    pub fn upsert(&mut self, id: AssetId, label: String, vector: &[f32]) -> Result<(), IndexError> {
        if vector.len() != self.dim {
            return Err(IndexError::Dimension { got: vector.len(), want: self.dim });
        }
        let norm = vector.iter().map(|x| x * x).sum::<f32>().sqrt().max(1e-12);
        let v: Vec<f32> = vector.iter().map(|x| x / norm).collect();
        if let Some(i) = self.entries.iter().position(|e| e.id == id) {
            self.entries[i].label = label;
            self.vectors[i * self.dim..(i + 1) * self.dim].copy_from_slice(&v);
        } else {
            self.entries.push(Entry { id, label });
            self.vectors.extend(v);
        }
        Ok(())
    }

    /// Keeps the assets `keep` says yes to; returns how many were dropped.
    pub fn retain(&mut self, mut keep: impl FnMut(&AssetId) -> bool) -> usize {
        let before = self.entries.len();
        let mut entries = Vec::with_capacity(before);
        let mut vectors = Vec::with_capacity(self.vectors.len());
        for (e, row) in self.entries.drain(..).zip(self.vectors.chunks_exact(self.dim)) {
            if keep(&e.id) {
                entries.push(e);
                vectors.extend_from_slice(row);
            }
        }
        self.entries = entries;
        self.vectors = vectors;
        before - self.entries.len()
    }

    /// The `k` most similar assets to a unit query vector, best first.
    pub fn search(&self, query: &[f32], k: usize) -> Result<Vec<Hit>, IndexError> {
        if query.len() != self.dim {
            return Err(IndexError::Dimension { got: query.len(), want: self.dim });
        }
        let mut best: Vec<(f32, usize)> = Vec::with_capacity(k + 1);
        for (i, row) in self.vectors.chunks_exact(self.dim).enumerate() {
            let s: f32 = row.iter().zip(query).map(|(a, b)| a * b).sum();
            if best.len() < k || best.last().is_some_and(|(w, _)| s > *w) {
                let at = best.partition_point(|(b, _)| *b >= s);
                best.insert(at, (s, i));
                best.truncate(k);
            }
        }
        Ok(best
            .into_iter()
            .map(|(score, i)| Hit { id: self.entries[i].id.clone(), label: self.entries[i].label.clone(), score })
            .collect())
    }

    /// Writes `index.bin` and `index.json` into `dir`.
    pub fn save(&self, dir: &Path) -> Result<(), IndexError> {
        fs_err::create_dir_all(dir).map_err(|e| io(dir, e))?;
        let mut bin = Vec::with_capacity(16 + self.vectors.len() * 4);
        bin.extend_from_slice(MAGIC);
        bin.extend_from_slice(&(self.dim as u32).to_le_bytes());
        bin.extend_from_slice(&(self.entries.len() as u32).to_le_bytes());
        for x in &self.vectors {
            bin.extend_from_slice(&x.to_le_bytes());
        }
        let json = serde_json::to_vec(&self.entries).map_err(|e| io(dir, e))?;
        for (name, bytes) in [("index.bin", bin), ("index.json", json)] {
            let path = dir.join(name);
            let mut tmp = tempfile::NamedTempFile::new_in(dir).map_err(|e| io(dir, e))?;
            std::io::Write::write_all(&mut tmp, &bytes).map_err(|e| io(&path, e))?;
            tmp.persist(&path).map_err(|e| io(&path, e.error))?;
        }
        Ok(())
    }

    /// Reads an index saved by [`SemanticIndex::save`]; an empty one when there is none.
    pub fn load(dir: &Path, dim: usize) -> Result<Self, IndexError> {
        let bin_path = dir.join("index.bin");
        if !bin_path.exists() {
            return Ok(Self::new(dim));
        }
        let bin = fs_err::read(&bin_path).map_err(|e| io(&bin_path, e))?;
        let bad = |m: &str| IndexError::Format { path: bin_path.display().to_string(), message: m.to_string() };
        if bin.len() < 16 || &bin[..8] != MAGIC {
            return Err(bad("bad magic"));
        }
        let word =
            |at: usize| -> usize { u32::from_le_bytes([bin[at], bin[at + 1], bin[at + 2], bin[at + 3]]) as usize };
        let (d, n) = (word(8), word(12));
        if d != dim {
            return Err(IndexError::Dimension { got: d, want: dim });
        }
        if bin.len() != 16 + d * n * 4 {
            return Err(bad("truncated"));
        }
        let vectors: Vec<f32> =
            bin[16..].chunks_exact(4).map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
        let json_path = dir.join("index.json");
        let json = fs_err::read(&json_path).map_err(|e| io(&json_path, e))?;
        let entries: Vec<Entry> = serde_json::from_slice(&json)
            .map_err(|e| IndexError::Format { path: json_path.display().to_string(), message: e.to_string() })?;
        if entries.len() != n {
            return Err(bad("the labels and the vectors disagree in number"));
        }
        Ok(Self { dim, entries, vectors })
    }
}

/// Precision and recall of "reuse when the score ≥ threshold" on labelled pairs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ThresholdPoint {
    pub threshold: f32,
    pub precision: f64,
    pub recall: f64,
    pub f1: f64,
    pub true_pos: usize,
    pub false_pos: usize,
    pub false_neg: usize,
}

/// Precision, recall and F1 at `threshold` over (score, is a match) pairs.
pub fn evaluate(pairs: &[(f32, bool)], threshold: f32) -> ThresholdPoint {
    let tp = pairs.iter().filter(|(s, m)| *m && *s >= threshold).count();
    let fp = pairs.iter().filter(|(s, m)| !*m && *s >= threshold).count();
    let fneg = pairs.iter().filter(|(s, m)| *m && *s < threshold).count();
    let precision = if tp + fp == 0 { 1.0 } else { tp as f64 / (tp + fp) as f64 };
    let recall = if tp + fneg == 0 { 1.0 } else { tp as f64 / (tp + fneg) as f64 };
    let f1 = if precision + recall == 0.0 { 0.0 } else { 2.0 * precision * recall / (precision + recall) };
    ThresholdPoint { threshold, precision, recall, f1, true_pos: tp, false_pos: fp, false_neg: fneg }
}

/// Every threshold from 0.30 to 0.95 in steps of 0.01.
pub fn sweep(pairs: &[(f32, bool)]) -> Vec<ThresholdPoint> {
    (30..=95).map(|t| evaluate(pairs, t as f32 / 100.0)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_nearest_and_round_trips_through_disk() {
        let mut idx = SemanticIndex::new(3);
        idx.upsert(AssetId::of(b"x"), "x".into(), &[1.0, 0.0, 0.0]).unwrap();
        idx.upsert(AssetId::of(b"y"), "y".into(), &[0.0, 2.0, 0.0]).unwrap();
        idx.upsert(AssetId::of(b"xy"), "xy".into(), &[1.0, 1.0, 0.0]).unwrap();
        let hits = idx.search(&[0.0, 1.0, 0.0], 2).unwrap();
        assert_eq!(hits[0].label, "y");
        assert!((hits[0].score - 1.0).abs() < 1e-6);
        assert_eq!(hits[1].label, "xy");
        idx.upsert(AssetId::of(b"y"), "y again".into(), &[0.0, 0.0, 1.0]).unwrap();
        assert_eq!(idx.len(), 3);
        let mut fewer = idx.clone();
        assert_eq!(fewer.retain(|id| *id != AssetId::of(b"x")), 1);
        assert_eq!(fewer.search(&[1.0, 0.0, 0.0], 1).unwrap()[0].label, "xy");
        let dir = tempfile::tempdir().unwrap();
        idx.save(dir.path()).unwrap();
        let back = SemanticIndex::load(dir.path(), 3).unwrap();
        assert_eq!(back, idx);
        assert!(SemanticIndex::load(dir.path(), 4).is_err());
        assert!(idx.search(&[1.0], 1).is_err());
        std::fs::write(dir.path().join("index.bin"), b"garbage").unwrap();
        assert!(SemanticIndex::load(dir.path(), 3).is_err());
    }
}
