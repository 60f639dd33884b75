// Exports open in CesiumJS (npm cesium), offline: for each tileset folder, `maquette view` serves
// it with the page of tests/viewer/cesium (Cesium from the build tree, no ion token, no base
// imagery, no geocoder or layer picker) to headless chromium; the test waits until Cesium has
// loaded every tile in view, then checks that no tile, request or rendering failed, that nothing
// was asked of another host, and that terrain (pixels away from the background; the globe is
// hidden) covers at least the given share of the frame and its centre. The page frames the
// content itself, from the tileset's regions (its top cells' regions bound their terrain), as
// the three.js viewer does: no camera is given to it. Checked against the regions read here from
// tileset.json: a regional tileset is seen straight down, every corner of its content in the
// frame; one around the globe from space, looking at the Earth's centre. Screenshots:
// OUT/cesium-NAME.png.
//
// node cesium.mjs --maquette BIN --page DIR --node-modules DIR --out DIR
//   --tilesets NAME=DIR=MIN_COVER,...
// Exit codes: 0 pass, 1 fail, 77 skipped (no chromium).
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
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

// The share of terrain pixels (`mask`, from terrainPixels) in the middle ninth of the frame.
function centreCover({ width, height }, mask) {
  let n = 0, terrain = 0;
  for (let y = Math.floor(height / 3); y < Math.ceil(2 * height / 3); y++) {
    for (let x = Math.floor(width / 3); x < Math.ceil(2 * width / 3); x++, n++) terrain += mask[y * width + x];
  }
  return terrain / n;
}

// The regions (radians) of the root's children in DIR/tileset.json, else the root's.
function topRegions(dir) {
  const { root } = JSON.parse(readFileSync(join(dir, 'tileset.json'), 'utf8'));
  return (root.children?.length ? root.children : [root]).map((t) => t.boundingVolume.region);
}

// Where the camera looks (in the page): the angle (degrees) between its view direction and
// straight down under it, and between it and the direction of the Earth's centre; its height
// (m); and the window position of each lon/lat point (radians, on the ellipsoid).
function cameraView(points) {
  const C = window.Cesium;
  const { camera, scene } = window.__cesium;
  const angle = (a, b) => C.Math.toDegrees(C.Cartesian3.angleBetween(a, b));
  const normal = C.Ellipsoid.WGS84.geodeticSurfaceNormal(camera.positionWC, new C.Cartesian3());
  return {
    fromNadir: angle(camera.directionWC, C.Cartesian3.negate(normal, new C.Cartesian3())),
    fromCentre: angle(camera.directionWC, C.Cartesian3.negate(camera.positionWC, new C.Cartesian3())),
    height: C.Cartographic.fromCartesian(camera.positionWC).height,
    canvas: [scene.canvas.clientWidth, scene.canvas.clientHeight],
    onScreen: points.map(([lon, lat]) => {
      const p = C.SceneTransforms.worldToWindowCoordinates(scene, C.Cartesian3.fromRadians(lon, lat, 0));
      return p ? [p.x, p.y] : null;
    }),
  };
}

async function checkFraming(b, name, dir) {
  const regions = topRegions(dir);
  const west = Math.min(...regions.map((r) => r[0])), east = Math.max(...regions.map((r) => r[2]));
  const south = Math.min(...regions.map((r) => r[1])), north = Math.max(...regions.map((r) => r[3]));
  const corners = [[west, south], [east, south], [east, north], [west, north]];
  const view = await b.page.evaluate(cameraView, corners);
  if (east - west > 1.9 * Math.PI) {
    check(view.height > 6.4e6 && view.fromCentre < 1,
      `${name}: the globe is seen from space (${(view.height / 1000).toFixed(0)} km up), looking at the Earth's centre (${view.fromCentre.toFixed(2)} deg off)`);
    return;
  }
  check(view.fromNadir < 1, `${name}: the camera looks straight down (${view.fromNadir.toFixed(2)} deg off)`);
  const [w, h] = view.canvas;
  const inside = view.onScreen.every((p) => p && p[0] >= -2 && p[0] <= w + 2 && p[1] >= -2 && p[1] <= h + 2);
  check(inside, `${name}: every corner of the content is in the frame ${JSON.stringify(view.onScreen.map((p) => p && p.map(Math.round)))}`);
}

async function opensInCesium(name, dir, minCover) {
  const view = await startView(args.maquette, dir, args.page);
  // small: SwiftShader draws Cesium's frames at a few per second, and it processes tiles per frame
  const b = await launchBrowser(args['node-modules'], { width: 640, height: 400 });
  try {
    await b.page.goto(view.url, { waitUntil: 'load' });
    await waitLoaded(b, name, out, () => ({ error: document.documentElement.dataset.error }), 120000);
    const error = await b.page.evaluate(() => document.documentElement.dataset.error);
    check(!error, `${name}: Cesium loaded the tileset and every tile in view ${error || ''}`);
    await checkFraming(b, name, dir);
    // without Cesium's credits (its logo), which are not terrain
    await b.page.addStyleTag({ content: '.cesium-viewer-bottom { display: none; }' });
    const png = await shoot(b, out, `cesium-${name}.png`, PNG);
    const { cover, sd, mask } = terrainPixels(png, [0x1d, 0x22, 0x29]);
    check(cover > minCover, `${name}: terrain covers ${(100 * cover).toFixed(2)} % of the frame (> ${100 * minCover} %)`);
    const centre = centreCover(png, mask);
    check(centre > 0.5, `${name}: the frame is centred on the terrain (${(100 * centre).toFixed(1)} % of its middle ninth, > 50 %)`);
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
    const [name, dir, minCover] = entry.split('=');
    await opensInCesium(name, resolve(dir), Number(minCover));
  }
  exitCode = checks.failures.length ? 1 : 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
}
log(exitCode ? `CesiumJS test FAILED: ${checks.failures.join('; ')}` : `CesiumJS test passed; screenshots in ${out}`);
process.exit(exitCode);
