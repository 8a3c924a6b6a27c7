#include "edit/history.h"

#include <gtest/gtest.h>

namespace grass::core {
namespace {

Edit projectEdit(const std::string& label, float densityBefore, float densityAfter) {
    ProjectEdit change;
    change.before.layers.front().scatter.density = densityBefore;
    change.after.layers.front().scatter.density = densityAfter;
    return Edit{label, change};
}

Edit paintEdit(std::size_t texels) {
    PaintEdit change;
    change.record.texelIndex.reserve(texels);
    change.record.before.reserve(texels);
    change.record.after.reserve(texels);
    for (std::size_t i = 0; i < texels; ++i) {
        change.record.texelIndex.push_back(static_cast<std::uint32_t>(i));
        change.record.before.push_back(0.0f);
        change.record.after.push_back(1.0f);
    }
    return Edit{"paint", change};
}

TEST(EditHistory, UndoAndRedoWalkTheEditsInOrder) {
    EditHistory history;
    EXPECT_EQ(history.undo(), nullptr);
    EXPECT_EQ(history.redo(), nullptr);
    history.push(projectEdit("a", 1, 2));
    history.push(projectEdit("b", 2, 3));
    ASSERT_TRUE(history.canUndo());
    EXPECT_EQ(history.nextUndo()->label, "b");
    EXPECT_EQ(history.undo()->label, "b");
    EXPECT_EQ(history.undo()->label, "a");
    EXPECT_EQ(history.undo(), nullptr);
    EXPECT_EQ(history.redoSteps(), 2u);
    EXPECT_EQ(history.redo()->label, "a");
    EXPECT_EQ(history.redo()->label, "b");
    EXPECT_EQ(history.redo(), nullptr);
}

TEST(EditHistory, ANewEditDropsTheRedoBranch) {
    EditHistory history;
    history.push(projectEdit("a", 1, 2));
    history.push(projectEdit("b", 2, 3));
    history.undo();
    history.push(projectEdit("c", 2, 5));
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(history.undo()->label, "c");
    EXPECT_EQ(history.undo()->label, "a");
}

// The save point: undoing or redoing back to the edits the file holds leaves nothing unsaved.
TEST(EditHistory, UndoingBackToTheSavePointIsAtIt) {
    EditHistory history;
    EXPECT_FALSE(history.atSavePoint()) << "never saved";
    history.markSaved();  // opened from a file
    EXPECT_TRUE(history.atSavePoint());
    history.push(projectEdit("a", 1, 2));
    EXPECT_FALSE(history.atSavePoint());
    history.undo();
    EXPECT_TRUE(history.atSavePoint());
    history.redo();
    history.push(projectEdit("b", 2, 3));
    history.markSaved();  // saved after a and b
    history.undo();
    EXPECT_FALSE(history.atSavePoint());
    history.redo();
    EXPECT_TRUE(history.atSavePoint());
    history.clear();
    EXPECT_FALSE(history.atSavePoint()) << "a new document is unsaved until saved";
}

TEST(EditHistory, ASavePointItsEditsNoLongerReachIsLost) {
    // Saved after a and b; b undone, c done: the saved state lay in the dropped redo branch.
    EditHistory history;
    history.push(projectEdit("a", 1, 2));
    history.push(projectEdit("b", 2, 3));
    history.markSaved();
    history.undo();
    history.push(projectEdit("c", 2, 5));
    history.undo();
    EXPECT_FALSE(history.atSavePoint());
    history.redo();
    EXPECT_FALSE(history.atSavePoint());
    // Saved before any edit, then more edits than the history keeps: undoing cannot go back.
    EditHistory short3(EditHistory::Limits{3, std::size_t{1} << 30});
    short3.markSaved();
    for (int i = 0; i < 5; ++i)
        short3.push(projectEdit(std::to_string(i), float(i), float(i + 1)));
    while (short3.undo() != nullptr)
        EXPECT_FALSE(short3.atSavePoint());
    // Saved after the second of five kept edits: dropping older ones keeps it reachable.
    EditHistory kept(EditHistory::Limits{4, std::size_t{1} << 30});
    kept.push(projectEdit("0", 0, 1));
    kept.push(projectEdit("1", 1, 2));
    kept.markSaved();
    for (int i = 2; i < 5; ++i)
        kept.push(projectEdit(std::to_string(i), float(i), float(i + 1)));
    for (int i = 0; i < 3; ++i)
        kept.undo();
    EXPECT_TRUE(kept.atSavePoint());
}

TEST(EditHistory, KeepsAtLeastTwoHundredStepsByDefault) {
    EditHistory history;
    for (int i = 0; i < 250; ++i)
        history.push(paintEdit(100));
    EXPECT_EQ(history.undoSteps(), 250u);
    for (int i = 0; i < 250; ++i)
        ASSERT_NE(history.undo(), nullptr) << i;
}

TEST(EditHistory, DropsTheOldestBeyondTheStepLimit) {
    EditHistory history(EditHistory::Limits{3, std::size_t{1} << 30});
    for (int i = 0; i < 5; ++i)
        history.push(projectEdit(std::to_string(i), float(i), float(i + 1)));
    EXPECT_EQ(history.undoSteps(), 3u);
    EXPECT_EQ(history.undo()->label, "4");
    EXPECT_EQ(history.undo()->label, "3");
    EXPECT_EQ(history.undo()->label, "2");
    EXPECT_EQ(history.undo(), nullptr);
}

TEST(EditHistory, MemoryIsBoundedByTheByteLimitAndCountsChangedTexelsOnly) {
    const std::size_t oneStroke = editBytes(paintEdit(10000));
    // 12 bytes a changed texel plus a constant (the Edit itself, sized for a project step,
    // about a kilobyte): a stroke costs what it changed, not what the map holds.
    EXPECT_GE(oneStroke, 10000u * 12u);
    EXPECT_LT(oneStroke, 10000u * 12u + 4096u);
    EditHistory history(EditHistory::Limits{1000, 5 * oneStroke});
    for (int i = 0; i < 20; ++i)
        history.push(paintEdit(10000));
    EXPECT_LE(history.bytes(), 5 * oneStroke);
    EXPECT_EQ(history.undoSteps(), 5u);
}

TEST(EditHistory, KeepsTheNewestEditEvenWhenItAloneIsOverTheLimit) {
    EditHistory history(EditHistory::Limits{1000, 16});
    history.push(paintEdit(1000));
    EXPECT_EQ(history.undoSteps(), 1u);
    history.push(paintEdit(1000));
    EXPECT_EQ(history.undoSteps(), 1u);
    history.clear();
    EXPECT_EQ(history.bytes(), 0u);
    EXPECT_FALSE(history.canUndo());
}

}  // namespace
}  // namespace grass::core
