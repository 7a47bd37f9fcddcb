//! The offline template synthesizer: writes CadQuery code for dimensioned mechanical
//! prompts ("A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm")
//! with no LLM, and says what the result must measure — its bounding box, its volume and
//! its number of through-holes, computed analytically from the same dimensions — so the
//! validator can check the executed code against the request.
//!
//! [`measure`] reads the lengths (mm, cm, m, inches, "M6"), what each measures and the
//! words that qualify it; [`templates`] picks the part by its nouns and builds it as a
//! [`body::Body`] of disjoint primitives, whose volume and bounds are exact.

pub mod body;
pub mod measure;
pub mod templates;

use serde::{Deserialize, Serialize};

use crate::validate::{Orientation, Target};

/// What the synthesizer wrote for a prompt.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Synthesis {
    /// The template used (`washer`, `plate_with_holes` …).
    pub template: String,
    /// CadQuery code that assigns the part (in mm) to `result`.
    pub code: String,
    /// Bounding box of the part, mm, per axis as built.
    pub size: [f64; 3],
    /// Its minimum corner, mm.
    pub min: [f64; 3],
    /// Its volume, mm³, when known exactly.
    pub volume: Option<f64>,
    /// Its through-holes, when known.
    pub genus: Option<u32>,
}

impl Synthesis {
    /// What the validator checks the executed code's mesh against: the bounding box per
    /// axis within 1 % (plus 0.02 mm for tessellation), the volume within 2 %.
    pub fn target(&self) -> Target {
        Target {
            size: Some(self.size),
            orientation: Orientation::Strict,
            size_tolerance: 0.01,
            size_slack: 0.02,
            volume: self.volume,
            volume_tolerance: 0.02,
            genus: self.genus,
            ..Target::default()
        }
    }
}

/// Why no code was written.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SynthError {
    #[error("the prompt is empty")]
    Empty,
    #[error("the prompt gives no dimensions (say e.g. \"50mm long, 30mm wide and 20mm tall\")")]
    NoDimensions,
    #[error("{template}: {message}")]
    Template { template: String, message: String },
    #[error("{0}")]
    Unknown(String),
}

/// The largest part the synthesizer writes (10 m), and the smallest feature (1 µm).
const MAX_MM: f64 = 10_000.0;
const MIN_MM: f64 = 0.001;

/// Writes CadQuery code for a dimensioned prompt.
pub fn synthesize(prompt: &str) -> Result<Synthesis, SynthError> {
    let prompt = prompt.trim();
    if prompt.is_empty() {
        return Err(SynthError::Empty);
    }
    let reading = measure::read(prompt);
    if reading.dims.is_empty() {
        return Err(SynthError::NoDimensions);
    }
    if let Some(d) = reading
        .dims
        .iter()
        .find(|d| if d.coord.is_some() { d.mm.abs() > MAX_MM } else { !(MIN_MM..=MAX_MM).contains(&d.mm) })
    {
        return Err(SynthError::Unknown(format!(
            "a length of {} mm is outside what the synthesizer makes ({MIN_MM} mm to {MAX_MM} mm)",
            d.mm
        )));
    }
    let built = templates::build(&reading).map_err(|(template, message)| {
        if template == "none" {
            SynthError::Unknown(message)
        } else {
            SynthError::Template { template: template.to_string(), message }
        }
    })?;
    let b = built.body.bounds();
    let size = built.body.size();
    if size.iter().any(|s| !s.is_finite() || *s <= 0.0) {
        return Err(SynthError::Template { template: built.template.into(), message: "the part has no extent".into() });
    }
    let title = prompt.lines().next().unwrap_or(prompt).chars().take(200).collect::<String>();
    Ok(Synthesis {
        template: built.template.to_string(),
        code: built.body.code(&title),
        size,
        min: b[0],
        volume: built.body.volume(),
        genus: built.genus,
    })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-6 * b.abs().max(1.0)
    }

    #[test]
    fn washer_from_the_issue() {
        let s = synthesize("A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm").unwrap();
        assert_eq!(s.template, "washer");
        assert!(close(s.size[0], 20.0) && close(s.size[1], 20.0) && close(s.size[2], 2.0), "{:?}", s.size);
        assert!(close(s.volume.unwrap(), PI * (100.0 - 5.25 * 5.25) * 2.0));
        assert_eq!(s.genus, Some(1));
        assert!(s.code.contains("revolve"));
    }

    #[test]
    fn blocks_cylinders_and_spheres() {
        let s = synthesize("A rectangular block 50mm long, 30mm wide, and 20mm tall.").unwrap();
        assert_eq!(s.size, [50.0, 30.0, 20.0]);
        assert!(close(s.volume.unwrap(), 30_000.0));
        let s = synthesize("A cylinder with a diameter of 25mm and a height of 40mm.").unwrap();
        assert!(close(s.volume.unwrap(), PI * 12.5 * 12.5 * 40.0));
        let s = synthesize("A solid sphere with a radius of 15mm.").unwrap();
        assert_eq!(s.size, [30.0, 30.0, 30.0]);
        let s = synthesize("a 2 inch cube").unwrap_or_else(|e| panic!("{e}"));
        assert!(close(s.size[0], 50.8));
    }

    #[test]
    fn plate_with_inset_holes() {
        let s = synthesize(
            "A flat mounting plate: 80mm (X) by 60mm (Y) by 5mm thick (Z), centered at the origin. Four M4 clearance holes (4.2mm diameter) drilled through the plate, positioned 8mm inset from each corner.",
        )
        .unwrap();
        assert_eq!(s.template, "plate_with_holes");
        assert_eq!(s.genus, Some(4));
        assert!(close(s.volume.unwrap(), 80.0 * 60.0 * 5.0 - 4.0 * PI * 2.1 * 2.1 * 5.0));
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        assert_eq!(synthesize("   "), Err(SynthError::Empty));
        assert_eq!(synthesize("a washer"), Err(SynthError::NoDimensions));
        assert!(matches!(synthesize("a washer 10mm thick"), Err(SynthError::Template { .. })));
        assert!(matches!(
            synthesize("a washer: outer diameter 10mm, inner diameter 12mm, 1mm thick"),
            Err(SynthError::Template { .. })
        ));
        assert!(synthesize("a spaceship 20mm long").is_err());
        assert!(synthesize("a block 1e400mm long").is_err());
        assert!(synthesize("a cube with 99999999mm sides").is_err());
    }
}
