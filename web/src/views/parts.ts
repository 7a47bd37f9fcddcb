// The asset library as a list: catalog categories and the user's generated parts (nearest
// in meaning first when the server's index can say), each draggable into an open scene.

import * as api from '../api';
import { fill, fmtSize, h, notice } from '../dom';
import type { AssetSearch } from '../types';

/** The drag payload's type: `catalog:<name>` or a generated asset's id. */
export const PART_MIME = 'application/x-scenewright-part';

export interface PartChoice {
  ref: string;
  label: string;
}

/** A catalog category's small picture; it goes quietly if it cannot be drawn. */
function picture(category: string): HTMLElement {
  const img = h('img', { class: 'part-pic', attrs: { alt: '', loading: 'lazy', width: '48', height: '48', draggable: 'false', src: api.catalogPictureUrl(category) } });
  img.addEventListener('error', () => img.remove());
  return img;
}

function item(ref: string, label: string, meta: string, onPick?: (p: PartChoice) => void): HTMLElement {
  const category = ref.startsWith('catalog:') ? ref.slice('catalog:'.length) : null;
  const li = h(
    'li',
    { class: 'part', data: { part: ref }, attrs: { draggable: 'true' }, title: 'drag into the scene' },
    category ? picture(category) : null,
    h('div', { class: 'part-text' }, h('b', { text: label }), h('span', { class: 'meta', text: meta })),
  );
  li.addEventListener('dragstart', (e) => {
    e.dataTransfer?.setData(PART_MIME, ref);
    e.dataTransfer?.setData('text/plain', label);
    if (e.dataTransfer) e.dataTransfer.effectAllowed = 'copy';
  });
  if (onPick) li.addEventListener('click', () => onPick({ ref, label }));
  return li;
}

export function renderSearch(res: AssetSearch, onPick?: (p: PartChoice) => void): HTMLElement {
  const mine = [...res.similar, ...res.mine.filter((m) => !res.similar.some((s) => s.id === m.id))];
  return h(
    'div',
    { class: 'parts' },
    res.note ? notice('info', res.note) : null,
    h('h4', { text: 'Your parts' }),
    mine.length
      ? h(
          'ul',
          { id: 'my-parts' },
          ...mine.map((a) =>
            item(a.id, a.description, [a.source, fmtSize(a.size), a.score !== null ? `match ${a.score.toFixed(2)}` : ''].filter(Boolean).join(' · '), onPick),
          ),
        )
      : h('p', { class: 'muted', text: 'None yet: parts made in the asset studio appear here.' }),
    h('h4', { text: 'Catalog' }),
    h('ul', { id: 'catalog-parts' }, ...res.catalog.slice(0, 40).map((c) => item(`catalog:${c.name}`, c.display, fmtSize(c.size), onPick))),
  );
}

/** A search box over the library with its results below; `refresh` searches again. */
export function partsBrowser(onPick?: (p: PartChoice) => void): HTMLElement & { refresh: () => void } {
  const q = h('input', { class: 'part-search', placeholder: 'search by meaning: “a bracket with holes”' });
  const out = h('div', { class: 'part-results' });
  let seq = 0;
  const run = async () => {
    const mine = ++seq;
    try {
      const res = await api.searchAssets(q.value.trim());
      if (mine === seq) fill(out, renderSearch(res, onPick));
    } catch (e) {
      if (mine === seq) fill(out, notice('error', `The library did not answer: ${api.describe(e)}.`));
    }
  };
  let timer: ReturnType<typeof setTimeout> | null = null;
  q.addEventListener('input', () => {
    if (timer !== null) clearTimeout(timer);
    timer = setTimeout(() => void run(), 250);
  });
  void run();
  return Object.assign(h('div', { class: 'parts-browser' }, q, out), { refresh: () => void run() });
}
