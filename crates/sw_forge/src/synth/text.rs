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
    // "that's", "bar's": the word itself.
    if let Some(base) = w.strip_suffix("'s").or_else(|| w.strip_suffix("’s"))
        && !base.is_empty()
    {
        return fold(base);
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
    // "2 in. long", "1.5 in x 3 in", "0.5 in thick", "3/8 in holes": after a number, "in"
    // ending at `e` is the inch, not the preposition, unless an article or a place follows.
    let inch_after = |e: usize| {
        let mut f = e;
        while at(f) == Some(' ') {
            f += 1;
        }
        let mut g = f;
        while at(g).is_some_and(|c| c.is_ascii_alphabetic()) {
            g += 1;
        }
        let next: String = chars[f..g].iter().map(|c| c.1).collect::<String>().to_ascii_lowercase();
        let article = matches!(
            next.as_str(),
            "the" | "a" | "an" | "its" | "each" | "one" | "both" | "from" | "which" | "this" | "that" | "all" | "place"
        );
        let coordinate = matches!(next.as_str(), "x" | "y" | "z") && at(g) == Some('=');
        !(article || coordinate)
    };
    // A role symbol read before the next number ("Ø"), and where it began.
    let mut pending_role: Option<(&'static str, usize)> = None;
    while i < chars.len() {
        if let Some((role, from)) = pending_role
            && toks.last().is_some_and(|t| matches!(t.kind, Tk::Num { .. }) && t.end > from && t.start >= from)
        {
            // The number just read: it begins at the symbol, and its role word follows it.
            let (s, e) = (from, toks.last().map_or(from, |t| t.end));
            if let Some(t) = toks.last_mut() {
                t.start = s;
            }
            toks.push(Token { kind: Tk::Word(role.into()), start: s, end: e });
            pending_role = None;
        }
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
            // "1-1/2\"", "1 1/2 in": a whole number and a fraction.
            if v.fract() == 0.0 && matches!(at(j), Some('-' | ' ')) {
                let ds = j + 1;
                let mut k = ds;
                while at(k).is_some_and(|d| d.is_ascii_digit()) {
                    k += 1;
                }
                let mut e = k + 1;
                while at(e).is_some_and(|d| d.is_ascii_digit()) {
                    e += 1;
                }
                if k > ds && at(k) == Some('/') && e > k + 1 {
                    let num: String = chars[ds..k].iter().map(|c| c.1).collect();
                    let den: String = chars[k + 1..e].iter().map(|c| c.1).collect();
                    if let (Ok(a), Ok(b)) = (num.parse::<f64>(), den.parse::<f64>())
                        && b > 0.0
                        && a < b
                    {
                        v += a / b;
                        j = e;
                    }
                }
            }
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
            let inch = super::notation::INCH_WORDS.contains(&unit.as_str()) && inch_after(e);
            // "16 SWG": a gauge, in inches.
            if unit == "swg"
                && let Some(g) = super::notation::swg_inch(v)
            {
                toks.push(Token { kind: Tk::Num { v: g * 25.4, unit: Some(1.0), pm, signed }, start, end: pos(e) });
                i = e;
                continue;
            }
            let unit_f = if inch { Some(25.4) } else { unit_factor(&unit) };
            if !hyphen && let Some(f) = unit_f {
                // "in." is the unit's abbreviation, not the end of a sentence.
                let e = if inch && at(e) == Some('.') && at(e + 1).is_some_and(|c| c == ' ') && {
                    let mut q = e + 1;
                    while at(q) == Some(' ') {
                        q += 1;
                    }
                    at(q).is_some_and(|c| c.is_ascii_lowercase() || c.is_ascii_digit())
                } {
                    e + 1
                } else {
                    e
                };
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
                    // "3/8\"": the inch mark right after the fraction.
                    if at(k) == Some('"') {
                        toks.push(Token {
                            kind: Tk::Num { v: value, unit: Some(25.4), pm, signed },
                            start,
                            end: pos(k + 1),
                        });
                        i = k + 1;
                        continue;
                    }
                    let mut e = k;
                    while at(e) == Some(' ') {
                        e += 1;
                    }
                    let mut f = e;
                    while at(f).is_some_and(|c| c.is_ascii_alphabetic()) {
                        f += 1;
                    }
                    let unit: String = chars[e..f].iter().map(|c| c.1).collect::<String>().to_ascii_lowercase();
                    let u = if super::notation::INCH_WORDS.contains(&unit.as_str()) && inch_after(f) {
                        Some(25.4)
                    } else {
                        unit_factor(&unit)
                    };
                    if let Some(u) = u {
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
        // "Ø20", "⌀ 20": the number's role, written after it ("20 diameter") so that the
        // phrase reads as the language's own.
        if let Some(role) = super::notation::role_symbol(c) {
            let mut k = i + 1;
            while at(k) == Some(' ') {
                k += 1;
            }
            if at(k).is_some_and(|d| d.is_ascii_digit() || d == '.') {
                pending_role = Some((role, start));
                i = k;
                continue;
            }
            // "20⌀": written after the number.
            if let Some(t) = toks.last()
                && matches!(t.kind, Tk::Num { .. })
                && t.end == start
            {
                let s = t.start;
                toks.push(Token { kind: Tk::Word(role.into()), start: s, end: pos(i + 1) });
                i += 1;
                continue;
            }
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
                // "C0.5", "R2.5", "M2.5": a letter and a decimal number, one word.
                let point = d == '.'
                    && j > i + 1
                    && chars[i + 1..j].iter().all(|c| c.1.is_ascii_digit())
                    && at(j + 1).is_some_and(|e| e.is_ascii_digit());
                if d.is_alphanumeric() || joins || point {
                    j += 1;
                } else {
                    break;
                }
            }
            let raw: String = chars[i..j].iter().map(|c| c.1).collect();
            let mut w = raw.to_lowercase();
            // "A/F", "C/L", "w/": a spelling written with a slash.
            if at(j) == Some('/') {
                let mut k = j + 1;
                while at(k).is_some_and(|c| c.is_ascii_alphabetic()) {
                    k += 1;
                }
                let joined: String = chars[i..k].iter().map(|c| c.1).collect::<String>().to_lowercase();
                if super::notation::spelling(&joined).is_some() {
                    w = joined;
                    j = k;
                }
            }
            // "ISO 7089", "NEMA 17": a standard's designation.
            if super::notation::STANDARDS.contains(&w.as_str()) {
                let mut k = j;
                while at(k) == Some(' ') {
                    k += 1;
                }
                let ds = k;
                while at(k).is_some_and(|c| c.is_ascii_digit()) {
                    k += 1;
                }
                if k > ds && !at(k).is_some_and(|c| c.is_ascii_alphabetic() || c == '.') {
                    toks.push(Token { kind: Tk::Word("standard".into()), start, end: pos(k) });
                    i = k;
                    continue;
                }
            }
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
            // "R5": a radius.
            if let Some((role, v)) = super::notation::role_prefix(&w) {
                toks.push(Token { kind: Tk::Num { v, unit: None, pm: false, signed: false }, start, end: pos(j) });
                toks.push(Token { kind: Tk::Word(role.into()), start, end: pos(j) });
                i = j;
                continue;
            }
            if w == "x" {
                toks.push(Token { kind: Tk::Sym('x'), start, end: pos(j) });
            } else if let Some(words) = super::notation::spelling(&w) {
                for to in words {
                    toks.push(Token { kind: Tk::Word((*to).into()), start, end: pos(j) });
                }
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
    if let Some((role, from)) = pending_role
        && toks.last().is_some_and(|t| matches!(t.kind, Tk::Num { .. }) && t.start >= from)
    {
        let e = toks.last().map_or(from, |t| t.end);
        if let Some(t) = toks.last_mut() {
            t.start = from;
        }
        toks.push(Token { kind: Tk::Word(role.into()), start: from, end: e });
    }
    compounds(&mut toks);
    slash_pairs(&mut toks);
    inherit_units(&mut toks);
    notes(&mut toks, text);
    toks
}

/// "OD 140 / ID 60", "30 OD / 17 ID", "Ø40 / Ø20": a slash between two sizes that each
/// carry their role is a list of them, read as a comma.
fn slash_pairs(toks: &mut [Token]) {
    let role = |t: Option<&Token>| t.and_then(Token::word).is_some_and(|w| super::doc::role_of(w).is_some());
    let num = |t: Option<&Token>| t.is_some_and(|t| matches!(t.kind, Tk::Num { .. }));
    for i in 1..toks.len() {
        if !toks[i].is_sym('/') {
            continue;
        }
        // Before: "140" after its role word, or "30 OD"; after: "ID 60", "17 ID" or "Ø20".
        let left = num(toks.get(i - 1)) && i >= 2 && role(toks.get(i - 2))
            || role(toks.get(i - 1)) && i >= 2 && num(toks.get(i - 2));
        let right = role(toks.get(i + 1)) && num(toks.get(i + 2)) || num(toks.get(i + 1)) && role(toks.get(i + 2));
        if left && right {
            toks[i].kind = Tk::Sym(',');
        }
    }
}

/// Two words written apart that name one thing when hyphenated: a section's letter and its
/// noun ("L bracket" is an L-bracket, "U channel" a U-channel, "I beam" an I-beam), or a
/// spelling of two words ("top hat bush" is a flanged bush, "angle iron" an angle): one
/// token spanning both, read as the hyphenated word (or the words its spelling stands for).
fn compounds(toks: &mut Vec<Token>) {
    let mut i = 0;
    while i + 1 < toks.len() {
        let (Some(a), Some(b)) = (toks[i].word(), toks[i + 1].word()) else {
            i += 1;
            continue;
        };
        let joined = format!("{a}-{b}");
        let words: Option<Vec<String>> = if let Some(to) = super::notation::spelling(&joined) {
            Some(to.iter().map(|w| (*w).to_string()).collect())
        } else if a.len() == 1 && super::lexicon::noun(&joined).is_some() {
            Some(vec![joined])
        } else {
            None
        };
        if let Some(words) = words {
            let (s, e) = (toks[i].start, toks[i + 1].end);
            toks.drain(i..i + 2);
            for (k, w) in words.into_iter().enumerate() {
                toks.insert(i + k, Token { kind: Tk::Word(w), start: s, end: e });
            }
        }
        i += 1;
    }
}

/// Whether token `i` is a role written as a symbol with the number before it ("Ø20" read
/// as 20 diameter, "R5" as 5 radius, "C1" as a 1 chamfer): a word spanning that number.
fn marker(toks: &[Token], i: usize) -> bool {
    i > 0
        && toks.get(i).is_some_and(|t| matches!(t.word(), Some("diameter" | "radius" | "chamfer")))
        && toks[i].start == toks[i - 1].start
        && matches!(toks[i - 1].kind, Tk::Num { .. })
}

/// The unit of a prompt's numbers written without one: inches when every unit it writes is
/// the inch, or when it writes no unit at all and writes its numbers as inch drawings do
/// (binary fractions "3/8", "1-1/4", decimals with no leading digit ".191"); else
/// millimetres (a drawing's default; "50 x 50 x 6, 1 m length" is in mm).
fn prompt_unit(toks: &[Token], text: &str) -> f64 {
    let units: Vec<f64> =
        toks.iter().filter_map(|t| if let Tk::Num { unit: Some(f), .. } = t.kind { Some(f) } else { None }).collect();
    if !units.is_empty() {
        return if units.iter().all(|f| (f - 25.4).abs() < 1e-9) { 25.4 } else { 1.0 };
    }
    let inch_written = toks.iter().any(|t| {
        let Tk::Num { unit: None, .. } = t.kind else { return false };
        let raw = text.get(t.start..t.end).unwrap_or("").trim();
        inch_notation(raw)
    });
    if inch_written { 25.4 } else { 1.0 }
}

/// Whether a number is written the way only inch drawings write lengths: a fraction of a
/// power of two ("3/8", "1-1/4", "7/16") or a decimal with no digit before its point (".191").
fn inch_notation(raw: &str) -> bool {
    let raw = raw.trim_start_matches(['+', '-']);
    if raw.starts_with('.') && raw.len() > 1 && raw[1..].chars().all(|c| c.is_ascii_digit()) {
        return true;
    }
    let frac = raw.rsplit(['-', ' ']).next().unwrap_or(raw);
    match frac.split_once('/') {
        Some((a, b)) => {
            let (Ok(a), Ok(b)) = (a.parse::<u32>(), b.parse::<u32>()) else { return false };
            a > 0 && a < b && b.is_power_of_two() && (2..=64).contains(&b)
        }
        None => false,
    }
}

/// Drawing-note lengths: numbers written without a unit that the words around them make
/// lengths ("42 OD x 36 ID x 120 long", "Ø20", "thickness 5", "100 x 60 x 5 plate"), in the
/// prompt's unit; a chamfer's "1 x 45°"; spacings "on 50 centres"; and holes named by
/// their callout alone ("4x Ø6.6 thru", "M6 clearance").
fn notes(toks: &mut Vec<Token>, text: &str) {
    let unit = prompt_unit(toks, text);
    let n = toks.len();
    let word = |toks: &[Token], i: usize| toks.get(i).and_then(Token::word).map(str::to_string);
    let is_role = |w: &str| super::doc::role_of(w).is_some() && !matches!(w, "side" | "sided" | "extruded" | "extrude");
    let unitless = |t: &Token| matches!(t.kind, Tk::Num { unit: None, .. });
    // "0.5x45 chfr": a chamfer's angle written without its degree sign.
    for i in 2..toks.len() {
        let angle = matches!(toks[i].kind, Tk::Num { v, unit: None, .. } if v == 45.0)
            && toks[i - 1].is_sym('x')
            && matches!(toks[i - 2].kind, Tk::Num { v, .. } if v < 45.0)
            && !toks.get(i + 1).is_some_and(|t| t.is_sym('x'))
            && !toks
                .get(i + 1)
                .and_then(Token::word)
                .is_some_and(|w| matches!(super::lexicon::noun(w), Some(super::lexicon::Noun::Body(_))));
        if angle {
            toks[i].kind = Tk::Deg(45.0);
            if let Tk::Num { v, unit: None, pm, signed } = toks[i - 2].kind {
                toks[i - 2].kind = Tk::Num { v, unit: Some(unit), pm, signed };
            }
        }
    }
    // "bored 16 right through", "drilled 8 thru": the participle names the cut its number
    // sizes ("drilled 4 holes" counts them; "bored 20 deep" is a depth).
    for i in 0..n.saturating_sub(1) {
        let cut = match toks[i].word() {
            Some("bored") => "bore",
            Some("drilled") => "hole",
            _ => continue,
        };
        let sized = matches!(toks[i + 1].kind, Tk::Num { .. })
            && !word(toks, i + 2)
                .as_deref()
                .is_some_and(|w| super::lexicon::noun(w).is_some() || super::doc::role_of(w).is_some() || w == "from");
        if sized {
            toks[i].kind = Tk::Word(cut.into());
        }
    }
    let mut length = vec![false; n];
    for i in 0..n {
        if !unitless(&toks[i]) || (i > 0 && toks[i - 1].is_sym('=')) {
            continue;
        }
        let next = word(toks, i + 1);
        let length_noun = next.as_deref().is_some_and(|w| super::notation::LENGTH_NOUNS.contains(&w))
            // "40 base diameter": a qualifier noun before the role.
            || (next.as_deref().is_some_and(|w| super::doc::QUALS.contains(&w))
                && word(toks, i + 2).as_deref().is_some_and(is_role));
        // "C1": a chamfer's size, written with its letter (not one chamfer).
        let marked = marker(toks, i + 1) && toks[i + 1].is_word("chamfer");
        // A count: "6 holes", "4x Ø6.6", "16 teeth", "4 x M6".
        if !length_noun
            && !marked
            && next
                .as_deref()
                .is_some_and(|w| super::lexicon::noun(w).is_some() || matches!(w, "tooth" | "vertex" | "point"))
        {
            continue;
        }
        let next2 = word(toks, i + 2);
        let next3 = word(toks, i + 3);
        // "10 from edges", "35 from ctr", "20 from the end".
        let from_edge = matches!(next.as_deref(), Some("from" | "above" | "below" | "over" | "under" | "up"))
            && [next2.as_deref(), next3.as_deref()].iter().any(|w| {
                matches!(
                    w,
                    Some(
                        "edge"
                            | "end"
                            | "side"
                            | "corner"
                            | "center"
                            | "face"
                            | "centerline"
                            | "top"
                            | "bottom"
                            | "base"
                            | "underside"
                            | "floor"
                            | "datum"
                            | "origin"
                    )
                )
            });
        let after = next.as_deref().is_some_and(is_role)
            || length_noun
            // "40 base diameter", "30 outside dia", "12 in from each end".
            || (next.as_deref().is_some_and(|w| super::doc::QUALS.contains(&w) || w == "in")
                && next2.as_deref().is_some_and(|w| is_role(w) || w == "from"))
            || next.as_deref().is_some_and(|w| super::notation::SPACING_AFTER.contains(&w))
            || next.as_deref().is_some_and(|w| super::notation::LENGTH_AFTER.contains(&w));
        // "diameter 20", "thickness: 5", "its diameter is 30", "length of 120".
        let prev = if i >= 2
            && (toks[i - 1].is_word("of")
                || toks[i - 1].is_word("is")
                || toks[i - 1].is_word("are")
                || toks[i - 1].is_word("measures")
                || toks[i - 1].is_word("being")
                || toks[i - 1].is_sym(':')
                || toks[i - 1].is_sym('='))
        {
            word(toks, i - 2)
        } else {
            i.checked_sub(1).and_then(|p| word(toks, p))
        };
        let before = i > 0
            && prev.as_deref().is_some_and(|w| {
                matches!(
                    super::doc::role_of(w),
                    Some(
                        super::doc::Role::Diameter
                            | super::doc::Role::Radius
                            | super::doc::Role::Thickness
                            | super::doc::Role::Length
                            | super::doc::Role::Width
                            | super::doc::Role::Height
                            | super::doc::Role::Depth
                            | super::doc::Role::Fillet
                            | super::doc::Role::Chamfer
                    )
                ) && !matches!(w, "long" | "wide" | "thick" | "tall" | "high" | "deep")
                    // "bore 25", "hole 6": a hole's diameter after its noun; "projecting 10".
                    || (i >= 1
                        && matches!(w, "bore" | "hole" | "projecting" | "protruding" | "extending" | "proud" | "rising"))
            });
        // "1 x 45°": a chamfer's size.
        let chamfer = toks.get(i + 1).is_some_and(|t| t.is_sym('x'))
            && toks.get(i + 2).is_some_and(|t| matches!(t.kind, Tk::Deg(_)));
        if after || before || chamfer || from_edge || marked {
            length[i] = true;
        }
    }
    // Lists: "100 x 60 x 5" with one member a length (or all three given), all of them.
    loop {
        let mut changed = false;
        for i in 0..n {
            if !unitless(&toks[i]) || length[i] {
                continue;
            }
            let joined = |j: usize| {
                toks.get(j).is_some_and(|t| matches!(t.kind, Tk::Num { .. }))
                    && (length[j] || matches!(toks[j].kind, Tk::Num { unit: Some(_), .. }))
            };
            // The number before "x", past a role written with it ("Ø20 x 50": 20 diameter x 50).
            let before_x = |x: usize| -> Option<usize> {
                let p = x.checked_sub(1)?;
                // Past a role written with the number: "Ø20 x 50", "80 dia x 10", "42 OD x 36 ID".
                let role = marker(toks, p)
                    || (toks[p].word().is_some_and(|w| {
                        matches!(super::doc::role_of(w), Some(super::doc::Role::Diameter | super::doc::Role::Radius))
                    }) && p >= 1
                        && matches!(toks[p - 1].kind, Tk::Num { .. }));
                if role { p.checked_sub(1) } else { Some(p) }
            };
            let times = |t: Option<&Token>| t.is_some_and(|t| t.is_sym('x') || t.is_word("by"));
            let left = i >= 2 && times(toks.get(i - 1)) && before_x(i - 1).is_some_and(joined);
            // "4x Ø6.6", "2 x Ø14 holes": a count of what the Ø names, not a list.
            let right = times(toks.get(i + 1)) && joined(i + 2) && !marker(toks, i + 3);
            // "80 x 50", "200 by 150": two sizes, unless they count a grid ("3x2 array").
            let grid = (i + 3..(i + 6).min(toks.len())).any(|j| {
                toks[j].word().is_some_and(|w| matches!(super::lexicon::noun(w), Some(super::lexicon::Noun::Pattern)))
            });
            let longer = toks.get(i + 3).is_some_and(|t| t.is_sym('x') || t.is_word("by"));
            let after_times = i > 0 && times(toks.get(i - 1));
            let pair = times(toks.get(i + 1))
                && toks.get(i + 2).is_some_and(unitless)
                && !(after_times || longer || grid || marker(toks, i + 3));
            // Three numbers in a row joined by x: a box.
            let triple = times(toks.get(i + 1))
                && toks.get(i + 2).is_some_and(unitless)
                && times(toks.get(i + 3))
                && toks.get(i + 4).is_some_and(unitless)
                && !(i > 0 && toks[i - 1].is_sym('x'));
            if left || right || triple || pair {
                length[i] = true;
                if triple {
                    length[i + 2] = true;
                    length[i + 4] = true;
                }
                if pair {
                    length[i + 2] = true;
                }
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    for (i, t) in toks.iter_mut().enumerate() {
        if let (true, Tk::Num { v, unit: None, pm, signed }) = (length[i], &t.kind) {
            t.kind = Tk::Num { v: *v, unit: Some(unit), pm: *pm, signed: *signed };
        }
    }
    // "1 x 45°", "45° x 1": the times sign between a chamfer's size and angle is no list.
    let mut i = 1;
    while i + 1 < toks.len() {
        let num = |t: &Token| matches!(t.kind, Tk::Num { unit: Some(_), .. });
        let deg = |t: &Token| matches!(t.kind, Tk::Deg(_));
        let times = toks[i].is_sym('x') || toks[i].is_word("by");
        if times && ((num(&toks[i - 1]) && deg(&toks[i + 1])) || (deg(&toks[i - 1]) && num(&toks[i + 1]))) {
            toks.remove(i);
        }
        i += 1;
    }
    // "on 50 centres": a spacing; but "1.050 in centre bore", "a 10 mm center hole": where
    // the cut is.
    for i in 1..toks.len() {
        let placed_cut = toks[i].word().is_some_and(|w| matches!(w, "center" | "centre"))
            && toks
                .get(i + 1)
                .and_then(Token::word)
                .is_some_and(|w| matches!(super::lexicon::noun(w), Some(super::lexicon::Noun::Cut(_))));
        if matches!(toks[i - 1].kind, Tk::Num { unit: Some(_), .. })
            && !placed_cut
            && toks[i].word().is_some_and(|w| super::notation::SPACING_AFTER.contains(&w) && w != "pitch")
        {
            toks[i].kind = Tk::Word("spacing".into());
        }
    }
    // "s = 13 mm", "m = 6.8": a standard's letter for a size, read as its role's words.
    let mut i = 0;
    while i + 2 < toks.len() {
        let letter = toks[i].word().and_then(|w| super::notation::LETTERS.iter().find(|(l, _)| *l == w));
        if let Some((_, words)) = letter
            && toks[i + 1].is_sym('=')
            && matches!(toks[i + 2].kind, Tk::Num { .. })
            && !(i > 0
                && toks[i - 1].word().is_some_and(|w| w.chars().all(|c| c.is_ascii_alphabetic()) && w.len() == 1))
        {
            let (s, e) = (toks[i].start, toks[i + 1].end);
            toks.remove(i + 1);
            toks.remove(i);
            for (k, w) in words.iter().enumerate() {
                toks.insert(i + k, Token { kind: Tk::Word((*w).into()), start: s, end: e });
            }
            i += words.len();
        }
        i += 1;
    }
    // "3/8 in SAE", "M8 ISO": a nominal size named by its standard is its designation.
    for i in 0..toks.len().saturating_sub(1) {
        if matches!(toks[i].kind, Tk::Num { .. })
            && toks[i + 1].word().is_some_and(|w| super::notation::STANDARDS.contains(&w))
        {
            toks[i].kind = Tk::Word("standard".into());
            toks[i + 1].kind = Tk::Word("standard".into());
        }
    }
    // "set screw", "grub screw": a radial hole (its size the screw's thread).
    for i in 0..toks.len().saturating_sub(1) {
        if toks[i].word().is_some_and(|w| w == "set" || w == "grub") && toks[i + 1].is_word("screw") {
            toks[i].kind = Tk::Word("radial".into());
            toks[i + 1].kind = Tk::Word("hole".into());
        }
    }
    // "M6 tapped", "M5 thread through", "Hex nut M16": a thread, made as its tap drill.
    for i in 0..toks.len().saturating_sub(1) {
        if !toks[i].is_word("metric") || toks[i + 1].start != toks[i].start {
            continue;
        }
        let spelt = text.get(toks[i].start..toks[i].end).unwrap_or("").to_lowercase();
        let nominal = spelt.get(1..).and_then(|v| v.parse::<f64>().ok());
        let Some(drill) = nominal.and_then(super::notation::tap_drill) else { continue };
        let sentence_end = (i..toks.len()).find(|j| toks[*j].is_sym('.') || toks[*j].is_sym(';')).unwrap_or(toks.len());
        let sentence_start = (0..i).rev().find(|j| toks[*j].is_sym('.') || toks[*j].is_sym(';')).map_or(0, |j| j + 1);
        let near: Vec<&str> = (i + 2..(i + 5).min(toks.len())).filter_map(|j| toks[j].word()).collect();
        let clearance = near.contains(&"clearance");
        let tapped = near.iter().any(|w| super::notation::THREAD.contains(w))
            || (sentence_start..sentence_end).any(|j| {
                toks[j].word().is_some_and(|w| {
                    super::notation::THREAD.contains(&w) || (j < i && super::notation::THREADED_NOUNS.contains(&w))
                })
            });
        if tapped && !clearance {
            if let Tk::Num { pm, signed, .. } = toks[i + 1].kind {
                toks[i + 1].kind = Tk::Num { v: drill, unit: Some(1.0), pm, signed };
            }
            toks[i].kind = Tk::Word("tapped".into());
            // A nut's or standoff's thread with no hole named: its hole.
            let named = (i + 2..sentence_end).any(|j| {
                toks[j].word().is_some_and(|w| matches!(super::lexicon::noun(w), Some(super::lexicon::Noun::Cut(_))))
            });
            let threaded_noun = (sentence_start..i)
                .any(|j| toks[j].word().is_some_and(|w| super::notation::THREADED_NOUNS.contains(&w)));
            if !named && threaded_noun {
                let e = toks[i + 1].end;
                toks.insert(i + 2, Token { kind: Tk::Word("hole".into()), start: e, end: e });
            }
        }
    }
    // A hole named by its callout: a diameter (or a screw's clearance) followed, before any
    // noun or the end of its phrase, by "thru", "deep", "clearance" …, or counted "4x Ø6.6".
    let mut i = 0;
    while i < toks.len() {
        let bored = i >= 1
            && matches!(toks[i].kind, Tk::Num { unit: Some(_), .. })
            && toks[i - 1].word().is_some_and(|w| matches!(w, "bored" | "drilled"));
        let dia_after = bored
            || (matches!(toks[i].kind, Tk::Num { unit: Some(_), .. })
                && toks.get(i + 1).is_some_and(|t| t.is_word("diameter"))
                && toks.get(i + 1).is_some_and(|t| t.start == toks[i].start));
        let metric = i > 0
            && (toks[i - 1].is_word("metric") || toks[i - 1].is_word("tapped"))
            && toks[i - 1].start == toks[i].start
            && matches!(toks[i].kind, Tk::Num { unit: Some(_), .. });
        if !(dia_after || metric) {
            i += 1;
            continue;
        }
        // A counterbore's or countersink's own diameter ("c'bore Ø15 x 9 dp") is no hole.
        if i >= 1
            && toks[i - 1]
                .word()
                .is_some_and(|w| matches!(w, "counterbore" | "countersink" | "counterbored" | "countersunk"))
        {
            i += 1;
            continue;
        }
        let marked = toks.get(i + 1).is_some_and(|t| t.is_word("diameter") && t.start == toks[i].start);
        let at = if dia_after && marked { i + 2 } else { i + 1 };
        let first = if metric { i - 1 } else { i };
        let counted = (first >= 2 && toks[first - 1].is_sym('x') && matches!(toks[first - 2].kind, Tk::Num { unit: None, .. }))
            // "bored 22 mm through", "drilled 6 mm".
            || (first >= 1 && toks[first - 1].word().is_some_and(|w| matches!(w, "bored" | "drilled")));
        // Up to the end of its phrase: a callout word, and no noun naming what it is (a
        // counterbore or countersink is the hole's own).
        let mut said = counted;
        let mut named = false;
        let mut j = at;
        while let Some(t) = toks.get(j) {
            match &t.kind {
                Tk::Word(w) if super::notation::CALLOUT.contains(&w.as_str()) => said = true,
                // A body it goes through ("THRU FLANGE") is where it is, not what it is.
                Tk::Word(w)
                    if super::lexicon::noun(w).is_some_and(|k| k != super::lexicon::Noun::Pattern)
                        && !matches!(w.as_str(), "counterbore" | "countersink" | "center" | "face")
                        && !(j >= 1
                            && toks[j - 1].word().is_some_and(|p| matches!(p, "through" | "into" | "in" | "the"))
                            && matches!(super::lexicon::noun(w), Some(super::lexicon::Noun::Body(_)))) =>
                {
                    named = true;
                }
                Tk::Sym(',' | ';' | '.' | ')' | '(') => break,
                _ => {}
            }
            j += 1;
        }
        let callout = said && !named;
        if callout {
            let (s, e) = (toks[at - 1].end, toks[at - 1].end);
            toks.insert(at, Token { kind: Tk::Word("hole".into()), start: s, end: e });
        }
        i = at + 1;
    }
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
    // "legs of 50 and 20 mm", "30, 40 and 50 mm": a run of numbers ending in one with a unit.
    for i in (2..n).rev() {
        let Tk::Num { unit: Some(f), .. } = toks[i].kind else { continue };
        let mut run = Vec::new();
        let mut j = i;
        while j >= 2 && (toks[j - 1].is_word("and") || toks[j - 1].is_sym(',')) {
            match toks[j - 2].kind {
                Tk::Num { unit: None, .. } => {
                    run.push(j - 2);
                    j -= 2;
                }
                _ => break,
            }
        }
        // Not coordinates ("X = -24, -12, 0, 12, 24mm"), which are read as such.
        let coordinates = run.iter().chain([&i]).any(|k| {
            matches!(toks[*k].kind, Tk::Num { signed: true, .. })
                || (*k >= 1 && (toks[*k - 1].is_sym('=') || toks[*k - 1].is_sym('x') || toks[*k - 1].is_word("by")))
        });
        if !coordinates {
            for k in run {
                if let Tk::Num { v, unit: None, pm, signed } = toks[k].kind {
                    toks[k].kind = Tk::Num { v, unit: Some(f), pm, signed };
                }
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
