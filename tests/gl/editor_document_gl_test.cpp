// The editor's document (issue 23): a failed open leaves everything as it was; the render
// settings have one source, the project, which T/L, the combo boxes and undo all change.
#include <gtest/gtest.h>

#include "app/document.h"
#include "app/edit_actions.h"
#include "gl_context_fixture.h"
#include "app/panels.h"
#include "support/test_paths.h"
#include "app/viewport_tools.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;

class EditorDocument : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        auto loaded = core::loadProject(sourceDir() / "tests/data/projects/tiny");
        ASSERT_TRUE(loaded) << loaded.error().str();
        ASSERT_TRUE(editor::replaceDocument(state, live, std::move(*loaded), true, "cannot open"))
            << state.transient.message;
    }
    editor::EditorState state;
    editor::Live live;
};

// Before: the panel and title switched to the new project while the viewport kept the old
// scene, and a Ctrl+S then saved the mix.
TEST_F(EditorDocument, AFailedOpenLeavesThePreviousDocumentSceneAndTitle) {
    state.doc.loaded.project.layers.front().scatter.density = 33.0f;  // an unsaved edit
    editor::recordProjectEdit(state, false);
    const core::LoadedProject before = state.doc.loaded;
    const core::Scene* scene = state.scene;
    const std::size_t steps = state.doc.history.undoSteps();
    ASSERT_EQ(steps, 1u);

    auto broken = core::loadProject(sourceDir() / "tests/data/projects/truncated_mesh");
    ASSERT_TRUE(broken) << "the project file itself is fine; its mesh is not";
    EXPECT_FALSE(editor::replaceDocument(state, live, std::move(*broken), true, "cannot open"));
    EXPECT_EQ(state.doc.loaded.file, before.file);
    EXPECT_EQ(state.doc.loaded.project, before.project);  // what the title and the panels show
    EXPECT_EQ(state.scene, scene);
    EXPECT_EQ(live.scene.get(), scene);
    EXPECT_EQ(state.doc.history.undoSteps(), steps);
    EXPECT_EQ(state.transient.message.rfind("cannot open: ", 0), 0u) << state.transient.message;
    EXPECT_NE(state.transient.message.find("field.gltf"), std::string::npos) << state.transient.message;
}

// Before: T and L changed the view only (not saved, not undoable, not marking the project
// unsaved) while the Render combo showed the new value.
TEST_F(EditorDocument, TechniqueAndLightingAreProjectSettingsThatTheViewFollows) {
    state.doc.dirty = false;
    const core::Project before = state.doc.loaded.project;
    state.doc.loaded.project.render.technique = core::GrassTechnique::Billboards;  // the T key's edit
    state.doc.loaded.project.lighting.model = core::LightingModel::Simple;         // the L key's edit
    editor::recordProjectEdit(state, false);
    EXPECT_TRUE(state.doc.dirty);
    EXPECT_EQ(state.doc.history.undoSteps(), 1u);
    render::RenderOptions drawn = editor::viewRenderOptions(state);
    EXPECT_EQ(drawn.technique, core::GrassTechnique::Billboards);
    EXPECT_EQ(drawn.lighting.model, core::LightingModel::Simple);

    ASSERT_TRUE(editor::undo(state));
    drawn = editor::viewRenderOptions(state);
    EXPECT_EQ(state.doc.loaded.project, before);
    EXPECT_EQ(drawn.technique, before.render.technique);
    EXPECT_EQ(drawn.lighting.model, before.lighting.model);

    // The cull tests are the view's own: switching one off changes the picture, not the project.
    state.view.overrides.occlusion = false;
    EXPECT_FALSE(editor::viewRenderOptions(state).cull.occlusion);
    editor::recordProjectEdit(state, false);
    EXPECT_EQ(state.doc.history.undoSteps(), 0u);
}

}  // namespace
}  // namespace grass::test
