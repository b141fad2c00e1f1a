// Builds the page template `antipode view` fills: page.html with the viewer's script
// (src/main.js and three.js, bundled and minified by esbuild) inlined, so that a page needs
// no server and no network. The command puts its data where <!--antipode-data--> stands.
//   node build.mjs OUT.html
import { readFileSync, writeFileSync, renameSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';

const here = dirname(fileURLToPath(import.meta.url));
const out = process.argv[2];
if (!out) {
  console.error('usage: node build.mjs OUT.html');
  process.exit(2);
}
const result = await build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'none',
  write: false,
});
const script = result.outputFiles[0].text;
if (/<\/script/i.test(script)) throw new Error('the bundle holds "</script": it cannot be inlined');
const page = readFileSync(join(here, 'page.html'), 'utf8');
const marker = '/*antipode-viewer-script*/';
if (!page.includes(marker) || !page.includes('<!--antipode-data-->'))
  throw new Error('page.html lacks its markers');
writeFileSync(out + '.tmp', page.replace(marker, () => script));
renameSync(out + '.tmp', out);
