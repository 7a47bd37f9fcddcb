// The signed-in user's access token, kept for the browser session (sessionStorage: it
// survives reloads of the tab, not closing it), and what happens when it stops working.

const KEY = 'scenewright.token';
const USER = 'scenewright.user';

type Listener = (reason: string) => void;
let onExpired: Listener | null = null;

export function token(): string | null {
  return sessionStorage.getItem(KEY);
}

export function username(): string | null {
  return sessionStorage.getItem(USER);
}

export function signIn(t: string, user: string): void {
  sessionStorage.setItem(KEY, t);
  sessionStorage.setItem(USER, user);
}

export function signOut(): void {
  sessionStorage.removeItem(KEY);
  sessionStorage.removeItem(USER);
}

/** The router's reaction to a token the server no longer accepts. */
export function whenExpired(l: Listener): void {
  onExpired = l;
}

export function expire(reason: string): void {
  signOut();
  onExpired?.(reason);
}
