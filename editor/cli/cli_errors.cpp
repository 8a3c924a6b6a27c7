// How every sub-command reports an error: one line on stderr, "grass <command>: <problem>";
// and its notes, "note: <note>".
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace grass::cli {

// One line, valid UTF-8: control characters and invalid bytes (a binary file's name or
// contents echoed in a message) become '?', so the terminal and log parsers stay sane.
static std::string printable(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        std::size_t length = byte < 0x80         ? 1
                             : (byte >> 5) == 6  ? 2
                             : (byte >> 4) == 14 ? 3
                             : (byte >> 3) == 30 ? 4
                                                 : 0;
        bool valid = length > 0 && i + length <= text.size();
        for (std::size_t k = 1; valid && k < length; ++k)
            valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 2;
        if (!valid || (length == 1 && (byte < 0x20 || byte == 0x7f))) {
            out += byte == '\n' ? ' ' : '?';
            ++i;
            continue;
        }
        out.append(text, i, length);
        i += length;
    }
    return out;
}

void printError(const std::string& command, const std::string& message) {
    const std::string prefix = command.empty() ? "grass: " : "grass " + command + ": ";
    std::fprintf(stderr, "%s%s\n", prefix.c_str(), printable(message).c_str());
}

int reportFailure(const std::string& command, const Error& error, int exitCode) {
    printError(command, error.str());
    return exitCode;
}

void printNotes(const std::vector<std::string>& notes) {
    for (const auto& note : notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
}

std::function<void(const std::string&)> buildProgressNotes() {
    return [](const std::string& stage) { std::fprintf(stderr, "note: %s ...\n", stage.c_str()); };
}

}  // namespace grass::cli
