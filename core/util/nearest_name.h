// "Did you mean …?": the known name nearest to a mistyped one, when it is near enough to be the
// one meant (a letter or two off, or two letters swapped). For unknown project keys
// (project/json_reader.h), commands and options (util/arg_parser.h, the CLI's main).
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace grass::core {

// Edits (insert, delete, replace, swap two neighbours) from `a` to `b`, case-insensitive.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `word` by edit distance, or nullopt when none is close enough to be
// a likely typo: a third of the word, at least 2 and at most 3 edits ("densty" → "density",
// "sz" → "size", but "fov" is not a typo of "name"). An exact match is its own answer.
std::optional<std::string_view> closestMatch(std::string_view word,
                                             std::span<const std::string_view> candidates);

}  // namespace grass::core
