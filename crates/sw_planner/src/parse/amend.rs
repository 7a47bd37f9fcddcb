//! Counts and groups amended after they were named: "checkouts x2", "pallets along the
//! wall, 8 of them", a retraction ("a UR3e… no, a UR5e", "pendant lights (ignore)"), and a
//! thing named loosely first and counted later ("the bowls on the left …, 3 bowls": one
//! group of three, not seven).

use sw_plan::{Approximation, RelationKind};

use super::{CountRule, Parser, Subject};
use crate::quantity::numeral_at;
use crate::text::TokenKind;

impl Parser<'_> {
    /// "toasters x2", "checkouts ×3": a count after the group's phrase. Returns the index
    /// after.
    pub(super) fn try_times_count(&mut self, i: usize) -> Option<usize> {
        if self.toks.get(i)?.kind != TokenKind::Times {
            return None;
        }
        let Some(Subject::Group(g)) = self.subject.clone() else {
            return None;
        };
        let (n, len) = numeral_at(&self.toks, i + 1)?;
        if !self.just_after_group(i, &g) || !(1.0..=10_000.0).contains(&n) {
            return None;
        }
        if let Some(group) = self.draft.groups.iter_mut().find(|x| x.id == g) {
            group.count = Some(n);
            group.plural = n > 1.0;
        }
        self.mark(i, i + 1 + len);
        Some(i + 1 + len)
    }

    /// "3D printers (3)", "laundry baskets (4)": a numeral in brackets right after a plural
    /// named without a count is its count.
    pub(super) fn try_bracket_count(&mut self, i: usize) -> Option<usize> {
        if self.toks.get(i)?.norm != "(" {
            return None;
        }
        let Some(Subject::Group(g)) = self.subject.clone() else {
            return None;
        };
        let (n, len) = numeral_at(&self.toks, i + 1)?;
        if self.toks.get(i + 1 + len)?.norm != ")" || !self.just_after_group(i, &g) || !(1.0..=10_000.0).contains(&n) {
            return None;
        }
        let group = self.draft.groups.iter_mut().find(|x| x.id == g)?;
        if group.count.is_some() || !group.plural {
            return None;
        }
        group.count = Some(n);
        group.count_rule = None;
        self.mark(i, i + 2 + len);
        Some(i + 2 + len)
    }

    /// "pallets along the wall, 8 of them": the count of the plural group named before.
    pub(super) fn try_count_of_them(&mut self, i: usize) -> Option<usize> {
        let (n, len) = numeral_at(&self.toks, i)?;
        if self.word(i + len) != "of" || !matches!(self.word(i + len + 1), "them" | "these" | "those") {
            return None;
        }
        // The plural group being described, else the one named before.
        let current = match &self.subject {
            Some(Subject::Group(g)) if self.group(g).is_some_and(|x| x.plural) => Some(g.clone()),
            _ => None,
        };
        let g = current.or_else(|| match self.resolve_pronoun("them") {
            Some(Subject::Group(g)) => Some(g),
            _ => None,
        })?;
        if let Some(group) = self.draft.groups.iter_mut().find(|x| x.id == g)
            && group.count_rule.is_none()
        {
            group.count = Some(n);
            group.plural = n > 1.0;
        }
        self.mark(i, i + len + 2);
        Some(i + len + 2)
    }

    /// "a UR3e… no, a UR5e", "pendant lights (ignore)", "a rug (skip that)": the thing
    /// named just before is taken back. Returns the index after the words.
    pub(super) fn try_retraction(&mut self, i: usize) -> Option<usize> {
        let w = self.word(i);
        let prev = i.checked_sub(1).and_then(|k| self.toks.get(k));
        let next = self.toks.get(i + 1);
        let after_break = prev.is_some_and(|t| matches!(t.kind, TokenKind::Comma | TokenKind::Other | TokenKind::Stop));
        let correction =
            w == "no" && after_break && next.is_some_and(|t| matches!(t.kind, TokenKind::Comma | TokenKind::Other));
        let in_brackets = prev.is_some_and(|t| t.norm == "(")
            && matches!(w, "ignore" | "skip" | "omit" | "none" | "optional" | "not")
            || matches!((w, self.word(i + 1)), ("skip" | "ignore" | "omit", "those" | "that" | "them" | "it"));
        if !(correction || in_brackets) {
            return None;
        }
        let last = self.mentions.last().cloned()?;
        let phrase = match &last {
            Subject::Group(g) => {
                let g = g.clone();
                let group = self.draft.groups.iter_mut().find(|x| x.id == g)?;
                group.count = Some(0.0);
                group.count_rule = None;
                group.phrase.clone()
            }
            Subject::Robot(r) => {
                let robot = self.draft.robots.get_mut(*r)?;
                robot.count = Some(0.0);
                robot.phrase.clone()
            }
        };
        self.draft.approximated.push(Approximation {
            text: phrase,
            became: "left out".into(),
            reason: "the prompt takes it back".into(),
        });
        let mut end = i + 1;
        if matches!(self.word(end), "those" | "that" | "them" | "it" | "needed") {
            end += 1;
        }
        self.mark(i, end);
        self.subject = None;
        Some(end)
    }

    /// True when token `i` directly follows the phrase of group `g`.
    fn just_after_group(&self, i: usize, g: &str) -> bool {
        i > 0
            && self.used[i - 1]
            && self.group(g).is_some_and(|x| x.phrase.to_lowercase().ends_with(&self.toks[i - 1].norm))
    }

    /// A group named without a count (a plural's default, or a definite phrase with nothing
    /// to refer to) and later counted under the same category is one group: "the bowls on
    /// the left of the table, 3 bowls" is three bowls. Its relations move to the counted one.
    pub(super) fn merge_restated(&mut self) {
        let mut k = 0;
        while k < self.draft.groups.len() {
            let a = &self.draft.groups[k];
            let loose = a.count_rule.is_none() && (a.count.is_none() || a.accommodated) && a.category.is_some();
            let later = self.draft.groups[k + 1..]
                .iter()
                // A thing of another colour is another thing ("the pink block", "red blocks").
                .find(|b| {
                    b.category == a.category
                        && b.count.is_some()
                        && !b.accommodated
                        && b.count_rule.is_none()
                        && (a.color.is_none() || b.color.is_none() || a.color == b.color)
                })
                .map(|b| b.id.clone());
            let (Some(b), true) = (later, loose) else {
                k += 1;
                continue;
            };
            let a_id = a.id.clone();
            let redirect = |s: &mut String| {
                if *s == a_id {
                    *s = b.clone();
                }
            };
            for (s, kind) in &mut self.draft.relations {
                redirect(s);
                if let Some(t) = kind.targets().first().map(|t| t.to_string())
                    && t == a_id
                {
                    *kind = retarget(kind.clone(), &b);
                }
            }
            self.draft.relations.retain(|(s, kind)| !kind.targets().contains(&s.as_str()));
            let mut seen = Vec::new();
            self.draft.relations.retain(|r| {
                let fresh = !seen.contains(r);
                seen.push(r.clone());
                fresh
            });
            // "a stool at each bench, 3 benches": the stools are counted per counted bench.
            for g in &mut self.draft.groups {
                if let Some(CountRule::EachOf { host, .. } | CountRule::Fill { host, .. }) = &mut g.count_rule {
                    redirect(host);
                }
            }
            for r in &mut self.draft.robots {
                if let sw_plan::Mount::OnSurface { target } = &mut r.mount {
                    redirect(target);
                }
                if let Some(n) = &mut r.near {
                    redirect(n);
                }
            }
            self.draft.groups.remove(k);
        }
    }
}

/// `kind` pointing at `target` instead (for the kinds with one target).
fn retarget(kind: RelationKind, target: &str) -> RelationKind {
    let t = target.to_string();
    match kind {
        RelationKind::On { .. } => RelationKind::On { target: t },
        RelationKind::Under { .. } => RelationKind::Under { target: t },
        RelationKind::NextTo { .. } => RelationKind::NextTo { target: t },
        RelationKind::Near { .. } => RelationKind::Near { target: t },
        RelationKind::InFrontOf { .. } => RelationKind::InFrontOf { target: t },
        RelationKind::Behind { .. } => RelationKind::Behind { target: t },
        RelationKind::Around { .. } => RelationKind::Around { target: t },
        RelationKind::AtEndOfRow { .. } => RelationKind::AtEndOfRow { target: t },
        RelationKind::Loaded { .. } => RelationKind::Loaded { target: t },
        RelationKind::FullOf { .. } => RelationKind::FullOf { target: t },
        RelationKind::EachWith { .. } => RelationKind::EachWith { target: t },
        RelationKind::Reach { .. } => RelationKind::Reach { target: t },
        RelationKind::Inside { .. } => RelationKind::Inside { target: t },
        RelationKind::SetInto { .. } => RelationKind::SetInto { target: t },
        RelationKind::AtEndOf { end, .. } => RelationKind::AtEndOf { target: t, end },
        RelationKind::OnEdgeOf { .. } => RelationKind::OnEdgeOf { target: t },
        RelationKind::OnEachSideOf { .. } => RelationKind::OnEachSideOf { target: t },
        RelationKind::Facing { .. } => RelationKind::Facing { target: t },
        other => other,
    }
}
