// What the page exposes for its end-to-end test and benchmarks (`window.__sw`): when the
// scene's first frame was drawn, where bodies are drawn, and the stepping benchmark. It
// reads the same objects the user sees; it changes nothing.

export interface Probe {
  /** performance.now() when the viewer page started loading the scene, and its first frame. */
  loadStartedAt: number | null;
  firstFrameAt: number | null;
  /** The worker's load timings (fetch, compile, extract). */
  timings: Record<string, number> | null;
  /** Every body's name, in MuJoCo's order. */
  bodies: () => string[];
  /** The drawn world position of a body by name. */
  bodyPosition: (name: string) => [number, number, number] | null;
  /** Client coordinates of an object's drawn centre, to click or drag it. */
  objectOnScreen: (name: string) => { x: number; y: number } | null;
  /** Steps as fast as possible for `seconds`: simulated seconds per wall second. */
  bench: (seconds: number) => Promise<{ simSeconds: number; wallSeconds: number; steps: number }>;
  /** Frees the loaded scene; the WASM heap's size afterwards, bytes. */
  unload: () => Promise<number>;
  /** GPU resources the viewer holds now. */
  renderInfo: () => { geometries: number; textures: number };
  /** The last real-time factor the worker measured while playing. */
  realtime: number;
  /** Where the viewer's camera is and looks. */
  camera: () => { position: [number, number, number]; target: [number, number, number] };
}

declare global {
  interface Window {
    __sw?: Partial<Probe>;
  }
}

export function probe(): Partial<Probe> {
  window.__sw ??= {};
  return window.__sw;
}
