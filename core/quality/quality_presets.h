// Quality presets (issue 10, SPEC §13): draft, balanced, high and reference, chosen from the
// cost/error fronts that `grass tradeoff` measured, never by hand. The measurements are the
// tradeoff.json files under core/quality/measured/, built into the binary; for every knob a
// preset takes the cheapest measured setting whose error is within the preset's bound (so it
// lies on the knob's Pareto front), and `reference` takes the knob's reference setting.
// docs/presets.md shows the table (`grass presets` prints it).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "project/project.h"
#include "util/result.h"

namespace grass::core {

enum class QualityPreset { Draft, Balanced, High, Reference };
inline constexpr std::array<QualityPreset, 4> QUALITY_PRESETS{
    QualityPreset::Draft, QualityPreset::Balanced, QualityPreset::High, QualityPreset::Reference};

std::string_view qualityPresetName(QualityPreset preset);  // "draft", "balanced", ...
// Errors name the valid presets.
Result<QualityPreset> parseQualityPreset(std::string_view name);

// One setting of a knob as `grass tradeoff` measured it (tradeoff.json's "settings").
struct MeasuredSetting {
    std::string label;
    double value = 0.0;   // the knob's number; 0 is "off" for the distance knobs
    double costMs = 0.0;  // median
    double error = 0.0;
    bool reference = false;
    bool check = false;  // the reference's own convergence check: never a choice
    bool pareto = false;
};

struct MeasuredKnob {
    std::string name;  // physics_step, geometry_detail, lod_distance, cull_distance, ...
    std::string project;
    std::string device;
    std::vector<MeasuredSetting> settings;
};

// The measured knobs of a tradeoff.json document (knobs it skipped are left out). Errors name
// `sourceName` and what is missing or malformed.
Result<std::vector<MeasuredKnob>> parseTradeoffJson(std::string_view text,
                                                    const std::string& sourceName);
// core/quality/measured/*.json in name order, the first measurement of each knob.
const std::vector<MeasuredKnob>& builtInMeasurements();

// The largest error a preset accepts on a knob, in the knob's error unit: mean CIELAB ΔE76 over
// the feature's pixels for the image knobs (draft one just-noticeable difference, 2.3; balanced
// half of it; high a quarter), mean tip error in blade heights for the physics step (0.02,
// 0.01, 0.0025: 2, 1 and a quarter pixel on a blade 100 px tall). Reference: 0.
double presetErrorBound(const std::string& knobName, QualityPreset preset);
std::string_view knobErrorUnit(const std::string& knobName);  // "ΔE76" or "h"

// Index into knob.settings of the preset's choice: the cheapest (median cost; ties: the
// smaller error) setting, checks excluded, whose error is within the bound; the reference
// when none is, or for QualityPreset::Reference.
std::size_t choosePresetSetting(const MeasuredKnob& knob, QualityPreset preset);

// What a preset sets; an unset field's knob was not measured and the project keeps its own.
struct QualitySettings {
    std::optional<float> physicsStepS;       // the longest substep
    std::optional<int> geometryDetail;       // strip segments, and the tessellation level
    std::optional<float> lodDistanceM;       // 0: off
    std::optional<float> thinningDistanceM;  // 0: off
    std::optional<int> snowMapResolution;
    std::optional<int> snowSamples;
    std::optional<float> billboardFadeStartM;  // end = 1.6 × start, as measured
    std::optional<float> aoCellSigmas;         // the shading bake's cells; 0: exact
};

QualitySettings qualitySettingsFor(const std::vector<MeasuredKnob>& knobs, QualityPreset preset);
QualitySettings qualitySettings(QualityPreset preset);  // from builtInMeasurements()

// Writes the settings into the project: physics substeps, strip segments and tessellation
// level, LOD and thinning distances, snow map and samples, billboard cross-fade, AO bake cells. A substep
// longer than the project's step makes one substep per step; the substep cap grows to fit.
void applyQuality(const QualitySettings& settings, Project& project);

// The project's value of a knob in the unit tradeoff.json uses (the substep actually taken,
// segments of the project's geometry path, 0 for off, resolution × 100 + samples for snow).
std::optional<double> projectKnobValue(const Project& project, const std::string& knobName);
// The preset whose every built-in knob the project matches, if any ("custom" otherwise).
std::optional<QualityPreset> matchingPreset(const Project& project);

// For the editor's readout: the measured setting at (or nearest to, in ratio) the project's
// value of each built-in knob.
struct KnobEstimate {
    const MeasuredKnob* knob = nullptr;
    const MeasuredSetting* setting = nullptr;
    double projectValue = 0.0;
    bool exact = false;  // the project's value was measured; otherwise the nearest one
};
std::vector<KnobEstimate> estimateQuality(const Project& project);

}  // namespace grass::core
