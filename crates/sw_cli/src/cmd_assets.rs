//! `assets list|show|render|sheet|generate`.

use std::path::{Path, PathBuf};

use clap::Subcommand;
use serde::Serialize;
use sw_catalog::AssetRequest;
use sw_geom::raster::{Image, draw_asset};
use sw_geom::{Asset, MassModel};

use crate::Failure;
use crate::output::{print, print_json};

#[derive(Debug, Subcommand)]
pub(crate) enum AssetsCommand {
    /// One line per category.
    List {
        #[arg(long)]
        json: bool,
    },
    /// A category's parameters, surfaces and mass — or a stored asset, by its id (or a
    /// unique prefix of 8+ hex digits, as `assets generate` and `assets search` print).
    Show {
        name: String,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// The asset store for ids: a directory or s3://bucket/prefix (default:
        /// SCENEWRIGHT_ASSET_STORE or .cache/assets).
        #[arg(long)]
        store: Option<String>,
        #[arg(long)]
        json: bool,
    },
    /// A picture of one asset.
    Render {
        name: String,
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        #[arg(long, default_value_t = 640)]
        size: u32,
    },
    /// A part from a dimensioned mechanical prompt, offline: CadQuery code from the
    /// template synthesizer, run in the sandbox, validated (size 1 %, volume 2 %), written
    /// as part.stl (metres), part.py, part.json and preview.png.
    Generate {
        prompt: String,
        #[arg(long)]
        out: PathBuf,
        /// Skip the preview picture.
        #[arg(long)]
        no_preview: bool,
        /// The asset store to put the part in: a directory or s3://bucket/prefix (default:
        /// SCENEWRIGHT_ASSET_STORE or .cache/assets in the checkout).
        #[arg(long)]
        store: Option<String>,
        /// Do not store and index the part.
        #[arg(long)]
        no_store: bool,
        #[arg(long)]
        json: bool,
    },
    /// Stored assets nearest in meaning to a description (all-MiniLM-L6-v2).
    Search {
        query: String,
        #[arg(long, default_value_t = 5)]
        top: usize,
        /// The asset store: a directory or s3://bucket/prefix (default:
        /// SCENEWRIGHT_ASSET_STORE or .cache/assets).
        #[arg(long)]
        store: Option<String>,
        #[arg(long)]
        json: bool,
    },
    /// A contact sheet of every category (or of the listed ones).
    Sheet {
        #[arg(long)]
        out: PathBuf,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Only these categories, comma-separated.
        #[arg(long, value_delimiter = ',')]
        only: Vec<String>,
        /// Tiles per row.
        #[arg(long, default_value_t = 8)]
        columns: u32,
    },
}

#[derive(Serialize)]
struct CategoryInfo {
    name: &'static str,
    display: &'static str,
    placement: sw_geom::PlacementKind,
    movable: bool,
    synonyms: &'static [&'static str],
    /// What it is a kind of ("pot" for a stock pot): the words a suite's keys and a
    /// reader may name it by besides its own names.
    is_a: &'static [&'static str],
    tags: &'static [&'static str],
    default_size_m: [f64; 3],
}

#[derive(Serialize)]
struct ParamInfo {
    name: &'static str,
    default: f64,
    min: f64,
    max: f64,
    doc: &'static str,
}

#[derive(Serialize)]
struct AssetInfo {
    category: CategoryInfo,
    params: Vec<ParamInfo>,
    seed: u64,
    values: Vec<(String, f64)>,
    bounds_m: [f64; 3],
    mass_kg: Option<f64>,
    surfaces: Vec<sw_geom::SupportSurface>,
    collision_primitives: usize,
    visual_triangles: usize,
}

fn category_info(c: &'static sw_catalog::Category) -> CategoryInfo {
    CategoryInfo {
        name: c.name,
        display: c.display,
        placement: c.placement,
        movable: c.movable,
        synonyms: c.synonyms,
        is_a: c.is_a,
        tags: c.tags,
        default_size_m: c.default_size(),
    }
}

fn find(name: &str) -> Result<&'static sw_catalog::Category, Failure> {
    let key = name.trim().to_lowercase().replace([' ', '-'], "_");
    sw_catalog::find(&key)
        .ok_or_else(|| Failure::input(format!("unknown asset category '{name}' (see `scenewright assets list`)")))
}

fn build(c: &sw_catalog::Category, seed: u64) -> Result<Asset, Failure> {
    sw_catalog::generate(&AssetRequest::new(c.name, seed)).map_err(|e| Failure::input(e.to_string()))
}

pub(crate) fn run(c: AssetsCommand) -> Result<u8, Failure> {
    match c {
        AssetsCommand::List { json } => {
            let all: Vec<CategoryInfo> = sw_catalog::categories().iter().map(category_info).collect();
            if json {
                print_json(&all);
            } else {
                for c in all {
                    let s = c.default_size_m;
                    print(&format!(
                        "{:<18} {:.2} × {:.2} × {:.2} m  {:?}  {}",
                        c.name, s[0], s[1], s[2], c.placement, c.display
                    ));
                }
            }
            Ok(0)
        }
        AssetsCommand::Show { name, seed, store, json } => {
            let looks_like_id = name.len() >= 8 && name.bytes().all(|b| b.is_ascii_hexdigit());
            if looks_like_id && sw_catalog::find(&name).is_none() {
                return crate::cmd_forge::show_stored(&name, store, json);
            }
            let cat = find(&name)?;
            let a = build(cat, seed)?;
            let info = AssetInfo {
                category: category_info(cat),
                params: cat
                    .params
                    .iter()
                    .map(|p| ParamInfo { name: p.name, default: p.default, min: p.min, max: p.max, doc: p.doc })
                    .collect(),
                seed,
                values: a.params.clone(),
                bounds_m: a.bounds().size(),
                mass_kg: match a.mass {
                    MassModel::Free { mass } => Some(mass),
                    MassModel::Static => None,
                },
                surfaces: a.surfaces.clone(),
                collision_primitives: a.links.iter().map(|l| l.collisions.len()).sum(),
                visual_triangles: a.links.iter().flat_map(|l| &l.visuals).map(|v| v.mesh.triangles.len()).sum(),
            };
            if json {
                print_json(&info);
            } else {
                let mut lines = vec![format!(
                    "{} ({}), {:?}, {}",
                    cat.name,
                    cat.display,
                    cat.placement,
                    if cat.movable { "free item" } else { "static fixture" }
                )];
                lines.push(format!("  synonyms: {}", cat.synonyms.join(", ")));
                lines.push(format!("  tags: {}", cat.tags.join(", ")));
                for p in cat.params {
                    let used = a.param(p.name).unwrap_or(p.default);
                    lines.push(format!(
                        "  {:<16} {:>8.3}  (default {}, {}..{})  {}",
                        p.name, used, p.default, p.min, p.max, p.doc
                    ));
                }
                let b = info.bounds_m;
                lines.push(format!(
                    "  bounds {:.3} × {:.3} × {:.3} m · {} collision primitives · {} triangles",
                    b[0], b[1], b[2], info.collision_primitives, info.visual_triangles
                ));
                if let Some(m) = info.mass_kg {
                    lines.push(format!("  mass {m:.2} kg"));
                }
                for s in &a.surfaces {
                    lines.push(format!(
                        "  surface {:<12} z {:.3} m, {:.2} × {:.2} m{}",
                        s.name,
                        s.z,
                        s.max[0] - s.min[0],
                        s.max[1] - s.min[1],
                        s.clearance.map(|c| format!(", {c:.2} m clear above")).unwrap_or_default()
                    ));
                }
                print(&lines.join("\n"));
            }
            Ok(0)
        }
        AssetsCommand::Generate { prompt, out, no_preview, store, no_store, json } => {
            crate::cmd_forge::generate(&prompt, out, no_preview, store, no_store, json)
        }
        AssetsCommand::Search { query, top, store, json } => crate::cmd_forge::search(&query, top, store, json),
        AssetsCommand::Render { name, out, seed, size } => {
            let cat = find(&name)?;
            let a = build(cat, seed)?;
            let size = size.clamp(64, 4096);
            write_png(&draw_asset(&a, size, size), &out)?;
            Ok(0)
        }
        AssetsCommand::Sheet { out, seed, only, columns } => {
            let cats: Vec<&'static sw_catalog::Category> = if only.is_empty() {
                sw_catalog::categories().iter().collect()
            } else {
                only.iter().map(|n| find(n)).collect::<Result<_, _>>()?
            };
            let tile = 200u32;
            let cols = columns.clamp(1, 32);
            let rows = (cats.len() as u32).div_ceil(cols);
            let mut sheet = Image::new(cols * tile, rows * (tile + 22), [255, 255, 255]);
            for (i, c) in cats.iter().enumerate() {
                let a = build(c, seed)?;
                let img = draw_asset(&a, tile, tile);
                let (x, y) = ((i as u32 % cols) * tile, (i as u32 / cols) * (tile + 22));
                sheet.blit(&img, x, y);
                // 12 px per character at scale 2; long names drop to scale 1 to fit the tile.
                let scale = if c.name.len() as u32 * 12 + 5 > tile { 1 } else { 2 };
                sheet.text(x + 5, y + tile + 5 + (2 - scale) * 3, c.name, scale, [20, 20, 30]);
            }
            write_png(&sheet, &out)?;
            Ok(0)
        }
    }
}

fn write_png(img: &Image, out: &Path) -> Result<(), Failure> {
    let file = fs_err::File::create(out).map_err(|e| Failure::input(e.to_string()))?;
    img.write_png(std::io::BufWriter::new(file)).map_err(|e| Failure::internal(e.to_string()))
}
