# CLI tests of `grass paint` (issue 6: painting environment maps from the command line) and of
# `grass render --technique growth`. Included from cli_tests.cmake, after grass_cli_test().
#
# growth_tiny (tests/data/projects/growth_tiny): a 2 m plane, 60 blades/m², growth on, 64² maps,
# 32-blade patches, so a stroke re-grows a few of several patches in milliseconds. Painting
# writes into the project, and tests must never change the source tree, so a fixture copies it
# afresh into test-tmp/cli/paint/ first: one copy per independent chain of tests, so they can
# run in parallel.

set(PAINT_TMP ${GRASS_CLI_TMP}/paint)
set(PAINT_SOURCE ${GRASS_CLI_PROJECTS}/growth_tiny)
set(PAINT_COPIES soil uv dry errors cut)
add_test(NAME cli.paint_setup_copies
         COMMAND ${GRASS_BASH} -c
                 "rm -rf -- \"$0\" && for c in \"\${@:2}\"; do mkdir -p -- \"$0/$c\" && cp -R -- \"$1/.\" \"$0/$c\" || exit 1; done"
                 ${PAINT_TMP} ${PAINT_SOURCE} ${PAINT_COPIES})
set_tests_properties(cli.paint_setup_copies PROPERTIES LABELS cli TIMEOUT 30
                     FIXTURES_SETUP paint_copies)

# grass_cli_test plus the fixture and, optionally, the test it must follow (same copy).
# PARSE_ARGV, not ${ARGN}: it keeps the ';' inside a stroke's text in one argument.
function(paint_cli_test name after)
    cmake_parse_arguments(PARSE_ARGV 2 PASS "" "" "")
    grass_cli_test(${name} ${PASS_UNPARSED_ARGUMENTS})
    set_tests_properties(cli.${name} PROPERTIES FIXTURES_REQUIRED paint_copies)
    if(after)
        set_tests_properties(cli.${name} PROPERTIES DEPENDS cli.${after})
    endif()
endfunction()
# A plain shell check on a copy (what expect_ok.sh cannot say: a file unchanged, a folder
# absent, a line of project.json that must not be deleted first).
function(paint_check name after script)
    add_test(NAME cli.${name} COMMAND ${GRASS_BASH} -c "${script}" ${ARGN})
    set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 30
                         FIXTURES_REQUIRED paint_copies DEPENDS cli.${after})
endfunction()

grass_cli_test(paint_help OK --no-stderr
    --stdout "^usage: grass paint" --stdout "^  --map density\\|soil\\|light\\|cut" --stdout "^  --stroke "
    --stdout "^  --uv" --stdout "^  --dry-run" --stdout "^  --help"
    -- ${GRASS_BIN} paint --help)

# --- a new soil map, painted, saved, named in project.json, then painted again -----------------
set(SOIL ${PAINT_TMP}/soil)
paint_cli_test(paint_soil_new "" OK --png ${SOIL}/maps/grass-soil.png 64 64
    --stdout "^soil map of layer \"grass\": new, 64x64"
    --stdout "^stroke 1: 3 points, [1-9][0-9]* dabs, [1-9][0-9]* texels changed, bounds .*; re-grew [1-9][0-9]* of [1-9][0-9]* patches in [0-9.]+ ms$"
    --stdout "^total: 1 strokes, [1-9][0-9]* dabs, [1-9][0-9]* texels changed"
    --stdout "^wrote .*maps/grass-soil\\.png \\(64x64\\)$"
    --stdout "^updated .*project\\.json: layer \"grass\" soil_map = \"maps/grass-soil\\.png\"$"
    -- ${GRASS_BIN} paint ${SOIL} --map soil --mode subtract --strength 1 --radius 0.2
       --stroke "-0.8,0,-0.8; -0.5,0,-0.6; -0.3,0,-0.8")
paint_check(paint_soil_project_names_map paint_soil_new
    "grep -Eq '\"soil_map\": \"maps/grass-soil\\.png\"' \"$0/project.json\"" ${SOIL})
paint_cli_test(paint_soil_again paint_soil_project_names_map OK
    --stdout "^soil map of layer \"grass\": loaded maps/grass-soil\\.png at 64x64"
    --stdout "^stroke 1: .* [1-9][0-9]* texels changed"
    --stdout "^stroke 2: .* [1-9][0-9]* texels changed"
    --stdout "^total: 2 strokes, .* re-grew [1-9][0-9]* of"
    --stdout "^wrote .*maps/grass-soil\\.png"
    -- ${GRASS_BIN} paint ${SOIL}/project.json --map soil --mode smooth --strength 1
       --stroke "-0.9,0,-0.55; -0.2,0,-0.55" --stroke "-0.5,0,0.5; -0.5,0,-0.5")
# The painted copy renders with Kim & Cho's stem sets (SPEC §9), grown from the painted soil.
paint_cli_test(render_technique_growth paint_soil_again GL OK
    --stdout "^  technique  growth; .*stem sets drawn [1-9][0-9]*$"
    --file ${GRASS_CLI_TMP}/growth-stats.json "\"stem_sets\": \\{\"drawn\": [1-9][0-9]*,"
    -- ${GRASS_BIN} render ${SOIL} --technique growth --frames 1 --width 64 --height 48
       --out ${GRASS_CLI_TMP}/growth.png --stats ${GRASS_CLI_TMP}/growth-stats.json)

# --- density in UV space, to a chosen file; live blades drop ----------------------------------
set(UV ${PAINT_TMP}/uv)
paint_cli_test(paint_density_uv "" OK --png ${UV}/painted/density.png 64 64
    --stdout "^stroke 1: 2 points, [1-9][0-9]* dabs, [1-9][0-9]* texels changed"
    --stdout "^live blades [0-9]+ -> [0-9]+$"
    --stdout "^updated .*density_map = \"painted/density\\.png\"$"
    -- ${GRASS_BIN} paint ${UV} --map density --uv --stroke "0.1,0.5; 0.9,0.5" --mode set
       --value 0 --strength 1 --falloff constant --radius 0.2 --file painted/density.png)

# --- --dry-run paints and reports, writes nothing ---------------------------------------------
set(DRY ${PAINT_TMP}/dry)
paint_cli_test(paint_light_dry_run "" OK
    --stdout "^stroke 1: .* [1-9][0-9]* texels changed" --stdout "^dry run: nothing written"
    -- ${GRASS_BIN} paint ${DRY} --map light --mode subtract --stroke "0,0,0; 0.5,0,0" --dry-run)
paint_check(paint_light_dry_run_wrote_nothing paint_light_dry_run
    "test ! -e \"$0/maps\" && cmp -s \"$0/project.json\" \"$1/project.json\"" ${DRY} ${PAINT_SOURCE})

# --- errors: one line naming the option, nothing written --------------------------------------
set(ERR ${PAINT_TMP}/errors)
paint_cli_test(paint_layer_unknown "" ERROR "--layer" --also "nosuch" --also "layers: grass"
    --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --layer nosuch --stroke "0,0,0")
paint_cli_test(paint_map_unknown "" ERROR "--map" --also "dirt" --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map dirt --stroke "0,0,0")
paint_cli_test(paint_stroke_malformed "" ERROR "--stroke" --also "stroke 2, point 2"
    --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --stroke "0,0,0" --stroke "0,0,0; 1,0; 2,0,0")
paint_cli_test(paint_stroke_not_finite "" ERROR "--stroke" --also "stroke 1, point 1"
    --also "finite" --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --stroke "nan,0,0")
paint_cli_test(paint_strength_out_of_range "" ERROR "--strength" --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --strength 2 --stroke "0,0,0")
paint_cli_test(paint_radius_zero "" ERROR "--radius" --also "1e-06" --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --radius 0 --stroke "0,0,0")
paint_cli_test(paint_uv_off_mesh "" ERROR "--stroke" --also "not on the mesh"
    --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --uv --stroke "0.5,0.5; 1.5,0.5")
paint_cli_test(paint_file_leaves_project "" ERROR "--file" --absent ${ERR}/maps
    -- ${GRASS_BIN} paint ${ERR} --map soil --stroke "0,0,0" --file ../soil.png)
paint_cli_test(paint_project_missing "" ERROR "no-such-project"
    -- ${GRASS_BIN} paint ${PAINT_TMP}/no-such-project --map soil --stroke "0,0,0")

# --- a surface without UVs (issue 27): painted in a generated atlas, which the paint keeps ------
# projects/terrain_rules is copied (painting writes into the project); the stroke thins the cliff
# moss on the Rock face, and terrain.uvatlas is written and named in project.json.
set(ATLAS ${PAINT_TMP}/atlas)
add_test(NAME cli.paint_atlas_setup
         COMMAND ${GRASS_BASH} -c "rm -rf -- \"$0\" && mkdir -p -- \"$0\" && cp -R -- \"$1/.\" \"$0\""
                 ${ATLAS} ${CMAKE_SOURCE_DIR}/projects/terrain_rules)
set_tests_properties(cli.paint_atlas_setup PROPERTIES LABELS cli TIMEOUT 30
                     FIXTURES_SETUP paint_atlas_copy)
grass_cli_test(paint_atlas_kept OK
    --stdout "^stroke 1: .* [1-9][0-9]* texels changed"
    --stdout "^wrote .*terrain\\.uvatlas: the UVs the map is painted in$"
    --stdout "^updated .*project\\.json: layer \"cliff moss\" density_map = "
    -- ${GRASS_BIN} paint ${ATLAS} --layer "cliff moss" --map density --mode subtract
       --strength 1 --radius 0.5 --stroke "6.9,1.6,0")
set_tests_properties(cli.paint_atlas_kept PROPERTIES FIXTURES_REQUIRED paint_atlas_copy)
add_test(NAME cli.paint_atlas_named
         COMMAND ${GRASS_BASH} -c "grep -q '\"uv_atlas\": \"terrain.uvatlas\"' \"$0/project.json\" && test -s \"$0/terrain.uvatlas\""
                 ${ATLAS})
set_tests_properties(cli.paint_atlas_named PROPERTIES LABELS cli TIMEOUT 30
                     FIXTURES_REQUIRED paint_atlas_copy DEPENDS cli.paint_atlas_kept)

# --- cut and regrow (issue 30 item 10): a path mown to a fifth of the blades' height ---------
set(CUT ${PAINT_TMP}/cut)
paint_cli_test(paint_cut_new "" OK --png ${CUT}/maps/grass-cut.png 64 64
    --stdout "^cut map of layer \"grass\": new, 64x64"
    --stdout "^stroke 1: 2 points, [1-9][0-9]* dabs, [1-9][0-9]* texels changed, .*re-grew [1-9][0-9]* of"
    --stdout "^updated .*project\\.json: layer \"grass\" cut_map = \"maps/grass-cut\\.png\"$"
    -- ${GRASS_BIN} paint ${CUT} --map cut --mode set --value 0.2 --strength 1 --radius 0.25
       --stroke "-0.9,0,0; 0.9,0,0")
paint_check(paint_cut_project_names_map paint_cut_new
    "grep -Eq '\"cut_map\": \"maps/grass-cut\\.png\"' \"$0/project.json\"" ${CUT})
paint_cli_test(render_cut_regrown paint_cut_project_names_map GL OK
    --stdout "^simulated  0\\.500 s"
    -- ${GRASS_BIN} render ${CUT} --time 0.5 --frames 1 --width 64 --height 48
       --out ${GRASS_CLI_TMP}/cut.png)
