//! Words that contradict each other or the part they are said of, found by the second
//! reading ([`Takeoff`]) on the words alone, before and apart from the feature program:
//!
//! - one length said twice with two values (a body's length, width, height, thickness,
//!   diameter, inner diameter or wall; a length and its restatement in other units in
//!   parentheses; two lists of sizes for one body);
//! - a shape word the sizes deny (a cube or a *square* bar with unequal sides, a ball given
//!   two diameters or a height, a polygon whose across-flats and across-corners disagree, an
//!   inner diameter not inside the outer, a wall thicker than the radius);
//! - a cut that fits the part in no direction (a hole as wide as the face it is drilled in or
//!   deeper than the part, a pocket or slot longer or wider than the part, a keyway as wide
//!   as the shaft);
//! - a pattern of holes that cannot be laid out (holes that overlap on their pitch circle or
//!   their row, a pitch circle or rectangle of centres whose holes break out of the part or
//!   into its bore, holes closer to an edge than their radius).
//!
//! A cut's room is judged against the box of the one body the words size (a round body by
//! its square box), so a cut refused here fits in no orientation of even that box: nothing
//! the words allow is refused.

use std::f64::consts::PI;

use super::doc::{Dim, QUALS, Role, role_of};
use super::lexicon::{CutKind, Noun, ShapeHint};
use super::num::n;
use super::takeoff::{Disagreement, Solid, Takeoff};

/// Two lengths that differ by more than half a percent.
fn differ(a: f64, b: f64) -> bool {
    (a - b).abs() > 0.005 * a.abs().max(b.abs()) + 1e-6
}

/// A diameter, or twice a radius.
fn as_diameter(x: &Dim) -> f64 {
    if x.role == Role::Radius { 2.0 * x.mm } else { x.mm }
}

/// What a length is of, beyond its role: its qualifying words ("tip", "root", "base",
/// "top", "across flats"), less those that only say it is the outside one.
fn key<'a>(x: &'a Dim, noun: &str) -> Vec<&'a str> {
    let mut k: Vec<&str> = x
        .quals
        .iter()
        .map(String::as_str)
        .filter(|q| *q != noun && !matches!(*q, "outer" | "outside" | "across" | "overall" | "total"))
        .collect();
    k.sort_unstable();
    k
}

/// Words of a pattern: a pitch circle, a spacing, an inset, rows.
fn of_pattern(x: &Dim) -> bool {
    ["pitch", "circle", "pattern", "from-center"].iter().any(|q| x.has(q))
        || matches!(x.role, Role::Spacing | Role::Inset)
}

/// Words of a counterbore or countersink (their own sizes, not the hole's).
fn of_recess(x: &Dim) -> bool {
    x.has("counterbore") || x.has("countersink")
}

impl Takeoff<'_> {
    /// The words that contradict each other, quoted, with what they say.
    pub fn contradictions(&self) -> Result<(), Disagreement> {
        self.restatements()?;
        let bodies: Vec<usize> = (0..self.things.len())
            .filter(|t| matches!(self.things[*t].kind, Noun::Body(_)) && !self.body_dims(*t).is_empty())
            .collect();
        for &t in &bodies {
            self.own_words(t)?;
        }
        // The one sized body the cuts are made in.
        let host = match bodies.as_slice() {
            [b] if self.things[*b].count == Some(1) => self.solid(*b),
            _ => None,
        };
        // The largest round body, for pitch circles on a part of several bodies.
        let round = bodies
            .iter()
            .filter_map(|t| match self.solid(*t)? {
                Solid::Cylinder { d, .. } => Some((d, None)),
                Solid::Ring { od, id, .. } => Some((od, Some(id))),
                _ => None,
            })
            .max_by(|a, b| a.0.total_cmp(&b.0));
        if let [b] = bodies.as_slice()
            && let Some(h) = host
        {
            self.treatments_fit(*b, h)?;
            // "120 overall", "total height 35": of a part of one body, one of its extents.
            let e = h.extents();
            let d = self.doc;
            if let Some((_, x)) = d.dims.iter().enumerate().find(|(k, x)| {
                (x.has("overall") || x.has("total"))
                    && matches!(x.role, Role::Length | Role::Height | Role::Width | Role::Thickness | Role::Bare)
                    && x.restates.is_none()
                    && self.owner[*k].is_none_or(|t| matches!(self.things[t].kind, Noun::Body(_) | Noun::Whole))
                    && !e.iter().any(|v| !differ(*v, x.mm))
            }) {
                return Err(Disagreement {
                    phrase: d.quote(x.phrase.0.min(x.tok), x.phrase.1.max(x.tok + 1) - 1),
                    reason: format!(
                        "{} mm overall is none of the sizes of the {} ({} x {} x {} mm)",
                        n(x.mm),
                        self.things[*b].noun,
                        n(e[2]),
                        n(e[1]),
                        n(e[0])
                    ),
                });
            }
        }
        for t in 0..self.things.len() {
            if let Noun::Cut(kind) = self.things[t].kind {
                if let Some(h) = host {
                    self.cut_fits(t, kind, h)?;
                }
                if kind == CutKind::Hole {
                    self.pattern_fits(t, host, round)?;
                }
            }
        }
        Ok(())
    }

    /// The words of thing `t` and its lengths, for a refusal.
    fn quote_thing(&self, t: usize) -> String {
        let d = self.doc;
        let th = &self.things[t];
        let first = th.dims.iter().map(|k| d.dims[*k].tok).min().unwrap_or(th.phrase.0).min(th.phrase.0);
        let last = th.dims.iter().map(|k| d.dims[*k].phrase.1.max(d.dims[*k].tok + 1) - 1).max().unwrap_or(0);
        d.quote(first, last.max(th.phrase.1))
    }

    /// A length and its restatement in parentheses ("2 in (50 mm)") agree within 2 %.
    fn restatements(&self) -> Result<(), Disagreement> {
        let d = self.doc;
        for x in &d.dims {
            let Some(p) = x.restates else { continue };
            let y = &d.dims[p];
            let comparable = x.role == y.role
                || matches!((x.role, y.role), (Role::Radius, Role::Diameter) | (Role::Diameter, Role::Radius))
                || x.role == Role::Bare
                || y.role == Role::Bare;
            let approx = (y.tok..x.tok).any(|i| {
                d.word(i).is_some_and(|w| {
                    matches!(w, "approximately" | "approx" | "about" | "around" | "nominal" | "roughly")
                })
            });
            let (a, b) = (as_diameter(x), as_diameter(y));
            if comparable && !approx && key(x, "") == key(y, "") && (a - b).abs() > 0.02 * a.max(b) {
                return Err(Disagreement {
                    phrase: d.quote(y.tok, x.phrase.1.max(x.tok + 1)),
                    reason: format!("{} mm and {} mm are given for one length", n(b), n(a)),
                });
            }
        }
        Ok(())
    }

    /// A body's own sizes agree with each other and with its shape words.
    fn own_words(&self, t: usize) -> Result<(), Disagreement> {
        let d = self.doc;
        let th = &self.things[t];
        let dims: Vec<&Dim> = self.body_dims(t).into_iter().map(|k| &d.dims[k]).collect();
        let err = |reason: String| Err(Disagreement { phrase: self.quote_thing(t), reason });
        let hint = match th.kind {
            Noun::Body(h) => th.shape.unwrap_or(h),
            _ => return Ok(()),
        };
        // A body of one section along its length (not a cone, a gear, a profile or a loft,
        // whose diameters and plans differ by design), said to be one.
        let prismatic = matches!(
            hint,
            ShapeHint::Round | ShapeHint::Ring | ShapeHint::Rect | ShapeHint::Ngon(_) | ShapeHint::Sphere
        ) && !(th.phrase.0..=th.phrase.1).any(|i| {
            d.word(i).is_some_and(|w| matches!(w, "frustum" | "truncated" | "tapered" | "cone" | "conical" | "stepped"))
        });
        let single = th.count == Some(1) && prismatic;
        let round = matches!(hint, ShapeHint::Round | ShapeHint::Ring);
        let swept = (0..d.len()).any(|i| {
            d.word(i).is_some_and(|w| {
                matches!(
                    w,
                    "arc" | "bend" | "bent" | "sweep" | "swept" | "sweeping" | "elbow" | "path" | "curve" | "curved"
                )
            })
        });
        // One length, two values.
        type Pick = fn(&Dim) -> bool;
        let groups: [(&str, Pick); 7] = [
            ("length", |x| x.role == Role::Length && !x.has("overall") && !x.has("total")),
            ("width", |x| x.role == Role::Width),
            ("height", |x| x.role == Role::Height && !x.has("overall") && !x.has("total")),
            ("thickness", |x| x.role == Role::Thickness && !x.has("wall")),
            ("wall", |x| x.role == Role::Thickness && x.has("wall")),
            ("diameter", |x| {
                matches!(x.role, Role::Diameter | Role::Radius)
                    && !["inner", "inside", "flat", "corner", "minor", "major"].iter().any(|q| x.has(q))
            }),
            ("inner diameter", |x| {
                matches!(x.role, Role::Diameter | Role::Radius) && (x.has("inner") || x.has("inside"))
            }),
        ];
        if single {
            for (name, pick) in groups {
                if name.contains("diameter") && !round {
                    continue;
                }
                // (Not an edge's radius: "a 2 mm radius on the outside edges".)
                let edge = |x: &Dim| {
                    x.role == Role::Radius
                        && (x.phrase.1..(x.phrase.1 + 3).min(d.len())).any(|i| {
                            d.word(i).is_some_and(|w| matches!(w, "on" | "edge" | "edges" | "corner" | "corners"))
                        })
                };
                // (Nor a length of another thing: "an arc of 40 mm radius".)
                let foreign = |x: &Dim| {
                    (x.phrase.0.saturating_sub(1)..x.tok).any(|i| {
                        i > 0
                            && d.is(i, "of")
                            && d.word(i - 1)
                                .is_some_and(|w| w != th.noun && role_of(w).is_none() && !QUALS.contains(&w))
                    })
                };
                // (Nor a path's radius, where the body is swept along one.)
                let path = |x: &Dim| x.role == Role::Radius && swept;
                let vals: Vec<&Dim> =
                    dims.iter().copied().filter(|x| pick(x) && !edge(x) && !foreign(x) && !path(x)).collect();
                if let Some(w) = vals.iter().skip(1).find(|w| {
                    key(w, &th.noun) == key(vals[0], &th.noun) && differ(as_diameter(w), as_diameter(vals[0]))
                }) {
                    return err(format!(
                        "its {name} is given as both {} and {} mm",
                        n(as_diameter(vals[0])),
                        n(as_diameter(w))
                    ));
                }
            }
            // Two lists of sizes ("1 x 2 x 3 in, 40 x 60 x 80 mm").
            let mut lists: Vec<Vec<f64>> = Vec::new();
            for x in &dims {
                if let Some((id, _)) = x.list {
                    match lists.get_mut(id) {
                        Some(l) => l.push(x.mm),
                        None => {
                            lists.resize(id + 1, Vec::new());
                            lists[id].push(x.mm);
                        }
                    }
                }
            }
            let lists: Vec<Vec<f64>> = lists
                .into_iter()
                .filter(|l| l.len() >= 2)
                .map(|mut l| {
                    l.sort_by(f64::total_cmp);
                    l
                })
                .collect();
            for (i, a) in lists.iter().enumerate() {
                for b in &lists[i + 1..] {
                    if a.len() == 3 && b.len() == 3 && a.iter().zip(b).any(|(x, y)| differ(*x, *y)) {
                        return err(format!("two sets of sizes are given for one {}", th.noun));
                    }
                }
            }
            // A size said by its role that the list of sizes does not have ("70 x 40 x 25
            // … 30 thick"), on a body of three sizes.
            // (Not a section named in the body's phrase, "ANGLE BRACKET 50 x 50 x 5, 30 WIDE":
            // its list is the section's designation and the length is said apart.)
            let section = (th.phrase.0..=th.phrase.1).any(|i| {
                d.word(i).is_some_and(|w| matches!(super::lexicon::noun(w), Some(Noun::Body(ShapeHint::Section(_)))))
            });
            if lists.len() == 1 && lists[0].len() == 3 && matches!(hint, ShapeHint::Rect) && !section {
                let along = [Role::Length, Role::Width, Role::Height, Role::Thickness, Role::Depth];
                if let Some(x) = dims.iter().find(|x| {
                    x.list.is_none()
                        && along.contains(&x.role)
                        && key(x, &th.noun).is_empty()
                        && !lists[0].iter().any(|v| !differ(*v, x.mm))
                }) {
                    return err(format!(
                        "{} mm is none of its sizes {} x {} x {} mm",
                        n(x.mm),
                        n(lists[0][2]),
                        n(lists[0][1]),
                        n(lists[0][0])
                    ));
                }
            }
        }
        // Shape words the sizes deny.
        let said = |w: &str| (th.phrase.0..=th.phrase.1).any(|i| d.is(i, w));
        // "a 40 mm cube that is 30 mm tall": a cube has one size, whatever role says it.
        if single && th.noun == "cube" {
            let extent =
                [Role::Bare, Role::Side, Role::Length, Role::Width, Role::Height, Role::Thickness, Role::Depth];
            let sizes: Vec<&Dim> =
                dims.iter().copied().filter(|x| extent.contains(&x.role) && key(x, &th.noun).is_empty()).collect();
            if let Some(w) = sizes.iter().skip(1).find(|w| differ(w.mm, sizes[0].mm)) {
                let (a, b) = (sizes[0].tok.min(w.tok), sizes[0].phrase.1.max(w.phrase.1));
                return Err(Disagreement {
                    phrase: d.quote(a, b),
                    reason: format!("a cube has equal sides, not {} and {} mm", n(sizes[0].mm), n(w.mm)),
                });
            }
        }
        if single
            && (said("square") || said("sq"))
            && let Some(Solid::Box { x, y, z }) = self.solid(t)
            && differ(x, y)
            && differ(y, z)
            && differ(x, z)
        {
            return err(format!("a square {} has two equal sides, not {} x {} x {} mm", th.noun, n(x), n(y), n(z)));
        }
        let diameters: Vec<f64> =
            dims.iter().filter(|x| matches!(x.role, Role::Diameter | Role::Radius)).map(|x| as_diameter(x)).collect();
        if single && matches!(th.kind, Noun::Body(ShapeHint::Sphere | ShapeHint::Hemisphere)) && !said("hollow") {
            let others = dims.iter().any(|x| matches!(x.role, Role::Height | Role::Length | Role::Width));
            let bare: Vec<f64> = dims.iter().filter(|x| x.role == Role::Bare).map(|x| x.mm).collect();
            let all: Vec<f64> = diameters.iter().chain(bare.iter()).copied().collect();
            if others && !diameters.is_empty() {
                return err("a ball is as tall as it is across".into());
            }
            if let Some(w) = all.iter().skip(1).find(|v| differ(**v, all[0])) {
                return err(format!("a ball has one diameter, not {} and {} mm", n(all[0]), n(*w)));
            }
        }
        // A polygon's across-flats and across-corners.
        if let Some(ShapeHint::Ngon(k)) = th.shape.or(match th.kind {
            Noun::Body(h) => Some(h),
            _ => None,
        }) {
            let flats = dims.iter().find(|x| x.has("flat")).map(|x| x.mm);
            let corners = dims.iter().find(|x| x.has("corner")).map(|x| x.mm);
            if let (Some(f), Some(c)) = (flats, corners) {
                let want = f / (PI / k as f64).cos();
                if (want - c).abs() > 0.01 * want {
                    return err(format!(
                        "a {k}-sided bar {} across the flats is {} across the corners, not {}",
                        n(f),
                        n((want * 1000.0).round() / 1000.0),
                        n(c)
                    ));
                }
            }
        }
        // Inner and outer diameters, walls.
        let outer = dims
            .iter()
            .filter(|x| matches!(x.role, Role::Diameter | Role::Radius))
            .find(|x| !["inner", "inside", "flat", "corner", "minor", "major"].iter().any(|q| x.has(q)))
            .map(|x| as_diameter(x));
        let inner = dims
            .iter()
            .filter(|x| matches!(x.role, Role::Diameter | Role::Radius))
            .find(|x| x.has("inner") || x.has("inside"))
            .map(|x| as_diameter(x));
        let wall = dims.iter().find(|x| x.role == Role::Thickness && x.has("wall")).map(|x| x.mm);
        if let (Some(o), Some(i)) = (outer, inner)
            && i >= o * 0.995
        {
            return err(format!("its inside ({} mm) is not inside its outside ({} mm)", n(i), n(o)));
        }
        if let (Some(o), Some(i), Some(w)) = (outer, inner, wall)
            && differ(o - 2.0 * w, i)
        {
            return err(format!("a {} mm wall makes the inside {} mm, not {} mm", n(w), n(o - 2.0 * w), n(i)));
        }
        if let (Some(o), Some(w)) = (outer, wall)
            && 2.0 * w >= o * 0.995
        {
            return err(format!("a {} mm wall leaves no inside in {} mm across", n(w), n(o)));
        }
        Ok(())
    }

    /// A rounding or chamfer of the body's edges is smaller than the faces beside them: a
    /// box's edges have faces at most its middle extent wide, and a pair of them on a face
    /// meet at half of it; a round body's end edges are as deep as its radius, a ring's as its
    /// wall.
    fn treatments_fit(&self, b: usize, host: Solid) -> Result<(), Disagreement> {
        let d = self.doc;
        let owned = |t: usize| t == b || matches!(self.things[t].kind, Noun::Fillet | Noun::Chamfer);
        let Some((_, x)) = d.dims.iter().enumerate().find(|(k, x)| {
            matches!(x.role, Role::Fillet | Role::Chamfer)
                && x.restates.is_none()
                && self.owner[*k].is_some_and(owned)
                && {
                    // "all edges": a pair on the thinnest face meets at half of it.
                    let sent = d.sent[x.tok];
                    let all = (0..d.len()).any(|i| d.sent[i] == sent && (d.is(i, "all") || d.is(i, "every")));
                    let room = match host {
                        Solid::Cylinder { d: dia, l } => (dia / 2.0).min(l),
                        Solid::Ring { od, id, l } => ((od - id) / 2.0).min(l),
                        Solid::Ball { .. } | Solid::Dome { .. } => f64::INFINITY,
                        Solid::Box { .. } => host.extents()[usize::from(!all)] / 2.0,
                    };
                    x.mm > room * 1.005
                }
        }) else {
            return Ok(());
        };
        let e = host.extents();
        Err(Disagreement {
            // ("6x45°": the angle too.)
            phrase: d.quote(
                x.phrase.0.min(x.tok),
                (x.phrase.1.max(x.tok + 1) - 1).max(
                    (x.tok + 1..(x.tok + 3).min(d.len()))
                        .find(|i| matches!(d.toks[*i].kind, super::text::Tk::Deg(_)))
                        .unwrap_or(0),
                ),
            ),
            reason: format!(
                "an edge treatment of {} mm does not fit the edges of a {} x {} x {} mm part",
                n(x.mm),
                n(e[2]),
                n(e[1]),
                n(e[0])
            ),
        })
    }

    /// A cut fits the host body in some direction: its section inside the face it enters,
    /// its depth inside the length it goes along.
    fn cut_fits(&self, t: usize, kind: CutKind, host: Solid) -> Result<(), Disagreement> {
        let d = self.doc;
        let dims: Vec<&Dim> =
            self.things[t].dims.iter().map(|k| &d.dims[*k]).filter(|x| !of_pattern(x) && !of_recess(x)).collect();
        let depth = dims.iter().filter(|x| x.role == Role::Depth).map(|x| x.mm).fold(0.0, f64::max);
        let dia = dims
            .iter()
            .filter(|x| matches!(x.role, Role::Diameter | Role::Radius))
            .map(|x| as_diameter(x))
            .fold(0.0, f64::max);
        let mut plan: Vec<f64> = dims
            .iter()
            .filter(|x| matches!(x.role, Role::Bare | Role::Length | Role::Width | Role::Side))
            .map(|x| x.mm)
            .collect();
        plan.sort_by(|a, b| b.total_cmp(a));
        // Its section (largest, smallest).
        // A hole's size said bare ("a 40 mm hole") is its diameter.
        let (dia, plan) = match (kind, dia > 0.0, plan.as_slice()) {
            (CutKind::Hole | CutKind::Bore, false, [x]) => (*x, Vec::new()),
            _ => (dia, plan),
        };
        let section = match kind {
            CutKind::Hole | CutKind::Bore if dia > 0.0 && plan.is_empty() => (dia, dia),
            CutKind::Slot | CutKind::Pocket if plan.len() >= 2 => (plan[0], plan[1]),
            CutKind::Slot | CutKind::Pocket if plan.len() == 1 && dia > 0.0 => (plan[0].max(dia), plan[0].min(dia)),
            CutKind::Keyway if dims.iter().any(|x| x.role == Role::Width) => {
                let w = dims.iter().find(|x| x.role == Role::Width).map_or(0.0, |x| x.mm);
                (w, w)
            }
            _ => return Ok(()),
        };
        let mut e = host.extents();
        e.sort_by(f64::total_cmp);
        let fits = (0..3).any(|a| {
            let mut face: Vec<f64> = (0..3).filter(|b| *b != a).map(|b| e[b]).collect();
            face.sort_by(|x, y| y.total_cmp(x));
            let room = section.0 <= face[0] * 1.005 && section.1 < face[1] * 0.995;
            room && depth <= e[a] * 1.005
        });
        if fits {
            return Ok(());
        }
        let what = if depth > e[2] * 1.005 {
            format!("{} mm deep is deeper than the part is long ({} mm)", n(depth), n(e[2]))
        } else {
            format!(
                "a cut {} x {} mm does not fit in any face of a {} x {} x {} mm part",
                n(section.0),
                n(section.1),
                n(e[2]),
                n(e[1]),
                n(e[0])
            )
        };
        Err(Disagreement { phrase: self.quote_thing(t), reason: what })
    }

    /// A pattern of holes can be laid out on the part: on its pitch circle, its row or its
    /// rectangle of centres, clear of each other, of the part's edges and of its bore.
    fn pattern_fits(
        &self,
        t: usize,
        host: Option<Solid>,
        round: Option<(f64, Option<f64>)>,
    ) -> Result<(), Disagreement> {
        let d = self.doc;
        let th = &self.things[t];
        let own: Vec<&Dim> = th.dims.iter().map(|k| &d.dims[*k]).collect();
        let free = |x: &&&Dim| !of_pattern(x) && !of_recess(x) && x.restates.is_none() && x.list.is_none();
        let dias: Vec<f64> = own
            .iter()
            .filter(free)
            .filter(|x| matches!(x.role, Role::Diameter | Role::Radius))
            .map(|x| as_diameter(x))
            .collect();
        let bare: Vec<f64> = own.iter().filter(free).filter(|x| x.role == Role::Bare).map(|x| x.mm).collect();
        let hole = match (dias.as_slice(), bare.as_slice()) {
            ([h], _) => *h,
            ([], [h]) => *h,
            _ => return Ok(()),
        };
        // Its count, also when written as a bare number before it ("7 holes").
        let count = th.count.unwrap_or_else(|| {
            (th.phrase.0..th.phrase.1)
                .find_map(|i| match d.toks[i].kind {
                    super::text::Tk::Num { v, unit: None, .. } if v.fract() == 0.0 && (1.0..=1000.0).contains(&v) => {
                        Some(v as u32)
                    }
                    _ => None,
                })
                .unwrap_or(1)
        });
        let err = |reason: String| Err(Disagreement { phrase: self.quote_thing(t), reason });
        // The pitch circle said with these holes: their own, else the next one after them in
        // their sentence.
        let sent = d.sent[th.phrase.1];
        let pcd = own
            .iter()
            .copied()
            .chain(d.dims.iter().filter(|x| x.tok > th.phrase.1 && d.sent[x.tok] == sent))
            .find(|x| {
                matches!(x.role, Role::Diameter | Role::Radius | Role::Bare)
                    && (x.has("pitch") || x.has("circle"))
                    && !x.has("from-center")
                    && x.restates.is_none()
            })
            .map(as_diameter);
        let mut e = host.map(|h| h.extents());
        if let Some(e) = e.as_mut() {
            e.sort_by(|a, b| b.total_cmp(a));
        }
        if let Some(p) = pcd {
            if count >= 2 && p * (PI / f64::from(count)).sin() <= hole * 1.005 {
                return err(format!("{count} holes of {} mm overlap on a {} mm circle", n(hole), n(p)));
            }
            let outside = match (host, round) {
                (Some(Solid::Cylinder { d: od, .. } | Solid::Ring { od, .. }), _) => Some(od),
                (Some(_), _) => e.map(|e| e[1]),
                (None, Some((od, _))) => Some(od),
                _ => None,
            };
            if let Some(o) = outside
                && p + hole > o * 1.005
            {
                return err(format!(
                    "holes of {} mm on a {} mm circle reach {} mm across, outside the part's {} mm",
                    n(hole),
                    n(p),
                    n(p + hole),
                    n(o)
                ));
            }
            // The bore they surround: the part's inside, or a bore named with it.
            let bore = match host {
                Some(Solid::Ring { id, .. }) => Some(id),
                _ => (0..self.things.len())
                    .filter(|b| self.things[*b].kind == Noun::Cut(CutKind::Bore) && self.things[*b].count == Some(1))
                    .filter_map(|b| {
                        self.things[b]
                            .dims
                            .iter()
                            .map(|k| &d.dims[*k])
                            .find(|x| matches!(x.role, Role::Diameter | Role::Radius) && !of_pattern(x))
                            .map(as_diameter)
                    })
                    .next()
                    .or(round.and_then(|r| r.1)),
            };
            if let Some(b) = bore
                && p - hole < b * 0.995
            {
                return err(format!("holes of {} mm on a {} mm circle break into the {} mm bore", n(hole), n(p), n(b)));
            }
            return Ok(());
        }
        // Rows and rectangles of centres.
        let spacing: Vec<f64> =
            own.iter().filter(|x| x.role == Role::Spacing || x.has("pitch")).map(|x| x.mm).collect();
        let listed: Vec<f64> = own.iter().filter(|x| x.has("pattern") && x.list.is_some()).map(|x| x.mm).collect();
        if listed.len() == 2
            && let Some(e) = e
        {
            let (a, b) = (listed[0].max(listed[1]), listed[0].min(listed[1]));
            if a + hole > e[0] * 1.005 || b + hole > e[1] * 1.005 {
                return err(format!(
                    "holes of {} mm on {} x {} mm centres break out of a {} x {} mm face",
                    n(hole),
                    n(a),
                    n(b),
                    n(e[0]),
                    n(e[1])
                ));
            }
        } else if let [s] = spacing.as_slice() {
            if count >= 2 && *s <= hole * 1.005 {
                return err(format!("holes of {} mm at {} mm pitch overlap", n(hole), n(*s)));
            }
            let text = d.text.to_lowercase();
            let rows = text.contains("rows") || text.contains(" per ");
            if let Some(e) = e
                && !rows
                && count >= 2
                && f64::from(count - 1) * s + hole > e[0] * 1.005
            {
                return err(format!(
                    "{count} holes of {} mm at {} mm pitch span {} mm, longer than the part's {} mm",
                    n(hole),
                    n(*s),
                    n(f64::from(count - 1) * s + hole),
                    n(e[0])
                ));
            }
        }
        // Holes placed from the edges.
        if let Some(i) = own.iter().find(|x| x.role == Role::Inset)
            && i.mm < hole / 2.0 * 0.995
        {
            return err(format!("a {} mm hole {} mm from an edge breaks out of it", n(hole), n(i.mm)));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::{SynthError, synthesize};

    /// Refused, quoting words that include `words`.
    fn refused(prompt: &str, words: &str) {
        match synthesize(prompt) {
            Err(SynthError::Unread { phrase, reason }) => {
                assert!(phrase.contains(words), "{prompt}: quoted \"{phrase}\" ({reason}), not \"{words}\"")
            }
            other => panic!("{prompt}: {other:?}"),
        }
    }

    fn made(prompt: &str) {
        if let Err(e) = synthesize(prompt) {
            panic!("{prompt}: {e}");
        }
    }

    #[test]
    fn one_length_with_two_values_is_refused() {
        refused("Rod Ø20 x 100 lg, 25 diameter", "25 diameter");
        refused("Ø20 x 60 pin, 60 mm diameter.", "60 mm diameter");
        refused("A 10 mm thick plate, 100 x 50, 12 mm thick.", "12 mm thick");
        refused("Block 60 x 40 x 30 high, 40 high.", "40 high");
        refused("Block 70 x 40 x 25. The block is 30 thick.", "30 thick");
        refused("Plate 100 long, 60 wide, 8 thick, overall length 120.", "overall length 120");
        refused("3 in OD x 2-1/2 in ID tube, 1/8 in wall, 6 in long", "1/8 in wall");
        refused("A cylinder 40 mm in diameter and 20 mm tall, 20 mm across.", "20 mm across");
        refused("A disc of radius 20, 50 across, 5 thick.", "50 across");
        refused("a round bar 20 dia, 100 long, 22 mm OD", "22 mm OD");
        // The same length said again agrees, and diameters of different places differ.
        made("A cylinder 30 mm in diameter and 60 mm long. Its diameter is 30 and its length 60.");
        made("A frustum with a bottom diameter of 50 mm, a top diameter of 30 mm and a height of 25 mm");
        made("A disc 60 across and 8 thick with a 2 mm radius on both outside edges and a 20 mm bore.");
    }

    #[test]
    fn units_that_disagree_are_refused() {
        refused("a 2 in (60 mm) round bar, 100 mm long", "2 in (60 mm)");
        refused("Round bar 30 mm dia (1.5 in), 200 long", "(1.5 in)");
        refused("A 1 in x 2 in x 3 in block, 40 x 60 x 80 mm.", "40 x 60 x 80");
        made("a 2 in (50.8 mm) round bar, 100 mm long");
    }

    #[test]
    fn shape_words_the_sizes_deny_are_refused() {
        refused("Square bar 20 x 25, 100 long.", "Square bar 20 x 25");
        refused("A 40 mm ball with a radius of 25 mm.", "radius of 25");
        refused("Hex bar 20 A/F, 18 across corners, 50 long", "18 across corners");
        refused("Spacer: OD 12 mm, ID 14 mm, length 10 mm.", "ID 14 mm");
        made("A square bar, 16 mm square and 300 mm long.");
        made("Hex bar 20 A/F, 23.09 across corners, 50 long");
    }

    #[test]
    fn cuts_that_fit_the_part_in_no_direction_are_refused() {
        refused("DISC Ø30 x 5, Ø35 CENTRE HOLE", "Ø35");
        refused("Plate 60 x 40 x 5 with a 10 wide slot 80 long through it along the centreline", "slot 80 long");
        refused("Block 50 x 50 x 20 with a 30 x 30 pocket 25 deep in the top", "pocket 25 deep");
        refused("Block 40 x 40 x 40 with a 50 x 20 pocket 10 deep in the top.", "50 x 20 pocket");
        refused("a 50 x 50 x 50 block with an Ø8 hole 60 deep", "60 deep");
        refused("Ø25 x 100 shaft with a keyway 30 wide.", "keyway 30 wide");
        made("Block 50 x 50 x 20 with a 30 x 30 pocket 15 deep in the top");
    }

    #[test]
    fn hole_patterns_that_cannot_be_laid_out_are_refused() {
        // Overlapping on the pitch circle, breaking out of the rim, into the bore.
        refused("Disc Ø100 x 8, 8x Ø10 thru on 25 PCD", "25 PCD");
        refused("Flange Ø120 x 12, Ø40 bore, 6x Ø14 holes on 110 PCD", "110 PCD");
        refused("Flange Ø100 x 10, Ø30 bore, 4x Ø12 on 40 PCD", "40 PCD");
        // Rows and rectangles of centres, and holes nearer an edge than their radius.
        refused("Bar 200 x 30 x 10, 5x Ø8 thru at 50 pitch", "50 pitch");
        refused("Plate 120 x 80 x 10, 4x Ø10 holes on 140 x 60 centres", "140 x 60 centres");
        refused("Plate 50 x 50 x 6, four Ø12 holes at 4 mm from the edges at the corners", "Ø12");
        // The same patterns with room are made.
        made("Ø50 x 20 disc, 6x Ø12 thru on 30 PCD");
        made("Flange Ø100 x 10, Ø30 bore, 4x Ø12 on 60 PCD");
        made("Bar 200 x 30 x 10, 3x Ø8 thru at 50 pitch");
    }

    #[test]
    fn edge_treatments_larger_than_the_edges_are_refused() {
        refused("plt 100x60x6, R40 cnrs", "R40");
        refused("Ø10 x 40 pin, 6x45° chamfer both ends", "6x45");
        refused("A 20 mm cube with all its edges rounded 12 mm.", "12 mm");
        made("plt 100x60x6, R20 cnrs");
    }
}
