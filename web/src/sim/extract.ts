// Copies what the renderer needs out of a compiled MjModel: bodies, geoms, meshes,
// materials and textures, as plain arrays. Views into the WASM heap go stale when the
// heap grows, so every array is copied; boolean arrays are not read at all (their getters
// throw in the 3.14 bindings).

import type { MjModel } from '@mujoco/mujoco';
import type { BodyInfo, GeomInfo, MaterialInfo, MeshInfo, ModelInfo, TextureInfo } from './protocol';

/** MuJoCo's number of texture roles per material (mjNTEXROLE) and the RGB role. */
const NTEXROLE = 10;
const ROLE_RGB = 1;

export function f64(v: unknown, what: string): Float64Array {
  if (v instanceof Float64Array) return v;
  throw new Error(`MuJoCo's ${what} is not a Float64Array`);
}

export function f32(v: unknown, what: string): Float32Array {
  if (v instanceof Float32Array) return v;
  throw new Error(`MuJoCo's ${what} is not a Float32Array`);
}

export function i32(v: unknown, what: string): Int32Array {
  if (v instanceof Int32Array) return v;
  throw new Error(`MuJoCo's ${what} is not an Int32Array`);
}

function bytes(v: unknown, what: string): Uint8Array {
  if (v instanceof Uint8Array) return v;
  if (v instanceof Int8Array) return new Uint8Array(v.buffer, v.byteOffset, v.byteLength);
  throw new Error(`MuJoCo's ${what} is not a byte array`);
}

/** The model's names (a copy of its `names` buffer) and a reader of one name at an address. */
export function nameReader(m: MjModel): (adr: number) => string {
  const buf = bytes(m.names, 'names').slice();
  const dec = new TextDecoder();
  return (adr: number) => {
    if (adr < 0 || adr >= buf.length) return '';
    let end = adr;
    while (end < buf.length && buf[end] !== 0) end++;
    return dec.decode(buf.subarray(adr, end));
  };
}

function at(a: ArrayLike<number>, i: number): number {
  return a[i] ?? 0;
}

function vec3(a: ArrayLike<number>, i: number): [number, number, number] {
  return [at(a, 3 * i), at(a, 3 * i + 1), at(a, 3 * i + 2)];
}

function vec4(a: ArrayLike<number>, i: number): [number, number, number, number] {
  return [at(a, 4 * i), at(a, 4 * i + 1), at(a, 4 * i + 2), at(a, 4 * i + 3)];
}

function bodies(m: MjModel, name: (adr: number) => string): BodyInfo[] {
  const parent = i32(m.body_parentid, 'body_parentid');
  const adr = i32(m.name_bodyadr, 'name_bodyadr');
  const out: BodyInfo[] = [];
  for (let b = 0; b < m.nbody; b++) {
    const p = at(parent, b);
    // The ancestor whose parent is the world.
    let root = b;
    while (root > 0 && at(parent, root) !== 0) root = at(parent, root);
    out.push({ name: name(at(adr, b)), parent: p, root: b === 0 ? 0 : root });
  }
  return out;
}

function geoms(m: MjModel, name: (adr: number) => string): GeomInfo[] {
  const type = i32(m.geom_type, 'geom_type');
  const body = i32(m.geom_bodyid, 'geom_bodyid');
  const group = i32(m.geom_group, 'geom_group');
  const size = f64(m.geom_size, 'geom_size');
  const pos = f64(m.geom_pos, 'geom_pos');
  const quat = f64(m.geom_quat, 'geom_quat');
  const rgba = f32(m.geom_rgba, 'geom_rgba');
  const mat = i32(m.geom_matid, 'geom_matid');
  const data = i32(m.geom_dataid, 'geom_dataid');
  const adr = i32(m.name_geomadr, 'name_geomadr');
  const out: GeomInfo[] = [];
  for (let g = 0; g < m.ngeom; g++) {
    const t = at(type, g);
    out.push({
      name: name(at(adr, g)),
      type: t,
      body: at(body, g),
      group: at(group, g),
      size: vec3(size, g),
      pos: vec3(pos, g),
      quat: vec4(quat, g),
      rgba: vec4(rgba, g),
      mat: at(mat, g),
      mesh: t === 7 ? at(data, g) : -1,
    });
  }
  return out;
}

function meshes(m: MjModel): MeshInfo[] {
  if (m.nmesh === 0) return [];
  const vert = f32(m.mesh_vert, 'mesh_vert');
  const vertadr = i32(m.mesh_vertadr, 'mesh_vertadr');
  const face = i32(m.mesh_face, 'mesh_face');
  const faceadr = i32(m.mesh_faceadr, 'mesh_faceadr');
  const facenum = i32(m.mesh_facenum, 'mesh_facenum');
  const normal = m.nmeshnormal > 0 ? f32(m.mesh_normal, 'mesh_normal') : null;
  const normaladr = i32(m.mesh_normaladr, 'mesh_normaladr');
  const facenormal = m.nmeshnormal > 0 ? i32(m.mesh_facenormal, 'mesh_facenormal') : null;
  const tc = m.nmeshtexcoord > 0 ? f32(m.mesh_texcoord, 'mesh_texcoord') : null;
  const tcadr = i32(m.mesh_texcoordadr, 'mesh_texcoordadr');
  const facetc = m.nmeshtexcoord > 0 ? i32(m.mesh_facetexcoord, 'mesh_facetexcoord') : null;
  const out: MeshInfo[] = [];
  for (let k = 0; k < m.nmesh; k++) {
    const v0 = at(vertadr, k);
    const f0 = at(faceadr, k);
    const nf = at(facenum, k);
    const n0 = at(normaladr, k);
    const t0 = at(tcadr, k);
    const positions = new Float32Array(nf * 9);
    const normals = normal && facenormal && n0 >= 0 ? new Float32Array(nf * 9) : null;
    const uvs = tc && facetc && t0 >= 0 ? new Float32Array(nf * 6) : null;
    for (let f = 0; f < nf; f++) {
      for (let c = 0; c < 3; c++) {
        const fi = 3 * (f0 + f) + c;
        const v = v0 + at(face, fi);
        const o = 9 * f + 3 * c;
        positions[o] = at(vert, 3 * v);
        positions[o + 1] = at(vert, 3 * v + 1);
        positions[o + 2] = at(vert, 3 * v + 2);
        if (normals && normal && facenormal) {
          const n = n0 + at(facenormal, fi);
          normals[o] = at(normal, 3 * n);
          normals[o + 1] = at(normal, 3 * n + 1);
          normals[o + 2] = at(normal, 3 * n + 2);
        }
        if (uvs && tc && facetc) {
          const t = t0 + at(facetc, fi);
          uvs[6 * f + 2 * c] = at(tc, 2 * t);
          uvs[6 * f + 2 * c + 1] = at(tc, 2 * t + 1);
        }
      }
    }
    out.push({ positions, normals, uvs });
  }
  return out;
}

/** Materials whose MJCF says `texuniform="true"` (the 3.14 bindings cannot read the flag). */
function uniformNames(xml: string): Set<string> {
  const out = new Set<string>();
  const re = /<material\b([^>]*)>/g;
  for (let m = re.exec(xml); m; m = re.exec(xml)) {
    const attrs = m[1] ?? '';
    const name = /\bname\s*=\s*"([^"]*)"/.exec(attrs)?.[1];
    if (name && /\btexuniform\s*=\s*"true"/.test(attrs)) out.add(name);
  }
  return out;
}

function materials(m: MjModel, name: (adr: number) => string, xml: string): MaterialInfo[] {
  if (m.nmat === 0) return [];
  const uniform = uniformNames(xml);
  const adr = i32(m.name_matadr, 'name_matadr');
  const rgba = f32(m.mat_rgba, 'mat_rgba');
  const texid = i32(m.mat_texid, 'mat_texid');
  const repeat = f32(m.mat_texrepeat, 'mat_texrepeat');
  const spec = f32(m.mat_specular, 'mat_specular');
  const shin = f32(m.mat_shininess, 'mat_shininess');
  const refl = f32(m.mat_reflectance, 'mat_reflectance');
  const perRole = texid.length === m.nmat * NTEXROLE;
  const out: MaterialInfo[] = [];
  for (let i = 0; i < m.nmat; i++) {
    out.push({
      rgba: vec4(rgba, i),
      tex: perRole ? at(texid, i * NTEXROLE + ROLE_RGB) : at(texid, i),
      texrepeat: [at(repeat, 2 * i), at(repeat, 2 * i + 1)],
      // mat_texuniform's getter throws in the 3.14 bindings: read from the MJCF instead.
      texuniform: uniform.has(name(at(adr, i))),
      specular: at(spec, i),
      shininess: at(shin, i),
      reflectance: at(refl, i),
    });
  }
  return out;
}

function textures(m: MjModel): TextureInfo[] {
  if (m.ntex === 0) return [];
  const w = i32(m.tex_width, 'tex_width');
  const h = i32(m.tex_height, 'tex_height');
  const type = i32(m.tex_type, 'tex_type');
  const nch = i32(m.tex_nchannel, 'tex_nchannel');
  const adr = i32(m.tex_adr, 'tex_adr');
  const data = bytes(m.tex_data, 'tex_data');
  const out: TextureInfo[] = [];
  for (let t = 0; t < m.ntex; t++) {
    const width = at(w, t);
    const height = at(h, t);
    const ch = at(nch, t);
    const a0 = at(adr, t);
    // A cube map stores six faces one under the other: the first face serves as a 2-D texture.
    const rows = at(type, t) === 0 ? height : Math.min(height, width);
    const rgba = new Uint8Array(width * rows * 4);
    for (let p = 0; p < width * rows; p++) {
      for (let c = 0; c < 4; c++) {
        rgba[4 * p + c] = c < ch ? at(data, a0 + p * ch + c) : c === 3 ? 255 : at(data, a0 + p * ch);
      }
    }
    out.push({ width, height: rows, type: at(type, t), rgba });
  }
  return out;
}

/** Everything the renderer needs from a model. */
export function extractModel(m: MjModel, xml: string): ModelInfo {
  const name = nameReader(m);
  const keyAdr = i32(m.name_keyadr, 'name_keyadr');
  let hasHome = false;
  for (let k = 0; k < m.nkey; k++) if (name(at(keyAdr, k)) === 'home') hasHome = true;
  // `stat` and `opt` hand out a new handle on every read; each is deleted here.
  const stat = m.stat;
  const opt = m.opt;
  try {
    const center = f64(stat.center, 'stat.center');
    return {
      bodies: bodies(m, name),
      geoms: geoms(m, name),
      meshes: meshes(m),
      materials: materials(m, name, xml),
      textures: textures(m),
      timestep: opt.timestep,
      extent: stat.extent,
      center: [at(center, 0), at(center, 1), at(center, 2)],
      hasHome,
      nq: m.nq,
      nu: m.nu,
    };
  } finally {
    stat.delete();
    opt.delete();
  }
}

/** The index of the keyframe named `home`, or -1. */
export function homeKey(m: MjModel): number {
  const name = nameReader(m);
  const keyAdr = i32(m.name_keyadr, 'name_keyadr');
  for (let k = 0; k < m.nkey; k++) if (name(at(keyAdr, k)) === 'home') return k;
  return -1;
}
