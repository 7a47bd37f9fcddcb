//! Reading an instruction: words → clauses (an action, the things it moves, how they relate
//! to a goal thing or place). Binding the noun phrases to bodies is `bind`'s.

use crate::TaskError;
use crate::vocab::{self, Action, EVERY, PRONOUNS, REGIONS, RELS, Region, Rel};

/// A noun phrase as written.
#[derive(Debug, Clone, PartialEq)]
pub struct NounPhrase {
    /// The words, lowercase, without the article.
    pub text: String,
    /// "all the cubes", "cubes": every instance that fits.
    pub every: bool,
    /// "the other cube", "another one": one not named by an earlier clause.
    pub other: bool,
}

/// One clause of an instruction.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Clause {
    pub action: Action,
    pub subjects: Vec<NounPhrase>,
    pub rel: Option<Rel>,
    pub target: Option<NounPhrase>,
    /// "to the left of the table": a part of the subject's (or the named) surface.
    pub region: Option<Region>,
    /// The side a relation names ("to the right of", "in front of", "behind"): beside the
    /// target on that side, or — when the target is what the thing stands on — that part
    /// of its surface.
    pub side: Option<Region>,
}

/// Characters that break a clause: punctuation, dashes and brackets ("… and a bowl — put
/// the cube in it", "Task: …", "(Panda) put …"). A hyphen inside a word does not.
pub(crate) fn breaks_clause(c: char) -> bool {
    matches!(c, ',' | '.' | ';' | ':' | '!' | '?' | '(' | ')' | '[' | ']' | '{' | '}' | '\u{2013}' | '\u{2014}' | '/')
}

/// Lowercase words and the punctuation that breaks clauses, as tokens (`,`).
pub(crate) fn tokens(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let push = |cur: &mut String, out: &mut Vec<String>| {
        if cur.is_empty() {
            return;
        }
        let w = std::mem::take(cur);
        // A dash standing alone ("table - put", "--") breaks the clause; a word keeps its
        // hyphens but not ones hanging at its ends.
        let trimmed = w.trim_matches('-');
        if trimmed.is_empty() {
            out.push(",".to_string());
        } else {
            out.push(trimmed.to_string());
        }
    };
    for c in text.chars() {
        if c.is_alphanumeric() || c == '\'' || c == '-' {
            cur.extend(c.to_lowercase());
        } else {
            push(&mut cur, &mut out);
            if breaks_clause(c) {
                out.push(",".to_string());
            }
        }
    }
    push(&mut cur, &mut out);
    out
}

/// The longest relation word sequence starting at `i`: (relation, length).
pub(crate) fn rel_at(t: &[String], i: usize) -> Option<(Rel, usize)> {
    let mut best: Option<(Rel, usize)> = None;
    for (words, rel) in RELS {
        let n = words.len();
        if i + n <= t.len() && t[i..i + n].iter().zip(words.iter()).all(|(a, b)| a == b) && best.is_none_or(|b| n > b.1)
        {
            best = Some((*rel, n));
        }
    }
    best
}

fn noun_phrase(words: &[String]) -> Option<NounPhrase> {
    let mut ws: Vec<&str> = words.iter().map(String::as_str).filter(|w| *w != ",").collect();
    let mut every = false;
    let mut other = false;
    while let Some(first) = ws.first() {
        if EVERY.contains(first) {
            every = true;
            ws.remove(0);
        } else if matches!(*first, "other" | "another" | "remaining" | "second") {
            other = true;
            ws.remove(0);
        } else if matches!(*first, "the" | "a" | "an" | "of" | "up" | "some" | "any") {
            ws.remove(0);
        } else {
            break;
        }
    }
    // Counts ("stack 2 red blocks", "the two cubes") say every one of them.
    let before = ws.len();
    ws.retain(|w| w.parse::<f64>().is_err() && !matches!(*w, "two" | "three" | "four" | "five" | "six" | "both"));
    if ws.len() < before {
        every = true;
    }
    // "pick the cube up": a trailing particle.
    while ws
        .last()
        .is_some_and(|w| matches!(*w, "up" | "away" | "over" | "down" | "please" | "carefully" | "too" | "also"))
    {
        ws.pop();
    }
    if ws.is_empty() {
        // "the other": one more of the kind named before.
        return other.then(|| NounPhrase { text: "one".into(), every: false, other });
    }
    if let Some(last) = ws.last() {
        let singular = sw_planner::vocab::words(last);
        if singular.first().is_some_and(|s| s != last) {
            every = true;
        }
    }
    Some(NounPhrase { text: ws.join(" "), every, other })
}

fn is_pronoun(np: &NounPhrase) -> bool {
    PRONOUNS.contains(&np.text.as_str()) && !np.other
}

/// A phrase that names its kind by reference: "the green one", "the other one", "the
/// other", "the big ones" — `one(s)` standing for the head noun of the thing named before
/// (`antecedent`). The phrase with that noun put in, or `None` when it is no such phrase
/// or nothing was named before.
fn resolve_one(np: &NounPhrase, antecedent: Option<&NounPhrase>) -> Option<NounPhrase> {
    let words: Vec<&str> = np.text.split(' ').collect();
    let last = *words.last()?;
    if !matches!(last, "one" | "ones") || (words.len() == 1 && !np.other) {
        return None;
    }
    let head = antecedent?.text.rsplit(' ').next()?.to_string();
    let mut text: Vec<String> = words[..words.len() - 1].iter().map(|w| (*w).to_string()).collect();
    text.push(head);
    Some(NounPhrase { text: text.join(" "), every: np.every || last == "ones", other: np.other })
}

/// The verb a word is in imperative position, typos of one letter forgiven ("pikc",
/// "plcae", "opne"): a known action, a switch verb, or an action the robot cannot do.
#[derive(Debug, Clone, Copy, PartialEq)]
enum VerbWord {
    Known(Action),
    /// "turn", "switch": on/off make it open/close.
    Switch,
    /// A verb for something the expert cannot do ("pour", "wipe").
    Unsupported,
}

fn verb_word(w: &str, next: Option<&str>) -> Option<VerbWord> {
    // "go" leads a wrapper ("go ahead and put", "go push the block") unless it goes somewhere.
    if w == "go" && !matches!(next, Some("to" | "towards" | "toward" | "back" | "over" | "near")) {
        return None;
    }
    if vocab::SWITCH_VERBS.contains(&w) {
        return Some(VerbWord::Switch);
    }
    if let Some((a, _)) = vocab::verb(w) {
        return Some(VerbWord::Known(a));
    }
    if vocab::UNSUPPORTED.contains(&w) || vocab::UNSUPPORTED.iter().any(|u| vocab::base_form_of(w, u)) {
        return Some(VerbWord::Unsupported);
    }
    None
}

/// A function word or verb one edit (or one swap of neighbours) from `w`, for words that
/// are no noun: "inot" → "into", "teh" → "the", "plcae" → "place".
fn fix_typo(w: &str, imperative_position: bool) -> Option<&'static str> {
    let n = w.chars().count();
    if n < 3 || w.chars().any(|c| !c.is_alphabetic()) {
        return None;
    }
    let known = |x: &str| {
        vocab::verb(x).is_some()
            || vocab::FUNCTION_WORDS.contains(&x)
            || vocab::SWITCH_VERBS.contains(&x)
            || vocab::UNSUPPORTED.contains(&x)
    };
    if known(w) {
        return None;
    }
    let mut cands: Vec<&'static str> = vocab::FUNCTION_WORDS.iter().copied().filter(|f| f.len() >= 3).collect();
    if imperative_position && n >= 4 {
        cands.extend(vocab::VERBS.iter().map(|(v, _)| *v).filter(|v| v.len() >= 4));
    }
    let hits: Vec<&'static str> = cands.into_iter().filter(|c| vocab::near_miss(w, c)).collect();
    // A noun the planner knows is never "fixed" into a function word.
    let is_noun = !matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Unknown)
        && sw_planner::vocab::words(w).first().is_some_and(|s| s == w || n > 4);
    match hits.as_slice() {
        [one] if !is_noun || imperative_position => Some(one),
        _ => None,
    }
}

/// Where each part of a clause's argument words begins: the goal relation, if any.
struct Args {
    subjects: Vec<NounPhrase>,
    rel: Option<Rel>,
    side: Option<Region>,
    region: Option<Region>,
    /// The goal thing's words (empty with a bare "put it inside": elided).
    target_words: Option<Vec<String>>,
    /// "pull the drawer open": the state the verb leaves it in.
    result: Option<Action>,
}

/// The first word of `t[from..]` that begins a goal phrase with a relation (`(i, rel, len)`).
fn next_goal(t: &[String], from: usize) -> Option<(usize, Rel, usize)> {
    (from..t.len()).find_map(|i| rel_at(t, i).map(|(r, n)| (i, r, n)))
}

fn side_of(words: &[String]) -> Option<Region> {
    words.iter().find_map(|w| match w.as_str() {
        "left" => Some(Region::Left),
        "right" => Some(Region::Right),
        "front" => Some(Region::Front),
        "behind" | "back" => Some(Region::Back),
        _ => None,
    })
}

/// A phrase that is only a region word ("the left", "the right side"): a place, not a thing.
fn region_only(words: &[String]) -> Option<Region> {
    let w: Vec<&str> = words.iter().map(String::as_str).filter(|w| *w != "the").collect();
    let (first, rest) = w.split_first()?;
    let r = REGIONS.iter().find(|(n, _)| n == first)?.1;
    (rest.is_empty() || (rest.len() == 1 && matches!(rest[0], "side" | "edge" | "end" | "half" | "part" | "hand")))
        .then_some(r)
}

/// The argument words of one clause (after its verb): the things, modifiers dropped or kept
/// as adjectives, and the goal phrase. `goal_frame`: the verb takes a goal ("put" does,
/// "pick up" and "open" do not, so their prepositions modify the thing).
fn arguments(action: Action, t: &[String], clause: &str) -> Result<Args, TaskError> {
    let goal_frame = matches!(action, Action::Place | Action::Stack | Action::Push | Action::Navigate);
    let mut np: Vec<String> = Vec::new();
    let mut adjectives: Vec<String> = Vec::new();
    let mut args = Args { subjects: Vec::new(), rel: None, side: None, region: None, target_words: None, result: None };
    let mut i = 0;
    // A goal for a verb without a goal frame: only "to", "into", "onto" ("take it to the bin").
    let moves_to =
        |r: Rel, w: &str| matches!(r, Rel::Inside | Rel::On | Rel::To) && matches!(w, "to" | "into" | "onto");
    while i < t.len() {
        let w = t[i].as_str();
        if vocab::UNDER.contains(&w) {
            return Err(TaskError::Words(format!(
                "\"{}\": putting a thing {w} another is not a goal the robot can be judged on (in, on, next to, left of, behind ... are)",
                clause
            )));
        }
        // A source or a locating modifier: "from the counter", "between the plate and the
        // ramekin", "out of the drawer" — skipped up to the goal phrase.
        if matches!(
            w,
            "from"
                | "off"
                | "between"
                | "among"
                | "with"
                | "using"
                | "lying"
                | "sitting"
                | "located"
                | "that"
                | "which"
        ) || (w == "out" && t.get(i + 1).is_some_and(|x| x == "of"))
        {
            i = match next_goal(t, i + 1) {
                Some((j, r, _)) if goal_frame || moves_to(r, &t[j]) => j,
                _ => t.len(),
            };
            continue;
        }
        if let Some((r, n)) = rel_at(t, i) {
            let rest = &t[i + n..];
            // "push the drawer in", "slide it back in": a particle that ends the clause is
            // where the part goes — shut — not a relation missing its thing.
            if rest.is_empty() && n == 1 && w == "in" && matches!(action, Action::Push | Action::Place) {
                args.result = Some(Action::Close);
                break;
            }
            let later_goal = next_goal(t, i + n).is_some();
            // "the cube on the left": a place word alone after "on"/"at"/"in" modifies the thing.
            if let Some(region) = region_only(&t[i + n..next_goal(t, i + n).map_or(t.len(), |g| g.0)])
                && matches!(w, "on" | "in" | "at")
                && (later_goal || !goal_frame)
            {
                adjectives.push(REGIONS.iter().find(|(_, r)| *r == region).map_or("", |x| x.0).to_string());
                i = next_goal(t, i + n).map_or(t.len(), |g| g.0);
                continue;
            }
            if !goal_frame && !moves_to(r, w) {
                // "the bowl on the stove" after "pick up": where the thing is, not where it goes.
                i = next_goal(t, i + n).map_or(t.len(), |g| g.0);
                continue;
            }
            args.rel = Some(r);
            args.side = if r == Rel::Near { side_of(&t[i..i + n]) } else { None };
            let mut target: Vec<String> = rest.to_vec();
            if matches!(r, Rel::To | Rel::Inside | Rel::Near) && args.side.is_none() {
                // "to the left (of the table)", "into the corner", "to the centre of the table".
                if let Some(region) = region_only(&target) {
                    args.region = Some(region);
                    target.clear();
                } else if let Some(k) = target.iter().position(|x| x == "of")
                    && let Some(region) = region_only(&target[..k])
                {
                    if matches!(region, Region::Centre | Region::Corner) || target[..k].len() > 2 || r != Rel::To {
                        args.region = Some(region);
                    } else {
                        // "to the front of the stove": beside it on that side.
                        args.rel = Some(Rel::Near);
                        args.side = Some(region);
                    }
                    target.drain(..=k);
                }
            }
            if args.region.is_some() && target.is_empty() {
                args.target_words = None;
            } else {
                args.target_words = Some(target);
            }
            break;
        }
        np.push(t[i].clone());
        i += 1;
    }
    // "pull the drawer open", "place the can upright": a result after the thing.
    while let Some(last) = np.last().map(String::as_str) {
        match last {
            "open" => args.result = Some(Action::Open),
            // "slide the drawer out": a moving verb's particle, the part left open.
            "out" if matches!(action, Action::Push | Action::Place) => args.result = Some(Action::Open),
            // "set it down on the tray", "pick the cube up": the verb's particle after its
            // thing.
            "down" | "up" | "away" | "back" if np.len() > 1 => {}
            "shut" | "closed" => args.result = Some(Action::Close),
            w if vocab::RESULTS.contains(&w) => {
                return Err(TaskError::Words(format!(
                    "\"{clause}\": leaving a thing {w} is not a goal the robot can be judged on"
                )));
            }
            _ => break,
        }
        np.pop();
    }
    // "both the soup and the sauce": one phrase per thing.
    let mut parts: Vec<Vec<String>> = vec![Vec::new()];
    for (k, w) in np.iter().enumerate() {
        let colours_joined = w == "and"
            && k > 0
            && sw_planner::vocab::color(&np[k - 1]).is_some()
            && np.get(k + 1).is_some_and(|n| sw_planner::vocab::color(n).is_some());
        if (w == "and" || w == "&") && !colours_joined {
            parts.push(Vec::new());
        } else if let Some(p) = parts.last_mut() {
            p.push(w.clone());
        }
    }
    parts.retain(|p| !p.is_empty());
    if parts.len() > 1 && matches!(parts[0].first().map(String::as_str), Some("both" | "either")) {
        parts[0].remove(0);
    }
    for mut p in parts {
        // The place adjective before the head ("the cube on the left" → "left cube").
        if !adjectives.is_empty() {
            let at = p.iter().position(|w| !matches!(w.as_str(), "the" | "a" | "an")).unwrap_or(0);
            for a in adjectives.iter().rev() {
                p.insert(at, a.clone());
            }
        }
        args.subjects.extend(noun_phrase(&p));
    }
    Ok(args)
}

/// Reads an instruction into clauses by its phrase structure: each clause an imperative
/// verb (with its particle: "pick up", "turn on"), the things it acts on (noun phrases,
/// coordinated with "and"; modifiers such as "from the counter" or "between the plate and
/// the ramekin" dropped, "on the left" kept as an adjective) and a goal phrase (a relation
/// and its thing). Wrappers ("please", "can you", "the robot should") go; typos of one
/// letter in verbs and function words are forgiven. A clause without a verb takes the one
/// before ("put the red cube in the bowl and the green one on the plate"); pronouns and an
/// elided goal ("put the bowl inside") take the thing last named. A verb the robot cannot
/// do, or a goal it cannot be judged on, is refused with one line naming the words.
pub(crate) fn read(instruction: &str) -> Result<Vec<Clause>, TaskError> {
    let raw = tokens(instruction);
    // Typos: in the position of a verb (a clause's first word) a verb, elsewhere a function word.
    let mut t: Vec<String> = Vec::with_capacity(raw.len());
    for (i, w) in raw.iter().enumerate() {
        let lead =
            i == 0 || matches!(t.last().map(String::as_str), Some("," | "and" | "then" | "to" | "please" | "you"));
        t.push(fix_typo(w, lead).map_or_else(|| w.clone(), str::to_string));
    }
    let is_verb_at = |t: &[String], i: usize| verb_word(&t[i], t.get(i + 1).map(String::as_str)).is_some();
    let any_known_verb = (0..t.len()).any(|i| {
        matches!(verb_word(&t[i], t.get(i + 1).map(String::as_str)), Some(VerbWord::Known(_) | VerbWord::Switch))
    });
    // Hard breaks ("then", "afterwards", "next" but not "next to") and soft ones ("and", ",").
    let mut hard: Vec<Vec<Vec<String>>> = vec![vec![Vec::new()]];
    for (i, w) in t.iter().enumerate() {
        let next = t.get(i + 1).map(String::as_str);
        let is_hard = matches!(w.as_str(), "then" | "afterwards" | "finally" | "after" | "before" | "so" | "while")
            || (w == "next" && next != Some("to"));
        if is_hard {
            hard.push(vec![Vec::new()]);
        } else if w == "," || w == "and" {
            if let Some(h) = hard.last_mut() {
                h.push(vec![w.clone()]);
            }
        } else if let Some(p) = hard.last_mut().and_then(|h| h.last_mut()) {
            p.push(w.clone());
        }
    }
    // Soft parts join into clauses: a part that starts with a verb starts one; so does one
    // after a clause that is complete (has its goal, or needs none); otherwise it is
    // another thing of the same clause ("both the soup and the sauce in the basket").
    let mut clauses_words: Vec<Vec<String>> = Vec::new();
    for h in hard {
        let mut cur: Vec<String> = Vec::new();
        for part in h {
            let (joint, body): (Option<&String>, &[String]) = match part.first() {
                Some(j) if j == "," || j == "and" => (Some(j), &part[1..]),
                _ => (None, &part[..]),
            };
            let body: Vec<String> = body.to_vec();
            if body.is_empty() {
                continue;
            }
            let starts_verb = {
                let k = body.iter().position(|w| !vocab::WRAPPERS.contains(&w.as_str())).unwrap_or(0);
                is_verb_at(&body, k)
            };
            let cur_has_goal = next_goal(&cur, 0).is_some();
            let cur_action =
                cur.iter().enumerate().find_map(|(i, w)| match verb_word(w, cur.get(i + 1).map(String::as_str)) {
                    Some(VerbWord::Known(a)) => Some(a),
                    Some(VerbWord::Switch) => Some(Action::Open),
                    _ => None,
                });
            let between_open =
                cur.iter().rposition(|w| w == "between").is_some_and(|b| !cur[b..].iter().any(|w| w == "and"));
            let colours = joint.is_some_and(|j| j == "and")
                && cur.last().is_some_and(|l| sw_planner::vocab::color(l).is_some())
                && body.first().is_some_and(|f| sw_planner::vocab::color(f).is_some());
            let complete = cur_has_goal || matches!(cur_action, Some(Action::Lift | Action::Open | Action::Close));
            if cur.is_empty() {
                cur = body;
            } else if !starts_verb && (between_open || colours || (!complete && cur_action.is_some())) {
                cur.push("and".into());
                cur.extend(body);
            } else if !starts_verb && cur_action.is_none() && any_known_verb {
                // Things named before any verb ("the mug and the cup, put them in the bin").
                cur.push("and".into());
                cur.extend(body);
            } else {
                clauses_words.push(std::mem::take(&mut cur));
                cur = body;
            }
        }
        if !cur.is_empty() {
            clauses_words.push(cur);
        }
    }
    let mut out: Vec<Clause> = Vec::new();
    let mut pending: Vec<NounPhrase> = Vec::new();
    let mut last_action: Option<Action> = None;
    let mut last_subjects: Vec<NounPhrase> = Vec::new();
    // Every thing named, in order (pronouns and elided goals look back through it).
    let mut named: Vec<NounPhrase> = Vec::new();
    for (ci, seg) in clauses_words.iter().enumerate() {
        let clause = seg.join(" ");
        // The verb: the first word after the wrappers that is one.
        let verb_at = (0..seg.len()).find(|&i| is_verb_at(seg, i));
        let lead: Vec<&String> =
            seg[..verb_at.unwrap_or(0)].iter().filter(|w| !vocab::WRAPPERS.contains(&w.as_str())).collect();
        let (mut action, mut from) = (None, 0);
        if let Some(v) = verb_at {
            from = v + 1;
            match verb_word(&seg[v], seg.get(v + 1).map(String::as_str)) {
                Some(VerbWord::Known(a)) => action = Some(a),
                Some(VerbWord::Switch) => {
                    // "turn on the stove", "turn the stove off".
                    let pos = seg[v + 1..].iter().position(|w| matches!(w.as_str(), "on" | "off"));
                    match pos.map(|p| (p, seg[v + 1 + p].as_str())) {
                        Some((p, dir)) if p == 0 || v + 2 + p == seg.len() => {
                            action = Some(if dir == "on" { Action::Open } else { Action::Close });
                            if p == 0 {
                                from += 1;
                            }
                        }
                        _ => {
                            return Err(TaskError::Words(format!(
                                "\"{clause}\": \"{}\" without on or off asks for a rotation the robot cannot be judged on (turn on/off, open and close are)",
                                seg[v]
                            )));
                        }
                    }
                }
                Some(VerbWord::Unsupported) | None => {
                    return Err(TaskError::Words(format!(
                        "\"{clause}\": \"{}\" is not something the robot can do (it can put, place, stack, push, pick up, lift, open, close, turn on/off, go to)",
                        seg[v]
                    )));
                }
            }
            if !lead.is_empty() {
                pending.extend(noun_phrase(&lead.iter().map(|w| (*w).clone()).collect::<Vec<_>>()));
            }
        } else if last_action.is_none() && !any_known_verb {
            let first = seg.iter().find(|w| !vocab::WRAPPERS.contains(&w.as_str())).unwrap_or(&seg[0]);
            return Err(TaskError::Words(format!(
                "\"{clause}\": \"{first}\" is not something the robot can do (it can put, place, stack, push, pick up, lift, open, close, turn on/off, go to)"
            )));
        }
        // Particles of the verb ("pick up", "put down", "put away", "take out").
        while seg.get(from).is_some_and(|w| matches!(w.as_str(), "up" | "down" | "away" | "out" | "back"))
            && verb_at.is_some()
        {
            from += 1;
        }
        let Some(mut act) = action.or(last_action) else {
            // Words before any verb: things for the next clause ("Robot," is a wrapper).
            if !seg.iter().all(|w| vocab::WRAPPERS.contains(&w.as_str())) {
                pending.extend(noun_phrase(seg));
            }
            continue;
        };
        // "push and close the drawer": verbs joined by "and" share the thing after the
        // last; a verb with nothing after it before another verb's clause is its manner.
        if verb_at.is_some()
            && seg[from..].iter().all(|w| w == "and" || vocab::WRAPPERS.contains(&w.as_str()))
            && clauses_words.get(ci + 1).is_some_and(|next| (0..next.len()).any(|i| is_verb_at(next, i)))
        {
            continue;
        }
        let args = arguments(act, &seg[from..], &clause)?;
        if let Some(r) = args.result {
            act = r;
        }
        let antecedent = last_subjects.first().or(pending.first()).cloned();
        let mut subjects: Vec<NounPhrase> = std::mem::take(&mut pending);
        for np in args.subjects {
            let np = resolve_one(&np, antecedent.as_ref()).unwrap_or(np);
            if is_pronoun(&np) {
                // Opening and closing act on the thing last named; moving, on the things
                // moved before ("pick up the cube and put it in the bowl").
                if matches!(act, Action::Open | Action::Close) {
                    subjects.extend(named.last().cloned());
                } else {
                    subjects.extend(last_subjects.iter().cloned());
                }
            } else {
                subjects.push(np);
            }
        }
        if subjects.is_empty() && verb_at.is_none() {
            subjects.extend(last_subjects.iter().cloned());
        }
        let (mut rel, mut region, mut side) = (args.rel, args.region, args.side);
        // The goal thing; a pronoun or nothing after the relation ("on it", "put the bowl
        // inside") is the thing last named that is not moved here.
        let elided = |named: &[NounPhrase], subjects: &[NounPhrase]| {
            named.iter().rev().find(|n| !subjects.iter().any(|s| s.text == n.text)).cloned()
        };
        let mut target = match &args.target_words {
            Some(w) => match noun_phrase(w) {
                Some(np) if is_pronoun(&np) => elided(&named, &subjects),
                Some(np) => Some(resolve_one(&np, subjects.first().or(last_subjects.first())).unwrap_or(np)),
                None => elided(&named, &subjects),
            },
            None => None,
        };
        if rel.is_some() && region.is_none() && target.is_none() {
            return Err(TaskError::Words(format!(
                "\"{clause}\" says where but not what: nothing follows the last word"
            )));
        }
        // "…, then the green one too": no verb and no place — the clause before's, again.
        if verb_at.is_none()
            && rel.is_none()
            && region.is_none()
            && let Some(prev) = out.last()
        {
            (rel, target, region, side) = (prev.rel, prev.target.clone(), prev.region, prev.side);
        }
        if act == Action::Navigate {
            if target.is_none() && subjects.is_empty() {
                return Err(TaskError::Words(format!("\"{clause}\" names no place to go")));
            }
        } else if subjects.is_empty() {
            return Err(TaskError::Words(format!("\"{clause}\" says what to do but not to what")));
        } else if matches!(act, Action::Place | Action::Push) && rel.is_none() && region.is_none() {
            return Err(TaskError::Words(format!("\"{clause}\" says what to move but not where to")));
        }
        if act == Action::Lift && rel.is_some() {
            // "take the cube to the bin": a lift with a goal places it.
            act = Action::Place;
        }
        last_action = Some(act);
        last_subjects.clone_from(&subjects);
        named.extend(subjects.iter().cloned());
        named.extend(target.iter().cloned());
        // "pick up the cube and put it in the bowl": the lift is part of the placing.
        if let Some(prev) = out.last()
            && prev.action == Action::Lift
            && prev.rel.is_none()
            && prev.subjects == subjects
        {
            out.pop();
        }
        out.push(Clause { action: act, subjects, rel, target, region, side });
    }
    if out.is_empty() {
        return Err(TaskError::Words(format!(
            "\"{}\" asks for nothing the robot can do (put, place, stack, push, lift, open, close, go to ...)",
            instruction.trim()
        )));
    }
    Ok(out)
}

/// Where a task clause starts in a scene prompt ("a Panda that puts the mug in the sink",
/// "a UR5e sorting the cubes into the bins", "... Put the red cube in the bowl"): the
/// token index of its verb, or `None` when the prompt asks for no task.
pub(crate) fn task_start(t: &[String]) -> Option<usize> {
    for i in 0..t.len() {
        let switch = vocab::SWITCH_VERBS.contains(&t[i].as_str())
            && t[i + 1..].iter().take(6).any(|w| matches!(w.as_str(), "on" | "off"));
        let form = match vocab::verb(&t[i]) {
            Some((_, form)) => form,
            None if switch => vocab::Form::Base,
            None => continue,
        };
        // The words before it, past any wrappers ("please", "can you", "the robot should").
        let mut k = i;
        while k > 0 && vocab::WRAPPERS.contains(&t[k - 1].as_str()) && !matches!(t[k - 1].as_str(), "to" | "and") {
            k -= 1;
        }
        let prev = if i > 0 { Some(t[i - 1].as_str()) } else { None };
        let before_wrappers = if k > 0 { Some(t[k - 1].as_str()) } else { None };
        let relative = matches!(prev, Some("that" | "which" | "who" | "to"));
        let imperative = form == vocab::Form::Base && matches!(before_wrappers, None | Some(","));
        // "a UR5e on a table sorting the cubes …": a robot named before the verb does it.
        let robot_before =
            t[..i].iter().any(|w| matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Robot { .. }));
        let after_robot = matches!(form, vocab::Form::Gerund | vocab::Form::Third) && robot_before;
        if relative || imperative || after_robot {
            // It must read as a task: something to move or open, or somewhere to go.
            let rest = &t[i + 1..];
            let has_object = rest.iter().any(|w| {
                matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Category(_))
                    || vocab::PARTS.contains(&w.as_str())
            });
            if has_object {
                return Some(k);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn subjects(c: &Clause) -> Vec<(&str, bool)> {
        c.subjects.iter().map(|s| (s.text.as_str(), s.other)).collect()
    }

    #[test]
    fn dashes_colons_and_brackets_break_clauses_but_hyphens_do_not() {
        assert_eq!(tokens("a bowl — put it"), ["a", "bowl", ",", "put", "it"]);
        assert_eq!(tokens("a bowl – put it"), ["a", "bowl", ",", "put", "it"]);
        assert_eq!(tokens("a bowl - put it"), ["a", "bowl", ",", "put", "it"]);
        assert_eq!(tokens("a bowl -- put it"), ["a", "bowl", ",", "put", "it"]);
        assert_eq!(tokens("Goal: put it"), ["goal", ",", "put", "it"]);
        assert_eq!(tokens("(Panda) put it"), [",", "panda", ",", "put", "it"]);
        assert_eq!(tokens("a T-shaped block"), ["a", "t-shaped", "block"]);
    }

    #[test]
    fn refusals_name_the_words_and_wrappers_go() {
        for (text, word) in [
            ("pour the water into the glass", "pour"),
            ("turn the dial", "turn"),
            ("put the pan under the shelf", "under"),
            ("place the can upright", "upright"),
            ("put the cube", "put the cube"),
        ] {
            let e = read(text).map(|c| c.len()).unwrap_err().to_string();
            assert!(e.contains(word), "{text}: {e}");
        }
        let c = read("Robot, could you please pick up teh cube and put it inot the bowl?")
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(c.len(), 1);
        assert_eq!((c[0].action, c[0].rel), (Action::Place, Some(Rel::Inside)));
        assert_eq!(subjects(&c[0]), [("cube", false)]);
        // "and" between things of one goal, between two goals, and inside a colour.
        assert_eq!(read("put both the mug and the cup in the bin").map(|c| c[0].subjects.len()).ok(), Some(2));
        assert_eq!(read("put the mug in the bin and the cup on the tray").map(|c| c.len()).ok(), Some(2));
        let c = read("put the red and white mug on the tray").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(subjects(&c[0]), [("red and white mug", false)]);
    }

    #[test]
    fn particles_after_the_thing_and_shared_verbs_are_read_by_structure() {
        let one = |text: &str| {
            let c = read(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(c.len(), 1, "{text}: {c:?}");
            c.into_iter().next().unwrap_or_else(|| panic!("{text}"))
        };
        // A particle ending a moving verb's clause leaves the part shut or open.
        for text in ["push the drawer in", "slide the top drawer back in", "push and close the drawer"] {
            assert_eq!(one(text).action, Action::Close, "{text}");
        }
        assert_eq!(one("slide the drawer out").action, Action::Open);
        // "in" with a thing after it is still a relation.
        let c = one("push the cube in the box");
        assert_eq!((c.action, c.rel), (Action::Push, Some(Rel::Inside)));
        // The verb's particle after its thing.
        for text in ["set it down on the tray", "put it back on the shelf", "put the mug down in the bowl"] {
            let c = read(&format!("pick up the mug and {text}")).unwrap_or_else(|e| panic!("{text}: {e}"));
            let last = c.last().unwrap_or_else(|| panic!("{text}"));
            assert_eq!(last.action, Action::Place, "{text}");
            assert_eq!(subjects(last), [("mug", false)], "{text}");
        }
    }

    #[test]
    fn one_stands_for_the_kind_named_before() {
        // A colour or size with "one": the head noun of the thing named before.
        let c = read("put the red cube in the bowl and the green one on the plate").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(c.len(), 2);
        assert_eq!(subjects(&c[1]), [("green cube", false)]);
        assert_eq!(c[1].target.as_ref().map(|t| t.text.as_str()), Some("plate"));
        // "the other one", "the other", "another one": the same kind, marked other.
        for text in ["the other one", "the other", "another one"] {
            let c = read(&format!("move the mug to the tray, then {text} too")).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(subjects(&c[1]), [("mug", true)], "{text}");
        }
        // "the other cube": the noun kept, marked other.
        let c = read("stack the blue block on the other block").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(c[0].target.as_ref().map(|t| (t.text.as_str(), t.other)), Some(("block", true)));
        // "the small ones": every one of the kind.
        let c = read("pick up the bottle and put the small ones in the bin").unwrap_or_else(|e| panic!("{e}"));
        let last = c.last().unwrap_or_else(|| panic!());
        assert_eq!(last.subjects[0].text, "small bottle");
        assert!(last.subjects[0].every);
        // "it" is still the thing itself.
        let c = read("grab the sphere and drop it into the bin").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(subjects(c.last().unwrap_or_else(|| panic!())), [("sphere", false)]);
    }
}
