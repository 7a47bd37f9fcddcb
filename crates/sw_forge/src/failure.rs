//! The failure taxonomy of generated CAD code: every way an attempt can go wrong gets
//! one kind, a one-line message that names the problem (and the line of code when there
//! is one), and that message is what the next attempt is told.

use std::fmt;

use serde::{Deserialize, Serialize};

/// Why an attempt did not give a usable part.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FailureKind {
    /// The code does not parse.
    Syntax,
    /// The code raised, crashed the CAD kernel, or made no shape.
    Runtime,
    /// The shape is not a closed, valid solid with positive volume (or its mesh is not
    /// watertight, or has more triangles than the budget).
    InvalidSolid,
    /// The bounding box is not the requested size.
    ScaleMismatch,
    /// The code ran longer than its time limit (wall clock or CPU).
    Timeout,
    /// The code tried something the sandbox forbids (an import, a file outside its
    /// directory, the network, a process, too much memory or output).
    SandboxViolation,
    /// The part has the requested size but not the requested shape (its volume or its
    /// number of through-holes is off).
    SemanticMismatch,
    /// No code was written: the writer (a model endpoint, the template synthesizer)
    /// could not answer.
    Writer,
    /// The CAD runner is not available (not set up, or its workers would not start).
    Runner,
}

impl FailureKind {
    pub const ALL: [FailureKind; 9] = [
        FailureKind::Syntax,
        FailureKind::Runtime,
        FailureKind::InvalidSolid,
        FailureKind::ScaleMismatch,
        FailureKind::Timeout,
        FailureKind::SandboxViolation,
        FailureKind::SemanticMismatch,
        FailureKind::Writer,
        FailureKind::Runner,
    ];

    pub fn name(self) -> &'static str {
        match self {
            FailureKind::Syntax => "syntax",
            FailureKind::Runtime => "runtime",
            FailureKind::InvalidSolid => "invalid_solid",
            FailureKind::ScaleMismatch => "scale_mismatch",
            FailureKind::Timeout => "timeout",
            FailureKind::SandboxViolation => "sandbox_violation",
            FailureKind::SemanticMismatch => "semantic_mismatch",
            FailureKind::Writer => "writer",
            FailureKind::Runner => "runner",
        }
    }

    /// True when the code itself was at fault (worth another attempt with the error).
    pub fn is_code_failure(self) -> bool {
        !matches!(self, FailureKind::Writer | FailureKind::Runner)
    }

    /// The kind for an error the CAD worker reports.
    pub fn from_worker(kind: &str) -> FailureKind {
        match kind {
            "syntax" => FailureKind::Syntax,
            "invalid_solid" | "no_result" => FailureKind::InvalidSolid,
            "timeout" => FailureKind::Timeout,
            "sandbox" | "memory" | "output_limit" => FailureKind::SandboxViolation,
            _ => FailureKind::Runtime,
        }
    }
}

impl fmt::Display for FailureKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One failed attempt.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, thiserror::Error)]
#[error("{kind}: {message}")]
pub struct Failure {
    pub kind: FailureKind,
    pub message: String,
    /// The line of generated code the failure points at.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub line: Option<u32>,
}

impl Failure {
    pub fn new(kind: FailureKind, message: impl Into<String>) -> Self {
        Self { kind, message: message.into(), line: None }
    }

    pub fn at_line(mut self, line: Option<u32>) -> Self {
        self.line = line;
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn worker_kinds_map_onto_the_taxonomy() {
        assert_eq!(FailureKind::from_worker("syntax"), FailureKind::Syntax);
        assert_eq!(FailureKind::from_worker("memory"), FailureKind::SandboxViolation);
        assert_eq!(FailureKind::from_worker("output_limit"), FailureKind::SandboxViolation);
        assert_eq!(FailureKind::from_worker("no_result"), FailureKind::InvalidSolid);
        assert_eq!(FailureKind::from_worker("crash"), FailureKind::Runtime);
        assert_eq!(
            serde_json::to_string(&FailureKind::SandboxViolation).ok().as_deref(),
            Some("\"sandbox_violation\"")
        );
        assert!(FailureKind::Timeout.is_code_failure() && !FailureKind::Writer.is_code_failure());
    }
}
