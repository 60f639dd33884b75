// Renders a GLB of `maquette export glb --dem dem --content bridge` (the valley of
// tests/bridge, its deck across it) with three.js's GLTFLoader in Debian's chromium, and saves
// the screenshot: the picture of the structures README's bridge section.
//
//   node tests/bridge/bridge_picture.mjs --glb valley.glb \
//     --node-modules build/tests/viewer/npm/node_modules --three build/viewer-npm/node_modules/three \
//     --out bridge.png
//
// The camera looks at the centre of the deck's bounding box (the node whose name starts with
// "bridge") from the south, a little above it. Fails (exit 1) unless the terrain and the deck are
// drawn without console errors.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { launchBrowser, log, parseArgs } from '../viewer/harness.mjs';

const args = parseArgs();
const page = `<!doctype html><html><body style="margin:0">
<script type="importmap">{"imports": {"three": "/three/build/three.module.js",
  "three/addons/": "/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(innerWidth, innerHeight);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xbcd4e6);
scene.add(new THREE.HemisphereLight(0xdfefff, 0x4a5a30, 1.2));
const sun = new THREE.DirectionalLight(0xfff4e0, 2.4);
sun.position.set(-1, 2, 1.5);
scene.add(sun);
const loader = new GLTFLoader();
const draco = new DRACOLoader();
draco.setDecoderPath('/three/examples/jsm/libs/draco/gltf/');
loader.setDRACOLoader(draco);
loader.load('/scene.glb', (gltf) => {
  let deck = null, meshes = 0;
  gltf.scene.traverse((o) => {
    if (o.name.startsWith('bridge')) deck = deck || o;
    if (o.isMesh) {
      meshes++;
      const inDeck = (() => { for (let p = o; p; p = p.parent) if (p.name.startsWith('bridge')) return true; return false; })();
      o.material = new THREE.MeshStandardMaterial({ color: inDeck ? 0xc0392b : 0x9c9a86, roughness: 1,
        flatShading: true, side: THREE.DoubleSide });
    }
  });
  scene.add(gltf.scene);
  scene.updateMatrixWorld(true);
  if (!deck) { document.documentElement.dataset.error = 'no bridge node'; return; }
  const box = new THREE.Box3().setFromObject(deck);
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3()).length();
  // glTF axes: x east, y up, z south.
  const camera = new THREE.PerspectiveCamera(40, innerWidth / innerHeight, 1, 20 * size);
  camera.position.set(centre.x - 0.15 * size, centre.y + 0.06 * size, centre.z + 0.8 * size);
  camera.lookAt(centre.x, centre.y - 0.05 * size, centre.z);
  renderer.render(scene, camera);
  document.documentElement.dataset.meshes = String(meshes);
  document.documentElement.dataset.loaded = 'true';
}, undefined, (e) => { document.documentElement.dataset.error = String(e); });
</script></body></html>`;

const b = await launchBrowser(args['node-modules'], { width: 960, height: 480 });
await b.page.route('http://bridge.test/**', (route) => {
  const path = new URL(route.request().url()).pathname;
  if (path === '/') return route.fulfill({ contentType: 'text/html', body: page });
  if (path === '/scene.glb') return route.fulfill({ contentType: 'model/gltf-binary', body: readFileSync(args.glb) });
  if (path.startsWith('/three/')) {
    const type = path.endsWith('.wasm') ? 'application/wasm' : 'text/javascript';
    return route.fulfill({ contentType: type, body: readFileSync(join(args.three, path.slice(7))) });
  }
  return route.fulfill({ status: 404 });
});
await b.page.goto('http://bridge.test/');
await b.page.waitForFunction(() => document.documentElement.dataset.loaded === 'true'
  || document.documentElement.dataset.error, null, { timeout: 60000 });
const error = await b.page.evaluate(() => document.documentElement.dataset.error);
const meshes = await b.page.evaluate(() => document.documentElement.dataset.meshes);
await b.page.screenshot({ path: args.out });
await b.close();
if (error || b.consoleErrors.length || !(Number(meshes) >= 2)) {
  log(`failed: ${error || ''} ${b.consoleErrors.join(' | ')} (${meshes} meshes)`);
  process.exit(1);
}
log(`${meshes} meshes drawn; saved ${args.out}`);
