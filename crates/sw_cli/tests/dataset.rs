//! `scenewright dataset` as a process: kill -9 twice and resume, Ctrl-C, a line cut short,
//! a full disk, a foreign directory, a bad prompt file — every time the manifest lists
//! only whole, verified, distinct scenes and nothing finished is redone or lost.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");
const PROMPT: &str = "a kitchen with a table, two chairs and two mugs on the table";

/// A child process that is killed when dropped, so a failing test leaves none behind.
struct Proc(Child);

impl Drop for Proc {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

fn start(out: &Path, count: u32) -> Proc {
    Proc(
        Command::new(BIN)
            .args(["dataset", "--prompt", PROMPT, "--count", &count.to_string(), "--jobs", "2", "--out"])
            .arg(out)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap(),
    )
}

fn run(args: &[&str], out: &Path) -> Output {
    Command::new(BIN).args(args).arg("--out").arg(out).output().unwrap()
}

fn lines(out: &Path) -> usize {
    std::fs::read_to_string(out.join("manifest.jsonl")).map_or(0, |t| t.matches('\n').count())
}

/// Waits until the manifest lists at least `n` scenes.
fn wait_for(out: &Path, n: usize) {
    let t0 = Instant::now();
    while lines(out) < n {
        assert!(t0.elapsed() < Duration::from_secs(300), "the dataset made fewer than {n} scenes in 300 s");
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn entries(out: &Path) -> Vec<Value> {
    let text = std::fs::read_to_string(out.join("manifest.jsonl")).unwrap();
    assert!(text.is_empty() || text.ends_with('\n'), "the manifest ends in a torn line");
    text.lines().map(|l| serde_json::from_str(l).expect("a manifest line is whole JSON")).collect()
}

/// Every listed scene is a whole package that MuJoCo verifies now, its files as listed;
/// ids and fingerprints are unique. Returns id → (entry, inode of its scene.xml).
fn check(out: &Path) -> BTreeMap<String, (Value, u64)> {
    use std::os::unix::fs::MetadataExt;
    let mut by_id = BTreeMap::new();
    let mut fingerprints = BTreeSet::new();
    for e in entries(out) {
        let id = e["id"].as_str().unwrap().to_string();
        let dir = out.join(e["dir"].as_str().unwrap());
        for f in e["files"].as_array().unwrap() {
            let meta = std::fs::metadata(dir.join(f["path"].as_str().unwrap())).unwrap();
            assert_eq!(meta.len(), f["bytes"].as_u64().unwrap(), "{id}: {f}");
        }
        let v = sw_pipeline::validate_dir(&dir).unwrap();
        assert!(v.passed, "{id} does not verify: {:?}", v.failures);
        assert!(fingerprints.insert(e["fingerprint"].as_str().unwrap().to_string()), "{id} is a duplicate");
        let ino = std::fs::metadata(dir.join("scene.xml")).unwrap().ino();
        assert!(by_id.insert(id.clone(), (e, ino)).is_none(), "{id} listed twice");
    }
    // Nothing half-made is left where a reader looks.
    for d in std::fs::read_dir(out.join("scenes")).unwrap().flatten() {
        let name = d.file_name().to_string_lossy().into_owned();
        assert!(!name.starts_with('.'), "a hidden directory in scenes/: {name}");
    }
    by_id
}

/// Independently of the fingerprint: two scenes differ when an object stands 1 cm or
/// more elsewhere, or their assets (mesh files) differ.
fn differ(a: &Path, b: &Path) -> bool {
    let read =
        |d: &Path| -> Value { serde_json::from_str(&std::fs::read_to_string(d.join("layout.json")).unwrap()).unwrap() };
    let (la, lb) = (read(a), read(b));
    let pos = |l: &Value| -> BTreeMap<String, Vec<f64>> {
        l["objects"]
            .as_array()
            .unwrap()
            .iter()
            .map(|o| {
                let p = o["pos"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
                (o["name"].as_str().unwrap().to_string(), p)
            })
            .collect()
    };
    let (pa, pb) = (pos(&la), pos(&lb));
    if pa.keys().ne(pb.keys()) {
        return true;
    }
    let moved = pa.iter().any(|(k, p)| {
        let q = &pb[k];
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt() >= 0.01
    });
    let meshes = |d: &Path| -> BTreeSet<String> {
        std::fs::read_dir(d.join("assets"))
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect()
    };
    moved || meshes(a) != meshes(b)
}

#[test]
fn killed_twice_and_resumed_ends_with_every_scene_once() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("ds");
    let count = 24;
    let mut before: BTreeMap<String, (Value, u64)> = BTreeMap::new();
    for (round, at) in [4usize, 12].into_iter().enumerate() {
        let mut p = start(&out, count);
        wait_for(&out, at);
        p.0.kill().unwrap(); // SIGKILL
        let status = p.0.wait().unwrap();
        assert!(status.code().is_none(), "round {round}: the run ended before it was killed");
        let now = check(&out);
        // Nothing listed before the kill is lost or made again.
        for (id, (e, ino)) in &before {
            let (e2, ino2) = now.get(id).unwrap_or_else(|| panic!("round {round}: {id} was lost"));
            assert_eq!(e, e2, "round {round}: {id}'s line changed");
            assert_eq!(ino, ino2, "round {round}: {id} was made again");
        }
        before = now;
    }
    let done = run(&["dataset", "--prompt", PROMPT, "--count", &count.to_string(), "--jobs", "2", "--json"], &out);
    assert_eq!(done.status.code(), Some(0), "{}", String::from_utf8_lossy(&done.stderr));
    let summary: Value = serde_json::from_slice(&done.stdout).unwrap();
    assert_eq!(summary["scenes_listed"], count);
    assert_eq!(
        summary["made"].as_u64().unwrap() as usize + summary["resumed"]["listed"].as_u64().unwrap() as usize,
        count as usize
    );
    let all = check(&out);
    let ids: Vec<String> = all.keys().cloned().collect();
    let want: Vec<String> = (0..count).map(|k| format!("0000-{k:06}")).collect();
    assert_eq!(ids, want);
    for (id, (e, ino)) in &before {
        assert_eq!((e, ino), (&all[id].0, &all[id].1), "{id} changed on the final resume");
    }
    let dirs: Vec<PathBuf> = all.values().map(|(e, _)| out.join(e["dir"].as_str().unwrap())).collect();
    for (i, a) in dirs.iter().enumerate() {
        for b in &dirs[i + 1..] {
            assert!(differ(a, b), "{} and {} are the same scene", a.display(), b.display());
        }
    }
    assert!(!out.join(".work").exists() || std::fs::read_dir(out.join(".work")).unwrap().next().is_none());
}

#[test]
fn ctrl_c_stops_cleanly_and_a_torn_line_is_made_again() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("ds");
    let p = start(&out, 30);
    wait_for(&out, 3);
    let pid = p.0.id().to_string();
    assert!(Command::new("kill").args(["-INT", &pid]).status().unwrap().success());
    let mut p = p;
    let t0 = Instant::now();
    let status = loop {
        if let Some(s) = p.0.try_wait().unwrap() {
            break s;
        }
        assert!(t0.elapsed() < Duration::from_secs(30), "Ctrl-C did not stop the run");
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(status.code(), Some(130));
    let mut stdout = String::new();
    std::io::Read::read_to_string(p.0.stdout.as_mut().unwrap(), &mut stdout).unwrap();
    assert!(stdout.contains("interrupted"), "{stdout}");
    let listed = check(&out);
    assert!(listed.len() >= 3 && listed.len() < 30);

    // A kill in the middle of appending: the last line cut in half. Its package is in
    // place, so resuming makes the same line again from the package.
    let path = out.join("manifest.jsonl");
    let text = std::fs::read_to_string(&path).unwrap();
    let last_start = text[..text.len() - 1].rfind('\n').map_or(0, |i| i + 1);
    let last: Value = serde_json::from_str(text[last_start..].trim()).unwrap();
    std::fs::write(&path, &text[..last_start + (text.len() - last_start) / 2]).unwrap();
    // And a half-made package where a kill leaves one.
    std::fs::create_dir_all(out.join(".work/0000-000029-seed999")).unwrap();
    std::fs::create_dir_all(out.join("scenes/.0000-000029.partial-1-2")).unwrap();
    let done = run(&["dataset", "--prompt", PROMPT, "--count", "30", "--json"], &out);
    assert_eq!(done.status.code(), Some(0), "{}", String::from_utf8_lossy(&done.stderr));
    let summary: Value = serde_json::from_slice(&done.stdout).unwrap();
    assert_eq!(summary["resumed"]["adopted"], 1);
    assert_eq!(summary["resumed"]["dropped_torn_line"], true);
    assert!(summary["resumed"]["discarded_partial"].as_u64().unwrap() >= 2);
    let all = check(&out);
    assert_eq!(all.len(), 30);
    let id = last["id"].as_str().unwrap();
    assert_eq!(all[id].0, last, "the adopted scene's line is not the one that was cut");
}

#[test]
fn a_full_disk_keeps_what_is_done_and_resumes() {
    // A 400 KiB tmpfs in a private mount namespace (needs root or user namespaces).
    let tmp = tempfile::tempdir().unwrap();
    let mnt = tmp.path().join("small");
    std::fs::create_dir(&mnt).unwrap();
    let script = format!(
        "mount -t tmpfs -o size=400k none {m} && {bin} dataset --prompt '{PROMPT}' --count 30 --jobs 2 --out {m}/ds; \
         code=$?; cp -a {m}/ds {keep}; exit $code",
        m = mnt.display(),
        bin = BIN,
        keep = tmp.path().join("kept").display()
    );
    let probe = Command::new("unshare").args(["-m", "true"]).output();
    if !probe.is_ok_and(|o| o.status.success()) {
        eprintln!("skipped: cannot make a private mount namespace here (unshare -m)");
        return;
    }
    let o = Command::new("unshare").args(["-m", "sh", "-c", &script]).output().unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    let last = stderr.lines().last().unwrap_or_default();
    assert!(last.contains("No space left on device") && last.contains("run the same command again"), "{last}");
    let kept = tmp.path().join("kept");
    let listed = check(&kept);
    assert!(!listed.is_empty() && listed.len() < 30, "{} listed", listed.len());
    // On a disk with room, the same command finishes the dataset.
    let done = run(&["dataset", "--prompt", PROMPT, "--count", "30", "--json"], &kept);
    assert_eq!(done.status.code(), Some(0), "{}", String::from_utf8_lossy(&done.stderr));
    let all = check(&kept);
    assert_eq!(all.len(), 30);
    for (id, (e, _)) in &listed {
        assert_eq!(&all[id].0, e);
    }
}

#[test]
fn bad_input_is_one_line_and_writes_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    // A directory that is not a dataset.
    let foreign = tmp.path().join("photos");
    std::fs::create_dir(&foreign).unwrap();
    std::fs::write(foreign.join("a.jpg"), b"x").unwrap();
    let o = run(&["dataset", "--prompt", PROMPT, "--count", "2"], &foreign);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("is not a scenewright dataset"), "{err}");
    assert_eq!(std::fs::read_dir(&foreign).unwrap().count(), 1);
    // A place that cannot be written (under a regular file: unwritable even for root).
    let o = run(&["dataset", "--prompt", PROMPT, "--count", "2"], &foreign.join("a.jpg").join("ds"));
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("cannot write the dataset in") && err.contains("a.jpg"), "{err}");
    assert_eq!(std::fs::read(foreign.join("a.jpg")).unwrap(), b"x");
    // A prompt file with a bad line names the line.
    let prompts = tmp.path().join("prompts.txt");
    std::fs::write(
        &prompts,
        format!("# comment\n{PROMPT}\n\n   \n").as_bytes().iter().chain(b"\x80\x81\n").copied().collect::<Vec<u8>>(),
    )
    .unwrap();
    let out = tmp.path().join("new");
    let o = run(&["dataset", "--prompts", prompts.to_str().unwrap(), "--count", "2"], &out);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("line 5 is not UTF-8"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!out.exists());
    // A line the planner cannot read is refused before any scene is made, naming the line.
    std::fs::write(&prompts, format!("{PROMPT}\nzzz qqq\n")).unwrap();
    let o = run(&["dataset", "--prompts", prompts.to_str().unwrap(), "--count", "2"], &out);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("line 2: nothing in the prompt was recognised") && err.lines().count() == 1, "{err}");
    assert!(!out.exists());
    std::fs::write(&prompts, "a kitchen with a table\n\n\n").unwrap();
    for (args, needle) in [
        (vec!["--count", "0"], "--count must be"),
        (vec!["--count", "2", "--robots", "r2d2"], "unknown robot 'r2d2'"),
        (vec!["--count", "2", "--physics", "bullet"], "unknown physics target"),
        (vec!["--count", "2", "--anomaly", "gremlins"], "unknown anomaly"),
    ] {
        let mut a = vec!["dataset", "--prompts", prompts.to_str().unwrap()];
        a.extend(args);
        let o = run(&a, &out);
        assert_eq!(o.status.code(), Some(2), "{a:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(needle) && err.lines().count() == 1, "{a:?}: {err}");
        assert!(!out.exists());
    }
    // Another dataset in the directory: other options are refused, the same resume.
    let o = run(&["dataset", "--prompts", prompts.to_str().unwrap(), "--count", "1"], &out);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let o = run(&["dataset", "--prompts", prompts.to_str().unwrap(), "--count", "1", "--seed", "5"], &out);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("other seed"));
    assert_eq!(check(&out).len(), 1);
}
