// Text broken into lines that fit a width: a long message (a path, an error naming a file) must
// be read whole, and a label is cut off at its window's edge.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "font.h"

namespace grass::ui {

// `text` broken at spaces into lines no wider than `width` points at sizePt; a word wider than
// a line (a long path) is cut where it must be, never inside a UTF-8 sequence. A line holds at
// least one character, so any width makes progress. Empty text gives no lines.
std::vector<std::string> wrapText(const FontAtlas& fonts, float sizePt, std::string_view text,
                                  float width);

// The height of `lines` lines of text at sizePt, `spacing` apart (Style::itemSpacing.y): what
// wrapText's lines take as labels, for a window sized to the text it wraps.
float linesHeight(const FontAtlas& fonts, float sizePt, float spacing, std::size_t lines);

// `text` whole when it is no wider than `width` points at sizePt, else its longest beginning
// that fits with " …" after it (never cut inside a UTF-8 sequence): one line that must keep
// its place, such as a status line.
std::string elideText(const FontAtlas& fonts, float sizePt, std::string_view text, float width);

}  // namespace grass::ui
