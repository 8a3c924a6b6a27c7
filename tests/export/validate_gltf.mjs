// Validates a .gltf or .glb file with the Khronos glTF-Validator (npm package gltf-validator),
// loading its external buffers and images from the file's folder. Prints the report's issues
// and exits 1 on any error (or, with --strict, any warning), 2 when the validator cannot run.
//   node validate_gltf.mjs [--strict] FILE
// The validator is looked up in GLTF_VALIDATOR_DIR (a folder holding node_modules/, what
// install_validator.sh fills) or by Node's own resolution.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const args = process.argv.slice(2);
const strict = args.includes('--strict');
const file = args.find((a) => a !== '--strict');
if (!file) {
    console.error('usage: node validate_gltf.mjs [--strict] FILE.gltf|FILE.glb');
    process.exit(2);
}

let validator;
try {
    const base = process.env.GLTF_VALIDATOR_DIR
        ? path.join(path.resolve(process.env.GLTF_VALIDATOR_DIR), 'package.json')
        : import.meta.url;
    validator = createRequire(base)('gltf-validator');
} catch (error) {
    console.error(`validate_gltf: gltf-validator is not installed (${error.code ?? error}); ` +
        'run tests/export/install_validator.sh <build-dir>/gltf-validator');
    process.exit(2);
}

const fullPath = path.resolve(file);
let bytes;
try {
    bytes = new Uint8Array(fs.readFileSync(fullPath));
} catch (error) {
    console.error(`validate_gltf: ${file}: ${error.message}`);
    process.exit(2);
}

const report = await validator.validateBytes(bytes, {
    uri: path.basename(fullPath),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
        new Promise((resolve, reject) => {
            const resource = path.resolve(path.dirname(fullPath), decodeURIComponent(uri));
            fs.readFile(resource, (error, data) =>
                error ? reject(error.toString()) : resolve(new Uint8Array(data)));
        }),
});

const SEVERITY = ['error', 'warning', 'info', 'hint'];
for (const message of report.issues.messages)
    console.log(`${SEVERITY[message.severity]} ${message.code} ${message.pointer ?? ''}: ` +
        message.message);
const { numErrors, numWarnings, numInfos, numHints } = report.issues;
console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ` +
    `${numHints} hints (glTF-Validator ${report.validatorVersion})`);
process.exit(numErrors > 0 || (strict && numWarnings > 0) ? 1 : 0);
