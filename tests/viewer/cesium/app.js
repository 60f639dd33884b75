// Opens ./tileset.json (a `maquette export tiles3d` served by `maquette view --viewer` this
// folder) in CesiumJS, offline: no Cesium ion (no token, no default imagery or terrain), no base
// imagery, no geocoder or layer picker; the globe and sky hidden so that only the tileset is
// drawn, over the background colour #1d2229. Flies to the tileset and signals on <html>:
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
  await viewer.zoomTo(tileset);

  let stable = 0;
  scene.postRender.addEventListener(() => {
    stable = tileset.tilesLoaded ? stable + 1 : 0;
    if (stable === STABLE_FRAMES) html.dataset.tilesLoaded = 'true';
  });
}

html.dataset.tilesLoaded = 'false';
main().catch((e) => fail(String(e?.stack || e)));
