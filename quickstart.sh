#!/usr/bin/env bash
# grass quick start: installs what is missing (as root) or says what to install, builds, then
#   ./quickstart.sh run    opens the editor on projects/meadow (or, with no display, renders it
#                          headless after 5 s of its physics to build/meadow.png, with timings)
#   ./quickstart.sh test   runs the whole test suite (what CI runs: .ci/run), then fuzzes every
#                          file reader for a bounded time (tests/fuzz/README.md) and runs the
#                          unit tests again under AddressSanitizer and UBSan
set -euo pipefail
cd "$(dirname "$0")"

mode="${1:-}"
case "$mode" in
  run|test) ;;
  *) echo "usage: ./quickstart.sh run|test" >&2; exit 2 ;;
esac

# Debian 12 packages: toolchain, the libraries of the design card, Mesa for headless GL, Xvfb
# and xdotool for the editor's window tests (real X input; libx11-dev for their close button),
# gnuplot for the plots of `grass tradeoff`, python3 for test scripts (fuzz seeds, reading a painted PNG back).
packages=(g++ cmake ninja-build pkg-config ccache
  libglfw3-dev libglm-dev libtinygltf-dev libopenmesh-dev libopenimageio-dev libepoxy-dev
  libegl-dev libegl-mesa0 libgl1-mesa-dri nlohmann-json3-dev libgtest-dev libbenchmark-dev
  libstb-dev fonts-dejavu-core xvfb xauth xdotool gnuplot-nox libdraco-dev libmeshoptimizer-dev
  libhwy-dev libx11-dev python3)
# The export tests validate glTF files with the Khronos glTF-Validator, an npm package. Node
# from elsewhere (nodesource's nodejs bundles npm) will do, so look for the commands first.
if [ "$mode" = test ] && ! { command -v node && command -v npm; } >/dev/null; then
  packages+=(nodejs npm)
fi
# The fuzz stage of the tests builds core with clang and links libFuzzer (tests/fuzz/README.md).
if [ "$mode" = test ]; then
  packages+=(clang libclang-rt-14-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [ "$(id -u)" = 0 ]; then
    echo "== installing ${#missing[@]} missing Debian packages: ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
  else
    echo "Missing Debian packages. Install them, then run this again:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

jobs=$(nproc 2>/dev/null || echo 2)
# ccache keeps the compiled objects of earlier runs (~/.cache/ccache): a second run on the same
# machine, or CI on a machine that keeps its cache, recompiles only what changed.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
echo "== configuring and building (build/, $jobs jobs)"
# Without debug information: it cost a third of the build's time (CMakeLists.txt).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRASS_WERROR=ON \
  -DGRASS_DEBUG_INFO=OFF "${launcher[@]}" >/dev/null
cmake --build build -j "$jobs"

if [ "$mode" = run ]; then
  if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    exec build/bin/grass-editor projects/meadow
  fi
  echo "== no display: simulating 5 s of projects/meadow (wind, rolling ball) and rendering it headless"
  exec build/bin/grass render projects/meadow --time 5 --out build/meadow.png
fi

echo "== installing the glTF validator (npm gltf-validator) into build/gltf-validator"
tests/export/install_validator.sh build/gltf-validator

echo "== running the tests"
status=0
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 600 || status=1

# Every file reader under libFuzzer (tests/fuzz/README.md): core built again with clang, ASan,
# UBSan and coverage in build-fuzz/; the kept regression inputs and seeds run once, then each
# target is fuzzed for GRASS_FUZZ_SECONDS (default 20 s: 11 targets, $jobs at a time). Any
# crash, leak, hang or sanitizer report fails the suite. The same build then runs the unit tests.
fuzz_seconds="${GRASS_FUZZ_SECONDS:-20}"
echo "== fuzzing the file readers (build-fuzz/, clang, ${fuzz_seconds} s per target)"
if cmake -S tests/fuzz -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" >/dev/null && cmake --build build-fuzz -j "$jobs"; then
  tests/fuzz/run_fuzz.sh -j "$jobs" build-fuzz "$fuzz_seconds" || status=1
  # The same build holds the unit tests of core and ui (no GL) under these sanitizers; the whole
  # suite, GL and command line included, runs under them in .ci/sanitize. They run in $jobs
  # gtest shards at once (each with its own scratch folder), about 6 min of work in all, most of
  # it ExtremeValues; bounded, so that a hang fails the run in 20 minutes instead of holding CI
  # to its limit. Each shard's report is printed when it ends.
  echo "== the unit tests under AddressSanitizer, LeakSanitizer and UBSan (build-fuzz/, $jobs shards)"
  shard_pids=()
  for ((shard = 0; shard < jobs; shard++)); do
    mkdir -p "build-fuzz/test-tmp/shard-$shard"
    GRASS_TEST_TMP="$PWD/build-fuzz/test-tmp/shard-$shard" UBSAN_OPTIONS=print_stacktrace=1 \
      LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0" \
      GTEST_TOTAL_SHARDS="$jobs" GTEST_SHARD_INDEX="$shard" \
      timeout -k 10 1200 build-fuzz/bin/sanitized_unit_tests --gtest_brief=1 \
      >"build-fuzz/sanitized-shard-$shard.log" 2>&1 &
    shard_pids+=($!)
  done
  for ((shard = 0; shard < jobs; shard++)); do
    wait "${shard_pids[$shard]}" || status=1
    echo "-- shard $((shard + 1)) of $jobs"
    cat "build-fuzz/sanitized-shard-$shard.log"
  done
else
  echo "fuzz and sanitizer build failed" >&2
  status=1
fi
exit "$status"
