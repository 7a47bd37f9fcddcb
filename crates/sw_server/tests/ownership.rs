//! A real job through the in-process runners (MuJoCo-verified), then every endpoint that
//! names a job, scene or asset: the owner gets it, anyone else gets exactly the 404 of
//! an id that does not exist. Also files, traversal, the zip, edits and metrics. On SQLite
//! and on a throwaway PostgreSQL cluster.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use axum::http::{Method, StatusCode};
use common::cluster::Cluster;
use common::{Db, PROMPT, Payload, app_on, start_workers};
use serde_json::json;
use sw_store::QueueLimits;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn owners_see_their_things_and_others_see_nothing() {
    owners_and_others(Db::Sqlite).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn owners_see_their_things_and_others_see_nothing_on_postgresql() {
    let cluster = Cluster::start();
    owners_and_others(Db::Url(cluster.database("ownership"))).await;
}

async fn owners_and_others(db: Db) {
    let a = app_on(&db, QueueLimits::default()).await;
    let ann = a.user("ann").await;
    let bob = a.user("bob").await;
    let _stop = start_workers(&a.state, 2);

    let (s, v) = a.post("/api/jobs", &ann, json!({"prompt": PROMPT, "seed": 1})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let job_id = v["job_id"].as_str().unwrap().to_string();
    let job = a.wait_job(&job_id, &ann).await;
    assert_eq!(job["state"], "succeeded", "{job}");
    assert_eq!(job["attempts"], 1);
    let scene_id = job["scene_id"].as_str().unwrap().to_string();
    let (s, scene) = a.get(&format!("/api/scenes/{scene_id}"), &ann).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(scene["status"], "verified", "verified in MuJoCo: {}", scene["report"]);
    assert_eq!(scene["version"], 1);
    let files: Vec<String> = serde_json::from_value(scene["files"].clone()).unwrap();
    for f in ["scene.xml", "scene_only.xml", "plan.json", "layout.json", "report.json", "timings.json"] {
        assert!(files.contains(&f.to_string()), "{f} missing from {files:?}");
    }
    assert!(files.iter().any(|f| f.starts_with("assets/") && f.ends_with(".stl")));
    let (_, asset) = a.post("/api/assets", &ann, json!({"description": "conveyor"})).await;
    let asset_id = asset["id"].as_str().unwrap().to_string();

    // The stream of the finished job: every stage started and finished, then the result.
    let events = a.state.store.events_after(&job_id, 0).await.unwrap();
    let kinds: Vec<String> = events.iter().map(|e| e.1["event"].as_str().unwrap().to_string()).collect();
    for stage in ["plan", "forge", "layout", "bridge", "verify"] {
        for k in ["stage_started", "stage_finished"] {
            assert!(events.iter().any(|e| e.1["event"] == k && e.1["stage"] == stage), "no {k} {stage} in {kinds:?}");
        }
    }
    assert_eq!(kinds.first().map(String::as_str), Some("queued"));
    assert_eq!(kinds.last().map(String::as_str), Some("finished"));

    // Files: the owner gets them; traversal is refused.
    let (s, xml) =
        a.raw(Method::GET, &format!("/api/scenes/{scene_id}/files/scene.xml"), Some(&ann), Payload::None).await;
    assert_eq!(s, StatusCode::OK);
    assert!(String::from_utf8_lossy(&xml).contains("<mujoco"));
    for evil in ["../../../etc/passwd", "%2e%2e/%2e%2e/scenewright.db", "assets/..%2F..%2Fplan.json", "%2Fetc%2Fpasswd"]
    {
        let (s, v) =
            a.call(Method::GET, &format!("/api/scenes/{scene_id}/files/{evil}"), Some(&ann), Payload::None).await;
        assert_eq!(s, StatusCode::BAD_REQUEST, "{evil}: {v}");
    }
    let (s, _) =
        a.call(Method::GET, &format!("/api/scenes/{scene_id}/files/nothing.xml"), Some(&ann), Payload::None).await;
    assert_eq!(s, StatusCode::NOT_FOUND);

    // The zip holds every file.
    let (s, zip) = a.raw(Method::GET, &format!("/api/scenes/{scene_id}/package.zip"), Some(&ann), Payload::None).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(&zip[..4], b"PK\x03\x04");
    let eocd = &zip[zip.len() - 22..];
    assert_eq!(&eocd[..4], b"PK\x05\x06");
    assert_eq!(u16::from_le_bytes([eocd[10], eocd[11]]) as usize, files.len());
    let zpath = a.dir.path().join("p.zip");
    std::fs::write(&zpath, &zip).unwrap();
    let check = std::process::Command::new("python3")
        .args(["-c", "import sys, zipfile; z = zipfile.ZipFile(sys.argv[1]); assert z.testzip() is None; print(len(z.namelist()))"])
        .arg(&zpath)
        .output();
    if let Ok(out) = check {
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), files.len().to_string());
    }

    // Every endpoint, for bob, answers exactly as for an id that does not exist.
    let missing = sw_store::new_id();
    let endpoints = |job: &str, scene: &str, asset: &str| {
        vec![
            (Method::GET, format!("/api/jobs/{job}"), None),
            (Method::DELETE, format!("/api/jobs/{job}"), None),
            (Method::GET, format!("/api/jobs/{job}/events"), None),
            (Method::GET, format!("/api/scenes/{scene}"), None),
            (Method::GET, format!("/api/scenes/{scene}/files/scene.xml"), None),
            (Method::GET, format!("/api/scenes/{scene}/package.zip"), None),
            (Method::POST, format!("/api/scenes/{scene}/edits"), Some(json!({"command": "remove chair_1"}))),
            (
                Method::POST,
                format!("/api/scenes/{scene}/edits"),
                Some(json!({"move": {"object": "chair_1", "pos": [0, 0]}})),
            ),
            (
                Method::POST,
                format!("/api/scenes/{scene}/edits"),
                Some(json!({"place": {"asset": "catalog:crate", "pos": [0, 0]}})),
            ),
            (Method::GET, format!("/api/scenes/{scene}/versions"), None),
            (Method::GET, format!("/api/scenes/{scene}/thumbnail.png"), None),
            (Method::GET, format!("/api/assets/{asset}"), None),
        ]
    };
    let theirs = endpoints(&job_id, &scene_id, &asset_id);
    let nothing = endpoints(&missing, &missing, &missing);
    let jobs_before = a.jobs_stored().await;
    for ((m, uri, body), (_, uri_missing, _)) in theirs.into_iter().zip(nothing) {
        let payload = |b: &Option<serde_json::Value>| b.clone().map_or(Payload::None, Payload::Json);
        let (s1, v1) = a.call(m.clone(), &uri, Some(&bob), payload(&body)).await;
        let (s2, v2) = a.call(m.clone(), &uri_missing, Some(&bob), payload(&body)).await;
        assert_eq!(s1, StatusCode::NOT_FOUND, "{m} {uri}: {v1}");
        assert_eq!((s1, &v1), (s2, &v2), "{m} {uri} differs from a missing id");
        // And ids that are not ids at all.
        let junk =
            uri.replace(&job_id, "1%27%20OR%20%271%27%3D%271").replace(&scene_id, "..").replace(&asset_id, "%00");
        let (s3, _) = a.call(m.clone(), &junk, Some(&bob), payload(&body)).await;
        assert!(s3 == StatusCode::NOT_FOUND || s3 == StatusCode::BAD_REQUEST, "{m} {junk}: {s3}");
    }
    assert_eq!(a.jobs_stored().await, jobs_before, "bob's edit of ann's scene stored nothing");
    for list in ["/api/jobs", "/api/scenes", "/api/assets"] {
        let (s, v) = a.get(list, &bob).await;
        assert_eq!(s, StatusCode::OK);
        let text = v.to_string();
        assert!(!text.contains(&job_id) && !text.contains(&scene_id) && !text.contains(&asset_id), "{list}: {v}");
    }
    assert_eq!(a.state.store.job(&job_id).await.unwrap().unwrap().state, sw_store::JobState::Succeeded);

    // Ann edits her scene: a new version with its history.
    let (s, v) = a.post(&format!("/api/scenes/{scene_id}/edits"), &ann, json!({"command": "remove chair_1"})).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let edit_job = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    assert_eq!(edit_job["state"], "succeeded", "{edit_job}");
    let v2 = edit_job["scene_id"].as_str().unwrap();
    let (_, scene2) = a.get(&format!("/api/scenes/{v2}"), &ann).await;
    assert_eq!(scene2["version"], 2);
    assert_eq!(scene2["parent_id"], scene_id.as_str());
    assert_eq!(scene2["status"], "verified");
    assert_eq!(scene2["edits"][0]["command"], "remove chair_1");
    let (_, layout) = a.get(&format!("/api/scenes/{v2}/files/layout.json"), &ann).await;
    assert!(!layout.to_string().contains("\"chair_1\""), "chair_1 is gone");
    let (_, list) = a.get("/api/scenes", &ann).await;
    assert_eq!(list["scenes"].as_array().unwrap().len(), 2);
    // Both versions, from either end of the lineage (a recursive query on both databases).
    for from in [scene_id.as_str(), v2] {
        let (s, versions) = a.get(&format!("/api/scenes/{from}/versions"), &ann).await;
        assert_eq!(s, StatusCode::OK, "{versions}");
        let ids: Vec<&str> =
            versions["versions"].as_array().unwrap().iter().map(|x| x["id"].as_str().unwrap()).collect();
        assert_eq!(ids, vec![scene_id.as_str(), v2]);
        assert_eq!(versions["versions"][1]["command"], "remove chair_1");
    }
    // An edit the grammar cannot apply fails the job with a reason, and makes no scene.
    let (_, v) = a.post(&format!("/api/scenes/{scene_id}/edits"), &ann, json!({"command": "remove the unicorn"})).await;
    let bad = a.wait_job(v["job_id"].as_str().unwrap(), &ann).await;
    assert_eq!(bad["state"], "failed");
    assert!(bad["error"].as_str().unwrap().contains("unicorn"), "{bad}");

    // Metrics cover what happened (an admin reads them; ann is the first user).
    let (s, m) = a.raw(Method::GET, "/metrics", Some(&ann), Payload::None).await;
    assert_eq!(s, StatusCode::OK);
    let m = String::from_utf8(m).unwrap();
    assert!(m.contains("scenewright_jobs{state=\"succeeded\"} 2"), "{m}");
    assert!(m.contains("scenewright_jobs{state=\"failed\"} 1"), "{m}");
    assert!(m.contains("scenewright_queue_depth 0"), "{m}");
    assert!(m.contains("scenewright_stage_seconds_count{stage=\"verify\"} 2"), "{m}");
    assert!(m.contains("scenewright_job_seconds_count{phase=\"queue_wait\"} 2"), "{m}");
    assert!(m.contains("scenewright_llm_calls_total 0"), "{m}");
}
