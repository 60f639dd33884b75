// Writes the synthetic whole-globe DEM of global_dem.mjs for the viewer tests: OUT.bil + OUT.hdr
// (GDAL's EHdr format, float32, lon/lat cells: pass `--src-crs EPSG:4326` to `maquette ingest`),
// W x H pixels covering -180..180, -90..90, each the height at its centre.
//
// Usage: node make_global_dem.mjs OUT [W H]   (default 1024 x 512)
import { writeFileSync } from 'node:fs';
import { demHeight } from './global_dem.mjs';

const out = process.argv[2];
const w = Number(process.argv[3] || 1024);
const h = Number(process.argv[4] || 512);
if (!out || !(w > 0) || !(h > 0)) {
  console.error('usage: node make_global_dem.mjs OUT [W H]');
  process.exit(2);
}

const data = new Float32Array(w * h);
for (let r = 0; r < h; r++) {
  const lat = 90 - (r + 0.5) * (180 / h);
  for (let c = 0; c < w; c++) data[r * w + c] = demHeight(-180 + (c + 0.5) * (360 / w), lat);
}
writeFileSync(`${out}.bil`, Buffer.from(data.buffer));
// ulxmap/ulymap: the centre of the upper-left pixel.
writeFileSync(`${out}.hdr`, [
  'byteorder I', 'layout bil', `nrows ${h}`, `ncols ${w}`, 'nbands 1', 'nbits 32', 'pixeltype float',
  `ulxmap ${-180 + 180 / w}`, `ulymap ${90 - 90 / h}`, `xdim ${360 / w}`, `ydim ${180 / h}`, '',
].join('\n'));
