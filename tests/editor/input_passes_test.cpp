// A frame's button events as UI passes (editor/app/input_passes.h): at 1 fps a click's press and
// release arrive in one frame, and a double-click's four events too. Before, the UI saw only the
// frame's final state, and these clicks were lost.
#include "app/input_passes.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ui/text_edit.h"
#include "ui/ui_harness.h"

namespace grass::editor {
namespace {

using ui::test::findText;
using ui::test::UiHarness;

// Runs one editor frame: every pass of `events`, the harness's input being the frame's last.
template <class F>
void frameWithEvents(UiHarness& h, const std::vector<ButtonEvent>& events, F&& build) {
    std::vector<ui::Input> passes = uiPasses(h.input, events);
    for (std::size_t i = 0; i + 1 < passes.size(); ++i) {
        h.ctx.beginFrame(passes[i]);
        ui::Ui ui(h.ctx, h.panel);
        build(ui);
        h.ctx.endFrame();
    }
    h.input = passes.back();
    h.frame(build);
}

std::vector<ButtonEvent> clicks(ui::Vec2 at, int count, double startS, double gapS) {
    std::vector<ButtonEvent> events;
    for (int i = 0; i < count; ++i) {
        events.push_back({0, true, at, startS + gapS * i});
        events.push_back({0, false, at, startS + gapS * i + 0.03});
    }
    return events;
}

TEST(InputPasses, NoEventsIsOnePassOfTheFrame) {
    ui::Input last;
    last.pointerPos = {5.0f, 6.0f};
    last.text = "x";
    const auto passes = uiPasses(last, {});
    ASSERT_EQ(passes.size(), 1u);
    EXPECT_EQ(passes[0].pointerPos, last.pointerPos);
    EXPECT_EQ(passes[0].text, "x");
}

TEST(InputPasses, AClickInsideOneFrameIsAPressPassAndAReleasePassAtItsPlace) {
    ui::Input last;
    last.pointerPos = {100.0f, 100.0f};  // the pointer moved on after the click
    last.keys = {ui::KeyEvent{ui::Key::Enter, {}}};
    const auto passes = uiPasses(last, clicks({10.0f, 20.0f}, 1, 2.0, 0.0));
    ASSERT_EQ(passes.size(), 3u);
    EXPECT_TRUE(passes[0].buttonDown[0]);
    EXPECT_EQ(passes[0].pointerPos, ui::Vec2(10.0f, 20.0f));
    EXPECT_DOUBLE_EQ(passes[0].timeS, 2.0);
    EXPECT_TRUE(passes[0].keys.empty()) << "keys belong to the frame's last pass";
    EXPECT_FALSE(passes[1].buttonDown[0]);
    EXPECT_DOUBLE_EQ(passes[1].timeS, 2.03);
    EXPECT_EQ(passes[2].pointerPos, last.pointerPos);
    EXPECT_EQ(passes[2].keys.size(), 1u);
}

// Each pass but the last names the event it came from, so the editor can read what else the
// event carries (the typed text and pointer path before it); an event that changes nothing (a
// second press of a held button) makes no pass and is named by none.
TEST(InputPasses, EachPassNamesTheEventItCameFrom) {
    ui::Input last;
    std::vector<ButtonEvent> events = clicks({10.0f, 20.0f}, 1, 2.0, 0.0);
    events.insert(events.begin() + 1, ButtonEvent{0, true, {11.0f, 20.0f}, 2.01});  // a repeat
    events.push_back({1, true, {30.0f, 40.0f}, 2.1});  // the right button
    std::vector<PassSource> sources{{99, true}};
    const auto passes = uiPasses(last, events, &sources);
    ASSERT_EQ(passes.size(), 4u);
    EXPECT_EQ(sources, (std::vector<PassSource>{{0, false}, {2, false}, {3, false}}));
    EXPECT_EQ(passes[2].pointerPos, ui::Vec2(30.0f, 40.0f));
}

// Keys and text typed before a click come in a pass of their own just before its press, with the
// buttons as they were, each key's place counted in its own piece; the last pass has the rest.
TEST(InputPasses, TheKeysTypedBeforeAClickComeInAPassOfTheirOwnBeforeIt) {
    ui::Input last;
    last.pointerPos = {100.0f, 100.0f};
    last.text = "35x";
    last.keys = {ui::KeyEvent{ui::Key::Backspace, {}, 1}, ui::KeyEvent{ui::Key::Enter, {}, 3}};
    std::vector<ButtonEvent> events = clicks({10.0f, 20.0f}, 1, 2.0, 0.0);
    for (ButtonEvent& e : events) {
        e.typedBefore = 2;  // "35" and the Backspace between its digits came before the click
        e.keysBefore = 1;
    }
    std::vector<PassSource> sources;
    const auto passes = uiPasses(last, events, &sources);
    ASSERT_EQ(passes.size(), 4u);
    EXPECT_EQ(sources, (std::vector<PassSource>{{0, true}, {0, false}, {1, false}}));
    EXPECT_EQ(passes[0].text, "35");
    ASSERT_EQ(passes[0].keys.size(), 1u);
    EXPECT_EQ(passes[0].keys[0].key, ui::Key::Backspace);
    EXPECT_EQ(passes[0].keys[0].textBefore, 1u);
    EXPECT_FALSE(passes[0].buttonDown[0]) << "typed before the press";
    EXPECT_TRUE(passes[1].buttonDown[0]);
    EXPECT_TRUE(passes[1].text.empty() && passes[1].keys.empty());
    EXPECT_EQ(passes[3].text, "x");
    ASSERT_EQ(passes[3].keys.size(), 1u);
    EXPECT_EQ(passes[3].keys[0].key, ui::Key::Enter);
    EXPECT_EQ(passes[3].keys[0].textBefore, 1u);
    EXPECT_EQ(passes[3].pointerPos, last.pointerPos);
}

// A name typed into a field and a click elsewhere inside one slow frame: the field takes the
// text before the click ends its entry. Before, the text came with the frame's last pass, after
// the click had taken the keyboard from the field, and was lost.
TEST(InputPasses, TextTypedJustBeforeAClickElsewhereReachesTheFieldThatHadTheKeyboard) {
    UiHarness h;
    std::string name = "grass";
    bool committed = false;
    const auto build = [&](ui::Ui& ui) {
        bool now = false;
        ui::textEdit(ui, "name", name, 150.0f, &now);
        committed = committed || now;
        ui.label("elsewhere");
    };
    const ui::Output& first = h.frame(build);
    const auto box = findText(first, "grass");
    const auto elsewhere = findText(first, "elsewhere");
    ASSERT_TRUE(box && elsewhere);
    h.clickAt(box->max + ui::Vec2(2.0f, 0.0f), build);  // the cursor after the text
    h.moveTo(elsewhere->centre());
    h.input.text = "land";
    std::vector<ButtonEvent> events = clicks(elsewhere->centre(), 1, h.input.timeS, 0.0);
    for (ButtonEvent& e : events)
        e.typedBefore = 4;
    frameWithEvents(h, events, build);
    EXPECT_EQ(name, "grassland");
    EXPECT_TRUE(committed) << "the click elsewhere ends the entry";
}

TEST(InputPasses, AQuickClickTogglesACheckboxThatTheFrameAloneMisses) {
    for (const bool withPasses : {false, true}) {
        UiHarness h;
        bool on = false;
        const auto build = [&](ui::Ui& ui) { ui.checkbox(on, "snow"); };
        const ui::Output& first = h.frame(build);
        const auto box = findText(first, "snow");
        ASSERT_TRUE(box.has_value());
        h.moveTo(box->centre());
        h.frame(build);
        // Press and release between two frames: the frame's own state shows the button up.
        if (withPasses)
            frameWithEvents(h, clicks(box->centre(), 1, h.input.timeS, 0.0), build);
        else
            h.frame(build);
        EXPECT_EQ(on, withPasses) << (withPasses ? "the click is lost" : "nothing was seen");
    }
}

TEST(InputPasses, TwoClicksInOneFrameOpenANumberFieldForTyping) {
    UiHarness h;
    float value = 0.5f;
    const auto build = [&](ui::Ui& ui) {
        ui::dragValueWithEntry(ui, "height", value, 0.01f, 0.0f, 10.0f, 2);
    };
    const ui::Output& first = h.frame(build);
    const auto number = findText(first, "0.50");
    ASSERT_TRUE(number.has_value());
    h.moveTo(number->centre());
    h.frame(build);
    frameWithEvents(h, clicks(number->centre(), 2, h.input.timeS, 0.15), build);
    h.frame(build);  // the entry box appears
    h.input.keys = {ui::KeyEvent{ui::Key::A, ui::Modifiers{.ctrl = true}}};
    h.frame(build);
    h.input.text = "2.25";
    h.frame(build);
    h.input.keys = {ui::KeyEvent{ui::Key::Enter, {}}};
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 2.25f);
}

// A double-click is judged by the events' times, not the frames': two clicks 0.15 s apart that
// arrive a second apart (at 1 fps) still count; two clicks 0.6 s apart do not.
TEST(InputPasses, ADoubleClickIsJudgedByEventTimesAcrossSlowFrames) {
    for (const double gapS : {0.15, 0.6}) {
        UiHarness h;
        int doubles = 0;
        const auto build = [&](ui::Ui& ui) {
            if (ui.button("reset").doubleClicked())
                ++doubles;
        };
        const ui::Output& first = h.frame(build);
        const auto button = findText(first, "reset");
        ASSERT_TRUE(button.has_value());
        h.moveTo(button->centre());
        h.frame(build);
        const double t0 = h.input.timeS;
        auto events = clicks(button->centre(), 2, t0, gapS);
        const std::vector<ButtonEvent> firstClick(events.begin(), events.begin() + 2);
        const std::vector<ButtonEvent> secondClick(events.begin() + 2, events.end());
        h.input.timeS = t0 + 1.0;  // the frame ends a second later
        frameWithEvents(h, firstClick, build);
        h.input.timeS = t0 + 2.0;
        frameWithEvents(h, secondClick, build);
        EXPECT_EQ(doubles, gapS < 0.3 ? 1 : 0) << "clicks " << gapS << " s apart";
    }
}

}  // namespace
}  // namespace grass::editor
