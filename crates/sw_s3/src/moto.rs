//! moto's S3 server on loopback, for tests: a real S3-protocol server installed from PyPI
//! by `scripts/setup.sh --tests` into `.cache/s3-venv`. (moto checks the protocol, not the
//! signatures; the signer is checked against AWS's published values in this crate's unit
//! tests.)

use std::net::{SocketAddr, TcpListener, TcpStream};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::{S3Client, S3Config};

/// A running moto server, stopped on drop.
#[derive(Debug)]
pub struct MotoServer {
    child: Child,
    addr: SocketAddr,
}

impl MotoServer {
    /// Where setup puts the server.
    pub fn binary() -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../.cache/s3-venv/bin/moto_server")
    }

    /// Starts a server on a free loopback port and waits until it listens.
    pub fn start() -> Result<Self, String> {
        let bin = Self::binary();
        if !bin.exists() {
            return Err(format!("{} is missing: run scripts/setup.sh --tests", bin.display()));
        }
        let port = TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .map_err(|e| format!("no free port: {e}"))?
            .port();
        let child = Command::new(&bin)
            .args(["-H", "127.0.0.1", "-p", &port.to_string()])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .map_err(|e| format!("{}: {e}", bin.display()))?;
        let mut server = Self { child, addr: SocketAddr::from(([127, 0, 0, 1], port)) };
        let deadline = Instant::now() + Duration::from_secs(60);
        while TcpStream::connect(server.addr).is_err() {
            if let Ok(Some(status)) = server.child.try_wait() {
                return Err(format!("moto_server exited ({status}) before listening"));
            }
            if Instant::now() > deadline {
                return Err("moto_server did not listen within 60 s".into());
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        Ok(server)
    }

    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    /// A configuration for `bucket` on this server (moto takes any credentials).
    pub fn config(&self, bucket: &str) -> S3Config {
        S3Config {
            endpoint: format!("http://{}", self.addr),
            bucket: bucket.into(),
            region: "us-east-1".into(),
            access_key: "testing".into(),
            secret_key: "testing".into(),
        }
    }

    /// A client for `bucket`, created.
    pub fn bucket(&self, bucket: &str) -> Result<S3Client, crate::S3Error> {
        let c = S3Client::new(self.config(bucket));
        c.ensure_bucket()?;
        Ok(c)
    }
}

impl Drop for MotoServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
