//! Reading the meshes CAD code produces: binary STL (CadQuery/OCCT, OpenSCAD with
//! `binstl`) or ASCII STL, vertices welded by exact position, with a size limit and a
//! refusal of anything but a regular file (the job that wrote it was untrusted).

use std::collections::HashMap;
use std::io::Read;
use std::path::Path;

use sw_geom::Mesh;

/// Why a mesh file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum MeshFileError {
    #[error("{path}: {message}")]
    Unreadable { path: String, message: String },
    #[error("{path}: larger than {limit} bytes")]
    TooLarge { path: String, limit: u64 },
    #[error("{path}: {source}")]
    Stl { path: String, source: sw_geom::StlError },
    #[error("{path}: ASCII STL: {message}")]
    Ascii { path: String, message: String },
}

/// Reads an STL file the sandbox wrote: a regular file (not a link), at most `limit`
/// bytes, binary or ASCII.
pub fn read_untrusted_stl(path: &Path, limit: u64) -> Result<Mesh, MeshFileError> {
    let p = path.display().to_string();
    let meta = std::fs::symlink_metadata(path)
        .map_err(|e| MeshFileError::Unreadable { path: p.clone(), message: e.to_string() })?;
    if !meta.file_type().is_file() {
        return Err(MeshFileError::Unreadable { path: p, message: "not a regular file".into() });
    }
    if meta.len() > limit {
        return Err(MeshFileError::TooLarge { path: p, limit });
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    std::fs::File::open(path)
        .and_then(|f| f.take(limit + 1).read_to_end(&mut bytes))
        .map_err(|e| MeshFileError::Unreadable { path: p.clone(), message: e.to_string() })?;
    parse_stl(&bytes).map_err(|e| match e {
        StlParseError::Binary(source) => MeshFileError::Stl { path: p, source },
        StlParseError::Ascii(message) => MeshFileError::Ascii { path: p, message },
    })
}

#[derive(Debug)]
pub enum StlParseError {
    Binary(sw_geom::StlError),
    Ascii(String),
}

/// Parses binary or ASCII STL bytes.
pub fn parse_stl(bytes: &[u8]) -> Result<Mesh, StlParseError> {
    if looks_ascii(bytes) {
        return parse_ascii(bytes).map_err(StlParseError::Ascii);
    }
    sw_geom::read_stl(bytes).map_err(StlParseError::Binary)
}

/// ASCII STL starts with `solid` and says `facet` soon after; binary STL can start with
/// `solid` too (in its free-form header), so the size decides when in doubt.
fn looks_ascii(bytes: &[u8]) -> bool {
    if !bytes.starts_with(b"solid") {
        return false;
    }
    if bytes.len() >= 84 {
        let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        if 84 + 50 * n == bytes.len() {
            return false;
        }
    }
    let head = &bytes[..bytes.len().min(512)];
    head.windows(5).any(|w| w == b"facet") || head.windows(8).any(|w| w == b"endsolid")
}

fn parse_ascii(bytes: &[u8]) -> Result<Mesh, String> {
    let text = std::str::from_utf8(bytes).map_err(|_| "not UTF-8".to_string())?;
    let mut mesh = Mesh::default();
    let mut weld: HashMap<[u32; 3], u32> = HashMap::new();
    let mut corners: Vec<u32> = Vec::with_capacity(3);
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("vertex") => {
                let mut v = [0f32; 3];
                for c in &mut v {
                    *c = words
                        .next()
                        .and_then(|w| w.parse::<f32>().ok())
                        .filter(|x| x.is_finite())
                        .ok_or_else(|| format!("line {}: bad vertex", n + 1))?;
                }
                let next = mesh.vertices.len() as u32;
                let id = *weld.entry(v.map(f32::to_bits)).or_insert_with(|| {
                    mesh.vertices.push(v);
                    next
                });
                corners.push(id);
            }
            Some("endloop") => {
                if corners.len() != 3 {
                    return Err(format!("line {}: a facet with {} vertices", n + 1, corners.len()));
                }
                mesh.triangles.push([corners[0], corners[1], corners[2]]);
                corners.clear();
            }
            _ => {}
        }
    }
    if mesh.triangles.is_empty() {
        return Err("no triangles".into());
    }
    Ok(mesh)
}

/// The mesh scaled uniformly (millimetres to metres: 0.001).
pub fn scaled(mesh: &Mesh, factor: f64) -> Mesh {
    Mesh {
        vertices: mesh.vertices.iter().map(|v| v.map(|c| (f64::from(c) * factor) as f32)).collect(),
        triangles: mesh.triangles.clone(),
    }
}

/// Binary STL bytes, in metres, of a mesh in millimetres.
pub fn stl_bytes_mm_as_m(mesh_mm: &Mesh, name: &str) -> Vec<u8> {
    let mut bytes = Vec::new();
    // Writing into a Vec cannot fail.
    let _ = sw_geom::write_stl(&mut bytes, &scaled(mesh_mm, 1e-3), name);
    bytes
}

/// Removes triangles whose corners are not three distinct vertices (CAD kernels leave
/// them at the poles of spheres and cones). Returns how many were removed.
pub fn drop_collapsed_triangles(mesh: &mut Mesh) -> usize {
    let before = mesh.triangles.len();
    mesh.triangles.retain(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    before - mesh.triangles.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_and_binary_stl_read_the_same_solid() {
        let cube = sw_geom::box_mesh([0.5, 0.5, 0.5]);
        let mut bin = Vec::new();
        sw_geom::write_stl(&mut bin, &cube, "solid cube").expect("write to a Vec");
        let from_bin = parse_stl(&bin).expect("binary");
        let mut ascii = String::from("solid cube\n");
        for t in &cube.triangles {
            ascii.push_str(" facet normal 0 0 0\n  outer loop\n");
            for &i in t {
                let v = cube.vertices[i as usize];
                ascii.push_str(&format!("   vertex {} {} {}\n", v[0], v[1], v[2]));
            }
            ascii.push_str("  endloop\n endfacet\n");
        }
        ascii.push_str("endsolid cube\n");
        let from_ascii = parse_stl(ascii.as_bytes()).expect("ascii");
        assert_eq!(from_bin.triangles.len(), 12);
        assert_eq!(from_ascii.triangles.len(), 12);
        assert!(from_ascii.check().is_valid_solid());
        assert!((from_ascii.volume() - from_bin.volume()).abs() < 1e-9);
    }

    #[test]
    fn broken_ascii_is_an_error() {
        assert!(parse_stl(b"solid x\n facet normal 0 0 0\n outer loop\n vertex 0 0\n endloop\n").is_err());
    }
}
