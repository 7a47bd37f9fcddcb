//! An episode's frames as a LeRobot data file: one parquet file per episode at
//! `data/chunk-CCC/file-FFF.parquet`, columns `timestamp` (float32), `frame_index`,
//! `episode_index`, `index`, `task_index` (int64) and one fixed-size float32 list per
//! vector feature (`action`, `observation.state`, …). Written to a temporary name and
//! renamed into place.

use std::path::Path;
use std::sync::Arc;

use arrow_array::builder::{FixedSizeListBuilder, Float32Builder};
use arrow_array::{Array, ArrayRef, Float32Array, Int64Array, RecordBatch};
use arrow_schema::{DataType, Field, Schema};
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::properties::WriterProperties;

use crate::LeRobotError;

/// One vector feature's values, a row per frame.
#[derive(Debug, Clone)]
pub struct Column<'a> {
    pub key: &'a str,
    pub rows: &'a [Vec<f32>],
}

/// What places an episode in the dataset.
#[derive(Debug, Clone, Copy)]
pub struct EpisodePlace {
    pub episode_index: u64,
    pub task_index: u64,
    /// The dataset-wide index of the episode's first frame.
    pub first_index: u64,
    pub fps: u32,
}

/// Writes the episode's data file at `path`; its size in bytes.
pub fn write_episode(path: &Path, place: EpisodePlace, columns: &[Column<'_>]) -> Result<u64, LeRobotError> {
    let n = columns.first().map_or(0, |c| c.rows.len());
    if n == 0 {
        return Err(LeRobotError::Data("an episode without frames".into()));
    }
    let mut fields = vec![
        Field::new("timestamp", DataType::Float32, false),
        Field::new("frame_index", DataType::Int64, false),
        Field::new("episode_index", DataType::Int64, false),
        Field::new("index", DataType::Int64, false),
        Field::new("task_index", DataType::Int64, false),
    ];
    let mut arrays: Vec<ArrayRef> = vec![
        Arc::new(Float32Array::from_iter_values((0..n).map(|k| (k as f64 / f64::from(place.fps)) as f32))),
        Arc::new(Int64Array::from_iter_values((0..n).map(|k| k as i64))),
        Arc::new(Int64Array::from_iter_values(std::iter::repeat_n(place.episode_index as i64, n))),
        Arc::new(Int64Array::from_iter_values((0..n).map(|k| (place.first_index + k as u64) as i64))),
        Arc::new(Int64Array::from_iter_values(std::iter::repeat_n(place.task_index as i64, n))),
    ];
    for c in columns {
        if c.rows.len() != n {
            return Err(LeRobotError::Data(format!("{} has {} rows, the episode {n} frames", c.key, c.rows.len())));
        }
        let dim = c.rows[0].len();
        if c.rows.iter().any(|r| r.len() != dim) {
            return Err(LeRobotError::Data(format!("{}: rows of different lengths", c.key)));
        }
        let mut b = FixedSizeListBuilder::new(Float32Builder::with_capacity(n * dim), dim as i32)
            .with_field(Arc::new(Field::new("item", DataType::Float32, true)));
        for r in c.rows {
            b.values().append_slice(r);
            b.append(true);
        }
        let array = b.finish();
        fields.push(Field::new(c.key, array.data_type().clone(), false));
        arrays.push(Arc::new(array));
    }
    let schema = Arc::new(Schema::new(fields));
    let batch = RecordBatch::try_new(schema.clone(), arrays).map_err(|e| LeRobotError::Data(e.to_string()))?;
    write_batch(path, &batch)
}

/// Writes one record batch as a parquet file (snappy), atomically; its size in bytes.
pub(crate) fn write_batch(path: &Path, batch: &RecordBatch) -> Result<u64, LeRobotError> {
    if let Some(dir) = path.parent() {
        fs_err::create_dir_all(dir).map_err(|e| LeRobotError::Io(e.to_string()))?;
    }
    let tmp = path.with_extension(format!("partial-{}", std::process::id()));
    let file = fs_err::File::create(&tmp).map_err(|e| LeRobotError::Io(e.to_string()))?;
    let props = WriterProperties::builder().set_compression(Compression::SNAPPY).build();
    let mut w = ArrowWriter::try_new(file.into_parts().0, batch.schema(), Some(props))
        .map_err(|e| LeRobotError::Data(e.to_string()))?;
    w.write(batch).map_err(|e| LeRobotError::Data(e.to_string()))?;
    let f = w.into_inner().map_err(|e| LeRobotError::Data(e.to_string()))?;
    f.sync_all().map_err(|e| LeRobotError::Io(e.to_string()))?;
    drop(f);
    fs_err::rename(&tmp, path).map_err(|e| LeRobotError::Io(e.to_string()))?;
    Ok(fs_err::metadata(path).map_err(|e| LeRobotError::Io(e.to_string()))?.len())
}
