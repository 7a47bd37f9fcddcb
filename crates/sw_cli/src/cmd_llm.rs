//! `scenewright llm …`: the pipeline with a language model for L1 (`llm generate`), the
//! plan alone (`llm plan`) and the configured endpoints, probed (`llm status`: the models
//! a server lists, a one-token call, whether it takes our schemas and in which dialect).
//! Endpoints come from `--llm-config FILE` or the environment (`SCENEWRIGHT_LLM_*`, see
//! the README); `scenewright generate` stays offline. The CAD runner and the asset
//! library start only when the first part is to be made, not before the first model call.

use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

use clap::Subcommand;
use serde_json::json;
use sw_forge::generate::{LlmWriter, LoopConfig};
use sw_forge::runner::{CadRunner, RunnerConfig};
use sw_llm::{Client, LlmConfig, LlmStage};
use sw_pipeline::{AssetSource, CatalogSource, Event, ForgeSource, GroupAssets, LlmRun, Options};
use sw_plan::{LlmCall, LlmOutcome, ObjectPlan, Status};

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Debug, Subcommand)]
pub(crate) enum LlmCommand {
    /// Generate a scene with the LLM planner (falls back to the offline planner, with a
    /// warning in report.json, when the endpoint fails).
    Generate {
        prompt: String,
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        #[arg(long)]
        no_verify: bool,
        /// Fail instead of planning offline when the endpoint fails.
        #[arg(long)]
        no_fallback: bool,
        /// Keep objects the catalog does not have as labelled proxies instead of having
        /// the CAD stage's model write them (used when a CAD endpoint is configured).
        #[arg(long)]
        no_forge: bool,
        /// A JSON file with the endpoints (else the environment).
        #[arg(long, value_name = "FILE")]
        llm_config: Option<PathBuf>,
        #[arg(long)]
        json: bool,
    },
    /// Print the plan the LLM planner makes of a prompt (plan.json's format).
    Plan {
        prompt: String,
        #[arg(long)]
        no_fallback: bool,
        #[arg(long, value_name = "FILE")]
        llm_config: Option<PathBuf>,
    },
    /// The configured endpoints per stage (never the keys), each server probed: the
    /// models it lists, a one-token call, and whether it takes a JSON Schema.
    Status {
        #[arg(long, value_name = "FILE")]
        llm_config: Option<PathBuf>,
        /// Only print the configuration; ask the servers nothing.
        #[arg(long)]
        no_probe: bool,
        #[arg(long)]
        json: bool,
    },
}

/// The endpoints from a file (and the environment, which overrides it) or the
/// environment alone.
pub(crate) fn config(file: Option<&Path>) -> Result<LlmConfig, Failure> {
    match file {
        Some(f) => LlmConfig::from_file_and_env(f),
        None => LlmConfig::from_env(),
    }
    .map_err(|e| Failure::input(e.to_string()))
}

fn need(cfg: &LlmConfig, stage: LlmStage) -> Result<(), Failure> {
    if cfg.endpoint(stage).is_none() {
        return Err(Failure::input(format!(
            "no LLM endpoint is configured for the {} stage: set SCENEWRIGHT_LLM_BASE_URL and SCENEWRIGHT_LLM_MODEL \
             (and SCENEWRIGHT_LLM_API_KEY), or pass --llm-config FILE; `scenewright generate` works offline",
            stage.name()
        )));
    }
    Ok(())
}

pub(crate) fn failure(e: sw_pipeline::PipelineError) -> Failure {
    match e.exit_code() {
        2 => Failure::input(e.to_string()),
        // The model's failure, named as such (not an internal error).
        3 => Failure { code: 3, message: e.to_string() },
        _ => Failure::internal(e.to_string()),
    }
}

/// Plain progress lines on stderr (nothing with --json).
pub(crate) fn progress(json: bool) -> impl FnMut(&Event) {
    move |e| {
        if json {
            return;
        }
        match e {
            Event::StageFinished { stage, ms, summary } => eprintln!("{:<9} {:>8.1} ms  {summary}", stage.label(), ms),
            Event::Note { stage, message } => eprintln!("{:<9}             {message}", stage.label()),
            Event::StageStarted { .. } | Event::Object { .. } => {}
        }
    }
}

/// L2 with the forge: the CAD stage's model writes parts the catalog lacks, run in the
/// sandboxed runner; the asset library (when its embedder is set up) reuses parts made
/// before by meaning and keeps every new one.
fn forge_source(client: &Client) -> Result<ForgeSource, String> {
    let runner = CadRunner::start(RunnerConfig::default()).map_err(|e| e.to_string())?;
    let source = ForgeSource::new(runner, Arc::new(LlmWriter::new(client.clone())), LoopConfig::default());
    let location = sw_forge::library::default_store_location();
    match sw_forge::embed::MiniLm::load_default().map_err(|e| e.to_string()).and_then(|m| {
        sw_forge::library::AssetLibrary::open_location(&location, m).map_err(|e| format!("{location}: {e}"))
    }) {
        Ok(library) => Ok(source.with_library(Arc::new(library))),
        Err(why) => {
            eprintln!("warning: generated parts are not stored for reuse: {why}");
            Ok(source)
        }
    }
}

/// The forge, started when the first group the catalog lacks is to be made: a prompt
/// whose objects are all in the catalog never pays for the CAD runner (4–7 s).
struct LazyForge {
    client: Client,
    source: OnceLock<Result<ForgeSource, String>>,
}

impl AssetSource for LazyForge {
    fn name(&self) -> &str {
        "forge"
    }

    fn is_cached(&self, group: &ObjectPlan) -> bool {
        group.proxy.is_none() || self.source.get().and_then(|s| s.as_ref().ok()).is_some_and(|s| s.is_cached(group))
    }

    fn make(&self, group: &ObjectPlan, seed: u64) -> GroupAssets {
        if group.proxy.is_none() {
            return CatalogSource.make(group, seed);
        }
        match self.source.get_or_init(|| forge_source(&self.client)) {
            Ok(source) => source.make(group, seed),
            Err(why) => {
                let mut out = CatalogSource.make(group, seed);
                out.warnings.push(sw_plan::Warning::new(
                    sw_plan::Stage::Forge,
                    "asset_forge_unavailable",
                    format!("{}: kept the labelled proxy; the asset forge could not start ({why})", group.phrase),
                ));
                out
            }
        }
    }
}

/// One line per stage of calls: "plan 1 call · 2.31 s · 1203 tokens in / 356 out".
pub(crate) fn calls_summary(calls: &[LlmCall]) -> Vec<String> {
    let mut out = Vec::new();
    for stage in LlmStage::ALL {
        let of: Vec<&LlmCall> = calls.iter().filter(|c| c.stage == stage).collect();
        if of.is_empty() {
            continue;
        }
        let secs: f64 = of.iter().map(|c| c.latency_ms).sum::<f64>() / 1000.0;
        let (tin, tout): (u64, u64) = of.iter().fold((0, 0), |(a, b), c| (a + c.tokens_in, b + c.tokens_out));
        let retries: u32 = of.iter().map(|c| c.retries).sum();
        let failed = of.iter().filter(|c| c.outcome != LlmOutcome::Ok).count();
        let mut line = format!(
            "{} {} call{} · {secs:.2} s · {tin} tokens in / {tout} out",
            stage.name(),
            of.len(),
            if of.len() == 1 { "" } else { "s" }
        );
        if retries > 0 {
            line.push_str(&format!(" · {retries} retries"));
        }
        if failed > 0 {
            line.push_str(&format!(" · {failed} failed"));
        }
        out.push(line);
    }
    out
}

pub(crate) fn run(c: LlmCommand) -> Result<u8, Failure> {
    match c {
        LlmCommand::Generate { prompt, out, seed, no_verify, no_fallback, no_forge, llm_config, json } => {
            let cfg = config(llm_config.as_deref())?;
            need(&cfg, LlmStage::Plan)?;
            let mut run = LlmRun::new(Client::new(cfg));
            run.fallback = !no_fallback;
            if !no_forge && run.client.has(LlmStage::Cad) {
                run.assets = Arc::new(LazyForge { client: run.client.clone(), source: OnceLock::new() });
            }
            let opts = Options { seed, verify: !no_verify, ..Options::default() };
            let o = sw_pipeline::generate_with_llm(&prompt, &out, &opts, &run, &mut progress(json)).map_err(failure)?;
            let code = if sw_pipeline::succeeded(&o.report) { 0 } else { 1 };
            if json {
                print_json(&json!({
                    "status": o.report.status, "out_dir": o.out_dir, "scene": o.out_dir.join("scene.xml"),
                    "report": o.report, "timings": o.timings,
                }));
            } else {
                let r = &o.report;
                let mut lines = vec![
                    format!("scene    {}", o.out_dir.join("scene.xml").display()),
                    format!(
                        "room     {} · {} of {} objects placed{}",
                        r.summary.room.replace('_', " "),
                        r.summary.objects_placed,
                        r.summary.objects_requested,
                        if r.summary.robots.is_empty() {
                            String::new()
                        } else {
                            format!(" · robots: {}", r.summary.robots.join(", "))
                        }
                    ),
                    format!(
                        "verify   {}",
                        match (&r.status, &r.verification) {
                            (Status::Verified, Some(v)) => format!("passed in {}", v.engine),
                            (_, Some(v)) => format!("FAILED: {}", v.failures.join("; ")),
                            _ => "skipped (--no-verify)".into(),
                        }
                    ),
                ];
                lines.extend(calls_summary(&r.llm_calls).into_iter().map(|l| format!("llm      {l}")));
                lines.extend(
                    r.approximated.iter().map(|a| format!("approx   \"{}\" → {} ({})", a.text, a.became, a.reason)),
                );
                lines.extend(r.not_understood.iter().map(|n| format!("ignored  \"{}\" ({})", n.text, n.reason)));
                lines.extend(r.warnings.iter().map(|w| format!("warning  {}", w.message)));
                lines.push(format!("time     {:.0} ms", o.timings.total_ms));
                print(&lines.join("\n"));
            }
            Ok(code)
        }
        LlmCommand::Plan { prompt, no_fallback, llm_config } => {
            let cfg = config(llm_config.as_deref())?;
            need(&cfg, LlmStage::Plan)?;
            let client = Client::new(cfg);
            let (plan, warnings) = sw_pipeline::plan_with_llm(&prompt, &client, !no_fallback).map_err(failure)?;
            for w in &warnings {
                eprintln!("warning: {}", w.message);
            }
            for l in calls_summary(&client.telemetry().calls()) {
                eprintln!("llm      {l}");
            }
            print_json(&plan);
            Ok(0)
        }
        LlmCommand::Status { llm_config, no_probe, json } => status(llm_config.as_deref(), !no_probe, json),
    }
}

/// `llm status`: the configuration per stage and, unless told not to, what each distinct
/// server answers.
fn status(file: Option<&Path>, probe: bool, json: bool) -> Result<u8, Failure> {
    let cfg = config(file)?;
    let mut probes: Vec<((String, String), serde_json::Value)> = Vec::new();
    let mut stages = Vec::new();
    for s in LlmStage::ALL {
        let Some(e) = cfg.endpoint(s) else {
            stages.push(json!({ "stage": s.name(), "configured": false }));
            continue;
        };
        let mut row = json!({
            "stage": s.name(), "configured": true, "endpoint": e.origin(), "model": e.model,
            "key": e.api_key.is_some(), "timeout_s": e.timeout.as_secs_f64(), "retries": e.max_retries,
            "stream": e.stream, "structured": e.structured,
            "max_tokens": e.max_tokens.or_else(|| sw_llm::default_max_tokens(s)),
            "endpoint_concurrency": sw_llm::limits::limit(e),
        });
        if probe && s != LlmStage::Embeddings {
            let k = (e.completions_url(), e.model.clone());
            let found = probes.iter().find(|(key, _)| *key == k).map(|(_, v)| v.clone());
            let p = found.unwrap_or_else(|| {
                let r = sw_llm::probe::probe(s, e);
                let v = json!({
                    "models": r.models.as_ref().ok(), "models_error": r.models.as_ref().err(),
                    "model_listed": r.model_listed,
                    "ping_ms": r.ping.as_ref().ok().map(|p| p.0), "served_model": r.ping.as_ref().ok().and_then(|p| p.1.clone()),
                    "ping_error": r.ping.as_ref().err(),
                    "dialect": r.schema.as_ref().ok().map(|s| s.0.clone()),
                    "schema_followed": r.schema.as_ref().ok().map(|s| s.1),
                    "schema_error": r.schema.as_ref().err(),
                });
                probes.push((k, v.clone()));
                v
            });
            row["probe"] = p;
        }
        stages.push(row);
    }
    if json {
        print_json(&json!({ "stages": stages }));
        return Ok(0);
    }
    let str_of = |v: &serde_json::Value| v.as_str().unwrap_or("").to_string();
    let mut lines = Vec::new();
    for s in &stages {
        if s["configured"] != true {
            lines.push(format!("{:<11} offline", str_of(&s["stage"])));
            continue;
        }
        lines.push(format!(
            "{:<11} {} model {} · key {} · silence limit {} s · {} retries · max_tokens {} · {} in flight",
            str_of(&s["stage"]),
            str_of(&s["endpoint"]),
            str_of(&s["model"]),
            if s["key"] == true { "set" } else { "none" },
            s["timeout_s"],
            s["retries"],
            s["max_tokens"],
            s["endpoint_concurrency"].as_u64().map_or("any number".to_string(), |n| n.to_string()),
        ));
        let p = &s["probe"];
        if p.is_null() {
            continue;
        }
        let models = match (p["models"].as_array(), p["models_error"].as_str()) {
            (Some(m), _) => {
                let names: Vec<String> = m.iter().map(str_of).collect();
                let listed = if p["model_listed"] == false { " (the configured model is not among them)" } else { "" };
                format!("lists {}{listed}", names.join(", "))
            }
            (None, Some(e)) => format!("no model list ({e})"),
            _ => "no model list".into(),
        };
        let ping = match (p["ping_ms"].as_f64(), p["ping_error"].as_str()) {
            (Some(ms), _) => format!(
                "answers in {ms:.0} ms as {}",
                p["served_model"].as_str().unwrap_or("(the server does not say which model)")
            ),
            (None, Some(e)) => format!("does not answer: {e}"),
            _ => String::new(),
        };
        let schema = match (p["dialect"].as_str(), p["schema_error"].as_str()) {
            (Some(d), _) => {
                format!("schema as {d}{}", if p["schema_followed"] == true { ", followed" } else { ", NOT followed" })
            }
            (None, Some(e)) => format!("schema call failed: {e}"),
            _ => String::new(),
        };
        lines.push(format!("{:<11} {models} · {ping} · {schema}", ""));
    }
    print(&lines.join("\n"));
    Ok(0)
}
