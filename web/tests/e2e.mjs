#!/usr/bin/env node
// The web app end to end, in headless Chromium (Debian's, through playwright-core) against
// a real `scenewright serve` on a free loopback port with a fresh data directory:
// register → refine → generate with a robot → the stage timeline completes → the canvas
// is not blank and bodies are drawn where the package puts them → click an object and
// read its panel → a sentence removes it → drag an object and see it moved → make a part
// in the studio and drag it in → versions and the way back → download the zip and load it
// with MuJoCo (WASM). Bad input: a dropped socket, a refused edit, a part that cannot be
// made, an expired token, another user's scene — each a clear message, never a blank page.
// Issue 22: a double-clicked Generate makes one job; the scene opens when its job ends;
// the report's contacts; keys (Space, ., F, Delete, Ctrl+Z) and the camera's frame and
// reset; a cancelled job's heading; another user's job and scene are "not found"; text
// with direction overrides cannot reorder the page; the sign-in page shows no text from
// its address; CSP and nosniff on every answer; My scenes grouped, searched and deleted
// from; an API key revoked; signing out revokes the token; the pages at 390 px.
// Screenshots of every page go to docs/web/ (SCREENSHOTS=0 skips writing them).
//
//   node tests/e2e.mjs          (SCENEWRIGHT_BIN picks the binary; CHROMIUM the browser)

import { execFileSync } from 'node:child_process';
import crypto from 'node:crypto';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import loadMujoco from '@mujoco/mujoco';
import { check, readZip } from '../scripts/load-packages.mjs';
import { CHROMIUM, ROOT, startServer } from './lib/server.mjs';

const SHOTS = path.join(ROOT, 'docs', 'web');
const WRITE_SHOTS = process.env.SCREENSHOTS !== '0';
const VIEWPORT = { width: 1180, height: 760 };
const PASSWORD = 'correct horse battery';
const started = Date.now();
let failures = 0;

function log(msg) {
  console.log(`[${((Date.now() - started) / 1000).toFixed(1).padStart(6)} s] ${msg}`);
}

function assert(cond, msg) {
  if (!cond) throw new Error(`assertion failed: ${msg}`);
}

async function shot(page, name) {
  if (!WRITE_SHOTS) return;
  fs.mkdirSync(SHOTS, { recursive: true });
  await page.screenshot({ path: path.join(SHOTS, `${name}.png`) });
}

/** The page is never blank: its main area holds visible text. */
async function notBlank(page, where) {
  const text = await page.locator('#main').innerText();
  assert(text.trim().length > 20, `${where}: the page is blank`);
}

async function api(server, token, method, url, body) {
  const r = await fetch(`${server.url}${url}`, {
    method,
    headers: { authorization: `Bearer ${token}`, ...(body ? { 'content-type': 'application/json' } : {}) },
    body: body ? JSON.stringify(body) : undefined,
  });
  const text = await r.text();
  let json;
  try {
    json = JSON.parse(text);
  } catch {
    json = text;
  }
  return { status: r.status, json };
}

/** Pixel statistics of a PNG, computed by decoding it in the page (no image library here). */
async function pixelStats(page, png, probes = []) {
  return page.evaluate(
    async ({ b64, probes }) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      const colours = new Set();
      let sum = 0;
      let sum2 = 0;
      const n = d.length / 4;
      for (let i = 0; i < d.length; i += 4) {
        const l = 0.299 * d[i] + 0.587 * d[i + 1] + 0.114 * d[i + 2];
        sum += l;
        sum2 += l * l;
        if (colours.size < 5000) colours.add((d[i] >> 3) * 1024 + (d[i + 1] >> 3) * 32 + (d[i + 2] >> 3));
      }
      const at = probes.map(([x, y]) => Array.from(g.getImageData(Math.round(x), Math.round(y), 1, 1).data.slice(0, 3)));
      return { colours: colours.size, std: Math.sqrt(sum2 / n - (sum / n) ** 2), at };
    },
    { b64: png.toString('base64'), probes },
  );
}

async function waitReady(page) {
  await page.waitForFunction(() => {
    const v = document.getElementById('viewer');
    return v && (v.dataset.state === 'ready' || v.dataset.state === 'error');
  }, null, { timeout: 90_000 });
  const state = await page.locator('#viewer').getAttribute('data-state');
  if (state !== 'ready') throw new Error(`the viewer failed: ${await page.locator('#viewer-status').innerText()}`);
}

async function waitForNewScene(page, from) {
  await page.waitForFunction((old) => location.pathname.startsWith('/scenes/') && location.pathname !== `/scenes/${old}`, from, { timeout: 180_000 });
  await waitReady(page);
  return page.evaluate(() => location.pathname.split('/')[2]);
}

/** An HS256 JWT signed with the server's secret, expired a minute ago. */
function expiredToken(server, user) {
  const secret = execFileSync('python3', [
    '-c',
    "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute(\"select value from settings where name='jwt_secret'\").fetchone()[0])",
    path.join(server.data, 'scenewright.db'),
  ])
    .toString()
    .trim();
  const b64 = (o) => Buffer.from(JSON.stringify(o)).toString('base64url');
  const now = Math.floor(Date.now() / 1000);
  const body = `${b64({ alg: 'HS256', typ: 'JWT' })}.${b64({ sub: user.id, role: user.role, iat: now - 7200, exp: now - 60 })}`;
  const sig = crypto.createHmac('sha256', secret).update(body).digest('base64url');
  return `${body}.${sig}`;
}

async function main() {
  // One runner: jobs wait in the queue behind each other (the cancel step needs a queued job).
  const server = await startServer({ workers: 1 });
  log(`server at ${server.url} (data ${server.data})`);
  const browser = await chromium.launch(CHROMIUM);
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'sw-e2e-'));
  try {
    const ctx = await browser.newContext({ viewport: VIEWPORT, acceptDownloads: true });
    const page = await ctx.newPage();
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));

    // --- The sign-in page words its reason itself: text in its address is never shown ---
    await page.goto(`${server.url}/signin?reason=${encodeURIComponent('Your account is locked: call 555-0100 now')}`);
    await page.locator('#username').waitFor();
    assert(!(await page.locator('body').innerText()).includes('555-0100'), 'the sign-in page printed text from its URL');
    // Every answer carries the security headers (the app's page, an asset, the API).
    for (const u of ['/', '/api/openapi.json', '/healthz']) {
      const r = await fetch(`${server.url}${u}`);
      const csp = r.headers.get('content-security-policy') ?? '';
      assert(csp.includes("frame-ancestors 'none'") && csp.includes("script-src 'self'"), `${u}: CSP ${csp}`);
      assert(r.headers.get('x-content-type-options') === 'nosniff', `${u}: no nosniff`);
    }
    log('sign-in shows no text from its URL; CSP, nosniff and frame-ancestors on every answer');

    // --- A signed-out visitor is sent to sign in, then back ---
    await page.goto(`${server.url}/scenes`);
    await page.waitForURL(/\/signin\?next=%2Fscenes/);
    await shot(page, '01-sign-in');
    await page.fill('#username', 'ann');
    await page.fill('#password', PASSWORD);
    await page.click('#register');
    await page.waitForURL(`${server.url}/scenes`);
    await page.getByText('No scenes yet').waitFor();
    const token = await page.evaluate(() => sessionStorage.getItem('scenewright.token'));
    assert(token, 'no token in the session');
    log('registered; back on /scenes');

    // --- Refine: the server's questions, turn by turn, then the final prompt ---
    await page.click('a[href="/"]');
    await page.fill('#prompt', 'a lab with a workbench and a shelf');
    await page.click('#refine');
    let turns = 0;
    let sized = false;
    for (;;) {
      await page.waitForFunction(() => document.querySelector('#chat-final blockquote') || !document.querySelector('#chat-answer').disabled, null, { timeout: 30_000 });
      if (await page.locator('#chat-final blockquote').count()) break;
      turns++;
      const question = await page.locator('.bubble.q').last().innerText();
      // The room's size when asked; after that, done.
      const answer = !sized && /room|big|size/i.test(question) ? '6 by 5 m' : sized ? 'done' : 'skip';
      sized ||= answer === '6 by 5 m';
      await page.fill('#chat-answer', answer);
      await page.click('#chat-send');
      if (turns > 9) throw new Error('the refinement did not end');
    }
    const final = await page.locator('#final-prompt').innerText();
    assert(sized, 'the chat asked for the room size');
    assert(/6\s*(by|x|×)\s*5/.test(final), `the final prompt holds the answer: ${final}`);
    await shot(page, '02-compose-refine');
    await page.click('#chat-accept');
    assert((await page.inputValue('#prompt')) === final, 'the accepted prompt is in the box');
    log(`refined in ${turns} turn(s): ${final}`);

    // --- Generate with a robot (double-clicked: one job) ---
    const jobsBefore = (await api(server, token, 'GET', '/api/jobs')).json.jobs.length;
    await page.fill('#prompt', `${final} Six boxes on the workbench and a cabinet.`);
    await page.locator('#robots [data-robot="ur5e"]').click();
    await page.dblclick('#generate');
    await page.waitForURL(/\/jobs\//);
    const firstJob = await page.evaluate(() => location.pathname.split('/')[2]);
    // Watched to its end, the scene opens by itself.
    await page.waitForURL(/\/scenes\//, { timeout: 150_000 });
    await waitReady(page);
    const jobsAfter = (await api(server, token, 'GET', '/api/jobs')).json.jobs.length;
    assert(jobsAfter === jobsBefore + 1, `a double click made ${jobsAfter - jobsBefore} jobs`);
    log('a double-clicked Generate made one job; the scene opened when it was done');
    // Its job page afterwards: the whole timeline, and a link (no second jump).
    await page.goto(`${server.url}/jobs/${firstJob}`);
    await page.locator('#open-scene').waitFor({ timeout: 30_000 });
    assert((await page.locator('#job-heading').innerText()) === 'The scene is built', 'the heading says it is built');
    for (const s of ['plan', 'forge', 'layout', 'bridge', 'verify']) {
      const cls = await page.locator(`.stage[data-stage="${s}"]`).getAttribute('class');
      assert(cls.includes('done'), `stage ${s} is ${cls}`);
      assert((await page.locator(`.stage[data-stage="${s}"] .time`).innerText()).length > 0, `stage ${s} has a time`);
    }
    assert((await page.locator('.stage[data-stage="layout"] .steps li').count()) >= 3, 'per-object steps are listed');
    await shot(page, '03-job-timeline');
    log('the stage timeline completed');

    // --- See it ---
    await page.click('#open-scene');
    await waitReady(page);
    const sceneId = await page.evaluate(() => location.pathname.split('/')[2]);
    const layout = (await api(server, token, 'GET', `/api/scenes/${sceneId}/files/layout.json`)).json;
    assert(layout.robots.length === 1 && layout.robots[0].model === 'ur5e', 'the scene has the UR5e');
    // Bodies are drawn where the package puts them (the home state, before playing).
    for (const o of layout.objects.slice(0, 6)) {
      const drawn = await page.evaluate((n) => window.__sw.bodyPosition(n), o.name);
      assert(drawn, `${o.name} is not drawn`);
      const d = Math.hypot(drawn[0] - o.pos[0], drawn[1] - o.pos[1], drawn[2] - o.pos[2]);
      assert(d < 0.01, `${o.name} drawn at ${drawn} but the package puts it at ${o.pos}`);
    }
    // The robot's first body stands where the layout spawned it.
    const robot = layout.robots[0];
    const robotBody = (await page.evaluate(() => window.__sw.bodies())).find((b) => b.startsWith(`${robot.name}_`));
    const rb = await page.evaluate((n) => window.__sw.bodyPosition(n), robotBody);
    assert(rb && Math.hypot(rb[0] - robot.pos[0], rb[1] - robot.pos[1]) < 0.01, `${robotBody} drawn at ${rb}, spawned at ${robot.pos}`);
    log(`bodies drawn where layout.json puts them (six objects; the robot's ${robotBody} at its spawn point)`);
    // The canvas is not blank, and an object's centre is not the background.
    const target = layout.objects.find((o) => o.category === 'shelf') ?? layout.objects[0];
    const at = await page.evaluate((n) => window.__sw.objectOnScreen(n), target.name);
    const box = await page.locator('#viewer').boundingBox();
    const png = await page.locator('#viewer').screenshot();
    const stats = await pixelStats(page, png, [[at.x - box.x, at.y - box.y], [5, 5]]);
    assert(stats.colours > 40 && stats.std > 12, `the canvas looks blank: ${JSON.stringify(stats)}`);
    log(`canvas: ${stats.colours} colours, luminance σ ${stats.std.toFixed(1)}; at ${target.name} ${stats.at[0]} vs corner ${stats.at[1]}`);

    // The report says how many contacts there are and how many are deep — not "N deeper".
    const detail = (await api(server, token, 'GET', `/api/scenes/${sceneId}`)).json;
    const deep = detail.report.verification.initial_contacts.deep.length;
    await page.locator('button[data-tab="report"]').click();
    const contactsLine = await page.locator('#report-panel dd').nth(await page.locator('#report-panel dt').allInnerTexts().then((t) => t.indexOf('at t = 0'))).innerText();
    assert(deep === 0 ? /none deeper than 1 mm/.test(contactsLine) : contactsLine.includes(`${deep} deeper than 1 mm`), `report: "${contactsLine}" with ${deep} deep`);
    log(`report: "${contactsLine}"`);

    // Click the object: its panel.
    await page.mouse.click(at.x, at.y);
    await page.locator(`#object-panel[data-object="${target.name}"]`).waitFor();
    const panel = await page.locator('#object-panel').innerText();
    assert(panel.includes(target.name) && panel.includes(target.support?.on === 'floor' ? 'the floor' : ''), `the panel names it: ${panel}`);
    assert(panel.includes('rests on') && panel.includes('size'), `the panel: ${panel}`);
    // F frames the selected object: the camera turns about it; Reset view goes back.
    const cam0 = await page.evaluate(() => window.__sw.camera());
    // Keys go to the page, not to a focused button (Space presses a focused button).
    await page.evaluate(() => document.activeElement?.blur?.());
    await page.keyboard.press('f');
    const cam1 = await page.evaluate(() => window.__sw.camera());
    // About the middle of the object: its origin is at its foot, half its height below.
    const foot = await page.evaluate((n) => window.__sw.bodyPosition(n), target.name);
    const tgt = [foot[0], foot[1], foot[2] + target.size[2] / 2];
    const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    assert(dist(cam1.target, tgt) < 0.25, `F framed around ${cam1.target}, the object's middle is at ${tgt}`);
    assert(dist(cam1.position, cam1.target) < dist(cam0.position, cam0.target), 'F moved the camera closer');
    await page.click('#reset-view');
    const cam2 = await page.evaluate(() => window.__sw.camera());
    assert(dist(cam2.position, cam0.position) < 1e-6 && dist(cam2.target, cam0.target) < 1e-6, 'Reset view is the first view');
    log('F framed the selected object; Reset view went back to the first view');
    // Play (Space): the robot holds its home pose as in native MuJoCo, and everything stays put.
    const posesNow = () =>
      page.evaluate(() => Object.fromEntries(window.__sw.bodies().slice(1).map((n) => [n, window.__sw.bodyPosition(n)])));
    const atHome = await posesNow();
    // (The Reset view button has the focus: Space would press it.)
    await page.evaluate(() => document.activeElement?.blur?.());
    await page.keyboard.press(' ');
    await page.waitForFunction(() => /t = (0\.[7-9]|[1-9])/.test(document.getElementById('clock').textContent), null, { timeout: 30_000 });
    await shot(page, '04-scene-viewer');
    await page.keyboard.press(' ');
    const pausedAt = await page.locator('#clock').innerText();
    await page.keyboard.press('.');
    await page.waitForFunction((c) => document.getElementById('clock').textContent !== c, pausedAt, { timeout: 10_000 });
    assert((await page.locator('#play').innerText()).includes('Play'), 'Space paused it');
    const clock = await page.locator('#clock').innerText();
    const played = await posesNow();
    let worst = ['', 0];
    for (const [n, p] of Object.entries(atHome)) {
      const q = played[n];
      const d = Math.hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
      if (d > worst[1]) worst = [n, d];
    }
    assert(worst[1] < 0.005, `${worst[0]} moved ${worst[1]} m while playing`);
    log(`object panel read; played to ${clock.replace(/\s+/g, ' ')}: no body (robot links included) moved more than ${(worst[1] * 1000).toFixed(2)} mm`);
    await page.click('#reset');

    // --- Delete removes the selected object (an edit: a new version) ---
    await page.mouse.click(at.x, at.y);
    await page.locator(`#object-panel[data-object="${target.name}"]`).waitFor();
    await page.evaluate(() => document.activeElement?.blur?.());
    await page.keyboard.press('Delete');
    const v2 = await waitForNewScene(page, sceneId);
    const layout2 = (await api(server, token, 'GET', `/api/scenes/${v2}/files/layout.json`)).json;
    assert(!layout2.objects.some((o) => o.name === target.name), `${target.name} is still in the layout`);
    assert((await page.evaluate((n) => window.__sw.bodyPosition(n), target.name)) === null, `${target.name} is still drawn`);
    // The edited scene keeps its relation checks (issue 22: an edit dropped them).
    const v2report = (await api(server, token, 'GET', `/api/scenes/${v2}`)).json.report;
    assert(v2report.relations.length >= detail.report.relations.length - 1 && v2report.relations.length > 0, `v2 lists ${v2report.relations.length} relations, v1 ${detail.report.relations.length}`);
    log(`Delete removed ${target.name}: v2 without it, its report still measures ${v2report.relations.length} relations`);

    // --- A refused edit says why and keeps the scene ---
    await page.locator('button[data-tab="edit"]').click();
    await page.fill('#edit-command', 'remove the purple unicorn');
    await page.click('#apply-edit');
    await page.locator('#edit-status .notice.error').waitFor({ timeout: 60_000 });
    const refusal = await page.locator('#edit-status').innerText();
    assert(/Refused|not accepted/.test(refusal) && refusal.length > 30, `the refusal: ${refusal}`);
    assert((await page.evaluate(() => location.pathname)) === `/scenes/${v2}`, 'a refused edit changed the page');
    await shot(page, '05-edit-refused');
    log(`refused: ${refusal.replace(/\s+/g, ' ')}`);

    // --- Drag an object: the server re-solves around it ---
    const dragged = layout2.objects.find((o) => o.category === 'cabinet');
    assert(dragged, 'the scene has a cabinet to drag');
    const p0 = await page.evaluate((n) => window.__sw.objectOnScreen(n), dragged.name);
    // Half way towards the workbench, on screen.
    const bench = layout2.objects.find((o) => o.category === 'workbench');
    const pw = await page.evaluate((n) => window.__sw.objectOnScreen(n), bench.name);
    await page.mouse.move(p0.x, p0.y);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(p0.x + ((pw.x - p0.x) * k) / 16, p0.y + ((pw.y - p0.y) * k) / 16);
    await page.mouse.up();
    const grabbed = await page.locator('#object-panel').getAttribute('data-object');
    assert(grabbed === dragged.name, `the drag took ${grabbed}, not ${dragged.name}`);
    const v3 = await waitForNewScene(page, v2);
    const layout3 = (await api(server, token, 'GET', `/api/scenes/${v3}/files/layout.json`)).json;
    const before = dragged.pos;
    const after = layout3.objects.find((o) => o.name === dragged.name).pos;
    const moved = Math.hypot(after[0] - before[0], after[1] - before[1]);
    assert(moved > 0.1, `${dragged.name} moved only ${moved} m`);
    const drawnAfter = await page.evaluate((n) => window.__sw.bodyPosition(n), dragged.name);
    assert(Math.hypot(drawnAfter[0] - after[0], drawnAfter[1] - after[1]) < 0.01, 'the moved object is drawn where v3 puts it');
    log(`dragged ${dragged.name} ${moved.toFixed(2)} m → v3`);

    // Shift-drag turns it where it stands: 120 px to the right is 30°.
    const p1 = await page.evaluate((n) => window.__sw.objectOnScreen(n), dragged.name);
    await page.keyboard.down('Shift');
    await page.mouse.move(p1.x, p1.y);
    await page.mouse.down();
    for (let k = 1; k <= 6; k++) await page.mouse.move(p1.x + 20 * k, p1.y);
    await page.mouse.up();
    await page.keyboard.up('Shift');
    const v3b = await waitForNewScene(page, v3);
    const turnedTo = (await api(server, token, 'GET', `/api/scenes/${v3b}/files/layout.json`)).json.objects.find((o) => o.name === dragged.name);
    const before3 = layout3.objects.find((o) => o.name === dragged.name);
    const dYaw = (((turnedTo.yaw - before3.yaw) * 180) / Math.PI + 540) % 360 - 180;
    assert(Math.abs(dYaw - 30) < 0.01, `turned by ${dYaw}°`);
    assert(Math.hypot(turnedTo.pos[0] - before3.pos[0], turnedTo.pos[1] - before3.pos[1]) < 1e-6, 'turning kept its place');
    log(`shift-dragged ${dragged.name}: turned ${dYaw.toFixed(1)}° in place → v4`);

    // --- Asset studio: a part made, then one that cannot be made (the preview is cleared) ---
    await page.click('a[href="/studio"]');
    await page.fill('#part-description', 'a flat washer: outer diameter 120mm, inner diameter 40mm, thickness 10mm');
    await page.click('#make-part');
    await page.locator('#mesh-size').waitFor({ timeout: 200_000 });
    const meshSize = await page.locator('#mesh-size').innerText();
    assert(/120\.0 × 120\.0 × 10\.0/.test(meshSize), `the preview's size: ${meshSize}`);
    assert((await page.locator('#preview').getAttribute('data-part')) !== '', 'the washer is previewed');
    await shot(page, '06-asset-studio');
    await page.fill('#part-description', 'a sentient hovercraft that sings opera');
    await page.click('#make-part');
    // The washer's preview goes at once: it is not the part asked for.
    assert((await page.locator('#preview').getAttribute('data-part')) === '', 'the previous part stayed in the preview');
    assert((await page.locator('#mesh-size').count()) === 0, "the previous part's size stayed");
    await page.locator('#forge-status .notice.error').waitFor({ timeout: 200_000 });
    const notMade = await page.locator('#forge-status').innerText();
    const kinds = await page.locator('#forge-progress li.bad').count();
    assert(/could not be made/.test(notMade), `the failure: ${notMade}`);
    assert(!/\/(work|tmp|root|home)\//.test(notMade), `a server path in the answer: ${notMade}`);
    assert((await page.locator('#preview').getAttribute('data-part')) === '', 'a failed part left a preview');
    await shot(page, '06a-part-not-made');
    log(`a part that cannot be made: ${notMade.replace(/\s+/g, ' ').slice(0, 160)} (${kinds} failed attempt(s) listed); the washer's preview was cleared`);
    const assets = (await api(server, token, 'GET', `/api/assets?q=${encodeURIComponent('a big ring-shaped spacer')}`)).json;
    const plate = [...assets.similar, ...assets.mine].find((a) => a.meta?.asset_id);
    assert(plate, 'the washer is in the library');
    assert(assets.similar.length > 0 && assets.similar[0].id === plate.id, `search by meaning finds it: ${JSON.stringify(assets.note)}`);
    log(`made a washer (${meshSize}); searching "a big ring-shaped spacer" by meaning ranks it first`);

    // --- The catalog has pictures: in the library list and, picked, in the studio ---
    await page.fill('.part-search', 'kettle');
    const kettleItem = page.locator('#catalog-parts li[data-part="catalog:kettle"]');
    await kettleItem.waitFor({ timeout: 20_000 });
    await page.waitForFunction(() => {
      const img = document.querySelector('#catalog-parts li[data-part="catalog:kettle"] img.part-pic');
      return !!img && img.complete && img.naturalWidth === 256;
    }, null, { timeout: 60_000 });
    await kettleItem.click();
    await page.waitForFunction(() => {
      const img = document.querySelector('#catalog-picture');
      return !!img && img.complete && img.naturalWidth === 256;
    }, null, { timeout: 60_000 });
    await shot(page, '06b-catalog-picture');
    log('the catalog list shows each category\'s picture; picking the kettle shows it at 256 px');

    // --- Drag the part from the library into the open scene ---
    await page.goto(`${server.url}/scenes/${v3b}?tab=parts`);
    await waitReady(page);
    await page.fill('.part-search', 'washer');
    const item = page.locator(`li.part[data-part="${plate.id}"]`);
    await item.waitFor();
    const vb = await page.locator('#viewer').boundingBox();
    await item.dragTo(page.locator('#viewer'), { targetPosition: { x: vb.width * 0.3, y: vb.height * 0.75 } });
    const v4 = await waitForNewScene(page, v3b);
    const layout4 = (await api(server, token, 'GET', `/api/scenes/${v4}/files/layout.json`)).json;
    const added = layout4.objects.filter((o) => !layout3.objects.some((x) => x.name === o.name));
    assert(layout4.objects.length === layout3.objects.length + 1, 'one object more');
    assert(added.length === 1 && added[0].category === 'proxy', `the part is in the scene: ${JSON.stringify(added)}`);
    const v4detail = (await api(server, token, 'GET', `/api/scenes/${v4}`)).json;
    assert(v4detail.files.includes('parts.json'), 'the part travels with the package');
    log(`dropped the washer in: ${added[0].name} at ${added[0].pos.map((v) => v.toFixed(2))}`);

    // --- Versions and the way back ---
    await page.locator('button[data-tab="history"]').click();
    await page.locator('#history li[data-version="5"]').waitFor();
    await shot(page, '07-versions');
    await page.locator('#history li[data-version="1"] a').click();
    await page.waitForURL(`${server.url}/scenes/${sceneId}`);
    await waitReady(page);
    log('history lists 5 versions; v1 opens');

    // --- Download the zip and load it with MuJoCo (WASM) ---
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
    const zipPath = path.join(tmp, 'scene.zip');
    await download.saveAs(zipPath);
    const mj = await loadMujoco();
    const files = readZip(fs.readFileSync(zipPath));
    const loaded = check(mj, 'downloaded package.zip', files, 0);
    assert(loaded.ok, `the downloaded package: ${loaded.error}`);
    log(`downloaded package.zip (${files.size} files) loads and settles in MuJoCo 3.14: largest move ${(loaded.max_displacement_m * 1000).toFixed(2)} mm`);
    // Every version this test made loads in the browser's MuJoCo too.
    for (const [i, id] of [v2, v3, v3b, v4].entries()) {
      const r = await fetch(`${server.url}/api/scenes/${id}/package.zip`, { headers: { authorization: `Bearer ${token}` } });
      const c = check(mj, `v${i + 2}`, readZip(Buffer.from(await r.arrayBuffer())), i + 1);
      assert(c.ok, `v${i + 2}: ${c.error}`);
    }

    // --- A robot-pack scene (robosuite's Panda, OBJ meshes): drawn where MuJoCo puts it ---
    const packJob = (await api(server, token, 'POST', '/api/jobs', { prompt: 'a lab with a workbench', robots: ['robosuite_panda'] })).json.job_id;
    // A job queued behind it is cancelled from its page.
    const doomed = (await api(server, token, 'POST', '/api/jobs', { prompt: 'a garage with a car lift and two toolboxes' })).json.job_id;
    await page.goto(`${server.url}/jobs/${doomed}`);
    await page.getByText('Waiting in the queue').waitFor({ timeout: 20_000 });
    await page.click('#cancel');
    await page.getByText('The job was cancelled').waitFor({ timeout: 30_000 });
    assert((await api(server, token, 'GET', `/api/jobs/${doomed}`)).json.state === 'cancelled', 'the job is cancelled');
    const cancelledHeading = await page.locator('#job-heading').innerText();
    assert(cancelledHeading === 'The build was cancelled', `the heading after cancelling: ${cancelledHeading}`);
    assert(!(await page.locator('#cancel').isVisible()), 'a cancelled job still offers Cancel');
    log(`a queued job cancelled from its page: "${cancelledHeading}"`);
    await page.goto(`${server.url}/jobs/${packJob}`);
    // Opens by itself when it ends while watched (or offers the link when it had ended).
    await page.waitForFunction(
      () => location.pathname.startsWith('/scenes/') || (document.querySelector('#open-scene') && !/opening it/.test(document.getElementById('result')?.textContent ?? '')),
      null,
      { timeout: 180_000 },
    );
    if (!page.url().includes('/scenes/')) await page.click('#open-scene');
    await page.waitForURL(/\/scenes\//);
    await waitReady(page);
    const packId = await page.evaluate(() => location.pathname.split('/')[2]);
    const packLayout = (await api(server, token, 'GET', `/api/scenes/${packId}/files/layout.json`)).json;
    const arm = packLayout.robots[0];
    const armBody = (await page.evaluate(() => window.__sw.bodies())).find((b) => b.startsWith(`${arm.name}_`));
    const drawnArm = await page.evaluate((n) => window.__sw.bodyPosition(n), armBody);
    assert(Math.hypot(drawnArm[0] - arm.pos[0], drawnArm[1] - arm.pos[1]) < 0.01, `${armBody} drawn at ${drawnArm}, spawned at ${arm.pos}`);
    const packTimings = await page.evaluate(() => window.__sw.timings);
    assert(packTimings.converted > 0, 'the OBJ fast path was taken');
    const packPng = await page.locator('#viewer').screenshot();
    const packStats = await pixelStats(page, packPng);
    assert(packStats.colours > 40 && packStats.std > 12, `the robot-pack canvas looks blank: ${JSON.stringify(packStats)}`);
    const packZip = await fetch(`${server.url}/api/scenes/${packId}/package.zip`, { headers: { authorization: `Bearer ${token}` } });
    const packCheck = check(mj, 'the robot-pack scene', readZip(Buffer.from(await packZip.arrayBuffer())), 8);
    assert(packCheck.ok, `the robot-pack package in MuJoCo 3.14: ${packCheck.error}`);
    await shot(page, '13-robot-pack');
    log(`robot pack: ${packTimings.converted} OBJ meshes read by the worker, compiled in ${packTimings.compileMs.toFixed(0)} ms; ${armBody} drawn at its spawn point`);

    // --- An anomaly dataset scene: the labelled object's panel shows its label (linked by URL) ---
    const anomJob = (await api(server, token, 'POST', '/api/jobs', { prompt: 'a storage room with two shelves and eight boxes on them', seed: 5, options: { anomaly: { kinds: ['floating'], rate: 0.5 } } })).json.job_id;
    let anomScene = null;
    for (let k = 0; k < 600 && !anomScene; k++) {
      const j = (await api(server, token, 'GET', `/api/jobs/${anomJob}`)).json;
      assert(j.state !== 'failed', `the anomaly job failed: ${j.error}`);
      anomScene = j.scene_id;
      if (!anomScene) await new Promise((r) => setTimeout(r, 200));
    }
    const anomLayout = (await api(server, token, 'GET', `/api/scenes/${anomScene}/files/layout.json`)).json;
    const label = anomLayout.anomalies[0];
    assert(label, 'the scene has an anomaly label');
    await page.goto(`${server.url}/scenes/${anomScene}?object=${label.object}`);
    await waitReady(page);
    await page.locator(`#object-panel[data-object="${label.object}"]`).waitFor();
    const anomPanel = await page.locator('#object-panel').innerText();
    assert(anomPanel.includes('Anomaly labels') || anomPanel.toLowerCase().includes('anomaly labels'), `the panel: ${anomPanel}`);
    assert(anomPanel.includes(label.kind), `the panel names the kind ${label.kind}: ${anomPanel}`);
    await shot(page, '14-anomaly-label');
    log(`anomaly scene: ${label.object}'s panel shows "${label.kind}: ${label.description}"`);
    const zipA = await fetch(`${server.url}/api/scenes/${anomScene}/package.zip`, { headers: { authorization: `Bearer ${token}` } });
    const cA = check(mj, 'the anomaly scene', readZip(Buffer.from(await zipA.arrayBuffer())), 10);
    assert(cA.ok, `the anomaly scene in MuJoCo 3.14: ${cA.error}`);

    // --- Variations: one request, a job per seed, one card with a row per seed ---
    const varied = (await api(server, token, 'POST', '/api/jobs', { prompt: 'a small office with a desk and a chair', seed: 11, variations: 2 })).json;
    assert(varied.job_ids.length === 2, `variations: ${JSON.stringify(varied)}`);
    for (const j of varied.job_ids) {
      for (let k = 0; k < 600; k++) {
        const st = (await api(server, token, 'GET', `/api/jobs/${j}`)).json.state;
        if (st === 'succeeded') break;
        assert(st !== 'failed' && st !== 'cancelled', `variation job ${j}: ${st}`);
        await new Promise((r) => setTimeout(r, 200));
      }
    }

    // --- My scenes: one card per description, its versions under it; search; delete ---
    page.on('dialog', (d) => void d.accept());
    await page.click('a[href="/scenes"]');
    await page.waitForFunction(() => {
      const imgs = [...document.querySelectorAll('img.thumb')];
      return imgs.length >= 3 && imgs.every((i) => i.complete && i.naturalWidth > 0);
    }, null, { timeout: 60_000 });
    const cards = await page.locator('.scene-card').count();
    const all = (await api(server, token, 'GET', '/api/scenes')).json.scenes;
    const descriptions = new Set(all.map((x) => x.scene_prompt));
    assert(cards === descriptions.size, `${cards} cards for ${descriptions.size} descriptions (${all.length} scenes)`);
    const labCard = page.locator('.scene-card', { hasText: final.slice(0, 30) });
    assert((await labCard.locator('.variation').count()) === 1, 'the lab is one variation');
    const labRow = await labCard.locator('.variation').innerText();
    assert(/5 versions/.test(labRow) && /seed 0/.test(labRow) && /v5/.test(labRow), `the lab's row: ${labRow}`);
    const officeRows = await page.locator('.scene-card', { hasText: 'a small office with a desk' }).locator('.variation').allInnerTexts();
    assert(officeRows.length === 2 && /seed 11/.test(officeRows[0]) && /seed 12/.test(officeRows[1]), `the office's variations: ${officeRows}`);
    await shot(page, '08-my-scenes');
    await page.fill('#scene-search', 'storage room');
    await page.waitForFunction(() => document.querySelectorAll('.scene-card').length === 1);
    await page.locator('.scene-card', { hasText: 'storage room' }).locator('button.delete').click();
    await page.getByText('Deleted 1 version').waitFor({ timeout: 20_000 });
    assert((await api(server, token, 'GET', `/api/scenes/${anomScene}`)).status === 404, 'the deleted scene is gone');
    // The notice can come before the list is drawn again: give the list its moment, then check.
    await page
      .waitForFunction(() => document.querySelectorAll('.scene-card').length === 0, null, { timeout: 20_000 })
      .catch(() => {});
    assert((await page.locator('.scene-card').count()) === 0, 'the deleted card is gone');
    await page.fill('#scene-search', '');
    await page.waitForFunction((n) => document.querySelectorAll('.scene-card').length === n, cards - 1);
    log(`My scenes: ${cards} cards for ${all.length} scenes (the lab's 5 versions in one); search found the storage room, deleted it`);

    // --- Settings: a key made, used, revoked ---
    await page.click('a[href="/settings"]');
    await page.fill('#key-name', 'e2e script');
    await page.click('#create-key');
    const key = await page.locator('#new-key').innerText();
    assert(key.startsWith('swk_'), 'a key is shown');
    assert((await api(server, key, 'GET', '/api/me')).json.username === 'ann', 'the key works');
    await page.locator('#keys li', { hasText: 'e2e script' }).waitFor();
    await shot(page, '09-settings');
    await page.locator('#keys li', { hasText: 'e2e script' }).locator('button.revoke').click();
    await page.getByText('is revoked').waitFor({ timeout: 10_000 });
    assert((await api(server, key, 'GET', '/api/me')).status === 401, 'a revoked key still works');
    log('an API key made, used and revoked from the settings page');

    // --- Text with direction overrides cannot reorder the page ---
    const rtl = (await api(server, token, 'POST', '/api/jobs', { prompt: 'a lab with a table \u202Eelbat a dna\u202C and a shelf' })).json.job_id;
    await page.goto(`${server.url}/jobs/${rtl}`);
    await page.locator('.prompt-line').waitFor();
    await page.waitForFunction(() => document.querySelector('.prompt-line').textContent.includes('and a shelf'));
    const bodyText = await page.evaluate(() => document.body.innerText);
    assert(!/[\u202A-\u202E\u2066-\u2069]/.test(bodyText), 'a direction override reached the page');
    await api(server, token, 'DELETE', `/api/jobs/${rtl}`);
    log('a prompt holding U+202E is shown without it');

    // --- Bad input: a socket dropped mid-job catches up on reconnection ---
    let dropped = false;
    await page.routeWebSocket(/\/events/, (ws) => {
      const upstream = ws.connectToServer();
      if (dropped) return;
      dropped = true;
      let n = 0;
      upstream.onMessage((m) => {
        ws.send(m);
        if (++n === 2) {
          ws.close();
          upstream.close();
        }
      });
    });
    const job2 = (await api(server, token, 'POST', '/api/jobs', { prompt: 'a small office with two desks, two chairs and a cabinet', seed: 3 })).json.job_id;
    await page.goto(`${server.url}/jobs/${job2}`);
    await page.getByText('Lost the live connection').waitFor({ timeout: 20_000 });
    await shot(page, '10-socket-dropped');
    await page.locator('#open-scene').waitFor({ timeout: 120_000 });
    for (const s of ['plan', 'forge', 'layout', 'bridge', 'verify']) {
      assert((await page.locator(`.stage[data-stage="${s}"]`).getAttribute('class')).includes('done'), `${s} done after reconnecting`);
    }
    const layoutSteps = await page.locator('.stage[data-stage="layout"] .steps li').allInnerTexts();
    assert(new Set(layoutSteps).size === layoutSteps.length, 'no step shown twice after catching up');
    await page.unrouteAll({ behavior: 'ignoreErrors' });
    const job2Scene = (await api(server, token, 'GET', `/api/jobs/${job2}`)).json.scene_id;
    const zip2 = await fetch(`${server.url}/api/scenes/${job2Scene}/package.zip`, { headers: { authorization: `Bearer ${token}` } });
    const c2 = check(await loadMujoco(), 'the office', readZip(Buffer.from(await zip2.arrayBuffer())), 9);
    assert(c2.ok, `the office scene in MuJoCo 3.14: ${c2.error}`);
    log('a dropped socket: message shown, reconnected, caught up without repeats');

    // --- Bad input: another user's scene, an unknown scene ---
    const ctx2 = await browser.newContext({ viewport: VIEWPORT });
    const page2 = await ctx2.newPage();
    page2.on('pageerror', (e) => pageErrors.push(e.message));
    await page2.goto(`${server.url}/scenes/${sceneId}`);
    await page2.waitForURL(/\/signin/);
    await page2.fill('#username', 'bob');
    await page2.fill('#password', PASSWORD);
    await page2.click('#register');
    await page2.waitForURL(`${server.url}/scenes/${sceneId}`);
    await page2.locator('#not-found').waitFor({ timeout: 30_000 });
    const other = await page2.locator('#not-found').innerText();
    assert(/No such scene here/.test(other), `another user's scene: ${other}`);
    assert((await page2.locator('#viewer').count()) === 0, "another user's scene shows a viewer");
    await notBlank(page2, "another user's scene");
    await shot(page2, '11-not-your-scene');
    await page2.goto(`${server.url}/jobs/${job2}`);
    await page2.locator('#not-found').waitFor({ timeout: 20_000 });
    assert(/No such job here/.test(await page2.locator('#not-found').innerText()), "another user's job");
    assert((await page2.locator('#cancel').count()) === 0 && (await page2.locator('#timeline').count()) === 0, "another user's job shows a live page");
    await notBlank(page2, "another user's job");
    log(`another user's scene and job: "${other.split('\n')[0]}" and "No such job here", no viewer, no Cancel`);

    // --- Bad input: an expired token ends the session with the reason ---
    const me = (await api(server, token, 'GET', '/api/me')).json;
    const stale = expiredToken(server, me);
    assert((await api(server, stale, 'GET', '/api/me')).status === 401, 'the server refuses the expired token');
    await page.evaluate((t) => sessionStorage.setItem('scenewright.token', t), stale);
    await page.goto(`${server.url}/scenes/${v3}`);
    await page.waitForURL(/\/signin\?next=/, { timeout: 20_000 });
    const reason = await page.locator('.notice').first().innerText();
    assert(/expired/.test(reason), `the sign-in page says why: ${reason}`);
    await shot(page, '12-session-expired');
    await page.fill('#username', 'ann');
    await page.fill('#password', PASSWORD);
    await page.click('#signin');
    await page.waitForURL(`${server.url}/scenes/${v3}`);
    await waitReady(page);
    log(`expired token: "${reason.trim()}"; signed in again and back on the scene`);

    // --- Bad input: a browser without WebGL gets a message and the download, not a blank page ---
    const noGl = await chromium.launch({ ...CHROMIUM, args: [...CHROMIUM.args.filter((a) => !a.includes('swiftshader')), '--disable-3d-apis'] });
    try {
      const p3 = await (await noGl.newContext({ viewport: VIEWPORT })).newPage();
      await p3.goto(`${server.url}/signin`);
      await p3.evaluate((t) => sessionStorage.setItem('scenewright.token', t), token);
      await p3.goto(`${server.url}/scenes/${sceneId}`);
      await p3.getByText('This browser cannot draw the scene').waitFor({ timeout: 20_000 });
      await notBlank(p3, 'no WebGL');
      log('a browser without WebGL: told so, offered the package');
    } finally {
      await noGl.close();
    }

    // --- At 390 px (a phone): nothing wider than the screen, the top bar included ---
    const session = await page.evaluate(() => ({ t: sessionStorage.getItem('scenewright.token'), u: sessionStorage.getItem('scenewright.user') }));
    const phone = await browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 1 });
    const p4 = await phone.newPage();
    p4.on('pageerror', (e) => pageErrors.push(e.message));
    await p4.goto(`${server.url}/signin`);
    await p4.evaluate((x) => (sessionStorage.setItem('scenewright.token', x.t), sessionStorage.setItem('scenewright.user', x.u)), session);
    for (const [where, shotName] of [['/', '15-phone-compose'], ['/scenes', '16-phone-scenes'], [`/scenes/${v3}`, '17-phone-scene'], ['/studio', null], ['/settings', null]]) {
      await p4.goto(`${server.url}${where}`);
      if (where.startsWith('/scenes/')) await waitReady(p4);
      else await p4.waitForTimeout(800);
      const widths = await p4.evaluate(() => ({ doc: document.documentElement.scrollWidth, header: document.querySelector('header.top').scrollWidth, headerBox: document.querySelector('header.top').clientWidth }));
      assert(widths.doc <= 390 && widths.header <= widths.headerBox, `${where} at 390 px: ${JSON.stringify(widths)}`);
      if (shotName) await shot(p4, shotName);
    }
    await phone.close();
    log('at 390 px: no page and no top bar wider than the screen');

    // --- Signing out revokes the token on the server ---
    await page.goto(`${server.url}/scenes`);
    await page.locator('#scene-grid').waitFor();
    const live = await page.evaluate(() => sessionStorage.getItem('scenewright.token'));
    assert((await api(server, live, 'GET', '/api/me')).status === 200, 'the session works before signing out');
    await page.click('#signout');
    await page.waitForURL(/\/signin/);
    assert((await api(server, live, 'GET', '/api/me')).status === 401, 'a signed-out token still works');
    log('signing out revoked the token');

    assert(pageErrors.length === 0, `uncaught page errors: ${pageErrors.join('; ')}`);
    await ctx2.close();
    await ctx.close();
  } catch (e) {
    failures++;
    console.error(`e2e FAILED: ${e.stack ?? e}`);
    console.error(`--- server log (last 4000 characters) ---\n${server.log().slice(-4000)}`);
  } finally {
    await browser.close();
    await server.stop();
    fs.rmSync(tmp, { recursive: true, force: true });
  }
  log(failures ? 'FAILED' : 'passed');
  process.exit(failures ? 1 : 0);
}

await main();
