#!/usr/bin/env bash
# The GPU checks of issue 29 item 4, run on a machine with a GPU driver (no Debian libraries,
# no display), from the repository root with .gpu/ made by .ci/gpu/pack.py beside it:
#   1. grass render of the default project through the GPU's own EGL (the headless context
#      finds the driver's EGL vendor file itself; the tessellation path `auto` picks on a GPU)
#   2. grass bench: 100k, 1M (also at 1080p) and 10M blades, and the 1M and 10M cases again with
#      the per-blade compute passes in groups of 256 (GRASS_COMPUTE_GROUP) instead of 32
#   3. the GL test suite
#   4. grass tradeoff on one scene, grass sim on the CPU's threads
# Everything lands in $OUT (default /tmp/gpu-out): run.log, the bench JSON, and results.tgz.
# Here: `ninja -C build grass grass_gl_tests && .ci/gpu/pack.py`; there, with .gpu carried along:
# `bash .ci/gpu/run.sh` (all steps in about a minute on an H200; docs/gpu-h200/ holds the last).
# Each step has its own time limit and the whole run a deadline (GPU_DEADLINE_S, default 420),
# so one hung step cannot eat the others.
set -u
ROOT=$PWD
OUT=${OUT:-/tmp/gpu-out}
WORK=/tmp/gpu-work
DEADLINE=$((SECONDS + ${GPU_DEADLINE_S:-420}))
mkdir -p "$OUT" "$WORK"
exec > >(tee "$OUT/run.log") 2>&1

# The binaries look for shaders and test data where they were built.
src=$(cat "$ROOT/.gpu/source_dir")
if [ -n "$src" ] && [ ! -e "$src/shaders" ]; then mkdir -p "$(dirname "$src")"; ln -sfn "$ROOT" "$src"; fi
export GRASS_SHADER_DIR=$ROOT/shaders
export LD_LIBRARY_PATH=$ROOT/.gpu/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}

# Debian 12's glibc 2.36 and GCC 12's libstdc++: the machine's own when new enough.
LOADER=()
glibc=$(getconf GNU_LIBC_VERSION | awk '{print $2}')
if [ "$(printf '%s\n2.36\n' "$glibc" | sort -V | head -1)" != "2.36" ]; then
    LOADER=("$ROOT/.gpu/compat/ld-linux-x86-64.so.2" --library-path "$ROOT/.gpu/compat:$LD_LIBRARY_PATH")
    echo "glibc $glibc is older than 2.36: running through the packed loader"
else
    stdcxx=$(ldconfig -p | awk '/libstdc\+\+\.so\.6 .*x86-64/ {print $NF; exit}')
    if [ -z "$stdcxx" ] || ! grep -aq GLIBCXX_3.4.30 "$stdcxx"; then
        export LD_LIBRARY_PATH=$LD_LIBRARY_PATH:$ROOT/.gpu/compat-cxx
        mkdir -p "$ROOT/.gpu/compat-cxx"
        cp "$ROOT/.gpu/compat/libstdc++.so.6" "$ROOT/.gpu/compat/libgcc_s.so.1" "$ROOT/.gpu/compat-cxx/"
        echo "libstdc++ older than GCC 12's: using the packed one"
    fi
fi

# The UI font where ui/font.cpp looks for it (the machine has no fonts-dejavu-core).
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
if [ ! -f "$font" ]; then mkdir -p "$(dirname "$font")" && cp "$ROOT/.gpu/fonts/DejaVuSans.ttf" "$font"; fi

# GPU_STEPS (comma-separated names below; default all) picks the steps of a rerun.
want() { [ -z "${GPU_STEPS:-}" ] || [[ ",$GPU_STEPS," == *",$1,"* ]]; }

step() {  # step NAME LIMIT_S COMMAND...: runs within its limit and the run's deadline
    local name=$1 limit=$2; shift 2
    want "$name" || return 0
    local left=$((DEADLINE - SECONDS))
    if [ "$left" -lt 10 ]; then echo "== $name: skipped, the run's deadline is near"; return 1; fi
    [ "$limit" -gt "$left" ] && limit=$left
    echo "== $name (limit ${limit} s): $*"
    local start=$SECONDS
    timeout -k 5 "$limit" "$@"
    local rc=$?
    echo "== $name: exit $rc after $((SECONDS - start)) s"
    return $rc
}
G=("${LOADER[@]}" "$ROOT/.gpu/bin/grass")
T=("${LOADER[@]}" "$ROOT/.gpu/bin/grass_gl_tests")

echo "== machine"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv 2>&1
nproc; getconf GNU_LIBC_VERSION; uname -r
ls /usr/local/nvidia/share/glvnd/egl_vendor.d /usr/share/glvnd/egl_vendor.d 2>&1

# 1. The headless context on the GPU, first as a user would start it (no EGL variables).
if ! step render 90 "${G[@]}" render projects/nature --out "$WORK/nature_gpu.png" --stats "$WORK/render_stats.json"; then
    echo "== the headless context needed the vendor file named: __EGL_VENDOR_LIBRARY_FILENAMES"
    export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
    step render-named-vendor 90 "${G[@]}" render projects/nature --out "$WORK/nature_gpu.png" --stats "$WORK/render_stats.json"
fi
step render-1080p 60 "${G[@]}" render projects/helicopter --width 1920 --height 1080 --out "$WORK/helicopter_gpu.png" --stats "$WORK/render_helicopter_stats.json"

# 2. grass bench at 720p, then the million drawn blades at 1080p, then ten million.
step bench 150 "${G[@]}" bench --cases nature-100k,nature-100k-all,helicopter-100k,winter-100k,nature-1m,helicopter-1m,nature-1m-all \
    --frames 20 --frames-1m 10 --steps 50 --steps-1m 20 --out "$OUT/bench_gpu.json"
step bench-1080p 60 "${G[@]}" bench --cases nature-1m,nature-1m-all,nature-1m-hybrid --width 1920 --height 1080 --msaa 0 \
    --frames-1m 10 --steps-1m 20 --out "$OUT/bench_gpu_1080p.json"
step bench-1080p-strips 40 "${G[@]}" bench --cases nature-1m,nature-1m-all --width 1920 --height 1080 --msaa 0 \
    --geometry strips --frames-1m 10 --steps-1m 5 --out "$OUT/bench_gpu_1080p_strips.json"
step bench-10m 120 "${G[@]}" bench --cases nature-10m --frames-1m 5 --steps-1m 10 --out "$OUT/bench_gpu_10m.json"
# 2b. The same with the per-blade compute passes in work groups of 256 instead of 32
# (GRASS_COMPUTE_GROUP, core/util/blade_pass_group.h), on the same warm machine:
# `grass bench --results bench_gpu_groups256.json --compare bench_gpu_10m.json` (and the 1M cases
# against bench_gpu.json).
step bench-groups-256 150 env GRASS_COMPUTE_GROUP=256 "${G[@]}" bench --cases nature-1m,helicopter-1m,nature-10m \
    --frames-1m 5 --steps-1m 10 --out "$OUT/bench_gpu_groups256.json"

# 3. The GL tests (goldens were made on llvmpipe: a GPU rasterises edges differently).
# The editor's tests need grass-editor and an X server, which the pack does not carry.
step gl-tests 150 "${T[@]}" --gtest_brief=1 --gtest_output=json:"$WORK/gl_tests.json" \
    --gtest_filter=-EditorScreenshotTest.*:EditorScript.*:EditorTime.*
cp -r /tmp/grass-tests/golden "$WORK/golden-actual" 2>/dev/null

# 4. The quality knobs on one scene, and the CPU physics on this machine's cores.
step tradeoff 60 "${G[@]}" tradeoff projects/meadow --out "$WORK/tradeoff" --frames 5
step sim-cpu 30 "${G[@]}" sim projects/nature --backend cpu --threads "$(nproc)" --seconds 2
step sim-gpu 30 "${G[@]}" sim projects/nature --backend gpu --seconds 2
step sim-gpu-256 30 env GRASS_COMPUTE_GROUP=256 "${G[@]}" sim projects/nature --backend gpu --seconds 2

# 5. Where nature's GPU physics step goes (a constant ~1.5 ms at 100k blades, helicopter's is
# 0.05): the same project without its colliders, without its wind, without both.
variant() {  # variant NAME: a copy of projects/nature with one part emptied
    local dir=$WORK/nature-$1
    mkdir -p "$dir" && cp projects/nature/bunny.glb "$dir/"
    case $1 in
      no-colliders) sed '/"colliders": \[/,$d' projects/nature/project.json > "$dir/project.json"
                    echo '  "colliders": []}' >> "$dir/project.json" ;;
      no-wind) sed '/"wind": \[/,/^  \],/c\  "wind": [],' projects/nature/project.json > "$dir/project.json" ;;
      bare) sed '/"wind": \[/,/^  \],/c\  "wind": [],' projects/nature/project.json |
              sed '/"colliders": \[/,$d' > "$dir/project.json"
            echo '  "colliders": []}' >> "$dir/project.json" ;;
      few-spheres) sed 's/"spheres": 1000/"spheres": 100/' projects/nature/project.json > "$dir/project.json" ;;
      collider-aloft) sed 's/\("position": \[[-0-9.]*, \)[0-9.]*\(, 9.0\]\)/\150.0\2/' \
                        projects/nature/project.json > "$dir/project.json" ;;
    esac
    echo "$dir"
}
# few-spheres: the bunny packed in 100 spheres; collider-aloft: its path 50 m up, out of every
# blade's reach (what is left is the per-step cost of having a collider at all).
for v in no-colliders no-wind bare few-spheres collider-aloft; do
    step "sim-gpu-$v" 30 "${G[@]}" sim "$(variant $v)" --backend gpu --seconds 2
done
step sim-gpu-helicopter 30 "${G[@]}" sim projects/helicopter --backend gpu --seconds 2

tar czf "$OUT/results.tgz" -C "$WORK" . 2>/dev/null
echo "== done in $SECONDS s"
