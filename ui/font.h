// The font atlas: glyphs of one TrueType font (DejaVu Sans by default, Debian
// fonts-dejavu-core) rasterised with stb_truetype into one single-channel coverage image,
// shared by every text size the UI uses (sizes are rasterised on first use, at the current
// pixels-per-point, and packed into the atlas). Texture 0 of the backend. Text positions and
// sizes are in points. The const queries (glyph, textSize) may rasterise and grow the atlas:
// logically const caching, so one atlas must not be used from two threads at once. No kerning:
// the width of a concatenation is the sum of the widths.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "types.h"

namespace grass::ui {

// Where a glyph sits in the atlas and how it is placed relative to the pen (points).
struct Glyph {
    Rect uv;               // in the atlas, 0..1
    Rect offset;           // quad relative to the pen on the baseline, points
    float advance = 0.0f;  // points
};

// Decodes the UTF-8 code point starting at text[pos] and advances pos past it (at least one
// byte). Invalid or truncated sequences, overlong forms and surrogates give U+FFFD, so broken
// text still shows as something and decoding always makes progress.
char32_t decodeUtf8(std::string_view text, std::size_t& pos);

class FontAtlas {
public:
    // Loads a .ttf file; the error message names the file and the problem. The default path is
    // the Debian one; the editor falls back to it.
    static std::optional<FontAtlas> load(const std::filesystem::path& ttfFile, std::string* error);
    static std::filesystem::path defaultFontPath();

    // Height of one line of text of sizePt points (ascent − descent + line gap), points.
    float lineHeight(float sizePt) const;
    // Size of `text` laid out at sizePt ('\n' breaks lines), points.
    Vec2 textSize(std::string_view text, float sizePt) const;
    // The glyph of `codepoint` at sizePt (rasterised into the atlas on first use; missing
    // glyphs map to '?').
    const Glyph& glyph(char32_t codepoint, float sizePt) const;
    float ascent(float sizePt) const;

    // Pixels per point the glyphs are rasterised at; changing it re-rasterises (HiDPI).
    void setPixelsPerPoint(float pixelsPerPoint);
    float pixelsPerPoint() const;

    // The coverage image (width × height bytes, row 0 at the top) and a version that changes
    // whenever glyphs were added, so the backend re-uploads only then.
    int width() const;
    int height() const;
    const std::vector<std::uint8_t>& pixels() const;
    std::uint64_t version() const;
    // An opaque texel for untextured shapes (mesh.h).
    Vec2 whiteUv() const;

    // True when the font has a glyph for `codepoint` (else glyph() draws '?').
    bool hasGlyph(char32_t codepoint) const;

    FontAtlas(FontAtlas&&) noexcept;
    FontAtlas& operator=(FontAtlas&&) noexcept;
    ~FontAtlas();

private:
    FontAtlas();
    struct State;
    std::unique_ptr<State> mState;
};

}  // namespace grass::ui
