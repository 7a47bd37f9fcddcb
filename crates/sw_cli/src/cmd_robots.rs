//! `robots list|show|bench`: the registry, one robot's facts (or its MJCF, or a fresh
//! measurement in MuJoCo), and the merger's speed per robot.

use std::time::Instant;

use clap::Subcommand;
use serde::Serialize;
use sw_geom::Pose;
use sw_robots::{Origin, RobotDef};

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Debug, Subcommand)]
pub(crate) enum RobotsCommand {
    /// Every registered robot, the robot packs (installed or how to fetch them), and user
    /// files that could not be registered.
    List {
        #[arg(long)]
        json: bool,
    },
    /// One robot's facts, or its MJCF with `--mjcf` (the robot alone, loadable as is).
    Show {
        name: String,
        #[arg(long)]
        mjcf: bool,
        /// Measure the robot at its home pose in MuJoCo (keep-out boxes, reach).
        #[arg(long)]
        measure: bool,
        #[arg(long)]
        json: bool,
    },
    /// Time reading and merging every registered robot.
    Bench {
        /// Merges per robot (the median and the slowest are printed).
        #[arg(long, default_value_t = 20)]
        repeat: usize,
        #[arg(long)]
        json: bool,
    },
}

#[derive(Serialize)]
struct RobotInfo {
    name: &'static str,
    aliases: Vec<&'static str>,
    display: &'static str,
    kind: &'static str,
    origin: String,
    source: &'static str,
    licence: &'static str,
    licence_files: Vec<String>,
    files: Vec<String>,
    reach_m: f64,
    footprint_radius_m: f64,
    height_m: f64,
    base_radius_m: f64,
    keepout: Vec<([f64; 3], [f64; 3])>,
    /// False for user robots: their mounting facts are measured when first used.
    measured: bool,
}

fn origin(o: &Origin) -> String {
    match o {
        Origin::BuiltIn => "built-in".into(),
        Origin::Pack { pack, .. } => format!("pack: {pack}"),
        Origin::User { .. } => "user".into(),
    }
}

fn info(r: &'static RobotDef) -> RobotInfo {
    RobotInfo {
        name: r.name,
        aliases: r.aliases.to_vec(),
        display: r.display,
        kind: r.kind.label(),
        origin: origin(&r.origin),
        source: r.source,
        licence: r.licence.name,
        licence_files: r.licence.files.iter().map(|f| f.display().to_string()).collect(),
        files: r.files().iter().map(|f| f.display().to_string()).collect(),
        reach_m: r.reach,
        footprint_radius_m: r.footprint_radius,
        height_m: r.height,
        base_radius_m: r.base_radius,
        keepout: r.keepout.to_vec(),
        measured: r.measured,
    }
}

#[derive(Serialize)]
struct PackInfo {
    name: &'static str,
    present: bool,
    dir: String,
    licence: &'static str,
    robots: Vec<&'static str>,
    fetch: &'static str,
}

#[derive(Serialize)]
struct ListOutput {
    robots: Vec<RobotInfo>,
    packs: Vec<PackInfo>,
    problems: Vec<String>,
}

fn lookup(name: &str) -> Result<&'static RobotDef, Failure> {
    sw_robots::find(name).ok_or_else(|| {
        Failure::input(sw_robots::why_missing(name).unwrap_or_else(|| {
            let known: Vec<&str> = sw_robots::registry().iter().map(|r| r.name).collect();
            format!("unknown robot '{name}' (known: {})", known.join(", "))
        }))
    })
}

pub(crate) fn run(c: RobotsCommand) -> Result<u8, Failure> {
    match c {
        RobotsCommand::List { json } => {
            let s = sw_robots::status();
            let out = ListOutput {
                robots: s.robots.iter().map(|r| info(r)).collect(),
                packs: s
                    .packs
                    .iter()
                    .map(|p| PackInfo {
                        name: p.name,
                        present: p.present,
                        dir: p.dir.display().to_string(),
                        licence: p.licence,
                        robots: p.robots.clone(),
                        fetch: p.fetch,
                    })
                    .collect(),
                problems: s.problems.iter().map(ToString::to_string).collect(),
            };
            if json {
                print_json(&out);
            } else {
                for r in &out.robots {
                    print(&format!("{:<24} {:<18} {:<28} {}", r.name, r.kind, r.origin, r.display));
                }
                for p in &out.packs {
                    if p.present {
                        print(&format!("pack {}: installed in {} ({})", p.name, p.dir, p.licence));
                    } else {
                        print(&format!(
                            "pack {}: not installed ({}); run `{}` to fetch it",
                            p.name,
                            p.robots.join(", "),
                            p.fetch
                        ));
                    }
                }
                for e in &out.problems {
                    eprintln!("error: {e}");
                }
            }
            Ok(0)
        }
        RobotsCommand::Show { name, mjcf, measure, json } => {
            let r = lookup(&name)?;
            let model = r.model().map_err(|e| Failure::input(e.to_string()))?;
            if mjcf {
                let doc = sw_mjcf::robot_document(&model, r.name).map_err(|e| Failure::input(e.to_string()))?;
                print(&doc);
                return Ok(0);
            }
            // Merging validates the model (names, references, files); notes say what changed.
            let prepared =
                sw_mjcf::prepare_robot(&model, r.name, &Pose::IDENTITY).map_err(|e| Failure::input(e.to_string()))?;
            let measured = if measure { Some(sw_pipeline::measure_robot(r).map_err(Failure::input)?) } else { None };
            let i = info(r);
            if json {
                #[derive(Serialize)]
                struct Show {
                    #[serde(flatten)]
                    info: RobotInfo,
                    actuators: usize,
                    files_referenced: usize,
                    notes: Vec<String>,
                    measured_now: Option<Measured>,
                }
                #[derive(Serialize)]
                struct Measured {
                    keepout: Vec<([f64; 3], [f64; 3])>,
                    footprint_radius_m: f64,
                    height_m: f64,
                    reach_m: f64,
                    base_radius_m: f64,
                }
                print_json(&Show {
                    info: i,
                    actuators: prepared.sections.get("actuator").map_or(0, Vec::len),
                    files_referenced: prepared.files.len(),
                    notes: prepared.notes.clone(),
                    measured_now: measured.map(|f| Measured {
                        keepout: f.keepout,
                        footprint_radius_m: f.footprint_radius,
                        height_m: f.height,
                        reach_m: f.reach,
                        base_radius_m: f.base_radius,
                    }),
                });
            } else {
                let mut lines = vec![
                    i.name.to_string(),
                    format!("  {}", i.display),
                    format!(
                        "  kind {} · reach {} m · footprint radius {} m · height {} m · base radius {} m",
                        i.kind, i.reach_m, i.footprint_radius_m, i.height_m, i.base_radius_m
                    ),
                    format!("  {} ({})", i.origin, i.source),
                    format!(
                        "  licence: {}{}",
                        i.licence,
                        if i.licence_files.is_empty() {
                            String::new()
                        } else {
                            format!(" ({})", i.licence_files.join(", "))
                        }
                    ),
                    format!(
                        "  {} actuators · {} files referenced",
                        prepared.sections.get("actuator").map_or(0, Vec::len),
                        prepared.files.len()
                    ),
                ];
                if !i.aliases.is_empty() {
                    lines.push(format!("  also found as: {}", i.aliases.join(", ")));
                }
                for (lo, hi) in &i.keepout {
                    lines.push(format!("  keep-out {lo:?} .. {hi:?}"));
                }
                if !i.measured {
                    lines.push("  mounting facts are measured in MuJoCo when the robot is first used".into());
                }
                for n in &prepared.notes {
                    lines.push(format!("  note: {n}"));
                }
                if let Some(f) = measured {
                    lines.push(format!(
                        "  measured now: reach {:.3} m · footprint radius {:.2} m · height {:.2} m · base radius {:.3} m",
                        f.reach, f.footprint_radius, f.height, f.base_radius
                    ));
                    for (lo, hi) in &f.keepout {
                        lines.push(format!("  measured keep-out {lo:?} .. {hi:?}"));
                    }
                }
                print(&lines.join("\n"));
            }
            Ok(0)
        }
        RobotsCommand::Bench { repeat, json } => bench(repeat.max(1), json),
    }
}

#[derive(Serialize)]
struct BenchRow {
    robot: &'static str,
    parts: usize,
    files: usize,
    /// Reading the MJCF/URDF (and includes) from disk, ms.
    load_ms: f64,
    /// `prepare_robot`: parse, normalise, prefix, assemble, ms (median, slowest).
    merge_ms_p50: f64,
    merge_ms_max: f64,
}

fn bench(repeat: usize, json: bool) -> Result<u8, Failure> {
    let mut rows = Vec::new();
    for r in sw_robots::registry() {
        let t = Instant::now();
        let model = r.model().map_err(|e| Failure::input(format!("{}: {e}", r.name)))?;
        let load_ms = t.elapsed().as_secs_f64() * 1e3;
        let mut times = Vec::with_capacity(repeat);
        let mut files = 0;
        for k in 0..repeat {
            let t = Instant::now();
            let p = sw_mjcf::prepare_robot(&model, &format!("{}_{}", r.name, k + 1), &Pose::from_pos([1.0, 2.0, 0.75]))
                .map_err(|e| Failure::input(e.to_string()))?;
            times.push(t.elapsed().as_secs_f64() * 1e3);
            files = p.files.len();
        }
        times.sort_by(f64::total_cmp);
        rows.push(BenchRow {
            robot: r.name,
            parts: model.parts.len(),
            files,
            load_ms,
            merge_ms_p50: times[times.len() / 2],
            merge_ms_max: times[times.len() - 1],
        });
    }
    if json {
        print_json(&rows);
    } else {
        let mut lines = vec![format!(
            "{:<24} {:>5} {:>6} {:>9} {:>11} {:>11}",
            "robot", "parts", "files", "load ms", "merge p50", "merge max"
        )];
        for r in &rows {
            lines.push(format!(
                "{:<24} {:>5} {:>6} {:>9.2} {:>11.2} {:>11.2}",
                r.robot, r.parts, r.files, r.load_ms, r.merge_ms_p50, r.merge_ms_max
            ));
        }
        print(&lines.join("\n"));
    }
    Ok(0)
}
