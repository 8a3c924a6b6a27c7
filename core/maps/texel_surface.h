// TexelSurface: where each texel of a W × H map (MapImage, mesh UV space, SPEC §9/§12) lies on
// the mesh in 3D, so brushes can pick texels by world distance instead of UV distance: a dab
// across a UV seam then paints both sides. Positions and normals are in the mesh's world units
// (metres for glTF). Texel (i, j) has index j * width + i, as MapImage::texels; its centre is at
// uv ((i + 0.5) / width, (j + 0.5) / height), row 0 = v 0 = the top of the image.
//
// Coverage. Each triangle is rasterised in texel space. A texel is covered when its centre lies
// within one texel, measured per axis (L∞), of the triangle: exactly the texels a bilinear
// sample (MapImage::sample) taken anywhere on the triangle reads, so sampling at triangle
// borders and seams only mixes painted texels. A texel inside the triangle gets the point under
// its centre; a margin texel gets the triangle's plane extrapolated to its centre (so it lands
// just across the seam, next to the texels the other side paints). A texel several triangles
// cover belongs to the nearest one (inside beats margin); ties, such as centres on a shared edge
// or overlapping UV islands, go to the first triangle in face order. Limitation: with
// overlapping UVs (mirrored islands) the texel sits on the first copy only, so painting the
// other copy does not reach it. UVs outside [0, 1]² are not wrapped: that part is clipped.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/surface_mesh.h"

namespace grass::core {

class TexelSurface {
public:
    TexelSurface() = default;
    // Preconditions (GRASS_ASSERT): width, height in [1, 16384]. Triangles with no UV area are
    // skipped. Linear in texels covered plus triangles.
    TexelSurface(const SurfaceMesh& mesh, int width, int height);

    int width() const { return mWidth; }
    int height() const { return mHeight; }
    std::size_t texelCount() const { return mCovered.size(); }
    std::size_t coveredCount() const { return mCoveredCount; }

    bool isCovered(std::uint32_t texel) const { return mCovered[texel] != 0; }
    // World position and unit normal; (0, 0, 0) for an uncovered texel.
    glm::vec3 position(std::uint32_t texel) const { return mPosition[texel]; }
    glm::vec3 normal(std::uint32_t texel) const { return mNormal[texel]; }
    // The longer side of the texel in world units on its triangle (UV layouts stretch, so the
    // two differ): the reach of a one-texel step, for blur kernels and for padding touched
    // regions. 0 when uncovered.
    float texelSizeM(std::uint32_t texel) const { return mTexelSize[texel]; }
    // Bounds of all covered texel positions.
    const Bounds& bounds() const { return mBounds; }

    // Replaces `out` with the covered texels whose position is within `radiusM` (inclusive) of
    // `centre`, in a fixed order (grid cell, then texel index). A uniform grid keeps this
    // proportional to the texels near the sphere, not to the map. A negative or NaN radius
    // gives none.
    void texelsWithin(glm::vec3 centre, float radiusM, std::vector<std::uint32_t>& out) const;
    std::vector<std::uint32_t> texelsWithin(glm::vec3 centre, float radiusM) const;

private:
    void buildGrid();

    int mWidth = 0;
    int mHeight = 0;
    std::size_t mCoveredCount = 0;
    std::vector<std::uint8_t> mCovered;
    std::vector<glm::vec3> mPosition;
    std::vector<glm::vec3> mNormal;
    std::vector<float> mTexelSize;
    Bounds mBounds;

    // Uniform grid over mBounds in compressed-row form: the texels of cell c are
    // mCellTexels[mCellStart[c] .. mCellStart[c + 1]), ascending.
    glm::vec3 mGridOrigin{0.0f};
    float mCellSize = 1.0f;
    glm::ivec3 mGridDims{0};
    std::vector<std::uint32_t> mCellStart;
    std::vector<std::uint32_t> mCellTexels;
};

}  // namespace grass::core
