#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue 20 in the layout (session 7): several things in front of one small loose thing
//! ("a bin and three trays in front of it": was the trays along the far wall, placed
//! before the bin), a bowl on each side of a cutting board on a table (was: on the board,
//! then the floor), a row in a room whose size was not given (was: folded into two rows).
//!
//! Every scene comes from a hand-built plan (the reader is not under test), is written,
//! verified (compiled and settled) in MuJoCo, and judged by the independent judge
//! (`bench/relations/judge.py`, reading the written `scene.xml` only) over three seeds.

mod common;

use common::plan;
use serde_json::{Value, json};
use sw_plan::ScenePlan;

fn check(name: &str, plan: &ScenePlan, line: Value) {
    common::assert_holds_on_three_seeds(name, plan, &line, "S7_LAYOUT_KEEP");
}

#[test]
fn three_trays_stand_in_front_of_one_bin() {
    let p = plan(
        "tabletop",
        [4.0, 4.0, 3.0],
        &[("bin", "bin", 1), ("trays", "tray", 3)],
        json!([{"subject": "trays", "relation": "in_front_of", "target": "bin"}]),
        json!([]),
    );
    let line = json!({"counts": {"bin": 1, "tray": 3}, "robots": {}, "relations": [
        {"subject": "tray", "relation": "in_front_of", "target": "bin"}]});
    check("trays-before-bin", &p, line);
}

#[test]
fn a_bowl_on_each_side_of_the_cutting_board_on_the_table() {
    let p = plan(
        "kitchen",
        [5.0, 4.0, 2.7],
        &[("table", "table", 1), ("board", "cutting_board", 1), ("bowls", "bowl", 2)],
        json!([
            {"subject": "board", "relation": "on", "target": "table"},
            {"subject": "bowls", "relation": "on_each_side_of", "target": "board"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"table": 1, "cutting_board": 1, "bowl": 2}, "robots": {}, "relations": [
        {"subject": "cutting_board", "relation": "on", "target": "table"},
        {"subject": "bowl", "relation": "on", "target": "table"},
        {"subject": "bowl", "relation": "on_each_side_of", "target": "cutting_board"}]});
    check("bowls-by-board", &p, line);
}

#[test]
fn a_row_grows_a_room_of_no_stated_size() {
    let mut p = plan(
        "workshop",
        [6.0, 5.0, 3.0],
        &[("benches", "workbench", 8)],
        json!([{"subject": "benches", "relation": "in_row"}]),
        json!([]),
    );
    p.room.size_fixed = false;
    let line = json!({"counts": {"workbench": 8}, "robots": {}, "relations": [
        {"subject": "workbench", "relation": "in_row"}]});
    check("bench-row", &p, line);
}
