// The project.json schema in both directions: parseProject reads and validates every field,
// serializeProject writes every field in the documented order (docs/project-format.md). Key
// names appear here only; keep the reader, the writer and the doc in step.
#include "project/project.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "project/project_json_parts.h"
#include "util/byte_size.h"

namespace grass::core {

namespace {

using json::checkAssetPath;
using json::Json;
using json::jsonFloat;
using json::jsonRange;
using json::jsonVec3;
using json::readList;

constexpr std::string_view FORMAT_NAME = "grass-project";

constexpr std::array<std::string_view, 15> TOP_KEYS{
    "format",   "version", "name",       "seed",    "mesh", "layers",    "cameras", "sun",
    "lighting", "render",  "billboards", "physics", "wind", "colliders", "snow"};
constexpr std::array<std::string_view, 8> MESH_KEYS{"file",       "procedural",  "size",
                                                    "minor_size", "hill_height", "hill_scale",
                                                    "resolution", "noise_seed"};
constexpr std::array<std::string_view, 15> LAYER_KEYS{
    "name",           "density",       "density_map",      "soil_map",     "light_map",
    "map_resolution", "clump_spacing", "blades_per_clump", "clump_radius", "blade",
    "shape",          "tip_start",     "root_color",       "tip_color",    "growth"};
constexpr std::array<std::string_view, 3> BLADE_KEYS{"height", "width", "stiffness"};
constexpr std::array<std::string_view, 4> CAMERA_KEYS{"name", "position", "target", "fov_y_deg"};
constexpr std::array<std::string_view, 3> SUN_KEYS{"direction", "color", "intensity"};
constexpr std::array<std::string_view, 12> RENDER_KEYS{
    "width",      "height",    "geometry",     "tess_level", "strip_segments", "msaa",
    "patch_size", "sky_color", "ground_color", "technique",  "lod_distance",   "thinning_distance"};
// Camera distances beyond 100 km are typos (and push the LOD bands out of float range).
constexpr json::NumberRule DISTANCE_OR_OFF{0.0, 1e5};

constexpr int MAX_IMAGE_SIDE = 16384;
constexpr int MAX_MESH_RESOLUTION = 1024;
// Blades per clump: beyond this a clump is a carpet, and a typo (12000 for 12) would stall.
constexpr int MAX_BLADES_PER_CLUMP = 10000;
// Blades up to 100 m tall and 10 m wide (ours are 0.15-0.9 m): far beyond, the float positions
// of a blade's control points lose the bits its length is kept to (1e30 broke it by 100 %).
constexpr json::NumberRule BLADE_HEIGHT_RULE{0.0, 100.0, true, false};
constexpr json::NumberRule BLADE_WIDTH_RULE{0.0, 10.0, true, false};
// The cull shader's work-group is 32 blades; a patch is whole groups.
constexpr std::uint32_t PATCH_GRANULE = 32;
constexpr std::uint32_t MAX_PATCH_SIZE = 65536;

constexpr std::string_view XYZ = "[x, y, z]";
constexpr std::string_view RGB = "[r, g, b]";

std::array<std::string_view, 3> geometryNames() {
    return {geometryPathName(GeometryPath::Auto), geometryPathName(GeometryPath::Tessellation),
            geometryPathName(GeometryPath::Strips)};
}

void readMesh(json::Reader& reader, const Json& node, MeshSource& mesh) {
    json::Object object(reader, node, "/mesh", MESH_KEYS);
    if (!object.valid())
        return;
    if (object.find("file")) {
        for (const std::string_view key : MESH_KEYS) {
            if (key != "file" && object.find(key))
                reader.fail(object.pointerTo(key),
                            "not allowed with \"file\" (it is a parameter of procedural meshes)");
        }
        mesh.isFile = true;
        object.readString("file", false, mesh.file);
        checkAssetPath(reader, "/mesh/file", mesh.file);
        const std::string extension = std::filesystem::path(mesh.file).extension().string();
        if (reader.ok() && extension != ".gltf" && extension != ".glb")
            reader.fail("/mesh/file", "must be a glTF file ending in .gltf or .glb (got " +
                                          json::quote(mesh.file) + ")");
        return;
    }
    ProceduralMeshParams& params = mesh.procedural;
    if (const Json* shape = object.find("procedural")) {
        const std::vector<std::string_view> names = proceduralShapeNames();
        std::size_t index = 0;
        if (reader.readEnum(*shape, "/mesh/procedural", names, index)) {
            const auto parsed = parseProceduralShape(names[index]);
            if (parsed)
                params.shape = *parsed;
            else
                reader.fail("/mesh/procedural", parsed.error().message);
        }
    }
    object.readFloat("size", json::POSITIVE, params.size);
    object.readFloat("minor_size", json::POSITIVE, params.minorSize);
    object.readFloat("hill_height", json::NON_NEGATIVE, params.hillHeight);
    object.readFloat("hill_scale", json::POSITIVE, params.hillScale);
    object.readInt("resolution", 1, MAX_MESH_RESOLUTION, params.resolution);
    object.readUint64("noise_seed", params.noiseSeed);
}

// [width, height] of a layer's maps; a side beyond the limit is refused with the memory the map
// would take (float texels), since each map of the layer is allocated at this size.
void readMapResolution(json::Reader& reader, const json::Object& object, glm::ivec2& resolution) {
    const Json* size = object.find("map_resolution");
    if (!size)
        return;
    const std::string at = object.pointerTo("map_resolution");
    if (!size->is_array() || size->size() != 2) {
        reader.fail(at, "must be an array of 2 integers [width, height] (got " +
                            json::describeValue(*size) + ")");
        return;
    }
    const auto side = [&](std::size_t i) {
        const Json& value = (*size)[i];
        return value.is_number_integer() ? value.get<double>() : 0.0;
    };
    for (std::size_t i = 0; i < 2; ++i) {
        if (side(i) <= MAX_MAP_RESOLUTION)
            continue;
        const double width = side(0) > 0.0 ? side(0) : side(1);
        const double height = side(1) > 0.0 ? side(1) : side(0);
        const auto texels = [](double w, double h) {
            char text[64];
            std::snprintf(text, sizeof text, "%.0f×%.0f", w, h);
            return std::string(text);
        };
        const auto bytes = [](double w, double h) {
            return byteSizeText(w * h * static_cast<double>(sizeof(float)));
        };
        const auto limit = static_cast<double>(MAX_MAP_RESOLUTION);
        reader.fail(json::childPointer(at, i),
                    "must be an integer in 1.." + std::to_string(MAX_MAP_RESOLUTION) + " (got " +
                        json::describeValue((*size)[i]) + ": a " + texels(width, height) +
                        " map would take " + bytes(width, height) +
                        " of float texels; the limit, " + texels(limit, limit) + ", takes " +
                        bytes(limit, limit) + ")");
        return;
    }
    std::int64_t width = 0, height = 0;
    if (reader.readInt((*size)[0], json::childPointer(at, 0), 1, MAX_MAP_RESOLUTION, width) &&
        reader.readInt((*size)[1], json::childPointer(at, 1), 1, MAX_MAP_RESOLUTION, height))
        resolution = {static_cast<int>(width), static_cast<int>(height)};
}

void readLayer(json::Reader& reader, const Json& node, const std::string& pointer,
               GrassLayer& layer) {
    json::Object object(reader, node, pointer, LAYER_KEYS);
    object.readString("name", false, layer.name);
    ScatterParams& scatter = layer.scatter;
    object.readFloat("density", json::NON_NEGATIVE, scatter.density);
    const auto readMapPath = [&](std::string_view key, std::string& path) {
        object.readString(key, true, path);
        if (!path.empty())
            checkAssetPath(reader, object.pointerTo(key), path);
    };
    readMapPath("density_map", layer.densityMap);
    readMapPath("soil_map", layer.soilMap);
    readMapPath("light_map", layer.lightMap);
    readMapResolution(reader, object, layer.mapResolution);
    object.readFloat("clump_spacing", json::NON_NEGATIVE, scatter.clumpSpacing);
    object.readInt("blades_per_clump", 0, MAX_BLADES_PER_CLUMP, scatter.bladesPerClump);
    object.readFloat("clump_radius", json::NON_NEGATIVE, scatter.clumpRadius);
    if (const Json* blade = object.find("blade")) {
        json::Object ranges(reader, *blade, object.pointerTo("blade"), BLADE_KEYS);
        BladeRanges& b = scatter.blade;
        ranges.readRange("height", BLADE_HEIGHT_RULE, b.heightMin, b.heightMax);
        ranges.readRange("width", BLADE_WIDTH_RULE, b.widthMin, b.widthMax);
        ranges.readRange("stiffness", json::NON_NEGATIVE, b.stiffnessMin, b.stiffnessMax);
    }
    if (const Json* shape = object.find("shape")) {
        std::size_t index = 0;
        if (reader.readEnum(*shape, object.pointerTo("shape"), bladeShapeNames(), index))
            layer.shape = static_cast<BladeShape>(index);
    }
    // τ = 1 would divide by zero in the triangle-tip shape (1 − τ).
    object.readFloat("tip_start", json::NumberRule{0.0, 1.0, false, true}, layer.tipStart);
    object.readVec3("root_color", json::UNIT_INTERVAL, RGB, layer.rootColor);
    object.readVec3("tip_color", json::UNIT_INTERVAL, RGB, layer.tipColor);
    if (const Json* growth = object.find("growth"))
        json::readGrowth(reader, *growth, object.pointerTo("growth"), layer.growth);
}

void readCamera(json::Reader& reader, const Json& node, const std::string& pointer,
                CameraDesc& camera) {
    json::Object object(reader, node, pointer, CAMERA_KEYS);
    object.readString("name", false, camera.name);
    object.readVec3("position", json::ANY_NUMBER, XYZ, camera.position);
    object.readVec3("target", json::ANY_NUMBER, XYZ, camera.target);
    // A field of view of 0 or 180 degrees has no perspective projection.
    object.readFloat("fov_y_deg", json::NumberRule{0.0, 180.0, true, true}, camera.fovYDeg);
    if (reader.ok() && camera.position == camera.target)
        reader.fail(object.pointerTo("target"), "must differ from position (got the same point)");
}

void readSun(json::Reader& reader, const Json& node, SunDesc& sun) {
    json::Object object(reader, node, "/sun", SUN_KEYS);
    object.readVec3("direction", json::ANY_NUMBER, XYZ, sun.direction);
    if (reader.ok() && sun.direction == glm::vec3(0.0f))
        reader.fail("/sun/direction", "must not be [0, 0, 0] (it is the way the light travels)");
    object.readVec3("color", json::UNIT_INTERVAL, RGB, sun.color);
    object.readFloat("intensity", json::NON_NEGATIVE, sun.intensity);
}

void readRender(json::Reader& reader, const Json& node, RenderSettings& render) {
    json::Object object(reader, node, "/render", RENDER_KEYS);
    object.readInt("width", 1, MAX_IMAGE_SIDE, render.width);
    object.readInt("height", 1, MAX_IMAGE_SIDE, render.height);
    if (const Json* geometry = object.find("geometry")) {
        const auto names = geometryNames();
        std::size_t index = 0;
        if (reader.readEnum(*geometry, "/render/geometry", names, index))
            render.geometry = static_cast<GeometryPath>(index);
    }
    object.readInt("tess_level", 1, 64, render.tessLevel);
    object.readInt("strip_segments", 1, 32, render.stripSegments);
    if (const Json* msaa = object.find("msaa")) {
        const std::uint64_t samples = msaa->is_number_unsigned() ? msaa->get<std::uint64_t>() : 3;
        const bool valid = samples <= 8 && (samples == 0 || std::has_single_bit(samples));
        if (valid)
            render.msaaSamples = msaa->get<int>();
        else
            reader.fail("/render/msaa",
                        "must be 0, 1, 2, 4 or 8 samples (got " + json::describeValue(*msaa) + ")");
    }
    if (const Json* patch = object.find("patch_size")) {
        const bool valid = patch->is_number_unsigned() && patch->get<std::uint64_t>() > 0 &&
                           patch->get<std::uint64_t>() <= MAX_PATCH_SIZE &&
                           patch->get<std::uint64_t>() % PATCH_GRANULE == 0;
        if (valid)
            render.patchSize = patch->get<std::uint32_t>();
        else
            reader.fail("/render/patch_size",
                        "must be a positive multiple of 32 up to 65536 (got " +
                            json::describeValue(*patch) + ")");
    }
    object.readVec3("sky_color", json::UNIT_INTERVAL, RGB, render.skyColor);
    object.readVec3("ground_color", json::UNIT_INTERVAL, RGB, render.groundColor);
    if (const Json* technique = object.find("technique")) {
        std::size_t index = 0;
        if (reader.readEnum(*technique, "/render/technique", json::TECHNIQUE_NAMES, index))
            render.technique = static_cast<GrassTechnique>(index);
    }
    object.readFloat("lod_distance", DISTANCE_OR_OFF, render.lodDistanceM);
    object.readFloat("thinning_distance", DISTANCE_OR_OFF, render.thinningDistanceM);
    const double bytes = framebufferBytes(render.width, render.height, render.msaaSamples);
    if (reader.ok() && bytes > MAX_FRAMEBUFFER_BYTES)
        reader.fail("/render",
                    "width × height at msaa must fit the frame buffer limit, " +
                        byteSizeText(MAX_FRAMEBUFFER_BYTES) + " (got " +
                        std::to_string(render.width) + "×" + std::to_string(render.height) +
                        " at " + std::to_string(render.msaaSamples) +
                        " samples: " + byteSizeText(bytes) + "): lower width, height or msaa");
}

void readHeader(json::Reader& reader, const Json& root) {
    // Format and version first: a file that is not a project (or is a newer one) should say
    // so, not list the keys this build does not know.
    const std::string readsVersion =
        "this build reads version " + std::to_string(PROJECT_FORMAT_VERSION);
    const auto format = root.find("format");
    if (format == root.end()) {
        reader.fail("/format", "missing required key (a grass project begins {\"format\": \"" +
                                   std::string(FORMAT_NAME) + "\", \"version\": " +
                                   std::to_string(PROJECT_FORMAT_VERSION) + ", ...})");
        return;
    }
    if (!format->is_string() || format->get_ref<const std::string&>() != FORMAT_NAME) {
        reader.fail("/format", "must be \"" + std::string(FORMAT_NAME) + "\" (got " +
                                   json::describeValue(*format) + "); not a grass project file");
        return;
    }
    const auto version = root.find("version");
    if (version == root.end()) {
        reader.fail("/version", "missing required key (" + readsVersion + ")");
        return;
    }
    if (!version->is_number_integer())
        reader.fail("/version", "must be an integer (got " + json::describeValue(*version) + "); " +
                                    readsVersion);
    else if (version->get<std::int64_t>() != PROJECT_FORMAT_VERSION)
        reader.fail("/version", "unsupported version " + json::describeValue(*version) + " (" +
                                    readsVersion + " only)");
}

void readProject(json::Reader& reader, const Json& root, Project& project) {
    if (!root.is_object()) {
        reader.fail("", "a project file must be a JSON object {\"format\": \"" +
                            std::string(FORMAT_NAME) + "\", ...} (got " +
                            json::describeValue(root) + ")");
        return;
    }
    readHeader(reader, root);
    json::Object top(reader, root, "", TOP_KEYS);
    top.readString("name", false, project.name);
    top.readUint64("seed", project.seed);
    if (const Json* mesh = top.find("mesh"))
        readMesh(reader, *mesh, project.mesh);
    if (const Json* layers = top.find("layers"))
        readList(reader, *layers, "/layers", "layer", MAX_LAYERS, project.layers, readLayer);
    if (const Json* cameras = top.find("cameras")) {
        readList(reader, *cameras, "/cameras", "camera", MAX_CAMERAS, project.cameras, readCamera);
        if (reader.ok() && project.cameras.empty())
            reader.fail("/cameras", "must hold at least one camera");
    }
    if (const Json* sun = top.find("sun"))
        readSun(reader, *sun, project.sun);
    if (const Json* lighting = top.find("lighting"))
        json::readLighting(reader, *lighting, project.lighting);
    if (const Json* render = top.find("render"))
        readRender(reader, *render, project.render);
    if (const Json* billboards = top.find("billboards"))
        json::readBillboards(reader, *billboards, project.billboards);
    if (const Json* physics = top.find("physics"))
        json::readPhysics(reader, *physics, project.physics);
    if (const Json* wind = top.find("wind"))
        readList(reader, *wind, "/wind", "wind source", MAX_WIND_SOURCES, project.wind,
                 json::readWind);
    if (const Json* colliders = top.find("colliders"))
        readList(reader, *colliders, "/colliders", "collider", MAX_COLLIDERS, project.colliders,
                 json::readCollider);
    if (const Json* snow = top.find("snow"))
        json::readSnow(reader, *snow, project.snow);
}

Json meshJson(const MeshSource& mesh) {
    Json out = Json::object();
    if (mesh.isFile) {
        out["file"] = mesh.file;
        return out;
    }
    const ProceduralMeshParams& p = mesh.procedural;
    out["procedural"] = std::string(proceduralShapeName(p.shape));
    out["size"] = jsonFloat(p.size);
    out["minor_size"] = jsonFloat(p.minorSize);
    out["hill_height"] = jsonFloat(p.hillHeight);
    out["hill_scale"] = jsonFloat(p.hillScale);
    out["resolution"] = p.resolution;
    out["noise_seed"] = p.noiseSeed;
    return out;
}

Json layerJson(const GrassLayer& layer) {
    const ScatterParams& s = layer.scatter;
    Json out = Json::object();
    out["name"] = layer.name;
    out["density"] = jsonFloat(s.density);
    out["density_map"] = layer.densityMap;
    out["soil_map"] = layer.soilMap;
    out["light_map"] = layer.lightMap;
    out["map_resolution"] = Json::array({layer.mapResolution.x, layer.mapResolution.y});
    out["clump_spacing"] = jsonFloat(s.clumpSpacing);
    out["blades_per_clump"] = s.bladesPerClump;
    out["clump_radius"] = jsonFloat(s.clumpRadius);
    Json blade = Json::object();
    blade["height"] = jsonRange(s.blade.heightMin, s.blade.heightMax);
    blade["width"] = jsonRange(s.blade.widthMin, s.blade.widthMax);
    blade["stiffness"] = jsonRange(s.blade.stiffnessMin, s.blade.stiffnessMax);
    out["blade"] = std::move(blade);
    out["shape"] = std::string(bladeShapeName(layer.shape));
    out["tip_start"] = jsonFloat(layer.tipStart);
    out["root_color"] = jsonVec3(layer.rootColor);
    out["tip_color"] = jsonVec3(layer.tipColor);
    out["growth"] = json::growthJson(layer.growth);
    return out;
}

Json cameraJson(const CameraDesc& camera) {
    Json out = Json::object();
    out["name"] = camera.name;
    out["position"] = jsonVec3(camera.position);
    out["target"] = jsonVec3(camera.target);
    out["fov_y_deg"] = jsonFloat(camera.fovYDeg);
    return out;
}

Json renderJson(const RenderSettings& render) {
    Json out = Json::object();
    out["width"] = render.width;
    out["height"] = render.height;
    out["geometry"] = std::string(geometryPathName(render.geometry));
    out["tess_level"] = render.tessLevel;
    out["strip_segments"] = render.stripSegments;
    out["msaa"] = render.msaaSamples;
    out["patch_size"] = render.patchSize;
    out["sky_color"] = jsonVec3(render.skyColor);
    out["ground_color"] = jsonVec3(render.groundColor);
    out["technique"] = std::string(grassTechniqueName(render.technique));
    out["lod_distance"] = jsonFloat(render.lodDistanceM);
    out["thinning_distance"] = jsonFloat(render.thinningDistanceM);
    return out;
}

std::string scalarText(const Json& value) {
    // Invalid UTF-8 in a name is replaced rather than thrown on.
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// Like dump(2) but with arrays of numbers on one line ("[14.0, 7.0, 14.0]"), which reads
// better for vectors, colours and ranges.
void writeJson(std::string& out, const Json& value, std::size_t indent) {
    const std::string inner(indent + 2, ' ');
    if (value.is_object() && !value.empty()) {
        out += "{\n";
        std::size_t i = 0;
        for (const auto& item : value.items()) {
            out += inner + scalarText(Json(item.key())) + ": ";
            writeJson(out, item.value(), indent + 2);
            out += ++i < value.size() ? ",\n" : "\n";
        }
        out += std::string(indent, ' ') + "}";
    } else if (value.is_array() && !value.empty()) {
        const bool flat = std::none_of(value.begin(), value.end(),
                                       [](const Json& element) { return element.is_structured(); });
        out += flat ? "[" : "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!flat)
                out += inner;
            writeJson(out, value[i], indent + 2);
            if (i + 1 < value.size())
                out += flat ? ", " : ",\n";
        }
        out += flat ? "]" : "\n" + std::string(indent, ' ') + "]";
    } else {
        out += scalarText(value);
    }
}

}  // namespace

void json::checkAssetPath(json::Reader& reader, const std::string& pointer,
                          const std::string& path) {
    if (!reader.ok())
        return;
    const auto resolved = resolveAssetPath({}, path, pointer);
    if (!resolved)
        reader.fail(pointer, resolved.error().message);
}

double framebufferBytes(int width, int height, int msaaSamples) {
    // RGBA8 + DEPTH_COMPONENT32F per sample; resolved RGBA8, depth texture, read-back RGBA8.
    constexpr double BYTES_PER_SAMPLE = 4.0 + 4.0;
    constexpr double BYTES_PER_PIXEL = 4.0 + 4.0 + 4.0;
    const double samples = std::max(1, msaaSamples);
    return static_cast<double>(width) * static_cast<double>(height) *
           (BYTES_PER_SAMPLE * samples + BYTES_PER_PIXEL);
}

std::string_view geometryPathName(GeometryPath path) {
    switch (path) {
        case GeometryPath::Auto:
            return "auto";
        case GeometryPath::Tessellation:
            return "tess";
        case GeometryPath::Strips:
            return "strips";
    }
    return "auto";
}

Result<GeometryPath> parseGeometryPath(std::string_view name) {
    const auto names = geometryNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return static_cast<GeometryPath>(i);
    return makeError("", "unknown geometry path " + json::quote(name) +
                             " (valid: " + json::quotedList(names) + ")");
}

Result<Project> parseProject(std::string_view jsonText, const std::string& sourceName) {
    auto document = json::parseDocument(jsonText, sourceName);
    if (!document)
        return document.error();
    json::Reader reader(sourceName);
    Project project;
    readProject(reader, *document, project);
    if (!reader.ok())
        return reader.error();
    return project;
}

std::string serializeProject(const Project& project) {
    Json document = Json::object();
    document["format"] = std::string(FORMAT_NAME);
    document["version"] = PROJECT_FORMAT_VERSION;
    document["name"] = project.name;
    document["seed"] = project.seed;
    document["mesh"] = meshJson(project.mesh);
    document["layers"] = Json::array();
    for (const GrassLayer& layer : project.layers)
        document["layers"].push_back(layerJson(layer));
    document["cameras"] = Json::array();
    for (const CameraDesc& camera : project.cameras)
        document["cameras"].push_back(cameraJson(camera));
    document["sun"] = Json::object({{"direction", jsonVec3(project.sun.direction)},
                                    {"color", jsonVec3(project.sun.color)},
                                    {"intensity", jsonFloat(project.sun.intensity)}});
    document["lighting"] = json::lightingJson(project.lighting);
    document["render"] = renderJson(project.render);
    document["billboards"] = json::billboardsJson(project.billboards);
    document["physics"] = json::physicsJson(project.physics);
    document["wind"] = Json::array();
    for (const WindDesc& wind : project.wind)
        document["wind"].push_back(json::windJson(wind));
    document["colliders"] = Json::array();
    for (const ColliderDesc& collider : project.colliders)
        document["colliders"].push_back(json::colliderJson(collider));
    document["snow"] = json::snowJson(project.snow);
    std::string text;
    writeJson(text, document, 0);
    text += "\n";
    return text;
}

}  // namespace grass::core
