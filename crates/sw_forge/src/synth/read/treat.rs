//! Edge treatments and shells: fillets and chamfers on the edges the words select ("all
//! edges", "the four vertical edges", "all long edges", "both circular edges", "the top
//! edges"), and a body hollowed to a wall with a face removed ("the top face is removed
//! and the body is shelled inward with 2mm wall thickness").

use super::super::doc::Role;
use super::super::lexicon::{Noun, ShapeHint};
use super::super::solid::{Axis, EdgeKind, EdgeOp, Edges, Shape, Shell};
use super::{Reader, Refusal, Res};

/// The body treatments apply to: the part's own (its name's), else the first one made.
fn main_body(r: &Reader<'_>) -> Option<usize> {
    let t = r.els.iter().position(|e| e.title)?;
    r.built[t]
        .as_ref()
        .and_then(|b| b.bodies.first().copied())
        .filter(|_| !r.built[t].as_ref().is_some_and(|b| b.cut))
        .or((!r.model.adds.is_empty()).then_some(0))
}

pub fn read(r: &mut Reader<'_>) -> Res<()> {
    // Fillets and chamfers: their elements ("3mm fillets"), or lengths whose role says so,
    // or a radius in a sentence that rounds edges ("filleted with a 5mm radius").
    let d = r.doc;
    let mut ops: Vec<(usize, EdgeKind, f64, usize)> = Vec::new(); // (dim, kind, size, sentence)
    // Treatments said to be made but named without a size of their own: (element, kind,
    // sentence).
    let mut bare: Vec<(usize, EdgeKind, usize)> = Vec::new();
    for e in 0..r.els.len() {
        let kind = match r.els[e].kind {
            Noun::Fillet => EdgeKind::Fillet,
            Noun::Chamfer => EdgeKind::Chamfer,
            _ => continue,
        };
        let sized = r.free_dims(e).into_iter().find(|k| !d.dims[*k].paren);
        if let Some(k) = sized {
            ops.push((k, kind, d.dims[k].mm, d.sent[d.dims[k].tok]));
            r.used_dims[k] = true;
        } else if let Some(m) = r.els[e].mentions.first() {
            // Not "no chamfers", "without a fillet", nor "the chamfer" said of one sized
            // elsewhere.
            let said_made = r.els[e].mentions.iter().all(|mi| {
                let x = &r.mentions[*mi];
                let negated = x.start > 0 && matches!(d.word(x.start - 1), Some("no" | "without" | "not"));
                !(x.definite || negated)
            });
            if said_made {
                bare.push((e, kind, d.sent[r.mentions[*m].head]));
            }
        }
        r.mark_element(e);
        // A chamfer's "45-degree": the only angle a chamfer of one size has.
        for (t, a) in r.els[e].angles.clone() {
            if (a - 45.0).abs() < 1e-9 {
                r.used_angles.insert(t);
                d.mark(t);
            }
        }
    }
    for k in 0..d.dims.len() {
        if r.used_dims[k] {
            continue;
        }
        let dm = &d.dims[k];
        let s = d.sent[dm.tok];
        let (a, b) = d.sentence(s);
        let rounding = (a..b).any(|i| matches!(d.word(i), Some("filleted" | "rounded" | "fillet" | "radiused")));
        let kind = match dm.role {
            Role::Fillet => Some(EdgeKind::Fillet),
            Role::Chamfer => Some(EdgeKind::Chamfer),
            Role::Radius
                if (a..b).any(|i| matches!(d.word(i), Some("edge" | "corner")))
                    && (rounding || role_on_edges(d, dm)) =>
            {
                Some(EdgeKind::Fillet)
            }
            _ => None,
        };
        if let Some(kind) = kind {
            ops.push((k, kind, dm.mm, s));
            r.used_dims[k] = true;
        }
    }
    // "with a chamfer on both faces": a treatment of a kind no length in the prompt sizes
    // is refused, never left off the part.
    if let Some((e, kind, _)) = bare.iter().find(|(_, kind, _)| !ops.iter().any(|o| o.1 == *kind)) {
        let what = if *kind == EdgeKind::Fillet { "fillet" } else { "chamfer" };
        return Err(Refusal::new(r.quote_element(*e), format!("a {what} is named but no size is given for it")));
    }
    for (k, kind, size, s) in ops {
        let Some(bi) = main_body(r) else { break };
        let edges = select(r, s, bi)?;
        let body = &r.model.adds[bi];
        let bb = body.bounds();
        // Edges along an axis are limited by the sizes across it.
        let thin = (0..3)
            .filter(|i| !matches!(edges, Edges::Parallel(a) if a.index() == *i))
            .map(|i| bb[1][i] - bb[0][i])
            .fold(f64::INFINITY, f64::min);
        if size <= 0.0 || 2.0 * size >= thin {
            return Err(Refusal::new(
                r.quote_dim(k),
                format!("an edge treatment of {size} mm does not fit a body {thin} mm thin"),
            ));
        }
        // Said again ("both ends chamfered, same size, 1 mm"): the same treatment, once; a
        // different size on the same edges contradicts it.
        if let Some(prev) = r.model.adds[bi].edges.iter().find(|o| o.kind == kind && o.edges == edges) {
            if (prev.size - size).abs() > 1e-9 {
                return Err(Refusal::new(
                    r.quote_dim(k),
                    format!("these edges are already treated with {} mm, not {size} mm", prev.size),
                ));
            }
        } else {
            r.model.adds[bi].edges.push(EdgeOp { edges, kind, size });
        }
        let dm = &d.dims[k];
        d.mark_range(dm.phrase.0.min(dm.tok), dm.phrase.1.max(dm.tok + 1));
        // "1 x 45°": a chamfer's 45 degrees, the only angle one size gives.
        if kind == EdgeKind::Chamfer
            && let Some(super::super::text::Tk::Deg(a)) = d.toks.get(dm.tok + 1).map(|t| &t.kind)
            && (a - 45.0).abs() < 1e-9
        {
            r.used_angles.insert(dm.tok + 1);
            d.mark(dm.tok + 1);
        }
    }
    shell(r)
}

/// "a 2 mm radius on both outside edges": a radius said on edges rounds them.
fn role_on_edges(d: &super::super::doc::Doc, dm: &super::super::doc::Dim) -> bool {
    (dm.phrase.1..(dm.phrase.1 + 5).min(d.len())).any(|i| matches!(d.word(i), Some("edge" | "corner")))
}

/// The edges a sentence selects on a body.
fn select(r: &Reader<'_>, s: usize, bi: usize) -> Res<Edges> {
    let d = r.doc;
    let (a, b) = d.sentence(s);
    let has = |w: &str| (a..b).any(|i| d.is(i, w));
    // "on one edge", "on an edge": which one is not said.
    for i in a..b {
        if d.is(i, "edge") {
            let raw = d.text.get(d.toks[i].start..d.toks[i].end).unwrap_or("").to_lowercase();
            let counted = d
                .word(i.wrapping_sub(1))
                .is_some_and(|w| matches!(w, "one" | "two" | "three" | "an" | "a" | "single" | "some"));
            let named = (a..i).any(|j| {
                matches!(
                    d.word(j),
                    Some(
                        "top"
                            | "bottom"
                            | "vertical"
                            | "long"
                            | "circular"
                            | "all"
                            | "four"
                            | "each"
                            | "every"
                            | "outside"
                            | "outer"
                            | "od"
                            | "both"
                    )
                )
            });
            if counted || (raw == "edge" && !named) {
                return Err(Refusal::new(d.quote(i.saturating_sub(2), i), "which edge is not said"));
            }
        }
    }
    let mark = |w: &str| {
        for i in a..b {
            if d.is(i, w) {
                d.mark(i);
            }
        }
    };
    for w in ["edge", "all", "four", "both", "only", "on"] {
        mark(w);
    }
    let round =
        matches!(&r.model.adds[bi].shape, Shape::Prism { profile: super::super::profile::Profile::Circle { .. }, .. });
    // "R10 corners" on a plate: its vertical corners.
    let corners = has("corner") && !round;
    if has("vertical") || corners {
        mark("vertical");
        mark("corner");
        // "with rounded vertical corners" anywhere.
        for i in 0..d.len() {
            if d.is(i, "corner") && d.word(i.wrapping_sub(1)).is_some_and(|w| w == "vertical" || w == "rounded") {
                d.mark_range(i.saturating_sub(2), i + 1);
            }
        }
        return Ok(Edges::Parallel(Axis::Z));
    }
    // "the long edges" (not a length's "long": "Ø20 x 50 lg pin").
    let long_edges = (a..b).any(|i| d.is(i, "long") && (d.is(i + 1, "edge") || d.is(i + 2, "edge")));
    if long_edges && !round {
        mark("long");
        let bb = r.model.adds[bi].bounds();
        let s = [bb[1][0] - bb[0][0], bb[1][1] - bb[0][1], bb[1][2] - bb[0][2]];
        let k = if s[0] >= s[1] && s[0] >= s[2] {
            Axis::X
        } else if s[1] >= s[2] {
            Axis::Y
        } else {
            Axis::Z
        };
        return Ok(Edges::Parallel(k));
    }
    // "at one end": the edges of one end face (either gives the same part).
    let one_end = (a..b.saturating_sub(1)).any(|i| d.is(i, "one") && d.is(i + 1, "end"));
    if one_end {
        for w in ["one", "end", "at"] {
            mark(w);
        }
        let bb = r.model.adds[bi].bounds();
        let s = [bb[1][0] - bb[0][0], bb[1][1] - bb[0][1], bb[1][2] - bb[0][2]];
        let k = if round {
            match &r.model.adds[bi].shape {
                Shape::Prism { axis, .. } => axis.index(),
                _ => 2,
            }
        } else {
            (0..3).max_by(|a, b| s[*a].total_cmp(&s[*b])).unwrap_or(2)
        };
        return Ok(Edges::Face(Axis::ALL[k], true));
    }
    // A bar's end edges: both end faces, across its longest extent.
    if !round && (has("end") || (has("top") && has("bottom"))) {
        for w in ["end", "top", "bottom", "and", "both"] {
            mark(w);
        }
        let bb = r.model.adds[bi].bounds();
        let s = [bb[1][0] - bb[0][0], bb[1][1] - bb[0][1], bb[1][2] - bb[0][2]];
        let k = if has("end") && !(has("top") && has("bottom")) {
            (0..3).max_by(|a, b| s[*a].total_cmp(&s[*b])).unwrap_or(2)
        } else {
            2
        };
        return Ok(Edges::Ends(Axis::ALL[k]));
    }
    // A ring's outer edges are not told apart from its bore's by the circular selector.
    let ring =
        matches!(&r.model.adds[bi].shape, Shape::Prism { profile: super::super::profile::Profile::Annulus { .. }, .. });
    if ring && (has("od") || has("outside") || has("outer")) {
        return Err(Refusal::new(
            d.quote(a, b.saturating_sub(1)),
            "a ring's outside edges alone are not treated (its bore's edges would be too)",
        ));
    }
    if has("circular")
        || has("end")
        || (has("top") && has("bottom"))
        || (round && (has("od") || has("outside") || has("outer") || has("side")))
    {
        for w in ["circular", "end", "top", "bottom", "and", "od", "outside", "outer", "side"] {
            mark(w);
        }
        return Ok(Edges::Circular);
    }
    if has("top") {
        mark("top");
        return Ok(Edges::Face(Axis::Z, true));
    }
    if has("bottom") {
        mark("bottom");
        return Ok(Edges::Face(Axis::Z, false));
    }
    Ok(if round { Edges::Circular } else { Edges::All })
}

/// "shelled inward with 2mm wall thickness", with the face removed ("the top face (+Z)
/// is removed", "open on top").
/// Whether the words hollow the part: "shelled", "hollowed", or a box "open at the top" with
/// its walls' thickness ("3 mm walls and floor").
pub fn hollowed(d: &super::super::doc::Doc) -> Option<usize> {
    (0..d.len()).find(|i| matches!(d.word(*i), Some("shelled" | "shell" | "hollowed"))).or_else(|| {
        let walls = d.dims.iter().any(|x| x.has("wall") && x.role == Role::Thickness);
        (0..d.len()).find(|i| walls && matches!(d.word(*i), Some("open" | "open-top" | "open-topped")))
    })
}

/// Whether the part is a box the words hollow (not a channel or tube, open by its section).
pub fn hollow_box(r: &Reader<'_>) -> Option<usize> {
    let at = hollowed(r.doc)?;
    let named = matches!(r.doc.word(at), Some("shelled" | "shell" | "hollowed"));
    let t = r.els.iter().position(|e| e.title)?;
    (named || matches!(r.shape_of(t), Some(ShapeHint::Rect) | None)).then_some(at)
}

fn shell(r: &mut Reader<'_>) -> Res<()> {
    let d = r.doc;
    let Some(at) = hollow_box(r) else {
        return Ok(());
    };
    let s = d.sent[at];
    let (a, b) = d.sentence(s);
    let k = (0..d.dims.len())
        .find(|k| !r.used_dims[*k] && d.dims[*k].has("wall") && d.dims[*k].role == Role::Thickness)
        .or_else(|| {
            (0..d.dims.len()).find(|k| {
                !r.used_dims[*k]
                    && d.sent[d.dims[*k].tok] == s
                    && matches!(d.dims[*k].role, Role::Thickness | Role::Bare)
            })
        });
    let Some(k) = k else { return Err(Refusal::new(d.quote(at, at), "the shell's wall thickness is not given")) };
    let t = d.dims[k].mm;
    r.used_dims[k] = true;
    d.mark_range(d.dims[k].phrase.0.min(d.dims[k].tok), d.dims[k].phrase.1.max(d.dims[k].tok + 1));
    let Some(bi) = main_body(r) else { return Ok(()) };
    // The open face: the top, unless the words say the bottom.
    let open_top = !(a..b).any(|i| d.is(i, "bottom")) || (a..b).any(|i| d.is(i, "top"));
    let bb = r.model.adds[bi].bounds();
    let thin = (0..3).map(|i| bb[1][i] - bb[0][i]).fold(f64::INFINITY, f64::min);
    if t <= 0.0 || 2.0 * t >= thin {
        return Err(Refusal::new(d.quote(at, at), format!("a {t} mm wall does not fit a body {thin} mm thin")));
    }
    // The walls and the floor are the shell's; a floor of another thickness is not made.
    for name in ["wall", "floor", "side", "base"] {
        for e in r.elements_named(name) {
            if r.built[e].is_some() || r.els[e].title {
                continue;
            }
            for k in r.els[e].dims.clone() {
                let x = &d.dims[k];
                if r.used_dims[k] || !(x.role == Role::Thickness || (x.role == Role::Bare && x.list.is_none())) {
                    continue;
                }
                if (x.mm - t).abs() > 1e-9 {
                    return Err(Refusal::new(
                        r.quote_dim(k),
                        format!("a {name} of {} mm in a shell of {t} mm walls is not made", x.mm),
                    ));
                }
                r.used_dims[k] = true;
            }
            r.mark_element(e);
        }
    }
    r.model.adds[bi].shell = Some(Shell { axis: Axis::Z, max: open_top, t });
    d.mark(at);
    super::bodies::mark_words(r, &["hollow", "shelled", "shell"]);
    // "at the neck opening".
    for i in a..b {
        if d.is(i, "opening") {
            d.mark(i);
            if d.word(i - 1).is_some_and(|w| super::super::lexicon::noun(w).is_some()) {
                d.mark(i - 1);
            }
        }
    }
    for i in 0..d.len() {
        let w = d.word(i).unwrap_or("");
        if matches!(w, "top" | "face" | "removed" | "open" | "open-top" | "inward" | "wall" | "opening" | "neck")
            && d.sent[i] <= s
        {
            // Only the words that say which face is open.
            if matches!(w, "removed" | "open" | "open-top" | "inward")
                || (i + 1 < d.len() && d.is(i + 1, "face"))
                || w == "face"
            {
                d.mark(i);
                if d.is(i + 1, "face") {
                    d.mark(i + 1);
                }
            }
        }
    }
    Ok(())
}
