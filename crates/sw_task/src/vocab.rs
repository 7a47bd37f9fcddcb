//! The task reader's vocabulary, as data: verbs and the action they ask for, the words that
//! relate a thing to its goal, region words, and words that make a noun phrase mean every
//! instance. Adding a word never adds a branch.

/// What a verb asks the robot to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Action {
    Place,
    Stack,
    Push,
    Lift,
    Open,
    Close,
    Navigate,
}

/// Verbs by their base form; inflections (`puts`, `putting`, `placed`) are found by
/// [`verb`].
pub(crate) const VERBS: &[(&str, Action)] = &[
    ("put", Action::Place),
    ("place", Action::Place),
    ("set", Action::Place),
    ("move", Action::Place),
    ("drop", Action::Place),
    ("bring", Action::Place),
    ("transfer", Action::Place),
    ("relocate", Action::Place),
    ("carry", Action::Place),
    ("load", Action::Place),
    ("sort", Action::Place),
    ("pack", Action::Place),
    ("stow", Action::Place),
    ("return", Action::Place),
    ("store", Action::Place),
    ("tidy", Action::Place),
    ("insert", Action::Place),
    ("deposit", Action::Place),
    ("toss", Action::Place),
    ("throw", Action::Place),
    ("stack", Action::Stack),
    ("pile", Action::Stack),
    ("push", Action::Push),
    ("slide", Action::Push),
    ("shove", Action::Push),
    ("nudge", Action::Push),
    ("lift", Action::Lift),
    ("raise", Action::Lift),
    ("pick", Action::Lift),
    ("grab", Action::Lift),
    ("grasp", Action::Lift),
    ("hold", Action::Lift),
    ("take", Action::Lift),
    ("open", Action::Open),
    ("pull", Action::Open),
    ("close", Action::Close),
    ("shut", Action::Close),
    ("go", Action::Navigate),
    ("drive", Action::Navigate),
    ("navigate", Action::Navigate),
    ("travel", Action::Navigate),
    ("head", Action::Navigate),
    ("roll", Action::Navigate),
];

/// Irregular forms not made by the suffix rules.
const IRREGULAR: &[(&str, &str)] = &[
    ("brought", "bring"),
    ("carried", "carry"),
    ("carries", "carry"),
    ("took", "take"),
    ("threw", "throw"),
    ("thrown", "throw"),
    ("held", "hold"),
    ("went", "go"),
    ("goes", "go"),
    ("drove", "drive"),
    ("driven", "drive"),
    ("tidies", "tidy"),
];

/// How a thing relates to its goal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rel {
    Inside,
    On,
    Near,
    /// "to the X": a place of its own surface, or a thing to go to.
    To,
}

/// Relation words, longest first wins.
pub(crate) const RELS: &[(&[&str], Rel)] = &[
    (&["in", "to"], Rel::Inside),
    (&["into"], Rel::Inside),
    (&["inside", "of"], Rel::Inside),
    (&["inside"], Rel::Inside),
    (&["in"], Rel::Inside),
    (&["within"], Rel::Inside),
    (&["on", "top", "of"], Rel::On),
    (&["on", "to"], Rel::On),
    (&["onto"], Rel::On),
    (&["on"], Rel::On),
    (&["upon"], Rel::On),
    (&["atop"], Rel::On),
    (&["next", "to"], Rel::Near),
    (&["close", "to"], Rel::Near),
    (&["beside"], Rel::Near),
    (&["besides"], Rel::Near),
    (&["near"], Rel::Near),
    (&["nearby"], Rel::Near),
    (&["by"], Rel::Near),
    (&["alongside"], Rel::Near),
    (&["to", "the", "left", "of"], Rel::Near),
    (&["to", "the", "right", "of"], Rel::Near),
    (&["in", "front", "of"], Rel::Near),
    (&["behind"], Rel::Near),
    (&["towards"], Rel::To),
    (&["toward"], Rel::To),
    (&["to"], Rel::To),
    (&["up", "to"], Rel::To),
];

/// A part of a surface, in the robot's frame (it works towards its +x; left is +y).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Region {
    Left,
    Right,
    Front,
    Back,
    Centre,
    Corner,
}

/// Region words (after "to the", "into the").
pub(crate) const REGIONS: &[(&str, Region)] = &[
    ("left", Region::Left),
    ("right", Region::Right),
    ("front", Region::Front),
    ("near", Region::Front),
    ("back", Region::Back),
    ("rear", Region::Back),
    ("far", Region::Back),
    ("centre", Region::Centre),
    ("center", Region::Centre),
    ("middle", Region::Centre),
    ("corner", Region::Corner),
];

/// Words that make a noun phrase mean every instance of its kind.
pub(crate) const EVERY: &[&str] = &["all", "every", "each", "both", "the rest of"];

/// Verbs that say on or off ("turn on the stove", "switch the lamp off"): open and close.
pub(crate) const SWITCH_VERBS: &[&str] = &["turn", "switch", "power"];

/// Verbs for things the expert cannot do or be judged on: a clause led by one is refused,
/// naming it.
pub(crate) const UNSUPPORTED: &[&str] = &[
    "pour", "wipe", "fold", "unfold", "sweep", "water", "rotate", "flip", "press", "unplug", "plug", "reach", "knock",
    "unstack", "twist", "cut", "slice", "chop", "hang", "wash", "stir", "scoop", "screw", "unscrew", "spin", "tilt",
    "shake", "squeeze", "clean", "scrub", "peel", "lock", "unlock", "touch", "tap", "hit", "kick", "fill", "empty",
    "hand", "give", "point", "wave", "write", "draw", "erase", "cook", "boil", "heat", "fry",
];

/// Parts of things that open and close (joints are named `<object>_<part>_<n>_joint`).
pub(crate) const PARTS: &[&str] = &["drawer", "drawers", "door", "doors", "lid", "flap", "hatch"];

/// Relation words for a goal under another thing, which no predicate judges.
pub(crate) const UNDER: &[&str] = &["under", "underneath", "beneath", "below"];

/// Words after a thing that say how it must be left, which no predicate judges.
pub(crate) const RESULTS: &[&str] =
    &["upright", "sideways", "over", "flat", "vertical", "vertically", "horizontal", "horizontally", "upside", "down"];

/// Words around a command that ask politely or say who does it ("please", "can you", "the
/// robot should", "I want you to", "go ahead and").
pub(crate) const WRAPPERS: &[&str] = &[
    "please",
    "pls",
    "kindly",
    "can",
    "could",
    "would",
    "will",
    "you",
    "robot",
    "the",
    "should",
    "must",
    "shall",
    "i",
    "i'd",
    "want",
    "need",
    "needs",
    "like",
    "to",
    "now",
    "try",
    "ahead",
    "first",
    "your",
    "task",
    "is",
    "lets",
    "let's",
    "let",
    "us",
    "we",
    "just",
    "also",
    "go",
    "goal",
    "instruction",
    "arm",
    "gripper",
    "and",
    "then",
    "finally",
    "ok",
    "okay",
    "hey",
    "quickly",
    "carefully",
    "gently",
    "slowly",
    "mind",
    "be",
    "able",
];

/// Closed-class words a typo may hide ("teh", "inot", "ontop").
pub(crate) const FUNCTION_WORDS: &[&str] = &[
    "the", "into", "onto", "inside", "behind", "beside", "between", "next", "front", "left", "right", "top", "from",
    "and", "then", "please", "near", "towards", "toward", "upon", "within",
];

/// `w` is `to` with one letter changed, added or dropped, or two neighbours swapped.
pub(crate) fn near_miss(w: &str, to: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (w.chars().collect(), to.chars().collect());
    if a == b || a.len().abs_diff(b.len()) > 1 {
        return false;
    }
    if a.len() == b.len() {
        let diff: Vec<usize> = (0..a.len()).filter(|&i| a[i] != b[i]).collect();
        return match diff.as_slice() {
            [_] => a.len() >= 4,
            [i, j] => *j == i + 1 && a[*i] == b[*j] && a[*j] == b[*i],
            _ => false,
        };
    }
    if a.len().min(b.len()) < 4 {
        return false;
    }
    let (long, short) = if a.len() > b.len() { (&a, &b) } else { (&b, &a) };
    let k = (0..short.len()).find(|&i| long[i] != short[i]).unwrap_or(short.len());
    long[k + 1..] == short[k..]
}

/// `w` is an inflection of the verb `base` ("pours", "wiped", "rotating").
pub(crate) fn base_form_of(w: &str, base: &str) -> bool {
    ["s", "es", "ed", "d", "ing"].iter().any(|s| {
        w.strip_suffix(s).is_some_and(|stem| {
            stem == base
                || format!("{stem}e") == base
                || stem.strip_suffix(base.chars().last().unwrap_or(' ')) == Some(base)
        })
    })
}

/// Words that refer back to the last thing named.
pub(crate) const PRONOUNS: &[&str] = &["it", "them", "this", "that", "these", "those", "one"];

/// The base form of `word` when it is a form of a known verb (`puts` → `put`).
pub(crate) fn base_form(word: &str) -> Option<&'static str> {
    let w = word.to_lowercase();
    if let Some((v, _)) = VERBS.iter().find(|(v, _)| *v == w) {
        return Some(v);
    }
    if let Some((_, b)) = IRREGULAR.iter().find(|(f, _)| *f == w) {
        return VERBS.iter().find(|(v, _)| v == b).map(|(v, _)| *v);
    }
    for suffix in ["ing", "es", "s", "ed"] {
        let Some(stem) = w.strip_suffix(suffix) else { continue };
        let mut cands = vec![stem.to_string(), format!("{stem}e")];
        let b = stem.as_bytes();
        if b.len() >= 2 && b[b.len() - 1] == b[b.len() - 2] {
            cands.push(stem[..stem.len() - 1].to_string());
        }
        if let Some(s) = stem.strip_suffix('i') {
            cands.push(format!("{s}y"));
        }
        for c in cands {
            if let Some((v, _)) = VERBS.iter().find(|(v, _)| *v == c) {
                return Some(v);
            }
        }
    }
    None
}

/// The action of `word` when it is a form of a known verb, and whether that form is a
/// base or imperative (`put`), third person (`puts`), gerund (`putting`) or past.
pub(crate) fn verb(word: &str) -> Option<(Action, Form)> {
    let w = word.to_lowercase();
    let base = |b: &str| VERBS.iter().find(|(v, _)| *v == b).map(|(_, a)| *a);
    if let Some(a) = base(&w) {
        return Some((a, Form::Base));
    }
    if let Some((_, b)) = IRREGULAR.iter().find(|(f, _)| *f == w) {
        let form = if w.ends_with('s') { Form::Third } else { Form::Past };
        return base(b).map(|a| (a, form));
    }
    let stems = |suffix: &str| -> Vec<String> {
        let Some(stem) = w.strip_suffix(suffix) else { return Vec::new() };
        let mut out = vec![stem.to_string(), format!("{stem}e")];
        let b = stem.as_bytes();
        if b.len() >= 2 && b[b.len() - 1] == b[b.len() - 2] {
            out.push(stem[..stem.len() - 1].to_string());
        }
        if let Some(s) = stem.strip_suffix('i') {
            out.push(format!("{s}y"));
        }
        out
    };
    for (suffix, form) in [("ing", Form::Gerund), ("es", Form::Third), ("s", Form::Third), ("ed", Form::Past)] {
        for s in stems(suffix) {
            if let Some(a) = base(&s) {
                return Some((a, form));
            }
        }
    }
    None
}

/// The grammatical form of a verb.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Form {
    Base,
    Third,
    Gerund,
    Past,
}

/// Catalog categories with a work surface that things stand on within an arm's reach.
pub(crate) const SURFACES: &[&str] =
    &["table", "dining_table", "desk", "workbench", "counter", "mobile_cart", "conveyor", "kitchen_island", "bench"];
