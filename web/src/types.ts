// The API's JSON, written once: a type per document and the decoder that checks it.
// Fields the page only shows are read tolerantly (a newer server may add or change them);
// fields the page acts on are required.

import {
  type Obj,
  DecodeError,
  bool,
  isObj,
  list,
  listLenient,
  num,
  numTuple,
  obj,
  optNum,
  optStr,
  optTuple,
  str,
  strList,
} from './json';

export interface User {
  id: string;
  username: string;
  role: string;
}

export function decodeUser(v: unknown): User {
  const o = obj(v, 'user');
  return { id: str(o, 'id', 'user'), username: str(o, 'username', 'user'), role: optStr(o, 'role') ?? 'user' };
}

export interface ApiKey {
  id: string;
  name: string;
  created_at: number;
}

export function decodeKey(v: unknown, what: string): ApiKey {
  const o = obj(v, what);
  return { id: str(o, 'id', what), name: str(o, 'name', what), created_at: optNum(o, 'created_at') ?? 0 };
}

export interface Robot {
  name: string;
  display: string;
  kind: string;
  source: string;
  licence: string;
  reach: number | null;
  height: number | null;
  available: boolean;
  why_unavailable: string | null;
}

export function decodeRobot(v: unknown, what: string): Robot {
  const o = obj(v, what);
  return {
    name: str(o, 'name', what),
    display: optStr(o, 'display') ?? str(o, 'name', what),
    kind: optStr(o, 'kind') ?? 'robot',
    source: optStr(o, 'source') ?? '',
    licence: optStr(o, 'licence') ?? '',
    reach: optNum(o, 'reach'),
    height: optNum(o, 'height'),
    available: bool(o, 'available', true),
    why_unavailable: optStr(o, 'why_unavailable'),
  };
}

export type JobState = 'queued' | 'running' | 'succeeded' | 'failed' | 'cancelled';
const JOB_STATES: readonly string[] = ['queued', 'running', 'succeeded', 'failed', 'cancelled'];

export function isTerminal(s: JobState): boolean {
  return s === 'succeeded' || s === 'failed' || s === 'cancelled';
}

export interface Job {
  id: string;
  kind: string;
  prompt: string;
  seed: number;
  state: JobState;
  stage: string | null;
  attempts: number;
  created_at: number;
  started_at: number | null;
  finished_at: number | null;
  error: string | null;
  scene_id: string | null;
  parent_scene_id: string | null;
}

export function decodeJob(v: unknown, what = 'job'): Job {
  const o = obj(v, what);
  const state = str(o, 'state', what);
  if (!JOB_STATES.includes(state)) throw new DecodeError(`${what}.state: unknown state '${state}'`);
  return {
    id: str(o, 'id', what),
    kind: optStr(o, 'kind') ?? 'generate',
    prompt: optStr(o, 'prompt') ?? '',
    seed: optNum(o, 'seed') ?? 0,
    state: state as JobState,
    stage: optStr(o, 'stage'),
    attempts: optNum(o, 'attempts') ?? 0,
    created_at: optNum(o, 'created_at') ?? 0,
    started_at: optNum(o, 'started_at'),
    finished_at: optNum(o, 'finished_at'),
    error: optStr(o, 'error'),
    scene_id: optStr(o, 'scene_id'),
    parent_scene_id: optStr(o, 'parent_scene_id'),
  };
}

export interface SceneSummary {
  id: string;
  job_id: string;
  parent_id: string | null;
  version: number;
  /** What its job was asked: the description, or for a later version the edit. */
  prompt: string;
  /** The description the scene was generated from. */
  scene_prompt: string;
  status: string;
  created_at: number;
  /** The seed it was generated with (its variation). */
  seed: number | null;
}

export function decodeSceneSummary(v: unknown, what = 'scene'): SceneSummary {
  const o = obj(v, what);
  return {
    id: str(o, 'id', what),
    job_id: optStr(o, 'job_id') ?? '',
    parent_id: optStr(o, 'parent_id'),
    version: optNum(o, 'version') ?? 1,
    prompt: optStr(o, 'prompt') ?? '',
    scene_prompt: optStr(o, 'scene_prompt') ?? optStr(o, 'prompt') ?? '',
    status: optStr(o, 'status') ?? 'unknown',
    created_at: optNum(o, 'created_at') ?? 0,
    seed: optNum(o, 'seed'),
  };
}

export interface Warning {
  stage: string;
  code: string;
  message: string;
}

function decodeWarning(v: unknown, what: string): Warning {
  const o = obj(v, what);
  return { stage: optStr(o, 'stage') ?? '', code: optStr(o, 'code') ?? '', message: str(o, 'message', what) };
}

export interface Violation {
  rule: string;
  objects: string[];
  measured: number | null;
  required: number | null;
  unit: string;
  standard: string;
  message: string;
  requested: boolean;
}

function decodeViolation(v: unknown, what: string): Violation {
  const o = obj(v, what);
  return {
    rule: optStr(o, 'rule') ?? '',
    objects: strList(o, 'objects'),
    measured: optNum(o, 'measured'),
    required: optNum(o, 'required'),
    unit: optStr(o, 'unit') ?? '',
    standard: optStr(o, 'standard') ?? '',
    message: str(o, 'message', what),
    requested: bool(o, 'requested', false),
  };
}

/** A relation the report says holds or not (issue 12's `relations`, read tolerantly). */
export interface RelationCheck {
  /** The plan group it constrains (objects are `<group>_<n>` or share its category). */
  subject: string;
  relation: string;
  /** The groups, wall or corner it names. */
  targets: string[];
  /** The relation in the prompt's words, when the report gives them. */
  phrase: string;
  held: boolean | null;
  measured: string;
  reason: string;
}

const RELATION_FIELDS = ['subject', 'relation', 'target', 'targets', 'first', 'second', 'wall', 'corner', 'held', 'kind', 'phrase', 'reason', 'subject_category', 'target_categories', 'objects'];

function decodeRelation(v: unknown, what: string): RelationCheck {
  const o = obj(v, what);
  const measured: string[] = [];
  const add = (k: string, x: unknown) => {
    if (typeof x === 'number') measured.push(`${k.replace(/_/g, ' ')} ${fmt(x)}`);
  };
  for (const [k, x] of Object.entries(o)) {
    if (RELATION_FIELDS.includes(k)) continue;
    add(k, x);
    if (isObj(x)) for (const [k2, y] of Object.entries(x)) add(k2, y);
  }
  const targets = ['target', 'first', 'second', 'wall', 'corner'].map((k) => optStr(o, k)).filter((t): t is string => t !== null);
  return {
    subject: str(o, 'subject', what),
    relation: (optStr(o, 'relation') ?? optStr(o, 'kind') ?? '?').replace(/_/g, ' '),
    targets: [...targets, ...strList(o, 'targets')],
    phrase: optStr(o, 'phrase') ?? '',
    held: typeof o.held === 'boolean' ? o.held : null,
    measured: measured.join(', '),
    reason: optStr(o, 'reason') ?? '',
  };
}

function fmt(x: number): string {
  if (Number.isInteger(x)) return String(x);
  return Math.abs(x) >= 100 ? x.toFixed(0) : Math.abs(x) >= 1 ? x.toFixed(2) : x.toPrecision(2);
}

export interface Verification {
  engine: string;
  passed: boolean;
  compiled: boolean;
  failures: string[];
  expected: string[];
  /** Every contact MuJoCo reported at t = 0 (resting things touch). */
  contacts: number | null;
  /** Contacts between different bodies deeper than `threshold` (m): the finding. */
  deep: number;
  threshold: number | null;
  maxDepth: number | null;
  maxDisplacement: number | null;
  worstBody: string | null;
  settleS: number | null;
  robots: { name: string; drift: number | null }[];
}

function decodeVerification(v: unknown): Verification | null {
  if (!isObj(v)) return null;
  const ic = isObj(v.initial_contacts) ? v.initial_contacts : {};
  const st = isObj(v.settle) ? v.settle : {};
  return {
    engine: optStr(v, 'engine') ?? 'MuJoCo',
    passed: bool(v, 'passed', false),
    compiled: bool(v, 'compiled', false),
    failures: strList(v, 'failures'),
    expected: strList(v, 'expected'),
    contacts: optNum(ic, 'contacts'),
    deep: Array.isArray(ic.deep) ? ic.deep.length : 0,
    threshold: optNum(ic, 'threshold_m'),
    maxDepth: optNum(ic, 'max_depth_m'),
    maxDisplacement: optNum(st, 'max_displacement_m'),
    worstBody: optStr(st, 'worst_body'),
    settleS: optNum(st, 'duration_s'),
    robots: listLenient(v, 'robots', (r, w) => {
      const ro = obj(r, w);
      return { name: str(ro, 'name', w), drift: optNum(ro, 'max_joint_drift') };
    }),
  };
}

export interface Report {
  status: string;
  room: string;
  roomSize: number[] | null;
  objectsRequested: number | null;
  objectsPlaced: number | null;
  robots: string[];
  verification: Verification | null;
  warnings: Warning[];
  violations: Violation[];
  relations: RelationCheck[];
  notUnderstood: { text: string; reason: string }[];
  leftOut: { group: string; category: string; requested: number; placed: number; reason: string }[];
}

export function decodeReport(v: unknown): Report {
  const o: Obj = isObj(v) ? v : {};
  const s: Obj = isObj(o.summary) ? o.summary : {};
  const roomSize = optTuple(s, 'room_size', 3);
  return {
    status: optStr(o, 'status') ?? 'unknown',
    room: optStr(s, 'room') ?? '',
    roomSize,
    objectsRequested: optNum(s, 'objects_requested'),
    objectsPlaced: optNum(s, 'objects_placed'),
    robots: strList(s, 'robots'),
    verification: decodeVerification(o.verification),
    warnings: listLenient(o, 'warnings', decodeWarning),
    violations: listLenient(o, 'violations', decodeViolation),
    relations: listLenient(o, 'relations', decodeRelation),
    notUnderstood: listLenient(o, 'not_understood', (x, w) => {
      const n = obj(x, w);
      return { text: str(n, 'text', w), reason: optStr(n, 'reason') ?? '' };
    }),
    leftOut: listLenient(o, 'left_out', (x, w) => {
      const n = obj(x, w);
      return {
        group: optStr(n, 'group') ?? '',
        category: optStr(n, 'category') ?? '',
        requested: optNum(n, 'requested') ?? 0,
        placed: optNum(n, 'placed') ?? 0,
        reason: optStr(n, 'reason') ?? '',
      };
    }),
  };
}

export interface EditEntry {
  scene_id: string;
  new_scene_id: string;
  command: string;
  created_at: number;
}

export interface SceneDetail extends SceneSummary {
  report: Report;
  files: string[];
  edits: EditEntry[];
}

export function decodeSceneDetail(v: unknown): SceneDetail {
  const o = obj(v, 'scene');
  const files = strList(o, 'files');
  if (!files.includes('scene.xml')) throw new DecodeError('scene.files: no scene.xml in the package');
  return {
    ...decodeSceneSummary(o),
    report: decodeReport(o.report),
    files,
    edits: listLenient(o, 'edits', (x, w) => {
      const e = obj(x, w);
      return {
        scene_id: str(e, 'scene_id', w),
        new_scene_id: str(e, 'new_scene_id', w),
        command: optStr(e, 'command') ?? '',
        created_at: optNum(e, 'created_at') ?? 0,
      };
    }),
  };
}

export interface Version extends SceneSummary {
  command: string | null;
}

export function decodeVersions(v: unknown): Version[] {
  const o = obj(v, 'versions');
  return list(o, 'versions', (x, w) => {
    const e = obj(x, w);
    return { ...decodeSceneSummary(e, w), command: optStr(e, 'command') };
  });
}

/** An object of layout.json. */
export interface PlacedObject {
  name: string;
  group: string;
  category: string;
  label: string;
  pos: number[];
  yaw: number;
  size: number[];
  support: string;
  movable: boolean;
  mass: number | null;
}

export interface Anomaly {
  object: string;
  kind: string;
  description: string;
}

export interface Layout {
  room: { width: number; depth: number; height: number } | null;
  objects: PlacedObject[];
  robots: { name: string; model: string; pos: number[]; mount: string; mounted_on: string | null }[];
  anomalies: Anomaly[];
}

function describeSupport(v: unknown): string {
  if (!isObj(v)) return 'the floor';
  const on = optStr(v, 'on');
  if (on === 'object') {
    const what = optStr(v, 'object') ?? '?';
    const surface = optStr(v, 'surface');
    return surface ? `${what} (${surface})` : what;
  }
  if (on === 'wall') return `the ${optStr(v, 'wall') ?? ''} wall`;
  return 'the floor';
}

export function decodeLayout(v: unknown): Layout {
  const o = obj(v, 'layout');
  const room = isObj(o.room) && isObj(o.room.size) ? o.room.size : null;
  return {
    room: room
      ? { width: num(room, 'width', 'room'), depth: num(room, 'depth', 'room'), height: num(room, 'height', 'room') }
      : null,
    objects: list(o, 'objects', (x, w) => {
      const p = obj(x, w);
      return {
        name: str(p, 'name', w),
        group: optStr(p, 'group') ?? '',
        category: optStr(p, 'category') ?? '',
        label: optStr(p, 'label') ?? '',
        pos: numTuple(p, 'pos', 3, w),
        yaw: optNum(p, 'yaw') ?? 0,
        size: numTuple(p, 'size', 3, w),
        support: describeSupport(p.support),
        movable: bool(p, 'movable', false),
        mass: optNum(p, 'mass'),
      };
    }),
    robots: listLenient(o, 'robots', (x, w) => {
      const r = obj(x, w);
      return {
        name: str(r, 'name', w),
        model: optStr(r, 'model') ?? '',
        pos: numTuple(r, 'pos', 3, w),
        mount: optStr(r, 'mount') ?? '',
        mounted_on: optStr(r, 'mounted_on'),
      };
    }),
    anomalies: listLenient(o, 'anomalies', (x, w) => {
      const a = obj(x, w);
      return { object: str(a, 'object', w), kind: optStr(a, 'kind') ?? '', description: optStr(a, 'description') ?? '' };
    }),
  };
}

/** One message of a job's event stream. */
export type JobEvent =
  | { event: 'stage_started'; seq: number; stage: string }
  | { event: 'stage_finished'; seq: number; stage: string; ms: number; summary: string }
  | { event: 'object'; seq: number; stage: string; object: string; step: string }
  | { event: 'note'; seq: number; stage: string; message: string }
  | { event: 'warning'; seq: number; stage: string; message: string }
  | { event: 'result'; seq: number; job: Job; scene_id: string | null }
  | { event: 'other'; seq: number; name: string; text: string };

export function decodeEvent(v: unknown): JobEvent {
  const o = obj(v, 'event');
  const seq = optNum(o, 'seq') ?? -1;
  const name = optStr(o, 'event') ?? '';
  const stage = optStr(o, 'stage') ?? '';
  switch (name) {
    case 'stage_started':
      return { event: name, seq, stage };
    case 'stage_finished':
      return { event: name, seq, stage, ms: optNum(o, 'ms') ?? 0, summary: optStr(o, 'summary') ?? '' };
    case 'object':
      return { event: name, seq, stage, object: optStr(o, 'object') ?? '', step: optStr(o, 'step') ?? '' };
    case 'note':
      return { event: name, seq, stage, message: optStr(o, 'message') ?? '' };
    case 'warning':
      return { event: name, seq, stage, message: optStr(o, 'message') ?? '' };
    case 'result': {
      const scene = isObj(o.scene) ? optStr(o.scene, 'id') : null;
      return { event: name, seq, job: decodeJob(o.job, 'result.job'), scene_id: scene };
    }
    default: {
      const text = optStr(o, 'error') ?? optStr(o, 'reason') ?? optStr(o, 'message') ?? '';
      return { event: 'other', seq, name, text };
    }
  }
}

export interface CatalogEntry {
  name: string;
  display: string;
  size: number[] | null;
  movable: boolean;
}

export interface Asset {
  id: string;
  description: string;
  category: string | null;
  source: string;
  size: number[] | null;
  hasMesh: boolean;
  score: number | null;
  created_at: number;
}

export function decodeAsset(v: unknown, what = 'asset'): Asset {
  const o = obj(v, what);
  const meta: Obj = isObj(o.meta) ? o.meta : {};
  const size = optTuple(meta, 'size_m', 3) ?? optTuple(meta, 'size', 3);
  return {
    id: str(o, 'id', what),
    description: optStr(o, 'description') ?? '',
    category: optStr(o, 'category'),
    source: optStr(meta, 'source') ?? 'catalog',
    size,
    hasMesh: typeof meta.asset_id === 'string',
    score: optNum(o, 'score'),
    created_at: optNum(o, 'created_at') ?? 0,
  };
}

export interface AssetSearch {
  catalog: CatalogEntry[];
  mine: Asset[];
  /** The caller's generated parts nearest in meaning, best first (when the index is available). */
  similar: Asset[];
  note: string | null;
}

export function decodeAssetSearch(v: unknown): AssetSearch {
  const o = obj(v, 'assets');
  return {
    catalog: listLenient(o, 'catalog', (x, w) => {
      const c = obj(x, w);
      const size = optTuple(c, 'size', 3);
      return { name: str(c, 'name', w), display: optStr(c, 'display') ?? str(c, 'name', w), size, movable: bool(c, 'movable', false) };
    }),
    mine: list(o, 'mine', decodeAsset),
    similar: listLenient(o, 'similar', decodeAsset),
    note: optStr(o, 'note'),
  };
}

export interface RefineState {
  question: string | null;
  prompt: string;
  done: boolean;
  asked_by: string;
  turns: { question: string; answer: string }[];
  summary: string;
  warnings: string[];
}

export function decodeRefine(v: unknown): RefineState {
  const o = obj(v, 'refine');
  return {
    question: optStr(o, 'question'),
    prompt: str(o, 'prompt', 'refine'),
    done: bool(o, 'done', false),
    asked_by: optStr(o, 'asked_by') ?? 'offline',
    turns: list(o, 'turns', (x, w) => {
      const t = obj(x, w);
      return { question: str(t, 'question', w), answer: str(t, 'answer', w) };
    }),
    summary: optStr(o, 'summary') ?? '',
    warnings: strList(o, 'warnings'),
  };
}

/** One line of a streamed asset request (`POST /api/assets` with `stream`). */
export type AssetProgress =
  | { event: 'progress'; message: string }
  | { event: 'failure'; attempt: number; kind: string; message: string }
  | { event: 'asset'; asset: Asset }
  | { event: 'error'; status: number; message: string; kinds: string[] };

export function decodeAssetProgress(v: unknown): AssetProgress {
  const o = obj(v, 'progress');
  switch (optStr(o, 'event')) {
    case 'failure':
      return { event: 'failure', attempt: optNum(o, 'attempt') ?? 0, kind: optStr(o, 'kind') ?? '', message: optStr(o, 'message') ?? '' };
    case 'asset':
      return { event: 'asset', asset: decodeAsset(o.asset) };
    case 'error':
      return { event: 'error', status: optNum(o, 'status') ?? 500, message: optStr(o, 'error') ?? 'failed', kinds: strList(o, 'kinds') };
    default:
      return { event: 'progress', message: optStr(o, 'message') ?? '' };
  }
}
