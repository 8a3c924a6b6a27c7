#include "scene/layer_growth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "mesh/procedural.h"
#include "scene/scene.h"

namespace grass::core {
namespace {

constexpr std::uint32_t PATCH_SIZE = 64;
constexpr std::uint64_t SEED = 42;

SurfaceMesh plane(float size = 4.0f) {
    ProceduralMeshParams params;
    params.shape = ProceduralShape::Plane;
    params.size = size;
    params.resolution = 8;
    return makeProceduralMesh(params);
}

LayerSource sourceOn(const SurfaceMesh& mesh, float density = 200.0f) {
    ScatterParams scatter;
    scatter.density = density;
    LayerSource source;
    source.candidates = scatterCandidates(mesh, scatter, SEED);
    return source;
}

// u = 0 → 0, u = 1 → 1: the soil ramp of the golden image.
MapImage rampU(int width, int height) {
    MapImage map = makeConstantMap(width, height, 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            map.texels[static_cast<std::size_t>(y * width + x)] =
                (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
    return map;
}

float angleBetween(glm::vec3 a, glm::vec3 b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

TEST(LayerGrowth, WithoutMapsOrGrowthEverySlotHoldsItsCandidate) {
    const SurfaceMesh mesh = plane();
    const LayerSource source = sourceOn(mesh);
    const GrownField field = growField(source, PATCH_SIZE);
    ASSERT_GT(source.candidates.blades.size(), 1000u);
    EXPECT_EQ(field.liveBlades, source.candidates.blades.size());
    for (std::size_t slot = 0; slot < field.patched.blades.size(); ++slot) {
        const std::uint32_t candidate = field.patched.sourceIndex[slot];
        if (candidate == UINT32_MAX)
            continue;
        EXPECT_EQ(field.patched.blades[slot], source.candidates.blades[candidate]);
        EXPECT_EQ(field.wilt[slot], 0.0f);
    }
}

TEST(LayerGrowth, DensityMapKeepsWhatScatterBladesKeeps) {
    const SurfaceMesh mesh = plane();
    LayerSource source = sourceOn(mesh);
    source.maps.density = rampU(32, 32);
    const GrownField field = growField(source, PATCH_SIZE);
    ScatterParams scatter;
    scatter.density = 200.0f;
    const ScatterResult thinned = scatterBlades(mesh, scatter, &source.maps.density, SEED);
    EXPECT_EQ(field.liveBlades, thinned.blades.size());
    std::size_t live = 0;
    for (const Blade& blade : field.patched.blades)
        live += blade.h() > 0.0f ? 1 : 0;
    EXPECT_EQ(live, thinned.blades.size());
    // About half the candidates survive a 0→1 ramp.
    const double share = static_cast<double>(live) / static_cast<double>(source.candidates.blades.size());
    EXPECT_NEAR(share, 0.5, 0.05);
}

TEST(LayerGrowth, SoilRampGrowsTallerWiderGreenerBladesOnTheGoodSide) {
    const SurfaceMesh mesh = plane();
    LayerSource source = sourceOn(mesh);
    source.maps.soil = rampU(64, 64);
    source.growthEnabled = true;
    const GrownField field = growField(source, PATCH_SIZE);
    double heightPoor = 0, heightGood = 0, widthPoor = 0, widthGood = 0, wiltPoor = 0,
           wiltGood = 0;
    int poor = 0, good = 0;
    for (std::size_t slot = 0; slot < field.patched.blades.size(); ++slot) {
        const std::uint32_t candidate = field.patched.sourceIndex[slot];
        if (candidate == UINT32_MAX)
            continue;
        const Blade& grown = field.patched.blades[slot];
        const Blade& original = source.candidates.blades[candidate];
        ASSERT_GT(grown.h(), 0.0f);
        ASSERT_LE(grown.h(), original.h());
        ASSERT_LE(grown.w(), original.w());
        const float u = source.candidates.uvs[candidate].x;
        // The rest lean is the growth model's θ, towards the blade's front (validation keeps
        // the tip on that side; the angle is the chord's).
        const float g = source.maps.soil.sample(source.candidates.uvs[candidate]);
        const GrowthParams expected = growthParams(source.curves, g, 1.0f);
        EXPECT_NEAR(angleBetween(grown.v2() - grown.v0(), grown.up()), expected.theta, 0.02f);
        EXPECT_NEAR(grown.h(), original.h() * expected.beta, 1e-5f * original.h());
        EXPECT_NEAR(field.wilt[slot], 1.0f - expected.b, 1e-6f);
        if (u < 0.2f) {
            heightPoor += grown.h() / original.h();
            widthPoor += grown.w() / original.w();
            wiltPoor += field.wilt[slot];
            ++poor;
        } else if (u > 0.8f) {
            heightGood += grown.h() / original.h();
            widthGood += grown.w() / original.w();
            wiltGood += field.wilt[slot];
            ++good;
        }
    }
    ASSERT_GT(poor, 100);
    ASSERT_GT(good, 100);
    // Default curves at l = 1 (full light: short, wide grass): β 0.15 → 0.6, width α/0.25
    // 0.5 → 0.95, b 0.325 → 0.775 across the ramp; the 20 % bands average a little inside those.
    EXPECT_GT(heightGood / good, 1.6 * heightPoor / poor);
    EXPECT_GT(widthGood / good, 1.5 * widthPoor / poor);
    EXPECT_LT(wiltGood / good, 0.5 * wiltPoor / poor);
}

TEST(LayerGrowth, StemSetsSitOnEverySixthLiveSlot) {
    const SurfaceMesh mesh = plane();
    LayerSource source = sourceOn(mesh);
    source.maps.density = rampU(16, 16);
    source.growthEnabled = true;
    const GrownField field = growField(source, PATCH_SIZE);
    ASSERT_EQ(field.stemSets.size(), (field.patched.blades.size() + 5) / 6);
    for (std::size_t k = 0; k < field.stemSets.size(); ++k) {
        const Blade& blade = field.patched.blades[k * STEMS_PER_SET];
        const StemSetInstance& set = field.stemSets[k];
        if (blade.h() > 0.0f) {
            EXPECT_EQ(glm::vec3(set.rootMetresPerUnit), blade.v0());
            EXPECT_GT(set.rootMetresPerUnit.w, 0.0f);
        } else {
            EXPECT_EQ(set.rootMetresPerUnit.w, 0.0f) << "a removed blade grows no stem set";
        }
    }
}

// A repaint re-grows only the patches it reaches, and they come out exactly as a full re-grow
// on the repainted maps.
TEST(LayerGrowth, RegrowingARegionMatchesAFullRegrow) {
    const SurfaceMesh mesh = plane();
    LayerSource source = sourceOn(mesh);
    source.growthEnabled = true;
    source.maps.soil = makeConstantMap(64, 64, 0.2f);
    source.maps.density = makeConstantMap(64, 64, 0.6f);
    LayerField layer;
    static_cast<GrownField&>(layer) = growField(source, PATCH_SIZE);
    layer.source = source;
    layer.seed = SEED;
    const GrassLightingDesc lighting;
    layer.shading = *bakeBladeShading(layer.patched.blades, bladeShadingParams(lighting), SEED);
    const LayerField before = layer;

    // Paint texels 40..47 × 40..47 (u, v in [0.625, 0.75)): soil to 1 and density to 1.
    for (int y = 40; y < 48; ++y)
        for (int x = 40; x < 48; ++x) {
            layer.source.maps.soil.texels[static_cast<std::size_t>(y * 64 + x)] = 1.0f;
            layer.source.maps.density.texels[static_cast<std::size_t>(y * 64 + x)] = 1.0f;
        }
    // On the 4 m plane those texels span 0.5 m; the painted box in world space, found from the
    // candidates whose bilinear footprint touches them.
    Bounds painted{glm::vec3(1e9f), glm::vec3(-1e9f)};
    for (std::size_t i = 0; i < source.candidates.blades.size(); ++i) {
        const glm::vec2 uv = source.candidates.uvs[i] * 64.0f;
        if (uv.x > 39.5f && uv.x < 48.5f && uv.y > 39.5f && uv.y < 48.5f) {
            painted.min = glm::min(painted.min, source.candidates.blades[i].v0());
            painted.max = glm::max(painted.max, source.candidates.blades[i].v0());
        }
    }
    const auto report = regrowLayerRegion(layer, painted, 4.0f / 64.0f, lighting);
    ASSERT_TRUE(report) << report.error().str();
    ASSERT_FALSE(report->patches.empty());
    EXPECT_LT(report->patches.size(), layer.patched.patches.size() / 4)
        << "a small dab must not re-grow most of the field";

    GrownField full = growField(layer.source, PATCH_SIZE);
    ASSERT_EQ(full.patched.blades.size(), layer.patched.blades.size());
    for (std::size_t slot = 0; slot < full.patched.blades.size(); ++slot) {
        ASSERT_EQ(layer.patched.blades[slot], full.patched.blades[slot]) << "slot " << slot;
        ASSERT_EQ(layer.wilt[slot], full.wilt[slot]);
    }
    EXPECT_EQ(layer.liveBlades, full.liveBlades);
    EXPECT_GT(layer.liveBlades, before.liveBlades) << "density painted up adds blades";
    for (std::size_t k = 0; k < full.stemSets.size(); ++k)
        ASSERT_EQ(std::memcmp(&layer.stemSets[k], &full.stemSets[k], sizeof(StemSetInstance)), 0);

    // Shading: untouched far away, close to a full bake inside the re-baked region.
    const auto fullShading =
        *bakeBladeShading(layer.patched.blades, bladeShadingParams(lighting), SEED);
    float worstAo = 0.0f;
    std::size_t changed = 0;
    for (std::size_t slot = 0; slot < fullShading.size(); ++slot) {
        const glm::vec3 root = layer.patched.blades[slot].v0();
        const Bounds& r = report->shadedRegion;
        const bool inside = glm::all(glm::greaterThanEqual(root, r.min)) &&
                            glm::all(glm::lessThanEqual(root, r.max));
        if (!inside) {
            ASSERT_EQ(layer.shading[slot], before.shading[slot]) << "slot " << slot;
            continue;
        }
        changed += layer.shading[slot] == before.shading[slot] ? 0 : 1;
        worstAo = std::max(worstAo, std::abs(layer.shading[slot].ao() - fullShading[slot].ao()));
        EXPECT_EQ(layer.shading[slot].waterAge.z, layer.wilt[slot]);
    }
    EXPECT_GT(changed, 0u);
    // Two cluster approximations (the bake's own: < 0.003 against exact sums) differ a little.
    EXPECT_LT(worstAo, 0.01f);
}

// Soil and light reshape and recolour blades but add or remove none, and the shading bake sums
// blade counts and surface normals only: a soil repaint re-bakes nothing, and the shading comes
// out exactly as a full bake of the repainted field (with the new wilt).
TEST(LayerGrowth, SoilRepaintKeepsTheBakeAndUpdatesTheWilt) {
    const SurfaceMesh mesh = plane();
    LayerField layer;
    layer.source = sourceOn(mesh);
    layer.source.growthEnabled = true;
    layer.source.maps.soil = makeConstantMap(64, 64, 0.3f);
    static_cast<GrownField&>(layer) = growField(layer.source, PATCH_SIZE);
    layer.seed = SEED;
    const GrassLightingDesc lighting;
    layer.shading = *bakeBladeShading(layer.patched.blades, bladeShadingParams(lighting), SEED);
    for (std::size_t slot = 0; slot < layer.shading.size(); ++slot)
        layer.shading[slot].waterAge.z = layer.wilt[slot];

    for (int y = 8; y < 24; ++y)
        for (int x = 8; x < 24; ++x)
            layer.source.maps.soil.texels[static_cast<std::size_t>(y * 64 + x)] = 1.0f;
    // Texels 8..23 of 64 on the 4 m plane: x and z in [−1.5, −0.5] m.
    const Bounds painted{{-1.5f, -0.1f, -1.5f}, {-0.5f, 0.1f, -0.5f}};
    const auto report = regrowLayerRegion(layer, painted, 4.0f / 64.0f, lighting);
    ASSERT_TRUE(report) << report.error().str();
    ASSERT_FALSE(report->patches.empty());
    EXPECT_EQ(report->bladesAddedOrRemoved, 0u);
    EXPECT_EQ(report->rebakedBlades, 0u);
    EXPECT_EQ(report->shadedPatches, report->patches) << "only the wilt of regrown slots moved";

    auto full = *bakeBladeShading(layer.patched.blades, bladeShadingParams(lighting), SEED);
    std::size_t wiltChanged = 0;
    for (std::size_t slot = 0; slot < full.size(); ++slot) {
        full[slot].waterAge.z = layer.wilt[slot];
        ASSERT_EQ(layer.shading[slot], full[slot]) << "slot " << slot;
        wiltChanged += layer.wilt[slot] < 0.3f ? 1 : 0;  // good soil: b 0.775, soil 0.2: 0.42
    }
    EXPECT_GT(wiltChanged, 0u);
}

}  // namespace
}  // namespace grass::core
