// The README's picture of Zion draped three ways (docs/synthesis-zion-drapes.jpg): the same oblique
// view in the project's viewer (`maquette view`, three.js, headless chromium) of the SRTM terrain
// draped with, left to right, the calibrated Landsat scene and the procedural texture of
// examples/texture-zion.json, and Bruegel's The Harvesters transferred onto the land cover by
// examples/synthesis-zion.json. Run both examples first; the Landsat drape is exported here from
// the texture example's store (its `rgb` layer, on the same DEM).
//
//   node tests/synthesis_zion/drape_picture.mjs --maquette build/bin/maquette \
//     --viewer build/share/maquette/viewer --node-modules build/tests/viewer/npm/node_modules \
//     --examples examples --out docs/synthesis-zion-drapes.jpg
//
// Each panel's frame is the viewer's canvas at a fixed camera, sky-blue behind the terrain; the
// panels are joined with pngjs and written as a JPEG by GDAL. Exits 1 on a tile, console or
// request error.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { launchBrowser, log, parseArgs, requireFrom, startView, waitLoaded } from '../viewer/harness.mjs';

const args = parseArgs();
const examples = resolve(args.examples);
// From the south, 11 km above the ellipsoid over the region's southern edge south of Rockville,
// looking north 25 degrees down across Zion's canyons (the foreground and centre) to the forest of
// the Kolob Terrace and the region's northern edge (the skyline), 20 km to the target.
const EYE = [-113.02, 37.13, 11000];
const TARGET = [-113.02, 37.31, 1800];
const SKY = 0xbcd4e6;
const VIEWPORT = { width: 800, height: 560 };

function run(program, ...argv) {
  const r = spawnSync(program, argv, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${program} ${argv.join(' ')} failed (${r.status}): ${r.stderr}`);
}

// One panel: the tileset in DIR seen from EYE, saved as FILE.
async function panel(name, dir, file) {
  const view = await startView(args.maquette, dir, resolve(args.viewer));
  const b = await launchBrowser(args['node-modules'], VIEWPORT);
  try {
    // Tiles refined to 4 pixels of screen-space error (the viewer opens at 6).
    await b.page.goto(`${view.url}?errorTarget=4`, { waitUntil: 'load' });
    await waitLoaded(b, name, tmpdir(), () => ({ state: window.__maquette }), 180000);
    await b.page.evaluate(([eye, target, sky]) => {
      const { THREE, tiles, camera, controls, renderer } = window.__maquetteViewer;
      const world = ([lon, lat, h]) => tiles.ellipsoid.getCartographicToPosition(THREE.MathUtils.degToRad(lat),
        THREE.MathUtils.degToRad(lon), h, new THREE.Vector3()).applyMatrix4(tiles.group.matrixWorld);
      renderer.setClearColor(sky);
      controls.target.copy(world(target));
      camera.position.copy(world(eye));
      controls.update();
      document.documentElement.dataset.tilesLoaded = 'false';
    }, [EYE, TARGET, SKY]);
    await new Promise((r) => setTimeout(r, 1000));
    await waitLoaded(b, `${name} view`, tmpdir(), () => ({ state: window.__maquette }), 180000);
    log(`${name}: loaded`);
    const errors = await b.page.evaluate(() => window.__maquette.errors);
    await b.page.addStyleTag({ content: '#panel { display: none !important; }' });
    await b.page.screenshot({ path: file, timeout: 180000 });
    const fatal = b.consoleErrors.filter((e) => !/favicon/.test(e));
    if (errors.length || fatal.length || b.badRequests.length)
      throw new Error(`${name}: ${errors.join('; ')} ${fatal.join(' | ')} ${b.badRequests.join(' ')}`);
    log(`${name}: ${file}`);
  } finally {
    await b.close();
    await view.stop();
  }
}

const work = mkdtempSync(join(tmpdir(), 'maquette-drapes-'));
let exitCode = 1;
try {
  const landsat = join(work, 'landsat');
  run(args.maquette, '-q', 'export', 'tiles3d', join(examples, 'zion.mqt'), landsat, '--dem', 'dem',
    '--texture', 'rgb', '--no-stretch');
  const panels = [];
  for (const [name, dir] of [['landsat', landsat], ['procedural', join(examples, 'zion-output/tiles3d')],
    ['bruegel', join(examples, 'synthesis-zion-output/tiles3d')]]) {
    panels.push(join(work, `${name}.png`));
    await panel(name, dir, panels.at(-1));
  }
  // Side by side with 12 white pixels between the panels, then a JPEG (quality 90) by GDAL.
  const { PNG } = requireFrom(args['node-modules'])('pngjs');
  const images = panels.map((p) => PNG.sync.read(readFileSync(p)));
  const gap = 12;
  const joined = new PNG({ width: images.reduce((w, im) => w + im.width + gap, -gap), height: VIEWPORT.height });
  joined.data.fill(255);
  images.reduce((x, im) => { PNG.bitblt(im, joined, 0, 0, im.width, im.height, x, 0); return x + im.width + gap; }, 0);
  writeFileSync(join(work, 'joined.png'), PNG.sync.write(joined));
  run('gdal_translate', '-q', '-of', 'JPEG', '-co', 'QUALITY=90', '--config', 'GDAL_PAM_ENABLED', 'NO',
    join(work, 'joined.png'), resolve(args.out));
  log(`saved ${args.out}`);
  exitCode = 0;
} catch (e) {
  log(`FAIL ${e.stack || e}`);
} finally {
  rmSync(work, { recursive: true, force: true });
}
process.exit(exitCode);
