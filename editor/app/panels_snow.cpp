// The side panel's Snow section: the project's snow accumulation settings (SPEC §11,
// core/snow/snow_params.h). The renderer reads them every frame, so edits apply at once and
// never re-grow the scene; each widget keeps its value inside what core/project/snow_json.cpp
// accepts, so a project saved after any edit loads again.
#include <algorithm>
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "app/panels.h"
#include "ui/color_edit.h"
#include "ui/text_edit.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

// The ranges of snow_json.cpp, in the units the panel shows. Exclusive lower bounds (A > 0,
// B > 1, scale > 0) become the smallest value a widget can reach.
constexpr float MAX_DEPTH_M = 10.0f;
constexpr float MIN_AMPLITUDE = 0.01f;
constexpr float MIN_FREQUENCY = 1.01f;
constexpr float MAX_FREQUENCY = 16.0f;
constexpr float MIN_NOISE_SCALE_M = 0.01f;
constexpr float MAX_NOISE_SCALE_M = 1000.0f;
constexpr float MAX_SAMPLE_RADIUS = 64.0f;
constexpr float MAX_FALLOFF_M = 100.0f;
constexpr float MAX_RATE = 1.0f;
constexpr float MAX_LOAD_GRAVITY = 1000.0f;
// The loader refuses a fall direction shorter than 1e-3; a direction is a direction at any
// length, so the row stays within the unit cube and keeps its old value rather than vanish.
constexpr float MIN_DIRECTION_LENGTH = 1e-2f;
constexpr std::array<int, 3> MAP_RESOLUTIONS{512, 1024, 2048};
constexpr std::array<const char*, 3> MAP_RESOLUTION_NAMES{"512", "1024", "2048"};

// The renderer reads the snow every frame: only the project needs saving.
void live(EditorState& s, const ui::Response& r) {
    if (r.changed())
        s.dirty = true;
}

void fallDirectionRow(ui::Ui& ui, EditorState& s, glm::vec3& direction) {
    ui.withId("fall direction", [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            for (int c = 0; c < 3; ++c) {
                row.pushId(std::uint64_t(c));
                const glm::vec3 before = direction;
                const ui::Response r = row.dragValue(c == 2 ? "fall direction" : "", direction[c],
                                                     0.01f, -1.0f, 1.0f, 2);
                if (glm::length(direction) < MIN_DIRECTION_LENGTH)
                    direction = before;
                live(s, r);
                row.popId();
            }
        });
    });
}

void mapResolutionCombo(ui::Ui& ui, EditorState& s, core::SnowParams& snow) {
    const auto* found =
        std::find(MAP_RESOLUTIONS.begin(), MAP_RESOLUTIONS.end(), snow.mapResolution);
    int index = found == MAP_RESOLUTIONS.end() ? 1 : int(found - MAP_RESOLUTIONS.begin());
    if (const ui::Response r = ui.comboBox("depth map texels", index, MAP_RESOLUTION_NAMES);
        r.changed()) {
        snow.mapResolution = MAP_RESOLUTIONS[std::size_t(index)];
        live(s, r);
    }
}

// Fractal noise of the snow surface (paper eq. 4) and of the incline (Fi = cos φ + n).
void noiseRows(ui::Ui& ui, EditorState& s, core::SnowParams& snow) {
    live(s, ui.slider("octaves", snow.noiseOctaves, 1, core::SNOW_MAX_OCTAVES));
    live(s, ui::sliderWithEntry(ui, "noise A", snow.noiseAmplitude, MIN_AMPLITUDE, 1.0f,
                                {.decimals = 2}));
    live(s, ui::sliderWithEntry(ui, "noise B", snow.noiseFrequency, MIN_FREQUENCY, MAX_FREQUENCY,
                                {.decimals = 2}));
    live(s, ui::sliderWithEntry(ui, "scale m", snow.noiseScaleM, MIN_NOISE_SCALE_M,
                                MAX_NOISE_SCALE_M, {.logarithmic = true, .decimals = 2}));
    live(s, ui.slider("incline", snow.inclineNoise, 0.0f, 1.0f, {.decimals = 2}));
}

// The exposure test against the depth map along the fall (Fe).
void exposureRows(ui::Ui& ui, EditorState& s, core::SnowParams& snow) {
    mapResolutionCombo(ui, s, snow);
    live(s, ui.slider("samples", snow.samples, 1, core::SNOW_MAX_SAMPLES));
    live(s, ui::dragValueWithEntry(ui, "sample radius texels", snow.sampleRadiusTexels, 0.05f, 0.0f,
                                   MAX_SAMPLE_RADIUS, 2));
    live(s,
         ui::dragValueWithEntry(ui, "depth bias m", snow.depthBiasM, 0.001f, 0.0f, MAX_DEPTH_M, 3));
    live(s, ui::dragValueWithEntry(ui, "boundary falloff m", snow.boundaryFalloffM, 0.01f, 0.0f,
                                   MAX_FALLOFF_M, 2));
}

// Accumulation and melt over --time, and the snow's load on the blades.
void timeRows(ui::Ui& ui, EditorState& s, core::SnowParams& snow) {
    live(s, ui::dragValueWithEntry(ui, "accumulation m/s", snow.accumulationRate, 0.0005f, 0.0f,
                                   MAX_RATE, 4));
    live(s, ui::dragValueWithEntry(ui, "melt m/s", snow.meltRate, 0.0005f, 0.0f, MAX_RATE, 4));
    live(s, ui::dragValueWithEntry(ui, "load gravity (m/s²)/m", snow.loadGravity, 0.5f, 0.0f,
                                   MAX_LOAD_GRAVITY, 1));
}

void snowBody(ui::Ui& ui, EditorState& s, core::SnowParams& snow) {
    bool enabled = snow.enabled != 0u;
    if (const ui::Response r = ui.checkbox(enabled, "snow"); r.changed()) {
        snow.enabled = enabled ? 1u : 0u;
        live(s, r);
    }
    // amount ≤ max amount (the loader refuses more): each bounds the other.
    live(s,
         ui::sliderWithEntry(ui, "amount m", snow.amountM, 0.0f, snow.maxAmountM, {.decimals = 3}));
    live(s, ui::dragValueWithEntry(ui, "max amount m", snow.maxAmountM, 0.01f, snow.amountM,
                                   MAX_DEPTH_M, 2));
    fallDirectionRow(ui, s, snow.fallDirection);
    live(s, ui::colorEdit(ui, "snow colour", snow.snowColor, true));
    ui.collapsingHeader("noise", [&](ui::Ui& body) { noiseRows(body, s, snow); });
    ui.collapsingHeader("exposure", [&](ui::Ui& body) { exposureRows(body, s, snow); });
    ui.collapsingHeader("accumulation, melt, load", [&](ui::Ui& body) { timeRows(body, s, snow); });
}

}  // namespace

void snowSection(ui::Ui& ui, EditorState& s) {
    core::SnowParams& snow = s.loaded.project.snow;
    ui.collapsingHeader("Snow", [&](ui::Ui& section) { snowBody(section, s, snow); });
}

}  // namespace grass::editor
