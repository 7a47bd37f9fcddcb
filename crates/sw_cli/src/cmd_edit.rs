//! `scenewright edit DIR "<command>"` and `scenewright refine`.

use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;

use serde_json::json;
use sw_llm::{Client, LlmStage};
use sw_pipeline::{EditReader, Refiner};

use crate::Failure;
use crate::cmd_llm::{calls_summary, config, failure, progress};
use crate::output::{print, print_json};

#[derive(Debug, clap::Args)]
pub(crate) struct EditArgs {
    /// The package to edit (changed in place, all or nothing).
    dir: PathBuf,
    /// What to change, in plain English ("remove the chair next to the conveyor").
    command: String,
    /// Read the command with the LLM only.
    #[arg(long, conflicts_with = "offline")]
    llm: bool,
    /// Read the command with the offline grammar only (never call an LLM).
    #[arg(long)]
    offline: bool,
    #[arg(long, value_name = "FILE")]
    llm_config: Option<PathBuf>,
    #[arg(long)]
    json: bool,
}

#[derive(Debug, clap::Args)]
pub(crate) struct RefineArgs {
    /// A first description (else the first question asks for one).
    prompt: Option<String>,
    /// Answers, in order, instead of reading them from stdin (repeatable).
    #[arg(long = "answer", value_name = "TEXT")]
    answers: Vec<String>,
    /// Let the LLM ask the questions (and plan the final prompt).
    #[arg(long)]
    llm: bool,
    /// Write the final plan here.
    #[arg(long, value_name = "FILE")]
    plan_out: Option<PathBuf>,
    #[arg(long, value_name = "FILE")]
    llm_config: Option<PathBuf>,
    /// Print one JSON document at the end (questions go to stderr).
    #[arg(long)]
    json: bool,
}

pub(crate) fn edit(a: EditArgs) -> Result<u8, Failure> {
    let reader = if a.offline {
        EditReader::Grammar
    } else if a.llm {
        EditReader::Llm
    } else {
        EditReader::GrammarThenLlm
    };
    let client = if a.offline { None } else { Some(Client::new(config(a.llm_config.as_deref())?)) };
    let o = sw_pipeline::edit_package(&a.dir, &a.command, reader, client.as_ref(), &mut progress(a.json))
        .map_err(failure)?;
    if a.json {
        print_json(
            &json!({ "status": o.report.status, "dir": o.dir, "edit": o.record, "report": o.report, "timings": o.timings }),
        );
    } else {
        let r = &o.record;
        let mut lines = vec![format!("edit #{} ({}): {}", r.number, r.understood_by, r.operations.join("; "))];
        for (what, names) in
            [("added", &r.added), ("removed", &r.removed), ("moved", &r.moved), ("changed", &r.modified)]
        {
            if !names.is_empty() {
                lines.push(format!("{what:<8} {}", names.join(", ")));
            }
        }
        lines.extend(calls_summary(&r.llm_calls).into_iter().map(|l| format!("llm      {l}")));
        let v = o.report.verification.as_ref().map_or("skipped".to_string(), |v| format!("passed in {}", v.engine));
        lines.push(format!("verify   {v}"));
        lines.push(format!("scene    {}", o.dir.join("scene.xml").display()));
        print(&lines.join("\n"));
    }
    Ok(0)
}

pub(crate) fn refine(a: RefineArgs) -> Result<u8, Failure> {
    let cfg = config(a.llm_config.as_deref())?;
    if a.llm && cfg.endpoint(LlmStage::Refine).is_none() {
        return Err(Failure::input(
            "--llm needs an endpoint for the refine stage (SCENEWRIGHT_LLM_BASE_URL and SCENEWRIGHT_LLM_MODEL, or --llm-config)",
        ));
    }
    let client = a.llm.then(|| Client::new(cfg));
    let mut refiner = Refiner::new(a.prompt.as_deref().unwrap_or(""), client.clone());
    let mut scripted = a.answers.clone().into_iter();
    let stdin = std::io::stdin();
    let interactive = stdin.is_terminal();
    let mut lines = stdin.lock().lines();
    let ask = |q: &str| {
        if a.json {
            eprintln!("? {q}");
        } else {
            let mut out = std::io::stdout().lock();
            let _ = writeln!(out, "? {q}");
            if interactive {
                let _ = write!(out, "> ");
            }
            let _ = out.flush();
        }
    };
    while let Some(q) = refiner.next_question() {
        ask(&q);
        let answer = match scripted.next() {
            Some(s) => s,
            None if a.answers.is_empty() || !interactive => match lines.next() {
                Some(Ok(l)) => l,
                // End of input: the defaults for the rest.
                _ => "done".to_string(),
            },
            None => "done".to_string(),
        };
        if !a.json && !interactive {
            print(&format!("> {answer}"));
        }
        refiner.answer(&answer);
    }
    let refined = refiner.finish(client.as_ref()).map_err(failure)?;
    if let Some(path) = &a.plan_out {
        let mut text = serde_json::to_string_pretty(&refined.plan).map_err(|e| Failure::internal(e.to_string()))?;
        text.push('\n');
        fs_err::write(path, text).map_err(|e| Failure::input(e.to_string()))?;
    }
    if a.json {
        print_json(&refined);
    } else {
        let mut out = vec![format!("prompt   {}", refined.prompt)];
        if let Some(t) = &refined.task {
            out.push(format!("task     {t}"));
        }
        let p = &refined.plan;
        out.push(format!(
            "plan     {} {} × {} m · {} objects in {} groups · {} robots",
            p.room.kind.name().replace('_', " "),
            p.room.size.width,
            p.room.size.depth,
            p.object_count(),
            p.objects.len(),
            p.robots.iter().map(|r| r.count).sum::<u32>()
        ));
        out.extend(refined.warnings.iter().map(|w| format!("warning  {}", w.message)));
        out.extend(calls_summary(&refined.llm_calls).into_iter().map(|l| format!("llm      {l}")));
        out.push(format!("next     scenewright generate {} --out DIR", shell_quote(&refined.prompt)));
        print(&out.join("\n"));
    }
    Ok(0)
}

fn shell_quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', "'\\''"))
}
