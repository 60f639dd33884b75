// Writes a small 3D Tiles 1.1 tileset shaped like `maquette export tiles3d` output, for the viewer
// test until the exporter can be used: a root tile (cell Q1, coarse) refined (REPLACE) by its four
// children (Q10..Q13), each a Draco-compressed (KHR_draco_mesh_compression) GLB terrain grid with
// normals and an embedded PNG texture, in a local east-north-up frame (glTF y-up) with the
// ENU -> ECEF transform in the tileset, `region` bounding volumes, and the cell id in the glTF
// node/scene extras (`extras.cell`) and in the content file name.
//
// Usage: node make_tileset.mjs OUTDIR NODE_MODULES_DIR
import { createRequire } from 'node:module';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import zlib from 'node:zlib';

const outDir = resolve(process.argv[2] || 'tileset');
const require = createRequire(join(resolve(process.argv[3] || 'node_modules'), '..', 'package.json'));
const draco3d = require('draco3dgltf');

const A = 6378137.0;
const F = 1 / 298.257223563;
const E2 = F * (2 - F);
const DEG = Math.PI / 180;

function ecef(lon, lat, h) {
  const sl = Math.sin(lat), cl = Math.cos(lat);
  const n = A / Math.sqrt(1 - E2 * sl * sl);
  return [(n + h) * cl * Math.cos(lon), (n + h) * cl * Math.sin(lon), (n * (1 - E2) + h) * sl];
}
// Column-major 4x4 ENU -> ECEF at (lon, lat, 0), as 3D Tiles `transform` wants.
function enuFrame(lon, lat) {
  const o = ecef(lon, lat, 0);
  const e = [-Math.sin(lon), Math.cos(lon), 0];
  const n = [-Math.sin(lat) * Math.cos(lon), -Math.sin(lat) * Math.sin(lon), Math.cos(lat)];
  const u = [Math.cos(lat) * Math.cos(lon), Math.cos(lat) * Math.sin(lon), Math.sin(lat)];
  return { o, e, n, u, matrix: [...e, 0, ...n, 0, ...u, 0, ...o, 1] };
}

// A smooth synthetic terrain (metres) over the region: hills and a valley.
function height(lon, lat) {
  const x = (lon / DEG - 10.0) * 40, y = (lat / DEG - 45.0) * 40;
  return 600 + 450 * Math.sin(x * 1.7) * Math.cos(y * 1.3) + 250 * Math.cos(x * 3.1 + y * 2.3) - 300 * Math.exp(-(x * x) * 4);
}

// --- PNG writer (RGB, 8 bit) -----------------------------------------------------------------
const CRC = new Int32Array(256).map((_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c;
});
function crc32(buf) {
  let c = -1;
  for (const b of buf) c = CRC[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ -1) >>> 0;
}
function chunk(type, data) {
  const len = Buffer.alloc(4); len.writeUInt32BE(data.length);
  const td = Buffer.concat([Buffer.from(type, 'ascii'), data]);
  const crc = Buffer.alloc(4); crc.writeUInt32BE(crc32(td));
  return Buffer.concat([len, td, crc]);
}
function png(w, h, rgbAt) {
  const raw = Buffer.alloc((w * 3 + 1) * h);
  for (let y = 0; y < h; y++) {
    raw[y * (w * 3 + 1)] = 0;
    for (let x = 0; x < w; x++) {
      const [r, g, b] = rgbAt(x, y);
      const i = y * (w * 3 + 1) + 1 + x * 3;
      raw[i] = r; raw[i + 1] = g; raw[i + 2] = b;
    }
  }
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(w, 0); ihdr.writeUInt32BE(h, 4); ihdr[8] = 8; ihdr[9] = 2;
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr),
    chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]);
}

// --- one terrain tile -------------------------------------------------------------------------
function terrainTile(enc, cell, w, s, e, n, segments, hue) {
  const lonc = (w + e) / 2, latc = (s + n) / 2;
  const f = enuFrame(lonc, latc);
  const side = segments + 1;
  const pos = new Float32Array(side * side * 3);
  const uv = new Float32Array(side * side * 2);
  let minH = Infinity, maxH = -Infinity;
  for (let j = 0; j < side; j++) {
    for (let i = 0; i < side; i++) {
      const lon = w + (e - w) * i / segments, lat = s + (n - s) * j / segments;
      const h = height(lon, lat);
      minH = Math.min(minH, h); maxH = Math.max(maxH, h);
      const p = ecef(lon, lat, h), d = [p[0] - f.o[0], p[1] - f.o[1], p[2] - f.o[2]];
      const de = d[0] * f.e[0] + d[1] * f.e[1] + d[2] * f.e[2];
      const dn = d[0] * f.n[0] + d[1] * f.n[1] + d[2] * f.n[2];
      const du = d[0] * f.u[0] + d[1] * f.u[1] + d[2] * f.u[2];
      const k = j * side + i;
      pos.set([de, du, -dn], k * 3);  // glTF y-up: x east, y up, z south
      uv.set([i / segments, 1 - j / segments], k * 2);
    }
  }
  const nor = new Float32Array(side * side * 3);
  const at = (i, j) => { const k = (Math.min(Math.max(j, 0), segments) * side + Math.min(Math.max(i, 0), segments)) * 3; return [pos[k], pos[k + 1], pos[k + 2]]; };
  for (let j = 0; j < side; j++) {
    for (let i = 0; i < side; i++) {
      const a = at(i + 1, j), b = at(i - 1, j), c = at(i, j + 1), d = at(i, j - 1);
      const dx = [a[0] - b[0], a[1] - b[1], a[2] - b[2]], dz = [c[0] - d[0], c[1] - d[1], c[2] - d[2]];
      // i grows east (+x), j north (-z): normal = dx x dz points up
      const nx = dx[1] * dz[2] - dx[2] * dz[1], ny = dx[2] * dz[0] - dx[0] * dz[2], nz = dx[0] * dz[1] - dx[1] * dz[0];
      const l = Math.hypot(nx, ny, nz) || 1;
      nor.set([nx / l, ny / l, nz / l], (j * side + i) * 3);
    }
  }
  const idx = new Uint32Array(segments * segments * 6);
  let t = 0;
  for (let j = 0; j < segments; j++) {
    for (let i = 0; i < segments; i++) {
      const a = j * side + i, b = a + 1, c = a + side, d = c + 1;
      idx.set([a, b, d, a, d, c], t); t += 6;  // counter-clockwise seen from above
    }
  }
  // Draco
  const builder = new enc.MeshBuilder(), mesh = new enc.Mesh(), encoder = new enc.Encoder();
  builder.AddFacesToMesh(mesh, idx.length / 3, idx);
  const posId = builder.AddFloatAttributeToMesh(mesh, enc.POSITION, side * side, 3, pos);
  const norId = builder.AddFloatAttributeToMesh(mesh, enc.NORMAL, side * side, 3, nor);
  const uvId = builder.AddFloatAttributeToMesh(mesh, enc.TEX_COORD, side * side, 2, uv);
  encoder.SetAttributeQuantization(enc.POSITION, 14);
  encoder.SetAttributeQuantization(enc.NORMAL, 10);
  encoder.SetAttributeQuantization(enc.TEX_COORD, 10);
  encoder.SetEncodingMethod(enc.MESH_EDGEBREAKER_ENCODING);
  const out = new enc.DracoInt8Array();
  const len = encoder.EncodeMeshToDracoBuffer(mesh, out);
  const drc = Buffer.alloc(len);
  for (let i = 0; i < len; i++) drc[i] = out.GetValue(i);
  enc.destroy(out); enc.destroy(encoder); enc.destroy(mesh); enc.destroy(builder);

  // Texture: coloured fields with a grid, distinct from the hillshade's grey.
  const texture = png(128, 128, (x, y) => {
    const line = x % 32 === 0 || y % 32 === 0;
    const v = 0.55 + 0.45 * Math.sin(x / 9) * Math.cos(y / 7);
    return line ? [250, 240, 200] : [Math.round(hue[0] * v), Math.round(hue[1] * v), Math.round(hue[2] * v)];
  });

  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  for (let k = 0; k < pos.length; k++) { min[k % 3] = Math.min(min[k % 3], pos[k]); max[k % 3] = Math.max(max[k % 3], pos[k]); }
  const pad4 = (b) => Buffer.concat([b, Buffer.alloc((4 - (b.length % 4)) % 4)]);
  const drcP = pad4(drc), pngP = pad4(texture);
  const gltf = {
    asset: { version: '2.0', generator: 'maquette tests/viewer/make_tileset.mjs' },
    extensionsUsed: ['KHR_draco_mesh_compression'],
    extensionsRequired: ['KHR_draco_mesh_compression'],
    scene: 0,
    scenes: [{ nodes: [0], extras: { cell } }],
    nodes: [{ mesh: 0, name: cell, extras: { cell } }],
    meshes: [{ primitives: [{
      attributes: { POSITION: 0, NORMAL: 1, TEXCOORD_0: 2 }, indices: 3, material: 0, mode: 4,
      extensions: { KHR_draco_mesh_compression: { bufferView: 0, attributes: { POSITION: posId, NORMAL: norId, TEXCOORD_0: uvId } } },
    }] }],
    accessors: [
      { componentType: 5126, count: side * side, type: 'VEC3', min, max },
      { componentType: 5126, count: side * side, type: 'VEC3' },
      { componentType: 5126, count: side * side, type: 'VEC2' },
      { componentType: 5125, count: idx.length, type: 'SCALAR' },
    ],
    materials: [{ pbrMetallicRoughness: { baseColorTexture: { index: 0 }, metallicFactor: 0, roughnessFactor: 1 } }],
    textures: [{ source: 0, sampler: 0 }],
    samplers: [{ magFilter: 9729, minFilter: 9987, wrapS: 33071, wrapT: 33071 }],
    images: [{ bufferView: 1, mimeType: 'image/png' }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: drc.length },
      { buffer: 0, byteOffset: drcP.length, byteLength: texture.length },
    ],
    buffers: [{ byteLength: drcP.length + pngP.length }],
  };
  let json = Buffer.from(JSON.stringify(gltf));
  json = Buffer.concat([json, Buffer.alloc((4 - (json.length % 4)) % 4, 0x20)]);
  const bin = Buffer.concat([drcP, pngP]);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0); header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + json.length + 8 + bin.length, 8);
  const jh = Buffer.alloc(8); jh.writeUInt32LE(json.length, 0); jh.writeUInt32LE(0x4e4f534a, 4);
  const bh = Buffer.alloc(8); bh.writeUInt32LE(bin.length, 0); bh.writeUInt32LE(0x004e4942, 4);
  const glb = Buffer.concat([header, jh, json, bh, bin]);
  const uri = `tiles/${cell}.glb`;
  writeFileSync(join(outDir, uri), glb);
  return { uri, transform: f.matrix, region: [w, s, e, n, minH, maxH] };
}

// A plain (not Draco) GLB of a few red boxes standing on the terrain around the tile centre, as a
// second content of a tile (3D Tiles 1.1 `contents`), like a 3D content layer's.
function boxesContent(cell, w, s, e, n) {
  const f = enuFrame((w + e) / 2, (s + n) / 2);
  const pos = [], nor = [], idx = [];
  const faces = [[[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[-1, 0, 0], [0, 0, 1], [0, 1, 0]], [[0, 1, 0], [0, 0, 1], [1, 0, 0]],
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]], [[0, 0, 1], [1, 0, 0], [0, 1, 0]], [[0, 0, -1], [0, 1, 0], [1, 0, 0]]];
  for (let b = 0; b < 5; b++) {
    const lon = w + (e - w) * (0.2 + 0.15 * b), lat = s + (n - s) * (0.3 + 0.1 * b);
    const p = ecef(lon, lat, height(lon, lat)), d = [p[0] - f.o[0], p[1] - f.o[1], p[2] - f.o[2]];
    const c = [d[0] * f.e[0] + d[1] * f.e[1] + d[2] * f.e[2], d[0] * f.u[0] + d[1] * f.u[1] + d[2] * f.u[2],
      -(d[0] * f.n[0] + d[1] * f.n[1] + d[2] * f.n[2])];
    const half = [150, 300, 150];
    for (const [nv, a, bb] of faces) {
      const base = pos.length / 3;
      for (const [sa, sb] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
        for (let k = 0; k < 3; k++) pos.push(c[k] + half[k] * (nv[k] + sa * a[k] + sb * bb[k]) + (k === 1 ? half[1] : 0));
        nor.push(...nv);
      }
      idx.push(base, base + 1, base + 2, base, base + 2, base + 3);
    }
  }
  const P = Buffer.from(new Float32Array(pos).buffer), N = Buffer.from(new Float32Array(nor).buffer);
  const I = Buffer.from(new Uint32Array(idx).buffer);
  const min = [0, 1, 2].map((k) => Math.min(...pos.filter((_, i) => i % 3 === k)));
  const max = [0, 1, 2].map((k) => Math.max(...pos.filter((_, i) => i % 3 === k)));
  const gltf = {
    asset: { version: '2.0', generator: 'maquette tests/viewer/make_tileset.mjs' },
    scene: 0, scenes: [{ nodes: [0], extras: { cell } }], nodes: [{ mesh: 0, name: `${cell}-boxes`, extras: { cell } }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0, NORMAL: 1 }, indices: 2, material: 0 }] }],
    materials: [{ pbrMetallicRoughness: { baseColorFactor: [0.85, 0.2, 0.15, 1], metallicFactor: 0, roughnessFactor: 0.8 } }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: pos.length / 3, type: 'VEC3', min, max },
      { bufferView: 1, componentType: 5126, count: nor.length / 3, type: 'VEC3' },
      { bufferView: 2, componentType: 5125, count: idx.length, type: 'SCALAR' },
    ],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: P.length }, { buffer: 0, byteOffset: P.length, byteLength: N.length },
      { buffer: 0, byteOffset: P.length + N.length, byteLength: I.length }],
    buffers: [{ byteLength: P.length + N.length + I.length }],
  };
  const uri = `tiles/${cell}-boxes.glb`;
  writeFileSync(join(outDir, uri), glbOf(gltf, Buffer.concat([P, N, I])));
  return uri;
}

function glbOf(gltf, binIn) {
  let json = Buffer.from(JSON.stringify(gltf));
  json = Buffer.concat([json, Buffer.alloc((4 - (json.length % 4)) % 4, 0x20)]);
  const bin = Buffer.concat([binIn, Buffer.alloc((4 - (binIn.length % 4)) % 4)]);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0); header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + json.length + 8 + bin.length, 8);
  const jh = Buffer.alloc(8); jh.writeUInt32LE(json.length, 0); jh.writeUInt32LE(0x4e4f534a, 4);
  const bh = Buffer.alloc(8); bh.writeUInt32LE(bin.length, 0); bh.writeUInt32LE(0x004e4942, 4);
  return Buffer.concat([header, jh, json, bh, bin]);
}

const enc = await draco3d.createEncoderModule({});
mkdirSync(join(outDir, 'tiles'), { recursive: true });
const W = 9.9 * DEG, S = 44.93 * DEG, E = 10.1 * DEG, N = 45.07 * DEG;
const root = terrainTile(enc, 'Q1', W, S, E, N, 24, [150, 170, 110]);
const hues = [[200, 160, 90], [110, 170, 120], [120, 150, 200], [190, 120, 140]];
const children = [];
for (let q = 0; q < 4; q++) {
  const col = q % 2, row = q < 2 ? 1 : 0;  // children 0 1 (north) / 2 3 (south)
  const w = W + (E - W) * col / 2, e = W + (E - W) * (col + 1) / 2;
  const s = S + (N - S) * row / 2, n = S + (N - S) * (row + 1) / 2;
  const t = terrainTile(enc, `Q1${q}`, w, s, e, n, 32, hues[q]);
  const child = {
    boundingVolume: { region: t.region }, geometricError: 0, refine: 'REPLACE',
    transform: t.transform, content: { uri: t.uri },
  };
  if (q === 2) {  // terrain plus a 3D content layer
    delete child.content;
    child.contents = [{ uri: t.uri }, { uri: boxesContent(`Q1${q}`, w, s, e, n) }];
    child.boundingVolume.region[5] += 600;
  }
  children.push(child);
}
const minH = Math.min(root.region[4], ...children.map((c) => c.boundingVolume.region[4]));
const maxH = Math.max(root.region[5], ...children.map((c) => c.boundingVolume.region[5]));
const tileset = {
  asset: { version: '1.1', generator: 'maquette tests/viewer/make_tileset.mjs' },
  geometricError: 2000,
  root: {
    boundingVolume: { region: [W, S, E, N, minH, maxH] }, geometricError: 600, refine: 'REPLACE',
    transform: root.transform, content: { uri: root.uri }, children,
  },
};
// Children's transforms are relative to their parent's in 3D Tiles: make them so.
const inv = invertRigid(root.transform);
for (const c of children) c.transform = mul(inv, c.transform);
writeFileSync(join(outDir, 'tileset.json'), JSON.stringify(tileset, null, 1));
console.log(`test tileset written to ${outDir}`);

function mul(a, b) {  // column-major 4x4
  const r = new Array(16).fill(0);
  for (let c = 0; c < 4; c++) for (let rr = 0; rr < 4; rr++) for (let k = 0; k < 4; k++) r[c * 4 + rr] += a[k * 4 + rr] * b[c * 4 + k];
  return r;
}
function invertRigid(m) {  // rotation + translation
  const r = [m[0], m[4], m[8], 0, m[1], m[5], m[9], 0, m[2], m[6], m[10], 0, 0, 0, 0, 1];
  const t = [m[12], m[13], m[14]];
  r[12] = -(r[0] * t[0] + r[4] * t[1] + r[8] * t[2]);
  r[13] = -(r[1] * t[0] + r[5] * t[1] + r[9] * t[2]);
  r[14] = -(r[2] * t[0] + r[6] * t[1] + r[10] * t[2]);
  return r;
}
