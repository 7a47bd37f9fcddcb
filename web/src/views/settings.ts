// Settings: who is signed in, and API keys for scripts (a new key is shown once; any key
// can be revoked).

import * as api from '../api';
import { fill, fmtDate, h, notice } from '../dom';
import type { View } from '../router';
import type { ApiKey } from '../types';

export const settingsView: View = (root) => {
  const who = h('p', { class: 'muted', text: 'loading…' });
  const list = h('ul', { class: 'keys', id: 'keys' });
  const status = h('div', { class: 'status', id: 'key-status' });
  const name = h('input', { id: 'key-name', placeholder: 'a name for the key (e.g. laptop script)' });
  const revoke = (k: ApiKey) => {
    if (!window.confirm(`Revoke the key "${k.name}"? Scripts using it stop working at once.`)) return;
    api
      .revokeKey(k.id)
      .then(() => {
        fill(status, notice('ok', `The key "${k.name}" is revoked.`));
        return refresh();
      })
      .catch((e: unknown) => fill(status, notice('error', `The key was not revoked: ${api.describe(e)}.`)));
  };
  const row = (k: ApiKey) =>
    h(
      'li',
      { data: { key: k.id } },
      h('b', { text: k.name }),
      ` created ${fmtDate(k.created_at)}`,
      h('code', { text: ` ${k.id.slice(0, 8)}…` }),
      h('button', { class: 'revoke', text: 'Revoke', on: { click: () => revoke(k) } }),
    );
  const refresh = () =>
    api
      .keys()
      .then((ks) => fill(list, ...(ks.length ? ks.map(row) : [h('li', { class: 'muted', text: 'No API keys yet.' })])))
      .catch((e: unknown) => fill(list, notice('error', `The keys did not load: ${api.describe(e)}.`)));
  const create = async () => {
    if (!name.value.trim()) return fill(status, notice('error', 'Give the key a name.'));
    try {
      const k = await api.createKey(name.value.trim());
      fill(
        status,
        notice('ok', 'Copy this key now; it is not shown again:'),
        h('code', { class: 'secret', id: 'new-key', text: k.secret }),
        h('p', { class: 'muted', text: 'Use it as Authorization: Bearer <key> or X-API-Key: <key>.' }),
      );
      name.value = '';
      await refresh();
    } catch (e) {
      fill(status, notice('error', `The key was not created: ${api.describe(e)}.`));
    }
  };
  root.append(
    h(
      'div',
      { class: 'page narrow-page' },
      h('h1', { text: 'Settings' }),
      who,
      h('h2', { text: 'API keys' }),
      list,
      h('div', { class: 'row' }, name, h('button', { id: 'create-key', class: 'primary', text: 'Create a key', on: { click: () => void create() } })),
      status,
    ),
  );
  api
    .me()
    .then((u) => fill(who, `Signed in as ${u.username} (${u.role}).`))
    .catch((e: unknown) => fill(who, notice('error', api.describe(e))));
  void refresh();
};
