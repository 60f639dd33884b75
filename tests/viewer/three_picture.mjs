// A picture of one GLB drawn by three.js's GLTFLoader (Draco through its DRACOLoader) in Debian's
// chromium, the page served from memory through playwright's routing: what the README pictures
// of tests/instances (the grove) and tests/bridge (the deck across its valley) share.
//
// threePicture(args, { viewport, params, setup, frame }) opens the page at `viewport`; on it,
// `setup(THREE, scene, renderer, params)` adds the lights (and anything else) to a scene whose
// background is the sky (0xbcd4e6), and once ARGS.glb is loaded and added,
// `frame(THREE, gltf, scene, params)` returns the camera to render with (it may set
// document.documentElement.dataset values, or dataset.error). Both run in the page: they are
// passed as source text, so they may use only their arguments. ARGS (parseArgs): --glb,
// --node-modules (playwright-core, pngjs: the viewer tests' npm step), --three (three.js: the
// viewer's npm step), --out (the screenshot, PNG). Returns { png (pngjs), dataset } once drawn;
// throws naming the error when the page fails or logs a console error (node then exits 1).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { launchBrowser, requireFrom } from './harness.mjs';

function page(params, setup, frame) {
  return `<!doctype html><html><body style="margin:0">
<script type="importmap">{"imports": {"three": "/three/build/three.module.js",
  "three/addons/": "/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
const params = ${JSON.stringify(params)};
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(innerWidth, innerHeight);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xbcd4e6);
(${setup})(THREE, scene, renderer, params);
const loader = new GLTFLoader();
const draco = new DRACOLoader();
draco.setDecoderPath('/three/examples/jsm/libs/draco/gltf/');
loader.setDRACOLoader(draco);
loader.load('/scene.glb', (gltf) => {
  scene.add(gltf.scene);
  scene.updateMatrixWorld(true);
  const camera = (${frame})(THREE, gltf, scene, params);
  if (document.documentElement.dataset.error) return;
  renderer.render(scene, camera);
  document.documentElement.dataset.drawn = 'true';
}, undefined, (e) => { document.documentElement.dataset.error = String(e); });
</script></body></html>`;
}

export async function threePicture(args, { viewport, params = {}, setup, frame }) {
  const body = page(params, setup, frame);
  const b = await launchBrowser(args['node-modules'], viewport);
  await b.page.route('http://picture.test/**', (route) => {
    const path = new URL(route.request().url()).pathname;
    if (path === '/') return route.fulfill({ contentType: 'text/html', body });
    if (path === '/scene.glb') return route.fulfill({ contentType: 'model/gltf-binary', body: readFileSync(args.glb) });
    if (path.startsWith('/three/')) {
      const type = path.endsWith('.wasm') ? 'application/wasm' : 'text/javascript';
      return route.fulfill({ contentType: type, body: readFileSync(join(args.three, path.slice(7))) });
    }
    return route.fulfill({ status: 404 });
  });
  try {
    await b.page.goto('http://picture.test/');
    await b.page.waitForFunction(() => document.documentElement.dataset.drawn === 'true'
      || document.documentElement.dataset.error, null, { timeout: 60000 });
    const dataset = await b.page.evaluate(() => ({ ...document.documentElement.dataset }));
    if (dataset.error || b.consoleErrors.length)
      throw new Error(`the picture failed: ${dataset.error || ''} ${b.consoleErrors.join(' | ')}`);
    const { PNG } = requireFrom(args['node-modules'])('pngjs');
    const png = PNG.sync.read(await b.page.screenshot({ path: args.out }));
    return { png, dataset };
  } finally {
    await b.close();
  }
}
