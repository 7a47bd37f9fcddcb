//! A stored file that no longer matches the checksum recorded with its scene is never
//! served, zipped or edited from: 500 saying it is damaged, not the wrong bytes.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use axum::http::{Method, StatusCode};
use common::Payload;
use serde_json::json;
use sw_store::QueueLimits;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_damaged_stored_file_is_not_served() {
    let a = common::app(QueueLimits::default()).await;
    let _workers = common::start_workers(&a.state, 1);
    let t = a.user("ann").await;
    let (_, v) = a.post("/api/jobs", &t, json!({"prompt": "a 5 by 4 m lab with a table and a chair"})).await;
    let job = a.wait_job(v["job_id"].as_str().unwrap(), &t).await;
    assert_eq!(job["state"], "succeeded", "{job}");
    let id = job["scene_id"].as_str().unwrap();
    let file = format!("/api/scenes/{id}/files/scene.xml");
    let (s, good) = a.raw(Method::GET, &file, Some(&t), Payload::None).await;
    assert_eq!(s, StatusCode::OK);

    // One byte changed on disk, behind the service's back.
    let path = a.dir.path().join("blobs").join("scenes").join(id).join("scene.xml");
    let mut bytes = std::fs::read(&path).unwrap();
    assert_eq!(bytes, good);
    let k = bytes.iter().position(|b| *b == b'<').unwrap() + 1;
    bytes[k] ^= 0x20;
    std::fs::write(&path, &bytes).unwrap();

    let (s, v) = a.call(Method::GET, &file, Some(&t), Payload::None).await;
    assert_eq!(s, StatusCode::INTERNAL_SERVER_ERROR, "{v}");
    assert!(
        v["error"].as_str().unwrap().contains("scene.xml") && v["error"].as_str().unwrap().contains("damaged"),
        "{v}"
    );
    let (s, _) = a.raw(Method::GET, &format!("/api/scenes/{id}/package.zip"), Some(&t), Payload::None).await;
    assert_eq!(s, StatusCode::INTERNAL_SERVER_ERROR);
    // An edit does not build on it either.
    let (_, v) = a.post(&format!("/api/scenes/{id}/edits"), &t, json!({"command": "remove the chair"})).await;
    let edit = a.wait_job(v["job_id"].as_str().unwrap(), &t).await;
    assert_eq!(edit["state"], "failed", "{edit}");
    assert!(edit["error"].as_str().unwrap().contains("damaged"), "{edit}");
    // Other files of the scene are still served.
    let (s, _) = a.raw(Method::GET, &format!("/api/scenes/{id}/files/layout.json"), Some(&t), Payload::None).await;
    assert_eq!(s, StatusCode::OK);
}
