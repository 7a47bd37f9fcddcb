// Compose a scene: the prompt, a refinement chat beside it (the server's questions, turn
// by turn, ending with a final prompt to accept), the robot picker fed by /api/robots,
// and the options (seed, variations, anomalies, rules profile).

import * as api from '../api';
import { fill, h, notice } from '../dom';
import { navigate, type View } from '../router';
import type { Robot } from '../types';
import { robotIcon } from './icons';

const ANOMALIES = ['overlap', 'scale', 'misplacement', 'floating', 'rule_violation'];

export const composeView: View = (root) => {
  const prompt = h('textarea', {
    id: 'prompt',
    placeholder: 'a small lab with a workbench, two shelves and six boxes, and a UR5e on the bench',
    attrs: { rows: '5', maxlength: '65536' },
  });
  const status = h('div', { class: 'status', id: 'compose-status' });
  const picked = new Set<string>();

  // --- The refinement chat ---
  const turns: { question: string; answer: string }[] = [];
  let pending: string | null = null;
  const log = h('div', { class: 'chat-log', id: 'chat-log' });
  const answer = h('input', { id: 'chat-answer', placeholder: 'your answer (or "done")', disabled: true });
  const sendBtn = h('button', { id: 'chat-send', text: 'Answer', disabled: true });
  const finalBox = h('div', { class: 'final', id: 'chat-final' });
  const chatStatus = h('div', { class: 'status' });
  const say = (who: 'q' | 'a' | 'note', text: string) =>
    log.append(h('div', { class: `bubble ${who}`, text, data: { who } }));
  const askNext = async () => {
    fill(chatStatus, notice('info', 'thinking…'));
    answer.disabled = sendBtn.disabled = true;
    try {
      const st = await api.refine(prompt.value, turns);
      fill(chatStatus);
      for (const w of st.warnings) say('note', w);
      if (st.done || st.question === null) {
        pending = null;
        fill(
          finalBox,
          h('div', { class: 'label', text: `Final prompt (asked by the ${st.asked_by} planner)` }),
          h('blockquote', { id: 'final-prompt', text: st.prompt }),
          st.summary ? h('div', { class: 'muted', text: st.summary }) : null,
          h('button', {
            id: 'chat-accept',
            class: 'primary',
            text: 'Use this prompt',
            on: {
              click: () => {
                prompt.value = st.prompt;
                fill(finalBox, notice('ok', 'The prompt box now holds the refined prompt.'));
              },
            },
          }),
        );
        return;
      }
      pending = st.question;
      say('q', st.question);
      answer.disabled = sendBtn.disabled = false;
      answer.focus();
    } catch (e) {
      fill(chatStatus, notice('error', `Refinement failed: ${api.describe(e)}.`));
    }
  };
  const send = () => {
    if (pending === null) return;
    const a = answer.value.trim() || 'skip';
    turns.push({ question: pending, answer: a });
    say('a', a);
    answer.value = '';
    pending = null;
    void askNext();
  };
  sendBtn.addEventListener('click', send);
  answer.addEventListener('keydown', (e) => {
    if (e.key === 'Enter') send();
  });
  const startChat = () => {
    turns.length = 0;
    log.replaceChildren();
    fill(finalBox);
    void askNext();
  };

  // --- Robots ---
  const robotGrid = h('div', { class: 'robots', id: 'robots' }, h('span', { class: 'muted', text: 'loading robots…' }));
  const robotCard = (r: Robot) => {
    const card = h(
      'button',
      {
        class: 'robot',
        type: 'button',
        data: { robot: r.name },
        title: r.available ? `${r.display} (${r.source})` : (r.why_unavailable ?? 'not installed'),
        disabled: !r.available,
      },
      robotIcon(r.kind),
      h('span', { class: 'name', text: r.display }),
      h('span', { class: 'meta', text: [r.kind, r.reach ? `reach ${r.reach.toFixed(2)} m` : ''].filter(Boolean).join(' · ') }),
      h('span', { class: 'meta', text: r.licence ? `licence ${r.licence}` : '' }),
    );
    card.addEventListener('click', () => {
      if (picked.has(r.name)) picked.delete(r.name);
      else picked.add(r.name);
      card.classList.toggle('picked', picked.has(r.name));
      fill(pickedLine, picked.size ? `Robots: ${[...picked].join(', ')}` : 'Robots: as the prompt says');
    });
    return card;
  };
  const pickedLine = h('div', { class: 'muted', id: 'picked', text: 'Robots: as the prompt says' });
  api
    .robots()
    .then((rs) => fill(robotGrid, ...rs.map(robotCard)))
    .catch((e: unknown) => fill(robotGrid, notice('error', `The robot list did not load: ${api.describe(e)}.`)));

  // --- Options ---
  const seed = h('input', { id: 'seed', type: 'number', value: '0', attrs: { min: '0', step: '1' } });
  const variations = h('input', { id: 'variations', type: 'number', value: '1', attrs: { min: '1', max: '10' } });
  const rate = h('input', { id: 'anomaly-rate', type: 'number', value: '0.2', attrs: { min: '0', max: '1', step: '0.05' } });
  const rules = h('select', { id: 'rules' }, h('option', { value: '', text: 'the room kind’s' }));
  const kinds = ANOMALIES.map((k) => h('input', { type: 'checkbox', value: k, data: { anomaly: k } }));
  api
    .options()
    .then((o) => rules.append(...o.rules_profiles.map((p) => h('option', { value: p, text: p }))))
    .catch(() => undefined);

  // One request per press: the button is off from the press until the answer (a double
  // click, or Enter pressed twice, makes one set of jobs).
  let submitting = false;
  const generate = async () => {
    if (submitting) return;
    const text = prompt.value.trim();
    if (!text) {
      fill(status, notice('error', 'Describe the workspace first.'));
      return;
    }
    const s = Number(seed.value);
    const n = Number(variations.value);
    const r = Number(rate.value);
    if (!Number.isInteger(s) || s < 0) return fill(status, notice('error', 'The seed is a whole number, 0 or more.'));
    if (!Number.isInteger(n) || n < 1 || n > 10) return fill(status, notice('error', 'Variations: 1 to 10.'));
    const chosen = kinds.filter((k) => k.checked).map((k) => k.value);
    if (chosen.length && !(r > 0 && r <= 1)) return fill(status, notice('error', 'The anomaly rate is above 0 and at most 1.'));
    const req: api.JobRequest = { prompt: text, seed: s };
    if (n > 1) req.variations = n;
    if (picked.size) req.robots = [...picked];
    const options: NonNullable<api.JobRequest['options']> = {};
    if (rules.value) options.rules = rules.value;
    if (chosen.length) options.anomaly = { kinds: chosen, rate: r };
    if (Object.keys(options).length) req.options = options;
    fill(status, notice('info', 'Submitting…'));
    submitting = true;
    generateBtn.disabled = true;
    try {
      const [first, ...rest] = await api.submitJob(req);
      if (first) navigate(`/jobs/${first}${rest.length ? `?also=${rest.join(',')}` : ''}`);
    } catch (e) {
      fill(status, notice('error', `The job was not accepted: ${api.describe(e)}.`));
    } finally {
      submitting = false;
      generateBtn.disabled = false;
    }
  };
  const generateBtn = h('button', { id: 'generate', class: 'primary', text: 'Generate', on: { click: () => void generate() } });

  root.append(
    h(
      'div',
      { class: 'page compose' },
      h(
        'section',
        { class: 'card' },
        h('h1', { text: 'Describe a workspace' }),
        prompt,
        h(
          'div',
          { class: 'row' },
          generateBtn,
          h('button', { id: 'refine', text: 'Refine in a chat', on: { click: startChat } }),
        ),
        status,
        h('h2', { text: 'Robots' }),
        pickedLine,
        robotGrid,
        h(
          'details',
          { class: 'options' },
          h('summary', { text: 'Options' }),
          h('label', { text: 'Seed' }, seed),
          h('label', { text: 'Variations (one scene per seed, from the seed up)' }, variations),
          h('label', { text: 'Rules profile' }, rules),
          h(
            'fieldset',
            {},
            h('legend', { text: 'Anomalies (labelled, for detector training)' }),
            ...kinds.map((k) => h('label', { class: 'inline' }, k, ` ${k.value.replace('_', ' ')}`)),
            h('label', { text: 'Share of objects to corrupt' }, rate),
          ),
        ),
      ),
      h(
        'aside',
        { class: 'card chat' },
        h('h2', { text: 'Refine' }),
        h('p', { class: 'muted', text: 'Answers a few questions about what the prompt leaves open, then offers a final prompt.' }),
        log,
        h('div', { class: 'row' }, answer, sendBtn),
        chatStatus,
        finalBox,
      ),
    ),
  );
  prompt.focus();
};
