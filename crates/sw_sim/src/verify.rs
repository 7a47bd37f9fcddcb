//! Compile, contacts at t = 0, settle.

use std::collections::BTreeSet;
use std::path::Path;

use mujoco_rs::prelude::*;
use sw_plan::{ContactCheck, DeepContact, ModelStats, MovedBody, RobotCheck, SettleCheck, Verification};

/// Thresholds and duration of a verification.
#[derive(Debug, Clone)]
pub struct VerifyOptions {
    /// Penetration between different bodies allowed at t = 0, m.
    pub contact_threshold: f64,
    /// Settle duration, s.
    pub settle_seconds: f64,
    /// Largest displacement of a free body over the settle, m.
    pub move_threshold: f64,
    /// Instance names of the robots; contacts and joints with these prefixes are theirs.
    pub robots: Vec<String>,
    /// Bodies whose contacts and motion are expected (injected anomalies): reported in
    /// `expected`, not as failures.
    pub expected_bodies: Vec<String>,
}

impl Default for VerifyOptions {
    fn default() -> Self {
        Self {
            contact_threshold: 0.001,
            settle_seconds: 2.0,
            move_threshold: 0.01,
            robots: Vec::new(),
            expected_bodies: Vec::new(),
        }
    }
}

/// "MuJoCo 3.17.0": the engine this binary links.
pub fn mujoco_version() -> String {
    // mujoco-rs asserts at start-up that the loaded library is the version it binds.
    let v = mujoco_rs::mujoco_c::mjVERSION_HEADER;
    format!("MuJoCo {}.{}.{}", v / 1_000_000, (v / 1000) % 1000, v % 1000)
}

/// Verifies the MJCF at `path`. Never panics on a bad scene: compile errors and failed
/// checks are reported in the returned value. MuJoCo's built-in textures are compiled
/// small (see `load.rs`); the verdict is the one [`verify_file_full_load`] gives.
pub fn verify_file(path: &Path, opts: &VerifyOptions) -> Verification {
    verify_loaded(opts, crate::load::load_for_verification(path))
}

/// [`verify_file`] with the scene compiled by MuJoCo's own `from_xml`, textures at full
/// size: the reference the fast load is tested against.
pub fn verify_file_full_load(path: &Path, opts: &VerifyOptions) -> Verification {
    verify_loaded(opts, MjModel::from_xml(path).map_err(|e| e.to_string()))
}

fn verify_loaded(opts: &VerifyOptions, loaded: Result<MjModel, String>) -> Verification {
    let mut v = Verification {
        engine: mujoco_version(),
        compiled: false,
        compile_error: None,
        model: None,
        initial_state: "qpos0".into(),
        initial_contacts: None,
        settle: None,
        robots: Vec::new(),
        passed: false,
        failures: Vec::new(),
        expected: Vec::new(),
    };
    let is_expected = |name: &str| opts.expected_bodies.iter().any(|b| b == name);
    let model = match loaded {
        Ok(m) => m,
        Err(msg) => {
            v.failures
                .push(format!("MuJoCo rejected the scene: {}", msg.split_whitespace().collect::<Vec<_>>().join(" ")));
            v.compile_error = Some(msg);
            return v;
        }
    };
    v.compiled = true;
    let ffi = model.ffi();
    let free_joints: Vec<usize> =
        (0..ffi.njnt as usize).filter(|&j| model.jnt_type()[j] == MjtJoint::mjJNT_FREE).collect();
    v.model = Some(ModelStats {
        bodies: ffi.nbody as u32,
        geoms: ffi.ngeom as u32,
        joints: ffi.njnt as u32,
        actuators: ffi.nu as u32,
        meshes: ffi.nmesh as u32,
        free_bodies: free_joints.len() as u32,
        keyframes: ffi.nkey as u32,
    });

    let mut data = model.make_data();
    if let Some(key) = model.name_to_id(MjtObjBase::mjOBJ_KEY, "home")
        && data.reset_keyframe(key).is_ok()
    {
        v.initial_state = "keyframe 'home'".into();
    }
    data.forward();

    let body_name = |b: usize| model.id_to_name(MjtObjBase::mjOBJ_BODY, b).unwrap_or("").to_string();
    let geom_label = |g: usize| {
        let b = model.geom_bodyid()[g] as usize;
        if b == 0 {
            model.id_to_name(MjtObjBase::mjOBJ_GEOM, g).map_or_else(|| format!("world geom {g}"), str::to_string)
        } else {
            body_name(b)
        }
    };
    let robot_of =
        |label: &str| opts.robots.iter().find(|r| label == r.as_str() || label.starts_with(&format!("{r}_"))).cloned();

    // ---- contacts at t = 0
    let mut deep = Vec::new();
    let mut max_depth: f64 = 0.0;
    let ncon = data.ncon().max(0) as usize;
    for c in data.contact().iter().take(ncon) {
        let (g1, g2) = (c.geom1 as usize, c.geom2 as usize);
        let (b1, b2) = (model.geom_bodyid()[g1], model.geom_bodyid()[g2]);
        if b1 == b2 {
            continue;
        }
        let depth = -c.dist;
        max_depth = max_depth.max(depth);
        if depth > opts.contact_threshold {
            let (a, b) = (geom_label(g1), geom_label(g2));
            let (a, b) = if a <= b { (a, b) } else { (b, a) };
            match deep.iter_mut().find(|d: &&mut DeepContact| d.body1 == a && d.body2 == b) {
                Some(d) => d.depth_m = d.depth_m.max(depth),
                None => deep.push(DeepContact { body1: a, body2: b, depth_m: depth }),
            }
        }
    }
    deep.sort_by(|a, b| b.depth_m.total_cmp(&a.depth_m).then(a.body1.cmp(&b.body1)));
    for d in deep.iter().filter(|d| is_expected(&d.body1) || is_expected(&d.body2)) {
        v.expected.push(format!("{}–{} {:.1} mm deep at t = 0", d.body1, d.body2, d.depth_m * 1000.0));
    }
    let unexpected: Vec<&DeepContact> =
        deep.iter().filter(|d| !is_expected(&d.body1) && !is_expected(&d.body2)).collect();
    if !unexpected.is_empty() {
        let deep = &unexpected;
        let list: Vec<String> =
            deep.iter().take(5).map(|d| format!("{}–{} {:.1} mm", d.body1, d.body2, d.depth_m * 1000.0)).collect();
        v.failures.push(format!(
            "{} contact{} deeper than {:.0} mm at t = 0: {}{}",
            deep.len(),
            if deep.len() == 1 { "" } else { "s" },
            opts.contact_threshold * 1000.0,
            list.join(", "),
            if deep.len() > 5 { ", …" } else { "" }
        ));
    }
    let mut robots: Vec<RobotCheck> = opts
        .robots
        .iter()
        .map(|r| RobotCheck { name: r.clone(), spawn_contacts: 0, max_joint_drift: 0.0, base_displacement_m: 0.0 })
        .collect();
    for d in &deep {
        let owners: BTreeSet<String> = [robot_of(&d.body1), robot_of(&d.body2)].into_iter().flatten().collect();
        for o in owners {
            if let Some(rc) = robots.iter_mut().find(|r| r.name == o) {
                rc.spawn_contacts += 1;
            }
        }
    }
    v.initial_contacts = Some(ContactCheck {
        threshold_m: opts.contact_threshold,
        contacts: ncon as u32,
        max_depth_m: round_um(max_depth),
        deep: deep.into_iter().map(|d| DeepContact { depth_m: round_um(d.depth_m), ..d }).collect(),
    });

    // ---- settle
    let free_bodies: Vec<usize> = free_joints.iter().map(|&j| model.jnt_bodyid()[j] as usize).collect();
    let start: Vec<[f64; 3]> = free_bodies.iter().map(|&b| data.xpos()[b]).collect();
    let tracked: Vec<(usize, usize, String)> = (0..ffi.njnt as usize)
        .filter(|&j| model.jnt_limited()[j] && model.jnt_type()[j] != MjtJoint::mjJNT_FREE)
        .filter_map(|j| {
            let name = model.id_to_name(MjtObjBase::mjOBJ_JOINT, j)?;
            let robot = robot_of(name)?;
            Some((j, model.jnt_qposadr()[j] as usize, robot))
        })
        .collect();
    let q0: Vec<f64> = tracked.iter().map(|(_, a, _)| data.qpos()[*a]).collect();
    let timestep = ffi.opt.timestep;
    let steps = if timestep > 0.0 { (opts.settle_seconds / timestep).round() as usize } else { 0 };
    let mut max_drift = vec![0.0f64; tracked.len()];
    let mut nan = false;
    for step in 0..steps {
        // A cancelled job stops stepping (`sw_geom::cancel`); the unfinished check fails.
        if step % 10 == 0 && sw_geom::cancel::requested() {
            v.failures.push("cancelled before the settle ended".into());
            return v;
        }
        data.step();
        if step % 10 == 9 || step + 1 == steps {
            for (k, (_, adr, _)) in tracked.iter().enumerate() {
                let q = data.qpos()[*adr];
                if !q.is_finite() {
                    nan = true;
                }
                max_drift[k] = max_drift[k].max((q - q0[k]).abs());
            }
        }
    }
    let mut moved = Vec::new();
    let mut worst: Option<(f64, String)> = None;
    for (k, &b) in free_bodies.iter().enumerate() {
        let p = data.xpos()[b];
        let dist = ((p[0] - start[k][0]).powi(2) + (p[1] - start[k][1]).powi(2) + (p[2] - start[k][2]).powi(2)).sqrt();
        let dist = if dist.is_finite() { dist } else { f64::INFINITY };
        let name = body_name(b);
        if worst.as_ref().is_none_or(|(d, _)| dist > *d) {
            worst = Some((dist, name.clone()));
        }
        if dist > opts.move_threshold {
            moved.push(MovedBody { body: name.clone(), displacement_m: round_um(dist) });
        }
        if let Some(r) = robot_of(&name)
            && let Some(rc) = robots.iter_mut().find(|x| x.name == r)
        {
            rc.base_displacement_m = rc.base_displacement_m.max(round_um(dist));
        }
    }
    for (k, (_, _, r)) in tracked.iter().enumerate() {
        if let Some(rc) = robots.iter_mut().find(|x| &x.name == r) {
            rc.max_joint_drift = rc.max_joint_drift.max(round_um(max_drift[k]));
        }
    }
    moved.sort_by(|a, b| b.displacement_m.total_cmp(&a.displacement_m).then(a.body.cmp(&b.body)));
    let mut engine_warnings = Vec::new();
    for (i, w) in data.warning().iter().enumerate() {
        if w.number > 0 {
            engine_warnings.push(format!("{} ×{}", warning_name(i), w.number));
        }
    }
    let unstable = nan || !engine_warnings.is_empty();
    for m in moved.iter().filter(|m| is_expected(&m.body)) {
        v.expected.push(format!("{} moved {:.1} cm in the settle", m.body, m.displacement_m * 100.0));
    }
    let unexpected_moves: Vec<&MovedBody> = moved.iter().filter(|m| !is_expected(&m.body)).collect();
    if !unexpected_moves.is_empty() {
        let moved = &unexpected_moves;
        let list: Vec<String> =
            moved.iter().take(5).map(|m| format!("{} {:.1} cm", m.body, m.displacement_m * 100.0)).collect();
        v.failures.push(format!(
            "{} free bod{} moved more than {:.0} cm in the {} s settle: {}{}",
            moved.len(),
            if moved.len() == 1 { "y" } else { "ies" },
            opts.move_threshold * 100.0,
            opts.settle_seconds,
            list.join(", "),
            if moved.len() > 5 { ", …" } else { "" }
        ));
    }
    if unstable {
        v.failures.push(format!(
            "the simulation was numerically unstable{}",
            if engine_warnings.is_empty() { String::new() } else { format!(": {}", engine_warnings.join(", ")) }
        ));
    }
    v.settle = Some(SettleCheck {
        duration_s: opts.settle_seconds,
        timestep_s: timestep,
        threshold_m: opts.move_threshold,
        max_displacement_m: worst.as_ref().map_or(0.0, |(d, _)| round_um(*d)),
        worst_body: worst.map(|(_, n)| n),
        moved,
        unstable,
        engine_warnings,
    });
    v.robots = robots;
    v.passed = v.failures.is_empty();
    v
}

/// Rounds to 0.1 µm: below MuJoCo's run-to-run noise on one machine, and keeps JSON short.
fn round_um(x: f64) -> f64 {
    if x.is_finite() { (x * 1e7).round() / 1e7 } else { x }
}

fn warning_name(i: usize) -> &'static str {
    match i {
        0 => "inertia too small",
        1 => "contact buffer full",
        2 => "constraint buffer full",
        3 => "vertex buffer full",
        4 => "bad qpos",
        5 => "bad qvel",
        6 => "bad qacc",
        7 => "bad ctrl",
        _ => "engine warning",
    }
}
