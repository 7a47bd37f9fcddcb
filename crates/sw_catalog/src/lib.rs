//! The procedural asset catalog: a parametric generator per object category.
//!
//! Each [`Category`] declares named parameters with realistic defaults and allowed
//! ranges, its placement kind, whether it is a free item or a fixture, and the words
//! people use for it. [`generate`] turns an [`AssetRequest`] into an [`Asset`]:
//! deterministic in (parameters, seed), with seeded variation of proportions, colours
//! and sub-parts, and collision made of primitives so that things fit under tables and
//! onto every shelf level.

mod categories;
mod kinds;
mod params;
mod proxy;

use sw_geom::{Asset, AssetBuilder, MassModel, Rng};

pub use kinds::{Kind, KindPrior};
pub use params::{ParamDef, Params};
pub use proxy::proxy_asset;
pub use sw_geom::PlacementKind;

/// One kind of object the catalog can make.
#[derive(Debug)]
pub struct Category {
    /// Registry name, snake_case: `pallet_rack`.
    pub name: &'static str,
    /// What people call it: `pallet rack`.
    pub display: &'static str,
    /// Other phrases for it, singular, lowercase ("storage rack", "racking").
    pub synonyms: &'static [&'static str],
    /// Domains and traits: `warehouse`, `storage`, `tall`, `electrical`, `tabletop` …
    pub tags: &'static [&'static str],
    /// One line saying what it is, for matching nouns the catalog lacks by meaning.
    pub description: &'static str,
    /// What it is a kind of (hypernyms, singular, lowercase: a toaster is a "kitchen
    /// appliance" and an "appliance"). A noun the catalog lacks maps to this category
    /// only when the noun's own head is one of these or one of its names' heads.
    pub is_a: &'static [&'static str],
    /// Its coarse class, with the size prior of a proxy of that class.
    pub kind: Kind,
    pub placement: PlacementKind,
    /// Every category has `width`, `depth` and `height` (its overall box) first.
    pub params: &'static [ParamDef],
    /// A free item (true) or a static fixture (false).
    pub movable: bool,
    /// When true, each instance in a group gets its own variation (boxes, plants);
    /// otherwise a group shares one look (a row of identical racks).
    pub vary_per_instance: bool,
    /// Builds the geometry from resolved parameters. Returns the mass of a free item.
    pub build: fn(&Params, &mut Rng, &mut AssetBuilder) -> f64,
}

impl Category {
    pub fn param(&self, name: &str) -> Option<&ParamDef> {
        self.params.iter().find(|p| p.name == name)
    }

    pub fn has_tag(&self, tag: &str) -> bool {
        self.tags.contains(&tag)
    }

    /// The default overall size (width, depth, height), m.
    pub fn default_size(&self) -> [f64; 3] {
        ["width", "depth", "height"].map(|n| self.param(n).map_or(0.5, |p| p.default))
    }

    /// Whether an object of this category can be of a stated size (m, along its width,
    /// depth and height; any may be unstated): every stated side within [`SIZE_SLACK`]
    /// times the range of its parameter. A size a little out of range is made clamped (and
    /// noted); one far out of it names another thing by the same word — a flat washer 20 mm
    /// across is no washing machine.
    pub fn admits_size(&self, stated: [Option<f64>; 3]) -> bool {
        ["width", "depth", "height"].iter().zip(stated).all(|(name, side)| match (self.param(name), side) {
            (Some(p), Some(v)) => (p.min / SIZE_SLACK..=p.max * SIZE_SLACK).contains(&v),
            _ => true,
        })
    }
}

/// How far out of a category's size range a stated size may be and still be that thing.
pub const SIZE_SLACK: f64 = 3.0;

/// What to make.
#[derive(Debug, Clone, Default)]
pub struct AssetRequest {
    pub category: String,
    pub seed: u64,
    /// Multipliers of the default width, depth and height (from size words).
    pub scale: Option<[f64; 3]>,
    /// Explicit parameter values, by name (e.g. `height` from "a 2 m tall shelf").
    pub overrides: Vec<(String, f64)>,
    /// Colour of the recolourable material ("a red cabinet").
    pub color: Option<[f32; 4]>,
}

impl AssetRequest {
    pub fn new(category: &str, seed: u64) -> Self {
        Self { category: category.to_string(), seed, ..Self::default() }
    }
}

#[derive(Debug, thiserror::Error, PartialEq)]
pub enum CatalogError {
    #[error("unknown asset category '{0}' (see `scenewright assets list`)")]
    UnknownCategory(String),
    #[error("{category}: unknown parameter '{param}' (known: {known})")]
    UnknownParam { category: String, param: String, known: String },
    #[error("{category}: parameter '{param}' must be a finite number, got {value}")]
    NotFinite { category: String, param: String, value: f64 },
    #[error("{category}: size scale {scale:?} must be three finite numbers above zero")]
    BadScale { category: String, scale: [f64; 3] },
}

/// Every category, in a stable order.
pub fn categories() -> &'static [Category] {
    categories::ALL
}

/// The category with this registry name.
pub fn find(name: &str) -> Option<&'static Category> {
    categories().iter().find(|c| c.name == name)
}

/// Builds an asset. Out-of-range parameters (zero and negative sizes included) are
/// clamped and noted in `Asset::notes`; unknown categories and parameters, non-finite
/// values and a scale that is not three positive numbers are errors.
pub fn generate(req: &AssetRequest) -> Result<Asset, CatalogError> {
    let cat = find(&req.category).ok_or_else(|| CatalogError::UnknownCategory(req.category.clone()))?;
    let mut rng = Rng::new(req.seed);
    let (params, notes) = Params::resolve(cat, req, &mut rng)?;
    let mut b = AssetBuilder::new(cat.name, req.seed);
    for n in notes {
        b.note(n);
    }
    b.params(params.values().to_vec());
    let mass = (cat.build)(&params, &mut rng, &mut b);
    let mut asset = b.build(cat.placement, if cat.movable { MassModel::Free { mass } } else { MassModel::Static });
    if let MassModel::Free { mass } = asset.mass {
        asset.mass = MassModel::Free { mass: mass.max(inertia_floor_mass(&asset)) };
    }
    if let Some(rgba) = req.color {
        if rgba.iter().all(|c| c.is_finite()) {
            let rgba = rgba.map(|c| c.clamp(0.0, 1.0));
            for m in asset.materials.iter_mut().filter(|m| m.recolorable) {
                m.rgba = rgba;
            }
        } else {
            asset.notes.push(format!("{}: colour {rgba:?} is not a colour; kept its own", cat.display));
        }
    }
    Ok(asset)
}

/// Smallest principal inertia a free body may have, kg·m². MJCF numbers are written with
/// 6 decimals, and the inertia of a free body comes from its collision box and mass: a
/// thin pen's 1e-7 would be written as 0, which MuJoCo refuses.
const MIN_INERTIA: f64 = 1.2e-6;

/// The mass below which the smallest principal inertia of the root link's collision box
/// would fall under [`MIN_INERTIA`].
fn inertia_floor_mass(a: &Asset) -> f64 {
    let Some(root) = a.links.first() else {
        return 0.0;
    };
    let b = root.collisions.iter().fold(sw_geom::Aabb::EMPTY, |acc, c| acc.union(&c.aabb()));
    if b.is_empty() {
        return 0.0;
    }
    let s = b.size();
    let pairs = [s[1] * s[1] + s[2] * s[2], s[0] * s[0] + s[2] * s[2], s[0] * s[0] + s[1] * s[1]];
    let least = pairs.iter().copied().fold(f64::INFINITY, f64::min);
    if least > 0.0 { MIN_INERTIA * 12.0 / least } else { 0.0 }
}
