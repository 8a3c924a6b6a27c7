// Compressed glTF geometry (issue 26 item 3): KHR_draco_mesh_compression and
// EXT_meshopt_compression copies of a mesh decode to the triangles of the uncompressed file
// (Draco within its quantisation, meshopt exactly), and broken compressed data is refused with
// the file and the extension named.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/gltf_loader.h"
#include "mesh/gltf_view.h"
#include "support/compressed_gltf.h"
#include "support/gltf_load_expect.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

GltfImport load(const fs::path& file) { return test::loadGltfExpectingSuccess(file); }

std::string loadError(const fs::path& file) { return test::loadGltfError(file); }

struct Corner {
    glm::vec3 position, normal;
    glm::vec2 uv;
};
using Triangle = std::array<Corner, 3>;

std::vector<Triangle> triangles(const SurfaceMesh& mesh) {
    std::vector<Triangle> out;
    for (const auto fh : mesh.faces()) {
        Triangle t;
        int k = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            const auto p = mesh.point(vh), n = mesh.normal(vh);
            const auto uv = mesh.texcoord2D(vh);
            t[std::size_t(k++)] = {{p[0], p[1], p[2]}, {n[0], n[1], n[2]}, {uv[0], uv[1]}};
        }
        out.push_back(t);
    }
    return out;
}

// Every triangle of `expected` is in `actual` (same corners in the same cyclic order, so the
// same winding) within the tolerances, and the counts agree.
void expectSameTriangles(const SurfaceMesh& expected, const SurfaceMesh& actual, float position,
                         float normal, float uv) {
    const std::vector<Triangle> a = triangles(expected), b = triangles(actual);
    ASSERT_EQ(a.size(), b.size());
    const auto close = [&](const Corner& x, const Corner& y) {
        return glm::distance(x.position, y.position) <= position &&
               glm::distance(x.normal, y.normal) <= normal && glm::distance(x.uv, y.uv) <= uv;
    };
    for (std::size_t i = 0; i < a.size(); ++i) {
        bool found = false;
        for (const Triangle& t : b)
            for (int shift = 0; shift < 3 && !found; ++shift)
                found = close(a[i][0], t[std::size_t(shift)]) && close(a[i][1], t[std::size_t((shift + 1) % 3)]) &&
                        close(a[i][2], t[std::size_t((shift + 2) % 3)]);
        EXPECT_TRUE(found) << "triangle " << i << " is not in the decoded mesh";
    }
}

// A box of 24 vertices (a normal and UVs per face), 4 × 2 × 3 m, off the origin.
test::GltfPrimitive box() {
    return test::boxPrimitive({1.0f, -0.5f, 2.0f}, {5.0f, 1.5f, 5.0f});
}

TEST(GltfCompressed, DracoDecodesToTheSameTrianglesWithinItsQuantisation) {
    const fs::path dir = test::scratchDir("gltf_draco");
    test::writeGltf(dir / "plain.gltf", test::singleMeshAsset(box()));
    const int bits = 14;
    test::writeGltf(dir / "draco.gltf", test::dracoDocument(box(), bits));
    test::writeGltf(dir / "draco.glb", test::dracoDocument(box(), bits), test::BufferStorage::Glb);
    const GltfImport plain = load(dir / "plain.gltf");
    // Quantisation: the box's largest side (4 m) in 2^14 steps, half a step off at most per
    // axis; normals at 10 bits, UVs at 12.
    const float step = 4.0f / float((1 << bits) - 1);
    for (const char* name : {"draco.gltf", "draco.glb"}) {
        SCOPED_TRACE(name);
        const GltfImport draco = load(dir / name);
        EXPECT_TRUE(draco.hasNormals);
        EXPECT_TRUE(draco.hasUv);
        expectSameTriangles(plain.mesh, draco.mesh, std::sqrt(3.0f) * step, 4e-3f, 1e-3f);
    }
}

TEST(GltfCompressed, MeshoptDecodesToTheSameTriangles) {
    const fs::path dir = test::scratchDir("gltf_meshopt");
    test::writeGltf(dir / "plain.gltf", test::singleMeshAsset(box()));
    test::writeGltf(dir / "meshopt.gltf", test::meshoptDocument(box()));
    test::writeGltf(dir / "meshopt.glb", test::meshoptDocument(box()), test::BufferStorage::Glb);
    test::writeGltf(dir / "octahedral.gltf", test::meshoptDocument(box(), true));
    const GltfImport plain = load(dir / "plain.gltf");
    for (const char* name : {"meshopt.gltf", "meshopt.glb"}) {
        SCOPED_TRACE(name);
        // The codecs are lossless: exactly the same triangles.
        expectSameTriangles(plain.mesh, load(dir / name).mesh, 0.0f, 0.0f, 0.0f);
    }
    // Normals through the octahedral filter at 16 bits: within 1e-4 of unit length and place.
    expectSameTriangles(plain.mesh, load(dir / "octahedral.gltf").mesh, 0.0f, 1e-4f, 0.0f);
    // The stock viewer's reader decodes the same way.
    auto view = loadGltfView(dir / "meshopt.glb", 1000);
    ASSERT_TRUE(view.ok()) << view.error().str();
    EXPECT_EQ(view->indices.size(), 3 * plain.mesh->n_faces());
}

TEST(GltfCompressed, BrokenDracoIsRefusedByName) {
    const fs::path dir = test::scratchDir("gltf_draco_broken");
    test::GltfDocument truncated = test::dracoDocument(box());
    truncated.json["bufferViews"][0]["byteLength"] = 10;
    test::writeGltf(dir / "truncated.gltf", truncated);
    const std::string message = loadError(dir / "truncated.gltf");
    EXPECT_NE(message.find("KHR_draco_mesh_compression) cannot be decoded"), std::string::npos) << message;

    test::GltfDocument miscounted = test::dracoDocument(box());
    const std::size_t count = miscounted.json["accessors"][0]["count"].get<std::size_t>();
    miscounted.json["accessors"][0]["count"] = count + 1;
    test::writeGltf(dir / "miscounted.gltf", miscounted);
    EXPECT_NE(loadError(dir / "miscounted.gltf").find("but its POSITION accessor says " + std::to_string(count + 1)),
              std::string::npos);

    test::GltfDocument unknownId = test::dracoDocument(box());
    unknownId.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]
                  ["NORMAL"] = 77;
    test::writeGltf(dir / "unknown_id.gltf", unknownId);
    EXPECT_NE(loadError(dir / "unknown_id.gltf").find("NORMAL (id 77) is not in the compressed data"),
              std::string::npos);
}

TEST(GltfCompressed, BrokenMeshoptIsRefusedByName) {
    const fs::path dir = test::scratchDir("gltf_meshopt_broken");
    const auto extension = [](test::GltfDocument& doc, std::size_t view) -> nlohmann::json& {
        return doc.json["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
    };
    test::GltfDocument shortData = test::meshoptDocument(box());
    extension(shortData, 0)["byteLength"] = 3;
    test::writeGltf(dir / "short.gltf", shortData);
    EXPECT_NE(loadError(dir / "short.gltf").find("bufferView 0 (EXT_meshopt_compression) holds data "
                                                "meshoptimizer cannot decode"),
              std::string::npos);

    test::GltfDocument badMode = test::meshoptDocument(box());
    extension(badMode, 0)["mode"] = "VERTICES";
    test::writeGltf(dir / "mode.gltf", badMode);
    EXPECT_NE(loadError(dir / "mode.gltf").find("mode \"VERTICES\""), std::string::npos);

    test::GltfDocument pastEnd = test::meshoptDocument(box());
    extension(pastEnd, 1)["byteOffset"] = 1u << 30;
    test::writeGltf(dir / "past.gltf", pastEnd);
    EXPECT_NE(loadError(dir / "past.gltf").find("reads past the end of buffer 0"), std::string::npos);

    // A fallback buffer claiming a terabyte from a file of a few kilobytes: refused before any
    // allocation.
    test::GltfDocument bomb = test::meshoptDocument(box());
    bomb.json["buffers"][1]["byteLength"] = std::uint64_t{1} << 40;
    test::writeGltf(dir / "bomb.gltf", bomb);
    EXPECT_NE(loadError(dir / "bomb.gltf").find("more than a file of this size decodes to"), std::string::npos);
}

}  // namespace
}  // namespace grass::core
