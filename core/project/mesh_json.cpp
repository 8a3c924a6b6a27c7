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
bool isFileMesh(const MeshSource& mesh) { return mesh.isFile; }

constexpr std::string_view ONLY_WITH_FILE =
    "only allowed with \"file\" (procedural meshes are made in metres, +Y up)";

// "unit": a name or the metres one unit of the file measures.
void readUnit(json::Reader& reader, json::Object& object, std::string_view key, MeshSource& mesh) {
    const Json* value = object.find(key);
    if (!value)
        return;
    Result<float> parsed = makeError("", "must be a unit name (\"mm\", \"cm\", \"m\", \"in\", "
                                         "\"ft\") or a number of metres per unit");
    if (value->is_string())
        parsed = parseMeshUnit(value->get<std::string>());
    else if (value->is_number())
        parsed = parseMeshUnit(meshUnitText(value->get<float>()));
    if (parsed)
        mesh.metresPerUnit = *parsed;
    else
        reader.fail(object.pointerTo(key), parsed.error().message);
}

Json unitJson(const MeshSource& mesh) {
    if (!mesh.isFile || mesh.metresPerUnit == 1.0f)
        return Json();
    const std::string text = meshUnitText(mesh.metresPerUnit);
    for (const MeshUnit& unit : MESH_UNITS)
        if (text == unit.name)
            return Json(text);
    return Json(mesh.metresPerUnit);
}

void readUp(json::Reader& reader, json::Object& object, std::string_view key, MeshSource& mesh) {
    const Json* value = object.find(key);
    if (!value)
        return;
    const auto parsed = value->is_string() ? parseUpAxis(value->get<std::string>())
                                           : Result<UpAxis>(makeError("", "must be \"+Y\" or \"+Z\""));
    if (parsed)
        mesh.up = *parsed;
    else
        reader.fail(object.pointerTo(key), parsed.error().message);
}

Json upJson(const MeshSource& mesh) {
    return mesh.isFile && mesh.up != UpAxis::Y ? Json(std::string(upAxisText(mesh.up))) : Json();
}

// A setting of a file's frame: refused with a procedural mesh.
constexpr settings::Setting<MeshSource> fileOnly(settings::Setting<MeshSource> row) {
    row.applies = isFileMesh;
    row.onlyText = ONLY_WITH_FILE;
    return row;
}

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

void readUvAtlas(json::Reader& reader, json::Object& object, std::string_view key, MeshSource& mesh) {
    if (!object.find(key))
        return;
    object.readString(key, false, mesh.uvAtlas);
    json::checkAssetPath(reader, object.pointerTo(key), mesh.uvAtlas);
}

void readFileMaterial(json::Reader&, json::Object& object, std::string_view key, MeshSource& mesh) {
    if (object.find(key))
        object.readBool(key, mesh.fileMaterial);
}

Json fileMaterialJson(const MeshSource& mesh) {
    return mesh.isFile && !mesh.fileMaterial ? Json(false) : Json();
}

Json uvAtlasJson(const MeshSource& mesh) {
    return mesh.isFile && !mesh.uvAtlas.empty() ? Json(mesh.uvAtlas) : Json();
}

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
         .allowedText = "a relative asset path ending in `.gltf` or `.glb`; when present, only "
                        "`unit`, `up`, `uv_atlas` and `file_material` may join it",
         .defaultText = "absent"},
        readMeshFile, meshFileJson),
    fileOnly(settings::custom<MeshSource>(
        {.key = "unit",
         .help = "what one unit of the file measures: the mesh is scaled to metres on load",
         .typeText = "string or number",
         .allowedText = "`\"mm\"`, `\"cm\"`, `\"m\"`, `\"in\"`, `\"ft\"`, or metres per unit in "
                        "[1e-6, 1e6]",
         .defaultText = "`\"m\"`"},
        readUnit, unitJson)),
    fileOnly(settings::custom<MeshSource>(
        {.key = "up",
         .help = "the file's up axis: +Z up is turned to grass's +Y up on load",
         .typeText = "string",
         .allowedText = "`\"+Y\"`, `\"+Z\"`",
         .defaultText = "`\"+Y\"`"},
        readUp, upJson)),
    fileOnly(settings::custom<MeshSource>(
        {.key = "uv_atlas",
         .help = "the generated UVs maps are painted in when the file's are missing or overlap "
                 "(see [maps](#maps)); written by a save, not by hand",
         .typeText = "string",
         .allowedText = "a relative asset path",
         .defaultText = "absent"},
        readUvAtlas, uvAtlasJson)),
    fileOnly(settings::custom<MeshSource>(
        {.key = "file_material",
         .help = "draw and export the surface in the file's own material (its base colour and "
                 "base-colour texture); `false`: in `render.ground_color`, as a procedural "
                 "surface (for a file whose default white material shows between the blades)",
         .typeText = "boolean",
         .allowedText = "`true`, `false`",
         .defaultText = "`true`"},
        readFileMaterial, fileMaterialJson)),
    procedural(settings::custom<MeshSource>(
        {.key = "procedural",
         .typeText = "string",
         .allowedText = "`\"plane\"`, `\"hills\"`, `\"sphere\"`, `\"torus\"`, `\"moebius\"`"},
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
