//! Quantities before a noun: numerals in digits and words ("12", "twenty-five", "two
//! hundred"), quantity phrases from `tables/quantities.tsv` ("a dozen", "half a dozen", "a
//! pair of", "several"), multipliers ("two dozen", "three pairs of"), and additions ("three
//! more", "another").

use std::sync::OnceLock;

use crate::tables::{MULTIPLIERS, QUANTITIES, rows};
use crate::text::{Token, TokenKind, number_word};

/// A quantity read before a noun.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Quantity {
    pub value: f64,
    /// Tokens it spans.
    pub len: usize,
    /// False for "several", "a few": a guess at what the user did not count.
    pub exact: bool,
    /// "three more", "another": added to a group of the same kind named before.
    pub more: bool,
}

#[derive(Debug)]
struct Phrase {
    words: Vec<&'static str>,
    value: f64,
    exact: bool,
    /// "a set of": the count is the number after it, if any.
    set: bool,
}

fn phrases() -> &'static [Phrase] {
    static P: OnceLock<Vec<Phrase>> = OnceLock::new();
    P.get_or_init(|| {
        let mut v: Vec<Phrase> = rows(QUANTITIES)
            .map(|r| Phrase {
                words: r[0].split(' ').collect(),
                value: r[1].parse().unwrap_or(1.0),
                exact: r[2] != "approx",
                set: r[2] == "set",
            })
            .collect();
        v.sort_by_key(|p| std::cmp::Reverse(p.words.len()));
        v
    })
}

fn multipliers() -> &'static [(Vec<&'static str>, f64)] {
    static M: OnceLock<Vec<(Vec<&'static str>, f64)>> = OnceLock::new();
    M.get_or_init(|| {
        let mut v: Vec<(Vec<&'static str>, f64)> =
            rows(MULTIPLIERS).map(|r| (r[0].split(' ').collect(), r[1].parse().unwrap_or(1.0))).collect();
        v.sort_by_key(|(w, _)| std::cmp::Reverse(w.len()));
        v
    })
}

fn word(toks: &[Token], i: usize) -> &str {
    toks.get(i).filter(|t| t.kind == TokenKind::Word).map_or("", |t| t.norm.as_str())
}

fn starts(toks: &[Token], i: usize, words: &[&str]) -> bool {
    words.iter().enumerate().all(|(k, w)| word(toks, i + k) == *w)
}

/// A numeral at `i`: digits, or number words ("twenty five", "twenty-five", "two hundred
/// and fifty", "a hundred"). Returns the value and the tokens it spans.
pub(crate) fn numeral_at(toks: &[Token], i: usize) -> Option<(f64, usize)> {
    if let Some(n) = toks.get(i).and_then(Token::number) {
        return Some((n, 1));
    }
    let w = word(toks, i);
    // "no" and "single" are quantities of their own, read by the table; "pair", "couple",
    // "dozen" there too.
    if matches!(w, "no" | "single" | "pair" | "couple" | "both" | "twin" | "dozen") {
        return None;
    }
    let mut value = number_word(w)?;
    let mut j = i + 1;
    loop {
        let next = word(toks, j);
        let skip_and = next == "and" && number_word(word(toks, j + 1)).is_some_and(|v| v < 100.0) && value >= 100.0;
        let k = if skip_and { j + 1 } else { j };
        match number_word(word(toks, k)) {
            Some(100.0) if value < 100.0 && !matches!(word(toks, k), "dozen") => {
                value *= 100.0;
                j = k + 1;
            }
            Some(u) if u < 10.0 && value >= 20.0 && value % 10.0 == 0.0 && value < 100.0 => {
                value += u;
                j = k + 1;
            }
            Some(u) if u < 100.0 && value >= 100.0 && value % 100.0 == 0.0 && !matches!(word(toks, k), "dozen") => {
                value += u;
                j = k + 1;
            }
            _ => break,
        }
    }
    Some((value, j - i))
}

/// The quantity before a noun at `i`, if any.
pub(crate) fn quantity_at(toks: &[Token], i: usize) -> Option<Quantity> {
    // "too armchairs": a typo of "two" before a plural.
    if word(toks, i) == "too" && word(toks, i + 1).ends_with('s') && word(toks, i + 1).len() > 3 {
        return Some(Quantity { value: 2.0, len: 1, exact: true, more: false });
    }
    // "another", "one more", "3 more".
    if word(toks, i) == "another" {
        return Some(Quantity { value: 1.0, len: 1, exact: true, more: true });
    }
    // Longest table phrase; "a dozen" before "a".
    let mut q = None;
    for p in phrases() {
        if starts(toks, i, &p.words) {
            let mut value = p.value;
            let mut len = p.words.len();
            let mut exact = p.exact;
            if p.set {
                // "a set of four chairs": the number after; "a set of chairs": a few.
                match numeral_at(toks, i + len) {
                    Some((n, l)) => {
                        value = n;
                        len += l;
                    }
                    None => {
                        value = 4.0;
                        exact = false;
                    }
                }
            }
            q = Some(Quantity { value, len, exact, more: false });
            break;
        }
    }
    if q.is_none()
        && let Some((value, len)) = numeral_at(toks, i)
    {
        q = Some(Quantity { value, len, exact: true, more: false });
    }
    let mut q = q?;
    // "two dozen", "three pairs of".
    let j = i + q.len;
    for (words, factor) in multipliers() {
        if starts(toks, j, words) && q.exact && q.value >= 1.0 && !(q.len == 1 && matches!(word(toks, i), "a" | "an")) {
            q.value *= factor;
            q.len += words.len();
            break;
        }
    }
    // "four of", not "four of the" (a part of a group named before).
    let j = i + q.len;
    if word(toks, j) == "of" && !matches!(word(toks, j + 1), "the" | "them" | "these" | "those" | "which" | "its") {
        q.len += 1;
    }
    let j = i + q.len;
    if matches!(word(toks, j), "more" | "other" | "additional" | "extra") && !matches!(word(toks, i), "a" | "an") {
        q.more = true;
        q.len += 1;
    }
    // "a pair of scissors", "two pairs of pliers": a pair of a thing named only in the
    // plural is one thing, not two.
    let paired = (i..i + q.len).any(|k| matches!(word(toks, k), "pair" | "pairs"));
    if paired && (0..3).map(|k| word(toks, i + q.len + k)).take_while(|w| !is_joint(w)).any(is_pair_noun) {
        q.value /= 2.0;
    }
    Some(q)
}

/// Words that end the noun phrase after a quantity ("a pair of pliers and …").
fn is_joint(w: &str) -> bool {
    w.is_empty() || matches!(w, "and" | "or" | "with" | "on" | "in" | "at" | "by" | "of" | "next" | "beside")
}

/// Nouns used only in the plural for one thing made of two halves.
fn is_pair_noun(w: &str) -> bool {
    matches!(
        w,
        "scissors"
            | "pliers"
            | "tongs"
            | "tweezers"
            | "shears"
            | "clippers"
            | "snips"
            | "cutters"
            | "pincers"
            | "secateurs"
            | "glasses"
            | "spectacles"
            | "goggles"
            | "binoculars"
            | "headphones"
            | "earphones"
            | "trousers"
            | "pants"
            | "jeans"
            | "shorts"
            | "tights"
            | "leggings"
            | "pyjamas"
            | "pajamas"
            | "overalls"
            | "dungarees"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::tokenize;

    fn q(s: &str) -> Option<(f64, usize, bool, bool)> {
        quantity_at(&tokenize(s), 0).map(|q| (q.value, q.len, q.exact, q.more))
    }

    #[test]
    fn numerals_in_digits_and_words() {
        assert_eq!(q("12 mugs"), Some((12.0, 1, true, false)));
        assert_eq!(q("twelve mugs"), Some((12.0, 1, true, false)));
        assert_eq!(q("twenty-five mugs"), Some((25.0, 1, true, false)));
        assert_eq!(q("twenty five mugs"), Some((25.0, 2, true, false)));
        assert_eq!(q("two hundred mugs"), Some((200.0, 2, true, false)));
        assert_eq!(q("two hundred and fifty mugs"), Some((250.0, 4, true, false)));
        assert_eq!(q("a hundred mugs"), Some((100.0, 2, true, false)));
    }

    #[test]
    fn quantity_phrases_and_multipliers() {
        assert_eq!(q("a dozen mugs"), Some((12.0, 2, true, false)));
        assert_eq!(q("half a dozen mugs"), Some((6.0, 3, true, false)));
        assert_eq!(q("two dozen mugs"), Some((24.0, 2, true, false)));
        assert_eq!(q("a pair of mugs"), Some((2.0, 3, true, false)));
        assert_eq!(q("three pairs of gloves"), Some((6.0, 3, true, false)));
        // A pair of a thing named only in the plural is one thing.
        assert_eq!(q("a pair of scissors"), Some((1.0, 3, true, false)));
        assert_eq!(q("a pair of sharp pliers"), Some((1.0, 3, true, false)));
        assert_eq!(q("two pairs of safety goggles"), Some((2.0, 3, true, false)));
        assert_eq!(q("3 pairs of Tongs"), Some((3.0, 3, true, false)));
        assert_eq!(q("a pair of mugs and scissors"), Some((2.0, 3, true, false)));
        assert_eq!(q("a couple of mugs"), Some((2.0, 3, true, false)));
        assert_eq!(q("a few mugs").map(|x| (x.0, x.2)), Some((3.0, false)));
        assert_eq!(q("several mugs").map(|x| (x.0, x.2)), Some((4.0, false)));
        assert_eq!(q("a handful of mugs").map(|x| (x.0, x.1)), Some((5.0, 3)));
        assert_eq!(q("a set of four chairs"), Some((4.0, 4, true, false)));
        assert_eq!(q("a mug"), Some((1.0, 1, true, false)));
        assert_eq!(q("four of mugs").map(|x| x.1), Some(2));
        assert_eq!(q("four of the mugs").map(|x| x.1), Some(1));
    }

    #[test]
    fn additions() {
        assert_eq!(q("another mug"), Some((1.0, 1, true, true)));
        assert_eq!(q("three more mugs"), Some((3.0, 2, true, true)));
        assert_eq!(q("2 more mugs"), Some((2.0, 2, true, true)));
        assert_eq!(q("one more mug"), Some((1.0, 2, true, true)));
        assert_eq!(q("two other mugs"), Some((2.0, 2, true, true)));
        assert_eq!(q("mugs"), None);
    }
}
