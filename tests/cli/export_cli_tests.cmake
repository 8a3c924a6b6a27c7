# grass export (issue 8): help, both formats on a small project, the one-line errors of bad
# options and bad output folders, and the Khronos glTF-Validator on exported files (the
# validator is an npm package, installed by tests/export/install_validator.sh into
# <build>/gltf-validator; ./quickstart.sh test does it; the validation tests fail without it).
# No GL: export grows the field on the CPU.

set(GRASS_EXPORT_TMP ${GRASS_CLI_TMP}/export)
set(GRASS_VALIDATOR_DIR ${CMAKE_BINARY_DIR}/gltf-validator)

grass_cli_test(export_help OK --no-stderr
    --stdout "^usage: grass export" --stdout "^  --out DIR" --stdout "^  --format gltf\\|raw"
    --stdout "^  --lod N" --stdout "^  --help"
    -- ${GRASS_BIN} export --help)
grass_cli_test(export_tiny_gltf OK
    --file ${GRASS_EXPORT_TMP}/tiny-gltf/grass.gltf "EXT_mesh_gpu_instancing"
    --stdout "^layer \"grass\": [1-9][0-9]* live blades, [1-9][0-9]* instances$"
    --stdout "^wrote .*grass\\.gltf \\([0-9]+ bytes\\)$" --stdout "^wrote .*grass-[0-9a-f]{16}\\.bin "
    --stderr "^note: export +100%"
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_EXPORT_TMP}/tiny-gltf)
grass_cli_test(export_tiny_raw OK
    --file ${GRASS_EXPORT_TMP}/tiny-raw/manifest.json "\"format\": \"grass-raw-export\""
    --stdout "^wrote .*grass\\.blades-[0-9a-f]{16}\\.bin "
    --stdout "^wrote .*grass\\.patches-[0-9a-f]{16}\\.bin "
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_EXPORT_TMP}/tiny-raw
       --format raw)

# Bad command lines: one line naming the option, nothing written.
grass_cli_test(export_unknown_format ERROR "--format: unknown format \"fbx\" (gltf, raw, glb, mesh)"
    --absent ${GRASS_EXPORT_TMP}/fbx
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_EXPORT_TMP}/fbx --format fbx)
# A mesh where the project goes: the error says which commands take a mesh.
grass_cli_test(export_mesh_as_project ERROR "cube.glb: is a glTF mesh, not a project"
    --also "grass-editor cube.glb" --also "grass render cube.glb"
    --absent ${GRASS_EXPORT_TMP}/from-mesh
    -- ${GRASS_BIN} export ${GRASS_CLI_GLTF}/cube.glb --out ${GRASS_EXPORT_TMP}/from-mesh)
grass_cli_test(export_lod_out_of_range ERROR "--lod" --also "99"
    --absent ${GRASS_EXPORT_TMP}/lod99
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_EXPORT_TMP}/lod99 --lod 99)
grass_cli_test(export_lod_not_a_number ERROR "--lod" --also "'x'"
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_EXPORT_TMP}/lodx --lod x)
grass_cli_test(export_lod_with_raw ERROR "--lod: applies to --format gltf, glb and mesh only"
    --absent ${GRASS_EXPORT_TMP}/raw-lod
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_EXPORT_TMP}/raw-lod
       --format raw --lod 2)
grass_cli_test(export_missing_out ERROR "--out: missing" --also "--out exported/gltf"
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny)
grass_cli_test(export_missing_project ERROR "project"
    -- ${GRASS_BIN} export --out ${GRASS_EXPORT_TMP}/none)
grass_cli_test(export_project_not_found ERROR "no-such-project"
    --absent ${GRASS_EXPORT_TMP}/not-found
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/no-such-project --out ${GRASS_EXPORT_TMP}/not-found)
# A file where the folder should be: named, left as it was.
grass_cli_test(export_out_is_a_file ERROR "--out" --also "is not a folder"
    -- ${GRASS_BIN} export ${GRASS_CLI_PROJECTS}/tiny --out ${GRASS_CLI_PROJECTS}/tiny/project.json)

# The Khronos validator on exported glTF: a procedural plane, a glTF mesh with a cube (rock),
# a textured glTF surface, a LOD, and projects/meadow (58,942 blades, the three painted maps as PNG images).
function(grass_export_validate_test name project)
    add_test(NAME cli.export_validate_${name}
        COMMAND ${GRASS_BASH} ${CMAKE_CURRENT_SOURCE_DIR}/export/export_and_validate.sh
            ${GRASS_BIN} ${GRASS_VALIDATOR_DIR} ${GRASS_EXPORT_TMP}/validate-${name} ${project}
            ${ARGN})
    set_tests_properties(cli.export_validate_${name} PROPERTIES LABELS "cli;export" TIMEOUT 300)
endfunction()
grass_export_validate_test(tiny ${GRASS_CLI_PROJECTS}/tiny)
grass_export_validate_test(growth_tiny_lod2 ${GRASS_CLI_PROJECTS}/growth_tiny --lod 2)
grass_export_validate_test(rock ${GRASS_CLI_PROJECTS}/rock)
grass_export_validate_test(meadow ${GRASS_SOURCE_DIR}/projects/meadow)
grass_export_validate_test(meadow_glb ${GRASS_SOURCE_DIR}/projects/meadow --format glb)
grass_export_validate_test(meadow_mesh ${GRASS_SOURCE_DIR}/projects/meadow --format mesh)
# A glTF surface with a base-colour and a normal texture: both travel embedded, with tangents.
grass_export_validate_test(textured_stone ${GRASS_CLI_PROJECTS}/textured_stone)
grass_export_validate_test(textured_stone_glb ${GRASS_CLI_PROJECTS}/textured_stone --format glb)

# A stock third-party loader (three.js' GLTFLoader) draws the meadow's export as the field at
# rest: every blade an instance, tips and colours as the raw export's exact blades (issue 25).
add_test(NAME cli.export_stock_loader_meadow
    COMMAND ${GRASS_BASH} ${CMAKE_CURRENT_SOURCE_DIR}/export/export_stock_loader.sh
        ${GRASS_BIN} ${GRASS_VALIDATOR_DIR} ${GRASS_EXPORT_TMP}/stock-meadow
        ${GRASS_SOURCE_DIR}/projects/meadow)
set_tests_properties(cli.export_stock_loader_meadow PROPERTIES LABELS "cli;export" TIMEOUT 300)
add_test(NAME cli.export_stock_loader_meadow_glb
    COMMAND ${GRASS_BASH} ${CMAKE_CURRENT_SOURCE_DIR}/export/export_stock_loader.sh
        ${GRASS_BIN} ${GRASS_VALIDATOR_DIR} ${GRASS_EXPORT_TMP}/stock-meadow-glb
        ${GRASS_SOURCE_DIR}/projects/meadow glb)
set_tests_properties(cli.export_stock_loader_meadow_glb PROPERTIES LABELS "cli;export" TIMEOUT 300)
