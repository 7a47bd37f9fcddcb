//! Anomaly injection: controlled, exactly labelled corruptions of a valid layout, for
//! training and evaluating anomaly detectors. Each label names the object, the kind, the
//! magnitude and the other object involved.

use sw_geom::{Aabb, Rng};
use sw_plan::{AnomalyKind, AnomalyLabel, AnomalyRequest, LaidOutScene, Stage, Support, Warning};

use crate::LayoutInput;
use crate::frames::Spot;
use crate::space::union;

/// An object of the scene with its world footprint.
struct Placed {
    index: usize,
    name: String,
    local: Aabb,
    world: Aabb,
    /// Collision boxes in the world.
    boxes: Vec<Aabb>,
    on_floor: bool,
    movable: bool,
}

/// Corrupts `scene` as requested and records a label per corruption. Scale anomalies
/// are labelled here and applied to the asset by the caller (`Asset::scaled`).
pub fn inject(input: &LayoutInput<'_>, scene: &mut LaidOutScene, request: &AnomalyRequest, seed: u64) -> Vec<Warning> {
    let mut warnings = Vec::new();
    let mut rng = Rng::derive(seed, "anomalies");
    let objects = placed(input, scene);
    // Robots are obstacles for anything moved: an anomaly must not push a robot.
    let robots: Vec<Aabb> = scene
        .robots
        .iter()
        .filter_map(|r| {
            let item = input.robots.iter().find(|x| x.name == r.name)?;
            Some(union(&item.keepout).transformed(&Spot::new(r.pos[0], r.pos[1], r.pos[2], r.yaw).pose()))
        })
        .collect();
    // Objects that carry others or robots are left alone: corrupting them would corrupt
    // more than the labelled object.
    let carrying: Vec<String> = scene
        .objects
        .iter()
        .filter_map(|o| match &o.support {
            Support::Object { object, .. } => Some(object.clone()),
            _ => None,
        })
        .chain(scene.robots.iter().filter_map(|r| r.mounted_on.clone()))
        .collect();
    let mut eligible: Vec<usize> = (0..objects.len()).filter(|&i| !carrying.contains(&objects[i].name)).collect();
    rng.shuffle(&mut eligible);
    let total =
        ((request.rate.clamp(0.0, 1.0) * eligible.len() as f64).round() as usize).max(usize::from(request.rate > 0.0));
    let total = total.min(eligible.len());
    if total == 0 || request.kinds.is_empty() {
        if request.rate > 0.0 {
            warnings.push(Warning::new(Stage::Layout, "anomaly_none", "no object could take an anomaly"));
        }
        return warnings;
    }
    let mut touched: Vec<String> = Vec::new();
    for (n, &i) in eligible.iter().take(total).enumerate() {
        let kind = request.kinds[n % request.kinds.len()];
        // Positions as they are now; objects already corrupted (or corrupted into) are
        // neither corrupted again nor used as the other party, so every label stays exact.
        let name = objects[i].name.clone();
        if touched.contains(&name) {
            continue;
        }
        let full = placed(input, scene);
        let now: Vec<Placed> =
            placed(input, scene).into_iter().filter(|p| p.name == name || !touched.contains(&p.name)).collect();
        let Some(o) = now.iter().find(|p| p.name == name) else { continue };
        let label = match kind {
            AnomalyKind::Floating => floating(scene, o, &mut rng),
            AnomalyKind::Overlap => overlap(scene, &now, o, &mut rng),
            AnomalyKind::Scale => scale(o, &mut rng),
            AnomalyKind::Misplacement => misplacement(scene, &full, &robots, o),
            AnomalyKind::RuleViolation => rule_violation(input, scene, &full, &robots, o),
        };
        match label {
            Some(l) => {
                touched.push(l.object.clone());
                touched.extend(l.with.clone());
                scene.anomalies.push(l);
            }
            None => warnings.push(Warning::new(
                Stage::Layout,
                "anomaly_skipped",
                format!("{name}: could not inject a {kind:?} anomaly"),
            )),
        }
    }
    warnings
}

fn placed(input: &LayoutInput<'_>, scene: &LaidOutScene) -> Vec<Placed> {
    scene
        .objects
        .iter()
        .enumerate()
        .filter_map(|(index, o)| {
            let item = input.objects.iter().find(|x| x.name == o.name)?;
            if item.carries_robot.is_some() {
                return None;
            }
            let pose = Spot::new(o.pos[0], o.pos[1], o.pos[2], o.yaw).pose();
            let boxes: Vec<Aabb> = item.asset.collision_aabbs().iter().map(|b| b.transformed(&pose)).collect();
            let local = union(&item.asset.collision_aabbs());
            let world = local.transformed(&pose);
            Some(Placed {
                index,
                name: o.name.clone(),
                local,
                world,
                boxes,
                on_floor: o.support == Support::Floor,
                movable: o.movable,
            })
        })
        .collect()
}

fn label(
    o: &Placed,
    kind: AnomalyKind,
    magnitude: f64,
    unit: &str,
    with: Option<String>,
    description: String,
) -> AnomalyLabel {
    AnomalyLabel {
        object: o.name.clone(),
        kind,
        magnitude: (magnitude * 1e4).round() / 1e4,
        unit: unit.into(),
        with,
        description,
    }
}

fn floating(scene: &mut LaidOutScene, o: &Placed, rng: &mut Rng) -> Option<AnomalyLabel> {
    let h = rng.range(0.1, 0.4);
    let room_h = scene.room.size.height;
    if o.world.max[2] + h > room_h {
        return None;
    }
    scene.objects[o.index].pos[2] += h;
    Some(label(o, AnomalyKind::Floating, h, "m", None, format!("raised {h:.2} m above its support")))
}

/// Pushes the object into the nearest collision box of another object beside it (at the
/// same height) until they interpenetrate by the labelled depth.
fn overlap(scene: &mut LaidOutScene, all: &[Placed], o: &Placed, rng: &mut Rng) -> Option<AnomalyLabel> {
    let depth = rng.range(0.03, 0.12);
    let (neighbour, target) = all
        .iter()
        .filter(|b| b.name != o.name)
        .flat_map(|b| b.boxes.iter().map(move |bx| (b, bx)))
        .filter(|(_, bx)| {
            let vertical = o.world.max[2].min(bx.max[2]) - o.world.min[2].max(bx.min[2]);
            vertical > 0.05 && gap(&o.world, bx) < 1.5 && gap(&o.world, bx) >= 0.0
        })
        .min_by(|a, b| gap(&o.world, a.1).total_cmp(&gap(&o.world, b.1)))?;
    let (mx, my) = approach(&o.world, target, depth);
    let p = &mut scene.objects[o.index].pos;
    p[0] += mx;
    p[1] += my;
    Some(label(
        o,
        AnomalyKind::Overlap,
        depth,
        "m",
        Some(neighbour.name.clone()),
        format!("pushed {depth:.3} m into {}", neighbour.name),
    ))
}

fn scale(o: &Placed, rng: &mut Rng) -> Option<AnomalyLabel> {
    // Items on shelves only shrink: grown, they would burst through the shelf above.
    let f = if !o.on_floor || rng.chance(0.5) { rng.range(0.45, 0.7) } else { rng.range(1.4, 1.9) };
    Some(label(o, AnomalyKind::Scale, f, "x", None, format!("scaled by {f:.2}")))
}

/// Moves an item off its support to the floor, or a floor object to the middle of the
/// room turned a quarter turn: a valid pose in the wrong place.
fn misplacement(scene: &mut LaidOutScene, all: &[Placed], robots: &[Aabb], o: &Placed) -> Option<AnomalyLabel> {
    let half = [scene.room.size.width / 2.0, scene.room.size.depth / 2.0];
    let s = o.local.size();
    let r = 0.5 * s[0].hypot(s[1]);
    let from = scene.objects[o.index].pos;
    // The free floor spot nearest the room's centre, on a coarse grid.
    let mut best: Option<(f64, [f64; 2])> = None;
    let step = 0.25;
    let mut x = -half[0] + r + 0.05;
    while x <= half[0] - r - 0.05 {
        let mut y = -half[1] + r + 0.05;
        while y <= half[1] - r - 0.05 {
            let spot = Aabb { min: [x - r, y - r, 0.0], max: [x + r, y + r, s[2]] };
            let free = is_free(&spot, all, robots, &o.name);
            let moved = (x - from[0]).hypot(y - from[1]);
            if free && moved > 1.0 {
                let score = x.hypot(y);
                if best.is_none_or(|(d, _)| score < d) {
                    best = Some((score, [x, y]));
                }
            }
            y += step;
        }
        x += step;
    }
    let (_, [x, y]) = best?;
    let obj = &mut scene.objects[o.index];
    let dz = -o.world.min[2];
    obj.pos =
        [x - (o.local.min[0] + o.local.max[0]) / 2.0, y - (o.local.min[1] + o.local.max[1]) / 2.0, obj.pos[2] + dz];
    obj.yaw = 0.0;
    obj.support = Support::Floor;
    let d = (obj.pos[0] - from[0]).hypot(obj.pos[1] - from[1]);
    let what =
        if o.on_floor { "moved to the middle of the room" } else { "taken off its support and left on the floor" };
    Some(label(o, AnomalyKind::Misplacement, d, "m", None, format!("{what}, {d:.2} m from where it belonged")))
}

/// Moves a small free item into the working space in front of equipment that needs it,
/// or into the doorway.
fn rule_violation(
    input: &LayoutInput<'_>,
    scene: &mut LaidOutScene,
    all: &[Placed],
    robots: &[Aabb],
    o: &Placed,
) -> Option<AnomalyLabel> {
    if !o.movable {
        return None;
    }
    let profile = crate::rules::profile(&input.plan.rules_profile)?;
    for e in all.iter().filter(|e| e.on_floor && e.name != o.name) {
        let item = input.objects.iter().find(|x| x.name == e.name)?;
        let c = profile.clearance(&item.tags);
        if c.front <= 0.0 {
            continue;
        }
        let eo = &scene.objects[e.index];
        let spot = Spot::new(eo.pos[0], eo.pos[1], eo.pos[2], eo.yaw);
        let s = o.local.size();
        let r = 0.5 * s[0].max(s[1]);
        // In the zone, its near face 60 % of the depth in, wherever along the front is free.
        let depth = c.front * 0.6;
        let half_w = 0.5 * (e.local.max[0] - e.local.min[0]);
        let free_centre = [0.0, -0.25, 0.25, -0.5, 0.5].iter().find_map(|f| {
            let c = spot.apply([
                0.5 * (e.local.min[0] + e.local.max[0]) + f * half_w,
                e.local.max[1] + c.front - depth + r,
                0.0,
            ]);
            let area = Aabb { min: [c[0] - r, c[1] - r, 0.0], max: [c[0] + r, c[1] + r, s[2]] };
            is_free(&area, all, robots, &o.name).then_some(c)
        });
        let Some(centre) = free_centre else { continue };
        let obj = &mut scene.objects[o.index];
        obj.pos = [
            centre[0] - (o.local.min[0] + o.local.max[0]) / 2.0,
            centre[1] - (o.local.min[1] + o.local.max[1]) / 2.0,
            -o.local.min[2],
        ];
        obj.yaw = 0.0;
        obj.support = Support::Floor;
        let rule = c.rule_front.unwrap_or_default();
        return Some(label(
            o,
            AnomalyKind::RuleViolation,
            depth,
            "m",
            Some(e.name.clone()),
            format!("placed {depth:.2} m into the {rule} space in front of {}", e.name),
        ));
    }
    None
}

/// The move of `a` that makes it penetrate `b` by `depth`: along the axis on which their
/// centres are furthest apart, with the other axis brought into line.
fn approach(a: &Aabb, b: &Aabb, depth: f64) -> (f64, f64) {
    let (ca, cb) = (a.center(), b.center());
    let (cx, cy) = (cb[0] - ca[0], cb[1] - ca[1]);
    if cx.abs() >= cy.abs() {
        let touch = if cx >= 0.0 { b.min[0] - a.max[0] + depth } else { b.max[0] - a.min[0] - depth };
        (touch, cy)
    } else {
        let touch = if cy >= 0.0 { b.min[1] - a.max[1] + depth } else { b.max[1] - a.min[1] - depth };
        (cx, touch)
    }
}

/// True when `area` keeps 5 cm from every object but `except` and from every robot.
fn is_free(area: &Aabb, all: &[Placed], robots: &[Aabb], except: &str) -> bool {
    all.iter().filter(|b| b.name != except).all(|b| gap(area, &b.world) > 0.05)
        && robots.iter().all(|r| gap(area, r) > 0.05)
}

fn gap(a: &Aabb, b: &Aabb) -> f64 {
    let dx = (b.min[0] - a.max[0]).max(a.min[0] - b.max[0]);
    let dy = (b.min[1] - a.max[1]).max(a.min[1] - b.max[1]);
    if dx < 0.0 && dy < 0.0 { dx.max(dy) } else { dx.max(0.0).hypot(dy.max(0.0)) }
}
