// Text read from a file, made safe to print: control characters (escape sequences, newlines,
// NUL) become spaces, so a terminal, a window title or a script line shows the text instead of
// doing what it says.
#pragma once

#include <string>
#include <string_view>

namespace grass {

inline std::string printableText(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = ' ';
    return out;
}

}  // namespace grass
