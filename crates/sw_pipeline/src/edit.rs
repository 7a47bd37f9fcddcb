//! `scenewright edit DIR "<command>"`: a natural-language edit of a package. The
//! command is read by the offline grammar (or, for what it does not understand, by the
//! edit LLM), applied with everything it does not change pinned where it was, the
//! layout re-solved around the pins, the package re-written and re-verified in MuJoCo,
//! and the edit appended to `edits.json`. All or nothing: the new package is built
//! beside the old one and swapped in only when it verified; any failure leaves the
//! package exactly as it was.

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;
use sw_edit::{EditCommand, SceneView};
use sw_layout::{LayoutInput, Pins, solve_pinned};
use sw_llm::{ChatRequest, Client, LlmStage, Message, extract_json};
use sw_plan::{EditLog, EditRecord, LaidOutScene, Report, ScenePlan, Stage, Timings, Warning};
use tracing::info_span;

use crate::edit_pose::StructuredEdit;
use crate::edit_work::Work;
use crate::{Event, OutputError, PipelineError, package, report, stage_finished, stage_started};

/// How an edit command is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EditReader {
    /// The offline grammar only.
    Grammar,
    /// The grammar, and the LLM for what it does not understand (when configured).
    GrammarThenLlm,
    /// The LLM only.
    Llm,
}

/// What an edit did.
#[derive(Debug)]
pub struct EditOutcome {
    pub record: EditRecord,
    pub plan: ScenePlan,
    pub layout: LaidOutScene,
    pub report: Report,
    pub timings: Timings,
    pub dir: PathBuf,
}

fn input(e: impl ToString) -> PipelineError {
    PipelineError::Input(e.to_string())
}

fn read_json<T: serde::de::DeserializeOwned>(dir: &Path, name: &str) -> Result<T, PipelineError> {
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path).map_err(|e| input(format!("{}: {e}", path.display())))?;
    serde_json::from_str(&text).map_err(|e| input(format!("{}: {e}", path.display())))
}

/// The package's documents.
struct Package {
    plan: ScenePlan,
    layout: LaidOutScene,
    report: Report,
    edits: EditLog,
}

fn load(dir: &Path) -> Result<Package, PipelineError> {
    if !dir.join("scene.xml").is_file() {
        return Err(PipelineError::Output(OutputError::NotAPackage(dir.to_path_buf())));
    }
    let plan_path = dir.join("plan.json");
    let text = std::fs::read_to_string(&plan_path).map_err(|e| input(format!("{}: {e}", plan_path.display())))?;
    let plan = ScenePlan::from_json(&text).map_err(|e| input(format!("{}: {e}", plan_path.display())))?;
    let layout: LaidOutScene = read_json(dir, "layout.json")?;
    let report: Report = read_json(dir, "report.json")?;
    let edits: EditLog =
        if dir.join("edits.json").is_file() { read_json(dir, "edits.json")? } else { EditLog::default() };
    if !layout.anomalies.is_empty() {
        return Err(input(format!(
            "{} holds injected anomalies (a dataset sample); edits would make its labels wrong — generate it again instead",
            dir.display()
        )));
    }
    Ok(Package { plan, layout, report, edits })
}

/// Reads the command with the LLM (structured output, one repair round).
fn read_with_llm(command: &str, view: &SceneView<'_>, client: &Client) -> Result<EditCommand, PipelineError> {
    let (system, user) = sw_edit::llm::edit_messages(command, view);
    let mut messages = vec![Message::system(system), Message::user(user)];
    let mut problem = String::new();
    for round in 0..2 {
        let req = ChatRequest::new(messages.clone())
            .with_schema(sw_edit::llm::EDIT_SCHEMA_NAME, sw_edit::llm::model_schema());
        let purpose = if round == 0 { "edit" } else { "edit (repair)" };
        let answer = client.complete(LlmStage::Edit, &req, purpose).map_err(|e| {
            let how = if e.unreachable() { "could not be reached" } else { "failed" };
            PipelineError::Upstream(format!("the edit LLM {how} ({e})"))
        })?;
        match extract_json(&answer.content).map_err(|e| e.to_string()).and_then(|v| sw_edit::llm::read_edit(&v)) {
            Ok(c) => return Ok(c),
            Err(p) => problem = p,
        }
        let mut echo = answer.content;
        echo.truncate(echo.floor_char_boundary(8 * 1024));
        messages.push(Message::assistant(echo));
        messages.push(Message::user(format!(
            "Your answer could not be used: {problem}. Answer again with one JSON object {{\"ops\": [...]}} following the schema."
        )));
    }
    Err(input(format!("the edit LLM answered unusably twice (last: {problem})")))
}

/// Applies `command` to the package in `dir`.
pub fn edit_package(
    dir: &Path,
    command: &str,
    reader: EditReader,
    client: Option<&Client>,
    on_event: &mut dyn FnMut(&Event),
) -> Result<EditOutcome, PipelineError> {
    let started = Instant::now();
    let _span = info_span!("edit", dir = %dir.display()).entered();
    let pkg = load(dir)?;
    let mut timings = Timings::default();
    let client = client.map(Client::fresh);

    // Understand the command.
    let t = stage_started(Stage::Plan, on_event);
    let view = SceneView { plan: &pkg.plan, layout: &pkg.layout };
    let llm_ok = client.as_ref().is_some_and(|c| c.has(LlmStage::Edit));
    let (cmd, understood_by) = match reader {
        EditReader::Llm => {
            let c = client.as_ref().filter(|_| llm_ok).ok_or_else(|| {
                input("no LLM endpoint is configured for the edit stage (set SCENEWRIGHT_LLM_BASE_URL and SCENEWRIGHT_LLM_MODEL)")
            })?;
            (read_with_llm(command, &view, c)?, "llm")
        }
        EditReader::Grammar => (sw_edit::parse(command).map_err(input)?, "grammar"),
        EditReader::GrammarThenLlm => match sw_edit::parse(command) {
            Ok(c) => (c, "grammar"),
            Err(e) => match client.as_ref().filter(|_| llm_ok) {
                Some(c) => (read_with_llm(command, &view, c)?, "llm"),
                None => return Err(input(e)),
            },
        },
    };
    stage_finished(
        Stage::Plan,
        t,
        format!("{} operation(s), read by the {understood_by}", cmd.ops.len()),
        &mut timings,
        on_event,
    );
    let change = Change { command, understood_by };
    let calls = || client.as_ref().map(|c| c.telemetry().calls()).unwrap_or_default();
    let mut apply = |work: &mut Work| -> Result<(), String> {
        for op in &cmd.ops {
            work.apply(op)?;
        }
        Ok(())
    };
    run_edit(dir, pkg, &change, &mut apply, &calls, timings, started, on_event)
}

/// Applies a structured edit from the viewer (an object put at a pose, a part placed) to
/// the package in `dir`, as `edit_package` applies a sentence: re-solved around the change,
/// re-verified in MuJoCo, all or nothing. `command` is how the edit history names it.
pub fn edit_structured(
    dir: &Path,
    edit: &StructuredEdit,
    command: &str,
    on_event: &mut dyn FnMut(&Event),
) -> Result<EditOutcome, PipelineError> {
    let started = Instant::now();
    let _span = info_span!("edit", dir = %dir.display()).entered();
    let pkg = load(dir)?;
    let mut timings = Timings::default();
    let t = stage_started(Stage::Plan, on_event);
    stage_finished(Stage::Plan, t, format!("from the viewer: {command}"), &mut timings, on_event);
    let change = Change { command, understood_by: "viewer" };
    let mut apply = |work: &mut Work| work.apply_structured(edit);
    run_edit(dir, pkg, &change, &mut apply, &Vec::new, timings, started, on_event)
}

/// What an edit is called and who read it.
struct Change<'a> {
    command: &'a str,
    understood_by: &'static str,
}

/// The part every edit shares: the package's assets made again, the change applied with
/// everything else pinned, the layout re-solved around the pins, the package written and
/// verified beside the old one and swapped in only when it verified.
#[allow(clippy::too_many_arguments)]
fn run_edit(
    dir: &Path,
    pkg: Package,
    change: &Change<'_>,
    apply: &mut dyn FnMut(&mut Work) -> Result<(), String>,
    calls: &dyn Fn() -> Vec<sw_plan::LlmCall>,
    mut timings: Timings,
    started: Instant,
    on_event: &mut dyn FnMut(&Event),
) -> Result<EditOutcome, PipelineError> {
    let seed = pkg.layout.seed;
    // Apply it to the scene in memory.
    let t = stage_started(Stage::Forge, on_event);
    let mut forged = crate::rebuild::rebuild(&pkg.plan, &pkg.layout).map_err(PipelineError::Internal)?;
    // Placed parts come back from their meshes, not as their stand-ins.
    let parts = crate::parts::load(dir)?;
    for p in &parts {
        if let Some(f) = forged.objects.iter_mut().find(|o| o.name == p.entry.object) {
            f.asset = p.asset();
        }
    }
    let mut work = Work {
        plan: pkg.plan.clone(),
        layout: pkg.layout.clone(),
        forged,
        free: Default::default(),
        riders: Vec::new(),
        seed,
        ops: Vec::new(),
        added: Vec::new(),
        removed: Vec::new(),
        moved: Vec::new(),
        modified: Vec::new(),
        warnings: Vec::new(),
        parts,
    };
    apply(&mut work).map_err(|e| input(format!("{e}; the package is unchanged")))?;
    work.plan.validate().map_err(|e| PipelineError::Internal(format!("the edited plan is invalid: {e}")))?;
    stage_finished(Stage::Forge, t, work.ops.join("; "), &mut timings, on_event);

    // Re-solve around the pins.
    let t = stage_started(Stage::Layout, on_event);
    let mut layout = {
        let pins = Pins {
            room: work.layout.room.clone(),
            objects: work.layout.objects.clone(),
            robots: work.layout.robots.clone(),
        };
        let li = LayoutInput {
            plan: &work.plan,
            objects: work.items(),
            robots: work.forged.robots.clone(),
            seed,
            max_layers: Default::default(),
        };
        solve_pinned(&li, &pins)
    };
    work.land_riders(&mut layout);
    let missing: Vec<String> = work
        .forged
        .objects
        .iter()
        .map(|o| o.name.clone())
        .filter(|n| layout.object(n).is_none())
        .chain(
            work.forged.robots.iter().map(|r| r.name.clone()).filter(|n| !layout.robots.iter().any(|r| &r.name == n)),
        )
        .collect();
    if !missing.is_empty() {
        let s = layout.room.size;
        return Err(input(format!(
            "no free place for {} in the {:.1} × {:.1} m room; the package is unchanged",
            missing.join(", "),
            s.width,
            s.depth
        )));
    }
    // Requested objects that were never placed stay reported.
    for l in &pkg.layout.left_out {
        if work.plan.object(&l.group).is_some() && !layout.left_out.iter().any(|x| x.group == l.group) {
            layout.left_out.push(l.clone());
        }
    }
    // Objects keep the order of the original layout, new ones after.
    let order = |n: &str| pkg.layout.objects.iter().position(|o| o.name == n).unwrap_or(usize::MAX);
    layout.objects.sort_by_key(|o| order(&o.name));
    stage_finished(Stage::Layout, t, report::layout_summary(&layout), &mut timings, on_event);

    // Write, verify, swap in.
    let tmp = sibling(dir, "edit")?;
    let result = build_package(&tmp, &pkg, &work, &layout, &mut timings, started, on_event);
    let (report, record) = match result {
        Ok(x) => x,
        Err(e) => {
            let _ = std::fs::remove_dir_all(&tmp);
            return Err(e);
        }
    };
    let mut record = record;
    record.command = change.command.to_string();
    record.understood_by = change.understood_by.to_string();
    record.llm_calls = calls();
    let mut edits = pkg.edits.clone();
    record.number = edits.edits.last().map_or(1, |e| e.number + 1);
    edits.edits.push(record.clone());
    let finish = (|| -> Result<(), PipelineError> {
        write_json(&tmp.join("edits.json"), &edits)?;
        crate::parts::write(&tmp, &work.parts, |name| layout.object(name).is_some())?;
        copy_extras(dir, &tmp)?;
        swap(dir, &tmp)
    })();
    if let Err(e) = finish {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    Ok(EditOutcome { record, plan: work.plan, layout, report, timings, dir: dir.to_path_buf() })
}

fn build_package(
    tmp: &Path,
    pkg: &Package,
    work: &Work,
    layout: &LaidOutScene,
    timings: &mut Timings,
    started: Instant,
    on_event: &mut dyn FnMut(&Event),
) -> Result<(Report, EditRecord), PipelineError> {
    let staging = package::Staging::create(tmp)?;
    let t = stage_started(Stage::Bridge, on_event);
    let files = package::bridge(&work.plan.prompt, layout, &work.forged)?;
    staging.write_scene(&files, &work.plan, layout)?;
    stage_finished(Stage::Bridge, t, format!("{} meshes", files.meshes.len()), timings, on_event);
    let t = stage_started(Stage::Verify, on_event);
    let v = sw_sim::verify_file(
        &staging.path().join("scene.xml"),
        &sw_sim::VerifyOptions { robots: layout.robots.iter().map(|r| r.name.clone()).collect(), ..Default::default() },
    );
    stage_finished(Stage::Verify, t, report::verify_summary(&v), timings, on_event);
    if !v.passed {
        return Err(PipelineError::Internal(format!(
            "the edited scene failed verification in MuJoCo ({}); the package is unchanged",
            v.failures.join("; ")
        )));
    }
    // Warnings of how the scene was planned and its assets made are kept; the layout's
    // and the verification's are measured again.
    let mut warnings: Vec<Warning> = pkg
        .report
        .warnings
        .iter()
        .filter(|w| matches!(w.stage, Stage::Plan | Stage::Forge | Stage::Bridge))
        .cloned()
        .collect();
    warnings.extend(work.warnings.iter().cloned());
    let mut rep = report::assemble(&work.plan, layout, pkg.layout.seed, warnings, Some(v));
    // The stated relations are measured again on the edited scene, as on a generated one:
    // an edit never drops them from the report.
    crate::relations_check::attach(&mut rep, &work.plan, staging.path());
    rep.llm_calls = pkg.report.llm_calls.clone();
    // How the scene's assets came about is the generation's story.
    rep.asset_cache = pkg.report.asset_cache;
    timings.total_ms = started.elapsed().as_secs_f64() * 1000.0;
    staging.write_report(&rep, timings)?;
    staging.commit()?;
    let record = EditRecord {
        number: 0,
        command: String::new(),
        understood_by: String::new(),
        operations: work.ops.clone(),
        added: work.added.clone(),
        removed: work.removed.clone(),
        moved: work.moved.clone(),
        modified: work.modified.clone(),
        llm_calls: Vec::new(),
    };
    Ok((rep, record))
}

/// A hidden sibling path of `dir` that does not exist.
fn sibling(dir: &Path, what: &str) -> Result<PathBuf, PipelineError> {
    let name = dir
        .file_name()
        .and_then(|n| n.to_str())
        .ok_or_else(|| input(format!("'{}' is not a package directory", dir.display())))?;
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let stamp = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos());
    Ok(parent.join(format!(".{name}.{what}-{}-{stamp}", std::process::id())))
}

fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), PipelineError> {
    let mut text = serde_json::to_string_pretty(value).map_err(|e| PipelineError::Internal(e.to_string()))?;
    text.push('\n');
    fs_err::write(path, text).map_err(|e| PipelineError::Internal(e.to_string()))
}

/// Files of the package that the pipeline does not write (a user's notes) come along.
fn copy_extras(from: &Path, to: &Path) -> Result<(), PipelineError> {
    const OURS: &[&str] = &[
        "scene.xml",
        "scene_only.xml",
        "plan.json",
        "layout.json",
        "report.json",
        "timings.json",
        "edits.json",
        crate::parts::FILE,
    ];
    let entries = std::fs::read_dir(from).map_err(|e| PipelineError::Internal(format!("{}: {e}", from.display())))?;
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(n) = name.to_str() else { continue };
        if OURS.contains(&n) || !e.path().is_file() {
            continue;
        }
        std::fs::copy(e.path(), to.join(n)).map_err(|err| PipelineError::Internal(format!("copying {n}: {err}")))?;
    }
    Ok(())
}

/// Replaces `dir` with `new`: the old package is renamed aside, the new one renamed into
/// place, the old one removed. If the second rename fails, the old one is put back.
fn swap(dir: &Path, new: &Path) -> Result<(), PipelineError> {
    let old = sibling(dir, "old")?;
    std::fs::rename(dir, &old).map_err(|e| PipelineError::Internal(format!("{}: {e}", dir.display())))?;
    if let Err(e) = std::fs::rename(new, dir) {
        let _ = std::fs::rename(&old, dir);
        return Err(PipelineError::Internal(format!("{}: {e}", dir.display())));
    }
    let _ = std::fs::remove_dir_all(&old);
    Ok(())
}
