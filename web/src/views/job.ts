// Watch it build: the job's WebSocket drives a stage timeline (plan, forge, layout,
// bridge, verify) with each stage's time and summary, the per-object steps and warnings
// as they come. A dropped socket is reopened and catches up from the job's events; the job
// can be cancelled. The heading says where the job is; a job watched to its end opens its
// scene. A job that is not the visitor's is "not found", never an empty timeline.

import * as api from '../api';
import { fill, fmtMs, h, notice, setText } from '../dom';
import { navigate, notFoundPage, type View } from '../router';
import { sim } from '../sim/client';
import { type Job, type JobEvent, isTerminal } from '../types';

const STAGES = ['plan', 'forge', 'layout', 'bridge', 'verify'] as const;
const STAGE_TITLES: Record<string, string> = {
  plan: 'Plan — reading the prompt',
  forge: 'Forge — making the assets',
  layout: 'Layout — placing objects and robots',
  bridge: 'Bridge — writing MJCF and meshes',
  verify: 'Verify — compiling and settling in MuJoCo',
};

interface StageRow {
  el: HTMLElement;
  state: HTMLElement;
  time: HTMLElement;
  summary: HTMLElement;
  steps: HTMLElement;
  nsteps: number;
}

const HEADINGS: Record<string, string> = {
  queued: 'Waiting to build the scene',
  running: 'Building the scene',
  succeeded: 'The scene is built',
  failed: 'The build failed',
  cancelled: 'The build was cancelled',
};

export const jobView: View = (root, params, query) => {
  const id = params.id ?? '';
  let stopWatching: (() => void) | null = null;
  let disposed = false;
  const loading = h('div', { class: 'page' }, notice('info', 'Loading the job…'));
  root.append(loading);
  api
    .job(id)
    .then((job) => {
      if (disposed) return;
      loading.remove();
      stopWatching = jobPage(root, id, job, query);
    })
    .catch((e: unknown) => {
      if (disposed) return;
      loading.remove();
      if (e instanceof api.ApiError && e.status === 404) notFoundPage(root, 'No such job here', 'This job does not exist, or it is not yours.');
      else root.append(h('div', { class: 'page' }, notice('error', `The job did not load: ${api.describe(e)}.`)));
    });
  return () => {
    disposed = true;
    stopWatching?.();
  };
};

function jobPage(root: HTMLElement, id: string, initial: Job, query: URLSearchParams): () => void {
  // MuJoCo's WebAssembly compiles while the job runs, ready for the scene.
  if (!isTerminal(initial.state)) sim.warm();
  // Watched live (not opened after the end): the scene opens by itself when it is ready.
  const live = !isTerminal(initial.state);
  const heading = h('h1', { id: 'job-heading', text: HEADINGS[initial.state] ?? 'Building the scene' });
  const head = h('div', { class: 'job-head' }, heading);
  const promptLine = h('p', { class: 'prompt-line' });
  const conn = h('div', { class: 'status', id: 'conn' });
  const result = h('div', { class: 'status', id: 'result' });
  const warnings = h('ul', { class: 'warnings', id: 'warnings' });
  const cancel = h('button', { id: 'cancel', text: 'Cancel' });
  const rows = new Map<string, StageRow>();
  const timeline = h('ol', { class: 'timeline', id: 'timeline' });
  for (const s of STAGES) {
    const row: StageRow = {
      el: h('li', { class: 'stage pending', data: { stage: s } }),
      state: h('span', { class: 'dot' }),
      time: h('span', { class: 'time' }),
      summary: h('div', { class: 'summary' }),
      steps: h('ul', { class: 'steps' }),
      nsteps: 0,
    };
    row.el.append(
      h('div', { class: 'stage-head' }, row.state, h('span', { class: 'title', text: STAGE_TITLES[s] ?? s }), row.time),
      row.summary,
      row.steps,
    );
    rows.set(s, row);
    timeline.append(row.el);
  }
  const also = (query.get('also') ?? '').split(',').filter(Boolean);
  const others = also.length
    ? h(
        'div',
        { class: 'muted' },
        'Other variations: ',
        ...also.map((j, i) => h('a', { href: `/jobs/${j}`, text: ` #${i + 2}` })),
      )
    : null;

  let finishedJob: Job | null = null;
  const show = (job: Job) => {
    setText(promptLine, job.prompt);
    setText(heading, HEADINGS[job.state] ?? 'Building the scene');
    cancel.disabled = job.state !== 'queued' && job.state !== 'running';
    cancel.hidden = isTerminal(job.state);
    if (job.state === 'queued') fill(result, notice('info', 'Waiting in the queue…'));
  };
  const onEvent = (e: JobEvent) => {
    switch (e.event) {
      case 'stage_started': {
        const r = rows.get(e.stage);
        if (r) r.el.className = 'stage running';
        setText(heading, HEADINGS.running ?? '');
        fill(result);
        return;
      }
      case 'stage_finished': {
        const r = rows.get(e.stage);
        if (!r) return;
        r.el.className = 'stage done';
        r.time.textContent = fmtMs(e.ms);
        r.summary.textContent = e.summary;
        return;
      }
      case 'object': {
        const r = rows.get(e.stage);
        if (!r) return;
        r.nsteps++;
        const cls = /left out|not placed|removed|failed/i.test(e.step) ? 'step bad' : 'step';
        r.steps.append(h('li', { class: cls }, h('b', { text: e.object }), ` ${e.step}`));
        return;
      }
      case 'note':
        rows.get(e.stage)?.steps.append(h('li', { class: 'step note', text: e.message }));
        return;
      case 'warning':
        warnings.append(h('li', {}, h('span', { class: 'tag', text: e.stage }), ` ${e.message}`));
        return;
      case 'result':
        finishedJob = e.job;
        show(e.job);
        fill(conn);
        if (e.job.state === 'succeeded' && e.scene_id) {
          const sceneId = e.scene_id;
          fill(
            result,
            notice('ok', live ? 'The scene is ready and verified in MuJoCo; opening it…' : 'The scene is ready and verified in MuJoCo.'),
            h('a', { id: 'open-scene', class: 'button primary', href: `/scenes/${sceneId}`, text: 'Open the scene' }),
          );
          // Watched to its end: the scene opens (a moment to see the timeline complete).
          if (live && !also.length) openTimer = setTimeout(() => navigate(`/scenes/${sceneId}`), OPEN_DELAY_MS);
        } else if (e.job.state === 'succeeded') {
          fill(result, notice('ok', `The ${e.job.kind} job finished.`));
        } else if (e.job.state === 'cancelled') {
          fill(result, notice('info', 'The job was cancelled; nothing was stored.'));
        } else {
          fill(result, notice('error', `The job failed: ${e.job.error ?? 'no reason given'}.`));
        }
        for (const r of rows.values()) if (r.el.classList.contains('running')) r.el.className = 'stage stopped';
        return;
      case 'other':
        if (e.name === 'requeued') warnings.append(h('li', { text: `The runner was lost; the job runs again (${e.text}).` }));
        if (e.name === 'started') for (const r of rows.values()) r.el.className = 'stage pending';
        return;
    }
  };

  let openTimer: ReturnType<typeof setTimeout> | null = null;
  show(initial);
  const stop = api.watchJob(id, {
    onEvent,
    onDrop: (attempt, why) => {
      if (finishedJob) return;
      fill(conn, notice('error', `Lost the live connection (${why}); reconnecting, attempt ${attempt}…`));
    },
    onReconnect: () => fill(conn, notice('ok', 'Reconnected; caught up with the job’s events.')),
    onFatal: (why) => fill(conn, notice('error', `This job cannot be followed: ${why}.`)),
  });
  cancel.addEventListener('click', () => {
    cancel.disabled = true;
    api
      .cancelJob(id)
      .then(show)
      .catch((e: unknown) => fill(result, notice('error', `Cancelling failed: ${api.describe(e)}.`)));
  });

  head.append(cancel);
  root.append(h('div', { class: 'page job' }, head, promptLine, others, conn, timeline, result, h('h2', { text: 'Warnings' }), warnings));
  return () => {
    if (openTimer !== null) clearTimeout(openTimer);
    stop();
  };
}

/** How long a finished timeline stays on screen before its scene opens, ms. */
const OPEN_DELAY_MS = 1500;
