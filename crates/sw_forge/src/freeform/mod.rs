//! Free-form objects offline: "a coffee mug with a handle", "a dumbbell", "a chair with
//! four legs and a backrest", "a wheelbarrow". The object is named by the prompt's words;
//! the procedural catalog makes it when it has it, else a parametric composition of
//! parts ([`basic`] shapes, [`objects`]) with real proportions and sizes. Size words
//! ("large", "tall", "thick", "long" …) scale it; "with …", "on …" name features the object
//! must have. A word that is none of these refuses the prompt with that word.

pub mod basic;
pub mod objects;
pub mod shapes;

use sw_geom::{Asset, Mesh};

use crate::synth::model::Model;
use crate::synth::text::{Tk, tokenize};
use crate::synth::{SynthError, Synthesis, finish};

/// How the size words scale an object (1 = as made).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spec {
    pub size: f64,
    pub tall: f64,
    pub long: f64,
    pub thick: f64,
    pub wide: f64,
    /// "three steps", "two hooks".
    pub count: Option<u32>,
}

impl Default for Spec {
    fn default() -> Self {
        Self { size: 1.0, tall: 1.0, long: 1.0, thick: 1.0, wide: 1.0, count: None }
    }
}

/// A composition: what it is called, the features its words may name, its builder.
#[derive(Debug, Clone, Copy)]
pub struct Build {
    pub names: &'static [&'static str],
    pub features: &'static [&'static str],
    pub build: fn(&Spec) -> Model,
}

/// A free-form object made.
#[derive(Debug, Clone)]
pub enum Freeform {
    /// The procedural catalog's object (metres, in its own materials).
    Catalog { category: &'static str, asset: Box<Asset> },
    /// A composition, as a model of the feature language (mm).
    Composed { object: &'static str, synthesis: Box<Synthesis> },
}

/// Features of catalog objects the words may name (the catalog's generator makes them).
const CATALOG_FEATURES: &[(&str, &[&str])] = &[
    ("mug", &["handle"]),
    ("cup", &["handle"]),
    ("bottle", &["cap", "lid"]),
    ("fire_extinguisher", &["hose", "handle", "nozzle"]),
    ("traffic_cone", &["base", "flat base", "square base"]),
    ("chair", &["legs", "four legs", "backrest", "back", "seat"]),
    ("dining_table", &["legs", "four legs", "top"]),
    ("table", &["legs", "four legs", "top"]),
    ("bookshelf", &["shelves", "shelf"]),
    ("desk_lamp", &["arm", "bent arm", "shade", "base"]),
    ("sofa", &["armrests", "arms", "cushions", "back"]),
    ("monitor", &["stand", "screen"]),
    ("shopping_cart", &["wheels", "handle", "basket"]),
    ("desk", &["drawers", "drawer"]),
    ("bucket", &["handle", "wire handle"]),
    ("saucepan", &["handle", "long handle"]),
    ("coat_rack", &["hooks", "base", "round base"]),
    ("teapot", &["handle", "lid", "spout"]),
    ("desk_fan", &["base", "foot", "round foot", "stand"]),
];

/// Size words and what they scale.
fn size_word(w: &str, s: &mut Spec) -> bool {
    match w {
        "large" | "big" => s.size *= 1.6,
        "huge" | "giant" | "enormous" => s.size *= 2.5,
        "small" | "little" | "mini" => s.size *= 0.6,
        "tiny" => s.size *= 0.35,
        "tall" | "high" => s.tall *= 1.6,
        "short" | "low" => s.tall *= 0.6,
        "long" => s.long *= 2.0,
        "thick" | "chunky" | "heavy" => s.thick *= 1.8,
        "thin" | "slim" | "slender" => s.thick *= 0.5,
        "wide" | "broad" => s.wide *= 1.6,
        "narrow" => s.wide *= 0.6,
        "flat" => s.tall *= 0.6,
        _ => return false,
    }
    true
}

/// Words that say nothing of the geometry of a free-form object.
fn is_plain(w: &str) -> bool {
    matches!(
        w,
        "a" | "an"
            | "the"
            | "one"
            | "simple"
            | "basic"
            | "plain"
            | "solid"
            | "shape"
            | "shaped"
            | "object"
            | "model"
            | "standard"
            | "typical"
            | "ordinary"
            | "classic"
            | "regular"
            | "some"
            | "of"
            | "for"
            | "kind"
            | "sort"
            | "style"
            | "red"
            | "blue"
            | "green"
            | "yellow"
            | "black"
            | "white"
            | "grey"
            | "gray"
            | "brown"
            | "orange"
            | "wooden"
            | "metal"
            | "steel"
            | "plastic"
            | "ceramic"
            | "glass"
            | "rubber"
            | "new"
            | "old"
            | "nice"
    )
}

/// Objects open inside by nature, of which "hollow" says nothing more ("a hollow pipe"); a
/// hollow ball or a hollow block is not made.
fn hollow_by_nature(cand: &Candidate) -> bool {
    const OPEN: &[&str] = &["pipe", "tube", "cup", "mug", "bucket", "vase", "bowl", "pot", "bottle", "glass", "ring"];
    let names: Vec<&str> = match cand {
        Candidate::Basic(b) | Candidate::Object(b) => b.names.to_vec(),
        Candidate::Catalog(c) => std::iter::once(c.name).chain(c.synonyms.iter().copied()).collect(),
    };
    names.iter().any(|n| n.split([' ', '_']).any(|w| OPEN.contains(&w)))
}

/// One of the objects the words may name: a catalog category or a composition.
#[derive(Debug, Clone, Copy)]
enum Candidate {
    Basic(&'static Build),
    Catalog(&'static sw_catalog::Category),
    Object(&'static Build),
}

impl Candidate {
    /// Ties between phrases of one length go to basic shapes ("a cone" is a cone, not a
    /// traffic cone), then the catalog, then compositions.
    fn rank(&self) -> u8 {
        match self {
            Candidate::Basic(_) => 0,
            Candidate::Catalog(_) => 1,
            Candidate::Object(_) => 2,
        }
    }

    fn features(&self) -> &'static [&'static str] {
        match self {
            Candidate::Basic(b) | Candidate::Object(b) => b.features,
            Candidate::Catalog(c) => CATALOG_FEATURES.iter().find(|(n, _)| *n == c.name).map_or(&[], |(_, f)| *f),
        }
    }

    fn same(&self, other: &Candidate) -> bool {
        match (self, other) {
            (Candidate::Basic(a), Candidate::Basic(b)) | (Candidate::Object(a), Candidate::Object(b)) => {
                std::ptr::eq(*a, *b)
            }
            (Candidate::Catalog(a), Candidate::Catalog(b)) => a.name == b.name,
            _ => false,
        }
    }
}

fn phrases() -> Vec<(Vec<String>, Candidate)> {
    let split = |p: &str| p.split_whitespace().map(crate::synth::text::fold).collect::<Vec<_>>();
    let mut out = Vec::new();
    for b in basic::BASIC {
        out.extend(b.names.iter().map(|n| (split(n), Candidate::Basic(b))));
    }
    for c in sw_catalog::categories() {
        out.push((split(c.display), Candidate::Catalog(c)));
        out.push((split(&c.name.replace('_', " ")), Candidate::Catalog(c)));
        out.extend(c.synonyms.iter().filter(|n| !names_a_part(n)).map(|n| (split(n), Candidate::Catalog(c))));
    }
    for b in objects::OBJECTS {
        out.extend(b.names.iter().map(|n| (split(n), Candidate::Object(b))));
    }
    out
}

/// A catalog object's other name that is one word the feature language reads as a body
/// of a part ("washer" is a washing machine's and a flat ring's): the forge, asked for
/// parts, reads it as the part, which needs sizes. The object's own name still makes it.
fn names_a_part(name: &str) -> bool {
    let mut words = name.split_whitespace().map(crate::synth::text::fold);
    match (words.next(), words.next()) {
        (Some(w), None) => matches!(crate::synth::lexicon::noun(&w), Some(crate::synth::lexicon::Noun::Body(_))),
        _ => false,
    }
}

fn unread(phrase: &str, reason: &str) -> SynthError {
    SynthError::Unread { phrase: phrase.to_string(), reason: reason.to_string() }
}

/// Reads a free-form prompt and makes the object.
pub fn read(prompt: &str) -> Result<Freeform, SynthError> {
    let toks = tokenize(prompt);
    if toks.iter().any(|t| matches!(t.kind, Tk::Num { unit: Some(_), .. })) {
        return Err(unread(
            prompt.trim(),
            "a free-form object is named without sizes (sizes make it a dimensioned part)",
        ));
    }
    // Words, with where they are.
    let words: Vec<(String, usize, usize)> = toks
        .iter()
        .filter_map(|t| match &t.kind {
            Tk::Word(w) => Some((w.clone(), t.start, t.end)),
            Tk::Num { v, unit: None, .. } => Some((format!("#{v}"), t.start, t.end)),
            _ => None,
        })
        .collect();
    // The object: the longest name found, its first place; every object of that name there,
    // as ranked.
    let mut best: Option<(usize, usize)> = None;
    let mut tied: Vec<Candidate> = Vec::new();
    for (name, cand) in phrases() {
        let n = name.len();
        if n == 0 || n > words.len() {
            continue;
        }
        let Some(at) = (0..=words.len() - n).find(|&at| (0..n).all(|k| words[at + k].0 == name[k])) else {
            continue;
        };
        // Longest, then first said (features come after the object).
        let better = best.is_none_or(|(ba, bn)| n > bn || (n == bn && at < ba));
        if better {
            best = Some((at, n));
            tied.clear();
        }
        if best == Some((at, n)) && !tied.iter().any(|c| c.same(&cand)) {
            tied.push(cand);
        }
    }
    let Some((at, n)) = best else {
        let text = prompt.trim();
        return Err(unread(
            text,
            "the synthesizer knows no object by these words (a catalog object, a shape, or a dimensioned part)",
        ));
    };
    // "a lamp shade", "the leg of a table": the head of the noun phrase is a part of the
    // object, not the object; the whole object is never made for it.
    if let Some(part) = part_of_object(&words, at, n) {
        return Err(unread(
            &part,
            "this names a part of an object, not the whole object: give the part's sizes to make it as a part",
        ));
    }
    tied.sort_by_key(Candidate::rank);
    // The first object of the name that honours every word; else the refusal of the first
    // one that knows the refused words (a part of it, a count of its feature), else the
    // first one's: "a bathtub with legs" is the composition when the catalog's tub has none.
    let mut refusals = Vec::new();
    for cand in tied {
        match read_as(prompt, &words, at, n, cand) {
            Ok(spec) => return make(prompt, cand, &spec),
            Err(r) => refusals.push(r),
        }
    }
    let first_known = refusals.iter().position(|r| r.known).unwrap_or(0);
    match refusals.into_iter().nth(first_known) {
        Some(r) => Err(r.error),
        None => Err(unread(prompt.trim(), "the synthesizer knows no object by these words")),
    }
}

/// Nouns that name a part of an object rather than an object ("shade", "leg", "lid").
const PART_NOUNS: &[&str] = &[
    "shade",
    "leg",
    "top",
    "tabletop",
    "shelf",
    "lid",
    "door",
    "drawer",
    "handle",
    "knob",
    "seat",
    "backrest",
    "armrest",
    "arm",
    "base",
    "foot",
    "wheel",
    "blade",
    "cap",
    "cover",
    "panel",
    "frame",
    "rail",
    "spout",
    "stem",
    "bulb",
    "cushion",
    "hinge",
    "tray",
    "rung",
    "slat",
    "caster",
    "castor",
    "pedal",
    "post",
    "stretcher",
    "apron",
    "plinth",
    "hood",
    "strap",
    "spoke",
];

/// The part a prompt names of the object found at `at` (`n` words): the noun right after
/// the object's name ("lamp shade": the head of the compound) or before "of" the object
/// ("the leg of a table").
fn part_of_object(words: &[(String, usize, usize)], at: usize, n: usize) -> Option<String> {
    let is_part = |w: &str| PART_NOUNS.contains(&crate::synth::text::fold(w).as_str());
    if let Some((w, _, _)) = words.get(at + n)
        && is_part(w)
    {
        return Some(format!("{} {w}", words[at..at + n].iter().map(|x| x.0.as_str()).collect::<Vec<_>>().join(" ")));
    }
    let mut k = at;
    while k > 0 && matches!(words[k - 1].0.as_str(), "a" | "an" | "the" | "this" | "that") {
        k -= 1;
    }
    if k >= 2 && words[k - 1].0 == "of" && is_part(&words[k - 2].0) {
        return Some(format!(
            "{} of {}",
            words[k - 2].0,
            words[at..at + n].iter().map(|x| x.0.as_str()).collect::<Vec<_>>().join(" ")
        ));
    }
    None
}

/// Why an object of the prompt's name cannot be made as the prompt says.
struct Refusal {
    error: SynthError,
    /// The object knows the refused words (a part of it, a feature with another count).
    known: bool,
}

impl Refusal {
    fn known(error: SynthError) -> Self {
        Self { error, known: true }
    }

    fn unknown(error: SynthError) -> Self {
        Self { error, known: false }
    }
}

/// Reads the words around the object's name (`n` words at `at`) as `cand`: its size words
/// and the features it is said to have.
fn read_as(
    prompt: &str,
    words: &[(String, usize, usize)],
    at: usize,
    n: usize,
    cand: Candidate,
) -> Result<Spec, Refusal> {
    let quote = |a: usize, b: usize| prompt.get(words[a].1..words[b].2).unwrap_or("").to_string();
    let mut spec = Spec::default();
    // Before the name: size and plain words, or another name of it and "or" ("a goblet
    // or wine glass").
    let names: Vec<Vec<String>> = phrases().into_iter().filter(|(_, c)| c.same(&cand)).map(|(n, _)| n).collect();
    let mut i = 0;
    while i < at {
        let w = &words[i].0;
        let hollow = w == "hollow" && hollow_by_nature(&cand);
        if is_plain(w) || hollow || size_word(w, &mut spec) || (w == "or" && i > 0) {
            i += 1;
            continue;
        }
        let other = names
            .iter()
            .filter(|nm| {
                !nm.is_empty()
                    && i + nm.len() <= at
                    && (0..nm.len()).all(|k| words[i + k].0 == nm[k])
                    && words.get(i + nm.len()).is_some_and(|x| x.0 == "or")
            })
            .map(Vec::len)
            .max();
        match other {
            Some(len) => i += len,
            None if cand
                .features()
                .iter()
                .any(|f| f.split_whitespace().map(crate::synth::text::fold).any(|x| x == *w)) =>
            {
                return Err(Refusal::known(unread(&quote(i, at + n - 1), &part_of(&cand))));
            }
            None => {
                return Err(Refusal::unknown(unread(&quote(i, i), "a word the synthesizer cannot give this object")));
            }
        }
    }
    // After it: "with …", "on …", "and …", "or <another name of it>": features it has.
    let feats = cand.features();
    let mut i = at + n;
    // A feature named right after the object, with nothing joining them ("a lamp shade",
    // "a table leg"), is that part of it, not the object with it.
    let mut joined = false;
    while i < words.len() {
        let w = words[i].0.clone();
        if matches!(w.as_str(), "with" | "on" | "and" | "having" | "has") {
            joined = true;
            i += 1;
            continue;
        }
        if is_plain(&w) {
            i += 1;
            continue;
        }
        if w == "or" {
            // "a goblet or wine glass": another name of the same object.
            let rest: Vec<String> = words[i + 1..].iter().map(|x| x.0.clone()).filter(|x| !is_plain(x)).collect();
            let same = phrases().into_iter().any(|(name, c)| {
                c.same(&cand) && !name.is_empty() && rest.starts_with(&name) && rest.len() == name.len()
            });
            if same {
                break;
            }
            return Err(Refusal::unknown(unread(&quote(i, words.len() - 1), "two different objects")));
        }
        // A count ("three steps", "four legs").
        let mut count = None;
        let mut j = i;
        if let Some(c) = crate::synth::lexicon::number_word(&w).or_else(|| {
            w.strip_prefix('#')
                .and_then(|v| v.parse::<f64>().ok())
                .filter(|v| v.fract() == 0.0 && *v >= 1.0)
                .map(|v| v as u32)
        }) {
            count = Some(c);
            j += 1;
        }
        // The longest feature phrase here.
        let hit = feats
            .iter()
            .map(|f| f.split_whitespace().map(crate::synth::text::fold).collect::<Vec<_>>())
            .filter(|f| f.len() + j <= words.len() && (0..f.len()).all(|k| words[j + k].0 == f[k]))
            .max_by_key(Vec::len);
        let Some(f) = hit else {
            return Err(Refusal::unknown(unread(
                &quote(i, (i + 2).min(words.len() - 1)),
                "a feature the synthesizer cannot give this object",
            )));
        };
        if !joined {
            return Err(Refusal::known(unread(&quote(at, j + f.len() - 1), &part_of(&cand))));
        }
        if let Some(c) = count {
            check_count(&cand, &f, c).map_err(|reason| Refusal::known(unread(&quote(i, j + f.len() - 1), &reason)))?;
            spec.count = Some(c);
        }
        i = j + f.len();
    }
    Ok(spec)
}

/// Why a part of an object is not made as the object: the whole is never handed out for it.
fn part_of(cand: &Candidate) -> String {
    let name = match cand {
        Candidate::Basic(b) | Candidate::Object(b) => b.names.first().copied().unwrap_or("object").to_string(),
        Candidate::Catalog(c) => c.display.to_string(),
    };
    format!(
        "this names a part of a {name}, and the synthesizer makes only whole objects without sizes \
         (give the part's sizes to make it as a dimensioned part)"
    )
}

/// The counts an object can have of a feature.
fn check_count(cand: &Candidate, feature: &[String], c: u32) -> Result<(), String> {
    let f = feature.join(" ");
    let ok = match cand {
        Candidate::Catalog(cat) => match (cat.name, f.as_str()) {
            ("chair" | "dining_table" | "table", "leg") => c == 4,
            ("mug" | "cup" | "bucket" | "saucepan" | "teapot", "handle") => c == 1,
            // Two crossed bars: a hook at each of their four ends.
            ("coat_rack", "hook") => c == 4,
            _ => false,
        },
        Candidate::Object(b) | Candidate::Basic(b) => match (b.names.first().copied(), f.as_str()) {
            (Some("staircase"), "step") => (1..=30).contains(&c),
            (Some("coat rack"), "hook") => c == 2 || c == 4,
            (Some("bathtub"), "leg" | "foot") => c == 4,
            (Some("trophy"), "handle") => c == 2,
            (Some("bucket" | "saucepan" | "hammer" | "mallet" | "microphone" | "plunger"), "handle") => c == 1,
            _ => false,
        },
    };
    if ok { Ok(()) } else { Err(format!("the synthesizer makes this object with a different number of {f}")) }
}

fn make(prompt: &str, cand: Candidate, spec: &Spec) -> Result<Freeform, SynthError> {
    match cand {
        Candidate::Catalog(cat) => {
            let mut req = sw_catalog::AssetRequest::new(cat.name, 0);
            let s = spec.size;
            req.scale = Some([s * spec.wide * spec.long, s * spec.wide * spec.thick, s * spec.tall]);
            let asset = sw_catalog::generate(&req).map_err(|e| unread(cat.display, &e.to_string()))?;
            Ok(Freeform::Catalog { category: cat.name, asset: Box::new(asset) })
        }
        Candidate::Basic(b) | Candidate::Object(b) => {
            let model = (b.build)(spec);
            let object = b.names.first().copied().unwrap_or("object");
            let synthesis = finish(prompt.trim(), &format!("freeform:{}", object.replace(' ', "_")), &model);
            Ok(Freeform::Composed { object, synthesis: Box::new(synthesis) })
        }
    }
}

/// What the offline synthesizer makes of a prompt: code (a dimensioned part of the
/// feature language, or a composed free-form object), or the catalog's object.
#[derive(Debug, Clone)]
pub enum Offline {
    Code(Box<Synthesis>),
    Catalog { category: &'static str, asset: Box<Asset> },
}

/// Reads a prompt offline: a prompt with sizes is a dimensioned part; one without is a
/// free-form object.
pub fn offline(prompt: &str) -> Result<Offline, SynthError> {
    match crate::synth::synthesize(prompt) {
        Ok(s) => Ok(Offline::Code(Box::new(s))),
        Err(SynthError::NoDimensions) => match read(prompt)? {
            Freeform::Catalog { category, asset } => Ok(Offline::Catalog { category, asset }),
            Freeform::Composed { synthesis, .. } => Ok(Offline::Code(synthesis)),
        },
        Err(e) => Err(e),
    }
}

/// A catalog object's visual meshes as one mesh, in millimetres (Z up, on its floor).
pub fn catalog_mesh_mm(asset: &Asset) -> Mesh {
    let mut out = Mesh::default();
    for (link, pose) in asset.links.iter().zip(asset.link_poses()) {
        for v in &link.visuals {
            out.append(&v.mesh, &pose);
        }
    }
    for p in &mut out.vertices {
        for c in p.iter_mut() {
            *c *= 1000.0;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn made(p: &str) -> String {
        match read(p) {
            Ok(Freeform::Catalog { category, .. }) => format!("catalog:{category}"),
            Ok(Freeform::Composed { object, .. }) => format!("composed:{object}"),
            Err(e) => format!("error: {e}"),
        }
    }

    #[test]
    fn objects_are_named_by_their_longest_phrase() {
        assert_eq!(made("a coffee mug with a handle"), "catalog:mug");
        assert_eq!(made("a cone"), "composed:cone");
        assert_eq!(made("a traffic cone on a flat base"), "catalog:traffic_cone");
        // The catalog makes what it has, by its longest name ("desk fan", not "fan"); a
        // longer name of a composition beats a shorter catalog one ("trophy cup", not "cup").
        assert_eq!(made("a desk fan shape"), "catalog:desk_fan");
        assert_eq!(made("a trophy cup"), "composed:trophy");
        // Of one name, the object that has the features said: the catalog's bathtub has no
        // legs, the composition has.
        assert_eq!(made("a bathtub"), "catalog:bathtub");
        assert_eq!(made("a bathtub with legs"), "composed:bathtub");
        assert_eq!(made("a goblet or wine glass"), "catalog:wine_glass");
        assert_eq!(made("a chalice or goblet"), "composed:goblet");
        assert_eq!(made("a staircase with three steps"), "composed:staircase");
    }

    #[test]
    fn words_it_cannot_honour_are_refused_with_the_words() {
        let e = made("a chair with three legs");
        assert!(e.starts_with("error") && e.contains("three legs"), "{e}");
        let e = made("a mug with a dragon");
        assert!(e.contains("dragon"), "{e}");
        let e = made("a teleporter");
        assert!(e.starts_with("error"), "{e}");
        let e = made("a hammer or a saw");
        assert!(e.contains("saw"), "{e}");
    }

    #[test]
    fn a_part_noun_is_the_part_not_the_catalog_object_of_that_other_name() {
        // "washer", "rod", "wheel" are a washing machine's, a cylinder's, a tyre's other
        // names and parts of the feature language: without sizes the part is refused.
        for p in ["a washer", "a flat washer", "a rod", "a wheel", "a dowel"] {
            let e = made(p);
            assert!(e.starts_with("error") && e.contains("knows no object"), "{p}: {e}");
        }
        // The object's own names still make it.
        assert_eq!(made("a washing machine"), "catalog:washing_machine");
        assert_eq!(made("a front loader"), "catalog:washing_machine");
        assert_eq!(made("a tire"), "catalog:tire");
    }

    #[test]
    fn a_part_of_an_object_is_never_the_whole_object() {
        // Every object with features: "<object> <feature>" and "<feature> of a <object>"
        // name the part, and are refused with those words; "with a <feature>" is the whole.
        for (names, feats) in objects::OBJECTS.iter().map(|b| (b.names, b.features)) {
            let (Some(name), Some(feat)) = (names.first(), feats.first()) else { continue };
            let p = format!("a {name} {feat}");
            let e = made(&p);
            assert!(e.starts_with("error") && e.contains("part of"), "{p}: {e}");
            // Said the other way round it is refused too (as a part, or as another object's
            // feature when the part is an object of its own: "the pedestal of a trophy").
            let p = format!("the {feat} of a {name}");
            assert!(made(&p).starts_with("error"), "{p}");
            let whole = made(&format!("a {name} with a {feat}"));
            assert!(!whole.starts_with("error") || whole.contains("number of"), "{name} with {feat}: {whole}");
        }
        for (cat, feats) in CATALOG_FEATURES {
            let Some(c) = sw_catalog::categories().iter().find(|c| c.name == *cat) else { continue };
            let Some(feat) = feats.iter().find(|f| !f.contains(' ')) else { continue };
            let p = format!("a {} {feat}", c.display);
            let e = made(&p);
            assert!(e.starts_with("error") && e.contains("part of"), "{p}: {e}");
        }
    }
}
