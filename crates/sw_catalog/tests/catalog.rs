#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The catalog's contract, checked for every category over many seeds and sizes: valid
//! watertight visuals, primitive collision resting on z = 0, the requested size, support
//! surfaces that touch their geometry and are free above, determinism, masses, and the
//! registry's names and synonyms.

use std::collections::HashSet;

use proptest::prelude::*;
use sw_catalog::{AssetRequest, CatalogError, Category, categories, find, generate};
use sw_geom::{Aabb, Asset, MassModel};

/// How far the overall size may differ from `width`, `depth`, `height`, m.
const SIZE_TOL: f64 = 0.01;
/// How far visual-only decoration may stand out of the collision geometry, m.
const DECAL_TOL: f64 = 0.005;
/// f32 rounding of visual vertices a few metres from the origin.
const F32_TOL: f64 = 2e-6;
/// Margin that keeps touching faces from counting as intrusions.
const EPS: f64 = 1e-6;

fn collision_bounds(a: &Asset) -> Aabb {
    a.collision_aabbs().iter().fold(Aabb::EMPTY, |acc, b| acc.union(b))
}

fn visual_bounds(a: &Asset) -> Aabb {
    let poses = a.link_poses();
    let mut out = Aabb::EMPTY;
    for (link, pose) in a.links.iter().zip(&poses) {
        for v in &link.visuals {
            out = out.union(&v.mesh.bounds().transformed(pose));
        }
    }
    out
}

/// Everything the layout, the MJCF writer and MuJoCo rely on. Returns what is wrong.
fn problems(cat: &Category, a: &Asset) -> Vec<String> {
    let mut out = Vec::new();
    let mut bad = |cond: bool, msg: String| {
        if !cond {
            out.push(msg);
        }
    };
    bad(a.category == cat.name, format!("category is {}", a.category));
    bad(a.placement == cat.placement, format!("placement {:?}", a.placement));
    // Moving parts: each hangs from an earlier link by a limited, damped joint.
    for (i, link) in a.links.iter().enumerate().skip(1) {
        bad(link.parent.is_some_and(|p| p < i), format!("link '{}' has parent {:?}", link.name, link.parent));
        bad(
            !link.name.is_empty() && !link.collisions.is_empty(),
            format!("link {i} '{}' is unnamed or empty", link.name),
        );
        bad(link.mass.is_finite() && link.mass > 0.0, format!("link '{}' mass {}", link.name, link.mass));
        match link.joint {
            Some(j) => {
                let norm = j.axis.iter().map(|v| v * v).sum::<f64>().sqrt();
                bad((norm - 1.0).abs() < 1e-9, format!("link '{}' axis {:?}", link.name, j.axis));
                bad(
                    j.range[0] <= 0.0 && 0.0 <= j.range[1] && j.range[1] > j.range[0],
                    format!("link '{}' range {:?} excludes its closed state", link.name, j.range),
                );
                bad(j.damping > 0.0, format!("link '{}' is undamped", link.name));
            }
            None => bad(false, format!("link '{}' has no joint", link.name)),
        }
    }
    bad(a.links.first().is_some_and(|l| l.parent.is_none() && l.joint.is_none()), "root link is not a root".into());
    // No two links touch at joint value zero: MuJoCo checks contacts between a moving
    // part and a static carcass, and between sibling parts.
    let poses = a.link_poses();
    let per_link: Vec<Vec<Aabb>> = a
        .links
        .iter()
        .zip(&poses)
        .map(|(l, p)| l.collisions.iter().map(|c| c.aabb().transformed(p)).collect())
        .collect();
    for i in 0..per_link.len() {
        for j in i + 1..per_link.len() {
            for x in &per_link[i] {
                for y in &per_link[j] {
                    let overlap = (0..3).all(|k| x.min[k] < y.max[k] - EPS && y.min[k] < x.max[k] - EPS);
                    bad(!overlap, format!("links {i} and {j} overlap: {x:?} {y:?}"));
                }
            }
        }
    }

    // Parameters: declared ones, in order, within range.
    let names: Vec<&str> = a.params.iter().map(|(n, _)| n.as_str()).collect();
    let declared: Vec<&str> = cat.params.iter().map(|p| p.name).collect();
    bad(names == declared, format!("params {names:?} vs declared {declared:?}"));
    for (def, (_, v)) in cat.params.iter().zip(&a.params) {
        bad(
            v.is_finite() && *v >= def.min && *v <= def.max,
            format!("param {} = {v} outside {}..{}", def.name, def.min, def.max),
        );
    }
    let size = [a.param("width"), a.param("depth"), a.param("height")].map(|v| v.unwrap_or(f64::NAN));

    // Visuals: watertight solids in known materials, and something to recolour.
    let visuals: Vec<_> = a.links.iter().flat_map(|l| &l.visuals).collect();
    bad(!visuals.is_empty(), "no visuals".into());
    for v in &visuals {
        let check = v.mesh.check();
        let name = a.materials.get(v.material).map_or("?", |m| m.name.as_str());
        bad(v.material < a.materials.len(), format!("visual uses material {} of {}", v.material, a.materials.len()));
        bad(check.is_valid_solid(), format!("visual '{name}' is not a valid solid: {check:?}"));
    }
    bad(a.materials.iter().any(|m| m.recolorable), "no recolourable material".into());
    let mut material_names = HashSet::new();
    for m in &a.materials {
        bad(material_names.insert(m.name.as_str()), format!("material '{}' twice", m.name));
    }

    // Collision: well-formed primitives, resting on z = 0, of the requested size.
    let aabbs = a.collision_aabbs();
    bad(!aabbs.is_empty(), "no collision".into());
    for c in a.links.iter().flat_map(|l| &l.collisions) {
        bad(c.shape.is_well_formed(), format!("malformed collision {:?}", c.shape));
    }
    let cb = collision_bounds(a);
    // Wall-mounted things hang at their mounting height above the origin on the floor.
    let lift = a.param("mount_height").unwrap_or(0.0);
    bad((cb.min[2] - lift).abs() <= 1e-9, format!("lowest collision point at z = {}, not {lift}", cb.min[2]));
    let cs = cb.size();
    let fb = a.bounds();
    let fs = fb.size();
    for (i, axis) in ["width", "depth", "height"].iter().enumerate() {
        bad((cs[i] - size[i]).abs() <= SIZE_TOL, format!("collision {axis} {:.4} vs param {:.4}", cs[i], size[i]));
        bad(
            (fs[i] - size[i]).abs() <= SIZE_TOL + DECAL_TOL,
            format!("overall {axis} {:.4} vs param {:.4}", fs[i], size[i]),
        );
    }
    bad(
        cb.center()[0].abs() < 0.005 && cb.center()[1].abs() < 0.005,
        format!("footprint not centred: {:?}", cb.center()),
    );
    let vb = visual_bounds(a);
    for i in 0..3 {
        bad(
            cb.min[i] - vb.min[i] <= DECAL_TOL + F32_TOL,
            format!("visuals stick out {:.4} below axis {i}", cb.min[i] - vb.min[i]),
        );
        bad(
            vb.max[i] - cb.max[i] <= DECAL_TOL + F32_TOL,
            format!("visuals stick out {:.4} above axis {i}", vb.max[i] - cb.max[i]),
        );
    }

    // Support surfaces: on top of a primitive that holds the whole rectangle, inside the
    // footprint, and with nothing colliding above them up to their clearance.
    let mut surface_names = HashSet::new();
    for s in &a.surfaces {
        bad(surface_names.insert(s.name.as_str()), format!("surface '{}' twice", s.name));
        bad(s.area() > 0.0, format!("surface '{}' has no area", s.name));
        bad(s.z.is_finite() && s.z > 0.0 && s.z <= cb.max[2], format!("surface '{}' at z = {}", s.name, s.z));
        for k in 0..2 {
            bad(
                s.min[k] >= cb.min[k] - 1e-9 && s.max[k] <= cb.max[k] + 1e-9,
                format!("surface '{}' leaves the footprint on axis {k}", s.name),
            );
        }
        let centre = [(s.min[0] + s.max[0]) / 2.0, (s.min[1] + s.max[1]) / 2.0];
        let holds = |b: &&Aabb| (0..2).all(|k| b.min[k] <= s.min[k] + 1e-9 && b.max[k] >= s.max[k] - 1e-9);
        let covers_centre = |b: &&Aabb| (0..2).all(|k| b.min[k] <= centre[k] && b.max[k] >= centre[k]);
        let under: Vec<&Aabb> = aabbs.iter().filter(|b| b.max[2] == s.z).collect();
        bad(
            under.iter().any(covers_centre),
            format!("surface '{}' at z = {} is not the top of a primitive under its centre", s.name, s.z),
        );
        bad(under.iter().any(holds), format!("surface '{}' is not within the deck that carries it", s.name));
        if let Some(c) = s.clearance {
            bad(c > 0.05, format!("surface '{}' has clearance {c}", s.name));
        }
        let top = s.z + s.clearance.unwrap_or(f64::INFINITY);
        for b in &aabbs {
            let intrudes = b.min[0] < s.max[0] - EPS
                && b.max[0] > s.min[0] + EPS
                && b.min[1] < s.max[1] - EPS
                && b.max[1] > s.min[1] + EPS
                && b.min[2] < top - EPS
                && b.max[2] > s.z + EPS;
            bad(
                !intrudes,
                format!("collision {b:?} intrudes above surface '{}' (z {}, clearance {:?})", s.name, s.z, s.clearance),
            );
        }
    }

    match (cat.movable, a.mass) {
        (true, MassModel::Free { mass }) => bad(mass.is_finite() && mass > 0.0, format!("mass {mass}")),
        (false, MassModel::Static) => {}
        (movable, mass) => out.push(format!("movable {movable} but mass model {mass:?}")),
    }
    out
}

fn assert_valid(cat: &Category, req: &AssetRequest) -> Asset {
    let a = generate(req).unwrap_or_else(|e| panic!("{} seed {}: {e}", cat.name, req.seed));
    let p = problems(cat, &a);
    assert!(
        p.is_empty(),
        "{} seed {} scale {:?} overrides {:?}:\n  {}",
        cat.name,
        req.seed,
        req.scale,
        req.overrides,
        p.join("\n  ")
    );
    a
}

#[test]
fn every_category_and_seed_gives_a_valid_asset() {
    for cat in categories() {
        for seed in 0..20 {
            let a = assert_valid(cat, &AssetRequest::new(cat.name, seed));
            // Seeded defaults always fit together: nothing to correct.
            assert!(a.notes.is_empty(), "{} seed {seed}: {:?}", cat.name, a.notes);
            if let MassModel::Free { mass } = a.mass {
                assert!((0.005..200.0).contains(&mass), "{} seed {seed}: mass {mass} kg", cat.name);
            }
        }
    }
}

#[test]
fn same_request_gives_the_same_asset_and_seeds_vary_it() {
    for cat in categories() {
        for seed in [0, 1, 7, 12345, u64::MAX] {
            let mut req = AssetRequest::new(cat.name, seed);
            req.scale = Some([1.1, 0.9, 1.05]);
            req.color = Some([0.8, 0.1, 0.1, 1.0]);
            assert_eq!(generate(&req).unwrap(), generate(&req).unwrap(), "{} seed {seed}", cat.name);
        }
        // Variation: the seed changes proportions, colours or parts.
        let looks: HashSet<String> = (0..20)
            .map(|seed| {
                let a = generate(&AssetRequest::new(cat.name, seed)).unwrap();
                format!("{:?} {:?}", a.params, a.materials)
            })
            .collect();
        assert!(looks.len() > 1, "{} looks the same for every seed", cat.name);
    }
}

#[test]
fn registry_names_synonyms_tags_and_params_are_consistent() {
    let all = categories();
    assert_eq!(all[0].name, "table");
    assert_eq!(all[1].name, "cardboard_box");
    let mut names = HashSet::new();
    let mut phrases = HashSet::new();
    for cat in all {
        assert!(names.insert(cat.name), "category {} twice", cat.name);
        assert!(cat.name.chars().all(|c| c.is_ascii_lowercase() || c == '_'), "{}", cat.name);
        assert_eq!(find(cat.name).map(|c| c.name), Some(cat.name));
        assert!(phrases.insert(cat.display.to_string()), "display '{}' clashes", cat.display);
        assert!(
            phrases.insert(cat.name.replace('_', " ")) || cat.display == cat.name.replace('_', " "),
            "{}",
            cat.name
        );
        assert!(!cat.synonyms.is_empty(), "{} has no synonym", cat.name);
        assert!(!cat.tags.is_empty(), "{} has no tag", cat.name);
        for t in cat.tags {
            assert!(t.chars().all(|c| c.is_ascii_lowercase() || c == '_'), "{}: tag '{t}'", cat.name);
        }
        let p: Vec<&str> = cat.params.iter().take(3).map(|p| p.name).collect();
        assert_eq!(p, ["width", "depth", "height"], "{}", cat.name);
        for def in cat.params {
            assert!(def.min <= def.default && def.default <= def.max, "{} {}", cat.name, def.name);
            assert!(def.min > 0.0 || def.name.starts_with("fill"), "{} {} may be zero", cat.name, def.name);
            assert!((0.0..1.0).contains(&def.vary), "{} {}", cat.name, def.name);
        }
        assert!(cat.default_size().iter().all(|v| *v > 0.0));
    }
    for cat in all {
        for s in cat.synonyms {
            assert_eq!(*s, s.to_lowercase(), "{}: synonym '{s}' is not lowercase", cat.name);
            assert_eq!(*s, s.trim(), "{}: synonym '{s}'", cat.name);
            assert!(phrases.insert(s.to_string()), "{}: synonym '{s}' is used twice", cat.name);
        }
    }
}

#[test]
fn every_category_says_what_it_is_and_what_it_is_a_kind_of() {
    for cat in categories() {
        assert!(cat.description.split_whitespace().count() >= 3, "{}: description '{}'", cat.name, cat.description);
        assert_eq!(cat.description, cat.description.trim(), "{}", cat.name);
        assert!(!cat.is_a.is_empty(), "{} is a kind of nothing", cat.name);
        for h in cat.is_a {
            assert_eq!(*h, h.to_lowercase(), "{}: is-a '{h}'", cat.name);
            assert!(!h.is_empty() && *h != cat.display, "{}: is-a '{h}'", cat.name);
        }
        assert_eq!(sw_catalog::Kind::from_name(cat.kind.name()), Some(cat.kind), "{}", cat.name);
        // A category's kind agrees with what it is: free things have an on-surface prior.
        let prior = cat.kind.prior();
        assert!(prior.size.iter().all(|v| *v > 0.0));
    }
}

/// A Panda's fingers open 8 cm: a mug is grasped around its body, so the body of every
/// default mug is at most 8 cm across, and a mug asked for narrower than its body and
/// handle (an "8 cm mug") is made narrower instead of being widened to 12 cm.
#[test]
fn a_mug_body_fits_a_panda_gripper_and_narrow_mugs_stay_narrow() {
    for seed in 0..40 {
        let a = generate(&AssetRequest::new("mug", seed)).unwrap();
        let body = a.param("depth").unwrap();
        assert!(body <= 0.0805, "seed {seed}: mug body {body}");
        assert!(a.notes.is_empty(), "{:?}", a.notes);
    }
    let mut req = AssetRequest::new("mug", 3);
    req.overrides = vec![("width".into(), 0.09)];
    let a = assert_valid(find("mug").unwrap(), &req);
    let s = a.bounds().size();
    assert!((s[0] - 0.09).abs() < 0.002 && s[1] <= 0.0605, "{s:?}");
    assert!(a.notes.is_empty(), "an in-range width needs no note: {:?}", a.notes);
}

#[test]
fn everyday_doors_drawers_and_lids_open() {
    use sw_geom::JointKind;
    for (name, kind, moving) in [
        ("dishwasher", JointKind::Hinge, 1),
        ("toaster_oven", JointKind::Hinge, 1),
        ("washing_machine", JointKind::Hinge, 1),
        ("tumble_dryer", JointKind::Hinge, 1),
        ("chest_freezer", JointKind::Hinge, 1),
        ("wardrobe", JointKind::Hinge, 2),
        ("dresser", JointKind::Slide, 3),
        ("nightstand", JointKind::Slide, 2),
        ("toy_chest", JointKind::Hinge, 1),
        ("display_fridge", JointKind::Hinge, 1),
    ] {
        let a = generate(&AssetRequest::new(name, 0)).unwrap();
        let joints: Vec<_> = a.links.iter().filter_map(|l| l.joint).filter(|j| j.kind == kind).collect();
        assert!(joints.len() >= moving, "{name}: {} {kind:?} joints", joints.len());
        assert!(joints.iter().all(|j| j.range[1] > 0.5 || kind == JointKind::Slide), "{name}: {joints:?}");
    }
}

#[test]
fn out_of_range_overrides_are_clamped_with_a_note() {
    for cat in categories() {
        let mut req = AssetRequest::new(cat.name, 3);
        let max = cat.param("height").unwrap().max;
        let min = cat.param("width").unwrap().min;
        req.overrides = vec![("height".into(), max * 10.0), ("width".into(), min / 10.0)];
        let a = assert_valid(cat, &req);
        // A cube or a ball has one size: its height follows its width.
        let height = if cat.has_tag("uniform") { min } else { max };
        assert_eq!(a.param("height"), Some(height), "{}", cat.name);
        assert_eq!(a.param("width"), Some(min), "{}", cat.name);
        assert!(a.notes.iter().any(|n| n.contains("height")), "{}: {:?}", cat.name, a.notes);
        assert!(a.notes.iter().any(|n| n.contains("width")), "{}: {:?}", cat.name, a.notes);
    }
}

#[test]
fn unknown_category_unknown_param_and_non_finite_values_are_errors() {
    assert_eq!(generate(&AssetRequest::new("spaceship", 0)), Err(CatalogError::UnknownCategory("spaceship".into())));
    let mut req = AssetRequest::new("shelf", 0);
    req.overrides = vec![("wingspan".into(), 1.0)];
    assert!(matches!(generate(&req), Err(CatalogError::UnknownParam { param, .. }) if param == "wingspan"));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        req.overrides = vec![("height".into(), bad)];
        assert!(matches!(generate(&req), Err(CatalogError::NotFinite { param, .. }) if param == "height"), "{bad}");
    }
}

#[test]
fn a_colour_applies_to_the_recolourable_materials() {
    for cat in categories() {
        let mut req = AssetRequest::new(cat.name, 2);
        req.color = Some([0.9, 0.1, 0.1, 1.0]);
        let a = generate(&req).unwrap();
        for m in &a.materials {
            assert_eq!(m.rgba == [0.9, 0.1, 0.1, 1.0], m.recolorable, "{} material {}", cat.name, m.name);
        }
    }
}

fn surface_names(a: &Asset) -> Vec<&str> {
    a.surfaces.iter().map(|s| s.name.as_str()).collect()
}

#[test]
fn shelves_have_a_surface_per_level_with_clearance_to_the_next() {
    for levels in 3..=6 {
        for seed in 0..5 {
            let mut req = AssetRequest::new("shelf", seed);
            req.overrides = vec![("levels".into(), levels as f64)];
            let a = generate(&req).unwrap();
            let expected: Vec<String> = (1..=levels).map(|i| format!("level_{i}")).collect();
            assert_eq!(surface_names(&a), expected);
            for pair in a.surfaces.windows(2) {
                let c = pair[0].clearance.unwrap();
                assert!(pair[1].z > pair[0].z + c - 1e-9 && c > 0.05, "{:?}", a.surfaces);
            }
            assert_eq!(a.surfaces.last().unwrap().clearance, None);
            assert!((a.surfaces.last().unwrap().z - a.param("height").unwrap()).abs() < 1e-9);
        }
    }
}

#[test]
fn pallet_racks_have_beam_levels_and_an_industrial_size() {
    let cat = find("pallet_rack").unwrap();
    assert_eq!(cat.default_size(), [2.7, 1.1, 4.5]);
    for seed in 0..20 {
        let a = generate(&AssetRequest::new("pallet_rack", seed)).unwrap();
        let n = a.param("levels").unwrap().round() as usize;
        assert!((2..=4).contains(&n));
        assert_eq!(a.surfaces.len(), n);
        assert!(a.surfaces.iter().all(|s| s.max[0] - s.min[0] > 2.2 && s.max[1] - s.min[1] > 0.9));
        // A pallet load fits between levels.
        assert!(a.surfaces.iter().filter_map(|s| s.clearance).all(|c| c > 0.7), "{:?}", a.surfaces);
    }
}

#[test]
fn workbench_has_a_top_and_a_lower_shelf_under_it() {
    let a = generate(&AssetRequest::new("workbench", 4)).unwrap();
    assert_eq!(surface_names(&a), ["top", "lower_shelf"]);
    let (top, shelf) = (&a.surfaces[0], &a.surfaces[1]);
    assert!(shelf.z + shelf.clearance.unwrap() < top.z);
    assert!(top.clearance.is_none());
}

#[test]
fn the_bin_is_open_and_light_and_the_pallet_is_a_eur_pallet() {
    let bin = generate(&AssetRequest::new("bin", 0)).unwrap();
    assert!(bin.links[0].collisions.len() >= 5, "a bottom and four walls");
    let inside = &bin.surfaces[0];
    assert_eq!((inside.name.as_str(), inside.clearance), ("inside", None));
    assert!(inside.z < 0.05 && inside.area() > 0.15);
    let MassModel::Free { mass } = bin.mass else { panic!("a bin is movable") };
    assert!((1.0..2.5).contains(&mass), "{mass}");

    let pallet = generate(&AssetRequest::new("pallet", 0)).unwrap();
    let size = pallet.bounds().size();
    assert!((size[0] - 1.2).abs() < 1e-6 && (size[1] - 0.8).abs() < 0.002 && (size[2] - 0.144).abs() < 1e-6);
    let MassModel::Free { mass } = pallet.mass else { panic!("a pallet is movable") };
    assert!((20.0..30.0).contains(&mass), "{mass}");
    assert_eq!(surface_names(&pallet), ["top"]);
}

#[test]
fn the_chair_faces_plus_y_with_its_backrest_behind() {
    for seed in 0..10 {
        let a = generate(&AssetRequest::new("chair", seed)).unwrap();
        let aabbs = a.collision_aabbs();
        let highest = aabbs.iter().max_by(|a, b| a.max[2].total_cmp(&b.max[2])).unwrap();
        assert!(highest.center()[1] < 0.0, "backrest at {:?}", highest.center());
    }
}

#[test]
fn conveyor_belt_and_cart_deck_are_at_working_height() {
    let conveyor = generate(&AssetRequest::new("conveyor", 0)).unwrap();
    let belt = &conveyor.surfaces[0];
    assert_eq!(belt.name, "belt");
    assert!((belt.z - 0.8).abs() < 0.05 && belt.max[0] - belt.min[0] > 2.0);
    let cart = generate(&AssetRequest::new("mobile_cart", 0)).unwrap();
    assert!((cart.surfaces[0].z - 0.45).abs() < 0.05);
    let pedestal = generate(&AssetRequest::new("pedestal", 0)).unwrap();
    assert_eq!(surface_names(&pedestal), ["top"]);
    assert!(find("electrical_panel").unwrap().has_tag("electrical"));
    assert!(find("machine").unwrap().has_tag("machine"));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn any_scale_gives_valid_assets(
        index in 0usize..1024,
        sx in 0.2f64..5.0,
        sy in 0.2f64..5.0,
        sz in 0.2f64..5.0,
        seed in any::<u64>(),
    ) {
        let all = categories();
        let cat = &all[index % all.len()];
        let mut req = AssetRequest::new(cat.name, seed);
        req.scale = Some([sx, sy, sz]);
        let a = generate(&req).unwrap();
        let p = problems(cat, &a);
        prop_assert!(p.is_empty(), "{} seed {seed} scale {:?}:\n  {}", cat.name, req.scale, p.join("\n  "));
    }

    #[test]
    fn any_in_range_parameters_give_valid_assets(
        index in 0usize..1024,
        fractions in proptest::collection::vec(0.0f64..=1.0, 8),
        seed in any::<u64>(),
    ) {
        let all = categories();
        let cat = &all[index % all.len()];
        let mut req = AssetRequest::new(cat.name, seed);
        req.overrides = cat
            .params
            .iter()
            .zip(&fractions)
            .map(|(def, f)| (def.name.to_string(), def.min + (def.max - def.min) * f))
            .collect();
        let a = generate(&req).unwrap();
        let p = problems(cat, &a);
        prop_assert!(p.is_empty(), "{} seed {seed} overrides {:?}:\n  {}", cat.name, req.overrides, p.join("\n  "));
    }

    /// Any values at all — zero, negative, huge, NaN, infinite — give a valid asset with a
    /// note for each value that had to move, or (for non-finite ones) a clear error.
    #[test]
    fn any_parameter_values_give_a_valid_asset_or_a_clear_error(
        index in 0usize..1024,
        values in proptest::collection::vec(
            prop_oneof![
                Just(0.0),
                Just(-1.0),
                Just(f64::NAN),
                Just(f64::INFINITY),
                Just(1e12),
                -5.0f64..5.0,
                any::<f64>(),
            ],
            8,
        ),
        seed in any::<u64>(),
    ) {
        let all = categories();
        let cat = &all[index % all.len()];
        let mut req = AssetRequest::new(cat.name, seed);
        req.overrides = cat.params.iter().zip(&values).map(|(def, v)| (def.name.to_string(), *v)).collect();
        match generate(&req) {
            Ok(a) => {
                let p = problems(cat, &a);
                prop_assert!(p.is_empty(), "{} {:?}:\n  {}", cat.name, req.overrides, p.join("\n  "));
                for (def, v) in cat.params.iter().zip(&values) {
                    let off = (def.min - v).max(v - def.max);
                    if off > 1e-9 * v.abs().max(1.0) {
                        prop_assert!(
                            a.notes.iter().any(|n| n.contains(def.name)),
                            "{} {} = {v}: no note in {:?}", cat.name, def.name, a.notes
                        );
                    }
                }
            }
            Err(CatalogError::NotFinite { param, value, .. }) => {
                prop_assert!(!value.is_finite(), "{} {param} = {value}", cat.name);
                prop_assert!(values.iter().any(|v| !v.is_finite()));
            }
            Err(e) => prop_assert!(false, "{}: unexpected error {e}", cat.name),
        }
    }

    /// A scale must be three positive finite numbers; anything else is refused.
    #[test]
    fn bad_scales_are_refused_and_good_ones_clamped(
        index in 0usize..1024,
        scale in proptest::array::uniform3(prop_oneof![Just(0.0), Just(-2.0), Just(f64::NAN), 0.01f64..100.0]),
        seed in any::<u64>(),
    ) {
        let all = categories();
        let cat = &all[index % all.len()];
        let mut req = AssetRequest::new(cat.name, seed);
        req.scale = Some(scale);
        let ok = scale.iter().all(|s| s.is_finite() && *s > 0.0);
        match generate(&req) {
            Ok(a) => {
                prop_assert!(ok, "{} accepted scale {scale:?}", cat.name);
                let p = problems(cat, &a);
                prop_assert!(p.is_empty(), "{} scale {scale:?}:\n  {}", cat.name, p.join("\n  "));
            }
            Err(e) => {
                prop_assert!(!ok, "{} refused scale {scale:?}: {e}", cat.name);
                prop_assert!(matches!(e, CatalogError::BadScale { .. }), "{}: {}", cat.name, e);
            }
        }
    }
}

#[test]
fn a_category_admits_the_sizes_of_its_kind_and_not_those_of_other_things() {
    for c in categories() {
        let d = c.default_size();
        assert!(c.admits_size([None; 3]), "{}: nothing stated", c.name);
        assert!(c.admits_size(d.map(Some)), "{}: its default size", c.name);
        for axis in 0..3 {
            let name = ["width", "depth", "height"][axis];
            let Some(p) = c.param(name) else { continue };
            let side = |v: f64| {
                let mut s = [None; 3];
                s[axis] = Some(v);
                s
            };
            // A little out of range is the thing, clamped; far out of it is another thing.
            assert!(c.admits_size(side(p.min * 0.9)) && c.admits_size(side(p.max * 1.1)), "{}: {name}", c.name);
            assert!(p.min <= 0.0 || !c.admits_size(side(p.min / 10.0)), "{}: {name} a tenth of its least", c.name);
            assert!(!c.admits_size(side(p.max * 10.0)), "{}: {name} ten times its most", c.name);
        }
    }
    let washer = find("washing_machine").unwrap();
    assert!(!washer.admits_size([Some(0.02), Some(0.02), Some(0.002)]), "a flat washer is no washing machine");
}

/// The MJCF writer gives a free body the inertia of its collision box, each principal value
/// written rounded (`sw_mjcf::xml::sig`: six decimals, five significant digits below 1e-3).
/// For a thin, wide, heavy thing (a placemat) `A + B - C` is `m h² / 6`, smaller than that
/// rounding: MuJoCo then refuses the model (A + B >= C). Every free category at every seed
/// keeps its inertia valid as written.
#[test]
fn every_free_body_keeps_its_inertia_valid_as_written() {
    let written = |v: f64| sw_mjcf::xml::sig(v).parse::<f64>().unwrap();
    for cat in categories().iter().filter(|c| c.movable) {
        for seed in 0..20 {
            let a = generate(&AssetRequest::new(cat.name, seed)).unwrap();
            let MassModel::Free { mass } = a.mass else { continue };
            if a.links.len() != 1 {
                continue;
            }
            let s = collision_bounds(&a).size();
            let i = [
                mass / 12.0 * (s[1] * s[1] + s[2] * s[2]),
                mass / 12.0 * (s[0] * s[0] + s[2] * s[2]),
                mass / 12.0 * (s[0] * s[0] + s[1] * s[1]),
            ]
            .map(|v| written(v.max(1e-7)));
            for c in 0..3 {
                let (x, y) = ((c + 1) % 3, (c + 2) % 3);
                assert!(
                    i[x] + i[y] >= i[c],
                    "{} seed {seed}: inertia {i:?} as written (mass {mass}, size {s:?}) breaks A + B >= C",
                    cat.name
                );
            }
        }
    }
}
