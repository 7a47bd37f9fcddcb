// The app's entry: the header, the routes, and a last line of defence that turns any
// uncaught failure into a visible message (never a blank page).

import './style.css';
import * as api from './api';
import { h } from './dom';
import { navigate, route, start } from './router';
import * as session from './session';
import { composeView } from './views/compose';
import { jobView } from './views/job';
import { sceneView } from './views/scene';
import { scenesView } from './views/scenes';
import { settingsView } from './views/settings';
import { signInView } from './views/signin';
import { studioView } from './views/studio';

route('/signin', signInView, true);
route('/', composeView);
route('/jobs/:id', jobView);
route('/scenes', scenesView);
route('/scenes/:id', sceneView);
route('/studio', studioView);
route('/settings', settingsView);

const app = document.getElementById('app') ?? document.body;
const user = h('span', { class: 'user' });
const out = h('button', {
  class: 'link',
  text: 'Sign out',
  id: 'signout',
  on: {
    click: () => {
      // The token is revoked on the server, not only forgotten here.
      void api.logout().finally(() => {
        session.signOut();
        navigate('/signin');
      });
    },
  },
});
const nav = h(
  'nav',
  {},
  h('a', { href: '/', text: 'Compose', data: { nav: '/' } }),
  h('a', { href: '/scenes', text: 'My scenes', data: { nav: '/scenes' } }),
  h('a', { href: '/studio', text: 'Asset studio', data: { nav: '/studio' } }),
  h('a', { href: '/settings', text: 'Settings', data: { nav: '/settings' } }),
);
const header = h('header', { class: 'top' }, h('a', { class: 'brand', href: '/', text: 'scenewright' }), nav, h('div', { class: 'who' }, user, out));
const banner = h('div', { class: 'banner', id: 'banner', attrs: { role: 'alert' } });
const main = h('main', { id: 'main' });
app.replaceChildren(header, banner, main);

function fail(what: string): void {
  banner.textContent = `Something went wrong: ${what}. Reload the page to try again.`;
  banner.classList.add('on');
}
window.addEventListener('error', (e) => fail(e.message || 'a script failed'));
window.addEventListener('unhandledrejection', (e) => fail(e.reason instanceof Error ? e.reason.message : String(e.reason)));

start(main, (path) => {
  const signedIn = session.token() !== null;
  header.classList.toggle('signed-out', !signedIn);
  user.textContent = session.username() ?? '';
  for (const a of nav.querySelectorAll('a')) {
    const target = a.dataset.nav ?? '';
    a.classList.toggle('on', target === '/' ? path === '/' : path.startsWith(target) && !(target === '/scenes' && path.startsWith('/scenes/')));
  }
  banner.classList.remove('on');
});
