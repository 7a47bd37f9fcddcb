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
        if r.done[e] || !matches!(r.els[e].kind, Noun::Body(_)) {
            continue;
        }
        // The part's name with no size of its own is only its name ("A hex bolt: …").
        if r.els[e].title && r.els[e].dims.is_empty() && r.els.len() > 1 {
            r.mark_element(e);
            continue;
        }
        // A body with no quantity of its own is a name or a reference ("through the wall",
        // "(bottom flange)"), not a new body; what it asks is checked when all is read.
        let el = &r.els[e];
        if el.dims.is_empty() && el.ranges.is_empty() && el.tuples.is_empty() && el.coords.is_empty() {
            continue;
        }
        let b = if super::paths::is_radial(r, e) { super::paths::radial(r, e)? } else { build(r, e)? };
        r.built[e] = Some(b);
        r.mark_element(e);
    }
    Ok(())
}

/// The axis a body runs along: a length given along an axis, a span on X or Y, else Z.
fn axis_of(r: &Reader<'_>, e: usize, round: bool) -> Axis {
    let el = &r.els[e];
    if round {
        for &k in &el.dims {
            let d = r.dim(k);
            if matches!(d.role, Role::Length | Role::Height) && !r.used_dims[k] && let Some(a) = d.axis {
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
        for (s, t) in r.sentences_of(e) {
            for i in s..t.saturating_sub(2) {
                if r.doc.is(i, "along") {
                    let a = r.doc.word(i + 1).and_then(axis_name).or_else(|| r.doc.word(i + 2).and_then(axis_name));
                    if let Some(a) = a {
                        return a;
                    }
                }
            }
        }
    }
    Axis::Z
}

pub fn axis_name(w: &str) -> Option<Axis> {
    match w {
        "x" | "+x" => Some(Axis::X),
        "y" | "+y" => Some(Axis::Y),
        "z" | "+z" => Some(Axis::Z),
        _ => None,
    }
}

/// The span of a body along its axis and the length that sized it.
fn span(r: &mut Reader<'_>, e: usize, axis: Axis, len: Option<f64>) -> Res<[f64; 2]> {
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
    // Stacked on the body before it along the same axis, when one is there and the
    // words say on top (or nothing says otherwise); the first body from 0 (or centred).
    let prev = (0..e).rev().find_map(|p| r.built[p].as_ref().filter(|b| b.axis == axis && !b.cut).map(|b| b.span));
    let on_top = r.says(e, "top") || r.says(e, "topped") || r.says(e, "above") || r.says(e, "on");
    match prev {
        Some(p) if on_top => {
            mark_on_top(r, e);
            Ok([p[1], p[1] + l])
        }
        _ if r.centered && prev.is_none() => Ok([-l / 2.0, l / 2.0]),
        _ => Ok([0.0, l]),
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
    if count > 1 {
        if let Some(g) = place::grid(r, e) {
            return Ok(g);
        }
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
        if d.paren || treat(&d) || matches!(d.role, Role::Fillet | Role::Chamfer | Role::Inset | Role::Spacing | Role::Diameter | Role::Radius) {
            continue;
        }
        if let Some(a) = d.axis
            && s[a.index()].is_none()
        {
            s[a.index()] = Some(d.mm);
            r.used_dims[k] = true;
        }
    }
    // A list fills X, Y, Z in order of the free axes.
    let list: Vec<usize> = dims.iter().copied().filter(|k| !r.used_dims[*k] && r.dim(*k).list.is_some() && !r.dim(*k).paren).collect();
    if list.len() >= 2 {
        for k in list {
            if let Some(i) = (0..3).find(|i| s[*i].is_none()) {
                s[i] = Some(r.dim(k).mm);
                r.used_dims[k] = true;
            }
        }
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
    // A side fills the square ("40mm sides", "80mm on each side").
    if let Some(k) = r.find(e, &[Role::Side], &[], &[]) {
        let v = r.dim(k).mm;
        r.used_dims[k] = true;
        let cube = r.els[e].noun == "cube" || r.shape_of(e) == Some(ShapeHint::Rect) && r.els[e].noun == "cube";
        for i in 0..if cube { 3 } else { 2 } {
            s[i] = s[i].or(Some(v));
        }
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
    s
}

fn build(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let shape = r.shape_of(e).unwrap_or(ShapeHint::Rect);
    match shape {
        ShapeHint::Round | ShapeHint::Ring | ShapeHint::Ngon(_) | ShapeHint::Star | ShapeHint::Ellipse | ShapeHint::Stadium => {
            prism(r, e, shape)
        }
        ShapeHint::Rect => rect(r, e),
        ShapeHint::Cone => cone(r, e),
        ShapeHint::Sphere | ShapeHint::Hemisphere => sphere(r, e, shape == ShapeHint::Hemisphere),
        ShapeHint::Torus => torus(r, e),
        ShapeHint::Capsule => capsule(r, e),
        ShapeHint::Pyramid => pyramid(r, e),
        ShapeHint::Wedge => wedge(r, e),
        ShapeHint::Section(_) => Err(Refusal::new(r.quote_element(e), "a named cross-section it could not size")),
    }
}

const NOT_OUTER: &[&str] = &["inner", "bore", "hole", "pitch", "circle", "tip", "root", "counterbore", "bolt", "inscribed"];

/// A profile extruded along an axis: cylinders, rings, polygons, stars, ellipses, stadiums.
fn prism(r: &mut Reader<'_>, e: usize, shape: ShapeHint) -> Res<Built> {
    let round = matches!(shape, ShapeHint::Round | ShapeHint::Ring | ShapeHint::Ngon(_) | ShapeHint::Star | ShapeHint::Ellipse);
    let axis = axis_of(r, e, round);
    let (profile, od, id) = match shape {
        ShapeHint::Round | ShapeHint::Ring => {
            let od = r.take_diameter(e, &["outer"], &[]).or_else(|| r.take_diameter(e, &[], NOT_OUTER));
            let od = need(od, "diameter", r, e)?;
            let mut id = r.take_diameter(e, &["inner"], &[]).or_else(|| r.take_diameter(e, &["bore"], &["pitch"]));
            if id.is_none() && shape == ShapeHint::Ring {
                id = r.take_diameter(e, &["hole"], &["pitch", "bolt"]);
                if id.is_none()
                    && let Some(w) = r.take(e, &[Role::Thickness], &["wall"], &[])
                {
                    id = Some(od - 2.0 * w);
                }
            }
            match id {
                Some(i) if i > 0.0 && i < od => (Profile::Annulus { od, id: i }, od, Some(i)),
                Some(i) => {
                    return Err(Refusal::new(r.quote_element(e), format!("its inner diameter {i} mm does not fit inside {od} mm")));
                }
                None => (Profile::Circle { d: od }, od, None),
            }
        }
        ShapeHint::Ngon(n) => {
            let d = r
                .take_diameter(e, &["circumscribed"], &[])
                .or_else(|| r.take(e, &[Role::Bare, Role::Diameter], &["across", "corner"], &[]))
                .or_else(|| r.take(e, &[Role::Bare, Role::Diameter, Role::Width], &["across", "flat"], &[]).map(|af| af / (std::f64::consts::PI / n as f64).cos()))
                .or_else(|| r.take_diameter(e, &[], NOT_OUTER));
            let d = need(d, "circumscribed diameter", r, e)?;
            // A triangle stands on its base (a corner on +v); other polygons have a corner on +u.
            let phase = if n == 3 { 90.0 } else { 0.0 };
            (Profile::Ngon { n, d, phase }, d, None)
        }
        ShapeHint::Star => {
            let tip = need(r.take_diameter(e, &["tip"], &[]), "tip diameter", r, e)?;
            let root = need(r.take_diameter(e, &["root"], &[]), "root diameter", r, e)?;
            let teeth = r.els[e].teeth.or(r.els[e].count).ok_or_else(|| Refusal::new(r.quote_element(e), "no number of teeth is given"))?;
            if !(3..=400).contains(&teeth) || root >= tip {
                return Err(Refusal::new(r.quote_element(e), format!("{teeth} teeth between {root} and {tip} mm is not a gear")));
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
            return Ok(add(r, e, Profile::Stadium { l, w }, Axis::Z, span, None, None, None));
        }
    };
    let has_range = r.els[e].ranges.iter().any(|k| !r.used_ranges[*k] && r.doc.ranges[*k].axis == axis);
    let mut len = None;
    if !has_range {
        len = r.find(e, ALONG, &[], &["wall", "counterbore", "face", "total", "overall"]).map(|k| {
            r.used_dims[k] = true;
            r.dim(k).mm
        });
        if len.is_none() && shape == ShapeHint::Star {
            len = r.take(e, &[Role::Width], &["face"], &[]);
        }
    }
    let span = span(r, e, axis, len)?;
    Ok(add(r, e, profile, axis, span, Some(od), id, None))
}

/// Adds the copies of a prism and records what it became.
#[allow(clippy::too_many_arguments)]
pub fn add(r: &mut Reader<'_>, e: usize, profile: Profile, axis: Axis, span: [f64; 2], od: Option<f64>, id: Option<f64>, size: Option<[f64; 2]>) -> Built {
    let at = positions(r, e, axis).unwrap_or_else(|_| vec![[0.0, 0.0]]);
    let mut bodies = Vec::new();
    for p in &at {
        bodies.push(r.model.adds.len());
        r.model.adds.push(Body::new(r.els[e].noun.clone(), Shape::Prism { profile: profile.clone(), axis, at: *p, rot: 0.0, from: span[0], to: span[1] }));
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
                return Err(Refusal::new(r.quote_element(e), format!("its size {v} mm and its span {}..{} along {} disagree", sp[0], sp[1], a.name())));
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
    let cx = r.take_coord(e, Axis::X);
    let cy = r.take_coord(e, Axis::Y);
    let zspan = match iv[2] {
        Some(sp) => sp,
        None => span(r, e, Axis::Z, Some(z))?,
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
    let t = r.els.iter().position(|e| e.title)?;
    if !matches!(r.els[t].kind, Noun::Whole) && !r.els[t].dims.is_empty() {
        return None;
    }
    let k = *r.els[t].ranges.iter().find(|k| r.doc.ranges[**k].axis == Axis::Z)?;
    r.used_ranges[k] = true;
    let rg = &r.doc.ranges[k];
    r.doc.mark_range(rg.toks.0, rg.toks.1);
    Some([rg.a.min(rg.b), rg.a.max(rg.b)])
}

fn cone(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let base = r.take_diameter(e, &["base"], &[]).or_else(|| r.take_diameter(e, &["bottom"], &[])).or_else(|| r.take_diameter(e, &[], &["top", "tip"]));
    let base = need(base, "base diameter", r, e)?;
    let top = r.take_diameter(e, &["top"], &[]).unwrap_or(0.0);
    let h = need(r.take(e, &[Role::Height, Role::Length], &[], &[]), "height", r, e)?;
    let span = span(r, e, Axis::Z, Some(h))?;
    let at = positions(r, e, Axis::Z)?;
    let mut bodies = Vec::new();
    for p in &at {
        bodies.push(r.model.adds.len());
        r.model.adds.push(Body::new(r.els[e].noun.clone(), Shape::Cone { axis: Axis::Z, at: *p, from: span[0], to: span[1], d_from: base, d_to: top }));
    }
    Ok(Built { axis: Axis::Z, span, at, od: Some(base), id: None, size: None, bodies, cut: false })
}

fn sphere(r: &mut Reader<'_>, e: usize, half: bool) -> Res<Built> {
    let dia = need(r.take_diameter(e, &[], &[]), "diameter or radius", r, e)?;
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
                Some("dome") if d.word(i + 1).is_some_and(|w| matches!(w, "rising" | "pointing" | "facing" | "up" | "upward")) => d.mark(i),
                Some("flat") if d.is(i + 1, "face") => d.mark_range(i, i + 2),
                _ => {}
            }
        }
    }
    let c = [0.0, 0.0, z0];
    let shape = if half { Shape::Hemisphere { c, d: dia, axis: Axis::Z, up } } else { Shape::Sphere { c, d: dia } };
    let b = r.model.adds.len();
    r.model.adds.push(Body::new(r.els[e].noun.clone(), shape));
    let span = if half && up { [z0, z0 + dia / 2.0] } else if half { [z0 - dia / 2.0, z0] } else { [z0 - dia / 2.0, z0 + dia / 2.0] };
    Ok(Built { axis: Axis::Z, span, at: vec![[0.0, 0.0]], od: Some(dia), id: None, size: None, bodies: vec![b], cut: false })
}

fn torus(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let od = r.take_diameter(e, &["outer"], &[]);
    let id = r.take_diameter(e, &["inner"], &[]);
    let (major, minor) = match (od, id) {
        (Some(o), Some(i)) if i < o => ((o + i) / 2.0, (o - i) / 2.0),
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
    Ok(Built { axis: Axis::Z, span: [z - minor / 2.0, z + minor / 2.0], at: vec![[0.0, 0.0]], od: Some(major + minor), id: Some(major - minor), size: None, bodies: vec![b], cut: false })
}

fn capsule(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let d = need(r.take_diameter(e, &[], &[]), "diameter", r, e)?;
    let l = need(r.take(e, ALONG, &[], &[]), "length", r, e)?;
    cylinder_with_caps(r, e, d, l)
}

/// A cylinder of length `l` with a hemisphere on each end (the caps outside its length).
pub fn cylinder_with_caps(r: &mut Reader<'_>, e: usize, d: f64, l: f64) -> Res<Built> {
    let (z0, z1) = if r.centered { (-l / 2.0, l / 2.0) } else { (d / 2.0, d / 2.0 + l) };
    let mut bodies = vec![r.model.adds.len()];
    r.model.adds.push(Body::new("cylinder", Shape::Prism { profile: Profile::Circle { d }, axis: Axis::Z, at: [0.0, 0.0], rot: 0.0, from: z0, to: z1 }));
    bodies.push(r.model.adds.len());
    r.model.adds.push(Body::new("cap", Shape::Hemisphere { c: [0.0, 0.0, z1], d, axis: Axis::Z, up: true }));
    bodies.push(r.model.adds.len());
    r.model.adds.push(Body::new("cap", Shape::Hemisphere { c: [0.0, 0.0, z0], d, axis: Axis::Z, up: false }));
    let _ = e;
    Ok(Built { axis: Axis::Z, span: [z0 - d / 2.0, z1 + d / 2.0], at: vec![[0.0, 0.0]], od: Some(d), id: None, size: None, bodies, cut: false })
}

fn pyramid(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let s = box_sizes(r, e);
    let a = s[0].or(s[1]);
    let a = need(a, "base side", r, e)?;
    let b = s[1].unwrap_or(a);
    let h = need(s[2].or_else(|| r.take(e, &[Role::Height], &[], &[])), "height", r, e)?;
    let span = span(r, e, Axis::Z, Some(h))?;
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(r.els[e].noun.clone(), Shape::Pyramid { at: [0.0, 0.0], from: span[0], to: span[1], w: a, d: b }));
    Ok(Built { axis: Axis::Z, span, at: vec![[0.0, 0.0]], od: None, id: None, size: Some([a, b]), bodies: vec![bi], cut: false })
}

/// A wedge: a triangle across Y (its ridge along X at the given height), extruded along X.
fn wedge(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let s = box_sizes(r, e);
    let (x, y) = (need(s[0], "length", r, e)?, need(s[1], "width", r, e)?);
    // The ridge height: a Z coordinate ("at height Z=25mm") or a height.
    let h = s[2].or_else(|| r.take_coord(e, Axis::Z));
    let h = need(h, "height", r, e)?;
    let x0 = if r.centered { -x / 2.0 } else { 0.0 };
    let bi = r.model.adds.len();
    let pts = vec![[-y / 2.0, 0.0], [y / 2.0, 0.0], [0.0, h]];
    r.model.adds.push(Body::new(r.els[e].noun.clone(), Shape::Prism { profile: Profile::Poly(pts), axis: Axis::X, at: [0.0, 0.0], rot: 0.0, from: x0, to: x0 + x }));
    Ok(Built { axis: Axis::X, span: [x0, x0 + x], at: vec![[0.0, 0.0]], od: None, id: None, size: Some([y, h]), bodies: vec![bi], cut: false })
}
