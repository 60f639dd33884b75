// End-to-end test of the viewer in a real browser: `maquette view TILESET_DIR --port 0` serves the
// viewer bundle and a tileset; Debian's chromium, driven by playwright-core, opens it, waits for
// the page to signal that every tile in view has loaded, screenshots it and checks that terrain
// covers a good part of the frame and differs from the background, that the hillshade/texture
// toggle changes the pixels, and that the readout names a cell and a lon/lat under the mouse.
//
// node e2e.mjs --maquette BIN --viewer DIR --node-modules DIR --out DIR [--tileset-dir DIR]
//   --tileset-dir: an export of `maquette export tiles3d` (e.g. the demo's); without it a small
//                  Draco tileset is generated into OUT/tileset (make_tileset.mjs).
// Exit codes: 0 pass, 1 fail, 77 skipped (no chromium).
import { spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  Checks, launchBrowser, log, parseArgs, requireFrom, shoot, startView, terrainPixels, waitLoaded as waitFor,
} from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const args = parseArgs();
const out = resolve(args.out || 'viewer-e2e-out');
const nodeModules = resolve(args['node-modules'] || join(here, 'node_modules'));
const { PNG } = requireFrom(nodeModules)('pngjs');

rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
let tilesetDir = args['tileset-dir'] && resolve(args['tileset-dir']);
const generated = !tilesetDir;
if (generated) {
  tilesetDir = join(out, 'tileset');
  const r = spawnSync(process.execPath, [join(here, 'make_tileset.mjs'), tilesetDir, nodeModules], { stdio: 'inherit' });
  if (r.status !== 0) throw new Error('make_tileset.mjs failed');
}

const checks = new Checks();
const check = checks.check.bind(checks);
const { failures } = checks;

const view = await startView(args.maquette, tilesetDir, args.viewer);
const { url } = view;
const b = await launchBrowser(nodeModules);
const { page, consoleErrors, requests, badRequests } = b;
let exitCode = 1;
try {
  await page.goto(url, { waitUntil: 'load' });
  // on a timeout, say where it got stuck: the page state, the renderer's tile counts, the camera
  const waitLoaded = async (what) => {
    await waitFor(b, what, out, () => {
      const v = window.__maquetteViewer;
      return { state: window.__maquette, stats: v?.tiles.stats, visibleTiles: v?.tiles.visibleTiles.size,
        camera: v?.camera.position.toArray(), target: v?.controls.target.toArray() };
    }, 40000);
    const st = await page.evaluate(() => ({ ...window.__maquette }));
    check(!st.errors.length, `${what}: tiles loaded without errors ${st.errors.join('; ')}`);
    return st;
  };
  const st = await waitLoaded('first view');
  log(`page state: ${JSON.stringify({ models: st.modelsLoaded, extra: st.extraContentsLoaded, framed: st.framed, shading: st.shading })}`);
  check(st.modelsLoaded > 0, `models loaded (${st.modelsLoaded})`);
  if (generated) check(st.extraContentsLoaded > 0, `second contents of tiles loaded (${st.extraContentsLoaded})`);
  const foreign = requests.filter((r) => !r.startsWith(url) && !/^(data|blob):/.test(r));
  check(foreign.length === 0, `the page loads only from maquette view (works offline) ${foreign.slice(0, 3).join(' ')}`);
  check(requests.some((r) => r.includes('/draco/')), 'the Draco decoder is served from the bundle');

  // Terrain: pixels away from the background colour. The panel (top left) is not terrain; it is
  // small next to the frame.
  const textured = await shoot(b, out, 'viewer-texture.png', PNG);
  const n = textured.width * textured.height;
  const { cover, sd, mask: isTerrain, count: terrain } = terrainPixels(textured, [0x1d, 0x22, 0x29]);
  check(cover > 0.25, `terrain covers ${(100 * cover).toFixed(1)} % of the frame (> 25 %)`);
  check(sd > 8, `terrain pixels vary (luminance s.d. ${sd.toFixed(1)} > 8): not a flat fill`);

  // Readout under the mouse at the centre of the frame (the framed tileset's centre).
  await page.mouse.move(textured.width / 2, textured.height / 2);
  await page.mouse.move(textured.width / 2 + 3, textured.height / 2 + 2);
  await page.waitForFunction(() => document.documentElement.dataset.cell !== undefined, null, { timeout: 5000 })
    .catch(() => {});
  const ro = await page.evaluate(() => ({ cell: window.__maquette.cell, lon: window.__maquette.lon,
    lat: window.__maquette.lat, text: document.getElementById('readout').textContent }));
  log(`readout: ${ro.text}`);
  check(typeof ro.cell === 'string' && /^[NOPQRS][0-3]*$/.test(ro.cell), `readout names a cell (${ro.cell})`);
  check(Number.isFinite(ro.lon) && Number.isFinite(ro.lat), `readout shows lon/lat (${ro.lon}, ${ro.lat})`);
  const root = JSON.parse(readFileSync(join(tilesetDir, 'tileset.json'), 'utf8')).root;
  const region = root.boundingVolume.region;
  if (region && Number.isFinite(ro.lon)) {
    const deg = region.map((v) => v * 180 / Math.PI);
    const inside = ro.lon >= deg[0] - 1e-6 && ro.lon <= deg[2] + 1e-6 && ro.lat >= deg[1] - 1e-6 && ro.lat <= deg[3] + 1e-6;
    check(inside, `lon/lat under the mouse lies in the root region [${deg.slice(0, 4).map((v) => v.toFixed(4))}]`);
    if (generated) check(ro.cell && ro.cell.length === 3, `readout shows a leaf cell of the refined tileset (${ro.cell})`);
  }

  // Hillshade toggle.
  await page.click('#toggle-shading');
  await page.waitForFunction(() => document.documentElement.dataset.shading === 'hillshade', null, { timeout: 5000 });
  await waitLoaded('hillshade');
  const hill = await shoot(b, out, 'viewer-hillshade.png', PNG);
  let diff = 0, changed = 0;
  for (let i = 0; i < n; i++) {
    if (!isTerrain[i]) continue;
    const d = Math.abs(hill.data[4 * i] - textured.data[4 * i]) + Math.abs(hill.data[4 * i + 1] - textured.data[4 * i + 1])
      + Math.abs(hill.data[4 * i + 2] - textured.data[4 * i + 2]);
    diff += d; if (d > 24) changed++;
  }
  check(terrain > 0 && changed / terrain > 0.3,
    `hillshade/texture toggle changes ${(100 * changed / Math.max(terrain, 1)).toFixed(1)} % of terrain pixels (> 30 %), mean |diff| ${(diff / Math.max(terrain, 1)).toFixed(1)}`);
  await page.click('#toggle-shading');
  await page.waitForFunction(() => document.documentElement.dataset.shading === 'texture', null, { timeout: 5000 });

  check(badRequests.length === 0, `every request succeeded ${badRequests.slice(0, 3).join(' ')}`);
  const fatal = consoleErrors.filter((e) => !/favicon/.test(e));
  check(fatal.length === 0, `no errors in the browser console ${fatal.slice(0, 3).join(' | ')}`);
  writeFileSync(join(out, 'summary.json'), JSON.stringify({ url, tilesetDir, cover, sd, readout: ro, failures }, null, 1));
  exitCode = failures.length ? 1 : 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
  exitCode = 1;
} finally {
  await b.close();
  if (!await view.stop()) exitCode = 1;
}
log(exitCode ? `viewer e2e FAILED: ${failures.join('; ')}` : `viewer e2e passed; screenshots in ${out}`);
process.exit(exitCode);
