#include "scene/scene_physics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <utility>

#include "collider/packing_cache.h"
#include "scene/scene_props.h"
#include "scene/scene_snow.h"
#include "snow/snow_drift.h"

namespace grass::core {

namespace {

std::string formatPercent(float share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", static_cast<double>(share) * 100.0);
    return text;
}

// One bounding sphere around spheres that move together (a packed mesh), stored on the first so
// blades out of its reach skip the whole group (SphereCollider::groupSize).
// The box around a group's spheres.
std::pair<glm::vec3, glm::vec3> sphereBox(std::span<const SphereCollider> group) {
    glm::vec3 low = group[0].centre, high = group[0].centre;
    for (const SphereCollider& sphere : group) {
        low = glm::min(low, sphere.centre - sphere.radiusM);
        high = glm::max(high, sphere.centre + sphere.radiusM);
    }
    return {low, high};
}

void addBroadPhase(std::span<SphereCollider> group) {
    if (group.size() < 2)
        return;
    const auto [low, high] = sphereBox(group);
    const glm::vec3 centre = 0.5f * (low + high);
    float radius = 0.0f;
    for (const SphereCollider& sphere : group)
        radius = std::max(radius, glm::length(sphere.centre - centre) + sphere.radiusM);
    SphereCollider& head = group[0];
    head.groupSize = static_cast<std::uint32_t>(group.size());
    head.boundOffset = centre - head.centre;
    // A little slack so float rounding of the moved centres never makes the bound too tight.
    head.boundRadiusM = radius * (1.0f + 1e-5f) + 1e-6f;
}

// Interleaves the low 10 bits of x, y and z (a Morton code): sorting by it keeps spheres that lie
// close together close in the list.
std::uint32_t mortonCode(glm::uvec3 cell) {
    std::uint32_t code = 0;
    for (std::uint32_t bit = 0; bit < 10; ++bit)
        for (std::uint32_t axis = 0; axis < 3; ++axis)
            code |= ((cell[static_cast<int>(axis)] >> bit) & 1u) << (3 * bit + axis);
    return code;
}

// Nested bounds over spheres in Morton order: the span is cut into `fanOut` runs of neighbours,
// each run cut again the same way until a run holds at most `fanOut` spheres, and the first
// sphere of every run but the first holds its run's bound (the first run's head is the span's
// own, which holds the larger bound).
void addNestedBounds(std::span<SphereCollider> spheres, std::size_t fanOut) {
    if (spheres.size() <= fanOut)
        return;
    const std::size_t run = (spheres.size() + fanOut - 1) / fanOut;
    for (std::size_t first = 0; first < spheres.size(); first += run) {
        const auto part = spheres.subspan(first, std::min(run, spheres.size() - first));
        addNestedBounds(part, fanOut);
        if (first > 0)
            addBroadPhase(part);
    }
}

// A packed mesh's broad phase, three levels deep. The spheres are put in Morton order; the first
// sphere holds the bound of the whole mesh, and the mesh is cut into runs of neighbours, each
// cut again, ∛N runs a level (addNestedBounds; the same SphereCollider fields, which the
// physics' loops read wherever they meet them). A blade within the mesh's reach then tests the
// bounds of the runs it reaches instead of every sphere: under projects/nature's 1000-sphere
// bunny, with the groups skipped on the tip and midpoint (physics_simd.cpp
// TipOrMidpointNearBound), the longest walk is ~1/4 of the 931 links of testing √N chunks and
// their spheres (docs/physics.md, Colliders). A bound only skips spheres that could not touch the
// blade, so the results are those of testing every sphere in this order.
void addMeshBroadPhase(std::span<SphereCollider> group) {
    if (group.size() < 2)
        return;
    const auto [low, high] = sphereBox(group);
    const glm::vec3 cellsPerMetre = 1023.0f / glm::max(high - low, glm::vec3(1e-6f));
    std::vector<std::pair<std::uint32_t, std::size_t>> order(group.size());
    for (std::size_t i = 0; i < group.size(); ++i)
        order[i] = {mortonCode(glm::uvec3((group[i].centre - low) * cellsPerMetre)), i};
    std::sort(order.begin(), order.end());
    std::vector<SphereCollider> sorted;
    sorted.reserve(group.size());
    for (const auto& [code, i] : order)
        sorted.push_back(std::move(group[i]));
    std::move(sorted.begin(), sorted.end(), group.begin());

    const auto fanOut = std::max<std::size_t>(
        2, static_cast<std::size_t>(std::ceil(std::cbrt(double(group.size())) - 1e-9)));
    addNestedBounds(group, fanOut);
    addBroadPhase(group);  // last: the first sphere's bound is the whole mesh's
}

// The packing of one mesh collider: its cache file's, or packed now (and cached). Notes say
// which, and what its mesh's placement did.
Result<SpherePacking> packMeshCollider(const LoadedProject& loaded, const ColliderDesc& collider,
                                       std::size_t index, glm::dvec3 groundOrigin,
                                       std::vector<std::string>& notes) {
    auto colliderMesh = loadColliderMesh(loaded, collider, index, groundOrigin);
    if (!colliderMesh)
        return colliderMesh.error();
    if (!colliderMesh->imported.placementNote.empty())
        notes.push_back("collider " + collider.name + ": " + collider.file + " " +
                        colliderMesh->imported.placementNote);
    const std::filesystem::path& file = colliderMesh->file;
    const SurfaceMesh& mesh = colliderMesh->imported.mesh;
    SpherePackingParams params;
    params.sphereCount = collider.sphereCount;
    params.resolution = collider.packingResolution;
    const std::filesystem::path cache = packingCachePath(loaded.folder, file, params);
    bool fromCache = false;
    std::string cacheNote;
    auto packing = loadOrPackSpheres(file, mesh, params, cache, &fromCache, &cacheNote);
    if (!packing) {
        Error error = packing.error();
        if (error.path.empty())
            error.path = file.string();
        return error;
    }
    const std::string source = fromCache            ? "cached in " + cache.string()
                               : cacheNote.empty() ? "packed, cached in " + cache.string()
                                                   : "packed";
    notes.push_back("collider " + collider.name + ": " + collider.file + " as " +
                    std::to_string(packing->spheres.size()) + " spheres (" + source +
                    "): " + formatPercent(packing->insideShare) + " of their volume inside, " +
                    formatPercent(packing->coverage) + " of the mesh covered");
    if (!cacheNote.empty())
        notes.push_back("collider " + collider.name + ": " + cacheNote);
    return packing;
}

// The packed spheres of one mesh collider, placed in the world: centre = position + scale·c,
// radius scale·r; a path moves every sphere by the same offset.
void placePackedSpheres(const SpherePacking& packing, const ColliderDesc& collider,
                        ScenePhysics& out) {
    const std::size_t first = out.colliders.size();
    for (const PackedSphere& packed : packing.spheres) {
        SphereCollider sphere;
        const glm::vec3 offset = collider.scale * packed.centre;
        sphere.centre = collider.position + offset;
        sphere.radiusM = collider.scale * packed.radiusM;
        for (PathKey key : collider.path) {
            key.posWorld += offset;
            sphere.path.push_back(key);
        }
        out.colliders.push_back(std::move(sphere));
    }
    addMeshBroadPhase(std::span(out.colliders).subspan(first));
}

Result<void> addMeshCollider(const LoadedProject& loaded, const ColliderDesc& collider,
                             std::size_t index, glm::dvec3 groundOrigin, ScenePhysics& out,
                             ColliderPackings* packings) {
    const ColliderPackings::Key key{collider.file, collider.sphereCount,
                                    collider.packingResolution};
    if (packings != nullptr)
        if (const auto known = packings->byFile.find(key); known != packings->byFile.end()) {
            placePackedSpheres(known->second, collider, out);
            return {};
        }
    auto packing = packMeshCollider(loaded, collider, index, groundOrigin, out.notes);
    if (!packing)
        return packing.error();
    placePackedSpheres(*packing, collider, out);
    if (packings != nullptr)
        packings->byFile.emplace(key, std::move(*packing));
    return {};
}

}  // namespace

Result<ScenePhysics> buildScenePhysics(const LoadedProject& loaded, glm::dvec3 groundOrigin,
                                       ColliderPackings* packings) {
    const Project& project = loaded.project;
    ScenePhysics out;
    out.params = project.physics;
    for (const WindDesc& wind : project.wind)
        out.wind.push_back(wind.source);
    out.snow = snowWithWindDrift(project.snow, out.wind);
    for (std::size_t i = 0; i < project.colliders.size(); ++i) {
        const ColliderDesc& collider = project.colliders[i];
        if (collider.shape == ColliderShape::Sphere) {
            out.colliders.push_back(
                SphereCollider{collider.position, collider.radiusM, collider.path});
            continue;
        }
        if (auto added = addMeshCollider(loaded, collider, i, groundOrigin, out, packings); !added)
            return added.error();
    }
    return out;
}

SceneSimulation::SceneSimulation(Scene& scene, ScenePhysics physics, unsigned threadCount)
    : mScene(scene), mPhysics(std::move(physics)), mThreadCount(threadCount) {
    for (const LayerField& layer : mScene.layers) {
        mEta.emplace_back(layer.patched.blades.size(), 0.0f);
        mRestTips.push_back(core::restTipsAsGrown(layer.patched.blades));
    }
    prepareSnowLoads(mPhysics, mScene);
}

void prepareSnowLoads(ScenePhysics& physics, const Scene& scene) {
    if (!snowLoadsBlades(physics.snow) || !physics.snowLoadPerMetre.empty())
        return;
    auto weigher = std::make_shared<const SnowWeigher>(sceneSnowDepthMap(scene, physics.snow, 0.0f),
                                                       physics.snow);
    for (const LayerField& layer : scene.layers)
        physics.snowLoadPerMetre.push_back(weigher->loadsPerMetre(layer.patched.blades));
    physics.snowWeigher = std::move(weigher);
}

void reweighSnowLoads(ScenePhysics& physics, const Scene& scene, std::size_t layer,
                      std::span<const std::uint32_t> patches) {
    if (!physics.snowWeigher || layer >= physics.snowLoadPerMetre.size() ||
        layer >= scene.layers.size())
        return;
    std::vector<float>& load = physics.snowLoadPerMetre[layer];
    const PatchedBlades& field = scene.layers[layer].patched;
    if (load.empty())
        return;
    // Slots never move (layer_growth.h), but a re-grow that changed the layout all the same
    // weighs the whole layer rather than read past its end.
    if (load.size() != field.blades.size()) {
        load = physics.snowWeigher->loadsPerMetre(field.blades);
        return;
    }
    for (const std::uint32_t patch : patches) {
        const std::size_t first = std::size_t(patch) * field.patchSize;
        const std::size_t end = std::min(first + field.patchSize, load.size());
        for (std::size_t i = first; i < end; ++i)
            load[i] = physics.snowWeigher->loadPerMetre(field.blades[i]);
    }
}

GravityLoad ScenePhysics::snowLoad(std::size_t layer, float timeS) const {
    if (layer >= snowLoadPerMetre.size() || snowLoadPerMetre[layer].empty())
        return {};
    return {snowLoadPerMetre[layer], snowAmountAt(snow, timeS)};
}

bool ScenePhysics::anySnowLoad() const {
    return std::any_of(snowLoadPerMetre.begin(), snowLoadPerMetre.end(),
                       [](const std::vector<float>& load) { return !load.empty(); });
}

bool ScenePhysics::snowLoadChangesWithTime() const {
    return anySnowLoad() && snow.accumulationRate != snow.meltRate;
}

void SceneSimulation::step() {
    for (std::size_t i = 0; i < mScene.layers.size(); ++i)
        stepPhysicsOn(mCpuPhysics, mScene.layers[i].patched.blades, mEta[i], mRestTips[i],
                      mPhysics.params, mPhysics.wind, mPhysics.colliders, mTimeS, mThreadCount,
                      mPhysics.snowLoad(i, mTimeS));
    advanceClock();
}

void SceneSimulation::advanceClock() {
    ++mSteps;
    // From the step count, so the clock does not drift by a rounding per step.
    mTimeS = static_cast<float>(static_cast<double>(mSteps) * mPhysics.params.dtS);
}

FieldHealth SceneSimulation::health() const {
    FieldHealth health;
    for (std::size_t i = 0; i < mScene.layers.size(); ++i)
        health.add(measureHealth(mScene.layers[i].patched.blades, mEta[i], mRestTips[i]));
    return health;
}

}  // namespace grass::core
