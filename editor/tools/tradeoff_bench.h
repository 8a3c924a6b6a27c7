// Internals shared by grass tradeoff's knobs (tradeoff_sweep.cpp, tradeoff_physics_knob.cpp,
// tradeoff_bake_knobs.cpp): timing, the image bench that draws a frame of a setting, the image
// error against a reference, and the Pareto and convergence verdicts of a knob.
#pragma once

#include <string>
#include <vector>

#include "gl/framebuffer.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"
#include "render/scene_renderer.h"
#include "tools/ms_since.h"
#include "tools/tradeoff_sweep.h"
#include "util/result.h"

namespace grass::render::tradeoff {

using tools::Clock;
using tools::msSince;

double median(std::vector<double> values);
Spread spreadOf(const std::vector<double>& values);
std::string fraction(double seconds);  // "1/60 s"
std::string metres(double m);          // "8 m"

struct Frame {
    gl::Rgba8Image image;
    SettingResult timing;
};

// Everything the image knobs share: the scene at the sweep's time, drawn with grass and without.
struct ImageBench {
    SceneRenderer& renderer;
    SceneRenderer& noGrass;
    core::OrbitCamera camera;
    gl::Framebuffer framebuffer;
    RenderOptions base;
    const TradeoffOptions& options;

    // One untimed warm-up frame, then options.frames timed ones; the last frame's image.
    Frame draw(SceneRenderer& target, const RenderOptions& render, const std::string& what);
};

// The image error of `frame` against `reference`: mean and max ΔE76 over the pixels either
// differs in from `background` (the frame without the feature), into result.
void setImageError(const ImageBench& bench, const gl::Rgba8Image& frame,
                   const gl::Rgba8Image& reference, const gl::Rgba8Image& background,
                   SettingResult& result);

// Marks the knob's Pareto front and the reference check's verdicts.
void finishKnob(KnobResult& knob);

// The knobs that are not one render option (tradeoff_physics_knob.cpp, tradeoff_bake_knobs.cpp).
Result<KnobResult> measurePhysicsKnob(const core::Scene& grown, const core::ScenePhysics& physics,
                                      const TradeoffOptions& options, const std::string& prefix);
Result<KnobResult> measureAoKnob(ImageBench& bench, const core::Scene& scene,
                                 const core::GrassLightingDesc& lighting, const std::string& prefix);
KnobResult measureClassesKnob(ImageBench& bench, const core::Scene& scene,
                              const std::string& prefix);

}  // namespace grass::render::tradeoff
