#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Nouns the catalog lacks: a kind of a category becomes it (reported), anything else
//! a labelled proxy of its kind, a non-thing is left out with a warning; never silent,
//! never dropped without a word. Checked with matching by meaning off (the offline
//! fallback, always) and with the real MiniLM when its weights are installed.

use sw_catalog::{Category, Kind};
use sw_pipeline::open_vocab::{Meaning, MiniLmMeaning, Resolution, resolve_noun};
use sw_pipeline::{Options, generate};

/// Matching by meaning switched off: what a machine without the MiniLM weights does.
struct Off;

impl Meaning for Off {
    fn scores(&self, _noun: &str, _among: &[&'static Category]) -> Option<Vec<f32>> {
        None
    }
    fn abstractness(&self, _noun: &str) -> Option<f32> {
        None
    }
}

fn minilm() -> Option<&'static MiniLmMeaning> {
    let m = MiniLmMeaning::shared();
    match m.unavailable() {
        None => Some(m),
        Some(why) => {
            eprintln!("MiniLM not installed ({why}): the checks by meaning are skipped");
            None
        }
    }
}

fn category_of(r: &Resolution) -> Option<&'static str> {
    match r {
        Resolution::Category { name, .. } => Some(name),
        _ => None,
    }
}

#[test]
fn without_the_model_a_noun_whose_head_names_a_category_is_a_kind_of_it() {
    // Compounds people write with an unknown first word: each is a kind of its head.
    for (noun, want) in [
        ("budget toaster", "toaster"),
        ("vintage kettle", "kettle"),
        ("ceramic teapot", "teapot"),
        ("office whiteboard", "whiteboard"),
        ("garden wheelbarrow", "wheelbarrow"),
        ("kids bicycle", "bicycle"),
    ] {
        assert_eq!(category_of(&resolve_noun(noun, &Off)), Some(want), "{noun}");
    }
    // No head in the catalog and no model: a proxy, never a guess.
    for noun in ["gizmo", "chaise longue", "happiness", "quokka"] {
        assert!(matches!(resolve_noun(noun, &Off), Resolution::Proxy { .. }), "{noun}");
    }
}

#[test]
fn by_meaning_kinds_map_to_their_category_and_other_things_keep_their_kind() {
    let Some(m) = minilm() else { return };
    // Kinds of a catalog thing, named alike but not in the catalog.
    for (noun, want) in
        [("deep fryer", &["air_fryer"][..]), ("camping kettle", &["kettle"]), ("kids bicycle", &["bicycle"])]
    {
        let r = resolve_noun(noun, m);
        assert!(category_of(&r).is_some_and(|c| want.contains(&c)), "{noun}: {r:?}");
    }
    // Things of no catalog category: a proxy of the right kind of thing, or of none.
    for (noun, kinds) in [
        ("air purifier", &[Kind::LargeAppliance, Kind::SmallAppliance][..]),
        ("dehumidifier", &[Kind::LargeAppliance, Kind::SmallAppliance]),
    ] {
        match resolve_noun(noun, m) {
            Resolution::Proxy { kind, .. } => assert!(kind.is_none_or(|k| kinds.contains(&k)), "{noun}: {kind:?}"),
            Resolution::Category { name, .. } => {
                let k = sw_catalog::find(name).unwrap().kind;
                assert!(kinds.contains(&k), "{noun} became {name}, a {k:?}");
            }
            r => panic!("{noun}: {r:?}"),
        }
    }
    // Feelings and events are not objects.
    for noun in ["happiness", "sadness", "silence", "a birthday party", "jealousy"] {
        assert!(matches!(resolve_noun(noun, m), Resolution::NotAThing { .. }), "{noun}: {:?}", resolve_noun(noun, m));
    }
}

#[test]
fn generate_reports_every_unknown_noun_and_drops_none_silently() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p");
    let prompt = "a living room with a sofa, a gizmo, a handsaw and a happiness";
    let o = generate(prompt, &out, &Options { verify: true, ..Options::default() }, &mut |_| {}).unwrap();
    assert!(sw_pipeline::succeeded(&o.report), "{:?}", o.report.verification);
    let says = |word: &str| o.report.warnings.iter().any(|w| w.message.contains(word));
    // The gizmo is a labelled proxy, said so; the sofa is real.
    assert!(o.layout.objects.iter().any(|p| p.category == "sofa"));
    assert!(o.layout.objects.iter().any(|p| p.label == "gizmo"), "{:?}", o.layout.objects);
    assert!(says("gizmo"), "{:?}", o.report.warnings);
    // A thing read through another of its category's names is said so.
    assert!(
        o.report.approximated.iter().any(|a| a.text.contains("handsaw") && a.became == "hand saw"),
        "{:?}",
        o.report.approximated
    );
    // The happiness is placed as nothing, with a warning (with the model) or a labelled
    // proxy with a warning (without it) — never silently.
    assert!(says("happiness"), "{:?}", o.report.warnings);
    let plan: sw_plan::ScenePlan =
        serde_json::from_str(&std::fs::read_to_string(out.join("plan.json")).unwrap()).unwrap();
    for g in &plan.objects {
        assert!(sw_catalog::find(&g.category).is_some() || g.proxy.is_some(), "{g:?}");
    }
}
