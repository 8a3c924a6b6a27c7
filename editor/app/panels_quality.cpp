// The Render section's quality rows (issue 10): a preset menu (draft, balanced, high, reference,
// chosen from the measured fronts; "custom" when the settings match none) and, per measured
// knob, the cost and error `grass tradeoff` measured at the current setting.
#include <array>
#include <cstdio>

#include "panels.h"
#include "quality/quality_presets.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

constexpr std::array<const char*, 5> PRESET_ITEMS{"custom", "draft", "balanced", "high",
                                                  "reference"};

std::string knobTitle(const std::string& name) {
    if (name == "physics_step")
        return "physics substep";
    if (name == "geometry_detail")
        return "blade segments";
    if (name == "lod_distance")
        return "LOD distance";
    if (name == "cull_distance")
        return "thinning";
    if (name == "snow_map")
        return "snow map";
    if (name == "billboard_fade")
        return "billboard fade";
    return name;
}

std::string estimateText(const core::KnobEstimate& e) {
    char text[160];
    std::snprintf(text, sizeof text, "%s %s%s: %.0f ms, %.3g %s", knobTitle(e.knob->name).c_str(),
                  e.exact ? "" : "~", e.setting->label.c_str(), e.setting->costMs,
                  e.setting->error, std::string(core::knobErrorUnit(e.knob->name)).c_str());
    return text;
}

}  // namespace

void syncQualityOptions(const core::Project& project, render::RenderOptions& options) {
    // The fields copied below do not depend on the rasterizer.
    const render::RenderOptions fromProject = render::renderOptionsFor(project, false);
    options.tessLevel = fromProject.tessLevel;
    options.stripSegments = fromProject.stripSegments;
    options.cull.lodDistanceM = fromProject.cull.lodDistanceM;
    options.cull.distance = fromProject.cull.distance;
    options.cull.maxDistanceM = fromProject.cull.maxDistanceM;
    options.billboards = fromProject.billboards;
    options.snow = fromProject.snow;
}

void qualityRows(ui::Ui& ui, EditorState& s) {
    core::Project& project = s.loaded.project;
    const std::optional<core::QualityPreset> current = core::matchingPreset(project);
    int selected = current ? static_cast<int>(*current) + 1 : 0;
    if (const ui::Response r = ui.comboBox("quality", selected, PRESET_ITEMS);
        r.changed() && selected > 0) {
        const core::PhysicsParams physicsBefore = project.physics;
        core::applyQuality(core::qualitySettings(core::QualityPreset(selected - 1)), project);
        syncQualityOptions(project, s.options);
        s.dirty = true;
        // The live simulation was built with the old substeps: re-grow it.
        if (project.physics != physicsBefore)
            s.rebuildPending = true;
    }
    const std::vector<core::KnobEstimate> estimates = core::estimateQuality(project);
    if (estimates.empty())
        return;
    ui.label("measured cost and error at these settings:");
    ui.indent([&](ui::Ui& body) {
        for (const core::KnobEstimate& e : estimates)
            body.label(estimateText(e));
        body.label("(" + estimates.front().knob->project + ", " + estimates.front().knob->device +
                   "; ~ nearest measured; docs/presets.md)");
    });
}

}  // namespace grass::editor
