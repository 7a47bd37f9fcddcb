//! Bodies made by moving a section: a profile of points revolved about Z ("straight from
//! the bore (X=6) to the rim (X=30) at Z=0, up to Z=5 …"), a loft between a rectangle and
//! a circle, a pipe bent along an arc ("a quarter-circle arc of 40mm radius … starting at
//! the origin heading in the +Z direction"), and arms or spokes set radially about a hub.

use super::super::doc::Role;
use super::super::lexicon::Noun;
use super::super::profile::Profile;
use super::super::solid::{Axis, Body, Shape};
use super::super::text::Tk;
use super::bodies::part_span;
use super::{Built, Reader, Refusal, Res, place};

/// Revolved profiles, lofts and bends, when the prompt describes one.
pub fn read(r: &mut Reader<'_>) -> Res<()> {
    let d = r.doc;
    let has = |w: &str| (0..d.len()).any(|i| d.is(i, w));
    if has("revolved") || has("revolve") || has("revolution") {
        revolve(r)?;
    }
    if has("lofted") || has("loft") {
        loft(r)?;
    }
    if (has("arc") || has("bend") || has("elbow")) && (has("pipe") || has("tube")) && !has("tee") {
        bend(r)?;
    }
    Ok(())
}

fn title(r: &Reader<'_>) -> usize {
    r.els.iter().position(|e| e.title).unwrap_or(0)
}

/// The sentences that describe a profile: from the one naming it to the one revolving it.
fn revolve(r: &mut Reader<'_>) -> Res<()> {
    let d = r.doc;
    let ns = d.sentences();
    let rev = (0..ns).find(|s| {
        let (a, b) = d.sentence(*s);
        (a..b).any(|i| matches!(d.word(i), Some("revolved" | "revolve")))
    });
    let first = (0..ns).find(|s| {
        let (a, b) = d.sentence(*s);
        (a..b).any(|i| d.is(i, "profile")) && (a..b).any(|i| d.is(i, "z") && d.sym(i + 1, '='))
    });
    let (Some(first), Some(rev)) = (first, rev) else {
        return Err(Refusal::new("revolved", "the profile to revolve is not given as points (X = radius, Z = height)"));
    };
    let (a, _) = d.sentence(first);
    let (_, b) = d.sentence(rev.max(first));
    // "revolved 360 degrees": a full turn (a part turn is not made).
    let (ra, rb) = d.sentence(rev);
    for i in ra..rb {
        if let Tk::Deg(v) = d.toks[i].kind {
            if (v - 360.0).abs() > 1e-9 {
                return Err(Refusal::new(d.quote(i, i), "only a full 360-degree revolve is made"));
            }
            r.used_angles.insert(i);
            d.mark(i);
        }
    }
    // Chunks at "to": each gives X (radius) and/or Z; missing ones carry over. The
    // sentence that puts the axis ("The axis of revolution is at X=0") is not a point.
    let mut pts: Vec<(Option<f64>, Option<f64>)> = vec![(None, None)];
    let mut i = a;
    let mut started = false;
    let axis_sentence = |i: usize| {
        let (s0, s1) = d.sentence(d.sent[i]);
        (s0..s1).any(|j| d.is(j, "axis")) && (s0..s1).any(|j| d.is(j, "revolution"))
    };
    while i < b {
        if axis_sentence(i) {
            i += 1;
            continue;
        }
        if d.is(i, "to") && started {
            pts.push((None, None));
        }
        if let (Some(ax), true) = (d.axis_at(i), d.sym(i + 1, '='))
            && let Some(Tk::Num { v, unit, .. }) = d.toks.get(i + 2).map(|t| &t.kind)
        {
            let v = v * unit.unwrap_or(1.0);
            if let Some(last) = pts.last_mut() {
                match ax {
                    Axis::X => last.0 = Some(v),
                    Axis::Z => last.1 = Some(v),
                    Axis::Y => {}
                }
            }
            d.mark_range(i, i + 3);
            started = true;
            i += 3;
            continue;
        }
        // "a belly radius of 28mm", "at radius 25mm".
        if d.is(i, "radius")
            && let Some(k) = r.doc.dims.iter().position(|x| x.tok > i && x.tok <= i + 2 && x.role == Role::Radius)
        {
            if let Some(last) = pts.last_mut() {
                last.0 = Some(d.dims[k].mm);
            }
            r.used_dims[k] = true;
            started = true;
        }
        i += 1;
    }
    // Carry each coordinate forward, then back into the first points.
    let mut out: Vec<[f64; 2]> = Vec::new();
    let (mut x, mut z) = (None, None);
    for p in &pts {
        x = p.0.or(x);
        z = p.1.or(z);
        if p.0.is_none() && p.1.is_none() {
            continue;
        }
        out.push([x.unwrap_or(f64::NAN), z.unwrap_or(f64::NAN)]);
    }
    let fx = out.iter().map(|p| p[0]).find(|v| v.is_finite());
    let fz = out.iter().map(|p| p[1]).find(|v| v.is_finite());
    for p in &mut out {
        if !p[0].is_finite() {
            p[0] = fx.unwrap_or(0.0);
        }
        if !p[1].is_finite() {
            p[1] = fz.unwrap_or(0.0);
        }
    }
    out.dedup_by(|p, q| (p[0] - q[0]).abs() < 1e-9 && (p[1] - q[1]).abs() < 1e-9);
    if out.len() < 2 || out.iter().any(|p| p[0] < 0.0) {
        return Err(Refusal::new(
            d.quote(a, b.saturating_sub(1)),
            "the profile needs at least two points at radii of zero or more",
        ));
    }
    // Closed by the words, else through the axis.
    let closed = (a..b).any(|i| d.is(i, "closed"));
    let first_pt = out[0];
    let last_pt = out[out.len() - 1];
    if !closed {
        if last_pt[0] > 1e-9 {
            out.push([0.0, last_pt[1]]);
        }
        if first_pt[0] > 1e-9 {
            out.push([0.0, first_pt[1]]);
        }
    }
    if (out[0][0] - out[out.len() - 1][0]).abs() < 1e-9 && (out[0][1] - out[out.len() - 1][1]).abs() < 1e-9 {
        out.pop();
    }
    // Counter-clockwise in (r, z).
    let (area, _) = super::super::profile::poly_area_centroid(&out);
    if area.abs() < 1e-9 {
        return Err(Refusal::new(d.quote(a, b.saturating_sub(1)), "the profile encloses no area"));
    }
    if area < 0.0 {
        out.reverse();
    }
    for p in &out {
        r.known_points.push([p[0], 0.0, p[1]]);
    }
    let zmin = out.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
    let zmax = out.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
    let rmax = out.iter().map(|p| p[0]).fold(0.0, f64::max);
    let rmin_hole = if closed { out.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min) } else { 0.0 };
    let t = title(r);
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(r.els[t].noun.clone(), Shape::Revolve { at: [0.0, 0.0], profile: Profile::Poly(out) }));
    r.built[t] = Some(Built {
        axis: Axis::Z,
        span: [zmin, zmax],
        at: vec![[0.0, 0.0]],
        od: Some(2.0 * rmax),
        id: (rmin_hole > 0.0).then_some(2.0 * rmin_hole),
        size: None,
        bodies: vec![bi],
        cut: false,
    });
    r.mark_element(t);
    for i in ra..rb {
        if matches!(d.word(i), Some("revolved" | "revolve" | "revolution" | "around" | "about")) {
            d.mark(i);
        }
    }
    super::bodies::mark_words(r, &["revolution"]);
    // The profile's words are read: its reference nouns ("from the bore", "(bottom flange)",
    // "the V-groove root") and the words naming the points.
    for i in a..b {
        if d.word(i).is_some_and(|w| {
            super::super::lexicon::noun(w).is_some()
                || super::super::doc::QUALS.contains(&w)
                || matches!(w, "v-groove" | "back" | "closed" | "inward" | "outward" | "further" | "straight")
        }) {
            d.mark(i);
        }
    }
    for (e, el) in r.els.iter().enumerate() {
        if el.mentions.first().is_some_and(|m| {
            let h = r.mentions[*m].head;
            h >= a && h < b
        }) && matches!(el.kind, Noun::Body(_))
        {
            r.done[e] = true;
        }
    }
    Ok(())
}

/// "a smooth lofted transition from a 60mm x 40mm rectangle at Z=3 to a circle of 30mm
/// diameter at Z=53".
fn loft(r: &mut Reader<'_>) -> Res<()> {
    let d = r.doc;
    let Some(at) = (0..d.len()).find(|i| matches!(d.word(*i), Some("lofted" | "loft"))) else { return Ok(()) };
    let (_, b) = d.sentence(d.sent[at]);
    let (a, _) = d.sentence(d.sent[at]);
    // Two sections after "from" … "to": a rectangle (two listed lengths) or a circle.
    let from = d
        .find("from", at, b)
        .ok_or_else(|| Refusal::new(d.quote(at, at), "a loft needs its two sections: from … to …"))?;
    let to = d
        .find("to", from, b)
        .ok_or_else(|| Refusal::new(d.quote(at, at), "a loft needs its two sections: from … to …"))?;
    let section = |r: &mut Reader<'_>, lo: usize, hi: usize| -> Option<(Profile, f64)> {
        let z = r.doc.coords.iter().position(|c| c.tok >= lo && c.tok < hi && c.axis == Axis::Z)?;
        let zv = r.doc.coords[z].v;
        r.used_coords[z] = true;
        let ct = r.doc.coords[z].tok;
        r.doc.mark_range(ct, ct + 3);
        let dims: Vec<usize> =
            (0..r.doc.dims.len()).filter(|k| r.doc.dims[*k].tok >= lo && r.doc.dims[*k].tok < hi).collect();
        let is = |w: &str| (lo..hi).any(|i| r.doc.is(i, w));
        let p = if is("rectangle") || is("square") {
            let [x, y] = dims.as_slice() else { return None };
            r.used_dims[*x] = true;
            r.used_dims[*y] = true;
            Profile::Rect { w: r.doc.dims[*x].mm, h: r.doc.dims[*y].mm }
        } else if is("circle") {
            let [k] = dims.as_slice() else { return None };
            r.used_dims[*k] = true;
            let dm = &r.doc.dims[*k];
            Profile::Circle { d: if dm.role == Role::Radius { 2.0 * dm.mm } else { dm.mm } }
        } else {
            return None;
        };
        for i in lo..hi {
            if matches!(r.doc.word(i), Some("rectangle" | "square" | "circle")) {
                r.doc.mark(i);
            }
        }
        Some((p, zv))
    };
    let s0 = section(r, from, to);
    let stop = (to..b).find(|i| d.sym(*i, ';') || d.sym(*i, ')')).unwrap_or(b);
    let s1 = section(r, to, stop);
    let (Some((p0, z0)), Some((p1, z1))) = (s0, s1) else {
        return Err(Refusal::new(
            d.quote(from, b.saturating_sub(1)),
            "a loft's sections must each be a rectangle (A x B) or a circle, at a Z",
        ));
    };
    if z1 <= z0 {
        return Err(Refusal::new(
            d.quote(from, b.saturating_sub(1)),
            "a loft must rise from its first section to its second",
        ));
    }
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new("transition", Shape::Loft { at: [0.0, 0.0], from: z0, to: z1, bottom: p0, top: p1 }));
    // The sentence's own element (the transition) is this body.
    if let Some(e) = r.mentions.iter().find(|m| m.head >= a && m.head < b).map(|m| m.elem) {
        r.built[e] = Some(Built {
            axis: Axis::Z,
            span: [z0, z1],
            at: vec![[0.0, 0.0]],
            od: None,
            id: None,
            size: None,
            bodies: vec![bi],
            cut: false,
        });
        r.mark_element(e);
    }
    d.mark(at);
    d.mark(from);
    d.mark(to);
    Ok(())
}

/// A pipe bent along a circular arc in a plane, from a start point and heading.
fn bend(r: &mut Reader<'_>) -> Res<()> {
    let d = r.doc;
    let t = title(r);
    // The pipe's diameters: the title's or a pipe element's.
    let holder =
        (0..r.els.len()).find(|e| r.find(*e, &[Role::Diameter, Role::Radius], &["outer"], &[]).is_some()).unwrap_or(t);
    let od = r
        .take_diameter(holder, &["outer"], &[])
        .ok_or_else(|| Refusal::new(r.quote_element(t), "no outer diameter is given for the pipe"))?;
    let id = r.take_diameter(holder, &["inner"], &[]).unwrap_or(0.0);
    // The bend radius: a radius qualified by arc/bend, or "of 40mm radius".
    let rk = (0..d.dims.len()).find(|k| {
        !r.used_dims[*k] && d.dims[*k].role == Role::Radius && !d.dims[*k].has("outer") && !d.dims[*k].has("inner")
    });
    let Some(rk) = rk else { return Err(Refusal::new(r.quote_element(t), "no bend radius is given")) };
    r.used_dims[rk] = true;
    let radius = d.dims[rk].mm;
    // The angle: "90-degree", "45 degrees", "quarter-circle", "semicircular", "U-bend".
    let mut angle = None;
    for i in 0..d.len() {
        if let Tk::Deg(a) = d.toks[i].kind
            && !r.used_angles.contains(&i)
            && (1.0..=360.0).contains(&a)
            && angle.is_none()
        {
            angle = Some(a);
            r.used_angles.insert(i);
            d.mark(i);
        }
    }
    let words = |w: &str| (0..d.len()).find(|i| d.is(*i, w));
    if angle.is_none() {
        if let Some(i) = words("quarter-circle") {
            angle = Some(90.0);
            d.mark(i);
        } else if let Some(i) = words("semicircular").or_else(|| words("u-bend")) {
            angle = Some(180.0);
            d.mark(i);
        }
    }
    let angle = angle.ok_or_else(|| Refusal::new(r.quote_element(t), "the bend's angle is not given"))?;
    // The same angle said again ("curving 45 degrees toward the +X direction").
    for i in 0..d.len() {
        if let Tk::Deg(a) = d.toks[i].kind
            && (a - angle).abs() < 1e-9
        {
            r.used_angles.insert(i);
            d.mark(i);
        }
    }
    super::bodies::mark_words(
        r,
        &[
            "quarter-circle",
            "semicircular",
            "arc",
            "u-bend",
            "elbow",
            "bend",
            "swept",
            "sweeping",
            "first",
            "quadrant",
            "leg",
            "parallel",
        ],
    );
    // Start heading and the way it turns: "heading in the +Z direction", "toward the +X".
    let mut dirs: Vec<(usize, Axis, f64)> = Vec::new();
    for i in 0..d.len().saturating_sub(1) {
        let sign = if d.sym(i, '+') {
            1.0
        } else if d.sym(i, '-') {
            -1.0
        } else {
            continue;
        };
        if let Some(a) = d.axis_at(i + 1) {
            dirs.push((i, a, sign));
        }
    }
    let heading = dirs
        .first()
        .copied()
        .ok_or_else(|| Refusal::new(r.quote_element(t), "the bend's start heading (+X, +Z …) is not given"))?;
    // The way it turns: a direction on another axis, else toward the end point given
    // ("returning down to (X=70, Z=0)").
    let toward_end = || {
        d.tuples.iter().find_map(|tu| {
            let v = tu.vals.iter().find(|(a, v, _)| a.is_some_and(|a| a != heading.1) && v.abs() > 1e-9)?;
            Some((tu.toks.0, v.0.unwrap_or(Axis::X), v.1.signum()))
        })
    };
    let turn = dirs
        .iter()
        .copied()
        .find(|x| x.1 != heading.1)
        .or_else(toward_end)
        .ok_or_else(|| Refusal::new(r.quote_element(t), "the way the bend turns (toward +X …) is not given"))?;
    for x in &dirs {
        d.mark_range(x.0, x.0 + 2);
    }
    // Plane axes: u the turn axis, v the heading axis; start at the origin.
    let (u, v) = (turn.1, heading.1);
    let mut c = [0.0; 3];
    c[u.index()] = radius * turn.2;
    let a0: f64 = if turn.2 > 0.0 { 180.0 } else { 0.0 };
    let dir = if a0.to_radians().cos() * heading.2 > 0.0 { 1.0 } else { -1.0 };
    let a1 = a0 + dir * angle;
    let shape = Shape::Bend { od, id, centre: c, radius, u, v, a0, a1 };
    let pt = |a: f64| {
        let mut p = c;
        p[u.index()] += radius * a.to_radians().cos();
        p[v.index()] += radius * a.to_radians().sin();
        p
    };
    r.known_points.push(pt(a0));
    r.known_points.push(pt(a1));
    r.known_points.push(pt((a0 + a1) / 2.0));
    // The apex of a half turn and the legs' spacing.
    r.known.push(radius);
    r.known.push(2.0 * radius);
    let b = shape.bounds();
    r.known.push(b[1][v.index()] - radius * 0.0);
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new("bend", shape));
    r.built[t] = Some(Built {
        axis: v,
        span: [0.0, 0.0],
        at: vec![[0.0, 0.0]],
        od: Some(od),
        id: Some(id),
        size: None,
        bodies: vec![bi],
        cut: false,
    });
    r.mark_element(t);
    if holder != t {
        r.mark_element(holder);
    }
    for e in r.elements_named("pipe") {
        r.mark_element(e);
    }
    Ok(())
}

/// Whether an element is a set of arms (or spokes) around a hub.
pub fn is_radial(r: &Reader<'_>, e: usize) -> bool {
    let el = &r.els[e];
    matches!(el.noun.as_str(), "arm" | "spoke" | "rib" | "leg" | "fin")
        && el.count.is_some_and(|c| c >= 2)
        && (!el.angles.is_empty()
            || r.says(e, "outward")
            || r.says(e, "radially")
            || r.doc.toks.iter().any(|t| t.kind == Tk::Sym('±')))
        || (el.noun == "spoke" && el.count.is_some_and(|c| c >= 2))
}

/// Arms or spokes set radially: their directions (angles, or "along the ±X and ±Y
/// axes"), their span from the centre, width and thickness; joined into the round hub and
/// rim they start and end at.
pub fn radial(r: &mut Reader<'_>, e: usize) -> Res<Built> {
    let count = r.els[e].count.unwrap_or(1);
    let mut angles = place::take_angles(r, e);
    if angles.is_empty() {
        // "along the ±X and ±Y axes".
        let d = r.doc;
        let (a, b) = r.sentences_of(e).first().copied().unwrap_or((0, 0));
        let pm = |ax: &str| (a..b).any(|i| d.is(i, ax) && i > 0 && matches!(d.toks[i - 1].kind, Tk::Sym(_)));
        let mut v = Vec::new();
        if pm("x") {
            v.extend([0.0, 180.0]);
        }
        if pm("y") {
            v.extend([90.0, 270.0]);
        }
        angles = if v.len() == count as usize {
            v
        } else {
            (0..count).map(|i| 360.0 * f64::from(i) / f64::from(count)).collect()
        };
    }
    if angles.len() != count as usize {
        return Err(Refusal::new(r.quote_element(e), format!("{} directions for {count} of them", angles.len())));
    }
    // Distances "N from center".
    let mut from_centre = Vec::new();
    for k in r.els[e].dims.clone() {
        let t = r.dim(k).tok;
        if (t + 1..(t + 4).min(r.doc.len())).any(|i| r.doc.is(i, "center")) && r.doc.is(t + 1, "from") {
            from_centre.push((k, r.dim(k).mm));
        }
    }
    let width = r
        .take(e, &[Role::Width], &[], &[])
        .ok_or_else(|| Refusal::new(r.quote_element(e), "no width is given for them"))?;
    let hub = (0..e).rev().find(|p| {
        r.built[*p].is_some() && (r.els[*p].noun == "hub" || r.els[*p].has_mod("hub") || r.els[*p].has_mod("central"))
    });
    let hub_r = hub
        .and_then(|h| r.built[h].as_ref())
        .map(|b| b.od.map_or_else(|| b.size.map_or(0.0, |s| s[0].min(s[1]) / 2.0), |d| d / 2.0));
    let (r0, r1) = match from_centre.as_slice() {
        [(k0, a), (k1, b)] => {
            r.used_dims[*k0] = true;
            r.used_dims[*k1] = true;
            (a.min(*b), a.max(*b))
        }
        [(k, b)] if hub_r.is_some() => {
            r.used_dims[*k] = true;
            (hub_r.unwrap_or(0.0), *b)
        }
        _ => {
            let l = r
                .take(e, &[Role::Length], &[], &[])
                .ok_or_else(|| Refusal::new(r.quote_element(e), "their span from the centre is not given"))?;
            let h = hub_r.ok_or_else(|| Refusal::new(r.quote_element(e), "they start at no hub of known size"))?;
            (h, h + l)
        }
    };
    r.known.extend([r0, r1, r1 - r0, (r0 + r1) / 2.0]);
    super::bodies::mark_words(r, &["edge", "tip", "outward", "radially", "enough", "bridge", "bridging"]);
    let thick = r.take(e, &[Role::Height, Role::Thickness], &[], &[]);
    let span = match thick {
        Some(t) => [0.0, t],
        None => part_span(r)
            .or_else(|| hub.and_then(|h| r.built[h].as_ref()).map(|b| b.span))
            .ok_or_else(|| Refusal::new(r.quote_element(e), "no thickness is given for them"))?,
    };
    // Join: into a round hub (its corners inside the disc) and into a rim they reach.
    let mut inner = r0;
    if let Some(h) = hub
        && r.built[h].as_ref().is_some_and(|b| b.od.is_some())
    {
        let rr = hub_r.unwrap_or(0.0);
        if (r0 - rr).abs() < 1e-6 && rr > width / 2.0 {
            inner = (rr * rr - width * width / 4.0).sqrt() * 0.9;
        }
    }
    let mut outer = r1;
    let rim = (0..r.els.len())
        .find(|p| r.built[*p].as_ref().is_some_and(|b| b.id.is_some_and(|i| (i / 2.0 - r1).abs() < 1e-6)));
    if let Some(rim) = rim
        && let Some(b) = &r.built[rim]
        && let (Some(od), Some(id)) = (b.od, b.id)
    {
        let need = (id * id / 4.0 + width * width / 4.0).sqrt();
        outer = (need + (od / 2.0 - need) * 0.5).max(r1);
    }
    let len = outer - inner;
    let mid = (outer + inner) / 2.0;
    let mut bodies = Vec::new();
    let mut at = Vec::new();
    for a in &angles {
        let p = [mid * a.to_radians().cos(), mid * a.to_radians().sin()];
        bodies.push(r.model.adds.len());
        r.model.adds.push(Body::new(
            r.els[e].noun.clone(),
            Shape::Prism {
                profile: Profile::Rect { w: len, h: width },
                axis: Axis::Z,
                at: p,
                rot: *a,
                from: span[0],
                to: span[1],
            },
        ));
        at.push([r1 * a.to_radians().cos(), r1 * a.to_radians().sin()]);
        r.known_points.push([r1 * a.to_radians().cos(), r1 * a.to_radians().sin(), span[0]]);
    }
    // Their tips, where mounts may be "at each arm tip".
    Ok(Built { axis: Axis::Z, span, at, od: None, id: None, size: Some([r1 - r0, width]), bodies, cut: false })
}
