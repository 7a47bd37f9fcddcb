#!/usr/bin/env node
// Loads scene packages in the browser's MuJoCo — the official WebAssembly build
// (@mujoco/mujoco 3.14), run here in Node — resets each to its `home` keyframe and steps
// it 2 s, as the viewer will. A package the viewer could not show (an MJCF feature newer
// than 3.14, a missing file) or that does not settle fails the run.
//
//   node scripts/load-packages.mjs [--json] DIR_OR_ZIP ...
//
// A directory is a package (scene.xml inside) or holds packages one level down; a .zip is a
// package as `GET /api/scenes/{id}/package.zip` serves it. Exit 0 when every package
// loads and settles, 1 when one does not, 2 on bad arguments.

import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import loadMujoco from '@mujoco/mujoco';

const SETTLE_S = 2;
/** A free body moving more than this in the settle fails (the native check's threshold). */
const MOVE_LIMIT_M = 0.01;
/** A robot joint drifting more than this from its home pose fails. */
const DRIFT_LIMIT_RAD = 0.05;

/** The files of a zip (stored or deflated entries), read from its central directory. */
export function readZip(buf) {
  let eocd = -1;
  for (let i = buf.length - 22; i >= Math.max(0, buf.length - 65557); i--) {
    if (buf.readUInt32LE(i) === 0x06054b50) {
      eocd = i;
      break;
    }
  }
  if (eocd < 0) throw new Error('not a zip file (no end of central directory)');
  const count = buf.readUInt16LE(eocd + 10);
  let p = buf.readUInt32LE(eocd + 16);
  const files = new Map();
  for (let k = 0; k < count; k++) {
    if (buf.readUInt32LE(p) !== 0x02014b50) throw new Error('corrupt zip central directory');
    const method = buf.readUInt16LE(p + 10);
    const csize = buf.readUInt32LE(p + 20);
    const nlen = buf.readUInt16LE(p + 28);
    const xlen = buf.readUInt16LE(p + 30);
    const clen = buf.readUInt16LE(p + 32);
    const local = buf.readUInt32LE(p + 42);
    const name = buf.toString('utf8', p + 46, p + 46 + nlen);
    const lnlen = buf.readUInt16LE(local + 26);
    const lxlen = buf.readUInt16LE(local + 28);
    const start = local + 30 + lnlen + lxlen;
    const raw = buf.subarray(start, start + csize);
    if (!name.endsWith('/')) files.set(name, method === 0 ? raw : method === 8 ? zlib.inflateRawSync(raw) : null);
    if (files.get(name) === null) throw new Error(`${name}: unsupported zip method ${method}`);
    p += 46 + nlen + xlen + clen;
  }
  return files;
}

function walk(dir, base = dir, out = new Map()) {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) walk(p, base, out);
    else out.set(path.relative(base, p).split(path.sep).join('/'), fs.readFileSync(p));
  }
  return out;
}

/** Every package an argument names: [label, Map(path -> bytes)]. */
function packagesOf(arg) {
  if (arg.endsWith('.zip')) return [[arg, readZip(fs.readFileSync(arg))]];
  if (fs.existsSync(path.join(arg, 'scene.xml'))) return [[arg, walk(arg)]];
  const subs = fs
    .readdirSync(arg, { withFileTypes: true })
    .filter((e) => e.isDirectory() && fs.existsSync(path.join(arg, e.name, 'scene.xml')))
    .map((e) => path.join(arg, e.name));
  if (subs.length === 0) throw new Error(`${arg}: no scene.xml in it or in its subdirectories`);
  return subs.map((d) => [d, walk(d)]);
}

function nameAt(names, adr) {
  let end = adr;
  while (end < names.length && names[end] !== 0) end++;
  return Buffer.from(names.subarray(adr, end)).toString('utf8');
}

/** Loads, resets and settles one package; returns what it measured. */
export function check(mj, label, files, n) {
  const root = `/pkg${n}`;
  for (const [rel, bytes] of files) {
    const full = `${root}/${rel}`;
    mj.FS.mkdirTree(full.slice(0, full.lastIndexOf('/')));
    mj.FS.writeFile(full, bytes);
  }
  const report = files.has('report.json') ? JSON.parse(Buffer.from(files.get('report.json')).toString('utf8')) : null;
  const out = { package: label, ok: false };
  let model = null;
  let data = null;
  try {
    const t0 = performance.now();
    try {
      model = mj.MjModel.from_xml_path(`${root}/scene.xml`);
    } catch (e) {
      out.error = `does not compile in MuJoCo 3.14 (WASM): ${e?.message ?? e}`;
      return out;
    }
    data = new mj.MjData(model);
    out.compile_ms = +(performance.now() - t0).toFixed(1);
    const names = new Uint8Array(model.names.buffer, model.names.byteOffset, model.names.byteLength).slice();
    const keyAdr = model.name_keyadr.slice();
    let home = -1;
    for (let k = 0; k < model.nkey; k++) if (nameAt(names, keyAdr[k]) === 'home') home = k;
    if (home >= 0) mj.mj_resetDataKeyframe(model, data, home);
    mj.mj_forward(model, data);
    // Free bodies (a free joint) and robot joints (hinges and slides), from the model.
    const jntType = model.jnt_type.slice();
    const jntBody = model.jnt_bodyid.slice();
    const jntQpos = model.jnt_qposadr.slice();
    const bodyAdr = model.name_bodyadr.slice();
    const free = [];
    const hinges = [];
    for (let j = 0; j < model.njnt; j++) {
      if (jntType[j] === 0) free.push(jntBody[j]);
      else if (jntType[j] === 2 || jntType[j] === 3) hinges.push(jntQpos[j]);
    }
    const start = free.map((b) => Array.from(data.xpos.slice(3 * b, 3 * b + 3)));
    const q0 = hinges.map((a) => data.qpos[a]);
    const steps = Math.round(SETTLE_S / model.opt.timestep);
    const t1 = performance.now();
    for (let s = 0; s < steps; s++) mj.mj_step(model, data);
    out.step_ms = +(performance.now() - t1).toFixed(1);
    out.realtime = +(SETTLE_S / ((performance.now() - t1) / 1000)).toFixed(2);
    const qpos = data.qpos.slice();
    if (!qpos.every(Number.isFinite)) {
      out.error = 'the simulation diverged (non-finite positions)';
      return out;
    }
    let worst = 0;
    let worstBody = null;
    free.forEach((b, i) => {
      const p = data.xpos.slice(3 * b, 3 * b + 3);
      const d = Math.hypot(p[0] - start[i][0], p[1] - start[i][1], p[2] - start[i][2]);
      if (d > worst) [worst, worstBody] = [d, nameAt(names, bodyAdr[b])];
    });
    const drift = hinges.reduce((m, a, i) => Math.max(m, Math.abs(qpos[a] - q0[i])), 0);
    Object.assign(out, {
      bodies: model.nbody,
      geoms: model.ngeom,
      meshes: model.nmesh,
      free_bodies: free.length,
      max_displacement_m: +worst.toFixed(6),
      worst_body: worstBody,
      max_joint_drift_rad: +drift.toFixed(5),
      native_max_displacement_m: report?.verification?.settle?.max_displacement_m ?? null,
    });
    // Anomaly datasets move on purpose; their report says what is expected.
    const expectedMoves = (report?.verification?.expected ?? []).length > 0;
    if (worst > MOVE_LIMIT_M && !expectedMoves) out.error = `${worstBody} moved ${(worst * 1000).toFixed(1)} mm in ${SETTLE_S} s`;
    else if (drift > DRIFT_LIMIT_RAD) out.error = `a robot joint drifted ${drift.toFixed(3)} rad from home`;
    else out.ok = true;
    return out;
  } finally {
    data?.delete();
    model?.delete();
    rmTree(mj.FS, root);
  }
}

function rmTree(fsys, p) {
  for (const e of fsys.readdir(p)) {
    if (e === '.' || e === '..') continue;
    const q = `${p}/${e}`;
    if (fsys.isDir(fsys.stat(q).mode)) rmTree(fsys, q);
    else fsys.unlink(q);
  }
  fsys.rmdir(p);
}

async function main() {
  const args = process.argv.slice(2);
  const asJson = args.includes('--json');
  const targets = args.filter((a) => a !== '--json');
  if (targets.length === 0) {
    console.error('usage: node scripts/load-packages.mjs [--json] DIR_OR_ZIP ...');
    process.exit(2);
  }
  let packages;
  try {
    packages = targets.flatMap(packagesOf);
  } catch (e) {
    console.error(`load-packages: ${e.message}`);
    process.exit(2);
  }
  const mj = await loadMujoco();
  const results = packages.map(([label, files], n) => check(mj, label, files, n));
  if (asJson) console.log(JSON.stringify(results, null, 1));
  else
    for (const r of results) {
      console.log(
        r.ok
          ? `ok    ${r.package}: ${r.bodies} bodies, compiled in ${r.compile_ms} ms, settled ${SETTLE_S} s at ${r.realtime}× real time, largest move ${(r.max_displacement_m * 1000).toFixed(2)} mm, robot drift ${r.max_joint_drift_rad} rad`
          : `FAIL  ${r.package}: ${r.error}`,
      );
    }
  const failed = results.filter((r) => !r.ok).length;
  if (!asJson) console.log(`${results.length - failed} of ${results.length} packages load and settle in MuJoCo 3.14 (WASM)`);
  process.exit(failed ? 1 : 0);
}

if (import.meta.url === `file://${process.argv[1]}`) await main();
