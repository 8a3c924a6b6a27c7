#include "project/project_migration.h"

#include <array>

#include "project/project.h"

namespace grass::core::json {

namespace {

// Version 2 (issue 22) only refuses what version 1 let through and no run could use: a physics
// step outside 10 µs .. 60 s (1e-30 asked for 9.2e18 steps), blades beyond 100 m by 10 m (their
// control points lost their length), more than 256 layers, cameras, wind sources or colliders,
// control characters in names. A version 1 file that ran reads unchanged; one that did not is
// refused by the reader with the limit it passed, as a version 2 file is.
void raiseToVersion2(Json& /*root*/) {}

// Version 3 (issue 30 item 5): the default height-vs-light curve falls with light, as Kim & Cho
// describe (before, it rose). A layer of an older file that leaves the curve out meant the rising
// one, so it gets it written out; a growth value that is not an object is left for the reader to
// refuse.
void raiseToVersion3(Json& root) {
    const auto layers = root.find("layers");
    if (layers == root.end() || !layers->is_array())
        return;
    for (Json& layer : *layers) {
        if (!layer.is_object())
            continue;
        Json& growth = layer["growth"];
        if (growth.is_null())
            growth = Json::object();
        if (growth.is_object() && !growth.contains("height_light_curve"))
            growth["height_light_curve"] = {0.1, 0.25, 0.4, 0.75, 0.8};
    }
}

struct Step {
    std::int64_t to;
    void (*raise)(Json& root);
};
constexpr std::array STEPS{Step{2, raiseToVersion2}, Step{3, raiseToVersion3}};
static_assert(STEPS.back().to == PROJECT_FORMAT_VERSION, "every version has a step up to it");

}  // namespace

void migrateProject(Json& root, std::int64_t version) {
    for (const Step& step : STEPS)
        if (version < step.to)
            step.raise(root);
    root["version"] = PROJECT_FORMAT_VERSION;
}

}  // namespace grass::core::json
