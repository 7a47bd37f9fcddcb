#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `assets generate` and `bench cad` through the binary. Needs `scripts/setup.sh --tests`
//! (the CadQuery venv).

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_scenewright");

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(BIN).args(args).output().expect("run scenewright");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn assets_generate_writes_the_washer_of_the_issue() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("washer");
    let prompt = "A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm";
    let store = dir.path().join("store");
    let (code, stdout, stderr) = run(&[
        "assets",
        "generate",
        prompt,
        "--out",
        out.to_str().unwrap(),
        "--store",
        store.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(code, 0, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["metadata"]["template"], "features");
    let measured = v["metadata"]["measured_size_mm"].as_array().unwrap();
    let want = [20.0, 20.0, 2.0];
    for (m, w) in measured.iter().zip(want) {
        assert!((m.as_f64().unwrap() - w).abs() <= 0.01 * w + 0.02, "{measured:?}");
    }
    let mesh = sw_geom::read_stl(std::fs::File::open(out.join("part.stl")).unwrap()).unwrap();
    assert!(mesh.check().watertight);
    let analytic = std::f64::consts::PI * (10.0f64.powi(2) - 5.25f64.powi(2)) * 2.0 * 1e-9;
    assert!((mesh.volume() - analytic).abs() / analytic < 0.02, "{} m³", mesh.volume());
    assert!(out.join("part.py").is_file() && out.join("preview.png").is_file());

    // Stored and indexed: found by meaning, shown by its id prefix.
    let id = v["stored"].as_str().unwrap().to_string();
    let (code, stdout, stderr) =
        run(&["assets", "search", "a ring-shaped spacer washer", "--store", store.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let hits: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(hits["hits"][0]["id"], id.as_str());
    let (code, stdout, stderr) = run(&["assets", "show", &id[..12], "--store", store.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("template:features"), "{stdout}");
    let (code, _, stderr) = run(&["assets", "show", "deadbeefdeadbeef", "--store", store.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    let (code, _, _) = run(&["assets", "search", "  ", "--store", store.to_str().unwrap()]);
    assert_eq!(code, 2);
}

#[test]
fn assets_go_to_an_s3_bucket_when_the_store_is_an_s3_url() {
    let server = sw_s3::moto::MotoServer::start().unwrap();
    let index = tempfile::tempdir().unwrap();
    let out = tempfile::tempdir().unwrap();
    let run_s3 = |args: &[&str]| {
        let o = Command::new(BIN)
            .args(args)
            .env("SCENEWRIGHT_S3_ENDPOINT", format!("http://{}", server.addr()))
            .env("AWS_ACCESS_KEY_ID", "testing")
            .env("AWS_SECRET_ACCESS_KEY", "testing")
            .env("SCENEWRIGHT_ASSET_INDEX", index.path())
            .output()
            .unwrap();
        (
            o.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&o.stdout).into_owned(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let store = "s3://cli-assets/team/parts";
    let prompt = "A rectangular block 40mm x 20mm x 10mm";
    let (code, stdout, stderr) = run_s3(&[
        "assets",
        "generate",
        prompt,
        "--out",
        out.path().to_str().unwrap(),
        "--no-preview",
        "--store",
        store,
        "--json",
    ]);
    assert_eq!(code, 0, "{stderr}");
    let id = serde_json::from_str::<serde_json::Value>(&stdout).unwrap()["stored"].as_str().unwrap().to_string();
    // In the bucket, under the prefix, by content address.
    let raw = sw_s3::S3Client::new(server.config("cli-assets"));
    assert!(raw.exists(&format!("team/parts/objects/{}/{id}.stl", &id[..2])).unwrap());
    // Found by meaning with a fresh index (rebuilt from the bucket), shown by its prefix.
    std::fs::remove_dir_all(index.path()).unwrap();
    let (code, stdout, stderr) = run_s3(&["assets", "search", "a rectangular brick", "--store", store, "--json"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(serde_json::from_str::<serde_json::Value>(&stdout).unwrap()["hits"][0]["id"], id.as_str());
    let (code, stdout, stderr) = run_s3(&["assets", "show", &id[..12], "--store", store]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("template:features"), "{stdout}");
    // Without an endpoint, an s3:// store is a one-line input error, not a crash.
    let (code, _, stderr) = run(&["assets", "search", "brick", "--store", store]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("SCENEWRIGHT_S3_ENDPOINT") && stderr.trim().lines().count() == 1, "{stderr}");
    let (code, _, stderr) = run(&["assets", "search", "brick", "--store", "ftp://x/y"]);
    assert_eq!(code, 2, "{stderr}");
}

#[test]
fn assets_generate_refuses_bad_prompts_with_one_line_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x");
    for prompt in ["", "a hovercraft", "a washer", "A washer: outer diameter 10mm, inner diameter 12mm, 2mm thick"] {
        let (code, stdout, stderr) = run(&["assets", "generate", prompt, "--out", out.to_str().unwrap(), "--no-store"]);
        assert_eq!(code, 2, "{prompt}: {stdout}{stderr}");
        assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
        assert!(!out.exists(), "nothing is written for bad input");
    }
}

#[test]
fn bench_cad_measures_against_references_and_catches_a_wrong_one() {
    let dir = tempfile::tempdir().unwrap();
    let suite = dir.path().join("mini.tsv");
    std::fs::write(
        &suite,
        "# a small suite\nA1\tT1\tA cube with 20mm sides.\nA2\tT1\tA cylinder 10mm in diameter and 30mm tall.\nA3\tT2\tA hovercraft.\n",
    )
    .unwrap();
    // A2's reference volume is deliberately 10 % off.
    let v2 = std::f64::consts::PI * 25.0 * 30.0 * 1.1;
    std::fs::write(dir.path().join("mini.refs.tsv"), format!("A1\t20\t20\t20\t8000\t-\nA2\t10\t10\t30\t{v2}\t-\n"))
        .unwrap();
    let (code, stdout, stderr) =
        run(&["bench", "cad", "--suite", suite.to_str().unwrap(), "--workers", "1", "--latency-repeat", "1", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let outcomes = v["outcomes"].as_array().unwrap();
    let by_id = |id: &str| outcomes.iter().find(|o| o["id"] == id).unwrap();
    assert_eq!(by_id("A1")["pass"], true);
    assert_eq!(by_id("A2")["executed"], true);
    assert_eq!(by_id("A2")["pass"], false);
    assert_eq!(by_id("A2")["failure"], "semantic_mismatch");
    assert_eq!(by_id("A3")["executed"], false);
    assert_eq!(by_id("A3")["failure"], "writer");
    assert_eq!(v["tiers"]["T1"]["executed"], 2);
    assert_eq!(v["tiers"]["T1"]["passed"], 1);
    assert!(v["warm_latency"]["median_ms"].as_f64().unwrap() > 0.0);
}

#[test]
fn bench_cad_with_the_model_writing_counts_attempts_and_measures_its_parts() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let cube_asks = std::sync::Arc::new(AtomicUsize::new(0));
    let asks = std::sync::Arc::clone(&cube_asks);
    let model = sw_mockllm::MockServer::start(move |req| {
        // The prompt is in the first user message; a retry's last one is the failure.
        if req.messages().iter().any(|(_, c)| c.contains("cube")) {
            // First a syntax error; the error fed back, then the right part.
            if asks.fetch_add(1, Ordering::SeqCst) == 0 {
                return sw_mockllm::Reply::answer("```python\nimport cadquery as cq\nresult = (\n```");
            }
            return sw_mockllm::Reply::answer(
                "```python\nimport cadquery as cq\nresult = cq.Workplane('XY').box(20, 20, 20)\n```",
            );
        }
        sw_mockllm::Reply::answer("```python\nimport cadquery as cq\nresult = cq.Workplane('XY').cylinder(8, 25)\n```")
    })
    .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let suite = dir.path().join("llm.tsv");
    std::fs::write(&suite, "B1\tT1\tA cube with 20mm sides.\nB2\tT3\tA round hockey puck.\n").unwrap();
    std::fs::write(dir.path().join("llm.refs.tsv"), "B1\t20\t20\t20\t8000\t-\n").unwrap();
    let bench = |writer: &str, with_endpoint: bool| {
        let mut c = Command::new(BIN);
        c.args(["bench", "cad", "--suite", suite.to_str().unwrap(), "--workers", "1", "--latency-repeat", "0"])
            .args(["--writer", writer, "--json"]);
        if with_endpoint {
            c.env("SCENEWRIGHT_LLM_BASE_URL", model.base_url()).env("SCENEWRIGHT_LLM_MODEL", "m-cad");
        }
        let o = c.output().unwrap();
        (
            o.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&o.stdout).into_owned(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let (code, stdout, stderr) = bench("llm", true);
    assert_eq!(code, 0, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["writer"], "llm:m-cad");
    let outcomes = v["outcomes"].as_array().unwrap();
    let by_id = |id: &str| outcomes.iter().find(|o| o["id"] == id).unwrap();
    assert_eq!(by_id("B1")["executed"], true);
    assert_eq!(by_id("B1")["retries"], 1, "one failed attempt, fed back");
    assert_eq!(by_id("B1")["pass"], true, "{}", by_id("B1"));
    assert_eq!(by_id("B2")["executed"], true);
    assert_eq!(by_id("B2")["retries"], 0);
    assert_eq!(v["tiers"]["T1"]["retried"], 1);
    assert_eq!(v["model_calls"]["calls"], 3);
    // Without a CAD model, or with an unknown writer: one line, exit 2.
    let (code, _, stderr) = bench("llm", false);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("CAD stage"), "{stderr}");
    let (code, _, stderr) = bench("oracle", true);
    assert_eq!(code, 2, "{stderr}");
}

#[test]
fn bench_cad_refuses_an_unknown_suite() {
    let (code, _, stderr) = run(&["bench", "cad", "--suite", "no_such_suite"]);
    assert_eq!(code, 2);
    assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
}
