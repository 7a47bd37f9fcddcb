//! Who is who in a prompt: the noun phrases that name a body, a cut or an edge
//! treatment (mentions), which of them are the same thing (coreference: "a hexagonal
//! head … The head has …"), and which lengths, spans, coordinates, tuples and angles
//! belong to each (attachment: "a 10mm diameter shaft, 30mm long" — both to the shaft;
//! "rises from the plate from Z=5 to Z=18" — the span to the subject, not to the plate).

use super::doc::Doc;
use super::lexicon::{Noun, ShapeHint, noun, number_word, shape_adjective};
use super::text::Tk;

/// Words that may stand before a noun to say what it is for ("mounting holes", "gasket
/// groove", "flight-controller holes"); they do not change its geometry.
pub const LABELS: &[&str] = &[
    "motor",
    "mounting",
    "flight-controller",
    "controller",
    "gasket",
    "lightening",
    "cooling",
    "set",
    "screw",
    "pilot",
    "clearance",
    "retaining",
    "bearing",
    "cable",
    "wire",
    "drain",
    "vent",
    "access",
    "locating",
    "alignment",
    "fixing",
    "tool",
    "spring",
    "lock",
    "electronics",
    "electronic",
    "internal",
    "external",
    "heat",
    "sink",
    "spur",
    "idler",
    "drive",
    "driven",
    "pinion",
    "support",
    "guide",
    "center",
    "central",
    "main",
    "run",
    "branch",
    "outer",
    "inner",
    "upper",
    "lower",
    "top",
    "bottom",
    "front",
    "back",
    "rear",
    "left",
    "right",
    "side",
    "end",
    "first",
    "second",
    "third",
    "large",
    "small",
    "big",
    "larger",
    "smaller",
    "narrower",
    "wider",
    "thinner",
    "thicker",
    "shorter",
    "longer",
    "taller",
    "raised",
    "sunken",
    "horizontal",
    "vertical",
    "upright",
    "parallel",
    "radial",
    "axial",
    "transverse",
    "longitudinal",
    "perpendicular",
    "diagonal",
    "solid",
    "simple",
    "plain",
    "flat",
    "thin",
    "thick",
    "long",
    "short",
    "tall",
    "wide",
    "narrow",
    "deep",
    "shallow",
    "straight",
    "smooth",
    "structural",
    "mechanical",
    "cross",
    "pipe",
    "allen",
    "cap",
    "socket",
    "hex",
    "machine",
    "wood",
    "metal",
    "steel",
    "aluminium",
    "aluminum",
    "brass",
    "plastic",
    "nylon",
    "rubber",
    "tooth",
    "belt",
    "v-belt",
    "timing",
    "pitch",
    "bolt",
    "stepped",
    "lamp",
    "table",
    "chair",
    "desk",
    "bench",
    "stool",
    "shelf",
    "cabinet",
    "door",
    "drawer",
    "bed",
    "bicycle",
    "bike",
    "pump",
    "valve",
    "sensor",
    "camera",
    "robot",
    "fan",
    "gearbox",
    "bearing",
    "dowel",
    "flanged",
    "threaded",
    "tapped",
    "smooth",
    "full",
    "half",
    "quarter",
    "semicircular",
    "continuous",
    "through",
    "blind",
    "counterbored",
    "countersunk",
    "rounded",
    "filleted",
    "chamfered",
    "drilled",
    "machined",
    "bored",
    "cut",
    "equal",
    "identical",
    "matching",
    "protruding",
    "extended",
    "integral",
    "single",
    "double",
    "twin",
    "triple",
    "compound",
    "coaxial",
    "concentric",
    "base",
    "mount",
    "shaft",
    "gear",
    "hub",
    "journal",
    "neck",
    "shoulder",
    "head",
    "body",
    "wall",
    "floor",
    "rim",
    "platform",
    "post",
    "plate",
    "standoff",
    "arm",
    "fin",
    "rib",
    "rail",
    "seat",
    "flange",
    "key",
    "keyway",
    "slot",
    "groove",
    "hole",
    "bore",
    "boss",
    "ring",
    "disc",
    "lug",
    "ear",
    "tab",
    "leg",
    "foot",
    "pad",
    "web",
    "stem",
    "spoke",
    "mid-height",
    "square",
    "rectangular",
    "round",
    "circular",
    "angle",
    "l-shaped",
    "cylindrical",
    "regular",
];

/// A noun phrase naming a body, a cut or an edge treatment.
#[derive(Debug, Clone, PartialEq)]
pub struct Mention {
    pub head: usize,
    /// First token of the phrase (after its determiner).
    pub start: usize,
    pub noun: String,
    pub kind: Noun,
    /// The words before the head in its phrase.
    pub mods: Vec<String>,
    pub shape: Option<ShapeHint>,
    pub count: Option<u32>,
    /// "each", "every", "both", "all" before it.
    pub each: bool,
    /// "the", "each", "both" … — it may refer back.
    pub definite: bool,
    /// The preposition it is the object of ("through the plate"), when it is one.
    pub prep: Option<String>,
    /// It has a determiner ("a", "the", "each" …).
    pub det: bool,
    /// Written in the plural ("rails").
    pub plural: bool,
    pub sent: usize,
    pub elem: usize,
    /// Alone in parentheses ("(four holes)"): an aside about something named before.
    pub paren_aside: bool,
}

/// One thing the prompt describes, from all its mentions.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    pub noun: String,
    pub kind: Noun,
    pub mods: Vec<String>,
    pub shape: Option<ShapeHint>,
    pub count: Option<u32>,
    pub mentions: Vec<usize>,
    /// Indices into the doc's dims, ranges, coords and tuples, and angles (token, deg).
    pub dims: Vec<usize>,
    pub ranges: Vec<usize>,
    pub coords: Vec<usize>,
    pub tuples: Vec<usize>,
    pub angles: Vec<(usize, f64)>,
    /// "16 teeth", "32 vertices" (halved).
    pub teeth: Option<u32>,
    /// The first element of the prompt: the part itself.
    pub title: bool,
    /// Named in the plural, or counted more than one.
    pub plural: bool,
}

impl Element {
    pub fn has_mod(&self, w: &str) -> bool {
        self.mods.iter().any(|m| m == w)
    }
}

fn is_det(w: &str) -> bool {
    matches!(w, "a" | "an" | "the" | "each" | "every" | "both" | "all" | "another" | "its" | "their" | "any" | "this")
}

fn is_prep(w: &str) -> bool {
    matches!(
        w,
        "through"
            | "on"
            | "onto"
            | "from"
            | "of"
            | "to"
            | "at"
            | "in"
            | "into"
            | "with"
            | "above"
            | "below"
            | "inside"
            | "around"
            | "past"
            | "between"
            | "along"
            | "over"
            | "under"
            | "beneath"
            | "across"
            | "within"
            | "toward"
            | "towards"
            | "bridging"
            | "connecting"
            | "via"
            | "per"
            | "matching"
            | "like"
            | "as"
    )
}

/// Reads the mentions of a prompt and groups them into elements.
pub fn read(doc: &Doc) -> (Vec<Mention>, Vec<Element>) {
    let mut mentions = Vec::new();
    let n = doc.len();
    for i in 0..n {
        let Some(w) = doc.word(i) else { continue };
        let Some(kind) = noun(w) else { continue };
        // A noun directly followed by another noun of the phrase is a modifier ("bolt
        // holes", "base plate", "motor mount platform").
        if let Some(next) = doc.word(i + 1)
            && (noun(next).is_some_and(|k| !matches!(k, Noun::Pattern)) || next == "through-hole")
            && !matches!(kind, Noun::Pattern)
        {
            continue;
        }
        if matches!(kind, Noun::Pattern) {
            continue;
        }
        // "a 3 mm wall", "with 3mm walls": a thickness, not a body.
        if w == "wall"
            && i > 0
            && matches!(doc.toks[i - 1].kind, Tk::Num { unit: Some(_), .. })
            && doc.word(i + 1).is_none_or(|n| super::doc::role_of(n).is_none())
        {
            doc.mark(i);
            continue;
        }
        // "base at Z=0": a place on the part, not a body.
        if matches!(w, "base" | "top" | "bottom")
            && doc.is(i + 1, "at")
            && doc.axis_at(i + 2).is_some()
            && doc.sym(i + 3, '=')
        {
            continue;
        }
        // "on a 60mm bolt circle", "a 20mm x 20mm square pattern": a noun naming a pattern.
        if doc.word(i + 1).is_some_and(|n| noun(n) == Some(Noun::Pattern)) {
            continue;
        }
        // A noun qualifying a length ("base diameter", "wall thickness", "flange width",
        // "head height") is not a mention of its own; but a drawing's title noun that opens
        // the prompt with its first size ("FLANGE OD 140 / ID 60", "SHAFT DIA 20 x 100 LG")
        // is the part.
        let title = (0..i).all(|k| doc.word(k).is_some_and(is_det))
            && matches!(doc.toks.get(i + 2).map(|t| &t.kind), Some(Tk::Num { .. }));
        if !title
            && doc.word(i + 1).is_some_and(|n| {
                super::doc::role_of(n).is_some_and(|r| r != super::doc::Role::Spacing)
                    && n != "side"
                    && n != "rounded"
                    && n != "filleted"
                    && n != "chamfered"
            })
            && !matches!(kind, Noun::Fillet | Noun::Chamfer)
        {
            continue;
        }
        // "A stadium (oblong) shape", "clevis bracket (fork mount)": a name in parentheses
        // right after another is the same thing, read with it.
        if i >= 2 && doc.depth[i] > 0 && doc.toks[i + 1..].first().is_some_and(|t| t.is_sym(')')) {
            let open = (0..i).rev().find(|j| doc.sym(*j, '('));
            if let Some(o) = open
                && o >= 1
                && doc.word(o - 1).is_some_and(|w| noun(w).is_some())
                && (o + 1..i).all(|j| doc.word(j).is_some())
            {
                doc.mark_range(o, i + 2);
                continue;
            }
        }
        // The phrase: back over modifiers, counts, lengths and determiners.
        let mut start = i;
        let mut mods = Vec::new();
        let mut shape = None;
        let mut count = None;
        let mut each = false;
        let mut definite = false;
        let mut j = i;
        while j > 0 {
            let k = j - 1;
            let t = &doc.toks[k];
            let take = match &t.kind {
                Tk::Word(v) => {
                    if is_det(v) {
                        definite |= !matches!(v.as_str(), "a" | "an" | "another");
                        each |= matches!(v.as_str(), "each" | "every" | "both" | "all");
                        if v == "both" {
                            count = count.or(Some(2));
                        }
                        start = k;
                        break;
                    }
                    if let Some(c) = number_word(v) {
                        count = Some(c);
                        true
                    } else if let Some(s) = shape_adjective(v) {
                        shape = shape.or(Some(s));
                        mods.push(v.clone());
                        true
                    } else if v == "through" && (k + 1 != i || !matches!(kind, Noun::Cut(_))) {
                        // "4x Ø6.6 hole through flange": a through hole, never a through flange.
                        false
                    } else if noun(v).is_some() || LABELS.contains(&v.as_str()) || v == "metric" || v == "tapped" {
                        mods.push(v.clone());
                        true
                    } else {
                        super::doc::role_of(v).is_some()
                            && doc.toks.get(k.wrapping_sub(1)).is_some_and(|p| matches!(p.kind, Tk::Num { .. }))
                    }
                }
                Tk::Num { unit: Some(_), .. } => true,
                Tk::Num { v, unit: None, .. } if v.fract() == 0.0 && *v >= 1.0 && !doc.sym(k.wrapping_sub(1), '=') => {
                    // "16-tooth gear": the count is the teeth's, not the gear's.
                    if !doc.is(k + 1, "tooth") {
                        count = Some(*v as u32);
                    }
                    true
                }
                Tk::Sym('x') => true,
                Tk::Sym('-') => true,
                // "a 30mm long, 8mm wide slot": lengths before the noun, listed.
                Tk::Sym(',') => {
                    k >= 2
                        && doc.word(k - 1).is_some_and(|w| super::doc::role_of(w).is_some())
                        && matches!(doc.toks[k - 2].kind, Tk::Num { unit: Some(_), .. })
                        && matches!(doc.toks.get(k + 1).map(|t| &t.kind), Some(Tk::Num { unit: Some(_), .. }))
                        // Only inside a phrase begun by its determiner ("a 30mm long, 8mm wide
                        // slot"), never into another noun's ("BLOCK 40 x 60 HIGH, Ø16 HOLE").
                        && {
                            let mut q = k;
                            let mut found = false;
                            while q > 0 {
                                q -= 1;
                                if doc.word(q).is_some_and(is_det) {
                                    found = true;
                                    break;
                                }
                                // Past the commas of the same list ("a 40mm long, 8mm wide, 4mm deep keyway").
                                let listed = doc.toks[q].is_sym(',')
                                    && q >= 2
                                    && doc.word(q - 1).is_some_and(|w| super::doc::role_of(w).is_some())
                                    && matches!(doc.toks[q - 2].kind, Tk::Num { unit: Some(_), .. });
                                let stop = (doc.toks[q].is_sym(',') && !listed)
                                    || doc.toks[q].is_sym('.')
                                    || doc.toks[q].is_sym(':')
                                    || doc.word(q).is_some_and(|w| noun(w).is_some());
                                if stop {
                                    break;
                                }
                            }
                            found
                        }
                }
                // "dodecagonal (12-sided) prism": an aside inside the phrase.
                Tk::Sym(')') => {
                    if let Some(o) = (0..k).rev().find(|q| doc.sym(*q, '(')) {
                        let sides = (o + 1..k).find_map(|q| match doc.toks[q].kind {
                            Tk::Num { v, unit: None, .. } if doc.is(q + 2, "sided") || doc.is(q + 1, "sided") => {
                                Some(v)
                            }
                            _ => None,
                        });
                        if sides.is_some() || (o + 1..k).all(|q| doc.word(q).is_some()) {
                            doc.mark_range(o, k + 1);
                            j = o;
                            start = o;
                            continue;
                        }
                    }
                    false
                }
                _ => false,
            };
            if !take {
                break;
            }
            start = k;
            j = k;
        }
        mods.reverse();
        let det_at = if doc.word(start).is_some_and(is_det) { Some(start) } else { None };
        let first = det_at.map_or(start, |d| d + 1).min(i);
        let before = det_at.unwrap_or(start);
        let prep = if before > 0 { doc.word(before - 1).filter(|p| is_prep(p)).map(str::to_string) } else { None };
        // "a 3x2 array of posts", "a row of fins": the thing, not a reference.
        let prep = match prep.as_deref() {
            Some("of")
                if before >= 2
                    && doc.word(before - 2).is_some_and(|w| {
                        matches!(
                            w,
                            "array"
                                | "row"
                                | "grid"
                                | "pattern"
                                | "set"
                                | "pair"
                                | "series"
                                | "ring"
                                | "circle"
                                | "length"
                                | "piece"
                                | "bit"
                                | "stick"
                                | "offcut"
                                | "blank"
                        )
                    }) =>
            {
                None
            }
            _ => prep,
        };
        let prep = prep.or_else(|| {
            // "one in each flange ear": the preposition before the determiner's phrase.
            if before >= 2 && doc.word(before - 1).is_some_and(|w| w == "one") {
                doc.word(before - 2).filter(|p| is_prep(p)).map(str::to_string)
            } else {
                None
            }
        });
        mentions.push(Mention {
            head: i,
            start: first,
            noun: w.to_string(),
            kind,
            mods,
            shape,
            count,
            each,
            definite,
            prep,
            det: det_at.is_some(),
            plural: {
                let t = &doc.toks[i];
                let raw = doc.text.get(t.start..t.end).unwrap_or("").to_lowercase();
                raw != w && raw.ends_with('s')
            },
            sent: doc.sent[i],
            elem: usize::MAX,
            paren_aside: doc.depth[i] > 0
                && doc.sym(first.saturating_sub(1), '(')
                && doc.sym(i + 1, ')')
                && (first..i).all(|j| doc.word(j).is_some_and(|w| number_word(w).is_some())),
        });
    }
    let elements = group(doc, &mut mentions);
    (mentions, elements)
}

/// Whether a later mention refers to an element already met.
/// Words that tell two things of one noun apart ("the bottom plate", "the top plate").
const DISTINCT: &[&str] = &[
    "top", "bottom", "upper", "lower", "left", "right", "front", "back", "rear", "first", "second", "third", "inner",
    "outer", "large", "small", "larger", "smaller", "center", "central",
];

fn same_thing(m: &Mention, e: &Element) -> bool {
    let pos = |mods: &[String]| mods.iter().filter(|x| DISTINCT.contains(&x.as_str())).cloned().collect::<Vec<_>>();
    let (pm, pe) = (pos(&m.mods), pos(&e.mods));
    if !pm.is_empty() && !pe.is_empty() && pm.iter().all(|x| !pe.contains(x)) {
        return false;
    }
    // "The first pipe" of "two pipes" is a thing of its own (it may differ from the second).
    if e.plural && m.mods.iter().any(|x| matches!(x.as_str(), "first" | "second" | "third")) {
        return false;
    }
    // "a 1/2 inch hole … (four holes)": an aside naming it again, with its count.
    if m.noun == e.noun && m.paren_aside {
        return true;
    }
    // "a block … with a block on top": a thing the part has, said with "a", is another one.
    if m.prep.as_deref() == Some("with") && m.det && !m.definite && !m.each {
        return false;
    }
    // A bare plural or heading ("Side rails: each rail is …") also refers back.
    let bare = m.count.is_none() && !m.det;
    if !(m.definite || m.each || m.prep.is_some() || (bare && m.noun == e.noun)) {
        return false;
    }
    // A piece is not the whole it is a piece of ("the main pipe" of a "pipe tee fitting").
    if e.kind == Noun::Whole && m.kind != Noun::Whole && m.noun != e.noun {
        return false;
    }
    if m.noun == e.noun || e.noun.ends_with(&format!("-{}", m.noun)) {
        // "the bore" vs a "keyway ... along the bore wall": same noun is enough.
        return true;
    }
    // "each motor mount" → a "motor mount platform".
    e.mods.contains(&m.noun) && m.mods.iter().all(|x| e.mods.contains(x) || *x == e.noun || noun(x).is_none())
}

fn group(doc: &Doc, mentions: &mut [Mention]) -> Vec<Element> {
    let mut elements: Vec<Element> = Vec::new();
    for mi in 0..mentions.len() {
        let m = mentions[mi].clone();
        // "Motor mounts: four circular platforms …": a heading names what follows it.
        let heading = mi > 0 && {
            let h = &mentions[mi - 1];
            h.sent == m.sent
                && h.sent > 0
                && doc.sym(h.head + 1, ':')
                && m.start <= h.head + 4
                && doc.sentence(h.sent).0 + 3 > h.start
        };
        // "The groove is a ring between …", "The central hub is a … square plate": the
        // predicate is the subject.
        let predicate = m.start >= 2
            && matches!(doc.word(m.start - 1), Some("a" | "an"))
            && matches!(doc.word(m.start - 2), Some("is" | "are"))
            && mentions[..mi].iter().rev().find(|p| p.sent == m.sent && p.prep.is_none() && p.head < m.start).is_some();
        let subject = if predicate {
            mentions[..mi].iter().rposition(|p| p.sent == m.sent && p.prep.is_none() && p.head < m.start)
        } else {
            None
        };
        if heading || subject.is_some() {
            let id = mentions[subject.unwrap_or(mi - 1)].elem;
            mentions[mi].elem = id;
            let e = &mut elements[id];
            e.mentions.push(mi);
            e.shape = e.shape.or(m.shape);
            e.count = e.count.or(m.count);
            e.plural |= m.plural || m.count.is_some_and(|c| c > 1);
            for x in &m.mods {
                if !e.mods.contains(x) {
                    e.mods.push(x.clone());
                }
            }
            continue;
        }
        // A heading ("Holes: one 5mm …") starts its own thing.
        let is_heading = doc.sym(m.head + 1, ':') && m.sent > 0 && doc.sentence(m.sent).0 + 3 > m.start;
        let mut target = if is_heading { None } else { elements.iter().rposition(|e| same_thing(&m, e)) };
        // "The outer box is 70mm (X) by …": a definite general name with nothing before it
        // is the part itself.
        if target.is_none()
            && m.definite
            && !m.each
            && matches!(m.noun.as_str(), "box" | "body" | "block" | "container" | "enclosure" | "outline")
            && elements.first().is_some_and(|t| matches!(t.kind, Noun::Body(_) | Noun::Whole))
        {
            target = Some(0);
        }
        let id = match target {
            Some(id) => {
                let e = &mut elements[id];
                e.mentions.push(mi);
                if e.shape.is_none() {
                    e.shape = m.shape;
                }
                // "The left rail" of two rails names one of them, not a kind of them.
                e.plural |= m.plural || m.each || m.count.is_some_and(|c| c > 1);
                let plural = e.plural;
                for x in &m.mods {
                    if !(e.mods.contains(x) || plural && DISTINCT.contains(&x.as_str())) {
                        e.mods.push(x.clone());
                    }
                }
                if e.count.is_none() && !m.each {
                    e.count = m.count;
                }
                id
            }
            None => {
                elements.push(Element {
                    noun: m.noun.clone(),
                    kind: m.kind,
                    mods: m.mods.clone(),
                    shape: m.shape,
                    count: if m.each { None } else { m.count },
                    mentions: vec![mi],
                    dims: Vec::new(),
                    ranges: Vec::new(),
                    coords: Vec::new(),
                    tuples: Vec::new(),
                    angles: Vec::new(),
                    teeth: None,
                    title: elements.is_empty(),
                    plural: m.plural || m.count.is_some_and(|c| c > 1) || m.each,
                });
                elements.len() - 1
            }
        };
        mentions[mi].elem = id;
    }
    attach(doc, mentions, &mut elements);
    bare_lengths_to_the_part(doc, &mut elements);
    callout_places_to_the_hole(doc, &mut elements);
    sentence_adjectives(doc, mentions, &mut elements);
    elements
}

/// "4x Ø9 thru, c'bore Ø15 x 9 dp on 60 x 60": where a counterbored hole is placed is said
/// after its counterbore; the places are the holes'.
fn callout_places_to_the_hole(doc: &Doc, elements: &mut [Element]) {
    use super::lexicon::CutKind;
    for c in 0..elements.len() {
        if !matches!(elements[c].kind, Noun::Cut(CutKind::Counterbore | CutKind::Countersink)) {
            continue;
        }
        let Some(h) = (0..c).rev().find(|h| matches!(elements[*h].kind, Noun::Cut(CutKind::Hole))) else { continue };
        let moved: Vec<usize> = elements[c].dims.iter().copied().filter(|k| doc.dims[*k].has("pattern")).collect();
        move_dims(elements, c, h, &moved);
    }
}

/// "… a lamp base? Round, 120 across": a shape said on its own at the start of a sentence
/// is the shape of the thing the sentences are about.
fn sentence_adjectives(doc: &Doc, mentions: &[Mention], elements: &mut [Element]) {
    for s in 1..doc.sentences() {
        let (a, _) = doc.sentence(s);
        let Some(shape) = doc.word(a).and_then(shape_adjective) else { continue };
        // "Round, 120 across …", "Square 40 x 40 at the top, …".
        let sizes_follow = matches!(doc.toks.get(a + 1).map(|t| &t.kind), Some(Tk::Num { .. }));
        if !(doc.sym(a + 1, ',') || sizes_follow) || mentions.iter().any(|m| m.sent == s && m.start <= a + 1) {
            continue;
        }
        let Some(m) = mentions.iter().rev().find(|m| m.sent < s && m.prep.is_none()) else { continue };
        let target = m.elem;
        if elements[target].shape.is_some() {
            continue;
        }
        elements[target].shape = Some(shape);
        if let Some(w) = doc.word(a) {
            elements[target].mods.push(w.to_string());
        }
        doc.mark(a);
        // Its sizes, said before anything else is named in the sentence, are its too.
        let first = mentions.iter().filter(|m| m.sent == s).map(|m| m.start).min().unwrap_or(usize::MAX);
        for e in 0..elements.len() {
            if e == target {
                continue;
            }
            let moved: Vec<usize> = elements[e]
                .dims
                .iter()
                .copied()
                .filter(|k| doc.sent[doc.dims[*k].tok] == s && doc.dims[*k].tok < first)
                .collect();
            move_dims(elements, e, target, &moved);
        }
    }
}

/// "lying flat on the XY plane (Z=0 to Z=3)": the whole part's span, nobody's own.
pub fn is_part_range(doc: &Doc, k: usize) -> bool {
    let r = &doc.ranges[k];
    (r.toks.0.saturating_sub(8)..r.toks.0).any(|i| matches!(doc.word(i), Some("lying" | "lies" | "lie")))
}

/// Whether a length of this role can belong to an element of this kind (a bore has no
/// height: "15mm bore (inner diameter), and 12mm height" — the height is the ring's).
fn fits(kind: Noun, dim: Option<&super::doc::Dim>) -> bool {
    use super::doc::Role::*;
    use super::lexicon::CutKind;
    let Some(dim) = dim else { return true };
    let role = dim.role;
    match kind {
        Noun::Cut(CutKind::Hole | CutKind::Bore | CutKind::Counterbore | CutKind::Countersink) => {
            let polygon = dim.has("across") && (dim.has("flat") || dim.has("corner"));
            // An outside size is never a hole's ("bore 12, OD 25").
            if dim.has("outer") {
                return false;
            }
            matches!(role, Diameter | Radius | Depth | Inset | Spacing)
                || (role == Bare && !polygon && dim.axis.is_none() && (dim.list.is_none() || dim.has("pattern")))
                || (role == Bare && dim.has("pattern"))
        }
        Noun::Fillet | Noun::Chamfer => matches!(role, Bare | Fillet | Chamfer | Radius),
        _ => true,
    }
}

/// The element a quantity at token `t` belongs to.
fn owner(doc: &Doc, mentions: &[Mention], t: usize) -> Option<usize> {
    owner_fit(doc, mentions, t, None, &[])
}

fn owner_fit(
    doc: &Doc,
    mentions: &[Mention],
    t: usize,
    role: Option<&super::doc::Dim>,
    kinds: &[Noun],
) -> Option<usize> {
    let kind_of = |m: &Mention| kinds.get(m.elem).copied().unwrap_or(m.kind);
    let s = doc.sent[t];
    // Inside a mention's phrase (before its head): that mention.
    if let Some(m) = mentions.iter().find(|m| m.sent == s && t >= m.start && t < m.head) {
        return Some(m.elem);
    }
    // A pre-modifier of the next head with only phrase words between.
    // Else the last mention before it in the sentence that is not a preposition's object
    // (a subject or a "with" feature); else the sentence's first mention; else the last
    // subject of an earlier sentence.
    let before: Vec<&Mention> = mentions.iter().filter(|m| m.sent == s && m.head < t).collect();
    // A mention inside parentheses owns nothing outside them.
    let aside = |m: &Mention| doc.depth[m.head] > doc.depth[t];
    if let Some(m) = before
        .iter()
        .rev()
        .find(|m| (m.prep.is_none() || m.prep.as_deref() == Some("with")) && fits(kind_of(m), role) && !aside(m))
    {
        return Some(m.elem);
    }
    if let Some(m) = mentions.iter().find(|m| m.sent == s && (m.prep.is_none() || m.prep.as_deref() == Some("with"))) {
        return Some(m.elem);
    }
    mentions.iter().rev().find(|m| m.sent < s && m.prep.is_none()).map(|m| m.elem)
}

/// A hole whose diameter is given takes no bare length of no kind ("Hex standoff, M3, 5.5
/// A/F, 30 mm, threaded through": the 30 is the part's): it goes to the part.
fn bare_lengths_to_the_part(doc: &Doc, elements: &mut [Element]) {
    let Some(t) = elements.iter().position(|e| e.title && matches!(e.kind, Noun::Body(_))) else { return };
    for c in 0..elements.len() {
        if c == t || !matches!(elements[c].kind, Noun::Cut(_)) {
            continue;
        }
        let first_d = elements[c]
            .dims
            .iter()
            .filter(|k| {
                let d = &doc.dims[**k];
                matches!(d.role, super::doc::Role::Diameter | super::doc::Role::Radius)
                    && !d.has("counterbore")
                    && !d.has("countersink")
            })
            .map(|k| doc.dims[*k].tok)
            .min();
        let Some(first_d) = first_d else { continue };
        let moved: Vec<usize> = elements[c]
            .dims
            .iter()
            .copied()
            .filter(|k| {
                let d = &doc.dims[*k];
                d.role == super::doc::Role::Bare
                    && d.quals.is_empty()
                    && d.list.is_none()
                    && d.axis.is_none()
                    && !d.paren
                    && d.tok > first_d
            })
            .collect();
        move_dims(elements, c, t, &moved);
    }
}

/// Gives lengths read as one element's to another.
fn move_dims(elements: &mut [Element], from: usize, to: usize, moved: &[usize]) {
    if moved.is_empty() {
        return;
    }
    elements[from].dims.retain(|k| !moved.contains(k));
    elements[to].dims.extend_from_slice(moved);
    elements[to].dims.sort_unstable();
}

fn attach(doc: &Doc, mentions: &[Mention], elements: &mut [Element]) {
    if elements.is_empty() {
        return;
    }
    for (k, d) in doc.dims.iter().enumerate() {
        // A restatement in parentheses right after another length: that length's owner.
        let o =
            if d.paren && k > 0 && doc.dims[k - 1].tok + 8 > d.tok && doc.depth[doc.dims[k - 1].tok] < doc.depth[d.tok]
            {
                owner(doc, mentions, doc.dims[k - 1].tok)
            } else {
                let kinds: Vec<Noun> = elements.iter().map(|e| e.kind).collect();
                owner_fit(doc, mentions, d.tok, Some(d), &kinds)
            };
        // "Total height 35mm", "40mm overall length": the part's own.
        // (Not a cut's own: "a slot, 40 long overall".)
        let of_cut = o.is_some_and(|o| matches!(elements[o].kind, Noun::Cut(_)));
        let o = if (d.has("total") || d.has("overall")) && !of_cut {
            elements.iter().position(|e| e.title).or(o)
        } else {
            o
        };
        if let Some(o) = o.and_then(|o| elements.get_mut(o)) {
            o.dims.push(k);
        }
    }
    for (k, r) in doc.ranges.iter().enumerate() {
        // "lying flat on the XY plane (Z=0 to Z=3)": the whole part's.
        if is_part_range(doc, k) {
            continue;
        }
        let o = owner(doc, mentions, r.toks.0);
        if let Some(o) = o.and_then(|o| elements.get_mut(o)) {
            o.ranges.push(k);
        }
    }
    for (k, c) in doc.coords.iter().enumerate() {
        if let Some(o) = owner(doc, mentions, c.tok).and_then(|o| elements.get_mut(o)) {
            o.coords.push(k);
        }
    }
    for (k, t) in doc.tuples.iter().enumerate() {
        if let Some(o) = owner(doc, mentions, t.toks.0).and_then(|o| elements.get_mut(o)) {
            o.tuples.push(k);
        }
    }
    for (i, t) in doc.toks.iter().enumerate() {
        match t.kind {
            Tk::Deg(a) => {
                if let Some(o) = owner(doc, mentions, i).and_then(|o| elements.get_mut(o)) {
                    o.angles.push((i, a));
                }
            }
            // "16 teeth", "16-tooth", "32 vertices", a star-shaped part's "5 points".
            Tk::Num { v, unit: None, .. } if v.fract() == 0.0 && v >= 1.0 => {
                let star_points = doc.is(i + 1, "point") && (0..doc.toks.len()).any(|j| doc.is(j, "star-shaped"));
                let per = if doc.is(i + 1, "tooth")
                    || star_points
                    || (doc.is(i + 2, "tooth") && doc.word(i + 1).is_some_and(|w| shape_adjective(w).is_some()))
                {
                    Some(1)
                } else if doc.is(i + 1, "vertex") {
                    Some(2)
                } else {
                    None
                };
                if let Some(per) = per
                    && let Some(o) = owner(doc, mentions, i).and_then(|o| elements.get_mut(o))
                {
                    o.teeth.get_or_insert((v as u32) / per);
                    let last =
                        if doc.is(i + 1, "tooth") || doc.is(i + 1, "vertex") || star_points { i + 1 } else { i + 2 };
                    doc.mark_range(i, last + 1);
                }
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subjects_own_their_lengths_and_objects_do_not() {
        let doc = Doc::new(
            "A flanged bushing. The flange is at the bottom: 30mm outer diameter, 3mm thick (Z=0 to Z=3). \
             The cylindrical body extends upward from the flange: 20mm outer diameter, 30mm long (Z=3 to Z=33). \
             A 10mm diameter bore runs through the entire length of the part.",
        );
        let (_, els) = read(&doc);
        let names: Vec<&str> = els.iter().map(|e| e.noun.as_str()).collect();
        // "The cylindrical body", with nothing before it, is the bushing itself.
        assert_eq!(names, vec!["bushing", "flange", "bore", "part"]);
        let mm = |e: &Element| e.dims.iter().map(|k| doc.dims[*k].mm).collect::<Vec<_>>();
        assert_eq!(mm(&els[1]), vec![30.0, 3.0]);
        assert_eq!(mm(&els[0]), vec![20.0, 30.0]);
        assert_eq!(els[0].ranges.len(), 1);
        assert_eq!(mm(&els[2]), vec![10.0]);
    }

    #[test]
    fn compounds_counts_and_coreference() {
        let doc = Doc::new(
            "A hex bolt: a 10mm diameter cylindrical shaft, 30mm long, with a hexagonal head on top. \
             The head has a 19.6mm circumscribed circle diameter and is 7mm tall. Four M3 mounting holes (3.2mm diameter).",
        );
        let (_, els) = read(&doc);
        let names: Vec<&str> = els.iter().map(|e| e.noun.as_str()).collect();
        assert_eq!(names, vec!["bolt", "shaft", "head", "hole"]);
        assert_eq!(els[2].shape, Some(ShapeHint::Ngon(6)));
        assert_eq!(els[2].dims.len(), 2);
        assert_eq!(els[3].count, Some(4));
    }
}
