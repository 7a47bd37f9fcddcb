//! `scenewright`: plain-English descriptions in, verified MuJoCo scenes out.
//!
//! Exit codes: 0 success; 2 bad input (one line on stderr); 1 internal error or a scene
//! that failed verification.

mod bench_cad;
mod bench_fill;
mod bench_index;
mod bench_llm;
mod bench_llm_real;
mod bench_relations;
mod bench_server;
mod cmd_assets;
mod cmd_bench;
mod cmd_dataset;
mod cmd_demos;
mod cmd_edit;
mod cmd_export;
mod cmd_forge;
mod cmd_generate;
mod cmd_llm;
mod cmd_robots;
mod cmd_serve;
mod dataset_queue;
mod demos_dir;
mod output;

use std::ffi::OsString;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

#[derive(Debug, Parser)]
#[command(name = "scenewright", version, about = "Plain-English descriptions in, verified MuJoCo scenes out.")]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// A directory of MJCF/URDF robots to register (repeatable; also SCENEWRIGHT_ROBOTS).
    #[arg(long, global = true, value_name = "DIR")]
    robots_dir: Vec<PathBuf>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Generate a scene package from a prompt.
    Generate(cmd_generate::GenerateArgs),
    /// Re-verify a package with MuJoCo and print the verification.
    Validate {
        dir: PathBuf,
        /// Print one JSON document.
        #[arg(long)]
        json: bool,
    },
    /// Render a package's scene.xml to a PNG (software renderer, no GPU needed).
    Render {
        dir: PathBuf,
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value_t = 1280)]
        width: u32,
        #[arg(long, default_value_t = 800)]
        height: u32,
        /// Draw collision geometry (group 3) instead of visual meshes.
        #[arg(long)]
        collision: bool,
    },
    /// The procedural asset catalog.
    #[command(subcommand)]
    Assets(cmd_assets::AssetsCommand),
    /// The robot registry.
    #[command(subcommand)]
    Robots(cmd_robots::RobotsCommand),
    /// Benchmarks that print numbers.
    #[command(subcommand)]
    Bench(cmd_bench::BenchCommand),
    /// Generate with an LLM planner, print its plan, show the configured endpoints.
    #[command(subcommand)]
    Llm(cmd_llm::LlmCommand),
    /// Change a package in plain English ("remove the chair next to the conveyor").
    Edit(cmd_edit::EditArgs),
    /// A conversation that asks about what a prompt leaves open, ending with a final
    /// prompt and plan.
    Refine(cmd_edit::RefineArgs),
    /// Run the HTTP API with in-process job runners.
    Serve(cmd_serve::ServeArgs),
    /// Run job runners only, on the same database and blob store as a `serve`.
    Worker(cmd_serve::WorkerArgs),
    /// N verified, structurally different scenes per prompt into a directory with
    /// manifest.jsonl (resumable; every core, or the service's queue with --database).
    Dataset(cmd_dataset::DatasetArgs),
    /// Solved demonstrations of a task as a LeRobot v3.0 dataset: an expert solves the task
    /// in MuJoCo on a new scene variant per episode (resumable; every core).
    Demos(cmd_demos::DemosArgs),
    /// Convert a package to another format (`--format usd`: OpenUSD via mujoco-usd-converter).
    Export(cmd_export::ExportArgs),
    /// Write the JSON Schemas of plan.json, layout.json, report.json and timings.json.
    Schema {
        /// Directory to write into (default: print the plan schema).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

/// A failure with its exit code. Messages are one line.
#[derive(Debug)]
pub(crate) struct Failure {
    pub code: u8,
    pub message: String,
}

impl Failure {
    pub fn input(message: impl Into<String>) -> Self {
        Self { code: 2, message: message.into() }
    }

    pub fn internal(message: impl Into<String>) -> Self {
        Self { code: 1, message: message.into() }
    }
}

impl From<anyhow::Error> for Failure {
    fn from(e: anyhow::Error) -> Self {
        Failure::internal(format!("{e:#}"))
    }
}

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().collect();
    let cli = match Cli::try_parse_from(&args) {
        Ok(c) => c,
        Err(e) if e.use_stderr() => {
            // Usage errors are bad input: one line, exit 2.
            eprintln!("error: {} (see scenewright --help)", one_line_usage_error(&e.render().to_string()));
            return ExitCode::from(2);
        }
        Err(e) => {
            // Help and version go to stdout.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
    };
    // The service logs in its --log-format (a bad SCENEWRIGHT_LOG_FORMAT is reported by
    // the command); every other command logs warnings as text.
    cmd_serve::init_logs(match &cli.command {
        Command::Serve(a) => Some(a.log_format().unwrap_or_default()),
        Command::Worker(a) => Some(a.log_format().unwrap_or_default()),
        _ => None,
    });
    // Ctrl-C or SIGTERM in the middle of a run: remove the half-written package. (The
    // service handles its own signals and shuts down gracefully.)
    let service = matches!(cli.command, Command::Serve(_) | Command::Worker(_));
    let _ = (!service).then(|| {
        ctrlc::set_handler(|| {
            // A dataset stops by itself at the first Ctrl-C, keeping every finished scene.
            if cmd_dataset::interrupt() {
                return;
            }
            sw_pipeline::discard_staged_packages();
            eprintln!("error: interrupted; no package was written");
            std::process::exit(130);
        })
    });
    if !cli.robots_dir.is_empty() {
        sw_robots::configure(sw_robots::Config { packs_dir: None, user_dirs: cli.robots_dir.clone() });
    }
    let result = match cli.command {
        Command::Generate(a) => cmd_generate::run(a),
        Command::Validate { dir, json } => cmd_generate::validate(&dir, json),
        Command::Render { dir, out, width, height, collision } => {
            cmd_generate::render(&dir, &out, width, height, collision)
        }
        Command::Assets(c) => cmd_assets::run(c),
        Command::Robots(c) => cmd_robots::run(c),
        Command::Bench(c) => cmd_bench::run(c),
        Command::Schema { out } => schema(out),
        Command::Serve(a) => cmd_serve::serve(a),
        Command::Worker(a) => cmd_serve::worker(a),
        Command::Llm(c) => cmd_llm::run(c),
        Command::Edit(a) => cmd_edit::edit(a),
        Command::Refine(a) => cmd_edit::refine(a),
        Command::Dataset(a) => cmd_dataset::run(a),
        Command::Demos(a) => cmd_demos::run(a),
        Command::Export(a) => cmd_export::run(a),
    };
    match result {
        Ok(code) => ExitCode::from(code),
        Err(f) => {
            let line = f.message.lines().collect::<Vec<_>>().join(" ");
            eprintln!("error: {line}");
            ExitCode::from(f.code)
        }
    }
}

/// Clap's message without its usage block and tips, on one line.
fn one_line_usage_error(rendered: &str) -> String {
    let mut parts = Vec::new();
    for line in rendered.lines() {
        let line = line.trim();
        if line.starts_with("Usage:") || line.starts_with("tip:") || line.starts_with("For more information") {
            break;
        }
        if !line.is_empty() {
            parts.push(line.trim_start_matches("error:").trim().to_string());
        }
    }
    parts.join(" ")
}

fn schema(out: Option<PathBuf>) -> Result<u8, Failure> {
    let schemas = sw_plan::schemas();
    match out {
        None => {
            output::print(&schemas[0].json);
            Ok(0)
        }
        Some(dir) => {
            fs_err::create_dir_all(&dir).map_err(|e| Failure::input(e.to_string()))?;
            for s in schemas {
                fs_err::write(dir.join(s.file_name), s.json).map_err(|e| Failure::input(e.to_string()))?;
            }
            Ok(0)
        }
    }
}
