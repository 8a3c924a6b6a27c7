// Where widgets land for a given panel, and what the painter emits (clip rects, culling).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/ui/ui_harness.h"
#include "ui/color_edit.h"
#include "ui/curve_edit.h"
#include "ui/menu.h"

namespace grass::ui {
namespace {

using test::findText;
using test::testFonts;
using test::UiHarness;

Vec2 textSize(std::string_view text) {
    return testFonts().textSize(text, Style{}.textSizePt);
}

TEST(UiLayout, VerticalItemsStackWithItemSpacing) {
    UiHarness h;
    const Style s;
    Rect a, b, button;
    h.frame([&](Ui& ui) {
        a = ui.label("Alpha").rect();
        b = ui.label("Beta").rect();
        button = ui.button("Press").rect();
    });
    EXPECT_EQ(a.min, h.panel.min);
    EXPECT_FLOAT_EQ(a.height(), textSize("Alpha").y);
    EXPECT_FLOAT_EQ(a.width(), textSize("Alpha").x);
    EXPECT_FLOAT_EQ(b.min.x, h.panel.min.x);
    EXPECT_FLOAT_EQ(b.min.y, a.max.y + s.itemSpacing.y);
    EXPECT_FLOAT_EQ(button.min.y, b.max.y + s.itemSpacing.y);
    EXPECT_FLOAT_EQ(button.width(), textSize("Press").x + 2.0f * s.buttonPadding.x);
    EXPECT_FLOAT_EQ(button.height(),
                    std::max(s.interactHeight, textSize("Press").y + 2.0f * s.buttonPadding.y));
}

TEST(UiLayout, HorizontalRowPlacesItemsSideBySideThenContinuesBelow) {
    UiHarness h;
    const Style s;
    Rect one, two, label, below;
    h.frame([&](Ui& ui) {
        ui.horizontal([&](Ui& row) {
            one = row.button("One").rect();
            two = row.button("Two").rect();
            label = row.label("text").rect();
        });
        below = ui.label("Below").rect();
    });
    EXPECT_EQ(one.min, h.panel.min);
    EXPECT_FLOAT_EQ(two.min.x, one.max.x + s.itemSpacing.x);
    EXPECT_FLOAT_EQ(two.min.y, one.min.y);
    EXPECT_FLOAT_EQ(label.min.x, two.max.x + s.itemSpacing.x);
    // A label is centred in the row height so its text lines up with the buttons'.
    EXPECT_NEAR(label.centre().y, one.centre().y, 1e-4f);
    const float rowHeight = std::max(one.height(), s.interactHeight);
    EXPECT_FLOAT_EQ(below.min.y, h.panel.min.y + rowHeight + s.itemSpacing.y);
    EXPECT_FLOAT_EQ(below.min.x, h.panel.min.x);
}

TEST(UiLayout, IndentShiftsContentAndAvailableWidth) {
    UiHarness h;
    const Style s;
    Rect inside, after, separator;
    h.frame([&](Ui& ui) {
        ui.indent([&](Ui& in) {
            inside = in.label("Inside").rect();
            separator = [&] {
                in.separator();
                return in.minRect();
            }();
        });
        after = ui.label("After").rect();
    });
    EXPECT_FLOAT_EQ(inside.min.x, h.panel.min.x + s.indent);
    // The separator spans what is left of the panel's width after the indent.
    EXPECT_FLOAT_EQ(separator.max.x, h.panel.max.x);
    EXPECT_FLOAT_EQ(after.min.x, h.panel.min.x);
    EXPECT_FLOAT_EQ(after.min.y, separator.max.y + s.itemSpacing.y);
}

TEST(UiLayout, GridColumnsAlignAcrossRowsOnSecondFrame) {
    UiHarness h;
    const Style s;
    std::vector<Rect> cells;
    const auto build = [&](Ui& ui) {
        cells.clear();
        ui.grid("settings", 2, [&](Ui& g) {
            cells.push_back(g.label("x").rect());
            cells.push_back(g.button("Short").rect());
            cells.push_back(g.label("A much longer label").rect());
            cells.push_back(g.button("B").rect());
        });
    };
    h.frame(build);
    // First frame: row 1's second column only knew the narrow first cell.
    EXPECT_LT(cells[1].min.x, cells[3].min.x);
    h.frame(build);
    ASSERT_EQ(cells.size(), 4u);
    const float column2 = h.panel.min.x + textSize("A much longer label").x + s.itemSpacing.x;
    EXPECT_FLOAT_EQ(cells[1].min.x, column2);
    EXPECT_FLOAT_EQ(cells[3].min.x, column2);
    EXPECT_FLOAT_EQ(cells[0].min.x, h.panel.min.x);
    EXPECT_FLOAT_EQ(cells[2].min.x, h.panel.min.x);
    // Rows are one interact height apart plus spacing; cells of a row share a centre line.
    EXPECT_NEAR(cells[0].centre().y, cells[1].centre().y, 1e-4f);
    EXPECT_FLOAT_EQ(cells[3].min.y, cells[1].max.y + s.itemSpacing.y);
}

TEST(UiLayout, ScrollAreaClipsCullsAndOffsets) {
    UiHarness h;
    const float maxHeight = 100.0f;
    std::vector<Rect> items;
    Rect after;
    const auto build = [&](Ui& ui) {
        items.clear();
        ui.scrollArea("list", maxHeight, [&](Ui& area) {
            for (int i = 0; i < 20; ++i) {
                items.push_back(area.label("Item " + std::to_string(i)).rect());
            }
        });
        after = ui.label("After").rect();
    };
    const Output& first = h.frame(build);
    const Rect view = Rect::fromMinSize(h.panel.min, {h.panel.width(), maxHeight});
    EXPECT_FLOAT_EQ(after.min.y, view.max.y + Style{}.itemSpacing.y);
    EXPECT_TRUE(findText(first, "Item 0"));
    // Items wholly below the view are not painted at all; the ones painted are clipped to it.
    EXPECT_FALSE(findText(first, "Item 19"));
    for (const ClippedShape& shape : first.shapes) {
        if (const auto* t = std::get_if<TextShape>(&shape.shape); t && t->text != "After") {
            EXPECT_EQ(shape.clip, view) << t->text;
        }
    }

    // Wheel towards the user (negative) scrolls the content up by that many points.
    h.moveTo(view.centre());
    h.input.scrollDelta = {0.0f, -50.0f};
    h.frame(build);
    const float before = items[5].min.y;
    h.frame(build);
    EXPECT_FLOAT_EQ(items[5].min.y, before - 50.0f);

    // Far past the end: clamped so that the last item ends at the view's bottom.
    h.input.scrollDelta = {0.0f, -10000.0f};
    h.frame(build);
    const Output& end = h.frame(build);
    EXPECT_FLOAT_EQ(items.back().max.y, view.max.y);
    EXPECT_TRUE(findText(end, "Item 19"));
    EXPECT_FALSE(findText(end, "Item 0"));
}

TEST(UiPainter, EveryShapeIntersectsItsClipRect) {
    UiHarness h({{0.0f, 0.0f}, {200.0f, 120.0f}});
    bool flag = true;
    float value = 0.3f;
    int choice = 1;
    const std::vector<std::string> names{"One", "Two", "Three"};
    const auto build = [&](Ui& ui) {
        for (int i = 0; i < 12; ++i) {
            ui.withId(std::uint64_t(i), [&](Ui& row) {
                row.checkbox(flag, "Flag");
                row.slider("Value", value, 0.0f, 1.0f);
                row.comboBox("Choice", choice, names);
                row.progressBar(0.5f, "half");
            });
        }
    };
    const Output& out = h.frame(build);
    ASSERT_FALSE(out.shapes.empty());
    for (const ClippedShape& s : out.shapes) {
        EXPECT_FALSE(s.clip.empty());
        Rect bounds;
        if (const auto* r = std::get_if<RectShape>(&s.shape)) {
            bounds = r->rect;
        } else if (const auto* c = std::get_if<CircleShape>(&s.shape)) {
            bounds = Rect{c->centre, c->centre}.expand(c->radius);
        } else if (const auto* t = std::get_if<TextShape>(&s.shape)) {
            bounds = Rect::fromMinSize(t->pos, testFonts().textSize(t->text, t->sizePt));
        } else {
            continue;
        }
        EXPECT_FALSE(bounds.intersect(s.clip).empty());
    }
    // Only the rows that fit the 120-point panel are painted.
    int checkMarks = 0;
    for (const ClippedShape& s : out.shapes) {
        if (const auto* t = std::get_if<TextShape>(&s.shape); t && t->text == "Flag") {
            ++checkMarks;
        }
    }
    EXPECT_GE(checkMarks, 1);
    EXPECT_LT(checkMarks, 12);
}

// Every widget shows its label without the "##key" that makes its id unique. Before, combo
// boxes, buttons, radios, list rows, colour swatches, curves and menus painted it whole: the
// editor's Surface section read "shape##surface".
TEST(UiLayout, NoWidgetShowsTheKeyOfItsLabel) {
    UiHarness h;
    int choice = 0;
    bool flag = false;
    glm::vec3 colour(0.5f);
    std::array<float, 3> curve{0.2f, 0.5f, 0.8f};
    const std::vector<std::string> items{"a", "b"};
    const Output& out = h.frame([&](Ui& ui) {
        ui.comboBox("combo##k1", choice, items);
        ui.button("button##k2");
        ui.checkbox(flag, "check##k3");
        ui.radio(true, "radio##k4");
        ui.selectable(false, "row##k5");
        colorEdit(ui, "colour##k6", colour);
        bezierCurveEdit(ui, "curve##k7", curve, {100.0f, 40.0f});
        menu(ui, "menu##k8", [](Ui&) {});
    });
    for (const char* shown :
         {"combo", "button", "check", "radio", "row", "colour", "curve", "menu"})
        EXPECT_TRUE(findText(out, shown)) << shown;
    for (const ClippedShape& shape : out.shapes) {
        if (const auto* t = std::get_if<TextShape>(&shape.shape)) {
            EXPECT_EQ(t->text.find("##"), std::string::npos) << t->text;
        }
    }
}

}  // namespace
}  // namespace grass::ui
