// Whether the viewport's picture must be drawn again. The window is immediate mode: every frame
// builds and draws the panels, and the viewport's picture used to be drawn with them, costing
// the whole scene each time (the meadow 310 ms on llvmpipe, an 8.4-million-triangle ground
// 1.7 s) even while nothing in it changed: hovering, clicking and typing in the panels of a
// paused field waited for it. The picture is drawn into its own framebuffer and blitted under the
// panels, so a frame whose inputs equal those of the last drawn picture blits that one again.
//
// The inputs are everything render::SceneRenderer::render reads: the renderer and what changed
// on it between frames (uploads, the map overlay: its content generation), the physics' step
// count (the GPU physics steps the renderer's blades in place), the camera, the target's size
// and samples, the render options (less the switches that change what is measured, not what is
// drawn), the project (whatever the panels edit lands there), and the looks the renderer reads
// from the scene's layers every frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "blade/blade_shape.h"
#include "project/project.h"
#include "render/render_options.h"
#include "render/scene_renderer.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace grass::editor {

// What the renderer reads from each of the scene's layers every frame (the panels change the
// colours and the shape on the drawn field at once).
struct LayerLook {
    glm::vec3 rootColor{0.0f}, tipColor{0.0f}, poorRootColor{0.0f}, poorTipColor{0.0f};
    core::BladeShape shape = core::BladeShape::Triangle;
    float tipStart = 0.0f;
    std::size_t liveBlades = 0;
    bool operator==(const LayerLook&) const = default;
};

struct ViewInputs {
    const render::SceneRenderer* renderer = nullptr;
    std::uint64_t rendererGeneration = 0;
    // The editor's count of changes to the live field (EditorState::mapsChanged: a field adopted,
    // patches re-grown): a new renderer may sit at the old one's address.
    std::uint64_t liveGeneration = 0;
    std::size_t physicsSteps = 0;
    core::OrbitCamera camera;
    int width = 0, height = 0, samples = 0;
    render::RenderOptions options;
    core::Project project;
    std::vector<LayerLook> layers;
    bool operator==(const ViewInputs&) const = default;
};

struct ViewTarget {
    int width = 0, height = 0, samples = 0;
};

ViewInputs viewInputsOf(const render::SceneRenderer& renderer, std::uint64_t liveGeneration,
                        std::size_t physicsSteps, const core::OrbitCamera& camera,
                        ViewTarget target, const render::RenderOptions& options,
                        const core::Project& project, const core::Scene& scene);

// Whether the picture changes with the timeline's time alone, the blades as they are: billboards
// sway, props move along their paths, snow falls or melts (what the renderer reads of
// RenderOptions::timeS). When it does not, the time is no input of the picture: a field that
// nothing moves is not drawn again while the timeline plays. The blades' own motion is not in
// it: the CPU physics says whether it moved the blades (LivePhysics::moved), the GPU's steps are
// inputs (ViewInputs::physicsSteps).
bool timeChangesThePicture(const core::Scene& scene, const render::RenderOptions& options);

// Whether the picture drawn for `drawn` (none: nothing drawn yet) is the one `now` would draw.
// A renderer whose worker places billboards draws every frame: its frame takes them in.
bool viewStillDrawn(const std::optional<ViewInputs>& drawn, const ViewInputs& now,
                    bool placingBillboards);

}  // namespace grass::editor
