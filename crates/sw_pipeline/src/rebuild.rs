//! A package's assets, made again from what it records: each object's asset from its
//! plan group and `asset_seed` (footprints shrunk to fit are shrunk again to the recorded
//! size), the pedestals and carts that carry robots, and the robots with their mounts.
//! Bridging the result with the package's own layout writes the package's `scene.xml`
//! byte for byte (the tests check this), which is what lets an edit keep everything it
//! does not change exactly as it was.

use std::collections::{BTreeMap, BTreeSet};

use sw_layout::{RobotItem, RobotMount};
use sw_plan::{LaidOutScene, PlacedObject, ScenePlan};

use crate::forge::{Forged, ForgedObject, carrier_asset, make_seeded, shrunk};
use crate::loads::Sizing;

/// Rebuilds the assets of a package; errors name the object.
pub(crate) fn rebuild(plan: &ScenePlan, layout: &LaidOutScene) -> Result<Forged, String> {
    // The plan's groups are finished in the forge's order (group by group, each group's
    // instances in the order they were named), so that what one group's first asset
    // tells the next (a table's top, a shelf's levels) is the same as it was.
    let number = |name: &str| name.rsplit('_').next().and_then(|n| n.parse::<u32>().ok()).unwrap_or(u32::MAX);
    let mut order: Vec<&PlacedObject> = Vec::with_capacity(layout.objects.len());
    for g in &plan.objects {
        let mut of_group: Vec<&PlacedObject> = layout.objects.iter().filter(|o| o.group == g.id).collect();
        of_group.sort_by_key(|o| number(&o.name));
        order.extend(of_group);
    }
    order.extend(layout.objects.iter().filter(|o| plan.object(&o.group).is_none()));
    let mut sizing = Sizing::default();
    let mut made: BTreeMap<&str, ForgedObject> = BTreeMap::new();
    let mut seen: BTreeSet<&str> = BTreeSet::new();
    for o in order {
        let first = seen.insert(o.group.as_str());
        made.insert(o.name.as_str(), object(plan, layout, o, first, &mut sizing)?);
    }
    let mut out = Forged::default();
    for o in &layout.objects {
        out.objects.extend(made.remove(o.name.as_str()));
    }
    for r in &layout.robots {
        out.robots.push(robot(plan, layout, r)?);
    }
    Ok(out)
}

/// One object's asset, as the package made it; `first` when it is the first of its group.
fn object(
    plan: &ScenePlan,
    layout: &LaidOutScene,
    o: &PlacedObject,
    first: bool,
    sizing: &mut Sizing,
) -> Result<ForgedObject, String> {
    let carries_robot = layout
        .robots
        .iter()
        .find(|r| r.mount != "surface" && r.mounted_on.as_deref() == Some(o.name.as_str()))
        .map(|r| r.name.clone());
    let (asset, tags, label) = match plan.object(&o.group) {
        Some(g) => {
            let (asset, tags, label) = make_seeded(g, o.asset_seed).map_err(|e| format!("{}: {e}", o.name))?;
            (sizing.finish(plan, &g.id, first, asset), tags, label)
        }
        None => {
            // A robot's pedestal or cart (its group is the robot's, with `_mount`), as tall
            // as the layout records: the forge sets a pedestal's height by its work.
            let plain = carrier_asset(&o.category, o.asset_seed, None);
            // Its height as the layout records it: the collision geometry's, to 0.1 µm.
            let tall = |a: &sw_geom::Asset| {
                let z = a.collision_aabbs().iter().fold(sw_geom::Aabb::EMPTY, |acc, b| acc.union(b)).size()[2];
                (z * 1e7).round() / 1e7
            };
            let asset = if tall(&plain) == o.size[2] {
                plain
            } else {
                carrier_asset(&o.category, o.asset_seed, Some(o.size[2]))
            };
            let tags = sw_catalog::find(&o.category)
                .map(|c| c.tags.iter().map(|t| t.to_string()).collect())
                .unwrap_or_default();
            (asset, tags, o.category.replace('_', " "))
        }
    };
    let mut f = ForgedObject {
        name: o.name.clone(),
        group: o.group.clone(),
        category: o.category.clone(),
        label: o.label.clone(),
        asset,
        tags,
        carries_robot,
    };
    let _ = label;
    // Footprints shrunk to fit the room are shrunk again to the recorded size (the
    // layout records the extent of the collision geometry).
    let extent =
        |a: &sw_geom::Asset| a.collision_aabbs().iter().fold(sw_geom::Aabb::EMPTY, |acc, b| acc.union(b)).size();
    let s = extent(&f.asset);
    let off = |a: f64, b: f64| (a - b).abs() > 2e-4;
    if (off(s[0], o.size[0]) || off(s[1], o.size[1])) && s[0] > 0.0 {
        // The pipeline's own steps first, then the ratio of the recorded size.
        for factor in crate::SHRINK_STEPS.into_iter().chain([o.size[0] / s[0]]) {
            let candidate = shrunk(&f, factor);
            let c = extent(&candidate);
            if !off(c[0], o.size[0]) && !off(c[1], o.size[1]) {
                f.asset = candidate;
                break;
            }
        }
    }
    Ok(f)
}

fn robot(plan: &ScenePlan, layout: &LaidOutScene, r: &sw_plan::PlacedRobot) -> Result<RobotItem, String> {
    let def =
        sw_robots::find(&r.model).ok_or_else(|| format!("{}: robot model '{}' is not registered", r.name, r.model))?;
    let facts = crate::robot_facts::facts(def);
    let mount = match (r.mount.as_str(), &r.mounted_on) {
        ("surface", Some(host)) => {
            let group = layout
                .object(host)
                .map(|h| h.group.clone())
                .ok_or_else(|| format!("{}: its surface {host} is missing", r.name))?;
            RobotMount::Surface { group }
        }
        (_, Some(carrier)) => RobotMount::Carrier { object: carrier.clone() },
        _ => RobotMount::Floor,
    };
    Ok(RobotItem {
        name: r.name.clone(),
        group: r.group.clone(),
        model: def.name.to_string(),
        is_arm: def.kind == sw_robots::RobotKind::Arm,
        keepout: facts.keepout.iter().map(|(lo, hi)| sw_geom::Aabb { min: *lo, max: *hi }).collect(),
        base_radius: facts.base_radius,
        reach: facts.reach,
        mount,
        near: plan.robots.iter().find(|p| p.id == r.group).and_then(|p| p.near.clone()),
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::{Options, generate};
    use sw_catalog::AssetRequest;

    /// Rebuilt assets bridged with the package's layout write its scene.xml exactly.
    #[test]
    fn a_rebuilt_package_bridges_to_the_same_scene() {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../bench/prompts.txt")).unwrap();
        let prompts: Vec<&str> = text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#')).collect();
        let dir = tempfile::tempdir().unwrap();
        for (i, p) in prompts.iter().enumerate() {
            let out = dir.path().join(format!("p{i}"));
            let o = generate(p, &out, &Options { seed: i as u64, verify: false, ..Options::default() }, &mut |_| {})
                .unwrap();
            if !o.layout.anomalies.is_empty() {
                continue;
            }
            let forged = rebuild(&o.plan, &o.layout).unwrap();
            let files = crate::package::bridge(&o.plan.prompt, &o.layout, &forged).unwrap();
            let on_disk = std::fs::read_to_string(out.join("scene.xml")).unwrap();
            assert!(files.scene_xml == on_disk, "prompt {i} ({p}): the rebuilt scene differs");
        }
    }

    /// A pedestal the forge made as tall as its arm's work (bins on the floor: lower
    /// than the catalog's) is rebuilt at that height, and the scene with it.
    #[test]
    fn a_pedestal_as_tall_as_its_work_is_rebuilt_at_its_height() {
        let plan: ScenePlan = serde_json::from_value(serde_json::json!({
            "schema_version": sw_plan::SCHEMA_VERSION,
            "prompt": "a UR5e on a pedestal reaching four bins on the floor",
            "room": {"kind": "warehouse", "size": {"width": 8.0, "depth": 8.0, "height": 4.0}, "size_fixed": true, "door": "south"},
            "objects": [{"id": "bins", "category": "bin", "phrase": "four bins", "count": 4}],
            "relations": [{"subject": "arm", "relation": "reach", "target": "bins"}],
            "robots": [{"id": "arm", "model": "ur5e", "phrase": "a UR5e", "count": 1, "mount": {"mount": "pedestal"}}],
            "rules_profile": "general",
            "understanding": {"not_understood": [], "approximated": []}
        }))
        .unwrap();
        let dir = tempfile::tempdir().unwrap();
        for seed in [1, 2, 3] {
            let out = dir.path().join(format!("s{seed}"));
            let o = crate::generate_from_plan(
                plan.clone(),
                &out,
                &Options { seed, verify: false, ..Options::default() },
                &mut |_| {},
            )
            .unwrap();
            let stand = o.layout.objects.iter().find(|x| x.category == "pedestal").unwrap();
            let plain = sw_catalog::generate(&AssetRequest::new("pedestal", stand.asset_seed)).unwrap();
            assert!(
                (plain.bounds().size()[2] - stand.size[2]).abs() > 0.05,
                "seed {seed}: the pedestal is the catalog's height ({:.2} m): the test proves nothing",
                stand.size[2]
            );
            let rebuilt = rebuild(&o.plan, &o.layout).unwrap();
            let files = crate::package::bridge(&o.plan.prompt, &o.layout, &rebuilt).unwrap();
            let on_disk = std::fs::read_to_string(out.join("scene.xml")).unwrap();
            assert!(files.scene_xml == on_disk, "seed {seed}: the rebuilt scene differs");
        }
    }

    /// Things sized by another asset: a cabinet fitted under a table's top, boxes sized to
    /// the levels of the shelf they fill, totes in a stack made one model, whatever the
    /// layout's order.
    #[test]
    fn assets_sized_by_another_group_are_rebuilt_to_the_same_size() {
        use sw_plan::RelationKind;
        let extent =
            |a: &sw_geom::Asset| a.collision_aabbs().iter().fold(sw_geom::Aabb::EMPTY, |acc, b| acc.union(b)).size();
        let dir = tempfile::tempdir().unwrap();
        let prompts = [
            "an office with a desk and a filing cabinet under the desk",
            "a lab with a table and a fridge under the table",
            "a warehouse with a bookshelf full of crates",
            "a warehouse with a stack of six bins",
        ];
        for (i, p) in prompts.iter().enumerate() {
            let out = dir.path().join(format!("p{i}"));
            let o = generate(p, &out, &Options { seed: 3, verify: false, ..Options::default() }, &mut |_| {}).unwrap();
            // Some object was sized by another group (else the test proves nothing): its
            // recorded size is not the catalog's for its seed.
            let sized_by_other = |x: &PlacedObject| {
                o.plan.relations.iter().any(|r| match &r.kind {
                    RelationKind::Under { .. } | RelationKind::Stacked { .. } => r.subject == x.group,
                    RelationKind::FullOf { target } => *target == x.group,
                    _ => false,
                })
            };
            let resized = o.layout.objects.iter().filter(|x| sized_by_other(x)).any(|x| {
                let plain = sw_catalog::generate(&AssetRequest::new(&x.category, x.asset_seed)).unwrap();
                extent(&plain).iter().zip(&x.size).any(|(a, b)| (a - b).abs() > 1e-3)
            });
            assert!(resized, "prompt {i} ({p}): nothing was sized by another group: {:?}", o.plan.relations);
            let on_disk = std::fs::read_to_string(out.join("scene.xml")).unwrap();
            let rebuilt = rebuild(&o.plan, &o.layout).unwrap();
            let files = crate::package::bridge(&o.plan.prompt, &o.layout, &rebuilt).unwrap();
            assert!(files.scene_xml == on_disk, "prompt {i} ({p}): the rebuilt scene differs");
            // The layout's objects in another order: each is rebuilt to its recorded size.
            let mut reversed = o.layout.clone();
            reversed.objects.reverse();
            let rebuilt = rebuild(&o.plan, &reversed).unwrap();
            for (x, f) in reversed.objects.iter().zip(&rebuilt.objects) {
                assert_eq!(x.name, f.name);
                let s = extent(&f.asset);
                assert!(
                    s.iter().zip(&x.size).all(|(a, b)| (a - b).abs() < 2e-4),
                    "prompt {i} ({p}): {} is {s:?}, recorded {:?}",
                    x.name,
                    x.size
                );
            }
        }
    }
}
