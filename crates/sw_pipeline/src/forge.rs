//! L2, offline: every object instance of the plan becomes an asset from the procedural
//! catalog (or a labelled proxy), and every robot gets its mount.

use sw_catalog::{AssetRequest, CatalogError};
use sw_geom::{Asset, Rng};
use sw_layout::{RobotItem, RobotMount};
use sw_plan::{Mount, ObjectPlan, RelationKind, ScenePlan, SizeHint, Stage, Warning};
use sw_robots::RobotKind;

/// One object instance with its asset.
#[derive(Debug, Clone)]
pub struct ForgedObject {
    pub name: String,
    pub group: String,
    pub category: String,
    pub label: String,
    pub asset: Asset,
    pub tags: Vec<String>,
    pub carries_robot: Option<String>,
}

#[derive(Debug, Clone, Default)]
pub struct Forged {
    pub objects: Vec<ForgedObject>,
    pub robots: Vec<RobotItem>,
    pub warnings: Vec<Warning>,
    /// Object groups whose assets were at hand, and those that had to be made.
    pub cache: sw_plan::AssetCache,
}

/// Builds every asset of the plan from the catalog: every group is at hand.
pub fn forge(plan: &ScenePlan, seed: u64) -> Forged {
    let mut forged = forge_with(plan, seed, &mut |group, k| make(group, k, seed).map_err(|e| e.to_string()));
    forged.cache = sw_plan::AssetCache { hits: plan.objects.len() as u32, misses: 0 };
    forged
}

/// An instance's asset, catalog tags and label, or why it could not be made.
pub(crate) type Made = Result<(Asset, Vec<String>, String), String>;

/// Builds every asset of the plan with `maker` (object group, instance index), robots
/// and their mounts from the catalog.
pub(crate) fn forge_with(plan: &ScenePlan, seed: u64, maker: &mut dyn FnMut(&ObjectPlan, u32) -> Made) -> Forged {
    let mut out = Forged::default();
    let mut counters: std::collections::BTreeMap<String, u32> = std::collections::BTreeMap::new();
    let mut next_name = |base: &str| {
        let n = counters.entry(base.to_string()).or_insert(0);
        *n += 1;
        format!("{base}_{n}")
    };
    // What each group's first asset tells the groups after it.
    let mut sizing = crate::loads::Sizing::default();
    for group in &plan.objects {
        let mut noted = false;
        for k in 0..group.count {
            let (asset, tags, label) = match maker(group, k) {
                Ok(x) => x,
                Err(e) => {
                    out.warnings.push(Warning::new(
                        Stage::Forge,
                        "asset_fallback",
                        format!("{}: {e}; used a labelled proxy", group.phrase),
                    ));
                    let size = sw_catalog::find(&group.category).map_or([0.5, 0.5, 0.5], |c| c.default_size());
                    let a =
                        sw_catalog::proxy_asset(&group.category, size, false, None, instance_seed(seed, &group.id, k));
                    (a, vec!["proxy".to_string()], group.category.replace('_', " "))
                }
            };
            if !noted && !asset.notes.is_empty() {
                for n in &asset.notes {
                    if !n.contains("labelled proxy") {
                        out.warnings.push(Warning::new(Stage::Forge, "size_clamped", format!("{}: {n}", group.phrase)));
                    }
                }
                noted = true;
            }
            let asset = sizing.finish(plan, &group.id, k == 0, asset);
            let base = if group.category == "proxy" { slug(&label) } else { group.category.clone() };
            out.objects.push(ForgedObject {
                name: next_name(&base),
                group: group.id.clone(),
                category: group.category.clone(),
                label,
                asset,
                tags,
                carries_robot: None,
            });
        }
    }
    // Robots and their mounts.
    let surface_group = plan
        .objects
        .iter()
        .find(|o| {
            sw_catalog::find(&o.category)
                .is_some_and(|c| c.has_tag("surface") && c.has_tag("furniture") && c.name != "chair")
        })
        .map(|o| o.id.clone());
    let mut robot_counter: std::collections::BTreeMap<String, u32> = std::collections::BTreeMap::new();
    let mut arms_on: std::collections::BTreeMap<String, u32> = std::collections::BTreeMap::new();
    for r in &plan.robots {
        let Some(def) = sw_robots::find(&r.model) else {
            out.warnings.push(Warning::new(
                Stage::Forge,
                "robot_unknown",
                format!("{}: no robot model '{}'", r.phrase, r.model),
            ));
            continue;
        };
        for _ in 0..r.count {
            let n = robot_counter.entry(def.name.to_string()).or_insert(0);
            *n += 1;
            let name = format!("{}_{n}", def.name);
            let is_arm = def.kind == RobotKind::Arm;
            let mut carrier = |category: &str, work: Option<&str>, out: &mut Forged| -> RobotMount {
                let height =
                    (category == "pedestal").then(|| pedestal_height(plan, &r.id, work, &out.objects)).flatten();
                let asset = carrier_asset(category, instance_seed(seed, &name, 0), height);
                let tags = sw_catalog::find(category)
                    .map(|c| c.tags.iter().map(|t| t.to_string()).collect())
                    .unwrap_or_default();
                let object = next_name(category);
                out.objects.push(ForgedObject {
                    name: object.clone(),
                    group: format!("{}_mount", r.id),
                    category: category.to_string(),
                    label: category.replace('_', " "),
                    asset,
                    tags,
                    carries_robot: Some(name.clone()),
                });
                RobotMount::Carrier { object }
            };
            // "a Panda on the edge of the table": mounted on it.
            let said_surface = plan.relations.iter().filter(|x| x.subject == r.id).find_map(|x| match &x.kind {
                RelationKind::On { target } | RelationKind::OnEdgeOf { target } if plan.object(target).is_some() => {
                    Some(target.clone())
                }
                _ => None,
            });
            let mount = match (&r.mount, is_arm) {
                (_, false) => RobotMount::Floor,
                (Mount::Auto, true) if said_surface.is_some() => {
                    RobotMount::Surface { group: said_surface.clone().unwrap_or_default() }
                }
                (Mount::OnSurface { target }, true) => RobotMount::Surface { group: target.clone() },
                (Mount::Pedestal, true) => carrier("pedestal", r.near.as_deref(), &mut out),
                (Mount::MobileBase, true) => carrier("mobile_cart", None, &mut out),
                (Mount::Floor, true) => RobotMount::Floor,
                (Mount::Auto, true) => match (&surface_group, &r.near) {
                    (Some(g), None) => RobotMount::Surface { group: g.clone() },
                    _ => carrier("pedestal", r.near.as_deref(), &mut out),
                },
            };
            // One arm per work surface: the arms beyond that stand on pedestals beside it.
            let mut near = r.near.clone();
            let mount = match mount {
                RobotMount::Surface { group } => {
                    let used = arms_on.entry(group.clone()).or_insert(0);
                    *used += 1;
                    // An arm per 0.75 m of each instance's top ("two Pandas on a workbench").
                    let capacity: u32 = out
                        .objects
                        .iter()
                        .filter(|o| o.group == group)
                        .map(|o| {
                            let top = o
                                .asset
                                .surfaces
                                .iter()
                                .filter(|s| s.clearance.is_none())
                                .map(|s| (s.max[0] - s.min[0]).max(s.max[1] - s.min[1]))
                                .fold(0.0, f64::max);
                            ((top / 0.75).floor() as u32).clamp(1, 3)
                        })
                        .sum::<u32>()
                        // Arms said to stand on either side of it share it (the layout
                        // keeps their home volumes apart).
                        .max(if flanking(plan, &r.id, &group) { r.count.min(2) } else { 0 });
                    if *used > capacity {
                        out.warnings.push(Warning::new(
                            Stage::Forge,
                            "robot_on_pedestal",
                            format!("{name}: every {group} already carries an arm; it stands on a pedestal beside one"),
                        ));
                        let mount = carrier("pedestal", Some(&group), &mut out);
                        near = Some(group);
                        mount
                    } else {
                        RobotMount::Surface { group }
                    }
                }
                m => m,
            };
            let facts = crate::robot_facts::facts(def);
            out.robots.push(RobotItem {
                name,
                group: r.id.clone(),
                model: def.name.to_string(),
                is_arm,
                keepout: facts.keepout.iter().map(|(lo, hi)| sw_geom::Aabb { min: *lo, max: *hi }).collect(),
                base_radius: facts.base_radius,
                reach: facts.reach,
                mount,
                near,
            });
        }
    }
    out
}

/// The asset of a robot's pedestal or cart, `height` tall (the catalog's height for its
/// seed when `None`). The forge and the rebuild of a package both make carriers here: the
/// forge with the height [`pedestal_height`] decides, the rebuild with the height the
/// package's layout records, so that a rebuilt scene is the scene that was written.
pub(crate) fn carrier_asset(category: &str, seed: u64, height: Option<f64>) -> Asset {
    let mut req = AssetRequest::new(category, seed);
    if let Some(h) = height
        && sw_catalog::find(category).is_some_and(|c| c.param("height").is_some())
    {
        req.overrides.push(("height".into(), h));
    }
    sw_catalog::generate(&req).unwrap_or_else(|_| sw_catalog::proxy_asset(category, [0.5, 0.5, 0.7], false, None, 0))
}

/// How tall the pedestal of robot group `robot` stands: its mounting plate 0.1 m below
/// the height it works at — the lowest of the things it is said to reach (and `work`,
/// the group it tends), each at its top surface, else its top, raised by what it rests
/// on — within 0.3–0.75 m, to the centimetre: an arm among bins on the floor stands low enough
/// to reach into them, one at a conveyor high enough to reach across its belt, one
/// tending a tall machine no higher than a bench. `None` (the catalog's height) when it
/// has no work among the forged objects.
pub(crate) fn pedestal_height(
    plan: &ScenePlan,
    robot: &str,
    work: Option<&str>,
    objects: &[ForgedObject],
) -> Option<f64> {
    let mut groups: Vec<&str> = plan
        .relations
        .iter()
        .filter(|x| x.subject == robot)
        .filter_map(|x| match &x.kind {
            RelationKind::Reach { target } => Some(target.as_str()),
            _ => None,
        })
        .collect();
    groups.extend(work);
    // Where on a thing the arm works: its top surface (not a shelf under it), else its top.
    let top_of = |group: &str| -> Option<f64> {
        objects
            .iter()
            .filter(|o| o.group == group)
            .map(|o| o.asset.top_surface().map_or_else(|| o.asset.bounds().max[2], |s| s.z))
            .reduce(f64::max)
    };
    // A thing resting on (or in) another stands at its host's highest surface open above
    // (a sink's drainboard: its tap stands above it, so it has no top surface).
    let base_of = |group: &str| -> f64 {
        plan.relations
            .iter()
            .filter(|x| x.subject == group)
            .find_map(|x| match &x.kind {
                RelationKind::On { target } | RelationKind::Inside { target } if target != group => {
                    objects.iter().filter(|o| &o.group == target).find_map(|o| {
                        o.asset.surfaces.iter().filter(|s| s.clearance.is_none()).map(|s| s.z).reduce(f64::max)
                    })
                }
                _ => None,
            })
            .unwrap_or(0.0)
    };
    // The lowest of its work: reaching up to a belt or a rack from a low stand is kept
    // within reach more easily than reaching down into a basin or a floor bin from a
    // stand as tall as the highest thing it tends.
    let top = groups.iter().filter_map(|g| top_of(g).map(|t| base_of(g) + t)).reduce(f64::min)?;
    Some(((top - 0.1).clamp(0.3, 0.75) * 100.0).round() / 100.0)
}

/// Whether a robot group is said to stand on each side of an object group.
fn flanking(plan: &ScenePlan, robot: &str, group: &str) -> bool {
    plan.relations
        .iter()
        .any(|r| r.subject == robot && matches!(&r.kind, RelationKind::OnEachSideOf { target } if target == group))
}

/// The same object with its footprint (width and depth) scaled by `factor`, kept within
/// its category's ranges (the catalog clamps). Height is kept. Used to fit a crowded room.
pub fn shrunk(o: &ForgedObject, factor: f64) -> Asset {
    let a = &o.asset;
    if sw_catalog::find(&o.category).is_none() {
        let s = a.bounds().size();
        let movable = a.is_free();
        return sw_catalog::proxy_asset(&o.label, [s[0] * factor, s[1] * factor, s[2]], movable, None, a.seed);
    }
    let mut req = AssetRequest::new(&o.category, a.seed);
    req.overrides =
        a.params.iter().map(|(n, v)| (n.clone(), if n == "width" || n == "depth" { v * factor } else { *v })).collect();
    req.color = a.materials.iter().find(|m| m.recolorable).map(|m| m.rgba);
    sw_catalog::generate(&req).unwrap_or_else(|_| a.clone())
}

/// The seed of instance `k` of a group: independent of other groups and of order.
pub(crate) fn instance_seed(seed: u64, group: &str, k: u32) -> u64 {
    Rng::derive(seed, &format!("{group}#{k}")).next_u64()
}

pub(crate) fn make(group: &ObjectPlan, k: u32, seed: u64) -> Result<(Asset, Vec<String>, String), CatalogError> {
    // Identical-looking groups share one seed; boxes, plants and proxies vary per instance.
    let vary = group.proxy.is_some() || sw_catalog::find(&group.category).is_none_or(|c| c.vary_per_instance);
    make_seeded(group, instance_seed(seed, &group.id, if vary { k } else { 0 }))
}

/// An instance's asset from its own seed (the one `layout.json` records as `asset_seed`).
pub(crate) fn make_seeded(group: &ObjectPlan, s: u64) -> Result<(Asset, Vec<String>, String), CatalogError> {
    let color = group.color.as_ref().map(|c| c.rgba.map(|v| v as f32));
    if let Some(p) = &group.proxy {
        // A stated size wins over the stand-in's prior.
        let stated = group.size.explicit.axes(p.size.width >= p.size.depth);
        let size = [p.size.width, p.size.depth, p.size.height];
        let size: [f64; 3] =
            std::array::from_fn(|i| stated[i].filter(|v| v.is_finite() && *v > 0.0).unwrap_or(size[i]));
        let a = sw_catalog::proxy_asset(&p.label, size, p.movable, color, s);
        let mut tags = vec!["proxy".to_string()];
        if p.movable {
            tags.push("tabletop".into());
        }
        return Ok((a, tags, p.label.clone()));
    }
    let cat = sw_catalog::find(&group.category).ok_or_else(|| CatalogError::UnknownCategory(group.category.clone()))?;
    let mut req = AssetRequest::new(cat.name, s);
    req.scale = scale_of(&group.size);
    req.color = color;
    // A stated length goes to the category's longer side ("a 4.5 m conveyor"); on a
    // squarish thing (a 90 cm range) to its width across the front.
    let default = |n: &str| cat.param(n).map_or(0.0, |p| p.default);
    let x_long = default("width") >= 0.85 * default("depth");
    for (name, v) in ["width", "depth", "height"].into_iter().zip(group.size.explicit.axes(x_long)) {
        if let Some(v) = v
            && cat.param(name).is_some()
        {
            req.overrides.push((name.to_string(), v));
        }
    }
    let asset = sw_catalog::generate(&req)?;
    Ok((asset, cat.tags.iter().map(|t| t.to_string()).collect(), cat.display.to_string()))
}

fn scale_of(hint: &SizeHint) -> Option<[f64; 3]> {
    if hint.words.is_empty() {
        return None;
    }
    let mut s = [1.0; 3];
    for w in &hint.words {
        let f = w.factors();
        for i in 0..3 {
            s[i] *= f[i];
        }
    }
    Some(s)
}

pub(crate) fn slug(label: &str) -> String {
    let s: String =
        label.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect();
    let s = s.trim_matches('_').to_string();
    if s.is_empty() { "object".into() } else { s }
}
