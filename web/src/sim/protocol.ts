// Messages between the page and the MuJoCo worker (sim.worker.ts). Everything the
// renderer needs is copied out of the WASM heap into plain arrays: views into the heap go
// stale when it grows, so nothing here points into it.

/** MuJoCo's geom types (mjtGeom) that packages use. */
export const GEOM = { plane: 0, hfield: 1, sphere: 2, capsule: 3, ellipsoid: 4, cylinder: 5, box: 6, mesh: 7 } as const;

export interface GeomInfo {
  name: string;
  type: number;
  body: number;
  group: number;
  size: [number, number, number];
  /** In its body's frame. */
  pos: [number, number, number];
  /** w, x, y, z (MuJoCo's order), in its body's frame. */
  quat: [number, number, number, number];
  rgba: [number, number, number, number];
  /** Material index or -1. */
  mat: number;
  /** Mesh index or -1. */
  mesh: number;
}

export interface BodyInfo {
  name: string;
  parent: number;
  /** The body under the world this one belongs to (an object or a robot's base). */
  root: number;
}

export interface MeshInfo {
  /** Three floats per corner of every triangle (unindexed, so normals and UVs can differ per face). */
  positions: Float32Array;
  normals: Float32Array | null;
  uvs: Float32Array | null;
}

export interface MaterialInfo {
  rgba: [number, number, number, number];
  /** Texture index (its RGB role) or -1. */
  tex: number;
  texrepeat: [number, number];
  texuniform: boolean;
  specular: number;
  shininess: number;
  reflectance: number;
}

export interface TextureInfo {
  width: number;
  height: number;
  /** 0 2-D, 1 cube, 2 skybox. */
  type: number;
  /** RGBA, width × height (for a cube map: its first face). */
  rgba: Uint8Array;
}

export interface ModelInfo {
  bodies: BodyInfo[];
  geoms: GeomInfo[];
  meshes: MeshInfo[];
  materials: MaterialInfo[];
  textures: TextureInfo[];
  timestep: number;
  /** Model statistics, for framing the camera. */
  extent: number;
  center: [number, number, number];
  hasHome: boolean;
  nq: number;
  nu: number;
}

/** Per body: x, y, z, then the quaternion w, x, y, z (MuJoCo's xpos and xquat). */
export const POSE_STRIDE = 7;

export interface LoadTimings {
  fetchMs: number;
  compileMs: number;
  extractMs: number;
  bytes: number;
  files: number;
  /** OBJ meshes read by the worker and handed to MuJoCo as STL (0: loaded as they are). */
  converted: number;
}

export type ToWorker =
  | { type: 'load'; id: number; base: string; token: string; files: string[]; scene: string }
  | { type: 'play' }
  | { type: 'pause' }
  | { type: 'step'; n: number }
  | { type: 'reset' }
  | { type: 'speed'; value: number }
  | { type: 'unload'; id: number }
  | { type: 'bench'; id: number; seconds: number };

export type FromWorker =
  | { type: 'progress'; id: number; message: string }
  | { type: 'loaded'; id: number; model: ModelInfo; poses: Float64Array; timings: LoadTimings }
  | { type: 'frame'; time: number; poses: Float64Array; playing: boolean; realtime: number }
  | { type: 'error'; id: number; message: string }
  | { type: 'unloaded'; id: number; heapBytes: number }
  | { type: 'bench'; id: number; simSeconds: number; wallSeconds: number; steps: number };
