//! The dataset directory as a library: scenes made, committed and listed; what a kill can
//! leave (a half-made package, a package without its line, a line cut short, a duplicate)
//! repaired on open; directories that are not ours, other options, a second process and
//! an unwritable place refused with the path named. And the verifier's fast load gives the
//! verdict MuJoCo's own `from_xml` gives on the dataset's scenes.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeSet;
use std::path::Path;

use sw_pipeline::dataset::{DatasetDir, DatasetError, DatasetSpec};
use sw_pipeline::manifest::{ManifestEntry, fingerprint};

const PROMPT: &str = "a kitchen with a table, two chairs and two mugs on the table";

/// Makes every pending slot of `dir` as the CLI does: seeds in turn until a verified scene
/// whose fingerprint is new. Returns the entries committed.
fn fill(dir: &DatasetDir) -> Vec<ManifestEntry> {
    let mut seen: BTreeSet<String> = dir.entries().iter().map(|e| e.fingerprint.clone()).collect();
    let mut seed = 0u64;
    let mut out = Vec::new();
    for (p, k) in dir.pending() {
        let id = DatasetSpec::scene_id(p, k);
        loop {
            assert!(seed < 100, "no valid scene in 100 seeds");
            let work = dir.work_dir(&id, seed).unwrap();
            let opts = dir.spec().scene_options(None, seed);
            seed += 1;
            let made = sw_pipeline::generate(&dir.spec().prompts[p], &work, &opts, &mut |_| {}).unwrap();
            if !sw_pipeline::succeeded(&made.report) || !seen.insert(fingerprint(&work).unwrap()) {
                std::fs::remove_dir_all(&work).unwrap();
                continue;
            }
            out.push(dir.commit(&work, &id, None).unwrap());
            break;
        }
    }
    dir.sync().unwrap();
    out
}

fn manifest_ids(root: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(root.join("manifest.jsonl")).unwrap();
    assert!(text.ends_with('\n'));
    text.lines().map(|l| serde_json::from_str::<ManifestEntry>(l).unwrap().id).collect()
}

#[test]
fn scenes_are_listed_once_and_the_fast_load_keeps_every_verdict() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path().join("ds");
    let spec = DatasetSpec::new(vec![PROMPT.into()], 3);
    let (dir, resumed) = DatasetDir::open(&root, &spec).unwrap();
    assert_eq!(resumed, Default::default());
    let made = fill(&dir);
    assert_eq!(made.len(), 3);
    assert!(!root.join(".work").exists(), "an empty .work/ is left after sync");
    let fps: BTreeSet<&str> = made.iter().map(|e| e.fingerprint.as_str()).collect();
    assert_eq!(fps.len(), 3);
    for e in &made {
        let scene = root.join(&e.dir).join("scene.xml");
        let xml = std::fs::read_to_string(&scene).unwrap();
        assert!(xml.contains("builtin="), "{}: no built-in texture, the comparison would be empty", e.id);
        let opts = sw_sim::VerifyOptions::default();
        let fast = sw_sim::verify_file(&scene, &opts);
        assert!(fast.passed, "{}: {:?}", e.id, fast.failures);
        assert_eq!(fast, sw_sim::verify_file_full_load(&scene, &opts), "{}", e.id);
    }
    // A second process is refused while this one holds the directory.
    assert!(matches!(DatasetDir::open(&root, &spec), Err(DatasetError::Busy(_))));
    drop(dir);

    // Reopened: all listed, nothing pending, nothing rewritten.
    let before = std::fs::read(root.join("manifest.jsonl")).unwrap();
    let (dir, resumed) = DatasetDir::open(&root, &spec).unwrap();
    assert_eq!(resumed.listed, 3);
    assert!(dir.pending().is_empty());
    assert_eq!(std::fs::read(root.join("manifest.jsonl")).unwrap(), before);
    drop(dir);

    // Other options are refused, naming what differs; a larger count extends the dataset.
    let other = DatasetSpec { seed: 7, ..spec.clone() };
    let err = DatasetDir::open(&root, &other).unwrap_err();
    assert!(matches!(err, DatasetError::Mismatch { .. }) && err.to_string().contains("seed"), "{err}");
    let (dir, _) = DatasetDir::open(&root, &DatasetSpec::new(vec![PROMPT.into()], 4)).unwrap();
    assert_eq!(dir.pending(), vec![(0, 3)]);
    assert_eq!(dir.spec().count, 4);
}

#[test]
fn what_a_kill_leaves_is_repaired_on_open() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path().join("ds");
    let spec = DatasetSpec::new(vec![PROMPT.into()], 2);
    let (dir, _) = DatasetDir::open(&root, &spec).unwrap();
    let made = fill(&dir);
    drop(dir);
    let manifest = root.join("manifest.jsonl");
    let text = std::fs::read_to_string(&manifest).unwrap();
    let first_line_end = text.find('\n').unwrap() + 1;

    // Killed while writing the second line: half of it is on disk; its package is in place.
    std::fs::write(&manifest, &text[..first_line_end + 40]).unwrap();
    // A half-made package in .work/ and a hidden staging directory in scenes/.
    std::fs::create_dir_all(root.join(".work/0000-000001-seed9/assets")).unwrap();
    std::fs::create_dir_all(root.join("scenes/.0000-000001.partial-1-2")).unwrap();
    // A copy of scene 0 in a slot of its own: a duplicate, removed rather than listed.
    let dup = root.join("scenes/0000-000002");
    std::fs::create_dir(&dup).unwrap();
    for f in std::fs::read_dir(root.join("scenes/0000-000000")).unwrap().flatten() {
        if f.path().is_file() {
            std::fs::copy(f.path(), dup.join(f.file_name())).unwrap();
        } else {
            std::fs::create_dir(dup.join(f.file_name())).unwrap();
            for g in std::fs::read_dir(f.path()).unwrap().flatten() {
                std::fs::copy(g.path(), dup.join(f.file_name()).join(g.file_name())).unwrap();
            }
        }
    }
    let spec3 = DatasetSpec::new(vec![PROMPT.into()], 3);
    let (dir, r) = DatasetDir::open(&root, &spec3).unwrap();
    assert!(r.dropped_torn_line);
    assert_eq!((r.listed, r.adopted, r.removed_packages), (2, 1, 1), "{r:?}");
    assert_eq!(r.discarded_partial, 2, "{r:?}");
    assert!(!dup.exists() && !root.join(".work").exists());
    assert!(!root.join("scenes/.0000-000001.partial-1-2").exists());
    assert_eq!(manifest_ids(&root), ["0000-000000", "0000-000001"]);
    // The adopted line is the one the kill cut short, made again from the package.
    assert_eq!(dir.entries()[1], made[1]);
    assert_eq!(dir.pending(), vec![(0, 2)]);
    drop(dir);

    // A listed scene whose package is gone is made again, not kept as a dangling line.
    std::fs::remove_dir_all(root.join("scenes/0000-000000")).unwrap();
    let (dir, r) = DatasetDir::open(&root, &spec3).unwrap();
    assert_eq!((r.listed, r.missing_packages), (1, 1), "{r:?}");
    assert_eq!(manifest_ids(&root), ["0000-000001"]);
    assert_eq!(dir.pending(), vec![(0, 0), (0, 2)]);
}

#[test]
fn places_that_are_not_a_dataset_are_refused_untouched() {
    let tmp = tempfile::tempdir().unwrap();
    let spec = DatasetSpec::new(vec![PROMPT.into()], 1);
    // Someone else's directory.
    let photos = tmp.path().join("photos");
    std::fs::create_dir(&photos).unwrap();
    std::fs::write(photos.join("a.jpg"), b"x").unwrap();
    let err = DatasetDir::open(&photos, &spec).unwrap_err();
    assert!(matches!(err, DatasetError::Foreign(_)) && err.to_string().contains("photos"), "{err}");
    assert_eq!(std::fs::read_dir(&photos).unwrap().count(), 1);
    // A dataset.json that is not ours.
    let other = tmp.path().join("other");
    std::fs::create_dir(&other).unwrap();
    std::fs::write(other.join("dataset.json"), r#"{"format":"coco"}"#).unwrap();
    assert!(matches!(DatasetDir::open(&other, &spec), Err(DatasetError::Foreign(_))));
    // A file where the directory should be.
    let file = tmp.path().join("file");
    std::fs::write(&file, b"x").unwrap();
    assert!(matches!(DatasetDir::open(&file, &spec), Err(DatasetError::Foreign(_))));
    // A directory that cannot be created (under a regular file: unwritable even for root).
    let under = file.join("ds");
    let err = DatasetDir::open(&under, &spec).unwrap_err();
    assert!(matches!(err, DatasetError::Unwritable { .. }), "{err}");
    assert!(err.to_string().contains("file"), "{err}");
    assert_eq!(std::fs::read(&file).unwrap(), b"x");
}
