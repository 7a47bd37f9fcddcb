//! Tokens, numbers and plurals: the lowest layer of the offline planner.

/// What a token is.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum TokenKind {
    /// A lowercase word (letters, digits inside words, apostrophes, inner hyphens).
    Word,
    /// A number written in digits (may be negative or fractional).
    Number(f64),
    /// `x` or `×` between dimensions.
    Times,
    /// `,` — separates items of a list.
    Comma,
    /// `.`, `;`, `!`, `?`, `:` or a newline — ends a sentence.
    Stop,
    /// Anything else (symbols, emoji, punctuation we do not use).
    Other,
}

#[derive(Debug, Clone)]
pub(crate) struct Token {
    pub kind: TokenKind,
    /// Lowercase text.
    pub norm: String,
    /// Byte range in the (cleaned) prompt.
    pub start: usize,
    pub end: usize,
}

impl Token {
    pub fn is_word(&self, w: &str) -> bool {
        self.kind == TokenKind::Word && self.norm == w
    }

    pub fn number(&self) -> Option<f64> {
        match self.kind {
            TokenKind::Number(n) => Some(n),
            _ => None,
        }
    }
}

/// Splits a prompt into tokens. Digits glued to units ("2m", "10x6") are split so that
/// "2m x 2m" and "2 m by 2 m" read the same.
pub(crate) fn tokenize(text: &str) -> Vec<Token> {
    let mut out = Vec::new();
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let end_of = |i: usize| chars.get(i).map_or(text.len(), |(b, _)| *b);
    let mut i = 0;
    while i < chars.len() {
        let (start, c) = chars[i];
        if c.is_whitespace() {
            if c == '\n' {
                out.push(Token { kind: TokenKind::Stop, norm: "\n".into(), start, end: end_of(i + 1) });
            }
            i += 1;
            continue;
        }
        let next_is_digit = chars.get(i + 1).is_some_and(|(_, d)| d.is_ascii_digit());
        if c.is_ascii_digit() || ((c == '-' || c == '.') && next_is_digit && !prev_is_alnum(&chars, i)) {
            let mut j = i + 1;
            let mut seen_dot = c == '.';
            while j < chars.len() {
                let d = chars[j].1;
                if d.is_ascii_digit() {
                    j += 1;
                } else if d == '.' && !seen_dot && chars.get(j + 1).is_some_and(|(_, e)| e.is_ascii_digit()) {
                    seen_dot = true;
                    j += 1;
                } else if d == ','
                    && chars.get(j + 1).is_some_and(|(_, e)| e.is_ascii_digit())
                    && chars.get(j + 2).is_some_and(|(_, e)| e.is_ascii_digit())
                    && chars.get(j + 3).is_some_and(|(_, e)| e.is_ascii_digit())
                    && !chars.get(j + 4).is_some_and(|(_, e)| e.is_ascii_digit())
                {
                    // Thousands separator: "1,000".
                    j += 1;
                } else {
                    break;
                }
            }
            // Scientific notation: "1e9", "2.5E-3".
            if chars.get(j).is_some_and(|(_, e)| *e == 'e' || *e == 'E') {
                let mut k = j + 1;
                if chars.get(k).is_some_and(|(_, c)| *c == '-' || *c == '+') {
                    k += 1;
                }
                if chars.get(k).is_some_and(|(_, c)| c.is_ascii_digit()) {
                    while chars.get(k).is_some_and(|(_, c)| c.is_ascii_digit()) {
                        k += 1;
                    }
                    if !chars.get(k).is_some_and(|(_, c)| c.is_alphabetic()) {
                        j = k;
                    }
                }
            }
            // Digits glued to letters that are not a unit are one word: "3d", "4k", "2nd".
            let mut k = j;
            while chars.get(k).is_some_and(|(_, c)| c.is_alphanumeric()) {
                k += 1;
            }
            // "6x2m", "4x3.5": a number, a times sign, and the rest read on.
            if chars.get(j).is_some_and(|(_, c)| *c == 'x' || *c == 'X')
                && chars.get(j + 1).is_some_and(|(_, c)| c.is_ascii_digit())
                && chars[i].1.is_ascii_digit()
            {
                let raw: String = chars[i..j].iter().map(|(_, ch)| *ch).filter(|ch| *ch != ',').collect();
                out.push(Token {
                    kind: TokenKind::Number(raw.parse::<f64>().unwrap_or(f64::NAN)),
                    norm: raw,
                    start,
                    end: end_of(j),
                });
                out.push(Token { kind: TokenKind::Times, norm: "x".into(), start: end_of(j), end: end_of(j + 1) });
                i = j + 1;
                continue;
            }
            if k > j {
                let suffix: String = chars[j..k].iter().map(|(_, c)| c.to_ascii_lowercase()).collect();
                let unit = matches!(suffix.as_str(), "m" | "cm" | "mm" | "km" | "ft" | "in" | "m2" | "sqm" | "x")
                    || suffix.starts_with('x') && suffix[1..].chars().all(|c| c.is_ascii_digit())
                    || ["meter", "meters", "metre", "metres", "feet", "foot", "inch", "inches"]
                        .contains(&suffix.as_str());
                if !unit && chars[i].1.is_ascii_digit() {
                    let word: String = chars[i..k].iter().map(|(_, c)| *c).collect::<String>().to_lowercase();
                    out.push(Token { kind: TokenKind::Word, norm: word, start, end: end_of(k) });
                    i = k;
                    continue;
                }
            }
            let raw: String = chars[i..j].iter().map(|(_, ch)| *ch).filter(|ch| *ch != ',').collect();
            let value = raw.parse::<f64>().unwrap_or(f64::NAN);
            out.push(Token { kind: TokenKind::Number(value), norm: raw, start, end: end_of(j) });
            i = j;
            continue;
        }
        if c.is_alphabetic() {
            let mut j = i + 1;
            while j < chars.len() {
                let d = chars[j].1;
                let inner =
                    (d == '\'' || d == '’' || d == '-') && chars.get(j + 1).is_some_and(|(_, e)| e.is_alphabetic());
                if d.is_alphanumeric() || inner {
                    j += 1;
                } else {
                    break;
                }
            }
            let word: String =
                chars[i..j].iter().map(|(_, ch)| *ch).collect::<String>().to_lowercase().replace('’', "'");
            // "x" between numbers is a times sign: "10x6", "12 x 12".
            if word == "x" {
                out.push(Token { kind: TokenKind::Times, norm: "x".into(), start, end: end_of(j) });
            } else if let Some(rest) =
                word.strip_prefix('x').filter(|r| r.chars().all(|d| d.is_ascii_digit()) && !r.is_empty())
            {
                out.push(Token { kind: TokenKind::Times, norm: "x".into(), start, end: start + 1 });
                out.push(Token {
                    kind: TokenKind::Number(rest.parse().unwrap_or(f64::NAN)),
                    norm: rest.into(),
                    start: start + 1,
                    end: end_of(j),
                });
            } else {
                out.push(Token { kind: TokenKind::Word, norm: word, start, end: end_of(j) });
            }
            i = j;
            continue;
        }
        // "w/ a fridge": with.
        if c == '/'
            && let Some(last) = out.last_mut()
            && last.kind == TokenKind::Word
            && last.norm == "w"
            && last.end == start
        {
            last.norm = "with".into();
            last.end = end_of(i + 1);
            i += 1;
            continue;
        }
        let kind = match c {
            '×' | '*' => TokenKind::Times,
            ',' => TokenKind::Comma,
            '.' | ';' | '!' | '?' | ':' => TokenKind::Stop,
            _ => TokenKind::Other,
        };
        out.push(Token { kind, norm: c.to_string(), start, end: end_of(i + 1) });
        i += 1;
    }
    out
}

fn prev_is_alnum(chars: &[(usize, char)], i: usize) -> bool {
    i > 0 && chars[i - 1].1.is_alphanumeric()
}

/// Number words: "one" … "twenty", tens, "hundred", "dozen", and compounds like
/// "twenty-five" or "two hundred".
pub(crate) fn number_word(w: &str) -> Option<f64> {
    let simple = |w: &str| -> Option<f64> {
        Some(match w {
            "zero" | "no" => 0.0,
            "one" | "single" => 1.0,
            "two" | "pair" | "couple" | "twin" | "both" => 2.0,
            "three" => 3.0,
            "four" => 4.0,
            "five" => 5.0,
            "six" => 6.0,
            "seven" => 7.0,
            "eight" => 8.0,
            "nine" => 9.0,
            "ten" => 10.0,
            "eleven" => 11.0,
            "twelve" | "dozen" => 12.0,
            "thirteen" => 13.0,
            "fourteen" => 14.0,
            "fifteen" => 15.0,
            "sixteen" => 16.0,
            "seventeen" => 17.0,
            "eighteen" => 18.0,
            "nineteen" => 19.0,
            "twenty" => 20.0,
            "thirty" => 30.0,
            "forty" => 40.0,
            "fifty" => 50.0,
            "sixty" => 60.0,
            "seventy" => 70.0,
            "eighty" => 80.0,
            "ninety" => 90.0,
            "hundred" => 100.0,
            _ => return None,
        })
    };
    if let Some(v) = simple(w) {
        return Some(v);
    }
    // "twenty-five"
    let (a, b) = w.split_once('-')?;
    match (simple(a), simple(b)) {
        (Some(t), Some(u)) if t >= 20.0 && u < 10.0 => Some(t + u),
        _ => None,
    }
}

/// Irregular and regular English plurals to singular, for nouns of workspaces.
pub(crate) fn singular(word: &str) -> String {
    const IRREGULAR: &[(&str, &str)] = &[
        ("shelves", "shelf"),
        ("knives", "knife"),
        ("leaves", "leaf"),
        ("people", "person"),
        ("men", "man"),
        ("women", "woman"),
        ("feet", "foot"),
        ("mice", "mouse"),
        ("children", "child"),
        ("boxes", "box"),
        ("benches", "bench"),
        ("couches", "couch"),
        ("glasses", "glass"),
        ("dishes", "dish"),
        ("brushes", "brush"),
        ("switches", "switch"),
        ("torches", "torch"),
        ("wrenches", "wrench"),
        ("lathes", "lathe"),
        ("cases", "case"),
        ("bases", "base"),
        ("vases", "vase"),
        ("buses", "bus"),
        ("lenses", "lens"),
        ("presses", "press"),
        ("series", "series"),
        ("chassis", "chassis"),
        ("species", "species"),
        ("tires", "tire"),
        ("tyres", "tyre"),
        ("tubes", "tube"),
        ("cubes", "cube"),
        ("plates", "plate"),
        ("crates", "crate"),
        ("pipes", "pipe"),
        ("drives", "drive"),
    ];
    if let Some((_, s)) = IRREGULAR.iter().find(|(p, _)| *p == word) {
        return (*s).to_string();
    }
    // "UR5e's", "PC's": a plural written with an apostrophe.
    if let Some(stem) = word.strip_suffix("'s").filter(|s| s.len() >= 2) {
        return stem.to_string();
    }
    // "bookshelves", "wall shelves".
    if let Some(stem) = word.strip_suffix("shelves") {
        return format!("{stem}shelf");
    }
    let keep = ["glass", "gas", "bus", "lens", "chassis", "series", "ss", "us", "is", "news"];
    if keep.contains(&word) || word.ends_with("ss") || word.len() <= 3 {
        return word.to_string();
    }
    if let Some(stem) = word.strip_suffix("ies")
        && stem.len() >= 2
    {
        return format!("{stem}y");
    }
    for suffix in ["ches", "shes", "xes", "sses", "zzes"] {
        if let Some(stem) = word.strip_suffix(suffix) {
            return format!("{stem}{}", &suffix[..suffix.len() - 2]);
        }
    }
    if let Some(stem) = word.strip_suffix('s')
        && !stem.ends_with('s')
        && !stem.ends_with('u')
    {
        return stem.to_string();
    }
    word.to_string()
}

/// Levenshtein distance, for typo-tolerant matching of nouns.
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for i in 1..=a.len() {
        cur[0] = i;
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

/// Edit distance counting a swap of two neighbouring letters as one edit ("tabel" is one
/// edit from "table"): the optimal string alignment distance, for typos.
pub(crate) fn typo_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let (n, m) = (a.len(), b.len());
    let mut d = vec![vec![0usize; m + 1]; n + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=n {
        for j in 1..=m {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut v = (d[i - 1][j] + 1).min(d[i][j - 1] + 1).min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                v = v.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = v;
        }
    }
    d[n][m]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(s: &str) -> Vec<String> {
        tokenize(s)
            .iter()
            .map(|t| match t.kind {
                TokenKind::Number(n) => format!("#{n}"),
                TokenKind::Times => "x".into(),
                TokenKind::Word => t.norm.clone(),
                TokenKind::Comma => ",".into(),
                TokenKind::Stop => ".".into(),
                TokenKind::Other => "?".into(),
            })
            .collect()
    }

    #[test]
    fn dimensions_split_into_numbers_units_and_times() {
        assert_eq!(kinds("2m x 2m"), ["#2", "m", "x", "#2", "m"]);
        assert_eq!(kinds("12x12 m"), ["#12", "x", "#12", "m"]);
        assert_eq!(kinds("6x2m"), ["#6", "x", "#2", "m"]);
        assert_eq!(kinds("4x3.5 m"), ["#4", "x", "#3.5", "m"]);
        assert_eq!(kinds("10 by 6 meter room"), ["#10", "by", "#6", "meter", "room"]);
        assert_eq!(kinds("3.5m×4.25m"), ["#3.5", "m", "x", "#4.25", "m"]);
        assert_eq!(kinds("a -5 by 3"), ["a", "#-5", "by", "#3"]);
        assert_eq!(kinds("1,000 boxes, 20 crates."), ["#1000", "boxes", ",", "#20", "crates", "."]);
        assert_eq!(kinds("UR5e's arm"), ["ur5e's", "arm"]);
        assert_eq!(kinds("a 3D printer, 2m"), ["a", "3d", "printer", ",", "#2", "m"]);
    }

    #[test]
    fn number_words_and_plurals() {
        assert_eq!(number_word("twelve"), Some(12.0));
        assert_eq!(number_word("twenty-five"), Some(25.0));
        assert_eq!(number_word("five-twenty"), None);
        assert_eq!(singular("shelves"), "shelf");
        assert_eq!(singular("boxes"), "box");
        assert_eq!(singular("batteries"), "battery");
        assert_eq!(singular("pallets"), "pallet");
        assert_eq!(singular("gas"), "gas");
        assert_eq!(singular("glasses"), "glass");
        assert_eq!(singular("turtlebots"), "turtlebot");
        assert_eq!(edit_distance("conveyer", "conveyor"), 1);
        assert_eq!(typo_distance("tabel", "table"), 1);
        assert_eq!(typo_distance("chiar", "chair"), 1);
        assert_eq!(typo_distance("broom", "room"), 1);
    }
}
