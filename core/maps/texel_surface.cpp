#include "maps/texel_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "util/assert.h"

namespace grass::core {

namespace {

// As MapImage's loader: past this a map is a mistake.
constexpr int MAX_MAP_SIDE = 16384;
// A texel whose centre is closer than this (L∞, in texels) to a triangle is covered: the reach
// of a bilinear tap (MapImage::sample reads texel centres less than one texel away per axis).
constexpr double MARGIN_TEXELS = 1.0;
// Grid cells are this many mean texels wide: on a surface a cell then holds about 16 texels,
// few enough to test one by one and large enough that a dab visits few empty cells.
constexpr float CELL_TEXELS = 4.0f;

double cross2(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// L∞ distance from p to the triangle (0 inside): the smallest s such that the square of half
// side s around p meets the triangle. By the separating-axis theorem for two convex polygons the
// candidate axes are the square's (x, y) and the triangle's edge normals; along a normal n the
// square reaches s·(|n.x| + |n.y|), so each axis gives a lower bound on s and the largest wins.
double distanceLinf(glm::dvec2 p, const std::array<glm::dvec2, 3>& t, double orientation) {
    const glm::dvec2 lo = glm::min(t[0], glm::min(t[1], t[2]));
    const glm::dvec2 hi = glm::max(t[0], glm::max(t[1], t[2]));
    double d = std::max({0.0, lo.x - p.x, p.x - hi.x, lo.y - p.y, p.y - hi.y});
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 a = t[static_cast<std::size_t>(k)];
        const glm::dvec2 edge = t[static_cast<std::size_t>((k + 1) % 3)] - a;
        // Outward normal: for a counter-clockwise triangle (orientation > 0) it is (y, -x).
        const glm::dvec2 n = orientation * glm::dvec2(edge.y, -edge.x);
        d = std::max(d, glm::dot(n, p - a) / (std::abs(n.x) + std::abs(n.y)));
    }
    return d;
}

}  // namespace

TexelSurface::TexelSurface(const SurfaceMesh& mesh, int width, int height)
    : mWidth(width), mHeight(height) {
    GRASS_ASSERT(width >= 1 && height >= 1 && width <= MAX_MAP_SIDE && height <= MAX_MAP_SIDE);
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    mCovered.assign(count, 0);
    mPosition.assign(count, glm::vec3(0.0f));
    mNormal.assign(count, glm::vec3(0.0f));
    mTexelSize.assign(count, 0.0f);
    // L∞ distance of each texel's current owner; strictly smaller replaces, so ties keep the
    // first triangle.
    std::vector<float> ownerDistance(count, std::numeric_limits<float>::infinity());
    const glm::dvec2 scale(width, height);
    const auto rowLength = static_cast<std::size_t>(width);

    for (const auto fh : mesh.faces()) {
        std::array<glm::dvec2, 3> t;
        std::array<glm::dvec3, 3> p;
        std::array<glm::dvec3, 3> n;
        std::size_t k = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            if (k == 3)
                break;
            t[k] = glm::dvec2(toGlm(mesh.texcoord2D(vh))) * scale;
            p[k] = glm::dvec3(toGlm(mesh.point(vh)));
            n[k] = glm::dvec3(toGlm(mesh.normal(vh)));
            ++k;
        }
        const double area2 = cross2(t[1] - t[0], t[2] - t[0]);
        // Also rejects NaN or infinite UVs (area2 is then NaN).
        if (k != 3 || !(std::abs(area2) > 1e-12) || !std::isfinite(area2))
            continue;
        const glm::dvec3 faceCross = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double faceCrossLength = glm::length(faceCross);
        // World length of one texel step in x and in y: the columns of the triangle's linear map
        // from texel space to 3D, [P1 − P0, P2 − P0] · [t1 − t0, t2 − t0]⁻¹.
        const glm::dvec2 e1 = t[1] - t[0], e2 = t[2] - t[0];
        const glm::dvec3 stepX = ((p[1] - p[0]) * e2.y - (p[2] - p[0]) * e1.y) / area2;
        const glm::dvec3 stepY = ((p[2] - p[0]) * e1.x - (p[1] - p[0]) * e2.x) / area2;
        const auto texelSize = static_cast<float>(std::max(glm::length(stepX), glm::length(stepY)));
        const glm::dvec3 faceNormal =
            faceCrossLength > 0.0 ? faceCross / faceCrossLength : glm::dvec3(0, 1, 0);

        // Texel i's centre i + 0.5 must lie within the margin of [lo.x, hi.x]; clamp in double
        // before converting so far-off UVs cannot overflow an int.
        const glm::dvec2 lo = glm::min(t[0], glm::min(t[1], t[2]));
        const glm::dvec2 hi = glm::max(t[0], glm::max(t[1], t[2]));
        const auto range = [](double a, double b, int size) {
            const double first = std::clamp(std::ceil(a - MARGIN_TEXELS - 0.5), 0.0, size * 1.0);
            const double last = std::clamp(std::floor(b + MARGIN_TEXELS - 0.5), -1.0, size - 1.0);
            return std::array<int, 2>{static_cast<int>(first), static_cast<int>(last)};
        };
        const auto [x0, x1] = range(lo.x, hi.x, width);
        const auto [y0, y1] = range(lo.y, hi.y, height);
        const double orientation = area2 > 0.0 ? 1.0 : -1.0;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const glm::dvec2 c(x + 0.5, y + 0.5);
                const double d = distanceLinf(c, t, orientation);
                const std::size_t index =
                    static_cast<std::size_t>(y) * rowLength + static_cast<std::size_t>(x);
                if (d >= MARGIN_TEXELS || !(d < ownerDistance[index]))
                    continue;
                ownerDistance[index] = static_cast<float>(d);
                // Barycentrics, extrapolated for margin texels (some weight negative).
                const double wa = cross2(t[1] - c, t[2] - c) / area2;
                const double wb = cross2(t[2] - c, t[0] - c) / area2;
                const double wc = 1.0 - wa - wb;
                const glm::dvec3 normal = wa * n[0] + wb * n[1] + wc * n[2];
                const double normalLength = glm::length(normal);
                mCovered[index] = 1;
                mPosition[index] = glm::vec3(wa * p[0] + wb * p[1] + wc * p[2]);
                mNormal[index] =
                    glm::vec3(normalLength > 1e-12 ? normal / normalLength : faceNormal);
                mTexelSize[index] = texelSize;
            }
        }
    }
    buildGrid();
}

void TexelSurface::buildGrid() {
    mCoveredCount = 0;
    double sizeSum = 0.0;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (std::size_t i = 0; i < mCovered.size(); ++i) {
        if (!mCovered[i])
            continue;
        ++mCoveredCount;
        sizeSum += mTexelSize[i];
        lo = glm::min(lo, mPosition[i]);
        hi = glm::max(hi, mPosition[i]);
    }
    if (mCoveredCount == 0)
        return;
    mBounds = Bounds{lo, hi};
    const glm::vec3 extent = hi - lo;
    const float largest = std::max({extent.x, extent.y, extent.z});
    float cell = CELL_TEXELS * static_cast<float>(sizeSum / static_cast<double>(mCoveredCount));
    // A mesh with no 3D area (all texels on one point) still needs a positive cell.
    cell = std::max({cell, largest * 1e-6f, std::numeric_limits<float>::min() * 1e6f});
    // Cap the cell count at a few per texel, so a sparse mesh in a large box cannot make the
    // dense grid outgrow the map.
    const double maxCells = 4.0 * static_cast<double>(mCoveredCount) + 64.0;
    const auto dims = [&](float c) {
        return glm::ivec3(glm::max(glm::vec3(1.0f), glm::ceil(extent / c)));
    };
    while (static_cast<double>(dims(cell).x) * dims(cell).y * dims(cell).z > maxCells)
        cell *= 1.25f;
    mCellSize = cell;
    mGridDims = dims(cell);
    mGridOrigin = lo;

    const auto cellOf = [this](glm::vec3 p) {
        const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((p - mGridOrigin) / mCellSize)),
                                        glm::ivec3(0), mGridDims - 1);
        return static_cast<std::size_t>((c.z * mGridDims.y + c.y) * mGridDims.x + c.x);
    };
    // Counting sort by cell; visiting texels in index order keeps each cell's list ascending.
    const auto cells = static_cast<std::size_t>(mGridDims.x) *
                       static_cast<std::size_t>(mGridDims.y) *
                       static_cast<std::size_t>(mGridDims.z);
    mCellStart.assign(cells + 1, 0);
    for (std::size_t i = 0; i < mCovered.size(); ++i) {
        if (mCovered[i])
            ++mCellStart[cellOf(mPosition[i]) + 1];
    }
    for (std::size_t c = 0; c < cells; ++c)
        mCellStart[c + 1] += mCellStart[c];
    mCellTexels.resize(mCoveredCount);
    std::vector<std::uint32_t> next(mCellStart.begin(), mCellStart.end() - 1);
    for (std::size_t i = 0; i < mCovered.size(); ++i) {
        if (mCovered[i])
            mCellTexels[next[cellOf(mPosition[i])]++] = static_cast<std::uint32_t>(i);
    }
}

void TexelSurface::texelsWithin(glm::vec3 centre, float radiusM,
                                std::vector<std::uint32_t>& out) const {
    out.clear();
    const bool finite = std::isfinite(centre.x) && std::isfinite(centre.y) &&
                        std::isfinite(centre.z) && !std::isnan(radiusM);
    if (mCoveredCount == 0 || !finite || radiusM < 0.0f)
        return;
    const glm::vec3 lo = (centre - radiusM - mGridOrigin) / mCellSize;
    const glm::vec3 hi = (centre + radiusM - mGridOrigin) / mCellSize;
    const glm::vec3 top = glm::vec3(mGridDims);
    if (glm::any(glm::greaterThanEqual(lo, top)) || glm::any(glm::lessThan(hi, glm::vec3(0.0f))))
        return;
    // Clamp in float first: an infinite radius must not reach the int conversion.
    const glm::ivec3 c0(glm::floor(glm::clamp(lo, glm::vec3(0.0f), top - 1.0f)));
    const glm::ivec3 c1(glm::floor(glm::clamp(hi, glm::vec3(0.0f), top - 1.0f)));
    const float r2 = radiusM * radiusM;
    for (int z = c0.z; z <= c1.z; ++z) {
        for (int y = c0.y; y <= c1.y; ++y) {
            const auto row = static_cast<std::size_t>((z * mGridDims.y + y) * mGridDims.x);
            for (std::size_t c = row + static_cast<std::size_t>(c0.x);
                 c <= row + static_cast<std::size_t>(c1.x); ++c) {
                for (std::uint32_t k = mCellStart[c]; k < mCellStart[c + 1]; ++k) {
                    const std::uint32_t texel = mCellTexels[k];
                    const glm::vec3 d = mPosition[texel] - centre;
                    if (glm::dot(d, d) <= r2)
                        out.push_back(texel);
                }
            }
        }
    }
}

std::vector<std::uint32_t> TexelSurface::texelsWithin(glm::vec3 centre, float radiusM) const {
    std::vector<std::uint32_t> out;
    texelsWithin(centre, radiusM, out);
    return out;
}

}  // namespace grass::core
