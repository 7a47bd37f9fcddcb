#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue 20's placements through the pipeline from hand-built plans (the reader emits
//! them separately): each scene is written, verified in MuJoCo and judged by the
//! independent judge (`bench/relations/judge.py`, the written `scene.xml` only), over
//! several seeds; the report's own measurement must agree.

mod common;

use common::{Expect, plan};
use serde_json::{Value, json};
use sw_plan::ScenePlan;

fn run(name: &str, plan: &ScenePlan, line: &Value, seeds: &[u64]) -> Vec<String> {
    common::run(name, plan, line, seeds, "PLACEMENTS_KEEP", Expect { sizes_and_room: true, ..Expect::default() })
}

fn check(name: &str, plan: &ScenePlan, line: Value) {
    let f = run(name, plan, &line, &[1, 2, 3]);
    assert!(f.is_empty(), "{} failures:\n{}", f.len(), f.join("\n"));
}

#[test]
fn a_sink_and_a_hob_are_set_into_the_counter_run() {
    let p = plan(
        "kitchen",
        [5.0, 4.0, 2.7],
        &[("counter", "counter", 1), ("sink", "sink", 1), ("hob", "stove", 1), ("fridge", "fridge", 1)],
        json!([
            {"subject": "counter", "relation": "against_wall", "wall": "north"},
            {"subject": "sink", "relation": "set_into", "target": "counter"},
            {"subject": "hob", "relation": "set_into", "target": "counter"},
            {"subject": "fridge", "relation": "in_corner"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"counter": 1, "sink": 1, "stove": 1, "fridge": 1}, "robots": {}, "room_size_m": [5, 4],
        "relations": [
            {"subject": "sink", "relation": "set_into", "target": "counter"},
            {"subject": "stove", "relation": "set_into", "target": "counter"},
            {"subject": "counter", "relation": "against_wall", "wall": "north"}]});
    check("kitchen-run", &p, line);
}

#[test]
fn bins_stand_at_both_ends_of_a_conveyor_and_a_crate_at_its_start() {
    let p = plan(
        "factory",
        [12.0, 8.0, 4.0],
        &[("conveyor", "conveyor", 1), ("bins", "bin", 2), ("crate", "crate", 1)],
        json!([
            {"subject": "bins", "relation": "at_end_of", "target": "conveyor", "end": "both"},
            {"subject": "crate", "relation": "at_end_of", "target": "conveyor", "end": "start"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"conveyor": 1, "bin": 2, "crate": 1}, "robots": {}, "relations": [
        {"subject": "bin", "relation": "at_end_of", "target": "conveyor", "end": "both"},
        {"subject": "crate", "relation": "at_end_of", "target": "conveyor", "end": "start"}]});
    check("conveyor-ends", &p, line);
}

#[test]
fn chairs_flank_a_desk_a_lamp_sits_on_its_edge_and_a_sofa_faces_the_whiteboard() {
    let p = plan(
        "office",
        [7.0, 6.0, 3.0],
        &[
            ("desk", "desk", 1),
            ("chairs", "chair", 2),
            ("lamp", "desk_lamp", 1),
            ("sofa", "sofa", 1),
            ("board", "whiteboard", 1),
        ],
        json!([
            {"subject": "chairs", "relation": "on_each_side_of", "target": "desk"},
            {"subject": "lamp", "relation": "on_edge_of", "target": "desk"},
            {"subject": "board", "relation": "against_wall", "wall": "north"},
            {"subject": "sofa", "relation": "facing", "target": "board"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"desk": 1, "chair": 2, "desk_lamp": 1, "sofa": 1, "whiteboard": 1}, "robots": {}, "relations": [
        {"subject": "chair", "relation": "on_each_side_of", "target": "desk"},
        {"subject": "desk_lamp", "relation": "on_edge_of", "target": "desk"},
        {"subject": "sofa", "relation": "facing", "target": "whiteboard"}]});
    check("office-sides", &p, line);
}

#[test]
fn walls_corners_and_back_to_back() {
    let p = plan(
        "warehouse",
        [14.0, 9.0, 5.0],
        &[("shelves", "shelf", 4), ("plants", "potted_plant", 4), ("desks", "desk", 4)],
        json!([
            {"subject": "shelves", "relation": "on_opposite_walls", "long": true},
            {"subject": "plants", "relation": "in_corners"},
            {"subject": "desks", "relation": "back_to_back"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"shelf": 4, "potted_plant": 4, "desk": 4}, "robots": {}, "relations": [
        {"subject": "shelf", "relation": "on_opposite_walls", "long": true},
        {"subject": "potted_plant", "relation": "in_corners"},
        {"subject": "desk", "relation": "back_to_back"}]});
    check("walls-corners", &p, line);
}

#[test]
fn rows_of_a_stated_length_and_stacks_of_a_stated_height() {
    let p = plan(
        "classroom",
        [10.0, 8.0, 3.0],
        &[("desks", "desk", 10), ("crates", "crate", 12)],
        json!([
            {"subject": "desks", "relation": "in_rows", "m": 4},
            {"subject": "crates", "relation": "stacked", "n": 4, "stacks": 3}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"desk": 10, "crate": 12}, "robots": {}, "relations": [
        {"subject": "desk", "relation": "in_rows", "n": 3, "m": 4},
        {"subject": "crate", "relation": "stacked", "n": 4, "stacks": 3}]});
    check("rows-stacks", &p, line);
}

#[test]
fn things_go_inside_bins_and_under_a_workbench() {
    let p = plan(
        "workshop",
        [8.0, 6.0, 3.0],
        &[("bench", "workbench", 1), ("crate", "crate", 1), ("bin", "bin", 1), ("cans", "drink_can", 3)],
        json!([
            {"subject": "crate", "relation": "under", "target": "bench"},
            {"subject": "cans", "relation": "inside", "target": "bin"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"workbench": 1, "crate": 1, "bin": 1, "drink_can": 3}, "robots": {}, "relations": [
        {"subject": "crate", "relation": "under", "target": "workbench"},
        {"subject": "drink_can", "relation": "inside", "target": "bin"}]});
    check("inside-under", &p, line);
}

#[test]
fn two_arms_on_opposite_sides_of_a_bench_reach_the_bins_between_them() {
    // Three bins in a line between two arms need a bench longer than the catalog's 1.5 m:
    // "a 2.4 m workbench" (on a shorter one the third bin stays within reach, off the line,
    // and the report says so).
    let mut p = plan(
        "workshop",
        [8.0, 6.0, 3.0],
        &[("bench", "workbench", 1), ("bins", "bin", 3)],
        json!([
            {"subject": "arms", "relation": "on_each_side_of", "target": "bench"},
            {"subject": "bins", "relation": "between", "first": "arms", "second": "arms"}
        ]),
        json!([{"id": "arms", "model": "ur5e", "phrase": "two UR5e arms", "count": 2, "mount": {"mount": "auto"}}]),
    );
    p.objects[0].size.explicit.length = Some(2.4);
    let line = json!({"counts": {"workbench": 1, "bin": 3}, "robots": {"ur5e": 2}, "relations": [
        {"subject": "ur5e", "relation": "on_each_side_of", "target": "workbench"},
        {"subject": "bin", "relation": "on", "target": "workbench"},
        {"subject": "bin", "relation": "between", "target": "ur5e"},
        {"subject": "ur5e", "relation": "reach", "target": "bin"},
        {"subject": "ur5e", "relation": "reach", "target": "workbench"}]});
    check("two-arms", &p, line);
}

#[test]
fn an_arm_on_the_edge_of_a_table_stands_on_it_and_reaches_its_items() {
    let p = plan(
        "tabletop",
        [4.0, 4.0, 3.0],
        &[("table", "table", 1), ("cubes", "cube", 3)],
        json!([
            {"subject": "arm", "relation": "on_edge_of", "target": "table"},
            {"subject": "cubes", "relation": "on", "target": "table"}
        ]),
        json!([{"id": "arm", "model": "panda", "phrase": "a Panda", "count": 1, "mount": {"mount": "auto"}}]),
    );
    let line = json!({"counts": {"table": 1, "cube": 3}, "robots": {"panda": 1}, "relations": [
        {"subject": "panda", "relation": "on_edge_of", "target": "table"},
        {"subject": "panda", "relation": "on", "target": "table"},
        {"subject": "panda", "relation": "reach", "target": "cube"}]});
    check("arm-edge", &p, line);
}

#[test]
fn a_stated_length_is_kept() {
    let mut p = plan("factory", [12.0, 8.0, 4.0], &[("belt", "conveyor", 1)], json!([]), json!([]));
    p.objects[0].size.explicit.length = Some(4.5);
    let line = json!({"counts": {"conveyor": 1}, "robots": {}, "relations": [
        {"subject": "conveyor", "relation": "size", "dims": {"length": [4.05, 4.95]}}]});
    check("stated-length", &p, line);
}

#[test]
fn nightstands_flank_a_bed_and_plates_sit_on_each_side_of_a_table() {
    let p = plan(
        "room",
        [5.0, 4.0, 2.7],
        &[("bed", "hospital_bed", 1), ("stands", "cabinet", 2), ("table", "dining_table", 1), ("plates", "plate", 2)],
        json!([
            {"subject": "bed", "relation": "against_wall", "wall": "west"},
            {"subject": "stands", "relation": "on_each_side_of", "target": "bed"},
            {"subject": "plates", "relation": "on_each_side_of", "target": "table"}
        ]),
        json!([]),
    );
    let line = json!({"counts": {"hospital_bed": 1, "cabinet": 2, "dining_table": 1, "plate": 2}, "robots": {}, "relations": [
        {"subject": "cabinet", "relation": "on_each_side_of", "target": "hospital_bed"},
        {"subject": "plate", "relation": "on_each_side_of", "target": "dining_table"},
        {"subject": "plate", "relation": "on", "target": "dining_table"}]});
    check("bed-table-sides", &p, line);
}

#[test]
fn two_pandas_on_either_side_of_a_table_share_its_items() {
    let p = plan(
        "tabletop",
        [4.0, 4.0, 3.0],
        &[("table", "table", 1), ("cubes", "cube", 4)],
        json!([
            {"subject": "pandas", "relation": "on_each_side_of", "target": "table"},
            {"subject": "cubes", "relation": "on", "target": "table"}
        ]),
        json!([{"id": "pandas", "model": "panda", "phrase": "two Pandas", "count": 2, "mount": {"mount": "auto"}}]),
    );
    let line = json!({"counts": {"table": 1, "cube": 4}, "robots": {"panda": 2}, "relations": [
        {"subject": "panda", "relation": "on_each_side_of", "target": "table"},
        {"subject": "panda", "relation": "reach", "target": "cube"},
        {"subject": "panda", "relation": "reach", "target": "table"}]});
    check("two-pandas", &p, line);
}

/// From a prompt: the offline reader's plan through the pipeline, judged as above.
fn check_prompt(name: &str, prompt: &str, line: Value) {
    let p = sw_planner::plan(prompt).unwrap_or_else(|e| panic!("{prompt:?}: {e}"));
    let f = run(name, &p, &line, &[1, 2, 3]);
    assert!(f.is_empty(), "{prompt:?}: {} failures:\n{}", f.len(), f.join("\n"));
}

#[test]
fn arms_said_to_be_on_opposite_sides_stand_on_opposite_sides_and_reach_the_bins() {
    check_prompt(
        "prompt-two-arms",
        "put two UR5e arms on opposite sides of a 2.4 m workbench with three bins between them",
        json!({"counts": {"workbench": 1, "bin": 3}, "robots": {"ur5e": 2}, "relations": [
            {"subject": "ur5e", "relation": "on_each_side_of", "target": "workbench"},
            {"subject": "bin", "relation": "between", "target": "ur5e"},
            {"subject": "ur5e", "relation": "reach", "target": "bin"}]}),
    );
}

#[test]
fn things_placed_by_a_mounted_arm_rest_on_its_table_within_reach() {
    check_prompt(
        "prompt-arm-work",
        "A TABLE, A PANDA ON THE TABLE, 3 BLOCKS NEXT TO THE PANDA",
        json!({"counts": {"table": 1, "cube": 3}, "robots": {"panda": 1}, "relations": [
            {"subject": "panda", "relation": "on", "target": "table"},
            {"subject": "cube", "relation": "on", "target": "table"},
            {"subject": "panda", "relation": "reach", "target": "cube"}]}),
    );
}

#[test]
fn two_arms_at_the_ends_of_a_table_both_reach_what_lies_between_them() {
    check_prompt(
        "prompt-two-ends",
        "two Pandas on a 2 m table with a cube between them",
        json!({"counts": {"table": 1, "cube": 1}, "robots": {"panda": 2}, "relations": [
            {"subject": "panda", "relation": "on", "target": "table"},
            {"subject": "cube", "relation": "on", "target": "table"},
            {"subject": "cube", "relation": "between", "target": "panda"},
            {"subject": "panda", "relation": "reach", "target": "cube"}]}),
    );
}

#[test]
fn a_small_thing_beside_something_on_the_counter_is_on_the_counter() {
    check_prompt(
        "prompt-shared-support",
        "kitchen with a toaster on the counter and a plate next to it",
        json!({"counts": {"counter": 1, "toaster": 1, "plate": 1}, "robots": {}, "relations": [
            {"subject": "toaster", "relation": "on", "target": "counter"},
            {"subject": "plate", "relation": "on", "target": "counter"},
            {"subject": "plate", "relation": "next_to", "target": "toaster"}]}),
    );
}
