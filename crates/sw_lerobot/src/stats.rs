//! Feature statistics as LeRobot keeps them: per feature `min`, `max`, `mean`, `std`,
//! `count` and the quantiles `q01`, `q10`, `q50`, `q90`, `q99`, each a list over the
//! feature's entries (per channel, shape [3, 1, 1], for images in [0, 1]). Per episode
//! they are exact; over the dataset min and max are exact, mean and std are pooled, and
//! quantiles are the episodes' weighted by length (as LeRobot aggregates them).

use serde::{Deserialize, Serialize};

/// The quantiles LeRobot records.
pub const QUANTILES: [(f64, &str); 5] = [(0.01, "q01"), (0.10, "q10"), (0.50, "q50"), (0.90, "q90"), (0.99, "q99")];

/// Statistics of one feature, one value per entry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FeatureStats {
    pub min: Vec<f64>,
    pub max: Vec<f64>,
    pub mean: Vec<f64>,
    pub std: Vec<f64>,
    pub count: u64,
    /// (name, values) in the order of [`QUANTILES`].
    pub quantiles: Vec<(String, Vec<f64>)>,
}

impl FeatureStats {
    /// Exact statistics of `rows` (each `dim` long).
    pub fn of_rows(rows: &[Vec<f64>], dim: usize) -> Self {
        let n = rows.len();
        let mut columns: Vec<Vec<f64>> = vec![Vec::with_capacity(n); dim];
        for r in rows {
            for (c, v) in columns.iter_mut().zip(r) {
                c.push(*v);
            }
        }
        Self::of_columns(columns, n as u64)
    }

    /// Exact statistics of each column; `count` is the number of samples it stands for.
    pub fn of_columns(mut columns: Vec<Vec<f64>>, count: u64) -> Self {
        let dim = columns.len();
        let mut s = FeatureStats {
            min: vec![0.0; dim],
            max: vec![0.0; dim],
            mean: vec![0.0; dim],
            std: vec![0.0; dim],
            count,
            quantiles: QUANTILES.iter().map(|(_, k)| (k.to_string(), vec![0.0; dim])).collect(),
        };
        for (i, c) in columns.iter_mut().enumerate() {
            if c.is_empty() {
                continue;
            }
            c.sort_by(f64::total_cmp);
            let n = c.len() as f64;
            let mean = c.iter().sum::<f64>() / n;
            s.min[i] = c[0];
            s.max[i] = c[c.len() - 1];
            s.mean[i] = mean;
            s.std[i] = (c.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
            for (k, (q, _)) in QUANTILES.iter().enumerate() {
                s.quantiles[k].1[i] = quantile(c, *q);
            }
        }
        s
    }

    /// Pools the statistics of several episodes.
    pub fn aggregate(parts: &[&FeatureStats]) -> Option<FeatureStats> {
        let first = parts.first()?;
        let dim = first.mean.len();
        let total: u64 = parts.iter().map(|p| p.count).sum();
        let w = |p: &FeatureStats| p.count as f64 / total.max(1) as f64;
        let mut out = FeatureStats {
            min: vec![f64::INFINITY; dim],
            max: vec![f64::NEG_INFINITY; dim],
            mean: vec![0.0; dim],
            std: vec![0.0; dim],
            count: total,
            quantiles: first.quantiles.iter().map(|(k, _)| (k.clone(), vec![0.0; dim])).collect(),
        };
        for p in parts {
            for i in 0..dim {
                out.min[i] = out.min[i].min(p.min[i]);
                out.max[i] = out.max[i].max(p.max[i]);
                out.mean[i] += w(p) * p.mean[i];
                for (k, q) in out.quantiles.iter_mut().enumerate() {
                    q.1[i] += w(p) * p.quantiles.get(k).map_or(0.0, |x| x.1[i]);
                }
            }
        }
        for i in 0..dim {
            let var: f64 = parts.iter().map(|p| w(p) * (p.std[i].powi(2) + (p.mean[i] - out.mean[i]).powi(2))).sum();
            out.std[i] = var.sqrt();
        }
        Some(out)
    }

    /// As LeRobot's `stats.json` writes a feature: lists, images nested as [c][1][1].
    pub fn to_json(&self, image: bool) -> serde_json::Value {
        let wrap = |v: &[f64]| -> serde_json::Value {
            if image {
                serde_json::Value::Array(v.iter().map(|x| serde_json::json!([[x]])).collect())
            } else {
                serde_json::json!(v)
            }
        };
        let mut m = serde_json::Map::new();
        m.insert("min".into(), wrap(&self.min));
        m.insert("max".into(), wrap(&self.max));
        m.insert("mean".into(), wrap(&self.mean));
        m.insert("std".into(), wrap(&self.std));
        m.insert("count".into(), serde_json::json!([self.count]));
        for (k, v) in &self.quantiles {
            m.insert(k.clone(), wrap(v));
        }
        serde_json::Value::Object(m)
    }
}

/// The `q`-quantile of sorted values, linearly interpolated.
fn quantile(sorted: &[f64], q: f64) -> f64 {
    let pos = q * (sorted.len() - 1) as f64;
    let lo = pos.floor() as usize;
    let hi = pos.ceil() as usize;
    let f = pos - lo as f64;
    sorted[lo] * (1.0 - f) + sorted[hi] * f
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pooled_statistics_equal_the_whole() {
        let a: Vec<Vec<f64>> = (0..10).map(|i| vec![f64::from(i)]).collect();
        let b: Vec<Vec<f64>> = (10..30).map(|i| vec![f64::from(i)]).collect();
        let all: Vec<Vec<f64>> = a.iter().chain(&b).cloned().collect();
        let (sa, sb, s) = (FeatureStats::of_rows(&a, 1), FeatureStats::of_rows(&b, 1), FeatureStats::of_rows(&all, 1));
        let p = FeatureStats::aggregate(&[&sa, &sb]).unwrap_or_else(|| panic!());
        assert_eq!((p.min[0], p.max[0], p.count), (0.0, 29.0, 30));
        assert!((p.mean[0] - s.mean[0]).abs() < 1e-12);
        assert!((p.std[0] - s.std[0]).abs() < 1e-9, "{} {}", p.std[0], s.std[0]);
        assert_eq!(s.quantiles[2].1[0], 14.5);
    }
}
