// `antipode view` of runs in Chromium. A clear-the-box report with its --selections and
// --pictures folders: the page lists every cycle; choosing a failed attempt shows its scene
// (the cloud the cycle captured, its selection, the grasp it tried) and its reason and record
// as the report has them. An isolation report: its attempts by variant, each with its scene.
// A scene file: built, seen, with its objects and box. A tree run's trace: the tree as a diagram, stepped to the node that
// failed. Bad input is one error line.
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

import { antipode, args, drawnPixels, expectRefused, file, launch, openPage, rows } from './browser.mjs';

// One run of four YCB objects with two failed attempts (seed 2002).
const bench = antipode('bench', 'clutter', '--objects', join(args.data, 'objects', 'ycb'), '--runs', '1',
                       '--objects-per-run', '4', '--seed', '2002', '--report', file('run.json'),
                       '--selections', file('sel'), '--pictures', file('pic'));
assert.equal(bench.code, 0, bench.out);
const report = JSON.parse(readFileSync(file('run.json'), 'utf8'));
const cycles = report.run_records[0].cycles;
const failed = cycles.findIndex((c) => c.record && c.outcome !== 'success');
assert.ok(failed >= 0, 'the run has no failed attempt: ' + cycles.map((c) => c.reason).join(', '));
const stem = `seed-2002-cycle-${String(failed + 1).padStart(2, '0')}`;
for (const suffix of ['.json', '.pcd', '-objects.json', '-path.json'])
  assert.ok(readdirSync(file('sel')).includes(stem + suffix), `no ${stem}${suffix}`);

const browser = await launch();
try {
  const made = antipode('view', file('run.json'), '--selections', file('sel'), '--pictures', file('pic'),
                        '--out', file('run.html'));
  assert.equal(made.code, 0, made.out);
  assert.match(made.out, new RegExp(`${cycles.length} scene\\(s\\)`));
  const page = await openPage(browser, file('run.html'));
  assert.equal(await page.$$eval('.cycle', (r) => r.length), cycles.length);
  await page.click(`.cycle[data-run="0"][data-cycle="${failed}"]`);
  const facts = await rows(page, '#cycle-facts');
  assert.equal(facts.outcome, cycles[failed].outcome);
  assert.equal(facts.reason, cycles[failed].reason);
  const state = await page.evaluate(() => {
    const v = window.antipodeView;
    const e = v.executed();
    return { scene: v.scene, points: v.points, hands: v.hands, executed: e, facts: e >= 0 ? v.facts(e) : null };
  });
  assert.equal(state.scene, failed);
  assert.ok(state.points > 1000, 'the cycle shows no cloud');
  const selection = JSON.parse(readFileSync(file(join('sel', stem + '.json')), 'utf8')).hands;
  assert.equal(state.hands, selection.length);
  assert.ok(state.executed >= 0, 'the tried grasp is not marked');
  const tried = cycles[failed].hand.position_m.map(Math.fround);
  assert.deepEqual(selection[state.executed].position_m.map(Math.fround), tried);
  assert.equal(state.facts.executed, 'yes: the grasp the cycle tried');
  assert.equal(state.facts['failure class'], cycles[failed].reason);  // its attempt record too
  assert.equal(state.facts.lift_m, cycles[failed].record.lift_m.toFixed(4));
  // The cell's two cameras: points seen by the left, by the right and by both.
  await page.selectOption('#cloud-colour', 'view');
  const views = await page.evaluate(() => window.antipodeView.viewCounts());
  assert.deepEqual(Object.keys(views).sort(), ['1', '2', '3'], JSON.stringify(views));
  assert.equal(await page.$$eval('#cycle-detail img', (i) => i.length), 1, 'no picture of the failed attempt');
  // The arm's planned path to the grasp it tried.
  const path = JSON.parse(readFileSync(file(join('sel', stem + '-path.json')), 'utf8'));
  assert.equal(await page.evaluate(() => window.antipodeView.waypoints()), path.waypoints.length);
  assert.ok(path.waypoints.length >= 2);
  assert.ok((await drawnPixels(page)) > 1000, 'the cycle view is blank');
  await page.screenshot({ path: file('run-page.jpg'), type: 'jpeg', quality: 80 });
  console.log(`clear the box: cycle ${failed + 1} of ${cycles.length}, ${cycles[failed].reason}: ` +
              `${state.points} points, ${state.hands} hands`);
  await page.close();

  // An isolation bench: its attempts grouped by variant, each with its scene.
  const iso = antipode('bench', 'isolation', '--objects', join(args.data, 'objects', 'ycb'), '--variants', 'nc_2v',
                       '--attempts', '2', '--report', file('iso.json'), '--selections', file('isel'));
  assert.equal(iso.code, 0, iso.out);
  const attempts = JSON.parse(readFileSync(file('iso.json'), 'utf8')).attempts;
  assert.equal(antipode('view', file('iso.json'), '--selections', file('isel'), '--out', file('iso.html')).code, 0);
  const isoPage = await openPage(browser, file('iso.html'));
  assert.deepEqual(await isoPage.$$eval('#cycles summary', (s) => s.map((e) => e.textContent)), [
    `nc_2v: ${attempts.filter((a) => a.outcome === 'success').length} of 2 attempts succeeded`,
  ]);
  await isoPage.click('.cycle[data-run="0"][data-cycle="1"]');
  assert.equal((await rows(isoPage, '#cycle-facts')).reason, attempts[1].reason);
  const isoStem = `nc_2v-${attempts[1].object}-pose${attempts[1].pose}`;
  const isoHands = JSON.parse(readFileSync(file(join('isel', isoStem + '.json')), 'utf8')).hands.length;
  assert.equal(await isoPage.evaluate(() => window.antipodeView.hands), isoHands);
  assert.ok((await isoPage.evaluate(() => window.antipodeView.points)) > 1000, 'the attempt shows no cloud');
  await isoPage.close();

  // A scene file: the scene built and seen by every camera, where its objects lie, its box.
  assert.equal(antipode('view', join(args.source, 'scenes', 'clear_box_procedural.yaml'), '--out', file('scene.html')).code, 0);
  const scenePage = await openPage(browser, file('scene.html'));
  const shown = await scenePage.evaluate(() => {
    const data = JSON.parse(document.getElementById('antipode-data').textContent);
    return { points: window.antipodeView.points, objects: data.scenes[0].objects.length, box: data.scenes[0].fixtures.box };
  });
  assert.ok(shown.points > 10000, 'the scene shows no cloud');
  assert.equal(shown.objects, 10, 'the scene file drops ten objects');
  assert.deepEqual(shown.box.inner_size_m, [0.3, 0.3]);
  await scenePage.close();

  // The trace.
  const detect = antipode('run', join(args.source, 'trees', 'detect.yaml'), '--set',
                          `cloud_file=${join(args.data, 'clouds', 'table_mug.pcd')}`, '--set',
                          'sampler.samples=300', '--set', `grasps_file=${file('g.json')}`, '--set',
                          'classifier.threshold=100', '--trace', file('trace.jsonl'));
  assert.equal(detect.code, 1, detect.out);
  const lines = readFileSync(file('trace.jsonl'), 'utf8').trim().split('\n').map((l) => JSON.parse(l));
  assert.equal(antipode('view', file('trace.jsonl'), '--out', file('trace.html')).code, 0);
  const trace = await openPage(browser, file('trace.html'));
  assert.equal(await trace.$$eval('#trace-tree .node', (n) => n.length), new Set(lines.map((l) => l.path)).size);
  await trace.evaluate(() => window.antipodeView.traceStep(0));
  const first = await trace.$$eval('#trace-tree .node', (n) => n.map((e) => e.dataset.status));
  assert.deepEqual(first, ['RUNNING', ...first.slice(1).map(() => 'IDLE')]);
  await trace.click('#trace-next-failure');
  const failure = lines.find((l) => l.to === 'FAILURE' && l.reason);
  const caption = await trace.textContent('#trace-caption');
  assert.ok(caption.includes(`${failure.node} → FAILURE (${failure.reason})`), caption);
  const node = [...new Set(lines.map((l) => l.path))].indexOf(failure.path);
  assert.equal(await trace.$eval(`#trace-tree .node[data-node="${node}"]`, (e) => e.dataset.status), 'FAILURE');
  await trace.screenshot({ path: file('trace-page.jpg'), type: 'jpeg', quality: 80 });
  await trace.close();
} finally {
  await browser.close();
}

// Bad input: one error line naming the input, exit 2, and no page written.
writeFileSync(file('bad.jsonl'), '{"time_s": 0, "path": "x", "to": "SUCCESS"}\n{"time_s": "soon"}\n');
expectRefused([
  [['view', file('bad.jsonl')], 'bad.jsonl:2: not a status change'],
  [['view', file('run.json'), '--selections', file('nowhere')], "'" + file('nowhere') + "' is not a folder"],
  [['view', file('run.json'), join(args.data, 'clouds', 'table_mug.pcd')], "a report's attempts bring their own clouds"],
  [['view', join(args.source, 'scenes', 'room.yaml'), file('run.json')], 'a scene file is shown alone'],
  [['view', file('nowhere.yaml')], "scene '" + file('nowhere.yaml') + "': no such file"],
]);
console.log('viewer (runs and traces): all checks passed');
