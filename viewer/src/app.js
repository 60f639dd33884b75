// Maquette viewer: opens a 3D Tiles 1.1 tileset written by `maquette export tiles3d` with three.js
// and 3d-tiles-renderer, frames it, and offers orbit controls, a hillshade/texture toggle and a
// cell-id + lon/lat readout under the mouse. Everything (Draco decoder included) is served from
// this folder, so it works offline.
//
// Query parameters: ?tileset=URL (default ./tileset.json), &shading=hillshade|texture,
// &errorTarget=PIXELS (screen-space error, default 6).
//
// For tests and scripts the page publishes its state in `window.__maquette` and as attributes on
// <html>: data-tiles-loaded="true" once every tile in view has loaded and a few frames have been
// drawn with nothing pending; data-error="..." when the tileset cannot be loaded.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { TilesRenderer } from '3d-tiles-renderer';
import { GLTFExtensionsPlugin, ReorientationPlugin } from '3d-tiles-renderer/plugins';

const params = new URLSearchParams(window.location.search);
const tilesetUrl = new URL(params.get('tileset') || './tileset.json', window.location.href).href;
const STABLE_FRAMES = 8;  // frames with nothing pending before "loaded" is signalled

const state = {
  tilesLoaded: false,
  framed: false,
  shading: params.get('shading') === 'hillshade' ? 'hillshade' : 'texture',
  tileset: tilesetUrl,
  modelsLoaded: 0,
  extraContentsLoaded: 0,
  errors: [],
  cell: null,
  lon: null,
  lat: null,
  height: null,
};
window.__maquette = state;
const html = document.documentElement;
const statusEl = document.getElementById('status');
const cellEl = document.getElementById('cell');
const lonlatEl = document.getElementById('lonlat');
const toggleEl = document.getElementById('toggle-shading');

function setStatus(text) { statusEl.textContent = text; }
function reportError(message) {
  state.errors.push(message);
  html.dataset.error = message;
  setStatus(message);
  console.error(message);
}

// --- renderer, scene, camera ----------------------------------------------------------------
const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight, false);
renderer.setClearColor(0x1d2229);
renderer.outputColorSpace = THREE.SRGBColorSpace;

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, 1, 1e7);
camera.position.set(0, 1000, 1000);
const controls = new OrbitControls(camera, canvas);
controls.enableDamping = false;
controls.screenSpacePanning = false;
controls.maxPolarAngle = Math.PI * 0.495;

// Sun from the north-west at 45 degrees, the classic hillshade light. After reorientation
// (ReorientationPlugin) +Y is up, +X west and +Z north.
const sun = new THREE.DirectionalLight(0xffffff, 2.6);
sun.position.set(1, Math.SQRT2, 1);
scene.add(sun);
scene.add(new THREE.HemisphereLight(0xdfe8f5, 0x3a3227, 0.55));

// --- materials: textured (as exported) or hillshade (lit, untextured) -----------------------
const hillshadeMaterial = new THREE.MeshStandardMaterial({
  color: 0xdedad2, roughness: 1.0, metalness: 0.0, side: THREE.DoubleSide,
});

function applyShading(root) {
  root.traverse((obj) => {
    if (!obj.isMesh) return;
    if (!obj.userData.maquetteTextured) {
      obj.userData.maquetteTextured = obj.material;
      if (!obj.geometry.attributes.normal && obj.geometry.attributes.position) {
        obj.geometry.computeVertexNormals();  // hillshade needs normals
      }
    }
    obj.material = state.shading === 'hillshade' ? hillshadeMaterial : obj.userData.maquetteTextured;
  });
}

function setShading(mode) {
  state.shading = mode;
  html.dataset.shading = mode;
  toggleEl.textContent = mode === 'hillshade' ? 'texture' : 'hillshade';
  tiles.forEachLoadedModel((model) => applyShading(model));
  stableFrames = 0;
}

// --- tiles ---------------------------------------------------------------------------------
// 3D Tiles 1.1 lets a tile hold several contents (`contents`: terrain plus 3D content layers);
// 3d-tiles-renderer loads one, so the first is loaded by the renderer and the others are added
// to its scene here.
class MaquetteTilesRenderer extends TilesRenderer {
  preprocessNode(tile, tilesetDir, parentTile) {
    if (!tile.content && Array.isArray(tile.contents) && tile.contents.length > 0) {
      tile.content = tile.contents[0];
      tile.maquetteExtraContents = tile.contents.slice(1);
    }
    super.preprocessNode(tile, tilesetDir, parentTile);
    // A tile without content shows nothing: refine it whatever its geometric error. The renderer
    // stops at a tile whose error meets the target even when it is empty (only external tilesets
    // are refined unconditionally), so an export whose root is an empty tile with a large region
    // (a coarse DGGS cell around the data) would otherwise show nothing when framed from afar.
    tile.maquetteEmpty = !tile.content && (tile.children?.length || 0) > 0;
  }

  calculateTileViewError(tile, target) {
    super.calculateTileViewError(tile, target);
    if (tile.maquetteEmpty && target.inView) target.error = Infinity;
  }
}

const dracoLoader = new DRACOLoader();
dracoLoader.setDecoderPath(new URL('./draco/', window.location.href).href);
dracoLoader.setDecoderConfig({ type: 'wasm' });
const extraLoader = new GLTFLoader();
extraLoader.setDRACOLoader(dracoLoader);

const tiles = new MaquetteTilesRenderer(tilesetUrl);
tiles.registerPlugin(new GLTFExtensionsPlugin({ dracoLoader, metadata: true }));
tiles.registerPlugin(new ReorientationPlugin({ recenter: true }));
tiles.errorTarget = Number(params.get('errorTarget') || 6);
tiles.setCamera(camera);
tiles.setResolutionFromRenderer(camera, renderer);
scene.add(tiles.group);
// For scripts and debugging in the console.
window.__maquetteViewer = { THREE, tiles, scene, camera, controls, renderer };

let pendingExtras = 0;
let stableFrames = 0;

const CELL_ID = /^[NOPQRS][0-3]*$/;

// The cell a tile content stands for, from (in order) the glTF's extras (scene, node or mesh
// `extras.cell`), the tile's 3D Tiles metadata or extras (`cell`, `cell_id`), or the content
// file name when it is a cell id (`Q2013.glb`).
function cellFromObject(obj) {
  for (let o = obj; o; o = o.parent) {
    const u = o.userData || {};
    for (const key of ['cell', 'cell_id', 'cellId', 'maquetteCell']) {
      if (typeof u[key] === 'string' && u[key]) return u[key];
    }
  }
  return null;
}
function cellFromTile(tile, url) {
  const sources = [tile.metadata?.properties, tile.metadata, tile.extras, tile.content?.metadata?.properties,
    tile.content?.metadata, tile.content?.extras];
  for (const s of sources) {
    if (!s) continue;
    for (const key of ['cell', 'cell_id', 'cellId']) {
      if (typeof s[key] === 'string' && s[key]) return s[key];
    }
  }
  const name = decodeURIComponent((url || tile.content?.uri || '').split(/[?#]/)[0].split('/').pop() || '');
  const stem = name.replace(/\.[^.]*$/, '');
  return CELL_ID.test(stem) ? stem : null;
}

tiles.addEventListener('load-model', ({ scene: model, tile, url }) => {
  state.modelsLoaded++;
  const cell = cellFromObject(model) || cellFromTile(tile, url);
  if (cell) model.userData.maquetteCell = cell;
  applyShading(model);
  for (const extra of tile.maquetteExtraContents || []) {
    pendingExtras++;
    const extraUrl = new URL(extra.uri, `${tile.internal.basePath}/`).href;  // as the renderer resolves contents
    extraLoader.loadAsync(extraUrl).then((gltf) => {
      model.add(gltf.scene);
      // the renderer updates tile world matrices itself, not every frame: do it for the new child
      model.updateMatrixWorld(true);
      applyShading(gltf.scene);
      state.extraContentsLoaded++;
    }).catch((e) => reportError(`cannot load ${extraUrl}: ${e.message || e}`))
      .finally(() => { pendingExtras--; stableFrames = 0; });
  }
  stableFrames = 0;
});
tiles.addEventListener('load-error', ({ url, error }) => {
  reportError(`cannot load ${url}: ${error?.message || error}`);
});
tiles.addEventListener('tiles-load-start', () => { stableFrames = 0; });

// Framing, after the reorientation plugin has moved the tileset to the origin with +Y up: looks
// at a volume from the south, 45 degrees above the horizon, from the distance at which its
// horizontal extent fills the view. First the root bounding volume, which is all that is known
// before any content has loaded; then, once the first tiles in view have loaded, the bounding box
// of the loaded content, since an export's bounding volumes are the cells of the grid, which can
// be far larger than the data (the root of a small area is a coarse cell hundreds of km wide).
// `F` frames the content again (the root volume when no content has loaded yet).
const box = new THREE.Box3();
const boxFrame = new THREE.Matrix4();
const sphere = new THREE.Sphere();
const contentBox = new THREE.Box3();
let contentFramed = false;

const ELEVATION = THREE.MathUtils.degToRad(45);

// Puts the camera at `dist` from `center`, to its south, ELEVATION above the horizon; `radius`
// bounds what is framed (for the clipping planes).
function frameAt(center, dist, radius) {
  const elev = ELEVATION;
  controls.target.copy(center);
  camera.position.copy(center).add(new THREE.Vector3(0, Math.sin(elev) * dist, -Math.cos(elev) * dist));
  camera.near = Math.max(dist / 1000, 0.1);
  camera.far = dist * 20 + radius * 4;
  camera.updateProjectionMatrix();
  controls.maxDistance = Math.max(dist * 8, radius * 4);
  controls.update();
  camera.updateMatrixWorld();
  state.framed = true;
  stableFrames = 0;
}

// The root bounding volume.
function frameRoot() {
  if (!tiles.root || !tiles.getBoundingSphere(sphere)) return false;
  tiles.group.updateMatrixWorld(true);
  sphere.applyMatrix4(tiles.group.matrixWorld);
  let r = Math.max(sphere.radius, 1);
  if (tiles.getOrientedBoundingBox(box, boxFrame)) {
    // half the longest horizontal side of the oriented box, in the reoriented frame
    boxFrame.premultiply(tiles.group.matrixWorld);
    const size = box.getSize(new THREE.Vector3());
    const sx = new THREE.Vector3().setFromMatrixColumn(boxFrame, 0).multiplyScalar(size.x);
    const sy = new THREE.Vector3().setFromMatrixColumn(boxFrame, 1).multiplyScalar(size.y);
    const sz = new THREE.Vector3().setFromMatrixColumn(boxFrame, 2).multiplyScalar(size.z);
    const horiz = (v) => Math.hypot(v.x, v.z);
    r = Math.max(0.5 * Math.max(horiz(sx), horiz(sy), horiz(sz)), 1);
  }
  const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
  const halfFovX = Math.atan(Math.tan(halfFov) * camera.aspect);
  frameAt(sphere.center, r / Math.tan(Math.min(halfFov, halfFovX)) * 1.15, sphere.radius);
  return true;
}

// The bounding box (in the scene) of the content of the tiles shown; false when there is none.
function computeContentBox(target) {
  target.makeEmpty();
  tiles.group.updateMatrixWorld(true);
  for (const tile of tiles.visibleTiles) {
    const model = tile.engineData?.scene;
    if (model) target.expandByObject(model);
  }
  return !target.isEmpty();
}

// Frames the content box: the closest camera, on the framing direction, that sees its 8 corners
// with a small margin.
function frameContent() {
  if (contentBox.isEmpty()) return false;
  const size = contentBox.getSize(new THREE.Vector3());
  const center = contentBox.getCenter(new THREE.Vector3());
  const fwd = new THREE.Vector3(0, -Math.sin(ELEVATION), Math.cos(ELEVATION));  // towards the north, looking down
  const right = new THREE.Vector3().crossVectors(fwd, camera.up).normalize();
  const up = new THREE.Vector3().crossVectors(right, fwd);
  const tanY = Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)) / 1.06;
  const tanX = tanY * camera.aspect;
  let dist = 1;
  const v = new THREE.Vector3();
  for (let i = 0; i < 8; i++) {
    v.set(i & 1 ? size.x : -size.x, i & 2 ? size.y : -size.y, i & 4 ? size.z : -size.z).multiplyScalar(0.5);
    const depth = v.dot(fwd);  // the corner is seen at depth dist + depth
    dist = Math.max(dist, Math.abs(v.dot(right)) / tanX - depth, Math.abs(v.dot(up)) / tanY - depth);
  }
  frameAt(center, dist, 0.5 * size.length());
  return true;
}

function frame() {
  return frameContent() || frameRoot();
}

// --- readout under the mouse ---------------------------------------------------------------
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
const inverseGroup = new THREE.Matrix4();
const ecef = new THREE.Vector3();
const cart = {};
let pointerDirty = false;

function updateReadout() {
  raycaster.setFromCamera(pointer, camera);
  raycaster.firstHitOnly = true;
  const hit = raycaster.intersectObject(tiles.group, true)[0];
  if (!hit) {
    state.cell = state.lon = state.lat = state.height = null;
    cellEl.textContent = 'cell —';
    lonlatEl.textContent = 'lon/lat —';
    delete html.dataset.cell;
    return;
  }
  state.cell = cellFromObject(hit.object);
  inverseGroup.copy(tiles.group.matrixWorld).invert();
  ecef.copy(hit.point).applyMatrix4(inverseGroup);
  tiles.ellipsoid.getPositionToCartographic(ecef, cart);
  state.lon = THREE.MathUtils.radToDeg(cart.lon);
  state.lat = THREE.MathUtils.radToDeg(cart.lat);
  state.height = cart.height;
  cellEl.textContent = `cell ${state.cell || '?'}`;
  lonlatEl.textContent = `lon ${state.lon.toFixed(5)}  lat ${state.lat.toFixed(5)}  h ${state.height.toFixed(1)} m`;
  html.dataset.cell = state.cell || '?';
}

canvas.addEventListener('pointermove', (e) => {
  const rect = canvas.getBoundingClientRect();
  pointer.set(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
  pointerDirty = true;
});

// --- UI ------------------------------------------------------------------------------------
toggleEl.addEventListener('click', () => setShading(state.shading === 'hillshade' ? 'texture' : 'hillshade'));
document.getElementById('reframe').addEventListener('click', frame);
window.addEventListener('keydown', (e) => {
  if (e.key === 'h' || e.key === 'H') toggleEl.click();
  if (e.key === 'f' || e.key === 'F') frame();
});
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight, false);
  tiles.setResolutionFromRenderer(camera, renderer);
});
controls.addEventListener('change', () => { stableFrames = 0; });
setShading(state.shading);

// --- loop ----------------------------------------------------------------------------------
function loop() {
  requestAnimationFrame(loop);
  if (!state.framed && tiles.root) {
    frameRoot();
    setStatus(`${new URL(tilesetUrl).pathname.split('/').pop()}: loading tiles…`);
  }
  controls.update();
  camera.updateMatrixWorld();
  tiles.update();
  renderer.render(scene, camera);
  if (pointerDirty && state.framed) {
    pointerDirty = false;
    updateReadout();
  }

  const s = tiles.stats;
  const busy = tiles.isLoading || s.queued + s.downloading + s.parsing > 0 || pendingExtras > 0;
  const loaded = state.framed && !busy && state.modelsLoaded > 0 && tiles.visibleTiles.size > 0;
  stableFrames = loaded ? stableFrames + 1 : 0;
  if (stableFrames >= STABLE_FRAMES && !contentFramed) {
    // the first tiles in view have loaded: frame what they hold, then wait for that view's tiles
    contentFramed = true;
    if (computeContentBox(contentBox)) frameContent();
    stableFrames = 0;
  }
  const ready = stableFrames >= STABLE_FRAMES;
  if (ready !== state.tilesLoaded) {
    state.tilesLoaded = ready;
    html.dataset.tilesLoaded = String(ready);
    if (ready) setStatus(`${tiles.visibleTiles.size} tiles shown, ${state.modelsLoaded} loaded`);
  }
}
html.dataset.tilesLoaded = 'false';
loop();
