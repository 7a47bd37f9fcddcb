//! The words of edit commands: tokens, numbers and units, spatial words, ordinals,
//! colours, directions and shifts, rotations and size changes.

use sw_plan::{Corner, Wall};
use sw_planner::vocab;

use crate::ast::{Placement, Resize, Spatial};

pub(crate) fn tokens(s: &str) -> Vec<String> {
    let mut spaced = String::with_capacity(s.len() + 16);
    let chars: Vec<char> = s.to_lowercase().chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        match c {
            '°' => spaced.push_str(" degrees "),
            '%' => spaced.push_str(" percent "),
            ',' | ';' | ':' | '!' | '?' | '"' | '(' | ')' => {
                spaced.push(' ');
                spaced.push(c);
                spaced.push(' ');
            }
            '.' => {
                let digit_before = i > 0 && chars[i - 1].is_ascii_digit();
                let digit_after = chars.get(i + 1).is_some_and(|c| c.is_ascii_digit());
                spaced.push(if digit_before && digit_after { '.' } else { ' ' });
            }
            '-' | '\'' | '’' => spaced.push(' '),
            c if c.is_control() => spaced.push(' '),
            c => {
                // "1m", "50cm", "90deg": a number glued to a unit.
                if c.is_alphabetic() && i > 0 && chars[i - 1].is_ascii_digit() {
                    let start = spaced.rfind(|ch: char| !(ch.is_ascii_digit() || ch == '.')).map_or(0, |p| p + 1);
                    let word_start = spaced[..start].ends_with('_');
                    if !word_start {
                        spaced.push(' ');
                    }
                }
                spaced.push(c);
            }
        }
    }
    spaced.split_whitespace().map(str::to_string).collect()
}

/// A number in an edit: digits, "a"/"an" (one), "half", or one of the planner's number
/// words — except "no", which in a command is a refusal, not a count.
pub(crate) fn number(w: &str) -> Option<f64> {
    if let Ok(v) = w.parse::<f64>() {
        return v.is_finite().then_some(v);
    }
    match w {
        "a" | "an" => Some(1.0),
        "half" => Some(0.5),
        "no" => None,
        _ => vocab::number_word(w),
    }
}

pub(crate) fn unit(w: &str) -> Option<f64> {
    Some(match w {
        "m" | "meter" | "meters" | "metre" | "metres" => 1.0,
        "cm" | "centimeter" | "centimeters" | "centimetre" | "centimetres" => 0.01,
        "mm" | "millimeter" | "millimeters" | "millimetre" | "millimetres" => 0.001,
        "ft" | "foot" | "feet" => 0.3048,
        "in" | "inch" | "inches" => 0.0254,
        _ => return None,
    })
}

/// Relation words that start an anchor ("the chair NEXT TO the table"), longest first.
pub(crate) const ANCHORS: &[(&[&str], Spatial)] = &[
    (&["to", "the", "left", "of"], Spatial::LeftOf),
    (&["to", "the", "right", "of"], Spatial::RightOf),
    (&["on", "the", "left", "of"], Spatial::LeftOf),
    (&["on", "the", "right", "of"], Spatial::RightOf),
    (&["in", "front", "of"], Spatial::InFrontOf),
    (&["on", "top", "of"], Spatial::On),
    (&["left", "of"], Spatial::LeftOf),
    (&["right", "of"], Spatial::RightOf),
    (&["next", "to"], Spatial::NextTo),
    (&["close", "to"], Spatial::NextTo),
    (&["nearest", "to"], Spatial::Nearest),
    (&["closest", "to"], Spatial::Nearest),
    (&["farthest", "from"], Spatial::Farthest),
    (&["furthest", "from"], Spatial::Farthest),
    (&["beside"], Spatial::NextTo),
    (&["near"], Spatial::NextTo),
    (&["by"], Spatial::NextTo),
    (&["behind"], Spatial::Behind),
    (&["onto"], Spatial::On),
    (&["on"], Spatial::On),
    (&["under"], Spatial::Under),
    (&["below"], Spatial::Under),
    (&["beneath"], Spatial::Under),
    (&["underneath"], Spatial::Under),
    (&["nearest"], Spatial::Nearest),
    (&["closest"], Spatial::Nearest),
];

pub(crate) fn starts_with(t: &[String], words: &[&str]) -> bool {
    t.len() >= words.len() && t.iter().zip(words).all(|(a, b)| a == b)
}

pub(crate) fn anchor_at(t: &[String], i: usize) -> Option<(Spatial, usize)> {
    ANCHORS.iter().find(|(w, _)| starts_with(&t[i..], w)).map(|(w, s)| (*s, w.len()))
}

pub(crate) const ORDINALS: &[(&str, u32)] = &[
    ("first", 1),
    ("second", 2),
    ("third", 3),
    ("fourth", 4),
    ("fifth", 5),
    ("sixth", 6),
    ("seventh", 7),
    ("eighth", 8),
    ("ninth", 9),
    ("tenth", 10),
    ("last", 0),
];

/// Words that modify a colour ("dark blue").
pub(crate) const SHADES: &[&str] = &["dark", "light", "pale", "bright", "deep", "vivid", "matte", "glossy"];

/// A colour written at the end of `t` (a colour word, perhaps with a shade before it):
/// its name and length.
pub(crate) fn trailing_color(t: &[String]) -> Option<(String, usize)> {
    let last = t.last()?;
    let c = vocab::color(last).filter(|c| vocab::words(last).len() == 1 && !c.name.is_empty())?;
    if t.len() >= 2 && SHADES.contains(&t[t.len() - 2].as_str()) {
        return Some((format!("{} {}", t[t.len() - 2], last), 2));
    }
    Some((c.name, 1))
}

pub(crate) fn wall_word(w: &str) -> Option<Wall> {
    match w {
        "north" | "northern" | "back" | "far" => Some(Wall::North),
        "south" | "southern" | "front" | "near" => Some(Wall::South),
        "east" | "eastern" | "right" => Some(Wall::East),
        "west" | "western" | "left" => Some(Wall::West),
        _ => None,
    }
}

/// Directions of a shift: (east, north, right, forward) per metre.
pub(crate) fn direction(w: &str) -> Option<[f64; 4]> {
    Some(match w {
        "east" | "eastward" | "eastwards" => [1.0, 0.0, 0.0, 0.0],
        "west" | "westward" | "westwards" => [-1.0, 0.0, 0.0, 0.0],
        "north" | "northward" | "northwards" => [0.0, 1.0, 0.0, 0.0],
        "south" | "southward" | "southwards" => [0.0, -1.0, 0.0, 0.0],
        "right" => [0.0, 0.0, 1.0, 0.0],
        "left" => [0.0, 0.0, -1.0, 0.0],
        "forward" | "forwards" | "ahead" | "further" | "away" => [0.0, 0.0, 0.0, 1.0],
        "back" | "backward" | "backwards" | "closer" => [0.0, 0.0, 0.0, -1.0],
        _ => return None,
    })
}

/// Default distance of a shift with no number ("move the chair left"), m.
pub(crate) const DEFAULT_SHIFT: f64 = 0.5;

/// A shift: "1 m to the left", "left by 50 cm", "2 meters north", "to the left".
pub(crate) fn shift(t: &[String]) -> Option<Placement> {
    let mut dist: Option<f64> = None;
    let mut dir: Option<[f64; 4]> = None;
    let mut i = 0;
    while i < t.len() {
        let w = t[i].as_str();
        if let Some(n) =
            number(w).filter(|_| !matches!(w, "a" | "an") || t.get(i + 1).is_some_and(|u| unit(u).is_some()))
        {
            let u = t.get(i + 1).and_then(|u| unit(u));
            dist = Some(n * u.unwrap_or(1.0));
            i += if u.is_some() { 2 } else { 1 };
            continue;
        }
        if let Some(d) = direction(w) {
            if dir.is_some() {
                return None;
            }
            dir = Some(d);
        } else if !matches!(
            w,
            "to" | "the" | "by" | "towards" | "toward" | "a" | "bit" | "little" | "further" | "more" | "side"
        ) {
            return None;
        }
        i += 1;
    }
    let d = dir?;
    let m = dist.unwrap_or(DEFAULT_SHIFT);
    if !(m.is_finite() && m > 0.0 && m <= 100.0) {
        return None;
    }
    Some(Placement::Shift { east: d[0] * m, north: d[1] * m, right: d[2] * m, forward: d[3] * m })
}

pub(crate) fn corner_of(t: &[String]) -> Option<Option<Corner>> {
    let pos = t.iter().position(|w| w == "corner")?;
    let ws: Vec<&str> = t[..pos].iter().map(String::as_str).collect();
    let has = |w: &str| ws.contains(&w);
    let ns = if has("north") || has("northern") || has("back") || has("far") {
        Some(true)
    } else if has("south") || has("southern") || has("front") {
        Some(false)
    } else {
        None
    };
    let ew = if has("east") || has("eastern") || has("right") {
        Some(true)
    } else if has("west") || has("western") || has("left") {
        Some(false)
    } else {
        None
    };
    let joined: String = ws.concat();
    let (ns, ew) = match (ns, ew) {
        (None, None) if joined.contains("northeast") => (Some(true), Some(true)),
        (None, None) if joined.contains("northwest") => (Some(true), Some(false)),
        (None, None) if joined.contains("southeast") => (Some(false), Some(true)),
        (None, None) if joined.contains("southwest") => (Some(false), Some(false)),
        x => x,
    };
    Some(match (ns, ew) {
        (Some(true), Some(true)) => Some(Corner::NorthEast),
        (Some(true), Some(false)) => Some(Corner::NorthWest),
        (Some(false), Some(true)) => Some(Corner::SouthEast),
        (Some(false), Some(false)) => Some(Corner::SouthWest),
        _ => None,
    })
}

pub(crate) fn rotation(t: &[String]) -> Result<(usize, f64), String> {
    let start = (1..t.len())
        .find(|&i| {
            let w = t[i].as_str();
            matches!(w, "by" | "around" | "round" | "clockwise" | "counterclockwise" | "anticlockwise" | "cw" | "ccw")
                || (number(w).is_some() && !matches!(w, "a" | "an" | "one"))
                || (w == "a" && t.get(i + 1).is_some_and(|x| matches!(x.as_str(), "quarter" | "half")))
                || (w == "half" && t.get(i + 1).is_some_and(|x| x == "a" || x == "turn"))
                || ((w == "left" || w == "right") && i + 1 == t.len())
        })
        .unwrap_or(t.len());
    let rest = &t[start..];
    let mut deg: Option<f64> = None;
    let mut sign = 1.0;
    for (k, w) in rest.iter().enumerate() {
        match w.as_str() {
            "around" | "round" => deg = Some(180.0),
            "quarter" => deg = Some(90.0),
            "half" if rest.get(k + 1).is_some_and(|x| x == "turn" || x == "a") => deg = Some(180.0),
            "clockwise" | "cw" | "right" => sign = -1.0,
            "counterclockwise" | "anticlockwise" | "ccw" | "left" => sign = 1.0,
            w => {
                if let Ok(v) = w.parse::<f64>() {
                    deg = Some(v);
                }
            }
        }
    }
    let d = deg.unwrap_or(90.0);
    if !(d.is_finite() && d.abs() <= 3600.0) {
        return Err(format!("{d} degrees is not an angle"));
    }
    Ok((start, sign * d))
}

pub(crate) const SIZE_WORDS: &[(&str, [f64; 3])] = &[
    ("bigger", [1.25; 3]),
    ("larger", [1.25; 3]),
    ("smaller", [0.8; 3]),
    ("taller", [1.0, 1.0, 1.25]),
    ("higher", [1.0, 1.0, 1.25]),
    ("shorter", [1.0, 1.0, 0.8]),
    ("lower", [1.0, 1.0, 0.8]),
    ("wider", [1.25, 1.0, 1.0]),
    ("broader", [1.25, 1.0, 1.0]),
    ("longer", [1.25, 1.0, 1.0]),
    ("narrower", [0.8, 1.0, 1.0]),
    ("deeper", [1.0, 1.25, 1.0]),
    ("shallower", [1.0, 0.8, 1.0]),
];

pub(crate) fn is_size_start(t: &[String], i: usize) -> bool {
    let w = t[i].as_str();
    SIZE_WORDS.iter().any(|(s, _)| *s == w)
        || matches!(w, "twice" | "double" | "half" | "triple" | "much" | "a" | "slightly" | "up" | "down" | "by" | "to")
            && i > 0
        || (number(w).is_some() && !matches!(w, "one"))
}

pub(crate) fn resize_of(t: &[String]) -> Result<Resize, String> {
    let s = t.join(" ");
    let mut r = Resize::uniform(1.0);
    let mut factor: Option<f64> = None;
    if s.contains("twice") || s.contains("double") {
        factor = Some(2.0);
    } else if s.contains("triple") || s.contains("three times") {
        factor = Some(3.0);
    } else if s.contains("half") {
        factor = Some(0.5);
    }
    // "50 percent bigger", "by 1.5", "1.5 times", "2 m tall".
    for (i, w) in t.iter().enumerate() {
        let Ok(v) = w.parse::<f64>() else { continue };
        let next = t.get(i + 1).map(String::as_str).unwrap_or("");
        if next == "percent" {
            // "50 percent taller": the axes the size word names, by that much.
            let word = t[i + 2..].iter().find_map(|x| SIZE_WORDS.iter().find(|(w, _)| w == x));
            match word {
                Some((_, pattern)) => {
                    let f = if pattern.iter().any(|p| *p > 1.0) { 1.0 + v / 100.0 } else { 1.0 - v / 100.0 };
                    r.scale = pattern.map(|p| if p == 1.0 { 1.0 } else { f });
                    if !r.scale.iter().all(|f| f.is_finite() && *f > 0.05 && *f <= 20.0) {
                        return Err(format!("{v} percent is not a plausible change"));
                    }
                    return Ok(r);
                }
                None => factor = Some(v / 100.0),
            }
        } else if let Some(u) = unit(next) {
            let axis = t[i + 2..].first().map(String::as_str).unwrap_or("");
            let m = v * u;
            match axis {
                "tall" | "high" | "height" => r.height = Some(m),
                "wide" | "width" | "long" | "length" => r.width = Some(m),
                "deep" | "depth" => r.depth = Some(m),
                _ => r.width = Some(m),
            }
        } else if matches!(next, "times" | "x" | "") || t.get(i.wrapping_sub(1)).is_some_and(|p| p == "by") {
            factor = Some(v);
        }
    }
    if factor.is_none() && r.width.is_none() && r.depth.is_none() && r.height.is_none() {
        let strong = t.iter().any(|w| w == "much");
        let slight = t.iter().any(|w| w == "slightly" || w == "bit");
        for (w, f) in SIZE_WORDS {
            if t.iter().any(|x| x == w) {
                let adjust = |v: f64| {
                    if strong {
                        1.0 + (v - 1.0) * 2.0
                    } else if slight {
                        1.0 + (v - 1.0) * 0.4
                    } else {
                        v
                    }
                };
                r.scale = f.map(adjust);
                return Ok(r);
            }
        }
        if t.iter().any(|w| w == "up") {
            factor = Some(1.25);
        } else if t.iter().any(|w| w == "down") {
            factor = Some(0.8);
        }
    }
    if let Some(f) = factor {
        if !(f.is_finite() && f > 0.05 && f <= 20.0) {
            return Err(format!("a size factor of {f} is not plausible"));
        }
        r.scale = [f; 3];
    }
    if r.scale == [1.0; 3] && r.width.is_none() && r.depth.is_none() && r.height.is_none() {
        return Err(format!("'{s}' is not a size change the grammar knows (try 'bigger', 'twice as big', '2 m tall')"));
    }
    for v in [r.width, r.depth, r.height].into_iter().flatten() {
        if !(v > 0.0 && v <= 50.0) {
            return Err(format!("{v} m is not a plausible size"));
        }
    }
    Ok(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_the_planners_words_plus_articles_and_half() {
        assert_eq!(number("3"), Some(3.0));
        assert_eq!(number("a"), Some(1.0));
        assert_eq!(number("half"), Some(0.5));
        assert_eq!(number("eleven"), Some(11.0), "beyond the old table");
        assert_eq!(number("twenty-five"), Some(25.0));
        assert_eq!(number("dozen"), Some(12.0));
        assert_eq!(number("no"), None, "a refusal, not zero");
        assert_eq!(number("inf"), None);
        assert_eq!(number("chair"), None);
    }
}
