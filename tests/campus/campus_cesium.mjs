// The campus example (examples/campus-soho.json) in CesiumJS: runs the example with `maquette
// run` (its sources at their absolute paths: ../../shared is SHARED, other paths the examples'),
// exports the same terrain again without content, and opens both tilesets with the page of
// tests/viewer/cesium (offline, no ion) in headless chromium, seen from one oblique camera over
// Soho, and from a second camera about 2 km away, where CesiumJS draws the coarser levels
// (content overviews: simplified buildings, thinned and widened trees). Checks: every tile
// loads, no console error or failed request, nothing asked of another host; near: the buildings
// are drawn: at the roof centre of at least 90 % of the footprints (the shared file's, less
// those in the vegetation strokes) the frame differs from the terrain alone; trees are drawn:
// over at least 5 % of each vegetation stroke the frame differs from the terrain alone and is
// foliage (green above red and blue; 49-62 % measured, 9-16 % when the coarser levels kept 1 tree
// in 4 per level whatever its size). Far: no roof is seen through (of the pixels inside the
// roofs' outlines, those showing the terrain alone are under 1 %: 0 measured; collapsed blocks
// left holes before), and each stroke still shows trees over at least 5 % of it (51-70 %
// measured; none were left at level 11 before). Screenshots: OUT/campus.png,
// OUT/campus-terrain.png, OUT/campus-far.png and OUT/campus-far-terrain.png.
//
// node campus_cesium.mjs --maquette BIN --page DIR --node-modules DIR --example JSON
//   --shared DIR --out DIR
// Exit codes: 0 pass, 1 fail, 77 skipped (no chromium, no ../shared data).
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { Checks, launchBrowser, log, parseArgs, requireFrom, SKIP, startView, waitLoaded } from '../viewer/harness.mjs';

const args = parseArgs();
const out = resolve(args.out);
const shared = resolve(args.shared);
const examples = dirname(resolve(args.example));
const footprintsFile = join(shared, 'data/buildings/london_soho_buildings_wgs84.geojson');
if (!existsSync(footprintsFile) || !existsSync(join(shared, 'data/global/world.tif'))) {
  console.log(`SKIPPED: no ${shared}/data (buildings, global)`);
  process.exit(SKIP);
}
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const { PNG } = requireFrom(args['node-modules'])('pngjs');
const checks = new Checks();
const check = checks.check.bind(checks);

// The oblique camera: 330 m above the ground south of Golden Square, looking north-north-east
// 35 degrees down, near enough for Cesium to draw the finest tiles, where the trees are.
const CAMERA = { lon: -0.1372, lat: 51.5080, height: 400, heading: 20, pitch: -35 };
// The far camera: 900 m up, 1.9 km south of Golden Square and 2.3 km of Soho Square, looking
// north 30 degrees down: CesiumJS draws levels 10 and 11 there (geometric errors 35 and 18 m).
const FAR_CAMERA = { lon: -0.1374, lat: 51.4970, height: 900, heading: 0, pitch: -30 };
const GROUND = 71;  // the ground above the ellipsoid: 25 m above EGM96, whose geoid is ~46 m up here

function maquette(...argv) {
  const r = spawnSync(args.maquette, ['-q', ...argv], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`maquette ${argv.join(' ')} failed (${r.status}): ${r.stderr}`);
}

// The example run into OUT: its pipeline with absolute sources, the store and tilesets beside it.
function runExample() {
  const pipeline = JSON.parse(readFileSync(args.example, 'utf8'));
  for (const step of pipeline.steps) {
    if (step.op !== 'ingest') continue;
    step.params.sources = step.params.sources.map((s) => (s.startsWith('../../shared/')
      ? join(shared, s.slice('../../shared/'.length)) : join(examples, s)));
  }
  const file = join(out, 'pipeline.json');
  writeFileSync(file, JSON.stringify(pipeline, null, 1));
  maquette('run', file);
  const exported = pipeline.steps.find((s) => s.op === 'export' && s.params.format === 'tiles3d');
  const terrain = join(out, 'terrain');
  maquette('export', 'tiles3d', join(out, pipeline.store), terrain, '--dem', exported.params.dem,
    '--texture', exported.params.texture, '--no-stretch');
  return { full: join(out, exported.params.out), terrain };
}

// A polygon's vertex mean (lon, lat), enough for the blocks' and squares' convex-ish shapes.
function centre(ring) {
  const n = ring.length - 1;
  return ring.slice(0, n).reduce(([x, y], p) => [x + p[0] / n, y + p[1] / n], [0, 0]);
}

function insideRing([x, y], ring) {
  let inside = false;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const [xi, yi] = ring[i], [xj, yj] = ring[j];
    if ((yi > y) !== (yj > y) && x < xj + (y - yj) / (yi - yj) * (xi - xj)) inside = !inside;
  }
  return inside;
}

// The page: `camera` set, then every tile in view loaded for a few frames.
async function view(b, camera) {
  await b.page.evaluate(async (c) => {
    const C = window.Cesium;
    const { camera, scene } = window.__cesium;
    camera.setView({
      destination: C.Cartesian3.fromDegrees(c.lon, c.lat, c.height),
      orientation: { heading: C.Math.toRadians(c.heading), pitch: C.Math.toRadians(c.pitch), roll: 0 },
    });
    const tileset = scene.primitives.get(0);
    await new Promise((done, fail) => {
      let stable = 0;
      const timer = setTimeout(() => fail(new Error('the tiles in view never loaded')), 180000);
      const remove = scene.postRender.addEventListener(() => {
        stable = tileset.tilesLoaded ? stable + 1 : 0;
        if (stable === 8) { remove(); clearTimeout(timer); done(); }
      });
    });
  }, camera);
}

// Window positions (pixels) of lon/lat points at `height` above the ellipsoid.
function projectPoints(b, points, height) {
  return b.page.evaluate(([pts, h]) => pts.map(([lon, lat]) => {
    const C = window.Cesium;
    const p = C.SceneTransforms.worldToWindowCoordinates(window.__cesium.scene, C.Cartesian3.fromDegrees(lon, lat, h));
    return p ? [p.x, p.y] : null;
  }), [points, height]);
}

// Opens the tileset in DIR in Cesium at `viewport`, seen from `camera`; the screenshot's PNG, and
// what `project(browser)` finds on the page (window positions).
async function render(name, dir, viewport, camera, project, file) {
  const server = await startView(args.maquette, dir, args.page);
  const b = await launchBrowser(args['node-modules'], viewport);
  try {
    await b.page.goto(server.url, { waitUntil: 'load' });
    await waitLoaded(b, name, out, () => ({ error: document.documentElement.dataset.error }), 180000);
    await view(b, camera);
    const error = await b.page.evaluate(() => document.documentElement.dataset.error);
    check(!error, `${name}: Cesium loaded the tileset and every tile in view ${error || ''}`);
    await b.page.addStyleTag({ content: '.cesium-viewer-bottom { display: none; }' });
    const png = PNG.sync.read(await b.page.screenshot({ path: file }));
    const foreign = b.requests.filter((r) => !r.startsWith(server.url) && !/^(data|blob):/.test(r));
    check(foreign.length === 0, `${name}: every request goes to maquette view ${foreign.slice(0, 3).join(' ')}`);
    check(b.badRequests.length === 0, `${name}: every request succeeded ${b.badRequests.slice(0, 3).join(' ')}`);
    const fatal = b.consoleErrors.filter((e) => !/favicon/.test(e));
    check(fatal.length === 0, `${name}: no errors in the browser console ${fatal.slice(0, 3).join(' | ')}`);
    return { png, screen: await project(b) };
  } finally {
    await b.close();
    check(await server.stop(), `${name}: maquette view stops cleanly on SIGINT`);
  }
}

// The largest channel difference between two screenshots, averaged over the 5 x 5 pixels at p.
function difference(a, b, [x, y]) {
  let sum = 0, n = 0;
  for (let j = Math.round(y) - 2; j <= Math.round(y) + 2; j++) {
    for (let i = Math.round(x) - 2; i <= Math.round(x) + 2; i++, n++) {
      const k = 4 * (j * a.width + i);
      sum += Math.max(...[0, 1, 2].map((c) => Math.abs(a.data[k + c] - b.data[k + c])));
    }
  }
  return sum / n;
}

// The largest channel difference between two screenshots at pixel (x, y).
function pixelDifference(a, b, x, y) {
  const k = 4 * (y * a.width + x);
  return Math.max(...[0, 1, 2].map((c) => Math.abs(a.data[k + c] - b.data[k + c])));
}

// Calls visit(x, y) for the pixels inside the window polygon `ring` (window positions) whose
// neighbours `margin` pixels away on either side are inside too (edges blend with what is
// beside them).
function insidePixels(png, ring, margin, visit) {
  const xs = ring.map((p) => p[0]), ys = ring.map((p) => p[1]);
  const inside = (x, y) => insideRing([x, y], ring);
  for (let y = Math.max(2, Math.floor(Math.min(...ys))); y <= Math.min(png.height - 3, Math.max(...ys)); y++) {
    for (let x = Math.max(2, Math.floor(Math.min(...xs))); x <= Math.min(png.width - 3, Math.max(...xs)); x++) {
      if (inside(x, y) && inside(x - margin, y) && inside(x + margin, y) && inside(x, y - margin)
        && inside(x, y + margin)) visit(x, y);
    }
  }
}

const onScreen = (png) => (p) => p && p[0] >= 2 && p[1] >= 2 && p[0] < png.width - 2 && p[1] < png.height - 2;
const isFoliage = (r, g, bl) => g > r + 8 && g > bl + 8;

// Of the pixels inside the window polygon `ring` (window positions), the share where the frame
// with content differs from the terrain alone and shows foliage: the trees there (the buildings
// are white, the terrain's olive is the same in both frames).
function treeCover(full, bare, ring) {
  let inside = 0, trees = 0;
  insidePixels(full, ring, 0, (x, y) => {
    inside++;
    const k = 4 * (y * full.width + x);
    trees += difference(full, bare, [x, y]) > 12 && isFoliage(full.data[k], full.data[k + 1], full.data[k + 2]);
  });
  return inside ? trees / inside : 0;
}

// Checks each stroke's outline is in the frame and trees cover more than 5 % of it.
function checkTrees(what, shot, bare, strokes) {
  shot.screen.outlines.forEach((ring, i) => {
    const name = `${what}: ${strokes[i].properties.name}`;
    if (!check(ring.every(onScreen(shot.png)), `${name} in the frame`)) return;
    const cover = treeCover(shot.png, bare.png, ring);
    check(cover > 0.05, `${name}: trees cover ${(100 * cover).toFixed(1)} % of it (> 5 %)`);
  });
}

let exitCode = 1;
try {
  const tilesets = runExample();
  const strokes = JSON.parse(readFileSync(join(examples, 'campus-soho/strokes.geojson'), 'utf8')).features
    .filter((f) => f.properties.tool === 'vegetation');
  // The blocks' outer rings (the footprints have no courtyards), less those in the strokes.
  const blocks = JSON.parse(readFileSync(footprintsFile, 'utf8')).features
    .map((f) => f.geometry.coordinates[0])
    .filter((ring) => !strokes.some((s) => insideRing(centre(ring), s.geometry.coordinates[0])));
  const roofs = blocks.map(centre);
  log(`${roofs.length} footprints outside the vegetation strokes`);
  const viewport = { width: 640, height: 400 };
  // The roof centres, and each stroke's outer ring on the ground.
  const outlines = strokes.map((f) => f.geometry.coordinates[0]);
  const project = async (b) => ({
    roofs: await projectPoints(b, roofs, GROUND + 10),
    outlines: await Promise.all(outlines.map((ring) => projectPoints(b, ring, GROUND))),
  });
  const full = await render('campus', tilesets.full, viewport, CAMERA, project, join(out, 'campus.png'));
  const bare = await render('campus-terrain', tilesets.terrain, viewport, CAMERA, project, join(out, 'campus-terrain.png'));
  const seen = full.screen.roofs.filter(onScreen(full.png));
  const drawn = seen.filter((p) => difference(full.png, bare.png, p) > 12);
  check(seen.length >= 40, `${seen.length} of ${roofs.length} roof centres in the frame (>= 40)`);
  check(drawn.length >= 0.9 * seen.length, `buildings drawn at ${drawn.length} of ${seen.length} roof centres (>= 90 %)`);
  checkTrees('near', full, bare, strokes);

  // From afar: the roofs' outlines at their height (every block is 10 m tall).
  const farViewport = { width: 960, height: 600 };
  const outlinesAt = (b) => Promise.all(blocks.map((ring) => projectPoints(b, ring, GROUND + 10)));
  const farProject = async (b) => ({ ...await project(b), roofs: await outlinesAt(b) });
  const far = await render('campus-far', tilesets.full, farViewport, FAR_CAMERA, farProject, join(out, 'campus-far.png'));
  const farBare = await render('campus-far-terrain', tilesets.terrain, farViewport, FAR_CAMERA, farProject, join(out, 'campus-far-terrain.png'));
  let roofPixels = 0, seeThrough = 0;
  for (const ring of far.screen.roofs) {
    if (!ring.every(onScreen(far.png))) continue;
    insidePixels(far.png, ring, 1, (x, y) => {
      roofPixels++;
      seeThrough += pixelDifference(far.png, farBare.png, x, y) <= 12;
    });
  }
  check(roofPixels > 5000, `far: ${roofPixels} pixels inside the roofs' outlines (> 5,000)`);
  check(seeThrough < 0.01 * roofPixels,
    `far: ${seeThrough} of them (${(100 * seeThrough / roofPixels).toFixed(2)} %) show the terrain alone (< 1 %)`);
  checkTrees('far', far, farBare, strokes);
  exitCode = checks.failures.length ? 1 : 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
}
log(exitCode ? `campus test FAILED: ${checks.failures.join('; ')}` : `campus test passed; screenshots in ${out}`);
process.exit(exitCode);
