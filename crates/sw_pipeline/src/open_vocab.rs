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

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use sha2::{Digest, Sha256};
use sw_catalog::{Category, Kind};
use sw_plan::{Approximation, Dims, ProxyPlan, ScenePlan, Stage, Warning};

/// A sibling (a category of the same hypernym as the noun) is taken only this close in
/// meaning, cosine similarity of MiniLM vectors (tuned on bench/vocab/dev.tsv).
pub const SIBLING_MIN: f32 = 0.62;
/// The nearest category tells an unknown noun's kind of thing only this close.
pub const KIND_MIN: f32 = 0.58;
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
];

/// How a noun was resolved.
#[derive(Debug, Clone, PartialEq)]
pub enum Resolution {
    /// A kind of this category (its head names it, or a close sibling by meaning).
    Category { name: &'static str, score: Option<f32>, lexical: bool },
    /// A labelled proxy sized by the prior of this kind.
    Proxy { kind: Option<Kind>, nearest: Option<(&'static str, f32)> },
    /// Not a physical thing: left out.
    NotAThing { nearest: Option<(&'static str, f32)> },
}

/// The name under which the abstract nouns' vectors are kept.
const ABSTRACT_KEY: &str = "__abstract__";

/// The words of a noun phrase, lowercase and singular (the planner's reading).
fn noun_words(label: &str) -> Vec<String> {
    sw_planner::vocab::words(label)
}

/// Every name of a category as singular words: its display name, registry name and synonyms.
fn names_of(cat: &Category) -> Vec<Vec<String>> {
    let mut out = vec![noun_words(cat.display), noun_words(&cat.name.replace('_', " "))];
    out.extend(cat.synonyms.iter().map(|s| noun_words(s)));
    out.retain(|n| !n.is_empty());
    out
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

/// The candidates for a noun, most specific head (last two words, then last word) first.
fn candidates(words: &[String]) -> Vec<(&'static Category, Tie)> {
    let heads: Vec<Vec<String>> = (1..=words.len().min(2)).rev().map(|n| words[words.len() - n..].to_vec()).collect();
    for head in &heads {
        let mut out: Vec<(&'static Category, Tie)> = Vec::new();
        for cat in sw_catalog::categories() {
            let names = names_of(cat);
            if names.iter().any(|n| n == head) {
                out.push((cat, Tie::Named));
            } else if names.iter().any(|n| n.len() > head.len() && n.ends_with(head)) {
                out.push((cat, Tie::HeadNamed));
            } else if cat.is_a.iter().any(|h| &noun_words(h) == head) {
                out.push((cat, Tie::Sibling));
            }
        }
        if !out.is_empty() {
            return out;
        }
    }
    Vec::new()
}

/// Ranks categories by meaning.
pub trait Meaning {
    /// Cosine similarity of `noun` to each category in `among`, in the same order; `None`
    /// when matching by meaning is unavailable.
    fn scores(&self, noun: &str, among: &[&'static Category]) -> Option<Vec<f32>>;
    /// Cosine similarity of `noun` to the nearest of [`ABSTRACT`]; `None` when unavailable.
    fn abstractness(&self, noun: &str) -> Option<f32>;
}

/// Resolves one noun phrase (a proxy's label).
pub fn resolve_noun(label: &str, meaning: &dyn Meaning) -> Resolution {
    let words = noun_words(label);
    if words.is_empty() {
        return Resolution::Proxy { kind: None, nearest: None };
    }
    let cands = candidates(&words);
    let text = words.join(" ");
    if !cands.is_empty() {
        let cats: Vec<&'static Category> = cands.iter().map(|(c, _)| *c).collect();
        let scores = meaning.scores(&text, &cats);
        let best = |ids: &[usize]| -> Option<(usize, Option<f32>)> {
            match &scores {
                Some(s) => ids.iter().copied().max_by(|&a, &b| s[a].total_cmp(&s[b])).map(|i| (i, Some(s[i]))),
                None => ids.first().map(|&i| (i, None)),
            }
        };
        let tied = |t: &[Tie]| -> Vec<usize> { (0..cands.len()).filter(|&i| t.contains(&cands[i].1)).collect() };
        // Named alike: the nearest by meaning when it is close ("a deep fryer" → air fryer).
        if let Some((i, Some(s))) = best(&tied(&[Tie::Named, Tie::HeadNamed]))
            && s >= SIBLING_MIN
        {
            return Resolution::Category { name: cands[i].0.name, score: Some(s), lexical: cands[i].1 == Tie::Named };
        }
        // Named by the head itself: a kind of that category.
        if let Some((i, score)) = best(&tied(&[Tie::Named])) {
            return Resolution::Category { name: cands[i].0.name, score, lexical: true };
        }
        let all: Vec<usize> = (0..cands.len()).collect();
        if let Some((i, score)) = best(&all) {
            if score.is_some_and(|s| s >= SIBLING_MIN) {
                return Resolution::Category { name: cands[i].0.name, score, lexical: false };
            }
            // Kinds of one thing: the proxy takes their kind when they agree, or the
            // nearest one's when the model can say which.
            let kinds: Vec<Kind> = cands.iter().map(|(c, _)| c.kind).collect();
            let kind =
                if kinds.iter().all(|k| *k == kinds[0]) || score.is_some() { Some(cands[i].0.kind) } else { None };
            return Resolution::Proxy { kind, nearest: score.map(|s| (cands[i].0.name, s)) };
        }
    }
    let all: Vec<&'static Category> = sw_catalog::categories().iter().collect();
    match meaning.scores(&text, &all) {
        Some(s) => {
            let (i, score) = s.iter().copied().enumerate().max_by(|a, b| a.1.total_cmp(&b.1)).unwrap_or((0, 0.0));
            let nearest = all.get(i).map(|c| (c.name, score));
            if meaning.abstractness(&text).is_some_and(|a| a >= score + ABSTRACT_MARGIN) {
                Resolution::NotAThing { nearest }
            } else {
                let kind = (score >= KIND_MIN).then(|| all[i].kind);
                Resolution::Proxy { kind, nearest }
            }
        }
        None => Resolution::Proxy { kind: None, nearest: None },
    }
}

/// Applies [`resolve_noun`] to every labelled proxy of `plan`: a kind of a category
/// becomes that category (reported as approximated); a proxy takes its kind's size prior
/// (explicit sizes kept); a noun that names no thing is left out. Returns the warnings.
pub fn resolve_plan(plan: &mut ScenePlan, meaning: &dyn Meaning) -> Vec<Warning> {
    let mut warnings = Vec::new();
    let mut dropped: Vec<String> = Vec::new();
    for group in &mut plan.objects {
        let Some(proxy) = group.proxy.clone() else { continue };
        let res = resolve_noun(&proxy.label, meaning);
        let noun = proxy.label.clone();
        match res {
            Resolution::Category { name, score, lexical } => {
                let Some(cat) = sw_catalog::find(name) else { continue };
                let how = match (lexical, score) {
                    (true, _) => format!("a kind of {} (its head noun names it)", cat.display),
                    (false, Some(s)) => format!(
                        "the nearest {} by meaning (similarity {s:.2})",
                        cat.is_a.first().copied().unwrap_or("thing")
                    ),
                    (false, None) => format!("a kind of {}", cat.display),
                };
                plan.understanding.approximated.push(Approximation {
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
            Resolution::Proxy { kind, nearest } => {
                let near = nearest.map_or(String::new(), |(n, s)| format!("; nearest category {n} at {s:.2}"));
                match kind {
                    Some(k) => {
                        group.proxy = Some(sized_by_kind(&proxy, k, &group.size.explicit));
                        warnings.push(Warning::new(
                            Stage::Forge,
                            "noun_proxy",
                            format!("'{noun}' is not in the catalog: a labelled proxy sized as a {}{near}", k.name()),
                        ));
                    }
                    None => warnings.push(Warning::new(
                        Stage::Forge,
                        "noun_proxy",
                        format!("'{noun}' is not in the catalog and its kind is unknown: a labelled proxy sized as a {}{near}", proxy.prior),
                    )),
                }
            }
            Resolution::NotAThing { nearest } => {
                let near = nearest.map_or(String::new(), |(n, s)| format!(" (nearest category {n} at {s:.2})"));
                warnings.push(Warning::new(
                    Stage::Forge,
                    "not_a_thing",
                    format!("'{noun}' does not name an object the catalog or its kinds know{near}; left out"),
                ));
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

/// A proxy resized to the prior of `kind` (explicit dimensions kept).
fn sized_by_kind(p: &ProxyPlan, kind: Kind, explicit: &sw_plan::ExplicitSize) -> ProxyPlan {
    let prior = kind.prior();
    let mut s = prior.size;
    for (i, v) in [explicit.width, explicit.depth, explicit.height].into_iter().enumerate() {
        if let Some(v) = v.filter(|v| v.is_finite() && *v > 0.0) {
            s[i] = v;
        }
    }
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

/// The noun words of a group's phrase: without counts, colours and size words.
fn phrase_noun(phrase: &str) -> Vec<String> {
    noun_words(phrase)
        .into_iter()
        .filter(|w| {
            sw_planner::vocab::color(w).is_none()
                && sw_planner::vocab::size_word(w).is_none()
                && sw_planner::vocab::number_word(w).is_none()
        })
        .collect()
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

/// Groups the planner read by a word that is not the phrase's head noun ("a bottle
/// opener" read as a bottle, "a potato masher" as a potato): the thing named is not a kind
/// of that category, so the group becomes an unknown noun for [`resolve_plan`], and the
/// report says why. Also notes every group read through another name of its category
/// ("a handsaw" made as the catalog's hand saw), so that no reading is silent.
pub fn check_readings(plan: &mut ScenePlan) -> Vec<Warning> {
    let mut warnings = Vec::new();
    let on_something: Vec<String> = plan
        .relations
        .iter()
        .filter(|r| matches!(r.kind, sw_plan::RelationKind::On { .. }))
        .map(|r| r.subject.clone())
        .collect();
    for group in plan.objects.iter_mut().filter(|o| o.proxy.is_none()) {
        let Some(cat) = sw_catalog::find(&group.category) else { continue };
        let words = phrase_noun(&group.phrase);
        let Some(last) = words.last() else { continue };
        let heads = name_heads(cat);
        let modifier_named = words[..words.len() - 1].iter().any(|w| heads.contains(w));
        if modifier_named && !is_head_of(last, &heads) {
            let label = words.join(" ");
            warnings.push(Warning::new(
                Stage::Forge,
                "noun_reread",
                format!(
                    "'{label}' is not a kind of {} (its head noun is '{last}'); read as a noun the catalog lacks",
                    cat.display
                ),
            ));
            let resting = on_something.contains(&group.id);
            group.proxy = Some(sw_planner::vocab::proxy(&label, resting, &group.size.words, &group.size.explicit));
            group.category = "proxy".to_string();
            continue;
        }
        let said = words.join(" ");
        let own = [cat.display.to_lowercase(), cat.name.replace('_', " ")];
        if !own.contains(&said) && !plan.understanding.approximated.iter().any(|a| a.text == group.phrase) {
            plan.understanding.approximated.push(Approximation {
                text: group.phrase.clone(),
                became: cat.display.to_string(),
                reason: format!("'{said}' is read as the catalog's {} (one of its names)", cat.display),
            });
        }
    }
    warnings
}

/// Checks how the planner read every group ([`check_readings`]), then resolves the
/// plan's unknown nouns with the shared matcher when there are any; says when matching
/// by meaning is off.
pub(crate) fn resolve_unknown_nouns(plan: &mut ScenePlan) -> Vec<Warning> {
    let mut warnings = check_readings(plan);
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
