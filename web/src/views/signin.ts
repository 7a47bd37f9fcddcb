// Sign in or register. The token is kept for the browser session; afterwards the visitor
// goes back to the page they were sent here from.

import * as api from '../api';
import { fill, h, notice } from '../dom';
import { navigate, type View } from '../router';
import * as session from '../session';

/** Only paths inside the app are followed after signing in. */
function safeNext(q: URLSearchParams): string {
  const next = q.get('next') ?? '/';
  return next.startsWith('/') && !next.startsWith('//') && !next.startsWith('/signin') ? next : '/';
}

export const signInView: View = (root, _params, query) => {
  const status = h('div', { class: 'status' });
  // A reason code from the address, worded here: text in the URL is never shown.
  const reason = session.reasonText(query.get('reason'));
  if (reason) fill(status, notice('info', reason));
  const user = h('input', { id: 'username', placeholder: 'user name', attrs: { autocomplete: 'username', required: '' } });
  const pass = h('input', {
    id: 'password',
    type: 'password',
    placeholder: 'password (8 characters or more)',
    attrs: { autocomplete: 'current-password', required: '' },
  });
  const busy = (on: boolean) => {
    for (const b of form.querySelectorAll('button')) b.disabled = on;
  };
  const done = async () => {
    const signedIn = await api.login(user.value.trim(), pass.value);
    session.signIn(signedIn.token, signedIn.username);
    navigate(safeNext(query), true);
  };
  const act = (register: boolean) => async (e: Event) => {
    e.preventDefault();
    if (!user.value.trim() || !pass.value) {
      fill(status, notice('error', 'Enter a user name and a password.'));
      return;
    }
    busy(true);
    fill(status, notice('info', register ? 'Creating your account…' : 'Signing in…'));
    try {
      if (register) await api.register(user.value.trim(), pass.value);
      await done();
    } catch (err) {
      fill(status, notice('error', `${register ? 'Registration' : 'Sign-in'} failed: ${api.describe(err)}.`));
      busy(false);
    }
  };
  const form = h(
    'form',
    { class: 'card narrow', on: { submit: (e) => void act(false)(e) } },
    h('h1', { text: 'Sign in to scenewright' }),
    h('p', { class: 'muted', text: 'Describe a robot workspace in plain English; get a verified MuJoCo scene.' }),
    h('label', { text: 'User name' }, user),
    h('label', { text: 'Password' }, pass),
    h(
      'div',
      { class: 'row' },
      h('button', { id: 'signin', type: 'submit', class: 'primary', text: 'Sign in' }),
      h('button', { id: 'register', type: 'button', text: 'Register', on: { click: (e) => void act(true)(e) } }),
    ),
    status,
  );
  root.append(h('div', { class: 'page center' }, form));
  user.focus();
};
