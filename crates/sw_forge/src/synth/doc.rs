//! A prompt read into sentences and quantities: every length with what it measures (its
//! role), the words that qualify it and the axis it is given along; coordinates and
//! coordinate ranges ("Z=3 to Z=33"), tuples ("(±60, 0)"), angles and counts. Every token
//! the reader uses is marked, so what is left unread can be named exactly.

use std::cell::RefCell;

use super::solid::Axis;
use super::text::{Tk, Token, tokenize};

/// What a length measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Role {
    Length,
    Width,
    Height,
    Thickness,
    Depth,
    Diameter,
    Radius,
    Side,
    Fillet,
    Chamfer,
    Inset,
    Spacing,
    /// A length with no role word near it ("100mm by 60mm", "6.93mm across corners").
    Bare,
}

pub fn role_of(word: &str) -> Option<Role> {
    Some(match word {
        "long" | "length" | "extruded" | "extrude" => Role::Length,
        "wide" | "width" | "broad" => Role::Width,
        "tall" | "high" | "height" => Role::Height,
        "thick" | "thickness" => Role::Thickness,
        "deep" | "depth" => Role::Depth,
        // "50 mm OD, 40 mm ID": outer and inner diameters.
        "diameter" | "od" | "id" => Role::Diameter,
        "radius" => Role::Radius,
        "side" | "sided" => Role::Side,
        "fillet" | "filleted" | "rounded" | "radiused" => Role::Fillet,
        "chamfer" | "chamfered" | "bevel" | "bevelled" | "beveled" => Role::Chamfer,
        "inset" | "offset" => Role::Inset,
        "spacing" | "spaced" | "interval" | "apart" | "pitch" => Role::Spacing,
        _ => return None,
    })
}

/// Words that qualify a length (its own phrase) — "outer diameter", "tip circle".
pub const QUALS: &[&str] = &[
    "outer",
    "outside",
    "inner",
    "inside",
    "bore",
    "hole",
    "tip",
    "root",
    "pitch",
    "bolt",
    "circle",
    "circumscribed",
    "across",
    "corner",
    "flat",
    "major",
    "minor",
    "face",
    "wall",
    "base",
    "top",
    "bottom",
    "head",
    "shaft",
    "total",
    "overall",
    "counterbore",
    "countersink",
    "radial",
    "radially",
    "axial",
    "center",
    "inscribed",
    "hub",
    "flange",
    "web",
    "leg",
    "end",
    "each",
    "both",
    "all",
    "vertical",
    "horizontal",
    "long",
    "short",
    "edge",
    "circular",
    "cross-section",
    "opening",
    "neck",
    "belly",
    "shoulder",
    "rim",
    "slot",
    "keyway",
    "groove",
    "pocket",
    "recess",
    "socket",
    "boss",
    "post",
    "arm",
    "fin",
    "rib",
    "plate",
    "disc",
    "body",
    "seat",
    "journal",
    "section",
    "tooth",
    "extruded",
    "metric",
    "tapped",
    "clearance",
    "thread",
    "key",
    "gasket",
    "mount",
    "motor",
    "spoke",
    "rail",
    "cap",
    "ring",
    "pattern",
    "counterbored",
    "countersunk",
    "wall",
];

/// Words that end the phrase after a length.
fn is_stop(word: &str) -> bool {
    matches!(
        word,
        "and"
            | "with"
            | "on"
            | "at"
            | "of"
            | "from"
            | "through"
            | "to"
            | "in"
            | "by"
            | "into"
            | "onto"
            | "is"
            | "are"
            | "for"
            | "that"
            | "which"
            | "then"
            | "where"
            | "running"
            | "runs"
            | "spanning"
            | "starting"
            | "rising"
    )
}

/// A length in the prompt.
#[derive(Debug, Clone, PartialEq)]
pub struct Dim {
    pub tok: usize,
    pub mm: f64,
    pub role: Role,
    /// Qualifying words of its phrase.
    pub quals: Vec<String>,
    /// The axis named with it: "60mm (X)", "along Z", "in the Y direction".
    pub axis: Option<Axis>,
    /// Inside parentheses (a restatement).
    pub paren: bool,
    /// Written "±" / "+/-".
    pub pm: bool,
    /// Part of an "A x B (x C)" list: (list id, position).
    pub list: Option<(usize, usize)>,
    /// The tokens of its phrase (for marking them read).
    pub phrase: (usize, usize),
    /// In parentheses right after another length, restating it ("40mm tip diameter
    /// (20mm radius)"): never used to build, only checked.
    pub restates: Option<usize>,
}

impl Dim {
    pub fn has(&self, q: &str) -> bool {
        self.quals.iter().any(|w| w == q)
    }
}

/// "Z=3 to Z=33", "from X=0 to X=30": a span along an axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Range {
    pub axis: Axis,
    pub a: f64,
    pub b: f64,
    pub toks: (usize, usize),
}

/// A coordinate "X=+25" (not part of a range).
#[derive(Debug, Clone, PartialEq)]
pub struct Coord {
    pub axis: Axis,
    pub v: f64,
    pub tok: usize,
}

/// "(±60, 0)", "(40,40)", "(X=+25, Y=20)": numbers in parentheses, with their axes when
/// named, and whether each is ±.
#[derive(Debug, Clone, PartialEq)]
pub struct Tuple {
    pub vals: Vec<(Option<Axis>, f64, bool)>,
    pub toks: (usize, usize),
}

/// The prompt read.
#[derive(Debug)]
pub struct Doc {
    pub text: String,
    pub toks: Vec<Token>,
    /// Sentence of each token.
    pub sent: Vec<usize>,
    /// Parenthesis depth of each token.
    pub depth: Vec<u8>,
    pub dims: Vec<Dim>,
    pub ranges: Vec<Range>,
    pub coords: Vec<Coord>,
    pub tuples: Vec<Tuple>,
    /// Tokens read so far.
    used: RefCell<Vec<bool>>,
}

fn axis_word(w: &str) -> Option<Axis> {
    match w {
        "x" | "+x" | "-x" => Some(Axis::X),
        "y" | "+y" | "-y" => Some(Axis::Y),
        "z" | "+z" | "-z" => Some(Axis::Z),
        _ => None,
    }
}

impl Doc {
    pub fn new(prompt: &str) -> Self {
        let toks = tokenize(prompt);
        let mut sent = Vec::with_capacity(toks.len());
        let mut depth = Vec::with_capacity(toks.len());
        let (mut s, mut d) = (0usize, 0u8);
        for t in &toks {
            if t.is_sym('(') {
                d = d.saturating_add(1);
            }
            sent.push(s);
            depth.push(d);
            if t.is_sym(')') {
                d = d.saturating_sub(1);
            }
            // A full stop, or a question or an exclamation ("… a lamp base? Round, 120 across").
            if (t.is_sym('.') || t.is_sym('?') || t.is_sym('!')) && d == 0 {
                s += 1;
            }
        }
        let n = toks.len();
        let mut doc = Doc {
            text: prompt.to_string(),
            toks,
            sent,
            depth,
            dims: Vec::new(),
            ranges: Vec::new(),
            coords: Vec::new(),
            tuples: Vec::new(),
            used: RefCell::new(vec![false; n]),
        };
        doc.read_coordinates();
        doc.read_tuples();
        let tuples = doc.tuples.clone();
        doc.coords.retain(|c| !tuples.iter().any(|t| c.tok >= t.toks.0 && c.tok < t.toks.1));
        doc.read_dims();
        doc
    }

    pub fn len(&self) -> usize {
        self.toks.len()
    }

    pub fn is_empty(&self) -> bool {
        self.toks.is_empty()
    }

    pub fn word(&self, i: usize) -> Option<&str> {
        self.toks.get(i).and_then(Token::word)
    }

    pub fn is(&self, i: usize, w: &str) -> bool {
        self.word(i) == Some(w)
    }

    pub fn sym(&self, i: usize, c: char) -> bool {
        self.toks.get(i).is_some_and(|t| t.is_sym(c))
    }

    /// The axis a token names: "X" is read as the times sign, so both count.
    pub fn axis_at(&self, i: usize) -> Option<Axis> {
        if self.sym(i, 'x') {
            return Some(Axis::X);
        }
        self.word(i).and_then(axis_word)
    }

    pub fn sentences(&self) -> usize {
        self.sent.last().map_or(0, |s| s + 1)
    }

    /// Token range [start, end) of sentence `s`.
    pub fn sentence(&self, s: usize) -> (usize, usize) {
        let start = self.sent.iter().position(|x| *x == s).unwrap_or(self.toks.len());
        let end = self.sent.iter().rposition(|x| *x == s).map_or(start, |e| e + 1);
        (start, end)
    }

    pub fn mark(&self, i: usize) {
        if let Some(u) = self.used.borrow_mut().get_mut(i) {
            *u = true;
        }
    }

    pub fn mark_range(&self, a: usize, b: usize) {
        let mut u = self.used.borrow_mut();
        for k in a..b.min(u.len()) {
            u[k] = true;
        }
    }

    pub fn is_used(&self, i: usize) -> bool {
        self.used.borrow().get(i).copied().unwrap_or(true)
    }

    /// The prompt's words from token `a` to token `b` (inclusive).
    pub fn quote(&self, a: usize, b: usize) -> String {
        let (Some(s), Some(e)) = (self.toks.get(a), self.toks.get(b.min(self.toks.len().saturating_sub(1)))) else {
            return String::new();
        };
        self.text.get(s.start..e.end).unwrap_or("").trim().to_string()
    }

    /// The first token at or after `from` (before `to`) that is the word `w`.
    pub fn find(&self, w: &str, from: usize, to: usize) -> Option<usize> {
        (from..to.min(self.len())).find(|i| self.is(*i, w))
    }

    fn num(&self, i: usize) -> Option<(f64, Option<f64>, bool)> {
        match self.toks.get(i)?.kind {
            Tk::Num { v, unit, pm, .. } => Some((v, unit, pm)),
            _ => None,
        }
    }

    fn read_coordinates(&mut self) {
        let n = self.toks.len();
        let mut coords = Vec::new();
        for i in 0..n.saturating_sub(2) {
            if let (Some(a), true, Some((v, Some(f), _))) = (self.axis_at(i), self.sym(i + 1, '='), self.num(i + 2)) {
                coords.push(Coord { axis: a, v: v * f, tok: i });
                // "X = -24, -12, 0, 12, 24mm": more of the same axis. Each is read as if
                // written "X=v" (its token is the number's, minus two).
                let mut j = i + 3;
                while self.sym(j, ',') || self.is(j, "and") {
                    let mut k = j + 1;
                    if self.is(k, "and") {
                        k += 1;
                    }
                    // Items without a unit, or a last one with it ("24mm)").
                    let last_ok = |k: usize| self.sym(k + 1, ')') || self.sym(k + 1, '.') || k + 1 >= n;
                    match self.num(k) {
                        Some((w, u, _)) if !self.sym(k + 1, '=') && (u.is_none() || last_ok(k)) => {
                            coords.push(Coord { axis: a, v: w * u.unwrap_or(f), tok: k - 2 });
                            j = k + 1;
                        }
                        _ => break,
                    }
                }
            }
        }
        // Ranges: two coordinates of one axis joined by "to" (or "-"), optionally "up".
        let mut used = vec![false; coords.len()];
        for k in 0..coords.len() {
            if used[k] {
                continue;
            }
            if let Some(l) = (k + 1..coords.len()).find(|l| coords[*l].axis == coords[k].axis && !used[*l]) {
                if coords[k].tok + 3 > coords[l].tok {
                    continue;
                }
                let between = &self.toks[coords[k].tok + 3..coords[l].tok];
                // "Z=0 to Z=10", "from the inner floor (Z=2) to the rim height (Z=30)".
                let joined = !between.is_empty()
                    && (between.len() <= 3
                        && between
                            .iter()
                            .all(|t| matches!(t.word(), Some("to" | "up" | "down" | "through")) || t.is_sym('-'))
                        || between.len() <= 9
                            && between.iter().any(|t| t.is_word("to"))
                            && between.iter().all(|t| t.word().is_some() || t.is_sym('(') || t.is_sym(')')));
                if joined {
                    used[k] = true;
                    used[l] = true;
                    self.ranges.push(Range {
                        axis: coords[k].axis,
                        a: coords[k].v,
                        b: coords[l].v,
                        toks: (coords[k].tok, coords[l].tok + 3),
                    });
                }
            }
        }
        self.coords = coords.into_iter().zip(used).filter(|(_, u)| !u).map(|(c, _)| c).collect();
    }

    fn read_tuples(&mut self) {
        let n = self.toks.len();
        let mut i = 0;
        while i < n {
            if !self.sym(i, '(') {
                i += 1;
                continue;
            }
            let Some(close) = (i + 1..n).find(|j| self.sym(*j, ')') || self.sym(*j, '(')) else { break };
            if !self.sym(close, ')') {
                i = close;
                continue;
            }
            // Numbers separated by commas, each optionally "A=".
            let mut vals = Vec::new();
            let mut j = i + 1;
            let mut ok = true;
            while j < close {
                let mut axis = None;
                if let (Some(a), true) = (self.axis_at(j), self.sym(j + 1, '=')) {
                    axis = Some(a);
                    j += 2;
                }
                match self.num(j) {
                    Some((v, f, pm)) => vals.push((axis, v * f.unwrap_or(1.0), pm)),
                    None => {
                        ok = false;
                        break;
                    }
                }
                j += 1;
                if j < close && !self.sym(j, ',') {
                    ok = false;
                    break;
                }
                j += 1;
            }
            if ok && vals.len() >= 2 {
                self.tuples.push(Tuple { vals, toks: (i, close + 1) });
            }
            i = close + 1;
        }
    }

    fn in_tuple_or_coord(&self, i: usize) -> bool {
        self.tuples.iter().any(|t| i >= t.toks.0 && i < t.toks.1)
            || self.ranges.iter().any(|r| i >= r.toks.0 && i < r.toks.1)
            || self.coords.iter().any(|c| i >= c.tok && i < c.tok + 3)
    }

    fn read_dims(&mut self) {
        let n = self.toks.len();
        let nums: Vec<usize> = (0..n)
            .filter(|i| matches!(self.toks[*i].kind, Tk::Num { unit: Some(_), .. }) && !self.in_tuple_or_coord(*i))
            .collect();
        let all_nums: Vec<usize> =
            (0..n).filter(|i| matches!(self.toks[*i].kind, Tk::Num { .. } | Tk::Deg(_))).collect();
        let mut dims = Vec::new();
        for &i in &nums {
            let Some((v, Some(f), pm)) = self.num(i) else { continue };
            let next_num = all_nums.iter().copied().find(|k| *k > i).unwrap_or(n);
            let prev_num = all_nums.iter().copied().rev().find(|k| *k < i);
            // The phrase after: to a stop word, punctuation or the next number.
            let mut after = Vec::new();
            let mut axis = None;
            let mut j = i + 1;
            while j < next_num.min(n) {
                match &self.toks[j].kind {
                    Tk::Word(w) => {
                        // "60mm in diameter", "80mm on each side" read on.
                        if is_stop(w) && !(after.is_empty() && (w == "in" || w == "on")) {
                            // "along the X axis", "in the Y direction": the axis, then stop.
                            if (w == "along" || w == "in")
                                && axis.is_none()
                                && let Some(a) = self
                                    .word(j + 1)
                                    .and_then(axis_word)
                                    .or_else(|| self.word(j + 2).and_then(axis_word))
                            {
                                axis = Some(a);
                            }
                            break;
                        }
                        if w == "along" {
                            if let Some(a) =
                                self.word(j + 1).and_then(axis_word).or_else(|| self.word(j + 2).and_then(axis_word))
                            {
                                axis = Some(a);
                            }
                            break;
                        }
                        after.push((j, w.clone()));
                    }
                    Tk::Sym('(') => {
                        // "(X)", "(Y, matching the base)", "(in X)", "(in the Y direction)".
                        let mut q = j + 1;
                        while matches!(self.word(q), Some("in" | "the" | "along")) {
                            q += 1;
                        }
                        if (self.sym(q + 1, ')')
                            || self.sym(q + 1, ',')
                            || self.is(q + 1, "direction")
                            || self.is(q + 1, "axis"))
                            && let Some(a) = self.axis_at(q)
                        {
                            axis = Some(a);
                            j = q + 1;
                        }
                        break;
                    }
                    Tk::Sym('-') => {}
                    // "30mm in X": the axis (X reads as a times sign).
                    Tk::Sym('x') if after.last().is_some_and(|(_, w): &(usize, String)| w == "in" || w == "along") => {
                        axis = Some(Axis::X);
                        j += 1;
                        break;
                    }
                    _ => break,
                }
                j += 1;
            }
            let after_end = j;
            // The phrase before: back to the previous number, punctuation or a clause break.
            let mut before = Vec::new();
            let mut j = i;
            let floor = prev_num.map_or(0, |p| p + 1);
            while j > floor {
                j -= 1;
                // A role written as a symbol with the number before ("Ø20 x 50": the 20's).
                if j > 0
                    && self.toks[j].start == self.toks[j - 1].start
                    && matches!(self.toks[j - 1].kind, Tk::Num { .. })
                {
                    break;
                }
                // "0.125 in wall x 10 in long": the words before the times sign are the previous number's.
                if self.toks[j].is_sym('x') && before.is_empty() && j > floor && self.word(j - 1).is_some() {
                    break;
                }
                match &self.toks[j].kind {
                    Tk::Word(w) if w == "and" || w == "with" || w == "has" || w == "have" => break,
                    // "a 100 mm length of 20 mm bar": the role before "of" is the earlier number's.
                    Tk::Word(w)
                        if w == "of"
                            && j >= 2
                            && self.word(j - 1).is_some_and(|r| role_of(r).is_some())
                            && matches!(self.toks[j - 2].kind, Tk::Num { .. }) =>
                    {
                        break;
                    }
                    Tk::Word(w) => before.push((j, w.clone())),
                    Tk::Sym('x') => {}
                    _ => break,
                }
            }
            before.reverse();
            let before_start = before.first().map_or(i, |b| b.0);
            // "on the long centreline": "long" names the line, not a length.
            let before: Vec<(usize, String)> = before
                .into_iter()
                .filter(|(j, w)| {
                    !(w == "long" && matches!(self.word(j + 1), Some("centerline" | "edge" | "side" | "axis")))
                })
                .collect();
            // After it, a role word counts only before the noun it sizes ("6mm holes equally
            // spaced": the 6mm is the holes', not a spacing).
            let heads = |k: usize| {
                let (_, w) = &after[k];
                let qualifier = after.get(k + 1).is_some_and(|(_, n)| role_of(n).is_some_and(|r| r != Role::Spacing));
                matches!(super::lexicon::noun(w), Some(n) if n != super::lexicon::Noun::Pattern) && !qualifier
            };
            let cut = (0..after.len()).find(|k| heads(*k)).unwrap_or(after.len());
            let upto_noun: Vec<&(usize, String)> = after[..cut].iter().collect();
            // "10 on one side": which side, not a square's side.
            let one_side =
                after.windows(2).any(|p| matches!(p[0].1.as_str(), "one" | "either" | "the") && p[1].1 == "side");
            let role = after
                .first()
                .and_then(|(_, w)| role_of(w))
                .filter(|r| !(one_side && *r == Role::Side))
                .or_else(|| before.last().and_then(|(_, w)| role_of(w)))
                .or_else(|| upto_noun.iter().find_map(|(_, w)| role_of(w)).filter(|r| !(one_side && *r == Role::Side)))
                // Before it, back to a noun ("10 mm deep pocket 50 mm": not the pocket's depth).
                .or_else(|| {
                    before
                        .iter()
                        .rev()
                        .take_while(|(_, w)| {
                            super::lexicon::noun(w).is_none()
                                && !matches!(w.as_str(), "on" | "at" | "from" | "in" | "to")
                        })
                        .find_map(|(_, w)| role_of(w))
                })
                .unwrap_or(Role::Bare);
            // "extruded to a height of", "pitch circle diameter": the later, more specific word wins.
            let role = match role {
                Role::Length if before.iter().any(|(_, w)| w == "height") => Role::Height,
                // (Not a hole's "6.5 dia" before the spacing: "6.5 dia at 50 ctrs".)
                Role::Spacing
                    if after.iter().any(|(_, w)| w == "circle" || w == "diameter")
                        || before.iter().any(|(_, w)| w == "circle")
                        || before.last().is_some_and(|(_, w)| w == "diameter") =>
                {
                    if after.iter().chain(before.iter()).any(|(_, w)| w == "radius") {
                        Role::Radius
                    } else {
                        Role::Diameter
                    }
                }
                r => r,
            };
            if axis.is_none() {
                for (k, (_, w)) in after.iter().enumerate() {
                    if (w == "in" || w == "along")
                        && let Some((_, a)) = after.get(k + 1)
                    {
                        axis = axis_word(a).or(axis);
                    }
                }
            }
            if axis.is_none() {
                for (k, (_, w)) in before.iter().enumerate() {
                    if (w == "along" || w == "in")
                        && let Some((_, a)) = before.get(k + 1)
                    {
                        axis = axis_word(a).or(axis);
                    }
                }
            }
            let mut quals: Vec<String> = before
                .iter()
                .chain(after.iter())
                .map(|(_, w)| match w.as_str() {
                    "inside" => "inner".to_string(),
                    "outside" | "od" => "outer".to_string(),
                    "id" => "inner".to_string(),
                    _ => w.clone(),
                })
                .filter(|w| QUALS.contains(&w.as_str()))
                .collect();
            // "(22.5mm radius from center)": a distance from the centre, not a size.
            let mut q = after_end;
            if after.len() <= 1 && self.is(q, "from") {
                q += 1;
                if self.is(q, "the") {
                    q += 1;
                }
                if self.is(q, "center") || self.is(q, "origin") || self.is(q, "axis") {
                    quals.push("from-center".into());
                }
            }
            // "R5", "R2 on OD": a radius called out on a drawing rounds edges.
            let role = if role == Role::Radius
                && self.toks.get(i + 1).is_some_and(|t| t.is_word("radius") && t.start == self.toks[i].start)
                && !after.iter().any(|(_, w)| {
                    super::lexicon::noun(w).is_some_and(|n| !matches!(n, super::lexicon::Noun::Body(_)))
                        && w != "corner"
                        && w != "edge"
                }) {
                Role::Fillet
            } else {
                role
            };
            // "1 x 45°", "1 mm 45° chamfer": a chamfer's size before its angle.
            let role = if matches!(self.toks.get(i + 1).map(|t| &t.kind), Some(Tk::Deg(_))) && role == Role::Bare {
                Role::Chamfer
            } else {
                role
            };
            // "10 from edges", "20 from each end", "12 in from the sides": an inset.
            let role = {
                let mut q = after_end;
                if self.is(q, "in") {
                    q += 1;
                }
                let from = self.is(q, "from");
                let height = matches!(self.word(q), Some("above" | "below" | "over" | "under" | "up"));
                while matches!(
                    self.word(q + 1),
                    Some("each" | "the" | "both" | "all" | "either" | "its" | "from" | "one" | "an" | "a")
                ) {
                    q += 1;
                }
                if role == Role::Bare
                    && from
                    && matches!(self.word(q + 1), Some("edge" | "end" | "side" | "corner" | "face"))
                {
                    Role::Inset
                } else if matches!(role, Role::Bare | Role::Height)
                    && (height || from)
                    && matches!(self.word(q + 1), Some("base" | "bottom" | "underside" | "floor" | "top"))
                    // (Not "28 above the base top", "30 above the top": heights from a face
                    // that is not the part's bottom, nor up from the part's top.)
                    && !(self.is(q + 1, "base") && self.is(q + 2, "top"))
                    && !(self.is(q + 1, "top") && matches!(self.word(q), Some("above" | "over" | "up")))
                {
                    // "its centre 30 above the base": a height on the part, from its bottom (or
                    // "20 below the top", from its top).
                    quals.push(if self.is(q + 1, "top") { "from-top".into() } else { "from-bottom".into() });
                    Role::Inset
                } else {
                    role
                }
            };
            // "120 across", "45 inside", "50 outside": a diameter; "16 square": a side.
            let past_the = |k: usize| after.iter().map(|(_, w)| w.as_str()).filter(|w| *w != "the").nth(k);
            let role = match (role, after.first().map(|(_, w)| w.as_str()), past_the(1)) {
                (Role::Bare, Some("across"), next) if !matches!(next, Some("flat" | "corner")) => Role::Diameter,
                // Not the last of a list ("60 x 40 outside": the box's outside).
                (Role::Bare, Some("inside" | "outside"), _)
                    if !(i > 0 && (self.sym(i - 1, 'x') || self.is(i - 1, "by"))) =>
                {
                    Role::Diameter
                }
                // "on 31 mm square centres": the corners of a square, a spacing.
                (Role::Bare, Some("square"), Some("spacing" | "pattern" | "pitch" | "center")) => {
                    quals.push("square".into());
                    Role::Spacing
                }
                (Role::Bare, Some("square"), next)
                    if next.is_none_or(|w| super::lexicon::noun(w).is_none())
                        || matches!(next, Some("base" | "top" | "bottom" | "end" | "section")) =>
                {
                    Role::Side
                }
                (r, ..) => r,
            };
            // "M4 clearance holes": the screw's clearance diameter; "a 95 mm bolt circle": the
            // circle's diameter.
            let role = if (matches!(role, Role::Bare | Role::Diameter)
                && quals.iter().any(|w| w == "metric" || w == "tapped"))
                || (role == Role::Bare && quals.iter().any(|w| w == "circle"))
            {
                Role::Diameter
            } else {
                role
            };
            // "counterbored to 14mm diameter", "countersunk to 8mm".
            for (from, to) in [("counterbored", "counterbore"), ("countersunk", "countersink")] {
                if before.iter().chain(after.iter()).any(|(_, w)| w == from) && !quals.iter().any(|q| q == to) {
                    quals.push(to.into());
                }
            }
            // "a 3 mm wall", "with 3mm walls", "1 in OD x 16 SWG wall": a wall thickness.
            let (role, wall) =
                if after.first().is_some_and(|(_, w)| w == "wall") { (Role::Thickness, true) } else { (role, false) };
            if wall && !quals.iter().any(|q| q == "wall") {
                quals.push("wall".into());
            }
            dims.push(Dim {
                tok: i,
                mm: v * f,
                role,
                quals,
                axis,
                paren: self.depth[i] > 0,
                pm,
                list: None,
                phrase: (before_start, after_end),
                restates: None,
            });
        }
        // "spaced 30mm in X and 25mm in Y": the second is a spacing too.
        for k in 1..dims.len() {
            if dims[k].role == Role::Bare && dims[k - 1].role == Role::Spacing && dims[k].axis.is_some() {
                let between = &self.toks[dims[k - 1].phrase.1.min(dims[k].tok)..dims[k].tok];
                if between.iter().all(|t| t.is_word("and") || t.is_sym(',')) {
                    dims[k].role = Role::Spacing;
                }
            }
        }
        // A length in parentheses just after another restates it.
        for k in 1..dims.len() {
            let (p, d) = (&dims[k - 1], &dims[k]);
            let opens = (p.tok + 1..d.tok).any(|i| self.sym(i, '('));
            if d.paren && opens && d.tok <= p.tok + 6 && !p.has("metric") && !d.has("metric") {
                dims[k].restates = Some(k - 1);
            }
        }
        // "Four M4 clearance holes (4.2mm diameter)", "M8: inside dia 8.4": a diameter stated
        // right after the screw size wins over the table's.
        let mut k = 0;
        while k < dims.len() {
            let at = dims[k].tok;
            let stated = dims[k].has("metric")
                && dims.iter().any(|d| {
                    let after = d.tok > at
                        && d.tok <= at + 8
                        && (at + 1..d.tok)
                            .all(|j| self.word(j).is_none_or(|w| super::lexicon::noun(w).is_none() || w == "hole"));
                    // "a 3.2mm diameter pilot hole (M3 clearance)".
                    let before = self.depth[at] > 0 && d.tok < at && d.tok + 8 >= at;
                    !d.has("metric")
                        && d.role == Role::Diameter
                        && !d.has("pitch")
                        && !d.has("circle")
                        && (after || before)
                });
            if stated {
                let t = dims[k].tok;
                self.used.borrow_mut()[t] = true;
                if t > 0 {
                    self.used.borrow_mut()[t - 1] = true;
                }
                dims.remove(k);
            } else {
                k += 1;
            }
        }
        // "A x B (x C)" lists: lengths joined by x / by, with at most an "(X)"-style tag between.
        let mut list_id = 0;
        let mut k = 0;
        while k < dims.len() {
            let mut group = vec![k];
            while let Some(&last) = group.last() {
                let Some(next) = dims.get(last + 1) else { break };
                let between = &self.toks[dims[last].tok + 1..next.tok];
                let joined = !between.is_empty()
                    && between.len() <= 5
                    && between.iter().any(|t| t.is_word("by") || t.is_sym('x'))
                    && between.iter().all(|t| match &t.kind {
                        Tk::Word(w) => {
                            w == "by"
                                || axis_word(w).is_some()
                                || w == "thick"
                                || w == "wide"
                                || w == "long"
                                || w == "tall"
                                || w == "deep"
                        }
                        Tk::Sym(c) => matches!(c, 'x' | '(' | ')'),
                        _ => false,
                    });
                if joined {
                    group.push(last + 1);
                } else {
                    break;
                }
            }
            if group.len() >= 2 {
                let len = group.len();
                // "in a 100mm x 60mm rectangular pattern": the whole list is the pattern's.
                // "on 120 x 70 centres", "on a 170 by 120 rectangle", "on 60 x 60": a list
                // that places copies.
                let first_tok = dims[group[0]].tok;
                let last_tok = dims[group[len - 1]].tok;
                let after = (last_tok + 1..(last_tok + 3).min(n)).find_map(|j| self.word(j));
                let on = first_tok >= 1
                    && (self.is(first_tok - 1, "on")
                        || (first_tok >= 2 && self.is(first_tok - 1, "a") && self.is(first_tok - 2, "on")));
                let places = matches!(after, Some("rectangle" | "square" | "pattern" | "spacing"))
                    || (on
                        && !after.is_some_and(|w| {
                            super::lexicon::noun(w).is_some_and(|k| k != super::lexicon::Noun::Pattern)
                        }));
                if places || group.iter().any(|g| dims[*g].has("pattern") || dims[*g].role == Role::Spacing) {
                    for g in &group {
                        if !dims[*g].has("pattern") {
                            dims[*g].quals.push("pattern".into());
                        }
                    }
                }
                for (pos, g) in group.iter().enumerate() {
                    dims[*g].list = Some((list_id, pos));
                    // A "(X)" tag right after each member.
                    let t = dims[*g].tok;
                    if dims[*g].axis.is_none() && self.sym(t + 1, '(') && self.sym(t + 3, ')') {
                        dims[*g].axis = self.axis_at(t + 2);
                    }
                }
                // "60mm x 60mm (X x Y)": tags after the list.
                let last_tok = dims[group[len - 1]].tok;
                if self.sym(last_tok + 1, '(') {
                    // "(X x Y)": tags at every other token.
                    let tags: Vec<Axis> = (0..len).filter_map(|p| self.axis_at(last_tok + 2 + 2 * p)).collect();
                    let closes = self.sym(last_tok + 2 * len + 1, ')');
                    let tags = if closes { tags } else { Vec::new() };
                    if tags.len() == len && dims[group[0]].axis.is_none() {
                        for (g, a) in group.iter().zip(tags) {
                            dims[*g].axis = Some(a);
                        }
                        let close = (last_tok + 1..n).find(|j| self.sym(*j, ')')).unwrap_or(last_tok + 1);
                        dims[group[len - 1]].phrase.1 = dims[group[len - 1]].phrase.1.max(close + 1);
                    }
                }
                list_id += 1;
            }
            k += group.len();
        }
        self.dims = dims;
    }

    /// The words of the prompt not read, as runs: (first token, last token).
    pub fn unread_runs(&self, ignorable: impl Fn(usize) -> bool) -> Vec<(usize, usize)> {
        let mut runs = Vec::new();
        let mut start: Option<usize> = None;
        for i in 0..self.len() {
            let open = !self.is_used(i) && !ignorable(i);
            match (open, start) {
                (true, None) => start = Some(i),
                (false, Some(s)) => {
                    runs.push((s, i - 1));
                    start = None;
                }
                _ => {}
            }
        }
        if let Some(s) = start {
            runs.push((s, self.len() - 1));
        }
        runs
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roles_axes_and_lists() {
        let d = Doc::new("A flat mounting plate: 80mm (X) by 60mm (Y) by 5mm thick (Z), with a 10mm diameter bore.");
        let got: Vec<(f64, Role, Option<Axis>)> = d.dims.iter().map(|d| (d.mm, d.role, d.axis)).collect();
        assert_eq!(
            got,
            vec![
                (80.0, Role::Bare, Some(Axis::X)),
                (60.0, Role::Bare, Some(Axis::Y)),
                (5.0, Role::Thickness, Some(Axis::Z)),
                (10.0, Role::Diameter, None)
            ]
        );
        assert!(d.dims[0].list.is_some() && d.dims[2].list.is_some());
        assert!(d.dims[3].has("bore") || d.dims[3].quals.is_empty());
    }

    #[test]
    fn ranges_coordinates_and_tuples() {
        let d = Doc::new("The flange is 3mm thick (Z=0 to Z=3). Holes at (X=+25, Y=20) and (±60, 0) mm, at Z=6mm.");
        assert_eq!(d.ranges.len(), 1);
        assert_eq!((d.ranges[0].a, d.ranges[0].b), (0.0, 3.0));
        assert_eq!(d.tuples.len(), 2);
        assert_eq!(d.tuples[1].vals[0], (None, 60.0, true));
        assert_eq!(d.coords.len(), 1);
        assert_eq!(d.dims.len(), 1, "{:?}", d.dims);
        assert_eq!(d.sentences(), 2);
    }
}
