//! The notation of drawings, catalogues and workshop notes, as tables the tokenizer reads:
//! abbreviations and other spellings folded to the words the feature language knows
//! ("thru" → through, "c'bore" → counterbore, "thk" → thick, "PCD" → pitch circle
//! diameter, "centreline" → centerline), the symbols that stand for a length's role ("Ø20"
//! → 20 diameter, "R5" → 5 radius), and the callout grammar of a drawing note: a hole named
//! by its diameter alone ("4x Ø6.6 thru", "Ø8 x 10 deep", "M6 clearance") is a hole.
//!
//! Adding a spelling is adding a row; no stage branches on one.

/// Spellings folded to the words of the feature language (after lower-casing). A row may
/// stand for several words ("pcd").
pub const SPELLINGS: &[(&str, &[&str])] = &[
    // Holes and their callouts.
    ("thru", &["through"]),
    ("thro", &["through"]),
    ("thru-hole", &["through-hole"]),
    ("thruhole", &["through-hole"]),
    ("c'bore", &["counterbore"]),
    ("cbore", &["counterbore"]),
    ("c-bore", &["counterbore"]),
    ("counter-bore", &["counterbore"]),
    ("c'bored", &["counterbored"]),
    ("cbored", &["counterbored"]),
    ("counter-bored", &["counterbored"]),
    ("c'sink", &["countersink"]),
    ("csink", &["countersink"]),
    ("csk", &["countersink"]),
    ("c-sink", &["countersink"]),
    ("counter-sink", &["countersink"]),
    ("c'sunk", &["countersunk"]),
    ("csk'd", &["countersunk"]),
    ("counter-sunk", &["countersunk"]),
    ("spotface", &["counterbore"]),
    ("spot-face", &["counterbore"]),
    ("s'face", &["counterbore"]),
    ("drilling", &["hole"]),
    ("pcd", &["pitch", "circle", "diameter"]),
    ("bcd", &["bolt", "circle", "diameter"]),
    // Lengths and their roles.
    ("thk", &["thick"]),
    ("thck", &["thick"]),
    ("lg", &["long"]),
    ("lng", &["long"]),
    ("wd", &["wide"]),
    ("ht", &["high"]),
    ("hgt", &["high"]),
    ("dp", &["deep"]),
    ("dia", &["diameter"]),
    ("diam", &["diameter"]),
    ("rad", &["radius"]),
    ("oal", &["overall", "length"]),
    ("o/a", &["overall"]),
    ("sq", &["square"]),
    // Placement and explanation.
    ("centreline", &["centerline"]),
    ("center-line", &["centerline"]),
    ("centre-line", &["centerline"]),
    ("ctr", &["center"]),
    ("cntr", &["center"]),
    ("ea", &["each"]),
    ("typ", &["typical"]),
    ("eq", &["equally"]),
    ("equi-spaced", &["equally", "spaced"]),
    ("equispaced", &["equally", "spaced"]),
    ("eq-spaced", &["equally", "spaced"]),
    ("nom", &["nominal"]),
    ("sp", &["spaced"]),
    ("chamf", &["chamfer"]),
    ("chmf", &["chamfer"]),
    ("rnd", &["round"]),
    ("aluminium", &["aluminum"]),
    // Shop-floor shorthand.
    ("plt", &["plate"]),
    ("blk", &["block"]),
    ("rd", &["round"]),
    ("pkt", &["pocket"]),
    ("cnr", &["corner"]),
    ("cnrs", &["corner"]),
    ("crnr", &["corner"]),
    ("crnrs", &["corner"]),
    ("chfr", &["chamfer"]),
    ("chfrd", &["chamfered"]),
    ("kw", &["keyway"]),
    ("k/w", &["keyway"]),
    ("x-hole", &["cross", "hole"]),
    ("x-holes", &["cross", "hole"]),
    ("crosshole", &["cross", "hole"]),
    ("clr", &["clearance"]),
    ("clrnc", &["clearance"]),
    ("a/f", &["across", "flat"]),
    ("af", &["across", "flat"]),
    ("a/c", &["across", "corner"]),
    ("c/l", &["centerline"]),
    ("cl", &["centerline"]),
    ("c/c", &["spacing"]),
    ("o/a", &["overall"]),
    ("w/", &["with"]),
    ("o/d", &["od"]),
    ("i/d", &["id"]),
    ("dowel-hole", &["hole"]),
    ("set-screw", &["radial", "hole"]),
    // Contractions: the copula is read ("that's a ring": the ring is the washer).
    ("that's", &["that", "is"]),
    ("it's", &["it", "is"]),
    ("what's", &["what", "is"]),
    ("there's", &["there", "is"]),
    ("here's", &["here", "is"]),
    ("female-female", &["female"]),
    ("male-female", &["female"]),
    ("l-angle", &["angle"]),
    ("unequal-angle", &["angle"]),
    ("equal-angle", &["angle"]),
    ("angle-iron", &["angle"]),
    ("setscrew", &["radial", "hole"]),
    ("grub-screw", &["radial", "hole"]),
    // Named part families written as other families' words ("top hat bush" is a flanged
    // bush; "L bracket" and "U channel" are joined as hyphenated nouns by the tokenizer).
    ("top-hat", &["flanged"]),
    ("tophat", &["flanged"]),
];

/// Names of standards and the number after them ("ISO 7089", "DIN 912", "NEMA 17"): a
/// designation, read as no geometry (the sizes given with it are).
pub const STANDARDS: &[&str] = &["iso", "din", "en", "nema", "sae", "ansi", "bs", "asme", "jis", "astm", "uns"];

/// Nouns after a number that make it a length, not a count ("3.2 wall", "2 mm floor").
pub const LENGTH_NOUNS: &[&str] = &["wall", "walls", "floor", "face", "web"];

/// Words after a number that make it a length when it has no unit ("120 across").
pub const LENGTH_AFTER: &[&str] = &[
    "across",
    "outside",
    "inside",
    "square",
    "sq",
    "swg",
    "gauge",
    "by",
    "way",
    "overall",
    "total",
    "projecting",
    "proud",
    "each",
];

/// Words that, right after a length, say it is a spacing ("on 50 mm centres").
pub const SPACING_AFTER: &[&str] = &["centres", "centers", "ctrs", "crs", "ctr", "centre", "center", "pitch"];

/// Words after a number that, when it has no unit, mean inches ("2 in. long", "1.5 in x 3 in").
pub const INCH_WORDS: &[&str] = &["in", "ins"];

/// Standard wire gauge (SWG) to inches: a tube's wall "16 SWG".
pub fn swg_inch(g: f64) -> Option<f64> {
    const TABLE: &[(f64, f64)] = &[
        (8.0, 0.160),
        (10.0, 0.128),
        (11.0, 0.116),
        (12.0, 0.104),
        (13.0, 0.092),
        (14.0, 0.080),
        (16.0, 0.064),
        (18.0, 0.048),
        (20.0, 0.036),
        (22.0, 0.028),
        (24.0, 0.022),
    ];
    TABLE.iter().find(|(n, _)| (n - g).abs() < 1e-9).map(|(_, v)| *v)
}

/// ISO coarse tap drill of a metric thread (nominal less pitch): a tapped hole is modelled
/// as a plain hole of this size, as CAD hole tools model cosmetic threads.
pub fn tap_drill(size: f64) -> Option<f64> {
    const TABLE: &[(f64, f64)] = &[
        (2.0, 1.6),
        (2.5, 2.05),
        (3.0, 2.5),
        (4.0, 3.3),
        (5.0, 4.2),
        (6.0, 5.0),
        (8.0, 6.8),
        (10.0, 8.5),
        (12.0, 10.2),
        (14.0, 12.0),
        (16.0, 14.0),
        (20.0, 17.5),
        (24.0, 21.0),
    ];
    TABLE.iter().find(|(s, _)| (s - size).abs() < 1e-9).map(|(_, d)| *d)
}

/// Words that make a metric size a thread ("M6 tapped", "M5 thread through", "M3 female").
pub const THREAD: &[&str] = &["tapped", "tap", "thread", "threaded", "female", "set", "setscrew", "grub", "radial"];

/// Nouns whose metric size is their thread ("Hex nut M16").
pub const THREADED_NOUNS: &[&str] = &["nut", "standoff", "insert", "coupler"];

/// Letters standards give sizes by ("Hex nut ISO 4032 M8, s = 13 mm, m = 6.8 mm"): the
/// words of their roles (x, y, z and r are coordinates).
pub const LETTERS: &[(&str, &[&str])] = &[
    ("s", &["across", "flat"]),
    ("e", &["across", "corner"]),
    ("m", &["height"]),
    ("k", &["height"]),
    ("h", &["height"]),
    ("t", &["thickness"]),
    ("l", &["length"]),
    ("b", &["width"]),
    ("d", &["diameter"]),
];

/// The words a spelling stands for, if it is one.
pub fn spelling(w: &str) -> Option<&'static [&'static str]> {
    SPELLINGS.iter().find(|(s, _)| *s == w).map(|(_, to)| *to)
}

/// Symbols written before a number that give its role: "Ø20", "⌀ 20", "R5".
pub fn role_symbol(c: char) -> Option<&'static str> {
    match c {
        'Ø' | 'ø' | '⌀' | '∅' => Some("diameter"),
        _ => None,
    }
}

/// Letters written fused to a number that give its role ("R5" a radius).
/// "C2" a 2 x 45° chamfer (ISO 13715 / drawing practice).
pub fn role_prefix(w: &str) -> Option<(&'static str, f64)> {
    if let Some(v) = w.strip_prefix('c').and_then(|v| v.parse::<f64>().ok()) {
        return Some(("chamfer", v));
    }
    let v = w.strip_prefix('r')?.parse::<f64>().ok()?;
    Some(("radius", v))
}

/// Words after a hole's diameter in a callout that make it a hole when no noun says so
/// ("4x Ø6.6 thru", "Ø5 x 8 deep", "M4 clearance").
pub const CALLOUT: &[&str] = &[
    "through",
    "deep",
    "clearance",
    "blind",
    "drilled",
    "drill",
    "counterbore",
    "countersink",
    "tapped",
    "thread",
    "threaded",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings_fold_to_known_words() {
        // Every word a spelling stands for is one the language reads (a noun, a role, a
        // qualifier or a filler), so a spelling never brings in an unknown word.
        for (from, to) in SPELLINGS {
            for w in *to {
                let known = super::super::lexicon::noun(w).is_some()
                    || super::super::doc::role_of(w).is_some()
                    || super::super::doc::QUALS.contains(w)
                    || super::super::lexicon::is_filler(w)
                    || super::super::lexicon::shape_adjective(w).is_some()
                    || matches!(
                        *w,
                        "counterbored" | "countersunk" | "through" | "typical" | "hex" | "centerline" | "flanged"
                    );
                assert!(known, "{from} → {w}: not a word of the feature language");
            }
        }
    }
}
