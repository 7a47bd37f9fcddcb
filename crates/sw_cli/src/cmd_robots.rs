//! `robots list|show`.

use clap::Subcommand;
use serde::Serialize;

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Debug, Subcommand)]
pub(crate) enum RobotsCommand {
    /// Every registered robot.
    List {
        #[arg(long)]
        json: bool,
    },
    /// One robot's facts, or its MJCF with `--mjcf`.
    Show {
        name: String,
        #[arg(long)]
        mjcf: bool,
        #[arg(long)]
        json: bool,
    },
}

#[derive(Serialize)]
struct RobotInfo {
    name: &'static str,
    display: &'static str,
    kind: &'static str,
    source: &'static str,
    reach_m: f64,
    footprint_radius_m: f64,
    height_m: f64,
}

fn info(r: &sw_robots::RobotDef) -> RobotInfo {
    RobotInfo {
        name: r.name,
        display: r.display,
        kind: match r.kind {
            sw_robots::RobotKind::Arm => "arm",
            sw_robots::RobotKind::MobileBase => "mobile_base",
        },
        source: r.source,
        reach_m: r.reach,
        footprint_radius_m: r.footprint_radius,
        height_m: r.height,
    }
}

pub(crate) fn run(c: RobotsCommand) -> Result<u8, Failure> {
    match c {
        RobotsCommand::List { json } => {
            let all: Vec<RobotInfo> = sw_robots::registry().iter().map(|r| info(r)).collect();
            if json {
                print_json(&all);
            } else {
                for r in all {
                    print(&format!("{:<12} {:<12} {}", r.name, r.kind, r.display));
                }
            }
            Ok(0)
        }
        RobotsCommand::Show { name, mjcf, json } => {
            let r = sw_robots::find(&name.to_lowercase()).ok_or_else(|| {
                let known: Vec<&str> = sw_robots::registry().iter().map(|r| r.name).collect();
                Failure::input(format!("unknown robot '{name}' (known: {})", known.join(", ")))
            })?;
            if mjcf {
                print(r.mjcf);
            } else if json {
                print_json(&info(r));
            } else {
                let i = info(r);
                print(&format!(
                    "{}\n  {}\n  kind {} · reach {} m · footprint radius {} m · height {} m\n  {}",
                    i.name, i.display, i.kind, i.reach_m, i.footprint_radius_m, i.height_m, i.source
                ));
            }
            Ok(0)
        }
    }
}
