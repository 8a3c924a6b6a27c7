#include "util/json_text.h"

#include <algorithm>

namespace grass {

std::size_t jsonDepth(std::string_view text) {
    std::size_t depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (const char c : text) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& sourceName) {
    if (jsonDepth(text) > MAX_JSON_DEPTH)
        return makeError(sourceName, "JSON nested more than " + std::to_string(MAX_JSON_DEPTH) +
                                         " levels deep; no file of ours nests that deep");
    nlohmann::json parsed = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (parsed.is_discarded())
        return makeError(sourceName, "not valid JSON (truncated or corrupt)");
    return parsed;
}

}  // namespace grass
