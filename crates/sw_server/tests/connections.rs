//! Over real sockets: a connection that never finishes its request headers (or sends
//! nothing) is closed after the header timeout, by the hundred; the data directory and the
//! database holding the token secret are readable by the service's user only.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::time::{Duration, Instant};

use sw_server::HttpOptions;
use sw_store::QueueLimits;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn connections_that_never_finish_their_headers_are_closed() {
    let a = common::app(QueueLimits::default()).await;
    let opts = HttpOptions { header_timeout: Duration::from_secs(1), ..HttpOptions::default() };
    let (addr, _stop, _served) = common::serve_on_socket(&a, opts).await;
    let mut conns = Vec::new();
    for i in 0..300 {
        let mut s = tokio::net::TcpStream::connect(addr).await.unwrap();
        // A third send nothing, a third half a request line, a third headers without the end.
        match i % 3 {
            0 => {}
            1 => s.write_all(b"GET /api/me HT").await.unwrap(),
            _ => s.write_all(b"GET /api/me HTTP/1.1\r\nHost: x\r\nX-Slow: 1\r\n").await.unwrap(),
        }
        conns.push(s);
    }
    // A well-behaved client is served meanwhile.
    let (s, _, v) = common::http(addr, "GET", "/healthz", None, None).await;
    assert_eq!(s, 200, "{v}");
    let t0 = Instant::now();
    for (i, mut c) in conns.into_iter().enumerate() {
        let mut buf = [0u8; 256];
        // The server closes it (EOF, possibly after a 408) well within a few seconds.
        let left = Duration::from_secs(6).saturating_sub(t0.elapsed());
        let r = tokio::time::timeout(left, async {
            loop {
                match c.read(&mut buf).await {
                    Ok(0) | Err(_) => return,
                    Ok(_) => {}
                }
            }
        })
        .await;
        assert!(r.is_ok(), "connection {i} still open {:?} after it stalled", t0.elapsed());
    }
    eprintln!("300 stalled connections closed {:?} after they stalled", t0.elapsed());
}

#[cfg(unix)]
#[tokio::test]
async fn the_data_is_private_to_the_service() {
    use std::os::unix::fs::PermissionsExt;
    let a = common::app(QueueLimits::default()).await;
    a.user("ann").await;
    let mode = |p: &std::path::Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(a.dir.path()), 0o700);
    for f in ["scenewright.db", "scenewright.db-wal", "scenewright.db-shm"] {
        let p = a.dir.path().join(f);
        if p.exists() {
            assert_eq!(mode(&p), 0o600, "{f}");
        }
    }
}
