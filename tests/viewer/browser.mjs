// What the viewer's browser tests share: their arguments, the antipode command, and Debian's
// Chromium (headless, software rendering) opening a page offline.
//   node TEST.mjs --cli ANTIPODE --node-modules DIR --chromium EXE --data DIR --work DIR
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join, resolve } from 'node:path';

export const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, word, i, all) => {
    if (word.startsWith('--')) pairs.push([word.slice(2), all[i + 1]]);
    return pairs;
  }, []),
);
rmSync(args.work, { recursive: true, force: true });
mkdirSync(args.work, { recursive: true });

/** A path in the test's work folder (screenshots are kept there as the test's artefacts). */
export const file = (name) => join(args.work, name);

/** Runs antipode; {code, out} (stdout then stderr). */
export function antipode(...words) {
  const run = spawnSync(args.cli, words, { encoding: 'utf8' });
  return { code: run.status, out: run.stdout + run.stderr };
}

export async function launch() {
  const { chromium } = createRequire(join(resolve(args['node-modules']), 'x.js'))('playwright-core');
  return chromium.launch({
    executablePath: args.chromium,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
}

/** Opens the page at `path`; asserts it loaded with no error and fetched nothing. */
export async function openPage(browser, path) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  const outside = [];
  page.on('request', (request) => {
    const url = request.url();
    if (!url.startsWith('file://') && !url.startsWith('data:') && !url.startsWith('blob:'))
      outside.push(url);
  });
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => message.type() === 'error' && errors.push(message.text()));
  await page.goto('file://' + path);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
  assert.deepEqual(errors, [], 'the page raised errors');
  assert.deepEqual(outside, [], 'the page fetched something');
  page.errors = errors;
  return page;
}

/** Pixels of the 3D view that are not the background: something was drawn. */
export const drawnPixels = (page) =>
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

/** The rows of a facts table (`#hand-info`, `#cycle-facts`) as {key: value}. */
export const rows = (page, selector) =>
  page.$$eval(`${selector} tr`, (trs) =>
    Object.fromEntries(trs.map((r) => [r.dataset.key, r.querySelector('td').textContent])),
  );

/**
 * Each of `cases` ([arguments, text]) is refused: exit 2, one error line holding `text`, and
 * no page written.
 */
export function expectRefused(cases) {
  for (const [words, text] of cases) {
    const bad = antipode(...words, '--out', file('bad.html'));
    assert.equal(bad.code, 2, bad.out);
    assert.equal(bad.out.trim().split('\n').length, 1, bad.out);
    assert.ok(bad.out.includes(text), bad.out);
  }
  assert.throws(() => readFileSync(file('bad.html')), 'a failed view wrote its page');
}
