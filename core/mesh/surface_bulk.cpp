#include "mesh/surface_bulk.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace grass::core {

Bounds surfaceBulkBounds(const SurfaceMesh& mesh, double outside) {
    const Bounds whole = meshBounds(mesh);
    // A triangle's area stands at its corners, a third at each, not at its centroid: a surface of
    // a few large triangles (a wall of two quads) then reaches its edges, where centroids stopped
    // a third of a triangle short of them and the first camera cut the wall off.
    std::vector<std::pair<glm::dvec3, double>> corners;  // corner, a third of its face's area
    corners.reserve(3 * mesh.n_faces());
    double total = 0.0, edges = 0.0;
    std::size_t faces = 0;
    for (const auto fh : mesh.faces()) {
        glm::dvec3 p[3];
        int k = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            const auto& point = mesh.point(vh);
            p[k++] = glm::dvec3(point[0], point[1], point[2]);
        }
        const double area = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
        if (!(area > 0.0) || !std::isfinite(area))
            continue;
        for (const glm::dvec3& corner : p)
            corners.emplace_back(corner, area / 3.0);
        total += area;
        edges += std::sqrt(area);
        ++faces;
    }
    if (corners.empty())
        return whole;
    const double margin = edges / double(faces);
    Bounds bulk;
    for (int axis = 0; axis < 3; ++axis) {
        std::sort(corners.begin(), corners.end(),
                  [axis](const auto& a, const auto& b) { return a.first[axis] < b.first[axis]; });
        const auto quantile = [&](double share) {
            double sum = 0.0;
            for (const auto& [corner, weight] : corners) {
                sum += weight;
                if (sum >= share * total)
                    return corner[axis];
            }
            return corners.back().first[axis];
        };
        bulk.min[axis] = float(std::max(double(whole.min[axis]), quantile(0.5 * outside) - margin));
        bulk.max[axis] = float(std::min(double(whole.max[axis]), quantile(1.0 - 0.5 * outside) + margin));
    }
    return bulk;
}

}  // namespace grass::core
