//! `bench scenes --suite FILE.jsonl`: the relation suite (`bench/relations/suite.jsonl`)
//! through the pipeline — every prompt on seeds 1..=N — with the pass rate of each
//! relation as `report.json` measured it on the written scene, the share of prompts with
//! every relation held, and the object and robot counts against the suite's. The
//! independent judge (`bench/relations/judge.py`) measures the same packages its own way.

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

use serde::{Deserialize, Serialize};
use sw_pipeline::Options;
use sw_plan::{LaidOutScene, Relation, RelationCheck, RelationKind, Status};

use crate::Failure;
use crate::output::{print, print_json};

/// One line of the suite.
#[derive(Debug, Clone, Deserialize)]
pub(crate) struct SuiteLine {
    pub id: String,
    pub prompt: String,
    #[serde(default)]
    pub counts: BTreeMap<String, u32>,
    #[serde(default)]
    pub min_counts: BTreeMap<String, u32>,
    #[serde(default)]
    pub robots: BTreeMap<String, u32>,
    #[serde(default)]
    pub allow_extra: Vec<String>,
    #[serde(default)]
    pub relations: Vec<Expected>,
}

/// A relation the suite expects (the suite's own field names).
#[derive(Debug, Clone, Deserialize)]
pub(crate) struct Expected {
    pub subject: String,
    pub relation: String,
    #[serde(default)]
    pub target: Option<String>,
    #[serde(default)]
    pub target2: Option<String>,
    #[serde(default)]
    pub wall: Option<String>,
}

/// Reads a JSONL suite; a bad line is an input error naming its number.
pub(crate) fn parse(text: &str) -> Result<Vec<SuiteLine>, Failure> {
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let l: SuiteLine =
            serde_json::from_str(line).map_err(|e| Failure::input(format!("suite line {}: {e}", i + 1)))?;
        out.push(l);
    }
    Ok(out)
}

#[derive(Debug, Default, Serialize)]
struct Rate {
    held: u32,
    cases: u32,
}

#[derive(Debug, Serialize)]
struct Miss {
    id: String,
    seed: u64,
    relation: String,
    subject: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    target: Option<String>,
    why: String,
}

#[derive(Debug, Serialize)]
struct RelationsResult {
    prompts: usize,
    seeds: u64,
    scenes: usize,
    verified: usize,
    per_relation: BTreeMap<String, Rate>,
    held: u32,
    cases: u32,
    /// Scenes with every expected relation held.
    all_held: usize,
    /// Scenes whose object and robot counts are the suite's.
    counts_exact: usize,
    /// Scenes with an arm, and those whose every reach relation held.
    arm_scenes: usize,
    arm_scenes_reach_held: usize,
    p50_ms: f64,
    max_ms: f64,
    misses: Vec<Miss>,
    /// Scenes whose counts are not the suite's: what was found.
    count_misses: Vec<String>,
}

/// Whether a suite key (`a|b|c`, `arm`, `mobile`, a category or model) names `category`.
fn key_matches(key: &str, category: &str) -> bool {
    key.split('|').any(|k| match k {
        "arm" => sw_robots::find(category).is_some_and(|d| d.kind == sw_robots::RobotKind::Arm),
        "mobile" => sw_robots::find(category).is_some_and(|d| d.kind != sw_robots::RobotKind::Arm),
        k => k == category,
    })
}

fn wall_of(kind: &RelationKind) -> Option<&'static str> {
    match kind {
        RelationKind::AgainstWall { wall } | RelationKind::Leaning { wall } | RelationKind::AtEnd { wall } => {
            wall.map(|w| w.name())
        }
        _ => None,
    }
}

/// The suite's name for a group: the name its bodies are written under, `<category>_<n>`
/// without the number (a proxy's label, "part"), or a robot group's model. This is the
/// judge's convention, so both routes match relations to the suite the same way.
fn group_key(layout: &LaidOutScene, group: &str, fallback: &str) -> String {
    layout
        .objects
        .iter()
        .find(|o| o.group == group)
        .map(|o| body_key(&o.name))
        .or_else(|| layout.robots.iter().find(|r| r.group == group).map(|r| r.model.clone()))
        .unwrap_or_else(|| fallback.to_string())
}

/// `shelf_12` -> `shelf`.
fn body_key(name: &str) -> String {
    match name.rsplit_once('_') {
        Some((head, n)) if !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()) => head.to_string(),
        _ => name.to_string(),
    }
}

/// The report's check of an expected relation, if the report states it.
fn find<'a>(checks: &'a [RelationCheck], layout: &LaidOutScene, e: &Expected) -> Option<&'a RelationCheck> {
    checks.iter().find(|c| {
        let Relation { kind, subject } = &c.relation;
        if kind.name() != e.relation || !key_matches(&e.subject, &group_key(layout, subject, &c.subject_category)) {
            return false;
        }
        let targets: Vec<String> = match kind {
            RelationKind::Between { first, second } => vec![first.clone(), second.clone()],
            k => k.targets().iter().map(|t| t.to_string()).collect(),
        };
        let target_key = |i: usize| {
            targets.get(i).map(|t| group_key(layout, t, c.target_categories.get(i).map_or("", |x| x.as_str())))
        };
        if let Some(t) = &e.target
            && !target_key(0).is_some_and(|x| key_matches(t, &x))
        {
            return false;
        }
        if let Some(t2) = &e.target2
            && !target_key(1).is_some_and(|x| key_matches(t2, &x))
        {
            return false;
        }
        e.wall.as_deref().is_none_or(|w| wall_of(kind) == Some(w))
    })
}

/// Object and robot counts against the suite's: exact per key, at least per `min`
/// key, no category the line does not name in its counts or relations (a robot's pedestal
/// or cart aside).
fn counts_held(line: &SuiteLine, objects: &BTreeMap<String, u32>, robots: &BTreeMap<String, u32>) -> bool {
    let sum = |map: &BTreeMap<String, u32>, key: &str| -> u32 {
        map.iter().filter(|(c, _)| key_matches(key, c)).map(|(_, n)| n).sum()
    };
    let exact = line.counts.iter().all(|(k, n)| sum(objects, k) == *n);
    let at_least = line.min_counts.iter().all(|(k, n)| sum(objects, k) >= *n);
    let robots_ok = line.robots.iter().all(|(k, n)| sum(robots, k) == *n)
        && robots.keys().all(|m| line.robots.keys().any(|k| key_matches(k, m)));
    let named = |c: &str| {
        line.counts.keys().chain(line.min_counts.keys()).any(|k| key_matches(k, c))
            || line.relations.iter().any(|r| {
                [Some(&r.subject), r.target.as_ref(), r.target2.as_ref()]
                    .into_iter()
                    .flatten()
                    .any(|k| key_matches(k, c))
            })
            || line.allow_extra.iter().any(|a| a == c)
            || matches!(c, "pedestal" | "mobile_cart")
    };
    exact && at_least && robots_ok && objects.keys().all(|c| named(c))
}

/// Runs the suite on seeds 1..=`seeds`.
pub(crate) fn run(lines: &[SuiteLine], seeds: u64, json: bool) -> Result<u8, Failure> {
    if lines.is_empty() {
        return Err(Failure::input("the suite holds no prompts"));
    }
    let scratch = tempfile::tempdir().map_err(|e| Failure::internal(e.to_string()))?;
    let mut r = RelationsResult {
        prompts: lines.len(),
        seeds: seeds.max(1),
        scenes: 0,
        verified: 0,
        per_relation: BTreeMap::new(),
        held: 0,
        cases: 0,
        all_held: 0,
        counts_exact: 0,
        arm_scenes: 0,
        arm_scenes_reach_held: 0,
        p50_ms: 0.0,
        max_ms: 0.0,
        misses: Vec::new(),
        count_misses: Vec::new(),
    };
    let mut times = Vec::new();
    let mut n = 0u64;
    for line in lines {
        for seed in 1..=seeds.max(1) {
            n += 1;
            let out = scratch.path().join(format!("run{n}"));
            let t0 = Instant::now();
            let result =
                sw_pipeline::generate(&line.prompt, &out, &Options { seed, ..Options::default() }, &mut |_| {});
            times.push(t0.elapsed().as_secs_f64() * 1000.0);
            r.scenes += 1;
            let (checks, layout, objects, robots) = match &result {
                Ok(o) => {
                    r.verified += usize::from(o.report.status == Status::Verified);
                    let mut objects: BTreeMap<String, u32> = BTreeMap::new();
                    for x in &o.layout.objects {
                        *objects.entry(body_key(&x.name)).or_insert(0) += 1;
                    }
                    let mut robots: BTreeMap<String, u32> = BTreeMap::new();
                    for x in &o.layout.robots {
                        *robots.entry(x.model.clone()).or_insert(0) += 1;
                    }
                    (o.report.relations.clone(), Some(o.layout.clone()), objects, robots)
                }
                Err(_) => (Vec::new(), None, BTreeMap::new(), BTreeMap::new()),
            };
            let mut all = true;
            let mut reach_all = true;
            let has_reach = line.relations.iter().any(|e| e.relation == "reach");
            for e in &line.relations {
                let found = layout.as_ref().and_then(|l| find(&checks, l, e));
                let held = found.is_some_and(|c| c.held);
                let rate = r.per_relation.entry(e.relation.clone()).or_default();
                rate.cases += 1;
                rate.held += u32::from(held);
                r.cases += 1;
                r.held += u32::from(held);
                all &= held;
                if e.relation == "reach" {
                    reach_all &= held;
                }
                if !held {
                    let why = match (&result, found) {
                        (Err(err), _) => format!("no package: {err}"),
                        (Ok(_), None) => "not among the report's relations".to_string(),
                        (Ok(_), Some(c)) => c.reason.clone().unwrap_or_default(),
                    };
                    r.misses.push(Miss {
                        id: line.id.clone(),
                        seed,
                        relation: e.relation.clone(),
                        subject: e.subject.clone(),
                        target: e.target.clone(),
                        why,
                    });
                }
            }
            r.all_held += usize::from(all);
            let counts_ok = result.is_ok() && counts_held(line, &objects, &robots);
            r.counts_exact += usize::from(counts_ok);
            if !counts_ok {
                r.count_misses.push(format!("{} seed {seed}: objects {objects:?}, robots {robots:?}", line.id));
            }
            if has_reach {
                r.arm_scenes += 1;
                r.arm_scenes_reach_held += usize::from(reach_all);
            }
            let _ = std::fs::remove_dir_all(&out);
        }
    }
    times.sort_by(f64::total_cmp);
    r.p50_ms = (times[times.len() / 2] * 100.0).round() / 100.0;
    r.max_ms = (times[times.len() - 1] * 100.0).round() / 100.0;
    if json {
        print_json(&r);
    } else {
        print(&table(&r));
    }
    Ok(0)
}

fn pct(a: u32, b: u32) -> f64 {
    100.0 * f64::from(a) / f64::from(b.max(1))
}

fn table(r: &RelationsResult) -> String {
    let mut lines = vec![
        format!(
            "{} prompts × {} seeds = {} scenes · verified {}/{}",
            r.prompts, r.seeds, r.scenes, r.verified, r.scenes
        ),
        format!("{:<18} {:>13} {:>7}", "relation", "held / cases", "rate"),
    ];
    let mut rows: Vec<(&String, &Rate)> = r.per_relation.iter().collect();
    rows.sort_by(|a, b| pct(a.1.held, a.1.cases).total_cmp(&pct(b.1.held, b.1.cases)).then(a.0.cmp(b.0)));
    for (name, rate) in rows {
        lines.push(format!(
            "{:<18} {:>13} {:>6.1}%",
            name,
            format!("{} / {}", rate.held, rate.cases),
            pct(rate.held, rate.cases)
        ));
    }
    lines.push(format!("{:<18} {:>13} {:>6.1}%", "all", format!("{} / {}", r.held, r.cases), pct(r.held, r.cases)));
    let share = |a: usize, b: usize| 100.0 * a as f64 / b.max(1) as f64;
    lines.push(format!(
        "every relation held {}/{} ({:.1} %) · counts exact {}/{} ({:.1} %) · arms with every reach held {}/{} · p50 {:.0} ms, max {:.0} ms",
        r.all_held,
        r.scenes,
        share(r.all_held, r.scenes),
        r.counts_exact,
        r.scenes,
        share(r.counts_exact, r.scenes),
        r.arm_scenes_reach_held,
        r.arm_scenes,
        r.p50_ms,
        r.max_ms
    ));
    for m in &r.count_misses {
        lines.push(format!("counts   {m}"));
    }
    for m in &r.misses {
        lines.push(format!("miss     {} seed {}: {} {}: {}", m.id, m.seed, m.subject, m.relation, m.why));
    }
    lines.join("\n")
}

/// True when `path` names a JSONL relation suite.
pub(crate) fn is_suite(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "jsonl")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suite_keys_name_categories_alternatives_and_robot_kinds() {
        assert!(key_matches("shelf|pallet_rack", "pallet_rack"));
        assert!(!key_matches("shelf|pallet_rack", "gondola_shelf"));
        assert!(key_matches("arm", "ur5e") && key_matches("arm", "panda"));
        assert!(!key_matches("arm", "turtlebot3"));
        assert!(key_matches("mobile", "turtlebot3") && key_matches("mobile", "mobile_manipulator"));
    }

    #[test]
    fn counts_need_every_named_category_and_nothing_unnamed_but_robot_stands() {
        let line: SuiteLine = serde_json::from_str(
            r#"{"id": "x", "prompt": "p", "counts": {"desk": 2}, "min_counts": {"cardboard_box": 2},
                "robots": {"arm": 1}, "relations": []}"#,
        )
        .unwrap();
        let objs = |v: &[(&str, u32)]| v.iter().map(|(k, n)| (k.to_string(), *n)).collect::<BTreeMap<_, _>>();
        let ur5e = objs(&[("ur5e", 1)]);
        assert!(counts_held(&line, &objs(&[("desk", 2), ("cardboard_box", 5), ("pedestal", 1)]), &ur5e));
        assert!(!counts_held(&line, &objs(&[("desk", 3), ("cardboard_box", 5)]), &ur5e));
        assert!(!counts_held(&line, &objs(&[("desk", 2), ("cardboard_box", 1)]), &ur5e));
        assert!(!counts_held(&line, &objs(&[("desk", 2), ("cardboard_box", 2), ("row", 1)]), &ur5e));
        assert!(!counts_held(&line, &objs(&[("desk", 2), ("cardboard_box", 2)]), &objs(&[("turtlebot3", 1)])));
    }
}
