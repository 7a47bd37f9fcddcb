//! Mounting facts of a registered robot: written down for built-ins and packs, measured
//! in MuJoCo (once per process) for user robots, whose facts nobody wrote down.

use std::collections::BTreeMap;
use std::sync::Mutex;

use sw_robots::{Facts, MeasuredBody, RobotDef};

static MEASURED: Mutex<BTreeMap<&'static str, Facts>> = Mutex::new(BTreeMap::new());

/// The robot's facts. A user robot that cannot be measured keeps its conservative
/// placeholders; the bridge then reports what is wrong with its file.
pub(crate) fn facts(def: &'static RobotDef) -> Facts {
    let declared = || Facts {
        footprint_radius: def.footprint_radius,
        height: def.height,
        reach: def.reach,
        base_radius: def.base_radius,
        keepout: def.keepout.to_vec(),
    };
    if def.measured {
        return declared();
    }
    if let Ok(cache) = MEASURED.lock()
        && let Some(f) = cache.get(def.name)
    {
        return f.clone();
    }
    let f = measure(def).unwrap_or_else(|_| declared());
    if let Ok(mut cache) = MEASURED.lock() {
        cache.insert(def.name, f.clone());
    }
    f
}

/// Measures a robot alone at its home pose in MuJoCo.
pub fn measure(def: &RobotDef) -> Result<Facts, String> {
    let model = def.model().map_err(|e| e.to_string())?;
    let doc = sw_mjcf::robot_document(&model, "m").map_err(|e| e.to_string())?;
    let path = std::env::temp_dir().join(format!(
        "scenewright-measure-{}-{}-{}.xml",
        std::process::id(),
        def.name,
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.subsec_nanos())
    ));
    std::fs::write(&path, doc).map_err(|e| e.to_string())?;
    let measured = sw_sim::measure_robot(&path);
    let _ = std::fs::remove_file(&path);
    let bodies: Vec<MeasuredBody> = measured?
        .into_iter()
        .map(|b| MeasuredBody { name: b.name, parent: b.parent, origin: b.origin, min: b.min, max: b.max })
        .collect();
    Ok(sw_robots::facts_from_measurement(def.kind, &bodies))
}
