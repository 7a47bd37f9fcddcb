//! The offline synthesizer: a feature language for dimensioned parts, read from English.
//! A part is base solids ([`solid`]: profiles extruded along an axis, cones, spheres,
//! tori, revolved profiles, lofts, pyramids, pipes bent along arcs) with features placed on
//! faces and axes (holes, counterbores, countersinks, slots, keyways, grooves, pockets),
//! edge treatments and shells, copied in patterns (points, corners, pitch circles, grids,
//! rows, radial arms) and joined at stated coordinates ([`model`]). The reader ([`read`])
//! builds it from the prompt's words ([`text`], [`doc`], [`mention`], [`lexicon`]) and
//! accounts for every number and word: a prompt it cannot fully read is refused with the
//! exact words, never made into a different part.
//!
//! What the part must measure — its bounding box (on the axes no cut can trim), its volume
//! when every overlap is known, its through-holes when simple — comes from the same model
//! analytically, so the validator can check the executed code against it.

pub mod account;
pub mod contradict;
pub mod doc;
pub mod family;
pub mod lexicon;
pub mod mention;
pub mod model;
pub mod notation;
pub mod num;
pub mod profile;
pub mod read;
pub mod solid;
pub mod takeoff;
pub mod text;

use serde::{Deserialize, Serialize};

use crate::validate::{Orientation, Target};

/// What the synthesizer wrote for a prompt.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Synthesis {
    /// What made it: `features` (the feature language), or `freeform:<object>`.
    pub template: String,
    /// CadQuery code that assigns the part (in mm) to `result`.
    pub code: String,
    /// Bounding box of the part, mm, per axis as built.
    pub size: [f64; 3],
    /// Its minimum corner, mm.
    pub min: [f64; 3],
    /// Which extents are certain (no cut can have trimmed them).
    #[serde(default = "all_axes")]
    pub size_certain: [bool; 3],
    /// Its volume, mm³, when known exactly.
    pub volume: Option<f64>,
    /// Its through-holes, when known.
    pub genus: Option<u32>,
}

fn all_axes() -> [bool; 3] {
    [true; 3]
}

impl Synthesis {
    /// What the validator checks the executed code's mesh against: the certain extents
    /// within 1 % (plus 0.02 mm for tessellation), the volume within 2 %.
    pub fn target(&self) -> Target {
        Target {
            size: Some(self.size),
            orientation: Orientation::Strict,
            size_tolerance: 0.01,
            size_slack: 0.02,
            size_axes: self.size_certain,
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
    /// The words it could not honour, and why.
    #[error("could not read \"{phrase}\": {reason}")]
    Unread { phrase: String, reason: String },
}

/// The largest part the synthesizer writes (10 m), and the smallest length (1 µm).
const MAX_MM: f64 = 10_000.0;
const MIN_MM: f64 = 0.001;

/// Writes CadQuery code for a dimensioned prompt.
pub fn synthesize(prompt: &str) -> Result<Synthesis, SynthError> {
    let prompt = prompt.trim();
    if prompt.is_empty() {
        return Err(SynthError::Empty);
    }
    let d = doc::Doc::new(prompt);
    if d.dims.is_empty() && d.ranges.is_empty() && d.coords.is_empty() {
        return Err(SynthError::NoDimensions);
    }
    for (k, x) in d.dims.iter().enumerate() {
        if !x.mm.is_finite() || !(MIN_MM..=MAX_MM).contains(&x.mm) {
            let phrase = d.quote(x.tok, x.tok);
            let _ = k;
            return Err(SynthError::Unread {
                phrase,
                reason: format!(
                    "a length of {} mm is outside what the synthesizer makes ({MIN_MM} mm to {MAX_MM} mm)",
                    x.mm
                ),
            });
        }
    }
    if let Some(c) = d.coords.iter().find(|c| !c.v.is_finite() || c.v.abs() > MAX_MM) {
        return Err(SynthError::Unread {
            phrase: d.quote(c.tok, c.tok + 2),
            reason: "a coordinate outside 10 m".into(),
        });
    }
    // Words that contradict each other are refused with them, whatever the first reader
    // would make of them.
    let takeoff = takeoff::Takeoff::read(&d);
    takeoff.contradictions().map_err(|x| SynthError::Unread { phrase: x.phrase, reason: x.reason })?;
    let model = match read::read(&d) {
        Ok(m) => m,
        // A named part family reads what the feature language could not: its template's
        // parameters bound by role, checked against its own formulas.
        Err(r) => match family::read(&d) {
            Some(Ok((template, m))) => {
                takeoff.account(&m).map_err(|x| SynthError::Unread { phrase: x.phrase, reason: x.reason })?;
                return Ok(finish(prompt, template, &m));
            }
            // The feature language's words stay quoted; the family says what it lacks.
            Some(Err(f)) => {
                return Err(SynthError::Unread {
                    phrase: r.phrase,
                    reason: format!("{}; read as a part family (\"{}\"): {}", r.reason, f.phrase, f.reason),
                });
            }
            None => return Err(SynthError::Unread { phrase: r.phrase, reason: r.reason }),
        },
    };
    // The second reading: what the words alone say the part measures.
    takeoff.check(&model).map_err(|x| SynthError::Unread { phrase: x.phrase, reason: x.reason })?;
    takeoff.account(&model).map_err(|x| SynthError::Unread { phrase: x.phrase, reason: x.reason })?;
    // A named part family that reads every word the same sizes bound by their roles must
    // agree with the feature language; where they differ, one of them misread the words.
    if let Some(Ok((_, fm))) = family::read(&d) {
        let (a, b) = (family::sorted(model.size()), family::sorted(fm.size()));
        let agree = (0..3).all(|k| (a[k] - b[k]).abs() <= 0.005 * b[k].max(1.0))
            && match (model.volume(), fm.volume()) {
                (Some(x), Some(y)) => (x - y).abs() <= 0.005 * y.max(1.0),
                _ => true,
            };
        if !agree {
            return Err(SynthError::Unread {
                phrase: prompt.chars().take(120).collect(),
                reason: format!(
                    "the part's family reads these sizes as {:.3?} mm, the feature language as {:.3?} mm: they disagree",
                    b, a
                ),
            });
        }
    }
    Ok(finish(prompt, "features", &model))
}

/// The synthesis of a built model.
pub fn finish(prompt: &str, template: &str, model: &model::Model) -> Synthesis {
    let b = model.bounds();
    let title = prompt.lines().next().unwrap_or(prompt).chars().take(200).collect::<String>();
    Synthesis {
        template: template.to_string(),
        code: model.code(&title),
        size: model.size(),
        min: b[0],
        size_certain: model.extent_certain(),
        volume: model.volume(),
        genus: model.genus(),
    }
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
        assert!(close(s.size[0], 20.0) && close(s.size[1], 20.0) && close(s.size[2], 2.0), "{:?}", s.size);
        assert!(close(s.volume.unwrap(), PI * (100.0 - 5.25 * 5.25) * 2.0));
        assert_eq!(s.genus, Some(1));
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
    fn bad_input_is_an_error_naming_the_words() {
        assert_eq!(synthesize("   "), Err(SynthError::Empty));
        assert_eq!(synthesize("a washer"), Err(SynthError::NoDimensions));
        assert!(matches!(synthesize("a washer 10mm thick"), Err(SynthError::Unread { .. })));
        match synthesize("a block 20mm long, 10mm wide and 5mm tall with a dragon engraved on top") {
            Err(SynthError::Unread { phrase, .. }) => assert!(phrase.contains("dragon"), "{phrase}"),
            other => panic!("{other:?}"),
        }
        assert!(synthesize("a spaceship 20mm long").is_err());
        assert!(synthesize("a block 1e400mm long").is_err());
        assert!(synthesize("a cube with 99999999mm sides").is_err());
    }
}
