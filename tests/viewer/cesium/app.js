// Opens ./tileset.json (a `maquette export tiles3d` served by `maquette view --viewer` this
// folder) in CesiumJS, offline: no Cesium ion (no token, no default imagery or terrain), no base
// imagery, no geocoder or layer picker; the globe and sky hidden so that only the tileset is
// drawn, over the background colour #1d2229. Frames the tileset's content itself (from its
// regions, as the three.js viewer does) and signals on <html>:
// data-tiles-loaded="true" once every tile in view has loaded and a few frames were drawn,
// data-error="..." when a tile, the tileset or the rendering fails.
const html = document.documentElement;
const STABLE_FRAMES = 8;

function fail(message) {
  html.dataset.error = message;
  console.error(message);
}

// The content's lon/lat rectangle, as the three.js viewer finds it before any content has loaded:
// the union of the regions of the root's children (an export's top cells; their regions bound
// the terrain, not the cells), else the root's region; undefined for other bounding volumes.
function contentRectangle(tileset) {
  const { root } = tileset;
  let union;
  for (const tile of root.children.length ? root.children : [root]) {
    const rect = tile.boundingVolume.rectangle;  // a region's (TileBoundingRegion)
    if (!rect) return undefined;
    union = union ? Cesium.Rectangle.union(union, rect, new Cesium.Rectangle()) : rect.clone();
  }
  return union;
}

// Looks straight down at the content's rectangle; content spanning most of the globe is seen
// from space above its centre (Cesium's home view when it surrounds the globe), and a tileset
// without regions by its bounding sphere.
function frameContent(camera, tileset) {
  const rect = contentRectangle(tileset);
  if (!rect) return camera.viewBoundingSphere(tileset.boundingSphere);
  if (rect.width < Math.PI && rect.height < Math.PI / 2) return camera.setView({ destination: rect });
  if (rect.width >= 1.9 * Math.PI) return camera.flyHome(0);
  const centre = Cesium.Rectangle.center(rect);
  return camera.setView({
    destination: Cesium.Cartesian3.fromRadians(centre.longitude, centre.latitude, 2.5 * Cesium.Ellipsoid.WGS84.maximumRadius),
  });
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
  frameContent(viewer.camera, tileset);

  let stable = 0;
  scene.postRender.addEventListener(() => {
    stable = tileset.tilesLoaded ? stable + 1 : 0;
    if (stable === STABLE_FRAMES) html.dataset.tilesLoaded = 'true';
  });
}

html.dataset.tilesLoaded = 'false';
main().catch((e) => fail(String(e?.stack || e)));
