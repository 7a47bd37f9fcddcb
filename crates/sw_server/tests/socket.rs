//! Over a real socket, through the service's own connection loop: clients submit jobs and
//! follow them on the WebSocket until the result; a bad token is refused at the handshake.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use futures_util::StreamExt;
use serde_json::{Value, json};
use sw_store::QueueLimits;
use tokio_tungstenite::tungstenite::Message;

/// The status and JSON body of a request over a real socket.
async fn http(
    addr: std::net::SocketAddr,
    method: &str,
    path: &str,
    token: Option<&str>,
    body: Option<Value>,
) -> (u16, Value) {
    let (status, _, body) = common::http(addr, method, path, token, body).await;
    (status, body)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn clients_follow_their_jobs_over_websockets() {
    let a = common::app(QueueLimits::default()).await;
    // The service's own connection loop (header timeout, client addresses, upgrades).
    let (addr, _stop, _served) = common::serve_on_socket(&a, sw_server::HttpOptions::default()).await;
    let state = a.state.clone();
    let _stop = common::start_workers(&state, 2);

    let creds = json!({"username": "ann", "password": "correct horse battery"});
    assert_eq!(http(addr, "POST", "/api/auth/register", None, Some(creds.clone())).await.0, 201);
    let (_, v) = http(addr, "POST", "/api/auth/login", None, Some(creds)).await;
    let token = v["token"].as_str().unwrap().to_string();

    let mut clients = Vec::new();
    for i in 0..3u64 {
        let token = token.clone();
        clients.push(tokio::spawn(async move {
            let prompt = format!("a lab with {} tables and a UR5e", i + 1);
            let (s, v) =
                http(addr, "POST", "/api/jobs", Some(&token), Some(json!({"prompt": prompt, "seed": i}))).await;
            assert_eq!(s, 202, "{v}");
            let id = v["job_id"].as_str().unwrap().to_string();
            let url = format!("ws://{addr}/api/jobs/{id}/events?token={token}");
            let (mut ws, _) = tokio_tungstenite::connect_async(url).await.unwrap();
            let mut events = Vec::new();
            while let Some(m) = ws.next().await {
                match m.unwrap() {
                    Message::Text(t) => events.push(serde_json::from_str::<Value>(&t).unwrap()),
                    Message::Close(_) => break,
                    _ => {}
                }
            }
            (id, events)
        }));
    }
    for c in clients {
        let (id, events) = c.await.unwrap();
        let last = events.last().unwrap();
        assert_eq!(last["event"], "result", "{events:?}");
        assert_eq!(last["job"]["id"], id.as_str());
        assert_eq!(last["job"]["state"], "succeeded");
        assert_eq!(last["scene"]["status"], "verified");
        for stage in ["plan", "forge", "layout", "bridge", "verify"] {
            assert!(
                events.iter().any(|e| e["event"] == "stage_finished" && e["stage"] == stage),
                "{id}: no stage_finished {stage}"
            );
        }
        // Per-object steps: each asset made, each placed object (every one of them made
        // in L2), and the robot's spawn.
        let steps = |stage: &str| -> Vec<(String, String)> {
            events
                .iter()
                .filter(|e| e["event"] == "object" && e["stage"] == stage)
                .map(|e| (e["object"].as_str().unwrap_or("").to_string(), e["step"].as_str().unwrap_or("").to_string()))
                .collect()
        };
        let (made, laid) = (steps("forge"), steps("layout"));
        let placed: Vec<&(String, String)> = laid.iter().filter(|(_, s)| s.starts_with("placed at")).collect();
        assert!(!placed.is_empty(), "{id}: {laid:?}");
        assert!(placed.iter().all(|(o, _)| made.iter().any(|(m, _)| m == o)), "{id}: {made:?} vs {laid:?}");
        assert!(laid.iter().any(|(_, s)| s.starts_with("ur5e spawned")), "{id}: {laid:?}");
        let seqs: Vec<i64> = events.iter().filter_map(|e| e["seq"].as_i64()).collect();
        assert!(seqs.windows(2).all(|w| w[1] == w[0] + 1) && seqs[0] == 1, "gapless: {seqs:?}");
        assert!(events.iter().any(|e| e["event"] == "finished"));
    }

    // Handshakes without a valid token are refused with 401.
    let url = format!("ws://{addr}/api/jobs/{}/events?token=nonsense", sw_store::new_id());
    match tokio_tungstenite::connect_async(url).await {
        Err(tokio_tungstenite::tungstenite::Error::Http(r)) => assert_eq!(r.status(), 401),
        other => panic!("expected a 401, got {other:?}"),
    }
}
