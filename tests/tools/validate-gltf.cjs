// SPDX-License-Identifier: GPL-3.0-or-later
// node validate-gltf.cjs FILE.glb: the Khronos glTF validator (npm package gltf-validator, with
// NODE_PATH at the global modules) on FILE; prints its issues as JSON, exits 1 on any error
// and 3 when the validator is not installed.
let validator;
try {
    validator = require('gltf-validator');
} catch (e) {
    console.error('gltf-validator is not installed (npm install -g gltf-validator)');
    process.exit(3);
}
const fs = require('fs');
const data = new Uint8Array(fs.readFileSync(process.argv[2]));
validator.validateBytes(data, {maxIssues: 100})
    .then((report) => {
        console.log(JSON.stringify(report.issues));
        process.exit(report.issues.numErrors > 0 ? 1 : 0);
    })
    .catch((error) => {
        console.error(String(error));
        process.exit(2);
    });
