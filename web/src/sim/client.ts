// The page's side of the MuJoCo worker: one worker for the whole app (the WASM module is
// compiled once), one scene loaded at a time, answers matched to requests by id so a
// slow load that was superseded is ignored.

import type { FromWorker, LoadTimings, ModelInfo, ToWorker } from './protocol';

export interface Loaded {
  model: ModelInfo;
  poses: Float64Array;
  timings: LoadTimings;
}

export interface Frame {
  time: number;
  poses: Float64Array;
  playing: boolean;
  realtime: number;
}

type Pending<T> = { resolve: (v: T) => void; reject: (e: Error) => void };

class Sim {
  private worker: Worker | null = null;
  private nextId = 1;
  private loads = new Map<number, Pending<Loaded>>();
  private benches = new Map<number, Pending<{ simSeconds: number; wallSeconds: number; steps: number }>>();
  private unloads = new Map<number, Pending<number>>();
  private current = 0;
  onFrame: ((f: Frame) => void) | null = null;
  onProgress: ((message: string) => void) | null = null;
  onError: ((message: string) => void) | null = null;

  /** Starts the worker (and MuJoCo's compilation) ahead of the first scene. */
  warm(): void {
    if (this.worker) return;
    this.worker = new Worker(new URL('../sim.worker.ts', import.meta.url), { type: 'module', name: 'mujoco' });
    this.worker.onmessage = (e: MessageEvent<FromWorker>) => this.receive(e.data);
    this.worker.onerror = (e: ErrorEvent) => {
      const message = `the MuJoCo worker failed: ${e.message || 'it could not start'}`;
      for (const p of this.loads.values()) p.reject(new Error(message));
      this.loads.clear();
      this.onError?.(message);
    };
  }

  private send(msg: ToWorker): void {
    this.warm();
    this.worker?.postMessage(msg);
  }

  private receive(m: FromWorker): void {
    switch (m.type) {
      case 'progress':
        if (m.id === this.current) this.onProgress?.(m.message);
        return;
      case 'loaded': {
        const p = this.loads.get(m.id);
        this.loads.delete(m.id);
        if (m.id === this.current) p?.resolve({ model: m.model, poses: m.poses, timings: m.timings });
        else p?.reject(new Error('superseded by another scene'));
        return;
      }
      case 'frame':
        this.onFrame?.({ time: m.time, poses: m.poses, playing: m.playing, realtime: m.realtime });
        return;
      case 'error': {
        const p = this.loads.get(m.id) ?? this.benches.get(m.id);
        this.loads.delete(m.id);
        this.benches.delete(m.id);
        if (p) p.reject(new Error(m.message));
        else this.onError?.(m.message);
        return;
      }
      case 'unloaded':
        this.unloads.get(m.id)?.resolve(m.heapBytes);
        this.unloads.delete(m.id);
        return;
      case 'bench':
        this.benches.get(m.id)?.resolve({ simSeconds: m.simSeconds, wallSeconds: m.wallSeconds, steps: m.steps });
        this.benches.delete(m.id);
        return;
    }
  }

  /** Loads a package's scene from the API (files listed by the scene's metadata). */
  load(base: string, token: string, files: string[], scene = 'scene.xml'): Promise<Loaded> {
    const id = this.nextId++;
    this.current = id;
    return new Promise((resolve, reject) => {
      this.loads.set(id, { resolve, reject });
      this.send({ type: 'load', id, base, token, files, scene });
    });
  }

  /** Frees the loaded scene; answers the WASM heap's size afterwards. */
  unload(): Promise<number> {
    const id = this.nextId++;
    this.current = id;
    return new Promise((resolve, reject) => {
      this.unloads.set(id, { resolve, reject });
      this.send({ type: 'unload', id });
    });
  }

  play(): void {
    this.send({ type: 'play' });
  }
  pause(): void {
    this.send({ type: 'pause' });
  }
  step(n = 1): void {
    this.send({ type: 'step', n });
  }
  reset(): void {
    this.send({ type: 'reset' });
  }
  speed(value: number): void {
    this.send({ type: 'speed', value });
  }

  /** Steps as fast as possible for `seconds` (the stepping benchmark). */
  bench(seconds: number): Promise<{ simSeconds: number; wallSeconds: number; steps: number }> {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.benches.set(id, { resolve, reject });
      this.send({ type: 'bench', id, seconds });
    });
  }
}

export const sim = new Sim();
