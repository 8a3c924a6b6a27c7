#include "preset_table.h"

#include <algorithm>
#include <cstdio>

namespace grass::core {

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string cell(const MeasuredKnob& knob, QualityPreset preset) {
    const MeasuredSetting& s = knob.settings[choosePresetSetting(knob, preset)];
    return "**" + s.label + "**: " + format("%.4g", s.costMs) + " ms, " +
           format("%.3g", s.error) + " " + std::string(knobErrorUnit(knob.name));
}

}  // namespace

std::string presetTableMarkdown(const std::vector<MeasuredKnob>& knobs) {
    std::string out;
    out += "| knob | draft | balanced | high | reference | measured on |\n";
    out += "|---|---|---|---|---|---|\n";
    for (const MeasuredKnob& knob : knobs) {
        out += "| `" + knob.name + "` ";
        for (const QualityPreset preset : QUALITY_PRESETS)
            out += "| " + cell(knob, preset) + " ";
        out += "| " + knob.project + " |\n";
    }
    out += "\nError bounds (a preset takes the cheapest measured setting within its bound):\n\n";
    out += "| error | draft | balanced | high |\n|---|---|---|---|\n";
    for (const char* name : {"geometry_detail", "physics_step"}) {
        out += std::string("| ") +
               (std::string(name) == "physics_step" ? "tip error (physics_step)"
                                                    : "mean ΔE76 (image knobs)");
        for (const QualityPreset preset :
             {QualityPreset::Draft, QualityPreset::Balanced, QualityPreset::High})
            out += " | " + format("%.4g", presetErrorBound(name, preset)) + " " +
                   std::string(knobErrorUnit(name));
        out += " |\n";
    }
    std::vector<std::string> devices;
    for (const MeasuredKnob& knob : knobs)
        if (std::find(devices.begin(), devices.end(), knob.device) == devices.end())
            devices.push_back(knob.device);
    out += "\nMeasured on: ";
    for (std::size_t i = 0; i < devices.size(); ++i)
        out += (i > 0 ? "; " : "") + devices[i];
    out += "\n";
    return out;
}

}  // namespace grass::core
