// The "mesh" section of project.json: a glTF file, or the parameters of a procedural surface.
#include <array>
#include <filesystem>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;

constexpr int MAX_MESH_RESOLUTION = 1024;
constexpr std::string_view NOT_WITH_FILE =
    "not allowed with \"file\" (it is a parameter of procedural meshes)";

bool isProcedural(const MeshSource& mesh) { return !mesh.isFile; }

void readMeshFile(json::Reader& reader, json::Object& object, std::string_view key, MeshSource& mesh) {
    if (!object.find(key))
        return;
    mesh.isFile = true;
    object.readString(key, false, mesh.file);
    json::checkAssetPath(reader, object.pointerTo(key), mesh.file);
    const std::string extension = std::filesystem::path(mesh.file).extension().string();
    if (reader.ok() && extension != ".gltf" && extension != ".glb")
        reader.fail(object.pointerTo(key), "must be a glTF file ending in .gltf or .glb (got " +
                                      json::quote(mesh.file) + ")");
}

Json meshFileJson(const MeshSource& mesh) { return mesh.isFile ? Json(mesh.file) : Json(); }

void readProceduralShape(json::Reader& reader, json::Object& object, std::string_view key, MeshSource& mesh) {
    const Json* shape = object.find(key);
    if (!shape)
        return;
    const std::vector<std::string_view> names = proceduralShapeNames();
    std::size_t index = 0;
    if (!reader.readEnum(*shape, object.pointerTo(key), names, index))
        return;
    if (const auto parsed = parseProceduralShape(names[index]))
        mesh.procedural.shape = *parsed;
    else
        reader.fail(object.pointerTo(key), parsed.error().message);
}

Json proceduralShapeJson(const MeshSource& mesh) {
    return std::string(proceduralShapeName(mesh.procedural.shape));
}

// A parameter of the procedural surface: refused next to "file", which is read first.
constexpr settings::Setting<MeshSource> procedural(settings::Setting<MeshSource> row) {
    row.applies = isProcedural;
    row.onlyText = NOT_WITH_FILE;
    return row;
}

constexpr std::array MESH{
    settings::custom<MeshSource>(
        {.key = "file",
         .typeText = "string",
         .allowedText = "a relative asset path ending in `.gltf` or `.glb`; when present, no "
                        "other key is allowed",
         .defaultText = "absent"},
        readMeshFile, meshFileJson),
    procedural(settings::custom<MeshSource>(
        {.key = "procedural",
         .typeText = "string",
         .allowedText =
             "`\"plane\"`, `\"hills\"`, `\"sphere\"`, `\"torus\"`, `\"moebius\"`"},
        readProceduralShape, proceduralShapeJson)),
    procedural(field<&MeshSource::procedural, &ProceduralMeshParams::size>(
        {.key = "size",
         .rule = json::POSITIVE,
         .help = "Plane and hills: side length; sphere: radius; torus: major radius; Möbius: "
                 "radius of the centre circle"})),
    procedural(field<&MeshSource::procedural, &ProceduralMeshParams::minorSize>(
        {.key = "minor_size",
         .rule = json::POSITIVE,
         .help = "Torus: tube radius; Möbius: half width of the strip"})),
    procedural(field<&MeshSource::procedural, &ProceduralMeshParams::hillHeight>(
        {.key = "hill_height",
         .rule = json::NON_NEGATIVE,
         .help = "Hills: peak-to-trough amplitude"})),
    procedural(field<&MeshSource::procedural, &ProceduralMeshParams::hillScale>(
        {.key = "hill_scale",
         .rule = json::POSITIVE,
         .help = "Hills: feature size (wavelength of the lowest noise octave)"})),
    procedural(field<&MeshSource::procedural, &ProceduralMeshParams::resolution>(
        {.key = "resolution",
         .intMin = 1,
         .intMax = MAX_MESH_RESOLUTION,
         .help = "quads along each parametric direction"})),
    procedural(field<&MeshSource::procedural, &ProceduralMeshParams::noiseSeed>(
        {.key = "noise_seed", .help = "Hills: the noise seed"})),
};

}  // namespace

std::span<const settings::Setting<MeshSource>> settings::mesh() { return MESH; }

}  // namespace grass::core
