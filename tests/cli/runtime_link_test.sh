#!/usr/bin/env bash
# The reference runtime links with only its stated dependencies (issue 28): runtime_link_check,
# which links grass_runtime alone, needs none of the editor's libraries at run time and reads a
# raw export of the tiny project.
#   runtime_link_test.sh GRASS LINK_CHECK PROJECT WORK_DIR
set -u
grass=$1 check=$2 project=$3 work=$4
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf -- "$work" && mkdir -p -- "$work" || fail "cannot make $work"
needed=$(ldd "$check") || fail "ldd $check"
for library in OpenImageIO OpenMesh tinygltf draco meshoptimizer glfw; do
  if echo "$needed" | grep -qi "$library"; then fail "the runtime pulls in $library:
$needed"; fi
done
echo "$needed" | grep -q libepoxy || fail "the runtime's GL loader (libepoxy) is not linked:
$needed"
"$grass" export "$project" --format raw --out "$work/export" > "$work/export.txt" 2>&1 ||
  { cat "$work/export.txt" >&2; fail "grass export"; }
"$check" "$work/export" || fail "runtime_link_check could not read the export"
echo "runtime links: $(echo "$needed" | awk '{print $1}' | tr '\n' ' ')"
