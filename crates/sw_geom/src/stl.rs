//! Binary STL, the mesh format MuJoCo, CadQuery and most CAD tools share.

use std::io::{self, Read, Write};

use crate::Mesh;

#[derive(Debug, thiserror::Error)]
pub enum StlError {
    #[error("STL is truncated: {0}")]
    Truncated(&'static str),
    #[error("STL declares {declared} triangles but holds {present}")]
    CountMismatch { declared: u32, present: usize },
    #[error("STL has no triangles")]
    Empty,
    #[error("STL holds a non-finite coordinate in triangle {0}")]
    NonFinite(usize),
    #[error(transparent)]
    Io(#[from] io::Error),
}

/// Writes `mesh` as binary STL. The 80-byte header carries `name` (truncated) so that
/// output is byte-for-byte reproducible.
pub fn write_stl<W: Write>(mut out: W, mesh: &Mesh, name: &str) -> io::Result<()> {
    let mut header = [b' '; 80];
    let label = format!("scenewright {name}");
    for (dst, src) in header.iter_mut().zip(label.bytes()) {
        *dst = src;
    }
    out.write_all(&header)?;
    out.write_all(&(mesh.triangles.len() as u32).to_le_bytes())?;
    let mut buf = Vec::with_capacity(mesh.triangles.len() * 50);
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.vertices[i as usize]);
        let n = normal(a, b, c);
        for v in [n, a, b, c] {
            for x in v {
                buf.extend_from_slice(&x.to_le_bytes());
            }
        }
        buf.extend_from_slice(&0u16.to_le_bytes());
    }
    out.write_all(&buf)
}

/// Reads binary STL, welding vertices that share an exact position.
pub fn read_stl<R: Read>(mut input: R) -> Result<Mesh, StlError> {
    let mut bytes = Vec::new();
    input.read_to_end(&mut bytes)?;
    if bytes.len() < 84 {
        return Err(StlError::Truncated("header"));
    }
    let declared = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]);
    let body = &bytes[84..];
    let present = body.len() / 50;
    if present != declared as usize {
        return Err(StlError::CountMismatch { declared, present });
    }
    if declared == 0 {
        return Err(StlError::Empty);
    }
    let mut mesh = Mesh::default();
    let mut weld = std::collections::HashMap::new();
    for (ti, rec) in body.chunks_exact(50).enumerate() {
        let mut tri = [0u32; 3];
        for (k, slot) in tri.iter_mut().enumerate() {
            let off = 12 + 12 * k;
            let v: [f32; 3] = std::array::from_fn(|j| {
                let o = off + 4 * j;
                f32::from_le_bytes([rec[o], rec[o + 1], rec[o + 2], rec[o + 3]])
            });
            if v.iter().any(|c| !c.is_finite()) {
                return Err(StlError::NonFinite(ti));
            }
            let next = mesh.vertices.len() as u32;
            *slot = *weld.entry(v.map(f32::to_bits)).or_insert_with(|| {
                mesh.vertices.push(v);
                next
            });
        }
        mesh.triangles.push(tri);
    }
    Ok(mesh)
}

fn normal(a: [f32; 3], b: [f32; 3], c: [f32; 3]) -> [f32; 3] {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 { n.map(|x| x / len) } else { [0.0, 0.0, 0.0] }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::box_mesh;

    #[test]
    fn round_trip_keeps_the_solid() {
        let m = box_mesh([0.1, 0.2, 0.3]);
        let mut bytes = Vec::new();
        write_stl(&mut bytes, &m, "box").unwrap();
        assert_eq!(bytes.len(), 84 + 50 * 12);
        let back = read_stl(bytes.as_slice()).unwrap();
        assert_eq!(back.triangles.len(), 12);
        assert_eq!(back.vertices.len(), 8);
        assert!(back.check().is_valid_solid());
    }

    #[test]
    fn truncated_and_lying_files_are_errors() {
        assert!(matches!(read_stl(&[0u8; 10][..]), Err(StlError::Truncated(_))));
        let mut bytes = vec![0u8; 84];
        bytes[80] = 5;
        assert!(matches!(read_stl(bytes.as_slice()), Err(StlError::CountMismatch { declared: 5, .. })));
    }
}
