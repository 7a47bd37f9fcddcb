//! Where things go: the part's frame ("centered at the origin", "standing upright along
//! Z"), and the copies of a body or a cut — explicit points ("at (X=+25, Y=20)",
//! "(±60, 0) and (0, ±60)"), corners inset from the edges, rectangular patterns, pitch
//! circles at given or equal angles, grids with spacings, and rows at intervals.

use super::super::doc::Role;
use super::super::solid::Axis;
use super::{Reader, Refusal, Res};

/// Words that name the shape of a section ("an equilateral triangle cross-section").
const SECTION_WORDS: &[&str] = &[
    "triangle",
    "rectangle",
    "square",
    "circle",
    "hexagon",
    "octagon",
    "pentagon",
    "polygon",
    "star",
    "u-shaped",
    "t-shaped",
    "l-shaped",
    "z-shaped",
    "i-shaped",
    "semicircular",
    "circular",
    "rectangular",
    "hexagonal",
    "triangular",
    "annular",
    "equilateral",
    "right",
    "rounded-rectangle",
    "star-polygon",
    "tooth",
    "v-shaped",
    "t",
    "i",
    "l",
    "u",
    "z",
    "c",
    "h",
    "shaped",
    "outer",
    "inner",
];

/// Reads the words that orient the whole part, describe its section in words, or
/// compare it with something ("resembling a hockey puck").
pub fn read_frame(r: &mut Reader<'_>) {
    let d = r.doc;
    for i in 0..d.len() {
        // "… cross-section", "… profile": the section's name words before it.
        if matches!(d.word(i), Some("cross-section" | "profile" | "outline" | "polygon")) {
            d.mark(i);
            let mut j = i;
            while j > 0 && d.word(j - 1).is_some_and(|w| SECTION_WORDS.contains(&w)) {
                j -= 1;
                d.mark(j);
            }
        }
        // "resembling a hockey puck", "shaped like a coin": a likeness, up to the clause's end.
        if matches!(d.word(i), Some("resembling" | "like")) {
            let mut j = i;
            while j < d.len()
                && !(d.toks[j].kind == super::super::text::Tk::Sym(',')
                    || d.toks[j].kind == super::super::text::Tk::Sym('.'))
            {
                d.mark(j);
                j += 1;
            }
        }
        // "extruded in the +Z direction", "thickness extruded along +Z": the default.
        if d.is(i, "extruded") && d.word(i + 1).is_some_and(|w| w == "in" || w == "along") {
            let end = (i + 1..(i + 6).min(d.len())).find(|j| d.is(*j, "direction") || d.is(*j, "axis"));
            if let Some(end) = end {
                d.mark_range(i, end + 1);
            }
        }
        // "viewed from the side in the XZ plane": a point of view.
        if d.is(i, "viewed") || d.is(i, "seen") {
            let end = (i + 1..(i + 4).min(d.len()))
                .find(|j| matches!(d.word(*j), Some("side" | "front" | "top" | "above" | "end")));
            if let Some(end) = end {
                d.mark_range(i, end + 1);
            }
        }
        // "creating two parallel prongs", "giving the container a smooth rounded-rectangle
        // cross-section", "forming flange ears": what the words before make, restated (their
        // numbers are still checked against the part).
        if matches!(d.word(i), Some("creating" | "forming" | "giving" | "producing" | "leaving" | "resulting")) {
            let mut j = i;
            while j < d.len() && !(d.sym(j, ',') || d.sym(j, '.') || d.sym(j, ';') || d.sym(j, ')')) {
                if !matches!(d.toks[j].kind, super::super::text::Tk::Num { .. }) {
                    d.mark(j);
                }
                j += 1;
            }
        }
        // "in a plus (+) configuration", "an H-frame configuration": the layout's name.
        if d.is(i, "configuration") || d.is(i, "layout") {
            let mut j = i;
            while j > 0
                && (d
                    .word(j - 1)
                    .is_some_and(|w| matches!(w, "plus" | "x" | "h" | "h-frame" | "cross" | "star" | "y" | "t"))
                    || d.sym(j - 1, '(')
                    || d.sym(j - 1, ')')
                    || d.sym(j - 1, '+')
                    || d.sym(j - 1, 'x'))
            {
                j -= 1;
                d.mark(j);
            }
        }
        // "standing upright on its end", "stood on end", "lying on its side": how the part
        // rests, which its extents do not depend on.
        if matches!(
            d.word(i),
            Some(
                "standing" | "stood" | "stands" | "stand" | "upright" | "lying" | "lies" | "laid" | "resting" | "rests"
            )
        ) {
            let mut j = i + 1;
            if matches!(d.word(j), Some("upright" | "up" | "vertically" | "flat")) {
                j += 1;
            }
            if d.is(j, "on") {
                let k = if matches!(d.word(j + 1), Some("its" | "one" | "an" | "the")) { j + 2 } else { j + 1 };
                if matches!(d.word(k), Some("end" | "side" | "base" | "face" | "edge")) {
                    d.mark_range(i, k + 1);
                }
            }
        }
        // "CHANNEL … U-SECTION": the section's letter said again of a section body.
        if matches!(d.word(i), Some("u-section" | "c-section" | "l-section" | "t-section" | "i-section" | "h-section"))
            && r.els.iter().any(|e| {
                matches!(e.kind, super::super::lexicon::Noun::Body(super::super::lexicon::ShapeHint::Section(_)))
            })
        {
            d.mark(i);
        }
        // "centroid at the origin".
        if d.is(i, "centroid") && d.is(i + 1, "at") {
            let end = (i + 1..(i + 4).min(d.len())).find(|j| d.is(*j, "origin"));
            if let Some(end) = end {
                d.mark_range(i, end + 1);
            }
        }
        // "centered at the origin", "centred on the origin".
        if (d.is(i, "centered") || d.is(i, "center")) && (i + 3 < d.len()) {
            let end = (i + 1..(i + 4).min(d.len())).find(|j| d.is(*j, "origin"));
            if let Some(end) = end {
                r.centered = true;
                d.mark_range(i, end + 1);
            }
        }
    }
}

/// A count of copies: the element's count, else 1.
pub fn count_of(r: &Reader<'_>, e: usize) -> u32 {
    r.els[e].count.unwrap_or(1)
}

/// Angles given for an element (degrees), marked read.
pub fn take_angles(r: &mut Reader<'_>, e: usize) -> Vec<f64> {
    let a: Vec<(usize, f64)> = r.els[e].angles.iter().copied().filter(|(t, _)| !r.used_angles.contains(t)).collect();
    // A single "45-degree" before a noun is a chamfer or bend angle, not a position.
    a.into_iter()
        .map(|(t, v)| {
            r.used_angles.insert(t);
            r.doc.mark(t);
            v
        })
        .collect()
}

/// Explicit points from the element's tuples and coordinates, in the plane of `axis`:
/// "(±60, 0) and (0, ±60)", "(X=+25, Y=20)", "(+/-27, +/-17)".
pub fn points(r: &mut Reader<'_>, e: usize, axis: Axis) -> Res<Vec<[f64; 2]>> {
    let (u, v) = axis.uv();
    let mut out: Vec<[f64; 2]> = Vec::new();
    let tuples: Vec<usize> = r.els[e].tuples.iter().copied().filter(|k| !r.used_tuples[*k]).collect();
    for k in tuples {
        let t = r.doc.tuples[k].clone();
        if t.vals.len() != 2 {
            continue;
        }
        // Named axes map to (u, v); unnamed ones are in the plane's order (X, Y for Z).
        let mut pair = [None, None];
        let mut unnamed = Vec::new();
        for (a, val, pm) in &t.vals {
            match a {
                Some(a) if *a == u => pair[0] = Some((*val, *pm)),
                Some(a) if *a == v => pair[1] = Some((*val, *pm)),
                Some(a) => {
                    return Err(Refusal::new(
                        r.doc.quote(t.toks.0, t.toks.1 - 1),
                        format!(
                            "a point given in {} where the feature is placed in {}{}",
                            a.name(),
                            u.name(),
                            v.name()
                        ),
                    ));
                }
                None => unnamed.push((*val, *pm)),
            }
        }
        let (a, b) = match (pair, unnamed.as_slice()) {
            ([Some(a), Some(b)], []) => (a, b),
            ([None, None], [a, b]) => {
                // Unnamed pairs are (X, Y) on a horizontal face; mapped to (u, v) of Z.
                if axis == Axis::Z { (*a, *b) } else { continue }
            }
            _ => continue,
        };
        r.used_tuples[k] = true;
        r.doc.mark_range(t.toks.0, t.toks.1);
        let us: Vec<f64> = if a.1 { vec![a.0, -a.0] } else { vec![a.0] };
        let vs: Vec<f64> = if b.1 { vec![b.0, -b.0] } else { vec![b.0] };
        for x in &us {
            for y in &vs {
                if !out.iter().any(|p| (p[0] - x).abs() < 1e-9 && (p[1] - y).abs() < 1e-9) {
                    out.push([*x, *y]);
                }
            }
        }
    }
    // "at X=20", "centered at Y=-30 mm … at Y=+30 mm", "at X = -24, -12, 0, 12, 24mm":
    // coordinates (the other in-plane one 0, or the one given once).
    if out.is_empty() {
        let mut us = Vec::new();
        while let Some(c) = r.take_coord(e, u) {
            us.push(c);
        }
        let mut vs = Vec::new();
        while let Some(c) = r.take_coord(e, v) {
            vs.push(c);
        }
        match (us.len(), vs.len()) {
            (0, 0) => {}
            (_, 0 | 1) => {
                let y = vs.first().copied().unwrap_or(0.0);
                let us = if us.is_empty() { vec![0.0] } else { us };
                out.extend(us.iter().map(|x| [*x, y]));
            }
            (0 | 1, _) => {
                let x = us.first().copied().unwrap_or(0.0);
                out.extend(vs.iter().map(|y| [x, *y]));
            }
            (a, b) if a == b => out.extend(us.iter().zip(&vs).map(|(x, y)| [*x, *y])),
            _ => {
                return Err(Refusal::new(r.quote_element(e), "its coordinates do not pair up into points"));
            }
        }
    }
    // Coordinate lists "centered at X = -24, -12, 0, 12, 24mm".
    Ok(out)
}

/// Copies on a pitch circle: "on a 45mm pitch circle diameter", "on a 40mm bolt circle",
/// "equally spaced", "at 0, 60, 120 … degrees".
pub fn circle(r: &mut Reader<'_>, e: usize, count: u32) -> Option<Vec<[f64; 2]>> {
    let k = r
        .find(e, &[Role::Diameter, Role::Radius], &["pitch"], &[])
        .or_else(|| r.find(e, &[Role::Diameter, Role::Radius], &["circle"], &[]))
        .or_else(|| r.find(e, &[Role::Diameter, Role::Radius], &["bolt"], &["hole"]))?;
    let d = &r.doc.dims[k];
    let pcd = if d.role == Role::Radius { 2.0 * d.mm } else { d.mm };
    // The angles given, when there are as many as copies; none given, equal spacing from 0;
    // another number of them is not a circle of these copies (left to be refused).
    let given = r.els[e].angles.iter().filter(|(t, _)| !r.used_angles.contains(t)).count();
    let angles = if given == count as usize {
        take_angles(r, e)
    } else if given == 0 {
        (0..count).map(|i| 360.0 * f64::from(i) / f64::from(count)).collect()
    } else {
        return None;
    };
    r.used_dims[k] = true;
    Some(angles.iter().map(|a| [pcd / 2.0 * a.to_radians().cos(), pcd / 2.0 * a.to_radians().sin()]).collect())
}

/// Four copies at the corners of a `size` rectangle (centred), `inset` from its edges.
pub fn corners(r: &mut Reader<'_>, e: usize, size: [f64; 2]) -> Option<Vec<[f64; 2]>> {
    let k = r.find(e, &[Role::Inset], &[], &[])?;
    let i = r.doc.dims[k].mm;
    r.used_dims[k] = true;
    let (x, y) = (size[0] / 2.0 - i, size[1] / 2.0 - i);
    for (a, b) in r.sentences_of(e) {
        for j in a..b {
            if matches!(r.doc.word(j), Some("corner" | "edge" | "nearest" | "inset")) {
                r.doc.mark(j);
            }
        }
    }
    Some(vec![[-x, -y], [x, -y], [x, y], [-x, y]])
}

/// "4 x M3 clearance on 31 mm square centres": four copies at the corners of a centred square.
pub fn square_pattern(r: &mut Reader<'_>, e: usize) -> Option<Vec<[f64; 2]>> {
    let k = r.find(e, &[Role::Spacing], &["square"], &[])?;
    let h = r.doc.dims[k].mm / 2.0;
    r.used_dims[k] = true;
    Some(vec![[-h, -h], [h, -h], [h, h], [-h, h]])
}

/// "two holes on the centreline, 15 from each end", "2x Ø8 on CL 20 from ends": two copies
/// on the long centreline of a part of size (u, v), each inset from an end.
pub fn ends(r: &mut Reader<'_>, e: usize, size: [f64; 2]) -> Option<Vec<[f64; 2]>> {
    let said =
        r.sentences_of(e).iter().any(|(a, b)| (*a..*b).any(|i| matches!(r.doc.word(i), Some("end" | "centerline"))));
    if !said {
        return None;
    }
    // From each end, or "35 from ctr" either side of the centre.
    let centred = r.find(e, &[Role::Bare], &["from-center"], &[]);
    let k = r.find(e, &[Role::Inset], &[], &[]).or(centred)?;
    let i = r.doc.dims[k].mm;
    r.used_dims[k] = true;
    for (a, b) in r.sentences_of(e) {
        for j in a..b {
            if matches!(r.doc.word(j), Some("end" | "centerline" | "long" | "on" | "center")) {
                r.doc.mark(j);
            }
        }
    }
    let i = if centred == Some(k) { size[0].max(size[1]) / 2.0 - i } else { i };
    Some(if size[0] >= size[1] {
        vec![[-(size[0] / 2.0 - i), 0.0], [size[0] / 2.0 - i, 0.0]]
    } else {
        vec![[0.0, -(size[1] / 2.0 - i)], [0.0, size[1] / 2.0 - i]]
    })
}

/// "in a 20mm x 20mm square pattern", "in a rectangular pattern 64mm (X) by 34mm (Y)":
/// the four corners of a centred rectangle given by a list of two lengths.
pub fn rect_pattern(r: &mut Reader<'_>, e: usize) -> Option<Vec<[f64; 2]>> {
    let dims = r.free_dims(e);
    let list: Vec<usize> = dims.iter().copied().filter(|k| r.doc.dims[*k].list.is_some()).collect();
    let [a, b] = list.as_slice() else { return None };
    let spacing = [a, b].iter().any(|k| r.doc.dims[**k].role == Role::Spacing || r.doc.dims[**k].has("pattern"));
    let said = spacing
        || r.sentences_of(e).iter().any(|(s, t)| {
            (*s..*t).any(|i| r.doc.is(i, "pattern") || r.doc.is(i, "square") || r.doc.is(i, "rectangle"))
        });
    if !said {
        return None;
    }
    let (x, y) = (r.doc.dims[*a].mm / 2.0, r.doc.dims[*b].mm / 2.0);
    r.used_dims[*a] = true;
    r.used_dims[*b] = true;
    for (s, t) in r.sentences_of(e) {
        for i in s..t {
            if r.doc.is(i, "pattern") || r.doc.is(i, "rectangle") {
                r.doc.mark(i);
                if r.doc.word(i.wrapping_sub(1)).is_some_and(|w| w == "rectangular" || w == "square") {
                    r.doc.mark(i - 1);
                }
            }
        }
    }
    Some(vec![[-x, -y], [x, -y], [x, y], [-x, y]])
}

/// "a 3x2 rectangular array … with 30mm spacing in X and 30mm spacing in Y": a centred
/// grid. Returns the points and marks the words.
pub fn grid(r: &mut Reader<'_>, e: usize) -> Option<Vec<[f64; 2]>> {
    let d = r.doc;
    for (s, t) in r.sentences_of(e) {
        for i in s..t.saturating_sub(2) {
            let (Some((nx, _)), true, Some((ny, _))) = (int_at(r, i), d.sym(i + 1, 'x'), int_at(r, i + 2)) else {
                continue;
            };
            let sx = r.find(e, &[Role::Spacing], &[], &[]).filter(|k| d.dims[*k].axis != Some(Axis::Y));
            let Some(sx) = sx else { continue };
            r.used_dims[sx] = true;
            let sy = r.find(e, &[Role::Spacing], &[], &[]).or_else(|| {
                r.els[e]
                    .dims
                    .iter()
                    .copied()
                    .find(|k| !r.used_dims[*k] && d.dims[*k].axis == Some(Axis::Y) && d.dims[*k].role == Role::Bare)
            });
            let (px, py) = (d.dims[sx].mm, sy.map_or(d.dims[sx].mm, |k| d.dims[k].mm));
            if let Some(k) = sy {
                r.used_dims[k] = true;
            }
            d.mark_range(i, i + 3);
            for j in i + 3..(i + 6).min(t) {
                if d.is(j, "array") || d.is(j, "grid") || d.is(j, "pattern") || d.is(j, "rectangular") {
                    d.mark(j);
                }
            }
            let mut out = Vec::new();
            for a in 0..ny {
                for b in 0..nx {
                    out.push([
                        (f64::from(b) - f64::from(nx - 1) / 2.0) * px,
                        (f64::from(a) - f64::from(ny - 1) / 2.0) * py,
                    ]);
                }
            }
            return Some(out);
        }
    }
    None
}

fn int_at(r: &Reader<'_>, i: usize) -> Option<(u32, usize)> {
    match r.doc.toks.get(i)?.kind {
        super::super::text::Tk::Num { v, unit: None, .. } if v.fract() == 0.0 && (1.0..=100.0).contains(&v) => {
            Some((v as u32, i))
        }
        _ => None,
    }
}

/// "evenly spaced along X at 12mm intervals": `count` copies in a centred row.
pub fn row(r: &mut Reader<'_>, e: usize, count: u32, default_axis: Axis, plane: Axis) -> Option<Vec<[f64; 2]>> {
    let k = r.find(e, &[Role::Spacing], &[], &[])?;
    let d = &r.doc.dims[k];
    let along = d.axis.unwrap_or(default_axis);
    let p = d.mm;
    r.used_dims[k] = true;
    // "a row of 5 holes": the pattern's noun is read with it.
    for (a, b) in r.sentences_of(e) {
        for i in a..b {
            if r.doc.is(i, "row") {
                r.doc.mark(i);
            }
        }
    }
    let (u, v) = plane.uv();
    Some(
        (0..count)
            .map(|i| {
                let off = (f64::from(i) - f64::from(count - 1) / 2.0) * p;
                if along == u {
                    [off, 0.0]
                } else if along == v {
                    [0.0, off]
                } else {
                    [off, 0.0]
                }
            })
            .collect(),
    )
}
