//! The generation loop: a writer (a language model through `sw_llm`, or the template
//! synthesizer) writes CadQuery code for an object of a requested size, the sandboxed
//! runner executes it, the validator checks it, and every failure — filed under the
//! taxonomy, with its one-line message — is fed back to the writer for the next attempt.
//! After K failed attempts the caller falls back (catalog or labelled proxy); it is told
//! every attempt's kind so the report can say why.

use serde::Serialize;
use sw_geom::Mesh;
use sw_llm::{ChatRequest, Client, LlmStage, Message};
use tracing::{info_span, warn};

use crate::failure::{Failure, FailureKind};
use crate::mesh_io;
use crate::runner::{CadJob, CadRunner};
use crate::store::{AssetId, AssetRecord};
use crate::validate::{self, MeshReport, Orientation, Target};

/// What to make.
#[derive(Debug, Clone, PartialEq)]
pub struct PartRequest {
    /// What the object is ("a coffee mug with a handle").
    pub description: String,
    /// Its bounding box, metres (any orientation), when the plan gives one.
    pub size_m: Option<[f64; 3]>,
}

/// One attempt and how it ended.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Attempt {
    pub code: String,
    /// `None` when the part passed.
    pub failure: Option<Failure>,
}

/// Writes code for a request, given the attempts so far.
pub trait CodeWriter: Send + Sync {
    fn name(&self) -> String;
    fn write(&self, request: &PartRequest, history: &[Attempt]) -> Result<String, Failure>;
    /// The model calls made since the last take, for the run's telemetry.
    fn take_calls(&self) -> Vec<sw_llm::LlmCall> {
        Vec::new()
    }
}

/// The offline template synthesizer as a writer (deterministic: it never improves on a
/// retry, so one attempt is enough).
#[derive(Debug, Clone, Copy, Default)]
pub struct TemplateWriter;

impl CodeWriter for TemplateWriter {
    fn name(&self) -> String {
        "template".into()
    }

    fn write(&self, request: &PartRequest, _history: &[Attempt]) -> Result<String, Failure> {
        match crate::freeform::offline(&request.description) {
            Ok(crate::freeform::Offline::Code(s)) => Ok(s.code),
            Ok(crate::freeform::Offline::Catalog { category, .. }) => Err(Failure::new(
                FailureKind::Writer,
                format!("the procedural catalog's {category} is this object: take it from the catalog"),
            )),
            Err(e) => Err(Failure::new(FailureKind::Writer, e.to_string())),
        }
    }
}

/// A language model behind an OpenAI-compatible endpoint (the `cad` stage).
#[derive(Debug, Clone)]
pub struct LlmWriter {
    client: Client,
}

const SYSTEM: &str = "You write CadQuery (Python) code for one solid part. Rules: the code starts with \
`import cadquery as cq`; it may import only cadquery and math; it does not read or write files, print, or \
use the network; it assigns the finished solid to a variable named `result`; lengths are in millimetres; \
the part is one closed solid whose bounding box has the requested size. Answer with the code only, in one \
```python block.";

impl LlmWriter {
    pub fn new(client: Client) -> Self {
        Self { client }
    }

    pub fn client(&self) -> &Client {
        &self.client
    }

    fn messages(request: &PartRequest, history: &[Attempt]) -> Vec<Message> {
        let mut ask = format!("Make: {}.", request.description.trim());
        if let Some(s) = request.size_m {
            ask.push_str(&format!(
                " Bounding box: {:.1} × {:.1} × {:.1} mm (X × Y × Z).",
                s[0] * 1e3,
                s[1] * 1e3,
                s[2] * 1e3
            ));
        }
        let mut m = vec![Message::system(SYSTEM), Message::user(ask)];
        for a in history {
            m.push(Message::assistant(format!("```python\n{}\n```", a.code)));
            if let Some(f) = &a.failure {
                m.push(Message::user(format!(
                    "That code failed ({}): {}. Fix it and answer with the whole corrected code.",
                    f.kind.name(),
                    f.message
                )));
            }
        }
        m
    }
}

/// The bounding box (mm) a request written by [`LlmWriter`] asks for, read back from its
/// text ("Bounding box: 400.0 × 350.0 × 200.0 mm"): for model doubles and logs.
pub fn asked_size_mm(text: &str) -> Option<[f64; 3]> {
    let after = text.split("Bounding box:").nth(1)?;
    let nums: Vec<f64> = after
        .split(|c: char| !(c.is_ascii_digit() || c == '.'))
        .filter(|s| !s.is_empty())
        .filter_map(|s| s.parse().ok())
        .take(3)
        .collect();
    (nums.len() == 3).then(|| [nums[0], nums[1], nums[2]])
}

/// The code inside the first fenced block of an answer (or the whole answer).
pub fn extract_code(answer: &str) -> String {
    if let Some(start) = answer.find("```") {
        let rest = &answer[start + 3..];
        let rest = rest.split_once('\n').map_or(rest, |(lang, body)| if lang.trim().len() < 12 { body } else { rest });
        if let Some(end) = rest.find("```") {
            return rest[..end].trim().to_string();
        }
        return rest.trim().to_string();
    }
    answer.trim().to_string()
}

impl CodeWriter for LlmWriter {
    fn take_calls(&self) -> Vec<sw_llm::LlmCall> {
        self.client.telemetry().take()
    }

    fn name(&self) -> String {
        self.client.config().endpoint(LlmStage::Cad).map_or_else(|| "llm".into(), |e| format!("llm:{}", e.model))
    }

    fn write(&self, request: &PartRequest, history: &[Attempt]) -> Result<String, Failure> {
        let req = ChatRequest::new(Self::messages(request, history));
        let answer = self
            .client
            .complete(LlmStage::Cad, &req, "cad code")
            .map_err(|e| Failure::new(FailureKind::Writer, format!("the model did not answer: {e}")))?;
        let code = extract_code(&answer.content);
        if code.is_empty() {
            return Err(Failure::new(FailureKind::Writer, "the model answered with no code"));
        }
        Ok(code)
    }
}

/// A part the loop made.
#[derive(Debug, Clone)]
pub struct Forged {
    /// The mesh in the code's units (mm).
    pub mesh_mm: Mesh,
    pub report: MeshReport,
    pub code: String,
    pub attempts: Vec<Attempt>,
    pub writer: String,
}

impl Forged {
    /// The part as the asset store keeps it: binary STL in metres, and its record
    /// (`label` is what the index embeds; `extra` adds to the attempts and volume).
    pub fn stored(&self, label: &str, description: &str, extra: serde_json::Value) -> (Vec<u8>, AssetRecord) {
        let stl = mesh_io::stl_bytes_mm_as_m(&self.mesh_mm, "generated");
        let b = self.report.size;
        let mut all = serde_json::json!({ "attempts": self.attempts.len(), "volume_mm3": self.report.volume });
        if let (Some(all), serde_json::Value::Object(more)) = (all.as_object_mut(), extra) {
            all.extend(more);
        }
        let record = AssetRecord {
            id: AssetId::of(&stl),
            label: label.trim().to_string(),
            description: description.to_string(),
            source: self.writer.clone(),
            size_m: [b[0] * 1e-3, b[1] * 1e-3, b[2] * 1e-3],
            triangles: self.report.triangles,
            code: Some(self.code.clone()),
            extra: all,
        };
        (stl, record)
    }

    /// The part as a scene asset in metres: its mesh as the visual, its convex
    /// decomposition as collision, standing on z = 0.
    pub fn asset(&self, category: &str, mass_kg: Option<f64>, placement: sw_geom::PlacementKind) -> sw_geom::Asset {
        crate::collision::part_asset(category, &mesh_io::scaled(&self.mesh_mm, 1e-3), mass_kg, placement)
    }
}

/// How the loop ended.
#[derive(Debug, Clone)]
pub enum ForgeOutcome {
    Made(Box<Forged>),
    /// Every attempt failed: fall back to the catalog or a labelled proxy.
    Failed {
        attempts: Vec<Attempt>,
        writer: String,
    },
}

impl ForgeOutcome {
    pub fn attempts(&self) -> &[Attempt] {
        match self {
            ForgeOutcome::Made(f) => &f.attempts,
            ForgeOutcome::Failed { attempts, .. } => attempts,
        }
    }
}

/// The loop's settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopConfig {
    /// Attempts before falling back (K).
    pub max_attempts: usize,
    /// Relative tolerance of the bounding box against the requested size.
    pub size_tolerance: f64,
}

impl Default for LoopConfig {
    fn default() -> Self {
        Self { max_attempts: 3, size_tolerance: 0.05 }
    }
}

/// Writes, runs and validates until a part passes or `max_attempts` have failed.
pub fn forge(runner: &CadRunner, writer: &dyn CodeWriter, request: &PartRequest, config: LoopConfig) -> ForgeOutcome {
    let _span = info_span!("forge_loop", writer = %writer.name()).entered();
    let target = Target {
        size: request.size_m.map(|s| s.map(|v| v * 1e3)),
        orientation: Orientation::Free,
        size_tolerance: config.size_tolerance,
        ..Target::default()
    };
    let mut attempts: Vec<Attempt> = Vec::new();
    for _ in 0..config.max_attempts.max(1) {
        let code = match writer.write(request, &attempts) {
            Ok(c) => c,
            Err(f) => {
                // No code: nothing to feed back; the writer is out.
                attempts.push(Attempt { code: String::new(), failure: Some(f) });
                break;
            }
        };
        let failure = match runner.run(&CadJob::cadquery(code.clone())) {
            Err(e) => e.failure,
            Ok(mut run) => {
                mesh_io::drop_collapsed_triangles(&mut run.mesh);
                match validate::validate(&run.mesh, &target) {
                    Ok(report) => {
                        attempts.push(Attempt { code: code.clone(), failure: None });
                        return ForgeOutcome::Made(Box::new(Forged {
                            mesh_mm: run.mesh,
                            report,
                            code,
                            attempts,
                            writer: writer.name(),
                        }));
                    }
                    Err(f) => f,
                }
            }
        };
        warn!("attempt {} failed: {failure}", attempts.len() + 1);
        attempts.push(Attempt { code, failure: Some(failure) });
    }
    ForgeOutcome::Failed { attempts, writer: writer.name() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn code_is_taken_from_the_fenced_block() {
        assert_eq!(extract_code("Here:\n```python\nresult = 1\n```\nDone."), "result = 1");
        assert_eq!(extract_code("```\nresult = 2\n```"), "result = 2");
        assert_eq!(extract_code("result = 3"), "result = 3");
        assert_eq!(extract_code("```python\nresult = 4"), "result = 4");
    }

    #[test]
    fn the_asked_size_reads_back_from_the_request() {
        let req = PartRequest { description: "a spectrum analyzer".into(), size_m: Some([0.4, 0.35, 0.2]) };
        let m = LlmWriter::messages(&req, &[]);
        assert_eq!(asked_size_mm(&m[1].content), Some([400.0, 350.0, 200.0]));
        let unsized_req = PartRequest { description: "a knob".into(), size_m: None };
        assert_eq!(asked_size_mm(&LlmWriter::messages(&unsized_req, &[])[1].content), None);
    }

    #[test]
    fn retries_carry_the_failure_back_to_the_model() {
        let req = PartRequest { description: "a mug".into(), size_m: Some([0.08, 0.08, 0.1]) };
        let history = vec![Attempt {
            code: "result = cq.Workplane().box(1, 1, 1)".into(),
            failure: Some(Failure::new(FailureKind::ScaleMismatch, "the bounding box is 1 × 1 × 1")),
        }];
        let m = LlmWriter::messages(&req, &history);
        assert_eq!(m.len(), 4);
        let last = format!("{:?}", m[3]);
        assert!(last.contains("scale_mismatch") && last.contains("1 × 1 × 1"), "{last}");
        assert!(format!("{:?}", m[1]).contains("80.0 × 80.0 × 100.0 mm"));
    }
}
