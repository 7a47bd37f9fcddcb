//! The reader's vocabulary tables: plain tab-separated files under `tables/`, one per kind
//! of word (quantities, place nouns, size words …), compiled in. Adding a word is a line
//! in a table, never a branch in the code.

/// The rows of a table: tab-separated fields, `#` comments and blank lines skipped.
pub(crate) fn rows(text: &'static str) -> impl Iterator<Item = Vec<&'static str>> {
    text.lines()
        .map(str::trim_end)
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .map(|l| l.split('\t').map(str::trim).collect())
}

pub(crate) const QUANTITIES: &str = include_str!("../tables/quantities.tsv");
pub(crate) const MULTIPLIERS: &str = include_str!("../tables/multipliers.tsv");
pub(crate) const PLACES: &str = include_str!("../tables/places.tsv");
pub(crate) const PEOPLE: &str = include_str!("../tables/people.tsv");
pub(crate) const FUNCTION_NOUNS: &str = include_str!("../tables/function_nouns.tsv");
pub(crate) const FUNCTION_WORDS: &str = include_str!("../tables/function_words.tsv");
pub(crate) const SIZE_WORDS: &str = include_str!("../tables/size_words.tsv");
pub(crate) const KIND_SIZES: &str = include_str!("../tables/kind_sizes.tsv");
pub(crate) const SET_INTO: &str = include_str!("../tables/set_into.tsv");
pub(crate) const ROOM_SENSES: &str = include_str!("../tables/room_senses.tsv");
pub(crate) const COMPOUND_MODIFIERS: &str = include_str!("../tables/compound_modifiers.tsv");
pub(crate) const PARTS: &str = include_str!("../tables/parts.tsv");
pub(crate) const MEASURES: &str = include_str!("../tables/measures.tsv");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_table_parses_with_its_columns() {
        for (name, text, cols) in [
            ("quantities", QUANTITIES, 3),
            ("multipliers", MULTIPLIERS, 2),
            ("places", PLACES, 2),
            ("people", PEOPLE, 1),
            ("function_nouns", FUNCTION_NOUNS, 1),
            ("function_words", FUNCTION_WORDS, 1),
            ("size_words", SIZE_WORDS, 3),
            ("kind_sizes", KIND_SIZES, 5),
            ("set_into", SET_INTO, 2),
            ("room_senses", ROOM_SENSES, 3),
            ("compound_modifiers", COMPOUND_MODIFIERS, 1),
            ("parts", PARTS, 1),
            ("measures", MEASURES, 1),
        ] {
            let mut n = 0;
            for r in rows(text) {
                assert_eq!(r.len(), cols, "{name}: {r:?}");
                assert!(r.iter().all(|f| !f.is_empty()), "{name}: {r:?}");
                n += 1;
            }
            assert!(n > 0, "{name} is empty");
        }
    }
}
