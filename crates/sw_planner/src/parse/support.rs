//! Phrases that arrange or load a group rather than place it: collective nouns ("a row
//! of", "two rows of", "a stack of", "an aisle of"), carriers and their load ("pallets
//! of boxes", "shelves full of boxes", "loaded with"), companions ("each with a
//! stool", "a stool at each station"), and pronoun subjects ("They face each other").

use sw_plan::RelationKind;

use super::{Collective, CountRule, Parser, Subject, Support};
use crate::text::{TokenKind, number_word};

impl Parser<'_> {
    /// "a row of", "two rows of", "a stack of", "an aisle of": remembered for the next
    /// group. Returns the index after "of".
    pub(super) fn try_collective(&mut self, i: usize) -> Option<usize> {
        let (n, q) = match self.toks.get(i) {
            Some(t) if t.number().is_some() => (t.number().unwrap_or(1.0), 1),
            Some(t) if matches!(t.norm.as_str(), "a" | "an" | "one" | "single") => (1.0, 1),
            Some(t) if number_word(&t.norm).is_some() => (number_word(&t.norm).unwrap_or(1.0), 1),
            _ => (1.0, 0),
        };
        let noun = self.word(i + q);
        let kind = match noun {
            "row" | "rows" | "line" | "lines" | "column" | "columns" | "bank" | "banks" => Collective::Row,
            "stack" | "stacks" | "pile" | "piles" | "tower" => Collective::Stack,
            "aisle" | "aisles" => Collective::Aisle,
            _ => return None,
        };
        if self.word(i + q + 1) != "of" {
            return None;
        }
        // "an aisle of racks" when "aisles" is plural: several aisles.
        let n = if noun.ends_with('s') && q == 0 { 2.0 } else { n };
        self.mark(i, i + q + 2);
        // A new arrangement starts a new thing: it is not the load of the one before.
        self.with_host = None;
        self.support = None;
        self.each_host = None;
        self.collective = Some((kind, n));
        Some(i + q + 2)
    }

    /// The arrangement a collective gives the group just introduced.
    pub(super) fn take_collective(&mut self, id: &str) {
        let Some((kind, n)) = self.collective.take() else { return };
        let rel = match kind {
            Collective::Row if n >= 2.0 => RelationKind::InRows { n: Some(n.round() as u32), m: None },
            Collective::Row => RelationKind::InRow,
            Collective::Stack => RelationKind::Stacked { n: None, stacks: None },
            Collective::Aisle if n >= 2.0 => RelationKind::InAisles,
            Collective::Aisle => RelationKind::FacingEachOther,
        };
        // "two rows of five desks": five in each.
        if kind == Collective::Row
            && n >= 2.0
            && let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id)
            && let Some(c) = g.count
        {
            g.count = Some(c * n.round());
        }
        self.relate(id, rel);
    }

    /// "each with", "each having", "each has": the current plural subject hosts the
    /// companions that follow. Returns the index after the words.
    pub(super) fn try_each(&mut self, i: usize) -> Option<usize> {
        if !matches!(self.word(i), "each" | "every") {
            return None;
        }
        let mut j = i + 1;
        if matches!(self.word(j), "one") {
            j += 1;
        }
        if self.word(j) == "of" && matches!(self.word(j + 1), "them" | "which" | "these" | "those") {
            j += 2;
        }
        let verbs =
            ["with", "having", "has", "have", "holding", "carrying", "gets", "get", "equipped", "fitted", "topped"];
        if !verbs.contains(&self.word(j)) {
            return None;
        }
        j += 1;
        if matches!(self.word(j), "with") {
            j += 1;
        }
        let host = match &self.subject {
            Some(Subject::Group(g)) => Some(g.clone()),
            _ => None,
        }
        .or_else(|| match self.resolve_pronoun("they") {
            Some(Subject::Group(g)) => Some(g),
            _ => None,
        })?;
        self.mark(i, j);
        self.each_host = Some(host.clone());
        self.each_taken = 0;
        self.with_host = None;
        self.subject = Some(Subject::Group(host));
        Some(j)
    }

    /// "with a stool each": the group just introduced after "with" is a companion of the
    /// subject before it.
    pub(super) fn try_trailing_each(&mut self, i: usize) -> Option<usize> {
        if self.word(i) != "each" {
            return None;
        }
        let (host, last) = (self.with_subject.clone()?, self.draft.groups.last()?.id.clone());
        if host == last {
            return None;
        }
        self.used[i] = true;
        self.draft
            .relations
            .retain(|(s, k)| !(s == &last && matches!(k, RelationKind::On { target } if *target == host)));
        self.add_companion(&host, &last);
        self.subject = Some(Subject::Group(host));
        Some(i + 1)
    }

    /// Makes `id` the companions of `host`: one (or the phrase's count) for every host
    /// instance; small things rest on a host that has a surface.
    pub(super) fn add_companion(&mut self, host: &str, id: &str) {
        if let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id) {
            let per = g.count.unwrap_or(1.0).max(1.0);
            g.count_rule = Some(CountRule::EachOf { host: host.to_string(), per });
        }
        self.relate(host, RelationKind::EachWith { target: id.to_string() });
        if self.group_is_small(id) && self.group_has_surface(host) {
            self.relate(id, RelationKind::On { target: host.to_string() });
            self.on_host.push((id.to_string(), host.to_string()));
        }
    }

    /// "full of", "stocked with", "loaded with", and the "of" of "pallets of boxes" after
    /// a carrier: the small things that follow rest on it. Returns the index after.
    pub(super) fn try_support(&mut self, i: usize) -> Option<usize> {
        // The thing just named ("on a table in front of a shelf full of bins"), else the
        // subject.
        let last = self.draft.groups.last().map(|g| g.id.clone()).filter(|g| self.just_after_subject(i, g));
        let subject = match &self.subject {
            Some(Subject::Group(g)) => Some(g.clone()),
            _ => None,
        };
        let host = last.into_iter().chain(subject).find(|g| self.group_has_surface(g))?;
        let two = (self.word(i), self.word(i + 1));
        let (kind, len) = match two {
            ("full" | "filled" | "stocked" | "packed" | "crammed" | "lined" | "fully", "of" | "with") => {
                (Support::FullOf, 2)
            }
            ("loaded" | "stacked" | "piled" | "laden" | "heaped", "with") => (Support::Loaded, 2),
            ("of", _) if self.just_after_subject(i, &host) => {
                let storage = self
                    .group(&host)
                    .and_then(|g| g.category)
                    .and_then(sw_catalog::find)
                    .is_some_and(|c| c.has_tag("storage") && c.has_tag("tall"));
                (if storage { Support::FullOf } else { Support::Loaded }, 1)
            }
            _ => return None,
        };
        // "full of" needs something to follow.
        let next = i + len;
        if !self.toks.get(next).is_some_and(|t| t.kind == TokenKind::Word || t.number().is_some()) {
            return None;
        }
        self.mark(i, next);
        self.with_host = Some(host);
        self.support = Some(kind);
        self.support_taken = 0;
        Some(next)
    }

    /// True when token `i` directly follows the phrase that introduced `host`.
    fn just_after_subject(&self, i: usize, host: &str) -> bool {
        self.draft.groups.last().is_some_and(|g| g.id == host) && i > 0 && self.used[i - 1]
    }

    /// The load a supported group gets: on its carrier, and "loaded"/"full of" stated.
    pub(super) fn take_support(&mut self, host: &str, id: &str) {
        let Some(kind) = self.support else { return };
        let rel = match kind {
            Support::Loaded => RelationKind::Loaded { target: id.to_string() },
            Support::FullOf => RelationKind::FullOf { target: id.to_string() },
        };
        self.relate(host, rel);
        if let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id)
            && g.count.is_none()
        {
            g.count_rule = Some(CountRule::Fill { host: host.to_string(), levels: kind == Support::FullOf });
        }
    }

    /// "It stands in the corner.", "They face each other.": a pronoun at the start of a
    /// sentence is the subject it refers to.
    pub(super) fn try_pronoun_subject(&mut self, i: usize) -> Option<usize> {
        let w = self.word(i);
        if !matches!(w, "it" | "they" | "these" | "those" | "both") || self.subject.is_some() {
            return None;
        }
        let sentence_start = i == 0 || matches!(self.toks[i - 1].kind, TokenKind::Stop);
        if !sentence_start {
            return None;
        }
        // "These racks …" is a phrase, not a pronoun.
        if self.phrase_at(i + 1, false, super::Bare::No).ok().flatten().is_some() {
            return None;
        }
        let s = self.resolve_pronoun(w)?;
        self.used[i] = true;
        self.subject = Some(s);
        Some(i + 1)
    }
}
