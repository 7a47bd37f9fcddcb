// three.js objects for MuJoCo geoms: every geom type the packages use (plane, box,
// sphere, capsule, cylinder, ellipsoid, mesh), their materials and textures. Geometry is
// made in the geom's own frame (MuJoCo's Z-up axes) and placed by the geom's pose in its
// body; bodies are moved each frame from the simulation.

import * as THREE from 'three';
import { GEOM, type GeomInfo, type MaterialInfo, type MeshInfo, type ModelInfo, type TextureInfo } from '../sim/protocol';

/** Planes MuJoCo calls infinite (size 0) are drawn this large, metres. */
const INFINITE_PLANE = 60;

/** Caches shared by every geom of one model; `dispose` frees all of it. */
export class Resources {
  private readonly geometries: THREE.BufferGeometry[] = [];
  private readonly materials: THREE.Material[] = [];
  private readonly textures = new Map<number, THREE.Texture>();
  private readonly meshGeometry = new Map<number, THREE.BufferGeometry>();
  private readonly primitive = new Map<string, THREE.BufferGeometry>();

  constructor(private readonly model: ModelInfo) {}

  keep<T extends THREE.BufferGeometry>(g: T): T {
    this.geometries.push(g);
    return g;
  }

  keepMaterial<T extends THREE.Material>(m: T): T {
    this.materials.push(m);
    return m;
  }

  texture(index: number): THREE.Texture | null {
    const t: TextureInfo | undefined = this.model.textures[index];
    if (!t || t.type === 2) return null;
    let tex = this.textures.get(index);
    if (!tex) {
      tex = new THREE.DataTexture(t.rgba, t.width, t.height, THREE.RGBAFormat);
      tex.wrapS = tex.wrapT = THREE.RepeatWrapping;
      tex.colorSpace = THREE.SRGBColorSpace;
      tex.magFilter = THREE.LinearFilter;
      tex.minFilter = THREE.LinearMipmapLinearFilter;
      tex.generateMipmaps = true;
      tex.needsUpdate = true;
      this.textures.set(index, tex);
    }
    return tex;
  }

  mesh(index: number): THREE.BufferGeometry | null {
    const m: MeshInfo | undefined = this.model.meshes[index];
    if (!m) return null;
    let g = this.meshGeometry.get(index);
    if (!g) {
      g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(m.positions, 3));
      if (m.normals) g.setAttribute('normal', new THREE.BufferAttribute(m.normals, 3));
      else g.computeVertexNormals();
      if (m.uvs) g.setAttribute('uv', new THREE.BufferAttribute(m.uvs, 2));
      g.computeBoundingSphere();
      this.meshGeometry.set(index, this.keep(g));
    }
    return g;
  }

  /** A primitive's geometry, shared between geoms of the same type and size. */
  shape(g: GeomInfo): THREE.BufferGeometry | null {
    const [a, b, c] = g.size;
    const key = `${g.type}:${a.toFixed(5)}:${b.toFixed(5)}:${c.toFixed(5)}`;
    const cached = this.primitive.get(key);
    if (cached) return cached;
    let geo: THREE.BufferGeometry | null;
    switch (g.type) {
      case GEOM.plane:
        geo = new THREE.PlaneGeometry(2 * (a || INFINITE_PLANE), 2 * (b || INFINITE_PLANE));
        break;
      case GEOM.box:
        geo = new THREE.BoxGeometry(2 * a, 2 * b, 2 * c);
        break;
      case GEOM.sphere:
        geo = new THREE.SphereGeometry(a, 24, 16);
        break;
      case GEOM.ellipsoid:
        geo = new THREE.SphereGeometry(1, 24, 16);
        geo.scale(a, b, c);
        break;
      case GEOM.capsule:
        // three.js builds along Y; MuJoCo's capsules and cylinders run along their Z.
        geo = new THREE.CapsuleGeometry(a, 2 * b, 6, 16);
        geo.rotateX(Math.PI / 2);
        break;
      case GEOM.cylinder:
        geo = new THREE.CylinderGeometry(a, a, 2 * b, 24);
        geo.rotateX(Math.PI / 2);
        break;
      default:
        geo = null;
    }
    if (geo) this.primitive.set(key, this.keep(geo));
    return geo;
  }

  dispose(): void {
    for (const g of this.geometries) g.dispose();
    for (const m of this.materials) m.dispose();
    for (const t of this.textures.values()) t.dispose();
    this.geometries.length = 0;
    this.materials.length = 0;
    this.textures.clear();
    this.meshGeometry.clear();
    this.primitive.clear();
  }
}

/** Materials by colour and texture, shared between geoms that look the same. */
export class MaterialCache {
  private readonly cache = new Map<string, THREE.MeshLambertMaterial | THREE.MeshPhongMaterial>();

  constructor(
    private readonly res: Resources,
    private readonly model: ModelInfo,
  ) {}

  for(g: GeomInfo): THREE.Material {
    const mat: MaterialInfo | undefined = g.mat >= 0 ? this.model.materials[g.mat] : undefined;
    // MuJoCo: a geom's own rgba wins unless it is the default and a material is set.
    const rgba = mat && isDefaultRgba(g.rgba) ? mat.rgba : g.rgba;
    const tex = mat && mat.tex >= 0 ? this.res.texture(mat.tex) : null;
    let repeat: [number, number] = mat ? mat.texrepeat : [1, 1];
    if (tex && mat?.texuniform && g.type === GEOM.plane) {
      // Per metre: the plane's full size times the repeat.
      repeat = [repeat[0] * 2 * (g.size[0] || INFINITE_PLANE), repeat[1] * 2 * (g.size[1] || INFINITE_PLANE)];
    }
    const key = `${rgba.map((v) => v.toFixed(3)).join(',')}|${tex ? mat?.tex : -1}|${repeat.join(',')}|${mat?.specular ?? 0}`;
    let m = this.cache.get(key);
    if (!m) {
      const color = new THREE.Color().setRGB(rgba[0], rgba[1], rgba[2], THREE.SRGBColorSpace);
      const transparent = rgba[3] < 0.999;
      const shiny = (mat?.specular ?? 0) > 0.3;
      const params = { color, transparent, opacity: rgba[3], depthWrite: !transparent, side: THREE.FrontSide };
      m = this.res.keepMaterial(shiny ? new THREE.MeshPhongMaterial({ ...params, shininess: 30 * (mat?.shininess ?? 0.5) }) : new THREE.MeshLambertMaterial(params));
      if (tex) {
        const t = tex.clone();
        t.repeat.set(repeat[0], repeat[1]);
        t.needsUpdate = true;
        m.map = t;
      }
      this.cache.set(key, m);
    }
    return m;
  }
}

function isDefaultRgba(c: readonly number[]): boolean {
  return Math.abs((c[0] ?? 0) - 0.5) < 1e-6 && Math.abs((c[1] ?? 0) - 0.5) < 1e-6 && Math.abs((c[2] ?? 0) - 0.5) < 1e-6 && (c[3] ?? 0) === 1;
}

/** A three.js mesh for a geom, placed in its body's frame; null for types not drawn. */
export function geomObject(g: GeomInfo, res: Resources, mats: MaterialCache): THREE.Mesh | null {
  const geo = g.type === GEOM.mesh ? res.mesh(g.mesh) : res.shape(g);
  if (!geo) return null;
  const mesh = new THREE.Mesh(geo, mats.for(g));
  mesh.position.set(g.pos[0], g.pos[1], g.pos[2]);
  mesh.quaternion.set(g.quat[1], g.quat[2], g.quat[3], g.quat[0]);
  mesh.matrixAutoUpdate = false;
  mesh.updateMatrix();
  return mesh;
}
