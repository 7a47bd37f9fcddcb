//! Part families: a named part (a collar, a spacer, a washer, a flange, a pulley, a hex nut,
//! a standoff, a key, a shim, an angle, a channel, a beam, a tee, a gusset, or a part of a
//! piece of furniture named as stock — "a table leg") read as a parametric template with
//! named dimensions. The prompt's lengths bind to the template's parameters by the roles
//! their words give them (bore / ID, OD, width, thickness, PCD, hole count and size, across
//! flats, legs, web), by the order a standard's designation writes them ("50 x 50 x 5" an
//! angle's legs and thickness, EN 10056), or by a parenthesised legend ("(web x flange x
//! thickness)"). A dimension the family needs and the prompt does not give is taken from a
//! standard only where the prompt names one that defines it (ISO 7089 washers, ISO 4032
//! nuts, ISO 261 coarse tap drills); otherwise the part is refused, quoting the family and
//! naming the missing dimension.
//!
//! Every word must be one the family reads or carries no geometry, else the family layer
//! declines and the feature language's refusal stands. The self-check is a second reading:
//! the extents and volume each family's closed formula gives from its parameters, compared
//! with the model built from bodies and cuts.

use std::f64::consts::PI;

use super::doc::Doc;
use super::lexicon;
use super::model::Model;
use super::notation;
use super::profile::Profile;
use super::read::{Refusal, Res};
use super::solid::{Axis, Body, Shape};
use super::text::Tk;

/// A family of parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// A plain ring: collar, spacer, bushing, sleeve, washer, tube.
    Ring,
    /// A flat ring or disc with a bolt circle: flange, blind flange.
    Flange,
    /// A flat pulley with an optional hub on one side.
    Pulley,
    HexNut,
    Standoff,
    /// A rectangular bar: key, keystock, shim, flat bar, board.
    Bar,
    /// A round pin (dowel pin, pin, rod).
    Pin,
    Angle,
    Channel,
    Beam,
    Tee,
    Gusset,
    /// A part of an object named as stock: a leg, a shelf, a top, a rail.
    Stock,
}

/// The names of the families (folded words, in order).
const NAMES: &[(&[&str], Family)] = &[
    (&["collar"], Family::Ring),
    (&["spacer"], Family::Ring),
    (&["bushing"], Family::Ring),
    (&["bush"], Family::Ring),
    (&["sleeve"], Family::Ring),
    (&["washer"], Family::Ring),
    (&["tube"], Family::Ring),
    (&["flange"], Family::Flange),
    (&["pulley"], Family::Pulley),
    (&["hex", "nut"], Family::HexNut),
    (&["nut"], Family::HexNut),
    (&["standoff"], Family::Standoff),
    (&["key"], Family::Bar),
    (&["keystock"], Family::Bar),
    (&["shim"], Family::Bar),
    (&["flat", "bar"], Family::Bar),
    (&["dowel", "pin"], Family::Pin),
    (&["dowel"], Family::Pin),
    (&["pin"], Family::Pin),
    (&["angle", "bracket"], Family::Angle),
    (&["angle"], Family::Angle),
    (&["l-bracket"], Family::Angle),
    (&["u-channel"], Family::Channel),
    (&["c-channel"], Family::Channel),
    (&["channel"], Family::Channel),
    (&["i-beam"], Family::Beam),
    (&["h-beam"], Family::Beam),
    (&["tee", "section"], Family::Tee),
    (&["t-bar"], Family::Tee),
    (&["t-beam"], Family::Tee),
    (&["tee-beam"], Family::Tee),
    (&["gusset"], Family::Gusset),
    (&["leg"], Family::Stock),
    (&["shelf"], Family::Stock),
    (&["top"], Family::Stock),
    (&["tabletop"], Family::Stock),
    (&["rail"], Family::Stock),
    (&["slat"], Family::Stock),
];

/// Words with no geometry in a family's reading beyond the lexicon's fillers (finishes, most
/// materials and a question's courtesy words are fillers there, `lexicon::is_filler`): the
/// stock's own nouns, a few more materials and the CAD programs a question names.
const NO_GEOMETRY: &[&str] = &[
    "shaft",
    "round",
    "bronze",
    "oak",
    "pine",
    "draw",
    "section",
    "parallel",
    "triangular",
    "bracket",
    "blank",
    "bar",
    "hex",
    "square",
    "end",
    "nut",
    "dowel",
    "fusion",
    "fusion360",
    "onshape",
    "freecad",
    "solidworks",
];

/// The role words a length can carry, as tags.
const TAGS: &[&str] = &[
    "od",
    "outer",
    "outside",
    "id",
    "inner",
    "inside",
    "bore",
    "bored",
    "diameter",
    "long",
    "length",
    "overall",
    "wide",
    "width",
    "face",
    "thick",
    "thickness",
    "plate",
    "high",
    "height",
    "tall",
    "deep",
    "depth",
    "across",
    "flat",
    "pitch",
    "circle",
    "bolt",
    "bc",
    "hole",
    "through",
    "clearance",
    "tapped",
    "thread",
    "threaded",
    "leg",
    "web",
    "base",
    "flange",
    "wall",
    "hub",
    "projecting",
    "square",
    "shaft",
];

/// A length of the prompt and the role words it carries.
#[derive(Debug, Clone)]
struct Len {
    tok: usize,
    mm: f64,
    tags: Vec<String>,
    /// Its "A x B x C" list (id) and position.
    list: Option<(usize, usize)>,
    /// A metric size written "M8" (its nominal diameter).
    metric: Option<f64>,
    used: bool,
}

impl Len {
    fn has(&self, t: &str) -> bool {
        self.tags.iter().any(|w| w == t)
    }
}

/// The lengths, counts and words of a prompt, as a family reads them.
#[derive(Debug)]
struct Reading<'a> {
    doc: &'a Doc,
    lens: Vec<Len>,
    /// Counts ("6x", "four") and the token of the length they count.
    counts: Vec<(u32, usize)>,
    /// Words of the prompt (index, folded word).
    words: Vec<(usize, String)>,
    family: Family,
    /// The tokens naming the family.
    name: (usize, usize),
}

fn num_mm(doc: &Doc, i: usize) -> Option<f64> {
    match doc.toks.get(i)?.kind {
        Tk::Num { v, unit: Some(f), pm: false, .. } => Some(v * f),
        _ => None,
    }
}

fn is_break(doc: &Doc, i: usize) -> bool {
    let t = &doc.toks[i];
    matches!(t.kind, Tk::Num { .. } | Tk::Deg(_))
        || t.is_sym(',')
        || t.is_sym(';')
        || t.is_sym('.')
        || t.is_sym(':')
        || t.is_sym('x')
        || t.is_sym('(')
        || t.is_sym(')')
        || t.is_sym('-')
        || t.is_word("x")
        || t.is_word("and")
}

fn tag_of(w: &str) -> Option<&'static str> {
    TAGS.iter().find(|t| **t == w).copied()
}

/// Reads the prompt for a family; `None` when it names none or says something a family
/// does not read.
fn reading(doc: &Doc) -> Option<Reading<'_>> {
    let words: Vec<(usize, String)> =
        doc.toks.iter().enumerate().filter_map(|(i, t)| t.word().map(|w| (i, super::text::fold(w)))).collect();
    // The family: exactly one name (the longest at its place).
    let mut found: Vec<(Family, usize, usize)> = Vec::new();
    let mut k = 0;
    while k < words.len() {
        let hit = NAMES.iter().find(|(name, _)| {
            name.iter()
                .enumerate()
                .all(|(j, w)| words.get(k + j).is_some_and(|(i, x)| x == w && (j == 0 || *i == words[k + j - 1].0 + 1)))
        });
        // A part of an object is named with its object: "table leg", "the shelf of a
        // bookcase" — never "a top diameter".
        let owned = |len: usize| {
            let before = k > 0
                && words[k - 1].0 + 1 == words[k].0
                && !lexicon::is_filler(&words[k - 1].1)
                && tag_of(&words[k - 1].1).is_none();
            // "of" and then the object's name (past an article), not a number ("legs of 50").
            let of = words.get(k + len).is_some_and(|(i, w)| {
                let mut j = i + 1;
                while doc.word(j).is_some_and(|x| matches!(x, "a" | "an" | "the")) {
                    j += 1;
                }
                w == "of" && doc.word(j).is_some_and(|x| !lexicon::is_filler(x) && tag_of(x).is_none())
            });
            let next_tag =
                words.get(k + len).is_some_and(|(i, w)| *i == words[k + len - 1].0 + 1 && tag_of(w).is_some());
            (before || of) && !next_tag
        };
        let hit = hit.filter(|(name, f)| *f != Family::Stock || owned(name.len()));
        if let Some((name, f)) = hit {
            found.push((*f, words[k].0, words[k + name.len() - 1].0));
            k += name.len();
        } else {
            k += 1;
        }
    }
    // A part of an object ("leg") names the family only when no other does ("an angle with
    // 60 and 40 legs"); a flange of a section is the section's.
    let section =
        |f: Family| matches!(f, Family::Angle | Family::Channel | Family::Beam | Family::Tee | Family::Gusset);
    if found.iter().any(|x| x.0 != Family::Stock) {
        found.retain(|x| x.0 != Family::Stock);
    }
    if found.iter().any(|x| section(x.0)) {
        found.retain(|x| x.0 != Family::Flange);
    }
    found.dedup_by(|a, b| a.0 == b.0);
    let [(family, a, b)] = found.as_slice() else { return None };
    let (family, name) = (*family, (*a, *b));
    let mut lens = Vec::new();
    let mut counts = Vec::new();
    let mut list_id = 0usize;
    let mut i = 0;
    while i < doc.toks.len() {
        if let Some(mm) = num_mm(doc, i) {
            let metric = (i > 0 && doc.is(i - 1, "metric"))
                .then(|| {
                    let t = &doc.toks[i];
                    doc.text
                        .get(t.start..t.end)
                        .and_then(|s| s.trim().trim_start_matches(['M', 'm']).parse::<f64>().ok())
                })
                .flatten();
            lens.push(Len { tok: i, mm, tags: Vec::new(), list: None, metric, used: false });
        } else if let Tk::Num { v, unit: None, pm: false, .. } = doc.toks[i].kind
            && v.fract() == 0.0
            && v > 0.0
            && (doc.toks.get(i + 1).is_some_and(|t| t.is_sym('x') || t.is_word("x")))
            && num_mm(doc, i + 2).is_some()
        {
            counts.push((v as u32, i + 2));
            i += 2;
            continue;
        } else if let Some(w) = doc.word(i)
            && let Some(n) = lexicon::number_word(w)
            && n > 1
            && num_mm(doc, i + 1).is_some()
        {
            counts.push((n, i + 1));
        }
        i += 1;
    }
    if lens.is_empty() {
        return None;
    }
    // Tags: the role words after a length up to the next break; if none, those before it.
    for len in lens.iter_mut() {
        let t = len.tok;
        let mut after = Vec::new();
        let mut j = t + 1;
        while j < doc.toks.len() && !is_break(doc, j) {
            if let Some(w) = doc.word(j)
                && let Some(g) = tag_of(&super::text::fold(w))
            {
                after.push(g.to_string());
            }
            j += 1;
        }
        let mut tags = after;
        if tags.is_empty() || tags.iter().all(|g| g == "diameter") {
            let mut j = t;
            while j > 0 && !is_break(doc, j - 1) {
                j -= 1;
                // A role fused to the number before ("Ø20") is that number's.
                if j > 0 && doc.toks[j].start == doc.toks[j - 1].start {
                    break;
                }
                if let Some(w) = doc.word(j)
                    && let Some(g) = tag_of(&super::text::fold(w))
                {
                    tags.push(g.to_string());
                }
            }
        }
        len.tags = tags;
    }
    // Lists: lengths joined by "x" or "and"; the nouns after the last member size them all.
    let mut k = 0;
    while k < lens.len() {
        let mut e = k;
        while e + 1 < lens.len() && joined(doc, lens[e].tok, lens[e + 1].tok) {
            e += 1;
        }
        if e > k {
            for (p, m) in (k..=e).enumerate() {
                lens[m].list = Some((list_id, p));
            }
            let last = lens[e].tags.clone();
            for member in &mut lens[k..e] {
                for g in &last {
                    let noun = matches!(g.as_str(), "hub" | "leg" | "flange" | "hole" | "web" | "plate");
                    if (noun || member.tags.is_empty()) && !member.has(g) {
                        member.tags.push(g.clone());
                    }
                }
            }
            list_id += 1;
        }
        k = e + 1;
    }
    legends(doc, &mut lens);
    Some(Reading { doc, lens, counts, words, family, name })
}

/// Whether two lengths are joined in a list: "A x B", "A and B".
fn joined(doc: &Doc, a: usize, b: usize) -> bool {
    let between: Vec<usize> = (a + 1..b).collect();
    let sep = between.iter().filter(|&&j| doc.toks[j].is_sym('x') || doc.is(j, "x") || doc.is(j, "and")).count();
    sep == 1
        && between.iter().all(|&j| {
            doc.toks[j].is_sym('x')
                || doc.is(j, "x")
                || doc.is(j, "and")
                || (doc.toks[j].start == doc.toks[a].start && doc.word(j).is_some())
                || doc.word(j).is_some_and(|w| tag_of(&super::text::fold(w)).is_some())
        })
}

/// A parenthesised legend "(web x flange x thickness)" names the members of the list of
/// as many lengths before it.
fn legends(doc: &Doc, lens: &mut [Len]) {
    let mut i = 0;
    while i < doc.toks.len() {
        if !doc.toks[i].is_sym('(') {
            i += 1;
            continue;
        }
        let mut groups: Vec<Vec<String>> = vec![Vec::new()];
        let mut j = i + 1;
        let mut ok = true;
        while j < doc.toks.len() && !doc.toks[j].is_sym(')') {
            if doc.toks[j].is_sym('x') || doc.is(j, "x") {
                groups.push(Vec::new());
            } else if let Some(w) = doc.word(j) {
                if let Some(last) = groups.last_mut() {
                    last.push(super::text::fold(w));
                }
            } else {
                ok = false;
            }
            j += 1;
        }
        if ok && groups.len() >= 2 && groups.iter().all(|g| !g.is_empty()) {
            let lists: Vec<usize> = lens
                .iter()
                .filter(|l| l.tok < i)
                .filter_map(|l| l.list.map(|x| x.0))
                .filter(|id| lens.iter().filter(|l| l.list.map(|x| x.0) == Some(*id)).count() == groups.len())
                .collect();
            if let Some(id) = lists.last().copied() {
                for l in lens.iter_mut().filter(|l| l.list.map(|x| x.0) == Some(id)) {
                    let p = l.list.map_or(0, |x| x.1);
                    l.tags = groups[p].iter().filter_map(|w| tag_of(w).map(str::to_string)).collect();
                    // "legs", "base", "wall": legend words are their roles.
                }
                for t in i..=j.min(doc.toks.len() - 1) {
                    doc.mark(t);
                }
            }
        }
        i = j + 1;
    }
}

/// A family's parameter: its name, the tags that bind a length to it (any of), and the tags
/// that keep a length from it.
struct Param {
    name: &'static str,
    any: &'static [&'static str],
    not: &'static [&'static str],
}

const fn p(name: &'static str, any: &'static [&'static str], not: &'static [&'static str]) -> Param {
    Param { name, any, not }
}

const HOLE: &[&str] = &["hole", "through", "clearance", "tapped", "thread", "threaded"];
const PCD: &[&str] = &["pitch", "circle", "bc"];
const LONG: &[&str] = &["long", "length", "overall"];

/// Binds the lengths to the parameters: by tags first, then the untagged lengths in list
/// order to the parameters still open (the designation's order).
fn bind(r: &mut Reading<'_>, params: &[Param], order: &[&str]) -> Res<Vec<Option<f64>>> {
    let mut val: Vec<Option<(f64, usize)>> = vec![None; params.len()];
    for k in 0..r.lens.len() {
        let l = &r.lens[k];
        // A metric size ("M8") is a thread or a standard's size, never a length here.
        if l.tags.is_empty() || l.metric.is_some() {
            continue;
        }
        let hit = params.iter().position(|q| q.any.iter().any(|t| l.has(t)) && !q.not.iter().any(|t| l.has(t)));
        let Some(pi) = hit else { continue };
        match val[pi] {
            Some((v, tok)) if (v - l.mm).abs() > 1e-9 * v.max(1.0) => {
                return Err(Refusal::new(
                    r.doc.quote(tok.min(l.tok), tok.max(l.tok)),
                    format!(
                        "the {} of the {} is given twice, as {v} mm and {} mm",
                        params[pi].name,
                        family_word(r),
                        l.mm
                    ),
                ));
            }
            _ => val[pi] = Some((l.mm, l.tok)),
        }
        r.lens[k].used = true;
    }
    // Untagged lengths, in order, to the open parameters of the designation's order.
    let mut open: Vec<usize> =
        order.iter().filter_map(|n| params.iter().position(|q| q.name == *n)).filter(|&pi| val[pi].is_none()).collect();
    open.reverse();
    for k in 0..r.lens.len() {
        if r.lens[k].used || !r.lens[k].tags.is_empty() || r.lens[k].metric.is_some() {
            continue;
        }
        let Some(pi) = open.pop() else { break };
        val[pi] = Some((r.lens[k].mm, r.lens[k].tok));
        r.lens[k].used = true;
    }
    Ok(val.into_iter().map(|v| v.map(|x| x.0)).collect())
}

fn family_word(r: &Reading<'_>) -> String {
    r.doc.quote(r.name.0, r.name.1).to_lowercase()
}

fn missing(r: &Reading<'_>, what: &str) -> Refusal {
    Refusal::new(
        r.doc.quote(r.name.0, r.name.1),
        format!("the {} is not given, and no standard the prompt names defines it", what),
    )
}

/// ISO 7089 plain washers (normal series): nominal size → (d1 bore, d2 OD, h).
const ISO_7089: &[(f64, [f64; 3])] = &[
    (3.0, [3.2, 7.0, 0.5]),
    (4.0, [4.3, 9.0, 0.8]),
    (5.0, [5.3, 10.0, 1.0]),
    (6.0, [6.4, 12.0, 1.6]),
    (8.0, [8.4, 16.0, 1.6]),
    (10.0, [10.5, 20.0, 2.0]),
    (12.0, [13.0, 24.0, 2.5]),
    (16.0, [17.0, 30.0, 3.0]),
    (20.0, [21.0, 37.0, 3.0]),
];

/// ISO 4032 hex nuts: nominal size → (s across flats, m height, its maximum).
const ISO_4032: &[(f64, [f64; 2])] = &[
    (3.0, [5.5, 2.4]),
    (4.0, [7.0, 3.2]),
    (5.0, [8.0, 4.7]),
    (6.0, [10.0, 5.2]),
    (8.0, [13.0, 6.8]),
    (10.0, [16.0, 8.4]),
    (12.0, [18.0, 10.8]),
    (16.0, [24.0, 14.8]),
    (20.0, [30.0, 18.0]),
];

/// Whether the prompt names the ISO standard of this number ("ISO 7089", "ISO-4032").
fn names_standard(r: &Reading<'_>, number: &str) -> bool {
    let text = r.doc.text.to_ascii_lowercase();
    ["iso ", "iso-", "iso"].iter().any(|p| {
        text.match_indices(&format!("{p}{number}"))
            .any(|(k, m)| !text[k + m.len()..].starts_with(|c: char| c.is_ascii_digit()))
    })
}

/// What a family's closed formulas say the part measures: sorted extents and volume.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Takeoff {
    pub extents: [f64; 3],
    pub volume: f64,
}

pub fn sorted(mut e: [f64; 3]) -> [f64; 3] {
    e.sort_by(|a, b| b.total_cmp(a));
    e
}

fn disc(d: f64) -> f64 {
    PI * d * d / 4.0
}

fn prism(label: &str, profile: Profile, at: [f64; 2], from: f64, to: f64) -> Body {
    Body::new(label, Shape::Prism { profile, axis: Axis::Z, at, rot: 0.0, from, to })
}

/// A family part: its model, and its takeoff by the family's own formulas.
struct Made {
    model: Model,
    takeoff: Takeoff,
}

/// A hole pattern on a pitch circle: count, hole diameter, PCD.
fn bolt_circle(r: &mut Reading<'_>, vals: &[Option<f64>], hole: usize, pcd: usize) -> Res<Option<(u32, f64, f64)>> {
    match (vals[hole], vals[pcd]) {
        (None, None) => Ok(None),
        (Some(d), Some(c)) => {
            let tok = r.lens.iter().find(|l| (l.mm - d).abs() < 1e-12 && l.used).map(|l| l.tok);
            let n = r.counts.iter().find(|(_, t)| Some(*t) == tok).map(|(n, _)| *n);
            let Some(n) = n else {
                return Err(missing(r, "number of holes"));
            };
            Ok(Some((n, d, c)))
        }
        (Some(_), None) => Err(missing(r, "pitch circle of the holes")),
        (None, Some(_)) => Err(missing(r, "size of the holes")),
    }
}

fn holes_on_circle(model: &mut Model, n: u32, d: f64, pcd: f64, from: f64, to: f64) {
    for k in 0..n {
        let a = 2.0 * PI * k as f64 / n as f64 + PI / 2.0;
        let at = [pcd / 2.0 * a.cos(), pcd / 2.0 * a.sin()];
        model.cuts.push(prism("bolt holes", Profile::Circle { d }, at, from - 0.0, to));
    }
}

/// Holes on a pitch circle must lie in the ring and clear each other.
fn check_circle(r: &Reading<'_>, od: f64, id: f64, n: u32, d: f64, pcd: f64) -> Res<()> {
    let ring = pcd / 2.0 + d / 2.0 < od / 2.0 && pcd / 2.0 - d / 2.0 > id / 2.0;
    let apart = n < 2 || pcd * (PI / n as f64).sin() > d;
    if ring && apart {
        Ok(())
    } else {
        Err(Refusal::new(
            r.doc.quote(r.name.0, r.doc.len().saturating_sub(1)),
            format!(
                "{n} holes of {d} mm on a {pcd} mm pitch circle do not fit between {id} mm and {od} mm, clear of each other"
            ),
        ))
    }
}

fn ring(r: &mut Reading<'_>) -> Res<Made> {
    let params = [
        p("bore", &["id", "inner", "inside", "bore", "bored", "shaft"], &[]),
        p("outside diameter", &["od", "outer", "outside", "diameter"], &["hub", "flange"]),
        p("wall", &["wall"], &[]),
        p(
            "length",
            &["long", "length", "overall", "wide", "width", "thick", "thickness", "high", "height", "tall", "face"],
            &[],
        ),
    ];
    // "Ø25.4 x 1.6 wall x 300": with a wall, the list is OD, wall, length.
    let order: &[&str] = if r.lens.iter().any(|l| l.has("wall")) {
        &["outside diameter", "length"]
    } else {
        &["outside diameter", "bore", "length"]
    };
    let vals = bind(r, &params, order)?;
    let (mut id, mut od, wall, mut len) = (vals[0], vals[1], vals[2], vals[3]);
    let washer = r.words.iter().any(|(_, w)| w == "washer");
    if washer && names_standard(r, "7089") {
        let m = r.lens.iter().find_map(|l| l.metric);
        if let Some(&(_, [d1, d2, h])) = m.and_then(|m| ISO_7089.iter().find(|(s, _)| (s - m).abs() < 1e-9)) {
            for l in r.lens.iter_mut().filter(|l| l.metric.is_some()) {
                l.used = true;
            }
            id = id.or(Some(d1));
            od = od.or(Some(d2));
            len = len.or(Some(h));
        }
    }
    if let (Some(w), None) = (wall, id) {
        let o = od.ok_or_else(|| missing(r, "outside diameter"))?;
        id = Some(o - 2.0 * w);
    }
    let od = od.ok_or_else(|| missing(r, "outside diameter"))?;
    let id = id.ok_or_else(|| missing(r, "bore"))?;
    let len = len.ok_or_else(|| missing(r, "length (or width)"))?;
    if let Some(w) = wall
        && (od - 2.0 * w - id).abs() > 1e-6
    {
        let tok = r.lens.iter().find(|l| l.has("wall")).map_or(r.name.0, |l| l.tok);
        return Err(Refusal::new(
            r.doc.quote(tok, (tok + 1).min(r.doc.len() - 1)),
            format!("a {w} mm wall does not join a {od} mm OD to a {id} mm bore"),
        ));
    }
    if id <= 0.0 || id >= od {
        return Err(Refusal::new(
            r.doc.quote(r.name.0, r.doc.len().saturating_sub(1)),
            format!("a bore of {id} mm does not fit in an outside diameter of {od} mm"),
        ));
    }
    let mut model = Model::default();
    model.adds.push(prism(&family_word(r), Profile::Annulus { od, id }, [0.0, 0.0], 0.0, len));
    let takeoff = Takeoff { extents: sorted([od, od, len]), volume: (disc(od) - disc(id)) * len };
    Ok(Made { model, takeoff })
}

fn flange(r: &mut Reading<'_>) -> Res<Made> {
    let params = [
        p("pitch circle", PCD, &[]),
        p("hole size", HOLE, &["bore"]),
        p("bore", &["id", "inner", "bore", "bored"], &[]),
        p("outside diameter", &["od", "outer", "outside", "diameter"], &[]),
        p("thickness", &["thick", "thickness", "high", "height", "wide", "long", "length"], &[]),
    ];
    let vals = bind(r, &params, &["outside diameter", "thickness"])?;
    let blind = r.words.iter().any(|(_, w)| w == "blind");
    let od = vals[3].ok_or_else(|| missing(r, "outside diameter"))?;
    let t = vals[4].ok_or_else(|| missing(r, "thickness"))?;
    let id = match (vals[2], blind) {
        (Some(b), false) => b,
        (None, true) => 0.0,
        (Some(_), true) => {
            return Err(Refusal::new(family_word(r), "a blind flange has no bore".to_string()));
        }
        (None, false) => return Err(missing(r, "bore (or say a blind flange)")),
    };
    let bc = bolt_circle(r, &vals, 1, 0)?;
    if id >= od {
        return Err(Refusal::new(family_word(r), format!("a bore of {id} mm does not fit in {od} mm")));
    }
    let profile = if id > 0.0 { Profile::Annulus { od, id } } else { Profile::Circle { d: od } };
    let mut model = Model::default();
    model.adds.push(prism("flange", profile, [0.0, 0.0], 0.0, t));
    let mut volume = (disc(od) - disc(id)) * t;
    if let Some((n, d, c)) = bc {
        check_circle(r, od, id, n, d, c)?;
        holes_on_circle(&mut model, n, d, c, 0.0, t);
        volume -= n as f64 * disc(d) * t;
    }
    Ok(Made { model, takeoff: Takeoff { extents: sorted([od, od, t]), volume } })
}

fn pulley(r: &mut Reading<'_>) -> Res<Made> {
    let params = [
        p("hub projection", &["projecting", "long", "length"], &["diameter"]),
        p("hub diameter", &["hub"], &["bore"]),
        p("bore", &["id", "inner", "bore", "bored", "through", "hole"], &[]),
        p("outside diameter", &["od", "outer", "outside", "diameter"], &[]),
        p("face width", &["face", "wide", "width", "thick", "thickness"], &[]),
    ];
    // "a Ø30 x 12 hub": the hub's diameter, then its projection.
    for l in r.lens.iter_mut() {
        if l.has("hub") && !l.has("diameter") && l.list.is_some_and(|x| x.1 > 0) {
            l.tags.push("projecting".into());
        }
    }
    let vals = bind(r, &params, &["outside diameter", "face width"])?;
    let od = vals[3].ok_or_else(|| missing(r, "outside diameter"))?;
    let w = vals[4].ok_or_else(|| missing(r, "face width"))?;
    let bore = vals[2].ok_or_else(|| missing(r, "bore"))?;
    let hub = match (vals[1], vals[0]) {
        (Some(d), Some(h)) => Some((d, h)),
        (None, None) => None,
        (Some(_), None) => return Err(missing(r, "hub's projection")),
        (None, Some(_)) => return Err(missing(r, "hub's diameter")),
    };
    if bore >= hub.map_or(od, |h| h.0.min(od)) || hub.is_some_and(|h| h.0 >= od) {
        return Err(Refusal::new(family_word(r), format!("a {bore} mm bore does not fit the pulley's diameters")));
    }
    let top = w + hub.map_or(0.0, |h| h.1);
    let mut model = Model::default();
    model.adds.push(prism("pulley", Profile::Circle { d: od }, [0.0, 0.0], 0.0, w));
    if let Some((d, h)) = hub {
        model.adds.push(prism("hub", Profile::Circle { d }, [0.0, 0.0], w, w + h));
    }
    model.cuts.push(prism("bore", Profile::Circle { d: bore }, [0.0, 0.0], 0.0, top));
    let volume = disc(od) * w + hub.map_or(0.0, |(d, h)| disc(d) * h) - disc(bore) * top;
    Ok(Made { model, takeoff: Takeoff { extents: sorted([od, od, top]), volume } })
}

fn thread_size(r: &Reading<'_>) -> Option<(f64, usize)> {
    r.lens.iter().find_map(|l| l.metric.map(|m| (m, l.tok)))
}

fn hexagon_bar(r: &mut Reading<'_>, nut: bool) -> Res<Made> {
    let params = [
        p("across flats", &["across", "flat"], &[]),
        p("outside diameter", &["od", "outer", "diameter"], &["hole", "thread", "tapped"]),
        p("height", &["high", "height", "thick", "thickness", "long", "length", "tall"], &[]),
    ];
    // The thread is not a length of the body.
    let m = thread_size(r);
    for l in r.lens.iter_mut().filter(|l| l.metric.is_some()) {
        l.used = true;
        l.tags.push("thread".into());
    }
    let vals = bind(r, &params, &["across flats", "height"])?;
    let (mut af, od, mut h) = (vals[0], vals[1], vals[2]);
    let Some((m, _)) = m else { return Err(missing(r, "thread size (M…)")) };
    if nut
        && names_standard(r, "4032")
        && let Some(&(_, [s, mm])) = ISO_4032.iter().find(|(x, _)| (x - m).abs() < 1e-9)
    {
        af = af.or(Some(s));
        h = h.or(Some(mm));
    }
    let tap = notation::tap_drill(m).ok_or_else(|| missing(r, "tap drill of this thread"))?;
    let h = h.ok_or_else(|| missing(r, if nut { "height" } else { "length" }))?;
    let mut model = Model::default();
    let (extents, area) = match (af, od, nut) {
        (Some(s), None, _) => {
            let ac = s / (PI / 6.0).cos();
            model.adds.push(prism("hexagon", Profile::Ngon { n: 6, d: ac, phase: 0.0 }, [0.0, 0.0], 0.0, h));
            ([ac, s, h], 3f64.sqrt() / 2.0 * s * s)
        }
        (None, Some(d), false)
            if r.words.iter().any(|(_, w)| w == "round") || !r.words.iter().any(|(_, w)| w == "hex") =>
        {
            model.adds.push(prism("standoff", Profile::Circle { d }, [0.0, 0.0], 0.0, h));
            ([d, d, h], disc(d))
        }
        _ => return Err(missing(r, "across-flats size")),
    };
    if tap >= extents[1] {
        return Err(Refusal::new(family_word(r), format!("an M{m} thread does not fit in it")));
    }
    model.cuts.push(prism("thread", Profile::Circle { d: tap }, [0.0, 0.0], 0.0, h));
    Ok(Made { model, takeoff: Takeoff { extents: sorted(extents), volume: (area - disc(tap)) * h } })
}

fn bar(r: &mut Reading<'_>) -> Res<Made> {
    // Three lengths in any roles; "40 square" is two of them.
    let mut ext: Vec<f64> = Vec::new();
    let two = r.lens.len() == 2;
    for l in r.lens.iter_mut() {
        l.used = true;
        ext.push(l.mm);
        if two && l.has("square") && !l.has("long") {
            ext.push(l.mm);
        }
    }
    let round = r.lens.iter().find(|l| l.has("diameter")).map(|l| l.mm);
    let mut model = Model::default();
    if let (Some(d), 2) = (round, ext.len()) {
        let len = ext
            .iter()
            .copied()
            .find(|x| (x - d).abs() > 1e-12 || ext.iter().filter(|y| (*y - d).abs() < 1e-12).count() == 2);
        let len = len.ok_or_else(|| missing(r, "length"))?;
        model.adds.push(prism(&family_word(r), Profile::Circle { d }, [0.0, 0.0], 0.0, len));
        return Ok(Made { model, takeoff: Takeoff { extents: sorted([d, d, len]), volume: disc(d) * len } });
    }
    let [a, b, c] = ext.as_slice() else {
        return Err(Refusal::new(
            r.doc.quote(r.name.0, r.doc.len().saturating_sub(1)),
            format!("a {} needs three sizes (or a diameter and a length); {} given", family_word(r), ext.len()),
        ));
    };
    model.adds.push(prism(&family_word(r), Profile::Rect { w: *a, h: *b }, [0.0, 0.0], 0.0, *c));
    Ok(Made { model, takeoff: Takeoff { extents: sorted([*a, *b, *c]), volume: a * b * c } })
}

fn pin(r: &mut Reading<'_>) -> Res<Made> {
    let params = [p("diameter", &["diameter", "od"], &[]), p("length", LONG, &[])];
    let vals = bind(r, &params, &["diameter", "length"])?;
    let d = vals[0].ok_or_else(|| missing(r, "diameter"))?;
    let len = vals[1].ok_or_else(|| missing(r, "length"))?;
    let mut model = Model::default();
    model.adds.push(prism("pin", Profile::Circle { d }, [0.0, 0.0], 0.0, len));
    Ok(Made { model, takeoff: Takeoff { extents: sorted([d, d, len]), volume: disc(d) * len } })
}

/// A profile family (angle, channel, beam, tee, gusset) extruded over its length.
fn section(r: &mut Reading<'_>) -> Res<Made> {
    let thick = &["thick", "thickness", "wall", "plate"][..];
    let f = r.family;
    let params: Vec<Param> = match f {
        Family::Angle | Family::Gusset => vec![
            p("length", &["long", "length", "wide", "width"], &[]),
            p("thickness", thick, &[]),
            p("first leg", &["leg"], &[]),
            p("second leg", &["leg"], &[]),
        ],
        Family::Channel => vec![
            p("length", LONG, &[]),
            p("thickness", thick, &[]),
            p("web", &["web", "base", "deep", "depth"], &[]),
            p("flange", &["flange", "leg", "wide", "width", "high", "height"], &[]),
        ],
        Family::Tee => vec![
            p("length", LONG, &[]),
            p("thickness", thick, &[]),
            p("flange", &["flange", "wide", "width"], &[]),
            p("depth", &["deep", "depth", "high", "height"], &[]),
        ],
        _ => vec![
            p("length", LONG, &[]),
            p("web thickness", &["web"], &[]),
            p("flange thickness", &["thick", "thickness"], &[]),
            p("depth", &["deep", "depth", "high", "height"], &[]),
            p("flange", &["flange", "wide", "width"], &[]),
        ],
    };
    // Two legs are two parameters: the second length tagged "leg" is the second leg.
    let legs: Vec<usize> = (0..r.lens.len()).filter(|&k| r.lens[k].has("leg")).collect();
    if matches!(f, Family::Angle | Family::Gusset) && legs.len() == 2 {
        r.lens[legs[1]].tags = vec!["second".into()];
    }
    let params: Vec<Param> = params
        .into_iter()
        .map(|q| if q.name == "second leg" { p("second leg", &["second"], &[]) } else { q })
        .collect();
    let order: &[&str] = match f {
        Family::Angle => &["first leg", "second leg", "thickness", "length"],
        Family::Gusset => &["first leg", "second leg", "thickness"],
        Family::Channel => &["web", "flange", "thickness", "length"],
        Family::Tee => &["flange", "depth", "thickness", "length"],
        _ => &["depth", "flange", "web thickness", "flange thickness", "length"],
    };
    let vals = bind(r, &params, order)?;
    let get = |k: usize| vals[k].ok_or_else(|| missing(r, params[k].name));
    let (outline, len, area, ext2): (Vec<[f64; 2]>, f64, f64, [f64; 2]) = match f {
        Family::Angle | Family::Gusset => {
            let (a, b, t) = (get(2)?, get(3)?, get(1)?);
            if f == Family::Gusset {
                if get(0).is_ok() {
                    return Err(Refusal::new(family_word(r), "a gusset is a triangle of two legs and a thickness"));
                }
                (vec![[0.0, 0.0], [a, 0.0], [0.0, b]], t, a * b / 2.0, [a, b])
            } else {
                if t >= a.min(b) {
                    return Err(Refusal::new(family_word(r), format!("a {t} mm thickness leaves no leg")));
                }
                let len = get(0)?;
                (vec![[0.0, 0.0], [a, 0.0], [a, t], [t, t], [t, b], [0.0, b]], len, (a + b - t) * t, [a, b])
            }
        }
        Family::Channel => {
            let (h, b, t, len) = (get(2)?, get(3)?, get(1)?, get(0)?);
            if 2.0 * t >= h || t >= b {
                return Err(Refusal::new(family_word(r), format!("a {t} mm wall leaves no channel")));
            }
            let o = vec![[0.0, 0.0], [h, 0.0], [h, b], [h - t, b], [h - t, t], [t, t], [t, b], [0.0, b]];
            (o, len, h * b - (h - 2.0 * t) * (b - t), [h, b])
        }
        Family::Tee => {
            let (b, h, t, len) = (get(2)?, get(3)?, get(1)?, get(0)?);
            if t >= b || t >= h {
                return Err(Refusal::new(family_word(r), format!("a {t} mm thickness leaves no tee")));
            }
            let (l, rr) = (b / 2.0 - t / 2.0, b / 2.0 + t / 2.0);
            let o = vec![[0.0, h], [0.0, h - t], [l, h - t], [l, 0.0], [rr, 0.0], [rr, h - t], [b, h - t], [b, h]];
            (o, len, b * t + (h - t) * t, [b, h])
        }
        _ => {
            let (len, tw, tf, h, b) = (get(0)?, get(1)?, get(2)?, get(3)?, get(4)?);
            if 2.0 * tf >= h || tw >= b {
                return Err(Refusal::new(family_word(r), "the flanges and web do not fit the section"));
            }
            let (l, rr) = (b / 2.0 - tw / 2.0, b / 2.0 + tw / 2.0);
            let o = vec![
                [0.0, 0.0],
                [b, 0.0],
                [b, tf],
                [rr, tf],
                [rr, h - tf],
                [b, h - tf],
                [b, h],
                [0.0, h],
                [0.0, h - tf],
                [l, h - tf],
                [l, tf],
                [0.0, tf],
            ];
            (o, len, 2.0 * b * tf + (h - 2.0 * tf) * tw, [b, h])
        }
    };
    let mut model = Model::default();
    model.adds.push(prism(&family_word(r), Profile::Poly(outline), [0.0, 0.0], 0.0, len));
    Ok(Made { model, takeoff: Takeoff { extents: sorted([ext2[0], ext2[1], len]), volume: area * len } })
}

/// Whether word `w` at token `i` is one a family reads: its name, a role, a standard's
/// designation, a count or a word with no geometry (or one of `extra`, its own shape words).
fn family_word_read(r: &Reading<'_>, i: usize, w: &str, extra: &[&str]) -> bool {
    (i >= r.name.0 && i <= r.name.1)
        || tag_of(w).is_some()
        || lexicon::is_filler(w)
        || NO_GEOMETRY.contains(&w)
        || notation::STANDARDS.contains(&w)
        || extra.contains(&w)
        || lexicon::number_word(w).is_some()
        || matches!(w, "x" | "diameter" | "equally" | "spaced" | "blind" | "hub" | "side" | "sae" | "metric")
}

/// Every word must be read: a family's name, a role, a count, a standard's designation, or
/// a word with no geometry. The first word that is none of these ends the family reading.
fn all_read(r: &Reading<'_>, extra: &[&str]) -> bool {
    r.words.iter().all(|(i, w)| family_word_read(r, *i, w, extra) || r.doc.is_used(*i))
        && r.lens.iter().all(|l| l.used)
        && r.doc.toks.iter().enumerate().all(|(i, t)| match t.kind {
            // Counts, and a standard's number.
            Tk::Num { unit: None, .. } => {
                r.counts.iter().any(|(_, k)| *k == i + 2 || *k == i + 1)
                    || (i > 0 && r.doc.word(i - 1).is_some_and(|w| notation::STANDARDS.contains(&w)))
            }
            Tk::Deg(_) => false,
            _ => true,
        })
}

/// Reads a prompt as a part family; `None` when it names none, or says what the family
/// does not read (the feature language's refusal then stands).
pub fn read(doc: &Doc) -> Option<Res<(&'static str, Model)>> {
    let mut r = reading(doc)?;
    // A part of an object: the owner is the one word before the part's name, or after "of".
    let mut owner: Vec<String> = Vec::new();
    if r.family == Family::Stock
        && let Some(pos) = r.words.iter().position(|(i, _)| *i == r.name.0)
    {
        if pos > 0 {
            owner.push(r.words[pos - 1].1.clone());
        }
        if r.words.get(pos + 1).is_some_and(|(_, x)| x == "of")
            && let Some((_, w)) = r.words.iter().skip(pos + 2).find(|(_, w)| !lexicon::is_filler(w))
        {
            owner.push(w.clone());
        }
    }
    let made = match r.family {
        Family::Ring => ring(&mut r),
        Family::Flange => flange(&mut r),
        Family::Pulley => pulley(&mut r),
        Family::HexNut => hexagon_bar(&mut r, true),
        Family::Standoff => hexagon_bar(&mut r, false),
        Family::Bar | Family::Stock => bar(&mut r),
        Family::Pin => pin(&mut r),
        Family::Angle | Family::Channel | Family::Beam | Family::Tee | Family::Gusset => section(&mut r),
    };
    let mut extra: Vec<&str> = owner.iter().map(String::as_str).collect();
    // Words that restate the family's own shape.
    extra.extend_from_slice(match r.family {
        Family::Gusset => &["triangle", "right-angled", "right-angle", "triangular"][..],
        Family::Angle => &["l", "l-shaped", "outside"][..],
        _ => &[][..],
    });
    let name = match r.family {
        Family::Ring => "family:ring",
        Family::Flange => "family:flange",
        Family::Pulley => "family:pulley",
        Family::HexNut => "family:hex_nut",
        Family::Standoff => "family:standoff",
        Family::Bar => "family:bar",
        Family::Stock => "family:stock",
        Family::Pin => "family:pin",
        Family::Angle => "family:angle",
        Family::Channel => "family:channel",
        Family::Beam => "family:beam",
        Family::Tee => "family:tee",
        Family::Gusset => "family:gusset",
    };
    match made {
        // A refusal of the family's own stands only when the family read every word.
        Err(e) => r.words.iter().all(|(i, w)| family_word_read(&r, *i, w, &extra)).then_some(Err(e)),
        Ok(m) => {
            if !all_read(&r, &extra) {
                return None;
            }
            Some(check(&r, &m).map(|()| (name, m.model)))
        }
    }
}

/// The second reading: the family's closed formulas against the model's own extents and
/// volume.
fn check(r: &Reading<'_>, m: &Made) -> Res<()> {
    let size = sorted(m.model.size());
    let vol = m.model.volume();
    let size_ok = (0..3).all(|k| (size[k] - m.takeoff.extents[k]).abs() <= 1e-6 * m.takeoff.extents[k].max(1.0));
    let vol_ok = vol.is_some_and(|v| (v - m.takeoff.volume).abs() <= 1e-6 * m.takeoff.volume.max(1.0));
    if size_ok && vol_ok && m.takeoff.volume > 0.0 {
        Ok(())
    } else {
        Err(Refusal::new(
            family_word(r),
            format!(
                "the family's formulas give {:?} mm and {:.1} mm³, the model {:?} mm and {:?} mm³",
                m.takeoff.extents, m.takeoff.volume, size, vol
            ),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn made(prompt: &str) -> (&'static str, Model) {
        match read(&Doc::new(prompt)) {
            Some(Ok(m)) => m,
            Some(Err(e)) => panic!("{prompt}: refused {e:?}"),
            None => panic!("{prompt}: no family reading"),
        }
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-6 * b.abs().max(1.0)
    }

    #[test]
    fn rings_bind_by_role_in_any_order() {
        // Role words, not order: the same ring however the sizes are written.
        for (prompt, od, id, len) in [
            ("Shaft collar, 25 mm bore, 45 OD, 14 wide", 45.0, 25.0, 14.0),
            ("Spacer, round, 12 OD x 6.4 ID x 20 long", 12.0, 6.4, 20.0),
            ("3/8\" ID x 3/4\" OD x 1/2\" spacer", 19.05, 9.525, 12.7),
            ("how do I model a bushing? it's 30 OD, 20 ID and 25 long", 30.0, 20.0, 25.0),
            ("Shaft collar for a 1/2 in shaft, 1-1/8 in OD, 1/2 in wide", 28.575, 12.7, 12.7),
        ] {
            let (_, m) = made(prompt);
            assert!(close(m.volume().unwrap_or(0.0), (disc(od) - disc(id)) * len), "{prompt}");
        }
    }

    #[test]
    fn a_missing_dimension_is_refused_by_name() {
        match read(&Doc::new("Shaft collar, 20 mm bore, 15 wide")) {
            Some(Err(e)) => assert!(e.reason.contains("outside diameter") && e.phrase.contains("collar"), "{e:?}"),
            other => panic!("{other:?}"),
        }
        match read(&Doc::new("Collar, 30 bore, 25 OD, 10 wide")) {
            Some(Err(e)) => assert!(e.reason.contains("bore"), "{e:?}"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn standards_fill_only_what_they_define() {
        let (_, m) = made("Plain washer ISO 7089, M12");
        assert!(close(m.volume().unwrap_or(0.0), (disc(24.0) - disc(13.0)) * 2.5));
        let (_, m) = made("M10 hex nut to ISO 4032");
        assert!(close(m.size()[2], 8.4));
        // Without the standard, the nut's sizes are the prompt's to give.
        assert!(matches!(read(&Doc::new("Hex nut M10")), Some(Err(_))));
    }

    #[test]
    fn flanges_and_sections() {
        let (_, m) = made("FLANGE Ø120 x 12 THK, Ø40 BORE, 6x Ø11 THRU EQ SP ON Ø90 PCD");
        let want = (disc(120.0) - disc(40.0) - 6.0 * disc(11.0)) * 12.0;
        assert!(close(m.volume().unwrap_or(0.0), want));
        let (_, m) = made("ANGLE BRACKET 50 x 50 x 5, 30 WIDE");
        assert!(close(m.volume().unwrap_or(0.0), (50.0 * 5.0 + 45.0 * 5.0) * 30.0));
        let (_, m) = made("U-channel 40 x 20 x 3, 250 long (base x legs x wall)");
        assert!(close(m.volume().unwrap_or(0.0), (40.0 * 20.0 - 34.0 * 17.0) * 250.0));
        let (_, m) = made("Triangular gusset, 6 mm plate, legs 80 x 60");
        assert!(close(m.volume().unwrap_or(0.0), 80.0 * 60.0 / 2.0 * 6.0));
    }

    #[test]
    fn a_part_of_an_object_needs_its_object() {
        assert!(matches!(read(&Doc::new("the shelf of a bookcase, 800 x 250 x 18")), Some(Ok(_))));
        assert!(matches!(read(&Doc::new("a table leg, 40 mm square, 720 long")), Some(Ok(_))));
        // "legs of 50", "a top diameter of 30": no object owns them; no family.
        assert!(read(&Doc::new("A wedge with legs of 50 and 20 mm, 30 mm thick")).is_none());
        assert!(read(&Doc::new("A frustum with a top diameter of 30 mm, 25 mm high")).is_none());
    }

    #[test]
    fn a_part_of_a_catalog_object_is_never_the_whole_object() {
        // (The catalog's own lamp shade, where it has one, is that part: it may be made.)
        if let Ok(crate::freeform::Offline::Catalog { category, .. }) = crate::freeform::offline("a lamp shade") {
            assert!(category.contains("shade"), "a lamp shade became {category}");
        }
        for (prompt, words) in
            [("a sofa leg", "sofa leg"), ("a table leg", "table leg"), ("the leg of a table", "leg of")]
        {
            match crate::freeform::offline(prompt) {
                Err(super::super::SynthError::Unread { phrase, .. }) => {
                    assert!(phrase.contains(words), "{prompt}: {phrase}")
                }
                Err(e) => panic!("{prompt}: {e}"),
                Ok(_) => panic!("{prompt}: made"),
            }
        }
    }

    #[test]
    fn unknown_words_end_the_family_reading() {
        assert!(read(&Doc::new("Collar 40 OD x 20 ID x 15 wide with a dragon engraved")).is_none());
        assert!(read(&Doc::new("a block 20 x 10 x 5")).is_none());
    }
}
