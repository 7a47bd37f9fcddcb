//! A part of the feature language: bodies joined (in order) and then cut — what the
//! reader builds from a prompt. It knows its bounding box, which of its extents a cut
//! may have trimmed, its volume when every overlap is known exactly, and its through-holes
//! when they are simple; and it writes itself as CadQuery code.

use std::fmt::Write as _;

use super::profile::Profile;
use super::solid::{Axis, Body, Shape};

/// Bodies added in order, then cut.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Model {
    pub adds: Vec<Body>,
    pub cuts: Vec<Body>,
}

const EPS: f64 = 1e-7;

fn overlap_1d(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[1].min(b[1]) - a[0].max(b[0])).max(0.0)
}

fn boxes_overlap(a: &[[f64; 3]; 2], b: &[[f64; 3]; 2]) -> f64 {
    (0..3).map(|k| overlap_1d([a[0][k], a[1][k]], [b[0][k], b[1][k]])).product()
}

fn inside_box(inner: &[[f64; 3]; 2], outer: &[[f64; 3]; 2]) -> bool {
    (0..3).all(|k| inner[0][k] >= outer[0][k] - EPS && inner[1][k] <= outer[1][k] + EPS)
}

/// The prism's profile, axis, centre and span, without edge treatments or a shell.
/// A prism's profile, axis, centre, turn and span.
type PrismParts<'a> = (&'a Profile, Axis, [f64; 2], f64, [f64; 2]);

fn plain_prism(b: &Body) -> Option<PrismParts<'_>> {
    match &b.shape {
        Shape::Prism { profile, axis, at, rot, from, to } if b.edges.is_empty() && b.shell.is_none() => {
            Some((profile, *axis, *at, *rot, [from.min(*to), from.max(*to)]))
        }
        _ => None,
    }
}

/// An axis-aligned box body (a rectangle prism not turned off the axes).
fn as_box(b: &Body) -> Option<[[f64; 3]; 2]> {
    let (p, _, _, rot, _) = plain_prism(b)?;
    (matches!(p, Profile::Rect { .. }) && rot.rem_euclid(90.0) < 1e-9).then(|| b.bounds())
}

/// Whether the profile `small` placed at `at_s` (turned `rot_s`) lies in `big` at `at_b`
/// (turned `rot_b`): exactly for circles, by the outline for convex profiles, and for a
/// circle in a polygon (a hub in a gear) by its distance from every edge.
fn profile_inside(small: &Profile, at_s: [f64; 2], rot_s: f64, big: &Profile, at_b: [f64; 2], rot_b: f64) -> bool {
    let off = [at_s[0] - at_b[0], at_s[1] - at_b[1]];
    let dist = (off[0] * off[0] + off[1] * off[1]).sqrt();
    if let (Profile::Circle { d: ds }, Profile::Circle { d: db } | Profile::Annulus { od: db, .. }) = (small, big) {
        let outer_ok = dist + ds / 2.0 <= db / 2.0 + EPS;
        return match big {
            Profile::Annulus { id, .. } => outer_ok && dist - ds / 2.0 >= id / 2.0 - EPS,
            _ => outer_ok,
        };
    }
    // Into the big profile's own frame.
    let (sb, cb) = (-rot_b).to_radians().sin_cos();
    let to_big = |q: [f64; 2]| [cb * q[0] - sb * q[1], sb * q[0] + cb * q[1]];
    match big {
        Profile::Annulus { .. } => false,
        Profile::Star { .. } | Profile::Poly(_) | Profile::Path { .. } => {
            let Profile::Circle { d } = small else { return false };
            let c = to_big(off);
            let outline = big.outline();
            big.contains(c)
                && (0..outline.len())
                    .all(|i| seg_dist(c, outline[i], outline[(i + 1) % outline.len()]) >= d / 2.0 - EPS)
        }
        _ => {
            let (ss, cs) = rot_s.to_radians().sin_cos();
            small
                .outline()
                .into_iter()
                .all(|p| big.contains(to_big([cs * p[0] - ss * p[1] + off[0], ss * p[0] + cs * p[1] + off[1]])))
        }
    }
}

fn seg_dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let len2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t = if len2 > 0.0 { (((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let q = [a[0] + t * ab[0] - p[0], a[1] + t * ab[1] - p[1]];
    (q[0] * q[0] + q[1] * q[1]).sqrt()
}

/// The exact volume two bodies share, when it is known: disjoint bounds, two boxes, or
/// two prisms along the same axis one of whose profiles holds the other's.
fn overlap(a: &Body, b: &Body) -> Option<f64> {
    let (ba, bb) = (a.bounds(), b.bounds());
    if boxes_overlap(&ba, &bb) <= EPS {
        return Some(0.0);
    }
    if let (Some(x), Some(y)) = (as_box(a), as_box(b)) {
        return Some(boxes_overlap(&x, &y));
    }
    let (pa, axa, ata, ra, sa) = plain_prism(a)?;
    let (pb, axb, atb, rb, sb) = plain_prism(b)?;
    if axa != axb {
        return None;
    }
    let span = overlap_1d(sa, sb);
    if profile_inside(pa, ata, ra, pb, atb, rb) {
        Some(pa.area() * span)
    } else if profile_inside(pb, atb, rb, pa, ata, ra) {
        Some(pb.area() * span)
    } else {
        None
    }
}

impl Model {
    /// Bounds of what is added, [min, max].
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        for body in &self.adds {
            let q = body.bounds();
            for k in 0..3 {
                b[0][k] = b[0][k].min(q[0][k]);
                b[1][k] = b[1][k].max(q[1][k]);
            }
        }
        b
    }

    pub fn size(&self) -> [f64; 3] {
        let b = self.bounds();
        [b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]]
    }

    /// Per axis: whether the extent is the added bodies' for certain (no cut can have
    /// trimmed it). A cut that reaches a side of the part trims it unless it runs through
    /// along that axis inside the part's other two extents (a hole through a plate).
    pub fn extent_certain(&self) -> [bool; 3] {
        let b = self.bounds();
        let mut ok = [true; 3];
        for c in &self.cuts {
            let q = c.bounds();
            for k in 0..3 {
                let reaches = q[0][k] <= b[0][k] + EPS || q[1][k] >= b[1][k] - EPS;
                if !reaches {
                    continue;
                }
                // A cut running along this axis leaves the end faces where it does not cover
                // them: kept when, across, it leaves a quarter of the part on some side.
                let along = c.shape.axis().is_some_and(|a| a.index() == k);
                let leaves = (0..3).filter(|j| *j != k).any(|j| {
                    let w = (b[1][j] - b[0][j]).max(EPS);
                    (q[0][j] - b[0][j]).max(b[1][j] - q[1][j]) >= 0.25 * w
                });
                if !(along && leaves) {
                    ok[k] = false;
                }
            }
        }
        ok
    }

    /// The volume, when every overlap between added bodies and every cut's share of the
    /// part is known exactly.
    pub fn volume(&self) -> Option<f64> {
        let mut v = 0.0;
        let mut overlaps: Vec<(usize, usize)> = Vec::new();
        for (i, a) in self.adds.iter().enumerate() {
            v += a.volume()?;
            for (j, b) in self.adds.iter().enumerate().skip(i + 1) {
                let o = overlap(a, b)?;
                if o > EPS {
                    overlaps.push((i, j));
                }
                v -= o;
            }
        }
        // Inclusion–exclusion stops at pairs: three bodies sharing a region would need more.
        for &(i, j) in &overlaps {
            for &(k, l) in &overlaps {
                if k == i && l != j && overlaps.contains(&(j.min(l), j.max(l))) {
                    let (a, b, c) = (self.adds[i].bounds(), self.adds[j].bounds(), self.adds[l].bounds());
                    let abc: f64 = (0..3)
                        .map(|m| (a[1][m].min(b[1][m]).min(c[1][m]) - a[0][m].max(b[0][m]).max(c[0][m])).max(0.0))
                        .product();
                    if abc > EPS {
                        return None;
                    }
                }
            }
        }
        for (i, c) in self.cuts.iter().enumerate() {
            for d in self.cuts.iter().skip(i + 1) {
                if overlap(c, d)? > EPS {
                    return None;
                }
            }
            v -= self.removed(c)?;
        }
        Some(v)
    }

    /// What a cut removes, when it lies wholly in the part and that is known: inside one
    /// box, or along an axis covered by coaxial prisms that each hold its profile, and
    /// touching no other body.
    fn removed(&self, cut: &Body) -> Option<f64> {
        let cv = cut.volume()?;
        let cb = cut.bounds();
        let touching: Vec<&Body> = self.adds.iter().filter(|a| boxes_overlap(&a.bounds(), &cb) > EPS).collect();
        if touching.is_empty() {
            return Some(0.0);
        }
        if let [one] = touching.as_slice()
            && let Some(bx) = as_box(one)
            && inside_box(&cb, &bx)
        {
            return Some(cv);
        }
        let (pc, axc, atc, rc, sc) = plain_prism(cut)?;
        let mut spans = Vec::new();
        for a in &touching {
            let (pa, axa, ata, ra, sa) = plain_prism(a)?;
            if axa != axc || !profile_inside(pc, atc, rc, pa, ata, ra) {
                return None;
            }
            spans.push(sa);
        }
        spans.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let mut reach = sc[0];
        for s in spans {
            if s[0] > reach + EPS {
                return None;
            }
            reach = reach.max(s[1]);
        }
        (reach >= sc[1] - EPS).then_some(cv)
    }

    /// Through-holes, for a single ring or prism with cuts that each run through it along
    /// its axis, apart from one another.
    pub fn genus(&self) -> Option<u32> {
        let [body] = self.adds.as_slice() else { return None };
        let (p, ax, at, rot, span) = plain_prism(body)?;
        let mut g = u32::from(matches!(p, Profile::Annulus { .. }));
        for (i, c) in self.cuts.iter().enumerate() {
            let (pc, axc, atc, rc, sc) = plain_prism(c)?;
            if axc != ax || sc[0] > span[0] + EPS || sc[1] < span[1] - EPS || !profile_inside(pc, atc, rc, p, at, rot) {
                return None;
            }
            if self.cuts.iter().skip(i + 1).any(|d| boxes_overlap(&c.bounds(), &d.bounds()) > EPS) {
                return None;
            }
            g += 1;
        }
        Some(g)
    }

    /// CadQuery code that assigns the part to `result`.
    pub fn code(&self, title: &str) -> String {
        let mut s =
            format!("# {title}\n# Units: mm. Written by scenewright's offline synthesizer.\nimport cadquery as cq\n\n");
        for (i, b) in self.adds.iter().enumerate() {
            let _ = writeln!(s, "# {}", b.label);
            if i == 0 {
                let _ = writeln!(s, "result = {}", b.code());
            } else {
                let _ = writeln!(s, "result = result.union({})", b.code());
            }
        }
        // Round holes first, then the other cuts: a slot whose sides are tangent to a hole
        // already cut leaves OCCT a valid solid, the other way round it may not.
        let round = |c: &&Body| matches!(&c.shape, Shape::Prism { profile: Profile::Circle { .. }, .. });
        for c in self.cuts.iter().filter(round).chain(self.cuts.iter().filter(|c| !round(c))) {
            let _ = writeln!(s, "# {}", c.label);
            let _ = writeln!(s, "result = result.cut({})", c.code());
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;

    fn cyl(d: f64, from: f64, to: f64, at: [f64; 2]) -> Body {
        Body::new("c", Shape::Prism { profile: Profile::Circle { d }, axis: Axis::Z, at, rot: 0.0, from, to })
    }

    #[test]
    fn a_flanged_shaft_with_bolt_holes_has_an_exact_volume() {
        let mut m = Model::default();
        m.adds.push(cyl(40.0, 0.0, 5.0, [0.0, 0.0]));
        m.adds.push(cyl(20.0, 5.0, 55.0, [0.0, 0.0]));
        for k in 0..4 {
            let a = f64::from(k) * PI / 2.0;
            m.cuts.push(cyl(6.0, 0.0, 5.0, [15.0 * a.cos(), 15.0 * a.sin()]));
        }
        let want = PI * 400.0 * 5.0 + PI * 100.0 * 50.0 - 4.0 * PI * 9.0 * 5.0;
        assert!((m.volume().unwrap() - want).abs() < 1e-6);
        assert_eq!(m.extent_certain(), [true, true, true]);
        // A bore through both, covered by the two coaxial discs.
        m.cuts.push(cyl(10.0, 0.0, 55.0, [0.0, 0.0]));
        assert!((m.volume().unwrap() - (want - PI * 25.0 * 55.0)).abs() < 1e-6);
    }

    #[test]
    fn a_keyway_trims_the_shafts_extent_and_a_washer_has_one_hole() {
        let mut m = Model::default();
        m.adds.push(cyl(20.0, 0.0, 60.0, [0.0, 0.0]));
        m.cuts.push(Body::new(
            "keyway",
            Shape::Prism {
                profile: Profile::Rect { w: 5.0, h: 6.0 },
                axis: Axis::Z,
                at: [9.5, 0.0],
                rot: 0.0,
                from: 0.0,
                to: 60.0,
            },
        ));
        assert_eq!(m.extent_certain(), [false, true, true]);
        assert_eq!(m.volume(), None);
        let w = Model {
            adds: vec![Body::new(
                "washer",
                Shape::Prism {
                    profile: Profile::Annulus { od: 20.0, id: 10.5 },
                    axis: Axis::Z,
                    at: [0.0; 2],
                    rot: 0.0,
                    from: 0.0,
                    to: 2.0,
                },
            )],
            cuts: Vec::new(),
        };
        assert_eq!(w.genus(), Some(1));
    }
}
