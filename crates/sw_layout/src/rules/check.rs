//! Measures a finished layout against its rules profile: one [`Violation`] per
//! shortfall, with the measured and required numbers and the standard they come from.

use sw_geom::{Aabb, Pose};
use sw_plan::{LaidOutScene, RelationKind, Support, Violation};

use super::{EgressGrid, Profile};
use crate::LayoutInput;
use crate::frames::Spot;
use crate::space::union;

/// An object standing on the floor, in world coordinates.
struct Standing {
    name: String,
    group: String,
    spot: Spot,
    local: Aabb,
    world: Aabb,
    tags: Vec<String>,
}

/// Every violation of `profile` in `scene`. `door_zone` is the doorway's keep-clear area.
pub fn check(input: &LayoutInput<'_>, scene: &LaidOutScene, profile: &Profile, door_zone: &Aabb) -> Vec<Violation> {
    let half = [scene.room.size.width / 2.0, scene.room.size.depth / 2.0];
    let mut standing: Vec<Standing> = Vec::new();
    for o in &scene.objects {
        if o.support != Support::Floor {
            continue;
        }
        let Some(item) = input.objects.iter().find(|x| x.name == o.name) else { continue };
        let local = union(&item.asset.collision_aabbs());
        let spot = Spot::new(o.pos[0], o.pos[1], o.pos[2], o.yaw);
        standing.push(Standing {
            name: o.name.clone(),
            group: o.group.clone(),
            world: local.transformed(&spot.pose()),
            spot,
            local,
            tags: item.tags.clone(),
        });
    }
    // Robots that stand on the floor are obstacles too.
    let mut robot_boxes: Vec<(String, Aabb)> = Vec::new();
    for r in &scene.robots {
        if r.mount != "floor" {
            continue;
        }
        if let Some(item) = input.robots.iter().find(|x| x.name == r.name) {
            let pose = Pose::from_pos_yaw(r.pos, r.yaw);
            robot_boxes.push((r.name.clone(), union(&item.keepout).transformed(&pose)));
        }
    }
    let requested_in_front = |culprit_group: &str, target_group: &str| {
        input.plan.relations.iter().any(|r| {
            r.subject == culprit_group
                && matches!(&r.kind, RelationKind::InFrontOf { target } if target == target_group)
        })
    };
    // A robot the prompt puts at something (next to, between, reaching, tending it) works
    // in its access space; so does the stand it is mounted on (`<robot group>_mount`).
    let robot_group_of = |name: &str| scene.robots.iter().find(|r| r.name == name).map(|r| r.group.clone());
    // What moves (a mobile robot, an arm on a mobile cart) passes through access space
    // rather than blocking it, as for the exit routes below.
    let moves = |culprit_group: &str| {
        let robot = culprit_group.strip_suffix("_mount").unwrap_or(culprit_group);
        input.plan.robot(robot).is_some_and(|r| r.mount == sw_plan::Mount::MobileBase)
            || input.robots.iter().any(|x| x.group == robot && !x.is_arm)
    };
    let works_at = |culprit_group: &str, target_group: &str| {
        let robot = culprit_group.strip_suffix("_mount").unwrap_or(culprit_group);
        moves(culprit_group)
            || input.plan.robot(robot).is_some()
                && input.plan.relations.iter().any(|r| {
                    r.subject == robot
                        && match &r.kind {
                            RelationKind::Between { first, second } => first == target_group || second == target_group,
                            k => k.targets().contains(&target_group),
                        }
                })
    };

    let put_at_wall = |group: &str| {
        input.plan.relations.iter().any(|r| {
            r.subject == group
                && matches!(
                    r.kind,
                    RelationKind::AgainstWall { .. }
                        | RelationKind::OnTwoWalls
                        | RelationKind::InCorner { .. }
                        | RelationKind::Leaning { .. }
                )
        })
    };

    let mut out = Vec::new();
    let mut access: Vec<(String, Aabb)> = Vec::new();
    for s in &standing {
        let c = profile.clearance(&s.tags);
        if c.is_empty() {
            continue;
        }
        let b = s.local;
        let width = (b.max[0] - b.min[0]).max(c.min_width);
        let cx = 0.5 * (b.min[0] + b.max[0]);
        // (side, depth, rule, zone in the object's frame)
        let sides = [
            (
                "front",
                c.front,
                &c.rule_front,
                Aabb { min: [cx - width / 2.0, b.max[1], 0.0], max: [cx + width / 2.0, b.max[1] + c.front, 2.0] },
            ),
            (
                "back",
                c.back,
                &c.rule_back,
                Aabb { min: [b.min[0], b.min[1] - c.back, 0.0], max: [b.max[0], b.min[1], 2.0] },
            ),
            (
                "left side",
                c.sides,
                &c.rule_sides,
                Aabb { min: [b.min[0] - c.sides, b.min[1], 0.0], max: [b.min[0], b.max[1], 2.0] },
            ),
            (
                "right side",
                c.sides,
                &c.rule_sides,
                Aabb { min: [b.max[0], b.min[1], 0.0], max: [b.max[0] + c.sides, b.max[1], 2.0] },
            ),
        ];
        let to_local = inverse(&s.spot);
        for (side, depth, rule, zone) in sides {
            let Some(rule) = rule else { continue };
            if depth <= 0.0 {
                continue;
            }
            if side == "front" {
                access.push((s.name.clone(), zone.transformed(&s.spot.pose())));
            }
            // Distance from the face to the first thing in the zone, in the object's frame.
            let face_dist = |r: &Aabb| -> Option<f64> {
                let overlap_x = r.min[0] < zone.max[0] - 1e-6 && zone.min[0] < r.max[0] - 1e-6;
                let overlap_y = r.min[1] < zone.max[1] - 1e-6 && zone.min[1] < r.max[1] - 1e-6;
                if !(overlap_x && overlap_y) {
                    return None;
                }
                Some(match side {
                    "front" => r.min[1] - b.max[1],
                    "back" => b.min[1] - r.max[1],
                    "left side" => b.min[0] - r.max[0],
                    _ => r.min[0] - b.max[0],
                })
            };
            let mut measured = depth;
            let mut culprit: Option<(String, bool)> = None;
            for o in standing.iter().filter(|o| o.name != s.name) {
                if let Some(d) = face_dist(&o.world.transformed(&to_local))
                    && d < measured
                {
                    measured = d.max(0.0);
                    culprit =
                        Some((o.name.clone(), requested_in_front(&o.group, &s.group) || works_at(&o.group, &s.group)));
                }
            }
            for (name, rb) in &robot_boxes {
                if let Some(d) = face_dist(&rb.transformed(&to_local))
                    && d < measured
                {
                    measured = d.max(0.0);
                    let requested = robot_group_of(name).is_some_and(|g| works_at(&g, &s.group));
                    culprit = Some((name.clone(), requested));
                }
            }
            // The walls: how far the zone reaches before leaving the room.
            let world_zone = zone.transformed(&s.spot.pose());
            let outside = (world_zone.max[0] - half[0])
                .max(-half[0] - world_zone.min[0])
                .max(world_zone.max[1] - half[1])
                .max(-half[1] - world_zone.min[1]);
            if outside > 1e-6 && depth - outside < measured {
                measured = (depth - outside).max(0.0);
                // "a machine against the wall" asks for its back (or side) to be at it.
                culprit = Some(("the wall".to_string(), put_at_wall(&s.group)));
            }
            if measured < depth - 1e-3 {
                let (who, requested) = culprit.unwrap_or_else(|| ("an obstacle".into(), false));
                let mut objects = vec![s.name.clone()];
                if who != "the wall" {
                    objects.push(who.clone());
                }
                out.push(Violation {
                    rule: rule.clone(),
                    objects,
                    measured: round_cm(measured),
                    required: depth,
                    unit: "m".into(),
                    standard: profile.standard_of(rule).to_string(),
                    message: format!(
                        "{}: {side} clearance {:.2} m of the {depth:.2} m required ({who} is in it)",
                        s.name, measured
                    ),
                    requested,
                });
            }
        }
    }

    // Egress: every working front reachable from the door by a wide enough route.
    if let Some((rule, width, standard)) = profile.egress()
        && !access.is_empty()
    {
        let grid = EgressGrid::new(half, width, door_zone);
        // Mobile robots move out of the way; arms on the floor do not.
        let arm = |name: &str| input.robots.iter().any(|x| x.name == name && x.is_arm);
        let obstacles: Vec<Aabb> = standing
            .iter()
            .map(|s| s.world)
            .chain(robot_boxes.iter().filter(|(n, _)| arm(n)).map(|(_, b)| *b))
            .collect();
        let zones: Vec<Aabb> = access.iter().map(|(_, z)| *z).collect();
        let widths = grid.route_widths(&obstacles, &zones);
        for ((name, _), w) in access.iter().zip(widths) {
            // The grid measures to within one cell; only clear shortfalls are reported.
            if w + 0.1 < width {
                out.push(Violation {
                    rule: rule.to_string(),
                    objects: vec![name.clone()],
                    measured: round_cm(w),
                    required: width,
                    unit: "m".into(),
                    standard: standard.to_string(),
                    message: format!(
                        "{name}: the widest route from the door to its working space is {w:.2} m, {width:.2} m required"
                    ),
                    requested: false,
                });
            }
        }
    }

    // Guards stand outside an arm's reach by the safety distance.
    if let Some((rule, tags, distance, standard)) = profile.fence_distance() {
        for r in &scene.robots {
            let Some(item) = input.robots.iter().find(|x| x.name == r.name).filter(|x| x.is_arm) else { continue };
            for f in standing.iter().filter(|s| tags.iter().all(|t| s.tags.contains(t))) {
                let dx = (f.world.min[0] - r.pos[0]).max(r.pos[0] - f.world.max[0]).max(0.0);
                let dy = (f.world.min[1] - r.pos[1]).max(r.pos[1] - f.world.max[1]).max(0.0);
                let beyond_reach = dx.hypot(dy) - item.reach;
                if beyond_reach < distance {
                    out.push(Violation {
                        rule: rule.to_string(),
                        objects: vec![f.name.clone(), r.name.clone()],
                        measured: round_cm(beyond_reach),
                        required: distance,
                        unit: "m".into(),
                        standard: standard.to_string(),
                        message: format!(
                            "{}: {:.2} m outside the reach of {}, {distance:.2} m required",
                            f.name, beyond_reach, r.name
                        ),
                        requested: false,
                    });
                }
            }
        }
    }

    // The robot's restricted space off the doorway.
    if let Some((rule, margin, standard)) = profile.robot_space() {
        for r in &scene.robots {
            let Some(item) = input.robots.iter().find(|x| x.name == r.name).filter(|x| x.is_arm) else { continue };
            let required = item.reach + margin;
            let dx = (door_zone.min[0] - r.pos[0]).max(r.pos[0] - door_zone.max[0]).max(0.0);
            let dy = (door_zone.min[1] - r.pos[1]).max(r.pos[1] - door_zone.max[1]).max(0.0);
            let d = dx.hypot(dy);
            if d < required {
                out.push(Violation {
                    rule: rule.to_string(),
                    objects: vec![r.name.clone()],
                    measured: round_cm(d),
                    required: round_cm(required),
                    unit: "m".into(),
                    standard: standard.to_string(),
                    message: format!(
                        "{}: the doorway is {d:.2} m from the robot, within its reach plus margin ({required:.2} m)",
                        r.name
                    ),
                    requested: false,
                });
            }
        }
    }
    out
}

/// The inverse of a planar pose.
fn inverse(s: &Spot) -> Pose {
    let rot = Pose::from_pos_yaw([0.0; 3], -s.yaw);
    let p = rot.apply([-s.x, -s.y, -s.z]);
    Pose { pos: p, quat: rot.quat }
}

fn round_cm(x: f64) -> f64 {
    (x * 100.0).round() / 100.0
}
