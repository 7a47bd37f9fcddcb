//! Reading the numbers of a dimensioned prompt: every length with a unit (mm, cm, m,
//! inches), what it measures (its role: diameter, height, fillet …), the words around it
//! that qualify it (outer, bore, hole, flange …), the axis it is given along, and the
//! counts ("four", "6x", "16 teeth").

use std::collections::BTreeSet;

/// What a length measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Role {
    Length,
    Width,
    Height,
    Thickness,
    Depth,
    Diameter,
    Radius,
    Side,
    Fillet,
    Chamfer,
    Inset,
    Spacing,
    Wall,
    /// A length with no role word near it ("100mm by 60mm").
    Bare,
}

/// An axis named next to a length ("60mm (X)", "along Z").
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Axis {
    X,
    Y,
    Z,
}

/// One length in the prompt, in millimetres.
#[derive(Debug, Clone, PartialEq)]
pub struct Dim {
    pub mm: f64,
    pub role: Role,
    /// Qualifying words of its own phrase ("outer", "bore", "hole", "top" …).
    pub mods: BTreeSet<String>,
    /// Qualifying words of its whole clause (a fallback for `mods`).
    pub clause_mods: BTreeSet<String>,
    pub axis: Option<Axis>,
    /// Which clause it is in (clauses are split at , ; : . "and" "with").
    pub clause: usize,
    /// Inside parentheses (a restatement, lower priority).
    pub paren: bool,
    /// Part of a "A by B by C" list, its position in it.
    pub list: Option<(usize, usize)>,
    /// A coordinate ("Z=25mm"): a position along this axis, not a size.
    pub coord: Option<Axis>,
}

impl Dim {
    pub fn has(&self, word: &str) -> bool {
        self.mods.contains(word)
    }
    pub fn clause_has(&self, word: &str) -> bool {
        self.mods.contains(word) || self.clause_mods.contains(word)
    }
}

/// The words that qualify a length. Plural forms are folded to these.
const MODS: &[&str] = &[
    "outer",
    "outside",
    "inner",
    "inside",
    "bore",
    "hole",
    "base",
    "bottom",
    "top",
    "head",
    "shaft",
    "flange",
    "hub",
    "body",
    "web",
    "pitch",
    "bolt",
    "counterbore",
    "tip",
    "root",
    "major",
    "minor",
    "circumscribed",
    "across",
    "center",
    "corner",
    "edge",
    "vertical",
    "long",
    "circular",
    "all",
    "wall",
    "leg",
    "teeth",
    "tooth",
    "face",
    "sides",
    "cap",
    "socket",
    "slot",
    "keyway",
    "shoulder",
    "thread",
    "ring",
    "rim",
    "spoke",
    "fin",
    "groove",
    "circle",
    "metric",
    "extruded",
];

/// A prompt's lengths and counts.
#[derive(Debug, Clone, Default)]
pub struct Reading {
    pub dims: Vec<Dim>,
    /// Words of the prompt, lower case, punctuation split off.
    pub words: Vec<String>,
    /// The prompt in lower case.
    pub text: String,
    /// Counts: ("hole", 4), ("teeth", 16) — the number and the noun after it.
    pub counts: Vec<(String, u32)>,
}

impl Reading {
    pub fn mentions(&self, phrase: &str) -> bool {
        contains_phrase(&self.text, phrase)
    }

    /// The first length with this role whose own words include every one of `with` and
    /// none of `without`; non-parenthesised first.
    pub fn find(&self, role: Role, with: &[&str], without: &[&str]) -> Option<&Dim> {
        let pick = |paren: bool, own: bool| {
            self.dims.iter().find(|d| {
                d.role == role
                    && d.coord.is_none()
                    && d.paren == paren
                    && with.iter().all(|w| if own { d.has(w) } else { d.clause_has(w) })
                    && without.iter().all(|w| !d.has(w))
            })
        };
        pick(false, true).or_else(|| pick(true, true)).or_else(|| pick(false, false)).or_else(|| pick(true, false))
    }

    pub fn mm(&self, role: Role, with: &[&str], without: &[&str]) -> Option<f64> {
        self.find(role, with, without).map(|d| d.mm)
    }

    /// A diameter, or twice a radius, qualified the same way.
    pub fn diameter(&self, with: &[&str], without: &[&str]) -> Option<f64> {
        self.mm(Role::Diameter, with, without).or_else(|| self.mm(Role::Radius, with, without).map(|r| 2.0 * r))
    }

    /// The count given for a noun ("four holes", "6x M5", "16 teeth").
    pub fn count(&self, noun: &str) -> Option<u32> {
        self.counts.iter().find(|(n, _)| n == noun).map(|(_, c)| *c)
    }

    /// The first "A by B (by C)" list.
    pub fn list(&self) -> Vec<f64> {
        let mut out = Vec::new();
        for d in &self.dims {
            if let Some((i, _)) = d.list {
                if i == 0 && !out.is_empty() {
                    break;
                }
                out.push(d.mm);
            }
        }
        out
    }
}

pub fn contains_phrase(text: &str, phrase: &str) -> bool {
    text.match_indices(phrase).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + phrase.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_alphanumeric()) && !after.is_some_and(|c| c.is_ascii_alphanumeric())
    })
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Word(String),
    /// A number; with its unit factor to mm when it had one.
    Num(f64, Option<f64>),
    /// `,` `;` `:` `.` `(` `)` `=` `x` (times) …
    Punct(char),
}

fn unit_factor(word: &str) -> Option<f64> {
    match word {
        "mm" | "millimeter" | "millimeters" | "millimetre" | "millimetres" => Some(1.0),
        "cm" | "centimeter" | "centimeters" | "centimetre" | "centimetres" => Some(10.0),
        "m" | "meter" | "meters" | "metre" | "metres" => Some(1000.0),
        "in" | "inch" | "inches" | "\"" => Some(25.4),
        "ft" | "foot" | "feet" => Some(304.8),
        _ => None,
    }
}

fn number_word(w: &str) -> Option<u32> {
    Some(match w {
        "one" | "a" | "single" => 1,
        "two" | "both" | "pair" => 2,
        "three" => 3,
        "four" => 4,
        "five" => 5,
        "six" => 6,
        "seven" => 7,
        "eight" => 8,
        "nine" => 9,
        "ten" => 10,
        "eleven" => 11,
        "twelve" | "dozen" => 12,
        "sixteen" => 16,
        "twenty" => 20,
        _ => return None,
    })
}

/// Singular of a noun we count or qualify with.
fn fold(w: &str) -> String {
    let w = w.to_ascii_lowercase();
    match w.as_str() {
        "holes" => "hole".into(),
        "tips" => "tip".into(),
        "roots" => "root".into(),
        "circles" => "circle".into(),
        "bores" => "bore".into(),
        "flanges" => "flange".into(),
        "fillets" | "filleted" | "rounded" | "round" | "radiused" => {
            if w == "round" {
                w
            } else {
                "fillet".into()
            }
        }
        "chamfers" | "chamfered" => "chamfer".into(),
        "edges" => "edge".into(),
        "corners" => "corner".into(),
        "legs" => "leg".into(),
        "walls" => "wall".into(),
        "fins" => "fin".into(),
        "spokes" => "spoke".into(),
        "outside" => "outer".into(),
        "inside" | "internal" | "interior" => "inner".into(),
        "centre" | "central" | "centred" | "centered" => "center".into(),
        "diam" | "dia" => "diameter".into(),
        "counterbores" | "counterbored" => "counterbore".into(),
        _ if w.ends_with("-hole") || w.ends_with("-holes") => "hole".into(),
        _ => w,
    }
}

fn tokenize(text: &str) -> Vec<Tok> {
    let chars: Vec<char> = text.chars().collect();
    let mut toks = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(|d| d.is_ascii_digit())) {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                // A full stop ends a number unless a digit follows.
                if chars[i] == '.' && !chars.get(i + 1).is_some_and(|d| d.is_ascii_digit()) {
                    break;
                }
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            let Ok(mut v) = s.parse::<f64>() else {
                continue;
            };
            // "X=-25": a signed coordinate.
            if start >= 2
                && chars[start - 1] == '-'
                && chars[..start - 1].iter().rev().find(|c| **c != ' ') == Some(&'=')
            {
                v = -v;
            }
            // A unit, directly or after a space.
            let mut j = i;
            while j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            let mut k = j;
            while k < chars.len() && chars[k].is_ascii_alphabetic() {
                k += 1;
            }
            let unit: String = chars[j..k].iter().collect::<String>().to_ascii_lowercase();
            if let Some(f) = unit_factor(&unit) {
                toks.push(Tok::Num(v, Some(f)));
                i = k;
            } else if chars.get(i) == Some(&'"') {
                toks.push(Tok::Num(v, Some(25.4)));
                i += 1;
            } else if unit == "x" && k == i + 1 {
                // "4x" — a multiplier, handled as a count.
                toks.push(Tok::Num(v, None));
                toks.push(Tok::Punct('x'));
                i = k;
            } else {
                toks.push(Tok::Num(v, None));
            }
        } else if c.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '-' || chars[i] == '\'') {
                i += 1;
            }
            let w: String = chars[start..i].iter().collect::<String>().to_ascii_lowercase();
            let w = w.trim_end_matches('-').to_string();
            // "M6" — a metric screw size: its clearance hole.
            if let Some(size) = w.strip_prefix('m').and_then(|s| s.parse::<f64>().ok()) {
                toks.push(Tok::Word("metric".into()));
                toks.push(Tok::Num(metric_clearance(size), Some(1.0)));
                toks.push(Tok::Word("diameter".into()));
                continue;
            }
            if w == "x" || w == "×" {
                toks.push(Tok::Punct('x'));
            } else {
                toks.push(Tok::Word(w));
            }
        } else if c == '×' || c == '*' {
            toks.push(Tok::Punct('x'));
            i += 1;
        } else if matches!(c, ',' | ';' | ':' | '.' | '(' | ')' | '=' | '/' | '"') {
            toks.push(Tok::Punct(c));
            i += 1;
        } else {
            i += 1;
        }
    }
    // "Z=0 to Z=10": a coordinate without a unit is in the prompt's unit.
    let unit = toks.iter().find_map(|t| if let Tok::Num(_, Some(f)) = t { Some(*f) } else { None }).unwrap_or(1.0);
    for i in 2..toks.len() {
        if let Tok::Num(v, None) = toks[i]
            && matches!(toks[i - 1], Tok::Punct('='))
            && matches!(&toks[i - 2], Tok::Punct('x') | Tok::Word(_))
        {
            toks[i] = Tok::Num(v, Some(unit));
        }
    }
    // "80 x 60 x 5 mm": the last unit applies to the whole list.
    for i in (0..toks.len()).rev() {
        if let Tok::Num(v, None) = toks[i]
            && i + 1 < toks.len()
        {
            let sep = match &toks[i + 1] {
                Tok::Punct('x') => true,
                Tok::Word(w) => w == "by",
                _ => false,
            };
            if let (true, Some(Tok::Num(_, Some(f)))) = (sep, toks.get(i + 2)) {
                let f = *f;
                toks[i] = Tok::Num(v, Some(f));
            }
        }
    }
    toks
}

/// ISO 273 medium clearance hole of a metric screw.
fn metric_clearance(size: f64) -> f64 {
    const TABLE: &[(f64, f64)] = &[
        (2.0, 2.4),
        (2.5, 2.9),
        (3.0, 3.4),
        (4.0, 4.5),
        (5.0, 5.5),
        (6.0, 6.6),
        (8.0, 9.0),
        (10.0, 11.0),
        (12.0, 13.5),
        (16.0, 17.5),
        (20.0, 22.0),
    ];
    TABLE.iter().find(|(s, _)| (s - size).abs() < 1e-9).map_or(size * 1.1, |(_, c)| *c)
}

fn role_of(word: &str) -> Option<Role> {
    Some(match word {
        "long" | "length" | "lengths" | "extruded" | "extrude" => Role::Length,
        "wide" | "width" | "broad" => Role::Width,
        "tall" | "high" | "height" | "heights" => Role::Height,
        "thick" | "thickness" => Role::Thickness,
        "deep" | "depth" => Role::Depth,
        "diameter" | "diameters" => Role::Diameter,
        "radius" | "radii" => Role::Radius,
        "side" | "sides" | "sided" => Role::Side,
        "fillet" => Role::Fillet,
        "chamfer" => Role::Chamfer,
        "inset" | "offset" => Role::Inset,
        "spacing" | "spaced" | "intervals" | "apart" => Role::Spacing,
        _ => return None,
    })
}

/// Words that end the phrase after a length (what follows belongs to the next one).
fn is_stop(word: &str) -> bool {
    matches!(
        word,
        "and" | "with" | "on" | "at" | "of" | "from" | "through" | "to" | "in" | "by" | "into" | "onto" | "is" | "are"
    )
}

/// Reads every length, its role and its qualifiers, and the counts.
pub fn read(prompt: &str) -> Reading {
    let text = prompt.to_ascii_lowercase();
    let toks = tokenize(prompt);
    let words: Vec<String> = toks
        .iter()
        .filter_map(|t| match t {
            Tok::Word(w) => Some(fold(w)),
            _ => None,
        })
        .collect();

    // Clause index and parenthesis depth per token.
    let mut clause = 0usize;
    let mut depth = 0usize;
    let mut clause_of = Vec::with_capacity(toks.len());
    let mut paren_of = Vec::with_capacity(toks.len());
    for t in &toks {
        match t {
            Tok::Punct('(') => {
                depth += 1;
                clause += 1;
            }
            Tok::Punct(')') => {
                depth = depth.saturating_sub(1);
                clause += 1;
            }
            Tok::Punct(',' | ';' | ':' | '.') => clause += 1,
            Tok::Word(w) if w == "and" || w == "with" || w == "while" => clause += 1,
            _ => {}
        }
        clause_of.push(clause);
        paren_of.push(depth > 0);
    }
    let clause_words = |c: usize| -> BTreeSet<String> {
        toks.iter()
            .zip(&clause_of)
            .filter(|(_, k)| **k == c)
            .filter_map(|(t, _)| match t {
                Tok::Word(w) => Some(fold(w)),
                _ => None,
            })
            .filter(|w| MODS.contains(&w.as_str()))
            .collect()
    };

    let mut dims = Vec::new();
    let mut dim_toks = Vec::new();
    let nums: Vec<usize> =
        toks.iter().enumerate().filter(|(_, t)| matches!(t, Tok::Num(_, Some(_)))).map(|(i, _)| i).collect();
    for (n, &i) in nums.iter().enumerate() {
        let Tok::Num(v, Some(f)) = toks[i] else { continue };
        // A coordinate ("Z=3mm") is a position, not a size.
        let coord = if i > 1 && matches!(toks[i - 1], Tok::Punct('=')) {
            match &toks[i - 2] {
                Tok::Punct('x') => Some(Axis::X),
                Tok::Word(a) if a == "y" => Some(Axis::Y),
                Tok::Word(a) if a == "z" => Some(Axis::Z),
                _ => continue,
            }
        } else {
            None
        };
        let c = clause_of[i];
        let prev_num = if n > 0 { nums[n - 1] } else { 0 };
        let next_num = nums.get(n + 1).copied().unwrap_or(toks.len());
        // The phrase after: up to a stop word, a clause break or the next length.
        let mut after = Vec::new();
        let mut axis = None;
        let mut j = i + 1;
        while j < next_num && j < toks.len() {
            match &toks[j] {
                Tok::Word(w) => {
                    let w = fold(w);
                    // "60mm in diameter", "80mm on each side" read on.
                    if is_stop(&w) && !(after.is_empty() && (w == "in" || w == "on")) {
                        break;
                    }
                    after.push(w);
                }
                // "1mm 45-degree chamfer": an angle inside the phrase.
                Tok::Num(_, None) => {}
                Tok::Punct('(') => {
                    // "(X)" right after a length.
                    if matches!(toks.get(j + 2), Some(Tok::Punct(')'))) {
                        axis = match toks.get(j + 1) {
                            Some(Tok::Punct('x')) => Some(Axis::X),
                            Some(Tok::Word(a)) if a == "y" => Some(Axis::Y),
                            Some(Tok::Word(a)) if a == "z" => Some(Axis::Z),
                            _ => None,
                        };
                    }
                    break;
                }
                _ => break,
            }
            j += 1;
        }
        // The phrase before: back to the previous length or the clause start.
        let mut before = Vec::new();
        let mut j = i;
        while j > prev_num && j > 0 {
            j -= 1;
            if clause_of[j] != c {
                break;
            }
            match &toks[j] {
                Tok::Word(w) => before.push(fold(w)),
                Tok::Punct('x') => {}
                _ => break,
            }
        }
        before.reverse();
        // The word right after ("20mm thick"), else right before ("thickness 2mm"), else
        // any after ("80mm on each side"), else any before ("a diameter of 25mm").
        let circle = after.iter().any(|w| w == "circle" || w == "diameter");
        let role = after
            .first()
            .and_then(|w| role_of(w))
            .or_else(|| before.last().and_then(|w| role_of(w)))
            .or_else(|| after.iter().find_map(|w| role_of(w)))
            .or_else(|| before.iter().rev().find_map(|w| role_of(w)))
            .or_else(|| (after.iter().chain(before.iter()).any(|w| w == "pitch") && !circle).then_some(Role::Spacing))
            .unwrap_or(Role::Bare);
        let role = match role {
            // "extruded to a height of" — the height wins over "extruded".
            Role::Length if before.iter().any(|w| w == "height") => Role::Height,
            r => r,
        };
        if axis.is_none() {
            let along = after.iter().chain(before.iter()).collect::<Vec<_>>();
            for (k, w) in along.iter().enumerate() {
                if (*w == "along" || *w == "in") && k + 1 < along.len() {
                    axis = match along[k + 1].as_str() {
                        "x" => Some(Axis::X),
                        "y" => Some(Axis::Y),
                        "z" => Some(Axis::Z),
                        _ => axis,
                    };
                }
            }
        }
        let mods: BTreeSet<String> =
            before.iter().chain(after.iter()).filter(|w| MODS.contains(&w.as_str())).cloned().collect();
        dims.push(Dim {
            mm: v * f,
            role,
            mods,
            clause_mods: clause_words(c),
            axis,
            clause: c,
            paren: paren_of[i],
            list: None,
            coord,
        });
        dim_toks.push(i);
    }

    // "M4 clearance holes (4.2mm diameter)": the stated diameter wins over the table's.
    let mut k = 0;
    while k < dims.len() {
        let metric = dims[k].mods.contains("metric");
        let stated = metric
            && dims.iter().zip(&dim_toks).any(|(d, &t)| {
                !d.mods.contains("metric") && d.role == Role::Diameter && t > dim_toks[k] && t <= dim_toks[k] + 12
            });
        if stated {
            dims.remove(k);
            dim_toks.remove(k);
        } else {
            k += 1;
        }
    }

    // "A by B by C" / "A x B x C" lists (coordinates are never part of one).
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut last: Option<usize> = None;
    for (k, d) in dims.iter().enumerate() {
        if d.coord.is_some() {
            continue;
        }
        let i = dim_toks[k];
        let joined = last.is_some_and(|p| {
            let between = &toks[dim_toks[p] + 1..i];
            !between.is_empty()
                && between.len() <= 5
                && between.iter().any(|t| matches!(t, Tok::Word(w) if w == "by") || matches!(t, Tok::Punct('x')))
                && between.iter().all(|t| match t {
                    Tok::Word(w) => w == "by" || w == "y" || w == "z",
                    Tok::Punct(c) => matches!(c, 'x' | '(' | ')'),
                    Tok::Num(..) => false,
                })
        });
        if joined {
            if let Some(g) = groups.last_mut() {
                g.push(k);
            }
        } else {
            groups.push(vec![k]);
        }
        last = Some(k);
    }
    for g in groups.into_iter().filter(|g| g.len() >= 2) {
        let n = g.len();
        for (pos, k) in g.into_iter().enumerate() {
            if let Some(d) = dims.get_mut(k) {
                d.list = Some((pos, n));
            }
        }
    }

    // Counts: a number (digits or a word) followed by a noun, or "4x".
    let mut counts = Vec::new();
    for (i, t) in toks.iter().enumerate() {
        let n = match t {
            Tok::Num(v, None) if v.fract() == 0.0 && *v >= 1.0 && *v <= 1000.0 => Some(*v as u32),
            Tok::Word(w) => number_word(w).filter(|_| w != "a"),
            _ => None,
        };
        let Some(n) = n else { continue };
        if i > 0 && matches!(toks[i - 1], Tok::Punct('=')) {
            continue;
        }
        // The noun: the next word that is not an adjective we know, within 4 tokens.
        for t in toks.iter().skip(i + 1).take(5) {
            match t {
                Tok::Word(w) => {
                    let w = fold(w);
                    if matches!(
                        w.as_str(),
                        "metric"
                            | "diameter"
                            | "radius"
                            | "wide"
                            | "long"
                            | "deep"
                            | "mounting"
                            | "clearance"
                            | "through"
                            | "bolt"
                            | "rectangular"
                            | "triangular"
                            | "equal"
                            | "counterbore"
                            | "circular"
                            | "round"
                            | "evenly"
                            | "spaced"
                            | "cylindrical"
                            | "upright"
                            | "parallel"
                            | "identical"
                            | "small"
                            | "large"
                            | "radial"
                            | "lightening"
                            | "mounting-holes"
                    ) {
                        continue;
                    }
                    let noun = match w.as_str() {
                        "teeth" | "tooth" => "teeth".to_string(),
                        "vertices" => "vertices".to_string(),
                        _ => w.trim_end_matches('s').to_string(),
                    };
                    counts.push((noun, n));
                    break;
                }
                Tok::Punct('x') => continue,
                Tok::Num(_, Some(_)) => continue,
                _ => break,
            }
        }
    }
    Reading { dims, words, text, counts }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn washer_reads_outer_inner_and_thickness() {
        let r = read("A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm");
        assert_eq!(r.mm(Role::Diameter, &["outer"], &[]), Some(20.0));
        assert_eq!(r.mm(Role::Diameter, &["inner"], &[]), Some(10.5));
        assert_eq!(r.mm(Role::Thickness, &[], &[]), Some(2.0));
    }

    #[test]
    fn units_convert_to_mm() {
        let r = read("a rod 2 cm in diameter and 0.5 m long");
        assert_eq!(r.mm(Role::Diameter, &[], &[]), Some(20.0));
        assert_eq!(r.mm(Role::Length, &[], &[]), Some(500.0));
        let r = read("a plate 4 inches wide");
        assert!((r.mm(Role::Width, &[], &[]).unwrap_or(0.0) - 101.6).abs() < 1e-9);
    }

    #[test]
    fn lists_and_counts() {
        let r = read("A rectangular block with dimensions 120mm by 45mm by 15mm and four M6 holes");
        assert_eq!(r.list(), vec![120.0, 45.0, 15.0]);
        assert_eq!(r.count("hole"), Some(4));
        assert_eq!(r.mm(Role::Diameter, &[], &[]), Some(6.6));
        let r = read("a plate 80 x 60 x 5 mm with 6x holes");
        assert_eq!(r.count("hole"), Some(6));
    }

    #[test]
    fn coordinates_are_not_sizes() {
        let r = read("a flange 30mm outer diameter, 3mm thick (Z=0 to Z=3mm) at X=-25");
        assert_eq!(r.dims.iter().filter(|d| d.coord.is_none()).count(), 2);
        let coords: Vec<(Option<Axis>, f64)> =
            r.dims.iter().filter(|d| d.coord.is_some()).map(|d| (d.coord, d.mm)).collect();
        assert_eq!(coords, vec![(Some(Axis::Z), 0.0), (Some(Axis::Z), 3.0), (Some(Axis::X), -25.0)]);
        assert_eq!(r.mm(Role::Thickness, &[], &[]), Some(3.0));
    }
}
