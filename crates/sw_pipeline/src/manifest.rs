//! One line of a dataset's `manifest.jsonl`, derived from a finished package, and the
//! structural fingerprint that tells two scenes apart.
//!
//! Everything in an entry is read back from the package directory (`report.json`,
//! `layout.json`, `timings.json`, `scene.xml`, the files), so an entry can always be
//! made again from its package: a scene whose line was lost (the process was killed
//! between moving the package into place and appending its line) is adopted on resume,
//! and the distributed mode assembles the manifest from packages in the blob store.
//! The report is read as plain JSON, field by field, so that newer or older reports (with
//! or without `relations`) are read alike.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};
use serde_json::Value;
use sha2::{Digest, Sha256};

/// A file of the package: its path inside the package, size and SHA-256.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct FileEntry {
    pub path: String,
    pub bytes: u64,
    pub sha256: String,
}

/// Object instances of the scene, by catalog category.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ObjectCounts {
    /// Instances the prompt asked for.
    pub requested: u32,
    /// Instances in the scene.
    pub placed: u32,
    /// Free bodies among them.
    pub movable: u32,
    pub by_category: BTreeMap<String, u32>,
}

/// How the scene varies from the prompt's other scenes.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Variation {
    /// What was varied: `layout`, `asset_parameters`, `colours` (all by the seed), `robot`
    /// (drawn from `--robots`), `anomalies` (injected and labelled).
    pub kinds: Vec<String>,
    /// The robot drawn for this scene, when robots are drawn from a list (`none` for none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub robot: Option<String>,
}

/// The relations the report measured (absent when the report has no `relations` list).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct RelationsHeld {
    pub total: u32,
    pub held: u32,
    /// `subject relation target(s): held` for each relation, in the report's order.
    pub list: Vec<Value>,
}

/// MuJoCo's verdict, in brief.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct VerificationBrief {
    pub status: String,
    pub engine: String,
    pub passed: bool,
    /// Contacts between different bodies deeper than the threshold at t = 0.
    pub deep_contacts: u32,
    pub max_depth_m: f64,
    /// Largest displacement of a free body in the settle.
    pub max_displacement_m: f64,
    pub unstable: bool,
    pub failures: Vec<String>,
    /// Findings explained by injected anomalies.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub expected: Vec<String>,
}

/// One scene of a dataset.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ManifestEntry {
    /// `PPPP-KKKKKK`: the prompt's index and the scene's slot within the prompt.
    pub id: String,
    /// The package directory, relative to the dataset (`scenes/<id>`).
    pub dir: String,
    pub prompt_index: u32,
    pub prompt: String,
    pub seed: u64,
    /// [`fingerprint`] of the scene's structure; no two scenes of a dataset share one.
    pub fingerprint: String,
    pub variation: Variation,
    pub physics: String,
    pub objects: ObjectCounts,
    /// Robot models in the scene, one per instance.
    pub robots: Vec<String>,
    /// Absent when the report does not measure relations.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relations: Option<RelationsHeld>,
    /// Industrial-rule violations (`rule`, `requested`, `measured`, `required`, `unit`).
    pub violations: Vec<Value>,
    /// Labels of injected anomalies, as in `layout.json`.
    pub anomalies: Vec<Value>,
    pub verification: VerificationBrief,
    /// Wall-clock time per stage and in total, ms.
    pub timings_ms: BTreeMap<String, f64>,
    pub files: Vec<FileEntry>,
}

/// A package that cannot become a manifest entry.
#[derive(Debug, thiserror::Error)]
pub enum ManifestError {
    #[error("{path}: {reason}")]
    Unreadable { path: String, reason: String },
}

fn read_json(dir: &Path, name: &str) -> Result<Value, ManifestError> {
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path)
        .map_err(|e| ManifestError::Unreadable { path: path.display().to_string(), reason: e.to_string() })?;
    serde_json::from_str(&text)
        .map_err(|e| ManifestError::Unreadable { path: path.display().to_string(), reason: e.to_string() })
}

/// What the dataset says about a scene that its package does not: where it belongs.
#[derive(Debug, Clone)]
pub struct EntryContext<'a> {
    pub id: &'a str,
    pub prompt_index: u32,
    pub physics: &'a str,
    pub variation: Variation,
}

/// The manifest entry of the package in `dir` (whose path in the dataset is `rel`).
pub fn entry_from_package(dir: &Path, rel: &str, ctx: EntryContext<'_>) -> Result<ManifestEntry, ManifestError> {
    let report = read_json(dir, "report.json")?;
    let layout = read_json(dir, "layout.json")?;
    let timings = read_json(dir, "timings.json").unwrap_or(Value::Null);
    let mut objects = ObjectCounts {
        requested: u32_of(&report["summary"]["objects_requested"]),
        placed: u32_of(&report["summary"]["objects_placed"]),
        ..ObjectCounts::default()
    };
    for o in layout["objects"].as_array().into_iter().flatten() {
        *objects.by_category.entry(str_of(&o["category"])).or_insert(0) += 1;
        objects.movable += u32::from(o["movable"].as_bool().unwrap_or(false));
    }
    let robots = layout["robots"].as_array().into_iter().flatten().map(|r| str_of(&r["model"])).collect();
    let relations = report.get("relations").and_then(Value::as_array).map(|list| RelationsHeld {
        total: list.len() as u32,
        held: list.iter().filter(|r| r["held"].as_bool() == Some(true)).count() as u32,
        list: list
            .iter()
            .map(|r| {
                serde_json::json!({
                    "subject": r["subject"],
                    "relation": r.get("relation").or_else(|| r.get("kind")).cloned().unwrap_or(Value::Null),
                    "target": r.get("target").or_else(|| r.get("targets")).cloned().unwrap_or(Value::Null),
                    "held": r["held"],
                    "measured": r.get("measured").cloned().unwrap_or(Value::Null),
                })
            })
            .collect(),
    });
    let violations = report["violations"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|v| {
            serde_json::json!({
                "rule": v["rule"], "requested": v["requested"], "measured": v["measured"],
                "required": v["required"], "unit": v["unit"],
            })
        })
        .collect();
    let v = &report["verification"];
    let verification = VerificationBrief {
        status: str_of(&report["status"]),
        engine: str_of(&v["engine"]),
        passed: v["passed"].as_bool().unwrap_or(false),
        deep_contacts: v["initial_contacts"]["deep"].as_array().map_or(0, |d| d.len() as u32),
        max_depth_m: v["initial_contacts"]["max_depth_m"].as_f64().unwrap_or(0.0),
        max_displacement_m: v["settle"]["max_displacement_m"].as_f64().unwrap_or(0.0),
        unstable: v["settle"]["unstable"].as_bool().unwrap_or(false),
        failures: strings(&v["failures"]),
        expected: strings(&v["expected"]),
    };
    let mut timings_ms = BTreeMap::new();
    for s in timings["stages"].as_array().into_iter().flatten() {
        if let (Some(stage), Some(ms)) = (s["stage"].as_str(), s["ms"].as_f64()) {
            timings_ms.insert(stage.to_string(), round3(ms));
        }
    }
    if let Some(t) = timings["total_ms"].as_f64() {
        timings_ms.insert("total".into(), round3(t));
    }
    Ok(ManifestEntry {
        id: ctx.id.to_string(),
        dir: rel.to_string(),
        prompt_index: ctx.prompt_index,
        prompt: str_of(&report["prompt"]),
        seed: report["seed"].as_u64().unwrap_or(0),
        fingerprint: fingerprint(dir)?,
        variation: ctx.variation,
        physics: ctx.physics.to_string(),
        objects,
        robots,
        relations,
        violations,
        anomalies: layout["anomalies"].as_array().cloned().unwrap_or_default(),
        verification,
        timings_ms,
        files: file_list(dir)?,
    })
}

fn str_of(v: &Value) -> String {
    v.as_str().unwrap_or_default().to_string()
}

fn u32_of(v: &Value) -> u32 {
    v.as_u64().map_or(0, |x| x.min(u64::from(u32::MAX)) as u32)
}

fn strings(v: &Value) -> Vec<String> {
    v.as_array().into_iter().flatten().filter_map(|s| s.as_str().map(str::to_string)).collect()
}

fn round3(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

/// Every file under `dir` with its size and SHA-256, sorted by path (`/` separated).
pub fn file_list(dir: &Path) -> Result<Vec<FileEntry>, ManifestError> {
    let unreadable = |p: &Path, e: std::io::Error| ManifestError::Unreadable {
        path: p.display().to_string(),
        reason: e.to_string(),
    };
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).map_err(|e| unreadable(&d, e))? {
            let entry = entry.map_err(|e| unreadable(&d, e))?;
            let p = entry.path();
            if entry.file_type().map_err(|e| unreadable(&p, e))?.is_dir() {
                stack.push(p);
                continue;
            }
            let bytes = std::fs::read(&p).map_err(|e| unreadable(&p, e))?;
            let rel = p.strip_prefix(dir).unwrap_or(&p);
            let rel: Vec<String> = rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
            out.push(FileEntry {
                path: rel.join("/"),
                bytes: bytes.len() as u64,
                sha256: hex(&Sha256::digest(&bytes)),
            });
        }
    }
    out.sort_by(|a, b| a.path.cmp(&b.path));
    Ok(out)
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// The structural fingerprint of the package in `dir`: SHA-256 (first 128 bits, hex) of
/// a canonical text of what makes the scene what it is, at the resolution a person would
/// notice:
///
/// - the room: kind, size (1 cm), door wall, offset and width (1 cm);
/// - every object by name: category, label, position (1 cm), yaw (1°, modulo 360°),
///   bounding-box size (1 mm: the asset's parameters), support, free or fixed;
/// - every robot by name: model, position (1 cm), yaw (1°), mount and what it stands on;
/// - every material's colour (0.01 per channel), by name;
/// - the content hashes of the object meshes (the file names in `assets/`): the exact
///   geometry of every asset;
/// - every anomaly label: object, kind, magnitude (1 mm or 0.01×).
///
/// Two scenes are duplicates when these texts are equal, i.e. nothing moved by a
/// centimetre or turned by a degree, no asset changed, no colour changed. The seed, the
/// prompt's wording and the timings are not part of it.
pub fn fingerprint(dir: &Path) -> Result<String, ManifestError> {
    Ok(hex(&Sha256::digest(canonical_structure(dir)?.as_bytes())[..16]))
}

/// The text [`fingerprint`] hashes (kept apart for tests and debugging).
pub fn canonical_structure(dir: &Path) -> Result<String, ManifestError> {
    let layout = read_json(dir, "layout.json")?;
    let cm = |v: &Value| format!("{:.0}", v.as_f64().unwrap_or(0.0) * 100.0);
    let mm = |v: &Value| format!("{:.0}", v.as_f64().unwrap_or(0.0) * 1000.0);
    let deg = |v: &Value| {
        let d = v.as_f64().unwrap_or(0.0).to_degrees().round().rem_euclid(360.0);
        format!("{d:.0}")
    };
    let mut lines: Vec<String> = Vec::new();
    let room = &layout["room"];
    lines.push(format!(
        "room {} {}x{}x{} door {} {} {}",
        str_of(&room["kind"]),
        cm(&room["size"]["width"]),
        cm(&room["size"]["depth"]),
        cm(&room["size"]["height"]),
        str_of(&room["door"]["wall"]),
        cm(&room["door"]["offset"]),
        cm(&room["door"]["width"]),
    ));
    let mut objects: Vec<String> = layout["objects"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|o| {
            format!(
                "object {} {} {:?} at {} {} {} yaw {} size {} {} {} on {} {}",
                str_of(&o["name"]),
                str_of(&o["category"]),
                str_of(&o["label"]),
                cm(&o["pos"][0]),
                cm(&o["pos"][1]),
                cm(&o["pos"][2]),
                deg(&o["yaw"]),
                mm(&o["size"][0]),
                mm(&o["size"][1]),
                mm(&o["size"][2]),
                o["support"],
                if o["movable"].as_bool() == Some(true) { "free" } else { "fixed" },
            )
        })
        .collect();
    objects.sort();
    lines.extend(objects);
    let mut robots: Vec<String> = layout["robots"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|r| {
            format!(
                "robot {} {} at {} {} {} yaw {} {} {}",
                str_of(&r["name"]),
                str_of(&r["model"]),
                cm(&r["pos"][0]),
                cm(&r["pos"][1]),
                cm(&r["pos"][2]),
                deg(&r["yaw"]),
                str_of(&r["mount"]),
                str_of(&r["mounted_on"]),
            )
        })
        .collect();
    robots.sort();
    lines.extend(robots);
    let mut anomalies: Vec<String> = layout["anomalies"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|a| format!("anomaly {} {} {}", str_of(&a["object"]), a["kind"], mm(&a["magnitude"])))
        .collect();
    anomalies.sort();
    lines.extend(anomalies);
    let xml_path = dir.join("scene.xml");
    let xml = std::fs::read_to_string(&xml_path)
        .map_err(|e| ManifestError::Unreadable { path: xml_path.display().to_string(), reason: e.to_string() })?;
    let mut materials = material_colours(&xml);
    materials.sort();
    lines.extend(materials);
    let assets = dir.join("assets");
    let mut meshes: Vec<String> = match std::fs::read_dir(&assets) {
        Ok(rd) => rd
            .filter_map(Result::ok)
            .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
            .map(|e| format!("mesh {}", e.file_name().to_string_lossy()))
            .collect(),
        Err(_) => Vec::new(),
    };
    meshes.sort();
    lines.extend(meshes);
    Ok(lines.join("\n"))
}

/// `material NAME r g b a` (0.01 per channel) for every `<material … rgba="…">` of the MJCF.
fn material_colours(xml: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, _) in xml.match_indices("<material ") {
        let tag = &xml[i..xml[i..].find('>').map_or(xml.len(), |e| i + e)];
        let attr = |key: &str| {
            let pat = format!(" {key}=\"");
            tag.find(&pat).and_then(|s| {
                let rest = &tag[s + pat.len()..];
                rest.find('"').map(|e| &rest[..e])
            })
        };
        if let (Some(name), Some(rgba)) = (attr("name"), attr("rgba")) {
            let c: Vec<String> =
                rgba.split_whitespace().map(|x| format!("{:.0}", x.parse::<f64>().unwrap_or(0.0) * 100.0)).collect();
            out.push(format!("material {name} {}", c.join(" ")));
        }
    }
    out
}
