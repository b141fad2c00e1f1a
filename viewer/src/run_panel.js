// A bench run, attempt by attempt: a clear-the-box run's cycles per seed, or an isolation
// bench's attempts per variant, with their outcomes; choosing one shows its scene (the cloud
// it captured, its selection and the grasp it tried) and what happened: the outcome, its
// failure class, the cell's detail and record, and its picture.

import { element, factRows, recordFacts } from './dom.js';

/**
 * Builds the run's list into `root`; `choose(sceneIndex)` shows one of `scenes`. Returns
 * {choose(run, cycle)} for the page's test hook.
 */
export function buildRunPanel(root, run, scenes, choose) {
  root.appendChild(element('h2', {}, run.report));
  const s = run.summary || {};
  if (s.attempts !== undefined)
    root.appendChild(
      element('p', {}, `${s.successes} of ${s.attempts} attempts succeeded; ${s.removed} of ${s.objects} objects removed`),
    );
  const list = root.appendChild(element('div', { id: 'cycles' }));
  const detail = root.appendChild(element('div', { id: 'cycle-detail' }));
  const rows = [];
  function show(r, c) {
    const cycle = run.runs[r].cycles[c];
    rows.forEach((row) => row.classList.toggle('chosen', row.dataset.run == r && row.dataset.cycle == c));
    detail.replaceChildren();
    detail.appendChild(element('h3', {}, cycle.title));
    const facts = [
      ['outcome', cycle.outcome],
      ['reason', cycle.reason],
    ];
    if (cycle.detail) facts.push(['detail', cycle.detail]);
    const table = detail.appendChild(element('table', { id: 'cycle-facts' }));
    factRows(table, facts.concat(recordFacts(cycle.record)));
    const picture = scenes[cycle.scene].picture;
    if (picture) detail.appendChild(element('img', { src: picture, alt: 'the attempt as DrawAttempt drew it', width: '100%' }));
    choose(cycle.scene);
  }
  run.runs.forEach((r, ri) => {
    const block = list.appendChild(element('details', { open: '' }));
    block.appendChild(element('summary', {}, r.title));
    r.cycles.forEach((cycle, ci) => {
      const ok = cycle.outcome === 'success';
      const attempt = cycle.record !== undefined;
      const row = block.appendChild(
        element(
          'div',
          { class: 'cycle ' + (ok ? 'ok' : attempt ? 'failed' : 'none'), 'data-run': ri, 'data-cycle': ci },
          `${run.bench === 'clutter' ? ci + 1 + '.' : cycle.title + ':'} ${cycle.outcome}${!ok && cycle.reason !== cycle.outcome ? ': ' + cycle.reason : ''}`,
        ),
      );
      row.addEventListener('click', () => show(ri, ci));
      rows.push(row);
    });
  });
  return { choose: show };
}

