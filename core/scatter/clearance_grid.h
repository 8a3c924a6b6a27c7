// Whether a point lies within a distance of a set of triangles: the clearance rule's test
// (placement_rules.h), for every candidate blade of a layer. A hashed uniform grid holds each
// triangle in the cells its box, grown by the distance, touches; a query checks one cell.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

namespace grass::core {

class ClearanceGrid {
public:
    using Triangle = std::array<glm::vec3, 3>;
    ClearanceGrid(std::vector<Triangle> triangles, float distance);

    // Closer than the distance to some triangle (a point on one counts at any distance > 0).
    bool within(glm::vec3 p) const;
    bool empty() const { return mTriangles.empty() || !(mDistance > 0.0f); }

private:
    std::int64_t cellKey(glm::ivec3 cell) const;
    glm::ivec3 cellOf(glm::vec3 p) const;

    std::vector<Triangle> mTriangles;
    float mDistance = 0.0f;
    float mCellSize = 1.0f;
    glm::vec3 mOrigin{0.0f};
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> mCells;
};

}  // namespace grass::core
