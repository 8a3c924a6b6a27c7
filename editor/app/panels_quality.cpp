// The Render section's quality rows (issue 10): a preset menu (draft, balanced, high, reference,
// chosen from the measured fronts; "custom" when the settings match none) and, per measured
// knob, the cost and error `grass tradeoff` measured at the current setting.
#include <array>
#include <cstdio>

#include "app/panels.h"
#include "quality/quality_presets.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

constexpr std::array<const char*, 5> PRESET_ITEMS{"custom", "draft", "balanced", "high",
                                                  "reference"};

std::string knobTitle(const std::string& name) {
    // Short: a row must fit the side panel.
    if (name == "physics_step")
        return "substep";
    if (name == "geometry_detail")
        return "segments";
    if (name == "lod_distance")
        return "LOD";
    if (name == "cull_distance")
        return "thinning";
    if (name == "snow_map")
        return "snow";
    if (name == "billboard_fade")
        return "fade";
    if (name == "ao_kernel")
        return "AO cells";
    return name;
}

std::string estimateText(const core::KnobEstimate& e) {
    char text[160];
    const bool tips = e.knob->name == "physics_step";
    std::snprintf(text, sizeof text, "%s %s%s: %.0f ms, %s %.2g", knobTitle(e.knob->name).c_str(),
                  e.exact ? "" : "~", e.setting->label.c_str(), e.setting->costMs,
                  tips ? "tip h" : "ΔE", e.setting->error);
    return text;
}

}  // namespace

void qualityRows(ui::Ui& ui, EditorState& s) {
    core::Project& project = s.transient.draft.project;
    const std::optional<core::QualityPreset> current = core::matchingPreset(project);
    int selected = current ? static_cast<int>(*current) + 1 : 0;
    if (const ui::Response r =
            ui.comboBox("quality", selected, PRESET_ITEMS)
                .onHoverText("Set the measured quality knobs to a preset: draft, balanced, high "
                             "or reference; custom means they match none");
        r.changed() && selected > 0) {
        const float aoCellsBefore = project.lighting.aoCellSigmas;
        core::applyQuality(core::qualitySettings(core::QualityPreset(selected - 1)), project);
        // The blades' ambient occlusion is baked with the AO kernel's cells when they grow:
        // re-grow them. The physics' substeps are followed live (followPhysicsSteps): draft,
        // balanced and high share one AO kernel, and switching between them grew the whole
        // field again for the substeps alone.
        if (project.lighting.aoCellSigmas != aoCellsBefore)
            s.transient.draft.regrow = true;
    }
    // Only the knobs this scene uses: a blades-only field pays nothing for billboards.
    std::vector<core::KnobEstimate> estimates;
    for (const core::KnobEstimate& e : core::estimateQuality(project)) {
        if (e.knob->name == "billboard_fade" &&
            project.render.technique != core::GrassTechnique::Hybrid)
            continue;
        if (e.knob->name == "snow_map" && project.snow.enabled == 0u)
            continue;
        estimates.push_back(e);
    }
    if (estimates.empty())
        return;
    // The device string's renderer part: "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& device = estimates.front().knob->device;
    ui.label("measured cost, error here:");
    ui.indent([&](ui::Ui& body) {
        for (const core::KnobEstimate& e : estimates)
            body.label(estimateText(e));
        body.label("~ nearest measured value");
        body.label("on " + device.substr(0, device.find(" |")));
    });
}

}  // namespace grass::editor
