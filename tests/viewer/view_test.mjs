// `antipode view` in Chromium: a page of 300,000 points and 5,000 hands loads offline (no
// request leaves the page), draws, and answers a click on a hand with that hand's facts; the
// filters hide hands; a real detection's page shows its hands; bad input is one error line.
//   node view_test.mjs --cli ANTIPODE --node-modules DIR --chromium EXE --data DIR --work DIR
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, rmSync, writeFileSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join, resolve } from 'node:path';

import { writeCloud, writeGrasps } from '../../viewer/tools/synthetic_scene.mjs';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, word, i, all) => {
    if (word.startsWith('--')) pairs.push([word.slice(2), all[i + 1]]);
    return pairs;
  }, []),
);
const { chromium } = createRequire(join(resolve(args['node-modules']), 'x.js'))('playwright-core');
rmSync(args.work, { recursive: true, force: true });
mkdirSync(args.work, { recursive: true });
const file = (name) => join(args.work, name);

function antipode(...words) {
  const run = spawnSync(args.cli, words, { encoding: 'utf8' });
  return { code: run.status, out: run.stdout + run.stderr };
}

async function openPage(browser, path) {
  const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
  const outside = [];
  page.on('request', (request) => {
    const url = request.url();
    if (!url.startsWith('file://') && !url.startsWith('data:') && !url.startsWith('blob:'))
      outside.push(url);
  });
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('file://' + path);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
  assert.deepEqual(errors, [], 'the page raised errors');
  assert.deepEqual(outside, [], 'the page fetched something');
  return page;
}

// Pixels of the 3D view that are not the background: something was drawn.
const drawnPixels = (page) =>
  page.evaluate(() => {
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    [c.width, c.height] = [gl.width, gl.height];
    const g = c.getContext('2d');
    g.drawImage(gl, 0, 0);
    const pixels = g.getImageData(0, 0, c.width, c.height).data;
    let drawn = 0;
    for (let i = 0; i < pixels.length; i += 4) if (Math.abs(pixels[i] - 244) > 12) drawn++;
    return drawn;
  });

const info = (page) =>
  page.$$eval('#hand-info tr', (rows) =>
    Object.fromEntries(rows.map((r) => [r.dataset.key, r.querySelector('td').textContent])),
  );

const browser = await chromium.launch({
  executablePath: args.chromium,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
});
try {
  // 1. The large page.
  writeCloud(file('cloud.ply'), 300000);
  const hands = writeGrasps(file('grasps.json'), 5000);
  const made = antipode('view', file('cloud.ply'), file('grasps.json'), '--out', file('page.html'));
  assert.equal(made.code, 0, made.out);
  assert.match(made.out, /300000 points, 5000 hands/);
  const page = await openPage(browser, file('page.html'));
  const view = await page.evaluate(() => ({ ...window.antipodeView }));
  assert.equal(view.points, 300000);
  assert.equal(view.hands, 5000);
  console.log(`300,000 points and 5,000 hands: ready ${view.loadMs.toFixed(0)} ms after navigation`);
  assert.ok((await drawnPixels(page)) > 10000, 'the view is blank');

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
  const shown = await info(page);
  assert.equal(shown.hand, String(picked));
  assert.equal(shown.score, hands[picked].score.toFixed(4));
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
  // and the filters list the stages' reasons.
  const cloud = join(args.data, 'clouds', 'table_mug.pcd');
  const detect = antipode('detect', cloud, '--out', file('mug.json'), '--rejected',
                          '--set', 'sampler.samples=300');
  assert.equal(detect.code, 0, detect.out);
  const found = JSON.parse(readFileSync(file('mug.json'), 'utf8')).hands;
  const count = found.length;
  const reasons = new Set(found.map((h) => h.rejection || 'accepted'));
  assert.ok(reasons.has('accepted') && reasons.size > 1, [...reasons].join(', '));
  assert.equal(antipode('view', cloud, file('mug.json'), '--out', file('mug.html')).code, 0);
  const mug = await openPage(browser, file('mug.html'));
  assert.equal(await mug.evaluate(() => window.antipodeView.hands), count);
  assert.ok(count > 0);
  const listed = await mug.$$eval('#reasons input', (inputs) => inputs.map((i) => i.dataset.value));
  assert.deepEqual(new Set(listed), reasons);
  assert.ok((await drawnPixels(mug)) > 1000, 'the mug view is blank');
  await mug.close();
} finally {
  await browser.close();
}

// 5. Bad input: one error line naming the input, exit 2, and no page written.
for (const [words, text] of [
  [['view', file('scene.yaml')], "'" + file('scene.yaml') + "': not a cloud (.pcd, .ply) or a grasps file"],
  [['view', file('grasps.json')], 'give a cloud'],
  [['view', file('cloud.ply'), file('cloud.ply')], 'a second cloud'],
  [['view', file('cloud.ply'), file('mug.html') + '.json'], 'mug.html.json'],
]) {
  const bad = antipode(...words, '--out', file('bad.html'));
  assert.equal(bad.code, 2, bad.out);
  assert.equal(bad.out.trim().split('\n').length, 1, bad.out);
  assert.ok(bad.out.includes(text), bad.out);
}
writeFileSync(file('not-grasps.json'), '{"grasps": []}');
const notGrasps = antipode('view', file('cloud.ply'), file('not-grasps.json'), '--out', file('bad.html'));
assert.equal(notGrasps.code, 2, notGrasps.out);
assert.match(notGrasps.out, /not a grasps file/);
assert.throws(() => readFileSync(file('bad.html')), 'a failed view wrote its page');
console.log('viewer: all checks passed');
