// The three.js view of a MuJoCo model: a group per body moved from the simulation's
// poses, a mesh per geom, Z up, geom groups switchable, the walls on the camera's side
// cut away, picking and a horizontal drag plane for moving objects. It draws only when
// something changed (poses, camera, selection), which keeps software WebGL cheap.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GEOM, type ModelInfo, POSE_STRIDE } from '../sim/protocol';
import { MaterialCache, Resources, geomObject } from './build';

THREE.Object3D.DEFAULT_UP.set(0, 0, 1);

/** MuJoCo's default visible geom groups: 0, 1 and 2. */
const DEFAULT_GROUPS = [true, true, true, false, false, false];

export interface Pick {
  body: number;
  root: number;
  point: THREE.Vector3;
}

interface Wall {
  mesh: THREE.Mesh;
  center: THREE.Vector3;
  normal: THREE.Vector3;
}

export class Viewer {
  readonly canvas: HTMLCanvasElement;
  private readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera: THREE.PerspectiveCamera;
  private readonly controls: OrbitControls;
  private readonly raycaster = new THREE.Raycaster();
  private readonly resize: ResizeObserver;
  private model: ModelInfo | null = null;
  private res: Resources | null = null;
  private root = new THREE.Group();
  private bodies: THREE.Group[] = [];
  /** Meshes per root body (an object or a robot), for picking and highlighting. */
  private byRoot = new Map<number, THREE.Mesh[]>();
  private walls: Wall[] = [];
  private groups = [...DEFAULT_GROUPS];
  private highlighted: number | null = null;
  private saved = new Map<THREE.Mesh, THREE.Material | THREE.Material[]>();
  private offsets = new Map<number, { dx: number; dy: number; dyaw: number }>();
  private poses: Float64Array | null = null;
  private dirty = true;
  private raf = 0;
  private disposed = false;
  /** performance.now() of the first frame drawn with a model, and frames drawn since. */
  firstFrameAt: number | null = null;
  frames = 0;
  onFirstFrame: (() => void) | null = null;

  constructor(private readonly container: HTMLElement) {
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'viewer-canvas';
    container.append(this.canvas);
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true, powerPreference: 'high-performance' });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.outputColorSpace = THREE.SRGBColorSpace;
    this.scene.background = new THREE.Color(0xdfe5ec);
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.05, 500);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.invalidate());
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8a80, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(-3, -5, 10);
    this.scene.add(sun);
    this.scene.add(this.root);
    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(container);
    this.fit();
    const loop = () => {
      if (this.disposed) return;
      this.raf = requestAnimationFrame(loop);
      if (this.dirty) this.draw();
    };
    loop();
  }

  private fit(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.invalidate();
  }

  invalidate(): void {
    this.dirty = true;
  }

  /** Replaces the model: every body, geom, material and texture of the old one is freed. */
  setModel(model: ModelInfo, poses: Float64Array): void {
    this.clear();
    this.model = model;
    this.res = new Resources(model);
    const mats = new MaterialCache(this.res, model);
    this.bodies = model.bodies.map((b, i) => {
      const g = new THREE.Group();
      g.name = b.name;
      g.userData.body = i;
      g.matrixAutoUpdate = false;
      this.root.add(g);
      return g;
    });
    model.geoms.forEach((g, i) => {
      const mesh = geomObject(g, this.res as Resources, mats);
      if (!mesh) return;
      mesh.name = g.name;
      mesh.userData.geom = i;
      mesh.userData.group = g.group;
      mesh.visible = this.groups[g.group] ?? false;
      this.bodies[g.body]?.add(mesh);
      const root = model.bodies[g.body]?.root ?? 0;
      if (root > 0) {
        const list = this.byRoot.get(root) ?? [];
        list.push(mesh);
        this.byRoot.set(root, list);
      }
      if (g.body === 0 && g.type === GEOM.box && g.name.startsWith('wall_')) this.walls.push(wallOf(mesh, g.size, g.pos));
    });
    this.frame(model);
    this.setPoses(poses);
  }

  /** Frames the model like MuJoCo's free camera (azimuth 120°, elevation −30°). */
  frame(model: ModelInfo): void {
    const c = new THREE.Vector3(...model.center);
    const dist = Math.max(1.5, model.extent * 2.1);
    const az = (120 * Math.PI) / 180;
    const el = (30 * Math.PI) / 180;
    // MuJoCo's azimuth is measured from +X towards +Y, the camera looking along it.
    const dir = new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), -Math.sin(el));
    this.camera.position.copy(c).addScaledVector(dir, -dist);
    this.camera.near = Math.max(0.01, dist / 500);
    this.camera.far = dist * 20;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(c);
    this.controls.update();
    this.invalidate();
  }

  /** Back to the first view of the whole scene. */
  resetCamera(): void {
    if (this.model) this.frame(this.model);
  }

  /**
   * Frames one object or robot (a root body) from the camera's current side: it fills the
   * view, the orbit turning about its centre. `false` when it has nothing drawn.
   */
  frameObject(root: number): boolean {
    const meshes = this.byRoot.get(root);
    if (!meshes?.length) return false;
    this.root.updateMatrixWorld(true);
    const box = new THREE.Box3();
    for (const m of meshes) box.expandByObject(m);
    if (box.isEmpty()) return false;
    const c = box.getCenter(new THREE.Vector3());
    const radius = Math.max(0.15, box.getSize(new THREE.Vector3()).length() / 2);
    const fov = (this.camera.fov * Math.PI) / 180;
    const dist = (radius / Math.sin(fov / 2)) * 1.15;
    const dir = this.camera.position.clone().sub(this.controls.target);
    if (dir.lengthSq() < 1e-9) dir.set(-1, -1, 1);
    this.camera.position.copy(c).addScaledVector(dir.normalize(), dist);
    this.camera.near = Math.max(0.005, dist / 500);
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(c);
    this.controls.update();
    this.invalidate();
    return true;
  }

  /** Where the camera is and looks (for the page's tests). */
  cameraState(): { position: [number, number, number]; target: [number, number, number] } {
    const p = this.camera.position;
    const t = this.controls.target;
    return { position: [p.x, p.y, p.z], target: [t.x, t.y, t.z] };
  }

  setPoses(p: Float64Array): void {
    this.poses = p;
    const q = new THREE.Quaternion();
    const turn = new THREE.Quaternion();
    const z = new THREE.Vector3(0, 0, 1);
    for (let b = 0; b < this.bodies.length; b++) {
      const g = this.bodies[b];
      if (!g) continue;
      const o = b * POSE_STRIDE;
      g.position.set(p[o] ?? 0, p[o + 1] ?? 0, p[o + 2] ?? 0);
      q.set(p[o + 4] ?? 0, p[o + 5] ?? 0, p[o + 6] ?? 0, p[o + 3] ?? 1);
      g.quaternion.copy(q);
      const root = this.model?.bodies[b]?.root ?? 0;
      const off = this.offsets.get(root);
      if (off) {
        // A body being dragged: turned about its root's origin and shifted with it.
        const r0 = (this.model && root * POSE_STRIDE) || 0;
        const origin = new THREE.Vector3(p[r0] ?? 0, p[r0 + 1] ?? 0, p[r0 + 2] ?? 0);
        turn.setFromAxisAngle(z, off.dyaw);
        g.position.sub(origin).applyQuaternion(turn).add(origin);
        g.position.x += off.dx;
        g.position.y += off.dy;
        g.quaternion.premultiply(turn);
      }
      g.updateMatrix();
    }
    this.root.updateMatrixWorld(true);
    this.invalidate();
  }

  /** Shows a dragged object shifted and turned before the server has placed it. */
  setOffset(root: number, dx: number, dy: number, dyaw: number): void {
    this.offsets.set(root, { dx, dy, dyaw });
    if (this.poses) this.setPoses(this.poses);
  }

  clearOffsets(): void {
    this.offsets.clear();
    if (this.poses) this.setPoses(this.poses);
  }

  setGroupVisible(group: number, on: boolean): void {
    this.groups[group] = on;
    this.root.traverse((o) => {
      if (o instanceof THREE.Mesh && o.userData.group === group) o.visible = on;
    });
    this.invalidate();
  }

  groupVisible(group: number): boolean {
    return this.groups[group] ?? false;
  }

  /** Tints the meshes of one object (or robot); null clears. */
  highlight(root: number | null): void {
    for (const [mesh, mat] of this.saved) mesh.material = mat;
    this.saved.clear();
    this.highlighted = root;
    if (root !== null) {
      for (const mesh of this.byRoot.get(root) ?? []) {
        this.saved.set(mesh, mesh.material);
        const m = (Array.isArray(mesh.material) ? mesh.material[0] : mesh.material)?.clone();
        if (m && 'emissive' in m && m.emissive instanceof THREE.Color) m.emissive.setRGB(0.55, 0.32, 0.0);
        if (m) mesh.material = m;
      }
    }
    this.invalidate();
  }

  private ndc(x: number, y: number): THREE.Vector2 {
    const r = this.canvas.getBoundingClientRect();
    return new THREE.Vector2(((x - r.left) / r.width) * 2 - 1, -((y - r.top) / r.height) * 2 + 1);
  }

  /** The object or robot under a screen point (walls, floor and cut-away walls excluded). */
  pick(x: number, y: number): Pick | null {
    this.raycaster.setFromCamera(this.ndc(x, y), this.camera);
    const targets: THREE.Object3D[] = [];
    for (const list of this.byRoot.values()) for (const m of list) if (m.visible) targets.push(m);
    const hit = this.raycaster.intersectObjects(targets, false)[0];
    if (!hit) return null;
    const body = (hit.object.parent?.userData.body as number | undefined) ?? 0;
    const root = this.model?.bodies[body]?.root ?? 0;
    return root > 0 ? { body, root, point: hit.point.clone() } : null;
  }

  /** Where a screen point's ray meets the horizontal plane at height z. */
  planePoint(x: number, y: number, z: number): THREE.Vector3 | null {
    this.raycaster.setFromCamera(this.ndc(x, y), this.camera);
    const out = new THREE.Vector3();
    return this.raycaster.ray.intersectPlane(new THREE.Plane(new THREE.Vector3(0, 0, 1), -z), out);
  }

  setControlsEnabled(on: boolean): void {
    this.controls.enabled = on;
  }

  /** The drawn world position of a body (for checks against the package). */
  bodyPosition(name: string): [number, number, number] | null {
    const i = this.model?.bodies.findIndex((b) => b.name === name) ?? -1;
    const g = i >= 0 ? this.bodies[i] : undefined;
    if (!g) return null;
    const v = new THREE.Vector3().setFromMatrixPosition(g.matrixWorld);
    return [v.x, v.y, v.z];
  }

  /** A body's origin on screen, in client pixels (null when behind the camera). */
  project(name: string): { x: number; y: number } | null {
    const p = this.bodyPosition(name);
    if (!p) return null;
    const v = new THREE.Vector3(...p).project(this.camera);
    if (v.z > 1) return null;
    const r = this.canvas.getBoundingClientRect();
    return { x: r.left + ((v.x + 1) / 2) * r.width, y: r.top + ((1 - v.y) / 2) * r.height };
  }

  /** The centre of an object's drawn meshes on screen (a better click target than its origin). */
  projectObject(root: number): { x: number; y: number } | null {
    const box = new THREE.Box3();
    for (const m of this.byRoot.get(root) ?? []) if (m.visible) box.expandByObject(m);
    if (box.isEmpty()) return null;
    const v = box.getCenter(new THREE.Vector3()).project(this.camera);
    const r = this.canvas.getBoundingClientRect();
    return { x: r.left + ((v.x + 1) / 2) * r.width, y: r.top + ((1 - v.y) / 2) * r.height };
  }

  private cutaway(): void {
    const cam = this.camera.position;
    for (const w of this.walls) {
      const side = cam.clone().sub(w.center).dot(w.normal);
      w.mesh.visible = side <= 0 && (this.groups[0] ?? true);
    }
  }

  private draw(): void {
    this.dirty = false;
    this.cutaway();
    this.renderer.render(this.scene, this.camera);
    if (this.model) {
      this.frames++;
      if (this.firstFrameAt === null) {
        this.firstFrameAt = performance.now();
        this.onFirstFrame?.();
      }
    }
  }

  private clear(): void {
    this.highlight(null);
    this.offsets.clear();
    for (const g of this.bodies) this.root.remove(g);
    this.bodies = [];
    this.byRoot.clear();
    this.walls = [];
    this.res?.dispose();
    this.res = null;
    this.model = null;
    this.firstFrameAt = null;
    this.frames = 0;
  }

  dispose(): void {
    this.disposed = true;
    cancelAnimationFrame(this.raf);
    this.resize.disconnect();
    this.controls.dispose();
    this.clear();
    this.renderer.dispose();
    this.renderer.forceContextLoss();
    this.canvas.remove();
  }

  /** GPU resources alive now (geometries, textures), to see that nothing leaks. */
  info(): { geometries: number; textures: number } {
    const m = this.renderer.info.memory;
    return { geometries: m.geometries, textures: m.textures };
  }

  get selected(): number | null {
    return this.highlighted;
  }
}

/** A wall's outward normal: its thinnest axis, pointing away from the room's centre. */
function wallOf(mesh: THREE.Mesh, size: readonly number[], pos: readonly number[]): Wall {
  const thinX = (size[0] ?? 0) < (size[1] ?? 0);
  const normal = thinX ? new THREE.Vector3(Math.sign(pos[0] ?? 1) || 1, 0, 0) : new THREE.Vector3(0, Math.sign(pos[1] ?? 1) || 1, 0);
  return { mesh, center: new THREE.Vector3(pos[0] ?? 0, pos[1] ?? 0, pos[2] ?? 0), normal };
}
