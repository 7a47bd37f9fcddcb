#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The template synthesizer end to end: its code runs in the sandboxed runner and the
//! mesh has the analytic size (1 %), volume (2 %) and through-holes — over one prompt of
//! each template, in mm, cm and inches.
//!
//! Needs `scripts/setup.sh --tests` (the CadQuery venv); fails, never skips, without it.

use std::sync::OnceLock;
use std::time::Duration;

use sw_forge::part::{GenerateError, generate_offline, write_part};
use sw_forge::runner::{CadRunner, RunnerConfig};

fn runner() -> &'static CadRunner {
    static R: OnceLock<CadRunner> = OnceLock::new();
    R.get_or_init(|| {
        CadRunner::start(RunnerConfig { workers: 2, timeout: Duration::from_secs(20), ..RunnerConfig::default() })
            .unwrap_or_else(|e| panic!("the CAD runner must start (run scripts/setup.sh --tests): {e}"))
    })
}

const PROMPTS: &[(&str, &str)] = &[
    ("washer", "A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm"),
    ("box", "A rectangular block 50mm long, 30mm wide, and 20mm tall."),
    ("box", "A rounded rectangular block 50mm long, 25mm wide, and 15mm tall, with 3mm fillets on all vertical edges."),
    ("box", "A rectangular block 70mm by 40mm by 25mm with 5mm fillets on all edges."),
    ("cube", "A chamfered cube with 30mm sides and 2mm chamfers on all edges."),
    ("cylinder", "A cylinder 2 cm in diameter and 1.5 inches tall"),
    ("cylinder", "A coin-shaped disc: 38mm diameter, 3mm thick, with 0.5mm fillets on both circular edges."),
    ("cylinder", "A cylinder with a 12mm diameter, 100mm tall, with 1mm chamfers on both circular edges."),
    ("sphere", "A solid sphere with a radius of 15mm."),
    ("hemisphere", "A solid upper hemisphere with a diameter of 50mm."),
    ("cone", "A cone with a base diameter of 30mm and a height of 45mm."),
    (
        "frustum",
        "A truncated cone (frustum) with a base diameter of 40mm, a top diameter of 20mm, and a height of 30mm.",
    ),
    ("pyramid", "A pyramid with a square base of 40mm sides and a height of 50mm."),
    ("polygon_prism", "A hexagonal prism with a circumscribed circle diameter of 20mm and a height of 35mm."),
    ("stadium", "A stadium (oblong) shape 60mm long (X), 20mm wide (Y), and 8mm thick (Z)."),
    (
        "elliptic_cylinder",
        "A solid elliptical cylinder with a major axis of 40mm, minor axis of 20mm, and a height of 25mm.",
    ),
    ("capsule", "A capsule shape: a cylinder 30mm in diameter and 50mm tall, with hemispherical caps on both ends."),
    ("tube", "A hollow tube with an outer diameter of 30mm, inner diameter of 24mm, and length of 80mm."),
    (
        "plate_with_holes",
        "A mounting plate 80mm (X) by 60mm (Y) by 5mm thick (Z) with four M4 holes 8mm inset from each corner",
    ),
    ("plate_with_holes", "A mounting plate 120mm x 80mm x 6mm with four 8mm holes"),
    (
        "plate_with_holes",
        "A plate with counterbored holes: 60mm (X) by 40mm (Y) by 8mm thick (Z). Four counterbored holes at the corners, each positioned 8mm inset from the nearest edges. Each hole is 5.5mm diameter through the full thickness, with a 10mm diameter counterbore 3mm deep on the top face (+Z).",
    ),
    (
        "flange",
        "A round flange plate: a solid disc 60mm in diameter and 8mm thick. A 20mm diameter center bore goes through the full thickness. Six 5.5mm diameter bolt holes on a 45mm pitch circle diameter.",
    ),
    (
        "square_washer",
        "A square flat washer: a square plate 24mm x 24mm (X x Y), 3mm thick (Z), with a 10.5mm diameter central through-hole.",
    ),
    (
        "hex_nut",
        "A hexagonal nut: a regular hexagonal prism with a 19.6mm circumscribed circle diameter, 8mm tall, with a 10mm diameter through-hole.",
    ),
    (
        "i_beam",
        "A structural I-beam: 100mm long along the X axis, 40mm total height along Z, 20mm flange width along Y. Both flanges are 3mm thick and the vertical web is 2mm thick.",
    ),
    ("channel", "A U-channel: 80mm long (X), 40mm wide (Y), 30mm tall (Z), wall thickness 3mm, base thickness 3mm."),
    (
        "l_bracket",
        "An L-bracket: vertical wall 50mm tall (Z), 40mm wide (X), 3mm thick (Y). Horizontal base 40mm deep (Y), 40mm wide (X), 3mm thick (Z).",
    ),
    (
        "rect_tube",
        "A hollow rectangular tube: 80mm long (X), outer cross-section 30mm wide (Y) by 40mm tall (Z), wall thickness 2mm on all four sides.",
    ),
    (
        "stacked_shaft",
        "A flanged bushing: the flange is 30mm outer diameter, 3mm thick (Z=0 to Z=3). The body is 20mm outer diameter, 30mm long (Z=3 to Z=33). A 10mm diameter bore runs through the entire length.",
    ),
    (
        "gear",
        "A simplified spur gear with 16 triangular teeth: tip circle of 40mm diameter and root circle of 32mm diameter, a 10mm diameter center bore, 8mm thick.",
    ),
];

#[test]
fn every_template_runs_and_measures_what_it_promised() {
    let r = runner();
    let mut failures = Vec::new();
    for (template, prompt) in PROMPTS {
        match generate_offline(r, prompt) {
            Ok(part) => {
                assert_eq!(part.synthesis.template, *template, "{prompt}");
                assert!(part.report.watertight, "{prompt}");
                let size_err = part.report.size_error.expect("a size was checked");
                assert!(size_err <= 0.01 + 1e-9 || size_err * part.synthesis.size[0] < 0.03, "{prompt}: {size_err}");
                if let Some(v) = part.synthesis.volume {
                    let rel = (part.report.volume - v).abs() / v;
                    assert!(rel <= 0.02, "{prompt}: mesh volume {} vs {v}", part.report.volume);
                    // The CAD kernel's exact volume is closer still.
                    if let Some(b) = part.brep_volume {
                        assert!((b - v).abs() / v <= 0.005, "{prompt}: B-rep volume {b} vs analytic {v}");
                    }
                }
            }
            Err(e) => failures.push(format!("{template}: {prompt}: {e}")),
        }
    }
    assert!(failures.is_empty(), "{} of {} failed:\n{}", failures.len(), PROMPTS.len(), failures.join("\n"));
}

#[test]
fn a_part_is_written_as_stl_in_metres_with_metadata_and_preview() {
    let part = generate_offline(runner(), PROMPTS[0].1).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let files = write_part(dir.path(), &part, true).unwrap();
    let mesh = sw_geom::read_stl(std::fs::File::open(&files.mesh).unwrap()).unwrap();
    let size = mesh.bounds().size();
    assert!((size[0] - 0.020).abs() < 2e-4 && (size[2] - 0.002).abs() < 2e-5, "{size:?}");
    let meta: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&files.metadata).unwrap()).unwrap();
    assert_eq!(meta["template"], "washer");
    assert_eq!(meta["through_holes"], 1);
    let png = std::fs::read(files.preview.unwrap()).unwrap();
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn a_wrong_part_fails_validation_with_its_kind() {
    // Code that makes a different size than the synthesizer promised is caught: run the
    // washer's code with a doubled thickness through the same validator.
    let s = sw_forge::synth::synthesize(PROMPTS[0].1).unwrap();
    let code = s.code.replace("(10, 2), (5.25, 2)", "(10, 4), (5.25, 4)");
    assert_ne!(code, s.code, "the test edits the profile: {}", s.code);
    let run = runner().run(&sw_forge::runner::CadJob::cadquery(code)).unwrap();
    let err = sw_forge::validate::validate(&run.mesh, &s.target()).unwrap_err();
    assert_eq!(err.kind, sw_forge::failure::FailureKind::ScaleMismatch);
}

#[test]
fn bad_prompts_are_synth_errors() {
    for p in ["", "a teapot", "a washer", "a washer 2mm thick"] {
        assert!(matches!(generate_offline(runner(), p), Err(GenerateError::Synth(_))), "{p}");
    }
}
