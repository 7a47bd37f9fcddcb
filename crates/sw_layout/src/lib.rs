//! L3: the layout. Places every object and robot of a plan: inside the room, with no
//! overlap between collision geometry, small items resting on the surfaces they are said
//! to be on, relations honoured where they can be, robots at collision-free spawns facing
//! their work. What cannot be placed is reported, never overlapped.
//!
//! The solver is greedy and deterministic in (plan, assets, seed): objects are placed in
//! dependency order (targets before the things related to them), each at the first
//! candidate pose that passes the collision test, candidates ordered by how well they
//! satisfy the object's relations, with seeded variation among equals. When a room whose
//! size the user did not fix is too small, it grows and the layout starts again.

mod anomaly;
mod attempt;
mod candidates;
pub mod fill;
mod floor;
mod formation;
mod frames;
mod guards;
mod order;
mod pinned;
mod reach;
mod relate;
mod robots;
pub mod rules;
mod space;
mod surface;

pub use anomaly::inject as inject_anomalies;
pub use pinned::{Pins, solve_pinned};
use sw_geom::{Aabb, Asset};
use sw_plan::{LaidOutScene, ScenePlan, Stage, Warning};

/// One object instance to place.
#[derive(Debug, Clone)]
pub struct ObjectItem<'a> {
    /// Final name: `<category>_<n>`.
    pub name: String,
    /// Plan group id.
    pub group: String,
    pub category: String,
    /// What a person calls it.
    pub label: String,
    pub asset: &'a Asset,
    /// Catalog tags (storage, tall, machine, electrical, tabletop, surface …).
    pub tags: Vec<String>,
    /// Set when this object exists to carry a robot (a pedestal or a cart).
    pub carries_robot: Option<String>,
}

impl ObjectItem<'_> {
    pub fn has_tag(&self, tag: &str) -> bool {
        self.tags.iter().any(|t| t == tag)
    }
}

/// How a robot is held.
#[derive(Debug, Clone, PartialEq)]
pub enum RobotMount {
    /// On the floor (mobile bases, or arms on their own base plate).
    Floor,
    /// On the top surface of an instance of this plan group.
    Surface { group: String },
    /// On the object with this name (a pedestal or cart made for it).
    Carrier { object: String },
}

/// One robot instance to place.
#[derive(Debug, Clone)]
pub struct RobotItem {
    pub name: String,
    pub group: String,
    pub model: String,
    pub is_arm: bool,
    /// Boxes containing the robot at home, in its base frame (it works towards +X).
    pub keepout: Vec<Aabb>,
    pub base_radius: f64,
    pub reach: f64,
    pub mount: RobotMount,
    /// Plan group to work next to.
    pub near: Option<String>,
}

#[derive(Debug)]
pub struct LayoutInput<'a> {
    pub plan: &'a ScenePlan,
    pub objects: Vec<ObjectItem<'a>>,
    pub robots: Vec<RobotItem>,
    pub seed: u64,
    /// The most members a column of a stacked group may hold, by group (besides the
    /// ceiling). The pipeline learns it from the settle: a tall column of light things
    /// sinks into MuJoCo's soft contacts, its top by more than verification allows.
    pub max_layers: std::collections::BTreeMap<String, usize>,
}

/// Measures a layout against its plan's rules profile (after anomalies were injected, say).
pub fn check_rules(input: &LayoutInput<'_>, scene: &LaidOutScene) -> Vec<sw_plan::Violation> {
    let profile = rules::profile(&input.plan.rules_profile).or_else(|| rules::profile("general"));
    match profile {
        Some(p) => rules::check(input, scene, &p, &attempt::door_zone(&scene.room.door, &scene.room.size)),
        None => Vec::new(),
    }
}

/// How many times a room may grow by [`GROWTH`] before objects are left out.
const MAX_GROWTH_STEPS: u32 = 8;
const GROWTH: f64 = 1.2;

/// Solves the layout.
pub fn solve(input: &LayoutInput<'_>) -> LaidOutScene {
    let mut size = input.plan.room.size;
    let original = size;
    // A room whose size was not given is as tall as its tallest floor object needs.
    let tallest = input.objects.iter().map(|o| o.asset.bounds().max[2]).fold(0.0, f64::max);
    let raised = !input.plan.room.size_fixed && tallest + 0.3 > size.height;
    if raised {
        size.height = ((tallest + 0.5) * 10.0).ceil() / 10.0;
    }
    let mut steps = 0;
    loop {
        let mut result = attempt::run(input, size);
        if raised {
            result.scene.warnings.insert(
                0,
                Warning::new(
                    Stage::Layout,
                    "ceiling_raised",
                    format!(
                        "the ceiling was raised from {:.1} m to {:.1} m for a {:.1} m tall object (the room's size was not given)",
                        original.height, size.height, tallest
                    ),
                ),
            );
        }
        let short = result.floor_failures > 0;
        // A cancelled job does not grow the room again (`sw_geom::cancel`).
        if !short || input.plan.room.size_fixed || steps >= MAX_GROWTH_STEPS || sw_geom::cancel::requested() {
            let mut scene = result.scene;
            if steps > 0 {
                scene.warnings.insert(
                    0,
                    Warning::new(
                        Stage::Layout,
                        "room_grown",
                        format!(
                            "the room grew from {:.1} × {:.1} m to {:.1} × {:.1} m to fit everything (its size was not given)",
                            original.width, original.depth, size.width, size.depth
                        ),
                    ),
                );
            }
            return scene;
        }
        size.width *= GROWTH;
        size.depth *= GROWTH;
        steps += 1;
    }
}
