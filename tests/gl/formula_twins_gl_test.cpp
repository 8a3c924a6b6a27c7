// The GLSL formulas against their C++ twins: tests/gl/shaders/formula_twins.comp runs the
// functions of shaders/include/grass_lighting.glsl and shaders/include/cull_rules.glsl (the
// files the passes include, not copies) on seeded inputs and on grids of the scalar arguments;
// core/scene/grass_lighting_formulas.h and core/scene/cull_rules.h, which unit tests pin to
// hand-computed values, must give the same results. A constant or term changed on one side
// only fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/uniform_block.h"
#include "gl_context_fixture.h"
#include "scene/cull_rules.h"
#include "scene/frame_lighting.h"
#include "scene/grass_lighting_formulas.h"
#include "support/test_paths.h"
#include "util/rng.h"

namespace grass::test {
namespace {

using FormulaTwins = GlTest;

// FormulaCase of formula_twins.comp (std430: eleven vec4).
struct FormulaCase {
    glm::vec4 albedoAo{0.0f};
    glm::vec4 bladeNormalWater{0.0f};
    glm::vec4 terrainNormalHeight{0.0f};
    glm::vec4 blurredNormalDistance{0.0f};
    glm::vec4 toEyeNv{0.0f};
    glm::vec4 toLightNh{0.0f};
    glm::vec4 dirViewAlpha{0.0f};
    glm::vec4 dirWidthDproj{0.0f};
    glm::vec4 toBladeMaxDistance{0.0f};
    glm::vec4 up{0.0f};
    glm::uvec4 classesIndex{0u};

    core::GrassSurface surface() const {
        core::GrassSurface s;
        s.albedo = glm::vec3(albedoAo);
        s.bladeNormal = glm::vec3(bladeNormalWater);
        s.terrainNormal = glm::vec3(terrainNormalHeight);
        s.blurredNormal = glm::vec3(blurredNormalDistance);
        s.ao = albedoAo.w;
        s.water = bladeNormalWater.w;
        s.height = terrainNormalHeight.w;
        s.toEye = glm::vec3(toEyeNv);
        s.eyeDistance = blurredNormalDistance.w;
        s.sunVisibility = up.w;
        return s;
    }
};
static_assert(sizeof(FormulaCase) == 11 * 16, "FormulaCase must match formula_twins.comp");

// FormulaResult of formula_twins.comp.
struct FormulaResult {
    glm::vec4 lightingLobes{0.0f};
    glm::vec4 ggxSchlickDproj{0.0f};
    glm::uvec4 keptKeptByEdgeOn{0u};
};
static_assert(sizeof(FormulaResult) == 3 * 16, "FormulaResult must match formula_twins.comp");

constexpr std::uint64_t SEED = 30;
constexpr std::uint32_t CASES_PER_BLOCK = 4096;
constexpr std::uint32_t WORK_GROUP = 64;  // local_size_x of formula_twins.comp

// Both sides evaluate the same float expressions in the same order; what differs is how the
// driver computes pow, normalize (inversesqrt), division and dot (GLSL allows pow 3 + 2|y·log2 x|
// ULP, inversesqrt 2 ULP, division 2.5 ULP, and fused multiply-adds anywhere). On the scalar
// functions those few ULP stay near 1e-7 relative on llvmpipe (with x⁵ and a quotient of
// squares in the chain); 2e-5 of the magnitude (floored at 1, for results near 0) leaves room
// for other drivers, yet fails on a changed constant or term (each one tried, F0 0.05 for 0.04,
// ambient 0.36 for 0.35, a lobe weight, the clamp, moved some result by 1e-3 or more).
constexpr float RELATIVE_TOLERANCE = 2e-5f;
// Near a narrow lobe's peak GGX is ill-conditioned: D ∝ 1/d², d = (n·h)²(α² − 1) + 1 ≈ α², so an
// error δ in n·h changes D by about 4δ/α² relative (α = 0.005: 1.6e5·δ); one ULP of n·h from the
// GLSL's normalize moves the lobes by far more than the tolerance above, with both sides right.
// d itself cancels there (α² − 1 rounds to a ULP of 1, 2e-3 of α² = 2.5e-5), so even ggxD on
// the same inputs depends on how the driver fuses or reorders the expression (llvmpipe returns
// 1/(πα²) exactly at n·h = 1, α = 0.005, where the C++ is 0.2 % above it). So the C++ value is
// bracketed by the twin at n·h (or the normals) scaled by 1 ± 8 ULP of 1, and the GLSL must land
// in that bracket within RELATIVE_TOLERANCE.
constexpr float NORMAL_SCALE = 8.0f * 0.5f * std::numeric_limits<float>::epsilon();
// Float expressions near a decision boundary may round either way under those ULP: a keep count
// n·(1 − dproj/dmax) this close to an integer, or a |dot| this close to 0.9, is not compared.
constexpr float BOUNDARY_BAND = 1e-5f;

glm::vec3 randomUnit(Rng& rng) {
    for (;;) {
        const glm::vec3 v{rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                          rng.uniform(-1.0f, 1.0f)};
        const float length2 = glm::dot(v, v);
        if (length2 > 0.01f && length2 <= 1.0f)
            return v / std::sqrt(length2);
    }
}

glm::vec3 randomColor(Rng& rng, float hi) {
    return {rng.uniform(0.0f, hi), rng.uniform(0.0f, hi), rng.uniform(0.0f, hi)};
}

// The project's default lighting, then seeded ones over the settings' whole ranges, then two of
// them with the article's model.
std::vector<core::LightingBlock> lightingBlocks() {
    std::vector<core::LightingBlock> blocks{core::frameLighting(
        core::GrassLightingDesc{}, core::SunDesc{}, {0.5f, 0.7f, 1.0f}, {0.3f, 0.25f, 0.2f})};
    Rng rng(SEED, 1);
    for (int i = 0; i < 3; ++i) {
        core::LightingBlock b;
        b.sunDirection = randomUnit(rng);
        b.terrainNormalWeight = rng.uniform();
        b.sunColor = randomColor(rng, 3.0f);
        b.specular = rng.uniform(0.0f, 2.0f);
        b.skyColor = randomColor(rng, 1.0f);
        b.transmission = rng.uniform(0.0f, 2.0f);
        b.groundColor = randomColor(rng, 1.0f);
        b.transmissionDistortion = rng.uniform();
        b.diffuseLow = randomColor(rng, 1.0f);
        b.transmissionPower = rng.uniform(0.5f, 8.0f);
        b.diffuseMid = randomColor(rng, 1.0f);
        b.sss = rng.uniform();
        b.diffuseHigh = randomColor(rng, 1.0f);
        b.sssIntensity = rng.uniform();
        b.specularFadeM.x = rng.uniform(0.0f, 10.0f);
        b.specularFadeM.y = b.specularFadeM.x + rng.uniform(1.0f, 20.0f);
        b.grassLighting = core::GRASS_LIGHTING;
        blocks.push_back(b);
    }
    // The article's model (LightingModel::Article) under the default and a seeded lighting.
    for (std::size_t i : {std::size_t(0), std::size_t(1)}) {
        core::LightingBlock b = blocks[i];
        b.grassLighting = core::ARTICLE_LIGHTING;
        blocks.push_back(b);
    }
    return blocks;
}

// Cases for one lighting block: random surfaces (a quarter of them near the mirror direction,
// where the narrow lobes peak and the clamp at 4 acts), grids of ggxD's (n·h, α), schlickF's n·v
// and the keep count's (n, dproj/dmax), orientation views spread around the 0.9 threshold.
std::vector<FormulaCase> makeCases(const core::LightingBlock& block, std::uint64_t stream) {
    Rng rng(SEED, stream);
    const glm::vec3 toLight = -block.sunDirection;
    const float maxDistances[] = {1e-3f, 1.0f, 30.0f, 100.0f, 250.0f};
    std::vector<FormulaCase> cases(CASES_PER_BLOCK);
    // Braced initializers evaluate their arguments in order (a call's may not), so a seed draws
    // the same cases with every compiler.
    for (std::uint32_t i = 0; i < CASES_PER_BLOCK; ++i) {
        FormulaCase& c = cases[i];
        c.albedoAo = glm::vec4{randomColor(rng, 1.0f), rng.uniform(0.2f, 1.0f)};
        const glm::vec3 n = randomUnit(rng);
        glm::vec3 toEye = randomUnit(rng);
        glm::vec3 caseLight = randomUnit(rng);
        if (i % 4 == 0) {
            // Near the mirror of the sun about n: the half vector within a few degrees of n.
            toEye = glm::normalize(glm::reflect(-toLight, n) + 0.05f * randomUnit(rng));
            caseLight = glm::normalize(glm::reflect(-toEye, n) + 0.02f * randomUnit(rng));
        }
        c.bladeNormalWater = glm::vec4{n, rng.uniform()};
        c.terrainNormalHeight = glm::vec4{i % 4 == 0 ? n : randomUnit(rng), rng.uniform()};
        c.blurredNormalDistance = glm::vec4{randomUnit(rng), rng.uniform(0.0f, 40.0f)};
        c.toEyeNv = glm::vec4(toEye, float(i % 257) / 256.0f);
        c.toLightNh = glm::vec4(caseLight, float(i % 101) / 100.0f);
        const glm::vec3 width = randomUnit(rng);
        glm::vec3 view = randomUnit(rng);
        if (i % 2 == 0) {
            // |cos| spread over [0.85, 0.95] around the threshold, either sign.
            const glm::vec3 across = glm::normalize(glm::cross(width, randomUnit(rng)));
            const float cosine = rng.uniform(0.85f, 0.95f) * (i % 4 == 0 ? 1.0f : -1.0f);
            view = cosine * width + std::sqrt(1.0f - cosine * cosine) * across;
        }
        c.dirViewAlpha = glm::vec4(view, 0.005f + 0.995f * float(i / 101 % 20) / 19.0f);
        const float maxDistance = maxDistances[i / 16 % 5];
        // dproj/dmax on a grid of hundredths to 1.3: n·(1 − k/100) is often an integer.
        const float dproj = float(i / 80 % 131) / 100.0f * maxDistance;
        c.dirWidthDproj = glm::vec4(width, dproj);
        c.toBladeMaxDistance = glm::vec4{rng.uniform(-100.0f, 100.0f), rng.uniform(-100.0f, 100.0f),
                                         rng.uniform(-100.0f, 100.0f), maxDistance};
        // Half the cases in full sun, the rest anywhere from shadow to sun.
        c.up = glm::vec4(randomUnit(rng), i % 2 == 0 ? 1.0f : rng.uniform(0.0f, 1.0f));
        c.classesIndex = glm::uvec4(1u + i % 16u, rng.below(100000), 0u, 0u);
    }
    return cases;
}

// Runs formula_twins.comp over `cases` under `block`.
std::vector<FormulaResult> runShader(const gl::Program& program, const core::LightingBlock& block,
                                     const std::vector<FormulaCase>& cases) {
    gl::UniformBlock<core::LightingBlock> lighting("formula twins lighting");
    lighting.upload(block);
    const gl::Buffer input = gl::Buffer::fromVector(cases, "formula twins cases");
    // NaN everywhere first: a case the shader never wrote cannot pass by accident.
    FormulaResult sentinel;
    sentinel.lightingLobes = glm::vec4(std::numeric_limits<float>::quiet_NaN());
    sentinel.ggxSchlickDproj = sentinel.lightingLobes;
    sentinel.keptKeptByEdgeOn = glm::uvec4(0xDEADBEEFu);
    const gl::Buffer output = gl::Buffer::fromVector(
        std::vector<FormulaResult>(cases.size(), sentinel), "formula twins results");
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    program.use();
    program.set("uCaseCount", static_cast<unsigned>(cases.size()));
    glDispatchCompute((static_cast<GLuint>(cases.size()) + WORK_GROUP - 1) / WORK_GROUP, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<FormulaResult> results(cases.size());
    const std::vector<std::byte> bytes = output.read(0, output.size());
    std::memcpy(results.data(), bytes.data(), bytes.size());
    return results;
}

gl::Program loadProgram() {
    // An absolute path: the includes resolve against shaders/include, as the passes' do.
    auto program = gl::Program::load(
        {{GL_COMPUTE_SHADER, (sourceDir() / "tests/gl/shaders/formula_twins.comp").string()}},
        "formula twins");
    EXPECT_TRUE(program.ok()) << (program.ok() ? "" : program.error().str());
    return program.ok() ? std::move(*program) : gl::Program{};
}

// The C++ value and the range of the twin under the normals' perturbation (NORMAL_SCALE).
struct Bracket {
    float value = 0.0f;
    float lo = 0.0f;
    float hi = 0.0f;
};

// `twin(scale)` evaluated at the normals scaled by 1 − NORMAL_SCALE, 1 and 1 + NORMAL_SCALE.
template <class Twin>
std::array<Bracket, 4> bracketOf(Twin&& twin) {
    const glm::vec4 below = twin(1.0f - NORMAL_SCALE), value = twin(1.0f),
                    above = twin(1.0f + NORMAL_SCALE);
    std::array<Bracket, 4> out;
    for (int k = 0; k < 4; ++k)
        out[k] = {value[k], std::min({below[k], value[k], above[k]}),
                  std::max({below[k], value[k], above[k]})};
    return out;
}

// How far the GLSL result lies from the C++ one (and outside its bracket), relative to the
// magnitude floored at 1; the largest of each, for the report.
struct Agreement {
    const char* what;
    float worstDifference = 0.0f;
    float worstOutside = 0.0f;
    std::size_t compared = 0;

    ::testing::AssertionResult check(float gpu, float cpu) { return check(gpu, {cpu, cpu, cpu}); }
    ::testing::AssertionResult check(float gpu, Bracket cpu) {
        ++compared;
        const float scale = std::max(1.0f, std::abs(cpu.value));
        const float difference = std::abs(gpu - cpu.value) / scale;
        const float outside = std::max({cpu.lo - gpu, gpu - cpu.hi, 0.0f}) / scale;
        if (!(outside <= RELATIVE_TOLERANCE))  // NaN fails too
            return ::testing::AssertionFailure()
                   << what << ": GLSL " << gpu << ", C++ " << cpu.value << " in [" << cpu.lo << ", "
                   << cpu.hi << "] (relative " << outside << " outside)";
        worstDifference = std::max(worstDifference, difference);
        worstOutside = std::max(worstOutside, outside);
        return ::testing::AssertionSuccess();
    }
    void print() const {
        std::printf(
            "[ formulas ] %-18s %6zu values, largest relative difference %.3g, "
            "outside the bracket %.3g\n",
            what, compared, static_cast<double>(worstDifference),
            static_cast<double>(worstOutside));
    }
};

TEST_F(FormulaTwins, GrassLightingMatchesItsCppTwin) {
    const gl::Program program = loadProgram();
    ASSERT_NE(program.id(), 0u);
    Agreement lighting{"grassLighting"}, lobes{"specularLobes"}, ggx{"ggxD"}, schlick{"schlickF"};
    const std::vector<core::LightingBlock> blocks = lightingBlocks();
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const std::vector<FormulaCase> cases = makeCases(blocks[b], 10 + b);
        const std::vector<FormulaResult> results = runShader(program, blocks[b], cases);
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const FormulaCase& c = cases[i];
            const FormulaResult& r = results[i];
            const core::GrassSurface s = c.surface();
            const float article = blocks[b].grassLighting == core::ARTICLE_LIGHTING ? 1.0f : 0.0f;
            const std::array<Bracket, 4> cpu = bracketOf([&](float scale) {
                core::GrassSurface scaled = s;
                scaled.bladeNormal *= scale;
                scaled.terrainNormal *= scale;
                const glm::vec3 toLight(c.toLightNh);
                return glm::vec4(
                    core::grassLighting(scaled, blocks[b]),
                    core::specularLobes(scaled.bladeNormal, toLight, s.toEye, s.water,
                                        article));
            });
            for (int k = 0; k < 3; ++k)
                ASSERT_TRUE(lighting.check(r.lightingLobes[k], cpu[k]))
                    << "block " << b << " case " << i << " channel " << k << " seed " << SEED;
            ASSERT_TRUE(lobes.check(r.lightingLobes.w, cpu[3]))
                << "block " << b << " case " << i << " seed " << SEED;
            const float nh = c.toLightNh.w, alpha = c.dirViewAlpha.w;
            const Bracket ggxCpu =
                bracketOf([&](float scale) { return glm::vec4(core::ggxD(nh * scale, alpha)); })[0];
            ASSERT_TRUE(ggx.check(r.ggxSchlickDproj.x, ggxCpu))
                << "n·h " << c.toLightNh.w << " α " << c.dirViewAlpha.w;
            ASSERT_TRUE(schlick.check(r.ggxSchlickDproj.y, core::schlickF(c.toEyeNv.w)))
                << "n·v " << c.toEyeNv.w;
        }
    }
    for (const Agreement* a : {&lighting, &lobes, &ggx, &schlick})
        a->print();
}

TEST_F(FormulaTwins, CullRulesMatchTheirCppTwin) {
    const gl::Program program = loadProgram();
    ASSERT_NE(program.id(), 0u);
    const core::LightingBlock block = lightingBlocks().front();
    const std::vector<FormulaCase> cases = makeCases(block, 20);
    const std::vector<FormulaResult> results = runShader(program, block, cases);
    Agreement dproj{"projectedDistance"};
    std::size_t keptCompared = 0, keptOnBoundary = 0, keptOffByOne = 0;
    std::size_t edgeCompared = 0, edgeOnBoundary = 0, edgeDiffers = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const FormulaCase& c = cases[i];
        const FormulaResult& r = results[i];
        ASSERT_TRUE(
            dproj.check(r.ggxSchlickDproj.z,
                        core::projectedDistance(glm::vec3(c.toBladeMaxDistance), glm::vec3(c.up))))
            << "case " << i;

        const std::uint32_t classes = c.classesIndex.x, index = c.classesIndex.y;
        const float d = c.dirWidthDproj.w, maxDistance = c.toBladeMaxDistance.w;
        // n·(1 − dproj/dmax) before the clamp: at dproj = dmax too the GPU's quotient may fall a
        // ULP short of 1 and keep a class.
        const float share = float(classes) * (1.0f - d / maxDistance);
        const float band = BOUNDARY_BAND * float(classes);
        if (share > -band && std::abs(share - std::round(share)) < band) {
            // An exact integer on the CPU; the GPU's division may land a ULP either side.
            ++keptOnBoundary;
            const int off = std::abs(int(r.keptKeptByEdgeOn.x) -
                                     int(core::distanceKeptCount(classes, d, maxDistance)));
            EXPECT_LE(off, 1) << "case " << i;
            keptOffByOne += off != 0 ? 1u : 0u;
        } else {
            ++keptCompared;
            ASSERT_EQ(r.keptKeptByEdgeOn.x, core::distanceKeptCount(classes, d, maxDistance))
                << "case " << i << ": n " << classes << " dproj " << d << " dmax " << maxDistance;
            ASSERT_EQ(r.keptKeptByEdgeOn.y != 0u,
                      core::keptByDistance(index, classes, d, maxDistance))
                << "case " << i << ": index " << index << " n " << classes;
        }

        const glm::vec3 view(c.dirViewAlpha), width(c.dirWidthDproj);
        if (std::abs(std::abs(glm::dot(view, width)) - core::ORIENTATION_CULL_COS) <
            BOUNDARY_BAND) {
            ++edgeOnBoundary;
            edgeDiffers += (r.keptKeptByEdgeOn.z != 0u) != core::seenEdgeOn(view, width) ? 1u : 0u;
            continue;
        }
        ++edgeCompared;
        ASSERT_EQ(r.keptKeptByEdgeOn.z != 0u, core::seenEdgeOn(view, width))
            << "case " << i << ": |cos| " << std::abs(glm::dot(view, width));
    }
    dproj.print();
    std::printf(
        "[ formulas ] distanceKeptCount %6zu exact, %zu within %.0e of an integer (%zu "
        "of them one apart)\n",
        keptCompared, keptOnBoundary, static_cast<double>(BOUNDARY_BAND), keptOffByOne);
    std::printf(
        "[ formulas ] seenEdgeOn        %6zu exact, %zu within %.0e of 0.9 (%zu of them "
        "differ)\n",
        edgeCompared, edgeOnBoundary, static_cast<double>(BOUNDARY_BAND), edgeDiffers);
    // The grid must reach both sides of each rule, and mostly away from the boundaries.
    EXPECT_GT(keptCompared, cases.size() / 2);
    EXPECT_GT(edgeCompared, cases.size() * 9 / 10);
}

}  // namespace
}  // namespace grass::test
