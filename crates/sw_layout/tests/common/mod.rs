//! What the layout's test files share: plans, assets made from the catalog, the solve.
#![allow(dead_code)]

use sw_catalog::AssetRequest;
use sw_geom::Asset;
use sw_layout::{LayoutInput, ObjectItem, RobotItem, solve};
use sw_plan::{Dims, LaidOutScene, ObjectPlan, RoomKind, RoomPlan, ScenePlan, Wall};

pub struct Forged {
    pub plan: ScenePlan,
    pub assets: Vec<(String, String, Asset, Vec<String>)>,
}

pub fn forge(plan: ScenePlan, seed: u64) -> Forged {
    let mut assets = Vec::new();
    let mut n = std::collections::BTreeMap::new();
    for g in &plan.objects {
        let cat = sw_catalog::find(&g.category).unwrap();
        for k in 0..g.count {
            let a = sw_catalog::generate(&AssetRequest::new(&g.category, seed ^ (u64::from(k) * 7919))).unwrap();
            let c = n.entry(g.category.clone()).or_insert(0);
            *c += 1;
            assets.push((
                format!("{}_{c}", g.category),
                g.id.clone(),
                a,
                cat.tags.iter().map(|t| t.to_string()).collect(),
            ));
        }
    }
    Forged { plan, assets }
}

pub fn solve_forged(f: &Forged, robots: Vec<RobotItem>, seed: u64) -> LaidOutScene {
    let objects = f
        .assets
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
    solve(&LayoutInput { plan: &f.plan, objects, robots, seed, max_layers: Default::default() })
}

pub fn room(kind: RoomKind, size: Dims, fixed: bool) -> ScenePlan {
    ScenePlan::new("test", RoomPlan { kind, size, size_fixed: fixed, door: Wall::South })
}

pub fn group(id: &str, category: &str, count: u32) -> ObjectPlan {
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
