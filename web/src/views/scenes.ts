// My scenes: one card per description, holding its variations (one per seed) and, for
// each, its versions (edits) — the newest version shown, with a thumbnail rendered by the
// server. A search box filters by the words of the description or of an edit; a variation
// can be downloaded or deleted (with all its versions). The jobs follow.

import * as api from '../api';
import { fill, fmtDate, h, notice } from '../dom';
import type { View } from '../router';
import * as session from '../session';
import type { SceneSummary } from '../types';

/** An <img> of a scene's thumbnail, fetched with the session's token. */
function thumbnail(id: string): HTMLElement {
  const img = h('img', { class: 'thumb', attrs: { alt: 'scene thumbnail', loading: 'lazy', width: '320', height: '200' } });
  fetch(`/api/scenes/${encodeURIComponent(id)}/thumbnail.png`, { headers: { authorization: `Bearer ${session.token() ?? ''}` } })
    .then(async (r) => {
      if (!r.ok) throw new Error(String(r.status));
      img.src = URL.createObjectURL(await r.blob());
      img.onload = () => URL.revokeObjectURL(img.src);
    })
    .catch(() => img.replaceWith(h('div', { class: 'thumb none', text: 'no picture' })));
  return img;
}

function downloadButton(id: string, onError: (m: string) => void): HTMLElement {
  return h('button', {
    text: 'package.zip',
    title: 'download the package',
    on: {
      click: () =>
        void api
          .packageZip(id)
          .then((blob) => {
            const a = h('a', { href: URL.createObjectURL(blob), attrs: { download: `scene_${id}.zip` } });
            document.body.append(a);
            a.click();
            a.remove();
          })
          .catch((e: unknown) => onError(`The download failed: ${api.describe(e)}.`)),
    },
  });
}

/** A scene's versions: its first version and every edit of it. */
export interface Lineage {
  root: SceneSummary;
  versions: SceneSummary[];
  newest: SceneSummary;
}

/** A description's variations (one lineage per seed), newest activity first. */
export interface Family {
  description: string;
  lineages: Lineage[];
  newest: number;
}

/** Groups scenes into lineages (by following `parent_id`) and lineages into families (by description). */
export function group(scenes: SceneSummary[]): Family[] {
  const byId = new Map(scenes.map((s) => [s.id, s]));
  const rootOf = (s: SceneSummary): SceneSummary => {
    let at = s;
    const seen = new Set<string>();
    while (at.parent_id && byId.has(at.parent_id) && !seen.has(at.id)) {
      seen.add(at.id);
      at = byId.get(at.parent_id) ?? at;
    }
    return at;
  };
  const lineages = new Map<string, Lineage>();
  for (const s of scenes) {
    const root = rootOf(s);
    const l = lineages.get(root.id) ?? { root, versions: [], newest: s };
    l.versions.push(s);
    if (s.version > l.newest.version || (s.version === l.newest.version && s.created_at > l.newest.created_at)) l.newest = s;
    lineages.set(root.id, l);
  }
  const families = new Map<string, Family>();
  for (const l of lineages.values()) {
    l.versions.sort((a, b) => a.version - b.version || a.created_at - b.created_at);
    const key = l.root.scene_prompt;
    const f = families.get(key) ?? { description: key, lineages: [], newest: 0 };
    f.lineages.push(l);
    f.newest = Math.max(f.newest, ...l.versions.map((v) => v.created_at));
    families.set(key, f);
  }
  const out = [...families.values()];
  for (const f of out) f.lineages.sort((a, b) => (a.root.seed ?? 0) - (b.root.seed ?? 0) || a.root.created_at - b.root.created_at);
  return out.sort((a, b) => b.newest - a.newest);
}

/** True when a family's description, or one of its edits, holds every word of `q`. */
function matches(f: Family, q: string): boolean {
  const words = q.toLowerCase().split(/\s+/).filter(Boolean);
  const text = [f.description, ...f.lineages.flatMap((l) => l.versions.map((v) => v.prompt))].join(' ').toLowerCase();
  return words.every((w) => text.includes(w));
}

export const scenesView: View = (root) => {
  const status = h('div', { class: 'status', id: 'scenes-status' });
  const search = h('input', { id: 'scene-search', type: 'search', placeholder: 'search your scenes (words of the description or of an edit)' });
  const grid = h('div', { class: 'scene-grid', id: 'scene-grid' }, notice('info', 'Loading your scenes…'));
  const jobs = h('table', { class: 'jobs', id: 'jobs' });
  root.append(h('div', { class: 'page' }, h('h1', { text: 'My scenes' }), h('div', { class: 'row' }, search), status, grid, h('h2', { text: 'Jobs' }), jobs));
  const err = (m: string) => fill(status, notice('error', m));
  let families: Family[] = [];

  const remove = (l: Lineage) => {
    const n = l.versions.length;
    if (!window.confirm(`Delete this scene${n > 1 ? ` and its ${n} versions` : ''}? This cannot be undone.`)) return;
    api
      .deleteScene(l.root.id)
      .then((ids) => {
        fill(status, notice('ok', `Deleted ${ids.length} version${ids.length === 1 ? '' : 's'}.`));
        load();
      })
      .catch((e: unknown) => err(`Deleting failed: ${api.describe(e)}.`));
  };

  const lineageRow = (l: Lineage) =>
    h(
      'li',
      { class: 'variation', data: { scene: l.newest.id, root: l.root.id } },
      h('a', { href: `/scenes/${l.newest.id}`, text: l.root.seed !== null ? `seed ${l.root.seed}` : 'open' }),
      h('span', { class: 'tag', text: `v${l.newest.version}` }),
      l.versions.length > 1 ? h('span', { class: 'muted versions', text: ` ${l.versions.length} versions` }) : null,
      h('span', { class: `badge ${l.newest.status}`, text: l.newest.status }),
      l.newest.version > 1 ? h('div', { class: 'muted edit-line', text: `last edit: ${l.newest.prompt}` }) : null,
      h(
        'div',
        { class: 'row' },
        downloadButton(l.newest.id, err),
        h('button', { class: 'delete', text: 'Delete', title: 'delete this scene and its versions', on: { click: () => remove(l) } }),
      ),
    );

  const card = (f: Family) => {
    const first = f.lineages[0];
    if (!first) return null;
    const variations = f.lineages.length;
    return h(
      'div',
      { class: 'scene-card card', data: { scene: first.newest.id } },
      h('a', { href: `/scenes/${first.newest.id}` }, thumbnail(first.newest.id)),
      h('a', { href: `/scenes/${first.newest.id}`, class: 'prompt', text: f.description }),
      h('div', { class: 'muted', text: `${variations} variation${variations === 1 ? '' : 's'} · ${fmtDate(f.newest)}` }),
      h('ul', { class: 'variations' }, ...f.lineages.map(lineageRow)),
    );
  };

  const render = () => {
    if (!families.length) {
      fill(grid, h('p', { class: 'muted' }, 'No scenes yet. ', h('a', { href: '/', text: 'Describe one.' })));
      return;
    }
    const shown = families.filter((f) => matches(f, search.value));
    fill(grid, ...(shown.length ? shown.map(card) : [h('p', { class: 'muted', text: 'No scene matches the search.' })]));
  };
  search.addEventListener('input', render);

  const load = () => {
    api
      .scenes()
      .then((list) => {
        families = group(list);
        render();
      })
      .catch((e: unknown) => fill(grid, notice('error', `Your scenes did not load: ${api.describe(e)}.`)));
    api
      .jobs()
      .then((list) =>
        fill(
          jobs,
          h('tr', {}, ...['job', 'kind', 'state', 'prompt', 'created'].map((t) => h('th', { text: t }))),
          ...list.slice(0, 50).map((j) =>
            h(
              'tr',
              {},
              h('td', {}, h('a', { href: `/jobs/${j.id}`, text: j.id.slice(0, 8) })),
              h('td', { text: j.kind }),
              h('td', {}, h('span', { class: `badge ${j.state}`, text: j.state })),
              h('td', { class: 'prompt', text: j.error ? `${j.prompt} — ${j.error}` : j.prompt }),
              h('td', { text: fmtDate(j.created_at) }),
            ),
          ),
        ),
      )
      .catch((e: unknown) => fill(jobs, h('tr', {}, h('td', { text: `Jobs did not load: ${api.describe(e)}.` }))));
  };
  load();
};
