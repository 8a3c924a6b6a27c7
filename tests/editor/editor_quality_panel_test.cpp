// The Render section's quality presets chosen as a user chooses them (panel_driver.h): a preset
// that changes the baked AO kernel grows the field again; one that changes only the physics'
// substeps (draft, balanced and high share one AO kernel) and the renderer's settings does not:
// the editor's live physics follows the substeps (editor::followPhysicsSteps,
// LivePhysicsTest.AnotherPhysicsStepIsFollowedWithoutTheFieldGrowingAgain). Before, every preset
// that changed the substeps grew the whole field again, and its blades restarted from rest.
#include <gtest/gtest.h>

#include <string>

#include "panel_driver.h"
#include "quality/quality_presets.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

// Opens the quality combo box and picks `preset`.
void choosePreset(PanelDriver& editor, const std::string& shown, const std::string& preset) {
    editor.click(shown);
    editor.click(preset);
}

TEST(EditorQualityPanel, OnlyAPresetThatChangesTheAoKernelGrowsTheFieldAgain) {
    PanelDriver editor(sourceDir() / "projects/meadow");
    if (!editor.shows("quality"))
        editor.click("Render");
    ASSERT_TRUE(editor.shows("quality"));
    const core::Project& project = editor.state.doc.loaded.project;
    const float aoBefore = project.lighting.aoCellSigmas;

    choosePreset(editor, "custom", "draft");
    ASSERT_NE(project.lighting.aoCellSigmas, aoBefore) << "the meadow's AO kernel is no preset's";
    EXPECT_TRUE(editor.state.rebuildPending) << "another AO kernel grows the field again";
    editor.state.rebuildPending = false;  // as the editor does when it starts the re-grow
    const core::PhysicsParams draft = project.physics;

    choosePreset(editor, "draft", "balanced");
    EXPECT_NE(project.physics, draft) << "balanced steps the physics otherwise";
    EXPECT_EQ(project.lighting.aoCellSigmas,
              core::qualitySettings(core::QualityPreset::Draft).aoCellSigmas.value_or(-1.0f));
    EXPECT_FALSE(editor.state.rebuildPending) << "the substeps alone grew the field again";
    choosePreset(editor, "balanced", "high");
    EXPECT_FALSE(editor.state.rebuildPending);
    EXPECT_TRUE(core::matchingPreset(project) == core::QualityPreset::High);
}

}  // namespace
}  // namespace grass::test
