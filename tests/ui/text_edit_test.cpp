// The single-line text edit and typed number entry, driven by simulated keys and pointer.
#include "ui/text_edit.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "tests/ui/ui_harness.h"

namespace grass::ui {
namespace {

using test::UiHarness;

constexpr Modifiers NONE{};
constexpr Modifiers SHIFT{true, false, false};
constexpr Modifiers CTRL{false, true, false};

struct TextEditFixture {
    UiHarness h;
    std::string text;
    Response r;
    bool committed = false;
    int changes = 0;

    void frame() {
        h.frame([&](Ui& ui) {
            r = textEdit(ui, "Name", text, 150.0f, &committed);
            changes += r.changed() ? 1 : 0;
        });
    }
    void key(Key k, Modifiers m = NONE) {
        h.input.keys.push_back({k, m});
        frame();
    }
    void type(const std::string& s) {
        h.input.text = s;
        frame();
    }
    // Focuses the box with a click near its right end (cursor after the last character).
    void focusAtEnd() {
        // Well after any earlier click, so this one is not taken for a double click.
        h.input.timeS += 1.0;
        frame();
        const Rect box = r.rect();
        const Vec2 p{box.max.x - 3.0f, box.centre().y};
        h.clickAt(p, [&](Ui& ui) { r = textEdit(ui, "Name", text, 150.0f, &committed); });
        h.moveTo({700.0f, 500.0f});
        frame();
    }
};

TEST(UiTextEdit, TypingInsertsTextAndReportsChanged) {
    TextEditFixture f;
    f.focusAtEnd();
    ASSERT_TRUE(f.r.hasFocus());
    f.type("héllo");
    EXPECT_EQ(f.text, "héllo");
    EXPECT_TRUE(f.r.changed());
    f.type(" wörld");
    EXPECT_EQ(f.text, "héllo wörld");
    EXPECT_EQ(f.changes, 2);
    EXPECT_TRUE(f.h.ctx.output().wantsKeyboard);
}

// A slow frame (1–3 fps on a software renderer) gathers several keystrokes: keys act where they
// fell between the typed characters. Before, the frame's text went in first and the keys after
// it, so Ctrl+A then "ut" selected "farut" and the next letter replaced it all (seen under Xvfb
// with xdotool typing into a layer's name).
TEST(UiTextEdit, KeysActBetweenTheCharactersTypedInTheSameFrame) {
    TextEditFixture f;
    f.text = "far";
    f.focusAtEnd();
    f.h.input.keys.push_back({Key::A, CTRL, 0});
    f.h.input.text = "ut";
    f.frame();
    EXPECT_EQ(f.text, "ut");
    f.type("m meadow");
    EXPECT_EQ(f.text, "utm meadow");

    // "ab", Backspace, "c" in one frame; then "x", Home, "y".
    f.h.input.text = "abc";
    f.h.input.keys.push_back({Key::Backspace, NONE, 2});
    f.frame();
    EXPECT_EQ(f.text, "utm meadowac");
    f.h.input.text = "xy";
    f.h.input.keys.push_back({Key::Home, NONE, 1});
    f.frame();
    EXPECT_EQ(f.text, "yutm meadowacx");

    // What is typed after Enter in the same frame does not go into the committed text.
    f.h.input.text = "!?";
    f.h.input.keys.push_back({Key::Enter, NONE, 1});
    f.frame();
    EXPECT_TRUE(f.committed);
    EXPECT_EQ(f.text, "y!utm meadowacx");
}

// The frame whose Enter ends the edit still owns its keys: typed together at 1 fps, "/tmp" and
// Enter arrive in one frame, and the "t" must not also reach the app's shortcuts (the editor's
// technique key; seen with xdotool typing an export folder). The frame after is the app's again.
TEST(UiTextEdit, TheFrameWhoseEnterEndsTheEditKeepsItsKeys) {
    TextEditFixture f;
    f.focusAtEnd();
    ASSERT_TRUE(f.r.hasFocus());
    f.h.input.text = "/tmp";
    f.h.input.keys.push_back({Key::Enter, NONE, 4});
    f.frame();
    EXPECT_TRUE(f.committed);
    EXPECT_EQ(f.text, "/tmp");
    EXPECT_TRUE(f.h.ctx.output().wantsKeyboard) << "the t would change the technique";
    f.frame();
    EXPECT_FALSE(f.h.ctx.output().wantsKeyboard);
}

TEST(UiTextEdit, CursorMovesAndDeletesByCodePoints) {
    TextEditFixture f;
    f.text = "aé€b";
    f.focusAtEnd();
    f.key(Key::Left);
    f.key(Key::Backspace);  // removes the 3-byte €
    EXPECT_EQ(f.text, "aéb");
    f.key(Key::Left, SHIFT);  // selects é (2 bytes)
    f.key(Key::Delete);
    EXPECT_EQ(f.text, "ab");
    f.key(Key::Home);
    f.key(Key::Delete);
    EXPECT_EQ(f.text, "b");
    f.key(Key::End);
    f.type("ž");
    EXPECT_EQ(f.text, "bž");
    f.key(Key::Home);
    f.key(Key::End, SHIFT);
    f.type("x");  // typing replaces the selection
    EXPECT_EQ(f.text, "x");
}

TEST(UiTextEdit, CodePointStepsNeverSplitASequence) {
    const std::string s = "a€😀";
    EXPECT_EQ(nextCodePoint(s, 0), 1u);
    EXPECT_EQ(nextCodePoint(s, 1), 4u);
    EXPECT_EQ(nextCodePoint(s, 4), 8u);
    EXPECT_EQ(nextCodePoint(s, 8), 8u);
    EXPECT_EQ(prevCodePoint(s, 8), 4u);
    EXPECT_EQ(prevCodePoint(s, 4), 1u);
    EXPECT_EQ(prevCodePoint(s, 1), 0u);
    EXPECT_EQ(prevCodePoint(s, 0), 0u);
}

TEST(UiTextEdit, CopyCutAndPasteGoThroughInputAndOutput) {
    TextEditFixture f;
    f.text = "hello world";
    f.focusAtEnd();
    f.key(Key::A, CTRL);
    f.key(Key::C, CTRL);
    ASSERT_TRUE(f.h.ctx.output().copiedText.has_value());
    EXPECT_EQ(*f.h.ctx.output().copiedText, "hello world");
    EXPECT_EQ(f.text, "hello world");
    f.key(Key::End);
    f.h.input.clipboardText = "!\n";
    f.key(Key::V, CTRL);
    EXPECT_EQ(f.text, "hello world!") << "line breaks are dropped from single-line pastes";
    f.key(Key::Left, SHIFT);
    f.key(Key::X, CTRL);
    EXPECT_EQ(*f.h.ctx.output().copiedText, "!");
    EXPECT_EQ(f.text, "hello world");
    f.key(Key::C, CTRL);
    EXPECT_FALSE(f.h.ctx.output().copiedText.has_value()) << "nothing selected, nothing copied";
}

TEST(UiTextEdit, EscapeRevertsAndEnterCommits) {
    TextEditFixture f;
    f.text = "keep";
    f.focusAtEnd();
    f.type("xyz");
    EXPECT_EQ(f.text, "keepxyz");
    f.key(Key::Escape);
    EXPECT_EQ(f.text, "keep");
    EXPECT_TRUE(f.r.changed());
    EXPECT_FALSE(f.committed);
    f.frame();
    EXPECT_FALSE(f.r.hasFocus());
    EXPECT_FALSE(f.committed);

    f.focusAtEnd();
    f.type("!");
    f.key(Key::Enter);
    EXPECT_TRUE(f.committed);
    f.frame();
    EXPECT_FALSE(f.r.hasFocus());
    EXPECT_FALSE(f.committed) << "reported once";
    EXPECT_EQ(f.text, "keep!");
}

TEST(UiTextEdit, FocusLossByClickingElsewhereCommits) {
    TextEditFixture f;
    f.focusAtEnd();
    f.type("a");
    f.h.clickAt({700.0f, 500.0f}, [&](Ui& ui) {
        f.r = textEdit(ui, "Name", f.text, 150.0f, &f.committed);
        if (f.committed) {
            f.changes += 100;
        }
    });
    EXPECT_FALSE(f.r.hasFocus());
    EXPECT_GE(f.changes, 100);
}

// An editor at rest draws only when something changes (editor/app/idle_wait.h), so the caret's
// blink must ask for its frames: a focused box asks for one when the caret next appears or
// goes, an unfocused one asks for none.
TEST(UiTextEdit, AFocusedBoxAsksForAFrameWhenItsCaretNextBlinks) {
    TextEditFixture f;
    f.frame();
    EXPECT_FALSE(f.h.ctx.output().repaintAfterS.has_value());
    f.focusAtEnd();
    f.type("a");  // activity: the caret is solid from here for 0.6 s
    const double typedS = f.h.input.timeS - 1.0 / 60.0;
    const auto caretLines = [&] {
        int lines = 0;
        for (const ClippedShape& shape : f.h.ctx.output().shapes)
            lines += std::holds_alternative<PathShape>(shape.shape) ? 1 : 0;
        return lines;
    };
    f.h.input.timeS = typedS + 0.25;
    f.frame();
    ASSERT_TRUE(f.h.ctx.output().repaintAfterS.has_value());
    EXPECT_NEAR(*f.h.ctx.output().repaintAfterS, 0.35, 1e-9);  // it goes at 0.6 s
    const int shownLines = caretLines();
    f.h.input.timeS = typedS + 0.7;
    f.frame();
    EXPECT_NEAR(*f.h.ctx.output().repaintAfterS, 0.3, 1e-9);  // back at 1.0 s
    EXPECT_EQ(caretLines(), shownLines - 1);
    f.h.input.timeS = typedS + 1.1;
    f.frame();
    EXPECT_NEAR(*f.h.ctx.output().repaintAfterS, 0.5, 1e-9);
    EXPECT_EQ(caretLines(), shownLines);
    f.h.clickAt({700.0f, 500.0f}, [&](Ui& ui) { f.r = textEdit(ui, "Name", f.text, 150.0f); });
    EXPECT_FALSE(f.r.hasFocus());
    EXPECT_FALSE(f.h.ctx.output().repaintAfterS.has_value());
}

TEST(UiTextEdit, ClickPlacesCursorBetweenGlyphs) {
    TextEditFixture f;
    f.text = "abcd";
    f.frame();
    const Style& s = f.h.ctx.style();
    const float ab = test::testFonts().textSize("ab", s.textSizePt).x;
    const Rect box = f.r.rect();
    const Vec2 p{box.min.x + s.buttonPadding.x + ab + 1.0f, box.centre().y};
    f.h.clickAt(p, [&](Ui& ui) { f.r = textEdit(ui, "Name", f.text, 150.0f); });
    f.type("X");
    EXPECT_EQ(f.text, "abXcd");
}

TEST(UiTextEdit, DoubleClickSelectsAll) {
    TextEditFixture f;
    f.text = "old name";
    f.frame();
    const Vec2 p = f.r.rect().centre();
    const auto build = [&](Ui& ui) { f.r = textEdit(ui, "Name", f.text, 150.0f); };
    f.h.clickAt(p, build);
    f.h.clickAt(p, build);
    f.type("new");
    EXPECT_EQ(f.text, "new");
}

TEST(UiTextEdit, LongTextScrollsToKeepTheCursorInTheBox) {
    TextEditFixture f;
    f.text = "a rather long piece of text that cannot fit in the box";
    f.focusAtEnd();
    const Rect box = f.r.rect();
    const auto textPos = [&] {
        const auto found = test::findText(f.h.ctx.output(), f.text);
        return found ? found->min.x : 0.0f;
    };
    f.key(Key::End);
    EXPECT_LT(textPos(), box.min.x) << "scrolled left to show the end";
    const float width = test::testFonts().textSize(f.text, f.h.ctx.style().textSizePt).x;
    EXPECT_LE(textPos() + width, box.max.x);
    f.key(Key::Home);
    EXPECT_FLOAT_EQ(textPos(), box.min.x + f.h.ctx.style().buttonPadding.x);
}

TEST(UiTextEdit, IdsStayStableAndUnique) {
    UiHarness h;
    std::string a = "one";
    std::string b = "two";
    Id first;
    for (int i = 0; i < 3; ++i) {
        h.frame([&](Ui& ui) {
            const Response ra = textEdit(ui, "A", a, 100.0f);
            textEdit(ui, "B", b, 100.0f);
            if (i == 0) {
                first = ra.id();
            }
            EXPECT_EQ(ra.id(), first);
        });
        EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
    }
}

// A "Height" drag value with its entry, 0 to 1 at 0.01 a point, at 0.5 and drawn once; `p` is
// its box's centre.
struct HeightEntry {
    UiHarness h;
    float value = 0.5f;
    Response r;
    std::function<void(Ui&)> build = [this](Ui& ui) {
        r = dragValueWithEntry(ui, "Height", value, 0.01f, 0.0f, 1.0f);
    };
    Vec2 p = [this] {
        h.frame(build);
        return r.rect().centre();
    }();
};

TEST(UiTextEdit, DoubleClickOnDragValueTypesANumber) {
    HeightEntry f;
    auto& [h, value, r, build, p] = f;
    h.clickAt(p, build);
    h.clickAt(p, build);
    h.frame(build);
    ASSERT_TRUE(r.hasFocus()) << "the double click opened a focused text box";
    h.input.text = "0.25";
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.5f) << "applied on commit, not while typing";
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.25f);
    EXPECT_TRUE(r.changed());

    // Issue 26: an out-of-range value is refused, not clamped: the box stays open and focused,
    // outlined, with the reason under it; a correction is taken.
    h.clickAt(p, build);
    h.clickAt(p, build);
    h.input.text = "7";
    h.frame(build);
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.25f);
    const Output& refused = h.frame(build);
    EXPECT_TRUE(r.hasFocus()) << "the refused entry keeps the keyboard for the correction";
    EXPECT_TRUE(test::findText(refused, "must be in [0.000, 1.000]").has_value());
    EXPECT_TRUE(test::findText(refused, "7").has_value()) << "the typed text stays visible";
    h.input.text = "abc";  // replaces the selected "7"
    h.frame(build);
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_TRUE(test::findText(h.frame(build), "\"abc\" is not a number").has_value());
    EXPECT_FLOAT_EQ(value, 0.25f);
    h.input.text = "0.75";
    h.frame(build);
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.75f);
    EXPECT_FALSE(test::findText(h.frame(build), "\"abc\" is not a number").has_value());

    // Escape leaves the value alone.
    h.clickAt(p, build);
    h.clickAt(p, build);
    h.input.text = "0.1";
    h.frame(build);
    h.input.keys.push_back({Key::Escape, {}});
    h.frame(build);
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.75f);
    EXPECT_FALSE(r.hasFocus());
}

// A click that does not drag opens the box, as egui's DragValue and Blender's number fields do:
// the gesture a user tries first. Before, it did nothing and what was typed after it was lost.
// A drag still drags and opens nothing.
TEST(UiTextEdit, ASingleClickOnDragValueTypesANumberAndADragDrags) {
    HeightEntry f;
    auto& [h, value, r, build, p] = f;
    h.clickAt(p, build);
    h.frame(build);
    ASSERT_TRUE(r.hasFocus()) << "the click opened a focused text box";
    h.input.text = "0.3";  // typed over the selected value
    h.frame(build);
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 0.3f);
    h.frame(build);
    EXPECT_FALSE(r.hasFocus());

    h.moveTo(p);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(p + Vec2(20.0f, 0.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    h.frame(build);
    EXPECT_NEAR(value, 0.5f, 1e-5f) << "0.3 dragged 20 points at 0.01 a point";
    EXPECT_FALSE(r.hasFocus()) << "a drag opens no text box";
}

TEST(UiTextEdit, CtrlClickOnDragValueTypesAndACheckSaysWhy) {
    UiHarness h;
    int value = 3;
    Response r;
    const auto build = [&](Ui& ui) {
        r = dragValueWithEntry(ui, "Count", value, 1.0f, 0, 100, [](double typed) {
            return typed > 50.0 ? std::string("must be at most 50 blades") : std::string();
        });
    };
    h.frame(build);
    const Vec2 p = r.rect().centre();
    h.input.modifiers = CTRL;
    h.clickAt(p, build);
    h.input.modifiers = NONE;
    h.frame(build);
    ASSERT_TRUE(r.hasFocus()) << "Ctrl+click opens the text box, as in Blender";
    for (const char* typed : {"2.5", "60"}) {
        h.input.text = typed;
        h.frame(build);
        h.input.keys.push_back({Key::Enter, {}});
        h.frame(build);
    }
    EXPECT_EQ(value, 3);
    EXPECT_TRUE(test::findText(h.frame(build), "must be at most 50 blades").has_value());
    // A click elsewhere leaves the refused entry showing: nothing is reverted silently.
    h.clickAt({700.0f, 500.0f}, build);
    EXPECT_FALSE(r.hasFocus());
    EXPECT_TRUE(test::findText(h.frame(build), "must be at most 50 blades").has_value());
    h.clickAt(p, build);
    h.input.keys.push_back({Key::A, CTRL});
    h.frame(build);
    h.input.text = "42";
    h.frame(build);
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_EQ(value, 42);
}

TEST(UiTextEdit, SliderWithEntryDragsAndTypes) {
    UiHarness h;
    float value = 0.0f;
    Response r;
    const auto build = [&](Ui& ui) { r = sliderWithEntry(ui, "Stiffness", value, 0.0f, 10.0f); };
    h.frame(build);
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
    const Style& s = h.ctx.style();
    // The slider track starts the row; the drag box follows it.
    const Vec2 trackEnd{r.rect().min.x + s.sliderWidth - 1.0f, r.rect().centre().y};
    h.moveTo({r.rect().min.x + s.sliderHandleRadius, trackEnd.y});
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(trackEnd + Vec2(50.0f, 0.0f));
    h.frame(build);
    h.release();
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 10.0f);
    const Vec2 box{r.rect().min.x + s.sliderWidth + s.itemSpacing.x + 10.0f, trackEnd.y};
    h.clickAt(box, build);
    h.clickAt(box, build);
    h.input.text = "2.5";
    h.frame(build);
    h.input.keys.push_back({Key::Enter, {}});
    h.frame(build);
    EXPECT_FLOAT_EQ(value, 2.5f);
}

}  // namespace
}  // namespace grass::ui
