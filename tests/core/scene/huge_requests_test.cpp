// Huge requests are refused up front (issue 11): a billion blades, a clump carpet, ten million
// billboards, a 65536² map and a 16384² frame at 8 samples each fail before anything of that size
// is allocated, with one line naming the field, the count and the memory it would need.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "project/project.h"
#include "scene/scene.h"
#include "support/plane_project.h"
#include "util/byte_size.h"

namespace grass::core {
namespace {

void expectMentions(const std::string& error, std::initializer_list<const char*> parts) {
    EXPECT_EQ(error.find('\n'), std::string::npos) << "not one line: " << error;
    for (const char* part : parts)
        EXPECT_NE(error.find(part), std::string::npos) << "no \"" << part << "\" in: " << error;
}

TEST(HugeRequests, ByteSizesReadInBinaryUnits) {
    EXPECT_EQ(byteSizeText(512.0), "512 B");
    EXPECT_EQ(byteSizeText(1536.0), "1.5 KiB");
    EXPECT_EQ(byteSizeText(16.0 * 1024 * 1024 * 1024), "16 GiB");
    EXPECT_EQ(byteSizeText(std::numeric_limits<double>::infinity()), "inf B");
}

TEST(HugeRequests, BillionBladesAreRefusedBeforeScattering) {
    // 625 000 blades/m² on a 40 m plane: 1e9 blades, ~276 GiB at 296 bytes each.
    LoadedProject loaded = test::planeFieldProject({40.0f, 4, 625000.0f});
    loaded.file = "billion/project.json";
    const auto scene = buildScene(loaded);
    ASSERT_FALSE(scene.ok());
    expectMentions(scene.error().str(),
                   {"billion/project.json", "/layers/0", "density 6.25e+05", "1.6e+03 m²",
                    "1e+09 blades", "GiB of blade data", "limit is 20 million blades"});
    EXPECT_EQ(sceneBytesPerBlade(), 296u);
}

TEST(HugeRequests, ClumpCarpetsAreRefusedBeforeScattering) {
    LoadedProject loaded = test::planeFieldProject({40.0f, 4, 0.0f});
    ScatterParams& scatter = loaded.project.layers.front().scatter;
    scatter.clumpSpacing = 0.01f;
    scatter.bladesPerClump = 10000;
    const auto scene = buildScene(loaded);
    ASSERT_FALSE(scene.ok());
    expectMentions(scene.error().str(), {"/layers/0", "clumps of 10000 blades 0.01 m apart",
                                         "TiB of blade data", "clump_spacing"});
}

TEST(HugeRequests, TenMillionBillboardsAreRefusedBeforePlacing) {
    // No blades at all: the billboards' own density × area is what is too much.
    LoadedProject loaded = test::planeFieldProject({100.0f, 4, 0.0f});
    loaded.project.billboards.placement.density = 1000.0f;
    loaded.project.render.technique = GrassTechnique::Hybrid;
    const auto scene = buildScene(loaded);
    ASSERT_FALSE(scene.ok());
    expectMentions(scene.error().str(),
                   {"/billboards/density", "1e+07 billboards", "GiB", "limit is 2 million"});
}

// The same billboards do not stop a field its technique draws by blades alone (a 1 km² terrain
// at the default billboard density was refused for 30 million billboards it never drew); placing
// them later, for a renderer asked to draw them, is refused in the same words.
TEST(HugeRequests, BillboardsNotDrawnAreNotCounted) {
    LoadedProject loaded = test::planeFieldProject({100.0f, 4, 0.0f});
    loaded.project.billboards.placement.density = 1000.0f;
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const auto placed = placeBillboards(*scene);
    ASSERT_FALSE(placed.ok());
    expectMentions(placed.error().str(),
                   {"/billboards/density", "1e+07 billboards", "GiB", "limit is 2 million"});
    EXPECT_TRUE(scene->billboards.placed.empty());
}

// The largest plane a project may ask for (3e38 m, within float range): its area is finite in
// double, and asks for far too many blades even at 1 /m²; the message points at the mesh too.
TEST(HugeRequests, HugeSurfacesAreRefused) {
    LoadedProject loaded = test::planeFieldProject({3e38f, 2, 1.0f});
    const auto scene = buildScene(loaded);
    ASSERT_FALSE(scene.ok());
    expectMentions(scene.error().str(), {"/layers/0", "9e+76 m²", "EiB", "/mesh"});
}

TEST(HugeRequests, HugeMapResolutionIsRefusedWithItsMemory) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 1,
        "layers": [{"name": "grass", "map_resolution": [65536, 65536]}]})",
                                     "maps.json");
    ASSERT_FALSE(parsed.ok());
    expectMentions(parsed.error().str(), {"maps.json", "/layers/0/map_resolution/0", "1..8192",
                                          "65536×65536", "16 GiB", "8192×8192", "256 MiB"});
}

TEST(HugeRequests, HugeFramesAreRefusedWithTheirMemory) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 1,
        "render": {"width": 16384, "height": 16384, "msaa": 8}})",
                                     "frame.json");
    ASSERT_FALSE(parsed.ok());
    expectMentions(parsed.error().str(),
                   {"/render", "16384×16384 at 8 samples", "19 GiB", "8 GiB", "msaa"});
    // The largest frame at 2 samples still fits.
    EXPECT_LE(framebufferBytes(16384, 16384, 2), MAX_FRAMEBUFFER_BYTES);
    EXPECT_TRUE(parseProject(R"({"format": "grass-project", "version": 1,
        "render": {"width": 16384, "height": 16384, "msaa": 2}})",
                             "frame.json")
                    .ok());
}

}  // namespace
}  // namespace grass::core
