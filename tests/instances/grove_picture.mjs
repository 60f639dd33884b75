// Renders the grove that tests/instances writes (build/tests/instances/grove/grove.glb: the three
// built-in prototypes drawn with EXT_mesh_gpu_instancing) with three.js's GLTFLoader in Debian's
// chromium, and saves the screenshot: the picture of docs/builtin-prototypes.png.
//
//   node tests/instances/grove_picture.mjs --glb build/tests/instances/grove/grove.glb \
//     --node-modules build/tests/viewer/npm/node_modules --three build/viewer-npm/node_modules/three \
//     --out grove.png
//
// (--node-modules: playwright-core, installed by the viewer tests' npm step; --three: three.js,
// installed by the viewer's; --camera X,Y,Z places the camera elsewhere than in front, glTF axes.)
// The page is served from memory through playwright's routing. It fails (exit 1) unless the six
// instanced meshes are drawn without console errors and the crowns rise above the horizon: at
// least 3 % of the sky above it, seen from the default camera, is foliage, green above red and
// blue (prototypes lying down or upside down, wrong axes, would leave the sky empty).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { launchBrowser, log, parseArgs, requireFrom } from '../viewer/harness.mjs';

const args = parseArgs();
const page = `<!doctype html><html><body style="margin:0">
<script type="importmap">{"imports": {"three": "/three/build/three.module.js",
  "three/addons/": "/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(innerWidth, innerHeight);
renderer.shadowMap.enabled = true;
renderer.shadowMap.type = THREE.PCFSoftShadowMap;
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xbcd4e6);
scene.add(new THREE.HemisphereLight(0xdfefff, 0x4a5a30, 1.6));
const sun = new THREE.DirectionalLight(0xfff4e0, 2.6);
sun.position.set(-30, 45, 25);
sun.castShadow = true;
sun.shadow.mapSize.set(2048, 2048);
Object.assign(sun.shadow.camera, { left: -30, right: 30, top: 30, bottom: -30, near: 1, far: 150 });
scene.add(sun);
const ground = new THREE.Mesh(new THREE.CircleGeometry(400, 64),
  new THREE.MeshStandardMaterial({ color: 0x71803f, roughness: 1 }));
ground.rotation.x = -Math.PI / 2;
ground.receiveShadow = true;
scene.add(ground);
const camera = new THREE.PerspectiveCamera(38, innerWidth / innerHeight, 0.5, 500);
camera.position.set(${args.camera || '0, 7, 34'});
camera.lookAt(0, 4.5, 0);
new GLTFLoader().load('/grove.glb', (gltf) => {
  gltf.scene.traverse((o) => { if (o.isMesh) { o.castShadow = true; o.receiveShadow = true; } });
  scene.add(gltf.scene);
  renderer.render(scene, camera);
  document.documentElement.dataset.instanced = String(gltf.scene.children.filter((o) => o.isInstancedMesh).length);
  document.documentElement.dataset.tilesLoaded = 'true';
}, undefined, (e) => { document.documentElement.dataset.error = String(e); });
</script></body></html>`;

const b = await launchBrowser(args['node-modules'], { width: 800, height: 450 });
await b.page.route('http://grove.test/**', (route) => {
  const path = new URL(route.request().url()).pathname;
  if (path === '/') return route.fulfill({ contentType: 'text/html', body: page });
  if (path === '/grove.glb') return route.fulfill({ contentType: 'model/gltf-binary', body: readFileSync(args.glb) });
  if (path.startsWith('/three/')) return route.fulfill({ contentType: 'text/javascript', body: readFileSync(join(args.three, path.slice(7))) });
  return route.fulfill({ status: 404 });
});
await b.page.goto('http://grove.test/');
await b.page.waitForFunction(() => document.documentElement.dataset.tilesLoaded === 'true'
  || document.documentElement.dataset.error, null, { timeout: 60000 });
const error = await b.page.evaluate(() => document.documentElement.dataset.error);
const instanced = await b.page.evaluate(() => document.documentElement.dataset.instanced);
if (error || b.consoleErrors.length) {
  log(`failed: ${error || ''} ${b.consoleErrors.join(' | ')}`);
  await b.close();
  process.exit(1);
}
const { PNG } = requireFrom(args['node-modules'])('pngjs');
const png = PNG.sync.read(await b.page.screenshot({ path: args.out }));
await b.close();
log(`${instanced} instanced meshes drawn; saved ${args.out}`);
// The horizon of the default camera (7 m up, looking 2.5 m down over 34 m) is at 40 % of the
// height; above it, the sky (0xbcd4e6) or the crowns.
const horizon = Math.floor(png.height * 0.4);
let foliage = 0;
for (let i = 0; i < png.width * horizon; i++) {
  const [r, g, bl] = [png.data[4 * i], png.data[4 * i + 1], png.data[4 * i + 2]];
  foliage += g > r && g > bl;
}
const share = foliage / (png.width * horizon);
log(`foliage above the horizon: ${(100 * share).toFixed(1)} % of the sky`);
if (instanced !== '6' || (!args.camera && share < 0.03)) process.exit(1);
