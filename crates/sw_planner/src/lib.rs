//! L1, offline: a deterministic planner that reads English workspace descriptions.
//!
//! It understands room kinds and sizes, object phrases with counts, colours and size
//! words, spatial relations, robots and their mounting. Nouns with no catalog asset are
//! matched to the nearest category when close (typos) or become labelled proxies sized
//! by priors. Every word of the prompt is either used or reported in
//! `understanding.not_understood`; every approximation is listed in
//! `understanding.approximated`.

mod assemble;
mod cues;
mod lexicon;
pub mod llm;
mod parse;
mod phrase;
mod priors;
pub use priors::FALLBACK as FALLBACK_PRIOR;
mod quantity;
pub mod refine;
mod said;
mod tables;
mod text;
pub mod vocab;

use std::sync::OnceLock;

use sw_plan::ScenePlan;

/// Longest prompt accepted, in bytes (the same limit as the HTTP API).
pub const MAX_PROMPT_BYTES: usize = 64 * 1024;

/// Longest prompt the reader reads, in characters once runs of spaces are collapsed: a
/// scene description, not a document. Longer ones are refused up front (exit 2).
pub const MAX_PROMPT_CHARS: usize = 4000;

/// Why a prompt cannot be planned. Each is a problem with the input (exit code 2).
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PlannerError {
    #[error(
        "the prompt is empty: describe a room, its objects and robots, e.g. \"a warehouse with two pallet racks, six boxes and a TurtleBot\""
    )]
    Empty,
    #[error("the prompt is {bytes} bytes; the limit is {limit} bytes")]
    TooLong { bytes: usize, limit: usize },
    #[error("the prompt is {chars} characters; the reader reads at most {limit}: describe one scene in fewer words")]
    TooManyChars { chars: usize, limit: usize },
    #[error("{0}")]
    InvalidSize(String),
    #[error(
        "nothing in the prompt was recognised as a room, object or robot (the offline planner reads English; \
         configure an LLM endpoint for other languages and open vocabulary)"
    )]
    NothingUnderstood,
}

fn lexicon() -> &'static lexicon::Lexicon {
    static LEX: OnceLock<lexicon::Lexicon> = OnceLock::new();
    LEX.get_or_init(lexicon::Lexicon::new)
}

/// Plans a scene from a prompt. Deterministic: the same prompt gives the same plan.
pub fn plan(prompt: &str) -> Result<ScenePlan, PlannerError> {
    if prompt.len() > MAX_PROMPT_BYTES {
        return Err(PlannerError::TooLong { bytes: prompt.len(), limit: MAX_PROMPT_BYTES });
    }
    let cleaned = clean(prompt);
    if cleaned.is_empty() {
        return Err(PlannerError::Empty);
    }
    let chars = cleaned.chars().count();
    if chars > MAX_PROMPT_CHARS {
        return Err(PlannerError::TooManyChars { chars, limit: MAX_PROMPT_CHARS });
    }
    let mut tokens = text::tokenize(&cleaned);
    let typos = phrase::correct_function_words(lexicon(), &mut tokens);
    let mut parser = parse::Parser::new(lexicon(), &cleaned, tokens);
    parser.run()?;
    parser.draft.approximated.extend(typos);
    let leftovers = parser.leftovers();
    assemble::assemble(&cleaned, parser.draft, leftovers)
}

/// Trims, drops control characters and collapses runs of spaces (newlines are kept:
/// they end sentences).
fn clean(prompt: &str) -> String {
    let mut out = String::with_capacity(prompt.len());
    let mut last_space = true;
    for c in prompt.chars() {
        let c = if c == '\t' || c == '\r' { ' ' } else { c };
        if c.is_control() && c != '\n' {
            continue;
        }
        if c == ' ' {
            if !last_space {
                out.push(' ');
            }
            last_space = true;
        } else {
            out.push(c);
            last_space = c == '\n';
        }
    }
    out.trim().to_string()
}
