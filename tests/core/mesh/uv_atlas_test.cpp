#include "mesh/uv_atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "mesh/gltf_loader.h"
#include "mesh/procedural.h"
#include "mesh/uv_atlas_detail.h"
#include "mesh/uv_atlas_file.h"
#include "support/scratch_folder.h"
#include "support/test_paths.h"
#include "util/rng.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
constexpr float PI = 3.14159265358979f;

// ---- Test meshes, built the way loaders build them (SurfaceMeshBuilder). ----

// Adds triangles by position; `outward` orients each so its normal points away from it.
class MeshMaker {
public:
    std::uint32_t vertex(glm::vec3 p, glm::vec3 n = {0, 1, 0}) {
        return mBuilder.addVertex(p, n, glm::vec2(0.0f));
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mBuilder.addTriangle(a, b, c);
    }
    void outwardTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::vec3 inside) {
        const glm::vec3 pa = position(a), pb = position(b), pc = position(c);
        if (glm::dot(glm::cross(pb - pa, pc - pa), (pa + pb + pc) / 3.0f - inside) < 0.0f)
            std::swap(b, c);
        mBuilder.addTriangle(a, b, c);
    }
    // An n × n quad grid over u, v ∈ [0, 1] mapped by `surface`, wound by the (u, v) order.
    template <class Surface>
    void grid(int nu, int nv, Surface surface) {
        const auto first = static_cast<std::uint32_t>(mBuilder.mesh().n_vertices());
        for (int j = 0; j <= nv; ++j) {
            for (int i = 0; i <= nu; ++i)
                vertex(surface(static_cast<float>(i) / static_cast<float>(nu),
                               static_cast<float>(j) / static_cast<float>(nv)));
        }
        const auto at = [&](int i, int j) {
            return first + static_cast<std::uint32_t>(j * (nu + 1) + i);
        };
        for (int j = 0; j < nv; ++j) {
            for (int i = 0; i < nu; ++i) {
                triangle(at(i, j), at(i, j + 1), at(i + 1, j + 1));
                triangle(at(i, j), at(i + 1, j + 1), at(i + 1, j));
            }
        }
    }
    // A closed UV sphere with single-vertex poles; `bump` scales the radius per direction.
    template <class Bump>
    void sphere(glm::vec3 centre, float radius, int rings, int segments, Bump bump) {
        const auto point = [&](float theta, float phi) {
            const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            return vertex(centre + d * radius * bump(d), d);
        };
        const std::uint32_t north = point(0.0f, 0.0f);
        std::vector<std::uint32_t> ring;
        for (int j = 1; j < rings; ++j) {
            for (int i = 0; i < segments; ++i)
                ring.push_back(
                    point(PI * static_cast<float>(j) / static_cast<float>(rings),
                          2.0f * PI * static_cast<float>(i) / static_cast<float>(segments)));
        }
        const std::uint32_t south = point(PI, 0.0f);
        const auto at = [&](int j, int i) {
            return ring[static_cast<std::size_t>((j - 1) * segments + (i % segments))];
        };
        for (int i = 0; i < segments; ++i) {
            outwardTriangle(north, at(1, i), at(1, i + 1), centre);
            outwardTriangle(south, at(rings - 1, i), at(rings - 1, i + 1), centre);
            for (int j = 1; j + 1 < rings; ++j) {
                outwardTriangle(at(j, i), at(j + 1, i), at(j + 1, i + 1), centre);
                outwardTriangle(at(j, i), at(j + 1, i + 1), at(j, i + 1), centre);
            }
        }
    }
    SurfaceMesh take() { return mBuilder.take(); }

private:
    // From the builder's mesh: it adds vertices of its own for faces OpenMesh refuses.
    glm::vec3 position(std::uint32_t v) {
        return toGlm(mBuilder.mesh().point(mBuilder.mesh().vertex_handle(static_cast<int>(v))));
    }

    SurfaceMeshBuilder mBuilder;
};

float noBump(glm::vec3) {
    return 1.0f;
}

void addGround(MeshMaker& m, float size, int n) {
    m.grid(n, n,
           [&](float u, float v) { return glm::vec3((u - 0.5f) * size, 0.0f, (v - 0.5f) * size); });
}

// A flat 10 m ground with a sphere floating 3 m over it: planar UVs put both on the same texels.
SurfaceMesh sphereOverGround() {
    MeshMaker m;
    addGround(m, 10.0f, 40);
    m.sphere({0.5f, 3.0f, -0.5f}, 1.5f, 16, 32, noBump);
    return m.take();
}

SurfaceMesh uvSphere() {
    MeshMaker m;
    m.sphere({0, 0, 0}, 2.0f, 24, 48, noBump);
    return m.take();
}

// A noisy sphere: normals turn every way, with concave pockets.
SurfaceMesh blob() {
    MeshMaker m;
    m.sphere({0, 0, 0}, 1.0f, 40, 80, [](glm::vec3 d) {
        return 1.0f + 0.3f * std::sin(5.0f * d.x + 1.0f) * std::cos(4.0f * d.z) +
               0.15f * std::sin(9.0f * d.y + 3.0f * d.x);
    });
    return m.take();
}

// Six sides with vertices of their own, as a flat-shaded glTF cube has them.
SurfaceMesh box() {
    MeshMaker m;
    const glm::vec3 half(1.0f, 0.5f, 2.0f);
    for (int axis = 0; axis < 3; ++axis) {
        for (const float side : {-1.0f, 1.0f}) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            m.grid(4, 4, [&](float u, float v) {
                glm::vec3 p(0.0f);
                p[axis] = side * half[axis];
                p[a] = (2.0f * u - 1.0f) * half[a];
                p[b] = (2.0f * v - 1.0f) * half[b];
                return p;
            });
        }
    }
    return m.take();
}

// A plane that turns up into a 70° cliff along x = 0, sharing the crease's vertices.
SurfaceMesh cliff() {
    MeshMaker m;
    const float c = std::cos(70.0f * PI / 180.0f), s = std::sin(70.0f * PI / 180.0f);
    m.grid(30, 20, [&](float u, float v) {
        const float x = u * 8.0f - 5.0f;  // x ≤ 0: plane; beyond: 3 m up the slope
        return x <= 0.0f ? glm::vec3(x, 0.0f, v * 5.0f) : glm::vec3(x * c, x * s, v * 5.0f);
    });
    return m.take();
}

// A spiral ramp of 1.5 turns: every normal is within 15° of up, so one chart by the normal
// cone, but its projection onto the ground overlaps itself; the chart must be split.
SurfaceMesh spiralRamp() {
    MeshMaker m;
    m.grid(120, 6, [](float u, float v) {
        const float angle = u * 3.0f * PI, radius = 1.0f + v;
        return glm::vec3(radius * std::cos(angle), 0.25f * angle, radius * std::sin(angle));
    });
    return m.take();
}

// The same grid twice (two glTF primitives with the same geometry): faces weld onto each other
// and overlap exactly in any projection.
SurfaceMesh doubledGround() {
    MeshMaker m;
    addGround(m, 4.0f, 6);
    addGround(m, 4.0f, 6);
    return m.take();
}

// ---- Independent checks of an atlas. ----

struct Island {
    double areaUv = 0.0;
    double area3d = 0.0;
};

// Faces joined by bitwise-equal corner UVs: the generator gives every corner of one vertex in a
// chart the same UV, so an island is a chart (or part of one); nothing here asks the generator.
std::vector<std::uint32_t> islandsOf(const CornerUvs& uvs) {
    std::vector<std::uint32_t> parent(uvs.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t f) {
        while (parent[f] != f)
            f = parent[f] = parent[parent[f]];
        return f;
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
    for (std::uint32_t f = 0; f < uvs.size(); ++f) {
        for (const glm::vec2 uv : uvs[f])
            keys.emplace_back(std::uint64_t{std::bit_cast<std::uint32_t>(uv.x)} << 32 |
                                  std::bit_cast<std::uint32_t>(uv.y),
                              f);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i) {
        if (keys[i].first == keys[i - 1].first)
            parent[find(keys[i].second)] = find(keys[i - 1].second);
    }
    for (std::uint32_t f = 0; f < uvs.size(); ++f)
        parent[f] = find(f);
    return parent;
}

double pointSegmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double t =
        glm::dot(ab, ab) > 0.0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

bool inside(glm::dvec2 p, const std::array<glm::vec2, 3>& t) {
    double sign[3];
    for (std::size_t i = 0; i < 3; ++i) {
        const glm::dvec2 a = t[i], b = t[(i + 1) % 3];
        sign[i] = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    }
    return (sign[0] >= 0 && sign[1] >= 0 && sign[2] >= 0) ||
           (sign[0] <= 0 && sign[1] <= 0 && sign[2] <= 0);
}

// Distance between two UV triangles, 0 when they touch or overlap.
double triangleDistance(const std::array<glm::vec2, 3>& s, const std::array<glm::vec2, 3>& t) {
    if (inside(s[0], t) || inside(t[0], s))
        return 0.0;
    double best = INFINITY;
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            const glm::dvec2 a = s[i], b = s[(i + 1) % 3], c = t[j], d = t[(j + 1) % 3];
            const auto side = [](glm::dvec2 o, glm::dvec2 p, glm::dvec2 q) {
                return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
            };
            if (side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0)
                return 0.0;
            best = std::min({best, pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
                             pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)});
        }
    }
    return best;
}

// The smallest distance between triangles of different islands, up to `limit` (closer pairs
// are searched by sweeping boxes grown by `limit` along u).
double closestIslands(const CornerUvs& uvs, const std::vector<std::uint32_t>& island,
                      double limit) {
    struct Box {
        glm::vec2 lo, hi;
        std::uint32_t face;
    };
    std::vector<Box> boxes;
    for (std::uint32_t f = 0; f < uvs.size(); ++f) {
        const auto& t = uvs[f];
        boxes.push_back(
            {glm::min(glm::min(t[0], t[1]), t[2]), glm::max(glm::max(t[0], t[1]), t[2]), f});
    }
    std::sort(boxes.begin(), boxes.end(),
              [](const Box& a, const Box& b) { return a.lo.x < b.lo.x; });
    double closest = limit;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lo.x <= boxes[i].hi.x + limit;
             ++j) {
            const Box& a = boxes[i];
            const Box& b = boxes[j];
            if (island[a.face] == island[b.face] || b.lo.y > a.hi.y + limit ||
                a.lo.y > b.hi.y + limit)
                continue;
            closest = std::min(closest, triangleDistance(uvs[a.face], uvs[b.face]));
        }
    }
    return closest;
}

// Texel density (UV area / 3D area) max over min among islands holding ≥ 1% of the surface.
double islandDensityRatio(const SurfaceMesh& mesh, const CornerUvs& uvs,
                          const std::vector<std::uint32_t>& island) {
    std::vector<Island> islands(uvs.size());
    double total = 0.0;
    for (const auto fh : mesh.faces()) {
        const auto f = static_cast<std::size_t>(fh.idx());
        const auto p = facePositions(mesh, fh);
        const glm::dvec3 a = p[0], b = p[1], c = p[2];
        const glm::dvec2 u0 = uvs[f][0], u1 = uvs[f][1], u2 = uvs[f][2];
        const glm::dvec2 e1 = u1 - u0, e2 = u2 - u0;
        islands[island[f]].area3d += 0.5 * glm::length(glm::cross(b - a, c - a));
        islands[island[f]].areaUv += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    double lo = INFINITY, hi = 0.0;
    for (const Island& i : islands) {
        if (i.area3d >= 0.01 * total) {
            lo = std::min(lo, i.areaUv / i.area3d);
            hi = std::max(hi, i.areaUv / i.area3d);
        }
    }
    return hi >= lo ? hi / lo : 1.0;  // 1 when no island holds 1%
}

// Texel density: every face lies within the 60° cone of the normal its chart is projected along,
// so a chart keeps between cos 60° = 0.5 and 1 of its area and no ratio can pass 2. Measured on
// the meshes here: at most 1.30 (the procedural sphere: caps lose most at their rim), bunny 1.13,
// blob 1.17. 1.5 leaves 15% over the worst and fails an atlas that flattens charts worse than a
// 60° cap would.
constexpr double DENSITY_RATIO_MAX = 1.5;

struct AtlasCheck {
    AtlasStats stats;
    CornerUvs uvs;
};

// Generates an atlas and checks it from outside: no overlaps, no degenerate or outside faces,
// gutters between islands, UVs that survive withCornerUvs, even texel density.
AtlasCheck checkAtlas(const SurfaceMesh& mesh, const std::string& name,
                      const AtlasParams& params = {}) {
    AtlasCheck check;
    check.uvs = generateUvAtlas(mesh, params, &check.stats);
    EXPECT_EQ(check.uvs.size(), mesh.n_faces()) << name;
    const UvOverlapReport report = findUvOverlaps(check.uvs, mesh);
    EXPECT_EQ(report.overlappingPairs, 0u) << name;
    EXPECT_EQ(report.degenerateFaces, 0u) << name;
    EXPECT_EQ(report.outsideUnitSquare, 0u) << name;
    EXPECT_TRUE(report.paintable()) << name;
    EXPECT_EQ(check.stats.gutterTexels, static_cast<double>(params.gutterTexels))
        << name << ": gutter had to shrink";
    const double gutter = params.gutterTexels / static_cast<double>(params.resolution);
    // 1e-6: float UVs near 1 round by 6e-8; a gutter is 2e-3.
    const std::vector<std::uint32_t> island = islandsOf(check.uvs);
    EXPECT_GE(closestIslands(check.uvs, island, 2.0 * gutter), gutter - 1e-6) << name;
    // Islands are the charts seen from outside: fewer islands than charts would mean two charts
    // touch (share a corner UV), which the distance between islands cannot show.
    std::vector<std::uint32_t> roots = island;
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    EXPECT_EQ(roots.size(), check.stats.charts) << name;
    EXPECT_EQ(cornerUvsOf(withCornerUvs(mesh, check.uvs)), check.uvs) << name;
    EXPECT_LE(check.stats.texelDensityRatio, DENSITY_RATIO_MAX) << name;
    EXPECT_LE(islandDensityRatio(mesh, check.uvs, island), DENSITY_RATIO_MAX * 1.001) << name;
    // The atlas must leave room to paint: a packer that shrank everything would pass the rest.
    // Measured: 0.32 at least (Möbius strip, spiral ramp: long curved charts), most over 0.4.
    double covered = 0.0;
    for (const auto& t : check.uvs) {
        const glm::dvec2 e1 = glm::dvec2(t[1]) - glm::dvec2(t[0]);
        const glm::dvec2 e2 = glm::dvec2(t[2]) - glm::dvec2(t[0]);
        covered += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
    }
    EXPECT_GT(covered, 0.25) << name;
    EXPECT_NEAR(check.stats.uvCoverage, covered, 1e-4) << name;
    return check;
}

// Large inputs search on the shared pool's threads in runs (atlas::countOverlaps); the pairs
// come out as one thread finds them, and the cap cuts them where one thread stops. 300,000
// triangles in a grid of cells, each cell's two triangles laid on the same UVs: exactly the
// pairs (2i, 2i + 1) overlap.
TEST(UvOverlaps, ALargeSearchOnThreadsFindsThePairsInTheSerialOrder) {
    constexpr std::uint32_t PAIRS = 150'000, SIDE = 388;  // 388² cells ≥ PAIRS
    std::vector<atlas::Triangle2> triangles;
    triangles.reserve(2 * PAIRS);
    for (std::uint32_t i = 0; i < PAIRS; ++i) {
        const glm::dvec2 cell(double(i % SIDE) / SIDE, double(i / SIDE) / SIDE);
        const double h = 0.8 / SIDE;
        const atlas::Triangle2 t{cell, cell + glm::dvec2(h, 0.0), cell + glm::dvec2(0.0, h)};
        triangles.push_back(t);
        triangles.push_back(t);
    }
    const std::vector<char> active(triangles.size(), 1);
    std::vector<atlas::OverlapPair> pairs;
    EXPECT_EQ(atlas::countOverlaps(triangles, active, 1e-9, UV_OVERLAP_CAP, &pairs), PAIRS);
    ASSERT_EQ(pairs.size(), PAIRS);
    for (std::uint32_t i = 0; i < PAIRS; ++i) {
        ASSERT_EQ(pairs[i].a, 2 * i) << "pair " << i;
        ASSERT_EQ(pairs[i].b, 2 * i + 1) << "pair " << i;
    }
    // Capped: the first pairs, as a single thread would stop, whichever run found them.
    std::vector<atlas::OverlapPair> first;
    EXPECT_EQ(atlas::countOverlaps(triangles, active, 1e-9, 100'000, &first), 100'000u);
    ASSERT_EQ(first.size(), 100'000u);
    EXPECT_EQ(first.back().a, 2u * 99'999u);
    // A stop requested ends every run before its first triangle: nothing is counted (the
    // caller, who asked, throws the count away).
    std::stop_source source;
    source.request_stop();
    EXPECT_EQ(
        atlas::countOverlaps(triangles, active, 1e-9, UV_OVERLAP_CAP, nullptr, source.get_token()),
        0u);
}

// ---- findUvOverlaps ----

// Two triangles far apart in 3D (non-zero area), for UV cases.
SurfaceMesh twoTriangles() {
    MeshMaker m;
    m.triangle(m.vertex({0, 0, 0}), m.vertex({1, 0, 0}), m.vertex({0, 0, 1}));
    m.triangle(m.vertex({5, 0, 0}), m.vertex({6, 0, 0}), m.vertex({5, 0, 1}));
    return m.take();
}

UvOverlapReport reportFor(std::array<glm::vec2, 3> a, std::array<glm::vec2, 3> b) {
    return findUvOverlaps({a, b}, twoTriangles());
}

TEST(UvAtlas, TrianglesSharingAnEdgeDoNotOverlap) {
    const UvOverlapReport r =
        reportFor({{{0, 0}, {0.5f, 0}, {0, 0.5f}}}, {{{0.5f, 0}, {0.5f, 0.5f}, {0, 0.5f}}});
    EXPECT_EQ(r.overlappingPairs, 0u);
    EXPECT_TRUE(r.paintable());
    // Touching at one corner only.
    EXPECT_EQ(reportFor({{{0, 0}, {0.5f, 0}, {0, 0.5f}}}, {{{0.5f, 0}, {1, 0}, {1, 0.5f}}})
                  .overlappingPairs,
              0u);
}

TEST(UvAtlas, PartlyOverlappingTrianglesAreOnePair) {
    EXPECT_EQ(reportFor({{{0, 0}, {0.5f, 0}, {0, 0.5f}}}, {{{0.2f, 0}, {0.7f, 0}, {0.2f, 0.5f}}})
                  .overlappingPairs,
              1u);
    // Crossing like a star of David: no vertex of either inside the other.
    EXPECT_EQ(reportFor({{{0.5f, 0.1f}, {0.9f, 0.8f}, {0.1f, 0.8f}}},
                        {{{0.5f, 0.95f}, {0.1f, 0.25f}, {0.9f, 0.25f}}})
                  .overlappingPairs,
              1u);
}

TEST(UvAtlas, TriangleInsideAnotherIsOnePair) {
    EXPECT_EQ(reportFor({{{0, 0}, {1, 0}, {0, 1}}}, {{{0.1f, 0.1f}, {0.3f, 0.1f}, {0.1f, 0.3f}}})
                  .overlappingPairs,
              1u);
}

TEST(UvAtlas, ReportsDegenerateAndOutsideFaces) {
    // Collinear UVs on a face with 3D area: it would get no texels.
    const UvOverlapReport line =
        reportFor({{{0, 0}, {0.5f, 0}, {0, 0.5f}}}, {{{0.6f, 0.6f}, {0.7f, 0.7f}, {0.8f, 0.8f}}});
    EXPECT_EQ(line.degenerateFaces, 1u);
    EXPECT_EQ(line.overlappingPairs, 0u);
    EXPECT_FALSE(line.paintable());
    const UvOverlapReport tiled =
        reportFor({{{0, 0}, {0.5f, 0}, {0, 0.5f}}}, {{{2.0f, 0}, {3.0f, 0}, {2.0f, 1.0f}}});
    EXPECT_EQ(tiled.outsideUnitSquare, 1u);
    EXPECT_EQ(tiled.overlappingPairs, 0u);
}

TEST(UvAtlas, OverlapCountStopsAtCap) {
    // 1500 faces on the same UV triangle: 1.1 million pairs, more than the cap.
    MeshMaker m;
    for (int i = 0; i < 1500; ++i) {
        const auto x = static_cast<float>(i);
        m.triangle(m.vertex({x, 0, 0}), m.vertex({x + 1, 0, 0}), m.vertex({x, 0, 1}));
    }
    const SurfaceMesh mesh = m.take();
    const CornerUvs uvs(mesh.n_faces(),
                        {glm::vec2(0.1f, 0.1f), glm::vec2(0.9f, 0.1f), glm::vec2(0.1f, 0.9f)});
    EXPECT_EQ(findUvOverlaps(uvs, mesh).overlappingPairs, UV_OVERLAP_CAP);
}

// ---- generateUvAtlas ----

TEST(UvAtlas, PlanarUvsOverlapAndTheAtlasDoesNot) {
    SurfaceMesh mesh = sphereOverGround();
    generatePlanarUVs(mesh);
    const UvOverlapReport planar = findUvOverlaps(cornerUvsOf(mesh), mesh);
    EXPECT_GT(planar.overlappingPairs, 1000u);  // the sphere's two halves and the ground
    EXPECT_FALSE(planar.paintable());

    const AtlasCheck atlas = checkAtlas(mesh, "sphere over ground");
    const SurfaceMesh fixed = withCornerUvs(mesh, atlas.uvs);
    EXPECT_TRUE(findUvOverlaps(cornerUvsOf(fixed), fixed).paintable());
}

TEST(UvAtlas, NoOverlapOnTestShapes) {
    checkAtlas(uvSphere(), "sphere");
    checkAtlas(blob(), "blob");
    checkAtlas(box(), "box");
    // Steep noisy terrain: projections fold behind ridges, so charts lose faces at fault.
    ProceduralMeshParams rough;
    rough.shape = ProceduralShape::Hills;
    rough.size = 50.0f;
    rough.hillHeight = 8.0f;
    rough.resolution = 96;
    checkAtlas(makeProceduralMesh(rough), "rough hills");
    const AtlasCheck c = checkAtlas(cliff(), "cliff");
    // The 70° crease is past the 60° cone: the plane and the cliff cannot share a chart.
    EXPECT_GE(c.stats.charts, 2u);
}

TEST(UvAtlas, SplitsAChartWhoseProjectionOverlapsItself) {
    const AtlasCheck ramp = checkAtlas(spiralRamp(), "spiral ramp");
    EXPECT_GE(ramp.stats.charts, 2u);
    checkAtlas(doubledGround(), "doubled ground");
}

TEST(UvAtlas, NoOverlapOnProceduralMeshes) {
    for (const std::string_view name : proceduralShapeNames()) {
        ProceduralMeshParams params;
        params.shape = *parseProceduralShape(name);
        checkAtlas(makeProceduralMesh(params), std::string(name));
    }
}

TEST(UvAtlas, NoOverlapOnHeldGltfFiles) {
    std::vector<fs::path> files;
    for (const char* folder : {"projects", "tests/data"}) {
        for (const auto& entry : fs::recursive_directory_iterator(test::sourceDir() / folder)) {
            const std::string ext = entry.path().extension().string();
            if (entry.is_regular_file() && (ext == ".glb" || ext == ".gltf"))
                files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    int checked = 0;
    for (const fs::path& file : files) {
        // Some held files are broken on purpose (loader tests); those have nothing to check.
        const Result<GltfImport> import = loadGltf(file);
        // Over 300k faces would take most of CI's time budget for this file.
        if (!import.ok() || import->mesh->n_faces() > 300'000)
            continue;
        checkAtlas(import->mesh, file.string());
        ++checked;
    }
    EXPECT_GE(checked, 3);
}

TEST(UvAtlas, TriangleSoupPacksWithoutOverlap) {
    // Random triangles that share no vertex: every one is a chart, with gutters between them.
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
        Rng rng(seed);
        MeshMaker m;
        for (int i = 0; i < 400; ++i) {
            const glm::vec3 c(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
            const auto corner = [&] {
                return c + glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            };
            m.triangle(m.vertex(corner()), m.vertex(corner()), m.vertex(corner()));
        }
        const AtlasCheck c = checkAtlas(m.take(), "soup seed " + std::to_string(seed));
        EXPECT_EQ(c.stats.charts, 400u) << "seed " << seed;
    }
}

TEST(UvAtlas, WiderGutterIsKept) {
    AtlasParams params;
    params.resolution = 256;
    params.gutterTexels = 4;
    checkAtlas(sphereOverGround(), "sphere over ground, 4 texels at 256", params);
}

TEST(UvAtlas, ConePastEdgeOnStillPaintable) {
    // Cones of 120° would take faces seen edge-on or from behind; those go to other charts.
    AtlasParams params;
    params.chartAngleDeg = 120.0f;
    const SurfaceMesh mesh = blob();
    AtlasStats stats;
    const UvOverlapReport report = findUvOverlaps(generateUvAtlas(mesh, params, &stats), mesh);
    EXPECT_TRUE(report.paintable())
        << report.overlappingPairs << " overlapping, " << report.degenerateFaces << " degenerate";
    EXPECT_GE(stats.charts, 2u);
}

TEST(UvAtlas, HandlesEmptyAndZeroAreaMeshes) {
    EXPECT_TRUE(generateUvAtlas(SurfaceMesh{}, {}).empty());
    EXPECT_TRUE(findUvOverlaps({}, SurfaceMesh{}).paintable());
    // Collinear corners and a triangle of one repeated position: no normal, no area.
    MeshMaker m;
    m.triangle(m.vertex({0, 0, 0}), m.vertex({1, 0, 0}), m.vertex({2, 0, 0}));
    m.triangle(m.vertex({3, 3, 3}), m.vertex({3, 3, 3}), m.vertex({3, 3, 3}));
    const SurfaceMesh flat = m.take();
    const CornerUvs uvs = generateUvAtlas(flat, {});
    ASSERT_EQ(uvs.size(), 2u);
    const UvOverlapReport report = findUvOverlaps(uvs, flat);
    EXPECT_TRUE(report.paintable());
}

TEST(UvAtlas, IsDeterministic) {
    const SurfaceMesh mesh = blob();
    AtlasStats a, b;
    EXPECT_EQ(generateUvAtlas(mesh, {}, &a), generateUvAtlas(mesh, {}, &b));
    EXPECT_EQ(a, b);
}

TEST(UvAtlas, WithCornerUvsKeepsFacesAndUvs) {
    MeshMaker m;
    addGround(m, 2.0f, 3);
    // A fin: a third face on one edge, which OpenMesh refuses and the builder separates.
    const std::uint32_t a = m.vertex({0, 0, 0}), b = m.vertex({1, 0, 0});
    m.triangle(a, b, m.vertex({0, 1, 0}));
    m.triangle(b, a, m.vertex({0, -1, 0}));
    m.triangle(a, b, m.vertex({0, 0, 1}));
    m.sphere({0, 2, 0}, 0.5f, 6, 8, noBump);
    const SurfaceMesh mesh = m.take();
    const CornerUvs uvs = generateUvAtlas(mesh, {});
    const SurfaceMesh out = withCornerUvs(mesh, uvs);
    ASSERT_EQ(out.n_faces(), mesh.n_faces());
    EXPECT_EQ(cornerUvsOf(out), uvs);
    std::vector<std::pair<int, std::uint64_t>> distinct;  // (source vertex, UV bits) per corner
    for (const auto fh : mesh.faces()) {
        const auto fo = out.face_handle(fh.idx());
        EXPECT_EQ(facePositions(out, fo), facePositions(mesh, fh)) << "face " << fh.idx();
        auto source = mesh.cfv_begin(fh);
        for (const auto vh : out.fv_range(fo)) {
            EXPECT_EQ(toGlm(out.normal(vh)), toGlm(mesh.normal(*source)));
            const glm::vec2 uv = toGlm(out.texcoord2D(vh));
            distinct.emplace_back(source->idx(),
                                  std::uint64_t{std::bit_cast<std::uint32_t>(uv.x)} << 32 |
                                      std::bit_cast<std::uint32_t>(uv.y));
            ++source;
        }
    }
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    // One vertex per (vertex, UV) the corners use, plus the builder's copies for refused faces.
    EXPECT_GE(out.n_vertices(), distinct.size());
    EXPECT_LE(out.n_vertices(), distinct.size() + 3);
    EXPECT_GT(out.n_vertices(), mesh.n_vertices());  // chart seams split vertices
}

// ---- The atlas file ----

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
}

testing::AssertionResult failsWith(const Result<CornerUvs>& result, const fs::path& file,
                                   const std::string& part) {
    if (result.ok())
        return testing::AssertionFailure() << "loaded, but should not have";
    const std::string message = result.error().str();
    if (message.find(part) == std::string::npos ||
        message.find(file.filename().string()) == std::string::npos)
        return testing::AssertionFailure()
               << "\"" << message << "\" does not name the file and \"" << part << "\"";
    return testing::AssertionSuccess();
}

TEST(UvAtlasFile, RoundTripsExactly) {
    const test::ScratchFolder folder("uv-atlas-round-trip");
    const SurfaceMesh mesh = box();
    const CornerUvs uvs = generateUvAtlas(mesh, {});
    const fs::path file = folder / "mesh.uvatlas";
    ASSERT_TRUE(saveUvAtlas(file, uvs, meshFingerprint(mesh)).ok());
    EXPECT_EQ(fs::file_size(file), 20u + 24u * mesh.n_faces());
    const Result<CornerUvs> loaded = loadUvAtlas(file, mesh);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    EXPECT_EQ(*loaded, uvs);
}

TEST(UvAtlasFile, RefusesBrokenFiles) {
    const test::ScratchFolder folder("uv-atlas-broken");
    const SurfaceMesh mesh = box();
    const CornerUvs uvs = generateUvAtlas(mesh, {});
    const fs::path good = folder / "good.uvatlas";
    ASSERT_TRUE(saveUvAtlas(good, uvs, meshFingerprint(mesh)).ok());
    const std::string bytes = readBytes(good);

    EXPECT_TRUE(failsWith(loadUvAtlas(folder / "missing.uvatlas", mesh), folder / "missing.uvatlas",
                          "missing.uvatlas"));

    std::string magic = bytes;
    magic[5] = 'X';
    writeBytes(folder / "magic.uvatlas", magic);
    EXPECT_TRUE(failsWith(loadUvAtlas(folder / "magic.uvatlas", mesh), folder / "magic.uvatlas",
                          "bad magic"));

    writeBytes(folder / "short.uvatlas", bytes.substr(0, bytes.size() - 5));
    EXPECT_TRUE(failsWith(loadUvAtlas(folder / "short.uvatlas", mesh), folder / "short.uvatlas",
                          "truncated"));
    writeBytes(folder / "header.uvatlas", bytes.substr(0, 12));
    EXPECT_TRUE(failsWith(loadUvAtlas(folder / "header.uvatlas", mesh), folder / "header.uvatlas",
                          "truncated"));

    std::string nan = bytes;
    const std::uint32_t quietNan = 0x7FC00000u;
    for (int i = 0; i < 4; ++i)
        nan[20 + 8 * 3 + static_cast<std::size_t>(i)] = static_cast<char>(quietNan >> (8 * i));
    writeBytes(folder / "nan.uvatlas", nan);
    EXPECT_TRUE(failsWith(loadUvAtlas(folder / "nan.uvatlas", mesh), folder / "nan.uvatlas",
                          "face 1 corner 0: UV is not finite"));
}

TEST(UvAtlasFile, RefusesAnAtlasOfAnotherMesh) {
    const test::ScratchFolder folder("uv-atlas-mesh-changed");
    const SurfaceMesh mesh = box();
    const fs::path file = folder / "box.uvatlas";
    ASSERT_TRUE(saveUvAtlas(file, generateUvAtlas(mesh, {}), meshFingerprint(mesh)).ok());
    // Another face count.
    EXPECT_TRUE(failsWith(loadUvAtlas(file, uvSphere()), file, "mesh changed"));
    // The same faces, one corner moved 1% of the box.
    SurfaceMesh moved = box();
    const auto vh = moved.vertex_handle(7);
    moved.set_point(vh, moved.point(vh) + OpenMesh::Vec3f(0.04f, 0.0f, 0.0f));
    ASSERT_EQ(moved.n_faces(), mesh.n_faces());
    EXPECT_NE(meshFingerprint(moved), meshFingerprint(mesh));
    EXPECT_TRUE(failsWith(loadUvAtlas(file, moved), file, "mesh changed"));
    EXPECT_EQ(meshFingerprint(box()), meshFingerprint(mesh));
}

}  // namespace
}  // namespace grass::core
