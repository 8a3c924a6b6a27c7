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

}  // namespace grass::ui
