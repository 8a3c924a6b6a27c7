#include "mesh/procedural.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grass::core {
namespace {

constexpr double PI = 3.14159265358979323846;

ProceduralMeshParams shapeParams(ProceduralShape shape, int resolution) {
    ProceduralMeshParams p;
    p.shape = shape;
    p.resolution = resolution;
    return p;
}

struct Face {
    glm::vec3 a, b, c;
    glm::vec3 normal() const { return glm::cross(b - a, c - a); }
    glm::vec3 centroid() const { return (a + b + c) / 3.0f; }
};

std::vector<Face> faces(const SurfaceMesh& mesh) {
    std::vector<Face> out;
    for (const auto fh : mesh.faces()) {
        std::vector<glm::vec3> p;
        for (const auto vh : mesh.fv_range(fh))
            p.push_back(toGlm(mesh.point(vh)));
        out.push_back({p[0], p[1], p[2]});
    }
    return out;
}

// Finite positions and normals, unit normals, UVs in [0, 1]² on every vertex.
void expectWellFormed(const SurfaceMesh& mesh, const char* shape) {
    ASSERT_GT(mesh.n_faces(), 0u) << shape;
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 p = toGlm(mesh.point(vh)), n = toGlm(mesh.normal(vh));
        const glm::vec2 uv = toGlm(mesh.texcoord2D(vh));
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << shape;
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f) << shape << " vertex " << vh.idx();
        EXPECT_GE(uv.x, 0.0f) << shape;
        EXPECT_LE(uv.x, 1.0f) << shape;
        EXPECT_GE(uv.y, 0.0f) << shape;
        EXPECT_LE(uv.y, 1.0f) << shape;
    }
}

TEST(Procedural, ShapeNamesRoundTrip) {
    for (const std::string_view name : proceduralShapeNames()) {
        const Result<ProceduralShape> shape = parseProceduralShape(name);
        ASSERT_TRUE(shape.ok()) << name;
        EXPECT_EQ(proceduralShapeName(*shape), name);
    }
    const Result<ProceduralShape> bad = parseProceduralShape("cube");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("cube"), std::string::npos);
    EXPECT_NE(bad.error().message.find("moebius"), std::string::npos);
}

TEST(Procedural, EveryShapeIsWellFormed) {
    for (const std::string_view name : proceduralShapeNames()) {
        const SurfaceMesh mesh = makeProceduralMesh(shapeParams(*parseProceduralShape(name), 16));
        expectWellFormed(mesh, std::string(name).c_str());
    }
}

TEST(Procedural, ResolutionIsClamped) {
    const SurfaceMesh tiny = makeProceduralMesh(shapeParams(ProceduralShape::Plane, -5));
    EXPECT_EQ(tiny.n_faces(), 2u);  // one quad
    const SurfaceMesh sphere = makeProceduralMesh(shapeParams(ProceduralShape::Sphere, 0));
    expectWellFormed(sphere, "sphere at resolution 0");  // clamped to 3 segments
    EXPECT_GT(surfaceArea(sphere), 0.0);
}

TEST(Procedural, PlaneAreaIsSideSquared) {
    ProceduralMeshParams p = shapeParams(ProceduralShape::Plane, 8);
    p.size = 7.0f;
    const SurfaceMesh mesh = makeProceduralMesh(p);
    EXPECT_NEAR(surfaceArea(mesh), 49.0, 1e-4);
    for (const Face& f : faces(mesh))
        EXPECT_GT(f.normal().y, 0.0f);  // wound to face +Y
    const Bounds b = meshBounds(mesh);
    EXPECT_NEAR(b.min.x, -3.5f, 1e-6f);
    EXPECT_NEAR(b.max.z, 3.5f, 1e-6f);
}

// A UV sphere is inscribed in the sphere: its area falls short by O(step²). At 64 segments
// (steps of π/64 and 2π/64) the deficit is about 0.2 %; 0.5 % leaves margin.
TEST(Procedural, SphereAreaAndNormalsPointOutward) {
    ProceduralMeshParams p = shapeParams(ProceduralShape::Sphere, 64);
    p.size = 2.0f;
    const SurfaceMesh mesh = makeProceduralMesh(p);
    const double exact = 4.0 * PI * 4.0;
    EXPECT_NEAR(surfaceArea(mesh), exact, 0.005 * exact);
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 pos = toGlm(mesh.point(vh)), n = toGlm(mesh.normal(vh));
        EXPECT_NEAR(glm::length(pos), 2.0f, 1e-5f);
        EXPECT_GT(glm::dot(n, glm::normalize(pos)), 0.999f);
    }
    for (const Face& f : faces(mesh))
        EXPECT_GT(glm::dot(f.normal(), f.centroid()), 0.0f);
}

// Torus area 4π²Rr; the same O(step²) deficit, 0.5 % at 64 × 64.
TEST(Procedural, TorusAreaAndNormalsPointOutward) {
    ProceduralMeshParams p = shapeParams(ProceduralShape::Torus, 64);
    p.size = 3.0f;
    p.minorSize = 0.75f;
    const SurfaceMesh mesh = makeProceduralMesh(p);
    const double exact = 4.0 * PI * PI * 3.0 * 0.75;
    EXPECT_NEAR(surfaceArea(mesh), exact, 0.005 * exact);
    const auto tubeCentre = [](glm::vec3 q) {
        return 3.0f * glm::normalize(glm::vec3(q.x, 0.0f, q.z));
    };
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 pos = toGlm(mesh.point(vh)), n = toGlm(mesh.normal(vh));
        const glm::vec3 out = pos - tubeCentre(pos);
        EXPECT_NEAR(glm::length(out), 0.75f, 1e-5f);
        EXPECT_GT(glm::dot(n, glm::normalize(out)), 0.999f);
    }
    for (const Face& f : faces(mesh))
        EXPECT_GT(glm::dot(f.normal(), f.centroid() - tubeCentre(f.centroid())), 0.0f);
}

// The Möbius strip's area has no closed form: ∫∫ √((R + t cos(u/2))² + t²/4) du dt, here by a
// fine midpoint rule (relative error ~1e-7). The mesh at 128 × 128 is within 0.1 %.
TEST(Procedural, MoebiusAreaMatchesFineReference) {
    ProceduralMeshParams p = shapeParams(ProceduralShape::Moebius, 128);
    p.size = 2.0f;
    p.minorSize = 0.8f;
    const double R = 2.0, w = 0.8;
    const int nu = 4000, nt = 400;
    double reference = 0.0;
    for (int i = 0; i < nu; ++i) {
        const double u = 2.0 * PI * (i + 0.5) / nu;
        for (int j = 0; j < nt; ++j) {
            const double t = -w + 2.0 * w * (j + 0.5) / nt;
            const double r = R + t * std::cos(0.5 * u);
            reference += std::sqrt(r * r + 0.25 * t * t);
        }
    }
    reference *= (2.0 * PI / nu) * (2.0 * w / nt);
    const SurfaceMesh mesh = makeProceduralMesh(p);
    EXPECT_NEAR(surfaceArea(mesh), reference, 0.001 * reference);
    // Face winding agrees with the parametrisation's normals everywhere: one-sided, but
    // consistent away from the seam (which is not welded).
    for (const auto fh : mesh.faces()) {
        glm::vec3 pts[3], normalSum(0.0f);
        int k = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            pts[k++] = toGlm(mesh.point(vh));
            normalSum += toGlm(mesh.normal(vh));
        }
        EXPECT_GT(glm::dot(glm::cross(pts[1] - pts[0], pts[2] - pts[0]), normalSum), 0.0f);
    }
}

TEST(Procedural, HillsHeightMatchesMeshVertices) {
    ProceduralMeshParams p = shapeParams(ProceduralShape::Hills, 48);
    p.hillHeight = 2.0f;
    const SurfaceMesh mesh = makeProceduralMesh(p);
    float lo = 1e9f, hi = -1e9f;
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 pos = toGlm(mesh.point(vh));
        EXPECT_NEAR(pos.y, hillsHeight(p, pos.x, pos.z), 1e-5f);
        // By construction |height| ≤ hillHeight / 2.
        EXPECT_LE(std::abs(pos.y), 1.0f);
        lo = std::min(lo, pos.y);
        hi = std::max(hi, pos.y);
    }
    // Not flat: fractal noise over 2.5 wavelengths spans a good part of the amplitude.
    EXPECT_GT(hi - lo, 0.3f);
}

// The analytic noise derivative gives the vertex normals; check it against central differences.
TEST(Procedural, HillsNormalsMatchHeightGradient) {
    ProceduralMeshParams p = shapeParams(ProceduralShape::Hills, 32);
    p.hillHeight = 3.0f;
    p.hillScale = 2.0f;
    const SurfaceMesh mesh = makeProceduralMesh(p);
    const float e = 1e-3f;
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 pos = toGlm(mesh.point(vh)), n = toGlm(mesh.normal(vh));
        const float dx =
            (hillsHeight(p, pos.x + e, pos.z) - hillsHeight(p, pos.x - e, pos.z)) / (2 * e);
        const float dz =
            (hillsHeight(p, pos.x, pos.z + e) - hillsHeight(p, pos.x, pos.z - e)) / (2 * e);
        const glm::vec3 expected = glm::normalize(glm::vec3(-dx, 1.0f, -dz));
        EXPECT_GT(glm::dot(n, expected), 0.9999f) << "at " << pos.x << ", " << pos.z;
    }
}

TEST(Procedural, HillsDependOnNoiseSeedOnly) {
    ProceduralMeshParams a = shapeParams(ProceduralShape::Hills, 8), b = a;
    b.noiseSeed = a.noiseSeed + 1;
    EXPECT_EQ(hillsHeight(a, 1.3f, -2.1f), hillsHeight(a, 1.3f, -2.1f));
    int differing = 0;
    for (int i = 0; i < 10; ++i) {
        const float x = static_cast<float>(i) * 0.7f - 3.0f;
        if (hillsHeight(a, x, 0.4f * x) != hillsHeight(b, x, 0.4f * x))
            ++differing;
    }
    EXPECT_GE(differing, 9);
    EXPECT_NE(hillsHeight(a, 0.0f, 0.0f), 0.0f);  // no lattice point pinned at the origin
}

}  // namespace
}  // namespace grass::core
