// Issue 25: an export drawn as a stock glTF viewer draws it — instance TRS × the node's mesh,
// baseColorFactor × COLOR_0 × _COLOR_0 (core/mesh/gltf_view.h) — looks like `grass render` of
// the same project at rest; the export as it was before (every blade upright, one colour) does not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "export/export.h"
#include "export/gltf_export.h"
#include "gl_context_fixture.h"
#include "mesh/gltf_view.h"
#include "render/gltf_view_render.h"
#include "render/offscreen_render.h"
#include "support/image_compare.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using ExportStockTest = GlTest;

constexpr int WIDTH = 640, HEIGHT = 360;
constexpr std::size_t MAX_VIEW_VERTICES = 20'000'000;

// The mean of each TILE × TILE block, RGB: what the field looks like at a glance, without the
// blade-by-blade placement of thin blades that no two renderers share exactly.
constexpr int TILE = 8;
std::vector<double> tileMeans(const gl::Rgba8Image& image) {
    std::vector<double> means;
    for (int ty = 0; ty + TILE <= image.height; ty += TILE)
        for (int tx = 0; tx + TILE <= image.width; tx += TILE)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0;
                for (int y = ty; y < ty + TILE; ++y)
                    for (int x = tx; x < tx + TILE; ++x)
                        sum += image.pixels[4 * std::size_t(y * image.width + x) + std::size_t(c)];
                means.push_back(sum / (TILE * TILE));
            }
    return means;
}

double tileError(const gl::Rgba8Image& a, const gl::Rgba8Image& b) {
    const std::vector<double> ma = tileMeans(a), mb = tileMeans(b);
    double sum = 0.0;
    for (std::size_t i = 0; i < ma.size(); ++i)
        sum += std::abs(ma[i] - mb[i]);
    return sum / double(ma.size());
}

// The export as it was before issue 25, rebuilt from today's .gltf: every instancing node draws
// one upright unit blade in the layer's tip colour (the material's base colour then), and the
// per-instance colour sits where stock loaders do not look.
void makeUprightOneColourExport(const fs::path& gltfFile, const core::LayerField& layer, int segments) {
    json doc = json::parse(std::ifstream(gltfFile));
    const core::UnitBladeMesh blade = core::unitBladeMesh(layer.shape, layer.tipStart, segments, 0.0f);
    std::string bytes;
    const auto append = [&](const auto& values) {
        const std::size_t offset = bytes.size();
        bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(values[0]));
        return offset;
    };
    const std::size_t positions = append(blade.positions), normals = append(blade.normals),
                      indices = append(blade.indices);
    const fs::path bin = gltfFile.parent_path() / "upright.bin";
    std::ofstream(bin, std::ios::binary) << bytes;
    const std::size_t buffer = doc["buffers"].size();
    doc["buffers"].push_back({{"uri", "upright.bin"}, {"byteLength", bytes.size()}});
    const auto view = [&](std::size_t offset, std::size_t length) {
        doc["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", offset}, {"byteLength", length}});
        return doc["bufferViews"].size() - 1;
    };
    const auto accessor = [&](std::size_t bufferView, int componentType, std::size_t count, const char* type) {
        doc["accessors"].push_back(
            {{"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}});
        return doc["accessors"].size() - 1;
    };
    const std::size_t vertices = blade.positions.size() / 3;
    const std::size_t p = accessor(view(positions, normals - positions), 5126, vertices, "VEC3");
    const std::size_t n = accessor(view(normals, indices - normals), 5126, vertices, "VEC3");
    const std::size_t i = accessor(view(indices, bytes.size() - indices), 5125, blade.indices.size(), "SCALAR");
    doc["materials"].push_back(
        {{"doubleSided", true},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {layer.tipColor.r, layer.tipColor.g, layer.tipColor.b, 1.0}}}}});
    doc["meshes"].push_back(
        {{"primitives",
          {{{"attributes", {{"POSITION", p}, {"NORMAL", n}}}, {"indices", i},
            {"material", doc["materials"].size() - 1}}}}});
    for (json& node : doc["nodes"])
        if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing")) {
            node["mesh"] = doc["meshes"].size() - 1;
            node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"].erase("_COLOR_0");
        }
    std::ofstream(gltfFile) << doc.dump();
}

gl::Rgba8Image drawAsStockViewer(const fs::path& file, const core::OrbitCamera& camera,
                                 const render::RenderOptions& options) {
    auto view = core::loadGltfView(file, MAX_VIEW_VERTICES);
    EXPECT_TRUE(view.ok()) << view.error().str();
    if (!view)
        return {};
    render::GltfViewRequest request;
    request.width = WIDTH;
    request.height = HEIGHT;
    auto image = render::renderGltfView(*view, camera, request, options);
    EXPECT_TRUE(image.ok()) << image.error().str();
    return image ? std::move(*image) : gl::Rgba8Image{};
}

// Kept next to the test's scratch files for a look (a failure names them).
void save(const gl::Rgba8Image& image, const fs::path& file) {
    EXPECT_TRUE(writeRgba8Image(file, image.width, image.height, image.pixels).ok()) << file;
}

struct Pictures {
    gl::Rgba8Image ours, stock, before;
};

// Issue 25's check: the meadow (lean 24–50°, painted soil and light, so wilted straw-coloured
// blades beside green ones) exported as glTF and drawn as a stock viewer draws it, against
// `grass render`. Both draw their unlit colours (RenderOptions::albedoView): the export decides
// geometry and colour, while the lighting is each viewer's own (lit pictures in docs/export.md).
// The collider ball is not part of an export and is left out of ours.
TEST_F(ExportStockTest, AStockViewerDrawsTheMeadowAsGrassRenderDoes) {
    auto loaded = core::loadProject(sourceDir() / "projects/meadow");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    auto camera = render::projectCamera(loaded->project, "");
    ASSERT_TRUE(camera.ok());
    const fs::path dir = scratchDir("export_stock_gl");
    core::ExportOptions exportOptions;
    exportOptions.format = core::ExportFormat::Gltf;
    exportOptions.outDir = dir / "gltf";
    auto report = core::exportProject(*loaded, *scene, exportOptions, {});
    ASSERT_TRUE(report.ok()) << report.error().str();
    const fs::path file = dir / "gltf/grass.gltf";
    scene->props.clear();

    render::OffscreenRequest request;
    request.width = WIDTH;
    request.height = HEIGHT;
    request.frames = 1;
    request.options = render::renderOptionsFor(loaded->project, true);
    request.options.albedoView = true;
    const auto picturesWith = [&](bool widthCorrection) {
        request.options.widthCorrection = widthCorrection;
        Pictures p;
        auto ours = render::renderOffscreen(*scene, *camera, request);
        EXPECT_TRUE(ours.ok()) << ours.error().str();
        if (ours)
            p.ours = std::move(ours->image);
        p.stock = drawAsStockViewer(file, *camera, request.options);
        return p;
    };
    Pictures exact = picturesWith(false);
    Pictures asRendered = picturesWith(true);
    // The lit pictures, for a look (docs/export-stock-viewer.png): each viewer's own lighting.
    request.options.albedoView = false;
    const Pictures lit = picturesWith(true);
    save(lit.ours, dir / "grass_render_lit.png");
    save(lit.stock, dir / "stock_viewer_lit.png");
    request.options.albedoView = true;
    makeUprightOneColourExport(file, scene->layers[0], loaded->project.render.stripSegments);
    exact.before = drawAsStockViewer(file, *camera, request.options);
    asRendered.before = exact.before;
    for (const Pictures* p : {&exact, &asRendered})
        for (const gl::Rgba8Image* image : {&p->ours, &p->stock, &p->before})
            ASSERT_EQ(image->pixels.size(), std::size_t(4 * WIDTH * HEIGHT));
    save(exact.ours, dir / "grass_render_no_width_correction.png");
    save(asRendered.ours, dir / "grass_render.png");
    save(exact.stock, dir / "stock_viewer.png");
    save(exact.before, dir / "stock_viewer_before_issue_25.png");

    const double exactTiles = tileError(exact.stock, exact.ours);
    const double exactPixels = compareImages(exact.stock.pixels, exact.ours.pixels, 24).meanAbs;
    const double renderedTiles = tileError(asRendered.stock, asRendered.ours);
    const double beforeTiles = tileError(exact.before, exact.ours);
    const double beforeRenderedTiles = tileError(asRendered.before, asRendered.ours);
    std::printf("mean |difference| of 8x8 tiles (0..255): stock %.2f (pixels %.2f), before %.2f; "
                "against grass render's width correction: stock %.2f, before %.2f\n",
                exactTiles, exactPixels, beforeTiles, renderedTiles, beforeRenderedTiles);
    RecordProperty("tile_error", std::to_string(exactTiles));
    // The same blades drawn by both (our renderer's width correction off: it widens blades
    // thinner than a pixel into quads, SPEC §7, which no stock viewer does): measured 0.68 per
    // tile, 3.25 per pixel (blade edges rasterise differently: strips against the exported
    // mesh). Before issue 25 — upright blades in one colour — 15.1 per tile. A tolerance of 2
    // is 3× the measured error and an eighth of the old export's.
    EXPECT_LE(exactTiles, 2.0);
    EXPECT_LE(exactPixels, 5.0);
    EXPECT_GT(beforeTiles, 2.0) << "the test must fail on the export before issue 25";
    // Against grass render as it draws (width correction on), recorded, not asserted: SPEC §7
    // turns a blade thinner than a pixel into the full quad, which no stock viewer can do, and
    // that difference dominates (measured 7.37, and 7.95 for the export before issue 25; 3.97
    // while the correction widened one edge alone, issue 30). It cannot tell a good export from
    // a bad one; the comparison above, the same blades drawn by both, does.
    RecordProperty("tile_error_width_corrected", std::to_string(renderedTiles));
    EXPECT_LT(exactTiles, renderedTiles) << "the width correction must show in our picture";
}

}  // namespace
}  // namespace grass::test
