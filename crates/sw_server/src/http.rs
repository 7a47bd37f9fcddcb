//! The HTTP/1.1 server loop and what every answer carries.
//!
//! - Connections are served by hyper with a timeout on reading a request's headers: a
//!   client that connects and never finishes its headers (or sits idle between requests)
//!   is closed after [`HttpOptions::header_timeout`] instead of holding a socket forever.
//! - Every request knows its client's address ([`ClientAddr`]), for the attempt limits.
//! - Shutdown stops accepting, lets requests in flight finish for a grace period, then
//!   drops what is left (an open WebSocket included).
//! - Every answer carries a Content-Security-Policy (scripts, workers and WebAssembly from
//!   this origin only, no string evaluation, no framing; the simulation worker's script
//!   alone may evaluate strings, which MuJoCo's WebAssembly bindings need),
//!   `X-Content-Type-Options: nosniff` and no referrer.

use std::convert::Infallible;
use std::net::{IpAddr, SocketAddr};
use std::time::Duration;

use axum::Router;
use axum::extract::{ConnectInfo, FromRequestParts, Request};
use axum::http::request::Parts;
use axum::http::{HeaderValue, header};
use axum::middleware::Next;
use axum::response::Response;
use hyper_util::rt::{TokioIo, TokioTimer};
use tokio::net::TcpListener;
use tower::ServiceExt;

/// How connections are served.
#[derive(Debug, Clone, Copy)]
pub struct HttpOptions {
    /// A request's headers must arrive within this time after the connection is ready for
    /// one (idle keep-alive connections close after it too).
    pub header_timeout: Duration,
    /// After shutdown begins, requests in flight get this long to finish.
    pub grace: Duration,
}

impl Default for HttpOptions {
    fn default() -> Self {
        Self { header_timeout: Duration::from_secs(10), grace: Duration::from_secs(5) }
    }
}

/// The client's address, when the request came over a socket (`None` through a `Router`
/// driven in-process, as in tests).
#[derive(Debug, Clone, Copy)]
pub struct ClientAddr(pub Option<IpAddr>);

impl<S: Send + Sync> FromRequestParts<S> for ClientAddr {
    type Rejection = Infallible;

    async fn from_request_parts(parts: &mut Parts, _state: &S) -> Result<Self, Self::Rejection> {
        Ok(ClientAddr(parts.extensions.get::<ConnectInfo<SocketAddr>>().map(|c| c.0.ip())))
    }
}

/// Serves `app` on `listener` until `shutdown` resolves, then for at most `opts.grace`.
pub async fn serve(
    listener: TcpListener,
    app: Router,
    opts: HttpOptions,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    let (stop_tx, stop_rx) = tokio::sync::watch::channel(false);
    let mut connections = tokio::task::JoinSet::new();
    let mut shutdown = std::pin::pin!(shutdown);
    loop {
        let (stream, addr) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok(a) => a,
                Err(e) => {
                    // Out of file descriptors and the like: wait a little, keep serving.
                    tracing::warn!(error = %e, "accepting a connection failed");
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
            () = &mut shutdown => break,
        };
        // Reap finished connection tasks as we go.
        while connections.try_join_next().is_some() {}
        let app = app.clone();
        let mut stop = stop_rx.clone();
        connections.spawn(async move {
            let service = hyper::service::service_fn(move |req: hyper::Request<hyper::body::Incoming>| {
                let mut req = req.map(axum::body::Body::new);
                req.extensions_mut().insert(ConnectInfo(addr));
                app.clone().oneshot(req)
            });
            let mut builder = hyper::server::conn::http1::Builder::new();
            builder.timer(TokioTimer::new()).header_read_timeout(opts.header_timeout);
            let conn = builder.serve_connection(TokioIo::new(stream), service).with_upgrades();
            let mut conn = std::pin::pin!(conn);
            tokio::select! {
                r = conn.as_mut() => {
                    if let Err(e) = r {
                        tracing::debug!(error = %e, client = %addr, "connection ended");
                    }
                }
                () = async { let _ = stop.wait_for(|s| *s).await; } => {
                    conn.as_mut().graceful_shutdown();
                    let _ = conn.await;
                }
            }
        });
    }
    drop(listener);
    let _ = stop_tx.send(true);
    let drained = tokio::time::timeout(opts.grace, async { while connections.join_next().await.is_some() {} }).await;
    if drained.is_err() {
        tracing::info!(left = connections.len(), "closing the connections still open after the grace period");
        connections.abort_all();
    }
    Ok(())
}

/// The policy for every answer: the app's own scripts, styles, workers and WebAssembly
/// (MuJoCo's), its own API and WebSocket; blobs for downloads and thumbnails; no plugins,
/// no framing by other sites.
const CSP: &str = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self' blob:; \
    connect-src 'self'; img-src 'self' blob: data:; style-src 'self' 'unsafe-inline'; object-src 'none'; \
    base-uri 'none'; form-action 'self'; frame-ancestors 'none'";

/// The simulation worker's own policy (a dedicated worker runs under the policy its script
/// is served with): MuJoCo's WebAssembly glue (Emscripten's embind) builds its bindings
/// with `Function(…)`, so that script alone may evaluate strings; the pages may not.
const WORKER_CSP: &str = "default-src 'self'; script-src 'self' 'unsafe-eval' 'wasm-unsafe-eval'; \
    connect-src 'self'; object-src 'none'; base-uri 'none'";

/// Adds the security headers to every answer.
pub async fn security_headers(req: Request, next: Next) -> Response {
    let worker = {
        let path = req.uri().path();
        path.starts_with("/assets/") && path.contains(".worker") && path.ends_with(".js")
    };
    let mut r = next.run(req).await;
    let h = r.headers_mut();
    h.insert(header::CONTENT_SECURITY_POLICY, HeaderValue::from_static(if worker { WORKER_CSP } else { CSP }));
    h.insert(header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    h.insert(header::X_FRAME_OPTIONS, HeaderValue::from_static("DENY"));
    h.insert(header::REFERRER_POLICY, HeaderValue::from_static("no-referrer"));
    r
}
