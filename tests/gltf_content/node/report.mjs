// Validates one GLB with the Khronos glTF validator installed in the directory given first
// (tests/tiles3d's node_modules); prints its errors and warnings as JSON lines, then their
// counts.
import { createRequire } from "node:module";
import { readFileSync } from "node:fs";

const require = createRequire(process.argv[2] + "/node_modules/");
const validator = require("gltf-validator");
const report = await validator.validateBytes(new Uint8Array(readFileSync(process.argv[3])));
for (const m of report.issues.messages)
  if (m.severity <= 1)
    console.log(JSON.stringify({ severity: m.severity, code: m.code, message: m.message,
                                 pointer: m.pointer }));
console.log(JSON.stringify({ errors: report.issues.numErrors,
                             warnings: report.issues.numWarnings }));
