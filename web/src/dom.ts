// A small helper for building DOM nodes (the app uses no framework). Text put in through
// it never carries the controls that reorder a line (see `plain`).

import { plain } from './json';

type Child = Node | string | null | undefined | false;

export interface Attrs {
  class?: string;
  text?: string;
  title?: string;
  id?: string;
  href?: string;
  type?: string;
  value?: string;
  placeholder?: string;
  disabled?: boolean;
  data?: Record<string, string>;
  attrs?: Record<string, string>;
  on?: Partial<{ [K in keyof HTMLElementEventMap]: (e: HTMLElementEventMap[K]) => void }>;
}

export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  a: Attrs = {},
  ...children: Child[]
): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  if (a.class) el.className = a.class;
  if (a.text !== undefined) el.textContent = plain(a.text);
  if (a.title) el.title = a.title;
  if (a.id) el.id = a.id;
  if (a.href !== undefined) el.setAttribute('href', a.href);
  if (a.type) el.setAttribute('type', a.type);
  if (a.value !== undefined && 'value' in el) (el as HTMLInputElement).value = a.value;
  if (a.placeholder) el.setAttribute('placeholder', a.placeholder);
  if (a.disabled) el.setAttribute('disabled', '');
  for (const [k, v] of Object.entries(a.data ?? {})) el.dataset[k] = v;
  for (const [k, v] of Object.entries(a.attrs ?? {})) el.setAttribute(k, v);
  for (const [name, fn] of Object.entries(a.on ?? {})) el.addEventListener(name, fn as EventListener);
  for (const c of children) if (c !== null && c !== undefined && c !== false) el.append(typeof c === 'string' ? plain(c) : c);
  return el;
}

/** Sets an element's text (cleaned as `h` cleans it). */
export function setText(el: Element, text: string): void {
  el.textContent = plain(text);
}

/** Replaces an element's children. */
export function fill(el: Element, ...children: Child[]): void {
  el.replaceChildren(
    ...children.filter((c): c is Node | string => c !== null && c !== undefined && c !== false).map((c) => (typeof c === 'string' ? plain(c) : c)),
  );
}

/** A message box: `kind` is error, info or ok. */
export function notice(kind: 'error' | 'info' | 'ok', text: string): HTMLElement {
  return h('div', { class: `notice ${kind}`, text, attrs: { role: kind === 'error' ? 'alert' : 'status' } });
}

export function fmtMs(ms: number): string {
  if (ms >= 1000) return `${(ms / 1000).toFixed(2)} s`;
  if (ms >= 10) return `${ms.toFixed(0)} ms`;
  // The offline stages take fractions of a millisecond: "0 ms" reads as "not measured".
  return ms >= 0.1 ? `${ms.toFixed(1)} ms` : '< 0.1 ms';
}

export function fmtDate(ms: number): string {
  if (!ms) return '';
  return new Date(ms).toLocaleString(undefined, { dateStyle: 'medium', timeStyle: 'short' });
}

export function fmtSize(s: number[] | null): string {
  if (!s) return '';
  return s.map((v) => v.toFixed(2)).join(' × ') + ' m';
}
