// The side panel's Snow section: the project's snow accumulation settings (SPEC §11,
// core/snow/snow_params.h), each drawn from its row of core::settings::snow(), so the widget's
// range is the loader's. The renderer reads them every frame, so edits apply at once and never
// re-grow the scene.
#include <algorithm>
#include <array>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "app/panels.h"
#include "app/setting_widget.h"
#include "project/settings.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {


void rows(ui::Ui& ui, core::SnowParams& snow,
          std::initializer_list<std::string_view> keys) {
    for (const std::string_view key : keys)
        settingWidget(ui, core::settings::snow(), key, snow);
}

// amount ≤ max amount (the loader refuses more): each bounds the other.
void amountRows(ui::Ui& ui, core::SnowParams& snow) {
    const auto table = core::settings::snow();
    const auto& amountRow = *core::settings::findSetting(table, "amount");
    const auto& maxRow = *core::settings::findSetting(table, "max_amount");
    core::settings::UiHint amount = amountRow.ui;
    amount.min = float(amountRow.rule.min);
    amount.max = snow.maxAmountM;
    settingWidget(ui, amountRow, snow, &amount);
    core::settings::UiHint maxAmount = maxRow.ui;
    maxAmount.min = snow.amountM;
    maxAmount.max = float(maxRow.rule.max);
    settingWidget(ui, maxRow, snow, &maxAmount);
}

// The loader refuses a fall or drift direction of length < 1e-3; a direction is a direction at
// any length, so the row stays within the unit cube and keeps its old value rather than vanish.
void directionRow(ui::Ui& ui, core::SnowParams& snow, std::string_view key,
                  glm::vec3 core::SnowParams::*direction) {
    constexpr float MIN_DIRECTION_LENGTH = 1e-2f;
    const glm::vec3 before = snow.*direction;
    settingWidget(ui, core::settings::snow(), key, snow);
    if (glm::length(snow.*direction) < MIN_DIRECTION_LENGTH)
        snow.*direction = before;
}

// One of the three sizes the loader accepts.
void mapResolutionCombo(ui::Ui& ui, core::SnowParams& snow) {
    const auto& sizes = core::SNOW_MAP_RESOLUTIONS;
    std::array<std::string, sizes.size()> names;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        names[i] = std::to_string(sizes[i]);
    const auto* found = std::find(sizes.begin(), sizes.end(), snow.mapResolution);
    int index = found == sizes.end() ? 1 : int(found - sizes.begin());
    if (ui.comboBox("depth map texels", index, names)
            .onHoverText("Side of the depth map that tests which ground the snow reaches, "
                         "in texels: 512, 1024 or 2048")
            .changed())
        snow.mapResolution = sizes[std::size_t(index)];
}

void snowBody(ui::Ui& ui, core::SnowParams& snow) {
    rows(ui, snow, {"enabled"});
    amountRows(ui, snow);
    directionRow(ui, snow, "fall_direction", &core::SnowParams::fallDirection);
    rows(ui, snow, {"color"});
    // Fractal noise of the snow surface (paper eq. 4) and of the incline (Fi = cos φ + n).
    ui.collapsingHeader("noise", [&](ui::Ui& body) {
        rows(body, snow,
             {"noise_octaves", "noise_amplitude", "noise_frequency", "noise_scale",
              "incline_noise"});
    });
    // The exposure test against the depth map along the fall (Fe).
    ui.collapsingHeader("exposure", [&](ui::Ui& body) {
        mapResolutionCombo(body, snow);
        rows(body, snow, {"samples", "sample_radius", "depth_bias", "boundary_falloff"});
    });
    // Drift with the wind: more snow in the lee of rocks and ridges, less facing the wind.
    ui.collapsingHeader(snow.drift > 0.0f ? "drift (on)##drift" : "drift##drift", [&](ui::Ui& body) {
        rows(body, snow, {"drift", "drift_reach", "drift_follows_wind"});
        if (snow.driftFollowsWind == 0u)
            directionRow(body, snow, "drift_direction", &core::SnowParams::driftDirection);
    });
    // Accumulation and melt over --time, and the snow's load on the blades.
    ui.collapsingHeader("accumulation, melt, load", [&](ui::Ui& body) {
        rows(body, snow, {"accumulation_rate", "melt_rate", "load_gravity"});
    });
}

}  // namespace

void snowSection(ui::Ui& ui, EditorState& s) {
    core::SnowParams& snow = s.transient.draft.project.snow;
    ui.collapsingHeader("Snow", [&](ui::Ui& section) { snowBody(section, snow); });
}

}  // namespace grass::editor
