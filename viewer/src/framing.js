// Framing a tileset on the globe, from a single cell to the whole Earth. The content is known by
// points that bound it, in the tileset's frame (ECEF): first the corners of the top tiles'
// regions, then, once tiles have loaded, the corners of their meshes. The view looks at the
// surface point under the points' mean direction, from above: 45 degrees above the horizon for a
// small area, straight down for a continent, and a content around the whole globe is seen from
// space (lon 0, lat 20 unless an earlier view had a direction).
import * as THREE from 'three';

const DEG = Math.PI / 180;
const WHOLE_GLOBE = { lat: 20 * DEG, lon: 0 };
const MIN_SPREAD = 0.3;  // below this mean of unit vectors the content surrounds the globe

// Points (ECEF) bounding a 3D Tiles region: a 5 x 5 lon/lat grid at its lowest and highest
// heights (regions across the antimeridian have west > east).
function regionPoints(ellipsoid, region, out) {
  const [west, south, north] = [region[0], region[1], region[3]];
  const east = region[2] < west ? region[2] + 2 * Math.PI : region[2];
  for (let i = 0; i <= 4; i++) {
    for (let j = 0; j <= 4; j++) {
      for (const h of [region[4], region[5]]) {
        out.push(ellipsoid.getCartographicToPosition(south + (north - south) * j / 4,
          west + (east - west) * i / 4, h, new THREE.Vector3()));
      }
    }
  }
}

function boxCorners(box, matrix, out) {
  for (let i = 0; i < 8; i++) {
    out.push(new THREE.Vector3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
      i & 4 ? box.max.z : box.min.z).applyMatrix4(matrix));
  }
}

// Before any content: the regions of the root's children (an export's top cells), else the
// corners of the root's oriented bounding box.
export function tilesetPoints(tiles) {
  const points = [];
  const children = tiles.root?.children || [];
  if (children.length && children.every((c) => c.boundingVolume?.region)) {
    for (const c of children) regionPoints(tiles.ellipsoid, c.boundingVolume.region, points);
    return points;
  }
  const box = new THREE.Box3();
  const frame = new THREE.Matrix4();
  if (tiles.getOrientedBoundingBox(box, frame)) boxCorners(box, frame, points);
  return points;
}

// The corners of the meshes of the tiles shown.
export function contentPoints(tiles) {
  const points = [];
  tiles.group.updateMatrixWorld(true);
  const toEcef = tiles.group.matrixWorld.clone().invert();
  const m = new THREE.Matrix4();
  for (const tile of tiles.visibleTiles) {
    tile.engineData?.scene?.traverse((o) => {
      if (!o.isMesh) return;
      if (!o.geometry.boundingBox) o.geometry.computeBoundingBox();
      boxCorners(o.geometry.boundingBox, m.multiplyMatrices(toEcef, o.matrixWorld), points);
    });
  }
  return points;
}

// Where the view looks: the geodetic lat/lon (radians) under the points' mean direction and the
// points' angular radius around it (radians). `previous` is kept when the points surround the
// globe.
export function contentCentre(ellipsoid, points, previous) {
  const sum = new THREE.Vector3();
  for (const p of points) sum.add(p.clone().normalize());
  const spread = sum.length() / Math.max(points.length, 1);
  const at = {};
  if (spread >= MIN_SPREAD) {
    ellipsoid.getPositionToCartographic(sum.normalize().multiplyScalar(ellipsoid.radius.x), at);
  } else {
    Object.assign(at, previous || WHOLE_GLOBE);
  }
  const dir = ellipsoid.getCartographicToNormal(at.lat, at.lon, new THREE.Vector3());
  let radius = 0;
  for (const p of points) radius = Math.max(radius, dir.angleTo(p));
  return { lat: at.lat, lon: at.lon, radius };
}

// The elevation of the view above the horizon (radians) for content of angular radius `radius`:
// 45 degrees up to 1 degree (a valley, a city, a cell), then steeper, straight down from 15.
export function viewElevation(radius) {
  const t = THREE.MathUtils.clamp((radius / DEG - 1) / 14, 0, 1);
  return THREE.MathUtils.lerp(45, 89.9, t) * DEG;
}

// The camera at `elevation` above the horizon, from the south, in the frame where +Y is up at
// the content's centre and +Z north: the closest one whose view holds every point (world
// coordinates) with a small margin, looking at their bounding box's centre.
export function fitView(camera, points, elevation) {
  const box = new THREE.Box3().setFromPoints(points);
  const target = box.getCenter(new THREE.Vector3());
  const fwd = new THREE.Vector3(0, -Math.sin(elevation), Math.cos(elevation));
  const right = new THREE.Vector3().crossVectors(fwd, camera.up).normalize();
  const up = new THREE.Vector3().crossVectors(right, fwd);
  const tanY = Math.tan(THREE.MathUtils.degToRad(camera.fov / 2)) / 1.06;
  const tanX = tanY * camera.aspect;
  let dist = 1;
  let radius = 0;
  const v = new THREE.Vector3();
  for (const p of points) {
    v.subVectors(p, target);
    radius = Math.max(radius, v.length());
    const depth = v.dot(fwd);  // the point is seen at depth dist + depth
    dist = Math.max(dist, Math.abs(v.dot(right)) / tanX - depth, Math.abs(v.dot(up)) / tanY - depth);
  }
  return { target, position: target.clone().addScaledVector(fwd, -dist), dist, radius };
}
