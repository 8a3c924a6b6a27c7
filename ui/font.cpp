#include "ui/font.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <unordered_map>

// stb_truetype is third-party C: its implementation lives in this one translation unit, and
// its warnings (conversions, shadowing) are not ours to fix. The include directory is SYSTEM,
// which already silences most; the pragmas cover the rest under -Werror.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wcast-qual"
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb_truetype.h>
#pragma GCC diagnostic pop

namespace grass::ui {

namespace {

// 1024 texels wide fits a whole ASCII set of 14 pt text at 2 pixels per point on two shelves;
// the height starts small and doubles when a shelf no longer fits (version() changes).
constexpr int ATLAS_WIDTH = 1024;
constexpr int INITIAL_ATLAS_HEIGHT = 256;
// Empty texels around every glyph so bilinear sampling never picks up a neighbour's edge.
constexpr int PADDING = 1;
// The white block at the atlas origin: 3×3 texels, sampled at its centre texel, so all four
// bilinear taps are opaque whatever the filter does.
constexpr int WHITE_BLOCK = 3;
// Sizes are cached per quarter point: finer steps would rasterise near-duplicates when a
// layout computes sizes like 13.999.
constexpr float SIZE_STEPS_PER_POINT = 4.0f;
// Tab stops are four spaces wide (no tab glyph in DejaVu).
constexpr float TAB_SPACES = 4.0f;
constexpr char32_t REPLACEMENT = 0xFFFD;

float quantiseSize(float sizePt) {
    return std::max(1.0f, std::round(sizePt * SIZE_STEPS_PER_POINT)) / SIZE_STEPS_PER_POINT;
}

std::uint64_t glyphKey(float sizePt, char32_t codepoint) {
    const auto steps = static_cast<std::uint64_t>(std::lround(sizePt * SIZE_STEPS_PER_POINT));
    return (steps << 32) | static_cast<std::uint64_t>(codepoint);
}

std::uint32_t readU32(const std::vector<unsigned char>& data, std::size_t at) {
    return (std::uint32_t(data[at]) << 24) | (std::uint32_t(data[at + 1]) << 16) |
           (std::uint32_t(data[at + 2]) << 8) | std::uint32_t(data[at + 3]);
}

// The sfnt version tags of a single TrueType/OpenType font: 1.0, 'true' (Apple), 'OTTO' (CFF).
bool isSingleFont(const std::vector<unsigned char>& data) {
    if (data.size() < 4)
        return false;
    const std::uint32_t tag = readU32(data, 0);
    return tag == 0x00010000u || tag == 0x74727565u || tag == 0x4F54544Fu;
}

// stb_truetype trusts its input: a table offset beyond the end of the file reads out of
// bounds. So the sfnt table directory is checked before stb sees the data.
bool tableDirectoryFits(const std::vector<unsigned char>& data) {
    constexpr std::size_t HEADER = 12;
    constexpr std::size_t RECORD = 16;
    if (data.size() < HEADER)
        return false;
    const std::size_t tables = (std::size_t(data[4]) << 8) | data[5];
    if (tables == 0 || HEADER + tables * RECORD > data.size())
        return false;
    for (std::size_t t = 0; t < tables; ++t) {
        const std::size_t record = HEADER + t * RECORD;
        const std::uint64_t offset = readU32(data, record + 8);
        const std::uint64_t length = readU32(data, record + 12);
        if (offset + length > data.size())
            return false;
    }
    return true;
}

}  // namespace

char32_t decodeUtf8(std::string_view text, std::size_t& pos) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(pos);
    if (lead < 0x80) {
        ++pos;
        return lead;
    }
    int continuation = 0;
    char32_t cp = 0;
    char32_t minimum = 0;
    if ((lead & 0xE0) == 0xC0) {
        continuation = 1, cp = lead & 0x1Fu, minimum = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        continuation = 2, cp = lead & 0x0Fu, minimum = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        continuation = 3, cp = lead & 0x07u, minimum = 0x10000;
    } else {
        // A stray continuation byte or 0xF8..0xFF: one replacement per byte.
        ++pos;
        return REPLACEMENT;
    }
    std::size_t next = pos + 1;
    for (int i = 0; i < continuation; ++i, ++next) {
        if (next >= text.size() || (byte(next) & 0xC0) != 0x80) {
            // Truncated: consume only the bytes read so far, so the next lead byte still decodes.
            pos = next;
            return REPLACEMENT;
        }
        cp = (cp << 6) | (byte(next) & 0x3Fu);
    }
    pos = next;
    if (cp < minimum || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return REPLACEMENT;
    return cp;
}

struct FontAtlas::State {
    std::vector<unsigned char> ttf;
    stbtt_fontinfo info{};
    // Font design units: ascent above the baseline (> 0), descent below (< 0), extra gap.
    float unitsPerEm = 2048.0f;
    int ascentUnits = 0, descentUnits = 0, lineGapUnits = 0;

    float pixelsPerPoint = 1.0f;
    int height = INITIAL_ATLAS_HEIGHT;
    std::vector<std::uint8_t> pixels;
    std::uint64_t version = 1;
    // Shelf packer: glyphs fill a row left to right; the shelf is as tall as its tallest glyph.
    int shelfX = 0, shelfY = 0, shelfHeight = 0;
    // Node-based, so references handed out by glyph() stay valid as more glyphs are added.
    std::unordered_map<std::uint64_t, Glyph> glyphs;

    void reset() {
        height = INITIAL_ATLAS_HEIGHT;
        pixels.assign(std::size_t(ATLAS_WIDTH) * std::size_t(height), 0);
        for (int y = 0; y < WHITE_BLOCK; ++y)
            std::fill_n(&pixels[std::size_t(y) * ATLAS_WIDTH], WHITE_BLOCK, std::uint8_t(255));
        shelfX = WHITE_BLOCK + PADDING;
        shelfY = 0;
        shelfHeight = WHITE_BLOCK;
        glyphs.clear();
        ++version;
    }

    // Doubles the height; normalised v coordinates of glyphs already placed halve with it.
    void grow() {
        const int newHeight = height * 2;
        pixels.resize(std::size_t(ATLAS_WIDTH) * std::size_t(newHeight), 0);
        const float scale = float(height) / float(newHeight);
        for (auto& [key, glyph] : glyphs) {
            glyph.uv.min.y *= scale;
            glyph.uv.max.y *= scale;
        }
        height = newHeight;
    }

    // Top-left texel of a w×h free block (padding included by the caller).
    std::pair<int, int> allocate(int w, int h) {
        if (shelfX + w > ATLAS_WIDTH) {
            shelfY += shelfHeight + PADDING;
            shelfX = 0;
            shelfHeight = 0;
        }
        while (shelfY + h > height)
            grow();
        const std::pair<int, int> at{shelfX, shelfY};
        shelfX += w + PADDING;
        shelfHeight = std::max(shelfHeight, h);
        return at;
    }

    float pointsPerUnit(float sizePt) const { return sizePt / unitsPerEm; }

    Glyph rasterise(char32_t codepoint, float sizePt) {
        Glyph out;
        if (codepoint == U'\t') {
            const int space = stbtt_FindGlyphIndex(&info, ' ');
            int advance = 0, bearing = 0;
            stbtt_GetGlyphHMetrics(&info, space, &advance, &bearing);
            out.advance = TAB_SPACES * float(advance) * pointsPerUnit(sizePt);
            return out;
        }
        // Other control characters ('\r', ...) take no space and draw nothing.
        if (codepoint < 0x20 || codepoint == 0x7F)
            return out;
        int index = stbtt_FindGlyphIndex(&info, int(codepoint));
        if (index == 0)
            index = stbtt_FindGlyphIndex(&info, '?');
        int advance = 0, bearing = 0;
        stbtt_GetGlyphHMetrics(&info, index, &advance, &bearing);
        out.advance = float(advance) * pointsPerUnit(sizePt);

        // Rasterised at the physical pixel size so text is crisp on HiDPI; reported in points.
        const float scalePx = stbtt_ScaleForMappingEmToPixels(&info, sizePt * pixelsPerPoint);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetGlyphBitmapBox(&info, index, scalePx, scalePx, &x0, &y0, &x1, &y1);
        const int w = x1 - x0;
        const int h = y1 - y0;
        // Blank glyphs (space) and glyphs wider than the atlas (absurd sizes) get no quad.
        if (w <= 0 || h <= 0 || w + PADDING > ATLAS_WIDTH)
            return out;
        const auto [ax, ay] = allocate(w + PADDING, h + PADDING);
        stbtt_MakeGlyphBitmap(&info, &pixels[std::size_t(ay) * ATLAS_WIDTH + std::size_t(ax)], w, h,
                              ATLAS_WIDTH, scalePx, scalePx, index);
        ++version;
        const Vec2 atlasSize{float(ATLAS_WIDTH), float(height)};
        out.uv = {Vec2(float(ax), float(ay)) / atlasSize,
                  Vec2(float(ax + w), float(ay + h)) / atlasSize};
        out.offset = {Vec2(float(x0), float(y0)) / pixelsPerPoint,
                      Vec2(float(x1), float(y1)) / pixelsPerPoint};
        return out;
    }
};

FontAtlas::FontAtlas() : mState(std::make_unique<State>()) {}
FontAtlas::FontAtlas(FontAtlas&&) noexcept = default;
FontAtlas& FontAtlas::operator=(FontAtlas&&) noexcept = default;
FontAtlas::~FontAtlas() = default;

std::filesystem::path FontAtlas::defaultFontPath() {
    return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

std::optional<FontAtlas> FontAtlas::load(const std::filesystem::path& ttfFile, std::string* error) {
    const auto fail = [&](const std::string& problem) -> std::optional<FontAtlas> {
        if (error != nullptr)
            *error = ttfFile.string() + ": " + problem;
        return std::nullopt;
    };
    std::error_code ec;
    if (!std::filesystem::exists(ttfFile, ec))
        return fail("no such file (install fonts-dejavu-core for the default font)");
    if (std::filesystem::is_directory(ttfFile, ec))
        return fail("is a directory, not a font file");
    std::ifstream in(ttfFile, std::ios::binary);
    if (!in)
        return fail(std::string("cannot open: ") + std::strerror(errno));
    FontAtlas atlas;
    State& s = *atlas.mState;
    s.ttf.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad())
        return fail("read error");
    // Only single-font files: a collection (.ttc) would need a face index.
    if (!isSingleFont(s.ttf) || !tableDirectoryFits(s.ttf))
        return fail("not a TrueType/OpenType font");
    if (stbtt_InitFont(&s.info, s.ttf.data(), 0) == 0)
        return fail("TrueType font without the tables needed for glyphs (cmap, head, hhea, hmtx)");
    stbtt_GetFontVMetrics(&s.info, &s.ascentUnits, &s.descentUnits, &s.lineGapUnits);
    // 1 / scale for a 1-pixel em gives the font's units per em.
    s.unitsPerEm = 1.0f / stbtt_ScaleForMappingEmToPixels(&s.info, 1.0f);
    if (s.ascentUnits <= 0 || !(s.unitsPerEm > 0.0f))
        return fail("font has no usable vertical metrics");
    s.reset();
    return atlas;
}

float FontAtlas::lineHeight(float sizePt) const {
    const State& s = *mState;
    return float(s.ascentUnits - s.descentUnits + s.lineGapUnits) *
           s.pointsPerUnit(quantiseSize(sizePt));
}

float FontAtlas::ascent(float sizePt) const {
    return float(mState->ascentUnits) * mState->pointsPerUnit(quantiseSize(sizePt));
}

const Glyph& FontAtlas::glyph(char32_t codepoint, float sizePt) const {
    State& s = *mState;
    const float size = quantiseSize(sizePt);
    const std::uint64_t key = glyphKey(size, codepoint);
    if (const auto found = s.glyphs.find(key); found != s.glyphs.end())
        return found->second;
    return s.glyphs.emplace(key, s.rasterise(codepoint, size)).first->second;
}

bool FontAtlas::hasGlyph(char32_t codepoint) const {
    return stbtt_FindGlyphIndex(&mState->info, int(codepoint)) != 0;
}

Vec2 FontAtlas::textSize(std::string_view text, float sizePt) const {
    const float line = lineHeight(sizePt);
    float widest = 0.0f;
    float pen = 0.0f;
    // Empty text is still one (empty) line tall, so an empty label or text field keeps its row.
    int lines = 1;
    for (std::size_t pos = 0; pos < text.size();) {
        const char32_t cp = decodeUtf8(text, pos);
        if (cp == U'\n') {
            widest = std::max(widest, pen);
            pen = 0.0f;
            ++lines;
            continue;
        }
        pen += glyph(cp, sizePt).advance;
    }
    widest = std::max(widest, pen);
    return {widest, float(lines) * line};
}

void FontAtlas::setPixelsPerPoint(float pixelsPerPoint) {
    if (!(pixelsPerPoint > 0.0f) || pixelsPerPoint == mState->pixelsPerPoint)
        return;
    mState->pixelsPerPoint = pixelsPerPoint;
    mState->reset();
}

float FontAtlas::pixelsPerPoint() const {
    return mState->pixelsPerPoint;
}

int FontAtlas::width() const {
    return ATLAS_WIDTH;
}

int FontAtlas::height() const {
    return mState->height;
}

const std::vector<std::uint8_t>& FontAtlas::pixels() const {
    return mState->pixels;
}

std::uint64_t FontAtlas::version() const {
    return mState->version;
}

Vec2 FontAtlas::whiteUv() const {
    const float centre = 0.5f * float(WHITE_BLOCK);
    return {centre / float(ATLAS_WIDTH), centre / float(mState->height)};
}

}  // namespace grass::ui
