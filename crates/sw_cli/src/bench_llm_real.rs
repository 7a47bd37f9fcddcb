//! `bench llm-real`: the LLM stages against a real OpenAI-compatible server and a real
//! model (`scripts/setup.sh --real-llm` provides llama.cpp's and llama-cpp-python's
//! servers with SmolLM2-135M-Instruct). For each prompt of an annotated suite
//! (`bench/llm/grounding.jsonl`: the room kind, the counts and the robots the prompt
//! states, written by hand) it asks for a plan (streamed, grounded, falling back offline
//! on failure), relations for it, and — on every fourth prompt — an edit of the offline
//! package, then reports per stage: calls, how many the server accepted without an HTTP
//! error, how many were cut off at their token limit and after how many attempts, the
//! slowest call, and whether the final plan keeps every stated fact.

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};
use serde_json::json;
use sw_llm::{Client, Endpoint, LlmCall, LlmConfig, LlmOutcome, LlmStage, Telemetry};
use sw_pipeline::{EditReader, Options};
use sw_plan::ScenePlan;

use crate::Failure;
use crate::output::{print, print_json};

/// One annotated prompt.
#[derive(Debug, Clone, Deserialize)]
struct Case {
    prompt: String,
    room: String,
    #[serde(default)]
    size: Option<[f64; 2]>,
    objects: std::collections::BTreeMap<String, u32>,
    robots: std::collections::BTreeMap<String, u32>,
}

/// How many of a thing the plan holds: groups of that category, else proxies whose label
/// has it as a word. Phrases are not read: a model writes any words there ("a car and a
/// TurtleBot" for an air compressor), and the scene holds what the category or label is.
fn count_of(plan: &ScenePlan, noun: &str) -> u32 {
    let by_category: u32 = plan.objects.iter().filter(|o| o.category == noun).map(|o| o.count).sum();
    if by_category > 0 {
        return by_category;
    }
    let singular = |w: &str| w.trim_end_matches('s').to_string();
    let wanted: Vec<String> = noun.split('_').map(singular).collect();
    plan.objects
        .iter()
        .filter(|o| {
            o.proxy.as_ref().is_some_and(|p| {
                let label: Vec<String> = p.label.to_lowercase().split_whitespace().map(singular).collect();
                label.windows(wanted.len()).any(|w| w == wanted.as_slice())
            })
        })
        .map(|o| o.count)
        .sum()
}

/// The stated facts the plan does not keep, in words.
fn unkept(plan: &ScenePlan, case: &Case) -> Vec<String> {
    let mut out = Vec::new();
    if plan.room.kind.name() != case.room {
        out.push(format!("room {} (said {})", plan.room.kind.name(), case.room));
    }
    if let Some([w, d]) = case.size
        && !(plan.room.size_fixed && (plan.room.size.width - w).abs() < 0.01 && (plan.room.size.depth - d).abs() < 0.01)
    {
        out.push(format!("room size {} × {} (said {w} × {d})", plan.room.size.width, plan.room.size.depth));
    }
    for (noun, n) in &case.objects {
        let got = count_of(plan, noun);
        if got != *n {
            out.push(format!("{noun} {got} (said {n})"));
        }
    }
    let mut robots: std::collections::BTreeMap<String, u32> = std::collections::BTreeMap::new();
    for r in &plan.robots {
        *robots.entry(r.model.clone()).or_default() += r.count;
    }
    if robots != case.robots {
        out.push(format!("robots {robots:?} (said {:?})", case.robots));
    }
    out
}

/// A call the server took: no attempt ended in an HTTP error status or a broken
/// connection, whatever the model then wrote.
fn accepted(c: &LlmCall) -> bool {
    let http = |e: &str| e.contains("HTTP ") || e.contains("connection");
    let final_ok = matches!(c.outcome, LlmOutcome::Ok | LlmOutcome::Length | LlmOutcome::Unusable);
    final_ok && !c.attempt_errors.iter().any(|e| http(e))
}

#[derive(Debug, Default, Serialize)]
struct StageRow {
    calls: usize,
    accepted: usize,
    /// Accepted once the endpoint's dialect was learnt (the first call of a process may
    /// step down from `json_schema` once).
    accepted_after_negotiation: usize,
    cut_off: usize,
    cut_off_max_attempts: u32,
    p50_s: f64,
    max_s: f64,
}

fn rows(calls: &[LlmCall]) -> Vec<(LlmStage, StageRow)> {
    let mut out = Vec::new();
    for stage in [LlmStage::Plan, LlmStage::Relations, LlmStage::Edit] {
        let of: Vec<&LlmCall> = calls.iter().filter(|c| c.stage == stage).collect();
        if of.is_empty() {
            continue;
        }
        let mut secs: Vec<f64> = of.iter().map(|c| c.latency_ms / 1000.0).collect();
        secs.sort_by(f64::total_cmp);
        let negotiated = |c: &&&LlmCall| {
            let refusals = c.attempt_errors.iter().filter(|e| e.contains("response_format")).count();
            let rest = LlmCall {
                attempt_errors: c.attempt_errors[refusals.min(c.attempt_errors.len())..].to_vec(),
                ..(**c).clone()
            };
            accepted(&rest)
        };
        let cut: Vec<&&LlmCall> = of.iter().filter(|c| c.outcome == LlmOutcome::Length).collect();
        out.push((
            stage,
            StageRow {
                calls: of.len(),
                accepted: of.iter().filter(|c| accepted(c)).count(),
                accepted_after_negotiation: of.iter().filter(negotiated).count(),
                cut_off: cut.len(),
                // Attempts that produced tokens (a dialect refusal produces none).
                cut_off_max_attempts: cut
                    .iter()
                    .map(|c| {
                        1 + c.retries - c.attempt_errors.iter().filter(|e| e.contains("response_format")).count() as u32
                    })
                    .max()
                    .unwrap_or(0),
                p50_s: secs[secs.len() / 2],
                max_s: secs.last().copied().unwrap_or(0.0),
            },
        ));
    }
    out
}

pub(crate) fn run(base_url: &str, model: &str, suite: Option<PathBuf>, json_out: bool) -> Result<u8, Failure> {
    let path = suite.unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/llm/grounding.jsonl"));
    let text = std::fs::read_to_string(&path)
        .map_err(|e| Failure::input(format!("cannot read the suite '{}': {e}", path.display())))?;
    let cases: Vec<Case> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .enumerate()
        .map(|(i, l)| serde_json::from_str(l).map_err(|e| Failure::input(format!("{}:{}: {e}", path.display(), i + 1))))
        .collect::<Result<_, _>>()?;
    let ep = Endpoint::new(base_url, model);
    let client = Client::new(LlmConfig::offline().with_all(ep));
    let scratch = tempfile::tempdir().map_err(|e| Failure::internal(format!("scratch directory: {e}")))?;
    let started = Instant::now();
    let mut kept = 0usize;
    let mut model_plans = 0usize;
    let mut per_prompt = Vec::new();
    let mut all: Vec<LlmCall> = Vec::new();
    for (i, case) in cases.iter().enumerate() {
        // Every call of the prompt, the edit's too (it takes its own fresh client and
        // keeps its calls only in a record it writes when it succeeds).
        let tap = Telemetry::default();
        let c = client.fresh_tapped(&tap);
        let (mut plan, warnings) =
            sw_pipeline::plan_with_llm(&case.prompt, &c, true).map_err(|e| Failure::internal(e.to_string()))?;
        let fell_back = warnings.iter().any(|w| w.code != "llm_plan_grounded");
        if !fell_back {
            model_plans += 1;
        }
        let missing = unkept(&plan, case);
        if missing.is_empty() {
            kept += 1;
        }
        plan.relations.clear();
        let relations = sw_pipeline::relations_with_llm(&c, &mut plan);
        let mut edit = None;
        if i % 4 == 0 {
            let dir = scratch.path().join(format!("p{i}"));
            let opts = Options { seed: 0, ..Options::default() };
            if sw_pipeline::generate(&case.prompt, &dir, &opts, &mut |_| {}).is_ok() {
                let r = sw_pipeline::edit_package(
                    &dir,
                    "make it feel tidier: put the smallest things together",
                    EditReader::Llm,
                    Some(&c),
                    &mut |_| {},
                );
                edit = Some(r.map(|o| o.record.operations.join("; ")).map_err(|e| e.to_string()));
            }
        }
        let calls = tap.calls();
        if !json_out {
            eprintln!(
                "{:>2} {:<70} {} {}",
                i + 1,
                case.prompt.chars().take(70).collect::<String>(),
                if fell_back { "offline" } else { "model+grounding" },
                if missing.is_empty() { "faithful".to_string() } else { format!("UNKEPT: {}", missing.join(", ")) }
            );
        }
        per_prompt.push(json!({
            "prompt": case.prompt, "fell_back": fell_back, "unkept": missing,
            "warnings": warnings.iter().map(|w| &w.message).collect::<Vec<_>>(),
            "relations": relations.as_ref().ok(), "relations_error": relations.err(),
            "edit": edit.as_ref().and_then(|e| e.as_ref().ok()), "edit_error": edit.and_then(|e| e.err()),
            "calls": calls,
        }));
        all.extend(calls);
    }
    let table = rows(&all);
    let total_s = started.elapsed().as_secs_f64();
    if json_out {
        print_json(&json!({
            "endpoint": base_url, "model": model, "prompts": cases.len(), "faithful": kept, "model_plans": model_plans,
            "stages": table.iter().map(|(s, r)| json!({"stage": s.name(), "row": r})).collect::<Vec<_>>(),
            "total_s": total_s, "per_prompt": per_prompt,
        }));
    } else {
        let mut lines = vec![format!(
            "{base_url} ({model}): {} prompts in {total_s:.0} s · plans keeping every stated fact {kept}/{} · \
             plans from the model {model_plans}/{}",
            cases.len(),
            cases.len(),
            cases.len()
        )];
        lines.push("stage      calls  accepted  (after dialect)  cut off  attempts when cut  p50 s  max s".into());
        for (s, r) in &table {
            lines.push(format!(
                "{:<10} {:>5}  {:>8}  {:>15}  {:>7}  {:>16}  {:>5.1}  {:>5.1}",
                s.name(),
                r.calls,
                r.accepted,
                r.accepted_after_negotiation,
                r.cut_off,
                r.cut_off_max_attempts,
                r.p50_s,
                r.max_s
            ));
        }
        print(&lines.join("\n"));
    }
    Ok(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_suite_reads_and_its_checker_counts_categories_and_words() {
        let text =
            std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/llm/grounding.jsonl"))
                .unwrap();
        let cases: Vec<Case> = text.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
        assert_eq!(cases.len(), 20);
        let plan = sw_planner::plan(&cases[0].prompt).unwrap();
        assert!(unkept(&plan, &cases[0]).is_empty(), "{:?}", unkept(&plan, &cases[0]));
        let mut wrong = plan.clone();
        wrong.objects.retain(|o| o.category != "plate");
        assert_eq!(unkept(&wrong, &cases[0]), vec!["plate 0 (said 2)".to_string()]);
        // A proxy counts by its label's words, not by words the phrase merely contains.
        let garage = cases.iter().find(|c| c.objects.contains_key("car")).unwrap();
        let mut plan = sw_planner::plan(&garage.prompt).unwrap();
        assert!(unkept(&plan, garage).is_empty(), "{:?}", unkept(&plan, garage));
        let car = plan.objects.iter().position(|o| o.proxy.as_ref().is_some_and(|p| p.label == "car")).unwrap();
        let mut cardboard = plan.objects[car].clone();
        cardboard.category = "cardboard_box".into();
        cardboard.proxy = None;
        cardboard.phrase = "a car and cardboard".into();
        plan.objects[car] = cardboard;
        assert_eq!(unkept(&plan, garage), vec!["car 0 (said 1)".to_string()]);
    }
}
