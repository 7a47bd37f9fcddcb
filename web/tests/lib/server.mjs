// Starts `scenewright serve` for a test or a benchmark: a free loopback port, a fresh
// data directory, the built app; stops it (and removes the directory) when asked, when
// the process exits, and on Ctrl-C — a failing test leaves no server behind.

import { spawn } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';

export const WEB = path.resolve(import.meta.dirname, '..', '..');
export const ROOT = path.resolve(WEB, '..');

/** The scenewright binary: SCENEWRIGHT_BIN, else the newest of target/{debug,release}. */
export function binary() {
  if (process.env.SCENEWRIGHT_BIN) return process.env.SCENEWRIGHT_BIN;
  const found = ['debug', 'release']
    .map((p) => path.join(ROOT, 'target', p, 'scenewright'))
    .filter((p) => fs.existsSync(p))
    .sort((a, b) => fs.statSync(b).mtimeMs - fs.statSync(a).mtimeMs);
  if (!found.length) throw new Error('no scenewright binary: run cargo build -p sw_cli or set SCENEWRIGHT_BIN');
  return found[0];
}

async function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once('error', reject);
    s.listen(0, '127.0.0.1', () => {
      const { port } = s.address();
      s.close(() => resolve(port));
    });
  });
}

const running = new Set();
function stopAll() {
  for (const s of running) s.stopSync();
}
process.on('exit', stopAll);
for (const sig of ['SIGINT', 'SIGTERM']) {
  process.on(sig, () => {
    stopAll();
    process.exit(130);
  });
}

/**
 * A running server: `{ url, data, stop() }`. `args` are extra `serve` arguments, `workers`
 * its job runners.
 * `env` adds environment variables (e.g. SCENEWRIGHT_ASSET_STORE).
 */
export async function startServer({ args = [], env = {}, log = false, workers = 2 } = {}) {
  const port = await freePort();
  const data = fs.mkdtempSync(path.join(os.tmpdir(), 'sw-web-'));
  const bin = binary();
  const child = spawn(
    bin,
    ['serve', '--addr', `127.0.0.1:${port}`, '--data', data, '--web', path.join(WEB, 'dist'), '--workers', String(workers), ...args],
    { env: { ...process.env, SCENEWRIGHT_ASSET_STORE: path.join(data, 'assets'), ...env }, stdio: ['ignore', 'ignore', 'pipe'] },
  );
  let stderr = '';
  const ready = new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`the server did not start in 60 s:\n${stderr}`)), 60_000);
    child.stderr.on('data', (d) => {
      stderr += d.toString();
      if (log) process.stderr.write(d);
      if (stderr.includes('listening on http://')) {
        clearTimeout(timer);
        resolve();
      }
    });
    child.once('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`the server exited (${code}) before listening:\n${stderr}`));
    });
  });
  const server = {
    url: `http://127.0.0.1:${port}`,
    data,
    child,
    log: () => stderr,
    stopSync() {
      if (child.exitCode === null && child.signalCode === null) child.kill('SIGKILL');
      fs.rmSync(data, { recursive: true, force: true });
      running.delete(server);
    },
    async stop() {
      if (child.exitCode === null && child.signalCode === null) {
        const gone = new Promise((r) => child.once('exit', r));
        child.kill('SIGTERM');
        const t = setTimeout(() => child.kill('SIGKILL'), 8000);
        await gone;
        clearTimeout(t);
      }
      fs.rmSync(data, { recursive: true, force: true });
      running.delete(server);
    },
  };
  running.add(server);
  try {
    await ready;
  } catch (e) {
    server.stopSync();
    throw e;
  }
  return server;
}

/** Chromium from Debian through playwright-core (never a downloaded browser). */
export const CHROMIUM = {
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  args: [
    '--use-angle=swiftshader',
    '--enable-unsafe-swiftshader',
    '--no-sandbox',
    '--no-first-run',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
  ],
};
