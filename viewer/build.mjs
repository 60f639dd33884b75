// Bundles the viewer into a static folder: node build.mjs [OUTDIR] (default ./dist).
// OUTDIR gets index.html, style.css, app.js and draco/ (three's Draco decoder, served locally).
import { build } from 'esbuild';
import { cpSync, mkdirSync, copyFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const out = resolve(process.argv[2] || join(here, 'dist'));
mkdirSync(out, { recursive: true });

await build({
  entryPoints: [join(here, 'src', 'app.js')],
  bundle: true,
  format: 'iife',
  target: ['es2020'],
  minify: true,
  sourcemap: false,
  legalComments: 'linked',
  outfile: join(out, 'app.js'),
  logLevel: 'warning',
});
for (const f of ['index.html', 'style.css']) copyFileSync(join(here, 'src', f), join(out, f));
const draco = join(here, 'node_modules', 'three', 'examples', 'jsm', 'libs', 'draco', 'gltf');
mkdirSync(join(out, 'draco'), { recursive: true });
for (const f of ['draco_decoder.js', 'draco_decoder.wasm', 'draco_wasm_wrapper.js']) {
  cpSync(join(draco, f), join(out, 'draco', f));
}
console.log(`maquette viewer bundled into ${out}`);
