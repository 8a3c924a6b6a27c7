#include "quality_presets.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "measured_tradeoffs.h"
#include "physics/physics.h"
#include "util/json_text.h"

namespace grass::core {

namespace {

using Json = nlohmann::json;

// ΔE76 ≈ 2.3 is the just-noticeable difference of two flat colours (Sharma, Digital Color
// Imaging Handbook); the image bounds are 1, 1/2 and 1/4 of it.
constexpr double JUST_NOTICEABLE_DELTA_E = 2.3;
constexpr std::array<double, 3> IMAGE_BOUNDS{JUST_NOTICEABLE_DELTA_E,
                                             JUST_NOTICEABLE_DELTA_E / 2.0,
                                             JUST_NOTICEABLE_DELTA_E / 4.0};
constexpr std::array<double, 3> TIP_BOUNDS{0.02, 0.01, 0.0025};
// Substep length of the physics reference's own cap (project files allow at most 64).
constexpr std::uint32_t MAX_SUBSTEPS = 64;
// Billboards end their cross-fade at 1.6 × its start in every measured setting.
constexpr float FADE_END_PER_START = 1.6f;

Result<double> number(const Json& node, const char* key, const std::string& where) {
    const auto it = node.find(key);
    if (it == node.end() || !it->is_number())
        return makeError(where, std::string("\"") + key + "\" must be a number");
    return it->get<double>();
}

Result<MeasuredSetting> parseSetting(const Json& node, const std::string& where) {
    if (!node.is_object())
        return makeError(where, "must be an object");
    MeasuredSetting s;
    if (const auto label = node.find("label"); label != node.end() && label->is_string())
        s.label = label->get<std::string>();
    auto value = number(node, "value", where);
    if (!value)
        return value.error();
    s.value = *value;
    auto error = number(node, "error", where);
    if (!error)
        return error.error();
    s.error = *error;
    const auto cost = node.find("cost_ms");
    if (cost == node.end() || !cost->is_object())
        return makeError(where, "\"cost_ms\" must be an object with a \"median\"");
    auto median = number(*cost, "median", where + "/cost_ms");
    if (!median)
        return median.error();
    s.costMs = *median;
    const std::string role = node.value("role", std::string("setting"));
    s.reference = role == "reference";
    s.check = role == "check";
    s.pareto = node.value("pareto", false);
    return s;
}

// Log-ratio distance between two knob values; "off" (0) is only near itself.
double valueDistance(double a, double b) {
    if (a == b)
        return 0.0;
    if (!(a > 0.0) || !(b > 0.0))
        return INFINITY;
    return std::abs(std::log(a / b));
}

const MeasuredKnob* findKnob(const std::vector<MeasuredKnob>& knobs, const std::string& name) {
    for (const MeasuredKnob& knob : knobs)
        if (knob.name == name)
            return &knob;
    return nullptr;
}

}  // namespace

std::string_view qualityPresetName(QualityPreset preset) {
    switch (preset) {
    case QualityPreset::Draft: return "draft";
    case QualityPreset::Balanced: return "balanced";
    case QualityPreset::High: return "high";
    case QualityPreset::Reference: return "reference";
    }
    return "?";
}

Result<QualityPreset> parseQualityPreset(std::string_view name) {
    for (const QualityPreset preset : QUALITY_PRESETS)
        if (qualityPresetName(preset) == name)
            return preset;
    return makeError("--preset", "unknown preset \"" + std::string(name) +
                                     "\" (valid: draft, balanced, high, reference)");
}

Result<std::vector<MeasuredKnob>> parseTradeoffJson(std::string_view text,
                                                    const std::string& sourceName) {
    const auto parsed = parseJsonText(text, sourceName);
    if (!parsed)
        return makeError(sourceName,
                         "not a JSON object (a grass tradeoff.json): " + parsed.error().message);
    const Json& root = *parsed;
    if (!root.is_object())
        return makeError(sourceName, "not a JSON object (a grass tradeoff.json)");
    const auto knobs = root.find("knobs");
    if (knobs == root.end() || !knobs->is_array())
        return makeError(sourceName, "\"knobs\" must be an array (a grass tradeoff.json)");
    std::vector<MeasuredKnob> out;
    for (std::size_t k = 0; k < knobs->size(); ++k) {
        const Json& node = (*knobs)[k];
        const std::string where = sourceName + ": /knobs/" + std::to_string(k);
        if (!node.is_object() || !node.contains("name") || !node["name"].is_string())
            return makeError(where, "must be an object with a \"name\"");
        if (node.contains("skipped"))
            continue;
        MeasuredKnob knob;
        knob.name = node["name"].get<std::string>();
        knob.project = root.value("project", std::string());
        knob.device = root.value("device", std::string());
        const auto settings = node.find("settings");
        if (settings == node.end() || !settings->is_array())
            return makeError(where, "\"settings\" must be an array");
        for (std::size_t i = 0; i < settings->size(); ++i) {
            auto setting = parseSetting((*settings)[i], where + "/settings/" + std::to_string(i));
            if (!setting)
                return setting.error();
            knob.settings.push_back(std::move(*setting));
        }
        if (std::none_of(knob.settings.begin(), knob.settings.end(),
                         [](const MeasuredSetting& s) { return s.reference; }))
            return makeError(where, "has no setting with \"role\": \"reference\"");
        out.push_back(std::move(knob));
    }
    return out;
}

const std::vector<MeasuredKnob>& builtInMeasurements() {
    static const std::vector<MeasuredKnob> knobs = [] {
        std::vector<MeasuredKnob> all;
        for (const MeasuredDocument& document : measuredTradeoffDocuments()) {
            // The documents are part of the build; tests/core/quality/quality_presets_test.cpp parses
            // each one, so a malformed file fails there rather than vanishing here.
            auto parsed = parseTradeoffJson(document.text, std::string(document.name));
            if (!parsed)
                continue;
            for (MeasuredKnob& knob : *parsed)
                if (!findKnob(all, knob.name))
                    all.push_back(std::move(knob));
        }
        return all;
    }();
    return knobs;
}

std::string_view knobErrorUnit(const std::string& knobName) {
    return knobName == "physics_step" ? "h" : "ΔE76";
}

double presetErrorBound(const std::string& knobName, QualityPreset preset) {
    if (preset == QualityPreset::Reference)
        return 0.0;
    const auto& bounds = knobName == "physics_step" ? TIP_BOUNDS : IMAGE_BOUNDS;
    return bounds[static_cast<std::size_t>(preset)];
}

std::size_t choosePresetSetting(const MeasuredKnob& knob, QualityPreset preset) {
    std::size_t reference = 0;
    for (std::size_t i = 0; i < knob.settings.size(); ++i)
        if (knob.settings[i].reference)
            reference = i;
    if (preset == QualityPreset::Reference)
        return reference;
    const double bound = presetErrorBound(knob.name, preset);
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < knob.settings.size(); ++i) {
        const MeasuredSetting& s = knob.settings[i];
        if (s.check || !(s.error <= bound))
            continue;
        if (!best)
            best = i;
        else {
            const MeasuredSetting& b = knob.settings[*best];
            if (s.costMs < b.costMs || (s.costMs == b.costMs && s.error < b.error))
                best = i;
        }
    }
    return best.value_or(reference);
}

QualitySettings qualitySettingsFor(const std::vector<MeasuredKnob>& knobs, QualityPreset preset) {
    QualitySettings out;
    const auto chosen = [&](const char* name) -> std::optional<double> {
        const MeasuredKnob* knob = findKnob(knobs, name);
        if (!knob || knob->settings.empty())
            return std::nullopt;
        return knob->settings[choosePresetSetting(*knob, preset)].value;
    };
    if (const auto v = chosen("physics_step"))
        out.physicsStepS = static_cast<float>(*v);
    if (const auto v = chosen("geometry_detail"))
        out.geometryDetail = static_cast<int>(std::lround(*v));
    if (const auto v = chosen("lod_distance"))
        out.lodDistanceM = static_cast<float>(*v);
    if (const auto v = chosen("cull_distance"))
        out.thinningDistanceM = static_cast<float>(*v);
    if (const auto v = chosen("snow_map")) {
        // tradeoff.json encodes a snow setting as resolution × 100 + samples.
        const auto code = static_cast<long>(std::lround(*v));
        out.snowMapResolution = static_cast<int>(code / 100);
        out.snowSamples = static_cast<int>(code % 100);
    }
    if (const auto v = chosen("billboard_fade"))
        out.billboardFadeStartM = static_cast<float>(*v);
    if (const auto v = chosen("ao_kernel"))
        out.aoCellSigmas = static_cast<float>(*v);
    return out;
}

QualitySettings qualitySettings(QualityPreset preset) {
    return qualitySettingsFor(builtInMeasurements(), preset);
}

void applyQuality(const QualitySettings& settings, Project& project) {
    if (settings.physicsStepS && *settings.physicsStepS > 0.0f) {
        PhysicsParams& physics = project.physics;
        physics.maxSubstepS = *settings.physicsStepS;
        const double wanted = std::ceil(double(physics.dtS) / double(physics.maxSubstepS) - 1e-6);
        const auto needed = static_cast<std::uint32_t>(std::clamp(wanted, 1.0, 64.0));
        physics.maxSubsteps = std::min(std::max(physics.maxSubsteps, needed), MAX_SUBSTEPS);
    }
    if (settings.geometryDetail) {
        project.render.stripSegments = std::clamp(*settings.geometryDetail, 1, 32);
        project.render.tessLevel = std::clamp(*settings.geometryDetail, 1, 64);
    }
    if (settings.lodDistanceM)
        project.render.lodDistanceM = *settings.lodDistanceM;
    if (settings.thinningDistanceM)
        project.render.thinningDistanceM = *settings.thinningDistanceM;
    if (settings.snowMapResolution)
        project.snow.mapResolution = static_cast<std::uint32_t>(*settings.snowMapResolution);
    if (settings.snowSamples)
        project.snow.samples = *settings.snowSamples;
    if (settings.billboardFadeStartM)
        project.billboards.crossFadeM = {*settings.billboardFadeStartM,
                                         FADE_END_PER_START * *settings.billboardFadeStartM};
    if (settings.aoCellSigmas)
        project.lighting.aoCellSigmas = *settings.aoCellSigmas;
}

std::optional<double> projectKnobValue(const Project& project, const std::string& knobName) {
    if (knobName == "physics_step") {
        const std::uint32_t substeps = substepCount(project.physics);
        if (substeps == 0)
            return std::nullopt;
        return double(project.physics.dtS) / substeps;
    }
    if (knobName == "geometry_detail") {
        const bool tess = project.render.geometry == GeometryPath::Tessellation;
        return tess ? project.render.tessLevel : project.render.stripSegments;
    }
    if (knobName == "lod_distance")
        return project.render.lodDistanceM;
    if (knobName == "cull_distance")
        return project.render.thinningDistanceM;
    if (knobName == "snow_map")
        return double(project.snow.mapResolution) * 100.0 + project.snow.samples;
    if (knobName == "billboard_fade")
        return project.billboards.crossFadeM.x;
    if (knobName == "ao_kernel")
        return project.lighting.aoCellSigmas;
    return std::nullopt;
}

std::optional<QualityPreset> matchingPreset(const Project& project) {
    const std::vector<MeasuredKnob>& knobs = builtInMeasurements();
    for (const QualityPreset preset : QUALITY_PRESETS) {
        Project applied = project;
        applyQuality(qualitySettingsFor(knobs, preset), applied);
        if (applied == project)
            return preset;
    }
    return std::nullopt;
}

std::vector<KnobEstimate> estimateQuality(const Project& project) {
    std::vector<KnobEstimate> out;
    for (const MeasuredKnob& knob : builtInMeasurements()) {
        const auto value = projectKnobValue(project, knob.name);
        if (!value)
            continue;
        KnobEstimate estimate;
        estimate.knob = &knob;
        estimate.projectValue = *value;
        double nearest = INFINITY;
        for (const MeasuredSetting& s : knob.settings) {
            const double d = s.check ? INFINITY : valueDistance(s.value, *value);
            if (d < nearest) {
                nearest = d;
                estimate.setting = &s;
            }
        }
        if (!estimate.setting)
            continue;
        // A relative tolerance: the project stores its values as floats (a substep dtS / n).
        estimate.exact = nearest < 1e-4;
        out.push_back(estimate);
    }
    return out;
}

}  // namespace grass::core
