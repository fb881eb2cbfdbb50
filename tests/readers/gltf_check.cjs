// SPDX-License-Identifier: GPL-3.0-or-later
// Validates a glTF 2.0 file (.glb, or .gltf with its external buffers) with the Khronos glTF
// validator (npm `gltf-validator`) and prints its report's issues as JSON.
// Exit status: 0 no error and no warning, 1 errors or warnings, 2 usage.
// Usage: node tests/readers/gltf_check.cjs FILE.glb|FILE.gltf
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require(path.join(__dirname, 'node_modules', 'gltf-validator'));

async function main() {
  if (process.argv.length !== 3) {
    console.error('usage: node gltf_check.cjs FILE.glb|FILE.gltf');
    process.exit(2);
  }
  const file = process.argv[2];
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (error, data) =>
          error ? reject(error.toString()) : resolve(new Uint8Array(data)));
      }),
  });
  const issues = report.issues;
  const out = { errors: issues.numErrors, warnings: issues.numWarnings, infos: issues.numInfos,
    hints: issues.numHints, messages: issues.messages, info: report.info };
  process.stdout.write(JSON.stringify(out) + '\n');
  process.exit(issues.numErrors === 0 && issues.numWarnings === 0 ? 0 : 1);
}
main().catch((e) => { process.stderr.write(`gltf_check: ${e.stack || e}\n`); process.exit(1); });
