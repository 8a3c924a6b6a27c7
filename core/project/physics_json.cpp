// The physics part of project.json: "physics" (gravity and the integration policy), "wind"
// (SPEC §4 sources) and "colliders" (SPEC §5). Keys are spelled here only; docs/project-format.md
// lists them in the order they are written.
#include <array>

#include "collider/sphere_packing.h"
#include "project/project_json_parts.h"

namespace grass::core::json {

namespace {

constexpr std::array<std::string_view, 8> PHYSICS_KEYS{"step_s",
                                                       "gravity",
                                                       "eta_decay_per_s",
                                                       "max_substep_s",
                                                       "max_substeps",
                                                       "max_move_per_substep",
                                                       "front_gravity_scale",
                                                       "crushed_recovery_floor"};
constexpr std::array<std::string_view, 3> GRAVITY_KEYS{"direction", "centre", "strength"};
constexpr std::array<std::string_view, 12> WIND_KEYS{
    "name",   "kind",        "position",   "direction", "axis", "strength",
    "radius", "core_radius", "wavelength", "speed",     "gust", "path"};
constexpr std::array<std::string_view, 10> COLLIDER_KEYS{
    "name",  "shape",   "position",           "radius", "file",
    "scale", "spheres", "packing_resolution", "path",   "color"};
constexpr std::array<std::string_view, 2> PATH_KEY_KEYS{"time", "position"};
constexpr std::string_view RGB = "[r, g, b]";

constexpr std::array<std::string_view, 3> WIND_KIND_NAMES{"directional", "point", "vortex"};
constexpr std::array<std::string_view, 2> COLLIDER_SHAPE_NAMES{"sphere", "mesh"};

constexpr std::string_view XYZ = "[x, y, z]";
// A step beyond a minute is a typo (and the substep cap would make it meaningless).
// 10 µs to a minute: a shorter step resolves nothing the blades do (their stiffest mode is
// ~1 ms) and made a run of seconds billions of steps.
constexpr NumberRule STEP_RULE{1e-5, 60.0};
constexpr NumberRule MOVE_RULE{0.0, 1.0, true, false};
constexpr std::int64_t MAX_SUBSTEPS = 64;

void readGravity(Reader& reader, const Json& node, PhysicsParams& physics) {
    Object object(reader, node, "/physics/gravity", GRAVITY_KEYS);
    if (!object.valid())
        return;
    if (object.find("direction") && object.find("centre")) {
        reader.fail("/physics/gravity/centre",
                    "not allowed with \"direction\" (gravity points along a direction or towards "
                    "a centre, not both)");
        return;
    }
    glm::vec3 vector = glm::vec3(physics.gravity);
    if (object.find("centre")) {
        physics.gravityMode = GravityMode::Centre;
        object.readVec3("centre", ANY_NUMBER, XYZ, vector);
    } else {
        physics.gravityMode = GravityMode::Direction;
        object.readVec3("direction", ANY_NUMBER, XYZ, vector);
    }
    float strength = physics.gravity.w;
    object.readFloat("strength", NON_NEGATIVE, strength);
    physics.gravity = glm::vec4(vector, strength);
    if (reader.ok() && physics.gravityMode == GravityMode::Direction && vector == glm::vec3(0.0f))
        reader.fail("/physics/gravity/direction",
                    "must not be [0, 0, 0] (set \"strength\": 0 for no gravity)");
}

void readPath(Reader& reader, const Json& node, const std::string& pointer,
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

Json pathJson(const std::vector<PathKey>& path) {
    Json out = Json::array();
    for (const PathKey& key : path)
        out.push_back(
            Json::object({{"time", jsonFloat(key.timeS)}, {"position", jsonVec3(key.posWorld)}}));
    return out;
}

}  // namespace

void readPhysics(Reader& reader, const Json& node, PhysicsParams& physics) {
    Object object(reader, node, "/physics", PHYSICS_KEYS);
    object.readFloat("step_s", STEP_RULE, physics.dtS);
    if (const Json* gravity = object.find("gravity"))
        readGravity(reader, *gravity, physics);
    object.readFloat("eta_decay_per_s", NON_NEGATIVE, physics.etaDecayPerS);
    object.readFloat("max_substep_s", STEP_RULE, physics.maxSubstepS);
    int maxSubsteps = static_cast<int>(physics.maxSubsteps);
    object.readInt("max_substeps", 1, MAX_SUBSTEPS, maxSubsteps);
    physics.maxSubsteps = static_cast<std::uint32_t>(maxSubsteps);
    object.readFloat("max_move_per_substep", MOVE_RULE, physics.maxMovePerSubstep);
    object.readFloat("front_gravity_scale", NON_NEGATIVE, physics.frontGravityScale);
    object.readFloat("crushed_recovery_floor", UNIT_INTERVAL, physics.crushedRecoveryFloor);
}

void readWind(Reader& reader, const Json& node, const std::string& pointer, WindDesc& wind) {
    Object object(reader, node, pointer, WIND_KEYS);
    object.readString("name", false, wind.name);
    WindSource& source = wind.source;
    if (const Json* kind = object.find("kind")) {
        std::size_t index = 0;
        if (reader.readEnum(*kind, object.pointerTo("kind"), WIND_KIND_NAMES, index))
            source.kind = static_cast<WindKind>(index);
    }
    object.readVec3("position", ANY_NUMBER, XYZ, source.position);
    object.readVec3("direction", ANY_NUMBER, XYZ, source.direction);
    object.readVec3("axis", ANY_NUMBER, XYZ, source.axis);
    object.readFloat("strength", ANY_NUMBER, source.strength);
    object.readFloat("radius", NON_NEGATIVE, source.radiusM);
    object.readFloat("core_radius", NON_NEGATIVE, source.coreRadiusM);
    object.readFloat("wavelength", NON_NEGATIVE, source.wavelengthM);
    object.readFloat("speed", ANY_NUMBER, source.speedMps);
    object.readFloat("gust", UNIT_INTERVAL, source.gust);
    if (const Json* path = object.find("path"))
        readPath(reader, *path, object.pointerTo("path"), source.path);
    if (!reader.ok())
        return;
    // A zero vector has no direction: the source would silently blow nowhere.
    if (source.kind == WindKind::Directional && source.direction == glm::vec3(0.0f))
        reader.fail(object.pointerTo("direction"),
                    "must not be [0, 0, 0] (it is where the wind blows to)");
    else if (source.kind == WindKind::Vortex && source.axis == glm::vec3(0.0f))
        reader.fail(object.pointerTo("axis"), "must not be [0, 0, 0] (it is the vortex axis)");
}

void readCollider(Reader& reader, const Json& node, const std::string& pointer,
                  ColliderDesc& collider) {
    Object object(reader, node, pointer, COLLIDER_KEYS);
    if (!object.valid())
        return;
    object.readString("name", false, collider.name);
    if (const Json* shape = object.find("shape")) {
        std::size_t index = 0;
        if (reader.readEnum(*shape, object.pointerTo("shape"), COLLIDER_SHAPE_NAMES, index))
            collider.shape = static_cast<ColliderShape>(index);
    }
    object.readVec3("position", ANY_NUMBER, XYZ, collider.position);
    if (object.find("color") != nullptr) {
        glm::vec3 color{0.0f};
        object.readVec3("color", UNIT_INTERVAL, RGB, color);
        collider.color = color;
    }
    if (const Json* path = object.find("path"))
        readPath(reader, *path, object.pointerTo("path"), collider.path);
    const bool mesh = collider.shape == ColliderShape::Mesh;
    const std::array<std::string_view, 4> meshOnly{"file", "scale", "spheres",
                                                   "packing_resolution"};
    for (const std::string_view key : meshOnly)
        if (!mesh && object.find(key))
            reader.fail(object.pointerTo(key), "only for \"shape\": \"mesh\" colliders");
    if (mesh && object.find("radius"))
        reader.fail(object.pointerTo("radius"),
                    "only for \"shape\": \"sphere\" colliders (a mesh collider takes \"scale\")");
    if (!mesh) {
        object.readFloat("radius", POSITIVE, collider.radiusM);
        return;
    }
    if (!object.find("file")) {
        reader.fail(object.pointerTo("file"),
                    "missing required key (a mesh collider names its .gltf or .glb file)");
        return;
    }
    object.readString("file", false, collider.file);
    checkAssetPath(reader, object.pointerTo("file"), collider.file);
    object.readFloat("scale", POSITIVE, collider.scale);
    int spheres = static_cast<int>(collider.sphereCount);
    object.readInt("spheres", 1, MAX_PACKED_SPHERES, spheres);
    collider.sphereCount = static_cast<std::uint32_t>(spheres);
    int resolution = static_cast<int>(collider.packingResolution);
    object.readInt("packing_resolution", MIN_PACKING_RESOLUTION, MAX_PACKING_RESOLUTION,
                   resolution);
    collider.packingResolution = static_cast<std::uint32_t>(resolution);
}

Json physicsJson(const PhysicsParams& physics) {
    Json gravity = Json::object();
    const glm::vec3 vector = glm::vec3(physics.gravity);
    if (physics.gravityMode == GravityMode::Centre)
        gravity["centre"] = jsonVec3(vector);
    else
        gravity["direction"] = jsonVec3(vector);
    gravity["strength"] = jsonFloat(physics.gravity.w);
    Json out = Json::object();
    out["step_s"] = jsonFloat(physics.dtS);
    out["gravity"] = std::move(gravity);
    out["eta_decay_per_s"] = jsonFloat(physics.etaDecayPerS);
    out["max_substep_s"] = jsonFloat(physics.maxSubstepS);
    out["max_substeps"] = physics.maxSubsteps;
    out["max_move_per_substep"] = jsonFloat(physics.maxMovePerSubstep);
    out["front_gravity_scale"] = jsonFloat(physics.frontGravityScale);
    out["crushed_recovery_floor"] = jsonFloat(physics.crushedRecoveryFloor);
    return out;
}

Json windJson(const WindDesc& wind) {
    const WindSource& source = wind.source;
    Json out = Json::object();
    out["name"] = wind.name;
    out["kind"] = std::string(WIND_KIND_NAMES[static_cast<std::size_t>(source.kind)]);
    out["position"] = jsonVec3(source.position);
    out["direction"] = jsonVec3(source.direction);
    out["axis"] = jsonVec3(source.axis);
    out["strength"] = jsonFloat(source.strength);
    out["radius"] = jsonFloat(source.radiusM);
    out["core_radius"] = jsonFloat(source.coreRadiusM);
    out["wavelength"] = jsonFloat(source.wavelengthM);
    out["speed"] = jsonFloat(source.speedMps);
    out["gust"] = jsonFloat(source.gust);
    out["path"] = pathJson(source.path);
    return out;
}

Json colliderJson(const ColliderDesc& collider) {
    Json out = Json::object();
    out["name"] = collider.name;
    out["shape"] = std::string(COLLIDER_SHAPE_NAMES[static_cast<std::size_t>(collider.shape)]);
    out["position"] = jsonVec3(collider.position);
    if (collider.color)
        out["color"] = jsonVec3(*collider.color);
    if (collider.shape == ColliderShape::Sphere) {
        out["radius"] = jsonFloat(collider.radiusM);
    } else {
        out["file"] = collider.file;
        out["scale"] = jsonFloat(collider.scale);
        out["spheres"] = collider.sphereCount;
        out["packing_resolution"] = collider.packingResolution;
    }
    out["path"] = pathJson(collider.path);
    return out;
}

}  // namespace grass::core::json
