#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The generation loop against a loopback model server speaking the real protocol
//! (sw_mockllm): failures are filed under the taxonomy and fed back, a later attempt that
//! passes is taken, K failures end in a fallback. Needs `scripts/setup.sh --tests`.

use std::sync::OnceLock;
use std::time::Duration;

use sw_forge::failure::FailureKind;
use sw_forge::generate::{ForgeOutcome, LlmWriter, LoopConfig, PartRequest, TemplateWriter, forge};
use sw_forge::runner::{CadRunner, RunnerConfig};
use sw_llm::{Client, Endpoint, LlmConfig, LlmStage};
use sw_mockllm::{MockServer, Reply, script};

fn runner() -> &'static CadRunner {
    static R: OnceLock<CadRunner> = OnceLock::new();
    R.get_or_init(|| {
        CadRunner::start(RunnerConfig { workers: 1, timeout: Duration::from_secs(20), ..RunnerConfig::default() })
            .unwrap_or_else(|e| panic!("the CAD runner must start (run scripts/setup.sh --tests): {e}"))
    })
}

fn client(server: &MockServer) -> Client {
    Client::new(LlmConfig::offline().with(LlmStage::Cad, Endpoint::new(server.base_url(), "mock-cad")))
}

fn fenced(code: &str) -> Reply {
    Reply::answer(format!("Here is the part:\n```python\n{code}\n```\n"))
}

#[test]
fn failures_are_fed_back_until_an_attempt_passes() {
    let server = MockServer::start(script(vec![
        fenced("import cadquery as cq\nresult = cq.Workplane('XY').box(80, 80,"),
        fenced("import cadquery as cq\nresult = cq.Workplane('XY').box(10, 10, 10)"),
        fenced("import cadquery as cq\nresult = cq.Workplane('XY').circle(40).extrude(100).faces('>Z').shell(-3)"),
    ]))
    .unwrap();
    let writer = LlmWriter::new(client(&server));
    let req = PartRequest { description: "a cylindrical cup".into(), size_m: Some([0.08, 0.08, 0.1]) };
    let out = forge(runner(), &writer, &req, LoopConfig::default());
    let ForgeOutcome::Made(part) = out else { panic!("the third attempt passes: {:?}", out.attempts()) };
    let kinds: Vec<Option<FailureKind>> = part.attempts.iter().map(|a| a.failure.as_ref().map(|f| f.kind)).collect();
    assert_eq!(kinds, vec![Some(FailureKind::Syntax), Some(FailureKind::ScaleMismatch), None]);
    assert_eq!(part.writer, "llm:mock-cad");
    // Each retry told the model what went wrong with its previous code.
    let requests = server.requests();
    assert_eq!(requests.len(), 3);
    assert!(requests[1].last_user().contains("syntax"), "{}", requests[1].last_user());
    assert!(requests[2].last_user().contains("scale_mismatch"), "{}", requests[2].last_user());
    assert!(requests[0].last_user().contains("80.0 × 80.0 × 100.0 mm"));
}

#[test]
fn k_failures_end_in_a_fallback_with_every_kind() {
    let server = MockServer::start(script(vec![
        fenced("import os\nresult = os.getcwd()"),
        fenced("import cadquery as cq\nresult = cq.Workplane('XY').box(1, 1, 1).edges().fillet(5)"),
        fenced("result = 42"),
    ]))
    .unwrap();
    let writer = LlmWriter::new(client(&server));
    let req = PartRequest { description: "a box".into(), size_m: Some([0.02, 0.02, 0.02]) };
    let out = forge(runner(), &writer, &req, LoopConfig { max_attempts: 3, ..LoopConfig::default() });
    let ForgeOutcome::Failed { attempts, .. } = out else { panic!("no attempt can pass") };
    let kinds: Vec<FailureKind> = attempts.iter().filter_map(|a| a.failure.as_ref().map(|f| f.kind)).collect();
    assert_eq!(kinds.len(), 3);
    assert_eq!(kinds[0], FailureKind::SandboxViolation);
    assert_eq!(kinds[1], FailureKind::Runtime);
}

#[test]
fn a_silent_model_is_a_writer_failure_not_a_hang() {
    let server = MockServer::start(script(vec![Reply::status(500, "down"); 8])).unwrap();
    let mut config = LlmConfig::offline().with(LlmStage::Cad, Endpoint::new(server.base_url(), "mock-cad"));
    if let Some(e) = config.endpoint_mut(LlmStage::Cad) {
        e.max_retries = 0;
    }
    let writer = LlmWriter::new(Client::new(config));
    let req = PartRequest { description: "a box".into(), size_m: None };
    let out = forge(runner(), &writer, &req, LoopConfig::default());
    let ForgeOutcome::Failed { attempts, .. } = out else { panic!("no model, no part") };
    assert_eq!(attempts.len(), 1);
    assert_eq!(attempts[0].failure.as_ref().unwrap().kind, FailureKind::Writer);
}

#[test]
fn the_template_writer_makes_dimensioned_parts_in_one_attempt() {
    let req = PartRequest {
        description: "A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm".into(),
        size_m: Some([0.02, 0.02, 0.002]),
    };
    let out = forge(runner(), &TemplateWriter, &req, LoopConfig::default());
    let ForgeOutcome::Made(part) = out else { panic!("{:?}", out.attempts()) };
    assert_eq!(part.attempts.len(), 1);
    assert_eq!(part.report.genus, 1);
    // A washer is concave: it collides as several convex pieces, not as a disc.
    let asset = part.asset("generated_washer", Some(0.005), sw_geom::PlacementKind::OnSurface);
    let pieces = &asset.links[0].convex;
    assert!(pieces.len() >= 2, "{} pieces", pieces.len());
    let hull_volume: f64 = pieces.iter().map(|p| p.mesh.volume()).sum();
    let disc = std::f64::consts::PI * 0.01f64.powi(2) * 0.002;
    assert!(hull_volume < 0.95 * disc, "the pieces fill the hole: {hull_volume} vs disc {disc}");
    let size = asset.bounds().size();
    assert!((size[0] - 0.02).abs() < 2e-4 && (size[2] - 0.002).abs() < 2e-5, "{size:?}");
}
