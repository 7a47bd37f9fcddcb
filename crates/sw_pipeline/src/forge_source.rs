//! The asset forge as L2's source: catalog categories come from the catalog; an object
//! the catalog does not have (a labelled proxy in the plan) is looked up by meaning in
//! the asset library, else made by the generation loop (a model writes CadQuery, the
//! sandboxed runner runs it, the validator checks it against the proxy's size, failures
//! go back to the model), stored and indexed; after K failed attempts the group keeps
//! its labelled proxy and the report says why.

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

use sw_forge::generate::{CodeWriter, ForgeOutcome, LoopConfig, PartRequest, forge};
use sw_forge::library::AssetLibrary;
use sw_forge::runner::CadRunner;
use sw_geom::{Asset, PlacementKind};
use sw_plan::ObjectPlan;

use crate::asset_source::{AssetSource, CatalogSource, GroupAssets, asset_key, forge_warning};

/// L2 with generated assets.
pub struct ForgeSource {
    runner: CadRunner,
    writer: Arc<dyn CodeWriter>,
    config: LoopConfig,
    made: Mutex<BTreeMap<String, Asset>>,
    library: Option<Arc<AssetLibrary>>,
}

impl std::fmt::Debug for ForgeSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ForgeSource").field("writer", &self.writer.name()).finish_non_exhaustive()
    }
}

impl ForgeSource {
    pub fn new(runner: CadRunner, writer: Arc<dyn CodeWriter>, config: LoopConfig) -> Self {
        Self { runner, writer, config, made: Mutex::new(BTreeMap::new()), library: None }
    }

    /// Reuses stored assets by meaning and stores every part made.
    pub fn with_library(mut self, library: Arc<AssetLibrary>) -> Self {
        self.library = Some(library);
        self
    }

    /// A stored asset that serves this label at this size (metres), fitted to the size.
    fn reuse(&self, label: &str, size_m: [f64; 3], movable: bool) -> Option<(Asset, String)> {
        let lib = self.library.as_ref()?;
        let found = lib.lookup(label, Some(size_m)).ok()??;
        let bytes = lib.store().mesh(&found.hit.id).ok()?;
        let mut mesh = sw_geom::read_stl(bytes.as_slice()).ok()?;
        let mut mass = found.record.extra.get("mass_kg").and_then(serde_json::Value::as_f64).filter(|_| movable);
        let mut how = String::new();
        if let Some(fit) = &found.fit {
            mesh = sw_forge::reuse::apply_fit(&mesh, fit);
            // Mass goes with volume.
            mass = mass.map(|m| m * fit.scale.iter().product::<f64>());
            how = format!(", scaled ×{:.2}{}", fit.overall, if fit.quarter_turn { ", turned 90°" } else { "" });
        }
        let placement = if movable { PlacementKind::OnSurface } else { PlacementKind::Floor };
        let a =
            sw_forge::collision::part_asset(&format!("generated_{}", label.replace(' ', "_")), &mesh, mass, placement);
        Some((a, format!("{}\" ({:.2}{how})", found.hit.label, found.hit.score)))
    }

    fn cached(&self, key: &str) -> Option<Asset> {
        self.made.lock().ok().and_then(|m| m.get(key).cloned())
    }
}

impl AssetSource for ForgeSource {
    fn name(&self) -> &str {
        "forge"
    }

    fn is_cached(&self, group: &ObjectPlan) -> bool {
        group.proxy.is_none() || self.cached(&asset_key(group)).is_some()
    }

    fn make(&self, group: &ObjectPlan, seed: u64) -> GroupAssets {
        let mut out = CatalogSource.make(group, seed);
        let Some(proxy) = &group.proxy else { return out };
        let key = asset_key(group);
        let size_m = [proxy.size.width, proxy.size.depth, proxy.size.height];
        let cached = self.cached(&key);
        let reused = if cached.is_none() { self.reuse(&proxy.label, size_m, proxy.movable) } else { None };
        let asset = match (cached, reused) {
            (Some(a), _) => a,
            (None, Some((a, what))) => {
                if let Ok(mut m) = self.made.lock() {
                    m.insert(key, a.clone());
                }
                out.warnings
                    .push(forge_warning("asset_reused", format!("{}: reused the stored asset \"{what}", group.phrase)));
                a
            }
            (None, None) => {
                out.cached = false;
                let request = PartRequest { description: proxy.label.clone(), size_m: Some(size_m) };
                let outcome = forge(&self.runner, self.writer.as_ref(), &request, self.config);
                out.llm_calls.extend(self.writer.take_calls());
                match outcome {
                    ForgeOutcome::Made(part) => {
                        let placement = if proxy.movable { PlacementKind::OnSurface } else { PlacementKind::Floor };
                        // A movable item gets the density of a plastic part (500 kg/m³).
                        let mass = proxy.movable.then(|| (part.report.volume * 1e-9 * 500.0).max(0.05));
                        let category = format!("generated_{}", proxy.label.replace(' ', "_"));
                        let a = part.asset(&category, mass, placement);
                        if let Some(lib) = &self.library {
                            let (stl, record) =
                                part.stored(&proxy.label, &group.phrase, serde_json::json!({ "mass_kg": mass }));
                            if let Err(e) = lib.add(&stl, record) {
                                out.warnings.push(forge_warning(
                                    "asset_not_stored",
                                    format!("{}: not stored in the asset library ({e})", group.phrase),
                                ));
                            }
                        }
                        if let Ok(mut m) = self.made.lock() {
                            m.insert(key, a.clone());
                        }
                        out.warnings.push(forge_warning(
                            "asset_generated",
                            format!(
                                "{}: generated by {} in {} attempt(s); collides as {} convex piece(s)",
                                group.phrase,
                                part.writer,
                                part.attempts.len(),
                                a.links.first().map_or(0, |l| l.convex.len())
                            ),
                        ));
                        a
                    }
                    ForgeOutcome::Failed { attempts, writer } => {
                        let kinds: Vec<&str> =
                            attempts.iter().filter_map(|a| a.failure.as_ref().map(|f| f.kind.name())).collect();
                        out.warnings.push(forge_warning(
                            "asset_generation_failed",
                            format!(
                                "{}: {writer} could not make it ({}); kept the labelled proxy",
                                group.phrase,
                                kinds.join(", ")
                            ),
                        ));
                        return out;
                    }
                }
            }
        };
        for inst in out.instances.iter_mut().flatten() {
            inst.asset = asset.clone();
        }
        out
    }
}
