// FontAtlas (ui/font.h): loading errors, metrics of DejaVu Sans, UTF-8 decoding and the atlas
// image the backend uploads.
#include "ui/font.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_paths.h"

namespace grass::ui {
namespace {

FontAtlas loadDefaultFont() {
    std::string error;
    auto font = FontAtlas::load(FontAtlas::defaultFontPath(), &error);
    // Without the font nothing else here means anything: fail loudly, naming the package.
    if (!font) {
        ADD_FAILURE() << error;
        std::abort();
    }
    return std::move(*font);
}

TEST(FontAtlas, MissingFileNamesFileAndProblem) {
    std::string error;
    const auto font = FontAtlas::load("/nonexistent/dir/NoSuchFont.ttf", &error);
    EXPECT_FALSE(font.has_value());
    EXPECT_NE(error.find("/nonexistent/dir/NoSuchFont.ttf"), std::string::npos) << error;
    EXPECT_NE(error.find("no such file"), std::string::npos) << error;
}

TEST(FontAtlas, NonFontFileIsRejectedWithReason) {
    const std::filesystem::path file = test::scratchDir("font-not-a-font") / "not-a-font.ttf";
    {
        std::ofstream out(file, std::ios::binary);
        out << "This is a text file pretending to be a font, long enough to have a header.\n";
    }
    std::string error;
    const auto font = FontAtlas::load(file, &error);
    EXPECT_FALSE(font.has_value());
    EXPECT_NE(error.find(file.string()), std::string::npos) << error;
    EXPECT_NE(error.find("not a TrueType/OpenType font"), std::string::npos) << error;
}

// A real sfnt header whose table directory points past the end: rejected before stb_truetype
// would read out of bounds.
TEST(FontAtlas, TruncatedFontIsRejected) {
    std::ifstream in(FontAtlas::defaultFontPath(), std::ios::binary);
    std::string bytes(4096, '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    const std::filesystem::path file = test::scratchDir("font-truncated") / "truncated.ttf";
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    std::string error;
    EXPECT_FALSE(FontAtlas::load(file, &error).has_value());
    EXPECT_NE(error.find("not a TrueType/OpenType font"), std::string::npos) << error;
}

// DejaVu Sans: ascent 1901, descent −483 of 2048 units per em, no line gap, so a line is
// 2384 / 2048 ≈ 1.164 em.
TEST(FontAtlas, DejaVuMetricsAreSane) {
    const FontAtlas font = loadDefaultFont();
    for (const float size : {10.0f, 14.0f, 24.0f}) {
        EXPECT_NEAR(font.lineHeight(size), 1.164f * size, 0.01f * size);
        EXPECT_GT(font.ascent(size), 0.8f * size);
        EXPECT_LT(font.ascent(size), font.lineHeight(size));
    }
    const Glyph& h = font.glyph('H', 20.0f);
    EXPECT_GT(h.advance, 0.5f * 20.0f);
    EXPECT_LT(h.advance, 1.0f * 20.0f);
    // Capital H stands on the baseline (y = 0) and reaches up to about the cap height.
    EXPECT_NEAR(h.offset.max.y, 0.0f, 1.0f);
    EXPECT_LT(h.offset.min.y, -0.6f * 20.0f);
    EXPECT_GT(h.uv.max.x, h.uv.min.x);
    EXPECT_GT(h.uv.max.y, h.uv.min.y);
}

TEST(FontAtlas, WidthGrowsWithSizeAndIsAdditive) {
    const FontAtlas font = loadDefaultFont();
    const Vec2 small = font.textSize("Hello", 12.0f);
    const Vec2 large = font.textSize("Hello", 24.0f);
    EXPECT_GT(small.x, 0.0f);
    EXPECT_NEAR(large.x, 2.0f * small.x, 0.01f * large.x);
    EXPECT_GT(large.y, small.y);
    // No kerning: the width of a concatenation is the sum of the widths.
    const float hello = font.textSize("Hello", 14.0f).x;
    const float world = font.textSize(" World", 14.0f).x;
    EXPECT_NEAR(font.textSize("Hello World", 14.0f).x, hello + world, 1e-3f);
}

TEST(FontAtlas, NewlinesAddLinesAndWidthIsTheWidest) {
    const FontAtlas font = loadDefaultFont();
    const Vec2 two = font.textSize("Hello\nHi", 14.0f);
    EXPECT_NEAR(two.y, 2.0f * font.lineHeight(14.0f), 1e-4f);
    EXPECT_NEAR(two.x, font.textSize("Hello", 14.0f).x, 1e-4f);
    EXPECT_NEAR(font.textSize("", 14.0f).y, font.lineHeight(14.0f), 1e-4f);
    EXPECT_EQ(font.textSize("", 14.0f).x, 0.0f);
}

TEST(FontAtlas, MeasuresUtf8Multibyte) {
    const FontAtlas font = loadDefaultFont();
    // "Größe": ö and ß are two bytes each; five glyphs, not seven.
    const float width = font.textSize(
                                "Gr\xC3\xB6\xC3\x9F"
                                "e",
                                14.0f)
                            .x;
    float sum = 0.0f;
    for (const char32_t cp : {U'G', U'r', U'\u00F6', U'\u00DF', U'e'})
        sum += font.glyph(cp, 14.0f).advance;
    EXPECT_NEAR(width, sum, 1e-3f);
    EXPECT_TRUE(font.hasGlyph(U'\u00DF'));
}

TEST(Utf8, DecodesValidAndReplacesInvalid) {
    const auto decodeAll = [](std::string_view text) {
        std::u32string out;
        for (std::size_t pos = 0; pos < text.size();)
            out += decodeUtf8(text, pos);
        return out;
    };
    EXPECT_EQ(decodeAll("a\xC3\xB6\xE2\x82\xAC\xF0\x9F\x8C\xB1"), U"a\u00F6\u20AC\U0001F331");
    // Stray continuation byte, truncated sequence before 'x', overlong '/', a surrogate.
    EXPECT_EQ(decodeAll("\x80"), U"\uFFFD");
    EXPECT_EQ(decodeAll("\xE2\x82x"), U"\uFFFDx");
    EXPECT_EQ(decodeAll("\xC0\xAF"), U"\uFFFD");
    EXPECT_EQ(decodeAll("\xED\xA0\x80"), U"\uFFFD");
    EXPECT_EQ(decodeAll("\xFF"), U"\uFFFD");
}

TEST(FontAtlas, WhiteTexelIsOpaqueAndAtlasGrowsWithNewGlyphs) {
    FontAtlas font = loadDefaultFont();
    const Vec2 white = font.whiteUv();
    const auto texel = [&](Vec2 uv) {
        const int x = int(uv.x * float(font.width()));
        const int y = int(uv.y * float(font.height()));
        return font.pixels()[std::size_t(y) * std::size_t(font.width()) + std::size_t(x)];
    };
    EXPECT_EQ(texel(white), 255);
    EXPECT_EQ(font.pixels().size(), std::size_t(font.width()) * std::size_t(font.height()));

    // Many large sizes overflow the first atlas height: it grows, the version changes, and
    // glyphs placed before keep pointing at their pixels.
    const Glyph& first = font.glyph('W', 12.0f);
    const Rect firstUv = first.uv;
    const int firstHeight = font.height();
    const std::uint64_t before = font.version();
    for (float size = 30.0f; size < 90.0f; size += 5.0f)
        for (char c = 'A'; c <= 'Z'; ++c)
            font.glyph(char32_t(c), size);
    EXPECT_GT(font.height(), firstHeight);
    EXPECT_NE(font.version(), before);
    const float shrink = float(firstHeight) / float(font.height());
    EXPECT_FLOAT_EQ(first.uv.min.y, firstUv.min.y * shrink);
    EXPECT_EQ(texel(font.whiteUv()), 255);
}

TEST(FontAtlas, GlyphsAreRasterisedAtPixelsPerPoint) {
    FontAtlas font = loadDefaultFont();
    const Glyph one = font.glyph('H', 14.0f);
    const float texelsOne = (one.uv.max.y - one.uv.min.y) * float(font.height());
    font.setPixelsPerPoint(2.0f);
    const Glyph two = font.glyph('H', 14.0f);
    const float texelsTwo = (two.uv.max.y - two.uv.min.y) * float(font.height());
    // Twice the texels, the same size in points.
    EXPECT_NEAR(texelsTwo, 2.0f * texelsOne, 2.0f);
    EXPECT_NEAR(two.offset.height(), one.offset.height(), 1.0f);
    EXPECT_FLOAT_EQ(two.advance, one.advance);
}

TEST(FontAtlas, MissingGlyphFallsBackToQuestionMark) {
    const FontAtlas font = loadDefaultFont();
    // U+E000 is a private-use code point DejaVu Sans does not define.
    ASSERT_FALSE(font.hasGlyph(U'\uE000'));
    EXPECT_FLOAT_EQ(font.glyph(U'\uE000', 14.0f).advance, font.glyph('?', 14.0f).advance);
}

}  // namespace
}  // namespace grass::ui
