// The signed-in user's access token, kept for the browser session (sessionStorage: it
// survives reloads of the tab, not closing it), and what happens when it stops working.

const KEY = 'scenewright.token';
const USER = 'scenewright.user';

/** Why a session ended, as the sign-in page's address says it (a code, never free text). */
export type EndReason = 'expired' | 'revoked' | 'signin';

/** The sign-in page's sentence for a reason code; anything else in the address is ignored. */
export function reasonText(code: string | null): string | null {
  switch (code) {
    case 'expired':
      return 'Your session expired; sign in again.';
    case 'revoked':
      return 'Your session was signed out; sign in again.';
    case 'signin':
      return 'Sign in to continue.';
    default:
      return null;
  }
}

/** The reason code for the server's message refusing a token. */
export function reasonOf(message: string): EndReason {
  if (/expired/i.test(message)) return 'expired';
  if (/revoked|signed out/i.test(message)) return 'revoked';
  return 'signin';
}

type Listener = (reason: EndReason) => void;
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

export function expire(reason: EndReason): void {
  signOut();
  onExpired?.(reason);
}
