//! Nouns the catalog lacks, at the start of L2: each labelled proxy of the plan goes to
//! the nearest category by meaning only when the noun is a kind of it, else stays a
//! labelled proxy sized by the prior of its kind of thing. Both are reported; nothing is
//! dropped silently.
//!
//! The kind check reads data, not spellings: English compounds are right-headed, so "an
//! espresso maker" is a kind of *maker* and "a bread knife" a kind of *knife*. A category
//! is a candidate for a noun when the noun's head (its last word, or last two) is one of
//! the category's own names (then the noun is a kind of that category: "a chef knife" →
//! chef's knife) or one of its hypernyms (`Category::is_a`: then the two are kinds of the
//! same thing, and the noun maps only when it is also close in meaning). Among candidates
//! the in-process MiniLM (all-MiniLM-L6-v2, `sw_forge::embed`) picks the nearest by the
//! largest cosine similarity to the category's names and one-line description. A noun
//! with no candidate stays a proxy; the nearest category overall then only tells its kind
//! (a size prior: appliance, furniture, fixture, hand-held item …) when it is close enough.
//!
//! Without the MiniLM weights the lexical part still runs (a noun whose head names a
//! category maps to it) and everything else keeps the kind prior of its candidates, with
//! a warning that matching by meaning was off. Category vectors are computed once and kept
//! in `.cache/vocab/` (keyed by a hash of the texts and the model's config), so a run
//! embeds only its unknown nouns.

use std::cell::OnceCell;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use sha2::{Digest, Sha256};
use sw_catalog::{Category, Kind};
use sw_plan::{Approximation, Dims, ProxyPlan, ScenePlan, Stage, Warning};

/// A sibling (a category of the same hypernym as the noun) or a category named alike
/// is taken only this close in meaning to one of its names, cosine similarity of MiniLM
/// vectors (tuned on bench/vocab/dev.tsv).
pub const SIBLING_MIN: f32 = 0.62;
/// … and only this close to its one-line description: the description carries the
/// category's sense, so a noun that shares a head word with one of its names but means
/// another thing ("salt shaker" and "lab shaker", "rocking horse" and "sawhorse") falls
/// below it while a true kind ("santoku knife" and the chef's knife) stays above.
pub const SENSE_MIN: f32 = 0.5;
/// A noun whose head names a category but whose modifiers are foreign to it (not words
/// of its names, tags, hypernyms or description) is refused as that category when it is
/// below this close to its description and another category's description is nearer by
/// more than [`SENSE_MARGIN`]: "a waffle iron" is no clothes iron, while "a kids bicycle"
/// (nothing is nearer than the bicycle) and "a bread knife" stay what their heads name.
pub const NAMED_SENSE_MIN: f32 = 0.45;
/// How much nearer another category's sense must be to take a noun away from the one its
/// words name.
pub const SENSE_MARGIN: f32 = 0.05;
/// The nearest categories tell an unknown noun's kind of thing only this close (the mean
/// of name and sense scores).
pub const KIND_MIN: f32 = 0.45;
/// How many of the nearest categories vote on an unknown noun's kind (each by its
/// similarity over its rank, so that the nearest counts most but four close neighbours
/// of one kind outvote it: "a trailer" is nearest a toy car but among vehicles), and how
/// many of the winning kind give its proxy a size.
const KIND_VOTERS: usize = 5;
const SIZE_VOTERS: usize = 3;
/// A word the planner read as a typo of a catalog name ("trailer" for "trainer") is that
/// name only when the model does not know the word itself, or knows it as this close in
/// meaning (a spelling variant: "tyre" and "tire" 0.84, "trailer" and "trainer" 0.27).
pub const TYPO_SENSE_MIN: f32 = 0.6;
/// A noun with no candidate by its head that is this much nearer to an abstract noun
/// ([`ABSTRACT`]) than to every category names nothing physical ("a happiness"): it is
/// left out, with a warning.
pub const ABSTRACT_MARGIN: f32 = 0.02;

/// Nouns that name no physical thing: feelings, ideas, events, sounds, time. A noun
/// nearer to these by meaning than to any category is not an object.
pub const ABSTRACT: &[&str] = &[
    "happiness",
    "sadness",
    "love",
    "fear",
    "anger",
    "an idea",
    "a thought",
    "a feeling",
    "an emotion",
    "a mood",
    "time",
    "a moment",
    "an hour",
    "a smell",
    "the weather",
    "a meeting",
    "a party",
    "a holiday",
    "a dream",
    "freedom",
    "peace",
    "a problem",
    "a question",
    "an event",
    "a concept",
    "luck",
    "silence",
    "history",
    "a memory",
    "an atmosphere",
    "a vibe",
    // Kinds of non-thing the list above lacked: money matters, speech and news, plans and situations, relations between people.
    "a price",
    "a debt",
    "a payment",
    "a conversation",
    "a speech",
    "news",
    "an opinion",
    "a promise",
    "a plan",
    "a mistake",
    "a situation",
    "a relationship",
    "a delay",
];

/// How a noun was resolved.
#[derive(Debug, Clone, PartialEq)]
pub enum Resolution {
    /// A kind of this category (its head names it, or a close sibling by meaning).
    Category { name: &'static str, score: Option<f32>, lexical: bool },
    /// A labelled proxy of this kind, sized (width, depth, height, m) like the nearest
    /// categories of that kind when the model could say which.
    Proxy { kind: Option<Kind>, size: Option<[f64; 3]>, nearest: Option<(&'static str, f32)> },
    /// Not a physical thing: left out.
    NotAThing { nearest: Option<(&'static str, f32)> },
}

/// The name under which the abstract nouns' vectors are kept.
const ABSTRACT_KEY: &str = "__abstract__";

/// The words of a noun phrase, lowercase and singular (the planner's reading).
fn noun_words(label: &str) -> Vec<String> {
    sw_planner::vocab::words(label)
}

/// Every name of a category as singular words: its display name, registry name and
/// synonyms. A name that loses a word to the planner's reading (the article of "a-board",
/// the number of "2-slice toaster") is left out: "a-board" is not a "board".
fn names_of(cat: &Category) -> Vec<Vec<String>> {
    let raw = |s: &str| s.split(|c: char| !(c.is_alphanumeric() || c == '\'')).filter(|w| !w.is_empty()).count();
    let mut out = vec![noun_words(cat.display), noun_words(&cat.name.replace('_', " "))];
    out.extend(cat.synonyms.iter().filter(|s| noun_words(s).len() == raw(s)).map(|s| noun_words(s)));
    out.retain(|n| !n.is_empty());
    out
}

/// Every word a category uses about itself: its names, tags, hypernyms and description.
/// A modifier among them agrees with the category ("kitchen sink", "office chair").
fn own_words(cat: &Category) -> Vec<String> {
    let mut w: Vec<String> = names_of(cat).concat();
    for t in cat.tags.iter().chain(cat.is_a).chain(std::iter::once(&cat.description)) {
        w.extend(noun_words(t));
    }
    w.sort();
    w.dedup();
    w
}

/// How a candidate category relates to a noun's head.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Tie {
    /// One of its names is the head itself: the noun is a kind of it.
    Named,
    /// One of its names ends in the head: the noun and it are kinds of one thing named
    /// alike ("santoku knife" and "chef's knife").
    HeadNamed,
    /// The head is one of its hypernyms.
    Sibling,
}

/// The candidates for a noun, most specific head (last two words, then last word)
/// first, with the number of words of the head.
fn candidates(words: &[String]) -> (Vec<(&'static Category, Tie)>, usize) {
    for n in (1..=words.len().min(2)).rev() {
        let head = &words[words.len() - n..];
        let mut out: Vec<(&'static Category, Tie)> = Vec::new();
        for cat in sw_catalog::categories() {
            let names = names_of(cat);
            if names.iter().any(|nm| nm == head) {
                out.push((cat, Tie::Named));
            } else if names.iter().any(|nm| nm.len() > head.len() && nm.ends_with(head)) {
                out.push((cat, Tie::HeadNamed));
            } else if cat.is_a.iter().any(|h| noun_words(h) == head) {
                out.push((cat, Tie::Sibling));
            }
        }
        if !out.is_empty() {
            return (out, n);
        }
    }
    (Vec::new(), 0)
}

/// Ranks categories by meaning.
pub trait Meaning {
    /// Cosine similarity of `noun` to each category in `among` (the nearest of its names
    /// and its description), in the same order; `None` when matching by meaning is
    /// unavailable.
    fn scores(&self, noun: &str, among: &[&'static Category]) -> Option<Vec<f32>>;
    /// Cosine similarity of `noun` to each category's one-line description (its sense);
    /// `None` when unavailable.
    fn senses(&self, _noun: &str, _among: &[&'static Category]) -> Option<Vec<f32>> {
        None
    }
    /// Cosine similarity of two words, when the model knows the first as a whole word
    /// (one token of its vocabulary); `None` for a word it does not know (a typo) or
    /// when unavailable.
    fn word_similarity(&self, _word: &str, _other: &str) -> Option<f32> {
        None
    }
    /// Cosine similarity of `noun` to the nearest of [`ABSTRACT`]; `None` when unavailable.
    fn abstractness(&self, noun: &str) -> Option<f32>;
}

/// Whether the modifiers of a noun (its words before the head) agree with a category:
/// each one is a word the category uses about itself.
fn modifiers_agree(modifiers: &[String], cat: &Category) -> bool {
    let own = own_words(cat);
    modifiers.iter().all(|m| own.binary_search(m).is_ok())
}

/// Whether `cat`, named with `head` as its last word ("toy car" for "car"), is not a
/// kind of what `head` names, by its hypernyms (`Category::is_a`): `head` is none of them
/// while a modifier of that name is one. A toy car is a toy (its hypernyms: toy, model), so
/// "a car" is not one; a baseball cap (hypernyms: cap, headwear) is a cap. A bare noun is
/// more general than a sub-kind named with it and maps to it only when the sub-kind is a
/// kind of it. Only compounds are read so: a phrase name ("bag of flour", "cabinet on
/// wheels") names its head's thing in a container or with a feature, the pack a mass noun
/// comes in.
fn named_as_a_kind_of_its_modifier(cat: &Category, head: &[String]) -> bool {
    const LINKS: [&str; 4] = ["of", "for", "with", "on"];
    let hypernyms: Vec<Vec<String>> = cat.is_a.iter().map(|h| noun_words(h)).collect();
    if hypernyms.iter().any(|h| h.as_slice() == head) {
        return false;
    }
    let raw = [cat.display.to_string(), cat.name.replace('_', " ")];
    let compounds = raw
        .iter()
        .map(String::as_str)
        .chain(cat.synonyms.iter().copied())
        .filter(|n| !n.split(|c: char| !c.is_alphanumeric()).any(|w| LINKS.contains(&w.to_lowercase().as_str())))
        .map(noun_words)
        .filter(|n| n.len() > head.len() && n.ends_with(head))
        .collect::<Vec<_>>();
    compounds.iter().any(|n| {
        let modifiers = &n[..n.len() - head.len()];
        hypernyms.iter().any(|h| !h.is_empty() && modifiers.windows(h.len()).any(|w| w == h.as_slice()))
    })
}

/// The category whose sense is nearest to `noun`, and its score (`None` without the model).
fn nearest_sense(noun: &str, meaning: &dyn Meaning) -> Option<(&'static Category, f32)> {
    let all: Vec<&'static Category> = sw_catalog::categories().iter().collect();
    let s = meaning.senses(noun, &all)?;
    all.into_iter().zip(s).max_by(|a, b| a.1.total_cmp(&b.1))
}

/// Per category of `cats`, the mean of `text`'s name score (`names`) and its sense score:
/// how near it is by name *and* by what the category is; the name scores alone where the
/// model gives no senses.
fn name_and_sense(text: &str, names: &[f32], cats: &[&'static Category], meaning: &dyn Meaning) -> Vec<f32> {
    match meaning.senses(text, cats) {
        Some(senses) => names.iter().zip(senses).map(|(n, s)| (n + s) / 2.0).collect(),
        None => names.to_vec(),
    }
}

/// The largest sense score of `noun` over every category (`None` without the model).
fn best_sense(noun: &str, meaning: &dyn Meaning) -> Option<f32> {
    nearest_sense(noun, meaning).map(|(_, s)| s)
}

/// Whether a sense score takes a noun away from a category its head names: low, and
/// another category is clearly nearer.
fn sense_refuses(sense: f32, best: Option<f32>) -> bool {
    sense < NAMED_SENSE_MIN && best.is_some_and(|b| sense < b - SENSE_MARGIN)
}

/// Resolves one noun phrase (a proxy's label).
pub fn resolve_noun(label: &str, meaning: &dyn Meaning) -> Resolution {
    // The head phrase names the thing ("a bag of feed" is a kind of bag); the model reads
    // the whole noun, complement included.
    let (words, complement) = phrase_parts(label);
    if words.is_empty() {
        return Resolution::Proxy { kind: None, size: None, nearest: None };
    }
    let (cands, head_len) = candidates(&words);
    let text = phrase_text(&words, &complement);
    let modifiers = &words[..words.len() - head_len];
    if !cands.is_empty() {
        let cats: Vec<&'static Category> = cands.iter().map(|(c, _)| *c).collect();
        let scores = meaning.scores(&text, &cats);
        let senses = meaning.senses(&text, &cats);
        let best = OnceCell::new();
        let best = || *best.get_or_init(|| best_sense(&text, meaning));
        // Whether candidate i is the thing named: its head names it and the modifiers
        // agree (by its own words, else by its sense), or it is a kind of one thing with
        // the noun that is close to it both by name and by sense.
        let admitted = |i: usize| -> bool {
            let (cat, tie) = cands[i];
            let name = scores.as_ref().map(|s| s[i]);
            let sense = senses.as_ref().map(|s| s[i]);
            match tie {
                Tie::Named => modifiers_agree(modifiers, cat) || !sense.is_some_and(|s| sense_refuses(s, best())),
                // Kinds of one thing with different modifiers ("a medicine box" and the
                // tissue box) are siblings, not the same thing: only a noun whose
                // modifiers the category uses about itself is taken, and then only near.
                Tie::HeadNamed | Tie::Sibling => {
                    (tie == Tie::Sibling
                        || !modifiers.is_empty()
                        || !named_as_a_kind_of_its_modifier(cat, &words[words.len() - head_len..]))
                        && modifiers_agree(modifiers, cat)
                        && name.is_some_and(|s| s >= SIBLING_MIN)
                        && sense.is_some_and(|s| s >= SENSE_MIN && best().is_none_or(|b| s >= b - SENSE_MARGIN))
                }
            }
        };
        let rank = |i: usize| -> (u8, u8, f32) {
            let (cat, tie) = cands[i];
            let score = scores.as_ref().map_or(0.0, |s| s[i]);
            // A generic word gets its generic category: the one whose own display name
            // is the head, before a sub-kind that lists the word as a synonym. A modified
            // noun goes to the nearest of the categories named like it ("a santoku knife"
            // is nearer the chef's knife than the table knife both named "knife").
            let generic = noun_words(cat.display) == words[words.len() - head_len..];
            let tie_rank = match (tie, modifiers.is_empty()) {
                (Tie::Named, true) => 2,
                (Tie::Named | Tie::HeadNamed, _) => 1,
                (Tie::Sibling, _) => 0,
            };
            (tie_rank, u8::from(generic && modifiers.is_empty()), score)
        };
        let best = (0..cands.len())
            .filter(|&i| admitted(i))
            .max_by(|&a, &b| rank(a).partial_cmp(&rank(b)).unwrap_or(std::cmp::Ordering::Equal));
        if let Some(i) = best {
            let (cat, tie) = cands[i];
            return Resolution::Category {
                name: cat.name,
                score: scores.as_ref().map(|s| s[i]),
                lexical: tie == Tie::Named && modifiers_agree(modifiers, cat),
            };
        }
        // Refused: a labelled proxy. Its kind is the candidates' when they agree (the
        // head names that kind of thing), else what the nearest categories say.
        let kinds: Vec<Kind> = cands.iter().map(|(c, _)| c.kind).collect();
        let agreed = kinds.iter().all(|k| *k == kinds[0]).then_some(kinds[0]);
        // A head that names a category is a thing of that kind; one only shared with a
        // longer name ("blind date" and the "box of dates") says nothing about the noun:
        // it is weighed as a thing or not like a noun with no candidate at all.
        if cands.iter().any(|(_, tie)| *tie == Tie::Named) {
            return proxy_by_meaning(&text, meaning, agreed);
        }
        return thing_or_not(&words, &text, meaning, agreed, &cats);
    }
    thing_or_not(&words, &text, meaning, None, &[])
}

/// A noun no category is: left out as not a thing when it is nearer the abstract anchors
/// than any category like it, else a labelled proxy (of kind `known` when its head said).
/// The `refused` candidates were judged not to be what the noun names and are no evidence
/// that it is a thing.
fn thing_or_not(
    words: &[String],
    text: &str,
    meaning: &dyn Meaning,
    known: Option<Kind>,
    refused: &[&'static Category],
) -> Resolution {
    let text = text.to_string();
    let all: Vec<&'static Category> = sw_catalog::categories().iter().collect();
    // The evidence that the noun is a thing is its nearness to a category by name *and*
    // by sense (its name with its description), the mean of the two: a name alone is near
    // by spelling and shared sub-words ("a hunch" and the ottoman, "a traffic jam" and the
    // forklift), a sense alone is low for a real thing the descriptions do not mention.
    let evidence = meaning.scores(&text, &all).map(|names| name_and_sense(&text, &names, &all, meaning));
    if let Some(s) = evidence {
        // Only a category that could be like the noun counts as evidence that it is a
        // thing: not one named for it or after its modifiers, nor one that shares only a
        // modifier with it ("a birthday party" is near the birthday cake by "birthday").
        let (i, score) = s
            .iter()
            .copied()
            .enumerate()
            .filter(|&(i, _)| {
                !related_not_alike(words, all[i])
                    && !shares_only_a_modifier(words, all[i])
                    && !refused.iter().any(|r| r.name == all[i].name)
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0));
        if meaning.abstractness(&text).is_some_and(|a| a >= score + ABSTRACT_MARGIN) {
            return Resolution::NotAThing { nearest: all.get(i).map(|c| (c.name, score)) };
        }
    }
    proxy_by_meaning(&text, meaning, known)
}

/// Whether `cat` is named as a thing *for* or *of* the noun rather than a thing like it
/// (English compounds are right-headed): one of its names uses the noun's head as a
/// modifier ("rice cooker" for "rice", "fish tank" for "fish", "bean bag" for "green
/// beans"), or the noun uses one of its names as a modifier ("egg tart" and the egg,
/// "pizza cutter" and the pizza). Near in meaning as such a category is, it says nothing
/// about the noun's kind of thing or its size: measured on the public-list dev slice, such
/// neighbours made rice a small appliance, ice cream's and fish's proxies a fridge and a
/// tank, and a hat furniture.
fn related_not_alike(words: &[String], cat: &Category) -> bool {
    let Some(head) = words.last() else { return false };
    let modifiers = &words[..words.len() - 1];
    names_of(cat).iter().any(|name| {
        let name_modifiers = &name[..name.len().saturating_sub(1)];
        name_modifiers.contains(head) || (!name.is_empty() && modifiers.windows(name.len()).any(|w| w == &name[..]))
    })
}

/// Whether a name of `cat` shares a modifier with the noun while its head is another word
/// ("birthday cake" and "a birthday party"): near by that word, not by what either is.
fn shares_only_a_modifier(words: &[String], cat: &Category) -> bool {
    let Some(head) = words.last() else { return false };
    let modifiers = &words[..words.len() - 1];
    names_of(cat).iter().any(|name| {
        name.last().is_some_and(|h| h != head) && name[..name.len() - 1].iter().any(|m| modifiers.contains(m))
    })
}

/// A labelled proxy for `text`: of kind `known` when the head said it, else the kind the
/// nearest categories by meaning vote for ([`KIND_VOTERS`]); sized like the nearest
/// categories of that kind (the whole default size of the one whose volume is the median
/// of up to [`SIZE_VOTERS`], so that a long thing and a flat thing never average into a
/// shape neither has), within a factor of three of the kind's prior. Categories named
/// for or after the noun rather than like it ([`related_not_alike`]) neither vote nor size.
fn proxy_by_meaning(text: &str, meaning: &dyn Meaning, known: Option<Kind>) -> Resolution {
    let all: Vec<&'static Category> = sw_catalog::categories().iter().collect();
    let Some(names) = meaning.scores(text, &all) else {
        return Resolution::Proxy { kind: known, size: None, nearest: None };
    };
    // A neighbour tells the noun's kind by what it *is* as well as by its name (the mean
    // of its name and sense scores, as for the evidence of a thing): near by name alone is near by spelling or by
    // shared sub-words ("chaise longue" and the chalice, "moka pot" and the lasagne), which
    // says nothing about the kind of thing or its size.
    let s = name_and_sense(text, &names, &all, meaning);
    let words = phrase_parts(text).0;
    let mut order: Vec<usize> = (0..all.len()).collect();
    order.sort_by(|&a, &b| names[b].total_cmp(&names[a]));
    let nearest = order.first().map(|&i| (all[i].name, names[i]));
    order.sort_by(|&a, &b| s[b].total_cmp(&s[a]));
    order.retain(|&i| !related_not_alike(&words, all[i]));
    let kind = known.or_else(|| {
        let mut votes: BTreeMap<Kind, f32> = BTreeMap::new();
        for (rank, &i) in order.iter().take(KIND_VOTERS).enumerate().filter(|(_, i)| s[**i] >= KIND_MIN) {
            *votes.entry(all[i].kind).or_default() += s[i] / (rank + 1) as f32;
        }
        votes.into_iter().max_by(|a, b| a.1.total_cmp(&b.1)).map(|(k, _)| k)
    });
    let size = kind.and_then(|k| {
        let near: Vec<[f64; 3]> = order
            .iter()
            .filter(|&&i| all[i].kind == k && s[i] >= KIND_MIN)
            .take(SIZE_VOTERS)
            .map(|&i| all[i].default_size())
            .collect();
        if near.is_empty() {
            return None;
        }
        let prior = k.prior().size;
        let mut by_volume = near;
        by_volume.sort_by(|a, b| (a[0] * a[1] * a[2]).total_cmp(&(b[0] * b[1] * b[2])));
        let middle = by_volume[by_volume.len() / 2];
        Some(std::array::from_fn(|d| middle[d].clamp(prior[d] / 3.0, prior[d] * 3.0)))
    });
    Resolution::Proxy { kind, size, nearest }
}

/// Applies [`resolve_noun`] to every labelled proxy of `plan`: a kind of a category
/// becomes that category (reported as approximated); a proxy takes its kind's size prior
/// (explicit sizes kept); a noun that names no thing is left out. Each phrase keeps one
/// line in `approximated`: the planner's "labelled proxy" line is replaced, never
/// repeated beside a contradicting one. Returns the warnings.
pub fn resolve_plan(plan: &mut ScenePlan, meaning: &dyn Meaning) -> Vec<Warning> {
    let mut warnings = Vec::new();
    let mut dropped: Vec<String> = Vec::new();
    for group in &mut plan.objects {
        let Some(proxy) = group.proxy.clone() else { continue };
        let res = resolve_noun(&proxy.label, meaning);
        let noun = proxy.label.clone();
        let approximated = &mut plan.understanding.approximated;
        let planners_line = |a: &Approximation| a.text == group.phrase && a.became.starts_with("labelled proxy");
        match res {
            Resolution::Category { name, score, lexical } => {
                let Some(cat) = sw_catalog::find(name) else { continue };
                let how = match (lexical, score) {
                    (true, _) => format!("a kind of {} (its head noun names it)", cat.display),
                    (false, Some(s)) => {
                        format!("a kind of {} by its head, near in meaning (similarity {s:.2})", cat.display)
                    }
                    (false, None) => format!("a kind of {}", cat.display),
                };
                approximated.retain(|a| !planners_line(a));
                approximated.push(Approximation {
                    text: group.phrase.clone(),
                    became: cat.display.to_string(),
                    reason: format!("'{noun}' is not in the catalog; made as a {}: {how}", cat.display),
                });
                warnings.push(Warning::new(
                    Stage::Forge,
                    "noun_approximated",
                    format!("'{noun}' is not in the catalog; made as a {} ({how})", cat.display),
                ));
                group.category = cat.name.to_string();
                group.proxy = None;
            }
            Resolution::Proxy { kind, size, nearest } => {
                let near = nearest.map_or(String::new(), |(n, s)| format!("; nearest category {n} at {s:.2}"));
                // What the prompt said of it (a head noun the planner knows, a surface it
                // rests on: "four parts on the bench") outranks its neighbours by meaning.
                let said = proxy.prior != sw_planner::FALLBACK_PRIOR;
                let sized = match kind {
                    Some(k) if !said => sized_by_kind(&proxy, k, size, &group.size),
                    _ => proxy.clone(),
                };
                let s = &sized.size;
                let what = match kind {
                    Some(k) if !said => format!("sized as a {}", k.name()),
                    Some(_) => format!("sized as a {} (as the prompt puts it)", sized.prior),
                    None => format!("its kind unknown, sized as a {}", sized.prior),
                };
                let reason = format!(
                    "no catalog asset for '{noun}'; a {:.2} × {:.2} × {:.2} m box {what}{near}",
                    s.width, s.depth, s.height
                );
                approximated.retain(|a| !planners_line(a));
                approximated.push(Approximation {
                    text: group.phrase.clone(),
                    became: format!("labelled proxy '{noun}'"),
                    reason: reason.clone(),
                });
                warnings.push(Warning::new(Stage::Forge, "noun_proxy", reason.clone()));
                group.proxy = Some(sized);
            }
            // A noun the prompt sets on or under something ("four parts on the bench") is
            // an object whatever its words are nearest: a labelled proxy of its said kind.
            Resolution::NotAThing { .. } if proxy.prior != sw_planner::FALLBACK_PRIOR => {
                let reason = format!(
                    "no catalog asset for '{noun}'; a labelled proxy sized as a {} (as the prompt puts it)",
                    proxy.prior
                );
                approximated.retain(|a| !planners_line(a));
                approximated.push(Approximation {
                    text: group.phrase.clone(),
                    became: format!("labelled proxy '{noun}'"),
                    reason: reason.clone(),
                });
                warnings.push(Warning::new(Stage::Forge, "noun_proxy", reason));
            }
            Resolution::NotAThing { nearest } => {
                let near = nearest.map_or(String::new(), |(n, s)| format!(" (nearest category {n} at {s:.2})"));
                warnings.push(Warning::new(
                    Stage::Forge,
                    "not_a_thing",
                    format!("'{noun}' does not name an object the catalog or its kinds know{near}; left out"),
                ));
                approximated.retain(|a| !planners_line(a));
                plan.understanding.not_understood.push(sw_plan::NotUnderstood {
                    text: group.phrase.clone(),
                    reason: format!("'{noun}' does not name a physical object"),
                });
                dropped.push(group.id.clone());
            }
        }
    }
    if !dropped.is_empty() {
        plan.objects.retain(|o| !dropped.contains(&o.id));
        plan.relations.retain(|r| {
            !dropped.contains(&r.subject) && !r.kind.targets().iter().any(|t| dropped.iter().any(|d| d == t))
        });
    }
    warnings
}

/// A proxy resized to `kind`: `size` (from the nearest categories of that kind) or the
/// kind's prior, scaled by the size words the planner applied to its own prior, with
/// explicit dimensions kept.
fn sized_by_kind(p: &ProxyPlan, kind: Kind, size: Option<[f64; 3]>, said: &sw_plan::SizeHint) -> ProxyPlan {
    let prior = kind.prior();
    let mut s = size.unwrap_or(prior.size);
    for w in &said.words {
        let f = w.factors();
        for (v, f) in s.iter_mut().zip(f) {
            *v *= f;
        }
    }
    let explicit = &said.explicit;
    for (i, v) in [explicit.width, explicit.depth, explicit.height].into_iter().enumerate() {
        if let Some(v) = v.filter(|v| v.is_finite() && *v > 0.0) {
            s[i] = v;
        }
    }
    let s = s.map(|v| v.clamp(0.01, 20.0));
    ProxyPlan {
        label: p.label.clone(),
        prior: kind.name().to_string(),
        size: Dims::new(s[0], s[1], s[2]),
        movable: prior.movable,
    }
}

/// The in-process MiniLM over every category's names and description; `None` inside when
/// the weights are not installed (the reason is kept for the warning).
pub struct MiniLmMeaning {
    model: Result<sw_forge::embed::MiniLm, String>,
    /// Each noun is embedded once per process.
    queries: std::sync::Mutex<BTreeMap<String, Vec<f32>>>,
    /// Per category, the unit vectors of its texts (names and description).
    vectors: BTreeMap<&'static str, Vec<Vec<f32>>>,
}

impl std::fmt::Debug for MiniLmMeaning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MiniLmMeaning").field("loaded", &self.model.is_ok()).finish_non_exhaustive()
    }
}

/// What a category is embedded as: each name, and "name: description".
fn texts_of(cat: &Category) -> Vec<String> {
    let mut t = vec![cat.display.to_string()];
    t.extend(cat.synonyms.iter().map(|s| s.to_string()));
    t.push(format!("{}: {}", cat.display, cat.description));
    t
}

impl MiniLmMeaning {
    /// Loads the model from `dir` and the category vectors from `cache` (computing and
    /// storing them when missing or stale).
    pub fn load(dir: &Path, cache: &Path) -> Self {
        let model = sw_forge::embed::MiniLm::load(dir).map_err(|e| e.to_string());
        let mut vectors = BTreeMap::new();
        if let Ok(m) = &model {
            let mut texts: Vec<(&'static str, String)> = sw_catalog::categories()
                .iter()
                .flat_map(|c| texts_of(c).into_iter().map(move |t| (c.name, t)))
                .collect();
            texts.extend(ABSTRACT.iter().map(|a| (ABSTRACT_KEY, a.to_string())));
            let key = cache_key(dir, &texts);
            let file = cache.join(format!("categories-{key}.bin"));
            let flat = read_cache(&file, texts.len()).or_else(|| {
                let v = embed_by_length(m, &texts)?;
                write_cache(&file, &v);
                Some(v)
            });
            if let Some(flat) = flat {
                for ((name, _), v) in texts.iter().zip(flat) {
                    vectors.entry(*name).or_insert_with(Vec::new).push(v);
                }
            }
        }
        Self { model, queries: std::sync::Mutex::new(BTreeMap::new()), vectors }
    }

    /// The process's one matcher, from the default model directory and `.cache/vocab`.
    pub fn shared() -> &'static MiniLmMeaning {
        static SHARED: OnceLock<MiniLmMeaning> = OnceLock::new();
        SHARED.get_or_init(|| {
            let cache = sw_forge::runner::checkout_cache().join("vocab");
            MiniLmMeaning::load(&sw_forge::embed::default_model_dir(), &cache)
        })
    }

    /// Why matching by meaning is off, if it is.
    pub fn unavailable(&self) -> Option<&str> {
        match &self.model {
            Ok(_) if self.vectors.is_empty() => Some("the category vectors could not be computed"),
            Ok(_) => None,
            Err(e) => Some(e.as_str()),
        }
    }
}

/// Embeds `texts` in batches of similar length (a batch is padded to its longest text),
/// returning the vectors in the texts' order.
fn embed_by_length(m: &sw_forge::embed::MiniLm, texts: &[(&'static str, String)]) -> Option<Vec<Vec<f32>>> {
    let mut order: Vec<usize> = (0..texts.len()).collect();
    order.sort_by_key(|&i| (m.tokenizer().encode(&texts[i].1).len(), i));
    let sorted: Vec<&str> = order.iter().map(|&i| texts[i].1.as_str()).collect();
    let vecs = m.embed(&sorted).ok()?;
    let mut out = vec![Vec::new(); texts.len()];
    for (k, v) in order.into_iter().zip(vecs) {
        out[k] = v;
    }
    Some(out)
}

impl MiniLmMeaning {
    /// The unit vector of `noun`, embedded once.
    fn query(&self, noun: &str) -> Option<Vec<f32>> {
        if let Some(v) = self.queries.lock().ok().and_then(|q| q.get(noun).cloned()) {
            return Some(v);
        }
        let model = self.model.as_ref().ok()?;
        let v = model.embed(&[noun]).ok()?.pop()?;
        if let Ok(mut q) = self.queries.lock() {
            q.insert(noun.to_string(), v.clone());
        }
        Some(v)
    }
}

impl Meaning for MiniLmMeaning {
    fn scores(&self, noun: &str, among: &[&'static Category]) -> Option<Vec<f32>> {
        if self.vectors.is_empty() {
            return None;
        }
        let q = self.query(noun)?;
        Some(
            among
                .iter()
                .map(|c| {
                    self.vectors.get(c.name).map_or(0.0, |vs| vs.iter().map(|v| dot(&q, v)).fold(f32::MIN, f32::max))
                })
                .collect(),
        )
    }

    fn senses(&self, noun: &str, among: &[&'static Category]) -> Option<Vec<f32>> {
        if self.vectors.is_empty() {
            return None;
        }
        let q = self.query(noun)?;
        // The last text of each category is "name: description" (`texts_of`).
        Some(
            among
                .iter()
                .map(|c| self.vectors.get(c.name).and_then(|vs| vs.last()).map_or(0.0, |v| dot(&q, v)))
                .collect(),
        )
    }

    fn word_similarity(&self, word: &str, other: &str) -> Option<f32> {
        let model = self.model.as_ref().ok()?;
        // [CLS], the word, [SEP]: a word of the model's vocabulary, not a misspelling.
        if model.tokenizer().encode(word).len() != 3 {
            return None;
        }
        Some(dot(&self.query(word)?, &self.query(other)?))
    }

    fn abstractness(&self, noun: &str) -> Option<f32> {
        let q = self.query(noun)?;
        self.vectors.get(ABSTRACT_KEY).map(|vs| vs.iter().map(|v| dot(&q, v)).fold(f32::MIN, f32::max))
    }
}

fn dot(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// A key for the cached vectors: the model's config and every text, in order.
fn cache_key(dir: &Path, texts: &[(&'static str, String)]) -> String {
    let mut h = Sha256::new();
    h.update(std::fs::read(dir.join("config.json")).unwrap_or_default());
    if let Ok(m) = std::fs::metadata(dir.join("model.safetensors")) {
        h.update(m.len().to_le_bytes());
    }
    for (n, t) in texts {
        h.update(n.as_bytes());
        h.update([0]);
        h.update(t.as_bytes());
        h.update([1]);
    }
    let d = h.finalize();
    d.iter().take(8).map(|b| format!("{b:02x}")).collect()
}

fn read_cache(file: &Path, rows: usize) -> Option<Vec<Vec<f32>>> {
    let bytes = std::fs::read(file).ok()?;
    let dim = sw_forge::embed::DIM;
    if bytes.len() != rows * dim * 4 {
        return None;
    }
    Some(
        bytes
            .chunks_exact(dim * 4)
            .map(|row| row.chunks_exact(4).map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect())
            .collect(),
    )
}

/// Best effort: a cache that cannot be written is computed again next time.
fn write_cache(file: &Path, rows: &[Vec<f32>]) {
    let Some(dir) = file.parent() else { return };
    if std::fs::create_dir_all(dir).is_err() {
        return;
    }
    let bytes: Vec<u8> = rows.iter().flat_map(|r| r.iter().flat_map(|v| v.to_le_bytes())).collect();
    let tmp: PathBuf =
        dir.join(format!(".{}.tmp{}", file.file_name().and_then(|n| n.to_str()).unwrap_or("v"), std::process::id()));
    if std::fs::write(&tmp, bytes).is_ok() && std::fs::rename(&tmp, file).is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
}

/// The noun of a phrase, in two parts: the words before "of" (the head phrase: "tin" of "a
/// tin of beans") and those after it (the of-complement: "beans"), each without counts,
/// colours and size words. Both stop at a measure — a number or number word after the noun
/// has begun ("a TV stand 250 cm wide", "a rug two metres long") — and the complement at a
/// second "of": a measure or a complement is said *of* the thing, never part of its name.
pub fn phrase_parts(phrase: &str) -> (Vec<String>, Vec<String>) {
    let keep = |w: &String| {
        sw_planner::vocab::color(w).is_none()
            && sw_planner::vocab::size_word(w).is_none()
            && sw_planner::vocab::number_word(w).is_none()
    };
    let (mut head, mut complement) = (Vec::new(), Vec::new());
    let mut in_complement = false;
    for token in phrase.split(|c: char| !(c.is_alphanumeric() || c == '\'')).filter(|t| !t.is_empty()) {
        let token = token.to_lowercase();
        let measure =
            token.starts_with(|c: char| c.is_ascii_digit()) || sw_planner::vocab::number_word(&token).is_some();
        if measure && (in_complement || !head.is_empty()) {
            break;
        }
        if token == "of" {
            if in_complement {
                break;
            }
            in_complement = !head.is_empty();
            continue;
        }
        let part = if in_complement { &mut complement } else { &mut head };
        part.extend(noun_words(&token).into_iter().filter(keep));
    }
    (head, complement)
}

/// The phrase's noun as one string for the model: "bag of feed", "tv stand".
fn phrase_text(head: &[String], complement: &[String]) -> String {
    if complement.is_empty() { head.join(" ") } else { format!("{} of {}", head.join(" "), complement.join(" ")) }
}

/// The head nouns of a category's names ("knife" of "chef's knife").
fn name_heads(cat: &Category) -> Vec<String> {
    let mut h: Vec<String> = names_of(cat).into_iter().filter_map(|n| n.last().cloned()).collect();
    h.sort();
    h.dedup();
    h
}

/// Levenshtein distance of two words (for the planner's typo tolerance).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for j in 0..b.len() {
            let cur = row[j + 1];
            row[j + 1] = if ca == b[j] { prev } else { 1 + prev.min(row[j]).min(row[j + 1]) };
            prev = cur;
        }
    }
    row[b.len()]
}

/// Whether `word` is one of `heads`, allowing the planner's typo tolerance.
fn is_head_of(word: &str, heads: &[String]) -> bool {
    let limit = match word.chars().count() {
        0..=4 => 0,
        5..=7 => 1,
        _ => 2,
    };
    heads.iter().any(|h| h == word || edit_distance(word, h) <= limit)
}

/// Why the planner's reading of `words` as `cat` is not that thing, if it is not: the
/// phrase's head is another word ("a bottle opener" read as a bottle), or the head is a
/// real word the planner took for a misspelling of one of its names ("trailer" for
/// "trainer"). A modifier the planner did not model leaves its reading standing: measured
/// on the scene corpus, weighing such modifiers by meaning turned "a hexagonal table", "a
/// tomato plant" and "coloured blocks" into proxies far more often than it caught another
/// thing, and the catalog now names the things it caught.
fn misreading(words: &[String], cat: &'static Category, meaning: &dyn Meaning) -> Option<String> {
    let last = words.last()?;
    let heads = name_heads(cat);
    let modifier_named = words[..words.len() - 1].iter().any(|w| heads.contains(w));
    if modifier_named && !is_head_of(last, &heads) {
        return Some(format!("its head noun is '{last}'"));
    }
    if !heads.contains(last) && is_head_of(last, &heads) {
        let near = heads.iter().min_by_key(|h| edit_distance(last, h))?;
        if meaning.word_similarity(last, near).is_some_and(|s| s < TYPO_SENSE_MIN) {
            return Some(format!("'{last}' is a word of its own, not a misspelling of '{near}'"));
        }
    }
    None
}
/// Groups the planner read as a category they are not ([`misreading`]): each becomes an
/// unknown noun for [`resolve_plan`], the planner's line for it is withdrawn and the
/// report says why. Also notes every group read through another name of its category
/// ("a handsaw" made as the catalog's hand saw), so that no reading is silent.
pub fn check_readings(plan: &mut ScenePlan, meaning: &dyn Meaning) -> Vec<Warning> {
    let mut warnings = Vec::new();
    let on_something: Vec<String> = plan
        .relations
        .iter()
        .filter(|r| matches!(r.kind, sw_plan::RelationKind::On { .. }))
        .map(|r| r.subject.clone())
        .collect();
    for group in plan.objects.iter_mut().filter(|o| o.proxy.is_none()) {
        let Some(cat) = sw_catalog::find(&group.category) else { continue };
        let (head, complement) = phrase_parts(&group.phrase);
        if head.is_empty() {
            continue;
        }
        // The planner may have read the head phrase ("a tin of beans" as a tin) or its
        // complement ("a bottle of water" as a water bottle): either reading stands.
        let readings = [&head, &complement];
        let standing = readings.iter().find(|w| !w.is_empty() && misreading(w, cat, meaning).is_none());
        if let (None, Some(why)) = (standing, misreading(&head, cat, meaning)) {
            let label = phrase_text(&head, &complement);
            warnings.push(Warning::new(
                Stage::Forge,
                "noun_reread",
                format!("'{label}' is not a kind of {} ({why}); read as a noun the catalog lacks", cat.display),
            ));
            let names = [cat.display.to_string(), cat.name.to_string(), cat.name.replace('_', " ")];
            plan.understanding.approximated.retain(|a| !(group.phrase.contains(&a.text) && names.contains(&a.became)));
            let resting = on_something.contains(&group.id);
            group.proxy = Some(sw_planner::vocab::proxy(&label, resting, &group.size.words, &group.size.explicit));
            group.category = "proxy".to_string();
            continue;
        }
        let said = phrase_text(&head, &complement);
        let own = [cat.display.to_lowercase(), cat.name.replace('_', " ")];
        let names = [cat.display.to_string(), cat.name.to_string(), cat.name.replace('_', " ")];
        // One line per reading: the planner may have said it already, of a word of the phrase.
        let said_already = plan
            .understanding
            .approximated
            .iter()
            .any(|a| a.text == group.phrase || (group.phrase.contains(&a.text) && names.contains(&a.became)));
        if !own.contains(&said) && !said_already {
            plan.understanding.approximated.push(Approximation {
                text: group.phrase.clone(),
                became: cat.display.to_string(),
                reason: format!("'{said}' is read as the catalog's {} (one of its names)", cat.display),
            });
        }
    }
    warnings
}

/// The shared matcher, loaded on its first question: a prompt whose every noun the
/// catalog knows never loads the model.
struct Lazy;

impl Meaning for Lazy {
    fn scores(&self, noun: &str, among: &[&'static Category]) -> Option<Vec<f32>> {
        MiniLmMeaning::shared().scores(noun, among)
    }
    fn senses(&self, noun: &str, among: &[&'static Category]) -> Option<Vec<f32>> {
        MiniLmMeaning::shared().senses(noun, among)
    }
    fn word_similarity(&self, word: &str, other: &str) -> Option<f32> {
        MiniLmMeaning::shared().word_similarity(word, other)
    }
    fn abstractness(&self, noun: &str) -> Option<f32> {
        MiniLmMeaning::shared().abstractness(noun)
    }
}

/// Checks how the planner read every group ([`check_readings`]), then resolves the
/// plan's unknown nouns with the shared matcher when there are any; says when matching
/// by meaning is off.
pub(crate) fn resolve_unknown_nouns(plan: &mut ScenePlan) -> Vec<Warning> {
    let mut warnings = check_readings(plan, &Lazy);
    if plan.objects.iter().all(|o| o.proxy.is_none()) {
        return warnings;
    }
    let meaning = MiniLmMeaning::shared();
    if let Some(why) = meaning.unavailable() {
        warnings.push(Warning::new(
            Stage::Forge,
            "meaning_unavailable",
            format!("unknown nouns were matched by their head words only, not by meaning: {why}"),
        ));
    }
    warnings.extend(resolve_plan(plan, meaning));
    warnings
}
