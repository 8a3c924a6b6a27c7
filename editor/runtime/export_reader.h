// Reading a raw export (core/export/export.h, docs/export.md "raw") with what the reference
// runtime needs: every layer's blade, patch and shading buffers, and the scene's behaviour
// (manifest.json "runtime", core/export/runtime_block.h): physics, wind, colliders, lighting,
// render settings, camera and meshes. Plain C++ over nlohmann-json and GLM; no GL.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "blade/blade.h"
#include "physics/physics.h"
#include "scene/lighting_block.h"

namespace grass::runtime {

// The version of manifest.json's "runtime" block this reader knows.
inline constexpr int RUNTIME_FORMAT_VERSION = 1;

struct LayerData {
    std::string name;
    std::uint32_t patchSize = 256;
    std::size_t liveBlades = 0;
    std::vector<core::Blade> blades;      // patch-major slots; padding is h = w = 0
    std::vector<glm::vec4> patchBounds;   // min, max per patch (w unused)
    std::vector<glm::vec4> shading;       // two per slot: (blurred normal, AO), (water, age, wilt, 0)
    glm::vec3 rootColor{0.0f}, tipColor{0.0f}, poorRootColor{0.0f}, poorTipColor{0.0f};
    int shape = 0;  // core::BladeShape, the shape id of shaders/include/shapes.glsl
    float tipStart = 0.0f;
};

struct MeshData {
    std::string name;
    std::vector<float> vertices;  // 8 floats a vertex: position, normal, uv
    std::vector<std::uint32_t> indices;
    glm::vec3 albedo{0.6f};
};

// One project collider: its spheres (a range of ExportData::spheres) move with its origin.
struct ColliderData {
    std::string name;
    glm::vec3 origin{0.0f};
    std::vector<core::PathKey> path;
    std::size_t firstSphere = 0;
    std::size_t sphereCount = 0;
    int mesh = -1;  // index into ExportData::meshes, -1: none
    float scale = 1.0f;
};

struct RenderData {
    std::string geometry = "auto";  // "auto", "strips", "tessellation"
    int tessLevel = 8;
    int stripSegments = 8;
    int msaaSamples = 4;
    int width = 1280;
    int height = 720;
    glm::vec3 skyColor{0.55f, 0.70f, 0.90f};
    float lodDistanceM = 8.0f;
    float thinningDistanceM = 100.0f;
};

struct CameraData {
    glm::vec3 position{8.0f, 5.0f, 8.0f};
    glm::vec3 target{0.0f};
    float fovYDeg = 45.0f;
    float nearM = 0.05f;
    float farM = 500.0f;
};

struct ExportData {
    std::string project;
    std::vector<LayerData> layers;
    core::PhysicsParams physics;
    std::vector<core::WindSource> wind;
    std::vector<core::SphereCollider> spheres;
    std::vector<ColliderData> colliders;
    core::LightingBlock lighting;
    RenderData render;
    CameraData camera;
    std::vector<MeshData> meshes;  // meshes[0] is the terrain
};

// Reads `folder`/manifest.json and every file it names. On failure returns false with one line in
// `error` naming the file and the problem (a missing file, a size that does not match its count,
// a runtime block of an unknown version, a malformed value).
bool readExport(const std::filesystem::path& folder, ExportData& out, std::string& error);

}  // namespace grass::runtime
