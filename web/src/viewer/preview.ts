// A small three.js view of one part's mesh (binary STL, metres) for the asset studio:
// lit, framed, turnable, with its bounding box size.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

/** The triangles of a binary STL; throws on a file that is not one. */
export function parseStl(buf: ArrayBuffer): THREE.BufferGeometry {
  const dv = new DataView(buf);
  if (buf.byteLength < 84) throw new Error('the mesh file is too short to be a binary STL');
  const n = dv.getUint32(80, true);
  if (84 + 50 * n !== buf.byteLength) throw new Error(`the mesh file holds ${buf.byteLength} bytes, not the ${84 + 50 * n} of ${n} triangles`);
  const pos = new Float32Array(n * 9);
  for (let t = 0; t < n; t++) {
    for (let k = 0; k < 9; k++) pos[9 * t + k] = dv.getFloat32(84 + 50 * t + 12 + 4 * k, true);
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
  g.computeVertexNormals();
  g.computeBoundingBox();
  return g;
}

export class PartPreview {
  private readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(40, 1, 0.001, 100);
  private readonly controls: OrbitControls;
  private mesh: THREE.Mesh | null = null;
  private raf = 0;
  readonly canvas: HTMLCanvasElement;

  constructor(private readonly host: HTMLElement) {
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'preview-canvas';
    host.append(this.canvas);
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.scene.background = new THREE.Color(0xeef1f5);
    this.camera.up.set(0, 0, 1);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x777777, 1.8));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(2, -3, 4);
    this.scene.add(sun);
    this.controls = new OrbitControls(this.camera, this.canvas);
    const loop = () => {
      this.raf = requestAnimationFrame(loop);
      const w = Math.max(1, this.host.clientWidth);
      const h = Math.max(1, this.host.clientHeight);
      if (this.canvas.width !== Math.floor(w * this.renderer.getPixelRatio())) {
        this.renderer.setSize(w, h, false);
        this.camera.aspect = w / h;
        this.camera.updateProjectionMatrix();
      }
      this.renderer.render(this.scene, this.camera);
    };
    loop();
  }

  /** Shows nothing (the part shown is no longer the one asked for). */
  clear(): void {
    if (this.mesh) {
      this.scene.remove(this.mesh);
      this.mesh.geometry.dispose();
      (this.mesh.material as THREE.Material).dispose();
      this.mesh = null;
    }
  }

  /** Whether a part is shown. */
  get showing(): boolean {
    return this.mesh !== null;
  }

  /** Shows a mesh; answers its size (x, y, z extent), metres. */
  show(geo: THREE.BufferGeometry): [number, number, number] {
    this.clear();
    const box = geo.boundingBox ?? new THREE.Box3().setFromBufferAttribute(geo.getAttribute('position') as THREE.BufferAttribute);
    const size = box.getSize(new THREE.Vector3());
    const center = box.getCenter(new THREE.Vector3());
    this.mesh = new THREE.Mesh(geo, new THREE.MeshStandardMaterial({ color: 0x9ea6b0, metalness: 0.3, roughness: 0.55 }));
    this.scene.add(this.mesh);
    const r = Math.max(size.x, size.y, size.z, 1e-3);
    this.camera.position.set(center.x + 1.6 * r, center.y - 2.0 * r, center.z + 1.3 * r);
    this.camera.near = r / 100;
    this.camera.far = r * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    return [size.x, size.y, size.z];
  }

  dispose(): void {
    cancelAnimationFrame(this.raf);
    this.controls.dispose();
    if (this.mesh) {
      this.mesh.geometry.dispose();
      (this.mesh.material as THREE.Material).dispose();
    }
    this.renderer.dispose();
    this.canvas.remove();
  }
}
