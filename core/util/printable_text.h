// Text read from a file, made safe to print: control characters (escape sequences, newlines,
// NUL) become spaces, so a terminal, a window title or a script line shows the text instead of
// doing what it says.
#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace grass {

inline std::string printableText(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = ' ';
    return out;
}

// A name read from a file (an attribute, a chunk type) as a one-line error may show it: in
// double quotes, bytes outside printable ASCII (a newline, say) and quotes as \xNN.
inline std::string quotedName(std::string_view name) {
    std::string out = "\"";
    for (const char c : name) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f && c != '"' && c != '\\') {
            out.push_back(c);
        } else {
            constexpr char HEX[] = "0123456789abcdef";
            out += "\\x";
            out.push_back(HEX[byte >> 4]);
            out.push_back(HEX[byte & 0xf]);
        }
    }
    return out + "\"";
}

// A library's multi-line message as one line: its lines trimmed of spaces, tabs and returns,
// empty lines and repeats dropped (a reader that fails twice on the same thing says so twice),
// joined by "; "; past `most` lines, "; … (N more)". Empty when no line holds anything.
inline std::string joinedLines(std::string_view text,
                               std::size_t most = std::numeric_limits<std::size_t>::max()) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos)
            end = text.size();
        std::string line(text.substr(start, end - start));
        line.erase(0, line.find_first_not_of(" \t"));
        line.erase(line.find_last_not_of(" \t") + 1);
        if (!line.empty() && std::find(lines.begin(), lines.end(), line) == lines.end())
            lines.push_back(std::move(line));
        start = end + 1;
    }
    std::string joined;
    for (std::size_t i = 0; i < lines.size() && i < most; ++i)
        joined += (joined.empty() ? "" : "; ") + lines[i];
    if (lines.size() > most)
        joined += "; … (" + std::to_string(lines.size() - most) + " more)";
    return joined;
}

}  // namespace grass
