#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `--fill`: furnished and cluttered rooms, verified in MuJoCo like every scene, never
//! moving what the prompt stated, keeping a robot's work its own, every added object
//! marked; the level read from the option or the prompt's own words.

use sw_pipeline::{FillLevel, Options, generate};
use sw_plan::Support;

#[test]
fn the_prompts_own_words_choose_the_level() {
    for (prompt, want) in [
        ("a cluttered kitchen", Some(FillLevel::Cluttered)),
        ("a lived-in living room with a sofa", Some(FillLevel::Cluttered)),
        ("a lived in bedroom", Some(FillLevel::Cluttered)),
        ("a realistic office with two desks", Some(FillLevel::Cluttered)),
        ("a messy, untidy workshop", Some(FillLevel::Cluttered)),
        ("a furnished bedroom", Some(FillLevel::Furnished)),
        ("a fully furnished flat", Some(FillLevel::Furnished)),
        ("a kitchen that is not cluttered", None),
        ("an uncluttered office", None),
        ("an unfurnished room with a chair", None),
        ("a kitchen with a counter", None),
    ] {
        assert_eq!(FillLevel::from_prompt(prompt), want, "{prompt}");
    }
    for name in FillLevel::NAMES {
        assert_eq!(FillLevel::from_name(name).map(FillLevel::name), Some(name));
    }
    assert_eq!(FillLevel::from_name("crowded"), None);
}

fn run(prompt: &str, seed: u64, fill: Option<FillLevel>) -> (sw_pipeline::Outcome, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p");
    let o = generate(prompt, &out, &Options { seed, fill, ..Options::default() }, &mut |_| {}).unwrap();
    (o, dir)
}

#[test]
fn a_cluttered_kitchen_keeps_the_stated_objects_and_the_robots_work_as_they_were() {
    let prompt = "a kitchen with a Panda on the counter and two mugs on the counter";
    let (plain, _d1) = run(prompt, 4, Some(FillLevel::None));
    let (full, dir) = run(prompt, 4, Some(FillLevel::Cluttered));
    for o in [&plain, &full] {
        assert!(sw_pipeline::succeeded(&o.report), "{:?}", o.report.verification);
    }
    let v = full.report.verification.as_ref().unwrap();
    assert!(v.initial_contacts.as_ref().unwrap().deep.is_empty(), "{v:?}");
    assert!(v.settle.as_ref().unwrap().moved.is_empty(), "{v:?}");
    // Nothing stated moved; everything else is marked added, and the report lists it.
    for p in &plain.layout.objects {
        let f = full.layout.object(&p.name).unwrap_or_else(|| panic!("{} lost", p.name));
        assert_eq!((p.pos, p.yaw, &p.support), (f.pos, f.yaw, &f.support), "{} moved", p.name);
        assert!(!f.added);
    }
    let added: Vec<_> = full.layout.objects.iter().filter(|o| o.added).collect();
    assert_eq!(added.len(), full.layout.objects.len() - plain.layout.objects.len());
    assert!(added.len() >= 40, "only {} added", added.len());
    assert_eq!(full.report.summary.objects_added.len(), added.len());
    assert_eq!(full.report.summary.objects_placed, plain.report.summary.objects_placed);
    // layout.json on disk says so too.
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("p/layout.json")).unwrap()).unwrap();
    let marked = json["objects"].as_array().unwrap().iter().filter(|o| o["added"] == true).count();
    assert_eq!(marked, added.len());
    // The counter the Panda stands on carries only what the prompt put there.
    let robot = &full.layout.robots[0];
    let host = robot.mounted_on.clone().unwrap_or_default();
    for a in &added {
        if let Support::Object { object, .. } = &a.support {
            assert_ne!(object, &host, "{} was put on the robot's counter", a.name);
        }
    }
    // Kitchens get kitchen things: something from the counter list is on a counter.
    assert!(added.iter().any(|a| {
        ["kettle", "toaster", "jar", "coffee_maker", "knife_block", "mug", "bottle"].contains(&a.category.as_str())
    }));
}

#[test]
fn a_fill_adds_no_second_of_what_was_stated_and_one_of_each_appliance() {
    // A stated table is the kitchen's table: no dining table beside it. And however many
    // counters there are, a kitchen has a kettle and a toaster, not four of each.
    for seed in [1, 2, 3] {
        let (o, _d) = run(
            "a kitchen with a counter along the wall, a sink, a fridge and a table with four chairs",
            seed,
            Some(FillLevel::Cluttered),
        );
        assert!(sw_pipeline::succeeded(&o.report), "{:?}", o.report.verification);
        let added: Vec<_> = o.layout.objects.iter().filter(|p| p.added).collect();
        assert!(added.len() >= 40, "seed {seed}: only {} added", added.len());
        for a in &added {
            let cat = sw_catalog::find(&a.category).unwrap();
            assert!(!cat.is_a.contains(&"table"), "seed {seed}: {} added beside the stated table", a.name);
        }
        let mut appliances = std::collections::BTreeMap::<&str, usize>::new();
        for p in &o.layout.objects {
            let cat = sw_catalog::find(&p.category).unwrap();
            if matches!(cat.kind, sw_catalog::Kind::SmallAppliance | sw_catalog::Kind::LargeAppliance) {
                *appliances.entry(cat.name).or_default() += 1;
            }
        }
        assert!(appliances.values().all(|&n| n == 1), "seed {seed}: {appliances:?}");
    }
}

#[test]
fn rooms_of_each_kind_are_furnished_the_way_they_are_used() {
    for (prompt, expect) in [
        ("a bedroom", "bed"),
        ("an office", "desk"),
        ("a living room", "sofa"),
        ("a workshop", "workbench"),
        ("a bathroom", "toilet"),
    ] {
        let (o, _d) = run(prompt, 1, Some(FillLevel::Furnished));
        assert!(sw_pipeline::succeeded(&o.report), "{prompt}: {:?}", o.report.verification);
        assert!(o.layout.objects.iter().any(|p| p.category == expect && p.added), "{prompt}: {:?}", o.layout.objects);
        // Furnished adds furniture only: nothing rests on another object.
        assert!(o.layout.objects.iter().filter(|p| p.added).all(|p| p.support == Support::Floor), "{prompt}");
    }
}

#[test]
fn a_room_too_small_for_more_says_so_and_keeps_what_was_asked() {
    let (o, _d) = run("a 1.2 m by 1 m room with a shelf", 0, Some(FillLevel::Cluttered));
    assert!(sw_pipeline::succeeded(&o.report), "{:?}", o.report.verification);
    assert!(o.layout.objects.iter().any(|p| p.category == "shelf" && !p.added));
    let furniture_added = o.layout.objects.iter().filter(|p| p.added && p.support == Support::Floor).count();
    if furniture_added == 0 {
        assert!(o.report.warnings.iter().any(|w| w.code == "fill_room_full"), "{:?}", o.report.warnings);
    }
}

#[test]
fn no_fill_by_default_and_the_same_fill_for_the_same_seed() {
    let (plain, _d) = run("a kitchen with a counter", 2, None);
    assert!(plain.layout.objects.iter().all(|o| !o.added));
    let (a, _da) = run("a cluttered kitchen", 2, None);
    let (b, _db) = run("a cluttered kitchen", 2, None);
    assert!(a.layout.objects.iter().filter(|o| o.added).count() > 20);
    assert_eq!(a.layout.objects, b.layout.objects);
}
