# End-to-end tests of the command-line tools (grass, grass-editor), run as a user runs them:
# exit codes, help text, outputs, and the one-line error every bad input must give (STYLE.md
# §4). Each test is a call to a small bash driver in tests/cli/ (bash and coreutils only):
#   expect_ok.sh     exit 0; optional stdout patterns and a PNG of a given size
#   expect_error.sh  exit 1..127 (no crash, no hang), exactly one stderr line naming the culprit
# Inputs are committed in tests/data/ (see tests/data/README.md); outputs go to
# test-tmp/cli/ in the build folder. Tests that open a GL context carry the label "gl" too.
# The suite stays fast on llvmpipe: tiny images, --frames 1.

if(NOT TARGET grass)
    return()
endif()
find_program(GRASS_BASH bash)
find_program(GRASS_TIMEOUT timeout)
if(NOT GRASS_BASH OR NOT GRASS_TIMEOUT)
    message(WARNING "bash or timeout (coreutils) not found: the CLI tests (label cli) are not added")
    return()
endif()

set(GRASS_CLI_DIR ${CMAKE_CURRENT_SOURCE_DIR}/cli)
set(GRASS_CLI_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data)
set(GRASS_CLI_TMP ${CMAKE_BINARY_DIR}/test-tmp/cli)
set(GRASS_CLI_GLTF ${GRASS_CLI_DATA}/gltf)
set(GRASS_CLI_PROJECTS ${GRASS_CLI_DATA}/projects)
file(MAKE_DIRECTORY ${GRASS_CLI_TMP})
set(GRASS_BIN $<TARGET_FILE:grass>)
# The real-window tests (editor, runtime sample) run under xvfb-run.
find_program(GRASS_XVFB_RUN xvfb-run)
if(NOT GRASS_XVFB_RUN)
    set(GRASS_XVFB_RUN xvfb-run)  # fails with "not found": never a silent skip
endif()

# grass_cli_test(NAME [GL] OK|ERROR <driver arguments>... -- <command>...)
function(grass_cli_test name)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "GL;OK;ERROR" "" "")
    if(ARG_OK)
        set(driver ${GRASS_CLI_DIR}/expect_ok.sh)
    elseif(ARG_ERROR)
        set(driver ${GRASS_CLI_DIR}/expect_error.sh)
    else()
        message(FATAL_ERROR "grass_cli_test(${name}): say OK or ERROR")
    endif()
    add_test(NAME cli.${name} COMMAND ${GRASS_BASH} ${driver} ${ARG_UNPARSED_ARGUMENTS}
             WORKING_DIRECTORY ${GRASS_CLI_TMP})
    set(labels cli)
    if(ARG_GL)
        list(APPEND labels gl)
    endif()
    # A sanitizer build (Debug, ASan + UBSan) runs a command several times slower: the soaks
    # take minutes there, so the bound on one command grows from 120 s to 600 s.
    set(timeout 150)
    set(environment "${GRASS_GL_TEST_ENV_MODIFICATION}")
    if(GRASS_SANITIZE)
        set(timeout 700)
        list(APPEND environment "GRASS_CLI_TIMEOUT=set:600")
    endif()
    set_tests_properties(cli.${name} PROPERTIES LABELS "${labels}" TIMEOUT ${timeout}
        ENVIRONMENT_MODIFICATION "${environment}")
endfunction()

# The drivers catch what they claim to catch (success, crash, hang, extra lines, ...).
add_test(NAME cli.driver_self_test
         COMMAND ${GRASS_BASH} ${GRASS_CLI_DIR}/driver_self_test.sh ${GRASS_CLI_TMP}/self-test)
set_tests_properties(cli.driver_self_test PROPERTIES LABELS cli TIMEOUT 60)

# --- help and version ------------------------------------------------------------------------
grass_cli_test(help OK --no-stderr
    --stdout "^usage: grass <command>" --stdout "^  render " --stdout "^  sim " --stdout "^  mesh-info "
    -- ${GRASS_BIN} --help)
grass_cli_test(version OK --no-stderr --stdout "^grass [0-9]+\\.[0-9]+\\.[0-9]+$"
    -- ${GRASS_BIN} --version)
grass_cli_test(render_help OK --no-stderr
    --stdout "^usage: grass render" --stdout "^  --mesh FILE" --stdout "^  --out FILE"
    --stdout "^  --width N" --stdout "^  --height N" --stdout "^  --seed N"
    --stdout "^  --camera NAME" --stdout "^  --geometry project\\|auto\\|tess\\|strips"
    --stdout "^  --frames N" --stdout "^  --blades N" --stdout "^  --help"
    -- ${GRASS_BIN} render --help)
grass_cli_test(mesh_info_help OK --no-stderr
    --stdout "^usage: grass mesh-info" --stdout "^  file" --stdout "^  --json" --stdout "^  --help"
    -- ${GRASS_BIN} mesh-info --help)
if(TARGET grass-editor)
    # --help must answer before any window or GL context is made (CI has no display).
    grass_cli_test(editor_help OK --no-stderr
        --stdout "^usage: grass-editor" --stdout "^  --screenshot FILE" --stdout "^  --frames N"
        -- $<TARGET_FILE:grass-editor> --help)
endif()

# --- mesh-info -------------------------------------------------------------------------------
# quad.gltf: a 2x2 quad (y = 0, x and z in [-1, 1]) with normals and UVs, placed by a node with
# scale 3 and translation [1, 0, 0]: a 6x6 square, area 36, x in [-2, 4], z in [-3, 3].
grass_cli_test(mesh_info_gltf_json OK --no-stderr
    --stdout "^\\{\"vertices\":4,\"triangles\":2,\"area\":36(\\.0+)?,"
    --stdout "\"has_normals\":true,\"has_uv\":true,"
    --stdout "\"bounds\":\\[\\[-2(\\.0+)?,0(\\.0+)?,-3(\\.0+)?\\],\\[4(\\.0+)?,0(\\.0+)?,3(\\.0+)?\\]\\],"
    --stdout "\"ground_origin\":\\[0(\\.0+)?,0(\\.0+)?,0(\\.0+)?\\]\\}$"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/quad.gltf --json)
grass_cli_test(mesh_info_gltf_text OK --no-stderr
    --stdout "quad\\.gltf$" --stdout "^  vertices +4$" --stdout "^  triangles +2$"
    --stdout "^  area +36$" --stdout "^  normals +from file$" --stdout "^  uv0 +from file$"
    --stdout "^  bounds +\\[-2 0 -3\\] \\.\\. \\[4 0 3\\]$"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/quad.gltf)
# box_draco.glb and box_meshopt.glb: the same 4 x 2 x 3 m box (24 vertices, a normal and UVs
# per face, area 52) compressed with KHR_draco_mesh_compression (positions at 14 bits) and
# EXT_meshopt_compression (lossless), written by tests/support/compressed_gltf.cpp.
grass_cli_test(mesh_info_draco OK --no-stderr
    --stdout "^  vertices +24$" --stdout "^  triangles +12$" --stdout "^  area +52(\\.00[0-9]*)?$"
    --stdout "^  normals +from file$" --stdout "^  uv0 +from file$"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/box_draco.glb)
# skinned_morphed.gltf: a triangle stored Z-up with its apex at z = 1, a morph target raising
# the apex by 1 at mesh weight 0.5, and a skin whose root joint turns Z-up to Y-up (written by
# hand for the glTF seeds of tests/fuzz): viewers show it upright, the apex at y = 1.5.
grass_cli_test(mesh_info_skinned_morphed OK
    --stdout "^  area +0\\.75$"
    --stdout "^  bounds +\\[0 0 -?[0-9.e-]+\\] \\.\\. \\[1 1\\.5 0\\]$"
    --stderr "^note: .*skinned_morphed\\.gltf: mesh \"Leaf\": morph targets applied at their default weights$"
    --stderr "^note: .*skinned_morphed\\.gltf: mesh \"Leaf\" is skinned: placed in its skeleton's rest pose \\(skin \"Armature\"\\)$"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/skinned_morphed.gltf)
grass_cli_test(mesh_info_meshopt OK --no-stderr
    --stdout "^  vertices +24$" --stdout "^  triangles +12$" --stdout "^  area +52$"
    --stdout "^  bounds +\\[1 -0\\.5 2\\] \\.\\. \\[5 1\\.5 5\\]$"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/box_meshopt.glb)
# cube.glb: a 2x2x2 cube around the origin (8 shared corners, 12 triangles, no normals, no UVs)
# placed by a node matrix (uniform scale 0.5, translation [0, 1, 0]): a unit cube, area 6,
# bounds [-0.5, 0.5, -0.5] .. [0.5, 1.5, 0.5].
grass_cli_test(mesh_info_glb_json OK --no-stderr
    --stdout "^\\{\"vertices\":8,\"triangles\":12,\"area\":6(\\.0+)?,"
    --stdout "\"has_normals\":false,\"has_uv\":false,"
    --stdout "\"bounds\":\\[\\[-0\\.5,0\\.5,-0\\.5\\],\\[0\\.5,1\\.5,0\\.5\\]\\],"
    --stdout "\"ground_origin\":\\[0(\\.0+)?,0(\\.0+)?,0(\\.0+)?\\]\\}$"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/cube.glb --json)

# far_quad.gltf: quad.gltf placed at map coordinates (512345, 120, 5412345). Its bounds stay in
# the file's frame; as a ground it is moved next to grass's origin, which mesh-info names.
grass_cli_test(mesh_info_far_ground OK
    --stdout "^  bounds +\\[512342 120 5412342\\] \\.\\. \\[512348 120 5412348\\]$"
    --stdout "^  origin +\\[512345 120 5412345\\] of the file is grass's origin as a ground$"
    --stderr "^note: .*far_quad\\.gltf: lies 5437 km from the file's origin, where 32-bit positions are 0\\.5 m apart: moved"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/far_quad.gltf)
# --- render (GL) -----------------------------------------------------------------------------
# The build says its stages as notes (a large mesh's read and growing took seconds in silence).
grass_cli_test(render_meadow GL OK --png ${GRASS_CLI_TMP}/meadow.png 160 90
    --stdout "^wrote .*meadow\\.png \\(160x90\\)$" --stdout "^  frames +1,"
    --stderr "^note: growing layer \"grass\" \\(1 of 1\\) \\.\\.\\.$"
    -- ${GRASS_BIN} render ${GRASS_SOURCE_DIR}/projects/meadow --out ${GRASS_CLI_TMP}/meadow.png
       --width 160 --height 90 --frames 1)
# The headless context's second way to a display, EGL_EXT_platform_device (how NVIDIA's driver
# offers a GPU without a window system), forced on llvmpipe, which offers it too.
grass_cli_test(render_egl_device_platform GL OK --png ${GRASS_CLI_TMP}/meadow_device.png 64 36
    --stdout "^  renderer +"
    -- env GRASS_EGL_PLATFORM=device ${GRASS_BIN} render ${GRASS_SOURCE_DIR}/projects/meadow
       --out ${GRASS_CLI_TMP}/meadow_device.png --width 64 --height 36 --frames 1)
grass_cli_test(render_egl_platform_bad ERROR "GRASS_EGL_PLATFORM" --also "auto, surfaceless or device"
    --absent ${GRASS_CLI_TMP}/never_egl.png
    -- env GRASS_EGL_PLATFORM=x11 ${GRASS_BIN} render ${GRASS_SOURCE_DIR}/projects/meadow
       --out ${GRASS_CLI_TMP}/never_egl.png --width 64 --height 36 --frames 1)
# Work groups of 256 (GRASS_COMPUTE_GROUP, core/util/blade_pass_group.h): the cull in 8 runs of 32
# blades and the physics on the GPU path (compute_group_gl_test.cpp compares their results).
grass_cli_test(render_compute_group_256 GL OK --png ${GRASS_CLI_TMP}/meadow_group.png 64 36
    --stdout "^simulated .* on the gpu," --stdout "^  renderer .*, compute groups of 256$"
    -- env GRASS_COMPUTE_GROUP=256 ${GRASS_BIN} render ${GRASS_SOURCE_DIR}/projects/meadow
       --out ${GRASS_CLI_TMP}/meadow_group.png --width 64 --height 36 --frames 1 --time 0.2
       --backend gpu)
grass_cli_test(render_compute_group_bad ERROR "GRASS_COMPUTE_GROUP" --also "multiple of 32"
    --absent ${GRASS_CLI_TMP}/never_group.png
    -- env GRASS_COMPUTE_GROUP=48 ${GRASS_BIN} render ${GRASS_SOURCE_DIR}/projects/meadow
       --out ${GRASS_CLI_TMP}/never_group.png --width 64 --height 36 --frames 1)
grass_cli_test(render_mesh GL OK --png ${GRASS_CLI_TMP}/quad.png 128 128
    --stdout "^wrote .*quad\\.png \\(128x128\\)$" --stdout "^  scene +2 triangles, [1-9][0-9]* blades"
    --stderr "^note: reading quad\\.gltf \\.\\.\\.$"
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_GLTF}/quad.gltf --out ${GRASS_CLI_TMP}/quad.png
       --width 128 --height 128 --frames 1 --blades 2000)
# The quad at map coordinates renders as the quad at the origin does, with the note.
grass_cli_test(render_mesh_far GL OK --png ${GRASS_CLI_TMP}/far-quad.png 128 128
    --stdout "^  scene +2 triangles, [1-9][0-9]* blades"
    --stderr "^note: .*far_quad\\.gltf: lies 5437 km from the file's origin"
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_GLTF}/far_quad.gltf --out ${GRASS_CLI_TMP}/far-quad.png
       --width 128 --height 128 --frames 1 --blades 2000)
# A model in millimetres with +Z up: scaled and turned, a field still grows and renders.
grass_cli_test(render_mesh_mm_zup GL OK --png ${GRASS_CLI_TMP}/quad-mm.png 96 64
    --stdout "^  scene +2 triangles, [1-9][0-9]* blades"
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_GLTF}/quad.gltf --unit mm --up +Z
       --out ${GRASS_CLI_TMP}/quad-mm.png --width 96 --height 64 --frames 1 --blades 2000)
# A glTF file where the project goes is taken as --mesh (it used to be refused: "use --mesh").
grass_cli_test(render_mesh_positional GL OK --png ${GRASS_CLI_TMP}/quad-positional.png 64 48
    --stdout "^  scene +2 triangles, [1-9][0-9]* blades"
    -- ${GRASS_BIN} render ${GRASS_CLI_GLTF}/quad.gltf
       --out ${GRASS_CLI_TMP}/quad-positional.png --width 64 --height 48 --frames 1 --blades 2000)
grass_cli_test(render_project_camera GL OK --png ${GRASS_CLI_TMP}/tiny-top.png 64 48
    --stdout "^wrote .*tiny-top\\.png \\(64x48\\)$"
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/tiny-top.png
       --camera top --seed 5 --geometry strips --frames 1)
# The image is written only after a full render: a folder that does not exist must be named,
# and nothing may be created (neither the folder nor a partial file).
grass_cli_test(render_out_folder_missing GL ERROR "no-such-folder"
    --absent ${GRASS_CLI_TMP}/no-such-folder
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/no-such-folder/out.png
       --frames 1)
grass_cli_test(render_out_unknown_format GL ERROR "never.xyz"
    --absent ${GRASS_CLI_TMP}/never.xyz
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_TMP}/never.xyz --frames 1)

# --- sim and render --time -------------------------------------------------------------------
set(WINDY ${GRASS_CLI_PROJECTS}/windy)
set(REPORT ${GRASS_CLI_TMP}/windy-report.json)
grass_cli_test(sim_help OK --no-stderr
    --stdout "^usage: grass sim" --stdout "^  --seconds S" --stdout "^  --backend"
    --stdout "^  --report FILE" -- ${GRASS_BIN} sim --help)
# 1 s at 0.02 s: 50 steps. The report carries every figure issue 4 names.
grass_cli_test(sim_windy_cpu OK
    --stdout "^simulated 1\\.000 s of windy: 50 steps"
    --stdout "^  health .*nonfinite 0, below ground 0$"
    --stdout "^  scene .*2 wind source\\(s\\), 1 collider sphere\\(s\\)$"
    --file ${REPORT} "\"backend\": \"cpu\""
    --file ${REPORT} "\"steps\": 50,"
    --file ${REPORT} "\"blades\": [1-9][0-9]*,"
    --file ${REPORT} "\"ms_per_step\": [0-9]"
    --file ${REPORT} "\"max_rel_length_error\": [0-9]"
    --file ${REPORT} "\"nonfinite\": 0,"
    --file ${REPORT} "\"below_ground\": 0,"
    --file ${REPORT} "\"mean_tip_displacement\": 0\\.[0-9]*[1-9]"
    --file ${REPORT} "\"max_tip_displacement\": 0\\.[0-9]*[1-9]"
    --file ${REPORT} "\"crushed_share\": 0\\.[0-9]*[1-9]"
    -- ${GRASS_BIN} sim ${WINDY} --seconds 1 --report ${REPORT})
grass_cli_test(sim_windy_gpu GL OK
    --stdout "^simulated 1\\.000 s of windy: 100 steps of 0\\.01 s"
    --stdout "^  backend +gpu \\(.*, compute groups of 32\\)$" --stdout "^  health .*nonfinite 0, below ground 0$"
    -- ${GRASS_BIN} sim ${WINDY} --seconds 1 --dt 0.01 --backend gpu)
# --backend auto (the default) runs the physics where it is fastest: the CPU on software GL.
grass_cli_test(render_time GL OK --png ${GRASS_CLI_TMP}/windy.png 64 48
    --stdout "^simulated +1\\.000 s in 50 steps on the (cpu|gpu)" --stdout "^wrote .*windy\\.png"
    --file ${GRASS_CLI_TMP}/windy-stats.json "\"physics_device\": \"(cpu|gpu)\""
    -- ${GRASS_BIN} render ${WINDY} --time 1 --out ${GRASS_CLI_TMP}/windy.png --frames 1
       --stats ${GRASS_CLI_TMP}/windy-stats.json)
grass_cli_test(render_time_gpu GL OK --png ${GRASS_CLI_TMP}/windy-gpu.png 64 48
    --stdout "^simulated +1\\.000 s in 50 steps on the gpu"
    -- ${GRASS_BIN} render ${WINDY} --time 1 --backend gpu --out ${GRASS_CLI_TMP}/windy-gpu.png
       --frames 1)
# A mesh collider packs into spheres once and caches them next to the project: the project is
# copied out of the source tree first (the cache must not land in tests/data).
set(ROCK ${GRASS_CLI_TMP}/rock)
add_test(NAME cli.sim_rock_setup COMMAND ${CMAKE_COMMAND} -E rm -rf ${ROCK})
add_test(NAME cli.sim_rock_copy
         COMMAND ${CMAKE_COMMAND} -E copy_directory ${GRASS_CLI_PROJECTS}/rock ${ROCK})
set_tests_properties(cli.sim_rock_setup PROPERTIES LABELS cli FIXTURES_SETUP rock_clean)
set_tests_properties(cli.sim_rock_copy PROPERTIES LABELS cli FIXTURES_SETUP rock_copy
    FIXTURES_REQUIRED rock_clean DEPENDS cli.sim_rock_setup)
grass_cli_test(sim_rock_packs OK
    --stdout "^  scene .*16 collider sphere\\(s\\)$"
    --stderr "^note: collider cube: cube.glb as 16 spheres \\(packed, cached in .*\\): 100\\.0 % of their volume inside, [0-9.]+ % of the mesh covered$"
    --file ${ROCK}/.grass-cache/cube.16-24.spheres.json "grass-sphere-packing"
    -- ${GRASS_BIN} sim ${ROCK} --seconds 0.2)
grass_cli_test(sim_rock_cached OK --stdout "^  scene .*16 collider sphere\\(s\\)$"
    --stderr "^note: collider cube: cube.glb as 16 spheres \\(cached in "
    -- ${GRASS_BIN} sim ${ROCK} --seconds 0.2)
set_tests_properties(cli.sim_rock_packs PROPERTIES FIXTURES_REQUIRED rock_copy
    FIXTURES_SETUP rock_packed)
set_tests_properties(cli.sim_rock_cached PROPERTIES FIXTURES_REQUIRED "rock_copy;rock_packed"
    DEPENDS cli.sim_rock_packs)
# A project whose cache cannot be written (a read-only folder: here a file where the cache
# folder would go, which holds for root too) still simulates: the spheres are packed in memory,
# with a note naming the cache.
set(ROCK_UNWRITABLE ${GRASS_CLI_TMP}/rock-unwritable-cache)
add_test(NAME cli.sim_rock_unwritable_setup
         COMMAND ${GRASS_BASH} -c "rm -rf '${ROCK_UNWRITABLE}' && cp -r '${GRASS_CLI_PROJECTS}/rock' '${ROCK_UNWRITABLE}' && rm -rf '${ROCK_UNWRITABLE}/.grass-cache' && : > '${ROCK_UNWRITABLE}/.grass-cache'")
set_tests_properties(cli.sim_rock_unwritable_setup PROPERTIES LABELS cli
    FIXTURES_SETUP rock_unwritable)
grass_cli_test(sim_rock_unwritable_cache OK
    --stdout "^  scene .*16 collider sphere\\(s\\)$"
    --stderr "^note: collider cube: cube.glb as 16 spheres \\(packed\\): 100\\.0 % of their volume inside"
    --stderr "^note: collider cube: sphere-packing cache .*rock-unwritable-cache/\\.grass-cache/cube\\.16-24\\.spheres\\.json not written \\(.*\\): packed in memory"
    -- ${GRASS_BIN} sim ${ROCK_UNWRITABLE} --seconds 0.2)
set_tests_properties(cli.sim_rock_unwritable_cache PROPERTIES FIXTURES_REQUIRED rock_unwritable)
grass_cli_test(sim_seconds_negative ERROR "--seconds" -- ${GRASS_BIN} sim ${WINDY} --seconds -1)
grass_cli_test(sim_dt_zero ERROR "--dt" -- ${GRASS_BIN} sim ${WINDY} --dt 0)
grass_cli_test(sim_dt_not_a_number ERROR "--dt" -- ${GRASS_BIN} sim ${WINDY} --dt fast)
grass_cli_test(sim_backend_unknown ERROR "--backend" -- ${GRASS_BIN} sim ${WINDY} --backend tpu)
grass_cli_test(sim_no_project ERROR "project" -- ${GRASS_BIN} sim)
grass_cli_test(sim_report_folder_missing ERROR "no-such-folder"
    --absent ${GRASS_CLI_TMP}/no-such-folder
    -- ${GRASS_BIN} sim ${WINDY} --report ${GRASS_CLI_TMP}/no-such-folder/r.json)
grass_cli_test(sim_bad_wind ERROR "/wind/0/kind" --also "vortex"
    -- ${GRASS_BIN} sim ${GRASS_CLI_PROJECTS}/bad_wind)
grass_cli_test(render_time_negative ERROR "--time" --absent ${GRASS_CLI_TMP}/never.png
    -- ${GRASS_BIN} render ${WINDY} --time -2 --out ${GRASS_CLI_TMP}/never.png)

# --- render: bad command lines (no GL needed: they fail before a context is made) -------------
set(TINY ${GRASS_CLI_PROJECTS}/tiny)
set(OUT ${GRASS_CLI_TMP}/never.png)
grass_cli_test(render_width_zero ERROR "--width" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --width 0)
# --unit and --up (issue 26): checked before any file is read, and only with --mesh.
grass_cli_test(render_unit_unknown ERROR "--unit" --also "mm, cm, m, in, ft" --absent ${OUT}
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_GLTF}/quad.gltf --out ${OUT} --unit parsec)
grass_cli_test(render_up_unknown ERROR "--up" --also "+Y or +Z" --absent ${OUT}
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_GLTF}/quad.gltf --out ${OUT} --up -x)
grass_cli_test(render_unit_without_mesh ERROR "--unit" --also "/mesh/unit" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --unit mm)
grass_cli_test(render_width_not_a_number ERROR "--width" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --width abc)
grass_cli_test(render_width_missing_value ERROR "--width" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --width)
grass_cli_test(render_height_too_large ERROR "--height" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --height 100000)
grass_cli_test(render_frames_negative ERROR "--frames" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --frames -1)
grass_cli_test(render_seed_negative ERROR "--seed" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --seed -3)
grass_cli_test(render_geometry_unknown ERROR "--geometry" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --geometry wires)
grass_cli_test(render_unknown_option ERROR "--no-such-option" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --no-such-option)
grass_cli_test(render_flag_with_value ERROR "--gl-debug" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --out ${OUT} --gl-debug=yes)
grass_cli_test(render_extra_argument ERROR "extra-argument" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} extra-argument --out ${OUT})
grass_cli_test(render_no_input ERROR "--mesh" --absent ${OUT}
    -- ${GRASS_BIN} render --out ${OUT})
grass_cli_test(render_project_and_mesh ERROR "--mesh" --absent ${OUT}
    -- ${GRASS_BIN} render ${TINY} --mesh ${GRASS_CLI_GLTF}/quad.gltf --out ${OUT})
# The message names the camera asked for and lists those there are, so the user can pick one.
grass_cli_test(render_camera_unknown ERROR "--camera" --also "nosuch" --also "front" --also "top"
    --absent ${OUT} -- ${GRASS_BIN} render ${TINY} --out ${OUT} --camera nosuch)
grass_cli_test(unknown_command ERROR "rnder"
    -- ${GRASS_BIN} rnder ${TINY})
grass_cli_test(unknown_top_level_option ERROR "--frobnicate"
    -- ${GRASS_BIN} --frobnicate)

# --- render: bad projects --------------------------------------------------------------------
grass_cli_test(render_project_missing ERROR "no-such-project" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_TMP}/no-such-project --out ${OUT})
# A glTF file as the project is taken as --mesh (render_mesh_positional); with --mesh as well it
# is one input too many.
grass_cli_test(render_gltf_as_project ERROR "not both" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_GLTF}/quad.gltf --mesh ${GRASS_CLI_GLTF}/quad.gltf --out ${OUT})
grass_cli_test(render_folder_without_project ERROR "project.json" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_GLTF} --out ${OUT})
grass_cli_test(render_project_unknown_format ERROR "/format" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/unknown_format --out ${OUT})
grass_cli_test(render_project_unknown_version ERROR "/version" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/unknown_version --out ${OUT})
grass_cli_test(render_project_infinite_density ERROR "/layers/0/density" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/inf_density --out ${OUT})
grass_cli_test(render_project_negative_density ERROR "/layers/0/density" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/negative_density --out ${OUT})
# 1e8 blades/m² on 4 m² is 4e8 blades: refused before scattering, with a message naming the
# layer, the blade count and the memory it would need, not grown for minutes into gigabytes.
grass_cli_test(render_project_density_too_high ERROR "/layers/0" --also "4e+08 blades"
    --also "GiB of blade data" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/huge_density --out ${OUT})
set_tests_properties(cli.render_project_density_too_high PROPERTIES
                     ENVIRONMENT GRASS_CLI_TIMEOUT=30)
grass_cli_test(render_project_density_map_missing ERROR "maps/missing.png" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/missing_density_map --out ${OUT})
grass_cli_test(render_project_density_map_not_image ERROR "maps/density.png" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/density_map_not_image --out ${OUT})
grass_cli_test(render_project_mesh_truncated ERROR "field.gltf" --absent ${OUT}
    -- ${GRASS_BIN} render ${GRASS_CLI_PROJECTS}/truncated_mesh --out ${OUT})
grass_cli_test(render_mesh_missing ERROR "no-such-mesh.gltf" --absent ${OUT}
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_TMP}/no-such-mesh.gltf --out ${OUT})
grass_cli_test(render_mesh_not_gltf ERROR "not_gltf.gltf" --absent ${OUT}
    -- ${GRASS_BIN} render --mesh ${GRASS_CLI_GLTF}/not_gltf.gltf --out ${OUT})

# --- mesh-info: bad files --------------------------------------------------------------------
grass_cli_test(mesh_info_no_file ERROR "file"
    -- ${GRASS_BIN} mesh-info --json)
grass_cli_test(mesh_info_missing_file ERROR "no-such-mesh.gltf"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_TMP}/no-such-mesh.gltf)
grass_cli_test(mesh_info_truncated ERROR "truncated.gltf"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/truncated.gltf)
grass_cli_test(mesh_info_accessor_past_buffer ERROR "accessor_past_buffer.gltf"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/accessor_past_buffer.gltf)
grass_cli_test(mesh_info_index_out_of_range ERROR "index_out_of_range.gltf"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/index_out_of_range.gltf)
grass_cli_test(mesh_info_uri_outside_folder ERROR "../outside.bin"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/outside_uri.gltf)
grass_cli_test(mesh_info_draco_required ERROR "KHR_draco_mesh_compression"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/draco_required.gltf)
grass_cli_test(mesh_info_not_gltf ERROR "not_gltf.gltf"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF}/not_gltf.gltf)
grass_cli_test(mesh_info_folder ERROR "gltf"
    -- ${GRASS_BIN} mesh-info ${GRASS_CLI_GLTF})

# --- grass-editor: bad command lines fail before a window is opened -------------------------
if(TARGET grass-editor)
    grass_cli_test(editor_project_missing ERROR "no-such-project"
        -- $<TARGET_FILE:grass-editor> ${GRASS_CLI_TMP}/no-such-project)
    grass_cli_test(editor_frames_zero ERROR "--frames"
        -- $<TARGET_FILE:grass-editor> --screenshot ${OUT} --frames 0)
    grass_cli_test(editor_project_negative_density ERROR "/layers/0/density"
        -- $<TARGET_FILE:grass-editor> ${GRASS_CLI_PROJECTS}/negative_density)
endif()
include(${GRASS_CLI_DIR}/cull_cli_tests.cmake)
include(${GRASS_CLI_DIR}/shape_cli_tests.cmake)
include(${GRASS_CLI_DIR}/technique_cli_tests.cmake)
include(${GRASS_CLI_DIR}/paint_cli_tests.cmake)
include(${GRASS_CLI_DIR}/export_cli_tests.cmake)
include(${GRASS_CLI_DIR}/turntable_cli_tests.cmake)
include(${GRASS_CLI_DIR}/bench_cli_tests.cmake)
include(${GRASS_CLI_DIR}/preset_cli_tests.cmake)
include(${GRASS_CLI_DIR}/reliability_cli_tests.cmake)
include(${GRASS_CLI_DIR}/extreme_cli_tests.cmake)
include(${GRASS_CLI_DIR}/soak_cli_tests.cmake)
include(${GRASS_CLI_DIR}/runtime_cli_tests.cmake)
