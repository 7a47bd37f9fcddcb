//! The pipeline with a language model for L1, on a short critical path:
//!
//! ```text
//! L1 plan (streamed) ──┬─ object 1 known ─▶ its assets ─┐
//!                      ├─ object 2 known ─▶ its assets ─┤
//!                      └─ plan complete (relations in it) ──┴─▶ L3 solver ─▶ L4 ─▶ verify
//! ```
//!
//! Each object group's assets start as soon as its closing brace arrives in the stream,
//! on worker threads, while the model is still writing the rest of the plan; the plan
//! carries the relations, so the layout solver needs no further call. A scene whose
//! assets all come from the cache or the catalog costs one LLM round trip; one with
//! misses costs two in sequence (the plan, then the slowest asset that started during
//! it). A plan that fails validation is sent back once with the errors (a repair round);
//! an endpoint that fails, an answer cut off at its token limit (never asked again), or a
//! second unusable answer, falls back to the offline planner with a warning in the report
//! (unless fallback is off). A plan the model wrote is grounded in the prompt's own words
//! (`sw_planner::llm::ground`): where it contradicts what the offline reader read
//! explicitly, the prompt wins and the report says so.
//!
//! Part jobs started from a plan that is then thrown away (a retried stream, a repair
//! round, the fallback, or groups the final plan no longer has) are cancelled: queued ones
//! never start, running ones end their model calls at once (`sw_llm::cancel`).
//!
//! [`Structure::Sequential`] runs the paper's arrangement instead (L1, then L2 in batches,
//! then an L3 call), for the latency benchmark.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::Instant;

use serde_json::Value;
use sw_llm::{
    ArrayScanner, CancelToken, ChatRequest, Client, LlmError, LlmOutcome, LlmStage, Message, StreamEvent, Telemetry,
    extract_json,
};
use sw_plan::{ObjectPlan, ScenePlan, Stage, Timings, Warning};
use sw_planner::llm::{
    PLAN_SCHEMA_NAME, RELATIONS_SCHEMA_NAME, ground, plan_messages, plan_schema, read_object, read_plan,
    read_relations, relations_messages, relations_schema, repair_message,
};
use tracing::info_span;

use crate::asset_source::{AssetSource, CatalogSource, GroupAssets};
use crate::forge::{Forged, forge_with};
use crate::{
    Event, FinishForge, Options, Outcome, PipelineError, Prepared, apply_options, package, report, run_from_plan,
    stage_finished, stage_started,
};

/// How the LLM stages are arranged.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Structure {
    /// Ours: assets start from the streamed plan; relations come with the plan.
    Overlapped,
    /// The paper's: L1, then the assets in batches of `batch` after the plan, then an
    /// L3 layout call, then L4 (its answer is not used: our solver places objects).
    Sequential { batch: usize },
}

/// How to run the pipeline with a language model.
#[derive(Clone)]
pub struct LlmRun {
    pub client: Client,
    /// L2: where assets come from (the catalog by default; the asset forge plugs in here).
    pub assets: Arc<dyn AssetSource>,
    /// Plan offline, with a warning, when the endpoint fails or answers unusably.
    pub fallback: bool,
    pub structure: Structure,
}

impl std::fmt::Debug for LlmRun {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LlmRun")
            .field("assets", &self.assets.name())
            .field("fallback", &self.fallback)
            .field("structure", &self.structure)
            .finish()
    }
}

impl LlmRun {
    pub fn new(client: Client) -> Self {
        Self { client, assets: Arc::new(CatalogSource), fallback: true, structure: Structure::Overlapped }
    }
}

/// Why L1 with the model produced no plan.
enum L1Error {
    Endpoint(LlmError),
    Unusable(String),
}

/// What L1 reports while the plan streams.
enum PlanEvent {
    /// An object group the stream completed.
    Object(ObjectPlan),
    /// Everything streamed so far is thrown away (a retry, a repair round, the fallback).
    Discard,
}

/// The longest part of an unusable answer sent back in the repair round, bytes.
const MAX_ECHO: usize = 16 * 1024;

/// L1: the streamed plan, with one repair round. `on` sees each object group as soon as
/// the stream completes it, and each time what was streamed is thrown away.
fn l1(prompt: &str, client: &Client, on: &mut dyn FnMut(PlanEvent)) -> Result<ScenePlan, L1Error> {
    let m = plan_messages(prompt);
    let schema = plan_schema();
    let mut messages = vec![Message::system(m.system), Message::user(m.user)];
    let mut problem = String::new();
    for round in 0..2 {
        if round > 0 {
            on(PlanEvent::Discard);
        }
        let req = ChatRequest::new(messages.clone()).with_schema(PLAN_SCHEMA_NAME, schema.clone());
        let mut scanner = ArrayScanner::new("objects");
        let mut index = 0usize;
        let purpose = if round == 0 { "plan" } else { "plan (repair)" };
        let answer = client
            .stream(LlmStage::Plan, &req, purpose, &mut |ev| match ev {
                StreamEvent::Delta(d) => {
                    for element in scanner.push(d) {
                        if let Ok(v) = serde_json::from_str::<Value>(&element)
                            && let Some((o, _)) = read_object(&v, index)
                        {
                            on(PlanEvent::Object(o));
                        }
                        index += 1;
                    }
                }
                StreamEvent::Restart => {
                    scanner.reset();
                    index = 0;
                    on(PlanEvent::Discard);
                }
            })
            .map_err(L1Error::Endpoint)?;
        problem = match extract_json(&answer.content) {
            Err(e) => {
                let cut = if answer.finish_reason.as_deref() == Some("length") {
                    " (the answer was cut off at the token limit)"
                } else {
                    ""
                };
                format!("{e}{cut}")
            }
            Ok(v) => match read_plan(prompt, &v) {
                Ok(plan) => return Ok(plan),
                Err(e) => e.to_string(),
            },
        };
        let mut echo = answer.content;
        if echo.len() > MAX_ECHO {
            echo.truncate(echo.floor_char_boundary(MAX_ECHO));
        }
        messages.push(Message::assistant(echo));
        messages.push(Message::user(repair_message(&problem)));
    }
    Err(L1Error::Unusable(problem))
}

fn check_prompt(prompt: &str) -> Result<(), PipelineError> {
    if prompt.len() > sw_planner::MAX_PROMPT_BYTES {
        return Err(PipelineError::Input(
            sw_planner::PlannerError::TooLong { bytes: prompt.len(), limit: sw_planner::MAX_PROMPT_BYTES }.to_string(),
        ));
    }
    if prompt.trim().is_empty() {
        return Err(PipelineError::Input(sw_planner::PlannerError::Empty.to_string()));
    }
    Ok(())
}

/// The model's plan grounded in the offline reader's reading of the prompt, with a
/// warning when the two disagreed.
fn grounded(prompt: &str, plan: ScenePlan) -> (ScenePlan, Vec<Warning>) {
    let Ok(reading) = sw_planner::plan(prompt) else {
        return (plan, Vec::new());
    };
    let (plan, g) = ground(plan, &reading);
    if g.notes.is_empty() {
        return (plan, Vec::new());
    }
    let what: Vec<String> = g.notes.iter().take(4).map(|n| format!("\"{}\" → {}", n.text, n.became)).collect();
    let more = if g.notes.len() > 4 { format!(" and {} more", g.notes.len() - 4) } else { String::new() };
    let w = Warning::new(
        Stage::Plan,
        "llm_plan_grounded",
        format!(
            "the model's plan contradicted or left out what the prompt says in {} place(s); the prompt's words won \
             ({}{more}; see understanding.approximated)",
            g.notes.len(),
            what.join(", ")
        ),
    );
    (plan, vec![w])
}

/// Why the model gave no plan, in words that say what happened.
fn endpoint_failure(e: &LlmError) -> (&'static str, String) {
    if e.outcome() == LlmOutcome::Length {
        ("llm_answer_cut_off", format!("wrote past its token limit ({e})"))
    } else if e.unreachable() {
        ("llm_unavailable", format!("could not be reached ({e})"))
    } else {
        ("llm_unavailable", format!("failed ({e})"))
    }
}

fn plan_inner(
    prompt: &str,
    client: &Client,
    fallback: bool,
    on: &mut dyn FnMut(PlanEvent),
) -> Result<(ScenePlan, Vec<Warning>, bool), PipelineError> {
    check_prompt(prompt)?;
    let (code, why) = match l1(prompt, client, on) {
        Ok(plan) => return Ok((plan, Vec::new(), true)),
        Err(L1Error::Endpoint(e)) => endpoint_failure(&e),
        Err(L1Error::Unusable(p)) => ("llm_answer_unusable", format!("answered unusably twice (last: {p})")),
    };
    on(PlanEvent::Discard);
    if !fallback {
        return Err(PipelineError::Upstream(format!("the LLM planner {why}")));
    }
    match sw_planner::plan(prompt) {
        Ok(plan) => Ok((
            plan,
            vec![Warning::new(Stage::Plan, code, format!("the LLM planner {why}; the offline planner made this plan"))],
            false,
        )),
        Err(e) => Err(PipelineError::Input(format!("{e} (and the LLM planner {why})"))),
    }
}

/// L1 with the model alone: the plan (or the offline planner's, with a warning, when
/// `fallback` and the model fails).
pub fn plan_with_llm(
    prompt: &str,
    client: &Client,
    fallback: bool,
) -> Result<(ScenePlan, Vec<Warning>), PipelineError> {
    let (plan, mut warnings, from_model) = plan_inner(prompt, client, fallback, &mut |_| {})?;
    if !from_model {
        return Ok((plan, warnings));
    }
    let (plan, w) = grounded(prompt, plan);
    warnings.extend(w);
    Ok((plan, warnings))
}

/// One submitted group's job: its cancel token, and whether it was made.
#[derive(Debug, Clone, Default)]
struct Job {
    token: CancelToken,
}

/// Asset work on worker threads: groups are submitted as they become known; results are
/// kept by the group's exact content, so a streamed group that the final plan changed is
/// simply made again.
struct Workers {
    tx: Option<Sender<(ObjectPlan, CancelToken)>>,
    /// Submitted groups (by content) and their jobs' tokens.
    submitted: BTreeMap<String, Job>,
    results: Arc<Mutex<BTreeMap<String, GroupAssets>>>,
    pending: Arc<(Mutex<usize>, Condvar)>,
    handles: Vec<JoinHandle<()>>,
    seed: u64,
}

impl Drop for Workers {
    /// A run that ends early (an error) cancels what is still being made.
    fn drop(&mut self) {
        for job in self.submitted.values() {
            job.token.cancel();
        }
    }
}

fn key(o: &ObjectPlan) -> String {
    serde_json::to_string(o).unwrap_or_default()
}

impl Workers {
    fn start(source: Arc<dyn AssetSource>, seed: u64, threads: usize, telemetry: Telemetry) -> Self {
        let (tx, rx) = channel::<(ObjectPlan, CancelToken)>();
        let rx: Arc<Mutex<Receiver<(ObjectPlan, CancelToken)>>> = Arc::new(Mutex::new(rx));
        let results: Arc<Mutex<BTreeMap<String, GroupAssets>>> = Arc::new(Mutex::new(BTreeMap::new()));
        let pending = Arc::new((Mutex::new(0usize), Condvar::new()));
        let handles = (0..threads.max(1))
            .filter_map(|i| {
                let (rx, results, pending, source, telemetry) = (
                    Arc::clone(&rx),
                    Arc::clone(&results),
                    Arc::clone(&pending),
                    Arc::clone(&source),
                    telemetry.clone(),
                );
                std::thread::Builder::new()
                    .name(format!("assets-{i}"))
                    .spawn(move || {
                        loop {
                            let job = match rx.lock() {
                                Ok(r) => r.recv(),
                                Err(_) => break,
                            };
                            let Ok((group, token)) = job else { break };
                            if !token.is_cancelled() {
                                let _s = info_span!("assets", group = %group.id).entered();
                                let mut made = sw_llm::cancel::scope(&token, || source.make(&group, seed));
                                // The calls happened (cancelled ones too): they are reported.
                                telemetry.extend(std::mem::take(&mut made.llm_calls));
                                if !token.is_cancelled()
                                    && let Ok(mut r) = results.lock()
                                {
                                    r.insert(key(&group), made);
                                }
                            }
                            let (lock, cv) = &*pending;
                            if let Ok(mut n) = lock.lock() {
                                *n = n.saturating_sub(1);
                            }
                            cv.notify_all();
                        }
                    })
                    .ok()
            })
            .collect();
        Self { tx: Some(tx), submitted: BTreeMap::new(), results, pending, handles, seed }
    }

    fn submit(&mut self, group: &ObjectPlan) {
        let k = key(group);
        if self.submitted.contains_key(&k) {
            return;
        }
        let job = Job::default();
        let token = job.token.clone();
        self.submitted.insert(k, job);
        if let Some(tx) = &self.tx {
            if let Ok(mut n) = self.pending.0.lock() {
                *n += 1;
            }
            if tx.send((group.clone(), token)).is_err()
                && let Ok(mut n) = self.pending.0.lock()
            {
                *n = n.saturating_sub(1);
            }
        }
    }

    /// Cancels the jobs of submitted groups that `keep` does not hold (all of them when
    /// `keep` is `None`); groups already made stay made. A cancelled group submitted again
    /// is made again.
    fn discard(&mut self, keep: Option<&ScenePlan>) {
        let wanted: BTreeSet<String> = keep.map(|p| p.objects.iter().map(key).collect()).unwrap_or_default();
        let made: BTreeSet<String> = match self.results.lock() {
            Ok(r) => r.keys().cloned().collect(),
            Err(p) => p.into_inner().keys().cloned().collect(),
        };
        self.submitted.retain(|k, job| {
            if wanted.contains(k) || made.contains(k) {
                return true;
            }
            job.token.cancel();
            false
        });
    }

    /// Waits until every submitted group is made.
    fn wait_idle(&self) {
        let (lock, cv) = &*self.pending;
        let Ok(mut n) = lock.lock() else { return };
        while *n > 0 {
            n = match cv.wait(n) {
                Ok(n) => n,
                Err(_) => return,
            };
        }
    }

    /// Makes what is missing, waits for everything, and assembles the scene's assets.
    fn finish(mut self, plan: &ScenePlan) -> Forged {
        for g in &plan.objects {
            self.submit(g);
        }
        self.tx = None;
        for h in self.handles.drain(..) {
            let _ = h.join();
        }
        let results = match self.results.lock() {
            Ok(r) => r.clone(),
            Err(p) => p.into_inner().clone(),
        };
        let seed = self.seed;
        let mut forged = forge_with(plan, seed, &mut |group, k| match results
            .get(&key(group))
            .and_then(|g| g.instances.get(k as usize))
        {
            Some(Ok(m)) => Ok((m.asset.clone(), m.tags.clone(), m.label.clone())),
            Some(Err(e)) => Err(e.clone()),
            None => crate::forge::make(group, k, seed).map_err(|e| e.to_string()),
        });
        for g in &plan.objects {
            match results.get(&key(g)) {
                Some(made) => {
                    forged.warnings.extend(made.warnings.iter().cloned());
                    if made.cached {
                        forged.cache.hits += 1;
                    } else {
                        forged.cache.misses += 1;
                    }
                }
                // Made here from the catalog.
                None => forged.cache.hits += 1,
            }
        }
        forged
    }
}

/// True when the prompt states relations (the offline planner finds some).
fn prompt_states_relations(prompt: &str) -> bool {
    sw_planner::plan(prompt).is_ok_and(|p| !p.relations.is_empty())
}

/// Asks the relations stage for relations between the plan's groups and adds those it
/// can read (the rest are notes); the number added, or why none could be.
pub fn relations_with_llm(client: &Client, plan: &mut ScenePlan) -> Result<usize, String> {
    let m = relations_messages(plan);
    let req = ChatRequest::new(vec![Message::system(m.system), Message::user(m.user)])
        .with_schema(RELATIONS_SCHEMA_NAME, relations_schema());
    let answer = client.complete(LlmStage::Relations, &req, "relations").map_err(|e| e.to_string())?;
    let v = extract_json(&answer.content).map_err(|e| e.to_string())?;
    let (rels, notes) = read_relations(plan, &v);
    let n = rels.len();
    let mut candidate = plan.clone();
    candidate.relations.extend(rels);
    candidate.understanding.approximated.extend(notes);
    candidate.validate().map_err(|e| e.to_string())?;
    *plan = candidate;
    Ok(n)
}

/// Runs the whole pipeline with a language model for L1 (see the module docs) and
/// writes the package to `out`.
pub fn generate_with_llm(
    prompt: &str,
    out: &Path,
    opts: &Options,
    run: &LlmRun,
    on_event: &mut dyn FnMut(&Event),
) -> Result<Outcome, PipelineError> {
    let started = Instant::now();
    package::check_destination(out)?;
    check_prompt(prompt)?;
    let client = run.client.fresh();
    let mut timings = Timings::default();
    let overlapped = run.structure == Structure::Overlapped;
    let threads = match run.structure {
        Structure::Overlapped => client.config().endpoint(LlmStage::Cad).map_or(8, |e| e.concurrency),
        Structure::Sequential { batch } => batch.max(1),
    };
    let mut workers = Workers::start(Arc::clone(&run.assets), opts.seed, threads, client.telemetry().clone());

    let t = stage_started(Stage::Plan, on_event);
    let (mut plan, mut warnings, from_model) = {
        let _s = info_span!("stage", stage = "plan", llm = true).entered();
        plan_inner(prompt, &client, run.fallback, &mut |ev| match ev {
            PlanEvent::Object(o) if overlapped => workers.submit(&o),
            PlanEvent::Object(_) => {}
            PlanEvent::Discard => workers.discard(None),
        })?
    };
    if overlapped {
        for g in &plan.objects {
            workers.submit(g);
        }
    }
    // Relations come with the plan; a plan without any, of a prompt that states some,
    // asks the relations stage (while the assets are being made).
    if overlapped
        && plan.relations.is_empty()
        && plan.objects.len() >= 2
        && client.has(LlmStage::Relations)
        && prompt_states_relations(prompt)
        && let Err(e) = relations_with_llm(&client, &mut plan)
    {
        warnings.push(Warning::new(
            Stage::Plan,
            "llm_relations_unavailable",
            format!(
                "the plan came without relations and the relations stage failed ({e}); the relations the prompt \
                 states were kept"
            ),
        ));
    }
    if from_model {
        let (g, w) = grounded(prompt, plan);
        plan = g;
        warnings.extend(w);
    }
    apply_options(&mut plan, opts)?;
    // Part jobs of groups the final plan does not hold are cancelled.
    workers.discard(Some(&plan));
    stage_finished(Stage::Plan, t, report::plan_summary(&plan), &mut timings, on_event);

    let structure = run.structure;
    let finish_client = client.clone();
    let forge: FinishForge<'static> = Box::new(move |plan: &ScenePlan| {
        if let Structure::Sequential { batch } = structure {
            for chunk in plan.objects.chunks(batch.max(1)) {
                for g in chunk {
                    workers.submit(g);
                }
                workers.wait_idle();
            }
            // The paper's L3: a layout call after every asset (kept for its latency).
            if finish_client.has(LlmStage::Relations) {
                let mut copy = plan.clone();
                let _ = relations_with_llm(&finish_client, &mut copy);
            }
        }
        workers.finish(plan)
    });
    let prepared = Prepared { forge: Some(forge), warnings, telemetry: Some(client.telemetry().clone()) };
    run_from_plan(prompt, plan, out, opts, prepared, timings, started, on_event)
}
