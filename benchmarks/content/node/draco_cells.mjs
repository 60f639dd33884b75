// gltf-transform's Draco compression (the `draco` transform its CLI's `draco` command runs,
// weld included) of every cell's plain GLB in one process, each cell at the position bits our
// encoder chose for it (cells.json from mesh_cells), so that node's start-up is paid once.
// Usage: node draco_cells.mjs PLAIN_DIR OUT_DIR CELLS_JSON SPEED NORMAL_BITS TEXCOORD_BITS
// Prints JSON: wall and CPU seconds of reading (GLB parse) and of compressing + writing.
import { readFileSync } from 'node:fs';
import { NodeIO } from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { draco } from '@gltf-transform/functions';
import draco3d from 'draco3dgltf';

const [plain, out, manifest, speed, normalBits, texcoordBits] = process.argv.slice(2);
const io = new NodeIO().registerExtensions(ALL_EXTENSIONS).registerDependencies({
  'draco3d.encoder': await draco3d.createEncoderModule(),
  'draco3d.decoder': await draco3d.createDecoderModule(),
});
const cpu = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1e6; };
const times = { read_wall_s: 0, read_cpu_s: 0, encode_write_wall_s: 0, encode_write_cpu_s: 0 };
for (const { cell, position_bits } of JSON.parse(readFileSync(manifest, 'utf8')).cells) {
  let [w, c] = [performance.now(), cpu()];
  const doc = await io.read(`${plain}/${cell}.glb`);
  times.read_wall_s += (performance.now() - w) / 1e3;
  times.read_cpu_s += cpu() - c;
  [w, c] = [performance.now(), cpu()];
  await doc.transform(draco({
    method: 'edgebreaker', encodeSpeed: Number(speed), decodeSpeed: Number(speed),
    quantizePosition: position_bits, quantizeNormal: Number(normalBits),
    quantizeTexcoord: Number(texcoordBits), quantizationVolume: 'mesh',
  }));
  await io.write(`${out}/${cell}.glb`, doc);  // Draco encodes here
  times.encode_write_wall_s += (performance.now() - w) / 1e3;
  times.encode_write_cpu_s += cpu() - c;
}
console.log(JSON.stringify(times));
