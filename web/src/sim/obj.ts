// Wavefront OBJ meshes to binary STL, for the worker's fast path. MuJoCo 3.14's OBJ reader
// is slow in WebAssembly (robosuite's Panda: 38 MB of OBJ text, 3.7 s to compile, against
// 0.6 s to read here plus 0.4 s for MuJoCo to take the same triangles as STL). The
// triangles are the same, so geometry, volume, inertia and collision hulls are the same;
// only the OBJ's texture coordinates are dropped, and the worker converts a mesh only
// when the scene has no image textures that could use them.

/** The triangles of an OBJ as binary STL, or null when the text is not a mesh this reads. */
export function objToStl(text: string): Uint8Array | null {
  const verts: number[] = [];
  const tris: number[] = [];
  let lineStart = 0;
  const n = text.length;
  const idx: number[] = [];
  while (lineStart < n) {
    let lineEnd = text.indexOf('\n', lineStart);
    if (lineEnd < 0) lineEnd = n;
    const c0 = text.charCodeAt(lineStart);
    const c1 = text.charCodeAt(lineStart + 1);
    // 'v ' and 'f ' lines only (normals, texture coordinates, groups and materials are skipped).
    if (c0 === 118 && (c1 === 32 || c1 === 9)) {
      const parts = text.slice(lineStart + 2, lineEnd).trim().split(/\s+/);
      const x = Number(parts[0]);
      const y = Number(parts[1]);
      const z = Number(parts[2]);
      if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) return null;
      verts.push(x, y, z);
    } else if (c0 === 102 && (c1 === 32 || c1 === 9)) {
      const parts = text.slice(lineStart + 2, lineEnd).trim().split(/\s+/);
      idx.length = 0;
      const nv = verts.length / 3;
      for (const p of parts) {
        const slash = p.indexOf('/');
        let i = parseInt(slash >= 0 ? p.slice(0, slash) : p, 10);
        if (!Number.isInteger(i) || i === 0) return null;
        i = i > 0 ? i - 1 : nv + i;
        if (i < 0 || i >= nv) return null;
        idx.push(i);
      }
      // A polygon becomes a fan, as MuJoCo's reader triangulates it.
      for (let k = 1; k + 1 < idx.length; k++) tris.push(idx[0] ?? 0, idx[k] ?? 0, idx[k + 1] ?? 0);
    }
    lineStart = lineEnd + 1;
  }
  const nt = tris.length / 3;
  if (nt === 0) return null;
  const buf = new ArrayBuffer(84 + 50 * nt);
  const dv = new DataView(buf);
  dv.setUint32(80, nt, true);
  for (let t = 0; t < nt; t++) {
    const o = 84 + 50 * t;
    // The facet normal is left zero: MuJoCo computes normals itself.
    for (let c = 0; c < 3; c++) {
      const v = tris[3 * t + c] ?? 0;
      for (let a = 0; a < 3; a++) dv.setFloat32(o + 12 + 12 * c + 4 * a, verts[3 * v + a] ?? 0, true);
    }
  }
  return new Uint8Array(buf);
}

/**
 * Rewrites `file="….obj"` of the scene's meshes to the converted `….obj.stl` files.
 * Returns the new XML and the converted files, or null to load the package as it is.
 */
export function fastMeshes(xml: string, files: Map<string, Uint8Array>, meshdir: string): { xml: string; converted: Map<string, Uint8Array> } | null {
  // An image texture could use the OBJ's texture coordinates: then nothing is converted.
  if (/<texture\b[^>]*\bfile\s*=/.test(xml)) return null;
  const converted = new Map<string, Uint8Array>();
  const dec = new TextDecoder();
  const out = xml.replace(/(<mesh\b[^>]*\bfile\s*=\s*")([^"]+\.obj)(")/gi, (whole, pre: string, file: string, post: string) => {
    const path = meshdir ? `${meshdir}/${file}` : file;
    const bytes = files.get(path);
    if (!bytes) return whole;
    const stl = objToStl(dec.decode(bytes));
    if (!stl) return whole;
    converted.set(`${path}.stl`, stl);
    return `${pre}${file}.stl${post}`;
  });
  return converted.size ? { xml: out, converted } : null;
}
