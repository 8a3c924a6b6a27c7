#!/usr/bin/env bash
# Installs the Khronos glTF-Validator (npm package gltf-validator, pinned) and three.js (npm
# `three`, pinned: its GLTFLoader is the stock loader the export is checked with,
# stock_loader_three.mjs) into DIR, a git-ignored folder in the build tree (the export tests look
# in <build>/gltf-validator):
#   tests/export/install_validator.sh build/gltf-validator
# Needs node and npm (Debian: apt-get install nodejs npm) and the npm registry.
set -euo pipefail
VERSION=2.0.0-dev.3.10
dir=${1:?usage: install_validator.sh DIR}
if ! command -v npm >/dev/null || ! command -v node >/dev/null; then
    echo "install_validator.sh: node and npm are missing. Install them, then run this again:" >&2
    echo "  sudo apt-get install -y nodejs npm" >&2
    exit 1
fi
# require() takes a path only when it is absolute (a bare relative one names a package).
dir=$(realpath -m "$dir")
THREE_VERSION=0.160.0
installed=$(node -p "require('$dir/node_modules/gltf-validator/package.json').version" 2>/dev/null || true)
three=$(node -p "require('$dir/node_modules/three/package.json').version" 2>/dev/null || true)
if [ "$installed" = "$VERSION" ] && [ "$three" = "$THREE_VERSION" ]; then
    exit 0
fi
mkdir -p "$dir"
npm install --prefix "$dir" --no-audit --no-fund --loglevel=error "gltf-validator@$VERSION" \
    "three@$THREE_VERSION"
