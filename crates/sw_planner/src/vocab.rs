//! The offline planner's vocabulary, for readers of other sources (an LLM's plan, an
//! edit command): what a noun phrase names, colours, size words, room kinds, robot
//! models and the size priors of labelled proxies.

use sw_plan::{Dims, ExplicitSize, NamedColor, ProxyPlan, RoomKind, SizeWord};
use sw_robots::RobotKind;

use crate::lexicon::{Meaning, is_head};
use crate::priors::prior_for;
use crate::text::{edit_distance, singular};

/// What a noun phrase names.
#[derive(Debug, Clone, PartialEq)]
pub enum Noun {
    /// A catalog category (registry name).
    Category(&'static str),
    /// A robot; the registry model it asks for (which may not be registered).
    Robot {
        wants: &'static str,
        arm: bool,
    },
    Room(RoomKind),
    Unknown,
}

/// Lowercase words, singular, without punctuation, articles and numbers.
pub fn words(phrase: &str) -> Vec<String> {
    let cleaned: String =
        phrase.chars().map(|c| if c.is_alphanumeric() || c == '\'' { c.to_ascii_lowercase() } else { ' ' }).collect();
    cleaned
        .split_whitespace()
        .filter(|w| !matches!(*w, "a" | "an" | "the" | "some" | "of") && w.parse::<f64>().is_err())
        .map(singular)
        .collect()
}

/// Reads a noun phrase ("two red industrial forklifts", "pallet_rack", "a workbench").
/// The head noun is the longest vocabulary entry ending the phrase; failing that, any
/// entry in it (the last), a typo of one, or a category named by the last word.
pub fn noun(phrase: &str) -> Noun {
    let ws = words(phrase);
    if ws.is_empty() {
        return Noun::Unknown;
    }
    let lex = crate::lexicon();
    let refs: Vec<&str> = ws.iter().map(String::as_str).collect();
    // Prefer entries that end the phrase, then longer ones, then later ones.
    let mut best: Option<((bool, usize, usize), Meaning)> = None;
    for i in 0..refs.len() {
        if let Some((e, n)) = lex.longest(&refs[i..], is_head) {
            let key = (i + n == refs.len(), n, i);
            if best.as_ref().is_none_or(|(k, _)| key > *k) {
                best = Some((key, e.meaning.clone()));
            }
        }
    }
    if let Some((_, m)) = best {
        return meaning_noun(&m);
    }
    // A typo of a single head word.
    let last = refs[refs.len() - 1];
    let limit = match last.chars().count() {
        0..=4 => 0,
        5..=7 => 1,
        _ => 2,
    };
    if limit > 0 {
        let mut found: Option<(usize, &str, Meaning)> = None;
        for (w, m) in lex.head_words() {
            let d = edit_distance(last, w);
            if d <= limit && found.as_ref().is_none_or(|(bd, bw, _)| d < *bd || (d == *bd && w < *bw)) {
                found = Some((d, w, m.clone()));
            }
        }
        if let Some((_, _, m)) = found {
            return meaning_noun(&m);
        }
    }
    // "bench" for a workbench: a category whose name ends with the word.
    if last.len() >= 5
        && let Some(c) = sw_catalog::categories()
            .iter()
            .find(|c| c.display.split_whitespace().last().is_some_and(|l| l != last && l.ends_with(last)))
    {
        return Noun::Category(c.name);
    }
    Noun::Unknown
}

fn meaning_noun(m: &Meaning) -> Noun {
    match m {
        Meaning::Category(c) => Noun::Category(c),
        Meaning::Robot(r) => Noun::Robot { wants: r.wants, arm: r.kind != RobotKind::MobileBase },
        Meaning::Room(k) | Meaning::RoomAisle(k) => Noun::Room(*k),
        Meaning::RoomWord => Noun::Room(RoomKind::Room),
        _ => Noun::Unknown,
    }
}

/// The catalog category a name or phrase means: an exact registry name first.
pub fn category(name: &str) -> Option<&'static str> {
    let snake = name.trim().to_lowercase().replace([' ', '-'], "_");
    if let Some(c) = sw_catalog::find(&snake) {
        return Some(c.name);
    }
    match noun(name) {
        Noun::Category(c) => Some(c),
        _ => None,
    }
}

/// A colour by name ("red", "dark grey", "wooden"), with its RGBA.
pub fn color(name: &str) -> Option<NamedColor> {
    let ws = words(name);
    let refs: Vec<&str> = ws.iter().map(String::as_str).collect();
    let lex = crate::lexicon();
    for i in 0..refs.len() {
        if let Some((e, _)) =
            lex.longest(&refs[i..], |m| matches!(m, Meaning::Color(..) | Meaning::Material(_, Some(_))))
        {
            return match &e.meaning {
                Meaning::Color(n, rgba) | Meaning::Material(n, Some(rgba)) => {
                    Some(NamedColor { name: n.to_string(), rgba: *rgba })
                }
                _ => None,
            };
        }
    }
    None
}

/// A size word ("large", "tall", "huge").
pub fn size_word(word: &str) -> Option<SizeWord> {
    let ws = words(word);
    let refs: Vec<&str> = ws.iter().map(String::as_str).collect();
    if refs.is_empty() {
        return None;
    }
    match crate::lexicon().longest(&refs, |m| matches!(m, Meaning::Size(_))) {
        Some((e, _)) => match e.meaning {
            Meaning::Size(s) => Some(s),
            _ => None,
        },
        None => None,
    }
}

/// A room kind by its JSON name or any word for it ("lab", "machine shop").
pub fn room_kind(name: &str) -> Option<RoomKind> {
    let snake = name.trim().to_lowercase().replace([' ', '-'], "_");
    if let Some(k) = RoomKind::ALL.iter().find(|k| k.name() == snake) {
        return Some(*k);
    }
    match noun(name) {
        Noun::Room(k) => Some(k),
        _ => None,
    }
}

/// The registered robot model a name means, and a note when it is an approximation.
pub fn robot_model(name: &str) -> Option<(&'static str, Option<String>)> {
    if let Some(def) = sw_robots::find(name.trim()) {
        return Some((def.name, None));
    }
    let Noun::Robot { wants, arm } = noun(name) else {
        return None;
    };
    if let Some(def) = sw_robots::find(wants) {
        return Some((def.name, Some(format!("read as the {}", def.display))));
    }
    let kind = if wants == "mobile_manipulator" {
        RobotKind::MobileManipulator
    } else if arm {
        RobotKind::Arm
    } else {
        RobotKind::MobileBase
    };
    let def = sw_robots::default_of(kind);
    Some((def.name, Some(format!("'{wants}' is not in the robot registry yet; used the built-in {}", def.display))))
}

/// The value of a number word ("seven", "dozen", "twenty-five", "pair"; "no" is 0), as
/// the planner reads counts.
pub fn number_word(w: &str) -> Option<f64> {
    crate::text::number_word(w)
}

/// A labelled stand-in for `label`, sized by the prior its head noun suggests, scaled by
/// size words and overridden by explicit dimensions; sides kept within 2 cm … 20 m.
pub fn proxy(label: &str, resting_on_something: bool, sizes: &[SizeWord], explicit: &ExplicitSize) -> ProxyPlan {
    let head: Vec<String> = words(label);
    let prior = prior_for(&head.join(" "), resting_on_something);
    let mut size = prior.size;
    for w in sizes {
        let f = w.factors();
        for i in 0..3 {
            size[i] *= f[i];
        }
    }
    for (i, v) in [explicit.width, explicit.depth, explicit.height].into_iter().enumerate() {
        if let Some(v) = v.filter(|v| v.is_finite() && *v > 0.0) {
            size[i] = v;
        }
    }
    let s = size.map(|v| v.clamp(0.02, 20.0));
    ProxyPlan {
        label: label.to_string(),
        prior: prior.name.into(),
        size: Dims::new(s[0], s[1], s[2]),
        movable: prior.movable,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nouns_read_like_the_offline_planner() {
        assert_eq!(noun("two red pallet racks"), Noun::Category("pallet_rack"));
        assert_eq!(noun("pallet_rack"), Noun::Category("pallet_rack"));
        assert_eq!(noun("the workbenches"), Noun::Category("workbench"));
        assert_eq!(noun("a forkilft"), Noun::Category("forklift"));
        assert!(matches!(noun("a UR5e"), Noun::Robot { wants: "ur5e", arm: true }));
        assert_eq!(noun("machine shop"), Noun::Room(RoomKind::Workshop));
        assert_eq!(noun("flux capacitor"), Noun::Unknown);
        assert_eq!(category("Cardboard Box"), Some("cardboard_box"));
    }

    #[test]
    fn colours_sizes_rooms_and_robots() {
        assert_eq!(color("red").unwrap().name, "red");
        assert!(color("plaid").is_none());
        assert_eq!(size_word("large"), Some(SizeWord::Large));
        assert_eq!(room_kind("data_centre"), Some(RoomKind::DataCentre));
        assert_eq!(room_kind("laboratory"), Some(RoomKind::Lab));
        assert_eq!(robot_model("ur5e").unwrap().0, "ur5e");
        assert_eq!(robot_model("Franka Panda").unwrap().0, "panda");
        assert!(robot_model("toaster").is_none());
    }

    #[test]
    fn proxies_follow_priors_and_explicit_sizes() {
        let p = proxy("flux capacitor", false, &[], &ExplicitSize::default());
        assert_eq!(p.prior, "floor object");
        let p =
            proxy("espresso cup", true, &[SizeWord::Large], &ExplicitSize { height: Some(0.3), ..Default::default() });
        assert!(p.movable && (p.size.height - 0.3).abs() < 1e-9);
    }
}
