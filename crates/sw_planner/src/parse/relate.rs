//! Relation phrases: a cue ("next to", "in two rows", "leaning on the wall"), its
//! targets resolved through the discourse model, and the relation it states about the
//! current subject — an object group or a robot.

use sw_plan::{EndOf, Mount, RelationKind};

use super::{Bare, CountRule, Head, Parser, Phrase, Subject};
use crate::cues::{Cue, cue_at, target_start};
use crate::lexicon::Meaning;
use crate::phrase::PlaceKind;
use crate::said::{Said, is_set_into};
use crate::text::{TokenKind, number_word, singular};

impl Parser<'_> {
    pub(super) fn try_cue(&mut self, i: usize) -> Option<usize> {
        if let Some(next) = self.try_surrounded(i) {
            return Some(next);
        }
        let (mut cue, len) = cue_at(&self.toks, i)?;
        let mut end = i + len;
        // "in 4 rows of 5": five in each row.
        if let Cue::Rows(Some(n)) = cue
            && self.word(end) == "of"
            && let Some((m, l)) = crate::quantity::numeral_at(&self.toks, end + 1)
        {
            cue = Cue::RowsOf(n, m.round().max(1.0) as u32);
            end += 1 + l;
        }
        // "a clear path to the door": the relation is the place's, not the subject's.
        if self.in_place_clause && self.subject.is_none() {
            if cue.takes_target() {
                let j = target_start(&self.toks, end);
                if let Some(p) = self.phrase_at(j, true, Bare::Target).ok().flatten() {
                    end = p.end;
                }
            }
            self.mark(i, end);
            return Some(end);
        }
        let mut targets = Vec::new();
        let mut coordinated: Vec<String> = Vec::new();
        if cue.takes_target() {
            let wanted = if cue == Cue::Between { 2 } else { 1 };
            let mut j = target_start(&self.toks, end);
            // "between them": the two things mentioned before (or the one plural group).
            if cue == Cue::Between && matches!(self.word(j), "them" | "these" | "those") {
                let current = self.subject.clone();
                let before: Vec<String> = self
                    .mentions
                    .iter()
                    .rev()
                    .filter(|m| Some(*m) != current.as_ref())
                    .filter_map(|m| match m {
                        Subject::Group(g) => Some(g.clone()),
                        Subject::Robot(_) => None,
                    })
                    .take(2)
                    .collect();
                let plural_first = before.first().is_some_and(|g| self.group_is_plural(g));
                // "a mixer and a blender on the worktop with the lid beside it, an arm between
                // them": the two said together, not the last two named.
                let together = self.coordination_still_in_view(current.as_ref());
                let targets = match before.as_slice() {
                    [a, ..] if plural_first => Some(vec![a.clone(), a.clone()]),
                    _ if together.is_some() => together,
                    [a, b] => Some(vec![b.clone(), a.clone()]),
                    _ => None,
                };
                if let Some(targets) = targets {
                    self.mark(i, j + 1);
                    match self.subject.clone() {
                        Some(s) => self.apply(&s, cue, targets),
                        None => self.pending.push((cue, targets)),
                    }
                    return Some(j + 1);
                }
            }
            // "at the end of the row", "between the rows": the most recent group in rows.
            // "next to the stack", "behind the pile": the group stacked last.
            let stack = matches!(self.word(j), "stack" | "stacks" | "pile" | "piles");
            if (stack || matches!(self.word(j), "row" | "line" | "rows" | "lines" | "aisle" | "aisles"))
                && matches!(
                    cue,
                    Cue::EndOf(_) | Cue::Between | Cue::InFront | Cue::Behind | Cue::NextTo | Cue::Near | Cue::On
                )
            {
                let row = self.draft.relations.iter().rev().find_map(|(s, k)| {
                    let fits = if stack {
                        matches!(k, RelationKind::Stacked { .. })
                    } else {
                        matches!(k, RelationKind::InRow | RelationKind::InRows { .. } | RelationKind::FacingEachOther)
                    };
                    fits.then(|| s.clone())
                });
                let current = match &self.subject {
                    Some(Subject::Group(g)) => Some(g.clone()),
                    _ => None,
                };
                let row =
                    row.filter(|r| Some(r) != current.as_ref()).or_else(|| self.last_plural_group(current.as_deref()));
                if let Some(row) = row {
                    // "a sink at the end of each row": one for every row of the group.
                    let rows = self.draft.relations.iter().rev().find_map(|(s, k)| match k {
                        RelationKind::InRows { n: Some(n), .. } if *s == row => Some(f64::from(*n)),
                        _ => None,
                    });
                    if j > 0
                        && matches!(self.word(j - 1), "each" | "every")
                        && let (Some(n), Some(Subject::Group(g))) = (rows, self.subject.clone())
                        && let Some(x) = self.draft.groups.iter_mut().find(|x| x.id == g)
                        && x.count.is_none_or(|c| c <= 1.0)
                    {
                        x.count = Some(n);
                        x.plural = true;
                    }
                    self.mark(i, j + 1);
                    let targets = if cue == Cue::Between { vec![row.clone(), row] } else { vec![row] };
                    match self.subject.clone() {
                        Some(s) => self.apply(&s, cue, targets),
                        None => self.pending.push((cue, targets)),
                    }
                    return Some(j + 1);
                }
            }
            // "between the two conveyors": one group, both ends.
            let mut twin = false;
            if cue == Cue::Between && matches!(self.word(j), "two" | "pair") {
                twin = true;
                j += 1;
            }
            // "at each of the desks", "on each of seven tables", "a stool at each station", "a
            // chair in front of every desk", "a lamp on both desks": one for every instance.
            if self.word(j) == "of" && j > 0 && matches!(self.word(j - 1), "each" | "every" | "one" | "both") {
                self.used[j] = true;
                j = target_start(&self.toks, j + 1);
            }
            let distributive = self.each_before(j) || matches!(self.word(j), "each" | "both");
            // "a Panda on each bench", "two tables, a UR5e at each", "an arm at every one of
            // the 4 stations": one robot (or the count said) for every instance.
            // A verb's object is not a place: "loading both", "tending each" are one robot's
            // work on all of them.
            let place = cue != Cue::Tend || self.word(i) == "at";
            if distributive
                && place
                && matches!(cue, Cue::Tend | Cue::NextTo | Cue::InFront | Cue::On | Cue::Near | Cue::Behind)
                && let Some(Subject::Robot(r)) = self.subject.clone()
            {
                let (target, next) = self.distributed_over(j, &cue)?;
                if !target.starts_with('@') {
                    self.mark(i, next);
                    let hosts = self.group(&target).and_then(|g| g.count).filter(|c| *c > 1.0);
                    if let (Some(n), Some(robot)) = (hosts, self.draft.robots.get_mut(r)) {
                        robot.count = Some(robot.count.unwrap_or(1.0) * n);
                        robot.plural = true;
                        self.relate(&target, RelationKind::EachWith { target: format!("@robot:{r}") });
                    }
                    self.apply(&Subject::Robot(r), cue, vec![target]);
                    return Some(next);
                }
            }
            if distributive
                && matches!(cue, Cue::Tend | Cue::NextTo | Cue::InFront | Cue::On | Cue::Near | Cue::In | Cue::Behind)
                && let Some(Subject::Group(g)) = self.subject.clone()
            {
                let (target, next) = self.distributed_over(j, &cue)?;
                if !target.starts_with('@') && target != g {
                    self.mark(i, next);
                    self.add_companion(&target, &g);
                    return Some(next);
                }
            }
            while targets.len() < wanted {
                let (target, next) = self.target_at(j, &cue)?;
                targets.push(target);
                j = next;
                if twin {
                    let t = targets[0].clone();
                    targets.push(t);
                    break;
                }
                if targets.len() < wanted {
                    if !matches!(self.word(j), "and" | "&") {
                        if cue == Cue::Between && targets.len() == 1 {
                            // "between the shelves": both ends in one plural group.
                            let t = targets[0].clone();
                            targets.push(t);
                            break;
                        }
                        return None;
                    }
                    j = target_start(&self.toks, j + 1);
                }
            }
            // "next to the lathe and the mill", "between the sink and the hob, facing the
            // door and the window": a definite phrase coordinated with the target, where the
            // clause ends after it, is another target of the same relation.
            if wanted == 1 && !twin {
                while let Some((t, next)) = {
                    let taken: Vec<String> = targets.iter().chain(&coordinated).cloned().collect();
                    self.coordinated_target(j, &cue, &taken)
                } {
                    coordinated.push(t);
                    j = next;
                }
            }
            end = j;
        }
        self.mark(i, end);
        match self.subject.clone() {
            Some(s) => {
                self.apply(&s, cue.clone(), targets.clone());
                for t in &coordinated {
                    self.apply(&s, cue.clone(), vec![t.clone()]);
                }
                // "a white mug and a red mug to the right of the caddy", "a sofa and two
                // armchairs around a table": a relation after phrases joined by "and" is
                // said of each of them.
                // Only where the relation follows the phrases directly ("…, clear them up into
                // the box" says nothing of the candles listed before).
                let follows = self.last_phrase.as_ref().is_some_and(|(e, g)| *e == i && s == Subject::Group(g.clone()));
                // Not to a place of the room ("… and an air compressor in the corner"): a
                // corner or a wall spot holds the thing named last, as the pieces of "on".
                let room_place = targets.is_empty() || targets.iter().any(|t| t.starts_with('@'));
                if follows && cue != Cue::On && !matches!(cue, Cue::Between) && !room_place {
                    for c in self.conjuncts_of(&s) {
                        if !targets.contains(&c) && !coordinated.contains(&c) {
                            self.apply(&Subject::Group(c.clone()), cue.clone(), targets.clone());
                            for t in &coordinated {
                                self.apply(&Subject::Group(c.clone()), cue.clone(), vec![t.clone()]);
                            }
                        }
                    }
                }
                // "three mugs and a bowl on the table": small things listed together rest
                // on the same thing; "a table and four chairs in a row" both stand so.
                // "a hob with a kettle and two mugs next to it": whatever the "with" lists
                // stands so to its host.
                let to_with_host = std::mem::take(&mut self.it_is_with_host);
                let all_of = std::mem::take(&mut self.all_of);
                if (cue == Cue::On || to_with_host || all_of) && targets.iter().all(|t| !t.starts_with('@')) {
                    let others: Vec<String> = self
                        .list
                        .iter()
                        .filter(|m| **m != s)
                        .filter_map(|m| match m {
                            Subject::Group(g) => Some(g.clone()),
                            Subject::Robot(_) => None,
                        })
                        .collect();
                    for g in others {
                        // Already on, in, under or set into something: it stays there.
                        let has_on = self.draft.relations.iter().any(|(x, k)| {
                            x == &g
                                && matches!(
                                    k,
                                    RelationKind::On { .. }
                                        | RelationKind::Inside { .. }
                                        | RelationKind::Under { .. }
                                        | RelationKind::SetInto { .. }
                                )
                        });
                        let small = self.group_is_small(&g) && !has_on;
                        if (small || all_of || (to_with_host && cue != Cue::On)) && !targets.contains(&g) {
                            self.apply(&Subject::Group(g), cue.clone(), targets.clone());
                        }
                    }
                }
                // What the relation was said of together, for a later "between them".
                let together: Vec<String> = self
                    .list
                    .iter()
                    .chain(std::iter::once(&s))
                    .filter_map(|m| match m {
                        Subject::Group(g) if !targets.contains(g) && !coordinated.contains(g) => Some(g.clone()),
                        _ => None,
                    })
                    .fold(Vec::new(), |mut v, g| {
                        if !v.contains(&g) {
                            v.push(g);
                        }
                        v
                    });
                if together.len() >= 2 {
                    self.last_coordination = together;
                }
                self.list.clear();
                self.pending.clear();
            }
            None => {
                for t in coordinated {
                    self.pending.push((cue.clone(), vec![t]));
                }
                self.pending.push((cue, targets));
            }
        }
        Some(end)
    }

    /// The first and last of the things last said together of one relation, when nothing
    /// named since stands apart from them (what came after is placed by them or they on
    /// it): the antecedent of a plural "them" that no plural group is nearer to.
    fn coordination_still_in_view(&self, current: Option<&Subject>) -> Option<Vec<String>> {
        let members = &self.last_coordination;
        let (a, b) = (members.first()?, members.last()?);
        if members.len() < 2 || current.is_some_and(|c| members.iter().any(|m| *c == Subject::Group(m.clone()))) {
            return None;
        }
        let last_seen = self.mentions.iter().rposition(|m| matches!(m, Subject::Group(g) if members.contains(g)))?;
        let related = |g: &str| {
            self.draft.relations.iter().any(|(s, k)| {
                (s == g && k.targets().iter().any(|t| members.iter().any(|m| m == t)))
                    || (members.contains(s) && k.targets().contains(&g))
            })
        };
        let apart = self.mentions[last_seen + 1..].iter().any(|m| match m {
            Subject::Group(g) => Some(m) != current && !members.contains(g) && !related(g),
            Subject::Robot(_) => false,
        });
        (!apart).then(|| vec![a.clone(), b.clone()])
    }

    /// The groups joined to the subject `s` by a bare "and", still in the clause's list.
    fn conjuncts_of(&self, s: &Subject) -> Vec<String> {
        let Subject::Group(g) = s else { return Vec::new() };
        let in_list = |x: &String| self.list.iter().any(|m| *m == Subject::Group(x.clone()));
        let mut out: Vec<String> = Vec::new();
        let mut cur = g.clone();
        while let Some((a, _)) = self.and_pairs.iter().rev().find(|(_, b)| *b == cur) {
            if !in_list(a) || out.contains(a) || a == g {
                break;
            }
            out.push(a.clone());
            cur = a.clone();
        }
        out
    }

    /// The target after "and" at `j` when it is coordinated with the one before: a definite
    /// phrase ("the mill", "its base") naming a thing, after which the clause ends (a comma,
    /// a full stop, the end, or another "and"). An indefinite one ("and a chair") starts a
    /// new thing.
    fn coordinated_target(&mut self, j: usize, cue: &Cue, taken: &[String]) -> Option<(String, usize)> {
        if !matches!(self.word(j), "and" | "&") {
            return None;
        }
        let k = target_start(&self.toks, j + 1);
        if k == j + 1 || !self.is_definite(k) {
            return None;
        }
        let p = self.phrase_at(k, true, Bare::Target).ok().flatten()?;
        if !matches!(p.head, Head::Known(Meaning::Category(_)) | Head::Unknown(_)) {
            return None;
        }
        let ends = self.toks.get(p.end).is_none_or(|t| matches!(t.kind, TokenKind::Comma | TokenKind::Stop))
            || matches!(self.word(p.end), "and" | "&");
        if !ends {
            return None;
        }
        let subject = match &self.subject {
            Some(Subject::Group(g)) => Some(g.clone()),
            _ => None,
        };
        let (mut t, next) = self.target_at(k, cue)?;
        // Coordinated phrases name different things: "the locker and the cabinet" is not
        // the locker twice, though a locker is a kind of cabinet.
        if taken.contains(&t)
            && let Head::Known(Meaning::Category(cat)) = &p.head
        {
            t = self.new_group(Some(cat), cat.replace('_', " "), &p, p.explicit);
            if let Some(g) = self.draft.groups.last_mut() {
                g.accommodated = true;
            }
        }
        if t.starts_with('@') || Some(&t) == subject.as_ref() || taken.contains(&t) {
            return None;
        }
        self.mark(j, next);
        Some((t, next))
    }

    /// "a robot surrounded by safety screens", "a press enclosed by fences": what follows
    /// "by" stands around what came before — "around" turned round. The pieces are a group
    /// of their own (a plural without a count gets the usual default, not two).
    fn try_surrounded(&mut self, i: usize) -> Option<usize> {
        // "a desk flanked by two chairs": the chairs on either side of the desk.
        let cue = match self.word(i) {
            "surrounded" | "enclosed" | "encircled" | "ringed" | "fenced" => Cue::Around,
            "flanked" => Cue::EachSide,
            _ => return None,
        };
        if !matches!(self.word(i + 1), "by" | "with") {
            return None;
        }
        let target = match self.subject.clone()? {
            Subject::Group(g) => g,
            Subject::Robot(r) => format!("@robot:{r}"),
        };
        let j = target_start(&self.toks, i + 2);
        self.taking_pieces = true;
        let taken = self.target_at(j, &cue);
        self.taking_pieces = false;
        let (pieces, next) = taken?;
        if pieces.starts_with('@') || pieces == target {
            return None;
        }
        self.mark(i, next);
        self.apply(&Subject::Group(pieces.clone()), cue, vec![target]);
        // "a UR10e on a pedestal surrounded by 4 bins on the floor": a placement right after
        // the pieces is theirs when the robot's own stand was already said.
        let mounted = match self.subject.clone() {
            Some(Subject::Robot(r)) => self.draft.robots.get(r).is_some_and(|x| !matches!(x.mount, Mount::Auto)),
            _ => false,
        };
        if mounted && cue_at(&self.toks, next).is_some() {
            self.subject = Some(Subject::Group(pieces));
        }
        Some(next)
    }

    /// "a bin at the end of each of two aisles": one at each of `count` places.
    fn one_at_each_place(&mut self, count: Option<f64>, at: usize) {
        if let (Some(n), true, Some(Subject::Group(g))) = (count, self.each_before(at), self.subject.clone())
            && n > 1.0
            && let Some(group) = self.draft.groups.iter_mut().find(|x| x.id == g)
            && group.count_rule.is_none()
        {
            group.count = Some(group.count.unwrap_or(1.0) * n);
            group.plural = true;
        }
    }

    /// The group a distributive target at `j` names ("each of the desks", "every bench"), or
    /// with the noun left out ("on each", "on both") the plural group named before.
    fn distributed_over(&mut self, j: usize, cue: &Cue) -> Option<(String, usize)> {
        let pronoun = j > 0
            && matches!(self.word(j - 1), "each" | "both" | "all")
            && self.phrase_at(j, true, Bare::Target).ok().flatten().is_none();
        if !pronoun {
            return self.target_at(j, cue);
        }
        match self.resolve_pronoun("they") {
            Some(Subject::Group(h)) => Some((h, j)),
            _ => None,
        }
    }

    /// True when the target starting at `j` is distributive: "each", "every", "both", "each
    /// of the", "every one of".
    fn each_before(&self, j: usize) -> bool {
        let mut k = j;
        for _ in 0..4 {
            if k == 0 {
                return false;
            }
            k -= 1;
            match self.word(k) {
                "each" | "every" | "both" => return true,
                "of" | "the" | "these" | "those" | "one" | "its" | "their" | "a" | "an" => {}
                _ => return false,
            }
        }
        false
    }

    fn group_is_plural(&self, id: &str) -> bool {
        self.group(id).is_some_and(|g| g.plural || g.count.is_some_and(|c| c > 1.0))
    }

    /// The most recent plural group other than `except`.
    fn last_plural_group(&self, except: Option<&str>) -> Option<String> {
        self.draft
            .groups
            .iter()
            .rev()
            .find(|g| Some(g.id.as_str()) != except && self.group_is_plural(&g.id))
            .map(|g| g.id.clone())
    }

    /// The group (or robot, as `@robot:N`) a relation points at: an earlier group or
    /// robot the phrase refers to, "it"/"them", "the cell", or — when nothing was
    /// introduced — a new group (noted when the phrase was definite).
    fn target_at(&mut self, j: usize, cue: &Cue) -> Option<(String, usize)> {
        let found = self.target_at_inner(j, cue);
        if let Some((t, _)) = &found
            && !t.starts_with('@')
        {
            self.worked_on(&t.clone());
        }
        found
    }

    fn target_at_inner(&mut self, j: usize, cue: &Cue) -> Option<(String, usize)> {
        let w = self.word(j);
        if matches!(w, "it" | "them" | "this" | "that" | "these" | "those" | "one" | "each" | "both" | "all") {
            // "each with a stool and a vice on it": it is each host.
            // "them" is the host only when there are several of it ("two Pandas on a table
            // with a cube between them": the Pandas).
            // "a hob with a kettle and two mugs next to it": it is the thing the "with" is on.
            let with_it = self.with_it.clone().filter(|_| w == "it");
            if let Some(host) = self.each_host.clone().or_else(|| self.with_host.clone()).or(with_it.clone())
                && self.subject != Some(Subject::Group(host.clone()))
                && matches!(w, "it" | "them" | "one" | "each")
                && (w != "them" || self.group_is_plural(&host) || self.each_host.is_some())
            {
                self.it_is_with_host = with_it.as_ref() == Some(&host);
                return Some((host, j + 1));
            }
            // "two bowls and a tray on a table, arm mounted on it": what an arm stands on is a
            // work surface, the latest one named (a target included).
            if w == "it"
                && *cue == Cue::On
                && matches!(self.subject, Some(Subject::Robot(_)))
                && let Some(surface) =
                    self.draft.groups.iter().rev().map(|g| g.id.clone()).find(|g| self.group_is_work_surface(g))
            {
                return Some((surface, j + 1));
            }
            let previous = self.resolve_pronoun(w)?;
            return Some((
                match previous {
                    Subject::Group(g) => g,
                    Subject::Robot(r) => format!("@robot:{r}"),
                },
                j + 1,
            ));
        }
        // Robot mounts name things that are not scene objects: pedestals, carts, the floor.
        if let Some(Subject::Robot(_)) = &self.subject
            && *cue == Cue::On
            && let Some(m) = self.mount_word(j)
        {
            return Some(m);
        }
        // "a TV on a stand", "a bench grinder on a stand": a support named only by a word
        // for supports is the kind that carries that thing (a TV stand), else a stand.
        if *cue == Cue::On
            && let Some(Subject::Group(g)) = self.subject.clone()
            && let Some(found) = self.support_by_load(j, &g)
        {
            return Some(found);
        }
        let definite = self.is_definite(j);
        let p = self.phrase_at(j, true, Bare::Target).ok().flatten()?;
        // "the edge of the table", "the far end of the conveyor", "the middle of the room":
        // a place of a thing; the relation is to the thing, qualified by the place.
        if let Head::Place(kind) = p.head {
            if self.word(p.end) == "of" {
                let k = target_start(&self.toks, p.end + 1);
                // "at the end of each of two aisles".
                let k = if self.word(k) == "of" { target_start(&self.toks, k + 1) } else { k };
                if let Some(q) = self.phrase_at(k, true, Bare::Target).ok().flatten()
                    && let Head::Place(inner) = q.head
                {
                    // A place of a place ("the end of the aisle"): no object, the outer kind;
                    // "at the end of each of two aisles" is one at each.
                    self.mark(j, q.end);
                    self.place_of = Some((kind, None));
                    let _ = inner;
                    self.one_at_each_place(q.count, k);
                    return Some((String::from("@place"), q.end));
                }
                let room = self.phrase_at(k, true, Bare::Target).ok().flatten().filter(|q| {
                    matches!(q.head, Head::Known(Meaning::Room(_) | Meaning::RoomWord | Meaning::RoomAisle(_)))
                });
                if let Some(q) = room {
                    self.mark(j, q.end);
                    self.place_of = Some((kind, None));
                    return Some((String::from("@room"), q.end));
                }
                let (inner, end) = self.target_at_inner(k, cue)?;
                // "a locker at the foot of each bunk", "a bin at the end of every bench": one
                // at each of them.
                let each = (j + 1..k).any(|x| matches!(self.word(x), "each" | "every"))
                    || (k > 0 && matches!(self.word(k - 1), "each" | "every"));
                if each
                    && !inner.starts_with('@')
                    && let Some(Subject::Group(g)) = self.subject.clone()
                    && g != inner
                    && let Some(x) = self.draft.groups.iter_mut().find(|x| x.id == g)
                    && x.count_rule.is_none()
                {
                    let per = x.count.unwrap_or(1.0).max(1.0);
                    x.count_rule = Some(CountRule::EachOf { host: inner.clone(), per });
                }
                self.mark(j, end);
                self.place_of = Some((kind, Some(inner.clone())));
                return Some((inner, end));
            }
            // "in the bottom drawer", "under the shelf": a part named with a thing before is
            // a place of that thing.
            // "the bottom drawer", "the top shelf": which of the parts, read as one.
            if matches!(
                kind,
                PlaceKind::Top | PlaceKind::Bottom | PlaceKind::Middle | PlaceKind::Front | PlaceKind::Back
            ) && let Some(q) = self.phrase_at(p.end, true, Bare::Target).ok().flatten()
                && let Some((owner, place)) = self.owner_of_part(&q)
            {
                self.mark(j, q.end);
                self.place_of = Some((place, Some(owner.clone())));
                return Some((owner, q.end));
            }
            // "on the table top", "at the bench end": a place of the thing its modifier names.
            if let Some(thing) = self.thing_before_place(j, p.end) {
                self.mark(j, p.end);
                self.place_of = Some((kind, Some(thing.clone())));
                return Some((thing, p.end));
            }
            if let Some((owner, place)) = self.owner_of_part(&p) {
                self.mark(j, p.end);
                self.place_of = Some((place, Some(owner.clone())));
                return Some((owner, p.end));
            }
            // "a place, not an object": a bare place ("near the window") is where the room's
            // walls are.
            self.one_at_each_place(p.count, j);
            self.mark(j, p.end);
            self.place_of = Some((kind, None));
            return Some((String::from("@place"), p.end));
        }
        // "on the table top", "on the tabletop": the top of a table, not the room's kind.
        if *cue == Cue::On && definite && matches!(p.head, Head::Known(Meaning::Room(sw_plan::RoomKind::Tabletop))) {
            let table = match self.draft.groups.iter().rev().find(|g| self.group_is_work_surface(&g.id)) {
                Some(g) => g.id.clone(),
                None => {
                    let mut q = p.clone();
                    q.head = Head::Known(Meaning::Category("table"));
                    let id = self.new_group(Some("table"), "table".into(), &q, q.explicit);
                    if let Some(g) = self.draft.groups.last_mut() {
                        g.accommodated = true;
                    }
                    id
                }
            };
            self.mark(j, p.end);
            return Some((table, p.end));
        }
        let indefinite = p.quantity.is_some() || (j > 0 && matches!(self.word(j - 1), "a" | "an" | "another"));
        if definite
            && !indefinite
            && let Some((owner, place)) = self.owner_of_part(&p)
        {
            self.mark(j, p.end);
            self.place_of = Some((place, Some(owner.clone())));
            return Some((owner, p.end));
        }
        let end = p.end;
        // A new group for a plural target without a count ("next to tables") gets two;
        // the pieces of a turned-round relation ("surrounded by screens") the usual default.
        let mut p2 = p.clone();
        if p2.count.is_none() && p2.plural && !self.taking_pieces {
            p2.count = Some(2.0);
        }
        let raw_head = p.text.split_whitespace().last().map(|h| singular(&h.to_lowercase())).unwrap_or_default();
        let id = match &p.head {
            // "the cell", "the work cell": the arm's work, or the arm.
            Head::Known(Meaning::RoomWord) if p.text.to_lowercase().contains("cell") && *cue != Cue::In => {
                self.resolve_cell()?
            }
            Head::Known(Meaning::Robot(word)) => {
                let generic = !word.exact;
                let r = self.resolve_robot(word.wants, word.kind, generic)?;
                format!("@robot:{r}")
            }
            // An indefinite phrase ("a filing cabinet") names a new thing unless a group of
            // its very category exists; only a definite one ("the cabinet") refers by head.
            // By its head word only when the phrase is that word alone ("the bench" for a
            // workbench; "the filing cabinet" is no cabinet named before).
            Head::Known(Meaning::Category(cat)) => match if definite || !indefinite {
                let generic = p.text.split_whitespace().filter(|w| number_word(w).is_none()).count() <= 1;
                if generic {
                    // Never the subject itself under another name ("a locker on either side of
                    // the cabinet").
                    let subject = match &self.subject {
                        Some(Subject::Group(g)) => Some(g.clone()),
                        _ => None,
                    };
                    self.resolve_group(Some(cat), &raw_head).filter(|g| {
                        Some(g) != subject.as_ref() || self.group(g).is_some_and(|x| x.category == Some(*cat))
                    })
                } else {
                    self.draft.groups.iter().rev().find(|g| g.category == Some(*cat)).map(|g| g.id.clone())
                }
            } else {
                // "a red cube on a green cube": another one, not the subject itself.
                let subject = match &self.subject {
                    Some(Subject::Group(g)) => Some(g.clone()),
                    _ => None,
                };
                self.draft
                    .groups
                    .iter()
                    .rev()
                    .find(|g| g.category == Some(*cat) && Some(&g.id) != subject.as_ref())
                    .map(|g| g.id.clone())
            } {
                Some(g) => g,
                None => {
                    let id = self.new_group(Some(cat), cat.replace('_', " "), &p2, p.explicit);
                    if definite {
                        if let Some(g) = self.draft.groups.last_mut() {
                            g.accommodated = true;
                        }
                        if !matches!(cue, Cue::On | Cue::Under) {
                            self.note_accommodated(&p.text, cat);
                        }
                    }
                    id
                }
            },
            Head::Unknown(label) if self.group_by_head(label).is_some() => {
                self.group_by_head(label).unwrap_or_default()
            }
            Head::Unknown(label) if self.category_by_head(label).is_some() => {
                let cat = self.category_by_head(label).unwrap_or("proxy");
                match self.resolve_group(Some(cat), label) {
                    Some(g) => g,
                    None => {
                        self.draft.approximated.push(sw_plan::Approximation {
                            text: label.clone(),
                            became: cat.to_string(),
                            reason: format!("read '{label}' as {}", cat.replace('_', " ")),
                        });
                        self.new_group(Some(cat), cat.replace('_', " "), &p2, p.explicit)
                    }
                }
            }
            Head::Unknown(label) => match self.resolve_group(None, label) {
                Some(g) => g,
                None => self.new_group(None, label.clone(), &p2, p.explicit),
            },
            _ => return None,
        };
        self.mark(j, end);
        Some((id, end))
    }

    /// "a pedestal", "a mobile cart", "the floor" after a robot's "on".
    fn mount_word(&self, j: usize) -> Option<(String, usize)> {
        let mount_words: &[(&str, &str)] = &[
            ("pedestal", "pedestal"),
            ("stand", "pedestal"),
            ("post", "pedestal"),
            ("column", "pedestal"),
            ("base", "pedestal"),
            ("riser", "pedestal"),
            ("plinth", "pedestal"),
            ("mobile cart", "mobile"),
            ("cart", "mobile"),
            // An arm on a base that drives is a mobile manipulator.
            ("mobile base", "manipulator"),
            ("mobile platform", "manipulator"),
            ("mobile robot", "manipulator"),
            ("wheeled base", "manipulator"),
            ("agv", "manipulator"),
            ("amr", "manipulator"),
            ("floor", "floor"),
            ("ground", "floor"),
        ];
        let mut k = j;
        // "a 60 cm pedestal": its height, read with the phrase's sizes.
        if let Some((_, len, true)) = self.phrases().length_at(k) {
            k += len;
        }
        while matches!(
            self.word(k),
            "steel" | "metal" | "small" | "large" | "low" | "high" | "tall" | "short" | "sturdy" | "fixed" | "wheeled"
        ) {
            k += 1;
        }
        for (phrase, kind) in mount_words {
            let n = phrase.split(' ').count();
            let got: Vec<String> = (k..k + n).map(|x| singular(self.word(x))).collect();
            if got.join(" ") == *phrase {
                return Some((format!("@mount:{kind}"), k + n));
            }
        }
        None
    }

    pub(super) fn apply_pending(&mut self) {
        let Some(s) = self.subject.clone() else {
            return;
        };
        // A leading relation ("On the bench, a UR5e and two bins") covers the whole list.
        for (cue, targets) in self.pending.clone() {
            self.apply(&s, cue, targets);
        }
    }

    pub(super) fn apply(&mut self, subject: &Subject, cue: Cue, targets: Vec<String>) {
        // A relation closes the "with" list: a later "it" is no longer its host.
        let listed_with = self.with_it.take();
        // A cue whose target was a place ("on the edge of the table", "at the end of the
        // conveyor", "in the corners of the room") says something else.
        if let Some((place, of)) = self.place_of.take()
            && let Some((cue, targets)) = self.placed(&cue, place, of, &targets)
        {
            return self.apply(subject, cue, targets);
        }
        if targets.iter().any(|t| t.starts_with("@place") || t.starts_with("@room")) {
            return;
        }
        match subject {
            Subject::Robot(idx) => self.apply_to_robot(*idx, cue, targets),
            Subject::Group(g) => {
                // "a table next to it" where "it" is an arm: the arm works at the table.
                if let Some(r) =
                    targets.iter().find_map(|t| t.strip_prefix("@robot:")).and_then(|r| r.parse::<usize>().ok())
                    && matches!(cue, Cue::NextTo | Cue::Near | Cue::InFront)
                    && self.group_is_work(g)
                    && let Some(robot) = self.draft.robots.get_mut(r)
                    && robot.word.kind == sw_robots::RobotKind::Arm
                {
                    robot.near = Some(g.clone());
                    return;
                }
                // A place noun's scope is the nearest host that holds the thing: "a desk with
                // a caddy in the middle" is the desk's middle, "a lamp in the corner" of the
                // bench it was listed on is that bench's corner. A small thing with no host
                // said is in the middle of the last work surface named, not of the room.
                if let Some(host) = self.host_of_place(g, &cue, &targets, listed_with.as_deref()) {
                    let cue = if cue == Cue::Center { Cue::On } else { Cue::OnEdge };
                    return self.apply(subject, cue, vec![host]);
                }
                // "a mug on the table next to the door": placement words after an "on"
                // describe where the table stands.
                let floor_level = matches!(
                    cue,
                    Cue::Wall(_)
                        | Cue::Door
                        | Cue::Corner(_)
                        | Cue::End(_)
                        | Cue::EndOf(_)
                        | Cue::Center
                        | Cue::NextTo
                        | Cue::Near
                        | Cue::InFront
                        | Cue::Behind
                );
                let host = self.on_host.iter().rev().find(|(s, _)| s == g).map(|(_, h)| h.clone());
                let subject = match host {
                    Some(h) if floor_level && !targets.contains(&h) => h,
                    _ => g.clone(),
                };
                let kind = match (cue, targets.as_slice()) {
                    (Cue::On, [t]) if t.starts_with("@robot:") => return,
                    (Cue::On, [t]) => {
                        self.on_host.push((subject.clone(), t.clone()));
                        RelationKind::On { target: t.clone() }
                    }
                    (Cue::Under, [t]) => RelationKind::Under { target: t.clone() },
                    (Cue::NextTo, [t]) => RelationKind::NextTo { target: t.clone() },
                    (Cue::Near, [t]) => RelationKind::Near { target: t.clone() },
                    (Cue::InFront, [t]) => RelationKind::InFrontOf { target: t.clone() },
                    (Cue::Behind, [t]) => RelationKind::Behind { target: t.clone() },
                    (Cue::Around, [t]) => RelationKind::Around { target: t.clone() },
                    (Cue::EndOf(end), [t]) if !self.group_is_plural_row(t) || end.is_some() => match end {
                        Some(EndOf::Both) => {
                            self.one_each_side(&subject);
                            // "parts bins at both ends": one at each end.
                            if let Some(g) = self.draft.groups.iter_mut().find(|x| x.id == subject)
                                && g.count.is_none()
                                && g.count_rule.is_none()
                            {
                                g.count = Some(2.0);
                            }
                            Said::AtEnd(t.clone(), EndOf::Both).kind()
                        }
                        Some(e) => Said::AtEnd(t.clone(), e).kind(),
                        None => Said::AtEndOf(t.clone()).kind(),
                    },
                    (Cue::EndOf(_), [t]) => RelationKind::AtEndOfRow { target: t.clone() },
                    (Cue::Tend, [t]) if self.group_is_seating(&subject) => {
                        RelationKind::InFrontOf { target: t.clone() }
                    }
                    (Cue::Tend, [t]) => RelationKind::NextTo { target: t.clone() },
                    (Cue::In, [t]) => {
                        let (sc, tc) = (self.category_of(&subject), self.category_of(t));
                        if is_set_into(sc, tc) { Said::SetInto(t.clone()) } else { Said::Inside(t.clone()) }.kind()
                    }
                    (Cue::EachSide, [t]) => {
                        self.one_each_side(&subject);
                        Said::OnEachSideOf(t.clone()).kind()
                    }
                    (Cue::FacingTarget, [t]) => Said::Facing(t.clone()).kind(),
                    (Cue::OnEdge, [t]) => Said::OnEdgeOf(t.clone()).kind(),
                    (Cue::Above, [t]) => RelationKind::Near { target: t.clone() },
                    (Cue::Between, [a, b]) => RelationKind::Between { first: a.clone(), second: b.clone() },
                    (Cue::Row, _) => RelationKind::InRow,
                    (Cue::Rows(n), _) => RelationKind::InRows { n, m: None },
                    (Cue::RowsOf(n, m), _) => RelationKind::InRows { n: Some(n), m: Some(m) },
                    (Cue::Aisles, _) => RelationKind::InAisles,
                    // "a chair on either side": of the thing named before.
                    (Cue::Facing, []) if !self.group_is_plural(&subject) => {
                        // The thing named before, or what that was placed by ("a bed, a
                        // stand beside it, a chair on either side": of the bed).
                        let other = self.draft.groups.iter().rev().find(|x| x.id != subject).map(|x| x.id.clone());
                        let other = other.map(|o| {
                            self.draft
                                .relations
                                .iter()
                                .rev()
                                .find(|(s, k)| {
                                    s == &o && matches!(k, RelationKind::NextTo { .. } | RelationKind::Near { .. })
                                })
                                .and_then(|(_, k)| k.targets().first().map(|t| t.to_string()))
                                .filter(|t| t != &subject)
                                .unwrap_or(o)
                        });
                        match other {
                            Some(t) => {
                                self.one_each_side(&subject);
                                Said::OnEachSideOf(t).kind()
                            }
                            None => return,
                        }
                    }
                    (Cue::Facing, _) => RelationKind::FacingEachOther,
                    // "each bench with a sink at one end": the bench's end, not the room's.
                    (Cue::End(None), _)
                        if self.each_host.as_ref().is_some_and(|h| !h.starts_with('@') && *h != subject) =>
                    {
                        Said::AtEndOf(self.each_host.clone().unwrap_or_default()).kind()
                    }
                    (Cue::End(w), _) => RelationKind::AtEnd { wall: w },
                    (Cue::Corner(c), _) => RelationKind::InCorner { corner: c },
                    (Cue::Center, _) => RelationKind::InCenter,
                    (Cue::Door, _) => RelationKind::NearDoor,
                    (Cue::Wall(w), _) => RelationKind::AgainstWall { wall: w },
                    (Cue::TwoWalls, _) => RelationKind::OnTwoWalls,
                    (Cue::OppositeWalls { long, per_wall }, _) => {
                        // "one bench along each long wall": one on each of the two.
                        if per_wall
                            && let Some(g) = self.draft.groups.iter_mut().find(|x| x.id == subject)
                            && g.count_rule.is_none()
                            && !g.plural
                            && g.count.is_some_and(|c| c <= 1.0)
                        {
                            g.count = Some(2.0);
                            g.plural = true;
                        }
                        RelationKind::OnOppositeWalls { long }
                    }
                    (Cue::Corners(n), _) => {
                        // "a fan in each corner": one in every corner.
                        if let Some(n) = n
                            && let Some(g) = self.draft.groups.iter_mut().find(|x| x.id == subject)
                            && g.count_rule.is_none()
                            && g.count.is_some_and(|c| c <= 1.0)
                        {
                            g.count = Some(f64::from(n));
                            g.plural = true;
                        }
                        RelationKind::InCorners
                    }

                    (Cue::BackToBack, _) => RelationKind::BackToBack,
                    (Cue::Leaning(w), _) => RelationKind::Leaning { wall: w },
                    (Cue::Stacked, _) => RelationKind::Stacked { n: None, stacks: None },
                    // "a bin on the floor": nothing to keep but that it stays there.
                    (Cue::Floor, _) => {
                        if !self.draft.on_floor.contains(&subject) {
                            self.draft.on_floor.push(subject.clone());
                        }
                        return;
                    }
                    _ => return,
                };
                if kind.targets().contains(&subject.as_str()) {
                    return;
                }
                // A stated placement replaces the "on" a "with" implied, and ends that list.
                let placement = !kind.is_group_formation() && !matches!(kind, RelationKind::EachWith { .. });
                if placement && let Some(k) = self.implicit_on.iter().position(|(s, _)| s == &subject) {
                    let (s, host) = self.implicit_on.remove(k);
                    if kind != (RelationKind::On { target: host.clone() }) {
                        self.draft
                            .relations
                            .retain(|(x, r)| !(x == &s && *r == RelationKind::On { target: host.clone() }));
                        self.on_host.retain(|(x, h)| !(x == &s && h == &host));
                        self.with_host = None;
                    }
                }
                self.relate(&subject, kind);
            }
        }
    }

    /// The cue a place qualifies: (cue, place, the thing it is a place of, targets) to what
    /// is said of the subject. `None` when the place changes nothing.
    fn placed(
        &self,
        cue: &Cue,
        place: PlaceKind,
        of: Option<String>,
        targets: &[String],
    ) -> Option<(Cue, Vec<String>)> {
        let room = targets.first().is_some_and(|t| t == "@room");
        let thing = of.map(|t| vec![t]);
        Some(match (place, thing) {
            (PlaceKind::Edge, Some(t)) => (Cue::OnEdge, t),
            // A part of a thing: in, on or under a shelf, a drawer, a compartment is inside
            // the thing; on its lid or seat is on it; by it is by the thing.
            (PlaceKind::Part, Some(t)) if matches!(cue, Cue::On | Cue::In | Cue::Under) => (Cue::In, t),
            (PlaceKind::Part, Some(t)) => (cue.clone(), t),
            // "bolted to one of the ends of the table", "on the corner of the desk".
            (PlaceKind::End | PlaceKind::Start | PlaceKind::Corner, Some(t)) if *cue == Cue::On => (Cue::OnEdge, t),
            (PlaceKind::Start, Some(t)) => (Cue::EndOf(Some(EndOf::Start)), t),
            (PlaceKind::End, Some(t)) => (Cue::EndOf(None), t),
            (PlaceKind::End | PlaceKind::Start, None) if room => (Cue::End(None), Vec::new()),
            (PlaceKind::Side, Some(t)) => (Cue::NextTo, t),
            (PlaceKind::Front, Some(t)) => (Cue::InFront, t),
            (PlaceKind::Back, Some(t)) => (Cue::Behind, t),
            (PlaceKind::Top | PlaceKind::Bottom, Some(t)) => (Cue::On, t),
            (PlaceKind::Middle, Some(t)) if matches!(cue, Cue::On | Cue::In) => (Cue::On, t),
            (PlaceKind::Middle | PlaceKind::Corner, Some(t)) => (Cue::Near, t),
            (PlaceKind::Middle, None) => (Cue::Center, Vec::new()),
            (PlaceKind::Corner, None) => (Cue::Corner(None), Vec::new()),
            (PlaceKind::Wall, None) => (Cue::Wall(None), Vec::new()),
            // "a counter along the back", "a till at the front": of the room.
            (PlaceKind::Back, None) => (Cue::Wall(Some(sw_plan::Wall::North)), Vec::new()),
            (PlaceKind::Front, None) => (Cue::Wall(Some(sw_plan::Wall::South)), Vec::new()),
            (PlaceKind::Door, None) => (Cue::Door, Vec::new()),
            (PlaceKind::Floor, None) => (Cue::Floor, Vec::new()),
            _ => return None,
        })
    }

    /// The host whose middle or corner a small thing's "in the middle" / "in the corner"
    /// names: the thing a "with" listed it on, else (for the middle only, with no host of
    /// its own) the last work surface named. `None` for the room's.
    fn host_of_place(&self, g: &str, cue: &Cue, targets: &[String], listed_with: Option<&str>) -> Option<String> {
        if !targets.is_empty() || !matches!(cue, Cue::Center | Cue::Corner(None)) {
            return None;
        }
        // A thing of no known kind listed with a surface ("a desk with a book caddy in the
        // middle") is on it as a small thing would be; furniture is not.
        let on_surface = self.group_is_small(g) || self.group(g).is_some_and(|x| x.category.is_none());
        if !on_surface {
            return None;
        }
        let listed_on = self.implicit_on.iter().rev().find(|(s, _)| s == g).map(|(_, h)| h.clone()).or_else(|| {
            listed_with
                .filter(|h| *h != g && self.group_has_surface(h) && !self.group(h).is_some_and(|x| x.plural))
                .map(str::to_string)
        });
        if listed_on.is_some() {
            return listed_on;
        }
        if !self.group_is_small(g) {
            return None;
        }
        // Said to be on something ("a mug on the table in the middle"): the words place
        // that host.
        if self.on_host.iter().any(|(s, _)| s == g) || *cue != Cue::Center {
            return None;
        }
        self.draft.groups.iter().rev().map(|x| x.id.clone()).find(|x| x != g && self.group_is_work_surface(x))
    }

    /// The thing a place noun's modifier names ("the table top", "the bench end"): the
    /// latest group of that kind, else one added (and noted). The place word is the last
    /// token before `end`; the modifier is the known noun right before it.
    fn thing_before_place(&mut self, j: usize, end: usize) -> Option<String> {
        let place = end.checked_sub(1)?;
        let mut k = j;
        while k < place && matches!(self.word(k), "a" | "an" | "the" | "its" | "their" | "one" | "each" | "every") {
            k += 1;
        }
        if k >= place {
            return None;
        }
        let (meaning, n) = self.lookup(k, crate::lexicon::is_head)?;
        let Meaning::Category(cat) = meaning else { return None };
        if k + n != place {
            return None;
        }
        if let Some(g) = self.draft.groups.iter().rev().find(|g| g.category == Some(cat)) {
            return Some(g.id.clone());
        }
        let text = self.span(k, place);
        let id = self.new_bare_group(cat, place, text);
        if let Some(g) = self.draft.groups.last_mut() {
            g.accommodated = true;
        }
        Some(id)
    }

    /// A group of one `cat` for a noun the reader met inside another phrase (a place's
    /// modifier, a support named by its load): no count, size or colour of its own; `end` is
    /// where its words stop and `text` what they said.
    fn new_bare_group(&mut self, cat: &'static str, end: usize, text: String) -> String {
        let p = Phrase {
            end,
            count: None,
            quantity: None,
            color: None,
            sizes: Vec::new(),
            explicit: sw_plan::ExplicitSize::default(),
            descriptors: Vec::new(),
            room_modifier: None,
            head: Head::Known(Meaning::Category(cat)),
            plural: false,
            text,
            fuzzy_from: None,
        };
        self.new_group(Some(cat), cat.replace('_', " "), &p, p.explicit)
    }

    /// "a stand", "a low unit", "a base" after `g`'s "on": a word that names only a
    /// support. Its kind is the catalog's support named by what it carries ("tv" + "stand"
    /// is a TV stand; "television" + "unit" a TV unit), else for a stand, base or plinth a
    /// pedestal. The group made (or the stand named before, for "the stand") and the end.
    fn support_by_load(&mut self, j: usize, g: &str) -> Option<(String, usize)> {
        let mut k = j;
        let definite = matches!(self.word(k), "the" | "its" | "their");
        while matches!(
            self.word(k),
            "a" | "an"
                | "the"
                | "its"
                | "their"
                | "low"
                | "small"
                | "tall"
                | "high"
                | "wooden"
                | "metal"
                | "steel"
                | "sturdy"
        ) {
            k += 1;
        }
        let support = self.word(k).to_string();
        if !matches!(support.as_str(), "stand" | "unit" | "base" | "plinth" | "riser" | "cabinet") {
            return None;
        }
        // "a stand mixer", "a unit heater": a noun after it makes another thing.
        let ends = self.toks.get(k + 1).is_none_or(|t| t.kind != TokenKind::Word)
            || cue_at(&self.toks, k + 1).is_some()
            || matches!(self.word(k + 1), "and" | "with" | "by" | "near" | "beside" | "opposite" | "facing");
        if !ends {
            return None;
        }
        let load = self.group(g)?.category.and_then(sw_catalog::find)?;
        let mut names: Vec<&str> = std::iter::once(load.display).chain(load.synonyms.iter().copied()).collect();
        names.retain(|n| !n.is_empty());
        let by_load = names.iter().find_map(|n| {
            let compound = format!("{n} {support}");
            sw_catalog::categories()
                .iter()
                .find(|c| c.display == compound || c.synonyms.contains(&compound.as_str()))
                .map(|c| c.name)
        });
        let cat = match by_load {
            Some(c) => c,
            None if matches!(support.as_str(), "stand" | "base" | "plinth" | "riser") => "pedestal",
            None => return None,
        };
        let text = self.span(j, k + 1);
        if definite && let Some(x) = self.draft.groups.iter().rev().find(|x| x.category == Some(cat)) {
            let id = x.id.clone();
            self.mark(j, k + 1);
            return Some((id, k + 1));
        }
        let id = self.new_bare_group(cat, k + 1, text.clone());
        self.draft.approximated.push(sw_plan::Approximation {
            text,
            became: cat.to_string(),
            reason: format!(
                "a {support} that carries a {} is read as the catalog's {}",
                load.display,
                cat.replace('_', " ")
            ),
        });
        self.mark(j, k + 1);
        Some((id, k + 1))
    }

    /// The thing a part phrase ("the shelf", "the bottom drawer") belongs to: the latest
    /// thing named with a part of that head, and the place the part is of it — inside it
    /// (a shelf, a drawer, a compartment) or its top (a lid, a seat).
    fn owner_of_part(&self, p: &Phrase) -> Option<(String, PlaceKind)> {
        let head = singular(&p.text.split_whitespace().last()?.to_lowercase());
        // Named with the part ("a cabinet with three drawers"), or a thing whose own name holds
        // a part noun (the planner's part tables) as a modifier or complement ("a chest of drawers", "a drawer unit",
        // a catalog name read whole such as "cabinet with drawers").
        let named_with = || self.parts.iter().rev().find(|(h, _)| *h == head).map(|(_, owner)| owner.clone());
        // The phrase's own noun is the last word before a complement ("cabinet" of "cabinet
        // with drawers", "chest" of "chest of drawers"); a thing whose noun is the part's
        // ("the mill" after "a mill", "the sink" after "a sink") is what the words refer to, so
        // then no thing is the part's owner by its name.
        let words_and_noun = |g: &super::GroupDraft| {
            let words: Vec<String> = g.phrase.split_whitespace().map(|w| singular(&w.to_lowercase())).collect();
            let noun_end =
                words.iter().position(|w| matches!(w.as_str(), "with" | "of" | "for")).unwrap_or(words.len());
            let noun = words[..noun_end].last().cloned().unwrap_or_default();
            (words, noun)
        };
        let named_by = || {
            if !crate::phrase::is_part_noun(&head) {
                return None;
            }
            let named: Vec<_> = self.draft.groups.iter().map(|g| (g, words_and_noun(g))).collect();
            if named.iter().any(|(_, (_, noun))| *noun == head) {
                return None;
            }
            named.iter().rev().find(|(_, (words, _))| words.contains(&head)).map(|(g, _)| g.id.clone())
        };
        let owner = named_with().or_else(named_by)?;
        let top = matches!(head.as_str(), "lid" | "seat" | "top" | "tabletop" | "worktop");
        Some((owner, if top { PlaceKind::Top } else { PlaceKind::Part }))
    }

    /// A group standing in a row (or several of them): its end is the row's end.
    fn group_is_plural_row(&self, id: &str) -> bool {
        self.group_is_plural(id)
            || self
                .draft
                .relations
                .iter()
                .any(|(s, k)| s == id && matches!(k, RelationKind::InRow | RelationKind::InRows { .. }))
    }

    fn category_of(&self, id: &str) -> Option<&'static str> {
        self.group(id).and_then(|g| g.category)
    }

    /// "a chair on either side of the desk": one on each side, so two of a single thing.
    fn one_each_side(&mut self, id: &str) {
        if let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id)
            && g.count_rule.is_none()
            && g.count.is_some_and(|c| c <= 1.0)
        {
            g.count = Some(2.0);
            g.plural = true;
        }
    }

    fn group_is_seating(&self, id: &str) -> bool {
        self.group(id).and_then(|g| g.category).and_then(sw_catalog::find).is_some_and(|c| c.has_tag("seating"))
    }

    /// A work surface, conveyor or machine: what an arm beside it works at.
    fn group_is_work(&self, id: &str) -> bool {
        self.group(id).and_then(|g| g.category).and_then(sw_catalog::find).is_some_and(|c| {
            (c.has_tag("surface") && c.has_tag("furniture")) || c.has_tag("conveyor") || c.has_tag("machine")
        })
    }

    fn apply_to_robot(&mut self, idx: usize, cue: Cue, targets: Vec<String>) {
        let Some(robot) = self.draft.robots.get(idx) else {
            return;
        };
        let is_arm = robot.word.kind == sw_robots::RobotKind::Arm;
        // "two Pandas on a bench tending a printer on the same bench": an arm already
        // mounted puts nothing more under itself; the "on" is the thing just named.
        if cue == Cue::On
            && !matches!(robot.mount, Mount::Auto)
            && let [t] = targets.as_slice()
            && !t.starts_with('@')
            && let Some(last) = self.draft.groups.last().map(|g| g.id.clone())
            && self.group_is_small(&last)
            && &last != t
        {
            self.apply(&Subject::Group(last), cue, targets);
            return;
        }
        // "a Kinova arm on a table in front of a shelf": where the table stands.
        if let Mount::OnSurface { target: host } = &robot.mount
            && !host.starts_with('@')
            && matches!(
                cue,
                Cue::InFront | Cue::Behind | Cue::Wall(_) | Cue::Corner(_) | Cue::End(_) | Cue::Center | Cue::Door
            )
        {
            let host = host.clone();
            self.apply(&Subject::Group(host), cue, targets);
            return;
        }
        if targets.iter().any(|t| t.starts_with("@robot:") && t != &format!("@robot:{idx}")) && cue == Cue::On {
            return;
        }
        let rel = match (&cue, targets.as_slice()) {
            (Cue::On, [t]) if t == "@mount:pedestal" => {
                self.set_mount(idx, Mount::Pedestal);
                return;
            }
            (Cue::On, [t]) if t == "@mount:mobile" => {
                self.set_mount(idx, Mount::MobileBase);
                return;
            }
            // An arm on a base that drives ("a robot arm on an AGV", "a Kinova on a mobile
            // base") is the catalog's mobile manipulator; a named arm other than its own is
            // said so. (A cart, which does not drive, keeps the named arm on it.)
            (Cue::On, [t]) if t == "@mount:manipulator" => {
                self.make_mobile_manipulator(idx);
                return;
            }
            (Cue::On, [t]) if t == "@mount:floor" => {
                self.set_mount(idx, Mount::Floor);
                return;
            }
            (Cue::Floor, _) => {
                self.set_mount(idx, Mount::Floor);
                return;
            }
            (Cue::On | Cue::OnEdge, [t]) => {
                self.set_mount(idx, Mount::OnSurface { target: t.clone() });
                if cue == Cue::OnEdge {
                    let rel = Said::OnEdgeOf(t.clone()).kind();
                    if !self.draft.robot_relations.contains(&(idx, rel.clone())) {
                        self.draft.robot_relations.push((idx, rel));
                    }
                }
                return;
            }
            // "a Panda picking from the belt": it works there (its reach is stated).
            (Cue::Tend, [t]) if !t.starts_with('@') => {
                if is_arm {
                    if let Some(r) = self.draft.robots.get_mut(idx) {
                        r.near = Some(t.clone());
                    }
                    return;
                }
                RelationKind::Near { target: t.clone() }
            }
            (Cue::NextTo, [t]) => RelationKind::NextTo { target: t.clone() },
            (Cue::Near, [t]) => RelationKind::Near { target: t.clone() },
            (Cue::InFront, [t]) => RelationKind::InFrontOf { target: t.clone() },
            (Cue::Behind, [t]) => RelationKind::Behind { target: t.clone() },
            (Cue::Around, [t]) | (Cue::FacingTarget, [t]) => RelationKind::Near { target: t.clone() },
            // "two arms on opposite sides of the bench": one on each side; a single robot
            // "either side of" something stands beside it.
            (Cue::EachSide, [t]) if robot.count.is_some_and(|c| c >= 2.0) || robot.plural => {
                Said::OnEachSideOf(t.clone()).kind()
            }
            (Cue::EachSide, [t]) => RelationKind::NextTo { target: t.clone() },
            // "two Pandas on a table, one on each side": of what they stand on or work at,
            // else of the last work surface named.
            (Cue::Facing, []) if robot.count.is_some_and(|c| c >= 2.0) || robot.plural => {
                let on = match &robot.mount {
                    Mount::OnSurface { target } if !target.starts_with('@') => Some(target.clone()),
                    _ => robot.near.clone(),
                };
                let work =
                    on.or_else(|| self.draft.groups.iter().rev().map(|g| g.id.clone()).find(|g| self.group_is_work(g)));
                match work {
                    Some(t) => Said::OnEachSideOf(t).kind(),
                    None => return,
                }
            }
            (Cue::In | Cue::Above, _) => return,
            (Cue::EndOf(end), [t]) => {
                // A named end ("at the start of the belt") is stated as such; the end of the
                // row of one is what the layout keeps for a robot.
                if let Some(e) = end {
                    let stated = Said::AtEnd(t.clone(), *e).kind();
                    if !self.draft.robot_relations.contains(&(idx, stated.clone())) {
                        self.draft.robot_relations.push((idx, stated));
                    }
                }
                RelationKind::AtEndOfRow { target: t.clone() }
            }
            (Cue::Between, [a, b]) => RelationKind::Between { first: a.clone(), second: b.clone() },
            (Cue::Door, _) => RelationKind::NearDoor,
            (Cue::Corner(c), _) => RelationKind::InCorner { corner: *c },
            (Cue::End(w), _) => RelationKind::AtEnd { wall: *w },
            (Cue::Center, _) => RelationKind::InCenter,
            (Cue::Wall(w), _) => RelationKind::AgainstWall { wall: *w },
            (cue, _) => {
                let phrase = robot.phrase.clone();
                self.draft.approximated.push(sw_plan::Approximation {
                    text: phrase,
                    became: "placed by the layout".into(),
                    reason: format!(
                        "robot placement '{}' is not supported; robots are placed near their work",
                        cue_name(cue)
                    ),
                });
                return;
            }
        };
        // An arm beside a work surface, conveyor or machine works at it.
        if is_arm
            && let Some(t) = rel.targets().first().map(|t| t.to_string())
            && !t.starts_with('@')
            && self.draft.robots.get(idx).is_some_and(|r| r.near.is_none())
            && !matches!(rel, RelationKind::Behind { .. } | RelationKind::OnEachSideOf { .. })
            && let Some(r) = self.draft.robots.get_mut(idx)
        {
            r.near = Some(t);
        }
        if !self.draft.robot_relations.contains(&(idx, rel.clone())) {
            self.draft.robot_relations.push((idx, rel));
        }
    }

    /// Robot `idx` becomes the catalog's mobile manipulator: an arm said to ride a base
    /// that drives, or a mobile robot said to handle things. A named model other than the
    /// one the catalog's mobile manipulator carries is listed as approximated.
    pub(super) fn make_mobile_manipulator(&mut self, idx: usize) {
        let Some(r) = self.draft.robots.get_mut(idx) else { return };
        if r.word.kind == sw_robots::RobotKind::MobileManipulator {
            return;
        }
        let carried = sw_robots::find("mobile_manipulator").map(|d| d.display).unwrap_or("mobile manipulator");
        let named = r.word.exact && r.word.kind == sw_robots::RobotKind::Arm;
        let own_arm = named && carried.to_lowercase().contains(&r.word.wants.to_lowercase());
        if named && !own_arm {
            let reason = format!("the robot catalog has no {} on a mobile base; it has {carried}", r.phrase);
            let text = r.phrase.clone();
            self.draft.approximated.push(sw_plan::Approximation { text, became: "mobile_manipulator".into(), reason });
        }
        r.word = crate::lexicon::RobotWord {
            wants: "mobile_manipulator",
            kind: sw_robots::RobotKind::MobileManipulator,
            exact: false,
            on_mobile_base: false,
        };
        r.mount = Mount::Auto;
    }

    fn set_mount(&mut self, idx: usize, mount: Mount) {
        if let Some(r) = self.draft.robots.get_mut(idx) {
            r.mount = mount;
        }
    }
}

pub(super) fn cue_name(c: &Cue) -> &'static str {
    match c {
        Cue::On => "on",
        Cue::Under => "under",
        Cue::NextTo => "next to",
        Cue::Near => "near",
        Cue::InFront => "in front of",
        Cue::Behind => "behind",
        Cue::Between => "between",
        Cue::Around => "around",
        Cue::Row => "in a row",
        Cue::Rows(_) | Cue::RowsOf(..) => "in rows",
        Cue::Aisles => "in aisles",
        Cue::Facing => "facing each other",
        Cue::End(_) => "at one end",
        Cue::EndOf(_) => "at the end of",
        Cue::Corner(_) => "in the corner",
        Cue::Center => "in the middle",
        Cue::Door => "near the door",
        Cue::Wall(_) => "against the wall",
        Cue::TwoWalls => "on two walls",
        Cue::OppositeWalls { .. } => "on opposite walls",
        Cue::Corners(_) => "in the corners",
        Cue::BackToBack => "back to back",
        Cue::Leaning(_) => "leaning on the wall",
        Cue::Stacked => "stacked",
        Cue::Tend => "working at",
        Cue::Floor => "on the floor",
        Cue::In => "in",
        Cue::EachSide => "on either side of",
        Cue::FacingTarget => "opposite",
        Cue::Above => "above",
        Cue::OnEdge => "on the edge of",
    }
}
