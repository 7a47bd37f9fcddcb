#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The round trip: a generator writes one scene (objects, counts, sizes, relations) in
//! many surface forms — number words, synonyms, clause orders, active, passive and
//! imperative, distribution, reference, titles, units — and the reader must return the
//! same plan for every one of them.
//!
//! Each family draws its scenes and wordings from a seeded generator, so a failure is
//! reproducible from its family and case number; the message names both and the words.
//! A plan is compared by what it means, not how it is spelt: the room kind and size,
//! the total count per category, stated dimensions, and the relations between
//! categories (group ids are the reader's business). Plans only: no layout, no MuJoCo.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

use sw_plan::{RelationKind, ScenePlan};

// ------------------------------------------------------------------ the generator's RNG

/// SplitMix64: the test's own, so that the cases do not move when a library's RNG does.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Self {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5_4A32_D192_ED03)
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len())]
    }
    fn chance(&mut self, p: f64) -> bool {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 <= p
    }
}

// ------------------------------------------------------------------ the vocabulary used

#[derive(Debug, Clone, Copy, PartialEq)]
enum Role {
    /// Floor furniture with a top things rest on.
    Surface,
    /// A small thing that rests on a surface.
    Item,
    /// A floor thing with no top to speak of.
    Floor,
}

#[derive(Debug)]
struct Noun {
    cat: &'static str,
    /// Ways people name it (singular); the first is the plain one.
    forms: &'static [&'static str],
    role: Role,
}

const NOUNS: &[Noun] = &[
    Noun { cat: "table", forms: &["table", "work table", "worktable"], role: Role::Surface },
    Noun { cat: "desk", forms: &["desk", "office desk"], role: Role::Surface },
    Noun { cat: "workbench", forms: &["workbench", "work bench"], role: Role::Surface },
    Noun { cat: "counter", forms: &["counter", "kitchen counter"], role: Role::Surface },
    Noun { cat: "dining_table", forms: &["dining table", "kitchen table"], role: Role::Surface },
    Noun { cat: "mug", forms: &["mug", "coffee mug"], role: Role::Item },
    Noun { cat: "bowl", forms: &["bowl", "soup bowl"], role: Role::Item },
    Noun { cat: "bottle", forms: &["bottle", "water bottle"], role: Role::Item },
    Noun { cat: "laptop", forms: &["laptop"], role: Role::Item },
    Noun { cat: "book", forms: &["book", "textbook"], role: Role::Item },
    Noun { cat: "desk_lamp", forms: &["desk lamp", "lamp", "table lamp"], role: Role::Item },
    Noun { cat: "plate", forms: &["plate", "dinner plate"], role: Role::Item },
    Noun { cat: "monitor", forms: &["monitor", "computer monitor"], role: Role::Item },
    Noun { cat: "keyboard", forms: &["keyboard"], role: Role::Item },
    Noun { cat: "chair", forms: &["chair", "office chair"], role: Role::Floor },
    Noun { cat: "cabinet", forms: &["cabinet", "storage cabinet"], role: Role::Floor },
    Noun { cat: "stool", forms: &["stool", "bar stool"], role: Role::Floor },
    Noun { cat: "bookshelf", forms: &["bookshelf", "bookcase"], role: Role::Floor },
    Noun { cat: "fridge", forms: &["fridge", "refrigerator"], role: Role::Floor },
    Noun { cat: "sofa", forms: &["sofa", "couch"], role: Role::Floor },
    Noun { cat: "potted_plant", forms: &["potted plant", "plant"], role: Role::Floor },
    Noun { cat: "trash_can", forms: &["trash can"], role: Role::Floor },
    Noun { cat: "filing_cabinet", forms: &["filing cabinet", "file cabinet"], role: Role::Floor },
    Noun { cat: "locker", forms: &["locker"], role: Role::Floor },
    Noun { cat: "whiteboard", forms: &["whiteboard"], role: Role::Floor },
];

const ROOMS: &[(&str, &[&str])] = &[
    ("kitchen", &["kitchen"]),
    ("office", &["office"]),
    ("lab", &["lab", "laboratory"]),
    ("workshop", &["workshop"]),
    ("living_room", &["living room", "lounge"]),
    ("classroom", &["classroom"]),
];

fn nouns(role: Role) -> Vec<&'static Noun> {
    NOUNS.iter().filter(|n| n.role == role).collect()
}

/// English plural of a noun phrase's last word (written here, apart from the reader's
/// singular()).
fn plural(phrase: &str) -> String {
    let (head, last) = match phrase.rsplit_once(' ') {
        Some((h, l)) => (format!("{h} "), l),
        None => (String::new(), phrase),
    };
    let p = if let Some(stem) = last.strip_suffix("shelf") {
        format!("{stem}shelves")
    } else if last.ends_with("ch") || last.ends_with("sh") || last.ends_with('s') || last.ends_with('x') {
        format!("{last}es")
    } else if last.ends_with('y') && !last.ends_with("ay") && !last.ends_with("ey") && !last.ends_with("oy") {
        format!("{}ies", &last[..last.len() - 1])
    } else {
        format!("{last}s")
    };
    format!("{head}{p}")
}

fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) { "an" } else { "a" }
}

const NUMBER_WORDS: &[&str] =
    &["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve"];

/// A count and a noun, in one of the ways people write it: "a mug", "one mug", "3 mugs",
/// "three mugs", "a pair of mugs", "half a dozen mugs", "a dozen mugs".
fn counted(rng: &mut Rng, n: u32, form: &str) -> String {
    if n == 1 {
        return match rng.below(4) {
            0 => format!("one {form}"),
            1 => format!("a single {form}"),
            _ => format!("{} {form}", article(form)),
        };
    }
    let p = plural(form);
    let mut ways = vec![format!("{n} {p}")];
    if let Some(w) = NUMBER_WORDS.get(n as usize) {
        ways.push(format!("{w} {p}"));
        ways.push(format!("{w} {p}"));
    }
    match n {
        2 => {
            ways.push(format!("a pair of {p}"));
            ways.push(format!("a couple of {p}"));
        }
        6 => ways.push(format!("half a dozen {p}")),
        12 => ways.push(format!("a dozen {p}")),
        _ => {}
    }
    rng.pick(&ways).clone()
}

fn capitalise(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().collect::<String>() + c.as_str(),
        None => String::new(),
    }
}

/// "a, b and c" (or with an Oxford comma, or "plus").
fn list(rng: &mut Rng, items: &[String]) -> String {
    match items {
        [] => String::new(),
        [a] => a.clone(),
        _ => {
            let (last, rest) = items.split_last().unwrap();
            let joiner = *rng.pick(&[" and ", ", and ", " and ", " plus "]);
            format!("{}{joiner}{last}", rest.join(", "))
        }
    }
}

// ------------------------------------------------------------------ what a plan means

/// A plan as its meaning: the room, counts per category, stated sizes (mm) and the
/// relations between categories.
#[derive(Debug, Clone, Default, PartialEq)]
struct Meaning {
    room: Option<String>,
    room_size_cm: Option<(i64, i64)>,
    counts: BTreeMap<String, u32>,
    sizes: BTreeMap<String, Vec<(&'static str, i64)>>,
    relations: BTreeSet<String>,
}

fn relation_key(subject: &str, kind: &RelationKind, name_of: &dyn Fn(&str) -> String) -> String {
    let detail = match kind {
        RelationKind::AgainstWall { wall: Some(w) } => format!(" wall={}", w.name()),
        RelationKind::InRows { n: Some(n), m: Some(m) } => format!(" n={n} m={m}"),
        RelationKind::InRows { n: Some(n), m: None } => format!(" n={n}"),
        RelationKind::Stacked { n, stacks } => format!(" n={n:?} stacks={stacks:?}"),
        RelationKind::AtEndOf { end: Some(e), .. } => format!(" end={}", e.name()),
        RelationKind::OnOppositeWalls { long: true } => " long".to_string(),
        _ => String::new(),
    };
    let targets: Vec<String> = kind.targets().iter().map(|t| name_of(t)).collect();
    format!("{} {}{}{}", name_of(subject), kind.name(), if targets.is_empty() { "" } else { " " }, targets.join(" "))
        + &detail
}

fn meaning_of(p: &ScenePlan, with_room: bool) -> Meaning {
    let name_of = |id: &str| -> String {
        if let Some(o) = p.object(id) {
            return o.category.clone();
        }
        if let Some(r) = p.robot(id) {
            return r.model.clone();
        }
        id.to_string()
    };
    let mut m = Meaning::default();
    if with_room {
        m.room = Some(p.room.kind.name().to_string());
        if p.room.size_fixed {
            m.room_size_cm =
                Some(((p.room.size.width * 100.0).round() as i64, (p.room.size.depth * 100.0).round() as i64));
        }
    }
    // A surface the reader sized for its load says so in the report; its length is the
    // reader's, not a stated size.
    let sized_for_load = |phrase: &str| {
        p.understanding.approximated.iter().any(|a| a.text == phrase && a.reason.contains("things on it need"))
    };
    for o in &p.objects {
        *m.counts.entry(o.category.clone()).or_insert(0) += o.count;
        let e = o.size.explicit;
        if !e.is_empty() && !sized_for_load(&o.phrase) {
            m.sizes.insert(
                o.category.clone(),
                e.stated().into_iter().map(|(n, v)| (n, (v * 1000.0).round() as i64)).collect(),
            );
        }
    }
    for r in &p.robots {
        *m.counts.entry(format!("robot:{}", r.model)).or_insert(0) += r.count;
    }
    for r in &p.relations {
        m.relations.insert(relation_key(&r.subject, &r.kind, &name_of));
    }
    m
}

// ------------------------------------------------------------------ a case and a family

struct Case {
    prompt: String,
    want: Meaning,
    with_room: bool,
}

fn rel(subject: &str, name: &str, target: Option<&str>) -> String {
    match target {
        Some(t) => format!("{subject} {name} {t}"),
        None => format!("{subject} {name}"),
    }
}

/// Runs `cases` of a family; returns (failures, lines describing the first few).
fn run_family(name: &str, cases: usize, make: fn(&mut Rng) -> Case) -> (usize, usize, String) {
    let mut failed = 0;
    let mut out = String::new();
    for k in 0..cases {
        let mut rng = Rng::new((k as u64) << 8 ^ name.len() as u64 ^ fnv(name));
        let case = make(&mut rng);
        let got = match sw_planner::plan(&case.prompt) {
            Ok(p) => meaning_of(&p, case.with_room),
            Err(e) => {
                failed += 1;
                if failed <= 6 {
                    let _ = writeln!(out, "  [{name} #{k}] {:?}: rejected: {e}", case.prompt);
                }
                continue;
            }
        };
        if got != case.want {
            failed += 1;
            if failed <= 6 {
                let _ = writeln!(
                    out,
                    "  [{name} #{k}] {:?}\n      want {:?}\n      got  {:?}",
                    case.prompt, case.want, got
                );
            }
        }
    }
    (failed, cases, out)
}

fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

// ------------------------------------------------------------------ families

/// Objects listed in a room, in many frames: "a kitchen with …", "… in a kitchen",
/// "Kitchen: …", "Make a kitchen with …", "I need a kitchen containing …".
fn lists(rng: &mut Rng) -> Case {
    let (room, room_forms) = rng.pick(ROOMS);
    let room_word = *rng.pick(room_forms);
    let k = 1 + rng.below(3);
    let mut used: Vec<&Noun> = Vec::new();
    while used.len() < k {
        let n = rng.pick(NOUNS);
        if !used.iter().any(|u| u.cat == n.cat) {
            used.push(n);
        }
    }
    let mut want = Meaning { room: Some(room.to_string()), ..Default::default() };
    let mut phrases = Vec::new();
    for n in &used {
        let count = 1 + rng.below(12) as u32;
        want.counts.insert(n.cat.to_string(), count);
        phrases.push({
            let form = rng_form(rng, n);
            counted(rng, count, form)
        });
    }
    let l = list(rng, &phrases);
    let prompt = match rng.below(8) {
        0 => format!("{} {room_word} with {l}", article(room_word)),
        1 => format!("{} in {} {room_word}", capitalise(&l), article(room_word)),
        2 => format!("{}: {l}.", capitalise(room_word)),
        3 => format!("Make {} {room_word} with {l}.", article(room_word)),
        4 => format!("I need {} {room_word} containing {l}", article(room_word)),
        5 => format!("{room_word} with {l}"),
        6 => format!("A {room_word} that has {l}."),
        _ => format!("There is {} {room_word}. It has {l}.", article(room_word)),
    };
    Case { prompt, want, with_room: true }
}

fn rng_form(rng: &mut Rng, n: &Noun) -> &'static str {
    // Mostly the plain name, sometimes another.
    if rng.chance(0.6) { n.forms[0] } else { n.forms[rng.below(n.forms.len())] }
}

/// Items on a surface: "two mugs on a table", "a table with two mugs on it", "On a
/// table, two mugs", "A table. Put two mugs on it.", "two mugs are placed on a table".
fn on_surface(rng: &mut Rng) -> Case {
    let s = *rng.pick(&nouns(Role::Surface));
    let mut i = *rng.pick(&nouns(Role::Item));
    while i.cat == s.cat {
        i = *rng.pick(&nouns(Role::Item));
    }
    let n = 1 + rng.below(6) as u32;
    let sf = rng_form(rng, s);
    let surf = format!("{} {sf}", article(sf));
    let item = {
        let form = rng_form(rng, i);
        counted(rng, n, form)
    };
    let head = sf.rsplit(' ').next().unwrap();
    let them = if n == 1 { "it" } else { "them" };
    let be = if n == 1 { "is" } else { "are" };
    let prompt = match rng.below(11) {
        0 => format!("{item} on {surf}"),
        1 => format!("{surf} with {item} on it"),
        2 => format!("{surf} with {item} on top"),
        3 => format!("On {surf}, {item}."),
        4 => format!("{}. Put {item} on it.", capitalise(&surf)),
        5 => format!("{}. {} {be} on the {head}.", capitalise(&surf), capitalise(&item)),
        6 => format!("{item} {be} placed on top of {surf}"),
        7 => format!("Put {item} on {surf}."),
        8 => format!("{item} resting on {surf}"),
        9 => format!("There is {surf} and {item} on it."),
        _ => format!("{surf} and {item}; put {them} on the {head}"),
    };
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    want.counts.insert(i.cat.into(), n);
    want.relations.insert(rel(i.cat, "on", Some(s.cat)));
    Case { prompt, want, with_room: false }
}

/// Distribution: "three desks, each with a lamp on it", "a lamp on each of three desks",
/// "three desks with a lamp each", "three desks with one lamp per desk".
fn distribution(rng: &mut Rng) -> Case {
    let h = *rng.pick(&nouns(Role::Surface));
    let item = rng.chance(0.6);
    let c = if item { *rng.pick(&nouns(Role::Item)) } else { *rng.pick(&[&NOUNS[14], &NOUNS[16]]) };
    let n = 2 + rng.below(7) as u32;
    let m = if rng.chance(0.7) { 1 } else { 2 };
    let hf = h.forms[0];
    let cf = c.forms[0];
    let hosts = counted(rng, n, hf);
    let comp = counted(rng, m, cf);
    let on_it = if item { " on it" } else { "" };
    let per_prep = if item { "on" } else { "at" };
    let prompt = match rng.below(7) {
        0 => format!("{hosts}, each with {comp}{on_it}"),
        1 => format!("{comp} {per_prep} each of {hosts}"),
        2 => format!("{hosts} with {comp} each"),
        3 => format!("{hosts} with {comp} per {hf}"),
        4 => format!("{hosts}, every one with {comp}"),
        5 => format!("{}. Put {comp} {per_prep} each {hf}.", capitalise(&hosts)),
        _ => format!("{hosts}, each of them with {comp}"),
    };
    let mut want = Meaning::default();
    want.counts.insert(h.cat.into(), n);
    want.counts.insert(c.cat.into(), n * m);
    // each_with pairs one to one: two per host is a count, not a pairing.
    if m == 1 {
        want.relations.insert(rel(h.cat, "each_with", Some(c.cat)));
    }
    if item {
        want.relations.insert(rel(c.cat, "on", Some(h.cat)));
    }
    Case { prompt, want, with_room: false }
}

/// Where a floor thing stands in the room: against a wall, in a corner, in the middle,
/// near the door — before or after, active, passive or imperative.
fn room_places(rng: &mut Rng) -> Case {
    let f = *rng.pick(&nouns(Role::Floor));
    let n = 1 + rng.below(3) as u32;
    let thing = {
        let form = rng_form(rng, f);
        counted(rng, n, form)
    };
    let (place, relation): (&str, &str) = *rng.pick(&[
        ("against the wall", "against_wall"),
        ("against a wall", "against_wall"),
        ("along the wall", "against_wall"),
        ("in the corner", "in_corner"),
        ("in a corner", "in_corner"),
        ("in the middle of the room", "in_middle"),
        ("in the centre of the room", "in_middle"),
        ("in the center", "in_middle"),
        ("near the door", "near_door"),
        ("by the door", "near_door"),
        ("next to the entrance", "near_door"),
    ]);
    let be = if n == 1 { "is" } else { "are" };
    let stand = if n == 1 { "stands" } else { "stand" };
    let prompt = match rng.below(6) {
        0 => format!("{thing} {place}"),
        1 => format!("Put {thing} {place}."),
        2 => format!("{thing} {stand} {place}"),
        3 => format!("{thing} {be} placed {place}"),
        4 => format!("{}, {thing}.", capitalise(place)),
        _ => format!("a room with {thing} {place}"),
    };
    let mut want = Meaning::default();
    want.counts.insert(f.cat.into(), n);
    want.relations.insert(rel(f.cat, relation, None));
    Case { prompt, want, with_room: false }
}

/// Two floor things in a binary relation: "a chair next to a desk", "a desk with a chair
/// beside it", "Next to the desk, a chair", "A desk. Put a chair in front of it."
fn floor_pairs(rng: &mut Rng) -> Case {
    let a = *rng.pick(&nouns(Role::Floor));
    let mut b = *rng.pick(&[nouns(Role::Floor), nouns(Role::Surface)].concat());
    while b.cat == a.cat {
        b = *rng.pick(&[nouns(Role::Floor), nouns(Role::Surface)].concat());
    }
    let (cue, relation): (&str, &str) = *rng.pick(&[
        ("next to", "next_to"),
        ("beside", "next_to"),
        ("right next to", "next_to"),
        ("near", "near"),
        ("close to", "near"),
        ("in front of", "in_front_of"),
        ("behind", "behind"),
    ]);
    let af = a.forms[0];
    let bf = b.forms[0];
    let thing = format!("{} {af}", article(af));
    let other = format!("{} {bf}", article(bf));
    let prompt = match rng.below(6) {
        0 => format!("{thing} {cue} {other}"),
        1 => format!("{other} with {thing} {cue} it"),
        2 => format!("{}, {thing}.", capitalise(&format!("{cue} {other}"))),
        3 => format!("{}. Put {thing} {cue} it.", capitalise(&other)),
        4 => format!("{thing} is placed {cue} {other}"),
        _ => format!("{other} and {thing}. The {af} stands {cue} the {bf}."),
    };
    let mut want = Meaning::default();
    want.counts.insert(a.cat.into(), 1);
    want.counts.insert(b.cat.into(), 1);
    want.relations.insert(rel(a.cat, relation, Some(b.cat)));
    Case { prompt, want, with_room: false }
}

/// Stated dimensions in every unit and position: "a 2 m long table", "a table 2 m long",
/// "a table, 200 cm long", "a 6 ft long table", "a table 80 cm high".
fn sizes(rng: &mut Rng) -> Case {
    let s = *rng.pick(&[nouns(Role::Surface), nouns(Role::Floor)].concat());
    let sf = s.forms[0];
    // (axis word, the dimension it names).
    let (axis, name): (&str, &'static str) =
        *rng.pick(&[("long", "length"), ("wide", "width"), ("deep", "depth"), ("tall", "height"), ("high", "height")]);
    let cm = 40 + 10 * rng.below(20) as i64;
    let (value, unit) = match rng.below(5) {
        0 => (format!("{}", cm as f64 / 100.0), *rng.pick(&[" m", "m", " metres", " meters"])),
        1 => (format!("{cm}"), *rng.pick(&[" cm", "cm", " centimetres"])),
        2 => (format!("{}", cm * 10), " mm"),
        3 => (format!("{}", cm as f64 / 100.0), " m"),
        _ => (format!("{}", cm as f64 / 100.0), " m"),
    };
    let dim = format!("{value}{unit} {axis}");
    let prompt = match rng.below(4) {
        0 => format!("{} {dim} {sf}", article(&value)),
        1 => format!("{} {sf} {dim}", article(sf)),
        2 => format!("{} {sf}, {dim}", article(sf)),
        _ => format!("{} {sf} that is {dim}", article(sf)),
    };
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    want.sizes.insert(s.cat.into(), vec![(name, cm * 10)]);
    Case { prompt, want, with_room: false }
}

/// Room sizes: "a 6 by 4 m kitchen", "a kitchen measuring 6 x 4 metres", "a 600 by 400 cm
/// kitchen", "a kitchen, 6 m by 4 m,", "a 20 ft by 13 ft kitchen".
fn room_sizes(rng: &mut Rng) -> Case {
    let (room, forms) = rng.pick(ROOMS);
    let rf = forms[0];
    let w = 3 + rng.below(9) as i64;
    let d = 2 + rng.below(w as usize - 1) as i64;
    let (dims, cm) = match rng.below(6) {
        0 => (format!("{w} by {d} m"), (w * 100, d * 100)),
        1 => (format!("{w} m by {d} m"), (w * 100, d * 100)),
        2 => (format!("{w}x{d}m"), (w * 100, d * 100)),
        3 => (format!("{w} x {d} metres"), (w * 100, d * 100)),
        4 => (format!("{} by {} cm", w * 100, d * 100), (w * 100, d * 100)),
        _ => {
            let (wf, df) = (w * 3, d * 3);
            (format!("{wf} ft by {df} ft"), ((wf as f64 * 30.48).round() as i64, (df as f64 * 30.48).round() as i64))
        }
    };
    let chair = counted(rng, 2, "chair");
    let prompt = match rng.below(4) {
        0 => format!("a {dims} {rf} with {chair}"),
        1 => format!("a {rf} measuring {dims} with {chair}"),
        2 => format!("a {rf}, {dims}, with {chair}"),
        _ => format!("{} {rf} of {dims} with {chair}", article(rf)),
    };
    let mut want = Meaning { room: Some(room.to_string()), room_size_cm: Some(cm), ..Default::default() };
    want.counts.insert("chair".into(), 2);
    Case { prompt, want, with_room: true }
}

/// Counts that add up: "three chairs and two more chairs", "a stool and another stool",
/// "two rows of four desks", "three stacks of four boxes".
fn quantities(rng: &mut Rng) -> Case {
    let f = *rng.pick(&nouns(Role::Floor));
    let ff = f.forms[0];
    let a = 1 + rng.below(5) as u32;
    let b = 1 + rng.below(4) as u32;
    let mut want = Meaning::default();
    let prompt = match rng.below(4) {
        0 => {
            want.counts.insert(f.cat.into(), a + b);
            want.counts.insert("desk".into(), 1);
            let more = NUMBER_WORDS[b as usize];
            let tail = if b == 1 { ff.to_string() } else { plural(ff) };
            format!("{}, a desk and {more} more {tail}", counted(rng, a, ff))
        }
        1 => {
            want.counts.insert(f.cat.into(), a + 1);
            format!("{} and another {ff}", counted(rng, a, ff))
        }
        2 => {
            let rows = 2 + rng.below(3) as u32;
            let per = 2 + rng.below(4) as u32;
            want.counts.insert(f.cat.into(), rows * per);
            want.relations.insert(rel(f.cat, "in_rows", None) + &format!(" n={rows} m={per}"));
            format!("{} rows of {} {}", NUMBER_WORDS[rows as usize], NUMBER_WORDS[per as usize], plural(ff))
        }
        _ => {
            want.counts.insert(f.cat.into(), a);
            format!("{} and nothing else", counted(rng, a, ff))
        }
    };
    Case { prompt, want, with_room: false }
}

/// A reference back to something named before: "a desk and a lamp. Put the lamp on the
/// desk.", "There is a desk. A lamp stands on it.", "A desk; on the desk, a lamp."
fn references(rng: &mut Rng) -> Case {
    let s = *rng.pick(&nouns(Role::Surface));
    let i = *rng.pick(&nouns(Role::Item));
    let sf = s.forms[0];
    let if_ = i.forms[0];
    let sh = sf.rsplit(' ').next().unwrap();
    let ih = if_.rsplit(' ').next().unwrap();
    let prompt = match rng.below(4) {
        0 => format!("{} {sf} and {} {if_}. Put the {ih} on the {sh}.", article(sf), article(if_)),
        1 => format!("There is {} {sf}. {} {if_} stands on it.", article(sf), capitalise(article(if_))),
        2 => format!("{} {sf}; on the {sh}, {} {if_}.", capitalise(article(sf)), article(if_)),
        _ => format!("{} {if_} and {} {sf}. The {ih} goes on the {sh}.", capitalise(article(if_)), article(sf)),
    };
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    want.counts.insert(i.cat.into(), 1);
    want.relations.insert(rel(i.cat, "on", Some(s.cat)));
    Case { prompt, want, with_room: false }
}

/// Words that name no object — a title, place nouns, a route — add nothing: "Reading
/// corner: a sofa and a lamp", "… leaving a clear path to the door".
fn no_objects_from_places(rng: &mut Rng) -> Case {
    let f = *rng.pick(&nouns(Role::Floor));
    let g = *rng.pick(&nouns(Role::Surface));
    let body = format!("{} {} and {} {}", article(f.forms[0]), f.forms[0], article(g.forms[0]), g.forms[0]);
    let prompt = match rng.below(5) {
        0 => format!("{}: {body}.", rng.pick(&["Study nook", "Quiet work area", "Demo setup", "Test scene 3"])),
        1 => format!("{body}, leaving a clear path to the door"),
        2 => format!("{body} with a free route to the exit"),
        3 => format!("{body}, with enough space between them to walk"),
        _ => format!("{body} along one side of the room"),
    };
    let mut want = Meaning::default();
    want.counts.insert(f.cat.into(), 1);
    want.counts.insert(g.cat.into(), 1);
    Case { prompt, want, with_room: false }
}

/// One on each side: "a chair on either side of the desk", "two chairs, one on each side
/// of the desk", "a desk flanked by two chairs", "chairs on both sides of the desk".
fn each_side(rng: &mut Rng) -> Case {
    let h = *rng.pick(&[nouns(Role::Surface), nouns(Role::Floor)].concat());
    let mut c = *rng.pick(&nouns(Role::Floor));
    while c.cat == h.cat {
        c = *rng.pick(&nouns(Role::Floor));
    }
    let (hf, cf) = (h.forms[0], c.forms[0]);
    let host = format!("{} {hf}", article(hf));
    let two = counted(rng, 2, cf);
    let prompt = match rng.below(5) {
        0 => format!("{} {cf} on either side of the {hf}", article(cf)),
        1 => format!("{} {cf} on each side of {host}", article(cf)),
        2 => format!("{host} flanked by {two}"),
        3 => format!("{} on both sides of {host}", two),
        _ => format!("{}. Put {} {cf} on either side of it.", capitalise(&host), article(cf)),
    };
    let mut want = Meaning::default();
    want.counts.insert(h.cat.into(), 1);
    want.counts.insert(c.cat.into(), 2);
    want.relations.insert(rel(c.cat, "on_each_side_of", Some(h.cat)));
    Case { prompt, want, with_room: false }
}

/// Corners: "a plant in each corner" (four), "four plants in the corners", "plants in
/// all four corners", "two plants in two corners".
fn corners(rng: &mut Rng) -> Case {
    let f = *rng.pick(&nouns(Role::Floor));
    let ff = f.forms[0];
    let (prompt, n) = match rng.below(5) {
        0 => (format!("{} {ff} in each corner", article(ff)), 4),
        1 => (format!("Put {} {ff} in every corner of the room.", article(ff)), 4),
        2 => (format!("four {} in the corners", plural(ff)), 4),
        3 => (format!("{} in all four corners", plural(ff)), 4),
        _ => (format!("two {} in two corners", plural(ff)), 2),
    };
    let mut want = Meaning::default();
    want.counts.insert(f.cat.into(), n);
    want.relations.insert(rel(f.cat, "in_corners", None));
    Case { prompt, want, with_room: false }
}

/// Stacks: "three stacks of four crates", "crates in three stacks, four high", "a stack
/// of five crates", "crates stacked five high".
fn stacks(rng: &mut Rng) -> Case {
    let (cat, noun) =
        *rng.pick(&[("crate", "crate"), ("cardboard_box", "box"), ("pallet", "pallet"), ("book", "book")]);
    let stacks = 2 + rng.below(3) as u32;
    let high = 2 + rng.below(4) as u32;
    let w = |n: u32| NUMBER_WORDS[n as usize];
    let (prompt, count, n, k) = match rng.below(4) {
        0 => (format!("{} stacks of {} {}", w(stacks), w(high), plural(noun)), stacks * high, Some(high), Some(stacks)),
        1 => (
            format!("{} stacks of {}, {} high", w(stacks), plural(noun), w(high)),
            stacks * high,
            Some(high),
            Some(stacks),
        ),
        2 => (format!("a stack of {} {}", w(high), plural(noun)), high, None, None),
        _ => (format!("{} stacked {} high", plural(noun), w(high)), high, Some(high), None),
    };
    let mut want = Meaning::default();
    want.counts.insert(cat.into(), count);
    want.relations.insert(format!("{cat} stacked n={n:?} stacks={k:?}"));
    Case { prompt, want, with_room: false }
}

/// Taking back: "a desk, a chair (skip that) and a lamp", "a desk and a stool… no, a
/// chair", "two lamps (ignore) and a desk".
fn retractions(rng: &mut Rng) -> Case {
    let a = *rng.pick(&nouns(Role::Surface));
    let b = *rng.pick(&nouns(Role::Floor));
    let mut c = *rng.pick(&nouns(Role::Floor));
    while c.cat == b.cat {
        c = *rng.pick(&nouns(Role::Floor));
    }
    let (af, bf, cf) = (a.forms[0], b.forms[0], c.forms[0]);
    let prompt = match rng.below(3) {
        0 => format!("{} {af}, {} {bf} (skip that) and {} {cf}", article(af), article(bf), article(cf)),
        1 => format!("{} {af} and {} {bf}... no, {} {cf}", article(af), article(bf), article(cf)),
        _ => format!("two {} (ignore), {} {af} and {} {cf}", plural(bf), article(af), article(cf)),
    };
    let mut want = Meaning::default();
    want.counts.insert(a.cat.into(), 1);
    want.counts.insert(c.cat.into(), 1);
    Case { prompt, want, with_room: false }
}

/// Typos in nouns and relation words: two letters swapped in a noun, a letter dropped
/// from "between" or "against".
fn typos(rng: &mut Rng) -> Case {
    let swap = |w: &str, at: usize| -> String {
        let mut c: Vec<char> = w.chars().collect();
        if at + 1 < c.len() {
            c.swap(at, at + 1);
        }
        c.into_iter().collect()
    };
    let pick =
        [("chair", "chair"), ("table", "table"), ("cabinet", "cabinet"), ("laptop", "laptop"), ("fridge", "fridge")];
    let (cat, w) = *rng.pick(&pick);
    let typo = swap(w, 1 + rng.below(w.len() - 3));
    let (prompt, relation) = match rng.below(3) {
        0 => (format!("a {typo} agianst the wall"), "against_wall"),
        1 => (format!("a {typo} in the corner"), "in_corner"),
        _ => (format!("a {typo} by the door"), "near_door"),
    };
    let mut want = Meaning::default();
    want.counts.insert(cat.into(), 1);
    want.relations.insert(rel(cat, relation, None));
    Case { prompt, want, with_room: false }
}

/// Imperial sizes: "a 6 ft long table", "a table 36 in wide", "a 6' table".
fn imperial(rng: &mut Rng) -> Case {
    let s = *rng.pick(&nouns(Role::Surface));
    let sf = s.forms[0];
    let feet = 3 + rng.below(6) as i64;
    let (prompt, name, mm) = match rng.below(4) {
        0 => (format!("a {feet} ft long {sf}"), "length", (feet as f64 * 304.8).round() as i64),
        1 => {
            (format!("{} {sf} {} in wide", article(sf), feet * 12), "width", (feet as f64 * 12.0 * 25.4).round() as i64)
        }
        2 => (format!("a {feet}' {sf}"), "length", (feet as f64 * 304.8).round() as i64),
        _ => (format!("{} {sf}, {feet} feet long", article(sf)), "length", (feet as f64 * 304.8).round() as i64),
    };
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    want.sizes.insert(s.cat.into(), vec![(name, mm)]);
    Case { prompt, want, with_room: false }
}

/// Ends: "a bin at the end of the workbench", "a bin at both ends of the workbench" (two).
fn ends(rng: &mut Rng) -> Case {
    let s = *rng.pick(&nouns(Role::Surface));
    let f = *rng.pick(&nouns(Role::Floor));
    let (sf, ff) = (s.forms[0], f.forms[0]);
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    let prompt = match rng.below(3) {
        0 => {
            want.counts.insert(f.cat.into(), 1);
            want.relations.insert(rel(f.cat, "at_end_of", Some(s.cat)));
            want.relations.insert(rel(f.cat, "at_end_of_row", Some(s.cat)));
            format!("{} {sf} with {} {ff} at one end of it", article(sf), article(ff))
        }
        1 => {
            want.counts.insert(f.cat.into(), 1);
            want.relations.insert(rel(f.cat, "at_end_of", Some(s.cat)));
            want.relations.insert(rel(f.cat, "at_end_of_row", Some(s.cat)));
            format!("{} {ff} at the end of {} {sf}", article(ff), article(sf))
        }
        _ => {
            want.counts.insert(f.cat.into(), 2);
            want.relations.insert(rel(f.cat, "at_end_of", Some(s.cat)) + " end=both");
            want.relations.insert(rel(f.cat, "at_end_of_row", Some(s.cat)));
            format!("{} {ff} at both ends of {} {sf}", article(ff), article(sf))
        }
    };
    Case { prompt, want, with_room: false }
}

/// A noun that only modifies another is no object: "a robot assembly cell with …" has no
/// robot, "a storage room with …" no storage, "the warehouse floor" no warehouse object.
fn modifier_nouns(rng: &mut Rng) -> Case {
    let f = *rng.pick(&nouns(Role::Floor));
    let s = *rng.pick(&nouns(Role::Surface));
    let body = format!("{} {} and {} {}", article(f.forms[0]), f.forms[0], article(s.forms[0]), s.forms[0]);
    let prompt = match rng.below(4) {
        0 => format!("a robot assembly cell with {body}"),
        1 => format!("A robot welding line: {body}."),
        2 => format!("{body} on the warehouse floor"),
        _ => format!("a robot test cell with {body}"),
    };
    let mut want = Meaning::default();
    want.counts.insert(f.cat.into(), 1);
    want.counts.insert(s.cat.into(), 1);
    Case { prompt, want, with_room: false }
}

/// A robot named as the subject of a verb, its model in brackets, a robot that is a
/// machine: "a Panda waits next to a table", "a robot arm (UR10e) next to a table", "a
/// robot vacuum cleaner".
fn robots_named(rng: &mut Rng) -> Case {
    let s = *rng.pick(&nouns(Role::Surface));
    let sf = s.forms[0];
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    let prompt = match rng.below(3) {
        0 => {
            want.counts.insert("robot:ur10e".into(), 1);
            want.relations.insert(rel("ur10e", "next_to", Some(s.cat)));
            want.relations.insert(rel("ur10e", "reach", Some(s.cat)));
            format!("a robot arm (UR10e) next to {} {sf}", article(sf))
        }
        1 => {
            want.counts.insert("robot:panda".into(), 1);
            want.relations.insert(rel("panda", "next_to", Some(s.cat)));
            want.relations.insert(rel("panda", "reach", Some(s.cat)));
            format!("a Panda waits next to {} {sf}", article(sf))
        }
        _ => {
            want.counts.insert("robot:turtlebot3".into(), 1);
            format!("a robot vacuum cleaner and {} {sf}", article(sf))
        }
    };
    Case { prompt, want, with_room: false }
}

// ------------------------------------------------------------------ the test

/// Three different floor things, by role.
fn three_floor(rng: &mut Rng) -> [&'static Noun; 3] {
    let all = nouns(Role::Floor);
    let a = *rng.pick(&all);
    let mut b = *rng.pick(&all);
    while b.cat == a.cat {
        b = *rng.pick(&all);
    }
    let mut c = *rng.pick(&all);
    while c.cat == a.cat || c.cat == b.cat {
        c = *rng.pick(&all);
    }
    [a, b, c]
}

/// Coordinated targets: "a stool next to the cabinet and the fridge" is next to both;
/// "a table with a mug and two bowls on it" puts both on it; "a sofa with a chair and a
/// plant next to it" sets both next to the sofa.
fn coordination(rng: &mut Rng) -> Case {
    let [a, b, c] = three_floor(rng);
    let (cue, relation): (&str, &str) =
        *rng.pick(&[("next to", "next_to"), ("beside", "next_to"), ("near", "near"), ("close to", "near")]);
    let (af, bf, cf) = (a.forms[0], b.forms[0], c.forms[0]);
    let mut want = Meaning::default();
    let prompt = if rng.chance(0.5) {
        // One subject, two targets.
        let intro = list(rng, &[format!("{} {bf}", article(bf)), format!("{} {cf}", article(cf))]);
        let p = match rng.below(4) {
            0 => format!("{} {af} {cue} the {bf} and the {cf}", article(af)),
            1 => format!("{intro}, and {} {af} {cue} the {bf} and the {cf}", article(af)),
            2 => format!("{}. Put {} {af} {cue} the {bf} and the {cf}.", capitalise(&intro), article(af)),
            _ => format!("{} {af} {cue} the {bf} and the {cf}, in an office", article(af)),
        };
        want.relations.insert(rel(a.cat, relation, Some(b.cat)));
        want.relations.insert(rel(a.cat, relation, Some(c.cat)));
        p
    } else {
        // Two things listed after "with", one relation to the host.
        let s = *rng.pick(&nouns(Role::Surface));
        let sf = s.forms[0];
        let i1 = *rng.pick(&nouns(Role::Item));
        let mut i2 = *rng.pick(&nouns(Role::Item));
        while i2.cat == i1.cat {
            i2 = *rng.pick(&nouns(Role::Item));
        }
        let n = 1 + rng.below(3) as u32;
        let first = counted(rng, 1, i1.forms[0]);
        let second = counted(rng, n, i2.forms[0]);
        let p = if rng.chance(0.5) {
            want.relations.insert(rel(i1.cat, "on", Some(s.cat)));
            want.relations.insert(rel(i2.cat, "on", Some(s.cat)));
            want.counts.insert(s.cat.into(), 1);
            want.counts.insert(i1.cat.into(), 1);
            want.counts.insert(i2.cat.into(), n);
            format!("{} {sf} with {first} and {second} on it", article(sf))
        } else {
            want.relations.insert(rel(b.cat, relation, Some(a.cat)));
            want.relations.insert(rel(c.cat, relation, Some(a.cat)));
            format!("{} {af} with {} {bf} and {} {cf} {cue} it", article(af), article(bf), article(cf))
        };
        if !want.counts.is_empty() {
            return Case { prompt: p, want, with_room: false };
        }
        p
    };
    for x in [a, b, c] {
        want.counts.insert(x.cat.into(), 1);
    }
    Case { prompt, want, with_room: false }
}

/// A measure of something is that thing, counted by the measure: "two pieces of cake on
/// a plate" is two cakes; "a bunch of" and "a slice of" count one each.
fn measures(rng: &mut Rng) -> Case {
    // (what is measured, its category)
    const MEASURED: &[(&str, &str)] = &[("bread", "bread_loaf"), ("cheese", "cheese"), ("soap", "soap_bar")];
    let (stuff, cat) = *rng.pick(MEASURED);
    let (one, many) = *rng.pick(&[("piece", "pieces"), ("slice", "slices"), ("portion", "portions"), ("bar", "bars")]);
    let n = 1 + rng.below(4) as u32;
    let q = if n == 1 {
        format!("{} {one}", if rng.chance(0.5) { "a" } else { "one" })
    } else {
        format!("{} {many}", if rng.chance(0.5) { n.to_string() } else { NUMBER_WORDS[n as usize].to_string() })
    };
    let s = *rng.pick(&nouns(Role::Surface));
    let sf = s.forms[0];
    let prompt = match rng.below(3) {
        0 => format!("{q} of {stuff} on {} {sf}", article(sf)),
        1 => format!("{} {sf} with {q} of {stuff} on it", article(sf)),
        _ => format!("Put {q} of {stuff} on {} {sf}.", article(sf)),
    };
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    want.counts.insert(cat.into(), n);
    want.relations.insert(rel(cat, "on", Some(s.cat)));
    Case { prompt, want, with_room: false }
}

/// Parts of a thing are no things of their own: "a cabinet with three drawers", "its
/// door", "every shelf of the bookcase", "a box with a lid"; and a count in brackets after
/// a plural is its count ("mugs (3)").
fn parts_and_bracket_counts(rng: &mut Rng) -> Case {
    let s = *rng.pick(&nouns(Role::Surface));
    let sf = s.forms[0];
    let i = *rng.pick(&nouns(Role::Item));
    let n = 2 + rng.below(5) as u32;
    let items = if rng.chance(0.5) { format!("{} ({n})", plural(i.forms[0])) } else { counted(rng, n, i.forms[0]) };
    let k = 1 + rng.below(4) as u32;
    let drawers = if k == 1 { "a drawer".to_string() } else { format!("{} drawers", NUMBER_WORDS[k as usize]) };
    let prompt = match rng.below(5) {
        0 => format!("{} {sf} with {drawers}, and {items} on it", article(sf)),
        1 => format!("{items} on {} {sf} with {drawers}", article(sf)),
        2 => format!("{} {sf} with its drawers open and {items} on the {sf}", article(sf)),
        3 => format!("{items} on the top of {} {sf}; the drawer of the {sf} is open", article(sf)),
        _ => format!("{} {sf} with {drawers} and a handle, {items} on it", article(sf)),
    };
    let mut want = Meaning::default();
    want.counts.insert(s.cat.into(), 1);
    want.counts.insert(i.cat.into(), n);
    want.relations.insert(rel(i.cat, "on", Some(s.cat)));
    Case { prompt, want, with_room: false }
}

/// Cases per family; each plans in well under a millisecond.
const PER_FAMILY: usize = 400;

#[test]
fn every_wording_of_a_scene_gives_the_same_plan() {
    type Family = (&'static str, fn(&mut Rng) -> Case);
    let families: &[Family] = &[
        ("lists", lists),
        ("on_surface", on_surface),
        ("distribution", distribution),
        ("room_places", room_places),
        ("floor_pairs", floor_pairs),
        ("sizes", sizes),
        ("room_sizes", room_sizes),
        ("quantities", quantities),
        ("references", references),
        ("no_objects_from_places", no_objects_from_places),
        ("each_side", each_side),
        ("corners", corners),
        ("stacks", stacks),
        ("retractions", retractions),
        ("typos", typos),
        ("imperial", imperial),
        ("ends", ends),
        ("modifier_nouns", modifier_nouns),
        ("robots_named", robots_named),
        ("coordination", coordination),
        ("measures", measures),
        ("parts_and_bracket_counts", parts_and_bracket_counts),
    ];
    let mut report = String::new();
    let mut total = 0;
    let mut failed = 0;
    for (name, make) in families {
        let (f, n, lines) = run_family(name, PER_FAMILY, *make);
        total += n;
        failed += f;
        let _ = writeln!(report, "{name}: {}/{n} read the same", n - f);
        report.push_str(&lines);
    }
    eprintln!("{report}");
    assert!(failed == 0, "{failed} of {total} wordings read differently:\n{report}");
}
