//! `GET /api/jobs/{id}/events`: a WebSocket that sends every event of a job as one JSON
//! text message (`{"seq", "event", ...}`: queued, started, stage_started, stage_finished,
//! object (per-object steps), note, warning, requeued, error, cancelled, finished), then a last `result` message
//! with the job and, when it made one, the scene — and closes. A client that connects
//! late gets the whole history first.

use std::time::Duration;

use axum::extract::ws::{Message, WebSocket, WebSocketUpgrade, rejection::WebSocketUpgradeRejection};
use axum::extract::{Path, State};
use axum::response::Response;
use serde_json::{Value, json};

use crate::AppState;
use crate::auth::Caller;
use crate::error::{ApiError, ApiResult};
use crate::routes_jobs::{job_json, owned_job};

pub async fn events(
    State(s): State<AppState>,
    caller: Caller,
    Path(id): Path<String>,
    ws: Result<WebSocketUpgrade, WebSocketUpgradeRejection>,
) -> ApiResult<Response> {
    let job = owned_job(&s, &caller, &id).await?;
    let ws = ws.map_err(|e| ApiError::bad_request(format!("this is a WebSocket endpoint: {e}")))?;
    let user_id = caller.user.id.clone();
    Ok(ws.on_upgrade(move |socket| stream(s, job.id, user_id, socket)))
}

async fn send(socket: &mut WebSocket, v: &Value) -> bool {
    socket.send(Message::Text(v.to_string().into())).await.is_ok()
}

async fn stream(s: AppState, job_id: String, user_id: String, mut socket: WebSocket) {
    let mut rx = s.events.subscribe();
    let mut seq = 0i64;
    loop {
        // Read the state first: a terminal state means the stream is complete (terminal
        // events are written in the same transaction as the state).
        let job = match s.store.job(&job_id).await {
            Ok(Some(j)) => j,
            _ => break,
        };
        let events = match s.store.events_after(&job_id, seq).await {
            Ok(e) => e,
            Err(_) => break,
        };
        for (n, mut body) in events {
            seq = n;
            body["seq"] = json!(n);
            if !send(&mut socket, &body).await {
                return;
            }
        }
        if job.state.is_terminal() {
            let scene =
                match &job.scene_id {
                    Some(sid) => s.store.scene_of(sid, &user_id).await.ok().flatten().map(
                        |sc| json!({ "id": sc.id, "status": sc.status, "files": sc.files, "version": sc.version }),
                    ),
                    None => None,
                };
            let _ = send(&mut socket, &json!({ "event": "result", "job": job_json(&job), "scene": scene })).await;
            break;
        }
        let poll = Duration::from_millis(s.runner.poll_ms.max(50));
        tokio::select! {
            _ = wait_for(&mut rx, &job_id) => {}
            _ = tokio::time::sleep(poll) => {}
            m = socket.recv() => match m {
                None | Some(Err(_)) | Some(Ok(Message::Close(_))) => return,
                _ => {}
            },
        }
    }
    let _ = socket.send(Message::Close(None)).await;
}

/// Resolves when this process notes new events of `job_id`.
async fn wait_for(rx: &mut tokio::sync::broadcast::Receiver<String>, job_id: &str) {
    loop {
        match rx.recv().await {
            Ok(id) if id == job_id => return,
            Ok(_) => {}
            Err(tokio::sync::broadcast::error::RecvError::Lagged(_)) => return,
            Err(tokio::sync::broadcast::error::RecvError::Closed) => std::future::pending::<()>().await,
        }
    }
}
