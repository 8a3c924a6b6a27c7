#!/usr/bin/env bash
# The artist's own mesh in, by real X input at about one frame a second (issue 26): File › New
# from mesh… by mouse, the mesh's path typed into the browser (its path field has the keyboard
# as it opens) and Enter; Ctrl+S asks where (the browser again) and saves the project with its
# mesh copied along; a typed density of 1e30 is refused in its box (and not saved); Ctrl+O opens
# the first project again; File › Open Recent's list holds both. Screenshots of the refused
# value and the browser are left in WORK_DIR for a person to look at.
#
#   editor_real_import_test.sh GRASS_EDITOR MESH.glb WORK_DIR   (under xvfb-run: X and xdotool)
set -u
editor=$1
mesh=$2
work=$3

. "$(dirname "$0")/editor_window_lib.sh"
mkdir -p -- "$work/meshes" "$work/config" || fail "cannot make $work"
cp -- "$mesh" "$work/meshes/rock.glb" || fail "cannot copy $mesh"
# The recent list goes to the test's own folder, not the user's.
export XDG_CONFIG_HOME="$work/config"
start_editor

shot() { command -v import >/dev/null && import -window root "$work/$1" 2>/dev/null; }
# Where the widgets are at Xvfb's scale of 1 (re-measure from a screenshot if the layout changes).
act mousemove 24 12 click 1                   # File
act mousemove 80 67 click 1                   # New from mesh…
act type "$work/meshes/rock.glb"
shot browser.png
act key Return
sleep 3                                       # the new field grows
act key ctrl+s                                # not saved yet: the browser asks where
act type "$work/saved"
act key Return
act mousemove 214 339 click --repeat 2 --delay 90 1   # the density field: double-click
act type 1e30
act key Return                                # refused: the box stays, with the reason
shot refused.png
act key Escape
act key ctrl+o
act type "$work/p"
act key Return
sleep 3
stop_editor

saved=$work/saved/project.json
[ -f "$saved" ] || fail "Ctrl+S with a typed folder saved nothing"
grep -q '"file": "rock.glb"' "$saved" || fail "the saved project does not name the mesh: $(grep -A2 '"mesh"' "$saved")"
[ -f "$work/saved/rock.glb" ] || fail "the mesh was not copied along with the project"
grep -q 'e+30' "$saved" && fail "the refused density reached the project"
recent=$work/config/grass/recent.json
grep -q "$work/saved/project.json" "$recent" && grep -q "$work/p/project.json" "$recent" ||
    fail "Open Recent does not hold both projects: $(cat "$recent" 2>/dev/null)"
echo "real import: new from mesh, browser typing, save as, refused value, open and recent all worked"
