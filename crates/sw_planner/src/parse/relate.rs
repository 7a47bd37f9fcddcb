//! Relation phrases: a cue ("next to", "in two rows", "leaning on the wall"), its
//! targets resolved through the discourse model, and the relation it states about the
//! current subject — an object group or a robot.

use sw_plan::{Mount, RelationKind};

use super::{Bare, Head, Parser, Subject};
use crate::cues::{Cue, cue_at, target_start};
use crate::lexicon::Meaning;
use crate::text::singular;

impl Parser<'_> {
    pub(super) fn try_cue(&mut self, i: usize) -> Option<usize> {
        if let Some(next) = self.try_surrounded(i) {
            return Some(next);
        }
        let (cue, len) = cue_at(&self.toks, i)?;
        let mut end = i + len;
        let mut targets = Vec::new();
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
                let targets = match before.as_slice() {
                    [a, ..] if plural_first => Some(vec![a.clone(), a.clone()]),
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
            if matches!(self.word(j), "row" | "line" | "rows" | "lines" | "aisle" | "aisles")
                && matches!(cue, Cue::EndOf | Cue::Between | Cue::InFront | Cue::Behind | Cue::NextTo | Cue::Near)
            {
                let row = self.draft.relations.iter().rev().find_map(|(s, k)| {
                    matches!(k, RelationKind::InRow | RelationKind::InRows { .. } | RelationKind::FacingEachOther)
                        .then(|| s.clone())
                });
                let current = match &self.subject {
                    Some(Subject::Group(g)) => Some(g.clone()),
                    _ => None,
                };
                let row =
                    row.filter(|r| Some(r) != current.as_ref()).or_else(|| self.last_plural_group(current.as_deref()));
                if let Some(row) = row {
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
            // "at each of the desks"
            if self.word(j) == "of" && j > 0 && matches!(self.word(j - 1), "each" | "every" | "one") {
                let k = target_start(&self.toks, j + 1);
                if k > j + 1 || self.phrase_at(j + 1, true, Bare::Target).ok().flatten().is_some() {
                    self.used[j] = true;
                    j = k.max(j + 1);
                    // Keep "each" visible to the companion check below.
                    if !matches!(self.word(j - 1), "each" | "every") && j >= 2 {
                        let each_at = (i..j).rev().find(|&x| matches!(self.word(x), "each" | "every"));
                        if let Some(x) = each_at {
                            let (target, next) = self.target_at(j, &cue)?;
                            if let Some(Subject::Group(g)) = self.subject.clone()
                                && !target.starts_with('@')
                                && target != g
                            {
                                self.mark(i, next);
                                let _ = x;
                                self.add_companion(&target, &g);
                                return Some(next);
                            }
                            return None;
                        }
                    }
                }
            }
            // "a stool at each station", "a chair in front of every desk": companions.
            let each = j > 0 && matches!(self.word(j - 1), "each" | "every");
            if each
                && matches!(cue, Cue::Tend | Cue::NextTo | Cue::InFront | Cue::On | Cue::Near)
                && let Some(Subject::Group(g)) = self.subject.clone()
            {
                let (target, next) = self.target_at(j, &cue)?;
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
            end = j;
        }
        self.mark(i, end);
        match self.subject.clone() {
            Some(s) => {
                self.apply(&s, cue.clone(), targets.clone());
                // "three mugs and a bowl on the table": small things listed together rest
                // on the same thing; "a table and four chairs in a row" both stand so.
                if cue == Cue::On && targets.iter().all(|t| !t.starts_with('@')) {
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
                        let has_on =
                            self.draft.relations.iter().any(|(x, k)| x == &g && matches!(k, RelationKind::On { .. }));
                        if self.group_is_small(&g) && !has_on && !targets.contains(&g) {
                            self.apply(&Subject::Group(g), cue.clone(), targets.clone());
                        }
                    }
                }
                self.list.clear();
                self.pending.clear();
            }
            None => self.pending.push((cue, targets)),
        }
        Some(end)
    }

    /// "a robot surrounded by safety screens", "a press enclosed by fences": what follows
    /// "by" stands around what came before — "around" turned round. The pieces are a group
    /// of their own (a plural without a count gets the usual default, not two).
    fn try_surrounded(&mut self, i: usize) -> Option<usize> {
        if !matches!(self.word(i), "surrounded" | "enclosed" | "encircled" | "ringed" | "fenced")
            || !matches!(self.word(i + 1), "by" | "with")
        {
            return None;
        }
        let target = match self.subject.clone()? {
            Subject::Group(g) => g,
            Subject::Robot(r) => format!("@robot:{r}"),
        };
        let j = target_start(&self.toks, i + 2);
        self.taking_pieces = true;
        let taken = self.target_at(j, &Cue::Around);
        self.taking_pieces = false;
        let (pieces, next) = taken?;
        if pieces.starts_with('@') || pieces == target {
            return None;
        }
        self.mark(i, next);
        self.apply(&Subject::Group(pieces), Cue::Around, vec![target]);
        Some(next)
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
        let w = self.word(j);
        if matches!(w, "it" | "them" | "this" | "that" | "these" | "those" | "one" | "each") {
            if let Some(host) = &self.with_host
                && self.subject != Some(Subject::Group(host.clone()))
            {
                return Some((host.clone(), j + 1));
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
        let definite = self.is_definite(j);
        let p = self.phrase_at(j, true, Bare::Target).ok().flatten()?;
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
            Head::Known(Meaning::RoomWord) if p.text.to_lowercase().contains("cell") => self.resolve_cell()?,
            Head::Known(Meaning::Robot(word)) => {
                let generic = !word.exact;
                let r = self.resolve_robot(word.wants, word.kind, generic)?;
                format!("@robot:{r}")
            }
            Head::Known(Meaning::Category(cat)) => match self.resolve_group(Some(cat), &raw_head) {
                Some(g) => g,
                None => {
                    let id = self.new_group(Some(cat), cat.replace('_', " "), &p2, p.explicit);
                    if definite && !matches!(cue, Cue::On | Cue::Under) {
                        self.note_accommodated(&p.text, cat);
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
            ("mobile base", "mobile"),
            ("mobile platform", "mobile"),
            ("cart", "mobile"),
            ("agv", "mobile"),
            ("amr", "mobile"),
            ("floor", "floor"),
            ("ground", "floor"),
        ];
        let mut k = j;
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
                // "a mug on the table next to the door": placement words after an "on"
                // describe where the table stands.
                let floor_level = matches!(
                    cue,
                    Cue::Wall(_)
                        | Cue::Door
                        | Cue::Corner(_)
                        | Cue::End(_)
                        | Cue::EndOf
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
                    (Cue::EndOf, [t]) => RelationKind::AtEndOfRow { target: t.clone() },
                    (Cue::Tend, [t]) if self.group_is_seating(&subject) => {
                        RelationKind::InFrontOf { target: t.clone() }
                    }
                    (Cue::Tend, [t]) => RelationKind::NextTo { target: t.clone() },
                    (Cue::Between, [a, b]) => RelationKind::Between { first: a.clone(), second: b.clone() },
                    (Cue::Row, _) => RelationKind::InRow,
                    (Cue::Rows(n), _) => RelationKind::InRows { n, m: None },
                    (Cue::Aisles, _) => RelationKind::InAisles,
                    (Cue::Facing, _) => RelationKind::FacingEachOther,
                    (Cue::End(w), _) => RelationKind::AtEnd { wall: w },
                    (Cue::Corner(c), _) => RelationKind::InCorner { corner: c },
                    (Cue::Center, _) => RelationKind::InCenter,
                    (Cue::Door, _) => RelationKind::NearDoor,
                    (Cue::Wall(w), _) => RelationKind::AgainstWall { wall: w },
                    (Cue::TwoWalls, _) => RelationKind::OnTwoWalls,
                    (Cue::Leaning(w), _) => RelationKind::Leaning { wall: w },
                    (Cue::Stacked, _) => RelationKind::Stacked { n: None, stacks: None },
                    (Cue::Floor, _) => return,
                    _ => return,
                };
                if kind.targets().contains(&subject.as_str()) {
                    return;
                }
                self.relate(&subject, kind);
            }
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
            (Cue::On, [t]) if t == "@mount:floor" => {
                self.set_mount(idx, Mount::Floor);
                return;
            }
            (Cue::Floor, _) => {
                self.set_mount(idx, Mount::Floor);
                return;
            }
            (Cue::On, [t]) => {
                self.set_mount(idx, Mount::OnSurface { target: t.clone() });
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
            (Cue::Around, [t]) => RelationKind::Near { target: t.clone() },
            (Cue::EndOf, [t]) => RelationKind::AtEndOfRow { target: t.clone() },
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
            && !matches!(rel, RelationKind::Behind { .. })
            && let Some(r) = self.draft.robots.get_mut(idx)
        {
            r.near = Some(t);
        }
        if !self.draft.robot_relations.contains(&(idx, rel.clone())) {
            self.draft.robot_relations.push((idx, rel));
        }
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
        Cue::Rows(_) => "in rows",
        Cue::Aisles => "in aisles",
        Cue::Facing => "facing each other",
        Cue::End(_) => "at one end",
        Cue::EndOf => "at the end of",
        Cue::Corner(_) => "in the corner",
        Cue::Center => "in the middle",
        Cue::Door => "near the door",
        Cue::Wall(_) => "against the wall",
        Cue::TwoWalls => "on two walls",
        Cue::Leaning(_) => "leaning on the wall",
        Cue::Stacked => "stacked",
        Cue::Tend => "working at",
        Cue::Floor => "on the floor",
    }
}
