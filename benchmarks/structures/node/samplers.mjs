// The peers of compare_poisson_disk.sh: two public Poisson-disk samplers (npm, MIT, by Kevin
// Chapelier) over the square [0, SIDE)^2 with the minimum distance R, each RUNS times in this
// process with its default random numbers (Math.random):
//   poisson-disk-sampling          Bridson's algorithm in any dimension: candidates in the annulus
//                                  [R, 2 R) around an active point, 30 tries (its defaults);
//   fast-2d-poisson-disk-sampling  the same author's 2D-only version, 30 tries (its default).
// Usage: node samplers.mjs SIDE R RUNS OUT_DIR [NAME]   (NAME: that sampler only)
// Writes OUT_DIR/NAME.bin (the last run's points as little-endian float64 x, y pairs) and prints
// one JSON object: per sampler, the count and each run's CPU seconds (user + system of this
// process: the JIT and the garbage collector's threads count) and wall seconds of fill().
import { createRequire } from "node:module";
import { writeFileSync } from "node:fs";
import { join } from "node:path";

const require = createRequire(import.meta.url);
const [side, r, runs] = process.argv.slice(2, 5).map(Number);
const [outDir, only] = process.argv.slice(5, 7);
const samplers = {
  "poisson-disk-sampling": () =>
    new (require("poisson-disk-sampling"))({ shape: [side, side], minDistance: r }),
  "fast-2d-poisson-disk-sampling": () =>
    new (require("fast-2d-poisson-disk-sampling"))({ shape: [side, side], radius: r }),
};
const result = {};
for (const [name, make] of Object.entries(samplers)) {
  if (only && name !== only) continue;
  const cpu = [], wall = [];
  let points = [];
  for (let run = 0; run < runs; ++run) {
    const c0 = process.cpuUsage(), t0 = performance.now();
    points = make().fill();
    const c = process.cpuUsage(c0);
    wall.push((performance.now() - t0) / 1e3);
    cpu.push((c.user + c.system) / 1e6);
  }
  const xy = new Float64Array(2 * points.length);
  points.forEach((p, i) => { xy[2 * i] = p[0]; xy[2 * i + 1] = p[1]; });
  writeFileSync(join(outDir, name + ".bin"), Buffer.from(xy.buffer));
  result[name] = { count: points.length, cpu_s: cpu, wall_s: wall };
}
console.log(JSON.stringify(result));
