#include "ui/text_wrap.h"

namespace grass::ui {

std::vector<std::string> wrapText(const FontAtlas& fonts, float sizePt, std::string_view text,
                                  float width) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find(' ', start);
        const std::string word(
            text.substr(start, end == std::string_view::npos ? text.npos : end - start));
        start = end == std::string_view::npos ? text.size() : end + 1;
        const std::string joined = line.empty() ? word : line + " " + word;
        if (fonts.textSize(joined, sizePt).x <= width || line.empty()) {
            line = joined;
        } else {
            lines.push_back(line);
            line = word;
        }
        // A single word wider than the line is cut where it must be.
        while (fonts.textSize(line, sizePt).x > width && line.size() > 1) {
            std::size_t cut = line.size() - 1;
            while (cut > 1 &&
                   fonts.textSize(std::string_view(line).substr(0, cut), sizePt).x > width)
                --cut;
            // Never inside a UTF-8 sequence.
            while (cut > 1 && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80)
                --cut;
            lines.push_back(line.substr(0, cut));
            line.erase(0, cut);
        }
    }
    if (!line.empty())
        lines.push_back(line);
    return lines;
}

std::string elideText(const FontAtlas& fonts, float sizePt, std::string_view text, float width) {
    if (fonts.textSize(text, sizePt).x <= width)
        return std::string(text);
    const std::string_view ellipsis = " \u2026";
    // Widths grow with the prefix (no kerning: font.h), so the longest fitting one is found by
    // bisection over byte lengths, then moved back to a character's start.
    std::size_t fits = 0, tooLong = text.size();
    while (tooLong - fits > 1) {
        const std::size_t mid = (fits + tooLong) / 2;
        if (fonts.textSize(std::string(text.substr(0, mid)) + std::string(ellipsis), sizePt).x <=
            width)
            fits = mid;
        else
            tooLong = mid;
    }
    while (fits > 0 && fits < text.size() &&
           (static_cast<unsigned char>(text[fits]) & 0xC0) == 0x80)
        --fits;
    return std::string(text.substr(0, fits)) + std::string(ellipsis);
}

float linesHeight(const FontAtlas& fonts, float sizePt, float spacing, std::size_t lines) {
    return static_cast<float>(lines) * (fonts.textSize("Ag", sizePt).y + spacing);
}

}  // namespace grass::ui
