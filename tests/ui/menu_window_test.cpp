// Menus, side panels, the top bar and floating windows, driven by simulated pointer input.
#include <gtest/gtest.h>

#include "tests/ui/ui_harness.h"
#include "ui/menu.h"
#include "ui/window.h"

namespace grass::ui {
namespace {

using test::findText;
using test::UiHarness;

struct MenuFixture {
    UiHarness h;
    int newClicks = 0;
    int undoClicks = 0;
    int redoClicks = 0;
    bool fileOpen = false;
    bool editOpen = false;

    void build(Ui& ui) {
        menuBar(ui, [&](Ui& bar) {
            fileOpen = menu(bar, "File", [&](Ui& m) {
                newClicks += menuItem(m, "New", "Ctrl+N") ? 1 : 0;
                menuItem(m, "Quit", "Ctrl+Q");
            });
            editOpen = menu(bar, "Edit", [&](Ui& m) {
                undoClicks += menuItem(m, "Undo") ? 1 : 0;
                redoClicks += menuItem(m, "Redo", "Ctrl+Shift+Z", /*enabled=*/false) ? 1 : 0;
            });
        });
    }
    void frame() {
        h.frame([&](Ui& ui) { build(ui); });
    }
    void clickAt(Vec2 p) {
        h.clickAt(p, [&](Ui& ui) { build(ui); });
    }
    Vec2 centreOf(std::string_view text) {
        const auto r = findText(h.ctx.output(), text);
        EXPECT_TRUE(r.has_value()) << text;
        return r ? r->centre() : Vec2(0.0f);
    }
};

TEST(UiMenu, OpensSwitchesOnHoverAndCloses) {
    MenuFixture f;
    f.frame();
    const Vec2 file = f.centreOf("File");
    const Vec2 edit = f.centreOf("Edit");
    f.h.moveTo(edit);
    f.frame();
    f.frame();
    EXPECT_FALSE(f.editOpen) << "hover alone opens nothing while no menu is open";

    f.clickAt(file);
    EXPECT_TRUE(f.fileOpen);
    f.frame();
    EXPECT_TRUE(findText(f.h.ctx.output(), "New").has_value());
    EXPECT_TRUE(findText(f.h.ctx.output(), "Ctrl+N").has_value());

    f.h.moveTo(edit);
    f.frame();
    f.frame();
    EXPECT_TRUE(f.editOpen);
    EXPECT_FALSE(f.fileOpen) << "one menu open at a time";
    EXPECT_FALSE(findText(f.h.ctx.output(), "New").has_value());
    f.h.moveTo(file);
    f.frame();
    f.frame();
    EXPECT_TRUE(f.fileOpen) << "and back";

    f.h.input.keys.push_back({Key::Escape, {}});
    f.frame();
    f.frame();
    EXPECT_FALSE(f.fileOpen);
    EXPECT_FALSE(f.editOpen);

    f.clickAt(file);
    f.frame();
    EXPECT_TRUE(f.fileOpen);
    f.clickAt({700.0f, 500.0f});
    EXPECT_FALSE(f.fileOpen) << "a press outside closes";
    EXPECT_EQ(f.h.ctx.duplicateIdCount(), 0);
}

// A disabled item (Redo with nothing to redo) is greyed and a click on it does nothing: the
// menu stays open. Before, Edit › Undo and Redo looked and acted the same with nothing to do.
TEST(UiMenu, ADisabledItemIsGreyedAndItsClickDoesNothing) {
    MenuFixture f;
    f.frame();
    f.clickAt(f.centreOf("Edit"));
    f.frame();
    const Output& open = f.h.ctx.output();
    const auto colourOf = [&](std::string_view text) {
        for (const ClippedShape& shape : open.shapes)
            if (const auto* t = std::get_if<TextShape>(&shape.shape); t && t->text == text)
                return t->color;
        return Color32{};
    };
    EXPECT_EQ(colourOf("Redo"), f.h.ctx.style().textWeak);
    EXPECT_NE(colourOf("Undo"), f.h.ctx.style().textWeak);
    f.clickAt(f.centreOf("Redo"));
    f.frame();
    EXPECT_EQ(f.redoClicks, 0);
    EXPECT_TRUE(f.editOpen) << "the menu stays open";
}

TEST(UiMenu, ItemClickReportsTrueOnceAndCloses) {
    MenuFixture f;
    f.frame();
    f.clickAt(f.centreOf("Edit"));
    f.frame();
    const Vec2 undo = f.centreOf("Undo");
    f.clickAt(undo);
    EXPECT_EQ(f.undoClicks, 1);
    f.frame();
    f.frame();
    EXPECT_EQ(f.undoClicks, 1);
    EXPECT_FALSE(f.editOpen);
    EXPECT_FALSE(findText(f.h.ctx.output(), "Undo").has_value());
    EXPECT_EQ(f.newClicks, 0);
}

TEST(UiPanel, DraggingTheInnerEdgeResizesAndIsRemembered) {
    UiHarness h;
    Rect left;
    Rect right;
    Rect top;
    Rect central;
    float defaultWidth = 200.0f;
    const auto build = [&](Ui& ui) {
        Context& ctx = ui.context();
        top = topBar(ctx, "top", [](Ui& bar) { bar.label("Status"); });
        left = sidePanel(ctx, "left", Side::Left, defaultWidth, [](Ui& p) { p.label("Layers"); });
        right = sidePanel(ctx, "right", Side::Right, 150.0f, [](Ui& p) { p.label("Render"); });
        central = centralRect(ctx);
    };
    h.frame(build);
    h.frame(build);
    EXPECT_FLOAT_EQ(left.width(), 200.0f);
    EXPECT_FLOAT_EQ(right.width(), 150.0f);
    EXPECT_FLOAT_EQ(left.min.y, top.max.y) << "panels start below the top bar";
    EXPECT_FLOAT_EQ(central.min.x, left.max.x);
    EXPECT_FLOAT_EQ(central.max.x, right.min.x);
    EXPECT_FLOAT_EQ(central.min.y, top.max.y);

    // Grabbed 1 point left of the edge, dragged 40 to the right.
    const Vec2 edge{left.max.x - 1.0f, 300.0f};
    h.moveTo(edge);
    h.frame(build);
    EXPECT_EQ(h.ctx.output().cursor, CursorIcon::ResizeHorizontal);
    h.press();
    h.frame(build);
    h.moveTo(edge + Vec2(40.0f, 0.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_FLOAT_EQ(left.width(), 240.0f);
    defaultWidth = 100.0f;
    h.moveTo({500.0f, 300.0f});
    h.frame(build);
    EXPECT_FLOAT_EQ(left.width(), 240.0f) << "remembered over the default";

    const Vec2 rightEdge{right.min.x, 300.0f};
    h.moveTo(rightEdge);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(rightEdge - Vec2(30.0f, 0.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_FLOAT_EQ(right.width(), 180.0f);

    h.moveTo({left.centre().x, 400.0f});
    h.frame(build);
    EXPECT_TRUE(h.ctx.output().wantsPointer) << "panels are UI areas";
    h.moveTo(central.centre());
    h.frame(build);
    EXPECT_FALSE(h.ctx.output().wantsPointer);
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
}

TEST(UiWindow, TitleDragMovesItAndItStaysOnScreen) {
    UiHarness h;
    bool open = true;
    const Rect initial{{60.0f, 60.0f}, {380.0f, 300.0f}};
    const auto build = [&](Ui& ui) {
        window(
            ui.context(), "Tools", &open, [](Ui& w) { w.label("Content"); }, initial);
    };
    h.frame(build);
    EXPECT_EQ(windowRect(h.ctx, "Tools"), initial);
    const Vec2 title{100.0f, 70.0f};
    h.moveTo(title);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(title + Vec2(50.0f, 30.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_EQ(windowRect(h.ctx, "Tools"),
              (Rect{initial.min + Vec2(50.0f, 30.0f), initial.max + Vec2(50.0f, 30.0f)}));

    const Vec2 grabbed = title + Vec2(50.0f, 30.0f);
    h.moveTo(grabbed);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(grabbed + Vec2(2000.0f, 2000.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    const Rect r = windowRect(h.ctx, "Tools");
    EXPECT_EQ(r.size(), initial.size());
    EXPECT_FLOAT_EQ(r.max.x, 800.0f);
    EXPECT_FLOAT_EQ(r.max.y, 600.0f);
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
}

// The index of the first text shape reading `text` in paint order (shapes.size() if none).
std::size_t paintIndex(const Output& out, std::string_view text) {
    for (std::size_t i = 0; i < out.shapes.size(); ++i)
        if (const auto* t = std::get_if<TextShape>(&out.shapes[i].shape); t && t->text == text)
            return i;
    return out.shapes.size();
}

// A combo's list opened in a window lies over the window's later widgets, and the combo's
// tooltip does not cover it. Before, the export window's Export and Cancel buttons were painted
// over the list's second entry, and the format's tooltip over its first.
TEST(UiWindow, AComboListInAWindowLiesAboveTheWindowsOtherWidgets) {
    UiHarness h;
    int choice = 0;
    const std::vector<std::string> items{"glTF per layer", "raw GPU buffers", "one .glb"};
    Response combo;
    const auto build = [&](Ui& ui) {
        window(ui.context(), "Export", nullptr, [&](Ui& w) {
            combo = w.comboBox("format", choice, items).onHoverText("What to write");
            w.button("Start");
        });
    };
    h.frame(build);
    h.clickAt(combo.rect().centre(), build);
    const Output& open = h.frame(build);
    ASSERT_LT(paintIndex(open, "raw GPU buffers"), open.shapes.size()) << "the list is open";
    EXPECT_GT(paintIndex(open, "raw GPU buffers"), paintIndex(open, "Start"));
    EXPECT_FALSE(findText(open, "What to write")) << "no tooltip over the open list";
    h.clickAt(combo.rect().centre(), build);  // closed again: the tooltip is back
    EXPECT_TRUE(findText(h.frame(build), "What to write"));
}

TEST(UiWindow, GripResizesAndCloseButtonCloses) {
    UiHarness h;
    bool open = true;
    bool shown = false;
    const Rect initial{{100.0f, 100.0f}, {300.0f, 250.0f}};
    const auto build = [&](Ui& ui) {
        shown = window(
            ui.context(), "Stats", &open, [](Ui& w) { w.label("Blades"); }, initial);
    };
    h.frame(build);
    const Vec2 grip = initial.max - Vec2(4.0f);
    h.moveTo(grip);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(grip + Vec2(40.0f, 20.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_EQ(windowRect(h.ctx, "Stats"), (Rect{initial.min, initial.max + Vec2(40.0f, 20.0f)}));
    // Not below the minimum size.
    h.moveTo(initial.max + Vec2(36.0f, 16.0f));
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(initial.min);
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_EQ(windowRect(h.ctx, "Stats").size(), WINDOW_MIN_SIZE);

    const Rect r = windowRect(h.ctx, "Stats");
    const float t = h.ctx.style().interactHeight;
    h.clickAt({r.max.x - 0.5f * t, r.min.y + 0.5f * t}, build);
    EXPECT_FALSE(open);
    h.frame(build);
    EXPECT_FALSE(shown);
}

TEST(UiWindow, ClickBringsAWindowToTheFront) {
    UiHarness h;
    int clicksA = 0;
    int clicksB = 0;
    // Both windows have a clickable probe over the same screen rect, where they overlap.
    const Rect probe{{210.0f, 230.0f}, {290.0f, 290.0f}};
    const auto build = [&](Ui& ui) {
        Context& ctx = ui.context();
        window(ctx, "A", nullptr,
               [&](Ui& w) {
                   clicksA += w.interact(probe, w.makeId("probe"), Sense::clickOnly()).clicked();
               },
               {{100.0f, 100.0f}, {300.0f, 300.0f}});
        window(ctx, "B", nullptr,
               [&](Ui& w) {
                   clicksB += w.interact(probe, w.makeId("probe"), Sense::clickOnly()).clicked();
               },
               {{200.0f, 200.0f}, {400.0f, 400.0f}});
    };
    h.frame(build);
    h.clickAt(probe.centre(), build);
    EXPECT_EQ(clicksB, 1) << "the newest window starts in front";
    EXPECT_EQ(clicksA, 0);
    h.clickAt({150.0f, 180.0f}, build);
    h.clickAt(probe.centre(), build);
    EXPECT_EQ(clicksA, 1) << "A was brought to the front by the click on it";
    EXPECT_EQ(clicksB, 1);
    h.clickAt({350.0f, 350.0f}, build);
    h.clickAt(probe.centre(), build);
    EXPECT_EQ(clicksB, 2);
    EXPECT_EQ(clicksA, 1);
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
}

}  // namespace
}  // namespace grass::ui
