//! The two real servers of the opt-in suite, started from what `scripts/setup.sh
//! --real-llm` put in `.cache/llm`: llama.cpp's `llama-server` and llama-cpp-python's
//! server, each with SmolLM2-135M-Instruct on one thread, on a free loopback port.
//! A server is killed when its handle is dropped, so a failing test leaves no process.

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// Which server.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    LlamaCpp,
    LlamaCppPython,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::LlamaCpp => "llama-server",
            Kind::LlamaCppPython => "llama-cpp-python",
        }
    }
}

/// The name both servers are told to answer to.
pub const ALIAS: &str = "smollm2-135m-instruct";

fn cache() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.cache/llm")
}

fn model() -> PathBuf {
    cache().join("smollm2/SmolLM2-135M-Instruct.Q4_1.gguf")
}

/// A running server.
#[derive(Debug)]
pub struct Server {
    pub kind: Kind,
    pub port: u16,
    child: Option<Child>,
    log: PathBuf,
}

fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0").and_then(|l| l.local_addr()).map(|a| a.port()).expect("a free port")
}

/// `GET path` answered 200.
fn get_ok(port: u16, path: &str) -> bool {
    use std::io::{Read, Write};
    let Ok(mut c) = std::net::TcpStream::connect(("127.0.0.1", port)) else { return false };
    let _ = c.set_read_timeout(Some(Duration::from_secs(2)));
    if c.write_all(format!("GET {path} HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n").as_bytes()).is_err() {
        return false;
    }
    let mut head = [0u8; 16];
    c.read(&mut head).is_ok_and(|n| String::from_utf8_lossy(&head[..n]).contains(" 200"))
}

impl Server {
    /// Starts `kind` on a free port and waits until it serves (at most a minute).
    pub fn start(kind: Kind) -> Server {
        Self::start_on(kind, free_port())
    }

    /// Starts `kind` on `port`.
    pub fn start_on(kind: Kind, port: u16) -> Server {
        assert!(
            model().is_file(),
            "{} is missing: run scripts/setup.sh --real-llm first (the real-model suite is opt-in)",
            model().display()
        );
        let log = std::env::temp_dir().join(format!("sw-real-llm-{}-{port}.log", kind.name()));
        let out = std::fs::File::create(&log).expect("the server's log file");
        let err = out.try_clone().expect("the server's log file");
        let mut cmd = match kind {
            Kind::LlamaCpp => {
                let mut c = Command::new(cache().join("build/bin/llama-server"));
                c.args(["-m"]).arg(model()).args([
                    "-t",
                    "1",
                    "--host",
                    "127.0.0.1",
                    "--port",
                    &port.to_string(),
                    "--alias",
                    ALIAS,
                    "-c",
                    "8192",
                    "-np",
                    "1",
                ]);
                c
            }
            Kind::LlamaCppPython => {
                let mut c = Command::new(cache().join("py-venv/bin/python"));
                c.args(["-m", "llama_cpp.server", "--model"]).arg(model()).args([
                    "--n_threads",
                    "1",
                    "--host",
                    "127.0.0.1",
                    "--port",
                    &port.to_string(),
                    "--model_alias",
                    ALIAS,
                    "--n_ctx",
                    "8192",
                ]);
                c
            }
        };
        let child =
            cmd.stdin(Stdio::null()).stdout(out).stderr(err).spawn().unwrap_or_else(|e| {
                panic!("{} could not start ({e}): run scripts/setup.sh --real-llm first", kind.name())
            });
        let s = Server { kind, port, child: Some(child), log };
        s.wait_ready(Duration::from_secs(60));
        s
    }

    fn wait_ready(&self, budget: Duration) {
        let t0 = Instant::now();
        let ready = match self.kind {
            Kind::LlamaCpp => "/health",
            Kind::LlamaCppPython => "/v1/models",
        };
        while t0.elapsed() < budget {
            if get_ok(self.port, ready) {
                return;
            }
            std::thread::sleep(Duration::from_millis(200));
        }
        panic!(
            "{} did not become ready in {budget:?}; its log: {}",
            self.kind.name(),
            std::fs::read_to_string(&self.log).unwrap_or_default()
        );
    }

    pub fn base_url(&self) -> String {
        format!("http://127.0.0.1:{}/v1", self.port)
    }

    /// Kills the process (`kill -9`: a crash, not a shutdown).
    pub fn kill(&mut self) {
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.kill();
        if std::thread::panicking() {
            eprintln!("{}'s log is kept: {}", self.kind.name(), self.log.display());
        } else {
            let _ = std::fs::remove_file(&self.log);
        }
    }
}
