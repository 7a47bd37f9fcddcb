// My scenes: the user's scenes (thumbnails rendered by the server, newest first) with a
// download of each package, and their jobs.

import * as api from '../api';
import { fill, fmtDate, h, notice } from '../dom';
import type { View } from '../router';
import * as session from '../session';

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

export const scenesView: View = (root) => {
  const status = h('div', { class: 'status' });
  const grid = h('div', { class: 'scene-grid', id: 'scene-grid' }, notice('info', 'Loading your scenes…'));
  const jobs = h('table', { class: 'jobs', id: 'jobs' });
  root.append(h('div', { class: 'page' }, h('h1', { text: 'My scenes' }), status, grid, h('h2', { text: 'Jobs' }), jobs));
  const err = (m: string) => fill(status, notice('error', m));
  api
    .scenes()
    .then((list) => {
      if (!list.length) {
        fill(grid, h('p', { class: 'muted' }, 'No scenes yet. ', h('a', { href: '/', text: 'Describe one.' })));
        return;
      }
      fill(
        grid,
        ...list.map((s) =>
          h(
            'div',
            { class: 'scene-card card', data: { scene: s.id } },
            h('a', { href: `/scenes/${s.id}` }, thumbnail(s.id)),
            h('a', { href: `/scenes/${s.id}`, class: 'prompt', text: s.scene_prompt }),
            s.version > 1 ? h('div', { class: 'muted edit-line', text: s.prompt }) : null,
            h('div', { class: 'row' }, h('span', { class: `badge ${s.status}`, text: s.status }), h('span', { class: 'tag', text: `v${s.version}` }), h('span', { class: 'muted', text: fmtDate(s.created_at) })),
            downloadButton(s.id, err),
          ),
        ),
      );
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
