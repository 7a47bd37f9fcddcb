//! The discourse model: which group a definite phrase or a pronoun refers to. Groups
//! are introduced by indefinite or counted noun phrases ("two racks", "a bench"); "the
//! racks", "the bench", "them", "it", "each", "the cell" bind to the most recent
//! compatible group already introduced and never create one. A definite phrase with
//! nothing to refer to is accommodated (the thing is added) and the report says so.

use sw_plan::{Approximation, Mount, RoomKind};

use super::{Parser, Subject};
use crate::text::singular;

/// Words that make the noun phrase after them definite.
const DEFINITE: &[&str] = &["the", "these", "those", "both", "each", "every", "its", "their", "all", "said"];

impl Parser<'_> {
    /// True when the phrase starting at token `start` is definite ("the racks").
    pub(super) fn is_definite(&self, start: usize) -> bool {
        let mut j = start;
        for _ in 0..2 {
            if j == 0 {
                return false;
            }
            j -= 1;
            let w = self.word(j);
            if DEFINITE.contains(&w) {
                return true;
            }
            if !matches!(w, "two" | "three" | "four" | "five" | "six" | "of") {
                return false;
            }
        }
        false
    }

    /// A catalog category a one-word noun names by the last word of its name: "bench" for
    /// a workbench. "rack" and "workstation" depend on the room: pallet racks and
    /// workbenches in industrial rooms, shelves and desks elsewhere.
    pub(super) fn category_by_head(&self, label: &str) -> Option<&'static str> {
        if label.contains(' ') || label.len() < 4 {
            return None;
        }
        let industrial = self.draft.room.as_ref().is_some_and(|(k, _)| {
            matches!(k, RoomKind::Warehouse | RoomKind::LoadingDock | RoomKind::Factory | RoomKind::StorageRoom)
        });
        if label == "rack" {
            return Some(if industrial { "pallet_rack" } else { "shelf" });
        }
        if matches!(label, "workstation" | "station" | "workplace") {
            let office = self
                .draft
                .room
                .as_ref()
                .is_some_and(|(k, _)| matches!(k, RoomKind::Office | RoomKind::Classroom | RoomKind::LivingRoom));
            return Some(if office { "desk" } else { "workbench" });
        }
        sw_catalog::categories().iter().find_map(|c| {
            let last = c.display.split_whitespace().last()?;
            (last != label && last.ends_with(label) && label.len() >= 5).then_some(c.name)
        })
    }

    /// An earlier group that a head noun refers to: "the racks" for shelving racks or
    /// pallet racks, "the bench" for a workbench, "the stations" for workbenches read
    /// from "workstations".
    pub(super) fn group_by_head(&self, label: &str) -> Option<String> {
        let head = singular(label.split_whitespace().last()?);
        if head.len() < 3 {
            return None;
        }
        self.draft.groups.iter().rev().find_map(|g| {
            let mut names: Vec<String> = match g.category.and_then(sw_catalog::find) {
                Some(c) => std::iter::once(c.display).chain(c.synonyms.iter().copied()).map(str::to_string).collect(),
                None => vec![g.label.clone()],
            };
            // The words the group was introduced with ("workstations", "shelving racks").
            names.push(g.phrase.to_lowercase());
            let hit = names.iter().any(|n| {
                n.split_whitespace()
                    .last()
                    .map(singular)
                    .is_some_and(|last| last == head || (head.len() >= 4 && last.ends_with(head.as_str())))
            });
            // "each bunk" for "3 bunk beds": the word that made the phrase a kind.
            let modifier = !hit
                && head.len() >= 4
                && g.phrase.to_lowercase().split_whitespace().rev().skip(1).any(|w| singular(w) == head);
            (hit || modifier).then(|| g.id.clone())
        })
    }

    /// The most recent group of `category`, or compatible by its head word `head`.
    pub(super) fn resolve_group(&self, category: Option<&'static str>, head: &str) -> Option<String> {
        if let Some(cat) = category
            && let Some(g) = self.draft.groups.iter().rev().find(|g| g.category == Some(cat))
        {
            return Some(g.id.clone());
        }
        if category.is_none()
            && let Some(g) = self.draft.groups.iter().rev().find(|g| g.category.is_none() && g.label == head)
        {
            return Some(g.id.clone());
        }
        self.group_by_head(head)
    }

    /// The robot a definite robot phrase refers to ("the robot", "the arm", "the UR5e"):
    /// the most recent robot of the same kind.
    pub(super) fn resolve_robot(&self, wants: &str, kind: sw_robots::RobotKind, generic: bool) -> Option<usize> {
        self.draft
            .robots
            .iter()
            .enumerate()
            .rev()
            .find(|(_, r)| r.word.wants == wants || (generic && r.word.kind == kind))
            .map(|(i, _)| i)
            .or_else(|| generic.then(|| self.draft.robots.len().checked_sub(1)).flatten())
    }

    /// "the cell", "the work cell": the work of the most recent arm (the group it stands
    /// on or tends), else the arm itself.
    pub(super) fn resolve_cell(&self) -> Option<String> {
        let (idx, r) =
            self.draft.robots.iter().enumerate().rev().find(|(_, r)| r.word.kind == sw_robots::RobotKind::Arm)?;
        match (&r.mount, &r.near) {
            (Mount::OnSurface { target }, _) => Some(target.clone()),
            (_, Some(n)) => Some(n.clone()),
            _ => Some(format!("@robot:{idx}")),
        }
    }

    /// The group or robot "it" / "they" refers to: the most recent mention other than the
    /// current subject, singular for "it", plural for "they".
    pub(super) fn resolve_pronoun(&self, word: &str) -> Option<Subject> {
        let plural = matches!(word, "they" | "them" | "these" | "those" | "both" | "all");
        let current = self.subject.clone();
        let candidates = self.mentions.iter().rev().filter(|m| Some(*m) != current.as_ref());
        let fits = |m: &Subject| match m {
            Subject::Group(g) => self.group(g).is_none_or(|g| (g.plural || g.count.is_some_and(|c| c > 1.0)) == plural),
            Subject::Robot(r) => self.draft.robots.get(*r).is_none_or(|r| r.plural == plural || !plural),
        };
        let all: Vec<&Subject> = candidates.collect();
        all.iter().find(|m| fits(m)).or_else(|| all.first()).map(|m| (*m).clone())
    }

    /// Notes a definite phrase that had nothing to refer to: the thing was added.
    pub(super) fn note_accommodated(&mut self, phrase: &str, became: &str) {
        self.draft.approximated.push(Approximation {
            text: phrase.to_string(),
            became: format!("added {}", became.replace('_', " ")),
            reason: "the prompt refers to it as if already mentioned, but did not introduce it; one was added".into(),
        });
    }
}
