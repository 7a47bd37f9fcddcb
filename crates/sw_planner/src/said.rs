//! What the reader says with the relations issue 20 adds to the vocabulary (inside, set
//! into, at the end of, on the edge of, on each side of, facing …), in one place: each
//! is written as the plan's relation that states it.

use sw_plan::{EndOf, RelationKind};

/// A relation as the reader understood it, before it is written into the plan.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Said {
    /// Within a container, a cabinet or a shelf's levels ("cups in the sink").
    Inside(String),
    /// A sink or hob set into a counter run ("a hob in the worktop").
    SetInto(String),
    /// Beyond an end of the target ("a bin at the end of the conveyor").
    AtEndOf(String),
    /// Resting on the target near an edge of its top.
    OnEdgeOf(String),
    /// On two opposite sides of the target ("a chair on either side of the desk").
    OnEachSideOf(String),
    /// Front turned to the target ("a sofa facing the TV", "opposite the desk").
    Facing(String),
    /// Beyond a named end of the target: its start, its end, or both.
    AtEnd(String, EndOf),
}

impl Said {
    /// The plan's relation for what was said.
    pub fn kind(self) -> RelationKind {
        match self {
            Said::Inside(target) => RelationKind::Inside { target },
            Said::SetInto(target) => RelationKind::SetInto { target },
            Said::OnEdgeOf(target) => RelationKind::OnEdgeOf { target },
            Said::AtEndOf(target) => RelationKind::AtEndOf { target, end: None },
            Said::AtEnd(target, end) => RelationKind::AtEndOf { target, end: Some(end) },
            Said::OnEachSideOf(target) => RelationKind::OnEachSideOf { target },
            Said::Facing(target) => RelationKind::Facing { target },
        }
    }
}

/// The relation a stated one implies and the layout already keeps: resting inside a
/// thing or on its edge is resting on one of its surfaces; beyond the end of one thing is
/// at the end of its row of one. Both go into the plan, so the scene keeps the stated
/// relation as far as the layout can while it learns the new kinds.
pub(crate) fn implied(kind: &RelationKind) -> Option<RelationKind> {
    match kind {
        RelationKind::Inside { target } | RelationKind::OnEdgeOf { target } => {
            Some(RelationKind::On { target: target.clone() })
        }
        RelationKind::AtEndOf { target, .. } => Some(RelationKind::AtEndOfRow { target: target.clone() }),
        _ => None,
    }
}

/// Categories a thing is set into rather than put in ("a sink in the counter").
/// (`tables/set_into.tsv`).
pub(crate) fn is_set_into(subject: Option<&str>, target: Option<&str>) -> bool {
    let (Some(s), Some(t)) = (subject, target) else { return false };
    crate::tables::rows(crate::tables::SET_INTO).any(|r| r[0] == s && r[1] == t)
}
