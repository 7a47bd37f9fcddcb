//! Titles: words before a colon or a dash at the start of a prompt or a line ("A repair
//! bay: a bench with …", "robot kitchen - a fridge …"). A title names the room or the
//! scene's purpose; it never introduces objects. A room it names is the room; a robot
//! model it names is kept only when the body names no robot.

use sw_plan::{Approximation, Mount};

use super::{Head, Parser, Phrase, RobotDraft};
use crate::lexicon::Meaning;
use crate::text::TokenKind;

/// The longest title, in words.
const MAX_TITLE_WORDS: usize = 8;

impl Parser<'_> {
    /// The end (exclusive, the separator's index) of a title starting at `i`, if one does.
    pub(super) fn title_at(&self, i: usize) -> Option<usize> {
        let line_start = i == 0 || self.toks.get(i - 1).is_some_and(|t| t.norm == "\n");
        if !line_start {
            return None;
        }
        let mut words = 0;
        for j in i..self.toks.len() {
            let t = &self.toks[j];
            let separator = (t.kind == TokenKind::Stop && t.norm == ":")
                || (t.kind == TokenKind::Other && matches!(t.norm.as_str(), "-" | "–" | "—") && j > i);
            if separator {
                // Something must follow the title.
                let rest = self.toks[j + 1..].iter().any(|t| t.kind == TokenKind::Word);
                return (words > 0 && rest).then_some(j);
            }
            match t.kind {
                TokenKind::Word | TokenKind::Number(_) | TokenKind::Times | TokenKind::Other => words += 1,
                // A list or a sentence before the colon is no title.
                TokenKind::Comma | TokenKind::Stop => return None,
            }
            // "Stack a red cube on a green cube - …" is a sentence, not a title.
            if crate::cues::cue_at(&self.toks, j).is_some() {
                return None;
            }
            // "a kitchen with: a fridge, …" — a list announced, not a title.
            if matches!(t.norm.as_str(), "containing" | "has" | "have" | "includes" | "including") {
                return None;
            }
            if words > MAX_TITLE_WORDS {
                return None;
            }
        }
        None
    }

    /// Takes a phrase of a title: true when it was taken here (an object or robot, which a
    /// title does not introduce), false for a room, which is read as anywhere.
    pub(super) fn title_phrase(&mut self, p: &Phrase) -> bool {
        match &p.head {
            Head::Known(Meaning::Robot(word)) => {
                if word.exact {
                    self.title_robots.push(RobotDraft {
                        word: word.clone(),
                        phrase: p.text.clone(),
                        count: p.count,
                        plural: p.plural,
                        mount: Mount::Auto,
                        near: None,
                    });
                }
                true
            }
            Head::Known(Meaning::Category(_)) | Head::Unknown(_) | Head::Place(_) => {
                self.draft.approximated.push(Approximation {
                    text: p.text.clone(),
                    became: "the title".into(),
                    reason: "words before the colon name the scene; they add no object".into(),
                });
                true
            }
            _ => false,
        }
    }
}
