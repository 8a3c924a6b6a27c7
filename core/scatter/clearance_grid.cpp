#include "scatter/clearance_grid.h"

#include <algorithm>
#include <cmath>

#include "mesh/closest_point.h"

namespace grass::core {

namespace {

// Cells per axis the key can tell apart (21 bits each); a grid needing more grows its cells.
constexpr int CELLS_PER_AXIS = 1 << 20;

}  // namespace

ClearanceGrid::ClearanceGrid(std::vector<Triangle> triangles, float distance)
    : mTriangles(std::move(triangles)), mDistance(distance) {
    if (empty())
        return;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    double extents = 0.0;
    for (const Triangle& t : mTriangles) {
        const glm::vec3 tlo = glm::min(glm::min(t[0], t[1]), t[2]);
        const glm::vec3 thi = glm::max(glm::max(t[0], t[1]), t[2]);
        lo = glm::min(lo, tlo);
        hi = glm::max(hi, thi);
        const glm::vec3 size = thi - tlo;
        extents += static_cast<double>(std::max({size.x, size.y, size.z}));
    }
    // Cells near the distance and the mean triangle: each triangle then lands in a few cells and
    // a query meets a few triangles, whichever of the two is larger.
    const auto meanExtent = static_cast<float>(extents / static_cast<double>(mTriangles.size()));
    const float span = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) + 2.0f * mDistance;
    mCellSize = std::max({mDistance, meanExtent, span / static_cast<float>(CELLS_PER_AXIS / 2)});
    mOrigin = lo - glm::vec3(mDistance);
    for (std::uint32_t i = 0; i < mTriangles.size(); ++i) {
        const Triangle& t = mTriangles[i];
        const glm::ivec3 from = cellOf(glm::min(glm::min(t[0], t[1]), t[2]) - glm::vec3(mDistance));
        const glm::ivec3 to = cellOf(glm::max(glm::max(t[0], t[1]), t[2]) + glm::vec3(mDistance));
        for (int z = from.z; z <= to.z; ++z)
            for (int y = from.y; y <= to.y; ++y)
                for (int x = from.x; x <= to.x; ++x)
                    mCells[cellKey({x, y, z})].push_back(i);
    }
}

glm::ivec3 ClearanceGrid::cellOf(glm::vec3 p) const {
    const glm::vec3 cell = glm::floor((p - mOrigin) / mCellSize);
    return glm::ivec3(glm::clamp(cell, glm::vec3(-1.0f), glm::vec3(float(CELLS_PER_AXIS - 1))));
}

std::int64_t ClearanceGrid::cellKey(glm::ivec3 cell) const {
    const auto axis = [](int v) { return static_cast<std::int64_t>(v + 1) & 0x1FFFFF; };
    return axis(cell.x) | (axis(cell.y) << 21) | (axis(cell.z) << 42);
}

bool ClearanceGrid::within(glm::vec3 p) const {
    if (empty() || !std::isfinite(p.x + p.y + p.z))
        return false;
    const auto found = mCells.find(cellKey(cellOf(p)));
    if (found == mCells.end())
        return false;
    const float limit = mDistance * mDistance;
    for (const std::uint32_t i : found->second) {
        const Triangle& t = mTriangles[i];
        const glm::vec3 d = p - closestPointOnTriangle(p, t[0], t[1], t[2]);
        if (glm::dot(d, d) < limit)
            return true;
    }
    return false;
}

}  // namespace grass::core
