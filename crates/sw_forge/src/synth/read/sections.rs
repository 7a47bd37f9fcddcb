//! Named cross-sections extruded along their length: I-beams, T-beams, U- and C-channels,
//! rectangular tubes, and the L-bracket of a wall and a base that meet at an inside corner.
//! Their sizes come from the part's own lengths and from the elements that name their
//! pieces ("Both flanges are 3mm thick and the vertical web is 2mm thick").

use super::super::doc::Role;
use super::super::lexicon::{Noun, Section, ShapeHint};
use super::super::profile::Profile;
use super::super::solid::{Axis, Body, Shape};
use super::{Built, Reader, Refusal, Res};

/// Builds the part when its name is a cross-section.
pub fn read(r: &mut Reader<'_>) -> Res<()> {
    let Some(t) = r.els.iter().position(|e| e.title) else { return Ok(()) };
    let section = match r.shape_of(t) {
        Some(ShapeHint::Section(s)) => s,
        _ => return Ok(()),
    };
    match section {
        Section::I | Section::T => beam(r, t, section),
        Section::U => channel(r, t),
        Section::RectTube => rect_tube(r, t),
        Section::L => l_bracket(r, t),
        // A Z-bracket is read from its plates' coordinates, as bodies.
        Section::Z => {
            r.mark_element(t);
            Ok(())
        }
    }
}

fn need(v: Option<f64>, what: &str, r: &Reader<'_>, e: usize) -> Res<f64> {
    v.filter(|x| x.is_finite() && *x > 0.0)
        .ok_or_else(|| Refusal::new(r.quote_element(e), format!("no {what} is given for it")))
}

/// A length of the part or of its named piece: the piece's own first, then the part's
/// qualified by the piece's name.
fn piece(r: &mut Reader<'_>, t: usize, name: &str, roles: &[Role]) -> Option<f64> {
    for p in r.elements_named(name) {
        if p != t
            && let Some(v) = r.take(p, roles, &[], &[])
        {
            r.mark_element(p);
            return Some(v);
        }
    }
    r.take(t, roles, &[name], &[])
}

/// Marks the pieces read and their words.
fn mark_pieces(r: &mut Reader<'_>, names: &[&str]) {
    for n in names {
        for p in r.elements_named(n) {
            if matches!(r.els[p].kind, Noun::Body(_)) {
                r.mark_element(p);
            }
        }
    }
}

/// Lengthwise along X (or the axis given with its length), centred.
fn length(r: &mut Reader<'_>, t: usize) -> Res<(f64, Axis)> {
    let Some(k) = r.find(t, &[Role::Length], &[], &[]) else {
        return Err(Refusal::new(r.quote_element(t), "no length is given for it"));
    };
    r.used_dims[k] = true;
    Ok((r.dim(k).mm, r.dim(k).axis.unwrap_or(Axis::X)))
}

fn extrude(r: &mut Reader<'_>, t: usize, pts: Vec<[f64; 2]>, len: f64, axis: Axis) -> Built {
    let from = if r.centered { -len / 2.0 } else { 0.0 };
    let b = r.model.adds.len();
    r.model.adds.push(Body::new(
        r.els[t].noun.clone(),
        Shape::Prism { profile: Profile::Poly(pts), axis, at: [0.0, 0.0], rot: 0.0, from, to: from + len },
    ));
    Built {
        axis,
        span: [from, from + len],
        at: vec![[0.0, 0.0]],
        od: None,
        id: None,
        size: None,
        bodies: vec![b],
        cut: false,
    }
}

fn beam(r: &mut Reader<'_>, t: usize, s: Section) -> Res<()> {
    let (len, axis) = length(r, t)?;
    let h = need(r.take(t, &[Role::Height], &[], &["web"]), "height", r, t)?;
    let w = piece(r, t, "flange", &[Role::Width]).or_else(|| r.take(t, &[Role::Width], &[], &[]));
    let w = need(w, "flange width", r, t)?;
    let tf = need(piece(r, t, "flange", &[Role::Thickness]), "flange thickness", r, t)?;
    // "a 3 mm web": a bare length before it is its thickness.
    let tw = need(
        piece(r, t, "web", &[Role::Thickness]).or_else(|| piece(r, t, "web", &[Role::Bare])),
        "web thickness",
        r,
        t,
    )?;
    if tw >= w || (s == Section::I && 2.0 * tf >= h) || tf >= h {
        return Err(Refusal::new(r.quote_element(t), "its flanges or web do not fit its height and width"));
    }
    let (y, a) = (w / 2.0, tw / 2.0);
    let pts = if s == Section::I {
        let z = h / 2.0;
        vec![
            [-y, -z],
            [y, -z],
            [y, -z + tf],
            [a, -z + tf],
            [a, z - tf],
            [y, z - tf],
            [y, z],
            [-y, z],
            [-y, z - tf],
            [-a, z - tf],
            [-a, -z + tf],
            [-y, -z + tf],
        ]
    } else {
        vec![[-a, 0.0], [a, 0.0], [a, h - tf], [y, h - tf], [y, h], [-y, h], [-y, h - tf], [-a, h - tf]]
    };
    // The web's height and the flanges' faces, as a restatement may give them.
    if s == Section::I {
        r.known.extend([h - 2.0 * tf, h / 2.0 - tf]);
    } else {
        r.known.extend([h - tf]);
        r.known_points.push([0.0, 0.0, h - tf]);
    }
    let b = extrude(r, t, pts, len, axis);
    r.built[t] = Some(b);
    r.mark_element(t);
    mark_pieces(r, &["flange", "web"]);
    Ok(())
}

fn channel(r: &mut Reader<'_>, t: usize) -> Res<()> {
    // "Channel 100 x 50 x 5 (web x flange x thickness), 400 long": a catalogue's size.
    let list: Vec<usize> =
        r.free_dims(t).into_iter().filter(|k| r.dim(*k).list.is_some() && !r.dim(*k).paren).collect();
    let catalogue = if let [a, b, c] = list.as_slice() {
        let v = [r.dim(*a).mm, r.dim(*b).mm, r.dim(*c).mm];
        for k in [a, b, c] {
            r.used_dims[*k] = true;
        }
        for i in 0..r.doc.len() {
            if (matches!(r.doc.word(i), Some("web" | "flange" | "thickness" | "x")) || r.doc.sym(i, 'x'))
                && r.doc.depth[i] > 0
            {
                r.doc.mark(i);
            }
        }
        Some(v)
    } else {
        None
    };
    let (len, axis) = length(r, t)?;
    let (w, h, tw, tb) = if let Some([w, h, th]) = catalogue {
        (w, h, th, th)
    } else {
        let w = need(r.take(t, &[Role::Width], &[], &[]), "width", r, t)?;
        let h = need(r.take(t, &[Role::Height], &[], &[]), "height", r, t)?;
        let tw = piece(r, t, "wall", &[Role::Thickness]).or_else(|| r.take(t, &[Role::Thickness], &[], &["base"]));
        let tw = need(tw, "wall thickness", r, t)?;
        let tb = piece(r, t, "base", &[Role::Thickness]).unwrap_or(tw);
        (w, h, tw, tb)
    };
    if 2.0 * tw >= w || tb >= h {
        return Err(Refusal::new(r.quote_element(t), "its walls do not fit its width and height"));
    }
    let (y, z) = (w / 2.0, h / 2.0);
    let pts =
        vec![[-y, -z], [y, -z], [y, z], [y - tw, z], [y - tw, -z + tb], [-y + tw, -z + tb], [-y + tw, z], [-y, z]];
    let b = extrude(r, t, pts, len, axis);
    r.built[t] = Some(b);
    r.mark_element(t);
    mark_open_words(r);
    Ok(())
}

/// "open on top and open on both ends": what a channel or tube is anyway.
fn mark_open_words(r: &mut Reader<'_>) {
    let d = r.doc;
    for i in 0..d.len() {
        if d.is(i, "open") {
            d.mark(i);
            for j in i + 1..(i + 5).min(d.len()) {
                if matches!(d.word(j), Some("top" | "end" | "both" | "on" | "along" | "x" | "y" | "z")) {
                    d.mark(j);
                } else {
                    break;
                }
            }
        }
    }
}

fn rect_tube(r: &mut Reader<'_>, t: usize) -> Res<()> {
    let (len, axis) = length(r, t)?;
    let w =
        need(r.take(t, &[Role::Width], &[], &[]).or_else(|| r.take(t, &[Role::Bare], &["outer"], &[])), "width", r, t)?;
    let h = need(r.take(t, &[Role::Height], &[], &[]).or_else(|| r.take(t, &[Role::Bare], &[], &[])), "height", r, t)?;
    let wall = need(r.take(t, &[Role::Thickness], &[], &[]), "wall thickness", r, t)?;
    if 2.0 * wall >= w.min(h) {
        return Err(Refusal::new(r.quote_element(t), "its walls do not fit its cross-section"));
    }
    let from = if r.centered { -len / 2.0 } else { 0.0 };
    let outer = r.model.adds.len();
    r.model.adds.push(Body::new(
        "tube",
        Shape::Prism { profile: Profile::Rect { w, h }, axis, at: [0.0, 0.0], rot: 0.0, from, to: from + len },
    ));
    r.model.cuts.push(Body::new(
        "tube bore",
        Shape::Prism {
            profile: Profile::Rect { w: w - 2.0 * wall, h: h - 2.0 * wall },
            axis,
            at: [0.0, 0.0],
            rot: 0.0,
            from,
            to: from + len,
        },
    ));
    r.built[t] = Some(Built {
        axis,
        span: [from, from + len],
        at: vec![[0.0, 0.0]],
        od: None,
        id: None,
        size: Some([w, h]),
        bodies: vec![outer],
        cut: false,
    });
    r.mark_element(t);
    mark_open_words(r);
    // "on all four sides".
    for i in 0..r.doc.len() {
        if r.doc.is(i, "side") && r.doc.word(i.wrapping_sub(1)).is_some_and(|w| w == "four" || w == "all") {
            r.doc.mark_range(i.saturating_sub(3), i + 1);
        }
    }
    Ok(())
}

/// An L of a wall and a base, each given as a box: the base runs from the inside corner
/// along +Y, the wall stands behind the corner (at −Y of it) and rises along +Z.
/// An angle section by its legs and thickness ("equal angle 50 x 50 x 6, 1 m length",
/// "60 by 40 legs, 6 mm thick, 250 long", "3 in and 2 in legs, 1/4 in plate, 2 in wide"):
/// the L of two legs (outside sizes) and its thickness, extruded along its length.
fn angle(r: &mut Reader<'_>, t: usize) -> Res<bool> {
    let dims = r.free_dims(t);
    let list: Vec<usize> =
        dims.iter().copied().filter(|k| r.dim(*k).list.is_some() && r.dim(*k).role == Role::Bare).collect();
    let legs: Vec<usize> = dims.iter().copied().filter(|k| r.dim(*k).has("leg") && !list.contains(k)).collect();
    let (a, b, mut th) = match (list.as_slice(), legs.as_slice()) {
        ([a, b, c], _) => (*a, *b, Some(r.dim(*c).mm)),
        ([a, b], _) => (*a, *b, None),
        ([], [a, b]) => (*a, *b, None),
        _ => return Ok(false),
    };
    let (la, lb) = (r.dim(a).mm, r.dim(b).mm);
    if th.is_none() {
        th = r.take(t, &[Role::Thickness], &[], &["wall"]);
    } else if let [_, _, c] = list.as_slice() {
        r.used_dims[*c] = true;
    }
    let th = need(th, "thickness", r, t)?;
    let len = r.take(t, &[Role::Length], &[], &[]).or_else(|| r.take(t, &[Role::Width], &[], &[]));
    let len = need(len, "length", r, t)?;
    if th >= la.min(lb) {
        return Err(Refusal::new(r.quote_element(t), "its thickness does not fit its legs"));
    }
    r.used_dims[a] = true;
    r.used_dims[b] = true;
    let pts = vec![[0.0, 0.0], [la, 0.0], [la, th], [th, th], [th, lb], [0.0, lb]];
    let bi = r.model.adds.len();
    r.model.adds.push(Body::new(
        "angle",
        Shape::Prism { profile: Profile::Poly(pts), axis: Axis::Z, at: [0.0, 0.0], rot: 0.0, from: 0.0, to: len },
    ));
    r.known.extend([th, la - th, lb - th]);
    r.built[t] = Some(Built {
        axis: Axis::Z,
        span: [0.0, len],
        at: vec![[0.0, 0.0]],
        od: None,
        id: None,
        size: Some([la, lb]),
        bodies: vec![bi],
        cut: false,
    });
    r.mark_element(t);
    mark_pieces(r, &["leg", "plate"]);
    for i in 0..r.doc.len() {
        if matches!(r.doc.word(i), Some("leg" | "outside" | "equal" | "unequal" | "each")) {
            r.doc.mark(i);
        }
    }
    Ok(true)
}

fn l_bracket(r: &mut Reader<'_>, t: usize) -> Res<()> {
    if angle(r, t)? {
        return Ok(());
    }
    let walls = r.elements_named("wall");
    let bases = r.elements_named("base");
    let (Some(&wl), Some(&bs)) = (walls.first(), bases.first()) else {
        // Its pieces are described as bodies with coordinates (read as bodies).
        r.mark_element(t);
        return Ok(());
    };
    // The pieces must be plain boxes given by their sizes (not coordinates of their own).
    let plain =
        |r: &Reader<'_>, e: usize| r.els[e].ranges.is_empty() && r.els[e].coords.is_empty() && r.els[e].noun != "plate";
    if !plain(r, wl) || !plain(r, bs) {
        r.mark_element(t);
        return Ok(());
    }
    let wall_h = need(r.take(wl, &[Role::Height], &[], &[]), "wall height", r, wl)?;
    let wall_w = need(r.take(wl, &[Role::Width, Role::Length], &[], &[]), "wall width", r, wl)?;
    let wall_t = need(r.take(wl, &[Role::Thickness], &[], &[]), "wall thickness", r, wl)?;
    let base_d = need(r.take(bs, &[Role::Depth, Role::Length], &[], &[]), "base depth", r, bs)?;
    let base_w = need(r.take(bs, &[Role::Width], &[], &[]), "base width", r, bs)?;
    let base_t = need(r.take(bs, &[Role::Thickness], &[], &[]), "base thickness", r, bs)?;
    if (wall_w - base_w).abs() > 1e-9 {
        return Err(Refusal::new(
            r.quote_element(bs),
            format!("the base is {base_w} mm wide and the wall {wall_w} mm: an L of two widths"),
        ));
    }
    let x = wall_w;
    let base = r.model.adds.len();
    r.model.adds.push(Body::new(
        "base",
        Shape::Prism {
            profile: Profile::Rect { w: x, h: base_d },
            axis: Axis::Z,
            at: [0.0, base_d / 2.0],
            rot: 0.0,
            from: 0.0,
            to: base_t,
        },
    ));
    let wall = r.model.adds.len();
    r.model.adds.push(Body::new(
        "wall",
        Shape::Prism {
            profile: Profile::Rect { w: x, h: wall_t },
            axis: Axis::Z,
            at: [0.0, -wall_t / 2.0],
            rot: 0.0,
            from: 0.0,
            to: wall_h,
        },
    ));
    r.built[bs] = Some(Built {
        axis: Axis::Z,
        span: [0.0, base_t],
        at: vec![[0.0, base_d / 2.0]],
        od: None,
        id: None,
        size: Some([x, base_d]),
        bodies: vec![base],
        cut: false,
    });
    r.built[wl] = Some(Built {
        axis: Axis::Z,
        span: [0.0, wall_h],
        at: vec![[0.0, -wall_t / 2.0]],
        od: None,
        id: None,
        size: Some([x, wall_t]),
        bodies: vec![wall],
        cut: false,
    });
    r.mark_element(t);
    r.mark_element(wl);
    r.mark_element(bs);
    // "The inside corner of the L is at the origin, … extending along +Y … rising along +Z".
    let d = r.doc;
    for i in 0..d.len() {
        if d.is(i, "corner") && d.word(i.wrapping_sub(1)) == Some("inside") {
            d.mark_range(i - 1, i + 1);
            if d.is(i + 1, "of") && d.is(i + 3, "l") {
                d.mark_range(i + 1, i + 4);
            }
        }
    }
    Ok(())
}
