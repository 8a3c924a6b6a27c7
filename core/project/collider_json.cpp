// A "colliders" entry of project.json (SPEC §5): a sphere, or a glTF mesh packed into spheres.
#include <array>

#include "collider/sphere_packing.h"
#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;
using settings::Kind;

constexpr std::array<std::string_view, 2> SHAPE_NAMES{"sphere", "mesh"};
constexpr std::string_view MESH_ONLY = "only for \"shape\": \"mesh\" colliders";

bool isMesh(const ColliderDesc& collider) { return collider.shape == ColliderShape::Mesh; }
bool isSphere(const ColliderDesc& collider) { return !isMesh(collider); }

void readColor(json::Reader& /*reader*/, json::Object& object, std::string_view key,
               ColliderDesc& collider) {
    if (object.find(key) == nullptr)
        return;
    glm::vec3 color{0.0f};
    object.readVec3(key, json::UNIT_INTERVAL, "[r, g, b]", color);
    collider.color = color;
}

Json colorJson(const ColliderDesc& collider) {
    return collider.color ? json::jsonVec3(*collider.color) : Json();
}

void readFile(json::Reader& reader, json::Object& object, std::string_view key,
              ColliderDesc& collider) {
    if (!object.find(key)) {
        reader.fail(object.pointerTo(key),
                    "missing required key (a mesh collider names its .gltf or .glb file)");
        return;
    }
    object.readString(key, false, collider.file);
    json::checkAssetPath(reader, object.pointerTo(key), collider.file);
}

Json fileJson(const ColliderDesc& collider) { return collider.file; }

constexpr std::array COLLIDER{
    field<&ColliderDesc::name>({.key = "name", .help = "unique among colliders"}),
    field<&ColliderDesc::shape>({.key = "shape", .names = SHAPE_NAMES}),
    field<&ColliderDesc::position>(
        {.key = "position",
         .help = "the sphere centre or the mesh origin (replaced by `path` when given)"}),
    settings::custom<ColliderDesc>(
        {.key = "color",
         .typeText = "[r, g, b]",
         .allowedText = "each in [0, 1]; the colour the prop is drawn with (absent: grey spheres, "
                        "stone meshes)",
         .defaultText = "absent"},
        readColor, colorJson),
    field<&ColliderDesc::radiusM>(
        {.key = "radius",
         .rule = json::POSITIVE,
         .unit = "m",
         .help = "sphere only",
         .applies = isSphere,
         .onlyText = "only for \"shape\": \"sphere\" colliders (a mesh collider takes \"scale\")",
         .ui = {.min = 0.01f, .max = 100.0f}}),
    settings::custom<ColliderDesc>({.key = "file",
                                    .typeText = "string",
                                    .allowedText = "mesh only: a relative `.gltf`/`.glb` asset path",
                                    .defaultText = "**required** for meshes",
                                    .applies = isMesh,
                                    .onlyText = MESH_ONLY},
                                   readFile, fileJson),
    field<&ColliderDesc::scale>({.key = "scale",
                                 .rule = json::POSITIVE,
                                 .help = "mesh only: uniform scale of the file's coordinates",
                                 .applies = isMesh,
                                 .onlyText = MESH_ONLY,
                                 .ui = {.min = 0.001f, .max = 1000.0f, .decimals = 3}}),
    field<&ColliderDesc::sphereCount>({.key = "spheres",
                                       .intMin = 1,
                                       .intMax = MAX_PACKED_SPHERES,
                                       .help = "mesh only: spheres to pack it into",
                                       .applies = isMesh,
                                       .onlyText = MESH_ONLY}),
    field<&ColliderDesc::packingResolution>(
        {.key = "packing_resolution",
         .intMin = MIN_PACKING_RESOLUTION,
         .intMax = MAX_PACKING_RESOLUTION,
         .help = "mesh only: voxels along the longest side when packing",
         .applies = isMesh,
         .onlyText = MESH_ONLY}),
    json::pathSetting<&ColliderDesc::path>(
        {.key = "path",
         .allowedText = "keys as in [wind](#wind); the collider's position over time"}),
};

}  // namespace

std::span<const settings::Setting<ColliderDesc>> settings::collider() { return COLLIDER; }

}  // namespace grass::core
