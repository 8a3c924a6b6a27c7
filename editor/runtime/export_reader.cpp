#include "runtime/export_reader.h"

#include <cstring>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "blade/blade_shape.h"

namespace grass::runtime {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A problem with one file; readExport turns it into "<file>: <what>".
struct FileError : std::runtime_error {
    fs::path file;
    FileError(fs::path f, const std::string& what) : std::runtime_error(what), file(std::move(f)) {}
};

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw FileError(file, "cannot be opened (missing, or not readable)");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Exactly count records of T from the file the manifest entry names.
template <class T>
std::vector<T> readRecords(const fs::path& folder, const json& entry, std::size_t count) {
    const fs::path file = folder / entry.at("file").get<std::string>();
    const std::string bytes = readBytes(file);
    if (bytes.size() != count * sizeof(T))
        throw FileError(file, "holds " + std::to_string(bytes.size()) + " bytes, the manifest says " +
                                  std::to_string(count) + " records of " +
                                  std::to_string(sizeof(T)) + " (a truncated or replaced file)");
    std::vector<T> records(count);
    if (count > 0)
        std::memcpy(records.data(), bytes.data(), bytes.size());
    return records;
}

glm::vec3 vec3Of(const json& value) {
    if (!value.is_array() || value.size() != 3)
        throw std::runtime_error("expected [x, y, z], got " + value.dump());
    return {value[0].get<float>(), value[1].get<float>(), value[2].get<float>()};
}

std::vector<core::PathKey> pathOf(const json& keys) {
    std::vector<core::PathKey> path;
    for (const json& key : keys)
        path.push_back({key.at("time_s").get<float>(), vec3Of(key.at("position"))});
    return path;
}

core::WindKind windKindOf(const std::string& name) {
    if (name == "directional")
        return core::WindKind::Directional;
    if (name == "point")
        return core::WindKind::Point;
    if (name == "vortex")
        return core::WindKind::Vortex;
    throw std::runtime_error("unknown wind kind \"" + name + "\" (directional, point, vortex)");
}

LayerData readLayer(const fs::path& folder, const json& entry) {
    LayerData layer;
    layer.name = entry.at("name").get<std::string>();
    layer.patchSize = entry.at("patch_size").get<std::uint32_t>();
    layer.liveBlades = entry.at("live_blades").get<std::size_t>();
    const auto shape = core::parseBladeShape(entry.at("shape").get<std::string>());
    if (!shape)
        throw std::runtime_error("layer \"" + layer.name + "\": " + shape.error().message);
    layer.shape = static_cast<int>(*shape);
    layer.tipStart = entry.at("tip_start").get<float>();
    const json& colors = entry.at("colors");
    layer.rootColor = vec3Of(colors.at("root"));
    layer.tipColor = vec3Of(colors.at("tip"));
    layer.poorRootColor = vec3Of(colors.at("poor_root"));
    layer.poorTipColor = vec3Of(colors.at("poor_tip"));
    const std::size_t slots = entry.at("blades").at("count").get<std::size_t>();
    layer.blades = readRecords<core::Blade>(folder, entry.at("blades"), slots);
    if (!entry.contains("shading"))
        throw std::runtime_error("layer \"" + layer.name +
                                 "\" has no shading file: export it again with this grass");
    layer.shading = readRecords<glm::vec4>(folder, entry.at("shading"), 2 * slots);
    struct PatchRecord {
        std::uint32_t first, count;
        float min[3], max[3];
    };
    static_assert(sizeof(PatchRecord) == 32);
    const auto patches = readRecords<PatchRecord>(folder, entry.at("patches"),
                                                  entry.at("patches").at("count").get<std::size_t>());
    for (const PatchRecord& patch : patches) {
        layer.patchBounds.emplace_back(patch.min[0], patch.min[1], patch.min[2], 0.0f);
        layer.patchBounds.emplace_back(patch.max[0], patch.max[1], patch.max[2], 0.0f);
    }
    if (layer.patchSize == 0 || patches.size() * layer.patchSize != slots)
        throw std::runtime_error("layer \"" + layer.name + "\": " + std::to_string(patches.size()) +
                                 " patches of " + std::to_string(layer.patchSize) +
                                 " slots do not make its " + std::to_string(slots) + " blades");
    return layer;
}

core::PhysicsParams physicsOf(const json& p) {
    core::PhysicsParams params;
    params.dtS = p.at("step_s").get<float>();
    params.gravity = glm::vec4(vec3Of(p.at("gravity")), p.at("gravity_strength").get<float>());
    params.gravityMode = p.at("gravity_mode").get<std::string>() == "centre"
                             ? core::GravityMode::Centre
                             : core::GravityMode::Direction;
    params.etaDecayPerS = p.at("eta_decay_per_s").get<float>();
    params.maxSubstepS = p.at("max_substep_s").get<float>();
    params.maxSubsteps = p.at("max_substeps").get<std::uint32_t>();
    params.maxMovePerSubstep = p.at("max_move_per_substep").get<float>();
    params.frontGravityScale = p.at("front_gravity_scale").get<float>();
    params.crushedRecoveryFloor = p.at("crushed_recovery_floor").get<float>();
    return params;
}

core::LightingBlock lightingOf(const json& l) {
    core::LightingBlock b;
    b.sunDirection = vec3Of(l.at("sun_direction"));
    b.sunColor = vec3Of(l.at("sun_color"));
    b.skyColor = vec3Of(l.at("sky_color"));
    b.groundColor = vec3Of(l.at("ground_color"));
    b.terrainNormalWeight = l.at("terrain_normal_weight").get<float>();
    b.specular = l.at("specular").get<float>();
    b.specularFadeM = {l.at("specular_fade_m").at(0).get<float>(),
                       l.at("specular_fade_m").at(1).get<float>()};
    b.transmission = l.at("transmission").get<float>();
    b.transmissionDistortion = l.at("transmission_distortion").get<float>();
    b.transmissionPower = l.at("transmission_power").get<float>();
    b.sss = l.at("sss").get<float>();
    b.sssIntensity = l.at("sss_intensity").get<float>();
    b.diffuseLow = vec3Of(l.at("diffuse_low"));
    b.diffuseMid = vec3Of(l.at("diffuse_mid"));
    b.diffuseHigh = vec3Of(l.at("diffuse_high"));
    b.grassLighting = l.at("grass_lighting").get<std::int32_t>();
    b.fieldWater = l.at("field_water").get<float>();
    return b;
}

MeshData readMesh(const fs::path& folder, const json& entry) {
    MeshData mesh;
    mesh.name = entry.at("name").get<std::string>();
    mesh.albedo = vec3Of(entry.at("albedo"));
    const std::size_t vertices = entry.at("vertex_count").get<std::size_t>();
    const std::size_t indices = entry.at("index_count").get<std::size_t>();
    const fs::path file = folder / entry.at("file").get<std::string>();
    const std::string bytes = readBytes(file);
    const std::size_t vertexBytes = vertices * 8 * sizeof(float);
    if (bytes.size() != vertexBytes + indices * sizeof(std::uint32_t))
        throw FileError(file, "holds " + std::to_string(bytes.size()) + " bytes, not the " +
                                  std::to_string(vertices) + " vertices and " +
                                  std::to_string(indices) + " indices the manifest says");
    mesh.vertices.resize(vertices * 8);
    mesh.indices.resize(indices);
    if (vertices > 0)
        std::memcpy(mesh.vertices.data(), bytes.data(), vertexBytes);
    if (indices > 0)
        std::memcpy(mesh.indices.data(), bytes.data() + vertexBytes, indices * sizeof(std::uint32_t));
    for (std::uint32_t index : mesh.indices)
        if (index >= vertices)
            throw FileError(file, "has index " + std::to_string(index) + " past its " +
                                      std::to_string(vertices) + " vertices");
    return mesh;
}

void readRuntimeBlock(const fs::path& folder, const json& r, ExportData& out) {
    const int version = r.at("version").get<int>();
    if (version != RUNTIME_FORMAT_VERSION)
        throw std::runtime_error("runtime block version " + std::to_string(version) +
                                 ", this runtime reads version " +
                                 std::to_string(RUNTIME_FORMAT_VERSION));
    out.physics = physicsOf(r.at("physics"));
    for (const json& w : r.at("wind")) {
        core::WindSource source;
        source.kind = windKindOf(w.at("kind").get<std::string>());
        source.position = vec3Of(w.at("position"));
        source.direction = vec3Of(w.at("direction"));
        source.axis = vec3Of(w.at("axis"));
        source.strength = w.at("strength").get<float>();
        source.radiusM = w.at("radius_m").get<float>();
        source.coreRadiusM = w.at("core_radius_m").get<float>();
        source.wavelengthM = w.at("wavelength_m").get<float>();
        source.speedMps = w.at("speed_mps").get<float>();
        source.gust = w.at("gust").get<float>();
        source.path = pathOf(w.at("path"));
        out.wind.push_back(std::move(source));
    }
    for (const json& s : r.at("spheres")) {
        core::SphereCollider sphere;
        sphere.centre = vec3Of(s.at("centre"));
        sphere.radiusM = s.at("radius_m").get<float>();
        sphere.path = pathOf(s.at("path"));
        sphere.groupSize = s.at("group_size").get<std::uint32_t>();
        sphere.boundOffset = vec3Of(s.at("bound_offset"));
        sphere.boundRadiusM = s.at("bound_radius_m").get<float>();
        out.spheres.push_back(std::move(sphere));
    }
    for (const json& m : r.at("meshes"))
        out.meshes.push_back(readMesh(folder, m));
    if (out.meshes.empty())
        throw std::runtime_error("runtime block lists no meshes (the terrain comes first)");
    for (const json& c : r.at("colliders")) {
        ColliderData collider;
        collider.name = c.at("name").get<std::string>();
        collider.origin = vec3Of(c.at("origin"));
        collider.path = pathOf(c.at("path"));
        collider.firstSphere = c.at("first_sphere").get<std::size_t>();
        collider.sphereCount = c.at("sphere_count").get<std::size_t>();
        if (collider.firstSphere + collider.sphereCount > out.spheres.size())
            throw std::runtime_error("collider \"" + collider.name + "\" names spheres past the " +
                                     std::to_string(out.spheres.size()) + " listed");
        collider.mesh = c.value("mesh", -1);
        if (collider.mesh >= static_cast<int>(out.meshes.size()))
            throw std::runtime_error("collider \"" + collider.name + "\" names mesh " +
                                     std::to_string(collider.mesh) + " of " +
                                     std::to_string(out.meshes.size()));
        collider.scale = c.value("scale", 1.0f);
        out.colliders.push_back(std::move(collider));
    }
    out.lighting = lightingOf(r.at("lighting"));
    const json& render = r.at("render");
    out.render.geometry = render.at("geometry").get<std::string>();
    out.render.tessLevel = render.at("tess_level").get<int>();
    out.render.stripSegments = render.at("strip_segments").get<int>();
    out.render.msaaSamples = render.at("msaa_samples").get<int>();
    out.render.width = render.at("width").get<int>();
    out.render.height = render.at("height").get<int>();
    out.render.skyColor = vec3Of(render.at("sky_color"));
    out.render.lodDistanceM = render.at("lod_distance_m").get<float>();
    out.render.thinningDistanceM = render.at("thinning_distance_m").get<float>();
    const json& camera = r.at("camera");
    out.camera.position = vec3Of(camera.at("position"));
    out.camera.target = vec3Of(camera.at("target"));
    out.camera.fovYDeg = camera.at("fov_y_deg").get<float>();
    out.camera.nearM = camera.at("near_m").get<float>();
    out.camera.farM = camera.at("far_m").get<float>();
}

}  // namespace

bool readExport(const fs::path& folder, ExportData& out, std::string& error) {
    const fs::path manifestFile = folder / "manifest.json";
    out = ExportData{};
    try {
        const json manifest = json::parse(readBytes(manifestFile));
        if (manifest.value("format", "") != "grass-raw-export")
            throw std::runtime_error(
                "not a raw grass export (\"format\" is not \"grass-raw-export\"); make one with "
                "`grass export PROJECT --format raw --out DIR`");
        if (!manifest.contains("runtime"))
            throw std::runtime_error(
                "has no \"runtime\" block (exported before issue 28): export it again");
        out.project = manifest.value("project", "");
        for (const json& layer : manifest.at("layers"))
            out.layers.push_back(readLayer(folder, layer));
        readRuntimeBlock(folder, manifest.at("runtime"), out);
    } catch (const FileError& e) {
        error = e.file.string() + ": " + e.what();
        return false;
    } catch (const std::exception& e) {
        error = manifestFile.string() + ": " + e.what();
        return false;
    }
    return true;
}

}  // namespace grass::runtime
