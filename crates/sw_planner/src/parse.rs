//! The scan: walks the tokens once, recognising dimensions, relation cues and phrases
//! (count, modifiers, head noun), and records them in a [`Draft`]. Every token it uses
//! is marked, so that what is left over can be reported as not understood.

use sw_catalog::PlacementKind;
use sw_plan::{Approximation, ExplicitSize, Mount, NamedColor, RelationKind, RoomKind, SizeWord};

use crate::PlannerError;
use crate::cues::Cue;
use crate::lexicon::{Lexicon, Meaning, RobotWord};
use crate::phrase::PlaceKind;
pub(crate) use crate::phrase::{Bare, Head, NounPhrase as Phrase, Phrases};
use crate::text::{Token, TokenKind, number_word, singular};

mod amend;
mod discourse;
mod relate;
mod support;
mod title;

/// What the scan found, before defaults and resolution.
#[derive(Debug, Default)]
pub(crate) struct Draft {
    pub room: Option<(RoomKind, String)>,
    pub aisle: bool,
    pub other_rooms: Vec<String>,
    /// Room dimensions in metres as written (2 or 3 numbers) and their text.
    pub room_dims: Option<(Vec<f64>, String)>,
    pub room_height: Option<(f64, String)>,
    /// A room noun ("room", "cell") was used, with or without a kind.
    pub room_word: bool,
    /// Size words on the room ("a small room", "a huge warehouse").
    pub room_sizes: Vec<SizeWord>,
    pub groups: Vec<GroupDraft>,
    pub robots: Vec<RobotDraft>,
    pub relations: Vec<(String, RelationKind)>,
    /// Relations whose subject is a robot (by index into `robots`); targets may be
    /// `@robot:N`.
    pub robot_relations: Vec<(usize, RelationKind)>,
    pub approximated: Vec<Approximation>,
    /// Groups said to stand on the floor ("a basket on the floor").
    pub on_floor: Vec<String>,
}

/// How a group's count follows from another group's.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum CountRule {
    /// "stations, each with a stool": `per` for every instance of the host.
    EachOf { host: String, per: f64 },
    /// "shelves full of boxes", "pallets of boxes": when no count was given, enough to
    /// fill every support level of every host (`levels` = true) or a few on each host.
    Fill { host: String, levels: bool },
}

#[derive(Debug, Clone)]
pub(crate) struct GroupDraft {
    pub id: String,
    /// Catalog category, or `None` for a proxy.
    pub category: Option<&'static str>,
    pub label: String,
    pub phrase: String,
    pub count: Option<f64>,
    pub plural: bool,
    pub color: Option<NamedColor>,
    pub sizes: Vec<SizeWord>,
    pub explicit: ExplicitSize,
    pub count_rule: Option<CountRule>,
    /// Stacks: how many columns ("three stacks of …") and layers ("… four high").
    pub stacks: Option<f64>,
    pub layers: Option<f64>,
    /// Named by a definite phrase with nothing to refer to ("the bowls" first).
    pub accommodated: bool,
}

#[derive(Debug, Clone)]
pub(crate) struct RobotDraft {
    pub word: RobotWord,
    pub phrase: String,
    pub count: Option<f64>,
    pub plural: bool,
    pub mount: Mount,
    pub near: Option<String>,
}

/// Who a relation applies to.
#[derive(Debug, Clone, PartialEq)]
enum Subject {
    Group(String),
    Robot(usize),
}

pub(crate) struct Parser<'a> {
    lex: &'a Lexicon,
    text: &'a str,
    toks: Vec<Token>,
    used: Vec<bool>,
    pub draft: Draft,
    /// The subject of the current sentence.
    subject: Option<Subject>,
    /// A relation that came before its subject ("On the bench, a UR5e").
    pending: Vec<(Cue, Vec<String>)>,
    /// "a shelf with boxes": small items and arms that follow go on this group.
    with_host: Option<String>,
    /// Dimensions seen just before a phrase: the phrase's size if it is an object.
    pending_dims: Option<(Vec<f64>, String, usize)>,
    /// The group each group was last put on (for "a mug on the table next to the door").
    on_host: Vec<(String, String)>,
    /// Groups and robots in the order they were mentioned (for "it" and "them").
    mentions: Vec<Subject>,
    /// The phrases since the last relation or sentence end: "three mugs and a bowl on
    /// the table" puts all of them on the table.
    list: Vec<Subject>,
    /// How many groups have been made from each id base (keeps ids unique in O(1)).
    id_counts: std::collections::HashMap<String, u32>,
    /// "a row of", "two rows of", "a stack of": arranges the group that follows.
    collective: Option<(Collective, f64)>,
    /// "each with": the host of the companions that follow.
    each_host: Option<String>,
    /// "full of" / "loaded with" / "pallets of": what the items after `with_host` are to it.
    support: Option<Support>,
    /// Companions taken since "each with".
    each_taken: usize,
    /// The group subject before the last "with" ("stations with a stool each").
    with_subject: Option<String>,
    /// Where the phrase being taken starts.
    phrase_start: usize,
    /// The thing before the last "with", until a relation follows: "a hob with a kettle and
    /// two mugs next to it" — it is the hob, and the relation is every listed thing's.
    with_it: Option<String>,
    /// The last pronoun target read was `with_it`.
    it_is_with_host: bool,
    /// Groups loaded since "full of" / "loaded with".
    support_taken: usize,
    /// The phrase being taken as a target is the subject of a turned-round relation
    /// ("surrounded by screens"): a plural without a count gets the subject's default.
    taking_pieces: bool,
    /// The place a relation's target named ("the edge of the table"), for `apply`.
    place_of: Option<(PlaceKind, Option<String>)>,
    /// "on" relations read from "with" ("a table with a mug"): a relation the prompt then
    /// states for the item ("a cabinet with a plant beside it") takes their place.
    implicit_on: Vec<(String, String)>,
    /// Places counted so far ("4 bays"), by their singular head, for "every bay has …".
    place_counts: std::collections::HashMap<String, f64>,
    /// Tokens before this index are a title: rooms only, no objects.
    title_end: usize,
    /// Robots a title named ("Bin picking with a UR5e:"), kept when the body names none.
    title_robots: Vec<RobotDraft>,
    /// The clause is about a place ("a clear path to the door"): its relations are the
    /// place's, not the subject's.
    in_place_clause: bool,
    /// The robot whose verb of handling is being read ("a Panda sorts blocks from a bin
    /// into trays"): every thing named up to the clause's end is its work, which it reaches.
    working: Option<usize>,
    /// The robot the sentence's last verb of handling was said of: a verb after a comma or
    /// "and" ("…, placing them in a crate") goes on with its work.
    last_worker: Option<usize>,
    /// What robots handle, by robot: (robot, group), in the order named.
    work: Vec<(usize, String)>,
    /// The list is everything named so far ("put it all on a table"): the relation that
    /// follows is said of every thing in it, not only the small ones.
    all_of: bool,
    /// The last "to its left"-style side in the sentence: (what was placed, what "its" was).
    /// A parallel one that follows ("…, another tote to its right") has the same referent.
    last_possessive: Option<(Subject, String)>,
    /// The things last said together of one relation ("a mixer and a blender on the
    /// worktop"): what a later "between them" names when no plural group is nearer.
    last_coordination: Vec<String>,
    /// Parts named with a thing ("a cabinet with a shelf", "a box with a lid"), by their
    /// singular head: (part, the thing). "the shelf", "the bottom drawer" refer to them.
    parts: Vec<(String, String)>,
    /// Where the last object phrase read as a subject ended, and its group.
    last_phrase: Option<(usize, String)>,
    /// Groups whose phrases were joined by a bare "and" ("a white mug and a red mug"):
    /// (first, second). A relation said after the second is said of both.
    and_pairs: Vec<(String, String)>,
}

/// A collective noun before a phrase: "a row of", "two rows of", "a stack of", "an aisle of".
#[derive(Debug, Clone, Copy, PartialEq)]
enum Collective {
    Row,
    Stack,
    Aisle,
}

/// What items said to be on a carrier are to it.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Support {
    /// "pallets of boxes", "loaded with": every carrier carries some.
    Loaded,
    /// "full of", "stocked with": every level holds some.
    FullOf,
}

impl<'a> Parser<'a> {
    pub fn new(lex: &'a Lexicon, text: &'a str, toks: Vec<Token>) -> Self {
        let n = toks.len();
        Self {
            lex,
            text,
            toks,
            used: vec![false; n],
            draft: Draft::default(),
            subject: None,
            pending: Vec::new(),
            with_host: None,
            pending_dims: None,
            on_host: Vec::new(),
            mentions: Vec::new(),
            list: Vec::new(),
            id_counts: std::collections::HashMap::new(),
            collective: None,
            each_host: None,
            support: None,
            each_taken: 0,
            with_subject: None,
            phrase_start: 0,
            with_it: None,
            it_is_with_host: false,
            support_taken: 0,
            taking_pieces: false,
            in_place_clause: false,
            working: None,
            last_worker: None,
            work: Vec::new(),
            all_of: false,
            last_possessive: None,
            last_coordination: Vec::new(),
            parts: Vec::new(),
            last_phrase: None,
            and_pairs: Vec::new(),
            place_of: None,
            implicit_on: Vec::new(),
            place_counts: std::collections::HashMap::new(),
            title_end: 0,
            title_robots: Vec::new(),
        }
    }

    /// The unused tokens, as maximal runs of prompt text.
    pub fn leftovers(&self) -> Vec<String> {
        let mut out = Vec::new();
        let mut run: Option<(usize, usize)> = None;
        for (i, t) in self.toks.iter().enumerate() {
            let skip = self.used[i] || matches!(t.kind, TokenKind::Comma | TokenKind::Stop);
            if skip {
                if let Some((s, e)) = run.take() {
                    out.push(self.text[s..e].to_string());
                }
            } else {
                run = Some(run.map_or((t.start, t.end), |(s, _)| (s, t.end)));
            }
        }
        if let Some((s, e)) = run {
            out.push(self.text[s..e].to_string());
        }
        out
    }

    fn word(&self, i: usize) -> &str {
        self.toks.get(i).filter(|t| t.kind == TokenKind::Word).map_or("", |t| t.norm.as_str())
    }

    fn words_from(&self, i: usize) -> Vec<&str> {
        self.toks[i.min(self.toks.len())..]
            .iter()
            .take(6)
            .map_while(|t| {
                (t.kind == TokenKind::Word || matches!(t.kind, TokenKind::Number(_))).then_some(t.norm.as_str())
            })
            .collect()
    }

    fn span(&self, from: usize, to: usize) -> String {
        match (self.toks.get(from), self.toks.get(to.saturating_sub(1))) {
            (Some(a), Some(b)) if to > from => self.text[a.start..b.end].to_string(),
            _ => String::new(),
        }
    }

    fn mark(&mut self, from: usize, to: usize) {
        for u in &mut self.used[from..to.min(self.toks.len())] {
            *u = true;
        }
    }

    fn lookup(&self, i: usize, accept: impl Fn(&Meaning) -> bool) -> Option<(Meaning, usize)> {
        let words = self.words_from(i);
        self.lex.longest(&words, accept).map(|(e, n)| (e.meaning.clone(), n))
    }

    /// Runs the scan over the whole prompt.
    pub fn run(&mut self) -> Result<(), PlannerError> {
        let mut i = 0;
        while i < self.toks.len() {
            if let Some(end) = self.title_at(i) {
                self.title_end = end;
                self.used[end] = true;
            }
            let kind = self.toks[i].kind.clone();
            match kind {
                TokenKind::Stop => {
                    self.end_sentence();
                    self.used[i] = true;
                    i += 1;
                    continue;
                }
                TokenKind::Comma => {
                    self.working = None;
                    self.used[i] = true;
                    i += 1;
                    continue;
                }
                _ => {}
            }
            // Read on as before: the verb only opens the robot's work (a word that is also a
            // noun, "a Panda, screws and a bin", stays a noun).
            self.note_handling_verb(i);
            self.pronoun_worked_on(i);
            if let Some(next) = self.try_possessive_side(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_bare_place_of_robot(i) {
                i = next;
                continue;
            }
            // "boxes onto two pallets, one either side of the robot": "one" before a place is
            // one of the group counted last, not of the clause's subject.
            if self.word(i) == "one"
                && i >= 1
                && self.toks[i - 1].kind == TokenKind::Comma
                && crate::cues::cue_at(&self.toks, i + 1).is_some()
                && !matches!(self.subject, Some(Subject::Robot(_)))
                && let Some(g) =
                    self.draft.groups.iter().rev().find(|g| g.count.is_some_and(|c| c >= 2.0)).map(|g| g.id.clone())
            {
                self.subject = Some(Subject::Group(g));
                self.used[i] = true;
                i += 1;
                continue;
            }
            if let Some(next) = self.try_dims(i)? {
                i = next;
                continue;
            }
            if let Some(next) = self.try_retraction(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_times_count(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_bracket_count(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_measure_of(i)? {
                i = next;
                continue;
            }
            if let Some(next) = self.try_count_of_them(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_layers(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_trailing_size(i)? {
                i = next;
                continue;
            }
            if let Some(next) = self.try_collective(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_each(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_support(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_pronoun_subject(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_per(i) {
                i = next;
                continue;
            }
            if let Some(next) = self.try_trailing_each(i) {
                i = next;
                continue;
            }
            // A known noun of several words ("loading dock", "welding robot") is a noun even
            // where its first word could start a relation.
            let long_noun = self.lookup(i, crate::lexicon::is_head).is_some_and(|(_, n)| n >= 2);
            if !long_noun && let Some(next) = self.try_cue(i) {
                i = next;
                continue;
            }
            if matches!(self.word(i), "with" | "holding" | "carrying" | "supporting" | "containing") {
                self.with_subject = match &self.subject {
                    Some(Subject::Group(g)) => Some(g.clone()),
                    _ => None,
                };
                self.with_it = self.with_subject.clone();
                match &self.subject {
                    Some(Subject::Group(g)) if self.group_has_surface(g) => self.with_host = Some(g.clone()),
                    // "a UR5e on a table with three mugs": the mugs go on the table.
                    Some(Subject::Robot(r)) => {
                        if let Some(Mount::OnSurface { target }) = self.draft.robots.get(*r).map(|x| &x.mount) {
                            self.with_host = Some(target.clone());
                        }
                    }
                    _ => {}
                }
                self.used[i] = true;
                i += 1;
                continue;
            }
            // A clause's start counts too: "shoe shop: benches in the middle", "Boxes on
            // every shelf."
            let after_list_word = i == 0
                || (self.toks[i - 1].kind == TokenKind::Comma
                    || self.toks[i - 1].kind == TokenKind::Stop
                    || matches!(self.word(i - 1), "and" | "with" | "plus" | "&"));
            // "two rows of desks", "a stack of boxes": what follows a collective is an object.
            let bare = if self.collective.is_some() {
                Bare::Target
            } else if after_list_word {
                Bare::PluralInList
            } else {
                Bare::No
            };
            if let Some(mut p) = self.phrase_at(i, true, bare)? {
                let end = p.end;
                self.mark(i, end);
                if self.part_after_with(i, &p) {
                    p.head = Head::Place(PlaceKind::Part);
                }
                // "a white mug and a red mug": joined by a bare "and" to the phrase before.
                let joined = i >= 1
                    && matches!(self.word(i - 1), "and" | "&")
                    && self.last_phrase.as_ref().is_some_and(|(e, _)| *e + 1 == i);
                let before = self.last_phrase.take().map(|(_, g)| g);
                let groups = self.draft.groups.len();
                // "red, blue and pink blocks": one of each colour, each its own group.
                let colours = self.colours_listed_before(i, &p);
                let coloured = !colours.is_empty();
                let mut previous: Option<String> = None;
                for (k, name, rgba) in colours {
                    let mut one = p.clone();
                    one.color = Some(NamedColor { name: name.to_string(), rgba });
                    one.count = Some(1.0);
                    one.quantity = None;
                    one.plural = false;
                    one.text =
                        format!("{} {}", self.word(k), p.text.split_whitespace().skip(1).collect::<Vec<_>>().join(" "));
                    self.mark(k, k + 1);
                    self.take_phrase(one, k);
                    // The colours are a list joined as "and" joins: what follows is said of each.
                    if let Some(Subject::Group(g)) = self.subject.clone()
                        && let Some(b) = previous.replace(g.clone())
                    {
                        self.and_pairs.push((b, g));
                    }
                }
                if coloured {
                    p.count = Some(1.0);
                    p.plural = false;
                }
                self.take_phrase(p, i);
                if self.draft.groups.len() > groups
                    && let Some(Subject::Group(g)) = self.subject.clone()
                {
                    if let Some(b) = previous.filter(|b| *b != g) {
                        self.and_pairs.push((b, g.clone()));
                    } else if joined && let Some(b) = before.filter(|b| *b != g) {
                        self.and_pairs.push((b, g.clone()));
                    }
                    self.last_phrase = Some((end, g));
                }
                i = end;
                continue;
            }
            // "The racks …": a bare definite noun naming a group already introduced.
            if self.is_definite(i)
                && let Some(p) = self.phrase_at(i, true, Bare::Target)?
                && let Some(g) = match &p.head {
                    Head::Unknown(label) => self.resolve_group(None, label),
                    Head::Known(Meaning::Category(cat)) => {
                        let head =
                            p.text.split_whitespace().last().map(|h| singular(&h.to_lowercase())).unwrap_or_default();
                        self.resolve_group(Some(cat), &head)
                    }
                    _ => None,
                }
            {
                let end = p.end;
                self.mark(i, end);
                self.bind(Subject::Group(g));
                i = end;
                continue;
            }
            if self.lookup(i, |m| matches!(m, Meaning::Filler)).is_some() || number_word(self.word(i)).is_some() {
                self.used[i] = true;
            }
            i += 1;
        }
        self.end_sentence();
        // A thing placed by the robot ("three fences around the robot") is where it stands,
        // not what it works on, though its clause began with a verb of handling.
        let placed_by = |g: &str, r: usize| {
            let robot = format!("@robot:{r}");
            self.draft.relations.iter().any(|(s, k)| s == g && k.targets().contains(&robot.as_str()))
        };
        // What the robot's other work is put on ("boxes onto two pallets, one either side of
        // the robot") is its work all the same.
        let carries_work = |g: &str, r: usize| {
            self.work.iter().any(|(x, w)| {
                *x == r
                    && w != g
                    && self
                        .draft
                        .relations
                        .iter()
                        .any(|(s, k)| s == w && matches!(k, RelationKind::On { target } if target == g))
            })
        };
        let work: Vec<(usize, RelationKind)> = self
            .work
            .iter()
            .filter(|(r, g)| !placed_by(g, *r) || carries_work(g, *r))
            .map(|(r, g)| (*r, RelationKind::Reach { target: g.clone() }))
            .filter(|w| !self.draft.robot_relations.contains(w))
            .collect();
        self.draft.robot_relations.extend(work);
        if self.draft.robots.is_empty() {
            let robots = std::mem::take(&mut self.title_robots);
            self.draft.robots.extend(robots);
        }
        self.merge_restated();
        // A title's words name the scene.
        let title_end = self.title_end.min(self.used.len());
        self.mark(0, title_end);
        // Articles carry no meaning of their own.
        for (i, t) in self.toks.iter().enumerate() {
            if t.kind == TokenKind::Word && matches!(t.norm.as_str(), "a" | "an" | "the") {
                self.used[i] = true;
            }
        }
        Ok(())
    }

    fn end_sentence(&mut self) {
        self.working = None;
        self.last_worker = None;
        self.subject = None;
        self.in_place_clause = false;
        self.list.clear();
        self.all_of = false;
        self.last_possessive = None;
        self.with_host = None;
        self.support = None;
        self.each_host = None;
        self.collective = None;
        self.with_subject = None;
        self.with_it = None;
        self.pending.clear();
        if let Some((dims, text, _)) = self.pending_dims.take() {
            self.set_room_dims(dims, text);
        }
    }

    fn set_room_dims(&mut self, dims: Vec<f64>, text: String) {
        if self.draft.room_dims.is_none() {
            self.draft.room_dims = Some((dims, text));
        } else {
            self.draft.approximated.push(Approximation {
                text,
                became: "ignored".into(),
                reason: "the room size was already given; a scene has one room".into(),
            });
        }
    }

    // ---------------------------------------------------------------- dimensions

    fn phrases(&self) -> Phrases<'_> {
        Phrases { lex: self.lex, toks: &self.toks, text: self.text, room: self.draft.room.as_ref().map(|(k, _)| *k) }
    }

    fn length_at(&self, i: usize) -> Option<(f64, usize, bool)> {
        self.phrases().length_at(i)
    }

    /// "10 by 6 m", "12x12 m", "2m x 2m x 3m", "30 m by 20 m", "100 square meters",
    /// "a 4 m ceiling", and single lengths with an axis word ("2 m tall") are handled in
    /// phrases. Returns the index after what it consumed.
    fn try_dims(&mut self, i: usize) -> Result<Option<usize>, PlannerError> {
        let Some((first, mut len, mut any_unit)) = self.length_at(i) else {
            return Ok(None);
        };
        let mut values = vec![first];
        let mut unit_factor: Option<f64> = None;
        if any_unit {
            unit_factor = self.unit_factor(i + 1);
        }
        while values.len() < 3 {
            let j = i + len;
            let sep = self.toks.get(j).is_some_and(|t| t.kind == TokenKind::Times || t.is_word("by"));
            if !sep {
                break;
            }
            let Some((v, l, u)) = self.length_at(j + 1) else {
                break;
            };
            if u {
                any_unit = true;
                unit_factor = unit_factor.or_else(|| self.unit_factor(j + 2));
            }
            values.push(v);
            len += 1 + l;
        }
        // "100 square meters" / "100 m2": an area.
        if values.len() == 1 {
            let j = i + 1;
            let area_unit = matches!(self.word(j), "square" | "sq")
                && self.lookup(j + 1, |m| matches!(m, Meaning::Unit(_))).is_some();
            let m2 = matches!(self.word(j), "m2" | "m²" | "sqm");
            if area_unit || m2 {
                let factor = if m2 { 1.0 } else { self.unit_factor(j + 1).unwrap_or(1.0) };
                let area = values[0] * factor * factor;
                let end = if m2 { j + 1 } else { j + 2 };
                let text = self.span(i, end);
                if !(area.is_finite() && area > 0.0) {
                    return Err(PlannerError::InvalidSize(format!("room area must be positive, got '{text}'")));
                }
                let w = (area * 1.5).sqrt();
                self.mark(i, end);
                self.set_room_dims(vec![w, area / w], text);
                return Ok(Some(end));
            }
            // "a 4 m ceiling", "4 m high ceiling", "ceiling height of 4 m".
            let mut k = i + len;
            if matches!(self.word(k), "high" | "tall") {
                k += 1;
            }
            if matches!(self.word(k), "ceiling" | "ceilings") && any_unit {
                let text = self.span(i, k + 1);
                if !(first.is_finite() && first > 0.0) {
                    return Err(PlannerError::InvalidSize(format!("ceiling height must be positive, got '{text}'")));
                }
                self.mark(i, k + 1);
                self.draft.room_height = Some((first, text));
                return Ok(Some(k + 1));
            }
            // "a 2 m room", "a 10 m square warehouse": a square floor.
            let mut k = i + len;
            while matches!(self.word(k), "square" | "sized" | "wide") {
                k += 1;
            }
            let names_room =
                self.lookup(k, |m| matches!(m, Meaning::Room(_) | Meaning::RoomAisle(_) | Meaning::RoomWord)).is_some();
            if any_unit && names_room {
                let text = self.span(i, k);
                if !(first.is_finite() && first > 0.0) {
                    return Err(PlannerError::InvalidSize(format!("sizes must be positive lengths, got '{text}'")));
                }
                self.mark(i, k);
                self.set_room_dims(vec![first, first], text);
                return Ok(Some(k));
            }
            return Ok(None);
        }
        // Trailing unit applies to numbers written without one: "10 by 6 meter room".
        let mut end = i + len;
        if !any_unit && let Some((Meaning::Unit(f), l)) = self.lookup(end, |m| matches!(m, Meaning::Unit(_))) {
            unit_factor = Some(f);
            end += l;
        }
        if let Some(f) = unit_factor {
            // Numbers written without a unit take the phrase's unit.
            let mut j = i;
            let mut k = 0;
            while j < end && k < values.len() {
                if let Some(n) = self.toks[j].number() {
                    let has_unit = self.lookup(j + 1, |m| matches!(m, Meaning::Unit(_))).is_some();
                    if !has_unit {
                        values[k] = n * f;
                    }
                    k += 1;
                }
                j += 1;
            }
        }
        let text = self.span(i, end);
        if values.iter().any(|v| !v.is_finite() || *v <= 0.0) {
            return Err(PlannerError::InvalidSize(format!("sizes must be positive lengths, got '{text}'")));
        }
        self.mark(i, end);
        // Dimensions right after a room phrase belong to the room; before a phrase they
        // wait to see whether an object or a room follows.
        let after_room = self.subject.is_none() && self.draft.room.is_some() && self.previous_was_room(i);
        // "a table about 1.5 by 0.8 m", "a bench (2 x 1 m)": right after the group's phrase.
        let after_group = match &self.subject {
            Some(Subject::Group(g)) if self.previous_ends_group(i, g) => Some(g.clone()),
            _ => None,
        };
        if after_room {
            self.set_room_dims(values, text);
        } else if let Some(g) = after_group {
            if let Some(group) = self.draft.groups.iter_mut().find(|x| x.id == g) {
                apply_dims(&mut group.explicit, &values);
            }
        } else {
            if let Some((d, t, _)) = self.pending_dims.take() {
                self.set_room_dims(d, t);
            }
            self.pending_dims = Some((values, text, end));
        }
        Ok(Some(end))
    }

    /// "a chair, 2.2 m long", "a fridge that is 0.7 m wide", "a bench (2 m long, 80 cm
    /// deep)": a dimension after its phrase is the current group's. Returns the index after.
    fn try_trailing_size(&mut self, i: usize) -> Result<Option<usize>, PlannerError> {
        let Some(Subject::Group(g)) = self.subject.clone() else {
            return Ok(None);
        };
        let Some((v, axis, len, text)) = self.phrases().axis_length_at(i) else {
            return Ok(None);
        };
        if !(v.is_finite() && v > 0.0) {
            return Err(PlannerError::InvalidSize(format!("sizes must be positive lengths, got '{text}'")));
        }
        if let Some(group) = self.draft.groups.iter_mut().find(|x| x.id == g) {
            axis.set(&mut group.explicit, v);
        }
        self.mark(i, i + len);
        Ok(Some(i + len))
    }

    /// True when the last words before `i` (past fillers such as "about", "measuring" and
    /// punctuation) end the phrase that introduced group `g`.
    fn previous_ends_group(&self, i: usize, g: &str) -> bool {
        let Some(phrase) = self.group(g).map(|x| x.phrase.to_lowercase()) else {
            return false;
        };
        let mut j = i;
        while j > 0 {
            j -= 1;
            let t = &self.toks[j];
            let skip = matches!(t.kind, TokenKind::Comma | TokenKind::Other)
                || matches!(
                    t.norm.as_str(),
                    "about"
                        | "approximately"
                        | "roughly"
                        | "around"
                        | "measuring"
                        | "is"
                        | "that"
                        | "which"
                        | "sized"
                        | "of"
                );
            if skip {
                continue;
            }
            return t.kind == TokenKind::Word && phrase.ends_with(&t.norm);
        }
        false
    }

    fn unit_factor(&self, i: usize) -> Option<f64> {
        match self.lookup(i, |m| matches!(m, Meaning::Unit(_))) {
            Some((Meaning::Unit(f), _)) => Some(f),
            _ => None,
        }
    }

    /// True when the last used word before `i` (skipping fillers) named a room.
    fn previous_was_room(&self, i: usize) -> bool {
        let mut j = i;
        while j > 0 {
            j -= 1;
            let w = self.word(j);
            let punctuation = matches!(self.toks[j].kind, TokenKind::Comma | TokenKind::Other);
            if punctuation
                || matches!(
                    w,
                    "of" | "measuring" | "is" | "about" | "approximately" | "sized" | "with" | "that" | "size"
                )
            {
                continue;
            }
            let words = self.words_from(j);
            return self
                .lex
                .longest(&words, |m| matches!(m, Meaning::Room(_) | Meaning::RoomAisle(_) | Meaning::RoomWord))
                .is_some()
                || self.toks.get(j).is_some_and(|t| {
                    self.lex
                        .longest(&[t.norm.as_str()], |m| matches!(m, Meaning::Room(_) | Meaning::RoomWord))
                        .is_some()
                });
        }
        false
    }

    // ---------------------------------------------------------------- phrases

    /// The noun phrase starting at `i` (the phrase stage).
    fn phrase_at(&self, i: usize, allow_unknown: bool, bare: Bare) -> Result<Option<Phrase>, PlannerError> {
        self.phrases().noun_phrase(i, allow_unknown, bare)
    }

    /// Records a phrase as a room, an object group or a robot.
    fn take_phrase(&mut self, p: Phrase, start: usize) {
        self.phrase_start = start;
        if !matches!(p.head, Head::Place(_)) {
            self.in_place_clause = false;
        }
        let dims_here = self.pending_dims.take();
        if let (Some(typed), Head::Known(Meaning::Category(cat))) = (&p.fuzzy_from, &p.head) {
            self.draft.approximated.push(Approximation {
                text: typed.clone(),
                became: cat.to_string(),
                reason: format!("read '{typed}' as {}", cat.replace('_', " ")),
            });
        }
        // "the kitchen sink", "the warehouse floor": the room a modifier names.
        if let Some(k) = p.room_modifier
            && self.draft.room.is_none()
        {
            self.draft.room = Some((k, p.text.clone()));
        }

        if start < self.title_end && self.title_phrase(&p) {
            return;
        }
        match p.head.clone() {
            Head::Known(Meaning::Room(kind)) | Head::Known(Meaning::RoomAisle(kind)) => {
                if matches!(p.head, Head::Known(Meaning::RoomAisle(_))) {
                    self.draft.aisle = true;
                }
                self.draft.room_sizes.extend(p.sizes.iter().copied());
                match &self.draft.room {
                    None => self.draft.room = Some((kind, p.text.clone())),
                    Some((k, _)) if *k == kind => {}
                    Some(_) => self.draft.other_rooms.push(p.text.clone()),
                }
                if let Some((d, t, _)) = dims_here {
                    self.set_room_dims(d, t);
                }
                self.subject = None;
            }
            Head::Known(Meaning::RoomWord) => {
                self.draft.room_word = true;
                self.draft.room_sizes.extend(p.sizes.iter().copied());
                if let Some((d, t, _)) = dims_here {
                    self.set_room_dims(d, t);
                }
                self.subject = None;
            }
            Head::Known(Meaning::Robot(word)) => {
                if let Some((d, t, _)) = dims_here {
                    self.set_room_dims(d, t);
                }
                // "a robot cleaner (TurtleBot)", "robot arm (UR10e)": the same robot, named
                // more exactly in brackets.
                if start >= 1
                    && self.toks[start - 1].norm == "("
                    && let Some(Subject::Robot(prev)) = self.mentions.last().cloned()
                    && word.exact
                    && let Some(r) = self.draft.robots.get_mut(prev)
                {
                    r.word = word;
                    return;
                }
                // "a mobile robot with an arm", "a mobile base carrying a UR5e": one robot,
                // an arm on a base that drives.
                let after_with = start >= 1 && matches!(self.word(start - 1), "with" | "carrying");
                if after_with
                    && word.kind == sw_robots::RobotKind::Arm
                    && let Some(Subject::Robot(prev)) = self.subject.clone()
                    && let Some(r) = self.draft.robots.get_mut(prev)
                    && r.word.kind == sw_robots::RobotKind::MobileBase
                {
                    r.word = word;
                    r.phrase = format!("{} with {}", r.phrase, p.text);
                    self.make_mobile_manipulator(prev);
                    return;
                }
                // "the robot", "the arm": the robot already introduced.
                if self.is_definite(start)
                    && let Some(idx) = self.resolve_robot(word.wants, word.kind, !word.exact)
                {
                    self.bind(Subject::Robot(idx));
                    return;
                }
                // "two Pandas …, one robot at each side": one of the robots already named
                // (each in turn), not another robot.
                if !word.exact
                    && matches!(self.word(start), "one" | "each")
                    && p.count.is_none_or(|c| c <= 1.0)
                    && let Some(idx) =
                        self.draft.robots.iter().rposition(|r| r.plural || r.count.is_some_and(|c| c >= 2.0))
                {
                    self.bind(Subject::Robot(idx));
                    return;
                }
                let idx = self.draft.robots.len();
                let mount = if word.on_mobile_base { Mount::MobileBase } else { Mount::Auto };
                // "tables, each with a Panda on it": one on every table.
                let each = self.each_host.clone().filter(|_| self.each_taken == 0);
                let count = match &each {
                    Some(h) => self.group(h).and_then(|g| g.count).map(|c| c * p.count.unwrap_or(1.0)).or(p.count),
                    None => p.count,
                };
                self.draft.robots.push(RobotDraft {
                    word,
                    phrase: p.text.clone(),
                    count,
                    plural: p.plural || each.is_some(),
                    mount,
                    near: None,
                });
                if let Some(h) = each {
                    self.each_taken += 1;
                    self.relate(&h, RelationKind::EachWith { target: format!("@robot:{idx}") });
                    self.with_host = Some(h);
                }
                // "a table with a UR5e": on it — unless a comma ended the list first.
                let s = start;
                let broken = s >= 2 && self.toks.get(s - 2).is_some_and(|t| t.kind == TokenKind::Comma);
                // Only a work surface carries an arm ("a conveyor with three UR5es" has them
                // beside it).
                if let Some(host) = self.with_host.clone()
                    && !broken
                {
                    if self.group_is_work_surface(&host) {
                        self.draft.robots[idx].mount = Mount::OnSurface { target: host };
                    } else if self.draft.robots[idx].word.kind == sw_robots::RobotKind::Arm {
                        self.draft.robots[idx].near = Some(host);
                    }
                } else if after_with
                    && let Some(g) = self.with_subject.clone()
                    && self.draft.robots[idx].word.kind == sw_robots::RobotKind::Arm
                {
                    // "a lathe with a robot arm", "packing station with a cobot": the thing
                    // it comes with is its work.
                    self.draft.robots[idx].near = Some(g);
                }
                self.subject = Some(Subject::Robot(idx));
                self.mentions.push(Subject::Robot(idx));
                self.list.push(Subject::Robot(idx));
                self.apply_pending();
            }
            Head::Known(Meaning::Category(cat)) => {
                // "the racks", "the bench": a group already introduced.
                let raw_head =
                    p.text.split_whitespace().last().map(|h| singular(&h.to_lowercase())).unwrap_or_default();
                // "the teacher's desk" is a desk of its own, not one of the desks before.
                let possessed =
                    p.text.to_lowercase().split_whitespace().any(|w| w.ends_with("'s") || w.ends_with("s'"));
                let definite = self.is_definite(start);
                if definite
                    && !possessed
                    && let Some(g) = self.resolve_group(Some(cat), &raw_head)
                {
                    self.bind(Subject::Group(g));
                    return;
                }
                // "4 tables and 7 chairs, tables by the window": the same noun again, bare.
                if !possessed && let Some(g) = self.bare_repeat(start, &p, |g| g.category == Some(cat)) {
                    self.bind(Subject::Group(g));
                    return;
                }
                let mut explicit = p.explicit;
                if let Some((d, t, end)) = dims_here {
                    if end == start || end + 1 == start {
                        apply_dims(&mut explicit, &d);
                    } else {
                        self.set_room_dims(d, t);
                    }
                }
                if !p.descriptors.is_empty() {
                    self.draft.approximated.push(Approximation {
                        text: p.text.clone(),
                        became: cat.to_string(),
                        reason: format!(
                            "'{}' is not modelled; the object is a plain {}",
                            p.descriptors.join(" "),
                            cat.replace('_', " ")
                        ),
                    });
                }
                let id = self.new_group(Some(cat), cat.replace('_', " "), &p, explicit);
                self.standard_size(&id, cat, &p.text);
                if definite
                    && !possessed
                    && let Some(g) = self.draft.groups.last_mut()
                {
                    g.accommodated = true;
                }
                self.after_new_group(&id);
            }
            Head::Unknown(label) => {
                if self.is_definite(start)
                    && let Some(g) = self.resolve_group(None, &label)
                {
                    self.bind(Subject::Group(g));
                    return;
                }
                if let Some(g) = self.bare_repeat(start, &p, |g| g.category.is_none() && g.label == label) {
                    self.bind(Subject::Group(g));
                    return;
                }
                let mut explicit = p.explicit;
                if let Some((d, t, end)) = dims_here {
                    if end == start || end + 1 == start {
                        apply_dims(&mut explicit, &d);
                    } else {
                        self.set_room_dims(d, t);
                    }
                }
                let id = self.new_group(None, label, &p, explicit);
                self.after_new_group(&id);
            }
            Head::Known(_) => {}
            Head::Place(kind) => self.take_place(&p, kind, start),
        }
    }

    /// A bare noun (no determiner, count or modifier of its own) naming a group already
    /// introduced refers to it, as "the" would: "a tray, tray on a low table", "4 tables
    /// and 7 chairs, tables by the window". Terse lists drop articles, not nouns: a second
    /// group of the same thing is said with a count, "another", a colour or a modifier
    /// ("red and blue blocks", "an empty tote"), and the number must agree ("a box …,
    /// boxes on the shelf" are more boxes). Another noun for the same category is another
    /// thing ("milk, orange juice" are two cartons).
    fn bare_repeat(&self, start: usize, p: &Phrase, same: impl Fn(&GroupDraft) -> bool) -> Option<String> {
        let plain = p.count.is_none()
            && p.quantity.is_none()
            && p.color.is_none()
            && p.sizes.is_empty()
            && p.explicit.is_empty()
            && p.descriptors.is_empty()
            && p.room_modifier.is_none();
        let determiner = |w: &str| {
            matches!(
                w,
                "a" | "an"
                    | "another"
                    | "one"
                    | "other"
                    | "some"
                    | "any"
                    | "more"
                    | "extra"
                    | "new"
                    | "second"
                    | "third"
                    | "spare"
                    | "different"
                    | "separate"
                    | "no"
                    | "of"
            ) || number_word(w).is_some()
        };
        // The words just before the phrase that it did not take ("an empty crate").
        let before = (start.saturating_sub(2)..start)
            .rev()
            .map_while(|k| (self.toks[k].kind == TokenKind::Word).then(|| self.word(k)))
            .take_while(|w| !matches!(*w, "and" | "or" | "with" | "by" | "on" | "in" | "at" | "to"))
            .any(determiner);
        if !plain || determiner(self.word(start)) || before {
            return None;
        }
        // The same noun, not another noun for the same category ("tomato sauce, ketchup" are
        // two bottles).
        let head = |t: &str| t.split_whitespace().last().map(|w| singular(&w.to_lowercase())).unwrap_or_default();
        let g = self.draft.groups.iter().rev().find(|g| same(g) && head(&g.phrase) == head(&p.text))?;
        let group_plural = g.plural || g.count.is_some_and(|c| c > 1.0);
        (group_plural == p.plural).then(|| g.id.clone())
    }

    /// A place where an object phrase was expected ("a clear path to the door", "the
    /// corridor"): no object; what is said of it is not said of the subject before it.
    /// "An aisle with two racks" at the start of a prompt is a warehouse aisle.
    /// "a box with a lid", "a cabinet with two shelves": a noun that names a part of a
    /// thing (tables/parts.tsv), right after "with" on that thing, is its part.
    fn part_after_with(&self, start: usize, p: &Phrase) -> bool {
        let Some(Subject::Group(host)) = &self.subject else {
            return false;
        };
        let mut k = start;
        while k > 0 && (self.toks[k - 1].kind == TokenKind::Word && matches!(self.word(k - 1), "a" | "an" | "one")) {
            k -= 1;
        }
        let after_with = k > 0 && self.word(k - 1) == "with";
        let head = p.text.split_whitespace().last().map(str::to_lowercase).unwrap_or_default();
        // "with a shelf above", "with a tray beside it": a thing placed by the host, not a part.
        let placed =
            crate::cues::cue_at(&self.toks, p.end).is_some() || crate::phrase::is_adverb_particle(self.word(p.end));
        // (A door is never placed by its thing: "a cabinet with a door on the table".)
        let door = matches!(p.head, Head::Place(PlaceKind::Door));
        after_with
            && (!placed || door)
            && self.group(host).is_some_and(|g| g.category.is_some())
            // "a cabinet with a door": a thing's door, not the room's.
            && matches!(p.head, Head::Known(Meaning::Category(_)) | Head::Unknown(_) | Head::Place(PlaceKind::Door))
            && crate::tables::rows(crate::tables::PARTS).any(|r| r[0] == head)
    }

    /// The colour words listed before a phrase that starts with a colour and names a
    /// plural with no count ("red, blue and pink blocks"): (token, name, rgba) in order.
    /// Empty when there is no such list.
    fn colours_listed_before(&self, i: usize, p: &Phrase) -> Vec<(usize, &'static str, [f64; 4])> {
        if p.color.is_none() || !p.plural || p.count.is_some() || p.quantity.is_some() {
            return Vec::new();
        }
        if !matches!(self.lookup(i, |m| matches!(m, Meaning::Color(..))), Some((Meaning::Color(..), 1))) {
            return Vec::new();
        }
        let mut out = Vec::new();
        let mut k = i;
        // "and" (or "or") before the last colour, commas between the others.
        if k < 2 || !matches!(self.word(k - 1), "and" | "&" | "or") {
            return Vec::new();
        }
        k -= 1;
        while let Some(c) = k.checked_sub(1) {
            match self.lookup(c, |m| matches!(m, Meaning::Color(..))) {
                Some((Meaning::Color(name, rgba), 1)) if !self.used[c] => out.push((c, name, rgba)),
                _ => break,
            }
            k = c;
            if k >= 1 && self.toks[k - 1].kind == TokenKind::Comma {
                k -= 1;
            } else {
                break;
            }
        }
        out.reverse();
        out
    }

    /// "a bunch of grapes", "two slices of bread", "a pint of milk": a measure noun
    /// (tables/measures.tsv), "of" and a phrase with no determiner are one object — the
    /// thing measured, counted by the measure. A name the vocabulary knows whole ("a roll of
    /// tape") is left to it.
    fn try_measure_of(&mut self, i: usize) -> Result<Option<usize>, PlannerError> {
        let (n, q) = match self.toks.get(i) {
            Some(t) if t.number().is_some() => (t.number().unwrap_or(1.0), 1),
            Some(t) if matches!(t.norm.as_str(), "a" | "an" | "one") => (1.0, 1),
            Some(t) if number_word(&t.norm).is_some() => (number_word(&t.norm).unwrap_or(1.0), 1),
            _ => return Ok(None),
        };
        let m = i + q;
        let measure = self.word(m).to_string();
        if self.word(m + 1) != "of" || !crate::tables::rows(crate::tables::MEASURES).any(|r| r[0] == measure) {
            return Ok(None);
        }
        // A name the vocabulary knows whole ("a bunch of grapes"): that thing, counted by
        // the measure.
        if self.lookup(m, crate::lexicon::is_head).is_some_and(|(_, len)| len > 2) {
            let Some(mut p) = self.phrase_at(i, true, Bare::No)? else {
                return Ok(None);
            };
            p.count = Some(n);
            p.quantity = None;
            p.plural = n > 1.0;
            let end = p.end;
            self.mark(i, end);
            self.take_phrase(p, i);
            return Ok(Some(end));
        }
        let k = m + 2;
        let determiner = matches!(
            self.word(k),
            "the" | "a" | "an" | "its" | "their" | "this" | "that" | "these" | "those" | "each" | "every"
        );
        if determiner || !self.toks.get(k).is_some_and(|t| t.kind == TokenKind::Word) {
            return Ok(None);
        }
        let Some(mut p) = self.phrase_at(k, true, Bare::Target)? else {
            return Ok(None);
        };
        if p.quantity.is_some() || !matches!(p.head, Head::Known(Meaning::Category(_)) | Head::Unknown(_)) {
            return Ok(None);
        }
        p.count = Some(n);
        p.plural = n > 1.0;
        p.text = self.span(i, p.end);
        let end = p.end;
        self.mark(i, end);
        self.draft.approximated.push(Approximation {
            text: p.text.clone(),
            became: format!("{} × {}", n, self.span(k, end)),
            reason: format!("'{measure} of' measures what follows: one object each"),
        });
        self.take_phrase(p, i);
        Ok(Some(end))
    }

    fn take_place(&mut self, p: &Phrase, kind: PlaceKind, start: usize) {
        // A part of a thing ("three drawers", "its lid"): the sentence stays about the thing.
        if kind == PlaceKind::Part {
            if let (Some(Subject::Group(owner)), Some(head)) = (&self.subject, p.text.split_whitespace().last()) {
                self.parts.push((singular(&head.to_lowercase()), owner.clone()));
            }
            self.draft.approximated.push(Approximation {
                text: p.text.clone(),
                became: "a part, not an object".into(),
                reason: "a part of a thing named with it (a drawer, a lid, a shelf level) is where things go, not a thing of its own".into(),
            });
            return;
        }
        if let Some(n) = p.count.filter(|n| *n > 1.0)
            && let Some(head) = p.text.split_whitespace().last()
        {
            self.place_counts.insert(singular(&head.to_lowercase()), n);
        }
        let first_words = start <= 1 && self.draft.groups.is_empty() && self.draft.robots.is_empty();
        let aisle = p.text.to_lowercase().split_whitespace().any(|w| singular(w) == "aisle");
        if kind == PlaceKind::Path && aisle && first_words {
            self.draft.aisle = true;
            if self.draft.room.is_none() {
                self.draft.room = Some((RoomKind::Warehouse, p.text.clone()));
            }
            self.subject = None;
            return;
        }
        let (became, reason) = match kind {
            PlaceKind::Person => ("a person, not an object", "people are not modelled; nothing is added for them"),
            PlaceKind::Shape => {
                ("an arrangement, not an object", "a shape names how things stand; nothing is added for it")
            }
            _ => (
                "a place, not an object",
                "place nouns (sides, ends, walls, corridors, routes …) name where things are; nothing is added for them",
            ),
        };
        self.draft.approximated.push(Approximation {
            text: p.text.clone(),
            became: became.into(),
            reason: reason.into(),
        });
        self.subject = None;
        self.in_place_clause = true;
    }

    /// "a king-size bed", "two single beds": a size word that names a standard size of the
    /// thing (tables/kind_sizes.tsv) sets that size, unless the prompt stated one, and says
    /// so.
    fn standard_size(&mut self, id: &str, cat: &str, text: &str) {
        let lower = text.to_lowercase();
        let words: Vec<&str> = lower.split(|c: char| c.is_whitespace() || c == '-').collect();
        let Some(row) = crate::tables::rows(crate::tables::KIND_SIZES).find(|r| r[0] == cat && words.contains(&r[1]))
        else {
            return;
        };
        let Ok(v) = row[3].parse::<f64>() else { return };
        let Some(g) = self.draft.groups.iter_mut().find(|g| g.id == id) else { return };
        if g.explicit.width.is_some() || g.explicit.length.is_some() || row[2] != "width" {
            return;
        }
        g.explicit.width = Some(v);
        self.draft.approximated.push(Approximation {
            text: text.to_string(),
            became: format!("{v} m wide"),
            reason: row[4].to_string(),
        });
    }

    fn new_group(
        &mut self,
        category: Option<&'static str>,
        label: String,
        p: &Phrase,
        explicit: ExplicitSize,
    ) -> String {
        let base = match category {
            Some(c) => c.to_string(),
            None => format!("proxy_{}", label.replace([' ', '-', '\''], "_")),
        };
        let n = self.id_counts.entry(base.clone()).or_insert(0);
        *n += 1;
        let id = if *n == 1 { base.clone() } else { format!("{base}_{n}") };
        self.draft.groups.push(GroupDraft {
            id: id.clone(),
            category,
            label,
            phrase: p.text.clone(),
            count: p.count,
            plural: p.plural,
            color: p.color.clone(),
            sizes: p.sizes.clone(),
            explicit,
            count_rule: None,
            stacks: None,
            layers: None,
            accommodated: false,
        });
        self.worked_on(&id);
        id
    }

    /// A verb of handling said of a robot ("a Panda sorts …", "a UR5e picking …", "…, and
    /// places them …"): what the clause names from here on is the robot's work.
    fn note_handling_verb(&mut self, i: usize) {
        // "… a robot arm to stand it upright", "… it to close the fridge door": after "to", a
        // verb of doing something to a thing (which elsewhere is an adjective or a noun).
        if !self.handling_verb_at(i) {
            return;
        }
        // "the sorting", "two stacks": after an article, a possessive or a count the word is a
        // noun ("a Panda that sorts": "that" is a relative pronoun here).
        let prev = if i >= 1 { self.word(i - 1) } else { "" };
        if i >= 1
            && self.toks[i - 1].kind == TokenKind::Word
            && (matches!(prev, "a" | "an" | "the" | "its" | "their" | "each" | "every" | "per")
                || number_word(prev).is_some()
                || prev.chars().all(|c| c.is_ascii_digit()))
        {
            return;
        }
        // A verb that is the first word of a known noun ("sorting table", "loading dock",
        // "pick station") is that noun.
        if self.lookup(i, crate::lexicon::is_head).is_some() {
            return;
        }
        let robot = match &self.subject {
            Some(Subject::Robot(r)) => Some(*r),
            _ => None,
        };
        let continues =
            i >= 1 && (self.toks[i - 1].kind == TokenKind::Comma || matches!(self.word(i - 1), "and" | "then" | "to"));
        let Some(r) = robot.or(self.last_worker.filter(|_| continues)) else {
            return;
        };
        self.working = Some(r);
        self.last_worker = Some(r);
        // A mobile robot said to handle things has an arm: the mobile manipulator (a
        // TurtleBot named as such stays one, and one that only carries things, "brings a
        // shelf pod", "delivers parcels", needs none).
        if !crate::phrase::is_transport_verb(self.word(i))
            && self
                .draft
                .robots
                .get(r)
                .is_some_and(|x| x.word.kind == sw_robots::RobotKind::MobileBase && !x.word.exact)
        {
            self.make_mobile_manipulator(r);
        }
    }

    /// "…, franka nearby", "a robot arm close by": a robot placed by an adverb
    /// with nothing after it is placed by the scene's first thing, and works at it.
    fn try_bare_place_of_robot(&mut self, i: usize) -> Option<usize> {
        let Some(Subject::Robot(r)) = self.subject.clone() else { return None };
        let ends = |k: usize| self.toks.get(k).is_none_or(|t| matches!(t.kind, TokenKind::Stop | TokenKind::Comma));
        // (A bare "behind" is read with the arm's mount: "a panda mounted behind".)
        let len = match self.word(i) {
            "nearby" | "alongside" => 1,
            "close" | "near" if self.word(i + 1) == "by" => 2,
            _ => return None,
        };
        if !ends(i + len) {
            return None;
        }
        let first = self.draft.groups.first()?.id.clone();
        let robot = self.draft.robots.get_mut(r)?;
        if robot.near.is_some() {
            return None;
        }
        let mounted = matches!(robot.mount, Mount::OnSurface { .. });
        if !mounted {
            robot.near = Some(first.clone());
        }
        self.draft.robot_relations.push((r, RelationKind::Near { target: first }));
        self.mark(i, i + len);
        Some(i + len)
    }

    /// "a tote to its left", "parts table on its left", "bins at their right-hand side": beside
    /// what the possessive refers to (a robot included).
    fn try_possessive_side(&mut self, i: usize) -> Option<usize> {
        if !matches!(self.word(i), "to" | "on" | "at" | "by") || !matches!(self.word(i + 2), "left" | "right" | "side")
        {
            return None;
        }
        let pronoun = match self.word(i + 1) {
            "its" => "it",
            "their" => "they",
            _ => return None,
        };
        let mut end = i + 3;
        if self.word(end) == "hand" {
            end += 1;
        }
        if self.word(end) == "side" && self.word(i + 2) != "side" {
            end += 1;
        }
        let subject = self.subject.clone()?;
        let mut target = match self.resolve_pronoun(pronoun)? {
            Subject::Group(g) => g,
            Subject::Robot(r) => format!("@robot:{r}"),
        };
        // Parallel sides share their referent: "a tote to its left and another tote to its
        // right" are both beside what the first "its" was, not the second beside the first.
        if let Some((placed, before)) = &self.last_possessive {
            let placed_id = match placed {
                Subject::Group(g) => g.clone(),
                Subject::Robot(r) => format!("@robot:{r}"),
            };
            let own = match &subject {
                Subject::Group(g) => g.clone(),
                Subject::Robot(r) => format!("@robot:{r}"),
            };
            if placed_id == target && *before != own && *placed != subject {
                target = before.clone();
            }
        }
        self.last_possessive = Some((subject.clone(), target.clone()));
        self.mark(i, end);
        // "a desk with … a book to its left": a side of the host it stands on, where it stays.
        let on_it =
            matches!(&subject, Subject::Group(g) if self.implicit_on.iter().any(|(x, h)| x == g && *h == target));
        if !on_it {
            self.apply(&subject, Cue::NextTo, vec![target]);
        }
        Some(end)
    }

    /// Whether the word at `i` is a verb of handling: one of the known verbs, or after "to"
    /// a verb of operating a thing ("to open it", "to stand it upright").
    fn handling_verb_at(&self, i: usize) -> bool {
        let w = self.word(i);
        if crate::phrase::is_handling_verb(w) {
            return true;
        }
        i >= 1
            && self.word(i - 1) == "to"
            && crate::phrase::is_operating_verb(w)
            && self.toks.get(i + 1).is_some_and(|t| t.kind == TokenKind::Word)
    }

    /// "a sawyer arm to open it", "a UR5e unloading them": the thing a pronoun after a verb
    /// of handling refers to is the robot's work.
    fn pronoun_worked_on(&mut self, i: usize) {
        if self.working.is_none() || self.used[i] || i == 0 || !self.handling_verb_at(i - 1) {
            return;
        }
        let w = self.word(i).to_string();
        if !matches!(w.as_str(), "it" | "them") {
            return;
        }
        if let Some(Subject::Group(g)) = self.resolve_pronoun(&w) {
            self.worked_on(&g);
            self.used[i] = true;
        }
    }

    /// A thing named in a robot's clause of handling is its work: the robot reaches it.
    fn worked_on(&mut self, id: &str) {
        let Some(r) = self.working else { return };
        if !self.work.iter().any(|(x, g)| *x == r && g == id) {
            self.work.push((r, id.to_string()));
        }
    }

    /// Makes an already introduced group or robot the subject again ("The racks …").
    fn bind(&mut self, s: Subject) {
        if let Subject::Group(g) = &s {
            self.worked_on(&g.clone());
        }
        self.subject = Some(s.clone());
        self.mentions.push(s.clone());
        self.list.push(s);
        self.collective = None;
        self.apply_pending();
    }

    fn after_new_group(&mut self, id: &str) {
        self.take_collective(id);
        if let Some(host) = self.each_host.clone() {
            // "each with a stool and a lamp": the list right after "each with" only.
            let s = self.phrase_start;
            let and_only = s >= 2
                && matches!(self.word(s - 1), "and" | "plus")
                && self.toks.get(s - 2).is_some_and(|t| t.kind != TokenKind::Comma);
            // "each bench with a sink and 2 stools": the list joined by "and" (no comma
            // before it, which would start something new).
            let joined = self.each_taken == 0 || and_only;
            if joined {
                self.each_taken += 1;
                // "each loaded with boxes" (no count): a load, not one per host.
                let uncounted_load = self.support.is_some() && self.group(id).is_some_and(|g| g.count.is_none());
                if !uncounted_load {
                    self.add_companion(&host, id);
                }
                if self.support.is_some() {
                    self.take_support(&host, id);
                    self.relate(id, RelationKind::On { target: host.clone() });
                }
                // "each with a monitor on it": what follows is said of the companion.
                self.subject = Some(Subject::Group(id.to_string()));
                self.mentions.push(Subject::Group(id.to_string()));
                return;
            }
            self.each_host = None;
        }
        // A load ("stocked with bins") is the list right after it, joined by "and".
        let s = self.phrase_start;
        let comma_break = s >= 1 && self.toks.get(s - 1).is_some_and(|t| t.kind == TokenKind::Comma)
            || s >= 2
                && matches!(self.word(s - 1), "and")
                && self.toks.get(s - 2).is_some_and(|t| t.kind == TokenKind::Comma);
        if self.support.is_some() && self.support_taken > 0 && comma_break {
            self.with_host = None;
            self.support = None;
        }
        if let Some(host) = self.with_host.clone()
            && self.group_is_small(id)
        {
            self.relate(id, RelationKind::On { target: host.clone() });
            self.implicit_on.push((id.to_string(), host.clone()));
            self.on_host.push((id.to_string(), host.clone()));
            self.take_support(&host, id);
            self.support_taken += 1;
        } else {
            self.with_host = None;
            self.support = None;
        }
        self.subject = Some(Subject::Group(id.to_string()));
        self.mentions.push(Subject::Group(id.to_string()));
        self.list.push(Subject::Group(id.to_string()));
        self.apply_pending();
    }

    fn group(&self, id: &str) -> Option<&GroupDraft> {
        self.draft.groups.iter().find(|g| g.id == id)
    }

    fn group_has_surface(&self, id: &str) -> bool {
        self.group(id).and_then(|g| g.category).and_then(sw_catalog::find).is_some_and(|c| {
            matches!(c.placement, PlacementKind::Floor | PlacementKind::AgainstWall) && c.has_tag("surface")
                || c.has_tag("storage")
                || (c.has_tag("container") && c.has_tag("open"))
        })
    }

    /// A table, bench or counter: what an arm can stand on.
    fn group_is_work_surface(&self, id: &str) -> bool {
        self.group(id)
            .and_then(|g| g.category)
            .and_then(sw_catalog::find)
            .is_some_and(|c| c.has_tag("surface") && c.has_tag("furniture"))
    }

    fn group_is_small(&self, id: &str) -> bool {
        match self.group(id) {
            Some(GroupDraft { category: Some(c), .. }) => {
                sw_catalog::find(c).is_some_and(|c| c.placement == PlacementKind::OnSurface)
            }
            Some(GroupDraft { category: None, label, .. }) => crate::priors::prior_for(label, false).movable,
            None => false,
        }
    }

    fn relate(&mut self, subject: &str, kind: RelationKind) {
        let also = crate::said::implied(&kind);
        let entry = (subject.to_string(), kind);
        if !self.draft.relations.contains(&entry) {
            self.draft.relations.push(entry);
        }
        if let Some(k) = also {
            self.relate(subject, k);
        }
    }
}

/// "a 4.5 m conveyor" (its length), "a 2 x 1 m table" (length and width), "a 1.2 x 0.8 x
/// 0.9 m crate" (and height).
fn apply_dims(e: &mut ExplicitSize, d: &[f64]) {
    if let Some(l) = d.first() {
        e.length = Some(*l);
    }
    if let Some(v) = d.get(1) {
        e.width = Some(*v);
    }
    if let Some(h) = d.get(2) {
        e.height = Some(*h);
    }
}
