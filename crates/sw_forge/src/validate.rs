//! The validator: is this mesh the part that was asked for? A closed, consistently
//! oriented solid with positive volume and a bounded number of triangles; then, when the
//! request says, the right size (bounding box within a tolerance), the right volume and
//! the right number of through-holes (the genus of its surface).

use std::collections::{HashMap, HashSet};

use serde::{Deserialize, Serialize};
use sw_geom::Mesh;

use crate::failure::{Failure, FailureKind};

/// How the bounding box is compared with the requested size.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Orientation {
    /// Per axis: X with X, Y with Y, Z with Z (the request names its axes).
    Strict,
    /// Sorted extents: any orientation of the right size passes.
    #[default]
    Free,
}

/// What the part should be. Lengths in the code's units (scenewright asks for mm).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Target {
    /// Bounding-box size.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<[f64; 3]>,
    #[serde(default)]
    pub orientation: Orientation,
    /// Relative tolerance of each extent.
    pub size_tolerance: f64,
    /// Absolute slack added to each extent's tolerance (tessellation of round parts).
    pub size_slack: f64,
    /// Which extents are checked (with `Strict` orientation): a cut that may trim a side
    /// of a part leaves that extent unpromised.
    #[serde(default = "all_axes")]
    pub size_axes: [bool; 3],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub volume: Option<f64>,
    pub volume_tolerance: f64,
    /// Through-holes (handles) of the surface: a washer 1, a plate with four holes 4.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub genus: Option<u32>,
    pub max_triangles: usize,
}

impl Default for Target {
    fn default() -> Self {
        Self {
            size: None,
            orientation: Orientation::Free,
            size_tolerance: 0.01,
            size_slack: 0.02,
            size_axes: all_axes(),
            volume: None,
            volume_tolerance: 0.02,
            genus: None,
            max_triangles: 200_000,
        }
    }
}

fn all_axes() -> [bool; 3] {
    [true; 3]
}

/// What the validator measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MeshReport {
    pub triangles: usize,
    pub vertices: usize,
    pub watertight: bool,
    pub volume: f64,
    pub min: [f64; 3],
    pub max: [f64; 3],
    pub size: [f64; 3],
    /// Connected shells.
    pub shells: usize,
    /// Through-holes, summed over the shells.
    pub genus: u32,
    /// The largest relative error of an extent, when a size was requested.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size_error: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub volume_error: Option<f64>,
}

/// Measures `mesh` and checks it against `target`.
pub fn validate(mesh: &Mesh, target: &Target) -> Result<MeshReport, Failure> {
    let report = measure(mesh);
    let check = mesh.check();
    if !check.finite {
        return Err(Failure::new(FailureKind::InvalidSolid, "the mesh has non-finite coordinates"));
    }
    if mesh.triangles.len() > target.max_triangles {
        return Err(Failure::new(
            FailureKind::InvalidSolid,
            format!(
                "the mesh has {} triangles, more than the budget of {}",
                mesh.triangles.len(),
                target.max_triangles
            ),
        ));
    }
    if !check.watertight {
        return Err(Failure::new(
            FailureKind::InvalidSolid,
            format!("the mesh is not watertight: {} edges are open or shared by more than two faces", check.bad_edges),
        ));
    }
    if check.volume <= 0.0 {
        return Err(Failure::new(
            FailureKind::InvalidSolid,
            format!("the solid's volume is not positive ({:.4})", check.volume),
        ));
    }
    let mut report = report;
    if let Some(want) = target.size {
        let (got, want) = match target.orientation {
            Orientation::Strict => (report.size, want),
            Orientation::Free => (sorted(report.size), sorted(want)),
        };
        let mut worst = 0.0f64;
        let mut problems = Vec::new();
        for (axis, (g, w)) in got.iter().zip(want.iter()).enumerate() {
            if target.orientation == Orientation::Strict && !target.size_axes[axis] {
                continue;
            }
            let err = (g - w).abs();
            let rel = if *w > 0.0 { err / w } else { err };
            worst = worst.max(rel);
            if err > target.size_tolerance * w + target.size_slack {
                let name = match target.orientation {
                    Orientation::Strict => ["X", "Y", "Z"][axis].to_string(),
                    Orientation::Free => format!("extent {}", axis + 1),
                };
                problems.push(format!("{name} is {g:.3}, wanted {w:.3}"));
            }
        }
        report.size_error = Some(worst);
        if !problems.is_empty() {
            return Err(Failure::new(
                FailureKind::ScaleMismatch,
                format!(
                    "the bounding box is {:.3} × {:.3} × {:.3}: {}",
                    report.size[0],
                    report.size[1],
                    report.size[2],
                    problems.join(", ")
                ),
            ));
        }
    }
    if let Some(want) = target.volume.filter(|v| *v > 0.0) {
        let rel = (report.volume - want).abs() / want;
        report.volume_error = Some(rel);
        if rel > target.volume_tolerance {
            return Err(Failure::new(
                FailureKind::SemanticMismatch,
                format!(
                    "the volume is {:.1}, wanted {:.1} ({:+.1} %): a feature is missing, extra or the wrong size",
                    report.volume,
                    want,
                    100.0 * (report.volume - want) / want
                ),
            ));
        }
    }
    if let Some(want) = target.genus
        && report.genus != want
    {
        return Err(Failure::new(
            FailureKind::SemanticMismatch,
            format!("the part has {} through-holes, wanted {want}", report.genus),
        ));
    }
    Ok(report)
}

/// Size, volume, shells and genus of a mesh, without judging it.
pub fn measure(mesh: &Mesh) -> MeshReport {
    let b = mesh.bounds();
    let size = b.size();
    let (shells, genus) = topology(mesh);
    MeshReport {
        triangles: mesh.triangles.len(),
        vertices: mesh.vertices.len(),
        watertight: mesh.check().watertight,
        volume: mesh.volume(),
        min: if b.is_empty() { [0.0; 3] } else { b.min },
        max: if b.is_empty() { [0.0; 3] } else { b.max },
        size,
        shells,
        genus,
        size_error: None,
        volume_error: None,
    }
}

fn sorted(mut v: [f64; 3]) -> [f64; 3] {
    v.sort_by(f64::total_cmp);
    v
}

/// Connected shells and total genus from the Euler characteristic of each shell
/// (V − E + F = 2 − 2g for a closed orientable surface). Vertices are welded by position.
fn topology(mesh: &Mesh) -> (usize, u32) {
    let mut weld: HashMap<[u32; 3], u32> = HashMap::new();
    let ids: Vec<u32> = mesh
        .vertices
        .iter()
        .map(|v| {
            let next = weld.len() as u32;
            *weld.entry(v.map(f32::to_bits)).or_insert(next)
        })
        .collect();
    let n = weld.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(mesh.triangles.len());
    for t in &mesh.triangles {
        let Some(w) = t.iter().map(|&i| ids.get(i as usize).copied()).collect::<Option<Vec<_>>>() else {
            continue;
        };
        let w = [w[0], w[1], w[2]];
        for k in 0..3 {
            let a = find(&mut parent, w[k] as usize);
            let b = find(&mut parent, w[(k + 1) % 3] as usize);
            if a != b {
                parent[a] = b;
            }
        }
        tris.push(w);
    }
    // Per shell: vertices, edges, faces.
    let mut v_count: HashMap<usize, i64> = HashMap::new();
    let mut used: HashSet<u32> = HashSet::new();
    for t in &tris {
        for &v in t {
            if used.insert(v) {
                let r = find(&mut parent, v as usize);
                *v_count.entry(r).or_insert(0) += 1;
            }
        }
    }
    let mut edges: HashSet<(u32, u32)> = HashSet::new();
    let mut e_count: HashMap<usize, i64> = HashMap::new();
    let mut f_count: HashMap<usize, i64> = HashMap::new();
    for t in &tris {
        let r = find(&mut parent, t[0] as usize);
        *f_count.entry(r).or_insert(0) += 1;
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let key = if a < b { (a, b) } else { (b, a) };
            if edges.insert(key) {
                *e_count.entry(r).or_insert(0) += 1;
            }
        }
    }
    let mut genus = 0i64;
    for (root, v) in &v_count {
        let chi = v - e_count.get(root).copied().unwrap_or(0) + f_count.get(root).copied().unwrap_or(0);
        genus += ((2 - chi) / 2).max(0);
    }
    (v_count.len(), genus.max(0) as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn torus_like_ring() -> Mesh {
        // A square ring: outer 4×4, inner 2×2, height 1, built from quads.
        let mut m = Mesh::default();
        let outer = [[-2.0f32, -2.0], [2.0, -2.0], [2.0, 2.0], [-2.0, 2.0]];
        let inner = [[-1.0f32, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        for z in [0.0f32, 1.0] {
            for p in outer.iter().chain(inner.iter()) {
                m.vertices.push([p[0], p[1], z]);
            }
        }
        // Indices: bottom outer 0..4, bottom inner 4..8, top outer 8..12, top inner 12..16.
        let mut quad = |a: u32, b: u32, c: u32, d: u32| {
            m.triangles.push([a, b, c]);
            m.triangles.push([a, c, d]);
        };
        for i in 0..4u32 {
            let j = (i + 1) % 4;
            quad(8 + i, 8 + j, 12 + j, 12 + i); // top face
            quad(i, 4 + i, 4 + j, j); // bottom face
            quad(i, j, 8 + j, 8 + i); // outer wall
            quad(4 + i, 12 + i, 12 + j, 4 + j); // inner wall
        }
        m
    }

    #[test]
    fn a_box_is_a_valid_solid_of_genus_zero_and_a_ring_has_one_hole() {
        let cube = sw_geom::box_mesh([1.0, 2.0, 3.0]);
        let r = validate(&cube, &Target { size: Some([6.0, 2.0, 4.0]), ..Target::default() }).expect("valid");
        assert_eq!((r.shells, r.genus), (1, 0));
        assert!((r.volume - 48.0).abs() < 1e-9);
        let ring = torus_like_ring();
        let r = measure(&ring);
        assert!(ring.check().watertight, "{:?}", ring.check());
        assert_eq!((r.shells, r.genus), (1, 1));
        assert!((r.volume - 12.0).abs() < 1e-6, "{}", r.volume);
    }

    #[test]
    fn each_check_fails_with_its_kind() {
        let cube = sw_geom::box_mesh([1.0, 1.0, 1.0]);
        let strict = Target { size: Some([2.0, 2.0, 3.0]), orientation: Orientation::Strict, ..Target::default() };
        assert_eq!(validate(&cube, &strict).map_err(|f| f.kind), Err(FailureKind::ScaleMismatch));
        let vol = Target { volume: Some(10.0), ..Target::default() };
        assert_eq!(validate(&cube, &vol).map_err(|f| f.kind), Err(FailureKind::SemanticMismatch));
        let holes = Target { genus: Some(1), ..Target::default() };
        assert_eq!(validate(&cube, &holes).map_err(|f| f.kind), Err(FailureKind::SemanticMismatch));
        let budget = Target { max_triangles: 4, ..Target::default() };
        assert_eq!(validate(&cube, &budget).map_err(|f| f.kind), Err(FailureKind::InvalidSolid));
        let mut open = cube.clone();
        open.triangles.pop();
        assert_eq!(validate(&open, &Target::default()).map_err(|f| f.kind), Err(FailureKind::InvalidSolid));
        let mut inside_out = cube;
        for t in &mut inside_out.triangles {
            t.swap(1, 2);
        }
        assert_eq!(validate(&inside_out, &Target::default()).map_err(|f| f.kind), Err(FailureKind::InvalidSolid));
    }
}
