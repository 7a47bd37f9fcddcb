//! Structured edits from the viewer: an object dragged to a point lands there (kept inside
//! the room), what it would stand in is placed again around it, everything else stays
//! where it was; turning in place; items set on the surface under the point or on the
//! floor; catalog and generated parts placed at a point, the generated one kept across
//! later edits; refusals with a reason that leave the package byte for byte. Every edited
//! scene is verified in MuJoCo by the edit itself; footprints are checked here apart from
//! the edit's own geometry (rotated rectangles from layout.json, separating axes).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;
use std::path::Path;

use sw_pipeline::{EditReader, Options, PipelineError, StructuredEdit, edit_package, edit_structured, generate};
use sw_plan::{LaidOutScene, PlacedObject, Status, Support};

const PROMPT: &str = "a 10 by 8 m warehouse with a conveyor, a table with four boxes on it, three chairs next to the conveyor, a red cabinet and a shelf against the north wall";

fn scene(dir: &Path, name: &str, prompt: &str) -> std::path::PathBuf {
    let out = dir.join(name);
    let o = generate(prompt, &out, &Options::default(), &mut |_| {}).unwrap();
    assert_eq!(o.report.status, Status::Verified);
    out
}

fn layout(dir: &Path) -> LaidOutScene {
    serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json")).unwrap()).unwrap()
}

fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fn walk(dir: &Path, base: &Path, out: &mut BTreeMap<String, Vec<u8>>) {
        for e in std::fs::read_dir(dir).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, base, out);
            } else {
                out.insert(p.strip_prefix(base).unwrap().display().to_string(), std::fs::read(&p).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    out
}

fn apply(dir: &Path, e: &StructuredEdit) -> sw_pipeline::EditOutcome {
    let o = edit_structured(dir, e, "a test edit", &mut |_| {}).unwrap_or_else(|err| panic!("{e:?}: {err}"));
    assert_eq!(o.report.status, Status::Verified, "{:?}", o.report.verification.as_ref().map(|v| &v.failures));
    o
}

fn refused(dir: &Path, e: &StructuredEdit, says: &str) {
    let before = files(dir);
    match edit_structured(dir, e, "a refused edit", &mut |_| {}) {
        Err(PipelineError::Input(m)) => assert!(m.contains(says), "{m}"),
        other => panic!("{e:?} was not refused: {:?}", other.map(|o| o.record.operations)),
    }
    assert!(files(dir) == before, "a refused edit changed the package");
}

/// The footprint of a placed object: its recorded size turned by its yaw about its
/// position (the layout records the collision extent centred on the footprint).
fn corners(o: &PlacedObject) -> [[f64; 2]; 4] {
    let (hw, hd) = (o.size[0] / 2.0, o.size[1] / 2.0);
    let (s, c) = o.yaw.sin_cos();
    [[-hw, -hd], [hw, -hd], [hw, hd], [-hw, hd]].map(|[x, y]| [o.pos[0] + c * x - s * y, o.pos[1] + s * x + c * y])
}

/// Two rotated rectangles overlap by more than `slack` (separating axis test).
fn overlap(a: &PlacedObject, b: &PlacedObject, slack: f64) -> bool {
    let (pa, pb) = (corners(a), corners(b));
    for poly in [&pa, &pb] {
        for i in 0..4 {
            let (p, q) = (poly[i], poly[(i + 1) % 4]);
            let n = [q[1] - p[1], p[0] - q[0]];
            let len = n[0].hypot(n[1]);
            let n = [n[0] / len, n[1] / len];
            let proj = |pts: &[[f64; 2]; 4]| {
                let v: Vec<f64> = pts.iter().map(|x| x[0] * n[0] + x[1] * n[1]).collect();
                (v.iter().copied().fold(f64::INFINITY, f64::min), v.iter().copied().fold(f64::NEG_INFINITY, f64::max))
            };
            let (a0, a1) = proj(&pa);
            let (b0, b1) = proj(&pb);
            if a1 - slack <= b0 || b1 - slack <= a0 {
                return false;
            }
        }
    }
    true
}

/// `name` stands clear of every other floor object (the layout may tuck a chair under a
/// table, so only the moved object is checked).
fn stands_clear(l: &LaidOutScene, name: &str) {
    let a = l.object(name).unwrap();
    for b in l.objects.iter().filter(|o| o.support == Support::Floor && o.name != name) {
        assert!(!overlap(a, b, 0.01), "{} and {} overlap", a.name, b.name);
    }
}

/// A point at least `r` from every object, inside the room.
fn free_spot(l: &LaidOutScene, r: f64) -> [f64; 2] {
    let (w, d) = (l.room.size.width / 2.0 - 0.8, l.room.size.depth / 2.0 - 0.8);
    let mut k = 0.0;
    while k <= 1.0 {
        for p in [[-w, -d], [w, -d], [-w, d], [w, d], [0.0, -d], [0.0, d], [-w, 0.0], [w, 0.0]] {
            let p = [p[0] * (1.0 - k), p[1] * (1.0 - k)];
            if l.objects.iter().all(|o| (o.pos[0] - p[0]).hypot(o.pos[1] - p[1]) > r) {
                return p;
            }
        }
        k += 0.1;
    }
    panic!("no free spot in the scene");
}

#[test]
fn a_dragged_object_lands_there_and_what_it_stands_in_is_placed_again() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s", PROMPT);
    let before = layout(&dir);
    let cabinet = before.objects.iter().find(|o| o.category == "cabinet").unwrap().clone();
    let conveyor = before.objects.iter().find(|o| o.category == "conveyor").unwrap().clone();
    // Onto the conveyor's spot.
    let to = [conveyor.pos[0], conveyor.pos[1]];
    let o = apply(&dir, &StructuredEdit::Move { object: cabinet.name.clone(), pos: to, yaw_deg: None });
    let after = layout(&dir);
    assert_eq!(&after, &o.layout);
    let moved = after.object(&cabinet.name).unwrap();
    assert!((moved.pos[0] - to[0]).abs() < 1e-6 && (moved.pos[1] - to[1]).abs() < 1e-6, "{:?}", moved.pos);
    assert_eq!(moved.yaw, cabinet.yaw, "a move keeps the heading");
    let conveyor_now = after.object(&conveyor.name).unwrap();
    assert!(conveyor_now.pos != conveyor.pos, "the conveyor was not placed again");
    assert!(!overlap(moved, conveyor_now, 0.01));
    stands_clear(&after, &cabinet.name);
    // What the conveyor did not carry and nothing else moved.
    let replaced: Vec<&str> = o.record.operations.iter().flat_map(|s| s.split(&[',', ' ', ';'][..])).collect();
    for b in &before.objects {
        let a = after.object(&b.name).unwrap();
        if a != b {
            assert!(
                b.name == cabinet.name || replaced.contains(&b.name.as_str()) || b.support != Support::Floor,
                "{} moved: {:?}",
                b.name,
                o.record.operations
            );
        }
    }
    let edits: sw_plan::EditLog =
        serde_json::from_str(&std::fs::read_to_string(dir.join("edits.json")).unwrap()).unwrap();
    assert_eq!(edits.edits.len(), 1);
    assert_eq!(edits.edits[0].understood_by, "viewer");
    assert_eq!(edits.edits[0].moved, vec![cabinet.name.clone()]);
}

#[test]
fn a_point_outside_the_room_is_brought_inside_and_turning_works_in_place() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s", PROMPT);
    let shelf = layout(&dir).objects.iter().find(|o| o.category == "shelf").unwrap().clone();
    let o = apply(&dir, &StructuredEdit::Move { object: shelf.name.clone(), pos: [100.0, -100.0], yaw_deg: None });
    let l = layout(&dir);
    let s = l.object(&shelf.name).unwrap();
    let room = l.room.size;
    for [x, y] in corners(s) {
        assert!(x.abs() <= room.width / 2.0 + 1e-6 && y.abs() <= room.depth / 2.0 + 1e-6, "({x}, {y}) is outside");
    }
    // It went as far towards the point as the room allows: into the south-east corner.
    assert!(s.pos[0] > room.width / 2.0 - 1.5 && s.pos[1] < -room.depth / 2.0 + 1.5, "{:?}", s.pos);
    assert!(o.report.warnings.iter().any(|w| w.code == "moved_inside_room"), "{:?}", o.report.warnings);
    stands_clear(&l, &shelf.name);

    // Turned a quarter where it stands.
    let at = [s.pos[0], s.pos[1]];
    let yaw = s.yaw.to_degrees() + 90.0;
    apply(&dir, &StructuredEdit::Move { object: shelf.name.clone(), pos: at, yaw_deg: Some(yaw) });
    let t = layout(&dir);
    let turned = t.object(&shelf.name).unwrap();
    let d = (turned.yaw - yaw.to_radians()).rem_euclid(std::f64::consts::TAU);
    assert!(d.min(std::f64::consts::TAU - d) < 1e-6, "yaw {} for {yaw}°", turned.yaw);
    stands_clear(&t, &shelf.name);
}

#[test]
fn an_item_goes_on_the_surface_under_the_point_or_on_the_floor() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s", PROMPT);
    let l = layout(&dir);
    let boxed = l.objects.iter().find(|o| matches!(&o.support, Support::Object { .. })).unwrap().clone();
    let Support::Object { object: table, .. } = &boxed.support else { unreachable!() };
    let table = l.object(table).unwrap().clone();
    // To a free spot on the floor, well away from everything.
    let free = free_spot(&l, 1.5);
    apply(&dir, &StructuredEdit::Move { object: boxed.name.clone(), pos: free, yaw_deg: None });
    let a = layout(&dir);
    let on_floor = a.object(&boxed.name).unwrap();
    assert_eq!(on_floor.support, Support::Floor);
    assert!(on_floor.pos[2].abs() < 1e-9, "{:?}", on_floor.pos);
    // And back onto the table's centre: on its top, at its height.
    apply(&dir, &StructuredEdit::Move { object: boxed.name.clone(), pos: [table.pos[0], table.pos[1]], yaw_deg: None });
    let b = layout(&dir);
    let back = b.object(&boxed.name).unwrap();
    assert!(matches!(&back.support, Support::Object { object, .. } if *object == table.name), "{:?}", back.support);
    assert!((back.pos[2] - boxed.pos[2]).abs() < 1e-6, "{} vs {}", back.pos[2], boxed.pos[2]);
}

#[test]
fn refusals_say_why_and_change_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s", "a small lab with a workbench, a shelf and a UR5e on the bench");
    let l = layout(&dir);
    let robot = l.robots[0].name.clone();
    let bench = l.robots[0].mounted_on.clone().unwrap();
    refused(&dir, &StructuredEdit::Move { object: robot.clone(), pos: [0.0, 0.0], yaw_deg: None }, "robot");
    refused(
        &dir,
        &StructuredEdit::Move { object: "no_such_thing_7".into(), pos: [0.0, 0.0], yaw_deg: None },
        "no object named",
    );
    refused(&dir, &StructuredEdit::Move { object: bench, pos: [0.0, 0.0], yaw_deg: None }, "carries");
    // Into the arm's working space.
    let shelf = l.objects.iter().find(|o| o.category == "shelf").unwrap().name.clone();
    let r = &l.robots[0];
    refused(&dir, &StructuredEdit::Move { object: shelf, pos: [r.pos[0], r.pos[1]], yaw_deg: None }, "working space");
    refused(
        &dir,
        &StructuredEdit::PlaceCategory { category: "unicorn".into(), pos: [0.0, 0.0], yaw_deg: None },
        "catalog",
    );
    refused(
        &dir,
        &StructuredEdit::PlaceMesh {
            asset_id: "abc".into(),
            label: "junk".into(),
            stl: b"not an stl".to_vec(),
            pos: [0.0, 0.0],
            yaw_deg: None,
        },
        "STL",
    );
}

/// A closed box mesh as binary STL (metres), standing for a generated part.
fn part_stl(size: [f64; 3]) -> Vec<u8> {
    let m = sw_geom::box_mesh([size[0] / 2.0, size[1] / 2.0, size[2] / 2.0]);
    let mut out = Vec::new();
    sw_geom::write_stl(&mut out, &m, "part").unwrap();
    out
}

#[test]
fn parts_are_placed_at_the_point_and_a_generated_one_survives_later_edits() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = scene(tmp.path(), "s", PROMPT);
    let l = layout(&dir);
    let spot = free_spot(&l, 1.5);
    let o = apply(&dir, &StructuredEdit::PlaceCategory { category: "crate".into(), pos: spot, yaw_deg: Some(30.0) });
    assert_eq!(o.record.added.len(), 1, "{:?}", o.record);
    let crate_ = layout(&dir).object(&o.record.added[0]).unwrap().clone();
    assert_eq!(crate_.category, "crate");
    assert!((crate_.yaw - 30f64.to_radians()).abs() < 1e-6);

    // A generated part (a 0.3 × 0.2 × 0.25 m block) onto the floor at another spot.
    let stl = part_stl([0.3, 0.2, 0.25]);
    let spot2 = free_spot(&layout(&dir), 1.5);
    let o = apply(
        &dir,
        &StructuredEdit::PlaceMesh {
            asset_id: "0123abcd".into(),
            label: "test block".into(),
            stl: stl.clone(),
            pos: spot2,
            yaw_deg: None,
        },
    );
    let name = o.record.added[0].clone();
    let part = layout(&dir).object(&name).unwrap().clone();
    assert!((part.pos[0] - spot2[0]).abs() < 1e-6 && (part.pos[1] - spot2[1]).abs() < 1e-6, "{:?}", part.pos);
    for (got, want) in part.size.iter().zip([0.3, 0.2, 0.25]) {
        assert!((got - want).abs() < 0.02, "{:?}", part.size);
    }
    assert_eq!(std::fs::read(dir.join("parts/0123abcd.stl")).unwrap(), stl);
    let parts: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("parts.json")).unwrap()).unwrap();
    assert_eq!(parts["parts"][0]["object"], name.as_str());
    let scene_before = std::fs::read_to_string(dir.join("scene.xml")).unwrap();
    let body = |xml: &str| {
        let start = xml.find(&format!("<body name=\"{name}\"")).expect("the part's body");
        xml[start..start + xml[start..].find("</body>").unwrap()].to_string()
    };
    let part_body = body(&scene_before);

    // A later edit elsewhere rebuilds the part from its mesh: the same body, the same files.
    let e = edit_package(&dir, "remove the red cabinet", EditReader::Grammar, None, &mut |_| {}).unwrap();
    assert_eq!(e.report.status, Status::Verified);
    let scene_after = std::fs::read_to_string(dir.join("scene.xml")).unwrap();
    assert_eq!(body(&scene_after), part_body, "the generated part changed in a later edit");
    assert!(dir.join("parts/0123abcd.stl").is_file());
    // Removing it removes its mesh from the package.
    edit_package(&dir, &format!("remove {name}"), EditReader::Grammar, None, &mut |_| {}).unwrap();
    assert!(!dir.join("parts.json").exists() && !dir.join("parts/0123abcd.stl").exists());
}
