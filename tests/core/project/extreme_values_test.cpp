// Extreme values from users (issue 11): every number of every committed project, and of the full
// document a project saves as (every field, defaults included), is replaced in turn by 0, −1,
// ±1e30, ±1e999 (beyond double), "nan", "abc", true, null, [] and {}; every key is removed and
// every array loses its last element. Each case must either be refused by the loader with one
// line naming the field and what it accepts, or load into a project that saves back finite, with
// the value as given. On the small projects an accepted case is also grown and stepped for a
// few physics steps: no error without a field named, no non-finite blade.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "physics/field_health.h"
#include "project/project.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Pointer = Json::json_pointer;

// JSON text of each replacement; "1e999" is not a double at all (the parser's overflow path).
const std::vector<std::string> REPLACEMENTS{"0",     "-1",     "-1e30",   "1e30",
                                            "1e999", "-1e999", "\"nan\"", "\"abc\"",
                                            "true",  "null",   "[]",      "{}"};
constexpr const char* PLACEHOLDER = "@@extreme@@";
// Numbers the format documents as ignored (docs/project-format.md): saved as 0 whatever is given.
const std::vector<std::string> IGNORED{"/billboards/wind_direction/1"};

struct Source {
    std::string name;
    std::string text;
    fs::path folder;  // where its assets are; empty: not grown
};

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every committed project that loads (the test data also holds deliberately broken ones), and
// the full saved documents of two of them.
std::vector<Source> sources(std::vector<std::string>& skipped) {
    std::vector<Source> out;
    std::vector<fs::path> files;
    for (const char* root : {"projects", "tests/data/projects"})
        for (const auto& entry : fs::directory_iterator(test::sourceDir() / root))
            if (fs::exists(entry.path() / "project.json"))
                files.push_back(entry.path() / "project.json");
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        const std::string text = readText(file);
        const std::string name = file.parent_path().filename().string();
        if (!parseProject(text, file.string())) {
            skipped.push_back(name);
            continue;
        }
        const bool small = name == "tiny" || name == "windy" || name == "growth_tiny";
        out.push_back({name, text, small ? file.parent_path() : fs::path()});
        if (name == "windy" || name == "tiny")
            out.push_back({name + " (full document)", serializeProject(*parseProject(text, name)),
                           file.parent_path()});
    }
    return out;
}

void collectPointers(const Json& node, const std::string& pointer, bool numbersOnly,
                     std::vector<std::string>& out) {
    if (node.is_number() || (!numbersOnly && pointer.size() > 0))
        out.push_back(pointer);
    if (node.is_object()) {
        for (const auto& item : node.items())
            collectPointers(item.value(), pointer + "/" + item.key(), numbersOnly, out);
    } else if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i)
            collectPointers(node[i], pointer + "/" + std::to_string(i), numbersOnly, out);
    }
}

// True when every number of `node` is finite and nothing is null (the writer prints a
// non-finite float as null).
bool allFinite(const Json& node, std::string& where, const std::string& pointer = "") {
    if (node.is_null() || (node.is_number_float() && !std::isfinite(node.get<double>()))) {
        where = pointer;
        return false;
    }
    if (node.is_object()) {
        for (const auto& item : node.items())
            if (!allFinite(item.value(), where, pointer + "/" + item.key()))
                return false;
    } else if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i)
            if (!allFinite(node[i], where, pointer + "/" + std::to_string(i)))
                return false;
    }
    return true;
}

std::string lastKey(const std::string& pointer) {
    std::string key = pointer.substr(pointer.rfind('/') + 1);
    // An array element is named by its array ("/layers/0/blade/height/1" by "height").
    if (!key.empty() && std::isdigit(static_cast<unsigned char>(key[0])))
        return lastKey(pointer.substr(0, pointer.rfind('/')));
    return key;
}

// A refusal names the field (its pointer, an enclosing pointer, or its key) and says what is
// allowed, on one line.
std::string checkRefusal(const std::string& error, const std::string& pointer) {
    if (error.find('\n') != std::string::npos)
        return "not one line";
    bool named = false;
    for (std::string at = pointer; !named && !at.empty(); at = at.substr(0, at.rfind('/')))
        named = error.find(at) != std::string::npos;
    named = named || error.find(pointer) != std::string::npos ||
            error.find(lastKey(pointer)) != std::string::npos;
    if (!named)
        return "does not name the field";
    for (const char* says :
         {"must", "expected", "only", "not allowed", "limit", "needs", "required", "duplicate"})
        if (error.find(says) != std::string::npos)
            return {};
    return "does not say what is allowed";
}

struct Tally {
    std::size_t cases = 0, refused = 0, accepted = 0, grown = 0;
    std::vector<std::string> failures;
    void fail(const Source& source, const std::string& what, const std::string& why) {
        failures.push_back(source.name + ": " + what + ": " + why);
    }
};

// Grows the accepted project on its small plane and steps its physics: the cheapest run that
// shows a value turning the field non-finite.
void growAndStep(const Source& source, const Project& project, const std::string& pointer,
                 const std::string& what, Tally& tally) {
    const LoadedProject loaded{project, source.folder, source.folder / "project.json"};
    auto scene = buildScene(loaded);
    if (!scene) {
        if (const std::string why = checkRefusal(scene.error().str(), pointer); !why.empty())
            tally.fail(source, what, "grow refused: " + why + ": " + scene.error().str());
        return;
    }
    auto physics = buildScenePhysics(loaded);
    if (!physics) {
        if (const std::string why = checkRefusal(physics.error().str(), pointer); !why.empty())
            tally.fail(source, what, "physics refused: " + why + ": " + physics.error().str());
        return;
    }
    ++tally.grown;
    SceneSimulation simulation(*scene, std::move(*physics), 1);
    for (int i = 0; i < 5; ++i)
        simulation.step();
    const FieldHealth health = simulation.health();
    if (health.nonfinite > 0)
        tally.fail(source, what,
                   "grew " + std::to_string(health.nonfinite) + " non-finite blades after 5 steps");
}

void tryDocument(const Source& source, const std::string& text, const std::string& pointer,
                 const std::string& what, const std::string& replacement, Tally& tally) {
    ++tally.cases;
    const auto parsed = parseProject(text, "extreme.json");
    if (!parsed) {
        ++tally.refused;
        if (const std::string why = checkRefusal(parsed.error().str(), pointer); !why.empty())
            tally.fail(source, what, why + ": " + parsed.error().str());
        return;
    }
    ++tally.accepted;
    const Json saved = Json::parse(serializeProject(*parsed));
    std::string where;
    if (!allFinite(saved, where)) {
        tally.fail(source, what, "accepted, saves a non-finite number at " + where);
        return;
    }
    if (!replacement.empty()) {
        const bool isNumber = replacement.find_first_not_of("-0123456789.e") == std::string::npos;
        if (!isNumber) {
            tally.fail(source, what, "accepted a value of the wrong type");
            return;
        }
        const bool kept = std::find(IGNORED.begin(), IGNORED.end(), pointer) == IGNORED.end();
        const Pointer at(pointer);
        const double given = std::strtod(replacement.c_str(), nullptr);
        if (kept && (!saved.contains(at) || !saved[at].is_number()))
            tally.fail(source, what, "accepted, but the saved project has no number there");
        else if (kept && static_cast<float>(saved[at].get<double>()) != static_cast<float>(given))
            tally.fail(source, what, "accepted, but saved as " + saved[at].dump());
    }
    if (!source.folder.empty())
        growAndStep(source, *parsed, pointer, what, tally);
}

TEST(ExtremeValues, EveryProjectNumberIsRefusedClearlyOrKeptFinite) {
    std::vector<std::string> skipped;
    const std::vector<Source> all = sources(skipped);
    ASSERT_GE(all.size(), 10u);
    Tally tally;
    std::size_t fields = 0;
    for (const Source& source : all) {
        const Json document = Json::parse(source.text);
        std::vector<std::string> numbers;
        collectPointers(document, "", true, numbers);
        fields += numbers.size();
        for (const std::string& pointer : numbers) {
            Json changed = document;
            changed[Pointer(pointer)] = PLACEHOLDER;
            const std::string dumped = changed.dump();
            const std::string quoted = std::string("\"") + PLACEHOLDER + "\"";
            for (const std::string& replacement : REPLACEMENTS) {
                std::string text = dumped;
                text.replace(text.find(quoted), quoted.size(), replacement);
                tryDocument(source, text, pointer, pointer + " = " + replacement, replacement,
                            tally);
            }
        }
    }
    for (const std::string& failure : tally.failures)
        ADD_FAILURE() << failure;
    std::printf(
        "extreme values: %zu numeric fields in %zu documents x %zu values = %zu cases "
        "(%zu refused, %zu accepted, %zu of them grown and stepped); skipped as "
        "invalid already: %zu projects\n",
        fields, all.size(), REPLACEMENTS.size(), tally.cases, tally.refused, tally.accepted,
        tally.grown, skipped.size());
}

// A missing key takes its documented default (and the project stays finite) or is refused as
// required; a shortened array is refused or kept finite.
TEST(ExtremeValues, MissingKeysAndShortArraysAreRefusedClearlyOrDefaulted) {
    std::vector<std::string> skipped;
    const std::vector<Source> all = sources(skipped);
    Tally tally;
    for (const Source& source : all) {
        const Json document = Json::parse(source.text);
        std::vector<std::string> members;
        collectPointers(document, "", false, members);
        for (const std::string& pointer : members) {
            const Pointer at(pointer);
            Json changed = document;
            Json& parent = changed[at.parent_pointer()];
            std::string what;
            if (parent.is_object()) {
                parent.erase(at.back());
                what = pointer + " removed";
            } else {
                // Only the last element, so each array is cut once.
                if (std::to_string(parent.size() - 1) != at.back())
                    continue;
                parent.erase(parent.size() - 1);
                what = pointer + " cut";
            }
            tryDocument(source, changed.dump(), pointer, what, "", tally);
        }
    }
    for (const std::string& failure : tally.failures)
        ADD_FAILURE() << failure;
    std::printf(
        "missing keys and short arrays: %zu cases (%zu refused, %zu accepted, %zu of "
        "them grown and stepped)\n",
        tally.cases, tally.refused, tally.accepted, tally.grown);
}

}  // namespace
}  // namespace grass::core
