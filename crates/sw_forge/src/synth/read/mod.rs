//! The reader: a dimensioned prompt to a [`Model`]. It reads the mentions (bodies, cuts,
//! treatments) and their quantities, builds each body ([`bodies`], [`sections`],
//! [`paths`]), places it ([`place`]), cuts the features ([`cuts`]), treats edges and
//! shells ([`treat`]), and then accounts for every number and word ([`verify`]): a length
//! the construction did not use must restate the part, and every word must have been read
//! or carry no geometry — else the prompt is refused with the exact words.

mod bodies;
mod cuts;
mod paths;
mod place;
mod sections;
mod treat;
mod verify;

use std::collections::BTreeSet;

use super::doc::{Dim, Doc, Role};
use super::lexicon::{Noun, ShapeHint};
use super::mention::{self, Element, Mention};
use super::model::Model;
use super::solid::Axis;

/// Why a prompt was not made: the words that could not be honoured, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    pub phrase: String,
    pub reason: String,
}

impl Refusal {
    pub fn new(phrase: impl Into<String>, reason: impl Into<String>) -> Self {
        Self { phrase: phrase.into(), reason: reason.into() }
    }
}

pub type Res<T> = Result<T, Refusal>;

/// What an element became: its bodies and where they are.
#[derive(Debug, Clone, PartialEq)]
pub struct Built {
    pub axis: Axis,
    /// Along the axis.
    pub span: [f64; 2],
    /// Centres of its copies in the plane normal to the axis (u, v).
    pub at: Vec<[f64; 2]>,
    /// Outer and inner diameter of a round body (circumscribed for a polygon, tip for a star).
    pub od: Option<f64>,
    pub id: Option<f64>,
    /// In-plane size (u, v) of a rectangular body.
    pub size: Option<[f64; 2]>,
    /// Indices of its bodies in the model's adds (or cuts).
    pub bodies: Vec<usize>,
    pub cut: bool,
}

/// The reading of one prompt.
#[derive(Debug)]
pub struct Reader<'a> {
    pub doc: &'a Doc,
    pub mentions: Vec<Mention>,
    pub els: Vec<Element>,
    pub model: Model,
    pub used_dims: Vec<bool>,
    pub used_ranges: Vec<bool>,
    pub used_coords: Vec<bool>,
    pub used_tuples: Vec<bool>,
    pub used_angles: BTreeSet<usize>,
    /// Elements read (built, cut or applied).
    pub done: Vec<bool>,
    pub built: Vec<Option<Built>>,
    /// "Centered at the origin" (in all axes unless a span says otherwise).
    pub centered: bool,
    /// Lengths the construction established (a radial span, a bend radius …) that a
    /// restatement may repeat, and points of paths (part coordinates).
    pub known: Vec<f64>,
    pub known_points: Vec<[f64; 3]>,
}

/// Reads a dimensioned prompt into a model.
pub fn read(doc: &Doc) -> Res<Model> {
    let (mentions, els) = mention::read(doc);
    let n = els.len();
    let mut r = Reader {
        doc,
        mentions,
        els,
        model: Model::default(),
        used_dims: vec![false; doc.dims.len()],
        used_ranges: vec![false; doc.ranges.len()],
        used_coords: vec![false; doc.coords.len()],
        used_tuples: vec![false; doc.tuples.len()],
        used_angles: BTreeSet::new(),
        done: vec![false; n],
        built: vec![None; n],
        centered: false,
        known: Vec::new(),
        known_points: Vec::new(),
    };
    if r.els.iter().all(|e| !matches!(e.kind, Noun::Body(_)) && e.kind != Noun::Whole) {
        return Err(Refusal::new(doc.quote(0, doc.len().saturating_sub(1)), "it names no body the synthesizer makes"));
    }
    place::read_frame(&mut r);
    bodies::merge_faces(&mut r);
    sections::read(&mut r)?;
    paths::read(&mut r)?;
    bodies::read(&mut r)?;
    if r.model.adds.is_empty() {
        let title = r.els.first().map_or(String::new(), |e| e.noun.clone());
        return Err(Refusal::new(title, "no body of it is given its size"));
    }
    join_pipes(&mut r);
    cuts::read(&mut r)?;
    treat::read(&mut r)?;
    verify::check(&mut r)?;
    Ok(r.model)
}

/// Pipes that meet (a tee, a cross) share one hollow interior: each becomes its outer
/// cylinder, joined, and its bore, cut after the joining.
fn join_pipes(r: &mut Reader<'_>) {
    use super::profile::Profile;
    use super::solid::{Body, Shape};
    let rings: Vec<usize> = (0..r.model.adds.len())
        .filter(|i| matches!(&r.model.adds[*i].shape, Shape::Prism { profile: Profile::Annulus { .. }, .. }))
        .collect();
    let meets = |a: usize, b: usize| {
        let (p, q) = (r.model.adds[a].bounds(), r.model.adds[b].bounds());
        (0..3).all(|k| p[0][k] < q[1][k] - 1e-9 && q[0][k] < p[1][k] - 1e-9)
    };
    let crossing: Vec<usize> = rings
        .iter()
        .copied()
        .filter(|a| {
            rings
                .iter()
                .any(|b| b != a && meets(*a, *b) && r.model.adds[*a].shape.axis() != r.model.adds[*b].shape.axis())
        })
        .collect();
    for i in crossing {
        let Shape::Prism { profile: Profile::Annulus { od, id }, axis, at, rot, from, to } =
            r.model.adds[i].shape.clone()
        else {
            continue;
        };
        r.model.adds[i].shape = Shape::Prism { profile: Profile::Circle { d: od }, axis, at, rot, from, to };
        let label = format!("{} bore", r.model.adds[i].label);
        r.model
            .cuts
            .push(Body::new(label, Shape::Prism { profile: Profile::Circle { d: id }, axis, at, rot, from, to }));
    }
}

impl Reader<'_> {
    pub fn dim(&self, k: usize) -> &Dim {
        &self.doc.dims[k]
    }

    /// The element's lengths not yet used, in prompt order.
    pub fn free_dims(&self, e: usize) -> Vec<usize> {
        self.els[e].dims.iter().copied().filter(|k| !self.used_dims[*k]).collect()
    }

    /// The first free length of element `e` with this role whose qualifiers include all of
    /// `with` and none of `without`; lengths outside parentheses first.
    pub fn take(&mut self, e: usize, roles: &[Role], with: &[&str], without: &[&str]) -> Option<f64> {
        let k = self.find(e, roles, with, without)?;
        self.used_dims[k] = true;
        Some(self.doc.dims[k].mm)
    }

    pub fn find(&self, e: usize, roles: &[Role], with: &[&str], without: &[&str]) -> Option<usize> {
        let ok = |k: &usize, paren: bool| {
            let d = &self.doc.dims[*k];
            !self.used_dims[*k]
                && d.restates.is_none()
                && d.paren == paren
                && roles.contains(&d.role)
                && with.iter().all(|w| d.has(w))
                && without.iter().all(|w| !d.has(w))
        };
        let dims = &self.els[e].dims;
        dims.iter().copied().find(|k| ok(k, false)).or_else(|| dims.iter().copied().find(|k| ok(k, true)))
    }

    /// A diameter, or twice a radius, qualified the same way.
    pub fn take_diameter(&mut self, e: usize, with: &[&str], without: &[&str]) -> Option<f64> {
        let mut without = without.to_vec();
        without.push("from-center");
        let without = without.as_slice();
        let d = self.find(e, &[Role::Diameter], with, without);
        let r = self.find(e, &[Role::Radius], with, without);
        // Outside parentheses first; a diameter before a radius.
        let paren = |k: Option<usize>| k.is_some_and(|k| self.doc.dims[k].paren);
        let pick = match (d, r) {
            (Some(a), Some(b)) if paren(Some(a)) && !paren(Some(b)) => Some(b),
            (Some(a), _) => Some(a),
            (None, b) => b,
        }?;
        self.used_dims[pick] = true;
        let d = &self.doc.dims[pick];
        Some(if d.role == Role::Radius { 2.0 * d.mm } else { d.mm })
    }

    /// The element's span along `axis` ("Z=0 to Z=10"), marking it used.
    pub fn take_range(&mut self, e: usize, axis: Axis) -> Option<[f64; 2]> {
        let k =
            self.els[e].ranges.iter().copied().find(|k| !self.used_ranges[*k] && self.doc.ranges[*k].axis == axis)?;
        self.used_ranges[k] = true;
        let r = &self.doc.ranges[k];
        self.doc.mark_range(r.toks.0, r.toks.1);
        Some([r.a.min(r.b), r.a.max(r.b)])
    }

    pub fn take_coord(&mut self, e: usize, axis: Axis) -> Option<f64> {
        let k =
            self.els[e].coords.iter().copied().find(|k| !self.used_coords[*k] && self.doc.coords[*k].axis == axis)?;
        self.used_coords[k] = true;
        let c = &self.doc.coords[k];
        self.doc.mark_range(c.tok, c.tok + 3);
        Some(c.v)
    }

    /// The words of an element's mentions (its phrases) marked read.
    pub fn mark_element(&mut self, e: usize) {
        self.done[e] = true;
        for &mi in &self.els[e].mentions {
            let m = &self.mentions[mi];
            self.doc.mark_range(m.start, m.head + 1);
        }
    }

    /// The shape an element has: its adjectives, else its noun's, else from its lengths.
    pub fn shape_of(&self, e: usize) -> Option<ShapeHint> {
        let el = &self.els[e];
        let from_noun = match el.kind {
            Noun::Body(h) => Some(h),
            _ => None,
        };
        // Teeth make a star ("the gear disc … with 16 teeth").
        if el.teeth.is_some() {
            return Some(ShapeHint::Star);
        }
        // "a half ball", "half a sphere": a hemisphere.
        if from_noun == Some(ShapeHint::Sphere) && el.has_mod("half") {
            return Some(ShapeHint::Hemisphere);
        }
        // An angle bracket (or iron) is an L.
        if matches!(el.noun.as_str(), "bracket" | "iron" | "profile" | "section" | "bar")
            && (el.has_mod("angle") || el.has_mod("l-shaped"))
        {
            return Some(ShapeHint::Section(super::lexicon::Section::L));
        }
        // A tapered or truncated rectangular block, or a square frustum, is a rectangular frustum.
        let squared = el.has_mod("rectangular") || el.has_mod("square");
        let tapering = (0..self.doc.len()).any(|i| matches!(self.doc.word(i), Some("tapering" | "tapers" | "tapered")));
        if squared && (el.has_mod("tapered") || el.has_mod("truncated") || el.noun == "frustum" || tapering) {
            return Some(ShapeHint::Pyramid);
        }
        // "a Ø60 x 40 gear blank": a box noun sized by a diameter is round.
        if from_noun == Some(ShapeHint::Rect)
            && el.shape.is_none()
            && el.dims.iter().any(|k| self.doc.dims[*k].role == Role::Diameter && !self.doc.dims[*k].has("inner"))
            && !el.dims.iter().any(|k| self.doc.dims[*k].list.is_some())
        {
            return Some(ShapeHint::Round);
        }
        // A rectangular or square tube or pipe is a hollow box section.
        if matches!(el.noun.as_str(), "tube" | "pipe" | "sleeve") && (el.has_mod("rectangular") || el.has_mod("square"))
        {
            return Some(ShapeHint::Section(super::lexicon::Section::RectTube));
        }
        // A named solid ("cone", "sphere", "gear") keeps its kind; "hollow cylinder" is a ring.
        match (el.shape, from_noun) {
            (Some(ShapeHint::Ring), Some(ShapeHint::Round | ShapeHint::Ring)) => Some(ShapeHint::Ring),
            // "a hexagonal spacer": the polygon, its bore a hole.
            (
                Some(a @ (ShapeHint::Ngon(_) | ShapeHint::Ellipse | ShapeHint::Stadium | ShapeHint::Star)),
                Some(ShapeHint::Ring),
            ) => Some(a),
            (Some(ShapeHint::Round), Some(ShapeHint::Ring)) => Some(ShapeHint::Ring),
            (Some(a), Some(ShapeHint::Round | ShapeHint::Rect)) => Some(a),
            (_, Some(n)) => Some(n),
            (a, None) => a,
        }
    }

    /// The sentence words of an element's mentions and the quantities attached to it:
    /// whether any is `w`.
    pub fn says(&self, e: usize, w: &str) -> bool {
        self.els[e].mentions.iter().any(|mi| {
            let s = self.mentions[*mi].sent;
            let (a, b) = self.doc.sentence(s);
            (a..b).any(|i| self.doc.is(i, w))
        })
    }

    /// Token ranges of the sentences an element is mentioned in.
    pub fn sentences_of(&self, e: usize) -> Vec<(usize, usize)> {
        let mut s: Vec<usize> = self.els[e].mentions.iter().map(|mi| self.mentions[*mi].sent).collect();
        s.dedup();
        s.into_iter().map(|x| self.doc.sentence(x)).collect()
    }

    /// Elements of a noun (or with it among their modifiers).
    pub fn elements_named(&self, w: &str) -> Vec<usize> {
        (0..self.els.len()).filter(|i| self.els[*i].noun == w || self.els[*i].has_mod(w)).collect()
    }

    pub fn quote_element(&self, e: usize) -> String {
        let Some(&mi) = self.els[e].mentions.first() else { return self.els[e].noun.clone() };
        let m = &self.mentions[mi];
        self.doc.quote(m.start, m.head)
    }

    pub fn quote_dim(&self, k: usize) -> String {
        let d = &self.doc.dims[k];
        self.doc.quote(d.phrase.0.min(d.tok), (d.phrase.1.max(d.tok + 1)).saturating_sub(1))
    }
}
