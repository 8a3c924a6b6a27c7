// grass tradeoff's knobs that are not one render option: the shading bake's cells (ao_kernel)
// and the thinning classes (distance_classes), whose error is the density's.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tools/tradeoff_bench.h"

namespace grass::render::tradeoff {

// The AO bake (SPEC §10): neighbours summed per cluster in cells of `cellSigmas` σ, against
// the exact sums. Cost is the bake's CPU wall time (it runs when the scene is built or painted);
// the error is the grass's ΔE76 in the frame drawn with that bake.
Result<KnobResult> measureAoKnob(ImageBench& bench, const core::Scene& scene,
                                 const core::GrassLightingDesc& lighting, const std::string& prefix) {
    KnobResult knob;
    knob.name = "ao_kernel";
    knob.description = "AO and normal-blur bake: cluster cell side in kernel σ (exact: every "
                       "neighbour on its own)";
    knob.errorMetric = "mean CIELAB ΔE76 over the pixels the grass touches in either image";
    knob.costMetric = "bake wall ms over all layers (CPU, every core; median of the bakes)";
    const gl::Rgba8Image background =
        bench.draw(bench.noGrass, bench.base, prefix + " background").image;
    const auto bakeAndDraw = [&](float cellSigmas,
                                 const std::string& label) -> Result<std::pair<Frame, Spread>> {
        core::Scene baked = scene;
        core::BladeShadingParams params = core::bladeShadingParams(lighting);
        params.cellSigmas = cellSigmas;
        std::vector<double> bakeMs;
        const int bakes = std::clamp(bench.options.frames, 1, 3);
        for (int b = 0; b < bakes; ++b) {
            double ms = 0.0;
            for (core::LayerField& layer : baked.layers) {
                const auto start = Clock::now();
                auto shading = core::bakeBladeShading(layer.patched.blades, params, layer.seed);
                if (!shading)
                    return shading.error();
                ms += msSince(start);
                // Only the AO and the blurred normal change; water, age and wilt stay.
                for (std::size_t i = 0; i < shading->size() && i < layer.shading.size(); ++i)
                    (*shading)[i].waterAge = layer.shading[i].waterAge;
                layer.shading = std::move(*shading);
            }
            bakeMs.push_back(ms);
        }
        auto renderer = SceneRenderer::create(baked);
        if (!renderer)
            return renderer.error();
        Frame frame = bench.draw(**renderer, bench.base, prefix + " " + label);
        return std::pair{std::move(frame), spreadOf(bakeMs)};
    };
    auto reference = bakeAndDraw(0.0f, "reference exact");
    if (!reference)
        return reference.error();
    const auto result = [&](const std::pair<Frame, Spread>& run, const std::string& label,
                            double value) {
        SettingResult s = run.first.timing;
        s.label = label;
        s.value = value;
        s.costMs = run.second;
        setImageError(bench, run.first.image, reference->first.image, background, s);
        return s;
    };
    for (const float cell : {2.0f, 1.0f, 0.5f, 0.25f}) {
        char label[32];
        std::snprintf(label, sizeof label, "%g σ", static_cast<double>(cell));
        auto run = bakeAndDraw(cell, label);
        if (!run)
            return run.error();
        knob.settings.push_back(result(*run, label, cell));
    }
    SettingResult ref = result(*reference, "exact", 0.0);
    ref.reference = true;
    knob.settings.push_back(ref);
    finishKnob(knob);
    return knob;
}

// Distance thinning keeps ceil(n·(1 − d/dmax))/n of the blades at distance d (cull.comp): n
// classes approximate the continuous falloff 1 − d/dmax from above. Which blades a class count
// keeps differs with n (index mod n), so images of two counts differ blade by blade and pixel
// ΔE cannot rank them; the error is the density's instead: the mean excess kept share over the
// live blades within dmax, from the blades' distances as the cull pass measures them. Cost is
// the frame.
KnobResult measureClassesKnob(ImageBench& bench, const core::Scene& scene,
                              const std::string& prefix) {
    KnobResult knob;
    knob.name = "distance_classes";
    char description[96];
    std::snprintf(description, sizeof description,
                  "distance thinning classes at the project's thinning distance (%g m)",
                  static_cast<double>(bench.base.cull.maxDistanceM));
    knob.description = description;
    knob.errorMetric = "mean kept share above the continuous 1 − d/dmax over the blades within "
                       "dmax (density error)";
    knob.costMetric = "frame wall ms (median of the timed frames, glFinish included)";
    const glm::vec3 eye = bench.camera.position();
    const float dmax = bench.base.cull.maxDistanceM;
    std::vector<float> falloff;  // 1 − d/dmax of every live blade within dmax
    for (const core::LayerField& layer : scene.layers)
        for (const core::Blade& blade : layer.patched.blades) {
            if (!(blade.h() > 0.0f))
                continue;
            const glm::vec3 up = glm::normalize(blade.up());
            const glm::vec3 toBlade = blade.v0() - eye;
            const float d = glm::length(toBlade - up * glm::dot(toBlade, up));
            if (d < dmax)
                falloff.push_back(1.0f - d / dmax);
        }
    const auto densityError = [&](int n) {
        double sum = 0.0;
        for (const float f : falloff)
            sum += std::ceil(double(n) * f) / n - f;
        return falloff.empty() ? 0.0 : sum / double(falloff.size());
    };
    const auto measure = [&](int n, const std::string& what) {
        RenderOptions options = bench.base;
        options.cull.distanceClasses = n;
        SettingResult s = bench.draw(bench.renderer, options, prefix + " " + what).timing;
        s.label = std::to_string(n);
        s.value = n;
        s.error = densityError(n);
        s.errorMax = 1.0 / n;  // a class's share: the largest excess at any distance
        s.pixels = falloff.size();
        return s;
    };
    for (const int n : {2, 4, 8, 16})
        knob.settings.push_back(measure(n, std::to_string(n)));
    // The reference is the continuous falloff, against which every error above is exact; 64
    // classes stand in for it in the frame (its own small error is listed, not zeroed).
    SettingResult reference = measure(64, "reference 64");
    reference.label = "64 (≈ continuous)";
    reference.reference = true;
    knob.settings.push_back(reference);
    finishKnob(knob);
    return knob;
}

}  // namespace grass::render::tradeoff
