//! What the words say about where things are and how many there are, checked on the part
//! that was made — the part of the second reading that the first reader may take for
//! filler. Three kinds of words carry geometry without a number of their own:
//!
//! - **multiplicity**: a hole or pocket "at both ends" / "each end" is two of them;
//! - **stacking**: a body "below" / "under" / "above" / "on top of" another round body
//!   stands beside it on their common axis, so the part is as long as both together;
//! - **direction**: a hole bored "through its length" (or "lengthwise", "end to end") runs
//!   along the part's stated length, and a part's own inner diameter ("16 ID", "bore 20",
//!   "Ø16 bore right through") runs through every body on its axis: either way its centre
//!   line is empty from one end of the part to the other.
//!
//! Each is measured on the model itself (its extents, its cuts, which points lie inside it),
//! never on the first reader's account of the words, so a phrase read as filler cannot pass.

use super::doc::{Doc, Role};
use super::lexicon::{CutKind, Noun};
use super::model::Model;
use super::profile::Profile;
use super::solid::{Axis, Shape};
use super::takeoff::{Disagreement, Solid, Takeoff};

/// The clause of token `h`: from it to the next comma, semicolon or full stop.
fn clause_end(t: &Takeoff<'_>, h: usize) -> usize {
    let d = t.doc;
    let mut b = h;
    while b < d.len() && !(d.sym(b, ',') || d.sym(b, ';') || d.sym(b, '.')) {
        b += 1;
    }
    b
}

/// "both ends", "each end", "either end" in `a..b`, not after "through" (a hole through
/// both ends is one hole).
pub fn at_both_ends(d: &Doc, a: usize, b: usize) -> Option<usize> {
    (a..b.saturating_sub(1)).find(|&i| {
        matches!(d.word(i), Some("both" | "each" | "either"))
            && d.is(i + 1, "end")
            && !(i > 0 && matches!(d.word(i - 1), Some("through" | "thru")))
    })
}

/// Whether point `p` is inside a shape; `None` where this check does not know the shape.
fn inside(shape: &Shape, p: [f64; 3]) -> Option<bool> {
    match shape {
        Shape::Prism { profile, axis, at, rot, from, to } => {
            if rot.abs() > 1e-9 {
                return None;
            }
            let (u, v) = axis.uv();
            let w = p[axis.index()];
            let (lo, hi) = (from.min(*to), from.max(*to));
            Some(w >= lo - 1e-9 && w <= hi + 1e-9 && profile.contains([p[u.index()] - at[0], p[v.index()] - at[1]]))
        }
        Shape::Cone { axis, at, from, to, d_from, d_to } => {
            let (u, v) = axis.uv();
            let w = p[axis.index()];
            let (lo, hi) = (from.min(*to), from.max(*to));
            if w < lo - 1e-9 || w > hi + 1e-9 || (to - from).abs() < 1e-12 {
                return Some(false);
            }
            let f = (w - from) / (to - from);
            let r = (d_from + f * (d_to - d_from)) / 2.0;
            let (du, dv) = (p[u.index()] - at[0], p[v.index()] - at[1]);
            Some(du * du + dv * dv <= r * r + 1e-9)
        }
        Shape::Sphere { c, d } => {
            let q: f64 = (0..3).map(|k| (p[k] - c[k]).powi(2)).sum();
            Some(q <= (d / 2.0).powi(2) + 1e-9)
        }
        _ => None,
    }
}

/// Whether `p` is material of the model; `None` where a body is of a kind not known here.
fn material(model: &Model, p: [f64; 3]) -> Option<bool> {
    let mut any = false;
    for b in &model.adds {
        if b.shell.is_some() {
            return None;
        }
        any |= inside(&b.shape, p)?;
    }
    if !any {
        return Some(false);
    }
    for c in &model.cuts {
        if inside(&c.shape, p)? {
            return Some(false);
        }
    }
    Some(true)
}

/// Whether the line along `axis` through (u, v) = `at` is empty of material over the whole
/// part; `None` when it cannot be told.
fn line_empty(model: &Model, axis: Axis, at: [f64; 2]) -> Option<bool> {
    let b = model.bounds();
    let k = axis.index();
    let (u, v) = axis.uv();
    let n = 64;
    for s in 0..n {
        // Sample strictly inside the part's span, off the faces.
        let w = b[0][k] + (b[1][k] - b[0][k]) * (s as f64 + 0.5) / n as f64;
        let mut p = [0.0; 3];
        p[k] = w;
        p[u.index()] = at[0];
        p[v.index()] = at[1];
        if material(model, p)? {
            return Some(false);
        }
    }
    Some(true)
}

/// The part's own axis, the one a bore "through its length" runs along: the common axis of
/// its round bodies (turned, revolved, coned or polygonal bars — whatever their
/// proportions: a flanged bushing wider than it is long still has its axis), else the one
/// axis along which it is longest; `None` where round bodies stand on different axes or two
/// extents tie for longest with no round body to decide.
pub fn part_axis(model: &Model) -> Option<Axis> {
    let round: Vec<Axis> = model
        .adds
        .iter()
        .filter_map(|b| match &b.shape {
            Shape::Prism {
                profile: Profile::Circle { .. } | Profile::Annulus { .. } | Profile::Ngon { .. },
                axis,
                ..
            } => Some(*axis),
            Shape::Cone { axis, .. } | Shape::Torus { axis, .. } => Some(*axis),
            Shape::Revolve { .. } => Some(Axis::Z),
            _ => None,
        })
        .collect();
    if let Some(first) = round.first() {
        return round.iter().all(|a| a == first).then_some(*first);
    }
    let size = model.size();
    let long = size.iter().copied().fold(0.0, f64::max);
    let axes: Vec<Axis> = Axis::ALL.into_iter().filter(|x| size[x.index()] >= long * (1.0 - 1e-9)).collect();
    match axes.as_slice() {
        [x] => Some(*x),
        _ => None,
    }
}

/// The axial length of a round body the second reading sizes.
fn axial(s: &Solid) -> Option<f64> {
    match *s {
        Solid::Cylinder { l, .. } | Solid::Ring { l, .. } => Some(l),
        _ => None,
    }
}

impl Takeoff<'_> {
    /// The count of a cut thing, with "at both ends" said of it.
    pub fn cut_count(&self, t: usize) -> u32 {
        let th = &self.things[t];
        let base = th.count.unwrap_or(1).max(1);
        let end = clause_end(self, th.phrase.1);
        if base == 1 && at_both_ends(self.doc, th.phrase.0, end).is_some() { 2 } else { base }
    }

    /// The checks of the words without numbers of their own (see the module's notes).
    pub fn account(&self, model: &Model) -> Result<(), Disagreement> {
        if model.adds.is_empty() {
            return Ok(());
        }
        let d = self.doc;
        let mut got = model.size();
        got.sort_by(f64::total_cmp);
        let close = |a: f64, b: f64| (a - b).abs() <= 0.005 * b.abs() + 0.01;
        // Multiplicity: holes said at both ends are at least two cuts of their size.
        for (t, th) in self.things.iter().enumerate() {
            if !matches!(th.kind, Noun::Cut(CutKind::Hole | CutKind::Bore | CutKind::Pocket)) || th.place {
                continue;
            }
            let n = self.cut_count(t);
            let end = clause_end(self, th.phrase.1);
            let Some(at) = at_both_ends(self.doc, th.phrase.0, end) else { continue };
            if n < 2 {
                continue;
            }
            let dia = th
                .dims
                .iter()
                .map(|k| &d.dims[*k])
                .find(|x| matches!(x.role, Role::Diameter | Role::Bare))
                .map(|x| x.mm);
            let made = model
                .cuts
                .iter()
                .filter(|c| match (&c.shape, dia) {
                    (Shape::Prism { profile: Profile::Circle { d: cd }, .. }, Some(x)) => (cd - x).abs() <= 1e-6 * x,
                    (_, None) => true,
                    _ => false,
                })
                .count();
            if made < n as usize {
                return Err(Disagreement {
                    phrase: d.quote(th.phrase.0.min(at), at + 1),
                    reason: format!("the words make {n} of these (one at each end), but {made} was made"),
                });
            }
        }
        // Stacking: a round body below / above another round body.
        for (a, ta) in self.things.iter().enumerate() {
            if !matches!(ta.kind, Noun::Body(_)) {
                continue;
            }
            let Some(sa) = self.solid(a) else { continue };
            let Some(la) = axial(&sa) else { continue };
            let end = clause_end(self, ta.phrase.1);
            for i in ta.phrase.1 + 1..end {
                let stack = matches!(d.word(i), Some("below" | "under" | "beneath" | "above" | "atop"))
                    || (d.is(i, "on") && d.is(i + 1, "top") && d.is(i + 2, "of"));
                if !stack {
                    continue;
                }
                // The body it stands against: the next thing named in the clause.
                let Some(b) = self
                    .things
                    .iter()
                    .position(|tb| (i + 1..end).any(|j| j == tb.phrase.1) && matches!(tb.kind, Noun::Body(_)))
                    .or_else(|| {
                        // Named again ("below the flange"): a thing whose noun is the word.
                        (i + 1..end).find_map(|j| {
                            let w = d.word(j)?;
                            self.things.iter().position(|tb| tb.noun == w && matches!(tb.kind, Noun::Body(_)))
                        })
                    })
                else {
                    continue;
                };
                if b == a {
                    continue;
                }
                let Some(lb) = self.solid(b).as_ref().and_then(axial) else { continue };
                if !got.iter().any(|g| close(*g, la + lb)) {
                    return Err(Disagreement {
                        phrase: d.quote(ta.phrase.0, end.saturating_sub(1)),
                        reason: format!(
                            "standing {} the {}, the two make the part {} mm long, but it was read as {} x {} x {} mm",
                            d.word(i).unwrap_or(""),
                            self.things[b].noun,
                            super::num::n(la + lb),
                            super::num::n(got[0]),
                            super::num::n(got[1]),
                            super::num::n(got[2])
                        ),
                    });
                }
            }
        }
        // Direction: a through bore along the stated length, or the part's own inner
        // diameter, leaves its centre line empty end to end.
        let b = model.bounds();
        let centre = |axis: Axis| {
            let (u, v) = axis.uv();
            [(b[0][u.index()] + b[1][u.index()]) / 2.0, (b[0][v.index()] + b[1][v.index()]) / 2.0]
        };
        let size = model.size();
        for th in self.things.iter() {
            if !matches!(th.kind, Noun::Cut(CutKind::Hole | CutKind::Bore)) || th.count.unwrap_or(1) > 1 {
                continue;
            }
            let end = clause_end(self, th.phrase.1);
            let blind = (th.phrase.0..end).any(|i| matches!(d.word(i), Some("blind" | "deep" | "dp" | "depth")));
            let along = (th.phrase.0..end).find(|&i| {
                (matches!(d.word(i), Some("through" | "thru" | "along" | "full" | "entire" | "whole"))
                    && d.word(i + 1).is_some_and(|w| matches!(w, "its" | "the"))
                    && d.is(i + 2, "length"))
                    || (matches!(d.word(i), Some("full" | "entire" | "whole")) && d.is(i + 1, "length"))
                    || matches!(d.word(i), Some("lengthwise" | "lengthways" | "axially"))
                    || (d.is(i, "end") && d.is(i + 1, "to") && d.is(i + 2, "end"))
            });
            let (Some(at), false) = (along, blind) else { continue };
            // Along the part's own axis (its round bodies', else its one longest extent);
            // where that cannot be told, along every extent the words' length matches.
            let length = d
                .dims
                .iter()
                .enumerate()
                .filter(|(k, x)| {
                    x.role == Role::Length
                        && x.restates.is_none()
                        && self.owner[*k].is_some_and(|o| matches!(self.things[o].kind, Noun::Body(_) | Noun::Whole))
                })
                .map(|(_, x)| x.mm)
                .next()
                .unwrap_or(got[2]);
            let axes: Vec<Axis> = match part_axis(model) {
                Some(a) => vec![a],
                None => Axis::ALL.into_iter().filter(|a| close(size[a.index()], length)).collect(),
            };
            if axes.is_empty() {
                continue;
            }
            let length = size[axes[0].index()];
            let mut told = false;
            let mut empty = false;
            for a in axes {
                if let Some(e) = line_empty(model, a, centre(a)) {
                    told = true;
                    empty |= e;
                }
            }
            if told && !empty {
                return Err(Disagreement {
                    phrase: d.quote(th.phrase.0.min(at), (at + 2).min(end.saturating_sub(1))),
                    reason: format!(
                        "the words bore it along its {} mm length, but no bore runs the part's length",
                        super::num::n(length)
                    ),
                });
            }
        }
        // The part's own inner diameter: said of the part (its first thing, or the whole)
        // and of no body of its own, with more than one body made on a common axis.
        if model.adds.len() >= 2
            && let Some(x) = d.dims.iter().enumerate().find(|(k, x)| {
                x.role == Role::Diameter
                    && x.has("inner")
                    && x.restates.is_none()
                    && self.owner[*k].is_some_and(|o| o == 0 || matches!(self.things[o].kind, Noun::Whole))
            })
        {
            let axes: Vec<(Axis, [f64; 2])> = model
                .adds
                .iter()
                .filter_map(|body| match &body.shape {
                    Shape::Prism { profile: Profile::Circle { .. } | Profile::Annulus { .. }, axis, at, .. } => {
                        Some((*axis, *at))
                    }
                    _ => None,
                })
                .collect();
            if let Some((axis, at)) = axes.first().copied()
                && axes.iter().all(|(a, p)| *a == axis && (p[0] - at[0]).abs() < 1e-6 && (p[1] - at[1]).abs() < 1e-6)
                && line_empty(model, axis, at) == Some(false)
            {
                let (_, x) = x;
                return Err(Disagreement {
                    phrase: d.quote(x.phrase.0.min(x.tok), x.phrase.1.max(x.tok + 1).saturating_sub(1)),
                    reason: format!(
                        "a {} mm inner diameter of the part runs through every body on its axis, but it was read as stopping short",
                        super::num::n(x.mm)
                    ),
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::super::solid::Body;
    use super::*;

    fn prism(label: &str, profile: Profile, axis: Axis, from: f64, to: f64) -> Body {
        Body::new(label, Shape::Prism { profile, axis, at: [0.0, 0.0], rot: 0.0, from, to })
    }

    fn account(text: &str, model: &Model) -> Result<(), Disagreement> {
        let d = Doc::new(text);
        Takeoff::read(&d).account(model)
    }

    #[test]
    fn a_bore_through_its_length_runs_along_it() {
        let text =
            "A square bar 25 mm across the flats and 100 mm long, with a 10 mm hole bored right through its length";
        let bar = prism("bar", Profile::Rect { w: 25.0, h: 25.0 }, Axis::X, -50.0, 50.0);
        let along = Model {
            adds: vec![bar.clone()],
            cuts: vec![prism("hole", Profile::Circle { d: 10.0 }, Axis::X, -50.0, 50.0)],
        };
        assert_eq!(account(text, &along), Ok(()));
        // Made across the bar instead: the bar's centre line is material.
        let across =
            Model { adds: vec![bar], cuts: vec![prism("hole", Profile::Circle { d: 10.0 }, Axis::Z, -12.5, 12.5)] };
        let e = account(text, &across).unwrap_err();
        assert!(e.phrase.contains("length"), "{e:?}");
    }

    #[test]
    fn holes_at_both_ends_are_two() {
        let text = "STANDOFF Ø10 x 30 LG, M5 TAPPED x 8 DP BOTH ENDS";
        let body = prism("standoff", Profile::Circle { d: 10.0 }, Axis::Z, 0.0, 30.0);
        let hole = |a: f64, b: f64| prism("hole", Profile::Circle { d: 4.2 }, Axis::Z, a, b);
        let one = Model { adds: vec![body.clone()], cuts: vec![hole(22.0, 30.0)] };
        let e = account(text, &one).unwrap_err();
        assert!(e.phrase.to_lowercase().contains("both ends"), "{e:?}");
        let two = Model { adds: vec![body], cuts: vec![hole(0.0, 8.0), hole(22.0, 30.0)] };
        assert_eq!(account(text, &two), Ok(()));
        // A hole through both ends is one hole.
        let through = "a rod 10 mm in diameter and 30 mm long with a 4 mm hole through both ends";
        let rod = prism("rod", Profile::Circle { d: 10.0 }, Axis::Z, 0.0, 30.0);
        let m = Model { adds: vec![rod], cuts: vec![prism("hole", Profile::Circle { d: 4.0 }, Axis::Z, 0.0, 30.0)] };
        assert_eq!(account(through, &m), Ok(()));
    }

    #[test]
    fn a_body_below_another_stands_beside_it() {
        let text = "Flanged bushing: flange Ø40 x 5 thick, body Ø25 x 20 long below the flange, Ø16 bore right through";
        let flange = |a: f64| prism("flange", Profile::Circle { d: 40.0 }, Axis::Z, a, a + 5.0);
        let body = prism("body", Profile::Circle { d: 25.0 }, Axis::Z, 0.0, 20.0);
        let overlapping = Model { adds: vec![flange(15.0), body.clone()], cuts: vec![] };
        let e = account(text, &overlapping).unwrap_err();
        assert!(e.phrase.contains("below the flange"), "{e:?}");
        let stacked = Model {
            adds: vec![flange(20.0), body],
            cuts: vec![prism("bore", Profile::Circle { d: 16.0 }, Axis::Z, 0.0, 25.0)],
        };
        assert_eq!(account(text, &stacked), Ok(()));
    }

    #[test]
    fn the_parts_inner_diameter_runs_through_every_body() {
        let text = "Flanged bushing: 16 ID, 22 OD, 20 long overall, flange Ø32 x 3";
        let body = prism("bushing", Profile::Annulus { od: 22.0, id: 16.0 }, Axis::Z, 3.0, 20.0);
        let solid_flange = prism("flange", Profile::Circle { d: 32.0 }, Axis::Z, 0.0, 3.0);
        let wrong = Model { adds: vec![body.clone(), solid_flange], cuts: vec![] };
        assert!(account(text, &wrong).is_err());
        let bored = prism("flange", Profile::Annulus { od: 32.0, id: 16.0 }, Axis::Z, 0.0, 3.0);
        let right = Model { adds: vec![body, bored], cuts: vec![] };
        assert_eq!(account(text, &right), Ok(()));
        let v = right.volume().unwrap();
        assert!(
            (v - PI / 4.0 * (32.0f64.powi(2) * 3.0 + 22.0f64.powi(2) * 17.0 - 16.0f64.powi(2) * 20.0)).abs() < 1e-6
        );
    }
}
