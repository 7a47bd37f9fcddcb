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
            Collective::Row if n >= 2.0 => RelationKind::InRows {
                n: Some(n.round() as u32),
                m: self.group(id).and_then(|g| g.count).filter(|c| *c >= 1.0).map(|c| c.round() as u32),
            },
            Collective::Row => RelationKind::InRow,
            Collective::Stack => RelationKind::Stacked { n: None, stacks: None },
            Collective::Aisle if n >= 2.0 => RelationKind::InAisles,
            Collective::Aisle => RelationKind::FacingEachOther,
        };
        // "three stacks of four boxes": four in each.
        if kind == Collective::Stack
            && let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id)
        {
            g.stacks = Some(n.round().max(1.0));
            if n >= 2.0 {
                g.layers = g.count;
                g.count = g.count.map(|c| c * n.round());
            }
        }
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
        // "each desk has a chair", "every bay has a leveller": the host is named.
        let mut named = None;
        if let Some(p) = self.phrase_at(j, true, super::Bare::Target).ok().flatten() {
            let host = match &p.head {
                super::Head::Known(crate::lexicon::Meaning::Category(cat)) => {
                    self.resolve_group(Some(cat), &singular_head(&p.text))
                }
                super::Head::Unknown(label) => self.resolve_group(None, label),
                _ => None,
            };
            if let Some(h) = host {
                named = Some(h);
                j = p.end;
            } else if let super::Head::Place(_) = p.head {
                // "4 bays, every bay has a leveller": one at each of the places counted.
                let n =
                    p.count.filter(|c| *c > 1.0).or_else(|| self.place_counts.get(&singular_head(&p.text)).copied());
                if let Some(n) = n {
                    named = Some(format!("@place:{n}"));
                    j = p.end;
                }
            }
        }
        let verbs = [
            "with", "having", "has", "have", "holding", "carrying", "gets", "get", "equipped", "fitted", "topped",
            "needs", "hosts", "carries", "holds",
        ];
        // "each loaded with two drums", "each stocked with bins": a load on every host.
        let load = match self.word(j) {
            "loaded" | "stacked" | "piled" | "laden" | "heaped" => Some(Support::Loaded),
            "filled" | "stocked" | "packed" | "full" => Some(Support::FullOf),
            _ => None,
        };
        let loaded = load.is_some() && matches!(self.word(j + 1), "with" | "of");
        if !(verbs.contains(&self.word(j)) || loaded) {
            return None;
        }
        j += 1;
        if matches!(self.word(j), "with" | "of") {
            j += 1;
        }
        let host = named
            .or_else(|| match &self.subject {
                Some(Subject::Group(g)) => Some(g.clone()),
                _ => None,
            })
            .or_else(|| match self.resolve_pronoun("they") {
                Some(Subject::Group(g)) => Some(g),
                _ => None,
            })?;
        self.mark(i, j);
        self.each_host = Some(host.clone());
        self.each_taken = 0;
        self.with_host = None;
        self.support = load;
        self.subject = Some(Subject::Group(host));
        Some(j)
    }

    /// "one lamp per desk", "two chairs for each table", "10 bags per pallet": the group just
    /// named is a companion of the group after "per". A bare number before "per" ("12
    /// printers on four units, 3 per unit") restates a count already given. Returns the
    /// index after.
    pub(super) fn try_per(&mut self, i: usize) -> Option<usize> {
        let len = match (self.word(i), self.word(i + 1)) {
            ("per", _) | ("a" | "an", _) if self.word(i) == "per" => 1,
            ("for", "each" | "every") => 2,
            _ => return None,
        };
        let Some(Subject::Group(g)) = self.subject.clone() else {
            return None;
        };
        let j = i + len;
        let p = self.phrase_at(j, true, super::Bare::Target).ok().flatten()?;
        let host = match &p.head {
            super::Head::Known(crate::lexicon::Meaning::Category(cat)) => {
                self.resolve_group(Some(cat), &singular_head(&p.text))
            }
            super::Head::Unknown(label) => self.resolve_group(None, label),
            _ => None,
        };
        let bare_number = i > 0
            && self.toks[i - 1].number().is_some()
            && !self.group(&g).is_some_and(|x| x.phrase.ends_with(&self.toks[i - 1].norm));
        self.mark(i, p.end);
        match host {
            Some(h) if h != g && !bare_number => self.add_companion(&h, &g),
            _ => {}
        }
        Some(p.end)
    }

    /// "stacked two high", "6 high", "in stacks four high": the layers of the current
    /// group's stacks (a count with no unit; "2 m high" is a size). A group with no count
    /// gets stacks × layers. Returns the index after.
    pub(super) fn try_layers(&mut self, i: usize) -> Option<usize> {
        let Some(Subject::Group(g)) = self.subject.clone() else {
            return None;
        };
        let mut j = i;
        let stacked = matches!(self.word(j), "stacked" | "piled" | "stacking");
        if stacked {
            j += 1;
        }
        let (n, len) = crate::quantity::numeral_at(&self.toks, j)?;
        j += len;
        if self.lookup(j, |m| matches!(m, crate::lexicon::Meaning::Unit(_))).is_some() {
            return None;
        }
        if !matches!(self.word(j), "high" | "tall" | "deep" | "layers" | "levels" | "tiers")
            || !(1.0..=100.0).contains(&n)
        {
            return None;
        }
        j += 1;
        if let Some(group) = self.draft.groups.iter_mut().find(|x| x.id == g) {
            group.layers = Some(n.round());
            if group.count.is_none() || !group.plural && group.count == Some(1.0) {
                group.count = Some(n.round() * group.stacks.unwrap_or(1.0));
            } else if group.stacks.is_some_and(|s| s >= 2.0) && group.count == group.stacks {
                // "5 stacks of totes, 6 high": the count so far was the stacks'.
                group.count = Some(n.round() * group.stacks.unwrap_or(1.0));
            }
        }
        self.relate(&g, RelationKind::Stacked { n: None, stacks: None });
        self.mark(i, j);
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
        if let Some(n) = host.strip_prefix("@place:").and_then(|n| n.parse::<f64>().ok()) {
            if let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id) {
                g.count = Some(g.count.unwrap_or(1.0).max(1.0) * n);
                g.plural = true;
            }
            return;
        }
        let mut per = 1.0;
        if let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id) {
            per = g.count.unwrap_or(1.0).max(1.0);
            g.count_rule = Some(CountRule::EachOf { host: host.to_string(), per });
        }
        // each_with pairs one to one; "two stools each" is a count, not a pairing.
        if per <= 1.0 {
            self.relate(host, RelationKind::EachWith { target: id.to_string() });
        }
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
        // "put it all on a table", "everything on the shelf", "all of them by the door":
        // every thing named so far that rests on nothing else.
        let collective = self.collective_pronoun(i);
        if collective.is_none()
            && (!matches!(w, "it" | "they" | "them" | "these" | "those" | "both") || self.subject.is_some())
        {
            return None;
        }
        // At the start of a sentence, or after its imperative verb ("Put them on the bench").
        let mut k = i;
        while k > 0
            && self.toks[k - 1].kind == TokenKind::Word
            && matches!(
                self.word(k - 1),
                "put"
                    | "place"
                    | "set"
                    | "stand"
                    | "move"
                    | "stack"
                    | "arrange"
                    | "position"
                    | "keep"
                    | "leave"
                    | "line"
                    | "then"
                    | "and"
                    | "now"
                    | "please"
            )
        {
            k -= 1;
        }
        let sentence_start = k == 0 || matches!(self.toks[k - 1].kind, TokenKind::Stop);
        if !sentence_start {
            return None;
        }
        if let Some(len) = collective {
            let all = self.free_standing_groups();
            let last = all.last()?.clone();
            self.mark(i, i + len);
            self.list = all.into_iter().map(Subject::Group).collect();
            self.all_of = true;
            self.subject = Some(Subject::Group(last));
            return Some(i + len);
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

    /// The length of a collective pronoun at `i` that stands for everything named so far:
    /// "it all", "them all", "all of it", "all of them", "everything", "all this".
    fn collective_pronoun(&self, i: usize) -> Option<usize> {
        match (self.word(i), self.word(i + 1), self.word(i + 2)) {
            ("it" | "them" | "these" | "those", "all", _) => Some(2),
            ("all", "of", "it" | "them" | "these" | "those" | "this") => Some(3),
            ("all", "this" | "that", _) => Some(2),
            ("everything", _, _) => Some(1),
            _ => None,
        }
    }

    /// The groups named so far that rest on, in or under no other group: what "it all"
    /// moves (the things on them go with them).
    pub(super) fn free_standing_groups(&self) -> Vec<String> {
        let held = |g: &str| {
            self.draft.relations.iter().any(|(s, k)| {
                s == g
                    && matches!(
                        k,
                        RelationKind::On { .. }
                            | RelationKind::Inside { .. }
                            | RelationKind::Under { .. }
                            | RelationKind::SetInto { .. }
                            | RelationKind::Loaded { .. }
                            | RelationKind::FullOf { .. }
                    )
                    && k.targets().iter().all(|t| !t.starts_with('@'))
            })
        };
        self.draft.groups.iter().map(|g| g.id.clone()).filter(|g| !held(g)).collect()
    }
}

fn singular_head(text: &str) -> String {
    text.split_whitespace().last().map(|h| crate::text::singular(&h.to_lowercase())).unwrap_or_default()
}
