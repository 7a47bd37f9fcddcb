//! Base solids from their words: boxes, cylinders, rings and tubes, regular prisms,
//! stars (gears), ellipses, stadiums, cones and frustums, spheres, hemispheres, capsules,
//! tori, pyramids and wedges — each sized from its lengths, turned along the axis it is
//! given along, stacked on the body before it or spanning the Z range it names, and
//! copied to the points, corners, circles, grids or rows its words place it at.

use super::super::doc::Role;
use super::super::lexicon::{Noun, ShapeHint};
use super::super::profile::Profile;
use super::super::solid::{Axis, Body, Shape};
use super::{Built, Reader, Refusal, Res, place};

/// Lengths that size a body along its axis.
const ALONG: &[Role] = &[Role::Length, Role::Height, Role::Thickness, Role::Depth];

fn need(v: Option<f64>, what: &str, r: &Reader<'_>, e: usize) -> Res<f64> {
    match v {
        Some(x) if x.is_finite() && x > 0.0 => Ok(x),
        Some(x) => Err(Refusal::new(r.quote_element(e), format!("its {what} must be a positive length, not {x}"))),
        None => Err(Refusal::new(r.quote_element(e), format!("no {what} is given for it"))),
    }
}

/// Builds every body element not built yet, in the order the prompt gives them.
pub fn read(r: &mut Reader<'_>) -> Res<()> {
    for e in 0..r.els.len() {
        // A round part named as a whole ("a flat belt pulley, Ø100 x 40 face", "a flywheel
        // 300 dia x 60") with nothing else made of it: its own round body.
        let round_whole = r.els[e].kind == Noun::Whole
            && r.els[e].title
            && r.model.adds.is_empty()
            && matches!(r.els[e].noun.as_str(), "pulley" | "flywheel" | "handwheel" | "coupling" | "idler")
            && r.els[e].dims.iter().any(|k| !r.used_dims[*k] && r.dim(*k).role == Role::Diameter);
        if round_whole {
            r.els[e].kind = Noun::Body(ShapeHint::Round);
        }
        if r.done[e] || !matches!(r.els[e].kind, Noun::Body(_)) {
            continue;
        }
        // The part's name with no size of its own is only its name ("A hex bolt: …"); its
        // overall sizes are restatements of its bodies.
        let own = r.els[e].dims.iter().any(|k| !r.dim(*k).has("total") && !r.dim(*k).has("overall"));
        let others =
            (0..r.els.len()).any(|o| o != e && matches!(r.els[o].kind, Noun::Body(_)) && !r.els[o].dims.is_empty());
        if r.els[e].title && !own && (r.els.len() > 1 && (r.els[e].dims.is_empty() || others)) {
            r.mark_element(e);
            continue;
        }
        // The walls and floor of a hollowed part are its shell's, read with it.
        if !r.els[e].title
            && matches!(r.els[e].noun.as_str(), "wall" | "floor")
            && super::treat::hollow_box(r).is_some()
        {
            continue;
        }
        // A body with no quantity of its own is a name or a reference ("through the wall",
        // "(bottom flange)"), not a new body; what it asks is checked when all is read.
        let el = &r.els[e];
        if el.dims.is_empty() && el.ranges.is_empty() && el.tuples.is_empty() && el.coords.is_empty() {
            // "with hemispherical caps on both ends", "with a domed top": ends of a round body.
            if r.shape_of(e) == Some(ShapeHint::Hemisphere) {
                caps(r, e)?;
            }
            continue;
        }
        // "with the base at Z=0": a place on the part, not a body.
        let definite = el.mentions.iter().all(|m| r.mentions[*m].definite);
        if el.dims.is_empty() && el.ranges.is_empty() && el.tuples.is_empty() && definite {
            continue;
        }
        let b = if super::paths::is_radial(r, e) { super::paths::radial(r, e)? } else { build(r, e)? };
        r.built[e] = Some(b);
        r.mark_element(e);
    }
    Ok(())
}

/// "A pyramid with a square base of 40mm sides", "the rectangular base is 60mm (X) by
/// 30mm (Y)" of a wedge, "the right triangle has a 20mm leg along X": a face or edge of
/// the part named as a noun — its lengths are the part's.
pub fn merge_faces(r: &mut Reader<'_>) {
    let Some(t) = r.els.iter().position(|e| e.title) else { return };
    let shape = r.shape_of(t);
    let faces: &[&str] = match shape {
        Some(ShapeHint::Cone | ShapeHint::Pyramid) => &["base"],
        Some(ShapeHint::Wedge) => &["base", "leg"],
        Some(ShapeHint::Ngon(3)) => &["leg", "base"],
        // An angle's legs ("60 by 40 legs").
        Some(ShapeHint::Section(super::super::lexicon::Section::L)) => &["leg"],
        _ => return,
    };
    for f in faces {
        for e in r.elements_named(f) {
            if e == t || r.els[e].noun != *f {
                continue;
            }
            let (dims, ranges, coords, tuples) =
                (r.els[e].dims.clone(), r.els[e].ranges.clone(), r.els[e].coords.clone(), r.els[e].tuples.clone());
            r.els[t].dims.extend(dims);
            r.els[t].ranges.extend(ranges);
            r.els[t].coords.extend(coords);
            r.els[t].tuples.extend(tuples);
            r.els[t].dims.sort_unstable();
            r.mark_element(e);
        }
    }
}

/// The axis a body runs along: a length given along an axis, a span on X or Y, else Z.
fn axis_of(r: &Reader<'_>, e: usize, round: bool) -> Axis {
    let el = &r.els[e];
    if round {
        for &k in &el.dims {
            let d = r.dim(k);
            if matches!(d.role, Role::Length | Role::Height)
                && !r.used_dims[k]
                && let Some(a) = d.axis
            {
                return a;
            }
        }
    }
    if let Some(rg) = el.ranges.iter().map(|k| &r.doc.ranges[*k]).find(|rg| rg.axis != Axis::Z)
        && round
        && !el.ranges.iter().any(|k| r.doc.ranges[*k].axis == Axis::Z)
    {
        return rg.axis;
    }
    // "along the X axis" in its sentence after its noun ("a pipe … along the X axis").
    if round {
        // Only where it is the subject, up to the next thing named.
        let spans: Vec<(usize, usize)> = el
            .mentions
            .iter()
            .map(|mi| &r.mentions[*mi])
            .filter(|m| m.prep.is_none())
            .map(|m| {
                let (_, end) = r.doc.sentence(m.sent);
                let next = r
                    .mentions
                    .iter()
                    .filter(|n| n.sent == m.sent && n.head > m.head && n.elem != e)
                    .map(|n| n.start)
                    .min()
                    .unwrap_or(end);
                (m.head, next)
            })
            .collect();
        for (s, t) in spans {
            for i in s..t.saturating_sub(1) {
                if r.doc.is(i, "along") {
                    let a = r.doc.axis_at(i + 1).or_else(|| r.doc.axis_at(i + 2));
                    if let Some(a) = a {
                        return a;
                    }
                }
            }
        }
    }
    Axis::Z
}

/// The span of a body along its axis and the length that sized it.
fn span(r: &mut Reader<'_>, e: usize, axis: Axis, len: Option<f64>) -> Res<[f64; 2]> {
    if std::env::var_os("SW_SYNTH_DEBUG").is_some() {
        eprintln!("span of {} along {axis:?}: ranges {:?} used {:?}", r.els[e].noun, r.els[e].ranges, r.used_ranges);
    }
    if let Some(s) = r.take_range(e, axis) {
        if let Some(l) = len
            && ((s[1] - s[0]) - l).abs() > 1e-6 * l.max(1.0)
        {
            return Err(Refusal::new(
                r.quote_element(e),
                format!("its length {l} mm and its span {}..{} along {} disagree", s[0], s[1], axis.name()),
            ));
        }
        return Ok(s);
    }
    let l = need(len, "length along its axis", r, e)?;
    // "starting at Z=0", "from X=0".
    if let Some(c) = r.take_coord(e, axis) {
        return Ok([c, c + l]);
    }
    // As thick as the flat part ("lying flat … (Z=0 to Z=3)"): its span.
    if axis == Axis::Z
        && let Some(p) = part_span(r)
        && (p[1] - p[0] - l).abs() < 1e-9
    {
        return Ok(p);
    }
    // "FLANGE Ø80 x 8 AT ONE END" of a hub already made: at its end, not stacked on it.
    let at_end = r.els[e].mentions.iter().any(|mi| {
        let m = &r.mentions[*mi];
        let d = r.doc;
        let mut i = m.head + 1;
        let mut hit = false;
        while i + 1 < d.len() && !d.sym(i, ',') && !d.sym(i, '.') && !d.sym(i, ';') {
            if d.is(i, "at") && matches!(d.word(i + 1), Some("one" | "either" | "the")) && d.is(i + 2, "end") {
                hit = true;
                d.mark_range(i, i + 3);
            }
            i += 1;
        }
        hit
    });
    if at_end
        && let Some(start) = (0..e)
            .filter_map(|p| r.built[p].as_ref().filter(|b| b.axis == axis && !b.cut).map(|b| b.span[0]))
            .reduce(f64::min)
    {
        return Ok([start, start + l]);
    }
    // Stacked on the body before it along the same axis, when one is there and the
    // words say on top (or nothing says otherwise); the first body from 0 (or centred).
    let prev_el = (0..e).rev().find(|p| r.built[*p].as_ref().is_some_and(|b| b.axis == axis && !b.cut));
    let prev = prev_el.and_then(|p| r.built[p].as_ref().map(|b| b.span));
    // "A plate with four posts": a body the part is said to have stands on the one before.
    let with = r.els[e].mentions.first().is_some_and(|m| r.mentions[*m].prep.as_deref() == Some("with"));
    let on_top = with || r.says(e, "top") || r.says(e, "topped") || r.says(e, "above") || r.says(e, "on");
    // "a body … below the flange": under the body before it.
    let below = ["below", "under", "beneath", "underneath"].iter().any(|w| r.says(e, w));
    match prev {
        Some(p) if below && !r.says(e, "top") => Ok([p[0] - l, p[0]]),
        Some(p) if on_top => {
            mark_on_top(r, e);
            Ok([p[1], p[1] + l])
        }
        _ if r.centered && prev.is_none() => Ok([-l / 2.0, l / 2.0]),
        // The same noun again ("a block 80 x 40 x 20 … one block"), or a part whose length
        // is said to be overall ("flange 24 dia x 3, overall length 20"): from the same end.
        Some(_)
            if prev_el.is_some_and(|p| r.els[p].noun == r.els[e].noun)
                || (0..r.doc.len()).any(|i| matches!(r.doc.word(i), Some("overall" | "total"))) =>
        {
            Ok([0.0, l])
        }
        // A second body on the same axis that no word places ("flange 40 dia x 5, body 25
        // dia x 20 long"): stacked end to end or overlapping are different parts, and the
        // words do not say which.
        Some(_) => Err(Refusal::new(
            r.quote_element(e),
            format!(
                "nothing says where the {} sits along the {} axis of the body before it (on top of it, below it, at one end)",
                r.els[e].noun,
                axis.name()
            ),
        )),
        None => Ok([0.0, l]),
    }
}

/// Marks every occurrence of these words read.
pub fn mark_words(r: &Reader<'_>, words: &[&str]) {
    for i in 0..r.doc.len() {
        if r.doc.word(i).is_some_and(|w| words.contains(&w)) {
            r.doc.mark(i);
        }
    }
}

/// "on top (of the shaft)", "topped by", "on the top face (of the base)": read.
pub fn mark_on_top(r: &Reader<'_>, e: usize) {
    let d = r.doc;
    for (a, b) in r.sentences_of(e) {
        for i in a..b {
            if d.is(i, "top") || d.is(i, "topped") {
                d.mark(i);
                if d.is(i + 1, "face") {
                    d.mark(i + 1);
                }
            }
        }
    }
}

/// The positions of a body's copies in the plane normal to its axis.
fn positions(r: &mut Reader<'_>, e: usize, axis: Axis) -> Res<Vec<[f64; 2]>> {
    let count = place::count_of(r, e);
    let pts = place::points(r, e, axis)?;
    if !pts.is_empty() {
        return Ok(pts);
    }
    if let Some(g) = place::grid(r, e) {
        return Ok(g);
    }
    if count > 1 {
        if let Some(c) = place::circle(r, e, count) {
            return Ok(c);
        }
        if let Some(p) = place::rect_pattern(r, e) {
            return Ok(p);
        }
        if let Some(row) = place::row(r, e, count, Axis::X, axis) {
            return Ok(row);
        }
    }
    Ok(vec![[0.0, 0.0]])
}

/// Rectangular sizes per part axis from tagged lengths, a list and roles.
fn box_sizes(r: &mut Reader<'_>, e: usize) -> [Option<f64>; 3] {
    let mut s: [Option<f64>; 3] = [None; 3];
    let dims = r.free_dims(e);
    let treat = |q: &super::super::doc::Dim| q.has("hole") || q.has("bore") || q.has("pitch") || q.has("circle");
    // Tagged lengths first.
    for &k in &dims {
        let d = r.dim(k).clone();
        if d.paren
            || treat(&d)
            || matches!(
                d.role,
                Role::Fillet | Role::Chamfer | Role::Inset | Role::Spacing | Role::Diameter | Role::Radius
            )
        {
            continue;
        }
        if let Some(a) = d.axis
            && s[a.index()].is_none()
        {
            s[a.index()] = Some(d.mm);
            r.used_dims[k] = true;
        }
    }
    // A list fills X, Y, Z in order of the free axes; a list of two ("flat bar 50 x 10,
    // length 300") fills what the lengths named by their roles leave.
    let list: Vec<usize> =
        dims.iter().copied().filter(|k| !r.used_dims[*k] && r.dim(*k).list.is_some() && !r.dim(*k).paren).collect();
    let fill_list = |r: &mut Reader<'_>, s: &mut [Option<f64>; 3]| {
        for &k in &list {
            if let Some(i) = (0..3).find(|i| s[*i].is_none()) {
                s[i] = Some(r.dim(k).mm);
                r.used_dims[k] = true;
            }
        }
    };
    let roles_named = dims.iter().any(|k| {
        !r.used_dims[*k]
            && r.dim(*k).list.is_none()
            && matches!(r.dim(*k).role, Role::Length | Role::Width | Role::Height | Role::Thickness | Role::Depth)
    });
    // "square bar 1-1/2\" x 6\" long", "40 sq x 200 lg": a square section's side and its
    // length, the length said by its role.
    let lengths: Vec<usize> = list.iter().copied().filter(|k| r.dim(*k).role == Role::Length).collect();
    if r.els[e].has_mod("square") && list.len() == 2 && lengths.len() == 1 && s.iter().all(Option::is_none) {
        let side = list.iter().copied().find(|k| *k != lengths[0]).map(|k| r.dim(k).mm);
        s = [Some(r.dim(lengths[0]).mm), side, side];
        for k in &list {
            r.used_dims[*k] = true;
        }
    }
    if s.iter().all(Option::is_none) && (list.len() >= 3 || (list.len() == 2 && !roles_named)) {
        fill_list(r, &mut s);
    }
    let role = |roles: &[Role], axis: usize, r: &mut Reader<'_>, s: &mut [Option<f64>; 3]| {
        if s[axis].is_none()
            && let Some(k) = r.find(e, roles, &[], &["hole", "bore", "pitch", "circle", "wall", "total", "overall"])
            && r.dim(k).axis.is_none()
        {
            s[axis] = Some(r.dim(k).mm);
            r.used_dims[k] = true;
        }
    };
    role(&[Role::Length], 0, r, &mut s);
    role(&[Role::Width, Role::Depth], 1, r, &mut s);
    role(&[Role::Height], 2, r, &mut s);
    // "a 20 mm square bar 100 long": a bare size of a square thing is its side.
    let square_bare = if r.els[e].has_mod("square") && r.find(e, &[Role::Side], &[], &[]).is_none() {
        let bare: Vec<usize> =
            r.free_dims(e).into_iter().filter(|k| r.dim(*k).role == Role::Bare && r.dim(*k).list.is_none()).collect();
        (bare.len() == 1 && s.iter().filter(|x| x.is_none()).count() == 2).then(|| bare[0])
    } else {
        None
    };
    // A side fills the square ("40mm sides", "80mm on each side", "16 mm square and 300
    // long": the two axes the length leaves).
    if let Some(k) = r.find(e, &[Role::Side], &[], &[]).or(square_bare) {
        let v = r.dim(k).mm;
        r.used_dims[k] = true;
        let cube = r.els[e].noun == "cube";
        let n = if cube { 3 } else { 2 };
        let mut filled = 0;
        for x in s.iter_mut() {
            if filled < n && x.is_none() {
                *x = Some(v);
                filled += 1;
            }
        }
    }
    if list.len() == 2 && roles_named {
        fill_list(r, &mut s);
    }
    // A thickness fills Z, else the one free horizontal axis.
    if let Some(k) = r.find(e, &[Role::Thickness], &[], &["wall"]) {
        let v = r.dim(k).mm;
        if let Some(i) = [2, 1, 0].into_iter().find(|i| s[*i].is_none()) {
            s[i] = Some(v);
            r.used_dims[k] = true;
        }
    }
    // "a 35mm cube": one bare length.
    if s.iter().all(Option::is_none)
        && r.els[e].noun == "cube"
        && let Some(k) = r.find(e, &[Role::Bare, Role::Length, Role::Width, Role::Height], &[], &[])
    {
        let v = r.dim(k).mm;
        r.used_dims[k] = true;
        s = [Some(v); 3];
    }
    // "a 40 mm cube, 40 mm tall": a cube's one size, said again by a role.
    if r.els[e].noun == "cube"
        && let Some(v) = s.iter().flatten().copied().next()
        && s.iter().flatten().all(|x| (x - v).abs() <= 1e-9 * v.max(1.0))
    {
        for k in r.free_dims(e) {
            let x = r.dim(k);
            if matches!(x.role, Role::Bare | Role::Side) && (x.mm - v).abs() <= 1e-9 * v.max(1.0) {
                r.used_dims[k] = true;
            }
        }
        s = [Some(v); 3];
    }
    s
}

fn build(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let shape = r.shape_of(e).unwrap_or(ShapeHint::Rect);
    match shape {
        ShapeHint::Round
        | ShapeHint::Ring
        | ShapeHint::Ngon(_)
        | ShapeHint::Star
        | ShapeHint::Ellipse
        | ShapeHint::Stadium => prism(r, e, shape),
        ShapeHint::Rect => rect(r, e),
        ShapeHint::Cone => cone(r, e),
        ShapeHint::Sphere | ShapeHint::Hemisphere => sphere(r, e, shape == ShapeHint::Hemisphere),
        ShapeHint::Torus => torus(r, e),
        ShapeHint::Capsule => capsule(r, e),
        ShapeHint::Pyramid => pyramid(r, e),
        // "a wedge with legs of 50 and 20": a right triangle extruded.
        ShapeHint::Wedge if r.els[e].dims.iter().any(|k| r.dim(*k).has("leg")) => right_triangle(r, e),
        ShapeHint::Wedge => wedge(r, e),
        ShapeHint::Section(_) => Err(Refusal::new(r.quote_element(e), "a named cross-section it could not size")),
    }
}

const NOT_OUTER: &[&str] =
    &["inner", "bore", "hole", "pitch", "circle", "tip", "root", "counterbore", "bolt", "inscribed"];

/// A profile extruded along an axis: cylinders, rings, polygons, stars, ellipses, stadiums.
fn prism(r: &mut Reader<'_>, e: usize, shape: ShapeHint) -> Res<Built> {
    let round =
        matches!(shape, ShapeHint::Round | ShapeHint::Ring | ShapeHint::Ngon(_) | ShapeHint::Star | ShapeHint::Ellipse);
    let axis = axis_of(r, e, round);
    let (profile, od, id) = match shape {
        ShapeHint::Round | ShapeHint::Ring => {
            // "42.4 x 2.6 tube": a tube's size as outside diameter by wall.
            if shape == ShapeHint::Ring
                && r.find(e, &[Role::Diameter, Role::Radius], &[], &[]).is_none()
                && let [a, b] = r
                    .free_dims(e)
                    .into_iter()
                    .filter(|k| r.dim(*k).list.is_some() && r.dim(*k).role == Role::Bare)
                    .collect::<Vec<_>>()
                    .as_slice()
                && r.dim(*b).mm < r.dim(*a).mm / 2.0
            {
                let (od, w) = (r.dim(*a).mm, r.dim(*b).mm);
                r.used_dims[*a] = true;
                r.used_dims[*b] = true;
                r.known.push(w);
                let len = r.take(e, ALONG, &[], &["wall"]);
                let span = span(r, e, axis, len)?;
                return Ok(add(
                    r,
                    e,
                    Profile::Annulus { od, id: od - 2.0 * w },
                    axis,
                    span,
                    Some(od),
                    Some(od - 2.0 * w),
                    None,
                ));
            }
            // "a 50 mm round bar, 80 long": a bare size before it, with its length named.
            if r.find(e, &[Role::Diameter, Role::Radius], &[], &[]).is_none()
                && r.find(e, ALONG, &[], &[]).is_some()
                && let [k] = r
                    .free_dims(e)
                    .into_iter()
                    .filter(|k| r.dim(*k).role == Role::Bare && r.dim(*k).list.is_none() && !r.dim(*k).paren)
                    .collect::<Vec<_>>()
                    .as_slice()
            {
                let k = *k;
                r.used_dims[k] = true;
                let od = r.dim(k).mm;
                let len = r.take(e, ALONG, &[], &["wall"]);
                let id = r.take(e, &[Role::Thickness], &["wall"], &[]).map(|w| od - 2.0 * w);
                let span = span(r, e, axis, len)?;
                let profile = match id {
                    Some(i) if i > 0.0 && shape == ShapeHint::Ring => Profile::Annulus { od, id: i },
                    _ => Profile::Circle { d: od },
                };
                let id = matches!(profile, Profile::Annulus { .. }).then_some(id).flatten();
                return Ok(add(r, e, profile, axis, span, Some(od), id, None));
            }
            let od = r.take_diameter(e, &["outer"], &[]).or_else(|| r.take_diameter(e, &[], NOT_OUTER));
            // "of the same diameter", "has the same dimensions": as the round body before it.
            let same = if od.is_none() && (r.says(e, "same") || r.says(e, "identical")) {
                (0..e)
                    .rev()
                    .find_map(|p| r.built[p].as_ref().filter(|b| !b.cut && b.od.is_some()).map(|b| (b.od, b.id)))
            } else {
                None
            };
            let od = od.or(same.and_then(|s| s.0));
            let od = need(od, "diameter", r, e)?;
            let mut id = r.take_diameter(e, &["inner"], &[]).or_else(|| r.take_diameter(e, &["bore"], &["pitch"]));
            if id.is_none() {
                id = same.and_then(|s| s.1);
            }
            if id.is_none() && shape == ShapeHint::Ring {
                id = r.take_diameter(e, &["hole"], &["pitch", "bolt"]);
                if id.is_none()
                    && let Some(w) = r.take(e, &[Role::Thickness], &["wall"], &[])
                {
                    id = Some(od - 2.0 * w);
                }
            }
            let half = r.doc.toks.iter().any(|t| matches!(t.word(), Some("semicircular" | "half-pipe" | "half")));
            match id {
                Some(i) if i > 0.0 && i < od && half => return half_pipe(r, e, od, i),
                Some(i) if i > 0.0 && i < od => (Profile::Annulus { od, id: i }, od, Some(i)),
                Some(i) => {
                    // Quote the sizes that disagree with the thing they size.
                    let last = r.els[e].dims.iter().map(|k| r.dim(*k).tok).max();
                    let first = r.els[e].mentions.first().map(|m| r.mentions[*m].start);
                    let phrase = match (first, last) {
                        (Some(a), Some(b)) if b >= a && b < a + 12 => r.doc.quote(a, b + 1),
                        _ => r.quote_element(e),
                    };
                    return Err(Refusal::new(phrase, format!("its inner diameter {i} mm does not fit inside {od} mm")));
                }
                None => (Profile::Circle { d: od }, od, None),
            }
        }
        ShapeHint::Ngon(3)
            if r.doc.toks.iter().any(|t| matches!(t.word(), Some("right" | "right-angle" | "right-angled"))) =>
        {
            return right_triangle(r, e);
        }
        ShapeHint::Ngon(n) => {
            let flats = r.find(e, &[Role::Bare, Role::Diameter, Role::Width], &["across", "flat"], &[]).is_some()
                && r.find(e, &[Role::Bare, Role::Diameter], &["across", "corner"], &[]).is_none()
                && r.find(e, &[Role::Diameter, Role::Radius], &["circumscribed"], &[]).is_none();
            let d = r
                .take_diameter(e, &["circumscribed"], &[])
                .or_else(|| r.take(e, &[Role::Bare, Role::Diameter], &["across", "corner"], &[]))
                .or_else(|| {
                    r.take(e, &[Role::Bare, Role::Diameter, Role::Width], &["across", "flat"], &[])
                        .map(|af| af / (std::f64::consts::PI / n as f64).cos())
                })
                .or_else(|| r.take_diameter(e, &[], NOT_OUTER))
                // "an equilateral triangle of 40 mm sides": a regular polygon by its side.
                .or_else(|| r.take(e, &[Role::Side], &[], &[]).map(|s| s / (std::f64::consts::PI / n as f64).sin()));
            let d = need(d, "circumscribed diameter", r, e)?;
            mark_words(r, &["triangle", "equilateral", "hexagon", "octagon", "regular", "polygon"]);
            // "across the corners it is what a hexagon gives": the polygon's other size, said.
            for i in 0..r.doc.len().saturating_sub(2) {
                let w = if r.doc.is(i + 1, "the") { i + 2 } else { i + 1 };
                if r.doc.is(i, "across") && matches!(r.doc.word(w), Some("corner" | "flat")) {
                    r.doc.mark_range(i, w + 1);
                }
            }
            // A triangle stands on its base (a corner on +v); other polygons have a corner on
            // +u, but one given across its flats lies on a flat (an octagon's flats on both axes).
            let phase = if n == 3 {
                90.0
            } else if flats && n % 4 == 0 {
                180.0 / n as f64
            } else {
                0.0
            };
            (Profile::Ngon { n, d, phase }, d, None)
        }
        ShapeHint::Star => {
            // A gear's tip and root circles; a star's outer and inner diameters.
            let tip = r.take_diameter(e, &["tip"], &[]).or_else(|| r.take_diameter(e, &["outer"], &[]));
            let root = r.take_diameter(e, &["root"], &[]).or_else(|| r.take_diameter(e, &["inner"], &[]));
            let (tip, root) = (need(tip, "tip diameter", r, e)?, need(root, "root diameter", r, e)?);
            let teeth = r.els[e]
                .teeth
                .or(r.els[e].count)
                .ok_or_else(|| Refusal::new(r.quote_element(e), "no number of teeth is given"))?;
            if !(3..=400).contains(&teeth) || root >= tip {
                return Err(Refusal::new(
                    r.quote_element(e),
                    format!("{teeth} teeth between {root} and {tip} mm is not a gear"),
                ));
            }
            (Profile::Star { n: teeth as usize, tip: tip / 2.0, root: root / 2.0 }, tip, None)
        }
        ShapeHint::Ellipse => {
            let a = r.take(e, &[Role::Bare, Role::Diameter, Role::Length], &["major"], &[]);
            let b = r.take(e, &[Role::Bare, Role::Diameter, Role::Width], &["minor"], &[]);
            let (a, b) = (need(a, "major axis", r, e)?, need(b, "minor axis", r, e)?);
            (Profile::Ellipse { a: a.max(b), b: a.min(b) }, a.max(b), None)
        }
        _ => {
            let s = box_sizes(r, e);
            let (l, w) = (need(s[0], "length", r, e)?, need(s[1], "width", r, e)?);
            if w >= l {
                return Err(Refusal::new(r.quote_element(e), "a stadium's width must be less than its length"));
            }
            let h = s[2];
            let span = span(r, e, Axis::Z, h)?;
            // "The shape is a rectangle with semicircular ends along the X axis": a stadium.
            mark_words(r, &["rectangle", "semicircular", "end", "rounded", "round"]);
            return Ok(add(r, e, Profile::Stadium { l, w }, Axis::Z, span, None, None, None));
        }
    };
    let has_range = r.els[e].ranges.iter().any(|k| !r.used_ranges[*k] && r.doc.ranges[*k].axis == axis);
    let mut len = None;
    // "Ø16 x 100 shaft": the length written with its diameter comes first.
    if !has_range && matches!(shape, ShapeHint::Round | ShapeHint::Ring) {
        let d = r.doc;
        let paired = r.free_dims(e).into_iter().find(|k| {
            let t = d.dims[*k].tok;
            d.dims[*k].role == Role::Bare
                && d.dims[*k].list.is_none()
                && t >= 2
                && (d.sym(t - 1, 'x') || d.is(t - 1, "by"))
                && d.dims.iter().any(|x| x.role == Role::Diameter && (x.tok + 2 == t || x.tok + 3 == t))
        });
        if let Some(k) = paired {
            r.used_dims[k] = true;
            len = Some(r.dim(k).mm);
        }
    }
    if !has_range && len.is_none() {
        len = r.find(e, ALONG, &[], &["wall", "counterbore", "face", "total", "overall"]).map(|k| {
            r.used_dims[k] = true;
            r.dim(k).mm
        });
        if len.is_none() && shape == ShapeHint::Star {
            len = r.take(e, &[Role::Width], &["face"], &[]);
        }
        // A collar's or pulley's width (its face) is its length along its axis.
        if len.is_none() && matches!(shape, ShapeHint::Round | ShapeHint::Ring) {
            len = r.take(e, &[Role::Width], &[], &["wall"]).or_else(|| r.take(e, &[Role::Bare], &["face"], &[]));
        }
        // "a Ø40 hub projecting 10 on one side": as long as the body before it, and that much more.
        if len.is_none()
            && (r.says(e, "projecting") || r.says(e, "protruding") || r.says(e, "proud"))
            && let Some(prev) =
                (0..e).rev().find_map(|p| r.built[p].as_ref().filter(|b| !b.cut && b.axis == axis).map(|b| b.span))
            && let Some(k) = r.find(e, &[Role::Bare, Role::Length], &[], &[])
        {
            r.used_dims[k] = true;
            let more = r.dim(k).mm;
            mark_words(r, &["projecting", "protruding", "proud", "one", "side"]);
            let span = [prev[0], prev[1] + more];
            r.known.push(more);
            return Ok(add(r, e, profile, axis, span, Some(od), id, None));
        }
        // "HUB Ø50 …, 30 OVERALL": a body with no length of its own spans the part's overall length.
        if len.is_none() {
            let overall = (0..r.doc.dims.len()).find(|k| {
                !r.used_dims[*k]
                    && (r.doc.dims[*k].has("overall") || r.doc.dims[*k].has("total"))
                    && r.doc.dims[*k].role != Role::Diameter
            });
            if let Some(k) = overall {
                r.used_dims[k] = true;
                let l = r.doc.dims[k].mm;
                // It spans the part: from where the bodies along its axis begin.
                let from = (0..e)
                    .filter_map(|p| r.built[p].as_ref().filter(|b| !b.cut && b.axis == axis).map(|b| b.span[0]))
                    .fold(f64::INFINITY, f64::min);
                let from = if from.is_finite() {
                    from
                } else if r.centered {
                    -l / 2.0
                } else {
                    0.0
                };
                return Ok(add(r, e, profile, axis, [from, from + l], Some(od), id, None));
            }
        }
        // "Ø20 x 50 pin", "Ø100 x 6 disc": the one length written after its diameter.
        if len.is_none() {
            let bare: Vec<usize> = r
                .free_dims(e)
                .into_iter()
                .filter(|k| {
                    let d = r.dim(*k);
                    d.role == Role::Bare
                        && !d.paren
                        && d.restates.is_none()
                        && !NOT_OUTER.iter().any(|q| d.has(q))
                        && !d.has("from-center")
                        && !d.has("pattern")
                })
                .collect();
            if let [k] = bare.as_slice() {
                r.used_dims[*k] = true;
                len = Some(r.dim(*k).mm);
            }
        }
        // A flat part's thickness ("lying flat … (Z=0 to Z=3)") for a disc on it.
        if len.is_none()
            && axis == Axis::Z
            && let Some(p) = part_span(r)
        {
            len = Some(p[1] - p[0]);
        }
    }
    let span = span(r, e, axis, len)?;
    Ok(add(r, e, profile, axis, span, Some(od), id, None))
}

/// Adds the copies of a prism and records what it became.
#[allow(clippy::too_many_arguments)]
pub fn add(
    r: &mut Reader<'_>,
    e: usize,
    profile: Profile,
    axis: Axis,
    span: [f64; 2],
    od: Option<f64>,
    id: Option<f64>,
    size: Option<[f64; 2]>,
) -> Built {
    let mut at = positions(r, e, axis).unwrap_or_else(|_| vec![[0.0, 0.0]]);
    // "a boss lying along Y, its axis 30 above the base underside": a body across the part
    // stands with its axis that high above the part's bottom.
    if axis != Axis::Z
        && at.len() == 1
        && let Some(k) = r.find(e, &[Role::Inset], &["from-bottom"], &[])
    {
        let bottom = if r.model.adds.is_empty() { 0.0 } else { r.model.bounds()[0][2] };
        let z = if axis == Axis::X { 1 } else { 0 };
        at[0][z] = bottom + r.dim(k).mm;
        r.used_dims[k] = true;
        let dm = r.doc.dims[k].clone();
        r.doc.mark_range(dm.phrase.0, dm.phrase.1 + 3);
    }
    let mut bodies = Vec::new();
    for p in &at {
        bodies.push(r.model.adds.len());
        r.model.adds.push(Body::new(
            r.els[e].noun.clone(),
            Shape::Prism { profile: profile.clone(), axis, at: *p, rot: 0.0, from: span[0], to: span[1] },
        ));
    }
    Built { axis, span, at, od, id, size, bodies, cut: false }
}

fn rect(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let mut s = box_sizes(r, e);
    // Per axis: a span given as coordinates sizes and places it; else a centre coordinate.
    let mut iv: [Option<[f64; 2]>; 3] = [None; 3];
    for a in Axis::ALL {
        if let Some(sp) = r.take_range(e, a) {
            let l = sp[1] - sp[0];
            if let Some(v) = s[a.index()]
                && (v - l).abs() > 1e-6 * l.max(1.0)
            {
                return Err(Refusal::new(
                    r.quote_element(e),
                    format!("its size {v} mm and its span {}..{} along {} disagree", sp[0], sp[1], a.name()),
                ));
            }
            s[a.index()] = Some(l);
            iv[a.index()] = Some(sp);
        }
    }
    // A size missing in X or Y: the one the body before it has ("25mm deep (Y, centered)"
    // on the plates of a Z-bracket, given once).
    for a in [0usize, 1] {
        if s[a].is_none()
            && let Some(prev) = (0..e).rev().find_map(|p| r.built[p].as_ref().and_then(|b| b.size))
        {
            s[a] = Some(prev[a]);
        }
    }
    if s[2].is_none() && iv[2].is_none() {
        s[2] = part_span(r).map(|p| {
            iv[2] = Some(p);
            p[1] - p[0]
        });
    }
    let (x, y, z) = (need(s[0], "length", r, e)?, need(s[1], "width", r, e)?, need(s[2], "height or thickness", r, e)?);
    // "rising from the Y=0 edge of the base": flush with that edge, on the base.
    if let Some(b) = on_edge(r, e, [x, y, z])? {
        return Ok(b);
    }
    // A centre coordinate, when it is the only one on its axis (several are copies).
    let one = |r: &Reader<'_>, a: Axis| r.els[e].coords.iter().filter(|k| r.doc.coords[**k].axis == a).count() == 1;
    let cx = if one(r, Axis::X) { r.take_coord(e, Axis::X) } else { None };
    let cy = if one(r, Axis::Y) { r.take_coord(e, Axis::Y) } else { None };
    let zspan = match iv[2] {
        Some(sp) => sp,
        None => match part_span(r) {
            // As thick as the flat part: its span.
            Some(p) if (p[1] - p[0] - z).abs() < 1e-9 => p,
            _ => span(r, e, Axis::Z, Some(z))?,
        },
    };
    let centre = |a: usize, c: Option<f64>| iv[a].map_or(c.unwrap_or(0.0), |sp| (sp[0] + sp[1]) / 2.0);
    let (mx, my) = (centre(0, cx), centre(1, cy));
    let mut b = add(r, e, Profile::Rect { w: x, h: y }, Axis::Z, zspan, None, None, Some([x, y]));
    if mx != 0.0 || my != 0.0 {
        for (p, bi) in b.at.iter_mut().zip(&b.bodies) {
            p[0] += mx;
            p[1] += my;
            if let Some(Shape::Prism { at, .. }) = r.model.adds.get_mut(*bi).map(|b| &mut b.shape) {
                *at = *p;
            }
        }
    }
    Ok(b)
}

/// The Z span the whole part is given ("lying flat on the XY plane (Z=0 to Z=3)").
pub fn part_span(r: &mut Reader<'_>) -> Option<[f64; 2]> {
    let k = (0..r.doc.ranges.len())
        .find(|k| r.doc.ranges[*k].axis == Axis::Z && super::super::mention::is_part_range(r.doc, *k))?;
    r.used_ranges[k] = true;
    let rg = &r.doc.ranges[k];
    r.doc.mark_range(rg.toks.0, rg.toks.1);
    Some([rg.a.min(rg.b), rg.a.max(rg.b)])
}

fn cone(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let base = r
        .take_diameter(e, &["base"], &[])
        .or_else(|| r.take_diameter(e, &["bottom"], &[]))
        .or_else(|| r.take_diameter(e, &[], &["top", "tip"]));
    // "a 30mm base": a bare length named for the base.
    let base = base.or_else(|| r.take(e, &[Role::Bare], &["base"], &[]));
    // "apex down, 40 across the top": the wide end is the top (the same solid turned over).
    let down = (0..r.doc.len()).any(|i| {
        matches!(r.doc.word(i), Some("apex" | "point" | "tip" | "vertex"))
            && matches!(r.doc.word(i + 1), Some("down" | "downward" | "downwards"))
    });
    let base = if base.is_none() && down { r.take_diameter(e, &["top"], &[]) } else { base };
    let base = need(base, "base diameter", r, e)?;
    let top = r.take_diameter(e, &["top"], &[]).unwrap_or(0.0);
    let h = need(r.take(e, &[Role::Height, Role::Length, Role::Depth], &[], &[]), "height", r, e)?;
    for i in 0..r.doc.len() {
        if matches!(r.doc.word(i), Some("apex" | "point" | "tip" | "vertex"))
            && matches!(r.doc.word(i + 1), Some("down" | "downward" | "downwards" | "up" | "upward" | "upwards"))
        {
            r.doc.mark_range(i, i + 2);
        }
    }
    let span = span(r, e, Axis::Z, Some(h))?;
    let at = positions(r, e, Axis::Z)?;
    let mut bodies = Vec::new();
    for p in &at {
        bodies.push(r.model.adds.len());
        r.model.adds.push(Body::new(
            r.els[e].noun.clone(),
            Shape::Cone { axis: Axis::Z, at: *p, from: span[0], to: span[1], d_from: base, d_to: top },
        ));
    }
    Ok(Built { axis: Axis::Z, span, at, od: Some(base), id: None, size: None, bodies, cut: false })
}

fn sphere(r: &mut Reader<'_>, e: usize, half: bool) -> Res<Built> {
    // "a 45 mm ball": a bare size before it is its diameter.
    let dia = r.take_diameter(e, &[], &[]).or_else(|| {
        let bare: Vec<usize> = r.free_dims(e).into_iter().filter(|k| r.dim(*k).role == Role::Bare).collect();
        let [k] = bare.as_slice() else { return None };
        r.used_dims[*k] = true;
        Some(r.dim(*k).mm)
    });
    let dia = need(dia, "diameter or radius", r, e)?;
    // "a hollow sphere, 50 OD with a 4 mm wall": the ball less a ball inside it.
    let wall = r.take(e, &[Role::Thickness], &["wall"], &[]);
    if let Some(w) = wall
        && !half
    {
        if 2.0 * w >= dia {
            return Err(Refusal::new(r.quote_element(e), "its wall does not fit inside it"));
        }
        let c = [0.0, 0.0, if r.centered { 0.0 } else { dia / 2.0 }];
        let b = r.model.adds.len();
        r.model.adds.push(Body::new(r.els[e].noun.clone(), Shape::Sphere { c, d: dia }));
        r.model.cuts.push(Body::new("hollow", Shape::Sphere { c, d: dia - 2.0 * w }));
        mark_words(r, &["hollow"]);
        r.known.push(dia - 2.0 * w);
        return Ok(Built {
            axis: Axis::Z,
            span: [c[2] - dia / 2.0, c[2] + dia / 2.0],
            at: vec![[0.0, 0.0]],
            od: Some(dia),
            id: Some(dia - 2.0 * w),
            size: None,
            bodies: vec![b],
            cut: false,
        });
    }
    // On top of the body before it ("topped by a hemisphere … centered on the top face").
    let prev = (0..e).rev().find_map(|p| r.built[p].as_ref().filter(|b| b.axis == Axis::Z && !b.cut).map(|b| b.span));
    let z0 = match (prev, half) {
        (Some(p), true) => p[1],
        (_, true) => 0.0,
        _ if r.centered => 0.0,
        _ => dia / 2.0,
    };
    if half && prev.is_some() {
        mark_on_top(r, e);
    }
    // A ball with another body: resting on it touches at one point, sunk into it is not said.
    if !half && prev.is_some() {
        return Err(Refusal::new(r.quote_element(e), "where a sphere's centre is, beside another body, is not read"));
    }
    // "upper hemisphere", "flat face on the XY plane, dome rising in +Z".
    let d = r.doc;
    let mut up = true;
    for (a, b) in r.sentences_of(e) {
        for i in a..b {
            match d.word(i) {
                Some("upper") => d.mark(i),
                Some("lower") | Some("inverted") => {
                    up = false;
                    d.mark(i);
                }
                Some("dome")
                    if d.word(i + 1)
                        .is_some_and(|w| matches!(w, "rising" | "pointing" | "facing" | "up" | "upward")) =>
                {
                    d.mark(i)
                }
                Some("flat") if d.is(i + 1, "face") || d.is(i + 1, "side") => {
                    d.mark_range(i, i + 2);
                    if matches!(d.word(i + 2), Some("down" | "downward" | "up" | "upward")) {
                        d.mark(i + 2);
                    }
                }
                _ => {}
            }
        }
    }
    let c = [0.0, 0.0, z0];
    let shape = if half { Shape::Hemisphere { c, d: dia, axis: Axis::Z, up } } else { Shape::Sphere { c, d: dia } };
    let b = r.model.adds.len();
    r.model.adds.push(Body::new(r.els[e].noun.clone(), shape));
    let span = if half && up {
        [z0, z0 + dia / 2.0]
    } else if half {
        [z0 - dia / 2.0, z0]
    } else {
        [z0 - dia / 2.0, z0 + dia / 2.0]
    };
    Ok(Built {
        axis: Axis::Z,
        span,
        at: vec![[0.0, 0.0]],
        od: Some(dia),
        id: None,
        size: None,
        bodies: vec![b],
        cut: false,
    })
}

fn torus(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    // "major radius 40, minor radius 10": the ring's and the tube's.
    let by_radii = match (
        r.find(e, &[Role::Diameter, Role::Radius], &["major"], &[]),
        r.find(e, &[Role::Diameter, Role::Radius], &["minor"], &[]),
    ) {
        (Some(_), Some(_)) => Some((r.take_diameter(e, &["major"], &[]), r.take_diameter(e, &["minor"], &[]))),
        _ => None,
    };
    let od = if by_radii.is_none() { r.take_diameter(e, &["outer"], &[]) } else { None };
    let id = if by_radii.is_none() { r.take_diameter(e, &["inner"], &[]) } else { None };
    let (major, minor) = match (by_radii, od, id) {
        (Some((Some(a), Some(b))), ..) => (a, b),
        (_, Some(o), Some(i)) if i < o => ((o + i) / 2.0, (o - i) / 2.0),
        _ => {
            let tube = r.take_diameter(e, &["tube"], &[]).or_else(|| r.take(e, &[Role::Thickness], &[], &[]));
            let ring = r.take_diameter(e, &[], &[]);
            (need(ring, "ring diameter", r, e)?, need(tube, "tube diameter", r, e)?)
        }
    };
    if minor >= major {
        return Err(Refusal::new(r.quote_element(e), "its tube is wider than its ring"));
    }
    let z = if r.centered { 0.0 } else { minor / 2.0 };
    let b = r.model.adds.len();
    r.model.adds.push(Body::new(r.els[e].noun.clone(), Shape::Torus { c: [0.0, 0.0, z], axis: Axis::Z, major, minor }));
    Ok(Built {
        axis: Axis::Z,
        span: [z - minor / 2.0, z + minor / 2.0],
        at: vec![[0.0, 0.0]],
        od: Some(major + minor),
        id: Some(major - minor),
        size: None,
        bodies: vec![b],
        cut: false,
    })
}

fn capsule(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let d = need(r.take_diameter(e, &[], &[]), "diameter", r, e)?;
    let l = need(r.take(e, ALONG, &[], &[]), "length", r, e)?;
    // "with hemispherical caps on both ends".
    for c in r.elements_named("cap") {
        r.mark_element(c);
    }
    mark_words(r, &["end", "hemispherical", "domed", "rounded"]);
    cylinder_with_caps(r, e, d, l)
}

/// A cylinder of length `l` with a hemisphere on each end (the caps outside its length).
pub fn cylinder_with_caps(r: &mut Reader<'_>, e: usize, d: f64, l: f64) -> Res<Built> {
    let (z0, z1) = if r.centered { (-l / 2.0, l / 2.0) } else { (d / 2.0, d / 2.0 + l) };
    let mut bodies = vec![r.model.adds.len()];
    r.model.adds.push(Body::new(
        "cylinder",
        Shape::Prism { profile: Profile::Circle { d }, axis: Axis::Z, at: [0.0, 0.0], rot: 0.0, from: z0, to: z1 },
    ));
    bodies.push(r.model.adds.len());
    r.model.adds.push(Body::new("cap", Shape::Hemisphere { c: [0.0, 0.0, z1], d, axis: Axis::Z, up: true }));
    bodies.push(r.model.adds.len());
    r.model.adds.push(Body::new("cap", Shape::Hemisphere { c: [0.0, 0.0, z0], d, axis: Axis::Z, up: false }));
    let _ = e;
    Ok(Built {
        axis: Axis::Z,
        span: [z0 - d / 2.0, z1 + d / 2.0],
        at: vec![[0.0, 0.0]],
        od: Some(d),
        id: None,
        size: None,
        bodies,
        cut: false,
    })
}

fn pyramid(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    // A rectangular frustum: two X-by-Y pairs, the base's and the top's; or two squares
    // ("60 square at the bottom and 30 square at the top"), or two lists ("60 x 40 base,
    // 30 x 20 top"), the bottom's first unless the words say which is the top.
    let pairs: Vec<usize> =
        r.free_dims(e).into_iter().filter(|k| matches!(r.dim(*k).axis, Some(Axis::X | Axis::Y))).collect();
    let sides: Vec<usize> = r.free_dims(e).into_iter().filter(|k| r.dim(*k).role == Role::Side).collect();
    let lists: Vec<usize> = r.free_dims(e).into_iter().filter(|k| r.dim(*k).list.is_some()).collect();
    let pairs = if pairs.len() == 4 {
        pairs
    } else if sides.len() == 2 {
        vec![sides[0], sides[0], sides[1], sides[1]]
    } else if lists.len() == 4 {
        lists
    } else {
        pairs
    };
    if pairs.len() == 4 {
        let mut v: Vec<f64> = pairs.iter().map(|k| r.dim(*k).mm).collect();
        // "40 x 40 at the top, … tapering to 25 x 25 at the bottom": which is said the top.
        let said_top = |k: usize| {
            let t = r.dim(k).tok;
            r.dim(k).has("top")
                || (t + 1..(t + 5).min(r.doc.len())).take_while(|i| !r.doc.sym(*i, ',')).any(|i| r.doc.is(i, "top"))
        };
        let top_first = said_top(pairs[1]) && !said_top(pairs[3]);
        mark_words(r, &["tapering", "tapers", "tapered", "top", "bottom", "whole"]);
        if top_first {
            v = vec![v[2], v[3], v[0], v[1]];
        }
        for k in &pairs {
            r.used_dims[*k] = true;
        }
        let h = need(r.take(e, &[Role::Height, Role::Length], &[], &[]), "height", r, e)?;
        let span = span(r, e, Axis::Z, Some(h))?;
        let bi = r.model.adds.len();
        r.model.adds.push(Body::new(
            r.els[e].noun.clone(),
            Shape::Loft {
                at: [0.0, 0.0],
                from: span[0],
                to: span[1],
                bottom: Profile::Rect { w: v[0], h: v[1] },
                top: Profile::Rect { w: v[2], h: v[3] },
            },
        ));
        for i in 0..r.doc.len() {
            if r.doc.is(i, "top") && r.doc.is(i + 1, "face") {
                r.doc.mark_range(i, i + 2);
            }
        }
        return Ok(Built {
            axis: Axis::Z,
            span,
            at: vec![[0.0, 0.0]],
            od: None,
            id: None,
            size: Some([v[0], v[1]]),
            bodies: vec![bi],
            cut: false,
        });
    }
    let s = box_sizes(r, e);
    let a = s[0].or(s[1]);
    let a = need(a, "base side", r, e)?;
    let b = s[1].unwrap_or(a);
    let h = need(s[2].or_else(|| r.take(e, &[Role::Height], &[], &[])), "height", r, e)?;
    let span = span(r, e, Axis::Z, Some(h))?;
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(
        r.els[e].noun.clone(),
        Shape::Pyramid { at: [0.0, 0.0], from: span[0], to: span[1], w: a, d: b },
    ));
    Ok(Built {
        axis: Axis::Z,
        span,
        at: vec![[0.0, 0.0]],
        od: None,
        id: None,
        size: Some([a, b]),
        bodies: vec![bi],
        cut: false,
    })
}

/// A wedge: a triangle across Y (its ridge along X at the given height), extruded along X.
fn wedge(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let s = box_sizes(r, e);
    let (x, y) = (need(s[0], "length", r, e)?, need(s[1], "width", r, e)?);
    // The ridge height: a Z coordinate ("at height Z=25mm") or a height.
    let h = s[2].or_else(|| r.take_coord(e, Axis::Z));
    let h = need(h, "height", r, e)?;
    let x0 = if r.centered { -x / 2.0 } else { 0.0 };
    // "It tapers symmetrically from both Y edges to a thin ridge line at Y=0".
    mark_words(r, &["tapers", "taper", "tapering", "ridge", "line", "edge", "apex"]);
    r.known.push(0.0);
    let bi = r.model.adds.len();
    let pts = vec![[-y / 2.0, 0.0], [y / 2.0, 0.0], [0.0, h]];
    r.model.adds.push(Body::new(
        r.els[e].noun.clone(),
        Shape::Prism { profile: Profile::Poly(pts), axis: Axis::X, at: [0.0, 0.0], rot: 0.0, from: x0, to: x0 + x },
    ));
    Ok(Built {
        axis: Axis::X,
        span: [x0, x0 + x],
        at: vec![[0.0, 0.0]],
        od: None,
        id: None,
        size: Some([y, h]),
        bodies: vec![bi],
        cut: false,
    })
}

/// A right-triangle prism: legs along two axes from the right angle at the origin,
/// extruded along the third ("a 20mm leg along X and a 30mm leg along Y … Extruded 40mm in +Z").
fn right_triangle(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let mut legs: Vec<(Axis, f64)> = Vec::new();
    for k in r.free_dims(e) {
        let d = r.dim(k).clone();
        if d.has("leg") || r.doc.is(d.tok + 1, "leg") {
            legs.push((d.axis.unwrap_or(if legs.is_empty() { Axis::X } else { Axis::Y }), d.mm));
            r.used_dims[k] = true;
        }
    }
    // "legs of 50 and 20 mm": the second leg listed with the first.
    if legs.len() == 1 {
        let more: Vec<usize> = r
            .free_dims(e)
            .into_iter()
            .filter(|k| r.dim(*k).role == Role::Bare && r.dim(*k).quals.is_empty() && r.dim(*k).axis.is_none())
            .collect();
        if let [k] = more.as_slice() {
            r.used_dims[*k] = true;
            legs.push((Axis::Y, r.dim(*k).mm));
        }
    }
    let [(a1, l1), (a2, l2)] = legs.as_slice() else {
        return Err(Refusal::new(r.quote_element(e), "a right triangle needs its two legs"));
    };
    let along = Axis::ALL.into_iter().find(|a| a != a1 && a != a2).unwrap_or(Axis::Z);
    let h = need(r.take(e, &[Role::Length, Role::Height, Role::Thickness, Role::Bare], &[], &[]), "extrusion", r, e)?;
    let (u, _) = along.uv();
    // In (u, v): the leg along u, the other along v.
    let (lu, lv) = if *a1 == u { (*l1, *l2) } else { (*l2, *l1) };
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(
        r.els[e].noun.clone(),
        Shape::Prism {
            profile: Profile::Poly(vec![[0.0, 0.0], [lu, 0.0], [0.0, lv]]),
            axis: along,
            at: [0.0, 0.0],
            rot: 0.0,
            from: 0.0,
            to: h,
        },
    ));
    for i in 0..r.doc.len() {
        if matches!(
            r.doc.word(i),
            Some("right" | "angle" | "right-angle" | "right-angled" | "triangle" | "leg" | "extruded")
        ) {
            r.doc.mark(i);
        }
    }
    Ok(Built {
        axis: along,
        span: [0.0, h],
        at: vec![[0.0, 0.0]],
        od: None,
        id: None,
        size: Some([lu, lv]),
        bodies: vec![bi],
        cut: false,
    })
}

/// A half pipe: a semicircular ring opening upward (+Z), extruded along its axis.
fn half_pipe(r: &mut Reader<'_>, e: usize, od: f64, id: f64) -> Res<Built> {
    let axis = axis_of(r, e, true);
    let axis = if axis == Axis::Z { Axis::Y } else { axis };
    let len = need(r.take(e, &[Role::Length], &[], &[]), "length", r, e)?;
    let (ro, ri) = (od / 2.0, id / 2.0);
    // In (h, z), h the in-plane horizontal axis: the lower half, its centre at z = ro.
    let hz = [[-ro, ro], [0.0, 0.0], [ro, ro], [ri, ro], [0.0, ro - ri], [-ri, ro]];
    let (u, _) = axis.uv();
    let to_uv = |p: [f64; 2]| if u == Axis::Z { [p[1], p[0]] } else { [p[0], p[1]] };
    let segs = vec![
        super::super::profile::Seg::Arc { mid: to_uv(hz[1]), end: to_uv(hz[2]) },
        super::super::profile::Seg::Line(to_uv(hz[3])),
        super::super::profile::Seg::Arc { mid: to_uv(hz[4]), end: to_uv(hz[5]) },
        super::super::profile::Seg::Line(to_uv(hz[0])),
    ];
    let profile = Profile::Path { start: to_uv(hz[0]), segs };
    let from = if r.centered { -len / 2.0 } else { 0.0 };
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(
        r.els[e].noun.clone(),
        Shape::Prism { profile, axis, at: [0.0, 0.0], rot: 0.0, from, to: from + len },
    ));
    for i in 0..r.doc.len() {
        if matches!(r.doc.word(i), Some("semicircular" | "arc" | "opening" | "upward" | "half-pipe" | "trough")) {
            r.doc.mark(i);
        }
    }
    r.known.push(ro - ri);
    Ok(Built {
        axis,
        span: [from, from + len],
        at: vec![[0.0, 0.0]],
        od: Some(od),
        id: Some(id),
        size: None,
        bodies: vec![bi],
        cut: false,
    })
}

/// Hemispherical caps on the ends of the round body before them ("on both ends", "on
/// top", "on the bottom"), as wide as it.
fn caps(r: &mut Reader<'_>, e: usize) -> Res<()> {
    let Some(p) =
        (0..e).rev().find(|p| r.built[*p].as_ref().is_some_and(|b| !b.cut && b.od.is_some() && b.id.is_none()))
    else {
        return Ok(());
    };
    let Some(b) = r.built[p].clone() else { return Ok(()) };
    let (Some(d), [at]) = (b.od, b.at.as_slice()) else { return Ok(()) };
    let both = r.says(e, "both") || r.els[e].count == Some(2);
    let top = both || r.says(e, "top");
    let bottom = both || r.says(e, "bottom");
    if !top && !bottom {
        return Ok(());
    }
    let mut bodies = Vec::new();
    let mut span = b.span;
    for (is, z, up) in [(top, b.span[1], true), (bottom, b.span[0], false)] {
        if !is {
            continue;
        }
        let mut c = super::super::solid::point(b.axis, *at, z);
        c[b.axis.index()] = z;
        bodies.push(r.model.adds.len());
        r.model.adds.push(Body::new("cap", Shape::Hemisphere { c, d, axis: b.axis, up }));
        if up {
            span[1] += d / 2.0;
        } else {
            span[0] -= d / 2.0;
        }
    }
    mark_words(r, &["end", "both", "top", "bottom"]);
    r.built[e] =
        Some(Built { axis: b.axis, span, at: b.at.clone(), od: Some(d), id: None, size: None, bodies, cut: false });
    r.mark_element(e);
    Ok(())
}

/// "… rising from the Y=0 edge of the base": the base is placed with that edge at the
/// coordinate (it runs from it), and this body stands on the base, flush with the edge.
fn on_edge(r: &mut Reader<'_>, e: usize, size: [f64; 3]) -> Res<Option<Built>> {
    let d = r.doc;
    let hit = r.els[e]
        .coords
        .iter()
        .copied()
        .find(|k| !r.used_coords[*k] && d.is(d.coords[*k].tok + 3, "edge") && d.is(d.coords[*k].tok + 4, "of"));
    let Some(k) = hit else { return Ok(None) };
    let c = d.coords[k].clone();
    let target = r.mentions.iter().find(|m| m.head > c.tok + 4 && m.head <= c.tok + 8).map(|m| m.elem);
    let Some(t) = target.filter(|t| r.built[*t].as_ref().is_some_and(|b| b.size.is_some() && b.axis == Axis::Z)) else {
        return Ok(None);
    };
    if c.axis == Axis::Z {
        return Ok(None);
    }
    r.used_coords[k] = true;
    d.mark_range(c.tok, c.tok + 6);
    mark_words(r, &["rising", "rises", "standing"]);
    // Move the target so that it runs from the edge.
    let Some(tb) = r.built[t].clone() else { return Ok(None) };
    let Some(tsize) = tb.size else { return Ok(None) };
    let ai = c.axis.index();
    let shift = c.v - (tb.at[0][ai] - tsize[ai] / 2.0);
    let mut moved = tb.clone();
    for (p, bi) in moved.at.iter_mut().zip(&tb.bodies) {
        p[ai] += shift;
        if let Some(Shape::Prism { at, .. }) = r.model.adds.get_mut(*bi).map(|b| &mut b.shape) {
            *at = *p;
        }
    }
    let centre = moved.at[0];
    r.built[t] = Some(moved);
    // This body: from the edge inwards along the axis, centred on the target across it.
    let mut at = centre;
    at[ai] = c.v + size[ai] / 2.0;
    let span = [tb.span[1], tb.span[1] + size[2]];
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(
        r.els[e].noun.clone(),
        Shape::Prism {
            profile: Profile::Rect { w: size[0], h: size[1] },
            axis: Axis::Z,
            at,
            rot: 0.0,
            from: span[0],
            to: span[1],
        },
    ));
    r.known.push((tsize[1 - ai] - size[1 - ai]) / 2.0);
    Ok(Some(Built {
        axis: Axis::Z,
        span,
        at: vec![at],
        od: None,
        id: None,
        size: Some([size[0], size[1]]),
        bodies: vec![bi],
        cut: false,
    }))
}
