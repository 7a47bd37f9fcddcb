//! L2's interface: "make the assets of this object group". The offline catalog is one
//! source; the asset forge (a cache of generated assets, an LLM writing CAD code, a
//! sandboxed runner) is another, plugged in behind the same trait. The LLM path calls a
//! source from worker threads as soon as a group is known from the streamed plan.

use std::collections::BTreeSet;
use std::sync::Mutex;

use sw_geom::Asset;
use sw_llm::{ChatRequest, Client, LlmStage, Message};
use sw_plan::ObjectPlan;

/// One instance's asset, with the catalog tags and the label the layout uses.
#[derive(Debug, Clone)]
pub struct MadeAsset {
    pub asset: Asset,
    pub tags: Vec<String>,
    pub label: String,
}

/// The assets of one object group.
#[derive(Debug, Clone, Default)]
pub struct GroupAssets {
    /// One per instance (`count` of them): the asset, or why it could not be made (the
    /// pipeline then uses a labelled proxy and says so).
    pub instances: Vec<Result<MadeAsset, String>>,
    /// True when no slow work was needed (catalog, cache).
    pub cached: bool,
    /// Best-effort problems and what was done about them, for the report's warnings.
    pub warnings: Vec<sw_plan::Warning>,
    /// Language-model calls made for the group, for the report's telemetry.
    pub llm_calls: Vec<sw_plan::LlmCall>,
}

/// Makes the assets of object groups. Implementations must be callable from several
/// threads at once; `make` may be slow (seconds, when a model writes CAD code).
pub trait AssetSource: Send + Sync {
    /// A short name for reports ("catalog", "forge").
    fn name(&self) -> &str;
    /// True when the group's assets are at hand without slow work.
    fn is_cached(&self, group: &ObjectPlan) -> bool;
    /// Makes every instance of the group, deterministically in (group, seed).
    fn make(&self, group: &ObjectPlan, seed: u64) -> GroupAssets;
}

/// The procedural catalog and labelled proxies: exactly what the offline pipeline uses.
#[derive(Debug, Clone, Copy, Default)]
pub struct CatalogSource;

impl AssetSource for CatalogSource {
    fn name(&self) -> &str {
        "catalog"
    }

    fn is_cached(&self, _group: &ObjectPlan) -> bool {
        true
    }

    fn make(&self, group: &ObjectPlan, seed: u64) -> GroupAssets {
        let instances = (0..group.count)
            .map(|k| {
                crate::forge::make(group, k, seed)
                    .map(|(asset, tags, label)| MadeAsset { asset, tags, label })
                    .map_err(|e| e.to_string())
            })
            .collect();
        GroupAssets { instances, cached: true, warnings: Vec::new(), llm_calls: Vec::new() }
    }
}

/// What a group asks the asset forge for: its catalog category or proxy label, with
/// colour and size words (instances share one generated design).
pub fn asset_key(group: &ObjectPlan) -> String {
    let what = group.proxy.as_ref().map_or(group.category.as_str(), |p| p.label.as_str());
    let color = group.color.as_ref().map_or("", |c| c.name.as_str());
    let words: Vec<String> = group.size.words.iter().map(|w| format!("{w:?}").to_lowercase()).collect();
    format!("{what}|{color}|{}", words.join(" ")).to_lowercase()
}

/// A stand-in for the asset forge's slow path, until it runs generated code: for a
/// group not in its cache it asks the CAD stage's endpoint for a CadQuery program (so
/// the call's latency, retries and failures are real), then builds the catalog's asset
/// or a labelled proxy, and remembers the group as cached. Catalog categories count as
/// cached only when `catalog_is_cached` (the benchmark makes every group a miss).
#[derive(Debug)]
pub struct CadCallSource {
    client: Client,
    cache: Mutex<BTreeSet<String>>,
    catalog_is_cached: bool,
}

impl CadCallSource {
    pub fn new(client: Client, catalog_is_cached: bool) -> Self {
        Self { client, cache: Mutex::new(BTreeSet::new()), catalog_is_cached }
    }

    /// Marks groups like this one as cached (a warm cache).
    pub fn remember(&self, group: &ObjectPlan) {
        if let Ok(mut c) = self.cache.lock() {
            c.insert(asset_key(group));
        }
    }

    /// Forgets every cached group.
    pub fn clear(&self) {
        if let Ok(mut c) = self.cache.lock() {
            c.clear();
        }
    }
}

impl AssetSource for CadCallSource {
    fn name(&self) -> &str {
        "cad-call"
    }

    fn is_cached(&self, group: &ObjectPlan) -> bool {
        (self.catalog_is_cached && group.proxy.is_none())
            || self.cache.lock().is_ok_and(|c| c.contains(&asset_key(group)))
    }

    fn make(&self, group: &ObjectPlan, seed: u64) -> GroupAssets {
        let mut out = CatalogSource.make(group, seed);
        if self.is_cached(group) {
            return out;
        }
        out.cached = false;
        let what = group.proxy.as_ref().map_or(group.category.replace('_', " "), |p| p.label.clone());
        let req = ChatRequest::new(vec![
            Message::system(
                "You write CadQuery (Python) that builds one object as a watertight solid in metres, Z up, \
                 its base on Z = 0, centred on the origin. Answer with the code only.",
            ),
            Message::user(serde_json::json!({ "object": what, "phrase": group.phrase }).to_string()),
        ]);
        let client = self.client.fresh();
        match client.complete(LlmStage::Cad, &req, &format!("cad: {what}")) {
            Ok(_) => self.remember(group),
            Err(e) => out.warnings.push(forge_warning(
                "asset_generation_failed",
                format!("{}: asset generation failed ({e}); used the stand-in", group.phrase),
            )),
        }
        out.llm_calls = client.telemetry().take();
        out
    }
}

/// A warning of L2.
pub(crate) fn forge_warning(code: &str, message: String) -> sw_plan::Warning {
    sw_plan::Warning::new(sw_plan::Stage::Forge, code, message)
}
