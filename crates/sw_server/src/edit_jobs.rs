//! Structured edits as jobs: the options `POST /api/scenes/{id}/edits` stored for a move
//! or a placement, read back by the runner and applied with `sw_pipeline::edit_structured`
//! (a generated part's mesh is taken from the asset store first).

use std::path::Path;

use serde_json::Value;
use sw_pipeline::{EditOutcome, Event, PipelineError, StructuredEdit};

use crate::forge::AssetForge;

/// A structured edit in a job's options, before its mesh (if any) is fetched.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Spec {
    Move { object: String, pos: [f64; 2], yaw_deg: Option<f64> },
    Category { category: String, pos: [f64; 2], yaw_deg: Option<f64> },
    Mesh { asset_id: String, label: String, pos: [f64; 2], yaw_deg: Option<f64> },
}

fn pos(v: &Value) -> Option<[f64; 2]> {
    let a = v.get("pos")?.as_array()?;
    match a.as_slice() {
        [x, y] => Some([x.as_f64()?, y.as_f64()?]),
        _ => None,
    }
}

fn text(v: &Value, key: &str) -> Option<String> {
    v.get(key).and_then(Value::as_str).map(str::to_string)
}

/// The structured edit a job's options hold: `None` for a sentence, `Some(Err)` for
/// options this runner cannot read.
pub(crate) fn spec(options: &Value) -> Option<Result<Spec, String>> {
    let s = options.get("structured")?;
    let bad = || format!("unreadable structured edit: {s}");
    let yaw = |v: &Value| v.get("yaw_deg").and_then(Value::as_f64);
    let read = || -> Option<Spec> {
        if let Some(m) = s.get("move") {
            return Some(Spec::Move { object: text(m, "object")?, pos: pos(m)?, yaw_deg: yaw(m) });
        }
        let p = s.get("place")?;
        if let Some(category) = text(p, "category") {
            return Some(Spec::Category { category, pos: pos(p)?, yaw_deg: yaw(p) });
        }
        Some(Spec::Mesh { asset_id: text(p, "mesh")?, label: text(p, "label")?, pos: pos(p)?, yaw_deg: yaw(p) })
    };
    Some(read().ok_or_else(bad))
}

/// Applies a structured edit to the package in `dir` (blocking).
pub(crate) fn run(
    dir: &Path,
    spec: Spec,
    command: &str,
    forge: &AssetForge,
    on_event: &mut dyn FnMut(&Event),
) -> Result<EditOutcome, PipelineError> {
    let edit = match spec {
        Spec::Move { object, pos, yaw_deg } => StructuredEdit::Move { object, pos, yaw_deg },
        Spec::Category { category, pos, yaw_deg } => StructuredEdit::PlaceCategory { category, pos, yaw_deg },
        Spec::Mesh { asset_id, label, pos, yaw_deg } => {
            let stl = forge
                .mesh(&asset_id)
                .map_err(|e| PipelineError::Internal(e.to_string()))?
                .ok_or_else(|| PipelineError::Input(format!("the part \"{label}\" is no longer in the asset store")))?;
            StructuredEdit::PlaceMesh { asset_id, label, stl, pos, yaw_deg }
        }
    };
    sw_pipeline::edit_structured(dir, &edit, command, on_event)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn options_read_back_as_the_edit_they_hold() {
        let m = json!({"structured": {"move": {"object": "table_1", "pos": [1.5, -0.25], "yaw_deg": 90.0}}});
        assert_eq!(spec(&m), Some(Ok(Spec::Move { object: "table_1".into(), pos: [1.5, -0.25], yaw_deg: Some(90.0) })));
        let c = json!({"structured": {"place": {"category": "shelf", "pos": [0, 1], "yaw_deg": null}}});
        assert_eq!(spec(&c), Some(Ok(Spec::Category { category: "shelf".into(), pos: [0.0, 1.0], yaw_deg: None })));
        assert_eq!(spec(&json!({})), None);
        assert!(matches!(spec(&json!({"structured": {"move": {"pos": [1]}}})), Some(Err(_))));
    }
}
