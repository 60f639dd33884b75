// Validates every .glb under a directory with the Khronos glTF validator; prints each file's
// error count and exits 1 when any file has errors.
import { readFileSync, readdirSync, statSync } from "node:fs";
import { join } from "node:path";
import validator from "gltf-validator";

function* glbs(dir) {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) yield* glbs(path);
    else if (name.endsWith(".glb")) yield path;
  }
}

let failed = 0, count = 0;
for (const path of glbs(process.argv[2])) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(path)));
  count++;
  if (report.issues.numErrors > 0) {
    failed++;
    console.log(path, JSON.stringify(report.issues.messages.filter((m) => m.severity === 0)));
  }
}
console.log(`${count} GLB files, ${failed} with errors`);
process.exit(failed > 0 || count === 0 ? 1 : 0);
