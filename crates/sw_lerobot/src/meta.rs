//! The dataset's metadata, derived from its episodes' records and rewritten whole (each
//! file atomically): `meta/info.json`, `meta/stats.json`, `meta/tasks.parquet` (indexed by
//! the task string, as pandas writes it) and `meta/episodes/chunk-000/file-000.parquet`
//! (one row per episode: where its frames and videos are, its statistics).

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use arrow_array::builder::{Float64Builder, ListBuilder, StringBuilder};
use arrow_array::{Array, ArrayRef, Float64Array, Int64Array, RecordBatch, StringArray};
use arrow_schema::{DataType, Field, Schema};
use serde::{Deserialize, Serialize};

use crate::stats::{FeatureStats, QUANTILES};
use crate::{CHUNK_SIZE, CODEBASE_VERSION, DATA_PATH, LeRobotError, VIDEO_PATH, chunk_file, write_atomically};

/// The kind of a feature's values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Dtype {
    Float32,
    Video,
}

/// One feature of every frame besides the index columns.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FeatureSpec {
    pub key: String,
    pub dtype: Dtype,
    /// `[n]` for vectors, `[height, width, 3]` for videos.
    pub shape: Vec<usize>,
    /// The entries' names (vectors).
    pub names: Vec<String>,
}

/// What the dataset is, for `info.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DatasetInfo {
    pub fps: u32,
    pub robot_type: String,
    pub features: Vec<FeatureSpec>,
}

/// What the metadata needs of one written episode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EpisodeRecord {
    pub episode_index: u64,
    pub length: u64,
    pub task: String,
    /// The dataset-wide index of its first frame.
    pub first_index: u64,
    /// Per feature key (vectors and videos).
    pub stats: BTreeMap<String, FeatureStats>,
}

fn index_feature(dtype: &str) -> serde_json::Value {
    serde_json::json!({"dtype": dtype, "shape": [1], "names": null})
}

/// Writes every metadata file for `episodes` (in episode order) of a dataset at `root`.
pub fn write_meta(root: &Path, info: &DatasetInfo, episodes: &[EpisodeRecord]) -> Result<(), LeRobotError> {
    for (k, e) in episodes.iter().enumerate() {
        if e.episode_index != k as u64 {
            return Err(LeRobotError::Data(format!("episode {k} is recorded as {}", e.episode_index)));
        }
    }
    let videos: Vec<&FeatureSpec> = info.features.iter().filter(|f| f.dtype == Dtype::Video).collect();
    // Tasks in order of first use.
    let mut tasks: Vec<&str> = Vec::new();
    for e in episodes {
        if !tasks.contains(&e.task.as_str()) {
            tasks.push(&e.task);
        }
    }
    let total_frames: u64 = episodes.iter().map(|e| e.length).sum();

    // info.json
    let mut features = serde_json::Map::new();
    for f in &info.features {
        let v = match f.dtype {
            Dtype::Float32 => serde_json::json!({"dtype": "float32", "shape": f.shape, "names": f.names}),
            Dtype::Video => serde_json::json!({
                "dtype": "video",
                "shape": f.shape,
                "names": ["height", "width", "channels"],
                "info": {
                    "video.height": f.shape[0],
                    "video.width": f.shape[1],
                    "video.codec": crate::video::CODEC,
                    "video.pix_fmt": crate::video::PIX_FMT,
                    "video.is_depth_map": false,
                    "video.fps": info.fps,
                    "video.channels": 3,
                    "has_audio": false
                }
            }),
        };
        features.insert(f.key.clone(), v);
    }
    features.insert("timestamp".into(), index_feature("float32"));
    for k in ["frame_index", "episode_index", "index", "task_index"] {
        features.insert(k.into(), index_feature("int64"));
    }
    let info_json = serde_json::json!({
        "codebase_version": CODEBASE_VERSION,
        "robot_type": info.robot_type,
        "total_episodes": episodes.len(),
        "total_frames": total_frames,
        "total_tasks": tasks.len(),
        "chunks_size": CHUNK_SIZE,
        "data_files_size_in_mb": 100,
        "video_files_size_in_mb": 200,
        "fps": info.fps,
        "splits": {"train": format!("0:{}", episodes.len())},
        "data_path": DATA_PATH,
        "video_path": if videos.is_empty() { serde_json::Value::Null } else { serde_json::json!(VIDEO_PATH) },
        "features": features,
    });
    let meta = root.join("meta");
    write_atomically(&meta.join("info.json"), &pretty(&info_json))?;

    // stats.json: pooled over the episodes.
    let mut stats = serde_json::Map::new();
    for f in &info.features {
        let parts: Vec<&FeatureStats> = episodes.iter().filter_map(|e| e.stats.get(&f.key)).collect();
        if let Some(s) = FeatureStats::aggregate(&parts) {
            stats.insert(f.key.clone(), s.to_json(f.dtype == Dtype::Video));
        }
    }
    write_atomically(&meta.join("stats.json"), &pretty(&serde_json::Value::Object(stats)))?;

    // tasks.parquet, indexed by the task string (pandas' metadata says so).
    let schema =
        Schema::new(vec![Field::new("task", DataType::Utf8, false), Field::new("task_index", DataType::Int64, false)])
            .with_metadata(
                [("pandas".to_string(), pandas_index_metadata())]
                    .into_iter()
                    .collect::<std::collections::HashMap<String, String>>(),
            );
    let batch = RecordBatch::try_new(
        Arc::new(schema),
        vec![
            Arc::new(StringArray::from_iter_values(tasks.iter())),
            Arc::new(Int64Array::from_iter_values(0..tasks.len() as i64)),
        ],
    )
    .map_err(|e| LeRobotError::Data(e.to_string()))?;
    crate::data::write_batch(&meta.join("tasks.parquet"), &batch)?;

    // meta/episodes
    let n = episodes.len();
    let mut fields: Vec<Field> = Vec::new();
    let mut arrays: Vec<ArrayRef> = Vec::new();
    let int = |name: &str, values: Vec<i64>, fields: &mut Vec<Field>, arrays: &mut Vec<ArrayRef>| {
        fields.push(Field::new(name, DataType::Int64, false));
        arrays.push(Arc::new(Int64Array::from(values)));
    };
    int("episode_index", episodes.iter().map(|e| e.episode_index as i64).collect(), &mut fields, &mut arrays);
    let mut tb = ListBuilder::new(StringBuilder::new());
    for e in episodes {
        tb.values().append_value(&e.task);
        tb.append(true);
    }
    let t = tb.finish();
    fields.push(Field::new("tasks", t.data_type().clone(), true));
    arrays.push(Arc::new(t));
    int("length", episodes.iter().map(|e| e.length as i64).collect(), &mut fields, &mut arrays);
    int(
        "data/chunk_index",
        episodes.iter().map(|e| chunk_file(e.episode_index).0 as i64).collect(),
        &mut fields,
        &mut arrays,
    );
    int(
        "data/file_index",
        episodes.iter().map(|e| chunk_file(e.episode_index).1 as i64).collect(),
        &mut fields,
        &mut arrays,
    );
    int("dataset_from_index", episodes.iter().map(|e| e.first_index as i64).collect(), &mut fields, &mut arrays);
    int(
        "dataset_to_index",
        episodes.iter().map(|e| (e.first_index + e.length) as i64).collect(),
        &mut fields,
        &mut arrays,
    );
    for v in &videos {
        let key = &v.key;
        int(
            &format!("videos/{key}/chunk_index"),
            episodes.iter().map(|e| chunk_file(e.episode_index).0 as i64).collect(),
            &mut fields,
            &mut arrays,
        );
        int(
            &format!("videos/{key}/file_index"),
            episodes.iter().map(|e| chunk_file(e.episode_index).1 as i64).collect(),
            &mut fields,
            &mut arrays,
        );
        fields.push(Field::new(format!("videos/{key}/from_timestamp"), DataType::Float64, false));
        arrays.push(Arc::new(Float64Array::from(vec![0.0; n])));
        fields.push(Field::new(format!("videos/{key}/to_timestamp"), DataType::Float64, false));
        arrays.push(Arc::new(Float64Array::from_iter_values(
            episodes.iter().map(|e| e.length as f64 / f64::from(info.fps)),
        )));
    }
    int("meta/episodes/chunk_index", vec![0; n], &mut fields, &mut arrays);
    int("meta/episodes/file_index", vec![0; n], &mut fields, &mut arrays);
    for f in &info.features {
        let stat_names: Vec<&str> =
            ["min", "max", "mean", "std", "count"].into_iter().chain(QUANTILES.iter().map(|(_, k)| *k)).collect();
        for s in stat_names {
            let mut b = ListBuilder::new(Float64Builder::new());
            for e in episodes {
                match e.stats.get(&f.key) {
                    Some(st) => {
                        let values: Vec<f64> = match s {
                            "min" => st.min.clone(),
                            "max" => st.max.clone(),
                            "mean" => st.mean.clone(),
                            "std" => st.std.clone(),
                            "count" => vec![st.count as f64],
                            q => st.quantiles.iter().find(|(k, _)| k == q).map(|(_, v)| v.clone()).unwrap_or_default(),
                        };
                        b.values().append_slice(&values);
                        b.append(true);
                    }
                    None => b.append(false),
                }
            }
            let a = b.finish();
            fields.push(Field::new(format!("stats/{}/{s}", f.key), a.data_type().clone(), true));
            arrays.push(Arc::new(a));
        }
    }
    let batch =
        RecordBatch::try_new(Arc::new(Schema::new(fields)), arrays).map_err(|e| LeRobotError::Data(e.to_string()))?;
    crate::data::write_batch(&meta.join("episodes/chunk-000/file-000.parquet"), &batch)?;
    Ok(())
}

fn pretty(v: &serde_json::Value) -> String {
    let mut s = serde_json::to_string_pretty(v).unwrap_or_default();
    s.push('\n');
    s
}

/// pandas' schema metadata that makes the `task` column the frame's index.
fn pandas_index_metadata() -> String {
    serde_json::json!({
        "index_columns": ["task"],
        "column_indexes": [{"name": null, "field_name": null, "pandas_type": "unicode", "numpy_type": "object", "metadata": {"encoding": "UTF-8"}}],
        "columns": [
            {"name": "task_index", "field_name": "task_index", "pandas_type": "int64", "numpy_type": "int64", "metadata": null},
            {"name": "task", "field_name": "task", "pandas_type": "unicode", "numpy_type": "object", "metadata": null}
        ],
        "creator": {"library": "scenewright", "version": env!("CARGO_PKG_VERSION")},
        "pandas_version": "2.2.3"
    })
    .to_string()
}
