// Widgets driven by simulated pointer and keyboard input over several frames.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/ui/ui_harness.h"

namespace grass::ui {
namespace {

using test::findText;
using test::UiHarness;

TEST(UiInteraction, ClickTogglesCheckbox) {
    UiHarness h;
    bool enabled = false;
    Response r;
    const auto build = [&](Ui& ui) { r = ui.checkbox(enabled, "Enabled"); };
    h.frame(build);
    const Vec2 centre = r.rect().centre();
    h.moveTo(centre);
    h.frame(build);
    EXPECT_TRUE(r.hovered());
    h.press();
    h.frame(build);
    EXPECT_FALSE(enabled) << "toggles on release, not on press";
    h.release();
    h.frame(build);
    EXPECT_TRUE(enabled);
    EXPECT_TRUE(r.clicked());
    EXPECT_TRUE(r.changed());
    h.clickAt(centre, build);
    EXPECT_FALSE(enabled);
}

TEST(UiInteraction, ButtonClickedOnlyWhenPressAndReleaseBothInside) {
    UiHarness h;
    int clicks = 0;
    Rect rect;
    const auto build = [&](Ui& ui) {
        const Response r = ui.button("Apply");
        rect = r.rect();
        clicks += r.clicked() ? 1 : 0;
    };
    h.frame(build);
    const Vec2 inside = rect.centre();
    const Vec2 outside = rect.max + Vec2(40.0f);

    // Pressed inside, released outside.
    h.moveTo(inside);
    h.press();
    h.frame(build);
    h.moveTo(outside);
    h.release();
    h.frame(build);
    EXPECT_EQ(clicks, 0);
    // Pressed outside, released inside.
    h.press();
    h.frame(build);
    h.moveTo(inside);
    h.release();
    h.frame(build);
    EXPECT_EQ(clicks, 0);
    // Both inside.
    h.clickAt(inside, build);
    EXPECT_EQ(clicks, 1);
    // Pressed and released within one frame still counts.
    h.input.buttonPressed[0] = true;
    h.input.buttonReleased[0] = true;
    h.frame(build);
    h.input.buttonPressed[0] = h.input.buttonReleased[0] = false;
    EXPECT_EQ(clicks, 2);
}

TEST(UiInteraction, SliderDragMovesByValuePerPointAndClampsAtBothEnds) {
    UiHarness h;
    const Style s;
    float value = 40.0f;
    Response r;
    const auto build = [&](Ui& ui) { r = ui.slider("Density", value, 0.0f, 200.0f); };
    h.frame(build);
    const float travel = s.sliderWidth - 2.0f * s.sliderHandleRadius;
    const float perPoint = 200.0f / travel;
    const float handleX = r.rect().min.x + s.sliderHandleRadius + 40.0f / perPoint;
    const float y = r.rect().centre().y;

    // Pressing on the handle keeps the value; dragging moves it by range / travel per point.
    h.moveTo({handleX, y});
    h.press();
    h.frame(build);
    EXPECT_NEAR(value, 40.0f, 1e-3f);
    h.moveTo({handleX + 25.0f, y + 30.0f});
    h.frame(build);
    EXPECT_TRUE(r.dragged());
    EXPECT_TRUE(r.changed());
    EXPECT_NEAR(value, 40.0f + 25.0f * perPoint, 1e-3f);
    // Dragging outside the widget keeps tracking, clamped at the ends.
    h.moveTo({handleX + 1000.0f, y});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 200.0f);
    h.moveTo({handleX - 1000.0f, y});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.0f);
    // The release ends the drag (its pass still takes the drag's last stretch); after it, the
    // slider is no longer dragged.
    h.release();
    h.frame(build);
    EXPECT_TRUE(r.dragStopped());
    EXPECT_FLOAT_EQ(value, 0.0f);
    h.frame(build);
    EXPECT_FALSE(r.dragged());
}

TEST(UiInteraction, LogSliderMapsTrackEndsToRangeEnds) {
    UiHarness h;
    const Style s;
    float value = 10.0f;
    Response r;
    const auto build = [&](Ui& ui) {
        r = ui.slider("Scale", value, 1.0f, 1000.0f, SliderOptions{.logarithmic = true});
    };
    h.frame(build);
    const float x0 = r.rect().min.x + s.sliderHandleRadius;
    const float x1 = r.rect().max.x - s.sliderHandleRadius;
    const float y = r.rect().centre().y;
    h.moveTo({x0, y});
    h.press();
    h.frame(build);
    EXPECT_NEAR(value, 1.0f, 1e-4f);
    h.moveTo({x1, y});
    h.frame(build);
    EXPECT_NEAR(value, 1000.0f, 1e-2f);
    // The middle of the track is the geometric mean.
    h.moveTo({0.5f * (x0 + x1), y});
    h.frame(build);
    EXPECT_NEAR(value, std::sqrt(1000.0f), 1e-3f);
    h.release();
    h.frame(build);
}

TEST(UiInteraction, IntSliderRoundsToWholeNumbers) {
    UiHarness h;
    const Style s;
    int count = 0;
    Response r;
    const auto build = [&](Ui& ui) { r = ui.slider("Count", count, 0, 10); };
    h.frame(build);
    const float x0 = r.rect().min.x + s.sliderHandleRadius;
    const float travel = s.sliderWidth - 2.0f * s.sliderHandleRadius;
    h.moveTo({x0 + 0.34f * travel, r.rect().centre().y});
    h.press();
    h.frame(build);
    EXPECT_EQ(count, 3);
    h.release();
    h.frame(build);
}

TEST(UiInteraction, DragValueChangesBySpeedTimesDelta) {
    UiHarness h;
    float height = 1.0f;
    int blades = 100;
    Response rf, ri;
    const auto build = [&](Ui& ui) {
        rf = ui.dragValue("Height", height, 0.01f, 0.0f, 1.5f);
        ri = ui.dragValue("Blades", blades, 0.25f, 0, 1000);
    };
    h.frame(build);
    Vec2 p = rf.rect().centre();
    h.moveTo(p);
    h.press();
    h.frame(build);
    for (int i = 0; i < 3; ++i) {
        p.x += 10.0f;
        h.moveTo(p);
        h.frame(build);
    }
    EXPECT_NEAR(height, 1.3f, 1e-5f);
    p.x += 100.0f;
    h.moveTo(p);
    h.frame(build);
    EXPECT_FLOAT_EQ(height, 1.5f) << "clamped at max";
    h.release();
    h.frame(build);

    // Integers accumulate sub-step movement: 4 frames of 1 point at 0.25 per point is +1.
    p = ri.rect().centre();
    h.moveTo(p);
    h.press();
    h.frame(build);
    for (int i = 0; i < 4; ++i) {
        p.x += 1.0f;
        h.moveTo(p);
        h.frame(build);
    }
    EXPECT_EQ(blades, 101);
    h.release();
    h.frame(build);
}

// At a low frame rate a drag's last stretch arrives with its release (the editor runs one pass
// per button event, the release's at its own place), and a flick's whole motion does: the value
// moves by it. A click that ends a point or two from its press moves nothing.
TEST(UiInteraction, DragValueTakesTheStretchThatCameWithTheRelease) {
    UiHarness h;
    float height = 1.0f;
    Response r;
    const auto build = [&](Ui& ui) { r = ui.dragValue("Height", height, 0.01f, 0.0f, 1.5f); };
    h.frame(build);
    Vec2 p = r.rect().centre();
    // Held over two frames, released 20 points on.
    h.moveTo(p);
    h.press();
    h.frame(build);
    p.x += 10.0f;
    h.moveTo(p);
    h.frame(build);
    p.x += 20.0f;
    h.moveTo(p);
    h.release();
    h.frame(build);
    EXPECT_NEAR(height, 1.3f, 1e-5f) << "the stretch that came with the release was lost";
    // A flick: the press's pass, then the release's 25 points away.
    p = r.rect().centre();
    h.moveTo(p);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(p - Vec2(25.0f, 0.0f));
    h.release();
    h.frame(build);
    EXPECT_NEAR(height, 1.05f, 1e-5f) << "the flick's motion was lost";
    // A click released 2 points from its press: no drag, no change.
    const float beforeClick = height;
    h.moveTo(p);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(p + Vec2(2.0f, 0.0f));
    h.release();
    h.frame(build);
    EXPECT_EQ(height, beforeClick) << "a click moved the value";
}

TEST(UiInteraction, ComboBoxOpensOnClickAndPickChangesValue) {
    UiHarness h;
    int technique = 0;
    const std::vector<std::string> items{"Blades", "Billboards", "Stems"};
    Response r;
    const auto build = [&](Ui& ui) { r = ui.comboBox("Technique", technique, items); };
    const Output& closed = h.frame(build);
    EXPECT_FALSE(findText(closed, "Stems"));

    h.clickAt(r.rect().centre(), build);
    const Output& open = h.frame(build);
    const std::optional<Rect> stems = findText(open, "Stems");
    ASSERT_TRUE(stems);
    EXPECT_GT(stems->min.y, r.rect().max.y) << "the list opens below the box";

    h.moveTo(stems->centre());
    h.frame(build);
    h.press();
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_EQ(technique, 2);
    EXPECT_TRUE(r.changed());
    EXPECT_FALSE(findText(h.frame(build), "Billboards")) << "a pick closes the list";

    // Escape closes it without a change; so does a press outside.
    h.clickAt(r.rect().centre(), build);
    EXPECT_TRUE(findText(h.frame(build), "Billboards"));
    h.input.keys.push_back({Key::Escape, {}});
    h.frame(build);
    EXPECT_FALSE(findText(h.frame(build), "Billboards"));
    h.clickAt(r.rect().centre(), build);
    h.clickAt({700.0f, 500.0f}, build);
    EXPECT_FALSE(findText(h.frame(build), "Billboards"));
    EXPECT_EQ(technique, 2);
}

// A combo box is as wide as its selected text where the panel has room, never narrower than
// the style's width and never wider than the room: the export window's long format names were
// cut at 120 points.
TEST(UiInteraction, AComboBoxShowsItsWholeTextWhereThereIsRoom) {
    const std::vector<std::string> items{"short", "glTF per layer (EXT_mesh_gpu_instancing)"};
    for (const float panelWidth : {600.0f, 200.0f}) {
        UiHarness h({{10.0f, 20.0f}, {10.0f + panelWidth, 580.0f}});
        int choice = 0;
        Response r;
        const auto build = [&](Ui& ui) { r = ui.comboBox("format", choice, items); };
        h.frame(build);
        const float narrow = r.rect().width();
        EXPECT_FLOAT_EQ(narrow, h.ctx.style().comboWidth);
        choice = 1;
        const Output& out = h.frame(build);
        const std::optional<Rect> text = findText(out, items[1]);
        ASSERT_TRUE(text);
        if (panelWidth > 500.0f) {
            EXPECT_GT(r.rect().max.x, text->max.x) << "the whole name lies inside the box";
        } else {
            EXPECT_LE(r.rect().max.x, 10.0f + panelWidth) << "no wider than the panel";
            EXPECT_GE(r.rect().width(), narrow);
        }
    }
}

TEST(UiInteraction, OnlyTheTopmostWidgetIsHoveredAndClicked) {
    UiHarness h;
    int choice = 0;
    int buttonClicks = 0;
    bool buttonHovered = false;
    Rect buttonRect;
    const std::vector<std::string> items{"First", "Second", "Third"};
    Response combo;
    const auto build = [&](Ui& ui) {
        combo = ui.comboBox("Pick", choice, items);
        const Response b = ui.button("Underneath");
        buttonHovered = b.hovered();
        buttonRect = b.rect();
        buttonClicks += b.clicked() ? 1 : 0;
    };
    h.frame(build);
    h.clickAt(combo.rect().centre(), build);
    const std::optional<Rect> first = findText(h.frame(build), "First");
    ASSERT_TRUE(first);
    // The popup's first item lies over the button below the combo box.
    ASSERT_GT(first->min.y, combo.rect().max.y);
    ASSERT_TRUE(buttonRect.contains(first->centre()));
    h.moveTo(first->centre());
    h.frame(build);
    h.frame(build);
    EXPECT_FALSE(buttonHovered);
    h.press();
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_EQ(buttonClicks, 0);
    EXPECT_EQ(choice, 0);
    EXPECT_FALSE(findText(h.frame(build), "Second")) << "picking the item closed the list";
    // With the popup gone the button is reachable again.
    h.frame(build);
    EXPECT_TRUE(buttonHovered);
}

TEST(UiInteraction, CollapsingHeaderTogglesItsContent) {
    UiHarness h;
    Response header;
    const auto build = [&](Ui& ui) {
        header = ui.collapsingHeader("Wind", [](Ui& in) { in.label("Strength"); });
        ui.label("Footer");
    };
    const Output& closed = h.frame(build);
    EXPECT_FALSE(findText(closed, "Strength"));
    h.clickAt(header.rect().centre(), build);
    const Output& open = h.frame(build);
    const std::optional<Rect> content = findText(open, "Strength");
    ASSERT_TRUE(content);
    EXPECT_FLOAT_EQ(content->min.x, h.panel.min.x + Style{}.indent);
    EXPECT_GT(findText(open, "Footer")->min.y, content->max.y);
    h.clickAt(header.rect().centre(), build);
    EXPECT_FALSE(findText(h.frame(build), "Strength"));
}

TEST(UiInteraction, IdsAreStableAcrossFramesAndDistinctInLoops) {
    UiHarness h;
    std::vector<Id> ids;
    const auto build = [&](Ui& ui) {
        ids.clear();
        ids.push_back(ui.button("Save").id());
        for (int i = 0; i < 3; ++i) {
            ui.withId(std::uint64_t(i), [&](Ui& row) { ids.push_back(row.button("Remove").id()); });
        }
    };
    h.frame(build);
    const std::vector<Id> first = ids;
    h.frame(build);
    EXPECT_EQ(ids, first);
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        for (std::size_t j = i + 1; j < ids.size(); ++j) {
            EXPECT_NE(ids[i], ids[j]) << i << " " << j;
        }
    }
    // Forgetting the index in a loop is detected.
    h.frame([](Ui& ui) {
        for (int i = 0; i < 3; ++i) {
            ui.button("Remove");
        }
    });
    EXPECT_EQ(h.ctx.duplicateIdCount(), 2);
}

TEST(UiInteraction, FocusFollowsClicksAndTab) {
    UiHarness h;
    std::vector<Response> fields(2);
    const auto build = [&](Ui& ui) {
        // Stand-ins for text edits: focusable boxes built from the public pieces.
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const Rect r = ui.allocate({100.0f, ui.style().interactHeight});
            fields[i] = ui.interact(r, ui.makeId(std::uint64_t(i)),
                                    Sense{.click = true, .focusable = true});
        }
    };
    h.frame(build);
    h.clickAt(fields[0].rect().centre(), build);
    EXPECT_TRUE(fields[0].hasFocus());
    EXPECT_TRUE(h.ctx.output().wantsKeyboard);
    h.input.keys.push_back({Key::Tab, {}});
    h.frame(build);
    h.frame(build);
    EXPECT_TRUE(fields[1].hasFocus());
    EXPECT_FALSE(fields[0].hasFocus());
    // A press on nothing focusable drops focus; the widget hears of it once.
    h.clickAt({700.0f, 500.0f}, build);
    EXPECT_FALSE(fields[1].hasFocus());
    EXPECT_TRUE(fields[1].lostFocus());
    EXPECT_FALSE(h.ctx.output().wantsKeyboard);
    h.frame(build);
    EXPECT_FALSE(fields[1].lostFocus());
}

TEST(UiInteraction, ScrollBarDragScrollsContent) {
    UiHarness h;
    std::vector<Rect> items;
    const auto build = [&](Ui& ui) {
        items.clear();
        ui.scrollArea("list", 100.0f, [&](Ui& area) {
            for (int i = 0; i < 40; ++i) {
                items.push_back(area.label("Row " + std::to_string(i)).rect());
            }
        });
    };
    h.frame(build);
    h.frame(build);
    const float top = items[0].min.y;
    // The handle sits at the top of the bar on the right edge of the view.
    const Vec2 handle{h.panel.max.x - 0.5f * Style{}.scrollBarWidth, h.panel.min.y + 4.0f};
    h.moveTo(handle);
    h.press();
    h.frame(build);
    h.moveTo(handle + Vec2(0.0f, 1000.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_LT(items[0].min.y, top - 500.0f);
    EXPECT_FLOAT_EQ(items.back().max.y, h.panel.min.y + 100.0f) << "clamped at the end";
}

TEST(UiInteraction, TooltipAndPointerOwnershipFollowHover) {
    UiHarness h;
    Response r;
    const auto build = [&](Ui& ui) { r = ui.button("Hover me").onHoverText("Explains it"); };
    const Output& away = h.frame(build);
    EXPECT_FALSE(away.wantsPointer);
    EXPECT_FALSE(findText(away, "Explains it"));
    h.moveTo(r.rect().centre());
    const Output& over = h.frame(build);
    EXPECT_TRUE(over.wantsPointer);
    const std::optional<Rect> tip = findText(over, "Explains it");
    ASSERT_TRUE(tip);
    // Tooltips are the last layer: painted after (over) everything else.
    EXPECT_TRUE(std::holds_alternative<TextShape>(over.shapes.back().shape));
}

// A setting's help runs to 200 characters (what it does, what it allows, its JSON key): the
// tooltip wraps it into lines within the screen, every word shown. Before (2026-12-07) it was
// one line, cut off at the window's right edge ("… project.json \"clear_collid").
TEST(UiInteraction, ALongTooltipWrapsWithinTheScreen) {
    UiHarness h;
    h.input.screenRect = {{0.0f, 0.0f}, {420.0f, 600.0f}};
    const std::string help =
        "keep clearance from every collider where it stands at time 0, and no grass under one "
        "(inside it, or under a rock open at the bottom) \u00b7 allowed: true or false \u00b7 "
        "project.json \"clear_colliders\"";
    Response r;
    const auto build = [&](Ui& ui) { r = ui.button("clear colliders").onHoverText(help); };
    h.frame(build);
    h.moveTo(r.rect().centre());
    const Output& over = h.frame(build);
    std::string shown;
    int lines = 0;
    for (const ClippedShape& clipped : over.shapes) {
        const auto* text = std::get_if<TextShape>(&clipped.shape);
        if (text == nullptr || text->text == "clear colliders")
            continue;
        ++lines;
        shown += (shown.empty() ? "" : " ") + text->text;
        const Rect box =
            Rect::fromMinSize(text->pos, test::testFonts().textSize(text->text, text->sizePt));
        EXPECT_GE(box.min.x, 0.0f) << text->text;
        EXPECT_LE(box.max.x, 420.0f) << "cut off at the screen's edge: " << text->text;
    }
    EXPECT_GE(lines, 3);
    EXPECT_EQ(shown, help) << "every word, in order";
    // A short one stays one line.
    const auto brief = [&](Ui& ui) { r = ui.button("clear colliders").onHoverText("Explains it"); };
    EXPECT_TRUE(findText(h.frame(brief), "Explains it"));
}

}  // namespace
}  // namespace grass::ui
