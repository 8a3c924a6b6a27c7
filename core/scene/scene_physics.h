// What a project's physics becomes at run time (issue 4): the integration parameters, the wind
// sources, and every collider as spheres — mesh colliders packed into spheres once and cached
// next to the project (core/collider/packing_cache.h). Shared by `grass sim`, `grass render
// --time` and the editor, so they simulate the same scene.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "collider/sphere_packing.h"
#include "physics/field_health.h"
#include "physics/physics.h"
#include "physics/physics_simd.h"
#include "project/project.h"
#include "scene/scene.h"
#include "scene/scene_snow.h"
#include "snow/snow_params.h"

namespace grass::core {

struct ScenePhysics {
    PhysicsParams params;
    std::vector<WindSource> wind;
    std::vector<SphereCollider> colliders;  // spheres and packed meshes, world space
    std::vector<std::string> notes;         // what packing did (cache hits, measures)
    // Snow (SPEC §11): the project's settings, and per layer the snow load of each blade per
    // metre of snow (scene_snow.h; empty without a load), filled by prepareSnowLoads.
    SnowParams snow;
    std::vector<std::vector<float>> snowLoadPerMetre;
    // What weighed them (with the snow map it rendered), kept to weigh re-grown blades alike
    // (reweighSnowLoads); null until prepareSnowLoads weighs a load.
    std::shared_ptr<const SnowWeigher> snowWeigher;
    // The load at timeS (GravityLoad over layer `layer`'s blades).
    GravityLoad snowLoad(std::size_t layer, float timeS) const;
    // Whether a load lies on any blade, and whether it changes with time (the snow accumulates
    // or melts).
    bool anySnowLoad() const;
    bool snowLoadChangesWithTime() const;
};

// Fills physics.snowLoadPerMetre from `scene` at rest when the snow loads blades and it is empty:
// the exposures are taken once, at the start (scene_snow.h says why). Every simulation of a
// scene calls it before its first step (SceneSimulation, the editor's live physics), so that
// they bend the same blades alike.
void prepareSnowLoads(ScenePhysics& physics, const Scene& scene);
// After a brush, an undo or a regrowth re-grew `patches` of layer `layer` (scene.h,
// RegrowReport): their slots' loads weighed anew, as prepareSnowLoads would weigh the blades
// now there. Before, a blade grown into an empty slot carried no snow and a re-grown one the
// load of the blade before it. Nothing without a load on that layer.
void reweighSnowLoads(ScenePhysics& physics, const Scene& scene, std::size_t layer,
                      std::span<const std::uint32_t> patches);

// The packings of a scene's mesh colliders by mesh file (as the project names it) and packing
// parameters, in the scene's frame. A caller that builds one scene's physics again and again (the
// editor following a collider dragged with the gizmo, every frame) keeps one: a packing found
// in it is neither read from its cache file nor its mesh loaded again.
struct ColliderPackings {
    using Key = std::tuple<std::string, std::uint32_t, std::uint32_t>;  // file, count, resolution
    std::map<Key, SpherePacking> byFile;
};

// Reads mesh collider files and packs (or loads the cached packing of) each. Errors name the
// mesh file or the project field. `groundOrigin` is the scene's (Scene::groundOrigin): a mesh
// collider in a moved ground's georeferenced frame is moved with it (loadColliderMesh).
// `packings`, when given, holds the packings of earlier builds of the same scene and keeps this
// one's (a packing taken from it adds no note).
Result<ScenePhysics> buildScenePhysics(const LoadedProject& project,
                                       glm::dvec3 groundOrigin = glm::dvec3(0.0),
                                       ColliderPackings* packings = nullptr);

// The CPU state of a simulated scene: η and rest tips per layer, parallel to the layer's blades.
class SceneSimulation {
public:
    // threadCount 0: hardware concurrency (core::stepPhysics). Steps run on the SIMD execution
    // (physics_simd.h) unless setCpuPhysics says the scalar reference.
    SceneSimulation(Scene& scene, ScenePhysics physics, unsigned threadCount = 0);
    void setCpuPhysics(CpuPhysics path) { mCpuPhysics = path; }
    CpuPhysics cpuPhysics() const { return mCpuPhysics; }

    // One step of params.dtS from timeS() on every layer.
    void step();
    float timeS() const { return mTimeS; }
    std::size_t stepsDone() const { return mSteps; }
    const ScenePhysics& physics() const { return mPhysics; }
    // For a driver that changes the scene between steps (grass soak keeps paths looping).
    ScenePhysics& physics() { return mPhysics; }
    FieldHealth health() const;

    // For a GPU execution that took over: the state of layer i.
    std::vector<float>& eta(std::size_t layer) { return mEta[layer]; }
    const std::vector<glm::vec3>& restTips(std::size_t layer) const { return mRestTips[layer]; }
    // Advances the clock without stepping (the GPU stepped instead).
    void advanceClock();

private:
    Scene& mScene;
    ScenePhysics mPhysics;
    unsigned mThreadCount;
    CpuPhysics mCpuPhysics = CpuPhysics::Simd;
    std::vector<std::vector<float>> mEta;
    std::vector<std::vector<glm::vec3>> mRestTips;
    float mTimeS = 0.0f;
    std::size_t mSteps = 0;
};

}  // namespace grass::core
