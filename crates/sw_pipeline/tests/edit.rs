//! Natural-language edits of packages: each kind of operation with references, what is
//! not changed stays exactly where it was, the history is kept in edits.json, every
//! edited scene is verified in MuJoCo, and a failed edit leaves the package byte for
//! byte as it was.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;
use std::path::Path;

use sw_pipeline::{EditReader, Options, edit_package, generate};
use sw_plan::{AssetCache, EditLog, LaidOutScene, PlacedObject, Status, Support};

const PROMPT: &str = "a 10 by 8 m warehouse with a conveyor, a table with four boxes on it, three chairs next to the conveyor, a red cabinet and a shelf against the north wall";

fn scene(dir: &Path, name: &str) -> std::path::PathBuf {
    let out = dir.join(name);
    let o = generate(PROMPT, &out, &Options::default(), &mut |_| {}).unwrap();
    assert_eq!(o.report.status, Status::Verified);
    // Offline, every group's assets come from the catalog: all hits.
    assert_eq!(o.report.asset_cache, AssetCache { hits: o.plan.objects.len() as u32, misses: 0 });
    out
}

fn layout(dir: &Path) -> LaidOutScene {
    serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json")).unwrap()).unwrap()
}

fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    for e in walk(dir) {
        let rel = e.strip_prefix(dir).unwrap().display().to_string();
        out.insert(rel, std::fs::read(&e).unwrap());
    }
    out
}

fn walk(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            v.extend(walk(&p));
        } else {
            v.push(p);
        }
    }
    v
}

fn edit(dir: &Path, cmd: &str) -> sw_pipeline::EditOutcome {
    let o = edit_package(dir, cmd, EditReader::Grammar, None, &mut |_| {}).unwrap_or_else(|e| panic!("{cmd}: {e}"));
    assert_eq!(o.report.status, Status::Verified, "{cmd}: {:?}", o.report.verification.as_ref().map(|v| &v.failures));
    o
}

/// Objects present before and after, except `changed`, stand exactly where they stood.
fn unchanged_except(before: &LaidOutScene, after: &LaidOutScene, changed: &[String]) {
    for o in &before.objects {
        if changed.contains(&o.name) {
            continue;
        }
        let a: Option<&PlacedObject> = after.object(&o.name);
        assert_eq!(a, Some(o), "{} changed", o.name);
    }
    for r in &before.robots {
        assert!(after.robots.contains(r), "{} changed", r.name);
    }
}

fn rides_on(l: &LaidOutScene, host: &str) -> Vec<String> {
    l.objects
        .iter()
        .filter(|o| matches!(&o.support, Support::Object { object, .. } if object == host))
        .map(|o| o.name.clone())
        .collect()
}

#[test]
fn remove_with_a_reference_keeps_everything_else_in_place() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s");
    let before = layout(&dir);
    let o = edit(&dir, "remove the chair nearest to the conveyor");
    assert_eq!(o.record.removed.len(), 1);
    let gone = &o.record.removed[0];
    assert!(gone.starts_with("chair_"), "{gone}");
    let after = layout(&dir);
    assert!(after.object(gone).is_none());
    unchanged_except(&before, &after, &o.record.removed);
    assert_eq!(after.objects.len(), before.objects.len() - 1);
    let log: EditLog = serde_json::from_str(&std::fs::read_to_string(dir.join("edits.json")).unwrap()).unwrap();
    assert_eq!(log.edits.len(), 1);
    assert_eq!(log.edits[0].command, "remove the chair nearest to the conveyor");
    assert_eq!(log.edits[0].understood_by, "grammar");
    // The plan now asks for two chairs.
    let chairs: u32 = o.plan.objects.iter().filter(|g| g.category == "chair").map(|g| g.count).sum();
    assert_eq!(chairs, 2);
}

#[test]
fn add_move_rotate_resize_recolour_replace_in_sequence() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s");

    // add, next to something
    let before = layout(&dir);
    let o = edit(&dir, "add two red chairs next to the conveyor");
    assert_eq!(o.record.added.len(), 2, "{:?}", o.record);
    let after = layout(&dir);
    unchanged_except(&before, &after, &[]);
    for n in &o.record.added {
        assert!(after.object(n).is_some());
    }
    assert!(o.plan.objects.iter().any(|g| g.color.as_ref().is_some_and(|c| c.name == "red") && g.category == "chair"));

    // move by a distance: the table and what is on it
    let before = layout(&dir);
    let table = before.objects.iter().find(|x| x.category == "table").unwrap().clone();
    let boxes = rides_on(&before, &table.name);
    assert_eq!(boxes.len(), 4);
    // The first direction with room (the door is south: right is east, forward north).
    let (delta, _) = [([0.5, 0.0], "right"), ([-0.5, 0.0], "left"), ([0.0, 0.5], "forward"), ([0.0, -0.5], "back")]
        .into_iter()
        .find(|(_, d)| {
            edit_package(&dir, &format!("move the table 50 cm {d}"), EditReader::Grammar, None, &mut |_| {}).is_ok()
        })
        .expect("the table can move somewhere");
    let after = layout(&dir);
    let t2 = after.object(&table.name).unwrap();
    assert!(
        (t2.pos[0] - table.pos[0] - delta[0]).abs() < 1e-6 && (t2.pos[1] - table.pos[1] - delta[1]).abs() < 1e-6,
        "{t2:?}"
    );
    for b in &boxes {
        let (x0, x1) = (before.object(b).unwrap(), after.object(b).unwrap());
        assert!(
            (x1.pos[0] - x0.pos[0] - delta[0]).abs() < 1e-6 && (x1.pos[1] - x0.pos[1] - delta[1]).abs() < 1e-6,
            "{b} rode along"
        );
    }
    let mut changed = boxes.clone();
    changed.push(table.name.clone());
    unchanged_except(&before, &after, &changed);

    // rotate
    let before = layout(&dir);
    edit(&dir, "rotate the table 90 degrees");
    let after = layout(&dir);
    let t3 = after.object(&table.name).unwrap();
    assert!((t3.pos[0] - before.object(&table.name).unwrap().pos[0]).abs() < 1e-9);
    unchanged_except(&before, &after, &changed);

    // recolour: geometry and pose unchanged
    let before = layout(&dir);
    let o = edit(&dir, "paint the red cabinet blue");
    let after = layout(&dir);
    unchanged_except(&before, &after, &[]);
    assert_eq!(o.record.modified.len(), 1);
    assert!(
        o.plan.objects.iter().any(|g| g.category == "cabinet" && g.color.as_ref().is_some_and(|c| c.name == "blue"))
    );

    // resize
    let before = layout(&dir);
    let o = edit(&dir, "make the shelf 20% shorter");
    let shelf = &o.record.modified[0];
    let after = layout(&dir);
    assert!(after.object(shelf).unwrap().size[2] < before.object(shelf).unwrap().size[2] * 0.85);
    let riders: Vec<String> = rides_on(&before, shelf);
    let mut changed = riders.clone();
    changed.push(shelf.clone());
    unchanged_except(&before, &after, &changed);

    // replace
    let before = layout(&dir);
    let conveyor = before.objects.iter().find(|x| x.category == "conveyor").unwrap().name.clone();
    let o = edit(&dir, "replace the conveyor with a workbench");
    let after = layout(&dir);
    assert!(after.object(&conveyor).is_none());
    assert!(o.record.added.iter().any(|n| n.starts_with("workbench")));
    unchanged_except(&before, &after, &[conveyor]);
    let _ = o;

    // delete all
    let o = edit(&dir, "delete all boxes");
    assert_eq!(o.record.removed.len(), 4);
    let log: EditLog = serde_json::from_str(&std::fs::read_to_string(dir.join("edits.json")).unwrap()).unwrap();
    assert_eq!(log.edits.iter().map(|e| e.number).collect::<Vec<_>>(), vec![1, 2, 3, 4, 5, 6, 7]);
}

#[test]
fn relational_moves_use_the_solver_and_keep_the_rest() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s");
    let before = layout(&dir);
    let o = edit(&dir, "move the second chair against the east wall");
    let after = layout(&dir);
    let moved = &o.record.moved;
    unchanged_except(&before, &after, moved);
    let c = after.object(&moved[0]).unwrap();
    let hw = after.room.size.width / 2.0;
    assert!(c.pos[0] > hw - 1.0, "{c:?} is against the east wall");
    // next to another object, placed here
    let o = edit(&dir, "move the cabinet next to the table");
    let cab = layout(&dir).object(&o.record.moved[0]).unwrap().clone();
    let table = layout(&dir).objects.iter().find(|x| x.category == "table").unwrap().clone();
    let d = (cab.pos[0] - table.pos[0]).hypot(cab.pos[1] - table.pos[1]);
    assert!(d < 2.5, "the cabinet is {d} m from the table");
}

#[test]
fn a_failed_edit_leaves_the_package_byte_for_byte() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s");
    std::fs::write(dir.join("notes.txt"), "mine").unwrap();
    let before = files(&dir);
    for (cmd, needle) in [
        ("remove the unicorn", "nothing in the scene is"),
        ("remove the chair", "could be any of chair_1, chair_2, chair_3"),
        ("move the table 40 m to the left", "cannot move there"),
        ("make the desk sparkle", "does not understand"),
        ("paint the cabinet plaid", "colour"),
        ("add a forklift on the moon", "nothing in the scene is"),
    ] {
        let e = edit_package(&dir, cmd, EditReader::Grammar, None, &mut |_| {}).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{cmd}: {e}");
        assert!(e.to_string().contains(needle), "{cmd}: {e}");
        assert_eq!(files(&dir), before, "{cmd} changed the package");
    }
    // Nothing left beside it either.
    let names: Vec<String> =
        std::fs::read_dir(tmp.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert_eq!(names, vec!["s".to_string()]);
    // A successful edit keeps the user's files.
    edit(&dir, "remove chair_1");
    assert_eq!(std::fs::read_to_string(dir.join("notes.txt")).unwrap(), "mine");
}

#[test]
fn robots_can_be_added_and_removed() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s");
    let before = layout(&dir);
    let o = edit(&dir, "add a UR5e next to the conveyor");
    let after = layout(&dir);
    assert_eq!(after.robots.len(), 1, "{:?}", o.record);
    unchanged_except(&before, &after, &[]);
    let o = edit(&dir, "remove the robot");
    assert!(o.record.removed.iter().any(|n| n.starts_with("ur5e")));
    assert!(layout(&dir).robots.is_empty());
}

mod with_an_llm {
    use std::time::Duration;

    use sw_llm::{Client, Endpoint, LlmConfig, LlmStage};
    use sw_mockllm::{MockServer, Reply, script};

    use super::*;

    fn client(server: &MockServer) -> Client {
        let mut e = Endpoint::new(server.base_url(), "m-edit");
        e.timeout = Duration::from_millis(800);
        e.backoff = Duration::from_millis(5);
        e.max_backoff = Duration::from_millis(20);
        e.max_retries = 1;
        Client::new(LlmConfig::offline().with(LlmStage::Edit, e))
    }

    #[test]
    fn what_the_grammar_does_not_read_goes_to_the_llm() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = scene(tmp.path(), "s");
        let server = MockServer::start(|_| {
            Reply::answer(r#"{"ops": [{"op": "remove", "target": {"noun": "cabinet"}}, {"op": "rotate", "target": {"noun": "table"}, "degrees": 180}]}"#)
        })
        .unwrap();
        let c = client(&server);
        let o = edit_package(
            &dir,
            "I'd rather not have the cabinet, and spin the table round",
            EditReader::GrammarThenLlm,
            Some(&c),
            &mut |_| {},
        )
        .unwrap();
        assert_eq!(o.report.status, Status::Verified);
        assert_eq!(o.record.understood_by, "llm");
        assert_eq!(o.record.llm_calls.len(), 1);
        assert!(o.record.removed.iter().any(|n| n.starts_with("cabinet")));
        // The model saw the scene's names and the command as data.
        let user: serde_json::Value = serde_json::from_str(&server.requests()[0].last_user()).unwrap();
        assert!(user["scene"]["objects"].as_array().unwrap().iter().any(|o| o["name"] == "table_1"));
        assert_eq!(server.requests()[0].response_format().as_deref(), Some("json_schema"));
        // A command the grammar reads does not call the model.
        edit_package(&dir, "remove chair_1", EditReader::GrammarThenLlm, Some(&c), &mut |_| {}).unwrap();
        assert_eq!(server.requests().len(), 1);
    }

    #[test]
    fn unusable_or_unreachable_llms_leave_the_package_as_it_was() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = scene(tmp.path(), "s");
        let before = files(&dir);
        let cases: Vec<(Reply, i32)> = vec![
            (Reply::answer("Sure, I removed it for you!"), 2),
            (Reply::answer(r#"{"ops": [{"op": "explode", "target": {"noun": "table"}}]}"#), 2),
            (
                Reply::answer(
                    r#"{"ops": [{"op": "move", "target": {"noun": "table"}, "to": {"kind": "shift", "east": 1e9}}]}"#,
                ),
                2,
            ),
            (Reply::answer(r#"{"ops": [{"op": "remove", "target": {"noun": "spaceship"}}]}"#), 2),
            // The model failing is the model's failure (exit 3), not an internal error.
            (Reply::status(500, "down"), 3),
            (Reply::Hang(Duration::from_secs(30)), 3),
        ];
        for (reply, code) in cases {
            let server = MockServer::start(script(vec![reply.clone()])).unwrap();
            let e = edit_package(
                &dir,
                "tidy the place up a bit",
                EditReader::GrammarThenLlm,
                Some(&client(&server)),
                &mut |_| {},
            )
            .unwrap_err();
            assert_eq!(e.exit_code(), code, "{reply:?}: {e}");
            assert_eq!(files(&dir), before, "{reply:?} changed the package");
        }
    }
}
