// Renders a GLB of `maquette export glb --dem dem --content bridge` (the valley of
// tests/bridge, its deck across it) with three.js's GLTFLoader in Debian's chromium
// (tests/viewer/three_picture.mjs), and saves the screenshot: the picture of the structures
// README's bridge section.
//
//   node tests/bridge/bridge_picture.mjs --glb valley.glb \
//     --node-modules build/tests/viewer/npm/node_modules --three build/viewer-npm/node_modules/three \
//     --out bridge.png
//
// The camera stands south-south-west of the centre of the deck's bounding box (the node whose
// name starts with "bridge"), 30 degrees above it, the deck across most of the frame, and the
// sun casts the deck's shadow onto the valley: its 10 m of width, its rise from bank to bank
// and its height above the floor read, where a camera at the deck's height saw it edge-on, a
// thin line. Fails (exit 1) unless the terrain and the deck are drawn without console errors.
import { log, parseArgs } from '../viewer/harness.mjs';
import { threePicture } from '../viewer/three_picture.mjs';

const args = parseArgs();
const { dataset } = await threePicture(args, {
  viewport: { width: 960, height: 540 },
  setup: (THREE, scene, renderer) => {
    renderer.shadowMap.enabled = true;
    renderer.shadowMap.type = THREE.PCFSoftShadowMap;
    scene.add(new THREE.HemisphereLight(0xdfefff, 0x4a5a30, 1.2));
    const sun = new THREE.DirectionalLight(0xfff4e0, 2.4);
    sun.name = 'sun';
    sun.castShadow = true;
    sun.shadow.mapSize.set(4096, 4096);
    scene.add(sun, sun.target);
  },
  frame: (THREE, gltf, scene) => {
    const inDeck = (o) => { for (let p = o; p; p = p.parent) if (p.name.startsWith('bridge')) return true; return false; };
    let deck = null, meshes = 0;
    gltf.scene.traverse((o) => {
      if (o.name.startsWith('bridge')) deck = deck || o;
      if (!o.isMesh) return;
      meshes++;
      o.material = new THREE.MeshStandardMaterial({ color: inDeck(o) ? 0xc0392b : 0x9c9a86, roughness: 1,
        flatShading: true, side: THREE.DoubleSide });
      o.castShadow = inDeck(o);
      o.receiveShadow = !inDeck(o);
    });
    document.documentElement.dataset.meshes = String(meshes);
    if (!deck) { document.documentElement.dataset.error = 'no bridge node'; return null; }
    const box = new THREE.Box3().setFromObject(deck);
    const centre = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3()).length();
    // glTF axes: x east, y up, z south. The sun high in the south-west, so that the deck's
    // shadow on the valley floor shows how high it stands.
    const sun = scene.getObjectByName('sun');
    sun.target.position.copy(centre);
    sun.position.set(centre.x - 0.3 * size, centre.y + size, centre.z + 0.4 * size);
    Object.assign(sun.shadow.camera, { left: -size, right: size, top: size, bottom: -size, near: 1, far: 4 * size });
    sun.shadow.camera.updateProjectionMatrix();
    // The camera the deck's size away, 30 degrees above it, from 25 degrees west of south.
    const distance = 1.0 * size, up = THREE.MathUtils.degToRad(30), west = THREE.MathUtils.degToRad(25);
    const camera = new THREE.PerspectiveCamera(40, innerWidth / innerHeight, 1, 20 * size);
    camera.position.set(centre.x - distance * Math.cos(up) * Math.sin(west), centre.y + distance * Math.sin(up),
      centre.z + distance * Math.cos(up) * Math.cos(west));
    camera.lookAt(centre);
    return camera;
  },
});
if (!(Number(dataset.meshes) >= 2)) {
  log(`failed: ${dataset.meshes} meshes drawn`);
  process.exit(1);
}
log(`${dataset.meshes} meshes drawn; saved ${args.out}`);
