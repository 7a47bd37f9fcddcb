//! Features cut into the bodies: holes and bores (through or blind, along an axis or
//! radial, copied to points, corners, circles, grids and the bodies they pass through),
//! counterbores and countersinks, slots, keyways (on a shaft or in a bore), ring grooves,
//! and pockets, recesses and sockets cut into a face.

use super::super::account::{at_both_ends, part_axis};
use super::super::doc::Role;
use super::super::lexicon::{CutKind, Noun, ShapeHint};
use super::super::profile::Profile;
use super::super::solid::{Axis, Body, Shape};
use super::super::text::Tk;
use super::{Built, Reader, Refusal, Res, place};

const EXTRA: f64 = 1.0;

/// Cuts every cut element, in the prompt's order.
pub fn read(r: &mut Reader<'_>) -> Res<()> {
    // Bores first: the holes through a part's middle that other features are placed by
    // ("a set screw into the bore", "a keyway in the bore").
    let mut order: Vec<usize> = (0..r.els.len()).collect();
    order.sort_by_key(|e| !matches!(r.els[*e].kind, Noun::Cut(CutKind::Bore)));
    for e in order {
        if r.done[e] {
            continue;
        }
        let Noun::Cut(kind) = r.els[e].kind else { continue };
        // A keyway named "keyway slot" is a keyway.
        let kind = if r.els[e].has_mod("keyway") || r.els[e].has_mod("keyseat") { CutKind::Keyway } else { kind };
        // A counterbore or countersink is cut with its holes.
        if matches!(kind, CutKind::Counterbore | CutKind::Countersink) && r.els[e].dims.is_empty() {
            continue;
        }
        // A cut named only as a reference ("from the bore", "the keyway is 6mm wide" after
        // its own mention) with nothing of its own: not a new cut.
        let el = &r.els[e];
        if el.dims.is_empty() && el.ranges.is_empty() && el.tuples.is_empty() && el.coords.is_empty() {
            continue;
        }
        let b = match kind {
            CutKind::Hole | CutKind::Bore => hole(r, e)?,
            CutKind::Keyway => keyway(r, e)?,
            CutKind::Slot => slot(r, e)?,
            CutKind::Groove => groove(r, e)?,
            CutKind::Pocket => pocket(r, e)?,
            CutKind::Counterbore | CutKind::Countersink => continue,
        };
        for bi in &b.bodies {
            check_cuts_something(r, e, *bi)?;
        }
        r.built[e] = Some(b);
        r.mark_element(e);
    }
    Ok(())
}

/// A cut lying wholly inside an earlier box cut removes nothing: the words ask for
/// something that is not there ("through both prongs in the Y direction", at X=0 in the slot).
fn check_cuts_something(r: &Reader<'_>, e: usize, bi: usize) -> Res<()> {
    let Some(c) = r.model.cuts.get(bi) else { return Ok(()) };
    let whole = r.model.bounds();
    // What of it lies within the part.
    let mut b = c.bounds();
    for k in 0..3 {
        b[0][k] = b[0][k].max(whole[0][k]);
        b[1][k] = b[1][k].min(whole[1][k]);
    }
    let outside = (0..3).any(|k| b[1][k] <= whole[0][k] + 1e-9 || b[0][k] >= whole[1][k] - 1e-9);
    let swallowed = r.model.cuts[..bi].iter().any(|p| {
        matches!(&p.shape, Shape::Prism { profile: Profile::Rect { .. }, rot, .. } if rot.abs() < 1e-9) && {
            let q = p.bounds();
            (0..3).all(|k| b[0][k] >= q[0][k] - 1e-9 && b[1][k] <= q[1][k] + 1e-9)
        }
    });
    if outside || swallowed || !touches_material(r, bi) {
        return Err(Refusal::new(
            r.quote_element(e),
            "as placed by these words it would cut nothing: it lies in empty space",
        ));
    }
    // A cut that holds a whole body would remove it ("a 25mm bore" in a 20mm cylinder).
    let raw = c.bounds();
    if let Some(body) = r.model.adds.iter().find(|a| {
        let q = a.bounds();
        (0..3).all(|k| raw[0][k] <= q[0][k] + 1e-9 && raw[1][k] >= q[1][k] - 1e-9)
    }) {
        return Err(Refusal::new(r.quote_element(e), format!("it would remove the whole {}", body.label)));
    }
    Ok(())
}

/// Whether a point of the part is in its material: inside a body added (a prism by its
/// profile, any other solid by its bounds) and not in a cut made before this one.
fn in_material(r: &Reader<'_>, p: [f64; 3], before: usize) -> bool {
    let in_prism = |b: &Body| match &b.shape {
        Shape::Prism { profile, axis, at, rot, from, to } => {
            let (u, v) = axis.uv();
            let w = p[axis.index()];
            let (du, dv) = (p[u.index()] - at[0], p[v.index()] - at[1]);
            let (sn, cs) = (-rot).to_radians().sin_cos();
            w >= from.min(*to) - 1e-9
                && w <= from.max(*to) + 1e-9
                && profile.contains([cs * du - sn * dv, sn * du + cs * dv])
        }
        _ => {
            let q = b.bounds();
            (0..3).all(|k| p[k] >= q[0][k] - 1e-9 && p[k] <= q[1][k] + 1e-9)
        }
    };
    let cut_before = r.model.cuts[..before].iter().any(|c| matches!(c.shape, Shape::Prism { .. }) && in_prism(c));
    r.model.adds.iter().any(in_prism) && !cut_before
}

/// Whether a cut reaches any material: points across its section (its centre and near its
/// outline) at three places along its length, one of them in the part.
fn touches_material(r: &Reader<'_>, bi: usize) -> bool {
    let Some(Shape::Prism { profile, axis, at, rot, from, to }) = r.model.cuts.get(bi).map(|c| &c.shape) else {
        return true;
    };
    let mut section = vec![[0.0, 0.0]];
    section.extend(profile.outline().into_iter().map(|q| [0.9 * q[0], 0.9 * q[1]]));
    let (sn, cs) = rot.to_radians().sin_cos();
    let (lo, hi) = (from.min(*to), from.max(*to));
    [0.1, 0.5, 0.9].iter().any(|f| {
        let w = lo + f * (hi - lo);
        section.iter().any(|q| {
            let uv = [at[0] + cs * q[0] - sn * q[1], at[1] + sn * q[0] + cs * q[1]];
            in_material(r, super::super::solid::point(*axis, uv, w), bi)
        })
    })
}

/// The bodies a cut goes through or into: the objects of "through", "into", "in", "on"
/// after its head in its sentences.
fn targets(r: &Reader<'_>, e: usize) -> Vec<usize> {
    let mut out = Vec::new();
    for &mi in &r.els[e].mentions {
        let m = &r.mentions[mi];
        for n in r.mentions.iter().filter(|n| n.sent == m.sent && n.head > m.head) {
            if n.elem == e {
                break;
            }
            if matches!(r.els[n.elem].kind, Noun::Cut(_)) && n.prep.is_none() {
                break;
            }
            if (matches!(n.prep.as_deref(), Some("through" | "into" | "in" | "on" | "of" | "and"))
                || (n.prep.is_none() && out.last().is_some()))
                && r.built[n.elem].is_some()
                && !out.contains(&n.elem)
            {
                out.push(n.elem);
            }
        }
    }
    out
}

/// The axis a cut runs along: "along the X axis", "in the Y direction", "radially … along X".
fn cut_axis(r: &Reader<'_>, e: usize) -> Option<Axis> {
    for &k in &r.els[e].dims {
        if let Some(a) = r.dim(k).axis
            && matches!(r.dim(k).role, Role::Diameter | Role::Radius)
        {
            return Some(a);
        }
    }
    let d = r.doc;
    for &mi in &r.els[e].mentions {
        let m = &r.mentions[mi];
        // Only where it is said of it, up to the next thing named.
        if m.prep.is_some() && m.prep.as_deref() != Some("with") {
            continue;
        }
        let (_, end) = d.sentence(m.sent);
        let end = r
            .mentions
            .iter()
            .filter(|n| n.sent == m.sent && n.head > m.head && n.elem != e && n.prep.is_none())
            .map(|n| n.start)
            .min()
            .unwrap_or(end);
        for i in m.head..end.saturating_sub(1) {
            // "oriented along the X axis", "along the Y axis", "in the Y direction" — not a
            // row's "spaced 40mm apart along X".
            let along = d.is(i, "along") || d.is(i, "oriented");
            if along || d.is(i, "direction") {
                let pick = |j: usize| d.axis_at(j);
                let a = if along {
                    let row = i > 0 && matches!(d.word(i - 1), Some("apart" | "spaced" | "interval"));
                    let named = (i + 1..(i + 5).min(d.len())).any(|j| d.is(j, "axis") || d.is(j, "direction"))
                        || d.is(i, "oriented");
                    if row || !named { None } else { pick(i + 1).or_else(|| pick(i + 2)).or_else(|| pick(i + 3)) }
                } else {
                    pick(i - 1)
                };
                if let Some(a) = a {
                    return Some(a);
                }
            }
        }
    }
    None
}

/// "through the 40 way", "through the 1.5 in way": along the axis on which the part
/// measures that length (one axis only).
fn way_axis(r: &mut Reader<'_>, e: usize) -> Res<Option<(Axis, bool)>> {
    let d = r.doc;
    let size = r.model.size();
    for k in r.els[e].dims.clone() {
        let dm = d.dims[k].clone();
        if r.used_dims[k] || !d.is(dm.tok + 1, "way") {
            continue;
        }
        let axes: Vec<Axis> =
            Axis::ALL.into_iter().filter(|a| (size[a.index()] - dm.mm).abs() <= 1e-6 * dm.mm.max(1.0)).collect();
        let [a] = axes.as_slice() else {
            return Err(Refusal::new(
                d.quote(dm.tok, dm.tok + 1),
                "the part does not measure this length along exactly one axis",
            ));
        };
        r.used_dims[k] = true;
        d.mark_range(dm.tok, dm.tok + 2);
        return Ok(Some((*a, false)));
    }
    // "through its length", "lengthwise", "end to end": along the part's longest extent.
    for (a, b) in r.sentences_of(e) {
        for i in a..b {
            let n = if matches!(d.word(i), Some("through" | "thru" | "along"))
                && matches!(d.word(i + 1), Some("its" | "the"))
                && d.is(i + 2, "length")
            {
                3
            } else if matches!(d.word(i), Some("full" | "entire" | "whole")) && d.is(i + 1, "length") {
                2
            } else if matches!(d.word(i), Some("lengthwise" | "lengthways")) {
                1
            } else if d.is(i, "end") && d.is(i + 1, "to") && d.is(i + 2, "end") {
                3
            } else {
                continue;
            };
            // An axis said with it ("through the full length along Z"), else the part's own
            // axis: its round bodies', whatever their proportions, else its longest extent.
            let Some(x) = cut_axis(r, e).or_else(|| part_axis(&r.model)) else {
                return Err(Refusal::new(
                    d.quote(i, i + n - 1),
                    "the part has no one axis (round bodies on one axis, or one longest extent) to bore along",
                ));
            };
            d.mark_range(i, i + n);
            return Ok(Some((x, true)));
        }
    }
    Ok(None)
}

/// "its centre 30 above the base": the height of a cut across the part, from its bottom
/// (or below its top).
fn height_of(r: &mut Reader<'_>, e: usize) -> Option<f64> {
    let k =
        r.find(e, &[Role::Inset], &["from-bottom"], &[]).or_else(|| r.find(e, &[Role::Inset], &["from-top"], &[]))?;
    r.used_dims[k] = true;
    let dm = r.doc.dims[k].clone();
    r.doc.mark_range(dm.phrase.0, dm.phrase.1 + 3);
    let b = r.model.bounds();
    Some(if dm.has("from-top") { b[1][2] - dm.mm } else { b[0][2] + dm.mm })
}

/// Extent of the whole part (or of some bodies) along an axis.
fn extent(r: &Reader<'_>, bodies: &[usize], axis: Axis) -> [f64; 2] {
    let k = axis.index();
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let all: Vec<usize> = if bodies.is_empty() { (0..r.model.adds.len()).collect() } else { bodies.to_vec() };
    for b in all {
        if let Some(body) = r.model.adds.get(b) {
            let q = body.bounds();
            lo = lo.min(q[0][k]);
            hi = hi.max(q[1][k]);
        }
    }
    [lo, hi]
}

/// The middle, across a cut's axis, of a part of one body (the body the cut goes through):
/// where a hole or a pattern no word places is centred. None for a part of several bodies,
/// whose holes are placed from the part's origin.
fn middle(r: &Reader<'_>, tg: &[usize], axis: Axis) -> Option<[f64; 2]> {
    if r.model.adds.len() != 1 || tg.iter().any(|t| r.built[*t].as_ref().is_some_and(|b| b.bodies != [0])) {
        return None;
    }
    let (u, v) = axis.uv();
    let (a, b) = (extent(r, &[0], u), extent(r, &[0], v));
    Some([(a[0] + a[1]) / 2.0, (b[0] + b[1]) / 2.0])
}

fn push_cut(r: &mut Reader<'_>, label: &str, shape: Shape) -> usize {
    r.model.cuts.push(Body::new(label, shape));
    r.model.cuts.len() - 1
}

fn hole(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    // "on each face", "through its side": faces other than the top and bottom are not read.
    for (a, b) in r.sentences_of(e) {
        for i in a..b {
            let face = r.doc.is(i, "face") || r.doc.is(i, "side");
            let which = r.doc.word(i.wrapping_sub(1)).unwrap_or("");
            if face
                && matches!(
                    which,
                    "each" | "every" | "all" | "its" | "front" | "back" | "left" | "right" | "other" | "four" | "six"
                )
            {
                return Err(Refusal::new(
                    r.doc.quote(i.saturating_sub(1), i),
                    "holes in faces other than the top and bottom are not made",
                ));
            }
        }
    }
    // A square hole is cut square; other shapes of hole are not made.
    let square = r.els[e].has_mod("square");
    // A thread given by its metric size is made as its tap drill ("M6 tapped"); other
    // threads, and holes of other shapes, are not made.
    let by_size = r.els[e].dims.iter().any(|k| r.dim(*k).has("tapped"));
    if by_size {
        super::bodies::mark_words(r, &["tapped", "thread", "threaded", "female"]);
    }
    if let Some(m) = r.els[e].mods.iter().find(|m| {
        matches!(m.as_str(), "rectangular" | "hexagonal" | "triangular" | "oval" | "elliptical" | "slotted")
            || (!by_size && matches!(m.as_str(), "tapped" | "threaded"))
    }) {
        return Err(Refusal::new(r.quote_element(e), format!("a {m} hole is not made")));
    }
    let d = r
        .take_diameter(e, &[], &["pitch", "circle", "counterbore", "countersink", "outer", "bolt"])
        .or_else(|| r.take_diameter(e, &["bolt"], &["pitch", "circle"]))
        // "15mm bore", "a 6mm hole": a bare size before the noun.
        .or_else(|| r.take(e, &[Role::Bare], &[], &["pitch", "circle", "from-center", "counterbore"]));
    let d = d.ok_or_else(|| Refusal::new(r.quote_element(e), "no diameter is given for it"))?;
    let tg = targets(r, e);
    // Its axis: said; else the one its points do not name ("at (X=+12, Z=19)" → Y); else
    // across the thin side of the plate or wall it goes through; else Z.
    let named: Vec<Axis> =
        r.els[e].tuples.iter().flat_map(|k| r.doc.tuples[*k].vals.iter().filter_map(|v| v.0)).collect();
    let by_points = (named.len() >= 2).then(|| Axis::ALL.into_iter().find(|a| !named.contains(a))).flatten();
    // A plate or wall: a box at most half as thick as its next size.
    let thin = tg.iter().find_map(|t| {
        let b = r.built[*t].as_ref()?;
        let body = r.model.adds.get(*b.bodies.first()?)?;
        if !matches!(&body.shape, Shape::Prism { profile: Profile::Rect { .. }, .. }) {
            return None;
        }
        let q = body.bounds();
        let s = [q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2]];
        let mut order = [0usize, 1, 2];
        order.sort_by(|a, b| s[*a].total_cmp(&s[*b]));
        (s[order[0]] <= 0.5 * s[order[1]]).then(|| Axis::ALL[order[0]])
    });
    let way = way_axis(r, e)?;
    let lengthwise = way.is_some_and(|w| w.1);
    let axis = match way {
        Some((a, _)) => Some(a),
        None => cut_axis(r, e),
    };
    // Across a round body standing on Z, unless its axis is said: a radial or cross hole.
    let named_radial = r.els[e].has_mod("radial") || r.els[e].has_mod("cross");
    let round_host = r.built.iter().flatten().any(|b| !b.cut && b.axis == Axis::Z && b.od.is_some());
    let axis = match axis {
        None if named_radial && round_host && by_points.is_none() => Some(Axis::X),
        a => a,
    };
    let axis = axis.or(by_points).or(thin).unwrap_or(Axis::Z);
    let count = place::count_of(r, e);
    let radial = r.says(e, "radial")
        || r.says(e, "radially")
        || named_radial
        || (axis != Axis::Z && by_points.is_none() && thin != Some(axis) && !lengthwise);
    if radial && axis != Axis::Z {
        return radial_hole(r, e, d, axis, &tg);
    }
    // Where: points, patterns, or the copies of the body it goes through ("through each mount").
    let mut at = place::points(r, e, axis)?;
    let target_size = tg.iter().find_map(|t| r.built[*t].as_ref().and_then(|b| b.size)).or_else(|| part_size(r));
    if at.is_empty() {
        at = place::grid(r, e).unwrap_or_default();
    }
    if at.is_empty() && count > 1 {
        at = place::circle(r, e, count)
            .or_else(|| place::rect_pattern(r, e))
            .or_else(|| if count == 4 { place::square_pattern(r, e) } else { None })
            .or_else(|| if count == 2 { target_size.and_then(|s| place::ends(r, e, s)) } else { None })
            .or_else(|| target_size.and_then(|s| place::corners(r, e, s)))
            .or_else(|| place::row(r, e, count, Axis::X, axis))
            .unwrap_or_default();
        // A pattern about the middle of the body it goes through (a channel runs from X=0).
        if let Some(c) = middle(r, &tg, axis) {
            for p in &mut at {
                *p = [p[0] + c[0], p[1] + c[1]];
            }
        }
    }
    if at.is_empty() && count == 1 && place::corners(r, e, target_size.unwrap_or([0.0, 0.0])).is_some() {
        return Err(Refusal::new(r.quote_element(e), "one hole inset from the corners: which corner is not said"));
    }
    if at.is_empty() {
        // Through the copies of what it passes through ("through each motor mount").
        let per = tg.iter().find_map(|t| r.built[*t].as_ref().filter(|b| b.at.len() > 1).map(|b| b.at.clone()));
        // A hole no word places is in the middle of what it goes through: a bore "through
        // its length" on the part's centre line, wherever the part stands (a bar lying
        // along X sits on the floor, its centre line above it), a hole "through the web" of
        // a channel that runs from X=0 at the middle of its length.
        let centre = middle(r, &tg, axis).or(lengthwise.then(|| {
            let (u, v) = axis.uv();
            let (a, b) = (extent(r, &[], u), extent(r, &[], v));
            [(a[0] + a[1]) / 2.0, (b[0] + b[1]) / 2.0]
        }));
        at = per.unwrap_or_else(|| vec![centre.unwrap_or([0.0, 0.0])]);
    }
    if count > 1 && at.len() != count as usize {
        return Err(Refusal::new(
            r.quote_element(e),
            format!("{count} of them asked for, {} placed by the words", at.len()),
        ));
    }
    // Depth: blind ("8mm deep") from the top face, else through what it passes through. A
    // depth after a counterbore's or countersink's size is theirs.
    let sink_at = r.els[e]
        .dims
        .iter()
        .map(|k| r.dim(*k))
        .filter(|d| d.has("counterbore") || d.has("countersink"))
        .map(|d| d.tok)
        .min();
    let depth = r
        .find(e, &[Role::Depth], &[], &["counterbore", "countersink"])
        .filter(|k| sink_at.is_none_or(|s| r.dim(*k).tok < s));
    let depth_tok = depth.map(|k| r.dim(k).tok);
    let depth = depth.map(|k| {
        r.used_dims[k] = true;
        r.dim(k).mm
    });
    let span = match r.take_range(e, axis) {
        Some(s) => s,
        None => {
            let bodies: Vec<usize> =
                tg.iter().filter_map(|t| r.built[*t].as_ref()).flat_map(|b| b.bodies.clone()).collect();
            let full = extent(r, &bodies, axis);
            let floor = tg.iter().find_map(|t| r.model.adds.get(r.built[*t].as_ref()?.bodies[0])?.shell.map(|s| s.t));
            if let Some(dp) = depth
                && dp >= full[1] - full[0] - 1e-9
            {
                return Err(Refusal::new(
                    r.quote_element(e),
                    format!(
                        "a blind hole {} mm deep in a part {} mm thick would go right through",
                        super::super::num::n(dp),
                        super::super::num::n(full[1] - full[0])
                    ),
                ));
            }
            match (depth, floor, r.says(e, "bottom")) {
                (Some(dp), _, true) => [full[0], full[0] + dp],
                (Some(dp), _, _) => [full[1] - dp, full[1]],
                (None, Some(t), true) => [full[0], full[0] + t],
                _ => full,
            }
        }
    };
    let profile = if square { Profile::Rect { w: d, h: d } } else { Profile::Circle { d } };
    // A blind hole "at both ends" ("M5 tapped x 8 dp both ends"): one from each end face.
    let mut spans = vec![span];
    if let (Some(dp), Some(a)) = (depth, depth_tok) {
        // In the depth's own clause, after it.
        let dc = r.doc;
        let b = (a..dc.len()).find(|&i| dc.sym(i, ',') || dc.sym(i, ';') || dc.sym(i, '.')).unwrap_or(dc.len());
        let both = at_both_ends(dc, a, b);
        if let Some(i) = both {
            let bodies: Vec<usize> =
                tg.iter().filter_map(|t| r.built[*t].as_ref()).flat_map(|b| b.bodies.clone()).collect();
            let full = extent(r, &bodies, axis);
            if 2.0 * dp >= full[1] - full[0] - 1e-9 {
                return Err(Refusal::new(
                    r.doc.quote(i, i + 1),
                    format!(
                        "two blind holes {} mm deep from the ends of a part {} mm long would meet",
                        super::super::num::n(dp),
                        super::super::num::n(full[1] - full[0])
                    ),
                ));
            }
            r.doc.mark_range(i, i + 2);
            spans = vec![[full[0], full[0] + dp], [full[1] - dp, full[1]]];
        }
    }
    let mut bodies = Vec::new();
    for span in &spans {
        for p in &at {
            bodies.push(push_cut(
                r,
                &r.els[e].noun.clone(),
                Shape::Prism { profile: profile.clone(), axis, at: *p, rot: 0.0, from: span[0], to: span[1] },
            ));
        }
    }
    // A counterbore or countersink with them: on the face the holes open into (+ end).
    counterbore(r, e, d, axis, &at, span)?;
    Ok(Built { axis, span, at, od: Some(d), id: None, size: None, bodies, cut: true })
}

fn part_size(r: &Reader<'_>) -> Option<[f64; 2]> {
    let b = r.model.bounds();
    (b[0][0].is_finite()).then(|| [b[1][0] - b[0][0], b[1][1] - b[0][1]])
}

/// "with a 10mm diameter counterbore 3mm deep on the top face", or "counterbored holes …
/// counterbore 10mm diameter, 3mm deep"; countersinks with their angle (90° unless said).
fn counterbore(r: &mut Reader<'_>, e: usize, d: f64, axis: Axis, at: &[[f64; 2]], span: [f64; 2]) -> Res<()> {
    let own = r.take_diameter(e, &["counterbore"], &[]).map(|v| (e, v));
    let cb_el = partner(r, e, CutKind::Counterbore);
    let (holder, dia) = match (own, cb_el) {
        (Some(x), _) => x,
        (None, Some(k)) => match r.take_diameter(k, &[], &[]) {
            Some(v) => (k, v),
            None => return Ok(()),
        },
        (None, None) => return countersink(r, e, d, axis, at, span),
    };
    let depth = r.take(holder, &[Role::Depth], &[], &[]).or_else(|| r.take(e, &[Role::Depth], &["counterbore"], &[]));
    let depth = depth.ok_or_else(|| Refusal::new(r.quote_element(holder), "the counterbore's depth is not given"))?;
    if dia <= d || depth >= span[1] - span[0] {
        return Err(Refusal::new(
            r.quote_element(holder),
            "the counterbore must be wider than its hole and shallower than the part",
        ));
    }
    // The hole below the counterbore stops where the counterbore begins (disjoint cuts).
    let n = at.len();
    let first = r.model.cuts.len() - n;
    for (k, p) in at.iter().enumerate() {
        if let Some(Shape::Prism { to, .. }) = r.model.cuts.get_mut(first + k).map(|c| &mut c.shape) {
            *to = span[1] - depth;
        }
        push_cut(
            r,
            "counterbore",
            Shape::Prism {
                profile: Profile::Circle { d: dia },
                axis,
                at: *p,
                rot: 0.0,
                from: span[1] - depth,
                to: span[1],
            },
        );
    }
    r.known.push(span[1] - span[0]);
    if holder != e {
        r.mark_element(holder);
    }
    Ok(())
}

fn countersink(r: &mut Reader<'_>, e: usize, d: f64, axis: Axis, at: &[[f64; 2]], span: [f64; 2]) -> Res<()> {
    let own = r.take_diameter(e, &["countersink"], &[]).map(|v| (e, v));
    let cs_el = partner(r, e, CutKind::Countersink);
    let (holder, dia) = match (own, cs_el) {
        (Some(x), _) => x,
        (None, Some(k)) => match r.take_diameter(k, &[], &[]) {
            Some(v) => (k, v),
            None => return Ok(()),
        },
        (None, None) => return Ok(()),
    };
    let angle = place::take_angles(r, holder)
        .first()
        .copied()
        .or_else(|| place::take_angles(r, e).first().copied())
        .unwrap_or(90.0);
    if dia <= d || !(30.0..=150.0).contains(&angle) {
        return Err(Refusal::new(
            r.quote_element(holder),
            "the countersink must be wider than its hole, at 30 to 150 degrees",
        ));
    }
    let depth = (dia - d) / 2.0 / (angle / 2.0).to_radians().tan();
    if depth >= span[1] - span[0] {
        return Err(Refusal::new(r.quote_element(holder), "the countersink is deeper than the part"));
    }
    let n = at.len();
    let first = r.model.cuts.len() - n;
    for (k, p) in at.iter().enumerate() {
        if let Some(Shape::Prism { to, .. }) = r.model.cuts.get_mut(first + k).map(|c| &mut c.shape) {
            *to = span[1] - depth;
        }
        push_cut(
            r,
            "countersink",
            Shape::Cone { axis, at: *p, from: span[1] - depth, to: span[1], d_from: d, d_to: dia },
        );
    }
    if holder != e {
        r.mark_element(holder);
    }
    Ok(())
}

/// The counterbore (or countersink) element of hole `e`: one named after it and before the
/// next hole ("Ø30 thru ctr, 4x Ø9 thru c'bore Ø15": the c'bore is the Ø9 holes').
fn partner(r: &Reader<'_>, e: usize, kind: CutKind) -> Option<usize> {
    let first = |k: usize| r.els[k].mentions.first().map_or(usize::MAX, |m| r.mentions[*m].head);
    let here = first(e);
    let next_hole = (0..r.els.len())
        .filter(|k| *k != e && matches!(r.els[*k].kind, Noun::Cut(CutKind::Hole | CutKind::Bore)) && first(*k) > here)
        .map(first)
        .min()
        .unwrap_or(usize::MAX);
    let undone = |k: &usize| matches!(r.els[*k].kind, Noun::Cut(c) if c == kind) && !r.done[*k];
    (0..r.els.len()).filter(undone).find(|k| first(*k) > here && first(*k) < next_hole).or_else(|| {
        // Said before the holes ("counterbored holes … counterbore 10 mm") when only one hole is named.
        let holes = (0..r.els.len()).filter(|k| matches!(r.els[*k].kind, Noun::Cut(CutKind::Hole))).count();
        if holes == 1 { (0..r.els.len()).find(undone) } else { None }
    })
}

/// A hole across a round body ("drilled radially through the hub at Z=20mm, oriented along
/// the X axis"): through one wall (from the axis out) or both ("passing through both walls").
fn radial_hole(r: &mut Reader<'_>, e: usize, d: f64, axis: Axis, tg: &[usize]) -> Res<Built> {
    let host = tg.iter().copied().find(|t| r.built[*t].as_ref().is_some_and(|b| b.axis == Axis::Z));
    let bodies: Vec<usize> = host.and_then(|h| r.built[h].as_ref()).map(|b| b.bodies.clone()).unwrap_or_default();
    let full = extent(r, &bodies, axis);
    let zspan = extent(r, &bodies, Axis::Z);
    // A hole across a body as wide as it (or wider) would cut it in two.
    if d >= full[1] - full[0] - 1e-9 {
        return Err(Refusal::new(
            r.quote_element(e),
            format!(
                "a {} mm hole across a body {} mm wide would cut it in two",
                super::super::num::n(d),
                super::super::num::n(full[1] - full[0])
            ),
        ));
    }
    // "8 from one end", "at 20 from one end": from the bottom end (either end makes the same part).
    let end_inset = r.find(e, &[Role::Inset], &[], &[]);
    let z = match r.take_coord(e, Axis::Z).or_else(|| height_of(r, e)) {
        Some(z) => z,
        None => match end_inset {
            Some(k) => {
                r.used_dims[k] = true;
                let dm = r.doc.dims[k].clone();
                r.doc.mark_range(dm.phrase.0, dm.phrase.1 + 3);
                zspan[0] + dm.mm
            }
            None => (zspan[0] + zspan[1]) / 2.0,
        },
    };
    // Through one wall of a ring (a set screw), else right through: "both walls", "a
    // through hole", or a host with no bore.
    let bored =
        r.built.iter().flatten().any(|b| {
            b.cut && b.axis == Axis::Z && b.at.len() == 1 && b.at[0][0].abs() < 1e-9 && b.at[0][1].abs() < 1e-9
        });
    let ring = host.and_then(|h| r.built[h].as_ref()).is_some_and(|b| b.id.is_some()) || bored;
    let both = r.says(e, "both")
        || r.says(e, "across")
        || r.els[e].has_mod("through")
        || r.els[e].noun == "through-hole"
        || !ring;
    let from = if both { full[0] - EXTRA } else { (full[0] + full[1]) / 2.0 };
    let to = full[1] + EXTRA;
    let (u, v) = axis.uv();
    let mut p = [0.0; 3];
    p[Axis::Z.index()] = z;
    let at = [p[u.index()], p[v.index()]];
    let bi = push_cut(
        r,
        &r.els[e].noun.clone(),
        Shape::Prism { profile: Profile::Circle { d }, axis, at, rot: 0.0, from, to },
    );
    // "at mid-height": the middle of what it passes through.
    r.known.push((zspan[0] + zspan[1]) / 2.0);
    for i in 0..r.doc.len() {
        if r.doc.is(i, "mid-height") {
            r.doc.mark(i);
        }
    }
    Ok(Built { axis, span: [from, to], at: vec![at], od: Some(d), id: None, size: None, bodies: vec![bi], cut: true })
}

/// A keyway: on a shaft's outer surface, or in the wall of its bore, on the side named
/// ("+X" unless said), as wide and deep as given, along the span given or the full length.
fn keyway(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let w = r
        .take(e, &[Role::Width], &[], &[])
        .ok_or_else(|| Refusal::new(r.quote_element(e), "no width is given for it"))?;
    let depth = r
        .take(e, &[Role::Depth], &[], &[])
        .ok_or_else(|| Refusal::new(r.quote_element(e), "no depth is given for it"))?;
    let in_bore = r.says(e, "bore");
    // The shaft or hub: the round body it is cut in.
    let host = (0..r.els.len())
        .filter(|k| r.built[*k].as_ref().is_some_and(|b| !b.cut && b.axis == Axis::Z && b.od.is_some()))
        .collect::<Vec<_>>();
    let zspan = r.take_range(e, Axis::Z).unwrap_or_else(|| {
        let all: Vec<usize> = host.iter().filter_map(|h| r.built[*h].as_ref()).flat_map(|b| b.bodies.clone()).collect();
        extent(r, &all, Axis::Z)
    });
    // Side: "+X" (default), "-X", "+Y", "-Y".
    let d = r.doc;
    let mut side = (Axis::X, 1.0);
    for (a, b) in r.sentences_of(e) {
        for i in a..b.saturating_sub(1) {
            let sign = if d.sym(i, '+') {
                1.0
            } else if d.sym(i, '-') {
                -1.0
            } else {
                continue;
            };
            if let Some(ax) = d.axis_at(i + 1).filter(|ax| *ax != Axis::Z) {
                side = (ax, sign);
                d.mark_range(i, i + 2);
                if d.is(i + 2, "side") {
                    d.mark(i + 2);
                }
                break;
            }
        }
    }
    let (lo, hi) = if in_bore {
        let bore = (0..r.els.len())
            .filter_map(|k| {
                r.built[k].as_ref().filter(|b| b.cut && b.axis == Axis::Z && b.at.len() == 1).and_then(|b| b.od)
            })
            .fold(f64::NAN, f64::max);
        let bore = if bore.is_finite() {
            bore
        } else {
            host.iter().filter_map(|h| r.built[*h].as_ref()?.id).fold(f64::NAN, f64::max)
        };
        if !bore.is_finite() {
            return Err(Refusal::new(r.quote_element(e), "a keyway in a bore, but no bore is given"));
        }
        let rb = bore / 2.0;
        // From inside the bore (past its surface at the keyway's edges) out to rb + depth.
        ((rb * rb - w * w / 4.0).max(0.0).sqrt() - 0.5, rb + depth)
    } else {
        let od = host.iter().filter_map(|h| r.built[*h].as_ref()?.od).fold(f64::NAN, f64::max);
        if !od.is_finite() {
            return Err(Refusal::new(r.quote_element(e), "a keyway on a shaft, but no round shaft is given"));
        }
        (od / 2.0 - depth, od / 2.0 + EXTRA)
    };
    r.known.extend([lo, hi, lo + 0.5, (lo + hi) / 2.0]);
    super::bodies::mark_words(r, &["radially", "radial", "outward", "surface"]);
    let rad = (hi - lo) / 2.0 + lo;
    let (u, _) = Axis::Z.uv();
    let at = if side.0 == u { [side.1 * rad, 0.0] } else { [0.0, side.1 * rad] };
    let (pw, ph) = if side.0 == u { (hi - lo, w) } else { (w, hi - lo) };
    let bi = push_cut(
        r,
        "keyway",
        Shape::Prism {
            profile: Profile::Rect { w: pw, h: ph },
            axis: Axis::Z,
            at,
            rot: 0.0,
            from: zspan[0],
            to: zspan[1],
        },
    );
    Ok(Built {
        axis: Axis::Z,
        span: zspan,
        at: vec![at],
        od: None,
        id: None,
        size: Some([pw, ph]),
        bodies: vec![bi],
        cut: true,
    })
}

/// A slot: cut from a face to a depth across the part ("a 10mm wide slot (in X) is cut from
/// the top face, 15mm deep, … running the full Y width"), or a stadium-shaped slot through
/// a plate ("a 30mm long, 8mm wide slot through the plate").
fn slot(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    // A slot's ends are round unless said square ("with round ends", "radiused ends").
    for (a, b) in r.sentences_of(e) {
        for i in a..b.saturating_sub(1) {
            if matches!(r.doc.word(i), Some("round" | "rounded" | "radiused" | "semicircular" | "full"))
                && r.doc.is(i + 1, "end")
            {
                r.doc.mark_range(i, i + 2);
            }
        }
    }
    // "a 60 x 20 slot": its length by its width, overall.
    let listed: Vec<usize> =
        r.free_dims(e).into_iter().filter(|k| r.dim(*k).list.is_some() && r.dim(*k).role == Role::Bare).collect();
    let (w, len) = if let ([a, b], None) = (listed.as_slice(), r.find(e, &[Role::Width], &[], &[])) {
        let (x, y) = (r.dim(*a).mm, r.dim(*b).mm);
        r.used_dims[*a] = true;
        r.used_dims[*b] = true;
        (x.min(y), Some(x.max(y)))
    } else {
        let w = r
            .take(e, &[Role::Width], &[], &[])
            .ok_or_else(|| Refusal::new(r.quote_element(e), "no width is given for it"))?;
        (w, r.take(e, &[Role::Length], &[], &[]))
    };
    let depth = r.take(e, &[Role::Depth], &[], &[]);
    let across = r.find(e, &[Role::Width], &[], &[]).map(|k| r.dim(k).axis);
    let w_axis = r.els[e]
        .dims
        .iter()
        .find_map(|k| (r.dim(*k).role == Role::Width).then(|| r.dim(*k).axis).flatten())
        .unwrap_or(Axis::X);
    let _ = across;
    let b = r.model.bounds();
    let at_pts = place::points(r, e, Axis::Z)?;
    let c = at_pts.first().copied().unwrap_or([0.0, 0.0]);
    match (depth, len) {
        (Some(dp), None) => {
            // Across the whole part, from the top face down.
            let (sx, sy) = if w_axis == Axis::X { (w, b[1][1] - b[0][1]) } else { (b[1][0] - b[0][0], w) };
            let cy = if w_axis == Axis::X { (b[0][1] + b[1][1]) / 2.0 } else { c[1] };
            let cx = if w_axis == Axis::X { c[0] } else { (b[0][0] + b[1][0]) / 2.0 };
            let span = [b[1][2] - dp, b[1][2]];
            let bi = push_cut(
                r,
                "slot",
                Shape::Prism {
                    profile: Profile::Rect { w: sx, h: sy },
                    axis: Axis::Z,
                    at: [cx, cy],
                    rot: 0.0,
                    from: span[0],
                    to: span[1],
                },
            );
            r.known.push(span[0]);
            r.known.push((span[0] + b[0][2]) / 2.0);
            r.known.push((span[0] + span[1]) / 2.0);
            for i in 0..r.doc.len() {
                if r.doc.is(i, "width") && r.doc.axis_at(i.wrapping_sub(1)).is_some() {
                    r.doc.mark_range(i.saturating_sub(3), i + 1);
                }
            }
            Ok(Built {
                axis: Axis::Z,
                span,
                at: vec![[cx, cy]],
                od: None,
                id: None,
                size: Some([sx, sy]),
                bodies: vec![bi],
                cut: true,
            })
        }
        (dp, Some(l)) => {
            if w >= l {
                return Err(Refusal::new(r.quote_element(e), "a slot's width must be less than its length"));
            }
            let span = match dp {
                Some(dp) => [b[1][2] - dp, b[1][2]],
                None => [b[0][2], b[1][2]],
            };
            let rect = r.says(e, "rectangular");
            let profile = if rect { Profile::Rect { w: l, h: w } } else { Profile::Stadium { l, w } };
            let rot = if r.els[e].dims.iter().any(|k| r.dim(*k).role == Role::Length && r.dim(*k).axis == Some(Axis::Y))
            {
                90.0
            } else {
                0.0
            };
            let bi =
                push_cut(r, "slot", Shape::Prism { profile, axis: Axis::Z, at: c, rot, from: span[0], to: span[1] });
            Ok(Built {
                axis: Axis::Z,
                span,
                at: vec![c],
                od: None,
                id: None,
                size: Some([l, w]),
                bodies: vec![bi],
                cut: true,
            })
        }
        (None, None) => Err(Refusal::new(r.quote_element(e), "a slot needs its length, or its depth from a face")),
    }
}

/// A ring groove: "a ring between 38mm inner diameter and 50mm outer diameter, cut from
/// Z=14 to Z=16", or "2mm deep" into the top face; or around a shaft ("a 3mm wide, 1mm
/// deep groove around the shaft at Z=20").
fn groove(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let od = r.take_diameter(e, &["outer"], &[]);
    let id = r.take_diameter(e, &["inner"], &[]);
    let depth = r.take(e, &[Role::Depth], &[], &[]);
    let b = r.model.bounds();
    let (od, id, span) = match (od, id) {
        (Some(o), Some(i)) if i < o => {
            let span = r.take_range(e, Axis::Z).or_else(|| depth.map(|dp| [b[1][2] - dp, b[1][2]]));
            let span = span.ok_or_else(|| Refusal::new(r.quote_element(e), "no depth is given for it"))?;
            r.known.push(span[1] - span[0]);
            (o, i, span)
        }
        _ => {
            // Around a round body, at a height.
            let w = r.take(e, &[Role::Width], &[], &[]).ok_or_else(|| {
                Refusal::new(r.quote_element(e), "a groove needs its inner and outer diameters, or its width and depth")
            })?;
            let dp = depth.ok_or_else(|| Refusal::new(r.quote_element(e), "no depth is given for it"))?;
            let host = (0..r.els.len())
                .filter_map(|k| r.built[k].as_ref().filter(|b| !b.cut && b.od.is_some()))
                .map(|b| b.od.unwrap_or(0.0))
                .fold(0.0, f64::max);
            let z = r
                .take_coord(e, Axis::Z)
                .ok_or_else(|| Refusal::new(r.quote_element(e), "where along the shaft is not given (at Z=…)"))?;
            (host + 2.0 * EXTRA, host - 2.0 * dp, [z - w / 2.0, z + w / 2.0])
        }
    };
    let bi = push_cut(
        r,
        "groove",
        Shape::Prism {
            profile: Profile::Annulus { od, id },
            axis: Axis::Z,
            at: [0.0, 0.0],
            rot: 0.0,
            from: span[0],
            to: span[1],
        },
    );
    Ok(Built {
        axis: Axis::Z,
        span,
        at: vec![[0.0, 0.0]],
        od: Some(od),
        id: Some(id),
        size: None,
        bodies: vec![bi],
        cut: true,
    })
}

/// A pocket, recess or socket cut into a face: hexagonal ("6.93mm across corners"),
/// round or rectangular, to a depth, in the top face of the body named (or of the part).
fn pocket(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let shape = r.els[e].shape;
    // "a window cut right through": as deep as the part.
    let through = r.says(e, "through") || r.says(e, "thru");
    let depth = r.take(e, &[Role::Depth], &[], &[]).or_else(|| {
        through.then(|| {
            let b = r.model.bounds();
            b[1][2] - b[0][2]
        })
    });
    let depth = depth.ok_or_else(|| Refusal::new(r.quote_element(e), "no depth is given for it"))?;
    let profile = match shape {
        Some(ShapeHint::Ngon(n)) => {
            let d = r
                .take(e, &[Role::Bare, Role::Diameter], &["across", "corner"], &[])
                .or_else(|| r.take_diameter(e, &["circumscribed"], &[]))
                .or_else(|| {
                    r.take(e, &[Role::Bare, Role::Width], &["across", "flat"], &[])
                        .map(|af| af / (std::f64::consts::PI / n as f64).cos())
                });
            let d =
                d.ok_or_else(|| Refusal::new(r.quote_element(e), "its size across corners (or flats) is not given"))?;
            Profile::Ngon { n, d, phase: 0.0 }
        }
        Some(ShapeHint::Round) => Profile::Circle {
            d: r.take_diameter(e, &[], &[])
                .ok_or_else(|| Refusal::new(r.quote_element(e), "no diameter is given for it"))?,
        },
        _ => {
            if let Some(dm) = r.take_diameter(e, &[], &[]) {
                Profile::Circle { d: dm }
            } else {
                let l = r.take(e, &[Role::Length, Role::Bare], &[], &[]);
                let w = r.take(e, &[Role::Width, Role::Bare], &[], &[]);
                match (l, w) {
                    (Some(l), Some(w)) => Profile::Rect { w: l, h: w },
                    _ => {
                        return Err(Refusal::new(
                            r.quote_element(e),
                            "its size is not given (a diameter, or length and width)",
                        ));
                    }
                }
            }
        }
    };
    // Into the top face of the body named ("of the head"), else of the part.
    let tg = targets(r, e);
    let bodies: Vec<usize> = tg.iter().filter_map(|t| r.built[*t].as_ref()).flat_map(|b| b.bodies.clone()).collect();
    let bottom = r.says(e, "bottom") && !r.says(e, "top");
    let z = extent(r, &bodies, Axis::Z);
    let span = if bottom { [z[0], z[0] + depth] } else { [z[1] - depth, z[1]] };
    let at = place::points(r, e, Axis::Z)?.first().copied().unwrap_or([0.0, 0.0]);
    let bi = push_cut(
        r,
        &r.els[e].noun.clone(),
        Shape::Prism { profile, axis: Axis::Z, at, rot: 0.0, from: span[0], to: span[1] },
    );
    let _ = Tk::Sym('.');
    Ok(Built { axis: Axis::Z, span, at: vec![at], od: None, id: None, size: None, bodies: vec![bi], cut: true })
}
