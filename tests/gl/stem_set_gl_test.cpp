// Kim & Cho stem sets drawn by instancing (SPEC §9): the vertex shader's geometry is the CPU
// reference's (core::stemSetVertices placed by render::stemSetWorldPosition), a field of sets
// draws grass with healthy sets greener than poor ones, and more levels draw taller sets.
#include "render/stem_set_gpu.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/framebuffer.h"
#include "gl/uniform_block.h"
#include "gl_context_fixture.h"
#include "growth/stem_set_cull.h"
#include "project/project.h"
#include "render/lighting_block.h"

namespace grass::test {
namespace {

using StemSetGpu = GlTest;
using StemSetRender = GlTest;
using core::StemSetInstance;
using render::StemSetField;

constexpr int SIDE = 128;
constexpr float PI = 3.14159265358979f;
const glm::vec3 SKY{0.55f, 0.70f, 0.90f};
const glm::vec3 SUN_DIRECTION = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));

// Uniform in [0, 1) from the top 24 bits: the same numbers with every standard library.
float unit(std::mt19937& rng) {
    return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f);
}

StemSetInstance instance(glm::vec3 root, float metresPerUnit, glm::vec3 up, float yawRad,
                         glm::vec4 alphaBetaThetaB, glm::vec4 halfWidthSpread) {
    StemSetInstance s;
    s.rootMetresPerUnit = glm::vec4(root, metresPerUnit);
    s.upYaw = glm::vec4(glm::normalize(up), yawRad);
    s.alphaBetaThetaB = alphaBetaThetaB;
    s.halfWidthSpread = halfWidthSpread;
    return s;
}

// Every combination of θ, β and up (two near ±z past the frame's switch to the x reference),
// with yaw, scale, width and spreads cycling through other values.
std::vector<StemSetInstance> variedInstances() {
    const float thetas[] = {0.0f, 0.5f, PI / 3.0f};
    const float betas[] = {0.3f, 0.7f, 1.0f};
    const glm::vec3 ups[] = {{0.0f, 1.0f, 0.0f},  {0.3f, 1.0f, 0.2f},    {1.0f, 0.0f, 0.0f},
                             {0.0f, 0.0f, -1.0f}, {-0.2f, -0.1f, 0.97f}, {0.0f, -1.0f, 0.0f},
                             {0.5f, 0.5f, -0.7f}};
    const float yaws[] = {0.0f, 0.7f, -2.1f, 3.0f};
    std::vector<StemSetInstance> instances;
    int n = 0;
    for (const float theta : thetas)
        for (const float beta : betas)
            for (const glm::vec3 up : ups) {
                const float f = static_cast<float>(n);
                const glm::vec3 root(-1.5f + 0.05f * f, 0.3f * std::sin(f), 1.0f - 0.03f * f);
                instances.push_back(instance(
                    root, 0.2f + 0.02f * static_cast<float>(n % 7), up, yaws[n % 4],
                    {0.05f + 0.04f * static_cast<float>(n % 5), beta, theta, 0.5f},
                    {0.01f + 0.01f * static_cast<float>(n % 3), 0.03f * static_cast<float>(n % 4),
                     0.02f * static_cast<float>(n % 5), n % 3 == 0 ? 1.0f : 0.0f}));
                ++n;
            }
    return instances;
}

// The CPU reference: the set's vertices in core::stemSetVertices order, in world space.
std::vector<glm::vec3> cpuWorldVertices(const StemSetInstance& s, int levels) {
    std::vector<glm::vec3> vertices =
        core::stemSetVertices(render::stemSetParams(s, levels), s.halfWidthSpread.x,
                              s.halfWidthSpread.w);
    for (glm::vec3& v : vertices)
        v = render::stemSetWorldPosition(s, v);
    return vertices;
}

std::optional<gl::Program> makeProgram(const std::vector<std::string>& defines = {}) {
    auto program = render::loadStemSetProgram(defines);
    if (!program.ok()) {
        ADD_FAILURE() << program.error().str();
        return std::nullopt;
    }
    return std::move(*program);
}

glm::mat4 viewProj(glm::vec3 eye, glm::vec3 target) {
    return glm::perspective(glm::radians(45.0f), 1.0f, 0.05f, 50.0f) *
           glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

// 0: the wrapped Lambert; 1: the grass lighting of SPEC §10 with the project defaults and a
// field water of 0.4. The sets are lit by it for as long as the returned block lives.
gl::UniformBlock<render::LightingBlock> uploadLighting(int grassLighting) {
    core::GrassLightingDesc lighting;
    lighting.model = grassLighting == 1 ? core::LightingModel::Grass : core::LightingModel::Simple;
    lighting.water = {0.4f, 0.4f};
    core::SunDesc sun;
    sun.direction = SUN_DIRECTION;
    gl::UniformBlock<render::LightingBlock> block("stem set test lighting");
    block.upload(render::lightingBlock(lighting, sun, SKY, glm::vec3(0.30f, 0.24f, 0.16f)));
    return block;
}

void setFieldUniforms(const gl::Program& program) {
    program.set("uFieldAo", 0.6f);
    render::setStemSetColours(program, render::StemSetColours{});
}

// With `culled`, the sets of core::cullStemSets' lists at their LODs; otherwise every set at
// full detail.
gl::Rgba8Image render(StemSetField& field, const gl::Program& program, glm::vec3 eye,
                      glm::vec3 target, int levels, int grassLighting = 0,
                      const core::StemSetCullResult* culled = nullptr) {
    gl::Framebuffer framebuffer(SIDE, SIDE, 4);
    framebuffer.bind();
    glClearColor(SKY.r, SKY.g, SKY.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_LESS);
    program.use();
    program.set("uViewProj", viewProj(eye, target));
    program.set("uCameraPosition", eye);
    const gl::UniformBlock<render::LightingBlock> lighting = uploadLighting(grassLighting);
    setFieldUniforms(program);
    if (culled)
        field.draw(program, levels, *culled);
    else
        field.draw(program, levels);
    glFinish();
    return framebuffer.readPixels();
}

// Pixels where some channel differs from the clear colour by more than 12 of 255.
bool covered(const gl::Rgba8Image& image, int row, int col) {
    const std::size_t p = 4 * static_cast<std::size_t>(row * image.width + col);
    for (std::size_t c = 0; c < 3; ++c)
        if (std::abs(static_cast<float>(image.pixels[p + c]) - 255.0f * SKY[static_cast<int>(c)]) >
            12.0f)
            return true;
    return false;
}

std::size_t coveredCount(const gl::Rgba8Image& image) {
    std::size_t n = 0;
    for (int row = 0; row < image.height; ++row)
        for (int col = 0; col < image.width; ++col)
            n += covered(image, row, col) ? 1 : 0;
    return n;
}

int topCoveredRow(const gl::Rgba8Image& image) {
    for (int row = 0; row < image.height; ++row)
        for (int col = 0; col < image.width; ++col)
            if (covered(image, row, col))
                return row;
    return image.height;
}

// Mean colour (0..255) of the covered pixels in columns [colBegin, colEnd).
glm::vec3 meanCoveredColour(const gl::Rgba8Image& image, int colBegin, int colEnd) {
    glm::dvec3 sum(0.0);
    std::size_t n = 0;
    for (int row = 0; row < image.height; ++row)
        for (int col = colBegin; col < colEnd; ++col) {
            if (!covered(image, row, col))
                continue;
            const std::size_t p = 4 * static_cast<std::size_t>(row * image.width + col);
            sum += glm::dvec3(image.pixels[p], image.pixels[p + 1], image.pixels[p + 2]);
            ++n;
        }
    return n ? glm::vec3(sum / static_cast<double>(n)) : glm::vec3(0.0f);
}

TEST(StemSetFrame, IsARotationCarryingYToUp) {
    const glm::vec3 ups[] = {{0, 1, 0},          {0, -1, 0},         {1, 0, 0},
                             {-1, 0, 0},         {0, 0, 1},          {0, 0, -1},
                             {0.3f, 1.0f, 0.2f}, {0.1f, 0.1f, 0.9f}, {0.0f, 0.44f, 0.9f}};
    for (const glm::vec3 up : ups)
        for (const float yaw : {0.0f, 0.9f, -2.5f}) {
            const glm::mat3 m = render::stemSetFrame(up, yaw);
            const glm::mat3 gram = glm::transpose(m) * m;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    EXPECT_NEAR(gram[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
            EXPECT_NEAR(glm::determinant(m), 1.0f, 1e-5f);
            const glm::vec3 n = glm::normalize(up);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(m[1][c], n[c], 1e-6f) << "up " << up.x << " " << up.y << " " << up.z;
        }
    // Up = +y and no yaw: the model frame is the world frame, so an upright set on flat ground
    // is core's geometry shifted and scaled.
    const glm::mat3 identity = render::stemSetFrame({0, 1, 0}, 0.0f);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(identity[i][j], i == j ? 1.0f : 0.0f, 1e-6f);
    // Yaw turns like glm::rotate about up: model x goes to (cos, 0, −sin).
    const glm::mat3 turned = render::stemSetFrame({0, 1, 0}, 0.5f);
    EXPECT_NEAR(turned[0].x, std::cos(0.5f), 1e-6f);
    EXPECT_NEAR(turned[0].z, -std::sin(0.5f), 1e-6f);
    // A zero normal counts as +y instead of producing NaNs.
    EXPECT_NEAR(render::stemSetFrame(glm::vec3(0.0f), 0.0f)[1].y, 1.0f, 1e-6f);
}

TEST_F(StemSetGpu, VerticesMatchTheCpuReference) {
    auto program = makeProgram({"STEM_SET_CAPTURE"});
    ASSERT_TRUE(program);
    const std::vector<StemSetInstance> instances = variedInstances();
    StemSetField field(instances);
    ASSERT_EQ(field.instanceCount(), instances.size());
    // Draws need a complete framebuffer even with rasterization off.
    gl::Framebuffer framebuffer(8, 8, 1);
    framebuffer.bind();
    for (int levels = 1; levels <= core::MAX_STEM_LEVELS; ++levels) {
        const int perSet = render::stemSetVertexCount(levels);
        ASSERT_EQ(perSet, core::STEMS_PER_SET * 2 * core::STEM_SAMPLES_PER_LEVEL * levels);
        // NaN everywhere first: a vertex the draw never shaded cannot pass by accident.
        const std::size_t slots = instances.size() * static_cast<std::size_t>(perSet);
        const std::vector<glm::vec4> sentinel(2 * slots,
                                              glm::vec4(std::numeric_limits<float>::quiet_NaN()));
        const gl::Buffer capture = gl::Buffer::fromVector(sentinel, "stem set capture");
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::STEM_SET_CAPTURE_BINDING, capture.id());
        program->use();
        program->set("uViewProj", glm::mat4(1.0f));
        glEnable(GL_RASTERIZER_DISCARD);
        field.draw(*program, levels);
        glDisable(GL_RASTERIZER_DISCARD);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        const std::vector<std::byte> bytes = capture.read(0, capture.size());
        std::vector<glm::vec4> gpu(sentinel.size());
        std::memcpy(gpu.data(), bytes.data(), bytes.size());

        const int samples = core::STEM_SAMPLES_PER_LEVEL * levels;
        for (std::size_t i = 0; i < instances.size(); ++i) {
            const std::vector<glm::vec3> cpu = cpuWorldVertices(instances[i], levels);
            ASSERT_EQ(cpu.size(), static_cast<std::size_t>(perSet));
            // The set's size: its farthest vertex from the root.
            const glm::vec3 root(instances[i].rootMetresPerUnit);
            float size = 0.0f;
            for (const glm::vec3& v : cpu)
                size = std::max(size, glm::distance(v, root));
            ASSERT_GT(size, 0.0f);
            const glm::vec3 across =
                render::stemSetFrame(glm::vec3(instances[i].upYaw), instances[i].upYaw.w)[0];
            // Sample s of the stem starting at vertex `first`: the midpoint of its two vertices.
            const auto centre = [&](std::size_t first, int s) {
                const auto v = first + 2 * static_cast<std::size_t>(std::clamp(s, 0, samples - 1));
                return 0.5f * (cpu[v] + cpu[v + 1]);
            };
            float worstPosition = 0.0f, worstNormal = 1.0f;
            for (std::size_t v = 0; v < cpu.size(); ++v) {
                const glm::vec4 position = gpu[2 * (i * static_cast<std::size_t>(perSet) + v)];
                const glm::vec3 normal(gpu[2 * (i * static_cast<std::size_t>(perSet) + v) + 1]);
                ASSERT_FALSE(std::isnan(position.x))
                    << "levels " << levels << " set " << i << " vertex " << v << " was not shaded";
                worstPosition = std::max(worstPosition, glm::distance(glm::vec3(position), cpu[v]));
                // The ribbon normal is cross(across, tangent); the CPU side estimates the tangent
                // by the chord between the neighbouring samples, which turns from it by a few
                // degrees on the most bent stems.
                const std::size_t first = v / static_cast<std::size_t>(2 * samples) *
                                          static_cast<std::size_t>(2 * samples);
                const int s = static_cast<int>((v - first) / 2);
                const glm::vec3 chord = centre(first, s + 1) - centre(first, s - 1);
                const glm::vec3 expected = glm::normalize(glm::cross(across, chord));
                EXPECT_NEAR(glm::length(normal), 1.0f, 1e-4f);
                EXPECT_NEAR(glm::dot(normal, across), 0.0f, 1e-4f);
                worstNormal = std::min(worstNormal, glm::dot(normal, expected));
            }
            EXPECT_LE(worstPosition, 1e-4f * size)
                << "levels " << levels << " set " << i << " size " << size << " m";
            EXPECT_GT(worstNormal, 0.97f) << "levels " << levels << " set " << i;
        }
    }
}

TEST_F(StemSetRender, FieldCoversTheViewAndHealthyIsGreener) {
    auto program = makeProgram();
    ASSERT_TRUE(program);
    // 324 sets on a jittered 18 × 18 grid over 2 m × 2 m: poor (b = 0) on the left (x < 0),
    // healthy (b = 1) on the right; growth parameters vary within the SPEC §9 ranges.
    std::mt19937 rng(17);
    std::vector<StemSetInstance> instances;
    const int grid = 18;
    const float step = 2.0f / static_cast<float>(grid);
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            // Named draws: the order of evaluation of function arguments is unspecified.
            const float jitterX = unit(rng), jitterZ = unit(rng), yaw = 2.0f * PI * unit(rng);
            const float alpha = 0.1f + 0.1f * unit(rng), beta = 0.6f + 0.3f * unit(rng);
            const float theta = 0.4f * unit(rng);
            const glm::vec3 root(-1.0f + step * (static_cast<float>(i) + jitterX), 0.0f,
                                 -1.0f + step * (static_cast<float>(j) + jitterZ));
            const float b = root.x < 0.0f ? 0.0f : 1.0f;
            instances.push_back(instance(root, 0.2f, {0, 1, 0}, yaw, {alpha, beta, theta, b},
                                         {0.1f, 0.08f, 0.08f, 0.0f}));
        }
    StemSetField field(instances);
    const glm::vec3 eye(0.0f, 1.6f, 1.8f);
    for (const int grassLighting : {0, 1}) {
        const gl::Rgba8Image image = render(field, *program, eye, {0, 0, 0}, 4, grassLighting);
        const double coverage = static_cast<double>(coveredCount(image)) / (SIDE * SIDE);
        const glm::vec3 poor = meanCoveredColour(image, 0, SIDE / 2);
        const glm::vec3 healthy = meanCoveredColour(image, SIDE / 2, SIDE);
        // The right half alone is healthy grass; straw fails grassPixelShare's green test.
        const double grassShare = grassPixelShare(image.pixels);
        const std::string tag = "lighting " + std::to_string(grassLighting);
        RecordProperty("coverage_" + std::to_string(grassLighting), std::to_string(coverage));
        RecordProperty("grass_share_" + std::to_string(grassLighting), std::to_string(grassShare));
        // The field fills most of the view with sky showing between the sets (measured 0.76 on
        // llvmpipe); an empty draw or sets smeared over the screen fall outside.
        EXPECT_GT(coverage, 0.4) << tag;
        EXPECT_LT(coverage, 0.92) << tag;
        EXPECT_GT(grassShare, 0.05) << tag;
        EXPECT_LT(grassShare, 0.5) << tag;
        // Greenness: green over the mean of red and blue, in 0..255 units.
        const auto greenness = [](glm::vec3 c) { return c.g - 0.5f * (c.r + c.b); };
        EXPECT_GT(greenness(healthy), greenness(poor) + 15.0f)
            << tag << " healthy " << healthy.r << " " << healthy.g << " " << healthy.b << ", poor "
            << poor.r << " " << poor.g << " " << poor.b;
        // Straw is red-heavy next to green grass.
        EXPECT_GT(poor.r, healthy.r) << tag;
    }
}

TEST_F(StemSetRender, MoreLevelsDrawTallerSets) {
    auto program = makeProgram();
    ASSERT_TRUE(program);
    // A row of upright sets seen level from the side, so image rows map to heights.
    std::vector<StemSetInstance> instances;
    for (int i = 0; i < 9; ++i)
        instances.push_back(instance({-0.6f + 0.15f * static_cast<float>(i), 0.0f, 0.0f}, 0.2f,
                                     {0, 1, 0}, 0.4f + 0.7f * static_cast<float>(i),
                                     {0.15f, 0.7f, 0.0f, 1.0f}, {0.15f, 0.05f, 0.05f, 0.0f}));
    StemSetField field(instances);
    const glm::vec3 eye(0.0f, 0.2f, 1.5f), target(0.0f, 0.2f, 0.0f);
    const glm::mat4 vp = viewProj(eye, target);
    // The image row of the highest CPU vertex of any set; row 0 is the top of the image.
    const auto expectedTopRow = [&](int levels) {
        float best = static_cast<float>(SIDE);
        for (const StemSetInstance& s : instances)
            for (const glm::vec3& v : cpuWorldVertices(s, levels)) {
                const glm::vec4 clip = vp * glm::vec4(v, 1.0f);
                best = std::min(best, (0.5f - 0.5f * clip.y / clip.w) * SIDE);
            }
        return static_cast<int>(std::floor(best));
    };
    const gl::Rgba8Image low = render(field, *program, eye, target, 1);
    const gl::Rgba8Image high = render(field, *program, eye, target, 4);
    const int lowTop = topCoveredRow(low), highTop = topCoveredRow(high);
    RecordProperty("rows", std::to_string(lowTop) + " " + std::to_string(highTop));
    // β = 0.7: 0.7 units tall at one level, 1.77 at four (0.14 m and 0.35 m); about 22 rows
    // apart at this distance.
    EXPECT_LT(highTop + 15, lowTop);
    // The tips taper to a point, so the top few rows of a tip may cover too little of a pixel
    // to show: the drawn top may sit a few rows under the CPU's, never above it.
    for (const auto& [levels, top] : {std::pair{1, lowTop}, std::pair{4, highTop}}) {
        EXPECT_GE(top, expectedTopRow(levels) - 1) << "levels " << levels;
        EXPECT_LE(top, expectedTopRow(levels) + 4) << "levels " << levels;
    }
    EXPECT_GT(coveredCount(high), 2 * coveredCount(low));
    // Levels clamp to 1..4.
    EXPECT_EQ(render(field, *program, eye, target, 9).pixels, high.pixels);
    EXPECT_EQ(render(field, *program, eye, target, 0).pixels, low.pixels);
}

// The growth technique's cull (issue 24, core/growth/stem_set_cull.h): drawn through the
// visible lists at full detail, the picture is the full draw's, pixel for pixel (the lists keep
// the sets' order, and the culled sets lie outside the view); at the farthest LOD (2 samples per
// level) it stays close to it.
TEST_F(StemSetRender, CulledDrawMatchesTheFullDrawAndLodStaysClose) {
    auto program = makeProgram();
    ASSERT_TRUE(program);
    std::vector<StemSetInstance> instances;
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 24; ++j)
            instances.push_back(instance({-3.0f + 0.25f * float(i), 0.0f, -3.0f + 0.25f * float(j)},
                                         0.2f, {0, 1, 0}, 0.7f * float(i + j),
                                         {0.15f, 0.7f, 0.3f, 1.0f}, {0.08f, 0.05f, 0.05f, 0.0f}));
    StemSetField field(instances);
    const glm::vec3 eye(0.0f, 0.8f, 1.2f), target(0.0f, 0.0f, -0.5f);
    core::StemSetCullSettings settings;
    settings.distance = false;
    settings.lodDistanceM = 0.0f;
    core::StemSetCullResult culled;
    core::cullStemSets(instances, 4, viewProj(eye, target), eye, settings, culled);
    RecordProperty("drawn", std::to_string(culled.drawn()));
    // The view sees the near part of the field only: the cull must have removed some sets.
    EXPECT_GT(culled.culledFrustum, instances.size() / 4);
    const gl::Rgba8Image full = render(field, *program, eye, target, 4);
    const gl::Rgba8Image viaLists = render(field, *program, eye, target, 4, 0, &culled);
    EXPECT_EQ(viaLists.pixels, full.pixels);

    settings.lodDistanceM = 1e-3f;  // everything at LOD 2
    core::cullStemSets(instances, 4, viewProj(eye, target), eye, settings, culled);
    ASSERT_EQ(culled.visible[2].size(), culled.drawn());
    const gl::Rgba8Image far = render(field, *program, eye, target, 4, 0, &culled);
    const double fullCover = double(coveredCount(full)), farCover = double(coveredCount(far));
    RecordProperty("coverage_full_lod2", std::to_string(fullCover) + " " + std::to_string(farCover));
    // 2 samples a level instead of 5 cut the curve's corners: a few per cent of the cover, not
    // a different picture (the LOD is meant for sets a few pixels tall).
    EXPECT_NEAR(farCover / fullCover, 1.0, 0.1);
    EXPECT_NE(far.pixels, full.pixels);
}

TEST_F(StemSetRender, EmptyFieldDrawsNothingAndDrawRestoresCulling) {
    auto program = makeProgram();
    ASSERT_TRUE(program);
    StemSetField empty(std::vector<StemSetInstance>{});
    const glm::vec3 eye(0.0f, 1.0f, 2.0f);
    const gl::Rgba8Image image = render(empty, *program, eye, {0, 0, 0}, 4);
    EXPECT_EQ(coveredCount(image), 0u);

    const StemSetField one({instance({0, 0, 0}, 0.3f, {0, 1, 0}, 0.0f, {0.1f, 0.7f, 0.3f, 1.0f},
                                     {0.1f, 0.05f, 0.05f, 0.0f})});
    gl::Framebuffer framebuffer(SIDE, SIDE, 1);
    framebuffer.bind();
    glEnable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    program->use();
    const gl::UniformBlock<render::LightingBlock> lighting = uploadLighting(0);
    one.draw(*program, 3);
    EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    glDisable(GL_CULL_FACE);
}

}  // namespace
}  // namespace grass::test
