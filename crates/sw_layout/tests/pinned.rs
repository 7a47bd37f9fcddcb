#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Pinned layouts (edits): what is pinned stays exactly where it was; what is new is
//! placed around it without overlap; the room keeps its size.

use sw_catalog::AssetRequest;
use sw_geom::{Aabb, Asset, Pose};
use sw_layout::{LayoutInput, ObjectItem, Pins, solve, solve_pinned};
use sw_plan::{LaidOutScene, ObjectPlan, Relation, RelationKind, RoomKind, RoomPlan, ScenePlan, Support, Wall};

fn group(id: &str, category: &str, count: u32) -> ObjectPlan {
    ObjectPlan {
        id: id.into(),
        category: category.into(),
        phrase: id.into(),
        count,
        color: None,
        size: Default::default(),
        proxy: None,
    }
}

fn assets(plan: &ScenePlan) -> Vec<(String, String, Asset, Vec<String>)> {
    let mut out = Vec::new();
    let mut n = std::collections::BTreeMap::new();
    for g in &plan.objects {
        let cat = sw_catalog::find(&g.category).unwrap();
        for k in 0..g.count {
            let a = sw_catalog::generate(&AssetRequest::new(&g.category, u64::from(k) * 31)).unwrap();
            let c = n.entry(g.category.clone()).or_insert(0);
            *c += 1;
            out.push((
                format!("{}_{c}", g.category),
                g.id.clone(),
                a,
                cat.tags.iter().map(|t| t.to_string()).collect(),
            ));
        }
    }
    out
}

fn input<'a>(plan: &'a ScenePlan, assets: &'a [(String, String, Asset, Vec<String>)]) -> LayoutInput<'a> {
    let objects = assets
        .iter()
        .map(|(name, group, asset, tags)| ObjectItem {
            name: name.clone(),
            group: group.clone(),
            category: asset.category.clone(),
            label: asset.category.clone(),
            asset,
            tags: tags.clone(),
            carries_robot: None,
        })
        .collect();
    LayoutInput { plan, objects, robots: Vec::new(), seed: 3, max_layers: Default::default() }
}

fn boxes(assets: &[(String, String, Asset, Vec<String>)], scene: &LaidOutScene, name: &str) -> Vec<Aabb> {
    let o = scene.object(name).unwrap();
    let (_, _, a, _) = assets.iter().find(|(n, ..)| n == name).unwrap();
    a.collision_aabbs().iter().map(|b| b.transformed(&Pose::from_pos_yaw(o.pos, o.yaw))).collect()
}

fn lab() -> ScenePlan {
    let mut p = ScenePlan::new(
        "test",
        RoomPlan { kind: RoomKind::Lab, size: RoomKind::Lab.default_size(), size_fixed: false, door: Wall::South },
    );
    p.objects.push(group("table", "table", 1));
    p.objects.push(group("mugs", "mug", 3));
    p.objects.push(group("shelf", "shelf", 2));
    p.relations.push(Relation { subject: "mugs".into(), kind: RelationKind::On { target: "table".into() } });
    p
}

#[test]
fn pinning_everything_reproduces_the_layout() {
    let plan = lab();
    let a = assets(&plan);
    let first = solve(&input(&plan, &a));
    let pins = Pins { room: first.room.clone(), objects: first.objects.clone(), robots: first.robots.clone() };
    let again = solve_pinned(&input(&plan, &a), &pins);
    assert_eq!(again.objects, first.objects);
    assert_eq!(again.room, first.room);
}

#[test]
fn new_objects_are_placed_around_the_pinned_ones() {
    let plan = lab();
    let a = assets(&plan);
    let first = solve(&input(&plan, &a));
    let mut more = plan.clone();
    more.objects.push(group("chairs", "chair", 3));
    more.objects.push(group("cups", "mug", 2));
    more.relations.push(Relation { subject: "cups".into(), kind: RelationKind::On { target: "table".into() } });
    let mut b = a.clone();
    for (k, (cat, id)) in
        [("chair", "chairs"), ("chair", "chairs"), ("chair", "chairs"), ("mug", "cups"), ("mug", "cups")]
            .into_iter()
            .enumerate()
    {
        let asset = sw_catalog::generate(&AssetRequest::new(cat, 100 + k as u64)).unwrap();
        let tags = sw_catalog::find(cat).unwrap().tags.iter().map(|t| t.to_string()).collect();
        b.push((format!("{cat}_new{k}"), id.into(), asset, tags));
    }
    let pins = Pins { room: first.room.clone(), objects: first.objects.clone(), robots: Vec::new() };
    let second = solve_pinned(&input(&more, &b), &pins);
    for o in &first.objects {
        assert_eq!(second.object(&o.name), Some(o), "{} moved", o.name);
    }
    assert_eq!(second.objects.len(), first.objects.len() + 5, "{:?}", second.left_out);
    assert_eq!(second.room.size, first.room.size);
    // New cups share the table with the pinned mugs without overlapping them.
    for cup in second.objects.iter().filter(|o| o.group == "cups") {
        assert!(matches!(&cup.support, Support::Object { object, .. } if object == "table_1"), "{cup:?}");
    }
    let names: Vec<&str> = second.objects.iter().map(|o| o.name.as_str()).collect();
    for (i, x) in names.iter().enumerate() {
        for y in &names[i + 1..] {
            for p in boxes(&b, &second, x) {
                for q in boxes(&b, &second, y) {
                    let d: Vec<f64> = (0..3).map(|k| p.max[k].min(q.max[k]) - p.min[k].max(q.min[k])).collect();
                    assert!(d[0].min(d[1]).min(d[2]) <= 1e-6, "{x} overlaps {y}");
                }
            }
        }
    }
}
