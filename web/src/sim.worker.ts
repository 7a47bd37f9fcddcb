// MuJoCo (the official WebAssembly build) in a module Worker: fetches a package's files
// into the WASM file system, compiles scene.xml, resets to the `home` keyframe and steps
// it in real time, posting the bodies' poses to the page. The page stays responsive while
// a robot scene compiles. This module owns every MuJoCo handle it makes and deletes each.

import loadMujoco, { type MainModule, type MjData, type MjModel } from '@mujoco/mujoco';
import { extractModel, f64, homeKey } from './sim/extract';
import { fastMeshes } from './sim/obj';
import { type FromWorker, POSE_STRIDE, type ToWorker } from './sim/protocol';

interface Loaded {
  id: number;
  root: string;
  model: MjModel;
  data: MjData;
  home: number;
}

const ctx = self as unknown as DedicatedWorkerGlobalScope;
const ROOT = '/pkg';
let mujoco: Promise<MainModule> | null = null;
/** The newest load asked for; an older one still fetching stops before compiling. */
let latestLoad = 0;
/** Loads and unloads run one after another (each frees what the one before made). */
let queue: Promise<void> = Promise.resolve();
let current: Loaded | null = null;
let playing = false;
let speed = 1;
let timer: ReturnType<typeof setTimeout> | null = null;
/** Simulated and wall time over the last second of play, for the real-time factor. */
let window0 = { wall: 0, sim: 0 };
let realtime = 0;

function post(msg: FromWorker, transfer: Transferable[] = []): void {
  ctx.postMessage(msg, transfer);
}

function engine(): Promise<MainModule> {
  mujoco ??= loadMujoco();
  return mujoco;
}

function message(e: unknown): string {
  if (e instanceof Error) return e.message;
  if (typeof e === 'string') return e;
  return 'MuJoCo failed (no message)';
}

/** The bodies' poses now (a copy: the heap's views go stale when it grows). */
function poses(l: Loaded): Float64Array {
  const xpos = f64(l.data.xpos, 'xpos');
  const xquat = f64(l.data.xquat, 'xquat');
  const n = l.model.nbody;
  const out = new Float64Array(n * POSE_STRIDE);
  for (let b = 0; b < n; b++) {
    for (let k = 0; k < 3; k++) out[b * POSE_STRIDE + k] = xpos[3 * b + k] ?? 0;
    for (let k = 0; k < 4; k++) out[b * POSE_STRIDE + 3 + k] = xquat[4 * b + k] ?? 0;
  }
  return out;
}

function removeTree(fs: MainModule['FS'], path: string): void {
  let entries: unknown;
  try {
    entries = fs.readdir(path);
  } catch {
    return;
  }
  if (!Array.isArray(entries)) return;
  for (const e of entries) {
    if (typeof e !== 'string' || e === '.' || e === '..') continue;
    const p = `${path}/${e}`;
    const st: unknown = fs.stat(p, undefined);
    const mode = typeof st === 'object' && st !== null && 'mode' in st && typeof st.mode === 'number' ? st.mode : 0;
    if (fs.isDir(mode)) removeTree(fs, p);
    else fs.unlink(p);
  }
  fs.rmdir(path);
}

function release(mj: MainModule): void {
  stop();
  if (!current) return;
  current.data.delete();
  current.model.delete();
  removeTree(mj.FS, current.root);
  current = null;
}

/** The WASM heap's size now (it grows and never shrinks; flat over loads means no leak). */
function heapBytes(mj: MainModule): number {
  const probe = new mj.DoubleBuffer(1);
  try {
    return f64(probe.GetView(), 'probe').buffer.byteLength;
  } finally {
    probe.delete();
  }
}

async function fetchAll(base: string, token: string, files: string[], id: number): Promise<Map<string, Uint8Array>> {
  const out = new Map<string, Uint8Array>();
  let next = 0;
  let done = 0;
  const headers = { authorization: `Bearer ${token}` };
  const one = async (): Promise<void> => {
    while (next < files.length) {
      const f = files[next++];
      if (f === undefined) return;
      const r = await fetch(`${base}/${f.split('/').map(encodeURIComponent).join('/')}`, { headers });
      if (!r.ok) throw new Error(`${f}: the server answered ${r.status}`);
      out.set(f, new Uint8Array(await r.arrayBuffer()));
      done++;
      if (done % 20 === 0 || done === files.length) post({ type: 'progress', id, message: `fetched ${done} of ${files.length} files` });
    }
  };
  await Promise.all(Array.from({ length: Math.min(8, files.length) }, one));
  return out;
}

async function load(msg: Extract<ToWorker, { type: 'load' }>): Promise<void> {
  const mj = await engine();
  release(mj);
  const t0 = performance.now();
  const wanted = msg.files.filter((f) => f.endsWith('.xml') || f.startsWith('assets/'));
  const data = await fetchAll(msg.base, msg.token, wanted, msg.id);
  const t1 = performance.now();
  if (msg.id !== latestLoad) throw new Error('superseded by another scene');
  // One root for every scene: MuJoCo keeps decoded meshes in an asset cache keyed by path,
  // and package paths name their content (meshes are content-addressed, robot files are
  // the model's own), so the same path is the same bytes — a fresh root per load would
  // fill the cache with copies (the heap grew ~60 MB per robot-pack load).
  const root = ROOT;
  const xml = new TextDecoder().decode(data.get(msg.scene) ?? new Uint8Array());
  const meshdir = (/<compiler\b[^>]*\bmeshdir\s*=\s*"([^"]*)"/.exec(xml)?.[1] ?? '').replace(/\/+$/, '');
  const fast = fastMeshes(xml, data, meshdir);
  const sceneDir = msg.scene.includes('/') ? msg.scene.slice(0, msg.scene.lastIndexOf('/') + 1) : '';
  const fastScene = `${sceneDir}.fast-${msg.scene.slice(sceneDir.length)}`;
  let bytes = 0;
  const write = (path: string, content: Uint8Array) => {
    const full = `${root}/${path}`;
    mj.FS.mkdirTree(full.slice(0, full.lastIndexOf('/')), undefined);
    mj.FS.writeFile(full, content, undefined);
  };
  for (const [path, content] of data) {
    write(path, content);
    bytes += content.byteLength;
  }
  if (fast) {
    for (const [path, content] of fast.converted) write(path, content);
    write(fastScene, new TextEncoder().encode(fast.xml));
  }
  post({ type: 'progress', id: msg.id, message: 'compiling in MuJoCo' });
  let model: MjModel | null = null;
  let usedFast = false;
  if (fast) {
    try {
      model = mj.MjModel.from_xml_path(`${root}/${fastScene}`);
      usedFast = true;
    } catch {
      // The package as it is, below.
      model = null;
    }
  }
  try {
    model ??= mj.MjModel.from_xml_path(`${root}/${msg.scene}`);
  } catch (e) {
    removeTree(mj.FS, root);
    throw new Error(`MuJoCo 3.14 could not compile ${msg.scene}: ${message(e)}`, { cause: e });
  }
  const d = new mj.MjData(model);
  const home = homeKey(model);
  current = { id: msg.id, root, model, data: d, home };
  reset(mj);
  const t2 = performance.now();
  const info = extractModel(model, xml);
  const p = poses(current);
  const t3 = performance.now();
  post(
    {
      type: 'loaded',
      id: msg.id,
      model: info,
      poses: p,
      timings: { fetchMs: t1 - t0, compileMs: t2 - t1, extractMs: t3 - t2, bytes, files: data.size, converted: usedFast ? (fast?.converted.size ?? 0) : 0 },
    },
    [p.buffer],
  );
}

function reset(mj: MainModule): void {
  if (!current) return;
  if (current.home >= 0) mj.mj_resetDataKeyframe(current.model, current.data, current.home);
  else mj.mj_resetData(current.model, current.data);
  mj.mj_forward(current.model, current.data);
}

function frame(): void {
  if (!current) return;
  const p = poses(current);
  post({ type: 'frame', time: current.data.time, poses: p, playing, realtime }, [p.buffer]);
}

function stop(): void {
  playing = false;
  if (timer !== null) clearTimeout(timer);
  timer = null;
}

/** One tick of play: steps until simulated time catches up with wall time × speed. */
function tick(mj: MainModule): void {
  if (!current || !playing) return;
  const l = current;
  const now = performance.now();
  const target = l.data.time + (speed * Math.min(now - lastTick, 100)) / 1000;
  lastTick = now;
  const budget = now + 30;
  while (l.data.time < target && performance.now() < budget) mj.mj_step(l.model, l.data);
  if (now - window0.wall >= 1000) {
    realtime = (l.data.time - window0.sim) / ((now - window0.wall) / 1000);
    window0 = { wall: now, sim: l.data.time };
  }
  frame();
  timer = setTimeout(() => tick(mj), 16);
}
let lastTick = 0;

/** Steps as fast as it can for `seconds` of wall time (the benchmark of stepping speed). */
function bench(mj: MainModule, id: number, seconds: number): void {
  if (!current) throw new Error('no scene is loaded');
  const l = current;
  const t0 = performance.now();
  const s0 = l.data.time;
  let steps = 0;
  while (performance.now() - t0 < seconds * 1000) {
    for (let k = 0; k < 10; k++) mj.mj_step(l.model, l.data);
    steps += 10;
  }
  post({ type: 'bench', id, simSeconds: l.data.time - s0, wallSeconds: (performance.now() - t0) / 1000, steps });
  frame();
}

async function handle(msg: ToWorker): Promise<void> {
  const mj = await engine();
  switch (msg.type) {
    case 'load':
      return load(msg);
    case 'play':
      if (!current || playing) return;
      playing = true;
      lastTick = performance.now();
      window0 = { wall: lastTick, sim: current.data.time };
      tick(mj);
      return;
    case 'pause':
      stop();
      frame();
      return;
    case 'step':
      if (!current) return;
      stop();
      for (let k = 0; k < msg.n; k++) mj.mj_step(current.model, current.data);
      frame();
      return;
    case 'reset':
      reset(mj);
      frame();
      return;
    case 'speed':
      speed = Math.min(8, Math.max(0.05, msg.value));
      return;
    case 'unload': {
      release(mj);
      post({ type: 'unloaded', id: msg.id, heapBytes: heapBytes(mj) });
      return;
    }
    case 'bench':
      stop();
      bench(mj, msg.id, msg.seconds);
      return;
  }
}

// Start compiling MuJoCo's WebAssembly now, before the first scene is asked for (a failure
// is reported to that first request).
engine().catch(() => undefined);

ctx.onmessage = (e: MessageEvent<ToWorker>) => {
  const msg = e.data;
  const fail = (err: unknown) => {
    const id = 'id' in msg ? msg.id : -1;
    post({ type: 'error', id, message: message(err) });
  };
  if (msg.type === 'load' || msg.type === 'unload') {
    if (msg.type === 'load') latestLoad = msg.id;
    queue = queue.then(() => handle(msg)).catch(fail);
  } else {
    handle(msg).catch(fail);
  }
};
