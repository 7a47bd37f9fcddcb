//! How long an answer may be, from what was asked; and, when an answer runs into its
//! limit, whether the model was looping or simply had more to say.
//!
//! A fixed limit per stage is wrong both ways: a prompt naming forty groups needs a plan
//! several times longer than one naming three, and a part with thirty dimensioned
//! features needs more CAD code than a washer — while a model stuck repeating itself should
//! be stopped early. So the limit grows with the request (the list items of the user's
//! text for a plan, its numbers for a part), never below the stage's default and never
//! above [`CEILING`]; and an answer cut off at the limit is looked at: one that ends in
//! the same stretch of text over and over is a loop (refused, not asked again), one that
//! does not is a long answer (asked once more with twice the room, up to the ceiling).

use sw_plan::LlmStage;

use crate::config::default_max_tokens;
use crate::request::{ChatRequest, Role};

/// No answer of any stage may be longer than this, tokens.
pub const CEILING: u32 = 8192;

/// The token limit of `stage` for `req` when neither the endpoint nor the caller set one.
pub fn max_tokens_for(stage: LlmStage, req: &ChatRequest) -> Option<u32> {
    let base = default_max_tokens(stage)?;
    let text = req.messages.iter().rev().find(|m| m.role == Role::User).map_or("", |m| m.content.as_str());
    let wanted = match stage {
        // Each object group is an object of the plan (id, category, count, phrase, size…).
        LlmStage::Plan => 200 + 120 * items(text),
        LlmStage::Relations => 120 + 64 * items(text),
        // Each dimension is a parameter or a feature of the code.
        LlmStage::Cad => 400 + 80 * numbers(text),
        LlmStage::Edit => 120 + 48 * items(text),
        LlmStage::Refine | LlmStage::Embeddings => 0,
    };
    Some(base.max(wanted.min(CEILING as usize) as u32))
}

/// The list items of a text: its phrases separated by commas, semicolons, full stops,
/// line breaks, "and", "with" and "plus".
fn items(text: &str) -> usize {
    let lower = text.to_lowercase();
    let words = lower.split_whitespace().filter(|w| matches!(*w, "and" | "with" | "plus" | "each")).count();
    let marks = lower.chars().filter(|c| matches!(c, ',' | ';' | '.' | '\n')).count();
    1 + words + marks
}

/// The numbers written in a text (`120`, `8.5`, `M6`'s 6): each a size or a count.
fn numbers(text: &str) -> usize {
    let mut n = 0;
    let mut in_number = false;
    for c in text.chars() {
        let digit = c.is_ascii_digit();
        if digit && !in_number {
            n += 1;
        }
        in_number = digit || (in_number && c == '.');
    }
    n
}

/// A stretch of text the answer ends in, over and over.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Repetition {
    /// The repeated stretch (at most 60 characters of it).
    pub unit: String,
    pub times: usize,
}

/// The loop an answer cut off at its limit ends in, if it ends in one: the end of the
/// answer is periodic — each byte equals the one a period of 1 to 600 bytes before it — over
/// at least three periods, at least 200 bytes and a third of its last 4000 bytes. (A
/// periodic run does not care where the answer was cut: in the middle of a repeat too.)
pub fn repetition(answer: &str) -> Option<Repetition> {
    let bytes = answer.as_bytes();
    let tail = &bytes[bytes.len() - bytes.len().min(4000)..];
    let n = tail.len();
    // (period, bytes covered by the periodic run including its first period)
    let mut best: Option<(usize, usize)> = None;
    for p in 1..=(n / 3).min(600) {
        let mut run = 0;
        while run + p < n && tail[n - 1 - run] == tail[n - 1 - run - p] {
            run += 1;
        }
        let covered = run + p;
        let longer = best.is_none_or(|(_, c)| covered > c + c / 10);
        if covered >= 3 * p && covered >= 200 && covered * 3 >= n && longer {
            best = Some((p, covered));
        }
    }
    let (p, covered) = best?;
    let start = n - covered;
    // The unit as it first appears in the run, from a character boundary.
    let mut from = start;
    while from < n && (tail[from] & 0xC0) == 0x80 {
        from += 1;
    }
    let unit = String::from_utf8_lossy(&tail[from..(from + p).min(n)]);
    Some(Repetition { unit: unit.chars().take(60).collect(), times: covered / p })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::request::Message;

    fn ask(text: &str) -> ChatRequest {
        ChatRequest::new(vec![Message::system("rules"), Message::user(text)])
    }

    #[test]
    fn the_limit_grows_with_what_is_asked() {
        let short = max_tokens_for(LlmStage::Plan, &ask("a table with two mugs")).unwrap();
        assert_eq!(short, 640, "a short prompt keeps the stage's default");
        let groups: Vec<String> = (0..40).map(|i| format!("{i} boxes")).collect();
        let long = max_tokens_for(LlmStage::Plan, &ask(&format!("a warehouse with {}", groups.join(", ")))).unwrap();
        assert!(long > 4000 && long <= CEILING, "{long}");
        let washer = max_tokens_for(LlmStage::Cad, &ask("a washer 40 mm outer, 20 mm inner, 3 mm thick")).unwrap();
        assert_eq!(washer, 1024);
        let dims: Vec<String> = (0..30).map(|i| format!("a hole of {i} mm at {i}.5 mm")).collect();
        let part = max_tokens_for(LlmStage::Cad, &ask(&dims.join("; "))).unwrap();
        assert!(part > 4000, "{part}");
        let huge = "a, ".repeat(100_000);
        assert_eq!(max_tokens_for(LlmStage::Plan, &ask(&huge)), Some(CEILING));
        assert_eq!(max_tokens_for(LlmStage::Embeddings, &ask("x")), None);
    }

    #[test]
    fn a_loop_is_told_from_a_long_answer() {
        let looped = format!("{{\"objects\": [{}", "{\"id\": \"box\", \"count\": 1}, ".repeat(60));
        let r = repetition(&looped).unwrap();
        assert!(r.times >= 50 && r.unit.contains("\"box\""), "{r:?}");
        // Cut off in the middle of a repeat.
        let cut = &looped[..looped.len() - 7];
        assert!(repetition(cut).is_some());
        // A long plan whose objects differ is not a loop.
        let long: String = (0..200).map(|i| format!("{{\"id\": \"group_{i}\", \"count\": {}}}, ", i % 7 + 1)).collect();
        assert_eq!(repetition(&long), None);
        // A short stutter is not a loop either.
        assert_eq!(repetition("ok ok ok ok"), None);
        // Multi-byte text repeated.
        let cjk = format!("计划：{}", "一张桌子，".repeat(80));
        assert!(repetition(&cjk).is_some());
    }
}
