//! A read instruction before it meets a scene: goals over noun phrases ("in(black bowl,
//! plate)"). `words` reads them, `bind` turns them into predicates over bodies; the
//! wording suite (`bench/demos/task_wordings_dev.tsv`) scores this layer alone.

use crate::vocab::{Action, Region, Rel};
use crate::words::{Clause, NounPhrase};

/// What a goal asks of its subject, before binding.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum GoalKind {
    In,
    On,
    Near,
    /// Beside the goal thing on one side ("to the left of", "in front of", "behind").
    Side(Region),
    /// A part of a surface (the goal thing, or the subject's own support).
    Region(Region),
    Lift,
    /// Stack the subjects on each other.
    Stack,
    Open,
    Closed,
    GoTo,
}

/// One goal of an instruction, over noun phrases as written.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Goal {
    pub kind: GoalKind,
    pub subject: NounPhrase,
    pub target: Option<NounPhrase>,
}

fn region_name(r: Region) -> &'static str {
    match r {
        Region::Left => "left",
        Region::Right => "right",
        Region::Front => "front",
        Region::Back => "back",
        Region::Centre => "centre",
        Region::Corner => "corner",
    }
}

/// A noun phrase as the wording suite writes it: singular head, `*` for every one.
fn phrase(np: &NounPhrase) -> String {
    let mut ws: Vec<String> = np.text.split(' ').filter(|w| !w.is_empty()).map(str::to_string).collect();
    // The head is the last word before an "of" complement ("top drawers of the cabinet").
    let head = ws.iter().position(|w| w == "of").map_or(ws.len(), |i| i).saturating_sub(1);
    if let Some(w) = ws.get_mut(head)
        && let Some(s) = sw_planner::vocab::words(w).first()
    {
        *w = s.clone();
    }
    let text: Vec<String> = ws.into_iter().filter(|w| !matches!(w.as_str(), "the" | "a" | "an")).collect();
    format!("{}{}", text.join(" "), if np.every { "*" } else { "" })
}

impl std::fmt::Display for Goal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = match self.kind {
            GoalKind::In => "in".to_string(),
            GoalKind::On => "on".to_string(),
            GoalKind::Near => "near".to_string(),
            GoalKind::Side(Region::Left) => "left_of".to_string(),
            GoalKind::Side(Region::Right) => "right_of".to_string(),
            GoalKind::Side(Region::Front) => "front_of".to_string(),
            GoalKind::Side(Region::Back) => "behind".to_string(),
            GoalKind::Side(r) => format!("{}_of", region_name(r)),
            GoalKind::Region(r) => format!("region_{}", region_name(r)),
            GoalKind::Lift => "lift".to_string(),
            GoalKind::Stack => "stack".to_string(),
            GoalKind::Open => "open".to_string(),
            GoalKind::Closed => "closed".to_string(),
            GoalKind::GoTo => "goto".to_string(),
        };
        match &self.target {
            Some(t) => write!(f, "{name}({}, {})", phrase(&self.subject), phrase(t)),
            None => write!(f, "{name}({})", phrase(&self.subject)),
        }
    }
}

/// The goals of clauses as the clause reader gives them.
pub(crate) fn from_clauses(clauses: &[Clause]) -> Vec<Goal> {
    let mut out = Vec::new();
    for c in clauses {
        let kind = match (c.action, c.rel, c.region, c.side) {
            (Action::Open, ..) => GoalKind::Open,
            (Action::Close, ..) => GoalKind::Closed,
            (Action::Navigate, ..) => GoalKind::GoTo,
            (_, _, Some(r), _) => GoalKind::Region(r),
            (Action::Lift, None, ..) => GoalKind::Lift,
            (Action::Stack, None, ..) => GoalKind::Stack,
            (_, Some(Rel::Near), _, Some(s)) => GoalKind::Side(s),
            (_, Some(Rel::Near), ..) => GoalKind::Near,
            (_, Some(Rel::Inside), ..) => GoalKind::In,
            (Action::Push, Some(Rel::To), ..) => GoalKind::Near,
            _ => GoalKind::On,
        };
        if kind == GoalKind::GoTo {
            if let Some(t) = c.target.clone().or_else(|| c.subjects.first().cloned()) {
                out.push(Goal { kind, subject: t, target: None });
            }
            continue;
        }
        if kind == GoalKind::Stack {
            for s in &c.subjects {
                out.push(Goal { kind, subject: s.clone(), target: None });
            }
            continue;
        }
        for s in &c.subjects {
            out.push(Goal { kind, subject: s.clone(), target: c.target.clone() });
        }
    }
    out
}

/// Reads an instruction into goals over noun phrases, as the wording suite writes them
/// ("in(black bowl, plate)"); the error is the reader's one-line refusal.
pub fn read_goals(instruction: &str) -> Result<Vec<String>, crate::TaskError> {
    let clauses = crate::words::read(instruction)?;
    Ok(from_clauses(&clauses).iter().map(Goal::to_string).collect())
}
