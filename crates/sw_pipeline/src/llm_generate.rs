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
//! an endpoint that fails, or a second unusable answer, falls back to the offline
//! planner with a warning in the report (unless fallback is off).
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
use sw_llm::{ArrayScanner, ChatRequest, Client, LlmError, LlmStage, Message, StreamEvent, Telemetry, extract_json};
use sw_plan::{ObjectPlan, ScenePlan, Stage, Timings, Warning};
use sw_planner::llm::{
    PLAN_SCHEMA_NAME, RELATIONS_SCHEMA_NAME, plan_messages, plan_schema, read_object, read_plan, read_relations,
    relations_messages, relations_schema, repair_message,
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

/// The longest part of an unusable answer sent back in the repair round, bytes.
const MAX_ECHO: usize = 16 * 1024;

/// L1: the streamed plan, with one repair round. `on_object` sees each object group as
/// soon as the stream completes it.
fn l1(prompt: &str, client: &Client, on_object: &mut dyn FnMut(ObjectPlan)) -> Result<ScenePlan, L1Error> {
    let m = plan_messages(prompt);
    let schema = plan_schema();
    let mut messages = vec![Message::system(m.system), Message::user(m.user)];
    let mut problem = String::new();
    for round in 0..2 {
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
                            on_object(o);
                        }
                        index += 1;
                    }
                }
                StreamEvent::Restart => {
                    scanner.reset();
                    index = 0;
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

fn plan_inner(
    prompt: &str,
    client: &Client,
    fallback: bool,
    on_object: &mut dyn FnMut(ObjectPlan),
) -> Result<(ScenePlan, Vec<Warning>), PipelineError> {
    check_prompt(prompt)?;
    let (code, why) = match l1(prompt, client, on_object) {
        Ok(plan) => return Ok((plan, Vec::new())),
        Err(L1Error::Endpoint(e)) => ("llm_unavailable", format!("could not be reached ({e})")),
        Err(L1Error::Unusable(p)) => ("llm_answer_unusable", format!("answered unusably twice (last: {p})")),
    };
    if !fallback {
        return Err(PipelineError::Internal(format!("the LLM planner {why}")));
    }
    match sw_planner::plan(prompt) {
        Ok(plan) => Ok((
            plan,
            vec![Warning::new(Stage::Plan, code, format!("the LLM planner {why}; the offline planner made this plan"))],
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
    plan_inner(prompt, client, fallback, &mut |_| {})
}

/// Asset work on worker threads: groups are submitted as they become known; results are
/// kept by the group's exact content, so a streamed group that the final plan changed is
/// simply made again.
struct Workers {
    tx: Option<Sender<ObjectPlan>>,
    submitted: BTreeSet<String>,
    results: Arc<Mutex<BTreeMap<String, GroupAssets>>>,
    pending: Arc<(Mutex<usize>, Condvar)>,
    handles: Vec<JoinHandle<()>>,
    seed: u64,
}

fn key(o: &ObjectPlan) -> String {
    serde_json::to_string(o).unwrap_or_default()
}

impl Workers {
    fn start(source: Arc<dyn AssetSource>, seed: u64, threads: usize, telemetry: Telemetry) -> Self {
        let (tx, rx) = channel::<ObjectPlan>();
        let rx: Arc<Mutex<Receiver<ObjectPlan>>> = Arc::new(Mutex::new(rx));
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
                            let Ok(group) = job else { break };
                            let _s = info_span!("assets", group = %group.id).entered();
                            let mut made = source.make(&group, seed);
                            telemetry.extend(std::mem::take(&mut made.llm_calls));
                            if let Ok(mut r) = results.lock() {
                                r.insert(key(&group), made);
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
        Self { tx: Some(tx), submitted: BTreeSet::new(), results, pending, handles, seed }
    }

    fn submit(&mut self, group: &ObjectPlan) {
        if !self.submitted.insert(key(group)) {
            return;
        }
        if let Some(tx) = &self.tx {
            if let Ok(mut n) = self.pending.0.lock() {
                *n += 1;
            }
            if tx.send(group.clone()).is_err()
                && let Ok(mut n) = self.pending.0.lock()
            {
                *n = n.saturating_sub(1);
            }
        }
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

/// Asks the relations stage for relations between the plan's groups.
fn ask_relations(client: &Client, plan: &mut ScenePlan) -> Result<usize, String> {
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
    let (mut plan, mut warnings) = {
        let _s = info_span!("stage", stage = "plan", llm = true).entered();
        plan_inner(prompt, &client, run.fallback, &mut |o| {
            if overlapped {
                workers.submit(&o);
            }
        })?
    };
    apply_options(&mut plan, opts)?;
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
        && let Err(e) = ask_relations(&client, &mut plan)
    {
        warnings.push(Warning::new(
            Stage::Plan,
            "llm_relations_unavailable",
            format!(
                "the plan came without relations and the relations stage failed ({e}); the solver used its defaults"
            ),
        ));
    }
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
                let _ = ask_relations(&finish_client, &mut copy);
            }
        }
        workers.finish(plan)
    });
    let prepared = Prepared { forge: Some(forge), warnings, telemetry: Some(client.telemetry().clone()) };
    run_from_plan(prompt, plan, out, opts, prepared, timings, started, on_event)
}
