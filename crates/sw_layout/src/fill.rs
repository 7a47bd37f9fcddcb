//! `--fill`: rooms that look lived in. After the stated objects are placed, and without
//! moving any of them, the room is furnished the way its kind is used (a kitchen gets
//! counters, a fridge and a table with chairs; a bedroom a bed, nightstands and a
//! wardrobe) and, when cluttered, the surfaces, shelves and containers get the small
//! things that belong on them (a counter gets a kettle, jars and fruit; a desk a lamp, a
//! keyboard and papers). What goes where is data ([`profiles`]), not code.
//!
//! Every added object is marked `added` and is placed by the same tests as the solver's:
//! inside the room, clear of the doorway, of every other object's collision boxes and of
//! every robot's keep-out boxes. A robot's work stays its own: nothing is added within an
//! arm's reach on the floor, and the surface an arm stands on or works at is left as the
//! prompt set it. Items stand exactly on their surface, so nothing starts in contact
//! deeper than the surface itself.

use std::collections::BTreeMap;

use sw_geom::{Aabb, Asset, Rng};
use sw_plan::{LaidOutScene, PlacedObject, RoomKind, Stage, Support, Wall, Warning};

use crate::RobotItem;

/// How much to add.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, PartialOrd, Ord)]
pub enum FillLevel {
    /// Only what the prompt states (the default).
    #[default]
    None,
    /// The furniture the room's kind is used with.
    Furnished,
    /// Furnished, and its surfaces, shelves and containers carry small things.
    Cluttered,
}

impl FillLevel {
    pub const NAMES: [&'static str; 3] = ["none", "furnished", "cluttered"];

    pub fn name(self) -> &'static str {
        match self {
            FillLevel::None => "none",
            FillLevel::Furnished => "furnished",
            FillLevel::Cluttered => "cluttered",
        }
    }

    pub fn from_name(s: &str) -> Option<FillLevel> {
        match s.trim().to_lowercase().as_str() {
            "none" | "off" => Some(FillLevel::None),
            "furnished" | "furnish" => Some(FillLevel::Furnished),
            "cluttered" | "clutter" => Some(FillLevel::Cluttered),
            _ => None,
        }
    }

    /// The level a prompt asks for with its own words ("a cluttered kitchen", "a lived-in
    /// living room", "a realistic office"), if any.
    pub fn from_prompt(prompt: &str) -> Option<FillLevel> {
        let text = prompt.to_lowercase().replace(['-', ','], " ");
        let words: Vec<&str> = text.split_whitespace().collect();
        let mut best: Option<FillLevel> = None;
        for (phrase, level) in profiles::PROMPT_WORDS {
            let p: Vec<&str> = phrase.split_whitespace().collect();
            for (k, w) in words.windows(p.len()).enumerate() {
                let negated = k > 0 && profiles::NEGATIONS.contains(&words[k - 1]);
                if w == p.as_slice() && !negated {
                    best = Some(best.map_or(*level, |b| b.max(*level)));
                }
            }
        }
        best
    }
}

pub mod profiles;

/// The name of the plan group that added objects belong to.
pub const FILL_GROUP: &str = "fill";

/// One object the fill added: its placement and its asset (generated from its category
/// and `asset_seed` alone, so a package's rebuild makes it again).
#[derive(Debug, Clone)]
pub struct Added {
    pub placed: PlacedObject,
    pub asset: Asset,
    pub tags: Vec<String>,
}

/// What the fill works from.
#[derive(Debug)]
pub struct FillInput<'a> {
    pub prompt: &'a str,
    pub room_kind: RoomKind,
    pub scene: &'a LaidOutScene,
    /// The asset of every placed object, by object name.
    pub assets: &'a BTreeMap<String, &'a Asset>,
    pub robots: &'a [RobotItem],
    pub seed: u64,
    /// At most this many objects are added.
    pub max_added: usize,
}

/// The fill's result.
#[derive(Debug, Default)]
pub struct FillOutcome {
    pub added: Vec<Added>,
    pub warnings: Vec<Warning>,
}

/// Gap kept between added floor objects and everything else, m.
const FLOOR_GAP: f64 = 0.06;
/// Gap kept between items on a surface, m.
const ITEM_GAP: f64 = 0.012;
/// Gap kept from the walls, m.
const WALL_GAP: f64 = 0.02;

/// The occupied space, in world coordinates.
struct Occupied {
    boxes: Vec<Aabb>,
}

impl Occupied {
    fn hits(&self, b: &Aabb, gap: f64) -> bool {
        self.boxes.iter().any(|o| {
            b.min[0] - gap < o.max[0]
                && o.min[0] < b.max[0] + gap
                && b.min[1] - gap < o.max[1]
                && o.min[1] < b.max[1] + gap
                && b.min[2] < o.max[2] - 1e-6
                && o.min[2] < b.max[2] - 1e-6
        })
    }
}

/// An asset's collision boxes (all links at rest) in world coordinates at `pos`, `yaw`.
fn world_boxes(a: &Asset, pos: [f64; 3], yaw: f64) -> Vec<Aabb> {
    let (s, c) = yaw.sin_cos();
    a.collision_aabbs()
        .iter()
        .map(|b| {
            let mut out = Aabb::EMPTY;
            for x in [b.min[0], b.max[0]] {
                for y in [b.min[1], b.max[1]] {
                    for z in [b.min[2], b.max[2]] {
                        let p = [pos[0] + c * x - s * y, pos[1] + s * x + c * y, pos[2] + z];
                        out = out.union(&Aabb { min: p, max: p });
                    }
                }
            }
            out
        })
        .collect()
}

fn union(boxes: &[Aabb]) -> Aabb {
    boxes.iter().fold(Aabb::EMPTY, |a, b| a.union(b))
}

/// Adds furniture and clutter to `input.scene` at `level`. Never moves a placed object.
pub fn fill(input: &FillInput<'_>, level: FillLevel) -> FillOutcome {
    let mut out = FillOutcome::default();
    if level == FillLevel::None {
        return out;
    }
    let profile = profiles::for_room(input.room_kind, input.prompt);
    let scene = input.scene;
    let size = scene.room.size;
    let (hw, hd) = (size.width / 2.0, size.depth / 2.0);
    let mut rng = Rng::derive(input.seed, "fill");
    let mut occupied = Occupied { boxes: Vec::new() };
    for o in &scene.objects {
        if let Some(a) = input.assets.get(&o.name) {
            occupied.boxes.extend(world_boxes(a, o.pos, o.yaw));
        }
    }
    // Robots: their keep-out boxes, and on the floor a disc of their reach kept clear.
    let mut arm_zones: Vec<([f64; 2], f64)> = Vec::new();
    for (r, placed) in
        input.robots.iter().filter_map(|r| scene.robots.iter().find(|p| p.name == r.name).map(|p| (r, p)))
    {
        let (s, c) = placed.yaw.sin_cos();
        for k in &r.keepout {
            let mut b = Aabb::EMPTY;
            for x in [k.min[0], k.max[0]] {
                for y in [k.min[1], k.max[1]] {
                    for z in [k.min[2], k.max[2]] {
                        let p = [placed.pos[0] + c * x - s * y, placed.pos[1] + s * x + c * y, placed.pos[2] + z];
                        b = b.union(&Aabb { min: p, max: p });
                    }
                }
            }
            occupied.boxes.push(b);
        }
        if r.is_arm {
            arm_zones.push(([placed.pos[0], placed.pos[1]], r.reach + 0.15));
        }
    }
    let door = crate::attempt::door_zone(&scene.room.door, &size);
    occupied.boxes.push(Aabb { min: door.min, max: [door.max[0], door.max[1], size.height] });
    // Objects a robot stands on or works at keep their surfaces as the prompt left them.
    let mut reserved: Vec<String> = scene.robots.iter().filter_map(|r| r.mounted_on.clone()).collect();
    for o in &scene.objects {
        let centre = [o.pos[0], o.pos[1]];
        if !o.movable && arm_zones.iter().any(|(p, r)| (centre[0] - p[0]).hypot(centre[1] - p[1]) < *r) {
            reserved.push(o.name.clone());
        }
    }

    let mut counters: BTreeMap<String, u32> = BTreeMap::new();
    for o in &scene.objects {
        if let Some(n) = o.name.rsplit('_').next().and_then(|n| n.parse::<u32>().ok()) {
            let base = o.name[..o.name.len() - n.to_string().len() - 1].to_string();
            let e = counters.entry(base).or_insert(0);
            *e = (*e).max(n);
        }
    }
    let mut name_of = |category: &str| {
        let n = counters.entry(category.to_string()).or_insert(0);
        *n += 1;
        format!("{category}_{n}")
    };

    // 1. Furniture along the walls (and in the open for tables), in the profile's order.
    let mut hosts: Vec<(String, Asset, [f64; 3], f64)> = Vec::new();
    // A stated table counts as the dining table the room would get: one place, one thing.
    let present = |cat: &str, added: &[Added]| {
        scene.objects.iter().filter(|o| same_role(&o.category, cat)).count()
            + added.iter().filter(|a| same_role(&a.placed.category, cat)).count()
    };
    let mut furniture_short = 0usize;
    for item in profile.furniture {
        // What the prompt already has counts towards the room's share.
        let have = present(item.category, &out.added);
        for _ in have..item.count as usize {
            if out.added.len() >= input.max_added {
                break;
            }
            let seed = rng.next_u64();
            let Ok(asset) = sw_catalog::generate(&sw_catalog::AssetRequest::new(item.category, seed)) else { continue };
            let spot = match item.place {
                profiles::Place::Wall => wall_spot(&asset, &occupied, &arm_zones, [hw, hd], &mut rng),
                profiles::Place::Open => open_spot(&asset, &occupied, &arm_zones, [hw, hd], &mut rng),
            };
            let Some((pos, yaw)) = spot else {
                furniture_short += 1;
                break;
            };
            occupied.boxes.extend(world_boxes(&asset, pos, yaw));
            let name = name_of(item.category);
            hosts.push((name.clone(), asset.clone(), pos, yaw));
            out.added.push(added(name, item.category, asset, pos, yaw, Support::Floor));
        }
    }
    if furniture_short > 0 && out.added.is_empty() {
        out.warnings.push(Warning::new(
            Stage::Layout,
            "fill_room_full",
            format!(
                "--fill {}: the {:.1} × {:.1} m room has no free floor for more furniture; only the stated objects are in it",
                level.name(),
                size.width,
                size.depth
            ),
        ));
    }

    // 2. Small things on the surfaces of the furniture (stated and added), shelves and
    // containers, when cluttered.
    if level == FillLevel::Cluttered {
        let mut surfaces: Vec<(String, Asset, [f64; 3], f64)> = scene
            .objects
            .iter()
            .filter(|o| !o.movable && !reserved.contains(&o.name))
            .filter_map(|o| input.assets.get(&o.name).map(|a| (o.name.clone(), (*a).clone(), o.pos, o.yaw)))
            .collect();
        surfaces.extend(hosts);
        let mut placed_items = 0usize;
        for (host, asset, pos, yaw) in &surfaces {
            let Some(items) = profiles::clutter_for(&asset.category, profile) else { continue };
            for s in &asset.surfaces {
                if out.added.len() >= input.max_added {
                    break;
                }
                let n =
                    clutter_surface(input, &mut out, &mut occupied, &mut name_of, &mut rng, items, host, s, *pos, *yaw);
                placed_items += n;
            }
        }
        if placed_items == 0 && !surfaces.is_empty() {
            out.warnings.push(Warning::new(
                Stage::Layout,
                "fill_no_surface",
                format!(
                    "--fill cluttered: no free surface in the {} for small things",
                    input.room_kind.name().replace('_', " ")
                ),
            ));
        }
    }
    out
}

/// Whether two categories take one place in a room: the same category, or one a kind of
/// the other (a dining table is a table, so a stated table is the room's dining table).
fn same_role(a: &str, b: &str) -> bool {
    if a == b {
        return true;
    }
    match (sw_catalog::find(a), sw_catalog::find(b)) {
        (Some(x), Some(y)) => x.is_a.contains(&y.display) || y.is_a.contains(&x.display),
        _ => false,
    }
}

/// Whether a room holds one of a category at most when it is filled: appliances and
/// machines (a kitchen has a kettle, not four), unlike mugs, jars and books.
fn one_per_room(category: &str) -> bool {
    use sw_catalog::Kind;
    sw_catalog::find(category)
        .is_some_and(|c| matches!(c.kind, Kind::SmallAppliance | Kind::LargeAppliance | Kind::Machine))
}

fn added(name: String, category: &str, asset: Asset, pos: [f64; 3], yaw: f64, support: Support) -> Added {
    let tags = sw_catalog::find(category).map(|c| c.tags.iter().map(|t| t.to_string()).collect()).unwrap_or_default();
    let round = |v: f64| (v * 1e6).round() / 1e6;
    let size = asset.bounds().size();
    let placed = PlacedObject {
        name,
        group: FILL_GROUP.to_string(),
        category: category.to_string(),
        label: category.replace('_', " "),
        pos: pos.map(round),
        yaw,
        size: size.map(round),
        support,
        movable: asset.is_free(),
        mass: match asset.mass {
            sw_geom::MassModel::Free { mass } => Some(round(mass)),
            sw_geom::MassModel::Static => None,
        },
        asset_seed: asset.seed,
        added: true,
    };
    Added { placed, asset, tags }
}

/// Footprint half sizes of an asset turned by `yaw` (a multiple of 90°).
fn half_footprint(a: &Asset, yaw: f64) -> [f64; 2] {
    let s = a.bounds().size();
    if (yaw.sin()).abs() > 0.5 { [s[1] / 2.0, s[0] / 2.0] } else { [s[0] / 2.0, s[1] / 2.0] }
}

/// A spot against a wall, its back to the wall (assets face +Y).
fn wall_spot(
    a: &Asset,
    occ: &Occupied,
    arms: &[([f64; 2], f64)],
    [hw, hd]: [f64; 2],
    rng: &mut Rng,
) -> Option<([f64; 3], f64)> {
    use std::f64::consts::{FRAC_PI_2, PI};
    let b = a.bounds();
    let mut walls = [Wall::North, Wall::East, Wall::South, Wall::West];
    let first = (rng.next_u64() % 4) as usize;
    walls.rotate_left(first);
    for wall in walls {
        // The yaw that turns the asset's +Y (its front) away from the wall.
        let yaw = match wall {
            Wall::South => 0.0,
            Wall::North => PI,
            Wall::West => -FRAC_PI_2,
            Wall::East => FRAC_PI_2,
        };
        let [fx, fy] = half_footprint(a, yaw);
        let along: Vec<f64> = match wall {
            Wall::North | Wall::South => steps(-hw + fx + WALL_GAP, hw - fx - WALL_GAP, 0.1),
            _ => steps(-hd + fy + WALL_GAP, hd - fy - WALL_GAP, 0.1),
        };
        let depth_half = b.size()[1] / 2.0;
        let offset = if rng.chance(0.5) { along.len() / 2 } else { 0 };
        for k in 0..along.len() {
            let t = along[(k + offset) % along.len()];
            let (x, y) = match wall {
                Wall::South => (t, -hd + WALL_GAP + depth_half),
                Wall::North => (t, hd - WALL_GAP - depth_half),
                Wall::West => (-hw + WALL_GAP + depth_half, t),
                Wall::East => (hw - WALL_GAP - depth_half, t),
            };
            // Centre the footprint (the asset origin is the centre of its bounds in X, Y).
            let c = b.center();
            let (s, co) = yaw.sin_cos();
            let pos = [x - (co * c[0] - s * c[1]), y - (s * c[0] + co * c[1]), 0.0];
            if fits_floor(a, pos, yaw, occ, arms, [hw, hd]) {
                return Some((pos, yaw));
            }
        }
    }
    None
}

/// A spot in the open floor, facing a random quarter.
fn open_spot(
    a: &Asset,
    occ: &Occupied,
    arms: &[([f64; 2], f64)],
    [hw, hd]: [f64; 2],
    rng: &mut Rng,
) -> Option<([f64; 3], f64)> {
    let yaw = f64::from((rng.next_u64() % 2) as u32) * std::f64::consts::FRAC_PI_2;
    let [fx, fy] = half_footprint(a, yaw);
    let xs = steps(-hw + fx + 0.5, hw - fx - 0.5, 0.15);
    let ys = steps(-hd + fy + 0.5, hd - fy - 0.5, 0.15);
    // Nearest the middle first: tables stand in the room, not in its corners.
    let mut spots: Vec<(f64, f64)> = xs.iter().flat_map(|x| ys.iter().map(move |y| (*x, *y))).collect();
    spots.sort_by(|a, b| (a.0.hypot(a.1)).total_cmp(&b.0.hypot(b.1)));
    let c = a.bounds().center();
    let (s, co) = yaw.sin_cos();
    spots
        .into_iter()
        .map(|(x, y)| [x - (co * c[0] - s * c[1]), y - (s * c[0] + co * c[1]), 0.0])
        .find(|p| fits_floor(a, *p, yaw, occ, arms, [hw, hd]))
        .map(|p| (p, yaw))
}

fn steps(a: f64, b: f64, step: f64) -> Vec<f64> {
    if b < a {
        return Vec::new();
    }
    let n = ((b - a) / step).floor() as usize;
    (0..=n).map(|k| a + step * k as f64).collect()
}

fn fits_floor(
    a: &Asset,
    pos: [f64; 3],
    yaw: f64,
    occ: &Occupied,
    arms: &[([f64; 2], f64)],
    [hw, hd]: [f64; 2],
) -> bool {
    let boxes = world_boxes(a, pos, yaw);
    let u = union(&boxes);
    if u.min[0] < -hw + WALL_GAP - 1e-9
        || u.max[0] > hw - WALL_GAP + 1e-9
        || u.min[1] < -hd + WALL_GAP - 1e-9
        || u.max[1] > hd - WALL_GAP + 1e-9
    {
        return false;
    }
    // Clear of every arm's floor reach (nearest point of the footprint).
    for (c, r) in arms {
        let dx = (c[0] - c[0].clamp(u.min[0], u.max[0])).abs();
        let dy = (c[1] - c[1].clamp(u.min[1], u.max[1])).abs();
        if dx.hypot(dy) < *r {
            return false;
        }
    }
    // Doors and drawers open: keep a little room in front as well.
    !boxes.iter().any(|b| occ.hits(b, FLOOR_GAP))
}

/// Fills one support surface of `host` with items from `items`; returns how many.
#[allow(clippy::too_many_arguments)]
fn clutter_surface(
    input: &FillInput<'_>,
    out: &mut FillOutcome,
    occ: &mut Occupied,
    name_of: &mut dyn FnMut(&str) -> String,
    rng: &mut Rng,
    items: &[profiles::Item],
    host: &str,
    s: &sw_geom::SupportSurface,
    host_pos: [f64; 3],
    host_yaw: f64,
) -> usize {
    let clearance = s.clearance.unwrap_or(0.6).min(0.6);
    let (w, d) = (s.max[0] - s.min[0], s.max[1] - s.min[1]);
    if w < 0.06 || d < 0.06 {
        return 0;
    }
    // Tries per surface follow its area: a shelf level gets a handful, a counter many.
    let tries = ((w * d) / 0.006).clamp(4.0, 80.0) as usize;
    let mut placed = 0;
    let (hs, hc) = host_yaw.sin_cos();
    for _ in 0..tries {
        if out.added.len() >= input.max_added {
            break;
        }
        let Some(item) = profiles::pick(items, rng) else { break };
        let seed = rng.next_u64();
        if one_per_room(item.category)
            && (input.scene.objects.iter().any(|o| same_role(&o.category, item.category))
                || out.added.iter().any(|a| same_role(&a.placed.category, item.category)))
        {
            continue;
        }
        let Ok(asset) = sw_catalog::generate(&sw_catalog::AssetRequest::new(item.category, seed)) else { continue };
        if !asset.is_free() {
            continue;
        }
        let size = asset.bounds().size();
        if size[2] > clearance - 0.015 {
            continue;
        }
        // A quarter turn with the host, so that the item's boxes stay axis-aligned.
        let quarter = f64::from((rng.next_u64() % 4) as u32) * std::f64::consts::FRAC_PI_2;
        let local_yaw = quarter;
        let yaw = host_yaw + local_yaw;
        let [fx, fy] = half_footprint(&asset, local_yaw);
        if 2.0 * fx + 2.0 * ITEM_GAP > w || 2.0 * fy + 2.0 * ITEM_GAP > d {
            continue;
        }
        let lx = rng.range(s.min[0] + fx + ITEM_GAP, s.max[0] - fx - ITEM_GAP);
        let ly = rng.range(s.min[1] + fy + ITEM_GAP, s.max[1] - fy - ITEM_GAP);
        // The asset origin is the centre of its footprint's bounds, shifted by its centre.
        let c = asset.bounds().center();
        let (ls, lc) = local_yaw.sin_cos();
        let (ox, oy) = (lx - (lc * c[0] - ls * c[1]), ly - (ls * c[0] + lc * c[1]));
        let pos = [host_pos[0] + hc * ox - hs * oy, host_pos[1] + hs * ox + hc * oy, host_pos[2] + s.z];
        let boxes = world_boxes(&asset, pos, yaw);
        if boxes.iter().any(|b| occ.hits(b, ITEM_GAP)) {
            continue;
        }
        occ.boxes.extend(boxes);
        let name = name_of(item.category);
        let support = Support::Object { object: host.to_string(), surface: s.name.clone() };
        out.added.push(added(name, item.category, asset, pos, yaw, support));
        placed += 1;
    }
    placed
}
