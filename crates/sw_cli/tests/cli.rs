//! End-to-end tests of the `scenewright` binary: the command-line contract of DESIGN.md
//! (exit codes, one-line errors, nothing written on bad input), the package layout,
//! determinism, and an independent check of generated scenes with the official Python
//! bindings of MuJoCo 4.0 (`.cache/venv`, made by `scripts/setup.sh --tests`).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;
use std::ffi::{OsStr, OsString};
use std::io::Read;
use std::os::unix::ffi::OsStringExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::Value;
use tempfile::TempDir;

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");

/// Every file a package holds besides its meshes.
const PACKAGE_FILES: &[&str] =
    &["scene.xml", "scene_only.xml", "plan.json", "layout.json", "report.json", "timings.json"];

/// The stage labels of the plain progress lines, in order.
const STAGES: &[&str] = &["L1 plan", "L2 forge", "L3 layout", "L4 bridge", "verify"];

/// A prompt with several object kinds, relations and a robot.
const BUSY_PROMPT: &str =
    "a warehouse with two pallet racks, a conveyor, six boxes on a table, two chairs and a turtlebot";

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/assets").join(name)
}

/// What one run of the binary did.
#[derive(Debug)]
struct Run {
    /// `None` when the process was killed by a signal.
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

impl Run {
    fn new(code: Option<i32>, stdout: &[u8], stderr: &[u8]) -> Self {
        Self {
            code,
            stdout: String::from_utf8_lossy(stdout).into_owned(),
            stderr: String::from_utf8_lossy(stderr).into_owned(),
        }
    }

    fn describe(&self) -> String {
        let clip = |s: &str| {
            if s.len() > 4000 {
                format!("{} …[{} bytes]", &s[..s.floor_char_boundary(4000)], s.len())
            } else {
                s.to_string()
            }
        };
        format!("exit code {:?}\n--- stdout\n{}\n--- stderr\n{}", self.code, clip(&self.stdout), clip(&self.stderr))
    }

    fn expect_code(&self, code: i32, what: &str) -> &Self {
        assert_eq!(self.code, Some(code), "{what}: expected exit code {code}\n{}", self.describe());
        self
    }

    /// stdout as exactly one JSON document.
    fn json(&self) -> Value {
        serde_json::from_str(&self.stdout)
            .unwrap_or_else(|e| panic!("stdout is not exactly one JSON document: {e}\n{}", self.describe()))
    }

    /// Bad input: exit 2, nothing on stdout, one line on stderr that starts with "error:".
    fn expect_input_error(&self, what: &str) -> &Self {
        self.expect_code(2, what);
        let text = self.stderr.trim_end_matches('\n');
        assert!(
            text.starts_with("error:") && !text.contains('\n') && !text.contains('\r'),
            "{what}: stderr must be exactly one line starting with 'error:'\n{}",
            self.describe()
        );
        assert!(self.stdout.is_empty(), "{what}: nothing should be printed on stdout\n{}", self.describe());
        self
    }
}

fn scenewright<I, S>(args: I) -> Run
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let out = Command::new(BIN)
        .args(args)
        .env_remove("SCENEWRIGHT_LOG")
        .stdin(Stdio::null())
        .output()
        .expect("cannot run the scenewright binary");
    Run::new(out.status.code(), &out.stdout, &out.stderr)
}

/// Runs the binary, killing it after `limit`; `None` when it did not finish in time.
fn scenewright_with_timeout(args: &[OsString], limit: Duration) -> Option<Run> {
    let mut child = Command::new(BIN)
        .args(args)
        .env_remove("SCENEWRIGHT_LOG")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("cannot run the scenewright binary");
    let drain = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            let _ = r.read_to_end(&mut buf);
            buf
        })
    };
    let out = drain(Box::new(child.stdout.take().unwrap()));
    let err = drain(Box::new(child.stderr.take().unwrap()));
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return Some(Run::new(status.code(), &out.join().unwrap(), &err.join().unwrap()));
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// A package generated into a fresh temporary directory (`<tmp>/pkg`).
struct Package {
    tmp: TempDir,
    dir: PathBuf,
    run: Run,
}

impl Package {
    fn file(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }

    fn json(&self, name: &str) -> Value {
        read_json(&self.file(name))
    }

    fn report(&self) -> Value {
        self.json("report.json")
    }
}

fn generate(prompt: &str, extra: &[&str]) -> Package {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("pkg");
    let mut args: Vec<OsString> = vec!["generate".into(), prompt.into(), "--out".into(), dir.clone().into()];
    args.extend(extra.iter().map(OsString::from));
    let run = scenewright(&args);
    Package { tmp, dir, run }
}

/// Generates and expects success and a verified report.
fn generate_verified(prompt: &str, extra: &[&str]) -> Package {
    let p = generate(prompt, extra);
    p.run.expect_code(0, &format!("generate {prompt:?} {extra:?}"));
    assert_package_files(&p.dir);
    let report = p.report();
    assert_eq!(report["status"], "verified", "report.json of {prompt:?} {extra:?}:\n{report:#}");
    p
}

fn read_json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{} is not JSON: {e}", path.display()))
}

/// Every file and directory under `root`, relative, with the bytes of the files.
fn snapshot(root: &Path) -> BTreeMap<PathBuf, Option<Vec<u8>>> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<PathBuf, Option<Vec<u8>>>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap()).collect();
        entries.sort_by_key(|e| e.file_name());
        for e in entries {
            let path = e.path();
            let rel = path.strip_prefix(root).unwrap().to_path_buf();
            if e.file_type().unwrap().is_dir() {
                out.insert(rel, None);
                walk(root, &path, out);
            } else {
                out.insert(rel, Some(std::fs::read(&path).unwrap()));
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(root, root, &mut out);
    out
}

fn assert_unchanged(
    before: &BTreeMap<PathBuf, Option<Vec<u8>>>,
    after: &BTreeMap<PathBuf, Option<Vec<u8>>>,
    what: &str,
) {
    let added: Vec<_> = after.keys().filter(|k| !before.contains_key(*k)).collect();
    let removed: Vec<_> = before.keys().filter(|k| !after.contains_key(*k)).collect();
    let changed: Vec<_> =
        before.iter().filter(|(k, v)| after.get(*k).is_some_and(|w| w != *v)).map(|(k, _)| k).collect();
    assert!(
        added.is_empty() && removed.is_empty() && changed.is_empty(),
        "{what}: the directory changed\n  added: {added:?}\n  removed: {removed:?}\n  changed: {changed:?}"
    );
}

/// The `file="…"` attributes of an MJCF document.
fn referenced_files(xml: &str) -> Vec<String> {
    xml.split(" file=\"").skip(1).filter_map(|s| s.split('"').next()).map(str::to_string).collect()
}

/// The package holds every contract file, and every mesh scene.xml references is a
/// well-formed STL under assets/.
fn assert_package_files(dir: &Path) {
    for f in PACKAGE_FILES {
        assert!(dir.join(f).is_file(), "package {} lacks {f}", dir.display());
    }
    assert!(dir.join("assets").is_dir(), "package {} lacks assets/", dir.display());
    for xml_name in ["scene.xml", "scene_only.xml"] {
        let xml = std::fs::read_to_string(dir.join(xml_name)).unwrap();
        assert!(xml.contains("meshdir=\"assets\""), "{xml_name} does not set meshdir=\"assets\"");
        for f in referenced_files(&xml) {
            assert!(!f.starts_with('/') && !f.contains(".."), "{xml_name} references a non-package path {f:?}");
            let path = dir.join("assets").join(&f);
            let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{xml_name} references {f}: {e}"));
            if f.to_lowercase().ends_with(".stl") {
                assert!(bytes.len() >= 84, "{f} is too short to be an STL");
                let n = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
                assert!(n > 0, "{f} holds no triangles");
                assert_eq!(bytes.len(), 84 + 50 * n, "{f} is not a well-formed binary STL ({n} triangles)");
            }
        }
    }
}

/// The stored JSON files parse as the contract types (which deny unknown fields).
fn assert_contract_types(dir: &Path) {
    fn parse<T: serde::de::DeserializeOwned>(dir: &Path, name: &str) {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        if let Err(e) = serde_json::from_str::<T>(&text) {
            panic!("{name} does not match its contract type: {e}");
        }
    }
    parse::<sw_plan::ScenePlan>(dir, "plan.json");
    parse::<sw_plan::LaidOutScene>(dir, "layout.json");
    parse::<sw_plan::Report>(dir, "report.json");
    parse::<sw_plan::Timings>(dir, "timings.json");
}

/// An independent verification in the official Python bindings of MuJoCo 4.0: load the
/// scene, reset to keyframe "home" when present, look for contacts between different
/// bodies deeper than 1 mm at t = 0, step 2 s, and look for free bodies that moved more
/// than 1 cm.
const MUJOCO4_CHECK: &str = r#"
import sys
try:
    import mujoco
    import numpy as np
except ImportError as e:
    print(f"cannot import the mujoco bindings ({e}): run scripts/setup.sh --tests")
    sys.exit(3)
if not mujoco.__version__.startswith("4."):
    print(f"expected the mujoco 4.x bindings, found {mujoco.__version__}: run scripts/setup.sh --tests")
    sys.exit(3)
failures = []
for path in sys.argv[1:]:
    try:
        m = mujoco.MjModel.from_xml_path(path)
    except Exception as e:
        failures.append(f"{path}: does not load: {e}")
        continue
    d = mujoco.MjData(m)
    key = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_KEY, "home")
    if key >= 0:
        mujoco.mj_resetDataKeyframe(m, d, key)
    mujoco.mj_forward(m, d)
    body = lambda b: mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, int(b)) or f"body{int(b)}"
    deep = []
    for i in range(d.ncon):
        c = d.contact[i]
        b1, b2 = m.geom_bodyid[c.geom[0]], m.geom_bodyid[c.geom[1]]
        if b1 != b2 and c.dist < -0.001:
            deep.append(f"{body(b1)}/{body(b2)} {-c.dist * 1000:.2f} mm")
    free = [j for j in range(m.njnt) if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    start = {j: d.qpos[m.jnt_qposadr[j]:m.jnt_qposadr[j] + 3].copy() for j in free}
    for _ in range(int(round(2.0 / m.opt.timestep))):
        mujoco.mj_step(m, d)
    moved = []
    for j in free:
        a = m.jnt_qposadr[j]
        disp = float(np.linalg.norm(d.qpos[a:a + 3] - start[j]))
        if not np.isfinite(disp) or disp > 0.01:
            moved.append(f"{body(m.jnt_bodyid[j])} {disp * 1000:.1f} mm")
    print(f"{path}: mujoco {mujoco.__version__}, {m.nbody} bodies, {len(free)} free, "
          f"key {'home' if key >= 0 else '-'}, t = {d.time:.3f} s, deep {deep}, moved {moved}")
    if deep:
        failures.append(f"{path}: contacts deeper than 1 mm at t = 0: {deep}")
    if moved:
        failures.append(f"{path}: free bodies moved more than 1 cm in 2 s: {moved}")
if failures:
    print("FAILED", *failures, sep="\n")
    sys.exit(1)
print("OK")
"#;

fn python() -> PathBuf {
    let py = workspace_root().join(".cache/venv/bin/python");
    assert!(
        py.is_file(),
        "the Python venv with the official mujoco 4.0 bindings is missing at {}: run scripts/setup.sh --tests",
        py.display()
    );
    py
}

/// Checks scene.xml and scene_only.xml of every package with MuJoCo 4.0 in Python.
fn assert_mujoco4_ok(packages: &[&Path]) {
    let scenes: Vec<PathBuf> = packages.iter().flat_map(|p| [p.join("scene.xml"), p.join("scene_only.xml")]).collect();
    let out = Command::new(python())
        .arg("-c")
        .arg(MUJOCO4_CHECK)
        .args(&scenes)
        .current_dir("/")
        .stdin(Stdio::null())
        .output()
        .expect("cannot run the venv's python");
    let run = Run::new(out.status.code(), &out.stdout, &out.stderr);
    assert_eq!(run.code, Some(0), "independent check in MuJoCo 4.0 (Python) failed\n{}", run.describe());
}

fn assert_png(path: &Path, width: u32, height: u32, min_bytes: usize) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("no PNG at {}: {e}", path.display()));
    assert_eq!(&bytes[..8.min(bytes.len())], b"\x89PNG\r\n\x1a\n", "{} lacks the PNG signature", path.display());
    assert!(bytes.len() >= 24 && &bytes[12..16] == b"IHDR", "{} has no IHDR chunk first", path.display());
    let w = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    assert_eq!((w, h), (width, height), "{} has the wrong size", path.display());
    assert!(bytes.windows(4).any(|c| c == b"IDAT"), "{} has no image data", path.display());
    assert!(bytes.len() >= min_bytes, "{} is suspiciously small ({} bytes)", path.display(), bytes.len());
}

fn texts(list: &Value, field: &str) -> Vec<String> {
    list.as_array()
        .unwrap_or_else(|| panic!("not a list: {list}"))
        .iter()
        .map(|x| x[field].as_str().unwrap_or_default().to_string())
        .collect()
}

/// `generate <prompt> --out <tmp>/pkg` must be refused as bad input with nothing written.
fn assert_prompt_rejected(prompt: OsString, what: &str) -> Run {
    let tmp = tempfile::tempdir().unwrap();
    std::fs::write(tmp.path().join("marker.txt"), "untouched").unwrap();
    let before = snapshot(tmp.path());
    let out = tmp.path().join("pkg");
    let run = scenewright([OsString::from("generate"), prompt, "--out".into(), out.clone().into_os_string()]);
    run.expect_input_error(what);
    assert!(!out.exists(), "{what}: {} was created", out.display());
    assert_unchanged(&before, &snapshot(tmp.path()), what);
    run
}

// ---------------------------------------------------------------------------------------
// generate: the package
// ---------------------------------------------------------------------------------------

#[test]
fn generate_writes_a_verified_package_with_a_human_summary() {
    let p = generate_verified("a warehouse with two shelves, three boxes and a ur5e robot", &[]);
    assert_contract_types(&p.dir);
    assert_mujoco4_ok(&[&p.dir]);

    // Stable, readable names: <category>_<n> for objects, <robot>_ for the robot's parts.
    let scene = std::fs::read_to_string(p.file("scene.xml")).unwrap();
    assert!(referenced_files(&scene).len() >= 3, "scene.xml references too few mesh files");
    for name in ["shelf_1", "shelf_2", "cardboard_box_1", "cardboard_box_3"] {
        assert!(scene.contains(&format!("<body name=\"{name}\"")), "scene.xml has no body {name}");
    }
    assert!(scene.contains("<body name=\"ur5e_1_"), "scene.xml has no ur5e_1_ bodies");
    let only = std::fs::read_to_string(p.file("scene_only.xml")).unwrap();
    assert!(only.contains("<body name=\"shelf_1\""), "scene_only.xml lost the objects");
    assert!(!only.contains("<body name=\"ur5e_1_"), "scene_only.xml still holds the robot");

    // The human summary names the scene and the verdict.
    let scene_path = p.file("scene.xml").display().to_string();
    assert!(p.run.stdout.contains(&scene_path), "stdout does not name {scene_path}\n{}", p.run.describe());
    assert!(p.run.stdout.contains("passed"), "stdout does not say 'passed'\n{}", p.run.describe());

    // Not a terminal: plain progress lines on stderr, one per stage, no escapes.
    for stage in STAGES {
        assert!(
            p.run.stderr.lines().any(|l| l.starts_with(stage)),
            "stderr has no progress line for {stage:?}\n{}",
            p.run.describe()
        );
    }
    assert!(
        !p.run.stderr.contains('\x1b') && !p.run.stderr.contains('\r'),
        "stderr holds terminal control characters although it is not a TTY\n{}",
        p.run.describe()
    );

    let report = p.report();
    assert_eq!(report["prompt"], "a warehouse with two shelves, three boxes and a ur5e robot");
    assert_eq!(report["seed"], 0);
    assert_eq!(report["verification"]["passed"], true);
    assert_eq!(report["summary"]["objects_placed"], report["summary"]["objects_requested"]);
}

#[test]
fn generate_json_prints_exactly_one_document() {
    let p = generate_verified("a table with two mugs and a ur5e", &["--json", "--seed", "3"]);
    let doc = p.run.json();
    for field in ["status", "out_dir", "scene", "report", "timings"] {
        assert!(doc.get(field).is_some(), "--json output lacks '{field}'\n{doc:#}");
    }
    assert_eq!(doc["status"], "verified");
    assert_eq!(doc["out_dir"].as_str(), Some(p.dir.to_str().unwrap()));
    assert_eq!(doc["scene"].as_str(), Some(p.file("scene.xml").to_str().unwrap()));
    assert_eq!(doc["report"], p.report(), "the printed report differs from report.json");
    assert_eq!(doc["timings"], p.json("timings.json"), "the printed timings differ from timings.json");
    assert_eq!(doc["report"]["seed"], 3);
    assert!(doc["timings"]["stages"].as_array().is_some_and(|s| s.len() == STAGES.len()), "{doc:#}");
    assert!(!p.run.stderr.lines().any(|l| l.starts_with("L1 plan")), "--json still prints progress lines");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn generate_no_verify_writes_an_unverified_package() {
    let p = generate("a workbench with three bins on it", &["--no-verify", "--json"]);
    p.run.expect_code(0, "generate --no-verify");
    assert_package_files(&p.dir);
    let doc = p.run.json();
    assert_eq!(doc["status"], "unverified");
    let report = p.report();
    assert_eq!(report["status"], "unverified");
    assert!(report.get("verification").is_none(), "--no-verify still verified:\n{report:#}");
    // The package is as good as a verified one; checking it afterwards passes.
    scenewright([OsStr::new("validate"), p.dir.as_os_str()]).expect_code(0, "validate an unverified package");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn generate_into_an_existing_empty_directory() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("empty");
    std::fs::create_dir(&out).unwrap();
    let run = scenewright([OsStr::new("generate"), OsStr::new("a table"), OsStr::new("--out"), out.as_os_str()]);
    run.expect_code(0, "generate into an empty directory");
    assert_package_files(&out);
    let names: Vec<_> = std::fs::read_dir(tmp.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, vec![OsString::from("empty")], "stray entries next to the package");
}

#[test]
fn generated_packages_pass_the_independent_mujoco4_check() {
    let prompts = [
        "a robotics lab with a workbench, a UR5e on the bench, three bins on the bench and a chair next to the workbench",
        "a loading dock with six pallets, twenty cardboard boxes on the pallets and a TurtleBot",
        "a kitchen with a table, four chairs around it, a cabinet against the wall and a red bin under the table",
        "a table with a red box, a green box and a blue box on it, and a UR5e arm mounted on the table",
        "a warehouse with four pallet racks against the north wall, twelve crates on the racks and three pallets near the door",
        BUSY_PROMPT,
    ];
    let mut packages = Vec::new();
    for prompt in prompts {
        for seed in ["0", "1"] {
            packages.push(generate_verified(prompt, &["--seed", seed]));
        }
    }
    let dirs: Vec<&Path> = packages.iter().map(|p| p.dir.as_path()).collect();
    assert_mujoco4_ok(&dirs);
}

// ---------------------------------------------------------------------------------------
// generate: determinism
// ---------------------------------------------------------------------------------------

#[test]
fn same_prompt_and_seed_give_byte_identical_packages() {
    let a = generate_verified(BUSY_PROMPT, &["--seed", "7"]);
    let b = generate_verified(BUSY_PROMPT, &["--seed", "7"]);
    let mut sa = snapshot(&a.dir);
    let mut sb = snapshot(&b.dir);
    assert!(sa.remove(Path::new("timings.json")).is_some() && sb.remove(Path::new("timings.json")).is_some());
    let only_a: Vec<_> = sa.keys().filter(|k| !sb.contains_key(*k)).collect();
    let only_b: Vec<_> = sb.keys().filter(|k| !sa.contains_key(*k)).collect();
    assert!(only_a.is_empty() && only_b.is_empty(), "different file sets: {only_a:?} vs {only_b:?}");
    let differing: Vec<_> = sa.iter().filter(|(k, v)| sb[*k] != **v).map(|(k, _)| k).collect();
    assert!(differing.is_empty(), "same prompt and seed, different bytes in {differing:?}");
    assert!(sa.keys().any(|k| k.starts_with("assets") && k != Path::new("assets")), "no meshes compared");
}

#[test]
fn different_seeds_give_different_layouts() {
    let a = generate_verified(BUSY_PROMPT, &["--seed", "1"]);
    let b = generate_verified(BUSY_PROMPT, &["--seed", "2"]);
    let la = std::fs::read(a.file("layout.json")).unwrap();
    let lb = std::fs::read(b.file("layout.json")).unwrap();
    assert_ne!(la, lb, "seeds 1 and 2 produced the same layout.json");
    assert_eq!(a.report()["seed"], 1);
    assert_eq!(b.report()["seed"], 2);
}

// ---------------------------------------------------------------------------------------
// generate: --robot
// ---------------------------------------------------------------------------------------

const ROBOT_PROMPT: &str = "a table with a mug and a ur5e";

#[test]
fn robot_option_replaces_the_prompts_robots() {
    let p = generate_verified(ROBOT_PROMPT, &["--robot", "turtlebot3"]);
    let robots = p.report()["summary"]["robots"].clone();
    assert_eq!(robots, serde_json::json!(["turtlebot3_1"]), "--robot turtlebot3 gave {robots}");
    let scene = std::fs::read_to_string(p.file("scene.xml")).unwrap();
    assert!(scene.contains("name=\"turtlebot3_1_"), "scene.xml has no turtlebot3_1_ elements");
    assert!(!scene.contains("name=\"ur5e_"), "scene.xml still holds the prompt's ur5e");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn robot_option_takes_a_list() {
    let p = generate_verified("a table", &["--robot", "ur5e,turtlebot3"]);
    let robots = p.report()["summary"]["robots"].clone();
    assert_eq!(robots, serde_json::json!(["ur5e_1", "turtlebot3_1"]));
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn robot_none_removes_the_prompts_robots() {
    let p = generate_verified(ROBOT_PROMPT, &["--robot", "none"]);
    let report = p.report();
    assert_eq!(report["summary"]["robots"], serde_json::json!([]), "{report:#}");
    let scene = std::fs::read_to_string(p.file("scene.xml")).unwrap();
    assert!(!scene.contains("name=\"ur5e_"), "--robot none left the ur5e in scene.xml");
    assert!(scene.contains("<body name=\"table_1\""), "--robot none lost the table");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn unknown_robot_is_bad_input_and_writes_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("pkg");
    let run = scenewright([
        OsStr::new("generate"),
        OsStr::new(ROBOT_PROMPT),
        OsStr::new("--out"),
        out.as_os_str(),
        OsStr::new("--robot"),
        OsStr::new("nosuchbot"),
    ]);
    run.expect_input_error("--robot nosuchbot");
    assert!(run.stderr.contains("nosuchbot"), "the message does not name the robot\n{}", run.describe());
    assert!(snapshot(tmp.path()).is_empty(), "something was written: {:?}", snapshot(tmp.path()).keys());
}

// ---------------------------------------------------------------------------------------
// generate: bad input is refused, nothing written
// ---------------------------------------------------------------------------------------

#[test]
fn empty_prompt_is_refused() {
    assert_prompt_rejected("".into(), "empty prompt");
}

#[test]
fn whitespace_prompt_is_refused() {
    assert_prompt_rejected("   \n\t".into(), "whitespace-only prompt");
}

#[test]
fn oversized_prompt_is_refused() {
    // Linux caps one argv string at 128 KiB (MAX_ARG_STRLEN), so a 1 MB prompt cannot
    // reach the binary as an argument at all; this is the largest that can, and it is
    // still well over the planner's limit. The 1 MB prompt goes through `bench` below.
    let prompt = "a table with a mug ".repeat(120_000 / 19);
    let run = assert_prompt_rejected(prompt.into(), "a 120 kB prompt");
    assert!(run.stderr.len() < 500, "the error line echoes the prompt\n{}", run.describe());
}

#[test]
fn one_megabyte_prompt_is_rejected_by_the_pipeline() {
    let tmp = tempfile::tempdir().unwrap();
    let suite = tmp.path().join("big.txt");
    let prompt = "a table with a mug ".repeat(1_048_576 / 19 + 1);
    std::fs::write(&suite, format!("{prompt}\n")).unwrap();
    let run = scenewright([
        OsStr::new("bench"),
        OsStr::new("scenes"),
        OsStr::new("--suite"),
        suite.as_os_str(),
        OsStr::new("--json"),
    ]);
    run.expect_code(0, "bench a 1 MB prompt");
    let v = run.json()["validity"].clone();
    assert_eq!(v["runs"], 1, "{v:#}");
    assert_eq!(v["rejected_as_bad_input"], 1, "the 1 MB prompt was not rejected as bad input: {v:#}");
    assert_eq!(v["verified"], 0, "{v:#}");
}

#[test]
fn invalid_utf8_prompt_is_refused() {
    let garbage = OsString::from_vec(vec![b'a', b' ', 0xff, 0xfe, 0xc3, 0x28, b't', b'a', b'b', 0x80, b'l', b'e']);
    assert_prompt_rejected(garbage, "a prompt that is not UTF-8");
}

#[test]
fn chinese_prompt_is_refused() {
    assert_prompt_rejected("一个有两个货架的仓库".into(), "a Chinese prompt");
}

#[test]
fn german_prompt_is_refused() {
    assert_prompt_rejected("Ein Lager mit zwei Regalen".into(), "a German prompt");
}

#[test]
fn negative_size_is_refused() {
    assert_prompt_rejected("a -5 by 3 m room with a table".into(), "a negative room size");
}

#[test]
fn zero_size_is_refused() {
    assert_prompt_rejected("a 0 by 0 m room with a table".into(), "a zero room size");
}

#[test]

fn refused_prompt_creates_no_parent_directories() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("missing/parents/pkg");
    let run = scenewright([OsStr::new("generate"), OsStr::new(""), OsStr::new("--out"), out.as_os_str()]);
    run.expect_input_error("empty prompt, --out under missing directories");
    assert!(snapshot(tmp.path()).is_empty(), "something was written: {:?}", snapshot(tmp.path()).keys());
}

#[test]

fn interrupted_run_leaves_no_partial_directory() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("pkg");
    let mut child = Command::new(BIN)
        .args([OsStr::new("generate"), OsStr::new("a room with 200 chairs"), OsStr::new("--out"), out.as_os_str()])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Interrupt as soon as the package is being staged.
    let start = Instant::now();
    let staged = loop {
        if !snapshot(tmp.path()).is_empty() {
            break true;
        }
        if child.try_wait().unwrap().is_some() || start.elapsed() > Duration::from_secs(30) {
            break false;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    if staged && child.try_wait().unwrap().is_none() {
        let pid = child.id().to_string();
        let killed = Command::new("kill").args(["-INT", pid.as_str()]).status().unwrap();
        assert!(killed.success(), "could not send SIGINT to {pid}");
    }
    let status = child.wait().unwrap();
    assert!(staged, "the run never started staging (status {status:?})");
    let left: Vec<_> = snapshot(tmp.path())
        .into_keys()
        .filter(|k| k.components().count() == 1 && k.to_string_lossy().contains("partial"))
        .collect();
    assert!(left.is_empty(), "an interrupted run (status {status:?}) left {left:?} behind");
}

#[test]

fn usage_errors_are_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("pkg");
    let cases: Vec<(Vec<OsString>, &str)> = vec![
        (vec!["generate".into(), "a table".into()], "generate without --out"),
        (
            vec![
                "generate".into(),
                "a table".into(),
                "--out".into(),
                out.clone().into(),
                "--seed".into(),
                "abc".into(),
            ],
            "--seed abc",
        ),
        (vec!["frobnicate".into()], "an unknown subcommand"),
    ];
    for (args, what) in cases {
        scenewright(&args).expect_input_error(what);
    }
    assert!(!out.exists());
}

// ---------------------------------------------------------------------------------------
// generate: best-effort input goes through, with the change reported
// ---------------------------------------------------------------------------------------

#[test]
fn absurd_size_is_clamped_and_reported() {
    let p = generate_verified("a 500 m tall table", &["--json"]);
    let report = p.report();
    let warnings = report["warnings"].as_array().unwrap();
    assert!(
        warnings.iter().any(|w| {
            let code = w["code"].as_str().unwrap_or_default();
            let msg = w["message"].as_str().unwrap_or_default();
            msg.contains("500") && (code.contains("clamp") || msg.contains("clamp") || msg.contains("used"))
        }),
        "no warning reports the clamped 500 m height:\n{report:#}"
    );
    // The table that was built is a table-sized table.
    let layout = p.json("layout.json");
    let table = layout["objects"].as_array().unwrap().iter().find(|o| o["category"] == "table").expect("no table");
    let height = table["size"][2].as_f64().unwrap();
    assert!(height > 0.3 && height < 2.0, "the table is {height} m tall");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn objects_that_do_not_fit_are_left_out_and_reported() {
    let p = generate_verified("40 pallet racks in a 2 m by 2 m room", &[]);
    let report = p.report();
    let left_out = report["left_out"].as_array().unwrap();
    assert!(!left_out.is_empty(), "nothing reported as left out:\n{report:#}");
    assert!(
        left_out.iter().any(|l| l["requested"] == 40 && l["placed"].as_u64() < Some(40)),
        "left_out does not account for the 40 racks:\n{report:#}"
    );
    assert!(p.run.stdout.contains("left out"), "the summary does not mention it\n{}", p.run.describe());
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn unknown_noun_becomes_a_labelled_proxy() {
    let p = generate_verified("a flux capacitor next to a table", &[]);
    let report = p.report();
    let approximated = report["approximated"].as_array().unwrap();
    assert!(
        approximated.iter().any(|a| {
            a["text"].as_str().unwrap_or_default().contains("flux capacitor")
                && a["became"].as_str().unwrap_or_default().contains("proxy")
        }),
        "approximated does not list a proxy for the flux capacitor:\n{report:#}"
    );
    assert_eq!(report["summary"]["objects_placed"], 2, "{report:#}");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]
fn leftover_words_are_reported_as_not_understood() {
    let p = generate_verified("a warehouse with two racks for training grasping policies", &[]);
    let report = p.report();
    let words = texts(&report["not_understood"], "text").join(" ");
    for w in ["training", "grasping", "policies"] {
        assert!(words.contains(w), "not_understood does not list '{w}':\n{report:#}");
    }
    assert!(p.run.stdout.contains("grasping"), "the summary does not mention the ignored words");
    assert_mujoco4_ok(&[&p.dir]);
}

#[test]

fn huge_counts_are_clamped_and_finish() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("pkg");
    let args: Vec<OsString> = vec![
        "generate".into(),
        "a room with 1000000 chairs".into(),
        "--out".into(),
        out.clone().into(),
        "--json".into(),
    ];
    let Some(run) = scenewright_with_timeout(&args, Duration::from_secs(120)) else {
        panic!("'a room with 1000000 chairs' did not finish in 120 s");
    };
    run.expect_code(0, "a room with 1000000 chairs");
    let report = read_json(&out.join("report.json"));
    assert!(
        texts(&report["approximated"], "text").iter().any(|t| t.contains("1000000")),
        "the count clamp is not reported:\n{report:#}"
    );
}

// ---------------------------------------------------------------------------------------
// generate: unusable --out
// ---------------------------------------------------------------------------------------

#[test]
fn non_empty_out_directory_is_refused_and_untouched() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("taken");
    std::fs::create_dir_all(out.join("sub")).unwrap();
    std::fs::write(out.join("keep.txt"), "mine").unwrap();
    std::fs::write(out.join("sub/scene.xml"), "<mujoco/>").unwrap();
    let before = snapshot(tmp.path());
    let run = scenewright([OsStr::new("generate"), OsStr::new("a table"), OsStr::new("--out"), out.as_os_str()]);
    run.expect_input_error("--out names a non-empty directory");
    assert_unchanged(&before, &snapshot(tmp.path()), "--out names a non-empty directory");
}

#[test]
fn out_under_proc_is_refused() {
    for out in ["/proc/scenewright-test-out", "/proc/scenewright-test-out/pkg"] {
        let run = scenewright(["generate", "a table", "--out", out]);
        run.expect_input_error(&format!("--out {out}"));
        assert!(!Path::new("/proc/scenewright-test-out").exists());
    }
}

#[test]
fn out_under_a_regular_file_is_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("a_file");
    std::fs::write(&file, "just a file").unwrap();
    let before = snapshot(tmp.path());
    for out in [file.join("pkg"), file.join("deeper/pkg"), file.clone()] {
        let run = scenewright([OsStr::new("generate"), OsStr::new("a table"), OsStr::new("--out"), out.as_os_str()]);
        run.expect_input_error(&format!("--out {}", out.display()));
        assert_unchanged(&before, &snapshot(tmp.path()), &format!("--out {}", out.display()));
    }
}

// ---------------------------------------------------------------------------------------
// validate
// ---------------------------------------------------------------------------------------

#[test]
fn validate_passes_a_fresh_package() {
    let p = generate_verified("a warehouse with two shelves and four boxes", &[]);
    let run = scenewright([OsStr::new("validate"), p.dir.as_os_str()]);
    run.expect_code(0, "validate");
    assert!(run.stdout.contains("passed"), "validate does not say 'passed'\n{}", run.describe());
    let run = scenewright([OsStr::new("validate"), p.dir.as_os_str(), OsStr::new("--json")]);
    run.expect_code(0, "validate --json");
    let v = run.json();
    assert_eq!(v["passed"], true, "{v:#}");
    assert_eq!(v["compiled"], true, "{v:#}");
}

#[test]
fn validate_refuses_a_directory_without_a_scene() {
    let tmp = tempfile::tempdir().unwrap();
    std::fs::write(tmp.path().join("plan.json"), "{}").unwrap();
    scenewright([OsStr::new("validate"), tmp.path().as_os_str()]).expect_input_error("validate a non-package");
    let missing = tmp.path().join("does-not-exist");
    scenewright([OsStr::new("validate"), missing.as_os_str()]).expect_input_error("validate a missing directory");
}

#[test]
fn validate_reports_a_scene_that_does_not_compile() {
    let p = generate_verified("a table with two mugs", &[]);
    let scene = p.file("scene.xml");
    let mut xml = std::fs::read_to_string(&scene).unwrap();
    xml.push_str("<<< this is not XML >>>\n");
    std::fs::write(&scene, xml).unwrap();

    let run = scenewright([OsStr::new("validate"), p.dir.as_os_str(), OsStr::new("--json")]);
    run.expect_code(1, "validate --json on a corrupt scene.xml");
    let v = run.json();
    assert_eq!(v["compiled"], false, "{v:#}");
    assert_eq!(v["passed"], false, "{v:#}");
    let error = v["compile_error"].as_str().expect("no compile_error");
    assert!(!error.trim().is_empty(), "empty compile_error");

    let run = scenewright([OsStr::new("validate"), p.dir.as_os_str()]);
    run.expect_code(1, "validate on a corrupt scene.xml");
    let first_line = error.lines().next().unwrap().trim();
    let all = format!("{}{}", run.stdout, run.stderr);
    assert!(all.contains("FAILED"), "validate does not say it failed\n{}", run.describe());
    assert!(all.contains(first_line), "validate does not report the compile error {first_line:?}\n{}", run.describe());
}

#[test]
fn validate_reports_a_box_sunk_into_the_floor() {
    let p = generate_verified("a warehouse with three boxes", &["--robot", "none"]);
    // Every joint is a box's free joint: move the first box 10 cm into the floor in the
    // home keyframe (which sets the initial state).
    let scene = p.file("scene.xml");
    let xml = std::fs::read_to_string(&scene).unwrap();
    let (head, rest) = xml.split_once("<key name=\"home\" qpos=\"").expect("no home keyframe with qpos");
    let (qpos, tail) = rest.split_once('"').unwrap();
    let mut q: Vec<String> = qpos.split_whitespace().map(str::to_string).collect();
    assert!(q.len() >= 7 * 3, "expected three free joints in {qpos:?}");
    q[2] = "-0.1".into();
    std::fs::write(&scene, format!("{head}<key name=\"home\" qpos=\"{}\"{tail}", q.join(" "))).unwrap();

    let run = scenewright([OsStr::new("validate"), p.dir.as_os_str(), OsStr::new("--json")]);
    run.expect_code(1, "validate a scene with a box in the floor");
    let v = run.json();
    assert_eq!(v["compiled"], true, "{v:#}");
    assert_eq!(v["passed"], false, "{v:#}");
    let deep = v["initial_contacts"]["deep"].as_array().expect("no initial_contacts.deep");
    assert!(
        deep.iter().any(|c| c["body1"] == "cardboard_box_1" || c["body2"] == "cardboard_box_1"),
        "the sunk box is not among the deep contacts:\n{v:#}"
    );
    assert!(!v["failures"].as_array().unwrap().is_empty(), "{v:#}");
}

// ---------------------------------------------------------------------------------------
// robots, assets, render, bench
// ---------------------------------------------------------------------------------------

#[test]
fn robots_list_json_names_the_builtin_robots() {
    let run = scenewright(["robots", "list", "--json"]);
    run.expect_code(0, "robots list --json");
    let names = texts(&run.json()["robots"], "name");
    for r in ["ur5e", "ur10e", "panda", "kinova_gen3", "turtlebot3", "mobile_manipulator"] {
        assert!(names.iter().any(|n| n == r), "robots list lacks {r}: {names:?}");
    }
    // The test set-up fetches the robot packs; they are listed with their licences.
    for r in ["robosuite_panda", "menagerie_ur5e"] {
        assert!(names.iter().any(|n| n == r), "robots list lacks the pack robot {r}: {names:?}");
    }
    let packs = run.json()["packs"].clone();
    assert!(packs.as_array().is_some_and(|p| p.len() == 2 && p.iter().all(|x| x["present"] == true)), "{packs}");
    let run = scenewright(["robots", "list"]);
    run.expect_code(0, "robots list");
    assert!(run.stdout.contains("ur5e") && run.stdout.contains("turtlebot3"), "{}", run.describe());
}

#[test]
fn assets_list_json_holds_every_catalog_category() {
    let run = scenewright(["assets", "list", "--json"]);
    run.expect_code(0, "assets list --json");
    let names = texts(&run.json(), "name");
    let expected: Vec<&str> = sw_catalog::categories().iter().map(|c| c.name).collect();
    assert!(expected.len() >= 10, "the catalog is suspiciously small: {expected:?}");
    for c in &expected {
        assert!(names.iter().any(|n| n == c), "assets list lacks '{c}': {names:?}");
    }
}

#[test]
fn assets_show_describes_a_category() {
    let run = scenewright(["assets", "show", "table"]);
    run.expect_code(0, "assets show table");
    assert!(run.stdout.starts_with("table"), "{}", run.describe());
    let run = scenewright(["assets", "show", "table", "--json"]);
    run.expect_code(0, "assets show table --json");
    let info = run.json();
    assert_eq!(info["category"]["name"], "table", "{info:#}");
    let bounds: Vec<f64> = info["bounds_m"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    assert!(bounds.len() == 3 && bounds.iter().all(|b| *b > 0.05 && *b < 5.0), "table bounds {bounds:?}");
    // Names are forgiving about case and spaces.
    let run = scenewright(["assets", "show", "Pallet Rack", "--json"]);
    run.expect_code(0, "assets show 'Pallet Rack'");
    assert_eq!(run.json()["category"]["name"], "pallet_rack");
}

#[test]
fn assets_show_unknown_is_bad_input() {
    scenewright(["assets", "show", "nosuch"]).expect_input_error("assets show nosuch");
}

#[test]
fn assets_render_writes_a_png() {
    let tmp = tempfile::tempdir().unwrap();
    let png = tmp.path().join("table.png");
    scenewright([
        OsStr::new("assets"),
        OsStr::new("render"),
        OsStr::new("table"),
        OsStr::new("--out"),
        png.as_os_str(),
    ])
    .expect_code(0, "assets render table");
    assert_png(&png, 640, 640, 2000);

    let missing = tmp.path().join("nosuch.png");
    scenewright([
        OsStr::new("assets"),
        OsStr::new("render"),
        OsStr::new("nosuch"),
        OsStr::new("--out"),
        missing.as_os_str(),
    ])
    .expect_input_error("assets render nosuch");
    assert!(!missing.exists(), "a PNG was written for an unknown category");
}

#[test]
fn render_writes_a_png_of_the_scene() {
    let p = generate_verified("a robotics lab with a workbench and a UR5e on the bench", &[]);
    let png = p.tmp.path().join("scene.png");
    scenewright([OsStr::new("render"), p.dir.as_os_str(), OsStr::new("--out"), png.as_os_str()])
        .expect_code(0, "render");
    assert_png(&png, 1280, 800, 4000);

    let small = p.tmp.path().join("small.png");
    scenewright([
        OsStr::new("render"),
        p.dir.as_os_str(),
        OsStr::new("--out"),
        small.as_os_str(),
        OsStr::new("--width"),
        OsStr::new("320"),
        OsStr::new("--height"),
        OsStr::new("200"),
        OsStr::new("--collision"),
    ])
    .expect_code(0, "render --width 320 --height 200 --collision");
    assert_png(&small, 320, 200, 500);

    let not_a_package = tempfile::tempdir().unwrap();
    let png = not_a_package.path().join("x.png");
    scenewright([OsStr::new("render"), not_a_package.path().as_os_str(), OsStr::new("--out"), png.as_os_str()])
        .expect_input_error("render a directory without scene.xml");
    assert!(!png.exists());
}

#[test]
fn bench_scenes_counts_every_run_as_verified() {
    let run = scenewright(["bench", "scenes", "--prompt", "a table with two mugs", "--json"]);
    run.expect_code(0, "bench scenes --prompt");
    let doc = run.json();
    let v = &doc["validity"];
    assert!(v["runs"].as_u64().is_some_and(|n| n >= 1), "{doc:#}");
    assert_eq!(v["verified"], v["runs"], "{doc:#}");
    assert_eq!(doc["failures"], serde_json::json!([]), "{doc:#}");

    let suite = fixture("suite.txt");
    let run = scenewright([
        OsStr::new("bench"),
        OsStr::new("scenes"),
        OsStr::new("--suite"),
        suite.as_os_str(),
        OsStr::new("--json"),
    ]);
    run.expect_code(0, "bench scenes --suite");
    let doc = run.json();
    assert_eq!(doc["prompts"], 2, "{doc:#}");
    assert_eq!(doc["validity"]["verified"], 2, "{doc:#}");
}

// ---------------------------------------------------------------------------------------
// Closed stdout, help
// ---------------------------------------------------------------------------------------

/// Runs with stdout a pipe whose reading end is closed before the binary writes.
fn run_with_closed_stdout(args: &[&OsStr]) -> Run {
    let mut child = Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("cannot run the scenewright binary");
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    Run::new(out.status.code(), &out.stdout, &out.stderr)
}

#[test]
fn closed_stdout_does_not_panic() {
    for args in [vec!["robots", "list"], vec!["assets", "list", "--json"], vec!["--help"]] {
        let os: Vec<&OsStr> = args.iter().map(OsStr::new).collect();
        let run = run_with_closed_stdout(&os);
        assert!(!run.stderr.contains("panicked"), "{args:?} panicked on a closed stdout\n{}", run.describe());
        run.expect_code(0, &format!("{args:?} with a closed stdout"));
    }
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("pkg");
    let run = run_with_closed_stdout(&[
        OsStr::new("generate"),
        OsStr::new("a table with two mugs"),
        OsStr::new("--out"),
        out.as_os_str(),
        OsStr::new("--json"),
    ]);
    assert!(!run.stderr.contains("panicked"), "generate panicked on a closed stdout\n{}", run.describe());
    run.expect_code(0, "generate --json with a closed stdout");
    assert_package_files(&out);
}

#[test]
fn help_and_version_succeed() {
    let run = scenewright(["--help"]);
    run.expect_code(0, "--help");
    for cmd in ["generate", "validate", "render", "assets", "robots", "bench"] {
        assert!(run.stdout.contains(cmd), "--help does not list '{cmd}'\n{}", run.describe());
    }
    let run = scenewright(["--version"]);
    run.expect_code(0, "--version");
    assert!(run.stdout.starts_with("scenewright "), "{}", run.describe());
}
