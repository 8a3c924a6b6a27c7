#include "tools/tradeoff_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/color_difference.h"
#include "util/pareto.h"

namespace grass::render::tradeoff {

namespace {

// A channel differing by more than this from the feature-free frame marks a pixel as touched by
// the feature: 8-bit rounding of the same colour never moves a channel by more than 1.
constexpr int MASK_THRESHOLD = 2;
// The reference has converged when refining it changes the result by less than a tenth of what
// a user can see: a tenth of a just-noticeable difference (ΔE76 2.3) in the image, a thousandth
// of a blade height at the tips (a tenth of the balanced preset's bound).
constexpr double CONVERGED_DELTA_E = 0.23;
constexpr double CONVERGED_TIP_ERROR = 0.001;
// It also resolves every swept error when the check differs from it by less than this share of
// the smallest one: then each swept error is known to within a factor of 2 and their order
// holds. Strip segments on meadow do not (a floor of ~0.15–0.19 ΔE from 16 to 128 segments,
// isolated pixels spread over the field), so settings below ~0.4 ΔE are not told apart there.
constexpr double RESOLVED_SHARE = 0.5;

void markTouched(const gl::Rgba8Image& image, const gl::Rgba8Image& background,
                 std::vector<std::uint8_t>& mask) {
    for (std::size_t i = 0; i < mask.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(int(image.pixels[4 * i + c]) - int(background.pixels[4 * i + c])) >
                MASK_THRESHOLD)
                mask[i] = 1;
}

}  // namespace

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

Spread spreadOf(const std::vector<double>& values) {
    if (values.empty())
        return {};
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    return {median(values), *low, *high};
}

std::string fraction(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "1/%.0f s", 1.0 / seconds);
    return text;
}

std::string metres(double m) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m", m);
    return text;
}

Frame ImageBench::draw(SceneRenderer& target, const RenderOptions& render,
                   const std::string& what) {
    Frame frame;
    std::vector<double> wall, mesh, cull, grass, billboard, snow;
    for (int i = 0; i <= options.frames; ++i) {
        if (options.progress && i > 0)
            options.progress(what + ": frame " + std::to_string(i) + "/" +
                             std::to_string(options.frames));
        const auto start = Clock::now();
        target.render(camera, options.width, options.height, framebuffer, render);
        glFinish();
        const double ms = msSince(start);
        // Frame 0 pays for shader compiles and first allocations (a new snow map size).
        if (i == 0)
            continue;
        const FrameTimings t = target.lastTimings();
        wall.push_back(ms);
        mesh.push_back(t.meshMs);
        cull.push_back(t.cullMs);
        grass.push_back(t.grassMs);
        billboard.push_back(t.billboardMs);
        snow.push_back(t.snowMs);
        frame.timing.bladesDrawn = t.bladesDrawn;
    }
    frame.timing.costMs = spreadOf(wall);
    frame.timing.meshMs = median(mesh);
    frame.timing.cullMs = median(cull);
    frame.timing.grassMs = median(grass);
    frame.timing.billboardMs = median(billboard);
    frame.timing.snowMs = median(snow);
    frame.image = framebuffer.readPixels();
    return frame;
}

void setImageError(const ImageBench& bench, const gl::Rgba8Image& frame,
                   const gl::Rgba8Image& reference, const gl::Rgba8Image& background,
                   SettingResult& result) {
    std::vector<std::uint8_t> mask(
        bench.framebuffer.width() * std::size_t(bench.framebuffer.height()), 0);
    markTouched(frame, background, mask);
    markTouched(reference, background, mask);
    const core::MaskedDeltaE e = core::maskedDeltaE76(frame.pixels, reference.pixels, mask);
    result.error = e.meanDeltaE;
    result.errorMax = e.maxDeltaE;
    result.pixels = e.pixels;
}

void finishKnob(KnobResult& knob) {
    std::vector<core::CostError> points;
    for (const SettingResult& s : knob.settings)
        points.push_back(s.check ? core::CostError{NAN, NAN}
                                 : core::CostError{s.costMs.median, s.error});
    const std::vector<bool> front = core::paretoFront(points);
    double smallest = INFINITY;
    for (std::size_t i = 0; i < knob.settings.size(); ++i) {
        knob.settings[i].pareto = front[i];
        if (!knob.settings[i].reference && !knob.settings[i].check)
            smallest = std::min(smallest, knob.settings[i].error);
    }
    if (!knob.checkLabel.empty()) {
        knob.convergedBelow =
            knob.name == "physics_step" ? CONVERGED_TIP_ERROR : CONVERGED_DELTA_E;
        knob.referenceConverged = knob.referenceCheckError < knob.convergedBelow;
        knob.referenceResolvesSweep = knob.referenceCheckError < RESOLVED_SHARE * smallest;
    }
}

}  // namespace grass::render::tradeoff
