// The live scene of the editor window: the grown field, the tools that pick and paint it, its
// renderer and the GPU physics stepping the renderer's blades, built and rebuilt together.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "project/project.h"
#include "scene/scene.h"
#include "scene/field_simulation.h"
#include "scene/scene_physics.h"
#include "render/scene_physics_gpu.h"
#include "render/scene_renderer.h"
#include "util/result.h"
#include "app/viewport_tools.h"

namespace grass::editor {

// Where the editor's live physics runs: the compute shader on the GL device, or the SIMD
// execution on the CPU with one upload of the blades a frame. Auto: the CPU on software
// renderers, where it is measured ~10× faster than the compute shader (llvmpipe, 2 cores: the
// meadow steps in 2.7 ms against 28 ms; docs/physics.md); the GPU elsewhere. Both apply the
// snow's load (core::prepareSnowLoads, made when the field grows).
enum class PhysicsDevice { Auto, Cpu, Gpu };
const char* physicsDeviceName(PhysicsDevice device);  // "auto" | "cpu" | "gpu"

// Physics stepping the renderer's blades in fixed steps of the project's step_s, following the
// timeline's time with at most MAX_STEPS_PER_FRAME steps a frame. What a slow device cannot
// step is dropped (the field jumps to the timeline's time) rather than piled up, so the field
// keeps moving with the wind and colliders it sees; droppedS says how much, for the status bar.
// Exactly one of gpu and cpu is set.
// Whether any blade's tip (v2) moved by more than STILL_TIP_SHARE of its height from `shownTips`
// (the tips as last uploaded; empty or of another size: moved). When moved, `shownTips` becomes
// the blades' tips. A field that nothing moves (no wind, the blades settled) is then neither
// uploaded nor drawn again while the timeline plays; the picture lags the physics by less than
// the share (1e-4 of a 0.5 m blade: 50 µm).
inline constexpr float STILL_TIP_SHARE = 1e-4f;
bool tipsMoved(std::span<const core::Blade> blades, std::vector<glm::vec3>& shownTips);
// Whether a crushed blade is recovering: its η fell over the frame by more than half the pure
// decay (`decay`, etaDecayPerS times the frame's simulated time), so no collider pressed it. Such
// a blade may stand still while η decays (its stiffness held at crushedRecoveryFloor) and rise
// once η falls below 1 − floor: the field must not rest. A blade a static collider holds down
// (a rock on the grass) has η rising, or falling less (collisions add to it): the step keeps it
// where it is. `etaBefore` empty or of another size: recovering (nothing to compare).
bool anyRecovering(std::span<const float> eta, std::span<const float> etaBefore, float decay);

struct LivePhysics {
    static constexpr int MAX_STEPS_PER_FRAME = 4;
    // On the CPU a frame steps on to the timeline's time while its steps took less than
    // CPU_STEP_BUDGET_MS, up to MAX_CPU_STEPS_PER_FRAME: at llvmpipe's 10 frames a second four
    // steps of 1/60 s dropped a third of the time (projects/winter, whose step costs 0.35 ms,
    // played "physics behind: skipping 0.3 s per s"), while a step's cost is known only on the
    // CPU (the GPU's are queued).
    static constexpr int MAX_CPU_STEPS_PER_FRAME = 16;
    static constexpr double CPU_STEP_BUDGET_MS = 12.0;
    core::ScenePhysics scene;
    std::optional<render::ScenePhysicsGpu> gpu;
    std::optional<core::FieldSimulation> cpu;
    render::SceneRenderer* renderer = nullptr;  // receives the CPU's blades after its steps
    std::size_t steps = 0;
    double droppedS = 0.0;  // simulated time skipped since the field was built
    // Whether the last frame that stepped moved the blades (tipsMoved, on the CPU): while the
    // timeline plays a field that stands still, the picture is full and drawn once (Editor).
    // On the GPU, whose blades are stepped in place and never read back, true until it rests.
    bool moved = true;
    std::vector<std::vector<glm::vec3>> shownTips;  // per layer (CPU): the tips uploaded
    std::vector<std::vector<float>> etaBefore;      // per layer (CPU): η before the frame's steps
    // A field on the CPU that nothing moves any more rests: its steps are not computed (the
    // clock still counts them) until a brush, an undo or a reset moves its blades again. It rests
    // once nothing in the scene depends on time (no wind, no collider on a path, no snow that
    // grows or melts: timeIndependent), no crushed blade is recovering (anyRecovering: a blade
    // under a rock stays crushed, a trail must rise) and no tip moved (tipsMoved) for
    // REST_AFTER_STEPS steps in a row. A new project from a mesh has no wind:
    // played, its blades settle under gravity in about a second, and stepping them on (82,913
    // blades of an 8.4 M-triangle mesh: 6.5 ms a frame) changed nothing on screen.
    //
    // On the GPU the steps themselves mark whether they moved a tip by more than
    // GPU_STILL_TIP_MOVE of its height or let a crushed blade recover (physics.comp, read a frame
    // later behind a fence: ScenePhysicsGpu::takeMotion), and the field rests after
    // REST_AFTER_STEPS unmarked steps in a row: a still step moves each tip at most a sixtieth
    // of STILL_TIP_SHARE, so the steps before the rest moved it less than that share in all.
    // Before 2026-12-07 a field on the GPU never rested: the editor stepped and drew a still
    // field every frame while the timeline played.
    static constexpr std::size_t REST_AFTER_STEPS = 60;
    static constexpr float GPU_STILL_TIP_MOVE = STILL_TIP_SHARE / float(REST_AFTER_STEPS);
    std::size_t gpuStepsUnanswered = 0;  // GPU steps since takeMotion last answered
    bool timeIndependent = false;  // set when built (bringUpLive)
    bool resting = false;
    std::size_t stillSteps = 0;     // steps in a row that moved no tip
    std::size_t computedSteps = 0;  // steps actually computed (tests; the status bar's cost)

    double timeS() const { return static_cast<double>(steps) * scene.params.dtS; }
    // "cpu" or "gpu", for the status bar.
    std::string deviceLabel() const;
    // Steps towards `targetS`, at most `maxSteps`, and no more once `budgetMs` (> 0) of wall
    // time went into them (one step at least); returns the time dropped this frame (0 when it
    // kept up).
    double advanceTo(double targetS, int maxSteps = MAX_STEPS_PER_FRAME, double budgetMs = 0.0);
    // After a brush or an undo re-grew patches of `layer`: they restart at rest, under the
    // snow they now carry (core::reweighSnowLoads).
    void regrown(std::size_t layer, const core::Scene& scene,
                 const std::vector<std::uint32_t>& patches);
    // Its blades were moved from outside (a re-grow, a reset): it steps again.
    void wake();
    // The project's snow, after an edit of the Snow section (which re-grows nothing): when it
    // differs from what the physics weighs, the loads are weighed again from `field` at rest
    // (core::prepareSnowLoads; ~0.5 s for projects/winter's 1024² map on 2 cores) and the field
    // steps on under them. Returns whether it changed anything.
    bool followSnow(const core::SnowParams& snow, const core::Scene& field);
    // The snow's loads weighed again from `field` at rest under scene.snow (prepareSnowLoads):
    // after the snow changed, or the props that shelter it moved.
    void weighSnowAgain(const core::Scene& field);
    // After an edit moved the colliders: the blades they held down are let go. η beyond
    // RELEASED_ETA (a blade fully crushed, for longer the longer a collider pressed it: η grows
    // by d·d every step a still collider holds a blade, 40 after 20 s under a sunk ball) falls
    // to it, so the imprint of a collider that stood still fades as a fresh trail does (stiffness
    // at its floor until η < 1 − floor, 0.2 s at the default decay) instead of η / decay seconds
    // (80 s after those 20 s, hours after a long play). Blades the colliders press where they
    // now stand are crushed again by the next step. Trails below it keep their η.
    static constexpr float RELEASED_ETA = 1.0f;
    void releaseHeldBlades();
    // Steps on with `params` (a quality preset's substeps): the blades keep their motion, and the
    // physics' time stays where it was in another step's count.
    void followParams(const core::PhysicsParams& params);
};

// What the live physics and the colliders' props follow now: the project's wind sources and
// colliders as of the last followMotion (or of the field's growing), with the packings of its
// mesh colliders kept so that following a drag reads no file.
struct LiveMotion {
    std::vector<core::WindDesc> wind;
    std::vector<core::ColliderDesc> colliders;
    core::PhysicsParams physics;  // how the live physics steps (core::onlyMotionChanged)
    // The colliders as of the last edit that ended: the snow's loads were weighed under them
    // (their props shelter the snow) and the blades they held were let go then.
    std::vector<core::ColliderDesc> settledColliders;
    core::ColliderPackings packings;
    // Mesh colliders' meshes read already, by file (add mesh… reads its file on a worker): the
    // next followMotion makes their props from these instead of reading the files on the
    // window's thread, then lets them go.
    std::map<std::string, core::MovableSurfaceMesh> readAheadProps;
    // Mesh colliders' files another program changed (a rock re-exported from a modeller) since
    // their packings and props were made: the next followMotion makes their props again, from
    // readAheadProps or the file, and builds the physics with their new packings.
    std::set<std::string> changedFiles;
    // Props were made again from changed files since the field's placement was grown: where a
    // layer clears the ground under the colliders, followColliderPlacement takes their shapes.
    bool placementOfOldShapes = false;
    // Whether every mesh collider of `wanted` has its packing here: then following them
    // packs nothing (which could take seconds on the window's thread).
    bool packed(const std::vector<core::ColliderDesc>& wanted) const;
    // `files` (as the project names them) changed on disk: their packings are let go, so the
    // next follow packs them again (ColliderPackingJob), and their props are made again.
    void forgetFiles(const std::set<std::string>& files);
    // What a worker packed and read (ColliderPackingJob), kept for the next follow: a packing
    // held already stays, a prop's mesh replaces one read before.
    void takeReadAhead(core::ColliderPackings packed,
                       std::map<std::string, core::MovableSurfaceMesh> props);
};

// What a project becomes on the GPU; rebuilt whole when the project is re-grown or replaced.
// Members are destroyed in reverse order: the physics (which steps the renderer's buffers)
// before the renderer, the renderer (which points at the scene) before the scene.
struct Live {
    core::LoadedProject builtFrom;  // the project `scene` was grown from (core::sameSurface)
    std::unique_ptr<core::Scene> scene;
    std::unique_ptr<SceneTools> tools;  // picks and paints `scene`
    std::unique_ptr<render::SceneRenderer> renderer;
    std::optional<LivePhysics> physics;
    LiveMotion motion;

    Live() = default;
    Live(Live&&) noexcept = default;
    // Replacing a live field lets the old one go in the order its destruction would: a
    // member-wise move would free the old scene before the old renderer, whose billboard worker
    // may still be reading it (SceneRenderer::placeBillboardsInBackground).
    Live& operator=(Live&& next) noexcept;
};

// What growing a project makes before the GPU sees it: nothing here touches GL, so a worker
// thread may grow it while the window goes on drawing the field before it (document_job.h).
struct GrownField {
    core::LoadedProject loaded;  // what it was grown from
    std::unique_ptr<core::Scene> scene;
    std::optional<core::ScenePhysics> physics;  // when grown with physics
    // The packings of its mesh colliders (LiveMotion::packings), so the first frame of a drag
    // reads no file either.
    core::ColliderPackings packings;
};

// The project's field and, `withPhysics`, its physics scene. `alreadyRead`: the project's mesh
// as newProjectFromMesh or projectWithImportedMesh read it (core::buildScene's). `sameSurface`:
// the scene of a project with the same surface (core::sameSurface), whose mesh the field grows
// on instead of the file's (core::regrowOnSameSurface). `stop`: a request ends the growing
// between its stages with core::buildStopped.
Result<GrownField> growField(core::LoadedProject loaded, bool withPhysics,
                             core::GltfImport* alreadyRead = nullptr,
                             const core::Scene* sameSurface = nullptr, std::stop_token stop = {},
                             const core::BuildProgress& progress = {});

// The grown field on the GPU (renderer, tools, physics): on the thread that owns the GL context.
// `prepare` runs on the grown scene before the GPU sees it (painted maps carried over).
// `grownOn`: a live field of the same surface, whose picking BVH the tools share and whose
// surface mesh on the GPU the renderer shares.
Result<Live> bringUpLive(GrownField grown,
                         const std::function<Result<void>(core::Scene&)>& prepare = {},
                         PhysicsDevice device = PhysicsDevice::Auto, const Live* grownOn = nullptr);

// Puts every layer's blades back at rest on the GPU and restarts the simulation from there
// (keeping its step count).
Result<void> resetPhysics(Live& live);

// How the physics steps (a quality preset's substeps, its step) followed at once: the live
// physics steps on with `physics`, the blades as they are. Not when the gravity changed (the
// field grows leaning under it: that is a re-grow). Returns whether anything changed.
bool followPhysicsSteps(Live& live, const core::PhysicsParams& physics);

// After an edit of `loaded` that changed only what moves the field (core::onlyMotionChanged
// against live.builtFrom): the live physics takes its wind sources and colliders (built as
// core::buildScenePhysics builds them, the packings from live.motion) and the colliders' props
// follow (moved, or made again when a collider was added, deleted or given another mesh:
// core::sameProps, or its file changed on disk: LiveMotion::changedFiles), while the field keeps
// its blades, their motion and their trails. Called every
// frame of a gizmo drag; `settled` (the edit has ended), when the colliders moved: the blades they
// held are let go (LivePhysics::releaseHeldBlades) and the snow's loads are weighed again under
// them where they now stand (~0.5 s for projects/winter), not on every frame of the drag. Returns
// whether anything changed; errors: a collider's file could not be read.
Result<bool> followMotion(Live& live, const core::LoadedProject& loaded, bool settled);

// Once an edit that moved, added or deleted colliders has ended (followMotion placed their props)
// in a project whose layers clear the ground under colliders (core::placementFollowsColliders):
// the blades grow back where the colliders left and go where they now stand, in the patches that
// changed alone (core::followColliderPlacement: the field a fresh build would grow), uploaded
// to the renderer and restarted at rest in the physics; the rest of the field keeps its motion.
// The live field then counts as grown for these colliders (builtFrom). Returns the number of
// patches grown again. Before, the whole field grew again on a worker once the drag ended.
Result<std::size_t> followColliderPlacement(Live& live, const core::Project& project);

}  // namespace grass::editor
