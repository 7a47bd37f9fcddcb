//! Runtime directories left by runners that were killed. A runner removes its directory
//! (the worker's sources, one directory per job) when it stops; a process killed with
//! `kill -9` or crashed cannot, and the test suite's kill tests alone left a few per run.
//! Each directory names its owner (process id and PID namespace); a starting runner
//! removes those whose owner is gone.

use std::path::{Path, PathBuf};

/// What every runtime directory's name starts with.
pub(super) const PREFIX: &str = "scenewright-cad-";
/// The file in a runtime directory naming its owner: `<pid> <pid namespace>`.
const OWNER: &str = "owner";

/// This process's PID namespace (`pid:[4026531836]`), where the system has one.
fn namespace() -> Option<String> {
    std::fs::read_link("/proc/self/ns/pid").ok().map(|p| p.to_string_lossy().into_owned())
}

/// Records this process as the owner of `dir`. Without a PID namespace to name (not
/// Linux) nothing is written, and the directory is never swept.
pub(super) fn claim(dir: &Path) -> std::io::Result<()> {
    match namespace() {
        Some(ns) => std::fs::write(dir.join(OWNER), format!("{} {ns}\n", std::process::id())),
        None => Ok(()),
    }
}

/// Removes the runtime directories in `base` whose owner was a process of this PID
/// namespace that no longer exists. Directories of another namespace (another container
/// sharing the directory), of a live process, or without an owner are left alone.
/// Returns the directories removed.
pub(super) fn sweep(base: &Path) -> Vec<PathBuf> {
    let Some(ns) = namespace() else { return Vec::new() };
    let Ok(entries) = std::fs::read_dir(base) else { return Vec::new() };
    let mut removed = Vec::new();
    for e in entries.flatten() {
        if !e.file_name().to_string_lossy().starts_with(PREFIX) {
            continue;
        }
        let path = e.path();
        let Ok(owner) = std::fs::read_to_string(path.join(OWNER)) else { continue };
        let mut words = owner.split_whitespace();
        let (Some(pid), Some(their_ns)) = (words.next().and_then(|p| p.parse::<u32>().ok()), words.next()) else {
            continue;
        };
        let alive = Path::new("/proc").join(pid.to_string()).exists();
        if their_ns == ns && pid != std::process::id() && !alive && std::fs::remove_dir_all(&path).is_ok() {
            removed.push(path);
        }
    }
    removed
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    /// The pid of a process that has exited (and been reaped).
    fn dead_pid() -> u32 {
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let pid = child.id();
        child.wait().unwrap();
        pid
    }

    #[test]
    fn only_the_directories_of_dead_owners_in_this_namespace_are_removed() {
        let base = tempfile::tempdir().unwrap();
        let ns = namespace().unwrap();
        let make = |name: &str, owner: Option<String>| {
            let d = base.path().join(name);
            std::fs::create_dir_all(d.join("w1")).unwrap();
            if let Some(o) = owner {
                std::fs::write(d.join(OWNER), o).unwrap();
            }
            d
        };
        let dead = make("scenewright-cad-dead", Some(format!("{} {ns}", dead_pid())));
        let mine = base.path().join("scenewright-cad-mine");
        std::fs::create_dir_all(&mine).unwrap();
        claim(&mine).unwrap();
        let other_ns = make("scenewright-cad-other", Some(format!("{} pid:[1]", dead_pid())));
        let unowned = make("scenewright-cad-unowned", None);
        let not_ours = make("something-else", Some(format!("{} {ns}", dead_pid())));
        let torn = make("scenewright-cad-torn", Some("12".into()));
        assert_eq!(sweep(base.path()), vec![dead.clone()]);
        assert!(!dead.exists());
        for kept in [&mine, &other_ns, &unowned, &not_ours, &torn] {
            assert!(kept.exists(), "{} was removed", kept.display());
        }
    }
}
