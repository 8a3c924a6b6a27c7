// Cut and regrow (issue 30 item 10): a layer's cut map sets the height blades are cut to, as a
// share of their own (0 mows them away, an unpainted map changes nothing), and cut blades grow
// back at the layer's regrow rate over scene time, in steps, re-growing only the patches that
// hold cut blades.
#include <gtest/gtest.h>

#include <set>

#include "scene/scene.h"
#include "support/plane_project.h"

namespace grass::core {
namespace {

Scene plainField(float regrowRate = 0.0f) {
    LoadedProject loaded = test::planeFieldProject({4.0f, 4, 60.0f});
    loaded.project.layers.front().regrowRate = regrowRate;
    loaded.project.render.patchSize = 32;
    auto scene = buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return std::move(*scene);
}

void regrowAll(LayerField& layer) {
    static_cast<GrownField&>(layer) = growField(layer.source, layer.patched.patchSize);
}

// The cut map of a path: `share` where u ∈ [0.4, 0.6), 1 elsewhere.
MapImage mownPath(float share) {
    MapImage map = makeConstantMap(40, 40, 1.0f);
    for (int y = 0; y < 40; ++y)
        for (int x = 16; x < 24; ++x)
            map.texels[static_cast<std::size_t>(y * 40 + x)] = share;
    return map;
}

TEST(CutRegrow, BladesAreCutToTheMapsShareOfTheirHeight) {
    Scene scene = plainField();
    LayerField& layer = scene.layers[0];
    const PatchedBlades uncut = layer.patched;
    layer.source.maps.cut = makeConstantMap(8, 8, 1.0f);
    regrowAll(layer);
    EXPECT_EQ(layer.patched.blades, uncut.blades) << "a map of 1 cuts nothing";
    for (const float share : {0.75f, 0.3f}) {
        layer.source.maps.cut = makeConstantMap(8, 8, share);
        regrowAll(layer);
        for (std::size_t slot = 0; slot < uncut.blades.size(); ++slot) {
            if (uncut.blades[slot].h() <= 0.0f)
                continue;
            const Blade& cut = layer.patched.blades[slot];
            EXPECT_NEAR(cut.h(), share * uncut.blades[slot].h(), 1e-6f);
            EXPECT_EQ(cut.v0(), uncut.blades[slot].v0());
            EXPECT_EQ(cut.w(), uncut.blades[slot].w()) << "cut blades keep their width";
        }
    }
    layer.source.maps.cut = makeConstantMap(8, 8, 0.0f);
    regrowAll(layer);
    EXPECT_EQ(layer.liveBlades, 0u) << "mown to the ground";
}

TEST(CutRegrow, CutBladesGrowBackAtTheRegrowRate) {
    Scene scene = plainField(0.1f);  // a tenth of the height a second
    LayerField& layer = scene.layers[0];
    const PatchedBlades uncut = layer.patched;
    layer.source.maps.cut = mownPath(0.2f);
    regrowAll(layer);
    // The patches with a blade on the path, and the blades there.
    std::set<std::uint32_t> pathPatches;
    const std::uint32_t size = layer.patched.patchSize;
    for (std::size_t slot = 0; slot < uncut.blades.size(); ++slot)
        if (layer.patched.blades[slot].h() < uncut.blades[slot].h() - 1e-6f)
            pathPatches.insert(static_cast<std::uint32_t>(slot / size));
    ASSERT_FALSE(pathPatches.empty());
    ASSERT_LT(pathPatches.size(), layer.patched.patches.size());

    const RegrowReport at4 = regrowCut(layer, 4.0f);
    // Every patch with a cut blade, and only those (a patch may hold blades near the path's
    // edge, where the bilinear map reads between 0.2 and 1).
    for (std::uint32_t p : pathPatches)
        EXPECT_TRUE(std::count(at4.patches.begin(), at4.patches.end(), p)) << "patch " << p;
    EXPECT_LT(at4.patches.size(), layer.patched.patches.size());
    for (std::size_t slot = 0; slot < uncut.blades.size(); ++slot) {
        const float h = uncut.blades[slot].h();
        if (h <= 0.0f)
            continue;
        const float cut = layer.source.maps.cut.sample(
            layer.source.candidates.uvs[layer.patched.sourceIndex[slot]]);
        // 0.2 + 0.1·4 = 0.6 of the height on the path (to a step of 1 %).
        EXPECT_NEAR(layer.patched.blades[slot].h(), std::min(cut + 0.4f, 1.0f) * h,
                    0.011f * h);
    }
    EXPECT_TRUE(regrowCut(layer, 4.05f).patches.empty()) << "no step due, nothing re-grown";
    EXPECT_FALSE(regrowCut(layer, 9.0f).patches.empty());
    // After 8 s everything stands at full height again, exactly as never cut.
    regrowCut(layer, 8.5f);
    regrowCut(layer, 12.0f);
    EXPECT_EQ(layer.patched.blades, uncut.blades);
}

TEST(CutRegrow, NothingRegrowsWithoutACutMapOrARate) {
    Scene still = plainField(0.0f);
    still.layers[0].source.maps.cut = mownPath(0.2f);
    regrowAll(still.layers[0]);
    const PatchedBlades cut = still.layers[0].patched;
    EXPECT_TRUE(regrowCut(still.layers[0], 100.0f).patches.empty());
    EXPECT_EQ(still.layers[0].patched.blades, cut.blades) << "rate 0: it stays cut";
    Scene unpainted = plainField(0.5f);
    EXPECT_TRUE(regrowCut(unpainted.layers[0], 3.0f).patches.empty());
}

}  // namespace
}  // namespace grass::core
