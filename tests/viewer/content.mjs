// The viewer draws 3D content: a tileset of `maquette export tiles3d --content` (the store of
// tests/content_export/make_content_store: a red box (mesh layer), green builtin:conifer
// instances (instances layer, EXT_mesh_gpu_instancing with per-instance colour) and a lake
// (volume layer) on grey untextured terrain) opened in Chromium; the screenshot must show red
// around where the box's top projects and not around the trees, and green around each tree and
// not around the box, also with the hillshade shading (which is the terrain's only).
//
// node content.mjs --maquette BIN --viewer DIR --node-modules DIR --out DIR --tileset-dir DIR
//   --expect FILE (make_content_store's JSON: lon, lat, height of the box's top and the trees)
// Exit codes: 0 pass, 1 fail, 77 skipped (no chromium).
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { Checks, launchBrowser, log, parseArgs, requireFrom, shoot, startView, waitLoaded } from './harness.mjs';

const args = parseArgs();
const out = resolve(args.out);
const nodeModules = resolve(args['node-modules']);
const { PNG } = requireFrom(nodeModules)('pngjs');
const expect = JSON.parse(readFileSync(args.expect, 'utf8'));
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });

const checks = new Checks();
const check = checks.check.bind(checks);
const view = await startView(args.maquette, resolve(args['tileset-dir']), args.viewer);
const b = await launchBrowser(nodeModules);
let exitCode = 1;

const isRed = (r, g, bl) => r > 90 && r > 2 * g && r > 2 * bl;
const isGreen = (r, g, bl) => g > 40 && g > 1.4 * r && g > 1.4 * bl;

// How many pixels of `png` within `radius` of (x, y) satisfy `test`.
function around(png, [x, y], radius, test) {
  let n = 0;
  for (let j = Math.max(0, Math.round(y - radius)); j <= Math.min(png.height - 1, y + radius); j++) {
    for (let i = Math.max(0, Math.round(x - radius)); i <= Math.min(png.width - 1, x + radius); i++) {
      const k = 4 * (j * png.width + i);
      if (test(png.data[k], png.data[k + 1], png.data[k + 2])) n++;
    }
  }
  return n;
}

try {
  // errorTarget 1: the finest tiles, where the trees are (they have no simplified copy).
  await b.page.goto(`${view.url}?errorTarget=1`, { waitUntil: 'load' });
  await waitLoaded(b, 'content', out, () => ({ state: window.__maquette }), 60000);
  const st = await b.page.evaluate(() => ({ ...window.__maquette }));
  check(!st.errors.length, `tiles loaded without errors ${st.errors.join('; ')}`);
  check(st.extraContentsLoaded >= 3, `content GLBs loaded (${st.extraContentsLoaded})`);
  const instanced = await b.page.evaluate(() => {
    let n = 0;
    window.__maquetteViewer.scene.traverse((o) => { if (o.isInstancedMesh && o.instanceColor) n++; });
    return n;
  });
  check(instanced > 0, `instances drawn as InstancedMesh with instance colours (${instanced})`);
  // Where the expected points are on the screen, through the tiles' group (reoriented) and camera.
  const screen = await b.page.evaluate((points) => {
    const { THREE, tiles, camera, renderer } = window.__maquetteViewer;
    const size = renderer.getSize(new THREE.Vector2());
    return points.map(([lon, lat, h]) => {
      const p = tiles.ellipsoid.getCartographicToPosition(THREE.MathUtils.degToRad(lat),
        THREE.MathUtils.degToRad(lon), h, new THREE.Vector3());
      p.applyMatrix4(tiles.group.matrixWorld).project(camera);
      return [(p.x + 1) / 2 * size.x, (1 - p.y) / 2 * size.y];
    });
  }, [expect.box, ...expect.trees]);
  const png = await shoot(b, out, 'viewer-content.png', PNG);
  const [box, ...trees] = screen;
  log(`box at ${box.map((v) => v.toFixed(0))}, trees at ${trees.map((t) => t.map((v) => v.toFixed(0)).join(',')).join(' ')}`);
  const radius = 8;
  check(around(png, box, radius, isRed) > 20, `red around the box's top (${around(png, box, radius, isRed)} pixels)`);
  check(around(png, box, radius, isGreen) === 0, 'no green around the box');
  trees.forEach((t, i) => {
    const green = around(png, t, radius, isGreen);
    check(green > 5, `green around tree ${i} (${green} pixels)`);
    check(around(png, t, radius, isRed) === 0, `no red around tree ${i}`);
  });
  // The hillshade is the terrain's: content keeps its colours.
  await b.page.click('#toggle-shading');
  await b.page.waitForFunction(() => document.documentElement.dataset.shading === 'hillshade', null, { timeout: 5000 });
  await waitLoaded(b, 'hillshade', out, () => ({ state: window.__maquette }), 60000);
  const hill = await shoot(b, out, 'viewer-content-hillshade.png', PNG);
  check(around(hill, box, radius, isRed) > 20, `hillshade: red around the box's top (${around(hill, box, radius, isRed)} pixels)`);
  check(around(hill, trees[0], radius, isGreen) > 5, `hillshade: green around tree 0 (${around(hill, trees[0], radius, isGreen)} pixels)`);
  exitCode = checks.failures.length ? 1 : 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
} finally {
  await b.close();
  await view.stop();
}
log(exitCode ? `${checks.failures.length} check(s) failed` : 'all checks passed');
process.exit(exitCode);
