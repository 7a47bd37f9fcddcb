#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The semantic index with the real embedder (all-MiniLM-L6-v2 on candle): similar labels
//! score above the reuse threshold, unrelated ones below, and a library reuses what it
//! stored. Needs `scripts/setup.sh --cad` or `--tests` (the model in `.cache/minilm`); fails, never skips.

use std::sync::OnceLock;

use sw_forge::embed::{DIM, MiniLm};
use sw_forge::index::{DEFAULT_THRESHOLD, evaluate};
use sw_forge::library::{AssetLibrary, Sync};
use sw_forge::store::{AssetId, AssetRecord, AssetStore, LocalStore};

fn model() -> &'static MiniLm {
    static M: OnceLock<MiniLm> = OnceLock::new();
    M.get_or_init(|| MiniLm::load_default().unwrap_or_else(|e| panic!("{e}")))
}

fn cos(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

#[test]
fn vectors_are_unit_length_and_batching_does_not_change_them() {
    let texts = ["shelving unit", "a very long description of a grey steel storage rack with five levels"];
    let batch = model().embed(&texts).unwrap();
    assert_eq!(batch.len(), 2);
    for (t, v) in texts.iter().zip(&batch) {
        assert_eq!(v.len(), DIM);
        assert!((cos(v, v) - 1.0).abs() < 1e-4);
        // Alone (no padding) and in a padded batch: the same vector.
        let alone = model().embed(&[t]).unwrap().remove(0);
        assert!(cos(v, &alone) > 0.9999, "{t}: padding changed the vector");
    }
}

#[test]
fn the_issue_examples_fall_on_either_side_of_the_threshold() {
    let v = model().embed(&["shelving unit", "storage rack", "shelf", "self-driving car"]).unwrap();
    let same = cos(&v[0], &v[1]);
    let different = cos(&v[2], &v[3]);
    assert!(same >= DEFAULT_THRESHOLD, "shelving unit ~ storage rack: {same}");
    assert!(different < DEFAULT_THRESHOLD, "shelf ~ self-driving car: {different}");
}

#[test]
fn the_labelled_pairs_are_separated_at_the_default_threshold() {
    let text = include_str!("../../../bench/forge/label_pairs.tsv");
    let rows: Vec<(&str, &str, bool)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let c: Vec<&str> = l.split('\t').collect();
            (c[0], c[1], c[2].trim() == "1")
        })
        .collect();
    assert!(rows.len() >= 200);
    let a: Vec<&str> = rows.iter().map(|r| r.0).collect();
    let b: Vec<&str> = rows.iter().map(|r| r.1).collect();
    let (va, vb) = (model().embed(&a).unwrap(), model().embed(&b).unwrap());
    let scored: Vec<(f32, bool)> = rows.iter().enumerate().map(|(i, r)| (cos(&va[i], &vb[i]), r.2)).collect();
    let p = evaluate(&scored, DEFAULT_THRESHOLD);
    assert!(p.precision >= 0.68 && p.recall >= 0.78, "{p:?}");
}

#[test]
fn a_library_stores_indexes_persists_and_reuses() {
    let dir = tempfile::tempdir().unwrap();
    let record = |label: &str| AssetRecord {
        id: AssetId::of(b""),
        label: label.into(),
        description: label.into(),
        source: "test".into(),
        size_m: [1.0, 0.5, 2.0],
        triangles: 12,
        code: None,
        extra: serde_json::Value::Null,
    };
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    let rack = lib.add(b"rack mesh", record("shelving unit")).unwrap();
    lib.add(b"mug mesh", record("coffee mug")).unwrap();
    lib.add(b"cone mesh", record("traffic cone")).unwrap();
    let hit = lib.lookup("storage rack", None).unwrap().expect("a shelving unit serves a storage rack");
    assert_eq!(hit.hit.id, rack.id);
    assert!(lib.lookup("self-driving car", None).unwrap().is_none());
    drop(lib);
    // Reopened from disk: the same index.
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    assert_eq!(lib.len(), 3);
    assert_eq!(lib.opened_with(), Sync::default());
    assert_eq!(lib.search("mug", 1).unwrap()[0].label, "coffee mug");
    assert_eq!(lib.store().mesh(&rack.id).unwrap(), b"rack mesh");
    assert!(lib.search("   ", 1).is_err());
}

fn record(label: &str, size_m: [f64; 3]) -> AssetRecord {
    AssetRecord {
        id: AssetId::of(b""),
        label: label.into(),
        description: label.into(),
        source: "test".into(),
        size_m,
        triangles: 12,
        code: None,
        extra: serde_json::Value::Null,
    }
}

#[test]
fn reuse_needs_a_size_that_fits_as_well_as_a_label() {
    let dir = tempfile::tempdir().unwrap();
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    let tall = lib.add(b"tall rack", record("shelving unit", [1.0, 0.5, 2.0])).unwrap();
    let low = lib.add(b"low rack", record("metal storage rack", [1.2, 0.4, 0.6])).unwrap();
    // A storage rack of the tall one's proportions, slightly smaller: the tall one, scaled.
    let r = lib.lookup("storage rack", Some([0.9, 0.45, 1.8])).unwrap().expect("fits");
    assert_eq!(r.record.id, tall.id);
    let fit = r.fit.unwrap();
    assert!((fit.overall - 0.9).abs() < 1e-9 && !fit.quarter_turn, "{fit:?}");
    // Asked for low and wide: only the low one fits.
    let r = lib.lookup("storage rack", Some([1.1, 0.4, 0.55])).unwrap().expect("the low one fits");
    assert_eq!(r.record.id, low.id);
    // Turned a quarter: still the tall one.
    let r = lib.lookup("storage rack", Some([0.5, 1.0, 2.0])).unwrap().expect("fits turned");
    assert_eq!(r.record.id, tall.id);
    assert!(r.fit.unwrap().quarter_turn);
    // Nothing stored has a car's proportions, whatever the label says.
    assert!(lib.lookup("storage rack", Some([4.5, 1.8, 1.5])).unwrap().is_none());
    assert!(lib.lookup("storage rack", Some([10.0, 5.0, 20.0])).unwrap().is_none(), "ten times larger");
}

#[test]
fn opening_brings_the_index_up_to_date_with_the_store() {
    let dir = tempfile::tempdir().unwrap();
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    let mug = lib.add(b"mug", record("coffee mug", [0.1, 0.1, 0.1])).unwrap();
    drop(lib);
    // Another process puts assets straight into the store and removes one.
    let store = LocalStore::open(dir.path()).unwrap();
    let cone = store.put(b"cone", record("traffic cone", [0.3, 0.3, 0.5])).unwrap();
    store.put(b"crate", record("wooden crate", [0.5, 0.4, 0.3])).unwrap();
    let shard = dir.path().join("objects").join(&mug.id.as_str()[..2]);
    std::fs::remove_file(shard.join(format!("{}.json", mug.id))).unwrap();
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    assert_eq!(lib.opened_with(), Sync { added: 2, dropped: 1, rebuilt: false });
    assert_eq!(lib.len(), 2);
    assert_eq!(lib.lookup("road cone", None).unwrap().unwrap().record.id, cone.id);
    assert!(lib.search("coffee mug", 2).unwrap().iter().all(|h| h.id != mug.id));
    // A fresh index is not re-read on every request; a stale one is.
    assert_eq!(lib.sync_if_older(std::time::Duration::from_secs(60)).unwrap(), None);
    assert_eq!(lib.sync_if_older(std::time::Duration::ZERO).unwrap(), Some(Sync::default()));
    drop(lib);
    // An index of an older embedder's vectors is rebuilt from the store.
    let mut bin = std::fs::read(dir.path().join("index.bin")).unwrap();
    bin[..8].copy_from_slice(b"SWIDX001");
    std::fs::write(dir.path().join("index.bin"), &bin).unwrap();
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    assert_eq!(lib.opened_with(), Sync { added: 2, dropped: 0, rebuilt: true });
    drop(lib);
    // A damaged index is rebuilt from the store, not fatal.
    std::fs::write(dir.path().join("index.bin"), b"garbage").unwrap();
    let lib = AssetLibrary::open(dir.path(), MiniLm::load_default().unwrap()).unwrap();
    assert_eq!(lib.opened_with(), Sync { added: 2, dropped: 0, rebuilt: true });
    assert_eq!(lib.lookup("road cone", None).unwrap().unwrap().record.id, cone.id);
}
