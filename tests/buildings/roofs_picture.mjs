// Renders a GLB of `maquette export glb --dem dem --content buildings` (structures.buildings'
// meshes over their terrain) with three.js's GLTFLoader in Debian's chromium, and saves the
// screenshot: the picture of the structures README's roofs.
//
//   node tests/buildings/roofs_picture.mjs --glb soho.glb \
//     --node-modules build/tests/viewer/npm/node_modules --three build/viewer-npm/node_modules/three \
//     --out roofs.png [--zoom 0.3]
//
// Each building face is coloured by its slope (the facet normals): roof faces, flat or pitched,
// tiled red, walls pale, so that a roof's planes and creases read at a glance. The camera looks
// at the centre of the buildings (nodes named "buildings...") from the south-south-west, 35
// degrees down, from `zoom` x their extent. Fails (exit 1) unless the terrain and the buildings
// are drawn without console errors.
import { drawGlbPage, parseArgs, threePageStart } from '../viewer/harness.mjs';

const args = parseArgs();
const zoom = Number(args.zoom || 0.3);
const page = `${threePageStart}
scene.add(new THREE.HemisphereLight(0xdfefff, 0x4a5a30, 0.7));
const sun = new THREE.DirectionalLight(0xfff4e0, 3.2);
sun.position.set(-1, 0.9, 0.35);
scene.add(sun);
loader.load('/scene.glb', (gltf) => {
  let meshes = 0;
  const buildings = new THREE.Box3();
  scene.add(gltf.scene);
  scene.updateMatrixWorld(true);
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    meshes++;
    let inBuildings = false;
    for (let p = o; p; p = p.parent) inBuildings = inBuildings || p.name.startsWith('buildings');
    if (!inBuildings) {
      o.material = new THREE.MeshStandardMaterial({ color: 0x9c9a86, roughness: 1 });
      return;
    }
    buildings.expandByObject(o);
    // A vertex colour per face from its normal's up component (world y): roofs red, walls pale.
    const g = o.geometry.index ? o.geometry.toNonIndexed() : o.geometry;
    g.computeVertexNormals();
    const n = g.attributes.normal, colours = new Float32Array(n.count * 3);
    const up = new THREE.Vector3(), normalMatrix = new THREE.Matrix3().getNormalMatrix(o.matrixWorld);
    for (let k = 0; k < n.count; k++) {
      up.fromBufferAttribute(n, k).applyMatrix3(normalMatrix).normalize();
      const c = up.y > 0.2 ? [0.72, 0.30, 0.22] : up.y < -0.2 ? [0.3, 0.3, 0.3] : [0.93, 0.89, 0.80];
      colours.set(c, 3 * k);
    }
    g.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    o.geometry = g;
    o.material = new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.9, flatShading: true });
  });
  if (buildings.isEmpty()) { document.documentElement.dataset.error = 'no buildings node'; return; }
  const centre = buildings.getCenter(new THREE.Vector3());
  const size = ${zoom} * buildings.getSize(new THREE.Vector3()).length();
  // glTF axes: x east, y up, z south; from the south-south-west, 35 degrees down.
  const camera = new THREE.PerspectiveCamera(35, innerWidth / innerHeight, 1, 20 * size);
  const d = size * 1.2;
  camera.position.set(centre.x - 0.38 * d * Math.cos(0.61), centre.y + d * Math.sin(0.61),
                      centre.z + 0.92 * d * Math.cos(0.61));
  camera.lookAt(centre);
  renderer.render(scene, camera);
  document.documentElement.dataset.meshes = String(meshes);
  document.documentElement.dataset.loaded = 'true';
}, undefined, (e) => { document.documentElement.dataset.error = String(e); });
</script></body></html>`;

await drawGlbPage({ nodeModules: args['node-modules'], three: args.three, glb: args.glb, out: args.out,
  page, viewport: { width: 1200, height: 700 } });
