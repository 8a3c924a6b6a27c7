// A mesh collider the live field holds no packing of (one just added with Colliders › add mesh…,
// or given another sphere count) is packed on a worker thread: packing a mesh into spheres can
// take seconds (a voxel grid, then the spheres one by one). Meanwhile the window goes on with the
// field as it is; once the packing is in, the live physics takes the collider like any moved one
// (live_scene.h followMotion) and the field keeps its blades. Before, the whole field was grown
// again for it, and its blades restarted from rest.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/worker_job.h"
#include "mesh/surface_mesh.h"
#include "project/project.h"
#include "scene/scene_physics.h"
#include "util/result.h"

namespace grass::editor {

// The packings the job made, and what packing them said (the notes a build prints); with the
// meshes of the files it was asked to read for props (LiveMotion::readAheadProps).
struct PackedColliders {
    core::ColliderPackings packings;
    std::vector<std::string> notes;
    std::map<std::string, core::MovableSurfaceMesh> props;
};

class ColliderPackingJob {
public:
    // Packs (or reads from the cache) every mesh collider of `loaded` whose packing `known` does
    // not hold, as core::buildScenePhysics would for a scene whose ground origin is
    // `groundOrigin`. `whenDone` is called on the worker once done() (EditorState::wakeFrame).
    // `propsToRead`: mesh files (as the project names them) whose meshes it reads for props too,
    // so the window reads no glTF when their props are made again (files changed on disk).
    ColliderPackingJob(core::LoadedProject loaded, glm::dvec3 groundOrigin,
                       const core::ColliderPackings& known, std::function<void()> whenDone = {},
                       std::set<std::string> propsToRead = {});
    ColliderPackingJob(const ColliderPackingJob&) = delete;
    ColliderPackingJob& operator=(const ColliderPackingJob&) = delete;

    bool done() const { return mJob->done(); }
    void wait() { mJob->wait(); }
    // The colliders it was started for and the ground origin it read them in.
    const std::vector<core::ColliderDesc>& colliders() const { return mLoaded.project.colliders; }
    glm::dvec3 groundOrigin() const { return mGroundOrigin; }
    const std::filesystem::path& folder() const { return mLoaded.folder; }
    // "packing rock.glb": what the status line says meanwhile.
    const std::string& what() const { return mWhat; }
    // Once done(): the new packings, or why a mesh could not be packed (naming its file).
    Result<PackedColliders> take();

private:
    core::LoadedProject mLoaded;
    glm::dvec3 mGroundOrigin;
    std::string mWhat;
    std::unique_ptr<WorkerJob<Result<PackedColliders>>> mJob;  // last: reads the members above
};

}  // namespace grass::editor
