// The far field follows the near field (core/scene/billboard_follow.h, issue 30 item 3): a path
// painted out of the density map has no billboards either, half density keeps about half, the
// placement rules clear them as they clear blades, growth tints and shortens them, and an
// unpainted field keeps every placed object exactly as placed.
#include "scene/billboard_follow.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

// A 6 m plane with one layer and 20 billboards a square metre (720 placed), drawn by the hybrid
// technique (a scene of blades alone places none: placeBillboards).
Scene fieldScene(LoadedProject loaded = test::planeFieldProject({6.0f, 4, 40.0f})) {
    loaded.project.billboards.placement.density = 20.0f;
    loaded.project.render.technique = GrassTechnique::Hybrid;
    auto scene = buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return std::move(*scene);
}

// A map of `side`² texels that is `inside` where u ∈ [u0, u1) and `outside` elsewhere.
MapImage stripeMap(int side, float u0, float u1, float inside, float outside) {
    MapImage map = makeConstantMap(side, side, outside);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(side);
            if (u >= u0 && u < u1)
                map.texels[static_cast<std::size_t>(y * side + x)] = inside;
        }
    return map;
}

TEST(BillboardFollow, AnUnpaintedFieldDrawsEveryPlacedObjectAsPlacedInItsBladesColour) {
    const Scene scene = fieldScene();
    const auto& placed = scene.billboards.placed;
    const auto& drawn = scene.billboards.objects;
    ASSERT_GT(placed.size(), 600u);
    ASSERT_EQ(drawn.size(), placed.size());
    // One tint for all: the texture's mean colour times it is the blades' visible colour,
    // root + 0.75·(tip − root).
    const LayerField& layer = scene.layers[0];
    const glm::vec3 visible = layer.rootColor + 0.75f * (layer.tipColor - layer.rootColor);
    const glm::vec3 texture = meanGrassColour(scene.billboards.texture);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        GrassObject untinted = drawn[i];
        untinted.tint = placed[i].tint;
        EXPECT_EQ(untinted, placed[i]);
        EXPECT_EQ(drawn[i].tint, drawn[0].tint);
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(drawn[0].tint[c] * texture[c], visible[c], 1e-5f) << "channel " << c;
}

TEST(BillboardFollow, APathPaintedOutOfTheDensityHasNoBillboards) {
    Scene scene = fieldScene();
    const std::size_t placed = scene.billboards.placed.size();
    // A path a quarter of the field wide, painted to 0; bilinear reads blur one texel each side.
    const int side = 64;
    scene.layers[0].source.maps.density = stripeMap(side, 0.375f, 0.625f, 0.0f, 1.0f);
    refreshBillboards(scene);
    const float texel = 1.0f / static_cast<float>(side);
    std::size_t outside = 0;
    for (const GrassObject& object : scene.billboards.objects) {
        EXPECT_FALSE(object.uv.x > 0.375f + texel && object.uv.x < 0.625f - texel)
            << "a billboard on the painted-out path at u = " << object.uv.x;
        outside += object.uv.x < 0.375f - texel || object.uv.x > 0.625f + texel ? 1 : 0;
    }
    std::size_t placedOutside = 0;
    for (const GrassObject& object : scene.billboards.placed)
        placedOutside += object.uv.x < 0.375f - texel || object.uv.x > 0.625f + texel ? 1 : 0;
    EXPECT_EQ(outside, placedOutside) << "away from the path every object stays";
    EXPECT_LT(scene.billboards.objects.size(), placed);
}

TEST(BillboardFollow, HalfTheDensityKeepsAboutHalfTheObjects) {
    Scene scene = fieldScene();
    const double placed = static_cast<double>(scene.billboards.placed.size());
    scene.layers[0].source.maps.density = makeConstantMap(16, 16, 0.5f);
    refreshBillboards(scene);
    const double kept = static_cast<double>(scene.billboards.objects.size());
    // Binomial(n, 0.5): 4 standard deviations.
    EXPECT_NEAR(kept, 0.5 * placed, 4.0 * std::sqrt(0.25 * placed));
    // The same objects as a blade would keep: keep < 0.5 exactly.
    for (const GrassObject& object : scene.billboards.objects)
        EXPECT_LT(object.keep, 0.5f);
}

TEST(BillboardFollow, TwoLayersKeepTheirBladeWeightedShare) {
    LoadedProject loaded = test::planeFieldProject({6.0f, 4, 30.0f});
    GrassLayer second = loaded.project.layers.front();
    second.name = "second";
    second.scatter.density = 90.0f;  // three times the first layer's blades
    loaded.project.layers.push_back(second);
    Scene scene = fieldScene(loaded);
    const double placed = static_cast<double>(scene.billboards.placed.size());
    // The first layer painted out entirely: a quarter of the near field's blades are gone.
    scene.layers[0].source.maps.density = makeConstantMap(8, 8, 0.0f);
    refreshBillboards(scene);
    const double kept = static_cast<double>(scene.billboards.objects.size());
    const double share = scene.billboards.follow.layerWeights[1] /
                         (scene.billboards.follow.layerWeights[0] +
                          scene.billboards.follow.layerWeights[1]);
    EXPECT_NEAR(share, 0.75, 0.05);
    EXPECT_NEAR(kept, share * placed, 4.0 * std::sqrt(share * (1.0 - share) * placed));
}

TEST(BillboardFollow, PlacementRulesClearBillboardsAsTheyClearBlades) {
    LoadedProject loaded = test::planeFieldProject({6.0f, 4, 40.0f});
    // The plane lies at y = 0: nothing may grow below 1 m, so nothing grows at all.
    loaded.project.layers.front().rules.altitudeMinM = 1.0f;
    const Scene cleared = fieldScene(loaded);
    EXPECT_GT(cleared.billboards.placed.size(), 600u);
    EXPECT_TRUE(cleared.billboards.objects.empty());
    EXPECT_EQ(cleared.layers[0].liveBlades, 0u);
    // A ball of radius 1 centred on the ground, cleared by 0.5 m: its surface is |r − 1| from a
    // ground point at radius r, so the ground within r < 1.5 is cleared, the inside of the ball
    // too (scatter/collider_interior.h: until 2026-12-07 the grass inside it stayed, hidden, as
    // the blades there did).
    loaded.project.layers.front().rules = {};
    loaded.project.layers.front().rules.clearanceM = 0.5f;
    loaded.project.layers.front().rules.clearColliders = true;
    test::addBall(loaded, {0.0f, 0.0f, 0.0f}, 1.0f);
    const Scene ringed = fieldScene(loaded);
    EXPECT_LT(ringed.billboards.objects.size(), ringed.billboards.placed.size());
    int beyond = 0;
    for (const GrassObject& object : ringed.billboards.objects) {
        const float r = glm::length(object.centre);
        EXPECT_FALSE(r < 1.45f) << "a billboard in or under the ball at r = " << r;
        beyond += r > 1.55f ? 1 : 0;
    }
    EXPECT_GT(beyond, 0);
    std::size_t under = 0;
    for (const Blade& blade : ringed.layers[0].patched.blades)
        under += blade.h() > 0.0f && glm::length(blade.v0()) < 1.45f ? 1 : 0;
    EXPECT_EQ(under, 0u) << "blades in or under the ball";
}

TEST(BillboardFollow, GrowthTintsAndShortensBillboardsWhereItGrowsPoorGrass) {
    LoadedProject loaded = test::planeFieldProject({6.0f, 4, 40.0f});
    GrassLayer& layer = loaded.project.layers.front();
    layer.growth.enabled = true;
    layer.rootColor = {0.1f, 0.4f, 0.1f};
    layer.tipColor = {0.3f, 0.7f, 0.2f};
    layer.growth.poorRootColor = {0.4f, 0.3f, 0.1f};
    layer.growth.poorTipColor = {0.7f, 0.6f, 0.2f};
    Scene scene = fieldScene(loaded);
    // Rich soil on the left half, none on the right.
    scene.layers[0].source.maps.soil = stripeMap(32, 0.5f, 1.01f, 0.0f, 1.0f);
    refreshBillboards(scene);
    const auto heightRatio = [&](const GrassObject& o) {
        for (const GrassObject& p : scene.billboards.placed)
            if (p.centre == o.centre)
                return o.height / p.height;
        return -1.0f;
    };
    double richRed = 0.0, poorRed = 0.0, richHeight = 0.0, poorHeight = 0.0;
    int rich = 0, poor = 0;
    for (const GrassObject& o : scene.billboards.objects) {
        if (o.uv.x < 0.4f) {
            richRed += o.tint.r, richHeight += heightRatio(o), ++rich;
        } else if (o.uv.x > 0.6f) {
            poorRed += o.tint.r, poorHeight += heightRatio(o), ++poor;
        }
    }
    ASSERT_GT(rich, 50);
    ASSERT_GT(poor, 20);
    // Poor soil: browner (more red than the healthy green) and shorter, as the blades there.
    EXPECT_GT(poorRed / poor, richRed / rich + 0.5);
    EXPECT_LT(poorHeight / poor, richHeight / rich - 0.1);
}

TEST(BillboardFollow, AMownPathMowsTheBillboardsToo) {
    Scene scene = fieldScene();
    // Cut to 40 % everywhere: every tuft stands at 40 % of its placed height, none is removed;
    // mown to the ground: none stands.
    scene.layers[0].source.maps.cut = makeConstantMap(8, 8, 0.4f);
    refreshBillboards(scene);
    ASSERT_EQ(scene.billboards.objects.size(), scene.billboards.placed.size());
    for (std::size_t i = 0; i < scene.billboards.placed.size(); ++i)
        EXPECT_NEAR(scene.billboards.objects[i].height,
                    0.4f * scene.billboards.placed[i].height, 1e-6f);
    scene.layers[0].source.maps.cut = makeConstantMap(8, 8, 0.0f);
    refreshBillboards(scene);
    EXPECT_TRUE(scene.billboards.objects.empty());
}

TEST(BillboardFollow, StiffnessIsTheLayersMeanBladeStiffness) {
    const Scene scene = fieldScene();
    double sum = 0.0;
    for (const Blade& blade : scene.layers[0].source.candidates.blades)
        sum += blade.s();
    const double mean = sum / static_cast<double>(scene.layers[0].source.candidates.blades.size());
    EXPECT_NEAR(scene.billboards.follow.stiffness, mean, 1e-3);
    const BladeRanges ranges;
    EXPECT_NEAR(scene.billboards.follow.stiffness,
                0.5f * (ranges.stiffnessMin + ranges.stiffnessMax), 2.0f);
}

TEST(BillboardFollow, TextureColourIsTheAlphaWeightedMean) {
    Rgba8Pixels texture;
    texture.width = 2;
    texture.height = 1;
    // An opaque red texel and a quarter-opaque blue one: (255, 0, 0)·1 + (0, 0, 255)·0.25.
    texture.pixels = {255, 0, 0, 255, 0, 0, 255, 64};
    const glm::vec3 mean = meanGrassColour(texture);
    EXPECT_NEAR(mean.r, 255.0f / 319.0f, 1e-6f);
    EXPECT_NEAR(mean.g, 0.0f, 1e-6f);
    EXPECT_NEAR(mean.b, 64.0f / 319.0f, 1e-6f);
}

TEST(BillboardFollow, WithoutLayersEveryObjectLives) {
    LoadedProject loaded = test::planeFieldProject({3.0f, 2, 10.0f});
    loaded.project.layers.clear();
    const Scene scene = fieldScene(loaded);
    EXPECT_FALSE(scene.billboards.objects.empty());
    EXPECT_EQ(scene.billboards.objects, scene.billboards.placed);
}

}  // namespace
}  // namespace grass::core
