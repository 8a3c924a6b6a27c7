#include "tools/tradeoff_report.h"

#include <algorithm>
#include <cstdio>

#include "quality/quality_presets.h"
#include "util/json_text.h"
#include "util/printable_text.h"

namespace grass::render {

namespace {

nlohmann::ordered_json settingJson(const SettingResult& s, const std::string& presets) {
    nlohmann::ordered_json out;
    out["label"] = s.label;
    out["value"] = s.value;
    out["role"] = s.reference ? "reference" : s.check ? "check" : "setting";
    out["cost_ms"] = {{"median", s.costMs.median}, {"min", s.costMs.min}, {"max", s.costMs.max}};
    out["gpu_timer_ms"] = {{"opaque", s.meshMs}, {"cull", s.cullMs},
                           {"grass", s.grassMs}, {"billboards", s.billboardMs},
                           {"snow", s.snowMs},   {"physics", s.physicsGpuMs}};
    out["blades_drawn"] = s.bladesDrawn;
    out["error"] = s.error;
    out["error_max"] = s.errorMax;
    out["pixels"] = s.pixels;
    out["pareto"] = s.pareto;
    out["presets"] = presets;
    return out;
}

using Json = nlohmann::json;

// The figures of the whole run; the knobs are read apart.
TradeoffReport reportFromJson(const Json& root) {
    TradeoffReport report;
    report.project = root.value("project", std::string());
    report.device = root.value("device", std::string());
    report.geometry = root.value("geometry", std::string());
    report.width = root.value("width", 0);
    report.height = root.value("height", 0);
    report.msaaSamples = root.value("msaa", 0);
    report.frames = root.value("frames", 0);
    report.sceneTimeS = root.value("scene_time_s", 0.0f);
    report.physicsSeconds = root.value("physics_seconds", 0.0);
    report.blades = root.value("blades", std::size_t(0));
    report.wallS = root.value("wall_s", 0.0);
    return report;
}

SettingResult settingFromJson(const Json& s) {
    SettingResult r;
    r.label = s.at("label").get<std::string>();
    r.value = s.at("value").get<double>();
    const std::string role = s.value("role", std::string("setting"));
    r.reference = role == "reference";
    r.check = role == "check";
    const Json& cost = s.at("cost_ms");
    r.costMs = {cost.at("median").get<double>(), cost.at("min").get<double>(),
                cost.at("max").get<double>()};
    const Json timers = s.value("gpu_timer_ms", Json::object());
    r.meshMs = timers.value("opaque", 0.0);
    r.cullMs = timers.value("cull", 0.0);
    r.grassMs = timers.value("grass", 0.0);
    r.billboardMs = timers.value("billboards", 0.0);
    r.snowMs = timers.value("snow", 0.0);
    r.physicsGpuMs = timers.value("physics", 0.0);
    r.bladesDrawn = s.value("blades_drawn", std::size_t(0));
    r.error = s.at("error").get<double>();
    r.errorMax = s.value("error_max", 0.0);
    r.pixels = s.value("pixels", std::size_t(0));
    r.pareto = s.value("pareto", false);
    return r;
}

// The knob at /knobs/<index>; an error for a name we never write.
Result<KnobResult> knobFromJson(const Json& k, std::size_t index, const std::string& sourceName) {
    KnobResult knob;
    knob.name = k.at("name").get<std::string>();
    // Knob names become file names (<knob>.gp, .dat, .png): only the names we write.
    const std::vector<std::string> known = tradeoffKnobNames();
    if (std::find(known.begin(), known.end(), knob.name) == known.end())
        return makeError(
            sourceName + ": /knobs/" + std::to_string(index) + "/name",
            "unknown knob " +
                nlohmann::json(knob.name).dump(-1, ' ', false, Json::error_handler_t::replace) +
                " (a grass tradeoff.json names only " + tradeoffKnobList() + ")");
    knob.skipped = k.value("skipped", std::string());
    knob.description = k.value("description", std::string());
    knob.costMetric = k.value("cost_metric", std::string());
    knob.errorMetric = k.value("error_metric", std::string());
    if (const auto check = k.find("reference_check"); check != k.end()) {
        knob.checkLabel = check->at("against").get<std::string>();
        knob.referenceCheckError = check->at("error").get<double>();
        knob.referenceConverged = check->at("converged").get<bool>();
        knob.convergedBelow = check->value("converged_below", 0.0);
        knob.referenceResolvesSweep = check->value("resolves_every_setting", true);
    }
    for (const Json& s : k.value("settings", Json::array()))
        knob.settings.push_back(settingFromJson(s));
    return knob;
}

// Printed on the terminal and in tradeoff.md: shown, never obeyed.
void makePrintable(TradeoffReport& report) {
    for (std::string* field : {&report.project, &report.device, &report.geometry})
        *field = printableText(*field);
    for (KnobResult& knob : report.knobs) {
        for (std::string* field : {&knob.skipped, &knob.description, &knob.costMetric,
                                   &knob.errorMetric, &knob.checkLabel})
            *field = printableText(*field);
        for (SettingResult& setting : knob.settings)
            setting.label = printableText(setting.label);
    }
}

}  // namespace

std::vector<std::string> presetLabels(const KnobResult& knob) {
    core::MeasuredKnob measured;
    measured.name = knob.name;
    for (const SettingResult& s : knob.settings)
        measured.settings.push_back(
            {s.label, s.value, s.costMs.median, s.error, s.reference, s.check, s.pareto});
    std::vector<std::string> labels(knob.settings.size());
    if (knob.settings.empty())
        return labels;
    for (const core::QualityPreset preset : core::QUALITY_PRESETS) {
        std::string& label = labels[core::choosePresetSetting(measured, preset)];
        label += (label.empty() ? "" : ", ") + std::string(core::qualityPresetName(preset));
    }
    return labels;
}

nlohmann::ordered_json tradeoffJson(const TradeoffReport& report) {
    nlohmann::ordered_json out;
    out["project"] = report.project;
    out["device"] = report.device;
    out["geometry"] = report.geometry;
    out["width"] = report.width;
    out["height"] = report.height;
    out["msaa"] = report.msaaSamples;
    out["frames"] = report.frames;
    out["scene_time_s"] = report.sceneTimeS;
    out["physics_seconds"] = report.physicsSeconds;
    out["blades"] = report.blades;
    out["wall_s"] = report.wallS;
    out["knobs"] = nlohmann::ordered_json::array();
    for (const KnobResult& knob : report.knobs) {
        nlohmann::ordered_json k;
        k["name"] = knob.name;
        if (!knob.skipped.empty()) {
            k["skipped"] = knob.skipped;
            out["knobs"].push_back(k);
            continue;
        }
        k["description"] = knob.description;
        k["cost_metric"] = knob.costMetric;
        k["error_metric"] = knob.errorMetric;
        if (!knob.checkLabel.empty())
            k["reference_check"] = {{"against", knob.checkLabel},
                                    {"error", knob.referenceCheckError},
                                    {"converged", knob.referenceConverged},
                                    {"converged_below", knob.convergedBelow},
                                    {"resolves_every_setting", knob.referenceResolvesSweep},
                                    {"rule",
                                     "converged: check error below a tenth of a "
                                     "just-noticeable difference (0.23 ΔE76; 0.001 h); "
                                     "resolves every setting: below half the smallest "
                                     "swept error"}};
        k["settings"] = nlohmann::ordered_json::array();
        const std::vector<std::string> presets = presetLabels(knob);
        for (std::size_t i = 0; i < knob.settings.size(); ++i)
            k["settings"].push_back(settingJson(knob.settings[i], presets[i]));
        out["knobs"].push_back(k);
    }
    return out;
}

Result<TradeoffReport> tradeoffFromJson(const std::string& text, const std::string& sourceName) {
    const auto bad = [&](const std::string& what) {
        return makeError(sourceName, what + " (not a grass tradeoff.json?)");
    };
    const auto parsed = parseJsonText(text, sourceName);
    if (!parsed)
        return bad(parsed.error().message);
    const Json& root = *parsed;
    if (!root.is_object() || !root.contains("knobs") || !root["knobs"].is_array())
        return bad("not a JSON object with a \"knobs\" array");
    // The readers below use nlohmann's at() and get(), which throw on a missing or mistyped
    // field; that is caught here, the one place this file meets exceptions (STYLE.md §4).
    try {
        TradeoffReport report = reportFromJson(root);
        for (std::size_t index = 0; index < root["knobs"].size(); ++index) {
            auto knob = knobFromJson(root["knobs"][index], index, sourceName);
            if (!knob)
                return knob.error();
            report.knobs.push_back(std::move(*knob));
        }
        makePrintable(report);
        return report;
    } catch (const Json::exception& e) {
        return bad(std::string("a field is missing or of the wrong type: ") + e.what());
    }
}

std::string tradeoffTable(const TradeoffReport& report) {
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s on %s: %zu blades, %s, %d×%d %d× MSAA, %d timed frames per setting, "
                  "images at t = %.2f s, physics over %.2f s; %.1f s in all\n",
                  report.project.c_str(), report.device.c_str(), report.blades,
                  report.geometry.c_str(), report.width, report.height, report.msaaSamples,
                  report.frames, static_cast<double>(report.sceneTimeS), report.physicsSeconds,
                  report.wallS);
    out += line;
    for (const KnobResult& knob : report.knobs) {
        if (!knob.skipped.empty()) {
            out += "\n## " + knob.name + ": skipped (" + knob.skipped + ")\n";
            continue;
        }
        out += "\n## " + knob.name + ": " + knob.description + "\ncost: " + knob.costMetric +
               "\nerror: " + knob.errorMetric + "\n\n";
        out +=
            "| setting | cost ms (min–max) | opaque | cull | grass | physics | error | "
            "error max | front | presets |\n|---|---:|---:|---:|---:|---:|---:|---:|:---:|---|\n";
        const std::vector<std::string> presets = presetLabels(knob);
        for (std::size_t i = 0; i < knob.settings.size(); ++i) {
            const SettingResult& s = knob.settings[i];
            std::snprintf(line, sizeof line,
                          "| %s%s | %.2f (%.2f–%.2f) | %.2f | %.2f | %.2f | %.2f | %.4g | %.4g | "
                          "%s | %s |\n",
                          s.label.c_str(),
                          s.reference ? " (ref)"
                          : s.check   ? " (check)"
                                      : "",
                          s.costMs.median, s.costMs.min, s.costMs.max, s.meshMs, s.cullMs,
                          s.grassMs, s.physicsGpuMs, s.error, s.errorMax, s.pareto ? "*" : "",
                          presets[i].c_str());
            out += line;
        }
        if (!knob.checkLabel.empty()) {
            std::snprintf(
                line, sizeof line, "reference against %s: error %.4g (%s, under %g: %s)\n",
                knob.checkLabel.c_str(), knob.referenceCheckError,
                knob.referenceConverged ? "converged" : "NOT converged", knob.convergedBelow,
                knob.referenceResolvesSweep
                    ? "resolves every swept setting"
                    : "does NOT resolve every swept setting (under half the smallest "
                      "swept error)");
            out += line;
        }
    }
    return out;
}

}  // namespace grass::render
