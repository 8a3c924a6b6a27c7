// Star billboard grass objects (SPEC §8) on the GPU: they draw grass-coloured tufts, the three
// wind modes agree without wind, wind moves the tops and not the roots, the distance fade hides
// them, the per-cluster mode draws once per cluster, and the shader's wind formula is the CPU's.
#include "render/billboard_gpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "billboard/grass_texture.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/uniform_block.h"
#include "gl_context_fixture.h"
#include "mesh/procedural.h"
#include "render/lighting_block.h"
#include "render/mesh_gpu.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

using BillboardRender = GlTest;
using render::BillboardDrawParams;
using render::BillboardField;
using render::BillboardWindMode;

constexpr int SIDE = 128;
const glm::vec3 SKY{0.55f, 0.70f, 0.90f};
const glm::vec3 GROUND{0.30f, 0.24f, 0.16f};
const glm::vec3 EYE{0.0f, 0.6f, 2.2f};
const BillboardWindMode MODES[] = {BillboardWindMode::PerCluster, BillboardWindMode::PerVertex,
                                   BillboardWindMode::PerObject};

core::SurfaceMesh plane(float side) {
    core::ProceduralMeshParams p;
    p.shape = core::ProceduralShape::Plane;
    p.size = side;
    p.resolution = 4;
    return core::makeProceduralMesh(p);
}

Rgba8Pixels grassTexture() {
    return core::generateGrassTexture(64, 64, 7, 3, {0.10f, 0.28f, 0.04f}, {0.45f, 0.70f, 0.18f});
}

// About 200 objects on a 2 m plane in 0.5 m clusters (16 of them).
std::vector<core::GrassObject> fieldObjects(float clusterSizeM = 0.5f) {
    core::StarBillboardParams params;
    params.density = 50.0f;
    params.heightRangeM = {0.2f, 0.35f};
    params.widthToHeight = 1.2f;
    params.clusterSizeM = clusterSizeM;
    return core::placeGrassObjects(plane(2.0f), params, 21);
}

// Empty when the program does not build (the failure names the shader and line).
std::optional<BillboardField> makeField(const std::vector<core::GrassObject>& objects) {
    auto field = BillboardField::create(objects, grassTexture());
    if (!field.ok()) {
        ADD_FAILURE() << field.error().str();
        return std::nullopt;
    }
    return std::move(*field);
}

glm::mat4 viewProj(glm::vec3 eye, glm::vec3 target) {
    return glm::perspective(glm::radians(45.0f), 1.0f, 0.05f, 50.0f) *
           glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

BillboardDrawParams drawParams(BillboardWindMode mode, float amplitudeM, float timeS) {
    BillboardDrawParams p;
    p.viewProj = viewProj(EYE, {0.0f, 0.1f, 0.0f});
    p.cameraPosWorld = EYE;
    p.timeS = timeS;
    p.mode = mode;
    p.wind.directionXZ = {1.0f, 0.3f};
    p.wind.amplitudeM = amplitudeM;
    p.wind.frequencyHz = 0.5f;
    return p;
}

// The project's default sun over SKY and GROUND with the wrapped Lambert (uGrassLighting 0):
// the billboards and the ground are lit by it for as long as the returned block lives.
gl::UniformBlock<render::LightingBlock> uploadLighting() {
    core::GrassLightingDesc lighting;
    lighting.model = core::LightingModel::Simple;
    gl::UniformBlock<render::LightingBlock> block("billboard test lighting");
    block.upload(render::lightingBlock(lighting, core::SunDesc{}, SKY, GROUND));
    return block;
}

gl::Rgba8Image render(BillboardField& field, const BillboardDrawParams& params, int side = SIDE) {
    gl::Framebuffer framebuffer(side, side, 4);
    framebuffer.bind();
    glClearColor(SKY.r, SKY.g, SKY.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_LESS);
    const gl::UniformBlock<render::LightingBlock> lighting = uploadLighting();
    field.draw(params);
    glFinish();
    return framebuffer.readPixels();
}

gl::Rgba8Image emptyImage() {
    gl::Framebuffer framebuffer(SIDE, SIDE, 4);
    framebuffer.bind();
    glClearColor(SKY.r, SKY.g, SKY.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return framebuffer.readPixels();
}

// Pixels where any channel differs by more than `threshold`, within rows [rowBegin, rowEnd).
std::size_t differingPixels(const gl::Rgba8Image& a, const gl::Rgba8Image& b, int rowBegin = 0,
                            int rowEnd = SIDE, int threshold = 24) {
    std::size_t n = 0;
    for (int row = std::max(rowBegin, 0); row < std::min(rowEnd, a.height); ++row)
        for (int col = 0; col < a.width; ++col) {
            const std::size_t p = 4 * static_cast<std::size_t>(row * a.width + col);
            for (std::size_t c = 0; c < 3; ++c)
                if (std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c])) > threshold) {
                    ++n;
                    break;
                }
        }
    return n;
}

// The horizontal shift (pixels, |shift| ≤ 12) that best maps rows [rowBegin, rowEnd) of `from`
// onto `to`: least mean absolute colour difference over the overlapping columns.
int bestShift(const gl::Rgba8Image& from, const gl::Rgba8Image& to, int rowBegin, int rowEnd) {
    int best = 0;
    double bestCost = 1e30;
    for (int shift = -12; shift <= 12; ++shift) {
        double cost = 0.0;
        std::size_t n = 0;
        for (int row = std::max(rowBegin, 0); row < std::min(rowEnd, from.height); ++row)
            for (int col = std::max(0, -shift); col < std::min(from.width, from.width - shift);
                 ++col) {
                const std::size_t a = 4 * static_cast<std::size_t>(row * from.width + col);
                const std::size_t b = 4 * static_cast<std::size_t>(row * from.width + col + shift);
                for (std::size_t c = 0; c < 3; ++c)
                    cost += std::abs(int(from.pixels[a + c]) - int(to.pixels[b + c]));
                ++n;
            }
        cost /= static_cast<double>(std::max<std::size_t>(n, 1));
        if (cost < bestCost) {
            bestCost = cost;
            best = shift;
        }
    }
    return best;
}

TEST_F(BillboardRender, BillboardsCoverPixelsWithGrassColour) {
    const auto objects = fieldObjects();
    ASSERT_GT(objects.size(), 150u);
    ASSERT_LT(objects.size(), 250u);
    auto fieldMade = makeField(objects);
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    const gl::Rgba8Image image = render(field, drawParams(BillboardWindMode::PerObject, 0, 0));
    const double share = grassPixelShare(image.pixels);
    RecordProperty("grass_share", std::to_string(share));
    // The field fills the lower part of the view; measured about 0.3 on llvmpipe.
    EXPECT_GT(share, 0.12);
    EXPECT_LT(share, 0.9) << "gaps between blades must stay transparent";
    EXPECT_EQ(field.drawnObjects(), objects.size());
    EXPECT_EQ(field.drawCalls(), 1u);
}

// The editor's reduced picture (RenderOptions::cull.keepEvery, widthScale): one object in 4 is
// drawn, in every wind mode, and widened by √4 = 2 the field covers about what it did (blades
// do the same); narrow, the thinned field shows its gaps. Billboards were not reduced before: a
// 41,000 m² terrain switched to billboards kept 8 s frames while the user orbited.
TEST_F(BillboardRender, TheReducedPictureDrawsOneObjectInNWidened) {
    const auto objects = fieldObjects();
    auto fieldMade = makeField(objects);
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    BillboardDrawParams params = drawParams(BillboardWindMode::PerObject, 0, 0);
    const double full = grassPixelShare(render(field, params).pixels);
    params.keepEvery = 4;
    const double narrow = grassPixelShare(render(field, params).pixels);
    const std::size_t kept = field.drawnObjects();
    // A quarter of each cluster's objects, rounded up or down per cluster (16 clusters).
    EXPECT_NEAR(double(kept), double(objects.size()) / 4.0, 16.0);
    EXPECT_LT(kept, objects.size() / 3);
    params.widthScale = 2.0f;
    const double wide = grassPixelShare(render(field, params).pixels);
    RecordProperty(
        "shares", std::to_string(full) + " " + std::to_string(narrow) + " " + std::to_string(wide));
    std::printf("[ billboards ] grass share: all %.3f, 1 in 4 %.3f, 1 in 4 twice as wide %.3f\n",
                full, narrow, wide);
    EXPECT_LT(narrow, 0.7 * full);
    EXPECT_GT(wide, 0.7 * full);
    EXPECT_LT(wide, 1.4 * full);
    for (const BillboardWindMode mode : MODES) {
        BillboardDrawParams thinned = drawParams(mode, 0.05f, 1.0f);
        thinned.keepEvery = 4;
        render(field, thinned);
        EXPECT_EQ(field.drawnObjects(), kept) << int(mode);
    }
    // Back to every object: the full index list again.
    render(field, drawParams(BillboardWindMode::PerObject, 0, 0));
    EXPECT_EQ(field.drawnObjects(), objects.size());
}

TEST_F(BillboardRender, WindlessModesDrawIdenticalImages) {
    auto fieldMade = makeField(fieldObjects());
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    // Same clusters in the same back-to-front order in every mode, and a zero offset: the same
    // fragments, so the same pixels.
    const gl::Rgba8Image reference = render(field, drawParams(MODES[0], 0.0f, 1.7f));
    for (const BillboardWindMode mode : MODES)
        EXPECT_EQ(render(field, drawParams(mode, 0.0f, 1.7f)).pixels, reference.pixels)
            << "mode " << static_cast<int>(mode);
}

TEST_F(BillboardRender, WindMovesTheTopsAndNotTheRoots) {
    // A row of equal objects seen level from the side, so image rows map to heights.
    std::vector<core::GrassObject> objects;
    const float height = 0.3f;
    for (int i = 0; i < 9; ++i) {
        core::GrassObject o;
        o.centre = {-0.6f + 0.15f * static_cast<float>(i), 0.0f, 0.0f};
        o.height = height;
        o.width = 0.36f;
        o.rotationRad = 0.4f + 0.7f * static_cast<float>(i);
        o.cluster = static_cast<std::uint32_t>(i / 3);
        objects.push_back(o);
    }
    auto fieldMade = makeField(objects);
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    const glm::vec3 eye(0.0f, 0.15f, 1.5f);
    const auto params = [&](BillboardWindMode mode, float amplitudeM) {
        // At t = 0.5 s the main sway is near its peak (phase ≈ π/2) for the whole row.
        BillboardDrawParams p = drawParams(mode, amplitudeM, 0.5f);
        p.viewProj = viewProj(eye, {0.0f, 0.15f, 0.0f});
        p.cameraPosWorld = eye;
        return p;
    };
    // Image row of a height at the row's depth (z = 0); row 0 is the top of the image.
    const glm::mat4 vp = viewProj(eye, {0.0f, 0.15f, 0.0f});
    const auto rowOf = [&](float y) {
        const glm::vec4 clip = vp * glm::vec4(0.0f, y, 0.0f, 1.0f);
        return static_cast<int>(std::lround((0.5f - 0.5f * clip.y / clip.w) * SIDE));
    };
    // Objects stand up to ±0.18 m nearer or farther than z = 0: a margin of rows either side.
    const int rootRow = rowOf(0.0f), topRow = rowOf(height);
    ASSERT_GT(rootRow - topRow, 20);
    for (const BillboardWindMode mode : MODES) {
        const gl::Rgba8Image still = render(field, params(mode, 0.0f));
        const gl::Rgba8Image windy = render(field, params(mode, 0.1f));
        RecordProperty("rows", std::to_string(topRow) + " " + std::to_string(rootRow));
        // How far the image content moved, band by band: 50–80 % of the height (where the
        // texture's blades are dense; above, most are shorter) and the lowest tenth. The wind
        // blows along +x (to the right in the image) with a main sway of about 0.7 × 10 cm at
        // this time: 7 px at the quads' tops, 3.5–5.5 px in the upper band, under 1 px at the
        // roots.
        const int top = bestShift(still, windy, rowOf(0.8f * height), rowOf(0.5f * height));
        const int bottom = bestShift(still, windy, rowOf(0.1f * height), rootRow + 2);
        RecordProperty("top_" + std::to_string(static_cast<int>(mode)), std::to_string(top));
        RecordProperty("bottom_" + std::to_string(static_cast<int>(mode)), std::to_string(bottom));
        EXPECT_GE(top, 3) << "mode " << static_cast<int>(mode);
        EXPECT_LE(std::abs(bottom), 1) << "mode " << static_cast<int>(mode);
        EXPECT_GT(differingPixels(still, windy), 100u) << "mode " << static_cast<int>(mode);
    }
}

TEST_F(BillboardRender, NothingIsDrawnBeyondTheFadeOut) {
    const gl::Rgba8Image empty = emptyImage();
    // Clustered: whole clusters lie beyond the fade-out and are not even drawn.
    auto clusteredMade = makeField(fieldObjects());
    ASSERT_TRUE(clusteredMade);
    BillboardField& clustered = *clusteredMade;
    // One cluster reaching from 1.3 m to 3.3 m: drawn, and the shader fades every object.
    std::vector<core::GrassObject> single = fieldObjects();
    for (core::GrassObject& o : single)
        o.cluster = 0;
    auto wholeMade = makeField(single);
    ASSERT_TRUE(wholeMade);
    BillboardField& whole = *wholeMade;
    for (const BillboardWindMode mode : MODES) {
        BillboardDrawParams p = drawParams(mode, 0.05f, 0.5f);
        p.fade = {0.0f, 0.0f, 0.9f, 1.0f};
        EXPECT_EQ(render(clustered, p).pixels, empty.pixels) << "mode " << static_cast<int>(mode);
        EXPECT_EQ(clustered.drawCalls(), 0u);
        EXPECT_EQ(clustered.drawnObjects(), 0u);
        EXPECT_EQ(render(whole, p).pixels, empty.pixels) << "mode " << static_cast<int>(mode);
        EXPECT_EQ(whole.drawCalls(), 1u);
        // Fading in beyond the field hides it too.
        p.fade = {10.0f, 12.0f, 100.0f, 200.0f};
        EXPECT_EQ(render(clustered, p).pixels, empty.pixels) << "mode " << static_cast<int>(mode);
    }
}

TEST_F(BillboardRender, FadeOutThinsTheFarObjects) {
    auto fieldMade = makeField(fieldObjects());
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    BillboardDrawParams p = drawParams(BillboardWindMode::PerVertex, 0.0f, 0.0f);
    const double full = grassPixelShare(render(field, p).pixels);
    // The field spans 1.3–3.3 m from the eye: fading out over 2–2.6 m removes the back half.
    p.fade = {0.0f, 0.0f, 2.0f, 2.6f};
    const double faded = grassPixelShare(render(field, p).pixels);
    RecordProperty("full", std::to_string(full));
    RecordProperty("faded", std::to_string(faded));
    EXPECT_GT(faded, 0.1 * full);
    EXPECT_LT(faded, 0.9 * full);
}

TEST_F(BillboardRender, PerClusterModeDrawsOncePerNonEmptyCluster) {
    auto objects = fieldObjects();
    // Leave a hole in the cluster numbering: cluster 16 stays empty, 17 takes one object.
    objects.back().cluster = 17;
    auto fieldMade = makeField(objects);
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    std::size_t nonEmpty = 0;
    for (const core::StarCluster& cluster : field.clusters())
        nonEmpty += cluster.vertexCount > 0 ? 1 : 0;
    ASSERT_EQ(field.clusterCount(), 18u);
    ASSERT_EQ(nonEmpty, 17u);
    for (const BillboardWindMode mode : MODES) {
        BillboardDrawParams p = drawParams(mode, 0.05f, 2.0f);
        // Some near corner clusters are outside the view; count them all.
        p.frustumCull = false;
        render(field, p);
        EXPECT_EQ(field.drawCalls(), mode == BillboardWindMode::PerCluster ? nonEmpty : 1u)
            << "mode " << static_cast<int>(mode);
        EXPECT_EQ(field.drawnObjects(), objects.size());
    }
}

TEST_F(BillboardRender, FrustumCullingSkipsClustersOutOfView) {
    auto fieldMade = makeField(fieldObjects());
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    std::size_t nonEmpty = 0;
    for (const core::StarCluster& cluster : field.clusters())
        nonEmpty += cluster.vertexCount > 0 ? 1 : 0;
    const gl::Rgba8Image empty = emptyImage();
    // Looking away from the field: no cluster survives, and drawing them all changes nothing.
    BillboardDrawParams p = drawParams(BillboardWindMode::PerCluster, 0.05f, 1.0f);
    p.viewProj = viewProj(EYE, EYE + glm::vec3(0.0f, 0.0f, 3.0f));
    EXPECT_EQ(render(field, p).pixels, empty.pixels);
    EXPECT_EQ(field.drawCalls(), 0u);
    EXPECT_EQ(field.drawnObjects(), 0u);
    p.frustumCull = false;
    EXPECT_EQ(render(field, p).pixels, empty.pixels);
    EXPECT_EQ(field.drawCalls(), nonEmpty);
    // Looking at the field's left edge: some clusters are culled, the image is the same as
    // without culling.
    p.viewProj = viewProj(EYE, {-1.6f, 0.1f, 0.0f});
    const gl::Rgba8Image all = render(field, p);
    p.frustumCull = true;
    const gl::Rgba8Image culled = render(field, p);
    EXPECT_LT(field.drawCalls(), nonEmpty);
    EXPECT_GT(field.drawCalls(), 0u);
    EXPECT_EQ(culled.pixels, all.pixels);
}

TEST_F(BillboardRender, DrawRestoresTheStateItChanges) {
    auto fieldMade = makeField(fieldObjects());
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    gl::Framebuffer framebuffer(SIDE, SIDE, 4);
    framebuffer.bind();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_CULL_FACE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDepthMask(GL_FALSE);
    const gl::UniformBlock<render::LightingBlock> lighting = uploadLighting();
    field.draw(drawParams(BillboardWindMode::PerCluster, 0.05f, 1.0f));
    EXPECT_GT(field.drawCalls(), 0u);
    EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE));
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    EXPECT_EQ(depthMask, GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
}

TEST_F(BillboardRender, ShaderWindMatchesTheCpuWind) {
    // Each object its own cluster: the cluster centre is the object centre, so the per-cluster
    // mode (offset from core::billboardWindOffset) and the per-object mode (the GLSL copy) must
    // move every object the same way. Only sin/cos rounding may differ between CPU and GPU.
    auto objects = fieldObjects();
    for (std::size_t i = 0; i < objects.size(); ++i)
        objects[i].cluster = static_cast<std::uint32_t>(i);
    auto fieldMade = makeField(objects);
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    const gl::Rgba8Image still = render(field, drawParams(BillboardWindMode::PerObject, 0, 2.3f));
    const gl::Rgba8Image cpu = render(field, drawParams(BillboardWindMode::PerCluster, 0.1f, 2.3f));
    const gl::Rgba8Image gpu = render(field, drawParams(BillboardWindMode::PerObject, 0.1f, 2.3f));
    const std::size_t moved = differingPixels(still, gpu);
    const std::size_t mismatched = differingPixels(cpu, gpu);
    RecordProperty("moved", std::to_string(moved));
    RecordProperty("mismatched", std::to_string(mismatched));
    EXPECT_GT(moved, 200u) << "the wind must move the field for the comparison to mean anything";
    // Rounding can flip a few edge samples; a different formula moves hundreds of pixels.
    EXPECT_LT(mismatched * 20, moved);
}

TEST_F(BillboardRender, SavesAViewOfTufts) {
    // For a person to look at: a 6 m field on brown soil, seen from a little above, with wind,
    // fading out towards the back (about 1300 objects).
    const int side = 256;
    const core::SurfaceMesh ground = plane(6.0f);
    core::StarBillboardParams params;
    params.density = 36.0f;
    params.heightRangeM = {0.18f, 0.32f};
    params.widthToHeight = 1.3f;
    params.clusterSizeM = 0.5f;
    auto fieldMade = makeField(core::placeGrassObjects(ground, params, 4));
    ASSERT_TRUE(fieldMade);
    BillboardField& field = *fieldMade;
    auto meshProgram = gl::Program::load(
        {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}}, "mesh");
    ASSERT_TRUE(meshProgram.ok()) << meshProgram.error().str();
    const render::MeshGpu groundGpu(ground);

    BillboardDrawParams p = drawParams(BillboardWindMode::PerVertex, 0.04f, 0.8f);
    const glm::vec3 eye(0.0f, 0.7f, 3.2f);
    p.viewProj = viewProj(eye, {0.0f, 0.0f, 0.0f});
    p.cameraPosWorld = eye;
    p.fade = {0.0f, 0.0f, 5.0f, 6.5f};
    gl::Framebuffer framebuffer(side, side, 4);
    framebuffer.bind();
    glClearColor(SKY.r, SKY.g, SKY.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    meshProgram->use();
    meshProgram->set("uViewProj", p.viewProj);
    // mesh.vert places props with uModel; the ground is at identity.
    meshProgram->set("uModel", glm::mat4(1.0f));
    meshProgram->set("uAlbedo", GROUND);
    const gl::UniformBlock<render::LightingBlock> lighting = uploadLighting();
    groundGpu.draw();
    field.draw(p);
    glFinish();
    const gl::Rgba8Image image = framebuffer.readPixels();
    const auto file = scratchDir("billboard_view") / "billboards.png";
    const auto written = writeRgba8Image(file, image.width, image.height, image.pixels);
    ASSERT_TRUE(written.ok()) << written.error().str();
    RecordProperty("png", file.string());
    const Rgba8Pixels texture = grassTexture();
    ASSERT_TRUE(writeRgba8Image(file.parent_path() / "texture.png", texture.width, texture.height,
                                texture.pixels)
                    .ok());
    EXPECT_GT(grassPixelShare(image.pixels), 0.15);
}

}  // namespace
}  // namespace grass::test
