#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The hostile-code suite: code that opens sockets, reads and writes outside its
//! directory, forks, runs programs, loads native code, exhausts memory, loops forever,
//! floods its output or signals its parent. Every case runs twice: through every layer
//! (the syntax-tree allow-list refuses it before it runs), and with the in-process
//! layers off (no allow-list, no audit hook, the real builtins) to prove that the
//! operating-system layers hold on their own. Each time the job gets a clear error, the
//! worker that ran it is replaced, nothing escapes (canaries, a listening socket, a
//! secret file), and the next job runs normally.
//!
//! Needs `scripts/setup.sh --tests` (the CadQuery venv); fails, never skips, without it.

use std::io::ErrorKind;
use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, OnceLock};
use std::time::Duration;

use sw_forge::failure::FailureKind;
use sw_forge::runner::{CadError, CadJob, CadRunner, RunnerConfig};

const BENIGN: &str = "result = cq.Workplane('XY').box(10, 20, 30)";

struct World {
    runner: CadRunner,
    /// Everything hostile code might try to create or reach.
    outside: tempfile::TempDir,
    listener: TcpListener,
    secret: String,
    /// Worker processes that ran hostile code (they must never serve again).
    retired: Mutex<Vec<u32>>,
}

fn world() -> &'static World {
    static W: OnceLock<World> = OnceLock::new();
    W.get_or_init(|| {
        let runner = CadRunner::start(RunnerConfig {
            workers: 2,
            timeout: Duration::from_secs(3),
            memory_mb: 1024,
            max_output_mb: 16,
            max_triangles: 100_000,
            ..RunnerConfig::default()
        })
        .unwrap_or_else(|e| panic!("the CAD runner must start (run scripts/setup.sh --tests): {e}"));
        let outside = tempfile::tempdir().expect("temp dir");
        let secret = format!("sw-secret-{}", std::process::id());
        std::fs::write(outside.path().join("secret.txt"), &secret).expect("secret");
        let listener = TcpListener::bind("127.0.0.1:0").expect("listener");
        listener.set_nonblocking(true).expect("nonblocking");
        World { runner, outside, listener, secret, retired: Mutex::new(Vec::new()) }
    })
}

impl World {
    fn canary(&self, name: &str) -> PathBuf {
        self.outside.path().join(name)
    }

    fn port(&self) -> u16 {
        self.listener.local_addr().map(|a| a.port()).unwrap_or(9)
    }

    fn fill(&self, code: &str, canary: &Path) -> String {
        code.replace("CANARY", &canary.display().to_string())
            .replace("SECRET", &self.canary("secret.txt").display().to_string())
            .replace("PORT", &self.port().to_string())
    }

    /// Nothing has reached out: no canary file, no connection, no leaked secret.
    fn assert_no_escape(&self, case: &str, canary: &Path, texts: &[&str]) {
        assert!(!canary.exists(), "{case}: the canary {} was created", canary.display());
        match self.listener.accept() {
            Err(e) if e.kind() == ErrorKind::WouldBlock => {}
            other => panic!("{case}: something connected to the test's socket: {other:?}"),
        }
        for t in texts {
            assert!(!t.contains(&self.secret), "{case}: the secret leaked: {t}");
        }
    }

    /// The next job runs normally, on a worker that never ran hostile code.
    fn assert_healthy(&self, case: &str) {
        let run = self.runner.run(&CadJob::cadquery(BENIGN)).unwrap_or_else(|e| panic!("{case}: next job failed: {e}"));
        let retired = self.retired.lock().unwrap_or_else(|e| e.into_inner());
        assert!(
            !retired.contains(&run.worker_pid),
            "{case}: worker {} ran hostile code and served again",
            run.worker_pid
        );
        let size = run.mesh.bounds().size();
        assert!((size[2] - 30.0).abs() < 1e-3, "{case}: {size:?}");
    }
}

/// Runs `code` through every layer (must be refused before it runs) and then through the
/// operating-system layers alone (must be contained, the worker replaced).
fn contained(case: &str, code: &str, kinds: &[FailureKind]) {
    let w = world();
    let canary = w.canary(&format!("{case}.canary"));
    let code = w.fill(code, &canary);

    // 1. All layers: refused by the allow-list, nothing ran, no worker harmed.
    let e = w.runner.run(&CadJob::cadquery(code.clone())).expect_err(case);
    assert_eq!(e.failure.kind, FailureKind::SandboxViolation, "{case} (all layers): {e}");
    assert!(!e.worker_replaced, "{case}: refused code ran nowhere");
    assert!(!e.failure.message.is_empty());
    w.assert_no_escape(case, &canary, &[&e.failure.message, e.output()]);

    // 2. Operating-system layers only.
    executed(case, CadJob { check_policy: false, ..CadJob::cadquery(code) }, kinds, &canary);
}

/// Runs a job that the sandbox must stop while it runs.
fn executed(case: &str, job: CadJob, kinds: &[FailureKind], canary: &Path) {
    let w = world();
    let before = w.runner.stats().replaced;
    let e = w.runner.run(&job).expect_err(case);
    assert!(kinds.contains(&e.failure.kind), "{case}: {:?} {}", e.failure.kind, e.failure.message);
    assert!(!e.failure.message.trim().is_empty(), "{case}: an empty message");
    assert!(e.worker_replaced, "{case}: the worker was not replaced ({e})");
    assert!(w.runner.stats().replaced > before, "{case}");
    if let Some(pid) = e.worker_pid {
        w.retired.lock().unwrap_or_else(|e| e.into_inner()).push(pid);
    }
    w.assert_no_escape(case, canary, &[&e.failure.message, e.output()]);
    w.assert_healthy(case);
}

const SANDBOX: &[FailureKind] = &[FailureKind::SandboxViolation];

#[test]
fn tcp_connections_are_killed() {
    contained(
        "tcp",
        "import socket\ns = socket.socket(socket.AF_INET, socket.SOCK_STREAM)\ns.connect(('127.0.0.1', PORT))\ns.sendall(b'x')",
        SANDBOX,
    );
}

#[test]
fn name_lookups_and_udp_are_killed() {
    contained("dns", "import socket\nsocket.getaddrinfo('example.com', 80)", SANDBOX);
}

#[test]
fn unix_sockets_are_killed() {
    contained("unix", "import socket\ns = socket.socket(socket.AF_UNIX)\ns.connect('\\0x11')", SANDBOX);
}

#[test]
fn reading_outside_the_job_directory_is_refused() {
    contained("read", "data = open('SECRET').read()\nraise ValueError(data)", SANDBOX);
    contained("passwd", "print(open('/etc/passwd').read())\nresult = cq.Workplane().box(1,1,1)", SANDBOX);
}

#[test]
fn writing_outside_the_job_directory_is_refused() {
    contained("write", "open('CANARY', 'w').write('escaped')", SANDBOX);
    contained("write_parent", "open('../escaped.txt', 'w').write('x')\nopen('CANARY', 'w')", SANDBOX);
}

#[test]
fn links_to_files_outside_are_refused() {
    contained("symlink", "import os\nos.symlink('SECRET', 'result.stl')\nresult = cq.Workplane().box(1,1,1)", SANDBOX);
}

#[test]
fn fork_bombs_are_killed() {
    contained("fork", "import os\nwhile True:\n    os.fork()", SANDBOX);
}

#[test]
fn programs_cannot_be_run() {
    contained("subprocess", "import subprocess\nsubprocess.run(['touch', 'CANARY'])", SANDBOX);
    contained("system", "import os\nos.system('touch CANARY')", SANDBOX);
    contained("exec", "import os\nos.execv('/usr/bin/touch', ['touch', 'CANARY'])", SANDBOX);
}

#[test]
fn native_code_through_ctypes_is_contained() {
    contained("ctypes", "import ctypes\nctypes.CDLL(None).system(b'touch CANARY')", SANDBOX);
}

#[test]
fn memory_bombs_are_stopped() {
    // Plain Python the allow-list cannot refuse: the memory limit stops one large request.
    // Memory written chunk by chunk grows at the speed pages are zeroed (~0.4 GB/s on a busy
    // 2-vCPU machine), so there either the memory limit or the 3 s clock stops it first.
    let w = world();
    const STOPPED: &[FailureKind] = &[FailureKind::SandboxViolation, FailureKind::Timeout];
    for (case, code, kinds) in [
        ("memory", "x = bytearray(64 * 1024 ** 3)", SANDBOX),
        ("memory_growth", "chunks = []\nwhile True:\n    chunks.append(bytearray(128 << 20))", STOPPED),
    ] {
        let canary = w.canary(&format!("{case}.canary"));
        executed(case, CadJob::cadquery(code), kinds, &canary);
        executed(case, CadJob { check_policy: false, ..CadJob::cadquery(code) }, kinds, &canary);
    }
}

#[test]
fn infinite_loops_are_killed() {
    // Nothing for the allow-list to refuse here: every layer runs it, the clock stops it.
    let w = world();
    let canary = w.canary("loop.canary");
    executed("loop", CadJob::cadquery("while True:\n    pass"), &[FailureKind::Timeout], &canary);
    executed(
        "loop_bare",
        CadJob { check_policy: false, ..CadJob::cadquery("while True:\n    pass") },
        &[FailureKind::Timeout],
        &canary,
    );
    contained("sleep", "import time\ntime.sleep(3600)", &[FailureKind::Timeout]);
}

#[test]
fn huge_outputs_are_stopped() {
    contained("print_flood", "import sys\nsys.stdout.write('x' * (64 << 20))\nsys.stdout.flush()", SANDBOX);
    contained(
        "file_flood",
        "import os\nf = open('big.bin', 'wb')\nwhile True:\n    f.write(b'0' * (1 << 20))",
        SANDBOX,
    );
}

#[test]
fn signals_to_other_processes_are_killed() {
    contained("kill_parent", "import os\nos.kill(os.getppid(), 9)", SANDBOX);
    contained("kill_group", "import os\nos.kill(0, 9)", SANDBOX);
}

#[test]
fn the_parents_memory_is_out_of_reach() {
    contained("proc_mem", "import os\nopen('/proc/%d/mem' % os.getppid(), 'rb').read(16)", SANDBOX);
}

#[test]
fn introspection_escapes_are_refused_by_the_allow_list() {
    // The classic way out of restricted builtins; the allow-list refuses the dunders,
    // and without it the operating-system layers still stop what the code reaches for.
    contained(
        "subclasses",
        "os = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close'][0].__init__.__globals__\nos['system']('touch CANARY')",
        SANDBOX,
    );
}

#[test]
fn huge_meshes_are_refused() {
    let w = world();
    let code = "result = cq.Workplane('XY').pushPoints([(i * 3.0, j * 3.0) for i in range(40) for j in range(40)]).sphere(1.2)";
    let e = w.runner.run(&CadJob::cadquery(code)).expect_err("too many triangles");
    assert!(
        matches!(e.failure.kind, FailureKind::SandboxViolation | FailureKind::Timeout),
        "{:?}: {}",
        e.failure.kind,
        e.failure.message
    );
    assert!(e.worker_replaced);
    w.assert_healthy("huge_mesh");
}

#[test]
fn a_worker_that_stops_answering_is_killed_and_replaced() {
    // A runner of its own: this test freezes its worker.
    let runner =
        CadRunner::start(RunnerConfig { workers: 1, timeout: Duration::from_secs(2), ..RunnerConfig::default() })
            .unwrap_or_else(|e| panic!("the CAD runner must start (run scripts/setup.sh --tests): {e}"));
    let first = runner.run(&CadJob::cadquery(BENIGN)).expect("a first job");
    let busy = runner.clone();
    let handle = std::thread::spawn(move || {
        busy.run(&CadJob::cadquery("import math\nx = 0\nfor i in range(10**9):\n    x += math.sqrt(i)"))
    });
    std::thread::sleep(Duration::from_millis(300));
    // Freeze the worker (and its job): only the runner's own deadline can end this.
    let pids = worker_pids(runner.runtime_dir());
    assert!(!pids.is_empty());
    for pid in &pids {
        let _ = std::process::Command::new("kill").args(["-STOP", &pid.to_string()]).status();
    }
    let result = handle.join().expect("join");
    let e = result.expect_err("a frozen worker gives no answer");
    assert_eq!(e.failure.kind, FailureKind::Timeout, "{}", e.failure.message);
    assert!(e.worker_replaced);
    assert_eq!(e.worker_pid, Some(first.worker_pid));
    // Killed, not merely abandoned.
    std::thread::sleep(Duration::from_millis(200));
    for pid in &pids {
        let alive = std::fs::read_to_string(format!("/proc/{pid}/stat")).is_ok_and(|s| !s.contains(") Z "));
        assert!(!alive, "process {pid} of the frozen worker is still alive");
    }
    let next = runner.run(&CadJob::cadquery(BENIGN)).expect("the replacement works");
    assert_ne!(next.worker_pid, first.worker_pid);
    assert_eq!(runner.stats().replaced, 1);
}

/// PIDs of the worker processes (the ones whose command line names the runtime dir).
fn worker_pids(runtime: &Path) -> Vec<u32> {
    let needle = runtime.display().to_string();
    let mut out = Vec::new();
    for entry in std::fs::read_dir("/proc").into_iter().flatten().flatten() {
        let Ok(pid) = entry.file_name().to_string_lossy().parse::<u32>() else { continue };
        let Ok(cmd) = std::fs::read(entry.path().join("cmdline")) else { continue };
        let cmd = String::from_utf8_lossy(&cmd).replace('\0', " ");
        if cmd.contains("cad_worker.py") && cmd.contains(&needle) {
            out.push(pid);
        }
    }
    out
}

#[test]
fn the_worker_reports_every_sandbox_layer() {
    let w = world();
    let info = w.runner.info().expect("info");
    let s = &info.sandbox;
    assert!(s["landlock_abi"].as_u64().unwrap_or(0) >= 1, "{s}");
    assert_eq!(s["seccomp"], serde_json::json!(true), "{s}");
    assert_eq!(s["selftest"]["file"], serde_json::json!(true), "{s}");
    assert_eq!(s["selftest"]["network"], serde_json::json!(true), "{s}");
    assert_eq!(s["threads_at_fork"], serde_json::json!(1), "{s}");
    assert!(info.languages.iter().any(|l| l == "cadquery"));
}

#[test]
fn ordinary_errors_keep_the_worker() {
    let w = world();
    let e = w.runner.run(&CadJob::cadquery("result = cq.Workplane('XY').box(1, 2)")).expect_err("bad call");
    assert_eq!(e.failure.kind, FailureKind::Runtime, "{}", e.failure.message);
    assert!(!e.worker_replaced);
    let e = w.runner.run(&CadJob::cadquery("result = cq.Workplane('XY'.box(1, 2, 3)")).expect_err("syntax");
    assert_eq!(e.failure.kind, FailureKind::Syntax, "{}", e.failure.message);
    assert_eq!(e.failure.line, Some(1));
    let e = w.runner.run(&CadJob::cadquery("result = cq.Workplane('XY').rect(3, 4)")).expect_err("a wire");
    assert_eq!(e.failure.kind, FailureKind::InvalidSolid, "{}", e.failure.message);
    let e = w.runner.run(&CadJob::cadquery("x = 1")).expect_err("nothing made");
    assert_eq!(e.failure.kind, FailureKind::InvalidSolid, "{}", e.failure.message);
    assert!(e.failure.message.contains("result"), "{}", e.failure.message);
}

#[test]
fn openscad_cannot_read_files_or_run_forever() {
    let w = world();
    let canary = w.canary("scad.canary");
    let read = w.fill("import(\"SECRET\");\nsurface(file = \"SECRET\");", &canary);
    let e = w.runner.run(&CadJob::openscad(read.clone())).expect_err("refused");
    assert_eq!(e.failure.kind, FailureKind::SandboxViolation, "{}", e.failure.message);
    assert!(!e.worker_replaced);
    // Without the statement check, Landlock keeps the file out of OpenSCAD's reach. A
    // cold OpenSCAD start (its libraries not yet in the page cache, the machine busy with
    // the bombs of the other tests) can outlast the suite's 3 s limit: such a run proves
    // nothing either way and is tried again.
    let e = patiently(|| w.runner.run(&CadJob { check_policy: false, ..CadJob::openscad(read.clone()) }))
        .expect_err("no geometry");
    w.assert_no_escape("scad_read", &canary, &[&e.failure.message, e.output()]);
    assert!(
        e.output().contains("Can't open") || e.output().contains("WARNING"),
        "OpenSCAD did not report the refused file: {:?}, output {:?}",
        e.failure,
        e.output()
    );
    let forever = "cube(len([for (i = [0 : 1e5]) for (j = [0 : 1e5]) i]));";
    let e = w.runner.run(&CadJob::openscad(forever)).expect_err("stopped");
    assert!(
        matches!(e.failure.kind, FailureKind::Timeout | FailureKind::Runtime | FailureKind::SandboxViolation),
        "{:?}",
        e.failure
    );
    w.assert_healthy("scad");
    let ok = patiently(|| w.runner.run(&CadJob::openscad("cube([10, 20, 30]);"))).expect("OpenSCAD runs");
    assert_eq!(ok.mesh.bounds().size().map(|v| v.round()), [10.0, 20.0, 30.0]);
}

/// Runs a job up to three times while it fails before printing anything (a timeout on a
/// cold start: see the OpenSCAD test); the earlier failures are printed for the record.
fn patiently<T>(mut job: impl FnMut() -> Result<T, CadError>) -> Result<T, CadError> {
    let mut last = job();
    for _ in 0..2 {
        match &last {
            Err(e) if e.output().is_empty() => {
                eprintln!("retrying a job that showed nothing: {:?}", e.failure);
                last = job();
            }
            _ => break,
        }
    }
    last
}
