//! The second reading: what the words alone say the part measures — its overall extents and
//! bounds on its volume — taken off the stated lengths apart from the feature program, so
//! that a misreading of the first reader cannot pass its own check (a phrase that restates
//! the part read as a second body, an inner diameter read as a length, a length given to the
//! wrong body).
//!
//! It has its own grammar, smaller than the reader's: a stated length belongs to the thing
//! its phrase names — the noun it stands before ("a 20 mm shaft"), else the last thing named
//! before it in its sentence that is not the object of a preposition ("the plate is 5 thick",
//! "Tube: 42 OD x 36 ID"), else the part. A thing named again ("the block", "its flange",
//! "Block …. Block is …") is the same thing, so a restatement never adds a body. A body of a
//! known shape whose sizes are all stated (a box by three lengths, a cylinder or ring by its
//! diameters and length, a ball) has exact extents and volume; the part must agree:
//!
//! - one body (with holes, pockets and treatments): its extents are the part's, and the
//!   part's volume lies between the body's less every stated cut at its largest and the
//!   body's own;
//! - several bodies: every extent of the part is a sum of stated lengths of different
//!   things (a flange's thickness and a boss's height, a centre height and a radius) or a
//!   span of stated coordinates, and, when every body is sized, the part's volume is at most
//!   the sum of theirs.
//!
//! Where the words do not determine a bound (a shape it does not size, angled arms, bent
//! paths, patterns of bodies), that bound is not checked; it never refuses a part its
//! words do determine and the first reader made as written.

use std::f64::consts::PI;

use super::doc::{Doc, Role};
use super::lexicon::{CutKind, Noun, ShapeHint, noun, number_word, shape_adjective};
use super::model::Model;
use super::text::Tk;

/// A thing the words name, with the lengths that belong to it.
#[derive(Debug, Clone, PartialEq)]
pub struct Thing {
    pub noun: String,
    pub kind: Noun,
    /// First and last token of its first naming phrase.
    pub phrase: (usize, usize),
    pub shape: Option<ShapeHint>,
    /// Indices into the doc's lengths.
    pub dims: Vec<usize>,
    /// How many ("four posts"); `None` for a plural without a number.
    pub count: Option<u32>,
    /// Named only as where something else is ("through the plate", "on the base").
    pub place: bool,
}

/// A body's shape as the second reading sizes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Solid {
    Box {
        x: f64,
        y: f64,
        z: f64,
    },
    Cylinder {
        d: f64,
        l: f64,
    },
    Ring {
        od: f64,
        id: f64,
        l: f64,
    },
    Ball {
        d: f64,
    },
    /// Half a ball, on its flat.
    Dome {
        d: f64,
    },
}

impl Solid {
    pub fn extents(&self) -> [f64; 3] {
        let mut e = match *self {
            Solid::Box { x, y, z } => [x, y, z],
            Solid::Cylinder { d, l } => [d, d, l],
            Solid::Ring { od, l, .. } => [od, od, l],
            Solid::Ball { d } => [d, d, d],
            Solid::Dome { d } => [d, d, d / 2.0],
        };
        e.sort_by(f64::total_cmp);
        e
    }

    pub fn volume(&self) -> f64 {
        match *self {
            Solid::Box { x, y, z } => x * y * z,
            Solid::Cylinder { d, l } => PI * d * d / 4.0 * l,
            Solid::Ring { od, id, l } => PI * (od * od - id * id) / 4.0 * l,
            Solid::Ball { d } => PI * d.powi(3) / 6.0,
            Solid::Dome { d } => PI * d.powi(3) / 12.0,
        }
    }
}

/// Why the second reading disagrees with the first: the words it read, and what they say.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Disagreement {
    pub phrase: String,
    pub reason: String,
}

/// The second reading of a prompt.
#[derive(Debug)]
pub struct Takeoff<'a> {
    pub doc: &'a Doc,
    pub things: Vec<Thing>,
    /// The thing each length belongs to.
    pub owner: Vec<Option<usize>>,
}

fn is_det(w: &str) -> bool {
    matches!(w, "a" | "an" | "the" | "its" | "each" | "both" | "this" | "that" | "every" | "their" | "all")
}

fn definite(w: &str) -> bool {
    matches!(w, "the" | "its" | "each" | "both" | "this" | "that" | "every" | "their" | "all")
}

fn is_prep(w: &str) -> bool {
    matches!(
        w,
        "through"
            | "into"
            | "in"
            | "of"
            | "from"
            | "on"
            | "onto"
            | "to"
            | "at"
            | "across"
            | "around"
            | "thru"
            | "above"
            | "below"
            | "under"
            | "over"
            | "beneath"
            | "inside"
            | "within"
            | "along"
            | "past"
            | "beside"
            | "between"
    )
}

/// Whether the clause of token `h` (between colons, semicolons and full stops) states a length.
fn clause_sized(d: &Doc, h: usize) -> bool {
    let stop = |i: usize| d.sym(i, ':') || d.sym(i, ';') || d.sym(i, '.');
    let mut a = h;
    while a > 0 && !stop(a - 1) {
        a -= 1;
    }
    let mut b = h;
    while b < d.len() && !stop(b) {
        b += 1;
    }
    d.dims.iter().any(|x| x.tok >= a && x.tok < b)
}

/// Words that may stand inside a length's phrase before the noun it sizes.
fn in_phrase(d: &Doc, i: usize) -> bool {
    match &d.toks[i].kind {
        Tk::Word(w) => {
            super::doc::role_of(w).is_some()
                || super::doc::QUALS.contains(&w.as_str())
                || shape_adjective(w).is_some()
                || number_word(w).is_some()
                || matches!(w.as_str(), "mm" | "long" | "wide" | "thick" | "tall" | "high" | "deep" | "od" | "id")
                || super::mention::LABELS.contains(&w.as_str())
                || (noun(w).is_some() && d.word(i + 1).is_some_and(|n| noun(n).is_some()))
        }
        Tk::Num { .. } | Tk::Deg(_) => true,
        Tk::Sym(c) => matches!(c, 'x' | '-'),
    }
}

impl<'a> Takeoff<'a> {
    pub fn read(doc: &'a Doc) -> Self {
        let n = doc.len();
        // Heads: nouns not standing before another noun of their phrase.
        let mut heads: Vec<usize> = Vec::new();
        for i in 0..n {
            let Some(w) = doc.word(i) else { continue };
            let Some(k) = noun(w) else { continue };
            if k == Noun::Pattern {
                continue;
            }
            if doc.word(i + 1).is_some_and(|x| noun(x).is_some_and(|k| k != Noun::Pattern)) {
                continue;
            }
            // A noun naming a length ("wall thickness", "flange width") is no thing.
            if doc.word(i + 1).is_some_and(|x| super::doc::role_of(x).is_some_and(|r| r != Role::Spacing)) {
                continue;
            }
            heads.push(i);
        }
        // Things: a head whose noun was named before, said definitely or bare, is the same.
        let mut things: Vec<Thing> = Vec::new();
        let mut head_thing: Vec<(usize, usize, bool)> = Vec::new(); // (head token, thing, object of a preposition)
        for &h in &heads {
            let Some(w) = doc.word(h) else { continue };
            let Some(kind) = noun(w) else { continue };
            // Back over the phrase to its determiner.
            let mut s = h;
            while s > 0 && doc.sent[s - 1] == doc.sent[h] && in_phrase(doc, s - 1) {
                s -= 1;
            }
            let det = s.checked_sub(1).and_then(|p| doc.word(p)).filter(|p| is_det(p));
            let before = if det.is_some() { s - 1 } else { s };
            let prep = before.checked_sub(1).and_then(|p| doc.word(p)).is_some_and(is_prep);
            let mut count = Some(1);
            let mut shape = None;
            for i in s..h {
                match &doc.toks[i].kind {
                    Tk::Word(x) => {
                        if let Some(c) = number_word(x) {
                            count = Some(c);
                        }
                        if let Some(a) = shape_adjective(x) {
                            shape = shape.or(Some(a));
                        }
                    }
                    Tk::Num { v, unit: None, .. } if v.fract() == 0.0 && *v >= 1.0 && doc.sym(i + 1, 'x') => {
                        count = Some(*v as u32);
                    }
                    _ => {}
                }
            }
            let raw = doc.text.get(doc.toks[h].start..doc.toks[h].end).unwrap_or("").to_lowercase();
            let plural = raw != w && raw.ends_with('s');
            if plural && count == Some(1) {
                count = None;
            }
            // "a keyway slot", "the keyway": one cut, named by its first noun.
            let modifier = h
                .checked_sub(1)
                .and_then(|p| doc.word(p))
                .filter(|m| matches!(noun(m), Some(Noun::Cut(_))) && matches!(kind, Noun::Cut(_)));
            let w = modifier.unwrap_or(w);
            let same = things.iter().rposition(|t| t.noun == w);
            // A thing announced without its sizes ("a shaft with a keyway: … A rectangular
            // keyway runs …") is the same when named again with them.
            let announced =
                same.is_some_and(|t| !clause_sized(doc, things[t].phrase.1) && things[t].count.is_none_or(|c| c <= 1));
            // Named again with no size of its own ("…; a single through hole", "one block").
            let again = same.is_some() && !clause_sized(doc, h);
            let refers = det.is_some_and(definite) || det.is_none() || prep || announced || again;
            let id = match (same, refers) {
                (Some(t), true) => t,
                _ if kind == Noun::Whole && !things.is_empty() => 0,
                _ => {
                    things.push(Thing {
                        noun: w.to_string(),
                        kind,
                        phrase: (s, h),
                        shape,
                        dims: Vec::new(),
                        count,
                        place: true,
                    });
                    things.len() - 1
                }
            };
            things[id].place &= prep;
            if things[id].shape.is_none() {
                things[id].shape = shape;
            }
            head_thing.push((h, id, prep));
        }
        // Each length to its thing.
        let mut owner = vec![None; doc.dims.len()];
        for (k, dm) in doc.dims.iter().enumerate() {
            let t = dm.tok;
            let sent = doc.sent[t];
            // The noun it stands before.
            let mut j = t + 1;
            while j < n && doc.sent[j] == sent && in_phrase(doc, j) && !head_thing.iter().any(|h| h.0 == j) {
                j += 1;
            }
            let ahead = head_thing.iter().find(|h| h.0 == j && doc.sent[j] == sent).map(|h| h.1);
            // Else the last thing named before it in its sentence, not a preposition's object.
            let behind = head_thing.iter().rev().find(|h| h.0 < t && doc.sent[h.0] == sent && !h.2).map(|h| h.1);
            // Else the part.
            let part = (!things.is_empty()).then_some(0);
            owner[k] = ahead.or(behind).or(part);
        }
        for (k, o) in owner.iter().enumerate() {
            if let Some(o) = o {
                things[*o].dims.push(k);
            }
        }
        Takeoff { doc, things, owner }
    }

    fn is_body(&self, t: usize) -> bool {
        matches!(self.things[t].kind, Noun::Body(_) | Noun::Whole)
    }

    /// Lengths that size a body (not a cut's, a treatment's, a pattern's or a placement's).
    pub(super) fn body_dims(&self, t: usize) -> Vec<usize> {
        const FEATURE: &[&str] = &[
            "hole",
            "bore",
            "pitch",
            "circle",
            "bolt",
            "counterbore",
            "countersink",
            "slot",
            "keyway",
            "groove",
            "pocket",
            "recess",
            "socket",
            "clearance",
            "metric",
            "from-center",
            "pattern",
        ];
        self.things[t]
            .dims
            .iter()
            .copied()
            .filter(|k| {
                let d = &self.doc.dims[*k];
                d.restates.is_none()
                    && !matches!(d.role, Role::Fillet | Role::Chamfer | Role::Inset | Role::Spacing)
                    && !FEATURE.iter().any(|q| d.has(q))
            })
            .collect()
    }

    /// The thing's shape and sizes, when its words determine them.
    pub fn solid(&self, t: usize) -> Option<Solid> {
        let th = &self.things[t];
        let hint = match th.kind {
            Noun::Body(h) => h,
            _ => return None,
        };
        let dims = self.body_dims(t);
        let d = |k: &usize| &self.doc.dims[*k];
        // One value per role: two different values of one role are two things (or a
        // reading this grammar does not make).
        let one = |roles: &[Role], with: &[&str], without: &[&str]| -> Result<Option<f64>, ()> {
            let vals: Vec<f64> = dims
                .iter()
                .filter(|k| {
                    roles.contains(&d(k).role)
                        && with.iter().all(|w| d(k).has(w))
                        && !without.iter().any(|w| d(k).has(w))
                })
                .map(|k| if d(k).role == Role::Radius { 2.0 * d(k).mm } else { d(k).mm })
                .collect();
            match vals.as_slice() {
                [] => Ok(None),
                [v, rest @ ..] if rest.iter().all(|r| (r - v).abs() <= 1e-6 * v.max(1.0)) => Ok(Some(*v)),
                _ => Err(()),
            }
        };
        let shape = match (hint, th.shape) {
            (ShapeHint::Round | ShapeHint::Ring, Some(ShapeHint::Ring)) => ShapeHint::Ring,
            (ShapeHint::Ring, Some(ShapeHint::Round) | None) => ShapeHint::Ring,
            (ShapeHint::Round, Some(ShapeHint::Round) | None) => ShapeHint::Round,
            (ShapeHint::Rect, Some(ShapeHint::Rect) | None) => ShapeHint::Rect,
            (ShapeHint::Rect, Some(ShapeHint::Round)) => ShapeHint::Round,
            (ShapeHint::Sphere, _) => ShapeHint::Sphere,
            (ShapeHint::Hemisphere, _) => ShapeHint::Hemisphere,
            _ => return None,
        };
        let along = [Role::Length, Role::Height, Role::Thickness, Role::Depth];
        match shape {
            ShapeHint::Round | ShapeHint::Ring => {
                let outer = one(&[Role::Diameter, Role::Radius], &[], &["inner"]).ok()?;
                let inner = one(&[Role::Diameter, Role::Radius], &["inner"], &[]).ok()?;
                let wall = one(&[Role::Thickness], &["wall"], &[]).ok()?;
                let len = one(&along, &[], &["wall"]).ok()?;
                let bare: Vec<f64> = dims.iter().filter(|k| d(k).role == Role::Bare).map(|k| d(k).mm).collect();
                let od = outer?;
                let len = match (len, bare.as_slice()) {
                    (Some(l), []) => l,
                    (None, [l]) => *l,
                    _ => return None,
                };
                let id = inner.or_else(|| wall.map(|w| od - 2.0 * w));
                match (shape, id) {
                    (_, Some(i)) if i > 0.0 && i < od => Some(Solid::Ring { od, id: i, l: len }),
                    (ShapeHint::Round, None) => Some(Solid::Cylinder { d: od, l: len }),
                    _ => None,
                }
            }
            ShapeHint::Sphere | ShapeHint::Hemisphere => {
                let dia = one(&[Role::Diameter, Role::Radius, Role::Bare], &[], &[]).ok()??;
                let half = hint == ShapeHint::Hemisphere || (th.phrase.0..th.phrase.1).any(|i| self.doc.is(i, "half"));
                let ok = dims.len() == 1 || dims.iter().all(|k| matches!(d(k).role, Role::Diameter | Role::Radius));
                ok.then_some(if half { Solid::Dome { d: dia } } else { Solid::Ball { d: dia } })
            }
            _ => {
                // Three lengths: a list ("80 x 60 x 5"), roles, sides — each role once.
                let list: Vec<f64> = dims.iter().filter(|k| d(k).list.is_some()).map(|k| d(k).mm).collect();
                let rest: Vec<usize> = dims.iter().copied().filter(|k| d(k).list.is_none()).collect();
                if rest.iter().any(|k| {
                    !(along.contains(&d(k).role) || matches!(d(k).role, Role::Width | Role::Side | Role::Bare))
                }) {
                    return None;
                }
                let mut v: Vec<f64> = list.clone();
                if list.len() == 3 {
                    // Whatever else is said restates the list.
                    if !rest.iter().all(|k| list.iter().any(|x| (x - d(k).mm).abs() <= 1e-6 * x.max(1.0))) {
                        return None;
                    }
                } else {
                    for roles in
                        [&[Role::Length][..], &[Role::Width], &[Role::Height], &[Role::Thickness], &[Role::Depth]]
                    {
                        if let Some(x) = one(roles, &[], &["wall"]).ok()? {
                            let listed = !list.is_empty()
                                && dims.iter().filter(|k| roles.contains(&d(k).role)).all(|k| d(k).list.is_some());
                            if listed {
                                continue;
                            }
                            v.push(x);
                        }
                    }
                    if let Some(s) = one(&[Role::Side], &[], &[]).ok()? {
                        let cube = th.noun == "cube";
                        v.extend(std::iter::repeat_n(s, if cube { 3 } else { 2 }));
                    }
                    let bare: Vec<f64> = rest.iter().filter(|k| d(k).role == Role::Bare).map(|k| d(k).mm).collect();
                    if th.noun == "cube" && v.is_empty() && bare.len() == 1 {
                        v = vec![bare[0]; 3];
                    } else {
                        v.extend(bare);
                    }
                }
                match v.as_slice() {
                    [x, y, z] => Some(Solid::Box { x: *x, y: *y, z: *z }),
                    _ => None,
                }
            }
        }
    }

    /// Things with lengths of their own that size a body.
    fn sized_bodies(&self) -> Vec<usize> {
        (0..self.things.len()).filter(|t| self.is_body(*t) && !self.body_dims(*t).is_empty()).collect()
    }

    /// The largest volume a cut thing may remove (its cross-section at its largest, through
    /// the part's largest extent, times its count), when its words say its size.
    fn cut_allowance(&self, t: usize, extents: [f64; 3], count_max: u32) -> Option<f64> {
        let th = &self.things[t];
        let dims: Vec<f64> = th.dims.iter().map(|k| &self.doc.dims[*k]).map(|d| d.mm).collect();
        let size = dims.iter().copied().fold(0.0, f64::max);
        if size <= 0.0 {
            return None;
        }
        // A fillet or chamfer along every edge of the body (a box has 4 of each extent).
        if matches!(th.kind, Noun::Fillet | Noun::Chamfer) {
            return Some(size * size * 4.0 * (extents[0] + extents[1] + extents[2]));
        }
        let n = f64::from(th.count.unwrap_or(count_max).max(1));
        Some(n * size * size * extents[2])
    }

    /// Whether the part the first reader made agrees with what the words say it measures.
    pub fn check(&self, model: &Model) -> Result<(), Disagreement> {
        if model.adds.is_empty() {
            return Ok(());
        }
        let mut got = model.size();
        got.sort_by(f64::total_cmp);
        let bodies = self.sized_bodies();
        let d = self.doc;
        let close = |a: f64, b: f64| (a - b).abs() <= 0.005 * b.abs() + 0.01;
        let quote = |t: usize| {
            let th = &self.things[t];
            let last = th.dims.iter().map(|k| d.dims[*k].tok).max().unwrap_or(th.phrase.1).max(th.phrase.1);
            let first = th.dims.iter().map(|k| d.dims[*k].tok).min().unwrap_or(th.phrase.0).min(th.phrase.0);
            d.quote(first, last)
        };
        let fmt =
            |e: [f64; 3]| format!("{} x {} x {} mm", super::num::n(e[0]), super::num::n(e[1]), super::num::n(e[2]));
        // "30 overall", "overall length 40", "total height 35": the part measures that.
        for (_, x) in d.dims.iter().enumerate().filter(|(k, x)| {
            // (Of the part, not of a cut: "a slot, 40 long overall".)
            let of_cut = self.owner[*k].is_some_and(|t| !self.is_body(t));
            !of_cut
                && (x.has("overall") || x.has("total"))
                && matches!(x.role, Role::Length | Role::Height | Role::Width | Role::Bare | Role::Thickness)
                && x.restates.is_none()
        }) {
            if !got.iter().any(|g| close(*g, x.mm)) {
                return Err(Disagreement {
                    phrase: d.quote(x.phrase.0.min(x.tok), x.phrase.1.max(x.tok + 1).saturating_sub(1)),
                    reason: format!(
                        "the words make the part {} mm overall, but it was read as {}",
                        super::num::n(x.mm),
                        fmt(got)
                    ),
                });
            }
        }
        // Words that contradict themselves: a cube of unequal sides, a ring whose wall and
        // diameters disagree.
        for t in bodies.iter().copied() {
            let dims = self.body_dims(t);
            let vals: Vec<f64> = dims.iter().map(|k| d.dims[*k].mm).collect();
            if self.things[t].noun == "cube"
                && let (Some(lo), Some(hi)) =
                    (vals.iter().copied().reduce(f64::min), vals.iter().copied().reduce(f64::max))
                && hi > lo * 1.005
            {
                return Err(Disagreement {
                    phrase: quote(t),
                    reason: format!("a cube has equal sides, not {} and {} mm", super::num::n(lo), super::num::n(hi)),
                });
            }
            let of = |role: Role, with: &str| {
                dims.iter()
                    .map(|k| &d.dims[*k])
                    .find(|x| x.role == role && (with.is_empty() || x.has(with)))
                    .map(|x| x.mm)
            };
            let od =
                dims.iter().map(|k| &d.dims[*k]).find(|x| x.role == Role::Diameter && !x.has("inner")).map(|x| x.mm);
            if let (Some(o), Some(i), Some(w)) = (od, of(Role::Diameter, "inner"), of(Role::Thickness, "wall"))
                && (o - 2.0 * w - i).abs() > 0.005 * o
            {
                return Err(Disagreement {
                    phrase: quote(t),
                    reason: format!(
                        "a {} mm wall makes the inside {} mm, not {} mm",
                        super::num::n(w),
                        super::num::n(o - 2.0 * w),
                        super::num::n(i)
                    ),
                });
            }
        }
        // A noun named again for another body with sizes of its own ("a block … with a block
        // 10 x 10 x 10 on top") is as many bodies.
        let mut seen: Vec<&str> = Vec::new();
        let mut again = 0usize;
        for t in &bodies {
            let th = &self.things[*t];
            // (Not a face or piece of one: "a 20mm leg along X and a 30mm leg along Y".)
            let piece = matches!(
                th.noun.as_str(),
                "leg" | "side" | "base" | "face" | "end" | "wall" | "floor" | "flange" | "web" | "top" | "bottom"
            );
            if matches!(th.kind, Noun::Body(_)) && !piece {
                if seen.contains(&th.noun.as_str()) {
                    again += 1;
                } else {
                    seen.push(&th.noun);
                }
            }
        }
        if again > 0 && model.adds.len() < again + 1 {
            let t = bodies[bodies.len() - 1];
            return Err(Disagreement {
                phrase: quote(t),
                reason: format!("the words name {} bodies of this kind, but {} was made", again + 1, model.adds.len()),
            });
        }
        // Every cut the words name is made: holes, bores, slots, keyways, grooves and pockets
        // named (with their counts) are at most the model's cuts, its rings' bores and shells.
        let named: u32 = (0..self.things.len())
            .filter(|t| {
                matches!(
                    self.things[*t].kind,
                    Noun::Cut(
                        CutKind::Hole
                            | CutKind::Bore
                            | CutKind::Slot
                            | CutKind::Keyway
                            | CutKind::Groove
                            | CutKind::Pocket
                    )
                )
            })
            .map(|t| self.things[t].count.unwrap_or(1).max(1))
            .sum();
        let made = model.cuts.len()
            + model
                .adds
                .iter()
                .filter(|b| {
                    b.shell.is_some()
                        || matches!(
                            &b.shape,
                            super::solid::Shape::Prism { profile: super::profile::Profile::Annulus { .. }, .. }
                                | super::solid::Shape::Bend { .. }
                        )
                })
                .count();
        let profiled = model
            .adds
            .iter()
            .any(|b| matches!(b.shape, super::solid::Shape::Revolve { .. } | super::solid::Shape::Loft { .. }));
        if named as usize > made && !profiled {
            let t = (0..self.things.len()).find(|t| matches!(self.things[*t].kind, Noun::Cut(_))).unwrap_or(0);
            return Err(Disagreement {
                phrase: quote(t),
                reason: format!("the words name {named} cuts, but {made} were made"),
            });
        }
        // A polygon said of a body is one of the part's bodies ("a hexagonal spacer" is no
        // round one).
        for th in self.things.iter().filter(|t| matches!(t.kind, Noun::Body(_)) && !t.place) {
            if let Some(ShapeHint::Ngon(n)) = th.shape {
                let has = model.adds.iter().chain(model.cuts.iter()).any(|b| {
                    matches!(&b.shape, super::solid::Shape::Prism { profile: super::profile::Profile::Ngon { n: m, .. }, .. } if *m == n)
                        || matches!(&b.shape, super::solid::Shape::Prism { profile: super::profile::Profile::Poly(p), .. } if p.len() == n)
                });
                if !has {
                    return Err(Disagreement {
                        phrase: d.quote(th.phrase.0, th.phrase.1),
                        reason: format!("the words make it a {n}-sided prism, but no such body was read"),
                    });
                }
            }
        }
        // Counted things: the largest count said, for cuts whose count is not.
        let count_max = self.things.iter().filter_map(|t| t.count).max().unwrap_or(1);
        // One body: the only body the words name (other than as a place), and the part's own.
        let others = (0..self.things.len())
            .filter(|t| matches!(self.things[*t].kind, Noun::Body(_)) && !self.things[*t].place)
            .count();
        let title_ok = |b: usize| {
            b == 0
                || matches!(self.things[0].kind, Noun::Whole)
                || matches!(self.things[0].kind, Noun::Body(ShapeHint::Round | ShapeHint::Ring | ShapeHint::Rect))
                    && self.things[0].dims.is_empty()
                    && self.things[0].noun == self.things[b].noun
        };
        if let [b] = bodies.as_slice()
            && others == 1
            && title_ok(*b)
            && self.things[*b].count == Some(1)
            && let Some(solid) = self.solid(*b)
        {
            let want = solid.extents();
            if !(0..3).all(|k| close(got[k], want[k])) {
                return Err(Disagreement {
                    phrase: quote(*b),
                    reason: format!("these words make it {}, but it was read as {}", fmt(want), fmt(got)),
                });
            }
            if let Some(v) = model.volume() {
                let top = solid.volume();
                if v > top * 1.005 + 1e-6 {
                    return Err(Disagreement {
                        phrase: quote(*b),
                        reason: format!(
                            "these words make at most {:.0} mm³ of material, but it was read as {v:.0} mm³",
                            top
                        ),
                    });
                }
                // Less what every cut and treatment may remove at its largest (a rounding
                // or chamfer said as a length of the body: along every edge).
                let mut least = top;
                let mut known = true;
                for k in self.things[*b].dims.iter().map(|k| &d.dims[*k]) {
                    if matches!(k.role, Role::Fillet | Role::Chamfer) {
                        least -= k.mm * k.mm * 4.0 * (want[0] + want[1] + want[2]);
                    }
                }
                for t in 0..self.things.len() {
                    if t == *b || self.is_body(t) {
                        continue;
                    }
                    match self.cut_allowance(t, want, count_max) {
                        Some(a) => least -= a,
                        None => known = false,
                    }
                }
                if known && v < least * 0.995 - 1e-6 {
                    return Err(Disagreement {
                        phrase: quote(*b),
                        reason: format!(
                            "these words leave at least {least:.0} mm³ of material, but it was read as {v:.0} mm³"
                        ),
                    });
                }
            }
            return Ok(());
        }
        // Several bodies: the part's volume is at most theirs together.
        if bodies.len() >= 2 {
            let solids: Vec<Option<(Solid, u32)>> =
                bodies.iter().map(|t| Some((self.solid(*t)?, self.things[*t].count?))).collect();
            if let (Some(v), true) = (model.volume(), solids.iter().all(Option::is_some)) {
                let top: f64 = solids.iter().flatten().map(|(s, n)| s.volume() * f64::from(*n)).sum();
                if v > top * 1.005 + 1e-6 {
                    let t = bodies[0];
                    return Err(Disagreement {
                        phrase: quote(t),
                        reason: format!(
                            "these words make at most {top:.0} mm³ of material in {} bodies, but it was read as {v:.0} mm³",
                            bodies.len()
                        ),
                    });
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solid_of(text: &str) -> Option<Solid> {
        let d = Doc::new(text);
        let t = Takeoff::read(&d);
        let b = t.sized_bodies();
        (b.len() == 1).then(|| t.solid(b[0])).flatten()
    }

    #[test]
    fn a_restatement_is_the_same_thing() {
        // The same block, said three ways: one thing with its three sizes.
        for text in [
            "A block 50 x 30 x 20 mm. The block is 20 mm tall.",
            "Block, 50 mm long, 30 mm wide, 20 mm high; block sits flat, 20 mm high.",
            "A rectangular block 50mm long, 30mm wide and 20mm tall. It is 20mm tall.",
        ] {
            assert_eq!(solid_of(text), Some(Solid::Box { x: 50.0, y: 30.0, z: 20.0 }), "{text}");
        }
    }

    #[test]
    fn round_bodies_by_their_diameters() {
        assert_eq!(solid_of("a cylinder 25 mm in diameter and 40 mm tall"), Some(Solid::Cylinder { d: 25.0, l: 40.0 }));
        assert_eq!(
            solid_of("A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm"),
            Some(Solid::Ring { od: 20.0, id: 10.5, l: 2.0 })
        );
        assert_eq!(solid_of("a solid sphere with a radius of 15mm"), Some(Solid::Ball { d: 30.0 }));
    }

    #[test]
    fn a_second_body_from_a_restatement_is_caught() {
        use super::super::profile::Profile;
        use super::super::solid::{Axis, Body, Shape};
        let text = "A block 50 x 30 x 20 mm. The block is 20 mm tall.";
        let d = Doc::new(text);
        let t = Takeoff::read(&d);
        let block = |from: f64| {
            Body::new(
                "block",
                Shape::Prism {
                    profile: Profile::Rect { w: 50.0, h: 30.0 },
                    axis: Axis::Z,
                    at: [0.0, 0.0],
                    rot: 0.0,
                    from,
                    to: from + 20.0,
                },
            )
        };
        let one = Model { adds: vec![block(0.0)], cuts: vec![] };
        assert_eq!(t.check(&one), Ok(()));
        let two = Model { adds: vec![block(0.0), block(20.0)], cuts: vec![] };
        let e = t.check(&two).unwrap_err();
        assert!(e.reason.contains("50 x 30 x 20") || e.reason.contains("20 x 30 x 50"), "{e:?}");
    }
}
