// The viewer frames any tileset from above its content, from a single cell to the whole globe,
// and exaggerates heights along the ellipsoid normal. For each export of make_globe_exports.sh
// (one cell, a continent over three faces of the grid, the whole globe) it opens `maquette view`
// in chromium, waits for the tiles in view, screenshots the frame and checks, against geodesy
// computed here (WGS84 normals, not the page's):
// - one cell, a continent: the point under the centre of the frame lies in the content, the view
//   looks down at it (the angle between the view direction and the downward normal there), and
//   terrain covers a good part of the frame, with no dark specks along the seams of the tiles
//   (in double-sided exports the back face of a skirt was drawn dark at every seam);
// - the globe: the camera is out in space, looking at the Earth's centre, the whole disc in view.
// Then, on the continent, vertical exaggeration (?exaggeration=3, then back to 1 with the `-`
// key): the readout under a grid of screen points gives the point drawn (ECEF) and its lon/lat;
// its height above the ellipsoid must be k times the DEM's (make_global_dem.mjs) there, as a
// scale along the normal gives and a uniform scale of the scene does not.
//
// node framing.mjs --maquette BIN --viewer DIR --node-modules DIR --exports DIR --out DIR
// Exit codes: 0 pass, 1 fail, 77 skipped (no chromium).
import { mkdirSync, rmSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { demHeight } from './global_dem.mjs';
import {
  Checks, launchBrowser, log, parseArgs, requireFrom, shoot, startView, terrainPixels, waitLoaded,
} from './harness.mjs';

const args = parseArgs();
const out = resolve(args.out);
const exportsDir = resolve(args.exports);
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const { PNG } = requireFrom(args['node-modules'])('pngjs');
const checks = new Checks();
const check = checks.check.bind(checks);

// WGS84.
const A = 6378137.0;
const F = 1 / 298.257223563;
const E2 = F * (2 - F);
const DEG = Math.PI / 180;
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a) => Math.hypot(...a);
const angleDeg = (a, b) => Math.acos(Math.min(Math.max(dot(a, b) / (norm(a) * norm(b)), -1), 1)) / DEG;
const up = (lonDeg, latDeg) => [Math.cos(latDeg * DEG) * Math.cos(lonDeg * DEG),
  Math.cos(latDeg * DEG) * Math.sin(lonDeg * DEG), Math.sin(latDeg * DEG)];
// Geodetic lon, lat (degrees) and height of an ECEF point (Bowring's iteration, to < 1 mm).
function geodetic([x, y, z]) {
  const p = Math.hypot(x, y);
  let lat = Math.atan2(z, p * (1 - E2));
  let h = 0;
  for (let i = 0; i < 6; i++) {
    const n = A / Math.sqrt(1 - E2 * Math.sin(lat) ** 2);
    h = p / Math.cos(lat) - n;
    lat = Math.atan2(z, p * (1 - E2 * n / (n + h)));
  }
  return { lon: Math.atan2(y, x) / DEG, lat: lat / DEG, h };
}

// Great-circle distance (km, on a sphere of radius A) between two lon/lat points in degrees.
function distanceKm(lon1, lat1, lon2, lat2) {
  return angleDeg(up(lon1, lat1), up(lon2, lat2)) * DEG * A / 1000;
}

// What make_globe_exports.sh ingested: whether a lon/lat lies in the content.
const CONTENT = {
  // the level-6 cell (144 km across) holding this point
  cell: { text: 'within 150 km of (10.5, 45.3)', holds: (lon, lat) => distanceKm(lon, lat, 10.5, 45.3) < 150 },
  continent: { text: 'in -125..-66, 24..50', holds: (lon, lat) => lon > -125 && lon < -66 && lat > 24 && lat < 50 },
};

// Pixels of the terrain (away from the panel and the terrain's outline) darker by more than 25
// than the median of their 5 x 5 neighbourhood, per 10,000: the dotted seams of a smooth,
// untextured terrain.
function darkSpecks(png, mask, panel) {
  const w = png.width, h = png.height;
  const lum = (i) => 0.3 * png.data[4 * i] + 0.59 * png.data[4 * i + 1] + 0.11 * png.data[4 * i + 2];
  let n = 0, specks = 0;
  const around = new Float64Array(25);
  for (let y = 2; y < h - 2; y++) {
    for (let x = 2; x < w - 2; x++) {
      if (x <= panel.right + 2 && y <= panel.bottom + 2) continue;
      let k = 0;
      for (let dy = -2; dy <= 2; dy++) {
        for (let dx = -2; dx <= 2; dx++) {
          const j = (y + dy) * w + x + dx;
          if (mask[j]) around[k++] = lum(j);
        }
      }
      if (k < 25) continue;
      n++;
      around.sort();
      if (lum(y * w + x) < around[12] - 25) specks++;
    }
  }
  return n ? 1e4 * specks / n : Infinity;
}

// The camera and the point under the centre of the frame, in the tileset's frame (ECEF).
async function cameraState(page) {
  return page.evaluate(() => {
    const { THREE, tiles, camera } = window.__maquetteViewer;
    const toEcef = tiles.group.matrixWorld.clone().invert();
    const dir = camera.getWorldDirection(new THREE.Vector3()).transformDirection(toEcef);
    return { position: camera.position.clone().applyMatrix4(toEcef).toArray(), dir: dir.toArray(),
      view: window.__maquette.view };
  });
}

// The readout under screen point (x, y): lon/lat/height as shown and the point drawn (ECEF).
async function readout(page, x, y) {
  await page.mouse.move(x, y);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return page.evaluate(() => {
    const s = window.__maquette;
    return { lon: s.lon, lat: s.lat, height: s.height, ecef: s.ecef, cell: s.cell };
  });
}

async function checkSeams(name, page, shot, mask) {
  const panel = await page.evaluate(() => document.getElementById('panel').getBoundingClientRect().toJSON());
  const specks = darkSpecks(shot, mask, panel);
  check(specks < 1, `${name}: ${specks.toFixed(2)} dark specks per 10,000 terrain pixels (< 1): no dotted seams`);
}

const diagnose = () => ({ state: window.__maquette, stats: window.__maquetteViewer?.tiles.stats });
const bg = [0x1d, 0x22, 0x29];

async function open(name, query = '') {
  const view = await startView(args.maquette, join(exportsDir, name), args.viewer);
  const b = await launchBrowser(args['node-modules']);
  await b.page.goto(`${view.url}${query}`, { waitUntil: 'load' });
  await waitLoaded(b, name, out, diagnose);
  const errors = await b.page.evaluate(() => window.__maquette.errors);
  check(errors.length === 0, `${name}: tiles loaded without errors ${errors.join('; ')}`);
  return { b, view };
}

async function close({ b, view }) {
  const fatal = b.consoleErrors.filter((e) => !/favicon/.test(e));
  check(fatal.length === 0, `no errors in the browser console ${fatal.slice(0, 3).join(' | ')}`);
  await b.close();
  check(await view.stop(), 'maquette view stops cleanly on SIGINT');
}

// One cell and a continent: seen from above, the content under the centre of the frame.
async function framesFromAbove(name, maxAngle, minCover) {
  const s = await open(name);
  try {
    const shot = await shoot(s.b, out, `framing-${name}.png`, PNG);
    const { cover, mask } = terrainPixels(shot, bg);
    await checkSeams(name, s.b.page, shot, mask);
    const cam = await cameraState(s.b.page);
    const centre = await readout(s.b.page, shot.width / 2, shot.height / 2);
    log(`${name}: camera ${JSON.stringify(cam)}; centre of the frame ${JSON.stringify(centre)}`);
    check(cover > minCover, `${name}: terrain covers ${(100 * cover).toFixed(1)} % of the frame (> ${100 * minCover} %)`);
    const inside = Number.isFinite(centre.lon) && CONTENT[name].holds(centre.lon, centre.lat);
    check(inside, `${name}: the centre of the frame shows the content (${centre.lon?.toFixed(3)}, ${centre.lat?.toFixed(3)} ${CONTENT[name].text})`);
    if (inside) {
      const down = up(centre.lon, centre.lat).map((v) => -v);
      const a = angleDeg(cam.dir, down);
      check(a < maxAngle, `${name}: the view looks down at the content: ${a.toFixed(1)} degrees from the vertical (< ${maxAngle})`);
    }
    return s;
  } catch (e) {
    await close(s);
    throw e;
  }
}

async function framesTheGlobe() {
  const s = await open('globe');
  try {
    const shot = await shoot(s.b, out, 'framing-globe.png', PNG);
    const { cover, mask } = terrainPixels(shot, bg);
    await checkSeams('globe', s.b.page, shot, mask);
    const cam = await cameraState(s.b.page);
    log(`globe: camera ${JSON.stringify(cam)}`);
    const altitude = geodetic(cam.position).h;
    check(altitude > 0.5 * A, `globe: the camera is in space (${(altitude / 1000).toFixed(0)} km up)`);
    const a = angleDeg(cam.dir, cam.position.map((v) => -v));
    check(a < 3, `globe: it looks at the Earth's centre (${a.toFixed(2)} degrees off)`);
    check(cover > 0.25, `globe: terrain covers ${(100 * cover).toFixed(1)} % of the frame (> 25 %)`);
    // the whole disc in view: the frame's border is background
    const { width: w, height: h } = shot;
    let border = 0;
    for (let x = 0; x < w; x++) border += mask[x] + mask[(h - 1) * w + x];
    for (let y = 0; y < h; y++) border += mask[y * w + w - 1];
    check(border === 0, `globe: the whole disc is in the frame (${border} terrain pixels on its border)`);
  } finally {
    await close(s);
  }
}

// Heights drawn at screen points across the frame: k times the DEM's at their lon/lat.
async function checkExaggeration(page, k, what) {
  const st = await page.evaluate(() => window.__maquette.exaggeration);
  check(st === k, `${what}: the page's exaggeration is ${st} (${k})`);
  const vp = page.viewportSize();
  let n = 0, worst = 0, worstTrue = 0;
  for (let i = 1; i < 6; i++) {
    for (let j = 1; j < 4; j++) {
      const r = await readout(page, vp.width * i / 6, vp.height * j / 4);
      if (!r.ecef) continue;
      n++;
      const g = geodetic(r.ecef);
      const dem = demHeight(g.lon, g.lat);
      worst = Math.max(worst, Math.abs(g.h - k * dem));
      worstTrue = Math.max(worstTrue, Math.abs(r.height - dem));
    }
  }
  // the mesh of the coarser tiles shown from afar differs from the DEM by up to some 300 m
  const tol = 250;
  check(n >= 10, `${what}: ${n} of 15 screen points show terrain`);
  check(worst < k * tol, `${what}: heights drawn are ${k} x the DEM's within ${worst.toFixed(0)} m (< ${k * tol})`);
  check(worstTrue < tol, `${what}: the readout's heights are the DEM's within ${worstTrue.toFixed(0)} m (< ${tol})`);
}

let exitCode = 1;
try {
  await close(await framesFromAbove('cell', 50, 0.2));
  await close(await framesFromAbove('continent', 15, 0.2));
  await framesTheGlobe();

  const s = await open('continent', '?exaggeration=3');
  try {
    await shoot(s.b, out, 'exaggeration-3.png', PNG);
    await checkExaggeration(s.b.page, 3, 'exaggeration 3 (query)');
    for (let i = 0; i < 4; i++) await s.b.page.keyboard.press('-');
    await waitLoaded(s.b, 'exaggeration 1', out, diagnose);
    await checkExaggeration(s.b.page, 1, 'exaggeration 1 (key -)');
  } finally {
    await close(s);
  }
  exitCode = checks.failures.length ? 1 : 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
}
log(exitCode ? `viewer framing FAILED: ${checks.failures.join('; ')}` : `viewer framing passed; screenshots in ${out}`);
process.exit(exitCode);
