#!/usr/bin/env bash
# Exports a project as glTF and runs the Khronos glTF-Validator on every .gltf written; fails
# (never skips) when node or the validator is missing, saying how to install them.
#   export_and_validate.sh GRASS VALIDATOR_DIR OUT_DIR PROJECT [grass export options]...
# VALIDATOR_DIR is where install_validator.sh put gltf-validator (<build>/gltf-validator).
set -u
[ $# -ge 4 ] || { echo "usage: export_and_validate.sh GRASS VALIDATOR_DIR OUT_DIR PROJECT [OPTION]..." >&2; exit 2; }
grass=$1 validatorDir=$2 outDir=$3 project=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)

if ! command -v node >/dev/null; then
    echo "FAIL: node is missing: sudo apt-get install -y nodejs npm, then $here/install_validator.sh $validatorDir"
    exit 1
fi
if [ ! -f "$validatorDir/node_modules/gltf-validator/package.json" ]; then
    echo "FAIL: the glTF validator is not installed in $validatorDir: run $here/install_validator.sh $validatorDir (or ./quickstart.sh test)"
    exit 1
fi

rm -rf -- "$outDir"
start=$(date +%s%N)
"$grass" export "$project" --out "$outDir" "$@" || { echo "FAIL: grass export exited with $?"; exit 1; }
end=$(date +%s%N)
echo "export took $(((end - start) / 1000000)) ms"

shopt -s nullglob
files=("$outDir"/*.gltf "$outDir"/*.glb)
if [ ${#files[@]} -eq 0 ]; then
    echo "FAIL: no .gltf or .glb file in $outDir"
    exit 1
fi
status=0
for file in "${files[@]}"; do
    # --strict: warnings fail too; docs/export.md promises none (infos are expected).
    GLTF_VALIDATOR_DIR=$validatorDir node "$here/validate_gltf.mjs" --strict "$file" || status=1
done
exit $status
