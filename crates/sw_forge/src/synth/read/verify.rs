//! Accounting for every number and word after the part is built. A length, span,
//! coordinate, point or angle the construction did not use must restate the part (its
//! extents, a body's diameter or span, a radial distance, a point of a path, within 0.5 %,
//! or 2 % after "approximately"); a body or cut that was named but not made, and any word
//! not read that carries geometry, refuses the prompt with its exact words.

use super::super::doc::{QUALS, role_of};
use super::super::lexicon::{Noun, is_filler};
use super::super::text::Tk;
use super::{Reader, Refusal, Res};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// Every length the finished part has, for restatements to match.
fn lengths(r: &Reader<'_>) -> Vec<f64> {
    let mut v = r.known.clone();
    let b = r.model.bounds();
    for (lo, hi) in b[0].iter().zip(&b[1]) {
        v.extend([hi - lo, *lo, *hi, (hi - lo) / 2.0]);
    }
    for built in r.built.iter().flatten() {
        v.extend([built.span[1] - built.span[0], built.span[0], built.span[1]]);
        if let Some(d) = built.od {
            v.extend([d, d / 2.0]);
            if let Some(i) = built.id {
                v.push((d - i) / 2.0);
            }
        }
        if let Some(i) = built.id {
            v.extend([i, i / 2.0]);
        }
        if let Some(s) = built.size {
            v.extend(s);
        }
        for p in &built.at {
            v.extend([
                p[0].abs(),
                p[1].abs(),
                (p[0] * p[0] + p[1] * p[1]).sqrt(),
                2.0 * (p[0] * p[0] + p[1] * p[1]).sqrt(),
            ]);
        }
        // Copies' spacing and the pattern's extent.
        if built.at.len() > 1 {
            for (i, p) in built.at.iter().enumerate() {
                for q in built.at.iter().skip(i + 1) {
                    v.push(((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt());
                    v.push((p[0] - q[0]).abs());
                    v.push((p[1] - q[1]).abs());
                }
            }
        }
    }
    // Steps between bodies' ends ("protruding 12mm above the gear face").
    let spans: Vec<[f64; 2]> = r.built.iter().flatten().filter(|b| !b.cut).map(|b| b.span).collect();
    for (i, a) in spans.iter().enumerate() {
        for b in spans.iter().skip(i + 1) {
            v.extend([(a[1] - b[1]).abs(), (a[0] - b[0]).abs()]);
        }
    }
    // Overhangs: half the difference of two bodies' sizes ("extends 10mm past the wall on each side").
    let sizes: Vec<[f64; 2]> = r.built.iter().flatten().filter_map(|b| b.size).collect();
    for (i, a) in sizes.iter().enumerate() {
        for b in sizes.iter().skip(i + 1) {
            for k in 0..2 {
                v.extend([(a[k] - b[k]).abs() / 2.0, (a[k] - b[k]).abs()]);
            }
        }
    }
    // Distances from a copy to the edges of the part (an inset restated).
    for built in r.built.iter().flatten() {
        for p in &built.at {
            v.extend([p[0] - b[0][0], b[1][0] - p[0], p[1] - b[0][1], b[1][1] - p[1]]);
        }
    }
    for (k, d) in r.doc.dims.iter().enumerate() {
        if r.used_dims[k] {
            v.push(d.mm);
        }
    }
    // Stars' tip and root circles.
    for b in r.model.adds.iter() {
        if let super::super::solid::Shape::Prism {
            profile: super::super::profile::Profile::Star { tip, root, .. },
            ..
        } = &b.shape
        {
            v.extend([*tip, *root, 2.0 * tip, 2.0 * root]);
        }
    }
    // Polygons' width across flats and their sides.
    for b in r.model.adds.iter().chain(r.model.cuts.iter()) {
        if let super::super::solid::Shape::Prism {
            profile: super::super::profile::Profile::Ngon { n, d, .. }, ..
        } = &b.shape
        {
            let n = *n as f64;
            v.extend([d * (std::f64::consts::PI / n).cos(), d * (std::f64::consts::PI / n).sin()]);
        }
    }
    v
}

/// Coordinates along an axis the part has (bounds, spans, copies, path points).
fn coordinates(r: &Reader<'_>, axis: usize) -> Vec<f64> {
    let mut v: Vec<f64> = r.known_points.iter().map(|p| p[axis]).collect();
    let b = r.model.bounds();
    v.extend([b[0][axis], b[1][axis], (b[0][axis] + b[1][axis]) / 2.0]);
    for body in r.model.adds.iter().chain(r.model.cuts.iter()) {
        let q = body.bounds();
        v.extend([q[0][axis], q[1][axis], (q[0][axis] + q[1][axis]) / 2.0]);
    }
    v.extend(r.known.iter().copied());
    v
}

fn approx_near(r: &Reader<'_>, tok: usize) -> bool {
    (tok.saturating_sub(4)..tok)
        .any(|i| matches!(r.doc.word(i), Some("approximately" | "about" | "approx" | "roughly" | "around" | "nearly")))
}

/// Distances that place things on the finished part: from each side of the part to each
/// body's and cut's sides and centre, and to each copy's centre.
fn placements(r: &Reader<'_>) -> Vec<f64> {
    let b = r.model.bounds();
    let mut v = Vec::new();
    for body in r.model.adds.iter().chain(r.model.cuts.iter()) {
        let q = body.bounds();
        for k in 0..3 {
            for x in [q[0][k], q[1][k], (q[0][k] + q[1][k]) / 2.0] {
                v.extend([(x - b[0][k]).abs(), (b[1][k] - x).abs(), (x - (b[0][k] + b[1][k]) / 2.0).abs()]);
            }
        }
    }
    for built in r.built.iter().flatten() {
        for p in &built.at {
            v.extend([p[0] - b[0][0], b[1][0] - p[0], p[1] - b[0][1], b[1][1] - p[1], p[0].abs(), p[1].abs()]);
        }
    }
    v
}

pub fn check(r: &mut Reader<'_>) -> Res<()> {
    let d = r.doc;
    let lens = lengths(r);
    let places = placements(r);
    // Lengths not used.
    for k in 0..d.dims.len() {
        let dm = &d.dims[k];
        if !r.used_dims[k] {
            let tol = if approx_near(r, dm.tok) { 0.02 } else { 0.005 };
            // A length that places something ("30 above the base", "10 from the edges")
            // restates only a place on the part, not any size it has.
            let candidates = if dm.role == super::super::doc::Role::Inset { &places } else { &lens };
            if !candidates.iter().any(|c| close(dm.mm, *c, tol)) {
                if std::env::var_os("SW_SYNTH_DEBUG").is_some() {
                    eprintln!("unplaced length {} ({:?}); candidates {lens:?}", dm.mm, dm.role);
                }
                return Err(Refusal::new(
                    r.quote_dim(k),
                    "a length the part does not have, or one the synthesizer could not place",
                ));
            }
            r.used_dims[k] = true;
        }
        // Its number and its role and qualifier words are read, and "on each side" after it.
        d.mark(dm.tok);
        for i in dm.phrase.1..(dm.phrase.1 + 8).min(d.len()) {
            if d.is(i, "side") && d.word(i - 1).is_some_and(|w| w == "each" || w == "both") {
                d.mark_range(i - 2, i + 1);
            }
        }
        for i in dm.phrase.0..dm.phrase.1.min(d.len()) {
            if let Some(w) = d.word(i)
                && (role_of(w).is_some()
                    || QUALS.contains(&w)
                    || is_filler(w)
                    || matches!(w, "x" | "y" | "z")
                    || (w == "square" && (dm.role == super::super::doc::Role::Side || dm.has("square"))))
            {
                d.mark(i);
            }
        }
    }
    // Spans.
    for k in 0..d.ranges.len() {
        if r.used_ranges[k] {
            continue;
        }
        let rg = &d.ranges[k];
        let cs = coordinates(r, rg.axis.index());
        let tol = 0.005;
        if !(cs.iter().any(|c| close(rg.a, *c, tol)) && cs.iter().any(|c| close(rg.b, *c, tol))) {
            return Err(Refusal::new(d.quote(rg.toks.0, rg.toks.1 - 1), "a span the part does not have"));
        }
        r.used_ranges[k] = true;
        d.mark_range(rg.toks.0, rg.toks.1);
    }
    // Coordinates.
    for k in 0..d.coords.len() {
        if r.used_coords[k] {
            continue;
        }
        let c = &d.coords[k];
        let tol = if approx_near(r, c.tok) { 0.02 } else { 0.005 };
        if !coordinates(r, c.axis.index()).iter().any(|v| close(c.v, *v, tol)) {
            return Err(Refusal::new(d.quote(c.tok, c.tok + 2), "a coordinate the part has nothing at"));
        }
        r.used_coords[k] = true;
        d.mark_range(c.tok, c.tok + 3);
    }
    // Points.
    for k in 0..d.tuples.len() {
        if r.used_tuples[k] {
            continue;
        }
        let t = &d.tuples[k];
        let tol = if approx_near(r, t.toks.0) { 0.02 } else { 0.005 };
        let ok = t.vals.iter().all(|(axis, v, _)| {
            let axes: Vec<usize> = match axis {
                Some(a) => vec![a.index()],
                None => vec![0, 1, 2],
            };
            axes.iter().any(|a| coordinates(r, *a).iter().any(|c| close(v.abs(), c.abs(), tol)))
        });
        if !ok {
            return Err(Refusal::new(d.quote(t.toks.0, t.toks.1 - 1), "a point the part has nothing at"));
        }
        r.used_tuples[k] = true;
        d.mark_range(t.toks.0, t.toks.1);
    }
    // Angles: used, or the same as one used ("the spokes at 0 and 180 degrees are …").
    let used: Vec<f64> =
        r.used_angles.iter().filter_map(|i| if let Tk::Deg(a) = d.toks[*i].kind { Some(a) } else { None }).collect();
    for (i, t) in d.toks.iter().enumerate() {
        if let Tk::Deg(a) = t.kind
            && !r.used_angles.contains(&i)
            && !used.iter().any(|u| (u - a).abs() < 1e-9)
        {
            return Err(Refusal::new(d.quote(i, i), "an angle the synthesizer could not place"));
        }
    }
    // Bodies and cuts named but not made.
    for e in 0..r.els.len() {
        if r.done[e] {
            continue;
        }
        match r.els[e].kind {
            Noun::Whole => r.mark_element(e),
            _ => {
                let m = &r.els[e].mentions;
                let all_read = m.iter().all(|mi| {
                    let x = &r.mentions[*mi];
                    (x.start..=x.head).all(|i| d.is_used(i))
                });
                if !all_read {
                    // A reference to a made thing ("through the plate") or a restating name.
                    // Named as where something else is ("through the wall", "of the shaft"),
                    // not as something the part has ("with four holes").
                    let referenced = m.iter().all(|mi| {
                        let x = &r.mentions[*mi];
                        x.prep.as_deref().is_some_and(|p| p != "with")
                            || (x.definite && x.prep.as_deref() != Some("with"))
                    });
                    // "no chamfers", "without a hole": said not to be there, and not made.
                    let negated = m.iter().all(|mi| {
                        let x = &r.mentions[*mi];
                        x.start > 0 && matches!(d.word(x.start - 1), Some("no" | "without" | "not"))
                    });
                    if negated {
                        r.mark_element(e);
                        continue;
                    }
                    // Or the shape of a thing made ("what a hexagon gives" of a hex bar).
                    let shape = match r.els[e].kind {
                        Noun::Body(h) if r.els[e].dims.is_empty() => Some(h),
                        _ => None,
                    };
                    let same_noun_made = (0..r.els.len()).any(|o| {
                        o != e
                            && r.done[o]
                            && (r.els[o].noun == r.els[e].noun
                                || r.els[o].has_mod(&r.els[e].noun)
                                || (shape.is_some() && r.built[o].is_some() && r.shape_of(o) == shape))
                    });
                    if referenced
                        || same_noun_made
                        || r.built.iter().flatten().count() > 0 && is_place_noun(&r.els[e].noun)
                    {
                        r.mark_element(e);
                        continue;
                    }
                    return Err(Refusal::new(r.quote_element(e), "named, but nothing says its size or where it is"));
                }
            }
        }
    }
    // "the base at Z=0", "the top at Z=30": the part's bottom and top.
    let pb = r.model.bounds();
    for i in 0..d.len().saturating_sub(4) {
        if matches!(d.word(i), Some("base" | "bottom" | "top"))
            && d.is(i + 1, "at")
            && d.axis_at(i + 2) == Some(super::super::solid::Axis::Z)
            && let Some(c) = d.coords.iter().find(|c| c.tok == i + 2)
        {
            let z = if d.is(i, "top") { pb[1][2] } else { pb[0][2] };
            if (c.v - z).abs() < 1e-6 {
                d.mark(i);
            }
        }
    }
    // "on top of the web", "sitting on top of the shaft": of a made thing.
    for i in 0..d.len().saturating_sub(2) {
        if (d.is(i, "top") || d.is(i, "end") || d.is(i, "tip") || d.is(i, "center"))
            && d.is(i + 1, "of")
            && !d.is_used(i)
        {
            let of_made =
                r.mentions.iter().any(|m| m.start <= i + 3 && m.head > i + 1 && m.head <= i + 5 && r.done[m.elem]);
            if of_made {
                d.mark_range(i, i + 2);
            }
        }
    }
    // "at the bottom", "on top": a body whose span is at the part's bottom or top says so.
    let b = r.model.bounds();
    for (e, built) in r.built.iter().enumerate() {
        let Some(built) = built else { continue };
        for (a, z) in r.sentences_of(e) {
            for i in a..z {
                let ok = match d.word(i) {
                    Some("bottom" | "base") => (built.span[0] - b[0][2]).abs() < 1e-6,
                    Some("top") => (built.span[1] - b[1][2]).abs() < 1e-6 || built.cut,
                    _ => false,
                };
                if ok && !d.is_used(i) {
                    d.mark(i);
                }
            }
        }
    }
    for (i, t) in d.toks.iter().enumerate() {
        if let Tk::Deg(_) = t.kind {
            d.mark(i);
        }
    }
    // Words.
    let runs = d.unread_runs(|i| match &d.toks[i].kind {
        // A qualifier naming a length with no number ("(inner diameter)").
        Tk::Word(w)
            if QUALS.contains(&w.as_str())
                && d.word(i + 1).is_some_and(|n| {
                    role_of(n).is_some() || matches!(n, "surface" | "face" | "dimension" | "size" | "edge")
                }) =>
        {
            true
        }
        Tk::Word(w) => {
            is_filler(w)
                || (role_of(w).is_some() && w != "side" && w != "sided")
                || matches!(w.as_str(), "x" | "y" | "z" | "xy" | "xz" | "yz" | "degree" | "mm")
        }
        Tk::Sym(_) => true,
        // A number without a unit is read only as a count ("4x", "six holes", "16 teeth")
        // or an enumeration "(1)"; any other is a size that was not read.
        Tk::Num { unit: None, .. } => is_count(d, i),
        _ => false,
    });
    // "… for the cable", "for weld clearance": what the part is for, no geometry.
    let runs: Vec<(usize, usize)> = runs
        .into_iter()
        .filter(|(a, b)| {
            let mut p = *a;
            while p > 0 && matches!(d.word(p - 1), Some("the" | "a" | "an")) {
                p -= 1;
            }
            let purpose = p > 0 && d.is(p - 1, "for");
            !(purpose && (*a..=*b).all(|i| d.word(i).is_some()))
        })
        .collect();
    if let Some((a, b)) = runs.first() {
        return Err(Refusal::new(d.quote(*a, *b), "the synthesizer does not know what these words ask for"));
    }
    Ok(())
}

/// Whether the unitless number at `i` counts something: before "x", before the noun it
/// counts (past fillers and labels: "6 equally spaced holes"), or numbering an item "(1)".
fn is_count(d: &super::super::doc::Doc, i: usize) -> bool {
    if d.sym(i + 1, 'x') || (i > 0 && d.sym(i - 1, '=')) || (i > 0 && d.sym(i - 1, '(') && d.sym(i + 1, ')')) {
        return true;
    }
    // The counted noun follows, past words of its own phrase only ("6 equally spaced
    // holes", "4 M6 clearance holes"), never past a preposition ("30 above the base").
    for j in i + 1..(i + 5).min(d.len()) {
        match (d.word(j), &d.toks[j].kind) {
            (Some(w), _) if super::super::lexicon::noun(w).is_some() => return true,
            (
                Some(
                    "tooth" | "vertex" | "point" | "side" | "sided" | "per" | "row" | "time" | "spoke" | "step"
                    | "turn",
                ),
                _,
            ) => {
                return true;
            }
            (Some(w), _)
                if super::super::lexicon::shape_adjective(w).is_some()
                    || super::super::mention::LABELS.contains(&w)
                    || matches!(w, "metric" | "equally" | "evenly" | "spaced" | "whole" | "more" | "identical") => {}
            (None, Tk::Num { .. } | Tk::Sym('-')) => {}
            _ => return false,
        }
    }
    false
}

/// Nouns that, said of a made part, name a place on it rather than a new body.
fn is_place_noun(w: &str) -> bool {
    matches!(
        w,
        "base"
            | "body"
            | "head"
            | "floor"
            | "wall"
            | "rim"
            | "section"
            | "seat"
            | "shoulder"
            | "neck"
            | "hub"
            | "prong"
            | "ear"
            | "tip"
            | "leg"
    )
}
