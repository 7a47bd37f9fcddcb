//! An episode's own scene: the package's `scene.xml` with the physics step that divides a
//! frame exactly (so a recorded control held for one frame is a whole number of steps),
//! and the episode's randomisation applied and recorded: the colours, masses and friction
//! of the movable things, the lights, and the pose of the `front` camera. (The layout,
//! sizes and asset parameters vary with the package's seed: every episode gets a new
//! verified variant.) The result loads in plain MuJoCo and starts from keyframe `home`.

use serde::{Deserialize, Serialize};
use sw_geom::Rng;
use sw_mjcf::xml::{Element, num, nums};

use crate::ExpertError;

/// The physics step the scenes are written with, s.
pub const BASE_TIMESTEP: f64 = 0.002;

/// The physics step and steps per frame for `fps`: the step nearest 2 ms that divides a
/// frame exactly.
pub fn frame_timing(fps: u32) -> (f64, u32) {
    let frame = 1.0 / f64::from(fps.max(1));
    let substeps = (frame / BASE_TIMESTEP).round().max(1.0) as u32;
    (frame / f64::from(substeps), substeps)
}

/// How much an episode varies, and what it drew.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Randomisation {
    pub seed: u64,
    /// Body → (rgba) of the material of each movable thing, as drawn.
    pub colours: Vec<(String, [f64; 4])>,
    /// Body → mass scale.
    pub mass_scale: Vec<(String, f64)>,
    /// Body → sliding friction.
    pub friction: Vec<(String, f64)>,
    /// Scale of the lights' diffuse intensity.
    pub light_scale: f64,
    /// The front camera's offset, m, and turn, rad.
    pub camera_offset: [f64; 3],
    pub camera_turn: f64,
}

/// Which things vary: the moved ones (their grasp must still fit, so their size is the
/// package's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Vary {
    pub colours: bool,
    pub physics: bool,
    pub lighting: bool,
    pub camera: bool,
}

impl Vary {
    pub const ALL: Vary = Vary { colours: true, physics: true, lighting: true, camera: true };
    pub const NONE: Vary = Vary { colours: false, physics: false, lighting: false, camera: false };
}

/// `impratio` of an episode's scene (see `episode_scene`).
const GRASP_IMPRATIO: f64 = 10.0;
/// `noslip_iterations` of an episode's scene (see `episode_scene`).
const GRASP_NOSLIP: u32 = 5;

/// Writes the episode's `scene.xml` text from the package's, for `fps`, with the
/// randomisation of `seed` applied to the `movable` bodies. Bodies in `named_colour` keep
/// the hue the prompt named ("the red cube" stays red; only its shade varies). The front
/// camera is aimed at the `focus` bodies (the task's), keeping its direction.
pub fn episode_scene(
    package_xml: &str,
    fps: u32,
    seed: u64,
    movable: &[String],
    named_colour: &[String],
    focus: &[String],
    vary: Vary,
) -> Result<(String, Randomisation), ExpertError> {
    let mut root = Element::parse(package_xml).map_err(|e| ExpertError::Scene(format!("scene.xml: {}", e.message)))?;
    let (timestep, substeps) = frame_timing(fps);
    // The shortest text that reads back as the same double.
    root.section("option").set("timestep", format!("{timestep}"));
    // Grasping: elliptic friction cones and a high ratio of frictional to normal
    // impedance, as MuJoCo's documentation advises for things held by friction alone —
    // with the defaults a held ball or bottle creeps out of the pads while carried.
    root.section("option").set("cone", "elliptic");
    root.section("option").set("impratio", format!("{GRASP_IMPRATIO}"));
    // Held things still crept down through the pads (a bottle ~0.5 mm/s by its neck, soft
    // friction constraints yield under a steady load): MuJoCo's noslip pass removes that
    // drift in the friction dimensions. In the scene, so a replay is the same physics.
    root.section("option").set("noslip_iterations", format!("{GRASP_NOSLIP}"));
    let mut rng = Rng::derive(seed, "episode");
    let mut r = Randomisation { seed, light_scale: 1.0, ..Randomisation::default() };
    // Materials by name, for colours.
    let mut material_of_body: Vec<(String, String)> = Vec::new();
    if let Some(world) = root.first_mut("worldbody") {
        for b in world.children.iter_mut().filter(|c| c.name == "body") {
            let Some(name) = b.get("name").map(str::to_string) else { continue };
            if !movable.contains(&name) {
                continue;
            }
            if vary.physics {
                let scale = rng.range(0.8, 1.25);
                let mu = rng.range(0.7, 1.3);
                if let Some(inertial) = b.first_mut("inertial") {
                    scale_inertial(inertial, scale);
                }
                b.walk_mut(&mut |g| {
                    if g.name == "geom" && g.get("class") == Some("sw_collision") {
                        g.set("friction", nums(&[mu, 0.005, 0.0001]));
                    }
                });
                r.mass_scale.push((name.clone(), round3(scale)));
                r.friction.push((name.clone(), round3(mu)));
            }
            let mut mat = None;
            b.walk(&mut |g| {
                if mat.is_none() && g.name == "geom" && g.get("class") == Some("sw_visual") {
                    mat = g.get("material").map(str::to_string);
                }
            });
            if let Some(m) = mat {
                material_of_body.push((name, m));
            }
        }
        if vary.lighting {
            let s = rng.range(0.7, 1.3);
            r.light_scale = round3(s);
            for l in world.children.iter_mut().filter(|c| c.name == "light") {
                let d: Vec<f64> = l.get("diffuse").map(parse_nums).unwrap_or_else(|| vec![0.7; 3]);
                l.set("diffuse", nums(&d.iter().map(|v| (v * s).min(1.0)).collect::<Vec<_>>()));
                if let Some(dir) = l.get("dir").map(parse_nums)
                    && dir.len() == 3
                {
                    let j = [dir[0] + rng.range(-0.15, 0.15), dir[1] + rng.range(-0.15, 0.15), dir[2]];
                    l.set("dir", nums(&j));
                }
            }
        }
        frame_front_camera(world, focus);
        if vary.camera {
            let off = [rng.range(-0.03, 0.03), rng.range(-0.03, 0.03), rng.range(-0.03, 0.03)];
            let turn = rng.range(-0.04, 0.04);
            for c in world.children.iter_mut().filter(|c| c.name == "camera" && c.get("name") == Some("front")) {
                let p = c.get("pos").map(parse_nums).unwrap_or_default();
                if p.len() == 3 {
                    c.set("pos", nums(&[p[0] + off[0], p[1] + off[1], p[2] + off[2]]));
                }
                if let Some(xy) = c.get("xyaxes").map(parse_nums)
                    && xy.len() == 6
                {
                    let (s, co) = turn.sin_cos();
                    let rz = |v: &[f64]| [co * v[0] - s * v[1], s * v[0] + co * v[1], v[2]];
                    let (x, y) = (rz(&xy[0..3]), rz(&xy[3..6]));
                    c.set("xyaxes", nums(&[x[0], x[1], x[2], y[0], y[1], y[2]]));
                }
            }
            r.camera_offset = off.map(round3);
            r.camera_turn = round3(turn);
        }
    }
    if vary.colours && !material_of_body.is_empty() {
        // The materials' colours as written.
        let mut written: Vec<(String, [f64; 4])> = Vec::new();
        if let Some(asset) = root.first("asset") {
            for m in asset.children.iter().filter(|c| c.name == "material") {
                let v = m.get("rgba").map(parse_nums).unwrap_or_default();
                if let (Some(n), [r, g, b, a]) = (m.get("name"), v.as_slice()) {
                    written.push((n.to_string(), [*r, *g, *b, *a]));
                }
            }
        }
        // A new material per moved thing (materials may be shared by several bodies).
        let mut new_materials = Vec::new();
        for (body, mat) in &material_of_body {
            let base = written.iter().find(|(n, _)| n == mat).map(|(_, c)| *c);
            let rgba = match base {
                // A named colour: the same hue, a shade lighter or darker.
                Some(c) if named_colour.contains(body) => {
                    let k = rng.range(0.8, 1.2);
                    [(c[0] * k).min(1.0), (c[1] * k).min(1.0), (c[2] * k).min(1.0), c[3]].map(round3)
                }
                _ => [rng.range(0.05, 0.95), rng.range(0.05, 0.95), rng.range(0.05, 0.95), 1.0].map(round3),
            };
            let new_name = format!("sw_episode_{body}");
            new_materials.push(
                Element::new("material")
                    .with("name", new_name.clone())
                    .with("rgba", nums(&rgba))
                    .with("specular", "0.2")
                    .with("shininess", "0.2"),
            );
            if let Some(world) = root.first_mut("worldbody")
                && let Some(b) = world.children.iter_mut().find(|c| c.get("name") == Some(body.as_str()))
            {
                b.walk_mut(&mut |g| {
                    if g.name == "geom" && g.get("material") == Some(mat.as_str()) {
                        g.set("material", new_name.clone());
                    }
                });
            }
            r.colours.push((body.clone(), rgba));
        }
        root.section("asset").children.extend(new_materials);
    }
    let _ = substeps;
    Ok((root.to_document(), r))
}

/// Sets the episode's start (keyframe `home`) with each of `joints` part way open — drawn
/// from `seed` between half and nine tenths of its range — so that a task that closes
/// them does not already hold at the start. `scene` is the written episode scene (it is
/// compiled for the joints' addresses) and is rewritten in place. Returns (joint,
/// position) as set, for the episode's record.
pub fn open_at_start(scene: &std::path::Path, joints: &[String], seed: u64) -> Result<Vec<(String, f64)>, ExpertError> {
    use mujoco_rs::prelude::*;
    if joints.is_empty() {
        return Ok(Vec::new());
    }
    let model = MjModel::from_xml(scene).map_err(|e| ExpertError::Scene(e.to_string()))?;
    let text = std::fs::read_to_string(scene).map_err(|e| ExpertError::Scene(format!("{}: {e}", scene.display())))?;
    let mut root = Element::parse(&text).map_err(|e| ExpertError::Scene(format!("scene.xml: {}", e.message)))?;
    let nq = model.ffi().nq as usize;
    let key = root
        .first_mut("keyframe")
        .and_then(|k| k.children.iter_mut().find(|c| c.name == "key" && c.get("name") == Some("home")))
        .ok_or_else(|| ExpertError::Scene("the episode scene has no keyframe 'home'".into()))?;
    let mut qpos = key.get("qpos").map(parse_nums).unwrap_or_default();
    if qpos.len() != nq {
        return Err(ExpertError::Scene(format!("keyframe 'home' has {} positions, the model {nq}", qpos.len())));
    }
    let mut rng = Rng::derive(seed, "start joints");
    let mut set = Vec::new();
    for j in joints {
        let id = model
            .name_to_id(MjtObjBase::mjOBJ_JOINT, j)
            .ok_or_else(|| ExpertError::Scene(format!("no joint '{j}' in the scene")))?;
        let [lo, hi] = model.jnt_range()[id];
        let v = round3(lo + rng.range(0.5, 0.9) * (hi - lo));
        qpos[model.jnt_qposadr()[id] as usize] = v;
        set.push((j.clone(), v));
    }
    key.set("qpos", nums(&qpos));
    std::fs::write(scene, root.to_document()).map_err(|e| ExpertError::Scene(format!("{}: {e}", scene.display())))?;
    Ok(set)
}

fn scale_inertial(e: &mut Element, s: f64) {
    if let Some(m) = e.get("mass").and_then(|m| m.trim().parse::<f64>().ok()) {
        e.set("mass", num(m * s));
    }
    for key in ["diaginertia", "fullinertia"] {
        if let Some(v) = e.get(key).map(parse_nums) {
            e.set(key, nums(&v.iter().map(|x| x * s).collect::<Vec<_>>()));
        }
    }
}

/// Aims the `front` camera at the top-level bodies named in `focus`, from its own
/// direction, near enough that they fill the middle of the image: the scene's camera frames
/// the whole work area around the robot, which leaves the things a task moves small and at
/// the image's edge.
fn frame_front_camera(world: &mut Element, focus: &[String]) {
    let pts: Vec<[f64; 3]> = world
        .children
        .iter()
        .filter(|b| b.name == "body" && b.get("name").is_some_and(|n| focus.iter().any(|f| f == n)))
        .filter_map(|b| b.get("pos").map(parse_nums))
        .filter(|p| p.len() == 3)
        .map(|p| [p[0], p[1], p[2] + FOCUS_LIFT])
        .collect();
    if pts.is_empty() {
        return;
    }
    let n = pts.len() as f64;
    let c = [0, 1, 2].map(|i| pts.iter().map(|p| p[i]).sum::<f64>() / n);
    let spread = pts.iter().map(|p| ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2)).sqrt()).fold(0.0, f64::max);
    for cam in world.children.iter_mut().filter(|e| e.name == "camera" && e.get("name") == Some("front")) {
        let Some(xy) = cam.get("xyaxes").map(parse_nums).filter(|v| v.len() == 6) else { continue };
        // The camera looks along −z, z = x × y.
        let z = [xy[1] * xy[5] - xy[2] * xy[4], xy[2] * xy[3] - xy[0] * xy[5], xy[0] * xy[4] - xy[1] * xy[3]];
        let fovy = cam.get("fovy").and_then(|f| f.trim().parse::<f64>().ok()).unwrap_or(45.0);
        let half = (0.5 * fovy).to_radians().tan().max(0.1);
        let dist = ((spread + FOCUS_MARGIN) / half).clamp(FOCUS_NEAREST, FOCUS_FARTHEST);
        cam.set("pos", nums(&[c[0] + z[0] * dist, c[1] + z[1] * dist, c[2] + z[2] * dist]));
    }
}

/// Height above a focus body's origin that the front camera aims at, m (the hand works there).
const FOCUS_LIFT: f64 = 0.08;
/// Room left around the focus bodies in the front camera's view, m.
const FOCUS_MARGIN: f64 = 0.12;
/// The front camera's distance from what it frames, m.
const FOCUS_NEAREST: f64 = 0.6;
const FOCUS_FARTHEST: f64 = 2.5;

fn parse_nums(s: &str) -> Vec<f64> {
    s.split_whitespace().filter_map(|x| x.parse().ok()).collect()
}

fn round3(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_whole_numbers_of_steps() {
        for fps in [10, 15, 20, 24, 30, 50] {
            let (dt, n) = frame_timing(fps);
            assert!((dt * f64::from(n) * f64::from(fps) - 1.0).abs() < 1e-12, "{fps}");
            assert!((dt - BASE_TIMESTEP).abs() < 0.0002, "{fps}: {dt}");
        }
    }
}
