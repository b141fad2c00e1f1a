// How fast a large `antipode view` page opens in headless Chromium (SwiftShader WebGL, no
// GPU): a seeded page of 300,000 points and 5,000 hands, opened REPEATS times, each in a new
// browser. Prints the page's size and the median and slowest of: the page's script done
// (window.antipodeView.loadMs, after navigation), the first frame read back from the canvas
// (navigation to pixels, which waits for the software renderer to draw it; the page opens on
// its 1,250 accepted hands), and ticking every rejection reason until all 5,000 hands are
// drawn and read back.
//   node bench/viewer/load.mjs --cli build/bin/antipode --node-modules build/viewer/node_modules \
//     --chromium /usr/bin/chromium [--repeats 5] [--work /tmp/antipode-viewer-bench]
import { spawnSync } from 'node:child_process';
import { mkdirSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join, resolve } from 'node:path';

import { writeCloud, writeGrasps } from '../../viewer/tools/synthetic_scene.mjs';

const args = { repeats: '5', work: '/tmp/antipode-viewer-bench' };
process.argv.slice(2).forEach((word, i, all) => {
  if (word.startsWith('--')) args[word.slice(2)] = all[i + 1];
});
for (const needed of ['cli', 'node-modules', 'chromium'])
  if (!args[needed]) {
    console.error(`load.mjs: give --${needed}`);
    process.exit(2);
  }
const { chromium } = createRequire(join(resolve(args['node-modules']), 'x.js'))('playwright-core');
mkdirSync(args.work, { recursive: true });
const file = (name) => join(args.work, name);
writeCloud(file('cloud.ply'), 300000);
writeGrasps(file('grasps.json'), 5000);
const made = spawnSync(args.cli, ['view', file('cloud.ply'), file('grasps.json'), '--out', file('page.html')]);
if (made.status !== 0) throw new Error(String(made.stderr));

const ready = [];
const drawn = [];
const all = [];
for (let k = 0; k < Number(args.repeats); k++) {
  const browser = await chromium.launch({
    executablePath: args.chromium,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
  const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
  const start = Date.now();
  await page.goto('file://' + file('page.html'), { timeout: 120000 });
  await page.evaluate(() => {
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    [c.width, c.height] = [gl.width, gl.height];
    c.getContext('2d').drawImage(gl, 0, 0);
  });
  drawn.push(Date.now() - start);
  ready.push(await page.evaluate(() => window.antipodeView.loadMs));
  // The page opens on its accepted hands; ticking every rejection reason draws all 5,000.
  const tick = Date.now();
  await page.evaluate(() => {
    for (const box of document.querySelectorAll('#reasons input:not(:checked)')) box.click();
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    [c.width, c.height] = [gl.width, gl.height];
    c.getContext('2d').drawImage(gl, 0, 0);
  });
  all.push(Date.now() - tick);
  await browser.close();
}
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
const mb = (statSync(file('page.html')).size / 1e6).toFixed(1);
console.log(`page of 300,000 points and 5,000 hands: ${mb} MB; ${ready.length} opens`);
console.log(`script done: median ${median(ready).toFixed(0)} ms, slowest ${Math.max(...ready).toFixed(0)} ms`);
console.log(`first frame read back: median ${median(drawn)} ms, slowest ${Math.max(...drawn)} ms`);
console.log(`every hand shown and read back: median ${median(all)} ms, slowest ${Math.max(...all)} ms`);
