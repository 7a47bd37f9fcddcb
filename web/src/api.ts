// The typed client of the service's HTTP API (`/api/...`) and of a job's WebSocket.
// Every answer is decoded (types.ts) before the page sees it; an error answer becomes an
// `ApiError` carrying the server's one-sentence message; a token the server refuses ends
// the session (the router sends the user to sign in, then back).

import { isObj, list, obj, optStr, str, strList } from './json';
import * as session from './session';
import {
  type ApiKey,
  type Asset,
  type AssetProgress,
  type AssetSearch,
  type Job,
  type JobEvent,
  type Layout,
  type RefineState,
  type Robot,
  type SceneDetail,
  type SceneSummary,
  type User,
  type Version,
  decodeAsset,
  decodeAssetProgress,
  decodeAssetSearch,
  decodeEvent,
  decodeJob,
  decodeKey,
  decodeLayout,
  decodeRefine,
  decodeRobot,
  decodeSceneDetail,
  decodeSceneSummary,
  decodeUser,
  decodeVersions,
} from './types';

export class ApiError extends Error {
  constructor(
    readonly status: number,
    message: string,
  ) {
    super(message);
    this.name = 'ApiError';
  }
}

/** A sentence for any failure, for the page to show. */
export function describe(e: unknown): string {
  if (e instanceof ApiError) return e.message;
  if (e instanceof TypeError) return `the server cannot be reached (${e.message})`;
  if (e instanceof Error) return e.message;
  return 'something went wrong';
}

async function errorOf(r: Response): Promise<ApiError> {
  let message = `the server answered ${r.status} ${r.statusText}`;
  try {
    const body: unknown = await r.json();
    if (isObj(body)) message = optStr(body, 'error') ?? message;
  } catch {
    // Not JSON (a proxy's page): the status line says enough.
  }
  return new ApiError(r.status, message);
}

interface Options {
  body?: unknown;
  auth?: boolean;
  signal?: AbortSignal;
}

async function call(method: string, path: string, opts: Options = {}): Promise<Response> {
  const headers: Record<string, string> = {};
  const t = session.token();
  if (opts.auth !== false) {
    if (!t) {
      session.expire('signin');
      throw new ApiError(401, 'you are not signed in');
    }
    headers.authorization = `Bearer ${t}`;
  }
  if (opts.body !== undefined) headers['content-type'] = 'application/json';
  const init: RequestInit = { method, headers };
  if (opts.body !== undefined) init.body = JSON.stringify(opts.body);
  if (opts.signal) init.signal = opts.signal;
  const r = await fetch(path, init);
  if (!r.ok) {
    const err = await errorOf(r);
    if (r.status === 401 && opts.auth !== false) session.expire(session.reasonOf(err.message));
    throw err;
  }
  return r;
}

async function json(method: string, path: string, opts: Options = {}): Promise<unknown> {
  const r = await call(method, path, opts);
  return (await r.json()) as unknown;
}

const enc = encodeURIComponent;

export async function register(username: string, password: string): Promise<User> {
  return decodeUser(await json('POST', '/api/auth/register', { body: { username, password }, auth: false }));
}

/** Signs in: the token, and the user name as registered (names are one whatever their case). */
export async function login(username: string, password: string): Promise<{ token: string; username: string }> {
  const o = obj(await json('POST', '/api/auth/login', { body: { username, password }, auth: false }), 'login');
  return { token: str(o, 'token', 'login'), username: optStr(o, 'username') ?? username };
}

/** Signs out on the server too: the token stops working now (best effort; the page forgets it either way). */
export async function logout(): Promise<void> {
  const t = session.token();
  if (!t) return;
  await fetch('/api/auth/logout', { method: 'POST', headers: { authorization: `Bearer ${t}` } }).catch(() => undefined);
}

export async function me(): Promise<User> {
  return decodeUser(await json('GET', '/api/me'));
}

export async function keys(): Promise<ApiKey[]> {
  return list(obj(await json('GET', '/api/auth/keys'), 'keys'), 'keys', decodeKey);
}

/** Revokes an API key: it stops working at once. */
export async function revokeKey(id: string): Promise<void> {
  await call('DELETE', `/api/auth/keys/${enc(id)}`);
}

export async function createKey(name: string): Promise<{ key: ApiKey; secret: string }> {
  const o = obj(await json('POST', '/api/auth/keys', { body: { name } }), 'key');
  return { key: decodeKey(o, 'key'), secret: str(o, 'key', 'key') };
}

export async function robots(): Promise<Robot[]> {
  return list(obj(await json('GET', '/api/robots'), 'robots'), 'robots', decodeRobot);
}

/** What a job may ask for: the rules profiles and anomaly kinds the server knows. */
export async function options(): Promise<{ rules_profiles: string[]; anomaly_kinds: string[] }> {
  const o = obj(await json('GET', '/api/options'), 'options');
  return { rules_profiles: strList(o, 'rules_profiles'), anomaly_kinds: strList(o, 'anomaly_kinds') };
}

export async function refine(prompt: string, turns: { question: string; answer: string }[]): Promise<RefineState> {
  return decodeRefine(await json('POST', '/api/refine', { body: { prompt, turns } }));
}

export interface JobRequest {
  prompt: string;
  seed?: number;
  robots?: string[];
  options?: { rules?: string; anomaly?: { kinds: string[]; rate: number } };
  /** Scenes to make, one per seed from `seed` up (queued together, or none). */
  variations?: number;
}

/** Queues a request; answers the ids of its jobs (one per variation). */
export async function submitJob(req: JobRequest): Promise<string[]> {
  const o = obj(await json('POST', '/api/jobs', { body: req }), 'job');
  const ids = strList(o, 'job_ids');
  return ids.length ? ids : [str(o, 'job_id', 'job')];
}

export async function job(id: string): Promise<Job> {
  return decodeJob(await json('GET', `/api/jobs/${enc(id)}`));
}

export async function jobs(): Promise<Job[]> {
  return list(obj(await json('GET', '/api/jobs'), 'jobs'), 'jobs', decodeJob);
}

export async function cancelJob(id: string): Promise<Job> {
  return decodeJob(await json('DELETE', `/api/jobs/${enc(id)}`));
}

export async function scenes(): Promise<SceneSummary[]> {
  return list(obj(await json('GET', '/api/scenes'), 'scenes'), 'scenes', decodeSceneSummary);
}

/** Deletes a scene with every version of its lineage; answers the ids deleted. */
export async function deleteScene(id: string): Promise<string[]> {
  return strList(obj(await json('DELETE', `/api/scenes/${enc(id)}`), 'deleted'), 'deleted');
}

export async function scene(id: string): Promise<SceneDetail> {
  return decodeSceneDetail(await json('GET', `/api/scenes/${enc(id)}`));
}

export async function versions(id: string): Promise<Version[]> {
  return decodeVersions(await json('GET', `/api/scenes/${enc(id)}/versions`));
}

/** A catalog category's picture (public: an <img> may point at it directly). */
export function catalogPictureUrl(category: string): string {
  return `/api/catalog/${enc(category)}/picture.png`;
}

export function fileUrl(sceneId: string, path: string): string {
  return `/api/scenes/${enc(sceneId)}/files/${path.split('/').map(enc).join('/')}`;
}

export async function layout(sceneId: string): Promise<Layout> {
  const r = await call('GET', fileUrl(sceneId, 'layout.json'));
  return decodeLayout(await r.json());
}

/** The package as a zip, as a Blob the page can offer for download. */
export async function packageZip(sceneId: string): Promise<Blob> {
  return (await call('GET', `/api/scenes/${enc(sceneId)}/package.zip`)).blob();
}

/** A structured edit from the viewer: move or turn an object, or place a library part. */
export type StructuredEdit =
  | { move: { object: string; pos: [number, number]; yaw_deg?: number } }
  | { place: { asset: string; pos: [number, number]; yaw_deg?: number } };

/** Starts an edit job (a sentence, or a structured edit); answers its job id. */
export async function edit(sceneId: string, e: string | StructuredEdit): Promise<string> {
  const body = typeof e === 'string' ? { command: e } : e;
  return str(obj(await json('POST', `/api/scenes/${enc(sceneId)}/edits`, { body }), 'edit'), 'job_id', 'edit');
}

export async function searchAssets(q: string): Promise<AssetSearch> {
  return decodeAssetSearch(await json('GET', `/api/assets?q=${enc(q)}`));
}

export async function asset(id: string): Promise<Asset> {
  return decodeAsset(await json('GET', `/api/assets/${enc(id)}`));
}

export async function assetMesh(id: string): Promise<ArrayBuffer> {
  return (await call('GET', `/api/assets/${enc(id)}/mesh.stl`)).arrayBuffer();
}

/**
 * Asks the forge for a part, reading its progress as it comes (one JSON object per line):
 * each failed attempt with its kind, then the asset or the reason it could not be made.
 */
export async function makeAsset(
  description: string,
  size: [number, number, number] | null,
  onProgress: (p: AssetProgress) => void,
): Promise<Asset> {
  const body: { description: string; size_m?: [number, number, number] } = { description };
  if (size) body.size_m = size;
  const r = await call('POST', '/api/assets?stream=1', { body });
  const reader = r.body?.getReader();
  if (!reader) throw new ApiError(500, 'the server sent no progress');
  const dec = new TextDecoder();
  let buf = '';
  let made: Asset | null = null;
  let failure: ApiError | null = null;
  for (;;) {
    const { value, done } = await reader.read();
    if (value) buf += dec.decode(value, { stream: true });
    let nl: number;
    while ((nl = buf.indexOf('\n')) >= 0) {
      const line = buf.slice(0, nl).trim();
      buf = buf.slice(nl + 1);
      if (!line) continue;
      const p = decodeAssetProgress(JSON.parse(line) as unknown);
      onProgress(p);
      if (p.event === 'asset') made = p.asset;
      if (p.event === 'error') failure = new ApiError(p.status, p.message);
    }
    if (done) break;
  }
  if (failure) throw failure;
  if (!made) throw new ApiError(502, 'the connection ended before the part was made');
  return made;
}

/** Handlers of a job's event stream. */
export interface JobWatch {
  onEvent: (e: JobEvent) => void;
  /** The socket dropped; `attempt` counts reconnection attempts. */
  onDrop: (attempt: number, why: string) => void;
  onReconnect: () => void;
  /** The job cannot be followed (gone, or the session ended). */
  onFatal: (why: string) => void;
}

/**
 * Follows a job's events over its WebSocket. A dropped socket is reopened with backoff; the
 * server sends the job's whole history on every connection, and events already seen
 * (by sequence number) are skipped, so the page catches up without repeats.
 */
export function watchJob(id: string, h: JobWatch): () => void {
  let lastSeq = 0;
  let closed = false;
  let finished = false;
  let attempt = 0;
  let socket: WebSocket | null = null;
  let retry: ReturnType<typeof setTimeout> | null = null;

  const open = () => {
    const t = session.token();
    if (!t) {
      h.onFatal('you are not signed in');
      return;
    }
    const proto = location.protocol === 'https:' ? 'wss' : 'ws';
    const ws = new WebSocket(`${proto}://${location.host}/api/jobs/${enc(id)}/events?token=${enc(t)}`);
    socket = ws;
    let opened = false;
    ws.onopen = () => {
      opened = true;
      if (attempt > 0) h.onReconnect();
      attempt = 0;
    };
    ws.onmessage = (m: MessageEvent) => {
      if (typeof m.data !== 'string') return;
      let e: JobEvent;
      try {
        e = decodeEvent(JSON.parse(m.data) as unknown);
      } catch {
        return;
      }
      if (e.event === 'result') {
        finished = true;
        h.onEvent(e);
        return;
      }
      if (e.seq >= 0 && e.seq <= lastSeq) return;
      if (e.seq >= 0) lastSeq = e.seq;
      h.onEvent(e);
    };
    ws.onclose = () => {
      if (closed || finished) return;
      attempt++;
      // Ask over HTTP why: an ended session or a missing job is final; anything else is retried.
      job(id)
        .then(() => {
          const delay = Math.min(8000, 500 * 2 ** Math.min(attempt - 1, 4));
          h.onDrop(attempt, opened ? 'the connection to the server dropped' : 'the server did not accept the connection');
          retry = setTimeout(open, delay);
        })
        .catch((err: unknown) => {
          if (err instanceof ApiError && (err.status === 401 || err.status === 404)) {
            h.onFatal(err.message);
            return;
          }
          const delay = Math.min(8000, 500 * 2 ** Math.min(attempt - 1, 4));
          h.onDrop(attempt, describe(err));
          retry = setTimeout(open, delay);
        });
    };
  };
  open();
  return () => {
    closed = true;
    if (retry !== null) clearTimeout(retry);
    socket?.close();
  };
}

/** Waits for a job to end (for edits): resolves with the finished job. */
export function waitForJob(id: string, onEvent: (e: JobEvent) => void = () => undefined): Promise<Job> {
  return new Promise((resolve, reject) => {
    const stop = watchJob(id, {
      onEvent: (e) => {
        onEvent(e);
        if (e.event === 'result') {
          stop();
          resolve(e.job);
        }
      },
      onDrop: () => undefined,
      onReconnect: () => undefined,
      onFatal: (why) => {
        stop();
        reject(new ApiError(410, why));
      },
    });
  });
}
