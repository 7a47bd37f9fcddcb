#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Bad input, in families: nonsense, impossible counts, relations to things never named,
//! contradictions, retractions and prompts at and over the length limit. Every answer is
//! a plan that validates, with the phrase that went wrong named in `understanding`, or a
//! one-line refusal — never a panic or a silent drop.

use sw_plan::ScenePlan;
use sw_planner::{MAX_PROMPT_CHARS, PlannerError, plan};

/// A small deterministic generator (SplitMix64), the test's own.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Every word the plan's notes mention, lowercase.
fn notes(p: &ScenePlan) -> String {
    let mut s = String::new();
    for a in &p.understanding.approximated {
        s.push_str(&format!("{} | {} | {}\n", a.text, a.became, a.reason));
    }
    for n in &p.understanding.not_understood {
        s.push_str(&format!("{} | not understood\n", n.text));
    }
    s.to_lowercase()
}

/// A plan that validates, or a refusal on one line.
fn answer(prompt: &str) -> Result<ScenePlan, PlannerError> {
    match plan(prompt) {
        Ok(p) => {
            p.validate().unwrap_or_else(|e| panic!("{prompt:?}: invalid plan: {e}"));
            Ok(p)
        }
        Err(e) => {
            let line = e.to_string();
            assert!(!line.is_empty() && !line.contains('\n'), "{prompt:?}: {line:?}");
            Err(e)
        }
    }
}

#[test]
fn nonsense_is_refused_or_reported_word_for_word() {
    let words = ["blorp", "quux", "zzz", "frobnicate", "the", "of", "very", "glarb", "snoo", "42", "!!", "é"];
    let mut rng = Rng(7);
    for _ in 0..300 {
        let n = 1 + rng.below(12);
        let prompt: Vec<&str> = (0..n).map(|_| words[rng.below(words.len())]).collect();
        let prompt = prompt.join(" ");
        if let Ok(p) = answer(&prompt) {
            // Whatever was made of it is said: every group is a proxy with its note, or the
            // words are listed as not understood.
            for o in &p.objects {
                assert!(notes(&p).contains(&o.phrase.to_lowercase()), "{prompt:?}: {} is unexplained", o.phrase);
            }
        }
    }
}

#[test]
fn impossible_counts_are_noted_with_their_phrase() {
    for (prompt, phrase) in [
        ("a warehouse with zero pallets and a forklift", "zero pallets"),
        ("a warehouse with no pallets and a forklift", "no pallets"),
        ("a lab with 2.5 tables", "2.5 tables"),
        ("a warehouse with a million boxes", "a million boxes"),
        ("a warehouse with 100000 boxes", "100000 boxes"),
    ] {
        let p = answer(prompt).unwrap();
        assert!(notes(&p).contains(phrase), "{prompt:?}: no note names {phrase:?}\n{}", notes(&p));
    }
    // A count past what a scene holds is cut to the limit, not read as one.
    let p = answer("a warehouse with a million boxes").unwrap();
    assert!(p.object_count() >= 1000, "{}", notes(&p));
}

#[test]
fn relations_to_things_never_named_are_noted_or_made() {
    // A definite target with nothing before it is added, and the note says so; a relation
    // to a robot that is not there is dropped, never left dangling in the plan.
    let p = answer("a kitchen with two mugs next to the kettle").unwrap();
    assert!(p.relations.iter().all(|r| r.kind.targets().iter().all(|t| p.object(t).is_some() || p.robot(t).is_some())));
    assert!(notes(&p).contains("kettle"), "{}", notes(&p));
    for prompt in [
        "a table facing the robot",
        "a bin next to the arm",
        "a chair between them",
        "put it on the shelf",
        "a lamp on each of them",
    ] {
        if let Ok(p) = answer(prompt) {
            for r in &p.relations {
                for t in r.kind.targets() {
                    assert!(p.object(t).is_some() || p.robot(t).is_some(), "{prompt:?}: {t} is nowhere");
                }
            }
        }
    }
}

#[test]
fn contradictions_give_a_plan_with_the_contradiction_noted() {
    // Two room sizes: the first is kept, the second named as ignored.
    let p = answer("a 6 by 4 m kitchen with a table, the kitchen is 10 by 8 m").unwrap();
    assert!((p.room.size.width - 6.0).abs() < 1e-9, "{:?}", p.room.size);
    assert!(notes(&p).contains("10 by 8 m"), "{}", notes(&p));
    // Two rooms: one is kept, the other named.
    let p = answer("a kitchen with a fridge in a warehouse").unwrap();
    assert!(notes(&p).contains("warehouse") || notes(&p).contains("kitchen"), "{}", notes(&p));
    // A room too small for what is in it is still a plan (the layout reports what it left out).
    let p = answer("a 2 by 2 m room with forty wardrobes").unwrap();
    assert_eq!(p.object_count(), 40);
}

#[test]
fn a_retraction_leaves_the_thing_out_and_says_so() {
    for (prompt, gone) in [
        ("a desk, a lamp (skip that) and a chair", "a lamp"),
        ("a desk and a stool... no, a chair", "a stool"),
        ("two pendant lights (ignore), a table and a sofa", "two pendant lights"),
    ] {
        let p = answer(prompt).unwrap();
        assert!(p.objects.iter().all(|o| o.phrase != gone), "{prompt:?}: {gone:?} is still there");
        assert!(notes(&p).contains(&format!("{gone} | left out")), "{prompt:?}\n{}", notes(&p));
    }
}

#[test]
fn prompts_at_the_limit_are_read_and_longer_ones_refused_up_front() {
    let clause = "a table with two mugs on it, ";
    let mut at = clause.repeat(MAX_PROMPT_CHARS / clause.len());
    at.truncate(at.trim_end_matches([',', ' ']).len());
    assert!(at.chars().count() <= MAX_PROMPT_CHARS);
    let p = answer(&at).unwrap();
    assert!(p.object_count() > 100);
    let over = format!("{at}{}", " and a chair".repeat(20));
    match answer(&over) {
        Err(PlannerError::TooManyChars { chars, limit }) => assert!(chars > limit && limit == MAX_PROMPT_CHARS),
        other => panic!("a prompt over the limit was not refused: {other:?}"),
    }
}
