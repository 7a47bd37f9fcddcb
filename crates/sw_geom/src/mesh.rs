//! Indexed triangle meshes and their validation.

use std::collections::HashMap;

use serde::{Deserialize, Serialize};

use crate::Pose;

/// An axis-aligned box, `min` to `max`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Aabb {
    pub min: [f64; 3],
    pub max: [f64; 3],
}

impl Aabb {
    /// The empty box: the identity of [`Aabb::union`].
    pub const EMPTY: Aabb = Aabb { min: [f64::INFINITY; 3], max: [f64::NEG_INFINITY; 3] };

    pub fn from_center_half(center: [f64; 3], half: [f64; 3]) -> Self {
        Self {
            min: [center[0] - half[0], center[1] - half[1], center[2] - half[2]],
            max: [center[0] + half[0], center[1] + half[1], center[2] + half[2]],
        }
    }

    pub fn is_empty(&self) -> bool {
        (0..3).any(|i| self.min[i] > self.max[i])
    }

    pub fn include(&mut self, p: [f64; 3]) {
        for ((lo, hi), v) in self.min.iter_mut().zip(self.max.iter_mut()).zip(p) {
            *lo = lo.min(v);
            *hi = hi.max(v);
        }
    }

    pub fn union(&self, other: &Aabb) -> Aabb {
        let mut out = *self;
        if !other.is_empty() {
            out.include(other.min);
            out.include(other.max);
        }
        out
    }

    pub fn size(&self) -> [f64; 3] {
        if self.is_empty() {
            return [0.0; 3];
        }
        [self.max[0] - self.min[0], self.max[1] - self.min[1], self.max[2] - self.min[2]]
    }

    pub fn center(&self) -> [f64; 3] {
        [0.5 * (self.min[0] + self.max[0]), 0.5 * (self.min[1] + self.max[1]), 0.5 * (self.min[2] + self.max[2])]
    }

    /// The bounding box of this box after a rigid transform.
    pub fn transformed(&self, pose: &Pose) -> Aabb {
        let mut out = Aabb::EMPTY;
        if self.is_empty() {
            return out;
        }
        for corner in 0..8 {
            let p = [
                if corner & 1 == 0 { self.min[0] } else { self.max[0] },
                if corner & 2 == 0 { self.min[1] } else { self.max[1] },
                if corner & 4 == 0 { self.min[2] } else { self.max[2] },
            ];
            out.include(pose.apply(p));
        }
        out
    }
}

/// An indexed triangle mesh. Triangles wind counter-clockwise seen from outside.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    pub vertices: Vec<[f32; 3]>,
    pub triangles: Vec<[u32; 3]>,
}

/// What [`Mesh::check`] found.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MeshCheck {
    pub vertices: usize,
    pub triangles: usize,
    /// Every edge is shared by exactly two triangles that traverse it in opposite directions.
    pub watertight: bool,
    /// Edges used by one triangle only, or by more than two, or twice in the same direction.
    pub bad_edges: usize,
    /// Triangles with (near) zero area.
    pub degenerate_triangles: usize,
    /// Signed volume (positive for an outward-facing closed mesh), m³.
    pub volume: f64,
    pub bounds: Aabb,
    pub finite: bool,
}

impl MeshCheck {
    /// A closed, consistently oriented, finite mesh with positive volume.
    pub fn is_valid_solid(&self) -> bool {
        self.watertight && self.finite && self.volume > 0.0 && self.degenerate_triangles == 0
    }
}

impl Mesh {
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Appends `other`, transformed by `pose`, as a separate shell.
    pub fn append(&mut self, other: &Mesh, pose: &Pose) {
        let base = self.vertices.len() as u32;
        self.vertices.extend(other.vertices.iter().map(|v| {
            let p = pose.apply([f64::from(v[0]), f64::from(v[1]), f64::from(v[2])]);
            [p[0] as f32, p[1] as f32, p[2] as f32]
        }));
        self.triangles.extend(other.triangles.iter().map(|t| [t[0] + base, t[1] + base, t[2] + base]));
    }

    pub fn bounds(&self) -> Aabb {
        let mut b = Aabb::EMPTY;
        for v in &self.vertices {
            b.include([f64::from(v[0]), f64::from(v[1]), f64::from(v[2])]);
        }
        b
    }

    /// Signed volume by the divergence theorem.
    pub fn volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertex(i));
                (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0]))
                    / 6.0
            })
            .sum()
    }

    fn vertex(&self, i: u32) -> [f64; 3] {
        let v = self.vertices.get(i as usize).copied().unwrap_or([f32::NAN; 3]);
        [f64::from(v[0]), f64::from(v[1]), f64::from(v[2])]
    }

    /// Topology and geometry checks. Vertices are compared by exact position, so shells
    /// that were built with duplicated vertices along seams are judged correctly.
    pub fn check(&self) -> MeshCheck {
        let finite = self.vertices.iter().all(|v| v.iter().all(|c| c.is_finite()))
            && self.triangles.iter().all(|t| t.iter().all(|&i| (i as usize) < self.vertices.len()));
        // Weld by exact position so that seams with split vertices still count as shared.
        let mut weld: HashMap<[u32; 3], u32> = HashMap::new();
        let ids: Vec<u32> = self
            .vertices
            .iter()
            .map(|v| {
                let key = v.map(f32::to_bits);
                let next = weld.len() as u32;
                *weld.entry(key).or_insert(next)
            })
            .collect();
        let mut edges: HashMap<(u32, u32), i32> = HashMap::new();
        let mut degenerate = 0;
        for t in &self.triangles {
            let Some(w) = t.iter().map(|&i| ids.get(i as usize).copied()).collect::<Option<Vec<_>>>() else {
                continue;
            };
            let [a, b, c] = t.map(|i| self.vertex(i));
            let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let ac = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let cross = [ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]];
            let area2 = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
            if area2 < 1e-14 || w[0] == w[1] || w[1] == w[2] || w[0] == w[2] {
                degenerate += 1;
            }
            for k in 0..3 {
                let (u, v) = (w[k], w[(k + 1) % 3]);
                // +1 for u<v traversed forwards, +1000 for the reverse direction.
                let (key, inc) = if u < v { ((u, v), 1) } else { ((v, u), 1000) };
                *edges.entry(key).or_insert(0) += inc;
            }
        }
        let bad_edges = edges.values().filter(|&&n| n != 1001).count();
        MeshCheck {
            vertices: self.vertices.len(),
            triangles: self.triangles.len(),
            watertight: bad_edges == 0 && !self.triangles.is_empty(),
            bad_edges,
            degenerate_triangles: degenerate,
            volume: self.volume(),
            bounds: self.bounds(),
            finite,
        }
    }
}
