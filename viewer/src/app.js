// Maquette viewer: opens a 3D Tiles 1.1 tileset written by `maquette export tiles3d` with three.js
// and 3d-tiles-renderer, frames it, and offers orbit controls, a hillshade/texture toggle and a
// cell-id + lon/lat readout under the mouse. Everything (Draco decoder included) is served from
// this folder, so it works offline.
//
// Query parameters: ?tileset=URL (default ./tileset.json), &shading=hillshade|texture,
// &errorTarget=PIXELS (screen-space error, default 6), &exaggeration=K (vertical, 1..10).
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
import { MAX_EXAGGERATION, MIN_EXAGGERATION, VerticalExaggeration } from './exaggeration.js';
import { contentCentre, contentPoints, fitView, tilesetPoints, viewElevation } from './framing.js';

const params = new URLSearchParams(window.location.search);
const tilesetUrl = new URL(params.get('tileset') || './tileset.json', window.location.href).href;
const STABLE_FRAMES = 8;  // frames with nothing pending before "loaded" is signalled
const EXAGGERATION_STEP = 0.5;

function exaggerationParam() {
  const k = Number(params.get('exaggeration') || 1);
  return Number.isFinite(k) ? THREE.MathUtils.clamp(k, MIN_EXAGGERATION, MAX_EXAGGERATION) : 1;
}

const state = {
  tilesLoaded: false,
  framed: false,
  shading: params.get('shading') === 'hillshade' ? 'hillshade' : 'texture',
  tileset: tilesetUrl,
  modelsLoaded: 0,
  extraContentsLoaded: 0,
  exaggeration: exaggerationParam(),
  view: null,  // the last framing: lat, lon (radians) and angular radius of the content
  errors: [],
  cell: null,
  lon: null,
  lat: null,
  height: null,  // of the terrain, as exported (the exaggerated height divided by the factor)
  ecef: null,  // the point hit under the mouse, as drawn (exaggerated), in the tileset's frame
};
window.__maquette = state;
const html = document.documentElement;
const statusEl = document.getElementById('status');
const cellEl = document.getElementById('cell');
const lonlatEl = document.getElementById('lonlat');
const toggleEl = document.getElementById('toggle-shading');
const exaggerationEl = document.getElementById('exaggeration');
const exaggerationValueEl = document.getElementById('exaggeration-value');

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
// Front faces only. Exports were double-sided until issue 13 (other tilesets may be), and glTF
// lights a back face with its normal reversed: the back of a tile's skirt, where it meets its own
// edge and the neighbour's skirt, drew dark dotted lines along every seam. A skirt is only needed
// from outside its tile, where its front face is.
const hillshadeMaterial = new THREE.MeshStandardMaterial({
  color: 0xdedad2, roughness: 1.0, metalness: 0.0, side: THREE.FrontSide,
});

function applyShading(root) {
  root.traverse((obj) => {
    if (!obj.isMesh) return;
    if (!obj.userData.maquetteTextured) {
      obj.material.side = THREE.FrontSide;
      obj.userData.maquetteTextured = obj.material;
      if (!obj.geometry.attributes.normal && obj.geometry.attributes.position) {
        obj.geometry.computeVertexNormals();  // hillshade needs normals
      }
    }
    // 3D content (a tile's extra contents) keeps its own colours: the hillshade is the terrain's.
    const hillshade = state.shading === 'hillshade' && !obj.userData.maquetteContent;
    obj.material = hillshade ? hillshadeMaterial : obj.userData.maquetteTextured;
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
    if (this.exaggeration.factor !== 1) this.exaggeration.applyToTile(tile);
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
const exaggeration = new VerticalExaggeration(tiles, state.exaggeration);
tiles.exaggeration = exaggeration;
const reorientation = new ReorientationPlugin({ recenter: true });
tiles.registerPlugin(new GLTFExtensionsPlugin({ dracoLoader, metadata: true }));
tiles.registerPlugin(reorientation);
tiles.errorTarget = Number(params.get('errorTarget') || 6);
tiles.setCamera(camera);
tiles.setResolutionFromRenderer(camera, renderer);
scene.add(tiles.group);
// For scripts and debugging in the console.
window.__maquetteViewer = { THREE, tiles, scene, camera, controls, renderer, exaggeration };

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
  exaggeration.applyToModel(model);
  applyShading(model);
  for (const extra of tile.maquetteExtraContents || []) {
    pendingExtras++;
    const extraUrl = new URL(extra.uri, `${tile.internal.basePath}/`).href;  // as the renderer resolves contents
    extraLoader.loadAsync(extraUrl).then((gltf) => {
      model.add(gltf.scene);
      exaggeration.applyToModel(model, gltf.scene);
      // the renderer updates tile world matrices itself, not every frame: do it for the new child
      model.updateMatrixWorld(true);
      gltf.scene.traverse((o) => { o.userData.maquetteContent = true; });
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

// Framing (framing.js): the tileset is reoriented so that +Y is up at the centre of its content
// (ReorientationPlugin: +X west, +Z north), and the camera looks at the content from above, from
// the south: first the top tiles' regions, all that is known before any content has loaded; then,
// once the first tiles in view have loaded, their meshes, since an export's bounding volumes are
// the cells of the grid, which can be far larger than the data (the top tiles of a continent can
// be whole faces of the grid). `F` frames the content shown again.
let contentFramed = false;
let contentRadius = 1;  // metres, from the framed target: bounds the far clipping plane

function frameOn(points) {
  if (!points.length) return false;
  state.view = contentCentre(tiles.ellipsoid, points, state.view);
  reorientation.transformLatLonHeightToOrigin(state.view.lat, state.view.lon);
  tiles.group.updateMatrixWorld(true);
  const world = points.map((p) => p.applyMatrix4(tiles.group.matrixWorld));
  const fit = fitView(camera, world, viewElevation(state.view.radius));
  controls.target.copy(fit.target);
  camera.position.copy(fit.position);
  contentRadius = Math.max(fit.radius, 1);
  // A continent or more is orbited around the globe; less, from above its horizon.
  const globe = state.view.radius > THREE.MathUtils.degToRad(20);
  controls.maxPolarAngle = globe ? Math.PI : Math.PI * 0.495;
  // the camera stays above the surface when the target lies deep under it (a globe's centre)
  controls.minDistance = Math.max(-ecefHeight(fit.target), 0);
  controls.maxDistance = Math.max(fit.dist * 8, contentRadius * 4);
  controls.update();
  updateClipping();
  state.framed = true;
  stableFrames = 0;
  return true;
}

function frame() {
  return frameOn(contentPoints(tiles)) || frameOn(tilesetPoints(tiles));
}

// The height above the ellipsoid of a point of the scene.
const inverseGroup = new THREE.Matrix4();
const cart = {};
function ecefOf(world, target) {
  inverseGroup.copy(tiles.group.matrixWorld).invert();
  return target.copy(world).applyMatrix4(inverseGroup);
}
function ecefHeight(world) {
  tiles.ellipsoid.getPositionToCartographic(ecefOf(world, new THREE.Vector3()), cart);
  return cart.height;
}

// Clipping planes from the camera's distance to the target and its height above the ellipsoid,
// so that zooming from space down to a valley keeps both the near terrain and the far horizon.
function updateClipping() {
  const d = camera.position.distanceTo(controls.target);
  camera.near = Math.max(Math.min(d, Math.abs(ecefHeight(camera.position))) / 1000, 0.1);
  camera.far = d + 2 * contentRadius + controls.maxDistance;
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

// --- readout under the mouse ---------------------------------------------------------------
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
const ecef = new THREE.Vector3();
let pointerDirty = false;

function updateReadout() {
  raycaster.setFromCamera(pointer, camera);
  raycaster.firstHitOnly = true;
  const hit = raycaster.intersectObject(tiles.group, true)[0];
  if (!hit) {
    state.cell = state.lon = state.lat = state.height = state.ecef = null;
    cellEl.textContent = 'cell —';
    lonlatEl.textContent = 'lon/lat —';
    delete html.dataset.cell;
    return;
  }
  state.cell = cellFromObject(hit.object);
  tiles.ellipsoid.getPositionToCartographic(ecefOf(hit.point, ecef), cart);
  state.ecef = ecef.toArray();
  state.lon = THREE.MathUtils.radToDeg(cart.lon);
  state.lat = THREE.MathUtils.radToDeg(cart.lat);
  state.height = cart.height / exaggeration.factor;
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

function setExaggeration(k) {
  const factor = THREE.MathUtils.clamp(k, MIN_EXAGGERATION, MAX_EXAGGERATION);
  state.exaggeration = factor;
  html.dataset.exaggeration = String(factor);
  exaggerationEl.value = String(factor);
  exaggerationValueEl.textContent = `×${factor}`;
  if (factor !== exaggeration.factor) exaggeration.set(factor);
  stableFrames = 0;
}
exaggerationEl.min = String(MIN_EXAGGERATION);
exaggerationEl.max = String(MAX_EXAGGERATION);
exaggerationEl.step = String(EXAGGERATION_STEP);
exaggerationEl.addEventListener('input', () => setExaggeration(Number(exaggerationEl.value)));
window.addEventListener('keydown', (e) => {
  if (e.target === exaggerationEl) return;  // the slider has its own keys
  if (e.key === 'h' || e.key === 'H') toggleEl.click();
  if (e.key === 'f' || e.key === 'F') frame();
  if (e.key === '+' || e.key === '=') setExaggeration(state.exaggeration + EXAGGERATION_STEP);
  if (e.key === '-' || e.key === '_') setExaggeration(state.exaggeration - EXAGGERATION_STEP);
});
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight, false);
  tiles.setResolutionFromRenderer(camera, renderer);
});
controls.addEventListener('change', () => { stableFrames = 0; });
setShading(state.shading);
setExaggeration(state.exaggeration);

// --- loop ----------------------------------------------------------------------------------
function loop() {
  requestAnimationFrame(loop);
  if (!state.framed && tiles.root) {
    frame();
    setStatus(`${new URL(tilesetUrl).pathname.split('/').pop()}: loading tiles…`);
  }
  controls.update();
  updateClipping();
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
    frame();
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
