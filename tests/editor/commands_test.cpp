// Every change to the document is a command applied in one place (app/commands.h): the keys,
// the panels' working copy, the gizmo and the brush all end there, and there alone the project
// changes, the undo step is made, the document is marked unsaved and the re-grow is asked for.
#include "app/commands.h"

#include <gtest/gtest.h>

#include "app/edit_actions.h"
#include "app/editor_keys.h"
#include "app/viewport_tools.h"
#include "support/plane_project.h"

namespace grass::test {
namespace {

struct CommandDriver {
    CommandDriver() {
        PlaneField field;
        field.sizeM = 2.0f;
        field.resolution = 2;
        state.doc.loaded = planeFieldProject(field);
        editor::resetHistory(state);
    }
    editor::EditorState state;
};

TEST(Commands, AnOngoingEditFollowsAtOnceAndBecomesOneStepWhenItEnds) {
    CommandDriver d;
    const glm::vec3 original = d.state.doc.project().layers[0].rootColor;
    core::Project edited = d.state.doc.project();
    for (int frame = 1; frame <= 3; ++frame) {
        edited.layers[0].rootColor.x = 0.01f + 0.3f * float(frame);
        EXPECT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited, .ongoing = true}));
        EXPECT_EQ(d.state.doc.project().layers[0].rootColor.x, 0.01f + 0.3f * float(frame));
    }
    EXPECT_TRUE(d.state.doc.dirty) << "the picture and the title follow the drag";
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
    EXPECT_FALSE(d.state.rebuildPending) << "a colour is read by the renderer every frame";

    editor::recordProjectEdit(d.state, false);  // the drag ended
    ASSERT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_EQ(d.state.doc.history.nextUndo()->label, "layers");
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_EQ(d.state.doc.project().layers[0].rootColor, original) << "one step undoes the drag";
}

TEST(Commands, AnEditTheSceneIsGrownFromAsksForARegrowAndKeepsItsLabel) {
    CommandDriver d;
    core::Project edited = d.state.doc.project();
    edited.layers[0].scatter.density *= 0.5f;
    d.state.doc.dirty = false;
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited,
                                                           .effect = editor::EditEffect::Regrow,
                                                           .label = "thin out"}));
    EXPECT_TRUE(d.state.rebuildPending);
    EXPECT_TRUE(d.state.doc.dirty);
    ASSERT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_EQ(d.state.doc.history.nextUndo()->label, "thin out");
    // The same project again changes nothing and makes no step.
    d.state.rebuildPending = false;
    EXPECT_FALSE(editor::apply(d.state, editor::EditProject{.after = edited}));
    EXPECT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_FALSE(d.state.rebuildPending);
}

// Undoing or redoing a step the field was not grown from (a colour, the lighting model) shows
// it as it is; before 2026-12-07 every undo grew the whole field again, and its blades restarted
// from rest (seconds on a large mesh). A step the field is grown from still grows it again.
TEST(Commands, UndoingAStepTheFieldWasNotGrownFromGrowsNothing) {
    CommandDriver d;
    core::Scene scene;  // what the renderer draws the layer's colours from
    scene.layers.resize(1);
    core::takeLayerLooks(scene, d.state.doc.project());
    d.state.scene = &scene;
    const glm::vec3 original = d.state.doc.project().layers[0].rootColor;
    const glm::vec3 red{0.8f, 0.1f, 0.1f};
    core::Project edited = d.state.doc.project();
    edited.layers[0].rootColor = red;  // the panel's colour: live, and the field takes it
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited}));
    scene.layers[0].rootColor = red;
    edited.lighting.model = core::LightingModel::Simple;
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited}));
    ASSERT_EQ(d.state.doc.history.undoSteps(), 2u);
    EXPECT_FALSE(d.state.rebuildPending);

    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_NE(d.state.doc.project().lighting.model, core::LightingModel::Simple);
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_FALSE(d.state.rebuildPending) << "nothing the field grows from was undone";
    EXPECT_EQ(scene.layers[0].rootColor, original) << "the drawn field shows the undone colour";
    ASSERT_TRUE(editor::redo(d.state));
    EXPECT_FALSE(d.state.rebuildPending);
    EXPECT_EQ(scene.layers[0].rootColor, red);

    // A step that changed the scatter with the colour grows the field again when undone.
    edited = d.state.doc.project();
    edited.layers[0].rootColor = original;
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited, .ongoing = true}));
    edited.layers[0].scatter.density *= 0.5f;
    ASSERT_TRUE(editor::apply(
        d.state, editor::EditProject{
                     .after = edited, .effect = editor::EditEffect::Regrow, .ongoing = true}));
    editor::recordProjectEdit(d.state, false);
    d.state.rebuildPending = false;  // grown
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_TRUE(d.state.rebuildPending);

    // An imported mesh's field was grown before its step was made: nothing to grow then, but
    // undoing it grows the field on the surface before.
    d.state.rebuildPending = false;
    edited = d.state.doc.project();
    edited.mesh.isFile = true;
    edited.mesh.file = "rock.glb";
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited,
                                                           .effect = editor::EditEffect::Grown,
                                                           .label = "import mesh"}));
    EXPECT_FALSE(d.state.rebuildPending);
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_TRUE(d.state.rebuildPending);
}

// An edit that ends where it began (a colour dragged and brought back) makes no step, and the
// title's * goes when nothing was unsaved before it; before 2026-12-07 the * stayed.
TEST(Commands, AnEditThatEndsWhereItBeganLeavesNothingUnsaved) {
    CommandDriver d;
    d.state.doc.history.markSaved();
    d.state.doc.dirty = false;
    const core::Project saved = d.state.doc.project();
    core::Project edited = saved;
    edited.layers[0].rootColor.x += 0.25f;
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited, .ongoing = true}));
    EXPECT_TRUE(d.state.doc.dirty) << "the title follows the drag";
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = saved, .ongoing = true}));
    editor::recordProjectEdit(d.state, false);  // released where it began
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
    EXPECT_FALSE(d.state.doc.dirty);

    // After a step since the save, a drag brought back leaves that step unsaved.
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited}));
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = saved, .ongoing = true}));
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited, .ongoing = true}));
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_TRUE(d.state.doc.dirty);
}

TEST(Commands, UndoWaitsForAToolDragToEnd) {
    CommandDriver d;
    core::Project edited = d.state.doc.project();
    edited.name = "renamed";
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = edited}));
    d.state.view.toolDragActive = true;
    EXPECT_FALSE(editor::undo(d.state));
    EXPECT_EQ(d.state.doc.project().name, "renamed");
    d.state.view.toolDragActive = false;
    EXPECT_TRUE(editor::undo(d.state));
    EXPECT_NE(d.state.doc.project().name, "renamed");
    EXPECT_TRUE(editor::redo(d.state));
    EXPECT_EQ(d.state.doc.project().name, "renamed");
}

// Before: T and L changed the picture only; now they are commands like the Render panel's combo
// boxes (saved, undoable, marking the project unsaved).
TEST(Commands, TheTechniqueAndLightingKeysAreUndoableProjectEdits) {
    CommandDriver d;
    d.state.doc.dirty = false;
    const core::Project before = d.state.doc.project();
    editor::InputState input;
    input.nextTechnique = true;
    const std::string said = editor::applyEditorKeys(d.state, input, true);
    EXPECT_NE(d.state.doc.project().render.technique, before.render.technique);
    EXPECT_EQ(said, "technique " + std::string(core::grassTechniqueName(
                                       d.state.doc.project().render.technique)));
    EXPECT_TRUE(d.state.doc.dirty);
    ASSERT_EQ(d.state.doc.history.undoSteps(), 1u);
    EXPECT_EQ(d.state.doc.history.nextUndo()->label, said);

    input = {};
    input.toggleLighting = true;
    editor::applyEditorKeys(d.state, input, true);
    EXPECT_NE(d.state.doc.project().lighting.model, before.lighting.model);
    EXPECT_EQ(d.state.doc.history.undoSteps(), 2u);

    // Ctrl+Z twice: the project is as it was.
    input = {};
    input.keys = {ui::KeyEvent{ui::Key::Z, ui::Modifiers{.ctrl = true}},
                  ui::KeyEvent{ui::Key::Z, ui::Modifiers{.ctrl = true}}};
    editor::applyEditorKeys(d.state, input, true);
    EXPECT_EQ(d.state.doc.project(), before);
    EXPECT_EQ(d.state.doc.history.redoSteps(), 2u);
}

// Issue 26 item 4: Delete removes the selected object as one undoable step; F frames it.
TEST(Commands, DeleteRemovesTheSelectedObjectAndFFramesIt) {
    CommandDriver d;
    core::Project project = d.state.doc.project();
    core::ColliderDesc ball;
    ball.name = "ball";
    ball.position = {3.0f, 0.5f, -1.0f};
    ball.radiusM = 2.0f;
    project.colliders = {ball};
    ASSERT_TRUE(editor::apply(d.state, editor::EditProject{.after = project}));
    const core::Project before = d.state.doc.project();

    editor::InputState input;
    input.keys = {ui::KeyEvent{ui::Key::Delete, ui::Modifiers{}}};
    EXPECT_EQ(editor::applyEditorKeys(d.state, input, true), "") << "nothing selected, nothing deleted";
    EXPECT_EQ(d.state.doc.project().colliders.size(), 1u);

    d.state.view.place.selected = editor::PlacedObject{editor::PlacedKind::Collider, 0};
    const auto framed = editor::selectionBounds(d.state, 0.0f);
    ASSERT_TRUE(framed.has_value());
    EXPECT_EQ(framed->centre(), ball.position);
    EXPECT_EQ(framed->size(), glm::vec3(4.0f)) << "as large as the ball's reach";

    EXPECT_EQ(editor::applyEditorKeys(d.state, input, true), "deleted ball");
    EXPECT_TRUE(d.state.doc.project().colliders.empty());
    EXPECT_FALSE(d.state.view.place.selected.has_value());
    EXPECT_FALSE(editor::selectionBounds(d.state, 0.0f).has_value()) << "F frames the scene again";
    EXPECT_EQ(d.state.doc.history.nextUndo()->label, "delete ball");
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_EQ(d.state.doc.project(), before);
}

// A cull-test key is the view's: the picture changes, the document does not.
TEST(Commands, ACullTestKeyIsNotADocumentChange) {
    CommandDriver d;
    d.state.doc.dirty = false;
    editor::InputState input;
    input.toggledCullTest = 4;
    EXPECT_EQ(editor::applyEditorKeys(d.state, input, true), "occlusion culling off");
    EXPECT_FALSE(d.state.view.overrides.occlusion);
    EXPECT_FALSE(d.state.doc.dirty);
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
}

// Space plays and pauses the timeline: the view's time, not a document change.
TEST(Commands, SpacePlaysAndPausesTheTimeline) {
    CommandDriver d;
    d.state.doc.dirty = false;
    ASSERT_FALSE(d.state.view.timeline.playing());
    editor::InputState input;
    input.typed = " ";
    EXPECT_EQ(editor::applyEditorKeys(d.state, input, true), "playing");
    EXPECT_TRUE(d.state.view.timeline.playing());
    EXPECT_EQ(editor::applyEditorKeys(d.state, input, true), "paused");
    EXPECT_FALSE(d.state.view.timeline.playing());
    EXPECT_FALSE(d.state.doc.dirty);
    EXPECT_EQ(d.state.doc.history.undoSteps(), 0u);
}

}  // namespace
}  // namespace grass::test
