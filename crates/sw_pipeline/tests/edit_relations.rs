//! An edit keeps the scene's relation checks: the stated relations are measured again on
//! the edited, written scene (report.json on disk and the outcome alike), never dropped —
//! for a sentence and for a structured edit from the viewer.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;

use sw_pipeline::{EditReader, Options, StructuredEdit, edit_package, edit_structured, generate};
use sw_plan::{Report, Status};

const PROMPT: &str = "a 10 by 8 m workshop with a table with four boxes on it, three chairs next to the table and a shelf against the north wall";

fn report_on_disk(dir: &Path) -> Report {
    serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap()
}

/// (subject, relation and targets as JSON) of each check: what was stated.
fn stated(r: &Report) -> Vec<String> {
    let mut v: Vec<String> = r.relations.iter().map(|c| serde_json::to_string(&c.relation).unwrap()).collect();
    v.sort();
    v
}

#[test]
fn edits_measure_the_stated_relations_again() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("scene");
    let o = generate(PROMPT, &dir, &Options::default(), &mut |_| {}).unwrap();
    assert_eq!(o.report.status, Status::Verified);
    let before = stated(&o.report);
    assert!(before.len() >= 3, "the prompt states relations: {before:?}");
    assert!(o.report.relations.iter().all(|c| c.held), "{:?}", o.report.relations);

    // A sentence that adds an object with a relation of its own.
    let e = edit_package(&dir, "add a chair next to the table", EditReader::Grammar, None, &mut |_| {}).unwrap();
    assert_eq!(e.report.status, Status::Verified);
    let on_disk = report_on_disk(&dir);
    assert_eq!(stated(&on_disk), stated(&e.report), "report.json is the outcome's report");
    let after = stated(&on_disk);
    for r in &before {
        assert!(after.contains(r), "the edit dropped {r}: {after:?}");
    }
    assert!(after.len() > before.len(), "the added chair's relation is measured too: {after:?}");
    assert!(on_disk.relations.iter().all(|c| c.held), "{:?}", on_disk.relations);
    // Measured on the written scene: every check carries its measurements.
    assert!(on_disk.relations.iter().all(|c| !c.measured.is_empty()), "{:?}", on_disk.relations);

    // A structured edit (the viewer's drag): the checks stay, and say whether they hold.
    let shelf = e.layout.objects.iter().find(|o| o.category == "shelf").unwrap().name.clone();
    let moved = edit_structured(
        &dir,
        &StructuredEdit::Move { object: shelf, pos: [0.0, 0.0], yaw_deg: None },
        "move the shelf",
        &mut |_| {},
    );
    let m = moved.unwrap();
    let r = report_on_disk(&dir);
    // The shelf moved by hand is no longer said to be against the wall (the move takes its
    // place in the room from the user); every other stated relation is measured still.
    let wall: Vec<&String> = after.iter().filter(|x| x.contains("\"shelf\"") && x.contains("against_wall")).collect();
    assert_eq!(wall.len(), 1, "{after:?}");
    let kept: Vec<String> = after.iter().filter(|x| !wall.contains(x)).cloned().collect();
    assert_eq!(stated(&r), kept, "{:?}", m.record);
    assert!(r.relations.iter().all(|c| c.held && !c.measured.is_empty()), "{:?}", r.relations);
}
