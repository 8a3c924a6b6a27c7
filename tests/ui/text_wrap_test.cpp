// wrapText and Ui::wrappedLabel (ui/text_wrap.h): a message read whole in a narrow window.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/ui/ui_harness.h"
#include "ui/text_wrap.h"

namespace grass::ui {
namespace {

using test::findText;
using test::testFonts;
using test::UiHarness;

constexpr float SIZE_PT = 14.0f;

float widthOf(std::string_view text) {
    return testFonts().textSize(text, SIZE_PT).x;
}

std::string joined(const std::vector<std::string>& lines, const char* separator) {
    std::string all;
    for (std::size_t i = 0; i < lines.size(); ++i)
        all += (i ? separator : "") + lines[i];
    return all;
}

TEST(UiTextWrap, WordsBreakAtSpacesIntoLinesThatFit) {
    const std::string text = "export failed: the folder is not writable, choose another one";
    const float width = widthOf("export failed: the");
    const std::vector<std::string> lines = wrapText(testFonts(), SIZE_PT, text, width);
    ASSERT_GT(lines.size(), 2u);
    for (const std::string& line : lines)
        EXPECT_LE(widthOf(line), width) << line;
    EXPECT_EQ(joined(lines, " "), text) << "nothing lost, spaces only where a line broke";
    EXPECT_EQ(lines.front(), "export failed: the") << "a line takes every word that fits";
}

TEST(UiTextWrap, APathWiderThanALineIsCutWhereItMust) {
    const std::string path = "/home/artist/projects/meadow-with-a-long-name/export/gltf/grass.gltf";
    const float width = widthOf("/home/artist/");
    const std::vector<std::string> lines = wrapText(testFonts(), SIZE_PT, "to " + path, width);
    ASSERT_GT(lines.size(), 3u);
    for (const std::string& line : lines)
        EXPECT_LE(widthOf(line), width) << line;
    EXPECT_EQ(joined(lines, ""), "to" + path) << "the path whole, in pieces";
}

TEST(UiTextWrap, NeverCutsInsideAUtf8Sequence) {
    std::string text;
    for (int i = 0; i < 40; ++i)
        text += "\xC3\xA4\xE8\x8D\x89";  // ä and a CJK character: 2- and 3-byte sequences
    const std::vector<std::string> lines =
        wrapText(testFonts(), SIZE_PT, text, widthOf("\xC3\xA4\xE8\x8D\x89") * 2.5f);
    ASSERT_GT(lines.size(), 10u);
    for (const std::string& line : lines) {
        for (std::size_t pos = 0; pos < line.size();)
            EXPECT_NE(decodeUtf8(line, pos), U'\uFFFD') << "a line starts or ends mid-character";
    }
    EXPECT_EQ(joined(lines, ""), text);
}

TEST(UiTextWrap, ANarrowerWidthThanOneCharacterStillMakesProgress) {
    const std::vector<std::string> lines = wrapText(testFonts(), SIZE_PT, "abc", 0.5f);
    EXPECT_EQ(lines, (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(wrapText(testFonts(), SIZE_PT, "", 100.0f).empty());
}

TEST(UiTextWrap, ElidedTextKeepsTheLongestBeginningThatFits) {
    const std::string text = "cannot save /home/artist/projects/meadow: permission denied";
    EXPECT_EQ(elideText(testFonts(), SIZE_PT, text, widthOf(text)), text) << "fits: whole";
    const float width = widthOf(text) * 0.5f;
    const std::string elided = elideText(testFonts(), SIZE_PT, text, width);
    ASSERT_TRUE(elided.ends_with(" \u2026")) << elided;
    const std::string kept = elided.substr(0, elided.size() - std::string(" \u2026").size());
    EXPECT_TRUE(text.starts_with(kept)) << elided;
    EXPECT_LE(widthOf(elided), width);
    EXPECT_GT(widthOf(text.substr(0, kept.size() + 1) + " \u2026"), width)
        << "one character more would not fit";
    // Multi-byte characters stay whole.
    std::string wide;
    for (int i = 0; i < 30; ++i)
        wide += "\xE8\x8D\x89";
    const std::string cut = elideText(testFonts(), SIZE_PT, wide, widthOf(wide) * 0.4f);
    for (std::size_t pos = 0; pos < cut.size();)
        EXPECT_NE(decodeUtf8(cut, pos), U'\uFFFD');
}

TEST(UiTextWrap, AWrappedLabelShowsTheWholeMessageInsideItsPanel) {
    UiHarness h({{10.0f, 20.0f}, {170.0f, 580.0f}});
    const std::string message =
        "exported 4 files (47.2 MB, 398083 instances) to /tmp/artist/projects/meadow/export";
    Rect whole;
    const Output& out = h.frame([&](Ui& ui) { whole = ui.wrappedLabel(message).rect(); });
    std::vector<std::string> shown;
    for (const ClippedShape& shape : out.shapes) {
        if (const auto* t = std::get_if<TextShape>(&shape.shape)) {
            const Rect box = Rect::fromMinSize(t->pos, testFonts().textSize(t->text, t->sizePt));
            EXPECT_LE(box.max.x, h.panel.max.x) << t->text << ": past the panel's edge";
            EXPECT_GE(box.min.y, whole.min.y);
            EXPECT_LE(box.max.y, whole.max.y + 0.01f) << "the label's rect holds every line";
            shown.push_back(t->text);
        }
    }
    ASSERT_GE(shown.size(), 3u);
    const auto withoutSpaces = [](std::string text) {
        std::erase(text, ' ');
        return text;
    };
    EXPECT_EQ(withoutSpaces(joined(shown, "")), withoutSpaces(message)) << "nothing cut off";
    // Without wrapping the one line was wider than the panel.
    EXPECT_GT(testFonts().textSize(message, Style{}.textSizePt).x, h.panel.width());
}

}  // namespace
}  // namespace grass::ui
