// The cost of the editor's UI (`grass bench`'s UI column): the side panel, menu and status bar
// over a scene, as bench_ui drives them: a 1280×720 window, the pointer over the panel, the
// median CPU ms of build + layout + tessellation over 30 frames after two to settle.
#pragma once

#include <cstddef>

#include "project/project.h"
#include "render/scene_renderer.h"
#include "scene/scene.h"
#include "ui/font.h"

namespace grass::tools {

// Frames timed after the two that settle the layout.
inline constexpr int UI_FRAMES = 30;

struct UiCost {
    double ms = 0.0;
    std::size_t shapes = 0, vertices = 0;  // of the last frame, to show what was measured
};

UiCost measureUi(const ui::FontAtlas& fonts, core::LoadedProject loaded, core::Scene& scene,
                 const render::RenderOptions& options, const render::FrameTimings& timings);

}  // namespace grass::tools
