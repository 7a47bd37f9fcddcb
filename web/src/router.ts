// Client-side routes: every view has its own URL (the server answers index.html for
// them), so links can be shared and reloaded. A signed-out visitor is sent to sign in and
// then back to where they were going.

import * as session from './session';

export type Cleanup = () => void;
export type View = (root: HTMLElement, params: Record<string, string>, query: URLSearchParams) => Cleanup | void;

interface Route {
  pattern: RegExp;
  keys: string[];
  view: View;
  public: boolean;
}

const routes: Route[] = [];
let outlet: HTMLElement | null = null;
let cleanup: Cleanup | null = null;
let onChange: ((path: string) => void) | null = null;

/** Registers a route like `/scenes/:id`. */
export function route(path: string, view: View, isPublic = false): void {
  const keys: string[] = [];
  const re = path.replace(/:([a-z]+)/g, (_m, k: string) => {
    keys.push(k);
    return '([^/]+)';
  });
  routes.push({ pattern: new RegExp(`^${re}/?$`), keys, view, public: isPublic });
}

export function navigate(to: string, replace = false): void {
  if (replace) history.replaceState(null, '', to);
  else history.pushState(null, '', to);
  render();
}

export function start(root: HTMLElement, changed: (path: string) => void): void {
  outlet = root;
  onChange = changed;
  window.addEventListener('popstate', render);
  document.addEventListener('click', (e) => {
    const a = (e.target as Element | null)?.closest('a');
    if (!a || a.target || a.hasAttribute('download') || e.metaKey || e.ctrlKey || e.shiftKey) return;
    const href = a.getAttribute('href');
    if (!href?.startsWith('/') || href.startsWith('/api/')) return;
    e.preventDefault();
    navigate(href);
  });
  session.whenExpired((reason) => {
    const here = location.pathname + location.search;
    if (location.pathname === '/signin') return;
    // The address carries a reason code only; the page words it (never text from the URL).
    navigate(`/signin?next=${encodeURIComponent(here)}&reason=${reason}`, true);
  });
  render();
}

function render(): void {
  if (!outlet) return;
  cleanup?.();
  cleanup = null;
  const path = location.pathname;
  const query = new URLSearchParams(location.search);
  const match = routes
    .map((r) => ({ r, m: r.pattern.exec(path) }))
    .find((x): x is { r: Route; m: RegExpExecArray } => x.m !== null);
  onChange?.(path);
  if (match && !match.r.public && !session.token()) {
    navigate(`/signin?next=${encodeURIComponent(path + location.search)}`, true);
    return;
  }
  const params: Record<string, string> = {};
  match?.r.keys.forEach((k, i) => (params[k] = decodeURIComponent(match.m[i + 1] ?? '')));
  outlet.replaceChildren();
  const view = match?.r.view ?? notFound;
  try {
    cleanup = view(outlet, params, query) ?? null;
  } catch (e) {
    outlet.replaceChildren(errorBox(e));
  }
  window.scrollTo(0, 0);
}

function errorBox(e: unknown): HTMLElement {
  const div = document.createElement('div');
  div.className = 'notice error';
  div.setAttribute('role', 'alert');
  div.textContent = `This page failed: ${e instanceof Error ? e.message : String(e)}`;
  return div;
}

/** The page for something that does not exist here (or is not the visitor's). */
export function notFoundPage(root: HTMLElement, title: string, text: string): void {
  const div = document.createElement('div');
  div.className = 'page not-found';
  div.id = 'not-found';
  const h1 = document.createElement('h1');
  h1.textContent = title;
  const p = document.createElement('p');
  p.textContent = `${text} `;
  const mine = document.createElement('a');
  mine.href = '/scenes';
  mine.textContent = 'Your scenes';
  const start = document.createElement('a');
  start.href = '/';
  start.textContent = 'describe a new one';
  p.append(mine, ' · ', start, '.');
  div.append(h1, p);
  root.append(div);
}

const notFound: View = (root) => notFoundPage(root, 'Not found', 'There is no page at this address.');
