#include "export/runtime_block.h"

#include <cstring>

#include "mesh/mesh_frame.h"
#include "mesh/surface_mesh.h"
#include "scene/camera.h"
#include "scene/frame_lighting.h"

namespace grass::core {

using nlohmann::json;

namespace {

json vec3Json(glm::vec3 v) {
    return json::array({v.x, v.y, v.z});
}

json pathKeysJson(const std::vector<PathKey>& path) {
    json keys = json::array();
    for (const PathKey& key : path)
        keys.push_back({{"time_s", key.timeS}, {"position", vec3Json(key.posWorld)}});
    return keys;
}

std::string meshBytes(const SurfaceMesh& mesh, std::size_t& vertexCount, std::size_t& indexCount) {
    std::vector<float> vertices;
    vertices.reserve(mesh.n_vertices() * 8);
    for (const auto vh : mesh.vertices()) {
        const auto& p = mesh.point(vh);
        const auto& n = mesh.normal(vh);
        const auto& t = mesh.texcoord2D(vh);
        vertices.insert(vertices.end(), {p[0], p[1], p[2], n[0], n[1], n[2], t[0], t[1]});
    }
    const auto triangles = triangleIndices(mesh);
    vertexCount = mesh.n_vertices();
    indexCount = triangles.size() * 3;
    std::string bytes(vertices.size() * sizeof(float) + indexCount * sizeof(std::uint32_t), '\0');
    if (!vertices.empty())
        std::memcpy(bytes.data(), vertices.data(), vertices.size() * sizeof(float));
    if (!triangles.empty())
        std::memcpy(bytes.data() + vertices.size() * sizeof(float), triangles.data(),
                    indexCount * sizeof(std::uint32_t));
    return bytes;
}

const char* windKindName(WindKind kind) {
    switch (kind) {
        case WindKind::Point: return "point";
        case WindKind::Vortex: return "vortex";
        case WindKind::Directional: break;
    }
    return "directional";
}

const char* geometryName(GeometryPath path) {
    switch (path) {
        case GeometryPath::Tessellation: return "tessellation";
        case GeometryPath::Strips: return "strips";
        case GeometryPath::Auto: break;
    }
    return "auto";
}

json physicsJson(const PhysicsParams& p) {
    return {{"step_s", p.dtS},
            {"gravity", vec3Json(glm::vec3(p.gravity))},
            {"gravity_strength", p.gravity.w},
            {"gravity_mode", p.gravityMode == GravityMode::Centre ? "centre" : "direction"},
            {"eta_decay_per_s", p.etaDecayPerS},
            {"max_substep_s", p.maxSubstepS},
            {"max_substeps", p.maxSubsteps},
            {"max_move_per_substep", p.maxMovePerSubstep},
            {"front_gravity_scale", p.frontGravityScale},
            {"crushed_recovery_floor", p.crushedRecoveryFloor}};
}

json windJson(const Project& project, const ScenePhysics& physics) {
    json sources = json::array();
    for (std::size_t i = 0; i < physics.wind.size(); ++i) {
        const WindSource& w = physics.wind[i];
        sources.push_back({{"name", i < project.wind.size() ? project.wind[i].name : "wind"},
                           {"kind", windKindName(w.kind)},
                           {"position", vec3Json(w.position)},
                           {"direction", vec3Json(w.direction)},
                           {"axis", vec3Json(w.axis)},
                           {"strength", w.strength},
                           {"radius_m", w.radiusM},
                           {"core_radius_m", w.coreRadiusM},
                           {"wavelength_m", w.wavelengthM},
                           {"speed_mps", w.speedMps},
                           {"gust", w.gust},
                           {"path", pathKeysJson(w.path)}});
    }
    return sources;
}

json spheresJson(const ScenePhysics& physics) {
    json spheres = json::array();
    for (const SphereCollider& s : physics.colliders)
        spheres.push_back({{"centre", vec3Json(s.centre)},
                           {"radius_m", s.radiusM},
                           {"path", pathKeysJson(s.path)},
                           {"group_size", s.groupSize},
                           {"bound_offset", vec3Json(s.boundOffset)},
                           {"bound_radius_m", s.boundRadiusM}});
    return spheres;
}

// Project collider i owns the spheres buildScenePhysics made of it: one for a sphere, a group
// (the head's groupSize) for a packed mesh; scene.props[i] draws it.
json collidersJson(const Project& project, const Scene& scene, const ScenePhysics& physics,
                   std::size_t meshCount) {
    json colliders = json::array();
    std::size_t first = 0;
    for (std::size_t i = 0; i < project.colliders.size(); ++i) {
        const ColliderDesc& desc = project.colliders[i];
        const std::size_t count =
            first < physics.colliders.size() ? std::max<std::size_t>(physics.colliders[first].groupSize, 1) : 0;
        json entry = {{"name", desc.name},
                      {"origin", vec3Json(desc.position)},
                      {"path", pathKeysJson(desc.path)},
                      {"first_sphere", first},
                      {"sphere_count", count}};
        if (i < scene.props.size()) {
            if (i + 1 < meshCount)
                entry["mesh"] = i + 1;  // meshes[0] is the terrain
            entry["scale"] = scene.props[i].scale;
        }
        colliders.push_back(std::move(entry));
        first += count;
    }
    return colliders;
}

json lightingJson(const LightingBlock& b) {
    return {{"sun_direction", vec3Json(b.sunDirection)},
            {"sun_color", vec3Json(b.sunColor)},
            {"sky_color", vec3Json(b.skyColor)},
            {"ground_color", vec3Json(b.groundColor)},
            {"terrain_normal_weight", b.terrainNormalWeight},
            {"specular", b.specular},
            {"specular_fade_m", json::array({b.specularFadeM.x, b.specularFadeM.y})},
            {"transmission", b.transmission},
            {"transmission_distortion", b.transmissionDistortion},
            {"transmission_power", b.transmissionPower},
            {"sss", b.sss},
            {"sss_intensity", b.sssIntensity},
            {"diffuse_low", vec3Json(b.diffuseLow)},
            {"diffuse_mid", vec3Json(b.diffuseMid)},
            {"diffuse_high", vec3Json(b.diffuseHigh)},
            {"grass_lighting", b.grassLighting},
            {"field_water", b.fieldWater}};
}

}  // namespace

std::vector<RuntimeMeshFile> runtimeMeshes(const LoadedProject& loaded, const Scene& scene) {
    std::vector<RuntimeMeshFile> meshes;
    RuntimeMeshFile terrain;
    terrain.name = "terrain";
    terrain.bytes = meshBytes(scene.mesh, terrain.vertexCount, terrain.indexCount);
    terrain.albedo = scene.look.baseColor.value_or(loaded.project.render.groundColor);
    meshes.push_back(std::move(terrain));
    for (const SceneProp& prop : scene.props) {
        RuntimeMeshFile mesh;
        mesh.name = prop.name;
        mesh.bytes = meshBytes(prop.mesh, mesh.vertexCount, mesh.indexCount);
        mesh.albedo = prop.albedo;
        meshes.push_back(std::move(mesh));
    }
    return meshes;
}

json runtimeBlock(const LoadedProject& loaded, const Scene& scene, const ScenePhysics& physics,
                  const std::vector<RuntimeMeshFile>& meshes,
                  const std::vector<std::string>& meshFiles) {
    const Project& project = loaded.project;
    const RenderSettings& render = project.render;
    const LightingBlock lighting =
        frameLighting(project.lighting, project.sun, render.skyColor, render.groundColor);
    json meshEntries = json::array();
    for (std::size_t i = 0; i < meshes.size() && i < meshFiles.size(); ++i)
        meshEntries.push_back({{"name", meshes[i].name},
                               {"file", meshFiles[i]},
                               {"vertex_count", meshes[i].vertexCount},
                               {"index_count", meshes[i].indexCount},
                               {"vertex_stride", RUNTIME_MESH_VERTEX_STRIDE},
                               {"index_offset", meshes[i].vertexCount * RUNTIME_MESH_VERTEX_STRIDE},
                               {"albedo", vec3Json(meshes[i].albedo)}});
    json camera = {{"position", vec3Json(glm::vec3(8.0f, 5.0f, 8.0f))},
                   {"target", vec3Json(glm::vec3(0.0f))},
                   {"fov_y_deg", 45.0f},
                   {"near_m", 0.05f},
                   {"far_m", 500.0f}};
    if (!project.cameras.empty()) {
        // The editor's camera of it (core::OrbitCamera), planes included, so a runtime sees
        // what `grass render` draws.
        const CameraDesc& desc = project.cameras[0];
        const OrbitCamera orbit =
            OrbitCamera::lookAt(desc.position, desc.target, glm::radians(desc.fovYDeg));
        camera = {{"name", desc.name},
                  {"position", vec3Json(orbit.position())},
                  {"target", vec3Json(desc.target)},
                  {"fov_y_deg", desc.fovYDeg},
                  {"near_m", orbit.nearPlane},
                  {"far_m", orbit.farPlane}};
    }
    json block = {{"format", "grass-runtime"},
            {"version", RUNTIME_BLOCK_VERSION},
            {"units", "metres, seconds, radians; +Y up, right-handed; colours linear RGB"},
            {"physics", physicsJson(physics.params)},
            {"wind", windJson(project, physics)},
            {"spheres", spheresJson(physics)},
            {"colliders", collidersJson(project, scene, physics, meshEntries.size())},
            {"lighting", lightingJson(lighting)},
            {"render",
             {{"geometry", geometryName(render.geometry)},
              {"tess_level", render.tessLevel},
              {"strip_segments", render.stripSegments},
              {"msaa_samples", render.msaaSamples},
              {"width", render.width},
              {"height", render.height},
              {"sky_color", vec3Json(render.skyColor)},
              {"lod_distance_m", render.lodDistanceM},
              {"thinning_distance_m", render.thinningDistanceM}}},
            {"camera", camera},
            {"meshes", meshEntries}};
    if (scene.groundOrigin != glm::dvec3(0.0)) {
        // Where the field was in its ground's file, for hosts that place it there again
        // (docs/runtime.md): a point p of the block is the file's `point` + R⁻¹(p) / m.
        const MeshSource& source = project.mesh;
        block["ground_origin"] = {
            {"file", source.file},
            {"point", {scene.groundOrigin.x, scene.groundOrigin.y, scene.groundOrigin.z}},
            {"metres_per_unit", source.metresPerUnit},
            {"up", std::string(upAxisText(source.up))}};
    }
    return block;
}

std::vector<std::string> runtimeBlockGaps(const LoadedProject& loaded, const Scene& scene) {
    const Project& project = loaded.project;
    std::vector<std::string> gaps;
    if (project.snow.enabled != 0u)
        gaps.push_back("runtime: snow does not travel (the runtime draws the field without it)");
    if (project.render.technique != GrassTechnique::Blades)
        gaps.push_back("runtime: the runtime draws blades only (no billboards or stem sets)");
    if (!scene.look.baseTexture.pixels.empty())
        gaps.push_back("runtime: the surface's texture does not travel (its base colour does)");
    if (project.sun.shadows)
        gaps.push_back("runtime: sun shadows do not travel (the runtime lights without them)");
    return gaps;
}

}  // namespace grass::core
