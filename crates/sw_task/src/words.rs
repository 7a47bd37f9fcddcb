//! Reading an instruction: words → clauses (an action, the things it moves, how they relate
//! to a goal thing or place). Binding the noun phrases to bodies is `bind`'s.

use crate::TaskError;
use crate::vocab::{self, Action, CLAUSE_BREAKS, EVERY, PRONOUNS, REGIONS, RELS, Region, Rel};

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

/// Reads an instruction into clauses. Pronouns ("it", "them") take the things of the clause
/// before; a clause without a verb takes the verb before ("put the red cube in the bowl and
/// the blue one on the plate").
pub(crate) fn read(instruction: &str) -> Result<Vec<Clause>, TaskError> {
    let t = tokens(instruction);
    // Clauses: split at punctuation and clause words.
    let mut segments: Vec<&[String]> = Vec::new();
    let mut start = 0;
    for (i, w) in t.iter().enumerate() {
        if w == "," || CLAUSE_BREAKS.contains(&w.as_str()) {
            if i > start {
                segments.push(&t[start..i]);
            }
            start = i + 1;
        }
    }
    if start < t.len() {
        segments.push(&t[start..]);
    }
    let mut out: Vec<Clause> = Vec::new();
    let mut pending: Vec<NounPhrase> = Vec::new();
    let mut last_action: Option<Action> = None;
    let mut last_subjects: Vec<NounPhrase> = Vec::new();
    for seg in segments {
        let verb_at = seg.iter().position(|w| vocab::verb(w).is_some());
        let action = verb_at.and_then(|i| vocab::verb(&seg[i])).map(|(a, _)| a);
        let from = verb_at.map_or(0, |i| i + 1);
        let rel_found = (from..seg.len()).find_map(|i| rel_at(seg, i).map(|(r, n)| (i, r, n)));
        let (subject_words, rel, rest) = match rel_found {
            Some((i, r, n)) => (&seg[from..i], Some(r), &seg[i + n..]),
            None => (&seg[from..], None, &seg[seg.len()..]),
        };
        let side = rel_found.and_then(|(i, _, n)| {
            seg[i..i + n].iter().find_map(|w| {
                let w = if w == "behind" { "back" } else { w.as_str() };
                REGIONS
                    .iter()
                    .find(|(name, r)| *name == w && !matches!(r, Region::Centre | Region::Corner))
                    .map(|x| x.1)
            })
        });
        let antecedent = last_subjects.first().or(pending.first());
        let subject = noun_phrase(subject_words).map(|np| resolve_one(&np, antecedent).unwrap_or(np));
        let Some(action) = action.or(last_action) else {
            // Words before any verb ("the mug and the cup"): subjects of the next clause.
            pending.extend(subject);
            continue;
        };
        if action != Action::Navigate && subject.is_none() && rel.is_none() && action != Action::Open {
            // A verb alone ("and then stop").
            continue;
        }
        let mut subjects: Vec<NounPhrase> = std::mem::take(&mut pending);
        match subject {
            Some(s) if is_pronoun(&s) => subjects.extend(last_subjects.iter().cloned()),
            Some(s) => subjects.push(s),
            None if verb_at.is_none() => subjects.extend(last_subjects.iter().cloned()),
            None => {}
        }
        // "to the left (of the table)", "into the corner": a region.
        let mut region = None;
        let mut target_words: &[String] = rest;
        if matches!(rel, Some(Rel::To | Rel::Inside | Rel::Near)) {
            let w: Vec<&str> = rest.iter().map(String::as_str).filter(|w| *w != "the").collect();
            if let Some((_, r)) = w.first().and_then(|f| REGIONS.iter().find(|(n, _)| n == f)) {
                let named_surface = w.iter().position(|x| *x == "of");
                let is_region = w.len() == 1
                    || named_surface == Some(1)
                    || w.get(1).is_some_and(|x| matches!(*x, "side" | "edge" | "end" | "half" | "part"));
                if is_region {
                    region = Some(*r);
                    target_words = match rest.iter().position(|x| x == "of") {
                        Some(k) => &rest[k + 1..],
                        None => &rest[rest.len()..],
                    };
                }
            }
        }
        // "… on the other one": the kind of the thing just named in this clause.
        let antecedent = subjects.first().or(last_subjects.first());
        let target = noun_phrase(target_words).map(|np| resolve_one(&np, antecedent).unwrap_or(np));
        if region.is_none() && rel.is_some() && target.is_none() {
            return Err(TaskError::Words(format!(
                "\"{}\" says where but not what: nothing follows the last word",
                seg.join(" ")
            )));
        }
        let mut target = match target {
            Some(t) if is_pronoun(&t) => last_subjects.first().cloned(),
            t => t,
        };
        // "…, then the green one too": no verb and no place — the clause before's, again.
        let (mut rel, mut region, mut side) = (rel, region, side);
        if verb_at.is_none()
            && rel.is_none()
            && let Some(prev) = out.last()
        {
            (rel, target, region, side) = (prev.rel, prev.target.clone(), prev.region, prev.side);
        }
        if action == Action::Navigate && subjects.is_empty() && target.is_none() {
            // "go to the shelf": the thing follows "to".
            continue;
        }
        last_action = Some(action);
        if !subjects.is_empty() {
            last_subjects.clone_from(&subjects);
        }
        // "pick up the cube and put it in the bowl": the lift is part of the placing.
        if let Some(prev) = out.last()
            && prev.action == Action::Lift
            && prev.rel.is_none()
            && prev.subjects == subjects
        {
            out.pop();
        }
        out.push(Clause { action, subjects, rel, target, region, side });
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
        let Some((_, form)) = vocab::verb(&t[i]) else { continue };
        let prev = if i > 0 { Some(t[i - 1].as_str()) } else { None };
        let relative = matches!(prev, Some("that" | "which" | "who" | "to"));
        let imperative = form == vocab::Form::Base && matches!(prev, None | Some(","));
        // "a UR5e on a table sorting the cubes …": a robot named before the verb does it.
        let robot_before =
            t[..i].iter().any(|w| matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Robot { .. }));
        let after_robot = matches!(form, vocab::Form::Gerund | vocab::Form::Third) && robot_before;
        if relative || imperative || after_robot {
            // It must read as a task: something to move, or somewhere to go.
            let rest = &t[i + 1..];
            let has_object =
                rest.iter().any(|w| matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Category(_)));
            if has_object {
                return Some(i);
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
