// `antipode view` of detections in Chromium: a page of 300,000 points and 5,000 hands loads
// offline (no request leaves the page), draws, and answers a click on a hand with that hand's
// facts; the filters show and hide hands; the page of a real detection shows every hand of its
// file, its chosen grasp's rank and score, why each hand around it was dropped, and the cloud's
// support and object segments; bad input is one error line.
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

import { writeCloud, writeGrasps } from '../../viewer/tools/synthetic_scene.mjs';
import { antipode, args, drawnPixels, expectRefused, file, launch, openPage, rows } from './browser.mjs';

const browser = await launch();
try {
  // 1. The large page. Its accepted hands are shown first; ticking every reason draws all.
  writeCloud(file('cloud.ply'), 300000);
  const hands = writeGrasps(file('grasps.json'), 5000);
  const made = antipode('view', file('cloud.ply'), file('grasps.json'), '--out', file('page.html'));
  assert.equal(made.code, 0, made.out);
  assert.match(made.out, /1 scene\(s\), 300000 points, 5000 hands/);
  const page = await openPage(browser, file('page.html'));
  const view = await page.evaluate(() => ({ ...window.antipodeView }));
  assert.equal(view.points, 300000);
  assert.equal(view.hands, 5000);
  console.log(`300,000 points and 5,000 hands: ready ${view.loadMs.toFixed(0)} ms after navigation`);
  for (const box of await page.$$('#reasons input:not(:checked)')) await box.click();
  assert.ok((await drawnPixels(page)) > 10000, 'the view is blank');
  await page.screenshot({ path: file('large-page.jpg'), type: 'jpeg', quality: 80 });

  // 2. Clicking a hand shows the facts of the hand drawn there (the first palm in view).
  let picked = -1;
  let at = null;
  for (let i = 0; i < hands.length && picked < 0; i += 7) {
    const [x, y] = await page.evaluate((j) => window.antipodeView.screenPositionOf(j), i);
    picked = await page.evaluate(([px, py]) => window.antipodeView.handAt(px, py), [x, y]);
    at = [x, y];
  }
  assert.ok(picked >= 0, 'no hand could be clicked at its palm');
  await page.mouse.click(at[0], at[1]);
  const shown = await rows(page, '#hand-info');
  assert.equal(shown.hand, String(picked));
  assert.equal(shown.score, Math.fround(hands[picked].score).toFixed(4));
  assert.equal(shown.object, String(hands[picked].object));
  assert.equal(shown.rejection, hands[picked].rejection || 'none (accepted)');

  // 3. Unticking the hand's rejection reason hides it: the same click no longer finds it.
  const reason = hands[picked].rejection || 'accepted';
  await page.click(`#reasons input[data-value="${reason}"]`);
  const after = await page.evaluate(([px, py]) => window.antipodeView.handAt(px, py), at);
  assert.notEqual(after, picked, 'a hidden hand was still picked');
  assert.ok(after < 0 || (hands[after].rejection || 'accepted') !== reason);
  await page.close();

  // 4. A real detection with its rejected hands: every hand of `detect --out` is on the page,
  // the filters list the stages' reasons, and the test hook gives the chosen grasp's rank and
  // score and each neighbour's reason as the file has them.
  const cloud = join(args.data, 'clouds', 'table_mug.pcd');
  const detect = antipode('detect', cloud, '--out', file('mug.json'), '--rejected',
                          '--set', 'sampler.samples=300');
  assert.equal(detect.code, 0, detect.out);
  const found = JSON.parse(readFileSync(file('mug.json'), 'utf8')).hands;
  const reasons = new Set(found.map((h) => h.rejection || 'accepted'));
  assert.ok(reasons.has('accepted') && reasons.size > 1, [...reasons].join(', '));
  assert.equal(antipode('view', cloud, file('mug.json'), '--out', file('mug.html')).code, 0);
  const mug = await openPage(browser, file('mug.html'));
  assert.equal(await mug.evaluate(() => window.antipodeView.hands), found.length);
  const listed = await mug.$$eval('#reasons input', (inputs) => inputs.map((i) => i.dataset.value));
  assert.deepEqual(new Set(listed), reasons);
  assert.ok((await drawnPixels(mug)) > 1000, 'the mug view is blank');

  // Coloured by segment: the table is the support and holds most points, the mug is one object.
  await mug.selectOption('#cloud-colour', 'segment');
  const segments = await mug.evaluate(() => window.antipodeView.segmentCounts());
  assert.ok(segments['-1'] > segments['0'] && segments['0'] > 1000, JSON.stringify(segments));
  assert.equal(segments['1'], undefined, 'the mug alone on the table is one segment');

  const best = found.findIndex((h) => h.rank === 1);
  const chosen = await mug.evaluate(() => window.antipodeView.chosen());
  assert.deepEqual(chosen, { index: best, rank: 1, score: Math.fround(found[best].score) });
  // The file's hands within 2 cm of the chosen one, at the page's float32 precision.
  const f = (v) => v.map(Math.fround);
  const [x, y, z] = f(found[best].position_m);
  const expected = found
    .map((h, index) => {
      const [u, v, w] = f(h.position_m);
      return { index, distance: Math.hypot(u - x, v - y, w - z), rejection: h.rejection || 'accepted' };
    })
    .filter((n) => n.index !== best && n.distance <= 0.02);
  const around = await mug.evaluate((i) => window.antipodeView.neighbours(i), best);
  assert.ok(around.length > 0, 'no hand around the chosen grasp');
  assert.deepEqual(
    around.map((n) => [n.index, n.rejection]).sort((a, b) => a[0] - b[0]),
    expected.map((n) => [n.index, n.rejection]),
  );
  console.log(`mug: chosen hand ${best} (score ${found[best].score.toFixed(3)}), ` +
              `${around.length} hands within 2 cm: ${[...new Set(around.map((n) => n.rejection))].join(', ')}`);
  // Clicking at the chosen grasp's palm shows the facts of the hand drawn there (the chosen
  // one, or an accepted hand in front of it) as the file has them, and lists its neighbours.
  const [cx, cy] = await mug.evaluate((i) => window.antipodeView.screenPositionOf(i), best);
  const hit = await mug.evaluate(([px, py]) => window.antipodeView.handAt(px, py), [cx, cy]);
  assert.ok(hit >= 0 && !found[hit].rejection, `no accepted hand drawn at the chosen palm (${hit})`);
  await mug.mouse.click(cx, cy);
  const facts = await rows(mug, '#hand-info');
  assert.equal(facts.hand, String(hit));
  assert.equal(facts.rank, String(found[hit].rank));
  assert.equal(facts.score, Math.fround(found[hit].score).toFixed(4));
  const aroundHit = await mug.evaluate((i) => window.antipodeView.neighbours(i), hit);
  assert.equal(await mug.$$eval('#neighbours li', (items) => items.length), Math.min(aroundHit.length, 12));
  await mug.screenshot({ path: file('mug-page.jpg'), type: 'jpeg', quality: 80 });
  await mug.close();
} finally {
  await browser.close();
}

// 5. Bad input: one error line naming the input, exit 2, and no page written.
writeFileSync(file('not-grasps.json'), '{"grasps": []}');
expectRefused([
  [['view', file('notes.txt')], "'" + file('notes.txt') + "': not a cloud (.pcd, .ply), a grasps file"],
  [['view', file('grasps.json')], 'give the cloud'],
  [['view', file('cloud.ply'), file('cloud.ply')], 'a second cloud'],
  [['view', file('cloud.ply'), file('mug.html') + '.json'], 'mug.html.json'],
  [['view', file('cloud.ply'), file('not-grasps.json')], 'not a grasps file'],
  [['view', file('cloud.ply'), '--selections', args.work], '--selections and --pictures go with a bench report'],
]);
console.log('viewer: all checks passed');
