// Loads a glTF export with a stock third-party loader — three.js' GLTFLoader (npm `three`,
// installed by install_validator.sh), which honours EXT_mesh_gpu_instancing's TRANSLATION,
// ROTATION, SCALE and _COLOR_0 — and checks what it would draw against the exact blades of the
// same project's raw export (issue 25):
//   node stock_loader_three.mjs LAYER.gltf|PROJECT.glb RAW_DIR   (the first layer is checked)
// For every live blade: an instance at its root, the instance's mesh tip (world space, through
// the node hierarchy) within 10 % of the blade's height of the blade's tip in the median and
// 5 % at worst, its colour at the tip (instance colour × vertex colour) the blade's tip colour
// within 1e-4, and one InstancedMesh per cell, lean bin and wilt bin (more than one). Prints the figures;
// exits 1 on a failed check.
import fs from 'node:fs';
import path from 'node:path';

// three's FileLoader reports progress with ProgressEvent, which Node does not have.
globalThis.ProgressEvent ??= class ProgressEvent extends Event {
    constructor(type, init = {}) {
        super(type);
        Object.assign(this, init);
    }
};

const [gltfFile, rawDir] = process.argv.slice(2);
if (!gltfFile || !rawDir) {
    console.error('usage: node stock_loader_three.mjs LAYER.gltf RAW_DIR');
    process.exit(2);
}
const modules = process.env.GLTF_VALIDATOR_DIR
    ? path.join(path.resolve(process.env.GLTF_VALIDATOR_DIR), 'node_modules')
    : null;
if (!modules || !fs.existsSync(path.join(modules, 'three/package.json'))) {
    console.error('FAIL: three is not installed: run tests/export/install_validator.sh DIR and set GLTF_VALIDATOR_DIR=DIR');
    process.exit(1);
}
const THREE = await import(path.join(modules, 'three/build/three.module.js'));
const { GLTFLoader } = await import(path.join(modules, 'three/examples/jsm/loaders/GLTFLoader.js'));

// A .glb goes in as it is. A .gltf's loader fetches the buffer; Node's fetch reads data: URLs
// but not files, so the buffer goes in as one (the document is otherwise as exported).
let input;
if (gltfFile.endsWith('.glb')) {
    const bytes = fs.readFileSync(gltfFile);
    input = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
} else {
    const json = JSON.parse(fs.readFileSync(gltfFile, 'utf8'));
    for (const buffer of json.buffers) {
        const bytes = fs.readFileSync(path.join(path.dirname(gltfFile), buffer.uri));
        buffer.uri = 'data:application/octet-stream;base64,' + bytes.toString('base64');
    }
    input = JSON.stringify(json);
}
const gltf = await new Promise((resolve, reject) => new GLTFLoader().parse(input, '', resolve, reject));
gltf.scene.updateMatrixWorld(true);

// The exact blades: 64-byte records (v0, θ) (v1, h) (v2, w) (up, s), and the wilt per slot.
const manifest = JSON.parse(fs.readFileSync(path.join(rawDir, 'manifest.json'), 'utf8'));
const layer = manifest.layers[0];
const blades = new Float32Array(fs.readFileSync(path.join(rawDir, layer.blades.file)).buffer.slice(0));
const wilt = new Float32Array(fs.readFileSync(path.join(rawDir, layer.wilt.file)).buffer.slice(0));
const key = (x, y, z) => `${Math.fround(x)},${Math.fround(y)},${Math.fround(z)}`;
const exact = new Map();
for (let slot = 0; slot < blades.length / 16; ++slot) {
    const b = blades.subarray(16 * slot, 16 * slot + 16);
    if (!(b[7] > 0 && b[11] > 0)) continue;  // h, w: padding and removed blades are null
    exact.set(key(b[0], b[1], b[2]), { v2: [b[8], b[9], b[10]], h: b[7], wilt: wilt[slot] });
}
const mix = (a, b, t) => a.map((x, i) => x + (b[i] - x) * t);

let meshes = 0, drawn = 0, missing = 0, worstColour = 0;
const tipErrors = [];
const matrix = new THREE.Matrix4(), world = new THREE.Matrix4();
const root = new THREE.Vector3(), tip = new THREE.Vector3(), colour = new THREE.Color();
gltf.scene.traverse((object) => {
    if (!object.isInstancedMesh) return;
    ++meshes;
    const position = object.geometry.attributes.position;
    // No COLOR_0: the loader shades with white (what an export before issue 25 showed).
    const vertexColour = object.geometry.attributes.color ??
        { getX: () => 1, getY: () => 1, getZ: () => 1 };
    const last = position.count - 1;  // the top row's last vertex: rows run root to tip
    for (let i = 0; i < object.count; ++i) {
        object.getMatrixAt(i, matrix);
        world.multiplyMatrices(object.matrixWorld, matrix);
        root.set(0, 0, 0).applyMatrix4(world);
        const blade = exact.get(key(root.x, root.y, root.z));
        if (!blade) { ++missing; continue; }
        ++drawn;
        tip.set(0, position.getY(last), position.getZ(last)).applyMatrix4(world);
        tipErrors.push(Math.hypot(tip.x - blade.v2[0], tip.y - blade.v2[1], tip.z - blade.v2[2]) / blade.h);
        object.getColorAt(i, colour);
        const shown = [colour.r * vertexColour.getX(last), colour.g * vertexColour.getY(last),
                       colour.b * vertexColour.getZ(last)];
        const expected = mix(layer.colors.tip, layer.colors.poor_tip, blade.wilt);
        worstColour = Math.max(worstColour, ...shown.map((c, k) => Math.abs(c - expected[k])));
    }
});
tipErrors.sort((a, b) => a - b);
const median = tipErrors.length ? tipErrors[tipErrors.length >> 1] : Infinity;
const worst = tipErrors.length ? tipErrors[tipErrors.length - 1] : Infinity;
console.log(`three ${THREE.REVISION}: ${meshes} instanced meshes, ${drawn} of ${exact.size} blades ` +
            `drawn (${missing} instances at no blade's root); tip error / h median ${median.toFixed(4)}, ` +
            `worst ${worst.toFixed(4)}; tip colour error ${worstColour.toExponential(2)}`);
const failures = [];
if (drawn !== exact.size || missing) failures.push('every live blade must be exactly one instance');
if (!(median <= 0.1)) failures.push(`median tip error ${median} > 0.1 h`);
if (!(worst <= 0.05)) failures.push(`worst tip error ${worst} > 0.05 h`);
if (!(worstColour <= 1e-4)) failures.push(`tip colour off by ${worstColour}`);
if (!(meshes > 1)) failures.push('one instanced mesh: nothing for an engine to cull');
for (const f of failures) console.log(`FAIL: ${f}`);
process.exit(failures.length ? 1 : 0);
