//! JSON Schemas of the contract types, generated from the code.

use crate::{EditLog, LaidOutScene, Report, ScenePlan, Timings};

/// One schema document and the file name it is checked in under (`schemas/<file_name>`).
#[derive(Debug, Clone)]
pub struct SchemaFile {
    pub file_name: &'static str,
    /// Pretty-printed JSON with a trailing newline.
    pub json: String,
}

/// The schemas of every document in a scene package.
pub fn schemas() -> Vec<SchemaFile> {
    let render = |schema: schemars::Schema| {
        let mut s = serde_json::to_string_pretty(&schema).unwrap_or_default();
        s.push('\n');
        s
    };
    vec![
        SchemaFile { file_name: "plan.schema.json", json: render(schemars::schema_for!(ScenePlan)) },
        SchemaFile { file_name: "layout.schema.json", json: render(schemars::schema_for!(LaidOutScene)) },
        SchemaFile { file_name: "report.schema.json", json: render(schemars::schema_for!(Report)) },
        SchemaFile { file_name: "timings.schema.json", json: render(schemars::schema_for!(Timings)) },
        SchemaFile { file_name: "edits.schema.json", json: render(schemars::schema_for!(EditLog)) },
    ]
}
