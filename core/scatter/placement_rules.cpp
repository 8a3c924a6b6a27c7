#include "scatter/placement_rules.h"

#include <algorithm>
#include <cmath>

#include "mesh/mesh_parts.h"
#include "scatter/collider_interior.h"

namespace grass::core {

namespace {

constexpr float DEGREES_PER_RADIAN = 57.29577951308232f;

bool anyName(const MeshPart& part, const std::vector<std::string>& names) {
    return std::any_of(names.begin(), names.end(),
                       [&](const std::string& name) { return partHasName(part, name); });
}

// Per part of the mesh, whether the include/exclude lists let the layer grow there.
std::vector<char> partsAllowed(const MeshParts& table, const PlacementRules& rules) {
    std::vector<char> allowed(table.parts.size());
    for (std::size_t i = 0; i < allowed.size(); ++i) {
        const MeshPart& part = table.parts[i];
        const bool included = rules.include.empty() || anyName(part, rules.include);
        allowed[i] = included && !anyName(part, rules.exclude) ? 1 : 0;
    }
    return allowed;
}

// The unit geometric normal of every face: the slope of the ground a blade stands on, exact
// where a vertex normal would blend a cliff into the field at its foot.
std::vector<glm::vec3> faceNormals(const SurfaceMesh& mesh) {
    std::vector<glm::vec3> normals(mesh.n_faces(), glm::vec3(0.0f, 1.0f, 0.0f));
    for (const auto fh : mesh.faces()) {
        const auto p = facePositions(mesh, fh);
        const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float length = glm::length(n);
        if (length > 0.0f && std::isfinite(length))
            normals[static_cast<std::size_t>(fh.idx())] = n / length;
    }
    return normals;
}

std::vector<ClearanceGrid::Triangle> clearanceTriangles(const SurfaceMesh& mesh,
                                                        const PlacementRules& rules,
                                                        const RuleWorld& world) {
    std::vector<ClearanceGrid::Triangle> triangles;
    if (!(rules.clearanceM > 0.0f))
        return triangles;
    if (rules.clearColliders)
        triangles = world.colliderTriangles;
    const MeshParts* table = meshPartsOf(mesh);
    if (!table || rules.clearOf.empty())
        return triangles;
    std::vector<char> chosen(table->parts.size());
    for (std::size_t i = 0; i < chosen.size(); ++i)
        chosen[i] = anyName(table->parts[i], rules.clearOf) ? 1 : 0;
    for (const auto fh : mesh.faces())
        if (chosen[table->faceParts[static_cast<std::size_t>(fh.idx())]])
            triangles.push_back(facePositions(mesh, fh));
    return triangles;
}

}  // namespace

float windowFactor(float value, float min, float max, float soft) {
    if (!std::isfinite(value))
        return 0.0f;
    const float outside = value < min ? min - value : value > max ? value - max : 0.0f;
    if (outside <= 0.0f)
        return 1.0f;
    return soft > 0.0f ? std::max(0.0f, 1.0f - outside / soft) : 0.0f;
}

glm::vec3 upAt(glm::vec3 p, const RuleWorld& world) {
    const glm::vec3 g(world.gravity);
    const glm::vec3 up = world.gravityMode == GravityMode::Centre ? p - g : -g;
    const float length = glm::length(up);
    return length > 0.0f && std::isfinite(length) ? up / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

float slopeDeg(glm::vec3 normal, glm::vec3 p, const RuleWorld& world) {
    const float cosine = std::clamp(glm::dot(normal, upAt(p, world)), -1.0f, 1.0f);
    return std::acos(cosine) * DEGREES_PER_RADIAN;
}

float altitudeM(glm::vec3 p, const RuleWorld& world) {
    if (world.gravityMode == GravityMode::Centre)
        return glm::length(p - glm::vec3(world.gravity));
    return glm::dot(p, upAt(p, world));
}

bool rulesAreOpen(const PlacementRules& rules) {
    const PlacementRules open;
    return rules.include.empty() && rules.exclude.empty() && rules.slopeMinDeg <= 0.0f &&
           rules.slopeMaxDeg >= 180.0f && rules.altitudeMinM <= open.altitudeMinM &&
           rules.altitudeMaxM >= open.altitudeMaxM &&
           (!(rules.clearanceM > 0.0f) || rules.clearOf.empty()) && !rules.clearColliders;
}

std::vector<float> placementFactors(const SurfaceMesh& mesh, const ScatterCandidates& candidates,
                                    const PlacementRules& rules, const RuleWorld& world) {
    if (rulesAreOpen(rules))
        return {};
    const std::vector<glm::vec3> normals = faceNormals(mesh);
    const MeshParts* table = meshPartsOf(mesh);
    const std::vector<char> allowed = table ? partsAllowed(*table, rules) : std::vector<char>{};
    // A surface without names is one unnamed part: only an include list can shut it out.
    const bool unnamedAllowed = rules.include.empty();
    const ClearanceGrid clear(clearanceTriangles(mesh, rules, world), rules.clearanceM);
    // A root under a collider is within any clearance of it, 0 included, however far from its
    // surface.
    const ColliderInteriors underColliders =
        rules.clearColliders ? ColliderInteriors(world.colliderTriangles, world.colliderEnds)
                             : ColliderInteriors();
    std::vector<float> factors(candidates.blades.size(), 1.0f);
    for (std::size_t i = 0; i < factors.size(); ++i) {
        const std::uint32_t face = candidates.faces[i];
        const glm::vec3 root = candidates.blades[i].v0();
        const bool partAllowed = table ? allowed[table->faceParts[face]] != 0 : unnamedAllowed;
        if (!partAllowed || clear.within(root) ||
            (!underColliders.empty() && underColliders.inside(root, upAt(root, world)))) {
            factors[i] = 0.0f;
            continue;
        }
        factors[i] = windowFactor(slopeDeg(normals[face], root, world), rules.slopeMinDeg,
                                  rules.slopeMaxDeg, rules.slopeSoftDeg) *
                     windowFactor(altitudeM(root, world), rules.altitudeMinM, rules.altitudeMaxM,
                                  rules.altitudeSoftM);
    }
    return factors;
}

}  // namespace grass::core
