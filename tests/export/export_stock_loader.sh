#!/usr/bin/env bash
# Exports a project as glTF and as raw, then loads the glTF with three.js' GLTFLoader (a stock
# third-party loader) and checks what it draws against the raw export's exact blades
# (stock_loader_three.mjs); fails (never skips) when node or the packages are missing.
#   export_stock_loader.sh GRASS VALIDATOR_DIR OUT_DIR PROJECT [gltf|glb]
set -u
[ $# -ge 4 ] || { echo "usage: export_stock_loader.sh GRASS VALIDATOR_DIR OUT_DIR PROJECT [gltf|glb]" >&2; exit 2; }
grass=$1 validatorDir=$2 outDir=$3 project=$4 format=${5:-gltf}
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v node >/dev/null; then
    echo "FAIL: node is missing: sudo apt-get install -y nodejs npm, then $here/install_validator.sh $validatorDir"
    exit 1
fi
rm -rf -- "$outDir"
"$grass" export "$project" --format "$format" --out "$outDir/gltf" >/dev/null || { echo "FAIL: grass export ($format) exited with $?"; exit 1; }
"$grass" export "$project" --format raw --out "$outDir/raw" >/dev/null || { echo "FAIL: grass export (raw) exited with $?"; exit 1; }
shopt -s nullglob
files=("$outDir"/gltf/*."$format")
[ ${#files[@]} -eq 1 ] || { echo "FAIL: expected one .$format in $outDir/gltf, found ${#files[@]}"; exit 1; }
GLTF_VALIDATOR_DIR=$validatorDir node "$here/stock_loader_three.mjs" "${files[0]}" "$outDir/raw"
