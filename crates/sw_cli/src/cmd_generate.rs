//! `generate`, `validate` and `render`.

use std::ffi::OsString;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use sw_pipeline::{Event, Options, Outcome};
use sw_plan::{AnomalyKind, AnomalyRequest, Report, Status, Verification};

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Debug, clap::Args)]
pub(crate) struct GenerateArgs {
    /// What the scene should hold, in plain English.
    prompt: OsString,
    /// Directory to write the package to (must not exist, or be empty).
    #[arg(long)]
    out: PathBuf,
    /// Seed for the layout and the assets' variation.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Robots to use instead of the prompt's, e.g. `--robot ur5e,turtlebot3` (`none` for none).
    #[arg(long, value_delimiter = ',')]
    robot: Option<Vec<String>>,
    /// Skip the MuJoCo verification.
    #[arg(long)]
    no_verify: bool,
    /// Industrial rules profile to check instead of the room kind's (warehouse,
    /// industrial, laboratory, data_centre, kitchen, commercial, agricultural, general).
    #[arg(long)]
    rules: Option<String>,
    /// Inject labelled anomalies: overlap, scale, misplacement, floating, rule-violation
    /// (comma separated, or `all`).
    #[arg(long, value_delimiter = ',')]
    anomaly: Option<Vec<String>>,
    /// Fraction of eligible objects to corrupt with --anomaly.
    #[arg(long, default_value_t = 0.2)]
    anomaly_rate: f64,
    /// Write N structurally different layouts of the prompt into DIR/variation_1 … N.
    #[arg(long)]
    variations: Option<u32>,
    /// The simulator to write for: `native` (MuJoCo, MuJoCo Warp) or `mjx` (MuJoCo XLA's
    /// collision pairs: no cylinder–box; see ARCHITECTURE.md).
    #[arg(long, default_value = "native", value_parser = crate::cmd_dataset::parse_physics)]
    physics: sw_pipeline::PhysicsTarget,
    /// Add furniture and small things after the stated objects are placed, without
    /// moving them: `none`, `furnished` (the furniture the room's kind is used with) or
    /// `cluttered` (furnished, with things on every surface). Default: the prompt's own
    /// words ("cluttered", "lived-in", "furnished", "realistic"), else `none`.
    #[arg(long, value_parser = parse_fill)]
    fill: Option<sw_pipeline::FillLevel>,
    /// A task for the scene's robot ("put the red cube in the bowl"): bound to the scene
    /// and written to DIR/task.json (a task the scene cannot hold is bad input).
    #[arg(long, conflicts_with = "variations")]
    task: Option<String>,
    /// Print one JSON document instead of progress and a summary.
    #[arg(long)]
    json: bool,
}

fn parse_fill(s: &str) -> Result<sw_pipeline::FillLevel, String> {
    sw_pipeline::FillLevel::from_name(s)
        .ok_or_else(|| format!("unknown fill '{s}' (one of: {})", sw_pipeline::FillLevel::NAMES.join(", ")))
}

/// Binds `instruction` to the package at `dir` and writes `task.json` there.
pub(crate) fn write_task(dir: &Path, instruction: &str) -> Result<sw_task::Task, Failure> {
    let read = |name: &str| -> Result<String, Failure> {
        fs_err::read_to_string(dir.join(name)).map_err(|e| Failure::internal(e.to_string()))
    };
    let plan: sw_plan::ScenePlan =
        serde_json::from_str(&read("plan.json")?).map_err(|e| Failure::internal(e.to_string()))?;
    let layout: sw_plan::LaidOutScene =
        serde_json::from_str(&read("layout.json")?).map_err(|e| Failure::internal(e.to_string()))?;
    let mut joints = Vec::new();
    if let Ok(root) = sw_mjcf::xml::Element::parse(&read("scene.xml")?) {
        root.walk(&mut |e| {
            if e.name == "joint"
                && let Some(n) = e.get("name")
            {
                joints.push(n.to_string());
            }
        });
    }
    let facts = sw_task::SceneFacts::new(&plan, &layout, joints);
    let task = sw_task::bind(instruction, "flag", &facts).map_err(|e| Failure::input(e.to_string()))?;
    let mut text = serde_json::to_string_pretty(&task).map_err(|e| Failure::internal(e.to_string()))?;
    text.push('\n');
    fs_err::write(dir.join("task.json"), text).map_err(|e| Failure::internal(e.to_string()))?;
    Ok(task)
}

/// Progress output: spinners on a terminal, plain lines otherwise, nothing for --json.
enum Progress {
    Quiet,
    Lines,
    Bars(Option<ProgressBar>),
}

impl Progress {
    fn new(json: bool) -> Self {
        if json {
            Progress::Quiet
        } else if std::io::stderr().is_terminal() {
            Progress::Bars(None)
        } else {
            Progress::Lines
        }
    }

    fn event(&mut self, e: &Event) {
        match (self, e) {
            (Progress::Quiet, _) => {}
            (Progress::Lines, Event::StageStarted { .. }) => {}
            (Progress::Lines, Event::StageFinished { stage, ms, summary }) => {
                eprintln!("{:<9} {:>8.1} ms  {summary}", stage.label(), ms);
            }
            (Progress::Lines, Event::Note { stage, message }) => {
                eprintln!("{:<9}             {message}", stage.label())
            }
            (Progress::Bars(bar), Event::StageStarted { stage }) => {
                let b = ProgressBar::new_spinner();
                b.set_style(
                    ProgressStyle::with_template("{spinner} {msg}")
                        .unwrap_or_else(|_| ProgressStyle::default_spinner()),
                );
                b.set_message(format!("{} …", stage.label()));
                b.enable_steady_tick(Duration::from_millis(80));
                *bar = Some(b);
            }
            (Progress::Bars(bar), Event::StageFinished { stage, ms, summary }) => {
                if let Some(b) = bar.take() {
                    b.finish_and_clear();
                }
                eprintln!("✓ {:<9} {:>8.1} ms  {summary}", stage.label(), ms);
            }
            (Progress::Bars(bar), Event::Note { stage, message }) => match bar {
                Some(b) => b.println(format!("  {:<9} {message}", stage.label())),
                None => eprintln!("  {:<9}             {message}", stage.label()),
            },
            // Per-object steps show on the spinner; plain lines stay one per stage.
            (Progress::Lines, Event::Object { .. }) => {}
            (Progress::Bars(bar), Event::Object { stage, object, step }) => {
                if let Some(b) = bar {
                    b.set_message(format!("{} … {object}: {step}", stage.label()));
                }
            }
        }
    }
}

pub(crate) fn run(a: GenerateArgs) -> Result<u8, Failure> {
    let prompt = a.prompt.to_str().ok_or_else(|| Failure::input("the prompt is not valid UTF-8 text"))?.to_string();
    let anomaly = match &a.anomaly {
        None => None,
        Some(kinds) => Some(AnomalyRequest { kinds: parse_anomalies(kinds)?, rate: a.anomaly_rate }),
    };
    let opts = Options {
        seed: a.seed,
        verify: !a.no_verify,
        robots: a.robot.clone(),
        rules_profile: a.rules.clone(),
        anomaly,
        cancel: None,
        physics: a.physics,
        fill: a.fill,
    };
    if let Some(n) = a.variations {
        return run_variations(&prompt, &a.out, n, &opts, a.json);
    }
    let mut progress = Progress::new(a.json);
    let outcome =
        sw_pipeline::generate(&prompt, &a.out, &opts, &mut |e| progress.event(e)).map_err(|e| match e.exit_code() {
            2 => Failure::input(e.to_string()),
            _ => Failure::internal(e.to_string()),
        })?;
    let code = if sw_pipeline::succeeded(&outcome.report) { 0 } else { 1 };
    if let Some(t) = &a.task
        && let Err(e) = write_task(&outcome.out_dir, t)
    {
        // A package for a task it cannot hold is not handed out.
        let _ = std::fs::remove_dir_all(&outcome.out_dir);
        return Err(e);
    }
    if a.json {
        print_json(&serde_json::json!({
            "status": outcome.report.status,
            "out_dir": outcome.out_dir,
            "scene": outcome.out_dir.join("scene.xml"),
            "report": outcome.report,
            "timings": outcome.timings,
        }));
    } else {
        print(&summary(&outcome));
    }
    if code != 0 && !a.json {
        eprintln!("error: the scene failed verification; see {}", outcome.out_dir.join("report.json").display());
    }
    Ok(code)
}

pub(crate) fn parse_anomalies(words: &[String]) -> Result<Vec<AnomalyKind>, Failure> {
    let mut out = Vec::new();
    for w in words {
        let kinds: &[AnomalyKind] = match w.trim().to_lowercase().replace('_', "-").as_str() {
            "overlap" => &[AnomalyKind::Overlap],
            "scale" => &[AnomalyKind::Scale],
            "misplacement" => &[AnomalyKind::Misplacement],
            "floating" => &[AnomalyKind::Floating],
            "rule-violation" => &[AnomalyKind::RuleViolation],
            "all" => &[
                AnomalyKind::Overlap,
                AnomalyKind::Scale,
                AnomalyKind::Misplacement,
                AnomalyKind::Floating,
                AnomalyKind::RuleViolation,
            ],
            other => {
                return Err(Failure::input(format!(
                    "unknown anomaly '{other}' (overlap, scale, misplacement, floating, rule-violation, all)"
                )));
            }
        };
        for k in kinds {
            if !out.contains(k) {
                out.push(*k);
            }
        }
    }
    Ok(out)
}

fn run_variations(prompt: &str, out: &Path, n: u32, opts: &Options, json: bool) -> Result<u8, Failure> {
    let mut progress = Progress::new(json);
    let outcomes = sw_pipeline::generate_variations(prompt, out, n, opts, &mut |e| progress.event(e)).map_err(|e| {
        match e.exit_code() {
            2 => Failure::input(e.to_string()),
            _ => Failure::internal(e.to_string()),
        }
    })?;
    let ok = outcomes.iter().all(|o| sw_pipeline::succeeded(&o.report));
    if json {
        let list: Vec<serde_json::Value> = outcomes
            .iter()
            .map(|o| serde_json::json!({ "status": o.report.status, "out_dir": o.out_dir, "seed": o.report.seed }))
            .collect();
        print_json(&serde_json::json!({ "variations": list, "index": out.join("variations.json") }));
    } else {
        for o in &outcomes {
            print(&format!(
                "{}  seed {}  {}",
                o.out_dir.join("scene.xml").display(),
                o.report.seed,
                verification_line(&o.report)
            ));
        }
    }
    Ok(if ok { 0 } else { 1 })
}

fn summary(o: &Outcome) -> String {
    let r = &o.report;
    let s = &r.summary;
    let mut lines = Vec::new();
    lines.push(format!("scene    {}", o.out_dir.join("scene.xml").display()));
    lines.push(format!(
        "room     {} {} × {} × {} m · {} of {} objects placed{}",
        s.room.replace('_', " "),
        trim(s.room_size[0]),
        trim(s.room_size[1]),
        trim(s.room_size[2]),
        s.objects_placed,
        s.objects_requested,
        if s.robots.is_empty() { String::new() } else { format!(" · robots: {}", s.robots.join(", ")) }
    ));
    lines.push(format!("verify   {}", verification_line(r)));
    if !r.relations.is_empty() {
        lines.push(relations_line(r));
    }
    for a in &r.approximated {
        lines.push(format!("approx   \"{}\" → {} ({})", a.text, a.became, a.reason));
    }
    for n in &r.not_understood {
        lines.push(format!("ignored  \"{}\" ({})", n.text, n.reason));
    }
    for l in &r.left_out {
        lines.push(format!("left out {} of {} {}: {}", l.requested - l.placed, l.requested, l.group, l.reason));
    }
    for v in &r.violations {
        let how = if v.requested { "(as asked)" } else { "VIOLATED" };
        lines.push(format!("rule     {} {how}: {} ({})", v.rule, v.message, v.standard));
    }
    for a in &o.layout.anomalies {
        lines.push(format!("anomaly  {} {:?}: {}", a.object, a.kind, a.description));
    }
    for w in &r.warnings {
        lines.push(format!("warning  {}", w.message));
    }
    lines.push(format!("time     {:.0} ms", o.timings.total_ms));
    lines.join("\n")
}

/// "relations 12/12 held", or which did not, measured on the written scene.
fn relations_line(r: &Report) -> String {
    let held = r.relations.iter().filter(|c| c.held).count();
    let mut line = format!("relations {held}/{} held", r.relations.len());
    let missed: Vec<&str> = r.relations.iter().filter(|c| !c.held).map(|c| c.phrase.as_str()).collect();
    if !missed.is_empty() {
        line.push_str(&format!(" · not held: {}", missed.join("; ")));
    }
    line
}

fn verification_line(r: &Report) -> String {
    match (&r.status, &r.verification) {
        (Status::Unverified, _) | (_, None) => "skipped (--no-verify)".into(),
        (_, Some(v)) => describe(v),
    }
}

fn describe(v: &Verification) -> String {
    if !v.compiled {
        return format!("FAILED: {}", v.failures.join("; "));
    }
    let deep = v.initial_contacts.as_ref().map_or(0, |c| c.deep.len());
    let settle = v
        .settle
        .as_ref()
        .map(|s| {
            format!(
                "largest drift in a {} s settle {:.2} mm{}",
                s.duration_s,
                s.max_displacement_m * 1000.0,
                s.worst_body.as_ref().map(|b| format!(" ({b})")).unwrap_or_default()
            )
        })
        .unwrap_or_default();
    let head = if v.passed {
        format!("passed in {}", v.engine)
    } else {
        format!("FAILED in {}: {}", v.engine, v.failures.join("; "))
    };
    let expected = if v.expected.is_empty() {
        String::new()
    } else {
        format!(" · {} findings explained by the injected anomalies", v.expected.len())
    };
    format!("{head} · compiled · {deep} contacts deeper than 1 mm at t = 0 · {settle}{expected}")
}

pub(crate) fn validate(dir: &Path, json: bool) -> Result<u8, Failure> {
    let v = sw_pipeline::validate_dir(dir).map_err(|e| Failure::input(e.to_string()))?;
    if json {
        print_json(&v);
    } else {
        print(&format!("verify   {}", describe(&v)));
    }
    Ok(if v.passed { 0 } else { 1 })
}

pub(crate) fn render(dir: &Path, out: &Path, width: u32, height: u32, collision: bool) -> Result<u8, Failure> {
    let scene = if dir.is_file() { dir.to_path_buf() } else { dir.join("scene.xml") };
    if !scene.is_file() {
        return Err(Failure::input(format!("'{}' is not a scene package (no scene.xml)", dir.display())));
    }
    if !(16..=8192).contains(&width) || !(16..=8192).contains(&height) {
        return Err(Failure::input("width and height must be between 16 and 8192 pixels"));
    }
    let groups: &[i32] = if collision { &[3] } else { &[2] };
    let img = sw_sim::render_scene(&scene, width, height, groups).map_err(Failure::internal)?;
    let file = fs_err::File::create(out).map_err(|e| Failure::input(e.to_string()))?;
    img.write_png(std::io::BufWriter::new(file)).map_err(|e| Failure::internal(e.to_string()))?;
    Ok(0)
}

fn trim(v: f64) -> String {
    let s = format!("{v:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}
