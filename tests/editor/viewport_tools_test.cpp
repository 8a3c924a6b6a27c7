// The viewport's tools driven through the editor's input path (issue 8): pointer events in
// viewport pixels go to runViewportTool exactly as main.cpp sends GLFW's, with no window. A brush
// stroke changes the texels under it and nothing else; undo restores the map and the field bit
// for bit; redo re-applies it; a gizmo drag moves a wind source by what the pointer moved in the
// world, as one undo step. (In grass_gl_tests because the editor library links the renderer; no
// GL context is used.)
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "app/edit_actions.h"
#include "app/panels.h"
#include "support/plane_project.h"
#include "app/viewport_tools.h"

namespace grass::test {
namespace {

constexpr glm::vec2 VIEWPORT{640.0f, 480.0f};

// The editor on a 4 m plane of grass, seen from above and in front.
struct ToolDriver {
    ToolDriver() {
        PlaneField field;
        field.sizeM = 4.0f;
        field.resolution = 4;
        field.density = 150.0f;
        state.doc.loaded = planeFieldProject(field);
        state.doc.loaded.project.layers.front().mapResolution = {64, 64};
        auto built = core::buildScene(state.doc.loaded);
        EXPECT_TRUE(built.ok()) << built.error().str();
        scene = std::move(*built);
        original = scene.layers[0].patched.blades;
        tools.emplace(scene, state.doc.loaded.project.lighting);
        state.scene = &scene;
        state.tools = &*tools;
        // What the Editor uploads to the renderer, collected.
        state.regrown = [this](std::size_t layer, const core::RegrowReport& report) {
            regrown.emplace_back(layer, report);
        };
        editor::resetHistory(state);
        camera = core::OrbitCamera::lookAt({0.0f, 3.5f, 3.5f}, {0.0f, 0.0f, 0.0f}, 0.8f);
    }

    glm::vec2 pixelOf(glm::vec3 posWorld) const {
        auto pixel = core::projectToPixel(camera, posWorld, VIEWPORT);
        EXPECT_TRUE(pixel.has_value());
        return pixel.value_or(glm::vec2(0.0f));
    }
    // One frame of pointer input.
    bool frame(glm::vec2 pixel, bool down, bool pressed, bool ctrl = false) {
        editor::ViewportPointer p;
        p.pixel = pixel;
        p.viewportSize = VIEWPORT;
        p.inside = true;
        p.down = down;
        p.pressed = pressed;
        p.released = !down;
        p.ctrl = ctrl;
        const bool used = editor::runViewportTool(state, camera, p);
        editor::recordProjectEdit(state, false);
        return used;
    }
    // Press at `from`, move in `steps` frames to `to`, release.
    void drag(glm::vec3 from, glm::vec3 to, int steps, bool ctrl = false) {
        frame(pixelOf(from), true, true, ctrl);
        for (int i = 1; i <= steps; ++i)
            frame(pixelOf(glm::mix(from, to, float(i) / float(steps))), true, false, ctrl);
        frame(pixelOf(to), false, false, ctrl);
    }

    editor::EditorState state;
    std::vector<std::pair<std::size_t, core::RegrowReport>> regrown;
    core::Scene scene;
    std::optional<editor::SceneTools> tools;
    std::vector<core::Blade> original;
    core::OrbitCamera camera;
};

// Distance from p to the segment ab.
float distanceToSegment(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const glm::vec3 ab = b - a;
    const float t = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

TEST(ViewportTools, AStrokeOfPointerEventsErasesTheTexelsUnderItAndUndoRestoresThem) {
    ToolDriver d;
    d.state.view.tool = editor::ViewportTool::Paint;
    d.state.view.paint.map = core::LayerMap::Density;
    d.state.view.paint.brush.mode = core::BrushMode::Add;  // Ctrl below inverts it to subtract
    d.state.view.paint.brush.falloff = core::BrushFalloff::Constant;
    d.state.view.paint.brush.strength = 1.0f;
    d.state.view.paint.brush.radiusM = 0.4f;
    d.state.view.paint.radiusChosen = true;
    const std::size_t liveBefore = d.scene.layers[0].liveBlades;
    const glm::vec3 a{-1.2f, 0.0f, 0.3f}, b{1.2f, 0.0f, -0.2f};
    d.drag(a, b, 16, true);

    const core::MapImage& map = d.scene.layers[0].source.maps.density;
    ASSERT_EQ(map.width, 64);
    const core::TexelSurface& surface = d.tools->painter.surface({64, 64});
    // Texels well inside the stroke's band are 0, texels well outside are untouched. The picked
    // hits lie within a hair of the segment, and the dabs are a quarter radius apart, so the
    // band's edge wobbles by less than (1 − cos)·r plus a texel; both margins cover it.
    const float texel = 4.0f / 64.0f;
    std::size_t erased = 0, kept = 0;
    for (std::uint32_t t = 0; t < map.texels.size(); ++t) {
        if (!surface.isCovered(t))
            continue;
        const float distance = distanceToSegment(surface.position(t), a, b);
        if (distance < 0.4f - 0.05f - texel) {
            ASSERT_EQ(map.texels[t], 0.0f) << "texel " << t << " at " << distance;
            ++erased;
        } else if (distance > 0.4f + texel) {
            ASSERT_EQ(map.texels[t], 1.0f) << "texel " << t << " at " << distance;
            ++kept;
        }
    }
    EXPECT_GT(erased, 300u);
    EXPECT_GT(kept, 2000u);
    EXPECT_LT(d.scene.layers[0].liveBlades, liveBefore);
    EXPECT_FALSE(d.regrown.empty());  // the renderer uploads the re-grown patches
    EXPECT_TRUE(d.state.doc.dirty);
    ASSERT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_EQ(d.state.doc.history.nextUndo()->label, "paint density");
    const std::vector<float> painted = map.texels;
    const std::vector<core::Blade> paintedBlades = d.scene.layers[0].patched.blades;

    ASSERT_TRUE(editor::undo(d.state));
    for (const float v : map.texels)
        ASSERT_EQ(v, 1.0f);
    EXPECT_EQ(d.scene.layers[0].patched.blades, d.original);
    EXPECT_EQ(d.scene.layers[0].liveBlades, liveBefore);

    ASSERT_TRUE(editor::redo(d.state));
    EXPECT_EQ(map.texels, painted);
    EXPECT_EQ(d.scene.layers[0].patched.blades, paintedBlades);
}

// Tools for a field re-grown on the same surface share the BVH of the tools before them (built
// once, on its worker); tools for another field build their own. Both pick the same surface.
TEST(ViewportTools, ToolsOfTheSameSurfaceShareOnePickingBvh) {
    ToolDriver d;
    const editor::SceneTools same(d.scene, d.state.doc.loaded.project.lighting, &*d.tools);
    const editor::SceneTools own(d.scene, d.state.doc.loaded.project.lighting);
    EXPECT_EQ(&same.bvh(), &d.tools->bvh());
    EXPECT_NE(&own.bvh(), &d.tools->bvh());
    const core::Ray down{{0.3f, 2.0f, -0.4f}, {0.0f, -1.0f, 0.0f}};
    const auto hit = same.bvh().intersect(down);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(own.bvh().intersect(down), hit);
    EXPECT_NEAR(hit->posWorld.y, 0.0f, 1e-5f);
}

TEST(ViewportTools, APressOffTheMeshPaintsNothing) {
    ToolDriver d;
    d.state.view.tool = editor::ViewportTool::Paint;
    // The sky above the horizon: the ray misses the plane.
    EXPECT_TRUE(d.frame({320.0f, 2.0f}, true, true));
    EXPECT_FALSE(d.frame({330.0f, 2.0f}, true, false));
    EXPECT_FALSE(d.frame({330.0f, 2.0f}, false, false));
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
    EXPECT_TRUE(d.scene.layers[0].source.maps.density.texels.empty() ||
                d.scene.layers[0].source.maps.density.maxValue() == 1.0f);
}

TEST(ViewportTools, BracketKeysResizeTheBrush) {
    ToolDriver d;
    // Before a radius is chosen the keys start from the one the ring shows, a twentieth of the
    // scene's diagonal (they started from the stored 1 m, which the ring did not show).
    const float sceneDefault = 0.05f * glm::length(d.state.scene->bounds.size());
    ASSERT_NE(sceneDefault, 1.0f);
    EXPECT_FLOAT_EQ(editor::brushRadius(d.state), sceneDefault);
    editor::applyToolKeys(d.state, "]");
    EXPECT_FLOAT_EQ(d.state.view.paint.brush.radiusM, 1.25f * sceneDefault);
    EXPECT_TRUE(d.state.view.paint.radiusChosen);
    d.state.view.paint.brush.radiusM = 1.0f;
    editor::applyToolKeys(d.state, "]]");
    EXPECT_FLOAT_EQ(d.state.view.paint.brush.radiusM, 1.5625f);
    editor::applyToolKeys(d.state, "[");
    EXPECT_FLOAT_EQ(d.state.view.paint.brush.radiusM, 1.25f);
    // Within the scene's range, whatever the keys.
    const editor::BrushRadiusRange range = editor::brushRadiusRange(d.state);
    editor::applyToolKeys(d.state, std::string(80, '['));
    EXPECT_FLOAT_EQ(d.state.view.paint.brush.radiusM, range.min);
    editor::applyToolKeys(d.state, std::string(80, ']'));
    EXPECT_FLOAT_EQ(d.state.view.paint.brush.radiusM, range.max);
    editor::applyToolKeys(d.state, "b");
    EXPECT_EQ(d.state.view.tool, editor::ViewportTool::Paint);
    editor::applyToolKeys(d.state, "gr");
    EXPECT_EQ(d.state.view.tool, editor::ViewportTool::Place);
    EXPECT_EQ(d.state.view.place.mode, core::GizmoMode::Scale);
}

TEST(ViewportTools, AGizmoDragMovesTheSelectedWindSourceAsOneUndoStep) {
    for (const float yawDeg : {0.0f, 35.0f, 120.0f}) {
        ToolDriver d;
        d.camera.yawRad = glm::radians(yawDeg);
        core::WindDesc wind;
        wind.source.kind = core::WindKind::Point;
        wind.source.position = {0.0f, 0.5f, 0.0f};
        d.state.doc.loaded.project.wind.push_back(wind);
        d.state.doc.committed = d.state.doc.loaded.project;
        d.state.view.tool = editor::ViewportTool::Place;
        d.state.view.place.mode = core::GizmoMode::Translate;

        // A click on the marker selects the source.
        const glm::vec3 pivot = wind.source.position;
        EXPECT_TRUE(d.frame(d.pixelOf(pivot), true, true));
        d.frame(d.pixelOf(pivot), false, false);
        ASSERT_TRUE(d.state.view.place.selected.has_value());

        // Drag the X arrow by 0.6 m along X.
        const float arm = core::worldLengthForPixels({d.camera, VIEWPORT}, pivot,
                                                     core::GizmoStyle{}.armPixels);
        const glm::vec3 grab = pivot + glm::vec3(0.7f * arm, 0.0f, 0.0f);
        ASSERT_EQ(core::pickGizmoHandle(core::GizmoMode::Translate, {d.camera, VIEWPORT}, pivot,
                                        d.pixelOf(grab)),
                  core::GizmoHandle::X)
            << "yaw " << yawDeg;
        d.drag(grab, grab + glm::vec3(0.6f, 0.0f, 0.0f), 8);
        const glm::vec3 moved = d.state.doc.loaded.project.wind[0].source.position;
        EXPECT_NEAR(moved.x, 0.6f, 1e-3f) << "yaw " << yawDeg;
        EXPECT_NEAR(moved.y, 0.5f, 1e-4f);
        EXPECT_NEAR(moved.z, 0.0f, 1e-4f);
        ASSERT_EQ(d.state.doc.history.undoSteps(), 1u);
        EXPECT_EQ(d.state.doc.history.nextUndo()->label, "wind");
        EXPECT_TRUE(d.state.rebuildPending);  // the renderer and physics follow the move
        EXPECT_TRUE(d.state.doc.dirty);

        ASSERT_TRUE(editor::undo(d.state));
        EXPECT_EQ(d.state.doc.loaded.project.wind[0].source.position, pivot);
        ASSERT_TRUE(editor::redo(d.state));
        EXPECT_NEAR(d.state.doc.loaded.project.wind[0].source.position.x, 0.6f, 1e-3f);
    }
}

TEST(ViewportTools, APanelDragBecomesOneStepWhenItEnds) {
    ToolDriver d;
    core::Project& project = d.state.doc.loaded.project;
    for (int frame = 1; frame <= 5; ++frame) {
        // The density slider, still held: the field is grown from it (panels_layers.cpp).
        core::Project dragged = project;
        dragged.layers[0].scatter.density = 150.0f + 10.0f * float(frame);
        editor::apply(d.state, editor::EditProject{.after = std::move(dragged),
                                                   .effect = editor::EditEffect::Regrow,
                                                   .ongoing = true});
    }
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
    editor::recordProjectEdit(d.state, false);
    ASSERT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_EQ(d.state.doc.history.nextUndo()->label, "layers");
    d.state.rebuildPending = false;  // the field grew for the drag
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_FLOAT_EQ(project.layers[0].scatter.density, 150.0f);
    EXPECT_TRUE(d.state.rebuildPending) << "the undone density grows the field again";
    // Undoing is not itself a new step.
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
    EXPECT_EQ(d.state.doc.history.redoSteps(), 1u);
}

}  // namespace
}  // namespace grass::test
