// Exports open in CesiumJS (npm cesium), offline: for each tileset folder, `maquette view` serves
// it with the page of tests/viewer/cesium (Cesium from the build tree, no ion token, no base
// imagery, no geocoder or layer picker) to headless chromium; the test waits until Cesium has
// loaded every tile in view, then checks that no tile, request or rendering failed, that nothing
// was asked of another host, and that terrain (pixels away from the background; the globe is
// hidden) covers at least the given share of the frame. The page frames the root's bounding
// volume (Cesium's `zoomTo`), a grid cell that can be far larger than the data (the demo's Olinda
// is about 1 % of its level-5 root cell); given the export's STORE, it looks down at the bounding
// box of the store's `dem` layer instead (`maquette info --json`), as a user flies to their area.
// Screenshots: OUT/cesium-NAME.png.
//
// node cesium.mjs --maquette BIN --page DIR --node-modules DIR --out DIR
//   --tilesets NAME=DIR=MIN_COVER[=STORE],...
// Exit codes: 0 pass, 1 fail, 77 skipped (no chromium).
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';
import {
  Checks, launchBrowser, log, parseArgs, requireFrom, shoot, startView, terrainPixels, waitLoaded,
} from './harness.mjs';

const args = parseArgs();
const out = resolve(args.out);
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const { PNG } = requireFrom(args['node-modules'])('pngjs');
const checks = new Checks();
const check = checks.check.bind(checks);

// The bounding box of STORE's `dem` layer, as the page's ?rect=W,S,E,N.
function demRect(store) {
  const info = JSON.parse(execFileSync(args.maquette, ['info', '--json', store], { encoding: 'utf8' }));
  return `?rect=${info.layers.find((l) => l.name === 'dem').bbox.join(',')}`;
}

async function opensInCesium(name, dir, minCover, store) {
  const view = await startView(args.maquette, dir, args.page);
  // small: SwiftShader draws Cesium's frames at a few per second, and it processes tiles per frame
  const b = await launchBrowser(args['node-modules'], { width: 640, height: 400 });
  try {
    await b.page.goto(`${view.url}${store ? demRect(store) : ''}`, { waitUntil: 'load' });
    await waitLoaded(b, name, out, () => ({ error: document.documentElement.dataset.error }), 120000);
    const error = await b.page.evaluate(() => document.documentElement.dataset.error);
    check(!error, `${name}: Cesium loaded the tileset and every tile in view ${error || ''}`);
    // without Cesium's credits (its logo), which are not terrain
    await b.page.addStyleTag({ content: '.cesium-viewer-bottom { display: none; }' });
    const { cover, sd } = terrainPixels(await shoot(b, out, `cesium-${name}.png`, PNG), [0x1d, 0x22, 0x29]);
    check(cover > minCover, `${name}: terrain covers ${(100 * cover).toFixed(2)} % of the frame (> ${100 * minCover} %)`);
    check(sd > 2, `${name}: terrain pixels vary (luminance s.d. ${sd.toFixed(1)} > 2): lit or textured, not a flat fill`);
    const foreign = b.requests.filter((r) => !r.startsWith(view.url) && !/^(data|blob):/.test(r));
    check(foreign.length === 0, `${name}: every request goes to maquette view (offline, no ion) ${foreign.slice(0, 3).join(' ')}`);
    check(b.badRequests.length === 0, `${name}: every request succeeded ${b.badRequests.slice(0, 3).join(' ')}`);
    const fatal = b.consoleErrors.filter((e) => !/favicon/.test(e));
    check(fatal.length === 0, `${name}: no errors in the browser console ${fatal.slice(0, 3).join(' | ')}`);
  } finally {
    await b.close();
    check(await view.stop(), `${name}: maquette view stops cleanly on SIGINT`);
  }
}

let exitCode = 1;
try {
  for (const entry of args.tilesets.split(',')) {
    const [name, dir, minCover, store] = entry.split('=');
    await opensInCesium(name, resolve(dir), Number(minCover), store);
  }
  exitCode = checks.failures.length ? 1 : 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
}
log(exitCode ? `CesiumJS test FAILED: ${checks.failures.join('; ')}` : `CesiumJS test passed; screenshots in ${out}`);
process.exit(exitCode);
