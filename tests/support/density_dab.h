// One dab of the density brush on a scene's first layer, as the editor's brush paints it
// (core::ScenePainter, a 64² map): the tests of what a repaint re-grows under snow.
#pragma once

#include <gtest/gtest.h>

#include "edit/scene_paint.h"

namespace grass::test {

// A constant dab of 0.4 m at (x, 0, 0) that adds or removes blades; its re-grow report.
inline core::RegrowReport paintDensityDab(core::Scene& scene, core::BrushMode mode, float x) {
    core::BrushSettings brush;
    brush.radiusM = 0.4f;
    brush.strength = 1.0f;
    brush.falloff = core::BrushFalloff::Constant;
    brush.mode = mode;
    core::ScenePainter painter(scene, core::GrassLightingDesc{});
    painter.begin(0, core::LayerMap::Density, {64, 64}, brush);
    auto report = painter.paintTo({x, 0.0f, 0.0f});
    EXPECT_TRUE(report) << report.error().str();
    EXPECT_TRUE(painter.end());
    return report ? *report : core::RegrowReport{};
}

}  // namespace grass::test
