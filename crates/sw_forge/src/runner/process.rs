//! One CAD worker process: started with its own process group and a private directory,
//! spoken to with JSON lines, killed (with every job process it forked) when it hangs,
//! breaks the protocol or ran code that violated the sandbox.

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::{RunnerConfig, RunnerError};

/// The longest protocol line accepted from a worker.
const MAX_LINE: usize = 4 << 20;

/// What a worker said when it was ready.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WorkerInfo {
    pub pid: u32,
    pub python: String,
    #[serde(default)]
    pub cadquery: Option<String>,
    #[serde(default)]
    pub openscad: Option<String>,
    #[serde(default)]
    pub languages: Vec<String>,
    /// The sandbox layers this kernel offers and the self-test's findings.
    #[serde(default)]
    pub sandbox: Value,
}

enum Line {
    Text(String),
    TooLong,
    Closed,
}

/// Why a job got no answer line.
#[derive(Debug)]
pub(crate) enum Fault {
    /// No answer within the deadline.
    Hung,
    /// The worker exited or closed its output; the tail of its stderr.
    Died(String),
    /// It answered with something that is not a result line.
    Protocol(String),
}

#[derive(Debug)]
pub(crate) struct WorkerProcess {
    child: Child,
    stdin: Option<ChildStdin>,
    lines: Receiver<Line>,
    stderr_tail: Arc<Mutex<VecDeque<String>>>,
    pub(crate) info: WorkerInfo,
    pub(crate) root: PathBuf,
}

impl std::fmt::Debug for Line {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Line::Text(t) => write!(f, "Text({} bytes)", t.len()),
            Line::TooLong => f.write_str("TooLong"),
            Line::Closed => f.write_str("Closed"),
        }
    }
}

impl WorkerProcess {
    /// Starts a worker in `root` (created here, removed on kill) and waits until it has
    /// imported CadQuery and passed its sandbox self-test.
    pub(crate) fn spawn(config: &RunnerConfig, script: &Path, root: PathBuf) -> Result<Self, RunnerError> {
        use std::os::unix::process::CommandExt;

        fs_err::create_dir_all(&root).map_err(|e| RunnerError::Io(e.to_string()))?;
        let limits = serde_json::json!({
            "timeout_s": config.timeout.as_secs_f64(),
            "memory_mb": config.memory_mb,
            "max_output_mb": config.max_output_mb,
            "max_triangles": config.max_triangles,
        });
        let mut cmd = Command::new(&config.python);
        cmd.arg("-I")
            .arg("-B")
            .arg(script)
            .arg("--root")
            .arg(&root)
            .arg("--limits")
            .arg(limits.to_string())
            .env_clear()
            .env("PATH", "/usr/bin:/bin")
            .env("LANG", "C.UTF-8")
            .env("OPENBLAS_NUM_THREADS", "1")
            .env("OMP_NUM_THREADS", "1")
            .env("HOME", &root)
            .env("TMPDIR", &root)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .process_group(0);
        if !config.strict_sandbox {
            cmd.arg("--weak");
        }
        let mut child = cmd
            .spawn()
            .map_err(|e| RunnerError::Spawn { python: config.python.display().to_string(), message: e.to_string() })?;
        let stdout = child.stdout.take();
        let stderr = child.stderr.take();
        let (tx, rx) = mpsc::channel();
        if let Some(out) = stdout {
            std::thread::spawn(move || read_lines(out, &tx));
        }
        let stderr_tail = Arc::new(Mutex::new(VecDeque::new()));
        if let Some(err) = stderr {
            let tail = Arc::clone(&stderr_tail);
            std::thread::spawn(move || keep_tail(err, &tail));
        }
        let stdin = child.stdin.take();
        let mut w = WorkerProcess {
            child,
            stdin,
            lines: rx,
            stderr_tail,
            info: WorkerInfo {
                pid: 0,
                python: String::new(),
                cadquery: None,
                openscad: None,
                languages: Vec::new(),
                sandbox: Value::Null,
            },
            root,
        };
        let first = match w.lines.recv_timeout(config.startup_timeout) {
            Ok(Line::Text(t)) => t,
            Ok(_) | Err(RecvTimeoutError::Disconnected) => {
                let tail = w.stderr();
                w.kill();
                return Err(RunnerError::Startup(format!("the worker exited while starting: {tail}")));
            }
            Err(RecvTimeoutError::Timeout) => {
                w.kill();
                return Err(RunnerError::Startup(format!(
                    "the worker was not ready within {:.0} s",
                    config.startup_timeout.as_secs_f64()
                )));
            }
        };
        let value: Value = serde_json::from_str(&first)
            .map_err(|e| RunnerError::Startup(format!("unreadable ready line ({e}): {}", preview(&first))))?;
        let kind = value.get("type").and_then(Value::as_str).unwrap_or("");
        if kind == "refused" {
            w.kill();
            return Err(RunnerError::SandboxUnavailable(
                value.get("sandbox").cloned().unwrap_or(Value::Null).to_string(),
            ));
        }
        if kind != "ready" {
            w.kill();
            return Err(RunnerError::Startup(format!("unexpected first line: {}", preview(&first))));
        }
        w.info = serde_json::from_value(value).map_err(|e| RunnerError::Startup(format!("ready line: {e}")))?;
        Ok(w)
    }

    /// Sends one job line and waits for its answer.
    pub(crate) fn call(&mut self, job: &Value, deadline: Duration) -> Result<Value, Fault> {
        let Some(stdin) = self.stdin.as_mut() else {
            return Err(Fault::Died("the worker's input is closed".into()));
        };
        let mut line = job.to_string();
        line.push('\n');
        if stdin.write_all(line.as_bytes()).and_then(|_| stdin.flush()).is_err() {
            return Err(Fault::Died(self.stderr()));
        }
        match self.lines.recv_timeout(deadline) {
            Ok(Line::Text(t)) => serde_json::from_str(&t).map_err(|e| Fault::Protocol(format!("{e}: {}", preview(&t)))),
            Ok(Line::TooLong) => Err(Fault::Protocol(format!("a line longer than {MAX_LINE} bytes"))),
            Ok(Line::Closed) | Err(RecvTimeoutError::Disconnected) => Err(Fault::Died(self.stderr())),
            Err(RecvTimeoutError::Timeout) => Err(Fault::Hung),
        }
    }

    /// The last lines the worker wrote to stderr.
    pub(crate) fn stderr(&self) -> String {
        self.stderr_tail.lock().map(|t| t.iter().cloned().collect::<Vec<_>>().join(" | ")).unwrap_or_default()
    }

    /// Kills the worker and every process in its group (the job it forked, its
    /// standby), then removes its directory.
    pub(crate) fn kill(&mut self) {
        self.stdin = None;
        if let Some(pid) = rustix::process::Pid::from_raw(self.child.id() as i32) {
            let _ = rustix::process::kill_process_group(pid, rustix::process::Signal::KILL);
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
        let _ = fs_err::remove_dir_all(&self.root);
    }
}

impl Drop for WorkerProcess {
    fn drop(&mut self) {
        self.kill();
    }
}

fn read_lines(out: impl Read, tx: &mpsc::Sender<Line>) {
    let mut reader = BufReader::with_capacity(1 << 16, out);
    let mut buf = Vec::new();
    loop {
        buf.clear();
        let mut limited = (&mut reader).take(MAX_LINE as u64 + 1);
        match limited.read_until(b'\n', &mut buf) {
            Ok(0) | Err(_) => {
                let _ = tx.send(Line::Closed);
                return;
            }
            Ok(_) => {}
        }
        if buf.len() > MAX_LINE {
            let _ = tx.send(Line::TooLong);
            // Skip to the end of the offending line.
            let mut rest = Vec::new();
            if reader.read_until(b'\n', &mut rest).map(|n| n == 0).unwrap_or(true) {
                let _ = tx.send(Line::Closed);
                return;
            }
            continue;
        }
        let text = String::from_utf8_lossy(&buf).trim().to_string();
        if text.is_empty() {
            continue;
        }
        if tx.send(Line::Text(text)).is_err() {
            return;
        }
    }
}

fn keep_tail(err: impl Read, tail: &Mutex<VecDeque<String>>) {
    let reader = BufReader::new(err.take(64 << 20));
    for line in reader.split(b'\n') {
        let Ok(line) = line else { return };
        let text = String::from_utf8_lossy(&line).trim().to_string();
        if text.is_empty() {
            continue;
        }
        tracing::debug!(target: "sw_forge::worker", "{}", preview(&text));
        if let Ok(mut t) = tail.lock() {
            if t.len() >= 12 {
                t.pop_front();
            }
            t.push_back(preview(&text));
        }
    }
}

fn preview(s: &str) -> String {
    let mut out: String = s.chars().take(300).collect();
    if out.len() < s.len() {
        out.push('…');
    }
    out
}
