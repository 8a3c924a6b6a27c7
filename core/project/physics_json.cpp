// The "physics" section of project.json (gravity and the integration policy) and the keyed
// paths that wind sources and colliders follow.
#include <array>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using json::Json;
using json::NumberRule;
using settings::field;

constexpr std::array<std::string_view, 3> GRAVITY_KEYS{"direction", "centre", "strength"};
constexpr std::array<std::string_view, 2> PATH_KEY_KEYS{"time", "position"};
constexpr std::string_view XYZ = "[x, y, z]";
// 10 µs to a minute: a shorter step resolves nothing the blades do (their stiffest mode is
// ~1 ms) and made a run of seconds billions of steps; a step beyond a minute is a typo (and the
// substep cap would make it meaningless).
constexpr NumberRule STEP_RULE{1e-5, 60.0};
constexpr NumberRule MOVE_RULE{0.0, 1.0, true, false};
constexpr std::int64_t MAX_SUBSTEPS = 64;

void readGravity(json::Reader& reader, json::Object& physicsObject, std::string_view key,
                 PhysicsParams& physics) {
    const Json* node = physicsObject.find(key);
    if (!node)
        return;
    json::Object object(reader, *node, physicsObject.pointerTo(key), GRAVITY_KEYS);
    if (!object.valid())
        return;
    if (object.find("direction") && object.find("centre")) {
        reader.fail(object.pointerTo("centre"),
                    "not allowed with \"direction\" (gravity points along a direction or towards "
                    "a centre, not both)");
        return;
    }
    glm::vec3 vector = glm::vec3(physics.gravity);
    if (object.find("centre")) {
        physics.gravityMode = GravityMode::Centre;
        object.readVec3("centre", json::ANY_NUMBER, XYZ, vector);
    } else {
        physics.gravityMode = GravityMode::Direction;
        object.readVec3("direction", json::ANY_NUMBER, XYZ, vector);
    }
    float strength = physics.gravity.w;
    object.readFloat("strength", json::NON_NEGATIVE, strength);
    physics.gravity = glm::vec4(vector, strength);
    if (reader.ok() && physics.gravityMode == GravityMode::Direction && vector == glm::vec3(0.0f))
        reader.fail(object.pointerTo("direction"),
                    "must not be [0, 0, 0] (set \"strength\": 0 for no gravity)");
}

Json gravityJson(const PhysicsParams& physics) {
    Json gravity = Json::object();
    const glm::vec3 vector = glm::vec3(physics.gravity);
    gravity[physics.gravityMode == GravityMode::Centre ? "centre" : "direction"] =
        json::jsonVec3(vector);
    gravity["strength"] = json::jsonFloat(physics.gravity.w);
    return gravity;
}

constexpr std::array PHYSICS{
    field<&PhysicsParams::dtS>(
        {.key = "step_s",
         .rule = STEP_RULE,
         .unit = "s",
         .help = "the step of `grass sim` and `render --time` (`--dt` overrides)",
         .defaultText = "`1/60`"}),
    settings::custom<PhysicsParams>(
        {.key = "gravity",
         .typeText = "object",
         .allowedText = "`direction` (finite, not `[0, 0, 0]`) **or** `centre` (a point every "
                        "blade falls towards: a planet, the core of a torus), and `strength` >= 0",
         .defaultText = "`{\"direction\": [0, -1, 0], \"strength\": 9.81}`"},
        readGravity, gravityJson),
    field<&PhysicsParams::etaDecayPerS>(
        {.key = "eta_decay_per_s",
         .rule = json::NON_NEGATIVE,
         .unit = "1/s",
         .help = "the rate a at which the collision strength η of a crushed blade decays: a trail "
                 "lasts about η/a seconds"}),
    field<&PhysicsParams::maxSubstepS>(
        {.key = "max_substep_s",
         .rule = STEP_RULE,
         .unit = "s",
         .help = "a step is cut into substeps no longer than this…",
         .defaultText = "`1/120`"}),
    field<&PhysicsParams::maxSubsteps>(
        {.key = "max_substeps",
         .intMin = 1,
         .intMax = MAX_SUBSTEPS,
         .help = "…but never more than this many (long steps then use longer substeps)"}),
    field<&PhysicsParams::maxMovePerSubstep>(
        {.key = "max_move_per_substep",
         .rule = MOVE_RULE,
         .help = "the tip moves at most this fraction of h per substep"}),
    field<&PhysicsParams::frontGravityScale>(
        {.key = "front_gravity_scale",
         .rule = json::NON_NEGATIVE,
         .help = "the paper's front gravity gF = scale·\\|gE\\|·front"}),
    field<&PhysicsParams::crushedRecoveryFloor>(
        {.key = "crushed_recovery_floor",
         .rule = json::UNIT_INTERVAL,
         .help = "recovery while crushed is s·max(1 − η, floor) (the paper: 0.1); lower keeps "
                 "trails longer"}),
};

}  // namespace

std::span<const settings::Setting<PhysicsParams>> settings::physics() { return PHYSICS; }

void json::readPath(Reader& reader, const Json& node, const std::string& pointer,
                    std::vector<PathKey>& path) {
    if (!node.is_array()) {
        reader.fail(pointer,
                    "must be an array of {\"time\": seconds, \"position\": [x, y, z]} "
                    "keys (got " +
                        describeValue(node) + ")");
        return;
    }
    std::vector<PathKey> keys(node.size());
    for (std::size_t i = 0; i < node.size() && reader.ok(); ++i) {
        Object key(reader, node[i], childPointer(pointer, i), PATH_KEY_KEYS);
        if (!key.valid())
            return;
        if (!key.find("time") || !key.find("position")) {
            reader.fail(key.pointer(), "a path key needs both \"time\" and \"position\"");
            return;
        }
        key.readFloat("time", ANY_NUMBER, keys[i].timeS);
        key.readVec3("position", ANY_NUMBER, XYZ, keys[i].posWorld);
        if (reader.ok() && i > 0 && keys[i].timeS < keys[i - 1].timeS)
            reader.fail(key.pointerTo("time"),
                        "path keys must be in time order (" + std::to_string(keys[i].timeS) +
                            " s comes after " + std::to_string(keys[i - 1].timeS) + " s)");
    }
    if (reader.ok())
        path = std::move(keys);
}

json::Json json::pathJson(const std::vector<PathKey>& path) {
    Json out = Json::array();
    for (const PathKey& key : path)
        out.push_back(
            Json::object({{"time", jsonFloat(key.timeS)}, {"position", jsonVec3(key.posWorld)}}));
    return out;
}

}  // namespace grass::core
