// The scene page's side panels: the clicked object (name, category, size, what it rests
// on, its relations, rule violations and anomaly labels), the report's verification, and
// the version history.

import { fmtDate, fmtSize, h } from '../dom';
import type { Layout, Report, SceneDetail, Version } from '../types';

export function objectPanel(name: string, layout: Layout | null, report: Report): HTMLElement {
  const o = layout?.objects.find((x) => x.name === name);
  const robot = layout?.robots.find((r) => r.name === name);
  const rows: [string, string][] = [];
  if (o) {
    rows.push(['category', o.label ? `${o.label} (${o.category})` : o.category]);
    rows.push(['size', fmtSize(o.size)]);
    rows.push(['rests on', o.support]);
    rows.push(['position', `${o.pos.map((v) => v.toFixed(2)).join(', ')} m, facing ${((o.yaw * 180) / Math.PI).toFixed(0)}°`]);
    rows.push(['movable', o.movable ? `yes${o.mass !== null ? `, ${o.mass.toFixed(2)} kg` : ''}` : 'no (fixed)']);
  } else if (robot) {
    rows.push(['robot model', robot.model]);
    rows.push(['mount', robot.mounted_on ? `${robot.mount} on ${robot.mounted_on}` : robot.mount]);
    rows.push(['position', `${robot.pos.map((v) => v.toFixed(2)).join(', ')} m`]);
  }
  const group = o?.group;
  const mine = (g: string) => g === name || (group !== undefined && g === group);
  const relations = report.relations.filter((r) => mine(r.subject) || r.targets.some(mine));
  const violations = report.violations.filter((v) => v.objects.includes(name));
  const anomalies = layout?.anomalies.filter((a) => a.object === name) ?? [];
  return h(
    'div',
    { class: 'object-panel', id: 'object-panel', data: { object: name } },
    h('h3', { text: name }),
    h('dl', {}, ...rows.flatMap(([k, v]) => [h('dt', { text: k }), h('dd', { text: v, data: { field: k } })])),
    h('h4', { text: 'Relations' }),
    relations.length
      ? h(
          'ul',
          { class: 'relations' },
          ...relations.map((r) =>
            h(
              'li',
              { class: r.held === false ? 'bad' : r.held ? 'good' : '' },
              r.phrase || `${r.subject} ${r.relation} ${r.targets.join(', ')}`,
              r.held === null ? '' : r.held ? ' — holds' : ' — does not hold',
              r.measured ? ` (${r.measured})` : '',
              r.reason ? `: ${r.reason}` : '',
            ),
          ),
        )
      : h('p', { class: 'muted', text: report.relations.length ? 'No relation names this object.' : 'This report lists no relations.' }),
    h('h4', { text: 'Rules' }),
    violations.length
      ? h(
          'ul',
          { class: 'violations' },
          ...violations.map((v) => h('li', { class: 'bad', text: `${v.message}${v.requested ? ' (asked for in the prompt)' : ''} — ${v.standard}` })),
        )
      : h('p', { class: 'muted', text: 'No rule violation.' }),
    anomalies.length ? h('h4', { text: 'Anomaly labels' }) : null,
    anomalies.length ? h('ul', { class: 'anomalies' }, ...anomalies.map((a) => h('li', { class: 'bad', text: `${a.kind}: ${a.description}` }))) : null,
  );
}

export function reportPanel(detail: SceneDetail): HTMLElement {
  const r = detail.report;
  const v = r.verification;
  const badge = h('span', { class: `badge ${r.status}`, text: r.status, id: 'status-badge' });
  const facts: [string, string][] = [];
  if (r.room) facts.push(['room', `${r.room}${r.roomSize ? ` ${r.roomSize.map((x) => x.toFixed(1)).join(' × ')} m` : ''}`]);
  if (r.objectsPlaced !== null) facts.push(['objects', `${r.objectsPlaced} of ${r.objectsRequested ?? r.objectsPlaced} placed`]);
  if (r.robots.length) facts.push(['robots', r.robots.join(', ')]);
  if (r.relations.length) facts.push(['relations', `${r.relations.filter((x) => x.held).length} of ${r.relations.length} hold`]);
  if (v) {
    facts.push(['engine', `${v.engine}, ${v.compiled ? 'compiled' : 'did not compile'}`]);
    if (v.contacts !== null) {
      // `contacts` counts every contact (things resting touch); only the deep ones are a finding.
      const limit = `${((v.threshold ?? 0.001) * 1000).toFixed(0)} mm`;
      const deep = v.deep === 0 ? `none deeper than ${limit}` : `${v.deep} deeper than ${limit}`;
      facts.push(['at t = 0', `${v.contacts} contact${v.contacts === 1 ? '' : 's'}, ${deep}${v.maxDepth ? `; deepest ${(v.maxDepth * 1000).toFixed(2)} mm` : ''}`]);
    }
    if (v.maxDisplacement !== null)
      facts.push([`${v.settleS ?? 2} s settle`, `largest move ${(v.maxDisplacement * 1000).toFixed(2)} mm${v.worstBody ? ` (${v.worstBody})` : ''}`]);
    for (const rb of v.robots) facts.push([rb.name, `joint drift ${rb.drift !== null ? rb.drift.toFixed(4) : '?'} rad`]);
  }
  const list = (title: string, items: string[], cls = '') =>
    items.length ? [h('h4', { text: title }), h('ul', { class: cls }, ...items.map((t) => h('li', { text: t })))] : [];
  return h(
    'div',
    { class: 'report-panel', id: 'report-panel' },
    h('h3', {}, 'Verification ', badge),
    h('dl', {}, ...facts.flatMap(([k, val]) => [h('dt', { text: k }), h('dd', { text: val })])),
    ...list('Failures', v?.failures ?? [], 'bad'),
    ...list('Expected (labelled anomalies)', v?.expected ?? []),
    ...list('Relations that do not hold', r.relations.filter((x) => x.held === false).map((x) => `${x.phrase || `${x.subject} ${x.relation} ${x.targets.join(', ')}`}${x.reason ? `: ${x.reason}` : ''}`), 'bad'),
    ...list('Rule violations', r.violations.map((x) => `${x.message}${x.requested ? ' (asked for)' : ''}`), 'bad'),
    ...list('Left out', r.leftOut.map((l) => `${l.category}: ${l.placed} of ${l.requested} placed — ${l.reason}`)),
    ...list('Not understood', r.notUnderstood.map((n) => `“${n.text}”: ${n.reason}`)),
    ...list('Warnings', r.warnings.map((w) => `[${w.stage}] ${w.message}`)),
  );
}

export function historyPanel(current: string, versions: Version[]): HTMLElement {
  return h(
    'div',
    { class: 'history', id: 'history' },
    h('p', { class: 'muted', text: 'Every edit makes a new version; open an older one to go back (edits from it branch off).' }),
    h(
      'ol',
      {},
      ...versions.map((v) =>
        h(
          'li',
          { class: v.id === current ? 'current' : '', data: { version: String(v.version) } },
          h('a', { href: `/scenes/${v.id}`, text: `v${v.version}` }),
          ` ${v.command ?? 'generated'} `,
          h('span', { class: `badge ${v.status}`, text: v.status }),
          h('span', { class: 'muted', text: ` ${fmtDate(v.created_at)}` }),
          v.id === current ? h('span', { class: 'tag', text: 'shown' }) : null,
        ),
      ),
    ),
  );
}
