// JSON from files the user (or anyone) made: parsed only after a linear look at how deeply it
// nests. nlohmann's DOM is built without recursion, but its dump, tinygltf's extras and our own
// walkers recurse once per level, so a file nested 50,000 levels deep would overflow the stack.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "util/result.h"

namespace grass {

// Far deeper than any document we read (project.json, glTF, tradeoff.json, bench results,
// packing caches: about 10 levels).
constexpr std::size_t MAX_JSON_DEPTH = 256;

// The deepest nesting of objects and arrays in `text`, strings skipped; no parsing.
std::size_t jsonDepth(std::string_view text);

// `text` parsed, or an error naming `sourceName`: nested deeper than MAX_JSON_DEPTH, or not JSON.
Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& sourceName);

}  // namespace grass
