// Vertical exaggeration on the globe: every vertex moves along the ellipsoid normal through it, so
// that its height h above the ellipsoid becomes k * h at the same lon/lat (a uniform scale of the
// scene would also stretch the Earth's curvature and move the content off its place). Normals
// follow: in the local east-north-up frame their horizontal part is scaled by k, as the slopes
// are. Instances (trees) keep their shape and move with the ground: their origins are moved. Tile bounding volumes (regions) get the same heights, so that culling and refinement see
// the exaggerated terrain.
import * as THREE from 'three';

export const MIN_EXAGGERATION = 1;
export const MAX_EXAGGERATION = 10;

const _p = new THREE.Vector3();
const _s = new THREE.Vector3();
const _up = new THREE.Vector3();
const _n = new THREE.Vector3();
const _d = new THREE.Vector3();
const _toEcef = new THREE.Matrix4();
const _toMesh = new THREE.Matrix4();
const _normalToEcef = new THREE.Matrix3();
const _normalToMesh = new THREE.Matrix3();

// The transform from `obj`'s geometry to the tileset's frame (ECEF): the chain of local matrices
// up to the tile's model, whose matrix holds the tile transform.
function meshToEcef(obj, model, target) {
  target.identity();
  for (let o = obj; o; o = o === model ? null : o.parent) {
    o.updateMatrix();
    target.premultiply(o.matrix);
  }
  return target;
}

// Moves ECEF point `p` to k times its height above the ellipsoid, along the normal; returns the
// normal (in _up) or null near the Earth's centre.
function exaggeratePoint(p, ellipsoid, k) {
  if (!ellipsoid.getPositionToSurfacePoint(p, _s)) return null;
  ellipsoid.getPositionToNormal(_s, _up);
  const h = _d.subVectors(p, _s).dot(_up);
  p.addScaledVector(_up, h * (k - 1));
  return _up;
}

const _m = new THREE.Matrix4();
function exaggerateInstances(mesh, model, ellipsoid, k) {
  const matrices = mesh.instanceMatrix;
  const original = mesh.userData.maquetteOriginal ||= matrices.array.slice();
  meshToEcef(mesh, model, _toEcef);
  _toMesh.copy(_toEcef).invert();
  for (let i = 0; i < mesh.count; i++) {
    _m.fromArray(original, 16 * i);
    _p.setFromMatrixPosition(_m).applyMatrix4(_toEcef);
    exaggeratePoint(_p, ellipsoid, k);
    _p.applyMatrix4(_toMesh);
    _m.setPosition(_p).toArray(matrices.array, 16 * i);
  }
  matrices.needsUpdate = true;
  mesh.computeBoundingBox();
  mesh.computeBoundingSphere();
}

function exaggerateMesh(mesh, model, ellipsoid, k) {
  const geometry = mesh.geometry;
  const position = geometry.attributes.position;
  if (!position) return;
  const normal = geometry.attributes.normal;
  const original = geometry.userData.maquetteOriginal ||= {
    position: position.array.slice(), normal: normal?.array.slice(),
  };
  meshToEcef(mesh, model, _toEcef);
  _toMesh.copy(_toEcef).invert();
  _normalToEcef.getNormalMatrix(_toEcef);
  _normalToMesh.getNormalMatrix(_toMesh);
  const op = original.position;
  const on = original.normal;
  for (let i = 0; i < position.count; i++) {
    _p.set(op[3 * i], op[3 * i + 1], op[3 * i + 2]).applyMatrix4(_toEcef);
    if (!exaggeratePoint(_p, ellipsoid, k)) continue;
    _p.applyMatrix4(_toMesh);
    position.setXYZ(i, _p.x, _p.y, _p.z);
    if (on) {
      _n.set(on[3 * i], on[3 * i + 1], on[3 * i + 2]).applyMatrix3(_normalToEcef);
      const vertical = _n.dot(_up);
      _n.addScaledVector(_up, -vertical).multiplyScalar(k).addScaledVector(_up, vertical)
        .applyMatrix3(_normalToMesh).normalize();
      normal.setXYZ(i, _n.x, _n.y, _n.z);
    }
  }
  position.needsUpdate = true;
  if (normal) normal.needsUpdate = true;
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
}

export class VerticalExaggeration {
  constructor(tiles, factor = 1) {
    this.tiles = tiles;
    this.factor = factor;
  }

  // A tile's model (or `part` of it: a content added later), as loaded (heights as exported) or
  // already exaggerated.
  applyToModel(model, part = model) {
    const { ellipsoid } = this.tiles;
    part.traverse((o) => {
      if (o.isInstancedMesh) exaggerateInstances(o, model, ellipsoid, this.factor);
      else if (o.isMesh) exaggerateMesh(o, model, ellipsoid, this.factor);
    });
  }

  // A tile's region bounding volume: the heights it had and their exaggerated values.
  applyToTile(tile) {
    const region = tile.boundingVolume?.region;
    const volume = tile.engineData?.boundingVolume;
    if (!region || !volume) return;
    const [west, south, east, north, low, high] = region;
    const k = this.factor;
    volume.setRegionData(this.tiles.ellipsoid, west, south, east, north, Math.min(low, low * k),
      Math.max(high, high * k));
  }

  set(factor) {
    this.factor = factor;
    this.tiles.traverse((tile) => { this.applyToTile(tile); }, null, false);
    this.tiles.forEachLoadedModel((model) => this.applyToModel(model));
  }
}
