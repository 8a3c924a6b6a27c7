#include "app/live_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "gl/headless_context.h"
#include "scene/collider_placement.h"
#include "scene/motion_edit.h"
#include "scene/scene_snow.h"
#include "snow/snow_drift.h"

namespace grass::editor {

const char* physicsDeviceName(PhysicsDevice device) {
    switch (device) {
        case PhysicsDevice::Cpu: return "cpu";
        case PhysicsDevice::Gpu: return "gpu";
        case PhysicsDevice::Auto: break;
    }
    return "auto";
}

std::string LivePhysics::deviceLabel() const {
    return cpu ? "cpu" : "gpu";
}

bool tipsMoved(std::span<const core::Blade> blades, std::vector<glm::vec3>& shownTips) {
    bool moved = shownTips.size() != blades.size();
    for (std::size_t i = 0; i < blades.size() && !moved; ++i) {
        const float limit = STILL_TIP_SHARE * blades[i].h();
        const glm::vec3 d = blades[i].v2() - shownTips[i];
        // Written so that a NaN tip counts as moved.
        moved = !(glm::dot(d, d) <= limit * limit);
    }
    if (moved) {
        shownTips.resize(blades.size());
        for (std::size_t i = 0; i < blades.size(); ++i)
            shownTips[i] = blades[i].v2();
    }
    return moved;
}

bool anyRecovering(std::span<const float> eta, std::span<const float> etaBefore, float decay) {
    const bool compared = eta.size() == etaBefore.size();
    for (std::size_t i = 0; i < eta.size(); ++i)
        // Written so that a NaN η counts as recovering.
        if (eta[i] != 0.0f && (!compared || !(eta[i] >= etaBefore[i] - 0.5f * decay)))
            return true;
    return false;
}

namespace {

// Nothing in the physics scene changes with time: the step is the same function of the blades
// at every time, so blades it leaves where they were stay there. A snow load that neither grows
// nor melts is such a function too (blades settle under it).
bool timeIndependent(const core::ScenePhysics& physics) {
    const bool anyPath = std::any_of(physics.colliders.begin(), physics.colliders.end(),
                                     [](const core::SphereCollider& c) { return !c.path.empty(); });
    return physics.wind.empty() && !anyPath && !physics.snowLoadChangesWithTime();
}

bool anyRecovering(const core::FieldSimulation& cpu,
                   const std::vector<std::vector<float>>& etaBefore, float decay) {
    for (std::size_t layer = 0; layer < cpu.layerCount(); ++layer)
        if (editor::anyRecovering(cpu.eta(layer),
                                  layer < etaBefore.size()
                                      ? std::span<const float>(etaBefore[layer])
                                      : std::span<const float>(),
                                  decay))
            return true;
    return false;
}

}  // namespace

void LivePhysics::wake() {
    resting = false;
    stillSteps = 0;
    gpuStepsUnanswered = 0;
}

bool LivePhysics::followSnow(const core::SnowParams& snow, const core::Scene& field) {
    const core::SnowParams resolved = core::snowWithWindDrift(snow, scene.wind);
    if (resolved == scene.snow)
        return false;
    scene.snow = resolved;
    weighSnowAgain(field);
    return true;
}

void LivePhysics::releaseHeldBlades() {
    if (cpu)
        cpu->capEta(RELEASED_ETA);
    else if (gpu)
        gpu->capEta(RELEASED_ETA);
    wake();
}

void LivePhysics::followParams(const core::PhysicsParams& params) {
    const double atS = timeS();
    scene.params = params;
    if (params.dtS > 0.0f)
        steps = static_cast<std::size_t>(std::llround(atS / double(params.dtS)));
    wake();
}

void LivePhysics::weighSnowAgain(const core::Scene& field) {
    scene.snowLoadPerMetre.clear();
    scene.snowWeigher.reset();
    core::prepareSnowLoads(scene, field);
    if (gpu)
        gpu->reloadSnowLoads();
    timeIndependent = editor::timeIndependent(scene);
    wake();
}

double LivePhysics::advanceTo(double targetS, int maxSteps, double budgetMs) {
    const double dtS = scene.params.dtS;
    // The GPU's answer for the steps of the frames before (their fence has passed by now on a
    // GPU that keeps up), then this frame's steps are marked while the field could rest.
    if (gpu && !resting) {
        if (const std::optional<bool> motion = gpu->takeMotion()) {
            stillSteps = *motion ? 0 : stillSteps + gpuStepsUnanswered;
            gpuStepsUnanswered = 0;
            resting = timeIndependent && stillSteps >= REST_AFTER_STEPS;
        }
        gpu->reportMotion(timeIndependent ? GPU_STILL_TIP_MOVE : 0.0f);
    }
    if (resting) {
        // The clock goes on; the blades, where the last step left them, would stay there.
        const auto due = static_cast<std::size_t>(std::floor(targetS / dtS + 1e-6));
        steps = std::max(steps, due);
        moved = false;
        return 0.0;
    }
    int stepped = 0;
    const auto start = std::chrono::steady_clock::now();
    for (; stepped < maxSteps && timeS() + dtS * (1.0 - 1e-6) <= targetS; ++stepped) {
        if (budgetMs > 0.0 && stepped > 0 &&
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count() >= budgetMs)
            break;
        // η as the frame found it, to tell the blades a collider holds from those recovering:
        // taken before its first step only (a paused frame steps nothing and copies nothing).
        if (stepped == 0 && cpu && timeIndependent) {
            etaBefore.resize(cpu->layerCount());
            for (std::size_t layer = 0; layer < cpu->layerCount(); ++layer)
                etaBefore[layer].assign(cpu->eta(layer).begin(), cpu->eta(layer).end());
        }
        if (cpu) {
            cpu->step(scene, static_cast<float>(timeS()));
        } else {
            gpu->step(scene, static_cast<float>(timeS()));
            ++gpuStepsUnanswered;
        }
        ++steps;
        ++computedSteps;
    }
    if (gpu && stepped > 0)
        moved = true;  // stepped in place: drawn again until the field rests
    // The CPU's blades go up once, after the frame's steps, and only the layers they moved.
    if (cpu && stepped > 0) {
        moved = false;
        shownTips.resize(cpu->layerCount());
        for (std::size_t layer = 0; layer < cpu->layerCount(); ++layer)
            if (tipsMoved(cpu->blades(layer), shownTips[layer])) {
                moved = true;
                if (renderer != nullptr)
                    renderer->uploadBlades(layer, cpu->blades(layer));
            }
        stillSteps = moved ? 0 : stillSteps + static_cast<std::size_t>(stepped);
        const float decayPerS =
            std::isfinite(scene.params.etaDecayPerS) ? scene.params.etaDecayPerS : 0.0f;
        resting = timeIndependent && stillSteps >= REST_AFTER_STEPS &&
                  !anyRecovering(*cpu, etaBefore, decayPerS * static_cast<float>(stepped * dtS));
    }
    const double behindS = targetS - timeS();
    if (behindS < dtS)
        return 0.0;
    const auto skipped = static_cast<std::size_t>(std::floor(behindS / dtS));
    steps += skipped;
    const double dropped = static_cast<double>(skipped) * dtS;
    droppedS += dropped;
    return dropped;
}

void LivePhysics::regrown(std::size_t layer, const core::Scene& field,
                          const std::vector<std::uint32_t>& patches) {
    // The re-grown blades carry the snow the rest of the field does (as a field grown so
    // carries it in grass render and grass sim).
    core::reweighSnowLoads(scene, field, layer, patches);
    if (gpu && scene.anySnowLoad())
        gpu->reloadSnowLoads();
    if (cpu) {
        cpu->resetPatches(layer, field, patches);
        shownTips.clear();  // the renderer has the patches at rest: compare anew
    } else {
        gpu->uploadRegrown(layer, field, patches);
    }
    wake();
}

// Auto: the CPU on software GL, the GPU elsewhere.
static bool physicsOnCpu(PhysicsDevice device) {
    if (device != PhysicsDevice::Auto)
        return device == PhysicsDevice::Cpu;
    return gl::isSoftwareRenderer();
}

Live& Live::operator=(Live&& next) noexcept {
    if (this == &next)
        return *this;
    physics.reset();
    renderer.reset();  // waits for its billboard worker
    tools.reset();
    scene.reset();
    builtFrom = std::move(next.builtFrom);
    scene = std::move(next.scene);
    tools = std::move(next.tools);
    renderer = std::move(next.renderer);
    physics = std::move(next.physics);
    motion = std::move(next.motion);
    return *this;
}

Result<GrownField> growField(core::LoadedProject loaded, bool withPhysics,
                             core::GltfImport* alreadyRead, const core::Scene* sameSurface,
                             std::stop_token stop, const core::BuildProgress& progress) {
    auto scene = sameSurface != nullptr
                     ? core::regrowOnSameSurface(loaded, *sameSurface, stop, progress)
                     : core::buildScene(loaded, alreadyRead, stop, progress);
    if (!scene)
        return scene.error();
    GrownField grown;
    grown.scene = std::make_unique<core::Scene>(std::move(*scene));
    if (withPhysics) {
        auto built = core::buildScenePhysics(loaded, grown.scene->groundOrigin, &grown.packings);
        if (!built)
            return built.error();
        // The snow's load on each blade, from the field at rest, as grass render and grass sim
        // take it: before, the live field bent under no snow at all.
        if (progress && core::snowLoadsBlades(built->snow))
            progress("weighing the snow on the blades");
        core::prepareSnowLoads(*built, *grown.scene);
        grown.physics.emplace(std::move(*built));
    }
    grown.loaded = std::move(loaded);
    return grown;
}

Result<Live> bringUpLive(GrownField grown, const std::function<Result<void>(core::Scene&)>& prepare,
                         PhysicsDevice device, const Live* grownOn) {
    for (const auto& note : grown.scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    if (prepare)
        if (auto prepared = prepare(*grown.scene); !prepared)
            return prepared.error();
    Live live;
    live.builtFrom = std::move(grown.loaded);
    live.motion.wind = live.builtFrom.project.wind;
    live.motion.physics = live.builtFrom.project.physics;
    live.motion.colliders = live.builtFrom.project.colliders;
    live.motion.settledColliders = live.motion.colliders;
    live.motion.packings = std::move(grown.packings);
    live.scene = std::move(grown.scene);
    live.tools = std::make_unique<SceneTools>(*live.scene, live.builtFrom.project.lighting,
                                              grownOn != nullptr ? grownOn->tools.get() : nullptr);
    auto renderer = render::SceneRenderer::create(
        *live.scene, grownOn != nullptr ? grownOn->renderer.get() : nullptr);
    if (!renderer)
        return renderer.error();
    live.renderer = std::move(*renderer);
    if (grown.physics) {
        for (const auto& note : grown.physics->notes)
            std::fprintf(stderr, "note: %s\n", note.c_str());
        LivePhysics physics;
        physics.scene = std::move(*grown.physics);
        physics.renderer = live.renderer.get();
        physics.timeIndependent = timeIndependent(physics.scene);
        if (physicsOnCpu(device)) {
            physics.cpu.emplace(*live.scene);
        } else {
            auto gpu =
                render::ScenePhysicsGpu::createOn(*live.scene, live.renderer->bladeBuffers());
            if (!gpu)
                return gpu.error();
            physics.gpu.emplace(std::move(*gpu));
        }
        live.physics.emplace(std::move(physics));
    }
    return live;
}

// Puts every layer's blades back at rest on the GPU and restarts the simulation from there
// (keeping its step count).
Result<void> resetPhysics(Live& live) {
    for (std::size_t layer = 0; layer < live.scene->layers.size(); ++layer) {
        core::RegrowReport all;
        for (std::uint32_t p = 0; p < live.scene->layers[layer].patched.patches.size(); ++p)
            all.patches.push_back(p);
        live.renderer->uploadRegrown(layer, all);
    }
    if (live.physics->cpu) {
        live.physics->cpu->reset(*live.scene);
        live.physics->shownTips.clear();
        live.physics->wake();
        return {};
    }
    auto gpu = render::ScenePhysicsGpu::createOn(*live.scene, live.renderer->bladeBuffers());
    if (!gpu)
        return gpu.error();
    live.physics->gpu = std::move(*gpu);
    live.physics->wake();
    return {};
}

bool LiveMotion::packed(const std::vector<core::ColliderDesc>& wanted) const {
    return std::all_of(wanted.begin(), wanted.end(), [&](const core::ColliderDesc& c) {
        return c.shape != core::ColliderShape::Mesh ||
               packings.byFile.contains({c.file, c.sphereCount, c.packingResolution});
    });
}

void LiveMotion::forgetFiles(const std::set<std::string>& files) {
    std::erase_if(packings.byFile,
                  [&](const auto& entry) { return files.contains(std::get<0>(entry.first)); });
    std::erase_if(readAheadProps, [&](const auto& entry) { return files.contains(entry.first); });
    changedFiles.insert(files.begin(), files.end());
}

void LiveMotion::takeReadAhead(core::ColliderPackings packed,
                               std::map<std::string, core::MovableSurfaceMesh> props) {
    for (auto& [key, packing] : packed.byFile)
        packings.byFile.try_emplace(key, std::move(packing));
    for (auto& [file, mesh] : props)
        readAheadProps.insert_or_assign(file, std::move(mesh));
}

bool followPhysicsSteps(Live& live, const core::PhysicsParams& physics) {
    LiveMotion& motion = live.motion;
    if (physics == motion.physics || physics.gravity != motion.physics.gravity ||
        physics.gravityMode != motion.physics.gravityMode)
        return false;
    if (live.physics)
        live.physics->followParams(physics);
    motion.physics = physics;
    return true;
}

Result<bool> followMotion(Live& live, const core::LoadedProject& loaded, bool settled) {
    const core::Project& project = loaded.project;
    LiveMotion& motion = live.motion;
    bool changed = false;
    const bool filesChanged = !motion.changedFiles.empty();
    if (project.wind != motion.wind || project.colliders != motion.colliders || filesChanged) {
        // Both built before either is taken, so a file that cannot be read changes nothing.
        std::optional<core::ScenePhysics> built;
        if (live.physics) {
            auto physics =
                core::buildScenePhysics(loaded, live.scene->groundOrigin, &motion.packings);
            if (!physics)
                return physics.error();
            built.emplace(std::move(*physics));
        }
        const bool propsMove =
            !filesChanged && core::sameProps(motion.colliders, project.colliders);
        std::vector<core::SceneProp> props;
        if (!propsMove) {
            // The props of changed files give up no mesh: theirs are made anew.
            std::vector<core::ColliderDesc> madeFor = motion.colliders;
            for (core::ColliderDesc& c : madeFor)
                if (c.shape == core::ColliderShape::Mesh && motion.changedFiles.contains(c.file))
                    c.file.clear();
            auto loadedProps =
                core::remakeSceneProps(loaded, live.scene->props, madeFor, live.scene->groundOrigin,
                                       &motion.readAheadProps);
            motion.readAheadProps.clear();
            if (!loadedProps)
                return loadedProps.error();
            props = std::move(*loadedProps);
        }
        if (built) {
            LivePhysics& physics = *live.physics;
            physics.scene.wind = std::move(built->wind);
            physics.scene.colliders = std::move(built->colliders);
            physics.timeIndependent = timeIndependent(physics.scene);
            physics.wake();
        }
        if (propsMove) {
            for (std::size_t i = 0; i < live.scene->props.size(); ++i)
                core::placeSceneProp(live.scene->props[i], project.colliders[i]);
        } else {
            live.scene->props = std::move(props);
            live.renderer->reloadProps();
        }
        motion.wind = project.wind;
        motion.colliders = project.colliders;
        motion.changedFiles.clear();
        motion.placementOfOldShapes = motion.placementOfOldShapes || filesChanged;
        // A prop of another shape shelters the snow elsewhere.
        if (filesChanged && live.physics && live.physics->scene.anySnowLoad())
            live.physics->weighSnowAgain(*live.scene);
        changed = true;
    }
    changed = followPhysicsSteps(live, project.physics) || changed;
    // Where the colliders stood, the blades they held rise; the props shelter the snow: where
    // they moved, the blades carry another load.
    if (settled && motion.settledColliders != motion.colliders) {
        if (live.physics) {
            live.physics->releaseHeldBlades();
            if (live.physics->scene.anySnowLoad())
                live.physics->weighSnowAgain(*live.scene);
            changed = true;
        }
        motion.settledColliders = motion.colliders;
    }
    return changed;
}

Result<std::size_t> followColliderPlacement(Live& live, const core::Project& project) {
    auto changed = core::followColliderPlacement(*live.scene, project);
    if (!changed)
        return changed.error();
    std::size_t patches = 0;
    for (const auto& [layer, report] : *changed) {
        live.renderer->uploadRegrown(layer, report);
        if (live.physics)
            live.physics->regrown(layer, *live.scene, report.patches);
        patches += report.patches.size();
    }
    live.renderer->billboardsChanged();
    live.builtFrom.project.colliders = project.colliders;
    live.motion.placementOfOldShapes = false;
    return patches;
}

}  // namespace grass::editor
