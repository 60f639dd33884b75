// The picture of docs/campus-soho.png: the campus example's 3D Tiles (as campus_cesium.mjs or
// examples/campus-soho/run.sh writes them) in the project's viewer (`maquette view`, three.js),
// seen from an oblique camera south of Soho Square, in Debian's chromium.
//
//   node tests/campus/campus_picture.mjs --maquette build/bin/maquette \
//     --viewer build/share/maquette/viewer --node-modules build/tests/viewer/npm/node_modules \
//     --tileset-dir build/tests/campus/cesium-out/campus-soho-output/tiles3d --out campus.png
//
// Fails (exit 1) on a tile, console or request error.
import { dirname, resolve } from 'node:path';
import { launchBrowser, log, parseArgs, startView, waitLoaded } from '../viewer/harness.mjs';

const args = parseArgs();
// Where the camera stands (lon, lat, metres above the ellipsoid) and what it looks at: from the
// south, 400 m from Soho Square's canal and footbridge (right) and 340 m from the hotel (left),
// near enough to see a 12 m bridge.
const EYE = [-0.1357, 51.5124, 300];
const TARGET = [-0.1354, 51.5150, 71];

const view = await startView(args.maquette, resolve(args['tileset-dir']), args.viewer);
const b = await launchBrowser(args['node-modules'], { width: 1200, height: 675 });
let exitCode = 1;
try {
  await b.page.goto(`${view.url}?errorTarget=1`, { waitUntil: 'load' });
  await waitLoaded(b, 'campus', dirname(resolve(args.out)), () => ({ state: window.__maquette }), 180000);
  await b.page.evaluate(([eye, target]) => {
    const { THREE, tiles, camera, controls } = window.__maquetteViewer;
    const world = ([lon, lat, h]) => tiles.ellipsoid.getCartographicToPosition(THREE.MathUtils.degToRad(lat),
      THREE.MathUtils.degToRad(lon), h, new THREE.Vector3()).applyMatrix4(tiles.group.matrixWorld);
    controls.target.copy(world(target));
    camera.position.copy(world(eye));
    controls.update();
    document.documentElement.dataset.tilesLoaded = 'false';
  }, [EYE, TARGET]);
  await new Promise((r) => setTimeout(r, 1000));
  await waitLoaded(b, 'campus view', dirname(resolve(args.out)), () => ({ state: window.__maquette }), 180000);
  const errors = await b.page.evaluate(() => window.__maquette.errors);
  await b.page.addStyleTag({ content: '#panel { display: none !important; }' });
  await b.page.screenshot({ path: args.out });
  const fatal = b.consoleErrors.filter((e) => !/favicon/.test(e));
  if (errors.length || fatal.length || b.badRequests.length) {
    log(`failed: ${errors.join('; ')} ${fatal.join(' | ')} ${b.badRequests.join(' ')}`);
  } else {
    log(`saved ${args.out}`);
    exitCode = 0;
  }
} catch (e) {
  log(`FAIL ${e.stack || e}`);
} finally {
  await b.close();
  await view.stop();
}
process.exit(exitCode);
