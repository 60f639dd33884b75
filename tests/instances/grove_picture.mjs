// Renders the grove that tests/instances writes (build/tests/instances/grove/grove.glb: the three
// built-in prototypes drawn with EXT_mesh_gpu_instancing) with three.js's GLTFLoader in Debian's
// chromium (tests/viewer/three_picture.mjs), and saves the screenshot: the picture of
// docs/builtin-prototypes.png.
//
//   node tests/instances/grove_picture.mjs --glb build/tests/instances/grove/grove.glb \
//     --node-modules build/tests/viewer/npm/node_modules --three build/viewer-npm/node_modules/three \
//     --out grove.png
//
// (--camera X,Y,Z places the camera elsewhere than in front, glTF axes.) It fails (exit 1)
// unless the six instanced meshes are drawn without console errors and the crowns rise above
// the horizon: at least 3 % of the sky above it, seen from the default camera, is foliage, green
// above red and blue (prototypes lying down or upside down, wrong axes, would leave the sky
// empty).
import { log, parseArgs } from '../viewer/harness.mjs';
import { threePicture } from '../viewer/three_picture.mjs';

const args = parseArgs();
const { png, dataset } = await threePicture(args, {
  viewport: { width: 800, height: 450 },
  params: { camera: (args.camera || '0,7,34').split(',').map(Number) },
  setup: (THREE, scene, renderer) => {
    renderer.shadowMap.enabled = true;
    renderer.shadowMap.type = THREE.PCFSoftShadowMap;
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
  },
  frame: (THREE, gltf, scene, params) => {
    gltf.scene.traverse((o) => { if (o.isMesh) { o.castShadow = true; o.receiveShadow = true; } });
    const camera = new THREE.PerspectiveCamera(38, innerWidth / innerHeight, 0.5, 500);
    camera.position.set(...params.camera);
    camera.lookAt(0, 4.5, 0);
    document.documentElement.dataset.instanced = String(gltf.scene.children.filter((o) => o.isInstancedMesh).length);
    return camera;
  },
});
log(`${dataset.instanced} instanced meshes drawn; saved ${args.out}`);
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
if (dataset.instanced !== '6' || (!args.camera && share < 0.03)) process.exit(1);
