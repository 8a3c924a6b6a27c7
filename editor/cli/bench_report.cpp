#include "cli/bench_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include <nlohmann/json.hpp>

#include "util/atomic_file.h"
#include "util/json_text.h"

namespace grass::cli {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* FORMAT = "grass-bench";
constexpr int VERSION = 1;

// One figure of a case: its column in the tables and its key in the JSON ("ms.grass").
struct Figure {
    const char* header;
    const char* group;  // JSON object the key sits in; "" = the case itself
    const char* key;
    int precision;  // decimals in the table
    double scale;   // table value = figure × scale
    double BenchCaseResult::*real = nullptr;
    std::size_t BenchCaseResult::*count = nullptr;
    // Added after runs were saved without it: absent reads as 0 (shown as "-" in ratios).
    bool optional = false;
};

double valueOf(const Figure& figure, const BenchCaseResult& result) {
    return figure.real ? result.*figure.real : static_cast<double>(result.*figure.count);
}

// The order of the table's columns. Ratios of the ms columns below 1 mean faster; of
// blade-steps/s above 1.
constexpr std::array<Figure, 16> FIGURES = {{
    {"blades in", "", "blades_in", 0, 1.0, nullptr, &BenchCaseResult::bladesIn},
    {"drawn", "", "drawn", 0, 1.0, nullptr, &BenchCaseResult::drawn},
    {"culled %", "", "culled_share", 1, 100.0, &BenchCaseResult::culledShare, nullptr},
    {"frame ms", "ms", "frame_wall", 1, 1.0, &BenchCaseResult::frameMs, nullptr},
    {"cull ms", "ms", "cull", 2, 1.0, &BenchCaseResult::cullMs, nullptr},
    {"opaque ms", "ms", "opaque", 2, 1.0, &BenchCaseResult::opaqueMs, nullptr},
    {"grass ms", "ms", "grass", 2, 1.0, &BenchCaseResult::grassMs, nullptr},
    {"snow ms", "ms", "snow", 2, 1.0, &BenchCaseResult::snowMs, nullptr},
    {"phys ms/step", "physics", "ms_per_step", 2, 1.0, &BenchCaseResult::physicsMsPerStep, nullptr},
    {"M blade-steps/s", "physics", "blade_steps_per_s", 2, 1e-6, &BenchCaseResult::bladeStepsPerS,
     nullptr},
    {"CPU ms/step", "physics", "cpu_ms_per_step", 2, 1.0, &BenchCaseResult::cpuPhysicsMsPerStep,
     nullptr, true},
    {"CPU M b-s/s", "physics", "cpu_blade_steps_per_s", 2, 1e-6,
     &BenchCaseResult::cpuBladeStepsPerS, nullptr, true},
    {"UI ms", "ms", "ui", 3, 1.0, &BenchCaseResult::uiMs, nullptr},
    {"build s", "", "build_s", 2, 1.0, &BenchCaseResult::buildS, nullptr, true},
    {"peak MB", "", "peak_rss_mb", 0, 1.0, &BenchCaseResult::peakRssMb, nullptr, true},
    {"M blade tris", "", "blade_triangles", 2, 1e-6, nullptr, &BenchCaseResult::bladeTriangles,
     true},
}};

int columnWidth(const Figure& figure) {
    return std::max(9, static_cast<int>(std::string(figure.header).size()));
}

constexpr int NAME_WIDTH = 16;

void printHeader(const char* firstColumn, bool withFrames) {
    std::printf("%-*s", NAME_WIDTH, firstColumn);
    if (withFrames)
        std::printf(" %6s", "frames");
    for (const Figure& figure : FIGURES)
        std::printf("  %*s", columnWidth(figure), figure.header);
    std::printf("\n");
}

Error fileError(const std::string& file, const std::string& message) {
    return makeError(file, message);
}

// The number at `key` of `object` into `out`; the error names the file and `where` + key.
Result<void> readNumber(const Json& object, const char* key, const std::string& where,
                        const std::string& file, double* out) {
    const auto found = object.find(key);
    if (found == object.end() || !found->is_number() || !std::isfinite(found->get<double>()) ||
        found->get<double>() < 0.0)
        return fileError(file, where + key + ": missing or not a number >= 0");
    *out = found->get<double>();
    return {};
}

// What the run was measured with: image size, samples, renderer and geometry path.
Result<BenchRun> runSettingsFromJson(const Json& document, const std::string& file) {
    BenchRun run;
    double width = 0.0, height = 0.0, msaa = 0.0;
    for (auto [key, out] : {std::pair{"width", &width}, {"height", &height}, {"msaa", &msaa}})
        if (auto read = readNumber(document, key, "", file, out); !read)
            return read.error();
    run.width = static_cast<int>(width);
    run.height = static_cast<int>(height);
    run.msaaSamples = static_cast<int>(msaa);
    if (const auto renderer = document.find("renderer");
        renderer != document.end() && renderer->is_string())
        run.renderer = renderer->get<std::string>();
    if (const auto geometry = document.find("geometry");
        geometry != document.end() && geometry->is_string())
        run.geometry = geometry->get<std::string>();
    if (const auto group = document.find("compute_group");
        group != document.end() && group->is_number_unsigned())
        run.computeGroup = group->get<std::uint32_t>();
    return run;
}

// The editor case's figures: cases[].editor.{orbit,paint,play}.{frames,median_ms,p95_ms},
// .full_quality_s and .realtime_factor.
constexpr std::array<std::pair<const char*, EditorPhaseFigures EditorFigures::*>, 3> EDITOR_PHASES{
    {{"orbit", &EditorFigures::orbit}, {"paint", &EditorFigures::paint}, {"play", &EditorFigures::play}}};

Json editorJson(const EditorFigures& figures) {
    Json editor;
    for (const auto& [name, phase] : EDITOR_PHASES) {
        const EditorPhaseFigures& f = figures.*phase;
        editor[name] = {{"frames", f.frames}, {"median_ms", f.medianMs}, {"p95_ms", f.p95Ms}};
    }
    editor["full_quality_s"] = figures.fullQualityS;
    editor["realtime_factor"] = figures.realtimeFactor;
    return editor;
}

Result<EditorFigures> editorFromJson(const Json& editor, const std::string& where,
                                     const std::string& file) {
    if (!editor.is_object())
        return fileError(file, where + "editor: not an object");
    EditorFigures figures;
    for (const auto& [name, phase] : EDITOR_PHASES) {
        const auto found = editor.find(name);
        if (found == editor.end() || !found->is_object())
            return fileError(file, where + "editor." + name + ": missing or not an object");
        EditorPhaseFigures& f = figures.*phase;
        const std::string prefix = where + "editor." + name + ".";
        double frames = 0.0;
        for (auto [key, out] : {std::pair{"frames", &frames}, {"median_ms", &f.medianMs},
                                {"p95_ms", &f.p95Ms}})
            if (auto read = readNumber(*found, key, prefix, file, out); !read)
                return read.error();
        f.frames = static_cast<int>(frames);
    }
    for (auto [key, out] : {std::pair{"full_quality_s", &figures.fullQualityS},
                            {"realtime_factor", &figures.realtimeFactor}})
        if (auto read = readNumber(editor, key, where + "editor.", file, out); !read)
            return read.error();
    return figures;
}

// One case's entry; `where` ("cases[2].") prefixes the field errors name.
Result<BenchCaseResult> caseFromJson(const Json& entry, const std::string& where,
                                     const std::string& file) {
    const auto name = entry.is_object() ? entry.find("name") : entry.end();
    if (!entry.is_object() || name == entry.end() || !name->is_string())
        return fileError(file, where + "name: missing or not a string");
    BenchCaseResult result;
    result.name = name->get<std::string>();
    // Shown but not compared: absent or odd values read as 0.
    if (const auto project = entry.find("project"); project != entry.end() && project->is_string())
        result.project = project->get<std::string>();
    result.frames =
        entry.value("frames", Json(0)).is_number_integer() ? entry.value("frames", 0) : 0;
    result.physicsSteps = entry.value("physics_steps", Json(0)).is_number_integer()
                              ? entry.value("physics_steps", 0)
                              : 0;
    for (const Figure& figure : FIGURES) {
        const std::string prefix = where + (*figure.group ? figure.group + std::string(".") : "");
        const Json* object = &entry;
        if (*figure.group) {
            const auto group = entry.find(figure.group);
            if (group == entry.end() || !group->is_object())
                return fileError(file, where + figure.group + ": missing or not an object");
            object = &*group;
        }
        double value = 0.0;
        if (figure.optional && object->find(figure.key) == object->end())
            value = 0.0;
        else if (auto read = readNumber(*object, figure.key, prefix, file, &value); !read)
            return read.error();
        if (figure.count)
            result.*figure.count = static_cast<std::size_t>(value);
        else
            result.*figure.real = value;
    }
    if (const auto editor = entry.find("editor"); editor != entry.end()) {
        auto figures = editorFromJson(*editor, where, file);
        if (!figures)
            return figures.error();
        result.editor = *figures;
    }
    return result;
}

}  // namespace

std::string benchRunJson(const BenchRun& run) {
    Json out;
    out["format"] = FORMAT;
    out["version"] = VERSION;
    out["renderer"] = run.renderer;
    out["width"] = run.width;
    out["height"] = run.height;
    out["msaa"] = run.msaaSamples;
    out["geometry"] = run.geometry;
    out["compute_group"] = run.computeGroup;
    Json cases = Json::array();
    for (const BenchCaseResult& result : run.cases) {
        Json entry;
        entry["name"] = result.name;
        entry["project"] = result.project;
        entry["frames"] = result.frames;
        entry["physics_steps"] = result.physicsSteps;
        for (const Figure& figure : FIGURES) {
            Json& target = *figure.group ? entry[figure.group] : entry;
            if (figure.count)
                target[figure.key] = result.*figure.count;
            else
                target[figure.key] = result.*figure.real;
        }
        if (result.editor)
            entry["editor"] = editorJson(*result.editor);
        cases.push_back(std::move(entry));
    }
    out["cases"] = std::move(cases);
    return out.dump(2) + "\n";
}

Result<BenchRun> readBenchRun(const std::string& file) {
    auto text = readFile(file, MAX_JSON_FILE_BYTES);
    if (!text)
        return text.error();
    const auto parsed = parseJsonText(*text, file);
    if (!parsed)
        return fileError(
            file, parsed.error().message + " (expected a file written by grass bench --out)");
    const Json& document = *parsed;
    if (!document.is_object() || document.value("format", Json()) != FORMAT)
        return fileError(file,
                         "not a grass bench result (no \"format\": \"grass-bench\"; write "
                         "one with grass bench --out)");
    if (document.value("version", Json()) != VERSION)
        return fileError(file, "unsupported grass bench version (this grass reads version " +
                                   std::to_string(VERSION) + ")");
    auto run = runSettingsFromJson(document, file);
    if (!run)
        return run;
    const auto cases = document.find("cases");
    if (cases == document.end() || !cases->is_array() || cases->empty())
        return fileError(file, "cases: missing or empty");
    for (std::size_t i = 0; i < cases->size(); ++i) {
        auto result = caseFromJson((*cases)[i], "cases[" + std::to_string(i) + "].", file);
        if (!result)
            return result.error();
        run->cases.push_back(std::move(*result));
    }
    return run;
}

void printBenchTable(const BenchRun& run) {
    std::printf("renderer  %s\n", run.renderer.c_str());
    std::printf(
        "settings  %dx%d, %dx MSAA, blade geometry %s%s; ms are medians over the timed frames: "
        "frame = CPU wall time with glFinish, stages = GPU timer queries (on software GL each "
        "pass alone between two glFinish, in separate frames)\n",
        run.width, run.height, run.msaaSamples, run.geometry.c_str(),
        run.computeGroup > 0 ? (", compute groups of " + std::to_string(run.computeGroup)).c_str()
                             : "");
    printHeader("case", true);
    for (const BenchCaseResult& result : run.cases) {
        std::printf("%-*s %6d", NAME_WIDTH, result.name.c_str(), result.frames);
        for (const Figure& figure : FIGURES)
            std::printf("  %*.*f", columnWidth(figure), figure.precision,
                        valueOf(figure, result) * figure.scale);
        std::printf("\n");
    }
    // The editor case: frame times while interacting, at wall-clock time.
    for (const BenchCaseResult& result : run.cases) {
        if (!result.editor)
            continue;
        const EditorFigures& e = *result.editor;
        std::printf("%s (the editor window, wall clock): ", result.name.c_str());
        for (const auto& [name, phase] : EDITOR_PHASES)
            std::printf("%s median %.1f ms, p95 %.1f ms (%d frames); ", name, (e.*phase).medianMs,
                        (e.*phase).p95Ms, (e.*phase).frames);
        std::printf("full picture %.2f s after input stops; physics at %.2f of real time\n",
                    e.fullQualityS, e.realtimeFactor);
    }
}

Result<void> checkComparable(const BenchRun& old, const std::string& oldFile,
                             const std::vector<std::string>& caseNames, int width, int height) {
    if (old.width != width || old.height != height)
        return fileError(oldFile, "measured at " + std::to_string(old.width) + "x" +
                                      std::to_string(old.height) + ", this run is at " +
                                      std::to_string(width) + "x" + std::to_string(height) +
                                      " (compare runs of the same --width and --height)");
    std::string oldNames;
    for (const BenchCaseResult& result : old.cases) {
        for (const std::string& name : caseNames)
            if (name == result.name)
                return {};
        oldNames += (oldNames.empty() ? "" : ", ") + result.name;
    }
    return fileError(oldFile, "has none of this run's cases (it has: " + oldNames + ")");
}

Result<void> printBenchComparison(const BenchRun& run, const BenchRun& old,
                                  const std::string& oldFile) {
    std::vector<std::string> names;
    for (const BenchCaseResult& result : run.cases)
        names.push_back(result.name);
    if (auto comparable = checkComparable(old, oldFile, names, run.width, run.height); !comparable)
        return comparable;
    std::printf("\ncompared with %s (%s)\n", oldFile.c_str(), old.renderer.c_str());
    std::printf(
        "ratios this run / old run: below 1.00 the ms columns got faster, above 1.00 "
        "blade-steps/s did; - where a figure is 0\n");
    printHeader("case", false);
    for (const BenchCaseResult& result : run.cases) {
        const BenchCaseResult* before = nullptr;
        for (const BenchCaseResult& candidate : old.cases)
            if (candidate.name == result.name)
                before = &candidate;
        std::printf("%-*s", NAME_WIDTH, result.name.c_str());
        for (const Figure& figure : FIGURES) {
            const double now = valueOf(figure, result);
            const double then = before ? valueOf(figure, *before) : 0.0;
            if (!before)
                std::printf("  %*s", columnWidth(figure), "new");
            else if (now > 0.0 && then > 0.0)
                std::printf("  %*.2f", columnWidth(figure), now / then);
            else
                std::printf("  %*s", columnWidth(figure), "-");
        }
        std::printf("\n");
    }
    std::string notRun;
    for (const BenchCaseResult& before : old.cases)
        if (std::none_of(run.cases.begin(), run.cases.end(),
                         [&](const BenchCaseResult& now) { return now.name == before.name; }))
            notRun += (notRun.empty() ? "" : ", ") + before.name;
    if (!notRun.empty())
        std::printf("in the old run only: %s\n", notRun.c_str());
    return {};
}

}  // namespace grass::cli
