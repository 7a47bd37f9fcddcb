#!/usr/bin/env node
// The web app's targets, measured in headless Chromium (Debian's, SwiftShader WebGL) against
// `scenewright serve` on loopback (prefer a release build: SCENEWRIGHT_BIN=target/release/…):
//   - first frame after a job completes: a 5-object scene (≤ 1 s) and a robot-pack scene
//     (≤ 3 s) — from the moment the job page shows the result to the first frame drawn
//     with the model, clicking through as a user does; and a cold load of the scene's URL;
//   - the page's JS + wasm transfer, as Chromium receives it (≤ 4 MB gzipped);
//   - stepping speed of a ~50-object scene in the browser's worker (≥ real time);
//   - memory over 20 scene loads in one page (WASM heap, JS heap, GPU objects: flat).
// Prints one JSON document (and a readable summary on stderr).
//
//   node scripts/bench.mjs [--runs N]

import { chromium } from 'playwright-core';
import fs from 'node:fs';
import path from 'node:path';
import { CHROMIUM, WEB, startServer } from '../tests/lib/server.mjs';

const runsArg = process.argv.indexOf('--runs');
const RUNS = runsArg > 0 ? Number(process.argv[runsArg + 1]) : 5;
const PASSWORD = 'correct horse battery';
const SMALL = 'a small office with a desk, a chair, a cabinet, a shelf and a plant';
const PACK = { prompt: 'a lab with a workbench and a shelf', robots: ['robosuite_panda'] };
const LARGE = 'a 24 by 16 m warehouse with twelve shelving racks, thirty cardboard boxes, four pallets and four crates';

const say = (m) => process.stderr.write(`${m}\n`);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const stats = (xs) => ({ median: +median(xs).toFixed(1), min: +Math.min(...xs).toFixed(1), max: +Math.max(...xs).toFixed(1), runs: xs.length });

async function json(server, token, method, url, body) {
  const r = await fetch(`${server.url}${url}`, {
    method,
    headers: { ...(token ? { authorization: `Bearer ${token}` } : {}), ...(body ? { 'content-type': 'application/json' } : {}) },
    body: body ? JSON.stringify(body) : undefined,
  });
  if (!r.ok) throw new Error(`${method} ${url}: ${r.status} ${await r.text()}`);
  return r.json();
}

async function waitReady(page) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.getElementById('viewer')?.dataset.state ?? ''), null, { timeout: 120_000 });
  if ((await page.locator('#viewer').getAttribute('data-state')) !== 'ready') throw new Error(await page.locator('#viewer-status').innerText());
}

/** Submits a job from the page's session, watches its page, opens the scene: ms from result to first frame. */
async function firstFrameAfterJob(page, server, token, body) {
  const { job_id } = await json(server, token, 'POST', '/api/jobs', body);
  await page.goto(`${server.url}/jobs/${job_id}`);
  await page.locator('#open-scene').waitFor({ timeout: 300_000 });
  const t0 = await page.evaluate(() => performance.now());
  await page.click('#open-scene');
  await waitReady(page);
  const r = await page.evaluate(() => ({ ff: window.__sw.firstFrameAt, timings: window.__sw.timings, bodies: window.__sw.bodies().length }));
  const scene = await page.evaluate(() => location.pathname.split('/')[2]);
  return { ms: r.ff - t0, timings: r.timings, bodies: r.bodies, scene };
}

/** A fresh page opening a scene's URL: ms from navigation start to the first frame. */
async function coldLoad(ctx, server, token, scene) {
  const page = await ctx.newPage();
  await page.goto(`${server.url}/signin`);
  await page.evaluate(([t]) => sessionStorage.setItem('scenewright.token', t), [token]);
  await page.goto(`${server.url}/scenes/${scene}`);
  await waitReady(page);
  const ms = await page.evaluate(() => window.__sw.firstFrameAt);
  await page.close();
  return ms;
}

async function main() {
  const server = await startServer();
  const browser = await chromium.launch(CHROMIUM);
  const out = { date: new Date().toISOString().slice(0, 10), browser: browser.version(), binary: process.env.SCENEWRIGHT_BIN ?? 'newest target/*/scenewright' };
  try {
    await json(server, null, 'POST', '/api/auth/register', { username: 'bench', password: PASSWORD });
    const { token } = await json(server, null, 'POST', '/api/auth/login', { username: 'bench', password: PASSWORD });

    // --- Transfer: what Chromium downloads for the app (first visit, empty cache) ---
    const ctx0 = await browser.newContext({ viewport: { width: 1180, height: 760 } });
    const p0 = await ctx0.newPage();
    const cdp = await ctx0.newCDPSession(p0);
    await cdp.send('Network.enable');
    const sizes = new Map();
    const urls = new Map();
    cdp.on('Network.responseReceived', (e) => urls.set(e.requestId, { url: e.response.url, enc: e.response.headers['content-encoding'] ?? e.response.headers['Content-Encoding'] ?? '' }));
    cdp.on('Network.loadingFinished', (e) => sizes.set(e.requestId, e.encodedDataLength));
    await p0.goto(`${server.url}/signin`);
    await p0.evaluate(([t]) => sessionStorage.setItem('scenewright.token', t), [token]);
    await p0.goto(`${server.url}/`);
    await p0.waitForLoadState('networkidle');
    await ctx0.close();
    // The worker and its wasm, fetched by the worker (not seen by the page's session): the
    // same files asked for as Chromium asks (br, gzip).
    const dist = path.join(WEB, 'dist', 'assets');
    const workerFiles = fs.readdirSync(dist).filter((f) => /^(sim\.worker|mujoco)-.*\.(js|wasm)$/.test(f));
    let workerBytes = 0;
    const workerSeen = [];
    for (const f of workerFiles) {
      // Node's fetch decodes the body: the bytes on the wire are the Content-Length.
      const r = await fetch(`${server.url}/assets/${f}`, { headers: { 'accept-encoding': 'gzip, deflate, br, zstd' } });
      await r.arrayBuffer();
      const n = Number(r.headers.get('content-length'));
      workerBytes += n;
      workerSeen.push(`/assets/${f} ${r.headers.get('content-encoding') ?? 'identity'} ${n}`);
    }
    let pageBytes = 0;
    const seen = [];
    for (const [id, n] of sizes) {
      const u = urls.get(id);
      if (u && /\/(assets\/|$|signin)/.test(new URL(u.url).pathname)) {
        pageBytes += n;
        seen.push(`${new URL(u.url).pathname} ${u.enc || 'identity'} ${n}`);
      }
    }
    const gz = (re) => fs.readdirSync(dist).filter((f) => re.test(f) && !/\.(br|gz)$/.test(f)).reduce((s, f) => s + fs.statSync(path.join(dist, `${f}.gz`)).size, 0);
    out.transfer = {
      page_bytes: pageBytes,
      worker_and_wasm_bytes: workerBytes,
      total_mb: +((pageBytes + workerBytes) / 1e6).toFixed(2),
      gzip_js_wasm_mb: +(gz(/\.(js|wasm)$/) / 1e6).toFixed(2),
      responses: [...seen, ...workerSeen],
    };
    say(`transfer: ${out.transfer.total_mb} MB as Chromium receives it (brotli); JS + wasm gzipped ${out.transfer.gzip_js_wasm_mb} MB`);

    // --- First frame after the job completes ---
    const ctx = await browser.newContext({ viewport: { width: 1180, height: 760 } });
    const page = await ctx.newPage();
    await page.goto(`${server.url}/signin`);
    await page.evaluate(([t]) => sessionStorage.setItem('scenewright.token', t), [token]);
    const small = [];
    const pack = [];
    let smallScene = null;
    let packScene = null;
    let smallDetail = null;
    let packDetail = null;
    for (let k = 0; k < RUNS; k++) {
      const s = await firstFrameAfterJob(page, server, token, { prompt: SMALL, seed: 100 + k });
      small.push(s.ms);
      smallScene ??= s.scene;
      smallDetail ??= s;
      const p = await firstFrameAfterJob(page, server, token, { ...PACK, seed: 200 + k });
      pack.push(p.ms);
      packScene ??= p.scene;
      packDetail ??= p;
      say(`run ${k + 1}: 5-object scene ${s.ms.toFixed(0)} ms, robot pack ${p.ms.toFixed(0)} ms (fetch ${p.timings.fetchMs.toFixed(0)}, compile ${p.timings.compileMs.toFixed(0)} ms, ${(p.timings.bytes / 1e6).toFixed(1)} MB)`);
    }
    const smallLayout = await json(server, token, 'GET', `/api/scenes/${smallScene}/files/layout.json`);
    out.first_frame_ms = {
      five_objects: { ...stats(small), objects: smallLayout.objects.length, worker: smallDetail.timings },
      robot_pack: { ...stats(pack), robot: PACK.robots[0], worker: packDetail.timings },
    };
    const coldSmall = [];
    const coldPack = [];
    for (let k = 0; k < Math.min(RUNS, 3); k++) {
      coldSmall.push(await coldLoad(ctx, server, token, smallScene));
      coldPack.push(await coldLoad(ctx, server, token, packScene));
    }
    out.cold_url_load_ms = { five_objects: stats(coldSmall), robot_pack: stats(coldPack) };
    say(`first frame after the job: 5 objects ${median(small).toFixed(0)} ms, robot pack ${median(pack).toFixed(0)} ms; cold URL loads ${median(coldSmall).toFixed(0)} / ${median(coldPack).toFixed(0)} ms`);

    // --- Stepping a large scene in the browser ---
    const large = await firstFrameAfterJob(page, server, token, { prompt: LARGE, seed: 7 });
    const largeLayout = await json(server, token, 'GET', `/api/scenes/${large.scene}/files/layout.json`);
    const bench = await page.evaluate(() => window.__sw.bench(5));
    await page.click('#play');
    await page.waitForTimeout(4000);
    const live = await page.evaluate(() => window.__sw.realtime);
    await page.click('#play');
    out.stepping = {
      objects: largeLayout.objects.length,
      bodies: large.bodies,
      flat_out_x_realtime: +(bench.simSeconds / bench.wallSeconds).toFixed(2),
      steps_per_s: Math.round(bench.steps / bench.wallSeconds),
      playing_x_realtime: +live.toFixed(2),
    };
    say(`stepping ${largeLayout.objects.length} objects: ${out.stepping.flat_out_x_realtime}× real time flat out, ${out.stepping.playing_x_realtime}× while playing and drawing`);

    // --- Memory over 20 loads in one page (in-app navigation, one worker) ---
    const scenes = [smallScene, large.scene, packScene, smallScene];
    const session = await ctx.newCDPSession(page);
    await session.send('Performance.enable');
    const mem = [];
    for (let k = 0; k < 20; k++) {
      const id = scenes[k % scenes.length];
      await page.evaluate((sid) => {
        history.pushState(null, '', `/scenes/${sid}`);
        dispatchEvent(new PopStateEvent('popstate'));
      }, id);
      await waitReady(page);
      const gpu = await page.evaluate(() => window.__sw.renderInfo());
      const heap = await page.evaluate(() => window.__sw.unload());
      await session.send('HeapProfiler.collectGarbage');
      const metrics = (await session.send('Performance.getMetrics')).metrics;
      const js = metrics.find((m) => m.name === 'JSHeapUsedSize')?.value ?? 0;
      mem.push({ load: k + 1, wasm_heap_mb: +(heap / 1048576).toFixed(1), js_heap_mb: +(js / 1048576).toFixed(1), geometries: gpu.geometries, textures: gpu.textures });
    }
    out.memory_over_20_loads = { first: mem[0], fifth: mem[4], last: mem[19], all: mem };
    say(`memory: load 1 wasm ${mem[0].wasm_heap_mb} MB / js ${mem[0].js_heap_mb} MB; load 20 wasm ${mem[19].wasm_heap_mb} MB / js ${mem[19].js_heap_mb} MB`);
    await ctx.close();
  } finally {
    await browser.close();
    await server.stop();
  }
  console.log(JSON.stringify(out, null, 1));
}

await main();
