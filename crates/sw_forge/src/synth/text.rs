//! The prompt as tokens: words (lower case, plural nouns folded), numbers with their
//! units, and punctuation, each with its place in the prompt so that a refusal can quote
//! the exact words it could not read. Numbers become quantities: lengths in mm (a unit
//! given, inherited by a list, or a coordinate "Z=3"), angles, counts and "±" pairs.

/// A token and where it is in the prompt (byte offsets).
#[derive(Debug, Clone, PartialEq)]
pub struct Token {
    pub kind: Tk,
    pub start: usize,
    pub end: usize,
}

#[derive(Debug, Clone, PartialEq)]
pub enum Tk {
    Word(String),
    /// A number; `unit` its factor to mm when a length unit followed it; `pm` when it was
    /// written "±" or "+/-"; `signed` when it carried an explicit sign.
    Num {
        v: f64,
        unit: Option<f64>,
        pm: bool,
        signed: bool,
    },
    /// An angle in degrees ("45°", "45-degree", "45 degrees").
    Deg(f64),
    Sym(char),
}

impl Token {
    pub fn word(&self) -> Option<&str> {
        match &self.kind {
            Tk::Word(w) => Some(w),
            _ => None,
        }
    }

    pub fn is_word(&self, w: &str) -> bool {
        self.word() == Some(w)
    }

    pub fn is_sym(&self, c: char) -> bool {
        self.kind == Tk::Sym(c)
    }
}

fn unit_factor(word: &str) -> Option<f64> {
    match word {
        "mm" | "millimeter" | "millimeters" | "millimetre" | "millimetres" => Some(1.0),
        "cm" | "centimeter" | "centimeters" | "centimetre" | "centimetres" => Some(10.0),
        "m" | "meter" | "meters" | "metre" | "metres" => Some(1000.0),
        "inch" | "inches" => Some(25.4),
        "ft" | "foot" | "feet" => Some(304.8),
        _ => None,
    }
}

/// Plural and inflected forms folded to the word the lexicon knows.
pub fn fold(w: &str) -> String {
    const SAME: &[(&str, &str)] = &[
        ("teeth", "tooth"),
        ("vertices", "vertex"),
        ("axes", "axis"),
        ("radii", "radius"),
        ("diameters", "diameter"),
        ("centre", "center"),
        ("centred", "centered"),
        ("centres", "center"),
        ("centers", "center"),
        ("centerline", "centerline"),
        ("disk", "disc"),
        ("disks", "disc"),
        ("dia", "diameter"),
        ("diam", "diameter"),
        ("grey", "gray"),
        ("millimetres", "mm"),
        ("shelves", "shelf"),
        ("leaves", "leaf"),
        ("knives", "knife"),
        ("ends", "end"),
        ("bosses", "boss"),
        ("bushes", "bush"),
        ("brushes", "brush"),
        ("boxes", "box"),
        ("benches", "bench"),
        ("inches", "inch"),
        ("notches", "notch"),
        ("arches", "arch"),
        ("series", "series"),
        ("press", "press"),
        ("glass", "glass"),
        ("across", "across"),
        ("thickness", "thickness"),
        ("radius", "radius"),
        ("axis", "axis"),
        ("chassis", "chassis"),
        ("its", "its"),
        ("this", "this"),
        ("has", "has"),
        ("was", "was"),
        ("is", "is"),
        ("as", "as"),
        ("us", "us"),
        ("plus", "plus"),
        ("minus", "minus"),
        ("less", "less"),
        ("gas", "gas"),
        ("thus", "thus"),
        ("degrees", "degree"),
    ];
    if let Some((_, to)) = SAME.iter().find(|(from, _)| *from == w) {
        return (*to).to_string();
    }
    for (suffix, keep) in [("sses", 2), ("oes", 1), ("ches", 2), ("shes", 2), ("xes", 1)] {
        if w.len() > suffix.len() && w.ends_with(suffix) {
            return w[..w.len() - suffix.len() + keep].to_string();
        }
    }
    if w.len() > 4 && w.ends_with("ies") {
        return format!("{}y", &w[..w.len() - 3]);
    }
    if w.len() > 3 && w.ends_with('s') && !w.ends_with("ss") && !w.ends_with("us") && !w.ends_with("is") {
        return w[..w.len() - 1].to_string();
    }
    w.to_string()
}

/// ISO 273 medium clearance hole of a metric screw ("M4" → 4.5 mm).
pub fn metric_clearance(size: f64) -> f64 {
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

/// Splits a prompt into tokens.
pub fn tokenize(text: &str) -> Vec<Token> {
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let at = |i: usize| chars.get(i).map(|c| c.1);
    let pos = |i: usize| chars.get(i).map_or(text.len(), |c| c.0);
    let mut toks: Vec<Token> = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i].1;
        let start = pos(i);
        // "±22", "+/-22", "+25", "-25" (a sign directly before a digit, not after a letter
        // or digit: "X=-25", "(-30"), handled with the number.
        let mut pm = false;
        let mut sign = 0.0f64;
        let mut j = i;
        if c == '±' {
            pm = true;
            j += 1;
        } else if c == '+' && at(i + 1) == Some('/') && at(i + 2) == Some('-') {
            pm = true;
            j += 3;
        } else if (c == '+' || c == '-' || c == '−')
            && at(i + 1).is_some_and(|d| d.is_ascii_digit() || d == '.')
            && !(i > 0 && at(i - 1).is_some_and(|p| p.is_alphanumeric()))
        {
            sign = if c == '+' { 1.0 } else { -1.0 };
            j += 1;
        }
        while pm && at(j) == Some(' ') {
            j += 1;
        }
        let digit_start = at(j).is_some_and(|d| d.is_ascii_digit())
            || (at(j) == Some('.') && at(j + 1).is_some_and(|d| d.is_ascii_digit()));
        if (pm || sign != 0.0 || j == i) && digit_start {
            let ns = j;
            while j < chars.len() {
                let d = chars[j].1;
                if d.is_ascii_digit() || (d == '.' && at(j + 1).is_some_and(|e| e.is_ascii_digit())) {
                    j += 1;
                } else {
                    break;
                }
            }
            let s: String = chars[ns..j].iter().map(|c| c.1).collect();
            let Ok(mut v) = s.parse::<f64>() else {
                i = j.max(i + 1);
                continue;
            };
            if sign < 0.0 {
                v = -v;
            }
            let signed = sign != 0.0;
            // A unit, directly or after a space; a hyphenated noun ("16-tooth", "45-degree").
            let mut k = j;
            while at(k) == Some(' ') {
                k += 1;
            }
            let hyphen = at(j) == Some('-');
            if hyphen {
                k = j + 1;
            }
            let mut e = k;
            while at(e).is_some_and(|c| c.is_ascii_alphabetic()) {
                e += 1;
            }
            let unit: String = chars[k..e].iter().map(|c| c.1).collect::<String>().to_ascii_lowercase();
            if at(j) == Some('°') {
                toks.push(Token { kind: Tk::Deg(v), start, end: pos(j + 1) });
                i = j + 1;
                continue;
            }
            if unit == "degree" || unit == "degrees" || unit == "deg" {
                toks.push(Token { kind: Tk::Deg(v), start, end: pos(e) });
                i = e;
                continue;
            }
            if !hyphen && let Some(f) = unit_factor(&unit) {
                toks.push(Token { kind: Tk::Num { v, unit: Some(f), pm, signed }, start, end: pos(e) });
                i = e;
                continue;
            }
            if at(j) == Some('"') {
                toks.push(Token { kind: Tk::Num { v, unit: Some(25.4), pm, signed }, start, end: pos(j + 1) });
                i = j + 1;
                continue;
            }
            if unit == "x" && e == j + 1 {
                // "4x", "3x2": a multiplier.
                toks.push(Token { kind: Tk::Num { v, unit: None, pm, signed }, start, end: pos(j) });
                toks.push(Token { kind: Tk::Sym('x'), start: pos(j), end: pos(e) });
                i = e;
                continue;
            }
            // "1/16 inch": a fraction.
            if at(j) == Some('/') && at(j + 1).is_some_and(|d| d.is_ascii_digit()) && v.fract() == 0.0 {
                let mut k = j + 1;
                while at(k).is_some_and(|d| d.is_ascii_digit()) {
                    k += 1;
                }
                let den: String = chars[j + 1..k].iter().map(|c| c.1).collect();
                if let Ok(d) = den.parse::<f64>()
                    && d > 0.0
                {
                    // Put the fraction back as one number and read its unit again.
                    let value = v / d;
                    let mut e = k;
                    while at(e) == Some(' ') {
                        e += 1;
                    }
                    let mut f = e;
                    while at(f).is_some_and(|c| c.is_ascii_alphabetic()) {
                        f += 1;
                    }
                    let unit: String = chars[e..f].iter().map(|c| c.1).collect::<String>().to_ascii_lowercase();
                    if let Some(u) = unit_factor(&unit) {
                        toks.push(Token { kind: Tk::Num { v: value, unit: Some(u), pm, signed }, start, end: pos(f) });
                        i = f;
                    } else {
                        toks.push(Token { kind: Tk::Num { v: value, unit: None, pm, signed }, start, end: pos(k) });
                        i = k;
                    }
                    continue;
                }
            }
            toks.push(Token { kind: Tk::Num { v, unit: None, pm, signed }, start, end: pos(j) });
            i = j;
            continue;
        }
        // "i.e." and "e.g.": one word, not two sentences.
        if (c == 'i' || c == 'e' || c == 'I' || c == 'E')
            && at(i + 1) == Some('.')
            && at(i + 3) == Some('.')
            && !(i > 0 && at(i - 1).is_some_and(|p| p.is_alphanumeric()))
        {
            let pair: String = [Some(c), at(i + 2)].iter().flatten().collect::<String>().to_lowercase();
            if pair == "ie" || pair == "eg" {
                toks.push(Token {
                    kind: Tk::Word(if pair == "ie" { "i.e".into() } else { "e.g".into() }),
                    start,
                    end: pos(i + 4),
                });
                i += 4;
                continue;
            }
        }
        if c.is_alphabetic() {
            let mut j = i;
            while j < chars.len() {
                let d = chars[j].1;
                let joins = (d == '-' || d == '\'') && at(j + 1).is_some_and(|e| e.is_alphanumeric());
                if d.is_alphanumeric() || joins {
                    j += 1;
                } else {
                    break;
                }
            }
            let raw: String = chars[i..j].iter().map(|c| c.1).collect();
            let w = raw.to_lowercase();
            // "M6": a metric screw size.
            if let Some(size) = w.strip_prefix('m').and_then(|s| s.parse::<f64>().ok()) {
                toks.push(Token { kind: Tk::Word("metric".into()), start, end: pos(j) });
                toks.push(Token {
                    kind: Tk::Num { v: metric_clearance(size), unit: Some(1.0), pm: false, signed: false },
                    start,
                    end: pos(j),
                });
                i = j;
                continue;
            }
            if w == "x" {
                toks.push(Token { kind: Tk::Sym('x'), start, end: pos(j) });
            } else {
                toks.push(Token { kind: Tk::Word(fold(&w)), start, end: pos(j) });
            }
            i = j;
            continue;
        }
        match c {
            '×' | '*' => toks.push(Token { kind: Tk::Sym('x'), start, end: pos(i + 1) }),
            '°' => toks.push(Token { kind: Tk::Word("degree".into()), start, end: pos(i + 1) }),
            ',' | ';' | ':' | '.' | '(' | ')' | '=' | '/' | '+' | '-' | '[' | ']' | '?' | '!' => {
                toks.push(Token { kind: Tk::Sym(c), start, end: pos(i + 1) })
            }
            _ => {}
        }
        i += 1;
    }
    inherit_units(&mut toks);
    toks
}

/// Gives a unit to numbers that take it from their neighbours: coordinates ("Z=0 to
/// Z=10", "(X=+25, Y=20)"), lists ("80 x 60 x 5 mm", "100 by 60mm"), tuples ("(±60, 0) mm")
/// and runs ("at 0, 60 and 120 degrees" becomes angles).
fn inherit_units(toks: &mut [Token]) {
    let unit = toks
        .iter()
        .find_map(|t| if let Tk::Num { unit: Some(f), .. } = t.kind { Some(f) } else { None })
        .unwrap_or(1.0);
    // Coordinates.
    for i in 2..toks.len() {
        if let Tk::Num { v, unit: None, pm, signed } = toks[i].kind
            && toks[i - 1].is_sym('=')
            && (matches!(toks[i - 2].word(), Some("x" | "y" | "z" | "r")) || toks[i - 2].is_sym('x'))
        {
            toks[i].kind = Tk::Num { v, unit: Some(unit), pm, signed };
        }
    }
    // Lists and tuples: a unitless number whose run (separated by x, by, commas, and, or
    // inside parentheses) ends in a number with a unit, or in ") mm".
    let n = toks.len();
    let mut i = n;
    while i > 0 {
        i -= 1;
        let Tk::Num { unit: Some(f), .. } = toks[i].kind else {
            // ") mm" after a tuple.
            if toks[i].is_sym(')')
                && let Some(Tk::Word(w)) = toks.get(i + 1).map(|t| &t.kind)
                && let Some(f) = unit_factor(w)
            {
                let mut j = i;
                let mut depth = 0;
                while j > 0 {
                    j -= 1;
                    match &toks[j].kind {
                        Tk::Sym(')') => depth += 1,
                        Tk::Sym('(') if depth == 0 => {
                            // Earlier tuples of the same run: "(±60, 0) and (0, ±60) mm".
                            let mut k = j;
                            while k > 0 && (toks[k - 1].is_word("and") || toks[k - 1].is_sym(',')) {
                                k -= 1;
                                if k > 0 && toks[k - 1].is_sym(')') {
                                    let mut d2 = 0;
                                    while k > 0 {
                                        k -= 1;
                                        if toks[k].is_sym(')') {
                                            d2 += 1;
                                        } else if toks[k].is_sym('(') {
                                            d2 -= 1;
                                            if d2 == 0 {
                                                break;
                                            }
                                        }
                                    }
                                    j = k;
                                } else {
                                    break;
                                }
                            }
                            break;
                        }
                        Tk::Sym('(') => depth -= 1,
                        _ => {}
                    }
                }
                for t in toks.iter_mut().take(i).skip(j) {
                    if let Tk::Num { v, unit: None, pm, signed } = t.kind {
                        t.kind = Tk::Num { v, unit: Some(f), pm, signed };
                    }
                }
            }
            continue;
        };
        let mut j = i;
        while j > 0 {
            let sep = &toks[j - 1];
            let joins = sep.is_sym('x') || sep.is_word("by");
            if !joins {
                break;
            }
            if j >= 2
                && let Tk::Num { v, unit: None, pm, signed } = toks[j - 2].kind
            {
                toks[j - 2].kind = Tk::Num { v, unit: Some(f), pm, signed };
                j -= 2;
            } else {
                break;
            }
        }
    }
    // "at 0, 60, 120, 180, 240, and 300 degrees": the run before an angle.
    let mut i = n;
    while i > 0 {
        i -= 1;
        if !matches!(toks[i].kind, Tk::Deg(_)) {
            continue;
        }
        let mut j = i;
        while j >= 2 {
            let sep_ok = toks[j - 1].is_sym(',') || toks[j - 1].is_word("and");
            let (k, sep_ok) = if toks[j - 1].is_word("and") && j >= 3 && toks[j - 2].is_sym(',') {
                (j - 2, true)
            } else {
                (j - 1, sep_ok)
            };
            if !sep_ok || k == 0 {
                break;
            }
            if let Tk::Num { v, unit: None, .. } = toks[k - 1].kind {
                toks[k - 1].kind = Tk::Deg(v);
                j = k - 1;
            } else {
                break;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(s: &str) -> Vec<Tk> {
        tokenize(s).into_iter().map(|t| t.kind).collect()
    }

    #[test]
    fn units_lists_coordinates_and_angles() {
        let k = kinds("a plate 80 x 60 x 5 mm at (X=+25, Y=20)");
        let lens: Vec<f64> =
            k.iter().filter_map(|t| if let Tk::Num { v, unit: Some(_), .. } = t { Some(*v) } else { None }).collect();
        assert_eq!(lens, vec![80.0, 60.0, 5.0, 25.0, 20.0]);
        let k = kinds("at 0, 60, 120, 180, 240, and 300 degrees from the +X axis");
        assert_eq!(k.iter().filter(|t| matches!(t, Tk::Deg(_))).count(), 6);
        let k = kinds("a 45-degree chamfer and a 16-tooth gear");
        assert!(k.contains(&Tk::Deg(45.0)) && k.contains(&Tk::Word("tooth".into())));
        let k = kinds("centered at (±60, 0) and (0, ±60) mm");
        assert_eq!(k.iter().filter(|t| matches!(t, Tk::Num { unit: Some(_), .. })).count(), 4);
        let k = kinds("positions (+/-22, +/-22) mm from the center");
        assert!(matches!(k[2], Tk::Num { v, pm: true, unit: Some(_), .. } if v == 22.0), "{k:?}");
    }

    #[test]
    fn spans_quote_the_prompt() {
        let text = "An L-bracket with a dragon";
        let t = tokenize(text);
        assert_eq!(&text[t[1].start..t[1].end], "L-bracket");
        assert_eq!(t[1].kind, Tk::Word("l-bracket".into()));
        assert_eq!(t[4].kind, Tk::Word("dragon".into()));
    }
}
