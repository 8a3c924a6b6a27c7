#include "app/collider_packing_job.h"

#include <utility>

#include "scene/scene_props.h"

namespace grass::editor {

namespace {

// "packing rock.glb, log.gltf": the mesh colliders whose packings `known` lacks.
std::string packingWhat(const core::Project& project, const core::ColliderPackings& known) {
    std::string files;
    for (const core::ColliderDesc& c : project.colliders)
        if (c.shape == core::ColliderShape::Mesh &&
            !known.byFile.contains({c.file, c.sphereCount, c.packingResolution}) &&
            files.find(c.file) == std::string::npos)
            files += (files.empty() ? "" : ", ") + c.file;
    return "packing " + (files.empty() ? std::string("colliders") : files);
}

}  // namespace

ColliderPackingJob::ColliderPackingJob(core::LoadedProject loaded, glm::dvec3 groundOrigin,
                                       const core::ColliderPackings& known,
                                       std::function<void()> whenDone,
                                       std::set<std::string> propsToRead)
    : mLoaded(std::move(loaded)),
      mGroundOrigin(groundOrigin),
      mWhat(packingWhat(mLoaded.project, known)) {
    // The worker packs into a copy: the live packings stay the window's.
    mJob = std::make_unique<WorkerJob<Result<PackedColliders>>>(
        [this, packings = known,
         propsToRead = std::move(propsToRead)]() mutable -> Result<PackedColliders> {
            // buildScenePhysics packs what `packings` lacks, as a fresh build would, and keeps it.
            auto built = core::buildScenePhysics(mLoaded, mGroundOrigin, &packings);
            if (!built)
                return built.error();
            PackedColliders packed{std::move(packings), std::move(built->notes), {}};
            const auto& colliders = mLoaded.project.colliders;
            for (std::size_t i = 0; i < colliders.size(); ++i) {
                const core::ColliderDesc& c = colliders[i];
                if (c.shape != core::ColliderShape::Mesh || !propsToRead.contains(c.file) ||
                    packed.props.contains(c.file))
                    continue;
                auto mesh = core::loadColliderMesh(mLoaded, c, i, mGroundOrigin);
                if (!mesh)
                    return mesh.error();
                packed.props.emplace(c.file, std::move(mesh->imported.mesh));
            }
            return packed;
        },
        std::move(whenDone));
}

Result<PackedColliders> ColliderPackingJob::take() {
    return mJob->take();
}

}  // namespace grass::editor
