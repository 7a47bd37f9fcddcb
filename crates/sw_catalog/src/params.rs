//! Named parameters: defaults, ranges, seeded variation, size words and clamping.

use sw_geom::Rng;

use crate::{AssetRequest, CatalogError, Category};

/// One parameter of a category.
#[derive(Debug, Clone, Copy)]
pub struct ParamDef {
    pub name: &'static str,
    pub default: f64,
    pub min: f64,
    pub max: f64,
    /// Relative seeded variation: the default is drawn from `default × (1 ± vary)`.
    pub vary: f64,
    pub doc: &'static str,
}

impl ParamDef {
    pub const fn new(name: &'static str, default: f64, min: f64, max: f64, vary: f64, doc: &'static str) -> Self {
        Self { name, default, min, max, vary, doc }
    }
}

/// Resolved parameter values, in the category's declaration order.
#[derive(Debug, Clone)]
pub struct Params {
    values: Vec<(String, f64)>,
}

impl Params {
    /// The value of `name`; 0 for a name the category does not declare (a bug in the
    /// generator, caught by the catalog's tests).
    pub fn get(&self, name: &str) -> f64 {
        self.values.iter().find(|(n, _)| n == name).map_or(0.0, |(_, v)| *v)
    }

    /// An integer parameter (counts of shelves, drawers …), rounded.
    pub fn count(&self, name: &str) -> usize {
        self.get(name).round().max(0.0) as usize
    }

    pub fn values(&self) -> &[(String, f64)] {
        &self.values
    }

    /// Defaults, varied by the seed, scaled by size words, overridden by explicit values,
    /// then clamped into range. Returns the values and a note for each clamp.
    pub(crate) fn resolve(
        cat: &Category,
        req: &AssetRequest,
        rng: &mut Rng,
    ) -> Result<(Params, Vec<String>), CatalogError> {
        for (name, value) in &req.overrides {
            if cat.param(name).is_none() {
                let known: Vec<&str> = cat.params.iter().map(|p| p.name).collect();
                return Err(CatalogError::UnknownParam {
                    category: cat.name.into(),
                    param: name.clone(),
                    known: known.join(", "),
                });
            }
            if !value.is_finite() {
                return Err(CatalogError::NotFinite { category: cat.name.into(), param: name.clone(), value: *value });
            }
        }
        if let Some(scale) = req.scale
            && !scale.iter().all(|s| s.is_finite() && *s > 0.0)
        {
            return Err(CatalogError::BadScale { category: cat.name.into(), scale });
        }
        let mut notes = Vec::new();
        let mut values = Vec::with_capacity(cat.params.len());
        for def in cat.params {
            // Always draw, so that overriding one parameter does not shift the others.
            let jitter = rng.range(-1.0, 1.0);
            let mut v = def.default * (1.0 + def.vary * jitter);
            if let Some(scale) = req.scale {
                match def.name {
                    "width" => v *= scale[0],
                    "depth" => v *= scale[1],
                    "height" => v *= scale[2],
                    _ => {}
                }
            }
            if let Some((_, o)) = req.overrides.iter().find(|(n, _)| n == def.name) {
                v = *o;
            }
            let clamped = v.clamp(def.min, def.max);
            if (clamped - v).abs() > 1e-9 * v.abs().max(1.0) {
                notes.push(format!(
                    "{} {} {} is outside {}..{}; used {}",
                    cat.display,
                    def.name,
                    trim(v),
                    trim(def.min),
                    trim(def.max),
                    trim(clamped)
                ));
            }
            values.push((def.name.to_string(), clamped));
        }
        if cat.has_tag("round") || cat.has_tag("uniform") {
            one_size(cat, req, &mut values, &mut notes);
        }
        if cat.has_tag("handled") {
            body_beside_handle(cat, req, &mut values, &mut notes);
        }
        Ok((Params { values }, notes))
    }
}

/// A round thing has one diameter: `depth` follows `width`. A uniform thing (a cube, a
/// ball) has one size: `height` follows it too. The size comes from `width` unless only
/// another of them was given (or scaled) explicitly.
fn one_size(cat: &Category, req: &AssetRequest, values: &mut [(String, f64)], notes: &mut Vec<String>) {
    let uniform = cat.has_tag("uniform");
    let axes: &[&str] = if uniform { &["width", "depth", "height"] } else { &["width", "depth"] };
    let given = |n: &str| req.overrides.iter().any(|(o, _)| o == n);
    let index = |n: &str| values.iter().position(|(v, _)| v == n);
    let Some(idx) = axes.iter().map(|a| index(a)).collect::<Option<Vec<usize>>>() else {
        return;
    };
    // The axis whose scale moved furthest from 1, or the only one given.
    let scaled = req.scale.map(|s| (0..axes.len()).max_by(|&a, &b| (s[a] - 1.0).abs().total_cmp(&(s[b] - 1.0).abs())));
    let source = if given("width") {
        0
    } else if let Some(k) = axes.iter().position(|a| given(a)) {
        k
    } else {
        scaled.flatten().unwrap_or(0)
    };
    let v = values[idx[source]].1;
    let conflict = axes.iter().enumerate().any(|(k, a)| k != source && given(a) && (values[idx[k]].1 - v).abs() > 1e-9);
    if conflict {
        let what = if uniform { "its sizes follow" } else { "its depth follows" };
        notes.push(format!("{} has one size: {what} its {} ({})", cat.display, axes[source], trim(v)));
    }
    for &i in &idx {
        values[i].1 = v;
    }
}

/// Room a side handle takes beside a round body, m (a mug's loop: 2.5 cm of grip and
/// its bars).
pub(crate) const HANDLE_REACH: f64 = 0.03;

/// A thing with a handle on its side (a mug) is as wide as its body and its handle:
/// `width` holds both, so `depth` (the body) is at most `width - HANDLE_REACH`. When the
/// width is the smaller of the two given, the body shrinks to fit it (noted only when the
/// body size was asked for).
fn body_beside_handle(cat: &Category, req: &AssetRequest, values: &mut [(String, f64)], notes: &mut Vec<String>) {
    let get = |values: &[(String, f64)], n: &str| values.iter().position(|(v, _)| v == n);
    let (Some(wi), Some(di)) = (get(values, "width"), get(values, "depth")) else {
        return;
    };
    let (w, d) = (values[wi].1, values[di].1);
    let body = w - HANDLE_REACH;
    if d <= body {
        return;
    }
    let floor = cat.param("depth").map_or(0.0, |p| p.min);
    if body >= floor {
        if req.overrides.iter().any(|(n, _)| n == "depth") {
            notes.push(format!(
                "{}: its body {} does not fit beside the handle in {}; used {}",
                cat.display,
                trim(d),
                trim(w),
                trim(body)
            ));
        }
        values[di].1 = body;
    } else {
        // Too narrow for the smallest body: widen to hold it.
        values[di].1 = floor;
        values[wi].1 = floor + HANDLE_REACH;
        notes.push(format!(
            "{} width {} cannot hold a body and a handle; used {}",
            cat.display,
            trim(w),
            trim(floor + HANDLE_REACH)
        ));
    }
}

fn trim(v: f64) -> String {
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}
