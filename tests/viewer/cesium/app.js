// Opens ./tileset.json (a `maquette export tiles3d` served by `maquette view --viewer` this
// folder) in CesiumJS, offline: no Cesium ion (no token, no default imagery or terrain), no base
// imagery, no geocoder or layer picker; the globe and sky hidden so that only the tileset is
// drawn, over the background colour #1d2229. Frames the tileset and signals on <html>:
// data-tiles-loaded="true" once every tile in view has loaded and a few frames were drawn,
// data-error="..." when a tile, the tileset or the rendering fails.
const html = document.documentElement;
const STABLE_FRAMES = 8;

function fail(message) {
  html.dataset.error = message;
  console.error(message);
}

async function main() {
  const viewer = new Cesium.Viewer('view', {
    baseLayer: false,
    baseLayerPicker: false,
    geocoder: false,
    terrainProvider: new Cesium.EllipsoidTerrainProvider(),
    homeButton: false,
    sceneModePicker: false,
    navigationHelpButton: false,
    animation: false,
    timeline: false,
    fullscreenButton: false,
    infoBox: false,
    selectionIndicator: false,
    skyBox: false,
    skyAtmosphere: false,  // with skyBox false: no sun or moon either
    contextOptions: { webgl: { preserveDrawingBuffer: true } },
  });
  const { scene } = viewer;
  scene.globe.show = false;
  scene.backgroundColor = Cesium.Color.fromCssColorString('#1d2229');
  scene.renderError.addEventListener((_, error) => fail(`render error: ${error}`));
  window.__cesium = viewer;

  const tileset = await Cesium.Cesium3DTileset.fromUrl('./tileset.json');
  tileset.tileFailed.addEventListener((e) => fail(`cannot load ${e.url}: ${e.message}`));
  scene.primitives.add(tileset);
  // zoomTo frames the root's bounding sphere from its radius, which for a whole-globe tileset
  // puts the camera at the Earth's surface: a tileset about as large as the Earth is shown from
  // Cesium's home view, the globe from space.
  // ?rect=W,S,E,N (degrees): the camera looks down at that box instead.
  const rect = new URLSearchParams(window.location.search).get('rect');
  if (rect) viewer.camera.setView({ destination: Cesium.Rectangle.fromDegrees(...rect.split(',').map(Number)) });
  else if (tileset.boundingSphere.radius > 0.5 * Cesium.Ellipsoid.WGS84.maximumRadius) viewer.camera.flyHome(0);
  else await viewer.zoomTo(tileset);

  let stable = 0;
  scene.postRender.addEventListener(() => {
    stable = tileset.tilesLoaded ? stable + 1 : 0;
    if (stable === STABLE_FRAMES) html.dataset.tilesLoaded = 'true';
  });
}

html.dataset.tilesLoaded = 'false';
main().catch((e) => fail(String(e?.stack || e)));
