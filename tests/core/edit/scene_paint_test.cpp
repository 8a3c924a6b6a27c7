#include "edit/scene_paint.h"

#include <gtest/gtest.h>

#include "support/plane_project.h"

namespace grass::core {
namespace {

// A 4 m plane with growth on: soil paints change heights, density paints add and remove blades.
Scene grownPlane() {
    test::PlaneField field;
    field.sizeM = 4.0f;
    field.resolution = 4;
    field.density = 200.0f;
    LoadedProject loaded = test::planeFieldProject(field);
    loaded.project.layers.front().mapResolution = {64, 64};
    loaded.project.layers.front().growth.enabled = true;
    auto scene = buildScene(loaded);
    EXPECT_TRUE(scene);
    return std::move(*scene);
}

BrushSettings eraser() {
    BrushSettings brush;
    brush.radiusM = 0.5f;
    brush.strength = 1.0f;
    brush.falloff = BrushFalloff::Constant;
    brush.mode = BrushMode::Subtract;
    return brush;
}

TEST(ScenePainter, AStrokeRegrowsTheFieldAsItGoesAndUndoRestoresItBitExactly) {
    Scene scene = grownPlane();
    const GrownField original = scene.layers[0];
    const std::size_t liveBefore = scene.layers[0].liveBlades;
    ScenePainter painter(scene, GrassLightingDesc{});
    painter.begin(0, LayerMap::Density, {64, 64}, eraser());
    ASSERT_TRUE(painter.active());
    // The first hit already removes grass: the field follows the brush, not the stroke's end.
    auto first = painter.paintTo({-1.0f, 0.0f, 0.0f});
    ASSERT_TRUE(first);
    EXPECT_FALSE(first->patches.empty());
    const std::size_t afterFirst = scene.layers[0].liveBlades;
    EXPECT_LT(afterFirst, liveBefore);
    ASSERT_TRUE(painter.paintTo({1.0f, 0.0f, 0.0f}));
    EXPECT_LT(scene.layers[0].liveBlades, afterFirst);
    auto edit = painter.end();
    EXPECT_FALSE(painter.active());
    ASSERT_TRUE(edit);
    const MapImage painted = scene.layers[0].source.maps.density;

    ASSERT_TRUE(painter.apply(*edit, true));
    EXPECT_EQ(scene.layers[0].liveBlades, liveBefore);
    EXPECT_EQ(scene.layers[0].patched.blades, original.patched.blades);
    for (const float v : scene.layers[0].source.maps.density.texels)
        ASSERT_EQ(v, 1.0f);

    ASSERT_TRUE(painter.apply(*edit, false));
    EXPECT_EQ(scene.layers[0].source.maps.density.texels, painted.texels);
    EXPECT_LT(scene.layers[0].liveBlades, afterFirst);
}

TEST(ScenePainter, ARegrownStrokeEqualsTheSameStrokePaintedAtOnce) {
    Scene live = grownPlane();
    Scene reference = grownPlane();
    BrushSettings soil = eraser();
    soil.falloff = BrushFalloff::Smooth;
    soil.strength = 0.6f;
    const std::vector<glm::vec3> hits{{-1.5f, 0, -1}, {-0.5f, 0, 0.2f}, {1.2f, 0, 1.1f}};
    ScenePainter painter(live, GrassLightingDesc{});
    painter.begin(0, LayerMap::Soil, {64, 64}, soil);
    for (const glm::vec3 hit : hits)
        ASSERT_TRUE(painter.paintTo(hit));
    ASSERT_TRUE(painter.end());

    ScenePainter once(reference, GrassLightingDesc{});
    MapImage& map = reference.layers[0].source.maps.soil;
    map = makeConstantMap(64, 64, 1.0f);
    const PaintRecord record = paintStroke(map, once.surface({64, 64}), soil, hits);
    ASSERT_TRUE(regrowLayerRegion(reference.layers[0], record.touchedBounds, 0.1f,
                                  GrassLightingDesc{})
                    );
    EXPECT_EQ(live.layers[0].source.maps.soil.texels, map.texels);
    EXPECT_EQ(live.layers[0].patched.blades, reference.layers[0].patched.blades);
    EXPECT_EQ(live.layers[0].wilt, reference.layers[0].wilt);
}

TEST(ScenePainter, PressureScalesTheDabAndZeroPressureChangesNothing) {
    Scene scene = grownPlane();
    ScenePainter painter(scene, GrassLightingDesc{});
    BrushSettings brush = eraser();
    brush.strength = 0.5f;
    painter.begin(0, LayerMap::Light, {64, 64}, brush);
    ASSERT_TRUE(painter.paintTo({0, 0, 0}, 0.0f));
    EXPECT_FALSE(painter.end());

    painter.begin(0, LayerMap::Light, {64, 64}, brush);
    ASSERT_TRUE(painter.paintTo({0, 0, 0}, 0.5f));
    auto edit = painter.end();
    ASSERT_TRUE(edit);
    for (const float after : edit->record.after)
        EXPECT_FLOAT_EQ(after, 0.75f);
}

TEST(ScenePainter, AnEditThatNoLongerFitsIsRefusedWithoutChangingAnything) {
    Scene scene = grownPlane();
    ScenePainter painter(scene, GrassLightingDesc{});
    PaintEdit edit;
    edit.layer = 3;
    edit.record.texelIndex = {0};
    edit.record.before = {0.0f};
    edit.record.after = {1.0f};
    EXPECT_FALSE(painter.apply(edit, true));
    edit.layer = 0;
    edit.record.texelIndex = {1u << 30};
    EXPECT_FALSE(painter.apply(edit, true));
    EXPECT_TRUE(scene.layers[0].source.maps.density.texels.empty());
}

}  // namespace
}  // namespace grass::core
