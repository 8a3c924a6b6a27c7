#!/usr/bin/env bash
# Hostile files and careless paths (issue 22): one class of defect per run, each case a command
# a hostile or careless user could give. Every case that must fail goes through expect_error.sh
# (non-zero exit below 128, one stderr line naming what the case says); every case also checks
# the thing that must not happen (a command run, a file outside the work folder written, an
# input overwritten, a half-written file left). Prints "CLASS: N cases, 0 failed" when all pass.
#
#   hostile_input_test.sh GRASS_BIN DATA_DIR WORK_DIR CLASS
#
# CLASS: gnuplot | paths | disk_full | output_is_input | export_cleanup | special_files |
#        bounds | messages
set -u
bin=$1
data=$2
work=$3
class=$4
here=$(cd "$(dirname "$0")" && pwd)
expect_error=("$BASH" "$here/expect_error.sh")

rm -rf -- "$work" && mkdir -p -- "$work" || exit 2
cd "$work" || exit 2
cases=0
failed=0
fail() { echo "FAIL ($class): $*" >&2; failed=$((failed + 1)); }
case_() { cases=$((cases + 1)); }
# refused SUBSTRING [--also S]... -- COMMAND...: the command fails cleanly naming SUBSTRING.
refused() {
    case_
    local out
    out=$("${expect_error[@]}" "$@" 2>&1) || fail "$out"
}
# A fresh copy of a test project in $work/$1 from tests/data/projects/$2.
project() { rm -rf -- "$1" && cp -R -- "$data/projects/$2" "$1"; }
hash_of() { cat -- "$@" 2>/dev/null | md5sum; }
# Writes a project.json with one JSON edit (python-free: sed on the tiny project's text).
tiny_with() {  # tiny_with DIR SED_EXPRESSION
    project "$1" tiny && sed -i -e "$2" "$1/project.json"
}

case $class in
gnuplot)
    # Strings of tradeoff.json are data: a quote plus a newline, backquotes and a gnuplot
    # system command in every text field must not run anything.
    mkdir -p tr && marker=$work/pwned
    evil="x\\\"\\nsystem \\\"touch $marker\\\"\\n\`touch $marker\` '\\\\"
    for field in project device description cost_metric label; do
        rm -f -- "$marker"
        P=P D=D DESC=DESC C=C L=L
        case $field in
            project) P=$evil ;;
            device) D=$evil ;;
            description) DESC=$evil ;;
            cost_metric) C=$evil ;;
            label) L=$evil ;;
        esac
        printf '{"project":"%s","device":"%s","knobs":[{"name":"lod_distance","description":"%s","cost_metric":"%s","error_metric":"E","settings":[{"label":"%s","value":1,"cost_ms":{"median":1,"min":1,"max":1},"error":1,"pareto":true}]}]}\n' \
            "$P" "$D" "$DESC" "$C" "$L" >tr/tradeoff.json
        case_
        "$bin" tradeoff --replot tr >/dev/null 2>&1 || fail "replot with an evil $field exits $?"
        [ -e "$marker" ] && fail "a string in $field ran a command (gnuplot)"
        command -v gnuplot >/dev/null && [ ! -s tr/lod_distance.png ] &&
            fail "no plot drawn for an evil $field"
        rm -f tr/lod_distance.png
    done
    # Knob names become file names: only the known knobs are accepted.
    for name in "../escaped" "/tmp/abs" "a'b" "lod_distance/../../x" ""; do
        printf '{"project":"p","knobs":[{"name":"%s","settings":[]}]}\n' "$name" >tr/tradeoff.json
        refused "/knobs/0/name" --also "unknown knob" -- "$bin" tradeoff --replot tr
    done
    case_
    [ -e "$work/escaped.gp" ] || [ -e /tmp/abs.gp ] && fail "a knob name wrote outside DIR"
    ;;

paths)
    # A project name that is a path or holds control characters.
    tiny_with abs 's|"name": "tiny"|"name": "/tmp/grass-hostile-abs"|'
    case_
    rm -f /tmp/grass-hostile-abs.png
    "$bin" render abs >/dev/null 2>&1 || fail "render of a project named /abs/path failed"
    [ -e /tmp/grass-hostile-abs.png ] && fail "render wrote /tmp/grass-hostile-abs.png (outside)"
    [ -e "$work/_tmp_grass-hostile-abs.png" ] || fail "no sanitised default output in the cwd"
    tiny_with ctl 's|"name": "tiny"|"name": "a\\u001b[31mred\\nline"|'
    refused "/name" --also "control characters" -- "$bin" render ctl
    tiny_with nul 's|"name": "grass"|"name": "gr\\u0000ass"|'
    refused "/layers/0/name" --also "control characters" -- "$bin" sim nul --seconds 0
    # Symbolic links out of the project: mesh, collider mesh, map, a linked folder, a dangling
    # link, a glTF buffer.
    tiny_with linkmesh 's|"mesh": {[^}]*}|"mesh": {"file": "m.glb"}|' &&
        ln -s /etc/passwd linkmesh/m.glb
    refused "/mesh/file" --also "outside the project folder" -- "$bin" sim linkmesh --seconds 0
    project linkcollider rock && rm linkcollider/cube.glb &&
        ln -s "$data/projects/rock/cube.glb" linkcollider/cube.glb
    refused "/colliders/0/file" --also "outside the project folder" -- \
        "$bin" sim linkcollider --seconds 0
    mkdir -p outside && printf 'secret' >outside/secret.png && cp outside/secret.png outside/d.png
    tiny_with linkmap 's|"density_map": ""|"density_map": "maps/d.png"|'
    ln -s ../outside linkmap/maps
    refused "/layers/0/density_map" --also "outside the project folder" -- \
        "$bin" sim linkmap --seconds 0
    tiny_with dangling 's|"density_map": ""|"density_map": "d.png"|'
    ln -s "$work/outside/new.png" dangling/d.png
    refused "d.png" --also "outside the project folder" -- \
        "$bin" paint dangling --map density --stroke "0,0,0"
    case_
    [ -e outside/new.png ] && fail "paint wrote through a dangling link to outside"
    mkdir -p gl && ln -s /etc/hostname gl/buf.bin
    # A view reads the buffer (one that nothing reads is not opened at all).
    printf '{"asset":{"version":"2.0"},"buffers":[{"uri":"buf.bin","byteLength":4}],%s}' \
        '"bufferViews":[{"buffer":0,"byteLength":4}]' >gl/b.gltf
    refused "buffer 0" --also "outside the glTF file's folder" -- "$bin" mesh-info gl/b.gltf
    # Painting through a linked maps folder writes nothing outside either.
    case_
    before=$(hash_of outside/*)
    "$bin" paint linkmap --map density --stroke "0,0,0" >/dev/null 2>&1 &&
        fail "paint through a linked folder succeeded"
    [ "$before" = "$(hash_of outside/*)" ] || fail "paint changed a file outside"
    ;;

disk_full)
    # A write that fails part way (RLIMIT_FSIZE: writes past 2 KiB fail with EFBIG, as on a
    # full disk; SIGXFSZ ignored so the process sees the error) must fail the command and leave
    # the old file as it was: PNG, TIFF and EXR maps, renders, reports, exports, projects.
    limited() { (trap '' XFSZ; ulimit -f 2; exec "$@") >/dev/null 2>"$work/limited.err"; }
    for ext in png tif exr; do
        project "map$ext" growth_tiny
        "$bin" paint "map$ext" --map density --mode set --value 0.5 --radius 0.4 \
            --file "maps/d.$ext" --stroke "-0.8,0,-0.8; 0.5,0,0.6" >/dev/null 2>&1 ||
            fail "paint to a .$ext map fails without a limit"
        before=$(hash_of "map$ext/maps/d.$ext" "map$ext/project.json")
        case_
        limited "$bin" paint "map$ext" --map density --mode set --value 0.2 --radius 0.4 \
            --stroke "-0.8,0,-0.8; 0.5,0,0.6" && fail "paint onto a full disk (.$ext) exits 0"
        grep -q "d.$ext" "$work/limited.err" || fail "the .$ext error does not name the map"
        [ "$before" = "$(hash_of "map$ext/maps/d.$ext" "map$ext/project.json")" ] ||
            fail "a failed .$ext save changed the map or the project"
        [ -z "$(find "map$ext" -name '.*.tmp-*')" ] || fail "a temporary was left (.$ext)"
    done
    project r tiny
    for out in render.png render.exr; do
        head -c 100000 /dev/urandom >"$out" && before=$(hash_of "$out")
        case_
        limited "$bin" render r --width 256 --height 256 --out "$out" &&
            fail "render --out $out onto a full disk exits 0"
        [ "$before" = "$(hash_of "$out")" ] || fail "a failed render replaced $out"
    done
    # Reports: a long JSON (the soak's samples) past the limit.
    head -c 100000 /dev/urandom >soak.json && before=$(hash_of soak.json)
    case_
    limited "$bin" soak r --seconds 20 --sample-every 0.02 --backend cpu --report soak.json &&
        fail "soak --report onto a full disk exits 0"
    [ "$before" = "$(hash_of soak.json)" ] || fail "a failed report replaced soak.json"
    # An export: every file staged, none renamed when one fails.
    project e growth_tiny
    "$bin" export e --out exp >/dev/null 2>&1 || fail "export fails without a limit"
    before=$(hash_of exp/*)
    sed -i 's|"density": 60.0|"density": 500.0|' e/project.json
    case_
    limited "$bin" export e --out exp && fail "export onto a full disk exits 0"
    [ "$before" = "$(hash_of exp/*)" ] || fail "a failed export changed the folder"
    ;;

output_is_input)
    # An output path that is one of the project's own files is refused before any work.
    project p rock && project t tiny
    "$bin" paint t --map density --mode set --value 0.5 --stroke "0,0,0" >/dev/null 2>&1 ||
        fail "paint fails"
    before=$(hash_of t/project.json t/maps/grass-density.png p/project.json p/cube.glb)
    refused "--report" --also "t/project.json" --also "project file" -- \
        "$bin" sim t --seconds 0.1 --report t/project.json
    refused "--stats" --also "project file" -- "$bin" render t --stats t/project.json --out x.png
    refused "--report" --also "project file" -- \
        "$bin" soak t --seconds 1 --backend cpu --report t/./project.json
    refused "--out" --also "density_map" -- "$bin" render t --out t/maps/grass-density.png
    ln -s t/project.json alias.json
    refused "--report" --also "project file" -- "$bin" sim t --seconds 0 --report alias.json
    refused "--stats" --also "--mesh file" -- "$bin" render --mesh p/cube.glb --stats p/cube.glb
    # An export into the project folder whose layer file equals the mesh's name.
    project q rock && sed -i 's|"name": "grass"|"name": "cube"|' q/project.json &&
        mv q/cube.glb q/cube.gltf 2>/dev/null
    cp "$data/gltf/quad.gltf" q/cube.gltf && cp "$data/gltf/"quad*.bin q/ 2>/dev/null
    sed -i 's|"cube.glb"|"cube.gltf"|' q/project.json
    beforeQ=$(hash_of q/*)
    refused "cube.gltf" --also "/colliders/0/file" -- "$bin" export q --out q
    case_
    [ "$before" = "$(hash_of t/project.json t/maps/grass-density.png p/project.json p/cube.glb)" ] ||
        fail "an input was changed"
    [ "$beforeQ" = "$(hash_of q/*)" ] || fail "the export changed the project folder"
    ;;

export_cleanup)
    # The clean-up of an export folder reads every .gltf already there: a 50,000-level nest,
    # a huge one, a FIFO and /dev/zero under a .gltf name must neither crash nor hang it.
    project e growth_tiny && mkdir -p exp
    { printf '{"a":'; for _ in $(seq 5000); do printf '[[[[[[[[[['; done; printf '1';
      for _ in $(seq 5000); do printf ']]]]]]]]]]'; done; printf '}'; } >exp/deep.gltf
    mkfifo exp/fifo.gltf && ln -s /dev/zero exp/zero.gltf
    truncate -s 100M exp/big.gltf
    printf 'kept' >exp/other-0123456789abcdef.bin
    case_
    timeout 120 "$bin" export e --out exp >/dev/null 2>"$work/export.err"
    rc=$?
    [ $rc -eq 0 ] || fail "export beside hostile .gltf files exits $rc: $(cat "$work/export.err")"
    [ -s exp/grass.gltf ] || fail "the export wrote no grass.gltf"
    [ -e exp/other-0123456789abcdef.bin ] ||
        fail "a file was removed though an unreadable .gltf might name it"
    ;;

special_files)
    # Readers take regular files only and refuse one over its cap before reading it.
    mkdir -p z && ln -s /dev/zero z/project.json
    refused "z/project.json" --also "device" -- "$bin" sim z --seconds 0
    mkdir -p f && mkfifo f/project.json
    refused "f/project.json" --also "FIFO" -- "$bin" sim f --seconds 0
    mkdir -p big && truncate -s 200M big/project.json
    refused "big/project.json" --also "more than the 64 MiB" -- "$bin" sim big --seconds 0
    project m rock && rm m/cube.glb && mkfifo m/cube.glb
    refused "cube.glb" --also "FIFO" -- "$bin" sim m --seconds 0
    tiny_with mz 's|"density_map": ""|"density_map": "d.png"|' && ln -s /dev/zero mz/d.png
    refused "d.png" -- "$bin" sim mz --seconds 0
    tiny_with mf 's|"density_map": ""|"density_map": "d.png"|' && mkfifo mf/d.png
    refused "d.png" --also "FIFO" -- "$bin" sim mf --seconds 0
    mkdir -p tz && ln -s /dev/zero tz/tradeoff.json
    refused "tradeoff.json" --also "device" -- "$bin" tradeoff --replot tz
    mkfifo bench.json
    refused "bench.json" --also "FIFO" -- "$bin" bench --quick --compare bench.json
    refused "fifo.gltf" --also "FIFO" -- "$bin" mesh-info "$(mkfifo fifo.gltf; echo fifo.gltf)"
    ;;

bounds)
    # Times, counts and sizes have bounds derived from what can run.
    tiny_with step 's|"render":|"physics": {"step_s": 1e-30}, "render":|'
    refused "/physics/step_s" --also "[0.00001, 60]" -- "$bin" sim step --seconds 1
    tiny_with step5 's|"render":|"physics": {"step_s": 1e-5}, "render":|'
    refused "--seconds" --also "steps" -- "$bin" sim step5 --seconds 3600
    refused "--time" --also "steps" -- "$bin" render step5 --time 3600 --out x.png
    refused "--seconds" --also "steps" -- "$bin" soak step5 --dt 0.0001 --seconds 3600
    tiny_with tall 's|"density": 20.0|"density": 20.0, "blade": {"height": [1e30, 1e30]}|'
    refused "/layers/0/blade/height/0" --also "100" -- "$bin" sim tall --seconds 0
    tiny_with wide 's|"density": 20.0|"density": 20.0, "blade": {"width": [0.01, 50]}|'
    refused "/layers/0/blade/width/1" -- "$bin" sim wide --seconds 0
    # At the bounds the physics still keeps every blade's length (to 1e-4 of it, SPEC §3).
    tiny_with bound 's|"density": 20.0|"density": 20.0, "blade": {"height": [100, 100], "width": [10, 10]}|'
    case_
    error=$("$bin" sim bound --seconds 2 --backend cpu 2>/dev/null |
        sed -n 's/.*max rel length error \([^,]*\),.*/\1/p')
    awk -v e="${error:-1}" 'BEGIN { exit !(e < 1e-4) }' ||
        fail "100 m blades keep their length only to ${error:-?} (bound 1e-4)"
    # 64k layers: refused at once by their count, not after a quadratic name check.
    {
        printf '{"format": "grass-project", "version": 1, "name": "many", "layers": ['
        for i in $(seq 0 65534); do printf '{"name": "l%d"},' "$i"; done
        printf '{"name": "last"}]}'
    } >many.json
    refused "/layers" --also "at most 256" -- "$bin" sim many.json --seconds 0
    # Report paths are checked writable before the run (a folder under /proc cannot be).
    refused "--report" -- "$bin" sim "$data/projects/tiny" --seconds 600 --report /proc/r.json
    refused "--stats" -- "$bin" render "$data/projects/tiny" --time 600 --stats /proc/s.json
    ;;

messages)
    # Refusals name the JSON pointer the user wrote and the range the docs state.
    tiny_with ao 's|"render":|"lighting": {"ao_radius": 0.00001}, "render":|'
    refused "/lighting/ao_radius" --also "0.0001 to 100" -- "$bin" sim ao --seconds 0
    tiny_with ao2 's|"render":|"lighting": {"normal_blur_radius": 0.00001}, "render":|'
    refused "/lighting/normal_blur_radius" -- "$bin" sim ao2 --seconds 0
    # Two exports into one folder at once: the second says why it cannot.
    project e growth_tiny
    "$bin" export e --out exp >/dev/null 2>&1 || fail "export fails"
    case_
    GRASS_TEST_SAVE_DELAY_MS=2000 "$bin" export e --out exp >/dev/null 2>&1 &
    first=$!
    sleep 1
    refused "exp" --also "another grass export is writing into this folder" -- \
        "$bin" export e --out exp
    wait $first || fail "the first of two concurrent exports failed"
    # --mesh on a huge mesh (a 1 km plane) blames no setting the user never gave.
    # (quad.gltf embeds its buffer; whitespace out, its node scale from 3 to 2000: 16 km².)
    mkdir -p huge && tr -d ' \n' <"$data/gltf/quad.gltf" |
        sed 's|"scale":\[3,3,3\]|"scale":[2000,2000,2000]|' >huge/quad.gltf
    case_
    grep -q '"scale":\[2000,2000,2000\]' huge/quad.gltf || fail "the huge quad was not made"
    "$bin" render --mesh huge/quad.gltf --width 64 --height 48 --out huge.png >/dev/null \
        2>"$work/huge.err" || fail "render --mesh on a 2 km quad failed: $(cat "$work/huge.err")"
    ;;

*)
    echo "hostile_input_test.sh: unknown class $class" >&2
    exit 2
    ;;
esac

echo "$class: $cases cases, $failed failed"
[ "$failed" -eq 0 ]
