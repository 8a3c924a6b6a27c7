#include "tradeoff_report.h"

#include <cstdio>

namespace grass::render {

namespace {

nlohmann::ordered_json settingJson(const SettingResult& s) {
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
    return out;
}

}  // namespace

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
                                    {"rule", "check error < 0.5 × the smallest swept error"}};
        k["settings"] = nlohmann::ordered_json::array();
        for (const SettingResult& s : knob.settings)
            k["settings"].push_back(settingJson(s));
        out["knobs"].push_back(k);
    }
    return out;
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
            "error max | front |\n|---|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
        for (const SettingResult& s : knob.settings) {
            std::snprintf(line, sizeof line,
                          "| %s%s | %.2f (%.2f–%.2f) | %.2f | %.2f | %.2f | %.2f | %.4g | %.4g | "
                          "%s |\n",
                          s.label.c_str(),
                          s.reference ? " (ref)"
                          : s.check   ? " (check)"
                                      : "",
                          s.costMs.median, s.costMs.min, s.costMs.max, s.meshMs, s.cullMs,
                          s.grassMs, s.physicsGpuMs, s.error, s.errorMax, s.pareto ? "*" : "");
            out += line;
        }
        if (!knob.checkLabel.empty()) {
            std::snprintf(line, sizeof line, "reference against %s: error %.4g (%s)\n",
                          knob.checkLabel.c_str(), knob.referenceCheckError,
                          knob.referenceConverged ? "converged" : "NOT converged");
            out += line;
        }
    }
    return out;
}

}  // namespace grass::render
