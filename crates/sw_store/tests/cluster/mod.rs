//! A throwaway PostgreSQL cluster for tests: `initdb` and `pg_ctl` from Debian's
//! `postgresql` package (which `scripts/setup.sh --tests` installs), started on loopback in
//! a temporary directory (as the `postgres` user when the tests run as root) and stopped
//! when dropped. Shared by the store's, the server's and the CLI's tests (`#[path]`), so it
//! needs nothing but the standard library and `tempfile`.

#![allow(clippy::unwrap_used, clippy::expect_used, dead_code)]

use std::net::TcpListener;
use std::path::PathBuf;
use std::process::{Command, Output};

/// A PostgreSQL cluster that lives as long as this value.
#[derive(Debug)]
pub struct Cluster {
    dir: tempfile::TempDir,
    bin: PathBuf,
    port: u16,
    as_postgres: bool,
}

/// The newest PostgreSQL's binaries.
fn bin_dir() -> PathBuf {
    let mut versions: Vec<PathBuf> = std::fs::read_dir("/usr/lib/postgresql")
        .expect("PostgreSQL is not installed: run scripts/setup.sh --tests")
        .filter_map(|e| e.ok().map(|e| e.path().join("bin")))
        .filter(|p| p.join("initdb").exists())
        .collect();
    versions.sort();
    versions.pop().expect("no initdb under /usr/lib/postgresql: run scripts/setup.sh --tests")
}

fn is_root() -> bool {
    Command::new("id").arg("-u").output().is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
}

impl Cluster {
    /// initdb + pg_ctl start on a free loopback port (fsync off: the tests kill our
    /// processes, never PostgreSQL's).
    pub fn start() -> Self {
        let dir = tempfile::Builder::new().prefix("sw-pg-").tempdir().unwrap();
        let as_postgres = is_root();
        if as_postgres {
            let ok = Command::new("chown").args(["-R", "postgres:postgres"]).arg(dir.path()).status().unwrap();
            assert!(ok.success());
        }
        let port = TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
        let c = Cluster { dir, bin: bin_dir(), port, as_postgres };
        let data = c.path("data");
        c.run("initdb", &["-D", &data, "-A", "trust", "-U", "sw", "-E", "UTF8", "--no-sync"]);
        let opts = format!("-h 127.0.0.1 -p {port} -k {} -c fsync=off -c max_connections=200", c.dir.path().display());
        c.run("pg_ctl", &["-D", &data, "-l", &c.path("log"), "-w", "-o", &opts, "start"]);
        c
    }

    fn command(&self, tool: &str) -> Command {
        let exe = self.bin.join(tool);
        if self.as_postgres {
            let mut c = Command::new("runuser");
            c.args(["-u", "postgres", "--"]).arg(exe);
            c
        } else {
            Command::new(exe)
        }
    }

    fn run(&self, tool: &str, args: &[&str]) -> Output {
        let out = self.command(tool).args(args).output().unwrap();
        assert!(
            out.status.success(),
            "{tool} failed: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        out
    }

    fn path(&self, name: &str) -> String {
        self.dir.path().join(name).display().to_string()
    }

    /// The URL of a database in the cluster (`postgres` always exists).
    pub fn url(&self, database: &str) -> String {
        format!("postgres://sw@127.0.0.1:{}/{database}", self.port)
    }

    /// Creates a fresh database and returns its URL.
    pub fn database(&self, name: &str) -> String {
        let plain = |c: char| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_';
        assert!(name.starts_with(|c: char| c.is_ascii_lowercase()) && name.chars().all(plain), "{name}");
        let port = self.port.to_string();
        self.run("createdb", &["-h", "127.0.0.1", "-p", &port, "-U", "sw", name]);
        self.url(name)
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let data = self.path("data");
        let _ = self.command("pg_ctl").args(["-D", &data, "-m", "immediate", "stop"]).output();
    }
}
