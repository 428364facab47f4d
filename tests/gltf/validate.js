// Validate glTF / GLB files with the Khronos glTF validator (npm gltf-validator).
// usage: node tests/gltf/validate.js FILE...
// Prints every error and warning; exits 1 when any file has an error, 2 on a usage problem.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function main(files) {
    if (files.length === 0) {
        console.error('usage: node tests/gltf/validate.js FILE...');
        return 2;
    }
    let failed = 0;
    for (const file of files) {
        const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
            uri: path.basename(file),
            maxIssues: 100,
        });
        const { numErrors, numWarnings, numInfos, numHints } = report.issues;
        console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints` +
            ` (${report.info ? report.info.drawCallCount + ' draw calls, ' + report.info.animationCount + ' animations' : ''})`);
        for (const m of report.issues.messages) {
            if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer || '-'}: ${m.message}`);
        }
        if (numErrors > 0) failed++;
    }
    return failed ? 1 : 0;
}

main(process.argv.slice(2)).then((code) => process.exit(code), (err) => {
    console.error(err);
    process.exit(1);
});
