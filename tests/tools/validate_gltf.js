// validate_gltf.js — runs the Khronos glTF validator (npm gltf-validator,
// installed into the build folder by install_gltf_validator.sh) on one file.
//
//   node validate_gltf.js VALIDATOR_PREFIX FILE.gltf
//
// Reads FILE (and any external buffer it names, relative to it) and
// VALIDATOR_PREFIX/node_modules/gltf-validator. Prints the number of
// errors, warnings, infos and hints, then every message (severity, code,
// pointer, message). Exit 0 when the report has no errors, 1 when it has some, 2 when
// the validator could not run (missing package, unreadable file).
'use strict';
const fs = require('fs');
const path = require('path');

if (process.argv.length !== 4) {
    console.error('usage: node validate_gltf.js VALIDATOR_PREFIX FILE.gltf');
    process.exit(2);
}
const prefix = path.resolve(process.argv[2]);
const file = path.resolve(process.argv[3]);
let validator;
try {
    validator = require(path.join(prefix, 'node_modules', 'gltf-validator'));
} catch (e) {
    console.error(`validate_gltf.js: no gltf-validator under ${prefix} (tests/tools/install_gltf_validator.sh): ${e}`);
    process.exit(2);
}
let bytes;
try {
    bytes = fs.readFileSync(file);
} catch (e) {
    console.error(`validate_gltf.js: cannot read ${file}: ${e}`);
    process.exit(2);
}

validator.validateBytes(new Uint8Array(bytes), {
    uri: path.basename(file),
    maxIssues: 0,  // all of them
    writeTimestamp: false,
    externalResourceFunction: (uri) => new Promise((resolve, reject) => {
        fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) => {
            if (err) reject(err.toString()); else resolve(new Uint8Array(data));
        });
    }),
}).then((report) => {
    const issues = report.issues;
    console.log(`${file}: gltf-validator ${validator.version()}: ${issues.numErrors} errors, ` +
                `${issues.numWarnings} warnings, ${issues.numInfos} infos, ${issues.numHints} hints`);
    for (const m of issues.messages) {
        const severity = ['error', 'warning', 'info', 'hint'][m.severity] || String(m.severity);
        console.log(`  ${severity} ${m.code} at ${m.pointer || '/'}: ${m.message}`);
    }
    process.exit(issues.numErrors > 0 ? 1 : 0);
}, (error) => {
    console.error(`validate_gltf.js: ${file}: the validator could not read it: ${error}`);
    process.exit(2);
});
