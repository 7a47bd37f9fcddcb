// The asset studio: search the library by meaning, make a part from text (the forge's
// progress as it comes, and the failure kinds when it cannot be made), a 3D preview of its
// mesh with its size, and the way into a scene (the scene's Parts tab takes it by drag).

import * as api from '../api';
import { fill, fmtSize, h, notice } from '../dom';
import { navigate, type View } from '../router';
import type { Asset } from '../types';
import { PartPreview, parseStl } from '../viewer/preview';
import { type PartChoice, partsBrowser } from './parts';

export const studioView: View = (root) => {
  const previewHost = h('div', { class: 'preview', id: 'preview' });
  const preview = new PartPreview(previewHost);
  const info = h('div', { class: 'part-info', id: 'part-info' }, h('p', { class: 'muted', text: 'Pick a part or make one to see it here.' }));
  const progress = h('ol', { class: 'progress', id: 'forge-progress' });
  const status = h('div', { class: 'status', id: 'forge-status' });
  const desc = h('textarea', { id: 'part-description', placeholder: 'a mounting plate 120 x 80 x 6 mm with four 8 mm holes', attrs: { rows: '3' } });
  const size = ['w', 'd', 'h'].map((k) => h('input', { type: 'number', class: 'size', placeholder: `${k} (mm)`, data: { axis: k }, attrs: { min: '0.5', step: '0.5' } }));
  const target = h('select', { id: 'target-scene' }, h('option', { value: '', text: 'choose a scene…' }));
  let current: PartChoice | null = null;
  const library = partsBrowser((p) => pick(p));

  const showAsset = async (a: Asset) => {
    current = { ref: a.id, label: a.description };
    preview.clear();
    previewHost.dataset.part = '';
    fill(info, h('h3', { text: a.description }), h('p', {}, `${a.source} · ${fmtSize(a.size)}`));
    if (!a.hasMesh) return;
    try {
      const dims = preview.show(parseStl(await api.assetMesh(a.id)));
      previewHost.dataset.part = a.id;
      info.append(h('p', { id: 'mesh-size', text: `mesh ${dims.map((v) => (v * 1000).toFixed(1)).join(' × ')} mm` }));
    } catch (e) {
      info.append(notice('error', `The mesh did not load: ${api.describe(e)}.`));
    }
  };
  function pick(p: PartChoice): void {
    current = p;
    if (p.ref.startsWith('catalog:')) {
      preview.clear();
      previewHost.dataset.part = '';
      const name = p.ref.slice('catalog:'.length);
      const img = h('img', { id: 'catalog-picture', class: 'catalog-picture', attrs: { alt: `${p.label}, as the catalog makes it`, width: '256', height: '256', src: api.catalogPictureUrl(name) } });
      img.addEventListener('error', () => img.replaceWith(h('p', { class: 'muted', text: 'The picture could not be drawn.' })));
      fill(info, h('h3', { text: p.label }), img, h('p', { class: 'muted', text: 'A catalog category: made procedurally in each scene, in a size and variant of its own (the picture is one of them).' }));
      return;
    }
    api
      .asset(p.ref)
      .then(showAsset)
      .catch((e: unknown) => fill(info, notice('error', api.describe(e))));
  }

  const make = async () => {
    const text = desc.value.trim();
    if (!text) return fill(status, notice('error', 'Describe the part first.'));
    const mm = size.map((s) => Number(s.value));
    const given = size.some((s) => s.value !== '');
    if (given && !mm.every((v) => v > 0)) return fill(status, notice('error', 'Give all three sizes in millimetres, or none.'));
    const sizeM: [number, number, number] | null = given ? [(mm[0] ?? 0) / 1000, (mm[1] ?? 0) / 1000, (mm[2] ?? 0) / 1000] : null;
    progress.replaceChildren();
    // The part shown is no longer the one asked for: the preview and its facts go.
    current = null;
    preview.clear();
    previewHost.dataset.part = '';
    fill(info, h('p', { class: 'muted', text: `Making “${text}”…` }));
    fill(status, notice('info', 'Making the part…'));
    const started = performance.now();
    try {
      const a = await api.makeAsset(text, sizeM, (ev) => {
        const t = `${((performance.now() - started) / 1000).toFixed(1)} s`;
        if (ev.event === 'progress') progress.append(h('li', { text: `${t} ${ev.message}` }));
        if (ev.event === 'failure') progress.append(h('li', { class: 'bad', data: { kind: ev.kind } }, `${t} attempt ${ev.attempt} failed: `, h('b', { text: ev.kind }), ` — ${ev.message}`));
      });
      fill(status, notice('ok', `Made: ${a.description} (${a.source}).`));
      library.refresh();
      await showAsset(a);
    } catch (e) {
      fill(status, notice('error', `The part could not be made: ${api.describe(e)}.`));
      fill(info, h('p', { class: 'muted', text: 'Nothing to show: the part was not made.' }));
    }
  };

  api
    .scenes()
    .then((list) => target.append(...list.slice(0, 30).map((s) => h('option', { value: s.id, text: `v${s.version} ${s.prompt.slice(0, 60)}` }))))
    .catch(() => undefined);
  const use = () => {
    if (!current) return fill(status, notice('error', 'Pick or make a part first.'));
    if (!target.value) return fill(status, notice('error', 'Choose the scene to put it in.'));
    navigate(`/scenes/${target.value}?tab=parts&part=${encodeURIComponent(current.ref)}`);
  };

  root.append(
    h(
      'div',
      { class: 'page studio' },
      h(
        'section',
        { class: 'card' },
        h('h1', { text: 'Asset studio' }),
        h('h2', { text: 'Make a part' }),
        desc,
        h('div', { class: 'row' }, ...size, h('button', { id: 'make-part', class: 'primary', text: 'Make it', on: { click: () => void make() } })),
        status,
        progress,
        h('h2', { text: 'Library' }),
        library,
      ),
      h(
        'section',
        { class: 'card' },
        previewHost,
        info,
        h('h3', { text: 'Use it in a scene' }),
        h('div', { class: 'row' }, target, h('button', { id: 'use-part', text: 'Open it', on: { click: use } })),
        h('p', { class: 'muted', text: 'The scene opens with its Parts tab: drag the part onto the floor where it should stand.' }),
      ),
    ),
  );
  return () => preview.dispose();
};
