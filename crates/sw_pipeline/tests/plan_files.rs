#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Opt-in (`--ignored`): generates a package from every plan file in `PLAN_FILES`
//! (`<stem>.json`) into `PLAN_OUT/<stem>-<seed>` for seeds 1..=`PLAN_SEEDS`; a plan that
//! cannot be generated leaves `error.txt` there instead. `bench/relations/oracle.py`
//! drives it to measure the solver on a corpus apart from the reader.

use std::path::PathBuf;

use sw_pipeline::{Options, generate_from_plan};
use sw_plan::ScenePlan;

#[test]
#[ignore = "driven by bench/relations/oracle.py"]
fn generate_every_plan_file() {
    let (Some(dir), Some(out)) = (std::env::var_os("PLAN_FILES"), std::env::var_os("PLAN_OUT")) else {
        panic!("set PLAN_FILES and PLAN_OUT");
    };
    let seeds: u64 = std::env::var("PLAN_SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let out = PathBuf::from(out);
    std::fs::create_dir_all(&out).unwrap();
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    for f in files.iter().filter(|f| f.extension().is_some_and(|e| e == "json")) {
        let stem = f.file_stem().unwrap().to_string_lossy().to_string();
        for seed in 1..=seeds {
            let pkg = out.join(format!("{stem}-{seed}"));
            let _ = std::fs::remove_dir_all(&pkg);
            let plan: Result<ScenePlan, String> = std::fs::read_to_string(f)
                .map_err(|e| e.to_string())
                .and_then(|t| serde_json::from_str(&t).map_err(|e| e.to_string()));
            let res = plan.and_then(|p| {
                generate_from_plan(p, &pkg, &Options { seed, ..Options::default() }, &mut |_| {})
                    .map_err(|e| e.to_string())
            });
            if let Err(e) = res {
                std::fs::create_dir_all(&pkg).unwrap();
                std::fs::write(pkg.join("error.txt"), e).unwrap();
            }
        }
    }
}
