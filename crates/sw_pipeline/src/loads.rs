//! Loads sized to their carriers. Items said to fill shelving ("shelves full of boxes",
//! "stocked with bins") are made small enough that two stand side by side on every
//! level and fit under the level above; the shelving keeps its category's number of
//! levels, so that the planner's count (two per level) fills every one.

use std::collections::BTreeMap;

use sw_catalog::AssetRequest;
use sw_geom::{Asset, SupportSurface};
use sw_plan::{RelationKind, ScenePlan};

/// The group whose levels `group` fills, if any.
pub(crate) fn host_of(plan: &ScenePlan, group: &str) -> Option<String> {
    plan.relations.iter().find_map(|r| match &r.kind {
        RelationKind::FullOf { target } if target == group => Some(r.subject.clone()),
        _ => None,
    })
}

/// Whether `group` is shelving said to be full of something.
pub(crate) fn is_filled(plan: &ScenePlan, group: &str) -> bool {
    plan.relations.iter().any(|r| r.subject == group && matches!(r.kind, RelationKind::FullOf { .. }))
}

/// Whether `group` is said to be stacked.
pub(crate) fn is_stacked(plan: &ScenePlan, group: &str) -> bool {
    plan.relations.iter().any(|r| r.subject == group && matches!(r.kind, RelationKind::Stacked { .. }))
}

/// The same catalog asset made again with some parameters changed (same seed, colour).
fn remade(a: &Asset, change: &BTreeMap<&str, f64>) -> Option<Asset> {
    sw_catalog::find(&a.category)?;
    let mut req = AssetRequest::new(&a.category, a.seed);
    req.overrides = a.params.iter().map(|(n, v)| (n.clone(), change.get(n.as_str()).copied().unwrap_or(*v))).collect();
    req.color = a.materials.iter().find(|m| m.recolorable).map(|m| m.rgba);
    sw_catalog::generate(&req).ok()
}

/// Shelving with its category's default number of levels (the count the plan filled).
pub(crate) fn pin_levels(a: Asset) -> Asset {
    let Some(def) = sw_catalog::find(&a.category).and_then(|c| c.param("levels")) else { return a };
    if a.param("levels").is_some_and(|v| (v.round() - def.default.round()).abs() < 0.5) {
        return a;
    }
    let change = BTreeMap::from([("levels", def.default)]);
    remade(&a, &change).unwrap_or(a)
}

/// What the plan's relations make of one of `group`'s assets, whatever stands around it:
/// flat things leaning on something stand on edge ("tires leaning on the wall"), shelving
/// that is filled keeps the levels the plan filled, and workpieces on an arm's surface are
/// sized to be worked on. The forge and a package's rebuild take the same steps, so that a
/// rebuilt package bridges to the scene it was.
pub(crate) fn shaped_by_relations(plan: &ScenePlan, group: &str, asset: Asset) -> Asset {
    let leaning = plan.relations.iter().any(|r| r.subject == group && matches!(r.kind, RelationKind::Leaning { .. }));
    let asset = if leaning { crate::upright::on_edge(asset) } else { asset };
    let asset = if is_filled(plan, group) { pin_levels(asset) } else { asset };
    if on_arm_surface(plan, group) { fit_workpiece(asset) } else { asset }
}

/// What the first asset of each group tells the groups after it: the levels of shelving
/// said to be full (to size what fills them) and the height of each group's top (to size
/// what stands under it). The forge and a package's rebuild finish every asset through
/// it, in the plan's group order, so that a rebuilt package bridges to the scene it was.
#[derive(Debug, Default)]
pub(crate) struct Sizing {
    levels: BTreeMap<String, Vec<SupportSurface>>,
    tops: BTreeMap<String, f64>,
    /// The parameters of the first of each stacked group of open totes.
    stacked: BTreeMap<String, Vec<(String, f64)>>,
}

impl Sizing {
    /// One of `group`'s assets as the plan's relations make it ([`shaped_by_relations`],
    /// fitted under what it stands under and to the shelving it fills); `first` is the
    /// group's first instance, the one the groups after it are sized by.
    pub(crate) fn finish(&mut self, plan: &ScenePlan, group: &str, first: bool, asset: Asset) -> Asset {
        let asset = shaped_by_relations(plan, group, asset);
        // Open totes said to be stacked are one model (their colours may differ): each
        // stands on the rim of the one below, which a smaller one would fall into.
        let asset = if is_stacked(plan, group) && asset.is_open() {
            match self.stacked.get(group) {
                Some(p) if !first => {
                    let change: BTreeMap<&str, f64> = p.iter().map(|(n, v)| (n.as_str(), *v)).collect();
                    remade(&asset, &change).unwrap_or(asset)
                }
                _ => {
                    self.stacked.insert(group.to_string(), asset.params.clone());
                    asset
                }
            }
        } else {
            asset
        };
        if first && is_filled(plan, group) {
            self.levels.insert(group.to_string(), asset.surfaces.clone());
        }
        let asset = match under_of(plan, group).and_then(|h| self.tops.get(&h).copied()) {
            Some(top) => fit_under(asset, top),
            None => asset,
        };
        if first && let Some(t) = top_height(&asset) {
            self.tops.insert(group.to_string(), t);
        }
        match host_of(plan, group).and_then(|h| self.levels.get(&h)) {
            Some(l) => fit_item(asset, l),
            None => asset,
        }
    }
}

/// Whether `group` rests on a surface an arm is mounted on (its workpieces).
pub(crate) fn on_arm_surface(plan: &ScenePlan, group: &str) -> bool {
    plan.relations.iter().any(|r| {
        r.subject == group
            && matches!(&r.kind, RelationKind::On { target }
                if plan.robots.iter().any(|b| matches!(&b.mount, sw_plan::Mount::OnSurface { target: t } if t == target)))
    })
}

/// A workpiece on an arm's surface sized to be worked on: at most 0.36 m across and
/// 0.26 m high (under the forearm of an arm at its home pose), so that what the prompt
/// puts there fits within the arm's reach beside it.
pub(crate) fn fit_workpiece(a: Asset) -> Asset {
    let s = a.bounds().size();
    let mut change: BTreeMap<&str, f64> = BTreeMap::new();
    for (name, v, cap) in [("width", s[0], 0.36), ("depth", s[1], 0.36), ("height", s[2], 0.26)] {
        if v > cap {
            change.insert(name, cap);
        }
    }
    if change.is_empty() {
        return a;
    }
    remade(&a, &change).unwrap_or(a)
}

/// The group `group` is said to stand under, if any.
pub(crate) fn under_of(plan: &ScenePlan, group: &str) -> Option<String> {
    plan.relations.iter().find_map(|r| match &r.kind {
        RelationKind::Under { target } if r.subject == group => Some(target.clone()),
        _ => None,
    })
}

/// The height of an asset's top work surface (the underside of what stands under it is
/// a little lower).
pub(crate) fn top_height(a: &Asset) -> Option<f64> {
    a.surfaces
        .iter()
        .filter(|s| s.clearance.is_none())
        .map(|s| s.z)
        .fold(None, |m: Option<f64>, z| Some(m.map_or(z, |m| m.max(z))))
}

/// Something said to stand under a table no taller than the room under its top.
pub(crate) fn fit_under(a: Asset, top: f64) -> Asset {
    let room = top - 0.08;
    if a.bounds().size()[2] <= room || room <= 0.05 {
        return a;
    }
    remade(&a, &BTreeMap::from([("height", room)])).unwrap_or(a)
}

/// An item small enough that two fit side by side on each of `levels` and under the
/// level above.
pub(crate) fn fit_item(a: Asset, levels: &[SupportSurface]) -> Asset {
    if levels.is_empty() {
        return a;
    }
    let s = a.bounds().size();
    let clear = levels.iter().filter_map(|l| l.clearance).fold(f64::INFINITY, f64::min) - 0.03;
    let long = levels.iter().map(|l| l.max[0] - l.min[0]).fold(f64::INFINITY, f64::min) / 2.0 - 0.03;
    let deep = levels.iter().map(|l| l.max[1] - l.min[1]).fold(f64::INFINITY, f64::min) - 0.02;
    let mut change: BTreeMap<&str, f64> = BTreeMap::new();
    if s[2] > clear && clear > 0.0 {
        change.insert("height", clear);
    }
    if s[0] > long && long > 0.0 {
        change.insert("width", long);
    }
    if s[1] > deep && deep > 0.0 {
        change.insert("depth", deep);
    }
    if change.is_empty() {
        return a;
    }
    remade(&a, &change).unwrap_or(a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bin_made_to_fill_shelf_levels_fits_two_to_a_level() {
        let shelf = pin_levels(sw_catalog::generate(&AssetRequest::new("gondola_shelf", 7)).unwrap());
        let levels = shelf.surfaces.clone();
        assert_eq!(levels.len(), 5, "four shelves above the base deck");
        let bin = fit_item(sw_catalog::generate(&AssetRequest::new("bin", 3)).unwrap(), &levels);
        let s = bin.bounds().size();
        for l in &levels {
            assert!(2.0 * s[0] + 0.03 <= l.max[0] - l.min[0], "{s:?} on {l:?}");
            assert!(s[1] <= l.max[1] - l.min[1]);
            if let Some(c) = l.clearance {
                assert!(s[2] < c, "{s:?} under {c}");
            }
        }
    }
}
