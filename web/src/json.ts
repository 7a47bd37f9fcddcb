// Reading JSON from the server without trusting it: every value is `unknown` until a
// decoder has checked its shape, and a wrong shape is a `DecodeError` naming the field.

export class DecodeError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'DecodeError';
  }
}

export type Obj = Record<string, unknown>;

/**
 * Text as the page shows it: without the Unicode controls that reorder what follows them
 * (bidirectional embeddings, overrides and isolates). A prompt holding U+202E would
 * otherwise turn the rest of its line, and the page around it, backwards.
 */
export function plain(s: string): string {
  return s.replace(/[\u202A-\u202E\u2066-\u2069]/g, '');
}

export function isObj(v: unknown): v is Obj {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}

export function obj(v: unknown, what: string): Obj {
  if (!isObj(v)) throw new DecodeError(`${what}: expected an object`);
  return v;
}

export function str(o: Obj, key: string, what = 'value'): string {
  const v = o[key];
  if (typeof v !== 'string') throw new DecodeError(`${what}.${key}: expected text`);
  return plain(v);
}

export function optStr(o: Obj, key: string): string | null {
  const v = o[key];
  return typeof v === 'string' ? plain(v) : null;
}

export function num(o: Obj, key: string, what = 'value'): number {
  const v = o[key];
  if (typeof v !== 'number' || !Number.isFinite(v)) throw new DecodeError(`${what}.${key}: expected a number`);
  return v;
}

export function optNum(o: Obj, key: string): number | null {
  const v = o[key];
  return typeof v === 'number' && Number.isFinite(v) ? v : null;
}

export function bool(o: Obj, key: string, fallback: boolean): boolean {
  const v = o[key];
  return typeof v === 'boolean' ? v : fallback;
}

/** An array field decoded element by element; a missing field is an empty list. */
export function list<T>(o: Obj, key: string, each: (v: unknown, what: string) => T, what = 'value'): T[] {
  const v = o[key];
  if (v === undefined || v === null) return [];
  if (!Array.isArray(v)) throw new DecodeError(`${what}.${key}: expected a list`);
  return v.map((x, i) => each(x, `${what}.${key}[${i}]`));
}

/** Like `list`, but elements that do not decode are skipped (for fields read tolerantly). */
export function listLenient<T>(o: Obj, key: string, each: (v: unknown, what: string) => T): T[] {
  const v = o[key];
  if (!Array.isArray(v)) return [];
  const out: T[] = [];
  for (const [i, x] of v.entries()) {
    try {
      out.push(each(x, `${key}[${i}]`));
    } catch {
      // A newer server's shape this page does not know: shown as absent.
    }
  }
  return out;
}

export function strList(o: Obj, key: string): string[] {
  const v = o[key];
  return Array.isArray(v) ? v.filter((x): x is string => typeof x === 'string').map(plain) : [];
}

export function numTuple(o: Obj, key: string, n: number, what = 'value'): number[] {
  const v = o[key];
  if (!Array.isArray(v) || v.length !== n || !v.every((x) => typeof x === 'number' && Number.isFinite(x))) {
    throw new DecodeError(`${what}.${key}: expected ${n} numbers`);
  }
  return v as number[];
}

export function asStr(v: unknown, what: string): string {
  if (typeof v !== 'string') throw new DecodeError(`${what}: expected text`);
  return plain(v);
}

/** A tuple of `n` numbers, or null when the field is missing or not one. */
export function optTuple(o: Obj, key: string, n: number): number[] | null {
  const v = o[key];
  return Array.isArray(v) && v.length === n && v.every((x) => typeof x === 'number' && Number.isFinite(x)) ? (v as number[]) : null;
}
