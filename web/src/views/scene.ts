// See it, edit it: the package simulating in MuJoCo (WASM, in a worker) drawn by three.js,
// with play / pause / step / reset to `home` / speed, geom groups, the camera framed on
// the scene or the selected object, a click to inspect an object, dragging to move it,
// parts dropped in from the library, natural-language edits, the version history and the
// package's download. Keys: Space play/pause, . step, R reset, F frame, Delete remove the
// selected object, Ctrl+Z back to the previous version, Esc deselect.

import * as api from '../api';
import { probe } from '../debug';
import { fill, h, notice, setText } from '../dom';
import { navigate, notFoundPage, type View } from '../router';
import * as session from '../session';
import { sim } from '../sim/client';
import type { Layout, SceneDetail } from '../types';
import { Viewer } from '../viewer/viewer';
import { PART_MIME, partsBrowser } from './parts';
import { historyPanel, objectPanel, reportPanel } from './scene_panels';

const GROUP_NAMES = ['0 static', '1 markers', '2 visual', '3 collision', '4', '5 surfaces'];

export const sceneView: View = (root, params, query) => {
  const id = params.id ?? '';
  const p = probe();
  p.loadStartedAt = performance.now();
  p.firstFrameAt = null;
  const title = h('h1', { class: 'scene-title', text: 'Scene' });
  const subtitle = h('p', { class: 'muted version-line' });
  const status = h('div', { class: 'status', id: 'viewer-status' }, notice('info', 'Loading the scene…'));
  const stage = h('div', { class: 'viewer', id: 'viewer', data: { state: 'loading' } });
  const clock = h('span', { class: 'clock', id: 'clock', text: 't = 0.000 s' });
  const side = h('div', { class: 'side-body' });
  const tabs = h('div', { class: 'tabs' });
  const editStatus = h('div', { class: 'status', id: 'edit-status' });
  let detail: SceneDetail | null = null;
  let layout: Layout | null = null;
  let selected: string | null = null;
  let disposed = false;

  let viewer: Viewer;
  try {
    viewer = new Viewer(stage);
  } catch (e) {
    // No WebGL here: say so, and offer the package instead of a blank page.
    root.append(
      h(
        'div',
        { class: 'page' },
        notice('error', `This browser cannot draw the scene (${api.describe(e)}). The package can still be downloaded and opened in MuJoCo.`),
        h('button', {
          text: 'Download package.zip',
          on: {
            click: () =>
              void api.packageZip(id).then((blob) => {
                const a = h('a', { href: URL.createObjectURL(blob), attrs: { download: `scene_${id}.zip` } });
                document.body.append(a);
                a.click();
                a.remove();
              }),
          },
        }),
        h('p', {}, h('a', { href: '/scenes', text: 'Your scenes' })),
      ),
    );
    return;
  }
  viewer.onFirstFrame = () => {
    p.firstFrameAt = performance.now();
    stage.dataset.state = 'ready';
  };
  p.bodyPosition = (name) => viewer.bodyPosition(name);
  p.bodies = () => model?.bodies.map((b) => b.name) ?? [];
  p.renderInfo = () => viewer.info();
  p.bench = (s) => sim.bench(s);
  p.unload = () => sim.unload();
  p.camera = () => viewer.cameraState();
  let model: { bodies: { name: string; root: number }[] } | null = null;
  const rootOf = (name: string) => model?.bodies.findIndex((b) => b.name === name) ?? -1;
  p.objectOnScreen = (name) => {
    const i = rootOf(name);
    return i > 0 ? viewer.projectObject(i) : null;
  };

  // --- Simulation controls ---
  const playBtn = h('button', { id: 'play', text: '▶ Play' });
  let playing = false;
  const setPlaying = (on: boolean) => {
    playing = on;
    playBtn.textContent = on ? '❚❚ Pause' : '▶ Play';
  };
  playBtn.addEventListener('click', () => togglePlay());
  playBtn.title = 'play or pause (Space)';
  const speed = h(
    'select',
    { id: 'speed', title: 'simulation speed' },
    ...['0.25', '0.5', '1', '2', '4'].map((s) => h('option', { value: s, text: `${s}×` })),
  );
  speed.value = '1';
  speed.addEventListener('change', () => sim.speed(Number(speed.value)));
  const groupBoxes = GROUP_NAMES.map((label, g) => {
    const box = h('input', { type: 'checkbox', data: { group: String(g) } });
    box.checked = viewer.groupVisible(g);
    box.addEventListener('change', () => viewer.setGroupVisible(g, box.checked));
    return h('label', { class: 'inline', title: `geom group ${g}` }, box, ` ${label}`);
  });
  const togglePlay = () => {
    if (playing) sim.pause();
    else sim.play();
    setPlaying(!playing);
  };
  const step = () => {
    setPlaying(false);
    sim.step(1);
  };
  const reset = () => {
    setPlaying(false);
    sim.reset();
  };
  // The selected object when there is one, else the whole scene.
  const frame = () => {
    const i = selected ? rootOf(selected) : -1;
    if (!(i > 0 && viewer.frameObject(i))) viewer.resetCamera();
  };
  const toolbar = h(
    'div',
    { class: 'toolbar' },
    playBtn,
    h('button', { id: 'step', text: 'Step', title: 'one step (.)', on: { click: step } }),
    h('button', { id: 'reset', text: 'Reset to home', title: 'reset to the home keyframe (R)', on: { click: reset } }),
    h('button', { id: 'frame', text: 'Frame', title: 'frame the selected object, or the whole scene (F)', on: { click: frame } }),
    h('button', { id: 'reset-view', text: 'Reset view', title: 'the first view of the whole scene', on: { click: () => viewer.resetCamera() } }),
    speed,
    clock,
    h('details', { class: 'groups' }, h('summary', { text: 'Geom groups' }), ...groupBoxes),
    h('span', { class: 'muted keys-hint', text: 'Space play · . step · R reset · F frame · Del remove · Ctrl+Z undo' }),
  );

  sim.onFrame = (f) => {
    if (disposed) return;
    viewer.setPoses(f.poses);
    clock.textContent = `t = ${f.time.toFixed(3)} s${f.playing && f.realtime > 0 ? ` · ${f.realtime.toFixed(2)}× real time` : ''}`;
    p.realtime = f.realtime;
  };
  sim.onProgress = (m) => fill(status, notice('info', `Loading the scene: ${m}…`));
  sim.onError = (m) => fill(status, notice('error', m));

  // --- Side panels ---
  const show = (tab: string) => {
    for (const b of tabs.querySelectorAll('button')) b.classList.toggle('on', b.dataset.tab === tab);
    switch (tab) {
      case 'object':
        fill(side, selected && detail ? objectPanel(selected, layout, detail.report) : h('p', { class: 'muted', text: 'Click an object in the view to inspect it; drag it to move it, Shift-drag to turn it.' }));
        if (selected) side.append(objectActions(selected));
        return;
      case 'report':
        fill(side, detail ? reportPanel(detail) : notice('info', 'loading…'));
        return;
      case 'edit':
        fill(side, editBox());
        return;
      case 'history':
        fill(side, notice('info', 'loading the versions…'));
        api
          .versions(id)
          .then((vs) => fill(side, historyPanel(id, vs)))
          .catch((e: unknown) => fill(side, notice('error', `The history did not load: ${api.describe(e)}.`)));
        return;
      case 'parts':
        fill(side, h('p', { class: 'muted', text: 'Drag a part onto the floor of the scene: the server places it there (kept inside the room) and verifies the scene.' }), partsBrowser());
        return;
    }
  };
  for (const [tab, label] of [
    ['object', 'Object'],
    ['report', 'Report'],
    ['edit', 'Edit'],
    ['history', 'History'],
    ['parts', 'Parts'],
  ] as const) {
    tabs.append(h('button', { text: label, data: { tab }, on: { click: () => show(tab) } }));
  }

  /** Runs an edit job and opens the new version, or says why it was refused. */
  const runEdit = async (what: string | api.StructuredEdit, doing: string) => {
    fill(editStatus, notice('info', `${doing}: the server re-solves the layout and verifies it in MuJoCo…`));
    try {
      const jobId = await api.edit(id, what);
      const job = await api.waitForJob(jobId);
      if (job.state === 'succeeded' && job.scene_id) {
        fill(editStatus, notice('ok', 'Done: the new version verified. Opening it…'));
        navigate(`/scenes/${job.scene_id}`);
      } else {
        viewer.clearOffsets();
        const why = job.error ?? 'the edit failed';
        fill(editStatus, notice('error', `Refused: ${why}${/unchanged/.test(why) ? '.' : '. The scene is unchanged.'}`));
      }
    } catch (e) {
      viewer.clearOffsets();
      fill(editStatus, notice('error', `The edit was not accepted: ${api.describe(e)}.`));
    }
  };

  const editBox = () => {
    const input = h('textarea', { id: 'edit-command', placeholder: 'remove the red box · move the shelf against the north wall · add a chair next to the desk', attrs: { rows: '3' } });
    const go = () => {
      const c = input.value.trim();
      if (c) void runEdit(c, 'Editing');
    };
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' && !e.shiftKey) {
        e.preventDefault();
        go();
      }
    });
    return h('div', { class: 'edit-box' }, input, h('button', { id: 'apply-edit', class: 'primary', text: 'Apply edit', on: { click: go } }), editStatus);
  };

  const objectActions = (name: string) => {
    const o = layout?.objects.find((x) => x.name === name);
    if (!o) return h('p', { class: 'muted', text: 'Robots move by words: “move the robot next to the table”.' });
    const turn = (deg: number) => () => void runEdit({ move: { object: name, pos: [o.pos[0] ?? 0, o.pos[1] ?? 0], yaw_deg: (o.yaw * 180) / Math.PI + deg } }, `Turning ${name}`);
    return h(
      'div',
      { class: 'row wrap' },
      h('button', { text: '⟲ 90°', on: { click: turn(90) } }),
      h('button', { text: '⟲ 15°', id: 'rotate-left', on: { click: turn(15) } }),
      h('button', { text: '⟳ 15°', on: { click: turn(-15) } }),
      h('button', { text: '⟳ 90°', on: { click: turn(-90) } }),
      h('button', { text: 'Remove', id: 'remove-object', on: { click: () => void runEdit(`remove ${name}`, `Removing ${name}`) } }),
      editStatus,
    );
  };

  const select = (name: string | null) => {
    selected = name;
    const i = name ? rootOf(name) : -1;
    viewer.highlight(i > 0 ? i : null);
    show('object');
  };

  // --- Picking and dragging ---
  // A drag moves the object; with Shift held it turns it about its origin instead.
  let drag: { name: string; root: number; z: number; from: { x: number; y: number }; moved: boolean; start: { x: number; y: number }; turn: boolean } | null = null;
  stage.addEventListener('pointerdown', (e) => {
    if (e.button !== 0 || !model) return;
    const hit = viewer.pick(e.clientX, e.clientY);
    if (!hit) return;
    const name = model.bodies[hit.root]?.name ?? '';
    const o = layout?.objects.find((x) => x.name === name);
    if (!o) {
      select(name);
      return;
    }
    const at = viewer.planePoint(e.clientX, e.clientY, o.pos[2] ?? 0);
    if (!at) return;
    drag = { name, root: hit.root, z: o.pos[2] ?? 0, from: { x: at.x, y: at.y }, moved: false, start: { x: e.clientX, y: e.clientY }, turn: e.shiftKey };
    viewer.setControlsEnabled(false);
    stage.setPointerCapture(e.pointerId);
  });
  stage.addEventListener('pointermove', (e) => {
    if (!drag) return;
    if (!drag.moved && Math.hypot(e.clientX - drag.start.x, e.clientY - drag.start.y) < 4) return;
    drag.moved = true;
    if (drag.turn) {
      const deg = Math.round((e.clientX - drag.start.x) / 4 / 5) * 5;
      viewer.setOffset(drag.root, 0, 0, (deg * Math.PI) / 180);
      fill(status, notice('info', `Turning ${drag.name} by ${deg}°: release to turn it`));
      return;
    }
    const at = viewer.planePoint(e.clientX, e.clientY, drag.z);
    if (!at) return;
    viewer.setOffset(drag.root, at.x - drag.from.x, at.y - drag.from.y, 0);
    fill(status, notice('info', `Moving ${drag.name}: release to place it (${at.x.toFixed(2)}, ${at.y.toFixed(2)}); Shift-drag turns it`));
  });
  const endDrag = (e: PointerEvent) => {
    if (!drag) return;
    const d = drag;
    drag = null;
    viewer.setControlsEnabled(true);
    if (stage.hasPointerCapture(e.pointerId)) stage.releasePointerCapture(e.pointerId);
    if (!d.moved) {
      select(d.name);
      return;
    }
    const o = layout?.objects.find((x) => x.name === d.name);
    if (d.turn && o) {
      const deg = Math.round((e.clientX - d.start.x) / 4 / 5) * 5;
      select(d.name);
      fill(status);
      if (deg !== 0) void runEdit({ move: { object: d.name, pos: [o.pos[0] ?? 0, o.pos[1] ?? 0], yaw_deg: (o.yaw * 180) / Math.PI + deg } }, `Turning ${d.name}`);
      else viewer.clearOffsets();
      return;
    }
    const at = viewer.planePoint(e.clientX, e.clientY, d.z);
    if (!at || !o) return;
    const x = (o.pos[0] ?? 0) + at.x - d.from.x;
    const y = (o.pos[1] ?? 0) + at.y - d.from.y;
    select(d.name);
    fill(status);
    void runEdit({ move: { object: d.name, pos: [x, y] } }, `Moving ${d.name}`);
  };
  stage.addEventListener('pointerup', endDrag);
  stage.addEventListener('pointercancel', endDrag);

  // Parts dropped from the library.
  stage.addEventListener('dragover', (e) => {
    if (e.dataTransfer?.types.includes(PART_MIME)) {
      e.preventDefault();
      e.dataTransfer.dropEffect = 'copy';
    }
  });
  stage.addEventListener('drop', (e) => {
    const ref = e.dataTransfer?.getData(PART_MIME);
    if (!ref) return;
    e.preventDefault();
    const at = viewer.planePoint(e.clientX, e.clientY, 0);
    if (!at) {
      fill(editStatus, notice('error', 'Drop the part onto the floor.'));
      return;
    }
    show('edit');
    void runEdit({ place: { asset: ref, pos: [at.x, at.y] } }, `Placing the part at (${at.x.toFixed(2)}, ${at.y.toFixed(2)})`);
  });

  // --- Loading ---
  const download = h('button', {
    id: 'download',
    text: 'Download package.zip',
    on: {
      click: () => {
        api
          .packageZip(id)
          .then((blob) => {
            const a = h('a', { href: URL.createObjectURL(blob), attrs: { download: `scene_${id}.zip` } });
            document.body.append(a);
            a.click();
            a.remove();
            setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
          })
          .catch((e: unknown) => fill(status, notice('error', `The download failed: ${api.describe(e)}.`)));
      },
    },
  });

  const body = h('div', { class: 'scene-body' }, h('div', { class: 'viewer-wrap' }, stage, toolbar), h('aside', { class: 'side card' }, tabs, side));
  const load = async () => {
    sim.warm();
    try {
      const [d, l] = await Promise.all([api.scene(id), api.layout(id).catch(() => null)]);
      if (disposed) return;
      detail = d;
      layout = l;
      setText(title, d.scene_prompt);
      title.append(h('span', { class: 'tag', text: `v${d.version}` }), h('span', { class: `badge ${d.status}`, text: d.status }));
      if (d.version > 1) setText(subtitle, `This version: ${d.prompt}`);
      show(query.get('tab') ?? 'report');
      const token = session.token() ?? '';
      const loaded = await sim.load(`/api/scenes/${encodeURIComponent(id)}/files`, token, d.files);
      if (disposed) return;
      model = loaded.model;
      p.timings = { ...loaded.timings };
      viewer.setModel(loaded.model, loaded.poses);
      // A link may name an object (`?object=shelf_1`): it is shown selected.
      const named = query.get('object');
      if (named && loaded.model.bodies.some((b) => b.name === named)) select(named);
      fill(status, notice('ok', `Loaded in MuJoCo 3.14 (WASM): ${loaded.model.bodies.length} bodies, ${loaded.model.geoms.length} geoms, ${(loaded.timings.bytes / 1e6).toFixed(1)} MB; compiled in ${loaded.timings.compileMs.toFixed(0)} ms. Click an object to inspect it, drag it to move it.`));
    } catch (e) {
      if (disposed) return;
      stage.dataset.state = 'error';
      if (!detail && e instanceof api.ApiError && e.status === 404) {
        // Not the visitor's (or gone): a page that says so, not an empty viewer.
        root.replaceChildren();
        notFoundPage(root, 'No such scene here', 'This scene does not exist, or it is not yours.');
        return;
      }
      fill(status, notice('error', `This scene cannot be shown: ${api.describe(e)}.`), h('p', {}, h('a', { href: '/scenes', text: 'Your scenes' }), ' · ', h('a', { href: '/', text: 'describe a new one' })));
      if (!detail) body.hidden = true;
    }
  };
  void load();

  root.append(
    h(
      'div',
      { class: 'page scene' },
      h('div', { class: 'scene-head' }, h('div', {}, title, subtitle), h('div', { class: 'row' }, download)),
      status,
      body,
    ),
  );

  // --- Keys (not while typing in a field) ---
  const onKey = (e: KeyboardEvent) => {
    const t = e.target as HTMLElement | null;
    if (t && (t.isContentEditable || ['INPUT', 'TEXTAREA', 'SELECT'].includes(t.tagName))) return;
    if (!model) return;
    const key = e.key.toLowerCase();
    if ((e.ctrlKey || e.metaKey) && key === 'z') {
      // Undo: back to the version this one was made from.
      if (detail?.parent_id) {
        e.preventDefault();
        navigate(`/scenes/${detail.parent_id}`);
      }
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    switch (key) {
      case ' ':
        // Space on a focused button or link presses it, as everywhere.
        if (t && ['BUTTON', 'A', 'SUMMARY'].includes(t.tagName)) return;
        e.preventDefault();
        togglePlay();
        return;
      case '.':
        step();
        return;
      case 'r':
        reset();
        return;
      case 'f':
        frame();
        return;
      case 'escape':
        select(null);
        return;
      case 'delete':
      case 'backspace':
        if (selected && layout?.objects.some((o) => o.name === selected)) {
          e.preventDefault();
          void runEdit(`remove ${selected}`, `Removing ${selected}`);
        }
        return;
    }
  };
  document.addEventListener('keydown', onKey);

  return () => {
    disposed = true;
    document.removeEventListener('keydown', onKey);
    sim.pause();
    sim.onFrame = null;
    sim.onProgress = null;
    sim.onError = null;
    viewer.dispose();
  };
};
